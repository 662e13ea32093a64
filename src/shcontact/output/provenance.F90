!> Where a result file comes from (issue 15): the git revision of the sources, the compiler and
!> its flags, the host and the number of threads, written as root attributes of every result
!> file.
!>
!> The git revision is fixed when the library is compiled: fpm has no build hooks, and a
!> `git describe` at run time would describe whatever directory the program runs in, not its
!> sources, and nothing at all after `scripts/install`. So this file is preprocessed (.F90) and
!> takes the revision from the macro SHCONTACT_GIT_REVISION, which `scripts/install` sets from
!> `git describe --always --dirty --tags` (by hand: `fpm build --flag
!> "-DSHCONTACT_GIT_REVISION=\"'$(git describe --always --dirty --tags)'\""`); a plain
!> `fpm build` leaves it empty and the file says "unknown".
module shcontact_output_provenance
   use, intrinsic :: iso_c_binding, only: c_char, c_int, c_size_t, c_null_char
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
   !$ use omp_lib, only: omp_get_max_threads
   implicit none
   private

   public :: git_revision, build_compiler, build_flags, host_name, available_threads

#ifdef SHCONTACT_GIT_REVISION
   !> `git describe --always --dirty --tags` of the sources, given at compile time.
   character(len=*), parameter :: compiled_revision = SHCONTACT_GIT_REVISION
#else
   character(len=*), parameter :: compiled_revision = ''
#endif

   interface
      !> POSIX gethostname(2).
      function c_gethostname(name, length) result(stat) bind(C, name='gethostname')
         import :: c_char, c_int, c_size_t
         character(kind=c_char), intent(out) :: name(*)
         integer(c_size_t), value, intent(in) :: length
         integer(c_int) :: stat
      end function c_gethostname
   end interface

contains

   !> The git revision the library was compiled from, or a note saying it is unknown.
   function git_revision() result(text)
      character(len=:), allocatable :: text
      if (len_trim(compiled_revision) > 0) then
         text = trim(compiled_revision)
      else
         text = 'unknown (built without SHCONTACT_GIT_REVISION; scripts/install records it)'
      end if
   end function git_revision

   !> Compiler name and version, as the compiler reports them.
   function build_compiler() result(text)
      character(len=:), allocatable :: text
      text = compiler_version()
   end function build_compiler

   !> The options the library was compiled with.
   function build_flags() result(text)
      character(len=:), allocatable :: text
      text = compiler_options()
   end function build_flags

   !> This machine's host name ('' when it cannot be read).
   function host_name() result(text)
      character(len=:), allocatable :: text
      character(kind=c_char) :: buffer(256)
      integer :: i
      buffer = c_null_char
      text = ''
      if (c_gethostname(buffer, int(size(buffer) - 1, c_size_t)) /= 0) return
      do i = 1, size(buffer)
         if (buffer(i) == c_null_char) exit
         text = text//buffer(i)
      end do
   end function host_name

   !> OpenMP threads a parallel region would use now (1 without OpenMP).
   integer function available_threads() result(n)
      n = 1
      !$ n = omp_get_max_threads()
   end function available_threads

end module shcontact_output_provenance
