!> Points on a straight line between others: the same curve gives the same profile however
!> densely its straight pieces are sampled (issue 24, item 5).
!>
!> The profile spline interpolates its points (doc/theory.md §5.5), so it depends on the points,
!> not only on the curve they sample: a point added on the chord between two samples of a curved
!> profile lies off the curve by up to the chord's sagitta (4·10⁻⁶ mm for 0.1 mm chords on
!> R = 330 mm), and the spline forced through it swings its curvature by about six sagittas over
!> the squared spacing: with nine such points per interval of S1002 the longitudinal force moved
!> by 19 % and the spin moment by 150 %. A program adds such points when it resamples a profile
!> linearly or stitches two exports.
!>
!> [[drop_collinear]] therefore reduces a profile to its polyline's **skeleton** and fills in its
!> long straight pieces, both determined by the polyline alone:
!>
!> 1. every point that lies within [[collinear_distance]] (5·10⁻⁸ mm) of a chord between two
!>    kept points, with the points between in order along the chord, is dropped (greedy from the
!>    first point; the chord from a kept point reaches as far as every point before its end
!>    stays within the distance; end points and kinks are always kept). Points added on a chord
!>    lie on it to their rounding (10 significant digits, 5·10⁻⁹ mm for coordinates below
!>    100 mm, leave a margin for the rounding of both chord ends), genuine samples of a curve
!>    lie off the chord of their neighbours by its sagitta, which is far larger unless the curve
!>    is straight there (R > 25 m for neighbouring samples 0.1 mm apart). Where a curve is that
!>    straight over a few samples (near an inflection), the skeleton may keep a point added on
!>    a chord next to a sample instead of the sample: both lie on the curve to that distance;
!> 2. a skeleton segment longer than [[long_segment_ratio]] (4) times the longer of its
!>    neighbouring segments — a straight piece of the profile, such as S1002's field-side cone
!>    or a rail's 1:20 flank — gets equally spaced points again, about as far apart as the
!>    longer neighbour, so that the spline stays straight along it (with its two end points
!>    only, a C² spline would bulge there to join the curvature of its neighbours). A skeleton
!>    of two or three points (a straight or a V-shaped profile) is filled to four, the fewest a
!>    profile has.
!>
!> A densely resampled copy of a profile has the same skeleton as the profile, hence the same
!> points and the same contact; running it again on its own result changes nothing (the points
!> of step 2 lie on their chord and are found again in step 1). Kink flags and file lines stay
!> with their points; the points of step 2 take the line of the segment's first point.
module shcontact_profile_collinear
   use shcontact_core_kinds, only: wp
   use shcontact_profile_points, only: profile_type
   implicit none
   private

   public :: drop_collinear, collinear_distance, long_segment_ratio

   !> A point closer than this to the chord of two kept points is dropped (mm).
   real(wp), parameter :: collinear_distance = 5.0e-8_wp
   !> A skeleton segment longer than this times its longer neighbour is filled in.
   real(wp), parameter :: long_segment_ratio = 4.0_wp
   !> The points filled in are at least this far apart (mm).
   real(wp), parameter :: min_fill_spacing = 0.01_wp
   !> A skeleton of fewer points is filled in up to this many (a profile has at least four).
   integer, parameter :: min_points = 4

contains

   !> Reduce a cleaned profile to its skeleton and fill in its long straight pieces (module text),
   !> repeated until the skeleton stays the same, so that the result is its own skeleton and
   !> filling: a profile written and read again comes back the same.
   subroutine drop_collinear(profile, lines)
      !> A cleaned profile (shcontact_profile_cleanup's clean_profile); `s` recomputed.
      type(profile_type), intent(inout) :: profile
      !> File line of each point, kept in step (may be unallocated).
      integer, allocatable, intent(inout) :: lines(:)
      !> Passes before giving up on a fixed point (each pass only removes points).
      integer, parameter :: max_passes = 50
      logical, allocatable :: keep(:), kink(:), skeleton(:)
      integer :: n, a, pass

      n = profile%size()
      if (n < 3) return
      allocate (skeleton(n), source=.true.)
      do pass = 1, max_passes
         n = profile%size()
         allocate (kink(n), source=.false.)
         if (allocated(profile%kink)) then
            if (size(profile%kink) == n) kink = profile%kink
         end if
         allocate (keep(n), source=.false.)
         keep(1) = .true.
         a = 1
         do while (a < n)
            a = chord_end(profile%y, profile%z, kink, a)
            keep(a) = .true.
         end do
         if (pass > 1 .and. all(keep .eqv. skeleton)) exit
         call refill(profile, lines, keep, skeleton)
         if (all(keep) .and. all(skeleton)) exit
         deallocate (keep, kink)
      end do
   end subroutine drop_collinear

   !> The kept points, with equally spaced points filled into the long segments between them;
   !> `skeleton` marks the kept points in the result.
   subroutine refill(profile, lines, keep, skeleton)
      type(profile_type), intent(inout) :: profile
      integer, allocatable, intent(inout) :: lines(:)
      logical, intent(in) :: keep(:)
      logical, allocatable, intent(out) :: skeleton(:)
      integer, allocatable :: kept(:), pieces(:), new_lines(:)
      logical, allocatable :: kink(:)
      real(wp), allocatable :: y(:), z(:)
      integer :: n, m, i, j, k, total

      n = size(keep)
      kept = pack([(i, i=1, n)], keep)
      m = size(kept)
      pieces = segment_pieces(profile%y(kept), profile%z(kept))
      total = sum(pieces) + 1
      allocate (y(total), z(total), new_lines(total), kink(total), skeleton(total))
      kink = .false.
      skeleton = .false.
      k = 1
      y(1) = profile%y(1)
      z(1) = profile%z(1)
      new_lines(1) = line_of(lines, 1)
      skeleton(1) = .true.
      do i = 1, m - 1
         associate (p => kept(i), q => kept(i + 1))
            do j = 1, pieces(i) - 1
               k = k + 1
               y(k) = profile%y(p) + (profile%y(q) - profile%y(p))*(real(j, wp)/pieces(i))
               z(k) = profile%z(p) + (profile%z(q) - profile%z(p))*(real(j, wp)/pieces(i))
               new_lines(k) = line_of(lines, p)
            end do
            k = k + 1
            y(k) = profile%y(q)
            z(k) = profile%z(q)
            new_lines(k) = line_of(lines, q)
            skeleton(k) = .true.
            if (allocated(profile%kink)) kink(k) = profile%kink(q)
         end associate
      end do
      if (total == n .and. m == n) return
      call move_alloc(y, profile%y)
      call move_alloc(z, profile%z)
      if (allocated(profile%kink)) call move_alloc(kink, profile%kink)
      if (allocated(lines)) call move_alloc(new_lines, lines)
      call profile%update_arc_length()
   end subroutine refill

   !> The file line of point i (0 when there are no lines).
   pure integer function line_of(lines, i)
      integer, allocatable, intent(in) :: lines(:)
      integer, intent(in) :: i
      line_of = 0
      if (allocated(lines)) then
         if (i <= size(lines)) line_of = lines(i)
      end if
   end function line_of

   !> The last point b > a such that every point strictly between a and b lies within
   !> [[collinear_distance]] of the chord a–b, further along it than the one before, and is no
   !> kink. Angles are measured from the direction of the first segment at a: the points between
   !> confine the chord's direction to an interval (a point at distance r and angle φ allows
   !> φ ± asin(δ/r)), which a candidate end must lie in; one pass, O(b − a).
   pure integer function chord_end(y, z, kink, a) result(b)
      real(wp), intent(in) :: y(:), z(:)
      logical, intent(in) :: kink(:)
      integer, intent(in) :: a
      real(wp) :: u(2), d(2), along, across, r, phi, lo, hi, progress, w
      integer :: j, n

      n = size(y)
      b = a + 1
      u = [y(a + 1) - y(a), z(a + 1) - z(a)]
      progress = norm2(u)
      u = u/progress
      w = asin(min(1.0_wp, collinear_distance/progress))
      lo = -w
      hi = w
      do j = a + 2, n
         if (kink(j - 1)) exit
         d = [y(j) - y(a), z(j) - z(a)]
         along = dot_product(d, u)
         across = u(1)*d(2) - u(2)*d(1)
         if (.not. (along > progress)) exit
         phi = atan2(across, along)
         if (phi < lo .or. phi > hi) exit
         b = j
         r = hypot(along, across)
         w = asin(min(1.0_wp, collinear_distance/r))
         lo = max(lo, phi - w)
         hi = min(hi, phi + w)
         progress = along
      end do
   end function chord_end

   !> Into how many equal pieces each segment of the skeleton is cut: 1, or about its length over
   !> its longer neighbour's when that is more than [[long_segment_ratio]] times shorter.
   pure function segment_pieces(y, z) result(pieces)
      real(wp), intent(in) :: y(:), z(:)
      integer, allocatable :: pieces(:)
      real(wp), allocatable :: length(:)
      real(wp) :: neighbour
      integer :: i, m

      m = size(y) - 1
      allocate (pieces(m), source=1)
      if (m < 1) return
      length = hypot(y(2:) - y(:m), z(2:) - z(:m))
      if (m == 1) then
         ! A straight profile (a cone, a flat rail head): its end points and two between, the
         ! fewest points a profile has (doc/profiles.md; a cleaned file then reads back).
         pieces(1) = min_points - 1
         return
      end if
      do i = 1, m
         neighbour = 0.0_wp
         if (i > 1) neighbour = length(i - 1)
         if (i < m) neighbour = max(neighbour, length(i + 1))
         if (length(i) > long_segment_ratio*neighbour) pieces(i) = &
            nint(length(i)/max(neighbour, min_fill_spacing))
      end do
      ! Two straight pieces: the longer one halved, so that there are min_points points.
      if (sum(pieces) + 1 < min_points) then
         i = maxloc(length, 1)
         pieces(i) = pieces(i) + min_points - 1 - sum(pieces)
      end if
   end function segment_pieces

end module shcontact_profile_collinear
