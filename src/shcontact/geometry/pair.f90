!> Point pairs on the wheel and the rail (doc/theory.md §5.3–5.4): the common-normal refinement of
!> a candidate contact point, and the walk along both profiles in a patch frame that gives the
!> rows of the strip tables; or, for conformal tables ([[follow_conformal]]), the walk along the
!> rail's arc length with the wheel point on each rail normal.
!>
!> Both follow a profile from a known point to the next one at a given frame coordinate η.
!> The table walk goes through the spline intervals in batches ([[walk_points]]): every table
!> point gets its own start from an inverse interpolant of its interval and one Newton step on
!> the interval's cubic, with [[walk_to_eta]] (Newton from the previous point) wherever an
!> interval is not strictly monotone in η. With the option `reference_search` it solves every
!> point from scratch by bracketing ([[locate_eta]]), the original and slower algorithm kept as
!> a reference for tests (the walks agree to ~1e-13 mm).
!> The common-normal refinement always solves from scratch: its bisection decides on the sign of
!> d(gap)/ds near zero, so round-off differences would move the reference point within its
!> tolerance (1e-10 mm) and the curvature tables by up to 1e-8 relative; solved the same way, the
!> reference points of the fast and the reference search are the same bits (and it costs little).
module shcontact_geometry_pair
   use shcontact_core_kinds, only: wp
   use shcontact_profile_spline, only: profile_spline_type, spline_point_type
   use shcontact_geometry_rigid, only: rigid_map_type, to_frame
   use shcontact_geometry_curve, only: frame_point_type, frame_point, locate_eta, walk_to_eta, &
      frame_walk_type, start_walk, walk_points
   use shcontact_geometry_prepared, only: contact_options_type, prepared_profiles_type
   implicit none
   private

   public :: normal_pair_type, refine_all, select_candidates, follow, strip_row, row_count, &
      load_reach, follow_conformal
   public :: max_candidates

   !> Largest number of candidates followed at one position (and of patches found).
   integer, parameter :: max_candidates = 16

   !> Convergence of the common-normal search (mm).
   real(wp), parameter :: s_tol = 1.0e-10_wp
   !> A profile is followed in a frame while |dη/ds| exceeds this (steeper: it turns back).
   real(wp), parameter :: min_deta = 0.05_wp
   !> Rows of the work tables: g − gap0, g'', γ, r_w, rail arc length, A ([[curvature_a]]).
   integer, parameter :: row_count = 7
   !> Table points walked at a time on each profile by the fast search ([[follow]]): the walk
   !> overruns the table's end by less than this.
   integer, parameter :: chunk = 32

   !> A rail point, the wheel point on its normal, and the distance between them.
   type :: normal_pair_type
      !> Arc lengths and spline intervals on the rail and the wheel.
      real(wp) :: s_r = 0.0_wp, s_w = 0.0_wp
      integer :: k_r = 1, k_w = 1
      !> Rail point in the side frame (mm) and the angle of the rail tangent there (rad).
      real(wp) :: y = 0.0_wp, z = 0.0_wp, theta = 0.0_wp
      !> Distance from the rail to the wheel along the rail normal (mm; < 0: interpenetration).
      real(wp) :: gap = 0.0_wp
      !> d(gap)/ds_r and its approximate derivative.
      real(wp) :: dgap = 0.0_wp, d2gap = 0.0_wp
   end type normal_pair_type


contains

   !> Refine every candidate; drop those that fail, and duplicates (same rail point).
   pure subroutine refine_all(prepared, wheel_map, pairs, n_pairs)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(normal_pair_type), intent(inout) :: pairs(:)
      integer, intent(inout) :: n_pairs
      logical :: ok(max_candidates)
      integer :: i, j, n

      do i = 1, n_pairs
         call refine_pair(prepared, wheel_map, pairs(i), ok(i))
         do j = 1, i - 1
            if (ok(i) .and. ok(j)) then
               if (abs(pairs(i)%s_r - pairs(j)%s_r) < 1.0e-3_wp) ok(i) = .false.
            end if
         end do
      end do
      n = 0
      do i = 1, n_pairs
         if (.not. ok(i)) cycle
         n = n + 1
         pairs(n) = pairs(i)
      end do
      n_pairs = n
   end subroutine refine_all

   !> Keep the candidates within max_gap of the deepest, deepest first.
   pure subroutine select_candidates(options, pairs, n_pairs)
      type(contact_options_type), intent(in) :: options
      type(normal_pair_type), intent(inout) :: pairs(:)
      integer, intent(inout) :: n_pairs
      type(normal_pair_type) :: tmp
      real(wp) :: gmin
      integer :: i, j, n

      gmin = minval(pairs(1:n_pairs)%gap)
      n = 0
      do i = 1, n_pairs
         if (pairs(i)%gap - gmin > options%max_gap) cycle
         n = n + 1
         pairs(n) = pairs(i)
      end do
      n_pairs = n
      do i = 2, n_pairs
         tmp = pairs(i)
         j = i - 1
         do while (j >= 1)
            if (pairs(j)%gap <= tmp%gap) exit
            pairs(j + 1) = pairs(j)
            j = j - 1
         end do
         pairs(j + 1) = tmp
      end do
   end subroutine select_candidates

   !> The distance from the rail point at s_r to the wheel along the rail normal, and its
   !> derivative d(gap)/ds_r = −(1 + κ_r·gap)·ζ_w' (ζ_w' the wheel's slope in the frame of the
   !> rail tangent): zero where the two profiles have a common normal.
   pure subroutine normal_pair(prepared, wheel_map, pair, ok, wheel)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(normal_pair_type), intent(inout) :: pair
      logical, intent(out) :: ok
      !> The wheel point in the frame of the rail tangent at the rail point.
      type(frame_point_type), intent(out), optional :: wheel
      type(spline_point_type) :: q
      type(rigid_map_type) :: frame, wmap
      type(frame_point_type) :: w
      real(wp) :: ty, tz, kappa
      integer :: dir

      pair%k_r = prepared%rail%interval(pair%s_r, pair%k_r)
      q = prepared%rail%eval(pair%s_r, pair%k_r)
      call prepared%rail_map%point(q%y, q%z, pair%y, pair%z)
      call prepared%rail_map%vector(q%dy, q%dz, ty, tz)
      pair%theta = atan2(tz, ty)
      kappa = (q%dy*q%d2z - q%dz*q%d2y)/hypot(q%dy, q%dz)**3
      frame = to_frame(pair%theta, pair%y, pair%z)
      wmap = wheel_map%then(frame)
      w = frame_point(prepared%wheel, wmap, pair%s_w, 1, pair%k_w)
      dir = merge(1, -1, w%deta >= 0.0_wp)
      w%deta = dir*w%deta
      call next_point(prepared, prepared%wheel, wmap, 0.0_wp, dir, w, ok, exact=.true.)
      if (.not. ok) return
      pair%s_w = w%s
      pair%k_w = w%k
      ok = w%deta > min_deta
      if (.not. ok) return
      pair%gap = -w%zeta
      pair%dgap = -(1.0_wp + kappa*pair%gap)*w%slope
      ! The rail's graph curvature in its own tangent frame is κ_r.
      pair%d2gap = kappa - w%curv
      if (present(wheel)) wheel = w
   end subroutine normal_pair

   !> The common-normal point near a start: a zero of d(gap)/ds_r where the gap has a minimum,
   !> bracketed by stepping downhill, then safeguarded Newton steps with bisection.
   pure subroutine refine_pair(prepared, wheel_map, pair, ok)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(normal_pair_type), intent(inout) :: pair
      logical, intent(out) :: ok
      type(normal_pair_type) :: lo, hi, trial
      real(wp) :: step, s_min, s_max, s_new
      integer :: it, dir

      s_min = prepared%rail%s(1)
      s_max = prepared%rail%s(prepared%rail%size())
      call normal_pair(prepared, wheel_map, pair, ok)
      if (.not. ok) return
      if (abs(pair%dgap) < tiny(1.0_wp)) return
      ! Bracket: walk downhill until the slope of the gap changes sign.
      dir = merge(1, -1, pair%dgap < 0.0_wp)
      step = 0.02_wp
      if (pair%d2gap > 0.0_wp) step = min(1.0_wp, max(1.0e-7_wp, 2.0_wp*abs(pair%dgap)/pair%d2gap))
      lo = pair
      do it = 1, 200
         trial = lo
         trial%s_r = min(s_max, max(s_min, lo%s_r + dir*step))
         if (abs(trial%s_r - lo%s_r) < s_tol) then
            ! The end of the rail profile: no minimum on this side.
            ok = .false.
            return
         end if
         call normal_pair(prepared, wheel_map, trial, ok)
         if (.not. ok) return
         if ((trial%dgap > 0.0_wp) .eqv. (dir > 0)) exit
         lo = trial
         step = min(2.0_wp, 1.6_wp*step)
      end do
      if (.not. ((trial%dgap > 0.0_wp) .eqv. (dir > 0))) then
         ok = .false.
         return
      end if
      ! lo: slope of the gap pointing downhill towards hi.
      hi = trial
      pair = trial
      do it = 1, 100
         if (abs(hi%s_r - lo%s_r) <= s_tol) exit
         s_new = 0.5_wp*(lo%s_r + hi%s_r)
         if (pair%d2gap > 0.0_wp) then
            if (abs(pair%dgap) < pair%d2gap*abs(hi%s_r - lo%s_r)) then
               s_new = pair%s_r - pair%dgap/pair%d2gap
               if ((s_new - lo%s_r)*(s_new - hi%s_r) >= 0.0_wp) s_new = 0.5_wp*(lo%s_r + hi%s_r)
            end if
         end if
         trial = pair
         trial%s_r = s_new
         call normal_pair(prepared, wheel_map, trial, ok)
         if (.not. ok) return
         step = abs(trial%s_r - pair%s_r)
         pair = trial
         if (step <= s_tol) exit
         if ((pair%dgap > 0.0_wp) .eqv. (hi%dgap > 0.0_wp)) then
            hi = pair
         else
            lo = pair
         end if
      end do
      ok = .true.
   end subroutine refine_pair

   !> One row of the tables from the rail and wheel points of a strip.
   pure function strip_row(prepared, r, w, theta, gap0) result(row)
      type(prepared_profiles_type), intent(in) :: prepared
      type(frame_point_type), intent(in) :: r, w
      real(wp), intent(in) :: theta, gap0
      real(wp) :: row(row_count)
      row(1) = (r%zeta - w%zeta) - gap0
      row(2) = r%curv - w%curv
      ! Local contact angle: the wheel surface's angle in the side frame (see module header).
      row(3) = theta + atan(w%slope)
      row(4) = prepared%track%nominal_radius + w%v - prepared%z_tape
      row(5) = r%s
      row(6) = curvature_a(prepared%options%a_reference_normal, cos(theta), sin(theta), &
         w%slope, row(4))
      row(7) = tan_gamma(tan(theta), w%slope)
   end function strip_row

   !> tan γ = tan(θ + atan w) = (tan θ + w)/(1 − w tan θ) from the wheel's slope w = tan(γ − θ)
   !> in the frame of a patch with contact angle θ, without a tangent per point (|γ| < 90° on
   !> any wheel profile the search accepts).
   elemental real(wp) function tan_gamma(tan_theta, w)
      real(wp), intent(in) :: tan_theta, w
      tan_gamma = (tan_theta + w)/(1.0_wp - w*tan_theta)
   end function tan_gamma

   !> Longitudinal relative curvature A = cos γ/(2 r_w) on a strip (straight track) for the
   !> wheel's slope w = tan(γ − θ) in the frame of a patch with contact angle θ:
   !> cos γ = cos(θ + atan w) = (cos θ − w sin θ)/√(1 + w²); with `fixed_normal` (the option
   !> a_reference_normal) cos θ/(2 r_w).
   elemental real(wp) function curvature_a(fixed_normal, cos_theta, sin_theta, w, r_wheel) &
         result(a)
      logical, intent(in) :: fixed_normal
      real(wp), intent(in) :: cos_theta, sin_theta, w, r_wheel
      if (fixed_normal) then
         a = cos_theta/(2.0_wp*r_wheel)
      else
         a = (cos_theta - w*sin_theta)/(2.0_wp*r_wheel*sqrt(1.0_wp + w*w))
      end if
   end function curvature_a

   !> Follow both profiles from the reference point in steps `step` of η, until the gap exceeds
   !> table_gap or a profile ends or turns back. The patch's own basin ends at the first maximum
   !> behind which the gap falls by more than merge_gap (a neighbouring minimum): `n_basin` rows
   !> and the rail arc length `s_basin` there. The table runs on past it into the neighbour's
   !> basin, so that the patch can grow into its neighbour under load.
   pure subroutine follow(prepared, rmap, wmap, r0, w0, dir_r, dir_w, theta, gap0, step, rows, &
         n_rows, n_basin, s_basin, end_gap)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: rmap, wmap
      type(frame_point_type), intent(in) :: r0, w0
      integer, intent(in) :: dir_r, dir_w
      real(wp), intent(in) :: theta, gap0, step
      !> Where the table ends, in [[table_reach]]'s measure (mm): table_gap, or a first-try
      !> table's own bound.
      real(wp), intent(in) :: end_gap
      real(wp), intent(out) :: rows(:, :)
      integer, intent(out) :: n_rows, n_basin
      real(wp), intent(out) :: s_basin
      type(frame_walk_type) :: walk_r, walk_w
      real(wp), dimension(chunk) :: r_zeta, r_curv, r_s, w_zeta, w_slope, w_curv, w_v, w_s, &
         w_angle, w_a, w_tan
      real(wp) :: top, c, sn, tn
      integer :: j, j0, j_top, i, m, n_r, n_w, n_both
      logical :: cut, fixed_normal

      if (prepared%options%reference_search) then
         call follow_pointwise(prepared, rmap, wmap, r0, w0, dir_r, dir_w, theta, gap0, step, &
            rows, n_rows, n_basin, s_basin, end_gap)
         return
      end if
      top = 0.0_wp; j_top = 0
      cut = .false.
      n_rows = 0
      n_basin = 0
      c = cos(theta)
      sn = sin(theta)
      tn = tan(theta)
      fixed_normal = prepared%options%a_reference_normal
      call start_walk(prepared%rail, rmap, r0, dir_r, step, walk_r)
      call start_walk(prepared%wheel, wmap, w0, dir_w, step, walk_w)
      j0 = 0
      m = chunk
      walk: do while (j0 < size(rows, 2))
         m = min(m, size(rows, 2) - j0)
         call walk_points(prepared%rail, rmap, walk_r, step, j0, m, min_deta, r_zeta, r_curv, &
            r_s, n_r)
         call walk_points(prepared%wheel, wmap, walk_w, step, j0, n_r, min_deta, w_zeta, w_curv, &
            w_s, n_w, w_slope, w_v)
         n_both = min(n_r, n_w)
         ! Loops of their own over the chunk, so that they vectorise (the vector atan).
         do i = 1, n_both
            w_angle(i) = atan(w_slope(i))
         end do
         do i = 1, n_both
            w_v(i) = prepared%track%nominal_radius + w_v(i) - prepared%z_tape
         end do
         do i = 1, n_both
            w_a(i) = curvature_a(fixed_normal, c, sn, w_slope(i), w_v(i))
         end do
         do i = 1, n_both
            w_tan(i) = tan_gamma(tn, w_slope(i))
         end do
         do i = 1, n_both
            rows(1, j0 + i) = (r_zeta(i) - w_zeta(i)) - gap0
            rows(2, j0 + i) = r_curv(i) - w_curv(i)
            rows(3, j0 + i) = theta + w_angle(i)
            rows(4, j0 + i) = w_v(i)
            rows(5, j0 + i) = r_s(i)
            rows(6, j0 + i) = w_a(i)
            rows(7, j0 + i) = w_tan(i)
         end do
         do i = 1, n_both
            j = j0 + i
            n_rows = j
            if (.not. cut) call track_basin(rows(1, j), j, prepared%options%merge_gap, top, &
               j_top, cut, n_basin)
            if (table_reach(prepared, rows(1, j), gap0, tn, rows(7, j)) > end_gap) exit walk
         end do
         if (n_both < m) exit
         j0 = j0 + m
         if (j0 >= 2 .and. .not. prepared%table_end_by_touch) &
            m = points_to_cut(rows(1, j0 - 1), rows(1, j0), end_gap)
      end do walk
      if (.not. cut) n_basin = n_rows
      s_basin = r0%s
      if (n_basin > 0) s_basin = rows(5, n_basin)
   end subroutine follow

   !> One row of a conformal table: the rail point at arc length pair%s_r, the wheel point on its
   !> normal (from the pair's last wheel point), the gap along that normal less gap0, and the
   !> wheel's angle, rolling radius and curvature A there. `ok` false where the wheel is not
   !> found on the normal or turns back in the rail's local frame.
   pure subroutine conformal_row(prepared, wheel_map, pair, gap0, theta0, row, ok)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(normal_pair_type), intent(inout) :: pair
      !> The reference point's gap and contact angle γ₀ (A with cos γ₀ under the option
      !> a_reference_normal).
      real(wp), intent(in) :: gap0, theta0
      real(wp), intent(out) :: row(row_count)
      logical, intent(out) :: ok
      type(frame_point_type) :: w
      call normal_pair(prepared, wheel_map, pair, ok, w)
      if (.not. ok) return
      row(1) = pair%gap - gap0
      row(2) = pair%d2gap
      row(3) = pair%theta + atan(w%slope)
      row(4) = prepared%track%nominal_radius + w%v - prepared%z_tape
      row(5) = pair%s_r
      if (prepared%options%a_reference_normal) then
         row(6) = cos(theta0)/(2.0_wp*row(4))
      else
         row(6) = curvature_a(.false., cos(pair%theta), sin(pair%theta), w%slope, row(4))
      end if
      row(7) = tan_gamma(tan(pair%theta), w%slope)
   end subroutine conformal_row

   !> [[follow]] for a conformal table: the rail followed by its arc length in steps `step`
   !> (sense dir_r in s for step > 0), each row by [[conformal_row]]; the same basin and end
   !> rules, the end measured with the conformal tilt (module shcontact_normal_angles).
   pure subroutine follow_conformal(prepared, wheel_map, pair0, dir_r, gap0, step, rows, &
         n_rows, n_basin, s_basin, end_gap)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(normal_pair_type), intent(in) :: pair0
      integer, intent(in) :: dir_r
      real(wp), intent(in) :: gap0, step, end_gap
      real(wp), intent(out) :: rows(:, :)
      integer, intent(out) :: n_rows, n_basin
      real(wp), intent(out) :: s_basin
      type(normal_pair_type) :: p
      real(wp) :: top, s_min, s_max, c0
      integer :: j, j_top
      logical :: ok, cut

      top = 0.0_wp; j_top = 0
      cut = .false.
      n_rows = 0
      n_basin = 0
      s_min = prepared%rail%s(1)
      s_max = prepared%rail%s(prepared%rail%size())
      c0 = cos(pair0%theta)
      p = pair0
      do j = 1, size(rows, 2)
         p%s_r = pair0%s_r + dir_r*j*step
         if (p%s_r < s_min .or. p%s_r > s_max) exit
         call conformal_row(prepared, wheel_map, p, gap0, pair0%theta, rows(:, j), ok)
         if (.not. ok) exit
         n_rows = j
         if (.not. cut) call track_basin(rows(1, j), j, prepared%options%merge_gap, top, j_top, &
            cut, n_basin)
         if (conformal_reach(prepared, rows(1, j), gap0, c0, rows(3, j)) > end_gap) exit
      end do
      if (.not. cut) n_basin = n_rows
      s_basin = pair0%s_r
      if (n_basin > 0) s_basin = rows(5, n_basin)
   end subroutine follow_conformal

   !> [[table_reach]] for a conformal table: the tilt c = 1 − cos γ/cos γ₀.
   pure real(wp) function conformal_reach(prepared, gap, gap0, cos_gamma0, gamma) result(t)
      type(prepared_profiles_type), intent(in) :: prepared
      real(wp), intent(in) :: gap, gap0, cos_gamma0, gamma
      real(wp) :: c
      t = gap
      if (.not. prepared%table_end_by_touch) return
      c = 1.0_wp - cos(gamma)/cos_gamma0
      if (c < 0.0_wp) t = (gap + gap0*c)/(1.0_wp - c)
   end function conformal_reach

   !> The basin rule of the table walks: the highest gap so far (`top` at row `j_top`); the
   !> patch's own basin ends (`cut`, `n_basin` rows) at the first maximum behind which the gap
   !> falls by more than merge_gap (a neighbouring minimum).
   pure subroutine track_basin(gap, j, merge_gap, top, j_top, cut, n_basin)
      real(wp), intent(in) :: gap, merge_gap
      integer, intent(in) :: j
      real(wp), intent(inout) :: top
      integer, intent(inout) :: j_top, n_basin
      logical, intent(inout) :: cut
      if (gap >= top) then
         top = gap
         j_top = j
      else if (gap < top - merge_gap) then
         cut = .true.
         n_basin = j_top
      end if
   end subroutine track_basin

   !> What the table end is measured by (mm; the table ends at the first point beyond
   !> table_gap): the gap g itself, or, for the kinematic call's first try
   !> (prepared%table_end_by_touch), a lower bound of the approach at which the point touches
   !> under a vertical approach. The strip method puts the point in contact at the approach
   !> (g + g₀c)/(ε_b − c) (shcontact_normal_semihertz's `touch`), with the vertical approach's
   !> tilt c = tan γ₀ tan(γ − γ₀) (doc/geometry.md, "Vertical approach") and ε_b < 1, so
   !> (g + g₀c)/(1 − c) bounds it from below where c < 0; where c ≥ 0 the gap does (g₀c ≥ 0).
   !> Where γ turns away from γ₀ (towards a flange root) c < 0: a vertical translation closes
   !> the gap there faster than at the reference point, and a region whose gap exceeds table_gap
   !> can touch at an approach below it. A table ended by the gap cut such a region off
   !> (the strips then ended short of a contact that was there, and the first try's forces
   !> differed from the full tables' by up to 0.021 in f: doc/performance.md, "Tables bounded by
   !> the load's reach").
   pure real(wp) function table_reach(prepared, gap, gap0, tan_gamma0, tan_gamma) result(t)
      type(prepared_profiles_type), intent(in) :: prepared
      !> Gap g and the reference point's gap g₀ (mm); tan γ₀ of the patch, tan γ of the point.
      real(wp), intent(in) :: gap, gap0, tan_gamma0, tan_gamma
      real(wp) :: den, c
      t = gap
      if (.not. prepared%table_end_by_touch) return
      den = 1.0_wp + tan_gamma*tan_gamma0
      if (.not. (den > 0.0_wp)) return
      c = tan_gamma0*(tan_gamma - tan_gamma0)/den
      if (c < 0.0_wp) t = (gap + gap0*c)/(1.0_wp - c)
   end function table_reach

   !> A first-try table's bound from the load (mm): reach_factor times the Hertz approach of a
   !> load F_z/cos γ₀ (the vertical load carried by this patch alone, along its normal) on the
   !> reference point's curvatures A, B (equivalent radius R_e = 1/(2√(AB)), δ =
   !> (9N²/(16E*²R_e))^{1/3}; the ellipse's own factor is ≤ 1), at most table_gap. A patch
   !> that carries more (friction on a flange, a load shared otherwise) reaches past it, and
   !> the call falls back to the full tables (shcontact_normal_semihertz's approach_reach): the
   !> bound changes the cost, not the forces.
   pure real(wp) function load_reach(prepared, curv_a, curv_b, theta) result(t)
      type(prepared_profiles_type), intent(in) :: prepared
      !> Curvatures A, B at the reference point (1/mm) and its contact angle γ₀ (rad).
      real(wp), intent(in) :: curv_a, curv_b, theta
      real(wp), parameter :: reach_factor = 1.2_wp, min_cos = 0.1_wp
      real(wp) :: load, r_e
      t = prepared%options%table_gap
      if (.not. (prepared%reach_load > 0.0_wp .and. prepared%reach_modulus > 0.0_wp .and. &
         curv_a > 0.0_wp .and. curv_b > 0.0_wp)) return
      load = prepared%reach_load/max(abs(cos(theta)), min_cos)
      r_e = 0.5_wp/sqrt(curv_a*curv_b)
      t = min(t, reach_factor*(9.0_wp*load**2/(16.0_wp*prepared%reach_modulus**2*r_e))**(1.0_wp/3.0_wp))
   end function load_reach

   !> How many points the next chunk of [[follow]] walks, so that the walk does not overrun
   !> the table's end by a whole chunk: the table ends at the first point whose gap exceeds
   !> table_gap, and where the gap rises convexly (a basin's flank) the last step's rise,
   !> continued linearly, reaches table_gap no earlier than the gap itself; one point more, at
   !> most `chunk`, at least 1. Only the cost depends on it: a walk's points do not depend on
   !> where its chunks end, and where the gap rises more slowly the next chunk goes on.
   pure integer function points_to_cut(gap_before, gap_last, table_gap) result(m)
      !> The relative gaps of the last two points walked (mm).
      real(wp), intent(in) :: gap_before, gap_last
      !> The gap where the table ends (mm).
      real(wp), intent(in) :: table_gap
      real(wp) :: rise, steps

      m = chunk
      rise = gap_last - gap_before
      if (.not. rise > 0.0_wp) return
      steps = (table_gap - gap_last)/rise
      if (steps < real(chunk - 1, wp)) m = max(1, int(steps) + 2)
   end function points_to_cut

   !> [[follow]] point after point, each point from the last one by [[next_point]] (the
   !> reference search).
   pure subroutine follow_pointwise(prepared, rmap, wmap, r0, w0, dir_r, dir_w, theta, gap0, &
         step, rows, &
         n_rows, n_basin, s_basin, end_gap)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: rmap, wmap
      type(frame_point_type), intent(in) :: r0, w0
      integer, intent(in) :: dir_r, dir_w
      real(wp), intent(in) :: theta, gap0, step, end_gap
      real(wp), intent(out) :: rows(:, :)
      integer, intent(out) :: n_rows, n_basin
      real(wp), intent(out) :: s_basin
      type(frame_point_type) :: r, w
      real(wp) :: top
      integer :: j, j_top
      logical :: ok_r, ok_w, cut

      top = 0.0_wp; j_top = 0
      cut = .false.
      n_rows = 0
      n_basin = 0
      r = r0; w = w0
      do j = 1, size(rows, 2)
         call next_point(prepared, prepared%rail, rmap, j*step, dir_r, r, ok_r)
         if (.not. ok_r) exit
         call next_point(prepared, prepared%wheel, wmap, j*step, dir_w, w, ok_w)
         if (.not. ok_w) exit
         if (r%deta <= min_deta .or. w%deta <= min_deta) exit
         rows(:, j) = strip_row(prepared, r, w, theta, gap0)
         n_rows = j
         if (.not. cut) call track_basin(rows(1, j), j, prepared%options%merge_gap, top, j_top, &
            cut, n_basin)
         if (table_reach(prepared, rows(1, j), gap0, tan(theta), rows(7, j)) > end_gap) exit
      end do
      if (.not. cut) n_basin = n_rows
      s_basin = r0%s
      if (n_basin > 0) s_basin = rows(5, n_basin)
   end subroutine follow_pointwise

   !> The next point of a walk along a profile in a frame, where η = eta: from the walk's last
   !> point ([[walk_to_eta]]), or solved from scratch ([[locate_eta]]) for the reference search.
   pure subroutine next_point(prepared, spline, map, eta, dir, point, found, exact)
      type(prepared_profiles_type), intent(in) :: prepared
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: eta
      integer, intent(in) :: dir
      !> The last point on entry, the new one on return (unchanged when not found).
      type(frame_point_type), intent(inout) :: point
      logical, intent(out) :: found
      !> Solve from scratch whatever the options say.
      logical, intent(in), optional :: exact
      type(frame_point_type) :: next
      real(wp) :: s
      integer :: k
      logical :: from_scratch

      from_scratch = prepared%options%reference_search
      if (present(exact)) from_scratch = from_scratch .or. exact
      if (from_scratch) then
         s = point%s
         k = point%k
         call locate_eta(spline, map, eta, dir, s, k, found)
         if (found) point = frame_point(spline, map, s, dir, k)
      else
         call walk_to_eta(spline, map, eta, dir, point, next, found)
         if (found) point = next
      end if
   end subroutine next_point

end module shcontact_geometry_pair
