!> shcontact-bench: how fast the contact model runs on this machine (issue 9, doc/performance.md).
!>
!>     fpm run --profile release --example shcontact-bench [-- OPTIONS]
!>
!> Options:
!>     --runs N               timed repetitions per item (default 15); median, min and max
!>     --batch-time S         target length of one timed batch in s (default 0.01)
!>     --quick                --runs 5 --batch-time 0.002, two DOE runs (for slow builds)
!>     --profiles DIR         directory of the Manchester profiles (default ../shared/profiles);
!>                            the built-in S1002 and UIC60 are used when it is absent
!>     --table-gap G          contact_options%table_gap (mm, default the library's 2 mm): how
!>                            far the strip tables reach; the geometry cost grows with it
!>     --output FILE          HDF5 summary of the DOE (default build/shcontact_bench_doe.h5)
!>     --save-results FILE    write the forces of the checked cases to a text file
!>     --compare-results FILE compare the forces with a file saved by another build
!>     --only SECTION         run one section: geometry, tangential, full or doe (no checks)
!>     --alloc-check N        only solve N full cases and N DOE cases, then stop (run it under
!>                            valgrind with N and 2N: the allocation count must not change)
!>
!> The case is the seed's: S1002 on UIC60 1:40 (Manchester profiles), centred wheelset, normal
!> force 64.7 kN, G = 82670 MPa, ν = 0.27, μ = 0.3; creepages at the geometric contact point
!> ν_x = 0.58e-3, ν_y = 0.061e-3, φ = 2.74e-4 rad/mm (../shared/reference/README.md).
program shcontact_bench
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options, output_unit, &
      error_unit
   use omp_lib, only: omp_get_num_procs, omp_get_max_threads
   use hdf5, only: h5open_f, h5close_f
   use shcontact, only: wp, error_type, material_type, profile_type, read_profile, clean_profile, &
      builtin_profile, track_type, wheelset_position_type, contact_options_type, &
      prepared_profiles_type, prepare_profiles, find_contact_patches, patch_geometry_type, &
      normal_options_type, normal_contact_type, prepare_normal_contact, solve_load, &
      normal_patch_type, tangential_options_type, march_workspace_type, prepare_fastsim_sh, &
      creepage_type, tangential_patch_type, solve_tangential, bound_name, shcontact_version
   use shcontact_normal_options, only: method_hertz
   use shcontact_tangential_options, only: bound_weighted
   use shcontact_tangential_march, only: solve_prepared
   use bench_timing, only: kernel_type, timing_type, time_kernel, wall_time, median_of
   use bench_kernels, only: geometry_kernel, normal_prepare_kernel, normal_load_kernel, &
      sh_prepare_kernel, fastsim_prepare_kernel, solve_kernel, full_case_kernel
   use bench_summary, only: doe_table_type, write_doe_summary
   use bench_doe, only: doe_creepages, solve_doe, reserve_table
   implicit none

   real(wp), parameter :: case_load = 64700.0_wp
   type(creepage_type), parameter :: headline = creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp)
   integer, parameter :: sizes(3) = [25, 50, 100]
   integer, parameter :: n_bounds = 5
   !> DOE grid: 20 values per creepage, 8000 cases, default discretisation.
   integer, parameter :: doe_points = 20, doe_strips = 100, doe_elements = 50

   type bench_config_type
      integer :: runs = 15
      integer :: doe_runs = 5
      real(wp) :: batch_time = 0.01_wp
      character(len=:), allocatable :: profiles, output, save_file, compare_file
      integer :: alloc_check = 0
      character(len=:), allocatable :: only
      real(wp) :: table_gap = -1.0_wp
   end type bench_config_type

   !> The figures the targets of issue 9 are about (negative: not measured in this run).
   type summary_type
      !> FASTSIM_SH solve at 50 x 50: weighted bound and the slowest bound (s).
      real(wp) :: sh50_weighted = -1.0_wp, sh50_worst = -1.0_wp
      !> FASTSIM_SH/FASTSIM ratios for every size and bound: solve, prepare + solve.
      real(wp) :: ratio_solve(3*n_bounds) = -1.0_wp, ratio_prep_solve(3*n_bounds) = -1.0_wp
      !> Full FASTSIM_SH case at 50 x 50 and 100 x 50, forces only (s).
      real(wp) :: full50 = -1.0_wp, full100 = -1.0_wp
      !> DOE end to end with 1 and 2 threads (s).
      real(wp) :: doe1 = -1.0_wp, doe2 = -1.0_wp
   end type summary_type

   type(bench_config_type) :: config
   type(summary_type) :: summary
   type(material_type) :: material
   type(profile_type) :: wheel, rail
   type(track_type) :: track
   type(contact_options_type) :: contact_options
   type(wheelset_position_type) :: position
   type(prepared_profiles_type) :: profiles
   type(patch_geometry_type), allocatable :: patches(:)
   type(error_type), allocatable :: error
   character(len=:), allocatable :: profile_note
   real(wp), allocatable :: saved(:)
   integer :: hstat
   real(wp) :: t0, t_profiles

   call read_arguments(config)
   call load_profiles(config%profiles, wheel, rail, track, profile_note)
   position = wheelset_position_type(y_ws=0.0_wp)
   if (config%table_gap > 0.0_wp) contact_options%table_gap = config%table_gap
   t0 = wall_time()
   call prepare_profiles(wheel, rail, track, contact_options, profiles, error)
   t_profiles = wall_time() - t0
   call stop_on(error, 'prepare_profiles')
   call find_contact_patches(profiles, position, patches, error)
   call stop_on(error, 'find_contact_patches')
   call h5open_f(hstat)
   if (hstat /= 0) call fail('cannot initialise the HDF5 library')

   if (config%alloc_check > 0) then
      call allocation_run(config%alloc_check)
      call h5close_f(hstat)
      stop
   end if

   call print_header()
   write (output_unit, '(a)') 'case: '//profile_note//', y_ws = 0, Fn = 64.7 kN, G = 82670 MPa, '// &
      'nu = 0.27, mu = 0.3; creepages nu_x = 0.58e-3, nu_y = 0.061e-3, phi = 2.74e-4 rad/mm'
   write (output_unit, '(a,i0,a,es9.2,a)') 'each item: ', config%runs, ' timed batches of about ', &
      config%batch_time, ' s; time per call in microseconds'
   write (output_unit, '(a,f0.1,a)') 'profile smoothing and sampling (once per profile pair, '// &
      'one run): ', 1.0e3_wp*t_profiles, ' ms'
   allocate (saved(0))
   if (wanted('geometry')) call bench_geometry_and_normal()
   if (wanted('tangential')) call bench_tangential()
   if (wanted('full')) call bench_full_case()
   if (wanted('doe')) call bench_doe()
   if (len(config%only) == 0) call check_results()
   call print_summary()
   call print_load('load at the end')
   call h5close_f(hstat)

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

      config%profiles = '../shared/profiles'
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
         select case (trim(arg))
         case ('--quick')
            config%runs = 5
            config%doe_runs = 2
            config%batch_time = 0.002_wp
            i = i - 1
         case ('--runs')
            read (val, *, iostat=stat) config%runs
            if (stat == 0 .and. config%runs < 1) stat = 1
         case ('--batch-time')
            read (val, *, iostat=stat) config%batch_time
            if (stat == 0 .and. .not. (config%batch_time > 0.0_wp)) stat = 1
         case ('--profiles')
            config%profiles = trim(val)
         case ('--output')
            config%output = trim(val)
         case ('--save-results')
            config%save_file = trim(val)
         case ('--compare-results')
            config%compare_file = trim(val)
         case ('--table-gap')
            read (val, *, iostat=stat) config%table_gap
            if (stat == 0 .and. .not. (config%table_gap > 0.0_wp)) stat = 1
         case ('--only')
            config%only = trim(val)
            if (all(config%only /= [character(len=10) :: 'geometry', 'tangential', 'full', &
               'doe'])) stat = 1
         case ('--alloc-check')
            read (val, *, iostat=stat) config%alloc_check
            if (stat == 0 .and. config%alloc_check < 1) stat = 1
         case default
            call fail('unknown argument '//trim(arg)//'; see the header of examples/bench/bench.f90')
         end select
         if (stat /= 0 .or. (i == n .and. trim(arg) /= '--quick')) &
            call fail('bad or missing value for '//trim(arg))
         i = i + 2
      end do
   end subroutine read_arguments

   !> The Manchester profiles when present, else the built-in S1002 and canted UIC60.
   subroutine load_profiles(dir, wheel, rail, track, note)
      character(len=*), intent(in) :: dir
      type(profile_type), intent(out) :: wheel, rail
      type(track_type), intent(out) :: track
      character(len=:), allocatable, intent(out) :: note
      type(error_type), allocatable :: error
      logical :: there

      inquire (file=dir//'/MBench_S1002_v3.prw', exist=there)
      track%rail_canted = .true.
      if (there) then
         call read_profile(dir//'/MBench_S1002_v3.prw', wheel, error)
         if (.not. allocated(error)) call clean_profile(wheel, error)
         if (.not. allocated(error)) call read_profile(dir//'/MBench_UIC60_v3.prr', rail, error)
         if (.not. allocated(error)) call clean_profile(rail, error)
         note = 'MBench_S1002_v3.prw on MBench_UIC60_v3.prr (canted 1:40)'
      else
         call builtin_profile('S1002', wheel, error)
         if (.not. allocated(error)) call builtin_profile('UIC60-canted', rail, error)
         note = 'built-in S1002 on built-in UIC60 canted 1:40 ('//dir//' is absent)'
      end if
      call stop_on(error, 'reading the profiles')
   end subroutine load_profiles

   subroutine print_header()
      character(len=256) :: model
      write (output_unit, '(a)') 'shcontact-bench, shcontact '//shcontact_version
      call cpu_model(model)
      write (output_unit, '(a,i0,a,i0)') 'machine: '//trim(model)//'; logical CPUs: ', &
         omp_get_num_procs(), '; OpenMP max threads: ', omp_get_max_threads()
      write (output_unit, '(a)') 'compiler: '//compiler_version()
      write (output_unit, '(a)') 'flags: '//compiler_options()
      call print_load('load at the start')
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
      geo%profiles = profiles
      geo%position = position
      t = time_kernel(geo, config%runs, config%batch_time)
      call report(geo, t, 'geometry: contact search + strip tables, one wheel position')
      write (output_unit, '(a,i0,a,i0,a)') '      (', size(patches), ' patch(es), ', &
         patches(1)%size(), ' table points)'
      prep%geometry = patches(1)
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
            options = tangential_options_type(bound=b, n_elements=sizes(i), fields=.false.)
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
         'preparation + solve, weighted bound, forces only unless said)')
      write (output_unit, '(a)') '  FASTSIM_SH: semi-Hertz solve_load + prepare_fastsim_sh + '// &
         'solve_prepared; FASTSIM: Hertz solve_load + prepare_fastsim + solve_prepared'
      do i = 2, 3
         do c = 1, 2
            full%classical = c == 2
            full%n_strips = sizes(i)
            full%contact = normal_contact(sizes(i), hertz=full%classical)
            full%load = case_load
            full%material = material
            full%options = tangential_options_type(n_elements=50, fields=.false.)
            full%creepage = headline
            t(c, 1) = time_kernel(full, config%runs, config%batch_time)
            if (c == 1 .and. i == 2) summary%full50 = t(c, 1)%median
            if (c == 1 .and. i == 3) summary%full100 = t(c, 1)%median
            call report(full, t(c, 1), merge('FASTSIM   ', 'FASTSIM_SH', full%classical)// &
               ' full case, '//itoa(sizes(i))//' x 50')
            full%options%fields = .true.
            t(c, 2) = time_kernel(full, config%runs, config%batch_time)
            call report(full, t(c, 2), merge('FASTSIM   ', 'FASTSIM_SH', full%classical)// &
               ' full case, '//itoa(sizes(i))//' x 50, with element fields')
         end do
         write (output_unit, '(2x,a,f5.2,a,f5.2,a)') 'ratio FASTSIM_SH/FASTSIM, full case '// &
            itoa(sizes(i))//' x 50: ', t(1, 1)%median/t(2, 1)%median, ' (forces), ', &
            t(1, 2)%median/t(2, 2)%median, ' (with fields)'
      end do
   end subroutine bench_full_case

   !> The 8000 cases end to end: contact search, normal solve, FASTSIM_SH preparation, the
   !> cases, the HDF5 summary; with 1 and 2 threads.
   subroutine bench_doe()
      type(creepage_type), allocatable :: creepages(:)
      type(doe_table_type) :: table
      real(wp), allocatable :: t_total(:), t_cases(:), t_write(:)
      integer :: threads, r

      call section('design of experiments: 20 x 20 x 20 creepages (nu_x, nu_y in [0, 2e-3], '// &
         'phi in [0, 2e-3] rad/mm), '//itoa(doe_strips)//' x '//itoa(doe_elements)// &
         ', weighted bound, HDF5 summary')
      write (output_unit, '(a)') '  end to end from the prepared profiles: contact search, '// &
         'normal solve, FASTSIM_SH preparation, 8000 solves, HDF5 file written and renamed'
      creepages = doe_creepages(doe_points, 2.0e-3_wp)
      call reserve_table(table, size(creepages))
      allocate (t_total(config%doe_runs), t_cases(config%doe_runs), t_write(config%doe_runs))
      do threads = 1, 2
         do r = 1, config%doe_runs
            call run_doe(creepages, threads, table, t_total(r), t_cases(r), t_write(r))
         end do
         write (output_unit, '(2x,a,i0,a,3(a,f8.1,a,f8.1,a,f8.1,a))') 'threads ', threads, &
            ': ', 'total ', 1.0e3_wp*median_of(t_total), ' ms [', 1.0e3_wp*minval(t_total), &
            ', ', 1.0e3_wp*maxval(t_total), ']; ', 'cases ', 1.0e3_wp*median_of(t_cases), &
            ' ms [', 1.0e3_wp*minval(t_cases), ', ', 1.0e3_wp*maxval(t_cases), ']; ', &
            'HDF5 ', 1.0e3_wp*median_of(t_write), ' ms [', 1.0e3_wp*minval(t_write), ', ', &
            1.0e3_wp*maxval(t_write), ']'
         if (threads == 1) summary%doe1 = median_of(t_total)
         if (threads == 2) summary%doe2 = median_of(t_total)
      end do
      write (output_unit, '(2x,a,i0,a)') '(', config%doe_runs, ' runs each; summary in '// &
         config%output//')'
      if (any(table%status /= 0)) call fail('a DOE case failed')
      call check_pipeline(creepages, table)
      call keep_array(table%fx)
      call keep_array(table%fy)
      call keep_array(table%mz)
   end subroutine bench_doe

   !> One DOE run, timed as a whole and in parts.
   subroutine run_doe(creepages, threads, table, t_total, t_cases, t_write)
      type(creepage_type), intent(in) :: creepages(:)
      integer, intent(in) :: threads
      type(doe_table_type), intent(inout) :: table
      real(wp), intent(out) :: t_total, t_cases, t_write
      type(patch_geometry_type), allocatable :: found(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      character(len=:), allocatable :: message
      real(wp) :: t0, t1, t2
      integer :: stat

      t0 = wall_time()
      call find_contact_patches(profiles, position, found, error)
      call stop_on(error, 'DOE: find_contact_patches')
      call prepare_normal_contact(contact, found(1), normal_options_type(n_strips=doe_strips), &
         material, error)
      call stop_on(error, 'DOE: prepare_normal_contact')
      call solve_load(contact, case_load, patch, error)
      call stop_on(error, 'DOE: solve_load')
      call prepare_fastsim_sh(ws, patch, material, doe_options(.false.), error)
      call stop_on(error, 'DOE: prepare_fastsim_sh')
      t1 = wall_time()
      call solve_doe(ws, creepages, table, threads)
      t2 = wall_time()
      call write_doe_summary(config%output, table, patch%load, 'shcontact-bench DOE: '// &
         profile_note//', y_ws = 0 mm, Fn = 64700 N, G = 82670 MPa, nu = 0.27, mu = 0.3, '// &
         'FASTSIM_SH, bound weighted, spin model additive, '//itoa(doe_strips)// &
         ' strips x '//itoa(doe_elements)//' elements', stat, message)
      if (stat /= 0) call fail(message)
      t_total = wall_time() - t0
      t_cases = t2 - t1
      t_write = wall_time() - t2
   end subroutine run_doe

   !> The DOE's tangential options (defaults: weighted bound, additive spin model).
   pure function doe_options(fields) result(options)
      logical, intent(in) :: fields
      type(tangential_options_type) :: options
      options = tangential_options_type(n_elements=doe_elements, fields=fields)
   end function doe_options

   ! ------------------------------------------------------------------------------- checks

   !> The targets of issue 9 against this run's medians.
   subroutine print_summary()
      call section('targets (issue 9; medians of this run)')
      if (summary%sh50_worst > 0.0_wp) write (output_unit, '(2x,a,f6.2,a,f6.2,a,a)') &
         'FASTSIM_SH solve 50 x 50 <= 15 us: weighted ', 1.0e6_wp*summary%sh50_weighted, &
         ' us, slowest bound ', 1.0e6_wp*summary%sh50_worst, ' us: ', &
         verdict(summary%sh50_worst <= 15.0e-6_wp)
      if (summary%full50 > 0.0_wp) write (output_unit, '(2x,a,f6.2,a,f6.2,a,a)') &
         'full case (normal + tangential, geometry reused) <= 30 us: 50 x 50 ', &
         1.0e6_wp*summary%full50, ' us, 100 x 50 ', 1.0e6_wp*summary%full100, ' us: ', &
         verdict(summary%full50 <= 30.0e-6_wp)
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
      if (summary%doe2 > 0.0_wp) write (output_unit, '(2x,a,f6.1,a,f6.1,a,a)') &
         '8000-case DOE with HDF5 summary <= 0.5 s with 2 threads: ', 1.0e3_wp*summary%doe2, &
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

   !> The forces of the timed DOE equal those of the library's plain pipeline: raw profiles,
   !> find_contact_patches (smoothing included), prepare_normal_contact, solve_load, then
   !> solve_tangential per case with a fresh workspace layout and the element fields on.
   subroutine check_pipeline(creepages, table)
      type(creepage_type), intent(in) :: creepages(:)
      type(doe_table_type), intent(in) :: table
      type(patch_geometry_type), allocatable :: found(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      real(wp) :: diff, scale
      integer :: k, n_equal

      call find_contact_patches(wheel, rail, track, position, contact_options, found, error)
      call stop_on(error, 'pipeline: find_contact_patches')
      call prepare_normal_contact(contact, found(1), normal_options_type(n_strips=doe_strips), &
         material, error)
      call stop_on(error, 'pipeline: prepare_normal_contact')
      call solve_load(contact, case_load, patch, error)
      call stop_on(error, 'pipeline: solve_load')
      scale = material%friction*patch%load
      diff = 0.0_wp
      n_equal = 0
      do k = 1, size(creepages)
         call solve_tangential(ws, patch, material, creepages(k), doe_options(.true.), result, &
            error)
         call stop_on(error, 'pipeline: solve_tangential')
         diff = max(diff, abs(result%fx - table%fx(k))/scale, abs(result%fy - table%fy(k))/scale)
         if (result%fx == table%fx(k) .and. result%fy == table%fy(k) .and. &
            result%mz == table%mz(k)) n_equal = n_equal + 1
      end do
      call section('checks')
      write (output_unit, '(2x,a,i0,a,i0,a,es9.2)') 'DOE (2 threads, reused workspace, no '// &
         'fields) vs the library pipeline (raw profiles, solve_tangential, fields): ', n_equal, &
         ' of ', size(creepages), ' cases bitwise equal; max |dF|/(mu Fn) = ', diff
      if (diff > 1.0e-12_wp) call fail('the benchmark forces differ from the pipeline''s')
   end subroutine check_pipeline

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

      full%contact = normal_contact(100)
      full%load = case_load
      full%material = material
      full%options = tangential_options_type()
      full%creepage = headline
      do k = 1, n
         call full%run(k)
      end do
      if (full%failed) call fail('alloc-check: '//full%message)
      patch = normal_solution(100, .false.)
      call prepare_fastsim_sh(ws, patch, material, doe_options(.false.), error)
      call stop_on(error, 'alloc-check: prepare_fastsim_sh')
      creepages = doe_creepages(doe_points, 2.0e-3_wp)
      creepages = [(creepages(mod(k - 1, size(creepages)) + 1), k=1, n)]
      call reserve_table(table, n)
      call solve_doe(ws, creepages, table, 1)
      call solve_doe(ws, creepages, table, 2)
      if (any(table%status /= 0)) call fail('alloc-check: a DOE case failed')
      write (output_unit, '(a,i0,a,2es24.16)') 'alloc-check: ', n, ' cases; last forces ', &
         full%result%fx, table%fx(n)
   end subroutine allocation_run

   ! ------------------------------------------------------------------------------ helpers

   !> The seed patch prepared for the strip method (or the Hertz method) with n strips.
   function normal_contact(n, hertz) result(contact)
      integer, intent(in) :: n
      logical, intent(in), optional :: hertz
      type(normal_contact_type) :: contact
      type(normal_options_type) :: options

      options%n_strips = n
      if (present(hertz)) then
         if (hertz) options%method = method_hertz
      end if
      call prepare_normal_contact(contact, patches(1), options, material, error)
      call stop_on(error, 'prepare_normal_contact')
   end function normal_contact

   !> The normal solution at the case load with n strips: semi-Hertz or the Hertz ellipse.
   function normal_solution(n, hertz) result(patch)
      integer, intent(in) :: n
      logical, intent(in) :: hertz
      type(normal_patch_type) :: patch
      type(normal_contact_type) :: contact
      type(normal_options_type) :: options

      options%n_strips = n
      if (hertz) options%method = method_hertz
      call prepare_normal_contact(contact, patches(1), options, material, error)
      if (.not. allocated(error)) call solve_load(contact, case_load, patch, error)
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
