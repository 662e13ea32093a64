!> A design of experiments at the library level: one normal patch, one prepared FASTSIM_SH
!> workspace, only the creepages vary. The cases are independent: OpenMP threads share them,
!> each thread with its own copy of the prepared workspace (one allocation per thread, none per
!> case); every case is stored by its index, so the results do not depend on the thread count.
!> This is the hardware's share of the seed's DOE; the app's sweep driver (run_sweep) adds the
!> case bookkeeping and the HDF5 file.
module bench_doe
   use shcontact, only: wp, error_type, creepage_type, march_workspace_type, &
      tangential_patch_type
   use shcontact_tangential_march, only: solve_prepared
   implicit none
   private

   public :: doe_table_type, solve_doe, reserve_table

   !> The results, one entry per case. Forces on the wheel (N, N·mm).
   type :: doe_table_type
      real(wp), allocatable :: nu_x(:), nu_y(:), phi(:)
      real(wp), allocatable :: fx(:), fy(:), mz(:), fx_norm(:), fy_norm(:)
      real(wp), allocatable :: coulomb_ratio(:), adhesion_fraction(:)
      !> Library status per case (0: solved).
      integer, allocatable :: status(:)
   end type doe_table_type

contains

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
      ! Dynamic: the cost of a case depends on its creepages (full slip or not), and a static
      ! split of the ordered grid gives one thread the dearer half.
      !$omp do schedule(dynamic, 16)
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
