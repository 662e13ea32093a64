!> Wheel on rail: the contact search and the strip geometry of every candidate patch
!> (doc/theory.md §4.1, §4.6, §5.3–5.4).
!>
!> Two steps, so that a scan over many wheel positions smooths the profiles only once:
!>
!> 1. [[prepare_profiles]] (module [[shcontact_geometry_prepared]]): fit the smoothing splines (§5.5), place the rail (§5.2), find the
!>    tape-circle height of the wheel profile (at flange_back_position + tape_circle_offset) and
!>    sample both profiles densely.
!> 2. [[find_contact_patches]] for one wheelset position, into fresh tables or into a
!>    [[contact_patches_type]] the caller keeps (no allocation once it is large enough):
!>    * place the wheel (lateral shift, roll), sample the vertical gap to the rail, lower the wheel
!>      onto the rail and take every separate local minimum of the gap as a candidate patch
!>      (minima behind a maximum lower than `merge_gap` belong to their deeper neighbour);
!>    * refine each candidate to the point pair with a common normal (the minimum of the distance
!>      measured along the rail normal), and adjust the wheel height until the smallest of these
!>      gaps is zero; candidates whose gap exceeds `max_gap` are dropped;
!>    * per patch, turn both profiles by −γ₀ about the reference point and tabulate on a uniform
!>      grid y_i = i·h the gap along the reference normal and the curvatures A(y), B(y), the local
!>      contact angle γ(y) and rolling radius r_w(y), out to `table_gap`: over the basin of the
!>      minimum and on past a maximum into a neighbouring basin (patches merge under load; the
!>      basin limits are kept in `basin_lower`, `basin_upper`).
!>
!> The common-normal refinement and the walk along both profiles that fills the table rows live
!> in [[shcontact_geometry_pair]]; with `reference_search` they use the original bracketing
!> solves (a slow reference for tests), otherwise Newton steps from the previous point.
!>
!> Conventions (binding, see doc/geometry.md):
!> * Every quantity of a patch is given in its side frame (y towards the field side, z down), the
!>   track frame for the right wheel and its mirror image for the left one, except `y_track`,
!>   which is the true track coordinate (negative on the left).
!> * Contact angle γ = atan(dz_rail/dy) in that frame (CONTACT's sign for the right wheel): the
!>   Manchester right wheel at y_ws = 0 has γ₀ = −0.0290 rad. CONTACT reports the left wheel's
!>   angle in the unmirrored track frame, i.e. −γ₀.
!> * Local contact angle γ(y): the angle of the wheel surface on the strip, so that γ and
!>   δr = r_w − r₀ come from the same wheel spline (§6.1) and dr_w/dy = sin γ along the tangent
!>   plane (dr_w/dy_track = tan γ).
!> * Rolling radius r_w = r_nom + z_w(y_w) − z_w(y_tape) in wheel profile coordinates (z down),
!>   y_tape = flange_back_position + tape_circle_offset the tape circle (0 for S1002, 70 mm for a
!>   MiniProf wheel whose origin is the flange back).
!> * A(y) = cos γ(y)/(2 r_w(y)) (option: cos γ₀, the fixed reference normal); B(y) = ½ g''(y),
!>   analytic from the splines, clamped to ≥ b_min.
module shcontact_geometry_contact
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, &
      stat_numerical, stat_no_contact
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_rigid, only: rigid_map_type, translation, to_frame
   use shcontact_geometry_curve, only: frame_point_type, frame_point
   use shcontact_geometry_search, only: polyline_envelope, envelope_segments, gap_minima
   use shcontact_geometry_track, only: track_type, wheelset_position_type, check_position, &
      wheel_placement, str => real_text
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_prepared, only: contact_options_type, prepared_profiles_type, &
      check_contact_options, prepare_profiles, prepare_wheel, sampling_grid_size, sample_block, &
      box_pad
   use shcontact_geometry_pair, only: normal_pair_type, refine_all, select_candidates, follow, load_reach, &
      follow_conformal, &
      strip_row, row_count, max_candidates
   implicit none
   private

   public :: contact_options_type, prepared_profiles_type, contact_patches_type
   public :: check_contact_options, prepare_profiles, prepare_wheel, find_contact_patches
   public :: extract_patch
   public :: positioned_profiles, write_geometry_table, max_candidates

   !> The patches of one wheel position in storage the caller keeps from search to search
   !> ([[find_contact_patches]] with this type), so that a search allocates nothing once the
   !> storage is large enough: the tables of patch k are the first `points(k)` entries of
   !> `patch(k)`'s arrays, which only ever grow (their size is a capacity, not the table size).
   !> The work arrays of the search live here too; they are sized from the prepared profiles at
   !> the first search. [[extract_patch]] copies a patch out with tables of exact size.
   type :: contact_patches_type
      !> Number of patches found, deepest first (0 after a failed search).
      integer :: count = 0
      !> Number of table points of each patch.
      integer :: points(max_candidates) = 0
      !> The patches; only the first points(k) table entries of patch(k) belong to it.
      type(patch_geometry_type) :: patch(max_candidates)
      !> The wheel samples placed laterally (side frame, mm).
      real(wp), allocatable, private :: wheel_y(:), wheel_z(:)
      !> The sampling grid: rail and wheel envelopes and their arc lengths, the gap, where it is
      !> defined, and the indices of its minima.
      real(wp), allocatable, private :: rail_env(:), rail_env_s(:), wheel_env(:), &
         wheel_env_s(:), gap(:)
      logical, allocatable, private :: rail_covered(:), wheel_covered(:)
      integer, allocatable, private :: minima(:)
      !> Lateral bounds of the placed blocks of wheel samples, and the runs of wheel segments
      !> that can lie over the rail (first and last segment).
      real(wp), allocatable, private :: block_lo(:), block_hi(:)
      integer, allocatable, private :: runs(:, :)
      !> Rows of the strip tables on either side of the reference point.
      real(wp), allocatable, private :: left(:, :), right(:, :)
   end type contact_patches_type

   !> Find the contact patches: from prepared profiles, or from raw profiles in one go; into
   !> freshly allocated tables, or into a reused [[contact_patches_type]].
   interface find_contact_patches
      module procedure find_patches_prepared
      module procedure find_patches_raw
      module procedure find_patches_reuse
   end interface find_contact_patches

   !> Height adjustment stops when the smallest gap is below this (mm).
   real(wp), parameter :: gap_tol = 1.0e-10_wp

contains

   !> Find the contact patches for one wheel position, from raw profiles (smoothing included).
   subroutine find_patches_raw(wheel, rail, track, position, options, patches, error)
      !> Wheel and rail profiles (right-side canonical form).
      type(profile_type), intent(in) :: wheel, rail
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      !> Wheelset position and side.
      type(wheelset_position_type), intent(in) :: position
      !> Options.
      type(contact_options_type), intent(in) :: options
      !> The patches, deepest first (gap0 = 0 for the first).
      type(patch_geometry_type), allocatable, intent(out) :: patches(:)
      !> Set on invalid input or when the profiles do not touch.
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prepared

      call prepare_profiles(wheel, rail, track, options, prepared, error)
      if (allocated(error)) return
      call find_patches_prepared(prepared, position, patches, error)
   end subroutine find_patches_raw

   !> Find the contact patches for one wheel position: candidates, wheel height, reference
   !> points and strip tables (see the module header), into tables of exact size.
   subroutine find_patches_prepared(prepared, position, patches, error)
      !> Profiles from [[prepare_profiles]].
      type(prepared_profiles_type), intent(in) :: prepared
      !> Wheelset position and side.
      type(wheelset_position_type), intent(in) :: position
      !> The patches, deepest first (gap0 = 0 for the first).
      type(patch_geometry_type), allocatable, intent(out) :: patches(:)
      !> Set on invalid input, when the profiles do not touch, or when no candidate converges.
      type(error_type), allocatable, intent(out) :: error
      type(contact_patches_type) :: found
      integer :: k

      call find_patches_reuse(prepared, position, found, error)
      if (allocated(error)) return
      allocate (patches(found%count))
      do k = 1, found%count
         call extract_patch(found, k, patches(k))
      end do
   end subroutine find_patches_prepared

   !> Find the contact patches for one wheel position into storage kept by the caller (see
   !> [[contact_patches_type]]): the same patches as the other forms, bit for bit, and no
   !> allocation once the storage has grown to the tables' size.
   subroutine find_patches_reuse(prepared, position, patches, error)
      !> Profiles from [[prepare_profiles]].
      type(prepared_profiles_type), intent(in) :: prepared
      !> Wheelset position and side.
      type(wheelset_position_type), intent(in) :: position
      !> The patches, deepest first (gap0 = 0 for the first); count = 0 on error.
      type(contact_patches_type), intent(inout) :: patches
      !> Set on invalid input, when the profiles do not touch, or when no candidate converges.
      type(error_type), allocatable, intent(out) :: error
      type(rigid_map_type) :: wheel_map
      type(normal_pair_type) :: pairs(max_candidates)
      real(wp) :: covered(2, max_candidates)
      logical :: keep(max_candidates)
      integer :: n_pairs, i, j

      patches%count = 0
      call place_wheel(prepared, position, patches, wheel_map, pairs, n_pairs, error)
      if (allocated(error)) return
      ! Deepest first; a candidate inside an earlier patch's basin (reached through a negligible
      ! maximum) belongs to that patch.
      keep = .false.
      do i = 1, n_pairs
         keep(i) = .true.
         do j = 1, i - 1
            if (.not. keep(j)) cycle
            if (pairs(i)%s_r >= covered(1, j) .and. pairs(i)%s_r <= covered(2, j)) then
               keep(i) = .false.
               exit
            end if
         end do
         if (.not. keep(i)) cycle
         call build_table(prepared, wheel_map, position%side, pairs(i), patches, &
            patches%count + 1, covered(:, i), error)
         if (allocated(error)) then
            patches%count = 0
            return
         end if
         patches%count = patches%count + 1
      end do
   end subroutine find_patches_reuse

   !> Patch k of a [[contact_patches_type]] with tables of exact size; the arrays of `patch`
   !> are reused when they already have that size.
   pure subroutine extract_patch(patches, k, patch)
      !> The patches of a search.
      type(contact_patches_type), intent(in) :: patches
      !> Which patch (1 to patches%count).
      integer, intent(in) :: k
      !> The copy.
      type(patch_geometry_type), intent(inout) :: patch
      integer :: n

      n = patches%points(k)
      associate (src => patches%patch(k))
         patch%y_track = src%y_track
         patch%z_track = src%z_track
         patch%y_rail = src%y_rail
         patch%y_wheel = src%y_wheel
         patch%gamma0 = src%gamma0
         patch%r0 = src%r0
         patch%gap0 = src%gap0
         patch%h = src%h
         patch%basin_lower = src%basin_lower
         patch%basin_upper = src%basin_upper
         patch%touch_reach = src%touch_reach
         patch%conformal = src%conformal
         call copy_table(src%y, n, patch%y)
         call copy_table(src%gap, n, patch%gap)
         call copy_table(src%curv_a, n, patch%curv_a)
         call copy_table(src%curv_b, n, patch%curv_b)
         call copy_table(src%gamma, n, patch%gamma)
         call copy_table(src%r_wheel, n, patch%r_wheel)
         call copy_table(src%tan_gamma, n, patch%tan_gamma)
      end associate
   end subroutine extract_patch

   !> dst = src(1:n), reallocating dst only when its size is not n.
   pure subroutine copy_table(src, n, dst)
      real(wp), intent(in) :: src(:)
      integer, intent(in) :: n
      real(wp), allocatable, intent(inout) :: dst(:)
      if (allocated(dst)) then
         if (size(dst) /= n) deallocate (dst)
      end if
      if (.not. allocated(dst)) allocate (dst(n))
      dst(:) = src(1:n)
   end subroutine copy_table

   !> The positioned profiles in true track coordinates (the left side mirrored back), with the
   !> wheel lowered onto the rail, sampled as polylines for plotting.
   subroutine positioned_profiles(prepared, position, rail_y, rail_z, wheel_y, wheel_z, error)
      !> Profiles from [[prepare_profiles]].
      type(prepared_profiles_type), intent(in) :: prepared
      !> Wheelset position and side.
      type(wheelset_position_type), intent(in) :: position
      !> Rail and wheel polylines, track coordinates (mm, z down).
      real(wp), allocatable, intent(out) :: rail_y(:), rail_z(:), wheel_y(:), wheel_z(:)
      !> Set when the wheel cannot be placed on the rail.
      type(error_type), allocatable, intent(out) :: error
      type(rigid_map_type) :: wheel_map
      type(normal_pair_type) :: pairs(max_candidates)
      type(contact_patches_type) :: work
      integer :: n_pairs

      call place_wheel(prepared, position, work, wheel_map, pairs, n_pairs, error)
      if (allocated(error)) return
      rail_y = position%side*prepared%rail_y
      rail_z = prepared%rail_z
      allocate (wheel_y(size(prepared%wheel_y)), wheel_z(size(prepared%wheel_z)))
      call wheel_map%point(prepared%wheel_y, prepared%wheel_z, wheel_y, wheel_z)
      wheel_y = position%side*wheel_y
   end subroutine positioned_profiles

   !> Place the wheel for a position: the lateral map, the vertical shift that makes the smallest
   !> gap zero, and the refined candidates (deepest first, gaps ≤ max_gap).
   subroutine place_wheel(prepared, position, work, wheel_map, pairs, n_pairs, error)
      type(prepared_profiles_type), intent(in) :: prepared
      type(wheelset_position_type), intent(in) :: position
      !> Provides the work arrays of the sampling.
      type(contact_patches_type), intent(inout) :: work
      type(rigid_map_type), intent(out) :: wheel_map
      type(normal_pair_type), intent(out) :: pairs(:)
      integer, intent(out) :: n_pairs
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: shift, gmin
      integer :: it, i, imin

      call check_position(position, error)
      if (allocated(error)) return
      if (.not. allocated(prepared%rail_s)) then
         call fatal_error(error, 'contact search: the profiles were not prepared '// &
            '(call prepare_profiles first)', stat_invalid_input)
         return
      end if
      wheel_map = wheel_placement(prepared%track, position)
      call sampled_candidates(prepared, wheel_map, work, pairs, n_pairs, shift, error)
      if (allocated(error)) return
      wheel_map = wheel_map%then(translation(0.0_wp, shift))

      ! Refine, then move the wheel vertically until the smallest normal gap is zero: a shift
      ! Δz reduces the gap of a patch with angle γ by Δz·cos γ.
      do it = 1, 30
         call refine_all(prepared, wheel_map, pairs, n_pairs)
         if (n_pairs == 0) then
            call fatal_error(error, 'contact search: no candidate contact point converged '// &
               '(no common normal between the wheel and the rail profile); '// &
               'check the profiles and the wheel position', stat_numerical)
            return
         end if
         imin = minloc(pairs(1:n_pairs)%gap, 1)
         gmin = pairs(imin)%gap
         if (abs(gmin) <= gap_tol) exit
         wheel_map = wheel_map%then(translation(0.0_wp, gmin/cos(pairs(imin)%theta)))
      end do
      if (abs(gmin) > 1.0e3_wp*gap_tol) then
         call fatal_error(error, 'contact search: the wheel height did not converge (smallest '// &
            'gap '//str(gmin)//' mm)', stat_numerical)
         return
      end if
      call select_candidates(prepared%options, pairs, n_pairs)
      do i = 1, n_pairs
         pairs(i)%gap = max(pairs(i)%gap - gmin, 0.0_wp)
      end do
   end subroutine place_wheel

   !> Sample the vertical gap between the rail and the wheel (before any vertical shift), find
   !> its separate minima and turn them into starting points of the refinement. `shift` is the
   !> vertical move (down) that makes the sampled gap's minimum zero. The samples live in the
   !> work arrays of `work` ([[reserve_search]]). Only the blocks of wheel samples that can lie
   !> over the rail are placed ([[wheel_extent]], [[wheel_runs]]); the reference search places
   !> them all. Both give the same envelope, bit for bit.
   pure subroutine sampled_candidates(prepared, wheel_map, work, pairs, n_pairs, shift, error)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(contact_patches_type), intent(inout) :: work
      type(normal_pair_type), intent(out) :: pairs(:)
      integer, intent(out) :: n_pairs
      real(wp), intent(out) :: shift
      type(error_type), allocatable, intent(out) :: error
      integer :: m, n_w, n_runs
      real(wp) :: h, y0, y1, w_min, w_max

      n_pairs = 0
      shift = 0.0_wp
      h = prepared%options%sample_step
      n_w = size(prepared%wheel_y)
      call reserve_search(prepared, work, 0)
      if (prepared%options%reference_search) then
         call wheel_map%points(prepared%wheel_y, prepared%wheel_z, work%wheel_y(1:n_w), &
            work%wheel_z(1:n_w))
         w_min = minval(work%wheel_y(1:n_w))
         w_max = maxval(work%wheel_y(1:n_w))
      else
         call wheel_extent(prepared, wheel_map, work, w_min, w_max)
      end if
      y0 = max(prepared%rail_y_min, w_min)
      y1 = min(prepared%rail_y_max, w_max)
      if (y1 - y0 < 4.0_wp*h) then
         call fatal_error(error, 'contact search: the wheel (y = '//str(w_min)//' to '// &
            str(w_max)//' mm) and the rail (y = '//str(prepared%rail_y_min)// &
            ' to '//str(prepared%rail_y_max)//' mm, side frame) do not overlap '// &
            'laterally; check the lateral shift and the track dimensions', stat_no_contact)
         return
      end if
      m = int((y1 - y0)/h) + 1
      call reserve_search(prepared, work, m)
      if (prepared%options%reference_search) then
         n_runs = 1
         work%runs(:, 1) = [1, n_w - 1]
      else
         call wheel_runs(prepared, wheel_map, work, y0, y1, n_runs)
      end if
      if (y0 == prepared%rail_y_min .and. m <= size(prepared%rail_env) .and. &
         .not. prepared%options%reference_search) then
         ! The grid of the rail's own envelope, computed once (the same values).
         call grid_candidates(prepared, work%wheel_y, work%wheel_z, work%runs(:, 1:n_runs), y0, &
            prepared%rail_env(1:m), prepared%rail_env_s(1:m), prepared%rail_env_covered(1:m), &
            work%wheel_env(1:m), work%wheel_env_s(1:m), work%gap(1:m), &
            work%wheel_covered(1:m), work%minima(1:m), pairs, n_pairs, shift, error)
      else
         call polyline_envelope(prepared%rail_y, prepared%rail_z, prepared%rail_s, y0, h, &
            .false., work%rail_env(1:m), work%rail_env_s(1:m), work%rail_covered(1:m))
         call grid_candidates(prepared, work%wheel_y, work%wheel_z, work%runs(:, 1:n_runs), y0, &
            work%rail_env(1:m), work%rail_env_s(1:m), work%rail_covered(1:m), &
            work%wheel_env(1:m), work%wheel_env_s(1:m), work%gap(1:m), &
            work%wheel_covered(1:m), work%minima(1:m), pairs, n_pairs, shift, error)
      end if
   end subroutine sampled_candidates

   !> The lateral bounds of a box of profile points (y_min, y_max, z_min, z_max) placed by
   !> `map`, widened by box_pad: every placed point of the box lies in [lo, hi].
   elemental subroutine box_extent(map, y_min, y_max, z_min, z_max, lo, hi)
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: y_min, y_max, z_min, z_max
      real(wp), intent(out) :: lo, hi
      ! y' = c y − s z + dy
      lo = min(map%c*y_min, map%c*y_max) + min(-map%s*z_min, -map%s*z_max) + map%dy - box_pad
      hi = max(map%c*y_min, map%c*y_max) + max(-map%s*z_min, -map%s*z_max) + map%dy + box_pad
   end subroutine box_extent

   !> The smallest and the largest y of the wheel samples placed by `wheel_map`, exactly as
   !> over all samples, placing only the blocks that can hold them; the lateral bounds of every
   !> placed block are left in work%block_lo, work%block_hi.
   pure subroutine wheel_extent(prepared, wheel_map, work, w_min, w_max)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(contact_patches_type), intent(inout) :: work
      real(wp), intent(out) :: w_min, w_max
      real(wp) :: lowest_top, highest_bottom
      integer :: b, nb, i1, i2

      nb = size(prepared%wheel_box, 2)
      associate (box => prepared%wheel_box, lo => work%block_lo(1:nb), hi => work%block_hi(1:nb))
         call box_extent(wheel_map, box(1, :), box(2, :), box(3, :), box(4, :), lo, hi)
         ! The smallest sample lies in a block whose lower bound is at most every block's upper
         ! bound (its own included); likewise the largest.
         lowest_top = minval(hi)
         highest_bottom = maxval(lo)
         w_min = huge(1.0_wp)
         w_max = -huge(1.0_wp)
         do b = 1, nb
            if (lo(b) > lowest_top .and. hi(b) < highest_bottom) cycle
            i1 = (b - 1)*sample_block + 1
            i2 = min(size(prepared%wheel_y), b*sample_block)
            call wheel_map%points(prepared%wheel_y(i1:i2), prepared%wheel_z(i1:i2), &
               work%wheel_y(i1:i2), work%wheel_z(i1:i2))
            if (lo(b) <= lowest_top) w_min = min(w_min, minval(work%wheel_y(i1:i2)))
            if (hi(b) >= highest_bottom) w_max = max(w_max, maxval(work%wheel_y(i1:i2)))
         end do
      end associate
   end subroutine wheel_extent

   !> The runs of wheel polyline segments that can cross the grid between y0 and y1 (increasing,
   !> without overlap, in work%runs(:, 1:n_runs)), with their end points placed by `wheel_map`
   !> in work%wheel_y, work%wheel_z: the segments of every block whose lateral bounds
   !> ([[wheel_extent]]) reach into [y0, y1] and those into and out of such a block. A segment
   !> left out lies within one block outside [y0, y1], or joins two such blocks on the same side.
   pure subroutine wheel_runs(prepared, wheel_map, work, y0, y1, n_runs)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      type(contact_patches_type), intent(inout) :: work
      real(wp), intent(in) :: y0, y1
      integer, intent(out) :: n_runs
      integer :: b, b1, nb, n_w, i1, i2, last

      nb = size(prepared%wheel_box, 2)
      n_w = size(prepared%wheel_y)
      n_runs = 0
      last = 0
      b = 1
      associate (lo => work%block_lo(1:nb), hi => work%block_hi(1:nb))
         do while (b <= nb)
            if (hi(b) >= y0 .and. lo(b) <= y1) then
               b1 = b
               do while (b < nb)
                  if (.not. (hi(b + 1) >= y0 .and. lo(b + 1) <= y1)) exit
                  b = b + 1
               end do
               ! Segments from the last sample before block b1 to the first after block b.
               i1 = max(1, (b1 - 1)*sample_block, last + 1)
               i2 = min(n_w - 1, b*sample_block)
            else if (b < nb) then
               ! Two blocks outside the grid on opposite sides: the segment joining them.
               i1 = b*sample_block
               i2 = i1
               if (.not. ((hi(b) < y0 .and. lo(b + 1) > y1) .or. &
                  (lo(b) > y1 .and. hi(b + 1) < y0))) i2 = i1 - 1
               i1 = max(i1, last + 1)
            else
               exit
            end if
            if (i1 <= i2) then
               n_runs = n_runs + 1
               work%runs(:, n_runs) = [i1, i2]
               last = i2
               call wheel_map%points(prepared%wheel_y(i1:i2 + 1), prepared%wheel_z(i1:i2 + 1), &
                  work%wheel_y(i1:i2 + 1), work%wheel_z(i1:i2 + 1))
            end if
            b = b + 1
         end do
      end associate
   end subroutine wheel_runs

   !> [[sampled_candidates]] on the grid y_j = y0 + (j − 1) h, j = 1..size(gap), given the
   !> rail's envelope (rz, rs, rc) and the placed wheel samples (wy, wz) of the segment runs
   !> `runs`; the other arrays are work space of the grid's size.
   pure subroutine grid_candidates(prepared, wy, wz, runs, y0, rz, rs, rc, wzl, ws, gap, wc, &
         minima, pairs, n_pairs, shift, error)
      type(prepared_profiles_type), intent(in) :: prepared
      real(wp), intent(in) :: wy(:), wz(:), y0
      integer, intent(in) :: runs(:, :)
      real(wp), intent(in) :: rz(:), rs(:)
      logical, intent(in) :: rc(:)
      real(wp), intent(out) :: wzl(:), ws(:), gap(:)
      logical, intent(out) :: wc(:)
      integer, intent(out) :: minima(:)
      type(normal_pair_type), intent(inout) :: pairs(:)
      integer, intent(inout) :: n_pairs
      real(wp), intent(out) :: shift
      type(error_type), allocatable, intent(out) :: error
      integer :: count, j, i, r
      real(wp) :: h, slope
      logical :: interior

      h = prepared%options%sample_step
      shift = 0.0_wp
      ! The wheel's envelope (wzl, ws) is read only where it is covered (wc).
      wc = .false.
      do r = 1, size(runs, 2)
         call envelope_segments(wy, wz, prepared%wheel_s, runs(1, r), runs(2, r), y0, h, .true., &
            wzl, ws, wc)
      end do
      ! wc: where both envelopes are defined; the gap there (0 elsewhere), in one pass.
      do j = 1, size(gap)
         wc(j) = rc(j) .and. wc(j)
         gap(j) = 0.0_wp
         if (wc(j)) gap(j) = rz(j) - wzl(j)
      end do
      call gap_minima(gap, wc, prepared%options%merge_gap, minima, count, interior)
      if (.not. interior) then
         j = minloc(gap, 1, mask=wc)
         call fatal_error(error, 'contact search: the wheel touches the rail at the end of a '// &
            'profile (y = '//str(y0 + (j - 1)*h)//' mm, side frame), not on a running surface; '// &
            'the profiles do not overlap enough at this wheel position', stat_no_contact)
         return
      end if
      shift = gap(minima(1))
      do i = 1, count
         if (n_pairs == size(pairs)) exit
         j = minima(i)
         ! Keep what may lie within max_gap along its own normal (gap·cos γ, with a margin).
         slope = (rz(j + 1) - rz(j - 1))/(2.0_wp*h)
         if ((gap(j) - shift)/sqrt(1.0_wp + slope**2) > 1.5_wp*prepared%options%max_gap &
            + 10.0_wp*h) cycle
         n_pairs = n_pairs + 1
         pairs(n_pairs)%s_r = rs(j)
         pairs(n_pairs)%s_w = ws(j)
         pairs(n_pairs)%k_r = prepared%rail%interval(rs(j))
         pairs(n_pairs)%k_w = prepared%wheel%interval(ws(j))
      end do
   end subroutine grid_candidates

   !> Size the work arrays of the search for these profiles, once: the placed wheel samples, a
   !> sampling grid over the rail's whole width (the overlap with the wheel is never wider),
   !> at least `m` points, and the strip-table rows. Arrays only grow.
   pure subroutine reserve_search(prepared, work, m)
      type(prepared_profiles_type), intent(in) :: prepared
      type(contact_patches_type), intent(inout) :: work
      integer, intent(in) :: m
      integer :: n_grid

      call reserve_vector(work%wheel_y, size(prepared%wheel_y))
      call reserve_vector(work%wheel_z, size(prepared%wheel_y))
      call reserve_vector(work%block_lo, size(prepared%wheel_box, 2))
      call reserve_vector(work%block_hi, size(prepared%wheel_box, 2))
      if (allocated(work%runs)) then
         if (size(work%runs, 2) < size(prepared%wheel_box, 2)) deallocate (work%runs)
      end if
      if (.not. allocated(work%runs)) allocate (work%runs(2, size(prepared%wheel_box, 2)))
      ! minima is allocated last and never larger than the others.
      if (allocated(work%minima)) then
         if (size(work%minima) >= m) return
      end if
      n_grid = max(m, sampling_grid_size(prepared))
      call reserve_vector(work%rail_env, n_grid)
      call reserve_vector(work%rail_env_s, n_grid)
      call reserve_vector(work%wheel_env, n_grid)
      call reserve_vector(work%wheel_env_s, n_grid)
      call reserve_vector(work%gap, n_grid)
      if (allocated(work%rail_covered)) deallocate (work%rail_covered, work%wheel_covered, &
         work%minima)
      allocate (work%rail_covered(n_grid), work%wheel_covered(n_grid), work%minima(n_grid))
   end subroutine reserve_search

   !> Make `a` hold at least n values (its content is not kept when it grows). It grows by half
   !> at least, so that a scan over positions with ever longer tables reallocates rarely.
   pure subroutine reserve_vector(a, n)
      real(wp), allocatable, intent(inout) :: a(:)
      integer, intent(in) :: n
      integer :: capacity
      capacity = n
      if (allocated(a)) then
         if (size(a) >= n) return
         capacity = max(n, size(a) + size(a)/2)
         deallocate (a)
      end if
      allocate (a(capacity))
   end subroutine reserve_vector

   !> Make `a` hold at least rows × n values (its content is not kept when it grows).
   pure subroutine reserve_rows(a, rows, n)
      real(wp), allocatable, intent(inout) :: a(:, :)
      integer, intent(in) :: rows, n
      if (allocated(a)) then
         if (size(a, 1) == rows .and. size(a, 2) >= n) return
         deallocate (a)
      end if
      allocate (a(rows, n))
   end subroutine reserve_rows

   !> Make the tables of a patch hold at least n points.
   pure subroutine reserve_patch(patch, n)
      type(patch_geometry_type), intent(inout) :: patch
      integer, intent(in) :: n
      call reserve_vector(patch%y, n)
      call reserve_vector(patch%gap, n)
      call reserve_vector(patch%curv_a, n)
      call reserve_vector(patch%curv_b, n)
      call reserve_vector(patch%gamma, n)
      call reserve_vector(patch%r_wheel, n)
      call reserve_vector(patch%tan_gamma, n)
   end subroutine reserve_patch

   !> The strip tables of one patch: both profiles turned by −γ₀ about the reference point and
   !> followed outwards in steps h up to table_gap (doc/theory.md §5.4), into patch k of `patches`.
   !> `covered` returns the rail arc-length range of the patch's own basin (up to the maxima
   !> that separate it from its neighbours), which the tables may overrun.
   pure subroutine build_table(prepared, wheel_map, side, pair, patches, k, covered, error)
      type(prepared_profiles_type), intent(in) :: prepared
      type(rigid_map_type), intent(in) :: wheel_map
      integer, intent(in) :: side
      type(normal_pair_type), intent(in) :: pair
      type(contact_patches_type), intent(inout) :: patches
      integer, intent(in) :: k
      real(wp), intent(out) :: covered(2)
      type(error_type), allocatable, intent(out) :: error
      type(rigid_map_type) :: rmap, wmap, frame
      type(frame_point_type) :: r0, w0
      real(wp) :: h, gap0, swap, end_gap, row0(row_count)
      integer :: n_left, n_right, basin_left, basin_right, n_max, dir_r, dir_w, n, i, i0

      h = prepared%options%table_step
      frame = to_frame(pair%theta, pair%y, pair%z)
      rmap = prepared%rail_map%then(frame)
      wmap = wheel_map%then(frame)
      r0 = frame_point(prepared%rail, rmap, pair%s_r, 1, pair%k_r)
      w0 = frame_point(prepared%wheel, wmap, pair%s_w, 1, pair%k_w)
      dir_r = merge(1, -1, r0%deta >= 0.0_wp)
      dir_w = merge(1, -1, w0%deta >= 0.0_wp)
      r0 = frame_point(prepared%rail, rmap, pair%s_r, dir_r, pair%k_r)
      w0 = frame_point(prepared%wheel, wmap, pair%s_w, dir_w, pair%k_w)
      gap0 = r0%zeta - w0%zeta
      row0 = strip_row(prepared, r0, w0, pair%theta, gap0)
      end_gap = prepared%options%table_gap
      if (prepared%table_end_by_touch) end_gap = load_reach(prepared, row0(6), &
         max(0.5_wp*row0(2), prepared%options%b_min), pair%theta)
      n_max = int(min(prepared%rail%length(), prepared%wheel%length())/h) + 2
      call reserve_rows(patches%left, row_count, n_max)
      call reserve_rows(patches%right, row_count, n_max)
      if (prepared%options%conformal_tables) then
         call follow_conformal(prepared, wheel_map, pair, dir_r, gap0, h, &
            patches%right(:, 1:n_max), n_right, basin_right, covered(2), end_gap)
         call follow_conformal(prepared, wheel_map, pair, dir_r, gap0, -h, &
            patches%left(:, 1:n_max), n_left, basin_left, covered(1), end_gap)
      else
         call follow(prepared, rmap, wmap, r0, w0, dir_r, dir_w, pair%theta, gap0, h, &
            patches%right(:, 1:n_max), n_right, basin_right, covered(2), end_gap)
         call follow(prepared, rmap, wmap, r0, w0, dir_r, dir_w, pair%theta, gap0, -h, &
            patches%left(:, 1:n_max), n_left, basin_left, covered(1), end_gap)
      end if
      if (covered(1) > covered(2)) then
         swap = covered(1)
         covered(1) = covered(2)
         covered(2) = swap
      end if

      n = n_left + n_right + 1
      i0 = n_left + 1
      call reserve_patch(patches%patch(k), n)
      patches%points(k) = n
      associate (patch => patches%patch(k))
         call put_rows(1, reshape(row0, [row_count, 1]), i0, i0, 1, h, &
            prepared%options%b_min, patch%y, patch%gap, &
            patch%curv_a, patch%curv_b, patch%gamma, patch%r_wheel, patch%tan_gamma)
         call put_rows(n_right, patches%right, i0, i0 + 1, 1, h, prepared%options%b_min, &
            patch%y, patch%gap, patch%curv_a, patch%curv_b, patch%gamma, patch%r_wheel, &
            patch%tan_gamma)
         call put_rows(n_left, patches%left, i0, i0 - 1, -1, h, prepared%options%b_min, &
            patch%y, patch%gap, patch%curv_a, patch%curv_b, patch%gamma, patch%r_wheel, &
            patch%tan_gamma)
         patch%h = h
         patch%basin_lower = -basin_left*h
         patch%basin_upper = basin_right*h
         patch%touch_reach = huge(1.0_wp)
         patch%conformal = prepared%options%conformal_tables
         if (prepared%table_end_by_touch) patch%touch_reach = end_gap
         patch%gap(i0) = 0.0_wp
         patch%y_track = side*pair%y
         patch%z_track = pair%z
         patch%y_rail = r0%u
         patch%y_wheel = w0%u
         patch%gamma0 = pair%theta
         patch%r0 = patch%r_wheel(i0)
         patch%gap0 = gap0
         if (any(patch%r_wheel(1:n) <= 0.0_wp)) then
            call fatal_error(error, 'contact search: a wheel rolling radius <= 0 in the patch '// &
               'at y = '//str(patch%y_track)//' mm; check the nominal radius and the wheel '// &
               'profile', stat_invalid_input)
         end if
      end associate
   end subroutine build_table

   !> Table points i1, i1 + sense, … of a patch (reference point i0) from n rows of
   !> [[strip_row]] or [[follow]]: y, the gap (≥ 0), B = g''/2 clamped to b_min, γ, r_w, A and
   !> tan γ.
   pure subroutine put_rows(n, rows, i0, i1, sense, h, b_min, y, gap, curv_a, curv_b, gamma, &
         r_wheel, tan_gamma)
      integer, intent(in) :: n
      real(wp), intent(in) :: rows(row_count, *)
      integer, intent(in) :: i0, i1, sense
      real(wp), intent(in) :: h, b_min
      real(wp), intent(inout) :: y(*), gap(*), curv_a(*), curv_b(*), gamma(*), r_wheel(*), &
         tan_gamma(*)
      integer :: j, i

      do j = 1, n
         i = i1 + sense*(j - 1)
         y(i) = (i - i0)*h
         gap(i) = max(rows(1, j), 0.0_wp)
         curv_b(i) = max(0.5_wp*rows(2, j), b_min)
         gamma(i) = rows(3, j)
         r_wheel(i) = rows(4, j)
         curv_a(i) = rows(6, j)
         tan_gamma(i) = rows(7, j)
      end do
   end subroutine put_rows

   !> Write the strip tables of all patches to a text file: a header naming the columns and
   !> units, then per patch a comment line with its reference data and one line per table point
   !> (blank lines between patches, for gnuplot's `index`).
   subroutine write_geometry_table(patches, filename, error)
      !> The patches.
      type(patch_geometry_type), intent(in) :: patches(:)
      !> File to write (replaced).
      character(len=*), intent(in) :: filename
      !> Set when the file cannot be written.
      type(error_type), allocatable, intent(out) :: error
      integer :: unit, stat, k, i
      character(len=256) :: msg
      character(len=:), allocatable :: frame

      frame = 'in the tangent plane, the gap along its normal'
      if (size(patches) > 0) then
         if (patches(1)%conformal) frame = 'along the rail (its arc length; conformal '// &
            'tables), the gap along each point''s rail normal'
      end if
      open (newunit=unit, file=filename, status='replace', action='write', iostat=stat, &
         iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, filename//': cannot open for writing: '//trim(msg), stat_io)
         return
      end if
      write (unit, '(a)', iostat=stat) &
         '# shcontact contact-patch geometry (doc/theory.md §4.1, §5.4); y from the reference '// &
         'point towards the field side, '//frame, &
         '# gamma: local contact angle, CONTACT sign (right wheel tread < 0); '// &
         'delta_r = r_w - r0', &
         '# columns: patch  y[mm]  gap[mm]  A[1/mm]  B[1/mm]  gamma[rad]  r_w[mm]  delta_r[mm]'
      do k = 1, size(patches)
         if (stat /= 0) exit
         associate (p => patches(k))
            if (k > 1) write (unit, '(/)', iostat=stat)
            write (unit, '(a,i0,a,i0,7(a,es16.8),a,i0)', iostat=stat) '# patch ', k, ' of ', &
               size(patches), ': y_track = ', p%y_track, ' mm, z_track = ', p%z_track, &
               ' mm, y_rail = ', p%y_rail, ' mm, y_wheel = ', p%y_wheel, ' mm, gamma0 = ', &
               p%gamma0, ' rad, r0 = ', p%r0, ' mm, gap0 = ', p%gap0, ' mm, points = ', p%size()
            do i = 1, p%size()
               if (stat /= 0) exit
               write (unit, '(i3,7es17.8e3)', iostat=stat) k, p%y(i), p%gap(i), p%curv_a(i), &
                  p%curv_b(i), p%gamma(i), p%r_wheel(i), p%r_wheel(i) - p%r0
            end do
         end associate
      end do
      if (stat /= 0) then
         call fatal_error(error, filename//': write failed', stat_io)
         close (unit)
         return
      end if
      close (unit, iostat=stat)
   end subroutine write_geometry_table

end module shcontact_geometry_contact
