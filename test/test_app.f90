!> Tests of the shcontact program itself, run as a user runs it (execute_command_line): the
!> default case, sweeps with 1 and 2 threads, shards and merge, an interrupted and resumed sweep,
!> every kind of bad input (exit status, message, no output left behind), and h5dump reading
!> every output.
!>
!> The program is found next to the tester in fpm's build tree (build/<hash>/test/tester →
!> build/<hash>/app/shcontact, which `fpm test` builds with the same flags), or at the path in
!> the environment variable SHCONTACT_EXE. Scratch files go to a fresh directory under $TMPDIR
!> (default /tmp) that is removed at the end. Tests that need h5dump skip without it.
module test_app
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_files, only: file_exists, process_id
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_strings, only: str_int
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_geometry_kinematics, only: wheelset_state_type, pure_rolling_pitch_rate
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      load_normal_force, load_vertical_force
   use shcontact_output_results, only: case_group_name
   use shcontact_output_merge, only: read_result_summary
   use shcontact_output_hdf5, only: h5_file_type, h5_open, h5_close, h5_read, h5_exists, &
      h5_read_attribute
   use shcontact_case_result, only: case_summary_type, summary_columns, n_summary_columns, &
      summary_value, summary_column_used
   use shcontact_geometry_track, only: side_right, side_left
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_input_config, only: case_config_type, case_point_type, load_config, &
      load_mode_vertical
   use shcontact_case_result, only: case_result_type
   use shcontact_case_runner, only: run_setup_type, stage_type, prepare_run, solve_geometry, &
      solve_stage, solve_case, case_workspace_type, tangential_patch_type
   use shcontact_tangential_option_registry, only: bound_clipped, spin_geometric
   implicit none
   private
   public :: collect_app
   ! Helpers shared with the robustness suite (test_robustness).
   public :: program_path, scratch_directory, shell, run_program, file_text, write_lines, &
      unavailable, expect_in, expect_failure, current_directory

   !> The sweep used by the determinism, shard and resume tests: 3 × 2 × 2 = 12 cases,
   !> all fields, checkpoint blocks of 3 cases, coarse grids to keep it fast.
   !> A kinematic case: the wheelset of examples/kinematic.nml (t_y = 4.733 mm, yaw 4 mrad,
   !> 30 m/s, pure rolling, 64.7 kN wheel load shared by the patches; two patches).
   character(len=*), parameter :: kinematic_case(*) = [character(len=72) :: &
      '&position t_y = 4.733 /', &
      "&kinematics mode = 'on', yaw = 0.004, v_forward = 30000.0 /", &
      "&load mode = 'vertical', vertical_force = 64700.0 /"]

   !> A kinematic sweep: t_y = 0, 4.733, 8 mm (tread, two patches, flange) × yaw 0, 4 mrad,
   !> all fields, checkpoint blocks of 2 cases, coarse grids.
   character(len=*), parameter :: kinematic_sweep_case(*) = [character(len=72) :: &
      "&kinematics mode = 'on', v_forward = 30000.0 /", &
      '&sweep t_y = 0.0, 4.733, 8.0, yaw = 0.0, 0.004 /', &
      "&output fields = 'all', checkpoint_cases = 2, compression = 1 /", &
      '&normal n_strips = 40 /', &
      '&tangential n_elements = 20 /']

   character(len=*), parameter :: sweep_case(*) = [character(len=72) :: &
      '! 12-case sweep of the app tests', &
      '&sweep', &
      "  bound = 'weighted', 'clipped'", &
      '  nu_x = 0.0, 1.0e-3, 2.0e-3', &
      '  phi = 0.0, 1.0e-3', &
      '/', &
      "&output fields = 'all', checkpoint_cases = 3, compression = 1 /", &
      '&normal n_strips = 40 /', &
      '&tangential n_elements = 20 /']

   !> A 3 × 3 × 4 = 36-case DOE on the default case storing every field (about 220 KiB of
   !> results per case), checkpoint blocks as large as the memory bound allows.
   character(len=*), parameter :: fields_doe_case(*) = [character(len=72) :: &
      "&sweep mode = 'grid', nu_x = 0.0, 2.0e-3, nu_x_points = 3,", &
      '  nu_y = 0.0, 2.0e-3, nu_y_points = 3,', &
      '  phi = 0.0, 2.0e-3, phi_points = 4 /', &
      "&output fields = 'all', checkpoint_cases = 100000 /"]

contains

   subroutine collect_app(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('default_case', test_default_case), &
         new_unittest('check_prints_resolved_namelist', test_check), &
         new_unittest('summary_formats', test_formats), &
         new_unittest('threads_give_identical_files', test_threads), &
         new_unittest('shards_merge_to_unsharded', test_shards), &
         new_unittest('killed_and_resumed', test_resume), &
         new_unittest('some_cases_fail', test_partial_failure), &
         new_unittest('summary_blocks_not_read_back', test_summary_blocks), &
         new_unittest('report_lines_threads', test_report_lines_threads), &
         new_unittest('bad_input', test_bad_input), &
         new_unittest('usage_errors', test_usage), &
         new_unittest('profiles_and_geometry_commands', test_other_commands), &
         new_unittest('prescribed_default_unchanged', test_prescribed_unchanged), &
         new_unittest('kinematic_case_equals_library', test_kinematic_case), &
         new_unittest('kinematic_sweep', test_kinematic_sweep), &
         new_unittest('sweep_memory_bounded', test_memory_bound), &
         new_unittest('both_wheels_equal_library', test_both_wheels), &
         new_unittest('prepared_workspace_reused_only_when_same', test_prepared_reuse), &
         new_unittest('joined_contact_equals_library', test_joined_contact) &
         ]
   end subroutine collect_app

   ! ------------------------------------------------------------------------------------------
   ! Helpers
   ! ------------------------------------------------------------------------------------------

   !> The program, or '' when it cannot be found.
   function program_path() result(path)
      character(len=:), allocatable :: path
      character(len=4096) :: buf
      integer :: length, stat, slash
      call get_environment_variable('SHCONTACT_EXE', buf, length, stat)
      if (stat == 0 .and. length > 0) then
         path = buf(1:length)
         return
      end if
      call get_command_argument(0, buf, length)
      path = ''
      slash = index(buf(1:length), '/test/', back=.true.)
      if (slash == 0) return
      path = buf(1:slash)//'app/shcontact'
      if (path(1:1) /= '/') path = current_directory()//'/'//path
      if (.not. file_exists(path)) path = ''
   end function program_path

   function current_directory() result(dir)
      character(len=:), allocatable :: dir
      character(len=4096) :: buf
      integer :: length, stat
      call get_environment_variable('PWD', buf, length, stat)
      dir = buf(1:length)
   end function current_directory

   !> A fresh scratch directory for one test.
   function scratch_directory(tag) result(dir)
      character(len=*), intent(in) :: tag
      character(len=:), allocatable :: dir
      character(len=4096) :: buf
      character(len=16) :: pid
      integer :: length, stat
      call get_environment_variable('TMPDIR', buf, length, stat)
      if (stat /= 0 .or. length == 0) then
         buf = '/tmp'
         length = 4
      end if
      write (pid, '(i0)') process_id()
      dir = buf(1:length)//'/shcontact_test_app_'//trim(pid)//'_'//tag
      call shell('rm -rf '//dir//' && mkdir -p '//dir)
   end function scratch_directory

   subroutine shell(command, stat)
      character(len=*), intent(in) :: command
      integer, intent(out), optional :: stat
      integer :: s, cmdstat
      call execute_command_line(command, exitstat=s, cmdstat=cmdstat)
      if (cmdstat /= 0) s = -1
      if (present(stat)) stat = s
   end subroutine shell

   !> Run the program in `dir` with arguments `args` (and environment assignments `env`);
   !> stdout and stderr go to dir/out.txt and dir/err.txt. Returns the exit status.
   function run_program(dir, args, env) result(stat)
      character(len=*), intent(in) :: dir, args
      character(len=*), intent(in), optional :: env
      integer :: stat
      character(len=:), allocatable :: prefix
      prefix = 'env -u SLURM_ARRAY_TASK_ID -u SLURM_ARRAY_TASK_COUNT -u SLURM_ARRAY_TASK_MIN '// &
         '-u SLURM_ARRAY_TASK_MAX -u SLURM_ARRAY_TASK_STEP '// &
         'SOURCE_DATE_EPOCH=1700000000 OMP_NUM_THREADS=2 '
      if (present(env)) prefix = prefix//env//' '
      call shell('cd '//dir//' && '//prefix//program_path()//' '//args// &
         ' > out.txt 2> err.txt', stat)
   end function run_program

   !> The whole text of a file ('' when it is missing).
   function file_text(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: unit, stat, size_
      text = ''
      open (newunit=unit, file=name, access='stream', form='unformatted', status='old', &
         action='read', iostat=stat)
      if (stat /= 0) return
      inquire (unit=unit, size=size_)
      if (size_ > 0) then
         deallocate (text)
         allocate (character(len=size_) :: text)
         read (unit, iostat=stat) text
      end if
      close (unit)
   end function file_text

   !> The integer a file holds (−1 when it holds none).
   integer function file_integer(name) result(value)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: stat
      text = file_text(name)
      read (text, *, iostat=stat) value
      if (stat /= 0) value = -1
   end function file_integer

   subroutine write_lines(name, lines)
      character(len=*), intent(in) :: name
      character(len=*), intent(in) :: lines(:)
      integer :: unit, i
      open (newunit=unit, file=name, status='replace', action='write')
      do i = 1, size(lines)
         write (unit, '(a)') trim(lines(i))
      end do
      close (unit)
   end subroutine write_lines

   !> Skip when the program (or h5dump, if asked) is not available.
   logical function unavailable(error, need_h5dump)
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in) :: need_h5dump
      integer :: stat
      unavailable = len(program_path()) == 0
      if (unavailable) then
         call skip_test(error, 'the shcontact program was not found next to the tester; '// &
            'set SHCONTACT_EXE')
         return
      end if
      if (need_h5dump) then
         call shell('h5dump --version > /dev/null 2>&1', stat)
         unavailable = stat /= 0
         if (unavailable) call skip_test(error, 'h5dump is not installed (scripts/setup)')
      end if
   end function unavailable

   !> h5dump of a file with full precision, without the line naming the file and without the
   !> attributes that record how and when it was made (command line, date, threads); object
   !> references (dimension scales) by the path they point to, not by address.
   subroutine dump(file, dumpfile, stat)
      character(len=*), intent(in) :: file, dumpfile
      integer, intent(out) :: stat
      call shell('h5dump -m %.17g '//file//" | sed -e '1d' -e '/ATTRIBUTE ""command_line""/,"// &
         "/^   }$/d' -e '/ATTRIBUTE ""date""/,/^   }$/d' -e '/ATTRIBUTE ""threads""/,/^   }$/d'"// &
         " -e 's/DATASET [0-9][0-9]* /DATASET /g' > "//dumpfile//' && test -s '//dumpfile, stat)
   end subroutine dump

   !> Check that two result files hold the same data (see [[dump]]).
   subroutine check_same_content(error, a, b, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: a, b, what
      call check_same_content_but(error, a, b, '', what)
   end subroutine check_same_content

   !> [[check_same_content]], but for the lines of the dumps that name `variable` (a namelist
   !> variable set differently in the two runs) and the string sizes, which it changes.
   subroutine check_same_content_but(error, a, b, variable, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: a, b, variable, what
      integer :: stat
      call dump(a, a//'.dump', stat)
      if (stat == 0) call dump(b, b//'.dump', stat)
      call check(error, stat, 0, message='h5dump reads '//a//' and '//b)
      if (allocated(error)) return
      if (len(variable) > 0) then
         call shell('grep -v -e '//variable//' -e STRSIZE '//a//'.dump > '//a//'.dump2 && '// &
            'mv '//a//'.dump2 '//a//'.dump && grep -v -e '//variable//' -e STRSIZE '//b// &
            '.dump > '//b//'.dump2 && mv '//b//'.dump2 '//b//'.dump', stat)
      end if
      call shell('cmp -s '//a//'.dump '//b//'.dump', stat)
      call check(error, stat, 0, message=what//': '//a//' and '//b//' differ')
   end subroutine check_same_content_but

   subroutine expect_in(error, text, fragment, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: text, fragment, what
      if (index(text, fragment) == 0) call test_failed(error, what//': expected "'// &
         fragment//'" in: '//text)
   end subroutine expect_in

   ! ------------------------------------------------------------------------------------------
   ! Tests
   ! ------------------------------------------------------------------------------------------

   subroutine test_default_case(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, text
      integer :: stat, n_datasets, n_units
      if (unavailable(error, .true.)) return
      dir = scratch_directory('default')
      stat = run_program(dir, 'run -o default.h5')
      call check(error, stat, 0, message='default case: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      call expect_in(error, text, 'Fn = 64700', 'summary of the headline case')
      if (allocated(error)) return
      call expect_in(error, text, 'fx = ', 'normalised forces in the summary')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'results in default.h5', 'note on stderr')
      if (allocated(error)) return
      ! Self-describing root, the resolved namelist, fields of the case.
      call shell('cd '//dir//' && h5dump -A default.h5 > attrs.txt', stat)
      call check(error, stat, 0, message='h5dump reads the output')
      if (allocated(error)) return
      text = file_text(dir//'/attrs.txt')
      call expect_in(error, text, 'ATTRIBUTE "sign_convention"', 'root attributes')
      if (allocated(error)) return
      call expect_in(error, text, 'ATTRIBUTE "units"', 'units')
      if (allocated(error)) return
      call expect_in(error, text, '"2023-11-14T22:13:20Z"', 'date from SOURCE_DATE_EPOCH')
      if (allocated(error)) return
      call expect_in(error, text, 'DATASET "px"', 'traction field stored')
      if (allocated(error)) return
      call expect_in(error, text, 'ATTRIBUTE "adhesion"', 'state code meanings')
      if (allocated(error)) return
      ! Every dataset has a units attribute.
      ! (`DATASET "name"` opens a dataset; `DATASET 1234 /path` is a dimension-scale reference.)
      call shell('cd '//dir//' && grep -c "^ *DATASET \"" attrs.txt > n_datasets.txt && '// &
         'grep -c "ATTRIBUTE \"units\"" attrs.txt > n_units.txt', stat)
      n_datasets = file_integer(dir//'/n_datasets.txt')
      n_units = file_integer(dir//'/n_units.txt')
      call check(error, n_units, n_datasets + 1, &
         message='one units attribute per dataset (and the root attribute units)')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/default.h5.partial'), &
         message='the checkpoint directory is removed')
      call shell('rm -rf '//dir)
   end subroutine test_default_case

   subroutine test_check(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, first
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('check')
      stat = run_program(dir, '--check --set creepage%nu_y=-1e-3 run')
      call check(error, stat, 1, message='options before the command are a usage error')
      if (allocated(error)) return
      stat = run_program(dir, 'run --check --set creepage%nu_y=-1e-3 --set sweep%phi=0,1e-3')
      call check(error, stat, 0, message='--check: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      first = file_text(dir//'/out.txt')
      call expect_in(error, first, 'nu_y = -0.001', 'the override in the resolved namelist')
      if (allocated(error)) return
      call expect_in(error, first, "wheel = 'builtin:S1002'", 'defaults in the resolved namelist')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/shcontact.h5'), message='--check solves nothing')
      if (allocated(error)) return
      ! The printed namelist is a case file that resolves to itself.
      call shell('cp '//dir//'/out.txt '//dir//'/resolved.nml')
      stat = run_program(dir, 'run resolved.nml --check')
      call check(error, stat, 0, message='resolved namelist as a case file')
      if (allocated(error)) return
      call check(error, file_text(dir//'/out.txt') == first, &
         message='the resolved namelist reads back to itself')
      call shell('rm -rf '//dir)
   end subroutine test_check

   subroutine test_formats(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, text
      integer :: stat, lines
      if (unavailable(error, .false.)) return
      dir = scratch_directory('formats')
      call write_lines(dir//'/sweep.nml', sweep_case)
      stat = run_program(dir, 'run sweep.nml -q --format csv -o s.h5')
      call check(error, stat, 0, message='csv: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      call expect_in(error, text, 'case,status,n_patches,n_loaded,main_patch,t_y,roll,normal_force,'// &
         'friction,bound,spin_model,nu_x,nu_y,phi,fn_total', 'csv header')
      if (allocated(error)) return
      call shell('test $(wc -l < '//dir//'/out.txt) -eq 13', stat)
      call check(error, stat, 0, message='a header and one csv line per case')
      if (allocated(error)) return
      call check(error, len(file_text(dir//'/err.txt')) == 0, message='-q: nothing on stderr')
      if (allocated(error)) return
      stat = run_program(dir, 'run sweep.nml -q --format json -o s.h5')
      call check(error, stat, 0, message='json')
      if (allocated(error)) return
      call shell('grep -c "^{\"case\":[0-9]*,\"status\":0,.*\"fy_norm\":.*}$" '//dir// &
         '/out.txt > '//dir//'/n.txt', stat)
      lines = file_integer(dir//'/n.txt')
      call check(error, lines, 12, message='one JSON object per line and case')
      call shell('rm -rf '//dir)
   end subroutine test_formats

   subroutine test_threads(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('threads')
      call shell('mkdir -p '//dir//'/one '//dir//'/two')
      call write_lines(dir//'/sweep.nml', sweep_case)
      ! The same command line in two directories; only the thread count differs.
      stat = run_program(dir//'/one', 'run ../sweep.nml -q -o out.h5', 'OMP_NUM_THREADS=1')
      call check(error, stat, 0, message='1 thread: '//file_text(dir//'/one/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir//'/two', 'run ../sweep.nml -q -o out.h5', 'OMP_NUM_THREADS=2')
      call check(error, stat, 0, message='2 threads: '//file_text(dir//'/two/err.txt'))
      if (allocated(error)) return
      ! The files record their thread count (root attribute `threads`), so they are compared
      ! through h5dump at full precision: every dataset and every other attribute.
      call check_same_content(error, dir//'/one/out.h5', dir//'/two/out.h5', 'threads')
      call shell('rm -rf '//dir)
   end subroutine test_threads

   subroutine test_shards(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('shards')
      call shell('mkdir -p '//dir//'/whole')
      call write_lines(dir//'/sweep.nml', sweep_case)
      stat = run_program(dir//'/whole', 'run ../sweep.nml -q -o out.h5')
      call check(error, stat, 0, message='unsharded: '//file_text(dir//'/whole/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run sweep.nml -q -o out.h5 --shard 1/3')
      if (stat == 0) stat = run_program(dir, 'run sweep.nml -q -o out.h5 --shard slurm', &
         'SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=1 SLURM_ARRAY_TASK_COUNT=3')
      if (stat == 0) stat = run_program(dir, 'run sweep.nml -q -o out.h5 --shard=slurm', &
         'SLURM_ARRAY_TASK_ID=2 SLURM_ARRAY_TASK_MIN=0 SLURM_ARRAY_TASK_COUNT=3')
      call check(error, stat, 0, message='shards: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_exists(dir//'/out-shard1of3.h5') .and. &
         file_exists(dir//'/out-shard2of3.h5') .and. file_exists(dir//'/out-shard3of3.h5'), &
         message='one file per shard, the third from SLURM_ARRAY_TASK_ID - _MIN + 1')
      if (allocated(error)) return
      stat = run_program(dir, 'merge out.h5 out-shard3of3.h5 out-shard1of3.h5 '// &
         'out-shard2of3.h5')
      call check(error, stat, 0, message='merge: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check_same_content(error, dir//'/whole/out.h5', dir//'/out.h5', 'shard + merge')
      if (allocated(error)) return
      stat = run_program(dir, 'merge bad.h5 out-shard1of3.h5 out-shard2of3.h5')
      call check(error, stat, 2, message='merge with a shard missing')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '4 of 12 cases are missing', 'message')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/bad.h5'), message='no file from a failed merge')
      call shell('rm -rf '//dir)
   end subroutine test_shards

   subroutine test_resume(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('resume')
      call shell('mkdir -p '//dir//'/whole')
      call write_lines(dir//'/sweep.nml', sweep_case)
      stat = run_program(dir//'/whole', 'run ../sweep.nml -q -o out.h5')
      call check(error, stat, 0, message='uninterrupted: '//file_text(dir//'/whole/err.txt'))
      if (allocated(error)) return
      ! Killed after 2 of 4 checkpoint blocks.
      stat = run_program(dir, 'run sweep.nml -q -o out.h5', &
         'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=2')
      call check(error, stat /= 0, message='the interrupted run fails')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5'), &
         message='no file under the final name after the interruption')
      if (allocated(error)) return
      call shell('h5dump -d /summary/case '//dir//'/out.h5.partial/block_000002.h5 > '// &
         dir//'/block.txt', stat)
      call check(error, stat, 0, message='finished blocks are readable')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/block.txt'), '(0): 4, 5, 6', 'cases of block 2')
      if (allocated(error)) return
      stat = run_program(dir, 'run sweep.nml -o out.h5 --resume')
      call check(error, stat, 0, message='resume: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '12 of 12 case(s) solved (6 from the '// &
         'checkpoint)', 'finished cases are not solved again')
      if (allocated(error)) return
      call check_same_content(error, dir//'/whole/out.h5', dir//'/out.h5', 'killed and resumed')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5.partial'), &
         message='the checkpoint is removed when complete')
      if (allocated(error)) return
      ! A checkpoint of another configuration is not used.
      stat = run_program(dir, 'run sweep.nml -q -o other.h5', &
         'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=1')
      stat = run_program(dir, 'run sweep.nml -q -o other.h5 --resume --set material%friction=0.2')
      call check(error, stat, 2, message='resume with another configuration')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'another configuration', 'message')
      if (allocated(error)) return
      ! A checkpoint of a version that wrote its numbers otherwise (0.5005 as
      ! 0.5004999999999999 before stop 49) is this run's: resumed.
      stat = run_program(dir, 'run sweep.nml -q -o third.h5 --set material%friction=0.5005', &
         'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=1')
      call shell('cd '//dir//'/third.h5.partial && grep -c "0.5005" configuration.txt && '// &
         'sed -i "s/0\.5005/0.5004999999999999/" configuration.txt && grep -q '// &
         '0.5004999999999999 configuration.txt', stat)
      call check(error, stat, 0, message='the key of the checkpoint holds 0.5005')
      if (allocated(error)) return
      stat = run_program(dir, 'run sweep.nml -o third.h5 --resume --set material%friction=0.5005')
      call check(error, stat, 0, message='resume of the older writing: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '(3 from the checkpoint)', &
         'the older writing''s cases are not solved again')
      call shell('rm -rf '//dir)
   end subroutine test_resume

   subroutine test_partial_failure(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('partial')
      ! The second approach (5 mm) is far beyond the patch geometry (tables end at a 2 mm gap).
      stat = run_program(dir, 'run -o f.h5 --set load%mode=approach '// &
         '--set sweep%approach=0.05,5 --format csv')
      call check(error, stat, 4, message='some cases failed: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'case 2 failed', 'the failed case')
      if (allocated(error)) return
      call shell('h5dump -d /failures/case '//dir//'/f.h5 > '//dir//'/failures.txt', stat)
      call check(error, stat, 0, message='the file records the failures')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/failures.txt'), '(0): 2', 'failed case number')
      call shell('rm -rf '//dir)
   end subroutine test_partial_failure

   !> Issue 27: a run without fields holds every case's summary in memory, so its output is
   !> written from them even when it wrote checkpoint block files (they are not read back):
   !> the approach sweep of 13 cases, 3 to a block and some failing, gives the same file as the
   !> run that held every case and wrote no block file (its failures table included), and -v
   !> says so.
   subroutine test_summary_blocks(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, text
      character(len=*), parameter :: sweep = 'run --set load%mode=approach '// &
         '--set sweep%approach=0.05,5 --set sweep%approach_points=13 -v --threads 2 '
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('summary_blocks')
      ! The same output name in two folders (the namelist in the file names it).
      call shell('mkdir -p '//dir//'/blocks '//dir//'/memory')
      stat = run_program(dir//'/blocks', sweep//'-o out.h5 --set output%checkpoint_cases=3')
      call check(error, stat, 4, message='blocks, some cases failed: '// &
         file_text(dir//'/blocks/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/blocks/err.txt')
      call expect_in(error, text, '0 block file(s) merged; the output written from memory', &
         'blocks written, not merged')
      if (allocated(error)) return
      call check(error, integer_after(text, 'block file(s) merged', 'from memory (') >= 2, &
         message='checkpoint block files written (at least 2): '//text)
      if (allocated(error)) return
      stat = run_program(dir//'/memory', sweep//'-o out.h5 --set output%checkpoint_cases=0')
      call check(error, stat, 4, message='from memory: '//file_text(dir//'/memory/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/memory/err.txt'), '0 block file(s) merged'// &
         new_line('a'), 'no block file')
      if (allocated(error)) return
      call shell('h5dump -d /failures/case '//dir//'/blocks/out.h5 > '//dir//'/failures.txt', &
         stat)
      call check(error, stat, 0, message='the file records the failures')
      if (allocated(error)) return
      call check_same_content_but(error, dir//'/blocks/out.h5', dir//'/memory/out.h5', &
         'checkpoint_cases', 'written from the summaries with or without block files')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_summary_blocks

   !> Issue 27: the report lines printed after a sweep are formatted by the run's threads
   !> (`report_lines`); with 2 threads they are the same bytes as with 1, in every format, on
   !> an approach sweep of 400 cases of which some fail (their messages in the lines).
   subroutine test_report_lines_threads(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      character(len=*), parameter :: formats(3) = [character(len=4) :: 'text', 'csv', 'json']
      character(len=*), parameter :: sweep = 'run --set load%mode=approach '// &
         '--set sweep%approach=0.05,5 --set sweep%approach_points=400 --no-output --format '
      integer :: stat, k, t
      if (unavailable(error, .true.)) return
      dir = scratch_directory('report_threads')
      do k = 1, size(formats)
         do t = 1, 2
            stat = run_program(dir, sweep//trim(formats(k))//' --threads '//str_int(t))
            call check(error, stat, 4, message=trim(formats(k))//', some cases failed: '// &
               file_text(dir//'/err.txt'))
            if (allocated(error)) return
            call shell('mv '//dir//'/out.txt '//dir//'/'//trim(formats(k))//str_int(t)//'.txt', &
               stat)
         end do
         call shell('cmp -s '//dir//'/'//trim(formats(k))//'1.txt '//dir//'/'// &
            trim(formats(k))//'2.txt', stat)
         call check(error, stat, 0, message=trim(formats(k))//': the report with 2 threads '// &
            'differs from the one with 1')
         if (allocated(error)) return
      end do
      call expect_in(error, file_text(dir//'/csv2.txt'), 'load too large', &
         'a failed case''s message in the CSV report')
      if (allocated(error)) return
      ! Every JSON line has the same keys: a failed case's results are null.
      call expect_in(error, file_text(dir//'/json2.txt'), '"fx":null,', &
         'a failed case''s results as null in the JSON report')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_report_lines_threads

   !> Each kind of bad input: exit status, a message naming the problem, no output left.
   subroutine test_bad_input(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('bad')
      call write_lines(dir//'/unknown.nml', [character(len=40) :: '&creepage', &
         '  nu_x = 1e-3', '  spin = 2e-4', '/'])
      call write_lines(dir//'/type.nml', [character(len=40) :: '&material friction = high /'])
      call write_lines(dir//'/range.nml', [character(len=40) :: '&material', 'poisson = 0.7', &
         '/'])
      call write_lines(dir//'/broken.prr', [character(len=40) :: '0.0 0.0', '1.0 abc', &
         '2.0 0.5'])
      call expect_failure(error, dir, 'run unknown.nml', 2, &
         'unknown.nml:3: &creepage: unknown variable "spin"')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run type.nml', 2, &
         'type.nml:1: &material friction = high: expected a real number')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run range.nml', 2, &
         'range.nml:2: &material poisson = 0.7 is out of range; expected 0.0 <= poisson < 0.5')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run --set profiles%rail=missing.prr', 3, 'missing.prr')
      if (allocated(error)) return
      call expect_failure(error, dir, "run --set profiles%rail=broken.prr --set "// &
         "profiles%rail_format=plain", 2, 'broken.prr')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run --set track%flange_back_distance=1800', 6, &
         'do not overlap')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run -o /nonexistent_shcontact_dir/out.h5', 3, &
         'cannot write the output "/nonexistent_shcontact_dir/out.h5"')
      if (allocated(error)) return
      call check(error, .not. file_exists('/nonexistent_shcontact_dir'), &
         message='nothing created for an unwritable output')
      call shell('rm -rf '//dir)
   end subroutine test_bad_input

   !> Run, expect the status and the message on stderr, and no output file or checkpoint.
   subroutine expect_failure(error, dir, args, status, fragment)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, args, fragment
      integer, intent(in) :: status
      integer :: stat
      if (index(args, ' -o ') > 0) then
         stat = run_program(dir, args)
      else
         stat = run_program(dir, args//' -o out.h5')
      end if
      call check(error, stat, status, message=args//': exit status; stderr: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), fragment, args)
      if (allocated(error)) return
      call shell('cd '//dir//' && test -z "$(ls -d out.h5* shcontact.h5* 2>/dev/null)"', stat)
      call check(error, stat, 0, message=args//': an output file or checkpoint was left behind')
   end subroutine expect_failure

   subroutine test_usage(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('usage')
      stat = run_program(dir, '--version')
      call check(error, stat, 0, message='--version')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'shcontact 0.', '--version output')
      if (allocated(error)) return
      stat = run_program(dir, '--help')
      call check(error, stat, 0, message='--help')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'Exit status', '--help lists exit codes')
      if (allocated(error)) return
      stat = run_program(dir, 'run --frobnicate')
      call check(error, stat, 1, message='unknown option')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'unknown option "--frobnicate"', 'message')
      if (allocated(error)) return
      stat = run_program(dir, 'run --shard 4/3')
      call check(error, stat, 1, message='bad shard')
      if (allocated(error)) return
      stat = run_program(dir, 'run --threads 0')
      call check(error, stat, 1, message='bad thread count')
      if (allocated(error)) return
      stat = run_program(dir, 'frobnicate')
      call check(error, stat, 1, message='unknown command')
      call shell('rm -rf '//dir)
   end subroutine test_usage

   subroutine test_other_commands(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('commands')
      stat = run_program(dir, 'profiles --write built-in')
      call check(error, stat, 0, message='profiles --write: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_exists(dir//'/built-in/S1002.txt') .and. &
         file_exists(dir//'/built-in/UIC60.txt'), message='built-in profiles written')
      if (allocated(error)) return
      ! A written profile reads back as a case input.
      stat = run_program(dir, 'run -q --check --set profiles%wheel=built-in/S1002.txt')
      call check(error, stat, 0, message='written profile as input: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'geometry -o geometry.txt --set position%t_y=0')
      call check(error, stat, 0, message='geometry: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/geometry.txt'), '# patch 1 of', 'geometry table')
      if (allocated(error)) return
      ! The cleaned profile's hint names it by its absolute path: a case file elsewhere reads a
      ! relative name from its own folder (`-o sub/w.txt` hinted wheel = 'sub/w.txt').
      call shell('mkdir -p '//dir//'/sub')
      stat = run_program(dir, 'profiles built-in/S1002.txt -o sub/w.txt')
      call check(error, stat, 0, message='profiles -o: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), "a case reads it as wheel = '/", &
         'the absolute path in the hint')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), "/sub/w.txt')", 'the file in the hint')
      if (allocated(error)) return
      ! The result file's /input/namelist is a case file that reruns the case wherever it is
      ! saved: its profile files by absolute paths (a run from `sub/` with `../built-in/...`
      ! stored the name as typed, which another folder then could not open).
      stat = run_program(dir//'/sub', 'run -q -o n.h5 --set profiles%wheel=../built-in/S1002.txt')
      call check(error, stat, 0, message='run from sub/: '//file_text(dir//'/sub/err.txt'))
      if (allocated(error)) return
      if (.not. unavailable(error, .true.)) then
         call shell('cd '//dir//' && h5dump -y -w 0 -d /input/namelist sub/n.h5 > dump.txt', &
            stat)
         call expect_in(error, file_text(dir//'/dump.txt'), "wheel = '/", &
            'the stored namelist names the wheel file by an absolute path')
         if (allocated(error)) return
         call expect_in(error, file_text(dir//'/dump.txt'), "/built-in/S1002.txt'", &
            'the stored namelist names the wheel file')
         if (allocated(error)) return
         ! A symbolic link keeps its own name (its extension chooses the format of 'auto').
         call shell('cd '//dir//'/sub && ln -s ../built-in/S1002.txt w_link.txt', stat)
         stat = run_program(dir//'/sub', 'run -q -o l.h5 --set profiles%wheel=w_link.txt')
         call check(error, stat, 0, message='run with a linked profile: '// &
            file_text(dir//'/sub/err.txt'))
         if (allocated(error)) return
         call shell('cd '//dir//' && h5dump -y -w 0 -d /input/namelist sub/l.h5 > dump.txt', &
            stat)
         call expect_in(error, file_text(dir//'/dump.txt'), "/sub/w_link.txt'", &
            'the stored namelist names the link, not its target')
         if (allocated(error)) return
      end if
      stat = run_program(dir, 'profiles')
      call check(error, stat, 1, message='profiles without --write')
      call shell('rm -rf '//dir)
   end subroutine test_other_commands

   ! ------------------------------------------------------------------------------------------
   ! Kinematic mode (&kinematics) and the track-frame totals
   ! ------------------------------------------------------------------------------------------

   !> Bitwise equality of two lists of reals.
   pure logical function same_bits(a, b)
      real(wp), intent(in) :: a(:), b(:)
      same_bits = size(a) == size(b)
      if (same_bits) same_bits = all(transfer(a, 0_i8, size(a)) == transfer(b, 0_i8, size(b)))
   end function same_bits

   !> The summaries of a result file.
   subroutine read_summaries(error, file, summaries)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: file
      type(case_summary_type), allocatable, intent(out) :: summaries(:)
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: text, messages(:)
      integer, allocatable :: indices(:), failed(:)
      integer :: n
      call read_result_summary(file, text, n, indices, summaries, failed, messages, lerr)
      if (allocated(lerr)) call test_failed(error, 'reading '//file//': '//lerr%message)
   end subroutine read_summaries

   !> A scalar of a result file (the value 0 after an error).
   real(wp) function scalar(error, file, path) result(value)
      type(error_type), allocatable, intent(inout) :: error
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(lib_error), allocatable :: lerr
      call h5_read(file, path, value, lerr)
      if (allocated(lerr) .and. .not. allocated(error)) call test_failed(error, lerr%message)
   end function scalar

   !> The program's default case (prescribed creepages) gives what the library's `solve` gives,
   !> bit for bit, including the new track-frame totals; it has no kinematic columns.
   subroutine test_prescribed_unchanged(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      type(case_summary_type), allocatable :: s(:)
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lerr
      type(h5_file_type) :: file
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('prescribed')
      stat = run_program(dir, 'run -q -o d.h5')
      call check(error, stat, 0, message='default case: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call read_summaries(error, dir//'/d.h5', s)
      if (allocated(error)) return
      call solver%init('builtin:S1002', 'builtin:UIC60', lerr)
      if (.not. allocated(lerr)) call solver%solve(4.733_wp, 0.0_wp, &
         contact_load_type(load_normal_force, 64.7e3_wp), &
         creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp), r, lerr)
      if (allocated(lerr)) then
         call test_failed(error, 'library: '//lerr%message)
         return
      end if
      call check(error, s(1)%stat == 0 .and. s(1)%n_patches == r%n_patches .and. &
         s(1)%n_loaded == r%n_loaded .and. s(1)%main_patch == r%main_patch, &
         message='status and patches')
      if (allocated(error)) return
      call check(error, same_bits([s(1)%fn_total, s(1)%fx_total, s(1)%fy_total, s(1)%fz_total, &
         s(1)%fn, s(1)%fx, s(1)%fy, s(1)%mz, s(1)%fx_norm, s(1)%fy_norm, s(1)%approach, &
         s(1)%area, s(1)%p_max, s(1)%gamma0, s(1)%r0, s(1)%y_track], [r%track%fn, r%track%fx, &
         r%track%fy, r%track%fz, r%main%fn, r%main%fx, r%main%fy, r%main%mz, r%main%fx_norm, &
         r%main%fy_norm, r%main%approach, r%main%area, r%main%p_max, r%main%gamma0, r%main%r0, &
         r%main%y_track]), message='the default case differs from the library solve')
      if (allocated(error)) return
      call h5_open(file, dir//'/d.h5', lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      call check(error, h5_exists(file, 'summary/fz_total') .and. .not. &
         (h5_exists(file, 'summary/nu_x') .or. h5_exists(file, 'summary/x_track') .or. &
         h5_exists(file, 'summary/yaw')), message='totals in /summary, no kinematic columns')
      call h5_close(file)
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_prescribed_unchanged

   !> A kinematic case through the program equals the library's `solve_kinematic` to the last
   !> bit: the summary (totals, main patch, creepages, lead) and every patch in /cases.
   subroutine test_kinematic_case(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, patch
      type(case_summary_type), allocatable :: s(:)
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(wheelset_state_type) :: state
      type(lib_error), allocatable :: lerr
      type(h5_file_type) :: file
      integer :: stat, k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('kinematic')
      call write_lines(dir//'/k.nml', kinematic_case)
      stat = run_program(dir, 'run k.nml -q -o k.h5')
      call check(error, stat, 0, message='kinematic case: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call read_summaries(error, dir//'/k.h5', s)
      if (allocated(error)) return

      ! The library, from its own defaults (those of the program's case files).
      state = wheelset_state_type(y_ws=4.733_wp, yaw=0.004_wp, v_forward=30000.0_wp, &
         pitch_rate=pure_rolling_pitch_rate(30000.0_wp, 460.0_wp))
      call solver%init('builtin:S1002', 'builtin:UIC60', lerr)
      if (.not. allocated(lerr)) call solver%solve_kinematic(state, &
         contact_load_type(load_vertical_force, 64.7e3_wp), r, lerr)
      if (allocated(lerr)) then
         call test_failed(error, 'library: '//lerr%message)
         return
      end if
      call check(error, r%n_loaded, 2, message='the case has two loaded patches')
      if (allocated(error)) return
      call check(error, s(1)%stat == 0 .and. s(1)%n_patches == r%n_patches .and. &
         s(1)%n_loaded == r%n_loaded .and. s(1)%main_patch == r%main_patch, &
         message='status and patches')
      if (allocated(error)) return
      call check(error, same_bits([s(1)%fn_total, s(1)%fx_total, s(1)%fy_total, s(1)%fz_total], &
         [r%track%fn, r%track%fx, r%track%fy, r%track%fz]), &
         message='track-frame totals differ from solve_kinematic')
      if (allocated(error)) return
      call check(error, same_bits([s(1)%fn, s(1)%fx, s(1)%fy, s(1)%mz, s(1)%fx_norm, &
         s(1)%fy_norm, s(1)%coulomb_ratio, s(1)%adhesion_fraction, s(1)%approach, s(1)%area, &
         s(1)%p_max, s(1)%gamma0, s(1)%r0, s(1)%y_track, s(1)%x_track, s(1)%nu_x, s(1)%nu_y, &
         s(1)%phi], [r%main%fn, r%main%fx, r%main%fy, r%main%mz, r%main%fx_norm, &
         r%main%fy_norm, r%main%coulomb_ratio, r%main%adhesion_fraction, r%main%approach, &
         r%main%area, r%main%p_max, r%main%gamma0, r%main%r0, r%main%y_track, r%main%x_track, &
         r%main%nu_x, r%main%nu_y, r%main%phi]), &
         message='the main patch differs from solve_kinematic')
      if (allocated(error)) return

      ! Every patch of the single case's fields.
      call h5_open(file, dir//'/k.h5', lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      do k = 1, r%n_loaded
         patch = case_group_name(1, 1)//'/patch_'//char(iachar('0') + k)
         associate (p => r%patch(k))
            call check(error, same_bits([scalar(error, file, patch//'/normal/load'), &
               scalar(error, file, patch//'/tangential/fx'), &
               scalar(error, file, patch//'/tangential/fy'), &
               scalar(error, file, patch//'/tangential/fy_track'), &
               scalar(error, file, patch//'/tangential/fz_track'), &
               scalar(error, file, patch//'/tangential/nu_x'), &
               scalar(error, file, patch//'/tangential/nu_y'), &
               scalar(error, file, patch//'/tangential/phi'), &
               scalar(error, file, patch//'/tangential/x_track')], &
               [p%fn, p%fx, p%fy, p%fy_track, p%fz_track, p%nu_x, p%nu_y, p%phi, p%x_track]), &
               message=patch//' differs from solve_kinematic')
         end associate
         if (allocated(error)) exit
      end do
      call h5_close(file)
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_kinematic_case

   !> A kinematic sweep t_y × yaw: every case solved, identical files with 1 and 2 threads,
   !> the wheelset inputs in /summary with units, and the track-frame totals equal to the sums
   !> over the patches stored in /cases.
   subroutine test_kinematic_sweep(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, group, patch, units, header
      type(case_summary_type), allocatable :: s(:)
      type(lib_error), allocatable :: lerr
      type(h5_file_type) :: file
      real(wp) :: total(4), fn
      integer :: stat, i, k
      if (unavailable(error, .true.)) return
      dir = scratch_directory('kinematic_sweep')
      call shell('mkdir -p '//dir//'/one '//dir//'/two')
      call write_lines(dir//'/ks.nml', kinematic_sweep_case)
      stat = run_program(dir//'/one', 'run ../ks.nml -q -o out.h5 --format csv', &
         'OMP_NUM_THREADS=1')
      call check(error, stat, 0, message='1 thread: '//file_text(dir//'/one/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir//'/two', 'run ../ks.nml -q -o out.h5 --format csv', &
         'OMP_NUM_THREADS=2')
      call check(error, stat, 0, message='2 threads: '//file_text(dir//'/two/err.txt'))
      if (allocated(error)) return
      call check_same_content(error, dir//'/one/out.h5', dir//'/two/out.h5', &
         'kinematic sweep with 1 and 2 threads')
      if (allocated(error)) return
      header = file_text(dir//'/one/out.txt')
      call expect_in(error, header, 'case,status,n_patches,n_loaded,main_patch,t_y,roll,yaw,'// &
         'vertical_force,friction,bound,v_forward,v_lateral,v_vertical,roll_rate,yaw_rate,'// &
         'pitch_rate,fn_total,fx_total,fy_total,fz_total,fn,', &
         'csv header of a kinematic sweep')
      if (allocated(error)) return
      call expect_in(error, header, ',y_track,x_track,nu_x,nu_y,phi,wheel_patches,wheel_fn,'// &
         'wheel_fx,wheel_fy,wheel_fx_norm,wheel_fy_norm,wheel_area,wheel_p_max,climbing,'// &
         'message', &
         'csv header')
      if (allocated(error)) return

      call read_summaries(error, dir//'/one/out.h5', s)
      if (allocated(error)) return
      call check(error, size(s), 6, message='3 x 2 cases')
      if (allocated(error)) return
      call check(error, all(s%stat == 0), message='every case solved')
      if (allocated(error)) return
      call check(error, any(s%n_loaded > 1), message='a case with two loaded patches')
      if (allocated(error)) return
      call h5_open(file, dir//'/one/out.h5', lerr)
      if (allocated(lerr)) then
         call test_failed(error, lerr%message)
         return
      end if
      call h5_read_attribute(file, 'summary/yaw', 'units', units, lerr)
      if (.not. allocated(lerr)) call check(error, units, 'rad', message='units of yaw')
      if (.not. allocated(lerr) .and. .not. allocated(error)) then
         call h5_read_attribute(file, 'summary/v_forward', 'units', units, lerr)
         if (.not. allocated(lerr)) call check(error, units, 'mm/s', message='units of v_forward')
      end if
      if (.not. allocated(lerr) .and. .not. allocated(error)) then
         call h5_read_attribute(file, 'summary/fz_total', 'units', units, lerr)
         if (.not. allocated(lerr)) call check(error, units, 'N', message='units of fz_total')
      end if
      if (.not. allocated(lerr) .and. .not. allocated(error)) then
         call h5_read_attribute(file, 'summary/phi', 'units', units, lerr)
         if (.not. allocated(lerr)) call check(error, units, 'rad/mm', message='units of phi')
      end if
      if (allocated(lerr)) call test_failed(error, lerr%message)
      do i = 1, size(s)
         if (allocated(error)) exit
         group = case_group_name(i, size(s))
         total = 0.0_wp
         do k = 1, s(i)%n_loaded
            patch = group//'/patch_'//char(iachar('0') + k)
            fn = scalar(error, file, patch//'/normal/load')
            if (.not. (fn > 0.0_wp)) cycle
            total(1) = total(1) + scalar(error, file, patch//'/tangential/fx')
            total(2) = total(2) + scalar(error, file, patch//'/tangential/fy_track')
            total(3) = total(3) + scalar(error, file, patch//'/tangential/fz_track')
            total(4) = total(4) + fn
         end do
         if (allocated(error)) exit
         call check(error, same_bits(total, [s(i)%fx_total, s(i)%fy_total, s(i)%fz_total, &
            s(i)%fn_total]), message=group//': /summary totals differ from the sums over '// &
            'the patches')
      end do
      call h5_close(file)
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_kinematic_sweep

   !> Issue 27: a sweep that stores every field holds at most --block-memory of results at
   !> once, whatever its length. The 36-case DOE with all fields, run with --block-memory 2
   !> (MiB; two blocks of at most 1 MiB, one being solved and one being written) and with 1024
   !> (every case in one block): the same file; the bounded run's largest block holds at most
   !> 1 MiB. The same two runs with 72 cases: the peak resident memory of the process before the
   !> output is assembled (VmHWM, which -v prints; the HDF5 caches of the final file grow with
   !> its number of objects, whatever the bound) grows with the cases by less than half of what
   !> 36 cases' results take in the bounded run, and by more than that in the unbounded one
   !> (which shows that the figure sees the results held). The bounded runs merge block files,
   !> the unbounded ones (one block) write their output straight from memory, and so does a run
   !> with automatic checkpoints: the same file.
   subroutine test_memory_bound(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, small, big
      character(len=*), parameter :: runs(4) = [character(len=7) :: 'small', 'big', &
         'small72', 'big72']
      integer :: stat, small_block, big_block, peak(4), k
      if (unavailable(error, .true.)) return
      dir = scratch_directory('memory')
      call write_lines(dir//'/doe.nml', fields_doe_case)
      call shell("sed 's/phi_points = 4/phi_points = 8/' "//dir//'/doe.nml > '//dir// &
         '/doe72.nml', stat)
      do k = 1, 4
         call shell('mkdir -p '//dir//'/'//trim(runs(k)))
         stat = run_program(dir//'/'//trim(runs(k)), 'run ../'// &
            trim(merge('doe.nml  ', 'doe72.nml', k <= 2))//' -v -o out.h5 --block-memory '// &
            trim(merge('2   ', '1024', mod(k, 2) == 1)))
         call check(error, stat, 0, message=trim(runs(k))//': '// &
            file_text(dir//'/'//trim(runs(k))//'/err.txt'))
         if (allocated(error)) return
         peak(k) = integer_after(file_text(dir//'/'//trim(runs(k))//'/err.txt'), &
            'peak memory ', 'KiB (VmHWM), ')
      end do
      call check_same_content(error, dir//'/small/out.h5', dir//'/big/out.h5', &
         'the block size changes no result')
      if (allocated(error)) return
      small = file_text(dir//'/small/err.txt')
      big = file_text(dir//'/big/err.txt')
      small_block = integer_after(small, 'largest checkpoint block', 'case(s), ')
      big_block = integer_after(big, 'largest checkpoint block', 'case(s), ')
      call check(error, small_block > 0 .and. small_block <= 1024, message='largest block of '// &
         'the bounded run (KiB, at most 1024): '//small)
      if (allocated(error)) return
      call check(error, big_block > 5*1024, message='largest block of the unbounded run '// &
         '(KiB, expected the 36 cases of about 220 KiB): '//big)
      if (allocated(error)) return
      call check(error, integer_after(small, 'KiB of results in memory; ', '; ') >= 2, &
         message='block files of the bounded run (at least 2): '//small)
      if (allocated(error)) return
      call check(error, integer_after(big, 'KiB of results in memory; ', '; '), 0, &
         message='block files of the unbounded run (written from memory): '//big)
      if (allocated(error)) return
      if (any(peak <= 0)) then
         call skip_test(error, 'no peak memory reported (no /proc/self/status)')
         return
      end if
      call check(error, peak(3) - peak(1) < big_block/2, message='peak memory before the '// &
         'output (KiB), bounded, 36 -> 72 cases: '//str_int(peak(1))//' -> '//str_int(peak(3)))
      if (allocated(error)) return
      call check(error, peak(4) - peak(2) > big_block/2, message='peak memory before the '// &
         'output (KiB), unbounded, 36 -> 72 cases: '//str_int(peak(2))//' -> '//str_int(peak(4)))
      if (allocated(error)) return
      ! Automatic checkpoints (checkpoint_cases = 0): a short run within its budget holds every
      ! case and writes its output straight from memory, the same file as the merged blocks.
      call shell('mkdir -p '//dir//'/auto')
      stat = run_program(dir//'/auto', 'run ../doe.nml -v -o out.h5 --block-memory 1024 '// &
         '--set output%checkpoint_cases=0')
      call check(error, stat, 0, message='automatic: '//file_text(dir//'/auto/err.txt'))
      if (allocated(error)) return
      call check(error, integer_after(file_text(dir//'/auto/err.txt'), &
         'KiB of results in memory; ', '; '), 0, message='block files of the automatic run: '// &
         file_text(dir//'/auto/err.txt'))
      if (allocated(error)) return
      call check_same_content_but(error, dir//'/small/out.h5', dir//'/auto/out.h5', &
         'checkpoint_cases', 'written from memory or merged from blocks')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_memory_bound

   !> The integer after the first `key` that follows the first `line` in `text` (−1 when
   !> there is none).
   integer function integer_after(text, line, key) result(value)
      character(len=*), intent(in) :: text, line, key
      integer :: i, j, stat
      value = -1
      j = index(text, line)
      if (j == 0) return
      i = index(text(j:), key)
      if (i == 0) return
      i = j + i - 1
      read (text(i + len(key):), *, iostat=stat) value
      if (stat /= 0) value = -1
   end function integer_after

   !> The program equals the library bit for bit in every /summary column it writes, and in the
   !> patch counts, for both wheels, with prescribed creepages (`solve`) and kinematic
   !> (`solve_kinematic`), on the headline case (t_y = 4.733 mm, 64.7 kN; the left wheel at the
   !> mirrored t_y = -4.733 mm, y_track < 0). Both go through the same pipeline stages
   !> (shcontact_pipeline_stages); before they did, the program's left wheel had y_track
   !> without the side factor (-737.785 mm instead of the library's -737.822 mm).
   subroutine test_both_wheels(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: side_names(2) = ['right', 'left ']
      integer, parameter :: sides(2) = [side_right, side_left]
      ! The left wheel's case is the right one's mirror image.
      character(len=*), parameter :: t_y_text(2) = ['4.733 ', '-4.733']
      real(wp), parameter :: t_y(2) = [4.733_wp, -4.733_wp]
      character(len=:), allocatable :: dir, name
      character(len=72) :: track_line, position_line
      type(case_summary_type), allocatable :: s(:)
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lerr
      logical :: kinematic
      integer :: stat, iside, mode, k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('wheels')
      do iside = 1, 2
         do mode = 1, 2
            kinematic = mode == 2
            name = trim(side_names(iside))//merge('_kinematic ', '_prescribed', kinematic)
            track_line = "&track side = '"//trim(side_names(iside))//"' /"
            position_line = '&position t_y = '//trim(t_y_text(iside))//' /'
            if (kinematic) then
               call write_lines(dir//'/'//trim(name)//'.nml', [position_line, &
                  kinematic_case(2:), track_line])
            else
               call write_lines(dir//'/'//trim(name)//'.nml', [position_line, track_line])
            end if
            stat = run_program(dir, 'run '//trim(name)//'.nml -q -o '//trim(name)//'.h5')
            call check(error, stat, 0, message=name//': '//file_text(dir//'/err.txt'))
            if (allocated(error)) return
            call read_summaries(error, dir//'/'//trim(name)//'.h5', s)
            if (allocated(error)) return
            ! The library from its defaults, which are those of the program's case files.
            call solver%init('builtin:S1002', 'builtin:UIC60', lerr, side=sides(iside))
            if (.not. allocated(lerr)) then
               if (kinematic) then
                  call solver%solve_kinematic(wheelset_state_type(y_ws=t_y(iside), yaw=0.004_wp, &
                     v_forward=30000.0_wp, pitch_rate=pure_rolling_pitch_rate(30000.0_wp, &
                     460.0_wp)), contact_load_type(load_vertical_force, 64.7e3_wp), r, lerr)
               else
                  call solver%solve(t_y(iside), 0.0_wp, contact_load_type(load_normal_force, &
                     64.7e3_wp), creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp), r, lerr)
               end if
            end if
            if (allocated(lerr)) then
               call test_failed(error, name//', library: '//lerr%message)
               return
            end if
            call check(error, s(1)%stat == 0 .and. s(1)%n_patches == r%n_patches .and. &
               s(1)%n_loaded == r%n_loaded .and. s(1)%main_patch == r%main_patch, &
               message=name//': status and patches')
            if (allocated(error)) return
            call check(error, (r%main%y_track < 0.0_wp) .eqv. (sides(iside) == side_left), &
               message=name//': the reference point is not on the wheel''s side of the track')
            if (allocated(error)) return
            do k = 1, n_summary_columns
               if (.not. summary_column_used(k, kinematic)) cycle
               call check(error, same_bits([summary_value(s(1), k)], &
                  [library_column(r, trim(summary_columns(1, k)))]), message=name//': /summary/'// &
                  trim(summary_columns(1, k))//' differs from the library')
               if (allocated(error)) return
            end do
         end do
      end do
      call shell('rm -rf '//dir)
   end subroutine test_both_wheels

   !> Issue 28 item 3: the wheel's joined contact (the patches the exact theory joins into one,
   !> doc/lobes.md) reaches the program's output. A vertical load of 64.7 kN with the default
   !> creepages at Y_WS = 5.0 and 5.3 mm, where CONTACT joins two lobes (data/exact/README.md),
   !> and at the single-lobe positions 2.0 and 5.8 mm: every /summary column (the `wheel_*` ones
   !> among them) equals the library's `solve` bit for bit; at the two-lobe positions the joined
   !> contact holds both loaded patches (its F_n is the total's, bit for bit, and more than the
   !> main patch's), at the single-lobe ones it is the main patch (forces, area and p_max bit for
   !> bit, f to rounding).
   subroutine test_joined_contact(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: t_y(4) = [5.0_wp, 5.3_wp, 2.0_wp, 5.8_wp]
      logical, parameter :: two_lobes(4) = [.true., .true., .false., .false.]
      character(len=:), allocatable :: dir, at
      type(case_summary_type), allocatable :: s(:)
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lerr
      integer :: stat, i, k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('joined')
      call write_lines(dir//'/joined.nml', [character(len=72) :: &
         "&load mode = 'vertical', vertical_force = 64700.0 /", &
         '&sweep t_y = 5.0, 5.3, 2.0, 5.8 /'])
      stat = run_program(dir, 'run joined.nml -q -o joined.h5')
      call check(error, stat, 0, message='joined: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call read_summaries(error, dir//'/joined.h5', s)
      if (allocated(error)) return
      call check(error, size(s), size(t_y), message='cases in /summary')
      if (allocated(error)) return
      call solver%init('builtin:S1002', 'builtin:UIC60', lerr)
      do i = 1, size(t_y)
         at = 't_y = '//merge('5.0', '5.3', i == 1)
         if (i > 2) at = 't_y = '//merge('2.0', '5.8', i == 3)
         if (.not. allocated(lerr)) call solver%solve(t_y(i), 0.0_wp, &
            contact_load_type(load_vertical_force, 64.7e3_wp), &
            creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp), r, lerr)
         if (allocated(lerr)) then
            call test_failed(error, at//', library: '//lerr%message)
            return
         end if
         call check(error, s(i)%stat == 0 .and. s(i)%n_loaded == r%n_loaded .and. &
            s(i)%main_patch == r%main_patch, message=at//': status and patches')
         if (allocated(error)) return
         do k = 1, n_summary_columns
            if (.not. summary_column_used(k, .false.)) cycle
            call check(error, same_bits([summary_value(s(i), k)], &
               [library_column(r, trim(summary_columns(1, k)))]), message=at//': /summary/'// &
               trim(summary_columns(1, k))//' differs from the library')
            if (allocated(error)) return
         end do
         if (two_lobes(i)) then
            call check(error, s(i)%n_loaded == 2 .and. s(i)%wheel%n_members == 2 .and. &
               same_bits([s(i)%wheel%fn], [s(i)%fn_total]) .and. &
               s(i)%wheel%fn > s(i)%fn + 1000.0_wp, message=at//': the joined contact '// &
               'should hold both loaded patches (wheel_fn = fn_total > fn)')
         else
            call check(error, s(i)%wheel%n_members == 1 .and. same_bits([s(i)%wheel%fn, &
               s(i)%wheel%fx, s(i)%wheel%fy, s(i)%wheel%area, s(i)%wheel%p_max], [s(i)%fn, &
               s(i)%fx, s(i)%fy, s(i)%area, s(i)%p_max]) .and. &
               abs(s(i)%wheel%fx_norm - s(i)%fx_norm) <= 1.0e-14_wp .and. &
               abs(s(i)%wheel%fy_norm - s(i)%fy_norm) <= 1.0e-14_wp, message=at// &
               ': the joined contact should be the main patch')
         end if
         if (allocated(error)) return
      end do
      call shell('rm -rf '//dir)
   end subroutine test_joined_contact

   !> The library's value of a /summary column: the track-frame totals, the main patch's value
   !> or the wheel's joined contact's (NaN for a column this test does not know, so that a new column fails the test until
   !> it is added here).
   function library_column(r, column) result(value)
      type(contact_result_type), intent(in) :: r
      character(len=*), intent(in) :: column
      real(wp) :: value
      select case (column)
      case ('fn_total'); value = r%track%fn
      case ('fx_total'); value = r%track%fx
      case ('fy_total'); value = r%track%fy
      case ('fz_total'); value = r%track%fz
      case ('fn'); value = r%main%fn
      case ('fx'); value = r%main%fx
      case ('fy'); value = r%main%fy
      case ('mz'); value = r%main%mz
      case ('fx_norm'); value = r%main%fx_norm
      case ('fy_norm'); value = r%main%fy_norm
      case ('coulomb_ratio'); value = r%main%coulomb_ratio
      case ('adhesion_fraction'); value = r%main%adhesion_fraction
      case ('delta'); value = r%main%approach
      case ('area'); value = r%main%area
      case ('p_max'); value = r%main%p_max
      case ('gamma0'); value = r%main%gamma0
      case ('r0'); value = r%main%r0
      case ('y_track'); value = r%main%y_track
      case ('x_track'); value = r%main%x_track
      case ('nu_x'); value = r%main%nu_x
      case ('nu_y'); value = r%main%nu_y
      case ('phi'); value = r%main%phi
      case ('wheel_patches'); value = real(r%wheel%n_members, wp)
      case ('wheel_fn'); value = r%wheel%fn
      case ('wheel_fx'); value = r%wheel%fx
      case ('wheel_fy'); value = r%wheel%fy
      case ('wheel_fx_norm'); value = r%wheel%fx_norm
      case ('wheel_fy_norm'); value = r%wheel%fy_norm
      case ('wheel_area'); value = r%wheel%area
      case ('wheel_p_max'); value = r%wheel%p_max
      case ('climbing'); value = merge(1.0_wp, 0.0_wp, r%climbing)
      case default; value = ieee_value(value, ieee_quiet_nan)
      end select
   end function library_column

   !> The sweep's runner keeps each thread's FASTSIM_SH workspaces prepared from case to case
   !> (shcontact_case_runner): a sequence of cases on one workspace, each differing from the one
   !> before in one thing the preparation reads (friction, bound, spin model, the stage's load,
   !> a stage of two patches, back to the first stage) or in the creepages only, gives every
   !> case's summary bit for bit as a fresh workspace does. Each change of the preparation's
   !> input changes the forces, so a key that missed it would fail here.
   subroutine test_prepared_reuse(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n_cases = 11
      type(case_config_type) :: config
      type(run_setup_type) :: setup, vertical
      type(case_point_type) :: base, point(n_cases)
      type(stage_type) :: stages(3)
      type(patch_geometry_type), allocatable :: geometry(:)
      type(case_workspace_type), allocatable :: kept, fresh
      type(tangential_patch_type), allocatable :: t_kept(:), t_fresh(:)
      type(case_result_type) :: r_kept, r_fresh
      type(lib_error), allocatable :: lerr
      character(len=1) :: no_overrides(0)
      real(wp), allocatable :: previous(:)
      integer :: stage_of(n_cases), i

      call load_config('', no_overrides, config, lerr)
      if (.not. allocated(lerr)) call prepare_run(config, setup, lerr)
      base = config%case_point(1)
      if (.not. allocated(lerr)) call solve_geometry(setup, base, geometry, lerr)
      if (allocated(lerr)) then
         call test_failed(error, 'set-up: '//lerr%message)
         return
      end if
      ! Stage 1: the headline case; stage 2: another normal force; stage 3: the vertical load
      ! shared by the patches of the same position.
      call solve_stage(setup, base, geometry, stages(1))
      point(1) = base
      point(1)%normal_force = 0.8_wp*base%normal_force
      call solve_stage(setup, point(1), geometry, stages(2))
      vertical = setup
      vertical%load_mode = load_mode_vertical
      point(1) = base
      point(1)%vertical_force = base%normal_force
      call solve_stage(vertical, point(1), geometry, stages(3))
      do i = 1, 3
         call check(error, stages(i)%stat, 0, message='stage '//char(48 + i)//' failed')
         if (allocated(error)) return
      end do
      call check(error, size(stages(3)%normal) >= 2, message='stage 3 should load two patches')
      if (allocated(error)) return

      stage_of = [1, 1, 1, 1, 2, 1, 3, 3, 1, 1, 3]
      point = base
      point(2)%friction = 0.8_wp*base%friction
      point(3)%friction = point(2)%friction
      point(3)%bound = bound_clipped
      point(4:) = point(3)
      point(4)%spin_model = spin_geometric
      point(5:) = point(4)
      point(8)%friction = base%friction
      point(9:) = point(8)
      point(10)%nu_x = 0.5_wp*base%nu_x
      point(11) = point(10)
      allocate (kept)
      do i = 1, n_cases
         call solve_case(setup, point(i), stages(stage_of(i)), stage_of(i), kept, t_kept, &
            r_kept, .false.)
         allocate (fresh)
         call solve_case(setup, point(i), stages(stage_of(i)), stage_of(i), fresh, t_fresh, &
            r_fresh, .false.)
         deallocate (fresh, t_fresh)
         call check(error, r_kept%summary%stat == 0 .and. r_fresh%summary%stat == 0, &
            message='case '//char(48 + mod(i, 10))//' failed')
         if (allocated(error)) return
         call check(error, same_bits(forces(r_kept), forces(r_fresh)), message='case '// &
            char(48 + mod(i, 10))//' on the kept workspace differs from a fresh preparation')
         if (allocated(error)) return
         if (i > 1) then
            call check(error, any(forces(r_kept) /= previous), message='case '// &
               char(48 + mod(i, 10))//' gives the forces of the case before: it tests nothing')
            if (allocated(error)) return
         end if
         previous = forces(r_kept)
      end do

   contains

      !> The forces and moments of a result.
      pure function forces(r) result(f)
         type(case_result_type), intent(in) :: r
         real(wp) :: f(10)
         f = [r%summary%fx, r%summary%fy, r%summary%mz, r%summary%fx_norm, r%summary%fy_norm, &
            r%summary%coulomb_ratio, r%summary%adhesion_fraction, r%summary%fx_total, &
            r%summary%fy_total, r%summary%fz_total]
      end function forces

   end subroutine test_prepared_reuse

end module test_app
