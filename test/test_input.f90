!> The input side of issue 24: case files from pipes, NUL and control bytes, tiny friction,
!> repeated variables of every kind, one range table for the app and the library, long sweep
!> lists, numbers beyond the double range. Each reproducer is run as the issue wrote it.
module test_input
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   use shcontact_core_text, only: format_real
   use shcontact_core_error, only: shc_error_type => error_type
   use shcontact_core_ranges, only: ranges, find_range, range_key, k_int, in_range, max_grid_cells
   use shcontact_core_material, only: material_type
   use shcontact_geometry_track, only: track_type
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_geometry_kinematics, only: max_yaw
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type, bound_parabolic
   use shcontact_api_context, only: contact_context_type, context_set_option, &
      context_set_material, context_set_track, context_message, context_solve
   use shcontact_api_values, only: result_value_count
   use shcontact_input_config, only: case_config_type, load_config, read_config_text, &
      config_namelist
   use shcontact_output_report, only: report_line
   use shcontact_input_config_sweep, only: axis_index
   use shcontact_input_config_variables, only: variables, k_real, k_int
   use shcontact_input_config_choices, only: load_mode_reading
   use shcontact_case_result, only: case_summary_type
   use test_fuzz_support, only: library_status, reset_library, samples, &
      new_library, library_option_fuzz
   use test_app, only: program_path, scratch_directory, shell, run_program, file_text, &
      write_lines, unavailable, expect_in
   implicit none
   private
   public :: collect_input

contains

   subroutine collect_input(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('case_file_from_a_pipe', test_pipe), &
         new_unittest('binary_stream_refused', test_binary), &
         new_unittest('nul_and_control_bytes_reported', test_nul), &
         new_unittest('tiny_friction_refused', test_tiny_friction), &
         new_unittest('json_never_prints_nan', test_json_null), &
         new_unittest('repeated_string_list_cli', test_repeated_cli), &
         new_unittest('repeated_variables_every_kind', test_repeated_kinds), &
         new_unittest('library_setter_reproducers', test_setter_reproducers), &
         new_unittest('ranges_app_equals_library', test_ranges_compare), &
         new_unittest('range_defaults_app_and_library', test_range_defaults), &
         new_unittest('long_sweep_list_linear', test_long_list), &
         new_unittest('number_beyond_double_range', test_overflow), &
         new_unittest('library_option_fuzz', test_option_fuzz), &
         new_unittest('doc_geometry_two_candidates', test_two_candidates), &
         new_unittest('doc_lobes_shared_force', test_shared_force_doc) &
         ]
   end subroutine collect_input

   ! ------------------------------------------------------------------------------------------
   ! Helpers
   ! ------------------------------------------------------------------------------------------

   !> Run `producer | shcontact ARGS` in dir (stdout, stderr to out.txt, err.txt).
   integer function run_piped(dir, producer, args) result(stat)
      character(len=*), intent(in) :: dir, producer, args
      call shell('cd '//dir//' && '//producer//' | OMP_NUM_THREADS=2 '//program_path()//' '// &
         args//' > out.txt 2> err.txt', stat)
   end function run_piped

   !> Exit status `status` and exactly one line on stderr holding `fragment`.
   subroutine expect_one_message(error, dir, stat, status, fragment, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, fragment, what
      integer, intent(in) :: stat, status
      character(len=:), allocatable :: err
      integer :: i
      err = file_text(dir//'/err.txt')
      call check(error, stat, status, message=what//': exit status; stderr: '//err)
      if (allocated(error)) return
      call expect_in(error, err, fragment, what)
      if (allocated(error)) return
      if (count([(err(i:i) == new_line('a'), i=1, len(err))]) /= 1) call test_failed(error, what//': expected one message: '//err)
   end subroutine expect_one_message

   !> True when the app accepts `key=value` as the only override of the default case.
   logical function app_accepts(key, value, message)
      character(len=*), intent(in) :: key, value
      character(len=:), allocatable, intent(out) :: message
      type(case_config_type) :: config
      type(shc_error_type), allocatable :: err
      character(len=80) :: override(2)
      ! A load quantity with the mode that reads it (another mode refuses it as ignored).
      override(1) = 'load%mode='//load_mode_reading(key(index(key, '%') + 1:))
      override(2) = key//'='//value
      call load_config('', override, config, err)
      app_accepts = .not. allocated(err)
      message = ''
      if (allocated(err)) message = err%message
   end function app_accepts


   ! ------------------------------------------------------------------------------------------
   ! Item 1: pipes, process substitution, /dev/stdin; item 3: NUL and control bytes
   ! ------------------------------------------------------------------------------------------

   !> `shcontact run <(printf '&position t_y = 2.0 /\n') --format csv -q` ran the default
   !> t_y = 4.733 (the reader sized the file with inquire(size=), 0 for a pipe).
   subroutine test_pipe(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_pipe')
      call shell('cd '//dir//" && bash -c ""OMP_NUM_THREADS=2 "//program_path()// &
         " run <(printf '&position t_y = 2.0 /\n') --format csv -q -o s.h5"" > out.txt "// &
         '2> err.txt', stat)
      out = file_text(dir//'/out.txt')
      call check(error, stat, 0, message='process substitution: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! The CSV's 5th column is t_y.
      call check(error, csv_value(out, 't_y'), 2.0_wp, message='process substitution: '//out)
      if (allocated(error)) return
      stat = run_piped(dir, "printf '&position t_y = 2.5 /\n'", 'run /dev/stdin --check')
      call check(error, stat, 0, message='/dev/stdin: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 't_y = 2.5', '/dev/stdin')
      if (allocated(error)) return
      ! A named pipe, written by another process.
      call shell('cd '//dir//" && mkfifo fifo.nml && (printf '&material friction = 0.2 /\n' "// &
         '> fifo.nml &) && '//program_path()//' run fifo.nml --check > out.txt 2> err.txt', stat)
      call check(error, stat, 0, message='named pipe: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'friction = 0.2', 'named pipe')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_pipe

   !> `/dev/urandom` passed `--check`; a stream of more than 256 MiB is refused as not a case
   !> file, both with status 2 and one message naming the file.
   subroutine test_binary(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_binary')
      stat = run_program(dir, 'run /dev/urandom --check')
      call expect_one_message(error, dir, stat, 2, '/dev/urandom:', '/dev/urandom')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'must be text', '/dev/urandom')
      if (allocated(error)) return
      stat = run_piped(dir, 'yes | head -c 300000000', 'run /dev/stdin --check')
      call expect_one_message(error, dir, stat, 2, '/dev/stdin: the case file is larger than', &
         'a 300 MB stream')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_binary

   !> `&position t_y = 2.0, roll = 0.01\0 /` gave roll = 0 with `--check` exit 0.
   subroutine test_nul(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_nul')
      call shell("printf '&position t_y = 2.0, roll = 0.01\0 /\n' > "//dir//'/nul.nml')
      stat = run_program(dir, 'run nul.nml --check')
      call expect_one_message(error, dir, stat, 2, 'nul.nml:1: a NUL byte', 'NUL')
      if (allocated(error)) return
      call shell("printf '&position\n t_y = 2.0, roll = 0.01\033 /\n' > "//dir//'/esc.nml')
      stat = run_program(dir, 'run esc.nml --check')
      call expect_one_message(error, dir, stat, 2, 'esc.nml:2: a control character <0x1B> '// &
         'in column 24', 'ESC')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_nul

   ! ------------------------------------------------------------------------------------------
   ! Item 4: tiny friction, JSON
   ! ------------------------------------------------------------------------------------------

   !> `--set material%friction=1e-300 --format json` printed "coulomb_ratio":NaN with status 0;
   !> μ = 4.9e-324 made every force NaN. Now μ < 0.001 is out of range (core/ranges), and at
   !> the limit the forces are finite and within Coulomb's bound |F| <= μ F_n.
   subroutine test_tiny_friction(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out
      real(wp) :: fn, fx, fy
      integer :: stat, i
      character(len=*), parameter :: tiny_values(2) = [character(len=9) :: '1e-300', '4.9e-324']
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_friction')
      do i = 1, size(tiny_values)
         stat = run_program(dir, 'run --set material%friction='//trim(tiny_values(i))// &
            ' --format json -q -o t.h5')
         call expect_one_message(error, dir, stat, 2, 'friction = ', trim(tiny_values(i)))
         if (allocated(error)) return
         call expect_in(error, file_text(dir//'/err.txt'), 'expected 0.001 <= friction', &
            trim(tiny_values(i)))
         if (allocated(error)) return
         call check(error, index(file_text(dir//'/out.txt'), 'NaN') == 0, &
            message='NaN printed for '//trim(tiny_values(i)))
         if (allocated(error)) return
      end do
      stat = run_program(dir, 'run --set material%friction=0.001 --set normal%n_strips=40 '// &
         '--set tangential%n_elements=20 --format csv -q -o t.h5')
      call check(error, stat, 0, message='mu = 0.001: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      out = file_text(dir//'/out.txt')
      fn = csv_value(out, 'fn')
      fx = csv_value(out, 'fx')
      fy = csv_value(out, 'fy')
      call check(error, fn > 0.0_wp .and. hypot(fx, fy) <= 1.0e-3_wp*fn* &
         (1.0_wp + 1.0e-9_wp) .and. hypot(fx, fy) > 0.0_wp, message='mu = 0.001: forces '// &
         'not within 0 < |F| <= mu F_n: '//out)
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_tiny_friction

   !> doc/geometry.md's table of the default case's two candidate patches at t_y = 4.5 and
   !> 5.0 mm under a vertical load of 64.7 kN, from the command it names (the CSV of the same
   !> run): the tread patch's N and δ, the corner's N (the wheel's sum less the tread's), as
   !> the table rounds them.
   subroutine test_two_candidates(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out
      real(wp), parameter :: t_y(2) = [4.5_wp, 5.0_wp], tread_n(2) = [65.15_wp, 45.93_wp], &
         tread_delta(2) = [0.0821_wp, 0.0596_wp], corner_n(2) = [0.0_wp, 20.0_wp], &
         force_delta(2) = [0.0817_wp, 0.0781_wp]
      integer :: stat, i
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_candidates')
      do i = 1, size(t_y)
         stat = run_program(dir, 'run --set position%t_y='//format_real(t_y(i))// &
            ' --set load%mode=vertical --set load%vertical_force=64700 --format csv -q '// &
            '--no-output')
         call check(error, stat, 0, message='t_y '//format_real(t_y(i))//': '// &
            file_text(dir//'/err.txt'))
         if (allocated(error)) return
         out = file_text(dir//'/out.txt')
         call check(error, abs(csv_value(out, 'fn')/1000.0_wp - tread_n(i)) <= 0.005_wp .and. &
            abs(csv_value(out, 'delta') - tread_delta(i)) <= 0.00005_wp .and. &
            abs((csv_value(out, 'wheel_fn') - csv_value(out, 'fn'))/1000.0_wp - corner_n(i)) &
            <= 0.005_wp, message='t_y '//format_real(t_y(i))//': not doc/geometry.md''s '// &
            'table: '//out)
         if (allocated(error)) return
         ! The force mode's column: the deepest patch's δ under 64.7 kN.
         call expect_columns(error, dir, 'run --set position%t_y='//format_real(t_y(i))// &
            ' --format csv -q --no-output', [character(len=5) :: 'delta'], [force_delta(i)], &
            [1.0e-4_wp])
         if (allocated(error)) return
      end do
      call shell('rm -rf '//dir)
   end subroutine test_two_candidates

   !> doc/lobes.md's figures of the plain and the shared normal force at the default case
   !> ("The plain normal force"), from the commands it names, each to its printed digit.
   subroutine test_shared_force_doc(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_shared_doc')
      ! shcontact run --format csv: F_x −5841.0 N, f_x −0.3009, f_y −0.3621.
      call expect_columns(error, dir, 'run --format csv -q --no-output', &
         [character(len=8) :: 'fx', 'fx_norm', 'fy_norm'], [-5841.0_wp, -0.3009_wp, -0.3621_wp], &
         [0.1_wp, 1.0e-4_wp, 1.0e-4_wp])
      if (allocated(error)) return
      ! --set load%mode=shared-force: the main patch 62.27 kN (the second the rest of 64.7 kN,
      ! 2.43), F_x −5612.3 N, f_x −0.3004, f_y −0.3632, fx_total −6337.4 N.
      call expect_columns(error, dir, 'run --set load%mode=shared-force --format csv -q '// &
         '--no-output', [character(len=8) :: 'fn', 'fx', 'fx_norm', 'fy_norm', 'fx_total'], &
         [62270.0_wp, -5612.3_wp, -0.3004_wp, -0.3632_wp, -6337.4_wp], &
         [10.0_wp, 0.1_wp, 1.0e-4_wp, 1.0e-4_wp, 0.1_wp])
      call shell('rm -rf '//dir)
   end subroutine test_shared_force_doc

   !> Run the program in `dir` and require each CSV column `names(k)` of its first case to
   !> equal `values(k)` within half of `units(k)` (the unit of the last printed digit).
   subroutine expect_columns(error, dir, args, names, values, units)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, args
      character(len=*), intent(in) :: names(:)
      real(wp), intent(in) :: values(:), units(:)
      character(len=:), allocatable :: out
      integer :: stat, k
      stat = run_program(dir, args)
      call check(error, stat, 0, message=args//': '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      out = file_text(dir//'/out.txt')
      do k = 1, size(names)
         call check(error, abs(csv_value(out, trim(names(k))) - values(k)) <= &
            0.5_wp*units(k)*(1.0_wp + 1.0e-9_wp), message=args//': '//trim(names(k))// &
            ' is not the doc''s '//format_real(values(k))//': '//out)
         if (allocated(error)) return
      end do
   end subroutine expect_columns

   !> The value of column `name` of the first case of CSV output (header, then lines).
   real(wp) function csv_value(csv, name) result(x)
      character(len=*), intent(in) :: csv, name
      character(len=:), allocatable :: h, line
      integer :: k, i, pos, start, nl, stat
      x = ieee_value(1.0_wp, ieee_quiet_nan)
      nl = index(csv, new_line('a'))
      if (nl == 0) return
      h = ','//csv(1:nl - 1)//','
      line = csv(nl + 1:)
      pos = index(h, ','//name//',')
      if (pos == 0) return
      k = 0
      do i = 1, pos
         if (h(i:i) == ',') k = k + 1
      end do
      start = 1
      do i = 1, k - 1
         start = start + index(line(start:), ',')
      end do
      read (line(start:start + scan(line(start:), ','//new_line('a')) - 2), *, iostat=stat) x
      if (stat /= 0) x = ieee_value(1.0_wp, ieee_quiet_nan)
   end function csv_value

   !> JSON has no NaN: a summary value that is not finite is written as null.
   subroutine test_json_null(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(shc_error_type), allocatable :: err
      type(case_summary_type) :: summary
      character(len=:), allocatable :: line
      character(len=80) :: none(0)
      call load_config('', none, config, err)
      call check(error, .not. allocated(err), message='default configuration')
      if (allocated(error)) return
      summary%stat = 0
      summary%n_patches = 1
      summary%n_loaded = 1
      summary%fn = 64700.0_wp
      summary%coulomb_ratio = ieee_value(1.0_wp, ieee_quiet_nan)
      line = report_line(config, 1, summary, 'json')
      call check(error, index(line, 'NaN') == 0 .and. index(line, '"coulomb_ratio":null') > 0 &
         .and. index(line, '"fn":64700.0') > 0, message='JSON line: '//line)
   end subroutine test_json_null

   ! ------------------------------------------------------------------------------------------
   ! Item 7: repeated variables
   ! ------------------------------------------------------------------------------------------

   !> `shcontact run examples/pure_spin.nml --set sweep%bound=clipped` and
   !> `&sweep bound='weighted' bound='clipped' /` crashed ("already allocated variable 'axis'").
   subroutine test_repeated_cli(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_repeat')
      call shell('cp examples/pure_spin.nml '//dir//'/')
      stat = run_program(dir, 'run pure_spin.nml --set sweep%bound=clipped --check')
      call check(error, stat, 0, message='pure_spin --set sweep%bound: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      out = file_text(dir//'/out.txt')
      call expect_in(error, out, "  bound = 'clipped'  !", 'the later list wins')
      if (allocated(error)) return
      call write_lines(dir//'/twice.nml', [character(len=60) :: &
         "&sweep bound='weighted' bound='clipped' /"])
      stat = run_program(dir, 'run twice.nml --check')
      call check(error, stat, 0, message='bound twice: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), "  bound = 'clipped'  !", 'bound twice')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_repeated_cli

   !> A variable given twice (in a group, or in the file and again with --set): the later
   !> assignment wins, whole lists included (doc/app.md, "Repeated variables"), for every kind.
   subroutine test_repeated_kinds(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: c
      type(shc_error_type), allocatable :: err
      character(len=*), parameter :: nl = new_line('a')
      call read_config_text("&position t_y = 1.0, t_y = 2.0 /"//nl// &
         "&normal n_strips = 30 n_strips = 40 /"//nl// &
         "&tangential bound = 'clipped', bound = 'parabolic' /"//nl// &
         "&track rail_canted = .true., rail_canted = .false. /"//nl// &
         "&output fields = 'pressure', 'slip', fields = 'state' /"//nl// &
         "&sweep t_y = 1, 2, 3, t_y = 4, 5, bound = 'weighted', 'clipped', "// &
         "bound = 'ellipsoidal', phi_points = 3, phi = 0, 1e-3, phi_points = 0 /", &
         'twice', c, err)
      if (allocated(err)) then
         call test_failed(error, 'repeated variables refused: '//err%message)
         return
      end if
      call check(error, c%position%t_y, 2.0_wp, message='real')
      if (allocated(error)) return
      call check(error, c%normal%n_strips, 40, message='integer')
      if (allocated(error)) return
      call check(error, c%tangential%bound, bound_parabolic, message='choice')
      if (allocated(error)) return
      call check(error, .not. c%track%rail_canted, message='logical')
      if (allocated(error)) return
      call check(error, c%output%fields(1) == 'state' .and. len_trim(c%output%fields(2)) == 0, &
         message='string list (output%fields)')
      if (allocated(error)) return
      call check(error, size(c%sweep%axes(axis_of(c, 't_y'))%given) == 2, &
         message='real list (sweep t_y)')
      if (allocated(error)) return
      associate (b => c%sweep%axes(axis_of(c, 'bound')))
         call check(error, size(b%labels) == 1, message='string list (sweep bound)')
         if (allocated(error)) return
         call check(error, b%labels(1), 'ellipsoidal', message='string list (sweep bound)')
         if (allocated(error)) return
      end associate
      call check(error, c%sweep%axes(axis_of(c, 'phi'))%points, 0, message='integer (_points)')
      if (allocated(error)) return
      ! The file's value, then --set: the command line wins, for every kind.
      call load_config('', [character(len=60) :: 'sweep%bound=weighted,clipped', &
         'sweep%bound=clipped', 'output%fields=slip', 'output%fields=state,pressure', &
         'sweep%nu_x=1e-3,2e-3,3e-3', 'sweep%nu_x=0', 'normal%n_strips=30', &
         'normal%n_strips=50'], c, err)
      if (allocated(err)) then
         call test_failed(error, 'repeated overrides refused: '//err%message)
         return
      end if
      call check(error, size(c%sweep%axes(axis_of(c, 'bound'))%labels) == 1 .and. &
         size(c%sweep%axes(axis_of(c, 'nu_x'))%given) == 1 .and. c%normal%n_strips == 50 &
         .and. c%output%fields(2) == 'pressure', message='repeated overrides: the last wins')
   end subroutine test_repeated_kinds

   !> Index of the sweep axis `name`.
   integer function axis_of(c, name) result(ia)
      type(case_config_type), intent(in) :: c
      character(len=*), intent(in) :: name
      ia = axis_index(name)
      if (ia < 1 .or. ia > size(c%sweep%axes)) ia = 1
   end function axis_of

   ! ------------------------------------------------------------------------------------------
   ! Item 8: one range table for the app and the library
   ! ------------------------------------------------------------------------------------------

   !> `shcontact_set_option(h, "normal%n_strips", "100000")` and ("tangential%n_elements",
   !> "1000000") returned 0; `wheel_smoothing = 1e9`, R0 = 1 mm and n_strips = 1 were accepted.
   subroutine test_setter_reproducers(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_context_type) :: ctx
      type(track_type) :: t
      real(wp) :: values(result_value_count)
      call new_library(error, ctx)
      if (allocated(error)) return
      call check(error, context_set_option(ctx, 'normal%n_strips', '100000'), 2, &
         message='n_strips = 100000 (5e6 cells with 50 elements)')
      if (allocated(error)) return
      call check(error, context_set_option(ctx, 'tangential%n_elements', '1000000'), 2, &
         message='n_elements = 1000000')
      if (allocated(error)) return
      call check(error, context_set_option(ctx, 'profiles%wheel_smoothing', '1e9'), 2, &
         message='wheel_smoothing = 1e9')
      if (allocated(error)) return
      call check(error, context_set_option(ctx, 'normal%n_strips', '1'), 2, &
         message='n_strips = 1')
      if (allocated(error)) return
      call check(error, context_set_track(ctx, t%gauge, t%gauge_height, t%rail_inclination, &
         t%rail_canted, t%flange_back_distance, t%flange_back_position, 1.0_wp), 2, &
         message='R0 = 1 mm')
      if (allocated(error)) return
      call check(error, context_set_material(ctx, 82670.0_wp, 0.27_wp, 1.0e-300_wp), 2, &
         message='mu = 1e-300')
      if (allocated(error)) return
      ! The per-call inputs of a solve: the program's load and creepage ranges.
      call check(error, context_solve(ctx, 4.733_wp, 0.0_wp, 1, 1.0e-300_wp, 5.8e-4_wp, &
         6.1e-5_wp, 2.74e-4_wp, values), 2, message='normal force 1e-300 N')
      if (allocated(error)) return
      call check(error, context_solve(ctx, 4.733_wp, 0.0_wp, 2, 4.9e-324_wp, 5.8e-4_wp, &
         6.1e-5_wp, 2.74e-4_wp, values), 2, message='vertical force 4.9e-324 N')
      if (allocated(error)) return
      call check(error, context_solve(ctx, 4.733_wp, 0.0_wp, 1, 64700.0_wp, 2.0_wp, &
         6.1e-5_wp, 2.74e-4_wp, values), 2, message='nu_x = 2')
      if (allocated(error)) return
      ! Accepted values still work, and the grid limit holds for the pair.
      call check(error, context_set_option(ctx, 'normal%n_strips', '200'), 0, &
         message='n_strips = 200: '//context_message(ctx))
      if (allocated(error)) return
      call check(error, context_set_option(ctx, 'tangential%n_elements', str_int( &
         max_grid_cells/200 + 1)), 2, message='200 strips x too many elements')
   end subroutine test_setter_reproducers

   !> Every numeric input the library takes (option setter, set_material, the track check) is
   !> accepted by the library exactly when the app accepts it, sampled below, at and above each
   !> limit, inside, and at tiny and huge values; the app checks every table entry.
   subroutine test_ranges_compare(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_context_type) :: ctx
      character(len=:), allocatable :: app_message, lib_message, key, text
      real(wp), allocatable :: x(:)
      integer :: ir, i, lib, n_lib
      logical :: app
      call new_library(error, ctx)
      if (allocated(error)) return
      n_lib = 0
      do ir = 1, size(ranges)
         key = trim(range_key(ranges(ir)))
         x = samples(ir)
         do i = 1, size(x)
            if (ranges(ir)%kind == k_int) then
               if (abs(x(i)) > real(huge(1), wp)) cycle
               text = str_int(nint(x(i)))
            else
               text = format_real(x(i))
            end if
            app = app_accepts(key, text, app_message)
            ! The app refuses what is outside the table's range, and accepts what is inside
            ! (the default case otherwise; the grid limit may refuse a large count).
            if (app .neqv. in_range(ranges(ir), x(i))) then
               if (.not. (ranges(ir)%kind == k_int .and. index(app_message, 'grid cells') > 0)) then
                  call test_failed(error, key//' = '//text//': the app '// &
                     trim(merge('accepts', 'refuses', app))//' it, the table says '// &
                     trim(merge('inside ', 'outside', in_range(ranges(ir), x(i))))// &
                     '; '//app_message)
                  return
               end if
            end if
            lib = library_status(ctx, key, x(i), lib_message)
            if (lib < 0) cycle
            n_lib = n_lib + 1
            if (app .neqv. (lib == 0)) then
               call test_failed(error, key//' = '//text//': the app '// &
                  trim(merge('accepts', 'refuses', app))//' it, the library '// &
                  trim(merge('accepts', 'refuses', lib == 0))//': '//app_message//' / '// &
                  lib_message)
               return
            end if
            if (lib == 0) call reset_library(ctx)
         end do
      end do
      ! Every real and integer variable of the case files has its entry (but the sweep's).
      do ir = 1, size(variables)
         if (variables(ir)%group == 'sweep' .or. .not. (variables(ir)%kind == k_real .or. &
             variables(ir)%kind == k_int)) cycle
         call check(error, find_range(trim(variables(ir)%group)//'%'// &
            trim(variables(ir)%name)) > 0, message=trim(variables(ir)%group)//'%'// &
            trim(variables(ir)%name)//' has no entry in the range table')
         if (allocated(error)) return
      end do
      ! 17 library inputs, about a dozen samples each.
      call check(error, n_lib > 17*10, message='too few library samples: '//str_int(n_lib))
      if (allocated(error)) return
      call check(error, ranges(find_range('kinematics%yaw'))%hi, max_yaw, &
         message='yaw range = the library''s max_yaw')
   end subroutine test_ranges_compare

   !> The table's defaults are the app's (its resolved namelist) and the library's (the
   !> components' default initialisation).
   subroutine test_range_defaults(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(shc_error_type), allocatable :: err
      character(len=:), allocatable :: text, key, group, name
      character(len=80) :: mode_override(1)
      type(material_type) :: m
      type(track_type) :: t
      type(normal_options_type) :: n
      type(tangential_options_type) :: tg
      type(contact_options_type) :: s
      real(wp) :: x
      integer :: ir, g, p, e, stat, checked

      checked = 0
      do ir = 1, size(ranges)
         key = trim(range_key(ranges(ir)))
         ! The load quantities are written by the mode that reads them.
         mode_override(1) = 'load%mode='//load_mode_reading(key(index(key, '%') + 1:))
         call load_config('', mode_override, config, err)
         call check(error, .not. allocated(err), message='default configuration')
         if (allocated(error)) return
         text = config_namelist(config)
         group = key(1:index(key, '%') - 1)
         name = key(index(key, '%') + 1:)
         g = index(text, '&'//group//new_line('a'))
         if (g == 0) cycle
         p = index(text(g:), new_line('a')//'  '//name//' = ')
         if (p == 0) cycle
         p = g + p + len(name) + 5
         e = index(text(p:), '  !')
         read (text(p:p + e - 2), *, iostat=stat) x
         call check(error, stat == 0 .and. x == ranges(ir)%default, message=key// &
            ': the app''s default '//text(p:p + e - 2)//' is not the table''s')
         if (allocated(error)) return
         checked = checked + 1
      end do
      call check(error, checked >= size(ranges) - 1, message='defaults found in the namelist: '// &
         str_int(checked))
      if (allocated(error)) return
      call check(error, all([m%shear_modulus, m%poisson, m%friction, t%gauge, t%gauge_height, &
         t%rail_inclination, t%flange_back_distance, t%flange_back_position, t%nominal_radius, &
         real(n%n_strips, wp), n%epsilon, s%b_min, s%l_filt_wheel, s%l_filt_rail, &
         real(tg%n_elements, wp)] == [(default_of(key_list(ir)), ir=1, 15)]), &
         message='a library default differs from the table')
   contains
      pure function key_list(i) result(k)
         integer, intent(in) :: i
         character(len=:), allocatable :: k
         character(len=*), parameter :: keys(15) = [character(len=28) :: &
            'material%shear_modulus', 'material%poisson', 'material%friction', 'track%gauge', &
            'track%gauge_height', 'track%inclination', 'track%flange_back_distance', &
            'track%flange_back_position', 'track%nominal_radius', 'normal%n_strips', &
            'normal%epsilon', 'normal%b_min', 'profiles%wheel_smoothing', &
            'profiles%rail_smoothing', 'tangential%n_elements']
         k = trim(keys(i))
      end function key_list
      pure real(wp) function default_of(k)
         character(len=*), intent(in) :: k
         default_of = ranges(find_range(k))%default
      end function default_of
   end subroutine test_range_defaults

   ! ------------------------------------------------------------------------------------------
   ! Items 9, 10: long lists, numbers beyond the double range
   ! ------------------------------------------------------------------------------------------

   !> `--check` on a 100 000-value sweep list took 15 s and grew quadratically (the pending
   !> value and the printed list were concatenated piece by piece); it is linear now (2.7 s
   !> in the debug build, 0.6 s CPU). A guard, not a timing: the old code needs minutes here.
   subroutine test_long_list(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_long')
      call write_long_list(dir//'/long.nml', 100000)
      call shell('cd '//dir//' && timeout 60 '//program_path()//' run long.nml --check '// &
         '> out.txt 2> err.txt', stat)
      call check(error, stat, 0, message='100 000 values: status '//str_int(stat)// &
         ' (124: over 60 s); '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '(100000 case(s))', '100 000 values')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_long_list

   !> A case file with one `&sweep` list of n values, 20 a line.
   subroutine write_long_list(name, n)
      character(len=*), intent(in) :: name
      integer, intent(in) :: n
      integer :: unit, i
      open (newunit=unit, file=name, status='replace', action='write')
      write (unit, '(a)') '&sweep t_y = '
      do i = 0, n - 1
         write (unit, '(f9.6,a)', advance=merge('yes', 'no ', mod(i, 20) == 19)) i*1.0e-5_wp, ', '
      end do
      write (unit, '(a)') '/'
      close (unit)
   end subroutine write_long_list

   !> Debug build only: `1e309` in a case file trapped inside strtod (the release build reported
   !> it). Now refused as beyond the double range in every build, from a file, --set, and the
   !> library's option setter.
   subroutine test_overflow(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_context_type) :: ctx
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('in_overflow')
      call write_lines(dir//'/big.nml', [character(len=40) :: '&position t_y = 1e309 /'])
      stat = run_program(dir, 'run big.nml --check')
      call expect_one_message(error, dir, stat, 2, 'big.nml:1: &position t_y = 1e309: a '// &
         'number beyond the range of double precision', 'file')
      if (allocated(error)) return
      stat = run_program(dir, 'run --set sweep%nu_x=0,-1e400 --check')
      call expect_one_message(error, dir, stat, 2, 'beyond the range of double precision', &
         '--set')
      if (allocated(error)) return
      call new_library(error, ctx)
      if (allocated(error)) return
      call check(error, context_set_option(ctx, 'normal%epsilon', '1e309'), 2, &
         message='option setter: '//context_message(ctx))
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_overflow

   ! ------------------------------------------------------------------------------------------
   ! Fuzz of the library's option setter
   ! ------------------------------------------------------------------------------------------

   !> The seeded fuzz of the option setter, bounded in time (test_robustness runs it too).
   subroutine test_option_fuzz(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      call library_option_fuzz(error, 20260524, 2.0, n)
      if (allocated(error)) return
      call check(error, n > 50, message='too few setter calls: '//str_int(n))
   end subroutine test_option_fuzz

end module test_input
