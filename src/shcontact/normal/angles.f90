!> Contact angles across a patch for the strip method: the tilt term of the vertical approach
!> (doc/geometry.md, "Vertical approach": a vertical translation of the wheel that closes the
!> gap by Δ at the reference point, contact angle γ₀, closes it by Δ(1 − c) at a point of
!> contact angle γ, c = tan γ₀ tan(γ − γ₀)) and the direction of the pressure, the angle of the
!> interface midway between the undeformed surfaces.
module shcontact_normal_angles
   use shcontact_core_kinds, only: wp
   use shcontact_geometry_patch, only: patch_geometry_type
   implicit none
   private

   public :: tilt_terms, vertical_tilt, interface_angles, approach_closure

contains

   !> [[vertical_tilt]] at table points i1 … i2, from the table's tan γ where the contact search
   !> filled it, c = tan γ₀ (tan γ − tan γ₀)/(1 + tan γ tan γ₀) (equal to tan γ₀ tan(γ − γ₀),
   !> without a tangent per point); otherwise, or when it does not belong to γ (checked at both
   !> ends), from γ.
   pure subroutine tilt_terms(geometry, i1, i2, gamma0, tilt)
      type(patch_geometry_type), intent(in) :: geometry
      integer, intent(in) :: i1, i2
      real(wp), intent(in) :: gamma0
      real(wp), intent(out) :: tilt(:)
      real(wp) :: t0
      integer :: i
      logical :: usable

      if (geometry%conformal) then
         t0 = cos(gamma0)
         do i = i1, i2
            tilt(i - i1 + 1) = 1.0_wp - cos(geometry%gamma(i))/t0
         end do
         return
      end if
      usable = allocated(geometry%tan_gamma)
      if (usable) usable = size(geometry%tan_gamma) >= i2
      if (usable) usable = matches(i1) .and. matches(i2)
      if (.not. usable) then
         tilt = vertical_tilt(geometry%gamma(i1:i2), gamma0)
         return
      end if
      t0 = tan(gamma0)
      do i = i1, i2
         associate (t => geometry%tan_gamma(i))
            tilt(i - i1 + 1) = t0*((t - t0)/(1.0_wp + t*t0))
         end associate
      end do
   contains
      !> Whether tan_gamma(i) is the tangent of gamma(i) to round-off.
      pure logical function matches(i)
         integer, intent(in) :: i
         real(wp) :: t
         t = tan(geometry%gamma(i))
         matches = abs(geometry%tan_gamma(i) - t) <= 1.0e-12_wp*(1.0_wp + t*t)
      end function matches
   end subroutine tilt_terms

   !> The tilt term of the vertical approach at every table point (module text):
   !> c = tan γ₀ tan(γ − γ₀). A vertical translation t of the wheel moves its surface, where
   !> its normal makes the angle γ with the vertical, by t cos γ/cos(γ − γ₀) along the contact
   !> normal (angle γ₀); relative to t cos γ₀ at the reference point that is 1 − c. It vanishes
   !> on a flat contact (γ₀ = 0) and where γ = γ₀, and is the same in the mirror image (γ → −γ).
   elemental real(wp) function vertical_tilt(gamma, gamma0) result(tilt)
      !> Contact angle γ (rad).
      real(wp), intent(in) :: gamma
      !> Contact angle γ₀ of the contact plane (rad).
      real(wp), intent(in) :: gamma0
      tilt = tan(gamma0)*tan(gamma - gamma0)
   end function vertical_tilt

   !> 1 − c: the share of the reference point's closure that a vertical translation gives a
   !> point of contact angle γ, along the table's normal there (plane: 1 − tan γ₀ tan(γ − γ₀);
   !> conformal table: cos γ/cos γ₀).
   elemental real(wp) function approach_closure(gamma, gamma0, conformal) result(w)
      real(wp), intent(in) :: gamma, gamma0
      logical, intent(in) :: conformal
      if (conformal) then
         w = cos(gamma)/cos(gamma0)
      else
         w = 1.0_wp - vertical_tilt(gamma, gamma0)
      end if
   end function approach_closure

   !> The direction of the pressure at each table point (doc/geometry.md, "The direction of the
   !> pressure"): with equal elastic constants the bodies' normal displacements are equal and
   !> opposite, so the deformed interface lies midway between the undeformed surfaces, and its
   !> slope in the table's frame (contact angle γ₀) is the mean of the rail's and the wheel's,
   !> w' + g'/2, with the wheel's slope w' = tan(γ − γ₀) and the relative slope g' = dg/dy:
   !> γ_n = γ₀ + atan(tan(γ − γ₀) + g'/2). g' by central differences (one-sided at the ends); a
   !> table of one point keeps γ.
   pure subroutine interface_angles(gap, gamma, gamma0, h, conformal, gamma_n)
      !> g(y) on the table's uniform grid (mm).
      real(wp), intent(in) :: gap(:)
      !> The wheel's contact angle γ(y) (rad).
      real(wp), intent(in) :: gamma(:)
      !> The table frame's contact angle γ₀ (rad) and the grid spacing h (mm).
      real(wp), intent(in) :: gamma0, h
      !> A conformal table (y the rail's arc length, g along each point's rail normal): the
      !> wheel's slope relative to the rail there is −g', so the interface turns from the
      !> wheel's angle by atan(g') − atan(g'/2).
      logical, intent(in) :: conformal
      !> γ_n(y) (rad).
      real(wp), intent(out) :: gamma_n(:)
      real(wp) :: slope
      integer :: i, n

      n = size(gap)
      if (n < 2) then
         gamma_n = gamma
         return
      end if
      do i = 1, n
         if (i == 1) then
            slope = (gap(2) - gap(1))/h
         else if (i == n) then
            slope = (gap(n) - gap(n - 1))/h
         else
            slope = (gap(i + 1) - gap(i - 1))/(2.0_wp*h)
         end if
         if (conformal) then
            gamma_n(i) = gamma(i) + atan(slope) - atan(0.5_wp*slope)
         else
            gamma_n(i) = gamma0 + atan(tan(gamma(i) - gamma0) + 0.5_wp*slope)
         end if
      end do
   end subroutine interface_angles

end module shcontact_normal_angles
