!> One block of a sweep's cases solved in parallel (shcontact_batch_sweep): the shared
!> geometry and normal stages first, then every case by one thread into its slot, while the
!> first thread writes the checkpoint block due and the output's header; and the blocks held in
!> memory until they are written.
module shcontact_batch_block
   !$ use omp_lib, only: omp_get_thread_num
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact_core_error, only: error_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_input_config, only: case_config_type, axis_geometry, axis_load
   use shcontact_output_results, only: run_info_type, begin_run_file
   use shcontact_output_hdf5, only: h5_file_type
   use shcontact_core_text, only: string_list_type
   use shcontact_case_result, only: case_result_type
   use shcontact_case_runner, only: run_setup_type, stage_type, solve_geometry, solve_stage, &
      solve_case, case_workspace_type, tangential_patch_type, solve_kinematic_case, &
      contact_solver_type
   use shcontact_case_memory, only: keep_stored, result_bytes, stage_bytes
   use shcontact_batch_checkpoint, only: commit_block
   use shcontact_batch_sweep_types, only: sweep_options_type
   implicit none
   private

   public :: geometry_set_type, stage_cache_type, pending_block_type, early_output_type, &
      thread_solutions_type
   public :: solve_block, first_thread_writes, held_capacity, grow_held, move_result

   !> Geometry of one wheelset position (or why there is none).
   type :: geometry_set_type
      integer :: stat = 0
      character(len=:), allocatable :: message
      type(patch_geometry_type), allocatable :: patches(:)
   end type geometry_set_type

   !> The normal stage of the last case of the last block, by its key (the first case of the
   !> run with the same t_y, roll and load): the next block, which in a grid usually starts on
   !> the same stage, takes it instead of solving it again.
   type :: stage_cache_type
      integer :: key = 0
      type(stage_type) :: stage
   end type stage_cache_type

   !> A solved block whose checkpoint file is still to be written: the first thread writes it
   !> while the others solve the next block.
   !> Also the blocks held in memory until they are written (automatic checkpoints).
   type :: pending_block_type
      logical :: waiting = .false.
      !> The cases and their results (the first n of the arrays).
      integer :: n = 0
      integer, allocatable :: cases(:)
      type(case_result_type), allocatable :: results(:)
   end type pending_block_type

   !> The output of a run written from memory, begun by the first thread while the others
   !> solve the last block (its header does not depend on the cases).
   type :: early_output_type
      !> Begin it during the next block.
      logical :: wanted = .false.
      !> Begun: `file` is open (or `error` says why not).
      logical :: begun = .false.
      type(h5_file_type) :: file
      type(error_type), allocatable :: error
      !> The output, its temporary name, the cases it will hold, and --force.
      character(len=:), allocatable :: output, temp_name
      integer :: cases_in_file = 0
      logical :: force = .false.
   end type early_output_type

   !> Per-thread tangential solutions (and solver object of a kinematic run).
   type :: thread_solutions_type
      type(tangential_patch_type), allocatable :: patches(:)
      type(contact_solver_type) :: solver
   end type thread_solutions_type
contains

   !> After a case of a block: keep what the file stores, count it, and report the progress
   !> (from the first thread only, which calls the app's procedure).
   subroutine case_done(result, keep_geometry, keep_strips, done, total, first, options)
      type(case_result_type), intent(inout) :: result
      logical, intent(in) :: keep_geometry, keep_strips
      !> Cases finished in the run (shared by the threads).
      integer, intent(inout) :: done
      integer, intent(in) :: total
      !> The calling thread is the first.
      logical, intent(in) :: first
      type(sweep_options_type), intent(in) :: options
      integer :: report
      call keep_stored(result, keep_geometry, keep_strips)
      !$omp atomic capture
      done = done + 1
      report = done
      !$omp end atomic
      if (first .and. associated(options%progress)) call options%progress(report, total, .false.)
   end subroutine case_done

   !> What the first thread writes while the others solve a block: the checkpoint block due,
   !> and the header of the run's output when it is wanted.
   subroutine first_thread_writes(pending, early, dir, blocks, info, config, write_error)
      type(pending_block_type), intent(in) :: pending
      type(early_output_type), intent(inout) :: early
      character(len=*), intent(in) :: dir
      type(string_list_type), intent(inout) :: blocks
      type(run_info_type), intent(in) :: info
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: write_error
      if (pending%waiting) call commit_block(dir, blocks, info, config, &
         pending%cases(1:pending%n), pending%results(1:pending%n), write_error)
      if (.not. early%wanted .or. early%begun) return
      call begin_run_file(early%file, early%output, info, config, early%cases_in_file, &
         early%error, early%temp_name, early%force)
      early%begun = .true.
   end subroutine first_thread_writes

   !> Room for this many results in the held arrays.
   pure integer function held_capacity(held)
      type(pending_block_type), intent(in) :: held
      held_capacity = 0
      if (allocated(held%results)) held_capacity = size(held%results)
   end function held_capacity

   !> New held arrays of `capacity` (the held results moved to them; the first block of a run,
   !> before its time per case is known, is held in arrays of its own size).
   subroutine grow_held(held, capacity)
      type(pending_block_type), intent(inout) :: held
      integer, intent(in) :: capacity
      type(case_result_type), allocatable :: results(:)
      integer, allocatable :: cases(:)
      integer :: i
      allocate (results(capacity), cases(capacity))
      do i = 1, held%n
         call move_result(held%results(i), results(i))
         cases(i) = held%cases(i)
      end do
      call move_alloc(results, held%results)
      call move_alloc(cases, held%cases)
   end subroutine grow_held

   !> Move a result: `to` receives it, `from` is left empty (its arrays freed at once, so that
   !> a move never holds two copies of the fields).
   subroutine move_result(from, to)
      type(case_result_type), intent(inout) :: from
      type(case_result_type), intent(out) :: to
      type(case_result_type) :: empty
      to = from
      from = empty
   end subroutine move_result

   !> Solve the cases of one block: shared geometry and normal stages first, then every case,
   !> each by one thread.
   subroutine solve_block(setup, config, common_geometry, common, cases, results, workspaces, &
                          solutions, fields, n_threads, options, done_before, total, &
                          keep_geometry, keep_strips, cache, bytes, fixed, pending, early, &
                          dir, blocks, info, write_error)
      type(run_setup_type), intent(in) :: setup
      type(case_config_type), intent(in) :: config
      logical, intent(in) :: common_geometry
      type(geometry_set_type), intent(in) :: common
      integer, intent(in) :: cases(:)
      type(case_result_type), intent(inout) :: results(:)
      type(case_workspace_type), intent(inout) :: workspaces(:)
      type(thread_solutions_type), intent(inout) :: solutions(:)
      logical, intent(in) :: fields
      integer, intent(in) :: n_threads
      type(sweep_options_type), intent(in) :: options
      integer, intent(in) :: done_before, total
      !> Keep the per-case geometry and the strip tables in the results (what the file stores).
      logical, intent(in) :: keep_geometry, keep_strips
      !> The stage of the last case of the previous block; on return that of this block.
      type(stage_cache_type), intent(inout) :: cache
      !> Bytes of the block's results and stages but its largest stage, which is `fixed`: a
      !> block that shares one stage holds its bytes once, whatever its number of cases.
      integer(int64), intent(out) :: bytes
      integer(int64), intent(inout) :: fixed
      !> The previous block, written to `dir` (listed in `blocks`) by the first thread while the
      !> others start on this one, when it is waiting.
      type(pending_block_type), intent(in) :: pending
      !> The run's output, begun by the first thread meanwhile when it is wanted.
      type(early_output_type), intent(inout) :: early
      character(len=*), intent(in) :: dir
      type(string_list_type), intent(inout) :: blocks
      type(run_info_type), intent(in) :: info
      !> Set when the previous block could not be written.
      type(error_type), allocatable, intent(out) :: write_error

      integer, allocatable :: geometry_keys(:), load_keys(:), stage_of(:), geometry_of(:)
      type(geometry_set_type), allocatable :: geometries(:)
      type(stage_type), allocatable :: stages(:)
      type(error_type), allocatable :: error
      logical, allocatable :: cached(:), needed(:)
      integer :: i, k, nb, done, me
      integer(int64) :: largest

      nb = size(cases)
      done = done_before
      if (setup%kinematic) then
         ! Each case through its thread's solver object (shcontact_case_runner).
         !$omp parallel default(none) num_threads(n_threads) &
         !$omp shared(cases, results, solutions, setup, config, fields, options, done, total, &
         !$omp nb, keep_geometry, keep_strips, pending, early, dir, blocks, info, &
         !$omp write_error) private(i, me)
         me = 1
         !$ me = omp_get_thread_num() + 1
         if (me == 1) call first_thread_writes(pending, early, dir, blocks, info, config, &
            write_error)
         !$omp do schedule(dynamic, 4)
         do i = 1, nb
            call solve_kinematic_case(setup, config%case_point(cases(i)), solutions(me)%solver, &
               results(i), fields)
            call case_done(results(i), keep_geometry, keep_strips, done, total, me == 1, &
               options)
         end do
         !$omp end do
         !$omp end parallel
         bytes = sum(result_bytes(results))
         return
      end if
      allocate (stage_of(nb))
      ! Distinct (t_y, roll, load) of the block, each named by its first case of the run.
      allocate (load_keys(nb))
      !$omp parallel do default(none) schedule(static) num_threads(n_threads) &
      !$omp shared(load_keys, config, cases, nb) private(i)
      do i = 1, nb
         load_keys(i) = config%shares_with(cases(i), axis_load)
      end do
      !$omp end parallel do
      call unique_keys(load_keys, stage_of)
      allocate (geometry_of(size(load_keys)))
      geometry_keys = [(config%shares_with(load_keys(k), axis_geometry), k=1, size(load_keys))]
      call unique_keys(geometry_keys, geometry_of)
      ! The stage the previous block ended on is taken, not solved again.
      allocate (stages(size(load_keys)), cached(size(load_keys)), needed(size(geometry_keys)))
      cached = load_keys == cache%key
      needed = .false.
      do k = 1, size(load_keys)
         if (cached(k)) then
            stages(k) = cache%stage
         else
            needed(geometry_of(k)) = .true.
         end if
      end do

      if (common_geometry) then
         allocate (geometries(1))
         geometries(1) = common
         geometry_of = 1
      else
         allocate (geometries(size(geometry_keys)))
         !$omp parallel do default(none) schedule(dynamic, 1) num_threads(n_threads) &
         !$omp shared(geometries, geometry_keys, setup, config, needed) private(k, error)
         do k = 1, size(geometry_keys)
            if (.not. needed(k)) cycle
            call solve_geometry(setup, config%case_point(geometry_keys(k)), &
               geometries(k)%patches, error)
            if (allocated(error)) then
               geometries(k)%stat = error%stat
               geometries(k)%message = error%message
            end if
         end do
         !$omp end parallel do
      end if

      !$omp parallel do default(none) schedule(dynamic, 1) num_threads(n_threads) &
      !$omp shared(stages, load_keys, geometries, geometry_of, setup, config, cached) private(k)
      do k = 1, size(load_keys)
         if (cached(k)) cycle
         if (geometries(geometry_of(k))%stat /= 0) then
            stages(k)%stat = geometries(geometry_of(k))%stat
            stages(k)%message = geometries(geometry_of(k))%message
         else
            call solve_stage(setup, config%case_point(load_keys(k)), &
               geometries(geometry_of(k))%patches, stages(k))
         end if
      end do
      !$omp end parallel do

      !$omp parallel default(none) num_threads(n_threads) &
      !$omp shared(cases, stages, stage_of, load_keys, results, workspaces, solutions, setup, &
      !$omp config, fields, options, done, total, nb, keep_geometry, keep_strips, &
      !$omp pending, early, dir, blocks, info, write_error) private(i, me)
      me = 1
      !$ me = omp_get_thread_num() + 1
      if (me == 1) call first_thread_writes(pending, early, dir, blocks, info, config, &
         write_error)
      !$omp do schedule(dynamic, 4)
      do i = 1, nb
         call solve_case(setup, config%case_point(cases(i)), stages(stage_of(i)), &
            load_keys(stage_of(i)), workspaces(me), solutions(me)%patches, results(i), fields)
         call case_done(results(i), keep_geometry, keep_strips, done, total, me == 1, options)
      end do
      !$omp end do
      !$omp end parallel
      bytes = sum(result_bytes(results))
      do k = 1, size(stages)
         bytes = bytes + stage_bytes(stages(k))
      end do
      largest = maxval([(stage_bytes(stages(k)), k=1, size(stages))])
      fixed = max(fixed, largest)
      bytes = bytes - largest
      cache%key = load_keys(stage_of(nb))
      call move_alloc(stages(stage_of(nb))%geometry, cache%stage%geometry)
      call move_alloc(stages(stage_of(nb))%normal, cache%stage%normal)
      cache%stage%stat = stages(stage_of(nb))%stat
      if (allocated(stages(stage_of(nb))%message)) cache%stage%message = &
         stages(stage_of(nb))%message
   end subroutine solve_block

   !> Replace each key by its position in the list of distinct keys (order of appearance) and
   !> shrink the list to the distinct keys.
   pure subroutine unique_keys(keys, position)
      integer, allocatable, intent(inout) :: keys(:)
      integer, intent(out) :: position(:)
      integer, allocatable :: distinct(:)
      integer :: i, j, n
      allocate (distinct(size(keys)))
      n = 0
      do i = 1, size(keys)
         position(i) = 0
         do j = n, max(1, n - 8), -1
            if (distinct(j) == keys(i)) then
               position(i) = j
               exit
            end if
         end do
         if (position(i) == 0) then
            do j = 1, n
               if (distinct(j) == keys(i)) then
                  position(i) = j
                  exit
               end if
            end do
         end if
         if (position(i) == 0) then
            n = n + 1
            distinct(n) = keys(i)
            position(i) = n
         end if
      end do
      keys = distinct(1:n)
   end subroutine unique_keys

end module shcontact_batch_block
