!> Checks of the project's layout rules that fpm does not enforce for us.
module test_layout
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_version_info, only: shcontact_version
   implicit none
   private
   public :: collect_layout

contains

   subroutine collect_layout(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('module_prefix', test_module_prefix), &
         new_unittest('version_matches_manifest', test_version) &
         ]
   end subroutine collect_layout

   !> Every module under src/ is named shcontact or shcontact_*, and its name follows its path.
   subroutine test_module_prefix(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: stat, cmdstat
      character(len=*), parameter :: cmd = &
         'cd src && for f in $(find . -name "*.f90" -o -name "*.F90"); do '// &
         'm=$(sed -n "s/^ *module  *\([A-Za-z_0-9]*\) *$/\1/Ip" "$f" | head -1 | tr A-Z a-z); '// &
         'p=$(echo "$f" | sed "s|^\./||; s|\.[fF]90$||; s|/|_|g"); '// &
         '[ "$m" = "$p" ] || { echo "layout: $f holds module $m, expected $p" >&2; exit 1; }; '// &
         'done'
      call execute_command_line(cmd, exitstat=stat, cmdstat=cmdstat)
      if (cmdstat /= 0) then
         call skip_test(error, 'no shell to list the sources')
         return
      end if
      call check(error, stat, 0, message='a module under src/ does not follow the naming rule')
   end subroutine test_module_prefix

   !> The version constant equals the version in fpm.toml.
   subroutine test_version(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: unit, stat
      character(len=256) :: line
      open (newunit=unit, file='fpm.toml', status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call skip_test(error, 'fpm.toml not found in the working directory')
         return
      end if
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, 'version') == 1) then
            close (unit)
            call check(error, index(line, '"'//shcontact_version//'"') > 0, &
               message='fpm.toml version differs from shcontact_version: '//trim(line))
            return
         end if
      end do
      close (unit)
      call test_failed(error, 'no version line in fpm.toml')
   end subroutine test_version

end module test_layout
