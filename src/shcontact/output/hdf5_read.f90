!> Reading HDF5 datasets and attributes (shcontact_output_hdf5): into allocatable arrays and
!> texts, with the dataset's shape and type checked and an error naming the file and the
!> object.
module shcontact_output_hdf5_read
   use, intrinsic :: iso_c_binding, only: c_loc, c_ptr
   use hdf5, only: hid_t, hsize_t, size_t, h5sclose_f, h5dopen_f, h5dclose_f, h5dread_f, &
      h5dget_space_f, h5dget_type_f, h5sget_simple_extent_ndims_f, h5sget_simple_extent_dims_f, &
      h5tclose_f, h5tget_size_f, H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, h5aopen_f, h5aclose_f, &
      h5aread_f, h5aexists_by_name_f, h5aget_type_f, h5oclose_f, h5tget_class_f, H5T_FLOAT_F, &
      H5T_INTEGER_F, H5T_STRING_F, h5tis_variable_str_f
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type
   use shcontact_core_strings, only: str_int
   use shcontact_output_hdf5_file, only: h5_file_type, open_object, fail, h5_exists
   implicit none
   private

   public :: h5_read, h5_read_attribute, h5_dataset_size, h5_dataset_info

   !> Read a dataset into an allocatable array or a text.
   interface h5_read
      module procedure :: read_real_0d, read_real_1d, read_real_2d, read_int_1d, read_text_0d, &
         read_text_1d
   end interface h5_read

   !> Read a scalar attribute.
   interface h5_read_attribute
      module procedure :: read_attr_text, read_attr_int, read_attr_real
   end interface h5_read_attribute

contains

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
      integer :: s, ndims, class
      logical :: variable
      type_size = 0
      is_float = .false.
      if (present(type_class)) type_class = 'other'
      allocate (dims(0))
      call open_existing(file, path, dset, error)
      if (allocated(error)) return
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
      integer :: s, ndims
      call open_existing(file, path, dset, error)
      if (allocated(error)) return
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

   !> Open dataset `path` of the file; an error naming the file and the path when it does not
   !> exist or cannot be opened.
   subroutine open_existing(file, path, dset, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      integer(hid_t), intent(out) :: dset
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      dset = -1
      if (.not. h5_exists(file, path)) then
         call fail(error, file, path, 'no such dataset')
         return
      end if
      call h5dopen_f(file%id, path, dset, stat)
      if (stat /= 0) call fail(error, file, path, 'cannot open the dataset')
   end subroutine open_existing

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

end module shcontact_output_hdf5_read
