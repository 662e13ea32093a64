!> The settings of a flat-interface handle (C API, Fortran 77 entry points) kept as the app's
!> configuration (shcontact_input_config's case_config_type), so that a key `group%variable` and
!> its value take the namelist's one path: [[set_config_value]] hands `group%variable=value` to
!> the namelist reader's single-assignment entry (apply_override → apply_assignment →
!> read_group_variable), and [[library_setup]] translates the configuration into the
!> library's objects (track, contact-search, normal and tangential options, material) as the
!> app does. Every variable of the namelist's variable table is a key; what a handle does with
!> it depends on its group ([[key_use]]): the solver's data, the state of a keyed solve, the
!> fields switch, or (profile files, output file, sweep) given at creation or app only.
module shcontact_api_settings
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_get_halting_mode, &
      ieee_set_halting_mode, ieee_get_flag, ieee_set_flag
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: to_lower, visible, control_characters
   use shcontact_geometry_track, only: track_type, side_right, side_left
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_input_config, only: case_config_type, case_point_type, apply_override, &
      normal_options_of, tangential_options_of, load_mode_force, load_mode_approach, &
      load_mode_shared
   use shcontact_input_config_types, only: set_origin, track_of, contact_options_of
   use shcontact_input_config_variables, only: variables, find_variable, &
      join_words, k_real, k_real_list, key_use, key_solver, key_state, key_fields, key_creation, &
      key_app
   use shcontact_api_solver, only: contact_load_type, load_normal_force, load_approach, &
      load_vertical_force, load_shared_force
   implicit none
   private

   public :: library_setup_type, library_setup, config_load, point_load, config_state
   public :: key_use, key_solver, key_state, key_fields, key_creation, key_app
   public :: set_config_value, split_key, handle_key_list

   !> The library's objects of a configuration.
   type :: library_setup_type
      !> Track and wheelset dimensions.
      type(track_type) :: track
      !> Contact-search options (smoothing, B clamp, longitudinal curvature).
      type(contact_options_type) :: contact_options
      !> Normal options.
      type(normal_options_type) :: normal
      !> Tangential options (bound and spin model those of the configuration).
      type(tangential_options_type) :: tangential
      !> G, ν, μ.
      type(material_type) :: material
      !> side_right or side_left.
      integer :: side = side_right
   end type library_setup_type

contains

   !> The library's objects of a configuration: track, contact-search options, normal and
   !> tangential options (bound and spin model those of the configuration), material, side.
   !> The one translation (each part a function of shcontact_input_config_types, beside the
   !> configuration's fields): the handles and the program's runner (`prepare_run`) call it.
   subroutine library_setup(config, setup, error)
      !> The configuration (choices in lower case, as the namelist reader stores them).
      type(case_config_type), intent(in) :: config
      !> The objects.
      type(library_setup_type), intent(out) :: setup
      !> Set for a choice the library does not know.
      type(error_type), allocatable, intent(out) :: error

      setup%track = track_of(config)
      setup%contact_options = contact_options_of(config)
      setup%side = config%track%side
      setup%normal = normal_options_of(config)
      setup%tangential = tangential_options_of(config)
      setup%material = config%material
   end subroutine library_setup

   !> The load of a case: `&load mode` ('force', 'approach', 'vertical') and its value.
   pure function config_load(config, point) result(load)
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> The case inputs.
      type(case_point_type), intent(in) :: point
      type(contact_load_type) :: load
      load = point_load(config%load%mode, point)
   end function config_load

   !> The load of a case for load mode `mode` (load_mode_force, load_mode_approach,
   !> load_mode_vertical or load_mode_shared: the configuration's `&load mode`) and the case's
   !> value; the one translation of the load that
   !> the handles and the program's runner (shcontact_case_runner) share.
   pure function point_load(mode, point) result(load)
      !> `&load mode`.
      integer, intent(in) :: mode
      !> The case inputs.
      type(case_point_type), intent(in) :: point
      type(contact_load_type) :: load
      select case (mode)
      case (load_mode_force)
         load = contact_load_type(load_normal_force, point%normal_force)
      case (load_mode_approach)
         load = contact_load_type(load_approach, point%approach)
      case (load_mode_shared)
         load = contact_load_type(load_shared_force, point%normal_force)
      case default
         load = contact_load_type(load_vertical_force, point%vertical_force)
      end select
   end function point_load

   !> The wheelset state of a case (track frame; the pitch rate resolved by the configuration);
   !> the program's runner takes it as its `kinematic_state`.
   pure function config_state(point) result(state)
      !> The case inputs.
      type(case_point_type), intent(in) :: point
      type(wheelset_state_type) :: state
      state = wheelset_state_type(y_ws=point%t_y, yaw=point%yaw, roll=point%roll, &
         v_forward=point%v_forward, v_lateral=point%v_lateral, v_vertical=point%v_vertical, &
         roll_rate=point%roll_rate, yaw_rate=point%yaw_rate, pitch_rate=point%pitch_rate)
   end function config_state

   !> Group and variable of a key `group%variable` (lower case, blanks removed); both '' when
   !> the key has no '%'.
   pure subroutine split_key(key, group, name)
      !> The key.
      character(len=*), intent(in) :: key
      !> Its group and variable.
      character(len=:), allocatable, intent(out) :: group, name
      character(len=:), allocatable :: k
      integer :: i
      k = trim(adjustl(to_lower(key)))
      i = index(k, '%')
      group = ''
      name = ''
      if (i < 2) return
      group = trim(k(1:i - 1))
      name = trim(adjustl(k(i + 1:)))
   end subroutine split_key

   !> Set `group%variable` = value (text as on the app's command line `--set`, strings with or
   !> without quotes) in a configuration through the namelist's single-assignment reader. A
   !> number must be finite. The configuration is unchanged on error; the message names the key.
   subroutine set_config_value(config, key, value, error)
      !> The configuration.
      type(case_config_type), intent(inout) :: config
      !> The key `group%variable` (case-insensitive) and the value.
      character(len=*), intent(in) :: key, value
      !> Set for an unknown key or a bad value (stat_invalid_input).
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: group, name, prefix
      type(case_config_type) :: trial
      integer :: iv

      call split_key(key, group, name)
      iv = find_variable(group, name)
      if (iv == 0 .or. group == 'sweep') then
         call fatal_error(error, "option '"//trim(visible(key))//"': unknown; expected "// &
            handle_key_list(group)//' (doc/api.md, "Option keys")', stat_invalid_input)
         return
      end if
      prefix = 'option '//group//'%'//name
      if (group == 'kinematics' .and. name == 'pitch_rate' .and. &
         to_lower(trim(adjustl(value))) == 'pure rolling') then
         ! Back to its default, as the option list names it: not given, pure rolling at each
         ! state's forward speed.
         config%kinematics%pitch_rate = variables(iv)%default
         call set_origin(config, 'kinematics%pitch_rate', 'default')
         return
      end if
      if (scan(value, control_characters) > 0) then
         call fatal_error(error, prefix//" = '"//visible(value)// &
            "': a control character in the value", stat_invalid_input)
         return
      end if
      if (variables(iv)%kind == k_real .or. variables(iv)%kind == k_real_list) then
         call check_number(prefix, value, error)
         if (allocated(error)) return
      end if
      trial = config
      call apply_override(trial, group//'%'//name//'='//value, error)
      if (allocated(error)) then
         call reword(error%message, 'command line --set '//group//'%'//name//'='// &
            trim(adjustl(value)), prefix)
         error%stat = stat_invalid_input
         return
      end if
      ! Messages of a later check (context_solve_state) name the option, not a command line.
      call set_origin(trial, group//'%'//name, prefix)
      config = trial
   end subroutine set_config_value

   !> A finite number (an overflow such as 1e309 is refused, never trapped).
   subroutine check_number(prefix, text, error)
      character(len=*), intent(in) :: prefix, text
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      real(wp) :: x
      logical :: halting, overflow
      call ieee_get_halting_mode(ieee_overflow, halting)
      call ieee_set_halting_mode(ieee_overflow, .false.)
      call ieee_set_flag(ieee_overflow, .false.)
      read (text, *, iostat=stat) x
      call ieee_get_flag(ieee_overflow, overflow)
      call ieee_set_flag(ieee_overflow, .false.)
      call ieee_set_halting_mode(ieee_overflow, halting)
      if (stat == 0) then
         if (overflow .or. .not. ieee_is_finite(x)) stat = 1
      end if
      if (stat /= 0) call fatal_error(error, prefix//" = '"//trim(text)// &
         "': expected a finite number", stat_invalid_input)
   end subroutine check_number

   !> Replace a leading `old` of a message by `new`.
   pure subroutine reword(message, old, new)
      character(len=:), allocatable, intent(inout) :: message
      character(len=*), intent(in) :: old, new
      if (index(message, old) == 1) message = new//message(len(old) + 1:)
   end subroutine reword

   !> The keys a handle accepts (every namelist variable but the sweep's), comma-separated: those
   !> of `group` when it has any, else the groups.
   pure function handle_key_list(group) result(text)
      !> The group of the key given.
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: text
      integer :: i
      text = ''
      if (group /= 'sweep' .and. any(variables%group == group)) then
         do i = 1, size(variables)
            if (variables(i)%group /= group) cycle
            if (len(text) > 0) text = text//', '
            text = text//trim(variables(i)%group)//'%'//trim(variables(i)%name)
         end do
         text = 'one of '//text
      else
         do i = 1, size(variables)
            if (variables(i)%group == 'sweep') cycle
            if (index(text, ' '//trim(variables(i)%group)//'%') > 0) cycle
            text = text//' '//trim(variables(i)%group)//'%...'
         end do
         text = 'group%variable, group one of'//text
      end if
   end function handle_key_list

end module shcontact_api_settings
