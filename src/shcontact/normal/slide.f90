!> The exact slide of the vertical approach (`&normal slide = 'exact'`, issue 28;
!> doc/geometry.md "Vertical approach"): the secant tilt c̄(y) = (1/d) ∫_y^{y+d} c(u) du of the
!> tilt term c over the slide d of the wheel along the contact plane, on a table of c at uniform
!> spacing (c linear between points, constant beyond the ends). Used by
!> shcontact_normal_semihertz (kept apart so that its hot loops stay small).
module shcontact_normal_slide
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: secant_tilt, running_integral

contains

   !> Q_j = ∫ c from the first point to point j (trapezoids: exact for c linear between points).
   pure subroutine running_integral(tilt, h, integral)
      !> The tilt term c at the table points.
      real(wp), intent(in) :: tilt(:)
      !> The table spacing (mm).
      real(wp), intent(in) :: h
      !> Q at the table points (mm), Q_1 = 0.
      real(wp), intent(out) :: integral(:)
      integer :: j
      integral(1) = 0.0_wp
      do j = 2, size(tilt)
         integral(j) = integral(j - 1) + 0.5_wp*h*(tilt(j - 1) + tilt(j))
      end do
   end subroutine running_integral

   !> c̄_j = (Q(y_j + d) − Q_j)/d, with Q the running integral of c; c_j itself where d vanishes
   !> (|d| ≤ 1e-9 h).
   pure real(wp) function secant_tilt(tilt, integral, h, j, d) result(c_bar)
      !> The tilt term c and its running integral Q at the table points ([[running_integral]]).
      real(wp), intent(in) :: tilt(:), integral(:)
      !> The table spacing and the slide d (mm).
      real(wp), intent(in) :: h, d
      !> The table point.
      integer, intent(in) :: j
      real(wp) :: p, f
      integer :: k, n

      if (.not. (abs(d) > 1.0e-9_wp*h)) then
         c_bar = tilt(j)
         return
      end if
      n = size(tilt)
      ! Position of y_j + d in table points from the first (0-based).
      p = real(j - 1, wp) + d/h
      if (p <= 0.0_wp) then
         c_bar = integral(1) + p*h*tilt(1)
      else if (p >= real(n - 1, wp)) then
         c_bar = integral(n) + (p - (n - 1))*h*tilt(n)
      else
         k = min(n - 1, 1 + int(p))
         f = p - (k - 1)
         c_bar = integral(k) + h*f*(tilt(k) + 0.5_wp*f*(tilt(k + 1) - tilt(k)))
      end if
      c_bar = (c_bar - integral(j))/d
   end function secant_tilt

end module shcontact_normal_slide
