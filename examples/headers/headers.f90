!> Writes the option lists of include/shcontact.h and include/shcontact.fi from the registry:
!> the lines between each header's '-- options --' and '-- end options --' become
!> shcontact_input_config_writer's `option_list` of `header_option_keys` (the variable table of
!> shcontact_core_ranges, the option registries' choices, the configuration's defaults). Run from
!> the repository root after adding or changing an option:
!>
!>     fpm run --example shcontact-headers
!>
!> A header whose list is already the registry's is left untouched; test `registry`
!> (`header_lists`) fails while a list differs. Exit status 0, or 3 when a header cannot be read
!> or written or has no option block.
program shcontact_headers
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact_input_config, only: case_config_type
   use shcontact_input_config_variables, only: header_option_keys
   use shcontact_input_config_writer, only: option_list
   implicit none
   logical :: ok

   ok = .true.
   ! The comment prefixes and widths of the two headers (as test `registry` checks them).
   call update('include/shcontact.h', ' * ', 99, ok)
   call update('include/shcontact.fi', '!   ', 72, ok)
   if (.not. ok) error stop 3

contains

   !> Replace the option block of `file` by the registry's list.
   subroutine update(file, prefix, width, ok)
      character(len=*), intent(in) :: file, prefix
      integer, intent(in) :: width
      logical, intent(inout) :: ok
      type(case_config_type) :: defaults
      character(len=:), allocatable :: before, block, after, list
      character(len=1000) :: line
      integer :: unit, stat, part
      character(len=1), parameter :: nl = new_line('a')

      before = ''
      block = ''
      after = ''
      part = 1
      open (newunit=unit, file=file, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         write (error_unit, '(a)') 'shcontact-headers: cannot read '//file// &
            ' (run from the repository root)'
         ok = .false.
         return
      end if
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (part == 2 .and. index(line, '-- end options --') > 0) part = 3
         select case (part)
         case (1)
            before = before//trim(line)//nl
         case (2)
            block = block//trim(line)//nl
         case default
            after = after//trim(line)//nl
         end select
         if (part == 1 .and. index(line, '-- options --') > 0) part = 2
      end do
      close (unit)
      if (part /= 3) then
         write (error_unit, '(a)') 'shcontact-headers: '//file//' has no "-- options --" ... '// &
            '"-- end options --" block'
         ok = .false.
         return
      end if
      list = option_list(defaults, header_option_keys(), prefix, width)
      if (list == block) then
         write (output_unit, '(a)') file//': up to date'
         return
      end if
      open (newunit=unit, file=file, status='replace', action='write', access='stream', &
         form='unformatted', iostat=stat)
      if (stat == 0) write (unit, iostat=stat) before//list//after
      if (stat == 0) close (unit, iostat=stat)
      if (stat /= 0) then
         write (error_unit, '(a)') 'shcontact-headers: cannot write '//file
         ok = .false.
         return
      end if
      write (output_unit, '(a)') file//': option list written from the registry'
   end subroutine update

end program shcontact_headers
