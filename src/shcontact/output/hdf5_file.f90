!> HDF5 files of shcontact_output_hdf5: the open file's handle, files written under a temporary
!> name and renamed when complete, files opened to read, groups, links and copies, and the
!> error that names the file and the object.
module shcontact_output_hdf5_file
   use hdf5, only: hid_t, h5open_f, h5dont_atexit_f, h5eset_auto_f, h5fcreate_f, h5fopen_f, &
      h5fclose_f, H5F_ACC_TRUNC_F, H5F_ACC_EXCL_F, H5F_ACC_RDONLY_F, h5pcreate_f, h5pclose_f, &
      H5P_LINK_CREATE_F, H5P_GROUP_CREATE_F, h5pset_obj_track_times_f, h5pset_create_inter_group_f, &
      h5gcreate_f, h5gclose_f, h5ocopy_f, h5lexists_f, h5oopen_f
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   use shcontact_core_files, only: rename_file, delete_file, process_id, path_kind
   use shcontact_core_strings, only: str_int
   implicit none
   private

   public :: h5_file_type, description_function, h5_create, h5_commit, h5_discard, h5_open, &
      h5_close, h5_skip_exit_cleanup, h5_make_group, h5_exists, h5_copy, open_object, fail

   abstract interface
      !> The `long_name` of the dataset at `path` ('' for none).
      pure subroutine description_function(path, text)
         character(len=*), intent(in) :: path
         character(len=:), allocatable, intent(out) :: text
      end subroutine description_function
   end interface

   !> An open HDF5 file.
   type :: h5_file_type
      !> HDF5 identifier (−1 when closed).
      integer(hid_t) :: id = -1
      !> The file's final name.
      character(len=:), allocatable :: name
      !> The name it is written under until [[h5_commit]] ('' for files opened to read).
      character(len=:), allocatable :: temp_name
      !> Deflate level for datasets written with `compress = .true.` (0: none).
      integer :: compression = 0
      !> Store real datasets written with `compress = .true.` as 32-bit floats.
      logical :: single = .false.
      !> Gives every dataset written its `long_name` attribute, when associated.
      procedure(description_function), pointer, nopass :: describe => null()
      !> Make and attach dimension scales ([[h5_set_scale]], [[h5_attach_scale]] do nothing
      !> when .false.: a checkpoint block, whose scales the merge makes afresh).
      logical :: scales = .true.
   end type h5_file_type

contains

   ! ------------------------------------------------------------------------------------------
   ! Files
   ! ------------------------------------------------------------------------------------------

   !> For a program that closes every file it writes (the shcontact program): the HDF5
   !> library is not to close what is left open when the process ends. A file whose close
   !> failed (a full disk) stays open inside the library, and its clean-up at exit then
   !> crashed the program (signal 11 instead of the I/O status 3). Effective only before the
   !> library's first use; a library caller keeps HDF5's default.
   subroutine h5_skip_exit_cleanup()
      integer :: stat
      call h5dont_atexit_f(stat)
   end subroutine h5_skip_exit_cleanup

   !> Start the library once per call (idempotent) and silence its error printing.
   subroutine start_library(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      call h5open_f(stat)
      if (stat /= 0) then
         call fatal_error(error, 'the HDF5 library could not be initialised', stat_io)
         return
      end if
      call h5eset_auto_f(0, stat)
   end subroutine start_library

   !> Create `name` for writing; the data go to `name.tmp<pid>` (or `temp_name`) until
   !> [[h5_commit]].
   subroutine h5_create(file, name, error, compression, single, temp_name, describe, scales)
      !> The new file.
      type(h5_file_type), intent(out) :: file
      !> Final file name.
      character(len=*), intent(in) :: name
      !> Set when the file cannot be created.
      type(error_type), allocatable, intent(out) :: error
      !> Deflate level for compressed datasets (default 0).
      integer, intent(in), optional :: compression
      !> Store compressed real datasets as 32-bit floats.
      logical, intent(in), optional :: single
      !> Temporary name to write to (in the same file system as `name`); a name the caller can
      !> find again to clean up after a kill, e.g. inside a checkpoint directory.
      character(len=*), intent(in), optional :: temp_name
      !> The description of each dataset, written as its `long_name` attribute.
      procedure(description_function), optional :: describe
      !> Make dimension scales (default .true.).
      logical, intent(in), optional :: scales
      integer :: stat, access

      call start_library(error)
      if (allocated(error)) return
      if (present(describe)) file%describe => describe
      file%name = name
      ! The default temporary name is created exclusively (a file of that name is never
      ! overwritten); a given one is the caller's own name (e.g. in its work folder).
      file%temp_name = name//'.tmp'//str_int(process_id())
      access = H5F_ACC_EXCL_F
      if (present(temp_name)) then
         file%temp_name = temp_name
         access = H5F_ACC_TRUNC_F
      end if
      if (present(compression)) file%compression = compression
      if (present(single)) file%single = single
      if (present(scales)) file%scales = scales
      if (access == H5F_ACC_EXCL_F .and. path_kind(file%temp_name) /= 'none') then
         call fatal_error(error, 'cannot write "'//name//'": its temporary name "'// &
            file%temp_name//'" is taken (by a file shcontact does not overwrite)', stat_io)
         file%id = -1
         file%temp_name = ''
         return
      end if
      call h5fcreate_f(file%temp_name, access, file%id, stat)
      if (stat /= 0) then
         file%id = -1
         ! Not ours: never removed by h5_discard.
         file%temp_name = ''
         call fatal_error(error, 'cannot create the output file "'//name// &
            '" (is the directory there and writable?)', stat_io)
      end if
   end subroutine h5_create

   !> Close a file being written and give it its final name.
   subroutine h5_commit(file, error)
      !> The file; closed afterwards.
      type(h5_file_type), intent(inout) :: file
      !> Set when closing or renaming fails (the temporary file is then removed).
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      call h5fclose_f(file%id, stat)
      file%id = -1
      if (stat /= 0) then
         call fatal_error(error, 'cannot finish writing "'//file%name//'"', stat_io)
         if (delete_file(file%temp_name)) continue
         return
      end if
      call rename_file(file%temp_name, file%name, error)
      if (allocated(error)) then
         if (delete_file(file%temp_name)) continue
      end if
   end subroutine h5_commit

   !> Abandon a file being written: close it and remove the temporary file.
   subroutine h5_discard(file)
      !> The file; closed afterwards.
      type(h5_file_type), intent(inout) :: file
      integer :: stat
      if (file%id >= 0) call h5fclose_f(file%id, stat)
      file%id = -1
      if (allocated(file%temp_name)) then
         if (len(file%temp_name) > 0) then
            if (delete_file(file%temp_name)) continue
         end if
      end if
   end subroutine h5_discard

   !> Open an existing file to read.
   subroutine h5_open(file, name, error)
      !> The file.
      type(h5_file_type), intent(out) :: file
      !> Its name.
      character(len=*), intent(in) :: name
      !> Set when it cannot be opened as HDF5.
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      character(len=:), allocatable :: kind
      call start_library(error)
      if (allocated(error)) return
      file%name = name
      file%temp_name = ''
      ! Only a regular file (opening a pipe would wait for a writer).
      kind = path_kind(name, follow=.true.)
      if (kind == 'none') then
         call fatal_error(error, 'cannot open "'//name//'": no such file', stat_io)
         return
      else if (kind /= 'file') then
         call fatal_error(error, 'cannot open "'//name//'": it is a '//kind//', not a '// &
            'regular file', stat_io)
         return
      end if
      call h5fopen_f(name, H5F_ACC_RDONLY_F, file%id, stat)
      if (stat /= 0) then
         file%id = -1
         call fatal_error(error, 'cannot open "'//name//'" as an HDF5 file', stat_io)
      end if
   end subroutine h5_open

   !> Close a file opened to read (or abandon one being written).
   subroutine h5_close(file)
      !> The file.
      type(h5_file_type), intent(inout) :: file
      call h5_discard(file)
   end subroutine h5_close

   ! ------------------------------------------------------------------------------------------
   ! Groups, links, copies
   ! ------------------------------------------------------------------------------------------

   !> Create a group (and its missing parents).
   subroutine h5_make_group(file, path, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Group path.
      character(len=*), intent(in) :: path
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: gid, lcpl, gcpl
      integer :: stat, s
      call h5pcreate_f(H5P_LINK_CREATE_F, lcpl, stat)
      call h5pset_create_inter_group_f(lcpl, 1, s)
      call h5pcreate_f(H5P_GROUP_CREATE_F, gcpl, s)
      call h5pset_obj_track_times_f(gcpl, .false., s)
      call h5gcreate_f(file%id, path, gid, stat, lcpl_id=lcpl, gcpl_id=gcpl)
      if (stat == 0) call h5gclose_f(gid, s)
      call h5pclose_f(gcpl, s)
      call h5pclose_f(lcpl, s)
      if (stat /= 0) call fail(error, file, path, 'cannot create the group')
   end subroutine h5_make_group

   !> True when a link of that path exists (every parent is checked first).
   function h5_exists(file, path) result(exists)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path.
      character(len=*), intent(in) :: path
      logical :: exists
      integer :: stat, i, j
      exists = .false.
      i = 0
      do
         j = index(path(i + 1:), '/')
         if (j == 0) then
            call h5lexists_f(file%id, path, exists, stat)
            if (stat /= 0) exists = .false.
            return
         end if
         i = i + j
         if (i > 1) then
            call h5lexists_f(file%id, path(1:i - 1), exists, stat)
            if (stat /= 0 .or. .not. exists) then
               exists = .false.
               return
            end if
         end if
      end do
   end function h5_exists

   !> Copy an object (a group with everything under it, or a dataset) between files. Object
   !> references (dimension scales) do not survive a copy to another file: attach them again.
   subroutine h5_copy(source, path, target, target_path, error)
      !> File to copy from.
      type(h5_file_type), intent(in) :: source
      !> Object in it.
      character(len=*), intent(in) :: path
      !> File to copy to.
      type(h5_file_type), intent(in) :: target
      !> Destination path (its parent groups are created).
      character(len=*), intent(in) :: target_path
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: lcpl
      integer :: stat, s
      call h5pcreate_f(H5P_LINK_CREATE_F, lcpl, stat)
      call h5pset_create_inter_group_f(lcpl, 1, s)
      call h5ocopy_f(source%id, path, target%id, target_path, stat, lcpl_id=lcpl)
      call h5pclose_f(lcpl, s)
      if (stat /= 0) call fatal_error(error, 'cannot copy "'//path//'" from "'//source%name// &
         '" to "'//target%name//'"', stat_io)
   end subroutine h5_copy


   !> Open the object at `path` ('/' for the root).
   subroutine open_object(file, path, obj, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(out) :: obj
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      call h5oopen_f(file%id, path, obj, stat)
      if (stat /= 0) call fail(error, file, path, 'no such object')
   end subroutine open_object

   !> An I/O error naming the file and the object.
   subroutine fail(error, file, path, what)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path, what
      call fatal_error(error, file%name//': '//path//': '//what, stat_io)
   end subroutine fail

end module shcontact_output_hdf5_file
