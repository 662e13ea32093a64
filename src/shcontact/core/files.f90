!> File-system operations that standard Fortran lacks (rename, directories), through the C library.
!>
!> Output files are written under a temporary name and renamed when complete; checkpoints live
!> in a directory next to the output. POSIX `rename` replaces the target atomically.
module shcontact_core_files
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char, c_ptr, c_null_ptr, &
      c_associated, c_f_pointer, c_size_t
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   implicit none
   private

   public :: rename_file, delete_file, make_directory, remove_directory, file_exists
   public :: directory_part, join_path, is_absolute, process_id, canonical_path, absolute_path
   public :: path_kind, lock_file, unlock_file, pause_briefly, peak_memory_kib
   public :: lock_taken, lock_busy, lock_missing
   public :: open_work_folder, folder_made, folder_existing, folder_busy, folder_unlocked, &
      folder_link, folder_not_directory, folder_cannot_create, folder_not_writable

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
      function c_flock(fd, operation) bind(c, name='flock') result(stat)
         import :: c_int
         integer(c_int), value :: fd, operation
         integer(c_int) :: stat
      end function c_flock
      function c_errno_location() bind(c, name='__errno_location') result(p)
         import :: c_ptr
         type(c_ptr) :: p
      end function c_errno_location
      function c_usleep(microseconds) bind(c, name='usleep') result(stat)
         import :: c_int
         integer(c_int), value :: microseconds
         integer(c_int) :: stat
      end function c_usleep
   end interface

   !> Outcomes of [[lock_file]]: the lock is held, another process holds it, no lock file.
   integer, parameter :: lock_taken = 0, lock_busy = 1, lock_missing = 2
   !> Outcomes of [[open_work_folder]].
   integer, parameter :: folder_made = 0, folder_existing = 1, folder_busy = 2, &
      folder_unlocked = 3, folder_link = 4, folder_not_directory = 5, folder_cannot_create = 6, &
      folder_not_writable = 7
   !> flock(2) operations (Linux and the BSDs): exclusive, do not wait.
   integer(c_int), parameter :: lock_ex = 2, lock_nb = 4
   !> errno of a lock held by another process (EWOULDBLOCK = EAGAIN on Linux).
   integer(c_int), parameter :: errno_would_block = 11

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

   !> The path made absolute by the working directory, its own name kept (a symbolic link stays
   !> the link: its name may choose a profile format by its extension).
   function absolute_path(path) result(absolute)
      !> The path.
      character(len=*), intent(in) :: path
      character(len=:), allocatable :: absolute
      if (is_absolute(path)) then
         absolute = trim(adjustl(path))
      else
         absolute = join_path(canonical_path('.'), trim(adjustl(path)))
      end if
   end function absolute_path

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

   !> What a path names, without following a symbolic link (unless `follow`): 'none' (nothing), 'file' (a
   !> regular file), 'directory', 'link' (a symbolic link, whatever it points to), 'pipe',
   !> 'device', 'socket' or 'other'.
   function path_kind(path, follow) result(kind)
      !> The path.
      character(len=*), intent(in) :: path
      !> Follow a symbolic link (say what it points to; 'none' for a dangling one).
      logical, intent(in), optional :: follow
      character(len=:), allocatable :: kind
      integer :: values(13), status, mode
      ! lstat and stat are GNU Fortran intrinsics (POSIX lstat, stat): values(3) is st_mode.
      if (present(follow)) then
         if (follow) then
            call stat(path, values, status)
         else
            call lstat(path, values, status)
         end if
      else
         call lstat(path, values, status)
      end if
      if (status /= 0) then
         kind = 'none'
         return
      end if
      mode = iand(values(3), int(o'170000'))
      select case (mode)
      case (int(o'100000'))
         kind = 'file'
      case (int(o'040000'))
         kind = 'directory'
      case (int(o'120000'))
         kind = 'link'
      case (int(o'010000'))
         kind = 'pipe'
      case (int(o'020000'), int(o'060000'))
         kind = 'device'
      case (int(o'140000'))
         kind = 'socket'
      case default
         kind = 'other'
      end select
   end function path_kind

   !> Open the lock file `name` (created when `create`, which fails when it exists) and take
   !> an exclusive advisory lock on it (flock, not waiting). The lock lasts while `unit` is
   !> open and goes with the process, so a killed run leaves no stale lock.
   subroutine lock_file(name, create, unit, state)
      !> The lock file.
      character(len=*), intent(in) :: name
      !> Create it (exclusively) rather than open an existing one.
      logical, intent(in) :: create
      !> Its unit while the lock is held (-1 otherwise).
      integer, intent(out) :: unit
      !> lock_taken, lock_busy (another process holds it) or lock_missing (it does not exist,
      !> or, with `create`, it exists already or cannot be created).
      integer, intent(out) :: state
      integer :: stat
      unit = -1
      state = lock_missing
      if (create) then
         open (newunit=unit, file=name, status='new', action='readwrite', iostat=stat)
      else
         if (path_kind(name) /= 'file') return
         open (newunit=unit, file=name, status='old', action='readwrite', iostat=stat)
      end if
      if (stat /= 0) then
         unit = -1
         return
      end if
      ! fnum (GNU Fortran intrinsic): the POSIX file descriptor of the unit. A file system
      ! without flock (some Lustre or NFS mounts: ENOLCK, ENOSYS, EOPNOTSUPP) counts as
      ! locked: the atomic mkdir of the work folder still keeps two new runs apart.
      if (c_flock(int(fnum(unit), c_int), ior(lock_ex, lock_nb)) == 0) then
         state = lock_taken
      else if (last_errno() /= errno_would_block) then
         state = lock_taken
      else
         state = lock_busy
         close (unit)
         unit = -1
      end if
   end subroutine lock_file

   !> errno of the last failed C library call of this thread (glibc).
   function last_errno() result(code)
      integer :: code
      integer(c_int), pointer :: p
      call c_f_pointer(c_errno_location(), p)
      code = int(p)
   end function last_errno

   !> Make a work folder and hold its lock file `dir/lock_name`, or, with `take_over`, hold the
   !> lock of an existing one. A symbolic link is never followed. The creation (mkdir) is
   !> atomic, so of two processes making the same folder one makes it and the other finds it
   !> locked (it waits up to a second for the maker to create the lock file).
   subroutine open_work_folder(dir, lock_name, take_over, unit, state)
      !> The folder.
      character(len=*), intent(in) :: dir
      !> Name of the lock file inside it.
      character(len=*), intent(in) :: lock_name
      !> Take an existing folder whose lock is free (otherwise folder_unlocked is returned).
      logical, intent(in) :: take_over
      !> The lock file's unit while the lock is held (-1 otherwise).
      integer, intent(out) :: unit
      !> folder_made (new, this process made it), folder_existing (taken over), folder_busy
      !> (another process holds it), folder_unlocked (exists, not taken over), folder_link,
      !> folder_not_directory, folder_cannot_create, folder_not_writable (exists, to be taken
      !> over, but its lock file can be neither opened nor created: another user's folder).
      integer, intent(out) :: state
      integer :: attempt, lock
      character(len=:), allocatable :: kind
      unit = -1
      do attempt = 1, 20
         kind = path_kind(dir)
         select case (kind)
         case ('none')
            if (c_mkdir(dir//c_null_char, int(o'777', c_int)) == 0) then
               call lock_file(dir//'/'//lock_name, .true., unit, lock)
               state = folder_made
               if (lock /= lock_taken) then
                  ! The folder this call made goes again.
                  state = folder_cannot_create
                  if (remove_directory(dir)) continue
               end if
               return
            end if
            if (path_kind(dir) == 'none') then
               state = folder_cannot_create
               return
            end if
         case ('directory')
            call lock_file(dir//'/'//lock_name, .false., unit, lock)
            if (lock == lock_missing .and. take_over) call lock_file(dir//'/'//lock_name, &
               .true., unit, lock)
            if (lock == lock_busy) then
               state = folder_busy
               return
            else if (lock == lock_taken) then
               ! Still the folder's lock file (not one its maker just removed)?
               if (path_kind(dir//'/'//lock_name) == 'file') then
                  state = folder_existing
                  if (take_over) return
                  call unlock_file(unit)
                  state = folder_unlocked
                  return
               end if
               call unlock_file(unit)
            end if
            ! No lock file: an older or foreign folder, or one being made this instant.
            if (attempt >= 20) then
               state = folder_unlocked
               if (take_over) state = folder_not_writable
               return
            end if
            call pause_briefly()
         case ('link')
            state = folder_link
            return
         case default
            state = folder_not_directory
            return
         end select
      end do
      state = folder_busy
   end subroutine open_work_folder

   !> Release a lock taken by [[lock_file]] (nothing when `unit` < 0).
   subroutine unlock_file(unit)
      !> The lock file's unit; -1 on return.
      integer, intent(inout) :: unit
      integer :: stat
      if (unit >= 0) close (unit, iostat=stat)
      unit = -1
   end subroutine unlock_file

   !> Wait a twentieth of a second.
   subroutine pause_briefly()
      if (c_usleep(50000_c_int) /= 0) continue
   end subroutine pause_briefly

   !> The process id (for unique temporary names).
   function process_id() result(pid)
      integer :: pid
      pid = int(c_getpid())
   end function process_id


   !> The process's peak resident memory in KiB (VmHWM of /proc/self/status; 0 where there is
   !> none, e.g. outside Linux).
   integer function peak_memory_kib() result(kib)
      character(len=256) :: line
      integer :: unit, stat
      kib = 0
      open (newunit=unit, file='/proc/self/status', status='old', action='read', iostat=stat)
      if (stat /= 0) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (line(1:6) /= 'VmHWM:') cycle
         read (line(7:), *, iostat=stat) kib
         if (stat /= 0) kib = 0
         exit
      end do
      close (unit)
   end function peak_memory_kib

end module shcontact_core_files
