!> SIMPACK profile files `.prr` (rail) and `.prw` (wheel) (shcontact_profile_reader; doc/profiles.md).
module shcontact_profile_simpack
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: lower => to_lower, str_real
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_profile_points, only: profile_kind_rail, profile_kind_wheel
   use shcontact_core_textfile, only: text_line => text_line_type
   use shcontact_profile_file_lines, only: point_list, file_settings, number_ok, read_point, &
      parse_real, at
   implicit none
   private

   public :: parse_simpack

   !> SIMPACK spline-section keys (doc/theory.md §5.1; CONTACT's reader).
   character(len=*), parameter :: simpack_spline_keys(20) = [character(len=14) :: &
      'approx.smooth', 'file', 'file.mtime', 'comment', 'type', 'point.dist.min', 'shift.y', &
      'shift.z', 'rotate', 'bound.y.min', 'bound.y.max', 'bound.z.min', 'bound.z.max', &
      'mirror.y', 'mirror.z', 'inversion', 'units.len', 'units.ang', 'units.len.f', &
      'units.ang.f']

   !> SIMPACK spline-section values (file units).
   type :: simpack_values
      real(wp) :: dist_min = 0.0_wp, shift(2) = 0.0_wp, rotate = 0.0_wp
      real(wp) :: bound_y(2) = [1.0_wp, 0.0_wp], bound_z(2) = [1.0_wp, 0.0_wp]
      real(wp) :: len_factor = 1000.0_wp
      integer :: rotate_line = 0
   end type simpack_values

contains

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

end module shcontact_profile_simpack
