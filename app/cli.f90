!> The command line of the shcontact program: commands, options, usage text.
module shcontact_app_cli
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_usage, stat_invalid_input
   use shcontact_core_strings, only: str_int, str_real, control_characters
   use shcontact_core_ranges, only: ranges, find_range
   use shcontact_core_text, only: string_list_type
   use shcontact, only: max_threads
   implicit none
   private

   public :: cli_type, parse_command_line, is_command

   !> What the command line asks for.
   type :: cli_type
      !> 'run', 'merge', 'profiles', 'geometry', 'help' or 'version'.
      character(len=:), allocatable :: command
      !> `COMMAND --help` (or `help COMMAND`): the help of that command.
      logical :: help = .false.
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
      !> profiles: the profile file to check ('' when not given), --plot SCRIPT ('' when not
      !> given), --kind ('' = from the file), --file-format.
      character(len=:), allocatable :: profile_file, plot_file, kind, file_format
      !> profiles: --mirror-y, --mirror-z ('yes', 'no'; '' = as the file or format says).
      character(len=:), allocatable :: mirror_y, mirror_z
      !> profiles: --scale (0: as the file says).
      real(wp) :: scale = 0.0_wp
      !> Summary format: 'text', 'csv', 'json' or 'none'.
      character(len=:), allocatable :: format
      !> --format was given (-q then keeps the summary on stdout).
      logical :: format_given = .false.
      !> --csv-units: a units line under the CSV header.
      logical :: csv_units = .false.
      !> --check, --resume, -q, -v.
      logical :: check = .false., resume = .false., quiet = .false., verbose = .false.
      !> --force: replace an output (or sidecar) that shcontact did not write (run, merge,
      !> profiles, geometry; shcontact_app_output_guard), start afresh in the work folder of an
      !> interrupted run (run).
      logical :: force = .false.
      !> --no-output: solve and print the summary, write no file.
      logical :: no_output = .false.
      !> --threads (0: OpenMP default).
      integer :: threads = 0
      !> --block-memory MB: results held in memory at once (0: the default).
      integer :: block_memory = 0
      !> --shard I/N (0/0 when not given).
      integer :: shard = 0, n_shards = 0
      !> --shard slurm: I/N from the Slurm job-array variables.
      logical :: shard_slurm = .false.
      !> geometry: --wheelset Y_MIN,Y_MAX,STEP (mm; wheelset_given when set) and --conicity
      !> AMPLITUDE[,...] (mm; empty when not given).
      real(wp) :: wheelset_range(3) = 0.0_wp
      logical :: wheelset_given = .false.
      real(wp), allocatable :: amplitudes(:)
   end type cli_type

contains

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
      cli%profile_file = ''
      cli%plot_file = ''
      cli%kind = ''
      cli%mirror_y = ''
      cli%mirror_z = ''
      cli%file_format = 'auto'
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
         ! `shcontact help run`: the help of run.
         if (n >= 2) then
            arg = argument(2)
            if (is_command(arg)) then
               cli%command = arg
               cli%help = .true.
            else
               call fatal_error(error, 'no help on "'//arg//'": expected one of the '// &
                  'commands run, merge, profiles, geometry', stat_usage)
            end if
         end if
         return
      case ('-V', '--version', 'version')
         cli%command = 'version'
         return
      case default
         if (.not. is_command(arg)) then
            call fatal_error(error, 'unknown command "'//arg//'"; expected run, merge, '// &
               'profiles, geometry, --help or --version', stat_usage)
            return
         end if
         cli%command = arg
      end select

      i = 2
      do while (i <= n)
         arg = argument(i)
         call split_option(arg, value, has_value)
         if (arg == '-h' .or. arg == '--help') then
            cli%help = .true.
            return
         end if
         if (arg(1:1) == '-' .and. len(arg) > 1) then
            if (.not. accepts(cli%command, arg)) then
               call fatal_error(error, unknown_option(cli%command, arg), stat_usage)
               return
            end if
         end if
         select case (arg)
         case ('-o', '--output')
            call option_value(i, arg, value, has_value, error)
            cli%output = value
         case ('--set')
            call option_value(i, arg, value, has_value, error)
            ! Refused here, before a value given after a space could be taken for the case
            ! file; with the status and words of an override read as a case-file line (an
            ! override without a group).
            if (.not. allocated(error) .and. index(value, '=') == 0) call fatal_error(error, &
               'command line --set '//value//': expected group%variable=value, e.g. '// &
               'creepage%nu_x=1e-3', stat_invalid_input)
            ! The override is read as a namelist line: a line break would be dropped on the
            ! way (output%file=$'a\nb.h5' wrote ab.h5), so it is refused here.
            if (.not. allocated(error) .and. scan(value, achar(10)//achar(13)) > 0) &
               call fatal_error(error, '--set "'//line_breaks_shown(value)//'": the value '// &
               'holds a line break; an override is one line', stat_invalid_input)
            if (.not. allocated(error)) call cli%sets%push(value)
         case ('--format')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) then
               if (all(value /= [character(len=4) :: 'text', 'csv', 'json', 'none'])) then
                  call fatal_error(error, '--format '//value//': expected text, csv, json or '// &
                     'none', stat_usage)
               end if
               cli%format = value
               cli%format_given = .true.
            end if
         case ('--csv-units')
            cli%csv_units = .true.
         case ('--threads')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call read_count(value, '--threads', cli%threads, error)
            if (.not. allocated(error) .and. cli%threads > max_threads) call fatal_error(error, &
               '--threads '//value//': at most '//str_int(max_threads)//' threads are allowed', &
               stat_usage)
         case ('--block-memory')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call read_count(value, '--block-memory', &
               cli%block_memory, error)
            if (.not. allocated(error) .and. cli%block_memory > 1048576) call fatal_error(error, &
               '--block-memory '//value//': expected at most 1048576 (MiB)', stat_usage)
         case ('--shard')
            call option_value(i, arg, value, has_value, error)
            if (allocated(error)) then
            else if (value == 'slurm') then
               cli%shard_slurm = .true.
               cli%shard = 0
               cli%n_shards = 0
            else
               cli%shard_slurm = .false.
               call read_shard(value, cli%shard, cli%n_shards, error)
            end if
         case ('--write')
            call option_value(i, arg, value, has_value, error)
            cli%write_dir = value
         case ('--plot')
            call option_value(i, arg, value, has_value, error)
            cli%plot_file = value
         case ('--kind')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) then
               if (value /= 'wheel' .and. value /= 'rail') call fatal_error(error, &
                  '--kind '//value//': expected wheel or rail', stat_usage)
               cli%kind = value
            end if
         case ('--mirror-y', '--mirror-z')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) then
               if (value /= 'yes' .and. value /= 'no') call fatal_error(error, &
                  arg//' '//value//': expected yes or no', stat_usage)
               if (arg == '--mirror-y') cli%mirror_y = value
               if (arg == '--mirror-z') cli%mirror_z = value
            end if
         case ('--file-format')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) then
               if (all(value /= [character(len=8) :: 'auto', 'plain', 'simpack', 'miniprof'])) &
                  call fatal_error(error, '--file-format '//value//': expected auto, plain, '// &
                  'simpack or miniprof', stat_usage)
               cli%file_format = value
            end if
         case ('--scale')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call read_positive(value, '--scale', cli%scale, error)
         case ('--wheelset', '--conicity')
            call option_value(i, arg, value, has_value, error)
            if (.not. allocated(error)) call wheelset_option(cli, arg, value, error)
         case ('--check')
            cli%check = .true.
         case ('--resume')
            cli%resume = .true.
         case ('--force')
            cli%force = .true.
         case ('--no-output')
            cli%no_output = .true.
         case ('-q', '--quiet')
            cli%quiet = .true.
         case ('-v', '--verbose')
            cli%verbose = .true.
         case default
            call operand(cli, arg, error)
         end select
         if (allocated(error)) return
         i = i + 1
      end do
      call check_combination(cli, error)
   end subroutine parse_command_line

   !> Whether `name` is one of the program's commands.
   pure logical function is_command(name)
      character(len=*), intent(in) :: name
      is_command = any(name == [character(len=8) :: 'run', 'merge', 'profiles', 'geometry'])
   end function is_command

   !> Whether `command` has the option `name` (a known option of another command is refused
   !> with a message naming the command it belongs to).
   pure logical function accepts(command, name)
      character(len=*), intent(in) :: command, name
      select case (name)
      case ('-q', '--quiet', '-v', '--verbose')
         accepts = .true.
      case ('-o', '--output')
         accepts = command /= 'merge'
      case ('--set')
         accepts = command == 'run' .or. command == 'geometry'
      case ('--format', '--csv-units', '--threads', '--shard', '--resume', '--check', &
            '--no-output', '--block-memory')
         accepts = command == 'run'
      case ('--force')
         accepts = command == 'run' .or. command == 'merge' .or. command == 'profiles' .or. &
            command == 'geometry'
      case ('--wheelset', '--conicity')
         accepts = command == 'geometry'
      case ('--write', '--plot', '--kind', '--file-format', '--scale', '--mirror-y', &
            '--mirror-z')
         accepts = command == 'profiles'
      case default
         accepts = .false.
      end select
   end function accepts

   function unknown_option(command, name) result(message)
      character(len=*), intent(in) :: command, name
      character(len=:), allocatable :: message
      character(len=*), parameter :: commands(4) = [character(len=8) :: 'run', 'merge', &
         'profiles', 'geometry']
      integer :: k
      do k = 1, size(commands)
         if (accepts(trim(commands(k)), name)) then
            message = 'option "'//name//'" belongs to '//owners(name)//', not to '//command// &
               '; see shcontact '//command//' --help'
            return
         end if
      end do
      message = 'unknown option "'//name//'" for '//command//'; '//nearest_option(command, name)// &
         'see shcontact '//command//' --help'
   end function unknown_option

   !> 'did you mean "--threads"? ' when one option of `command` begins with `name` or `name`
   !> with it (a word cut short or run on: "--thread", "--formats"), else ''.
   function nearest_option(command, name) result(text)
      character(len=*), intent(in) :: command, name
      character(len=:), allocatable :: text
      character(len=*), parameter :: options(20) = [character(len=14) :: '--quiet', &
         '--verbose', '--output', '--set', '--format', '--csv-units', '--threads', '--shard', &
         '--block-memory', &
         '--resume', '--check', '--no-output', '--write', '--plot', '--kind', '--file-format', &
         '--scale', '--mirror-y', '--mirror-z', '--help']
      integer :: k, n
      text = ''
      if (len(name) < 4) return
      do k = 1, size(options)
         n = len_trim(options(k))
         if (.not. accepts(command, options(k)(:n)) .and. options(k)(:n) /= '--help') cycle
         if (index(options(k)(:n), name) == 1 .or. index(name, options(k)(:n)) == 1) then
            text = 'did you mean "'//options(k)(:n)//'"? '
            return
         end if
      end do
   end function nearest_option

   !> The commands that have an option, as text ("run", "run and geometry").
   function owners(name) result(text)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      character(len=*), parameter :: commands(4) = [character(len=8) :: 'run', 'merge', &
         'profiles', 'geometry']
      integer :: k
      text = ''
      do k = 1, size(commands)
         if (.not. accepts(trim(commands(k)), name)) cycle
         if (len(text) > 0) text = text//' and '
         text = text//trim(commands(k))
      end do
   end function owners

   !> A word that is not an option: the case file, a merge input, the profile file.
   subroutine operand(cli, arg, error)
      type(cli_type), intent(inout) :: cli
      character(len=*), intent(in) :: arg
      type(error_type), allocatable, intent(out) :: error
      if (cli%command == 'merge') then
         call cli%inputs%push(arg)
      else if (len(cli%case_file) == 0 .and. (cli%command == 'run' .or. &
               cli%command == 'geometry')) then
         cli%case_file = arg
      else if (len(cli%profile_file) == 0 .and. cli%command == 'profiles') then
         cli%profile_file = arg
      else
         call fatal_error(error, 'unexpected argument "'//arg//'" for '//cli%command// &
            '; see shcontact '//cli%command//' --help', stat_usage)
      end if
   end subroutine operand

   !> Missing operands and options that exclude each other.
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
         if (len(cli%write_dir) == 0 .eqv. len(cli%profile_file) == 0) then
            call fatal_error(error, 'profiles needs a profile file or --write DIR (not both): '// &
               'shcontact profiles FILE [-o OUT] | shcontact profiles --write DIR', stat_usage)
         else if (len(cli%write_dir) > 0 .and. (len(cli%output) > 0 .or. &
                  len(cli%plot_file) > 0 .or. len(cli%kind) > 0 .or. cli%scale > 0.0_wp .or. &
                  cli%file_format /= 'auto' .or. len(cli%mirror_y) > 0 .or. &
                  len(cli%mirror_z) > 0)) then
            call fatal_error(error, '-o, --plot, --kind, --file-format, --scale and '// &
               '--mirror-y/z are options of "profiles FILE", not of "profiles --write DIR"', &
               stat_usage)
         end if
      case ('geometry')
         if ((cli%wheelset_given .or. allocated(cli%amplitudes)) .and. len(cli%output) > 0) &
            call fatal_error(error, '-o writes the strip geometry table; with --wheelset or '// &
            '--conicity the tables go to stdout (redirect them: > FILE)', stat_usage)
      case ('run')
         if (cli%csv_units .and. cli%format /= 'csv') call fatal_error(error, &
            '--csv-units needs --format csv', stat_usage)
         if (cli%no_output .and. (len(cli%output) > 0 .or. cli%resume)) call fatal_error(error, &
            '--no-output writes no file: it goes with neither -o nor --resume', stat_usage)
      end select
      if (allocated(error)) return
      if (cli%command == 'merge') then
         call check_output_name(cli%inputs%items(1)%text, 'merge OUT.h5', error)
      else if (cli%command == 'run') then
         call check_output_name(cli%output, '-o', error)
      end if
   end subroutine check_combination

   !> An output name without control characters (a newline in `-o` was dropped on the way
   !> and another file written).
   subroutine check_output_name(name, what, error)
      character(len=*), intent(in) :: name, what
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      k = scan(name, control_characters)
      if (k > 0) call fatal_error(error, what//' "'//name(1:k - 1)//'?'//name(k + 1:)// &
         '": the name holds a control character (byte '//str_int(iachar(name(k:k)))// &
         '); choose a name without one', stat_usage)
   end subroutine check_output_name

   !> The text with each line break (LF, CR) shown as '?'.
   pure function line_breaks_shown(text) result(shown)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: shown
      integer :: k
      shown = text
      do k = 1, len(text)
         if (text(k:k) == achar(10) .or. text(k:k) == achar(13)) shown(k:k) = '?'
      end do
   end function line_breaks_shown

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

   !> A positive finite real.
   subroutine read_positive(text, name, value, error)
      character(len=*), intent(in) :: text, name
      real(wp), intent(out) :: value
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      read (text, *, iostat=stat) value
      if (stat /= 0 .or. scan(text, ',/ ') > 0) value = -1.0_wp
      if (.not. (value > 0.0_wp .and. value <= huge(value))) then
         value = 0.0_wp
         call fatal_error(error, name//' '//text//': expected a positive number', stat_usage)
      end if
   end subroutine read_positive

   !> geometry --wheelset Y_MIN,Y_MAX,STEP (Y_MIN < Y_MAX, 0 < STEP) or --conicity A[,A...]
   !> (each A > 0).
   subroutine wheelset_option(cli, name, text, error)
      type(cli_type), intent(inout) :: cli
      character(len=*), intent(in) :: name, text
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: values(:)
      logical :: ok
      call read_real_list(text, values, ok)
      if (name == '--wheelset') then
         ok = ok .and. size(values) == 3
         if (ok) ok = values(1) < values(2) .and. values(3) > 0.0_wp .and. &
            values(3) <= values(2) - values(1) .and. (values(2) - values(1))/values(3) <= 1.0e5_wp
         if (.not. ok) then
            call fatal_error(error, '--wheelset '//text//': expected Y_MIN,Y_MAX,STEP in mm '// &
               'with Y_MIN < Y_MAX and 0 < STEP <= Y_MAX - Y_MIN (at most 100000 steps), '// &
               'e.g. --wheelset -10,10,0.5', stat_usage)
            return
         end if
         ! The lateral shifts the solver takes (&position t_y's range).
         associate (t_y => ranges(find_range('position%t_y')))
            if (values(1) < t_y%lo .or. values(2) > t_y%hi) then
               call fatal_error(error, '--wheelset '//text//': the shifts must lie within '// &
                  str_real(t_y%lo)//' ... '//str_real(t_y%hi)//' mm (the range of &position '// &
                  't_y)', stat_usage)
               return
            end if
         end associate
         cli%wheelset_range = values
         cli%wheelset_given = .true.
      else
         ! The amplitudes' shifts ±A within &position t_y's range, as --wheelset's.
         associate (t_y => ranges(find_range('position%t_y')))
            if (ok) ok = size(values) >= 1 .and. all(values > 0.0_wp .and. values <= &
               min(-t_y%lo, t_y%hi))
            if (.not. ok) then
               call fatal_error(error, '--conicity '//text//': expected amplitudes in mm '// &
                  '(0 < A <= '//str_real(min(-t_y%lo, t_y%hi))//', the range of &position '// &
                  't_y), separated by commas, e.g. --conicity 3 or --conicity 1,2,3,4,5', &
                  stat_usage)
               return
            end if
         end associate
         cli%amplitudes = values
      end if
   end subroutine wheelset_option

   !> Finite reals separated by commas ("1,2.5,-3"); ok = .false. on anything else.
   subroutine read_real_list(text, values, ok)
      character(len=*), intent(in) :: text
      real(wp), allocatable, intent(out) :: values(:)
      logical, intent(out) :: ok
      integer :: first, comma, stat
      real(wp) :: x
      allocate (values(0))
      ok = .false.
      first = 1
      do
         comma = index(text(first:), ',')
         if (comma == 0) then
            comma = len(text) + 1
         else
            comma = first + comma - 1
         end if
         if (comma == first .or. verify(text(first:comma - 1), '0123456789+-.eE') /= 0) return
         read (text(first:comma - 1), *, iostat=stat) x
         if (stat /= 0 .or. .not. abs(x) <= huge(x)) return
         values = [values, x]
         if (comma > len(text)) exit
         first = comma + 1
      end do
      ok = .true.
   end subroutine read_real_list

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
            '--shard 2/'//str_int(max(2, n_shards))//', or slurm', stat_usage)
      end if
   end subroutine read_shard

end module shcontact_app_cli
