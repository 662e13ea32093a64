!> Lines and numbers of a profile file (shcontact_profile_reader): the points as read, what the
!> file says about its conventions, one point per line with a message naming the file, the
!> line and what is expected, and a number parser that rejects what Fortran's list-directed read
!> would take silently.
module shcontact_profile_file_lines
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: lower => to_lower, str_int, replaced
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_textfile, only: text_line => text_line_type
   implicit none
   private

   public :: point_list, file_settings, kind_unknown, number_ok, read_point, numeric_line, &
      check_cut_off, &
      split_tokens, parse_real, at

   integer, parameter :: kind_unknown = -1

   !> Status of [[parse_real]].
   integer, parameter :: number_ok = 0, number_invalid = 1, number_nonfinite = 2, &
      number_too_large = 3
   !> Decimal exponent above which a number is rejected as out of range (reading it could
   !> overflow, which traps under -ffpe-trap=overflow).
   integer, parameter :: max_decimal_exponent = 300

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

contains

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

   !> A plain file cut off while it was written: its last line (`last`, line `il`) has no line
   !> end and its last number has fewer digits after the decimal point, or no exponent, where
   !> the same field on the data lines before it (`before`, the closest last), which all have
   !> the same number of fields, has the same form with more: `1.40107201288515E-002` cut to
   !> `1.401072` reads as 1.4 mm instead of 0.014 mm. Sign and integer digits do not count (a
   !> fixed-decimal file going from `10.1183` to `9.9187` is complete). Refused with a message
   !> that says how to accept a complete file. Needs two lines before.
   pure subroutine check_cut_off(filename, il, last, before, error)
      character(len=*), intent(in) :: filename, last
      integer, intent(in) :: il
      type(text_line), intent(in) :: before(:)
      type(error_type), allocatable, intent(out) :: error
      type(text_line), allocatable :: tokens(:), other(:)
      integer :: k, decimals, d
      logical :: exponent, e
      if (size(before) < 2) return
      tokens = split_tokens(last)
      if (size(tokens) < 2) return
      decimals = -1
      exponent = .false.
      do k = 1, size(before)
         other = split_tokens(before(k)%text)
         if (size(other) /= size(tokens)) return
         call number_form(other(size(other))%text, d, e)
         if (k == 1) then
            decimals = d
            exponent = e
         else if (d /= decimals .or. (e .neqv. exponent)) then
            return
         end if
      end do
      call number_form(tokens(size(tokens))%text, d, e)
      if (d >= decimals .and. (e .eqv. exponent)) return
      call fatal_error(error, at(filename, il)//"the file ends in the middle of a line: its "// &
         "last number '"//tokens(size(tokens))%text//"' has "//str_int(d)//" digit(s) after "// &
         "the decimal point"//trim(merge(' and no exponent', '                ', exponent .and. &
         .not. e))//", the lines before "//str_int(decimals)//trim(merge(' and an exponent', &
         '                ', exponent))//", and it has no line end, as in a file cut off "// &
         "while it was written; check the file (if it is complete, end its last line with a "// &
         "line break)", stat_invalid_input)
   contains
      !> Digits after the decimal point (0 without one) and whether an exponent follows.
      pure subroutine number_form(text, digits, has_exponent)
         character(len=*), intent(in) :: text
         integer, intent(out) :: digits
         logical, intent(out) :: has_exponent
         integer :: dot, mark
         mark = scan(text, 'eEdD')
         has_exponent = mark > 0
         if (mark == 0) mark = len(text) + 1
         dot = index(text(1:mark - 1), '.')
         digits = 0
         if (dot > 0) digits = verify(text(dot + 1:mark - 1)//'x', '0123456789') - 1
      end subroutine number_form
   end subroutine check_cut_off

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

   !> "file, line N: ".
   pure function at(filename, il) result(text)
      character(len=*), intent(in) :: filename
      integer, intent(in) :: il
      character(len=:), allocatable :: text
      text = filename//', line '//str_int(il)//': '
   end function at

end module shcontact_profile_file_lines
