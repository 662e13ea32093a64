!> One assignment applied to the configuration: checked against the variable table (known
!> name, number of values, string lengths), then read through a one-assignment namelist on an
!> internal file, so that the compiler's namelist reader converts the value and an error names
!> the file, the line, the group, the variable, the value found and what is allowed.
module shcontact_input_config_assign
   use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_get_halting_mode, &
      ieee_set_halting_mode, ieee_get_flag, ieee_set_flag
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: to_lower, str_int
   use shcontact_core_files, only: join_path
   use shcontact_input_config_limits, only: name_len, max_sweep_values, max_label_values, &
      max_fields
   use shcontact_input_config_sweep, only: sweep_axis_type, sweep_config_type, axis_index
   use shcontact_core_choices, only: choice_type, choice_code, choice_list
   use shcontact_input_config_types, only: case_config_type, profiles_config_type, &
      track_config_type, position_config_type, kinematics_config_type, load_config_type, &
      creepage_config_type, normal_config_type, tangential_config_type, output_config_type, &
      set_origin, set_choice_value
   use shcontact_input_config_variables, only: variables, find_variable, type_phrase, &
      string_capacity, suggestion, group_variable_list, is_choice, variable_choices, k_int, &
      k_string, k_string_list, k_real_list, k_choice
   use shcontact_input_config_parser, only: assignment_type
   implicit none
   private

   public :: apply_assignment, read_group_variable, stat_unknown_choice

   !> `stat` of [[read_group_variable]] for a value that is none of the variable's choices
   !> (`msg` then says which are allowed); any other non-zero `stat` is the namelist reader's.
   integer, parameter :: stat_unknown_choice = 900

   !> Sentinel of unset sweep-list entries.
   real(wp), parameter :: unset = huge(1.0_wp)

contains

   !> Check one assignment against the variable table, read it through a one-assignment
   !> namelist, and record where it came from.
   subroutine apply_assignment(config, a, base_dir, error)
      type(case_config_type), intent(inout) :: config
      type(assignment_type), intent(in) :: a
      !> Directory of the case file, for relative profile names.
      character(len=*), intent(in) :: base_dir
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: value
      character(len=256) :: msg
      integer :: iv, stat, capacity
      logical :: halting, overflow

      if (index(a%name, '(') > 0 .or. index(a%name, '%') > 0) then
         call fatal_error(error, a%where//': &'//a%group//' '//a%name//': give the whole '// &
            'variable, e.g. '//a%name(1:scan(a%name, '(%') - 1)//' = v1, v2, ...')
         return
      end if
      iv = find_variable(a%group, a%name)
      if (iv == 0) then
         call fatal_error(error, a%where//': &'//a%group//': unknown variable "'//a%name// &
            '"'//suggestion(a%group, a%name)//'; the variables of &'//a%group//' are '// &
            group_variable_list(a%group))
         return
      end if
      select case (variables(iv)%kind)
      case (k_real_list)
         capacity = max_sweep_values
      case (k_string_list)
         capacity = max_label_values
         if (a%group == 'output') capacity = max_fields
      case default
         capacity = 1
      end select
      if (a%n_items > capacity) then
         if (capacity == 1) then
            call fatal_error(error, value_context(a)//': expected one value ('// &
               type_phrase(variables(iv))//'), found '//str_int(a%n_items))
         else
            call fatal_error(error, value_context(a)//': at most '//str_int(capacity)// &
               ' values allowed, found '//str_int(a%n_items))
         end if
         return
      end if
      if (a%longest_string > string_capacity(variables(iv))) then
         call fatal_error(error, value_context(a)//': longer than '// &
            str_int(string_capacity(variables(iv)))//' characters')
         return
      end if

      ! Choices are case-insensitive: stored in lower case.
      value = a%value
      if (is_choice(variables(iv))) value = to_lower(a%value)
      msg = ''
      ! A number beyond the double range (1e309) overflows inside the run-time library's
      ! conversion: reported below, never trapped (a debug build halts on overflow).
      call ieee_get_halting_mode(ieee_overflow, halting)
      call ieee_set_halting_mode(ieee_overflow, .false.)
      call ieee_set_flag(ieee_overflow, .false.)
      if (variables(iv)%kind == k_choice .and. scan(adjustl(value), "'"//'"') /= 1) then
         ! A case file quotes every string (the option setters may leave a choice unquoted).
         stat = 1
      else if (a%group == 'sweep' .and. variables(iv)%kind /= k_choice) then
         call read_sweep(config%sweep, a%name, variables(iv)%kind, value, stat, msg)
      else
         call read_group_variable(config, a%group, a%name, value, stat, msg)
         if (stat == 0 .and. a%group == 'profiles') &
            call resolve_profile_path(config%profiles, a%name, base_dir)
      end if
      call ieee_get_flag(ieee_overflow, overflow)
      call ieee_set_flag(ieee_overflow, .false.)
      call ieee_set_halting_mode(ieee_overflow, halting)
      if (overflow) then
         call fatal_error(error, value_context(a)//': a number beyond the range of double '// &
            'precision (|x| < 1.8e308); expected '//type_phrase(variables(iv)))
         return
      end if
      if (stat == stat_unknown_choice) then
         call fatal_error(error, a%where//': &'//a%group//' '//a%name//' = '//trim(msg))
         return
      else if (stat /= 0) then
         call fatal_error(error, value_context(a)//': expected '// &
            type_phrase(variables(iv))//hint(variables(iv)%kind, a%value))
         return
      end if
      call set_origin(config, a%group//'%'//a%name, a%where)
   end subroutine apply_assignment

   !> "file:line: &group name = value".
   pure function value_context(a) result(c)
      type(assignment_type), intent(in) :: a
      character(len=:), allocatable :: c
      integer, parameter :: shown = 200
      c = a%where//': &'//a%group//' '//a%name//' = '
      if (len(a%value) > shown) then
         c = c//a%value(1:shown)//' ... ('//str_int(len(a%value))//' characters)'
      else
         c = c//a%value
      end if
   end function value_context

   !> A hint for the most common slip of each kind.
   pure function hint(kind, value) result(h)
      integer, intent(in) :: kind
      character(len=*), intent(in) :: value
      character(len=:), allocatable :: h
      h = ''
      if ((kind == k_string .or. kind == k_choice .or. kind == k_string_list) .and. &
          index(value, "'") == 0 .and. index(value, '"') == 0) h = " (strings are quoted: 'text')"
   end function hint

   !> Relative profile file names are taken from the directory of the case file.
   subroutine resolve_profile_path(profiles, name, base_dir)
      type(profiles_config_type), intent(inout) :: profiles
      character(len=*), intent(in) :: name, base_dir
      select case (name)
      case ('wheel')
         if (index(to_lower(profiles%wheel), 'builtin:') /= 1) profiles%wheel = join_path(base_dir, &
            trim(profiles%wheel))
      case ('rail')
         if (index(to_lower(profiles%rail), 'builtin:') /= 1) profiles%rail = join_path(base_dir, &
            trim(profiles%rail))
      end select
   end subroutine resolve_profile_path

   !> Read `group%name = value` (every group but `&sweep`, and the `&sweep mode`) through a
   !> one-assignment namelist whose objects are copies of the groups, written back only when the
   !> read succeeds. A choice variable (kind `k_choice`) is read as a string (quoted, or the
   !> unquoted text itself) and stored as the code of the registry's choice of that name
   !> (case-insensitive, '_' read as '-'); an unknown name gives `stat` = [[stat_unknown_choice]]. The one entry point that sets a case-file
   !> variable from text: the case files, `--set` and the option setters of the C and Fortran 77
   !> interfaces all go through it. Ranges are checked afterwards (validate_config), not here.
   subroutine read_group_variable(config, group, name, value, stat, msg)
      type(case_config_type), intent(inout) :: config
      !> Group and variable, known to the variable table.
      character(len=*), intent(in) :: group, name
      !> The value as namelist text (strings quoted).
      character(len=*), intent(in) :: value
      !> 0 on success; [[stat_unknown_choice]] or the namelist reader's iostat on failure.
      integer, intent(out) :: stat
      !> What went wrong (unchanged on success).
      character(len=*), intent(inout) :: msg
      type(profiles_config_type) :: profiles
      type(track_config_type) :: track
      type(position_config_type) :: position
      type(kinematics_config_type) :: kinematics
      type(material_type) :: material
      type(load_config_type) :: load
      type(creepage_config_type) :: creepage
      type(normal_config_type) :: normal
      type(tangential_config_type) :: tangential
      type(output_config_type) :: output
      character(len=:), allocatable :: text
      integer :: iv
      namelist /groups/ profiles, track, position, kinematics, material, load, creepage, normal, &
         tangential, output

      iv = find_variable(group, name)
      if (iv > 0) then
         if (variables(iv)%kind == k_choice) then
            call read_choice(config, group, name, value, stat, msg)
            return
         end if
      end if
      profiles = config%profiles; track = config%track; position = config%position
      kinematics = config%kinematics; material = config%material; load = config%load
      creepage = config%creepage; normal = config%normal; tangential = config%tangential
      output = config%output
      ! A list replaces the whole list.
      if (group == 'output' .and. name == 'fields') output%fields = ''
      text = '&groups '//group//'%'//name//' = '//value//' /'
      read (text, nml=groups, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      config%profiles = profiles; config%track = track; config%position = position
      config%kinematics = kinematics; config%material = material; config%load = load
      config%creepage = creepage; config%normal = normal; config%tangential = tangential
      config%output = output
   end subroutine read_group_variable

   !> Read a choice as a namelist string and store its code (see [[read_group_variable]]).
   subroutine read_choice(config, group, name, value, stat, msg)
      type(case_config_type), intent(inout) :: config
      !> A choice variable (kind `k_choice`).
      character(len=*), intent(in) :: group, name
      !> The value as namelist text.
      character(len=*), intent(in) :: value
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: choice
      character(len=:), allocatable :: text
      type(choice_type), allocatable :: choices(:)
      integer :: code
      namelist /choices_nml/ choice

      choice = ''
      text = trim(adjustl(value))
      if (index("'"//'"', text(1:min(1, len(text)))) == 0 .or. len(text) == 0) then
         ! Unquoted (an option setter's value): the text itself.
         stat = 0
         choice = text
      else
         text = '&choices_nml choice = '//text//' /'
         read (text, nml=choices_nml, iostat=stat, iomsg=msg)
         if (stat /= 0) return
      end if
      choices = variable_choices(group, name)
      code = choice_code(choices, choice)
      if (code == 0) then
         stat = stat_unknown_choice
         msg = "'"//trim(choice)//"' is not allowed; expected one of "//choice_list(choices)
         return
      end if
      call set_choice_value(config, group, name, code)
   end subroutine read_choice

   !> Read one `&sweep` variable into a namelist object of its kind (a list gets room for
   !> every value and starts unset, so that a list replaces the whole list) and store it: the
   !> mode, an axis's values or labels, or its `_points`.
   subroutine read_sweep(g, name, kind, value, stat, msg)
      type(sweep_config_type), intent(inout) :: g
      !> Variable name, known to the variable table.
      character(len=*), intent(in) :: name
      !> Its kind (k_int, k_real_list or k_string_list).
      integer, intent(in) :: kind
      !> The value as namelist text.
      character(len=*), intent(in) :: value
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: labels(max_label_values)
      real(wp), allocatable :: values(:)
      integer :: points
      character(len=:), allocatable :: object, text
      namelist /sweep/ labels, values, points

      labels = ''
      allocate (values(merge(max_sweep_values, 0, kind == k_real_list)), source=unset)
      points = 0
      select case (kind)
      case (k_real_list); object = 'values'
      case (k_string_list); object = 'labels'
      case default; object = 'points'
      end select
      text = '&sweep '//object//' = '//value//' /'
      read (text, nml=sweep, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      select case (kind)
      case (k_real_list)
         call store_values(g%axes(axis_index(name)), values, stat, msg)
      case (k_string_list)
         call store_labels(g%axes(axis_index(name)), labels)
      case default
         g%axes(axis_index(name(1:index(name, '_points') - 1)))%points = points
      end select
   end subroutine read_sweep

   !> Keep the leading set values of a sweep list; a gap (null value) is an error.
   subroutine store_values(axis, values, stat, msg)
      type(sweep_axis_type), intent(inout) :: axis
      real(wp), intent(in) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      integer :: n
      n = 0
      do while (n < size(values))
         if (values(n + 1) == unset) exit
         n = n + 1
      end do
      stat = 0
      if (any(values(n + 1:) /= unset)) then
         stat = 1
         msg = 'a value is missing in the list'
         return
      end if
      axis%given = values(1:n)
      axis%is_label = .false.
   end subroutine store_values

   subroutine store_labels(axis, labels)
      type(sweep_axis_type), intent(inout) :: axis
      character(len=*), intent(in) :: labels(:)
      integer :: i, n
      n = count(len_trim(labels) > 0)
      ! A list given again replaces the whole list (doc/app.md, "Repeated variables").
      if (allocated(axis%labels)) deallocate (axis%labels)
      allocate (axis%labels(n))
      n = 0
      do i = 1, size(labels)
         if (len_trim(labels(i)) == 0) cycle
         n = n + 1
         axis%labels(n) = labels(i)
      end do
      axis%is_label = .true.
   end subroutine store_labels

end module shcontact_input_config_assign
