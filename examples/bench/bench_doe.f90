!> The seed's design of experiments (physics.md §7 "DOE"): ν_x, ν_y ∈ [0, 2e-3] and
!> φ ∈ [0, 2e-3] rad/mm on a 20 × 20 × 20 grid, one normal patch for all cases. The cases are
!> independent: OpenMP threads share them, each thread with its own copy of the prepared
!> workspace (one allocation per thread, none per case); every case is stored by its index, so
!> the results do not depend on the thread count.
module bench_doe
   use shcontact, only: wp, error_type, creepage_type, march_workspace_type, &
      tangential_patch_type
   use shcontact_tangential_march, only: solve_prepared
   use bench_summary, only: doe_table_type
   implicit none
   private

   public :: doe_creepages, solve_doe, reserve_table

contains

   !> The grid in the order of ../shared/reference/*/doe_*.csv: φ fastest, then ν_y, then ν_x.
   pure function doe_creepages(n_points, top) result(creepages)
      !> Values per creepage.
      integer, intent(in) :: n_points
      !> Largest ν_x, ν_y (dimensionless) and φ (rad/mm).
      real(wp), intent(in) :: top
      type(creepage_type) :: creepages(n_points**3)
      integer :: i, j, l, k

      k = 0
      do i = 1, n_points
         do j = 1, n_points
            do l = 1, n_points
               k = k + 1
               creepages(k) = creepage_type(grid(i), grid(j), grid(l))
            end do
         end do
      end do

   contains

      pure real(wp) function grid(i)
         integer, intent(in) :: i
         grid = top*real(i - 1, wp)/real(n_points - 1, wp)
      end function grid

   end function doe_creepages

   !> Allocate the table for n cases (only when its size differs).
   subroutine reserve_table(table, n)
      type(doe_table_type), intent(inout) :: table
      integer, intent(in) :: n
      if (allocated(table%fx)) then
         if (size(table%fx) == n) return
         deallocate (table%nu_x, table%nu_y, table%phi, table%fx, table%fy, table%mz, &
            table%fx_norm, table%fy_norm, table%coulomb_ratio, table%adhesion_fraction, &
            table%status)
      end if
      allocate (table%nu_x(n), table%nu_y(n), table%phi(n), table%fx(n), table%fy(n), &
         table%mz(n), table%fx_norm(n), table%fy_norm(n), table%coulomb_ratio(n), &
         table%adhesion_fraction(n), table%status(n))
   end subroutine reserve_table

   !> Solve every case on the prepared workspace with n_threads OpenMP threads.
   subroutine solve_doe(prepared, creepages, table, n_threads)
      !> The workspace prepared for the patch (fields off for speed; copied per thread).
      type(march_workspace_type), intent(in) :: prepared
      !> The cases.
      type(creepage_type), intent(in) :: creepages(:)
      !> One row per case (reserved with [[reserve_table]]).
      type(doe_table_type), intent(inout) :: table
      !> Threads.
      integer, intent(in) :: n_threads
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(error_type), allocatable :: error
      integer :: k, n

      n = size(creepages)
      !$omp parallel num_threads(n_threads) default(none) &
      !$omp shared(prepared, creepages, table, n) private(ws, result, error, k)
      ws = prepared
      !$omp do schedule(static)
      do k = 1, n
         call solve_prepared(ws, creepages(k), result, error)
         table%nu_x(k) = creepages(k)%nu_x
         table%nu_y(k) = creepages(k)%nu_y
         table%phi(k) = creepages(k)%phi
         if (allocated(error)) then
            table%status(k) = error%stat
            result%fx = 0.0_wp
            result%fy = 0.0_wp
            result%mz = 0.0_wp
            result%fx_norm = 0.0_wp
            result%fy_norm = 0.0_wp
            result%coulomb_ratio = 0.0_wp
            result%adhesion_fraction = 0.0_wp
         else
            table%status(k) = 0
         end if
         table%fx(k) = result%fx
         table%fy(k) = result%fy
         table%mz(k) = result%mz
         table%fx_norm(k) = result%fx_norm
         table%fy_norm(k) = result%fy_norm
         table%coulomb_ratio(k) = result%coulomb_ratio
         table%adhesion_fraction(k) = result%adhesion_fraction
      end do
      !$omp end do
      !$omp end parallel
   end subroutine solve_doe

end module bench_doe
