!> Comma-separated tables for the validation program: read the exact-theory reference files
!> (`../shared/reference/`, README §3) and write the comparison tables of doc/validation/.
!>
!> Reading keeps every cell as text (the reference files mix names and numbers; `summary.csv` has
!> quoted notes with commas); [[column]] converts one column to reals on request.
module validate_csv
   use shcontact, only: wp, error_type, fatal_error, stat_io, stat_invalid_input
   implicit none
   private

   public :: csv_table_type, read_csv, column, column_index, summary_value
   public :: csv_writer_type

   !> Longest cell kept (longer cells are cut; the reference files stay far below).
   integer, parameter :: cell_len = 48
   !> Longest line read.
   integer, parameter :: line_len = 4096

   !> A table read from a CSV file with one header line.
   type :: csv_table_type
      !> The file it came from (for messages).
      character(len=:), allocatable :: source
      !> Column names from the header.
      character(len=cell_len), allocatable :: names(:)
      !> cells(row, col) as text.
      character(len=cell_len), allocatable :: cells(:, :)
   contains
      !> Number of data rows.
      procedure :: rows
   end type csv_table_type

   !> A CSV file being written: a header, then rows of numbers (and optional leading text cells).
   type :: csv_writer_type
      integer :: unit = -1
      character(len=:), allocatable :: path
   contains
      !> Open the file and write the header.
      procedure :: open => writer_open
      !> Write one row: optional text cells, then numbers.
      procedure :: row => writer_row
      !> Close the file.
      procedure :: close => writer_close
   end type csv_writer_type

contains

   !> Number of data rows.
   pure integer function rows(self)
      class(csv_table_type), intent(in) :: self
      rows = 0
      if (allocated(self%cells)) rows = size(self%cells, 1)
   end function rows

   !> Read a CSV file with one header line; every row must have as many cells as the header.
   subroutine read_csv(path, table, error)
      !> The file.
      character(len=*), intent(in) :: path
      !> The table.
      type(csv_table_type), intent(out) :: table
      !> stat_io when the file cannot be read, stat_invalid_input for a ragged row.
      type(error_type), allocatable, intent(out) :: error
      character(len=line_len) :: line
      character(len=cell_len), allocatable :: cells(:)
      character(len=256) :: msg
      integer :: unit, stat, n_rows, n_cols, row

      table%source = path
      open (newunit=unit, file=path, status='old', action='read', iostat=stat, iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, path//': cannot open ('//trim(msg)//')', stat_io)
         return
      end if
      read (unit, '(a)', iostat=stat) line
      if (stat /= 0) then
         call fatal_error(error, path//': no header line', stat_io)
         close (unit)
         return
      end if
      call split(line, table%names)
      n_cols = size(table%names)
      ! Count the data lines, then read them.
      n_rows = 0
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (len_trim(line) > 0) n_rows = n_rows + 1
      end do
      allocate (table%cells(n_rows, n_cols))
      rewind (unit)
      read (unit, '(a)') line
      row = 0
      do while (row < n_rows)
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (len_trim(line) == 0) cycle
         row = row + 1
         call split(line, cells)
         if (size(cells) /= n_cols) then
            write (msg, '(a,i0,a,i0,a,i0)') 'data row ', row, ' has ', size(cells), &
               ' cells, the header ', n_cols
            call fatal_error(error, path//': '//trim(msg), stat_invalid_input)
            close (unit)
            return
         end if
         table%cells(row, :) = cells
      end do
      close (unit)
   end subroutine read_csv

   !> Split one line at the commas outside double quotes; quotes are removed.
   pure subroutine split(line, cells)
      character(len=*), intent(in) :: line
      character(len=cell_len), allocatable, intent(out) :: cells(:)
      integer :: i, n, start, last
      logical :: quoted

      last = len_trim(line)
      ! Windows line ends: drop a trailing carriage return.
      if (last > 0) then
         if (line(last:last) == achar(13)) last = last - 1
      end if
      n = 1
      quoted = .false.
      do i = 1, last
         if (line(i:i) == '"') quoted = .not. quoted
         if (line(i:i) == ',' .and. .not. quoted) n = n + 1
      end do
      allocate (cells(n))
      n = 0
      start = 1
      quoted = .false.
      do i = 1, last + 1
         if (i <= last) then
            if (line(i:i) == '"') quoted = .not. quoted
            if (line(i:i) /= ',' .or. quoted) cycle
         end if
         n = n + 1
         cells(n) = unquote(line(start:i - 1))
         start = i + 1
      end do
   end subroutine split

   !> A cell without blanks around it and without enclosing double quotes.
   pure function unquote(text) result(cell)
      character(len=*), intent(in) :: text
      character(len=cell_len) :: cell
      character(len=:), allocatable :: t
      t = trim(adjustl(text))
      if (len(t) >= 2) then
         if (t(1:1) == '"' .and. t(len(t):len(t)) == '"') t = t(2:len(t) - 1)
      end if
      cell = t
   end function unquote

   !> Index of a column by name, 0 when absent.
   pure integer function column_index(table, name)
      !> The table.
      type(csv_table_type), intent(in) :: table
      !> Column name (exact).
      character(len=*), intent(in) :: name
      integer :: j
      column_index = 0
      do j = 1, size(table%names)
         if (trim(table%names(j)) == name) then
            column_index = j
            return
         end if
      end do
   end function column_index

   !> One column as reals.
   subroutine column(table, name, values, error)
      !> The table.
      type(csv_table_type), intent(in) :: table
      !> Column name.
      character(len=*), intent(in) :: name
      !> The values, one per data row.
      real(wp), allocatable, intent(out) :: values(:)
      !> stat_invalid_input for a missing column or a cell that is not a number.
      type(error_type), allocatable, intent(out) :: error
      integer :: j, i, stat

      j = column_index(table, name)
      if (j == 0) then
         call fatal_error(error, table%source//': no column "'//name//'"', stat_invalid_input)
         return
      end if
      allocate (values(table%rows()))
      do i = 1, table%rows()
         read (table%cells(i, j), *, iostat=stat) values(i)
         if (stat /= 0) then
            call fatal_error(error, table%source//': column "'//name//'", cell "'// &
               trim(table%cells(i, j))//'": expected a number', stat_invalid_input)
            return
         end if
      end do
   end subroutine column

   !> The value of `key` in a `key, value, unit, note` table (the reference summary.csv).
   subroutine summary_value(table, key, value, error)
      !> The summary table.
      type(csv_table_type), intent(in) :: table
      !> The key.
      character(len=*), intent(in) :: key
      !> Its value.
      real(wp), intent(out) :: value
      !> stat_invalid_input when the key is absent or its value is not a number.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, stat

      value = 0.0_wp
      do i = 1, table%rows()
         if (trim(table%cells(i, 1)) /= key) cycle
         read (table%cells(i, 2), *, iostat=stat) value
         if (stat /= 0) call fatal_error(error, table%source//': key "'//key//'", value "'// &
            trim(table%cells(i, 2))//'": expected a number', stat_invalid_input)
         return
      end do
      call fatal_error(error, table%source//': no key "'//key//'"', stat_invalid_input)
   end subroutine summary_value

   !> Open `path` for writing and write the header line.
   subroutine writer_open(self, path, header, error)
      !> The writer.
      class(csv_writer_type), intent(inout) :: self
      !> Output file.
      character(len=*), intent(in) :: path
      !> Column names, comma-separated.
      character(len=*), intent(in) :: header
      !> stat_io when the file cannot be opened.
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: msg
      integer :: stat

      self%path = path
      open (newunit=self%unit, file=path, status='replace', action='write', iostat=stat, &
         iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, path//': cannot write ('//trim(msg)//')', stat_io)
         return
      end if
      write (self%unit, '(a)') header
   end subroutine writer_open

   !> One row: the text cells (if any), then the numbers with `digits` significant digits
   !> (default 6).
   subroutine writer_row(self, values, text, digits)
      !> The writer.
      class(csv_writer_type), intent(in) :: self
      !> Numbers.
      real(wp), intent(in) :: values(:)
      !> Leading text cells.
      character(len=*), intent(in), optional :: text(:)
      !> Significant digits.
      integer, intent(in), optional :: digits
      character(len=:), allocatable :: line
      integer :: i, nd

      nd = 6
      if (present(digits)) nd = digits
      line = ''
      if (present(text)) then
         do i = 1, size(text)
            line = line//trim(text(i))//','
         end do
      end if
      do i = 1, size(values)
         line = line//number(values(i), nd)
         if (i < size(values)) line = line//','
      end do
      write (self%unit, '(a)') line
   end subroutine writer_row

   !> Close the file.
   subroutine writer_close(self)
      !> The writer.
      class(csv_writer_type), intent(inout) :: self
      if (self%unit /= -1) close (self%unit)
      self%unit = -1
   end subroutine writer_close

   !> A number with nd significant digits, short: fixed notation for 1e-4 ≤ |x| < 1e7, otherwise
   !> exponent notation; no trailing zeros, no blanks.
   pure function number(x, nd) result(text)
      real(wp), intent(in) :: x
      integer, intent(in) :: nd
      character(len=:), allocatable :: text
      character(len=48) :: buf, fmt
      integer :: decimals, e, m

      if (x == 0.0_wp) then
         text = '0'
         return
      end if
      if (abs(x) >= 1.0e-4_wp .and. abs(x) < 1.0e7_wp) then
         decimals = max(0, nd - 1 - floor(log10(abs(x))))
         write (fmt, '(a,i0,a)') '(f40.', decimals, ')'
         write (buf, fmt) x
         text = trim(adjustl(buf))
         if (decimals > 0) then
            m = verify(text, '0', back=.true.)
            if (text(m:m) == '.') m = m - 1
            text = text(1:m)
         end if
      else
         write (fmt, '(a,i0,a,i0,a)') '(es', nd + 8, '.', nd - 1, 'e3)'
         write (buf, fmt) x
         buf = adjustl(buf)
         e = index(buf, 'E')
         m = verify(buf(1:e - 1), '0', back=.true.)
         if (buf(m:m) == '.') m = m - 1
         text = buf(1:m)//'e'//exponent_text(trim(buf(e + 1:)))
      end if
   end function number

   !> '+003' → '3', '-012' → '-12'.
   pure function exponent_text(text) result(out)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: out
      integer :: value
      character(len=8) :: buf
      read (text, *) value
      write (buf, '(i0)') value
      out = trim(buf)
   end function exponent_text

end module validate_csv
