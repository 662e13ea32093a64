!> Small text helpers for the input/output layer: numbers as the shortest text that reads back
!> exactly, case folding, quoting for namelists and JSON.
module shcontact_core_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   implicit none
   private

   public :: format_real, format_real_buffer, quote_string, json_string, strip_quotes
   public :: string_type, string_list_type

   !> A text of any length (for lists of texts of different lengths).
   type :: string_type
      character(len=:), allocatable :: text
   end type string_type

   !> A growable list of texts.
   type :: string_list_type
      !> The texts; items(1:n) are in use.
      type(string_type), allocatable :: items(:)
      !> Number of texts.
      integer :: n = 0
   contains
      !> Append a text.
      procedure :: push => string_list_push
   end type string_list_type

contains

   !> Append a text to the list.
   pure subroutine string_list_push(self, text)
      !> The list.
      class(string_list_type), intent(inout) :: self
      !> The text.
      character(len=*), intent(in) :: text
      type(string_type), allocatable :: grown(:)
      if (.not. allocated(self%items)) allocate (self%items(8))
      if (self%n == size(self%items)) then
         allocate (grown(2*self%n))
         grown(1:self%n) = self%items(1:self%n)
         call move_alloc(grown, self%items)
      end if
      self%n = self%n + 1
      self%items(self%n)%text = text
   end subroutine string_list_push

   !> The length of [[plain]]'s text.
   pure integer function plain_length(nd, expo)
      integer, intent(in) :: nd, expo
      if (expo < 0) then
         plain_length = 2 + (-expo - 1) + nd
      else if (expo + 1 >= nd) then
         plain_length = expo + 1 + 2
      else
         plain_length = nd + 1
      end if
   end function plain_length

   !> Digits d₁d₂… with the decimal point after the (expo+1)-th digit, zero-padded.
   pure function plain(digits, expo) result(text)
      character(len=*), intent(in) :: digits
      integer, intent(in) :: expo
      character(len=plain_length(len(digits), expo)) :: text
      integer :: nd
      nd = len(digits)
      if (expo < 0) then
         text = '0.'//repeat('0', -expo - 1)//digits
      else if (expo + 1 >= nd) then
         text = digits//repeat('0', expo + 1 - nd)//'.0'
      else
         text = digits(1:expo + 1)//'.'//digits(expo + 2:nd)
      end if
   end function plain

   !> [[format_real]]'s text, left-aligned in a fixed buffer.
   pure function format_real_buffer(x) result(buffer)
      !> The number.
      real(wp), intent(in) :: x
      character(len=40) :: buffer
      character(len=:), allocatable :: text
      character(len=40) :: buf, buf15
      character(len=20) :: digits
      real(wp) :: back
      integer :: d, epos, expo, nd, ios

      if (ieee_is_nan(x)) then
         buffer = 'NaN'
         return
      else if (.not. ieee_is_finite(x)) then
         buffer = merge('-Infinity', '+Infinity', x < 0.0_wp)
         return
      else if (x == 0.0_wp) then
         buffer = '0.0'
         return
      end if
      ! 16 significant digits read back exactly for most doubles (17 always do); trailing
      ! zeros are dropped below, so short inputs such as 0.1 or 2e-3 come out short. Near the
      ! overflow threshold the rounded 16-digit form could overflow when read back.
      ios = 1
      if (abs(x) < 1.0e307_wp) then
         write (buf, '(es24.15e3)') x
         read (buf, *, iostat=ios) back
      end if
      if (ios /= 0 .or. back /= x) then
         write (buf, '(es25.16e3)') x
      else if (index('1289', buf(index(buf, 'E') - 1:index(buf, 'E') - 1)) > 0) then
         ! The 16th digit may be the noise of a number typed with 15 or fewer (8.2 reads as
         ! 8.19999999999999929...: 8.199999999999999): 15 digits, where they read back.
         write (buf15, '(es23.14e3)') x
         read (buf15, *, iostat=ios) back
         if (ios == 0 .and. back == x) buf = buf15
      end if
      buf = adjustl(buf)
      epos = index(buf, 'E')
      read (buf(epos + 1:), *) expo
      ! Mantissa digits without sign and point: "d.ddd" -> "dddd".
      digits = ''
      nd = 0
      do d = 1, epos - 1
         if (buf(d:d) >= '0' .and. buf(d:d) <= '9') then
            nd = nd + 1
            digits(nd:nd) = buf(d:d)
         end if
      end do
      do while (nd > 1 .and. digits(nd:nd) == '0')
         nd = nd - 1
      end do
      text = ''
      if (x < 0.0_wp) text = '-'
      if (expo >= -4 .and. expo < 7) then
         text = text//plain(digits(1:nd), expo)
      else
         text = text//digits(1:1)//'.'
         if (nd > 1) then
            text = text//digits(2:nd)
         else
            text = text//'0'
         end if
         text = text//'e'//str_int(expo)
      end if
      buffer = text
   end function format_real_buffer

   !> A short decimal text that reads back to exactly `x` (15, 16 or 17 significant digits
   !> without trailing zeros: 0.1, 2.0e-3, 8.2 and 64700 come out as written), in plain notation for
   !> 1e-4 ≤ |x| < 1e7 (always with a decimal point) and as `1.5e-8` otherwise. (No
   !> deferred-length result: the report lines are formatted by threads; doc/performance.md,
   !> "Threads and strings".)
   pure function format_real(x) result(text)
      !> The number.
      real(wp), intent(in) :: x
      character(len=len_trim(format_real_buffer(x))) :: text
      text = format_real_buffer(x)
   end function format_real


   !> A Fortran string literal in apostrophes (embedded apostrophes doubled), for namelists.
   pure function quote_string(s) result(q)
      !> The text (trailing blanks are removed).
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: q
      integer :: i
      q = "'"
      do i = 1, len_trim(s)
         if (s(i:i) == "'") then
            q = q//"''"
         else
            q = q//s(i:i)
         end if
      end do
      q = q//"'"
   end function quote_string

   !> Remove one level of matching apostrophes or quotes (undoubling embedded ones).
   pure function strip_quotes(s) result(t)
      !> The text, possibly quoted.
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: t
      character(len=1) :: q
      integer :: i, n
      t = trim(adjustl(s))
      n = len(t)
      if (n < 2) return
      q = t(1:1)
      if ((q /= "'" .and. q /= '"') .or. t(n:n) /= q) return
      t = t(2:n - 1)
      i = 1
      do while (i < len(t))
         if (t(i:i) == q .and. t(i + 1:i + 1) == q) t = t(1:i)//t(i + 2:)
         i = i + 1
      end do
   end function strip_quotes

   !> The length of [[json_string]]'s text.
   pure integer function json_length(s)
      character(len=*), intent(in) :: s
      integer :: i, c
      json_length = 2
      do i = 1, len_trim(s)
         c = iachar(s(i:i))
         select case (c)
         case (34, 92, 10, 9)
            json_length = json_length + 2
         case (0:8, 11:31)
            json_length = json_length + 6
         case default
            json_length = json_length + 1
         end select
      end do
   end function json_length

   !> A JSON string literal: quotes, backslashes and control characters escaped. (No
   !> deferred-length result: doc/performance.md, "Threads and strings".)
   pure function json_string(s) result(q)
      !> The text (trailing blanks are removed).
      character(len=*), intent(in) :: s
      character(len=json_length(s)) :: q
      character(len=6) :: hex
      integer :: i, c, at
      q(1:1) = '"'
      at = 1
      do i = 1, len_trim(s)
         c = iachar(s(i:i))
         select case (c)
         case (34)
            q(at + 1:at + 2) = '\"'
            at = at + 2
         case (92)
            q(at + 1:at + 2) = '\\'
            at = at + 2
         case (10)
            q(at + 1:at + 2) = '\n'
            at = at + 2
         case (9)
            q(at + 1:at + 2) = '\t'
            at = at + 2
         case (0:8, 11:31)
            write (hex, '(a,z4.4)') '\u', c
            q(at + 1:at + 6) = hex
            at = at + 6
         case default
            q(at + 1:at + 1) = s(i:i)
            at = at + 1
         end select
      end do
      q(at + 1:at + 1) = '"'
   end function json_string

end module shcontact_core_text
