!> LAPACK through explicit interfaces, and thin wrappers that take sizes from the arrays and
!> turn `info /= 0` into an [[error_type]] naming the routine.
!>
!> Band storage follows LAPACK: for the symmetric positive definite band solver (`dpbsv`, upper
!> triangle) `ab(kd + 1 + i − j, j) = a(i, j)` for max(1, j − kd) ≤ i ≤ j; for the general band
!> solver (`dgbsv`) `ab(kl + ku + 1 + i − j, j) = a(i, j)` with kl extra rows on top for the
!> fill-in of the factorisation.
module shcontact_math_lapack
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_numerical, stat_usage
   implicit none
   private

   public :: solve_spd_banded, solve_general_banded, solve_dense_leading, solve_factored_leading

   !> Largest order [[solve_dense_leading]] eliminates itself (unblocked) instead of calling dgesv.
   integer, parameter :: small_order = 32

   ! Explicit interfaces to the reference LAPACK routines used by the wrappers.
   interface
      pure subroutine dpbsv(uplo, n, kd, nrhs, ab, ldab, b, ldb, info)
         import :: wp
         character(len=1), intent(in) :: uplo
         integer, intent(in) :: n, kd, nrhs, ldab, ldb
         real(wp), intent(inout) :: ab(ldab, *), b(ldb, *)
         integer, intent(out) :: info
      end subroutine dpbsv
      pure subroutine dgbsv(n, kl, ku, nrhs, ab, ldab, ipiv, b, ldb, info)
         import :: wp
         integer, intent(in) :: n, kl, ku, nrhs, ldab, ldb
         real(wp), intent(inout) :: ab(ldab, *), b(ldb, *)
         integer, intent(out) :: ipiv(*)
         integer, intent(out) :: info
      end subroutine dgbsv
      pure subroutine dgesv(n, nrhs, a, lda, ipiv, b, ldb, info)
         import :: wp
         integer, intent(in) :: n, nrhs, lda, ldb
         real(wp), intent(inout) :: a(lda, *), b(ldb, *)
         integer, intent(out) :: ipiv(*)
         integer, intent(out) :: info
      end subroutine dgesv
   end interface

contains

   !> Solve A x = b for a symmetric positive definite band matrix in upper band storage
   !> `ab(kd + 1, n)` (LAPACK `dpbsv`). `ab` is overwritten by the Cholesky factor, `b` by x.
   pure subroutine solve_spd_banded(ab, b, error)
      !> Band matrix, upper storage, kd = size(ab, 1) − 1 super-diagonals.
      real(wp), intent(inout) :: ab(:, :)
      !> Right-hand sides on entry (n × nrhs), solutions on return.
      real(wp), intent(inout) :: b(:, :)
      !> Set when the matrix is not positive definite or the shapes disagree.
      type(error_type), allocatable, intent(out) :: error
      integer :: n, kd, info

      n = size(ab, 2); kd = size(ab, 1) - 1
      if (size(b, 1) /= n) then
         call fatal_error(error, 'dpbsv: right-hand side has the wrong number of rows', stat_usage)
         return
      end if
      call dpbsv('U', n, kd, size(b, 2), ab, size(ab, 1), b, size(b, 1), info)
      call check_info('dpbsv', info, 'the leading minor of order ', ' is not positive definite', &
                      error)
   end subroutine solve_spd_banded

   !> Solve A x = b for a general band matrix with kl sub- and ku super-diagonals, stored in
   !> `ab(2 kl + ku + 1, n)` as LAPACK `dgbsv` expects (rows 1..kl are workspace).
   pure subroutine solve_general_banded(ab, kl, ku, b, error)
      !> Band matrix in LAPACK general band storage; overwritten by the LU factors.
      real(wp), intent(inout) :: ab(:, :)
      !> Numbers of sub- and super-diagonals.
      integer, intent(in) :: kl, ku
      !> Right-hand sides on entry, solutions on return.
      real(wp), intent(inout) :: b(:, :)
      !> Set when the matrix is singular or the shapes disagree.
      type(error_type), allocatable, intent(out) :: error
      integer :: n, info
      integer :: ipiv(size(ab, 2))

      n = size(ab, 2)
      if (size(ab, 1) /= 2*kl + ku + 1 .or. size(b, 1) /= n) then
         call fatal_error(error, 'dgbsv: band storage or right-hand side has the wrong shape', &
                          stat_usage)
         return
      end if
      call dgbsv(n, kl, ku, size(b, 2), ab, size(ab, 1), ipiv, b, size(b, 1), info)
      call check_info('dgbsv', info, 'U(', ',.) is exactly zero: the matrix is singular', error)
   end subroutine solve_general_banded

   !> Solve the leading n × n block of `a` with one right-hand side, the first n entries of `b`:
   !> Gaussian elimination with partial pivoting, unblocked, for n ≤ [[small_order]] (the
   !> coupled reduction's systems of ≤ 17 unknowns, solved several times per contact call, where
   !> the blocked `dgesv` spends more in its call tree than in the arithmetic), `dgesv` with the
   !> leading dimension of `a` above. Fixed-size work arrays, no copy, nothing allocated.
   pure subroutine solve_dense_leading(n, a, b, ipiv, error)
      !> Order of the system, 1 ≤ n ≤ min(size(a, 1), size(a, 2), size(b), size(ipiv)).
      integer, intent(in) :: n
      !> Matrix in its leading block; overwritten by its LU factors.
      real(wp), intent(inout), contiguous :: a(:, :)
      !> Right-hand side on entry, solution on return (first n entries).
      real(wp), intent(inout), contiguous :: b(:)
      !> Pivot indices (workspace of the caller, so that nothing is allocated here).
      integer, intent(out) :: ipiv(:)
      !> Set when the block is singular or does not fit.
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: t, f, g
      integer :: info, i, j, k, p

      if (n < 1 .or. n > size(a, 1) .or. n > size(a, 2) .or. n > size(b) .or. &
         n > size(ipiv)) then
         call fatal_error(error, 'dgesv: the leading block does not fit the arrays', stat_usage)
         return
      end if
      if (n > small_order) then
         call dgesv(n, 1, a, size(a, 1), ipiv, b, size(b), info)
         call check_info('dgesv', info, 'U(', ',.) is exactly zero: the matrix is singular', &
            error)
         return
      end if
      do k = 1, n
         p = k - 1 + maxloc(abs(a(k:n, k)), dim=1)
         ipiv(k) = p
         if (.not. (abs(a(p, k)) > 0.0_wp)) then
            call check_info('solve_dense_leading', k, 'U(', &
               ',.) is exactly zero: the matrix is singular', error)
            return
         end if
         if (p /= k) then
            ! Whole rows, the multipliers too (LAPACK's dgetrf layout, which
            ! [[solve_factored_leading]] and dgetrs read).
            do j = 1, n
               t = a(k, j)
               a(k, j) = a(p, j)
               a(p, j) = t
            end do
         end if
         ! Column by column (contiguous in memory): the same operations on every element as
         ! row by row.
         ! One division per column, as LAPACK's dgetf2 scales by 1/pivot (and divides when
         ! the pivot is so small that its reciprocal would overflow).
         if (abs(a(k, k)) >= tiny(1.0_wp)) then
            f = 1.0_wp/a(k, k)
            do i = k + 1, n
               a(i, k) = a(i, k)*f
            end do
         else
            f = a(k, k)
            do i = k + 1, n
               a(i, k) = a(i, k)/f
            end do
         end if
         ! Two columns at a time (each multiplier column read once for both; the same
         ! operation on every element, so the same factors bit for bit).
         do j = k + 1, n - 1, 2
            f = a(k, j)
            g = a(k, j + 1)
            do i = k + 1, n
               a(i, j) = a(i, j) - a(i, k)*f
               a(i, j + 1) = a(i, j + 1) - a(i, k)*g
            end do
         end do
         if (modulo(n - k, 2) == 1) then
            f = a(k, n)
            do i = k + 1, n
               a(i, n) = a(i, n) - a(i, k)*f
            end do
         end if
      end do
      call solve_factored_leading(n, a, ipiv, b)
   end subroutine solve_dense_leading

   !> Solve U x = b in place with the upper triangle of the leading block of `a`, column by
   !> column.
   pure subroutine back_substitute(n, a, b)
      integer, intent(in) :: n
      real(wp), intent(in), contiguous :: a(:, :)
      real(wp), intent(inout), contiguous :: b(:)
      integer :: i, j
      do j = n, 1, -1
         b(j) = b(j)/a(j, j)
         do i = 1, j - 1
            b(i) = b(i) - a(i, j)*b(j)
         end do
      end do
   end subroutine back_substitute

   !> Solve with the factors that [[solve_dense_leading]] left in `a` and `ipiv` (any order: the
   !> unblocked elimination and dgesv store them alike): the row interchanges, then L and U.
   pure subroutine solve_factored_leading(n, a, ipiv, b)
      !> Order of the factorised system.
      integer, intent(in) :: n
      !> LU factors in the leading block.
      real(wp), intent(in), contiguous :: a(:, :)
      !> Pivot indices of the factorisation.
      integer, intent(in) :: ipiv(:)
      !> Right-hand side on entry, solution on return (first n entries).
      real(wp), intent(inout), contiguous :: b(:)
      real(wp) :: t
      integer :: i, k

      do k = 1, n
         if (ipiv(k) /= k) then
            t = b(k)
            b(k) = b(ipiv(k))
            b(ipiv(k)) = t
         end if
      end do
      do k = 1, n - 1
         do i = k + 1, n
            b(i) = b(i) - a(i, k)*b(k)
         end do
      end do
      call back_substitute(n, a, b)
   end subroutine solve_factored_leading

   !> Turn a LAPACK info code into an error naming the routine.
   pure subroutine check_info(routine, info, before, after, error)
      character(len=*), intent(in) :: routine, before, after
      integer, intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
      character(len=24) :: num

      if (info == 0) return
      write (num, '(i0)') abs(info)
      if (info < 0) then
         call fatal_error(error, routine//': argument '//trim(num)//' had an illegal value', &
                          stat_usage)
      else
         call fatal_error(error, routine//': '//before//trim(num)//after, stat_numerical)
      end if
   end subroutine check_info

end module shcontact_math_lapack
