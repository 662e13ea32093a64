!> MiniProf profile files `.ban` (rail) and `.whl` (wheel) (shcontact_profile_reader; doc/profiles.md).
module shcontact_profile_miniprof
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: lower => to_lower, str_int
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_textfile, only: text_line => text_line_type
   use shcontact_profile_file_lines, only: point_list, file_settings, number_ok, read_point, &
      numeric_line, split_tokens, parse_real, at
   implicit none
   private

   public :: parse_miniprof

contains

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

end module shcontact_profile_miniprof
