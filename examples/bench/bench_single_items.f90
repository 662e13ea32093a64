!> The benchmark's sections on the single case (issue 9): geometry and normal contact, the
!> tangential solvers FASTSIM_SH and FASTSIM at every size and bound, and the full case on a
!> reused geometry.
module bench_single_items
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: error_type, normal_patch_type, tangential_options_type, &
      prepare_fastsim_sh, bound_name
   use shcontact_tangential_options, only: bound_weighted
   use shcontact_core_strings, only: str_int
   use bench_timing, only: timing_type, time_kernel
   use bench_kernels, only: geometry_kernel, normal_prepare_kernel, normal_load_kernel, &
      sh_prepare_kernel, fastsim_prepare_kernel, solve_kernel, full_case_kernel
   use bench_config, only: bench_config_type, sizes, n_bounds
   use bench_case, only: bench_case_type
   use bench_results, only: summary_type, force_record_type
   use bench_report, only: section, report, triple, stop_on, fail
   implicit none
   private

   public :: geometry_section, tangential_section, full_case_section

contains

   !> Contact search with the strip tables, the normal preparation and solve_load per size.
   subroutine geometry_section(config, bench)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(in) :: bench
      type(geometry_kernel) :: geo
      type(normal_prepare_kernel) :: prep
      type(normal_load_kernel) :: load
      type(timing_type) :: t
      integer :: i

      call section('geometry and normal contact')
      geo%profiles = bench%setup%prepared
      geo%position = bench%position
      t = time_kernel(geo, config%runs, config%batch_time)
      call report(geo, t, 'geometry: contact search + strip tables, one wheel position')
      write (output_unit, '(a,i0,a,i0,a)') '      (', size(bench%patches), ' patch(es), ', &
         bench%patches(1)%size(), ' table points)'
      prep%geometry = bench%patches(1)
      prep%options = bench%normal_options
      prep%material = bench%material
      t = time_kernel(prep, config%runs, config%batch_time)
      call report(prep, t, 'normal: prepare_normal_contact (once per geometry)')
      do i = 1, size(sizes)
         load%contact = bench%normal_contact(sizes(i))
         load%load = bench%load
         t = time_kernel(load, config%runs, config%batch_time)
         call report(load, t, 'normal: solve_load, '//str_int(sizes(i))//' strips')
      end do
   end subroutine geometry_section

   !> FASTSIM_SH and classical FASTSIM, preparation and solve, at every size and bound, with
   !> their ratios; the forces go to the record.
   subroutine tangential_section(config, bench, summary, record)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(in) :: bench
      !> The figures of the targets.
      type(summary_type), intent(inout) :: summary
      !> The forces of the checked cases.
      type(force_record_type), intent(inout) :: record
      type(sh_prepare_kernel) :: sh_prep
      type(fastsim_prepare_kernel) :: fs_prep
      type(solve_kernel) :: sh_solve, fs_solve
      type(timing_type) :: t_shp, t_sh, t_shf, t_fsp, t_fs
      type(normal_patch_type) :: patch, hertz
      type(tangential_options_type) :: options
      type(error_type), allocatable :: error
      integer :: i, b

      call section('tangential: FASTSIM_SH and classical FASTSIM, strips x elements, '// &
         'microseconds')
      write (output_unit, '(a)') '  per call: prepare = workspace from the normal patch or '// &
         'ellipse; solve = one creepage set (forces only); +fields = solve with element fields'
      write (output_unit, '(a)') '  median [min, max]                   SH prepare'// &
         '             SH solve             SH +fields           FASTSIM prepare'// &
         '        FASTSIM solve        SH/FS solve  SH/FS prep+solve'
      do i = 1, size(sizes)
         patch = bench%normal_solution(sizes(i), .false.)
         hertz = bench%normal_solution(sizes(i), .true.)
         do b = 1, n_bounds
            options = bench%tangential_options
            options%bound = b
            options%n_elements = sizes(i)
            options%fields = .false.
            sh_prep%patch = patch
            sh_prep%material = bench%material
            sh_prep%options = options
            t_shp = time_kernel(sh_prep, config%runs, config%batch_time)
            sh_solve%ws = sh_prep%ws
            sh_solve%creepage = bench%headline
            t_sh = time_kernel(sh_solve, config%runs, config%batch_time)
            call record%keep(sh_solve%result%fx, sh_solve%result%fy, sh_solve%result%mz)
            options%fields = .true.
            call prepare_fastsim_sh(sh_solve%ws, patch, bench%material, options, error)
            call stop_on(error, 'prepare_fastsim_sh')
            t_shf = time_kernel(sh_solve, config%runs, config%batch_time)

            options%fields = .false.
            fs_prep%semi_a = hertz%ellipse_a
            fs_prep%semi_b = hertz%ellipse_b
            fs_prep%load = hertz%load
            fs_prep%y_centre = hertz%ellipse_y_centre
            fs_prep%gamma0 = hertz%gamma0
            fs_prep%n_strips = sizes(i)
            fs_prep%material = bench%material
            fs_prep%options = options
            t_fsp = time_kernel(fs_prep, config%runs, config%batch_time)
            fs_solve%ws = fs_prep%ws
            fs_solve%creepage = bench%headline
            t_fs = time_kernel(fs_solve, config%runs, config%batch_time)
            call record%keep(fs_solve%result%fx, fs_solve%result%fy, fs_solve%result%mz)
            if (sh_prep%failed .or. sh_solve%failed .or. fs_prep%failed .or. fs_solve%failed) &
               call fail('a tangential kernel failed')
            summary%ratio_solve((i - 1)*n_bounds + b) = t_sh%median/t_fs%median
            summary%ratio_prep_solve((i - 1)*n_bounds + b) = &
               (t_shp%median + t_sh%median)/(t_fsp%median + t_fs%median)
            if (sizes(i) == 50) then
               summary%sh50_worst = max(summary%sh50_worst, t_sh%median)
               if (b == bound_weighted) summary%sh50_weighted = t_sh%median
            end if
            write (output_unit, '(2x,i3,a,i3,1x,a13,5(1x,a21),2(f8.2,6x))') sizes(i), ' x', &
               sizes(i), bound_name(b), triple(t_shp), triple(t_sh), triple(t_shf), &
               triple(t_fsp), triple(t_fs), t_sh%median/t_fs%median, &
               (t_shp%median + t_sh%median)/(t_fsp%median + t_fs%median)
         end do
      end do
   end subroutine tangential_section

   !> The full case (normal solve for the load, tangential preparation and solve) on the reused
   !> geometry, FASTSIM_SH against FASTSIM, at 50 and 100 strips, with and without fields.
   subroutine full_case_section(config, bench, summary)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(in) :: bench
      !> The figures of the targets.
      type(summary_type), intent(inout) :: summary
      type(full_case_kernel) :: full
      type(timing_type) :: t(2, 2)
      integer :: i, c

      call section('full case on reused geometry (normal solve for the load + tangential '// &
         'preparation + solve, forces only unless said)')
      write (output_unit, '(a)') '  FASTSIM_SH: semi-Hertz solve_load + prepare_fastsim_sh + '// &
         'solve_prepared; FASTSIM: Hertz solve_load + prepare_fastsim + solve_prepared'
      write (output_unit, '(a,i0,a)') '  the load cycles through ', 16, &
         ' values in [0.9, 1.1] F_n (nothing is cached between loads)'
      do i = 2, 3
         do c = 1, 2
            full%classical = c == 2
            full%n_strips = sizes(i)
            full%contact = bench%normal_contact(sizes(i), hertz=full%classical)
            full%load = bench%load
            full%material = bench%material
            full%options = bench%tangential_options
            full%options%fields = .false.
            full%creepage = bench%headline
            t(c, 1) = time_kernel(full, config%runs, config%batch_time)
            if (c == 1 .and. i == 2) summary%full50 = t(c, 1)%median
            if (c == 1 .and. i == 3) summary%full100 = t(c, 1)%median
            call report(full, t(c, 1), merge('FASTSIM   ', 'FASTSIM_SH', full%classical)// &
               ' full case, '//str_int(sizes(i))//' x '//str_int(full%options%n_elements))
            full%options%fields = .true.
            t(c, 2) = time_kernel(full, config%runs, config%batch_time)
            call report(full, t(c, 2), merge('FASTSIM   ', 'FASTSIM_SH', full%classical)// &
               ' full case, '//str_int(sizes(i))//' x '//str_int(full%options%n_elements)// &
               ', with element fields')
         end do
         write (output_unit, '(2x,a,f5.2,a,f5.2,a)') 'ratio FASTSIM_SH/FASTSIM, full case '// &
            str_int(sizes(i))//' strips: ', t(1, 1)%median/t(2, 1)%median, ' (forces), ', &
            t(1, 2)%median/t(2, 2)%median, ' (with fields)'
      end do
   end subroutine full_case_section

end module bench_single_items
