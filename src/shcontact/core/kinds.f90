!> Kind parameters used throughout shcontact.
!>
!> Every real in the library is `real(wp)`; literals are written `1.0_wp`. C kinds appear only in
!> the C binding layer.
module shcontact_core_kinds
   use, intrinsic :: iso_fortran_env, only: real64, int8, int32, int64
   implicit none
   private

   public :: wp, i1, i4, i8

   !> Working precision: IEEE double.
   integer, parameter :: wp = real64
   !> One-byte integer (stick/slip state codes in output fields).
   integer, parameter :: i1 = int8
   !> Default-sized integer, spelled out where the size matters (file formats, C).
   integer, parameter :: i4 = int32
   !> Eight-byte integer (counters, timers).
   integer, parameter :: i8 = int64

end module shcontact_core_kinds
