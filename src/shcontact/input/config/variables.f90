!> The registry of the namelist groups (issue 26): the variable table of shcontact_core_ranges
!> (every variable's group, name, kind, units, help, and a number's default and range), the
!> allowed values of the choice variables ([[variable_choices]], from the layers' option
!> registries and shcontact_input_config_choices), what the flat interfaces do with each
!> variable ([[key_use]]), and the lookups and phrases built on them; test `registry` checks
!> the configuration's defaults, the library's, doc/app.md's tables and the headers' option
!> lists against them.
module shcontact_input_config_variables
   use shcontact_core_choices, only: choice_type
   use shcontact_core_ranges, only: variable_info_type, variables, has_range, k_real, k_int, &
      k_string, k_logical, k_real_list, k_string_list, k_choice
   use shcontact_input_config_limits, only: path_len, name_len
   use shcontact_normal_option_registry, only: normal_option_choices => option_choices
   use shcontact_tangential_option_registry, only: tangential_option_choices => option_choices
   use shcontact_pipeline_preset, only: preset_choices
   use shcontact_input_config_choices, only: side_choices, kinematics_mode_choices, &
      load_mode_choices, curvature_choices, strip_table_choices, precision_choices, sweep_mode_choices, &
      format_choices, mirror_choices, field_choices
   implicit none
   private

   public :: variable_info_type, variables, group_names, find_variable
   public :: k_real, k_int, k_string, k_logical, k_real_list, k_string_list, k_choice
   public :: type_phrase, string_capacity, is_choice, suggestion, group_variable_list, join_words
   public :: variable_choices, header_option_keys
   public :: key_use, key_solver, key_state, key_fields, key_creation, key_app

   !> What a flat-interface handle (C API, Fortran 77) does with a variable ([[key_use]]): the
   !> solver's data (track, material, smoothing, normal and tangential options), the state of a
   !> keyed solve (position, kinematics, load, creepage), the fields switch (output%fields),
   !> given at creation (profile files, track%side), or only the app's (output file, sweep).
   integer, parameter :: key_solver = 1, key_state = 2, key_fields = 3, key_creation = 4, &
      key_app = 5

   character(len=*), parameter :: group_names(*) = [character(len=12) :: 'profiles', 'track', &
      'position', 'kinematics', 'material', 'load', 'creepage', 'normal', 'tangential', &
      'output', 'sweep']

contains

   !> What a handle does with variable `name` of group `group` (key_solver, key_state,
   !> key_fields, key_creation, key_app).
   pure integer function key_use(group, name)
      !> Group and variable (lower case).
      character(len=*), intent(in) :: group, name
      select case (group)
      case ('material', 'normal', 'tangential')
         key_use = key_solver
      case ('track')
         key_use = merge(key_creation, key_solver, name == 'side')
      case ('profiles')
         key_use = merge(key_solver, key_creation, index(name, '_smoothing') > 0)
      case ('position', 'kinematics', 'load', 'creepage')
         key_use = key_state
      case ('output')
         key_use = merge(key_fields, key_app, name == 'fields')
      case default
         key_use = key_app
      end select
   end function key_use

   !> The options listed in the headers' option lists (include/shcontact.h,
   !> include/shcontact.fi), "group%variable" in the table's order: every choice and every
   !> number with a range that the option setters of the C and Fortran 77 interfaces take as
   !> the solver's data or a keyed solve's state ([[key_use]]).
   pure function header_option_keys() result(keys)
      character(len=37), allocatable :: keys(:)
      integer :: i
      allocate (keys(0))
      do i = 1, size(variables)
         if (.not. (variables(i)%kind == k_choice .or. has_range(variables(i)))) cycle
         if (key_use(trim(variables(i)%group), trim(variables(i)%name)) /= key_solver .and. &
             key_use(trim(variables(i)%group), trim(variables(i)%name)) /= key_state) cycle
         keys = [character(len=37) :: keys, trim(variables(i)%group)//'%'//variables(i)%name]
      end do
   end function header_option_keys

   !> Index of a variable in [[variables]], 0 when unknown.
   pure integer function find_variable(group, name)
      character(len=*), intent(in) :: group, name
      integer :: i
      find_variable = 0
      do i = 1, size(variables)
         if (variables(i)%group == group .and. variables(i)%name == name) then
            find_variable = i
            return
         end if
      end do
   end function find_variable

   !> The allowed values of a choice variable (`k_choice`, or a string or string list with a
   !> fixed set of values); none for any other variable. A `&sweep` list of choices takes the
   !> choices of the variable it sweeps.
   pure function variable_choices(group, name) result(choices)
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      type(choice_type), allocatable :: choices(:)
      select case (trim(group)//'%'//trim(name))
      case ('profiles%wheel_format', 'profiles%rail_format')
         choices = format_choices
      case ('profiles%wheel_mirror_y', 'profiles%wheel_mirror_z', 'profiles%rail_mirror_y', &
            'profiles%rail_mirror_z')
         choices = mirror_choices
      case ('track%side')
         choices = side_choices
      case ('kinematics%mode')
         choices = kinematics_mode_choices
      case ('load%mode')
         choices = load_mode_choices
      case ('normal%longitudinal_curvature')
         choices = curvature_choices
      case ('normal%strip_tables')
         choices = strip_table_choices
      case ('normal%preset')
         choices = preset_choices
      case ('output%fields')
         choices = field_choices
      case ('output%precision')
         choices = precision_choices
      case ('sweep%mode')
         choices = sweep_mode_choices
      case default
         ! The solvers' own choices come from their layers' registries (a `&sweep` axis of a
         ! tangential choice takes the choices of the variable it sweeps); none for the rest.
         select case (group)
         case ('normal')
            choices = normal_option_choices(name)
         case ('tangential', 'sweep')
            choices = tangential_option_choices(name)
         case default
            allocate (choices(0))
         end select
      end select
   end function variable_choices

   !> Words that describe the expected type.
   pure function type_phrase(v) result(p)
      type(variable_info_type), intent(in) :: v
      character(len=:), allocatable :: p
      select case (v%kind)
      case (k_real)
         p = 'a real number'
      case (k_int)
         p = 'an integer'
      case (k_logical)
         p = 'a logical (.true. or .false.)'
      case (k_string)
         p = 'a quoted string'
      case (k_choice)
         p = 'a quoted string'
      case (k_real_list)
         p = 'a list of real numbers'
      case default
         p = 'a list of quoted strings'
      end select
      if (len_trim(v%units) > 0 .and. v%units /= '1') p = p//' in '//trim(v%units)
   end function type_phrase

   pure integer function string_capacity(v)
      type(variable_info_type), intent(in) :: v
      string_capacity = name_len
      if (v%name == 'wheel' .or. v%name == 'rail' .or. v%name == 'file') string_capacity = path_len
   end function string_capacity

   !> True for a string variable that names a choice (every string but the file names): its
   !> values are case-insensitive and stored in lower case.
   pure logical function is_choice(v)
      type(variable_info_type), intent(in) :: v
      is_choice = v%kind == k_choice .or. ((v%kind == k_string .or. v%kind == k_string_list) &
         .and. string_capacity(v) == name_len)
   end function is_choice

   !> " (it belongs to &position)" when other groups have a variable of that name, else
   !> " (did you mean X?)" for a close variable name of the group.
   pure function suggestion(group, name) result(s)
      character(len=*), intent(in) :: group, name
      character(len=:), allocatable :: s
      integer :: i, best, d, dbest
      s = ''
      do i = 1, size(variables)
         if (variables(i)%group == group .or. trim(variables(i)%name) /= name) cycle
         if (len(s) == 0) then
            s = ' (it belongs to &'//trim(variables(i)%group)
         else
            s = s//', &'//trim(variables(i)%group)
         end if
      end do
      if (len(s) > 0) then
         s = s//')'
         return
      end if
      best = 0
      dbest = 3
      do i = 1, size(variables)
         if (variables(i)%group /= group) cycle
         d = edit_distance(name, trim(variables(i)%name))
         if (d < dbest) then
            dbest = d
            best = i
         end if
      end do
      if (best > 0) s = ' (did you mean "'//trim(variables(best)%name)//'"?)'
   end function suggestion

   !> Levenshtein distance (short names only).
   pure integer function edit_distance(a, b)
      character(len=*), intent(in) :: a, b
      integer :: d(0:len(a), 0:len(b)), i, j
      do i = 0, len(a)
         d(i, 0) = i
      end do
      do j = 0, len(b)
         d(0, j) = j
      end do
      do j = 1, len(b)
         do i = 1, len(a)
            d(i, j) = min(d(i - 1, j) + 1, d(i, j - 1) + 1, &
               d(i - 1, j - 1) + merge(0, 1, a(i:i) == b(j:j)))
         end do
      end do
      edit_distance = d(len(a), len(b))
   end function edit_distance

   pure function group_variable_list(group) result(s)
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(variables)
         if (variables(i)%group /= group) cycle
         if (len(s) > 0) s = s//', '
         s = s//trim(variables(i)%name)
      end do
   end function group_variable_list

   pure function join_words(words, prefix, quote) result(s)
      character(len=*), intent(in) :: words(:), prefix, quote
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(words)
         if (i > 1) s = s//', '
         s = s//quote//prefix//trim(words(i))//quote
      end do
   end function join_words

end module shcontact_input_config_variables
