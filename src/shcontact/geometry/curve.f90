!> A profile spline seen through a rigid map: its points, slopes and curvatures as the graph
!> ζ(η) in some frame (track coordinates, or a contact patch's frame, doc/theory.md §5.4).
!>
!> Profiles are splines in arc length, so they may be multi-valued in y; in a frame they are
!> read as graphs only locally, by following them from a known point ([[locate_eta]]).
module shcontact_geometry_curve
   use shcontact_core_kinds, only: wp
   use shcontact_profile_spline, only: profile_spline_type, spline_point_type
   use shcontact_geometry_rigid, only: rigid_map_type
   implicit none
   private

   public :: frame_point_type, frame_point, locate_eta, walk_to_eta
   public :: frame_walk_type, start_walk, walk_points

   !> Newton steps of [[walk_to_eta]] before it falls back to [[locate_eta]].
   integer, parameter :: max_newton = 8
   !> [[walk_to_eta]] stops after a Newton step this small (mm): the error of the next one would be
   !> below 1e-14 mm for any profile the walk follows (|dη/ds| > 0.05, curvature < 10/mm).
   real(wp), parameter :: newton_tol = 1.0e-8_wp
   !> Spline intervals a walk prepares at a time ([[frame_walk_type]]).
   integer, parameter :: batch = 16

   !> A profile point in a frame, with the profile's local shape as a graph ζ(η).
   type :: frame_point_type
      !> Arc length on the profile (mm) and the spline interval holding it.
      real(wp) :: s = 0.0_wp
      integer :: k = 1
      !> Profile coordinates (mm).
      real(wp) :: u = 0.0_wp, v = 0.0_wp
      !> Frame coordinates (mm).
      real(wp) :: eta = 0.0_wp, zeta = 0.0_wp
      !> dη/ds: the tangent's lateral component in the frame (≤ 0 where the profile runs
      !> against the direction it is followed in).
      real(wp) :: deta = 0.0_wp
      !> dζ/dη and d²ζ/dη² (1/mm); zero where dη/ds = 0.
      real(wp) :: slope = 0.0_wp, curv = 0.0_wp
      !> d²η/ds² (1/mm), for the second-order prediction of a walk's next point.
      real(wp) :: d2eta = 0.0_wp
   end type frame_point_type

   !> A walk along one profile in a frame at the table points η_j = j·step ([[walk_points]]),
   !> one spline interval at a time: the interval's cubics projected on the frame axes, and an
   !> inverse cubic Hermite interpolant of s(η) over it that gives every table point its own
   !> starting value (no chain from point to point, so consecutive points overlap in the CPU).
   type :: frame_walk_type
      !> The frame map as projections: η = ay·y + az·z + ey, ζ = by·y + bz·z + ez.
      real(wp) :: ay = 1.0_wp, az = 0.0_wp, ey = 0.0_wp, by = 0.0_wp, bz = 1.0_wp, ez = 0.0_wp
      !> +1 when η grows with s; the sign of the step; the sense of the walk in s (dir·sigma).
      integer :: dir = 1, sigma = 1, sd = 1
      !> Current interval (0: none, the walk falls back to [[walk_to_eta]]), its place in the
      !> batch below and the batch's size.
      integer :: k = 0, idx = 0, count = 0
      !> A batch of consecutive intervals in the walk's sense, prepared together (independent
      !> of each other, so that they overlap in the CPU instead of delaying the points):
      !> whether g = sigma·η is strictly increasing along the walk over the whole interval
      !> (dir·η' > 0 at both ends and at the extremum of η'), so that a crossing is unique;
      logical :: regular(batch) = .false.
      !> η and ζ on the interval as cubics in t = s − s(k), the frame offsets included, and the
      !> multiples of their coefficients that their derivatives take: 2c₃, 3c₄, 6c₄ of η (rows
      !> 1–3) and of ζ (rows 4–6); the arc length s(k) at the interval's start;
      real(wp) :: p(4, batch) = 0.0_wp, q(4, batch) = 0.0_wp, d(6, batch) = 0.0_wp
      real(wp) :: s0(batch) = 0.0_wp
      !> The profile's own z from the frame point: z = ay·ζ + az·η + v0 (the map is a rotation).
      real(wp) :: v0 = 0.0_wp
      !> the interval length, t at its near end (in the walk's sense), g at both ends;
      real(wp), dimension(batch) :: len = 0.0_wp, t_near = 0.0_wp, g_near = 0.0_wp, &
         g_far = 0.0_wp
      !> 1/(g_far − g_near) and the inverse Hermite cubic τ(u) = u (a1 + u (a2 + u a3)),
      !> τ = sd·(t − t_near), u = (g − g_near)/(g_far − g_near).
      real(wp), dimension(batch) :: inv_span = 0.0_wp, a1 = 0.0_wp, a2 = 0.0_wp, a3 = 0.0_wp
      !> The walk's last point (for the fallback; only s, k, eta, deta and d2eta are kept up to
      !> date on the fast path).
      type(frame_point_type) :: last
   end type frame_walk_type

contains

   !> Start a walk along `spline` (seen through `map`) from the point `start` (from
   !> [[frame_point]] with the same `dir`), at the table points η_j = j·step.
   pure subroutine start_walk(spline, map, start, dir, step, walk)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> The walk's first point (η = 0).
      type(frame_point_type), intent(in) :: start
      !> +1 when η grows with s near `start`, −1 when it falls.
      integer, intent(in) :: dir
      !> Table step (mm, signed: the walk goes towards −η when negative).
      real(wp), intent(in) :: step
      !> The walk's state.
      type(frame_walk_type), intent(out) :: walk

      walk%ay = map%c; walk%az = -map%s; walk%ey = map%dy
      walk%by = map%s; walk%bz = map%c; walk%ez = map%dz
      walk%v0 = map%s*map%dy - map%c*map%dz
      walk%dir = dir
      walk%sigma = merge(1, -1, step >= 0.0_wp)
      walk%sd = dir*walk%sigma
      walk%last = start
      call enter_interval(spline, walk, start%k)
   end subroutine start_walk

   !> Make interval k the walk's current one, preparing it and the next ones in the walk's
   !> sense (their projected cubics and inverse interpolants).
   pure subroutine enter_interval(spline, walk, k)
      type(profile_spline_type), intent(in) :: spline
      type(frame_walk_type), intent(inout) :: walk
      integer, intent(in) :: k
      real(wp) :: e_end, de_end, d_near, d_far, span, m0, m1, t_ext, dp_ext, len
      integer :: b, kb
      logical :: regular

      walk%k = k
      walk%idx = 1
      if (walk%sd > 0) then
         walk%count = min(batch, size(spline%s) - k)
      else
         walk%count = min(batch, k)
      end if
      do b = 1, walk%count
         kb = k + (b - 1)*walk%sd
         len = spline%s(kb + 1) - spline%s(kb)
         walk%len(b) = len
         walk%p(:, b) = walk%ay*spline%cy(:, kb) + walk%az*spline%cz(:, kb)
         walk%p(1, b) = walk%p(1, b) + walk%ey
         walk%q(:, b) = walk%by*spline%cy(:, kb) + walk%bz*spline%cz(:, kb)
         walk%q(1, b) = walk%q(1, b) + walk%ez
         walk%d(1, b) = 2.0_wp*walk%p(3, b)
         walk%d(2, b) = 3.0_wp*walk%p(4, b)
         walk%d(3, b) = 6.0_wp*walk%p(4, b)
         walk%d(4, b) = 2.0_wp*walk%q(3, b)
         walk%d(5, b) = 3.0_wp*walk%q(4, b)
         walk%d(6, b) = 6.0_wp*walk%q(4, b)
         walk%s0(b) = spline%s(kb)
         associate (p => walk%p(:, b))
            ! η and dη/dt at t = len; at t = 0 they are p(1) and p(2). dg/dτ = dir·η'(t) along
            ! the walk.
            e_end = p(1) + len*(p(2) + len*(p(3) + len*p(4)))
            de_end = p(2) + len*(2.0_wp*p(3) + 3.0_wp*len*p(4))
            if (walk%sd > 0) then
               walk%t_near(b) = 0.0_wp
               walk%g_near(b) = walk%sigma*p(1)
               walk%g_far(b) = walk%sigma*e_end
               d_near = walk%dir*p(2)
               d_far = walk%dir*de_end
            else
               walk%t_near(b) = len
               walk%g_near(b) = walk%sigma*e_end
               walk%g_far(b) = walk%sigma*p(1)
               d_near = walk%dir*de_end
               d_far = walk%dir*p(2)
            end if
            regular = d_near > 0.0_wp .and. d_far > 0.0_wp .and. &
               walk%g_far(b) > walk%g_near(b)
            ! η' is quadratic in t: its extremum inside the interval must keep the sign too.
            if (regular .and. p(4) /= 0.0_wp) then
               t_ext = -p(3)/(3.0_wp*p(4))
               if (t_ext > 0.0_wp .and. t_ext < len) then
                  dp_ext = walk%dir*(p(2) + t_ext*(2.0_wp*p(3) + 3.0_wp*t_ext*p(4)))
                  regular = dp_ext > 0.0_wp
               end if
            end if
         end associate
         walk%regular(b) = regular
         if (.not. regular) cycle
         span = walk%g_far(b) - walk%g_near(b)
         walk%inv_span(b) = 1.0_wp/span
         ! Hermite interpolation of τ(g): τ = 0, len at the ends, dτ/dg = 1/d_near, 1/d_far.
         m0 = span/d_near
         m1 = span/d_far
         walk%a1(b) = m0
         walk%a2(b) = 3.0_wp*len - 2.0_wp*m0 - m1
         walk%a3(b) = -2.0_wp*len + m0 + m1
      end do
   end subroutine enter_interval

   !> Continue a walk ([[start_walk]]) over the table points η_j = j·step, j = j0 + 1 … j0 + m:
   !> the frame height ζ, slope dζ/dη, curvature d²ζ/dη², the profile's own z (v) and the arc
   !> length s at each, as [[walk_to_eta]] would give them point after point (to ~1e-14 mm).
   !> `n` is the number of points found with dη/ds (in the walk's sense) > `min_deta`; the walk
   !> ends at the first point where the profile ends or turns back. On a strictly monotone
   !> interval every point is solved from the interval's inverse interpolant by Newton steps on
   !> the projected cubic; anywhere else the point comes from [[walk_to_eta]].
   pure subroutine walk_points(spline, map, walk, step, j0, m, min_deta, zeta, curv, s, n, &
         slope, v)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates (as for [[start_walk]]).
      type(rigid_map_type), intent(in) :: map
      !> The walk's state, updated.
      type(frame_walk_type), intent(inout) :: walk
      !> Table step (mm, as for [[start_walk]]).
      real(wp), intent(in) :: step
      !> Index of the last table point done, and the number of points to do.
      integer, intent(in) :: j0, m
      !> The walk ends where dη/ds ≤ this.
      real(wp), intent(in) :: min_deta
      !> Frame height (mm), dζ/dη, d²ζ/dη² (1/mm), profile z (mm) and arc length (mm); the
      !> slope and z only when asked for (the rail's table rows use neither).
      real(wp), intent(out) :: zeta(:), curv(:), s(:)
      real(wp), intent(out), optional :: slope(:), v(:)
      !> Number of points found.
      integer, intent(out) :: n
      type(frame_point_type) :: pnt
      real(wp) :: eta, g, u, t, t1, f, df, dt, d2f, dq, d2q, inv, sd, sigma, dir
      ! The fast path's last point, written to walk%last only where the walk leaves it.
      real(wp) :: l_s, l_eta, l_deta, l_d2eta
      integer :: i, it, kn, last_k, b, l_k
      logical :: ok, found

      n = 0
      last_k = size(spline%s) - 1
      sd = real(walk%sd, wp)
      sigma = real(walk%sigma, wp)
      dir = real(walk%dir, wp)
      l_s = walk%last%s; l_k = walk%last%k; l_eta = walk%last%eta
      l_deta = walk%last%deta; l_d2eta = walk%last%d2eta
      do i = 1, m
         eta = (j0 + i)*step
         g = sigma*eta
         ok = .false.
         do while (walk%k /= 0)
            b = walk%idx
            if (.not. walk%regular(b)) exit
            if (g <= walk%g_far(b)) then
               ok = .true.
               exit
            end if
            kn = walk%k + walk%sd
            if (kn < 1 .or. kn > last_k) exit
            if (b < walk%count) then
               walk%k = kn
               walk%idx = b + 1
            else
               call enter_interval(spline, walk, kn)
            end if
         end do
         if (ok) then
            associate (p => walk%p(:, b), q => walk%q(:, b), c => walk%d(:, b))
               u = (g - walk%g_near(b))*walk%inv_span(b)
               t = walk%t_near(b) + sd*(u*(walk%a1(b) + u*(walk%a2(b) + u*walk%a3(b))))
               ! One Newton step on η(t) = eta from the interpolant's start, then the point's
               ! height, slope and curvature evaluated at the step's end t1 (c holds the
               ! multiples 2p₃, 3p₄, 6p₄, 2q₃, 3q₄, 6q₄ of the coefficients).
               f = p(1) + t*(p(2) + t*(p(3) + t*p(4))) - eta
               df = p(2) + t*(c(1) + t*c(2))
               dt = -f/df
               if (.not. abs(dt) <= newton_tol) then
                  ! A poor start (rare): Newton to convergence, then one step more from there.
                  t = t + dt
                  do it = 2, max_newton
                     f = p(1) + t*(p(2) + t*(p(3) + t*p(4))) - eta
                     df = p(2) + t*(c(1) + t*c(2))
                     dt = f/df
                     t = t - dt
                     if (abs(dt) <= newton_tol) exit
                  end do
                  f = p(1) + t*(p(2) + t*(p(3) + t*p(4))) - eta
                  df = p(2) + t*(c(1) + t*c(2))
                  dt = -f/df
               end if
               t1 = t + dt
               ok = abs(dt) <= newton_tol .and. t1 >= 0.0_wp .and. t1 <= walk%len(b)
               if (ok) then
                  df = p(2) + t1*(c(1) + t1*c(2))
                  d2f = c(1) + t1*c(3)
                  zeta(i) = q(1) + t1*(q(2) + t1*(q(3) + t1*q(4)))
                  dq = q(2) + t1*(c(4) + t1*c(5))
                  d2q = c(4) + t1*c(6)
                  inv = 1.0_wp/df
                  if (present(slope)) slope(i) = dq*inv
                  curv(i) = (d2q*df - dq*d2f)*(inv*inv*inv)
                  if (present(v)) v(i) = walk%ay*zeta(i) + walk%az*eta + walk%v0
                  s(i) = walk%s0(b) + t1
                  l_s = s(i)
                  l_k = walk%k
                  l_eta = eta
                  l_deta = dir*df
                  l_d2eta = d2f
               end if
            end associate
         end if
         if (.not. ok) then
            call keep_last(walk, l_s, l_k, l_eta, l_deta, l_d2eta)
            call walk_to_eta(spline, map, eta, walk%dir, walk%last, pnt, found)
            if (.not. found) return
            walk%last = pnt
            zeta(i) = pnt%zeta
            if (present(slope)) slope(i) = pnt%slope
            curv(i) = pnt%curv
            if (present(v)) v(i) = pnt%v
            s(i) = pnt%s
            call enter_interval(spline, walk, pnt%k)
            l_s = pnt%s; l_k = pnt%k; l_eta = pnt%eta
            l_deta = pnt%deta; l_d2eta = pnt%d2eta
         end if
         if (.not. l_deta > min_deta) exit
         n = i
      end do
      call keep_last(walk, l_s, l_k, l_eta, l_deta, l_d2eta)
   end subroutine walk_points

   !> The fast path's last point of [[walk_points]] into the walk's `last` (s, k, eta, deta and
   !> d2eta: what [[walk_to_eta]] reads).
   pure subroutine keep_last(walk, s, k, eta, deta, d2eta)
      type(frame_walk_type), intent(inout) :: walk
      real(wp), intent(in) :: s, eta, deta, d2eta
      integer, intent(in) :: k
      walk%last%s = s
      walk%last%k = k
      walk%last%eta = eta
      walk%last%deta = deta
      walk%last%d2eta = d2eta
   end subroutine keep_last

   !> The point of `spline` at arc length s, mapped by `map`; `dir` = ±1 is the sense in which
   !> s runs along +η (the slope and curvature of the graph do not depend on it; `deta` does).
   pure type(frame_point_type) function frame_point(spline, map, s, dir, hint) result(p)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Arc length (mm).
      real(wp), intent(in) :: s
      !> +1 when η grows with s, −1 when it falls.
      integer, intent(in) :: dir
      !> A guess of the spline interval.
      integer, intent(in), optional :: hint
      real(wp) :: sc

      sc = min(max(s, spline%s(1)), spline%s(spline%size()))
      p = point_in_interval(spline, map, sc, spline%interval(sc, hint), dir)
   end function frame_point

   !> [[frame_point]] at s on interval k (s inside it or at its ends), without searching.
   pure type(frame_point_type) function point_in_interval(spline, map, s, k, dir) result(p)
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: s
      integer, intent(in) :: k, dir
      real(wp) :: t, y, dy, d2y, z, dz, d2z, de, d2e, d2z_frame

      p%k = k
      p%s = s
      t = s - spline%s(k)
      associate (cy => spline%cy(:, k), cz => spline%cz(:, k))
         y = cy(1) + t*(cy(2) + t*(cy(3) + t*cy(4)))
         dy = cy(2) + t*(2.0_wp*cy(3) + 3.0_wp*t*cy(4))
         d2y = 2.0_wp*cy(3) + 6.0_wp*t*cy(4)
         z = cz(1) + t*(cz(2) + t*(cz(3) + t*cz(4)))
         dz = cz(2) + t*(2.0_wp*cz(3) + 3.0_wp*t*cz(4))
         d2z = 2.0_wp*cz(3) + 6.0_wp*t*cz(4)
      end associate
      p%u = y; p%v = z
      ! The map (rigid_map_type's point and vector), written out: this is the walk's inner loop.
      p%eta = map%c*y - map%s*z + map%dy
      p%zeta = map%s*y + map%c*z + map%dz
      de = map%c*dy - map%s*dz
      dz = map%s*dy + map%c*dz
      d2e = map%c*d2y - map%s*d2z
      d2z_frame = map%s*d2y + map%c*d2z
      p%deta = dir*de
      p%d2eta = d2e
      if (de**2 > 1.0e-24_wp*(de**2 + dz**2)) then
         ! ζ' = ζ_s/η_s, ζ'' = (ζ_ss η_s − ζ_s η_ss)/η_s³.
         p%slope = dz/de
         p%curv = (d2z_frame*de - dz*d2e)/de**3
      else
         p%slope = 0.0_wp; p%curv = 0.0_wp
      end if
   end function point_in_interval

   !> Follow the profile from arc length `s` to the point where η = `eta`, walking the spline
   !> intervals in the sense `dir` says η grows. `found` is false when the profile ends first.
   !> The point found is the crossing nearest to the start in that walk, so stepping η in
   !> small increments follows one branch of a multi-valued profile.
   pure subroutine locate_eta(spline, map, eta, dir, s, k, found)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Frame lateral coordinate sought (mm).
      real(wp), intent(in) :: eta
      !> +1 when η grows with s near the start, −1 when it falls.
      integer, intent(in) :: dir
      !> Start on entry, the crossing on return (mm).
      real(wp), intent(inout) :: s
      !> Interval of s (guess on entry).
      integer, intent(inout) :: k
      !> Whether the crossing was found.
      logical, intent(out) :: found
      real(wp) :: ay, az, target
      integer :: n

      ! η = c·y − s·z + dy: the position projected on (c, −s).
      ay = map%c; az = -map%s
      target = eta - map%dy
      n = spline%size()
      k = spline%interval(s, k)
      found = .false.
      do while (f(spline%s(k), k) > 0.0_wp)
         k = k - 1
         if (k < 1) return
      end do
      do while (f(spline%s(k + 1), k) < 0.0_wp)
         k = k + 1
         if (k > n - 1) return
      end do
      s = spline%solve_in_interval(k, ay, az, target, guess=s)
      found = .true.
   contains
      !> dir·(η(s) − eta), increasing in s where the profile is followed the right way.
      pure real(wp) function f(sv, kv)
         real(wp), intent(in) :: sv
         integer, intent(in) :: kv
         f = dir*(spline%projection(sv, ay, az, kv) - target)
      end function f
   end subroutine locate_eta

   !> The next point of a walk along a profile: where η = eta, from the walk's last point
   !> `last` (followed in the sense `dir`), evaluated like [[frame_point]]. Where [[locate_eta]]
   !> brackets and solves from scratch, this predicts the arc length to second order from
   !> `last` and corrects it by Newton steps on the spline's cubics (one or two). The crossing
   !> is the one [[locate_eta]] finds, to ~1e-14 mm: it falls back to [[locate_eta]] when Newton
   !> leaves the profile, moves against the walk or further than twice the prediction, meets
   !> dη/ds ≤ 0 or does not converge. `found` is false when the profile ends first.
   pure subroutine walk_to_eta(spline, map, eta, dir, last, p, found)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Frame lateral coordinate sought (mm).
      real(wp), intent(in) :: eta
      !> +1 when η grows with s near `last`, −1 when it falls.
      integer, intent(in) :: dir
      !> The walk's last point (from [[frame_point]] or this routine, with the same `dir`).
      type(frame_point_type), intent(in) :: last
      !> The point found.
      type(frame_point_type), intent(out) :: p
      !> Whether the crossing was found.
      logical, intent(out) :: found
      real(wp) :: x, s
      integer :: k

      x = last%s
      k = last%k
      call newton_eta(spline, map, eta, dir, last, x, k, found)
      if (.not. found) then
         s = last%s
         k = last%k
         call locate_eta(spline, map, eta, dir, s, k, found)
         if (found) p = frame_point(spline, map, s, dir, k)
         return
      end if
      p = point_in_interval(spline, map, x, k, dir)
   end subroutine walk_to_eta

   !> Newton's method for η(s) = eta from the second-order prediction at `last` (see
   !> [[walk_to_eta]]); `found` is false where it cannot be trusted. On success x is the crossing
   !> and k the interval holding it ([[profile_spline_type]]'s `interval`).
   pure subroutine newton_eta(spline, map, eta, dir, last, x, k, found)
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: eta
      integer, intent(in) :: dir
      type(frame_point_type), intent(in) :: last
      real(wp), intent(out) :: x
      integer, intent(inout) :: k
      logical, intent(out) :: found
      real(wp) :: ay, az, target, ds, predicted, d_eta, t, f, df, c(4)
      integer :: it, kc, n

      found = .false.
      x = last%s
      if (.not. last%deta > 0.0_wp) return
      ay = map%c; az = -map%s
      target = eta - map%dy
      n = spline%size()
      ! η(σ) ≈ η₀ + η'σ + η''σ²/2 along σ = dir·(s − s₀), inverted to second order.
      d_eta = eta - last%eta
      predicted = dir*(d_eta/last%deta - 0.5_wp*last%d2eta*d_eta**2/last%deta**3)
      x = last%s + predicted
      kc = 0
      do it = 1, max_newton
         if (x < spline%s(1) .or. x > spline%s(n)) return
         if (.not. (x >= spline%s(k) .and. x < spline%s(k + 1))) k = spline%interval(x, k)
         if (k /= kc) then
            c = ay*spline%cy(:, k) + az*spline%cz(:, k)
            c(1) = c(1) - target
            kc = k
         end if
         t = x - spline%s(k)
         f = c(1) + t*(c(2) + t*(c(3) + t*c(4)))
         df = c(2) + t*(2.0_wp*c(3) + 3.0_wp*t*c(4))
         if (.not. (dir*df > 0.0_wp)) return
         ds = f/df
         x = x - ds
         if (abs(ds) <= newton_tol) then
            if (x < spline%s(1) .or. x > spline%s(n)) return
            if ((x - last%s)*predicted < 0.0_wp) return
            if (abs(x - last%s) > 2.0_wp*abs(predicted) + newton_tol) return
            k = spline%interval(x, k)
            found = .true.
            return
         end if
      end do
   end subroutine newton_eta

end module shcontact_geometry_curve
