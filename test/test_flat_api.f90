!> Helpers of the suites that call the flat interfaces in-process (api, api_kinematic): the
!> explicit interfaces of the legacy Fortran entry points SHC_* (external subroutines at the end
!> of src/shcontact/api/legacy.f90, so that a call with a wrong argument is a compile-time
!> error), C strings to and from Fortran text, and bitwise comparison of results. No tests of
!> its own.
module test_flat_api
   use, intrinsic :: iso_c_binding, only: c_char, c_null_char
   use shcontact_core_kinds, only: wp, i8
   implicit none
   private

   public :: shc_create, shc_create_arrays, shc_destroy, shc_errmsg, shc_get_profile
   public :: shc_set_material, shc_set_track, shc_set_option
   public :: shc_solve, shc_patch, shc_solve_kin, shc_patch_kin, shc_field_size, shc_fields
   public :: shc_set_value, shc_solve_state, shc_get_value, shc_get_field, shc_create_ws, &
      shc_solve_ws, shc_ws_wheel
   public :: to_chars, from_chars, bitwise_equal

   !> The legacy entry points are external procedures.
   interface
      subroutine shc_create(ihandle, wheel, rail, iside, istat)
         integer, intent(out) :: ihandle
         character(len=*), intent(in) :: wheel, rail
         integer, intent(in) :: iside
         integer, intent(out) :: istat
      end subroutine shc_create
      subroutine shc_create_arrays(ihandle, nw, yw, zw, nr, yr, zr, iside, istat)
         integer, intent(out) :: ihandle
         integer, intent(in) :: nw
         double precision, intent(in) :: yw(*), zw(*)
         integer, intent(in) :: nr
         double precision, intent(in) :: yr(*), zr(*)
         integer, intent(in) :: iside
         integer, intent(out) :: istat
      end subroutine shc_create_arrays
      subroutine shc_destroy(ihandle, istat)
         integer, intent(in) :: ihandle
         integer, intent(out) :: istat
      end subroutine shc_destroy
      subroutine shc_errmsg(ihandle, msg)
         integer, intent(in) :: ihandle
         character(len=*), intent(out) :: msg
      end subroutine shc_errmsg
      subroutine shc_get_profile(ihandle, ikind, nmax, n, y, z, istat)
         integer, intent(in) :: ihandle, ikind, nmax
         integer, intent(out) :: n
         double precision, intent(out) :: y(*), z(*)
         integer, intent(out) :: istat
      end subroutine shc_get_profile
      subroutine shc_set_material(ihandle, g, poiss, fric, istat)
         integer, intent(in) :: ihandle
         double precision, intent(in) :: g, poiss, fric
         integer, intent(out) :: istat
      end subroutine shc_set_material
      subroutine shc_set_track(ihandle, gauge, gheight, slope, icant, fbdist, fbpos, rnom, &
            istat)
         integer, intent(in) :: ihandle
         double precision, intent(in) :: gauge, gheight, slope
         integer, intent(in) :: icant
         double precision, intent(in) :: fbdist, fbpos, rnom
         integer, intent(out) :: istat
      end subroutine shc_set_track
      subroutine shc_set_option(ihandle, key, value, istat)
         integer, intent(in) :: ihandle
         character(len=*), intent(in) :: key, value
         integer, intent(out) :: istat
      end subroutine shc_set_option
      subroutine shc_solve(ihandle, ty, roll, imode, fload, cksi, ceta, cphi, values, istat)
         integer, intent(in) :: ihandle
         double precision, intent(in) :: ty, roll
         integer, intent(in) :: imode
         double precision, intent(in) :: fload, cksi, ceta, cphi
         double precision, intent(out) :: values(25)
         integer, intent(out) :: istat
      end subroutine shc_solve
      subroutine shc_patch(ihandle, ipatch, values, istat)
         integer, intent(in) :: ihandle, ipatch
         double precision, intent(out) :: values(17)
         integer, intent(out) :: istat
      end subroutine shc_patch
      subroutine shc_solve_kin(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, imode, &
            fload, values, istat)
         integer, intent(in) :: ihandle
         double precision, intent(in) :: yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch
         integer, intent(in) :: imode
         double precision, intent(in) :: fload
         double precision, intent(out) :: values(29)
         integer, intent(out) :: istat
      end subroutine shc_solve_kin
      subroutine shc_patch_kin(ihandle, ipatch, values, istat)
         integer, intent(in) :: ihandle, ipatch
         double precision, intent(out) :: values(29)
         integer, intent(out) :: istat
      end subroutine shc_patch_kin
      subroutine shc_field_size(ihandle, ipatch, nx, ny, istat)
         integer, intent(in) :: ihandle, ipatch
         integer, intent(out) :: nx, ny
         integer, intent(out) :: istat
      end subroutine shc_field_size
      subroutine shc_fields(ihandle, ipatch, nx, ny, x, y, area, pn, px, py, slip, state, istat)
         integer, intent(in) :: ihandle, ipatch
         integer, intent(in) :: nx, ny
         double precision, intent(inout) :: x(nx, ny), y(nx, ny), area(nx, ny), pn(nx, ny), &
            px(nx, ny), py(nx, ny), slip(nx, ny)
         integer, intent(inout) :: state(nx, ny)
         integer, intent(out) :: istat
      end subroutine shc_fields
      subroutine shc_set_value(ihandle, key, x, istat)
         integer, intent(in) :: ihandle
         character(len=*), intent(in) :: key
         double precision, intent(in) :: x
         integer, intent(out) :: istat
      end subroutine shc_set_value
      subroutine shc_solve_state(ihandle, istat)
         integer, intent(in) :: ihandle
         integer, intent(out) :: istat
      end subroutine shc_solve_state
      subroutine shc_get_value(ihandle, key, ipatch, x, istat)
         integer, intent(in) :: ihandle
         character(len=*), intent(in) :: key
         integer, intent(in) :: ipatch
         double precision, intent(out) :: x
         integer, intent(out) :: istat
      end subroutine shc_get_value
      subroutine shc_get_field(ihandle, key, ipatch, nx, ny, a, istat)
         integer, intent(in) :: ihandle
         character(len=*), intent(in) :: key
         integer, intent(in) :: ipatch, nx, ny
         double precision, intent(inout) :: a(nx, ny)
         integer, intent(out) :: istat
      end subroutine shc_get_field
      subroutine shc_create_ws(ihandle, wheel, rail, istat)
         integer, intent(out) :: ihandle
         character(len=*), intent(in) :: wheel, rail
         integer, intent(out) :: istat
      end subroutine shc_create_ws
      subroutine shc_solve_ws(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, imode, &
            fright, fleft, totals, istat)
         integer, intent(in) :: ihandle
         double precision, intent(in) :: yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch
         integer, intent(in) :: imode
         double precision, intent(in) :: fright, fleft
         double precision, intent(out) :: totals(4)
         integer, intent(out) :: istat
      end subroutine shc_solve_ws
      subroutine shc_ws_wheel(ihandle, iside, ipatch, values, istat)
         integer, intent(in) :: ihandle, iside, ipatch
         double precision, intent(out) :: values(29)
         integer, intent(out) :: istat
      end subroutine shc_ws_wheel
   end interface

contains

   !> A NUL-terminated C string in an array of n characters (the text cut to n - 1).
   pure function to_chars(text, n) result(chars)
      !> The text.
      character(len=*), intent(in) :: text
      !> Size of the array.
      integer, intent(in) :: n
      character(kind=c_char) :: chars(n)
      integer :: i
      chars = c_null_char
      do i = 1, min(len(text), n - 1)
         chars(i) = text(i:i)
      end do
   end function to_chars

   !> The text of a NUL-terminated C string.
   pure function from_chars(chars) result(text)
      !> The C string (all of it when it has no NUL).
      character(kind=c_char), intent(in) :: chars(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, size(chars)
         if (chars(i) == c_null_char) exit
         text = text//chars(i)
      end do
   end function from_chars

   !> Bitwise equality of two real arrays.
   pure logical function bitwise_equal(a, b)
      !> The arrays compared.
      real(wp), intent(in) :: a(:), b(:)
      bitwise_equal = size(a) == size(b)
      if (bitwise_equal) bitwise_equal = all(transfer(a, 0_i8, size(a)) == &
         transfer(b, 0_i8, size(b)))
   end function bitwise_equal

end module test_flat_api
