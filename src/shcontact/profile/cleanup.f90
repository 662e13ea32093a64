!> Checks and repairs of a profile before smoothing (doc/theory.md §5.1, CONTACT's curation).
!>
!> [[clean_profile]] runs, in this order:
!>
!> 1. at least [[min_profile_points]] and at most [[max_profile_points]] points;
!> 2. every coordinate finite. The test looks at the IEEE exponent bits, never compares or
!>    computes with the value, so it holds under `-ffast-math` (where `x /= x` and
!>    `ieee_is_finite` may be folded away) and under `-ffpe-trap=invalid`;
!> 3. total arc length within [[min_arc_length]] … [[max_arc_length]] mm (catches m or µm;
!>    before the duplicates, as in metres distinct points lie closer than their distance);
!> 4. no two consecutive points closer than [[duplicate_distance]]: **duplicates are rejected**,
!>    not removed, because a repeated point in a measured file usually means a stitching or
!>    export error the user should see (SIMPACK's `point.dist.min` removes close points on
!>    purpose when the file asks for it);
!> 5. the point order of the canonical form (rail: y(1) < y(n); wheel: y(1) > y(n));
!> 6. zig-zag pairs: two consecutive direction changes both larger than [[zigzag_angle]]
!>    (5π/6) are a stitching error; the two points are replaced by their mean;
!> 7. no loops: no two non-adjacent segments may cross or touch;
!> 8. kinks: a direction change above [[kink_angle]] (π/6) with no other change above
!>    [[kink_quiet_angle]] (π/30) within [[kink_window]] (2 mm) of the point is a true corner,
!>    flagged in `profile%kink` so that smoothing splits there.
!>
!> Points on the chord of their neighbours are dropped afterwards, for profiles from files, by
!> shcontact_profile_collinear's drop_collinear.
!>
!> Every rejection names the profile's source, the file line (when `line_of_point` is given)
!> or the point number, and the reason.
module shcontact_profile_cleanup
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_constants, only: pi, two_pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_usage
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, option_hint
   implicit none
   private

   public :: clean_profile, is_finite_value
   public :: min_profile_points, max_profile_points, duplicate_distance, min_arc_length, max_arc_length
   public :: zigzag_angle, kink_angle, kink_quiet_angle, kink_window

   !> Fewest points a profile may have.
   integer, parameter :: min_profile_points = 4
   !> Most points a profile may have: 0.01 mm steps over a 500 mm profile. The loop and kink
   !> checks compare segments pairwise, so a bound keeps a mistaken input (a 2-million-point
   !> file took minutes) to seconds.
   integer, parameter :: max_profile_points = 50000
   !> Consecutive points closer than this are duplicates (mm).
   real(wp), parameter :: duplicate_distance = 1.0e-6_wp
   !> Shortest total arc length accepted (mm); CONTACT's bound.
   real(wp), parameter :: min_arc_length = 5.0_wp
   !> Longest total arc length accepted (mm); CONTACT's bound.
   real(wp), parameter :: max_arc_length = 500.0_wp
   !> Direction change marking half of a zig-zag pair (rad), 5π/6.
   real(wp), parameter :: zigzag_angle = 5.0_wp*pi/6.0_wp
   !> Direction change that may be a kink (rad), π/6.
   real(wp), parameter :: kink_angle = pi/6.0_wp
   !> Largest direction change allowed near a kink (rad), π/30.
   real(wp), parameter :: kink_quiet_angle = pi/30.0_wp
   !> Half-width of the neighbourhood checked around a kink (mm).
   real(wp), parameter :: kink_window = 2.0_wp

contains

   !> Check and repair a profile in place (see the module description for the steps).
   subroutine clean_profile(profile, error, line_of_point, option_prefix, scale)
      !> The profile; zig-zag pairs merged, `s` recomputed, `kink` set.
      type(profile_type), intent(inout) :: profile
      !> The first check that failed (stat_invalid_input; stat_usage for a bad `line_of_point`).
      type(error_type), allocatable, intent(out) :: error
      !> File line of each point (0 = unknown), kept in step with the points when pairs merge.
      integer, allocatable, intent(inout), optional :: line_of_point(:)
      !> How the caller names the scale option in messages (as read_profile).
      character(len=*), intent(in), optional :: option_prefix
      !> The scale factor to mm the points were read with, when the caller gave one (named in
      !> the length-unit message).
      real(wp), intent(in), optional :: scale

      integer, allocatable :: lines(:)
      integer :: n, nz

      n = profile%size()
      nz = 0
      if (present(line_of_point)) then
         if (.not. allocated(line_of_point)) then
            allocate (lines(n), source=0)
         else if (size(line_of_point) /= n) then
            call fatal_error(error, source_name(profile)//': line_of_point has '// &
               str_int(size(line_of_point))//' entries for '//str_int(n)//' points', stat_usage)
            return
         else
            lines = line_of_point
         end if
      else
         allocate (lines(n), source=0)
      end if
      if (allocated(profile%z)) nz = size(profile%z)
      if (nz /= n) then
         call fatal_error(error, source_name(profile)//': '//str_int(n)//' y values but '// &
            str_int(nz)//' z values', stat_usage)
         return
      end if

      call check_count(profile, lines, error)
      if (allocated(error)) return
      call check_finite(profile, lines, error)
      if (allocated(error)) return
      ! The length unit first: in metres distinct points lie closer than the duplicate
      ! distance (1e-6 mm), and "remove one of them" would be the wrong advice.
      call profile%update_arc_length()
      call check_arc_length(profile, lines, option_prefix, error, scale)
      if (allocated(error)) return
      call check_duplicates(profile, lines, error)
      if (allocated(error)) return
      call check_order(profile, lines, error)
      if (allocated(error)) return
      call merge_zigzags(profile, lines)
      call check_count(profile, lines, error)
      if (allocated(error)) return
      call check_loops(profile, lines, error)
      if (allocated(error)) return
      call flag_kinks(profile)
      call profile%update_arc_length()
      if (present(line_of_point)) line_of_point = lines
   end subroutine clean_profile

   !> True when x is neither NaN nor ±Inf, decided from its exponent bits alone (safe under
   !> `-ffast-math` and floating-point traps).
   elemental logical function is_finite_value(x)
      !> The value to test.
      real(wp), intent(in) :: x
      integer(int64), parameter :: exponent_mask = 2047_int64
      is_finite_value = iand(shiftr(transfer(x, 0_int64), 52), exponent_mask) /= exponent_mask
   end function is_finite_value

   subroutine check_count(profile, lines, error)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      n = profile%size()
      if (n > max_profile_points) then
         call fatal_error(error, source_name(profile)//': the profile has '//str_int(n)// &
            ' points; at most '//str_int(max_profile_points)//' are accepted (0.01 mm steps '// &
            'over 500 mm): resample it more coarsely', stat_invalid_input)
         return
      end if
      if (n >= min_profile_points) return
      if (n == 0) then
         call fatal_error(error, source_name(profile)//': the profile has no points; at least '// &
            str_int(min_profile_points)//' are needed', stat_invalid_input)
      else
         call fatal_error(error, location(profile, lines, n)//': the profile ends after '// &
            str_int(n)//' point(s); at least '//str_int(min_profile_points)//' are needed', &
            stat_invalid_input)
      end if
   end subroutine check_count

   subroutine check_finite(profile, lines, error)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      do i = 1, profile%size()
         if (is_finite_value(profile%y(i)) .and. is_finite_value(profile%z(i))) cycle
         call fatal_error(error, location(profile, lines, i)//': point '//str_int(i)// &
            ' has a coordinate that is NaN or infinite', stat_invalid_input)
         return
      end do
   end subroutine check_finite

   subroutine check_duplicates(profile, lines, error)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      do i = 2, profile%size()
         if (hypot(profile%y(i) - profile%y(i - 1), profile%z(i) - profile%z(i - 1)) >= &
            duplicate_distance) cycle
         call fatal_error(error, location(profile, lines, i)//': duplicate point ('// &
            str_real(profile%y(i))//', '//str_real(profile%z(i))//') repeats '// &
            previous_line(lines, i)//'; remove one of them', stat_invalid_input)
         return
      end do
   end subroutine check_duplicates

   subroutine check_order(profile, lines, error)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      character(len=:), allocatable :: rule
      n = profile%size()
      if (profile%kind == profile_kind_wheel) then
         if (profile%y(1) > profile%y(n)) return
         rule = 'wheel points must run from the field side to the flange back (y(1) > y(n))'
      else
         if (profile%y(1) < profile%y(n)) return
         rule = 'rail points must run from the track centre to the field side (y(1) < y(n))'
      end if
      call fatal_error(error, location(profile, lines, 1)//': '//rule//', found y(1) = '// &
         str_real(profile%y(1))//', y(n) = '//str_real(profile%y(n)), stat_invalid_input)
   end subroutine check_order

   subroutine check_arc_length(profile, lines, prefix, error, scale)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:)
      character(len=*), intent(in), optional :: prefix
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: scale
      character(len=:), allocatable :: span, advice
      real(wp) :: total
      integer :: n
      n = profile%size()
      total = profile%s(n)
      if (total >= min_arc_length .and. total <= max_arc_length) return
      ! The file's lines in their order (a reversed file lists its last point first).
      if (lines(n) > 0 .and. lines(n) < lines(1)) then
         span = location(profile, lines, n)//' to '//line_word(lines, 1)
      else
         span = location(profile, lines, 1)//' to '//line_word(lines, n)
      end if
      advice = 'Give the scale factor to mm: '//option_hint(prefix, 'scale', 'FACTOR')
      if (present(scale)) then
         if (scale /= 1.0_wp) advice = 'The points were multiplied by the scale factor '// &
            'given, '//str_real(scale)//': give the factor from the file''s unit to mm '// &
            '(1000 for m, 25.4 for inch, 0.001 for µm): '//option_hint(prefix, 'scale', 'FACTOR')
      end if
      call fatal_error(error, span//': total arc length '//str_real(total)//' mm is outside '// &
         str_real(min_arc_length)//'–'//str_real(max_arc_length)//' mm; are the coordinates '// &
         'in another length unit (m, inch, µm)? '//advice, stat_invalid_input)
   end subroutine check_arc_length

   !> Replace each zig-zag pair — points i and i+1 where the direction turns by more than
   !> [[zigzag_angle]] at both — by the mean of the two (doc/theory.md §5.1). One pass.
   subroutine merge_zigzags(profile, lines)
      type(profile_type), intent(inout) :: profile
      integer, allocatable, intent(inout) :: lines(:)
      real(wp), allocatable :: turn(:), y(:), z(:)
      integer, allocatable :: new_lines(:)
      integer :: i, n, m

      n = profile%size()
      allocate (turn(n))
      turn(:) = turning_angles(profile%y, profile%z)
      if (.not. any(abs(turn) > zigzag_angle)) return
      allocate (y(n), z(n), new_lines(n))
      m = 1
      y(1) = profile%y(1)
      z(1) = profile%z(1)
      new_lines(1) = lines(1)
      i = 2
      do while (i <= n)
         m = m + 1
         if (i <= n - 2) then
            if (abs(turn(i)) > zigzag_angle .and. abs(turn(i + 1)) > zigzag_angle) then
               y(m) = 0.5_wp*(profile%y(i) + profile%y(i + 1))
               z(m) = 0.5_wp*(profile%z(i) + profile%z(i + 1))
               new_lines(m) = lines(i)
               i = i + 2
               cycle
            end if
         end if
         y(m) = profile%y(i)
         z(m) = profile%z(i)
         new_lines(m) = lines(i)
         i = i + 1
      end do
      profile%y = y(:m)
      profile%z = z(:m)
      lines = new_lines(:m)
      call profile%update_arc_length()
   end subroutine merge_zigzags

   !> Reject crossing or touching non-adjacent segments. Brute force with a bounding-box
   !> filter: profiles have a few thousand points and this runs once per profile.
   subroutine check_loops(profile, lines, error)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: i, j, n
      real(wp) :: a(2), b(2), c(2), d(2)

      n = profile%size()
      do i = 1, n - 3
         a = [profile%y(i), profile%z(i)]
         b = [profile%y(i + 1), profile%z(i + 1)]
         do j = i + 2, n - 1
            c = [profile%y(j), profile%z(j)]
            d = [profile%y(j + 1), profile%z(j + 1)]
            if (max(c(1), d(1)) < min(a(1), b(1)) .or. min(c(1), d(1)) > max(a(1), b(1))) cycle
            if (max(c(2), d(2)) < min(a(2), b(2)) .or. min(c(2), d(2)) > max(a(2), b(2))) cycle
            if (.not. segments_meet(a, b, c, d)) cycle
            call fatal_error(error, location(profile, lines, i)//': the profile crosses itself: '// &
               'the segment from point '//str_int(i)//' ('//str_real(a(1))//', '// &
               str_real(a(2))//') meets the segment from point '//str_int(j)//' ('// &
               str_real(c(1))//', '//str_real(c(2))//')'//at_line_text(lines, j)// &
               '; loops are not allowed', stat_invalid_input)
            return
         end do
      end do
   end subroutine check_loops

   !> Whether the closed segments ab and cd have a point in common.
   pure logical function segments_meet(a, b, c, d)
      real(wp), intent(in) :: a(2), b(2), c(2), d(2)
      real(wp) :: d1, d2, d3, d4
      d1 = cross(c, d, a)
      d2 = cross(c, d, b)
      d3 = cross(a, b, c)
      d4 = cross(a, b, d)
      if (((d1 > 0 .and. d2 < 0) .or. (d1 < 0 .and. d2 > 0)) .and. &
          ((d3 > 0 .and. d4 < 0) .or. (d3 < 0 .and. d4 > 0))) then
         segments_meet = .true.
      else
         segments_meet = (d1 == 0 .and. within_box(c, d, a)) .or. &
            (d2 == 0 .and. within_box(c, d, b)) .or. &
            (d3 == 0 .and. within_box(a, b, c)) .or. (d4 == 0 .and. within_box(a, b, d))
      end if
   end function segments_meet

   !> (q − p) × (r − p).
   pure real(wp) function cross(p, q, r)
      real(wp), intent(in) :: p(2), q(2), r(2)
      cross = (q(1) - p(1))*(r(2) - p(2)) - (q(2) - p(2))*(r(1) - p(1))
   end function cross

   pure logical function within_box(p, q, r)
      real(wp), intent(in) :: p(2), q(2), r(2)
      within_box = r(1) >= min(p(1), q(1)) .and. r(1) <= max(p(1), q(1)) .and. &
         r(2) >= min(p(2), q(2)) .and. r(2) <= max(p(2), q(2))
   end function within_box

   !> Flag true corners (doc/theory.md §5.1): a turn above [[kink_angle]] at point i with no turn
   !> above [[kink_quiet_angle]] at any other point closer than [[kink_window]] to it.
   subroutine flag_kinks(profile)
      type(profile_type), intent(inout) :: profile
      real(wp), allocatable :: turn(:)
      integer :: i, j, n
      logical :: quiet

      n = profile%size()
      if (allocated(profile%kink)) deallocate (profile%kink)
      allocate (profile%kink(n), source=.false.)
      turn = turning_angles(profile%y, profile%z)
      do i = 2, n - 1
         if (abs(turn(i)) <= kink_angle) cycle
         quiet = .true.
         do j = i - 1, 2, -1
            if (distance(profile, i, j) >= kink_window) exit
            quiet = quiet .and. abs(turn(j)) <= kink_quiet_angle
         end do
         do j = i + 1, n - 1
            if (distance(profile, i, j) >= kink_window) exit
            quiet = quiet .and. abs(turn(j)) <= kink_quiet_angle
         end do
         profile%kink(i) = quiet
      end do
   end subroutine flag_kinks

   pure real(wp) function distance(profile, i, j)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: i, j
      distance = hypot(profile%y(j) - profile%y(i), profile%z(j) - profile%z(i))
   end function distance

   !> Signed change of direction at each interior point, in (−π, π]; 0 at both ends.
   pure function turning_angles(y, z) result(turn)
      real(wp), intent(in) :: y(:), z(:)
      real(wp) :: turn(size(y))
      real(wp) :: before, after
      integer :: i
      turn = 0.0_wp
      do i = 2, size(y) - 1
         before = atan2(z(i) - z(i - 1), y(i) - y(i - 1))
         after = atan2(z(i + 1) - z(i), y(i + 1) - y(i))
         turn(i) = after - before
         if (turn(i) > pi) turn(i) = turn(i) - two_pi
         if (turn(i) <= -pi) turn(i) = turn(i) + two_pi
      end do
   end function turning_angles

   !> "source, line L" or, without a known line, "source, point i".
   pure function location(profile, lines, i) result(text)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: lines(:), i
      character(len=:), allocatable :: text
      text = source_name(profile)//', '//line_word(lines, i)
   end function location

   pure function line_word(lines, i) result(text)
      integer, intent(in) :: lines(:), i
      character(len=:), allocatable :: text
      if (lines(i) > 0) then
         text = 'line '//str_int(lines(i))
      else
         text = 'point '//str_int(i)
      end if
   end function line_word

   pure function previous_line(lines, i) result(text)
      integer, intent(in) :: lines(:), i
      character(len=:), allocatable :: text
      ! "The point of line N": a file read in reverse order (a wheel's .whl) has its
      ! neighbour on the next line, not the previous one.
      text = 'the previous one'
      if (lines(i - 1) > 0) text = 'the point of line '//str_int(lines(i - 1))
   end function previous_line

   pure function at_line_text(lines, j) result(text)
      integer, intent(in) :: lines(:), j
      character(len=:), allocatable :: text
      text = ''
      if (lines(j) > 0) text = ' at line '//str_int(lines(j))
   end function at_line_text

   pure function source_name(profile) result(text)
      type(profile_type), intent(in) :: profile
      character(len=:), allocatable :: text
      if (allocated(profile%source)) then
         text = profile%source
      else
         text = 'profile'
      end if
   end function source_name



end module shcontact_profile_cleanup
