!> The resolved configuration printed as a namelist: every variable, one per line, with its
!> units and help as a comment; reading the text back gives the same configuration.
module shcontact_input_config_writer
   use shcontact_core_strings, only: str_int
   use shcontact_core_buffer, only: text_buffer_type
   use shcontact_core_text, only: format_real, quote_string
   use shcontact_input_config_limits, only: max_fields
   use shcontact_input_config_sweep, only: sweep_axis_type, axis_index
   use shcontact_core_choices, only: choice_type, choice_name, choice_list
   use shcontact_core_ranges, only: ranges, find_range, range_text
   use shcontact_input_config_types, only: case_config_type, choice_value
   use shcontact_input_config_variables, only: variable_info_type, variables, variable_choices, &
      k_choice, find_variable
   implicit none
   private

   public :: config_namelist, variable_value_text, option_list

contains

   !> The resolved configuration as namelist text (every variable, one per line, with its
   !> units as a comment); reading it back gives the same configuration. In kinematic mode the
   !> unused `&creepage` group is left out, and a pitch rate that was not given stays a comment
   !> (pure rolling follows each case's forward speed).
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
      if (v%kind == k_choice) then
         value = quote_string(choice_name(variable_choices(v%group, v%name), &
            choice_value(config, v%group, v%name)))
      else
         select case (trim(v%group))
         case ('profiles')
            select case (name)
            case ('wheel'); value = quote_string(config%profiles%wheel)
            case ('rail'); value = quote_string(config%profiles%rail)
            case ('wheel_format'); value = quote_string(config%profiles%wheel_format)
            case ('rail_format'); value = quote_string(config%profiles%rail_format)
            case ('wheel_smoothing'); value = format_real(config%profiles%wheel_smoothing)
            case ('rail_smoothing'); value = format_real(config%profiles%rail_smoothing)
            case ('wheel_mirror_y'); value = quote_string(config%profiles%wheel_mirror_y)
            case ('wheel_mirror_z'); value = quote_string(config%profiles%wheel_mirror_z)
            case ('wheel_scale'); value = format_real(config%profiles%wheel_scale)
            case ('rail_mirror_y'); value = quote_string(config%profiles%rail_mirror_y)
            case ('rail_mirror_z'); value = quote_string(config%profiles%rail_mirror_z)
            case ('rail_scale'); value = format_real(config%profiles%rail_scale)
            end select
         case ('track')
            select case (name)
            case ('gauge'); value = format_real(config%track%gauge)
            case ('gauge_height'); value = format_real(config%track%gauge_height)
            case ('inclination'); value = format_real(config%track%inclination)
            case ('rail_canted'); value = format_logical(config%track%rail_canted)
            case ('flange_back_distance')
               value = format_real(config%track%flange_back_distance)
            case ('flange_back_position')
               value = format_real(config%track%flange_back_position)
            case ('nominal_radius'); value = format_real(config%track%nominal_radius)
            end select
         case ('position')
            select case (name)
            case ('t_y'); value = format_real(config%position%t_y)
            case ('roll'); value = format_real(config%position%roll)
            end select
         case ('kinematics')
            select case (name)
            case ('yaw'); value = format_real(config%kinematics%yaw)
            case ('v_forward'); value = format_real(config%kinematics%v_forward)
            case ('v_lateral'); value = format_real(config%kinematics%v_lateral)
            case ('v_vertical'); value = format_real(config%kinematics%v_vertical)
            case ('roll_rate'); value = format_real(config%kinematics%roll_rate)
            case ('yaw_rate'); value = format_real(config%kinematics%yaw_rate)
            case ('pitch_rate'); value = format_real(config%kinematics%pitch_rate)
            end select
         case ('material')
            select case (name)
            case ('shear_modulus'); value = format_real(config%material%shear_modulus)
            case ('poisson'); value = format_real(config%material%poisson)
            case ('friction'); value = format_real(config%material%friction)
            end select
         case ('load')
            select case (name)
            case ('normal_force'); value = format_real(config%load%normal_force)
            case ('approach'); value = format_real(config%load%approach)
            case ('vertical_force'); value = format_real(config%load%vertical_force)
            end select
         case ('creepage')
            select case (name)
            case ('nu_x'); value = format_real(config%creepage%nu_x)
            case ('nu_y'); value = format_real(config%creepage%nu_y)
            case ('phi'); value = format_real(config%creepage%phi)
            end select
         case ('normal')
            select case (name)
            case ('epsilon'); value = format_real(config%normal%epsilon)
            case ('n_strips'); value = str_int(config%normal%n_strips)
            case ('b_min'); value = format_real(config%normal%b_min)
            end select
         case ('tangential')
            select case (name)
            case ('n_elements'); value = str_int(config%tangential%n_elements)
            end select
         case ('output')
            select case (name)
            case ('file'); value = quote_string(config%output%file)
            case ('fields')
               value = ''
               do n = 1, max_fields
                  if (len_trim(config%output%fields(n)) == 0) cycle
                  if (len(value) > 0) value = value//', '
                  value = value//quote_string(config%output%fields(n))
               end do
            case ('compression'); value = str_int(config%output%compression)
            case ('checkpoint_cases'); value = str_int(config%output%checkpoint_cases)
            end select
         case ('sweep')
            if (index(name, '_points') > 0) then
               ia = axis_index(name(1:index(name, '_points') - 1))
               if (.not. config%sweep%axes(ia)%active) return
               if (config%sweep%axes(ia)%points == 0) return
               value = str_int(config%sweep%axes(ia)%points)
            else
               ia = axis_index(name)
               if (.not. config%sweep%axes(ia)%active) return
               value = axis_text(config%sweep%axes(ia))
            end if
      end select
      end if
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
            if (ranges(ir)%whole) then
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
