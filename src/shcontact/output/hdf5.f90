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
!>
!> This module writes datasets, attributes and dimension scales and is the one the rest of the
!> code uses; the file handle, files and groups are shcontact_output_hdf5_file's, reading is
!> shcontact_output_hdf5_read's (their procedures are public here too).
module shcontact_output_hdf5
   use, intrinsic :: iso_c_binding, only: c_loc, c_ptr
   use hdf5, only: hid_t, hsize_t, size_t, h5pcreate_f, h5pclose_f, H5P_DATASET_CREATE_F, &
      H5P_LINK_CREATE_F, h5pset_chunk_f, h5pset_deflate_f, h5pset_obj_track_times_f, &
      h5pset_create_inter_group_f, h5screate_f, h5screate_simple_f, h5sclose_f, H5S_SCALAR_F, &
      h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dget_space_f, h5sget_simple_extent_ndims_f, &
      h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5tclose_f, H5T_C_S1, H5T_STR_NULLPAD_F, &
      h5tset_cset_f, H5T_CSET_UTF8_F, &
      H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, H5T_STD_I8LE, H5T_STD_I32LE, H5T_IEEE_F64LE, &
      h5kind_to_type, H5_INTEGER_KIND, h5acreate_f, h5aclose_f, h5awrite_f, h5aexists_by_name_f, &
      h5oclose_f, H5T_IEEE_F32LE, h5adelete_f
   ! HDF5's high-level Fortran library (libhdf5hl_fortran, linked by fpm's hdf5 metapackage).
   use h5ds, only: h5dsset_scale_f, h5dsattach_scale_f, h5dsset_label_f
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_error, only: error_type
   use shcontact_core_strings, only: str_int
   use shcontact_output_hdf5_file, only: h5_file_type, description_function, h5_create, h5_commit, &
      h5_discard, h5_open, h5_close, h5_skip_exit_cleanup, h5_make_group, h5_exists, h5_copy, &
      open_object, fail
   use shcontact_output_hdf5_read, only: h5_read, h5_read_attribute, h5_dataset_size, &
      h5_dataset_info
   implicit none
   private

   public :: h5_file_type, h5_create, h5_commit, h5_discard, h5_open, h5_close
   public :: h5_write, h5_write_attribute, h5_make_group, h5_copy, h5_exists
   public :: h5_read, h5_read_attribute, h5_dataset_size
   public :: h5_skip_exit_cleanup
   public :: h5_set_scale, h5_attach_scale, h5_set_dim_label, h5_dataset_info, h5_delete_attribute
   public :: description_function


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


   !> Datasets smaller than this are stored contiguously, without compression.
   integer, parameter :: min_compressed_size = 256

   !> The extent of a scalar dataset (no dimensions).
   integer(hsize_t), parameter :: scalar(0) = [integer(hsize_t) ::]

contains

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

   !> A C string type of n bytes, null-padded, UTF-8 (the texts hold a few non-ASCII
   !> characters: `§` in the namelist's comments, `×` in messages; ASCII is UTF-8).
   subroutine make_string_type(n, str, stat)
      integer, intent(in) :: n
      integer(hid_t), intent(out) :: str
      integer, intent(out) :: stat
      integer :: s
      call h5tcopy_f(H5T_C_S1, str, stat)
      call h5tset_size_f(str, int(n, size_t), s)
      call h5tset_strpad_f(str, H5T_STR_NULLPAD_F, s)
      call h5tset_cset_f(str, H5T_CSET_UTF8_F, s)
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

end module shcontact_output_hdf5
