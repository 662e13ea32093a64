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
!>     --save-results FILE    write the forces of the checked cases to a text file (with
!>                            --only moving: the totals of every state of both trajectories)
!>     --compare-results FILE compare the forces with a file saved by another build
!>     --alloc-check N        only solve N full cases and N DOE cases, then stop (run it under
!>                            valgrind with N and 2N: the allocation count must not change)
!>
!> The case is the app's (shcontact_input_config): by default the built-in S1002 on UIC60 1:40 at
!> t_y = 4.733 mm, F_n = 64.7 kN, G = 82670 MPa, ν = 0.27, μ = 0.3, 100 strips × 50 elements,
!> weighted bound; the single-case items use its creepages (ν_x = 0.58e-3, ν_y = 0.061e-3,
!> φ = 2.74e-4 rad/mm), the DOE its sweep.
program shcontact_bench
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: error_type, march_workspace_type, normal_patch_type, creepage_type, &
      prepare_fastsim_sh
   use bench_kernels, only: full_case_kernel
   use bench_doe, only: doe_table_type, solve_doe, reserve_table
   use bench_config, only: bench_config_type, read_arguments
   use bench_case, only: bench_case_type, load_case, print_header
   use bench_results, only: summary_type, force_record_type, check_results, print_summary
   use bench_single_items, only: geometry_section, tangential_section, full_case_section
   use bench_doe_items, only: doe_section
   use bench_moving_items, only: moving_section, defaults_section, scan_section
   use bench_report, only: print_load, stop_on, fail
   implicit none

   type(bench_config_type) :: config
   type(bench_case_type) :: bench
   type(summary_type) :: summary
   type(force_record_type) :: record

   call read_arguments(config)
   call load_case(config, bench)

   if (config%alloc_check > 0) then
      call allocation_run(config%alloc_check)
      stop
   end if

   call print_header(config, bench)
   if (config%wanted('geometry')) call geometry_section(config, bench)
   if (config%wanted('tangential')) call tangential_section(config, bench, summary, record)
   if (config%wanted('full')) call full_case_section(config, bench, summary)
   if (config%wanted('doe')) call doe_section(config, bench, summary, record)
   if (config%wanted('moving')) call moving_section(config, summary, record)
   if (config%wanted('defaults')) call defaults_section(config, bench)
   if (config%only == 'scan') call scan_section()
   if (len(config%only) == 0 .or. config%only == 'moving') call check_results(config, record, &
      bench%material%friction*bench%load)
   call print_summary(summary)
   call print_load('load at the end')

contains

   !> N full cases (solve_load with varying load, prepare_fastsim_sh, solve_prepared with the
   !> fields) and N DOE cases on one thread and on two. Run under valgrind with N and 2N: the
   !> heap allocation count must be the same.
   subroutine allocation_run(n)
      !> Cases.
      integer, intent(in) :: n
      type(full_case_kernel) :: full
      type(creepage_type), allocatable :: creepages(:)
      type(doe_table_type) :: table
      type(march_workspace_type) :: ws
      type(normal_patch_type) :: patch
      type(error_type), allocatable :: error
      integer :: k

      full%contact = bench%normal_contact(bench%normal_options%n_strips)
      full%load = bench%load
      full%material = bench%material
      full%options = bench%tangential_options
      full%options%fields = .true.
      full%creepage = bench%headline
      do k = 1, n
         call full%run(k)
      end do
      if (full%failed) call fail('alloc-check: '//full%message)
      patch = bench%normal_solution(bench%normal_options%n_strips, .false.)
      call prepare_fastsim_sh(ws, patch, bench%material, bench%tangential_options, error)
      call stop_on(error, 'alloc-check: prepare_fastsim_sh')
      creepages = bench%creepages()
      creepages = [(creepages(mod(k - 1, size(creepages)) + 1), k=1, n)]
      call reserve_table(table, n)
      call solve_doe(ws, creepages, table, 1)
      call solve_doe(ws, creepages, table, 2)
      if (any(table%status /= 0)) call fail('alloc-check: a DOE case failed')
      write (output_unit, '(a,i0,a,2es24.16)') 'alloc-check: ', n, ' cases; last forces ', &
         full%result%fx, table%fx(n)
   end subroutine allocation_run

end program shcontact_bench
