!> Keeps doc/validation.md Table 2 (§2.2, the Manchester rows at F_z = 10 kN) true: every number
!> of our columns is recomputed with the library as `shcontact-validate` computes
!> doc/validation/manchester_10kN.csv (default normal options, G = 82 000 MPa, ν = 0.28, the
!> vertical load shared by the patches of the right wheel) and must equal the printed value to
!> its last digit (within half a unit of it). Skipped without the external data
!> (test_external_data).
module test_validation_normal
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type
   use shcontact_geometry_contact, only: contact_options_type, find_contact_patches
   use shcontact_geometry_prepared, only: prepared_profiles_type, prepare_profiles
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, new_normal_options
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, &
      solve_vertical_load
   use shcontact_normal_patch, only: normal_patch_type
   use test_validation, only: manchester_profiles, skip_without_profiles
   implicit none
   private
   public :: collect_validation_normal

   character(len=*), parameter :: doc_file = 'doc/validation.md'
   !> Columns of a Table 2 row: y_ws (mm), patch, F_n (N), approach (mm), p_max (MPa), γ₀ (rad),
   !> y_r centre (mm).
   integer, parameter :: n_columns = 7

contains

   !> Collect the tests.
   subroutine collect_validation_normal(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [new_unittest('manchester_10kN_table_2', test_table_2)]
   end subroutine collect_validation_normal

   !> Every row of Table 2 against the library, within half a unit of its last printed digit.
   subroutine test_table_2(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: rows(:, :), units(:, :)
      type(prepared_profiles_type) :: prepared
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_contact_type), allocatable :: contacts(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(normal_options_type) :: options
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(lib_error), allocatable :: err
      real(wp) :: dz, ours(3:n_columns)
      integer :: r, k, c

      call skip_without_profiles(error)
      if (allocated(error)) return
      call table_2_rows(rows, units, error)
      if (allocated(error)) return
      call manchester_profiles(wheel, rail, track, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track, &
         contact_options_type(), prepared, err)
      if (.not. allocated(err)) call new_normal_options(options, err)
      do r = 1, size(rows, 1)
         if (allocated(err)) exit
         call find_contact_patches(prepared, wheelset_position_type(y_ws=rows(r, 1)), geometry, err)
         if (allocated(err)) exit
         if (allocated(contacts)) deallocate (contacts)
         if (allocated(patches)) deallocate (patches)
         allocate (contacts(size(geometry)), patches(size(geometry)))
         do k = 1, size(geometry)
            if (.not. allocated(err)) call prepare_normal_contact(contacts(k), geometry(k), &
               options, material_type(shear_modulus=82000.0_wp, poisson=0.28_wp, &
               friction=0.3_wp), err)
         end do
         if (.not. allocated(err)) call solve_vertical_load(contacts, 10000.0_wp, patches, dz, err)
         if (allocated(err)) exit
         k = nint(rows(r, 2))
         if (k < 1 .or. k > size(patches)) then
            call test_failed(error, doc_file//' Table 2: no such patch')
            return
         end if
         ours = [patches(k)%load, patches(k)%approach, patches(k)%p_max, geometry(k)%gamma0, &
            load_centre(geometry(k), patches(k))]
         do c = 3, n_columns
            call check(error, ours(c), rows(r, c), thr=0.5_wp*units(r, c)*(1.0_wp + 1.0e-9_wp), &
               message=doc_file//' Table 2 differs from the library')
            if (allocated(error)) return
         end do
      end do
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine test_table_2

   !> The load centre projected on the rail profile's y (mm), as shcontact-validate writes it:
   !> the table's first contact, the loaded point's move along the contact plane, and the load
   !> centre about the loaded point (normal_patch_type's lateral_offset).
   pure real(wp) function load_centre(geometry, patch)
      type(patch_geometry_type), intent(in) :: geometry
      type(normal_patch_type), intent(in) :: patch
      load_centre = geometry%y_rail + patch%lateral_offset() + cos(geometry%gamma0)* &
         sum(patch%strip_load*patch%y)/sum(patch%strip_load)
   end function load_centre

   !> The numeric rows of Table 2 (doc/validation.md §2.2): y_ws, patch, F_n, approach, p_max,
   !> γ₀, y_r centre, and the unit of each value's last printed digit. The table starts after
   !> the line "Table 2"; "−" is a minus sign and spaces group digits.
   subroutine table_2_rows(rows, units, error)
      real(wp), allocatable, intent(out) :: rows(:, :), units(:, :)
      type(error_type), allocatable, intent(out) :: error
      character(len=1024) :: line
      character(len=64) :: cell
      real(wp) :: row(n_columns), buffer(16, n_columns), unit_row(n_columns), &
         unit_buffer(16, n_columns)
      integer :: unit, stat, n, c, p0, p1, rstat
      logical :: inside

      open (newunit=unit, file=doc_file, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, 'cannot open '//doc_file)
         return
      end if
      n = 0
      inside = .false.
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (trim(line) == 'Table 2') inside = .true.
         if (.not. inside) cycle
         if (line(1:2) == '##') exit
         if (line(1:2) /= '| ' .or. verify(line(3:3), '0123456789') /= 0) cycle
         p0 = 2
         do c = 1, n_columns
            p1 = p0 + index(line(p0 + 1:), '|')
            cell = numeric_text(line(p0 + 1:p1 - 1))
            read (cell, *, iostat=rstat) row(c)
            unit_row(c) = 1.0_wp
            if (index(cell, '.') > 0) unit_row(c) = 10.0_wp**(-(len_trim(cell) - index(cell, '.')))
            if (rstat /= 0) then
               call test_failed(error, doc_file//' Table 2: cannot read "'// &
                  trim(line(p0 + 1:p1 - 1))//'"')
               close (unit)
               return
            end if
            p0 = p1
         end do
         if (n == size(buffer, 1)) exit
         n = n + 1
         buffer(n, :) = row
         unit_buffer(n, :) = unit_row
      end do
      close (unit)
      if (n < 3) then
         call test_failed(error, doc_file//': fewer than 3 rows in Table 2')
         return
      end if
      rows = buffer(1:n, :)
      units = unit_buffer(1:n, :)
   end subroutine table_2_rows

   !> A table cell as Fortran can read it: "−" (U+2212) to "-", spaces and "*" dropped, text
   !> after the first number (" (tread)") dropped.
   pure function numeric_text(text) result(cell)
      character(len=*), intent(in) :: text
      character(len=64) :: cell
      character(len=*), parameter :: minus = char(226)//char(136)//char(146)
      integer :: i, n
      cell = ''
      n = 0
      i = 1
      do while (i <= len(text))
         if (i + 2 <= len(text)) then
            if (text(i:i + 2) == minus) then
               n = n + 1
               cell(n:n) = '-'
               i = i + 3
               cycle
            end if
         end if
         if (text(i:i) == '(') exit
         if (index('0123456789.+-eE', text(i:i)) > 0 .and. n < len(cell)) then
            n = n + 1
            cell(n:n) = text(i:i)
         end if
         i = i + 1
      end do
   end function numeric_text

end module test_validation_normal
