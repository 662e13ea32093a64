!> Tests of the namelist case configuration: defaults, partial groups, overrides, every kind of
!> bad input and its message, sweeps, and the printed namelist reading back to the same
!> configuration.
module test_config
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_io
   use shcontact_input_config, only: case_config_type, case_point_type, load_config, &
      read_config_text, config_namelist, axis_geometry, axis_load, n_sweep_axes, &
      sweep_axis_names
   use shcontact_core_text, only: format_real
   use shcontact_input_config_variables, only: variables, variable_choices, k_choice
   use shcontact_core_choices, only: choice_list
   use shcontact_input_config_choices, only: load_mode_force, load_mode_vertical
   use shcontact_tangential_options, only: method_fastsim_sh, bound_clipped, bound_parabolic, &
      bound_weighted, spin_uniform, spin_additive, tangential_options_type
   use shcontact_core_files, only: delete_file, process_id
   use shcontact_input_config_types, only: contact_options_of, tangential_options_of
   use shcontact_geometry_prepared, only: contact_options_type
   implicit none
   private
   public :: collect_config

   character(len=0), parameter :: no_overrides(0) = [character(len=0) ::]

contains

   subroutine collect_config(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('defaults_are_headline_case', test_defaults), &
         new_unittest('partial_groups_any_order', test_partial_file), &
         new_unittest('overrides', test_overrides), &
         new_unittest('unknown_variable', test_unknown_variable), &
         new_unittest('unknown_group', test_unknown_group), &
         new_unittest('wrong_type', test_wrong_type), &
         new_unittest('out_of_range', test_out_of_range), &
         new_unittest('bad_choice', test_bad_choice), &
         new_unittest('structure_errors', test_structure_errors), &
         new_unittest('missing_file', test_missing_file), &
         new_unittest('sweep_grid_order', test_sweep_grid), &
         new_unittest('sweep_list_and_errors', test_sweep_list), &
         new_unittest('shared_stages', test_shares_with), &
         new_unittest('namelist_round_trip', test_round_trip), &
         new_unittest('format_real_round_trip', test_format_real), &
         new_unittest('kinematics_parsing', test_kinematics), &
         new_unittest('kinematics_errors', test_kinematics_errors), &
         new_unittest('kinematics_round_trip', test_kinematics_round_trip), &
         new_unittest('load_quantity_of_another_mode', test_load_quantity_of_another_mode) &
         ]
   end subroutine collect_config

   !> A scratch case file with the given lines; returns its name.
   function scratch_file(tag, lines) result(name)
      character(len=*), intent(in) :: tag
      character(len=*), intent(in) :: lines(:)
      character(len=:), allocatable :: name
      integer :: unit, i
      character(len=16) :: pid
      write (pid, '(i0)') process_id()
      name = '/tmp/shcontact_test_config_'//trim(pid)//'_'//tag//'.nml'
      open (newunit=unit, file=name, status='replace', action='write')
      do i = 1, size(lines)
         write (unit, '(a)') trim(lines(i))
      end do
      close (unit)
   end function scratch_file

   !> Load a configuration that must be valid: a case file ('' for none) and overrides.
   subroutine load_valid(name, overrides, config, error)
      character(len=*), intent(in) :: name, overrides(:)
      type(case_config_type), intent(out) :: config
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: lerr
      call load_config(name, overrides, config, lerr)
      if (allocated(lerr)) call test_failed(error, lerr%message)
   end subroutine load_valid

   !> Load a scratch file and expect an error whose message contains every fragment.
   subroutine expect_error(error, tag, lines, fragments, stat)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: tag
      character(len=*), intent(in) :: lines(:), fragments(:)
      integer, intent(in), optional :: stat
      character(len=:), allocatable :: name
      name = scratch_file(tag, lines)
      call expect_load_error(error, tag, name, no_overrides, fragments, stat)
      if (delete_file(name)) continue
   end subroutine expect_error

   !> Expect an error from overrides of the default case, its message containing every
   !> fragment.
   subroutine expect_override_error(error, tag, overrides, fragments)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: tag
      character(len=*), intent(in) :: overrides(:), fragments(:)
      call expect_load_error(error, tag, '', overrides, fragments)
   end subroutine expect_override_error

   !> Load a case file ('' for none) with overrides and expect an error whose message contains
   !> every fragment (and whose status is `stat`, when given).
   subroutine expect_load_error(error, tag, name, overrides, fragments, stat)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: tag, name
      character(len=*), intent(in) :: overrides(:), fragments(:)
      integer, intent(in), optional :: stat
      type(case_config_type) :: config
      type(lib_error), allocatable :: lerr
      integer :: i
      call load_config(name, overrides, config, lerr)
      if (.not. allocated(lerr)) then
         call test_failed(error, tag//': expected an error, got none')
         return
      end if
      do i = 1, size(fragments)
         if (index(lerr%message, trim(fragments(i))) == 0) then
            call test_failed(error, tag//': message lacks "'//trim(fragments(i))//'": '// &
               lerr%message)
            return
         end if
      end do
      if (present(stat)) call check(error, lerr%stat, stat, message=tag//': status')
   end subroutine expect_load_error

   !> Print a configuration as a namelist and read it back: the text must read and print the
   !> same again.
   subroutine read_back(c, d, text, error)
      !> The configuration printed.
      type(case_config_type), intent(in) :: c
      !> The configuration read back.
      type(case_config_type), intent(out) :: d
      !> The printed namelist.
      character(len=:), allocatable, intent(out) :: text
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: lerr
      text = config_namelist(c)
      call read_config_text(text, 'printed', d, lerr)
      if (allocated(lerr)) then
         call test_failed(error, 'printed namelist does not read back: '//lerr%message// &
            new_line('a')//text)
         return
      end if
      call check(error, config_namelist(d) == text, message='printed namelist is a fixed point')
   end subroutine read_back

   subroutine test_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      call load_valid('', no_overrides, c, error)
      if (allocated(error)) return
      call check(error, c%n_cases(), 1)
      if (allocated(error)) return
      call check(error, c%profiles%wheel == 'builtin:S1002' .and. &
         c%profiles%rail == 'builtin:UIC60', message='built-in S1002 on UIC60')
      if (allocated(error)) return
      call check(error, c%track%inclination, 0.025_wp)
      if (allocated(error)) return
      call check(error, c%position%t_y, 4.733_wp)
      if (allocated(error)) return
      call check(error, c%load%normal_force, 64700.0_wp)
      if (allocated(error)) return
      call check(error, c%track%nominal_radius, 460.0_wp)
      if (allocated(error)) return
      call check(error, c%material%shear_modulus, 82670.0_wp)
      if (allocated(error)) return
      call check(error, c%material%poisson, 0.27_wp)
      if (allocated(error)) return
      call check(error, c%material%friction, 0.3_wp)
      if (allocated(error)) return
      call check(error, c%creepage%nu_x, 0.58e-3_wp)
      if (allocated(error)) return
      call check(error, c%creepage%nu_y, 0.061e-3_wp)
      if (allocated(error)) return
      call check(error, c%creepage%phi, 2.74e-4_wp)
      if (allocated(error)) return
      call check(error, c%tangential%method == method_fastsim_sh, message='FASTSIM_SH by default')
      if (allocated(error)) return
      call check(error, c%wants_field('traction'), message='a single case stores its fields')
   end subroutine test_defaults

   subroutine test_partial_file(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      character(len=:), allocatable :: name
      name = scratch_file('partial', [character(len=80) :: &
         '! a comment line', &
         '&creepage nu_y = -2.5e-4 /', &
         '', &
         "&tangential bound = 'Clipped', n_elements = 40  ! trailing comment", &
         '/', &
         '&material', &
         '  friction = 0.25', &
         '/', &
         "&profiles wheel = 'wheel.prw' /"])
      call load_valid(name, no_overrides, c, error)
      if (delete_file(name)) continue
      if (allocated(error)) return
      call check(error, c%creepage%nu_y, -2.5e-4_wp)
      if (allocated(error)) return
      call check(error, c%creepage%nu_x, 0.58e-3_wp, message='untouched variable keeps default')
      if (allocated(error)) return
      call check(error, c%tangential%bound == bound_clipped, message='choices are case-insensitive')
      if (allocated(error)) return
      call check(error, c%tangential%n_elements, 40)
      if (allocated(error)) return
      call check(error, c%material%friction, 0.25_wp)
      if (allocated(error)) return
      call check(error, c%profiles%wheel == '/tmp/wheel.prw', &
         message='relative profile names are taken from the case file directory: '// &
         trim(c%profiles%wheel))
   end subroutine test_partial_file

   subroutine test_overrides(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c, default_config
      type(contact_options_type) :: options, defaults
      type(tangential_options_type) :: tangential
      call load_valid('', [character(len=40) :: 'creepage%nu_x=1e-3', &
         'tangential%bound=parabolic', 'sweep%phi=0,1e-3', 'sweep%phi=0,2e-3,3e-3', &
         'output%fields=pressure,state'], c, error)
      if (allocated(error)) return
      call check(error, c%creepage%nu_x, 1.0e-3_wp)
      if (allocated(error)) return
      call check(error, c%tangential%bound == bound_parabolic, message='unquoted string override')
      if (allocated(error)) return
      call check(error, c%n_cases(), 3, message='a list override replaces the whole list')
      if (allocated(error)) return
      call check(error, c%wants_field('state') .and. .not. c%wants_field('traction'), &
         message='field list override')
      if (allocated(error)) return
      call expect_override_error(error, 'malformed override', [character(len=40) :: &
         'creepage.nu_x=1'], [character(len=40) :: 'group%variable=value'])
      if (allocated(error)) return
      call expect_override_error(error, 'wrong type in an override', [character(len=40) :: &
         'creepage%nu_x=abc'], [character(len=40) :: '--set creepage%nu_x=abc', 'real number'])
      if (allocated(error)) return
      ! The strip tables: the option reaches the contact search; the exact slide needs planar
      ! tables (it slides the wheel along their plane).
      call load_valid('', [character(len=40) :: 'normal%strip_tables=conformal'], c, error)
      if (allocated(error)) return
      options = contact_options_of(c)
      defaults = contact_options_of(default_config)
      call check(error, options%conformal_tables .and. .not. defaults%conformal_tables, &
         message='strip_tables')
      if (allocated(error)) return
      ! Classical FASTSIM takes Kalker's parabolic bound unless the case gives one.
      call load_valid('', [character(len=40) :: 'normal%method=hertz', &
         'tangential%method=fastsim'], c, error)
      if (allocated(error)) return
      tangential = tangential_options_of(c)
      call check(error, tangential%bound == bound_parabolic .and. c%tangential%bound == &
         bound_parabolic, message='classical FASTSIM: parabolic bound by default')
      if (allocated(error)) return
      call load_valid('', [character(len=40) :: 'normal%method=hertz', &
         'tangential%method=fastsim', 'tangential%bound=weighted'], c, error)
      if (allocated(error)) return
      tangential = tangential_options_of(c)
      call check(error, tangential%bound == bound_weighted, message='an explicit bound wins')
      if (allocated(error)) return
      tangential = tangential_options_of(default_config)
      call check(error, tangential%bound == bound_weighted, message='FASTSIM_SH: W1')
      if (allocated(error)) return
      call expect_override_error(error, 'exact slide on conformal tables', [character(len=40) :: &
         'normal%strip_tables=conformal', 'normal%slide=exact'], [character(len=40) :: &
         "strip_tables = 'planar'", '--set normal%slide=exact'])
   end subroutine test_overrides

   subroutine test_unknown_variable(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'unknown_var', [character(len=40) :: '&creepage', &
         '  nux = 1e-3', '/'], [character(len=40) :: 'unknown_var.nml:2', '&creepage', &
         'unknown variable "nux"', 'did you mean "nu_x"', 'nu_x, nu_y, phi'], &
         stat_invalid_input)
      if (allocated(error)) return
      ! A variable of another group is named as such, not taken for a misspelling.
      call expect_error(error, 'other_group_var', [character(len=40) :: '&creepage', &
         '  t_y = 3', '/'], [character(len=40) :: 'other_group_var.nml:2', &
         'unknown variable "t_y"', 'it belongs to &position'], stat_invalid_input)
   end subroutine test_unknown_variable

   subroutine test_unknown_group(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'unknown_group', [character(len=40) :: '&creepge nu_x = 0 /'], &
         [character(len=40) :: 'unknown_group.nml:1', 'unknown group &creepge', '&creepage'])
   end subroutine test_unknown_group

   subroutine test_wrong_type(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'type_real', [character(len=40) :: '&position t_y = abc /'], &
         [character(len=40) :: 'type_real.nml:1', '&position t_y = abc', &
         'expected a real number in mm'])
      if (allocated(error)) return
      call expect_error(error, 'type_int', [character(len=40) :: '&normal n_strips = 1.5 /'], &
         [character(len=40) :: '&normal n_strips = 1.5', 'expected an integer'])
      if (allocated(error)) return
      call expect_error(error, 'type_string', [character(len=40) :: &
         '&normal method = hertz /'], [character(len=40) :: 'expected a quoted string', &
         "strings are quoted"])
      if (allocated(error)) return
      call expect_error(error, 'type_count', [character(len=40) :: &
         '&creepage nu_x = 1e-3, 2e-3 /'], [character(len=40) :: 'expected one value', &
         'found 2'])
      if (allocated(error)) return
      call expect_error(error, 'type_logical', [character(len=40) :: &
         '&track rail_canted = maybe /'], [character(len=40) :: 'expected a logical'])
   end subroutine test_wrong_type

   subroutine test_out_of_range(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'range', [character(len=40) :: '&material', 'poisson = 0.5', &
         '/'], [character(len=60) :: 'range.nml:2', '&material poisson = 0.5', &
         'out of range', '0.0 <= poisson < 0.5'], stat_invalid_input)
      if (allocated(error)) return
      call expect_error(error, 'range_nan', [character(len=40) :: '&creepage phi = NaN /'], &
         [character(len=60) :: '&creepage phi = NaN', 'out of range'])
      if (allocated(error)) return
      call expect_error(error, 'range_sweep', [character(len=40) :: &
         '&sweep nu_x = 0, 1e-3, 5 /'], [character(len=60) :: 'range_sweep.nml:1', &
         '&sweep nu_x(3) = 5.0', '-1.0 <= nu_x <= 1.0'])
      if (allocated(error)) return
      call expect_error(error, 'range_int', [character(len=40) :: '&output compression = 12 /'], &
         [character(len=60) :: 'compression = 12', '0 <= compression <= 9'])
   end subroutine test_out_of_range

   subroutine test_bad_choice(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'choice', [character(len=40) :: &
         "&tangential bound = 'elliptic' /"], [character(len=80) :: 'choice.nml:1', &
         "&tangential bound = 'elliptic' is not allowed", "'ellipsoidal', 'parabolic'"])
      if (allocated(error)) return
      call expect_error(error, 'builtin', [character(len=40) :: &
         "&profiles wheel = 'builtin:S1003' /"], [character(len=80) :: &
         'unknown built-in profile', 'builtin:S1002'])
      if (allocated(error)) return
      ! 'all' or 'none' beside other fields (accepted before, 'none' winning silently).
      call expect_error(error, 'fields', [character(len=40) :: &
         "&output fields = 'all', 'none' /"], [character(len=80) :: 'fields.nml:1', &
         "'all', 'none' and 'auto' stand alone"])
   end subroutine test_bad_choice

   subroutine test_structure_errors(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'unclosed', [character(len=40) :: '&creepage nu_x = 0'], &
         [character(len=60) :: 'group &creepage (line 1) is not closed with /'])
      if (allocated(error)) return
      call expect_error(error, 'twice', [character(len=40) :: '&creepage nu_x = 0 /', &
         '&creepage nu_y = 0 /'], [character(len=60) :: 'twice.nml:2', 'appears twice'])
      if (allocated(error)) return
      call expect_error(error, 'outside', [character(len=40) :: 'nu_x = 0'], &
         [character(len=60) :: 'outside.nml:1', 'outside a group'])
      if (allocated(error)) return
      call expect_error(error, 'quote', [character(len=40) :: "&normal method = 'hertz /"], &
         [character(len=60) :: 'quote.nml:1', 'unterminated string'])
      if (allocated(error)) return
      call expect_error(error, 'subscript', [character(len=40) :: '&sweep nu_x(2) = 1e-3 /'], &
         [character(len=60) :: 'give the whole variable'])
   end subroutine test_structure_errors

   subroutine test_missing_file(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_load_error(error, 'missing case file', '/nonexistent/case.nml', no_overrides, &
         [character(len=40) :: '/nonexistent/case.nml'], stat_io)
   end subroutine test_missing_file

   subroutine test_sweep_grid(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      type(case_point_type) :: p
      call load_valid('', [character(len=60) :: 'sweep%nu_x=0,2e-3', 'sweep%nu_x_points=20', &
         'sweep%phi=0,1e-3,2e-3', "sweep%bound=weighted,clipped"], c, error)
      if (allocated(error)) return
      call check(error, c%n_cases(), 20*2*3)
      if (allocated(error)) return
      ! Loop order: bound, nu_x, phi (phi fastest).
      p = c%case_point(1)
      call check(error, p%nu_x == 0.0_wp .and. p%phi == 0.0_wp .and. p%bound == bound_weighted, &
         message='first case')
      if (allocated(error)) return
      p = c%case_point(2)
      call check(error, p%phi, 1.0e-3_wp, message='phi varies fastest')
      if (allocated(error)) return
      p = c%case_point(4)
      call check(error, p%nu_x, 2.0e-3_wp/19, rel=.true., thr=4*epsilon(1.0_wp), &
         message='linspace step 2e-3/19')
      if (allocated(error)) return
      p = c%case_point(60)
      call check(error, p%nu_x == 2.0e-3_wp .and. p%phi == 2.0e-3_wp .and. &
         p%bound == bound_weighted, message='last value of a range is exact')
      if (allocated(error)) return
      p = c%case_point(61)
      call check(error, p%bound == bound_clipped .and. p%nu_x == 0.0_wp, message='outer axis')
      if (allocated(error)) return
      call check(error, p%nu_y, 0.061e-3_wp, message='unswept input keeps its base value')
      if (allocated(error)) return
      call check(error, .not. c%wants_field('traction'), message='sweeps store no fields')
      if (allocated(error)) return
      ! A range point that is a short decimal is that decimal, not the rounding of the range's
      ! arithmetic (−0.1 + 0.2·3/4 = 0.05000000000000002); one that is not keeps its value.
      call load_valid('', [character(len=60) :: 'sweep%roll=-0.1,0.1', 'sweep%roll_points=5', &
         'sweep%nu_x=0,2e-3', 'sweep%nu_x_points=21'], c, error)
      if (allocated(error)) return
      ! nu_x varies fastest (21 points), then roll (5).
      p = c%case_point(3*21 + 1)
      call check(error, p%roll == 0.05_wp .and. p%nu_x == 0.0_wp, message='roll 0.05 exactly: '// &
         format_real(p%roll))
      if (allocated(error)) return
      p = c%case_point(4)
      call check(error, p%roll == -0.1_wp .and. p%nu_x == 3.0e-4_wp, message='nu_x 3e-4 '// &
         'exactly: '//format_real(p%nu_x))
      if (allocated(error)) return
      call load_valid('', [character(len=60) :: 'sweep%nu_x=0,2e-3', 'sweep%nu_x_points=20'], &
         c, error)
      if (allocated(error)) return
      p = c%case_point(8)
      call check(error, p%nu_x == 2.0e-3_wp*7/19, message='not a short decimal: '// &
         format_real(p%nu_x))
      if (allocated(error)) return
      ! A point that should be 0 (−2.8 + 4.2·2/3 = −4.4e-16).
      call load_valid('', [character(len=60) :: 'sweep%t_y=-2.8,1.4', 'sweep%t_y_points=4'], &
         c, error)
      if (allocated(error)) return
      p = c%case_point(3)
      call check(error, p%t_y == 0.0_wp, message='t_y 0 exactly: '//format_real(p%t_y))
   end subroutine test_sweep_grid

   subroutine test_sweep_list(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      type(case_point_type) :: p
      call load_valid('', [character(len=60) :: "sweep%mode=list", 'sweep%nu_x=0,1e-3,2e-3', &
         'sweep%nu_y=3e-3,4e-3,5e-3'], c, error)
      if (allocated(error)) return
      call check(error, c%n_cases(), 3)
      if (allocated(error)) return
      p = c%case_point(2)
      call check(error, p%nu_x == 1.0e-3_wp .and. p%nu_y == 4.0e-3_wp, message='list pairs')
      if (allocated(error)) return
      call expect_override_error(error, 'lists of unequal length', [character(len=60) :: &
         "sweep%mode=list", 'sweep%nu_x=0,1e-3', 'sweep%nu_y=3e-3,4e-3,5e-3'], &
         [character(len=20) :: 'equal length'])
      if (allocated(error)) return
      call expect_override_error(error, 'a range needs exactly two values', &
         [character(len=60) :: 'sweep%nu_x=0,1e-3,2e-3', 'sweep%nu_x_points=5'], &
         [character(len=20) :: 'exactly two'])
      if (allocated(error)) return
      call expect_override_error(error, 'load axis of another load mode', &
         [character(len=60) :: 'sweep%approach=0.01,0.02'], [character(len=20) :: "mode = 'force'"])
   end subroutine test_sweep_list

   subroutine test_shares_with(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      call load_valid('', [character(len=60) :: 'sweep%t_y=0,1,2', &
         'sweep%normal_force=5e4,6e4', 'sweep%nu_x=0,1e-3,2e-3,3e-3'], c, error)
      if (allocated(error)) return
      ! Case 14 = t_y index 2, force index 2, nu_x index 2 (4 nu_x per force, 8 per t_y).
      call check(error, c%shares_with(14, axis_geometry), 9, message='same geometry from case 9')
      if (allocated(error)) return
      call check(error, c%shares_with(14, axis_load), 13, message='same normal from case 13')
      if (allocated(error)) return
      call load_valid('', [character(len=60) :: 'sweep%mode=list', 'sweep%t_y=0,1,0', &
         'sweep%nu_x=0,1e-3,2e-3'], c, error)
      if (allocated(error)) return
      call check(error, c%shares_with(3, axis_geometry), 1, message='list: equal t_y found')
   end subroutine test_shares_with

   subroutine test_round_trip(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c, d
      character(len=:), allocatable :: text
      integer :: i
      call load_valid('', [character(len=60) :: 'creepage%nu_x=1.23456789012345e-4', &
         "profiles%wheel=it's.prw", 'sweep%phi=0,2e-3', 'sweep%phi_points=21', &
         'sweep%bound=weighted,clipped', 'track%rail_canted=.true.'], c, error)
      if (allocated(error)) return
      call read_back(c, d, text, error)
      if (allocated(error)) return
      call check(error, d%creepage%nu_x == c%creepage%nu_x, message='exact real round trip')
      if (allocated(error)) return
      call check(error, d%profiles%wheel == "it's.prw", message='quotes in strings')
      if (allocated(error)) return
      call check(error, d%n_cases() == 42 .and. d%track%rail_canted, message='sweep and logical')
      if (allocated(error)) return
      ! Every help comment is whole: none fills its field (a longer one would be cut), and the
      ! longest ones end as written.
      call check(error, all(len_trim(variables%help) < len(variables%help)), &
         message='a variable''s help text fills its field and may be cut')
      if (allocated(error)) return
      ! Every choice variable's line lists the registry's choices (--check shows them).
      do i = 1, size(variables)
         if (variables(i)%kind /= k_choice) cycle
         call check(error, index(text, '  '//trim(variables(i)%name)//' = ') > 0 .and. &
            index(text, choice_list(variable_choices(variables(i)%group, variables(i)%name))) &
            > 0, message='choices of '//trim(variables(i)%name)//' not printed')
         if (allocated(error)) return
      end do
   end subroutine test_round_trip

   subroutine test_format_real(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: values(*) = [0.0_wp, 1.0_wp, -2.5e-12_wp, 0.58e-3_wp, 64700.0_wp, &
         1.0_wp/3.0_wp, huge(1.0_wp), tiny(1.0_wp), 123456789.0_wp, 0.1_wp, -7.0e6_wp]
      integer :: i
      real(wp) :: back
      character(len=:), allocatable :: text
      do i = 1, size(values)
         text = format_real(values(i))
         read (text, *) back
         call check(error, back == values(i), message='round trip of '//format_real(values(i)))
         if (allocated(error)) return
      end do
      call check(error, format_real(64700.0_wp) == '64700.0', message=format_real(64700.0_wp))
      if (allocated(error)) return
      call check(error, format_real(0.58e-3_wp) == '0.00058', message=format_real(0.58e-3_wp))
      if (allocated(error)) return
      call check(error, format_real(2.74e-5_wp) == '2.74e-5', message=format_real(2.74e-5_wp))
      if (allocated(error)) return
      ! Numbers typed with 15 digits or fewer whose 16-digit form is noise come out as typed.
      call check(error, format_real(8.2_wp) == '8.2' .and. format_real(6.0e-4_wp) == &
         '0.0006' .and. format_real(9.36_wp) == '9.36' .and. format_real(0.088_wp) == '0.088' &
         .and. format_real(-8.03_wp) == '-8.03' .and. format_real(0.3_wp) == '0.3', &
         message='8.2, 6e-4, 9.36, 0.088, -8.03, 0.3: '//format_real(8.2_wp)//' '// &
         format_real(6.0e-4_wp)//' '//format_real(9.36_wp)//' '//format_real(0.088_wp)//' '// &
         format_real(-8.03_wp)//' '//format_real(0.3_wp))
      if (allocated(error)) return
      call check_random_round_trips(error)
   end subroutine test_format_real

   !> Seeded random numbers of every magnitude read back exactly, and random decimals of 1 to
   !> 15 significant digits come out with no more digits than they were typed with.
   subroutine check_random_round_trips(error)
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: seed(:)
      integer :: i, n, digits, expo, k
      real(wp) :: u, x, back
      character(len=40) :: typed
      character(len=:), allocatable :: text
      call random_seed(size=n)
      allocate (seed(n))
      seed = 20261129
      call random_seed(put=seed)
      do i = 1, 20000
         call random_number(u)
         expo = int(40.0_wp*u) - 20
         call random_number(u)
         digits = 1 + int(15.0_wp*u)
         call random_number(u)
         ! A decimal of `digits` significant digits, as a user types it.
         write (typed, '(i0,a,i0)') max(1_int64, int(u*10.0_wp**digits, int64)), 'e', expo
         read (typed, *) x
         text = format_real(x)
         read (text, *) back
         call check(error, back == x, message='round trip of '//trim(typed)//': '//text)
         if (allocated(error)) return
         ! Non-zero digits of the mantissa (a lower bound of its significant digits).
         n = index(text, 'e') - 1
         if (n < 0) n = len(text)
         k = count([(scan(text(k:k), '123456789') > 0, k = 1, n)])
         call check(error, k <= digits, message=trim(typed)//' printed with more digits: '//text)
         if (allocated(error)) return
         ! Any bit pattern (computed numbers).
         call random_number(u)
         x = (u - 0.5_wp)*10.0_wp**expo
         text = format_real(x)
         read (text, *) back
         call check(error, back == x, message='round trip of a computed number: '//text)
         if (allocated(error)) return
      end do
   end subroutine check_random_round_trips

   !> `&kinematics`: values, units, the pure-rolling pitch rate and the defaults that kinematic
   !> mode changes (vertical load, 'additive' spin model).
   subroutine test_kinematics(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      type(case_point_type) :: p
      character(len=:), allocatable :: name
      integer :: ia

      call load_valid('', no_overrides, c, error)
      if (allocated(error)) return
      call check(error, .not. c%is_kinematic() .and. c%load%mode == load_mode_force .and. &
         c%tangential%spin_model == spin_uniform, message='kinematics off by default, unchanged '// &
         'defaults of the prescribed-creepage mode')
      if (allocated(error)) return
      do ia = 1, n_sweep_axes
         if (c%reports_input(ia)) call test_failed(error, 'input '// &
            trim(sweep_axis_names(ia))//' reported without a sweep')
         if (allocated(error)) return
      end do

      name = scratch_file('kinematics', [character(len=80) :: &
         '&position t_y = 4.733 /', &
         '&kinematics', &
         "  mode = 'on', yaw = 0.004, v_forward = 30000.0, v_lateral = 100.0", &
         '  v_vertical = -5.0, roll_rate = 0.01, yaw_rate = -0.02', &
         '/', &
         '&sweep v_forward = 10000, 20000 /'])
      call load_valid(name, no_overrides, c, error)
      if (delete_file(name)) continue
      if (allocated(error)) return
      call check(error, c%is_kinematic(), message='mode on')
      if (allocated(error)) return
      call check(error, c%load%mode == load_mode_vertical, message='kinematic mode loads the wheel '// &
         'vertically unless &load mode is given')
      if (allocated(error)) return
      call check(error, c%tangential%spin_model == spin_additive, message='additive spin model')
      if (allocated(error)) return
      call check(error, .not. c%kinematics%pitch_rate_given, message='pitch rate not given')
      if (allocated(error)) return
      p = c%case_point(2)
      call check(error, p%yaw == 0.004_wp .and. p%v_forward == 20000.0_wp .and. &
         p%v_lateral == 100.0_wp .and. p%v_vertical == -5.0_wp .and. p%roll_rate == 0.01_wp &
         .and. p%yaw_rate == -0.02_wp .and. p%t_y == 4.733_wp, message='case inputs')
      if (allocated(error)) return
      call check(error, p%pitch_rate == -20000.0_wp/460.0_wp, &
         message='pure rolling at the case speed: -v_forward/nominal_radius')
      if (allocated(error)) return
      do ia = 1, n_sweep_axes
         if (trim(sweep_axis_names(ia)) == 'v_lateral') exit
      end do
      call check(error, c%reports_input(ia), message='a kinematic run reports its wheelset inputs')
      if (allocated(error)) return

      ! A pitch rate given is used as it is; the load mode given is kept.
      call load_valid('', [character(len=40) :: 'kinematics%mode=on', &
         'kinematics%pitch_rate=-60', 'load%mode=force'], c, error)
      if (allocated(error)) return
      p = c%case_point(1)
      call check(error, p%pitch_rate == -60.0_wp .and. c%load%mode == load_mode_force .and. &
         p%v_forward == 30000.0_wp, message='given pitch rate and load mode; V = 30 m/s default')
   end subroutine test_kinematics

   !> Range and consistency errors of `&kinematics`, each naming the file, the line, the
   !> variable, the value and what is expected (with units).
   subroutine test_kinematics_errors(error)
      type(error_type), allocatable, intent(out) :: error
      call expect_error(error, 'k_yaw', [character(len=40) :: "&kinematics mode = 'on',", &
         '  yaw = 0.2 /'], [character(len=80) :: 'k_yaw.nml:2', '&kinematics yaw = 0.2', &
         'out of range; expected -0.1 <= yaw <= 0.1 rad'], stat_invalid_input)
      if (allocated(error)) return
      call expect_error(error, 'k_speed', [character(len=60) :: &
         "&kinematics mode = 'on', v_forward = -5 /"], [character(len=80) :: 'k_speed.nml:1', &
         '&kinematics v_forward = -5.0', 'expected 0.0 < v_forward <= 200000.0 mm/s'])
      if (allocated(error)) return
      call expect_error(error, 'k_pitch', [character(len=40) :: '&kinematics', &
         "  mode = 'on'", '  pitch_rate = 65.2', '/'], [character(len=80) :: 'k_pitch.nml:3', &
         '&kinematics pitch_rate = 65.2', 'expected -2000.0 <= pitch_rate < 0.0 rad/s'])
      if (allocated(error)) return
      call expect_error(error, 'k_rate', [character(len=40) :: '&kinematics yaw_rate = 20 /'], &
         [character(len=80) :: '&kinematics yaw_rate = 20.0', '-10.0 <= yaw_rate <= 10.0 rad/s'])
      if (allocated(error)) return
      call expect_error(error, 'k_vlat', [character(len=40) :: '&kinematics v_lateral = 2e4 /'], &
         [character(len=80) :: '-10000.0 <= v_lateral <= 10000.0 mm/s'])
      if (allocated(error)) return
      call expect_error(error, 'k_mode', [character(len=40) :: "&kinematics mode = 'yes' /"], &
         [character(len=80) :: "&kinematics mode = 'yes' is not allowed", "'off', 'on'"])
      if (allocated(error)) return
      call expect_error(error, 'k_unit', [character(len=40) :: "&kinematics speed = 3e4 /"], &
         [character(len=80) :: 'unknown variable "speed"', 'v_forward'])
      if (allocated(error)) return
      call expect_error(error, 'k_creep', [character(len=40) :: "&kinematics mode = 'on' /", &
         '&creepage nu_x = 1e-3 /'], [character(len=100) :: 'k_creep.nml:2', &
         "&creepage nu_x is given, but &kinematics mode = 'on'", 'remove &creepage'])
      if (allocated(error)) return
      call expect_error(error, 'k_spin', [character(len=40) :: "&kinematics mode = 'on' /", &
         "&tangential spin_model = 'uniform' /"], [character(len=80) :: 'k_spin.nml:2', &
         "spin_model = 'additive'"])
      if (allocated(error)) return
      call expect_error(error, 'k_sweep_off', [character(len=40) :: '&sweep yaw = 0, 0.004 /'], &
         [character(len=80) :: 'k_sweep_off.nml:1', '&sweep yaw is given', &
         "&kinematics mode = 'off'"])
      if (allocated(error)) return
      call expect_error(error, 'k_sweep_nu', [character(len=40) :: "&kinematics mode = 'on' /", &
         '&sweep nu_y = 0, 1e-3 /'], [character(len=80) :: 'k_sweep_nu.nml:2', &
         '&sweep nu_y is given', 'wheelset inputs'])
      if (allocated(error)) return
      call expect_error(error, 'k_sweep_range', [character(len=40) :: &
         "&kinematics mode = 'on' /", '&sweep pitch_rate = -60, 0 /'], [character(len=80) :: &
         '&sweep pitch_rate(2) = 0.0', 'pitch_rate < 0.0 rad/s'])
   end subroutine test_kinematics_errors

   !> The printed namelist of a kinematic run (no &creepage, the pitch rate left to pure rolling)
   !> reads back to itself.
   subroutine test_kinematics_round_trip(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c, d
      type(case_point_type) :: p
      character(len=:), allocatable :: text
      call load_valid('', [character(len=60) :: 'kinematics%mode=on', 'kinematics%yaw=0.004', &
         'sweep%t_y=0,4.733,8', 'sweep%v_forward=1e4,3e4'], c, error)
      if (allocated(error)) return
      call read_back(c, d, text, error)
      if (allocated(error)) return
      call check(error, index(text, '&creepage') == 0 .or. index(text, '! &creepage') > 0, &
         message='&creepage is left out in kinematic mode')
      if (allocated(error)) return
      p = d%case_point(6)
      call check(error, d%n_cases() == 6 .and. .not. d%kinematics%pitch_rate_given .and. &
         p%pitch_rate == -3.0e4_wp/460.0_wp, message='sweep and pure rolling')
   end subroutine test_kinematics_round_trip

   !> A `&load` quantity that the load mode does not read (it would be ignored) is refused,
   !> naming where it was given, the mode and the quantity the mode reads; the resolved namelist
   !> leaves the unread quantities as comments, so that it reads back.
   subroutine test_load_quantity_of_another_mode(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c, d
      character(len=:), allocatable :: text
      call expect_error(error, 'l_force', [character(len=60) :: &
         "&load mode = 'force', approach = 0.1 /"], [character(len=100) :: 'l_force.nml:1', &
         "&load approach is given, but &load mode = 'force' does not read it", &
         "(it reads normal_force)", "('approach')"])
      if (allocated(error)) return
      call expect_error(error, 'l_vert', [character(len=60) :: "&load mode = 'approach',", &
         '  vertical_force = 5e4 /'], [character(len=100) :: 'l_vert.nml:2', &
         "&load vertical_force is given, but &load mode = 'approach'", '(it reads approach)'])
      if (allocated(error)) return
      ! The kinematic mode's default load mode is 'vertical': a normal force is not read.
      call expect_error(error, 'l_kin', [character(len=60) :: "&kinematics mode = 'on' /", &
         '&load normal_force = 5e4 /'], [character(len=100) :: 'l_kin.nml:2', &
         "&load mode = 'vertical' does not read it", "'force' or 'shared-force'"])
      if (allocated(error)) return
      call load_valid('', [character(len=60) :: 'load%mode=shared-force', &
         'load%normal_force=5e4'], c, error)
      if (allocated(error)) return
      call load_valid('', [character(len=60) :: 'load%mode=approach', 'load%approach=0.08'], c, &
         error)
      if (allocated(error)) return
      call read_back(c, d, text, error)
      if (allocated(error)) return
      call check(error, d%load%approach == 0.08_wp .and. index(text, &
         '! normal_force not read by this mode') > 0 .and. index(text, &
         '! vertical_force not read by this mode') > 0, message='resolved namelist: '//text)
   end subroutine test_load_quantity_of_another_mode

end module test_config
