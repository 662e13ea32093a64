!> The shcontact command-line program: parse the command line, call the library, map errors to
!> exit statuses.
program shcontact_main
   use shcontact, only: shcontact_version
   implicit none
   integer :: nargs
   character(len=256) :: arg

   nargs = command_argument_count()
   if (nargs >= 1) then
      call get_command_argument(1, arg)
      select case (trim(arg))
      case ('--version', '-V')
         print '(a)', 'shcontact '//shcontact_version
         stop
      end select
   end if
   print '(a)', 'shcontact '//shcontact_version//': the case runner is not built yet; try --version'
end program shcontact_main
