!> Is a cleaned profile file a wheel or a rail at all? Checks that catch files that read
!> without error but would give a wrong contact (issue 14): columns swapped, a single-point
!> spike. Run on profiles from files only (the built-in and synthetic profiles are exact).
!>
!> 1. **Spikes.** A point where the profile turns back by more than [[spike_angle]] (2π/3)
!>    and that lies more than [[spike_height]] (0.5 mm) off the chord of its neighbours is a
!>    spike (a measuring or editing error); smoothing would spread it over the smoothing
!>    length and bend the running surface. Zig-zag pairs are merged before (clean_profile).
!> 2. **Running surface.** A wheel or rail has a stretch at least [[min_running_width]]
!>    (10 mm) wide where the profile runs towards its end (rail: y increasing, wheel: y
!>    decreasing) with a slope |dz/dy| below [[running_slope]] (0.3): the tread or the rail top.
!>    For a rail the highest point must lie on it, at least 1 mm from its ends. Swapped columns, a profile turned by 90° or
!>    a file of another thing fail here.
module shcontact_profile_plausibility
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, option_hint
   implicit none
   private

   public :: check_plausible
   public :: spike_angle, spike_height, min_running_width, running_slope

   !> Direction change (rad) beyond which a point turns back: 2π/3.
   real(wp), parameter :: spike_angle = 2.0_wp*pi/3.0_wp
   !> Distance (mm) off the chord of its neighbours above which a turning point is a spike.
   real(wp), parameter :: spike_height = 0.5_wp
   !> Narrowest running surface (mm).
   real(wp), parameter :: min_running_width = 10.0_wp
   !> Steepest slope |dz/dy| of the running surface.
   real(wp), parameter :: running_slope = 0.3_wp
   !> The running surface extends at least this far (mm) on both sides of a rail's top.
   real(wp), parameter :: top_margin = 1.0_wp

contains

   !> Reject a profile with a spike or without a running surface (module description).
   subroutine check_plausible(profile, error, line_of_point, option_prefix)
      !> A cleaned profile in canonical form.
      type(profile_type), intent(in) :: profile
      !> stat_invalid_input naming the file, the line and what to check.
      type(error_type), allocatable, intent(out) :: error
      !> File line of each point (0 or absent: unknown).
      integer, intent(in), optional :: line_of_point(:)
      !> How the caller names the reading options in messages (as read_profile).
      character(len=*), intent(in), optional :: option_prefix
      call check_spikes(profile, error, line_of_point)
      if (allocated(error)) return
      call check_running_surface(profile, option_prefix, error, line_of_point)
   end subroutine check_plausible

   subroutine check_spikes(profile, error, line_of_point)
      type(profile_type), intent(in) :: profile
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: line_of_point(:)
      real(wp) :: a(2), b(2), turn, height, la, lb
      integer :: i, n
      n = size(profile%y)
      do i = 2, n - 1
         a = [profile%y(i) - profile%y(i - 1), profile%z(i) - profile%z(i - 1)]
         b = [profile%y(i + 1) - profile%y(i), profile%z(i + 1) - profile%z(i)]
         la = norm2(a)
         lb = norm2(b)
         if (la <= 0.0_wp .or. lb <= 0.0_wp) cycle
         turn = acos(max(-1.0_wp, min(1.0_wp, dot_product(a, b)/(la*lb))))
         if (turn <= spike_angle) cycle
         height = chord_distance(profile, i)
         if (height <= spike_height) cycle
         call fatal_error(error, where(profile, i, line_of_point)//'a spike: the profile '// &
            'turns back by '//str_real(turn*180.0_wp/pi)//' degrees at a point '// &
            str_real(height)//' mm off the line of its neighbours; remove the point '// &
            '(a single point cannot be smoothed away without bending the running surface)', &
            stat_invalid_input)
         return
      end do
   end subroutine check_spikes

   !> Distance of point i from the chord (the segment) between points i−1 and i+1: a spike
   !> along a steep flank lies on the chord's line but far beyond its end.
   pure real(wp) function chord_distance(profile, i) result(d)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: i
      real(wp) :: c(2), p(2), t
      c = [profile%y(i + 1) - profile%y(i - 1), profile%z(i + 1) - profile%z(i - 1)]
      p = [profile%y(i) - profile%y(i - 1), profile%z(i) - profile%z(i - 1)]
      t = 0.0_wp
      if (dot_product(c, c) > 0.0_wp) t = max(0.0_wp, min(1.0_wp, &
         dot_product(p, c)/dot_product(c, c)))
      d = norm2(p - t*c)
   end function chord_distance

   subroutine check_running_surface(profile, prefix, error, line_of_point)
      type(profile_type), intent(in) :: profile
      character(len=*), intent(in), optional :: prefix
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in), optional :: line_of_point(:)
      real(wp) :: sense, dy, dz, width, best, slopes(2)
      integer :: i, n, first, best_first, best_last, top
      logical :: wheel
      n = size(profile%y)
      wheel = profile%kind == profile_kind_wheel
      sense = 1.0_wp
      if (wheel) sense = -1.0_wp
      best = 0.0_wp
      best_first = 1
      best_last = 1
      first = 1
      width = 0.0_wp
      do i = 1, n - 1
         dy = sense*(profile%y(i + 1) - profile%y(i))
         dz = profile%z(i + 1) - profile%z(i)
         if (dy > 0.0_wp .and. abs(dz) <= running_slope*dy) then
            width = width + dy
            if (width > best) then
               best = width
               best_first = first
               best_last = i + 1
            end if
         else
            first = i + 1
            width = 0.0_wp
         end if
      end do
      top = minloc(profile%z, dim=1)
      if (best >= min_running_width .and. (wheel .or. (profile%y(top) - &
          profile%y(best_first) >= top_margin .and. profile%y(best_last) - profile%y(top) >= &
          top_margin))) return
      if (best < min_running_width) then
         call fatal_error(error, source_of(profile)//': no running surface: the '// &
            kind_word(wheel)//' has no stretch of '//str_real(min_running_width)//' mm '// &
            'running towards the '//end_word(wheel)//' with a slope below '// &
            str_real(running_slope)//' (the widest is '//str_real(best)//' mm); are the '// &
            'y and z columns swapped, or the profile turned or in other units ('// &
            option_hint(prefix, 'mirror_z', 'yes')//', '//option_hint(prefix, 'scale', &
            'FACTOR')//')?', stat_invalid_input)
         return
      end if
      call side_slopes(profile, top, slopes)
      if (all(slopes > running_slope)) then
         ! A single point above its neighbours (a measuring or editing error) cuts the running
         ! surface where it stands: name it rather than suggest a turned profile.
         call fatal_error(error, where(profile, top, line_of_point)//'the highest point of '// &
            'the rail (y = '//str_real(profile%y(top))//' mm) sticks out '// &
            str_real(chord_distance(profile, top))//' mm above the line of its neighbours, '// &
            'with slopes '//str_real(slopes(1))//' and '//str_real(slopes(2))//' on its two '// &
            'sides (the running surface has below '//str_real(running_slope)//'): a single '// &
            'point off the profile (a measuring or editing error?); remove it', &
            stat_invalid_input)
      else
         call fatal_error(error, source_of(profile)//': the highest point of the rail '// &
            '(y = '//str_real(profile%y(top))//' mm) is not on its running surface (y = '// &
            str_real(profile%y(best_first))//' to '//str_real(profile%y(best_last))// &
            ' mm); are the y and z columns swapped, or the profile turned ('// &
            option_hint(prefix, 'mirror_z', 'yes')//')?', stat_invalid_input)
      end if
   end subroutine check_running_surface

   !> |dz/dy| of the two segments at point i (0 at the profile's ends): a point steeper than
   !> the running surface on both sides is a single point off the profile.
   pure subroutine side_slopes(profile, i, slopes)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: i
      real(wp), intent(out) :: slopes(2)
      integer :: side, j
      slopes = 0.0_wp
      if (i <= 1 .or. i >= size(profile%y)) return
      do side = 1, 2
         j = i + 2*side - 3
         slopes(side) = huge(1.0_wp)
         if (profile%y(j) /= profile%y(i)) slopes(side) = abs((profile%z(j) - profile%z(i))/ &
            (profile%y(j) - profile%y(i)))
      end do
   end subroutine side_slopes

   pure function kind_word(wheel) result(text)
      logical, intent(in) :: wheel
      character(len=:), allocatable :: text
      text = 'rail'
      if (wheel) text = 'wheel'
   end function kind_word

   pure function end_word(wheel) result(text)
      logical, intent(in) :: wheel
      character(len=:), allocatable :: text
      text = 'field side'
      if (wheel) text = 'flange'
   end function end_word

   pure function source_of(profile) result(text)
      type(profile_type), intent(in) :: profile
      character(len=:), allocatable :: text
      text = 'profile'
      if (allocated(profile%source)) text = profile%source
   end function source_of

   !> "file, line L: " or "file, point i: ".
   pure function where(profile, i, line_of_point) result(text)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: i
      integer, intent(in), optional :: line_of_point(:)
      character(len=:), allocatable :: text
      text = source_of(profile)//', point '//str_int(i)//': '
      if (present(line_of_point)) then
         if (size(line_of_point) >= i) then
            if (line_of_point(i) > 0) text = source_of(profile)//', line '// &
               str_int(line_of_point(i))//': '
         end if
      end if
   end function where

end module shcontact_profile_plausibility
