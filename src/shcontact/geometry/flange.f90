!> The wheel flange's steepest part and flange climbing (doc/kinematics.md, "What the call
!> covers"; doc/app.md): beyond the tip-most point of the flange's steepest part the contact
!> angle falls again (Nadal), so a rigid wheelset whose contact lies there has climbed the
!> flange. The solver flags such a result (`contact_result_type%climbing`), the program notes
!> such cases and states (`run`, `geometry --wheelset`).
module shcontact_geometry_flange
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_profile_points, only: profile_type
   implicit none
   private

   public :: flange_steepest, steep_end_radius, climbing_margin

   !> A contact counts as beyond the steep part when its rolling radius exceeds the steep end's
   !> by more than this (mm): a yawed contact's radius differs from the profile's by a few
   !> hundredths of a millimetre.
   real(wp), parameter :: climbing_margin = 0.1_wp
   !> Slopes within this angle of the steepest count as the steepest part (rad, 0.5°).
   real(wp), parameter :: steep_tolerance = 0.5_wp*pi/180.0_wp
   !> A profile whose flange is nowhere steeper than this (rad, 45°) has no flange to climb (a
   !> flat wheel): no steep end.
   real(wp), parameter :: min_flange_angle = 0.25_wp*pi

contains

   !> Wheel profile y (mm, the profile's own coordinates) of the tip-most point of the flange's
   !> steepest part: between the tape circle and the flange tip (the largest z), the segment
   !> nearest the tip whose slope is within 0.5° of the steepest. The search runs with the tape
   !> circle at y = 0: the profile is moved by the tape circle's y in its own coordinates as the
   !> solver places it (`y_tape`: a MiniProf wheel's origin, or a file's with
   !> flange_back_position = 0, is its flange back).
   pure real(wp) function flange_steepest(profile, y_tape) result(y_s)
      type(profile_type), intent(in) :: profile
      real(wp), intent(in) :: y_tape
      real(wp) :: steepest
      call steepest_part(profile, y_tape, y_s, steepest)
   end function flange_steepest

   !> The rolling radius (mm) at the tip-most point of the flange's steepest part
   !> ([[flange_steepest]]), the wheel's tape circle at (y_tape, z_tape) of its profile with the
   !> nominal radius: a contact with a larger radius lies beyond it, towards the tip. Huge for a
   !> wheel without a flange (nowhere steeper than 45°).
   pure real(wp) function steep_end_radius(profile, y_tape, z_tape, nominal_radius) &
         result(radius)
      type(profile_type), intent(in) :: profile
      real(wp), intent(in) :: y_tape, z_tape, nominal_radius
      real(wp) :: y_s, steepest
      integer :: i
      radius = huge(1.0_wp)
      if (profile%size() < 2) return
      call steepest_part(profile, y_tape, y_s, steepest)
      if (steepest < min_flange_angle) return
      i = minloc(abs(profile%y - y_s), 1)
      radius = nominal_radius + profile%z(i) - z_tape
   end function steep_end_radius

   !> The tip-most point y_s of the flange's steepest part and that slope (rad).
   pure subroutine steepest_part(profile, y_tape, y_s, steepest)
      type(profile_type), intent(in) :: profile
      real(wp), intent(in) :: y_tape
      real(wp), intent(out) :: y_s, steepest
      real(wp), allocatable :: y(:), z(:)
      real(wp) :: y_tip, angle
      integer :: i
      y = profile%y - y_tape
      z = profile%z
      y_tip = y(maxloc(z, 1))
      steepest = 0.0_wp
      do i = 1, size(y) - 1
         if (.not. in_flange(i)) cycle
         steepest = max(steepest, atan2(abs(z(i + 1) - z(i)), abs(y(i + 1) - y(i))))
      end do
      ! The tip-most point of the steep segments: their smallest y.
      y_s = 0.0_wp
      do i = 1, size(y) - 1
         if (.not. in_flange(i)) cycle
         angle = atan2(abs(z(i + 1) - z(i)), abs(y(i + 1) - y(i)))
         if (angle >= steepest - steep_tolerance) y_s = min(y_s, min(y(i), y(i + 1)))
      end do
      y_s = y_s + y_tape
   contains
      pure logical function in_flange(i)
         integer, intent(in) :: i
         in_flange = min(y(i), y(i + 1)) >= y_tip .and. max(y(i), y(i + 1)) <= 0.0_wp .and. &
            y(i) /= y(i + 1)
      end function in_flange
   end subroutine steepest_part

end module shcontact_geometry_flange
