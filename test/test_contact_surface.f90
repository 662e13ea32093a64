!> The direction of the strips' pressure (`&tangential contact_surface`, doc/geometry.md "The
!> direction of the pressure"): the interface angle γ_n = γ₀ + atan(w' + g'/2) of the prepared
!> table and of the strips against its closed form on an asymmetric polynomial gap, and the
!> flange normal forces of the kinematic flange set's pure-rolling cases (CONTACT's conformal
!> approach, data/exact/kinematic_flange/) with both choices, held to doc/validation.md §6.8's
!> table. Needs nothing outside the repository.
module test_contact_surface
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_real
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_track, only: track_type
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load, &
      interface_contact_angles
   use shcontact_tangential_options, only: tangential_options_type, surface_wheel, &
      surface_interface
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, &
      contact_result_type, load_vertical_force
   use test_semihertz, only: polynomial_patch
   use test_validation, only: read_columns
   implicit none
   private
   public :: collect_contact_surface

   !> The asymmetric gap g = B₀y² + c₃y³ (1/mm, 1/mm²), the wheel's slope w' = k y in the table's
   !> frame (1/mm) and its contact angle γ₀ (rad), as on a flange (doc/geometry.md).
   real(wp), parameter :: b0 = 1.0_wp/600, c3 = 5.0e-5_wp, k_wheel = 0.02_wp, &
      gamma_flange = -1.2_wp, spacing = 0.01_wp

   !> The pure-rolling cases of kinematic_conformal.csv (Y_WS mm, yaw mrad) and (F_n,ours −
   !> F_n,CONTACT)/F_n,CONTACT with `contact_surface` 'wheel' and 'interface' (the table of
   !> doc/validation.md §6.8), held within ±tolerance.
   integer, parameter :: n_cases = 15
   real(wp), parameter :: held_wheel(n_cases) = [0.0005_wp, 0.0033_wp, 0.0048_wp, &
      0.0430_wp, 0.0211_wp, 0.0146_wp, 0.0327_wp, 0.0183_wp, 0.0143_wp, &
      -0.0144_wp, -0.0008_wp, 0.0005_wp, -0.0436_wp, -0.0182_wp, -0.0041_wp]
   real(wp), parameter :: held_interface(n_cases) = [-0.0002_wp, 0.0032_wp, 0.0049_wp, &
      0.0435_wp, 0.0197_wp, 0.0145_wp, 0.0343_wp, 0.0185_wp, 0.0142_wp, &
      0.0328_wp, 0.0147_wp, 0.0081_wp, 0.0002_wp, 0.0031_wp, 0.0058_wp]
   real(wp), parameter :: tolerance = 0.002_wp
   real(wp), parameter :: vertical_load = 64700.0_wp, mu = 0.3_wp

contains

   !> Collect the tests.
   subroutine collect_contact_surface(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('interface_angle_closed_form', test_closed_form), &
         new_unittest('flange_normal_forces', test_flange_forces)]
   end subroutine collect_contact_surface

   !> γ_n − γ = atan(w' + g'/2) − atan(w') at every table point, to the central difference's
   !> c₃h² (the table), and at the strips to linear interpolation's error; γ_n = γ₀ at the
   !> reference point, where g' = 0.
   subroutine test_closed_form(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geom
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(lib_error), allocatable :: err
      real(wp) :: y, expected, worst
      integer :: j, n, i0

      call polynomial_patch(geom, 1.0_wp/920, b0, 10.0_wp, spacing, c3=c3, gamma0=gamma_flange)
      geom%gamma = gamma_flange + atan(k_wheel*geom%y)
      call prepare_normal_contact(contact, geom, normal_options_type(), material_type(), err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      n = size(geom%y)
      ! Prepared for the default ('wheel'): the wheel's angles, no interface computed.
      call check(error, all(contact%geometry%gamma_n(1:n) == geom%gamma(1:n)), &
         message='γ_n without contact_surface = ''interface'' is not the wheel''s γ')
      if (allocated(error)) return
      call interface_contact_angles(contact)
      worst = 0.0_wp
      do j = 2, n - 1
         y = geom%y(j)
         expected = atan(interface_slope(y)) - atan(k_wheel*y)
         worst = max(worst, abs((contact%geometry%gamma_n(j) - geom%gamma(j)) - expected))
      end do
      call check(error, worst <= 1.0e-7_wp, message='table: |γ_n − γ − (atan(w''+g''/2) − '// &
         'atan(w''))| = '//str_real(worst)//' rad, expected ≤ 1e-7')
      if (allocated(error)) return
      i0 = (n + 1)/2
      call check(error, abs(contact%geometry%gamma_n(i0) - gamma_flange) <= 1.0e-7_wp, &
         message='γ_n at the reference point '//str_real(contact%geometry%gamma_n(i0))// &
         ' rad, expected γ₀ = '//str_real(gamma_flange))
      if (allocated(error)) return
      ! The asymmetry makes it differ from the wheel's angle by more than the tolerances.
      call check(error, maxval(abs(contact%geometry%gamma_n(2:n - 1) - geom%gamma(2:n - 1))) &
         > 1.0e-3_wp, message='γ_n equals the wheel''s γ: the test does not test')
      if (allocated(error)) return

      call solve_load(contact, 20000.0_wp, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      worst = 0.0_wp
      do j = 1, patch%n_strips
         if (.not. (patch%a(j) > 0.0_wp)) cycle
         ! Strip y from the loaded reference point; the table's y from its origin.
         y = patch%y(j) + patch%y_shift
         expected = gamma_flange + atan(interface_slope(y))
         worst = max(worst, abs(patch%gamma_n(j) - expected))
      end do
      call check(error, worst <= 1.0e-6_wp, message='strips: |γ_n − γ₀ − atan(w''+g''/2)| = '// &
         str_real(worst)//' rad, expected ≤ 1e-6')
   end subroutine test_closed_form

   !> w' + g'/2 of the test's table at y (mm).
   pure real(wp) function interface_slope(y)
      real(wp), intent(in) :: y
      interface_slope = k_wheel*y + 0.5_wp*(2.0_wp*b0*y + 3.0_wp*c3*y*y)
   end function interface_slope

   !> The flange set's pure-rolling cases with both choices: the relative F_n differences of
   !> doc/validation.md §6.8 within ±0.002; 'interface' brings Y_WS 8.5 mm, yaw −8 mrad within
   !> 1.2 % of CONTACT's conformal F_n where 'wheel' is 4.4 % low, and moves no F_n by more than
   !> 5 %.
   subroutine test_flange_forces(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: file = 'data/exact/kinematic_flange/kinematic_conformal.csv'
      character(len=*), parameter :: names(10) = [character(len=13) :: 'y_ws_mm', 'yaw_rad', &
         'vs_mm_s', 'vy_mm_s', 'vyaw_rad_s', 'vpitch_rad_s', 'xi_k', 'eta_k', 'omega_k', 'fn_N']
      real(wp), allocatable :: v(:, :)
      real(wp) :: dfn(n_cases, 2)
      integer :: i, m, choice
      type(contact_solver_type) :: solver
      type(track_type) :: track
      type(contact_result_type) :: result
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: lib

      call read_columns(file, names, v, error, row_tag='ok')
      if (allocated(error)) return
      track%rail_canted = .true.
      call solver%init('builtin:S1002', 'builtin:UIC60-canted', lib, track=track, &
         material=material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, friction=mu))
      if (allocated(lib)) then
         call test_failed(error, lib%message)
         return
      end if
      do choice = 1, 2
         options = tangential_options_type()
         options%contact_surface = merge(surface_wheel, surface_interface, choice == 1)
         call solver%set_options(lib, tangential=options)
         if (allocated(lib)) then
            call test_failed(error, lib%message)
            return
         end if
         m = 0
         do i = 1, size(v, 1)
            if (any(v(i, 7:9) /= 0.0_wp)) cycle
            m = m + 1
            if (m > n_cases) exit
            call solver%solve_kinematic(wheelset_state_type(y_ws=v(i, 1), yaw=v(i, 2), &
               v_forward=v(i, 3), v_lateral=v(i, 4), yaw_rate=v(i, 5), pitch_rate=v(i, 6)), &
               contact_load_type(load_vertical_force, vertical_load), result, lib)
            if (allocated(lib)) then
               call test_failed(error, file//', Y_WS '//str_real(v(i, 1))//': '//lib%message)
               return
            end if
            ! Every case is one CONTACT patch and one loaded patch of ours.
            dfn(m, choice) = sum(result%patch(1:result%n_loaded)%fn)/v(i, 10) - 1.0_wp
         end do
      end do
      call check(error, m == n_cases, message=file//': pure-rolling cases found: '// &
         str_real(real(m, wp)))
      if (allocated(error)) return
      do i = 1, n_cases
         call check(error, abs(dfn(i, 1) - held_wheel(i)) <= tolerance .and. &
            abs(dfn(i, 2) - held_interface(i)) <= tolerance, message=file// &
            ': pure-rolling case '//str_real(real(i, wp))//', ΔF_n/F_n wheel / interface '// &
            str_real(dfn(i, 1))//' / '//str_real(dfn(i, 2))//', held '// &
            str_real(held_wheel(i))//' / '//str_real(held_interface(i)))
         if (allocated(error)) return
      end do
      call check(error, abs(dfn(13, 2)) <= 0.012_wp .and. abs(dfn(13, 1)) >= 0.04_wp, &
         message='Y_WS 8.5 mm, yaw −8 mrad: ΔF_n/F_n wheel '//str_real(dfn(13, 1))// &
         ', interface '//str_real(dfn(13, 2)))
      if (allocated(error)) return
      call check(error, maxval(abs(dfn(:, 2) - dfn(:, 1))) <= 0.05_wp, &
         message='the interface moves an F_n by '//str_real(maxval(abs(dfn(:, 2) - dfn(:, 1)))))
   end subroutine test_flange_forces

end module test_contact_surface
