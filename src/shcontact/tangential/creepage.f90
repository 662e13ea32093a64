!> Creepages of one contact patch at its reference point (doc/theory.md §0, decision 2).
module shcontact_tangential_creepage
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   implicit none
   private

   public :: creepage_type, check_creepage

   !> Velocity of the wheel surface relative to the rail surface at the reference point, divided
   !> by the rolling speed, in the contact frame (x rolling, y lateral towards the field side):
   !> rigid slip w(x, y) = (ν_x − φ y, ν_y + φ x) (doc/theory.md §0). CONTACT reports the rail's side
   !> (rail relative to wheel): all three signs flip.
   type :: creepage_type
      !> Longitudinal creepage ν_x (dimensionless).
      real(wp) :: nu_x = 0.0_wp
      !> Lateral creepage ν_y (dimensionless), in the contact plane of the reference point.
      real(wp) :: nu_y = 0.0_wp
      !> Spin creepage φ about the reference normal (rad/mm; 1 m⁻¹ = 1e-3 mm⁻¹).
      real(wp) :: phi = 0.0_wp
   end type creepage_type

contains

   !> Reject creepages that are not finite numbers.
   pure subroutine check_creepage(creepage, error)
      !> The creepages to check.
      type(creepage_type), intent(in) :: creepage
      !> Set when a value is NaN or infinite.
      type(error_type), allocatable, intent(out) :: error

      if (.not. (ieee_is_finite(creepage%nu_x) .and. ieee_is_finite(creepage%nu_y) .and. &
         ieee_is_finite(creepage%phi))) then
         call fatal_error(error, 'creepages (nu_x, nu_y, phi): expected finite numbers, found '// &
            'NaN or Inf', stat_invalid_input)
      end if
   end subroutine check_creepage

end module shcontact_tangential_creepage
