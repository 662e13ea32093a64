!> Profile files in: plain 2-column text, SIMPACK-style `.prr`/`.prw`, MiniProf `.ban`/`.whl`
!> (doc/theory.md §5.1, decision 3). [[read_profile]] returns the points in the canonical form of
!> [[profile_type]]: right side, y towards the field side, z downward, mm, rail points from the
!> track centre to the field side, wheel points from the field side to the flange back.
!> The points are not cleaned: pass them (with `line_of_point`) to `clean_profile`.
!>
!> Transformations, in this order (doc/profiles.md has the details and the reasons):
!>
!> | step | plain | SIMPACK | MiniProf |
!> |---|---|---|---|
!> | file-specific | — | `point.dist.min`, `shift.y/z`, `bound.y` (delete), `bound.z` (clip); `rotate` ≠ 0 rejected | `XOffset`, `YOffset` added |
!> | mirror y (y → −y) | no | `mirror.y` | rails (`.ban`): yes, the MiniProf X axis points to the track centre; wheels (`.whl`): no |
!> | mirror z (z → −z) | no | `mirror.z` | decided from the shape (MiniProf writers differ) |
!> | scale to mm | 1 | 1000 / `units.len.f` | 1 |
!> | order | reversed if needed | `inversion`, then reversed if needed | reversed if needed |
!>
!> The optional arguments `mirror_y`, `mirror_z` and `scale` replace what the file (or the
!> format's default) says. Without them two sanity checks guard against a wrong convention: a
!> profile that is clearly upside down (a rail whose interior lies below both ends, a wheel
!> whose interior rises above both ends more than the flange reaches below them) and a wheel
!> whose flange lies on the field-side half are rejected with a hint.
!>
!> Lines: ends LF, CRLF or CR; a UTF-8 byte-order mark is skipped; numbers are separated by
!> blanks, tabs, commas or semicolons; columns after the first two (y z) are ignored but must be
!> numbers. Every rejection names the file, the line and the reason.
module shcontact_profile_reader
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: lower => to_lower, str_int, str_real
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, stat_usage
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel, &
      option_hint
   use shcontact_profile_cleanup, only: is_finite_value, min_profile_points
   use shcontact_core_textfile, only: text_line => text_line_type, read_text_lines
   use shcontact_profile_file_lines, only: point_list, file_settings, kind_unknown, read_point, at, &
      check_cut_off
   use shcontact_profile_simpack, only: parse_simpack
   use shcontact_profile_miniprof, only: parse_miniprof
   implicit none
   private

   public :: read_profile, profile_format_names, profile_file_format

   !> Values of the `format` argument of [[read_profile]] (case-insensitive).
   character(len=*), parameter :: profile_format_names(4) = &
      [character(len=8) :: 'auto', 'plain', 'simpack', 'miniprof']

   integer, parameter :: format_plain = 1, format_simpack = 2, format_miniprof = 3
contains

   !> Read a wheel or rail profile file into the canonical form (module description).
   subroutine read_profile(filename, profile, error, format, kind, mirror_y, mirror_z, scale, &
         line_of_point, option_prefix)
      !> The file; also the profile's `source` and the start of every message.
      character(len=*), intent(in) :: filename
      !> The profile: y, z (mm), s, kink (all false), kind, source.
      type(profile_type), intent(out) :: profile
      !> stat_io when the file cannot be read, stat_invalid_input for bad contents,
      !> stat_usage for bad arguments.
      type(error_type), allocatable, intent(out) :: error
      !> 'auto' (default: .prr/.prw → simpack, .ban/.whl → miniprof, any case; else plain),
      !> 'plain', 'simpack' or 'miniprof'.
      character(len=*), intent(in), optional :: format
      !> profile_kind_rail or profile_kind_wheel; default from the file (SIMPACK `type`, a plain
      !> comment `# kind = wheel`) or its extension. Must agree with the file when it says.
      integer, intent(in), optional :: kind
      !> Mirror y (y → −y), replacing the file's setting and the format's default.
      logical, intent(in), optional :: mirror_y
      !> Mirror z (z → −z), replacing the file's setting and the format's default.
      logical, intent(in), optional :: mirror_z
      !> Factor from file units to mm, replacing the file's setting (SIMPACK `units.len.f`).
      real(wp), intent(in), optional :: scale
      !> File line of each returned point, for `clean_profile`'s messages.
      integer, allocatable, intent(out), optional :: line_of_point(:)
      !> How the caller names mirror_y, mirror_z and scale in messages, e.g. '&profiles wheel_'
      !> (default: these arguments' names).
      character(len=*), intent(in), optional :: option_prefix

      integer :: file_format, profile_kind
      type(text_line), allocatable :: lines(:)
      type(point_list) :: points
      type(file_settings) :: settings

      call resolve_format(filename, format, file_format, error)
      if (allocated(error)) return
      call check_arguments(filename, kind, scale, error)
      if (allocated(error)) return
      call read_text_lines(filename, 'profile file', lines, error)
      if (allocated(error)) return

      allocate (points%y(0), points%z(0), points%line(0))
      select case (file_format)
      case (format_simpack)
         call parse_simpack(filename, lines, points, settings, error)
      case (format_miniprof)
         call parse_miniprof(filename, lines, points, settings, error)
      case default
         call parse_plain(filename, lines, points, settings, error)
      end select
      if (allocated(error)) return

      if (points%n == 0) then
         call fatal_error(error, filename//': no profile points in the file', stat_invalid_input)
         return
      else if (points%n < min_profile_points) then
         call fatal_error(error, at(filename, points%line(points%n))//'the point list ends '// &
            'after '//str_int(points%n)//' profile point(s); a profile needs at least '// &
            str_int(min_profile_points), stat_invalid_input)
         return
      end if
      call resolve_kind(filename, file_format, kind, settings, profile_kind, error, option_prefix)
      if (allocated(error)) return
      call to_canonical(filename, profile_kind, settings, points, mirror_y, mirror_z, scale, &
         option_prefix, error)
      if (allocated(error)) return

      profile%source = filename
      profile%kind = profile_kind
      ! A MiniProf wheel has its origin at the flange back (module text).
      profile%origin_at_flange_back = file_format == format_miniprof .and. &
         profile_kind == profile_kind_wheel
      profile%y = points%y(:points%n)
      profile%z = points%z(:points%n)
      allocate (profile%kink(points%n), source=.false.)
      call profile%update_arc_length()
      if (present(line_of_point)) line_of_point = points%line(:points%n)
   end subroutine read_profile

   ! ---------------------------------------------------------------------------------------------
   ! Arguments, format, kind
   ! ---------------------------------------------------------------------------------------------

   !> The format [[read_profile]] reads `filename` in: 'plain', 'simpack' or 'miniprof' ('' for
   !> an unknown `format`). Callers use it for conventions that depend on the format (a
   !> MiniProf wheel has its origin at the flange back).
   pure function profile_file_format(filename, format) result(name)
      !> The file.
      character(len=*), intent(in) :: filename
      !> As the `format` argument of [[read_profile]] (default 'auto').
      character(len=*), intent(in), optional :: format
      character(len=:), allocatable :: name
      name = 'auto'
      if (present(format)) name = lower(trim(adjustl(format)))
      select case (name)
      case ('auto')
         select case (extension(filename))
         case ('prr', 'prw')
            name = 'simpack'
         case ('ban', 'whl')
            name = 'miniprof'
         case default
            name = 'plain'
         end select
      case ('plain', 'simpack', 'miniprof')
      case default
         name = ''
      end select
   end function profile_file_format

   subroutine resolve_format(filename, format, file_format, error)
      character(len=*), intent(in) :: filename
      character(len=*), intent(in), optional :: format
      integer, intent(out) :: file_format
      type(error_type), allocatable, intent(out) :: error

      select case (profile_file_format(filename, format))
      case ('plain')
         file_format = format_plain
      case ('simpack')
         file_format = format_simpack
      case ('miniprof')
         file_format = format_miniprof
      case default
         file_format = 0
         call fatal_error(error, filename//": unknown profile format '"//trim(format)// &
            "'; expected auto, plain, simpack or miniprof", stat_usage)
      end select
   end subroutine resolve_format

   subroutine check_arguments(filename, kind, scale, error)
      character(len=*), intent(in) :: filename
      integer, intent(in), optional :: kind
      real(wp), intent(in), optional :: scale
      type(error_type), allocatable, intent(out) :: error
      if (present(kind)) then
         if (kind /= profile_kind_rail .and. kind /= profile_kind_wheel) then
            call fatal_error(error, filename//': kind = '//str_int(kind)//' is neither '// &
               'profile_kind_rail ('//str_int(profile_kind_rail)//') nor profile_kind_wheel ('// &
               str_int(profile_kind_wheel)//')', stat_usage)
            return
         end if
      end if
      if (present(scale)) then
         if (.not. is_finite_value(scale)) then
            call fatal_error(error, filename//': the scale factor is not a finite number', &
               stat_usage)
         else if (scale <= 0.0_wp) then
            call fatal_error(error, filename//': scale = '//str_real(scale)// &
               ' must be positive (mirror with mirror_y/mirror_z)', stat_usage)
         end if
      end if
   end subroutine check_arguments

   !> Rail or wheel: the argument, else the file's own statement, else the extension; the file
   !> and the argument (or the extension) must not contradict each other.
   subroutine resolve_kind(filename, file_format, kind, settings, profile_kind, error, &
         option_prefix)
      character(len=*), intent(in) :: filename
      integer, intent(in) :: file_format
      integer, intent(in), optional :: kind
      type(file_settings), intent(in) :: settings
      integer, intent(out) :: profile_kind
      type(error_type), allocatable, intent(out) :: error
      !> How the caller's option names begin ('--': the command line's --kind is named).
      character(len=*), intent(in), optional :: option_prefix
      integer :: from_extension
      character(len=:), allocatable :: option

      from_extension = kind_unknown
      select case (extension(filename))
      case ('prr', 'ban')
         if (file_format /= format_plain) from_extension = profile_kind_rail
      case ('prw', 'whl')
         if (file_format /= format_plain) from_extension = profile_kind_wheel
      end select

      profile_kind = settings%kind
      if (present(kind)) then
         if (settings%kind /= kind_unknown .and. settings%kind /= kind) then
            call fatal_error(error, filename//', line '//str_int(settings%kind_line)// &
               ': the file describes a '//kind_name(settings%kind)//' profile, but a '// &
               kind_name(kind)//' profile was asked for', stat_invalid_input)
            return
         end if
         ! A file without a statement of its kind (MiniProf's) is read by the conventions of
         ! its extension (a .ban rail mirrored, a .whl wheel reversed): used as the other kind
         ! its points would be nonsense.
         if (settings%kind == kind_unknown .and. from_extension /= kind_unknown .and. &
             from_extension /= kind) then
            call fatal_error(error, filename//": the extension '."//extension(filename)// &
               "' stands for a "//kind_name(from_extension)//' profile (read by its '// &
               'conventions), but a '//kind_name(kind)//' profile was asked for: give a '// &
               kind_name(kind)//' profile file', stat_invalid_input)
            return
         end if
         profile_kind = kind
      else if (settings%kind /= kind_unknown) then
         if (from_extension /= kind_unknown .and. from_extension /= settings%kind) then
            call fatal_error(error, filename//', line '//str_int(settings%kind_line)// &
               ': the file describes a '//kind_name(settings%kind)//' profile, but its '// &
               "extension '."//extension(filename)//"' stands for a "// &
               kind_name(from_extension)//' profile', stat_invalid_input)
            return
         end if
      else
         profile_kind = from_extension
      end if
      if (profile_kind == kind_unknown) then
         option = 'the kind'
         if (present(option_prefix)) then
            if (option_prefix == '--') option = '--kind rail (or wheel)'
         end if
         call fatal_error(error, filename//': cannot tell whether this is a rail or a wheel '// &
            'profile: pass '//option//", or add a comment line '# kind = rail' (or wheel)", &
            stat_invalid_input)
      end if
   end subroutine resolve_kind

   ! ---------------------------------------------------------------------------------------------
   ! Transformations to the canonical form
   ! ---------------------------------------------------------------------------------------------

   subroutine to_canonical(filename, kind, settings, points, mirror_y, mirror_z, scale, &
         prefix, error)
      character(len=*), intent(in) :: filename
      character(len=*), intent(in), optional :: prefix
      integer, intent(in) :: kind
      type(file_settings), intent(in) :: settings
      type(point_list), intent(inout) :: points
      logical, intent(in), optional :: mirror_y, mirror_z
      real(wp), intent(in), optional :: scale
      type(error_type), allocatable, intent(out) :: error
      logical :: flip
      integer :: n, sense
      character(len=:), allocatable :: shape
      real(wp) :: factor

      n = points%n
      flip = settings%mirror_y .or. (settings%mirror_y_if_rail .and. kind == profile_kind_rail)
      if (present(mirror_y)) flip = mirror_y
      if (flip) points%y(:n) = -points%y(:n)

      if (present(mirror_z)) then
         if (mirror_z) points%z(:n) = -points%z(:n)
      else
         if (settings%mirror_z) points%z(:n) = -points%z(:n)
         sense = vertical_sense(kind, points%z(:n))
         if (settings%detect_z .and. sense < 0) then
            points%z(:n) = -points%z(:n)
         else if (sense < 0) then
            if (kind == profile_kind_rail) then
               shape = "a rail's crown lies above both ends"
            else
               shape = "a wheel's flange reaches below both ends"
            end if
            call fatal_error(error, filename//', lines '//str_int(points%line(1))//'–'// &
               str_int(points%line(n))//': the '//kind_name(kind)//' profile looks upside '// &
               'down (with z downward, '//shape//'); set '//option_hint(prefix, 'mirror_z', &
               'yes')//' to flip z, or '//option_hint(prefix, 'mirror_z', 'no')// &
               ' to keep it', stat_invalid_input)
            return
         end if
      end if

      factor = settings%scale
      if (present(scale)) factor = scale
      points%y(:n) = factor*points%y(:n)
      points%z(:n) = factor*points%z(:n)

      if (settings%invert) call reverse_points(points)
      if ((kind == profile_kind_wheel) .neqv. (points%y(1) > points%y(n))) then
         if (points%y(1) /= points%y(n)) call reverse_points(points)
      end if

      if (kind == profile_kind_wheel .and. .not. present(mirror_y)) then
         call check_flange_side(filename, points, prefix, error)
      end if
   end subroutine to_canonical

   !> +1 when z points downward, −1 when it points upward, 0 when the shape does not say.
   !> A rail's crown rises above both ends; a wheel's flange reaches below both ends. The
   !> larger of "rise" (min(z₁, zₙ) − min z) and "sink" (max z − max(z₁, zₙ)) decides.
   pure integer function vertical_sense(kind, z)
      integer, intent(in) :: kind
      real(wp), intent(in) :: z(:)
      real(wp) :: rise, sink
      integer :: n
      n = size(z)
      rise = min(z(1), z(n)) - minval(z)
      sink = maxval(z) - max(z(1), z(n))
      vertical_sense = 0
      if (rise > sink) vertical_sense = 1
      if (sink > rise) vertical_sense = -1
      if (kind == profile_kind_wheel) vertical_sense = -vertical_sense
   end function vertical_sense

   !> A right wheel's flange (its lowest point, largest z) lies on the track-centre side. A
   !> flat profile (every point at one height, a cylinder) has no lowest point: its shape does
   !> not decide, and it passes.
   subroutine check_flange_side(filename, points, prefix, error)
      character(len=*), intent(in) :: filename
      character(len=*), intent(in), optional :: prefix
      type(point_list), intent(in) :: points
      type(error_type), allocatable, intent(out) :: error
      !> Heights within this of each other are one height (mm).
      real(wp), parameter :: flat_tolerance = 1.0e-6_wp
      integer :: n, i
      real(wp) :: middle
      n = points%n
      if (maxval(points%z(:n)) - minval(points%z(:n)) <= flat_tolerance) return
      i = maxloc(points%z(:n), dim=1)
      middle = 0.5_wp*(minval(points%y(:n)) + maxval(points%y(:n)))
      if (points%y(i) <= middle) return
      call fatal_error(error, filename//', line '//str_int(points%line(i))//': the wheel''s '// &
         'lowest point (the flange) is at y = '//str_real(points%y(i))//' mm, on the field '// &
         'side of the profile''s middle y = '//str_real(middle)//' mm; a right-side profile has '// &
         'its flange towards the track centre (negative y): set '//option_hint(prefix, &
         'mirror_y', 'yes')//' to flip y, or '//option_hint(prefix, 'mirror_y', 'no')// &
         ' to keep it', stat_invalid_input)
   end subroutine check_flange_side

   pure subroutine reverse_points(points)
      type(point_list), intent(inout) :: points
      integer :: n
      n = points%n
      points%y(:n) = points%y(n:1:-1)
      points%z(:n) = points%z(n:1:-1)
      points%line(:n) = points%line(n:1:-1)
   end subroutine reverse_points

   ! ---------------------------------------------------------------------------------------------
   ! Plain 2-column files
   ! ---------------------------------------------------------------------------------------------

   !> `y z` per line; comments from `#`, `!` or `%` to the end of the line; a comment line
   !> `# kind = rail` or `# kind = wheel` (as the writer puts) tells the kind.
   subroutine parse_plain(filename, lines, points, settings, error)
      character(len=*), intent(in) :: filename
      type(text_line), intent(in) :: lines(:)
      type(point_list), intent(inout) :: points
      type(file_settings), intent(inout) :: settings
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      !> The three data lines before the current one, the closest last.
      type(text_line) :: before(3)
      integer :: il, cut, n_before

      n_before = 0
      do il = 1, size(lines)
         text = adjustl(lines(il)%text)
         if (len_trim(text) == 0) cycle
         if (scan(text(1:1), '#!%') == 1) then
            call read_kind_hint(filename, il, text(2:), settings, error)
            if (allocated(error)) return
            cycle
         end if
         cut = scan(text, '#!%')
         if (cut > 0) text = text(:cut - 1)
         if (.not. lines(il)%ended .and. cut == 0) then
            call check_cut_off(filename, il, text, before(1:n_before), error)
            if (allocated(error)) return
         end if
         call read_point(filename, il, text, 1, 2, points, error)
         if (allocated(error)) return
         if (n_before == size(before)) before(1:n_before - 1) = before(2:n_before)
         n_before = min(n_before + 1, size(before))
         before(n_before)%text = text
      end do
   end subroutine parse_plain

   subroutine read_kind_hint(filename, il, comment, settings, error)
      character(len=*), intent(in) :: filename, comment
      integer, intent(in) :: il
      type(file_settings), intent(inout) :: settings
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, value
      integer :: sep

      text = lower(trim(adjustl(comment)))
      if (len(text) < 4) return
      if (text(1:4) /= 'kind') return
      text = adjustl(text(5:))
      sep = scan(text, '=:')
      if (sep /= 1) return
      value = trim(adjustl(text(2:)))
      select case (value)
      case ('rail')
         settings%kind = profile_kind_rail
      case ('wheel')
         settings%kind = profile_kind_wheel
      case default
         call fatal_error(error, filename//', line '//str_int(il)//": kind '"//value// &
            "' is neither rail nor wheel", stat_invalid_input)
         return
      end select
      settings%kind_line = il
   end subroutine read_kind_hint

   ! ---------------------------------------------------------------------------------------------
   ! Small helpers
   ! ---------------------------------------------------------------------------------------------
   !> Lower-case extension after the last dot of the file name (not of a directory).
   pure function extension(filename) result(ext)
      character(len=*), intent(in) :: filename
      character(len=:), allocatable :: ext
      integer :: dot, slash
      dot = index(filename, '.', back=.true.)
      slash = scan(filename, '/\', back=.true.)
      ext = ''
      if (dot > slash .and. dot > 0) ext = lower(trim(filename(dot + 1:)))
   end function extension

   pure function kind_name(kind) result(text)
      integer, intent(in) :: kind
      character(len=:), allocatable :: text
      if (kind == profile_kind_wheel) then
         text = 'wheel'
      else
         text = 'rail'
      end if
   end function kind_name

end module shcontact_profile_reader
