!> shcontact-bench: how fast the contact model runs on this machine (issue 9, doc/performance.md).
!>
!>     fpm run --profile release --example shcontact-bench [-- OPTIONS]
!>
!> Options:
!>     --case FILE            the case and its design of experiments, an app namelist file
!>                            (default examples/doe_8000.nml: the seed's DOE on the default case)
!>     --runs N               timed repetitions per item (default 15); median, min and max
!>     --batch-time S         target length of one timed batch in s (default 0.01)
!>     --doe-runs N           repetitions of each DOE run (default 5)
!>     --quick                --runs 5 --batch-time 0.002 --doe-runs 2 (for slow builds)
!>     --only SECTION         run one section: geometry, tangential, full, doe, moving,
!>                            defaults (new against old defaults; no checks), or scan (every
!>                            0.01 mm position, failed calls; not in the default run)
!>     --output FILE          HDF5 file of the DOE (default build/shcontact_bench_doe.h5)
!>     --save-results FILE    write the forces of the checked cases to a text file
!>     --compare-results FILE compare the forces with a file saved by another build
!>     --alloc-check N        only solve N full cases and N DOE cases, then stop (run it under
!>                            valgrind with N and 2N: the allocation count must not change)
!>
!> The case is the app's (shcontact_io_config): by default the built-in S1002 on UIC60 1:40 at
!> t_y = 4.733 mm, F_n = 64.7 kN, G = 82670 MPa, ν = 0.27, μ = 0.3, 100 strips × 50 elements,
!> weighted bound; the single-case items use its creepages (ν_x = 0.58e-3, ν_y = 0.061e-3,
!> φ = 2.74e-4 rad/mm), the DOE its sweep.
program shcontact_bench
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options, output_unit, &
      error_unit
   use omp_lib, only: omp_get_num_procs, omp_get_max_threads
   use shcontact, only: wp, error_type, material_type, wheelset_position_type, &
      find_contact_patches, patch_geometry_type, normal_options_type, normal_contact_type, &
      prepare_normal_contact, solve_load, normal_patch_type, tangential_options_type, &
      march_workspace_type, prepare_fastsim_sh, creepage_type, tangential_patch_type, &
      solve_tangential, bound_name, parse_bound, parse_spin_model, shcontact_version, &
      contact_solver_type
   use shcontact_normal_options, only: method_hertz, reduction_local_hertz
   use shcontact_tangential_options, only: bound_weighted
   use shcontact_io_config, only: case_config_type, case_point_type, load_config, axis_load
   use shcontact_case_runner, only: run_setup_type, prepare_run
   use shcontact_case_sweep, only: sweep_options_type, sweep_outcome_type, run_sweep
   use bench_timing, only: kernel_type, timing_type, time_kernel, wall_time, median_of
   use bench_kernels, only: geometry_kernel, normal_prepare_kernel, normal_load_kernel, &
      sh_prepare_kernel, fastsim_prepare_kernel, solve_kernel, full_case_kernel
   use bench_doe, only: doe_table_type, solve_doe, reserve_table
   use bench_moving, only: kinematic_kernel, hunting_states, scan_positions
   implicit none

   integer, parameter :: sizes(3) = [25, 50, 100]
   integer, parameter :: n_bounds = 5

   type bench_config_type
      integer :: runs = 15
      integer :: doe_runs = 5
      real(wp) :: batch_time = 0.01_wp
      character(len=:), allocatable :: case_file, output, save_file, compare_file, only
      integer :: alloc_check = 0
   end type bench_config_type

   !> The figures the targets of issue 9 are about (negative: not measured in this run).
   type summary_type
      !> FASTSIM_SH solve at 50 x 50: weighted bound and the slowest bound (s).
      real(wp) :: sh50_weighted = -1.0_wp, sh50_worst = -1.0_wp
      !> FASTSIM_SH/FASTSIM ratios for every size and bound: solve, prepare + solve.
      real(wp) :: ratio_solve(3*n_bounds) = -1.0_wp, ratio_prep_solve(3*n_bounds) = -1.0_wp
      !> Full FASTSIM_SH case at 50 x 50 and 100 x 50, forces only (s).
      real(wp) :: full50 = -1.0_wp, full100 = -1.0_wp
      !> DOE through the app's sweep driver with 1 and 2 threads (s).
      real(wp) :: doe1 = -1.0_wp, doe2 = -1.0_wp
      !> Kinematic call along the hunting trajectory (s), and over the same-position call.
      real(wp) :: moving = -1.0_wp, moving_ratio = -1.0_wp
   end type summary_type

   type(bench_config_type) :: config
   type(summary_type) :: summary
   type(case_config_type) :: case_config
   type(run_setup_type) :: setup
   type(case_point_type) :: point
   type(material_type) :: material
   type(wheelset_position_type) :: position
   type(normal_options_type) :: normal_options
   type(tangential_options_type) :: tangential_options
   type(creepage_type) :: headline
   type(patch_geometry_type), allocatable :: patches(:)
   type(error_type), allocatable :: error
   real(wp), allocatable :: saved(:)
   real(wp) :: case_load, t0, t_setup

   call read_arguments(config)
   call load_config(config%case_file, [character(len=len(config%output) + 12) :: &
      'output%file='//config%output], case_config, error)
   call stop_on(error, config%case_file)
   t0 = wall_time()
   call prepare_run(case_config, setup, error)
   t_setup = wall_time() - t0
   call stop_on(error, 'prepare_run')
   call case_of_run()
   call find_contact_patches(setup%prepared, position, patches, error)
   call stop_on(error, 'find_contact_patches')

   if (config%alloc_check > 0) then
      call allocation_run(config%alloc_check)
      stop
   end if

   call print_header()
   allocate (saved(0))
   if (wanted('geometry')) call bench_geometry_and_normal()
   if (wanted('tangential')) call bench_tangential()
   if (wanted('full')) call bench_full_case()
   if (wanted('doe')) call bench_doe()
   if (wanted('moving')) call bench_moving_wheel()
   if (wanted('defaults')) call bench_defaults()
   if (config%only == 'scan') call bench_scan()
   if (len(config%only) == 0) call check_results()
   call print_summary()
   call print_load('load at the end')

contains

   ! ------------------------------------------------------------------------------------ set-up

   !> Whether a section runs (all of them unless --only names one).
   logical function wanted(name)
      character(len=*), intent(in) :: name
      wanted = len(config%only) == 0 .or. config%only == name
   end function wanted

   subroutine read_arguments(config)
      type(bench_config_type), intent(inout) :: config
      character(len=512) :: arg, val
      integer :: i, n, stat
      logical :: flag

      config%case_file = 'examples/doe_8000.nml'
      config%output = 'build/shcontact_bench_doe.h5'
      config%save_file = ''
      config%compare_file = ''
      config%only = ''
      n = command_argument_count()
      i = 1
      do while (i <= n)
         call get_command_argument(i, arg)
         val = ''
         if (i < n) call get_command_argument(i + 1, val)
         stat = 0
         flag = .false.
         select case (trim(arg))
         case ('--quick')
            config%runs = 5
            config%doe_runs = 2
            config%batch_time = 0.002_wp
            flag = .true.
         case ('--case')
            config%case_file = trim(val)
         case ('--runs')
            read (val, *, iostat=stat) config%runs
            if (stat == 0 .and. config%runs < 1) stat = 1
         case ('--doe-runs')
            read (val, *, iostat=stat) config%doe_runs
            if (stat == 0 .and. config%doe_runs < 1) stat = 1
         case ('--batch-time')
            read (val, *, iostat=stat) config%batch_time
            if (stat == 0 .and. .not. (config%batch_time > 0.0_wp)) stat = 1
         case ('--only')
            config%only = trim(val)
            if (all(config%only /= [character(len=10) :: 'geometry', 'tangential', 'full', &
               'doe', 'moving', 'defaults', 'scan'])) stat = 1
         case ('--output')
            config%output = trim(val)
         case ('--save-results')
            config%save_file = trim(val)
         case ('--compare-results')
            config%compare_file = trim(val)
         case ('--alloc-check')
            read (val, *, iostat=stat) config%alloc_check
            if (stat == 0 .and. config%alloc_check < 1) stat = 1
         case default
            call fail('unknown argument '//trim(arg)//'; see the header of examples/bench/bench.f90')
         end select
         if (.not. flag .and. (stat /= 0 .or. i == n)) &
            call fail('bad or missing value for '//trim(arg))
         i = i + merge(1, 2, flag)
      end do
   end subroutine read_arguments

   !> The single case of the run: the first point of its sweep with the case file's creepages;
   !> the run must keep the geometry and the load (a DOE over tangential inputs only).
   subroutine case_of_run()
      integer :: k, code

      if (case_config%load%mode /= 'force') call fail(config%case_file// &
         ": the benchmark needs load%mode = 'force'")
      point = case_config%case_point(1)
      do k = 2, case_config%n_cases()
         if (case_config%shares_with(k, axis_load) /= 1) call fail(config%case_file// &
            ': the sweep must vary the tangential inputs only (one normal patch)')
      end do
      position = setup%position
      position%y_ws = point%t_y
      position%roll = point%roll
      case_load = point%normal_force
      material = setup%material
      material%friction = point%friction
      normal_options = setup%normal
      tangential_options = setup%tangential
      call parse_bound(trim(point%bound), code, error)
      call stop_on(error, 'bound')
      tangential_options%bound = code
      call parse_spin_model(trim(point%spin_model), code, error)
      call stop_on(error, 'spin model')
      tangential_options%spin_model = code
      tangential_options%fields = .false.
      headline = creepage_type(case_config%creepage%nu_x, case_config%creepage%nu_y, &
         case_config%creepage%phi)
   end subroutine case_of_run

   subroutine print_header()
      character(len=256) :: model
      write (output_unit, '(a)') 'shcontact-bench, shcontact '//shcontact_version
      call cpu_model(model)
      write (output_unit, '(a,i0,a,i0)') 'machine: '//trim(model)//'; logical CPUs: ', &
         omp_get_num_procs(), '; OpenMP max threads: ', omp_get_max_threads()
      write (output_unit, '(a)') 'compiler: '//compiler_version()
      write (output_unit, '(a)') 'flags: '//compiler_options()
      call print_load('load at the start')
      write (output_unit, '(a)') 'case: '//config%case_file//': '// &
         trim(case_config%profiles%wheel)//' on '//trim(case_config%profiles%rail)//', t_y = '// &
         real_text(point%t_y)//' mm, Fn = '//real_text(case_load)//' N, mu = '// &
         real_text(material%friction)//', '//itoa(normal_options%n_strips)//' strips x '// &
         itoa(tangential_options%n_elements)//' elements, bound '// &
         bound_name(tangential_options%bound)//', spin model '//trim(point%spin_model)
      write (output_unit, '(a)') 'single-case creepages: nu_x = '//real_text(headline%nu_x)// &
         ', nu_y = '//real_text(headline%nu_y)//', phi = '//real_text(headline%phi)//' rad/mm'
      write (output_unit, '(a,i0,a,es9.2,a)') 'each item: ', config%runs, &
         ' timed batches of about ', config%batch_time, ' s; time per call in microseconds'
      write (output_unit, '(a,f8.2,a)') 'profiles read, smoothed and sampled (prepare_run, '// &
         'once per run, one run): ', 1.0e3_wp*t_setup, ' ms'
   end subroutine print_header

   !> The first "model name" of /proc/cpuinfo.
   subroutine cpu_model(model)
      character(len=*), intent(out) :: model
      character(len=512) :: line
      integer :: unit, stat, c
      model = 'unknown CPU'
      open (newunit=unit, file='/proc/cpuinfo', status='old', action='read', iostat=stat)
      if (stat /= 0) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, 'model name') /= 1) cycle
         c = index(line, ':')
         model = adjustl(line(c + 1:))
         exit
      end do
      close (unit)
   end subroutine cpu_model

   !> /proc/loadavg: the machine is shared, so the load is part of every figure.
   subroutine print_load(label)
      character(len=*), intent(in) :: label
      character(len=128) :: line
      integer :: unit, stat
      line = 'unknown'
      open (newunit=unit, file='/proc/loadavg', status='old', action='read', iostat=stat)
      if (stat == 0) then
         read (unit, '(a)', iostat=stat) line
         close (unit)
      end if
      write (output_unit, '(a)') label//' (1, 5, 15 min): '//trim(line)
   end subroutine print_load

   ! ------------------------------------------------------------------------------ the items

   subroutine bench_geometry_and_normal()
      type(geometry_kernel) :: geo
      type(normal_prepare_kernel) :: prep
      type(normal_load_kernel) :: load
      type(timing_type) :: t
      integer :: i

      call section('geometry and normal contact')
      geo%profiles = setup%prepared
      geo%position = position
      t = time_kernel(geo, config%runs, config%batch_time)
      call report(geo, t, 'geometry: contact search + strip tables, one wheel position')
      write (output_unit, '(a,i0,a,i0,a)') '      (', size(patches), ' patch(es), ', &
         patches(1)%size(), ' table points)'
      prep%geometry = patches(1)
      prep%options = normal_options
      prep%material = material
      t = time_kernel(prep, config%runs, config%batch_time)
      call report(prep, t, 'normal: prepare_normal_contact (once per geometry)')
      do i = 1, size(sizes)
         load%contact = normal_contact(sizes(i))
         load%load = case_load
         t = time_kernel(load, config%runs, config%batch_time)
         call report(load, t, 'normal: solve_load, '//itoa(sizes(i))//' strips')
      end do
   end subroutine bench_geometry_and_normal

   subroutine bench_tangential()
      type(sh_prepare_kernel) :: sh_prep
      type(fastsim_prepare_kernel) :: fs_prep
      type(solve_kernel) :: sh_solve, fs_solve
      type(timing_type) :: t_shp, t_sh, t_shf, t_fsp, t_fs
      type(normal_patch_type) :: patch, hertz
      type(tangential_options_type) :: options
      integer :: i, b

      call section('tangential: FASTSIM_SH and classical FASTSIM, strips x elements, '// &
         'microseconds')
      write (output_unit, '(a)') '  per call: prepare = workspace from the normal patch or '// &
         'ellipse; solve = one creepage set (forces only); +fields = solve with element fields'
      write (output_unit, '(a)') '  median [min, max]                   SH prepare'// &
         '             SH solve             SH +fields           FASTSIM prepare'// &
         '        FASTSIM solve        SH/FS solve  SH/FS prep+solve'
      do i = 1, size(sizes)
         patch = normal_solution(sizes(i), .false.)
         hertz = normal_solution(sizes(i), .true.)
         do b = 1, n_bounds
            options = tangential_options
            options%bound = b
            options%n_elements = sizes(i)
            options%fields = .false.
            sh_prep%patch = patch
            sh_prep%material = material
            sh_prep%options = options
            t_shp = time_kernel(sh_prep, config%runs, config%batch_time)
            sh_solve%ws = sh_prep%ws
            sh_solve%creepage = headline
            t_sh = time_kernel(sh_solve, config%runs, config%batch_time)
            call keep(sh_solve%result%fx, sh_solve%result%fy, sh_solve%result%mz)
            options%fields = .true.
            call prepare_fastsim_sh(sh_solve%ws, patch, material, options, error)
            call stop_on(error, 'prepare_fastsim_sh')
            t_shf = time_kernel(sh_solve, config%runs, config%batch_time)

            options%fields = .false.
            fs_prep%semi_a = hertz%ellipse_a
            fs_prep%semi_b = hertz%ellipse_b
            fs_prep%load = hertz%load
            fs_prep%y_centre = hertz%ellipse_y_centre
            fs_prep%gamma0 = hertz%gamma0
            fs_prep%n_strips = sizes(i)
            fs_prep%material = material
            fs_prep%options = options
            t_fsp = time_kernel(fs_prep, config%runs, config%batch_time)
            fs_solve%ws = fs_prep%ws
            fs_solve%creepage = headline
            t_fs = time_kernel(fs_solve, config%runs, config%batch_time)
            call keep(fs_solve%result%fx, fs_solve%result%fy, fs_solve%result%mz)
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
   end subroutine bench_tangential

   subroutine bench_full_case()
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
            full%contact = normal_contact(sizes(i), hertz=full%classical)
            full%load = case_load
            full%material = material
            full%options = tangential_options
            full%options%fields = .false.
            full%creepage = headline
            t(c, 1) = time_kernel(full, config%runs, config%batch_time)
            if (c == 1 .and. i == 2) summary%full50 = t(c, 1)%median
            if (c == 1 .and. i == 3) summary%full100 = t(c, 1)%median
            call report(full, t(c, 1), merge('FASTSIM   ', 'FASTSIM_SH', full%classical)// &
               ' full case, '//itoa(sizes(i))//' x '//itoa(full%options%n_elements))
            full%options%fields = .true.
            t(c, 2) = time_kernel(full, config%runs, config%batch_time)
            call report(full, t(c, 2), merge('FASTSIM   ', 'FASTSIM_SH', full%classical)// &
               ' full case, '//itoa(sizes(i))//' x '//itoa(full%options%n_elements)// &
               ', with element fields')
         end do
         write (output_unit, '(2x,a,f5.2,a,f5.2,a)') 'ratio FASTSIM_SH/FASTSIM, full case '// &
            itoa(sizes(i))//' strips: ', t(1, 1)%median/t(2, 1)%median, ' (forces), ', &
            t(1, 2)%median/t(2, 2)%median, ' (with fields)'
      end do
   end subroutine bench_full_case

   !> The kinematic call (issue 12), 100 strips x 50 elements, vertical load 64.7 kN, 30 m/s:
   !> at one fixed wheelset position with the trajectory's velocities (new creepages at every
   !> call; the geometry and the prepared normal problem are reused) and along a hunting
   !> trajectory whose t_y and yaw change at every call (amplitudes 0.01-8 mm, up to 10 mrad),
   !> measured in the same run, with the ratio.
   subroutine bench_moving_wheel()
      type(kinematic_kernel) :: fixed, moving
      type(timing_type) :: t_fixed, t_moving
      real(wp) :: t_init

      call section('wheel in motion: kinematic call (solve_kinematic), 100 strips x 50 '// &
         'elements, vertical load 64.7 kN, 30 m/s')
      t_init = wall_time()
      call moving%solver%init('builtin:S1002', 'builtin:UIC60', error)
      t_init = wall_time() - t_init
      call stop_on(error, 'solver init')
      call fixed%solver%init('builtin:S1002', 'builtin:UIC60', error)
      call stop_on(error, 'solver init')
      moving%states = hunting_states(1000)
      ! Same position (that of state 200), the velocities of the trajectory: new creepages at
      ! every call, as a vehicle code's call when the wheelset has not moved.
      fixed%states = moving%states
      fixed%states%y_ws = moving%states(200)%y_ws
      fixed%states%yaw = moving%states(200)%yaw
      write (output_unit, '(2x,a,f8.1,a)') 'set-up (init: profiles smoothed and sampled): ', &
         1.0e6_wp*t_init, ' us, once per wheel'
      t_init = wall_time()
      call moving%run(1)
      t_init = wall_time() - t_init
      write (output_unit, '(2x,a,f8.1,a)') 'first yawed call (also prepares the yaw table): ', &
         1.0e6_wp*t_init, ' us, once per wheel'
      t_fixed = time_kernel(fixed, config%runs, config%batch_time)
      call report(fixed, t_fixed, 'same position, new velocities (creepages) every call')
      t_moving = time_kernel(moving, config%runs, config%batch_time)
      call report(moving, t_moving, 'hunting trajectory, t_y and yaw new every call')
      write (output_unit, '(2x,a,f7.2,a,i0)') 'ratio moving/fixed: ', &
         t_moving%median/t_fixed%median, '; failed calls: ', moving%failures + fixed%failures
      summary%moving = t_moving%median
      summary%moving_ratio = t_moving%median/t_fixed%median
   end subroutine bench_moving_wheel

   !> The defaults of issue 13 against the old ones, same run: the normal reduction `coupled`
   !> (the strips' load redistributed through the half-space) against `local-hertz`, on the
   !> full case at a fixed position (normal solve for the load + tangential) and on the
   !> kinematic call along the hunting trajectory, with the ratios new/old.
   subroutine bench_defaults()
      type(full_case_kernel) :: full(2)
      type(kinematic_kernel) :: moving(2)
      type(timing_type) :: t_full(2), t_moving(2)
      type(normal_options_type) :: old
      character(len=*), parameter :: names(2) = [character(len=11) :: 'coupled', 'local-hertz']
      integer :: c

      call section('defaults: normal reduction coupled (new, issue 13) against local-hertz '// &
         '(old), 100 strips x 50 elements, same run')
      old = normal_options
      old%reduction = reduction_local_hertz
      do c = 1, 2
         full(c)%n_strips = sizes(3)
         full(c)%contact = normal_contact(sizes(3), reduction=merge(normal_options%reduction, &
            old%reduction, c == 1))
         full(c)%load = case_load
         full(c)%material = material
         full(c)%options = tangential_options
         full(c)%options%fields = .false.
         full(c)%creepage = headline
         call moving(c)%solver%init('builtin:S1002', 'builtin:UIC60', error)
         call stop_on(error, 'solver init')
         if (c == 2) call moving(c)%solver%set_options(error, normal=old)
         call stop_on(error, 'set_options')
         moving(c)%states = hunting_states(1000)
         call moving(c)%run(1)
      end do
      ! The new and the old defaults of each item are timed one right after the other.
      do c = 1, 2
         t_full(c) = time_kernel(full(c), config%runs, config%batch_time)
         call report(full(c), t_full(c), 'full case, fixed position, '//trim(names(c)))
      end do
      do c = 1, 2
         t_moving(c) = time_kernel(moving(c), config%runs, config%batch_time)
         call report(moving(c), t_moving(c), 'kinematic call, hunting, '//trim(names(c)))
      end do
      write (output_unit, '(2x,a,f6.2,a,f6.2,a,i0)') 'ratio new/old defaults: full case ', &
         t_full(1)%median/t_full(2)%median, ', wheel in motion ', &
         t_moving(1)%median/t_moving(2)%median, '; failed calls: ', moving(1)%failures + &
         moving(2)%failures
   end subroutine bench_defaults

   !> Every 0.01 mm position from -10 to 10 mm at yaw 0 and +-10 mrad: the failed calls.
   subroutine bench_scan()
      type(contact_solver_type) :: solver
      integer :: failures
      real(wp) :: t

      call section('scan: kinematic call at every 0.01 mm, t_y = -10 ... 10 mm, yaw 0 and '// &
         '+-10 mrad, vertical load 64.7 kN')
      call solver%init('builtin:S1002', 'builtin:UIC60', error)
      call stop_on(error, 'solver init')
      t = wall_time()
      call scan_positions(solver, [0.0_wp, 0.01_wp, -0.01_wp], failures)
      write (output_unit, '(2x,a,i0,a,f8.1,a)') 'failed calls: ', failures, ' of 6003 (', &
         wall_time() - t, ' s)'
   end subroutine bench_scan

   !> The DOE of the case file end to end through the app's sweep driver (geometry, normal
   !> solution, every case, the HDF5 file with its checkpoint blocks, merge), with 1 and 2
   !> threads; and the same cases as a bare library loop on one prepared workspace.
   subroutine bench_doe()
      type(creepage_type), allocatable :: creepages(:)
      type(doe_table_type) :: table
      type(sweep_outcome_type) :: outcome
      type(march_workspace_type) :: ws
      type(normal_patch_type) :: patch
      real(wp), allocatable :: t_app(:), t_loop(:)
      integer :: threads, r, n

      n = case_config%n_cases()
      call section('design of experiments: '//config%case_file//', '//itoa(n)//' cases')
      creepages = run_creepages()
      call reserve_table(table, n)
      allocate (t_app(config%doe_runs), t_loop(config%doe_runs))
      patch = normal_solution(normal_options%n_strips, .false.)
      call prepare_fastsim_sh(ws, patch, material, tangential_options, error)
      call stop_on(error, 'DOE: prepare_fastsim_sh')
      write (output_unit, '(a)') '  app: run_sweep (shcontact_case_sweep) end to end: '// &
         'geometry, normal solution, every case, HDF5 blocks, merged file '//config%output
      write (output_unit, '(a)') '  library loop: solve_prepared on one prepared workspace '// &
         'per thread, forces only, no file'
      do threads = 1, 2
         do r = 1, config%doe_runs
            call run_app(threads, outcome, t_app(r))
            t0 = wall_time()
            call solve_doe(ws, creepages, table, threads)
            t_loop(r) = wall_time() - t0
         end do
         write (output_unit, '(2x,a,i0,a,3(f8.1,a),a,3(f8.1,a),a,f6.2,a)') 'threads ', threads, &
            ': app ', 1.0e3_wp*median_of(t_app), ' ms [', 1.0e3_wp*minval(t_app), ', ', &
            1.0e3_wp*maxval(t_app), ']', '; library loop ', 1.0e3_wp*median_of(t_loop), &
            ' ms [', 1.0e3_wp*minval(t_loop), ', ', 1.0e3_wp*maxval(t_loop), ']', ' (', &
            1.0e6_wp*median_of(t_loop)/n, ' us per case)'
         if (threads == 1) summary%doe1 = median_of(t_app)
         if (threads == 2) summary%doe2 = median_of(t_app)
      end do
      write (output_unit, '(2x,a,i0,a)') '(', config%doe_runs, ' runs each)'
      if (any(table%status /= 0)) call fail('a DOE case failed in the library loop')
      if (size(outcome%failures) > 0) call fail('a DOE case failed in the app')
      call check_doe(creepages, table, outcome)
      call keep_array(table%fx)
      call keep_array(table%fy)
      call keep_array(table%mz)
   end subroutine bench_doe

   !> The creepages of the run's cases.
   function run_creepages() result(creepages)
      type(creepage_type), allocatable :: creepages(:)
      type(case_point_type) :: p
      integer :: k
      allocate (creepages(case_config%n_cases()))
      do k = 1, size(creepages)
         p = case_config%case_point(k)
         creepages(k) = creepage_type(p%nu_x, p%nu_y, p%phi)
      end do
   end function run_creepages

   !> One run of the app's sweep driver, timed.
   subroutine run_app(threads, outcome, seconds)
      integer, intent(in) :: threads
      type(sweep_outcome_type), intent(out) :: outcome
      real(wp), intent(out) :: seconds
      type(sweep_options_type) :: options

      options%threads = threads
      options%command_line = 'shcontact-bench'
      t0 = wall_time()
      call run_sweep(case_config, options, outcome, error)
      seconds = wall_time() - t0
      call stop_on(error, 'run_sweep')
   end subroutine run_app

   ! ------------------------------------------------------------------------------- checks

   !> The forces of the library loop (2 threads, one reused workspace, no fields) equal, case by
   !> case, those of the app's sweep and those of the library's plain pipeline: the profiles as
   !> read, find_contact_patches with the smoothing, prepare_normal_contact, solve_load, then
   !> solve_tangential per case with a fresh preparation and the element fields on.
   subroutine check_doe(creepages, table, outcome)
      type(creepage_type), intent(in) :: creepages(:)
      type(doe_table_type), intent(in) :: table
      type(sweep_outcome_type), intent(in) :: outcome
      type(patch_geometry_type), allocatable :: found(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(tangential_options_type) :: options
      real(wp) :: diff_app, diff_pipe, scale
      integer :: k, n_app, n_pipe

      call section('checks')
      call find_contact_patches(setup%wheel, setup%rail, setup%prepared%track, position, &
         setup%prepared%options, found, error)
      call stop_on(error, 'pipeline: find_contact_patches')
      call prepare_normal_contact(contact, found(1), normal_options, material, error)
      call stop_on(error, 'pipeline: prepare_normal_contact')
      call solve_load(contact, case_load, patch, error)
      call stop_on(error, 'pipeline: solve_load')
      options = tangential_options
      options%fields = .true.
      scale = material%friction*patch%load
      diff_app = 0.0_wp
      diff_pipe = 0.0_wp
      n_app = 0
      n_pipe = 0
      do k = 1, size(creepages)
         call solve_tangential(ws, patch, material, creepages(k), options, result, error)
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

   !> Save the checked forces, or compare them with another build's.
   subroutine check_results()
      real(wp), allocatable :: other(:)
      integer :: unit, stat, n, i
      real(wp) :: scale, diff

      scale = material%friction*case_load
      if (len(config%save_file) > 0) then
         open (newunit=unit, file=config%save_file, status='replace', action='write', iostat=stat)
         if (stat /= 0) call fail('cannot write '//config%save_file)
         write (unit, '(i0)') size(saved)
         write (unit, '(es24.16e3)') saved
         close (unit)
         write (output_unit, '(2x,a,i0,a)') 'saved ', size(saved), ' forces to '// &
            config%save_file
      end if
      if (len(config%compare_file) > 0) then
         open (newunit=unit, file=config%compare_file, status='old', action='read', iostat=stat)
         if (stat /= 0) call fail('cannot read '//config%compare_file)
         read (unit, *, iostat=stat) n
         if (stat /= 0 .or. n /= size(saved)) call fail(config%compare_file// &
            ': expected '//itoa(size(saved))//' forces')
         allocate (other(n))
         read (unit, *, iostat=stat) other
         close (unit)
         if (stat /= 0) call fail('cannot read the forces of '//config%compare_file)
         diff = 0.0_wp
         do i = 1, n
            diff = max(diff, abs(other(i) - saved(i))/scale)
         end do
         write (output_unit, '(2x,a,i0,a,es9.2,a,i0,a)') 'this build vs '// &
            config%compare_file//': ', n, ' forces (N, N mm), max |d|/(mu Fn) = ', diff, &
            ' (', count(other == saved), ' bitwise equal)'
      end if
   end subroutine check_results

   !> Record forces for --save-results / --compare-results.
   subroutine keep(fx, fy, mz)
      real(wp), intent(in) :: fx, fy, mz
      saved = [saved, fx, fy, mz]
   end subroutine keep

   subroutine keep_array(values)
      real(wp), intent(in) :: values(:)
      saved = [saved, values]
   end subroutine keep_array

   !> The targets of issue 9 against this run's medians.
   subroutine print_summary()
      call section('targets (issue 9; medians of this run)')
      if (summary%sh50_worst > 0.0_wp) write (output_unit, '(2x,a,f6.2,a,f6.2,a,a)') &
         'FASTSIM_SH solve 50 x 50 <= 15 us: weighted ', 1.0e6_wp*summary%sh50_weighted, &
         ' us, slowest bound ', 1.0e6_wp*summary%sh50_worst, ' us: ', &
         verdict(summary%sh50_worst <= 15.0e-6_wp)
      if (summary%full50 > 0.0_wp) write (output_unit, '(2x,a,f6.2,a,a,a,f6.2,a,a)') &
         'full case (normal + tangential, geometry reused) <= 30 us: 50 strips ', &
         1.0e6_wp*summary%full50, ' us: ', verdict(summary%full50 <= 30.0e-6_wp), &
         '; the default 100 strips ', 1.0e6_wp*summary%full100, ' us: ', &
         verdict(summary%full100 <= 30.0e-6_wp)
      if (summary%ratio_solve(1) > 0.0_wp) then
         write (output_unit, '(2x,a,f5.2,a,f5.2,a,a)') 'FASTSIM_SH/FASTSIM <= 1.2 (median and '// &
            'largest over the 3 sizes x 5 bounds): solve ', median_of(summary%ratio_solve), &
            ', largest ', maxval(summary%ratio_solve), ': ', &
            verdict(median_of(summary%ratio_solve) <= 1.2_wp)
         write (output_unit, '(2x,a,f5.2,a,f5.2,a,a)') '  with the preparation from the '// &
            'normal solution (prepare + solve): ', median_of(summary%ratio_prep_solve), &
            ', largest ', maxval(summary%ratio_prep_solve), ': ', &
            verdict(median_of(summary%ratio_prep_solve) <= 1.2_wp)
      end if
      if (summary%moving > 0.0_wp) write (output_unit, '(2x,a,f8.1,a,f6.2,a)') &
         'wheel in motion (hunting, 100 x 50): ', 1.0e6_wp*summary%moving, &
         ' us per call, moving/fixed = ', summary%moving_ratio, &
         ' (targets <= 100 us and <= 3)'
      if (summary%doe2 > 0.0_wp) write (output_unit, '(2x,a,f6.1,a,f6.1,a,a)') &
         'DOE end to end with the HDF5 file <= 0.5 s with 2 threads: ', 1.0e3_wp*summary%doe2, &
         ' ms (1 thread: ', 1.0e3_wp*summary%doe1, ' ms): ', verdict(summary%doe2 <= 0.5_wp)
      write (output_unit, '(2x,a)') 'no heap allocation per case: run --alloc-check N and 2N '// &
         'under valgrind (doc/performance.md)'
   end subroutine print_summary

   pure function verdict(met) result(text)
      logical, intent(in) :: met
      character(len=:), allocatable :: text
      if (met) then
         text = 'met'
      else
         text = 'NOT met'
      end if
   end function verdict

   ! ---------------------------------------------------------------- allocation check

   !> N full cases (solve_load with varying load, prepare_fastsim_sh, solve_prepared with the
   !> fields) and N DOE cases on one thread and on two. Run under valgrind with N and 2N: the
   !> heap allocation count must be the same.
   subroutine allocation_run(n)
      integer, intent(in) :: n
      type(full_case_kernel) :: full
      type(creepage_type), allocatable :: creepages(:)
      type(doe_table_type) :: table
      type(march_workspace_type) :: ws
      type(normal_patch_type) :: patch
      integer :: k

      full%contact = normal_contact(normal_options%n_strips)
      full%load = case_load
      full%material = material
      full%options = tangential_options
      full%options%fields = .true.
      full%creepage = headline
      do k = 1, n
         call full%run(k)
      end do
      if (full%failed) call fail('alloc-check: '//full%message)
      patch = normal_solution(normal_options%n_strips, .false.)
      call prepare_fastsim_sh(ws, patch, material, tangential_options, error)
      call stop_on(error, 'alloc-check: prepare_fastsim_sh')
      creepages = run_creepages()
      creepages = [(creepages(mod(k - 1, size(creepages)) + 1), k=1, n)]
      call reserve_table(table, n)
      call solve_doe(ws, creepages, table, 1)
      call solve_doe(ws, creepages, table, 2)
      if (any(table%status /= 0)) call fail('alloc-check: a DOE case failed')
      write (output_unit, '(a,i0,a,2es24.16)') 'alloc-check: ', n, ' cases; last forces ', &
         full%result%fx, table%fx(n)
   end subroutine allocation_run

   ! ------------------------------------------------------------------------------ helpers

   !> The case's patch prepared for the strip method (or the Hertz method) with n strips.
   function normal_contact(n, hertz, reduction) result(contact)
      integer, intent(in) :: n
      logical, intent(in), optional :: hertz
      !> Normal reduction code (default: the case's).
      integer, intent(in), optional :: reduction
      type(normal_contact_type) :: contact
      type(normal_options_type) :: options

      options = normal_options
      options%n_strips = n
      if (present(hertz)) then
         if (hertz) options%method = method_hertz
      end if
      if (present(reduction)) options%reduction = reduction
      call prepare_normal_contact(contact, patches(1), options, material, error)
      call stop_on(error, 'prepare_normal_contact')
   end function normal_contact

   !> The normal solution at the case load with n strips: semi-Hertz or the Hertz ellipse.
   function normal_solution(n, hertz) result(patch)
      integer, intent(in) :: n
      logical, intent(in) :: hertz
      type(normal_patch_type) :: patch
      type(normal_contact_type) :: contact

      contact = normal_contact(n, hertz)
      call solve_load(contact, case_load, patch, error)
      call stop_on(error, 'normal solution')
   end function normal_solution

   subroutine section(title)
      character(len=*), intent(in) :: title
      write (output_unit, '(/,a)') '== '//title
   end subroutine section

   !> One line: label, median [min, max] in microseconds, batch size and runs.
   subroutine report(kernel, t, label)
      class(kernel_type), intent(in) :: kernel
      type(timing_type), intent(in) :: t
      character(len=*), intent(in) :: label
      if (kernel%failed) call fail(label//': '//kernel%message)
      write (output_unit, '(2x,a,t70,a,a,i0,a,i0,a)') label, triple(t), '  (', t%batch, &
         ' calls x ', t%runs, ')'
   end subroutine report

   !> "median [min, max]" in microseconds.
   function triple(t) result(text)
      type(timing_type), intent(in) :: t
      character(len=21) :: text
      write (text, '(f7.2,a,f5.1,a,f5.1,a)') 1.0e6_wp*t%median, ' [', 1.0e6_wp*t%min, ',', &
         1.0e6_wp*t%max, ']'
      if (t%median >= 1.0e-4_wp) write (text, '(f7.0,a,f5.0,a,f5.0,a)') 1.0e6_wp*t%median, &
         ' [', 1.0e6_wp*t%min, ',', 1.0e6_wp*t%max, ']'
   end function triple

   pure function itoa(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=16) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function itoa

   pure function real_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=24) :: buf
      write (buf, '(g0.6)') x
      text = trim(adjustl(buf))
   end function real_text

   subroutine stop_on(error, what)
      type(error_type), allocatable, intent(in) :: error
      character(len=*), intent(in) :: what
      if (allocated(error)) call fail(what//': '//error%message)
   end subroutine stop_on

   subroutine fail(message)
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'shcontact-bench: '//message
      error stop 1
   end subroutine fail

end program shcontact_bench
