!> Tests of the named option presets (issue 25 item 4, shcontact_api_preset): what the vehicle
!> preset sets, that the default preset restores the library's defaults, that a bad name is
!> rejected without changing anything, and that the vehicle preset's kinematic forces stay
!> within 0.01 in f = F/(μF_n) of the default's on states of the hunting trajectory (tread and
!> flange, yaw up to 10 mrad) with the vertical load balanced as tightly. The one option
!> `&normal preset` (case file, C/F77 key `normal%preset`): the app's run and the keyed handle
!> give set_preset's forces bit for bit, explicit n_strips/n_elements win over it in any order,
!> and an unknown name is refused with a message naming the option and the choices.
module test_preset
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_geometry_kinematics, only: wheelset_state_type, pure_rolling_pitch_rate
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      load_vertical_force, load_vertical_position
   use shcontact_api_preset, only: set_preset, apply_preset, preset_names
   use shcontact_core_material, only: material_type
   use shcontact_geometry_track, only: track_type
   use test_external_data, only: external_file
   use test_validation, only: read_columns, percentile, skip_without_profiles
   use test_kinematic_balance, only: flange_state
   use shcontact_input_config, only: case_config_type, case_point_type, read_config_text, &
      normal_options_of, tangential_options_of, table_step_of
   use shcontact_case_runner, only: run_setup_type, prepare_run, solve_kinematic_case
   use shcontact_case_result, only: case_result_type, case_summary, case_summary_type
   use shcontact_api_settings, only: library_setup_type, library_setup, set_config_value, &
      config_state, config_load
   use shcontact_api_values, only: kinematic_value_count, kinematic_values
   use shcontact_api_keyed, only: output_keys
   use test_flat_api, only: shc_create, shc_destroy, shc_set_option, shc_solve_state, &
      shc_get_value, shc_errmsg, bitwise_equal
   implicit none
   private

   public :: collect_preset

   !> Vertical wheel load (N), speed (mm/s) and friction coefficient of the default material.
   real(wp), parameter :: wheel_load = 64.7e3_wp, speed = 30.0e3_wp, mu = 0.3_wp
   !> A kinematic case (off centre, yawed, moving sideways) as keys and values.
   character(len=*), parameter :: case_keys(*) = [character(len=24) :: 'kinematics%mode', &
      'position%t_y', 'kinematics%yaw', 'kinematics%v_lateral', 'output%fields']
   character(len=*), parameter :: case_values(*) = [character(len=8) :: 'on', '3.0', &
      '0.004', '20.0', 'none']

contains

   !> Collect all exported unit tests.
   subroutine collect_preset(testsuite)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('vehicle_preset_options', test_options), &
         new_unittest('unknown_preset_rejected', test_unknown), &
         new_unittest('vehicle_forces_near_default', test_forces), &
         new_unittest('vehicle_flange_state_599_continuous', test_state_599), &
         new_unittest('vehicle_kinematic_sample_vs_exact', test_exact), &
         new_unittest('namelist_preset_is_set_preset', test_namelist), &
         new_unittest('keyed_preset_is_set_preset', test_keyed), &
         new_unittest('explicit_grid_wins_over_preset', test_precedence), &
         new_unittest('unknown_preset_option_refused', test_unknown_option) &
         ]
   end subroutine collect_preset

   !> The vehicle preset sets fewer strips and elements and coarser tables, keeps the other
   !> options, and the default preset gives back the library's defaults.
   subroutine test_options(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_options_type) :: normal, normal0
      type(tangential_options_type) :: tangential, tangential0
      type(contact_options_type) :: contact, contact0
      type(lib_error), allocatable :: lib

      call check(error, size(preset_names) == 2 .and. preset_names(2) == 'vehicle')
      if (allocated(error)) return
      tangential%bound = 1
      call apply_preset('Vehicle', normal, tangential, contact, lib)
      call check(error, .not. allocated(lib), 'the name is not case-sensitive')
      if (allocated(error)) return
      call check(error, normal%n_strips < normal0%n_strips .and. &
         tangential%n_elements < tangential0%n_elements .and. &
         contact%table_step > contact0%table_step, 'fewer strips, elements, table points')
      if (allocated(error)) return
      call check(error, tangential%bound == 1 .and. normal%reduction == normal0%reduction .and. &
         contact%kinematic_table_gap == contact0%kinematic_table_gap, 'other options kept')
      if (allocated(error)) return
      call apply_preset('default', normal, tangential, contact, lib)
      call check(error, .not. allocated(lib) .and. normal%n_strips == normal0%n_strips .and. &
         tangential%n_elements == tangential0%n_elements .and. &
         contact%table_step == contact0%table_step, 'the default preset restores the defaults')
   end subroutine test_options

   !> An unknown name: stat_invalid_input naming the presets, the solver unchanged.
   subroutine test_unknown(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      type(contact_options_type) :: contact
      type(lib_error), allocatable :: lib

      call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      call check(error, .not. allocated(lib), 'init')
      if (allocated(error)) return
      call set_preset(solver, 'fast', lib)
      call check(error, allocated(lib), 'an unknown preset is an error')
      if (allocated(error)) return
      call check(error, lib%stat == stat_invalid_input .and. index(lib%message, 'vehicle') > 0, &
         lib%message)
      if (allocated(error)) return
      call solver%get_options(normal, tangential)
      contact = solver%get_contact_options()
      call check(error, normal%n_strips == 100 .and. tangential%n_elements == 50 .and. &
         contact%table_step == 0.025_wp, 'solver unchanged')
   end subroutine test_unknown

   !> States of the benchmark's hunting trajectory, tread to flange (t_y = 0.5 … 8 mm, yaw up to
   !> 10 mrad, with lateral velocity and yaw rate): the vehicle preset's tangential forces (sum
   !> over the loaded patches in their contact planes, over μΣF_n) within 0.01 of the default's,
   !> both balancing the vertical load to 1e-5.
   subroutine test_forces(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: default, vehicle
      type(contact_result_type) :: a, b
      type(wheelset_state_type) :: state
      type(lib_error), allocatable :: lib
      real(wp), parameter :: amplitudes(4) = [0.5_wp, 2.0_wp, 4.0_wp, 8.0_wp], &
         phases(3) = [0.3_wp, 1.2_wp, 2.5_wp], w = 15.707963267948966_wp
      real(wp) :: psi, df
      integer :: i, j

      call default%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) call vehicle%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) call set_preset(vehicle, 'vehicle', lib)
      call check(error, .not. allocated(lib), 'init and preset')
      if (allocated(error)) return
      do i = 1, size(amplitudes)
         do j = 1, size(phases)
            psi = min(0.01_wp, 1.25e-3_wp*amplitudes(i))
            state = wheelset_state_type(y_ws=amplitudes(i)*sin(phases(j)), &
               yaw=-psi*cos(phases(j)), v_forward=speed, &
               v_lateral=amplitudes(i)*w*cos(phases(j)), yaw_rate=psi*w*sin(phases(j)), &
               pitch_rate=pure_rolling_pitch_rate(speed, 460.0_wp)*(1.0_wp + 2.0e-4_wp))
            call default%solve_kinematic(state, contact_load_type(load_vertical_force, &
               wheel_load), a, lib)
            if (.not. allocated(lib)) call vehicle%solve_kinematic(state, &
               contact_load_type(load_vertical_force, wheel_load), b, lib)
            call check(error, .not. allocated(lib), 'kinematic call')
            if (allocated(error)) return
            df = max(abs(f_of(b, 1) - f_of(a, 1)), abs(f_of(b, 2) - f_of(a, 2)))
            call check(error, df <= 0.01_wp, 'vehicle preset: |df| > 0.01 at state', &
               more=state_text(state, df))
            if (allocated(error)) return
            call check(error, abs(b%track%fz + wheel_load) <= 1.0e-5_wp*wheel_load .and. &
               abs(a%track%fz + wheel_load) <= 1.0e-5_wp*wheel_load, 'vertical balance')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_forces

   !> State 599 of the benchmark's flange trajectory (t_y = 7 + 2 sin(5π t) mm, yaw = 10
   !> sin(2π·1.618 t) mrad at t = 0.598 s), where the main lobe's last strip leaves the contact
   !> next to a loaded fillet strip: with the vehicle preset the carried vertical force C(Δz)
   !> jumped by 15 N between two approaches 2.5e-5 mm apart, right at F_z, and the call failed
   !> (the lobe's last strips took a ratio interpolated across the unloaded gap when their
   !> group emptied; shcontact_normal_coupling_groups' scale_patch, doc/performance.md, "Every
   !> group a node of the ratio interpolation"). C(Δz) over 0.5369 … 0.5372 mm in steps of
   !> 2.5e-5 mm rises by 2.5–4.2 N a step now: every step within 8 N, and the call balances F_z.
   subroutine test_state_599(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: vehicle
      type(contact_result_type) :: result
      type(wheelset_state_type) :: state
      type(lib_error), allocatable :: lib
      real(wp) :: carried(0:12)
      character(len=80) :: text
      integer :: j

      state = flange_state(599)
      call vehicle%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) call set_preset(vehicle, 'vehicle', lib)
      do j = 0, 12
         if (.not. allocated(lib)) call vehicle%solve_kinematic(state, &
            contact_load_type(load_vertical_position, 0.5369_wp + 2.5e-5_wp*j), result, lib)
         if (.not. allocated(lib)) carried(j) = -result%track%fz
      end do
      if (.not. allocated(lib)) call vehicle%solve_kinematic(state, &
         contact_load_type(load_vertical_force, wheel_load), result, lib)
      if (allocated(lib)) then
         call test_failed(error, 'flange state 599, vehicle preset: '//lib%message); return
      end if
      write (text, '(a, f7.2, a)') 'largest step of C ', maxval(abs(carried(1:) - carried(:11))), ' N'
      call check(error, maxval(abs(carried(1:) - carried(:11))) <= 8.0_wp, &
         'C(dz) jumps at flange state 599', more=text)
      if (allocated(error)) return
      call check(error, abs(result%track%fz + wheel_load) <= 1.0e-5_wp*wheel_load, &
         'vertical balance at flange state 599')
   end subroutine test_state_599

   !> The vehicle preset on CONTACT's kinematic sample (external data; doc/validation.md §6, the
   !> 35 cases CONTACT solved): the targets of doc/validation.md for the kinematic call, max |Δf|
   !> ≤ 0.1 and P80 |Δf_y| ≤ 0.04 (f = F/(μF_n) of the most loaded patch, CONTACT's sign), and
   !> the normal force of that patch within 5 % (the default: 3.9 %, Table 9). The preset gave
   !> max |Δf_x| 0.049, P80 0.018, max |Δf_y| 0.022, P80 0.006, |ΔF_n|/F_n max 0.039 (the
   !> default's Table 9: 0.049, 0.018, 0.020, 0.006, 0.039).
   subroutine test_exact(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=12), parameter :: names(7) = [character(len=12) :: 'y_ws_mm', 'yaw_rad', &
         'vs_mm_s', 'vy_mm_s', 'vyaw_rad_s', 'vpitch_rad_s', 'fn_N']
      character(len=12), parameter :: forces(2) = [character(len=12) :: 'fx_norm', 'fs_norm']
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(track_type) :: track
      type(lib_error), allocatable :: lib
      real(wp), allocatable :: rows(:, :), f(:, :), ex(:), ey(:), en(:)
      character(len=:), allocatable :: sample, wheel, rail
      character(len=80) :: stats
      integer :: i, n

      call skip_without_profiles(error)
      if (allocated(error)) return
      sample = external_file('reference/kinematic_sample/kinematic_sample.csv', error)
      if (.not. allocated(error)) wheel = external_file('profiles/MBench_S1002_v3.prw', error)
      if (.not. allocated(error)) rail = external_file('profiles/MBench_UIC60_v3.prr', error)
      if (allocated(error)) return
      call read_columns(sample, names, rows, error, row_tag='ok')
      if (.not. allocated(error)) call read_columns(sample, forces, f, error, row_tag='ok')
      if (allocated(error)) return
      n = size(rows, 1)
      call check(error, n == 35, 'kinematic sample: 35 cases CONTACT solved')
      if (allocated(error)) return
      track%rail_canted = .true.
      call solver%init(wheel, rail, lib, track=track, material=material_type( &
         shear_modulus=82670.0_wp, poisson=0.27_wp, friction=mu))
      if (.not. allocated(lib)) call set_preset(solver, 'vehicle', lib)
      call check(error, .not. allocated(lib), 'init and preset')
      if (allocated(error)) return
      allocate (ex(n), ey(n), en(n))
      do i = 1, n
         associate (r => rows(i, :))
            call solver%solve_kinematic(wheelset_state_type(y_ws=r(1), yaw=r(2), &
               v_forward=r(3), v_lateral=r(4), yaw_rate=r(5), pitch_rate=r(6)), &
               contact_load_type(load_vertical_force, wheel_load), result, lib)
            call check(error, .not. allocated(lib), 'kinematic call')
            if (allocated(error)) return
            ! CONTACT's sign: rail side.
            ex(i) = abs(-result%main%fx_norm - f(i, 1))
            ey(i) = abs(-result%main%fy_norm - f(i, 2))
            en(i) = abs(result%main%fn - r(7))/r(7)
         end associate
      end do
      write (stats, '(a,4f8.4)') 'max |dfx|, P80 |dfx|, max |dfy|, P80 |dfy| =', maxval(ex), &
         percentile(ex, 0.8_wp), maxval(ey), percentile(ey, 0.8_wp)
      call check(error, max(maxval(ex), maxval(ey)) <= 0.1_wp, 'max |Delta f| > 0.1', more=stats)
      if (allocated(error)) return
      call check(error, percentile(ey, 0.8_wp) <= 0.04_wp, 'P80 |Delta f_y| > 0.04', more=stats)
      if (allocated(error)) return
      write (stats, '(a,2f8.4)') 'max, P80 |dF_n|/F_n =', maxval(en), percentile(en, 0.8_wp)
      call check(error, maxval(en) <= 0.05_wp, 'max |Delta F_n|/F_n > 0.05', more=stats)

   end subroutine test_exact

   !> f_x (c = 1) or f_y (c = 2): the loaded patches' tangential forces over μΣF_n.
   pure real(wp) function f_of(r, c) result(f)
      type(contact_result_type), intent(in) :: r
      integer, intent(in) :: c
      associate (p => r%patch(1:r%n_loaded))
         if (c == 1) then
            f = sum(p%fx)/(mu*sum(p%fn))
         else
            f = sum(p%fy)/(mu*sum(p%fn))
         end if
      end associate
   end function f_of

   !> The state and the difference, for a failure message.
   pure function state_text(state, df) result(text)
      type(wheelset_state_type), intent(in) :: state
      real(wp), intent(in) :: df
      character(len=96) :: text
      write (text, '(a,f8.4,a,f8.5,a,f8.5)') 't_y = ', state%y_ws, ' mm, yaw = ', state%yaw, &
         ' rad, |df| = ', df
   end function state_text

   !> The case of [[case_keys]] as case-file text (one line per group), with `&normal preset`
   !> when `preset` /= ''.
   function case_text(preset) result(text)
      character(len=*), intent(in) :: preset
      character(len=:), allocatable :: text
      character(len=:), allocatable :: group
      integer :: i, k
      text = ''
      do i = 1, size(case_keys)
         group = case_keys(i)(1:index(case_keys(i), '%') - 1)
         if (index(text, '&'//group//' ') > 0) cycle
         text = text//'&'//group
         do k = i, size(case_keys)
            if (index(case_keys(k), group//'%') /= 1) cycle
            text = text//' '//trim(case_keys(k)(len(group) + 2:))//' = '// &
               quoted(case_keys(k), case_values(k))
         end do
         text = text//' /'//new_line('a')
      end do
      if (len(preset) > 0) text = text//"&normal preset = '"//preset//"' /"
   end function case_text

   !> A choice value quoted, a number as it is.
   function quoted(key, value) result(text)
      character(len=*), intent(in) :: key, value
      character(len=:), allocatable :: text
      if (key == 'kinematics%mode' .or. key == 'output%fields') then
         text = "'"//trim(value)//"'"
      else
         text = trim(value)
      end if
   end function quoted

   !> The library's kinematic result of the case with `set_preset(solver, 'vehicle')` on a
   !> solver with the library's defaults, and its configuration (no preset) for state and load.
   subroutine library_vehicle(result, config, error)
      type(contact_result_type), intent(out) :: result
      type(case_config_type), intent(out) :: config
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(case_point_type) :: p
      type(lib_error), allocatable :: lib
      call read_config_text(case_text(''), 'case', config, lib)
      if (.not. allocated(lib)) call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) call set_preset(solver, 'vehicle', lib)
      if (.not. allocated(lib)) then
         p = config%case_point(1)
         call solver%solve_kinematic(config_state(p), config_load(config, p), result, lib)
      end if
      if (allocated(lib)) call test_failed(error, 'library with set_preset: '//lib%message)
   end subroutine library_vehicle

   !> The summary values compared bit for bit.
   pure function summary_values(s) result(v)
      type(case_summary_type), intent(in) :: s
      real(wp) :: v(10)
      v = [s%fn_total, s%fx_total, s%fy_total, s%fz_total, s%fn, s%fx, s%fy, s%mz, s%area, &
         s%p_max]
   end function summary_values

   !> The app's run of a case file with `&normal preset = 'vehicle'` (prepare_run,
   !> solve_kinematic_case) gives the forces of the library's `set_preset(solver, 'vehicle')` bit
   !> for bit, and differs from the same case without the preset (the option acts).
   subroutine test_namelist(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: lib_result
      type(case_config_type) :: config
      type(case_result_type) :: vehicle, default
      real(wp) :: expected(10)

      call library_vehicle(lib_result, config, error)
      if (allocated(error)) return
      expected = summary_values(case_summary(lib_result))
      call app_case('vehicle', vehicle, error)
      if (allocated(error)) return
      call app_case('', default, error)
      if (allocated(error)) return
      call check(error, bitwise_equal(summary_values(vehicle%summary), expected), &
         'the app with &normal preset differs from set_preset')
      if (allocated(error)) return
      call check(error, .not. bitwise_equal(summary_values(default%summary), expected), &
         'the preset changes nothing')
   end subroutine test_namelist

   !> One kinematic case of the app (status 0 expected).
   subroutine app_case(preset, result, error)
      character(len=*), intent(in) :: preset
      type(case_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(run_setup_type) :: setup
      type(contact_solver_type) :: solver
      type(lib_error), allocatable :: lib
      call read_config_text(case_text(preset), 'case', config, lib)
      if (.not. allocated(lib)) call prepare_run(config, setup, lib)
      if (allocated(lib)) then
         call test_failed(error, 'app, preset "'//preset//'": '//lib%message)
         return
      end if
      solver = setup%solver
      call solve_kinematic_case(setup, config%case_point(1), solver, result, .false.)
      call check(error, result%summary%stat, 0, 'app case, preset "'//preset//'"')
   end subroutine app_case

   !> The Fortran 77 keys (SHC_SET_OPTION 'normal%preset', the C API's keyed path beneath)
   !> give every value of the kinematic layout of `set_preset` bit for bit.
   subroutine test_keyed(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: lib_result
      type(case_config_type) :: config
      real(wp) :: expected(kinematic_value_count), got(kinematic_value_count)
      character(len=512) :: msg
      integer :: ih, istat, i, j

      call library_vehicle(lib_result, config, error)
      if (allocated(error)) return
      call kinematic_values(lib_result, expected)
      got = 0.0_wp
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      do i = 1, size(case_keys)
         if (istat == 0) call shc_set_option(ih, trim(case_keys(i)), trim(case_values(i)), istat)
      end do
      if (istat == 0) call shc_set_option(ih, 'normal%preset', 'vehicle', istat)
      if (istat == 0) call shc_solve_state(ih, istat)
      do i = 1, size(output_keys)
         if (istat == 0) call shc_get_value(ih, trim(output_keys(i)%name), 0, &
            got(output_keys(i)%index), istat)
      end do
      call shc_errmsg(ih, msg)
      call shc_destroy(ih, j)
      call check(error, istat == 0 .and. bitwise_equal(got, expected), &
         'SHC_SET_OPTION normal%preset differs from set_preset: '//trim(msg))
   end subroutine test_keyed

   !> An explicit `&normal n_strips` or `&tangential n_elements` wins over the preset, which
   !> still sets the rest: in a case file, and through the keys in either order; 'default'
   !> gives the library's defaults back.
   subroutine test_precedence(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config, a, b
      type(library_setup_type) :: sa, sb
      type(lib_error), allocatable :: lib

      call read_config_text("&normal preset = 'vehicle' n_strips = 80 /", 'case', config, lib)
      call check(error, .not. allocated(lib), 'case file')
      if (allocated(error)) return
      call check(error, grid_is(config, 80, 40, 0.05_wp) .and. config%normal%n_strips == 80 &
         .and. config%tangential%n_elements == 40, 'case file: n_strips 80 given, 40 elements '// &
         'and 0.05 mm tables of the preset')
      if (allocated(error)) return
      call read_config_text("&tangential n_elements = 30 /"//new_line('a')// &
         "&normal preset = 'vehicle' /", 'case', config, lib)
      call check(error, .not. allocated(lib), 'case file')
      if (allocated(error)) return
      call check(error, grid_is(config, 60, 30, 0.05_wp), 'n_elements 30 given')
      if (allocated(error)) return
      call set_config_value(a, 'normal%n_strips', '80', lib)
      if (.not. allocated(lib)) call set_config_value(a, 'normal%preset', 'vehicle', lib)
      if (.not. allocated(lib)) call set_config_value(b, 'normal%preset', 'Vehicle', lib)
      if (.not. allocated(lib)) call set_config_value(b, 'normal%n_strips', '80', lib)
      if (.not. allocated(lib)) call library_setup(a, sa, lib)
      if (.not. allocated(lib)) call library_setup(b, sb, lib)
      call check(error, .not. allocated(lib), 'keys')
      if (allocated(error)) return
      call check(error, sa%normal%n_strips == 80 .and. sb%normal%n_strips == 80 .and. &
         sa%tangential%n_elements == 40 .and. sb%tangential%n_elements == 40 .and. &
         sa%contact_options%table_step == 0.05_wp .and. &
         sb%contact_options%table_step == 0.05_wp, 'keys: the explicit n_strips wins in '// &
         'either order')
      if (allocated(error)) return
      call set_config_value(b, 'normal%preset', 'default', lib)
      call check(error, .not. allocated(lib), 'preset default')
      if (allocated(error)) return
      call check(error, grid_is(b, 80, 50, 0.025_wp), "keys: preset 'default' after 'vehicle'")
   end subroutine test_precedence

   !> The grid a configuration gives the library.
   logical function grid_is(config, n_strips, n_elements, step)
      type(case_config_type), intent(in) :: config
      integer, intent(in) :: n_strips, n_elements
      real(wp), intent(in) :: step
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      normal = normal_options_of(config)
      tangential = tangential_options_of(config)
      grid_is = normal%n_strips == n_strips .and. tangential%n_elements == n_elements .and. &
         table_step_of(config) == step
   end function grid_is

   !> An unknown preset, in a case file and as a key: status 2 and a message naming the option
   !> and the choices.
   subroutine test_unknown_option(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(lib_error), allocatable :: lib
      character(len=512) :: msg
      integer :: ih, istat, j

      call read_config_text("&normal preset = 'fast' /", 'case.nml', config, lib)
      call check(error, allocated(lib), 'an unknown preset is accepted')
      if (allocated(error)) return
      call check(error, lib%stat == stat_invalid_input .and. &
         index(lib%message, '&normal preset') > 0 &
         .and. index(lib%message, 'fast') > 0 .and. &
         index(lib%message, "'default', 'vehicle'") > 0, 'case file: '//lib%message)
      if (allocated(error)) return
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      if (istat == 0) call shc_set_option(ih, 'normal%preset', 'fast', istat)
      call shc_errmsg(ih, msg)
      call shc_destroy(ih, j)
      call check(error, istat == stat_invalid_input .and. &
         index(msg, 'normal%preset') > 0 .and. index(msg, "'default', 'vehicle'") > 0, &
         'F77 key: '//trim(msg))
   end subroutine test_unknown_option

end module test_preset
