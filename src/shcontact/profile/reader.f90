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
   use shcontact_core_strings, only: lower => to_lower, str_int, str_real, replaced
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, stat_usage
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel, &
      option_hint
   use shcontact_profile_cleanup, only: is_finite_value, min_profile_points
   use shcontact_core_textfile, only: text_line => text_line_type, read_text_lines
   implicit none
   private

   public :: read_profile, profile_format_names, profile_file_format

   !> Values of the `format` argument of [[read_profile]] (case-insensitive).
   character(len=*), parameter :: profile_format_names(4) = &
      [character(len=8) :: 'auto', 'plain', 'simpack', 'miniprof']

   integer, parameter :: format_plain = 1, format_simpack = 2, format_miniprof = 3
   integer, parameter :: kind_unknown = -1

   !> Status of [[parse_real]].
   integer, parameter :: number_ok = 0, number_invalid = 1, number_nonfinite = 2, &
      number_too_large = 3
   !> Decimal exponent above which a number is rejected as out of range (reading it could
   !> overflow, which traps under -ffpe-trap=overflow).
   integer, parameter :: max_decimal_exponent = 300

   !> SIMPACK spline-section keys (doc/theory.md §5.1; CONTACT's reader).
   character(len=*), parameter :: simpack_spline_keys(20) = [character(len=14) :: &
      'approx.smooth', 'file', 'file.mtime', 'comment', 'type', 'point.dist.min', 'shift.y', &
      'shift.z', 'rotate', 'bound.y.min', 'bound.y.max', 'bound.z.min', 'bound.z.max', &
      'mirror.y', 'mirror.z', 'inversion', 'units.len', 'units.ang', 'units.len.f', &
      'units.ang.f']

   !> Points as read, in file units, with the line each came from.
   type :: point_list
      integer :: n = 0
      real(wp), allocatable :: y(:), z(:)
      integer, allocatable :: line(:)
   end type point_list

   !> What the file (or its format's convention) says about the transformations.
   type :: file_settings
      !> Rail or wheel according to the file contents (SIMPACK `type`, plain `# kind =`).
      integer :: kind = kind_unknown
      !> Line that gave `kind`.
      integer :: kind_line = 0
      logical :: mirror_y = .false.
      !> MiniProf: mirror y when the profile is a rail.
      logical :: mirror_y_if_rail = .false.
      logical :: mirror_z = .false.
      !> MiniProf: decide the z sense from the shape.
      logical :: detect_z = .false.
      !> SIMPACK `inversion`.
      logical :: invert = .false.
      !> Factor from file units to mm.
      real(wp) :: scale = 1.0_wp
   end type file_settings

   !> SIMPACK spline-section values (file units).
   type :: simpack_values
      real(wp) :: dist_min = 0.0_wp, shift(2) = 0.0_wp, rotate = 0.0_wp
      real(wp) :: bound_y(2) = [1.0_wp, 0.0_wp], bound_z(2) = [1.0_wp, 0.0_wp]
      real(wp) :: len_factor = 1000.0_wp
      integer :: rotate_line = 0
   end type simpack_values

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
      call resolve_kind(filename, file_format, kind, settings, profile_kind, error)
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
   subroutine resolve_kind(filename, file_format, kind, settings, profile_kind, error)
      character(len=*), intent(in) :: filename
      integer, intent(in) :: file_format
      integer, intent(in), optional :: kind
      type(file_settings), intent(in) :: settings
      integer, intent(out) :: profile_kind
      type(error_type), allocatable, intent(out) :: error
      integer :: from_extension

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
         call fatal_error(error, filename//': cannot tell whether this is a rail or a wheel '// &
            "profile: pass kind, or add a comment line '# kind = rail' (or wheel)", &
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

   !> A right wheel's flange (its lowest point, largest z) lies on the track-centre side.
   subroutine check_flange_side(filename, points, prefix, error)
      character(len=*), intent(in) :: filename
      character(len=*), intent(in), optional :: prefix
      type(point_list), intent(in) :: points
      type(error_type), allocatable, intent(out) :: error
      integer :: n, i
      real(wp) :: middle
      n = points%n
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
      integer :: il, cut

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
         call read_point(filename, il, text, 1, 2, points, error)
         if (allocated(error)) return
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
   ! SIMPACK .prr / .prw
   ! ---------------------------------------------------------------------------------------------

   !> SIMPACK profile: `header.begin … header.end` (`version`, `type` 0 rail / 1 wheel), then
   !> `spline.begin … spline.end` with the processing keys and the point block
   !> `point.begin … point.end` (y z [weight]). Comments from `!` or `%` outside quotes.
   subroutine parse_simpack(filename, lines, points, settings, error)
      character(len=*), intent(in) :: filename
      type(text_line), intent(in) :: lines(:)
      type(point_list), intent(inout) :: points
      type(file_settings), intent(inout) :: settings
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: outside = 0, in_header = 1, in_spline = 2, in_points = 3, done = 4
      character(len=:), allocatable :: text, word
      type(simpack_values) :: values
      integer :: il, state, last
      logical :: has_points

      state = outside
      has_points = .false.
      last = 0
      do il = 1, size(lines)
         text = trim(adjustl(strip_simpack_comment(lines(il)%text)))
         if (len(text) == 0) cycle
         last = il
         word = lower(text)
         if (state == done) then
            call fatal_error(error, at(filename, il)//"unexpected text after 'spline.end': '"// &
               text//"'", stat_invalid_input)
            return
         end if
         select case (word)
         case ('header.begin')
            call enter(outside, in_header)
         case ('header.end')
            call enter(in_header, outside)
         case ('spline.begin')
            call enter(outside, in_spline)
         case ('spline.end')
            call enter(in_spline, done)
         case ('point.begin')
            call enter(in_spline, in_points)
            has_points = .true.
         case ('point.end')
            call enter(in_points, in_spline)
         case default
            if (state == in_points) then
               call read_point(filename, il, text, 1, 2, points, error)
            else if (state == in_header .or. state == in_spline) then
               call read_simpack_key(filename, il, text, state == in_header, settings, values, &
                  error)
            else
               call fatal_error(error, at(filename, il)//"expected 'header.begin' or "// &
                  "'spline.begin', found '"//text//"'", stat_invalid_input)
            end if
         end select
         if (allocated(error)) return
      end do

      if (state == outside) then
         call fatal_error(error, filename//': no spline section (spline.begin … spline.end); '// &
            'is this a SIMPACK profile?', stat_invalid_input)
         return
      else if (state /= done) then
         call fatal_error(error, at(filename, last)//'the file ends '//open_section(state), &
            stat_invalid_input)
         return
      end if
      if (.not. has_points) then
         call fatal_error(error, at(filename, last)//'no point block (point.begin … point.end)', &
            stat_invalid_input)
         return
      end if
      call apply_simpack_values(filename, values, points, settings, error)

   contains

      subroutine enter(expected, next)
         integer, intent(in) :: expected, next
         if (state /= expected) then
            call fatal_error(error, at(filename, il)//"'"//text//"' is out of place ("// &
               open_section(state)//'); SIMPACK files nest header.begin … header.end, then '// &
               'spline.begin … point.begin … point.end … spline.end', stat_invalid_input)
            return
         end if
         state = next
      end subroutine enter

   end subroutine parse_simpack

   !> Where a SIMPACK reader stands, in words.
   pure function open_section(state) result(text)
      integer, intent(in) :: state
      character(len=:), allocatable :: text
      select case (state)
      case (1)
         text = 'inside the header section, header.end missing'
      case (2)
         text = 'inside the spline section, spline.end missing'
      case (3)
         text = 'inside the point block, point.end missing'
      case (4)
         text = 'after spline.end'
      case default
         text = 'outside any section'
      end select
   end function open_section

   !> One `key = value` line of the header or spline section.
   subroutine read_simpack_key(filename, il, text, header, settings, values, error)
      character(len=*), intent(in) :: filename, text
      integer, intent(in) :: il
      logical, intent(in) :: header
      type(file_settings), intent(inout) :: settings
      type(simpack_values), intent(inout) :: values
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: key, value
      integer :: eq, i
      real(wp) :: x

      eq = index(text, '=')
      if (eq == 0) then
         call fatal_error(error, at(filename, il)//"expected 'key = value', found '"//text// &
            "'", stat_invalid_input)
         return
      end if
      key = lower(trim(adjustl(text(:eq - 1))))
      value = trim(adjustl(text(eq + 1:)))

      if (header) then
         select case (key)
         case ('version')
            call key_number(x)
         case ('type')
            call key_flag(i)
            if (allocated(error)) return
            settings%kind = merge(profile_kind_wheel, profile_kind_rail, i == 1)
            settings%kind_line = il
         case default
            call fatal_error(error, at(filename, il)//"unknown key '"//key//"' in the header "// &
               'section; the header keys are version and type', stat_invalid_input)
         end select
         return
      end if

      select case (key)
      case ('file', 'comment', 'units.len', 'units.ang')
         ! Descriptive strings; lengths and angles are scaled by units.len.f and units.ang.f.
      case ('approx.smooth', 'file.mtime', 'type')
         ! SIMPACK's own smoothing and the original data file: no effect on the points here.
         call key_number(x)
      case ('point.dist.min')
         call key_number(values%dist_min)
      case ('shift.y')
         call key_number(values%shift(1))
      case ('shift.z')
         call key_number(values%shift(2))
      case ('rotate')
         call key_number(values%rotate)
         values%rotate_line = il
      case ('bound.y.min')
         call key_number(values%bound_y(1))
      case ('bound.y.max')
         call key_number(values%bound_y(2))
      case ('bound.z.min')
         call key_number(values%bound_z(1))
      case ('bound.z.max')
         call key_number(values%bound_z(2))
      case ('mirror.y')
         call key_flag(i)
         settings%mirror_y = i == 1
      case ('mirror.z')
         call key_flag(i)
         settings%mirror_z = i == 1
      case ('inversion')
         call key_flag(i)
         settings%invert = i == 1
      case ('units.len.f')
         call key_number(values%len_factor)
         if (allocated(error)) return
         if (values%len_factor <= 0.0_wp) call fatal_error(error, at(filename, il)// &
            'units.len.f = '//value//' must be positive (length units per metre, 1000 for mm)', &
            stat_invalid_input)
      case ('units.ang.f')
         call key_number(x)
      case default
         call fatal_error(error, at(filename, il)//"unknown key '"//key//"' in the spline "// &
            'section; the known keys are '//key_list(), stat_invalid_input)
      end select

   contains

      subroutine key_number(number)
         real(wp), intent(inout) :: number
         integer :: stat
         call parse_real(value, number, stat)
         if (stat /= number_ok) call fatal_error(error, at(filename, il)//key//" = '"//value// &
            "' is not a finite number", stat_invalid_input)
      end subroutine key_number

      subroutine key_flag(flag)
         integer, intent(out) :: flag
         real(wp) :: number
         number = -1.0_wp
         call key_number(number)
         flag = -1
         if (allocated(error)) return
         if (number == 0.0_wp) flag = 0
         if (number == 1.0_wp) flag = 1
         if (flag < 0) call fatal_error(error, at(filename, il)//key//' = '//value// &
            ' must be 0 or 1', stat_invalid_input)
      end subroutine key_flag

   end subroutine read_simpack_key

   pure function key_list() result(text)
      character(len=:), allocatable :: text
      integer :: i
      text = trim(simpack_spline_keys(1))
      do i = 2, size(simpack_spline_keys)
         text = text//', '//trim(simpack_spline_keys(i))
      end do
   end function key_list

   !> SIMPACK processing steps 1–6 in file units (the numbers in the files' comments):
   !> minimum point distance, shift, rotation (rejected: its sense is not documented), y bounds
   !> (points outside deleted), z bounds (clipped); `min ≥ max` disables a bound.
   subroutine apply_simpack_values(filename, values, points, settings, error)
      character(len=*), intent(in) :: filename
      type(simpack_values), intent(in) :: values
      type(point_list), intent(inout) :: points
      type(file_settings), intent(inout) :: settings
      type(error_type), allocatable, intent(out) :: error
      logical :: keep(points%n)
      integer :: i, last

      if (values%rotate /= 0.0_wp) then
         call fatal_error(error, at(filename, values%rotate_line)//'rotate = '// &
            str_real(values%rotate)//' is not supported (rotate the points in the file, or '// &
            'set rotate = 0)', stat_invalid_input)
         return
      end if
      keep = .true.
      if (values%dist_min > 0.0_wp) then
         last = 1
         do i = 2, points%n
            keep(i) = hypot(points%y(i) - points%y(last), points%z(i) - points%z(last)) >= &
               values%dist_min
            if (keep(i)) last = i
         end do
      end if
      points%y(:points%n) = points%y(:points%n) + values%shift(1)
      points%z(:points%n) = points%z(:points%n) + values%shift(2)
      if (values%bound_y(1) < values%bound_y(2)) keep = keep .and. &
         points%y(:points%n) >= values%bound_y(1) .and. points%y(:points%n) <= values%bound_y(2)
      if (values%bound_z(1) < values%bound_z(2)) points%z(:points%n) = &
         min(max(points%z(:points%n), values%bound_z(1)), values%bound_z(2))
      call keep_points(points, keep)
      ! SIMPACK works in metres: l[user]/l[m] = units.len.f, so mm = 1000/units.len.f user units.
      settings%scale = 1000.0_wp/values%len_factor
   end subroutine apply_simpack_values

   pure subroutine keep_points(points, keep)
      type(point_list), intent(inout) :: points
      logical, intent(in) :: keep(:)
      integer :: m
      m = count(keep)
      points%y = pack(points%y(:points%n), keep)
      points%z = pack(points%z(:points%n), keep)
      points%line = pack(points%line(:points%n), keep)
      points%n = m
   end subroutine keep_points

   !> The line without its comment: from the first `!` or `%` that is not inside quotes.
   pure function strip_simpack_comment(line) result(text)
      character(len=*), intent(in) :: line
      character(len=:), allocatable :: text
      character(len=1) :: quote
      integer :: i
      quote = ' '
      do i = 1, len(line)
         if (quote /= ' ') then
            if (line(i:i) == quote) quote = ' '
         else if (line(i:i) == '''' .or. line(i:i) == '"') then
            quote = line(i:i)
         else if (line(i:i) == '!' .or. line(i:i) == '%') then
            text = line(:i - 1)
            return
         end if
      end do
      text = line
   end function strip_simpack_comment

   ! ---------------------------------------------------------------------------------------------
   ! MiniProf .ban / .whl
   ! ---------------------------------------------------------------------------------------------

   !> MiniProf: a header of `Key=Value` or free-text lines ends at the first blank line (or at
   !> the first line of two or more numbers), then one point per line. Lines starting with `"`,
   !> `#`, `!` or `%` are comments (MiniProf comments points out with `"`), and so is the rest of
   !> a line from such a character on (`-0.036 1.2   " zig-zag pattern`). An old-style line of
   !> header numbers followed by its label (`32.58 37.11 14.71` then `(Sd/Sh/qR)`) belongs to
   !> the header. Header keys used:
   !> `ColumnDef` (which columns hold X and Y, e.g. `X,Y,A,C`), `XOffset`, `YOffset` (mm, added
   !> to the columns); all other keys are instrument metadata and ignored.
   subroutine parse_miniprof(filename, lines, points, settings, error)
      character(len=*), intent(in) :: filename
      type(text_line), intent(in) :: lines(:)
      type(point_list), intent(inout) :: points
      type(file_settings), intent(inout) :: settings
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      integer :: il, col_x, col_y, first_data, declared, commented
      real(wp) :: offset(2)
      logical :: in_header, seen_header

      col_x = 1
      col_y = 2
      offset = 0.0_wp
      in_header = .true.
      seen_header = .false.
      first_data = 0
      declared = -1
      commented = 0
      do il = 1, size(lines)
         text = trim(adjustl(lines(il)%text))
         if (len(text) == 0) then
            if (seen_header) in_header = .false.
            cycle
         end if
         if (scan(text(1:1), '"#!%') == 1) then
            ! A point commented out in the point list (`" 43.70 38.51`) still counts in
            ! XYPoints, as MiniProf writes it.
            if (.not. in_header .or. first_data > 0) then
               if (numeric_line(trim(adjustl(text(2:))))) commented = commented + 1
            end if
            cycle
         end if
         ! A comment after a point: `-0.0986 -22.06   " zig-zag pattern`, `... % dent`.
         if (scan(text, '"#!%') > 0) text = trim(text(:scan(text, '"#!%') - 1))
         if (in_header) then
            if (.not. numeric_line(text) .or. header_numbers(lines, il)) then
               seen_header = .true.
               call read_miniprof_key(filename, il, text, col_x, col_y, offset, declared, &
                  error)
               if (allocated(error)) return
               cycle
            end if
            in_header = .false.
         end if
         if (first_data == 0) first_data = il
         if (index(text, '=') > 0) then
            call fatal_error(error, at(filename, il)//"header line '"//text//"' after the "// &
               'point list started (line '//str_int(first_data)//')', stat_invalid_input)
            return
         end if
         call read_point(filename, il, text, col_x, col_y, points, error)
         if (allocated(error)) return
      end do
      ! A file cut short in a transfer, or two lists pasted together, reads as a plausible
      ! shorter or longer profile: the header's count tells.
      if (declared >= 0 .and. points%n + commented /= declared) then
         call fatal_error(error, filename//': the header declares XYPoints='// &
            str_int(declared)//' but the point list holds '//str_int(points%n + commented)// &
            ' point(s) ('//str_int(points%n)//' read, '//str_int(commented)// &
            ' commented out): the file looks '//trim(merge('cut short   ', 'to hold more', &
            points%n + commented < declared))//'; expected as many points as declared', &
            stat_invalid_input)
         return
      end if
      points%y(:points%n) = points%y(:points%n) + offset(1)
      points%z(:points%n) = points%z(:points%n) + offset(2)
      settings%mirror_y_if_rail = .true.
      settings%detect_z = .true.
   end subroutine parse_miniprof

   !> An old-style MiniProf header line of numbers (`32.58 37.11 14.71`, flange height,
   !> thickness, qR) that is followed by its label line (`(Sd/Sh/qR)`) rather than by points.
   logical function header_numbers(lines, il)
      type(text_line), intent(in) :: lines(:)
      integer, intent(in) :: il
      character(len=:), allocatable :: next
      integer :: j
      header_numbers = .false.
      do j = il + 1, size(lines)
         next = trim(adjustl(lines(j)%text))
         if (len(next) == 0) return
         if (scan(next(1:1), '"#!%') == 1) cycle
         header_numbers = .not. numeric_line(next) .and. index(next, '=') == 0
         return
      end do
   end function header_numbers

   subroutine read_miniprof_key(filename, il, text, col_x, col_y, offset, declared, error)
      character(len=*), intent(in) :: filename, text
      integer, intent(in) :: il
      integer, intent(inout) :: col_x, col_y
      real(wp), intent(inout) :: offset(2)
      !> The header's `XYPoints` (left as it is when the line is another key or empty).
      integer, intent(inout) :: declared
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: key, value
      type(text_line), allocatable :: names(:)
      integer :: eq, i, stat

      eq = index(text, '=')
      if (eq == 0) return
      key = lower(trim(adjustl(text(:eq - 1))))
      value = trim(adjustl(text(eq + 1:)))
      select case (key)
      case ('columndef')
         names = split_tokens(value)
         col_x = 0
         col_y = 0
         do i = 1, size(names)
            if (lower(names(i)%text) == 'x') col_x = i
            if (lower(names(i)%text) == 'y') col_y = i
         end do
         if (col_x == 0 .or. col_y == 0) call fatal_error(error, at(filename, il)// &
            "ColumnDef = '"//value//"' has no X and Y columns", stat_invalid_input)
      case ('xypoints')
         if (len(value) == 0) return
         read (value, *, iostat=stat) declared
         if (stat /= 0 .or. verify(value, '0123456789') /= 0) then
            call fatal_error(error, at(filename, il)//"XYPoints = '"//value//"' is not a "// &
               'whole number of points', stat_invalid_input)
            return
         end if
      case ('xoffset', 'yoffset')
         if (len(value) == 0) return
         i = merge(1, 2, key == 'xoffset')
         call parse_real(value, offset(i), stat)
         if (stat /= number_ok) call fatal_error(error, at(filename, il)//trim(text(:eq - 1))// &
            " = '"//value//"' is not a finite number", stat_invalid_input)
      end select
   end subroutine read_miniprof_key

   ! ---------------------------------------------------------------------------------------------
   ! Lines and numbers
   ! ---------------------------------------------------------------------------------------------

   !> Append the point in columns col_y (lateral) and col_z (vertical) of a data line.
   subroutine read_point(filename, il, text, col_y, col_z, points, error)
      character(len=*), intent(in) :: filename, text
      integer, intent(in) :: il, col_y, col_z
      type(point_list), intent(inout) :: points
      type(error_type), allocatable, intent(out) :: error
      type(text_line), allocatable :: tokens(:)
      real(wp), allocatable :: values(:)
      integer :: i, stat, need

      if (decimal_commas(text)) then
         call fatal_error(error, at(filename, il)//"'"//trim(text)//"' looks like numbers "// &
            "with decimal commas (a comma inside each of its blank-separated numbers); "// &
            "write them with a decimal point: '"//replaced(trim(text), ',', '.')//"'", &
            stat_invalid_input)
         return
      end if
      tokens = split_tokens(text)
      need = max(col_y, col_z)
      allocate (values(size(tokens)))
      do i = 1, size(tokens)
         call parse_real(tokens(i)%text, values(i), stat)
         select case (stat)
         case (number_ok)
            cycle
         case (number_nonfinite)
            call fatal_error(error, at(filename, il)//"'"//tokens(i)%text// &
               "' is not a finite number", stat_invalid_input)
         case (number_too_large)
            call fatal_error(error, at(filename, il)//"'"//tokens(i)%text// &
               "' is out of range", stat_invalid_input)
         case default
            if (i <= need) then
               call fatal_error(error, at(filename, il)//expectation(col_y, col_z)// &
                  ", found '"//trim(text)//"'", stat_invalid_input)
            else
               call fatal_error(error, at(filename, il)//'column '//str_int(i)//" holds '"// &
                  tokens(i)%text//"', not a number (extra columns are allowed, but numeric)", &
                  stat_invalid_input)
            end if
         end select
         return
      end do
      if (size(tokens) < need) then
         call fatal_error(error, at(filename, il)//expectation(col_y, col_z)//", found '"// &
            trim(text)//"'", stat_invalid_input)
         return
      end if
      call push_point(points, values(col_y), values(col_z), il)
   end subroutine read_point

   !> A data line written with decimal commas (a German or French locale): no decimal point,
   !> at least two blank- or semicolon-separated fields, each holding exactly one comma with a
   !> digit on both sides (`61,3221 -22,1058`). Commas as separators (`61.3,-22.1`, `61,-22`)
   !> do not match.
   pure logical function decimal_commas(text)
      character(len=*), intent(in) :: text
      type(text_line), allocatable :: fields(:)
      integer :: i, c
      decimal_commas = .false.
      if (index(text, '.') > 0 .or. index(text, ',') == 0) return
      fields = split_tokens(text, separators=' ;')
      if (size(fields) < 2) return
      do i = 1, size(fields)
         associate (f => fields(i)%text)
            c = index(f, ',')
            if (c <= 1 .or. c == len(f) .or. index(f, ',', back=.true.) /= c) return
            if (scan(f(c - 1:c - 1), '0123456789') == 0 .or. &
                scan(f(c + 1:c + 1), '0123456789') == 0) return
         end associate
      end do
      decimal_commas = .true.
   end function decimal_commas

   pure function expectation(col_y, col_z) result(text)
      integer, intent(in) :: col_y, col_z
      character(len=:), allocatable :: text
      if (col_y == 1 .and. col_z == 2) then
         text = "expected two numbers 'y z'"
      else
         text = 'expected numbers with y in column '//str_int(col_y)//' and z in column '// &
            str_int(col_z)
      end if
   end function expectation

   pure subroutine push_point(points, y, z, line)
      type(point_list), intent(inout) :: points
      real(wp), intent(in) :: y, z
      integer, intent(in) :: line
      real(wp), allocatable :: ty(:), tz(:)
      integer, allocatable :: tl(:)
      integer :: capacity
      capacity = size(points%y)
      if (points%n == capacity) then
         capacity = max(64, 2*capacity)
         allocate (ty(capacity), tz(capacity), tl(capacity))
         ty(:points%n) = points%y(:points%n)
         tz(:points%n) = points%z(:points%n)
         tl(:points%n) = points%line(:points%n)
         call move_alloc(ty, points%y)
         call move_alloc(tz, points%z)
         call move_alloc(tl, points%line)
      end if
      points%n = points%n + 1
      points%y(points%n) = y
      points%z(points%n) = z
      points%line(points%n) = line
   end subroutine push_point

   !> Whether a line holds two or more tokens, all numbers.
   pure logical function numeric_line(text)
      character(len=*), intent(in) :: text
      type(text_line), allocatable :: tokens(:)
      real(wp) :: x
      integer :: i, stat
      tokens = split_tokens(text)
      numeric_line = size(tokens) >= 2
      do i = 1, size(tokens)
         if (.not. numeric_line) return
         call parse_real(tokens(i)%text, x, stat)
         numeric_line = stat == number_ok
      end do
   end function numeric_line

   !> Tokens separated by blanks, tabs, commas or semicolons (or by the characters of
   !> `separators` and tabs).
   pure function split_tokens(text, separators) result(tokens)
      character(len=*), intent(in) :: text
      character(len=*), intent(in), optional :: separators
      type(text_line), allocatable :: tokens(:)
      character(len=:), allocatable :: between
      integer :: i, start, n, pass
      logical :: inside
      between = ' ,;'//achar(9)
      if (present(separators)) between = separators//achar(9)
      do pass = 1, 2
         n = 0
         inside = .false.
         start = 1
         do i = 1, len(text) + 1
            if (i <= len(text)) then
               if (scan(text(i:i), between) == 0) then
                  if (.not. inside) start = i
                  inside = .true.
                  cycle
               end if
            end if
            if (inside) then
               n = n + 1
               if (pass == 2) tokens(n)%text = text(start:i - 1)
            end if
            inside = .false.
         end do
         if (pass == 1) allocate (tokens(n))
      end do
   end function split_tokens

   !> Parse a real number: [sign] digits [. digits] [e|d [sign] digits], at least one digit in
   !> the mantissa. NaN and Inf spellings are reported as non-finite, magnitudes beyond
   !> 10^300 as too large — both without ever producing the value.
   pure subroutine parse_real(token, value, stat)
      character(len=*), intent(in) :: token
      real(wp), intent(inout) :: value
      integer, intent(out) :: stat
      character(len=:), allocatable :: word
      integer :: i, n, int_digits, lead_zeros, exponent, exp_digits, ios, first
      logical :: seen_point, seen_nonzero

      word = lower(trim(adjustl(token)))
      n = len(word)
      stat = number_invalid
      if (n == 0) return
      first = 1
      if (scan(word(1:1), '+-') == 1) first = 2
      if (first <= n) then
         select case (word(first:))
         case ('nan', 'inf', 'infinity')
            stat = number_nonfinite
            return
         end select
         if (index(word(first:), 'nan(') == 1) then
            stat = number_nonfinite
            return
         end if
      end if

      int_digits = 0
      lead_zeros = 0
      seen_point = .false.
      seen_nonzero = .false.
      i = first
      do while (i <= n)
         if (word(i:i) == '.') then
            if (seen_point) return
            seen_point = .true.
         else if (verify(word(i:i), '0123456789') == 0) then
            if (word(i:i) /= '0') seen_nonzero = .true.
            if (.not. seen_point .and. seen_nonzero) int_digits = int_digits + 1
            if (seen_point .and. .not. seen_nonzero) lead_zeros = lead_zeros + 1
         else
            exit
         end if
         i = i + 1
      end do
      if (verify(word(first:i - 1), '.') == 0) return

      exponent = 0
      if (i <= n) then
         if (scan(word(i:i), 'ed') /= 1) return
         i = i + 1
         if (i <= n) then
            if (scan(word(i:i), '+-') == 1) i = i + 1
         end if
         if (i > n) return
         if (verify(word(i:), '0123456789') /= 0) return
         exp_digits = len(word(i:))
         if (exp_digits > 6) then
            stat = number_too_large
            return
         end if
         read (word(i:), *, iostat=ios) exponent
         if (ios /= 0) return
         if (word(i - 1:i - 1) == '-') exponent = -exponent
      end if
      if (seen_nonzero) then
         if (int_digits > 0) then
            if (int_digits - 1 + exponent > max_decimal_exponent) then
               stat = number_too_large
               return
            end if
         else if (-lead_zeros - 1 + exponent > max_decimal_exponent) then
            stat = number_too_large
            return
         end if
         if (exponent < -max_decimal_exponent) then
            value = 0.0_wp
            stat = number_ok
            return
         end if
      end if
      read (word, *, iostat=ios) value
      if (ios == 0) stat = number_ok
   end subroutine parse_real

   ! ---------------------------------------------------------------------------------------------
   ! Small helpers
   ! ---------------------------------------------------------------------------------------------

   !> "file, line N: ".
   pure function at(filename, il) result(text)
      character(len=*), intent(in) :: filename
      integer, intent(in) :: il
      character(len=:), allocatable :: text
      text = filename//', line '//str_int(il)//': '
   end function at

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
