!> Keeps the headline validation numbers (doc/validation.md) from regressing: the whole pipeline
!> (profiles → geometry → semi-Hertzian normal contact → FASTSIM_SH) on the reference case of
!> ../shared/reference/ (S1002 on UIC60 1:40, Y_WS = 0, F_n = 64.7 kN) against Kalker's exact
!> theory computed by CONTACT. Tolerances are the project's targets (issue 7, physics.md §6.6) and
!> the reference's own values, never outputs of our code. Skipped when ../shared is absent.
!>
!> The tangential settings are the ones recommended as defaults in doc/validation.md: bound
!> 'weighted', spin model 'uniform', spin flexibility 'longitudinal', 100 strips × 50 elements.
!> Signs: the reference is CONTACT's rail side; we solve the same case from the wheel's side
!> (creepages −ν, forces −F), physics.md decision 2.
module test_validation
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile
   use shcontact_geometry_track, only: track_type, wheelset_position_type
   use shcontact_geometry_contact, only: contact_options_type, find_contact_patches
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, new_normal_options
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_options, only: tangential_options_type, parse_bound, &
      parse_spin_model, parse_spin_flexibility
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   implicit none
   private
   public :: collect_validation

   character(len=*), parameter :: profiles_dir = '../shared/profiles/'
   character(len=*), parameter :: reference_dir = '../shared/reference/ty0_literal/'
   !> The reference case (README §2).
   real(wp), parameter :: normal_force = 64700.0_wp

contains

   !> Collect the tests.
   subroutine collect_validation(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('normal_patch_vs_exact', test_normal), &
         new_unittest('doe_10x10x10_vs_exact', test_doe) &
         ]
   end subroutine collect_validation

   !> The semi-Hertzian patch against CONTACT's exact normal solution (headline_summary.csv,
   !> module3_exact_nonhertz): approach within 5 % of 0.05526 mm, contact area within 5 % of
   !> 151.24 mm², contact length within 5 % of 9.0 mm, width within 5 % of 19.8 mm.
   subroutine test_normal(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      real(wp) :: approach, area, length, width

      call reference_patch(patch, error)
      if (allocated(error)) return
      call reference_normal(approach, area, length, width, error)
      if (allocated(error)) return
      call check(error, patch%approach, approach, rel=.true., thr=0.05_wp, &
         message='approach against CONTACT exact')
      if (allocated(error)) return
      call check(error, patch%area, area, rel=.true., thr=0.05_wp, &
         message='contact area against CONTACT exact')
      if (allocated(error)) return
      call check(error, 2.0_wp*maxval(patch%a), length, rel=.true., thr=0.05_wp, &
         message='contact length against CONTACT exact')
      if (allocated(error)) return
      call check(error, patch_width(patch), width, rel=.true., thr=0.05_wp, &
         message='contact width against CONTACT exact')
   end subroutine test_normal

   !> The 10³ DOE (ξ, η ∈ [0, 2] ‰, φ ∈ [0, 2] 1/m) against the exact theory: max |Δf| ≤ 0.1 and
   !> the 80th percentile of |Δf_y| ≤ 0.04 (issue 7, physics.md §6.6), and the headline case
   !> within the same 0.1.
   subroutine test_doe(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      real(wp), allocatable :: cases(:, :), ex(:), ey(:)
      integer :: i, n

      call reference_patch(patch, error)
      if (allocated(error)) return
      call read_columns(reference_dir//'doe_10x10x10_exact_nonhertz.csv', &
         [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m', 'fx', 'fy'], cases, error)
      if (allocated(error)) return
      call recommended_options(options)
      call prepare_fastsim_sh(ws, patch, material_type(), options, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      n = size(cases, 1)
      allocate (ex(n), ey(n))
      do i = 1, n
         ! Wheel side: creepages −ν (φ in rad/mm), forces −F (decision 2).
         call solve_prepared(ws, creepage_type(-cases(i, 1), -cases(i, 2), &
            -1.0e-3_wp*cases(i, 3)), result, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         ex(i) = abs(-result%fx_norm - cases(i, 4))
         ey(i) = abs(-result%fy_norm - cases(i, 5))
      end do
      call check(error, n, 1000, message='DOE cases read')
      if (allocated(error)) return
      call check(error, max(maxval(ex), maxval(ey)) <= 0.1_wp, &
         message='DOE: max |Delta f| > 0.1 against the exact theory')
      if (allocated(error)) return
      call check(error, percentile(ey, 0.8_wp) <= 0.04_wp, &
         message='DOE: 80th percentile of |Delta f_y| > 0.04 against the exact theory')
      if (allocated(error)) return
      ! The headline creepages (README §5): f_x = −0.4960, f_y = −0.2869.
      call solve_prepared(ws, creepage_type(-0.58e-3_wp, -0.061e-3_wp, -2.74e-4_wp), result, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, -result%fx_norm, -0.4960_wp, thr=0.1_wp, message='headline f_x')
      if (allocated(error)) return
      call check(error, -result%fy_norm, -0.2869_wp, thr=0.1_wp, message='headline f_y')
   end subroutine test_doe

   ! ------------------------------------------------------------------ helpers

   !> The recommended tangential settings (doc/validation.md), explicitly: W1, uniform spin,
   !> longitudinal spin flexibility, 50 elements per strip.
   subroutine recommended_options(options)
      type(tangential_options_type), intent(out) :: options
      type(lib_error), allocatable :: err
      call parse_bound('weighted', options%bound, err)
      call parse_spin_model('uniform', options%spin_model, err)
      call parse_spin_flexibility('longitudinal', options%spin_flexibility, err)
      options%n_elements = 50
      options%fields = .false.
   end subroutine recommended_options

   !> The normal solution of the reference case: Manchester profiles, Y_WS = 0, semi-Hertz with
   !> the local-Hertz reduction, 100 strips, F_n = 64.7 kN, G = 82670 MPa, ν = 0.27 (the
   !> material_type defaults). Skips when the shared data is absent.
   subroutine reference_patch(patch, error)
      type(normal_patch_type), intent(out) :: patch
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(lib_error), allocatable :: err
      logical :: there

      inquire (file=profiles_dir//'MBench_S1002_v3.prw', exist=there)
      if (there) inquire (file=reference_dir//'doe_10x10x10_exact_nonhertz.csv', exist=there)
      if (.not. there) then
         call skip_test(error, '../shared (profiles or exact-theory reference) is absent')
         return
      end if
      call read_profile(profiles_dir//'MBench_S1002_v3.prw', wheel, err)
      if (.not. allocated(err)) call clean_profile(wheel, err)
      if (.not. allocated(err)) call read_profile(profiles_dir//'MBench_UIC60_v3.prr', rail, err)
      if (.not. allocated(err)) call clean_profile(rail, err)
      track%rail_canted = .true.
      if (.not. allocated(err)) call find_contact_patches(wheel, rail, track, &
         wheelset_position_type(y_ws=0.0_wp), contact_options_type(), geometry, err)
      if (.not. allocated(err)) call new_normal_options(options, err, method='semi-hertz', &
         reduction='local-hertz', n_strips=100)
      if (.not. allocated(err)) call prepare_normal_contact(contact, geometry(1), options, &
         material_type(), err)
      if (.not. allocated(err)) call solve_load(contact, normal_force, patch, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine reference_patch

   !> CONTACT's exact normal results (headline_summary.csv, row module3_exact_nonhertz).
   subroutine reference_normal(approach, area, length, width, error)
      real(wp), intent(out) :: approach, area, length, width
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: rows(:, :)

      call read_columns(reference_dir//'../headline_summary.csv', [character(len=17) :: &
         'pen_mm', 'contact_area_mm2', 'contact_length_mm', 'contact_width_mm'], rows, error, &
         row_tag='module3_exact_nonhertz')
      if (allocated(error)) return
      if (size(rows, 1) < 1) then
         call test_failed(error, 'headline_summary.csv: no module3_exact_nonhertz row')
         return
      end if
      approach = rows(1, 1)
      area = rows(1, 2)
      length = rows(1, 3)
      width = rows(1, 4)
   end subroutine reference_normal

   !> Lateral extent of the loaded strips (mm).
   pure real(wp) function patch_width(patch)
      type(normal_patch_type), intent(in) :: patch
      patch_width = patch%dy*count(patch%a(1:patch%n_strips) > 0.0_wp)
   end function patch_width

   !> The named columns of a CSV file with one header line, as reals (rows × columns). With
   !> row_tag, only rows having a cell equal to it are kept.
   subroutine read_columns(path, names, values, error, row_tag)
      character(len=*), intent(in) :: path
      character(len=*), intent(in) :: names(:)
      real(wp), allocatable, intent(out) :: values(:, :)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: row_tag
      character(len=4096) :: line
      character(len=64), allocatable :: header(:), cells(:)
      integer :: unit, stat, k, n, pass, col(size(names))

      open (newunit=unit, file=path, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, path//': cannot open')
         return
      end if
      read (unit, '(a)') line
      call split(line, header)
      do k = 1, size(names)
         col(k) = findloc(header, names(k), dim=1)
         if (col(k) == 0) then
            call test_failed(error, path//': no column '//trim(names(k)))
            close (unit)
            return
         end if
      end do
      ! Pass 1 counts the rows, pass 2 reads them.
      do pass = 1, 2
         n = 0
         do
            read (unit, '(a)', iostat=stat) line
            if (stat /= 0) exit
            if (len_trim(line) == 0) cycle
            call split(line, cells)
            if (present(row_tag)) then
               if (findloc(cells, row_tag, dim=1) == 0) cycle
            end if
            n = n + 1
            if (pass == 1) cycle
            do k = 1, size(names)
               read (cells(col(k)), *, iostat=stat) values(n, k)
               if (stat /= 0) then
                  call test_failed(error, path//': not a number: '//trim(cells(col(k))))
                  close (unit)
                  return
               end if
            end do
         end do
         if (pass == 1) then
            allocate (values(n, size(names)))
            rewind (unit)
            read (unit, '(a)') line
         end if
      end do
      close (unit)
   end subroutine read_columns

   !> Split a CSV line at commas (the files read here have no quoted commas).
   pure subroutine split(line, cells)
      character(len=*), intent(in) :: line
      character(len=64), allocatable, intent(out) :: cells(:)
      integer :: i, n, start
      n = count([(line(i:i) == ',', i=1, len_trim(line))]) + 1
      allocate (cells(n))
      n = 0
      start = 1
      do i = 1, len_trim(line) + 1
         if (i <= len_trim(line)) then
            if (line(i:i) /= ',') cycle
         end if
         n = n + 1
         cells(n) = adjustl(line(start:i - 1))
         start = i + 1
      end do
   end subroutine split

   !> Nearest-rank percentile (the smallest value with at least a fraction q at or below it).
   function percentile(values, q) result(p)
      real(wp), intent(in) :: values(:), q
      real(wp) :: p
      real(wp) :: sorted(size(values)), v
      integer :: i, j
      sorted = values
      do i = 2, size(sorted)
         v = sorted(i)
         j = i - 1
         do while (j >= 1)
            if (sorted(j) <= v) exit
            sorted(j + 1) = sorted(j)
            j = j - 1
         end do
         sorted(j + 1) = v
      end do
      p = sorted(min(size(sorted), max(1, ceiling(q*size(sorted) - 1.0e-9_wp))))
   end function percentile

end module test_validation
