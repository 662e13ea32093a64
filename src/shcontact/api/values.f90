!> The flat result layouts of the legacy Fortran and C interfaces (doc/api.md §"Layout",
!> include/shcontact.fi, include/shcontact.h): a contact result as one array of numbers, each at
!> a fixed 1-based index named here. The include file and the header repeat these numbers; the
!> test suite `api` checks that they agree.
!>
!> * patch layout, [[patch_value_count]] = 17: one patch's forces and geometry;
!> * result layout, [[result_value_count]] = 25: the main (most loaded) patch, then the counts and
!>   the totals of the wheel;
!> * kinematic layout, [[kinematic_value_count]] = 29: the result layout followed by the main
!>   patch's creepages (ν_x, ν_y, φ) and the longitudinal lead x_track of its contact point,
!>   which a vehicle code needs after a kinematic call. The per-patch form uses the same
!>   indices: patch values in 1–17 and 26–29, the result's 18–25.
!>
!> All values are in the wheel's side frame (the track frame for the right wheel, its mirror
!> image y ↦ −y for the left one) except y_track, the true track coordinate.
module shcontact_api_values
   use shcontact_core_kinds, only: wp
   use shcontact_api_solver, only: contact_result_type, patch_result_type
   implicit none
   private

   public :: patch_value_count, result_value_count, kinematic_value_count
   public :: value_fx, value_fy, value_mz, value_fn, value_fx_norm, value_fy_norm, &
      value_fy_track, value_fz_track, value_approach, value_area, value_p_max, value_gamma0, &
      value_r0, value_y_track, value_z_track, value_coulomb, value_adhesion
   public :: value_n_patches, value_n_loaded, value_main_patch, value_sum_fx, value_sum_fy, &
      value_sum_fz, value_sum_fn, value_dz
   public :: value_nu_x, value_nu_y, value_phi, value_x_track
   public :: patch_values, result_values, kinematic_values

   !> Patch layout: F_x, F_y (N, contact plane), M_z about the reference point (N·mm), F_n (N).
   integer, parameter :: value_fx = 1, value_fy = 2, value_mz = 3, value_fn = 4
   !> F_x/(μF_n), F_y/(μF_n).
   integer, parameter :: value_fx_norm = 5, value_fy_norm = 6
   !> F_y,track, F_z,track (N, z down).
   integer, parameter :: value_fy_track = 7, value_fz_track = 8
   !> Approach δ (mm), contact area (mm²), largest strip peak pressure (MPa).
   integer, parameter :: value_approach = 9, value_area = 10, value_p_max = 11
   !> Contact angle γ₀ (rad, CONTACT's sign), rolling radius r₀ (mm).
   integer, parameter :: value_gamma0 = 12, value_r0 = 13
   !> Reference point y_track, z_track (mm, z down).
   integer, parameter :: value_y_track = 14, value_z_track = 15
   !> Coulomb check max|p|/(μp_n), adhesion area fraction.
   integer, parameter :: value_coulomb = 16, value_adhesion = 17
   !> Length of the patch layout.
   integer, parameter :: patch_value_count = 17

   !> Result layout after the main patch: patches found, loaded, index of the main patch.
   integer, parameter :: value_n_patches = 18, value_n_loaded = 19, value_main_patch = 20
   !> Totals over the loaded patches, side frame (N): ΣF_x, ΣF_y,track, ΣF_z,track, ΣF_n.
   integer, parameter :: value_sum_fx = 21, value_sum_fy = 22, value_sum_fz = 23, &
      value_sum_fn = 24
   !> Rigid vertical approach Δz of the wheel (mm), vertical load.
   integer, parameter :: value_dz = 25
   !> Length of the result layout.
   integer, parameter :: result_value_count = 25

   !> Kinematic layout after the result layout: the patch's creepages (wheel relative to rail;
   !> φ in rad/mm) and the longitudinal position of its reference point (mm, forward).
   integer, parameter :: value_nu_x = 26, value_nu_y = 27, value_phi = 28, value_x_track = 29
   !> Length of the kinematic layout.
   integer, parameter :: kinematic_value_count = 29

contains

   !> A patch in the patch layout.
   pure subroutine patch_values(patch, values)
      !> The patch.
      type(patch_result_type), intent(in) :: patch
      !> Its values (at least patch_value_count).
      real(wp), intent(out) :: values(:)
      values(value_fx) = patch%fx
      values(value_fy) = patch%fy
      values(value_mz) = patch%mz
      values(value_fn) = patch%fn
      values(value_fx_norm) = patch%fx_norm
      values(value_fy_norm) = patch%fy_norm
      values(value_fy_track) = patch%fy_track
      values(value_fz_track) = patch%fz_track
      values(value_approach) = patch%approach
      values(value_area) = patch%area
      values(value_p_max) = patch%p_max
      values(value_gamma0) = patch%gamma0
      values(value_r0) = patch%r0
      values(value_y_track) = patch%y_track
      values(value_z_track) = patch%z_track
      values(value_coulomb) = patch%coulomb_ratio
      values(value_adhesion) = patch%adhesion_fraction
   end subroutine patch_values

   !> A result in the result layout: the main patch, then the counts and totals.
   pure subroutine result_values(result, values)
      !> The result.
      type(contact_result_type), intent(in) :: result
      !> Its values (at least result_value_count).
      real(wp), intent(out) :: values(:)
      call patch_values(result%main, values(1:patch_value_count))
      values(value_n_patches) = real(result%n_patches, wp)
      values(value_n_loaded) = real(result%n_loaded, wp)
      values(value_main_patch) = real(result%main_patch, wp)
      values(value_sum_fx) = result%track%fx
      values(value_sum_fy) = result%track%fy
      values(value_sum_fz) = result%track%fz
      values(value_sum_fn) = result%track%fn
      values(value_dz) = result%dz
   end subroutine result_values

   !> A result in the kinematic layout, for its main patch (k absent) or for patch k: the patch's
   !> values in 1–17 and 26–29, the result's counts and totals in 18–25.
   pure subroutine kinematic_values(result, values, k)
      !> The result.
      type(contact_result_type), intent(in) :: result
      !> Its values (at least kinematic_value_count).
      real(wp), intent(out) :: values(:)
      !> Patch index, 1 to result%n_patches (default: the main patch).
      integer, intent(in), optional :: k
      call result_values(result, values(1:result_value_count))
      if (present(k)) then
         call patch_values(result%patch(k), values(1:patch_value_count))
         call kinematic_extras(result%patch(k), values)
      else
         call kinematic_extras(result%main, values)
      end if
   end subroutine kinematic_values

   !> The creepages and the x lead of a patch at their places in the kinematic layout.
   pure subroutine kinematic_extras(patch, values)
      type(patch_result_type), intent(in) :: patch
      real(wp), intent(inout) :: values(:)
      values(value_nu_x) = patch%nu_x
      values(value_nu_y) = patch%nu_y
      values(value_phi) = patch%phi
      values(value_x_track) = patch%x_track
   end subroutine kinematic_extras

end module shcontact_api_values
