!> A small unit-test harness with the public API of fortran-lang/test-drive (the part that
!> shcontact's tests use), written for this project so the tests build without network access.
!>
!> Names and calling conventions follow test-drive's documentation, so that replacing this
!> package by upstream test-drive is a one-line change in the project's fpm.toml.
module testdrive
   use, intrinsic :: iso_fortran_env, only: sp => real32, dp => real64, i1 => int8, &
      i2 => int16, i4 => int32, i8 => int64
   implicit none
   private

   public :: run_testsuite, run_selected, new_unittest, new_testsuite, test_failed, skip_test
   public :: select_test, select_suite, check, to_string
   public :: unittest_type, testsuite_type, error_type, test_interface, collect_interface

   !> Status of a passed test.
   integer, parameter :: success = 0
   !> Status of a failed test.
   integer, parameter :: fatal = 1
   !> Status of a skipped test (as in test-drive and automake).
   integer, parameter :: skipped = 77

   !> Error handle of a test: allocated means failed (or skipped, with stat = 77).
   type :: error_type
      !> Status code.
      integer :: stat = success
      !> Explanation.
      character(len=:), allocatable :: message
   end type error_type

   abstract interface
      !> One test.
      subroutine test_interface(error)
         import :: error_type
         !> Allocated on failure or skip.
         type(error_type), allocatable, intent(out) :: error
      end subroutine test_interface
   end interface

   !> A named test.
   type :: unittest_type
      !> Name of the test.
      character(len=:), allocatable :: name
      !> The test procedure.
      procedure(test_interface), pointer, nopass :: test => null()
      !> The test is expected to fail.
      logical :: should_fail = .false.
   end type unittest_type

   abstract interface
      !> Collect the tests of a suite.
      subroutine collect_interface(testsuite)
         import :: unittest_type
         !> The tests.
         type(unittest_type), allocatable, intent(out) :: testsuite(:)
      end subroutine collect_interface
   end interface

   !> A named collection of tests.
   type :: testsuite_type
      !> Name of the suite.
      character(len=:), allocatable :: name
      !> Collector of its tests.
      procedure(collect_interface), pointer, nopass :: collect => null()
   end type testsuite_type

   !> Compare a result with an expectation; allocate `error` when they disagree.
   interface check
      module procedure :: check_stat, check_logical, check_int_i4, check_int_i8, check_char
      module procedure :: check_float_dp, check_float_sp
   end interface check

   !> Render a number as text.
   interface to_string
      module procedure :: int_to_string, dp_to_string
   end interface to_string

   character(len=*), parameter :: fmt_real = '(es24.16e3)'

contains

   !> Run every test of a collection, reporting on `unit`; `stat` is increased by the number of
   !> failures.
   subroutine run_testsuite(collect, unit, stat, parallel)
      !> Collector of the tests.
      procedure(collect_interface) :: collect
      !> Output unit.
      integer, intent(in) :: unit
      !> Failure count, increased.
      integer, intent(inout) :: stat
      !> Ignored (accepted for compatibility).
      logical, intent(in), optional :: parallel
      type(unittest_type), allocatable :: suite(:)
      integer :: i

      if (present(parallel)) continue
      call collect(suite)
      do i = 1, size(suite)
         write (unit, '(2x,a,1x,a,1x,"(",i0,"/",i0,")")') 'Starting', suite(i)%name, i, size(suite)
         call run_unittest(suite(i), unit, stat)
      end do
   end subroutine run_testsuite

   !> Run the test named `name` of a collection.
   subroutine run_selected(collect, name, unit, stat)
      !> Collector of the tests.
      procedure(collect_interface) :: collect
      !> Name of the test.
      character(len=*), intent(in) :: name
      !> Output unit.
      integer, intent(in) :: unit
      !> Failure count, increased (also when no test has that name).
      integer, intent(inout) :: stat
      type(unittest_type), allocatable :: suite(:)
      integer :: i

      call collect(suite)
      i = select_test(suite, name)
      if (i > 0 .and. i <= size(suite)) then
         call run_unittest(suite(i), unit, stat)
      else
         write (unit, '(a)') 'No test called "'//name//'" found, available tests are'
         do i = 1, size(suite)
            write (unit, '(a)') '- '//suite(i)%name
         end do
         stat = stat + 1
      end if
   end subroutine run_selected

   !> Run one test and report its outcome.
   subroutine run_unittest(test, unit, stat)
      type(unittest_type), intent(in) :: test
      integer, intent(in) :: unit
      integer, intent(inout) :: stat
      type(error_type), allocatable :: error
      logical :: failed

      call test%test(error)
      failed = .false.
      if (allocated(error)) failed = error%stat /= skipped
      if (failed .neqv. test%should_fail) stat = stat + 1
      write (unit, '(7x,a,1x,a,1x,a)') '...', test%name, trim(outcome(error, test%should_fail))
      if (allocated(error)) then
         if (allocated(error%message)) write (unit, '(a)') '  Message: '//error%message
      end if
   end subroutine run_unittest

   !> Outcome label of a test.
   pure function outcome(error, should_fail) result(label)
      type(error_type), intent(in), allocatable :: error
      logical, intent(in) :: should_fail
      character(len=16) :: label
      if (.not. allocated(error)) then
         label = merge('[UNEXPECTED PASS]', '[PASSED]         ', should_fail)
      else if (error%stat == skipped) then
         label = '[SKIPPED]'
      else
         label = merge('[EXPECTED FAIL]', '[FAILED]       ', should_fail)
      end if
   end function outcome

   !> Position of the test called `name`, or 0.
   pure function select_test(tests, name) result(pos)
      !> The tests.
      type(unittest_type), intent(in) :: tests(:)
      !> The name.
      character(len=*), intent(in) :: name
      integer :: pos
      integer :: i
      pos = 0
      do i = 1, size(tests)
         if (name == tests(i)%name) then
            pos = i
            return
         end if
      end do
   end function select_test

   !> Position of the suite called `name`, or 0.
   pure function select_suite(suites, name) result(pos)
      !> The suites.
      type(testsuite_type), intent(in) :: suites(:)
      !> The name.
      character(len=*), intent(in) :: name
      integer :: pos
      integer :: i
      pos = 0
      do i = 1, size(suites)
         if (name == suites(i)%name) then
            pos = i
            return
         end if
      end do
   end function select_suite

   !> Create a test.
   function new_unittest(name, test, should_fail) result(self)
      !> Name.
      character(len=*), intent(in) :: name
      !> Procedure.
      procedure(test_interface) :: test
      !> Expected to fail.
      logical, intent(in), optional :: should_fail
      type(unittest_type) :: self
      self%name = name
      self%test => test
      if (present(should_fail)) self%should_fail = should_fail
   end function new_unittest

   !> Create a suite.
   function new_testsuite(name, collect) result(self)
      !> Name.
      character(len=*), intent(in) :: name
      !> Collector.
      procedure(collect_interface) :: collect
      type(testsuite_type) :: self
      self%name = name
      self%collect => collect
   end function new_testsuite

   !> Fail a test with a message.
   subroutine test_failed(error, message, more)
      !> Error handle, allocated here.
      type(error_type), allocatable, intent(out) :: error
      !> Message.
      character(len=*), intent(in) :: message
      !> More detail on a second line.
      character(len=*), intent(in), optional :: more
      call set_error(error, fatal, message, more)
   end subroutine test_failed

   !> Skip a test with a reason.
   subroutine skip_test(error, message, more)
      !> Error handle, allocated here with stat 77.
      type(error_type), allocatable, intent(out) :: error
      !> Reason.
      character(len=*), intent(in) :: message
      !> More detail.
      character(len=*), intent(in), optional :: more
      call set_error(error, skipped, message, more)
   end subroutine skip_test

   subroutine set_error(error, stat, message, more)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in) :: stat
      character(len=*), intent(in) :: message
      character(len=*), intent(in), optional :: more
      allocate (error)
      error%stat = stat
      if (present(more)) then
         error%message = message//new_line('a')//'  '//more
      else
         error%message = message
      end if
   end subroutine set_error

   !> Fail unless the status is zero.
   subroutine check_stat(error, stat, message, more)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in) :: stat
      character(len=*), intent(in), optional :: message, more
      if (stat /= success) call fail_with(error, 'Non-zero exit code encountered', message, more)
   end subroutine check_stat

   !> Fail unless the expression is true (or equals `expected`).
   subroutine check_logical(error, expression, message, more)
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in) :: expression
      character(len=*), intent(in), optional :: message, more
      if (.not. expression) call fail_with(error, 'Condition not fulfilled', message, more)
   end subroutine check_logical

   subroutine check_int_i4(error, actual, expected, message, more)
      type(error_type), allocatable, intent(out) :: error
      integer(i4), intent(in) :: actual, expected
      character(len=*), intent(in), optional :: message, more
      if (actual /= expected) call fail_with(error, 'Integer value mismatch', message, &
         more, 'expected '//int_to_string(int(expected, i8))//' but got '// &
         int_to_string(int(actual, i8)))
   end subroutine check_int_i4

   subroutine check_int_i8(error, actual, expected, message, more)
      type(error_type), allocatable, intent(out) :: error
      integer(i8), intent(in) :: actual, expected
      character(len=*), intent(in), optional :: message, more
      if (actual /= expected) call fail_with(error, 'Integer value mismatch', message, &
         more, 'expected '//int_to_string(expected)//' but got '//int_to_string(actual))
   end subroutine check_int_i8

   subroutine check_char(error, actual, expected, message, more)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: actual, expected
      character(len=*), intent(in), optional :: message, more
      if (actual /= expected) call fail_with(error, 'Character value mismatch', message, &
         more, 'expected "'//expected//'" but got "'//actual//'"')
   end subroutine check_char

   !> Compare reals: with `thr` (absolute threshold, relative with `rel`), otherwise to within a
   !> few units of the last place, as test-drive does.
   subroutine check_float_dp(error, actual, expected, message, more, thr, rel)
      type(error_type), allocatable, intent(out) :: error
      real(dp), intent(in) :: actual, expected
      character(len=*), intent(in), optional :: message, more
      real(dp), intent(in), optional :: thr
      logical, intent(in), optional :: rel
      real(dp) :: diff, tol
      logical :: relative

      relative = .false.
      if (present(rel)) relative = rel
      tol = epsilon(expected)
      if (present(thr)) tol = thr
      if (actual /= actual .or. expected /= expected) then
         call fail_with(error, 'Floating point value is NaN', message, more, &
            'expected '//dp_to_string(expected)//' but got '//dp_to_string(actual))
         return
      end if
      diff = abs(actual - expected)
      if (relative .and. expected /= 0.0_dp) diff = diff/abs(expected)
      if (diff > tol) call fail_with(error, 'Floating point value mismatch', message, more, &
         'expected '//dp_to_string(expected)//' but got '//dp_to_string(actual)// &
         ' (difference '//dp_to_string(diff)//merge(' relative', ' absolute', relative)//')')
   end subroutine check_float_dp

   subroutine check_float_sp(error, actual, expected, message, more, thr, rel)
      type(error_type), allocatable, intent(out) :: error
      real(sp), intent(in) :: actual, expected
      character(len=*), intent(in), optional :: message, more
      real(sp), intent(in), optional :: thr
      logical, intent(in), optional :: rel
      if (present(thr)) then
         call check_float_dp(error, real(actual, dp), real(expected, dp), message, more, &
            real(thr, dp), rel)
      else
         call check_float_dp(error, real(actual, dp), real(expected, dp), message, more, &
            real(epsilon(expected), dp), rel)
      end if
   end subroutine check_float_sp

   subroutine fail_with(error, default, message, more, detail)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: default
      character(len=*), intent(in), optional :: message, more, detail
      character(len=:), allocatable :: text
      if (present(message)) then
         text = message
      else
         text = default
      end if
      if (present(detail)) text = text//new_line('a')//'  '//detail
      call set_error(error, fatal, text, more)
   end subroutine fail_with

   pure function int_to_string(val) result(str)
      integer(i8), intent(in) :: val
      character(len=:), allocatable :: str
      character(len=24) :: buf
      write (buf, '(i0)') val
      str = trim(buf)
   end function int_to_string

   pure function dp_to_string(val) result(str)
      real(dp), intent(in) :: val
      character(len=:), allocatable :: str
      character(len=32) :: buf
      write (buf, fmt_real) val
      str = trim(adjustl(buf))
   end function dp_to_string

end module testdrive
