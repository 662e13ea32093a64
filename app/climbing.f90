!> Flange climbing: where a wheel's flange is steepest, and the states whose contact lies beyond
!> it (towards the flange tip), which a rigid wheelset reaches only by climbing the flange
!> (doc/app.md; `geometry --wheelset` and `run` note them).
module shcontact_app_climbing
   use, intrinsic :: iso_fortran_env, only: error_unit
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_strings, only: str_int, str_format
   use shcontact, only: case_config_type, run_setup_type, profile_type, case_point_type, &
      case_summary_type
   implicit none
   private

   public :: flange_steepest, steep_end_radius, note_climbing_cases

contains

   !> Wheel profile y (mm, the profile's own coordinates, as the table's wheel_y) of the
   !> tip-most point of the flange's steepest part: between the tape circle and the flange tip
   !> (the largest z), the segment nearest the tip whose slope is within 0.5° of the steepest.
   !> A contact beyond it (towards the tip) is one the wheel climbs to: its contact angle falls
   !> again (Nadal). The search runs with the tape circle at y = 0: the profile is moved by the
   !> tape circle's y in its own coordinates as the solver places it (`y_tape`: a MiniProf
   !> wheel's origin, or a file's with flange_back_position = 0, is its flange back).
   pure real(wp) function flange_steepest(profile, y_tape) result(y_s)
      type(profile_type), intent(in) :: profile
      real(wp), intent(in) :: y_tape
      real(wp), parameter :: tolerance = 0.5_wp*pi/180.0_wp
      type(profile_type) :: wheel
      real(wp) :: y_tip, angle, steepest
      integer :: i
      wheel = profile
      wheel%y = profile%y - y_tape
      y_tip = wheel%y(maxloc(wheel%z, 1))
      steepest = 0.0_wp
      do i = 1, size(wheel%y) - 1
         if (.not. in_flange(i)) cycle
         steepest = max(steepest, atan2(abs(wheel%z(i + 1) - wheel%z(i)), &
            abs(wheel%y(i + 1) - wheel%y(i))))
      end do
      ! The tip-most point of the steep segments: their smallest y.
      y_s = 0.0_wp
      do i = 1, size(wheel%y) - 1
         if (.not. in_flange(i)) cycle
         angle = atan2(abs(wheel%z(i + 1) - wheel%z(i)), abs(wheel%y(i + 1) - wheel%y(i)))
         if (angle >= steepest - tolerance) y_s = min(y_s, min(wheel%y(i), wheel%y(i + 1)))
      end do
      y_s = y_s + y_tape
   contains
      pure logical function in_flange(i)
         integer, intent(in) :: i
         in_flange = min(wheel%y(i), wheel%y(i + 1)) >= y_tip .and. &
            max(wheel%y(i), wheel%y(i + 1)) <= 0.0_wp .and. wheel%y(i) /= wheel%y(i + 1)
      end function in_flange
   end function flange_steepest

   !> The rolling radius (mm) at the tip-most point of the flange's steepest part
   !> ([[flange_steepest]]): a contact with a larger radius lies beyond it, towards the tip.
   pure real(wp) function steep_end_radius(setup) result(radius)
      type(run_setup_type), intent(in) :: setup
      real(wp) :: y_s
      integer :: i
      y_s = flange_steepest(setup%wheel, setup%prepared%y_tape)
      i = minloc(abs(setup%wheel%y - y_s), 1)
      radius = setup%prepared%track%nominal_radius + setup%wheel%z(i) - setup%prepared%z_tape
   end function steep_end_radius

   !> A note on stderr when solved cases of a run have their main contact beyond the flange's
   !> steepest part (rolling radius above [[steep_end_radius]]): how many, their t_y range.
   subroutine note_climbing_cases(config, setup, summaries, first)
      type(case_config_type), intent(in) :: config
      type(run_setup_type), intent(in) :: setup
      !> The summaries of cases first, first + 1, ...
      type(case_summary_type), intent(in) :: summaries(:)
      integer, intent(in) :: first
      !> A yawed contact's radius differs from the profile's by a few hundredths of a mm.
      real(wp), parameter :: margin = 0.1_wp
      real(wp) :: radius, lo, hi
      type(case_point_type) :: point
      integer :: k, n
      radius = steep_end_radius(setup)
      n = 0
      lo = huge(1.0_wp)
      hi = -huge(1.0_wp)
      do k = 1, size(summaries)
         if (summaries(k)%stat /= 0) cycle
         if (.not. (summaries(k)%r0 > radius + margin)) cycle
         n = n + 1
         point = config%case_point(first + k - 1)
         lo = min(lo, point%t_y)
         hi = max(hi, point%t_y)
      end do
      if (n == 0) return
      write (error_unit, '(a)') 'shcontact: note: '//str_int(n)//' solved case(s) (t_y '// &
         str_format(lo, '(f0.3)')//' … '//str_format(hi, '(f0.3)')//' mm) touch the '// &
         'wheel''s flange beyond its steepest part (rolling radius above '// &
         str_format(radius, '(f0.2)')//' mm): flange-climbing states, which a rigid wheelset '// &
         'reaches only by climbing the flange (geometry --wheelset gives the shift where they begin)'
   end subroutine note_climbing_cases

end module shcontact_app_climbing
