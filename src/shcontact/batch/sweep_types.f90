!> What a sweep is asked to do and what it did (shcontact_batch_sweep's options and outcome),
!> and the progress callback it calls.
module shcontact_batch_sweep_types
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact_core_text, only: string_type
   use shcontact_case_result, only: case_summary_type, failure_type
   implicit none
   private

   public :: sweep_options_type, sweep_outcome_type, progress_interface, max_threads, &
      default_block_bytes

   !> Default of [[sweep_options_type]]%block_bytes: 64 MiB.
   integer(int64), parameter :: default_block_bytes = 64_int64*1024*1024

   !> Most OpenMP threads of a run (--threads, OMP_NUM_THREADS): each thread holds its own
   !> workspaces, and creating many more threads than cores only costs memory.
   integer, parameter :: max_threads = 1024

   abstract interface
      !> Called with the number of finished cases of the shard (resumed ones included): once
      !> before any case is solved (the cases resumed from a checkpoint), from one thread while
      !> cases are solved (committed = .false.), and after each checkpoint block is written
      !> (committed = .true.).
      subroutine progress_interface(done, total, committed)
         !> Cases finished and cases in the shard.
         integer, intent(in) :: done, total
         !> A checkpoint block has just been written.
         logical, intent(in) :: committed
      end subroutine progress_interface
   end interface

   !> How to run.
   type :: sweep_options_type
      !> Threads (0: the OpenMP default).
      integer :: threads = 0
      !> This shard and the number of shards.
      integer :: shard = 1, n_shards = 1
      !> Continue from the checkpoint of an interrupted run.
      logical :: resume = .false.
      !> Replace an output (and sidecar) that is not shcontact's, and start afresh in the work
      !> folder of an interrupted run (only shcontact's own files in it are removed).
      logical :: force = .false.
      !> Write the result file (and its checkpoints); .false. solves and summarises only
      !> (`--no-output`), and `outcome%output` is then ''.
      logical :: write_output = .true.
      !> Most bytes of per-case results (fields) held in memory at once: the checkpoint block
      !> is cut to fit (at least one case per thread).
      integer(int64) :: block_bytes = default_block_bytes
      !> Recorded in the output file.
      character(len=:), allocatable :: command_line
      !> Files the run reads besides the configuration's profile files (the case file): the
      !> output and its sidecar are never one of them, not even with `force`.
      type(string_type), allocatable :: inputs(:)
      !> Progress report (optional).
      procedure(progress_interface), pointer, nopass :: progress => null()
   end type sweep_options_type

   !> What a run did.
   type :: sweep_outcome_type
      !> The file written.
      character(len=:), allocatable :: output
      !> Cases of the run, and the slice [first, last] of this shard.
      integer :: n_cases = 0, first = 1, last = 0
      !> Summaries of the shard's cases, indexed first:last.
      type(case_summary_type), allocatable :: summaries(:)
      !> The failed cases.
      type(failure_type), allocatable :: failures(:)
      !> Cases taken from the checkpoint, threads used.
      integer :: n_resumed = 0, n_threads = 1
      !> The most bytes of results (fields) and stages one block held, and the most cases a
      !> block had ([[sweep_options_type]]%block_bytes bounds two blocks together).
      integer(int64) :: most_block_bytes = 0
      integer :: most_block_cases = 0
      !> Checkpoint block files the output was assembled from (0: written straight from memory).
      integer :: block_files = 0
      !> Checkpoint block files in the work folder at the end (written by this run or taken
      !> from the checkpoint it resumed); a run without fields writes its output from memory
      !> and does not read them back.
      integer :: checkpoint_files = 0
      !> Peak resident memory of the process (KiB, VmHWM; 0 where unknown) when every case was
      !> solved, before the output was written or merged (whose HDF5 caches grow with the file).
      integer :: solving_peak_kib = 0
      !> `--resume` found the output finished (no checkpoint): nothing was solved or written,
      !> the summaries and failures are the file's.
      logical :: finished_before = .false.
   end type sweep_outcome_type

end module shcontact_batch_sweep_types
