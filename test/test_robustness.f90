!> Hostile input to the shcontact program (issue 14): each reproducer of the issue with the
!> exit status and the message it now gets, and a seeded fuzz test of case files and profile
!> files. Every failure must end with a documented exit status, a message naming the file, no
!> backtrace, and nothing left under the output name.
!>
!> Runs the program as test_app does (its helpers); tests that read the sample profiles skip
!> when ../shared/profiles/ is absent.
module test_robustness
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_io_files, only: file_exists
   use test_app, only: program_path, scratch_directory, shell, run_program, file_text, &
      write_lines, unavailable, expect_in, expect_failure
   implicit none
   private
   public :: collect_robustness

contains

   subroutine collect_robustness(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('lone_carriage_return', test_lone_cr), &
         new_unittest('byte_order_mark_accepted', test_bom), &
         new_unittest('directory_as_case_file', test_directory_case), &
         new_unittest('grid_size_limit', test_grid_limit), &
         new_unittest('thread_limit', test_thread_limit), &
         new_unittest('empty_values_refused', test_empty_values), &
         new_unittest('sweep_errors_name_the_file', test_sweep_origin) &
         ]
   end subroutine collect_robustness

   ! ------------------------------------------------------------------------------------------
   ! Helpers
   ! ------------------------------------------------------------------------------------------

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

end module test_robustness
