!> Tests of the library interfaces (issue 8): the solver object, the legacy Fortran entry points
!> and the C API, called in-process. The examples built as separate programs are in test_examples.
module test_api
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_ptr, &
      c_null_char, c_loc, c_associated, c_intptr_t
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_io, &
      stat_usage
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type, side_left, side_right
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      prepare_profiles, find_contact_patches
   use shcontact_normal_options, only: normal_options_type
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_options, only: tangential_options_type, bound_ellipsoidal
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior, state_slip
   use shcontact_tangential_solver, only: solve_tangential
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      contact_fields_type, load_normal_force, load_vertical_force, load_approach, &
      load_vertical_position
   use shcontact_api_values, only: result_value_count, patch_value_count, result_values, &
      patch_values
   use shcontact_input_config, only: case_config_type, case_point_type, load_config
   use shcontact_case_result, only: case_result_type
   use shcontact_case_runner, only: run_setup_type, stage_type, prepare_run, solve_geometry, &
      solve_stage, solve_case, case_workspace_type
   use shcontact_api_capi, only: shcontact_create, shcontact_destroy, shcontact_solve, &
      shcontact_last_error, shcontact_set_option, shcontact_patch, shcontact_create_arrays, &
      shcontact_field_size, shcontact_fields, shcontact_get_field
   use test_flat_api, only: shc_create, shc_destroy, shc_set_material, shc_set_option, &
      shc_solve, shc_patch, shc_errmsg, shc_create_arrays, shc_get_profile, shc_field_size, &
      shc_fields, shc_create_ws, to_chars, from_chars, bitwise_equal
   implicit none
   private

   public :: collect_api, headline_t_y, headline_load, headline_creepage, headline_result

   !> Headline case (issue 8): lateral shift Y_WS (mm), the app's default (doc/theory.md decision
   !> 13), normal force (N) and creepages at the geometric contact point.
   real(wp), parameter :: headline_t_y = 4.733_wp
   real(wp), parameter :: headline_load = 64.7e3_wp
   type(creepage_type), parameter :: headline_creepage = creepage_type(0.58e-3_wp, 0.061e-3_wp, &
      2.74e-4_wp)

   !> A prescribed case for the flat interfaces: t_y, load mode and value, creepages.
   type :: flat_case_type
      real(wp) :: t_y
      integer :: mode
      real(wp) :: load, nu_x, nu_y, phi
   end type flat_case_type
   !> The headline case; a vertical load at t_y = 5 mm (tread and flange root, two patches).
   type(flat_case_type), parameter :: array_cases(2) = [ &
      flat_case_type(headline_t_y, load_normal_force, headline_load, 0.58e-3_wp, 0.061e-3_wp, &
      2.74e-4_wp), flat_case_type(5.0_wp, load_vertical_force, headline_load, 1.0e-3_wp, &
      -0.5e-3_wp, 1.0e-4_wp)]

contains

   !> Collect all exported unit tests.
   subroutine collect_api(testsuite)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('headline_matches_pipeline', test_headline_pipeline), &
         new_unittest('headline_matches_app_runner', test_app_runner), &
         new_unittest('init_from_profiles', test_init_profiles), &
         new_unittest('cache_gives_same_results', test_cache), &
         new_unittest('vertical_load_balance', test_vertical), &
         new_unittest('left_right_mirror', test_mirror), &
         new_unittest('fields_consistent_and_reused', test_fields), &
         new_unittest('moving_wheel_reuses_workspace', test_moving), &
         new_unittest('openmp_two_solvers', test_openmp), &
         new_unittest('bad_arguments_modern', test_bad_modern), &
         new_unittest('options_by_name', test_options), &
         new_unittest('legacy_interface', test_legacy), &
         new_unittest('legacy_bad_arguments', test_legacy_bad), &
         new_unittest('legacy_two_threads', test_legacy_threads), &
         new_unittest('c_interface', test_c_api), &
         new_unittest('legacy_arrays_equal_names', test_legacy_arrays), &
         new_unittest('c_arrays_equal_names', test_c_arrays), &
         new_unittest('bad_profile_arrays', test_bad_arrays), &
         new_unittest('legacy_fields_equal_modern', test_legacy_fields), &
         new_unittest('c_fields_equal_modern', test_c_fields), &
         new_unittest('fields_bad_calls', test_fields_bad) &
         ]
   end subroutine collect_api

   !> The headline case through a fresh solver object (right wheel, defaults).
   subroutine headline_result(result, error)
      !> Its result.
      type(contact_result_type), intent(out) :: result
      !> Set when the solver fails.
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      call new_solver(solver, error)
      if (allocated(error)) return
      call solve_checked(solver, headline_t_y, load_normal_force, headline_load, &
         headline_creepage, result, error)
   end subroutine headline_result

   !> The solver object against the stages called one by one as the app's case runner does
   !> (prepare_profiles → find_contact_patches → prepare_normal_contact → solve_load →
   !> solve_tangential with the app's defaults): the same numbers, bit for bit. Plus the
   !> closed-form checks: F_n as prescribed, forces opposing the creepages, |f| ≤ 1.
   subroutine test_headline_pipeline(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: result
      type(profile_type) :: wheel, rail
      type(prepared_profiles_type) :: prepared
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: normal
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: tangential
      type(lib_error), allocatable :: err
      real(wp) :: fz
      integer :: i

      call headline_result(result, error)
      if (allocated(error)) return
      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), prepared, err)
      if (.not. allocated(err)) call find_contact_patches(prepared, &
         wheelset_position_type(y_ws=headline_t_y), geometry, err)
      if (.not. allocated(err)) call prepare_normal_contact(contact, geometry(1), &
         normal_options_type(), material_type(), err)
      if (.not. allocated(err)) call solve_load(contact, headline_load, normal, err)
      if (.not. allocated(err)) call solve_tangential(ws, normal, material_type(), &
         headline_creepage, tangential_options_type(), tangential, err)
      if (lib_failed(error, err)) return

      call check(error, result%main_patch, 1)
      if (allocated(error)) return
      call check(error, result%n_patches, size(geometry))
      if (allocated(error)) return
      call check(error, bitwise_equal([result%main%fx, result%main%fy, result%main%mz, &
         result%main%fn, result%main%gamma0, result%main%gamma_plane, result%main%y_track], &
         [tangential%fx, tangential%fy, tangential%mz, normal%load, normal%gamma0, &
         geometry(1)%gamma0, geometry(1)%y_track + normal%y_shift*cos(geometry(1)%gamma0)]), &
         message='solver object differs from the stage-by-stage pipeline')
      if (allocated(error)) return
      call check(error, result%main%fn, headline_load, rel=.true., thr=1.0e-10_wp)
      if (allocated(error)) return
      call check(error, result%main%fx < 0.0_wp .and. result%main%fy < 0.0_wp, &
         message='forces on the wheel must oppose positive creepages (decision 2)')
      if (allocated(error)) return
      call check(error, hypot(result%main%fx_norm, result%main%fy_norm) <= 1.0_wp, &
         message='|F| exceeds mu F_n')
      if (allocated(error)) return
      ! Track frame: each strip's lateral and normal force turned by its own contact angle,
      ! F_z = Σ F_y,i sin γ_i − N_i cos γ_i, from the element tractions and the strip loads.
      fz = 0.0_wp
      do i = 1, normal%n_strips
         fz = fz + sum(tangential%py(:, i))*tangential%dx(i)*tangential%dy*sin(normal%gamma(i)) &
            - normal%strip_load(i)*cos(normal%gamma(i))
      end do
      call check(error, result%track%fz, fz, rel=.true., thr=1.0e-10_wp)
      if (allocated(error)) return
      ! Close to the whole patch turned by γ₀ (the patch is nearly flat here).
      call check(error, result%track%fz, result%main%fy*sin(result%main%gamma0) &
         - result%main%fn*cos(result%main%gamma0), rel=.true., thr=2.0e-3_wp)
   end subroutine test_headline_pipeline

   !> The app's case runner on its default configuration (the headline case) and the solver
   !> object give the same summary, bit for bit.
   subroutine test_app_runner(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: result
      type(case_config_type) :: config
      type(case_point_type) :: point
      type(run_setup_type) :: setup
      type(stage_type) :: stage
      type(patch_geometry_type), allocatable :: geometry(:)
      type(case_workspace_type) :: ws
      type(tangential_patch_type), allocatable :: tangential(:)
      type(case_result_type) :: app
      type(lib_error), allocatable :: err
      character(len=1) :: no_overrides(0)

      call headline_result(result, error)
      if (allocated(error)) return
      call load_config('', no_overrides, config, err)
      if (.not. allocated(err)) call prepare_run(config, setup, err)
      if (lib_failed(error, err)) return
      point = config%case_point(1)
      call check(error, point%t_y, headline_t_y)
      if (allocated(error)) return
      call solve_geometry(setup, point, geometry, err)
      if (lib_failed(error, err)) return
      call solve_stage(setup, point, geometry, stage)
      call solve_case(setup, point, stage, 1, ws, tangential, app, .false.)
      call check(error, app%summary%stat, 0, message='the app runner failed')
      if (allocated(error)) return
      call check(error, app%summary%main_patch == result%main_patch .and. &
         app%summary%n_patches == result%n_patches .and. app%summary%n_loaded == &
         result%n_loaded, message='patch counts differ from the app')
      if (allocated(error)) return
      call check(error, bitwise_equal([app%summary%fx, app%summary%fy, app%summary%mz, &
         app%summary%fn, app%summary%fx_norm, app%summary%fy_norm, app%summary%coulomb_ratio, &
         app%summary%approach, app%summary%gamma0, app%summary%y_track], [result%main%fx, &
         result%main%fy, result%main%mz, result%main%fn, result%main%fx_norm, &
         result%main%fy_norm, result%main%coulomb_ratio, result%main%approach, &
         result%main%gamma0, result%main%y_track]), &
         message='the solver object differs from the app runner')
   end subroutine test_app_runner

   !> init from profile_type objects gives the same result as init from `builtin:` names.
   subroutine test_init_profiles(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: by_name, by_profile
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err

      call headline_result(by_name, error)
      if (allocated(error)) return
      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call solver%init(wheel, rail, err, track=track_type(), &
         material=material_type(82670.0_wp, 0.27_wp, 0.3_wp), side=side_right)
      if (lib_failed(error, err)) return
      call solve_checked(solver, headline_t_y, load_normal_force, headline_load, &
         headline_creepage, by_profile, error)
      if (allocated(error)) return
      call check(error, same_result(by_name, by_profile), message='init by profiles differs')
   end subroutine test_init_profiles

   !> The object reuses geometry and normal solution between calls: a call after a different
   !> history gives the same numbers as the same call on a fresh object.
   subroutine test_cache(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: fresh, result
      type(creepage_type) :: other
      integer :: i

      other = creepage_type(-0.3e-3_wp, 0.2e-3_wp, 1.0e-4_wp)
      call headline_result(fresh, error)
      if (allocated(error)) return
      call new_solver(solver, error)
      if (allocated(error)) return
      ! Another position, other loads and creepages, then back to the headline case.
      do i = 1, 3
         call solve_checked(solver, 4.2_wp, load_normal_force, 50.0e3_wp, other, result, error)
         if (allocated(error)) return
         call solve_checked(solver, headline_t_y, load_vertical_force, 70.0e3_wp, other, &
            result, error)
         if (allocated(error)) return
         call solve_checked(solver, headline_t_y, load_normal_force, headline_load, other, &
            result, error)
         if (allocated(error)) return
         call solve_checked(solver, headline_t_y, load_normal_force, headline_load, &
            headline_creepage, result, error)
         if (allocated(error)) return
         call check(error, same_result(fresh, result), message='result depends on the history')
         if (allocated(error)) return
      end do
      ! The approach mode on the patch of the headline solution reproduces its normal force.
      call solve_checked(solver, headline_t_y, load_approach, fresh%main%approach, &
         headline_creepage, result, error)
      if (allocated(error)) return
      call check(error, result%main%fn, headline_load, rel=.true., thr=1.0e-9_wp)
   end subroutine test_cache

   !> Vertical load: Σ_k F_n,k cos γ_k = F_z (doc/theory.md §4.6), and the patches share one
   !> rigid approach.
   subroutine test_vertical(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      real(wp) :: balance
      integer :: k

      call new_solver(solver, error)
      if (allocated(error)) return
      ! The strips carry the load (doc/theory.md §4.6): without creep forces the reported
      ! vertical force is the load; with them it differs by their vertical share only.
      call solve_checked(solver, headline_t_y, load_vertical_force, headline_load, &
         creepage_type(0.0_wp, 0.0_wp, 0.0_wp), result, error)
      if (allocated(error)) return
      call check(error, result%n_loaded, result%n_patches)
      if (allocated(error)) return
      call check(error, -result%track%fz, headline_load, rel=.true., thr=1.0e-8_wp)
      if (allocated(error)) return
      balance = 0.0_wp
      do k = 1, result%n_loaded
         balance = balance + result%patch(k)%fn*cos(result%patch(k)%gamma_plane)
      end do
      ! On the tread the patch-plane resolution is within 0.3 % of the strips'.
      call check(error, balance, headline_load, rel=.true., thr=3.0e-3_wp)
      if (allocated(error)) return
      call solve_checked(solver, headline_t_y, load_vertical_force, headline_load, &
         headline_creepage, result, error)
      if (allocated(error)) return
      call check(error, result%track%fn, sum(result%patch(1:result%n_loaded)%fn), rel=.true., &
         thr=1.0e-14_wp)
   end subroutine test_vertical

   !> The left wheel at −t_y is the mirror image of the right wheel at t_y: the same forces in
   !> the side frame, the contact point at −y_track.
   subroutine test_mirror(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: left
      type(contact_result_type) :: right_result, left_result
      type(lib_error), allocatable :: err

      call headline_result(right_result, error)
      if (allocated(error)) return
      call left%init('builtin:S1002', 'builtin:UIC60', err, side=side_left)
      if (lib_failed(error, err)) return
      call solve_checked(left, -headline_t_y, load_normal_force, headline_load, &
         headline_creepage, left_result, error)
      if (allocated(error)) return
      call check(error, left_result%main%fx, right_result%main%fx, rel=.true., thr=1.0e-12_wp)
      if (allocated(error)) return
      call check(error, left_result%main%fy, right_result%main%fy, rel=.true., thr=1.0e-12_wp)
      if (allocated(error)) return
      call check(error, left_result%main%mz, right_result%main%mz, rel=.true., thr=1.0e-12_wp)
      if (allocated(error)) return
      call check(error, left_result%main%y_track, -right_result%main%y_track, rel=.true., &
         thr=1.0e-12_wp)
   end subroutine test_mirror

   !> The fields: the element tractions add up to the forces, the strips to the normal force;
   !> and the arrays of the fields are reused (same addresses) from call to call.
   subroutine test_fields(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(contact_fields_type) :: fields
      type(lib_error), allocatable :: err
      integer(c_intptr_t) :: addresses(4)
      real(wp) :: fx
      integer :: i

      call new_solver(solver, error)
      if (allocated(error)) return
      call solver%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, &
         headline_load), headline_creepage, result, err, fields)
      if (lib_failed(error, err)) return
      call check(error, fields%n_patches, 1)
      if (allocated(error)) return
      associate (t => fields%tangential(1), n => fields%normal(1))
         call check(error, n%load, result%main%fn, rel=.true., thr=1.0e-14_wp)
         if (allocated(error)) return
         call check(error, sum(n%strip_load), result%main%fn, rel=.true., thr=1.0e-12_wp)
         if (allocated(error)) return
         fx = 0.0_wp
         do i = 1, t%ny
            fx = fx + sum(t%px(:, i))*t%dx(i)*t%dy
         end do
         call check(error, fx, result%main%fx, rel=.true., thr=1.0e-10_wp)
         if (allocated(error)) return
         call check(error, all(t%state >= state_exterior .and. t%state <= state_slip), &
            message='element states outside 0..2')
         if (allocated(error)) return
      end associate
      addresses = field_addresses(fields)
      do i = 1, 10
         call solver%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, &
            headline_load*(1.0_wp + 0.01_wp*i)), creepage_type(0.1e-3_wp*i, 0.0_wp, 0.0_wp), &
            result, err, fields)
         if (lib_failed(error, err)) return
      end do
      call check(error, all(field_addresses(fields) == addresses), &
         message='the fields were reallocated between calls of the same size')
   end subroutine test_fields

   !> One solver moved among wheel positions (tables that shrink and grow, one and two patches,
   !> both force modes, with fields) gives at every call the result and the geometry fields of a
   !> new solver at that position, bit for bit: the reused workspaces carry nothing over.
   subroutine test_moving(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: moving, fresh
      type(contact_result_type) :: r_moving, r_fresh
      type(contact_fields_type) :: f_moving, f_fresh
      type(lib_error), allocatable :: err
      real(wp), parameter :: positions(6) = [headline_t_y, 0.0_wp, 9.0_wp, 1.0_wp, 5.5_wp, 2.0_wp]
      integer :: i, k, mode, two

      call new_solver(moving, error)
      if (allocated(error)) return
      two = 0
      do i = 1, 2*size(positions)
         mode = merge(load_vertical_force, load_normal_force, i > size(positions))
         call new_solver(fresh, error)
         if (allocated(error)) return
         call moving%solve(positions(1 + mod(i - 1, size(positions))), 0.0_wp, &
            contact_load_type(mode, headline_load), headline_creepage, r_moving, err, f_moving)
         if (lib_failed(error, err)) return
         call fresh%solve(positions(1 + mod(i - 1, size(positions))), 0.0_wp, &
            contact_load_type(mode, headline_load), headline_creepage, r_fresh, err, f_fresh)
         if (lib_failed(error, err)) return
         call check(error, same_result(r_fresh, r_moving), &
            message='the result depends on earlier positions')
         if (allocated(error)) return
         if (r_moving%n_loaded > 1) two = two + 1
         call check(error, f_moving%n_patches, f_fresh%n_patches)
         if (allocated(error)) return
         do k = 1, f_fresh%n_patches
            associate (a => f_moving%geometry(k), b => f_fresh%geometry(k))
               call check(error, bitwise_equal(a%y, b%y) .and. bitwise_equal(a%gap, b%gap) .and. &
                  bitwise_equal(a%curv_a, b%curv_a) .and. bitwise_equal(a%curv_b, b%curv_b) &
                  .and. bitwise_equal(a%gamma, b%gamma) .and. &
                  bitwise_equal(a%r_wheel, b%r_wheel), message='geometry fields differ')
               if (allocated(error)) return
            end associate
         end do
      end do
      call check(error, two > 0, message='expected a position with two loaded patches')
   end subroutine test_moving

   !> Two solver objects used from two OpenMP threads at once give the same numbers, bit for
   !> bit, as the same calls made one after the other.
   subroutine test_openmp(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n_calls = 6
      type(contact_solver_type) :: solvers(2)
      type(contact_result_type) :: sequential(n_calls, 2), parallel(n_calls, 2)
      logical :: ok(2)
      integer :: s

      do s = 1, 2
         call new_solver(solvers(s), error)
         if (allocated(error)) return
         call run_sequence(solvers(s), s, sequential(:, s), ok(s))
      end do
      call check(error, all(ok), message='a solve of the sequence failed')
      if (allocated(error)) return
      do s = 1, 2
         call new_solver(solvers(s), error)
         if (allocated(error)) return
      end do
      !$omp parallel sections num_threads(2) default(none) shared(solvers, parallel, ok)
      !$omp section
      call run_sequence(solvers(1), 1, parallel(:, 1), ok(1))
      !$omp section
      call run_sequence(solvers(2), 2, parallel(:, 2), ok(2))
      !$omp end parallel sections
      call check(error, all(ok), message='a solve in a thread failed')
      if (allocated(error)) return
      do s = 1, 2
         call check(error, all(same_results(sequential(:, s), parallel(:, s))), &
            message='threaded results differ from sequential ones')
         if (allocated(error)) return
      end do
   end subroutine test_openmp

   !> A sequence of solves at changing positions, loads and creepages (sequence 1 or 2).
   subroutine run_sequence(solver, which, results, ok)
      type(contact_solver_type), intent(inout) :: solver
      integer, intent(in) :: which
      type(contact_result_type), intent(out) :: results(:)
      logical, intent(out) :: ok
      type(lib_error), allocatable :: err
      integer :: i
      real(wp) :: t_y

      ok = .true.
      do i = 1, size(results)
         t_y = merge(4.0_wp + 0.1_wp*i, headline_t_y - 0.05_wp*(i/2), which == 1)
         call solver%solve(t_y, 0.0_wp, contact_load_type(merge(load_normal_force, &
            load_vertical_force, mod(i, 2) == 0), 50.0e3_wp + 2.0e3_wp*i), creepage_type( &
            0.2e-3_wp*i, -0.05e-3_wp*which, 1.0e-4_wp), results(i), err)
         ok = ok .and. .not. allocated(err)
      end do
   end subroutine run_sequence

   !> Bad input through the solver object: a status and a message, never a stop; the object
   !> stays usable.
   subroutine test_bad_modern(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver, unready
      type(contact_result_type) :: result, good
      type(lib_error), allocatable :: err
      real(wp) :: nan

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call unready%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, &
         headline_load), headline_creepage, result, err)
      call expect_error(error, err, stat_usage, 'init')
      if (allocated(error)) return
      call unready%init('no/such/wheel.prw', 'builtin:UIC60', err)
      call expect_error(error, err, stat_io, 'no/such/wheel.prw')
      if (allocated(error)) return
      call unready%init('builtin:S1002', 'builtin:NORAIL', err)
      call expect_error(error, err, stat_invalid_input, 'NORAIL')
      if (allocated(error)) return
      call unready%init('builtin:S1002', 'builtin:UIC60', err, side=0)
      call expect_error(error, err, stat_invalid_input, 'side')
      if (allocated(error)) return
      call unready%init('builtin:S1002', 'builtin:UIC60', err, &
         material=material_type(82670.0_wp, nan, 0.3_wp))
      call expect_error(error, err, stat_invalid_input, 'material')
      if (allocated(error)) return

      call new_solver(solver, error)
      if (allocated(error)) return
      call solver%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, &
         -headline_load), headline_creepage, result, err)
      call expect_error(error, err, stat_invalid_input, 'positive')
      if (allocated(error)) return
      call solver%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, &
         headline_load), creepage_type(nan, 0.0_wp, 0.0_wp), result, err)
      call expect_error(error, err, stat_invalid_input, 'NaN')
      if (allocated(error)) return
      call solver%solve(nan, 0.0_wp, contact_load_type(load_normal_force, headline_load), &
         headline_creepage, result, err)
      call expect_error(error, err, stat_invalid_input, 'position')
      if (allocated(error)) return
      call solver%solve(headline_t_y, 0.0_wp, contact_load_type(7, headline_load), &
         headline_creepage, result, err)
      call expect_error(error, err, stat_invalid_input, 'load mode')
      if (allocated(error)) return
      call solver%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, nan), &
         headline_creepage, result, err)
      call expect_error(error, err, stat_invalid_input, 'NaN')
      if (allocated(error)) return
      ! An approach whose normal force is past the largest load a force mode takes (5 mm at
      ! Y_WS = 0 gave 31 MN, p_max 14.6 GPa, with status 0); 1 mm (3.5 MN) is solved.
      call solver%solve(0.0_wp, 0.0_wp, contact_load_type(load_approach, 5.0_wp), &
         headline_creepage, result, err)
      call expect_error(error, err, stat_invalid_input, 'approach 5 mm gives the normal force')
      if (allocated(error)) return
      call solver%solve(0.0_wp, 0.0_wp, contact_load_type(load_approach, 1.0_wp), &
         headline_creepage, result, err)
      call check(error, .not. allocated(err), message='approach 1 mm refused')
      if (allocated(error)) return
      call solver%solve(0.0_wp, 0.0_wp, contact_load_type(load_vertical_position, 5.0_wp), &
         headline_creepage, result, err)
      call expect_error(error, err, stat_invalid_input, 'vertical position 5 mm gives the '// &
         'normal force')
      if (allocated(error)) return
      call solver%set_material(material_type(-1.0_wp, 0.27_wp, 0.3_wp), err)
      call expect_error(error, err, stat_invalid_input, 'shear modulus')
      if (allocated(error)) return
      ! Still usable, with unchanged data.
      call headline_result(good, error)
      if (allocated(error)) return
      call solve_checked(solver, headline_t_y, load_normal_force, headline_load, &
         headline_creepage, result, error)
      if (allocated(error)) return
      call check(error, same_result(good, result), message='solver changed by bad calls')
   end subroutine test_bad_modern

   !> Options by name (the flat interfaces' shcontact_set_option): a new bound changes the
   !> result as setting the typed option does; unknown keys and bad values are errors.
   subroutine test_options(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: typed
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      type(tangential_options_type) :: options
      integer :: ih, istat
      double precision :: values(25)
      character(len=256) :: msg

      call new_solver(typed, error)
      if (allocated(error)) return
      options%bound = bound_ellipsoidal
      call typed%set_options(err, tangential=options)
      if (lib_failed(error, err)) return
      call solve_checked(typed, headline_t_y, load_normal_force, headline_load, &
         headline_creepage, result, error)
      if (allocated(error)) return

      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_set_option(ih, 'Tangential%Bound', 'ellipsoidal', istat)
      call check(error, istat, 0)
      if (allocated(error)) return
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, headline_creepage%nu_x, &
         headline_creepage%nu_y, headline_creepage%phi, values, istat)
      call check(error, istat, 0)
      if (allocated(error)) return
      call check(error, bitwise_equal(values(1:3), [result%main%fx, result%main%fy, &
         result%main%mz]), message='option by name differs from the typed option')
      if (allocated(error)) return
      call shc_set_option(ih, 'tangential%colour', 'red', istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'tangential%bound') > 0, &
         message='unknown key: '//trim(msg))
      if (allocated(error)) return
      call shc_set_option(ih, 'normal%n_strips', 'many', istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'integer') > 0, &
         message='bad integer: '//trim(msg))
      if (allocated(error)) return
      call shc_set_option(ih, 'tangential%bound', 'square', istat)
      call check(error, istat, stat_invalid_input)
      call shc_destroy(ih, istat)
   end subroutine test_options

   !> The legacy entry points compute the headline case as the solver object does, and the
   !> flat values follow the documented layout.
   subroutine test_legacy(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: result
      double precision :: values(25), patch(17)
      real(wp) :: expected(result_value_count)
      integer :: ih, ih2, istat
      character(len=256) :: msg

      call headline_result(result, error)
      if (allocated(error)) return
      call result_values(result, expected)
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call check(error, istat, 0)
      if (allocated(error)) return
      call shc_set_material(ih, 82670.0d0, 0.27d0, 0.3d0, istat)
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, headline_creepage%nu_x, &
         headline_creepage%nu_y, headline_creepage%phi, values, istat)
      call check(error, istat, 0)
      if (allocated(error)) return
      call check(error, bitwise_equal(values, expected), &
         message='legacy result differs from the solver object')
      if (allocated(error)) return
      call check(error, bitwise_equal([values(1), values(4), values(18), values(23)], &
         [result%main%fx, result%main%fn, real(result%n_patches, wp), result%track%fz]), &
         message='flat layout: 1 fx, 4 fn, 18 n_patches, 23 sum fz')
      if (allocated(error)) return
      call shc_errmsg(ih, msg)
      call check(error, len_trim(msg), 0)
      if (allocated(error)) return
      call shc_patch(ih, 1, patch, istat)
      call check(error, istat == 0 .and. bitwise_equal(patch, values(1:17)), &
         message='patch 1 differs from the main patch')
      if (allocated(error)) return
      ! A second handle is independent; a destroyed handle is free for the next create.
      call shc_create(ih2, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call check(error, istat == 0 .and. ih2 /= ih, message='second handle')
      if (allocated(error)) return
      call shc_destroy(ih2, istat)
      call shc_destroy(ih, istat)
      call check(error, istat, 0)
      if (allocated(error)) return
      call shc_create(ih2, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call check(error, ih2, ih)
      call shc_destroy(ih2, istat)
   end subroutine test_legacy

   !> Bad calls through the legacy entry points: a status and a message.
   subroutine test_legacy_bad(error)
      type(error_type), allocatable, intent(out) :: error
      double precision :: values(25), patch(17), nan
      integer :: ih, istat, bad
      character(len=256) :: msg

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      do bad = -1, 1
         call shc_solve(bad*100000, headline_t_y, 0.0d0, 1, headline_load, 0.0d0, 0.0d0, &
            0.0d0, values, istat)
         call shc_errmsg(bad*100000, msg)
         call check(error, istat == stat_usage .and. index(msg, 'invalid contact handle') > 0, &
            message='invalid handle: '//trim(msg))
         if (allocated(error)) return
      end do
      call shc_create(ih, 'builtin:S1002', 'no_such_rail.prr', 1, istat)
      call shc_errmsg(ih, msg)
      call check(error, ih > 0 .and. istat == stat_io .and. index(msg, 'no_such_rail') > 0, &
         message='missing profile: '//trim(msg))
      if (allocated(error)) return
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, 0.0d0, 0.0d0, 0.0d0, values, &
         istat)
      call shc_errmsg(ih, msg)
      ! A later call repeats why the creation failed (a vehicle code may check only its solves).
      call check(error, istat == stat_usage .and. index(msg, 'its creation failed: ') > 0 &
         .and. index(msg, 'no_such_rail') > 0, message='solve after a failed creation: '// &
         trim(msg))
      if (allocated(error)) return
      call shc_destroy(ih, istat)
      call shc_create_ws(ih, 'builtin:S1002', 'no_such_rail.prr', istat)
      call check(error, ih > 0 .and. istat == stat_io, message='wheelset creation status')
      if (allocated(error)) return
      call shc_set_option(ih, 'material%friction', '0.3', istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'its creation failed: ') > 0 &
         .and. index(msg, 'no_such_rail') > 0, message='wheelset option after a failed '// &
         'creation: '//trim(msg))
      if (allocated(error)) return
      call shc_destroy(ih, istat)

      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_patch(ih, 1, patch, istat)
      call check(error, istat, stat_usage, message='patch values before any solve')
      if (allocated(error)) return
      call shc_solve(ih, headline_t_y, 0.0d0, 1, -headline_load, headline_creepage%nu_x, &
         headline_creepage%nu_y, headline_creepage%phi, values, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'positive') > 0, &
         message='negative load: '//trim(msg))
      if (allocated(error)) return
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, nan, headline_creepage%nu_y, &
         headline_creepage%phi, values, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'NaN') > 0, &
         message='NaN creepage: '//trim(msg))
      if (allocated(error)) return
      ! An approach of 0 (no load) or beyond the program's range is invalid input, not "the
      ! profiles do not touch" (status 6).
      call shc_solve(ih, headline_t_y, 0.0d0, 3, 0.0d0, 0.0d0, 0.0d0, 0.0d0, values, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'approach') > 0 .and. &
         index(msg, 'out of range') > 0, message='approach 0: '//trim(msg))
      if (allocated(error)) return
      call shc_set_material(ih, 82670.0d0, nan, 0.3d0, istat)
      call check(error, istat, stat_invalid_input)
      if (allocated(error)) return
      call shc_destroy(ih, istat)
      call shc_destroy(ih, istat)
      call check(error, istat, stat_usage, message='destroying twice')
   end subroutine test_legacy_bad

   !> Two handles created, used and destroyed from two OpenMP threads at once give the results
   !> of the same calls made one after the other.
   subroutine test_legacy_threads(error)
      type(error_type), allocatable, intent(out) :: error
      double precision :: sequential(25, 4, 2), parallel(25, 4, 2)
      integer :: stats(2)

      call legacy_sequence(1, sequential(:, :, 1), stats(1))
      call legacy_sequence(2, sequential(:, :, 2), stats(2))
      call check(error, all(stats == 0), message='a sequential legacy call failed')
      if (allocated(error)) return
      !$omp parallel sections num_threads(2) default(none) shared(parallel, stats)
      !$omp section
      call legacy_sequence(1, parallel(:, :, 1), stats(1))
      !$omp section
      call legacy_sequence(2, parallel(:, :, 2), stats(2))
      !$omp end parallel sections
      call check(error, all(stats == 0), message='a threaded legacy call failed')
      if (allocated(error)) return
      call check(error, bitwise_equal(reshape(sequential, [size(sequential)]), &
         reshape(parallel, [size(parallel)])), message='threaded legacy results differ')
   end subroutine test_legacy_threads

   !> Create a handle, solve four cases (sequence 1 or 2), destroy it; stat = worst status.
   subroutine legacy_sequence(which, values, stat)
      integer, intent(in) :: which
      double precision, intent(out) :: values(:, :)
      integer, intent(out) :: stat
      integer :: ih, i, istat

      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, stat)
      do i = 1, size(values, 2)
         call shc_solve(ih, 4.0d0 + 0.1d0*i + 0.05d0*which, 0.0d0, 1, 60.0d3, 0.1d-3*i, &
            0.0d0, 1.0d-4*which, values(:, i), istat)
         stat = max(stat, istat)
      end do
      call shc_destroy(ih, istat)
      stat = max(stat, istat)
   end subroutine legacy_sequence

   !> The C API called from Fortran: the headline case and the bad calls.
   subroutine test_c_api(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: result
      character(kind=c_char), target :: wheel(14), rail(14), key(18), value(12), message(256)
      type(c_ptr), target :: handle
      real(c_double) :: values(25), patch(17)
      real(wp) :: expected(result_value_count)
      integer(c_int) :: stat
      real(wp) :: nan

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call headline_result(result, error)
      if (allocated(error)) return
      call result_values(result, expected)
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      stat = shcontact_create(c_loc(handle), c_loc(wheel), c_loc(rail), 1_c_int)
      call check(error, stat == 0 .and. c_associated(handle), message='shcontact_create')
      if (allocated(error)) return
      key = to_chars('tangential%method', 18)
      value = to_chars('fastsim-sh', 12)
      stat = shcontact_set_option(handle, c_loc(key), c_loc(value))
      call check(error, stat, 0_c_int)
      if (allocated(error)) return
      stat = shcontact_solve(handle, headline_t_y, 0.0_c_double, 1_c_int, headline_load, &
         headline_creepage%nu_x, headline_creepage%nu_y, headline_creepage%phi, values)
      call check(error, stat == 0 .and. bitwise_equal(values, expected), &
         message='C result differs from the solver object')
      if (allocated(error)) return
      stat = shcontact_patch(handle, 1_c_int, patch)
      call check(error, stat == 0 .and. bitwise_equal(patch, values(1:17)), message='patch 1')
      if (allocated(error)) return

      stat = shcontact_solve(c_null_ptr, headline_t_y, 0.0_c_double, 1_c_int, headline_load, &
         0.0_c_double, 0.0_c_double, 0.0_c_double, values)
      call check(error, stat, 1_c_int)
      if (allocated(error)) return
      stat = shcontact_last_error(c_null_ptr, c_loc(message), size(message, kind=c_int))
      call check(error, stat == 1 .and. index(from_chars(message), 'NULL') > 0, &
         message='NULL handle: '//from_chars(message))
      if (allocated(error)) return
      stat = shcontact_solve(handle, headline_t_y, 0.0_c_double, 1_c_int, -headline_load, &
         0.0_c_double, 0.0_c_double, 0.0_c_double, values)
      call check(error, stat, int(stat_invalid_input, c_int))
      if (allocated(error)) return
      stat = shcontact_solve(handle, headline_t_y, 0.0_c_double, 1_c_int, headline_load, &
         0.0_c_double, nan, 0.0_c_double, values)
      call check(error, stat, int(stat_invalid_input, c_int))
      if (allocated(error)) return
      ! The message, cut to a short buffer and NUL-terminated.
      message = 'x'
      stat = shcontact_last_error(handle, c_loc(message), 8_c_int)
      call check(error, stat == stat_invalid_input .and. message(8) == c_null_char .and. &
         from_chars(message) == 'creepag', message='short buffer: '//from_chars(message))
      if (allocated(error)) return
      stat = shcontact_destroy(handle)
      call check(error, stat, 0_c_int)
      if (allocated(error)) return
      stat = shcontact_create(c_loc(handle), c_null_ptr, c_loc(rail), 1_c_int)
      call check(error, stat, int(stat_usage, c_int), message='NULL wheel name')
      stat = shcontact_destroy(handle)
   end subroutine test_c_api

   !> Profiles given as arrays through SHC_CREATE_ARRAYS (the built-in S1002 and UIC60 exported
   !> by builtin_profile) give the results of the handle created from their names, bit for bit:
   !> prescribed creepages with a normal force, a vertical load on two patches, every patch.
   subroutine test_legacy_arrays(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      double precision :: by_name(25), by_arrays(25), patch_name(17), patch_arrays(17)
      integer :: ih_name, ih_arrays, istat(2), icase, k, n
      character(len=256) :: msg
      type(flat_case_type) :: c
      double precision :: points(4000, 2)

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (lib_failed(error, err)) return
      call shc_create(ih_name, 'builtin:S1002', 'builtin:UIC60', 1, istat(1))
      call shc_create_arrays(ih_arrays, size(wheel%y), wheel%y, wheel%z, size(rail%y), rail%y, &
         rail%z, 1, istat(2))
      call shc_errmsg(ih_arrays, msg)
      call check(error, all(istat == 0), message='create: '//trim(msg))
      if (allocated(error)) return
      do icase = 1, size(array_cases)
         c = array_cases(icase)
            call shc_solve(ih_name, c%t_y, 0.0d0, c%mode, c%load, c%nu_x, c%nu_y, c%phi, &
               by_name, istat(1))
            call shc_solve(ih_arrays, c%t_y, 0.0d0, c%mode, c%load, c%nu_x, c%nu_y, c%phi, &
               by_arrays, istat(2))
         call check(error, all(istat == 0), message='solve failed')
         if (allocated(error)) return
         call check(error, bitwise_equal(by_name, by_arrays), message='case '// &
            char(48 + icase)//': profiles as arrays differ from the same profiles by name')
         if (allocated(error)) return
         do k = 1, nint(by_name(18))
            call shc_patch(ih_name, k, patch_name, istat(1))
            call shc_patch(ih_arrays, k, patch_arrays, istat(2))
            call check(error, all(istat == 0) .and. bitwise_equal(patch_name, patch_arrays), &
               message='case '//char(48 + icase)//': a patch differs')
            if (allocated(error)) return
         end do
      end do
      call check(error, nint(by_name(19)), 2, message='the vertical-load case loads two patches')
      if (allocated(error)) return
      ! SHC_GET_PROFILE gives the profiles back: first the count (capacity 0), then the points.
      call shc_get_profile(ih_name, 1, 0, n, points(:, 1), points(:, 2), istat(1))
      call check(error, istat(1) == stat_usage .and. n == size(wheel%y), &
         message='SHC_GET_PROFILE with no room: the count')
      if (allocated(error)) return
      call shc_get_profile(ih_name, 1, size(points, 1), n, points(:, 1), points(:, 2), istat(1))
      call check(error, istat(1) == 0 .and. n == size(wheel%y), message='SHC_GET_PROFILE wheel')
      if (allocated(error)) return
      call check(error, bitwise_equal(points(1:n, 1), wheel%y) .and. &
         bitwise_equal(points(1:n, 2), wheel%z), message='wheel points differ')
      if (allocated(error)) return
      call shc_get_profile(ih_arrays, 0, size(points, 1), n, points(:, 1), points(:, 2), istat(1))
      call check(error, istat(1) == 0 .and. bitwise_equal(points(1:n, 1), rail%y) .and. &
         bitwise_equal(points(1:n, 2), rail%z), message='rail points of the arrays handle')
      if (allocated(error)) return
      call shc_get_profile(ih_arrays, 7, size(points, 1), n, points(:, 1), points(:, 2), istat(1))
      call check(error, istat(1), stat_usage, message='SHC_GET_PROFILE bad kind')
      call shc_destroy(ih_name, istat(1))
      call shc_destroy(ih_arrays, istat(2))
   end subroutine test_legacy_arrays

   !> shcontact_create_arrays as SHC_CREATE_ARRAYS: the built-in profiles as arrays give the
   !> result of shcontact_create from their names, bit for bit (the left wheel too).
   subroutine test_c_arrays(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      real(c_double), allocatable, target :: wy(:), wz(:), ry(:), rz(:)
      character(kind=c_char), target :: wheel_name(14), rail_name(14)
      type(c_ptr), target :: by_name, by_arrays
      real(c_double) :: v_name(25), v_arrays(25)
      integer(c_int) :: stat(2), side

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (lib_failed(error, err)) return
      wy = wheel%y; wz = wheel%z; ry = rail%y; rz = rail%z
      wheel_name = to_chars('builtin:S1002', 14)
      rail_name = to_chars('builtin:UIC60', 14)
      do side = -1, 1, 2
         stat(1) = shcontact_create(c_loc(by_name), c_loc(wheel_name), c_loc(rail_name), side)
         stat(2) = shcontact_create_arrays(c_loc(by_arrays), size(wy, kind=c_int), c_loc(wy), &
            c_loc(wz), size(ry, kind=c_int), c_loc(ry), c_loc(rz), side)
         call check(error, all(stat == 0), message='shcontact_create_arrays')
         if (allocated(error)) return
         stat(1) = shcontact_solve(by_name, side*headline_t_y, 0.0_c_double, 2_c_int, &
            headline_load, headline_creepage%nu_x, headline_creepage%nu_y, &
            headline_creepage%phi, v_name)
         stat(2) = shcontact_solve(by_arrays, side*headline_t_y, 0.0_c_double, 2_c_int, &
            headline_load, headline_creepage%nu_x, headline_creepage%nu_y, &
            headline_creepage%phi, v_arrays)
         call check(error, all(stat == 0) .and. bitwise_equal(v_name, v_arrays), &
            message='C: profiles as arrays differ from the same profiles by name')
         if (allocated(error)) return
         stat(1) = shcontact_destroy(by_name)
         stat(2) = shcontact_destroy(by_arrays)
      end do
   end subroutine test_c_arrays

   !> Bad profile arrays through both flat interfaces: too few points, NaN, a duplicate point,
   !> the wrong order, a length in metres: status 2 and a message naming the array and the point;
   !> a negative count or a NULL array: status 1. The handle stays unusable (status 1).
   subroutine test_bad_arrays(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      real(wp), allocatable :: y(:), z(:)
      real(c_double), allocatable, target :: cy(:), cz(:), ry(:), rz(:)
      type(c_ptr), target :: handle
      character(kind=c_char), target :: message(512)
      double precision :: values(25)
      real(wp) :: nan
      integer :: ih, istat, icase
      integer(c_int) :: stat
      character(len=512) :: msg
      character(len=:), allocatable :: word, which

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (lib_failed(error, err)) return
      do icase = 1, 6
         y = wheel%y; z = wheel%z
         which = 'wheel array'
         select case (icase)
         case (1) ! one point
            y = y(1:1); z = z(1:1); word = 'point'
         case (2) ! NaN at point 7
            z(7) = nan; word = 'point 7'
         case (3) ! point 12 repeats point 11
            y(12) = y(11); z(12) = z(11); word = 'point 12'
         case (4) ! reversed: from the flange back to the field side
            y = y(size(y):1:-1); z = z(size(z):1:-1); word = 'y(1) > y(n)'
         case (5) ! in metres
            y = y/1000.0_wp; z = z/1000.0_wp; word = 'times'
         case (6) ! a rail with a duplicate point
            y = rail%y; z = rail%z; y(5) = y(4); z(5) = z(4); word = 'point 5'
            which = 'rail array'
         end select
         if (icase < 6) then
            call shc_create_arrays(ih, size(y), y, z, size(rail%y), rail%y, rail%z, 1, istat)
         else
            call shc_create_arrays(ih, size(wheel%y), wheel%y, wheel%z, size(y), y, z, 1, istat)
         end if
         call shc_errmsg(ih, msg)
         call check(error, ih > 0 .and. istat == stat_invalid_input .and. &
            index(msg, which) > 0 .and. index(msg, word) > 0, message='bad array case '// &
            char(48 + icase)//': status '//char(48 + istat)//', '//trim(msg))
         if (allocated(error)) return
         call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, 0.0d0, 0.0d0, 0.0d0, &
            values, istat)
         call check(error, istat, stat_usage, message='solve after a failed creation')
         if (allocated(error)) return
         call shc_destroy(ih, istat)
         ! The same array through the C API.
         cy = y; cz = z; ry = rail%y; rz = rail%z
         if (icase == 6) then
            cy = wheel%y; cz = wheel%z; ry = y; rz = z
         end if
         stat = shcontact_create_arrays(c_loc(handle), size(cy, kind=c_int), c_loc(cy), &
            c_loc(cz), size(ry, kind=c_int), c_loc(ry), c_loc(rz), 1_c_int)
         stat = shcontact_last_error(handle, c_loc(message), size(message, kind=c_int))
         call check(error, stat == stat_invalid_input .and. &
            index(from_chars(message), which) > 0, message='C bad array case '// &
            char(48 + icase)//': '//from_chars(message))
         if (allocated(error)) return
         stat = shcontact_destroy(handle)
      end do
      call shc_create_arrays(ih, -1, wheel%y, wheel%z, size(rail%y), rail%y, rail%z, 1, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'negative') > 0, &
         message='negative count: '//trim(msg))
      if (allocated(error)) return
      call shc_destroy(ih, istat)
      stat = shcontact_create_arrays(c_loc(handle), 10_c_int, c_null_ptr, c_loc(cz), &
         size(ry, kind=c_int), c_loc(ry), c_loc(rz), 1_c_int)
      call check(error, stat, int(stat_usage, c_int), message='NULL wheel array')
      stat = shcontact_destroy(handle)
   end subroutine test_bad_arrays

   !> SHC_FIELD_SIZE and SHC_FIELDS after solves with the option output%fields = all equal the
   !> solver object's fields bit for bit, and their sums (Σ p·area) equal each patch's forces; the
   !> results with fields equal those without. Cases: the headline case and a vertical load on
   !> two patches.
   subroutine test_legacy_fields(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(contact_fields_type) :: fields
      type(lib_error), allocatable :: err
      double precision :: values(25), plain(25), patch(17)
      double precision, allocatable :: x(:, :), y(:, :), area(:, :), pn(:, :), px(:, :), &
         py(:, :), slip(:, :)
      integer, allocatable :: state(:, :)
      integer :: ih, ih_plain, istat, icase, k, nx, ny
      type(flat_case_type) :: c

      call new_solver(solver, error)
      if (allocated(error)) return
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_create(ih_plain, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_set_option(ih, 'output%fields', 'all', istat)
      call check(error, istat, 0, message='option output%fields')
      if (allocated(error)) return
      do icase = 1, size(array_cases)
         c = array_cases(icase)
            call solver%solve(c%t_y, 0.0_wp, contact_load_type(c%mode, c%load), &
               creepage_type(c%nu_x, c%nu_y, c%phi), result, err, fields)
            if (lib_failed(error, err)) return
            call shc_solve(ih, c%t_y, 0.0d0, c%mode, c%load, c%nu_x, c%nu_y, c%phi, values, &
               istat)
            call shc_solve(ih_plain, c%t_y, 0.0d0, c%mode, c%load, c%nu_x, c%nu_y, c%phi, &
               plain, istat)
         call check(error, bitwise_equal(values, plain), &
            message='a solve with fields differs from one without')
         if (allocated(error)) return
         do k = 1, result%n_loaded
            call shc_field_size(ih, k, nx, ny, istat)
            call check(error, istat == 0 .and. nx == fields%tangential(k)%nx .and. &
               ny == fields%tangential(k)%ny .and. nx*ny > 0, message='field size')
            if (allocated(error)) return
            allocate (x(nx, ny), y(nx, ny), area(nx, ny), pn(nx, ny), px(nx, ny), py(nx, ny), &
               slip(nx, ny), state(nx, ny))
            call shc_fields(ih, k, nx, ny, x, y, area, pn, px, py, slip, state, istat)
            call check(error, istat, 0, message='SHC_FIELDS')
            if (allocated(error)) return
            call shc_patch(ih, k, patch, istat)
            call check_fields(error, fields%tangential(k), patch, x, y, area, pn, px, py, slip, &
               state)
            if (allocated(error)) return
            deallocate (x, y, area, pn, px, py, slip, state)
         end do
         ! A patch found but not loaded has no fields.
         if (result%n_patches > result%n_loaded) then
            call shc_field_size(ih, result%n_patches, nx, ny, istat)
            call check(error, istat == 0 .and. nx == 0 .and. ny == 0, &
               message='fields of a patch without load')
            if (allocated(error)) return
         end if
      end do
      call shc_destroy(ih, istat)
      call shc_destroy(ih_plain, istat)
   end subroutine test_legacy_fields

   !> shcontact_field_size and shcontact_fields as their legacy twins: the headline case's fields
   !> (C order [ny][nx]) equal the solver object's, their sums the forces.
   subroutine test_c_fields(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(contact_fields_type) :: fields
      type(lib_error), allocatable :: err
      character(kind=c_char), target :: wheel(14), rail(14), key(14), value(4), key_px(3)
      type(c_ptr), target :: handle
      real(c_double) :: values(25), patch(17)
      real(c_double), allocatable, target :: x(:, :), y(:, :), area(:, :), pn(:, :), &
         px(:, :), py(:, :), slip(:, :)
      integer(c_int), allocatable, target :: state(:, :)
      integer(c_int), target :: nx, ny
      integer(c_int) :: stat

      call new_solver(solver, error)
      if (allocated(error)) return
      call solver%solve(headline_t_y, 0.0_wp, contact_load_type(load_normal_force, &
         headline_load), headline_creepage, result, err, fields)
      if (lib_failed(error, err)) return
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      key = to_chars('output%fields', 14)
      key_px = to_chars('px', 3)
      value = to_chars('1', 4)
      stat = shcontact_create(c_loc(handle), c_loc(wheel), c_loc(rail), 1_c_int)
      if (stat == 0) stat = shcontact_set_option(handle, c_loc(key), c_loc(value))
      if (stat == 0) stat = shcontact_solve(handle, headline_t_y, 0.0_c_double, 1_c_int, &
         headline_load, headline_creepage%nu_x, headline_creepage%nu_y, &
         headline_creepage%phi, values)
      if (stat == 0) stat = shcontact_field_size(handle, 1_c_int, c_loc(nx), c_loc(ny))
      call check(error, stat == 0 .and. nx == fields%tangential(1)%nx .and. &
         ny == fields%tangential(1)%ny, message='C field size')
      if (allocated(error)) return
      allocate (x(nx, ny), y(nx, ny), area(nx, ny), pn(nx, ny), px(nx, ny), py(nx, ny), &
         slip(nx, ny), state(nx, ny))
      stat = shcontact_fields(handle, 1_c_int, nx, ny, c_loc(x), c_loc(y), c_loc(area), &
         c_loc(pn), c_loc(px), c_loc(py), c_loc(slip), c_loc(state))
      call check(error, stat, 0_c_int, message='shcontact_fields')
      if (allocated(error)) return
      stat = shcontact_patch(handle, 1_c_int, patch)
      call check_fields(error, fields%tangential(1), patch, x, y, area, pn, px, py, slip, state)
      if (allocated(error)) return
      ! Sizes that are not the fields' are refused (here smaller, within the arrays).
      stat = shcontact_fields(handle, 1_c_int, nx - 1_c_int, ny, c_loc(x), c_loc(y), &
         c_loc(area), c_loc(pn), c_loc(px), c_loc(py), c_loc(slip), c_loc(state))
      call check(error, stat, int(stat_usage, c_int), message='wrong field size')
      if (allocated(error)) return
      ! Larger than the arrays: refused before anything is written (the arrays keep the last
      ! call's values; they were zeroed past their ends before).
      px = -7.0_wp
      stat = shcontact_fields(handle, 1_c_int, nx, ny + 1_c_int, c_loc(x), c_loc(y), &
         c_loc(area), c_loc(pn), c_loc(px), c_loc(py), c_loc(slip), c_loc(state))
      call check(error, stat == stat_usage .and. all(px == -7.0_wp) .and. &
         all(pn == fields%tangential(1)%pn), message='larger field size wrote the arrays')
      if (allocated(error)) return
      stat = shcontact_get_field(handle, c_loc(key_px), 1_c_int, nx + 1_c_int, ny, c_loc(px))
      call check(error, stat == stat_usage .and. all(px == -7.0_wp), &
         message='shcontact_get_field with a larger size wrote the array')
      if (allocated(error)) return
      stat = shcontact_fields(handle, 1_c_int, nx, ny, c_null_ptr, c_loc(y), c_loc(area), &
         c_loc(pn), c_loc(px), c_loc(py), c_loc(slip), c_loc(state))
      call check(error, stat, int(stat_usage, c_int), message='NULL field array')
      if (allocated(error)) return
      ! Sizes whose product passes the int range, with NULL arrays: status 1, no crash.
      stat = shcontact_fields(handle, 1_c_int, 65536_c_int, 65536_c_int, c_null_ptr, &
         c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr, c_null_ptr)
      call check(error, stat, int(stat_usage, c_int), message='NULL arrays of 65536 x 65536')
      if (allocated(error)) return
      stat = shcontact_get_field(handle, c_loc(key_px), 1_c_int, 65536_c_int, 65536_c_int, &
         c_null_ptr)
      call check(error, stat, int(stat_usage, c_int), message='NULL field of 65536 x 65536')
      stat = shcontact_destroy(handle)
   end subroutine test_c_fields

   !> Fields asked for without the option, before any solve, of a patch that does not exist, or
   !> after the option was turned off again: status 1 and a message saying what to do.
   subroutine test_fields_bad(error)
      type(error_type), allocatable, intent(out) :: error
      double precision :: values(25), x(1, 1)
      integer :: ih, istat, nx, ny, state(1, 1)
      character(len=512) :: msg

      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_field_size(ih, 1, nx, ny, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'no result') > 0, &
         message='before a solve: '//trim(msg))
      if (allocated(error)) return
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, headline_creepage%nu_x, &
         headline_creepage%nu_y, headline_creepage%phi, values, istat)
      call shc_field_size(ih, 1, nx, ny, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'output%fields') > 0 .and. &
         nx == 0 .and. ny == 0, message='without the option: '//trim(msg))
      if (allocated(error)) return
      call shc_set_option(ih, 'output%fields', 'maybe', istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'all') > 0, &
         message='bad option value: '//trim(msg))
      if (allocated(error)) return
      call shc_set_option(ih, 'OUTPUT%FIELDS', 'all', istat)
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, headline_creepage%nu_x, &
         headline_creepage%nu_y, headline_creepage%phi, values, istat)
      call shc_field_size(ih, 9, nx, ny, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'patch 9') > 0, &
         message='patch out of range: '//trim(msg))
      if (allocated(error)) return
      call shc_fields(ih, 1, 1, 1, x, x, x, x, x, x, x, state, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'size') > 0, &
         message='wrong sizes: '//trim(msg))
      if (allocated(error)) return
      call shc_set_option(ih, 'output%fields', 'none', istat)
      call shc_solve(ih, headline_t_y, 0.0d0, 1, headline_load, headline_creepage%nu_x, &
         headline_creepage%nu_y, headline_creepage%phi, values, istat)
      call shc_field_size(ih, 1, nx, ny, istat)
      call check(error, istat, stat_usage, message='fields after the option was turned off')
      call shc_destroy(ih, istat)
   end subroutine test_fields_bad

   ! --- helpers ---------------------------------------------------------------------------------

   !> Flat fields against a patch's tangential solution: x, pn, px, py, slip, state bit for bit,
   !> y the strip centres, area = Δx_i·Δy; Σ px·area = F_x, Σ py·area = F_y, Σ pn·area ≈ F_n.
   subroutine check_fields(error, t, patch, x, y, area, pn, px, py, slip, state)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type), intent(in) :: t
      real(wp), intent(in) :: patch(:)
      real(wp), intent(in) :: x(:, :), y(:, :), area(:, :), pn(:, :), px(:, :), py(:, :), &
         slip(:, :)
      integer, intent(in) :: state(:, :)
      integer :: i

      call check(error, bitwise_equal(reshape(x, [size(x)]), reshape(t%x, [size(t%x)])) .and. &
         bitwise_equal(reshape(pn, [size(pn)]), reshape(t%pn, [size(t%pn)])) .and. &
         bitwise_equal(reshape(px, [size(px)]), reshape(t%px, [size(t%px)])) .and. &
         bitwise_equal(reshape(py, [size(py)]), reshape(t%py, [size(t%py)])) .and. &
         bitwise_equal(reshape(slip, [size(slip)]), reshape(t%slip, [size(t%slip)])) .and. &
         all(state == int(t%state)), message='flat fields differ from the solver object''s')
      if (allocated(error)) return
      do i = 1, t%ny
         call check(error, all(y(:, i) == t%y(i)) .and. all(area(:, i) == t%dx(i)*t%dy), &
            message='y or area of a strip')
         if (allocated(error)) return
      end do
      call check(error, sum(px*area), patch(1), rel=.true., thr=1.0e-10_wp, &
         message='sum of px*area is not F_x')
      if (allocated(error)) return
      call check(error, sum(py*area), patch(2), rel=.true., thr=1.0e-10_wp, &
         message='sum of py*area is not F_y')
      if (allocated(error)) return
      ! The element pressure is the semi-ellipse's value at the element centre (midpoint rule).
      call check(error, sum(pn*area), patch(4), rel=.true., thr=2.0e-2_wp, &
         message='sum of pn*area far from F_n')
   end subroutine check_fields

   !> A solver for the headline case's data (defaults: S1002, UIC60 canted by the track, R₀ = 460,
   !> G = 82 670 MPa, ν = 0.27, μ = 0.3, FASTSIM_SH).
   subroutine new_solver(solver, error)
      type(contact_solver_type), intent(inout) :: solver
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      if (lib_failed(error, err)) return
   end subroutine new_solver

   !> Solve and turn a library error into a test failure.
   subroutine solve_checked(solver, t_y, mode, load, creepage, result, error)
      type(contact_solver_type), intent(inout) :: solver
      real(wp), intent(in) :: t_y
      integer, intent(in) :: mode
      real(wp), intent(in) :: load
      type(creepage_type), intent(in) :: creepage
      type(contact_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call solver%solve(t_y, 0.0_wp, contact_load_type(mode, load), creepage, result, err)
      if (lib_failed(error, err)) return
   end subroutine solve_checked

   !> True (and error set) when the library reported an error.
   logical function lib_failed(error, err)
      type(error_type), allocatable, intent(inout) :: error
      type(lib_error), allocatable, intent(in) :: err
      lib_failed = allocated(err)
      if (lib_failed) call test_failed(error, 'library error: '//err%message)
   end function lib_failed

   !> An expected library error: its status and a word of its message.
   subroutine expect_error(error, err, stat, word)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable, intent(in) :: err
      integer, intent(in) :: stat
      character(len=*), intent(in) :: word
      if (.not. allocated(err)) then
         call test_failed(error, 'expected an error mentioning "'//word//'"')
         return
      end if
      call check(error, err%stat == stat .and. index(err%message, word) > 0, &
         message='unexpected error: '//err%message)
   end subroutine expect_error

   !> Bitwise equality of two results (all flat values and every patch).
   pure logical function same_result(a, b)
      type(contact_result_type), intent(in) :: a, b
      real(wp) :: va(result_value_count), vb(result_value_count)
      real(wp) :: pa(patch_value_count), pb(patch_value_count)
      integer :: k
      call result_values(a, va)
      call result_values(b, vb)
      same_result = bitwise_equal(va, vb)
      do k = 1, a%n_patches
         call patch_values(a%patch(k), pa)
         call patch_values(b%patch(k), pb)
         same_result = same_result .and. bitwise_equal(pa, pb)
      end do
   end function same_result

   !> Elementwise [[same_result]].
   elemental logical function same_results(a, b)
      type(contact_result_type), intent(in) :: a, b
      same_results = same_result(a, b)
   end function same_results

   !> Addresses of the field arrays of patch 1.
   function field_addresses(fields) result(addresses)
      type(contact_fields_type), intent(in), target :: fields
      integer(c_intptr_t) :: addresses(4)
      addresses = [transfer(c_loc(fields%tangential(1)%px), 0_c_intptr_t), &
         transfer(c_loc(fields%tangential(1)%state), 0_c_intptr_t), &
         transfer(c_loc(fields%normal(1)%a), 0_c_intptr_t), &
         transfer(c_loc(fields%geometry(1)%gap), 0_c_intptr_t)]
   end function field_addresses

end module test_api
