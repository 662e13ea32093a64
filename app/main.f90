!> The shcontact command-line program: parse the command line, call the library, map errors to
!> exit statuses (0 ok, 1 usage, 2 invalid input, 3 I/O failure, 4 some sweep cases failed,
!> 5 numerical failure, 6 no contact).
program shcontact_main
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact, only: shcontact_version, error_type, h5_skip_exit_cleanup, stat_usage
   use shcontact_app_cli, only: cli_type, parse_command_line, is_command
   use shcontact_app_help, only: usage_text, command_help
   use shcontact_app_commands, only: run_command, merge_command, geometry_command, report_error
   use shcontact_app_profiles, only: profiles_command
   use shcontact_app_wheelset, only: wheelset_command
   use shcontact_app_stdout, only: put_line, stdout_flush, stdout_failed
   implicit none
   type(cli_type) :: cli
   type(error_type), allocatable :: error
   integer :: status

   call h5_skip_exit_cleanup()
   call parse_command_line(cli, error)
   if (allocated(error)) then
      status = report_error(error)
      ! A usage error within a command points to that command's help (the general usage of
      ! every command was 16 lines of a batch log for one typo), and with -q says no more; a
      ! command line without a command gets the usage text. An invalid value (--set X without
      ! '=') gets its one line, as the same override read from a case file.
      if (error%stat == stat_usage) then
         if (command_named(cli)) then
            if (.not. (quiet_asked() .or. index(error%message, '--help') > 0)) &
               write (error_unit, '(a)') 'shcontact: see `shcontact '// &
               trim(cli%command)//' --help` for its options (doc/app.md)'
         else
            write (error_unit, '(a)') usage_text()
         end if
      end if
      stop status, quiet = .true.
   end if
   if (cli%help) then
      call put_line(command_help(cli%command))
      call finish(0)
   end if
   select case (cli%command)
   case ('help')
      call put_line('shcontact '//shcontact_version// &
         ': wheel-rail rolling contact (semi-Hertzian normal contact, FASTSIM_SH)')
      call put_line(usage_text())
      status = 0
   case ('version')
      call put_line('shcontact '//shcontact_version)
      status = 0
   case ('merge')
      status = merge_command(cli)
   case ('profiles')
      status = profiles_command(cli)
   case ('geometry')
      if (cli%wheelset_given .or. allocated(cli%amplitudes)) then
         status = wheelset_command(cli)
      else
         status = geometry_command(cli)
      end if
   case default
      status = run_command(cli)
   end select
   call finish(status)

contains

   !> End with `status`, or with the I/O status 3 when the standard output could not be
   !> written (a full disk: the tables and reports are the run's results).
   subroutine finish(status)
      integer, intent(in) :: status
      call stdout_flush()
      if (stdout_failed()) then
         write (error_unit, '(a)') 'shcontact: error: the standard output could not be '// &
            'written (a full disk or device?); what it should hold is lost'
         if (status == 0 .or. status == 4) stop 3, quiet = .true.
      end if
      stop status, quiet = .true.
   end subroutine finish

   !> Whether -q (--quiet) is on the command line, also after the option that was refused
   !> (the parse stops there).
   logical function quiet_asked()
      character(len=16) :: arg
      integer :: i
      quiet_asked = .false.
      do i = 1, command_argument_count()
         call get_command_argument(i, arg)
         if (arg == '-q' .or. arg == '--quiet') quiet_asked = .true.
      end do
   end function quiet_asked

   !> Whether the command line named one of the program's commands (before what it refused).
   pure logical function command_named(cli)
      type(cli_type), intent(in) :: cli
      command_named = .false.
      if (.not. allocated(cli%command)) return
      command_named = is_command(cli%command)
   end function command_named

end program shcontact_main
