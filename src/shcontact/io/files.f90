!> File-system operations that standard Fortran lacks (rename, directories), through the C library.
!>
!> Output files are written under a temporary name and renamed when complete; checkpoints live
!> in a directory next to the output. POSIX `rename` replaces the target atomically.
module shcontact_io_files
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, &
      c_associated, c_f_pointer, c_size_t
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   implicit none
   private

   public :: rename_file, delete_file, make_directory, remove_directory, file_exists
   public :: directory_part, join_path, is_absolute, process_id, canonical_path

   interface
      function c_rename(from, to) bind(c, name='rename') result(stat)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: from(*), to(*)
         integer(c_int) :: stat
      end function c_rename
      function c_remove(path) bind(c, name='remove') result(stat)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int) :: stat
      end function c_remove
      function c_mkdir(path, mode) bind(c, name='mkdir') result(stat)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: path(*)
         integer(c_int), value :: mode
         integer(c_int) :: stat
      end function c_mkdir
      function c_realpath(path, resolved) bind(c, name='realpath') result(p)
         import :: c_char, c_ptr
         character(kind=c_char), intent(in) :: path(*)
         type(c_ptr), value :: resolved
         type(c_ptr) :: p
      end function c_realpath
      subroutine c_free(p) bind(c, name='free')
         import :: c_ptr
         type(c_ptr), value :: p
      end subroutine c_free
      function c_strlen(p) bind(c, name='strlen') result(n)
         import :: c_ptr, c_size_t
         type(c_ptr), value :: p
         integer(c_size_t) :: n
      end function c_strlen
      function c_getpid() bind(c, name='getpid') result(pid)
         import :: c_int
         integer(c_int) :: pid
      end function c_getpid
   end interface

contains

   !> Rename `from` to `to`, replacing `to` if it exists.
   subroutine rename_file(from, to, error)
      !> Existing file.
      character(len=*), intent(in) :: from
      !> New name.
      character(len=*), intent(in) :: to
      !> Set when the rename fails.
      type(error_type), allocatable, intent(out) :: error
      if (c_rename(from//c_null_char, to//c_null_char) /= 0) then
         call fatal_error(error, 'cannot rename "'//from//'" to "'//to//'"', stat_io)
      end if
   end subroutine rename_file

   !> Delete a file or an empty directory if it exists; true when it is gone afterwards.
   function delete_file(path) result(gone)
      !> The file.
      character(len=*), intent(in) :: path
      logical :: gone
      if (c_remove(path//c_null_char) /= 0) continue
      gone = .not. file_exists(path)
   end function delete_file

   !> Create a directory (mode 0777 before umask); no error when it exists already.
   subroutine make_directory(path, error)
      !> The directory.
      character(len=*), intent(in) :: path
      !> Set when it neither exists nor can be created.
      type(error_type), allocatable, intent(out) :: error
      if (c_mkdir(path//c_null_char, int(o'777', c_int)) /= 0) then
         if (.not. file_exists(path)) call fatal_error(error, 'cannot create the directory "'// &
            path//'" (does its parent exist, and is it writable?)', stat_io)
      end if
   end subroutine make_directory

   !> Remove an empty directory; true when it is gone afterwards.
   function remove_directory(path) result(gone)
      !> The directory.
      character(len=*), intent(in) :: path
      logical :: gone
      gone = delete_file(path)
   end function remove_directory

   !> True when a file or directory of that name exists.
   function file_exists(path) result(exists)
      !> The name.
      character(len=*), intent(in) :: path
      logical :: exists
      ! gfortran's inquire also answers for directories; a trailing '/.' makes that explicit.
      inquire (file=path, exist=exists)
      if (.not. exists) inquire (file=path//'/.', exist=exists)
   end function file_exists

   !> The directory part of a path ('' when there is none), without the trailing '/'.
   pure function directory_part(path) result(dir)
      !> The path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: dir
      integer :: i
      i = index(path, '/', back=.true.)
      if (i == 0) then
         dir = ''
      else if (i == 1) then
         dir = '/'
      else
         dir = path(1:i - 1)
      end if
   end function directory_part

   !> `dir/name`, or `name` alone when it is absolute or `dir` is empty.
   pure function join_path(dir, name) result(path)
      !> Directory.
      character(len=*), intent(in) :: dir
      !> Relative or absolute name.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      if (len_trim(dir) == 0 .or. is_absolute(name)) then
         path = trim(name)
      else if (dir(len_trim(dir):len_trim(dir)) == '/') then
         path = trim(dir)//trim(name)
      else
         path = trim(dir)//'/'//trim(name)
      end if
   end function join_path

   !> True for a path starting with '/'.
   pure logical function is_absolute(path)
      !> The path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: p
      p = adjustl(path)
      is_absolute = .false.
      if (len(p) > 0) is_absolute = p(1:1) == '/'
   end function is_absolute

   !> The absolute path without symbolic links, `.` or `..` (POSIX realpath); the path itself
   !> when it cannot be resolved (e.g. it does not exist). Two names of one file give the same
   !> canonical path.
   function canonical_path(path) result(canonical)
      !> The path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: canonical
      type(c_ptr) :: p
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i
      canonical = path
      p = c_realpath(path//c_null_char, c_null_ptr)
      if (.not. c_associated(p)) return
      n = int(c_strlen(p))
      call c_f_pointer(p, chars, [n])
      deallocate (canonical)
      allocate (character(len=n) :: canonical)
      do i = 1, n
         canonical(i:i) = chars(i)
      end do
      call c_free(p)
   end function canonical_path

   !> The process id (for unique temporary names).
   function process_id() result(pid)
      integer :: pid
      pid = int(c_getpid())
   end function process_id

end module shcontact_io_files
