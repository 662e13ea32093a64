!> The tangential part of the validation (issues 5 and 7): every bound × spin model × spin
!> flexibility × normal reduction on the headline case, the three sweeps and the 10³ DOE of
!> ../shared/reference/ty0_literal/, the classical-FASTSIM and CONTACT-FASTSIM baselines, the
!> Hertzian check, the discretisation study, the traction fields and the saturation limits. Writes
!> the CSV tables of doc/validation/.
module validate_report
   use, intrinsic :: iso_fortran_env, only: output_unit, int64
   use shcontact, only: wp, error_type, fatal_error, stat_invalid_input, material_type, patch_geometry_type, normal_patch_type, &
      tangential_options_type, tangential_patch_type, march_workspace_type, creepage_type, &
      parse_bound, parse_spin_model, prepare_fastsim_sh, bound_name, spin_model_name
   use shcontact_tangential_options, only: parse_spin_flexibility, spin_flexibility_name, &
      method_fastsim, method_fastsim_sh, correction_none
   use shcontact_tangential_march, only: solve_prepared
   use validate_csv, only: csv_table_type, read_csv, column, column_index, summary_value, &
      csv_writer_type
   use validate_tangential, only: case_set_type, read_case_set, solve_set, abs_errors, &
      error_stats_type, error_stats, nearest_rank, sort_ascending
   use validate_case, only: solve_normal, quadratic_geometry
   use validate_normal, only: reference_pressure_patch, spin_saturation, patch_spin_saturation
   implicit none
   private

   public :: recommended_type, run_tangential

   !> The case sets, in this order everywhere: the headline case, the three sweeps, the DOE.
   integer, parameter :: n_sets = 5, i_headline = 1, i_doe = 5
   character(len=*), parameter :: set_names(n_sets) = [character(len=24) :: 'headline', &
      'sweep_spin_0to2', 'sweep_spin_0to5', 'sweep_creep_0to2permille', 'doe_10x10x10']
   character(len=*), parameter :: bounds(5) = [character(len=13) :: 'ellipsoidal', &
      'parabolic', 'weighted', 'weighted-slip', 'clipped']
   character(len=*), parameter :: spin_models(4) = [character(len=9) :: 'additive', 'uniform', &
      'scaled', 'geometric']
   character(len=*), parameter :: flexibilities(2) = [character(len=12) :: 'longitudinal', &
      'spin']
   character(len=*), parameter :: reductions(2) = [character(len=11) :: 'local-hertz', &
      'constant']
   !> Quantiles written for the cumulative distributions (0, 0.01, ..., 1).
   integer, parameter :: n_quantiles = 101

   !> The settings recommended as defaults (doc/validation.md): every run not varying a setting
   !> uses these.
   type :: recommended_type
      character(len=:), allocatable :: bound, spin_model, spin_flexibility, reduction
      integer :: n_strips = 100, n_elements = 50
   end type recommended_type

   !> f_x, f_y (on the rail) of one set of cases.
   type :: set_results_type
      real(wp), allocatable :: fx(:), fy(:)
   end type set_results_type

   !> One configuration's results on every set, with its description.
   type :: run_type
      !> CSV text cells: method, normal, bound, spin_model, spin_flexibility.
      character(len=24) :: text(5) = ''
      !> Column label in the sweep and CDF files.
      character(len=:), allocatable :: label
      type(set_results_type) :: set(n_sets)
      !> Adhesion fraction at the headline case (−1 when unknown).
      real(wp) :: adhesion = -1.0_wp
   end type run_type

   !> Everything read from the reference folder.
   type :: reference_type
      !> Exact non-Hertzian results (README §2 "exact_nonhertz"), and the exact Hertzian ones
      !> (headline and sweeps only).
      type(case_set_type) :: sets(n_sets), hertz_sets(n_sets - 1)
      !> CONTACT's FASTSIM on the non-Hertzian patch and on the Hertz ellipse.
      type(run_type) :: fastsim_nonhertz, fastsim_hertz
      !> Adhesion fraction of the exact headline solution.
      real(wp) :: adhesion = 0.0_wp
      !> CONTACT's local curvatures at the geometric point (1/mm) and its y (mm).
      real(wp) :: curv_a = 0.0_wp, curv_b = 0.0_wp, y_geo = 0.0_wp
   end type reference_type

contains

   !> The whole tangential validation; writes the CSV files into out_dir and a summary to stdout.
   subroutine run_tangential(ref_dir, out_dir, geometry, material, rec, error)
      !> ../shared/reference/ty0_literal/ (with '/').
      character(len=*), intent(in) :: ref_dir
      !> doc/validation/ (with '/').
      character(len=*), intent(in) :: out_dir
      !> Our geometry of the ty0 patch.
      type(patch_geometry_type), intent(in) :: geometry
      !> G, ν, μ of the reference.
      type(material_type), intent(in) :: material
      !> The recommended settings.
      type(recommended_type), intent(in) :: rec
      !> Set on any failure.
      type(error_type), allocatable, intent(out) :: error
      type(reference_type) :: ref
      type(normal_patch_type) :: patches(2), ellipse, exact_pressure
      type(run_type), allocatable :: selected(:)
      integer :: ir

      call read_reference(ref_dir, ref, error)
      if (allocated(error)) return
      do ir = 1, 2
         call solve_normal(geometry, material, 'semi-hertz', reductions(ir), rec%n_strips, &
            64700.0_wp, patches(ir), error)
         if (allocated(error)) return
      end do
      call solve_normal(geometry, material, 'hertz', 'local-hertz', rec%n_strips, 64700.0_wp, &
         ellipse, error)
      if (allocated(error)) return
      call reference_pressure_patch(ref_dir//'grid_module3_exact_nonhertz.csv', ref%y_geo, &
         patches(1), exact_pressure, error)
      if (allocated(error)) return

      call all_variants(out_dir//'errors.csv', patches, ellipse, exact_pressure, material, &
         ref, rec, selected, error)
      if (allocated(error)) return
      call print_recommended(ref, selected, rec)
      call write_sweeps(out_dir, ref, selected, error)
      if (allocated(error)) return
      call write_cdf(out_dir//'doe_cdf.csv', ref, selected, error)
      if (allocated(error)) return
      call discretisation_study(out_dir//'discretisation.csv', geometry, material, ref, rec, &
         error)
      if (allocated(error)) return
      call hertz_check(out_dir//'hertz_check.csv', material, ref, rec, error)
      if (allocated(error)) return
      call write_fields(out_dir//'fields_headline.csv', geometry, material, ref, rec, error)
      if (allocated(error)) return
      call saturation(out_dir//'saturation.csv', ref_dir, patches, ellipse, material, ref, &
         rec, error)
   end subroutine run_tangential

   ! ------------------------------------------------------------------------------ reference

   !> Read the sets, CONTACT's FASTSIM baselines and the headline values.
   subroutine read_reference(ref_dir, ref, error)
      character(len=*), intent(in) :: ref_dir
      type(reference_type), intent(out) :: ref
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: summary
      integer :: k
      real(wp) :: nux, nuy, phi

      call read_csv(ref_dir//'summary.csv', summary, error)
      if (allocated(error)) return
      call summary_value(summary, 'y_geo', ref%y_geo, error)
      if (allocated(error)) return
      call summary_value(summary, 'A1_local', ref%curv_a, error)
      if (allocated(error)) return
      call summary_value(summary, 'B1_local', ref%curv_b, error)
      if (allocated(error)) return
      call summary_value(summary, 'nux_geo', nux, error)
      if (allocated(error)) return
      call summary_value(summary, 'nuy_geo', nuy, error)
      if (allocated(error)) return
      call summary_value(summary, 'phi_geo', phi, error)
      if (allocated(error)) return

      call headline_set(ref_dir//'../headline_summary.csv', 'module3_exact_nonhertz', nux, nuy, &
         phi, ref%sets(i_headline), error, adhesion=ref%adhesion)
      if (allocated(error)) return
      call headline_set(ref_dir//'../headline_summary.csv', 'module3_exact_hertz', nux, nuy, &
         phi, ref%hertz_sets(i_headline), error)
      if (allocated(error)) return
      do k = 2, n_sets
         call read_case_set(ref_dir//trim(set_names(k))//'_exact_nonhertz.csv', &
            trim(set_names(k)), ref%sets(k), error)
         if (allocated(error)) return
         if (k < i_doe) then
            call read_case_set(ref_dir//trim(set_names(k))//'_exact_hertz.csv', &
               trim(set_names(k)), ref%hertz_sets(k), error)
            if (allocated(error)) return
         end if
      end do
      call contact_run(ref_dir, 'fastsim_nonhertz', ref%fastsim_nonhertz, error)
      if (allocated(error)) return
      call contact_run(ref_dir, 'fastsim_hertz', ref%fastsim_hertz, error)
   end subroutine read_reference

   !> A one-case set: the headline creepages with CONTACT's integrated forces of one method row
   !> of headline_summary.csv.
   subroutine headline_set(path, method, nux, nuy, phi, set, error, adhesion)
      character(len=*), intent(in) :: path, method
      real(wp), intent(in) :: nux, nuy, phi
      type(case_set_type), intent(out) :: set
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(out), optional :: adhesion
      type(csv_table_type) :: table
      real(wp), allocatable :: fx(:), fy(:), ncon(:), nadh(:)
      integer :: row

      call read_csv(path, table, error)
      if (allocated(error)) return
      row = findloc(table%cells(:, column_index(table, 'method')), method, dim=1)
      if (row == 0) then
         call fatal_error(error, path//': no row with method "'//method//'"', stat_invalid_input)
         return
      end if
      call column(table, 'fx', fx, error)
      if (allocated(error)) return
      call column(table, 'fy', fy, error)
      if (allocated(error)) return
      set%name = 'headline'
      set%nux = [nux]
      set%nuy = [nuy]
      set%phi = [phi]
      set%fx = [fx(row)]
      set%fy = [fy(row)]
      if (present(adhesion)) then
         call column(table, 'ncon', ncon, error)
         if (allocated(error)) return
         call column(table, 'nadh', nadh, error)
         if (allocated(error)) return
         adhesion = nadh(row)/ncon(row)
      end if
   end subroutine headline_set

   !> CONTACT's own results for one method (its files hold f_x, f_y on the rail already).
   subroutine contact_run(ref_dir, method, run, error)
      character(len=*), intent(in) :: ref_dir, method
      type(run_type), intent(out) :: run
      type(error_type), allocatable, intent(out) :: error
      type(case_set_type) :: set
      integer :: k

      run%text = [character(len=24) :: 'contact-'//method, '-', '-', '-', '-']
      run%label = 'contact_'//method
      call headline_set(ref_dir//'../headline_summary.csv', 'module3_'//method, 0.0_wp, 0.0_wp, &
         0.0_wp, set, error)
      if (allocated(error)) return
      run%set(i_headline)%fx = set%fx
      run%set(i_headline)%fy = set%fy
      do k = 2, n_sets
         call read_case_set(ref_dir//trim(set_names(k))//'_'//method//'.csv', &
            trim(set_names(k)), set, error)
         if (allocated(error)) return
         run%set(k)%fx = set%fx
         run%set(k)%fy = set%fy
      end do
   end subroutine contact_run

   ! ------------------------------------------------------------------------------ variants

   !> Options from the names (all valid by construction). §2–5 study the march itself (issues 5
   !> and 7), so the exact-ellipse correction is off here; §6.4 compares it.
   function options_of(bound, spin_model, flexibility, n_elements, method) result(options)
      character(len=*), intent(in) :: bound, spin_model, flexibility
      integer, intent(in) :: n_elements, method
      type(tangential_options_type) :: options
      type(error_type), allocatable :: error
      call parse_bound(bound, options%bound, error)
      call parse_spin_model(spin_model, options%spin_model, error)
      call parse_spin_flexibility(flexibility, options%spin_flexibility, error)
      options%n_elements = n_elements
      options%method = method
      options%correction = correction_none
      options%fields = .false.
   end function options_of

   !> Solve every set with one configuration.
   subroutine solve_run(patch, material, options, ref, run, error)
      type(normal_patch_type), intent(in) :: patch
      type(material_type), intent(in) :: material
      type(tangential_options_type), intent(in) :: options
      type(reference_type), intent(in) :: ref
      type(run_type), intent(inout) :: run
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: adhesion(:)
      integer :: k

      call solve_set(patch, material, options, ref%sets(i_headline), run%set(i_headline)%fx, &
         run%set(i_headline)%fy, error, adhesion=adhesion)
      if (allocated(error)) return
      run%adhesion = adhesion(1)
      do k = 2, n_sets
         call solve_set(patch, material, options, ref%sets(k), run%set(k)%fx, run%set(k)%fy, &
            error)
         if (allocated(error)) return
      end do
   end subroutine solve_run

   !> Every configuration against the exact theory, one row each in errors.csv; the runs with the
   !> recommended normal reduction and spin flexibility (all bounds × spin models), classical
   !> FASTSIM and CONTACT's FASTSIM are returned for the sweep and CDF files.
   subroutine all_variants(path, patches, ellipse, exact_pressure, material, ref, rec, &
      selected, error)
      character(len=*), intent(in) :: path
      type(normal_patch_type), intent(in) :: patches(2), ellipse, exact_pressure
      type(material_type), intent(in) :: material
      type(reference_type), intent(in) :: ref
      type(recommended_type), intent(in) :: rec
      type(run_type), allocatable, intent(out) :: selected(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      type(run_type) :: run
      integer :: ir, ifl, is, ib

      allocate (selected(0))
      call out%open(path, 'method,normal,bound,spin_model,spin_flexibility,'//metrics_header(), &
         error)
      if (allocated(error)) return
      do ir = 1, 2
         do ifl = 1, 2
            do is = 1, 4
               do ib = 1, 5
                  run%text = [character(len=24) :: 'fastsim-sh', reductions(ir), bounds(ib), &
                     spin_models(is), flexibilities(ifl)]
                  run%label = trim(bounds(ib))//'_'//trim(spin_models(is))
                  call solve_run(patches(ir), material, options_of(bounds(ib), spin_models(is), &
                     flexibilities(ifl), rec%n_elements, method_fastsim_sh), ref, run, error)
                  if (allocated(error)) return
                  call write_metrics(out, run, ref%sets)
                  if (reductions(ir) == rec%reduction .and. flexibilities(ifl) == &
                     rec%spin_flexibility) selected = [selected, run]
               end do
            end do
         end do
      end do
      ! FASTSIM_SH on CONTACT's exact pressure (uniform spin: CONTACT's rigid slip).
      do ifl = 1, 2
         do ib = 1, 5
            run%text = [character(len=24) :: 'fastsim-sh', 'contact-pressure', bounds(ib), &
               'uniform', flexibilities(ifl)]
            run%label = trim(bounds(ib))//'_contact-pressure'
            call solve_run(exact_pressure, material, options_of(bounds(ib), 'uniform', &
               flexibilities(ifl), rec%n_elements, method_fastsim_sh), ref, run, error)
            if (allocated(error)) return
            call write_metrics(out, run, ref%sets)
         end do
      end do
      ! Classical FASTSIM on the Hertz ellipse of our reference point (origin at its centre).
      do ib = 1, 5
         run%text = [character(len=24) :: 'fastsim', 'hertz', bounds(ib), '-', '-']
         run%label = 'fastsim_'//trim(bounds(ib))
         call solve_run(ellipse, material, options_of(bounds(ib), 'uniform', 'spin', &
            rec%n_elements, method_fastsim), ref, run, error)
         if (allocated(error)) return
         call write_metrics(out, run, ref%sets)
         selected = [selected, run]
      end do
      call write_metrics(out, ref%fastsim_nonhertz, ref%sets)
      call write_metrics(out, ref%fastsim_hertz, ref%sets)
      call write_metrics(out, exact_run(ref), ref%sets)
      selected = [selected, ref%fastsim_nonhertz, ref%fastsim_hertz]
      call out%close()
   end subroutine all_variants

   !> The exact solution as a run (zero errors; its headline values and adhesion fraction).
   pure function exact_run(ref) result(run)
      type(reference_type), intent(in) :: ref
      type(run_type) :: run
      integer :: k
      run%text = [character(len=24) :: 'contact-exact', '-', '-', '-', '-']
      run%label = 'contact_exact'
      do k = 1, n_sets
         run%set(k)%fx = ref%sets(k)%fx
         run%set(k)%fy = ref%sets(k)%fy
      end do
      run%adhesion = ref%adhesion
   end function exact_run

   !> Column names of [[write_metrics]].
   pure function metrics_header() result(header)
      character(len=:), allocatable :: header
      integer :: k
      header = 'headline_fx,headline_fy,headline_dfx,headline_dfy,headline_adhesion'
      do k = 2, i_doe - 1
         header = header//','//trim(set_names(k))//'_max_dfx,'//trim(set_names(k))//'_max_dfy'
      end do
      header = header//',doe_max_dfx,doe_max_dfy,doe_p80_dfx,doe_p80_dfy,doe_mean_dfx,'// &
         'doe_mean_dfy,doe_max_df'
   end function metrics_header

   !> One row of errors against `sets`: headline values and errors, the largest error of each
   !> sweep, the DOE statistics (when `sets` has a DOE).
   subroutine write_metrics(out, run, sets)
      type(csv_writer_type), intent(in) :: out
      type(run_type), intent(in) :: run
      type(case_set_type), intent(in) :: sets(:)
      real(wp), allocatable :: v(:)
      type(error_stats_type) :: sx, sy
      integer :: k

      v = [run%set(i_headline)%fx(1), run%set(i_headline)%fy(1), &
         run%set(i_headline)%fx(1) - sets(i_headline)%fx(1), &
         run%set(i_headline)%fy(1) - sets(i_headline)%fy(1), run%adhesion]
      do k = 2, min(size(sets), i_doe - 1)
         v = [v, maxval(abs_errors(run%set(k)%fx, sets(k)%fx)), &
            maxval(abs_errors(run%set(k)%fy, sets(k)%fy))]
      end do
      if (size(sets) >= i_doe) then
         sx = error_stats(abs_errors(run%set(i_doe)%fx, sets(i_doe)%fx))
         sy = error_stats(abs_errors(run%set(i_doe)%fy, sets(i_doe)%fy))
         v = [v, sx%max, sy%max, sx%p80, sy%p80, sx%mean, sy%mean, max(sx%max, sy%max)]
      end if
      call out%row(v, text=run%text, digits=4)
   end subroutine write_metrics

   !> The headline numbers of the recommended settings on stdout.
   subroutine print_recommended(ref, selected, rec)
      type(reference_type), intent(in) :: ref
      type(run_type), intent(in) :: selected(:)
      type(recommended_type), intent(in) :: rec
      type(error_stats_type) :: sx, sy
      integer :: r

      do r = 1, size(selected)
         if (selected(r)%label /= rec%bound//'_'//rec%spin_model) cycle
         sx = error_stats(abs_errors(selected(r)%set(i_doe)%fx, ref%sets(i_doe)%fx))
         sy = error_stats(abs_errors(selected(r)%set(i_doe)%fy, ref%sets(i_doe)%fy))
         write (output_unit, '(a)') 'recommended settings: bound '//rec%bound//', spin model '// &
            rec%spin_model//', spin flexibility '//rec%spin_flexibility//', reduction '// &
            rec%reduction
         write (output_unit, '(a,2f8.4,a,2f8.4)') '  headline f_x, f_y:', &
            selected(r)%set(i_headline)%fx(1), selected(r)%set(i_headline)%fy(1), &
            '   exact:', ref%sets(i_headline)%fx(1), ref%sets(i_headline)%fy(1)
         write (output_unit, '(a,2f8.4,a,2f8.4)') '  DOE 10^3 max |df_x|, |df_y|:', sx%max, &
            sy%max, '   P80:', sx%p80, sy%p80
      end do
   end subroutine print_recommended

   ! ------------------------------------------------------------------------------ sweeps, CDF

   !> One file per sweep: creepages, the exact f_x, f_y, then f_x, f_y of every selected run.
   subroutine write_sweeps(out_dir, ref, selected, error)
      character(len=*), intent(in) :: out_dir
      type(reference_type), intent(in) :: ref
      type(run_type), intent(in) :: selected(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      character(len=:), allocatable :: header
      real(wp), allocatable :: v(:)
      integer :: k, i, r

      header = 'nux,nuy,phi_1_per_m,fx_exact,fy_exact'
      do r = 1, size(selected)
         header = header//',fx_'//selected(r)%label//',fy_'//selected(r)%label
      end do
      do k = 2, i_doe - 1
         call out%open(out_dir//trim(set_names(k))//'.csv', header, error)
         if (allocated(error)) return
         do i = 1, size(ref%sets(k)%fx)
            v = [ref%sets(k)%nux(i), ref%sets(k)%nuy(i), 1.0e3_wp*ref%sets(k)%phi(i), &
               ref%sets(k)%fx(i), ref%sets(k)%fy(i)]
            do r = 1, size(selected)
               v = [v, selected(r)%set(k)%fx(i), selected(r)%set(k)%fy(i)]
            end do
            call out%row(v, digits=5)
         end do
         call out%close()
      end do
   end subroutine write_sweeps

   !> The cumulative distributions of |Δf_x|, |Δf_y| over the DOE: the nearest-rank quantile at
   !> q = 0, 0.01, ..., 1 for every selected run.
   subroutine write_cdf(path, ref, selected, error)
      character(len=*), intent(in) :: path
      type(reference_type), intent(in) :: ref
      type(run_type), intent(in) :: selected(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      character(len=:), allocatable :: header
      real(wp), allocatable :: ex(:, :), ey(:, :), v(:)
      integer :: r, iq, n
      real(wp) :: q

      n = size(ref%sets(i_doe)%fx)
      allocate (ex(n, size(selected)), ey(n, size(selected)))
      header = 'q'
      do r = 1, size(selected)
         header = header//',dfx_'//selected(r)%label//',dfy_'//selected(r)%label
         ex(:, r) = abs_errors(selected(r)%set(i_doe)%fx, ref%sets(i_doe)%fx)
         ey(:, r) = abs_errors(selected(r)%set(i_doe)%fy, ref%sets(i_doe)%fy)
         call sort_ascending(ex(:, r))
         call sort_ascending(ey(:, r))
      end do
      call out%open(path, header, error)
      if (allocated(error)) return
      do iq = 0, n_quantiles - 1
         q = real(iq, wp)/real(n_quantiles - 1, wp)
         v = [q]
         do r = 1, size(selected)
            v = [v, nearest_rank(ex(:, r), q), nearest_rank(ey(:, r), q)]
         end do
         call out%row(v, digits=4)
      end do
      call out%close()
   end subroutine write_cdf

   ! ------------------------------------------------------------------------------ studies

   !> The recommended settings at n_strips × n_elements: DOE statistics, headline forces and the
   !> time per tangential solve (release build, indicative: the machine is shared).
   subroutine discretisation_study(path, geometry, material, ref, rec, error)
      character(len=*), intent(in) :: path
      type(patch_geometry_type), intent(in) :: geometry
      type(material_type), intent(in) :: material
      type(reference_type), intent(in) :: ref
      type(recommended_type), intent(in) :: rec
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: strips(5) = [25, 50, 100, 200, 400]
      integer, parameter :: elements(6) = [10, 25, 50, 100, 200, 400]
      type(csv_writer_type) :: out
      type(normal_patch_type) :: patch
      type(run_type) :: run
      type(error_stats_type) :: sx, sy
      integer :: i, j
      integer(int64) :: t0, t1, rate

      call out%open(path, 'n_strips,n_elements,headline_fx,headline_fy,doe_max_dfx,'// &
         'doe_max_dfy,doe_p80_dfx,doe_p80_dfy,sweep_max_df,us_per_solve', error)
      if (allocated(error)) return
      do i = 1, size(strips)
         call solve_normal(geometry, material, 'semi-hertz', rec%reduction, strips(i), &
            64700.0_wp, patch, error)
         if (allocated(error)) return
         do j = 1, size(elements)
            call system_clock(t0, rate)
            call solve_run(patch, material, options_of(rec%bound, rec%spin_model, &
               rec%spin_flexibility, elements(j), method_fastsim_sh), ref, run, error)
            call system_clock(t1)
            if (allocated(error)) return
            sx = error_stats(abs_errors(run%set(i_doe)%fx, ref%sets(i_doe)%fx))
            sy = error_stats(abs_errors(run%set(i_doe)%fy, ref%sets(i_doe)%fy))
            call out%row([real(strips(i), wp), real(elements(j), wp), run%set(1)%fx(1), &
               run%set(1)%fy(1), sx%max, sy%max, sx%p80, sy%p80, sweep_max(run, ref), &
               1.0e6_wp*real(t1 - t0, wp)/real(rate, wp)/real(total_cases(ref), wp)], digits=4)
         end do
      end do
      call out%close()
   end subroutine discretisation_study

   !> Largest |Δf| over the three sweeps.
   pure real(wp) function sweep_max(run, ref)
      type(run_type), intent(in) :: run
      type(reference_type), intent(in) :: ref
      integer :: k
      sweep_max = 0.0_wp
      do k = 2, i_doe - 1
         sweep_max = max(sweep_max, maxval(abs_errors(run%set(k)%fx, ref%sets(k)%fx)), &
            maxval(abs_errors(run%set(k)%fy, ref%sets(k)%fy)))
      end do
   end function sweep_max

   !> Cases in all sets.
   pure integer function total_cases(ref)
      type(reference_type), intent(in) :: ref
      integer :: k
      total_cases = 0
      do k = 1, n_sets
         total_cases = total_cases + size(ref%sets(k)%fx)
      end do
   end function total_cases

   !> The tangential algorithms alone, on CONTACT's Hertz ellipse (curvatures A1_local, B1_local,
   !> 64.7 kN), against CONTACT's exact solution on that ellipse (`exact_hertz`, spin about the
   !> ellipse centre) and against CONTACT's FASTSIM on it (`fastsim_hertz`): classical FASTSIM
   !> and FASTSIM_SH on the ellipse's strips, for every bound and spin flexibility.
   subroutine hertz_check(path, material, ref, rec, error)
      character(len=*), intent(in) :: path
      type(material_type), intent(in) :: material
      type(reference_type), intent(in) :: ref
      type(recommended_type), intent(in) :: rec
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geometry
      type(normal_patch_type) :: ellipse
      type(reference_type) :: hertz_ref
      type(csv_writer_type) :: out
      type(run_type) :: run
      integer :: ib, im

      call quadratic_geometry(ref%curv_a, ref%curv_b, 460.0_wp, geometry)
      call solve_normal(geometry, material, 'hertz', 'local-hertz', rec%n_strips, 64700.0_wp, &
         ellipse, error)
      if (allocated(error)) return
      ! The Hertzian cases: headline and sweeps (CONTACT ran no DOE on the ellipse).
      hertz_ref%sets(1:n_sets - 1) = ref%hertz_sets
      hertz_ref%sets(i_doe) = ref%sets(i_doe)
      call out%open(path, 'method,normal,bound,spin_model,spin_flexibility,reference,'// &
         'headline_fx,headline_fy,headline_dfx,headline_dfy,headline_adhesion,'// &
         'sweep_spin_0to2_max_dfx,sweep_spin_0to2_max_dfy,sweep_spin_0to5_max_dfx,'// &
         'sweep_spin_0to5_max_dfy,sweep_creep_0to2permille_max_dfx,'// &
         'sweep_creep_0to2permille_max_dfy', error)
      if (allocated(error)) return
      do im = 1, 3
         do ib = 1, 5
            if (im == 3) then
               run%text = [character(len=24) :: 'fastsim', 'contact-ellipse', bounds(ib), &
                  'uniform', '-']
               call solve_run(ellipse, material, options_of(bounds(ib), 'uniform', 'spin', &
                  rec%n_elements, method_fastsim), hertz_ref, run, error)
            else
               run%text = [character(len=24) :: 'fastsim-sh', 'contact-ellipse', bounds(ib), &
                  'uniform', flexibilities(im)]
               call solve_run(ellipse, material, options_of(bounds(ib), 'uniform', &
                  flexibilities(im), rec%n_elements, method_fastsim_sh), hertz_ref, run, error)
            end if
            if (allocated(error)) return
            call hertz_rows(out, run, ref)
         end do
      end do
      call hertz_rows(out, ref%fastsim_hertz, ref)
      call out%close()
   end subroutine hertz_check

   !> Two rows of the Hertzian check: against exact_hertz and against CONTACT's fastsim_hertz.
   subroutine hertz_rows(out, run, ref)
      type(csv_writer_type), intent(in) :: out
      type(run_type), intent(in) :: run
      type(reference_type), intent(in) :: ref
      type(case_set_type) :: fastsim(n_sets - 1)
      integer :: k

      call write_hertz_row(out, run, ref%hertz_sets, 'contact-exact-hertz')
      do k = 1, n_sets - 1
         fastsim(k) = ref%hertz_sets(k)
         fastsim(k)%fx = ref%fastsim_hertz%set(k)%fx
         fastsim(k)%fy = ref%fastsim_hertz%set(k)%fy
      end do
      call write_hertz_row(out, run, fastsim, 'contact-fastsim-hertz')
   end subroutine hertz_rows

   !> One row of [[hertz_check]].
   subroutine write_hertz_row(out, run, sets, reference)
      type(csv_writer_type), intent(in) :: out
      type(run_type), intent(in) :: run
      type(case_set_type), intent(in) :: sets(:)
      character(len=*), intent(in) :: reference
      real(wp), allocatable :: v(:)
      character(len=24) :: text(6)
      integer :: k

      v = [run%set(1)%fx(1), run%set(1)%fy(1), run%set(1)%fx(1) - sets(1)%fx(1), &
         run%set(1)%fy(1) - sets(1)%fy(1), run%adhesion]
      do k = 2, size(sets)
         v = [v, maxval(abs_errors(run%set(k)%fx, sets(k)%fx)), &
            maxval(abs_errors(run%set(k)%fy, sets(k)%fy))]
      end do
      text(1:5) = run%text
      text(6) = reference
      call out%row(v, text=text, digits=4)
   end subroutine write_hertz_row

   !> Per-element tractions on the rail (−p on the wheel) of the headline case for every bound
   !> with the recommended spin model and flexibility, on a coarser grid for the figures (40 strips
   !> × 32 elements); columns per bound: px, py (MPa), state (0 exterior, 1 adhesion, 2 slip).
   subroutine write_fields(path, geometry, material, ref, rec, error)
      character(len=*), intent(in) :: path
      type(patch_geometry_type), intent(in) :: geometry
      type(material_type), intent(in) :: material
      type(reference_type), intent(in) :: ref
      type(recommended_type), intent(in) :: rec
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n_strips = 40, n_elements = 32
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result(5)
      type(csv_writer_type) :: out
      character(len=:), allocatable :: header
      real(wp), allocatable :: v(:)
      integer :: ib, i, j

      call solve_normal(geometry, material, 'semi-hertz', rec%reduction, n_strips, 64700.0_wp, &
         patch, error)
      if (allocated(error)) return
      header = 'strip,element,y_contact_mm,x_mm,pn_MPa'
      do ib = 1, 5
         options = options_of(bounds(ib), rec%spin_model, rec%spin_flexibility, n_elements, &
            method_fastsim_sh)
         options%fields = .true.
         call prepare_fastsim_sh(ws, patch, material, options, error)
         if (allocated(error)) return
         associate (s => ref%sets(i_headline))
            call solve_prepared(ws, creepage_type(-s%nux(1), -s%nuy(1), -s%phi(1)), &
               result(ib), error)
         end associate
         if (allocated(error)) return
         header = header//',px_'//trim(bounds(ib))//',py_'//trim(bounds(ib))//',state_'// &
            trim(bounds(ib))
      end do
      call out%open(path, header, error)
      if (allocated(error)) return
      do i = 1, result(1)%ny
         if (.not. (patch%a(i) > 0.0_wp)) cycle
         do j = 1, result(1)%nx
            v = [real(i, wp), real(j, wp), result(1)%y(i) + ref%y_geo, result(1)%x(j, i), &
               result(1)%pn(j, i)]
            do ib = 1, 5
               v = [v, -result(ib)%px(j, i), -result(ib)%py(j, i), &
                  real(result(ib)%state(j, i), wp)]
            end do
            call out%row(v, digits=3)
         end do
      end do
      call out%close()
   end subroutine write_fields

   !> Full-slip limit of pure spin, which depends on the normal pressure only: from CONTACT's
   !> exact pressure, from each of our normal solutions, and the solvers' values at φ = 5 1/m.
   subroutine saturation(path, ref_dir, patches, ellipse, material, ref, rec, error)
      character(len=*), intent(in) :: path, ref_dir
      type(normal_patch_type), intent(in) :: patches(2), ellipse
      type(material_type), intent(in) :: material
      type(reference_type), intent(in) :: ref
      type(recommended_type), intent(in) :: rec
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: grid
      type(csv_writer_type) :: out
      type(run_type) :: run
      real(wp), allocatable :: x(:), y(:), pn(:)
      real(wp) :: fx, fy
      integer :: ir, last

      call read_csv(ref_dir//'grid_module3_exact_nonhertz.csv', grid, error)
      if (allocated(error)) return
      call column(grid, 'x_mm', x, error)
      if (allocated(error)) return
      call column(grid, 'y_mm', y, error)
      if (allocated(error)) return
      call column(grid, 'pn_MPa', pn, error)
      if (allocated(error)) return
      last = size(ref%sets(3)%fx)
      call out%open(path, 'pressure,fx_saturated,fy_saturated,fx_at_phi5,fy_at_phi5', error)
      if (allocated(error)) return
      call spin_saturation(pn, x, y, ref%y_geo, fx, fy)
      call out%row([fx, fy, ref%sets(3)%fx(last), ref%sets(3)%fy(last)], text=['contact-exact'], &
         digits=4)
      do ir = 1, 2
         call patch_spin_saturation(patches(ir), 200, fx, fy)
         call solve_run(patches(ir), material, options_of(rec%bound, rec%spin_model, &
            rec%spin_flexibility, rec%n_elements, method_fastsim_sh), ref, run, error)
         if (allocated(error)) return
         call out%row([fx, fy, run%set(3)%fx(last), run%set(3)%fy(last)], &
            text=[character(len=24) :: 'semi-hertz_'//reductions(ir)], digits=4)
      end do
      call patch_spin_saturation(ellipse, 200, fx, fy)
      call solve_run(ellipse, material, options_of(rec%bound, 'uniform', 'spin', &
         rec%n_elements, method_fastsim), ref, run, error)
      if (allocated(error)) return
      call out%row([fx, fy, run%set(3)%fx(last), run%set(3)%fy(last)], text=['hertz-ellipse'], &
         digits=4)
      call out%close()
   end subroutine saturation

end module validate_report
