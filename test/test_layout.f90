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
         new_unittest('version_matches_manifest', test_version), &
         new_unittest('cited_docs_exist', test_citations), &
         new_unittest('citation_check_catches_bad_ones', test_citation_check), &
         new_unittest('layers_import_one_way', test_layers), &
         new_unittest('layer_check_catches_upward_use', test_layer_check) &
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

   !> Every doc/*.md path cited in a source (src/, app/, test/, examples/, include/, scripts/)
   !> exists, with the cited heading (§N) or decision when one is given; nothing cites the
   !> team's former physics notes outside the repository, and src/, app/, test/, include/ do
   !> not refer to the external data's folder (scripts/check_citations prints each bad one).
   subroutine test_citations(error)
      type(error_type), allocatable, intent(out) :: error
      call check_script(error, 'check_citations', 'a source cites a missing doc, heading or '// &
         'decision, or a file outside the repository (see the lines above)')
   end subroutine test_citations

   !> Run scripts/NAME on the repository: the test fails with `message` when it exits non-zero
   !> and is skipped without a shell.
   subroutine check_script(error, name, message)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: name, message
      integer :: stat, cmdstat
      call execute_command_line('bash scripts/'//name, exitstat=stat, cmdstat=cmdstat)
      if (cmdstat /= 0) then
         call skip_test(error, 'no shell to run scripts/'//name)
         return
      end if
      call check(error, stat, 0, message=message)
   end subroutine check_script

   !> The check itself fails on a scratch tree with one bad citation of each kind (a missing
   !> file, a missing heading, a missing decision, the former physics notes) and passes on the
   !> same tree with the good ones only. (The citations are built from pieces here so that this
   !> file does not cite them itself.)
   subroutine test_citation_check(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: tree = 'build/citation_check'
      character(len=*), parameter :: doc = 'doc/', t = doc//'t.md'
      character(len=*), parameter :: bad(4) = [character(len=40) :: '! see '//doc//'none.md', &
         '! see '//t//' §1.3', '! see '//t//' decision 2', '! see physics'//'.md §1.2']
      integer :: stat, cmdstat, k
      call execute_command_line('rm -rf '//tree//' && mkdir -p '//tree//'/src '//tree// &
         '/doc && printf ''## 1. One\n### 1.2 Two\n## Project decisions\n\n1. **A**\n'' > '// &
         tree//'/'//t//' && printf ''! '//t//' §1.2, '//t//' decision 1, '//t//'\n'' > '// &
         tree//'/src/good.f90 && bash scripts/check_citations '//tree, exitstat=stat, &
         cmdstat=cmdstat)
      if (cmdstat /= 0) then
         call skip_test(error, 'no shell to run scripts/check_citations')
         return
      end if
      call check(error, stat, 0, message='check_citations refuses good citations')
      if (allocated(error)) return
      do k = 1, size(bad)
         call execute_command_line('printf ''%s\n'' '''//trim(bad(k))//''' > '//tree// &
            '/src/bad.f90 && bash scripts/check_citations '//tree//' 2> /dev/null', &
            exitstat=stat)
         call check(error, stat /= 0, message='check_citations accepts: '//trim(bad(k)))
         if (allocated(error)) return
      end do
      call execute_command_line('rm -rf '//tree)
   end subroutine test_citation_check

   !> The library's layers import one way: a module under src/ uses only modules of its own
   !> layer or of lower ones. Folders are layers, lowest first: core → math → profile →
   !> geometry → normal → tangential → pipeline → input → api → case → output → batch, then the
   !> facade (scripts/check_layers lists the order and prints each upward use;
   !> doc/architecture.md).
   subroutine test_layers(error)
      type(error_type), allocatable, intent(out) :: error
      call check_script(error, 'check_layers', 'a module uses a module of a higher layer, or a '// &
         'source is in no layer (see the lines above)')
   end subroutine test_layers

   !> The layer check fails on a scratch tree where core/ uses api/, on one with a folder that
   !> is in no layer and on one whose app/ uses api/ past the facade, and passes once api/ uses
   !> core/ only and app/ the facade and core/.
   subroutine test_layer_check(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: tree = 'build/layer_check', lib = tree//'/src/shcontact'
      integer :: stat, cmdstat
      call execute_command_line('rm -rf '//tree//' && mkdir -p '//lib//'/core '//lib// &
         '/api '//lib//'/extra && printf ''module shcontact_api_b\n use shcontact_core_a\n'// &
         'end module shcontact_api_b\n'' > '//lib//'/api/b.f90 && printf ''module '// &
         'shcontact_core_a\n use shcontact_api_b, only: x\nend module shcontact_core_a\n'' > '// &
         lib//'/core/a.f90', exitstat=stat, cmdstat=cmdstat)
      if (cmdstat /= 0 .or. stat /= 0) then
         call skip_test(error, 'no shell to write the scratch tree')
         return
      end if
      call execute_command_line('bash scripts/check_layers '//tree//' 2> /dev/null', &
         exitstat=stat)
      call check(error, stat /= 0, message='check_layers accepts core/ using api/')
      if (allocated(error)) return
      call execute_command_line('printf ''module shcontact_core_a\nend module '// &
         'shcontact_core_a\n'' > '//lib//'/core/a.f90 && printf ''module shcontact_extra_c\n'// &
         'end module shcontact_extra_c\n'' > '//lib//'/extra/c.f90 && bash '// &
         'scripts/check_layers '//tree//' 2> /dev/null', exitstat=stat)
      call check(error, stat /= 0, message='check_layers accepts a folder in no layer')
      if (allocated(error)) return
      call execute_command_line('rm -rf '//lib//'/extra && bash scripts/check_layers '//tree, &
         exitstat=stat)
      call check(error, stat, 0, message='check_layers refuses api/ using core/')
      if (allocated(error)) return
      ! The program may use the facade and core/, not a layer's module.
      call execute_command_line('mkdir -p '//tree//'/app && printf ''module shcontact_app_d\n'// &
         ' use shcontact_api_b\nend module shcontact_app_d\n'' > '//tree//'/app/d.f90 && '// &
         'bash scripts/check_layers '//tree//' 2> /dev/null', exitstat=stat)
      call check(error, stat /= 0, message='check_layers accepts app/ using api/ past the facade')
      if (allocated(error)) return
      call execute_command_line('printf ''module shcontact_app_d\n use shcontact\n use '// &
         'shcontact_core_a\nend module shcontact_app_d\n'' > '//tree//'/app/d.f90 && '// &
         'bash scripts/check_layers '//tree, exitstat=stat)
      call check(error, stat, 0, message='check_layers refuses app/ using the facade and core/')
      call execute_command_line('rm -rf '//tree)
   end subroutine test_layer_check

end module test_layout
