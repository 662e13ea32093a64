!> Validation, once, into a trusted configuration: every value against its range or choices,
!> the sweep for consistency, and the settings derived from others (the wheel origin of a
!> MiniProf file, whether the pitch rate was given, the rules of kinematic mode). Messages
!> name where the value was set, the group, the variable, the value and what is allowed.
module shcontact_input_config_validate
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_error, only: error_type, fatal_error
   use shcontact_core_strings, only: to_lower, str_int
   use shcontact_core_text, only: format_real
   use shcontact_core_ranges, only: range_type => variable_info_type, ranges, find_range, &
      in_range, range_text, has_range, max_grid_cells
   use shcontact_profile_reader, only: profile_file_format
   use shcontact_input_config_limits, only: max_sweep_values, max_fields, max_cases
   use shcontact_input_config_sweep, only: n_sweep_axes, sweep_axis_names, axis_stage, axis_load, &
      is_kinematic_input
   use shcontact_input_config_types, only: case_config_type, origin, sweep_origin, choice_value, &
      normal_options_of, tangential_options_of, number_value
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_input_config_variables, only: variables, k_choice, k_int
   use shcontact_core_choices, only: choice_type, choice_code, choice_name, choice_list
   use shcontact_input_config_variables, only: variable_choices
   use shcontact_input_config_choices, only: format_choices, mirror_choices, field_choices, &
      load_mode_choices, load_mode_force, load_mode_approach, &
      load_mode_vertical, sweep_list, load_mode_shared, load_mode_uses, load_quantities, &
      load_mode_reading, tables_conformal
   use shcontact_normal_option_registry, only: normal_methods => method_choices, method_hertz, &
      slide_exact
   use shcontact_tangential_option_registry, only: method_fastsim, spin_additive, &
      spin_model_choices
   implicit none
   private

   public :: validate_config

contains

   !> Check every value against its allowed range or choices, and the sweep for consistency.
   !> Messages name where the value was set, the group, the variable, the value and what is
   !> allowed.
   subroutine validate_config(config, error)
      !> The configuration; choice values are normalised to lower case, sweep axes activated.
      type(case_config_type), intent(inout) :: config
      !> Set on the first problem found.
      type(error_type), allocatable, intent(out) :: error

      associate (c => config)
         call check_choice(c, 'profiles', 'wheel_format', c%profiles%wheel_format, &
            format_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'rail_format', c%profiles%rail_format, format_choices, &
            error)
         if (allocated(error)) return
         call check_profile_name(c, 'wheel', c%profiles%wheel, 'builtin:S1002', error)
         if (allocated(error)) return
         call check_profile_name(c, 'rail', c%profiles%rail, 'builtin:UIC60', error, &
            also='builtin:UIC60-canted')
         if (allocated(error)) return
         call resolve_wheel_origin(c)
         call check_choice(c, 'profiles', 'wheel_mirror_y', c%profiles%wheel_mirror_y, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'wheel_mirror_z', c%profiles%wheel_mirror_z, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'rail_mirror_y', c%profiles%rail_mirror_y, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'rail_mirror_z', c%profiles%rail_mirror_z, &
            mirror_choices, error)
         if (allocated(error)) return
         ! The numbers of each group in their ranges, in the variable table's order (a pitch
         ! rate only when given; the tangential grid after the preset has set it).
         c%kinematics%pitch_rate_given = origin(c, 'kinematics%pitch_rate') /= 'default'
         call check_numbers(c, ['profiles  ', 'track     ', 'position  ', 'kinematics', &
            'material  ', 'load      ', 'creepage  ', 'normal    '], error)
         if (allocated(error)) return
         call check_codes(c, error)
         if (allocated(error)) return
         call resolve_preset(c)
         call check_numbers(c, ['tangential'], error)
         if (allocated(error)) return
         call check_grid_size(c, error)
         if (allocated(error)) return
         if (c%tangential%method == method_fastsim .and. c%normal%method /= method_hertz) then
            call fatal_error(error, origin(c, 'tangential%method')//": &tangential method = "// &
               "'fastsim' works on the Hertz ellipse of the reference point: set &normal "// &
               "method = 'hertz' (now '"//choice_name(normal_methods, c%normal%method)//"')")
            return
         end if
         if (c%normal%strip_tables == tables_conformal .and. c%normal%slide == slide_exact) &
            then
            call fatal_error(error, origin(c, 'normal%slide')//": &normal slide = 'exact' "// &
               "slides the wheel along the plane of planar strip tables: set &normal "// &
               "strip_tables = 'planar' (conformal tables close each point's gap along its "// &
               "own normal)")
            return
         end if
         call check_output(c, error)
         if (allocated(error)) return
         call resolve_kinematic_mode(c, error)
         if (allocated(error)) return
         call check_load_quantities(c, error)
         if (allocated(error)) return
         call check_sweep(c, error)
      end associate
   end subroutine validate_config

   !> A MiniProf wheel has its origin at the flange back: unless `&track flange_back_position`
   !> is given, it is 0 for such a wheel (the default −70 mm is S1002's, whose origin is at the
   !> tape circle). The resolved namelist shows the value used.
   subroutine resolve_wheel_origin(config)
      type(case_config_type), intent(inout) :: config
      if (origin(config, 'track%flange_back_position') /= 'default') return
      if (index(to_lower(config%profiles%wheel), 'builtin:') == 1) return
      if (profile_file_format(trim(config%profiles%wheel), trim(config%profiles%wheel_format)) &
          == 'miniprof') config%track%flange_back_position = 0.0_wp
   end subroutine resolve_wheel_origin

   !> The grid of `&normal preset` where the case does not give n_strips or n_elements, so that
   !> the grid check, `--check` and the resolved namelist show the grid that is solved (the
   !> library's options come from normal_options_of and tangential_options_of, which apply the
   !> same rule).
   pure subroutine resolve_preset(config)
      type(case_config_type), intent(inout) :: config
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      normal = normal_options_of(config)
      tangential = tangential_options_of(config)
      config%normal%n_strips = normal%n_strips
      config%tangential%n_elements = tangential%n_elements
      config%tangential%bound = tangential%bound
   end subroutine resolve_preset

   !> n_strips × n_elements within [[max_grid_cells]], checked before anything is allocated.
   subroutine check_grid_size(config, error)
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      integer(i8) :: cells
      character(len=:), allocatable :: where
      cells = int(config%normal%n_strips, i8)*int(config%tangential%n_elements, i8)
      if (cells <= max_grid_cells) return
      where = origin(config, 'tangential%n_elements')
      if (where == 'default') where = origin(config, 'normal%n_strips')
      call fatal_error(error, where//': &normal n_strips × &tangential n_elements = '// &
         str_int(config%normal%n_strips)//' × '//str_int(config%tangential%n_elements)// &
         ' = '//str_int(cells)//' grid cells per patch; at most '//str_int(max_grid_cells)// &
         ' are allowed (memory grows with it on every thread)')
   end subroutine check_grid_size

   !> Every number of the groups `groups` (variables with a range of the variable table) in its
   !> range, in the table's order (its groups' order); the pitch rate only when it was given.
   subroutine check_numbers(config, groups, error)
      type(case_config_type), intent(in) :: config
      !> The groups.
      character(len=*), intent(in) :: groups(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: iv
      do iv = 1, size(variables)
         associate (v => variables(iv))
            if (.not. has_range(v)) cycle
            if (.not. any(groups == v%group)) cycle
            if (v%group == 'kinematics' .and. v%name == 'pitch_rate' .and. &
                .not. config%kinematics%pitch_rate_given) cycle
            if (v%kind == k_int) then
               call check_int_var(config, trim(v%group), trim(v%name), &
                  nint(number_value(config, v%group, v%name)), error)
            else
               call check_real(config, trim(v%group), trim(v%name), trim(v%name), &
                  number_value(config, v%group, v%name), error)
            end if
            if (allocated(error)) return
         end associate
      end do
   end subroutine check_numbers

   !> Kinematic mode takes the creepages from the wheelset motion: `&creepage` must not be
   !> given (it would be silently ignored), the spin model is 'additive' (that of the library's
   !> `solve_kinematic`, which carries the rigid slip to each strip) and the load defaults to
   !> the vertical wheel load shared by all patches.
   subroutine resolve_kinematic_mode(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: creepages(3) = [character(len=4) :: 'nu_x', 'nu_y', 'phi']
      character(len=:), allocatable :: where
      integer :: i

      if (.not. config%is_kinematic()) return
      do i = 1, size(creepages)
         where = origin(config, 'creepage%'//trim(creepages(i)))
         if (where == 'default') cycle
         call fatal_error(error, where//': &creepage '//trim(creepages(i))//' is given, but '// &
            "&kinematics mode = 'on' computes the creepages of every patch from the wheelset "// &
            "motion; remove &creepage, or set &kinematics mode = 'off' to prescribe them")
         return
      end do
      where = origin(config, 'tangential%spin_model')
      if (where /= 'default' .and. config%tangential%spin_model /= spin_additive) then
         call fatal_error(error, where//": &tangential spin_model = '"// &
            choice_name(spin_model_choices, config%tangential%spin_model)// &
            "': &kinematics mode = 'on' needs "// &
            "spin_model = 'additive' (the rigid slip carried to each strip, as the library's "// &
            "solve_kinematic); remove it or set 'additive'")
         return
      end if
      config%tangential%spin_model = spin_additive
      if (origin(config, 'load%mode') == 'default') config%load%mode = load_mode_vertical
   end subroutine resolve_kinematic_mode

   !> A `&load` quantity given (case file or override) that the load mode does not read would
   !> be silently ignored: refused, naming the mode and the quantity it reads. Checked after
   !> the kinematic mode has resolved the mode's default.
   subroutine check_load_quantities(config, error)
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: where, mode, used
      integer :: i, j

      do i = 1, size(load_quantities)
         where = origin(config, 'load%'//trim(load_quantities(i)))
         if (where == 'default' .or. load_mode_uses(trim(load_quantities(i)), &
            config%load%mode)) cycle
         mode = choice_name(load_mode_choices, config%load%mode)
         used = ''
         do j = 1, size(load_quantities)
            if (load_mode_uses(trim(load_quantities(j)), config%load%mode)) &
               used = trim(load_quantities(j))
         end do
         call fatal_error(error, where//': &load '//trim(load_quantities(i))//' is given, but '// &
            "&load mode = '"//mode//"' does not read it (it reads "//used//'); remove it, or '// &
            "set the mode that reads it ('"//load_mode_reading(trim(load_quantities(i)))//"'"// &
            trim(merge(" or 'shared-force'", '                  ', &
            trim(load_quantities(i)) == 'normal_force'))//')')
         return
      end do
   end subroutine check_load_quantities

   !> The key of a variable's range in shcontact_core_ranges (a sweep list takes the range of
   !> the variable it sweeps); 0 when it has none.
   pure integer function range_index(group, name) result(ir)
      character(len=*), intent(in) :: group, name
      integer :: i
      ir = find_range(group//'%'//name)
      if (ir > 0 .or. group /= 'sweep') return
      do i = 1, size(ranges)
         if (ranges(i)%name == name) then
            ir = i
            return
         end if
      end do
   end function range_index

   !> A real in its allowed range (shcontact_core_ranges), finite.
   subroutine check_real(config, group, name, label, x, error)
      type(case_config_type), intent(in) :: config
      !> Group and variable (for the range and the origin).
      character(len=*), intent(in) :: group, name
      !> How to show the variable in the message (e.g. 'nu_x(3)').
      character(len=*), intent(in) :: label
      real(wp), intent(in) :: x
      type(error_type), allocatable, intent(out) :: error
      type(range_type) :: r
      integer :: ir

      ir = range_index(group, name)
      if (ir == 0) then
         if (ieee_is_finite(x)) return
         r = range_type(lo=-huge(1.0_wp), hi=huge(1.0_wp))
      else
         r = ranges(ir)
         if (in_range(r, x)) return
      end if
      call fatal_error(error, origin(config, group//'%'//name)//': &'//group//' '//label// &
         ' = '//format_real(x)//' is out of range; expected '// &
         range_text(r, name, format_real(r%lo), format_real(r%hi)))
   end subroutine check_real

   !> An integer in its allowed range (shcontact_core_ranges).
   subroutine check_int_var(config, group, name, i, error)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: i
      type(error_type), allocatable, intent(out) :: error
      type(range_type) :: r
      r = ranges(find_range(group//'%'//name))
      if (in_range(r, real(i, wp))) return
      call fatal_error(error, origin(config, group//'%'//name)//': &'//group//' '//name// &
         ' = '//str_int(i)//' is out of range; expected '// &
         range_text(r, name, str_int(nint(r%lo)), str_int(nint(r%hi))))
   end subroutine check_int_var

   !> A string choice (kept as text) among the registry's names: spelt as the registry does.
   subroutine check_choice(config, group, name, value, allowed, error)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: group, name
      !> The value; its registry spelling on return.
      character(len=*), intent(inout) :: value
      type(choice_type), intent(in) :: allowed(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: code
      code = choice_code(allowed, value)
      if (code /= 0) then
         value = choice_name(allowed, code)
         return
      end if
      call fatal_error(error, origin(config, group//'%'//name)//': &'//group//' '//name// &
         " = '"//trim(value)//"' is not allowed; expected one of "//choice_list(allowed))
   end subroutine check_choice

   !> Every choice variable holds a code of its choices (they are read as names, so only a
   !> configuration set in code can fail this).
   subroutine check_codes(config, error)
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      type(choice_type), allocatable :: choices(:)
      integer :: i, code
      do i = 1, size(variables)
         if (variables(i)%kind /= k_choice) cycle
         choices = variable_choices(variables(i)%group, variables(i)%name)
         code = choice_value(config, variables(i)%group, variables(i)%name)
         if (any(choices%code == code)) cycle
         call fatal_error(error, origin(config, trim(variables(i)%group)//'%'// &
            trim(variables(i)%name))//': &'//trim(variables(i)%group)//' '// &
            trim(variables(i)%name)//' holds the code '//str_int(code)//'; expected that of '// &
            choice_list(choices))
         return
      end do
   end subroutine check_codes

   !> A built-in name is one we have; anything else is a file name (checked when it is read).
   subroutine check_profile_name(config, name, value, builtin, error, also)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: name, builtin
      !> The profile name; a built-in name is spelt canonically on return.
      character(len=*), intent(inout) :: value
      type(error_type), allocatable, intent(out) :: error
      !> Another accepted built-in name.
      character(len=*), intent(in), optional :: also
      if (to_lower(value) == to_lower(builtin)) value = builtin
      if (present(also)) then
         if (to_lower(value) == to_lower(also)) then
            value = also
            return
         end if
      end if
      if (len_trim(value) == 0) then
         call fatal_error(error, origin(config, 'profiles%'//name)//': &profiles '//name// &
            " is empty; expected '"//builtin//"' or a file name")
      else if (index(to_lower(value), 'builtin:') == 1 .and. &
               to_lower(value) /= to_lower(builtin)) then
         call fatal_error(error, origin(config, 'profiles%'//name)//': &profiles '//name// &
            " = '"//trim(value)//"': unknown built-in profile; expected '"//builtin// &
            "'"//alternative(also)//" or a file name")
      end if
   end subroutine check_profile_name

   pure function alternative(also) result(text)
      character(len=*), intent(in), optional :: also
      character(len=:), allocatable :: text
      text = ''
      if (present(also)) text = ", '"//also//"'"
   end function alternative

   subroutine check_output(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      integer :: i, n
      if (len_trim(config%output%file) == 0) then
         call fatal_error(error, origin(config, 'output%file')//': &output file is empty; '// &
            'expected a file name')
         return
      end if
      call check_numbers(config, ['output'], error)
      if (allocated(error)) return
      n = 0
      do i = 1, max_fields
         if (len_trim(config%output%fields(i)) == 0) cycle
         n = n + 1
         call check_choice(config, 'output', 'fields', config%output%fields(i), field_choices, &
            error)
         if (allocated(error)) return
      end do
      if (n == 0) config%output%fields(1) = 'none'
      ! 'all', 'none' and 'auto' stand alone: beside other fields they contradict them.
      if (n > 1 .and. (any(config%output%fields == 'none') .or. &
          any(config%output%fields == 'all') .or. any(config%output%fields == 'auto'))) then
         call fatal_error(error, origin(config, 'output%fields')//": 'all', 'none' and "// &
            "'auto' stand alone; expected one of them, or a list of fields (e.g. "// &
            "'pressure', 'traction')")
      end if
   end subroutine check_output

   !> Every sweep value in the range of its variable; ranges well formed; list lengths equal
   !> in 'list' mode; load axes that match the load mode.
   subroutine check_sweep(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: where, name
      integer :: ia, i, n_list

      n_list = -1
      do ia = 1, n_sweep_axes
         associate (axis => config%sweep%axes(ia))
            name = trim(sweep_axis_names(ia))
            where = origin(config, 'sweep%'//name)
            if (where == 'default') where = origin(config, 'sweep%'//name//'_points')
            if (where == 'default') where = sweep_origin(config)
            axis%active = .false.
            if (axis%is_label) then
               axis%active = size(axis%labels) > 0
               if (allocated(axis%codes)) deallocate (axis%codes)
               allocate (axis%codes(axis%size()))
               do i = 1, axis%size()
                  call check_choice(config, 'sweep', name, axis%labels(i), &
                     variable_choices('sweep', name), error)
                  if (allocated(error)) return
                  axis%codes(i) = choice_code(variable_choices('sweep', name), axis%labels(i))
               end do
            else
               if (.not. allocated(axis%given)) allocate (axis%given(0))
               if (axis%points /= 0) then
                  if (axis%points < 2 .or. axis%points > max_sweep_values) then
                     call fatal_error(error, origin(config, 'sweep%'//name//'_points')// &
                        ': &sweep '//name//'_points = '//str_int(axis%points)// &
                        ' is out of range; expected 0 (a list) or 2 to '// &
                        str_int(max_sweep_values))
                     return
                  end if
                  if (size(axis%given) /= 2) then
                     call fatal_error(error, where//': &sweep '//name//' has '// &
                        str_int(size(axis%given))//' values; with '//name// &
                        '_points > 0 it must hold exactly two: first, last')
                     return
                  end if
               end if
               axis%active = size(axis%given) > 0
               do i = 1, size(axis%given)
                  call check_real(config, 'sweep', name, name//'('//str_int(i)//')', &
                     axis%given(i), error)
                  if (allocated(error)) return
               end do
            end if
            if (.not. axis%active) cycle
            if (config%is_kinematic() .and. any(name == ['nu_x      ', 'nu_y      ', &
                'phi       ', 'spin_model'])) then
               call fatal_error(error, where//': &sweep '//name//" is given, but &kinematics "// &
                  "mode = 'on' takes the creepages from the wheelset motion (spin model "// &
                  "'additive'); sweep the wheelset inputs (t_y, roll, yaw, v_forward, ...) instead")
               return
            end if
            if (.not. config%is_kinematic() .and. is_kinematic_input(name) .and. &
                name /= 't_y' .and. name /= 'roll') then
               call fatal_error(error, where//': &sweep '//name//" is given, but &kinematics "// &
                  "mode = 'off' (prescribed creepages); set &kinematics mode = 'on' to solve "// &
                  'from the wheelset motion')
               return
            end if
            if (axis_stage(ia) == axis_load .and. .not. load_mode_uses(name, &
                config%load%mode)) then
               call fatal_error(error, where//': &sweep '//name//' is given but &load mode = '// &
                  "'"//choice_name(load_mode_choices, config%load%mode)// &
                  "'; sweep the quantity of the load mode")
               return
            end if
            if (config%sweep%mode == sweep_list) then
               if (n_list < 0) then
                  n_list = axis%size()
               else if (axis%size() /= n_list) then
                  call fatal_error(error, where//": &sweep mode = 'list' needs lists of equal "// &
                     'length; '//name//' has '//str_int(axis%size())//' values, an '// &
                     'earlier list '//str_int(n_list))
                  return
               end if
            end if
         end associate
      end do
      if (config%n_cases() > max_cases) then
         call fatal_error(error, sweep_origin(config)//': the sweep has more than '// &
            str_int(max_cases)//' cases; split it into several runs')
      end if
   end subroutine check_sweep


end module shcontact_input_config_validate
