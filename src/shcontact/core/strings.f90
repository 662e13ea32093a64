!> Small text helpers for messages and option parsing.
module shcontact_core_strings
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_buffer, only: text_buffer_type
   implicit none
   private

   public :: to_lower, substituted, str_int, str_real, visible, str_format, format_length, &
      control_characters, replaced

   !> The ASCII control characters (0–31) and DEL (127): no text input holds them (a case
   !> file's tabs and line ends are taken by the line reader first).
   character(len=*), parameter :: control_characters = achar(0)//achar(1)//achar(2)// &
      achar(3)//achar(4)//achar(5)//achar(6)//achar(7)//achar(8)//achar(9)//achar(10)// &
      achar(11)//achar(12)//achar(13)//achar(14)//achar(15)//achar(16)//achar(17)//achar(18)// &
      achar(19)//achar(20)//achar(21)//achar(22)//achar(23)//achar(24)//achar(25)//achar(26)// &
      achar(27)//achar(28)//achar(29)//achar(30)//achar(31)//achar(127)

   !> An integer (default or 64-bit) as text without blanks.
   interface str_int
      module procedure str_int_default, str_int_long
   end interface str_int

contains

   !> The text with every character `from` turned into `to`.
   pure function replaced(text, from, to) result(out)
      character(len=*), intent(in) :: text
      character, intent(in) :: from, to
      character(len=len(text)) :: out
      integer :: i
      out = text
      do i = 1, len(out)
         if (out(i:i) == from) out(i:i) = to
      end do
   end function replaced

   !> The text with every occurrence of the substring `from` (not empty) turned into `to`, left
   !> to right, without looking again at what was put in.
   pure function substituted(text, from, to) result(out)
      character(len=*), intent(in) :: text, from, to
      character(len=:), allocatable :: out
      integer :: i, k
      out = ''
      i = 1
      do
         k = index(text(i:), from)
         if (k == 0 .or. len(from) == 0) exit
         out = out//text(i:i + k - 2)//to
         i = i + k - 1 + len(from)
      end do
      out = out//text(i:)
   end function substituted

   !> ASCII lower case (option names, file extensions).
   pure function to_lower(text) result(low)
      !> Text to convert.
      character(len=*), intent(in) :: text
      character(len=len(text)) :: low
      integer :: i, code
      low = text
      do i = 1, len(text)
         code = iachar(text(i:i))
         if (code >= iachar('A') .and. code <= iachar('Z')) low(i:i) = achar(code + 32)
      end do
   end function to_lower

   !> Digits (and sign) of an integer.
   pure integer function int_length(i)
      integer(i8), intent(in) :: i
      character(len=24) :: buffer
      write (buffer, '(i0)') i
      int_length = len_trim(buffer)
   end function int_length

   !> [[str_real]]'s text, left-aligned in a fixed buffer.
   pure function real_buffer(x) result(buffer)
      real(wp), intent(in) :: x
      character(len=32) :: buffer
      integer :: last
      if (abs(x) >= 1.0e-3_wp .and. abs(x) < 1.0e6_wp) then
         write (buffer, '(f20.6)') x
         buffer = adjustl(buffer)
         last = verify(buffer, '0 ', back=.true.)
         if (buffer(last:last) == '.') last = last - 1
         buffer(last + 1:) = ''
      else if (x == 0.0_wp) then
         buffer = '0'
      else
         write (buffer, '(es13.5e3)') x
         buffer = adjustl(buffer)
      end if
   end function real_buffer

   !> An integer as text without blanks. (The number-to-text functions that messages call
   !> return a result whose length a specification function gives, not a deferred-length one:
   !> gfortran 12 keeps the length of a deferred-length function result in a static variable of
   !> the caller, so two threads building a message at the same place raced; a threads' test
   !> in `strings`, doc/performance.md "Threads and strings".)
   pure function str_int_default(i) result(text)
      !> The number.
      integer, intent(in) :: i
      character(len=int_length(int(i, i8))) :: text
      write (text, '(i0)') i
   end function str_int_default

   !> A 64-bit integer as text without blanks.
   pure function str_int_long(i) result(text)
      !> The number.
      integer(i8), intent(in) :: i
      character(len=int_length(i)) :: text
      write (text, '(i0)') i
   end function str_int_long

   !> A real in short form for messages: fixed with up to 6 decimals for 1e-3 ≤ |x| < 1e6,
   !> otherwise 6 significant digits in exponent form.
   pure function str_real(x) result(text)
      !> The number.
      real(wp), intent(in) :: x
      character(len=len_trim(real_buffer(x))) :: text
      text = real_buffer(x)
   end function str_real

   !> [[str_format]]'s text, left-aligned in a fixed buffer.
   pure function format_buffer(x, form) result(buffer)
      real(wp), intent(in) :: x
      character(len=*), intent(in) :: form
      character(len=40) :: buffer
      integer :: n
      write (buffer, form) x
      buffer = adjustl(buffer)
      n = len_trim(buffer)
      if (n > 1 .and. buffer(n:n) == '.') buffer(n:n) = ' '
      if (buffer(1:1) == '.') then
         buffer = '0'//buffer
      else if (buffer(1:2) == '-.') then
         buffer = '-0'//buffer(2:)
      end if
   end function format_buffer

   !> The length of [[str_format]]'s result.
   pure integer function format_length(x, form)
      !> The number.
      real(wp), intent(in) :: x
      !> The format, with parentheses.
      character(len=*), intent(in) :: form
      format_length = len_trim(format_buffer(x, form))
   end function format_length

   !> A real written with an edit descriptor for tables and messages ('(f0.1)', '(es9.2)'),
   !> without blanks, with a leading 0 before a bare decimal point and no trailing one
   !> (f0.0 of 48 gives 48). (No deferred-length result: see [[str_int_default]].)
   pure function str_format(x, form) result(text)
      !> The number.
      real(wp), intent(in) :: x
      !> The format, with parentheses.
      character(len=*), intent(in) :: form
      character(len=format_length(x, form)) :: text
      text = format_buffer(x, form)
   end function str_format

   !> Text with control characters (other than line feed and tab) shown as `<0xNN>`, so that
   !> a message quoting a stray byte of an input file shows it.
   pure function visible(text) result(shown)
      !> The text (UTF-8 passes through).
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: shown
      character(len=*), parameter :: hex = '0123456789ABCDEF'
      type(text_buffer_type) :: built
      integer :: i, code
      do i = 1, len(text)
         code = iachar(text(i:i))
         if ((code < 32 .and. code /= 10 .and. code /= 9) .or. code == 127) then
            call built%add('<0x'//hex(code/16 + 1:code/16 + 1)//hex(mod(code, 16) + 1: &
               mod(code, 16) + 1)//'>')
         else
            call built%add(text(i:i))
         end if
      end do
      shown = built%text()
   end function visible

end module shcontact_core_strings
