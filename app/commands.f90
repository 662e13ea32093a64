!> The commands of the shcontact program. Each calls the library, prints the results summary on
!> stdout and diagnostics on stderr, and returns the exit status.
module shcontact_app_commands
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_usage, stat_invalid_input
   use shcontact_core_strings, only: str_int, visible
   use shcontact_io_text, only: string_type
   use shcontact_io_config, only: case_config_type, load_config, config_namelist
   use shcontact_io_results, only: merge_result_files
   use shcontact_io_report, only: report_header, report_line, report_case_text
   use shcontact_io_files, only: make_directory
   use shcontact_io_clock, only: iso_timestamp, wall_seconds
   use shcontact_case_runner, only: run_setup_type, prepare_run, solve_geometry
   use shcontact_case_sweep, only: sweep_options_type, sweep_outcome_type, run_sweep
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_contact, only: write_geometry_table
   use shcontact_profile_writer, only: write_builtin_profiles
   use shcontact_app_cli, only: cli_type
   implicit none
   private

   public :: run_command, merge_command, profiles_command, geometry_command, report_error
   public :: exit_some_failed

   !> Exit status when some (not all) cases of a sweep failed.
   integer, parameter :: exit_some_failed = 4

   interface
      function c_isatty(fd) bind(c, name='isatty') result(yes)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: yes
      end function c_isatty
   end interface

   ! Progress display state (the program's own, single-threaded use: the library calls the
   ! progress procedure from one thread only).
   logical :: show_progress = .false., on_terminal = .false.
   real(wp) :: t_start = 0.0_wp, t_last = 0.0_wp
   integer :: blocks_committed = 0, abort_after_blocks = 0

contains

   !> Print an error on stderr and return its exit status.
   integer function report_error(error) result(status)
      !> The error.
      type(error_type), intent(in) :: error
      write (error_unit, '(a)') 'shcontact: error: '//visible(error%message)
      status = error%stat
   end function report_error

   !> The full command line, for the output file.
   function command_line() result(text)
      character(len=:), allocatable :: text
      integer :: length
      call get_command(length=length)
      allocate (character(len=length) :: text)
      if (length > 0) call get_command(text)
   end function command_line

   !> Defaults + case file + --set + -o.
   subroutine configure(cli, config, error)
      type(cli_type), intent(in) :: cli
      type(case_config_type), intent(out) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: sets(:)
      integer :: i, longest, n
      n = cli%sets%n
      if (len(cli%output) > 0) n = n + 1
      longest = len(cli%output) + 12
      do i = 1, cli%sets%n
         longest = max(longest, len(cli%sets%items(i)%text))
      end do
      allocate (character(len=longest) :: sets(n))
      do i = 1, cli%sets%n
         sets(i) = cli%sets%items(i)%text
      end do
      if (len(cli%output) > 0) sets(n) = 'output%file='//cli%output
      call load_config(cli%case_file, sets, config, error)
   end subroutine configure

   !> `shcontact run`: validate (and print with --check) or solve, print the summary.
   integer function run_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(case_config_type) :: config
      type(error_type), allocatable :: error
      type(run_setup_type) :: setup
      type(sweep_options_type) :: options
      type(sweep_outcome_type) :: outcome
      integer :: i, k

      status = 0
      call configure(cli, config, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (cli%check) then
         ! Reading the profiles is part of validating the input.
         call prepare_run(config, setup, error)
         if (allocated(error)) then
            status = report_error(error)
            return
         end if
         write (output_unit, '(a)', advance='no') config_namelist(config)
         flush (output_unit)
         if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: the configuration is '// &
            'valid ('//str_int(config%n_cases())//' case(s))'
         return
      end if

      options%threads = cli%threads
      options%resume = cli%resume
      options%command_line = command_line()
      call shard_from_environment(cli, options%shard, options%n_shards, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      call start_progress(cli)
      options%progress => progress
      if (cli%verbose) write (error_unit, '(a)') 'shcontact: '//str_int(config%n_cases())// &
         ' case(s), shard '//str_int(options%shard)//'/'//str_int(options%n_shards)
      call run_sweep(config, options, outcome, error)
      call end_progress()
      if (allocated(error)) then
         status = report_error(error)
         return
      end if

      call print_summary(cli%format, config, outcome)
      if (size(outcome%failures) > 0) then
         do k = 1, min(10, size(outcome%failures))
            write (error_unit, '(a)') 'shcontact: case '//str_int(outcome%failures(k)%case)// &
               ' failed: '//outcome%failures(k)%message
         end do
         if (size(outcome%failures) > 10) write (error_unit, '(a)') 'shcontact: ... and '// &
            str_int(size(outcome%failures) - 10)//' more failed cases (see /failures in '// &
            outcome%output//')'
         status = exit_some_failed
      end if
      if (.not. cli%quiet) then
         i = outcome%last - outcome%first + 1
         write (error_unit, '(a)') 'shcontact: '//str_int(i - size(outcome%failures))//' of '// &
            str_int(i)//' case(s) solved'//resumed_note(outcome)//', '// &
            str_int(outcome%n_threads)//' thread(s), '//elapsed(wall_seconds() - t_start)// &
            '; results in '//outcome%output
      end if
   end function run_command

   function resumed_note(outcome) result(text)
      type(sweep_outcome_type), intent(in) :: outcome
      character(len=:), allocatable :: text
      text = ''
      if (outcome%n_resumed > 0) text = ' ('//str_int(outcome%n_resumed)// &
         ' from the checkpoint)'
   end function resumed_note

   !> The results summary on stdout.
   subroutine print_summary(format, config, outcome)
      character(len=*), intent(in) :: format
      type(case_config_type), intent(in) :: config
      type(sweep_outcome_type), intent(in) :: outcome
      character(len=:), allocatable :: header
      integer :: icase, k
      if (format == 'text' .and. outcome%n_cases == 1) then
         if (outcome%summaries(1)%stat == 0) write (output_unit, '(a)') &
            report_case_text(config, outcome%summaries(1))
         return
      end if
      header = report_header(config, format)
      if (len(header) > 0) write (output_unit, '(a)') header
      k = 1
      do icase = outcome%first, outcome%last
         if (outcome%summaries(icase)%stat > 0) then
            do k = 1, size(outcome%failures)
               if (outcome%failures(k)%case == icase) exit
            end do
            write (output_unit, '(a)') report_line(config, icase, outcome%summaries(icase), &
               format, outcome%failures(min(k, size(outcome%failures)))%message)
         else
            write (output_unit, '(a)') report_line(config, icase, outcome%summaries(icase), &
               format)
         end if
      end do
   end subroutine print_summary

   !> --shard, else SLURM_ARRAY_TASK_ID − SLURM_ARRAY_TASK_MIN + 1 of SLURM_ARRAY_TASK_COUNT,
   !> else 1/1.
   subroutine shard_from_environment(cli, shard, n_shards, error)
      type(cli_type), intent(in) :: cli
      integer, intent(out) :: shard, n_shards
      type(error_type), allocatable, intent(out) :: error
      integer :: id, first, count
      logical :: ok_id, ok_count, ok_first
      shard = 1
      n_shards = 1
      if (cli%n_shards > 0) then
         shard = cli%shard
         n_shards = cli%n_shards
         return
      end if
      call integer_variable('SLURM_ARRAY_TASK_COUNT', count, ok_count)
      call integer_variable('SLURM_ARRAY_TASK_ID', id, ok_id)
      if (.not. (ok_count .and. ok_id)) return
      call integer_variable('SLURM_ARRAY_TASK_MIN', first, ok_first)
      if (.not. ok_first) first = 1
      shard = id - first + 1
      n_shards = count
      if (shard < 1 .or. shard > n_shards) then
         call fatal_error(error, 'SLURM_ARRAY_TASK_ID = '//str_int(id)//' does not give a '// &
            'shard of '//str_int(count)//' (use a contiguous job array, e.g. --array=1-'// &
            str_int(count)//', or give --shard I/N)', stat_usage)
      end if
   end subroutine shard_from_environment

   subroutine integer_variable(name, value, ok)
      character(len=*), intent(in) :: name
      integer, intent(out) :: value
      logical, intent(out) :: ok
      character(len=32) :: buf
      integer :: length, stat
      value = 0
      call get_environment_variable(name, buf, length, stat)
      ok = stat == 0 .and. length > 0
      if (.not. ok) return
      read (buf(1:length), *, iostat=stat) value
      ok = stat == 0
   end subroutine integer_variable

   ! ------------------------------------------------------------------------------------------
   ! Progress on stderr
   ! ------------------------------------------------------------------------------------------

   subroutine start_progress(cli)
      type(cli_type), intent(in) :: cli
      logical :: ok
      show_progress = .not. cli%quiet
      on_terminal = c_isatty(2_c_int) == 1
      t_start = wall_seconds()
      t_last = t_start
      blocks_committed = 0
      ! Test hook: end the process abruptly after this many checkpoint blocks, as a kill would
      ! (used by the tests of --resume; see doc/app.md).
      call integer_variable('SHCONTACT_TEST_ABORT_AFTER_BLOCKS', abort_after_blocks, ok)
      if (.not. ok) abort_after_blocks = 0
   end subroutine start_progress

   !> A bar with the ETA on a terminal, a line every 10 s otherwise, nothing with -q.
   subroutine progress(done, total, committed)
      integer, intent(in) :: done, total
      logical, intent(in) :: committed
      real(wp) :: now, eta
      integer :: width, filled
      if (committed) then
         blocks_committed = blocks_committed + 1
         if (abort_after_blocks > 0 .and. blocks_committed >= abort_after_blocks) then
            write (error_unit, '(a)') 'shcontact: SHCONTACT_TEST_ABORT_AFTER_BLOCKS: stopping '// &
               'after '//str_int(blocks_committed)//' checkpoint block(s)'
            stop 9, quiet = .true.
         end if
      end if
      if (.not. show_progress) return
      now = wall_seconds()
      eta = 0.0_wp
      if (done > 0) eta = (now - t_start)*real(total - done, wp)/real(done, wp)
      if (on_terminal) then
         if (now - t_last < 0.2_wp .and. done < total) return
         width = 30
         filled = (width*done)/max(total, 1)
         write (error_unit, '(a)', advance='no') achar(13)//'shcontact: ['// &
            repeat('#', filled)//repeat('.', width - filled)//'] '//str_int(done)//'/'// &
            str_int(total)//'  ETA '//elapsed(eta)//'   '
         flush (error_unit)
      else
         if (now - t_last < 10.0_wp) return
         write (error_unit, '(a)') 'shcontact: '//str_int(done)//' of '//str_int(total)// &
            ' cases, '//elapsed(now - t_start)//' elapsed, ETA '//elapsed(eta)
      end if
      t_last = now
   end subroutine progress

   subroutine end_progress()
      if (show_progress .and. on_terminal .and. t_last > t_start) then
         write (error_unit, '(a)') ''
      end if
   end subroutine end_progress

   !> Seconds as "12.3 s", "4 min 05 s" or "2 h 03 min".
   function elapsed(seconds) result(text)
      real(wp), intent(in) :: seconds
      character(len=:), allocatable :: text
      character(len=32) :: buf
      integer :: s
      if (seconds < 10.0_wp) then
         write (buf, '(f0.2,a)') max(seconds, 0.0_wp), ' s'
         text = trim(buf)
         if (text(1:1) == '.') text = '0'//text
         return
      else if (seconds < 60.0_wp) then
         write (buf, '(f0.1,a)') seconds, ' s'
         text = trim(buf)
         if (text(1:1) == '.') text = '0'//text
         return
      end if
      s = nint(seconds)
      if (s < 3600) then
         write (buf, '(i0,a,i2.2,a)') s/60, ' min ', mod(s, 60), ' s'
      else
         write (buf, '(i0,a,i2.2,a)') s/3600, ' h ', mod(s, 3600)/60, ' min'
      end if
      text = trim(buf)
   end function elapsed

   ! ------------------------------------------------------------------------------------------
   ! Other commands
   ! ------------------------------------------------------------------------------------------

   !> `shcontact merge OUT.h5 SHARD.h5...`.
   integer function merge_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(error_type), allocatable :: error
      status = 0
      call merge_result_files(cli%inputs%items(1)%text, cli%inputs%items(2:cli%inputs%n), &
         command_line(), iso_timestamp(), error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: merged '// &
         str_int(cli%inputs%n - 1)//' file(s) into '//cli%inputs%items(1)%text
   end function merge_command

   !> `shcontact profiles --write DIR`.
   integer function profiles_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(error_type), allocatable :: error
      status = 0
      call make_directory(cli%write_dir, error)
      if (.not. allocated(error)) call write_builtin_profiles(cli%write_dir, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: built-in profiles written '// &
         'to '//cli%write_dir
   end function profiles_command

   !> `shcontact geometry [CASE.nml] [-o FILE]`: the strip geometry of the case's wheel
   !> position (for plots of the profiles and the lateral curvature, the seed's Fig. 3).
   integer function geometry_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(case_config_type) :: config
      type(run_setup_type) :: setup
      type(patch_geometry_type), allocatable :: patches(:)
      type(error_type), allocatable :: error
      character(len=:), allocatable :: name
      type(cli_type) :: plain
      status = 0
      plain = cli
      plain%output = ''
      call configure(plain, config, error)
      if (.not. allocated(error)) call prepare_run(config, setup, error)
      if (.not. allocated(error)) call solve_geometry(setup, config%case_point(1), patches, error)
      name = 'geometry.txt'
      if (len(cli%output) > 0) name = cli%output
      if (.not. allocated(error)) call write_geometry_table(patches, name, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: geometry of '// &
         str_int(size(patches))//' patch(es) written to '//name
   end function geometry_command

end module shcontact_app_commands
