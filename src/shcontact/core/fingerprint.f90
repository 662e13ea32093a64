!> Fingerprints of data: a short text that changes when the data change, for telling apart two
!> inputs that carry the same name (a profile file rewritten between the blocks of a run).
module shcontact_core_fingerprint
   use, intrinsic :: iso_fortran_env, only: int8, int64
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: fingerprint

contains

   !> 16 hexadecimal digits from the bytes of the values: two FNV-1a hashes of 32 bits with
   !> different offset bases (not cryptographic; any change of a value changes them but for a
   !> chance of about 2⁻⁶⁴ per pair of inputs).
   pure function fingerprint(values) result(text)
      !> The values.
      real(wp), intent(in) :: values(:)
      character(len=16) :: text
      integer(int64), parameter :: prime = 16777619_int64, mask = 4294967295_int64
      integer(int8), allocatable :: bytes(:)
      integer(int64) :: h1, h2, b
      integer :: i

      h1 = 2166136261_int64
      h2 = 3735928559_int64
      bytes = transfer(values, [0_int8])
      do i = 1, size(bytes)
         b = iand(int(bytes(i), int64), 255_int64)
         h1 = iand(ieor(h1, b)*prime, mask)
         h2 = iand(ieor(h2, b)*prime, mask)
      end do
      write (text, '(2z8.8)') h1, h2
   end function fingerprint

end module shcontact_core_fingerprint
