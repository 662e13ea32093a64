!> The resolved configuration printed as a namelist: every variable, one per line, with its
!> units and help as a comment; reading the text back gives the same configuration.
module shcontact_input_config_writer
   use shcontact_core_strings, only: str_int, to_lower
   use shcontact_core_files, only: canonical_path, absolute_path
   use shcontact_core_buffer, only: text_buffer_type
   use shcontact_core_text, only: format_real, quote_string
   use shcontact_input_config_limits, only: max_fields
   use shcontact_input_config_sweep, only: sweep_axis_type, axis_index
   use shcontact_core_choices, only: choice_type, choice_name, choice_list
   use shcontact_input_config_choices, only: load_mode_uses, load_quantities
   use shcontact_core_ranges, only: ranges, find_range, range_text
   use shcontact_input_config_types, only: case_config_type, choice_value, number_value, &
      string_value, logical_value
   use shcontact_input_config_variables, only: variable_info_type, variables, variable_choices, &
      k_choice, k_real, k_int, k_logical, k_string, k_string_list, k_real_list, find_variable
   implicit none
   private

   public :: config_namelist, variable_value_text, option_list, with_absolute_profiles

contains

   !> The configuration with its profile files named by absolute paths (built-in names kept),
   !> so that its namelist is a case file that reproduces the run wherever it is saved (a case
   !> file's relative names are read from its own folder). Symbolic links are kept as links
   !> (their names choose the format of `'auto'`), unless `canonical` (POSIX realpath: two
   !> names of one file give one name, for the checkpoint's key).
   function with_absolute_profiles(config, canonical) result(resolved)
      type(case_config_type), intent(in) :: config
      logical, intent(in), optional :: canonical
      type(case_config_type) :: resolved
      logical :: real_paths
      real_paths = .false.
      if (present(canonical)) real_paths = canonical
      resolved = config
      if (index(to_lower(adjustl(config%profiles%wheel)), 'builtin:') /= 1) &
         resolved%profiles%wheel = named(trim(config%profiles%wheel))
      if (index(to_lower(adjustl(config%profiles%rail)), 'builtin:') /= 1) &
         resolved%profiles%rail = named(trim(config%profiles%rail))
   contains
      function named(path) result(full)
         character(len=*), intent(in) :: path
         character(len=:), allocatable :: full
         if (real_paths) then
            full = canonical_path(path)
         else
            full = absolute_path(path)
         end if
      end function named
   end function with_absolute_profiles

   !> The resolved configuration as namelist text (every variable, one per line, with its
   !> units as a comment); reading it back gives the same configuration. In kinematic mode the
   !> unused `&creepage` group is left out, and a pitch rate that was not given stays a comment
   !> (pure rolling follows each case's forward speed); so do the `&load` quantities that the
   !> load mode does not read (given, they would be refused).
   function config_namelist(config) result(text)
      !> A validated configuration.
      type(case_config_type), intent(in) :: config
      character(len=:), allocatable :: text
      character(len=1), parameter :: nl = new_line('a')
      integer :: i, ia, n
      character(len=:), allocatable :: value, name
      type(variable_info_type) :: v
      character(len=12) :: previous

      text = ''
      previous = ''
      do i = 1, size(variables)
         v = variables(i)
         if (config%is_kinematic() .and. v%group == 'creepage') then
            if (len_trim(previous) > 0) then
               text = text//'/'//nl//"! &creepage: not used, &kinematics mode = 'on' "// &
                  'computes the creepages'//nl
               previous = ''
            end if
            cycle
         end if
         if (v%group == 'kinematics' .and. v%name == 'pitch_rate' .and. &
             .not. config%kinematics%pitch_rate_given) then
            text = text//'  ! pitch_rate not given: pure rolling, -v_forward/nominal_radius '// &
               '[rad/s]'//nl
            cycle
         end if
         if (v%group /= previous) then
            if (len_trim(previous) > 0) text = text//'/'//nl
            text = text//'&'//trim(v%group)//nl
            previous = v%group
         end if
         name = trim(v%name)
         value = variable_value_text(config, v)
         if (len(value) == 0) cycle
         if (v%group == 'load' .and. any(load_quantities == v%name)) then
            if (.not. load_mode_uses(name, config%load%mode)) then
               ! Given, it would be refused (shcontact_input_config_validate).
               text = text//'  ! '//name//' not read by this mode'//nl
               cycle
            end if
         end if
         text = text//'  '//name//' = '//value//'  ! '
         if (len_trim(v%units) > 0) then
            if (v%units == '1') then
               text = text//'[-] '
            else
               text = text//'['//trim(v%units)//'] '
            end if
         end if
         text = text//trim(v%help)
         if (v%kind == k_choice) text = text//': '//choice_list(variable_choices(v%group, v%name))
         text = text//nl
      end do
      text = text//'/'//nl
   end function config_namelist

   !> The value of variable `v` in `config` as namelist text ('' for a sweep list or count
   !> that is not given).
   function variable_value_text(config, v) result(value)
      !> A configuration.
      type(case_config_type), intent(in) :: config
      !> The variable (an entry of the variable table).
      type(variable_info_type), intent(in) :: v
      character(len=:), allocatable :: value
      character(len=:), allocatable :: name
      integer :: ia, n

      value = ''
      name = trim(v%name)
      select case (v%kind)
      case (k_choice)
         value = quote_string(choice_name(variable_choices(v%group, v%name), &
            choice_value(config, v%group, v%name)))
      case (k_real)
         if (v%group /= 'sweep') value = format_real(number_value(config, v%group, v%name))
      case (k_int)
         if (v%group /= 'sweep') then
            value = str_int(nint(number_value(config, v%group, v%name)))
         else
            ia = axis_index(name(1:index(name, '_points') - 1))
            if (.not. config%sweep%axes(ia)%active) return
            if (config%sweep%axes(ia)%points == 0) return
            value = str_int(config%sweep%axes(ia)%points)
         end if
      case (k_logical)
         value = format_logical(logical_value(config, v%group, v%name))
      case (k_string)
         value = quote_string(string_value(config, v%group, v%name))
      case (k_string_list, k_real_list)
         if (v%group == 'output') then
            do n = 1, max_fields
               if (len_trim(config%output%fields(n)) == 0) cycle
               if (len(value) > 0) value = value//', '
               value = value//quote_string(config%output%fields(n))
            end do
         else
            ia = axis_index(name)
            if (.not. config%sweep%axes(ia)%active) return
            value = axis_text(config%sweep%axes(ia))
         end if
      end select
   end function variable_value_text

   !> The option list of the headers (the comment blocks of include/shcontact.h and
   !> include/shcontact.fi, test `registry`): for each key `group%name`, its default (its value
   !> in `config`; the pitch rate's is pure rolling) and units, then its choices or its range, on
   !> one line when it fits in `width` columns, else wrapped; every line starts with `prefix`.
   function option_list(config, keys, prefix, width) result(text)
      !> The configuration whose values are shown as defaults.
      type(case_config_type), intent(in) :: config
      !> The keys, `group%name`, of variables of the variable table.
      character(len=*), intent(in) :: keys(:)
      !> Start of every line (a comment marker).
      character(len=*), intent(in) :: prefix
      !> Longest line.
      integer, intent(in) :: width
      character(len=:), allocatable :: text
      character(len=1), parameter :: nl = new_line('a')
      type(choice_type), allocatable :: choices(:)
      character(len=:), allocatable :: key, group, name, line, units, word
      integer :: k, iv, ir, i

      text = ''
      do k = 1, size(keys)
         key = trim(keys(k))
         group = key(1:index(key, '%') - 1)
         name = key(index(key, '%') + 1:)
         iv = find_variable(group, name)
         if (iv == 0) cycle
         if (key == 'kinematics%pitch_rate') then
            line = key//' = pure rolling'
         else
            line = key//' = '//variable_value_text(config, variables(iv))
         end if
         choices = variable_choices(group, name)
         ir = find_range(key)
         ! The units: those of the range's text, '[-]' for a dimensionless number.
         units = trim(variables(iv)%units)
         if (units == '1') line = line//' [-]'
         if (ir == 0 .and. len(units) > 0 .and. units /= '1') line = line//' ['//units//']'
         line = line//':'
         if (size(choices) > 0) then
            do i = 1, size(choices)
               word = " '"//trim(choices(i)%name)//"'"
               if (i < size(choices)) word = word//','
               call add_word(word)
            end do
         else if (ir > 0) then
            if (ranges(ir)%kind == k_int) then
               word = ' '//range_text(ranges(ir), name, str_int(nint(ranges(ir)%lo)), &
                  str_int(nint(ranges(ir)%hi)))
            else
               word = ' '//range_text(ranges(ir), name, format_real(ranges(ir)%lo), &
                  format_real(ranges(ir)%hi))
            end if
            call add_word(word)
         end if
         text = text//prefix//line//nl
      end do

   contains

      !> Append to the line, or start a continuation line when it would be too long.
      subroutine add_word(w)
         character(len=*), intent(in) :: w
         if (len(prefix) + len(line) + len(w) > width) then
            text = text//prefix//line//nl
            line = '   '
         end if
         line = line//w
      end subroutine add_word

   end function option_list

   pure function format_logical(flag) result(text)
      logical, intent(in) :: flag
      character(len=:), allocatable :: text
      if (flag) then
         text = '.true.'
      else
         text = '.false.'
      end if
   end function format_logical

   !> The values of an axis as a namelist value list (built in linear time).
   pure function axis_text(axis) result(value)
      type(sweep_axis_type), intent(in) :: axis
      character(len=:), allocatable :: value
      type(text_buffer_type) :: list
      integer :: i
      if (axis%is_label) then
         do i = 1, size(axis%labels)
            if (i > 1) call list%add(', ')
            call list%add(quote_string(axis%labels(i)))
         end do
      else
         do i = 1, size(axis%given)
            if (i > 1) call list%add(', ')
            call list%add(format_real(axis%given(i)))
         end do
      end if
      value = list%text()
   end function axis_text

end module shcontact_input_config_writer
