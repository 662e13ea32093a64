!> Issue 26: one registry per option choice and per namelist group. Every place that states a
!> choice, a default, a unit or a range must agree with the registries (the layers' option
!> registries, shcontact_input_config_choices, the variable table and shcontact_core_ranges): the
!> configuration's defaults, the library's defaults (option types, material, track, contact
!> search), doc/app.md's variable tables and the option lists of include/shcontact.h and
!> include/shcontact.fi. Each test fails when one of them differs.
module test_registry
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_choices, only: choice_type, choice_code, choice_list
   use shcontact_core_ranges, only: ranges, find_range, range_key, k_int
   use shcontact_core_material, only: material_type
   use shcontact_geometry_track, only: track_type, side_right, side_left
   use shcontact_geometry_prepared, only: contact_options_type
   use shcontact_geometry_kinematics, only: pure_rolling_pitch_rate
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_api_solver, only: load_normal_force, load_vertical_force, load_approach
   use shcontact_input_config, only: case_config_type, normal_options_of, tangential_options_of, &
      load_mode_force, load_mode_vertical, load_mode_approach
   use shcontact_input_config_variables, only: variables, find_variable, variable_choices, &
      k_real, k_int, k_choice, k_real_list, header_option_keys
   use shcontact_input_config_writer, only: variable_value_text, option_list
   use shcontact_input_config_types, only: choice_value, number_value
   use shcontact_core_text, only: format_real
   use shcontact_core_strings, only: str_int
   use shcontact_pipeline_result, only: patch_columns, patch_value, find_patch_column, &
      wheel_columns, wheel_value, find_wheel_column, wheel_contact_of
   use shcontact_case_result, only: case_summary_type, case_summary, summary_columns, &
      n_summary_columns, summary_value, summary_column_help
   use shcontact_output_descriptions, only: dataset_description
   use shcontact_api_context, only: contact_context_type
   use shcontact_api_keyed, only: context_solve_state, context_get_value, output_keys
   use test_fuzz_support, only: new_library
   use shcontact_input_config_assign, only: read_group_variable, stat_unknown_choice
   implicit none
   private
   public :: collect_registry

contains

   subroutine collect_registry(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('library_defaults', test_library_defaults), &
         new_unittest('config_defaults_and_units', test_config_defaults), &
         new_unittest('doc_app_tables', test_doc_tables), &
         new_unittest('header_option_lists', test_header_lists), &
         new_unittest('every_choice_from_text', test_every_choice), &
         new_unittest('number_accessor_per_row', test_number_accessor), &
         new_unittest('output_column_table', test_output_columns) &
         ]
   end subroutine collect_registry

   !> The library's option types, material, track and contact-search options have the
   !> configuration's defaults (which are the registries'), and the codes of the load modes and
   !> sides are the library's.
   subroutine test_library_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      type(normal_options_type) :: n, nl
      type(tangential_options_type) :: t, tl
      type(material_type) :: m
      type(track_type) :: tr
      type(contact_options_type) :: o

      n = normal_options_of(c)
      call check(error, n%method == nl%method .and. n%reduction == nl%reduction .and. &
         n%epsilon == nl%epsilon .and. n%n_strips == nl%n_strips, &
         message='normal options: library default differs from the case file''s')
      if (allocated(error)) return
      t = tangential_options_of(c)
      call check(error, t%method == tl%method .and. t%bound == tl%bound .and. &
         t%spin_model == tl%spin_model .and. t%n_elements == tl%n_elements .and. &
         t%spin_flexibility == tl%spin_flexibility .and. t%correction == tl%correction, &
         message='tangential options: library default differs from the case file''s')
      if (allocated(error)) return
      call same(c%material%shear_modulus, m%shear_modulus, 'material%shear_modulus')
      call same(c%material%poisson, m%poisson, 'material%poisson')
      call same(c%material%friction, m%friction, 'material%friction')
      call same(c%track%gauge, tr%gauge, 'track%gauge')
      call same(c%track%gauge_height, tr%gauge_height, 'track%gauge_height')
      call same(c%track%inclination, tr%rail_inclination, 'track%inclination')
      call same(c%track%flange_back_distance, tr%flange_back_distance, &
         'track%flange_back_distance')
      call same(c%track%flange_back_position, tr%flange_back_position, &
         'track%flange_back_position')
      call same(c%track%nominal_radius, tr%nominal_radius, 'track%nominal_radius')
      call same(c%profiles%wheel_smoothing, o%l_filt_wheel, 'profiles%wheel_smoothing')
      call same(c%profiles%rail_smoothing, o%l_filt_rail, 'profiles%rail_smoothing')
      call same(c%normal%b_min, o%b_min, 'normal%b_min')
      if (allocated(error)) return
      call check(error, load_mode_force == load_normal_force .and. &
         load_mode_vertical == load_vertical_force .and. load_mode_approach == load_approach, &
         message='load-mode codes differ from the library''s')
      if (allocated(error)) return
      call check(error, c%track%side == side_right .and. &
         choice_code(variable_choices('track', 'side'), 'left') == side_left, &
         message='side codes differ from the library''s')

   contains

      subroutine same(app, library, key)
         real(wp), intent(in) :: app, library
         character(len=*), intent(in) :: key
         if (allocated(error)) return
         call check(error, app == library, message=key//': library default differs from '// &
            'the case file''s')
      end subroutine same

   end subroutine test_library_defaults

   !> Every number of the variable table with a range: the configuration's default is the
   !> range table's default (the pitch rate's is pure rolling), and its units are the range
   !> table's (a sweep list's those of the variable it sweeps); every range belongs to a
   !> variable; every choice variable's default is one of its choices.
   subroutine test_config_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      integer :: i, ir, stat
      real(wp) :: x
      character(len=:), allocatable :: key, text

      do i = 1, size(variables)
         key = trim(variables(i)%group)//'%'//trim(variables(i)%name)
         if (variables(i)%kind == k_real_list) then
            ir = range_of_swept(trim(variables(i)%name))
         else
            ir = find_range(key)
         end if
         if (variables(i)%kind == k_choice) then
            text = variable_value_text(c, variables(i))
            call check(error, choice_code(variable_choices(variables(i)%group, &
               variables(i)%name), text(2:len(text) - 1)) /= 0, &
               message=key//': default '//text//' is none of its choices')
            if (allocated(error)) return
         end if
         if (ir == 0) cycle
         call check(error, trim(variables(i)%units) == trim(ranges(ir)%units), &
            message=key//': units ['//trim(variables(i)%units)//'] in the variable table, ['// &
            trim(ranges(ir)%units)//'] in the range table')
         if (allocated(error)) return
         if (variables(i)%kind /= k_real .and. variables(i)%kind /= k_int) cycle
         if (key == 'kinematics%pitch_rate') then
            x = pure_rolling_pitch_rate(c%kinematics%v_forward, c%track%nominal_radius)
         else
            text = variable_value_text(c, variables(i))
            read (text, *, iostat=stat) x
            call check(error, stat, 0, message=key//': default '//text//' is not a number')
            if (allocated(error)) return
         end if
         call check(error, x, ranges(ir)%default, rel=.true., thr=1e-12_wp, &
            message=key//': the configuration''s default differs from the range table''s')
         if (allocated(error)) return
      end do
      do ir = 1, size(ranges)
         key = trim(range_key(ranges(ir)))
         call check(error, find_variable(key(1:index(key, '%') - 1), &
            key(index(key, '%') + 1:)) > 0, message=key//': a range of no variable')
         if (allocated(error)) return
      end do
   end subroutine test_config_defaults

   !> The range of the variable a sweep list sweeps (`&sweep t_y` → `position%t_y`).
   integer function range_of_swept(name) result(ir)
      character(len=*), intent(in) :: name
      integer :: i
      ir = 0
      do i = 1, size(ranges)
         if (ranges(i)%name == name) ir = i
      end do
   end function range_of_swept

   !> doc/app.md's tables "Variables (units and defaults)": every variable of every group but
   !> `&sweep` has a row, every row names a variable of its group, and each row's units,
   !> default, choices (each choice quoted in the last column) and range limits (both numbers
   !> in the last column, limits beyond 1e9 meaning "none") are the registries'.
   subroutine test_doc_tables(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      logical :: seen(size(variables)), inside
      character(len=4000) :: line
      character(len=:), allocatable :: group, cell(:), names(:)
      integer :: unit, stat, iv, k
      seen = .false.
      inside = .false.
      group = ''
      open (newunit=unit, file='doc/app.md', status='old', action='read', iostat=stat)
      call check(error, stat, 0, message='doc/app.md not found (run from the root)')
      if (allocated(error)) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, '### Variables (units and defaults)') == 1) then
            inside = .true.
            cycle
         end if
         if (.not. inside) cycle
         if (index(line, '## ') == 1 .or. index(line, '### ') == 1) exit
         if (index(line, '**&') == 1) then
            group = line(4:index(line(4:), '**') + 2)
            cycle
         end if
         if (index(line, '| `') /= 1 .or. group == 'sweep') cycle
         call split_row(trim(line), cell)
         if (size(cell) < 4) cycle
         call backticked(cell(1), names)
         do k = 1, size(names)
            iv = find_variable(group, trim(names(k)))
            call check(error, iv > 0, message='doc/app.md: &'//group//' '//trim(names(k))// &
               ' is no variable of the group')
            if (allocated(error)) exit
            seen(iv) = .true.
            call check_row(c, iv, cell, error)
            if (allocated(error)) exit
         end do
         if (allocated(error)) exit
      end do
      close (unit)
      if (allocated(error)) return
      do iv = 1, size(variables)
         if (variables(iv)%group == 'sweep') cycle
         call check(error, seen(iv), message='doc/app.md has no row for &'// &
            trim(variables(iv)%group)//' '//trim(variables(iv)%name))
         if (allocated(error)) return
      end do
   end subroutine test_doc_tables

   !> One variable's row: units, default, choices, range.
   subroutine check_row(c, iv, cell, error)
      type(case_config_type), intent(in) :: c
      integer, intent(in) :: iv
      character(len=*), intent(in) :: cell(:)
      type(error_type), allocatable, intent(out) :: error
      type(choice_type), allocatable :: choices(:)
      character(len=:), allocatable :: key, units, value, allowed
      real(wp), allocatable :: numbers(:)
      real(wp) :: x
      integer :: i, ir, stat

      key = trim(variables(iv)%group)//'%'//trim(variables(iv)%name)
      units = trim(adjustl(cell(3)))
      if (units == '[-]') units = '1'
      call check(error, units == trim(variables(iv)%units), message='doc/app.md: '//key// &
         ' in ['//units//'], the registry in ['//trim(variables(iv)%units)//']')
      if (allocated(error)) return
      value = variable_value_text(c, variables(iv))
      select case (variables(iv)%kind)
      case (k_real, k_int)
         if (key /= 'kinematics%pitch_rate') then
            numbers = numbers_in(cell(2))
            read (value, *, iostat=stat) x
            call check(error, size(numbers) > 0 .and. stat == 0, message='doc/app.md: '//key// &
               ': no default number')
            if (allocated(error)) return
            call check(error, numbers(1), x, rel=.true., thr=1e-12_wp, message='doc/app.md: '// &
               key//' default '//trim(cell(2))//', the registry '//value)
            if (allocated(error)) return
         end if
      case default
         call check(error, index(cell(2), '`'//value//'`') > 0, message='doc/app.md: '//key// &
            ' default '//trim(cell(2))//', the registry '//value)
         if (allocated(error)) return
      end select
      allowed = cell(4)
      choices = variable_choices(variables(iv)%group, variables(iv)%name)
      do i = 1, size(choices)
         call check(error, index(allowed, "`'"//trim(choices(i)%name)//"'`") > 0, &
            message='doc/app.md: '//key//": the choice '"//trim(choices(i)%name)// &
            "' is not listed; the registry's are "//choice_list(choices))
         if (allocated(error)) return
      end do
      ir = find_range(key)
      if (ir == 0) return
      numbers = numbers_in(allowed)
      call check(error, any(abs(numbers - ranges(ir)%lo) <= 1e-12_wp*abs(ranges(ir)%lo)) .and. &
         (abs(ranges(ir)%hi) > 1e9_wp .or. &
         any(abs(numbers - ranges(ir)%hi) <= 1e-12_wp*abs(ranges(ir)%hi))), &
         message='doc/app.md: '//key//': the range of the registry is not in "'// &
         trim(allowed)//'"')
   end subroutine check_row

   !> The cells of a table row `| a | b | c |`.
   subroutine split_row(line, cell)
      character(len=*), intent(in) :: line
      character(len=:), allocatable, intent(out) :: cell(:)
      integer :: i, n, start, k
      n = count([(line(i:i) == '|', i=1, len(line))]) - 1
      allocate (character(len=len(line)) :: cell(max(n, 0)))
      start = 2
      k = 0
      do i = 2, len(line)
         if (line(i:i) /= '|') cycle
         k = k + 1
         if (k > size(cell)) exit
         cell(k) = line(start:i - 1)
         start = i + 1
      end do
   end subroutine split_row

   !> The `words` in backticks of a cell.
   subroutine backticked(text, words)
      character(len=*), intent(in) :: text
      character(len=:), allocatable, intent(out) :: words(:)
      character(len=64) :: found(32)
      integer :: i, j, n
      n = 0
      i = 1
      do
         j = index(text(i:), '`')
         if (j == 0) exit
         i = i + j
         j = index(text(i:), '`')
         if (j == 0) exit
         n = n + 1
         found(n) = text(i:i + j - 2)
         i = i + j
      end do
      allocate (character(len=64) :: words(n))
      words = found(1:n)
   end subroutine backticked

   !> The numbers written in a text: '−' (U+2212) is a minus sign, '–' (U+2013) separates a
   !> range; a number starts with a digit or a sign or point followed by a digit.
   function numbers_in(text) result(x)
      character(len=*), intent(in) :: text
      real(wp), allocatable :: x(:)
      character(len=*), parameter :: minus = char(226)//char(136)//char(146)
      character(len=:), allocatable :: t
      real(wp) :: v
      integer :: i, j, stat
      t = text
      do
         i = index(t, minus)
         if (i == 0) exit
         t = t(1:i - 1)//' -'//t(i + 3:)
      end do
      allocate (x(0))
      i = 1
      do while (i <= len(t))
         if (index('0123456789', t(i:i)) > 0 .or. (index('-.', t(i:i)) > 0 .and. i < len(t) &
             .and. index('0123456789', t(min(i + 1, len(t)):min(i + 1, len(t)))) > 0)) then
            j = i
            do while (j < len(t))
               if (index('0123456789.eE+-', t(j + 1:j + 1)) == 0) exit
               if (index('+-', t(j + 1:j + 1)) > 0 .and. index('eE', t(j:j)) == 0) exit
               j = j + 1
            end do
            read (t(i:j), *, iostat=stat) v
            if (stat == 0) x = [x, v]
            i = j + 1
         else
            i = i + 1
         end if
      end do
   end function numbers_in

   !> The option lists of include/shcontact.h and include/shcontact.fi (between their
   !> '-- options --' and '-- end options --' lines) are the registry's, as
   !> shcontact_input_config_writer's option_list writes them.
   subroutine test_header_lists(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      call check_block('include/shcontact.h', ' * ', 99, error)
      if (allocated(error)) return
      call check_block('include/shcontact.fi', '!   ', 72, error)

   contains

      subroutine check_block(file, prefix, width, error)
         character(len=*), intent(in) :: file, prefix
         integer, intent(in) :: width
         type(error_type), allocatable, intent(out) :: error
         character(len=:), allocatable :: expected, found
         character(len=400) :: line
         integer :: unit, stat
         logical :: inside
         expected = option_list(c, header_option_keys(), prefix, width)
         found = ''
         inside = .false.
         open (newunit=unit, file=file, status='old', action='read', iostat=stat)
         call check(error, stat, 0, message=file//' not found (run from the root)')
         if (allocated(error)) return
         do
            read (unit, '(a)', iostat=stat) line
            if (stat /= 0) exit
            if (index(line, '-- end options --') > 0) exit
            if (inside) found = found//trim(line)//new_line('a')
            if (index(line, '-- options --') > 0) inside = .true.
         end do
         close (unit)
         call check(error, found == expected, message=file//': the option list differs '// &
            'from the registry; run `fpm run --example shcontact-headers` (it writes '// &
            'the list); it should read'//new_line('a')//expected)
         if (allocated(error)) return
         call check_mentions(file, error)
      end subroutine check_block

   end subroutine test_header_lists

   !> Anywhere in a header, a choice option named with its choices in parentheses,
   !> "tangential%bound (ellipsoidal, parabolic, ...)", names exactly the registry's choices.
   subroutine check_mentions(file, error)
      character(len=*), intent(in) :: file
      type(error_type), allocatable, intent(out) :: error
      type(choice_type), allocatable :: choices(:)
      character(len=:), allocatable :: text, key, list, item
      character(len=400) :: line
      integer :: unit, stat, i, at, close_at, n, comma
      text = ''
      open (newunit=unit, file=file, status='old', action='read', iostat=stat)
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         ! Comment markers and line breaks read as blanks.
         if (line(1:3) == ' * ') line(1:3) = ''
         if (line(1:1) == '!') line(1:1) = ''
         text = text//' '//trim(adjustl(line))
      end do
      close (unit)
      do i = 1, size(variables)
         if (variables(i)%kind /= k_choice) cycle
         key = trim(variables(i)%group)//'%'//trim(variables(i)%name)//' ('
         choices = variable_choices(variables(i)%group, variables(i)%name)
         at = index(text, key)
         do while (at > 0)
            list = text(at + len(key):)
            close_at = index(list, ')')
            list = list(1:close_at - 1)//','
            n = 0
            do
               comma = index(list, ',')
               if (comma == 0) exit
               item = trim(adjustl(list(1:comma - 1)))
               list = list(comma + 1:)
               n = n + 1
               call check(error, choice_code(choices, item) /= 0, message=file//': '//key// &
                  '...): '//item//' is none of the registry''s choices '//choice_list(choices))
               if (allocated(error)) return
            end do
            call check(error, n == size(choices), message=file//': '//key//'...) names '// &
               'not all of the registry''s choices '//choice_list(choices))
            if (allocated(error)) return
            text = text(at + len(key):)
            at = index(text, key)
         end do
      end do
   end subroutine check_mentions

   !> Every choice of every choice variable is set from its text by read_group_variable (the
   !> entry point of the case files, `--set` and the option setters), quoted or not and in any
   !> case, to the registry's code; an unknown name is refused with the list of the choices.
   subroutine test_every_choice(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      type(choice_type), allocatable :: choices(:)
      character(len=256) :: msg
      character(len=:), allocatable :: key, text
      integer :: i, k, stat
      do i = 1, size(variables)
         if (variables(i)%kind /= k_choice) cycle
         key = trim(variables(i)%group)//'%'//trim(variables(i)%name)
         choices = variable_choices(variables(i)%group, variables(i)%name)
         do k = 1, size(choices)
            msg = ''
            call read_group_variable(c, trim(variables(i)%group), trim(variables(i)%name), &
               "'"//trim(choices(k)%name)//"'", stat, msg)
            call check(error, stat == 0 .and. choice_value(c, variables(i)%group, &
               variables(i)%name) == choices(k)%code, message=key//" = '"// &
               trim(choices(k)%name)//"' not read: "//trim(msg))
            if (allocated(error)) return
            ! Unquoted, its first letter in upper case, '-' written '_'.
            text = capitalised(trim(choices(k)%name))
            call read_group_variable(c, trim(variables(i)%group), trim(variables(i)%name), &
               text, stat, msg)
            call check(error, stat == 0 .and. choice_value(c, variables(i)%group, &
               variables(i)%name) == choices(k)%code, message=key//' = '//text// &
               ' (unquoted) not read: '//trim(msg))
            if (allocated(error)) return
         end do
         call read_group_variable(c, trim(variables(i)%group), trim(variables(i)%name), &
            "'no-such-choice'", stat, msg)
         call check(error, stat == stat_unknown_choice .and. &
            index(msg, choice_list(choices)) > 0, message=key//': unknown choice accepted or '// &
            'reported without the choices: '//trim(msg))
         if (allocated(error)) return
      end do

   contains

      pure function capitalised(name) result(t)
         character(len=*), intent(in) :: name
         character(len=:), allocatable :: t
         integer :: dash
         t = achar(iachar(name(1:1)) - 32)//name(2:)
         dash = index(t, '-')
         if (dash > 0) t(dash:dash) = '_'
      end function capitalised

   end subroutine test_every_choice

   !> Every number with a range in the variable table is read by the one accessor
   !> (number_value, which the validation's generic range check and the resolved namelist use):
   !> a value set through the namelist reader, inside the range and off the default, comes back.
   subroutine test_number_accessor(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      character(len=256) :: msg
      character(len=:), allocatable :: text
      integer :: ir, stat
      real(wp) :: x
      do ir = 1, size(ranges)
         associate (r => ranges(ir))
            x = r%lo + 0.375_wp*(r%hi - r%lo)
            if (r%hi > 1.0e6_wp) x = r%lo + 3.0_wp
            if (r%kind == k_int) then
               x = anint(x)
               text = str_int(nint(x))
            else
               text = format_real(x)
               read (text, *) x
            end if
            msg = ''
            call read_group_variable(c, trim(r%group), trim(r%name), text, stat, msg)
            call check(error, stat, 0, message=trim(range_key(r))//' = '//text//': '//trim(msg))
            if (allocated(error)) return
            call check(error, number_value(c, r%group, r%name) == x, message= &
               trim(range_key(r))//': number_value does not give the value set ('//text//')')
            if (allocated(error)) return
         end associate
      end do
   end subroutine test_number_accessor

   !> The one column table of the per-patch results (shcontact_pipeline_result's patch_columns)
   !> agrees with the flat layout (every column that is also a flat value: the same number by
   !> name, main patch and patch 1), with /summary (each main-patch column is the table's value,
   !> under the table's name and units) and with the HDF5 descriptions (every real /summary
   !> column has the table's text), and so does the table of the wheel's joined contact
   !> (wheel_columns: by name, patch 0 only, the last /summary columns). On the default case
   !> every value read is nonzero, so a column wired to the wrong field shows.
   subroutine test_output_columns(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_context_type) :: ctx
      type(case_summary_type) :: s
      integer :: k, j, stat
      real(wp) :: x
      !> The case's flags after the joined contact's columns (climbing).
      integer, parameter :: n_flag_columns = 1
      call new_library(error, ctx)
      if (allocated(error)) return
      call check(error, context_solve_state(ctx), 0, message='solve of the default state')
      if (allocated(error)) return
      do k = 1, size(patch_columns)
         call check(error, find_patch_column(trim(patch_columns(k)%name), .false.), k, &
            message=trim(patch_columns(k)%name)//': name found twice in the column table')
         if (allocated(error)) return
         stat = context_get_value(ctx, trim(patch_columns(k)%name), 0, x)
         call check(error, stat == 0 .and. x == patch_value(ctx%result%main, k), &
            message=trim(patch_columns(k)%name)//': keyed value of the main patch differs '// &
            'from the column table''s')
         if (allocated(error)) return
         stat = context_get_value(ctx, trim(patch_columns(k)%name), 1, x)
         call check(error, stat == 0 .and. x == patch_value(ctx%result%patch(1), k), &
            message=trim(patch_columns(k)%name)//': keyed value of patch 1 differs')
         if (allocated(error)) return
         if (any(output_keys%name == patch_columns(k)%name) .and. &
             patch_columns(k)%name /= 'nu_x' .and. patch_columns(k)%name /= 'nu_y' .and. &
             patch_columns(k)%name /= 'phi' .and. patch_columns(k)%name /= 'x_track') then
            call check(error, patch_value(ctx%result%main, k) /= 0.0_wp, &
               message=trim(patch_columns(k)%name)//': zero on the default case')
            if (allocated(error)) return
         end if
      end do
      s = case_summary(ctx%result)
      do j = 1, n_summary_columns
         call check(error, len_trim(summary_column_help(trim(summary_columns(1, j)))) > 0 &
            .and. dataset_description('summary/'//trim(summary_columns(1, j))) == &
            summary_column_help(trim(summary_columns(1, j))), message='/summary/'// &
            trim(summary_columns(1, j))//': no description, or not the table''s')
         if (allocated(error)) return
         k = find_patch_column(trim(summary_columns(1, j)), .true.)
         if (k == 0) cycle
         call check(error, summary_value(s, j) == patch_value(ctx%result%main, k) .and. &
            summary_columns(2, j) == patch_columns(k)%units, message='/summary/'// &
            trim(summary_columns(1, j))//': not the main patch''s column of the table')
         if (allocated(error)) return
      end do
      ! The wheel's joined contact (doc/lobes.md): by name (patch 0 only), its /summary
      ! columns after the main patch's, the value of the result's `wheel`.
      do k = 1, size(wheel_columns)
         call check(error, find_wheel_column(trim(wheel_columns(k)%name)) == k .and. &
            find_patch_column(trim(wheel_columns(k)%name), .false.) == 0 .and. &
            find_patch_column(trim(wheel_columns(k)%name), .true.) == 0 .and. &
            .not. any(output_keys%name == wheel_columns(k)%name), &
            message=trim(wheel_columns(k)%name)//': name not unique among the outputs')
         if (allocated(error)) return
         stat = context_get_value(ctx, trim(wheel_columns(k)%name), 1, x)
         call check(error, stat /= 0, message=trim(wheel_columns(k)%name)//': a joined '// &
            'contact''s value of patch 1 should be refused')
         if (allocated(error)) return
         stat = context_get_value(ctx, trim(wheel_columns(k)%name), 0, x)
         call check(error, stat == 0 .and. x == wheel_value(wheel_contact_of(ctx%result%wheel), &
            k) .and. x /= 0.0_wp, message=trim(wheel_columns(k)%name)//': keyed value '// &
            'differs from the joined contact''s, or is zero on the default case')
         if (allocated(error)) return
         j = n_summary_columns - n_flag_columns - size(wheel_columns) + k
         call check(error, summary_columns(1, j) == wheel_columns(k)%summary .and. &
            summary_columns(2, j) == wheel_columns(k)%units .and. summary_value(s, j) == x, &
            message='/summary/'//trim(wheel_columns(k)%summary)//': not the joined contact''s '// &
            'column of the table')
         if (allocated(error)) return
      end do
      ! The flags last: climbing, the result's and the keyed value's, 0 on the default case.
      call check(error, summary_columns(1, n_summary_columns) == 'climbing' .and. &
         summary_value(s, n_summary_columns) == merge(1.0_wp, 0.0_wp, ctx%result%climbing), &
         message='/summary/climbing: not the result''s flag')
      if (allocated(error)) return
      stat = context_get_value(ctx, 'climbing', 0, x)
      call check(error, stat == 0 .and. x == summary_value(s, n_summary_columns) .and. &
         x == 0.0_wp, message='climbing: keyed value differs, or set on the default case')
      if (allocated(error)) return
      call check(error, count(patch_columns%summary /= '') + 4 + size(wheel_columns) + &
         n_flag_columns, n_summary_columns, message='/summary has a column that is not in '// &
         'the tables')
   end subroutine test_output_columns

end module test_registry
