!> The benchmark's design-of-experiments section: the case file's DOE end to end through the
!> app's sweep driver and as a bare library loop ([[bench_doe]]), then the check that both give
!> the forces of the library's plain pipeline.
module bench_doe_items
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: wp, error_type, patch_geometry_type, normal_contact_type, &
      prepare_normal_contact, solve_load, normal_patch_type, tangential_options_type, &
      march_workspace_type, prepare_fastsim_sh, creepage_type, tangential_patch_type, &
      find_contact_patches, solve_tangential
   use shcontact_batch_sweep, only: sweep_options_type, sweep_outcome_type, run_sweep
   use shcontact_core_strings, only: str_int
   use bench_timing, only: wall_time, median_of
   use bench_doe, only: doe_table_type, solve_doe, reserve_table
   use bench_config, only: bench_config_type
   use bench_case, only: bench_case_type
   use bench_results, only: summary_type, force_record_type
   use bench_report, only: section, stop_on, fail, verdict
   implicit none
   private

   public :: doe_section

contains

   !> The DOE of the case file end to end through the app's sweep driver (geometry, normal
   !> solution, every case, the HDF5 file with its checkpoint blocks, merge), with 1 and 2
   !> threads; and the same cases as a bare library loop on one prepared workspace.
   subroutine doe_section(config, bench, summary, record)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(in) :: bench
      !> The figures of the targets.
      type(summary_type), intent(inout) :: summary
      !> The forces of the checked cases.
      type(force_record_type), intent(inout) :: record
      type(creepage_type), allocatable :: creepages(:)
      type(doe_table_type) :: table
      type(sweep_outcome_type) :: outcome
      type(march_workspace_type) :: ws
      type(normal_patch_type) :: patch
      type(error_type), allocatable :: error
      real(wp), allocatable :: t_app(:, :), t_loop(:, :), c_app(:, :), c_loop(:, :)
      real(wp) :: t0, c0, ratio, speedup
      integer :: threads, r, n

      n = bench%case_config%n_cases()
      call section('design of experiments: '//config%case_file//', '//str_int(n)//' cases')
      creepages = bench%creepages()
      call reserve_table(table, n)
      allocate (t_app(config%doe_runs, 2), t_loop(config%doe_runs, 2), &
         c_app(config%doe_runs, 2), c_loop(config%doe_runs, 2))
      patch = bench%normal_solution(bench%normal_options%n_strips, .false.)
      call prepare_fastsim_sh(ws, patch, bench%material, bench%tangential_options, error)
      call stop_on(error, 'DOE: prepare_fastsim_sh')
      write (output_unit, '(a)') '  app: run_sweep (shcontact_batch_sweep) end to end: '// &
         'geometry, normal solution, every case, HDF5 blocks, merged file '//config%output
      write (output_unit, '(a)') '  library loop: solve_prepared on one prepared workspace '// &
         'per thread, forces only, no file'
      write (output_unit, '(a)') '  in turn, run after run: app 1 thread, library 1 thread, '// &
         'app 2 threads, library 2 threads; wall ms median [min, max], CPU us per case'
      do r = 1, config%doe_runs
         do threads = 1, 2
            c0 = cpu_seconds()
            call run_app(bench, threads, outcome, t_app(r, threads))
            c_app(r, threads) = cpu_seconds() - c0
            c0 = cpu_seconds()
            t0 = wall_time()
            call solve_doe(ws, creepages, table, threads)
            t_loop(r, threads) = wall_time() - t0
            c_loop(r, threads) = cpu_seconds() - c0
         end do
      end do
      do threads = 1, 2
         write (output_unit, '(2x,a,i0,a,3(f8.1,a),f6.1,a,3(f8.1,a),f6.1,a)') 'threads ', &
            threads, ': app ', 1.0e3_wp*median_of(t_app(:, threads)), ' ms [', &
            1.0e3_wp*minval(t_app(:, threads)), ', ', 1.0e3_wp*maxval(t_app(:, threads)), &
            '] ', 1.0e6_wp*median_of(c_app(:, threads))/n, ' us CPU; library loop ', &
            1.0e3_wp*median_of(t_loop(:, threads)), ' ms [', &
            1.0e3_wp*minval(t_loop(:, threads)), ', ', 1.0e3_wp*maxval(t_loop(:, threads)), &
            '] ', 1.0e6_wp*median_of(c_loop(:, threads))/n, ' us CPU per case'
      end do
      summary%doe1 = median_of(t_app(:, 1))
      summary%doe2 = median_of(t_app(:, 2))
      ! Issue 27's targets: the app's cost per case against the library loop's, and its scaling.
      ratio = median_of(t_app(:, 1))/median_of(t_loop(:, 1))
      write (output_unit, '(2x,a,f6.2,a,f6.2,a)') 'app / library loop per case, 1 thread: ', &
         ratio, ' wall (CPU ', median_of(c_app(:, 1))/median_of(c_loop(:, 1)), &
         '); target <= 1.3: '//verdict(ratio <= 1.3_wp)
      speedup = median_of(t_app(:, 1))/median_of(t_app(:, 2))
      write (output_unit, '(2x,a,f6.2,a,f6.2,a)') 'speed-up 1 -> 2 threads: app ', speedup, &
         ', library loop ', median_of(t_loop(:, 1))/median_of(t_loop(:, 2)), &
         '; app target >= 1.8: '//verdict(speedup >= 1.8_wp)
      write (output_unit, '(2x,a,i0,a)') '(', config%doe_runs, ' runs each)'
      if (any(table%status /= 0)) call fail('a DOE case failed in the library loop')
      if (size(outcome%failures) > 0) call fail('a DOE case failed in the app')
      call check_doe(bench, creepages, table, outcome)
      call record%keep_array(table%fx)
      call record%keep_array(table%fy)
      call record%keep_array(table%mz)
   end subroutine doe_section

   !> Processor time of the process, all threads (s).
   function cpu_seconds() result(t)
      real(wp) :: t
      call cpu_time(t)
   end function cpu_seconds

   !> One run of the app's sweep driver, timed.
   subroutine run_app(bench, threads, outcome, seconds)
      !> The case.
      type(bench_case_type), intent(in) :: bench
      !> OpenMP threads.
      integer, intent(in) :: threads
      !> The sweep's summaries and failures.
      type(sweep_outcome_type), intent(out) :: outcome
      !> Wall time of the run (s).
      real(wp), intent(out) :: seconds
      type(sweep_options_type) :: options
      type(error_type), allocatable :: error
      real(wp) :: t0

      options%threads = threads
      options%command_line = 'shcontact-bench'
      t0 = wall_time()
      call run_sweep(bench%case_config, options, outcome, error)
      seconds = wall_time() - t0
      call stop_on(error, 'run_sweep')
   end subroutine run_app

   !> The forces of the library loop (2 threads, one reused workspace, no fields) equal, case by
   !> case, those of the app's sweep and those of the library's plain pipeline: the profiles as
   !> read, find_contact_patches with the smoothing, prepare_normal_contact, solve_load, then
   !> solve_tangential per case with a fresh preparation and the element fields on.
   subroutine check_doe(bench, creepages, table, outcome)
      !> The case.
      type(bench_case_type), intent(in) :: bench
      !> The cases.
      type(creepage_type), intent(in) :: creepages(:)
      !> The library loop's results.
      type(doe_table_type), intent(in) :: table
      !> The app's results.
      type(sweep_outcome_type), intent(in) :: outcome
      type(patch_geometry_type), allocatable :: found(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(tangential_options_type) :: options
      type(error_type), allocatable :: error
      real(wp) :: diff_app, diff_pipe, scale
      integer :: k, n_app, n_pipe

      call section('checks')
      call find_contact_patches(bench%setup%wheel, bench%setup%rail, bench%setup%prepared%track, &
         bench%position, bench%setup%prepared%options, found, error)
      call stop_on(error, 'pipeline: find_contact_patches')
      call prepare_normal_contact(contact, found(1), bench%normal_options, bench%material, error)
      call stop_on(error, 'pipeline: prepare_normal_contact')
      call solve_load(contact, bench%load, patch, error)
      call stop_on(error, 'pipeline: solve_load')
      options = bench%tangential_options
      options%fields = .true.
      scale = bench%material%friction*patch%load
      diff_app = 0.0_wp
      diff_pipe = 0.0_wp
      n_app = 0
      n_pipe = 0
      do k = 1, size(creepages)
         call solve_tangential(ws, patch, bench%material, creepages(k), options, result, error)
         call stop_on(error, 'pipeline: solve_tangential')
         diff_pipe = max(diff_pipe, abs(result%fx - table%fx(k))/scale, &
            abs(result%fy - table%fy(k))/scale)
         if (result%fx == table%fx(k) .and. result%fy == table%fy(k) .and. &
            result%mz == table%mz(k)) n_pipe = n_pipe + 1
         associate (s => outcome%summaries(k))
            diff_app = max(diff_app, abs(s%fx - table%fx(k))/scale, &
               abs(s%fy - table%fy(k))/scale)
            if (s%fx == table%fx(k) .and. s%fy == table%fy(k) .and. s%mz == table%mz(k)) &
               n_app = n_app + 1
         end associate
      end do
      write (output_unit, '(2x,a,i0,a,i0,a,es9.2)') 'DOE library loop vs the library pipeline '// &
         '(profiles as read, solve_tangential, fields): ', n_pipe, ' of ', size(creepages), &
         ' cases bitwise equal; max |dF|/(mu Fn) = ', diff_pipe
      write (output_unit, '(2x,a,i0,a,i0,a,es9.2)') 'DOE library loop vs the app (run_sweep '// &
         'summaries): ', n_app, ' of ', size(creepages), &
         ' cases bitwise equal; max |dF|/(mu Fn) = ', diff_app
      if (diff_pipe > 1.0e-12_wp .or. diff_app > 1.0e-12_wp) &
         call fail('the benchmark forces differ from the pipeline''s or the app''s')
   end subroutine check_doe

end module bench_doe_items
