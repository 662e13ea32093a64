!> The HDF5 summary of the benchmark's design of experiments: one row per case (creepages,
!> forces, normalised forces, Coulomb check, adhesion fraction) as 1-D datasets, units as
!> attributes. The app's summary writer (issue 6) had not landed in main when this was written,
!> so the benchmark writes its own with the HDF5 Fortran API. The file is written under a
!> temporary name and renamed when complete; every handle is closed on every path.
module bench_summary
   use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
   use hdf5, only: hid_t, hsize_t, size_t, h5f_acc_trunc_f, h5t_native_double, h5t_native_integer, &
      h5t_fortran_s1, h5fcreate_f, h5fclose_f, h5screate_simple_f, h5screate_f, h5s_scalar_f, &
      h5sclose_f, h5dcreate_f, h5dwrite_f, h5dclose_f, h5acreate_f, h5awrite_f, h5aclose_f, &
      h5tcopy_f, h5tset_size_f, h5tclose_f
   use shcontact, only: wp
   implicit none
   private

   public :: doe_table_type, write_doe_summary

   !> The results of a design of experiments, one entry per case. Forces on the wheel (N, N·mm).
   type :: doe_table_type
      real(wp), allocatable :: nu_x(:), nu_y(:), phi(:)
      real(wp), allocatable :: fx(:), fy(:), mz(:), fx_norm(:), fy_norm(:)
      real(wp), allocatable :: coulomb_ratio(:), adhesion_fraction(:)
      !> Library status per case (0: solved).
      integer, allocatable :: status(:)
   end type doe_table_type

   interface
      !> C's rename(3): atomic replacement of the finished file.
      function c_rename(old, new) bind(C, name='rename') result(stat)
         import :: c_int, c_char
         character(kind=c_char), intent(in) :: old(*), new(*)
         integer(c_int) :: stat
      end function c_rename
   end interface

contains

   !> Write the table to `filename` (replaced), with the case description as attributes of the
   !> root group. `stat` is 0 on success; `message` says what failed otherwise.
   subroutine write_doe_summary(filename, table, fn, description, stat, message)
      !> Output file.
      character(len=*), intent(in) :: filename
      !> The results.
      type(doe_table_type), intent(in) :: table
      !> Normal force of the patch (N).
      real(wp), intent(in) :: fn
      !> One line describing the case and the options.
      character(len=*), intent(in) :: description
      !> 0 on success.
      integer, intent(out) :: stat
      !> What failed.
      character(len=:), allocatable, intent(out) :: message
      character(len=:), allocatable :: tmp
      integer(hid_t) :: file
      integer :: hstat

      tmp = filename//'.tmp'
      call h5fcreate_f(tmp, h5f_acc_trunc_f, file, hstat)
      if (hstat /= 0) then
         stat = 1
         message = tmp//': cannot create the HDF5 file'
         return
      end if
      stat = 0
      call put_text(file, 'description', description, stat)
      call put_text(file, 'sign_convention', 'creepages of the wheel relative to the rail; '// &
         'forces and moment act on the wheel (physics.md decision 2)', stat)
      call put_real(file, 'fn', fn, 'N', stat)
      call put_column(file, 'nu_x', table%nu_x, '1', stat)
      call put_column(file, 'nu_y', table%nu_y, '1', stat)
      call put_column(file, 'phi', table%phi, 'rad/mm', stat)
      call put_column(file, 'fx', table%fx, 'N', stat)
      call put_column(file, 'fy', table%fy, 'N', stat)
      call put_column(file, 'mz', table%mz, 'N mm', stat)
      call put_column(file, 'fx_norm', table%fx_norm, '1', stat)
      call put_column(file, 'fy_norm', table%fy_norm, '1', stat)
      call put_column(file, 'coulomb_ratio', table%coulomb_ratio, '1', stat)
      call put_column(file, 'adhesion_fraction', table%adhesion_fraction, '1', stat)
      call put_status(file, 'status', table%status, stat)
      call h5fclose_f(file, hstat)
      if (stat /= 0 .or. hstat /= 0) then
         stat = 1
         message = tmp//': writing the HDF5 datasets failed'
         return
      end if
      if (c_rename(tmp//c_null_char, filename//c_null_char) /= 0) then
         stat = 1
         message = 'cannot rename '//tmp//' to '//filename
      end if
   end subroutine write_doe_summary

   !> A 1-D double dataset with a `units` attribute.
   subroutine put_column(file, name, values, units, stat)
      integer(hid_t), intent(in) :: file
      character(len=*), intent(in) :: name, units
      real(wp), intent(in) :: values(:)
      integer, intent(inout) :: stat
      integer(hid_t) :: space, dset
      integer(hsize_t) :: dims(1)
      integer :: hstat

      if (stat /= 0) return
      dims(1) = size(values, kind=hsize_t)
      call h5screate_simple_f(1, dims, space, hstat)
      if (hstat /= 0) then
         stat = 1
         return
      end if
      call h5dcreate_f(file, name, h5t_native_double, space, dset, hstat)
      if (hstat == 0) then
         call h5dwrite_f(dset, h5t_native_double, values, dims, hstat)
         if (hstat == 0) call put_text(dset, 'units', units, hstat)
         call close_dataset(dset, hstat)
      end if
      call close_space(space, hstat)
      if (hstat /= 0) stat = 1
   end subroutine put_column

   !> A 1-D integer dataset.
   subroutine put_status(file, name, values, stat)
      integer(hid_t), intent(in) :: file
      character(len=*), intent(in) :: name
      integer, intent(in) :: values(:)
      integer, intent(inout) :: stat
      integer(hid_t) :: space, dset
      integer(hsize_t) :: dims(1)
      integer :: hstat

      if (stat /= 0) return
      dims(1) = size(values, kind=hsize_t)
      call h5screate_simple_f(1, dims, space, hstat)
      if (hstat /= 0) then
         stat = 1
         return
      end if
      call h5dcreate_f(file, name, h5t_native_integer, space, dset, hstat)
      if (hstat == 0) then
         call h5dwrite_f(dset, h5t_native_integer, values, dims, hstat)
         call close_dataset(dset, hstat)
      end if
      call close_space(space, hstat)
      if (hstat /= 0) stat = 1
   end subroutine put_status

   !> A scalar double attribute with its units in a companion text attribute `<name>_units`.
   subroutine put_real(object, name, value, units, stat)
      integer(hid_t), intent(in) :: object
      character(len=*), intent(in) :: name, units
      real(wp), intent(in) :: value
      integer, intent(inout) :: stat
      integer(hid_t) :: space, attr
      integer(hsize_t) :: dims(1)
      integer :: hstat

      if (stat /= 0) return
      dims(1) = 1
      call h5screate_f(h5s_scalar_f, space, hstat)
      if (hstat /= 0) then
         stat = 1
         return
      end if
      call h5acreate_f(object, name, h5t_native_double, space, attr, hstat)
      if (hstat == 0) then
         call h5awrite_f(attr, h5t_native_double, value, dims, hstat)
         call close_attribute(attr, hstat)
      end if
      call close_space(space, hstat)
      if (hstat /= 0) stat = 1
      call put_text(object, name//'_units', units, stat)
   end subroutine put_real

   !> A scalar fixed-length string attribute.
   subroutine put_text(object, name, text, stat)
      integer(hid_t), intent(in) :: object
      character(len=*), intent(in) :: name, text
      integer, intent(inout) :: stat
      integer(hid_t) :: space, attr, string_type
      integer(hsize_t) :: dims(1)
      integer :: hstat, tstat

      if (stat /= 0) return
      dims(1) = 1
      call h5tcopy_f(h5t_fortran_s1, string_type, hstat)
      if (hstat /= 0) then
         stat = 1
         return
      end if
      call h5tset_size_f(string_type, int(max(1, len(text)), kind=size_t), hstat)
      if (hstat == 0) call h5screate_f(h5s_scalar_f, space, hstat)
      if (hstat == 0) then
         call h5acreate_f(object, name, string_type, space, attr, hstat)
         if (hstat == 0) then
            call h5awrite_f(attr, string_type, text, dims, hstat)
            call close_attribute(attr, hstat)
         end if
         call close_space(space, hstat)
      end if
      call h5tclose_f(string_type, tstat)
      if (hstat /= 0 .or. tstat /= 0) stat = 1
   end subroutine put_text

   !> Close a dataset, keeping the first failure in hstat.
   subroutine close_dataset(dset, hstat)
      integer(hid_t), intent(in) :: dset
      integer, intent(inout) :: hstat
      integer :: s
      call h5dclose_f(dset, s)
      if (hstat == 0) hstat = s
   end subroutine close_dataset

   !> Close a dataspace, keeping the first failure in hstat.
   subroutine close_space(space, hstat)
      integer(hid_t), intent(in) :: space
      integer, intent(inout) :: hstat
      integer :: s
      call h5sclose_f(space, s)
      if (hstat == 0) hstat = s
   end subroutine close_space

   !> Close an attribute, keeping the first failure in hstat.
   subroutine close_attribute(attr, hstat)
      integer(hid_t), intent(in) :: attr
      integer, intent(inout) :: hstat
      integer :: s
      call h5aclose_f(attr, s)
      if (hstat == 0) hstat = s
   end subroutine close_attribute

end module bench_summary
