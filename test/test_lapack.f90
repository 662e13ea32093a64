!> Tests of the LAPACK wrappers on small systems with known solutions, and on singular ones.
module test_lapack
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_numerical
   use shcontact_math_lapack, only: solve_spd_banded, solve_general_banded, solve_dense_leading
   implicit none
   private
   public :: collect_lapack

   integer, parameter :: n = 6

contains

   subroutine collect_lapack(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('spd_banded_known_solution', test_spd), &
         new_unittest('spd_banded_indefinite_is_error', test_spd_indefinite), &
         new_unittest('general_banded_known_solution', test_gb), &
         new_unittest('general_banded_singular_is_error', test_gb_singular), &
         new_unittest('dense_leading_block_known_solution', test_dense_leading) &
         ]
   end subroutine collect_lapack

   !> The exact solution used throughout: x_i = i.
   pure function x_exact() result(x)
      real(wp) :: x(n)
      integer :: i
      x = [(real(i, wp), i=1, n)]
   end function x_exact

   !> Pentadiagonal SPD matrix 6 on the diagonal, −2 and 1 off it, in upper band storage.
   subroutine test_spd(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      real(wp) :: ab(3, n), b(n, 1), x(n), a(n, n)
      integer :: i, j
      a = 0
      do i = 1, n
         a(i, i) = 6
         if (i < n) a(i, i + 1) = -2
         if (i < n) a(i + 1, i) = -2
         if (i < n - 1) a(i, i + 2) = 1
         if (i < n - 1) a(i + 2, i) = 1
      end do
      ab = 0
      do j = 1, n
         do i = max(1, j - 2), j
            ab(3 + i - j, j) = a(i, j)
         end do
      end do
      x = x_exact()
      b(:, 1) = matmul(a, x)
      call solve_spd_banded(ab, b, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, maxval(abs(b(:, 1) - x)), 0.0_wp, thr=1.0e-13_wp)
   end subroutine test_spd

   subroutine test_spd_indefinite(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      real(wp) :: ab(2, n), b(n, 1)
      ab(1, :) = 2.0_wp   ! super-diagonal 2 with diagonal 1: not positive definite
      ab(2, :) = 1.0_wp
      b = 1
      call solve_spd_banded(ab, b, err)
      call check(error, allocated(err), message='indefinite matrix must give an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_numerical)
      if (allocated(error)) return
      call check(error, index(err%message, 'dpbsv') > 0, message=err%message)
   end subroutine test_spd_indefinite

   !> Non-symmetric tridiagonal as a general band matrix (kl = ku = 1).
   subroutine test_gb(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      real(wp) :: ab(4, n), b(n, 1), a(n, n), x(n)
      integer :: i, j
      a = 0
      do i = 1, n
         a(i, i) = 4
         if (i < n) a(i, i + 1) = -1
         if (i < n) a(i + 1, i) = 2
      end do
      ab = 0
      do j = 1, n
         do i = max(1, j - 1), min(n, j + 1)
            ab(1 + 1 + 1 + i - j, j) = a(i, j)
         end do
      end do
      x = x_exact()
      b(:, 1) = matmul(a, x)
      call solve_general_banded(ab, 1, 1, b, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, maxval(abs(b(:, 1) - x)), 0.0_wp, thr=1.0e-13_wp)
   end subroutine test_gb

   subroutine test_gb_singular(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      real(wp) :: ab(4, n), b(n, 1)
      ab = 0
      ab(3, :) = 1
      ab(3, 4) = 0   ! a zero row/column in a diagonal matrix
      b = 1
      call solve_general_banded(ab, 1, 1, b, err)
      call check(error, allocated(err), message='singular band matrix must give an error')
      if (allocated(error)) return
      call check(error, index(err%message, 'singular') > 0, message=err%message)
   end subroutine test_gb_singular

   !> solve_dense_leading on the leading block of larger arrays, against x_i = i: a nonsymmetric
   !> matrix that needs pivoting (zero first diagonal), by its own elimination (order 6) and
   !> through dgesv (order 40); a singular block is an error.
   subroutine test_dense_leading(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      integer, parameter :: big = 40
      real(wp) :: a(big + 3, big + 2), b(big + 5), x(big)
      integer :: ipiv(big + 1), order, i, j, k

      do k = 1, 2
         order = merge(n, big, k == 1)
         a = huge(1.0_wp)
         b = huge(1.0_wp)
         do j = 1, order
            do i = 1, order
               a(i, j) = 1.0_wp/real(i + 2*j, wp) + merge(3.0_wp, 0.0_wp, i == j .and. i > 1)
            end do
         end do
         a(1, 1) = 0.0_wp
         x(1:order) = [(real(i, wp), i=1, order)]
         b(1:order) = matmul(a(1:order, 1:order), x(1:order))
         call solve_dense_leading(order, a, b, ipiv, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, maxval(abs(b(1:order) - x(1:order))), 0.0_wp, thr=1.0e-10_wp, &
            message='order '//merge('6 ', '40', k == 1))
         if (allocated(error)) return
      end do
      a(1:3, 1:3) = reshape([1, 2, 3, 2, 4, 6, 0, 1, 1], [3, 3])
      b(1:3) = 1
      call solve_dense_leading(3, a, b, ipiv, err)
      call check(error, allocated(err), message='singular block must give an error')
   end subroutine test_dense_leading

end module test_lapack
