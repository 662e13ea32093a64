!> Never past Coulomb (issue 28): the tangential force of every patch stays inside the traction
!> bound, |f| = |F_t|/(μF_n) ≤ 1 + 1e-12, on every case of the exact-theory sets of the repository
!> (data/exact/: the Hertz ellipses of the correction table and its check, and, when
!> the external data are there (SHCONTACT_EXTERNAL_DATA), every patch of the 21 wheel positions and the shared DOEs) and
!> on a seeded random DOE near full slip over every bound and correction; and the Coulomb check
!> `coulomb_ratio` is that of the corrected tractions (doc/tangential.md "Never past Coulomb").
module test_coulomb
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type
   use shcontact_geometry_contact, only: contact_options_type, find_contact_patches
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, new_normal_options
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load
   use shcontact_normal_patch, only: normal_patch_type, ellipse_strip_patch
   use shcontact_tangential_options, only: tangential_options_type, method_fastsim, &
      bound_ellipsoidal, bound_clipped, spin_additive, spin_geometric, &
      spin_flexibility_spin, spin_flexibility_longitudinal, correction_none, &
      correction_exact_ellipse
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim, only: prepare_fastsim
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use shcontact_tangential_ellipse_correction, only: table_node_case
   use shcontact_tangential_ellipse_table, only: table_t_phi
   use test_validation, only: read_columns, manchester_profiles, skip_without_profiles, &
      summary_values, two_patch_solution
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, &
      contact_result_type, load_vertical_force, load_normal_force
   use test_external_data, only: external_file
   implicit none
   private
   public :: collect_coulomb

   !> The bound |f| ≤ 1 + this.
   real(wp), parameter :: slack = 1.0e-12_wp
   !> The wheel positions of data/exact/ (its README).
   character(len=*), parameter :: positions(21) = [character(len=7) :: 'yws-6p0', 'yws-4p0', &
      'yws-2p0', 'yws-1p0', 'yws0p5', 'yws0p75', 'yws1p0', 'yws1p25', 'yws1p5', 'yws2p0', &
      'yws2p5', 'yws3p0', 'yws3p5', 'yws4p0', 'yws4p4', 'yws4p6', 'yws5p0', 'yws5p3', &
      'yws6p0', 'yws6p5', 'yws7p0']

contains

   !> Collect the tests.
   subroutine collect_coulomb(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('ellipse_sets_within_coulomb', test_ellipse_sets), &
         new_unittest('position_sets_within_coulomb', test_position_sets), &
         new_unittest('position_sets_alternative_reductions', test_position_alternatives), &
         new_unittest('two_lobe_positions_within_coulomb', test_two_lobe_positions), &
         new_unittest('kinematic_sample_within_coulomb', test_kinematic_sample), &
         new_unittest('random_doe_near_full_slip', test_random_doe), &
         new_unittest('hertz_method_within_coulomb', test_hertz_method), &
         new_unittest('coulomb_ratio_of_corrected_tractions', test_ratio_after_correction) &
         ]
   end subroutine collect_coulomb

   !> The table's material (data/exact/README.md).
   pure type(material_type) function table_material()
      table_material = material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, friction=0.3_wp)
   end function table_material

   !> Every case of data/exact/ellipse_check.csv (370, ten ellipses) and of ellipse_table.csv
   !> (the correction table's 33 120 nodes, on the ellipses of its a/b with area 36 mm²), solved
   !> with the defaults and without the correction.
   subroutine test_ellipse_sets(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: v(:, :)
      type(normal_patch_type) :: patch
      integer :: i, n

      call read_columns('data/exact/ellipse_check.csv', [character(len=10) :: 'a_mm', 'b_mm', &
         'nu_x', 'nu_y', 'phi_per_mm'], v, error)
      if (allocated(error)) return
      n = 0
      do i = 1, size(v, 1)
         if (i == 1) then
            call ellipse_strip_patch(v(i, 1), v(i, 2), 64700.0_wp, 100, 460.0_wp, patch)
         else if (v(i, 1) /= v(i - 1, 1) .or. v(i, 2) /= v(i - 1, 2)) then
            call ellipse_strip_patch(v(i, 1), v(i, 2), 64700.0_wp, 100, 460.0_wp, patch)
         end if
         call check_cases(patch, table_material(), v(i:i, 3:5), 'ellipse_check row '// &
            str_int(i), error)
         if (allocated(error)) return
         n = n + 1
      end do
      call check(error, n == 370, message='ellipse_check.csv: expected 370 cases')
      if (allocated(error)) return
      ! The table: its creepages are those of table_node_case; here the scaled creepage t of each
      ! node is turned back into creepages through the linear theory of the same ellipse.
      call read_columns('data/exact/ellipse_table.csv', [character(len=7) :: 'i_ratio', 'k_x', &
         'k_y', 't_phi'], v, error)
      if (allocated(error)) return
      call check(error, size(v, 1) == 33120, message='ellipse_table.csv: expected 33120 nodes')
      if (allocated(error)) return
      call table_cases(v, error)
   contains
      subroutine table_cases(v, error)
         real(wp), intent(in) :: v(:, :)
         type(error_type), allocatable, intent(out) :: error
         type(creepage_type) :: creepage
         real(wp) :: c(1, 3)
         integer :: k, ip, last
         last = -1
         do k = 1, size(v, 1)
            ip = findloc(nint(1000*table_t_phi), nint(1000*v(k, 4)), dim=1)
            call check(error, ip > 0, message='t_phi of a table line is not a node')
            if (allocated(error)) return
            call table_node_case(nint(v(k, 1)), nint(v(k, 2)), nint(v(k, 3)), ip, &
               table_material(), patch, creepage)
            c(1, :) = [creepage%nu_x, creepage%nu_y, creepage%phi]
            call check_cases(patch, table_material(), c, 'ellipse_table node '//str_int(k), &
               error, reuse=nint(v(k, 1)) == last)
            if (allocated(error)) return
            last = nint(v(k, 1))
         end do
      end subroutine table_cases
   end subroutine test_ellipse_sets

   !> Every patch our geometry finds at each position of data/exact/ (one or two), each under
   !> F_n = 64.7 kN, with every case of its DOE (216), and the shared DOEs of ty0 (10³) and ty5p8
   !> (20³): the defaults (normal reduction `coupled`) and without the correction, as the
   !> validation runs them (doc/validation.md §6.4). Needs the external data (Manchester
   !> profiles, CONTACT's shared DOEs; SHCONTACT_EXTERNAL_DATA).
   subroutine test_position_sets(error)
      type(error_type), allocatable, intent(out) :: error
      call position_sets('coupled', .true., error)
   end subroutine test_position_sets

   !> The positions of data/exact/ as in test_position_sets with the normal reductions the
   !> validation compares beside the default, `local-hertz` and `constant` (Table 10).
   subroutine test_position_alternatives(error)
      type(error_type), allocatable, intent(out) :: error
      call position_sets('local-hertz', .false., error)
      if (.not. allocated(error)) call position_sets('constant', .false., error)
   end subroutine test_position_alternatives

   !> The DOEs of every position with one normal reduction (and the shared ones when asked).
   subroutine position_sets(reduction, shared, error)
      character(len=*), intent(in) :: reduction
      logical, intent(in) :: shared
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(lib_error), allocatable :: err
      real(wp) :: y_ws, y_geo, pen, ycp_r, delt, ycp_tr
      character(len=:), allocatable :: doe
      integer :: k

      call skip_without_profiles(error)
      if (allocated(error)) return
      call manchester_profiles(wheel, rail, track, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      do k = 1, size(positions)
         call summary_values('data/exact/'//trim(positions(k))//'/summary.csv', y_ws, y_geo, &
            pen, ycp_r, delt, ycp_tr, error)
         if (allocated(error)) return
         call position_doe(y_ws, 'data/exact/'//trim(positions(k))// &
            '/doe_6x6x6_exact_nonhertz.csv', 216, error)
         if (allocated(error)) return
      end do
      if (.not. shared) return
      doe = external_file('reference/ty0_literal/doe_10x10x10_exact_nonhertz.csv', error)
      if (.not. allocated(error)) call position_doe(0.0_wp, doe, 1000, error)
      if (allocated(error)) return
      doe = external_file('reference/ty5p8_literal/doe_20x20x20_exact_nonhertz.csv', error)
      if (.not. allocated(error)) call position_doe(5.8_wp, doe, 8000, error)
   contains
      subroutine position_doe(y_ws, doe, n_expected, error)
         real(wp), intent(in) :: y_ws
         character(len=*), intent(in) :: doe
         integer, intent(in) :: n_expected
         type(error_type), allocatable, intent(out) :: error
         type(patch_geometry_type), allocatable :: geometry(:)
         type(normal_options_type) :: options
         type(normal_contact_type) :: contact
         type(normal_patch_type) :: patch
         real(wp), allocatable :: v(:, :)
         integer :: p

         call read_doe(doe, n_expected, v, error)
         if (allocated(error)) return
         call find_contact_patches(wheel, rail, track, wheelset_position_type(y_ws=y_ws), &
            contact_options_type(), geometry, err)
         if (.not. allocated(err)) call new_normal_options(options, err, &
            method='semi-hertz', reduction=reduction, n_strips=100)
         do p = 1, size(geometry)
            if (allocated(err)) exit
            call prepare_normal_contact(contact, geometry(p), options, material_type(), err)
            if (.not. allocated(err)) call solve_load(contact, 64700.0_wp, patch, err)
            if (allocated(err)) exit
            call check_cases(patch, material_type(), v, doe//', '//reduction//', patch '// &
               str_int(p), error)
            if (allocated(error)) return
         end do
         if (allocated(err)) call test_failed(error, doe//': '//err%message)
      end subroutine position_doe
   end subroutine position_sets

   !> A DOE file's creepages in our sign: CONTACT's (rail relative to wheel) → −ν; φ in rad/mm.
   subroutine read_doe(doe, n_expected, v, error)
      character(len=*), intent(in) :: doe
      integer, intent(in) :: n_expected
      real(wp), allocatable, intent(out) :: v(:, :)
      type(error_type), allocatable, intent(out) :: error
      call read_columns(doe, [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m'], v, error)
      if (allocated(error)) return
      call check(error, size(v, 1) == n_expected, message=doe//': cases read')
      if (allocated(error)) return
      v(:, 1:2) = -v(:, 1:2)
      v(:, 3) = -1.0e-3_wp*v(:, 3)
   end subroutine read_doe

   !> The two-lobe positions of data/exact/ (5.0 and 5.3 mm) as the validation solves them
   !> (doc/validation.md §6.5): both patches under the vertical load for which their normal
   !> forces add up to 64.7 kN, the DOE's creepages carried to each patch's reference point by
   !> the rigid slip, ν_x,k = ν_x − φ (y_k − y_G); the defaults and without the correction.
   subroutine test_two_lobe_positions(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: names(2) = [character(len=6) :: 'yws5p0', 'yws5p3']
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_patch_type), allocatable :: patches(:)
      real(wp), allocatable :: v(:, :), c(:, :)
      real(wp) :: y_ws, y_geo, pen, ycp_r, delt, ycp_tr, y_k
      integer :: ip, k

      do ip = 1, size(names)
         call summary_values('data/exact/'//names(ip)//'/summary.csv', y_ws, y_geo, pen, &
            ycp_r, delt, ycp_tr, error)
         if (allocated(error)) return
         call two_patch_solution(y_ws, geometry, patches, error)
         if (allocated(error)) return
         call check(error, size(patches) == 2, message=names(ip)//': two patches expected')
         if (allocated(error)) return
         call read_doe('data/exact/'//names(ip)//'/doe_6x6x6_exact_nonhertz.csv', 216, v, &
            error)
         if (allocated(error)) return
         do k = 1, size(patches)
            ! Our sign: ν_x,k = ν_x − φ (y_k − y_G) holds in both signs (ν and φ flip together).
            y_k = (geometry(k)%y_track - ycp_tr)/cos(delt)
            c = v
            c(:, 1) = v(:, 1) - v(:, 3)*(y_k - y_geo)
            call check_cases(patches(k), material_type(), c, names(ip)//', patch '// &
               str_int(k), error)
            if (allocated(error)) return
         end do
      end do
   end subroutine test_two_lobe_positions

   !> The shared kinematic sample (CONTACT module 1, 35 cases solved by CONTACT) through the
   !> kinematic call as the validation runs it (doc/validation.md §6): every loaded patch of
   !> every case within Coulomb, with the defaults, with the additive spin model (the one for
   !> kinematics), and without the correction.
   subroutine test_kinematic_sample(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=12), parameter :: names(6) = [character(len=12) :: 'y_ws_mm', 'yaw_rad', &
         'vs_mm_s', 'vy_mm_s', 'vyaw_rad_s', 'vpitch_rad_s']
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(track_type) :: track
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: err
      real(wp), allocatable :: rows(:, :)
      character(len=:), allocatable :: sample, wheel, rail
      real(wp) :: f
      integer :: i, k, ic, n_patches

      call skip_without_profiles(error)
      if (allocated(error)) return
      sample = external_file('reference/kinematic_sample/kinematic_sample.csv', error)
      if (.not. allocated(error)) wheel = external_file('profiles/MBench_S1002_v3.prw', error)
      if (.not. allocated(error)) rail = external_file('profiles/MBench_UIC60_v3.prr', error)
      if (allocated(error)) return
      call read_columns(sample, names, rows, error, row_tag='ok')
      if (allocated(error)) return
      track%rail_canted = .true.
      call solver%init(wheel, rail, err, track=track, material=table_material())
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      n_patches = 0
      do ic = 1, 3
         options = tangential_options_type()
         if (ic == 2) options%spin_model = spin_additive
         if (ic == 3) options%correction = correction_none
         call solver%set_options(err, tangential=options)
         if (allocated(err)) exit
         do i = 1, size(rows, 1)
            associate (r => rows(i, :))
               call solver%solve_kinematic(wheelset_state_type(y_ws=r(1), yaw=r(2), &
                  v_forward=r(3), v_lateral=r(4), yaw_rate=r(5), pitch_rate=r(6)), &
                  contact_load_type(load_vertical_force, 64700.0_wp), result, err)
            end associate
            if (allocated(err)) exit
            do k = 1, result%n_loaded
               if (.not. (result%patch(k)%fn > 0.0_wp)) cycle
               n_patches = n_patches + 1
               f = hypot(result%patch(k)%fx_norm, result%patch(k)%fy_norm)
               if (f > 1.0_wp + slack) then
                  call test_failed(error, 'kinematic sample case '//str_int(i)// &
                     ', options '//str_int(ic)//', patch '//str_int(k)//': |f| = '//str_real(f))
                  return
               end if
            end do
         end do
         if (allocated(err)) exit
      end do
      if (allocated(err)) then
         call test_failed(error, 'kinematic sample: '//err%message)
         return
      end if
      call check(error, size(rows, 1) == 35 .and. n_patches >= 3*35, message= &
         'kinematic sample: '//str_int(size(rows, 1))//' cases, '//str_int(n_patches)// &
         ' loaded patches')
   end subroutine test_kinematic_sample

   !> Solve the creepages (our sign, rows ν_x, ν_y, φ in rad/mm) on a patch with the defaults and
   !> with correction 'none'; fail where |f| > 1 + slack.
   subroutine check_cases(patch, material, creepages, label, error, reuse)
      type(normal_patch_type), intent(in) :: patch
      type(material_type), intent(in) :: material
      real(wp), intent(in) :: creepages(:, :)
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      !> The workspaces already hold this patch.
      logical, intent(in), optional :: reuse
      type(march_workspace_type), save :: ws(2)
      type(tangential_options_type) :: options
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      integer :: ic, i

      do ic = 1, 2
         options = tangential_options_type(fields=.false.)
         if (ic == 2) options%correction = correction_none
         if (.not. present_and_true(reuse)) then
            call prepare_fastsim_sh(ws(ic), patch, material, options, err)
            if (allocated(err)) exit
         end if
         do i = 1, size(creepages, 1)
            call solve_prepared(ws(ic), creepage_type(creepages(i, 1), creepages(i, 2), &
               creepages(i, 3)), result, err)
            if (allocated(err)) exit
            if (hypot(result%fx_norm, result%fy_norm) > 1.0_wp + slack) then
               call test_failed(error, label//', case '//str_int(i)//', correction '// &
                  str_int(options%correction)//': |f| = '// &
                  str_real(hypot(result%fx_norm, result%fy_norm))//' > 1')
               return
            end if
         end do
         if (allocated(err)) exit
      end do
      if (allocated(err)) call test_failed(error, label//': '//err%message)
   end subroutine check_cases

   pure logical function present_and_true(flag)
      logical, intent(in), optional :: flag
      present_and_true = .false.
      if (present(flag)) present_and_true = flag
   end function present_and_true

   !> A seeded random DOE near full slip: on six patches (Hertz ellipses of a/b = 0.2, 1, 4 and
   !> 20, an ellipse with an uneven load and a two-lobe patch), creepages whose linear force is
   !> 0.5 to 20 times μF_n in random directions, with and without spin, every bound × correction
   !> (and classical FASTSIM on the ellipses), spin model, spin flexibility and n_x
   !> (10 or 50) drawn per case: |f| ≤ 1 + 1e-12 everywhere.
   subroutine test_random_doe(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n_cases = 60
      real(wp), parameter :: ratios(4) = [0.2_wp, 1.0_wp, 4.0_wp, 20.0_wp]
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      type(material_type) :: material
      integer(kind=8) :: seed
      real(wp) :: a, b, nu_sat, phi_sat, m, angle, worst, f
      integer :: ip, ibound, icorr, imethod, i, n_solved

      material = table_material()
      seed = 20261127_8  ! any value in 1 … 2³¹ − 2
      worst = 0.0_wp
      n_solved = 0
      do ip = 1, 6
         a = sqrt(36.0_wp*ratios(min(ip, 4)))
         b = a/ratios(min(ip, 4))
         call ellipse_strip_patch(a, b, 64700.0_wp, 60, 460.0_wp, patch)
         if (ip == 5) then
            ! Uneven: the load of the field-side half doubled, the gauge side's halved.
            where (patch%y > 0.0_wp) patch%strip_load = 2.0_wp*patch%strip_load
            where (patch%y < 0.0_wp) patch%strip_load = 0.5_wp*patch%strip_load
         else if (ip == 6) then
            ! Two lobes: the middle fifth of the strips unloaded.
            where (abs(patch%y) < 0.2_wp*b) patch%a = 0.0_wp
         end if
         patch%load = sum(patch%strip_load, mask=patch%a > 0.0_wp)
         ! A tread contact angle, so that every spin model (the scaled one too) applies.
         patch%gamma0 = -0.05_wp
         patch%gamma = -0.05_wp + 0.002_wp*patch%y
         patch%delta_r = -0.05_wp*patch%y
         ! Creepages whose linear force is μF_n (c₁₁ ≈ c₂₂ ≈ 4, c₂₃ ≈ 2).
         nu_sat = 0.3_wp*64700.0_wp/(material%shear_modulus*a*b*4.0_wp)
         phi_sat = 0.3_wp*64700.0_wp/(material%shear_modulus*(a*b)**1.5_wp*2.0_wp)
         do imethod = 1, merge(2, 1, ip <= 4)
            do ibound = bound_ellipsoidal, bound_clipped
               do icorr = correction_none, correction_exact_ellipse
                  do i = 1, n_cases
                     options = tangential_options_type(bound=ibound, correction=icorr, &
                        fields=.false.)
                     if (imethod == 2) options%method = method_fastsim
                     options%spin_model = spin_additive + int(4*uniform(seed))
                     options%spin_flexibility = merge(spin_flexibility_spin, &
                        spin_flexibility_longitudinal, uniform(seed) < 0.5_wp)
                     options%n_elements = merge(10, 50, uniform(seed) < 0.5_wp)
                     if (imethod == 2) then
                        call prepare_fastsim(ws, a, b, 64700.0_wp, material, options, 60, err, &
                           gamma0=-0.05_wp)
                     else
                        call prepare_fastsim_sh(ws, patch, material, options, err)
                     end if
                     if (allocated(err)) exit
                     m = nu_sat*0.5_wp*40.0_wp**uniform(seed)
                     angle = 6.283185307179586_wp*uniform(seed)
                     f = 0.0_wp
                     if (uniform(seed) < 0.7_wp) f = phi_sat*(2.0_wp*uniform(seed) - 1.0_wp)* &
                        10.0_wp**(2.0_wp*uniform(seed) - 0.5_wp)
                     call solve_prepared(ws, creepage_type(m*cos(angle), m*sin(angle), f), &
                        result, err)
                     if (allocated(err)) exit
                     n_solved = n_solved + 1
                     f = hypot(result%fx_norm, result%fy_norm)
                     worst = max(worst, f)
                     if (f > 1.0_wp + slack) then
                        call test_failed(error, 'patch '//str_int(ip)//', method '// &
                           str_int(imethod)//', bound '//str_int(ibound)//', correction '// &
                           str_int(icorr)//', case '//str_int(i)//': |f| = '//str_real(f))
                        return
                     end if
                  end do
                  if (allocated(err)) exit
               end do
               if (allocated(err)) exit
            end do
            if (allocated(err)) exit
         end do
         if (allocated(err)) exit
      end do
      if (allocated(err)) then
         call test_failed(error, 'random DOE: '//err%message)
         return
      end if
      ! Near full slip indeed: the largest |f| is at the bound.
      call check(error, n_solved == n_cases*5*2*(4*2 + 2) .and. worst > 1.0_wp - 1.0e-9_wp, &
         message='random DOE: '//str_int(n_solved)//' cases, largest |f| '//str_real(worst))
   end subroutine test_random_doe

   !> The Hertz method through the solver, at full slip: its strips' loads (the midpoint rule
   !> of the ellipse) summed to 1.00005 F_n with 100 strips and the traction bound followed
   !> them, so |F_t|/(μF_n) was 1.00005 (fx_norm −1 exactly, being taken against the strips'
   !> sum). Checked on the forces themselves, F_n being the patch's normal force: every
   !> tangential method × bound × correction, three positions, creepages at 5 to 20 times
   !> the saturation in eight directions.
   subroutine test_hertz_method(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(tangential_options_type) :: options
      type(normal_options_type) :: normal
      type(lib_error), allocatable :: err
      real(wp), parameter :: positions(3) = [0.0_wp, 2.0_wp, 4.0_wp]
      real(wp) :: f, worst, angle, m
      integer :: imethod, ibound, icorr, ip, id, k

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      if (.not. allocated(err)) call new_normal_options(normal, err, method='hertz')
      if (.not. allocated(err)) call solver%set_options(err, normal=normal)
      if (allocated(err)) then
         call test_failed(error, 'set-up: '//err%message)
         return
      end if
      worst = 0.0_wp
      do imethod = 1, 2
         do ibound = bound_ellipsoidal, bound_clipped
            do icorr = correction_none, correction_exact_ellipse
               options = tangential_options_type(bound=ibound, correction=icorr)
               if (imethod == 2) options%method = method_fastsim
               call solver%set_options(err, tangential=options)
               do ip = 1, size(positions)
                  do id = 0, 7
                     if (allocated(err)) exit
                     angle = 0.7853981633974483_wp*id
                     m = 5.0e-3_wp*(1.0_wp + 3.0_wp*mod(id, 2))
                     call solver%solve(positions(ip), 0.0_wp, contact_load_type( &
                        load_normal_force, 64700.0_wp), creepage_type(m*cos(angle), &
                        m*sin(angle), 0.0_wp), result, err)
                     if (allocated(err)) exit
                     do k = 1, result%n_patches
                        associate (p => result%patch(k))
                           if (.not. (p%fn > 0.0_wp)) cycle
                           f = hypot(p%fx, p%fy)/(0.3_wp*p%fn)
                        end associate
                        worst = max(worst, f)
                        if (f > 1.0_wp + slack) then
                           call test_failed(error, 'Hertz method, tangential method '// &
                              str_int(imethod)//', bound '//str_int(ibound)//', correction '// &
                              str_int(icorr)//', t_y '//str_real(positions(ip))//' mm, '// &
                              'direction '//str_int(id)//': |F_t|/(mu F_n) = '//str_real(f))
                           return
                        end if
                     end do
                  end do
               end do
               if (allocated(err)) exit
            end do
            if (allocated(err)) exit
         end do
         if (allocated(err)) exit
      end do
      if (allocated(err)) then
         call test_failed(error, 'Hertz method: '//err%message)
         return
      end if
      ! At full slip indeed (the weighted and ellipsoidal bounds reach it).
      call check(error, worst > 1.0_wp - 1.0e-9_wp, message='Hertz method: largest |f| '// &
         str_real(worst))
   end subroutine test_hertz_method

   !> The Coulomb check is taken on the corrected tractions: with the fields, coulomb_ratio is the
   !> largest |p_t|/(μp_n) over the corrected field, it is the same without the fields, and the
   !> fields sum to the (Coulomb-limited) totals. Cases near saturation with spin on a wide
   !> ellipse, where the correction is not small.
   subroutine test_ratio_after_correction(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: with_fields, without
      type(lib_error), allocatable :: err
      type(material_type) :: material
      real(wp) :: ratio, sum_x, sum_y, mu_fn
      real(wp), parameter :: cases(3, 4) = reshape([ &
         -4.0e-4_wp, 1.0e-3_wp, 1.5e-3_wp, &
         1.0e-3_wp, 0.0_wp, -2.0e-3_wp, &
         0.0_wp, -3.0e-4_wp, 6.0e-4_wp, &
         5.0e-3_wp, 5.0e-3_wp, 1.0e-2_wp], [3, 4])
      integer :: k, i, j

      material = table_material()
      call ellipse_strip_patch(3.0_wp, 6.0_wp, 64700.0_wp, 60, 460.0_wp, patch)
      mu_fn = material%friction*patch%load
      do k = 1, size(cases, 2)
         options = tangential_options_type(fields=.true.)
         call prepare_fastsim_sh(ws, patch, material, options, err)
         if (.not. allocated(err)) call solve_prepared(ws, creepage_type(cases(1, k), &
            cases(2, k), cases(3, k)), with_fields, err)
         options%fields = .false.
         if (.not. allocated(err)) call prepare_fastsim_sh(ws, patch, material, options, err)
         if (.not. allocated(err)) call solve_prepared(ws, creepage_type(cases(1, k), &
            cases(2, k), cases(3, k)), without, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         ratio = 0.0_wp
         sum_x = 0.0_wp
         sum_y = 0.0_wp
         do i = 1, with_fields%ny
            if (with_fields%dx(i) <= 0.0_wp) cycle
            do j = 1, with_fields%nx
               if (with_fields%state(j, i) == state_exterior) cycle
               ratio = max(ratio, hypot(with_fields%px(j, i), with_fields%py(j, i))/ &
                  (material%friction*with_fields%pn(j, i)))
               sum_x = sum_x + with_fields%px(j, i)*with_fields%dx(i)*with_fields%dy
               sum_y = sum_y + with_fields%py(j, i)*with_fields%dx(i)*with_fields%dy
            end do
         end do
         call check(error, abs(with_fields%coulomb_ratio - ratio) <= 1.0e-12_wp*ratio, &
            message='case '//str_int(k)//': coulomb_ratio '//str_real(with_fields%coulomb_ratio)// &
            ', the corrected field''s '//str_real(ratio))
         if (allocated(error)) return
         call check(error, abs(without%coulomb_ratio - ratio) <= 1.0e-12_wp*ratio, &
            message='case '//str_int(k)//': coulomb_ratio without fields '// &
            str_real(without%coulomb_ratio)//', with '//str_real(ratio))
         if (allocated(error)) return
         call check(error, abs(sum_x - with_fields%fx) + abs(sum_y - with_fields%fy) <= &
            1.0e-10_wp*mu_fn, message='case '//str_int(k)//': the fields do not sum to F_x, F_y')
         if (allocated(error)) return
         call check(error, hypot(without%fx_norm, without%fy_norm) <= 1.0_wp + slack, &
            message='case '//str_int(k)//': |f| > 1')
         if (allocated(error)) return
      end do
   end subroutine test_ratio_after_correction

   !> A uniform number in (0, 1) from the minimal standard generator (Park and Miller,
   !> x ← 16807 x mod (2³¹ − 1), no overflow in 64 bits), so that the DOE is the same on every
   !> compiler.
   real(wp) function uniform(seed)
      integer(kind=8), intent(inout) :: seed
      seed = modulo(16807_8*seed, 2147483647_8)
      uniform = real(seed, wp)/2147483647.0_wp
   end function uniform

end module test_coulomb
