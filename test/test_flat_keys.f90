!> Options, inputs and outputs by key through the flat interfaces (issue 26): every variable of
!> the namelist's variable table set from a case file (the app's reader), from C
!> (shcontact_set_option / shcontact_set_value) and from Fortran 77 (SHC_SET_OPTION) gives the
!> same result, bit for bit, and a different one from the defaults; the app's runner gives
!> the library's result with the handles' translation of the configuration; every value of the flat layouts has a name; unknown keys
!> and bad values are refused with a status and a message; the both-wheels call from C and
!> F77 is the Fortran wheelset's.
module test_flat_keys
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_ptr, c_loc, &
      c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_usage
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_api_solver, only: contact_solver_type, contact_result_type, contact_load_type
   use shcontact_api_values, only: kinematic_value_count, kinematic_values
   use shcontact_api_wheelset, only: wheelset_solver_type, wheelset_result_type, wheel_right, &
      wheel_left
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_input_config, only: case_config_type, case_point_type, read_config_text
   use shcontact_input_config_variables, only: variables, find_variable, k_string, k_choice, &
      k_real, k_int
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_case_runner, only: run_setup_type, prepare_run, stage_type, solve_geometry, &
      solve_stage, solve_case, solve_kinematic_case, case_workspace_type, tangential_patch_type
   use shcontact_case_result, only: case_result_type, case_summary_type, case_summary, &
      summary_value, summary_columns, n_summary_columns
   use shcontact_api_settings, only: library_setup_type, library_setup, config_load, &
      config_state, key_use, key_solver, key_state, key_creation, key_app
   use shcontact_api_keyed, only: output_keys, wheelset_keys, field_keys, output_key_type
   use shcontact_pipeline_result, only: wheel_columns
   use shcontact_api_capi, only: shcontact_create, shcontact_destroy, shcontact_set_option, &
      shcontact_set_value, shcontact_solve_state, shcontact_get_value, shcontact_last_error, &
      shcontact_create_wheelset, shcontact_solve_wheelset, shcontact_wheelset_wheel, &
      shcontact_field_size, shcontact_fields, shcontact_get_field, shcontact_solve, &
      shcontact_patch
   use test_flat_api, only: shc_create, shc_destroy, shc_set_option, shc_solve_state, &
      shc_solve_kin, shc_get_value, shc_errmsg, shc_set_value, shc_create_ws, shc_solve_ws, shc_ws_wheel, &
      shc_set_material, &
      to_chars, from_chars, bitwise_equal
   use test_external_data, only: external_file
   implicit none
   private
   public :: collect_flat_keys

   !> A value of every variable a handle takes (the last assignment; those before it make it
   !> count, e.g. the reduction 'constant' that epsilon needs). A variable of the table without
   !> a value here fails the test: add one when adding a variable.
   character(len=*), parameter :: samples(*) = [character(len=72) :: &
      'profiles%wheel_smoothing=0.5', 'profiles%rail_smoothing=0.5', &
      'track%gauge=1437', 'track%gauge_height=15', 'track%inclination=0.03', &
      'track%rail_canted=.true.', 'track%flange_back_distance=1362', &
      'track%flange_back_position=-69', 'kinematics%mode=on;track%nominal_radius=470', &
      'position%t_y=5.2', 'position%roll=0.001', 'kinematics%mode=on', &
      'kinematics%mode=on;kinematics%yaw=0.002', 'kinematics%mode=on;kinematics%v_forward=2e4', &
      'kinematics%mode=on;kinematics%v_lateral=100', &
      'kinematics%mode=on;kinematics%v_vertical=50', &
      'kinematics%mode=on;kinematics%roll_rate=0.1', &
      'kinematics%mode=on;kinematics%yaw_rate=0.1', &
      'kinematics%mode=on;kinematics%pitch_rate=-66', &
      'material%shear_modulus=80000', 'material%poisson=0.28', 'material%friction=0.25', &
      'load%mode=approach', 'load%normal_force=50000', 'load%mode=approach;load%approach=0.08', &
      'load%mode=vertical;load%vertical_force=60000', &
      'creepage%nu_x=1e-3', 'creepage%nu_y=1e-4', 'creepage%phi=1e-4', &
      'normal%method=hertz', 'normal%reduction=constant', &
      'normal%reduction=constant;normal%epsilon=0.4', 'normal%n_strips=60', 'normal%slide=exact', &
      'normal%b_min=0.05', 'normal%longitudinal_curvature=reference', 'normal%strip_tables=conformal', &
      'normal%method=hertz;tangential%method=fastsim', 'tangential%bound=ellipsoidal', &
      'tangential%spin_model=additive', 'tangential%spin_flexibility=spin', &
      'tangential%correction=none', 'tangential%n_elements=30', 'normal%preset=vehicle', &
      'tangential%contact_surface=interface']

   !> A kinematic state with two patches on the right wheel (flange root) for the wheelset call.
   type(wheelset_state_type), parameter :: ws_state = wheelset_state_type(y_ws=5.0_wp, &
      yaw=2.0e-3_wp, roll=0.0_wp, v_forward=30000.0_wp, v_lateral=10.0_wp, v_vertical=0.0_wp, &
      roll_rate=0.0_wp, yaw_rate=0.01_wp, pitch_rate=-30000.0_wp/460.0_wp)

contains

   subroutine collect_flat_keys(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('every_option_three_paths', test_every_option), &
         new_unittest('translation_is_the_apps', test_translation), &
         new_unittest('every_layout_value_named', test_output_names), &
         new_unittest('bad_keys_and_values', test_bad_keys), &
         new_unittest('wheelset_from_c_and_f77', test_wheelset), &
         new_unittest('wheelset_option_keeps_miniprof_origin', test_wheelset_miniprof), &
         new_unittest('vehicle_call_guards', test_vehicle_call_guards), &
         new_unittest('field_by_name', test_field_by_name), &
         new_unittest('kinematic_call_refuses_spin_model', test_kinematic_spin_model), &
         new_unittest('doc_lists_every_key', test_doc_keys) &
         ]
   end subroutine collect_flat_keys

   ! ------------------------------------------------------------------------------------------
   ! Helpers
   ! ------------------------------------------------------------------------------------------

   !> The assignments of a sample, 'g%n=v;g%n=v'.
   subroutine split_sample(sample, items)
      character(len=*), intent(in) :: sample
      character(len=72), allocatable, intent(out) :: items(:)
      character(len=:), allocatable :: rest
      integer :: i
      allocate (items(0))
      rest = trim(sample)
      do
         i = index(rest, ';')
         if (i == 0) exit
         items = [character(len=72) :: items, rest(1:i - 1)]
         rest = rest(i + 1:)
      end do
      items = [character(len=72) :: items, rest]
   end subroutine split_sample

   !> Key and value of 'g%n=v'.
   subroutine key_value(item, key, value)
      character(len=*), intent(in) :: item
      character(len=:), allocatable, intent(out) :: key, value
      key = trim(item(1:index(item, '=') - 1))
      value = trim(item(index(item, '=') + 1:))
   end subroutine key_value

   !> The sample as case-file text: one `&group name = value /` line per assignment (strings
   !> quoted).
   function namelist_text(items) result(text)
      character(len=*), intent(in) :: items(:)
      character(len=:), allocatable :: text, key, value, group, last
      integer :: i, p, iv
      text = ''
      last = ''
      do i = 1, size(items)
         call key_value(items(i), key, value)
         p = index(key, '%')
         group = key(1:p - 1)
         iv = find_variable(group, key(p + 1:))
         if (any(variables(iv)%kind == [k_string, k_choice])) value = "'"//value//"'"
         ! A group appears once in a case file: its variables on one line.
         if (group == last) then
            text = text(1:len(text) - 3)//' '//key(p + 1:)//' = '//value//' /'//new_line('a')
         else
            text = text//'&'//group//' '//key(p + 1:)//' = '//value//' /'//new_line('a')
         end if
         last = group
      end do
   end function namelist_text

   !> The result of a configuration through the Fortran API: the objects of library_setup, the
   !> state, load and creepages of the configuration, in the kinematic layout.
   subroutine reference(config, values, error)
      type(case_config_type), intent(in) :: config
      real(wp), intent(out) :: values(kinematic_value_count)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: result
      call library_result(config, result, error)
      if (allocated(error)) return
      call kinematic_values(result, values)
   end subroutine reference

   !> The solver object's result of a configuration's first case: the objects of library_setup,
   !> the state, load and creepages of the configuration.
   subroutine library_result(config, result, error)
      type(case_config_type), intent(in) :: config
      type(contact_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(library_setup_type) :: setup
      type(contact_solver_type) :: solver
      type(case_point_type) :: p
      type(lib_error), allocatable :: err
      call library_setup(config, setup, err)
      if (.not. allocated(err)) call solver%init(trim(config%profiles%wheel), &
         trim(config%profiles%rail), err, track=setup%track, material=setup%material, &
         side=setup%side, contact_options=setup%contact_options, normal_options=setup%normal, &
         tangential_options=setup%tangential)
      p = config%case_point(1)
      if (.not. allocated(err)) then
         if (config%is_kinematic()) then
            call solver%solve_kinematic(config_state(p), config_load(config, p), result, err)
         else
            call solver%solve(p%t_y, p%roll, config_load(config, p), &
               creepage_type(p%nu_x, p%nu_y, p%phi), result, err)
         end if
      end if
      if (allocated(err)) call test_failed(error, 'reference solve: '//err%message)
   end subroutine library_result

   !> The program's result of a configuration's first case: its runner (prepare_run, then the
   !> stages of a prescribed case or the solver copy of a kinematic one), as a sweep solves it.
   subroutine app_result(config, result, error)
      type(case_config_type), intent(in) :: config
      type(case_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(run_setup_type) :: setup
      type(case_point_type) :: p
      type(patch_geometry_type), allocatable :: geometry(:)
      type(stage_type) :: stage
      type(case_workspace_type) :: ws
      type(tangential_patch_type), allocatable :: tangential(:)
      type(contact_solver_type) :: solver
      type(lib_error), allocatable :: err
      call prepare_run(config, setup, err)
      p = config%case_point(1)
      if (.not. allocated(err)) then
         if (setup%kinematic) then
            solver = setup%solver
            call solve_kinematic_case(setup, p, solver, result, .false.)
         else
            call solve_geometry(setup, p, geometry, err)
            if (.not. allocated(err)) then
               call solve_stage(setup, p, geometry, stage)
               call solve_case(setup, p, stage, 1, ws, tangential, result, .false.)
            end if
         end if
      end if
      if (allocated(err)) then
         call test_failed(error, 'app runner: '//err%message)
      else if (result%summary%stat /= 0) then
         call test_failed(error, 'app runner: '//result%message)
      end if
   end subroutine app_result

   !> shcontact_set_option from Fortran text.
   integer function c_set_option(handle, key, value) result(stat)
      type(c_ptr), intent(in) :: handle
      character(len=*), intent(in) :: key, value
      character(kind=c_char), allocatable, target :: k(:), v(:)
      k = to_chars(key, len(key) + 1)
      v = to_chars(value, len(value) + 1)
      stat = shcontact_set_option(handle, c_loc(k), c_loc(v))
   end function c_set_option

   !> shcontact_set_value from Fortran text.
   integer function c_set_value(handle, key, x) result(stat)
      type(c_ptr), intent(in) :: handle
      character(len=*), intent(in) :: key
      real(wp), intent(in) :: x
      character(kind=c_char), allocatable, target :: k(:)
      k = to_chars(key, len(key) + 1)
      stat = shcontact_set_value(handle, c_loc(k), real(x, c_double))
   end function c_set_value

   !> shcontact_get_value from Fortran text.
   integer function c_get_value(handle, key, patch, x) result(stat)
      type(c_ptr), intent(in) :: handle
      character(len=*), intent(in) :: key
      integer, intent(in) :: patch
      real(wp), intent(out) :: x
      character(kind=c_char), allocatable, target :: k(:)
      real(c_double), target :: out
      k = to_chars(key, len(key) + 1)
      stat = shcontact_get_value(handle, c_loc(k), int(patch, c_int), c_loc(out))
      x = out
   end function c_get_value

   !> The message of a C handle's last call.
   function c_message(handle) result(text)
      type(c_ptr), intent(in) :: handle
      character(len=:), allocatable :: text
      character(kind=c_char), target :: buffer(1024)
      integer(c_int) :: stat
      stat = shcontact_last_error(handle, c_loc(buffer), size(buffer, kind=c_int))
      text = from_chars(buffer)
   end function c_message

   !> A new C contact of the built-in profiles (right wheel).
   subroutine c_create(handle, error)
      type(c_ptr), intent(out) :: handle
      type(error_type), allocatable, intent(out) :: error
      character(kind=c_char), target :: wheel(14), rail(14)
      type(c_ptr), target :: h
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      call check(error, shcontact_create(c_loc(h), c_loc(wheel), c_loc(rail), 1_c_int), &
         0_c_int, message='shcontact_create')
      handle = h
   end subroutine c_create

   !> Same list-directed text: equality of objects without allocatable parts (no padding).
   logical function same_text(a, b)
      character(len=*), intent(in) :: a, b
      same_text = a == b
   end function same_text

   ! ------------------------------------------------------------------------------------------
   ! Tests
   ! ------------------------------------------------------------------------------------------

   !> Every variable a handle takes: the case file, C and F77 give the same 29 values of the
   !> kinematic layout, bit for bit, and not those of the defaults. C sets the last assignment
   !> of a number with shcontact_set_value, F77 everything with SHC_SET_OPTION (text). The
   !> variables a handle does not take (profile files, side, output file, sweep) are refused by
   !> both with status 2 and a message that names them.
   subroutine test_every_option(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(lib_error), allocatable :: err
      real(wp) :: ref0(kinematic_value_count), ref(kinematic_value_count)
      real(wp) :: c_vals(kinematic_value_count), f_vals(kinematic_value_count), x
      character(len=72), allocatable :: items(:)
      character(len=:), allocatable :: key, value, name
      character(len=512) :: msg
      type(c_ptr) :: handle
      integer :: iv, is, i, j, ih, istat, use, n_done

      call read_config_text('', 'defaults', config, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call reference(config, ref0, error)
      if (allocated(error)) return
      n_done = 0
      do iv = 1, size(variables)
         if (variables(iv)%group == 'sweep') cycle
         name = trim(variables(iv)%group)//'%'//trim(variables(iv)%name)
         use = key_use(trim(variables(iv)%group), trim(variables(iv)%name))
         if (use == key_creation .or. use == key_app) then
            call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
            call shc_set_option(ih, name, 'x', istat)
            call shc_errmsg(ih, msg)
            call shc_destroy(ih, j)
            call check(error, istat == stat_invalid_input .and. index(msg, name) > 0, &
               message=name//' (not a handle option) from F77: status and message: '//trim(msg))
            if (allocated(error)) return
            cycle
         end if
         if (use /= key_solver .and. use /= key_state) cycle
         is = 0
         do i = 1, size(samples)
            if (index(samples(i), name//'=') > 0 .and. index(samples(i)(index(samples(i), &
                name//'=') + len(name) + 1:), ';') == 0) is = i
         end do
         if (is == 0) then
            call test_failed(error, 'no sample value of '//name//' in test_flat_keys: add one')
            return
         end if
         call split_sample(samples(is), items)
         ! The case file.
         call read_config_text(namelist_text(items), 'sample', config, err)
         if (allocated(err)) then
            call test_failed(error, trim(samples(is))//': '//err%message)
            return
         end if
         call reference(config, ref, error)
         if (allocated(error)) return
         call check(error, .not. bitwise_equal(ref, ref0), message=trim(samples(is))// &
            ': the same result as the defaults (the sample must change it)')
         if (allocated(error)) return
         ! C.
         call c_create(handle, error)
         if (allocated(error)) return
         do i = 1, size(items)
            call key_value(items(i), key, value)
            j = find_variable(key(1:index(key, '%') - 1), key(index(key, '%') + 1:))
            if (i == size(items) .and. (variables(j)%kind == k_real .or. &
                variables(j)%kind == k_int)) then
               read (value, *) x
               istat = c_set_value(handle, key, x)
            else
               istat = c_set_option(handle, key, value)
            end if
            if (istat /= 0) exit
         end do
         if (istat == 0) istat = shcontact_solve_state(handle)
         do i = 1, size(output_keys)
            if (istat == 0) istat = c_get_value(handle, trim(output_keys(i)%name), 0, &
               c_vals(output_keys(i)%index))
         end do
         msg = c_message(handle)
         istat = istat + shcontact_destroy(handle)
         call check(error, istat == 0 .and. bitwise_equal(c_vals, ref), &
            message=trim(samples(is))//': C differs from the case file; '//trim(msg))
         if (allocated(error)) return
         ! Fortran 77.
         call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
         do i = 1, size(items)
            call key_value(items(i), key, value)
            if (istat == 0) call shc_set_option(ih, key, value, istat)
         end do
         if (istat == 0) call shc_solve_state(ih, istat)
         do i = 1, size(output_keys)
            if (istat == 0) call shc_get_value(ih, trim(output_keys(i)%name), 0, &
               f_vals(output_keys(i)%index), istat)
         end do
         call shc_errmsg(ih, msg)
         call shc_destroy(ih, j)
         call check(error, istat == 0 .and. bitwise_equal(f_vals, ref), &
            message=trim(samples(is))//': F77 differs from the case file; '//trim(msg))
         if (allocated(error)) return
         n_done = n_done + 1
      end do
      call check(error, n_done >= 40, message='fewer handle options than expected')
   end subroutine test_every_option

   !> The program's runner (prepare_run, which translates the configuration with the handles'
   !> library_setup) and the library's solver object given library_setup's objects give the
   !> same summary, bit for bit in every column, for the defaults and every sample of the
   !> solver's data and of a case's state: the translation and the load and state of a case
   !> are the handles' (whose results the flat interfaces' test compares with C and F77).
   subroutine test_translation(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(lib_error), allocatable :: err
      type(contact_result_type) :: lib
      type(case_result_type) :: app
      type(case_summary_type) :: expected
      character(len=72), allocatable :: items(:)
      integer :: is, k, n_done
      character(len=:), allocatable :: key, value

      n_done = 0
      do is = 0, size(samples)
         if (is == 0) then
            allocate (items(0))
         else
            call split_sample(samples(is), items)
            call key_value(items(size(items)), key, value)
            select case (key_use(key(1:index(key, '%') - 1), key(index(key, '%') + 1:)))
            case (key_solver, key_state)
            case default
               cycle
            end select
         end if
         call read_config_text(namelist_text(items), 'sample', config, err)
         if (allocated(err)) then
            call test_failed(error, 'sample '//namelist_text(items)//': '//err%message)
            return
         end if
         call library_result(config, lib, error)
         if (.not. allocated(error)) call app_result(config, app, error)
         if (allocated(error)) then
            error%message = namelist_text(items)//': '//error%message
            return
         end if
         expected = case_summary(lib)
         call check(error, app%summary%n_patches == expected%n_patches .and. &
            app%summary%n_loaded == expected%n_loaded .and. &
            app%summary%main_patch == expected%main_patch, message='the app runner finds '// &
            'other patches than the library for '//namelist_text(items))
         if (allocated(error)) return
         do k = 1, n_summary_columns
            call check(error, bitwise_equal([summary_value(app%summary, k)], &
               [summary_value(expected, k)]), message='the app runner and the library '// &
               'differ in '//trim(summary_columns(1, k))//' for '//namelist_text(items))
            if (allocated(error)) return
         end do
         n_done = n_done + 1
         deallocate (items)
      end do
      call check(error, n_done >= 35, message='fewer samples than expected')
   end subroutine test_translation

   !> Every value of the kinematic layout (which holds the patch and result layouts) has exactly
   !> one name.
   subroutine test_output_names(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      do i = 1, kinematic_value_count
         call check(error, count(output_keys%index == i), 1, &
            message='layout value without exactly one name')
         if (allocated(error)) return
      end do
      call check(error, size(output_keys), kinematic_value_count)
   end subroutine test_output_names

   !> Unknown keys and bad values: status 2 (1 for a call in the wrong state) and a message
   !> naming what is wrong, from C and F77; nothing sticks (the result after them is that of
   !> the defaults).
   subroutine test_bad_keys(error)
      type(error_type), allocatable, intent(out) :: error
      type(c_ptr) :: handle
      character(len=512) :: msg
      real(wp) :: x, fx0, fx1
      integer :: ih, istat

      call c_create(handle, error)
      if (allocated(error)) return
      call check(error, c_set_option(handle, 'tangential%colour', 'red'), stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'tangential%bound') > 0, &
         message='unknown key without the list of keys: '//c_message(handle))
      if (allocated(error)) return
      call check(error, c_set_option(handle, 'normal%n_strips', 'many'), stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'integer') > 0 .and. &
         index(c_message(handle), 'normal%n_strips') > 0, message='bad integer: '// &
         c_message(handle))
      if (allocated(error)) return
      call check(error, c_set_option(handle, 'tangential%bound', 'square'), stat_invalid_input, &
         message='bound square')
      if (allocated(error)) return
      call check(error, c_set_option(handle, 'normal%longitudinal_curvature', 'global'), &
         stat_invalid_input, message='curvature global')
      if (allocated(error)) return
      call check(error, c_set_option(handle, 'sweep%t_y', '1, 2'), stat_invalid_input, &
         message='sweep')
      if (allocated(error)) return
      call check(error, c_set_option(handle, 'profiles%wheel', 'builtin:S1002'), &
         stat_invalid_input, message='profiles%wheel')
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'created') > 0, message=c_message(handle))
      if (allocated(error)) return
      call check(error, c_set_value(handle, 'normal%method', 1.0_wp), stat_invalid_input, &
         message='text by number')
      if (allocated(error)) return
      call check(error, c_set_value(handle, 'method', 1.0_wp), stat_invalid_input, &
         message='ambiguous')
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'several groups') > 0, &
         message=c_message(handle))
      if (allocated(error)) return
      call check(error, c_set_value(handle, 'n_strips', 60.5_wp), stat_invalid_input, &
         message='60.5 strips')
      if (allocated(error)) return
      ! A whole number beyond the int range is out of range, not "not a whole number".
      call check(error, c_set_value(handle, 'n_strips', 1.0e30_wp), stat_invalid_input, &
         message='1e30 strips')
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'is out of range; expected') > 0, &
         message=c_message(handle))
      if (allocated(error)) return
      call check(error, c_set_value(handle, 'position%t_y', ieee_value(x, ieee_quiet_nan)), &
         stat_invalid_input, message='t_y = NaN')
      if (allocated(error)) return
      call check(error, c_get_value(handle, 'fx', 0, x), stat_usage, message='before a solve')
      if (allocated(error)) return
      ! A mistyped output key is unknown whether or not a solve has succeeded (it was "no result
      ! yet" before one).
      call check(error, c_get_value(handle, 'sum_fyy', 0, x), stat_invalid_input, &
         message='unknown key before a solve')
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'unknown; expected one of') > 0, &
         message='unknown key before a solve: '//c_message(handle))
      if (allocated(error)) return
      ! The pitch rate not given reads back as the pure rolling the solve takes (−V/R₀), not 0.
      call check(error, c_get_value(handle, 'kinematics%pitch_rate', 0, x), 0)
      if (allocated(error)) return
      call check(error, x, -30000.0_wp/460.0_wp, rel=.true., thr=1.0e-12_wp, &
         message='kinematics%pitch_rate of a fresh handle')
      if (allocated(error)) return
      call check(error, c_set_value(handle, 'kinematics%pitch_rate', -60.0_wp), 0)
      if (allocated(error)) return
      call check(error, c_get_value(handle, 'kinematics%pitch_rate', 0, x) == 0 .and. &
         x == -60.0_wp, message='kinematics%pitch_rate set to -60')
      if (allocated(error)) return
      ! The app's range of t_y (±30 mm) at the keyed solve.
      call check(error, c_set_value(handle, 't_y', 40.0_wp), 0)
      if (allocated(error)) return
      call check(error, shcontact_solve_state(handle), stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(c_message(handle), 'position%t_y') > 0 .and. &
         index(c_message(handle), 'command line') == 0, message=c_message(handle))
      if (allocated(error)) return
      call check(error, c_set_value(handle, 't_y', 4.733_wp), 0)
      if (allocated(error)) return
      call check(error, shcontact_solve_state(handle), 0, message=c_message(handle))
      if (allocated(error)) return
      call check(error, c_get_value(handle, 'colour', 0, x), stat_invalid_input)
      if (allocated(error)) return
      call check(error, c_get_value(handle, 'fx', 9, x), stat_usage)
      if (allocated(error)) return
      call check(error, c_get_value(handle, 'fx', 0, fx0), 0)
      if (allocated(error)) return
      call check(error, shcontact_destroy(handle), 0)
      if (allocated(error)) return
      ! F77: the same refusals; the defaults' result after them.
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_set_option(ih, 'normal%colour', '1', istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, 'normal%colour') > 0, &
         message='F77 unknown key: '//trim(msg))
      if (allocated(error)) return
      call shc_set_option(ih, 'material%friction', 'nan', istat)
      call check(error, istat, stat_invalid_input, message='friction = nan')
      if (allocated(error)) return
      call shc_set_value(ih, 'output%file', 1.0d0, istat)
      call check(error, istat, stat_invalid_input, message='output%file by number')
      if (allocated(error)) return
      call shc_set_option(ih, 'output%file', 'a.h5', istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_invalid_input .and. index(msg, "app") > 0, &
         message='output%file: '//trim(msg))
      if (allocated(error)) return
      call shc_solve_state(ih, istat)
      if (istat == 0) call shc_get_value(ih, 'FX', 0, fx1, istat)
      call shc_destroy(ih, ih)
      call check(error, istat == 0 .and. bitwise_equal([fx1], [fx0]), &
         message='a refused setting stuck, or C and F77 differ')
   end subroutine test_bad_keys

   !> The wheelset handle from C and F77 gives the Fortran wheelset's totals and wheels, bit for
   !> bit, also after an option set by key (applied to both wheels), and keyed outputs
   !> (wheelset%fy, left%fn) match them; one-wheel calls on it are refused (status 1).
   subroutine test_wheelset(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_result_type) :: expected
      type(lib_error), allocatable :: err
      type(library_setup_type) :: setup
      type(case_config_type) :: config
      character(kind=c_char), target :: wheel(14), rail(14)
      type(c_ptr), target :: h
      real(c_double) :: totals(4), cw(kinematic_value_count, 2)
      integer(c_int), target :: nx, ny
      real(wp) :: ft(4), fw(kinematic_value_count, 2), ref(kinematic_value_count, 2), x, y, &
         again(4)
      integer :: ih, istat, k, bad, bad_gauge
      integer(c_int) :: stat

      call read_config_text("&tangential bound = 'ellipsoidal' /", 'ws', config, err)
      if (.not. allocated(err)) call library_setup(config, setup, err)
      if (allocated(err)) then
         call test_failed(error, 'configuration: '//err%message)
         return
      end if
      call fortran_wheelset('builtin:S1002', expected, error, setup%tangential)
      if (allocated(error)) return
      call check(error, expected%wheel(wheel_right)%n_loaded, 2, message='two right patches')
      if (allocated(error)) return
      do k = 1, 2
         call kinematic_values(expected%wheel(k), ref(:, k))
      end do
      ! C.
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      stat = shcontact_create_wheelset(c_loc(h), c_loc(wheel), c_loc(rail))
      if (stat == 0) stat = c_set_option(h, 'tangential%bound', 'ellipsoidal')
      if (stat == 0) stat = shcontact_solve_wheelset(h, ws_state%y_ws, ws_state%yaw, &
         ws_state%roll, ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, &
         ws_state%roll_rate, ws_state%yaw_rate, ws_state%pitch_rate, 2_c_int, 64.7e3_c_double, &
         60.0e3_c_double, totals)
      if (stat == 0) stat = shcontact_wheelset_wheel(h, 1_c_int, 0_c_int, cw(:, 1))
      if (stat == 0) stat = shcontact_wheelset_wheel(h, -1_c_int, 0_c_int, cw(:, 2))
      call check(error, stat == 0 .and. bitwise_equal(totals, [expected%fx, expected%fy, &
         expected%fz, expected%mz]) .and. bitwise_equal(reshape(cw, [size(cw)]), &
         reshape(ref, [size(ref)])), message='C wheelset differs: '//c_message(h))
      if (allocated(error)) return
      call check(error, c_get_value(h, 'wheelset%fy', 0, x), 0)
      if (allocated(error)) return
      call check(error, bitwise_equal([x], [expected%fy]), message='wheelset%fy')
      if (allocated(error)) return
      ! A total has no patch: patch 1 is refused (it returned the total, status 0).
      call check(error, c_get_value(h, 'wheelset%fy', 1, x), 1, message=c_message(h))
      if (allocated(error)) return
      call check(error, c_get_value(h, 'right%fn', 2, x), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, bitwise_equal([x], [expected%wheel(wheel_right)%patch(2)%fn]), &
         message='right%fn of patch 2')
      if (allocated(error)) return
      ! The wheel's joined contact by name (doc/lobes.md), patch 0 only.
      call check(error, c_get_value(h, 'right%wheel_fx_norm', 0, x), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, bitwise_equal([x], [expected%wheel(wheel_right)%wheel%fx_norm]) .and. &
         x /= 0.0_wp, message='right%wheel_fx_norm')
      if (allocated(error)) return
      call check(error, c_get_value(h, 'right%wheel_fn', 1, x), stat_usage, &
         message='right%wheel_fn of patch 1 should be refused')
      if (allocated(error)) return
      stat = shcontact_solve(h, 4.733_c_double, 0.0_c_double, 1_c_int, 64.7e3_c_double, &
         0.0_c_double, 0.0_c_double, 0.0_c_double, cw(1:25, 1))
      call check(error, stat == 1 .and. index(c_message(h), 'wheelset handle') > 0, &
         message='a one-wheel call on a wheelset handle: '//c_message(h))
      if (allocated(error)) return
      ! The one-wheel patch and field calls say so too (they said "expected 1 to 0").
      stat = shcontact_patch(h, 1_c_int, cw(1:17, 1))
      call check(error, stat == 1 .and. index(c_message(h), 'wheelset handle') > 0, &
         message='shcontact_patch on a wheelset handle: '//c_message(h))
      if (allocated(error)) return
      stat = shcontact_field_size(h, 1_c_int, c_loc(nx), c_loc(ny))
      call check(error, stat == 1 .and. index(c_message(h), 'wheelset handle') > 0, &
         message='shcontact_field_size on a wheelset handle: '//c_message(h))
      if (allocated(error)) return
      ! Fields asked of a wheelset handle are refused (they were kept and never readable);
      ! 'none' is accepted.
      call check(error, c_set_option(h, 'output%fields', 'all'), 1, message=c_message(h))
      if (allocated(error)) return
      call check(error, index(c_message(h), 'a wheelset handle returns no element fields') > 0, &
         message='fields on a wheelset handle: '//c_message(h))
      if (allocated(error)) return
      call check(error, c_set_option(h, 'output%fields', 'none'), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, c_set_option(h, 'track%side', 'left'), stat_invalid_input)
      if (allocated(error)) return
      ! A lifted left wheel (vertical force 0): no contact there, zeros, the right wheel as
      ! before, the totals its own (was status 2 and nothing for either wheel).
      stat = shcontact_solve_wheelset(h, ws_state%y_ws, ws_state%yaw, &
         ws_state%roll, ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, &
         ws_state%roll_rate, ws_state%yaw_rate, ws_state%pitch_rate, 2_c_int, 64.7e3_c_double, &
         0.0_c_double, totals)
      if (stat == 0) stat = shcontact_wheelset_wheel(h, 1_c_int, 0_c_int, cw(:, 1))
      if (stat == 0) stat = shcontact_wheelset_wheel(h, -1_c_int, 0_c_int, cw(:, 2))
      call check(error, stat == 0 .and. all(cw(:, 2) == 0.0_c_double) .and. &
         bitwise_equal(cw(:, 1), ref(:, 1)) .and. bitwise_equal(totals(1:3), &
         [expected%wheel(wheel_right)%track%fx, expected%wheel(wheel_right)%track%fy, &
         expected%wheel(wheel_right)%track%fz]), message='a lifted left wheel: '//c_message(h))
      if (allocated(error)) return
      ! Unloading through 0: 0.5 N, below the 1 N the contact is solved for, is lifted too
      ! (it failed both wheels with status 2).
      stat = shcontact_solve_wheelset(h, ws_state%y_ws, ws_state%yaw, &
         ws_state%roll, ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, &
         ws_state%roll_rate, ws_state%yaw_rate, ws_state%pitch_rate, 2_c_int, 64.7e3_c_double, &
         0.5_c_double, totals)
      if (stat == 0) stat = shcontact_wheelset_wheel(h, -1_c_int, 0_c_int, cw(:, 2))
      call check(error, stat == 0 .and. all(cw(:, 2) == 0.0_c_double), &
         message='a left wheel at 0.5 N: '//c_message(h))
      if (allocated(error)) return
      ! An option by its variable alone where one group has it, as shcontact_set_value takes
      ! it ('friction' was refused as unknown by set_option only).
      call check(error, c_set_option(h, 'friction', '0.25'), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, c_get_value(h, 'material%friction', 0, x), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, x == 0.25_c_double, message='friction by its bare name')
      if (allocated(error)) return
      call check(error, c_set_option(h, 'friction', '0.3'), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, c_set_option(h, 'frictio', '0.3'), 2, message=c_message(h))
      if (allocated(error)) return
      call check(error, index(c_message(h), "option 'frictio': unknown key") > 0, &
         message='an unknown bare option: '//c_message(h))
      if (allocated(error)) return
      ! The pitch rate set, then back to its default by the name the option list gives it.
      call check(error, c_set_option(h, 'kinematics%pitch_rate', '-1'), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, c_set_option(h, 'kinematics%pitch_rate', 'pure rolling'), 0, &
         message=c_message(h))
      if (allocated(error)) return
      call check(error, c_get_value(h, 'kinematics%pitch_rate', 0, x), 0, message=c_message(h))
      if (allocated(error)) return
      call check(error, x, -30000.0_wp/460.0_wp, thr=1.0e-12_wp, message='pitch rate reset')
      if (allocated(error)) return
      call check(error, shcontact_destroy(h), 0_c_int)
      if (allocated(error)) return
      ! F77.
      call shc_create_ws(ih, 'builtin:S1002', 'builtin:UIC60', istat)
      if (istat == 0) call shc_set_option(ih, 'tangential%bound', 'ellipsoidal', istat)
      if (istat == 0) call shc_solve_ws(ih, ws_state%y_ws, ws_state%yaw, ws_state%roll, &
         ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, ws_state%roll_rate, &
         ws_state%yaw_rate, ws_state%pitch_rate, 2, 64.7d3, 60.0d3, ft, istat)
      if (istat == 0) call shc_ws_wheel(ih, 1, 0, fw(:, 1), istat)
      if (istat == 0) call shc_ws_wheel(ih, -1, 0, fw(:, 2), istat)
      if (istat == 0) call shc_get_value(ih, 'left%fn', 0, x, istat)
      if (istat == 0) call shc_get_value(ih, 'left%wheel_fy_norm', 0, y, istat)
      ! A refused value leaves the wheelset handle as it was: the same solve, the same totals.
      if (istat == 0) then
         call shc_set_option(ih, 'material%friction', '-1', bad)
         call shc_set_option(ih, 'track%gauge', '99999', bad_gauge)
         call shc_solve_ws(ih, ws_state%y_ws, ws_state%yaw, ws_state%roll, &
            ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, ws_state%roll_rate, &
            ws_state%yaw_rate, ws_state%pitch_rate, 2, 64.7d3, 60.0d3, again, istat)
      end if
      call shc_destroy(ih, k)
      call check(error, istat == 0 .and. bad == stat_invalid_input .and. &
         bad_gauge == stat_invalid_input .and. bitwise_equal(again, ft), &
         message='a refused value changed or disabled the wheelset handle')
      if (allocated(error)) return
      call check(error, istat == 0 .and. bitwise_equal(ft, [expected%fx, expected%fy, &
         expected%fz, expected%mz]) .and. bitwise_equal(reshape(fw, [size(fw)]), &
         reshape(ref, [size(ref)])) .and. bitwise_equal([x], [expected%wheel(wheel_left)%main%fn]) &
         .and. bitwise_equal([y], [expected%wheel(wheel_left)%wheel%fy_norm]) .and. &
         y /= 0.0_wp, message='F77 wheelset differs')
   end subroutine test_wheelset

   !> An option set on a wheelset handle creates both wheels again from the handle's
   !> configuration: with a MiniProf wheel (origin at its flange back, so flange_back_position
   !> 0 when no track is given) that configuration must keep the wheels' track. Setting the
   !> smoothing to its default value leaves every force of the F77 wheelset call bitwise the
   !> same, and equal to the Fortran wheelset's (before the fix the wheels were re-created with
   !> the default −70 mm and the centred rolling radius moved from 459.8 to 479.1 mm). Skipped
   !> without the external data (its measured MiniProf wheel on the built-in UIC60).
   subroutine test_wheelset_miniprof(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_result_type) :: expected
      character(len=:), allocatable :: whl
      real(wp) :: before(4), after(4), position, builtin_position
      integer :: ih, istat, k

      whl = external_file('profiles/Car7216_0001r.whl', error)
      if (allocated(error)) return
      call fortran_wheelset(whl, expected, error)
      if (allocated(error)) return
      call shc_create_ws(ih, 'builtin:S1002', 'builtin:UIC60', istat)
      if (istat == 0) call shc_get_value(ih, 'track%flange_back_position', 0, builtin_position, &
         istat)
      call shc_destroy(ih, k)
      call shc_create_ws(ih, whl, 'builtin:UIC60', istat)
      if (istat == 0) call solve_ws(before)
      if (istat == 0) call shc_set_option(ih, 'profiles%wheel_smoothing', '0', istat)
      if (istat == 0) call solve_ws(after)
      if (istat == 0) call shc_get_value(ih, 'track%flange_back_position', 0, position, istat)
      call shc_destroy(ih, k)
      call check(error, istat, 0, message='F77 wheelset with a MiniProf wheel failed')
      if (allocated(error)) return
      ! The input read back by key: the wheel's resolved flange-back position.
      call check(error, position == 0.0_wp .and. builtin_position == -70.0_wp, &
         message='track%flange_back_position read back: not 0 (MiniProf) and -70 (S1002)')
      if (allocated(error)) return
      call check(error, bitwise_equal(before, [expected%fx, expected%fy, expected%fz, &
         expected%mz]), message='F77 wheelset differs from the Fortran wheelset')
      if (allocated(error)) return
      call check(error, bitwise_equal(after, before), message='an option set to its default '// &
         'value moved the MiniProf wheel (its flange back origin lost)')
   contains
      subroutine solve_ws(totals)
         real(wp), intent(out) :: totals(4)
         call solve_ws_state(ih, totals, istat)
      end subroutine solve_ws
   end subroutine test_wheelset_miniprof

   !> SHC_SOLVE_WS at ws_state, 64.7 kN on the right wheel and 60 kN on the left.
   subroutine solve_ws_state(handle, totals, istat)
      integer, intent(in) :: handle
      real(wp), intent(out) :: totals(4)
      integer, intent(out) :: istat
      call shc_solve_ws(handle, ws_state%y_ws, ws_state%yaw, ws_state%roll, &
         ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, ws_state%roll_rate, &
         ws_state%yaw_rate, ws_state%pitch_rate, 2, 64.7d3, 60.0d3, totals, istat)
   end subroutine solve_ws_state

   !> What a vehicle code meets in its time loop (issue 25's users): (1) the friction, an
   !> option or the track set on a wheelset handle do not read the profile files again (they
   !> did: a file moved away after the handle was made gave status 3, a file rewritten would
   !> have been taken silently, and the friction cost milliseconds) and give the forces of a
   !> handle made with them; (2) a
   !> NULL result array gives status 1, not a crash; (3) a lateral shift beyond the case
   !> file's range (a derailed wheelset) is refused by the positional calls as by the app.
   subroutine test_vehicle_call_guards(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: copy = 'build/test_vehicle_guard_wheel.txt'
      character(len=256) :: msg
      real(wp) :: totals(4), fresh(4), kin(kinematic_value_count)
      integer :: ih, ih2, istat, k, unit
      type(c_ptr), target :: h
      character(kind=c_char), target :: wheel(14), rail(14)
      integer(c_int) :: stat

      call execute_command_line('cp data/profiles/worn/S1002-worn.txt '//copy, exitstat=k)
      call check(error, k, 0, message='cannot copy the worn wheel profile')
      if (allocated(error)) return
      call shc_create_ws(ih, copy, 'builtin:UIC60', istat)
      if (istat == 0) call solve_ws_state(ih, totals, istat)
      open (newunit=unit, file=copy, status='old')
      close (unit, status='delete')
      if (istat == 0) call shc_set_material(ih, 82670.0d0, 0.27d0, 0.35d0, istat)
      if (istat /= 0) call shc_errmsg(ih, msg)
      call check(error, istat, 0, message='friction on a wheelset handle whose profile file '// &
         'is gone: '//trim(msg))
      if (allocated(error)) return
      call solve_ws_state(ih, totals, istat)
      call check(error, istat, 0, message='solve after the friction changed')
      if (allocated(error)) return
      ! An option and the track too: both wheels prepared again from the profiles as read.
      call shc_set_option(ih, 'tangential%n_elements', '40', istat)
      if (istat == 0) call shc_set_option(ih, 'track%gauge', '1437.0', istat)
      if (istat /= 0) call shc_errmsg(ih, msg)
      call check(error, istat, 0, message='an option on a wheelset handle whose profile file '// &
         'is gone: '//trim(msg))
      if (allocated(error)) return
      call solve_ws_state(ih, totals, istat)
      call shc_create_ws(ih2, 'data/profiles/worn/S1002-worn.txt', 'builtin:UIC60', istat)
      if (istat == 0) call shc_set_option(ih2, 'material%friction', '0.35', istat)
      if (istat == 0) call shc_set_option(ih2, 'tangential%n_elements', '40', istat)
      if (istat == 0) call shc_set_option(ih2, 'track%gauge', '1437.0', istat)
      if (istat == 0) call solve_ws_state(ih2, fresh, istat)
      call shc_destroy(ih2, k)
      call check(error, istat == 0 .and. bitwise_equal(totals, fresh), message='the friction, '// &
         'an option and the gauge set on a live wheelset handle give other forces than a '// &
         'handle made with them')
      if (allocated(error)) return
      ! A derailed wheelset: t_y = 40 mm (the case file allows |t_y| <= 30 mm).
      call shc_solve_ws(ih, 40.0d0, 0.0d0, 0.0d0, 3.0d4, 0.0d0, 0.0d0, 0.0d0, 0.0d0, &
         -3.0d4/460.0d0, 2, 64.7d3, 60.0d3, totals, istat)
      call shc_errmsg(ih, msg)
      call shc_destroy(ih, k)
      call check(error, istat, stat_invalid_input, message='wheelset at t_y = 40 mm: '//trim(msg))
      if (allocated(error)) return
      call check(error, index(msg, 't_y') > 0 .and. index(msg, '30') > 0, &
         message='the message should name t_y and its range: '//trim(msg))
      if (allocated(error)) return
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      if (istat == 0) call shc_solve_kin(ih, -40.0d0, 0.0d0, 0.0d0, 3.0d4, 0.0d0, 0.0d0, &
         0.0d0, 0.0d0, -3.0d4/460.0d0, 2, 64.7d3, kin, istat)
      call shc_destroy(ih, k)
      call check(error, istat, stat_invalid_input, message='one wheel at t_y = -40 mm')
      if (allocated(error)) return
      ! A blank profile name: status 2 and a message saying so (was status 3, "Cannot open
      ! file ''").
      call shc_create(ih, '  ', 'builtin:UIC60', 1, istat)
      call shc_errmsg(ih, msg)
      call shc_destroy(ih, k)
      call check(error, istat == stat_invalid_input .and. index(msg, 'empty profile name') > 0, &
         message='blank wheel name: '//trim(msg))
      if (allocated(error)) return
      ! NULL results through C: status 1 and a message, the handle still usable.
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      stat = shcontact_create_wheelset(c_loc(h), c_loc(wheel), c_loc(rail))
      if (stat == 0) stat = shcontact_solve_wheelset(h, ws_state%y_ws, ws_state%yaw, &
         ws_state%roll, ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, &
         ws_state%roll_rate, ws_state%yaw_rate, ws_state%pitch_rate, 2_c_int, 64.7e3_c_double, &
         60.0e3_c_double)
      call check(error, stat, stat_usage, message='NULL totals: '//c_message(h))
      if (allocated(error)) return
      call check(error, index(c_message(h), 'totals is NULL') > 0, message=c_message(h))
      if (allocated(error)) return
      stat = shcontact_solve(h, 4.733_c_double, 0.0_c_double, 1_c_int, 64.7e3_c_double, &
         0.0_c_double, 0.0_c_double, 0.0_c_double)
      call check(error, stat, stat_usage, message='NULL values of shcontact_solve')
      if (allocated(error)) return
      stat = shcontact_solve_wheelset(h, ws_state%y_ws, ws_state%yaw, ws_state%roll, &
         ws_state%v_forward, ws_state%v_lateral, ws_state%v_vertical, ws_state%roll_rate, &
         ws_state%yaw_rate, ws_state%pitch_rate, 2_c_int, 64.7e3_c_double, 60.0e3_c_double, &
         totals)
      msg = c_message(h)
      k = shcontact_destroy(h)
      call check(error, stat, 0, message='the handle after the NULL calls: '//trim(msg))
   end subroutine test_vehicle_call_guards

   !> The Fortran wheelset on `wheel` and the built-in UIC60 (default track and material;
   !> `tangential` options if given) at ws_state, 64.7 kN on the right wheel and 60 kN on the left.
   subroutine fortran_wheelset(wheel, expected, error, tangential)
      character(len=*), intent(in) :: wheel
      type(wheelset_result_type), intent(out) :: expected
      type(error_type), allocatable, intent(out) :: error
      type(tangential_options_type), intent(in), optional :: tangential
      type(wheelset_solver_type) :: ws
      type(lib_error), allocatable :: err
      call ws%init(wheel, 'builtin:UIC60', err, tangential_options=tangential)
      if (.not. allocated(err)) call ws%solve(ws_state, contact_load_type(2, 64.7e3_wp), &
         contact_load_type(2, 60.0e3_wp), expected, err)
      if (allocated(err)) call test_failed(error, 'Fortran wheelset: '//err%message)
   end subroutine fortran_wheelset

   !> A kinematic call takes the spin from the wheelset motion (spin model 'additive'): a spin
   !> model set otherwise on a handle makes SHC_SOLVE_KIN and SHC_SOLVE_WS refuse the call
   !> (status 2, the message names 'additive'), as the program refuses it in kinematic mode,
   !> rather than ignore it; 'additive' set again makes them solve.
   subroutine test_kinematic_spin_model(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: values(kinematic_value_count), totals(4)
      character(len=512) :: message
      integer :: ih, iw, istat, k, refused, refused_ws, solved, solved_ws

      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_create_ws(iw, 'builtin:S1002', 'builtin:UIC60', k)
      call check(error, istat == 0 .and. k == 0, message='handles not created')
      if (allocated(error)) return
      call shc_set_option(ih, 'tangential%spin_model', 'geometric', istat)
      call shc_set_option(iw, 'tangential%spin_model', 'geometric', k)
      call solve(refused, refused_ws)
      call shc_errmsg(ih, message)
      call shc_set_option(ih, 'tangential%spin_model', 'additive', istat)
      call shc_set_option(iw, 'tangential%spin_model', 'additive', k)
      call solve(solved, solved_ws)
      call shc_destroy(ih, k)
      call shc_destroy(iw, k)
      call check(error, refused == stat_invalid_input .and. refused_ws == stat_invalid_input &
         .and. index(message, "'additive'") > 0, message='a non-additive spin model should '// &
         'be refused by the kinematic calls: '//trim(message))
      if (allocated(error)) return
      call check(error, solved == 0 .and. solved_ws == 0, message='additive should solve')
   contains
      subroutine solve(one, both)
         integer, intent(out) :: one, both
         call shc_solve_kin(ih, ws_state%y_ws, ws_state%yaw, ws_state%roll, ws_state%v_forward, &
            ws_state%v_lateral, ws_state%v_vertical, ws_state%roll_rate, ws_state%yaw_rate, &
            ws_state%pitch_rate, 2, 64.7d3, values, one)
         call shc_solve_ws(iw, ws_state%y_ws, ws_state%yaw, ws_state%roll, ws_state%v_forward, &
            ws_state%v_lateral, ws_state%v_vertical, ws_state%roll_rate, ws_state%yaw_rate, &
            ws_state%pitch_rate, 2, 64.7d3, 64.7d3, totals, both)
      end subroutine solve
   end subroutine test_kinematic_spin_model

   !> A field by name is the array of shcontact_fields.
   subroutine test_field_by_name(error)
      type(error_type), allocatable, intent(out) :: error
      type(c_ptr) :: handle
      integer(c_int), target :: nx, ny
      real(c_double), allocatable, target :: f(:, :, :), g(:, :)
      integer(c_int), allocatable, target :: state(:, :)
      character(kind=c_char), allocatable, target :: k(:)
      character(len=5), parameter :: names(8) = ['x    ', 'y    ', 'area ', 'pn   ', 'px   ', &
         'py   ', 'slip ', 'state']
      integer :: i
      integer(c_int) :: stat

      call c_create(handle, error)
      if (allocated(error)) return
      stat = c_set_option(handle, 'output%fields', 'all')
      if (stat == 0) stat = shcontact_solve_state(handle)
      if (stat == 0) stat = shcontact_field_size(handle, 1_c_int, c_loc(nx), c_loc(ny))
      call check(error, stat == 0 .and. nx*ny > 0, message='fields: '//c_message(handle))
      if (allocated(error)) return
      allocate (f(nx, ny, 7), state(nx, ny), g(nx, ny))
      stat = shcontact_fields(handle, 1_c_int, nx, ny, c_loc(f(:, :, 1)), c_loc(f(:, :, 2)), &
         c_loc(f(:, :, 3)), c_loc(f(:, :, 4)), c_loc(f(:, :, 5)), c_loc(f(:, :, 6)), &
         c_loc(f(:, :, 7)), c_loc(state))
      call check(error, stat, 0_c_int)
      if (allocated(error)) return
      do i = 1, size(names)
         k = to_chars(trim(names(i)), 6)
         stat = shcontact_get_field(handle, c_loc(k), 1_c_int, nx, ny, c_loc(g))
         if (i <= 7) then
            call check(error, stat == 0 .and. bitwise_equal(reshape(g, [size(g)]), &
               reshape(f(:, :, i), [size(g)])), message='field '//trim(names(i)))
         else
            call check(error, stat == 0 .and. all(g == real(state, wp)), message='state')
         end if
         if (allocated(error)) return
      end do
      k = to_chars('tau', 4)
      call check(error, shcontact_get_field(handle, c_loc(k), 1_c_int, nx, ny, c_loc(g)), &
         int(stat_invalid_input, c_int))
      if (allocated(error)) return
      call check(error, shcontact_destroy(handle), 0_c_int)
   end subroutine test_field_by_name

   !> doc/api.md lists every input key a handle takes with its units (those of the variable
   !> table) and every output (the joined contact's too), wheelset and field key with its units.
   subroutine test_doc_keys(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: doc, units
      integer :: iv, use
      call read_whole('doc/api.md', doc, error)
      if (allocated(error)) return
      do iv = 1, size(variables)
         if (variables(iv)%group == 'sweep') cycle
         use = key_use(trim(variables(iv)%group), trim(variables(iv)%name))
         if (use /= key_solver .and. use /= key_state) cycle
         units = trim(variables(iv)%units)
         if (len(units) == 0) units = '—'
         call check(error, index(doc, new_line('a')//'| `'//trim(variables(iv)%group)//'%'// &
            trim(variables(iv)%name)//'` | ') > 0 .and. index(doc, '%'// &
            trim(variables(iv)%name)//'` | '//kind_word(variables(iv)%kind)//' | '//units// &
            ' |') > 0, message='doc/api.md: no row of input key '// &
            trim(variables(iv)%group)//'%'//trim(variables(iv)%name)//' with units '//units)
         if (allocated(error)) return
      end do
      call check_rows(output_keys)
      if (allocated(error)) return
      call check_rows(wheelset_keys)
      if (allocated(error)) return
      call check_rows(field_keys)
      if (allocated(error)) return
      ! The wheel's joined contact (keys beyond the flat layout).
      call check_rows([(output_key_type('', 0, wheel_columns(iv)%units, ''), &
         iv=1, size(wheel_columns))], wheel_columns%name)
   contains
      subroutine check_rows(keys, names)
         type(output_key_type), intent(in) :: keys(:)
         !> The keys' names when longer than output_key_type's (else keys%name).
         character(len=*), intent(in), optional :: names(:)
         integer :: i
         character(len=:), allocatable :: u, name
         do i = 1, size(keys)
            name = trim(keys(i)%name)
            if (present(names)) name = trim(names(i))
            u = trim(keys(i)%units)
            if (u == 'mm^2') u = 'mm²'
            if (u == 'N mm') u = 'N·mm'
            call check(error, index(doc, new_line('a')//'| `'//name//'` | '//u// &
               ' |') > 0, message='doc/api.md: no row of output key '//name// &
               ' with units '//u)
            if (allocated(error)) return
         end do
      end subroutine check_rows
      pure function kind_word(kind) result(w)
         integer, intent(in) :: kind
         character(len=:), allocatable :: w
         select case (kind)
         case (k_real); w = 'number'
         case (k_int); w = 'whole number'
         case (k_string, k_choice); w = 'text'
         case default; w = 'logical'
         end select
      end function kind_word
   end subroutine test_doc_keys

   !> A text file as one string (lines joined by new-line characters).
   subroutine read_whole(file, text, error)
      character(len=*), intent(in) :: file
      character(len=:), allocatable, intent(out) :: text
      type(error_type), allocatable, intent(out) :: error
      character(len=2000) :: line
      integer :: unit, stat
      text = new_line('a')
      open (newunit=unit, file=file, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, file//' not found (run from the root)')
         return
      end if
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         text = text//trim(line)//new_line('a')
      end do
      close (unit)
   end subroutine read_whole

end module test_flat_keys
