!> Tests of the command line as batch and shell users meet it (issue 15): per-command help,
!> the Slurm job-array variables (ignored unless `--shard slurm`), progress lines in a batch
!> log, `-q` and `--format none`, the inputs and units of the CSV/JSON lines, the patch counts
!> (found and loaded) in every output, `profiles FILE`, and documentation commands that write
!> nowhere near the repository.
!>
!> The program is run as in the suite `app` (test_app's helpers): stdout and stderr go to files,
!> so stderr is not a terminal, as in a batch log.
module test_cli
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use test_external_data, only: external_file
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_case_result, only: case_summary_type
   use shcontact_output_merge, only: read_result_summary
   use shcontact_output_hdf5, only: h5_file_type, h5_open, h5_close, h5_exists
   use shcontact_core_kinds, only: wp
   use shcontact_api_solver, only: contact_solver_type, contact_result_type, contact_load_type, &
      load_normal_force
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_core_files, only: file_exists
   use test_app, only: scratch_directory, shell, run_program, file_text, write_lines, &
      unavailable, expect_in, program_path, current_directory
   implicit none
   private
   public :: collect_cli

   !> A 12-case sweep, checkpoint blocks of 3, coarse grids (as test_app's).
   character(len=*), parameter :: sweep_case(*) = [character(len=72) :: &
      '&sweep', &
      "  bound = 'weighted', 'clipped'", &
      '  nu_x = 0.0, 1.0e-3, 2.0e-3', &
      '  phi = 0.0, 1.0e-3', &
      '/', &
      "&output checkpoint_cases = 3, compression = 1 /", &
      '&normal n_strips = 40 /', &
      '&tangential n_elements = 20 /']

   !> The Slurm variables of task 3 of an 8-task array --array=1-8.
   character(len=*), parameter :: slurm_task_3_of_8 = 'SLURM_ARRAY_TASK_ID=3 '// &
      'SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=8 SLURM_ARRAY_JOB_ID=4242'

contains

   subroutine collect_cli(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('per_command_help', test_help), &
         new_unittest('options_of_other_commands', test_foreign_options), &
         new_unittest('slurm_variables_ignored_without_shard', test_slurm_ignored), &
         new_unittest('shard_slurm', test_shard_slurm), &
         new_unittest('slurm_example_script', test_slurm_script), &
         new_unittest('progress_lines_in_a_batch_log', test_progress_lines), &
         new_unittest('quiet_and_format_none', test_quiet), &
         new_unittest('csv_json_inputs_and_units', test_inputs_and_units), &
         new_unittest('kinematic_csv_inputs', test_kinematic_inputs), &
         new_unittest('kinematic_sample_output_in_app_md', test_kinematic_sample), &
         new_unittest('profiles_sample_output_in_app_md', test_profiles_sample), &
         new_unittest('no_output', test_no_output), &
         new_unittest('patches_found_and_loaded', test_patch_counts), &
         new_unittest('profiles_file', test_profiles_file), &
         new_unittest('profiles_output_never_the_input', test_profiles_own_input), &
         new_unittest('profiles_geometry_never_overwrite', test_no_overwrite), &
         new_unittest('miniprof_wheel_written_same_contact', test_miniprof_written), &
         new_unittest('run_notes_on_profiles', test_profile_notes), &
         new_unittest('run_notes_on_measured_profiles', test_profile_notes_measured), &
         new_unittest('collinear_points_same_forces', test_collinear_points), &
         new_unittest('doc_commands_write_outside_the_repository', test_doc_outputs), &
         new_unittest('run_never_writes_its_inputs', test_run_inputs_kept), &
         new_unittest('stdout_write_error_is_status_3', test_stdout_full), &
         new_unittest('shard_of_failed_cases_writes_its_file', test_failed_shard), &
         new_unittest('every_case_failed_prints_its_lines', test_every_case_failed_lines), &
         new_unittest('resume_of_a_finished_run', test_resume_finished_run), &
         new_unittest('check_output_reproduces_elsewhere', test_check_elsewhere), &
         new_unittest('headline_example_is_the_default', test_headline_default) &
         ]
   end subroutine collect_cli

   !> Number of lines of a text.
   pure integer function count_lines(text) result(n)
      character(len=*), intent(in) :: text
      integer :: i
      n = 0
      do i = 1, len(text)
         if (text(i:i) == new_line('a')) n = n + 1
      end do
   end function count_lines

   !> Line `k` of a text ('' when it has fewer lines).
   function line_of(text, k) result(line)
      character(len=*), intent(in) :: text
      integer, intent(in) :: k
      character(len=:), allocatable :: line
      integer :: i, start, found
      start = 1
      found = 0
      line = ''
      do i = 1, len(text)
         if (text(i:i) /= new_line('a')) cycle
         found = found + 1
         if (found == k) then
            line = text(start:i - 1)
            return
         end if
         start = i + 1
      end do
   end function line_of

   subroutine expect_not_in(error, text, fragment, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: text, fragment, what
      if (index(text, fragment) > 0) call test_failed(error, what//': did not expect "'// &
         fragment//'" in: '//text)
   end subroutine expect_not_in

   !> Run, expect the status, and return stdout and stderr.
   subroutine run_expect(error, dir, args, status, out, err, env)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, args
      integer, intent(in) :: status
      character(len=:), allocatable, intent(out) :: out, err
      character(len=*), intent(in), optional :: env
      integer :: stat
      stat = run_program(dir, args, env)
      out = file_text(dir//'/out.txt')
      err = file_text(dir//'/err.txt')
      call check(error, stat, status, message='shcontact '//args//': exit status; stderr: '// &
         err)
   end subroutine run_expect

   ! ------------------------------------------------------------------------------------------

   !> `run -o OUT --force` never replaces a file the run reads: the case file, a profile file,
   !> or a case file that is OUT's sidecar name (it did: the case file became the HDF5 file).
   subroutine test_run_inputs_kept(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      character(len=*), parameter :: case_text = '&position t_y = 3.0 /'
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_run_inputs')
      call write_lines(dir//'/c.nml', [case_text])
      call write_lines(dir//'/g.xmf', [case_text])
      call run_expect(error, dir, 'run c.nml -o c.nml --force -q', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'is also an input of this command', '-o the case file')
      if (allocated(error)) return
      call check(error, file_text(dir//'/c.nml') == case_text//new_line('a'), &
         message='the case file was changed')
      if (allocated(error)) return
      call run_expect(error, dir, 'run g.xmf -o g.h5 --force -q', 1, out, err)
      if (allocated(error)) return
      call check(error, file_text(dir//'/g.xmf') == case_text//new_line('a') .and. &
         .not. file_exists(dir//'/g.h5'), message='the case file g.xmf was replaced')
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles --write prof -q', 0, out, err)
      if (allocated(error)) return
      out = file_text(dir//'/prof/S1002.txt')
      call run_expect(error, dir, 'run c.nml --set profiles%wheel=prof/S1002.txt '// &
         '-o prof/S1002.txt --force -q', 1, err, err)
      if (allocated(error)) return
      call check(error, len(out) > 0 .and. file_text(dir//'/prof/S1002.txt') == out, &
         message='the wheel profile file was replaced')
      if (allocated(error)) return
      call run_expect(error, dir, 'geometry c.nml --set profiles%wheel=prof/S1002.txt '// &
         '-o prof/S1002.txt --force -q', 3, err, err)
      if (allocated(error)) return
      call check(error, file_text(dir//'/prof/S1002.txt') == out, &
         message='geometry replaced the wheel profile file')
   end subroutine test_run_inputs_kept

   !> A write error on the standard output (a full disk) ends the program with status 3 and a
   !> message; gfortran's own unit 6 ignores it (the CSV report was lost with status 0).
   subroutine test_stdout_full(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      if (.not. file_exists('/dev/full')) then
         call skip_test(error, 'no /dev/full on this system')
         return
      end if
      dir = scratch_directory('cli_stdout_full')
      call write_lines(dir//'/c.nml', ['&sweep t_y = 1.0, 2.0, 3.0 /'])
      call shell('cd '//dir//' && '//program_path()//' run c.nml --no-output --format csv '// &
         '-q > /dev/full 2> err.txt', stat)
      call check(error, stat, 3, message='csv to a full device: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the standard output could not be '// &
         'written', 'csv to a full device')
      if (allocated(error)) return
      call shell('cd '//dir//' && '//program_path()//' --version > /dev/full 2> err.txt', stat)
      call check(error, stat, 3, message='--version to a full device')
      if (allocated(error)) return
      ! The same run to a file: status 0, four lines.
      call shell('cd '//dir//' && '//program_path()//' run c.nml --no-output --format csv '// &
         '-q > out.csv 2> err.txt', stat)
      call check(error, stat == 0 .and. count_lines(file_text(dir//'/out.csv')) == 4, &
         message='csv to a file: '//file_text(dir//'/err.txt'))
   end subroutine test_stdout_full

   !> A shard whose cases all fail writes its file (status 4), so that the shards of a run
   !> merge (before, it wrote none and the merge reported missing cases).
   subroutine test_failed_shard(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      character(len=*), parameter :: sweep = 'run --set track%gauge=1600 '// &
         '--set sweep%t_y=-30,-20,-10,0,10,20,30 -q --format none -o f.h5'
      integer :: k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_failed_shard')
      call run_expect(error, dir, sweep, 4, out, err)
      if (allocated(error)) return
      do k = 1, 3
         call run_expect(error, dir, sweep//' --shard '//achar(iachar('0') + k)//'/3', 4, &
            out, err)
         if (allocated(error)) return
      end do
      call check(error, file_exists(dir//'/f-shard1of3.h5'), message='shard 1, every case '// &
         'failed: no file')
      if (allocated(error)) return
      ! The merge gives the unsharded run's status 4 and says how many failed (it exited 0
      ! and said nothing: a pipeline that checks only the merge saw a clean result).
      call run_expect(error, dir, 'merge -q m.h5 f-shard1of3.h5 f-shard2of3.h5 '// &
         'f-shard3of3.h5', 4, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: 5 of 7 case(s) failed (see /failures in m.h5)', &
         'the merge names the failed cases')
      if (allocated(error)) return
      call shell('h5diff -q --exclude-attribute=/ '//dir//'/m.h5 '//dir//'/f.h5', k)
      call check(error, k, 0, message='the merged shards differ from the unsharded run')
   end subroutine test_failed_shard

   !> `--resume` of a finished run (no checkpoint left): the output of this configuration is
   !> kept as it is, its lines printed from it, status 4 for its failed cases; another run's
   !> output is refused (status 2), not solved again over it (a resubmitted array task solved
   !> every finished shard again, and --set changes replaced a finished file silently).
   subroutine test_resume_finished_run(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, first
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_resume_finished_run')
      call write_lines(dir//'/fin.nml', ['&sweep roll = 0.1, 0.0, 0.01 /'])
      call run_expect(error, dir, 'run fin.nml -o fin.h5 -q --format csv', 4, first, err)
      if (allocated(error)) return
      call shell('cd '//dir//' && cp fin.h5 kept.h5')
      call run_expect(error, dir, 'run fin.nml -o fin.h5 --resume --format csv', 4, out, err)
      if (allocated(error)) return
      call check(error, out == first, message='the lines of the finished run: '//out)
      if (allocated(error)) return
      call expect_in(error, err, 'nothing to resume: fin.h5 already holds every case of this '// &
         'run (2 solved)', 'the note')
      if (allocated(error)) return
      call run_expect(error, dir, 'run fin.nml -o '//dir//'/fin.h5 --resume -q', 4, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run fin.nml -o fin.h5 --resume -q --set '// &
         'material%friction=0.2', 2, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'holds another run (configurations differ: "friction = 0.3', &
         'another configuration')
      if (allocated(error)) return
      call shell('cmp -s '//dir//'/fin.h5 '//dir//'/kept.h5', stat)
      call check(error, stat, 0, message='the finished file was rewritten')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/fin.h5.partial'), message='no work folder left')
      if (allocated(error)) return
      ! With fields: a sidecar removed since is written again, the file itself untouched.
      call write_lines(dir//'/fld.nml', [character(len=28) :: '&sweep nu_x = 0.0, 1.0e-3 /', &
         '&output fields = ''all'' /'])
      call run_expect(error, dir, 'run fld.nml -o fld.h5 -q', 0, out, err)
      if (allocated(error)) return
      call shell('cd '//dir//' && cp fld.h5 fld_kept.h5 && cp fld.xmf fld_kept.xmf && rm fld.xmf')
      call run_expect(error, dir, 'run fld.nml -o fld.h5 -q --resume', 0, out, err)
      if (allocated(error)) return
      call shell('cd '//dir//' && cmp -s fld.h5 fld_kept.h5 && cmp -s fld.xmf fld_kept.xmf', stat)
      call check(error, stat, 0, message='the sidecar written again, the file kept')
      call shell('rm -rf '//dir)
   end subroutine test_resume_finished_run

   !> A run whose every case fails still prints each case's line with --format csv|json (a
   !> shell loop over runs keeps one line per run; the single case failing in the contact
   !> search printed nothing), with the failure's status.
   subroutine test_every_case_failed_lines(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_every_case_failed_lines')
      call run_expect(error, dir, 'run -q --no-output --format json --set position%roll=0.1', &
         6, out, err)
      if (allocated(error)) return
      call expect_in(error, out, '{"case":1,"status":6,', 'the single failed case''s line')
      if (allocated(error)) return
      call expect_in(error, out, '"fx":null', 'its results null')
      if (allocated(error)) return
      call expect_in(error, out, '"message":"contact search: ', 'its message')
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: error: contact search: ', 'the error on stderr')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --no-output --format csv --set sweep%roll=0.1,0.0995', &
         6, out, err)
      if (allocated(error)) return
      call check(error, count_lines(out), 3, message='header and two lines: '//out)
      if (allocated(error)) return
      call expect_in(error, line_of(out, 3), '2,6,0,0,0,', 'the second failed case''s line')
      if (allocated(error)) return
      ! A solved case's JSON line has the message key too (null): every line the same keys.
      call run_expect(error, dir, 'run -q --no-output --format json', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, out, ',"message":null}', 'a solved line''s message')
   end subroutine test_every_case_failed_lines

   !> `run --check` output saved next to a case file in another directory reproduces the run:
   !> its profile paths are absolute (they were relative to the working directory, so the saved
   !> file named sub/sub/prof/... and failed with status 3).
   subroutine test_check_elsewhere(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, first
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_check_elsewhere')
      call shell('mkdir -p '//dir//'/sub/prof && cp data/profiles/S1002.txt '//dir// &
         '/sub/prof/')
      call write_lines(dir//'/sub/rel.nml', ["&profiles wheel = 'prof/S1002.txt' /"])
      call run_expect(error, dir, 'run --check -q sub/rel.nml', 0, first, err)
      if (allocated(error)) return
      call write_lines(dir//'/sub/resolved.nml', [first])
      call run_expect(error, dir, 'run --check -q sub/resolved.nml', 0, out, err)
      if (allocated(error)) return
      call check(error, out == first, message='the saved --check output resolves otherwise')
   end subroutine test_check_elsewhere

   !> examples/headline.nml says that every value in it is the built-in default: its resolved
   !> configuration equals the default case's but for its output (it held the old default
   !> reduction 'local-hertz' and solved another case: F_x −5912.7 against −5841.0 N).
   subroutine test_headline_default(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, default
      character(len=*), parameter :: same_output = ' --check -q --set output%file=x.h5 '// &
         '--set output%fields=all'
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_headline_default')
      call run_expect(error, dir, 'run'//same_output, 0, default, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run '//current_directory()//'/examples/headline.nml'// &
         same_output, 0, out, err)
      if (allocated(error)) return
      call check(error, out == default, message='examples/headline.nml is not the default case')
   end subroutine test_headline_default

   !> `COMMAND --help` and `help COMMAND` print that command's help on stdout, status 0; every
   !> option a command's help lists is one the command accepts.
   subroutine test_help(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: commands(4) = [character(len=8) :: 'run', 'merge', &
         'profiles', 'geometry']
      character(len=*), parameter :: own_option(4) = [character(len=13) :: '--shard slurm', &
         'SHARD.h5', '--plot', 'geometry.txt']
      character(len=:), allocatable :: dir, out, err, general
      integer :: k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_help')
      call run_expect(error, dir, '--help', 0, general, err)
      if (allocated(error)) return
      do k = 1, size(commands)
         call run_expect(error, dir, trim(commands(k))//' --help', 0, out, err)
         if (allocated(error)) return
         call expect_in(error, out, 'Usage: shcontact '//trim(commands(k)), trim(commands(k))// &
            ' --help')
         if (allocated(error)) return
         call expect_in(error, out, trim(own_option(k)), trim(commands(k))//' --help')
         if (allocated(error)) return
         call expect_in(error, out, 'Exit status', trim(commands(k))//' --help')
         if (allocated(error)) return
         call check(error, out /= general, message=trim(commands(k))//' --help prints the '// &
            'general help')
         if (allocated(error)) return
         call check(error, len(err) == 0, message=trim(commands(k))//' --help: stderr '//err)
         if (allocated(error)) return
         ! Help wins over everything else on the line, even a bad option after it.
         call run_expect(error, dir, trim(commands(k))//' -q -h --frobnicate', 0, err, err)
         if (allocated(error)) return
         call run_expect(error, dir, 'help '//trim(commands(k)), 0, err, general)
         if (allocated(error)) return
         call check(error, err == out, message='help '//trim(commands(k))//' differs from '// &
            trim(commands(k))//' --help')
         if (allocated(error)) return
         call run_expect(error, dir, '--help', 0, general, err)
         if (allocated(error)) return
         call shell('cd '//dir//' && for o in $('//program_path()//' '//trim(commands(k))// &
            ' --help | sed -nE "s/^  (-[a-zA-Z], )?(--[a-z-]+).*/\2/p"); do '// &
            program_path()//' '//trim(commands(k))//' -q $o x 2>&1 | grep -qE '// &
            '"unknown option|belongs to" && echo "$o"; done > refused.txt')
         call check(error, len(file_text(dir//'/refused.txt')) == 0, message=trim(commands(k))// &
            ' --help lists options that '//trim(commands(k))//' refuses: '// &
            file_text(dir//'/refused.txt'))
         if (allocated(error)) return
      end do
      call expect_in(error, general, 'shcontact COMMAND --help', 'the general help points there')
      call shell('rm -rf '//dir)
   end subroutine test_help

   !> An option of another command is a usage error that names its command; a misspelt option
   !> gets a suggestion, and --set without '=' is refused.
   subroutine test_foreign_options(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_foreign')
      call run_expect(error, dir, 'merge a.h5 b.h5 --set x%y=1', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'option "--set" belongs to run and geometry, not to merge', &
         'merge --set')
      if (allocated(error)) return
      call run_expect(error, dir, 'run --plot p.gp', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'belongs to profiles', 'run --plot')
      if (allocated(error)) return
      call run_expect(error, dir, 'geometry --format csv', 1, out, err)
      if (allocated(error)) return
      ! A yawed case's geometry is not the yaw-0 table: refused, nothing written.
      call run_expect(error, dir, 'geometry -o yawed.txt --set kinematics%mode=on '// &
         '--set kinematics%yaw=0.004', 2, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'the built-in case: &kinematics yaw = ', 'geometry with yaw')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/yawed.txt'), message='geometry with yaw wrote a file')
      if (allocated(error)) return
      call run_expect(error, dir, 'run --csv-units', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, '--csv-units needs --format csv', 'run --csv-units')
      if (allocated(error)) return
      call run_expect(error, dir, 'help foo', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'no help on "foo": expected one of the commands', 'help foo')
      if (allocated(error)) return
      call run_expect(error, dir, 'run --format yaml', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'expected text, csv, json or none', 'run --format yaml')
      if (allocated(error)) return
      ! A word cut short gets the option it was meant to be; --set without '=' is refused
      ! before its value could be taken for a case file.
      call run_expect(error, dir, 'run --thread 2', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'did you mean "--threads"?', 'run --thread')
      if (allocated(error)) return
      ! A usage error in a command points to its help, not the 16 lines of every command's
      ! usage (one line when its message points there already); with -q, before or after the
      ! refused option, the error line alone (a batch log).
      call check(error, count_lines(err), 1, message='run --thread: one line: '//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run --threads 0', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: see `shcontact run --help` for its options', &
         'run --threads 0: the pointer to the help')
      if (allocated(error)) return
      call check(error, index(err, 'Usage:') == 0, message='the usage text after a usage '// &
         'error in run: '//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --threads 0', 1, out, err)
      if (allocated(error)) return
      call check(error, count_lines(err), 1, message='run -q --threads 0: one line: '//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run --threads 0 -q', 1, out, err)
      if (allocated(error)) return
      call check(error, count_lines(err), 1, message='run --threads 0 -q: one line: '//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run --set position%t_y 3', 2, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'command line --set position%t_y: expected '// &
         'group%variable=value', 'run --set position%t_y 3')
      if (allocated(error)) return
      call check(error, index(err, 'Usage:') == 0, message='the usage text after an invalid '// &
         'override: '//err)
      if (allocated(error)) return
      ! The same status and words as an override without its group.
      call run_expect(error, dir, 'run --set t_y=3', 2, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'command line --set t_y=3: expected group%variable=value', &
         'run --set t_y=3')
      call shell('rm -rf '//dir)
   end subroutine test_foreign_options

   !> Inside a job array, a run without --shard solves every case (the "one case file per
   !> array task" pattern), with a note on stderr that -q silences.
   subroutine test_slurm_ignored(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_slurm_ignored')
      call run_expect(error, dir, 'run -o one.h5', 0, out, err, env=slurm_task_3_of_8)
      if (allocated(error)) return
      call check(error, file_exists(dir//'/one.h5'), message='one.h5 written')
      if (allocated(error)) return
      call expect_in(error, out, 'Fn = 64700', 'the summary of the case')
      if (allocated(error)) return
      call expect_in(error, err, 'Slurm job-array task 3 of 8: solving every case', &
         'the note on stderr')
      if (allocated(error)) return
      call expect_in(error, err, '1 of 1 case(s) solved', 'the closing note')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q -o one.h5', 0, out, err, env=slurm_task_3_of_8)
      if (allocated(error)) return
      call check(error, len(err) == 0 .and. len(out) == 0, message='-q in a job array: '// &
         'nothing on stdout or stderr; got '//out//err)
      if (allocated(error)) return
      ! A sweep is not sliced either: every case, no shard file.
      call write_lines(dir//'/sweep.nml', sweep_case)
      call run_expect(error, dir, 'run sweep.nml -q --format csv -o sweep.h5', 0, out, err, &
         env=slurm_task_3_of_8)
      if (allocated(error)) return
      call check(error, count_lines(out), 13, message='a header and 12 cases')
      if (allocated(error)) return
      call check(error, file_exists(dir//'/sweep.h5') .and. &
         .not. file_exists(dir//'/sweep-shard3of8.h5'), message='the whole sweep in sweep.h5')
      call shell('rm -rf '//dir)
   end subroutine test_slurm_ignored

   !> --shard slurm takes the slice from the variables; errors outside an array, for a task
   !> outside the array and for more shards than cases; --shard I/N wins over the variables.
   subroutine test_shard_slurm(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      character(len=*), parameter :: task_3_of_4 = 'SLURM_ARRAY_TASK_ID=12 '// &
         'SLURM_ARRAY_TASK_MIN=10 SLURM_ARRAY_TASK_COUNT=4'
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_shard_slurm')
      call write_lines(dir//'/sweep.nml', sweep_case)
      call run_expect(error, dir, 'run sweep.nml --shard slurm --format csv -o s.h5', 0, out, &
         err, env=task_3_of_4)
      if (allocated(error)) return
      call check(error, file_exists(dir//'/s-shard3of4.h5'), message='s-shard3of4.h5 written')
      if (allocated(error)) return
      ! Cases 7 to 9 of 12.
      call check(error, count_lines(out), 4, message='a header and 3 cases: '//out)
      if (allocated(error)) return
      call check(error, index(line_of(out, 2), '7,0,') == 1 .and. &
         index(line_of(out, 4), '9,0,') == 1, message='cases 7 to 9: '//out)
      if (allocated(error)) return
      call run_expect(error, dir, 'run sweep.nml --shard 1/2 -q -o t.h5', 0, out, err, &
         env=task_3_of_4)
      if (allocated(error)) return
      call check(error, file_exists(dir//'/t-shard1of2.h5'), message='--shard I/N wins')
      if (allocated(error)) return
      ! One case, eight tasks: the error of the issue, now only when asked for.
      call run_expect(error, dir, 'run --shard slurm -o one.h5', 1, out, err, &
         env=slurm_task_3_of_8)
      if (allocated(error)) return
      call expect_in(error, err, 'shard 3/8: a run of 1 cases has fewer cases than shards', &
         '--shard slurm')
      if (allocated(error)) return
      ! Every task of such an array is refused, also the one whose slice is not empty.
      call run_expect(error, dir, 'run --shard 1/8 -o one.h5', 1, out, err)
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/one-shard1of8.h5'), &
         message='no file from a shard of an over-split run')
      if (allocated(error)) return
      call run_expect(error, dir, 'run --shard slurm -o one.h5', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT are not set', &
         '--shard slurm outside a job array')
      if (allocated(error)) return
      call run_expect(error, dir, 'run sweep.nml --shard slurm -o s.h5', 1, out, err, &
         env='SLURM_ARRAY_TASK_ID=9 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=4')
      if (allocated(error)) return
      call expect_in(error, err, 'does not give a shard of 4', 'a task outside the array')
      if (allocated(error)) return
      call run_expect(error, dir, 'run sweep.nml --shard slurm -o s.h5', 1, out, err, &
         env='SLURM_ARRAY_TASK_ID=x3 SLURM_ARRAY_TASK_COUNT=4')
      if (allocated(error)) return
      ! A stepped array (--array=1-7:2): task 5 is the third of four shards (it took shard 5
      ! and failed, task 3 took shard 3 and left shard 2 unsolved).
      call run_expect(error, dir, 'run sweep.nml --shard slurm --format csv -o st.h5', 0, &
         out, err, env='SLURM_ARRAY_TASK_ID=5 SLURM_ARRAY_TASK_MIN=1 '// &
         'SLURM_ARRAY_TASK_MAX=7 SLURM_ARRAY_TASK_STEP=2 SLURM_ARRAY_TASK_COUNT=4')
      if (allocated(error)) return
      call check(error, file_exists(dir//'/st-shard3of4.h5') .and. &
         index(line_of(out, 2), '7,0,') == 1, message='task 5 of 1-7:2 is shard 3/4: '//out)
      if (allocated(error)) return
      ! A list (--array=1,3,7) is not one range: refused in every task, also task 3.
      call run_expect(error, dir, 'run sweep.nml --shard slurm -o sl.h5', 1, out, err, &
         env='SLURM_ARRAY_TASK_ID=3 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_MAX=7 '// &
         'SLURM_ARRAY_TASK_STEP=1 SLURM_ARRAY_TASK_COUNT=3')
      if (allocated(error)) return
      call expect_in(error, err, 'are not 3 evenly spaced tasks', 'a job array given as a list')
      if (allocated(error)) return
      call shell('cd '//dir//' && test -z "$(ls -d one* sl* 2>/dev/null)"', stat)
      call check(error, stat, 0, message='no output from a refused shard')
      call shell('rm -rf '//dir)
   end subroutine test_shard_slurm

   !> examples/slurm_doe.sh as Slurm runs it: eight tasks with their array variables, then the
   !> merge of its comment; the merged file holds the 8000 cases. Logs hold errors only (-q).
   subroutine test_slurm_script(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, text, messages(:)
      type(case_summary_type), allocatable :: s(:)
      integer, allocatable :: indices(:), failed(:)
      type(lib_error), allocatable :: lerr
      integer :: stat, n, task
      character(len=2) :: id
      if (unavailable(error, .false.)) return
      if (.not. file_exists('examples/slurm_doe.sh')) then
         call skip_test(error, 'examples/slurm_doe.sh is not in the working directory')
         return
      end if
      dir = scratch_directory('cli_slurm_script')
      call shell('mkdir -p '//dir//'/bin '//dir//'/examples && cp examples/slurm_doe.sh '// &
         'examples/doe_8000.nml '//dir//'/examples/ && ln -s '//program_path()//' '//dir// &
         '/bin/shcontact')
      do task = 1, 8
         write (id, '(i0)') task
         call shell('cd '//dir//' && env -u SLURM_ARRAY_TASK_MAX -u SLURM_ARRAY_TASK_STEP '// &
            'PATH='//dir//'/bin:"$PATH" SLURM_ARRAY_TASK_ID='// &
            trim(id)//' SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=8 '// &
            'SLURM_CPUS_PER_TASK=2 bash examples/slurm_doe.sh > task'//trim(id)//'.log 2>&1', &
            stat)
         call check(error, stat, 0, message='task '//trim(id)//': '// &
            file_text(dir//'/task'//trim(id)//'.log'))
         if (allocated(error)) return
      end do
      call shell('cd '//dir//' && test -z "$(cat task*.log)"', stat)
      call check(error, stat, 0, message='the task logs hold errors only')
      if (allocated(error)) return
      call shell('cd '//dir//' && PATH='//dir//'/bin:"$PATH" && '// &
         'shcontact merge build/doe_8000.h5 build/doe_8000-shard*of8.h5 2> merge.log', stat)
      call check(error, stat, 0, message='merge: '//file_text(dir//'/merge.log'))
      if (allocated(error)) return
      call read_result_summary(dir//'/build/doe_8000.h5', text, n, indices, s, failed, &
         messages, lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      call check(error, size(indices) == 8000 .and. all(s%stat == 0), &
         message='the merged file holds the 8000 solved cases')
      if (allocated(error)) return
      ! A sweep with failed cases: the tasks end with status 0 (their files are written, with
      ! /failures), so that an afterok merge runs; the merge says 4 and how many failed.
      call shell('cd '//dir//' && rm -rf build && printf "&sweep roll = 0.1, 0.0, 0.1, 0.01 /'// &
         '\n" > examples/doe_8000.nml')
      do task = 1, 2
         write (id, '(i0)') task
         call shell('cd '//dir//' && env -u SLURM_ARRAY_TASK_MAX -u SLURM_ARRAY_TASK_STEP '// &
            'PATH='//dir//'/bin:"$PATH" SLURM_ARRAY_TASK_ID='//trim(id)// &
            ' SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=2 SLURM_CPUS_PER_TASK=2 '// &
            'bash examples/slurm_doe.sh > fail'//trim(id)//'.log 2>&1', stat)
         call check(error, stat, 0, message='task '//trim(id)//' of a sweep with failed '// &
            'cases: '//file_text(dir//'/fail'//trim(id)//'.log'))
         if (allocated(error)) return
      end do
      call shell('cd '//dir//' && PATH='//dir//'/bin:"$PATH" && '// &
         'shcontact merge build/doe_8000.h5 build/doe_8000-shard*of2.h5 2> merge.log', stat)
      call check(error, stat, 4, message='merge of shards with failed cases: '// &
         file_text(dir//'/merge.log'))
      if (allocated(error)) return
      call check(error, index(file_text(dir//'/merge.log'), '2 of 4 case(s) failed') > 0, &
         message='the merge names the failed cases: '//file_text(dir//'/merge.log'))
      call shell('rm -rf '//dir)
   end subroutine test_slurm_script

   !> With stderr in a file: progress lines with cases done, percentage, rate and ETA, the
   !> last one at 100 %; none with -q; none for a single case.
   subroutine test_progress_lines(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, header, row
      integer :: stat, p
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_progress')
      call write_lines(dir//'/sweep.nml', sweep_case)
      call run_expect(error, dir, 'run sweep.nml --format none -o s.h5', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: progress: 12 of 12 cases (100 %), ', 'last line')
      if (allocated(error)) return
      ! Checkpoint blocks of 3: at least 3, 6, 9 and 12 cases are reported.
      call shell('test $(grep -c "^shcontact: progress: [0-9]* of 12 cases ([0-9]* %), '// &
         '[0-9.]* cases/s, elapsed [0-9.]* s, ETA [0-9.]* s$" '//dir//'/err.txt) -ge 4', stat)
      call check(error, stat, 0, message='progress lines (cases, %, rate, ETA): '//err)
      if (allocated(error)) return
      call expect_not_in(error, err, achar(13), 'no carriage returns (a bar) in a log')
      if (allocated(error)) return
      call check(error, len(out) == 0, message='--format none: stdout '//out)
      if (allocated(error)) return
      ! Two threads: the first one writes blocks while the other solves; every tenth and the
      ! 100 % line still come (they stopped at 30 %).
      call write_lines(dir//'/doe.nml', [character(len=80) :: "&sweep mode = 'grid'", &
         'nu_x = 0, 2e-3  nu_x_points = 20  nu_y = 0, 2e-3  nu_y_points = 20', &
         'phi = 0, 2e-3  phi_points = 10 /'])
      call run_expect(error, dir, 'run doe.nml --format none --threads 2 -o d.h5', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: progress: 4000 of 4000 cases (100 %), ', &
         'two threads: the last line')
      if (allocated(error)) return
      call shell('test $(grep -c "^shcontact: progress: " '//dir//'/err.txt) -ge 8', stat)
      call check(error, stat, 0, message='two threads: a line at (nearly) every tenth: '//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run sweep.nml -q -o s.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, len(err) == 0, message='-q: no progress lines: '//err)
      if (allocated(error)) return
      ! The text table's columns line up behind the wide adhesion_fraction header.
      call run_expect(error, dir, 'run sweep.nml -q --format text -o s.h5', 0, out, err)
      if (allocated(error)) return
      header = line_of(out, 1)
      row = line_of(out, 3)
      p = index(header, 'wheel_fx_norm')
      call check(error, p > 1 .and. len(row) >= p, message='text table: '//header)
      if (allocated(error)) return
      call check(error, row(p - 1:p - 1) == ' ' .and. row(p:p) /= ' ', &
         message='values under their headers: '//header//new_line('a')//row)
      if (allocated(error)) return
      call run_expect(error, dir, 'run -o one.h5', 0, out, err)
      if (allocated(error)) return
      call expect_not_in(error, err, 'progress:', 'a single case')
      call shell('rm -rf '//dir)
   end subroutine test_progress_lines

   !> -q: nothing on stdout unless --format is given; --format none: nothing on stdout.
   subroutine test_quiet(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_quiet')
      call run_expect(error, dir, 'run -q -o q.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, len(out) == 0 .and. len(err) == 0, message='-q: '//out//err)
      if (allocated(error)) return
      call check(error, file_exists(dir//'/q.h5'), message='-q still writes the file')
      if (allocated(error)) return
      call run_expect(error, dir, 'run --format none -o q.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, len(out) == 0, message='--format none: '//out)
      if (allocated(error)) return
      call expect_in(error, err, 'results in q.h5', '--format none keeps the notes')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --format json -o q.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, count_lines(out) == 1 .and. len(err) == 0, &
         message='-q --format json: one line on stdout, nothing on stderr: '//out//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --format text -o q.h5', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, out, 'Fn = 64700', '-q --format text')
      if (allocated(error)) return
      ! -q -v: only -v's own lines (doc/app.md; the benchmark recipes of doc/performance.md).
      call run_expect(error, dir, 'run -q -v -o q.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, len(out) == 0 .and. count_lines(err) == 3 .and. &
         index(err, 'largest checkpoint block') > 0 .and. index(err, 'peak memory') > 0 .and. &
         index(err, 'progress') == 0, message='-q -v: the three lines of -v alone: '//out//err)
      call shell('rm -rf '//dir)
   end subroutine test_quiet

   !> A single case's CSV and JSON lines carry its inputs; --csv-units adds a units line under
   !> the header with one field per column.
   subroutine test_inputs_and_units(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, header, units, row
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_inputs')
      call run_expect(error, dir, 'run -q --format csv --csv-units --set creepage%nu_y=-1e-3 '// &
         '--set position%t_y=4.5 -o c.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, count_lines(out), 3, message='header, units, one case: '//out)
      if (allocated(error)) return
      header = line_of(out, 1)
      units = line_of(out, 2)
      row = line_of(out, 3)
      call expect_in(error, header, 'case,status,n_patches,n_loaded,main_patch,t_y,roll,normal_force,'// &
         'friction,bound,spin_model,nu_x,nu_y,phi,fn_total,', 'csv header')
      if (allocated(error)) return
      call expect_in(error, units, '1,1,1,1,1,mm,rad,N,1,,,1,1,rad/mm,N,', 'units line')
      if (allocated(error)) return
      call expect_in(error, row, ',4.5,0.0,64700.0,0.3,weighted,uniform,0.00058,-0.001,'// &
         '0.000274,', 'the inputs of the case')
      if (allocated(error)) return
      call shell('cd '//dir//' && test $(awk -F, "{print NF}" out.txt | sort -u | wc -l) '// &
         '-eq 1', stat)
      call check(error, stat, 0, message='header, units and row have as many fields: '//out)
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --format json --set creepage%nu_y=-1e-3 -o c.h5', 0, &
         out, err)
      if (allocated(error)) return
      call expect_in(error, out, '"t_y":4.733,"roll":0.0,"normal_force":64700.0,'// &
         '"friction":0.3,"bound":"weighted","spin_model":"uniform","nu_x":0.00058,'// &
         '"nu_y":-0.001,"phi":0.000274,', 'json inputs')
      call shell('rm -rf '//dir)
   end subroutine test_inputs_and_units

   !> doc/app.md's sample output of `shcontact run examples/kinematic.nml` is what the program
   !> prints now: every line of the block is a line of the program's stdout.
   subroutine test_kinematic_sample(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_kin_sample')
      call run_expect(error, dir, 'run '//current_directory()//'/examples/kinematic.nml', 0, &
         out, err)
      if (allocated(error)) return
      call shell("sed -n '/^\$ shcontact run examples\/kinematic.nml$/,/^```$/p' doc/app.md | "// &
         "sed '1d;$d' > "//dir//'/doc.txt && test -s '//dir//'/doc.txt && ! grep -vxFf '// &
         dir//'/out.txt '//dir//'/doc.txt > '//dir//'/stale.txt', stat)
      call check(error, stat, 0, message='doc/app.md''s kinematic sample output differs from '// &
         'the program''s: '//file_text(dir//'/stale.txt'))
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_kinematic_sample

   !> doc/app.md's sample of `shcontact profiles data/profiles/S1002.txt` is the program's
   !> output line for line (but the `written` and `plot` lines of its -o and --plot).
   subroutine test_profiles_sample(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_prof_sample')
      call shell('mkdir -p '//dir//'/data/profiles && cp data/profiles/S1002.txt '//dir// &
         '/data/profiles/')
      call run_expect(error, dir, 'profiles data/profiles/S1002.txt', 0, out, err)
      if (allocated(error)) return
      call shell("sed -n '/^  \$ shcontact profiles data\/profiles\/S1002.txt /,/^  ```$/p' "// &
         "doc/app.md | sed '1d;$d' | sed 's/^  //' | grep -v -e '^written ' -e '^plot ' > "// &
         dir//'/doc.txt && test $(wc -l < '//dir//'/doc.txt) -ge 10 && ! grep -vxFf '// &
         dir//'/out.txt '//dir//'/doc.txt > '//dir//'/stale.txt', stat)
      call check(error, stat, 0, message='doc/app.md''s profiles sample differs from the '// &
         'program''s output: '//file_text(dir//'/stale.txt'))
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_profiles_sample

   !> `run --no-output` solves a sweep and prints its lines but writes no file at all (no
   !> result, no checkpoint, no sidecar); with -o or --resume it is a usage error.
   subroutine test_no_output(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_no_output')
      call run_expect(error, dir, 'run --no-output --format csv --set sweep%t_y=0,4 '// &
         '--set sweep%t_y_points=3', 0, out, err)
      if (allocated(error)) return
      call check(error, index(out, new_line('a')//'3,0,') > 0, message='three case lines: '//out)
      if (allocated(error)) return
      call expect_in(error, err, 'no result file (--no-output)', 'the closing note')
      if (allocated(error)) return
      call shell('test -z "$(ls -A '//dir//' | grep -vxE ''out.txt|err.txt'')"', stat)
      call check(error, stat, 0, message='--no-output left files in '//dir)
      if (allocated(error)) return
      call run_expect(error, dir, 'run --no-output -o x.h5', 1, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'it goes with neither -o nor --resume', '--no-output -o')
      if (allocated(error)) return
      call run_expect(error, dir, 'run --no-output --resume', 1, out, err)
      call shell('rm -rf '//dir)
   end subroutine test_no_output

   !> A kinematic case's lines carry the wheelset inputs, the load and the friction.
   subroutine test_kinematic_inputs(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_kin_inputs')
      call run_expect(error, dir, "run -q --format csv --csv-units --set kinematics%mode=on "// &
         '--set kinematics%yaw=0.004 -o k.h5', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, line_of(out, 1), 'case,status,n_patches,n_loaded,main_patch,t_y,roll,yaw,'// &
         'vertical_force,friction,bound,v_forward,v_lateral,v_vertical,roll_rate,yaw_rate,'// &
         'pitch_rate,fn_total,', 'kinematic csv header')
      if (allocated(error)) return
      call expect_in(error, line_of(out, 2), '1,1,1,1,1,mm,rad,rad,N,1,,mm/s,mm/s,mm/s,rad/s,'// &
         'rad/s,rad/s,N,', 'kinematic units')
      if (allocated(error)) return
      call expect_in(error, line_of(out, 3), '1,0,2,2,1,4.733,0.0,0.004,64700.0,0.3,weighted,'// &
         '30000.0,', 'kinematic inputs (two patches, both loaded, the first the main one)')
      if (allocated(error)) return
      ! The joined contact's patch count is a count, as n_loaded is (it printed 2.0).
      call run_expect(error, dir, "run -q --format json --set kinematics%mode=on "// &
         '--set kinematics%yaw=0.004 --no-output', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, line_of(out, 1), '"wheel_patches":2,', 'JSON count')
      call shell('rm -rf '//dir)
   end subroutine test_kinematic_inputs

   !> The default case: two patches found, one loaded by the normal force; the same counts in
   !> the text, the CSV line, /summary and the library's result, /geometry/patch_2 beside
   !> /cases/000001/patch_1 only.
   subroutine test_patch_counts(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, text, messages(:)
      type(case_summary_type), allocatable :: s(:)
      integer, allocatable :: indices(:), failed(:)
      type(lib_error), allocatable :: lerr
      type(h5_file_type) :: file
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      integer :: n
      logical :: geometry_2, fields_2, fields_1
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_patches')
      call run_expect(error, dir, 'run -o p.h5', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, out, 'contact    2 patch(es) found, 1 loaded; main patch 1', 'text')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --format csv -o p.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, index(line_of(out, 2), '1,0,2,1,') == 1, message='csv: '//out)
      if (allocated(error)) return
      call read_result_summary(dir//'/p.h5', text, n, indices, s, failed, messages, lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      call check(error, s(1)%n_patches == 2 .and. s(1)%n_loaded == 1, &
         message='/summary/n_patches = 2 and /summary/n_loaded = 1')
      if (allocated(error)) return
      call h5_open(file, dir//'/p.h5', lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      geometry_2 = h5_exists(file, 'geometry/patch_2')
      fields_1 = h5_exists(file, 'cases/000001/patch_1')
      fields_2 = h5_exists(file, 'cases/000001/patch_2')
      call h5_close(file)
      call check(error, geometry_2 .and. fields_1 .and. .not. fields_2, &
         message='/geometry/patch_1..n_patches, /cases/000001/patch_1..n_loaded')
      if (allocated(error)) return
      ! The library's names mean the same.
      call solver%init('builtin:S1002', 'builtin:UIC60', lerr)
      if (.not. allocated(lerr)) call solver%solve(4.733_wp, 0.0_wp, &
         contact_load_type(load_normal_force, 64.7e3_wp), &
         creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp), r, lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      call check(error, r%n_patches == s(1)%n_patches .and. r%n_loaded == s(1)%n_loaded, &
         message='library and program count the patches alike')
      call shell('rm -rf '//dir)
   end subroutine test_patch_counts

   !> `profiles FILE`: summary, cleaned export readable as a case input, gnuplot script;
   !> errors for bad files and bad combinations.
   subroutine test_profiles_file(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_profiles')
      call run_expect(error, dir, 'profiles --write built-in', 0, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles built-in/S1002.txt -o clean.txt --plot s1002.gp', &
         0, out, err)
      if (allocated(error)) return
      call expect_in(error, out, 'built-in/S1002.txt: wheel, format plain', 'summary: kind')
      if (allocated(error)) return
      call expect_in(error, out, 'points     1597 read, 1603 after clean-up', &
         'summary: points (doc/app.md)')
      if (allocated(error)) return
      call expect_in(error, out, 'y          -70.000 to 60.000 mm', 'summary: range')
      if (allocated(error)) return
      call expect_in(error, out, 'units      mm', 'summary: units')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/clean.txt'), '# kind = wheel', 'exported profile')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/s1002.gp'), '$cleaned << EOD', 'gnuplot script')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/s1002.gp'), "set output 's1002.png'", &
         'gnuplot script output')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q -o w.h5 --set profiles%wheel=clean.txt', 0, out, err)
      if (allocated(error)) return
      ! The script makes its PNG where gnuplot is installed.
      call shell('command -v gnuplot > /dev/null 2>&1', stat)
      if (stat == 0) then
         call shell('cd '//dir//' && gnuplot s1002.gp > gnuplot.txt 2>&1 && test -s s1002.png', &
            stat)
         call check(error, stat, 0, message='gnuplot s1002.gp: '//file_text(dir//'/gnuplot.txt'))
         if (allocated(error)) return
      end if
      ! The rail, and -q.
      call run_expect(error, dir, 'profiles -q built-in/UIC60.txt -o rail.txt', 0, out, err)
      if (allocated(error)) return
      call check(error, len(out) == 0 .and. file_exists(dir//'/rail.txt'), message='-q: '//out)
      if (allocated(error)) return
      ! Errors: the kind contradicts the file (2), a file with too few points (2), a missing
      ! file (3), no operand or both forms (1).
      call run_expect(error, dir, 'profiles built-in/S1002.txt --kind rail', 2, out, err)
      if (allocated(error)) return
      call write_lines(dir//'/tiny.txt', [character(len=13) :: '# kind = rail', '0 0', '1 0', &
         '2 0'])
      call run_expect(error, dir, 'profiles tiny.txt -o tiny_out.txt', 2, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'tiny.txt, line 4', 'the line of the problem')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/tiny_out.txt'), message='nothing written')
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles missing.txt', 3, out, err)
      if (allocated(error)) return
      ! A file of unknown kind: the message names the command line's option.
      call shell('grep -v "^#" '//dir//'/built-in/UIC60.txt > '//dir//'/raw.txt')
      call run_expect(error, dir, 'profiles raw.txt', 2, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'pass --kind rail (or wheel), or add a comment line', &
         'profiles of a file of unknown kind')
      if (allocated(error)) return
      ! A case file's missing profile: the message names the case file, its line and the
      ! variable.
      call write_lines(dir//'/nw.nml', [character(len=24) :: '&profiles', &
         "  wheel = 'nowheel.txt'", '/'])
      call run_expect(error, dir, 'run nw.nml -o nw.h5', 3, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'nw.nml:2: &profiles wheel: ', 'a missing profile file')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/nw.h5'), message='output of a failed run')
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles', 1, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles built-in/S1002.txt --write x', 1, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles --write x --plot p.gp', 1, out, err)
      call shell('rm -rf '//dir)
   end subroutine test_profiles_file

   !> `profiles F -o F` overwrote its own input (issue 24, item 12), also through ./F, a
   !> symbolic link or a hard link, and with --force: refused with status 3 and one message,
   !> the file unchanged.
   subroutine test_profiles_own_input(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err, before
      character(len=16), parameter :: targets(5) = [character(len=16) :: 'F.txt', './F.txt', &
         'link.txt', 'hard.txt', 'F.txt --force']
      integer :: i
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_own_input')
      call run_expect(error, dir, 'profiles --write built-in', 0, out, err)
      if (allocated(error)) return
      call shell('cd '//dir//' && cp built-in/S1002.txt F.txt && ln -s F.txt link.txt && '// &
         'ln F.txt hard.txt')
      before = file_text(dir//'/F.txt')
      do i = 1, size(targets)
         call run_expect(error, dir, 'profiles F.txt -o '//trim(targets(i)), 3, out, err)
         if (allocated(error)) return
         call expect_in(error, err, 'names the input file F.txt', '-o '//trim(targets(i)))
         if (allocated(error)) return
         call check(error, file_text(dir//'/F.txt') == before, message='-o '// &
            trim(targets(i))//': the input changed')
         if (allocated(error)) return
         call check(error, count_lines(err), 1, message='one message: '//err)
         if (allocated(error)) return
      end do
      ! --plot too, and -o and --plot naming one file (status 1).
      call run_expect(error, dir, 'profiles F.txt --plot ./F.txt', 3, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles F.txt -o a.txt --plot a.txt', 1, out, err)
      if (allocated(error)) return
      call check(error, file_text(dir//'/F.txt') == before .and. &
         .not. file_exists(dir//'/a.txt'), message='nothing written')
      call shell('rm -rf '//dir)
   end subroutine test_profiles_own_input

   !> `geometry` without -o replaced ./geometry.txt and `profiles --write DIR` DIR/S1002.txt
   !> (issue 24, item 14); `profiles F -o OUT` and `--plot` likewise. A file that exists and was
   !> not written by this run is refused (status 3, unchanged, nothing else written) unless
   !> --force is given; the case file never.
   subroutine test_no_overwrite(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_no_overwrite')
      ! profiles --write DIR
      call shell('mkdir -p '//dir//'/built-in && echo mine > '//dir//'/built-in/S1002.txt')
      call run_expect(error, dir, 'profiles --write built-in', 3, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'built-in/S1002.txt: the file of --write exists', 'the message')
      if (allocated(error)) return
      call check(error, file_text(dir//'/built-in/S1002.txt') == 'mine'//new_line('a') .and. &
         .not. file_exists(dir//'/built-in/UIC60.txt'), message='--write: nothing replaced')
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles --write built-in --force', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/built-in/S1002.txt'), '# kind = wheel', &
         '--write --force replaced it')
      if (allocated(error)) return
      ! profiles FILE -o OUT, --plot SCRIPT
      call shell('echo mine > '//dir//'/out.prof && echo mine > '//dir//'/p.gp')
      call run_expect(error, dir, 'profiles built-in/S1002.txt -o out.prof', 3, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles built-in/S1002.txt --plot p.gp', 3, out, err)
      if (allocated(error)) return
      call check(error, file_text(dir//'/out.prof') == 'mine'//new_line('a') .and. &
         file_text(dir//'/p.gp') == 'mine'//new_line('a'), message='-o, --plot: unchanged')
      if (allocated(error)) return
      call run_expect(error, dir, 'profiles built-in/S1002.txt -o out.prof --plot p.gp '// &
         '--force', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.prof'), '# kind = wheel', '-o --force')
      if (allocated(error)) return
      ! A directory is never replaced, --force or not, and the message says what it is.
      call shell('mkdir -p '//dir//'/adir')
      call run_expect(error, dir, 'profiles built-in/S1002.txt -o adir --force', 3, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'adir: -o is a directory, not a file', 'directory as -o')
      if (allocated(error)) return
      call run_expect(error, dir, 'geometry -o adir', 3, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'adir: -o is a directory, not a file', 'geometry -o directory')
      if (allocated(error)) return
      ! geometry: the default geometry.txt, -o FILE, the case file
      call shell('echo mine > '//dir//'/geometry.txt')
      call run_expect(error, dir, 'geometry', 3, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'geometry.txt: the default output (no -o) exists', 'message')
      if (allocated(error)) return
      call check(error, file_text(dir//'/geometry.txt') == 'mine'//new_line('a'), &
         message='geometry.txt unchanged')
      if (allocated(error)) return
      call run_expect(error, dir, 'geometry -o geometry.txt', 3, out, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'geometry --force', 0, out, err)
      if (allocated(error)) return
      call check(error, file_text(dir//'/geometry.txt') /= 'mine'//new_line('a'), &
         message='geometry --force replaced it')
      if (allocated(error)) return
      call write_lines(dir//'/case.nml', [character(len=24) :: '&position t_y = 2.0 /'])
      call run_expect(error, dir, 'geometry case.nml -o ./case.nml --force', 3, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'names the input file case.nml', 'the case file')
      if (allocated(error)) return
      call check(error, file_text(dir//'/case.nml') == '&position t_y = 2.0 /'//new_line('a'), &
         message='the case file unchanged')
      call shell('rm -rf '//dir)
   end subroutine test_no_overwrite

   !> The reproducer of issue 24, item 2: `profiles Car7216_0001r.whl -o clean.txt`, then a case
   !> reading clean.txt as a plain file gives the contact of the .whl (γ₀ −0.068, not +0.088;
   !> 2 patches, not 3; p_max 1734 MPa, not 4805; to the 5 digits of the text summary).
   !> `run` notes on stderr where the case's settings disagree with its profiles' points
   !> (doc/app.md, "Notes on the profiles"): the built-in canted rail without
   !> track%rail_canted, the upright one with it; none for the default case, none with -q.
   subroutine test_profile_notes(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, out, err
      if (unavailable(error, .false.)) return
      dir = scratch_directory('cli_profile_notes')
      call run_expect(error, dir, 'run -o a.h5', 0, out, err)
      if (allocated(error)) return
      call check(error, index(err, 'note:') == 0, message='a note on the default case: '//err)
      if (allocated(error)) return
      ! The built-in canted rail canted again is refused by its name (status 2), after the note.
      call run_expect(error, dir, 'run -o b.h5 --set profiles%rail=builtin:UIC60-canted', 2, &
         out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: note: rail profile builtin:UIC60-canted: the head '// &
         'looks inclined by about 1:40 already', 'the canted rail without rail_canted')
      if (allocated(error)) return
      call expect_in(error, err, "rail 'builtin:UIC60-canted' is the UIC60 head canted 1:40 "// &
         'already', 'the refusal of the canted rail canted again')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -o c.h5 --set track%rail_canted=.true.', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'shcontact: note: rail profile builtin:UIC60: the head looks '// &
         'upright', 'the upright rail with rail_canted')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -o d.h5 --set profiles%rail=builtin:UIC60-canted '// &
         '--set track%rail_canted=.true.', 0, out, err)
      if (allocated(error)) return
      call check(error, index(err, 'note:') == 0, message='a note on a consistent case: '//err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q -o e.h5 --set track%rail_canted=.true.', 0, out, err)
      if (allocated(error)) return
      call check(error, len(err) == 0, message='-q prints no note: '//err)
      call shell('rm -rf '//dir)
   end subroutine test_profile_notes

   !> The same notes on the external data's measured pair: the noise of each unsmoothed file
   !> with the smoothing `shcontact profiles FILE` suggests (2.9 and 8.1 mm), the rail's 1:48
   !> cant; none once the case sets them. Skipped without the external data.
   subroutine test_profile_notes_measured(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, whl, ban, out, err, pair
      if (unavailable(error, .false.)) return
      whl = external_file('profiles/Car7216_0001r.whl', error, absolute=.true.)
      if (allocated(error)) return
      ban = external_file('profiles/avg_HR.BAN', error, absolute=.true.)
      if (allocated(error)) return
      dir = scratch_directory('cli_profile_notes_measured')
      pair = ' --set profiles%wheel='//whl//' --set profiles%rail='//ban
      call run_expect(error, dir, 'run -o a.h5'//pair, 0, out, err)
      if (allocated(error)) return
      call expect_in(error, err, 'profiles%wheel_smoothing = 2.9 mm keeps it below', &
         'the wheel smoothing note')
      if (allocated(error)) return
      call expect_in(error, err, 'profiles%rail_smoothing = 8.1 mm keeps it below', &
         'the rail smoothing note')
      if (allocated(error)) return
      call expect_in(error, err, 'looks inclined by about 1:48 already', 'the rail cant note')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -o b.h5'//pair//' --set profiles%wheel_smoothing=2.9 '// &
         '--set profiles%rail_smoothing=8.1 --set track%rail_canted=.true.', 0, out, err)
      if (allocated(error)) return
      call check(error, index(err, 'note:') == 0, message='a note on a consistent case: '//err)
      call shell('rm -rf '//dir)
   end subroutine test_profile_notes_measured

   subroutine test_miniprof_written(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, whl, out, err, a, b
      if (unavailable(error, .false.)) return
      whl = external_file('profiles/Car7216_0001r.whl', error, absolute=.true.)
      if (allocated(error)) return
      dir = scratch_directory('cli_miniprof_written')
      call run_expect(error, dir, 'profiles '//whl//' -o clean.txt', 0, out, err)
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/clean.txt'), '# origin: on the tape circle', &
         'the header says where the origin is')
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --format text -o a.h5 --set profiles%wheel='//whl, &
         0, a, err)
      if (allocated(error)) return
      call run_expect(error, dir, 'run -q --format text -o b.h5 --set profiles%wheel=clean.txt', &
         0, b, err)
      if (allocated(error)) return
      call check(error, a(index(a, new_line('a')):) == b(index(b, new_line('a')):), &
         message='the contact differs: '//a//' vs '//b)
      call shell('rm -rf '//dir)
   end subroutine test_miniprof_written

   !> The reproducer of issue 24, item 5: two and nine points added on every chord of
   !> data/profiles/S1002.txt (awk, 17 significant digits) moved F_x from −5846.8 to −5729.9 N and
   !> −6938.8 N; the text summary (forces, moment, pressure, γ₀; 5 digits) must be the same.
   subroutine test_collinear_points(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, s1002, out, err, a, b
      character(len=2) :: k
      integer :: i
      if (unavailable(error, .false.)) return
      s1002 = current_directory()//'/data/profiles/S1002.txt'
      if (.not. file_exists(s1002)) then
         call skip_test(error, s1002//' is not available')
         return
      end if
      dir = scratch_directory('cli_collinear')
      call run_expect(error, dir, 'run -q --format text -o a.h5 --set profiles%wheel='//s1002, &
         0, a, err)
      if (allocated(error)) return
      do i = 1, 2
         k = merge(' 2', ' 9', i == 1)
         call shell('awk -v k='//trim(adjustl(k))//' ''/^#/ { print; next } NF >= 2 { if '// &
            '(n++) for (j = 1; j <= k; j++) printf "%.17g %.17g\n", py + j*($1 - py)/(k + 1), '// &
            'pz + j*($2 - pz)/(k + 1); print; py = $1; pz = $2 }'' '//s1002//' > '//dir// &
            '/dense.txt')
         call run_expect(error, dir, 'run -q --format text -o b.h5 --set '// &
            'profiles%wheel=dense.txt', 0, b, err)
         if (allocated(error)) return
         call check(error, a(index(a, new_line('a')):) == b(index(b, new_line('a')):), &
            message='k ='//k//' points added per interval: the forces differ: '//a//' vs '//b)
         if (allocated(error)) return
         call shell('rm -f '//dir//'/b.h5')
      end do
      call shell('rm -rf '//dir)
   end subroutine test_collinear_points

   !> The README's and doc/app.md's `fpm run ... -- run` commands name an output under build/
   !> or /tmp (never the default shcontact.h5 in the repository root), and .gitignore keeps
   !> result files out of git.
   subroutine test_doc_outputs(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      if (.not. file_exists('README.md') .or. .not. file_exists('doc/app.md')) then
         call skip_test(error, 'README.md and doc/app.md are not in the working directory')
         return
      end if
      call shell('grep -h "fpm run .*-- run" README.md doc/app.md | grep -v -- "--check" | '// &
         'grep -v -e " -o build/" -e " -o /tmp/" > /dev/null', stat)
      call check(error, stat, 1, message='a README.md or doc/app.md command `fpm run ... -- '// &
         'run` without -o build/... or -o /tmp/...')
      if (allocated(error)) return
      call shell('grep -q "^\*\.h5$" .gitignore', stat)
      call check(error, stat, 0, message='.gitignore ignores *.h5')
   end subroutine test_doc_outputs

end module test_cli
