!> Hostile input to the shcontact program (issue 14): each reproducer of the issue with the
!> exit status and the message it now gets, and a seeded fuzz test of case files and profile
!> files. Every failure must end with a documented exit status, a message naming the file, no
!> backtrace, and nothing left under the output name.
!>
!> Runs the program as test_app does (its helpers); tests that read the sample profiles skip
!> without the external data (SHCONTACT_EXTERNAL_DATA, test_external_data).
module test_robustness
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_files, only: file_exists
   use test_external_data, only: external_file
   use test_app, only: program_path, scratch_directory, shell, run_program, file_text, &
      write_lines, unavailable, expect_in, expect_failure, current_directory
   use test_fuzz_support, only: next_random, fuzz_settings, repeated, names_input_file, &
      library_option_fuzz
   use shcontact_input_config_variables, only: variables, k_real
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_kinds, only: wp
   implicit none
   private
   public :: collect_robustness

   !> A small sweep in checkpoint blocks of 2 cases.
   character(len=*), parameter :: small_sweep(*) = [character(len=48) :: &
      '&sweep phi = 0, 1e-3, phi_points = 8 /', &
      '&output checkpoint_cases = 2 /', &
      '&normal n_strips = 40 /', &
      '&tangential n_elements = 20 /']

   !> The case the fuzz test mutates: every group, coarse grids (fast runs).
   character(len=*), parameter :: fuzz_case(*) = [character(len=60) :: &
      '! fuzz base case', &
      "&profiles rail = 'rail.txt', rail_smoothing = 0.5 /", &
      '&track gauge = 1435.0, inclination = 0.025 /', &
      '&position t_y = 4.733 /', &
      '&material friction = 0.3, poisson = 0.28 /', &
      "&load mode = 'force', normal_force = 64700.0 /", &
      '&creepage nu_x = 5.8e-4, nu_y = 6.1e-5, phi = 2.74e-4 /', &
      '&normal n_strips = 20 /', &
      "&tangential n_elements = 10, bound = 'weighted' /", &
      "&output fields = 'none', checkpoint_cases = 2 /", &
      '&sweep nu_x = 0.0, 1.0e-3 /']
   !> Fuzz runs of each kind, and the wall-clock bound of the whole fuzz test (s); the
   !> environment variable SHCONTACT_FUZZ_SECONDS sets a longer campaign (doc/app.md).
   integer, parameter :: fuzz_runs = 150
   real, parameter :: fuzz_seconds = 10.0
   !> Bytes a mutation inserts: structure characters, line ends, quotes, a UTF-8 lead byte,
   !> NUL and other control bytes.
   character(len=*), parameter :: fuzz_bytes = '&/=,%''"!# 0123456789.eE+-'// &
      achar(13)//achar(10)//achar(9)//achar(0)//achar(1)//achar(12)//achar(27)//achar(127)// &
      char(195)//'xyz'
   !> Assignments a mutation repeats inside their group (every kind of variable): the later
   !> one wins (doc/app.md, "Repeated variables").
   character(len=*), parameter :: repeats(*) = [character(len=48) :: &
      '&position|t_y = 3.0', '&position|t_y = -1e-300', '&normal|n_strips = 30', &
      '&tangential|bound = ''clipped''', '&tangential|n_elements = 12', &
      '&track|rail_canted = .false.', '&output|fields = ''state'', ''slip''', &
      '&sweep|nu_x = 1e-4', '&sweep|bound = ''weighted'', ''clipped''', &
      '&sweep|bound = ''parabolic''', '&material|friction = 1e-3', '&profiles|rail = ''rail.txt''', &
      '&load|mode = ''force''']
   !> Extreme values given to every real variable in turn (`--set`).
   character(len=*), parameter :: extreme_values(*) = [character(len=10) :: '1e-300', &
      '-1e-300', '4.9e-324', '1e308', '-1e308', '1e309', '0']

contains

   subroutine collect_robustness(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('lone_carriage_return', test_lone_cr), &
         new_unittest('byte_order_mark_accepted', test_bom), &
         new_unittest('directory_as_case_file', test_directory_case), &
         new_unittest('grid_size_limit', test_grid_limit), &
         new_unittest('thread_limit', test_thread_limit), &
         new_unittest('messages_from_two_threads', test_threaded_messages), &
         new_unittest('empty_values_refused', test_empty_values), &
         new_unittest('sweep_errors_name_the_file', test_sweep_origin), &
         new_unittest('checkpoint_never_deletes_foreign_files', test_foreign_checkpoint), &
         new_unittest('resume_from_another_directory', test_resume_elsewhere), &
         new_unittest('output_path_checked_before_solving', test_output_path), &
         new_unittest('merge_refuses_an_input_as_output', test_merge_output), &
         new_unittest('miniprof_wheel_origin', test_miniprof_origin), &
         new_unittest('swapped_columns_refused', test_swapped), &
         new_unittest('single_point_spike_refused', test_spike), &
         new_unittest('single_point_above_the_rail_top', test_top_outlier), &
         new_unittest('plain_profile_cut_off', test_cut_off), &
         new_unittest('collinear_points_same_forces', test_collinear), &
         new_unittest('profile_mirror_and_scale_variables', test_mirror_scale), &
         new_unittest('miniprof_comments_and_old_header', test_miniprof_variants), &
         new_unittest('fuzz_case_and_profile_files', test_fuzz), &
         new_unittest('valgrind_clean_failure_messages', test_valgrind) &
         ]
   end subroutine collect_robustness

   ! ------------------------------------------------------------------------------------------
   ! Helpers
   ! ------------------------------------------------------------------------------------------

   !> Absolute path of a sample profile; skips the test (and returns '') when it is absent.
   function sample_profile(error, name) result(path)
      type(error_type), allocatable, intent(inout) :: error
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      path = external_file('profiles/'//name, error, absolute=.true.)
   end function sample_profile

   !> Write raw bytes (printf format) to a file.
   subroutine write_bytes(name, printf_format)
      character(len=*), intent(in) :: name, printf_format
      call shell("printf '"//printf_format//"' > "//name)
   end subroutine write_bytes

   !> stderr has no runtime-error or backtrace text.
   subroutine expect_clean_stderr(error, dir, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, what
      character(len=:), allocatable :: text
      text = file_text(dir//'/err.txt')
      if (index(text, 'Fortran runtime error') > 0 .or. index(text, 'Backtrace') > 0 .or. &
          index(text, 'Error allocating') > 0 .or. index(text, 'SIGSEGV') > 0) &
         call test_failed(error, what//': a crash instead of a message: '//text)
   end subroutine expect_clean_stderr

   ! ------------------------------------------------------------------------------------------
   ! Crashes
   ! ------------------------------------------------------------------------------------------

   !> `printf 'x\ry' > cr.nml` crashed in the line reader; now a lone CR ends a line.
   subroutine test_lone_cr(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_cr')
      call write_bytes(dir//'/cr.nml', 'x\ry')
      call expect_failure(error, dir, 'run cr.nml', 2, 'cr.nml:1: "x" outside a group')
      if (allocated(error)) return
      call expect_clean_stderr(error, dir, 'lone CR')
      if (allocated(error)) return
      ! Old Mac line ends in a valid file: read as lines.
      call write_bytes(dir//'/mac.nml', '&material\rfriction = 0.2\r/\r')
      call check(error, run_program(dir, 'run mac.nml --check -q'), 0, &
         message='CR line ends: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'friction = 0.2', 'CR line ends')
      call shell('rm -rf '//dir)
   end subroutine test_lone_cr

   !> Strips × elements = 1e10 crashed allocating 80 GB; now refused before anything is
   !> allocated.
   subroutine test_grid_limit(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_grid')
      call write_lines(dir//'/grid.nml', [character(len=40) :: '&normal n_strips = 100000 /', &
         '&tangential n_elements = 100000 /'])
      call expect_failure(error, dir, 'run grid.nml', 2, 'grid.nml:2: &normal n_strips × '// &
         '&tangential n_elements = 100000 × 100000 = 10000000000 grid cells per patch; at '// &
         'most 1000000 are allowed')
      if (allocated(error)) return
      call expect_clean_stderr(error, dir, 'grid limit')
      call shell('rm -rf '//dir)
   end subroutine test_grid_limit

   !> --threads 100000 crashed (segfault) and left the checkpoint; now a usage error, and
   !> OMP_NUM_THREADS as large an error before any file is made.
   subroutine test_thread_limit(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_threads')
      call expect_failure(error, dir, 'run --threads 100000', 1, &
         '--threads 100000: at most 1024 threads are allowed')
      if (allocated(error)) return
      stat = run_program(dir, 'run -o out.h5', 'OMP_NUM_THREADS=100000')
      call check(error, stat, 1, message='OMP_NUM_THREADS=100000: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '100000 threads asked (--threads or '// &
         'OMP_NUM_THREADS); at most 1024 are allowed', 'OMP_NUM_THREADS')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5.partial'), &
         message='no checkpoint left by a refused thread count')
      if (allocated(error)) return
      ! Not a number: the OpenMP run time only warns and uses every core; the run refuses.
      stat = run_program(dir, 'run -o out.h5', 'OMP_NUM_THREADS=abc')
      call check(error, stat, 1, message='OMP_NUM_THREADS=abc: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), "OMP_NUM_THREADS = 'abc': expected a "// &
         'positive number of threads', 'OMP_NUM_THREADS=abc')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5'), message='no output after abc')
      if (allocated(error)) return
      ! Set but empty (OMP_NUM_THREADS=$UNSET in a job script) ran on every core, status 0.
      stat = run_program(dir, 'run -o out.h5', 'OMP_NUM_THREADS=')
      call check(error, stat, 1, message='OMP_NUM_THREADS empty: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), "OMP_NUM_THREADS = '': expected a "// &
         'positive number of threads', 'OMP_NUM_THREADS empty')
      call shell('rm -rf '//dir)
   end subroutine test_thread_limit

   ! ------------------------------------------------------------------------------------------
   ! Inputs that must be refused (or accepted)
   ! ------------------------------------------------------------------------------------------

   !> A UTF-8 byte-order mark is skipped, as the profile readers do.
   subroutine test_bom(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_bom')
      call write_bytes(dir//'/bom.nml', '\357\273\277&material friction = 0.2 /\n')
      call check(error, run_program(dir, 'run bom.nml --check -q'), 0, &
         message='BOM: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'friction = 0.2', 'BOM')
      call shell('rm -rf '//dir)
   end subroutine test_bom

   !> `run DIR` and `geometry DIR` ran the default case; now an I/O error.
   subroutine test_directory_case(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_dircase')
      call shell('mkdir -p '//dir//'/sub')
      call expect_failure(error, dir, 'run sub', 3, 'sub: cannot read the case file: it is '// &
         'a directory')
      if (allocated(error)) return
      call expect_failure(error, dir, 'geometry sub', 3, 'sub: cannot read the case file: '// &
         'it is a directory')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/geometry.txt'), message='no geometry table')
      call shell('rm -rf '//dir)
   end subroutine test_directory_case

   !> `--set material%friction=`, `--set output%file=` were ignored; `-o ''` wrote
   !> shcontact.h5.
   subroutine test_empty_values(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_empty')
      call expect_failure(error, dir, 'run --set material%friction=', 2, &
         'command line --set material%friction=: no value after "="')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run --set output%file=', 2, &
         'command line --set output%file=: no value after "="')
      if (allocated(error)) return
      call expect_failure(error, dir, "run -o ''", 1, '-o needs a value, not an empty text')
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_empty_values

   !> Two sweep errors named `default:` instead of the case file.
   subroutine test_sweep_origin(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_origin')
      call write_lines(dir//'/points.nml', [character(len=40) :: '&sweep phi_points=5 /'])
      call expect_failure(error, dir, 'run points.nml', 2, 'points.nml:1: &sweep phi has 0 '// &
         'values; with phi_points > 0 it must hold exactly two')
      if (allocated(error)) return
      call write_lines(dir//'/huge.nml', [character(len=72) :: '&sweep', &
         'nu_x = 0, 1e-3, nu_x_points = 10000', 'nu_y = 0, 1e-3, nu_y_points = 10000', &
         'phi = 0, 1e-4, phi_points = 10 /'])
      call expect_failure(error, dir, 'run huge.nml', 2, 'huge.nml:4: the sweep has more '// &
         'than 100000000 cases; split it into several runs')
      if (allocated(error)) return
      call expect_failure(error, dir, 'run --set sweep%phi_points=5', 2, &
         'command line --set sweep%phi_points=5: &sweep phi has 0 values')
      call shell('rm -rf '//dir)
   end subroutine test_sweep_origin

   ! ------------------------------------------------------------------------------------------
   ! Files lost or deleted
   ! ------------------------------------------------------------------------------------------

   !> A fresh run deleted whatever OUT.h5.partial/blocks.txt listed, even outside the folder.
   !> (An existing folder is now only taken over with --resume or --force: issue 24 item 13.)
   subroutine test_foreign_checkpoint(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_victim')
      call shell('mkdir -p '//dir//'/x.h5.partial && cd '//dir//' && echo precious > '// &
         'victim.txt && echo precious > x.h5.partial/mine.txt && printf "victim.txt\n'// &
         '../victim.txt\n'//dir//'/victim.txt\nmine.txt\n" > x.h5.partial/blocks.txt')
      stat = run_program(dir, 'run -q -o x.h5 --set sweep%phi=0,1e-3 --set sweep%phi_points=5'// &
         ' --force')
      call check(error, stat, 0, message='run: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_text(dir//'/victim.txt') == 'precious'//new_line('a') .and. &
         file_text(dir//'/x.h5.partial/mine.txt') == 'precious'//new_line('a'), &
         message='a file listed in blocks.txt was deleted')
      if (allocated(error)) return
      call check(error, file_exists(dir//'/x.h5'), message='the output is written')
      call shell('rm -rf '//dir)
   end subroutine test_foreign_checkpoint

   !> blocks.txt held paths relative to the first run's working directory: a resume from
   !> another directory recomputed everything. Temporaries of a killed run (block_N.h5.tmp,
   !> merged.h5.tmp) are removed when the resumed run finishes.
   subroutine test_resume_elsewhere(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('rob_resume')
      call shell('mkdir -p '//dir//'/sub '//dir//'/whole')
      call write_lines(dir//'/sub/sw.nml', small_sweep)
      stat = run_program(dir//'/whole', 'run -q ../sub/sw.nml -o out.h5')
      call check(error, stat, 0, message='uninterrupted: '//file_text(dir//'/whole/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir//'/sub', 'run -q sw.nml -o out.h5', &
         'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=2')
      call check(error, stat /= 0, message='the interrupted run fails')
      if (allocated(error)) return
      ! What a kill while writing a block or the merged file leaves.
      call shell('touch '//dir//'/sub/out.h5.partial/block_000003.h5.tmp '//dir// &
         '/sub/out.h5.partial/merged.h5.tmp')
      stat = run_program(dir, 'run sub/sw.nml -o '//dir//'/sub/out.h5 --resume')
      call check(error, stat, 0, message='resume from the parent: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '8 of 8 case(s) solved (4 from the '// &
         'checkpoint)', 'the finished blocks are used')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/sub/out.h5.partial'), &
         message='the checkpoint directory (and the temporaries) are removed')
      if (allocated(error)) return
      ! The data only (-o: the attributes hold references that differ from file to file).
      call shell('h5dump -y -d /summary/fy -o '//dir//'/a.txt '//dir//'/whole/out.h5 > '// &
         '/dev/null && h5dump -y -d /summary/fy -o '//dir//'/b.txt '//dir//'/sub/out.h5 > '// &
         '/dev/null && test -s '//dir//'/a.txt && cmp -s '//dir//'/a.txt '//dir//'/b.txt', stat)
      call check(error, stat, 0, message='the resumed forces equal the uninterrupted ones')
      call shell('rm -rf '//dir)
   end subroutine test_resume_elsewhere

   !> `-o out.h5` where out.h5 is a directory failed after solving with "cannot rename"; an
   !> existing file that is not a result file was overwritten.
   subroutine test_output_path(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_outdir')
      call shell('mkdir -p '//dir//'/out.h5 && echo mine > '//dir//'/notes.h5')
      call write_lines(dir//'/sw.nml', small_sweep)
      call check(error, run_program(dir, 'run sw.nml -o out.h5'), 3, &
         message='output is a directory: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'cannot write the output "out.h5": '// &
         'it is a directory', 'output is a directory')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5.partial') .and. &
         len(file_text(dir//'/out.txt')) == 0, message='refused before solving')
      if (allocated(error)) return
      call check(error, run_program(dir, 'run sw.nml -o notes.h5'), 3, &
         message='foreign output: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the output "notes.h5" exists and '// &
         'is not a shcontact result file; it is not overwritten', 'foreign output')
      if (allocated(error)) return
      call check(error, file_text(dir//'/notes.h5') == 'mine'//new_line('a'), &
         message='the foreign file is untouched')
      call shell('rm -rf '//dir)
   end subroutine test_output_path

   !> `shcontact merge doe-shard1of8.h5 doe-shard*of8.h5` returned 0 and overwrote shard 1.
   subroutine test_merge_output(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('rob_merge')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run -q sw.nml -o doe.h5 --shard 1/2')
      if (stat == 0) stat = run_program(dir, 'run -q sw.nml -o doe.h5 --shard 2/2')
      call check(error, stat, 0, message='shards: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call shell('cp '//dir//'/doe-shard1of2.h5 '//dir//'/copy.h5')
      call check(error, run_program(dir, 'merge doe-shard1of2.h5 doe-shard*of2.h5'), 1, &
         message='merge into an input: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the output "doe-shard1of2.h5" is '// &
         'also an input of this command', 'merge into an input')
      if (allocated(error)) return
      call check(error, run_program(dir, 'merge ./doe-shard2of2.h5 doe-shard*of2.h5'), 1, &
         message='merge into an input by another name')
      if (allocated(error)) return
      call shell('cmp -s '//dir//'/doe-shard1of2.h5 '//dir//'/copy.h5', stat)
      call check(error, stat, 0, message='shard 1 is unchanged')
      if (allocated(error)) return
      call check(error, run_program(dir, 'merge sw.nml doe-shard*of2.h5'), 3, &
         message='merge into a foreign file')
      if (allocated(error)) return
      call check(error, run_program(dir, 'merge all.h5 doe-shard*of2.h5'), 0, &
         message='merge: '//file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_merge_output

   ! ------------------------------------------------------------------------------------------
   ! Wrong answers given silently
   ! ------------------------------------------------------------------------------------------

   !> A MiniProf wheel ran with S1002's flange-back position −70 mm (p_max 8290 MPa, γ₀ = +0.091);
   !> its origin is at the flange back: flange_back_position = 0 (p_max 1594 MPa with the coupled
   !> reduction, 1788 MPa with local-hertz; γ₀ = −0.067). (1749.2 MPa before the coupled
   !> reduction's continuity fixes of issue 25's table-step robustness, 1749.3 MPa since, 1594.2
   !> MPa since the group-width mean of doc/validation.md §6.9: the peak is a single strip at a
   !> step of the local-Hertz loads, lowered by the mean.)
   subroutine test_miniprof_origin(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, whl, text
      if (unavailable(error, .false.)) return
      whl = sample_profile(error, 'Car7216_0001r.whl')
      if (allocated(error)) return
      dir = scratch_directory('rob_whl')
      call check(error, run_program(dir, 'run -o w.h5 --set profiles%wheel='//whl// &
         ' --set profiles%wheel_smoothing=2'), 0, message='MiniProf wheel: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      call expect_in(error, text, 'gamma0 = -6.74040E-02 rad', 'contact angle')
      if (allocated(error)) return
      call expect_in(error, text, 'p_max = 1594.2 MPa', 'peak pressure')
      if (allocated(error)) return
      call check(error, run_program(dir, 'run --check --set profiles%wheel='//whl), 0, &
         message='--check')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'flange_back_position = 0.0', &
         'the resolved namelist shows the origin used')
      if (allocated(error)) return
      ! Given explicitly, the value is used as given.
      call check(error, run_program(dir, 'run --check --set profiles%wheel='//whl// &
         ' --set track%flange_back_position=-70'), 0, message='--check')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/out.txt'), 'flange_back_position = -70.0', &
         'an explicit flange_back_position')
      call shell('rm -rf '//dir)
   end subroutine test_miniprof_origin

   !> Copy the data lines `first`..`last` of a profile file through an awk program (which sees
   !> each data line and prints what replaces it); other lines are copied unchanged.
   subroutine transform_points(source, target, first, last, program)
      character(len=*), intent(in) :: source, target, program
      integer, intent(in) :: first, last
      character(len=16) :: a, b
      write (a, '(i0)') first
      write (b, '(i0)') last
      call shell("awk 'NR >= "//trim(a)//' && NR <= '//trim(b)//' { '//program// &
         "; next } { print }' "//source//' > '//target)
   end subroutine transform_points

   !> y and z swapped on every line of MBench_UIC60_v3.prr was solved (γ₀ = −0.26, 3.4 GPa).
   subroutine test_swapped(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, prr
      if (unavailable(error, .false.)) return
      prr = sample_profile(error, 'MBench_UIC60_v3.prr')
      if (allocated(error)) return
      dir = scratch_directory('rob_swap')
      call transform_points(prr, dir//'/swapped.prr', 43, 537, 'printf "%s\t%s\n", $2, $1')
      call expect_failure(error, dir, 'run --set profiles%rail=swapped.prr', 2, &
         'swapped.prr: the highest point of the rail (y = 38.510726 mm) is not on its '// &
         'running surface')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), "are the y and z columns swapped, "// &
         "or the profile turned (&profiles rail_mirror_z = 'yes')?", 'the hint')
      call shell('rm -rf '//dir)
   end subroutine test_swapped

   !> An 11 mm single-point spike was accepted.
   subroutine test_spike(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, prr
      if (unavailable(error, .false.)) return
      prr = sample_profile(error, 'MBench_UIC60_v3.prr')
      if (allocated(error)) return
      dir = scratch_directory('rob_spike')
      call transform_points(prr, dir//'/spike.prr', 200, 200, 'printf "%s\t%.7E\n", $1, $2 + 11')
      call expect_failure(error, dir, 'run --set profiles%rail=spike.prr', 2, &
         'spike.prr, line 200: a spike: the profile turns back by 178.1')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '10.898304 mm off the line of its '// &
         'neighbours; remove the point', 'the size of the spike')
      call shell('rm -rf '//dir)
   end subroutine test_spike

   !> A scratch folder (tag) holding the built-in profiles as files, prof/S1002.txt and
   !> prof/UIC60.txt (`shcontact profiles --write`); false when the program is unavailable (the
   !> test skipped) or the files could not be written (error set).
   logical function builtin_profile_folder(tag, dir, error)
      character(len=*), intent(in) :: tag
      character(len=:), allocatable, intent(out) :: dir
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      builtin_profile_folder = .false.
      dir = ''
      if (unavailable(error, .false.)) return
      dir = scratch_directory(tag)
      stat = run_program(dir, 'profiles --write prof -q')
      call check(error, stat, 0, message='profiles --write: '//file_text(dir//'/err.txt'))
      builtin_profile_folder = .not. allocated(error)
   end function builtin_profile_folder

   !> One point of the rail top raised by 0.05 mm (0.3 mm: the same) was refused as "not on its
   !> running surface; are the y and z columns swapped, or the profile turned?": the user was
   !> sent the wrong way. Now the point's line is named as a single point off the profile.
   subroutine test_top_outlier(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      if (.not. builtin_profile_folder('rob_topoutlier', dir, error)) return
      call transform_points(dir//'/prof/UIC60.txt', dir//'/bump.txt', 700, 700, &
         'printf "%s %.15E\n", $1, $2 - 0.05')
      call expect_failure(error, dir, 'run --set profiles%rail=bump.txt', 2, &
         'bump.txt, line 700: the highest point of the rail (y = 2.999325 mm) sticks out '// &
         '0.050014 mm above the line of its neighbours')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'a single point off the profile '// &
         '(a measuring or editing error?); remove it', 'the hint')
      if (allocated(error)) return
      call check(error, index(file_text(dir//'/err.txt'), 'swapped') == 0, &
         message='no hint of swapped columns: '//file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_top_outlier

   !> A plain profile cut off while it was written (no line end after a shortened last number:
   !> 3.75000000000000E+001 cut to 3.75000000, i.e. 3.75 mm instead of 37.5 mm) was read as it
   !> stood. Refused now, naming the line; the complete file without its final line end is read
   !> as before.
   subroutine test_cut_off(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (.not. builtin_profile_folder('rob_cutoff', dir, error)) return
      ! The file without its final line end, and the same cut 11 characters earlier.
      call shell('cd '//dir//' && head -c -1 prof/UIC60.txt > whole.txt && '// &
         'head -c -12 prof/UIC60.txt > cut.txt')
      stat = run_program(dir, 'run -q --no-output --set profiles%rail=whole.txt')
      call check(error, stat, 0, message='a complete file without its final line end: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_failure(error, dir, 'run --set profiles%rail=cut.txt', 2, &
         "cut.txt, line 1334: the file ends in the middle of a line: its last number "// &
         "'3.75000000' has 8 digit(s) after the decimal point and no exponent, the lines "// &
         "before 14 and an exponent")
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'if it is complete, end its last '// &
         'line with a line break', 'the way to accept a complete file')
      if (allocated(error)) return
      ! A complete fixed-decimal file whose last number has one integer digit fewer than the
      ! lines before (10.1183, then 9.9187) and no final line end is read (the field's width
      ! refused it in the first version of the check).
      call write_lines(dir//'/f4.awk', [character(len=40) :: '/^#/ {print; next}', &
         '{printf "%.4f %.4f\n", $1, $2}'])
      call shell('cd '//dir//' && awk -f f4.awk prof/S1002.txt | head -n 1598 | head -c -1 '// &
         "> s4.txt && tail -c 7 s4.txt | grep -q '^ 9.9187$'", stat)
      call check(error, stat, 0, message='the fixed-decimal file ends in 9.9187')
      if (allocated(error)) return
      stat = run_program(dir, 'run -q --no-output --set profiles%wheel=s4.txt')
      call check(error, stat, 0, message='a complete fixed-decimal file: '// &
         file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_cut_off

   !> Points added halfway between the samples of MBench_S1002_v3.prw gave status 5; the same
   !> profile must give the same answer.
   subroutine test_collinear(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, prw, a, b
      integer :: stat
      if (unavailable(error, .false.)) return
      prw = sample_profile(error, 'MBench_S1002_v3.prw')
      if (allocated(error)) return
      dir = scratch_directory('rob_collinear')
      call transform_points(prw, dir//'/dense.prw', 44, 442, 'if ($0 !~ /^!/) { if (prev != '// &
         '"") { split(prev, p, "\t"); printf "%.9E\t%.9E\n", (p[1] + $1)/2, (p[2] + $2)/2 '// &
         '}; prev = $0 }; print')
      call shell('test $(grep -c . '//dir//'/dense.prw) -gt 800', stat)
      call check(error, stat, 0, message='the dense file has the points added')
      if (allocated(error)) return
      stat = run_program(dir, 'run -q --format text -o a.h5 --set profiles%wheel='//prw)
      a = file_text(dir//'/out.txt')
      call check(error, stat, 0, message='original: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run -q --format text -o b.h5 --set profiles%wheel=dense.prw')
      b = file_text(dir//'/out.txt')
      call check(error, stat, 0, message='with collinear points: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! The summary (forces, pressure, contact angle; 5 digits) is the same but for the name.
      call check(error, a(index(a, new_line('a')):) == b(index(b, new_line('a')):), &
         message='the forces differ: '//a//' vs '//b)
      call shell('rm -rf '//dir)
   end subroutine test_collinear

   !> Reader errors advised "mirror_z" or "the scale factor" that &profiles did not have.
   subroutine test_mirror_scale(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, prr
      if (unavailable(error, .false.)) return
      prr = sample_profile(error, 'MBench_UIC60_v3.prr')
      if (allocated(error)) return
      dir = scratch_directory('rob_mirror')
      ! In metres (and as a plain file): refused with the variable to set, accepted with it.
      call transform_points(prr, dir//'/metres.txt', 43, 537, 'if (NR % 5 == 3) printf '// &
         '"%.9E %.9E\n", $1/1000, $2/1000')
      call shell('grep -v "^[^-0-9]" '//dir//'/metres.txt > '//dir//'/m.txt')
      call expect_failure(error, dir, 'run --set profiles%rail=m.txt', 2, &
         'Give the scale factor to mm: &profiles rail_scale = FACTOR')
      if (allocated(error)) return
      call check(error, run_program(dir, 'run -q -o s.h5 --set profiles%rail=m.txt --set '// &
         'profiles%rail_scale=1000 --set track%rail_canted=T'), 0, &
         message='rail_scale: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! Upside down: the message names &profiles rail_mirror_z; the variable fixes it.
      call transform_points(prr, dir//'/up.prr', 43, 537, 'printf "%s\t%.7E\n", $1, -$2')
      call expect_failure(error, dir, 'run --set profiles%rail=up.prr', 2, &
         "set &profiles rail_mirror_z = 'yes' to flip z")
      if (allocated(error)) return
      call check(error, run_program(dir, 'run -q -o u.h5 --set profiles%rail=up.prr --set '// &
         'profiles%rail_mirror_z=yes --set track%rail_canted=T'), 0, &
         message='rail_mirror_z: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_failure(error, dir, 'run --set profiles%rail_mirror_y=maybe', 2, &
         "&profiles rail_mirror_y = 'maybe' is not allowed; expected one of 'auto', 'yes', 'no'")
      call shell('rm -rf '//dir)
   end subroutine test_mirror_scale

   ! ------------------------------------------------------------------------------------------
   ! Readers
   ! ------------------------------------------------------------------------------------------

   !> Real MiniProf files were refused: a comment after a point, and an old-style header line
   !> of numbers (`32.58 37.11 14.71`) before its label `(Sd/Sh/qR)`. They read as the file
   !> without them.
   subroutine test_miniprof_variants(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, whl, a, b
      integer :: stat
      if (unavailable(error, .false.)) return
      whl = sample_profile(error, 'Car7216_0001r.whl')
      if (allocated(error)) return
      dir = scratch_directory('rob_miniprof')
      call shell("sed -e '8s/^"" //' -e '20s/$/   "" zig-zag pattern/' -e '30s/$/ % dent/' "// &
         whl//' > '//dir//'/old.whl')
      call shell('grep -q "^32.58 37.11 14.71" '//dir//'/old.whl && grep -q "% dent" '//dir// &
         '/old.whl', stat)
      call check(error, stat, 0, message='the variant file')
      if (allocated(error)) return
      stat = run_program(dir, 'run -o a.h5 --set profiles%wheel_smoothing=2 --set '// &
         'profiles%wheel='//whl)
      a = file_text(dir//'/out.txt')
      call check(error, stat, 0, message='original: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run -o b.h5 --set profiles%wheel_smoothing=2 --set '// &
         'profiles%wheel=old.whl')
      b = file_text(dir//'/out.txt')
      call check(error, stat, 0, message='variant: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, a(index(a, new_line('a')):) == b(index(b, new_line('a')):), &
         message='the variant gives another contact: '//a//' vs '//b)
      call shell('rm -rf '//dir)
   end subroutine test_miniprof_variants

   !> Under valgrind, a sweep with a failed case read uninitialised memory (len_trim in the
   !> failure table of the merged file). Skips without valgrind.
   subroutine test_valgrind(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      call shell('valgrind --version > /dev/null 2>&1', stat)
      if (stat /= 0) then
         call skip_test(error, 'valgrind is not installed')
         return
      end if
      dir = scratch_directory('rob_valgrind')
      call shell('cd '//dir//' && valgrind -q --error-exitcode=99 '//program_path()// &
         ' run -q -o f.h5 --set load%mode=approach --set sweep%approach=0.05,5 --set '// &
         'normal%n_strips=20 --set tangential%n_elements=10 > out.txt 2> err.txt', stat)
      call check(error, stat, 4, message='valgrind (99: a memory error): '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_valgrind

   ! ------------------------------------------------------------------------------------------
   ! Fuzz
   ! ------------------------------------------------------------------------------------------

   !> Seeded mutations of a case file and of a rail profile file, each run through the
   !> program: the exit status is a documented one, a failure names the file and has no
   !> backtrace, a success prints no NaN, and no checkpoint, temporary or (after a failure)
   !> output is left. In turn, a run also repeats a variable of some kind, gives a real
   !> variable a tiny or huge value (`--set`, every real variable in turn), or reads the case
   !> through a pipe; the library's option setter is fuzzed as well (test_input).
   !> SHCONTACT_FUZZ_SECONDS=N makes it an N-second campaign (SHCONTACT_FUZZ_SEED its seed)
   !> that prints its counts.
   subroutine test_fuzz(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, base_case, base_rail, text, args, name
      integer :: seed, seed0, i, stat, runs, n_real, ir, setter_calls, counts(0:6), n_pipe
      integer :: real_vars(size(variables))
      real :: seconds
      logical :: campaign
      integer(kind=8) :: t0, t1, rate
      if (unavailable(error, .false.)) return
      call fuzz_settings(fuzz_seconds, fuzz_runs, seconds, runs, seed, campaign)
      seed0 = seed
      dir = scratch_directory('rob_fuzz')
      stat = run_program(dir, 'profiles --write builtin')
      call check(error, stat, 0, message='profiles --write')
      if (allocated(error)) return
      ! Every 10th point of the built-in rail: a short file, quick to read.
      call shell("awk '/^#/ || NR % 10 == 0' "//dir//'/builtin/UIC60.txt > '//dir// &
         '/base_rail.txt && cp '//dir//'/base_rail.txt '//dir//'/rail.txt')
      call write_lines(dir//'/base.nml', fuzz_case)
      base_case = file_text(dir//'/base.nml')
      base_rail = file_text(dir//'/base_rail.txt')
      call check(error, run_program(dir, 'run base.nml -q -o out.h5'), 0, &
         message='the base case: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call shell('rm -f '//dir//'/out.h5')
      ! The library's option setter: a tenth of the time.
      call library_option_fuzz(error, seed, max(1.0, 0.1*seconds), setter_calls)
      if (allocated(error)) return
      n_real = 0
      do i = 1, size(variables)
         if (variables(i)%kind /= k_real .or. variables(i)%group == 'sweep') cycle
         n_real = n_real + 1
         real_vars(n_real) = i
      end do
      counts = 0
      n_pipe = 0
      ir = next_random(seed, n_real*size(extreme_values)) - 1
      call system_clock(t0, rate)
      do i = 1, runs
         text = mutated(base_case, seed)
         args = ' -q --format json -o out.h5'
         name = 'case.nml'
         select case (mod(i, 3))
         case (0)
            text = repeated(text, repeats(next_random(seed, size(repeats))))
         case (1)
            ir = mod(ir + 1, n_real*size(extreme_values))
            associate (v => variables(real_vars(1 + ir/size(extreme_values))))
               args = args//' --set '//trim(v%group)//'%'//trim(v%name)//'='// &
                  trim(extreme_values(1 + mod(ir, size(extreme_values))))
            end associate
         end select
         call write_bytes_file(dir//'/case.nml', text)
         call write_bytes_file(dir//'/rail.txt', base_rail)
         if (mod(i, 3) == 2) then
            ! Through a pipe: relative names are taken from the current directory.
            name = '/dev/stdin'
            n_pipe = n_pipe + 1
            call check_fuzz_run(error, dir, 'run /dev/stdin'//args, name, text, &
               also='rail', pipe='case.nml', status=stat)
         else
            call check_fuzz_run(error, dir, 'run case.nml'//args, name, text, also='rail', &
               status=stat)
         end if
         if (allocated(error)) then
            error%message = error%message//new_line('a')//'arguments:'//args
            exit
         end if
         counts(stat) = counts(stat) + 1
         call write_bytes_file(dir//'/rail.txt', mutated(base_rail, seed))
         call check_fuzz_run(error, dir, 'run base.nml -q -o out.h5', 'rail.txt', &
            file_text(dir//'/rail.txt'), status=stat)
         if (allocated(error)) exit
         counts(stat) = counts(stat) + 1
         call system_clock(t1)
         if (real(t1 - t0)/real(rate) > seconds) exit
      end do
      if (campaign) print '(a,i0,a,i0,a,i0,a,7(1x,i0),a,i0)', 'fuzz campaign: ', &
         min(i, runs), ' case runs (', n_pipe, ' through a pipe) and as many profile runs, ', &
         setter_calls, ' option-setter calls; program runs by status 0..6:', counts, &
         '; seed ', seed0
      if (allocated(error)) return
      call shell('rm -rf '//dir)
   end subroutine test_fuzz

   !> One fuzz run and its checks (test_fuzz).
   subroutine check_fuzz_run(error, dir, args, name, input, also, pipe, status)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, args, name, input
      !> Another name a message may give instead.
      character(len=*), intent(in), optional :: also
      !> A file of dir given to the program's standard input.
      character(len=*), intent(in), optional :: pipe
      !> The exit status.
      integer, intent(out), optional :: status
      logical :: named
      character(len=:), allocatable :: err, listing
      integer :: stat, left
      if (present(pipe)) then
         call shell('cd '//dir//' && cat '//pipe//' | OMP_NUM_THREADS=2 '//program_path()// &
            ' '//args//' > out.txt 2> err.txt', stat)
      else
         stat = run_program(dir, args)
      end if
      if (present(status)) status = max(0, min(6, stat))
      err = file_text(dir//'/err.txt')
      if (stat < 0 .or. stat > 6) then
         call test_failed(error, 'exit status '//trim(str(stat))//' is not documented; '// &
            'stderr: '//err//'; input:'//new_line('a')//input)
         return
      end if
      call expect_clean_stderr(error, dir, name)
      if (allocated(error)) then
         error%message = error%message//'; input:'//new_line('a')//input
         return
      end if
      named = index(err, name) > 0
      if (present(also)) named = named .or. index(err, also) > 0
      ! A value given with --set is named as such; a file the input names (a mutated profile
      ! name) may be named instead.
      if (index(args, ' --set ') > 0) named = named .or. index(err, 'command line --set ') > 0 &
         .or. index(err, set_variable(args)) > 0
      named = named .or. names_input_file(err, input)
      if (stat >= 1 .and. stat <= 3 .and. .not. named) then
         call test_failed(error, 'status '//trim(str(stat))//': the message does not name '// &
            name//': '//err//'; input:'//new_line('a')//input)
         return
      end if
      ! A success never prints a NaN (nor JSON's null for one; a solved case's message is
      ! null).
      listing = without_null_messages(file_text(dir//'/out.txt'))
      ! (Status 4: a failed case's line has null results by design; NaN never.)
      if ((stat == 0 .and. index(listing, 'null') > 0) .or. &
          ((stat == 0 .or. stat == 4) .and. index(listing, 'NaN') > 0)) then
         call test_failed(error, 'status '//trim(str(stat))//' with NaN results: '// &
            file_text(dir//'/out.txt')//'; input:'//new_line('a')//input)
         return
      end if
      ! No checkpoint or temporary ever; no output after a failure of the whole run.
      if (stat == 0 .or. stat == 4) then
         call shell('cd '//dir//' && ls -d *.partial *.tmp* 2>/dev/null | wc -l > n.txt')
      else
         call shell('cd '//dir//' && ls -d *.h5* 2>/dev/null | wc -l > n.txt')
      end if
      listing = file_text(dir//'/n.txt')
      read (listing, *, iostat=stat) left
      if (stat == 0 .and. left > 0) then
         call test_failed(error, 'files left behind by "'//args//'": '//err// &
            '; input:'//new_line('a')//input)
         return
      end if
      call shell('cd '//dir//' && rm -rf *.h5 *.h5.* out.txt err.txt')
   end subroutine check_fuzz_run

   !> The variable of the first `--set group%name=value` of the arguments ('' when none): a
   !> message about its value may name it instead of the command line (e.g. a flange-back
   !> position the wheel profile does not reach).
   pure function set_variable(args) result(name)
      character(len=*), intent(in) :: args
      character(len=:), allocatable :: name
      integer :: at, pct, eq
      name = achar(0)
      at = index(args, ' --set ')
      if (at == 0) return
      pct = index(args(at:), '%')
      eq = index(args(at:), '=')
      if (pct == 0 .or. eq <= pct + 1) return
      name = args(at + pct:at + eq - 2)
   end function set_variable

   pure function str(i) result(text)
      integer, intent(in) :: i
      character(len=12) :: text
      write (text, '(i0)') i
   end function str

   !> The text with 1 to 3 random mutations: delete, insert or replace a byte, duplicate,
   !> delete or swap a line, replace a number by an extreme one, truncate.
   function mutated(text, seed) result(m)
      character(len=*), intent(in) :: text
      integer, intent(inout) :: seed
      character(len=:), allocatable :: m, line
      character(len=*), parameter :: extremes(6) = [character(len=8) :: '1e308', '-1e308', &
         'nan', '-0', '99999999', '1d-320']
      integer :: k, at, a, b, e
      m = text
      do k = 1, next_random(seed, 3)
         if (len(m) < 2) exit
         at = next_random(seed, len(m))
         select case (next_random(seed, 8))
         case (1)
            m = m(:at - 1)//m(at + 1:)
         case (2)
            a = next_random(seed, len(fuzz_bytes))
            m = m(:at - 1)//fuzz_bytes(a:a)//m(at:)
         case (3)
            a = next_random(seed, len(fuzz_bytes))
            m(at:at) = fuzz_bytes(a:a)
         case (4, 5)
            ! A whole line: duplicate (4) or delete (5).
            a = index(m(:at), new_line('a'), back=.true.) + 1
            b = index(m(at:), new_line('a'))
            b = merge(len(m), at + b - 1, b == 0)
            line = m(a:b)
            if (next_random(seed, 2) == 1) then
               m = m(:b)//line//m(b + 1:)
            else
               m = m(:a - 1)//m(b + 1:)
            end if
         case (6)
            ! A number (a digit run) replaced by an extreme value.
            a = scan(m(at:), '0123456789')
            if (a == 0) cycle
            a = at + a - 1
            e = verify(m(a:), '0123456789.eE+-')
            e = merge(len(m), a + e - 2, e == 0)
            m = m(:a - 1)//trim(extremes(next_random(seed, size(extremes))))//m(e + 1:)
         case (7)
            m = m(:at)
         case default
            ! Swap the two halves of a line at a blank (y and z of a profile line).
            a = index(m(:at), new_line('a'), back=.true.) + 1
            b = index(m(at:), new_line('a'))
            if (b == 0) cycle
            b = at + b - 2
            if (b <= a) cycle
            line = adjustl(m(a:b))
            e = index(trim(line), ' ', back=.true.)
            if (e == 0) cycle
            line = trim(adjustl(line(e + 1:)))//' '//trim(line(:e - 1))
            m = m(:a - 1)//line//m(b + 1:)
         end select
      end do
   end function mutated

   !> Write a text byte for byte (any bytes, no line end added).
   subroutine write_bytes_file(name, text)
      character(len=*), intent(in) :: name, text
      integer :: unit
      open (newunit=unit, file=name, access='stream', form='unformatted', status='replace', &
         action='write')
      write (unit) text
      close (unit)
   end subroutine write_bytes_file

   !> The number-to-text functions of messages (str_int, str_real) give the same text when two
   !> threads call them at once as when one does: with a deferred-length result gfortran 12
   !> kept the result's length in a static variable of the caller, and two threads building
   !> the same message raced (wrong lengths, lost or corrupted text; doc/performance.md,
   !> "Threads and strings"). 4 × 100 000 messages; the race showed in every such run before.
   subroutine test_threaded_messages(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 100000
      integer, allocatable :: lengths(:), expected(:)
      integer :: i, round, wrong
      allocate (lengths(n), expected(n))
      do i = 1, n
         expected(i) = message_length(i)
      end do
      do round = 1, 4
         lengths = -1
         !$omp parallel do default(none) schedule(dynamic, 16) num_threads(2) shared(lengths) &
         !$omp private(i)
         do i = 1, n
            lengths(i) = message_length(i)
         end do
         !$omp end parallel do
         wrong = count(lengths /= expected)
         call check(error, wrong, 0, message='messages of the wrong length from two threads, '// &
            'round '//str_int(round))
         if (allocated(error)) return
      end do
   contains
      !> The length of a message built as the solvers build them (a local text, as in a
      !> solver's error path; the calls of str_int and str_real are the ones under test).
      integer function message_length(i)
         integer, intent(in) :: i
         character(len=:), allocatable :: text
         text = 'case '//str_int(i)//': approach '//str_real(1.0e-3_wp*real(i, wp))// &
            ' mm, '//str_int(mod(i, 7)*1000003)//' N'
         message_length = len(text)
         if (text(len(text) - 1:) /= ' N') message_length = -len(text)
      end function message_length
   end subroutine test_threaded_messages

   !> A program's output without the JSON lines' `"message":null` (a solved case's).
   pure function without_null_messages(text) result(rest)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: rest
      character(len=*), parameter :: key = '"message":null'
      integer :: i
      rest = text
      do
         i = index(rest, key)
         if (i == 0) exit
         rest = rest(:i - 1)//rest(i + len(key):)
      end do
   end function without_null_messages

end module test_robustness
