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
   !> its norm is dropped (it would only amplify round-off).
   real(wp), parameter :: drop_ratio = 1.0e-8_wp

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
      real(wp) :: q(size(x), size(dx, 2)), r(size(dx, 2), size(dx, 2)), c(size(dx, 2)), &
         qf(size(dx, 2)), norm
      integer :: m, k, j, kept, keep(size(dx, 2))

      m = size(dx, 2)
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
      ! Least squares ΔF c ≈ f by modified Gram–Schmidt, newest column first.
      kept = 0
      do k = 1, used - 1
         q(:, kept + 1) = df(:, k)
         norm = sqrt(sum(df(:, k)**2))
         do j = 1, kept
            r(j, kept + 1) = dot_product(q(:, j), q(:, kept + 1))
            q(:, kept + 1) = q(:, kept + 1) - r(j, kept + 1)*q(:, j)
         end do
         r(kept + 1, kept + 1) = sqrt(sum(q(:, kept + 1)**2))
         if (.not. (r(kept + 1, kept + 1) > drop_ratio*norm)) cycle
         q(:, kept + 1) = q(:, kept + 1)/r(kept + 1, kept + 1)
         kept = kept + 1
         keep(kept) = k
      end do
      if (kept == 0) return
      do j = 1, kept
         qf(j) = dot_product(q(:, j), f)
      end do
      do j = kept, 1, -1
         c(j) = (qf(j) - dot_product(r(j, j + 1:kept), c(j + 1:kept)))/r(j, j)
      end do
      do j = 1, kept
         x_new = x_new - (dx(:, keep(j)) + df(:, keep(j)))*c(j)
      end do
      if (.not. (maxval(abs(x_new - x)) <= max_growth*maxval(abs(f)))) then
         x_new = x + f
         used = 1
      end if
   end subroutine anderson_step

end module shcontact_math_anderson
