!> The validation case (../shared/reference/README.md §2): S1002 (MBench_S1002_v3.prw) on UIC60
!> 1:40 (MBench_UIC60_v3.prr, already canted), the Manchester track, right wheel, zero roll and
!> yaw; the geometry of one lateral shift, and its normal solution under a prescribed normal force.
module validate_case
   use shcontact, only: wp, error_type, profile_type, read_profile, clean_profile, track_type, &
      contact_options_type, prepared_profiles_type, prepare_profiles, find_contact_patches, &
      wheelset_position_type, patch_geometry_type, material_type, normal_options_type, &
      new_normal_options, normal_contact_type, prepare_normal_contact, solve_load, &
      normal_patch_type
   implicit none
   private

   public :: load_manchester, deepest_patch, solve_normal, quadratic_geometry, reference_material

contains

   !> Read and clean both profiles and prepare them on the Manchester track (doc/theory.md §5.2).
   subroutine load_manchester(profiles_dir, prepared, error)
      !> Directory holding MBench_S1002_v3.prw and MBench_UIC60_v3.prr (with a trailing '/').
      character(len=*), intent(in) :: profiles_dir
      !> The prepared profiles.
      type(prepared_profiles_type), intent(out) :: prepared
      !> Set when a file cannot be read or used.
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(track_type) :: track

      call read_profile(profiles_dir//'MBench_S1002_v3.prw', wheel, error)
      if (allocated(error)) return
      call clean_profile(wheel, error)
      if (allocated(error)) return
      call read_profile(profiles_dir//'MBench_UIC60_v3.prr', rail, error)
      if (allocated(error)) return
      call clean_profile(rail, error)
      if (allocated(error)) return
      ! The Manchester rail file carries its 1:40 inclination already (CANT = 0 in CONTACT).
      track%rail_canted = .true.
      call prepare_profiles(wheel, rail, track, contact_options_type(), prepared, error)
   end subroutine load_manchester

   !> The deepest contact patch of the right wheel at lateral shift y_ws, no roll.
   subroutine deepest_patch(prepared, y_ws, geometry, error)
      !> The prepared profiles.
      type(prepared_profiles_type), intent(in) :: prepared
      !> Lateral shift Y_WS (mm).
      real(wp), intent(in) :: y_ws
      !> The geometry of the deepest patch.
      type(patch_geometry_type), intent(out) :: geometry
      !> Set when no contact is found.
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)

      call find_contact_patches(prepared, wheelset_position_type(y_ws=y_ws), patches, error)
      if (allocated(error)) return
      geometry = patches(1)
   end subroutine deepest_patch

   !> The normal solution of one patch under a prescribed normal force.
   subroutine solve_normal(geometry, material, method, reduction, n_strips, load, patch, error, &
      epsilon)
      !> The patch geometry.
      type(patch_geometry_type), intent(in) :: geometry
      !> Elastic constants.
      type(material_type), intent(in) :: material
      !> 'semi-hertz' or 'hertz'.
      character(len=*), intent(in) :: method
      !> 'local-hertz' or 'constant'.
      character(len=*), intent(in) :: reduction
      !> Strips per patch.
      integer, intent(in) :: n_strips
      !> Normal force (N).
      real(wp), intent(in) :: load
      !> The normal solution.
      type(normal_patch_type), intent(out) :: patch
      !> Set for bad options or when the table cannot carry the load.
      type(error_type), allocatable, intent(out) :: error
      !> ε of the constant reduction (default 0.55).
      real(wp), intent(in), optional :: epsilon
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact

      call new_normal_options(options, error, method=method, reduction=reduction, &
         n_strips=n_strips, epsilon=epsilon)
      if (allocated(error)) return
      call prepare_normal_contact(contact, geometry, options, material, error)
      if (allocated(error)) return
      call solve_load(contact, load, patch, error)
   end subroutine solve_normal

   !> A Hertzian patch geometry: constant curvatures A, B, gap B y², flat contact (γ = 0), constant
   !> rolling radius, on a table wide enough for any ellipse up to |y| = 30 mm. Solved with
   !> method 'hertz' it gives the ellipse of CONTACT's `fastsim_hertz`/`exact_hertz` runs.
   pure subroutine quadratic_geometry(curv_a, curv_b, r0, geometry)
      !> Curvatures A (rolling direction) and B (lateral) (1/mm).
      real(wp), intent(in) :: curv_a, curv_b
      !> Rolling radius (mm).
      real(wp), intent(in) :: r0
      !> The geometry.
      type(patch_geometry_type), intent(out) :: geometry
      integer, parameter :: half = 1200
      integer :: j

      geometry%h = 0.025_wp
      geometry%r0 = r0
      geometry%gamma0 = 0.0_wp
      geometry%y = [(j*geometry%h, j=-half, half)]
      geometry%gap = curv_b*geometry%y**2
      allocate (geometry%curv_a(2*half + 1), source=curv_a)
      allocate (geometry%curv_b(2*half + 1), source=curv_b)
      allocate (geometry%gamma(2*half + 1), source=0.0_wp)
      allocate (geometry%r_wheel(2*half + 1), source=r0)
   end subroutine quadratic_geometry

   !> The reference's material (../shared/reference/README.md §2): G = 82670 MPa, ν = 0.27, μ = 0.3.
   pure type(material_type) function reference_material() result(material)
      material = material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, friction=0.3_wp)
   end function reference_material

end module validate_case
