!> The sweep driver: every case of a run (one case, a grid or a list), solved in blocks by
!> OpenMP threads, checkpointed after each block, assembled into one HDF5 file.
!>
!> * **Determinism.** Each case is solved by one thread, from its own inputs only, and stored by
!>   its index: the results are bitwise identical for any number of threads and any block size.
!> * **Shared stages.** Geometry is computed once per distinct (t_y, roll) and the normal
!>   solution once per distinct (t_y, roll, load) of a block; a sweep over creepages, friction,
!>   bound or spin model solves the tangential problem only. Kinematic cases are solved by one
!>   library solver object per thread, which reuses the geometry and normal solution of
!>   consecutive cases that share them (shcontact_case_runner).
!> * **Checkpoints.** Next to the output OUT.h5 a directory OUT.h5.partial/ receives one
!>   complete result file per checkpoint block (written under a temporary name, renamed when
!>   complete) and a list of them, `blocks.txt`: with `checkpoint_cases` one per that many
!>   cases; automatically (the default) the solved cases are held in memory and written as one
!>   block after about 5 s of solving or when they fill half of `block_bytes`, and a run that
!>   never wrote a block (a short one) writes OUT.h5 straight from memory, the same file. A
!>   run that is killed keeps every written
!>   block readable; `resume` solves only the missing cases. At the end the blocks are merged
!>   into OUT.h5 (again through a temporary name) and the directory is removed, so a failed
!>   or interrupted run never leaves a partial file under the final name. The directory is
!>   made by the run (mkdir, atomic) and locked (flock on OUT.h5.partial/lock) while it is
!>   used: a second run with the same output is refused, an existing directory is only taken
!>   over with `resume` or `force`, and a symbolic link is never followed.
!> * **Overlap.** While the threads solve a block, the first thread writes the checkpoint
!>   block due (shcontact_batch_checkpoint) and then joins them.
!> * **Memory.** The blocks held, the block being solved and the block being written hold at
!>   most `block_bytes` of results (element fields, strip tables, stages) together: a block is
!>   the smaller of what takes about 0.5 s (or `checkpoint_cases`) and what fits in half the
!>   budget at the largest size per case seen so far (shcontact_case_memory; a stage that all
!>   cases of a block share counts once), the held blocks are written before they and the next
!>   block would pass half the budget, so a sweep that stores
!>   the fields runs in bounded memory whatever its length and thread count. A result keeps
!>   only what the file stores (the shared geometry and unstored strip tables are dropped as
!>   soon as the case is solved).
!> * **Shards.** Shard I of N solves the contiguous slice of cases
!>   ((I−1)·n/N, I·n/N] and writes OUT-shardIofN.h5; merging the N files gives the file of the
!>   unsharded run.
module shcontact_batch_sweep
   !$ use omp_lib, only: omp_get_max_threads
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_invalid_input, &
      stat_io, stat_usage
   use shcontact_input_config, only: case_config_type, config_namelist, with_absolute_profiles, &
      read_config_text
   use shcontact_output_results, only: run_info_type, begin_run_file, end_run_file, &
      end_summary_file, check_output_file, case_groups
   use shcontact_output_merge, only: merge_result_files, read_result_summary, &
      compare_finished_run, missing_summary_column
   use shcontact_core_files, only: file_exists, path_kind, open_work_folder, &
      peak_memory_kib, unlock_file, folder_made, folder_existing, folder_busy, folder_unlocked, &
      folder_not_writable, &
      folder_link, folder_not_directory
   use shcontact_output_clock, only: iso_timestamp, wall_seconds
   use shcontact_output_hdf5, only: h5_discard
   use shcontact_output_xdmf, only: write_xdmf_sidecar, xdmf_name
   use shcontact_core_strings, only: str_int, to_lower
   use shcontact_core_text, only: string_list_type, string_type
   use shcontact_case_result, only: case_result_type, case_summary_type, failure_type, case_not_run
   use shcontact_case_runner, only: run_setup_type, prepare_run, solve_geometry, &
      case_workspace_type, kinematic_state
   use shcontact_case_memory, only: estimated_result_bytes
   use shcontact_core_fingerprint, only: fingerprint
   use shcontact_batch_checkpoint, only: merged_temp_name, key_name, lock_name, commit_block, &
      read_manifest, write_text_file, read_text_file, clear_checkpoint
   use shcontact_batch_sweep_types, only: sweep_options_type, sweep_outcome_type, &
      progress_interface, max_threads, default_block_bytes
   use shcontact_batch_block, only: geometry_set_type, stage_cache_type, pending_block_type, &
      early_output_type, thread_solutions_type, solve_block, held_capacity, grow_held
   implicit none
   private

   public :: sweep_options_type, sweep_outcome_type, progress_interface, run_sweep
   public :: shard_range, shard_output_name, checkpoint_directory, max_threads
   public :: default_block_bytes

   !> Automatic checkpoints: the solved blocks held in memory are written as one block file
   !> after about this many seconds of solving (blocks are solved a tenth of it at a time).
   real(wp), parameter :: block_seconds = 5.0_wp

contains

   !> Cases ((shard−1)·n/N, shard·n/N] of a run of n cases split in N shards.
   pure subroutine shard_range(n_cases, shard, n_shards, first, last)
      !> Cases of the run.
      integer, intent(in) :: n_cases
      !> Shard index (1-based) and number of shards.
      integer, intent(in) :: shard, n_shards
      !> First and last case of the shard (last < first when it is empty).
      integer, intent(out) :: first, last
      first = int(int(shard - 1, kind=8)*n_cases/n_shards) + 1
      last = int(int(shard, kind=8)*n_cases/n_shards)
   end subroutine shard_range

   !> OUT.h5 → OUT-shardIofN.h5 (the extension kept), unchanged for one shard.
   pure function shard_output_name(file, shard, n_shards) result(name)
      !> Output file of the run.
      character(len=*), intent(in) :: file
      !> Shard index and number of shards.
      integer, intent(in) :: shard, n_shards
      character(len=:), allocatable :: name
      character(len=:), allocatable :: tag
      integer :: dot, slash
      name = trim(file)
      if (n_shards <= 1) return
      tag = '-shard'//str_int(shard)//'of'//str_int(n_shards)
      dot = index(name, '.', back=.true.)
      slash = index(name, '/', back=.true.)
      if (dot > slash + 1) then
         name = name(1:dot - 1)//tag//name(dot:)
      else
         name = name//tag
      end if
   end function shard_output_name

   !> The checkpoint directory of an output file.
   pure function checkpoint_directory(output) result(dir)
      !> The output file.
      character(len=*), intent(in) :: output
      character(len=:), allocatable :: dir
      dir = trim(output)//'.partial'
   end function checkpoint_directory

   !> Run every case of the shard and write the output file.
   !>
   !> Returns an error (and leaves no output) when the run cannot start (profiles, output
   !> directory, checkpoint of another configuration) or when every case failed; when only
   !> some cases fail the file is written and `outcome%failures` lists them.
   subroutine run_sweep(config, options, outcome, error)
      !> The validated configuration.
      type(case_config_type), intent(in) :: config
      !> Threads, shard, resume, progress.
      type(sweep_options_type), intent(in) :: options
      !> What was done.
      type(sweep_outcome_type), intent(out) :: outcome
      !> Set when the run failed as a whole.
      type(error_type), allocatable, intent(out) :: error

      type(run_setup_type) :: setup
      type(run_info_type) :: info
      type(geometry_set_type) :: common
      character(len=:), allocatable :: dir
      logical :: common_geometry, fields
      integer :: n, lock, state

      n = config%n_cases()
      outcome%n_cases = n
      if (options%n_shards < 1 .or. options%shard < 1 .or. options%shard > options%n_shards) then
         call fatal_error(error, 'shard '//str_int(options%shard)//'/'// &
            str_int(options%n_shards)//': expected 1 <= I <= N', stat_usage)
         return
      end if
      call shard_range(n, options%shard, options%n_shards, outcome%first, outcome%last)
      ! Refused for every shard, not only the empty ones, so that an array job either runs
      ! as a whole or not at all.
      if (options%n_shards > n) then
         call fatal_error(error, 'shard '//str_int(options%shard)//'/'// &
            str_int(options%n_shards)//': a run of '//str_int(n)// &
            ' cases has fewer cases than shards (some shards would be empty); use at most '// &
            str_int(n)//' shards', stat_usage)
         return
      end if
      outcome%output = shard_output_name(config%output%file, options%shard, options%n_shards)
      dir = checkpoint_directory(outcome%output)
      allocate (outcome%summaries(outcome%first:outcome%last), outcome%failures(0))
      outcome%n_threads = 1
      !$ outcome%n_threads = omp_get_max_threads()
      if (options%threads > 0) outcome%n_threads = options%threads
      if (outcome%n_threads > max_threads) then
         call fatal_error(error, str_int(outcome%n_threads)//' threads asked (--threads or '// &
            'OMP_NUM_THREADS); at most '//str_int(max_threads)//' are allowed', stat_usage)
         return
      end if
      fields = config%wants_field('geometry') .or. config%wants_field('strips') .or. &
         config%wants_field('pressure') .or. config%wants_field('traction') .or. &
         config%wants_field('state') .or. config%wants_field('slip')

      if (.not. options%write_output) outcome%output = ''
      ! Everything that can fail before any file is touched.
      if (options%write_output) then
         call check_output_file(outcome%output, error, inputs=run_inputs(config, options), &
            force=options%force)
         if (allocated(error)) return
         ! The work folder's name, refused early (open_work_folder checks again).
         select case (path_kind(dir))
         case ('none', 'directory')
         case ('link')
            call work_folder_error(folder_link, outcome%output, dir, error)
            return
         case default
            call work_folder_error(folder_not_directory, outcome%output, dir, error)
            return
         end select
      end if
      call prepare_run(config, setup, error)
      if (allocated(error)) return
      ! A case file that reproduces the run wherever it is saved: profiles by absolute paths.
      info%namelist = config_namelist(with_absolute_profiles(config))
      info%command_line = 'shcontact'
      if (allocated(options%command_line)) info%command_line = options%command_line
      info%date = iso_timestamp()
      info%n_cases = n
      ! The threads the run solves with (--threads, else OMP_NUM_THREADS), for the file's
      ! provenance.
      info%threads = outcome%n_threads
      info%shard = ''
      if (options%n_shards > 1) info%shard = str_int(options%shard)//'/'// &
         str_int(options%n_shards)
      info%profiles = [setup%wheel, setup%rail]
      if (options%write_output .and. options%resume .and. .not. options%force .and. &
         path_kind(dir) == 'none' .and. path_kind(outcome%output) == 'file') then
         ! Nothing to resume from: the output of a finished run of this configuration is
         ! taken as it is (a requeued array task); another run's is not replaced (--force
         ! replaces it: a run afresh).
         call take_finished_run(outcome, info, error)
         return
      end if
      common_geometry = .not. config%geometry_swept()
      if (common_geometry) then
         if (setup%kinematic) then
            call setup%solver%locate_kinematic(kinematic_state(config%case_point(outcome%first)), &
               common%patches, error)
         else
            call solve_geometry(setup, config%case_point(outcome%first), common%patches, error)
         end if
         if (allocated(error)) then
            ! The geometry every case shares cannot be found: each case then looks for it
            ! itself and fails for this reason, as a case of a swept geometry does (its line
            ! and /failures say why; a shard whose cases all fail still writes its file).
            deallocate (error)
            common_geometry = .false.
         else
            info%geometry = common%patches
         end if
      end if

      if (.not. options%write_output) then
         call sweep_in_folder(config, options, setup, info, common_geometry, common, fields, &
            '', outcome, error)
         return
      end if
      call open_work_folder(dir, lock_name, options%resume .or. options%force, lock, state)
      if (state /= folder_made .and. state /= folder_existing) then
         call work_folder_error(state, outcome%output, dir, error)
         return
      end if
      call sweep_in_folder(config, options, setup, info, common_geometry, common, fields, &
         dir, outcome, error)
      call unlock_file(lock)
   end subroutine run_sweep

   !> `--resume` where the output exists and there is no checkpoint: when the output holds
   !> this run, finished, its summaries and failures are the outcome (nothing is solved or
   !> written); otherwise an error (status 2) rather than solving it again over that file.
   subroutine take_finished_run(outcome, info, error)
      type(sweep_outcome_type), intent(inout) :: outcome
      type(run_info_type), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: difference, messages(:)
      integer, allocatable :: failed(:)
      logical :: same
      integer :: k
      call compare_finished_run(outcome%output, info%namelist, info%profiles, &
         outcome%n_cases, outcome%first, outcome%last, same, difference, outcome%summaries, &
         failed, messages, error)
      if (allocated(error)) then
         call prefix_error(error, 'cannot resume: "'//outcome%output//'" has no checkpoint ("'// &
            checkpoint_directory(outcome%output)//'")')
         return
      end if
      if (.not. same) then
         call fatal_error(error, 'cannot resume: "'//outcome%output//'" has no checkpoint ("'// &
            checkpoint_directory(outcome%output)//'") and holds another run ('//difference// &
            '); run without --resume to solve this one and replace it', stat_invalid_input)
         return
      end if
      deallocate (outcome%failures)
      allocate (outcome%failures(size(failed)))
      do k = 1, size(failed)
         outcome%failures(k)%case = failed(k)
         outcome%failures(k)%message = trim(messages(k))
      end do
      outcome%finished_before = .true.
      ! A sidecar removed since (by hand, or by a run killed between its two last steps) is
      ! written again; the results file itself is not touched.
      if (.not. file_exists(xdmf_name(outcome%output))) call write_xdmf_sidecar( &
         outcome%output, [(k, k=outcome%first, outcome%last)], case_groups([(k, &
         k=outcome%first, outcome%last)], outcome%n_cases), error)
   end subroutine take_finished_run

   !> The files a run reads: the options' inputs (the case file) and the profile files of the
   !> configuration (not the built-in profiles).
   function run_inputs(config, options) result(inputs)
      type(case_config_type), intent(in) :: config
      type(sweep_options_type), intent(in) :: options
      type(string_type), allocatable :: inputs(:)
      integer :: n, k
      n = 0
      if (allocated(options%inputs)) n = size(options%inputs)
      allocate (inputs(n + 2))
      do k = 1, n
         inputs(k)%text = options%inputs(k)%text
      end do
      ! (Elementwise: gfortran 12 garbles string_type(trim(...)) in an array constructor.)
      inputs(n + 1)%text = profile_file(config%profiles%wheel)
      inputs(n + 2)%text = profile_file(config%profiles%rail)
   end function run_inputs

   !> A profile's file name, or '' for a built-in profile.
   pure function profile_file(name) result(file)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: file
      file = trim(name)
      if (index(to_lower(file), 'builtin:') == 1) file = ''
   end function profile_file

   !> The message for a work folder that cannot be used.
   subroutine work_folder_error(state, output, dir, error)
      integer, intent(in) :: state
      character(len=*), intent(in) :: output, dir
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: why
      select case (state)
      case (folder_busy)
         call fatal_error(error, 'another run is writing "'//output//'" (its work folder "'// &
            dir//'" is locked); wait for it to finish or choose another output name', stat_io)
         return
      case (folder_unlocked)
         why = 'exists (the checkpoint of an interrupted run?); continue it with --resume, '// &
            'or start afresh with --force or after removing it'
      case (folder_link)
         why = 'is a symbolic link, which shcontact does not follow for its work folder; '// &
            'remove it'
      case (folder_not_directory)
         why = 'exists and is not a directory; remove it or choose another output name'
      case (folder_not_writable)
         why = 'exists, and its lock file can be neither opened nor created (another '// &
            'user''s folder, or not writable?): remove it yourself, or choose another output name'
      case default
         why = 'cannot be created (does its parent exist, and is it writable?)'
      end select
      call fatal_error(error, 'cannot write the output "'//output//'": its work folder "'// &
         dir//'" '//why, stat_io)
   end subroutine work_folder_error

   !> Solve the cases in the (locked) work folder `dir` and merge them into the output (with
   !> `--no-output`, dir is '' and nothing is written).
   subroutine sweep_in_folder(config, options, setup, info, common_geometry, common, fields, &
                              dir, outcome, error)
      type(case_config_type), intent(in) :: config
      type(sweep_options_type), intent(in) :: options
      type(run_setup_type), intent(inout) :: setup
      type(run_info_type), intent(inout) :: info
      logical, intent(in) :: common_geometry, fields
      type(geometry_set_type), intent(in) :: common
      character(len=*), intent(in) :: dir
      type(sweep_outcome_type), intent(inout) :: outcome
      type(error_type), allocatable, intent(out) :: error
      type(case_workspace_type), allocatable :: workspaces(:)
      type(thread_solutions_type), allocatable :: solutions(:)
      type(string_list_type) :: blocks
      type(stage_cache_type) :: cache
      type(pending_block_type) :: pending, held
      type(early_output_type) :: early
      integer, allocatable :: todo(:)
      integer :: n, n_done, next, block, nb, i, capacity
      integer(int64) :: block_used, per_case_bytes, fixed_bytes, held_bytes
      logical :: keep_geometry, keep_strips, automatic
      real(wp) :: t0, per_case, per_block, held_seconds

      n = outcome%n_cases
      if (.not. options%write_output) then
         blocks%n = 0
      else if (options%resume) then
         ! The blocks of a resumed run carry the namelist of the run that started it (which may
         ! differ in the output name or the spelling of the profile paths).
         call read_checkpoint(dir, checkpoint_key(config, setup), config%is_kinematic(), &
            info%namelist, n, outcome, &
            blocks, error)
         if (allocated(error)) return
      else
         ! A new folder, or one taken over with --force: shcontact's own files only go.
         call clear_checkpoint(dir, keep_directory=.true.)
         blocks%n = 0
         call write_text_file(dir//'/'//key_name, checkpoint_key(config, setup), error)
         if (allocated(error)) return
      end if

      todo = pack([(i, i=outcome%first, outcome%last)], &
         outcome%summaries%stat == case_not_run)
      n_done = (outcome%last - outcome%first + 1) - size(todo)
      ! The first report: the cases taken from a checkpoint (the caller's rate leaves them out).
      if (associated(options%progress)) call options%progress(n_done, &
         outcome%last - outcome%first + 1, .false.)
      allocate (workspaces(outcome%n_threads), solutions(outcome%n_threads))
      if (setup%kinematic) then
         do i = 1, outcome%n_threads
            solutions(i)%solver = setup%solver
         end do
      end if
      ! A result keeps what the file stores: per-case geometry only when it varies.
      keep_geometry = config%wants_field('geometry') .and. .not. common_geometry
      keep_strips = config%wants_field('strips')
      per_case_bytes = 0
      fixed_bytes = 0
      held_bytes = 0
      held_seconds = 0.0_wp
      per_case = 0.0_wp
      ! Automatic checkpoints: the solved blocks are held in memory and written as one block
      ! file only when they took block_seconds or fill half the memory budget; a run that never
      ! needed one writes its output straight from memory.
      automatic = config%output%checkpoint_cases <= 0
      next = 1
      block = max(16, 4*outcome%n_threads)
      if (config%output%checkpoint_cases > 0) block = config%output%checkpoint_cases
      ! Until the size of a result is measured, a run with fields sizes its first block by an
      ! estimate from the grid.
      if (fields) block = int(min(int(block, int64), max(int(outcome%n_threads, int64), &
         options%block_bytes/(2*estimated_result_bytes(config)))))
      do while (next <= size(todo))
         nb = min(block, size(todo) - next + 1)
         ! The held blocks are written while this block is solved when they took block_seconds
         ! or when they, this block and the one being written would pass block_bytes.
         if (options%write_output .and. held%n > 0 .and. (.not. automatic .or. &
             held_seconds >= block_seconds .or. &
             2*(held_bytes + fixed_bytes + nb*per_case_bytes) > options%block_bytes)) then
            call move_alloc(held%cases, pending%cases)
            call move_alloc(held%results, pending%results)
            pending%n = held%n
            pending%waiting = .true.
            held%n = 0
            held_bytes = 0
            held_seconds = 0.0_wp
         end if
         if (.not. options%write_output .and. allocated(held%results)) then
            ! Nothing is held without output: fresh slots for every block.
            held%n = 0
            deallocate (held%results, held%cases)
         end if
         if (held%n + nb > held_capacity(held)) then
            ! Arrays for the blocks to be held: this block, or with automatic checkpoints as
            ! many cases as about block_seconds of solving and half the budget allow.
            capacity = held%n + nb
            if (automatic .and. options%write_output .and. per_case > 0.0_wp) capacity = &
               int(max(int(capacity, int64), min(int(held%n + size(todo) - next + 1, int64), &
               int(min(1.0e9_wp, 1.25_wp*block_seconds/per_case), int64), &
               max(0_int64, options%block_bytes/2 - fixed_bytes)/per_case_bytes)))
            call grow_held(held, capacity)
         end if
         ! The last block of a run that has written no block file: its output will be written
         ! from memory, and its header can be written meanwhile.
         ! So can that of a run without fields, whose summaries are all held in memory
         ! (outcome%summaries): its block files are only its checkpoint, never read back.
         early%wanted = options%write_output .and. next + nb - 1 == size(todo) .and. &
            ((blocks%n == 0 .and. .not. pending%waiting) .or. .not. fields)
         if (early%wanted) then
            early%output = outcome%output
            early%temp_name = dir//'/'//merged_temp_name
            early%cases_in_file = outcome%last - outcome%first + 1
            early%force = options%force
         end if
         t0 = wall_seconds()
         ! The cases are solved into their slots of the held arrays; the previous blocks' file
         ! is written by the first thread meanwhile.
         call solve_block(setup, config, common_geometry, common, todo(next:next + nb - 1), &
            held%results(held%n + 1:held%n + nb), workspaces, solutions, fields, &
            outcome%n_threads, options, n_done, outcome%last - outcome%first + 1, &
            keep_geometry, keep_strips, cache, block_used, fixed_bytes, pending, early, dir, &
            blocks, info, error)
         if (allocated(error)) return
         per_case = (wall_seconds() - t0)/nb
         held_seconds = held_seconds + per_case*nb
         held_bytes = held_bytes + block_used
         held%cases(held%n + 1:held%n + nb) = todo(next:next + nb - 1)
         ! The largest share of a case seen so far (its fields and its stage's).
         per_case_bytes = max(per_case_bytes, block_used/nb + 1)
         outcome%most_block_bytes = max(outcome%most_block_bytes, block_used + fixed_bytes)
         outcome%most_block_cases = max(outcome%most_block_cases, nb)
         if (pending%waiting) then
            pending%waiting = .false.
            deallocate (pending%results, pending%cases)
            if (associated(options%progress)) call options%progress(n_done, &
               outcome%last - outcome%first + 1, .true.)
         end if
         !$omp parallel do default(none) schedule(static) num_threads(outcome%n_threads) &
         !$omp shared(outcome, held, nb) private(i)
         do i = held%n + 1, held%n + nb
            outcome%summaries(held%cases(i)) = held%results(i)%summary
         end do
         !$omp end parallel do
         do i = held%n + 1, held%n + nb
            if (held%results(i)%summary%stat > 0) call add_failure(outcome%failures, &
               held%cases(i), message_of(held%results(i)))
         end do
         held%n = held%n + nb
         n_done = n_done + nb
         if (.not. options%write_output .and. associated(options%progress)) then
            call options%progress(n_done, outcome%last - outcome%first + 1, .true.)
         else if (associated(options%progress)) then
            ! The first thread reports as it solves; while it wrote a block file or the output's
            ! header the others' cases went unreported: a report for the whole block.
            call options%progress(n_done, outcome%last - outcome%first + 1, .false.)
         end if
         next = next + nb
         if (config%output%checkpoint_cases > 0) then
            block = config%output%checkpoint_cases
         else if (per_case > 0.0_wp) then
            ! A tenth of block_seconds per block: the held blocks are written after about
            ! block_seconds, while the next block is solved.
            per_block = 0.1_wp*block_seconds/per_case
            block = int(min(1.0e6_wp, max(real(4*outcome%n_threads, wp), per_block)))
         end if
         ! The block being solved and the one being written together within block_bytes.
         block = int(min(int(block, int64), max(int(outcome%n_threads, int64), &
            max(0_int64, options%block_bytes - 2*fixed_bytes)/(2*per_case_bytes))))
      end do
      if (pending%waiting) then
         call commit_block(dir, blocks, info, config, pending%cases(1:pending%n), &
            pending%results(1:pending%n), error)
         if (allocated(error)) return
         deallocate (pending%results)
         if (associated(options%progress)) call options%progress(n_done, &
            outcome%last - outcome%first + 1, .true.)
      end if
      if (held%n > 0 .and. blocks%n > 0) then
         ! The last held blocks: a block file where the output is merged from them (a run
         ! with fields); without fields the output is written from memory next.
         if (fields) then
            call commit_block(dir, blocks, info, config, held%cases(1:held%n), &
               held%results(1:held%n), error)
            if (allocated(error)) return
            held%n = 0
         end if
         if (associated(options%progress)) call options%progress(n_done, &
            outcome%last - outcome%first + 1, fields)
      end if

      if (size(outcome%failures) == outcome%last - outcome%first + 1 .and. &
         (options%n_shards == 1 .or. .not. options%write_output)) then
         ! Nothing to write: every case failed, and they all tell why. (A shard whose cases
         ! all failed still writes its file, with /failures, so that the shards merge into
         ! the file of the whole run.)
         if (early%begun .and. .not. allocated(early%error)) call h5_discard(early%file)
         call fatal_error(error, failure_text(outcome, outcome%failures(1)), &
            outcome%summaries(outcome%failures(1)%case)%stat)
         if (options%write_output) call clear_checkpoint(dir, keep_directory=.false.)
         return
      end if
      outcome%solving_peak_kib = peak_memory_kib()
      if (.not. options%write_output) return
      outcome%checkpoint_files = blocks%n
      if ((held%n > 0 .and. blocks%n == 0) .or. (.not. fields .and. blocks%n > 0)) then
         if (.not. early%begun) call begin_run_file(early%file, outcome%output, info, config, &
            outcome%last - outcome%first + 1, early%error, dir//'/'//merged_temp_name, &
            options%force)
         if (allocated(early%error)) then
            call move_alloc(early%error, error)
            return
         end if
         if (blocks%n == 0) then
            ! Every case in memory, no block file written: the output straight from the
            ! results.
            call end_run_file(early%file, info, config, held%cases(1:held%n), &
               held%results(1:held%n), error)
         else
            ! No fields: the output from the run's summaries (the block files were its
            ! checkpoint; the last held block was not written as one).
            call end_summary_file(early%file, info, config, [(i, i=outcome%first, &
               outcome%last)], outcome%summaries, outcome%failures, error)
         end if
      else
         outcome%block_files = blocks%n
         call merge_result_files(outcome%output, blocks%items(1:blocks%n), info%command_line, &
            info%date, error, allow_partial=options%n_shards > 1, shard=info%shard, &
            temp_name=dir//'/'//merged_temp_name, threads=info%threads, force=options%force)
      end if
      if (allocated(error)) then
         ! Without a block file there is nothing to resume from: no work folder is left.
         if (blocks%n == 0) call clear_checkpoint(dir, keep_directory=.false.)
         return
      end if
      call clear_checkpoint(dir, keep_directory=.false.)
   end subroutine sweep_in_folder

   !> "case i: message" (just the message for a one-case run).
   function failure_text(outcome, failure) result(text)
      type(sweep_outcome_type), intent(in) :: outcome
      type(failure_type), intent(in) :: failure
      character(len=:), allocatable :: text
      text = failure%message
      if (outcome%n_cases > 1) text = 'case '//str_int(failure%case)//': '//text
   end function failure_text

   subroutine add_failure(failures, icase, message)
      type(failure_type), allocatable, intent(inout) :: failures(:)
      integer, intent(in) :: icase
      character(len=*), intent(in) :: message
      type(failure_type) :: f
      f%case = icase
      f%message = message
      failures = [failures, f]
   end subroutine add_failure

   function message_of(result) result(message)
      type(case_result_type), intent(in) :: result
      character(len=:), allocatable :: message
      message = 'failed'
      if (allocated(result%message)) message = result%message
   end function message_of

   ! ------------------------------------------------------------------------------------------
   ! Checkpoints
   ! ------------------------------------------------------------------------------------------

   !> Take the finished cases from the checkpoint of an interrupted run of this configuration.
   subroutine read_checkpoint(dir, key, kinematic, namelist, n_cases, outcome, blocks, error)
      character(len=*), intent(in) :: dir, key
      !> The run is kinematic (which /summary columns its blocks must hold).
      logical, intent(in) :: kinematic
      !> This run's namelist; on return that of the checkpoint's blocks.
      character(len=:), allocatable, intent(inout) :: namelist
      integer, intent(in) :: n_cases
      type(sweep_outcome_type), intent(inout) :: outcome
      type(string_list_type), intent(out) :: blocks
      type(error_type), allocatable, intent(out) :: error
      type(string_list_type) :: listed
      character(len=:), allocatable :: text, messages(:)
      integer, allocatable :: indices(:), failed(:)
      type(case_summary_type), allocatable :: summaries(:)
      integer :: b, i, n, j
      logical :: has_key
      character(len=:), allocatable :: original, missing

      call read_manifest(dir, listed)
      blocks%n = 0
      ! A checkpoint of this version names its configuration independently of the working
      ! directory; an older one only by the namelist of its blocks.
      has_key = file_exists(dir//'/'//key_name)
      if (has_key) then
         if (.not. same_key(read_text_file(dir//'/'//key_name), key)) then
            call another_configuration(dir, error)
            return
         end if
      end if
      do b = 1, listed%n
         if (.not. file_exists(listed%items(b)%text)) cycle
         call read_result_summary(listed%items(b)%text, text, n, indices, summaries, failed, &
            messages, error)
         if (allocated(error)) then
            call prefix_error(error, 'cannot resume from the checkpoint in "'//dir//'"')
            return
         end if
         if ((.not. has_key .and. text /= namelist) .or. n /= n_cases) then
            call another_configuration(dir, error)
            return
         end if
         ! A block of an older version lacks newer /summary columns (they would read as 0 in
         ! the merged file): refused now, not after solving the rest.
         call missing_summary_column(listed%items(b)%text, kinematic, missing, error)
         if (allocated(error)) return
         if (len(missing) > 0) then
            call fatal_error(error, 'cannot resume: the checkpoint in "'//dir//'" was made '// &
               'by an older version of shcontact (its blocks have no /summary/'//missing// &
               '); start again with --force (or after removing it)', stat_invalid_input)
            return
         end if
         if (blocks%n == 0) then
            original = text
         else if (text /= original) then
            call another_configuration(dir, error)
            return
         end if
         do i = 1, size(indices)
            if (indices(i) < outcome%first .or. indices(i) > outcome%last) cycle
            outcome%summaries(indices(i)) = summaries(i)
            outcome%n_resumed = outcome%n_resumed + 1
         end do
         do j = 1, size(failed)
            call add_failure(outcome%failures, failed(j), trim_text(messages(j)))
         end do
         call blocks%push(listed%items(b)%text)
      end do
      if (blocks%n > 0) namelist = original
   end subroutine read_checkpoint

   subroutine another_configuration(dir, error)
      character(len=*), intent(in) :: dir
      type(error_type), allocatable, intent(out) :: error
      call fatal_error(error, 'cannot resume: the checkpoint in "'//dir//'" was made with '// &
         'another configuration (or profile files whose points have changed since); start '// &
         'again with --force (or after removing it)', stat_invalid_input)
   end subroutine another_configuration

   !> The configuration as the checkpoint knows it: the resolved namelist without the output
   !> name and with the profile files as absolute paths, so that a run resumed from another
   !> working directory (or with an absolute -o) is recognised.
   function checkpoint_key(config, setup) result(key)
      type(case_config_type), intent(in) :: config
      !> The run's profiles as read: a profile file rewritten under the same name between the
      !> start of a run and its resumption gives another key (its cases are not mixed).
      type(run_setup_type), intent(in) :: setup
      character(len=:), allocatable :: key
      type(case_config_type) :: c
      c = with_absolute_profiles(config, canonical=.true.)
      c%output%file = '-'
      key = config_namelist(c)//'! profiles as read: wheel '// &
         fingerprint([setup%wheel%y, setup%wheel%z])//', rail '// &
         fingerprint([setup%rail%y, setup%rail%z])//new_line('a')
   end function checkpoint_key

   !> Whether the key a checkpoint stored names this run ([[checkpoint_key]]): the same text, or
   !> the same configuration in another version's writing of its numbers (8.2 was written
   !> 8.199999999999999 before stop 49), compared after reading its namelist again.
   logical function same_key(stored, key)
      character(len=*), intent(in) :: stored, key
      character(len=*), parameter :: mark = '! profiles as read:'
      type(case_config_type) :: c
      type(error_type), allocatable :: error
      integer :: k
      same_key = stored == key
      if (same_key) return
      k = index(stored, mark, back=.true.)
      if (k == 0) return
      call read_config_text(stored(1:k - 1), 'the checkpoint''s configuration', c, error)
      if (allocated(error)) return
      c%output%file = '-'
      same_key = config_namelist(c)//stored(k:) == key
   end function same_key

   function trim_text(text) result(t)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: t
      t = trim(text)
   end function trim_text

end module shcontact_batch_sweep
