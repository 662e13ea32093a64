!> Namelist text split into assignments: case-file lines are tokenised, the group structure is
!> checked (groups opened with `&name`, closed with `/`, each at most once), and every
!> `name = value` becomes an [[assignment_type]] that remembers where it was written. A command
!> line override `group%var=value` becomes an assignment the same way.
module shcontact_input_config_parser
   use shcontact_core_error, only: error_type, fatal_error
   use shcontact_core_strings, only: to_lower, str_int, visible, control_characters
   use shcontact_core_textfile, only: text_line_type, read_text_lines
   use shcontact_core_buffer, only: text_buffer_type
   use shcontact_core_text, only: quote_string, strip_quotes
   use shcontact_input_config_limits, only: max_line_length
   use shcontact_input_config_variables, only: variables, group_names, find_variable, join_words, &
      k_string, k_string_list, k_choice
   implicit none
   private

   public :: assignment_type, assignment_list_type
   public :: read_lines, split_lines, parse_namelist, parse_override

   !> One `name = value` of a group, with where it came from.
   type :: assignment_type
      character(len=:), allocatable :: group, name, value, where
      integer :: n_items = 0
      integer :: longest_string = 0
   end type assignment_type

   !> Growable list of assignments.
   type :: assignment_list_type
      type(assignment_type), allocatable :: items(:)
      integer :: n = 0
   end type assignment_list_type

contains

   !> All lines of a case file (line ends and byte-order mark as shcontact_core_textfile).
   subroutine read_lines(filename, lines, error)
      character(len=*), intent(in) :: filename
      character(len=:), allocatable, intent(out) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      type(text_line_type), allocatable :: text(:)
      integer :: i, longest, col

      call read_text_lines(filename, 'case file', text, error)
      if (allocated(error)) return
      longest = 1
      do i = 1, size(text)
         col = scan(text(i)%text, control_characters)
         if (col > 0) then
            call fatal_error(error, filename//':'//str_int(i)//': a control character '// &
               visible(text(i)%text(col:col))//' in column '//str_int(col)// &
               '; a case file is text (is it the right file?)')
            return
         end if
         if (len(text(i)%text) > max_line_length) then
            call fatal_error(error, filename//':'//str_int(i)//': line longer than '// &
               str_int(max_line_length)//' characters')
            return
         end if
         longest = max(longest, len(text(i)%text))
      end do
      allocate (character(len=longest) :: lines(size(text)))
      do i = 1, size(text)
         lines(i) = text(i)%text
      end do
   end subroutine read_lines

   !> Split namelist text into group assignments, checking the structure (groups opened with
   !> `&name`, closed with `/`, nothing but comments outside groups, each group at most once).
   subroutine parse_namelist(lines, filename, list, error)
      character(len=*), intent(in) :: lines(:)
      character(len=*), intent(in) :: filename
      type(assignment_list_type), intent(inout) :: list
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: group, token, vname
      ! The value of the pending assignment, grown in linear time (long sweep lists).
      type(text_buffer_type) :: value
      character(len=12) :: seen(size(group_names))
      integer :: seen_line(size(group_names))
      integer :: il, pos, n, kind, vline, nseen, ig, n_items, longest, tok_items
      logical :: inside
      integer, parameter :: t_none = 0, t_word = 1, t_string = 2, t_equals = 3, t_comma = 4, &
         t_slash = 5, t_amp = 6

      inside = .false.
      nseen = 0
      group = ''
      vname = ''
      vline = 0
      n_items = 0
      longest = 0
      do il = 1, size(lines)
         pos = 1
         n = len_trim(lines(il))
         do
            call next_token(lines(il), pos, n, kind, token, error)
            if (allocated(error)) then
               error%message = line_ref(il)//': '//error%message
               return
            end if
            if (kind == t_none) exit
            if (.not. inside) then
               if (kind /= t_amp) then
                  call fatal_error(error, line_ref(il)//': "'//token//'" outside a group; a group '// &
                     'starts with &name and ends with /')
                  return
               end if
               group = to_lower(token)
               if (.not. any(group_names == group)) then
                  call fatal_error(error, line_ref(il)//': unknown group &'//group// &
                     '; the groups are '//join_words(group_names, '&', ''))
                  return
               end if
               do ig = 1, nseen
                  if (seen(ig) == group) then
                     call fatal_error(error, line_ref(il)//': group &'//group// &
                        ' appears twice (first at line '//str_int(seen_line(ig))// &
                        '); put all its variables in one group')
                     return
                  end if
               end do
               nseen = nseen + 1
               seen(nseen) = group
               seen_line(nseen) = il
               inside = .true.
               cycle
            end if
            select case (kind)
            case (t_slash)
               call finish(error)
               if (allocated(error)) return
               inside = .false.
            case (t_amp)
               if (to_lower(token) == 'end') then
                  call finish(error)
                  if (allocated(error)) return
                  inside = .false.
               else
                  call fatal_error(error, line_ref(il)//': group &'//group// &
                     ' is not closed with / before &'//token)
                  return
               end if
            case (t_equals)
               call fatal_error(error, line_ref(il)//': "=" without a variable name in &'//group)
               return
            case (t_word)
               if (starts_assignment(lines, il, pos)) then
                  call finish(error)
                  if (allocated(error)) return
                  vname = to_lower(token)
                  vline = il
                  call skip_equals(lines(il), pos)
               else
                  if (len(vname) == 0) then
                     call fatal_error(error, line_ref(il)//': "'//token//'" in &'//group// &
                        ' is not an assignment variable = value')
                     return
                  end if
                  call word_items(token, tok_items)
                  n_items = n_items + tok_items
                  call value%add(' '//token)
               end if
            case (t_string)
               if (len(vname) == 0) then
                  call fatal_error(error, line_ref(il)//': '//token//' in &'//group// &
                     ' is not an assignment variable = value')
                  return
               end if
               n_items = n_items + 1
               longest = max(longest, len(strip_quotes(token)))
               call value%add(' '//token)
            case (t_comma)
               call value%add(' ,')
            end select
         end do
      end do
      if (inside) then
         call fatal_error(error, filename//': group &'//group//' (line '// &
            str_int(seen_line(nseen))//') is not closed with /')
      end if

   contains

      function line_ref(line) result(w)
         integer, intent(in) :: line
         character(len=:), allocatable :: w
         w = filename//':'//str_int(line)
      end function line_ref

      !> Store the pending assignment, if any.
      subroutine finish(error)
         type(error_type), allocatable, intent(out) :: error
         type(assignment_type) :: a
         if (len(vname) == 0) return
         if (len_trim(value%text()) == 0) then
            call fatal_error(error, line_ref(vline)//': &'//group//' '//vname//' = has no value')
            return
         end if
         a%group = group
         a%name = vname
         a%value = trim(adjustl(value%text()))
         a%where = line_ref(vline)
         a%n_items = n_items
         a%longest_string = longest
         call push(list, a)
         vname = ''
         call value%clear()
         n_items = 0
         longest = 0
      end subroutine finish

      !> The next token of a line from `pos`: a word, a quoted string, '=', ',', '/' or '&name'.
      subroutine next_token(line, pos, n, kind, token, error)
         character(len=*), intent(in) :: line
         integer, intent(inout) :: pos
         integer, intent(in) :: n
         integer, intent(out) :: kind
         character(len=:), allocatable, intent(out) :: token
         type(error_type), allocatable, intent(out) :: error
         integer :: start

         kind = t_none
         token = ''
         do while (pos <= n)
            if (line(pos:pos) /= ' ' .and. iachar(line(pos:pos)) /= 9) exit
            pos = pos + 1
         end do
         if (pos > n) return
         select case (line(pos:pos))
         case ('!')
            pos = n + 1
            return
         case ('=')
            kind = t_equals
            pos = pos + 1
         case (',')
            kind = t_comma
            pos = pos + 1
         case ('/')
            kind = t_slash
            pos = pos + 1
         case ('&', '$')
            start = pos + 1
            pos = start
            do while (pos <= n)
               if (.not. is_name_char(line(pos:pos))) exit
               pos = pos + 1
            end do
            kind = t_amp
            token = line(start:pos - 1)
            if (len(token) == 0) call fatal_error(error, 'a group name must follow "&"')
         case ("'", '"')
            start = pos
            pos = closing_quote(line, start, n)
            if (pos > n) then
               call fatal_error(error, 'unterminated string '//line(start:n))
               return
            end if
            kind = t_string
            token = line(start:pos)
            pos = pos + 1
         case default
            start = pos
            do while (pos <= n)
               if (index(" =,/!'""&"//achar(9), line(pos:pos)) > 0) exit
               pos = pos + 1
            end do
            kind = t_word
            token = line(start:pos - 1)
         end select
      end subroutine next_token

   end subroutine parse_namelist

   !> True when the word just read is followed by '=' (possibly on the same line only).
   logical function starts_assignment(lines, il, pos)
      character(len=*), intent(in) :: lines(:)
      integer, intent(in) :: il, pos
      integer :: p, n
      n = len_trim(lines(il))
      p = pos
      do while (p <= n)
         if (lines(il)(p:p) /= ' ' .and. iachar(lines(il)(p:p)) /= 9) exit
         p = p + 1
      end do
      starts_assignment = .false.
      if (p <= n) starts_assignment = lines(il)(p:p) == '='
   end function starts_assignment

   !> Move past the '=' that follows a variable name.
   subroutine skip_equals(line, pos)
      character(len=*), intent(in) :: line
      integer, intent(inout) :: pos
      pos = index(line(pos:), '=') + pos
   end subroutine skip_equals

   pure logical function is_name_char(c)
      character(len=1), intent(in) :: c
      is_name_char = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. &
         (c >= '0' .and. c <= '9') .or. c == '_'
   end function is_name_char

   !> Number of values a bare word stands for: `r*v` is r values, anything else one.
   subroutine word_items(word, n)
      character(len=*), intent(in) :: word
      integer, intent(out) :: n
      integer :: istar, ios
      n = 1
      istar = index(word, '*')
      if (istar > 1) then
         read (word(1:istar - 1), *, iostat=ios) n
         if (ios /= 0 .or. n < 1) n = 1
      end if
   end subroutine word_items

   !> Count the values of a value text (for overrides) and the longest quoted string.
   subroutine count_items(value, n, longest)
      character(len=*), intent(in) :: value
      integer, intent(out) :: n, longest
      integer :: pos, start, k
      n = 0
      longest = 0
      pos = 1
      do while (pos <= len_trim(value))
         select case (value(pos:pos))
         case (' ', ',')
            pos = pos + 1
         case ("'", '"')
            start = pos
            pos = closing_quote(value, start, len(value))
            n = n + 1
            longest = max(longest, len(strip_quotes(value(start:min(pos, len(value))))))
            pos = pos + 1
         case default
            start = pos
            do while (pos <= len(value))
               if (value(pos:pos) == ' ' .or. value(pos:pos) == ',') exit
               pos = pos + 1
            end do
            call word_items(value(start:pos - 1), k)
            n = n + k
         end select
      end do
   end subroutine count_items

   !> Quote each comma-separated item of an override value that is not quoted yet.
   function quote_items(value) result(q)
      character(len=*), intent(in) :: value
      character(len=:), allocatable :: q
      integer :: start, comma
      character(len=:), allocatable :: item
      if (len(value) > 0) then
         if (value(1:1) == "'" .or. value(1:1) == '"') then
            q = value
            return
         end if
      end if
      q = ''
      start = 1
      do
         comma = index(value(start:), ',')
         if (comma == 0) then
            item = trim(adjustl(value(start:)))
         else
            item = trim(adjustl(value(start:start + comma - 2)))
         end if
         if (len(q) > 0) q = q//', '
         q = q//quote_string(item)
         if (comma == 0) exit
         start = start + comma
      end do
   end function quote_items

   subroutine push(list, a)
      type(assignment_list_type), intent(inout) :: list
      type(assignment_type), intent(in) :: a
      type(assignment_type), allocatable :: tmp(:)
      if (.not. allocated(list%items)) allocate (list%items(16))
      if (list%n == size(list%items)) then
         allocate (tmp(2*list%n))
         tmp(1:list%n) = list%items
         call move_alloc(tmp, list%items)
      end if
      list%n = list%n + 1
      list%items(list%n) = a
   end subroutine push

   !> Namelist text (lines separated by new-line characters) as an array of lines.
   subroutine split_lines(text, lines)
      !> The text.
      character(len=*), intent(in) :: text
      !> Its lines, padded to the longest.
      character(len=:), allocatable, intent(out) :: lines(:)
      integer :: i, n, start, next, longest

      n = 0
      longest = 1
      start = 1
      do while (start <= len(text))
         next = index(text(start:), new_line('a'))
         if (next == 0) next = len(text) - start + 2
         n = n + 1
         longest = max(longest, next - 1)
         start = start + next
      end do
      allocate (character(len=longest) :: lines(n))
      start = 1
      do i = 1, n
         next = index(text(start:), new_line('a'))
         if (next == 0) next = len(text) - start + 2
         lines(i) = text(start:start + next - 2)
         start = start + next
      end do
   end subroutine split_lines

   !> One override `group%var=value` as an assignment (string values may be given without
   !> quotes: they are quoted here).
   subroutine parse_override(text, a, error)
      !> The override, e.g. `creepage%nu_x=1e-3` or `sweep%bound=weighted,clipped`.
      character(len=*), intent(in) :: text
      !> The assignment, to be applied.
      type(assignment_type), intent(out) :: a
      !> Set when the text is malformed.
      type(error_type), allocatable, intent(out) :: error
      integer :: ipct, ieq, iv

      ipct = index(text, '%')
      ieq = index(text, '=')
      a%where = 'command line --set '//trim(text)
      if (ipct < 2 .or. ieq < ipct + 2) then
         call fatal_error(error, a%where//': expected group%variable=value, e.g. '// &
            'creepage%nu_x=1e-3')
         return
      end if
      a%group = to_lower(trim(adjustl(text(1:ipct - 1))))
      a%name = to_lower(trim(adjustl(text(ipct + 1:ieq - 1))))
      a%value = trim(adjustl(text(ieq + 1:)))
      if (len(a%value) == 0) then
         call fatal_error(error, a%where//': no value after "="; give one, e.g. '// &
            trim(text)//'VALUE (quote an empty text: '//trim(text)//"'')")
         return
      end if
      if (.not. any(group_names == a%group)) then
         call fatal_error(error, a%where//': unknown group "'//a%group//'"; the groups are '// &
            join_words(group_names, '', ''))
         return
      end if
      iv = find_variable(a%group, a%name)
      if (iv > 0) then
         if (variables(iv)%kind == k_string .or. variables(iv)%kind == k_choice) then
            if (index("'"//'"', a%value(1:min(1, len(a%value)))) == 0) &
               a%value = quote_string(a%value)
         else if (variables(iv)%kind == k_string_list) then
            a%value = quote_items(a%value)
         end if
      end if
      call count_items(a%value, a%n_items, a%longest_string)
   end subroutine parse_override

   !> Position of the quote that closes the string opening at `text(start:start)` (a doubled
   !> quote stands for one inside the string); beyond `n` when the string is not closed.
   pure integer function closing_quote(text, start, n) result(pos)
      !> The text.
      character(len=*), intent(in) :: text
      !> Position of the opening quote.
      integer, intent(in) :: start
      !> Last position to look at.
      integer, intent(in) :: n

      pos = start + 1
      do while (pos <= n)
         if (text(pos:pos) == text(start:start)) then
            if (pos < n) then
               if (text(pos + 1:pos + 1) == text(start:start)) then
                  pos = pos + 2
                  cycle
               end if
            end if
            return
         end if
         pos = pos + 1
      end do
   end function closing_quote

end module shcontact_input_config_parser
