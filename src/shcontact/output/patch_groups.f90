!> The per-patch groups of a result file (shcontact_output_results' layout): a patch's geometry
!> tables, normal strips and tangential element fields (`/cases/NNNNNN/patch_K/...` and the
!> common `/geometry/patch_K`), with their units, descriptions and dimension scales.
module shcontact_output_patch_groups
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior, state_adhesion, &
      state_slip
   use shcontact_output_hdf5, only: h5_file_type, h5_write, h5_write_attribute, h5_make_group, &
      h5_exists, h5_set_scale, h5_attach_scale, h5_set_dim_label, h5_delete_attribute
   use shcontact_core_strings, only: str_int
   use shcontact_case_result, only: case_result_type
   implicit none
   private

   public :: field_choice_type, attach_scale, attach_patch_scales, write_geometry, write_case

   character(len=*), parameter :: geometry_tables(5) = [character(len=8) :: 'gap', 'curv_a', &
      'curv_b', 'gamma', 'r_wheel']
   character(len=*), parameter :: strip_tables(10) = [character(len=10) :: 'a', 'k', 'p0', &
      'strip_load', 'm', 'n', 'eps_a', 'gamma', 'delta_r', 'r_wheel']
   character(len=*), parameter :: element_fields(6) = [character(len=5) :: 'x', 'pn', 'px', &
      'py', 'slip', 'state']

   !> The fields a configuration stores, looked up once per file (not per case).
   type :: field_choice_type
      logical :: any = .false., geometry = .false., strips = .false., pressure = .false.
      logical :: traction = .false., slip = .false., state = .false., elements = .false.
   end type field_choice_type

contains

   !> Make `group/scale` a dimension scale and attach it to dimension `dim` of those datasets
   !> of `names` that exist in the group (their earlier attachments are dropped first, unless
   !> `keep` is true: a second dimension of the same datasets).
   subroutine attach_scale(file, group, scale, dimension_name, names, dim, error, keep)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: group, scale, dimension_name
      character(len=*), intent(in) :: names(:)
      integer, intent(in) :: dim
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: keep
      character(len=*), parameter :: scale_attributes(3) = [character(len=14) :: &
         'REFERENCE_LIST', 'CLASS', 'NAME']
      integer :: i
      logical :: keep_attached
      if (.not. file%scales) return
      keep_attached = .false.
      if (present(keep)) keep_attached = keep
      if (.not. h5_exists(file, group//'/'//scale)) return
      ! A group copied from another file keeps its attributes but not the objects their
      ! references point to: start afresh.
      do i = 1, size(scale_attributes)
         call h5_delete_attribute(file, group//'/'//scale, trim(scale_attributes(i)), error)
         if (allocated(error)) return
      end do
      call h5_set_scale(file, group//'/'//scale, dimension_name, error)
      do i = 1, size(names)
         if (allocated(error)) return
         if (.not. h5_exists(file, group//'/'//trim(names(i)))) cycle
         if (.not. keep_attached) call h5_delete_attribute(file, group//'/'//trim(names(i)), &
            'DIMENSION_LIST', error)
         if (.not. allocated(error)) call h5_attach_scale(file, group//'/'//trim(names(i)), &
            group//'/'//scale, dim, error)
      end do
   end subroutine attach_scale

   !> The dimension scales of a patch group (`.../patch_K` with geometry, normal, tangential),
   !> or of a common geometry group (`geometry/patch_K`): again after a copy between files.
   subroutine attach_patch_scales(file, patch, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: patch
      type(error_type), allocatable, intent(out) :: error
      call attach_scale(file, patch, 'y', 'y (lateral, from the reference point)', &
         geometry_tables, 1, error)
      if (.not. allocated(error)) call attach_scale(file, patch//'/geometry', 'y', &
         'y (lateral, from the reference point)', geometry_tables, 1, error)
      if (.not. allocated(error)) call attach_scale(file, patch//'/normal', 'y', &
         'y (strip centre)', strip_tables, 1, error)
      if (.not. allocated(error)) call attach_field_scales(file, patch//'/tangential', error)
   end subroutine attach_patch_scales

   !> Scales of the element fields of a tangential group: y on the strip dimension (and dx's),
   !> `element` on the element dimension, `component` on the first dimension of `xy` (every
   !> dimension has its scale, so netCDF readers such as xarray open the group).
   subroutine attach_field_scales(file, path, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(error_type), allocatable, intent(out) :: error
      if (.not. file%scales) return
      if (.not. h5_exists(file, path//'/xy')) return
      call attach_scale(file, path, 'y', 'strip (y, lateral)', element_fields, 2, error)
      if (.not. allocated(error)) call attach_scale(file, path, 'element', &
         'element (j from the leading edge)', element_fields, 1, error, keep=.true.)
      if (allocated(error)) return
      call h5_delete_attribute(file, path//'/xy', 'DIMENSION_LIST', error)
      if (.not. allocated(error)) call h5_attach_scale(file, path//'/xy', path//'/y', 3, error)
      if (.not. allocated(error)) call h5_delete_attribute(file, path//'/dx', 'DIMENSION_LIST', &
         error)
      if (.not. allocated(error)) call h5_attach_scale(file, path//'/dx', path//'/y', 1, error)
      if (.not. allocated(error) .and. h5_exists(file, path//'/element')) &
         call h5_attach_scale(file, path//'/xy', path//'/element', 2, error)
      if (.not. allocated(error)) call attach_scale(file, path, 'component', 'x, y', &
         [character(len=2) :: 'xy'], 1, error, keep=.true.)
   end subroutine attach_field_scales

   !> The patch geometry tables and reference point.
   subroutine write_geometry(file, path, g, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(patch_geometry_type), intent(in) :: g
      type(error_type), allocatable, intent(out) :: error
      if (.not. allocated(g%y)) then
         call h5_make_group(file, path, error)
         return
      end if
      call h5_write(file, path//'/y', g%y, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gap', g%gap, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/curv_a', g%curv_a, '1/mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/curv_b', g%curv_b, '1/mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma', g%gamma, 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/r_wheel', g%r_wheel, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_track', g%y_track, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/z_track', g%z_track, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_rail', g%y_rail, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_wheel', g%y_wheel, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma0', g%gamma0, 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/r0', g%r0, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gap0', g%gap0, 'mm', error)
      if (.not. allocated(error)) call attach_scale(file, path, 'y', 'y (lateral, from the '// &
         'reference point)', geometry_tables, 1, error)
   end subroutine write_geometry

   !> The per-case group: the fields the configuration asks for, per patch.
   subroutine write_case(file, fields, group, result, error)
      type(h5_file_type), intent(in) :: file
      type(field_choice_type), intent(in) :: fields
      character(len=*), intent(in) :: group
      type(case_result_type), intent(in) :: result
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      character(len=:), allocatable :: patch

      if (.not. fields%any .or. result%summary%stat /= 0) return
      do k = 1, result%summary%n_loaded
         patch = group//'/patch_'//str_int(k)
         if (fields%geometry .and. allocated(result%geometry)) then
            call write_geometry(file, patch//'/geometry', result%geometry(k), error)
            if (allocated(error)) return
         end if
         if (allocated(result%normal)) then
            call write_normal(file, fields, patch//'/normal', result%normal(k), error)
            if (allocated(error)) return
         end if
         if (allocated(result%tangential)) then
            call write_tangential(file, fields, patch//'/tangential', result%tangential(k), &
               error)
            if (allocated(error)) return
         end if
         if (allocated(result%nu_x)) then
            ! Kinematic case: the creepages of the wheelset motion at this patch.
            call h5_write(file, patch//'/tangential/nu_x', result%nu_x(k), '1', error)
            if (.not. allocated(error)) call h5_write(file, patch//'/tangential/nu_y', &
               result%nu_y(k), '1', error)
            if (.not. allocated(error)) call h5_write(file, patch//'/tangential/phi', &
               result%phi(k), 'rad/mm', error)
            if (.not. allocated(error)) call h5_write(file, patch//'/tangential/x_track', &
               result%x_track(k), 'mm', error)
            if (allocated(error)) return
         end if
      end do
   end subroutine write_case

   subroutine write_normal(file, fields, path, n, error)
      type(h5_file_type), intent(in) :: file
      type(field_choice_type), intent(in) :: fields
      character(len=*), intent(in) :: path
      type(normal_patch_type), intent(in) :: n
      type(error_type), allocatable, intent(out) :: error
      integer :: m
      call h5_write(file, path//'/approach', n%approach, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/load', n%load, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/area', n%area, 'mm^2', error)
      if (.not. allocated(error)) call h5_write(file, path//'/p_max', n%p_max, 'MPa', error)
      if (.not. allocated(error)) call h5_write(file, path//'/dy', n%dy, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_shift', n%y_shift, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma0', n%gamma0, 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/r0', n%r0, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/is_hertz', merge(1, 0, &
         n%is_hertz), '1', error)
      if (n%is_hertz .and. .not. allocated(error)) then
         call h5_write(file, path//'/ellipse_a', n%ellipse_a, 'mm', error)
         if (.not. allocated(error)) call h5_write(file, path//'/ellipse_b', n%ellipse_b, 'mm', &
            error)
         if (.not. allocated(error)) call h5_write(file, path//'/ellipse_y_centre', &
            n%ellipse_y_centre, 'mm', error)
      end if
      if (allocated(error) .or. .not. fields%strips) return
      if (.not. allocated(n%y)) return
      m = n%n_strips
      call h5_write(file, path//'/y', n%y(1:m), 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/a', n%a(1:m), 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/k', n%k(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/p0', n%p0(1:m), 'MPa', error)
      if (.not. allocated(error)) call h5_write(file, path//'/strip_load', n%strip_load(1:m), &
         'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/m', n%m(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/n', n%n(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/eps_a', n%eps_a(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma', n%gamma(1:m), 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/delta_r', n%delta_r(1:m), 'mm', &
         error)
      if (.not. allocated(error)) call h5_write(file, path//'/r_wheel', n%r_wheel(1:m), 'mm', &
         error)
      if (.not. allocated(error)) call attach_scale(file, path, 'y', 'y (strip centre)', &
         strip_tables, 1, error)
   end subroutine write_normal

   subroutine write_tangential(file, fields, path, t, error)
      type(h5_file_type), intent(in) :: file
      type(field_choice_type), intent(in) :: fields
      character(len=*), intent(in) :: path
      type(tangential_patch_type), intent(in) :: t
      type(error_type), allocatable, intent(out) :: error
      call h5_write(file, path//'/fx', t%fx, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fy', t%fy, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/mz', t%mz, 'N mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fn', t%fn, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fx_norm', t%fx_norm, '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fy_norm', t%fy_norm, '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/coulomb_ratio', t%coulomb_ratio, &
         '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/adhesion_fraction', &
         t%adhesion_fraction, '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fy_track', t%fy_track, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fz_track', t%fz_track, 'N', error)
      if (allocated(error) .or. .not. allocated(t%x)) return
      if (.not. fields%elements) return
      call h5_write(file, path//'/x', t%x, 'mm', error, compress=.true.)
      if (.not. allocated(error)) call h5_write(file, path//'/y', t%y, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/dx', t%dx, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/dy', t%dy, 'mm', error)
      if (allocated(error)) return
      if (fields%pressure .and. allocated(t%pn)) then
         call h5_write(file, path//'/pn', t%pn, 'MPa', error, compress=.true.)
         if (allocated(error)) return
      end if
      if (fields%traction .and. allocated(t%px)) then
         call h5_write(file, path//'/px', t%px, 'MPa', error, compress=.true.)
         if (.not. allocated(error)) call h5_write(file, path//'/py', t%py, 'MPa', error, &
            compress=.true.)
         if (allocated(error)) return
      end if
      if (fields%slip .and. allocated(t%slip)) then
         call h5_write(file, path//'/slip', t%slip, '1', error, compress=.true.)
         if (allocated(error)) return
      end if
      if (fields%state .and. allocated(t%state)) then
         call h5_write(file, path//'/state', t%state, '1', error, compress=.true.)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'codes', &
            str_int(int(state_exterior))//' exterior, '// &
            str_int(int(state_adhesion))//' adhesion, '// &
            str_int(int(state_slip))//' slip', error)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'exterior', &
            int(state_exterior), error)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'adhesion', &
            int(state_adhesion), error)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'slip', &
            int(state_slip), error)
         if (allocated(error)) return
      end if
      call write_field_grid(file, path, t, error)
   end subroutine write_tangential

   !> The element grid of the fields: `xy`, the element centres (x, y) interleaved (the mesh
   !> geometry of the XDMF sidecar: ParaView's XDMF reader wants the coordinates of a point
   !> together), y as the dimension scale of the strip dimension of every field, `element`
   !> (j = 0, 1, ...) that of the element dimension, `component` ('x', 'y') that of xy's first,
   !> every dimension labelled, and a `coordinates` attribute (x, y) on every field.
   subroutine write_field_grid(file, path, t, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(tangential_patch_type), intent(in) :: t
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: fields(6) = [character(len=5) :: 'x', 'pn', 'px', 'py', &
         'slip', 'state']
      real(wp), allocatable :: xy(:, :, :)
      integer :: i
      allocate (xy(2, size(t%x, 1), size(t%x, 2)))
      xy(1, :, :) = t%x
      xy(2, :, :) = spread(t%y, 1, size(t%x, 1))
      call h5_write(file, path//'/xy', xy, 'mm', error, compress=.true.)
      if (.not. allocated(error)) call h5_write(file, path//'/element', &
         [(i - 1, i = 1, size(t%x, 1))], '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/component', &
         [character(len=1) :: 'x', 'y'], error)
      if (.not. allocated(error)) call attach_field_scales(file, path, error)
      if (.not. allocated(error)) call h5_set_dim_label(file, path//'/xy', 1, 'x, y', error)
      if (.not. allocated(error)) call h5_set_dim_label(file, path//'/xy', 2, &
         'element (j from the leading edge)', error)
      if (.not. allocated(error)) call h5_set_dim_label(file, path//'/xy', 3, 'strip (y)', error)
      do i = 1, size(fields)
         if (allocated(error)) return
         if (.not. h5_exists(file, path//'/'//trim(fields(i)))) cycle
         call h5_set_dim_label(file, path//'/'//trim(fields(i)), 1, &
            'element (j from the leading edge)', error)
         if (.not. allocated(error)) call h5_set_dim_label(file, path//'/'//trim(fields(i)), &
            2, 'strip (y)', error)
         if (.not. allocated(error) .and. i > 1) call h5_write_attribute(file, &
            path//'/'//trim(fields(i)), 'coordinates', 'x y', error)
      end do
   end subroutine write_field_grid

end module shcontact_output_patch_groups
