!> Elastic and friction data of the wheel–rail pair (identical elastic bodies).
module shcontact_core_material
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type
   use shcontact_core_ranges, only: check_range, variables
   implicit none
   private

   public :: material_type, check_material

   !> Steel on steel: both bodies share G and ν (quasi-identity, doc/theory.md §0), Coulomb friction.
   !> The defaults are the variable table's (`&material`, shcontact_core_ranges).
   type :: material_type
      !> Shear modulus G (N/mm² = MPa).
      real(wp) :: shear_modulus = variables(findloc(variables%name, 'shear_modulus', 1, &
         mask=variables%group == 'material'))%default
      !> Poisson's ratio ν (dimensionless), 0 ≤ ν < 0.5.
      real(wp) :: poisson = variables(findloc(variables%name, 'poisson', 1, &
         mask=variables%group == 'material'))%default
      !> Coefficient of friction μ (dimensionless), 0.001 ≤ μ ≤ 10 (shcontact_core_ranges).
      real(wp) :: friction = variables(findloc(variables%name, 'friction', 1, &
         mask=variables%group == 'material'))%default
   contains
      !> Combined modulus E* = G/(1 − ν) of two identical bodies (doc/theory.md §1.2), MPa.
      procedure :: e_star
   end type material_type

contains

   !> E* = G/(1 − ν) = E/(2(1 − ν²)) (doc/theory.md §1.2), MPa.
   elemental function e_star(self) result(es)
      class(material_type), intent(in) :: self
      real(wp) :: es
      es = self%shear_modulus/(1.0_wp - self%poisson)
   end function e_star

   !> Reject non-physical material data with a message naming the value and the allowed range.
   pure subroutine check_material(material, error)
      !> The data to check.
      type(material_type), intent(in) :: material
      !> Set when a value is out of range.
      type(error_type), allocatable, intent(out) :: error
      ! The app's ranges (shcontact_core_ranges): one table for the app and the library.
      call check_range('material%shear_modulus', material%shear_modulus, 'shear modulus G', &
         error)
      if (.not. allocated(error)) call check_range('material%poisson', material%poisson, &
         'Poisson ratio nu', error)
      if (.not. allocated(error)) call check_range('material%friction', material%friction, &
         'friction coefficient mu', error)
   end subroutine check_material

end module shcontact_core_material
