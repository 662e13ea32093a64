!> Keeps the headline validation numbers (doc/validation.md) from regressing: the whole pipeline
!> (profiles → geometry → semi-Hertzian normal contact → FASTSIM_SH) on the reference case of
!> the external data's reference/ (S1002 on UIC60 1:40, Y_WS = 0, F_n = 64.7 kN) against Kalker's
!> exact theory computed by CONTACT. Tolerances are the project's targets (issue 7, doc/theory.md §6.6)
!> and the reference's own values, never outputs of our code. The tests that need the sample
!> profiles or CONTACT's reference files are skipped when SHCONTACT_EXTERNAL_DATA is unset
!> (test_external_data).
!>
!> The tangential settings are the ones recommended as defaults in doc/validation.md: bound
!> 'weighted', spin model 'uniform', spin flexibility 'longitudinal', 100 strips × 50 elements.
!> Signs: the reference is CONTACT's rail side; we solve the same case from the wheel's side
!> (creepages −ν, forces −F), doc/theory.md decision 2.
module test_validation
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_core_strings, only: str_real
   use shcontact_profile_cleanup, only: clean_profile
   use shcontact_geometry_track, only: track_type, wheelset_position_type
   use shcontact_geometry_contact, only: contact_options_type, find_contact_patches
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, new_normal_options
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load, &
      solve_vertical_load
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_options, only: tangential_options_type, &
      correction_none, parse_bound, parse_spin_model, parse_spin_flexibility, parse_correction
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, &
      contact_result_type, load_vertical_force
   use test_external_data, only: external_file
   implicit none
   private
   public :: collect_validation, percentile, read_columns, manchester_profiles, &
      summary_values, &
      skip_without_profiles, two_patch_solution, position_errors, recommended_options, &
      exact_positions, reference_patch, summary_value

   !> Files of the external data (SHCONTACT_EXTERNAL_DATA, test_external_data).
   character(len=*), parameter :: mbench_wheel = 'profiles/MBench_S1002_v3.prw', &
      mbench_rail = 'profiles/MBench_UIC60_v3.prr'
   character(len=*), parameter :: reference_dir = 'reference/ty0_literal/'
   character(len=*), parameter :: ty5p8_doe = 'reference/ty5p8_literal/'// &
      'doe_20x20x20_exact_nonhertz.csv'
   character(len=*), parameter :: kinematic_file = &
      'reference/kinematic_sample/kinematic_sample.csv'
   !> The reference case (README §2).
   real(wp), parameter :: normal_force = 64700.0_wp


   !> The single-lobe exact-theory positions of data/exact/ (doc/validation.md §6.4).
   character(len=*), parameter :: exact_positions(19) = [character(len=7) :: &
      'yws-6p0', 'yws-4p0', 'yws-2p0', 'yws-1p0', 'yws0p5', 'yws0p75', &
      'yws1p0', 'yws1p25', 'yws1p5', 'yws2p0', 'yws2p5', 'yws3p0', &
      'yws3p5', 'yws4p0', 'yws4p4', 'yws4p6', 'yws6p0', 'yws6p5', 'yws7p0']

contains

   !> Collect the tests.
   subroutine collect_validation(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('normal_patch_vs_exact', test_normal), &
         new_unittest('doe_10x10x10_vs_exact', test_doe), &
         new_unittest('kinematic_sample_vs_exact', test_kinematic), &
         new_unittest('doe_20x20x20_ty5p8_vs_exact', test_doe_ty5p8), &
         new_unittest('doe_ty5p8_local_hertz_vs_exact', test_doe_ty5p8_local_hertz), &
         new_unittest('doe_project_positions_vs_exact', test_doe_positions), &
         new_unittest('doe_positions_builtin_profiles_vs_exact', test_doe_positions_builtin), &
         new_unittest('plateau_load_centre_vs_exact', test_plateau_load_centre), &
         new_unittest('two_lobe_load_split_vs_exact', test_lobes), &
         new_unittest('two_lobe_doe_per_lobe_vs_exact', test_lobe_doe) &
         ]
   end subroutine collect_validation

   !> The semi-Hertzian patch against CONTACT's exact normal solution (headline_summary.csv,
   !> module3_exact_nonhertz): approach within 5 % of 0.05526 mm, contact area within 5 % of
   !> 151.24 mm², contact length within 5 % of 9.0 mm, width within 5 % of 19.8 mm.
   subroutine test_normal(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      real(wp) :: approach, area, length, width

      call reference_patch(patch, error)
      if (allocated(error)) return
      call reference_normal(approach, area, length, width, error)
      if (allocated(error)) return
      call check(error, patch%approach, approach, rel=.true., thr=0.05_wp, &
         message='approach against CONTACT exact')
      if (allocated(error)) return
      call check(error, patch%area, area, rel=.true., thr=0.05_wp, &
         message='contact area against CONTACT exact')
      if (allocated(error)) return
      call check(error, 2.0_wp*maxval(patch%a), length, rel=.true., thr=0.05_wp, &
         message='contact length against CONTACT exact')
      if (allocated(error)) return
      call check(error, patch_width(patch), width, rel=.true., thr=0.05_wp, &
         message='contact width against CONTACT exact')
   end subroutine test_normal

   !> The 10³ DOE (ξ, η ∈ [0, 2] ‰, φ ∈ [0, 2] 1/m) against the exact theory with the defaults:
   !> max |Δf| ≤ 0.1 and the 80th percentile of |Δf_y| ≤ 0.04 (issue 7, doc/theory.md §6.6), Table
   !> 10's row (issue 13), and the headline case within the same 0.1.
   subroutine test_doe(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      real(wp), allocatable :: cases(:, :), ex(:), ey(:)
      character(len=:), allocatable :: doe
      integer :: i, n

      doe = external_file(reference_dir//'doe_10x10x10_exact_nonhertz.csv', error)
      if (allocated(error)) return
      call reference_patch(patch, error)
      if (allocated(error)) return
      call read_columns(doe, &
         [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m', 'fx', 'fy'], cases, error)
      if (allocated(error)) return
      call recommended_options(options)
      call prepare_fastsim_sh(ws, patch, material_type(), options, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      n = size(cases, 1)
      allocate (ex(n), ey(n))
      do i = 1, n
         ! Wheel side: creepages −ν (φ in rad/mm), forces −F (decision 2).
         call solve_prepared(ws, creepage_type(-cases(i, 1), -cases(i, 2), &
            -1.0e-3_wp*cases(i, 3)), result, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         ex(i) = abs(-result%fx_norm - cases(i, 4))
         ey(i) = abs(-result%fy_norm - cases(i, 5))
      end do
      call check(error, n, 1000, message='DOE cases read')
      if (allocated(error)) return
      call check(error, max(maxval(ex), maxval(ey)) <= 0.1_wp, &
         message='DOE: max |Delta f| > 0.1 against the exact theory')
      if (allocated(error)) return
      call check(error, percentile(ey, 0.8_wp) <= 0.04_wp, &
         message='DOE: 80th percentile of |Delta f_y| > 0.04 against the exact theory')
      if (allocated(error)) return
      ! Issue 13: Table 10's defaults row (doc/validation.md §6.4) within ±0.002 and the targets
      ! P80 |Δf_x|, P80 |Δf_y| ≤ 0.02, max |Δf| ≤ 0.05.
      call check_row(ex, ey, [0.018_wp, 0.019_wp, 0.002_wp, 0.006_wp], 'ty0 defaults', error)
      if (allocated(error)) return
      call check(error, percentile(ex, 0.8_wp) <= 0.02_wp .and. percentile(ey, 0.8_wp) <= &
         0.02_wp .and. max(maxval(ex), maxval(ey)) <= 0.05_wp, &
         message='ty0: a target of issue 13 is missed')
      if (allocated(error)) return
      ! The headline creepages (README §5): f_x = −0.4960, f_y = −0.2869.
      call solve_prepared(ws, creepage_type(-0.58e-3_wp, -0.061e-3_wp, -2.74e-4_wp), result, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, -result%fx_norm, -0.4960_wp, thr=0.1_wp, message='headline f_x')
      if (allocated(error)) return
      call check(error, -result%fy_norm, -0.2869_wp, thr=0.1_wp, message='headline f_y')
   end subroutine test_doe

   !> solve_kinematic on CONTACT's kinematic sample (doc/validation.md §6; CONTACT's failed case
   !> c0003 has no `ok` and is not read). Keeps the statistics quoted there true within ±0.002
   !> (f) and ±0.005 (F_n ratio), and checks the creepages: ours carried from our geometric point
   !> to CONTACT's weighted centre (rigid slip, φ̄ the mean of the spin at both points, module
   !> validate_kinematic) against CONTACT's. Tolerances: on the tread (|δ| < 0.5 rad) 0.02 ‰ in
   !> ξ and η, 2 % of the 1 ‰ kinematic steps and five times the largest residual found (0.004 ‰,
   !> which is the size of CONTACT's printed digits and of the curved-surface transfer);
   !> 0.001 1/m in φ (0.4 % of the smallest tread spin). On the flange (δ ≈ −69°) η within
   !> 0.02 ‰ and φ within 0.005 1/m (0.25 %), ξ within 1 ‰: there our rolling radius is
   !> 0.4 mm larger than CONTACT's (0.9 ‰ in ξ, doc/validation.md §6.3), an open difference this
   !> test bounds but does not hide.
   subroutine test_kinematic(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=12), parameter :: names(18) = [character(len=12) :: 'y_ws_mm', 'yaw_rad', &
         'vs_mm_s', 'vy_mm_s', 'vyaw_rad_s', 'vpitch_rad_s', 'xcp_tr_mm', 'ycp_tr_mm', &
         'zcp_tr_mm', 'delta_rad', 'cksi', 'ceta', 'cphi_per_mm', 'fn_N', 'fx_norm', &
         'fs_norm', 'npatch', 'patch']
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(track_type) :: track
      type(lib_error), allocatable :: err
      real(wp), allocatable :: rows(:, :), ex(:), ey(:), en(:), wx(:), wy(:), ox(:), oy(:)
      real(wp) :: phi_t, y_g, x_g, nux_t, nuy_t, tol_xi
      integer :: i, n
      character(len=:), allocatable :: sample

      call skip_without_profiles(error)
      if (allocated(error)) return
      sample = external_file(kinematic_file, error)
      if (allocated(error)) return
      call read_columns(sample, names, rows, error, row_tag='ok')
      if (allocated(error)) return
      n = size(rows, 1)
      call check(error, n, 35, message='kinematic sample: cases CONTACT solved')
      if (allocated(error)) return
      track%rail_canted = .true.
      call solver%init(external(mbench_wheel), external(mbench_rail), &
         err, track=track, material=material_type( &
         shear_modulus=82670.0_wp, poisson=0.27_wp, friction=0.3_wp))
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      allocate (ex(n), ey(n), en(n), wx(n), wy(n), ox(n), oy(n))
      do i = 1, n
         associate (r => rows(i, :))
            call solver%solve_kinematic(wheelset_state_type(y_ws=r(1), yaw=r(2), &
               v_forward=r(3), v_lateral=r(4), yaw_rate=r(5), pitch_rate=r(6)), &
               contact_load_type(load_vertical_force, normal_force), result, err)
            if (allocated(err)) then
               call test_failed(error, err%message)
               return
            end if
            associate (p => result%main)
               ! CONTACT's sign: rail side, both the forces and the creepages flip.
               ox(i) = -p%fx_norm
               oy(i) = -p%fy_norm
               ex(i) = abs(-p%fx_norm - r(15))
               ey(i) = abs(-p%fy_norm - r(16))
               en(i) = abs(p%fn - r(14))/r(14)
               ! The wheel's joined contact (doc/lobes.md, doc/validation.md Table 12).
               wx(i) = abs(-result%wheel%fx_norm - r(15))
               wy(i) = abs(-result%wheel%fy_norm - r(16))
               phi_t = -p%phi - (sin(r(10)) - sin(p%gamma0))*abs(r(6))/r(3)
               y_g = (p%y_track - r(8))*cos(r(10)) + (p%z_track - r(9))*sin(r(10))
               x_g = p%x_track - r(7)
               nux_t = -p%nu_x + 0.5_wp*(-p%phi + phi_t)*y_g
               nuy_t = -p%nu_y - 0.5_wp*(-p%phi + phi_t)*x_g
            end associate
            tol_xi = merge(2.0e-5_wp, 1.0e-3_wp, abs(r(10)) < 0.5_wp)
            call check(error, nux_t, r(11), thr=tol_xi, message='transferred xi')
            if (allocated(error)) return
            ! First order in the distance between the two reference points (up to 0.8 mm on the
            ! 69° flange): 3e-5.
            call check(error, nuy_t, r(12), thr=3.0e-5_wp, message='transferred eta')
            if (allocated(error)) return
            call check(error, phi_t, r(13), thr=merge(1.0e-6_wp, 5.0e-6_wp, &
               abs(r(10)) < 0.5_wp), message='transferred phi (rad/mm)')
            if (allocated(error)) return
         end associate
      end do
      ! doc/validation.md Table 9, "all".
      call check(error, maxval(ex), 0.049_wp, thr=0.002_wp, message='max |Delta f_x|')
      if (allocated(error)) return
      call check(error, percentile(ex, 0.8_wp), 0.013_wp, thr=0.002_wp, &
         message='P80 |Delta f_x|')
      if (allocated(error)) return
      call check(error, maxval(ey), 0.026_wp, thr=0.002_wp, message='max |Delta f_y|')
      if (allocated(error)) return
      call check(error, percentile(ey, 0.8_wp), 0.006_wp, thr=0.002_wp, &
         message='P80 |Delta f_y|')
      if (allocated(error)) return
      call check(error, maxval(en), 0.039_wp, thr=0.005_wp, message='max |Delta F_n|/F_n')
      if (allocated(error)) return
      call check(error, percentile(en, 0.8_wp), 0.032_wp, thr=0.005_wp, &
         message='P80 |Delta F_n|/F_n')
      if (allocated(error)) return
      ! doc/validation.md Table 12, the wheel's joined contact: max |Delta f| 0.049, P80 0.013 /
      ! 0.008 (at Y_WS = 4.733 mm it holds both of our patches, CONTACT one).
      call check(error, max(maxval(wx), maxval(wy)), 0.049_wp, thr=0.002_wp, &
         message='joined contact: max |Delta f|')
      if (allocated(error)) return
      call check(error, percentile(wx, 0.8_wp), 0.013_wp, thr=0.002_wp, &
         message='joined contact: P80 |Delta f_x|')
      if (allocated(error)) return
      call check(error, percentile(wy, 0.8_wp), 0.008_wp, thr=0.002_wp, &
         message='joined contact: P80 |Delta f_y|')
      if (allocated(error)) return
      call check_conformal(rows, ox, oy, ex, error)
   end subroutine test_kinematic

   !> The same patches against CONTACT's conformal approach on the same decks
   !> (data/exact/kinematic_conformal/, doc/validation.md §6.3 item 6, Table 12): max |Δf|
   !> 0.020, P80 |Δf_x| 0.008, P80 |Δf_y| 0.009 within ±0.002. The file lists the 35 cases in
   !> the sample's order; the rows are matched by CONTACT's reference point (the two approaches
   !> put it within 0.005 mm of each other). It also keeps what the comparison shows: at
   !> Y_WS = 0, where the planar sample differs by up to 0.049 in f_x, the conformal approach
   !> agrees with ours within 0.016.
   subroutine check_conformal(rows, ox, oy, ex, error)
      !> The planar sample's columns (test_kinematic's names); our f_x, f_y (CONTACT's sign) and
      !> |Δf_x| against the planar sample.
      real(wp), intent(in) :: rows(:, :), ox(:), oy(:), ex(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=9), parameter :: names(3) = [character(len=9) :: 'ycp_tr_mm', 'fx_norm', &
         'fs_norm']
      real(wp), allocatable :: conf(:, :), cx(:), cy(:)
      integer :: n

      call read_columns('data/exact/kinematic_conformal/kinematic_conformal.csv', names, conf, &
         error, row_tag='ok')
      if (allocated(error)) return
      n = size(rows, 1)
      call check(error, size(conf, 1), n, message='conformal: cases')
      if (allocated(error)) return
      call check(error, maxval(abs(conf(:, 1) - rows(:, 8))) < 0.01_wp, &
         message='conformal: the rows are the sample''s cases (reference points)')
      if (allocated(error)) return
      cx = abs(ox - conf(:, 2))
      cy = abs(oy - conf(:, 3))
      call check(error, max(maxval(cx), maxval(cy)), 0.020_wp, thr=0.002_wp, &
         message='conformal: max |Delta f|')
      if (allocated(error)) return
      call check(error, percentile(cx, 0.8_wp), 0.008_wp, thr=0.002_wp, &
         message='conformal: P80 |Delta f_x|')
      if (allocated(error)) return
      call check(error, percentile(cy, 0.8_wp), 0.009_wp, thr=0.002_wp, &
         message='conformal: P80 |Delta f_y|')
      if (allocated(error)) return
      call check(error, maxval(cx, mask=rows(:, 1) == 0.0_wp) < 0.016_wp .and. &
         maxval(ex, mask=rows(:, 1) == 0.0_wp) > 0.045_wp, &
         message='conformal: at Y_WS = 0 within 0.016 of ours, the planar sample 0.049 off')
   end subroutine check_conformal


   !> Issue 13: the defaults (normal reduction `coupled`, correction `exact-ellipse`) on
   !> ty5p8_literal, Table 10's row within ±0.002 (max 0.013 / 0.024, P80 0.006 / 0.006), and the
   !> targets P80 |Δf_x|, |Δf_y| ≤ 0.02 and max |Δf| ≤ 0.05.
   subroutine test_doe_ty5p8(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: ex(:), ey(:)
      character(len=:), allocatable :: doe
      doe = external_file(ty5p8_doe, error)
      if (allocated(error)) return
      call doe_errors(doe, 5.8_wp, 726.0468_wp, 8000, ex, ey, error)
      if (allocated(error) .or. .not. allocated(ex)) return
      call check_row(ex, ey, [0.011_wp, 0.016_wp, 0.005_wp, 0.005_wp], 'ty5p8 defaults', error)
      if (allocated(error)) return
      call check(error, percentile(ex, 0.8_wp) <= 0.02_wp .and. percentile(ey, 0.8_wp) <= &
         0.02_wp .and. max(maxval(ex), maxval(ey)) <= 0.05_wp, &
         message='ty5p8 DOE: a target of issue 13 is missed')
   end subroutine test_doe_ty5p8

   !> The defaults when issue 13 was filed (reduction `local-hertz`, no correction) on
   !> ty5p8_literal, Table 10's row within ±0.002 (max 0.035 / 0.033, P80 0.027 / 0.010): f_x is
   !> what the coupling improves.
   subroutine test_doe_ty5p8_local_hertz(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: ex(:), ey(:)
      character(len=:), allocatable :: doe
      doe = external_file(ty5p8_doe, error)
      if (allocated(error)) return
      call doe_errors(doe, 5.8_wp, 726.0468_wp, 8000, ex, ey, error, &
         reduction='local-hertz', correction=correction_none)
      if (allocated(error) .or. .not. allocated(ex)) return
      call check_row(ex, ey, [0.035_wp, 0.033_wp, 0.027_wp, 0.010_wp], 'ty5p8 local-hertz', &
         error)
   end subroutine test_doe_ty5p8_local_hertz

   !> The defaults on the project's own single-lobe exact-theory positions (data/exact/,
   !> doc/validation.md §6.4): Table 10's defaults row within ±0.002 for each (max |Δf_x| / max
   !> |Δf_y|, P80 |Δf_x| / P80 |Δf_y|), and the targets of issue 13 at each.
   !> Needs the external data's sample profiles.
   subroutine test_doe_positions(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n_positions = size(exact_positions)
      real(wp), parameter :: rows(4, n_positions) = reshape([ &
         0.009_wp, 0.009_wp, 0.003_wp, 0.002_wp, &
         0.009_wp, 0.008_wp, 0.003_wp, 0.002_wp, &
         0.008_wp, 0.009_wp, 0.003_wp, 0.002_wp, &
         0.008_wp, 0.009_wp, 0.003_wp, 0.002_wp, &
         0.019_wp, 0.021_wp, 0.014_wp, 0.007_wp, &
         0.020_wp, 0.015_wp, 0.015_wp, 0.009_wp, &
         0.023_wp, 0.015_wp, 0.017_wp, 0.009_wp, &
         0.018_wp, 0.028_wp, 0.005_wp, 0.009_wp, &
         0.015_wp, 0.021_wp, 0.006_wp, 0.005_wp, &
         0.014_wp, 0.015_wp, 0.008_wp, 0.007_wp, &
         0.009_wp, 0.011_wp, 0.007_wp, 0.006_wp, &
         0.009_wp, 0.011_wp, 0.003_wp, 0.004_wp, &
         0.009_wp, 0.009_wp, 0.004_wp, 0.003_wp, &
         0.011_wp, 0.010_wp, 0.004_wp, 0.002_wp, &
         0.009_wp, 0.009_wp, 0.003_wp, 0.005_wp, &
         0.009_wp, 0.009_wp, 0.005_wp, 0.004_wp, &
         0.011_wp, 0.012_wp, 0.006_wp, 0.005_wp, &
         0.015_wp, 0.016_wp, 0.013_wp, 0.008_wp, &
         0.010_wp, 0.011_wp, 0.003_wp, 0.009_wp], [4, n_positions])
      real(wp), allocatable :: ex(:), ey(:)
      integer :: k

      do k = 1, n_positions
         call position_errors(trim(exact_positions(k)), ex, ey, error, builtin=.false.)
         if (allocated(error) .or. .not. allocated(ex)) return
         call check_row(ex, ey, rows(:, k), trim(exact_positions(k))//' defaults', error)
         if (allocated(error)) return
         call check_position_targets(ex, ey, trim(exact_positions(k)), error)
         if (allocated(error)) return
      end do
   end subroutine test_doe_positions

   !> The exact-theory positions of data/exact/ with the project's own built-in S1002 and
   !> UIC60-canted instead of the Manchester files, so that the validation against the exact
   !> theory runs on a clone with nothing beside it: CONTACT gives the same forces on both pairs
   !> to 1e-4 in f (data/exact/README.md), so the data are the exact theory of the built-in pair
   !> too. The targets of issue 13 at every position: max |Δf| ≤ 0.05, P80 |Δf_x|, |Δf_y| ≤ 0.02.
   subroutine test_doe_positions_builtin(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: ex(:), ey(:)
      integer :: k
      do k = 1, size(exact_positions)
         call position_errors(trim(exact_positions(k)), ex, ey, error, builtin=.true.)
         if (allocated(error)) return
         call check_position_targets(ex, ey, trim(exact_positions(k))//' (built-in profiles)', &
            error)
         if (allocated(error)) return
      end do
   end subroutine test_doe_positions_builtin

   !> |Δf_x|, |Δf_y| of the defaults over the DOE of the data/exact/ folder `name`, on the patch
   !> nearest CONTACT's reference point, with the Manchester or the built-in profiles.
   subroutine position_errors(name, ex, ey, error, builtin, reduction, correction)
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(out) :: ex(:), ey(:)
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in) :: builtin
      !> Normal reduction and `correction_*` (default: the library's).
      character(len=*), intent(in), optional :: reduction
      integer, intent(in), optional :: correction
      real(wp) :: y_ws, y_geo, pen, ycp_r, delt, y_ref
      call summary_values('data/exact/'//name//'/summary.csv', y_ws, y_geo, pen, ycp_r, delt, &
         y_ref, error)
      if (allocated(error)) return
      call doe_errors('data/exact/'//name//'/doe_6x6x6_exact_nonhertz.csv', y_ws, y_ref, 216, &
         ex, ey, error, builtin=builtin, reduction=reduction, correction=correction)
   end subroutine position_errors

   !> The targets of issue 13 (doc/validation.md §6.4), met at every position: max |Δf| ≤ 0.05,
   !> P80 |Δf_x|, |Δf_y| ≤ 0.02.
   subroutine check_position_targets(ex, ey, label, error)
      real(wp), intent(in) :: ex(:), ey(:)
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      call check(error, max(maxval(ex), maxval(ey)) <= 0.05_wp, message=label// &
         ': max |Delta f| '//str_real(max(maxval(ex), maxval(ey)))//' above the target 0.05')
      if (allocated(error)) return
      call check(error, &
         percentile(ex, 0.8_wp) <= 0.02_wp .and. percentile(ey, 0.8_wp) <= 0.02_wp, &
         message=label//': P80 |Delta f_x|, |Delta f_y| '//str_real(percentile(ex, 0.8_wp))// &
         ', '//str_real(percentile(ey, 0.8_wp))//' above the target 0.02')
   end subroutine check_position_targets

   !> The plateau positions Y_WS = 0.75, 1 and 1.25 mm (doc/validation.md §6.4, "Twelve more
   !> positions"): the lateral load centre of our patch against CONTACT's (its module-3 pressure,
   !> grid_module3_exact_nonhertz.csv, about its geometric point), ours minus CONTACT's within
   !> ±0.005 mm of +0.031, +0.021, −0.152 mm with the defaults (`coupled`; +0.026, +0.002, −0.165
   !> before the group-width mean of §6.9, +0.112, +0.096, +0.071 before issue 25's continuous
   !> coupling) and of −1.017, −1.018,
   !> −0.826 mm with the strips on their own (`local-hertz`). With spin, f_x follows the load's
   !> lateral moment: this offset is what is left of P80 |Δf_x| there.
   subroutine test_plateau_load_centre(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: names(3) = [character(len=7) :: 'yws0p75', 'yws1p0', &
         'yws1p25']
      real(wp), parameter :: offset(3, 2) = reshape([0.031_wp, 0.021_wp, -0.152_wp, &
         -1.017_wp, -1.018_wp, -0.826_wp], [3, 2])
      character(len=*), parameter :: reductions(2) = [character(len=11) :: 'coupled', &
         'local-hertz']
      type(normal_patch_type) :: patch
      real(wp), allocatable :: grid(:, :)
      real(wp) :: theirs, ours, y_ws, y_geo, pen, ycp_r, delt, y_ref
      integer :: k, r, n

      call skip_without_profiles(error)
      if (allocated(error)) return
      do k = 1, size(names)
         call summary_values('data/exact/'//trim(names(k))//'/summary.csv', y_ws, y_geo, pen, &
            ycp_r, delt, y_ref, error)
         if (allocated(error)) return
         call read_columns('data/exact/'//trim(names(k))//'/grid_module3_exact_nonhertz.csv', &
            [character(len=6) :: 'y_mm', 'pn_MPa'], grid, error)
         if (allocated(error)) return
         theirs = sum(grid(:, 1)*grid(:, 2))/sum(grid(:, 2)) - y_geo
         do r = 1, 2
            call reference_patch(patch, error, y_ws=y_ws, y_ref=y_ref, &
               reduction=trim(reductions(r)))
            if (allocated(error)) return
            n = patch%n_strips
            ours = sum(patch%strip_load(1:n)*patch%y(1:n))/sum(patch%strip_load(1:n))
            call check(error, ours - theirs, offset(k, r), thr=0.005_wp, message= &
               trim(names(k))//' '//trim(reductions(r))//': load centre minus CONTACT''s (mm)')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_plateau_load_centre

   !> The two-lobe positions Y_WS = 5.0 and 5.3 mm (data/exact/, doc/validation.md §6.5): CONTACT
   !> has one patch with a tread and a flange-side lobe, we have two patches. Under CONTACT's
   !> vertical load, the flange-side patch's share of the normal load is CONTACT's lobe share
   !> (31.3 %, 71.6 %) within 1.5 points with the patches coupled (the default), and Table 11's
   !> shares are kept within ±0.2 points: 30.5 %, 72.0 % coupled; 35.0 %, 66.1 % with the strips
   !> of each patch on their own (`local-hertz`), which miss CONTACT's by 3.7 and 5.5 points.
   subroutine test_lobes(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: y_ws(2) = [5.0_wp, 5.3_wp], f_z(2) = [65057.01997_wp, 65156.70991_wp]
      real(wp), parameter :: contact_share(2) = [0.312948_wp, 0.715826_wp]
      real(wp), parameter :: table_share(2, 2) = reshape([0.305_wp, 0.720_wp, 0.350_wp, &
         0.661_wp], [2, 2])
      type(contact_solver_type) :: solver
      type(normal_options_type) :: options
      integer :: r
      type(contact_result_type) :: result
      type(track_type) :: track
      type(lib_error), allocatable :: err
      real(wp) :: share
      integer :: k, flange

      call skip_without_profiles(error)
      if (allocated(error)) return
      track%rail_canted = .true.
      call solver%init(external(mbench_wheel), external(mbench_rail), &
         err, track=track, material=material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, &
         friction=0.3_wp))
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do r = 1, 2
         if (r == 2) then
            call new_normal_options(options, err, reduction='local-hertz')
            if (.not. allocated(err)) call solver%set_options(err, normal=options)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
         end if
         do k = 1, 2
            call solver%solve(y_ws(k), 0.0_wp, contact_load_type(load_vertical_force, f_z(k)), &
               creepage_type(0.0_wp, 0.0_wp, 0.0_wp), result, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            call check(error, result%n_loaded, 2, message='two loaded patches')
            if (allocated(error)) return
            flange = minloc(result%patch(1:2)%y_track, dim=1)
            share = result%patch(flange)%fn/sum(result%patch(1:2)%fn)
            if (r == 1) call check(error, share, contact_share(k), thr=0.015_wp, &
               message='flange-side share against CONTACT')
            if (allocated(error)) return
            call check(error, share, table_share(k, r), thr=0.002_wp, &
               message='flange-side share against Table 11')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_lobes

   !> The DOE per lobe at Y_WS = 5.0 and 5.3 mm (doc/validation.md §6.5, doc/validation/lobes.md):
   !> each of our two patches (defaults, the vertical load for which Σ F_n = 64.7 kN as in
   !> CONTACT's module 3) with the creepages carried from CONTACT's geometric point to its own by
   !> the rigid slip, ν_x,k = ξ − φ (y_k − y_G), y_k = (y_track,k − y_ref)/cos δ, against
   !> CONTACT's forces of the lobe it lies on (each over the lobe's F_n): the table within ±0.002.
   !> And the wheel's Σ F/(μ Σ F_n) over both patches against CONTACT's one f of its joined patch
   !> (doe_6x6x6_exact_nonhertz.csv, issue 28): its row of the table within ±0.002.
   subroutine test_lobe_doe(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: names(2) = [character(len=6) :: 'yws5p0', 'yws5p3']
      real(wp), parameter :: y_ws(2) = [5.0_wp, 5.3_wp], y_ref(2) = [734.5832_wp, 729.5134_wp]
      real(wp), parameter :: delta(2) = [-0.166_wp, -0.252651_wp]
      real(wp), parameter :: y_geo(2) = [2.704981413_wp, -3.117605365_wp]
      !> Track y of each lobe's pressure centre (lobes.csv), lobe 1 on the flange side.
      real(wp), parameter :: y_lobe(2, 2) = reshape([726.61_wp, 737.03_wp, 726.50_wp, &
         736.36_wp], [2, 2])
      real(wp), parameter :: rows(4, 2, 2) = reshape([ &
         0.022_wp, 0.029_wp, 0.002_wp, 0.007_wp, 0.011_wp, 0.019_wp, 0.006_wp, 0.009_wp, &
         0.017_wp, 0.023_wp, 0.012_wp, 0.018_wp, 0.024_wp, 0.028_wp, 0.005_wp, 0.013_wp], &
         [4, 2, 2])
      !> The wheel's sum against the joined patch, per position.
      real(wp), parameter :: wheel_rows(4, 2) = reshape([ &
         0.008_wp, 0.015_wp, 0.003_wp, 0.003_wp, 0.013_wp, 0.013_wp, 0.008_wp, 0.008_wp], [4, 2])
      real(wp), allocatable :: joined(:, :), wx(:), wy(:)
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      real(wp), allocatable :: cases(:, :), ex(:), ey(:)
      real(wp) :: y_k, nux
      integer :: ip, il, k, best, i, n
      logical :: there

      do ip = 1, 2
         inquire (file='data/exact/'//names(ip)//'/doe_6x6x6_exact_nonhertz_per_lobe.csv', &
            exist=there)
         if (.not. there) then
            call test_failed(error, 'data/exact/'//names(ip)//' is absent')
            return
         end if
         call two_patch_solution(y_ws(ip), geometry, patches, error)
         if (allocated(error) .or. .not. allocated(patches)) return
         call read_columns('data/exact/'//names(ip)//'/doe_6x6x6_exact_nonhertz_per_lobe.csv', &
            [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m', 'lobe', 'fx', 'fy'], cases, &
            error)
         if (allocated(error)) return
         call read_columns('data/exact/'//names(ip)//'/doe_6x6x6_exact_nonhertz.csv', &
            [character(len=2) :: 'fx', 'fy'], joined, error)
         if (allocated(error)) return
         call check(error, size(joined, 1), 216, message=names(ip)//': cases of the joined patch')
         if (allocated(error)) return
         wx = [(0.0_wp, i = 1, 216)]
         wy = wx
         call recommended_options(options)
         do il = 1, 2
            best = 1
            do k = 2, size(geometry)
               if (abs(geometry(k)%y_track - y_lobe(il, ip)) < &
                  abs(geometry(best)%y_track - y_lobe(il, ip))) best = k
            end do
            y_k = (geometry(best)%y_track - y_ref(ip))/cos(delta(ip))
            call prepare_fastsim_sh(ws, patches(best), material_type(), options, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            n = count(nint(cases(:, 4)) == il)
            call check(error, n, 216, message=names(ip)//': cases of the lobe')
            if (allocated(error)) return
            if (allocated(ex)) deallocate (ex, ey)
            allocate (ex(n), ey(n))
            n = 0
            do i = 1, size(cases, 1)
               if (nint(cases(i, 4)) /= il) cycle
               n = n + 1
               nux = cases(i, 1) - 1.0e-3_wp*cases(i, 3)*(y_k - y_geo(ip))
               call solve_prepared(ws, creepage_type(-nux, -cases(i, 2), &
                  -1.0e-3_wp*cases(i, 3)), result, err)
               if (allocated(err)) then
                  call test_failed(error, err%message); return
               end if
               ex(n) = abs(-result%fx_norm - cases(i, 5))
               ey(n) = abs(-result%fy_norm - cases(i, 6))
               ! The lobe's rows are the joined DOE's cases in its order.
               wx(n) = wx(n) - result%fx_norm*patches(best)%load/sum(patches%load)
               wy(n) = wy(n) - result%fy_norm*patches(best)%load/sum(patches%load)
            end do
            call check_row(ex, ey, rows(:, il, ip), names(ip)//' lobe '// &
               merge('1', '2', il == 1), error)
            if (allocated(error)) return
         end do
         call check_row(abs(wx - joined(:, 1)), abs(wy - joined(:, 2)), wheel_rows(:, ip), &
            names(ip)//' wheel sum against the joined patch', error)
         if (allocated(error)) return
      end do
   end subroutine test_lobe_doe

   !> Our patches at y_ws with the default options under the vertical load for which their
   !> normal forces add up to 64.7 kN (patches unallocated and the test skipped without the
   !> external data).
   subroutine two_patch_solution(y_ws, geometry, patches, error, reduction)
      real(wp), intent(in) :: y_ws
      type(patch_geometry_type), allocatable, intent(out) :: geometry(:)
      type(normal_patch_type), allocatable, intent(out) :: patches(:)
      type(error_type), allocatable, intent(out) :: error
      !> Normal reduction (default: the library's, `coupled`).
      character(len=*), intent(in), optional :: reduction
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(normal_contact_type), allocatable :: contacts(:)
      type(normal_options_type) :: options
      type(lib_error), allocatable :: err
      real(wp) :: f_z, dz
      integer :: k, it

      call skip_without_profiles(error)
      if (allocated(error)) return
      call manchester_profiles(wheel, rail, track, err)
      if (.not. allocated(err)) call find_contact_patches(wheel, rail, track, &
         wheelset_position_type(y_ws=y_ws), contact_options_type(), geometry, err)
      if (.not. allocated(err)) then
         if (present(reduction)) then
            call new_normal_options(options, err, reduction=reduction)
         else
            call new_normal_options(options, err)
         end if
      end if
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      allocate (contacts(size(geometry)), patches(size(geometry)))
      do k = 1, size(geometry)
         call prepare_normal_contact(contacts(k), geometry(k), options, material_type(), err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
      end do
      f_z = normal_force
      do it = 1, 4
         call solve_vertical_load(contacts, f_z, patches, dz, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         if (it < 4) f_z = f_z*normal_force/sum(patches%load)
      end do
   end subroutine two_patch_solution

   !> max |Δf_x|, max |Δf_y|, P80 |Δf_x|, P80 |Δf_y| against a table row, each within ±0.002.
   subroutine check_row(ex, ey, row, label, error)
      real(wp), intent(in) :: ex(:), ey(:), row(4)
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      call check(error, maxval(ex), row(1), thr=0.002_wp, message=label//' max |Delta f_x|')
      if (allocated(error)) return
      call check(error, maxval(ey), row(2), thr=0.002_wp, message=label//' max |Delta f_y|')
      if (allocated(error)) return
      call check(error, percentile(ex, 0.8_wp), row(3), thr=0.002_wp, &
         message=label//' P80 |Delta f_x|')
      if (allocated(error)) return
      call check(error, percentile(ey, 0.8_wp), row(4), thr=0.002_wp, &
         message=label//' P80 |Delta f_y|')
   end subroutine check_row

   !> |Δf_x|, |Δf_y| of the recommended tangential settings over an
   !> exact-theory DOE file (the shared columns) at Y_WS, on the patch nearest CONTACT's
   !> reference point y_ref (track y) with the given normal reduction (default: the library's);
   !> ex unallocated (and the test skipped) without the data.
   subroutine doe_errors(doe, y_ws, y_ref, n_expected, ex, ey, error, reduction, &
      correction, builtin)
      character(len=*), intent(in) :: doe
      real(wp), intent(in) :: y_ws, y_ref
      integer, intent(in) :: n_expected
      real(wp), allocatable, intent(out) :: ex(:), ey(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: reduction
      !> Tangential `correction_*` (default: the library's, `exact-ellipse`).
      integer, intent(in), optional :: correction
      !> The built-in S1002 and UIC60-canted instead of the Manchester files (default .false.).
      logical, intent(in), optional :: builtin
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      real(wp), allocatable :: cases(:, :)
      integer :: i, n
      logical :: there

      inquire (file=doe, exist=there)
      if (.not. there) then
         call test_failed(error, doe//' is absent')
         return
      end if
      call reference_patch(patch, error, y_ws=y_ws, y_ref=y_ref, reduction=reduction, &
         builtin=builtin)
      if (allocated(error)) return
      call read_columns(doe, [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m', 'fx', 'fy'], &
         cases, error)
      if (allocated(error)) return
      call recommended_options(options)
      if (present(correction)) options%correction = correction
      call prepare_fastsim_sh(ws, patch, material_type(), options, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      n = size(cases, 1)
      call check(error, n, n_expected, message=doe//': cases read')
      if (allocated(error)) return
      allocate (ex(n), ey(n))
      do i = 1, n
         call solve_prepared(ws, creepage_type(-cases(i, 1), -cases(i, 2), &
            -1.0e-3_wp*cases(i, 3)), result, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         ex(i) = abs(-result%fx_norm - cases(i, 4))
         ey(i) = abs(-result%fy_norm - cases(i, 5))
      end do
   end subroutine doe_errors

   ! ------------------------------------------------------------------ helpers

   !> The recommended tangential settings (doc/validation.md), explicitly: W1, uniform spin,
   !> longitudinal spin flexibility, the exact-ellipse correction, 50 elements per strip.
   subroutine recommended_options(options)
      type(tangential_options_type), intent(out) :: options
      type(lib_error), allocatable :: err
      call parse_bound('weighted', options%bound, err)
      call parse_spin_model('uniform', options%spin_model, err)
      call parse_spin_flexibility('longitudinal', options%spin_flexibility, err)
      call parse_correction('exact-ellipse', options%correction, err)
      options%n_elements = 50
      options%fields = .false.
   end subroutine recommended_options

   !> The normal solution of the reference case: Manchester profiles, Y_WS = 0, semi-Hertz with
   !> the default (coupled) reduction, 100 strips, F_n = 64.7 kN, G = 82670 MPa, ν = 0.27 (the
   !> material_type defaults). Skips when the shared data is absent.
   subroutine reference_patch(patch, error, y_ws, y_ref, reduction, builtin)
      type(normal_patch_type), intent(out) :: patch
      type(error_type), allocatable, intent(out) :: error
      !> Normal reduction (default: the library's, `coupled`).
      character(len=*), intent(in), optional :: reduction
      !> Y_WS (default 0) and CONTACT's reference point (track y): the patch nearest it is taken
      !> (default: the deepest).
      real(wp), intent(in), optional :: y_ws, y_ref
      !> The built-in S1002 and UIC60-canted (on the same track, no external data needed) instead
      !> of the Manchester files (default .false.).
      logical, intent(in), optional :: builtin
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(lib_error), allocatable :: err
      real(wp) :: shift
      integer :: k, best

      if (present(builtin)) then
         if (builtin) then
            call builtin_profiles(wheel, rail, track, err)
         end if
      end if
      if (.not. (allocated(err) .or. builtin_chosen())) then
         call skip_without_profiles(error)
         if (allocated(error)) return
         call manchester_profiles(wheel, rail, track, err)
      end if
      shift = 0.0_wp
      if (present(y_ws)) shift = y_ws
      if (.not. allocated(err)) call find_contact_patches(wheel, rail, track, &
         wheelset_position_type(y_ws=shift), contact_options_type(), geometry, err)
      best = 1
      if (.not. allocated(err) .and. present(y_ref)) then
         do k = 2, size(geometry)
            if (abs(geometry(k)%y_track - y_ref) < abs(geometry(best)%y_track - y_ref)) best = k
         end do
      end if
      if (.not. allocated(err)) then
         if (present(reduction)) then
            call new_normal_options(options, err, method='semi-hertz', reduction=reduction, &
               n_strips=100)
         else
            call new_normal_options(options, err, method='semi-hertz', n_strips=100)
         end if
      end if
      if (.not. allocated(err)) call prepare_normal_contact(contact, geometry(best), options, &
         material_type(), err)
      if (.not. allocated(err)) call solve_load(contact, normal_force, patch, err)
      if (allocated(err)) call test_failed(error, err%message)
   contains
      logical function builtin_chosen()
         builtin_chosen = .false.
         if (present(builtin)) builtin_chosen = builtin
      end function builtin_chosen
   end subroutine reference_patch

   !> The built-in S1002 and UIC60-canted (1:40 in the profile, origin at its top, as the
   !> Manchester rail file), cleaned as a case cleans them, on the Manchester track.
   subroutine builtin_profiles(wheel, rail, track, err)
      type(profile_type), intent(out) :: wheel, rail
      type(track_type), intent(out) :: track
      type(lib_error), allocatable, intent(out) :: err
      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call clean_profile(wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60-canted', rail, err)
      if (.not. allocated(err)) call clean_profile(rail, err)
      track%rail_canted = .true.
   end subroutine builtin_profiles

   !> Mark the test skipped (error allocated, as skip_test does) when SHCONTACT_EXTERNAL_DATA is
   !> unset, failed when it names a folder without the Manchester sample profiles.
   subroutine skip_without_profiles(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: path
      path = external_file(mbench_wheel, error)
      if (.not. allocated(error)) path = external_file(mbench_rail, error)
   end subroutine skip_without_profiles

   !> The Manchester profiles of the external data (profiles/), read and cleaned, on the track
   !> with the rail already canted (README §2). Call skip_without_profiles first.
   subroutine manchester_profiles(wheel, rail, track, err)
      type(profile_type), intent(out) :: wheel, rail
      type(track_type), intent(out) :: track
      type(lib_error), allocatable, intent(out) :: err
      call read_profile(external(mbench_wheel), wheel, err)
      if (.not. allocated(err)) call clean_profile(wheel, err)
      if (.not. allocated(err)) call read_profile(external(mbench_rail), rail, err)
      if (.not. allocated(err)) call clean_profile(rail, err)
      track%rail_canted = .true.
   end subroutine manchester_profiles

   !> Path of a file of the external data, once skip_without_profiles has let the test run.
   function external(relative) result(path)
      character(len=*), intent(in) :: relative
      character(len=:), allocatable :: path
      type(error_type), allocatable :: missing
      path = external_file(relative, missing)
   end function external

   !> CONTACT's exact normal results (headline_summary.csv, row module3_exact_nonhertz).
   subroutine reference_normal(approach, area, length, width, error)
      real(wp), intent(out) :: approach, area, length, width
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: rows(:, :)
      character(len=:), allocatable :: summary

      summary = external_file('reference/headline_summary.csv', error)
      if (allocated(error)) return
      call read_columns(summary, [character(len=17) :: &
         'pen_mm', 'contact_area_mm2', 'contact_length_mm', 'contact_width_mm'], rows, error, &
         row_tag='module3_exact_nonhertz')
      if (allocated(error)) return
      if (size(rows, 1) < 1) then
         call test_failed(error, 'headline_summary.csv: no module3_exact_nonhertz row')
         return
      end if
      approach = rows(1, 1)
      area = rows(1, 2)
      length = rows(1, 3)
      width = rows(1, 4)
   end subroutine reference_normal

   !> Lateral extent of the loaded strips (mm).
   pure real(wp) function patch_width(patch)
      type(normal_patch_type), intent(in) :: patch
      patch_width = patch%dy*count(patch%a(1:patch%n_strips) > 0.0_wp)
   end function patch_width

   !> The named columns of a CSV file with one header line, as reals (rows × columns). With
   !> row_tag, only rows having a cell equal to it are kept.
   subroutine read_columns(path, names, values, error, row_tag)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: names(:)
      real(wp), allocatable, intent(out) :: values(:, :)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: row_tag
      character(len=4096) :: line
      character(len=64), allocatable :: header(:), cells(:)
      integer :: unit, stat, k, n, pass, col(size(names))

      open (newunit=unit, file=path, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, path//': cannot open')
         return
      end if
      read (unit, '(a)') line
      call split(line, header)
      do k = 1, size(names)
         col(k) = findloc(header, names(k), dim=1)
         if (col(k) == 0) then
            call test_failed(error, path//': no column '//trim(names(k)))
            close (unit)
            return
         end if
      end do
      ! Pass 1 counts the rows, pass 2 reads them.
      do pass = 1, 2
         n = 0
         do
            read (unit, '(a)', iostat=stat) line
            if (stat /= 0) exit
            if (len_trim(line) == 0) cycle
            call split(line, cells)
            if (present(row_tag)) then
               if (findloc(cells, row_tag, dim=1) == 0) cycle
            end if
            n = n + 1
            if (pass == 1) cycle
            do k = 1, size(names)
               read (cells(col(k)), *, iostat=stat) values(n, k)
               if (stat /= 0) then
                  call test_failed(error, path//': not a number: '//trim(cells(col(k))))
                  close (unit)
                  return
               end if
            end do
         end do
         if (pass == 1) then
            allocate (values(n, size(names)))
            rewind (unit)
            read (unit, '(a)') line
         end if
      end do
      close (unit)
   end subroutine read_columns

   !> Split a CSV line at commas (the files read here have no quoted commas).
   pure subroutine split(line, cells)
      character(len=*), intent(in) :: line
      character(len=64), allocatable, intent(out) :: cells(:)
      integer :: i, n, start
      n = count([(line(i:i) == ',', i=1, len_trim(line))]) + 1
      allocate (cells(n))
      n = 0
      start = 1
      do i = 1, len_trim(line) + 1
         if (i <= len_trim(line)) then
            if (line(i:i) /= ',') cycle
         end if
         n = n + 1
         cells(n) = adjustl(line(start:i - 1))
         start = i + 1
      end do
   end subroutine split

   !> Nearest-rank percentile (the smallest value with at least a fraction q at or below it).
   function percentile(values, q) result(p)
      real(wp), intent(in) :: values(:), q
      real(wp) :: p
      real(wp) :: sorted(size(values)), v
      integer :: i, j
      sorted = values
      do i = 2, size(sorted)
         v = sorted(i)
         j = i - 1
         do while (j >= 1)
            if (sorted(j) <= v) exit
            sorted(j + 1) = sorted(j)
            j = j - 1
         end do
         sorted(j + 1) = v
      end do
      p = sorted(min(size(sorted), max(1, ceiling(q*size(sorted) - 1.0e-9_wp))))
   end function percentile

   !> Y_WS, y_geo, the approach pen, the reference point on the rail profile ycp_r, the contact
   !> angle delt and the reference point's track y ycp_tr of a summary.csv (key,value,...).
   subroutine summary_values(path, y_ws, y_geo, pen, ycp_r, delt, ycp_tr, error)
      character(len=*), intent(in) :: path
      real(wp), intent(out) :: y_ws, y_geo, pen, ycp_r, delt, ycp_tr
      type(error_type), allocatable, intent(out) :: error
      call summary_value(path, 'y_ws', y_ws, error)
      if (.not. allocated(error)) call summary_value(path, 'y_geo', y_geo, error)
      if (.not. allocated(error)) call summary_value(path, 'pen', pen, error)
      if (.not. allocated(error)) call summary_value(path, 'ycp_r', ycp_r, error)
      if (.not. allocated(error)) call summary_value(path, 'delt', delt, error)
      if (.not. allocated(error)) call summary_value(path, 'ycp_tr', ycp_tr, error)
   end subroutine summary_values

   !> One value of a summary.csv (key,value,unit,note; CONTACT runs' summaries).
   subroutine summary_value(path, key, value, error)
      character(len=*), intent(in) :: path, key
      real(wp), intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      character(len=512) :: line
      integer :: unit, stat, comma, last

      value = 0.0_wp
      open (newunit=unit, file=path, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, path//': cannot open')
         return
      end if
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         comma = index(line, ',')
         if (comma < 2) cycle
         if (line(1:comma - 1) /= key) cycle
         last = index(line(comma + 1:), ',')
         if (last == 0) last = len_trim(line(comma + 1:)) + 1
         read (line(comma + 1:comma + last - 1), *, iostat=stat) value
         close (unit)
         if (stat /= 0) call test_failed(error, path//': '//key//' is not a number')
         return
      end do
      close (unit)
      call test_failed(error, path//': no key '//key)
   end subroutine summary_value

end module test_validation
