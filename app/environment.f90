!> What the program takes from its environment: the Slurm job-array variables (only when asked
!> with `--shard slurm`) and integer variables in general.
module shcontact_app_environment
   use shcontact_core_error, only: error_type, fatal_error, stat_usage
   use shcontact_core_strings, only: str_int
   implicit none
   private

   public :: slurm_shard, in_slurm_array, integer_variable, check_thread_variable

contains

   !> The shard of this task of a Slurm job array: (SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN)/
   !> SLURM_ARRAY_TASK_STEP + 1 (MIN defaults to 1, STEP to 1) of SLURM_ARRAY_TASK_COUNT. A usage
   !> error outside a job array, for a task outside 1..COUNT, and in every task of an array
   !> whose tasks are not one evenly spaced range (MAX − MIN ≠ (COUNT − 1) STEP: a list).
   subroutine slurm_shard(shard, n_shards, error)
      !> This task's shard and the number of shards.
      integer, intent(out) :: shard, n_shards
      !> stat_usage when the variables do not give a shard.
      type(error_type), allocatable, intent(out) :: error
      integer :: id, first, count, step, last
      logical :: ok_id, ok_count, ok_first, ok_step, ok_last
      shard = 1
      n_shards = 1
      call integer_variable('SLURM_ARRAY_TASK_COUNT', count, ok_count)
      call integer_variable('SLURM_ARRAY_TASK_ID', id, ok_id)
      if (.not. (ok_count .and. ok_id)) then
         call fatal_error(error, '--shard slurm: SLURM_ARRAY_TASK_ID and '// &
            'SLURM_ARRAY_TASK_COUNT are not set (or not integers); --shard slurm is for the '// &
            'tasks of a Slurm job array (sbatch --array=1-N), elsewhere give --shard I/N', &
            stat_usage)
         return
      end if
      call integer_variable('SLURM_ARRAY_TASK_MIN', first, ok_first)
      if (.not. ok_first) first = 1
      ! A stepped array (--array=1-7:2) numbers its tasks MIN, MIN + STEP, ...
      call integer_variable('SLURM_ARRAY_TASK_STEP', step, ok_step)
      if (.not. ok_step) step = 1
      step = max(step, 1)
      shard = (id - first)/step + 1
      n_shards = count
      ! The tasks must be that progression and all of it (a list such as --array=1,3,7 is not):
      ! every task checks it, so that an array either runs whole or not at all.
      call integer_variable('SLURM_ARRAY_TASK_MAX', last, ok_last)
      if (ok_last .and. count >= 1) then
         if (last - first /= (count - 1)*step) then
            call fatal_error(error, '--shard slurm: the job array''s tasks '// &
               str_int(first)//' ... '//str_int(last)//' (SLURM_ARRAY_TASK_MIN, _MAX) with '// &
               'step '//str_int(step)//' are not '//str_int(count)// &
               ' evenly spaced tasks (SLURM_ARRAY_TASK_COUNT); use a range such as --array=1-'// &
               str_int(count)//', or give --shard I/N', stat_usage)
            return
         end if
      end if
      if (count < 1 .or. shard < 1 .or. shard > n_shards .or. mod(id - first, step) /= 0) then
         call fatal_error(error, '--shard slurm: SLURM_ARRAY_TASK_ID = '//str_int(id)// &
            ' (SLURM_ARRAY_TASK_MIN = '//str_int(first)//') does not give a shard of '// &
            str_int(count)//' (use a contiguous job array, e.g. --array=1-'// &
            str_int(max(count, 1))//', or give --shard I/N)', stat_usage)
      end if
   end subroutine slurm_shard

   !> A usage error when OMP_NUM_THREADS is set but its first entry is not a positive number of
   !> threads: the OpenMP run time then says so on its own and runs with all cores, so a job
   !> script's typo would go unnoticed (`--threads N` overrides the variable).
   subroutine check_thread_variable(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=64) :: buf
      character(len=:), allocatable :: first
      integer :: length, stat, n
      call get_environment_variable('OMP_NUM_THREADS', buf, length, stat)
      ! Unset: the run time's default. Set but empty (OMP_NUM_THREADS=$UNSET in a job script)
      ! is a typo like any other value that is not a number.
      if (stat == 1) return
      first = trim(adjustl(buf(1:min(length, len(buf)))))
      if (index(first, ',') > 0) first = trim(first(:index(first, ',') - 1))
      n = 0
      stat = 1
      if (len(first) > 0 .and. verify(first, '0123456789') == 0 .and. len(first) <= 9) &
         read (first, *, iostat=stat) n
      if (stat == 0 .and. n >= 1) return
      call fatal_error(error, "OMP_NUM_THREADS = '"//trim(buf(1:min(length, len(buf))))// &
         "': expected a positive number of threads (or unset it; --threads N overrides it)", &
         stat_usage)
   end subroutine check_thread_variable

   !> The task of a Slurm job array this process runs in ('' outside a job array).
   function in_slurm_array() result(text)
      character(len=:), allocatable :: text
      integer :: id, count
      logical :: ok_id, ok_count
      call integer_variable('SLURM_ARRAY_TASK_ID', id, ok_id)
      call integer_variable('SLURM_ARRAY_TASK_COUNT', count, ok_count)
      text = ''
      if (ok_id) text = 'task '//str_int(id)
      if (ok_id .and. ok_count) text = text//' of '//str_int(count)
   end function in_slurm_array

   !> An integer environment variable (ok = .false. when unset, empty or not an integer).
   subroutine integer_variable(name, value, ok)
      !> The variable.
      character(len=*), intent(in) :: name
      !> Its value (0 when not ok).
      integer, intent(out) :: value
      !> Set and an integer.
      logical, intent(out) :: ok
      character(len=32) :: buf
      integer :: length, stat
      value = 0
      call get_environment_variable(name, buf, length, stat)
      ok = stat == 0 .and. length > 0 .and. length <= len(buf)
      if (.not. ok) return
      if (verify(trim(adjustl(buf(1:length))), '+-0123456789') /= 0) then
         ok = .false.
         return
      end if
      read (buf(1:length), *, iostat=stat) value
      ok = stat == 0
      if (.not. ok) value = 0
   end subroutine integer_variable

end module shcontact_app_environment
