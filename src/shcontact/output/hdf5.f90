!> HDF5 behind one module: files written under a temporary name and renamed when complete,
!> datasets with a `units` attribute (and a `long_name` when the file was created with a
!> description function), dimension scales (H5DS), optional deflate compression, every handle
!> closed on every path, errors as values (the HDF5 library's own error printing is switched
!> off).
!>
!> Paths are slash-separated from the root (`cases/000001/patch_1/normal/a`); missing
!> intermediate groups are created. Object modification times are not recorded, so the same
!> content written in the same order gives the same bytes. Fortran arrays keep their memory
!> order: a Fortran (n1, n2) array is seen by C and h5py as shape (n2, n1).
module shcontact_output_hdf5
   use, intrinsic :: iso_c_binding, only: c_loc, c_ptr
   use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5dont_atexit_f, h5eset_auto_f, h5fcreate_f, h5fopen_f, &
      h5fclose_f, H5F_ACC_TRUNC_F, H5F_ACC_EXCL_F, H5F_ACC_RDONLY_F, h5pcreate_f, h5pclose_f, &
      H5P_DATASET_CREATE_F, H5P_LINK_CREATE_F, H5P_GROUP_CREATE_F, h5pset_chunk_f, &
      h5pset_deflate_f, h5pset_obj_track_times_f, h5pset_create_inter_group_f, h5screate_f, &
      h5screate_simple_f, h5sclose_f, H5S_SCALAR_F, h5dcreate_f, h5dopen_f, h5dclose_f, &
      h5dwrite_f, h5dread_f, h5dget_space_f, h5dget_type_f, h5sget_simple_extent_ndims_f, &
      h5sget_simple_extent_dims_f, h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5tclose_f, &
      h5tget_size_f, H5T_C_S1, H5T_STR_NULLPAD_F, H5T_NATIVE_DOUBLE, H5T_NATIVE_REAL, &
      H5T_NATIVE_INTEGER, H5T_STD_I8LE, H5T_STD_I32LE, H5T_IEEE_F64LE, h5kind_to_type, &
      H5_INTEGER_KIND, h5acreate_f, h5aopen_f, h5aclose_f, h5awrite_f, h5aread_f, &
      h5aexists_by_name_f, h5aget_type_f, h5gcreate_f, h5gclose_f, h5ocopy_f, h5lexists_f, &
      h5oopen_f, h5oclose_f, H5T_IEEE_F32LE, h5tget_class_f, H5T_FLOAT_F, h5adelete_f, &
      H5T_INTEGER_F, H5T_STRING_F, h5tis_variable_str_f
   ! HDF5's high-level Fortran library (libhdf5hl_fortran, linked by fpm's hdf5 metapackage).
   use h5ds, only: h5dsset_scale_f, h5dsattach_scale_f, h5dsset_label_f
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   use shcontact_core_files, only: rename_file, delete_file, process_id, path_kind
   use shcontact_core_strings, only: str_int
   implicit none
   private

   public :: h5_file_type, h5_create, h5_commit, h5_discard, h5_open, h5_close
   public :: h5_write, h5_write_attribute, h5_make_group, h5_copy, h5_exists
   public :: h5_read, h5_read_attribute, h5_dataset_size
   public :: h5_skip_exit_cleanup
   public :: h5_set_scale, h5_attach_scale, h5_set_dim_label, h5_dataset_info, h5_delete_attribute
   public :: description_function

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

   !> Write a dataset (real: scalar to 3-D; integer, int8 or text; scalar, 1-D or 2-D) with its
   !> units.
   interface h5_write
      module procedure :: write_real_0d, write_real_1d, write_real_2d, write_real_3d, &
         write_int_0d, write_int_1d, write_int8_2d, write_text_0d, write_text_1d
   end interface h5_write

   !> Write a scalar attribute (text, real or integer) on a group or dataset.
   interface h5_write_attribute
      module procedure :: attr_text, attr_real, attr_int
   end interface h5_write_attribute

   !> Read a dataset into an allocatable array or a text.
   interface h5_read
      module procedure :: read_real_0d, read_real_1d, read_real_2d, read_int_1d, read_text_0d, &
         read_text_1d
   end interface h5_read

   !> Read a scalar attribute.
   interface h5_read_attribute
      module procedure :: read_attr_text, read_attr_int, read_attr_real
   end interface h5_read_attribute

   !> Datasets smaller than this are stored contiguously, without compression.
   integer, parameter :: min_compressed_size = 256

   !> The extent of a scalar dataset (no dimensions).
   integer(hsize_t), parameter :: scalar(0) = [integer(hsize_t) ::]

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

   ! ------------------------------------------------------------------------------------------
   ! Writing datasets
   ! ------------------------------------------------------------------------------------------

   !> Create a dataset of the given file type and shape; compressed and chunked when asked and
   !> large enough. Returns the dataset; the caller writes and closes it.
   subroutine create_dataset(file, path, type_id, dims, compress, dset, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(in) :: type_id
      integer(hsize_t), intent(in) :: dims(:)
      logical, intent(in) :: compress
      integer(hid_t), intent(out) :: dset
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: space, dcpl, lcpl
      integer :: stat, s

      if (size(dims) == 0) then
         call h5screate_f(H5S_SCALAR_F, space, stat)
      else
         call h5screate_simple_f(size(dims), dims, space, stat)
      end if
      if (stat /= 0) then
         call fail(error, file, path, 'cannot create the data space')
         return
      end if
      call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, s)
      call h5pset_obj_track_times_f(dcpl, .false., s)
      if (compress .and. file%compression > 0 .and. size(dims) > 0) then
         if (product(dims) >= min_compressed_size) then
            call h5pset_chunk_f(dcpl, size(dims), dims, s)
            call h5pset_deflate_f(dcpl, file%compression, s)
         end if
      end if
      call h5pcreate_f(H5P_LINK_CREATE_F, lcpl, s)
      call h5pset_create_inter_group_f(lcpl, 1, s)
      call h5dcreate_f(file%id, path, type_id, space, dset, stat, dcpl_id=dcpl, lcpl_id=lcpl)
      call h5pclose_f(lcpl, s)
      call h5pclose_f(dcpl, s)
      call h5sclose_f(space, s)
      if (stat /= 0) call fail(error, file, path, 'cannot create the dataset')
   end subroutine create_dataset

   !> The file type of a real dataset: 32-bit when the file stores compressed fields in single
   !> precision, else 64-bit.
   integer(hid_t) function real_file_type(file, compress)
      type(h5_file_type), intent(in) :: file
      logical, intent(in) :: compress
      real_file_type = H5T_IEEE_F64LE
      if (compress .and. file%single) real_file_type = H5T_IEEE_F32LE
   end function real_file_type

   !> Finish a write: check its status, attach the units, close the dataset.
   subroutine finish_dataset(file, path, dset, stat, units, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(inout) :: dset
      integer, intent(in) :: stat
      character(len=*), intent(in) :: units
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      integer :: s
      if (stat /= 0) then
         call h5dclose_f(dset, s)
         call fail(error, file, path, 'cannot write the dataset')
         return
      end if
      call put_text_attribute(dset, 'units', units, s)
      if (s == 0 .and. associated(file%describe)) then
         call file%describe(path, text)
         call put_description(dset, text, s)
      end if
      call h5dclose_f(dset, s)
      if (s /= 0) call fail(error, file, path, 'cannot write the units of the dataset')
   end subroutine finish_dataset

   subroutine write_real_0d(file, path, value, units, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The value.
      real(wp), intent(in) :: value
      !> Its units ('1' for dimensionless).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      call write_reals(file, path, [value], scalar, units, error)
   end subroutine write_real_0d

   subroutine write_real_1d(file, path, values, units, error, compress)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values.
      real(wp), intent(in) :: values(:)
      !> Their units ('1' for dimensionless).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      !> Apply the file's compression and precision settings (a per-element field).
      logical, intent(in), optional :: compress
      call write_reals(file, path, values, shape(values, kind=hsize_t), units, error, compress)
   end subroutine write_real_1d

   subroutine write_real_2d(file, path, values, units, error, compress)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values (seen as shape (n2, n1) from C and h5py).
      real(wp), intent(in) :: values(:, :)
      !> Their units ('1' for dimensionless).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      !> Apply the file's compression and precision settings (a per-element field).
      logical, intent(in), optional :: compress
      call write_reals(file, path, values, shape(values, kind=hsize_t), units, error, compress)
   end subroutine write_real_2d

   subroutine write_real_3d(file, path, values, units, error, compress)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values (seen as shape (n3, n2, n1) from C and h5py).
      real(wp), intent(in) :: values(:, :, :)
      !> Their units ('1' for dimensionless).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      !> Apply the file's compression and precision settings (a per-element field).
      logical, intent(in), optional :: compress
      call write_reals(file, path, values, shape(values, kind=hsize_t), units, error, compress)
   end subroutine write_real_3d

   !> Write a real dataset of any rank with its units: `dims` is its extent ([[scalar]] for a
   !> scalar), `values` its elements in array element order (the writers of each rank pass
   !> their array as it is, by sequence association).
   subroutine write_reals(file, path, values, dims, units, error, compress)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hsize_t), intent(in) :: dims(:)
      real(wp), intent(in) :: values(product(dims))
      character(len=*), intent(in) :: units
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: compress
      integer(hid_t) :: dset
      integer :: stat
      logical :: pack
      pack = .false.
      if (present(compress)) pack = compress
      call create_dataset(file, path, real_file_type(file, pack), dims, pack, dset, error)
      if (allocated(error)) return
      call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, shape(values, kind=hsize_t), stat)
      call finish_dataset(file, path, dset, stat, units, error)
   end subroutine write_reals

   subroutine write_int_0d(file, path, value, units, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The value.
      integer, intent(in) :: value
      !> Its units ('1' for counts and codes).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      call write_ints(file, path, [value], scalar, units, error)
   end subroutine write_int_0d

   subroutine write_int_1d(file, path, values, units, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values.
      integer, intent(in) :: values(:)
      !> Their units ('1' for counts and codes).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      call write_ints(file, path, values, shape(values, kind=hsize_t), units, error)
   end subroutine write_int_1d

   !> Write a 32-bit integer dataset of any rank with its units, as [[write_reals]].
   subroutine write_ints(file, path, values, dims, units, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hsize_t), intent(in) :: dims(:)
      integer, intent(in) :: values(product(dims))
      character(len=*), intent(in) :: units
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: stat
      call create_dataset(file, path, H5T_STD_I32LE, dims, .false., dset, error)
      if (allocated(error)) return
      call h5dwrite_f(dset, H5T_NATIVE_INTEGER, values, shape(values, kind=hsize_t), stat)
      call finish_dataset(file, path, dset, stat, units, error)
   end subroutine write_ints

   subroutine write_int8_2d(file, path, values, units, error, compress)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values.
      integer(i1), intent(in) :: values(:, :)
      !> Their units ('1' for codes).
      character(len=*), intent(in) :: units
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      !> Apply the file's compression (a per-element field).
      logical, intent(in), optional :: compress
      integer(i1), allocatable, target :: buf(:, :)
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(2)
      integer :: stat
      logical :: pack
      type(c_ptr) :: ptr
      pack = .false.
      if (present(compress)) pack = compress
      dims = shape(values, kind=hsize_t)
      call create_dataset(file, path, H5T_STD_I8LE, dims, pack, dset, error)
      if (allocated(error)) return
      buf = values
      stat = 0
      if (size(buf) > 0) then
         ptr = c_loc(buf(1, 1))
         call h5dwrite_f(dset, h5kind_to_type(i1, H5_INTEGER_KIND), ptr, stat)
      end if
      call finish_dataset(file, path, dset, stat, units, error)
   end subroutine write_int8_2d

   subroutine write_text_0d(file, path, text, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The text (stored as a fixed-length string, no units attribute needed but one is
      !> written as '' for uniformity).
      character(len=*), intent(in) :: text
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      if (len(text) > 0) then
         call write_strings(file, path, [text], scalar, error)
      else
         call write_strings(file, path, [achar(0)], scalar, error)
      end if
   end subroutine write_text_0d

   subroutine write_text_1d(file, path, texts, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The texts (trailing blanks are not stored).
      character(len=*), intent(in) :: texts(:)
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer :: n
      n = 1
      if (size(texts) > 0) n = max(1, maxval(len_trim(texts)))
      call write_fixed(n)

   contains

      !> Write the texts NUL-padded to n characters.
      subroutine write_fixed(n)
         integer, intent(in) :: n
         character(len=n) :: buf(size(texts))
         integer :: i
         do i = 1, size(texts)
            buf(i) = repeat(achar(0), n)
            buf(i)(1:len_trim(texts(i))) = texts(i)(1:len_trim(texts(i)))
         end do
         call write_strings(file, path, buf, shape(texts, kind=hsize_t), error)
      end subroutine write_fixed

   end subroutine write_text_1d

   !> Write a text dataset of any rank, as [[write_reals]]: fixed-length strings of
   !> len(texts) bytes, NUL-padded, with an empty `units` attribute.
   subroutine write_strings(file, path, texts, dims, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hsize_t), intent(in) :: dims(:)
      character(len=*), intent(in) :: texts(product(dims))
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset, str
      integer :: stat, s
      call make_string_type(len(texts), str, stat)
      call create_dataset(file, path, str, dims, .false., dset, error)
      if (allocated(error)) then
         call h5tclose_f(str, s)
         return
      end if
      call h5dwrite_f(dset, str, texts, shape(texts, kind=hsize_t), stat)
      call h5tclose_f(str, s)
      call finish_dataset(file, path, dset, stat, '', error)
   end subroutine write_strings

   !> A C string type of n bytes, null-padded.
   subroutine make_string_type(n, str, stat)
      integer, intent(in) :: n
      integer(hid_t), intent(out) :: str
      integer, intent(out) :: stat
      integer :: s
      call h5tcopy_f(H5T_C_S1, str, stat)
      call h5tset_size_f(str, int(n, size_t), s)
      call h5tset_strpad_f(str, H5T_STR_NULLPAD_F, s)
   end subroutine make_string_type

   ! ------------------------------------------------------------------------------------------
   ! Attributes
   ! ------------------------------------------------------------------------------------------

   !> Write a scalar text attribute on an open object.
   subroutine put_text_attribute(obj, name, text, stat)
      integer(hid_t), intent(in) :: obj
      character(len=*), intent(in) :: name, text
      integer, intent(out) :: stat
      integer(hid_t) :: space, str, attr
      integer(hsize_t) :: dims(0)
      integer :: s
      call h5screate_f(H5S_SCALAR_F, space, stat)
      if (stat /= 0) return
      call make_string_type(max(1, len(text)), str, s)
      call h5acreate_f(obj, name, str, space, attr, stat)
      if (stat == 0) then
         if (len(text) > 0) then
            call h5awrite_f(attr, str, text, dims, stat)
         else
            call h5awrite_f(attr, str, achar(0), dims, stat)
         end if
         call h5aclose_f(attr, s)
      end if
      call h5tclose_f(str, s)
      call h5sclose_f(space, s)
   end subroutine put_text_attribute

   !> Write the `long_name` attribute (nothing for an empty description).
   subroutine put_description(obj, text, stat)
      integer(hid_t), intent(in) :: obj
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      stat = 0
      if (len(text) > 0) call put_text_attribute(obj, 'long_name', text, stat)
   end subroutine put_description

   ! ------------------------------------------------------------------------------------------
   ! Dimension scales (HDF5 high-level library, H5DS)
   ! ------------------------------------------------------------------------------------------

   !> Make the dataset at `path` a dimension scale named `name`.
   subroutine h5_set_scale(file, path, name, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path (a 1-D dataset).
      character(len=*), intent(in) :: path
      !> Name of the dimension it measures.
      character(len=*), intent(in) :: name
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: stat, s
      if (.not. file%scales) return
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot open the dataset')
         return
      end if
      call h5dsset_scale_f(dset, stat, name)
      call h5dclose_f(dset, s)
      if (stat /= 0) call fail(error, file, path, 'cannot make it a dimension scale')
   end subroutine h5_set_scale

   !> Attach the dimension scale at `scale_path` to dimension `dim` of the dataset at `path`.
   subroutine h5_attach_scale(file, path, scale_path, dim, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Path of a dataset made a scale by [[h5_set_scale]].
      character(len=*), intent(in) :: scale_path
      !> Dimension of the Fortran array written (1 is the fastest; C and h5py see it last).
      integer, intent(in) :: dim
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset, scale
      integer :: stat, s
      if (.not. file%scales) return
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot open the dataset')
         return
      end if
      call h5dopen_f(file%id, scale_path, scale, stat)
      if (stat == 0) then
         call h5dsattach_scale_f(dset, scale, h5ds_index(dset, dim), stat)
         call h5dclose_f(scale, s)
      end if
      call h5dclose_f(dset, s)
      if (stat /= 0) call fail(error, file, path, 'cannot attach the dimension scale '// &
         scale_path)
   end subroutine h5_attach_scale

   !> Label dimension `dim` (Fortran order, as in [[h5_attach_scale]]) of a dataset.
   subroutine h5_set_dim_label(file, path, dim, label, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Dimension of the Fortran array written.
      integer, intent(in) :: dim
      !> The label.
      character(len=*), intent(in) :: label
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer :: stat, s
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot open the dataset')
         return
      end if
      call h5dsset_label_f(dset, h5ds_index(dset, dim), label, stat)
      call h5dclose_f(dset, s)
      if (stat /= 0) call fail(error, file, path, 'cannot label dimension '//str_int(dim))
   end subroutine h5_set_dim_label

   !> The index that HDF5's Fortran H5DS routines take for dimension `dim` (Fortran order) of a
   !> dataset: they count from 1 in C order (slowest first), unlike the rest of the Fortran API.
   integer function h5ds_index(dset, dim)
      integer(hid_t), intent(in) :: dset
      integer, intent(in) :: dim
      integer(hid_t) :: space
      integer :: rank, s
      call h5dget_space_f(dset, space, s)
      call h5sget_simple_extent_ndims_f(space, rank, s)
      call h5sclose_f(space, s)
      h5ds_index = rank - dim + 1
   end function h5ds_index

   !> Shape (Fortran order), element size in bytes and kind (float or not) of a dataset.
   subroutine h5_dataset_info(file, path, dims, type_size, is_float, error, type_class)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> Its extent, as the Fortran array it was written from (empty for a scalar).
      integer, allocatable, intent(out) :: dims(:)
      !> Bytes per element.
      integer, intent(out) :: type_size
      !> True for a floating-point dataset.
      logical, intent(out) :: is_float
      !> Set when it does not exist or cannot be read.
      type(error_type), allocatable, intent(out) :: error
      !> 'integer', 'float', 'text' (fixed-length strings), 'variable-length text' or 'other'.
      character(len=:), allocatable, intent(out), optional :: type_class
      integer(hid_t) :: dset, space, dtype
      integer(hsize_t) :: d(8), maxd(8)
      integer(size_t) :: n
      integer :: stat, s, ndims, class
      logical :: variable
      type_size = 0
      is_float = .false.
      if (present(type_class)) type_class = 'other'
      allocate (dims(0))
      if (.not. h5_exists(file, path)) then
         call fail(error, file, path, 'no such dataset')
         return
      end if
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot open the dataset')
         return
      end if
      call h5dget_space_f(dset, space, s)
      call h5sget_simple_extent_ndims_f(space, ndims, s)
      ndims = min(max(ndims, 0), size(d))
      if (ndims > 0) call h5sget_simple_extent_dims_f(space, d(1:ndims), maxd(1:ndims), s)
      dims = int(d(1:ndims))
      call h5sclose_f(space, s)
      call h5dget_type_f(dset, dtype, s)
      call h5tget_size_f(dtype, n, s)
      call h5tget_class_f(dtype, class, s)
      type_size = int(n)
      is_float = class == H5T_FLOAT_F
      if (present(type_class)) then
         if (class == H5T_INTEGER_F) type_class = 'integer'
         if (class == H5T_FLOAT_F) type_class = 'float'
         if (class == H5T_STRING_F) then
            variable = .false.
            call h5tis_variable_str_f(dtype, variable, s)
            type_class = 'text'
            if (variable) type_class = 'variable-length text'
         end if
      end if
      call h5tclose_f(dtype, s)
      call h5dclose_f(dset, s)
   end subroutine h5_dataset_info

   !> Delete an attribute of an object, when it has one.
   subroutine h5_delete_attribute(file, path, name, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path.
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> Set when it exists and cannot be deleted.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: obj
      logical :: exists
      integer :: stat, s
      call h5aexists_by_name_f(file%id, path, name, exists, stat)
      if (stat /= 0 .or. .not. exists) return
      call open_object(file, path, obj, error)
      if (allocated(error)) return
      call h5adelete_f(obj, name, stat)
      call h5oclose_f(obj, s)
      if (stat /= 0) call fail(error, file, path, 'cannot delete the attribute '//name)
   end subroutine h5_delete_attribute

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

   subroutine attr_text(file, path, name, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path ('/' for the root group).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> The text.
      character(len=*), intent(in) :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: obj
      integer :: stat, s
      call open_object(file, path, obj, error)
      if (allocated(error)) return
      call put_text_attribute(obj, name, value, stat)
      call h5oclose_f(obj, s)
      if (stat /= 0) call fail(error, file, path, 'cannot write the attribute '//name)
   end subroutine attr_text

   subroutine attr_real(file, path, name, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path ('/' for the root group).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> The value.
      real(wp), intent(in), target :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      call write_scalar_attribute(file, path, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &
         c_loc(value), error)
   end subroutine attr_real

   subroutine attr_int(file, path, name, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path ('/' for the root group).
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> The value.
      integer, intent(in), target :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      call write_scalar_attribute(file, path, name, H5T_STD_I32LE, H5T_NATIVE_INTEGER, &
         c_loc(value), error)
   end subroutine attr_int

   !> Write a scalar numeric attribute: stored as `file_type`, read from `buf` as `mem_type`.
   subroutine write_scalar_attribute(file, path, name, file_type, mem_type, buf, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path, name
      integer(hid_t), intent(in) :: file_type, mem_type
      type(c_ptr), intent(in) :: buf
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: obj, space, attr
      integer :: stat, s
      call open_object(file, path, obj, error)
      if (allocated(error)) return
      call h5screate_f(H5S_SCALAR_F, space, s)
      call h5acreate_f(obj, name, file_type, space, attr, stat)
      if (stat == 0) then
         call h5awrite_f(attr, mem_type, buf, stat)
         call h5aclose_f(attr, s)
      end if
      call h5sclose_f(space, s)
      call h5oclose_f(obj, s)
      if (stat /= 0) call fail(error, file, path, 'cannot write the attribute '//name)
   end subroutine write_scalar_attribute

   ! ------------------------------------------------------------------------------------------
   ! Reading
   ! ------------------------------------------------------------------------------------------

   !> Open a dataset and get its shape (rank must be `rank`, or ≤ `rank` for 0).
   subroutine open_dataset(file, path, rank, dset, dims, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer, intent(in) :: rank
      integer(hid_t), intent(out) :: dset
      integer(hsize_t), intent(out) :: dims(max(rank, 1))
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: space
      integer(hsize_t) :: maxdims(max(rank, 1))
      integer :: stat, s, ndims
      if (.not. h5_exists(file, path)) then
         call fail(error, file, path, 'no such dataset')
         return
      end if
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot open the dataset')
         return
      end if
      call h5dget_space_f(dset, space, s)
      call h5sget_simple_extent_ndims_f(space, ndims, s)
      dims = 1
      if (ndims == rank) then
         if (rank > 0) call h5sget_simple_extent_dims_f(space, dims, maxdims, s)
      else
         call fail(error, file, path, 'expected rank '//str_int(rank)//', found '// &
            str_int(ndims))
      end if
      call h5sclose_f(space, s)
      if (allocated(error)) call h5dclose_f(dset, s)
   end subroutine open_dataset

   !> Number of elements of a dataset (0 when it does not exist).
   function h5_dataset_size(file, path) result(n)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      integer :: n
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(8), maxdims(8)
      integer :: stat, s, ndims
      n = 0
      if (.not. h5_exists(file, path)) return
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) return
      call h5dget_space_f(dset, space, s)
      call h5sget_simple_extent_ndims_f(space, ndims, s)
      dims = 1
      if (ndims > 0) call h5sget_simple_extent_dims_f(space, dims(1:ndims), maxdims(1:ndims), s)
      n = int(product(dims(1:max(ndims, 1))))
      if (ndims == 0) n = 1
      call h5sclose_f(space, s)
      call h5dclose_f(dset, s)
   end function h5_dataset_size

   subroutine read_real_0d(file, path, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path (a scalar dataset).
      character(len=*), intent(in) :: path
      !> The value.
      real(wp), intent(out) :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      integer :: stat, s
      value = 0.0_wp
      call open_dataset(file, path, 0, dset, dims, error)
      if (allocated(error)) return
      call h5dread_f(dset, H5T_NATIVE_DOUBLE, value, dims, stat)
      call h5dclose_f(dset, s)
      if (stat /= 0) call fail(error, file, path, 'cannot read the dataset')
   end subroutine read_real_0d

   subroutine read_real_1d(file, path, values, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values.
      real(wp), allocatable, intent(out) :: values(:)
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      call open_dataset(file, path, 1, dset, dims, error)
      if (allocated(error)) return
      allocate (values(dims(1)))
      call read_reals(file, path, dset, values, size(values, kind=hsize_t), error)
   end subroutine read_real_1d

   subroutine read_real_2d(file, path, values, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values.
      real(wp), allocatable, intent(out) :: values(:, :)
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(2)
      call open_dataset(file, path, 2, dset, dims, error)
      if (allocated(error)) return
      allocate (values(dims(1), dims(2)))
      call read_reals(file, path, dset, values, size(values, kind=hsize_t), error)
   end subroutine read_real_2d

   subroutine read_int_1d(file, path, values, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path.
      character(len=*), intent(in) :: path
      !> The values.
      integer, allocatable, intent(out) :: values(:)
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset
      integer(hsize_t) :: dims(1)
      call open_dataset(file, path, 1, dset, dims, error)
      if (allocated(error)) return
      allocate (values(dims(1)))
      call read_ints(file, path, dset, values, size(values, kind=hsize_t), error)
   end subroutine read_int_1d

   !> Read the whole of the open dataset `dset` as `n` reals (Fortran order) and close it.
   subroutine read_reals(file, path, dset, values, n, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(in) :: dset
      integer(hsize_t), intent(in) :: n
      real(wp), intent(out) :: values(n)
      type(error_type), allocatable, intent(out) :: error
      integer :: stat, s
      call h5dread_f(dset, H5T_NATIVE_DOUBLE, values, [n], stat)
      call h5dclose_f(dset, s)
      if (stat /= 0) call fail(error, file, path, 'cannot read the dataset')
   end subroutine read_reals

   !> Read the whole of the open dataset `dset` as `n` integers, as [[read_reals]].
   subroutine read_ints(file, path, dset, values, n, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(in) :: dset
      integer(hsize_t), intent(in) :: n
      integer, intent(out) :: values(n)
      type(error_type), allocatable, intent(out) :: error
      integer :: stat, s
      call h5dread_f(dset, H5T_NATIVE_INTEGER, values, [n], stat)
      call h5dclose_f(dset, s)
      if (stat /= 0) call fail(error, file, path, 'cannot read the dataset')
   end subroutine read_ints

   subroutine read_text_0d(file, path, text, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path of a scalar text.
      character(len=*), intent(in) :: path
      !> The text (padding removed).
      character(len=:), allocatable, intent(out) :: text
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset, str
      integer(hsize_t) :: dims(1)
      integer(size_t) :: n
      integer :: stat, s
      call open_dataset(file, path, 0, dset, dims, error)
      if (allocated(error)) return
      call h5dget_type_f(dset, str, s)
      call h5tget_size_f(str, n, s)
      allocate (character(len=n) :: text)
      text = repeat(achar(0), n)
      call h5dread_f(dset, str, text, dims(1:0), stat)
      call h5tclose_f(str, s)
      call h5dclose_f(dset, s)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot read the text')
         return
      end if
      text = unpad(text)
   end subroutine read_text_0d

   subroutine read_text_1d(file, path, texts, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Dataset path of a 1-D fixed-length text array.
      character(len=*), intent(in) :: path
      !> The texts (padding removed; length of the longest).
      character(len=:), allocatable, intent(out) :: texts(:)
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: dset, str
      integer(hsize_t) :: dims(1)
      integer(size_t) :: n
      integer :: stat, s, i
      call open_dataset(file, path, 1, dset, dims, error)
      if (allocated(error)) return
      call h5dget_type_f(dset, str, s)
      call h5tget_size_f(str, n, s)
      allocate (character(len=n) :: texts(dims(1)))
      texts = repeat(achar(0), n)
      call h5dread_f(dset, str, texts, dims, stat)
      call h5tclose_f(str, s)
      call h5dclose_f(dset, s)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot read the texts')
         return
      end if
      do i = 1, size(texts)
         texts(i) = unpad(texts(i))
      end do
   end subroutine read_text_1d

   !> Text up to the first NUL.
   pure function unpad(text) result(t)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: t
      integer :: i
      i = index(text, achar(0))
      if (i == 0) then
         t = text
      else
         t = text(1:i - 1)
      end if
   end function unpad

   !> Open an attribute of an object.
   subroutine open_attribute(file, path, name, obj, attr, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path, name
      integer(hid_t), intent(out) :: obj, attr
      type(error_type), allocatable, intent(out) :: error
      logical :: exists
      integer :: stat, s
      call open_object(file, path, obj, error)
      if (allocated(error)) return
      call h5aexists_by_name_f(file%id, path, name, exists, stat)
      if (stat /= 0 .or. .not. exists) then
         call h5oclose_f(obj, s)
         call fail(error, file, path, 'no attribute '//name)
         return
      end if
      call h5aopen_f(obj, name, attr, stat)
      if (stat /= 0) then
         call h5oclose_f(obj, s)
         call fail(error, file, path, 'cannot open the attribute '//name)
      end if
   end subroutine open_attribute

   subroutine read_attr_text(file, path, name, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path.
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> The text.
      character(len=:), allocatable, intent(out) :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: obj, attr, str
      integer(hsize_t) :: dims(0)
      integer(size_t) :: n
      integer :: stat, s
      call open_attribute(file, path, name, obj, attr, error)
      if (allocated(error)) return
      call h5aget_type_f(attr, str, s)
      call h5tget_size_f(str, n, s)
      allocate (character(len=n) :: value)
      call h5aread_f(attr, str, value, dims, stat)
      call h5tclose_f(str, s)
      call h5aclose_f(attr, s)
      call h5oclose_f(obj, s)
      if (stat /= 0) then
         call fail(error, file, path, 'cannot read the attribute '//name)
         return
      end if
      value = unpad(value)
   end subroutine read_attr_text

   subroutine read_attr_int(file, path, name, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path.
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> The value.
      integer, intent(out), target :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      value = 0
      call read_scalar_attribute(file, path, name, H5T_NATIVE_INTEGER, c_loc(value), error)
   end subroutine read_attr_int

   subroutine read_attr_real(file, path, name, value, error)
      !> The file.
      type(h5_file_type), intent(in) :: file
      !> Object path.
      character(len=*), intent(in) :: path
      !> Attribute name.
      character(len=*), intent(in) :: name
      !> The value.
      real(wp), intent(out), target :: value
      !> Set on failure.
      type(error_type), allocatable, intent(out) :: error
      value = 0.0_wp
      call read_scalar_attribute(file, path, name, H5T_NATIVE_DOUBLE, c_loc(value), error)
   end subroutine read_attr_real

   !> Read a scalar numeric attribute into `buf`, converted to `mem_type`.
   subroutine read_scalar_attribute(file, path, name, mem_type, buf, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path, name
      integer(hid_t), intent(in) :: mem_type
      type(c_ptr), intent(in) :: buf
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: obj, attr
      type(c_ptr) :: ptr ! h5aread_f takes its buffer intent(inout)
      integer :: stat, s
      call open_attribute(file, path, name, obj, attr, error)
      if (allocated(error)) return
      ptr = buf
      call h5aread_f(attr, mem_type, ptr, stat)
      call h5aclose_f(attr, s)
      call h5oclose_f(obj, s)
      if (stat /= 0) call fail(error, file, path, 'cannot read the attribute '//name)
   end subroutine read_scalar_attribute

   !> An I/O error naming the file and the object.
   subroutine fail(error, file, path, what)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path, what
      call fatal_error(error, file%name//': '//path//': '//what, stat_io)
   end subroutine fail

end module shcontact_output_hdf5
