!> The prescribed-creepage DOE on every shared patch (issue 13): for each patch folder of
!> ../shared/reference/ (ty0_literal, ty5p8_literal) our patch at the same Y_WS (the one nearest
!> CONTACT's reference point), loaded with F_n = 64.7 kN, and the exact-theory DOE of that folder
!> (10³ for ty0, 20³ for ty5p8) solved by the library defaults and the main alternatives, one
!> setting changed at a time. Writes patches_doe.csv and patches_doe.md.
!>
!> The creepages are prescribed at the geometric contact point, as in §3 (module 3); the sign
!> mapping is that of validate_tangential.
module validate_patches
   use, intrinsic :: iso_fortran_env, only: output_unit, int64
   use shcontact, only: wp, error_type, fatal_error, stat_invalid_input, material_type, &
      prepared_profiles_type, patch_geometry_type, normal_patch_type, find_contact_patches, &
      wheelset_position_type, tangential_options_type, parse_bound, parse_spin_model
   use shcontact_tangential_options, only: parse_spin_flexibility, parse_correction
   use validate_csv, only: csv_table_type, read_csv, summary_value, csv_writer_type, column
   use validate_case, only: solve_normal, reference_material
   use validate_normal, only: reference_pressure_patch, write_strips
   use validate_tangential, only: case_set_type, read_case_set, solve_set, error_stats_type, &
      error_stats
   use validate_lobes, only: run_lobes
   use validate_sets, only: pool_errors, set_all_positions, set_two_lobe, declare_set
   implicit none
   private

   public :: run_patches, patch_names, n_configs, config_labels

   !> The sets of the summary (validate_sets): the shared positions one by one, the project's
   !> single-lobe positions together, and every project position (with the two-lobe ones of
   !> validate_lobes).
   character(len=*), parameter :: set_names(2) = [character(len=62) :: &
      'ty0_literal: external data, Y_WS 0 mm, DOE 10³', &
      'ty5p8_literal: external data, Y_WS 5.8 mm, DOE 20³']
   character(len=*), parameter :: set_single = &
      'data/exact: the 19 single-lobe positions −6 … 7 mm, DOE 6³ each'
   !> The configurations of the summary: defaults, normal reduction local-hertz, correction none.
   integer, parameter :: set_configs(3) = [1, 9, 10]

   !> The patch folders: the two shared ones (under ../shared/reference/), then the positions of
   !> data/exact/ (doc/validation.md §6.5: CONTACT runs made for this project, same set-up).
   integer, parameter :: n_shared = 2
   character(len=*), parameter :: patch_names(21) = [character(len=13) :: 'ty0_literal', &
      'ty5p8_literal', 'yws-6p0', 'yws-4p0', 'yws-2p0', 'yws-1p0', 'yws0p5', 'yws0p75', &
      'yws1p0', 'yws1p25', 'yws1p5', 'yws2p0', 'yws2p5', 'yws3p0', 'yws3p5', 'yws4p0', &
      'yws4p4', 'yws4p6', 'yws6p0', 'yws6p5', 'yws7p0']
   !> Where the project's own exact-theory positions are (relative to the repository root).
   character(len=*), parameter :: extra_root = 'data/exact/'
   !> Configurations: the defaults first, then one setting changed at a time; the last rows run
   !> FASTSIM_SH on CONTACT's exact pressure (c_pressure = 'contact', validate_normal's
   !> reference_pressure_patch), which separates the tangential model's error from the normal one.
   integer, parameter :: n_configs = 14
   character(len=*), parameter :: config_labels(n_configs) = [character(len=48) :: &
      'defaults (coupled; W1; exact-ellipse)', 'bound ellipsoidal', &
      'bound parabolic', 'bound weighted-slip (W2)', 'bound clipped (W3)', &
      'spin flexibility spin', 'spin model additive', 'normal reduction constant', &
      'normal reduction local-hertz', 'correction none', &
      'issue-13 start (local-hertz; no correction)', 'defaults on CONTACT pressure', &
      'correction none on CONTACT pressure', 'ellipsoidal on CONTACT pressure']
   !> The configurations of the first table of patches_doe.md (doc/validation.md Table 10): the
   !> defaults, the defaults on CONTACT's pressure, the defaults when issue 13 was filed, then
   !> one option changed at a time.
   integer, parameter :: summary_configs(8) = [1, 12, 11, 2, 6, 7, 9, 10]
   character(len=*), parameter :: c_bound(n_configs) = [character(len=13) :: 'weighted', &
      'ellipsoidal', 'parabolic', 'weighted-slip', 'clipped', 'weighted', 'weighted', 'weighted', &
      'weighted', 'weighted', 'weighted', 'weighted', 'weighted', 'ellipsoidal']
   character(len=*), parameter :: c_flex(n_configs) = [character(len=12) :: 'longitudinal', &
      'longitudinal', 'longitudinal', 'longitudinal', 'longitudinal', 'spin', 'longitudinal', &
      'longitudinal', 'longitudinal', 'longitudinal', 'longitudinal', 'longitudinal', &
      'longitudinal', 'longitudinal']
   character(len=*), parameter :: c_spin(n_configs) = [character(len=8) :: 'uniform', &
      'uniform', 'uniform', 'uniform', 'uniform', 'uniform', 'additive', 'uniform', 'uniform', &
      'uniform', 'uniform', 'uniform', 'uniform', 'uniform']
   character(len=*), parameter :: c_reduction(n_configs) = [character(len=11) :: &
      'coupled', 'coupled', 'coupled', 'coupled', 'coupled', 'coupled', 'coupled', 'constant', &
      'local-hertz', 'coupled', 'local-hertz', 'coupled', 'coupled', 'coupled']
   character(len=*), parameter :: c_pressure(n_configs) = [character(len=7) :: 'ours', &
      'ours', 'ours', 'ours', 'ours', 'ours', 'ours', 'ours', 'ours', 'ours', 'ours', 'contact', &
      'contact', 'contact']
   !> Every configuration has each strip's own flexibilities (the 'patch' and 'carter' variants
   !> were removed in issue 26; doc/validation.md keeps their last numbers).
   character(len=*), parameter :: c_flexibility(n_configs) = [character(len=6) :: 'strip', &
      'strip', 'strip', 'strip', 'strip', 'strip', 'strip', 'strip', 'strip', 'strip', 'strip', &
      'strip', 'strip', 'strip']
   character(len=*), parameter :: c_correction(n_configs) = [character(len=13) :: &
      'exact-ellipse', 'exact-ellipse', 'exact-ellipse', 'exact-ellipse', 'exact-ellipse', &
      'exact-ellipse', 'exact-ellipse', 'exact-ellipse', 'exact-ellipse', 'none', 'none', &
      'exact-ellipse', 'none', 'exact-ellipse']

contains

   !> Every patch × configuration; writes patches_doe.csv and patches_doe.md.
   subroutine run_patches(ref_root, prepared, out_dir, error)
      !> ../shared/reference/ (with a trailing '/').
      character(len=*), intent(in) :: ref_root
      !> The prepared Manchester profiles (validate_case%load_manchester).
      type(prepared_profiles_type), intent(in) :: prepared
      !> Output directory.
      character(len=*), intent(in) :: out_dir
      !> Set when a file cannot be read or written.
      type(error_type), allocatable, intent(out) :: error
      type(error_stats_type) :: ex(n_configs, size(patch_names)), ey(n_configs, size(patch_names))
      real(wp) :: bx(n_configs, size(patch_names)), by(n_configs, size(patch_names))
      real(wp) :: cost(n_configs, size(patch_names)), fmax(n_configs, size(patch_names))
      character(len=24) :: doe_names(size(patch_names))
      integer :: n_cases(size(patch_names))
      type(csv_writer_type) :: out
      character(len=48) :: cells(10)
      real(wp) :: normal(4, size(patch_names))
      integer :: ip, ic

      ! The order of the summary's rows (validate_sets).
      call declare_set(trim(set_names(1)))
      call declare_set(trim(set_names(2)))
      call declare_set(set_single)
      call declare_set(set_two_lobe)
      call declare_set(set_all_positions)
      do ip = 1, size(patch_names)
         call run_patch(patch_dir(ref_root, ip), prepared, out_dir// &
            'patches_strips_'//trim(patch_names(ip)), ex(:, ip), ey(:, ip), bx(:, ip), &
            by(:, ip), cost(:, ip), fmax(:, ip), doe_names(ip), n_cases(ip), error, ip, &
            normal(:, ip))
         if (allocated(error)) return
      end do
      call write_normal(out_dir, normal, error)
      if (allocated(error)) return
      call out%open(out_dir//'patches_doe.csv', 'patch,doe,configuration,bound,spin_model,'// &
         'spin_flexibility,flexibility,reduction,pressure,correction,n_cases,dfx_max,dfx_p80,'// &
         'dfx_mean,dfx_bias,dfy_max,dfy_p80,dfy_mean,dfy_bias,f_max,us_per_case', &
         error)
      if (allocated(error)) return
      do ip = 1, size(patch_names)
         do ic = 1, n_configs
            ! Cell by cell: an array constructor of names of different lengths is cut to the
            ! first one's length by gfortran 12.
            cells(1) = patch_names(ip)
            cells(2) = doe_names(ip)
            cells(3) = config_labels(ic)
            cells(4) = c_bound(ic)
            cells(5) = c_spin(ic)
            cells(6) = c_flex(ic)
            cells(7) = c_flexibility(ic)
            cells(8) = c_reduction(ic)
            cells(9) = c_pressure(ic)
            cells(10) = c_correction(ic)
            call out%row([real(n_cases(ip), wp), ex(ic, ip)%max, ex(ic, ip)%p80, &
               ex(ic, ip)%mean, bx(ic, ip), ey(ic, ip)%max, ey(ic, ip)%p80, ey(ic, ip)%mean, &
               by(ic, ip), fmax(ic, ip), cost(ic, ip)], text=cells, digits=4)
         end do
      end do
      call out%close()
      call write_markdown(out_dir//'patches_doe.md', ex, ey, doe_names, error)
      if (allocated(error)) return
      write (output_unit, '(a)') 'shcontact-validate: DOE on every patch written to '// &
         out_dir//'patches_doe.csv, patches_doe.md'
      call run_lobes(prepared, out_dir, error)
   end subroutine run_patches

   !> One patch: geometry, normal solution per reduction, the DOE per configuration; the strip
   !> tables of our default patch and of CONTACT's pressure to strips_base_{ours,contact}.csv.
   subroutine run_patch(ref_dir, prepared, strips_base, ex, ey, bx, by, cost, fmax, doe_name, &
      n, error, ip, normal)
      character(len=*), intent(in) :: ref_dir
      type(prepared_profiles_type), intent(in) :: prepared
      character(len=*), intent(in) :: strips_base
      type(error_stats_type), intent(out) :: ex(n_configs), ey(n_configs)
      !> Mean magnitude bias of f_x and f_y: (f − f_exact) sign(f_exact) averaged, > 0 when our
      !> forces are too large.
      real(wp), intent(out) :: bx(n_configs), by(n_configs)
      !> Wall time of one tangential solve (µs per case, best of three runs of the set).
      real(wp), intent(out) :: cost(n_configs)
      !> Largest |f| = |F_t|/(μF_n) over the cases.
      real(wp), intent(out) :: fmax(n_configs)
      character(len=24), intent(out) :: doe_name
      integer, intent(out) :: n
      type(error_type), allocatable, intent(out) :: error
      !> The patch's index in patch_names (its set in the summary).
      integer, intent(in) :: ip
      !> The normal contact under F_n = 64.7 kN, ours (the defaults) and CONTACT's: p_max ours,
      !> CONTACT's (MPa), area ours, CONTACT's (mm²: its elements with p_n > 0); −1 without
      !> CONTACT's pressure grid.
      real(wp), intent(out) :: normal(4)
      type(csv_table_type) :: summary
      type(patch_geometry_type) :: geometry
      type(normal_patch_type) :: patch, default_patch, contact_patch, coupled_patch
      type(case_set_type) :: set
      type(tangential_options_type) :: options
      real(wp), allocatable :: fx(:), fy(:)
      real(wp) :: y_ws, y_ref, y_geo
      logical :: there, has_grid
      integer :: ic, rep
      integer(int64) :: t0, t1, rate

      call read_csv(ref_dir//'summary.csv', summary, error)
      if (allocated(error)) return
      call summary_value(summary, 'y_ws', y_ws, error)
      if (allocated(error)) return
      call summary_value(summary, 'ycp_tr', y_ref, error)
      if (allocated(error)) return
      call summary_value(summary, 'y_geo', y_geo, error)
      if (allocated(error)) return
      call nearest_patch(prepared, y_ws, y_ref, geometry, error)
      if (allocated(error)) return
      doe_name = 'doe_10x10x10'
      inquire (file=ref_dir//trim(doe_name)//'_exact_nonhertz.csv', exist=there)
      if (.not. there) doe_name = 'doe_20x20x20'
      inquire (file=ref_dir//trim(doe_name)//'_exact_nonhertz.csv', exist=there)
      if (.not. there) doe_name = 'doe_6x6x6'
      ! CONTACT's pressure field is kept for the shared patches only; without it those rows
      ! repeat our own pressure and are reported as not available.
      inquire (file=ref_dir//'grid_module3_exact_nonhertz.csv', exist=has_grid)
      call read_case_set(ref_dir//trim(doe_name)//'_exact_nonhertz.csv', doe_name, set, error)
      if (allocated(error)) return
      n = size(set%fx)
      call solve_normal(geometry, reference_material(), 'semi-hertz', 'local-hertz', 100, 64700.0_wp, &
         default_patch, error)
      if (allocated(error)) return
      contact_patch = default_patch
      if (has_grid) call reference_pressure_patch(ref_dir//'grid_module3_exact_nonhertz.csv', &
         y_geo, default_patch, contact_patch, error)
      if (allocated(error)) return
      call write_strips(strips_base//'_local_hertz.csv', default_patch, y_geo, error)
      if (allocated(error)) return
      call write_strips(strips_base//'_contact.csv', contact_patch, y_geo, error)
      if (allocated(error)) return
      do ic = 1, n_configs
         if (c_pressure(ic) == 'contact') then
            patch = contact_patch
         else if (c_reduction(ic) == 'local-hertz') then
            patch = default_patch
         else if (c_reduction(ic) == 'coupled' .and. ic > 1) then
            patch = coupled_patch
         else
            call solve_normal(geometry, reference_material(), 'semi-hertz', c_reduction(ic), 100, &
               64700.0_wp, patch, error)
            if (allocated(error)) return
            if (c_reduction(ic) == 'coupled') then
               coupled_patch = patch
               call write_strips(strips_base//'_coupled.csv', patch, y_geo, error)
               if (allocated(error)) return
            end if
         end if
         call options_of(ic, options, error)
         if (allocated(error)) return
         ! Best of three timed runs: the cost per case of each configuration, same run.
         cost(ic) = huge(1.0_wp)
         do rep = 1, 3
            call system_clock(t0, rate)
            call solve_set(patch, reference_material(), options, set, fx, fy, error)
            if (allocated(error)) return
            call system_clock(t1)
            cost(ic) = min(cost(ic), 1.0e6_wp*real(t1 - t0, wp)/real(rate, wp)/n)
         end do
         fmax(ic) = maxval(hypot(fx, fy))
         ex(ic) = error_stats(abs(fx - set%fx))
         ey(ic) = error_stats(abs(fy - set%fy))
         if (c_pressure(ic) == 'contact' .and. .not. has_grid) then
            ex(ic)%max = -1.0_wp
            ey(ic)%max = -1.0_wp
         end if
         bx(ic) = sum((fx - set%fx)*sign(1.0_wp, set%fx))/n
         if (any(set_configs == ic)) then
            if (ip <= n_shared) then
               call pool_errors(trim(set_names(ip)), findloc(set_configs, ic, 1), &
                  abs(fx - set%fx), abs(fy - set%fy), fmax(ic))
            else
               call pool_errors(set_single, findloc(set_configs, ic, 1), abs(fx - set%fx), &
                  abs(fy - set%fy), fmax(ic))
               call pool_errors(set_all_positions, findloc(set_configs, ic, 1), &
                  abs(fx - set%fx), abs(fy - set%fy), fmax(ic))
            end if
         end if
         by(ic) = sum((fy - set%fy)*sign(1.0_wp, set%fy))/n
      end do
      normal = -1.0_wp
      if (has_grid) call normal_against_grid(ref_dir, summary, coupled_patch, normal, error)
   end subroutine run_patch

   !> Our p_max and area beside CONTACT's from its pressure grid (run_patch's `normal`).
   subroutine normal_against_grid(ref_dir, summary, patch, normal, error)
      character(len=*), intent(in) :: ref_dir
      type(csv_table_type), intent(in) :: summary
      type(normal_patch_type), intent(in) :: patch
      real(wp), intent(out) :: normal(4)
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: grid
      real(wp), allocatable :: pn(:)
      real(wp) :: dx, dy

      normal = -1.0_wp
      call summary_value(summary, 'grid_dx', dx, error)
      if (.not. allocated(error)) call summary_value(summary, 'grid_dy', dy, error)
      if (.not. allocated(error)) call read_csv(ref_dir//'grid_module3_exact_nonhertz.csv', &
         grid, error)
      if (.not. allocated(error)) call column(grid, 'pn_MPa', pn, error)
      if (allocated(error)) return
      normal = [patch%p_max, maxval(pn), patch%area, count(pn > 0.0_wp)*dx*dy]
   end subroutine normal_against_grid

   !> The folder of patch ip: ../shared/reference/<name>/ for the shared ones, data/exact/<name>/.
   function patch_dir(ref_root, ip) result(dir)
      character(len=*), intent(in) :: ref_root
      integer, intent(in) :: ip
      character(len=:), allocatable :: dir
      if (ip <= n_shared) then
         dir = ref_root//trim(patch_names(ip))//'/'
      else
         dir = extra_root//trim(patch_names(ip))//'/'
      end if
   end function patch_dir


   !> Our patch at y_ws whose reference point is nearest CONTACT's (track y).
   subroutine nearest_patch(prepared, y_ws, y_ref, geometry, error)
      type(prepared_profiles_type), intent(in) :: prepared
      real(wp), intent(in) :: y_ws, y_ref
      type(patch_geometry_type), intent(out) :: geometry
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      integer :: k, best

      call find_contact_patches(prepared, wheelset_position_type(y_ws=y_ws), patches, error)
      if (allocated(error)) return
      if (size(patches) < 1) then
         call fatal_error(error, 'no contact patch at the reference''s Y_WS', stat_invalid_input)
         return
      end if
      best = 1
      do k = 2, size(patches)
         if (abs(patches(k)%y_track - y_ref) < abs(patches(best)%y_track - y_ref)) best = k
      end do
      geometry = patches(best)
   end subroutine nearest_patch

   !> The tangential options of configuration ic (fields off).
   subroutine options_of(ic, options, error)
      integer, intent(in) :: ic
      type(tangential_options_type), intent(out) :: options
      type(error_type), allocatable, intent(out) :: error
      call parse_bound(trim(c_bound(ic)), options%bound, error)
      if (.not. allocated(error)) call parse_spin_model(trim(c_spin(ic)), options%spin_model, &
         error)
      if (.not. allocated(error)) call parse_spin_flexibility(trim(c_flex(ic)), &
         options%spin_flexibility, error)
      if (.not. allocated(error)) call parse_correction(trim(c_correction(ic)), &
         options%correction, error)
      options%n_elements = 50
      options%fields = .false.
   end subroutine options_of

   !> patches_normal.csv and patches_normal.md: p_max and area, ours (defaults, F_n = 64.7 kN)
   !> and CONTACT's, at every position with CONTACT's pressure grid, and how many are within
   !> 10 % and 5 % (issue 28's goal: 21/21 and 18/21).
   subroutine write_normal(out_dir, normal, error)
      character(len=*), intent(in) :: out_dir
      real(wp), intent(in) :: normal(:, :)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      real(wp) :: dp(size(normal, 2)), da(size(normal, 2))
      logical :: has(size(normal, 2))
      integer :: ip, unit, stat

      has = normal(2, :) > 0.0_wp
      where (has)
         dp = normal(1, :)/normal(2, :) - 1.0_wp
         da = normal(3, :)/normal(4, :) - 1.0_wp
      elsewhere
         dp = 0.0_wp
         da = 0.0_wp
      end where
      call out%open(out_dir//'patches_normal.csv', 'patch,p_max_MPa,p_max_contact_MPa,'// &
         'area_mm2,area_contact_mm2,dp_rel,darea_rel', error)
      if (allocated(error)) return
      do ip = 1, size(patch_names)
         if (.not. has(ip)) cycle
         call out%row([normal(:, ip), dp(ip), da(ip)], text=[patch_names(ip)], digits=5)
      end do
      call out%close()
      open (newunit=unit, file=out_dir//'patches_normal.md', status='replace', action='write', &
         iostat=stat)
      if (stat /= 0) then
         call fatal_error(error, out_dir//'patches_normal.md: cannot write')
         return
      end if
      write (unit, '(a)') '<!-- written by `fpm run --example shcontact-validate --profile '// &
         'release` (patches_normal.csv) -->', '', 'Normal contact under F_n = 64.7 kN, the '// &
         'defaults against CONTACT (module 3, exact):', '', &
         '| position | p_max ours (MPa) | CONTACT | Δ | area ours (mm²) | CONTACT | Δ |', &
         '|---|---|---|---|---|---|---|'
      do ip = 1, size(patch_names)
         if (.not. has(ip)) cycle
         write (unit, '(a,2(" | ",i0," | ",i0," | ",sp,f5.1,"%",ss)," |")') &
            '| '//trim(patch_names(ip)), nint(normal(1:2, ip)), 1.0e2_wp*dp(ip), &
            nint(normal(3:4, ip)), 1.0e2_wp*da(ip)
      end do
      write (unit, '(a,i0,a,i0,a,i0,a,i0,a,i0,a)') '', count(has), ' positions: p_max within '// &
         '10 % at ', count(has .and. abs(dp) <= 0.1_wp), ', within 5 % at ', &
         count(has .and. abs(dp) <= 0.05_wp), '; area within 10 % at ', &
         count(has .and. abs(da) <= 0.1_wp), ', within 5 % at ', &
         count(has .and. abs(da) <= 0.05_wp), '.'
      close (unit)
   end subroutine write_normal

   !> patches_doe.md: first the positions as rows against the defaults and the main alternatives
   !> ([[summary_configs]]; doc/validation.md Table 10), then every configuration as a row.
   subroutine write_markdown(path, ex, ey, doe_names, error)
      character(len=*), intent(in) :: path
      type(error_stats_type), intent(in) :: ex(:, :), ey(:, :)
      character(len=*), intent(in) :: doe_names(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=2048) :: msg, line
      integer :: unit, stat, ic, ip, k

      open (newunit=unit, file=path, status='replace', action='write', iostat=stat, iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, path//': cannot write ('//trim(msg)//')')
         return
      end if
      write (unit, '(a)') '<!-- written by `fpm run --example shcontact-validate --profile '// &
         'release` (patches_doe.csv) -->', '', &
         'max \|Δf\| ; P80 \|Δf_x\| / P80 \|Δf_y\| against the exact theory', '', &
         'Every position, the defaults and the main alternatives:', ''
      line = '| position (DOE) |'
      do k = 1, size(summary_configs)
         line = trim(line)//' '//trim(config_labels(summary_configs(k)))//' |'
      end do
      write (unit, '(a)') trim(line), '|---|'//repeat('---|', size(summary_configs))
      do ip = 1, size(patch_names)
         line = '| '//trim(patch_names(ip))//' ('//trim(doe_names(ip))//') |'
         do k = 1, size(summary_configs)
            line = trim(line)//cell(summary_configs(k), ip)
         end do
         write (unit, '(a)') trim(line)
      end do
      write (unit, '(a)') '', 'Every configuration:', ''
      line = '| configuration |'
      do ip = 1, size(patch_names)
         line = trim(line)//' '//trim(patch_names(ip))//' ('//trim(doe_names(ip))//') |'
      end do
      write (unit, '(a)') trim(line), '|---|'//repeat('---|', size(patch_names))
      do ic = 1, n_configs
         line = '| '//trim(config_labels(ic))//' |'
         do ip = 1, size(patch_names)
            line = trim(line)//cell(ic, ip)
         end do
         write (unit, '(a)') trim(line)
      end do
      close (unit)
   contains
      !> One table cell: max ; P80 x / P80 y, or n/a.
      function cell(ic, ip) result(text)
         integer, intent(in) :: ic, ip
         character(len=:), allocatable :: text
         character(len=40) :: buf
         if (ex(ic, ip)%max < 0.0_wp) then
            text = ' n/a |'
         else
            write (buf, '(3(f5.3,a))') max(ex(ic, ip)%max, ey(ic, ip)%max), ' ; ', &
               ex(ic, ip)%p80, ' / ', ey(ic, ip)%p80, ' |'
            text = ' '//trim(buf)
         end if
      end function cell
   end subroutine write_markdown

end module validate_patches
