!> Mathematical constants in working precision.
module shcontact_core_constants
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: pi, two_pi, half_pi

   !> Archimedes' constant.
   real(wp), parameter :: pi = 3.141592653589793238462643383279502884_wp
   !> 2π.
   real(wp), parameter :: two_pi = 2.0_wp*pi
   !> π/2.
   real(wp), parameter :: half_pi = 0.5_wp*pi

end module shcontact_core_constants
