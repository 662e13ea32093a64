!> Keyed inputs and outputs of the flat interfaces (doc/api.md §"Keyed calls"): a value set by
!> its namelist key, a solve of the state so set, and any result value or element field read by
!> its name, so that a new input or output adds a key, never a changed signature.
!>
!> * [[context_set_value]]: a number by key (`group%variable`, or the variable alone where only
!>   one group has it: 't_y', 'yaw', 'vertical_force', ...), through the same setter as
!>   context_set_option;
!> * [[context_solve_state]]: solve the state of the keys `&position`, `&kinematics` (mode 'on':
!>   the kinematic call), `&load`, `&creepage`, as the app solves one case;
!> * [[context_get_value]]: a numeric input by its key `group%variable` (the handle's current
!>   setting: a default, or what the handle resolved, e.g. a MiniProf wheel's flange-back
!>   position 0), or a result value by its name in [[output_keys]] (or, beyond the flat
!>   layout, in shcontact_pipeline_result's patch_columns), of the main patch
!>   (patch 0) or of patch k, and the wheel's joined contact ('wheel_fx', ..., its
!>   wheel_columns, patch 0: doc/lobes.md); on a wheelset handle 'wheelset%fx' ... 'wheelset%mz' and
!>   'right%NAME', 'left%NAME';
!> * [[context_get_field]]: one element field by its name in [[field_keys]].
module shcontact_api_keyed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_usage
   use shcontact_core_strings, only: to_lower, str_int, visible
   use shcontact_core_text, only: format_real
   use shcontact_core_ranges, only: has_range, range_text
   use shcontact_input_config, only: case_config_type, case_point_type, validate_config
   use shcontact_input_config_types, only: output_config_type, number_value, normal_options_of, &
      tangential_options_of, origin
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_input_config_variables, only: variables, k_int, k_real, k_real_list, &
      find_variable
   use shcontact_api_solver, only: contact_result_type, contact_load_type, max_patches
   use shcontact_pipeline_result, only: patch_columns, patch_value, find_patch_column, &
      wheel_columns, wheel_value, find_wheel_column, wheel_contact_of
   use shcontact_api_wheelset, only: wheel_right, wheel_left
   use shcontact_api_settings, only: config_load, config_state, split_key
   use shcontact_geometry_kinematics, only: pure_rolling_pitch_rate
   use shcontact_api_values, only: kinematic_value_count, result_value_count, kinematic_values, value_fx, value_fy, &
      value_mz, value_fn, value_fx_norm, value_fy_norm, value_fy_track, value_fz_track, &
      value_approach, value_area, value_p_max, value_gamma0, value_r0, value_y_track, &
      value_z_track, value_coulomb, value_adhesion, value_n_patches, value_n_loaded, &
      value_main_patch, value_sum_fx, value_sum_fy, value_sum_fz, value_sum_fn, value_dz, &
      value_nu_x, value_nu_y, value_phi, value_x_track
   use shcontact_api_context, only: contact_context_type, context_record, context_usable, &
      context_set_option, context_solve, context_solve_kinematic, context_solve_wheelset
   use shcontact_api_context_results, only: context_check_field_arrays, context_field_size, &
      context_fields
   implicit none
   private

   public :: output_key_type, output_keys, field_keys, wheelset_keys
   public :: context_set_value, context_solve_state, context_get_value, context_get_field, &
      context_wheel, context_set_option_by_key

   !> A result value by name: its index in the kinematic layout (shcontact_api_values), its
   !> units and what it is.
   type :: output_key_type
      !> The name (lower case).
      character(len=12) :: name = ''
      !> Index in the kinematic layout (a total's or a field's position in its own list).
      integer :: index = 0
      !> Units ('1': dimensionless).
      character(len=8) :: units = ''
      !> What it is.
      character(len=72) :: help = ''
   end type output_key_type

   !> The result values by name (doc/api.md lists them with their units).
   type(output_key_type), parameter :: output_keys(*) = [ &
      output_key_type('fx', value_fx, 'N', 'longitudinal force F_x, contact plane'), &
      output_key_type('fy', value_fy, 'N', 'lateral force F_y, contact plane'), &
      output_key_type('mz', value_mz, 'N mm', 'spin moment M_z about the reference point'), &
      output_key_type('fn', value_fn, 'N', 'normal force F_n'), &
      output_key_type('fx_norm', value_fx_norm, '1', 'F_x/(mu F_n)'), &
      output_key_type('fy_norm', value_fy_norm, '1', 'F_y/(mu F_n)'), &
      output_key_type('fy_track', value_fy_track, 'N', 'lateral force, track frame'), &
      output_key_type('fz_track', value_fz_track, 'N', 'vertical force, track frame, z down'), &
      output_key_type('approach', value_approach, 'mm', 'approach delta'), &
      output_key_type('area', value_area, 'mm^2', 'contact area'), &
      output_key_type('p_max', value_p_max, 'MPa', 'largest strip peak pressure'), &
      output_key_type('gamma0', value_gamma0, 'rad', "contact angle (CONTACT's sign)"), &
      output_key_type('r0', value_r0, 'mm', 'wheel rolling radius at the reference point'), &
      output_key_type('y_track', value_y_track, 'mm', 'reference point, true track y'), &
      output_key_type('z_track', value_z_track, 'mm', 'reference point, track z (down)'), &
      output_key_type('coulomb', value_coulomb, '1', 'max |p|/(mu p_n)'), &
      output_key_type('adhesion', value_adhesion, '1', 'adhesion area fraction'), &
      output_key_type('n_patches', value_n_patches, '1', 'patches found'), &
      output_key_type('n_loaded', value_n_loaded, '1', 'patches solved'), &
      output_key_type('main_patch', value_main_patch, '1', 'index of the main patch'), &
      output_key_type('sum_fx', value_sum_fx, 'N', 'total F_x over the loaded patches'), &
      output_key_type('sum_fy', value_sum_fy, 'N', 'total F_y (track frame)'), &
      output_key_type('sum_fz', value_sum_fz, 'N', 'total F_z (track frame, z down)'), &
      output_key_type('sum_fn', value_sum_fn, 'N', 'total F_n'), &
      output_key_type('dz', value_dz, 'mm', 'rigid vertical approach of the wheel'), &
      output_key_type('nu_x', value_nu_x, '1', 'longitudinal creepage, wheel relative to rail'), &
      output_key_type('nu_y', value_nu_y, '1', 'lateral creepage'), &
      output_key_type('phi', value_phi, 'rad/mm', 'spin creepage'), &
      output_key_type('x_track', value_x_track, 'mm', 'reference point, track x (forward)')]

   !> The program's names of the same values (its `/summary` columns, CSV and JSON keys), taken
   !> as the keys they name, so that one name reads a value in every interface: pairs of
   !> (program's name, key).
   character(len=*), parameter :: summary_aliases(2, 7) = reshape([character(len=17) :: &
      'coulomb_ratio', 'coulomb', 'adhesion_fraction', 'adhesion', 'delta', 'approach', &
      'fn_total', 'sum_fn', 'fx_total', 'sum_fx', 'fy_total', 'sum_fy', 'fz_total', 'sum_fz'], &
      [2, 7])

   !> The key of the flange-climbing flag (1: the main patch's contact lies on the flange
   !> beyond its steepest part, contact_result_type%climbing; patch 0).
   character(len=*), parameter :: climbing_key = 'climbing'

   !> The wheelset totals of a wheelset handle (true track frame, forces on the wheelset).
   type(output_key_type), parameter :: wheelset_keys(*) = [ &
      output_key_type('wheelset%fx', 1, 'N', 'total longitudinal force'), &
      output_key_type('wheelset%fy', 2, 'N', 'total lateral force'), &
      output_key_type('wheelset%fz', 3, 'N', 'total vertical force (z down)'), &
      output_key_type('wheelset%mz', 4, 'N mm', 'moment about the vertical axis')]

   !> The element fields by name (context_fields; state as 0, 1, 2).
   type(output_key_type), parameter :: field_keys(*) = [ &
      output_key_type('x', 1, 'mm', 'element centre along the rolling direction'), &
      output_key_type('y', 2, 'mm', 'strip centre across the patch'), &
      output_key_type('area', 3, 'mm^2', 'element area'), &
      output_key_type('pn', 4, 'MPa', 'normal pressure'), &
      output_key_type('px', 5, 'MPa', 'longitudinal traction on the wheel'), &
      output_key_type('py', 6, 'MPa', 'lateral traction on the wheel'), &
      output_key_type('slip', 7, '1', 'slip magnitude (0 in adhesion)'), &
      output_key_type('state', 8, '1', 'element state: 0 exterior, 1 adhesion, 2 slip')]

contains

   !> context_set_option with the key as [[context_set_value]] takes it: `group%variable`, or a
   !> variable name that only one group has ('friction': set_value took it, set_option did not).
   integer function context_set_option_by_key(ctx, key, value) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> The key (case-insensitive).
      character(len=*), intent(in) :: key
      !> Its value, as in the case files.
      character(len=*), intent(in) :: value
      type(error_type), allocatable :: error
      character(len=:), allocatable :: full
      integer :: iv
      if (index(key, '%') > 0 .or. len_trim(key) == 0) then
         stat = context_set_option(ctx, key, value)
         return
      end if
      call resolve_key(key, full, iv, error, 'option')
      if (allocated(error)) then
         stat = context_record(ctx, error)
      else
         stat = context_set_option(ctx, full, value)
      end if
   end function context_set_option_by_key

   !> Set a number by key: `group%variable`, or a variable name that only one group has. Goes
   !> through context_set_option (one setter); an integer variable needs a whole number, a text
   !> variable context_set_option.
   integer function context_set_value(ctx, key, x) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> The key (case-insensitive).
      character(len=*), intent(in) :: key
      !> The value, in the units of the key (doc/api.md).
      real(wp), intent(in) :: x
      type(error_type), allocatable :: error
      character(len=:), allocatable :: full
      integer :: iv

      call resolve_key(key, full, iv, error)
      if (.not. allocated(error)) then
         select case (variables(iv)%kind)
         case (k_real, k_real_list)
            stat = context_set_option(ctx, full, format_real(x))
            return
         case (k_int)
            if (abs(x) < 2.0e9_wp .and. x == anint(x)) then
               stat = context_set_option(ctx, full, str_int(nint(x)))
               return
            end if
            if (x == anint(x) .and. has_range(variables(iv))) then
               ! A whole number beyond the int range is out of the variable's range.
               call fatal_error(error, 'value '//full//' = '//format_real(x)// &
                  ' is out of range; expected '//range_text(variables(iv), &
                  trim(variables(iv)%name), format_real(variables(iv)%lo), &
                  format_real(variables(iv)%hi)), stat_invalid_input)
            else
               call fatal_error(error, 'value '//full//' = '//format_real(x)// &
                  ': expected a whole number', stat_invalid_input)
            end if
         case default
            call fatal_error(error, 'value '//full//': a text option; set it with '// &
               'shcontact_set_option (shc_set_option)', stat_invalid_input)
         end select
      end if
      stat = context_record(ctx, error)
   end function context_set_value

   !> The full key and its index in the variable table of `group%variable` or of a variable
   !> name that exactly one group (not the sweep's) has.
   subroutine resolve_key(key, full, iv, error, what)
      character(len=*), intent(in) :: key
      character(len=:), allocatable, intent(out) :: full
      integer, intent(out) :: iv
      type(error_type), allocatable, intent(out) :: error
      !> What the key names, for the messages (default 'value').
      character(len=*), intent(in), optional :: what
      character(len=:), allocatable :: k, word
      integer :: i, n
      k = trim(adjustl(to_lower(key)))
      iv = 0
      n = 0
      do i = 1, size(variables)
         if (variables(i)%group == 'sweep') cycle
         if (k == trim(variables(i)%group)//'%'//trim(variables(i)%name)) then
            iv = i
            n = 1
            exit
         end if
         if (k == trim(variables(i)%name)) then
            iv = i
            n = n + 1
         end if
      end do
      if (n == 1) then
         full = trim(variables(iv)%group)//'%'//trim(variables(iv)%name)
         return
      end if
      word = 'value'
      if (present(what)) word = what
      if (n == 0) then
         call fatal_error(error, word//" '"//visible(key)//"': unknown key; expected "// &
            'group%variable as in the case files (doc/api.md)', stat_invalid_input)
      else
         call fatal_error(error, word//" '"//visible(key)//"': several groups have this "// &
            'variable; give group%variable', stat_invalid_input)
      end if
      iv = 0
   end subroutine resolve_key

   !> Solve the state set by key: the wheelset position and velocities (`&position`,
   !> `&kinematics`), the load (`&load`) and, unless `kinematics%mode` is 'on', the creepages
   !> (`&creepage`), with the result of context_solve (or context_solve_kinematic). The settings
   !> are first checked as the app checks a case file (validate_config: its ranges, and in
   !> kinematic mode no `&creepage` and the load 'vertical' unless given); the profiles were
   !> checked at creation. On a wheelset handle both wheels get the same load
   !> (context_solve_wheelset).
   integer function context_solve_state(ctx) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      type(case_config_type) :: config
      type(case_point_type) :: p
      type(contact_load_type) :: load
      type(error_type), allocatable :: error
      real(wp) :: values(kinematic_value_count), totals(4)

      config = ctx%config
      config%profiles%wheel = 'builtin:S1002'
      config%profiles%rail = 'builtin:UIC60'
      config%output = output_config_type()
      call validate_config(config, error)
      if (allocated(error)) then
         ctx%has_result = .false.
         ctx%has_fields = .false.
         stat = context_record(ctx, error)
         return
      end if
      p = config%case_point(1)
      load = config_load(config, p)
      if (ctx%is_wheelset) then
         stat = context_solve_wheelset(ctx, config_state(p), load%mode, load%value, &
            load%value, totals)
      else if (config%is_kinematic()) then
         stat = context_solve_kinematic(ctx, config_state(p), load%mode, load%value, values)
      else
         stat = context_solve(ctx, p%t_y, p%roll, load%mode, load%value, p%nu_x, p%nu_y, &
            p%phi, values(1:result_value_count))
      end if
   end function context_solve_state

   !> A result value of the last solve by name ([[output_keys]]): of the main patch (patch 0,
   !> with the result's counts and totals) or of patch `patch`. On a wheelset handle:
   !> 'wheelset%fx', ..., 'wheelset%mz' ([[wheelset_keys]], patch 0), and 'right%NAME' or
   !> 'left%NAME' for a wheel.
   integer function context_get_value(ctx, key, patch, x) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> The name (case-insensitive).
      character(len=*), intent(in) :: key
      !> 0: the main patch; 1 to the number of patches.
      integer, intent(in) :: patch
      !> The value (0 on failure).
      real(wp), intent(out) :: x
      type(error_type), allocatable :: error
      character(len=:), allocatable :: k, group, name
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      integer :: i, wheel
      logical :: numeric
      real(wp) :: totals(size(wheelset_keys))

      x = 0.0_wp
      k = trim(adjustl(to_lower(key)))
      ! An input key (not a sweep's) reads the handle's setting; only numbers can be returned.
      call split_key(k, group, name)
      i = find_variable(group, name)
      if (group == 'sweep') i = 0
      numeric = .false.
      if (i > 0) numeric = variables(i)%kind == k_real .or. variables(i)%kind == k_int
      if (.not. context_usable(ctx, error)) then
         continue
      else if (numeric) then
         ! The handle's current setting (no solve needed), the grid as the preset resolves it
         ! unless given.
         select case (k)
         case ('normal%n_strips')
            normal = normal_options_of(ctx%config)
            x = normal%n_strips
         case ('tangential%n_elements')
            tangential = tangential_options_of(ctx%config)
            x = tangential%n_elements
         case ('kinematics%pitch_rate')
            ! Not given: pure rolling at the handle's speed and nominal radius, as solved.
            x = number_value(ctx%config, group, name)
            if (origin(ctx%config, k) == 'default') x = pure_rolling_pitch_rate( &
               ctx%config%kinematics%v_forward, ctx%config%track%nominal_radius)
         case default
            x = number_value(ctx%config, group, name)
         end select
      else if (i > 0) then
         call fatal_error(error, "value '"//visible(key)//"': not a number (read back only "// &
            'numeric inputs)', stat_invalid_input)
      else if (.not. known_output(k, ctx%is_wheelset)) then
         ! The same answer for a mistyped key whether or not a solve has succeeded.
         call unknown_output(key, error)
      else if (.not. ctx%has_result) then
         call fatal_error(error, "value '"//visible(key)//"': no result yet (the last solve "// &
            'failed or none was made)', stat_usage)
      else if (.not. ctx%is_wheelset) then
         call result_value(ctx%result, k, patch, x, error)
      else if (index(k, 'wheelset%') == 1) then
         i = findloc(wheelset_keys%name, k, 1)
         if (i == 0) then
            call unknown_output(key, error)
         else if (patch /= 0) then
            call fatal_error(error, "value '"//visible(key)//"': the wheelset's total, patch "// &
               str_int(patch)//' given; expected patch 0 (the patches of a wheel: right%NAME, '// &
               'left%NAME)', stat_usage)
         else
            totals = [ctx%wheelset_result%fx, ctx%wheelset_result%fy, &
               ctx%wheelset_result%fz, ctx%wheelset_result%mz]
            x = totals(i)
         end if
      else
         wheel = 0
         if (index(k, 'right%') == 1) wheel = wheel_right
         if (index(k, 'left%') == 1) wheel = wheel_left
         if (wheel == 0) then
            call unknown_output(key, error)
         else
            call result_value(ctx%wheelset_result%wheel(wheel), k(index(k, '%') + 1:), patch, &
               x, error)
         end if
      end if
      stat = context_record(ctx, error)
   end function context_get_value

   !> Whether `key` (lower case) names a result value: of a contact ([[result_value]]'s names
   !> and aliases), or on a wheelset handle `wheelset%NAME` or `right%NAME`, `left%NAME`.
   pure logical function known_output(key, is_wheelset) result(known)
      character(len=*), intent(in) :: key
      logical, intent(in) :: is_wheelset
      if (.not. is_wheelset) then
         known = contact_output(key)
      else if (index(key, 'wheelset%') == 1) then
         known = any(wheelset_keys%name == key)
      else if (index(key, 'right%') == 1 .or. index(key, 'left%') == 1) then
         known = contact_output(key(index(key, '%') + 1:))
      else
         known = .false.
      end if
   contains
      pure logical function contact_output(name)
         character(len=*), intent(in) :: name
         character(len=:), allocatable :: alias
         integer :: i
         alias = name
         i = findloc(summary_aliases(1, :), alias, 1)
         if (i > 0) alias = trim(summary_aliases(2, i))
         contact_output = alias == climbing_key .or. any(output_keys%name == alias) .or. &
            find_patch_column(alias, .false.) > 0 .or. find_wheel_column(alias) > 0
      end function contact_output
   end function known_output

   !> Value `key` of patch `patch` (0: the main one) of a result.
   subroutine result_value(result, name, patch, x, error)
      type(contact_result_type), intent(in) :: result
      character(len=*), intent(in) :: name
      integer, intent(in) :: patch
      real(wp), intent(out) :: x
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: values(kinematic_value_count)
      character(len=:), allocatable :: key
      integer :: i, k, w
      x = 0.0_wp
      key = name
      i = findloc(summary_aliases(1, :), key, 1)
      if (i > 0) key = trim(summary_aliases(2, i))
      i = findloc(output_keys%name, key, 1)
      ! A per-patch value beyond the frozen flat layout: by name from the column table.
      k = 0
      if (i == 0) k = find_patch_column(key, .false.)
      ! A value of the wheel's joined contact (one per wheel, patch 0).
      w = 0
      if (i == 0 .and. k == 0) w = find_wheel_column(key)
      if (key == climbing_key) then
         ! The wheel's flag, 1 or 0 (contact_result_type%climbing).
         if (patch /= 0) then
            call fatal_error(error, 'patch '//str_int(patch)//': '//key//' is a value of the '// &
               'wheel (its main patch''s contact); expected patch 0', stat_usage)
         else
            x = merge(1.0_wp, 0.0_wp, result%climbing)
         end if
      else if (w > 0) then
         if (patch /= 0) then
            call fatal_error(error, 'patch '//str_int(patch)//': '//key//' is a value of the '// &
               'wheel''s joined contact; expected patch 0', stat_usage)
         else
            x = wheel_value(wheel_contact_of(result%wheel), w)
         end if
      else if (i == 0 .and. k == 0) then
         call unknown_output(key, error)
      else if (patch < 0 .or. patch > min(result%n_patches, max_patches)) then
         call fatal_error(error, 'patch '//str_int(patch)//': expected 0 (the main patch) '// &
            'to '//str_int(result%n_patches)//' (the patches of the last solve)', stat_usage)
      else
         if (k > 0 .and. patch == 0) then
            x = patch_value(result%main, k)
         else if (k > 0) then
            x = patch_value(result%patch(patch), k)
         else if (patch == 0) then
            call kinematic_values(result, values)
            x = values(output_keys(i)%index)
         else
            call kinematic_values(result, values, patch)
            x = values(output_keys(i)%index)
         end if
      end if
   end subroutine result_value

   subroutine unknown_output(key, error)
      character(len=*), intent(in) :: key
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: names
      integer :: i
      names = ''
      do i = 1, size(output_keys)
         names = names//trim(output_keys(i)%name)//merge(', ', '  ', i < size(output_keys))
      end do
      do i = 1, size(patch_columns)
         if (any(output_keys%name == patch_columns(i)%name)) cycle
         names = trim(names)//', '//trim(patch_columns(i)%name)
      end do
      do i = 1, size(wheel_columns)
         names = trim(names)//', '//trim(wheel_columns(i)%name)
      end do
      names = trim(names)//', '//climbing_key
      call fatal_error(error, "value '"//visible(key)//"': unknown; expected one of "// &
         trim(names)//" (a wheelset handle: wheelset%fx, wheelset%fy, wheelset%fz, "// &
         "wheelset%mz, right%NAME, left%NAME)", stat_invalid_input)
   end subroutine unknown_output

   !> One element field of patch `patch` of the last solve by name ([[field_keys]]), an array
   !> (nx, ny) as context_fields gives it (nx, ny those of context_field_size).
   integer function context_get_field(ctx, key, patch, nx, ny, a) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> The field name (case-insensitive).
      character(len=*), intent(in) :: key
      !> Patch index, 1 to the number of patches of the last result; the field sizes.
      integer, intent(in) :: patch, nx, ny
      !> The field (not written on failure).
      real(wp), intent(inout) :: a(nx, ny)
      type(error_type), allocatable :: error
      real(wp), allocatable :: f(:, :, :)
      integer, allocatable :: state(:, :)
      integer :: i

      i = findloc(field_keys%name, trim(adjustl(to_lower(key))), 1)
      if (i == 0) then
         call fatal_error(error, "field '"//visible(key)//"': unknown; expected x, y, area, "// &
            'pn, px, py, slip or state', stat_invalid_input)
      else
         ! The sizes first: the caller's array may be smaller than nx·ny (nothing is written
         ! then), and nothing of a wrong size is allocated.
         call context_check_field_arrays(ctx, patch, nx, ny, error)
      end if
      if (allocated(error)) then
         stat = context_record(ctx, error)
         return
      end if
      allocate (f(max(nx, 0), max(ny, 0), 7), state(max(nx, 0), max(ny, 0)))
      stat = context_fields(ctx, patch, nx, ny, f(:, :, 1), f(:, :, 2), f(:, :, 3), &
         f(:, :, 4), f(:, :, 5), f(:, :, 6), f(:, :, 7), state)
      if (stat /= 0) return
      if (i <= 7) then
         a = f(:, :, i)
      else
         a = real(state, wp)
      end if
   end function context_get_field

   !> Wheel `side` (1 right, −1 left) of the last wheelset solve in the kinematic layout
   !> (shcontact_api_values): its main patch (patch 0) or patch `patch`, with the wheel's counts
   !> and totals (its own side frame).
   integer function context_wheel(ctx, side, patch, values) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> 1 right, −1 left.
      integer, intent(in) :: side, patch
      !> The values (zero on failure).
      real(wp), intent(out) :: values(kinematic_value_count)
      type(error_type), allocatable :: error
      integer :: wheel

      values = 0.0_wp
      wheel = merge(wheel_right, wheel_left, side == 1)
      if (.not. context_usable(ctx, error)) then
         continue
      else if (.not. ctx%is_wheelset) then
         call fatal_error(error, 'a one-wheel handle: the wheels of a wheelset are read from '// &
            'a wheelset handle (shcontact_create_wheelset)', stat_usage)
      else if (side /= 1 .and. side /= -1) then
         call fatal_error(error, 'wheel side = '//str_int(side)//': expected 1 (right) or '// &
            '-1 (left)', stat_usage)
      else if (.not. ctx%has_result) then
         call fatal_error(error, 'wheel values: no result yet (the last solve failed or none '// &
            'was made)', stat_usage)
      else
         associate (r => ctx%wheelset_result%wheel(wheel))
            if (patch < 0 .or. patch > min(r%n_patches, max_patches)) then
               call fatal_error(error, 'patch '//str_int(patch)//': expected 0 (the main '// &
                  'patch) to '//str_int(r%n_patches)//' (the patches of the last solve)', &
                  stat_usage)
            else if (patch == 0) then
               call kinematic_values(r, values)
            else
               call kinematic_values(r, values, patch)
            end if
         end associate
      end if
      stat = context_record(ctx, error)
   end function context_wheel

end module shcontact_api_keyed
