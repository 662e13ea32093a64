!> The commands of the shcontact program. Each calls the library, prints the results summary on
!> stdout and diagnostics on stderr, and returns the exit status.
module shcontact_app_commands
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit, int64
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_usage, stat_invalid_input
   use shcontact_core_strings, only: str_int, str_real, visible, to_lower
   use shcontact_core_text, only: string_type
   use shcontact, only: case_config_type, load_config, config_namelist, merge_result_files, &
      with_absolute_profiles, &
      report_header, report_lines, report_case_text, report_units, iso_timestamp, &
      run_setup_type, prepare_run, solve_geometry, sweep_options_type, sweep_outcome_type, &
      run_sweep, patch_geometry_type, write_geometry_table, read_case_profiles, profile_type
   use shcontact_app_profile_advice, only: profile_notes
   use shcontact_app_output_guard, only: check_output_file
   use shcontact_app_cli, only: cli_type
   use shcontact_app_stdout, only: put_line, put_text
   use shcontact_app_climbing, only: note_climbing_cases
   use shcontact_app_progress, only: start_progress, progress, end_progress, elapsed, &
      run_seconds
   use shcontact_app_environment, only: slurm_shard, in_slurm_array, check_thread_variable
   use shcontact_core_files, only: peak_memory_kib
   implicit none
   private

   public :: run_command, merge_command, geometry_command, report_error
   public :: exit_some_failed, configure, refuse_yaw, print_profile_notes

   !> Exit status when some (not all) cases of a sweep failed.
   integer, parameter :: exit_some_failed = 4

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
      !> The command line.
      type(cli_type), intent(in) :: cli
      !> The configuration.
      type(case_config_type), intent(out) :: config
      !> Set on a bad case file or --set.
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
      character(len=:), allocatable :: where_to, kept
      integer :: i, k

      status = 0
      call configure(cli, config, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) call print_profile_notes(config)
      if (cli%check) then
         ! Reading the profiles is part of validating the input.
         call prepare_run(config, setup, error)
         if (allocated(error)) then
            status = report_error(error)
            return
         end if
         call put_text(config_namelist(with_absolute_profiles(config)))
         if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: the configuration is '// &
            'valid ('//str_int(config%n_cases())//' case(s))'
         return
      end if

      options%threads = cli%threads
      options%resume = cli%resume
      options%force = cli%force
      options%write_output = .not. cli%no_output
      if (cli%block_memory > 0) options%block_bytes = int(cli%block_memory, int64)*1048576_int64
      options%command_line = command_line()
      allocate (options%inputs(1))
      options%inputs(1)%text = cli%case_file
      call choose_shard(cli, options%shard, options%n_shards, error)
      if (.not. allocated(error) .and. cli%threads <= 0) call check_thread_variable(error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      call start_progress(cli%quiet)
      options%progress => progress
      if (cli%verbose) write (error_unit, '(a)') 'shcontact: '//str_int(config%n_cases())// &
         ' case(s), shard '//str_int(options%shard)//'/'//str_int(options%n_shards)
      call run_sweep(config, options, outcome, error)
      call end_progress()
      if (allocated(error)) then
         ! Every case failed: their lines still go to stdout (a shell loop over runs keeps
         ! one line per run, the failed one with its message), then the first failure's status.
         if (every_case_failed(outcome)) call print_summary(summary_format(cli), &
            cli%csv_units, config, outcome)
         status = report_error(error)
         return
      end if

      call print_summary(summary_format(cli), cli%csv_units, config, outcome)
      if (.not. cli%quiet) call note_climbing(config, outcome)
      if (size(outcome%failures) > 0) then
         do k = 1, min(10, size(outcome%failures))
            write (error_unit, '(a)') 'shcontact: case '//str_int(outcome%failures(k)%case)// &
               ' failed: '//outcome%failures(k)%message
         end do
         where_to = outcome%output
         if (cli%no_output) where_to = 'the result file of a run without --no-output'
         if (size(outcome%failures) > 10) write (error_unit, '(a)') 'shcontact: ... and '// &
            str_int(size(outcome%failures) - 10)//' more failed cases (see /failures in '// &
            where_to//')'
         status = exit_some_failed
      end if
      if (.not. cli%quiet .and. outcome%finished_before) then
         write (error_unit, '(a)') 'shcontact: nothing to resume: '//outcome%output// &
            ' already holds every case of this run ('//str_int(outcome%last - &
            outcome%first + 1 - size(outcome%failures))//' solved); it is left as it is'
      else if (.not. cli%quiet) then
         i = outcome%last - outcome%first + 1
         where_to = '; results in '//outcome%output
         if (cli%no_output) where_to = '; no result file (--no-output)'
         write (error_unit, '(a)') 'shcontact: '//str_int(i - size(outcome%failures))//' of '// &
            str_int(i)//' case(s) solved'//resumed_note(outcome)//', '// &
            str_int(outcome%n_threads)//' thread(s), '//elapsed(run_seconds())//where_to
      end if
      ! The figure doc/app.md sizes jobs with (and the memory test reads); nothing of it when
      ! a finished run was taken as it was.
      if (cli%verbose .and. .not. outcome%finished_before) then
         kept = ''
         if (outcome%block_files == 0 .and. outcome%checkpoint_files > 0) kept = '; the '// &
            'output written from memory ('//str_int(outcome%checkpoint_files)// &
            ' checkpoint block file(s) kept until then)'
         write (error_unit, '(a)') 'shcontact: largest checkpoint block '// &
            str_int(outcome%most_block_cases)//' case(s), '// &
            str_int(int(outcome%most_block_bytes/1024))//' KiB of results in memory; '// &
            str_int(outcome%block_files)//' block file(s) merged'//kept
      end if
      if (cli%verbose .and. peak_memory_kib() > 0 .and. .not. outcome%finished_before) &
         write (error_unit, '(a)') &
         'shcontact: peak memory '//str_int(peak_memory_kib())//' KiB (VmHWM), '// &
         str_int(outcome%solving_peak_kib)//' KiB before the output was assembled'
   end function run_command

   !> The note on cases solved in flange-climbing states ([[note_climbing_cases]]); none when
   !> the profiles cannot be prepared again (the run has reported them).
   subroutine note_climbing(config, outcome)
      type(case_config_type), intent(in) :: config
      type(sweep_outcome_type), intent(in) :: outcome
      type(run_setup_type) :: setup
      type(error_type), allocatable :: error
      if (.not. allocated(outcome%summaries)) return
      if (outcome%last < outcome%first) return
      call prepare_run(config, setup, error)
      if (allocated(error)) return
      call note_climbing_cases(config, setup, outcome%summaries(outcome%first:outcome%last), &
         outcome%first)
   end subroutine note_climbing

   !> The notes on the case's profiles and their settings ([[profile_notes]]) on stderr, one
   !> 'shcontact: note: ...' line each. A profile that cannot be read gets none here: the run
   !> reports it.
   subroutine print_profile_notes(config)
      type(case_config_type), intent(in) :: config
      type(profile_type) :: wheel, rail, wheel_read, rail_read
      type(error_type), allocatable :: error
      character(len=:), allocatable :: notes
      integer :: i
      call read_case_profiles(config, wheel, rail, error, wheel_read, rail_read)
      if (allocated(error)) return
      notes = profile_notes(config, wheel_read, rail_read, wheel, rail)
      do while (len(notes) > 0)
         i = index(notes, new_line('a'))
         write (error_unit, '(a)') 'shcontact: '//notes(1:i - 1)
         notes = notes(i + 1:)
      end do
   end subroutine print_profile_notes

   !> The configuration with its profile files named by absolute paths (built-in profiles as
   !> they are): `--check` prints a case file that reproduces the run wherever it is saved (a
   !> case file's relative paths are taken from its own directory; the resolved ones are
   !> relative to the working directory).
   function resumed_note(outcome) result(text)
      type(sweep_outcome_type), intent(in) :: outcome
      character(len=:), allocatable :: text
      text = ''
      if (outcome%n_resumed > 0) text = ' ('//str_int(outcome%n_resumed)// &
         ' from the checkpoint)'
   end function resumed_note

   !> Whether the run solved its cases and every one of them failed (the outcome then holds
   !> their summaries and failures, but no file was written).
   pure logical function every_case_failed(outcome)
      type(sweep_outcome_type), intent(in) :: outcome
      every_case_failed = .false.
      if (.not. (allocated(outcome%summaries) .and. allocated(outcome%failures))) return
      if (outcome%last < outcome%first) return
      every_case_failed = size(outcome%failures) == outcome%last - outcome%first + 1
   end function every_case_failed

   !> The summary format: --format, else none with -q, else text.
   function summary_format(cli) result(format)
      type(cli_type), intent(in) :: cli
      character(len=:), allocatable :: format
      format = cli%format
      if (cli%quiet .and. .not. cli%format_given) format = 'none'
   end function summary_format

   !> --shard I/N, --shard slurm (from the job-array variables), else 1/1. Inside a job array
   !> without --shard every case is solved, with a note (a script written for the former
   !> implicit sharding would otherwise run the whole sweep in every task unawares).
   subroutine choose_shard(cli, shard, n_shards, error)
      type(cli_type), intent(in) :: cli
      integer, intent(out) :: shard, n_shards
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: task
      shard = 1
      n_shards = 1
      if (cli%shard_slurm) then
         call slurm_shard(shard, n_shards, error)
      else if (cli%n_shards > 0) then
         shard = cli%shard
         n_shards = cli%n_shards
      else
         task = in_slurm_array()
         if (len(task) > 0 .and. .not. cli%quiet) write (error_unit, '(a)') 'shcontact: '// &
            'note: Slurm job-array '//task//': solving every case of the run (--shard '// &
            'slurm solves this task''s slice)'
      end if
   end subroutine choose_shard

   !> The results summary on stdout.
   subroutine print_summary(format, csv_units, config, outcome)
      character(len=*), intent(in) :: format
      logical, intent(in) :: csv_units
      type(case_config_type), intent(in) :: config
      type(sweep_outcome_type), intent(in) :: outcome
      !> Cases formatted at a time.
      integer, parameter :: chunk = 8192
      character(len=:), allocatable :: header
      type(string_type), allocatable :: lines(:)
      integer :: first, last, k
      if (format == 'none') return
      if (format == 'text' .and. outcome%n_cases == 1) then
         if (outcome%summaries(1)%stat == 0) call put_line( &
            report_case_text(config, outcome%summaries(1)))
         return
      end if
      header = report_header(config, format)
      if (len(header) > 0) call put_line(header)
      if (csv_units) call put_line(report_units(config))
      ! The lines of a chunk of cases are formatted by the run's threads, then written in order.
      allocate (lines(min(chunk, outcome%last - outcome%first + 1)))
      do first = outcome%first, outcome%last, chunk
         last = min(first + chunk - 1, outcome%last)
         call report_lines(config, first, outcome%summaries(first:last), outcome%failures, &
            format, outcome%n_threads, lines)
         do k = 1, last - first + 1
            call put_line(lines(k)%text)
         end do
      end do
   end subroutine print_summary

   ! ------------------------------------------------------------------------------------------
   ! Other commands
   ! ------------------------------------------------------------------------------------------

   !> `shcontact merge OUT.h5 SHARD.h5...`.
   integer function merge_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(error_type), allocatable :: error
      integer :: n_failed, n_merged
      status = 0
      call merge_result_files(cli%inputs%items(1)%text, cli%inputs%items(2:cli%inputs%n), &
         command_line(), iso_timestamp(), error, force=cli%force, n_failed=n_failed, &
         n_merged=n_merged)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      ! The shards' failed cases are the merged run's: the status a run of the whole sweep
      ! would give (a pipeline that checks only the merge sees them).
      if (n_failed > 0) then
         write (error_unit, '(a)') 'shcontact: '//str_int(n_failed)//' of '// &
            str_int(n_merged)//' case(s) failed (see /failures in '// &
            cli%inputs%items(1)%text//')'
         status = exit_some_failed
      end if
      if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: merged '// &
         str_int(cli%inputs%n - 1)//' file(s) into '//cli%inputs%items(1)%text
   end function merge_command

   !> `shcontact geometry [CASE.nml] [-o FILE]`: the strip geometry of the case's wheel
   !> position (for plots of the profiles and the lateral curvature, the seed's Fig. 3).
   integer function geometry_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(case_config_type) :: config
      type(run_setup_type) :: setup
      type(patch_geometry_type), allocatable :: patches(:)
      type(error_type), allocatable :: error
      character(len=:), allocatable :: name, what
      character(len=4096) :: inputs(3)
      type(cli_type) :: plain
      status = 0
      plain = cli
      plain%output = ''
      name = 'geometry.txt'
      what = 'the default output (no -o)'
      if (len(cli%output) > 0) then
         name = cli%output
         what = '-o'
      end if
      ! Refused before anything is computed: never over a file this run did not write, nor
      ! over a file it reads (the case file, the profile files).
      call configure(plain, config, error)
      if (.not. allocated(error)) then
         inputs(1) = cli%case_file
         inputs(2) = config%profiles%wheel
         inputs(3) = config%profiles%rail
         call check_output_file(name, what, cli%force, inputs, error)
      end if
      if (.not. allocated(error)) call refuse_yaw(cli, config, error)
      if (.not. allocated(error)) call prepare_run(config, setup, error)
      if (.not. allocated(error) .and. .not. cli%quiet) call print_profile_notes(config)
      if (.not. allocated(error)) call solve_geometry(setup, config%case_point(1), patches, error)
      if (.not. allocated(error)) call write_geometry_table(patches, name, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: geometry of '// &
         str_int(size(patches))//' patch(es) written to '//name
   end function geometry_command

   !> An error unless the case's wheelset has no yaw: the tables of `shcontact geometry` (the
   !> strip tables and the wheelset's) are those of a wheelset without yaw; a yawed wheel's
   !> (the contact locus, doc/kinematics.md) exist only inside the kinematic call, so writing
   !> these would be a wrong answer for the case asked.
   subroutine refuse_yaw(cli, config, error)
      type(cli_type), intent(in) :: cli
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      associate (first => config%case_point(1))
         if (first%yaw /= 0.0_wp) call fatal_error(error, case_source(cli)// &
            ': &kinematics yaw = '//str_real(first%yaw)//' rad: `shcontact geometry` '// &
            'writes the tables of a wheelset without yaw only; set yaw = 0', &
            stat_invalid_input)
      end associate
   end subroutine refuse_yaw

   !> Where a case's inputs come from, for messages: the case file, or the built-in case.
   pure function case_source(cli) result(text)
      type(cli_type), intent(in) :: cli
      character(len=:), allocatable :: text
      text = 'the built-in case'
      if (len(cli%case_file) > 0) text = cli%case_file
   end function case_source

end module shcontact_app_commands
