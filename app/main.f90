!> The shcontact command-line program: parse the command line, call the library, map errors to
!> exit statuses (0 ok, 1 usage, 2 invalid input, 3 I/O failure, 4 some sweep cases failed,
!> 5 numerical failure, 6 no contact).
program shcontact_main
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact, only: shcontact_version, error_type
   use shcontact_app_cli, only: cli_type, parse_command_line
   use shcontact_app_help, only: usage_text, command_help
   use shcontact_app_commands, only: run_command, merge_command, geometry_command, report_error
   use shcontact_app_profiles, only: profiles_command
   use shcontact_app_wheelset, only: wheelset_command
   implicit none
   type(cli_type) :: cli
   type(error_type), allocatable :: error
   integer :: status

   call parse_command_line(cli, error)
   if (allocated(error)) then
      status = report_error(error)
      write (error_unit, '(a)') usage_text()
      stop status, quiet = .true.
   end if
   if (cli%help) then
      write (output_unit, '(a)') command_help(cli%command)
      stop 0, quiet = .true.
   end if
   select case (cli%command)
   case ('help')
      write (output_unit, '(a)') 'shcontact '//shcontact_version// &
         ': wheel-rail rolling contact (semi-Hertzian normal contact, FASTSIM_SH)'
      write (output_unit, '(a)') usage_text()
      status = 0
   case ('version')
      write (output_unit, '(a)') 'shcontact '//shcontact_version
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
   stop status, quiet = .true.
end program shcontact_main
