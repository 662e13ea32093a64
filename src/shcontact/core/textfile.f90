!> Text input files read whole, as lines: the one place that decides what a line is, for the
!> case files and the profile files alike.
!>
!> Lines end with LF, CRLF or a lone CR (old Mac files, and the ends a fuzzer or a broken editor
!> leaves); a UTF-8 byte-order mark at the start is dropped; tabs become blanks. A directory is
!> refused with a message saying so (gfortran would open it and read nothing). Any readable
!> stream is read to its end (pipes, process substitutions, /dev/stdin); a NUL byte or more than
!> [[max_text_bytes]] bytes refuse it as not text (issue 24 item 1).
module shcontact_core_textfile
   use, intrinsic :: iso_c_binding, only: c_ptr, c_char, c_int, c_size_t, c_null_char, &
      c_associated
   use shcontact_core_error, only: error_type, fatal_error, stat_io, stat_invalid_input
   use shcontact_core_strings, only: str_int
   use shcontact_core_buffer, only: text_buffer_type
   implicit none
   private

   public :: text_line_type, read_text_lines, is_directory, max_text_bytes

   !> Largest text file read (case and profile files; a 2-million-point profile is ~80 MB).
   integer, parameter :: max_text_bytes = 256*1048576

   interface
      !> C's fopen (reads any stream: files, pipes, devices).
      function c_fopen(path, mode) bind(c, name='fopen') result(stream)
         import :: c_ptr, c_char
         character(kind=c_char), intent(in) :: path(*), mode(*)
         type(c_ptr) :: stream
      end function c_fopen
      !> C's fread.
      function c_fread(buffer, size, count, stream) bind(c, name='fread') result(got)
         import :: c_ptr, c_char, c_size_t
         character(kind=c_char), intent(out) :: buffer(*)
         integer(c_size_t), value :: size, count
         type(c_ptr), value :: stream
         integer(c_size_t) :: got
      end function c_fread
      !> C's ferror.
      function c_ferror(stream) bind(c, name='ferror') result(stat)
         import :: c_ptr, c_int
         type(c_ptr), value :: stream
         integer(c_int) :: stat
      end function c_ferror
      !> C's fclose.
      function c_fclose(stream) bind(c, name='fclose') result(stat)
         import :: c_ptr, c_int
         type(c_ptr), value :: stream
         integer(c_int) :: stat
      end function c_fclose
   end interface

   !> One line, without its end characters.
   type :: text_line_type
      !> The text (tabs as blanks).
      character(len=:), allocatable :: text
      !> False only for a file's last line that has no line end (a file cut off while it was
      !> written ends so; many complete files too).
      logical :: ended = .true.
   end type text_line_type

   !> The UTF-8 byte-order mark.
   character(len=*), parameter :: utf8_bom = char(239)//char(187)//char(191)

contains

   !> True when `path` names a directory.
   function is_directory(path) result(yes)
      !> The path.
      character(len=*), intent(in) :: path
      logical :: yes
      ! gfortran's inquire answers for `dir/.` only when dir is a directory.
      yes = .false.
      if (len_trim(path) == 0) return
      inquire (file=trim(path)//'/.', exist=yes)
   end function is_directory

   !> The lines of a text file. Messages start with `filename:` and call the file `what`
   !> (e.g. 'case file', 'profile file').
   subroutine read_text_lines(filename, what, lines, error)
      !> The file.
      character(len=*), intent(in) :: filename
      !> What the file is, for messages.
      character(len=*), intent(in) :: what
      !> Its lines.
      type(text_line_type), allocatable, intent(out) :: lines(:)
      !> stat_io when the file cannot be opened or read, or is a directory.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: buffer

      call read_bytes(filename, what, buffer, error)
      if (allocated(error)) return
      if (len(buffer) >= 3) then
         if (buffer(1:3) == utf8_bom) buffer = buffer(4:)
      end if
      call split_lines(buffer, lines)
   end subroutine read_text_lines

   !> The whole file as one string, read in chunks until its end, so that pipes, process
   !> substitutions and devices (`<(...)`, /dev/stdin) are read as well as plain files. A NUL
   !> byte or more than [[max_text_bytes]] refuse the file as not text (stat_invalid_input).
   subroutine read_bytes(filename, what, buffer, error)
      character(len=*), intent(in) :: filename, what
      character(len=:), allocatable, intent(out) :: buffer
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: chunk = 65536
      character(len=chunk) :: piece
      type(text_buffer_type) :: text
      type(c_ptr) :: stream
      integer :: got, nul

      buffer = ''
      if (is_directory(filename)) then
         call fatal_error(error, filename//': cannot read the '//what//': it is a directory', &
            stat_io)
         return
      end if
      stream = c_fopen(trim(filename)//c_null_char, 'rb'//c_null_char)
      if (.not. c_associated(stream)) then
         call open_error(filename, what, error)
         return
      end if
      do
         got = int(c_fread(piece, 1_c_size_t, int(chunk, c_size_t), stream))
         nul = index(piece(1:got), achar(0))
         if (nul > 0) then
            call fatal_error(error, filename//':'//str_int(line_of(text%text()// &
               piece(1:nul)))//': a NUL byte: the '//what//' must be text (is it the '// &
               'right file?)', stat_invalid_input)
            exit
         end if
         if (text%n + got > max_text_bytes) then
            call fatal_error(error, filename//': the '//what//' is larger than '// &
               str_int(max_text_bytes/1048576)//' MiB; expected a text '//what, &
               stat_invalid_input)
            exit
         end if
         call text%add(piece(1:got))
         if (got < chunk) exit
      end do
      if (.not. allocated(error) .and. c_ferror(stream) /= 0) call fatal_error(error, &
         filename//': cannot read the '//what//': read error', stat_io)
      if (c_fclose(stream) /= 0 .and. .not. allocated(error)) call fatal_error(error, &
         filename//': cannot read the '//what//': close failed', stat_io)
      if (.not. allocated(error)) buffer = text%text()
   end subroutine read_bytes

   !> Why a file cannot be opened, in the run-time library's words.
   subroutine open_error(filename, what, error)
      character(len=*), intent(in) :: filename, what
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: message
      integer :: unit, stat
      open (newunit=unit, file=filename, status='old', action='read', access='stream', &
         form='unformatted', iostat=stat, iomsg=message)
      if (stat == 0) then
         close (unit)
         message = 'the C library cannot open it'
      end if
      call fatal_error(error, filename//': cannot open the '//what//': '//trim(message), &
         stat_io)
   end subroutine open_error

   !> The line number of the last character of `text`.
   pure integer function line_of(text) result(line)
      character(len=*), intent(in) :: text
      integer :: i
      line = 1
      do i = 1, len(text) - 1
         if (is_line_end(text, i)) line = line + 1
      end do
   end function line_of

   !> Split at the line ends (module description).
   pure subroutine split_lines(buffer, lines)
      character(len=*), intent(in) :: buffer
      type(text_line_type), allocatable, intent(out) :: lines(:)
      integer :: i, start, n

      n = count_lines(buffer)
      allocate (lines(n))
      n = 0
      start = 1
      do i = 1, len(buffer)
         if (.not. is_line_end(buffer, i)) cycle
         n = n + 1
         lines(n)%text = line_text(buffer(start:i))
         start = i + 1
      end do
      if (start <= len(buffer)) then
         lines(n + 1)%text = line_text(buffer(start:))
         lines(n + 1)%ended = .false.
      end if
   end subroutine split_lines

   pure integer function count_lines(buffer) result(n)
      character(len=*), intent(in) :: buffer
      integer :: i
      n = 0
      do i = 1, len(buffer)
         if (is_line_end(buffer, i)) n = n + 1
      end do
      if (len(buffer) > 0) then
         if (.not. is_line_end(buffer, len(buffer))) n = n + 1
      end if
   end function count_lines

   !> Whether character i ends a line: a LF, or a CR not followed by a LF.
   pure logical function is_line_end(buffer, i)
      character(len=*), intent(in) :: buffer
      integer, intent(in) :: i
      is_line_end = buffer(i:i) == achar(10)
      if (buffer(i:i) == achar(13)) then
         is_line_end = .true.
         if (i < len(buffer)) is_line_end = buffer(i + 1:i + 1) /= achar(10)
      end if
   end function is_line_end

   !> A line without its end characters, tabs as blanks.
   pure function line_text(raw) result(text)
      character(len=*), intent(in) :: raw
      character(len=:), allocatable :: text
      integer :: i
      text = raw
      do i = 1, len(text)
         if (text(i:i) == achar(10) .or. text(i:i) == achar(13) .or. text(i:i) == achar(9)) &
            text(i:i) = ' '
      end do
   end function line_text

end module shcontact_core_textfile
