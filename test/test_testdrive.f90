!> Tests of the test harness itself: a check that should fail does fail.
module test_testdrive
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   implicit none
   private
   public :: collect_testdrive

contains

   subroutine collect_testdrive(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('real_mismatch_fails', test_real_mismatch, should_fail=.true.), &
         new_unittest('relative_tolerance', test_relative), &
         new_unittest('integer_mismatch_fails', test_int_mismatch, should_fail=.true.), &
         new_unittest('character_mismatch_fails', test_char_mismatch, should_fail=.true.), &
         new_unittest('nan_fails', test_nan, should_fail=.true.), &
         new_unittest('skip_is_not_failure', test_skip_status) &
         ]
   end subroutine collect_testdrive

   subroutine test_real_mismatch(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, 1.0d0, 1.0d0 + 1.0d-6, thr=1.0d-8)
   end subroutine test_real_mismatch

   subroutine test_relative(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, 1.0d6 + 0.5d0, 1.0d6, thr=1.0d-6, rel=.true.)
   end subroutine test_relative

   subroutine test_int_mismatch(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, 3, 4)
   end subroutine test_int_mismatch

   subroutine test_char_mismatch(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, 'abc', 'abd')
   end subroutine test_char_mismatch

   subroutine test_nan(error)
      use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
      type(error_type), allocatable, intent(out) :: error
      call check(error, ieee_value(1.0d0, ieee_quiet_nan), 1.0d0, thr=1.0d0)
   end subroutine test_nan

   subroutine test_skip_status(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type), allocatable :: inner
      call skip_test(inner, 'skipped on purpose')
      call check(error, inner%stat, 77, message='skip_test must set the status 77')
   end subroutine test_skip_status

end module test_testdrive
