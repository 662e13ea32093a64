!> Text input files read whole, as lines: the one place that decides what a line is, for the
!> case files and the profile files alike.
!>
!> Lines end with LF, CRLF or a lone CR (old Mac files, and the ends a fuzzer or a broken editor
!> leaves); a UTF-8 byte-order mark at the start is dropped; tabs become blanks. A directory is
!> refused with a message saying so (gfortran would open it and read nothing).
module shcontact_core_textfile
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   implicit none
   private

   public :: text_line_type, read_text_lines, is_directory

   !> One line, without its end characters.
   type :: text_line_type
      !> The text (tabs as blanks).
      character(len=:), allocatable :: text
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

   !> The whole file as one string.
   subroutine read_bytes(filename, what, buffer, error)
      character(len=*), intent(in) :: filename, what
      character(len=:), allocatable, intent(out) :: buffer
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: message
      integer :: unit, stat, nbytes

      if (is_directory(filename)) then
         call fatal_error(error, filename//': cannot read the '//what//': it is a directory', &
            stat_io)
         return
      end if
      open (newunit=unit, file=filename, status='old', action='read', access='stream', &
         form='unformatted', iostat=stat, iomsg=message)
      if (stat /= 0) then
         call fatal_error(error, filename//': cannot open the '//what//': '//trim(message), &
            stat_io)
         return
      end if
      inquire (unit=unit, size=nbytes)
      allocate (character(len=max(nbytes, 0)) :: buffer)
      stat = 0
      if (nbytes > 0) read (unit, iostat=stat, iomsg=message) buffer
      close (unit)
      if (stat /= 0 .or. nbytes < 0) then
         if (nbytes < 0) message = 'cannot tell its size'
         call fatal_error(error, filename//': cannot read the '//what//': '//trim(message), &
            stat_io)
      end if
   end subroutine read_bytes

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
      if (start <= len(buffer)) lines(n + 1)%text = line_text(buffer(start:))
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
