!> The benchmark's command line (the options are listed in the header of
!> examples/bench/bench.f90) and the sizes its items are timed at.
module bench_config
   use shcontact, only: wp
   use bench_report, only: fail
   implicit none
   private

   public :: bench_config_type, read_arguments, sizes, n_bounds

   !> Strips (and elements) of the timed items.
   integer, parameter :: sizes(3) = [25, 50, 100]
   !> Tangential bounds timed (codes 1 to n_bounds).
   integer, parameter :: n_bounds = 5

   !> The options of the run.
   type :: bench_config_type
      !> Timed repetitions per item.
      integer :: runs = 15
      !> Repetitions of each DOE run.
      integer :: doe_runs = 5
      !> Target length of one timed batch (s).
      real(wp) :: batch_time = 0.01_wp
      !> Case file, DOE output file, --save-results and --compare-results files, --only section
      !> (empty: not given).
      character(len=:), allocatable :: case_file, output, save_file, compare_file, only
      !> Cases of the allocation check (0: no check).
      integer :: alloc_check = 0
   contains
      procedure :: wanted
   end type bench_config_type

contains

   !> Whether a section runs (all of them unless --only names one).
   logical function wanted(self, name)
      !> The options.
      class(bench_config_type), intent(in) :: self
      !> The section.
      character(len=*), intent(in) :: name
      wanted = len(self%only) == 0 .or. self%only == name
   end function wanted

   !> The options from the command line; stops on an unknown option or a bad value.
   subroutine read_arguments(config)
      !> The options (defaults where not given).
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
            call fail('unknown argument '//trim(arg)// &
               '; see the header of examples/bench/bench.f90')
         end select
         if (.not. flag .and. (stat /= 0 .or. i == n)) &
            call fail('bad or missing value for '//trim(arg))
         i = i + merge(1, 2, flag)
      end do
   end subroutine read_arguments

end module bench_config
