!> Anderson acceleration of a fixed-point iteration (type II, short memory).
!>
!> An iteration x ← x + f(x) whose plain step f divides the error by a fixed factor (the
!> coupled reduction's strip lengths, shcontact_normal_coupling) converges linearly; its error
!> lies mostly in a few modes with their own factors. Anderson's method takes the step
!> x + f − (ΔX + ΔF) c, with ΔX, ΔF the differences of the last iterates and of their steps and
!> c the least-squares solution of ΔF c ≈ f: for a linear map with m distinct factors it is
!> exact after m + 1 steps. The fixed point (f = 0) is that of the plain iteration; only the
!> path to it changes. The history lives in the caller's arrays, so that nothing is allocated.
module shcontact_math_anderson
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: anderson_step

   !> Largest accelerated step, as a multiple of the largest plain step; beyond it the plain
   !> step is taken and the history restarted.
   real(wp), parameter :: max_growth = 4.0_wp
   !> A difference column whose part orthogonal to the newer ones is below this fraction of
   !> its norm is dropped (it would only amplify round-off; the normal equations resolve
   !> about 1e-8).
   real(wp), parameter :: drop_ratio = 1.0e-6_wp
   !> Most difference columns used (longer histories use the newest max_memory).
   integer, parameter :: max_memory = 8

contains

   !> The next iterate x_new of x ← x + f(x) (module text). The history (last_x, last_f and the
   !> `used` newest difference columns of dx, df; column 1 the newest) is updated here;
   !> `used` = 0 on the first call, or to restart (the plain step x + f is then taken).
   pure subroutine anderson_step(x, f, last_x, last_f, dx, df, used, x_new)
      !> The iterate and its plain step.
      real(wp), intent(in) :: x(:), f(:)
      !> The previous iterate and step (the history's base).
      real(wp), intent(inout) :: last_x(:), last_f(:)
      !> Differences of the iterates and of the steps, one column per step (at least one).
      real(wp), intent(inout) :: dx(:, :), df(:, :)
      !> Columns of dx, df in use.
      integer, intent(inout) :: used
      !> The next iterate.
      real(wp), intent(out) :: x_new(size(x))
      real(wp) :: gram(max_memory, max_memory), rhs(max_memory), c(max_memory), pivot, &
         largest
      integer :: m, k, j, i, kept, keep(max_memory)

      m = min(size(dx, 2), max_memory)
      if (used > 0) then
         ! The newest differences in column 1.
         do k = min(used - 1, m - 1), 1, -1
            dx(:, k + 1) = dx(:, k)
            df(:, k + 1) = df(:, k)
         end do
         dx(:, 1) = x - last_x
         df(:, 1) = f - last_f
      end if
      used = min(used + 1, m + 1)
      last_x = x
      last_f = f
      x_new = x + f
      if (used == 1) return
      ! Least squares ΔF c ≈ f by the normal equations (Cholesky, newest column first): a
      ! column whose pivot falls below drop_ratio² of its squared norm depends on the newer
      ! ones and is dropped.
      kept = 0
      do k = 1, used - 1
         keep(kept + 1) = k
         do j = 1, kept + 1
            gram(kept + 1, j) = dot_product(df(:, keep(j)), df(:, k))
         end do
         rhs(kept + 1) = dot_product(df(:, k), f)
         ! Forward elimination of the new row with the kept columns' factor L (L L^T = G).
         do j = 1, kept
            gram(kept + 1, j) = (gram(kept + 1, j) - &
               dot_product(gram(kept + 1, 1:j - 1), gram(j, 1:j - 1)))/gram(j, j)
         end do
         pivot = gram(kept + 1, kept + 1) - sum(gram(kept + 1, 1:kept)**2)
         if (.not. (pivot > drop_ratio**2*dot_product(df(:, k), df(:, k)))) cycle
         gram(kept + 1, kept + 1) = sqrt(pivot)
         kept = kept + 1
      end do
      if (kept == 0) return
      ! L y = rhs, then L^T c = y.
      do i = 1, kept
         c(i) = (rhs(i) - dot_product(gram(i, 1:i - 1), c(1:i - 1)))/gram(i, i)
      end do
      do i = kept, 1, -1
         c(i) = (c(i) - dot_product(gram(i + 1:kept, i), c(i + 1:kept)))/gram(i, i)
      end do
      do j = 1, kept
         x_new = x_new - (dx(:, keep(j)) + df(:, keep(j)))*c(j)
      end do
      largest = 0.0_wp
      do i = 1, size(x)
         largest = max(largest, abs(x_new(i) - x(i)))
      end do
      if (.not. (largest <= max_growth*maxval(abs(f)))) then
         x_new = x + f
         used = 1
      end if
   end subroutine anderson_step

end module shcontact_math_anderson
