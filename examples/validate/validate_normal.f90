!> Normal contact against the exact theory (issue 4): the ty0 patch under F_n = 64.7 kN against
!> CONTACT's module-3 solution (../shared/reference/, README §2), and the Manchester 10 kN rows of
!> doc/theory.md §4.7 / §5.6 with our 2-D, no-yaw geometry.
module validate_normal
   use shcontact, only: wp, error_type, fatal_error, stat_invalid_input, material_type, &
      prepared_profiles_type, element_pressure, &
      patch_geometry_type, normal_patch_type, find_contact_patches, wheelset_position_type, &
      normal_options_type, new_normal_options, normal_contact_type, prepare_normal_contact, &
      solve_vertical_load
   use shcontact_core_constants, only: pi
   use validate_csv, only: csv_table_type, read_csv, column, column_index, csv_writer_type
   implicit none
   private

   public :: patch_summary_type, summarise_patch, reference_patch_summary, write_strips
   public :: manchester_rows, reference_pressure_patch, spin_saturation, patch_spin_saturation

   !> Extent and peak of one normal solution, in CONTACT's local coordinates (y from CONTACT's
   !> weighted centre: ours + y_geo).
   type :: patch_summary_type
      !> Approach (mm), normal force (N).
      real(wp) :: approach = 0.0_wp, load = 0.0_wp
      !> Longest extent in x, lateral extent, area (mm, mm, mm²).
      real(wp) :: length = 0.0_wp, width = 0.0_wp, area = 0.0_wp
      !> Peak pressure (MPa).
      real(wp) :: p_max = 0.0_wp
      !> Lateral limits of the contact and the pressure-weighted centre (mm, CONTACT's y).
      real(wp) :: y_min = 0.0_wp, y_max = 0.0_wp, y_centre = 0.0_wp
   end type patch_summary_type

   !> Manchester benchmark, CONTACT exact at F_z = 10 kN (doc/theory.md §4.7 table and §5.6): y_ws,
   !> approach (mm), p_max (MPa), contact angle δ (rad), rail reference point y_r (mm).
   real(wp), parameter :: manchester_y_ws(3) = [0.0_wp, 0.5_wp, 5.0_wp]
   real(wp), parameter :: manchester_approach(3) = [0.01596_wp, 0.01948_wp, 0.02719_wp]
   real(wp), parameter :: manchester_p_max(3) = [338.3_wp, 632.5_wp, 1556.0_wp]
   real(wp), parameter :: manchester_delta(3) = [-0.0290_wp, -0.0568_wp, -0.2905_wp]
   real(wp), parameter :: manchester_y_r(3) = [-8.660_wp, -16.030_wp, -33.447_wp]
   !> The same rows by CONTACT's ANALYN (B = 6, the local-Hertz strip method) and KPEC (B = 5):
   !> approach (mm), p_max (MPa) (doc/theory.md §4.7).
   real(wp), parameter :: analyn_approach(3) = [0.01646_wp, 0.02055_wp, 0.02905_wp]
   real(wp), parameter :: analyn_p_max(3) = [352.1_wp, 710.3_wp, 1627.0_wp]
   real(wp), parameter :: kpec_approach(3) = [0.01344_wp, 0.02017_wp, 0.02993_wp]
   real(wp), parameter :: kpec_p_max(3) = [442.6_wp, 569.8_wp, 1625.0_wp]

contains

   !> Summary of one of our patches; lateral positions shifted by y_shift (y_geo: CONTACT's
   !> geometric point in its local coordinates).
   pure function summarise_patch(patch, y_shift) result(s)
      !> The normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> Added to our y (mm).
      real(wp), intent(in) :: y_shift
      type(patch_summary_type) :: s
      integer :: i, first, last

      s%approach = patch%approach
      s%load = patch%load
      s%area = patch%area
      s%p_max = patch%p_max
      s%length = 2.0_wp*maxval(patch%a(1:patch%n_strips))
      first = 0
      last = 0
      do i = 1, patch%n_strips
         if (.not. (patch%a(i) > 0.0_wp)) cycle
         if (first == 0) first = i
         last = i
      end do
      if (first == 0) return
      s%y_min = patch%y(first) - 0.5_wp*patch%dy + y_shift
      s%y_max = patch%y(last) + 0.5_wp*patch%dy + y_shift
      s%width = s%y_max - s%y_min
      ! Load-weighted strip centres: the pressure-weighted centre of the patch.
      s%y_centre = sum(patch%strip_load(1:patch%n_strips)*patch%y(1:patch%n_strips))/ &
         sum(patch%strip_load(1:patch%n_strips)) + y_shift
   end function summarise_patch

   !> The reference's normal solution: CONTACT's printed extent, area, p_max and approach from
   !> headline_summary.csv (row `method`), the load and the pressure-weighted centre from its
   !> traction grid (Σ p_n y / Σ p_n; the lateral limits are element edges).
   subroutine reference_patch_summary(summary_path, method, grid_path, s, error)
      !> headline_summary.csv.
      character(len=*), intent(in) :: summary_path
      !> Its `method` value, e.g. 'module3_exact_nonhertz'.
      character(len=*), intent(in) :: method
      !> grid_module3_<method>.csv.
      character(len=*), intent(in) :: grid_path
      !> The summary.
      type(patch_summary_type), intent(out) :: s
      !> Set when a file or column is missing.
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: table
      real(wp), allocatable :: v(:), y(:), x(:), pn(:)
      integer :: row, jm
      real(wp) :: dx, dy

      call read_csv(summary_path, table, error)
      if (allocated(error)) return
      jm = column_index(table, 'method')
      row = findloc(table%cells(:, jm), method, dim=1)
      if (row == 0) then
         call fatal_error(error, summary_path//': no row with method "'//method//'"', &
            stat_invalid_input)
         return
      end if
      call column(table, 'pen_mm', v, error)
      if (allocated(error)) return
      s%approach = v(row)
      call column(table, 'contact_length_mm', v, error)
      if (allocated(error)) return
      s%length = v(row)
      call column(table, 'contact_width_mm', v, error)
      if (allocated(error)) return
      s%width = v(row)
      call column(table, 'contact_area_mm2', v, error)
      if (allocated(error)) return
      s%area = v(row)
      call column(table, 'pmax_MPa', v, error)
      if (allocated(error)) return
      s%p_max = v(row)
      call column(table, 'grid_dx_mm', v, error)
      if (allocated(error)) return
      dx = v(row)
      call column(table, 'grid_dy_mm', v, error)
      if (allocated(error)) return
      dy = v(row)

      call read_csv(grid_path, table, error)
      if (allocated(error)) return
      call column(table, 'x_mm', x, error)
      if (allocated(error)) return
      call column(table, 'y_mm', y, error)
      if (allocated(error)) return
      call column(table, 'pn_MPa', pn, error)
      if (allocated(error)) return
      s%load = sum(pn)*dx*dy
      s%y_centre = sum(pn*y)/sum(pn)
      s%y_min = minval(y, mask=pn > 0.0_wp) - 0.5_wp*dy
      s%y_max = maxval(y, mask=pn > 0.0_wp) + 0.5_wp*dy
   end subroutine reference_patch_summary

   !> Write the strip table of a patch (for the pressure maps): y ours and in CONTACT's local
   !> coordinates, half-length, peak pressure, load per unit width.
   subroutine write_strips(path, patch, y_shift, error)
      !> Output file.
      character(len=*), intent(in) :: path
      !> The normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> CONTACT's y of our reference point (mm).
      real(wp), intent(in) :: y_shift
      !> Set when the file cannot be written.
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      integer :: i

      call out%open(path, 'y_mm,y_contact_mm,a_mm,k,p0_MPa,q_N_per_mm,a_over_b_local', error)
      if (allocated(error)) return
      do i = 1, patch%n_strips
         call out%row([patch%y(i), patch%y(i) + y_shift, patch%a(i), patch%k(i), patch%p0(i), &
            patch%strip_load(i)/patch%dy, patch%m(i)/patch%n(i)])
      end do
      call out%close()
   end subroutine write_strips

   !> The Manchester rows (doc/theory.md §4.7, §5.6): F_z = 10 kN shared by all patches of the
   !> right wheel through one rigid approach (§4.6), G = 82000 MPa, ν = 0.28, our geometry (2-D,
   !> no yaw: CONTACT's rows at y_ws > 0 are yawed 2.4 mrad/mm). One CSV row per loaded patch.
   subroutine manchester_rows(prepared, path, error)
      !> The Manchester profiles.
      type(prepared_profiles_type), intent(in) :: prepared
      !> Output CSV.
      character(len=*), intent(in) :: path
      !> Set when a solve or the file fails.
      type(error_type), allocatable, intent(out) :: error
      type(material_type) :: material
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_contact_type), allocatable :: contacts(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(normal_options_type) :: options
      type(csv_writer_type) :: out
      real(wp) :: dz, y_centre
      integer :: iw, k

      material = material_type(shear_modulus=82000.0_wp, poisson=0.28_wp, friction=0.3_wp)
      call new_normal_options(options, error)
      if (allocated(error)) return
      call out%open(path, 'y_ws_mm,patch,fn_N,approach_mm,p_max_MPa,gamma0_rad,y_r_centre_mm,'// &
         'y_r_geometric_mm,contact_approach_mm,contact_p_max_MPa,contact_delta_rad,'// &
         'contact_y_r_mm,analyn_approach_mm,analyn_p_max_MPa,kpec_approach_mm,kpec_p_max_MPa', &
         error)
      if (allocated(error)) return
      do iw = 1, size(manchester_y_ws)
         call find_contact_patches(prepared, wheelset_position_type(y_ws=manchester_y_ws(iw)), &
            geometry, error)
         if (allocated(error)) return
         if (allocated(contacts)) deallocate (contacts)
         if (allocated(patches)) deallocate (patches)
         allocate (contacts(size(geometry)), patches(size(geometry)))
         do k = 1, size(geometry)
            call prepare_normal_contact(contacts(k), geometry(k), options, material, error)
            if (allocated(error)) return
         end do
         call solve_vertical_load(contacts, 10000.0_wp, patches, dz, error)
         if (allocated(error)) return
         do k = 1, size(geometry)
            if (.not. (patches(k)%load > 0.0_wp)) cycle
            ! Tangent-plane offset of the load centre from the loaded point, and the loaded
            ! point's from the first contact, projected on the rail profile's y.
            y_centre = geometry(k)%y_rail + patches(k)%lateral_offset() + &
               cos(geometry(k)%gamma0)*sum(patches(k)%strip_load*patches(k)%y)/ &
               sum(patches(k)%strip_load)
            call out%row([manchester_y_ws(iw), real(k, wp), patches(k)%load, &
               patches(k)%approach, patches(k)%p_max, geometry(k)%gamma0, y_centre, &
               geometry(k)%y_rail, manchester_approach(iw), manchester_p_max(iw), &
               manchester_delta(iw), manchester_y_r(iw), analyn_approach(iw), &
               analyn_p_max(iw), kpec_approach(iw), kpec_p_max(iw)], digits=5)
         end do
      end do
      call out%close()
   end subroutine manchester_rows

   !> A strip table carrying CONTACT's exact pressure (the module-3 grid): one strip per grid row
   !> (width dy), half-length a_i from the row's contact elements, load N_i = Σ p_n dx dy, a
   !> semi-elliptic peak 2N_i/(π a_i dy) that carries it. The local Hertz data (a_H,i, m_i, n_i, γ_i,
   !> δr_i) are interpolated from our own patch at the same lateral position, and k_i = a_i/a_H,i
   !> (≤ 1). FASTSIM_SH on this table separates the tangential model's error from the normal one.
   subroutine reference_pressure_patch(grid_path, y_geo, ours, patch, error)
      !> grid_module3_exact_nonhertz.csv.
      character(len=*), intent(in) :: grid_path
      !> CONTACT's y of the geometric contact point (mm).
      real(wp), intent(in) :: y_geo
      !> Our semi-Hertzian solution (local Hertz data).
      type(normal_patch_type), intent(in) :: ours
      !> The strip table.
      type(normal_patch_type), intent(out) :: patch
      !> Set when the grid file cannot be read.
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: table
      real(wp), allocatable :: iy(:), y(:), x(:), pn(:)
      real(wp) :: dx, dy, a_h
      integer :: n_rows, r, i, j, iy0

      call read_csv(grid_path, table, error)
      if (allocated(error)) return
      call column(table, 'iy', iy, error)
      if (allocated(error)) return
      call column(table, 'x_mm', x, error)
      if (allocated(error)) return
      call column(table, 'y_mm', y, error)
      if (allocated(error)) return
      call column(table, 'pn_MPa', pn, error)
      if (allocated(error)) return
      ! The file may hold the whole grid or only the elements in contact (data/exact/): the
      ! steps are the smallest spacings, the strips run from the first to the last row present.
      iy0 = nint(minval(iy))
      n_rows = nint(maxval(iy)) - iy0 + 1
      dx = huge(1.0_wp)
      dy = huge(1.0_wp)
      do i = 2, size(pn)
         if (nint(iy(i)) == nint(iy(i - 1)) .and. abs(x(i) - x(i - 1)) > 0.0_wp) &
            dx = min(dx, abs(x(i) - x(i - 1)))
         if (nint(iy(i)) /= nint(iy(i - 1)) .and. abs(y(i) - y(i - 1)) > 0.0_wp) &
            dy = min(dy, abs(y(i) - y(i - 1))/abs(iy(i) - iy(i - 1)))
      end do
      if (dx == huge(1.0_wp) .or. dy == huge(1.0_wp)) then
         call fatal_error(error, grid_path//': fewer than two grid steps in x or y')
         return
      end if

      patch = ours
      patch%n_strips = n_rows
      patch%dy = dy
      deallocate (patch%y, patch%a, patch%k, patch%p0, patch%strip_load, patch%m, patch%n, &
         patch%eps_a, patch%gamma, patch%delta_r, patch%r_wheel)
      allocate (patch%y(n_rows), patch%a(n_rows), patch%k(n_rows), patch%p0(n_rows), &
         patch%strip_load(n_rows), patch%m(n_rows), patch%n(n_rows), patch%eps_a(n_rows), &
         patch%gamma(n_rows), patch%delta_r(n_rows), patch%r_wheel(n_rows))
      patch%a = 0.0_wp
      patch%strip_load = 0.0_wp
      do r = 1, n_rows
         patch%y(r) = y(1) - y_geo + real(r + iy0 - 1 - nint(iy(1)), wp)*dy
      end do
      do i = 1, size(pn)
         r = nint(iy(i)) - iy0 + 1
         if (pn(i) > 0.0_wp) then
            patch%a(r) = patch%a(r) + 0.5_wp*dx
            patch%strip_load(r) = patch%strip_load(r) + pn(i)*dx*dy
         end if
      end do
      do r = 1, n_rows
         j = nearest_loaded_strip(ours, patch%y(r))
         patch%m(r) = ours%m(j)
         patch%n(r) = ours%n(j)
         patch%eps_a(r) = ours%eps_a(j)
         patch%gamma(r) = ours%gamma(j)
         patch%delta_r(r) = ours%delta_r(j)
         patch%r_wheel(r) = ours%r_wheel(j)
         patch%k(r) = 0.0_wp
         patch%p0(r) = 0.0_wp
         if (patch%a(r) > 0.0_wp) then
            a_h = ours%a(j)/ours%k(j)
            patch%k(r) = min(1.0_wp, patch%a(r)/a_h)
            patch%p0(r) = 2.0_wp*patch%strip_load(r)/(pi*patch%a(r)*dy)
         end if
      end do
      patch%load = sum(patch%strip_load)
      patch%area = sum(2.0_wp*patch%a)*dy
      patch%p_max = maxval(pn)
   end subroutine reference_pressure_patch

   !> The loaded strip of `patch` nearest to y.
   pure integer function nearest_loaded_strip(patch, y) result(j)
      type(normal_patch_type), intent(in) :: patch
      real(wp), intent(in) :: y
      integer :: i
      real(wp) :: best
      j = 1
      best = huge(1.0_wp)
      do i = 1, patch%n_strips
         if (.not. (patch%a(i) > 0.0_wp)) cycle
         if (abs(patch%y(i) - y) < best) then
            best = abs(patch%y(i) - y)
            j = i
         end if
      end do
   end function nearest_loaded_strip

   !> Full-slip limit of pure spin about (0, y_c): every element slides against the rigid slip
   !> φ(−(y − y_c), x), so the force on the rail is μ Σ p_n (y − y_c, −x)/r; returned normalised,
   !> f = F/(μ Σ p_n). It depends on the pressure distribution only.
   pure subroutine spin_saturation(pn, x, y, y_c, fx, fy)
      !> Pressures (any weights proportional to the element loads) and element centres (mm).
      real(wp), intent(in) :: pn(:), x(:), y(:)
      !> Spin centre (mm).
      real(wp), intent(in) :: y_c
      !> Normalised saturated forces on the rail.
      real(wp), intent(out) :: fx, fy
      real(wp) :: r(size(pn))
      r = max(sqrt((y - y_c)**2 + x**2), 1.0e-9_wp)
      fx = sum(pn*(y - y_c)/r)/sum(pn)
      fy = -sum(pn*x/r)/sum(pn)
   end subroutine spin_saturation

   !> [[spin_saturation]] of our semi-elliptic strip pressure, spin centre at our reference point,
   !> on an element grid of nx elements per strip (element loads p_n Δx_i dy).
   pure subroutine patch_spin_saturation(patch, nx, fx, fy)
      !> The normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> Elements per strip.
      integer, intent(in) :: nx
      !> Normalised saturated forces on the rail.
      real(wp), intent(out) :: fx, fy
      real(wp) :: pn(nx, patch%n_strips), x(nx, patch%n_strips), y(nx, patch%n_strips)
      integer :: i

      call element_pressure(patch, pn, x)
      do i = 1, patch%n_strips
         y(:, i) = patch%y(i)
         ! Element loads: p_n times the element length 2a_i/nx.
         pn(:, i) = pn(:, i)*patch%a(i)
      end do
      call spin_saturation(reshape(pn, [size(pn)]), reshape(x, [size(x)]), &
         reshape(y, [size(y)]), 0.0_wp, fx, fy)
   end subroutine patch_spin_saturation

end module validate_normal
