!> Errors as values.
!>
!> A fallible procedure ends with `type(error_type), allocatable, intent(out) :: error`; an error
!> is signalled by allocating it (through [[fatal_error]]), and callers test
!> `if (allocated(error)) return`. The library never prints and never stops: only the app turns
!> an error into a message on stderr and an exit status (see [[error_type]] status codes).
module shcontact_core_error
   implicit none
   private

   public :: error_type, fatal_error, prefix_error
   public :: stat_invalid_input, stat_io, stat_numerical, stat_no_contact, stat_usage

   !> Status: bad input data (malformed file, unknown variable, out-of-range value).
   integer, parameter :: stat_invalid_input = 2
   !> Status: a file could not be read or written.
   integer, parameter :: stat_io = 3
   !> Status: a numerical procedure failed (no bracket, singular system, no convergence).
   integer, parameter :: stat_numerical = 5
   !> Status: the profiles do not touch, or the load cannot be carried.
   integer, parameter :: stat_no_contact = 6
   !> Status: wrong use of an interface (bad handle, bad argument combination).
   integer, parameter :: stat_usage = 1

   !> An error: a status code and one human-readable message.
   type :: error_type
      !> One of the `stat_*` codes of this module.
      integer :: stat = stat_invalid_input
      !> What went wrong, naming the item, the value found and what was expected.
      character(len=:), allocatable :: message
   end type error_type

contains

   !> Signal an error: allocate `error` with a message and a status (default: invalid input).
   pure subroutine fatal_error(error, message, stat)
      !> The error to allocate.
      type(error_type), allocatable, intent(out) :: error
      !> The message: what, where, found, expected.
      character(len=*), intent(in) :: message
      !> Status code; [[stat_invalid_input]] when absent.
      integer, intent(in), optional :: stat

      allocate (error)
      error%message = message
      if (present(stat)) error%stat = stat
   end subroutine fatal_error

   !> Put context (a file name, a case number) in front of an existing error message.
   pure subroutine prefix_error(error, context)
      !> The error to amend; nothing happens when it is not allocated.
      type(error_type), intent(inout), allocatable :: error
      !> Text placed before the message, followed by ": ".
      character(len=*), intent(in) :: context

      if (.not. allocated(error)) return
      error%message = context//": "//error%message
   end subroutine prefix_error

end module shcontact_core_error
