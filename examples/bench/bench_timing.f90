!> Timing of the benchmark: a kernel is any operation with a `run` procedure; [[time_kernel]]
!> calls it in batches long enough for the clock (about `min_batch_time` each), repeats the batch
!> `n_runs` times and reports the median, minimum and maximum time per call.
module bench_timing
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact, only: wp
   use shcontact_math_statistics, only: median
   implicit none
   private

   public :: kernel_type, timing_type, time_kernel, time_side_by_side, wall_time, median_of

   !> An operation to time. `run(k)` performs call number k of a batch (k = 1, 2, ...): a kernel
   !> may vary its input with k. `failed` is set by the kernel when the library reported an error.
   type, abstract :: kernel_type
      logical :: failed = .false.
      !> Fewest calls in a timed batch (a trajectory kernel needs enough calls per batch to
      !> cover the whole trajectory's range in every batch).
      integer :: min_calls = 1
      character(len=:), allocatable :: message
   contains
      procedure(run_interface), deferred :: run
   end type kernel_type

   abstract interface
      subroutine run_interface(self, k)
         import :: kernel_type
         class(kernel_type), intent(inout) :: self
         integer, intent(in) :: k
      end subroutine run_interface
   end interface

   !> Time per call (s): median, minimum and maximum over the runs; calls per run and runs.
   type :: timing_type
      real(wp) :: median = 0.0_wp, min = 0.0_wp, max = 0.0_wp
      integer :: batch = 0, runs = 0
   end type timing_type

contains

   !> Wall-clock time in seconds (monotonic, nanosecond counter).
   function wall_time() result(t)
      real(wp) :: t
      integer(int64) :: count, rate
      call system_clock(count, rate)
      t = real(count, wp)/real(rate, wp)
   end function wall_time

   !> Time a kernel: one warm-up call, a batch size such that one batch lasts about
   !> `min_batch_time` seconds (at least one call), then `n_runs` timed batches.
   function time_kernel(kernel, n_runs, min_batch_time) result(timing)
      !> The operation.
      class(kernel_type), intent(inout) :: kernel
      !> Number of timed batches.
      integer, intent(in) :: n_runs
      !> Target duration of one batch (s).
      real(wp), intent(in) :: min_batch_time
      type(timing_type) :: timing
      real(wp) :: samples(n_runs), t0
      integer :: batch, r, k

      batch = calibrated_batch(kernel, min_batch_time)
      do r = 1, n_runs
         t0 = wall_time()
         do k = 1, batch
            call kernel%run(k)
         end do
         samples(r) = (wall_time() - t0)/batch
      end do
      timing%median = median_of(samples)
      timing%min = minval(samples)
      timing%max = maxval(samples)
      timing%batch = batch
      timing%runs = n_runs
   end function time_kernel

   !> Several kernels timed side by side: each calibrated as by [[time_kernel]], then `n_runs`
   !> rounds, each one batch of every kernel in turn, so that a change of the machine's speed
   !> (another job on a shared machine, a frequency step) reaches them all alike. `ratios` are
   !> the median, minimum and maximum over the rounds of each kernel's time per call over the
   !> last kernel's in the same round.
   subroutine time_side_by_side(kernels, n_runs, min_batch_time, timings, ratios)
      !> The operations (one type: the configurations of one item).
      class(kernel_type), intent(inout) :: kernels(:)
      !> Number of rounds.
      integer, intent(in) :: n_runs
      !> Target duration of one batch (s).
      real(wp), intent(in) :: min_batch_time
      !> The timing of each kernel.
      type(timing_type), intent(out) :: timings(:)
      !> Ratio to the last kernel: median, minimum, maximum over the rounds (3 × kernels).
      real(wp), intent(out) :: ratios(:, :)
      real(wp) :: samples(n_runs, size(kernels)), t0
      integer :: batch(size(kernels)), n, c, r, k

      n = size(kernels)
      do c = 1, n
         batch(c) = calibrated_batch(kernels(c), min_batch_time)
      end do
      do r = 1, n_runs
         do c = 1, n
            t0 = wall_time()
            do k = 1, batch(c)
               call kernels(c)%run(k)
            end do
            samples(r, c) = (wall_time() - t0)/batch(c)
         end do
      end do
      do c = 1, n
         timings(c)%median = median_of(samples(:, c))
         timings(c)%min = minval(samples(:, c))
         timings(c)%max = maxval(samples(:, c))
         timings(c)%batch = batch(c)
         timings(c)%runs = n_runs
         ratios(1, c) = median_of(samples(:, c)/samples(:, n))
         ratios(2, c) = minval(samples(:, c)/samples(:, n))
         ratios(3, c) = maxval(samples(:, c)/samples(:, n))
      end do
   end subroutine time_side_by_side

   !> The batch size for which one batch of the kernel lasts about `min_batch_time` seconds:
   !> one warm-up call, then a short batch (the first call may include page faults and cache
   !> misses).
   integer function calibrated_batch(kernel, min_batch_time) result(batch)
      class(kernel_type), intent(inout) :: kernel
      real(wp), intent(in) :: min_batch_time
      real(wp) :: t0, t_one
      integer :: k
      t0 = wall_time()
      call kernel%run(1)
      t_one = max(wall_time() - t0, 1.0e-8_wp)
      batch = max(1, min(1000000, int(0.1_wp*min_batch_time/t_one)))
      t0 = wall_time()
      do k = 1, batch
         call kernel%run(k)
      end do
      t_one = max((wall_time() - t0)/batch, 1.0e-9_wp)
      batch = max(kernel%min_calls, 1, min(10000000, nint(min_batch_time/t_one)))
   end function calibrated_batch

   !> Median of a sample (the mean of the two middle values for an even count).
   function median_of(samples) result(median_value)
      real(wp), intent(in) :: samples(:)
      real(wp) :: median_value
      median_value = median(samples)
   end function median_of

end module bench_timing
