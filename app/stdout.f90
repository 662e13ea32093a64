!> The program's standard output, with its write errors seen. gfortran's preconnected unit 6
!> ignores a failed write (a full disk, a full device: `shcontact run --format csv > out.csv`
!> on a full file system lost every line with exit status 0), so the tables and reports go
!> through this buffer, written with the C library's `write`, and the program ends with the
!> I/O status 3 when any byte could not be written ([[stdout_failed]]).
module shcontact_app_stdout
   use, intrinsic :: iso_c_binding, only: c_int, c_size_t, c_intptr_t, c_loc, c_ptr
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private

   public :: put_line, put_text, stdout_flush, stdout_failed

   !> Bytes held before they are written.
   integer, parameter :: capacity = 65536

   character(len=capacity), target, save :: buffer
   integer, save :: used = 0
   logical, save :: failed = .false.

   interface
      !> POSIX write(2).
      function c_write(fd, buf, count) bind(C, name='write') result(written)
         import :: c_int, c_size_t, c_intptr_t, c_ptr
         integer(c_int), value :: fd
         type(c_ptr), value :: buf
         integer(c_size_t), value :: count
         integer(c_intptr_t) :: written
      end function c_write
   end interface

contains

   !> Write a line (a newline is added).
   subroutine put_line(text)
      !> The line.
      character(len=*), intent(in) :: text
      call put_text(text//new_line('a'))
   end subroutine put_line

   !> Write text as it is (no newline added).
   subroutine put_text(text)
      !> The text.
      character(len=*), intent(in) :: text
      integer :: start, n
      start = 1
      do while (start <= len(text))
         if (used == capacity) call stdout_flush()
         n = min(len(text) - start + 1, capacity - used)
         buffer(used + 1:used + n) = text(start:start + n - 1)
         used = used + n
         start = start + n
      end do
   end subroutine put_text

   !> Write what the buffer holds (also what Fortran's own unit 6 holds, first).
   subroutine stdout_flush()
      integer :: done
      integer(c_intptr_t) :: written
      flush (output_unit)
      done = 0
      do while (done < used)
         written = c_write(1_c_int, c_loc(buffer(done + 1:done + 1)), &
            int(used - done, c_size_t))
         if (written <= 0) then
            failed = .true.
            exit
         end if
         done = done + int(written)
      end do
      used = 0
   end subroutine stdout_flush

   !> Whether a write to the standard output failed (after [[stdout_flush]]).
   logical function stdout_failed()
      stdout_failed = failed
   end function stdout_failed

end module shcontact_app_stdout
