!> The benchmark's case: the app's case file read and prepared once (shcontact_input_config,
!> shcontact_case_runner), the single case of the items (the first point of the sweep with the
!> file's creepages) and its normal problem at a given number of strips; and the header of the
!> output, which describes the machine and the case.
module bench_case
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options, output_unit
   use omp_lib, only: omp_get_num_procs, omp_get_max_threads
   use shcontact, only: wp, error_type, material_type, wheelset_position_type, &
      find_contact_patches, patch_geometry_type, normal_options_type, normal_contact_type, &
      prepare_normal_contact, solve_load, normal_patch_type, tangential_options_type, &
      creepage_type, bound_name, spin_model_name, shcontact_version
   use shcontact_normal_options, only: method_hertz
   use shcontact_input_config, only: case_config_type, case_point_type, load_config, axis_load, &
      load_mode_force
   use shcontact_case_runner, only: run_setup_type, prepare_run
   use shcontact_core_strings, only: str_int
   use bench_timing, only: wall_time
   use bench_config, only: bench_config_type
   use bench_report, only: real_text, print_load, cpu_model, stop_on, fail
   implicit none
   private

   public :: bench_case_type, load_case, print_header

   !> The case of the run, set up once.
   type :: bench_case_type
      !> The case file as read.
      type(case_config_type) :: case_config
      !> Profiles read, smoothed and sampled; the case's material and options.
      type(run_setup_type) :: setup
      !> The first point of the sweep.
      type(case_point_type) :: point
      !> The material with the point's friction.
      type(material_type) :: material
      !> The wheelset position of the point.
      type(wheelset_position_type) :: position
      !> The case's normal options.
      type(normal_options_type) :: normal_options
      !> The case's tangential options with the point's bound and spin model, no fields.
      type(tangential_options_type) :: tangential_options
      !> The creepages of the single-case items.
      type(creepage_type) :: headline
      !> The contact patches at the position.
      type(patch_geometry_type), allocatable :: patches(:)
      !> Normal force of the point (N).
      real(wp) :: load = 0.0_wp
      !> Wall time of prepare_run (s).
      real(wp) :: setup_time = 0.0_wp
   contains
      procedure :: normal_contact
      procedure :: normal_solution
      procedure :: creepages
   end type bench_case_type

contains

   !> Read the case file (the DOE's output redirected to --output), prepare the run (timed) and
   !> find the contact patches of the single case.
   subroutine load_case(config, bench)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(out) :: bench
      type(error_type), allocatable :: error
      real(wp) :: t0

      call load_config(config%case_file, [character(len=len(config%output) + 12) :: &
         'output%file='//config%output], bench%case_config, error)
      call stop_on(error, config%case_file)
      t0 = wall_time()
      call prepare_run(bench%case_config, bench%setup, error)
      bench%setup_time = wall_time() - t0
      call stop_on(error, 'prepare_run')
      call case_of_run(config%case_file, bench)
      call find_contact_patches(bench%setup%prepared, bench%position, bench%patches, error)
      call stop_on(error, 'find_contact_patches')
   end subroutine load_case

   !> The single case of the run: the first point of its sweep with the case file's creepages;
   !> the run must keep the geometry and the load (a DOE over tangential inputs only).
   subroutine case_of_run(case_file, bench)
      !> The case file (for the messages).
      character(len=*), intent(in) :: case_file
      !> The case (read and prepared).
      type(bench_case_type), intent(inout) :: bench
      type(error_type), allocatable :: error
      integer :: k

      associate (case_config => bench%case_config, setup => bench%setup)
         if (case_config%load%mode /= load_mode_force) call fail(case_file// &
            ": the benchmark needs load%mode = 'force'")
         bench%point = case_config%case_point(1)
         do k = 2, case_config%n_cases()
            if (case_config%shares_with(k, axis_load) /= 1) call fail(case_file// &
               ': the sweep must vary the tangential inputs only (one normal patch)')
         end do
         bench%position = setup%position
         bench%position%y_ws = bench%point%t_y
         bench%position%roll = bench%point%roll
         bench%load = bench%point%normal_force
         bench%material = setup%material
         bench%material%friction = bench%point%friction
         bench%normal_options = setup%normal
         bench%tangential_options = setup%tangential
         bench%tangential_options%bound = bench%point%bound
         bench%tangential_options%spin_model = bench%point%spin_model
         bench%tangential_options%fields = .false.
         bench%headline = creepage_type(case_config%creepage%nu_x, &
            case_config%creepage%nu_y, case_config%creepage%phi)
      end associate
   end subroutine case_of_run

   !> The case's patch prepared for the strip method (or the Hertz method) with n strips.
   function normal_contact(self, n, hertz, reduction) result(contact)
      !> The case.
      class(bench_case_type), intent(in) :: self
      !> Strips.
      integer, intent(in) :: n
      !> The Hertz method instead of the case's (default: false).
      logical, intent(in), optional :: hertz
      !> Normal reduction code (default: the case's).
      integer, intent(in), optional :: reduction
      type(normal_contact_type) :: contact
      type(normal_options_type) :: options
      type(error_type), allocatable :: error

      options = self%normal_options
      options%n_strips = n
      if (present(hertz)) then
         if (hertz) options%method = method_hertz
      end if
      if (present(reduction)) options%reduction = reduction
      call prepare_normal_contact(contact, self%patches(1), options, self%material, error)
      call stop_on(error, 'prepare_normal_contact')
   end function normal_contact

   !> The normal solution at the case load with n strips: semi-Hertz or the Hertz ellipse.
   function normal_solution(self, n, hertz) result(patch)
      !> The case.
      class(bench_case_type), intent(in) :: self
      !> Strips.
      integer, intent(in) :: n
      !> The Hertz ellipse instead of the case's method.
      logical, intent(in) :: hertz
      type(normal_patch_type) :: patch
      type(normal_contact_type) :: contact
      type(error_type), allocatable :: error

      contact = self%normal_contact(n, hertz)
      call solve_load(contact, self%load, patch, error)
      call stop_on(error, 'normal solution')
   end function normal_solution

   !> The creepages of the run's cases.
   function creepages(self)
      !> The case.
      class(bench_case_type), intent(in) :: self
      type(creepage_type), allocatable :: creepages(:)
      type(case_point_type) :: p
      integer :: k
      allocate (creepages(self%case_config%n_cases()))
      do k = 1, size(creepages)
         p = self%case_config%case_point(k)
         creepages(k) = creepage_type(p%nu_x, p%nu_y, p%phi)
      end do
   end function creepages

   !> The machine, the compiler, the load, the case and the timing of the run.
   subroutine print_header(config, bench)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(in) :: bench
      character(len=256) :: model
      write (output_unit, '(a)') 'shcontact-bench, shcontact '//shcontact_version
      call cpu_model(model)
      write (output_unit, '(a,i0,a,i0)') 'machine: '//trim(model)//'; logical CPUs: ', &
         omp_get_num_procs(), '; OpenMP max threads: ', omp_get_max_threads()
      write (output_unit, '(a)') 'compiler: '//compiler_version()
      write (output_unit, '(a)') 'flags: '//compiler_options()
      call print_load('load at the start')
      write (output_unit, '(a)') 'case: '//config%case_file//': '// &
         trim(bench%case_config%profiles%wheel)//' on '// &
         trim(bench%case_config%profiles%rail)//', t_y = '//real_text(bench%point%t_y)// &
         ' mm, Fn = '//real_text(bench%load)//' N, mu = '// &
         real_text(bench%material%friction)//', '//str_int(bench%normal_options%n_strips)// &
         ' strips x '//str_int(bench%tangential_options%n_elements)//' elements, bound '// &
         bound_name(bench%tangential_options%bound)//', spin model '// &
         spin_model_name(bench%point%spin_model)
      write (output_unit, '(a)') 'single-case creepages: nu_x = '// &
         real_text(bench%headline%nu_x)//', nu_y = '//real_text(bench%headline%nu_y)// &
         ', phi = '//real_text(bench%headline%phi)//' rad/mm'
      write (output_unit, '(a,i0,a,es9.2,a)') 'each item: ', config%runs, &
         ' timed batches of about ', config%batch_time, ' s; time per call in microseconds'
      write (output_unit, '(a,f8.2,a)') 'profiles read, smoothed and sampled (prepare_run, '// &
         'once per run, one run): ', 1.0e3_wp*bench%setup_time, ' ms'
   end subroutine print_header

end module bench_case
