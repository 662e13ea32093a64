!> The command line of the shcontact program: commands, options, usage text.
module shcontact_app_cli
   use shcontact_core_error, only: error_type, fatal_error, stat_usage
   use shcontact_core_strings, only: str_int
   use shcontact_io_text, only: string_list_type
   use shcontact_case_sweep, only: max_threads
   implicit none
   private

   public :: cli_type, parse_command_line, usage_text

   !> What the command line asks for.
   type :: cli_type
      !> 'run', 'merge', 'profiles', 'geometry', 'help' or 'version'.
      character(len=:), allocatable :: command
      !> Case file ('' for the built-in default case).
      character(len=:), allocatable :: case_file
      !> -o/--output ('' when not given).
      character(len=:), allocatable :: output
      !> --set overrides, in order.
      type(string_list_type) :: sets
      !> merge: the input files.
      type(string_list_type) :: inputs
      !> profiles: --write DIR.
      character(len=:), allocatable :: write_dir
      !> Summary format: 'text', 'csv' or 'json'.
      character(len=:), allocatable :: format
      !> --check, --resume, -q, -v.
      logical :: check = .false., resume = .false., quiet = .false., verbose = .false.
      !> --threads (0: OpenMP default).
      integer :: threads = 0
      !> --shard I/N (0/0 when not given).
      integer :: shard = 0, n_shards = 0
   end type cli_type

contains

   !> The usage text of `shcontact --help`.
   function usage_text() result(text)
      character(len=:), allocatable :: text
      character(len=1), parameter :: nl = new_line('a')
      text = &
         'Usage:'//nl// &
         '  shcontact run [CASE.nml] [options]    solve the case (default: the built-in '// &
         'headline case)'//nl// &
         '  shcontact merge OUT.h5 SHARD.h5...    merge the shard files of one run'//nl// &
         '  shcontact profiles --write DIR        write the built-in profiles as 2-column files'// &
         nl// &
         '  shcontact geometry [CASE.nml] [-o FILE] [--set ...]'//nl// &
         '                                        write the strip geometry table of the case'// &
         nl// &
         '  shcontact --help | --version'//nl//nl// &
         'Options of run:'//nl// &
         '  -o, --output FILE        HDF5 output file (= --set output%file=FILE)'//nl// &
         '  --set GROUP%VAR=VALUE    override a namelist variable (repeatable; lists as '// &
         'v1,v2,...)'//nl// &
         '  --check                  validate, print the resolved namelist, solve nothing'//nl// &
         '  --format text|csv|json   summary on stdout: readable, CSV, or JSON lines'//nl// &
         '  -q, --quiet              no progress or notes on stderr (errors only)'//nl// &
         '  -v, --verbose            more notes on stderr'//nl// &
         '  --threads N              OpenMP threads (default: OMP_NUM_THREADS or all cores)'// &
         nl// &
         '  --shard I/N              solve the I-th of N slices of a sweep into '// &
         'OUT-shardIofN.h5'//nl// &
         '                           (default from SLURM_ARRAY_TASK_ID/_MIN/_COUNT)'//nl// &
         '  --resume                 complete an interrupted run from its checkpoint '// &
         'OUT.h5.partial/'//nl//nl// &
         'Exit status: 0 ok, 1 usage error, 2 invalid input, 3 I/O failure, 4 some sweep '// &
         'cases failed,'//nl// &
         '             5 numerical failure, 6 no contact (profiles do not touch)'
   end function usage_text

   !> Parse the command line.
   subroutine parse_command_line(cli, error)
      !> The request.
      type(cli_type), intent(out) :: cli
      !> stat_usage on a malformed command line.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: arg, value
      integer :: i, n
      logical :: has_value

      cli%case_file = ''
      cli%output = ''
      cli%write_dir = ''
      cli%format = 'text'
      n = command_argument_count()
      if (n == 0) then
         call fatal_error(error, 'no command given', stat_usage)
         return
      end if
      arg = argument(1)
      select case (arg)
      case ('-h', '--help', 'help')
         cli%command = 'help'
         return
      case ('-V', '--version', 'version')
         cli%command = 'version'
         return
      case ('run', 'merge', 'profiles', 'geometry')
         cli%command = arg
      case default
         call fatal_error(error, 'unknown command "'//arg//'"; expected run, merge, '// &
            'profiles, geometry, --help or --version', stat_usage)
         return
      end select

      i = 2
      do while (i <= n)
         arg = argument(i)
         call split_option(arg, value, has_value)
         select case (arg)
         case ('-h', '--help')
            cli%command = 'help'
            return
         case ('-o', '--output')
            call option_value(i, arg, value, has_value, error)
            cli%output = value
         case ('--set')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call cli%sets%push(value)
         case ('--format')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) then
               if (value /= 'text' .and. value /= 'csv' .and. value /= 'json') then
                  call fatal_error(error, '--format '//value//': expected text, csv or json', &
                     stat_usage)
               end if
               cli%format = value
            end if
         case ('--threads')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call read_count(value, '--threads', cli%threads, error)
            if (.not. allocated(error) .and. cli%threads > max_threads) call fatal_error(error, &
               '--threads '//value//': at most '//str_int(max_threads)//' threads are allowed', &
               stat_usage)
         case ('--shard')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call read_shard(value, cli%shard, cli%n_shards, error)
         case ('--write')
            call option_value(i, arg, value, has_value, error)
            cli%write_dir = value
         case ('--check')
            cli%check = .true.
         case ('--resume')
            cli%resume = .true.
         case ('-q', '--quiet')
            cli%quiet = .true.
         case ('-v', '--verbose')
            cli%verbose = .true.
         case default
            if (arg(1:1) == '-' .and. len(arg) > 1) then
               call fatal_error(error, 'unknown option "'//arg//'" for '//cli%command// &
                  '; see shcontact --help', stat_usage)
            else if (cli%command == 'merge') then
               call cli%inputs%push(arg)
            else if (len(cli%case_file) == 0 .and. (cli%command == 'run' .or. &
                     cli%command == 'geometry')) then
               cli%case_file = arg
            else
               call fatal_error(error, 'unexpected argument "'//arg//'" for '//cli%command// &
                  '; see shcontact --help', stat_usage)
            end if
         end select
         if (allocated(error)) return
         i = i + 1
      end do
      call check_combination(cli, error)
   end subroutine parse_command_line

   !> Options that belong to other commands, missing operands.
   subroutine check_combination(cli, error)
      type(cli_type), intent(inout) :: cli
      type(error_type), allocatable, intent(out) :: error
      select case (cli%command)
      case ('merge')
         if (cli%inputs%n < 2) then
            call fatal_error(error, 'merge needs the output file and at least one shard '// &
               'file: shcontact merge OUT.h5 SHARD.h5...', stat_usage)
         end if
      case ('profiles')
         if (len(cli%write_dir) == 0) call fatal_error(error, 'profiles needs --write DIR', &
            stat_usage)
      case ('run')
         if (len(cli%write_dir) > 0) call fatal_error(error, '--write belongs to the '// &
            'profiles command', stat_usage)
      end select
   end subroutine check_combination

   function argument(i) result(arg)
      integer, intent(in) :: i
      character(len=:), allocatable :: arg
      integer :: length
      call get_command_argument(i, length=length)
      allocate (character(len=length) :: arg)
      if (length > 0) call get_command_argument(i, arg)
   end function argument

   !> `--name=value` → `--name` and `value`.
   subroutine split_option(arg, value, has_value)
      character(len=:), allocatable, intent(inout) :: arg
      character(len=:), allocatable, intent(out) :: value
      logical, intent(out) :: has_value
      integer :: eq
      value = ''
      has_value = .false.
      if (len(arg) < 3) return
      if (arg(1:2) /= '--') return
      eq = index(arg, '=')
      if (eq == 0) return
      value = arg(eq + 1:)
      arg = arg(1:eq - 1)
      has_value = .true.
   end subroutine split_option

   !> The value of an option: after '=' or the next argument.
   subroutine option_value(i, name, value, has_value, error)
      integer, intent(inout) :: i
      character(len=*), intent(in) :: name
      character(len=:), allocatable, intent(inout) :: value
      logical, intent(in) :: has_value
      type(error_type), allocatable, intent(out) :: error
      if (.not. has_value) then
         if (i + 1 > command_argument_count()) then
            call fatal_error(error, name//' needs a value', stat_usage)
            return
         end if
         i = i + 1
         value = argument(i)
      end if
      if (len_trim(value) == 0) call fatal_error(error, name//' needs a value, not an '// &
         'empty text', stat_usage)
   end subroutine option_value

   subroutine read_count(text, name, value, error)
      character(len=*), intent(in) :: text, name
      integer, intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      read (text, *, iostat=stat) value
      if (stat /= 0 .or. verify(trim(text), '0123456789') /= 0 .or. value < 1) then
         value = 0
         call fatal_error(error, name//' '//text//': expected a positive integer', stat_usage)
      end if
   end subroutine read_count

   !> `I/N` with 1 ≤ I ≤ N.
   subroutine read_shard(text, shard, n_shards, error)
      character(len=*), intent(in) :: text
      integer, intent(out) :: shard, n_shards
      type(error_type), allocatable, intent(out) :: error
      integer :: slash
      shard = 0
      n_shards = 0
      slash = index(text, '/')
      if (slash > 1) then
         call read_count(text(1:slash - 1), '--shard', shard, error)
         if (.not. allocated(error)) call read_count(text(slash + 1:), '--shard', n_shards, error)
      end if
      if (slash <= 1 .or. allocated(error) .or. shard > n_shards) then
         if (allocated(error)) deallocate (error)
         call fatal_error(error, '--shard '//text//': expected I/N with 1 <= I <= N, e.g. '// &
            '--shard 2/'//str_int(max(2, n_shards)), stat_usage)
      end if
   end subroutine read_shard

end module shcontact_app_cli
