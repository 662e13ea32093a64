!> Small text helpers for the input/output layer: numbers as the shortest text that reads back
!> exactly, case folding, quoting for namelists and JSON.
module shcontact_core_text
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite, ieee_is_nan
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   implicit none
   private

   public :: format_real, quote_string, json_string, strip_quotes
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

   !> A short decimal text that reads back to exactly `x` (16 or 17 significant digits without
   !> trailing zeros: 0.1, 2.0e-3 and 64700 come out as written), in plain notation for
   !> 1e-4 ≤ |x| < 1e7 (always with a decimal point) and as `1.5e-8` otherwise.
   pure function format_real(x) result(text)
      !> The number.
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=40) :: buf
      character(len=20) :: digits
      real(wp) :: back
      integer :: d, epos, expo, nd, ios

      if (ieee_is_nan(x)) then
         text = 'NaN'
         return
      else if (.not. ieee_is_finite(x)) then
         text = merge('-Infinity', '+Infinity', x < 0.0_wp)
         return
      else if (x == 0.0_wp) then
         text = '0.0'
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
      if (ios /= 0 .or. back /= x) write (buf, '(es25.16e3)') x
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
   end function format_real

   !> Digits d₁d₂… with the decimal point after the (expo+1)-th digit, zero-padded.
   pure function plain(digits, expo) result(text)
      character(len=*), intent(in) :: digits
      integer, intent(in) :: expo
      character(len=:), allocatable :: text
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

   !> A JSON string literal: quotes, backslashes and control characters escaped.
   pure function json_string(s) result(q)
      !> The text (trailing blanks are removed).
      character(len=*), intent(in) :: s
      character(len=:), allocatable :: q
      character(len=6) :: hex
      integer :: i, c
      q = '"'
      do i = 1, len_trim(s)
         c = iachar(s(i:i))
         select case (c)
         case (34)
            q = q//'\"'
         case (92)
            q = q//'\\'
         case (10)
            q = q//'\n'
         case (9)
            q = q//'\t'
         case (0:8, 11:31)
            write (hex, '(a,z4.4)') '\u', c
            q = q//hex
         case default
            q = q//s(i:i)
         end select
      end do
      q = q//'"'
   end function json_string

end module shcontact_core_text
