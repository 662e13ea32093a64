!> Complete elliptic integrals through Carlson's symmetric forms (doc/theory.md §1.3, §1.5).
!>
!> Everything is parameterised by the complementary parameter `mc` = g² = 1 − k² (k the modulus),
!> so that neither the circle (mc → 1) nor the slender ellipse (mc → 0) suffers cancellation:
!> K = R_F(0, mc, 1), 𝔇 = R_D(0, mc, 1)/3, 𝔅 = K − 𝔇, E = 𝔅 + mc·𝔇.
!> The duplication algorithms follow Carlson, Numer. Algorithms 10 (1995) 13–26.
module shcontact_math_elliptic
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: carlson_rf, carlson_rd, complete_elliptic, elliptic_k, elliptic_e

   !> Relative tolerance that sets when the duplication stops (Carlson 1995, eq. 2.2 and 2.19).
   real(wp), parameter :: duplication_tol = 1.0e-16_wp
   !> A safety net on the number of duplication steps (each gains a factor 4 in the scale).
   integer, parameter :: max_duplications = 200

contains

   !> Carlson's symmetric integral of the first kind R_F(x, y, z); x, y, z ≥ 0, at most one zero.
   elemental function carlson_rf(x, y, z) result(rf)
      !> Arguments (order does not matter).
      real(wp), intent(in) :: x, y, z
      real(wp) :: rf
      real(wp) :: xn, yn, zn, an, a0, q, lam, sx, sy, sz, dx, dy, dz, e2, e3, scale
      integer :: n

      xn = x; yn = y; zn = z
      a0 = (x + y + z)/3.0_wp
      an = a0
      q = (3.0_wp*duplication_tol)**(-1.0_wp/6.0_wp)*max(abs(a0 - x), abs(a0 - y), abs(a0 - z))
      scale = 1.0_wp
      do n = 1, max_duplications
         if (q*scale < abs(an)) exit
         sx = sqrt(xn); sy = sqrt(yn); sz = sqrt(zn)
         lam = sx*sy + sx*sz + sy*sz
         xn = 0.25_wp*(xn + lam); yn = 0.25_wp*(yn + lam); zn = 0.25_wp*(zn + lam)
         an = 0.25_wp*(an + lam)
         scale = 0.25_wp*scale
      end do
      dx = (a0 - x)*scale/an
      dy = (a0 - y)*scale/an
      dz = -(dx + dy)
      e2 = dx*dy - dz*dz
      e3 = dx*dy*dz
      rf = (1.0_wp - e2/10.0_wp + e3/14.0_wp + e2*e2/24.0_wp - 3.0_wp*e2*e3/44.0_wp)/sqrt(an)
   end function carlson_rf

   !> Carlson's symmetric integral of the second kind R_D(x, y, z); x, y ≥ 0 (not both 0), z > 0.
   elemental function carlson_rd(x, y, z) result(rd)
      !> Arguments; R_D is symmetric in x and y only.
      real(wp), intent(in) :: x, y, z
      real(wp) :: rd
      real(wp) :: xn, yn, zn, an, a0, q, lam, sx, sy, sz, tail, scale
      real(wp) :: dx, dy, dz, e2, e3, e4, e5
      integer :: n

      xn = x; yn = y; zn = z
      a0 = (x + y + 3.0_wp*z)/5.0_wp
      an = a0
      q = (0.25_wp*duplication_tol)**(-1.0_wp/6.0_wp)*max(abs(a0 - x), abs(a0 - y), abs(a0 - z))
      scale = 1.0_wp
      tail = 0.0_wp
      do n = 1, max_duplications
         if (q*scale < abs(an)) exit
         sx = sqrt(xn); sy = sqrt(yn); sz = sqrt(zn)
         lam = sx*sy + sx*sz + sy*sz
         tail = tail + scale/(sz*(zn + lam))
         xn = 0.25_wp*(xn + lam); yn = 0.25_wp*(yn + lam); zn = 0.25_wp*(zn + lam)
         an = 0.25_wp*(an + lam)
         scale = 0.25_wp*scale
      end do
      dx = (a0 - x)*scale/an
      dy = (a0 - y)*scale/an
      dz = -(dx + dy)/3.0_wp
      e2 = dx*dy - 6.0_wp*dz*dz
      e3 = (3.0_wp*dx*dy - 8.0_wp*dz*dz)*dz
      e4 = 3.0_wp*(dx*dy - dz*dz)*dz*dz
      e5 = dx*dy*dz**3
      rd = scale/(an*sqrt(an))*(1.0_wp - 3.0_wp*e2/14.0_wp + e3/6.0_wp + 9.0_wp*e2*e2/88.0_wp &
           - 3.0_wp*e4/22.0_wp - 9.0_wp*e2*e3/52.0_wp + 3.0_wp*e5/26.0_wp) + 3.0_wp*tail
   end function carlson_rd

   !> K, E and the associated integrals 𝔅 = (E − mc·K)/k², 𝔇 = (K − E)/k² for 0 < mc ≤ 1.
   !>
   !> 𝔅 and 𝔇 stay finite as k → 0 (both → π/4); as k → 1 (mc → 0) 𝔅 → 1 while K and 𝔇 grow
   !> like ln(4/√mc).
   elemental subroutine complete_elliptic(mc, kk, ee, bb, dd)
      !> Complementary parameter mc = 1 − k² = g², in (0, 1].
      real(wp), intent(in) :: mc
      !> K(k), E(k): complete integrals of the first and second kinds.
      real(wp), intent(out) :: kk, ee
      !> 𝔅(k), 𝔇(k): the associated integrals of doc/theory.md §1.3.
      real(wp), intent(out) :: bb, dd

      kk = carlson_rf(0.0_wp, mc, 1.0_wp)
      dd = carlson_rd(0.0_wp, mc, 1.0_wp)/3.0_wp
      bb = kk - dd
      ee = bb + mc*dd
   end subroutine complete_elliptic

   !> K as a function of the complementary parameter mc = 1 − k² ∈ (0, 1].
   elemental function elliptic_k(mc) result(kk)
      !> Complementary parameter.
      real(wp), intent(in) :: mc
      real(wp) :: kk
      kk = carlson_rf(0.0_wp, mc, 1.0_wp)
   end function elliptic_k

   !> E as a function of the complementary parameter mc = 1 − k² ∈ [0, 1] (E(k = 1) = 1).
   elemental function elliptic_e(mc) result(ee)
      !> Complementary parameter.
      real(wp), intent(in) :: mc
      real(wp) :: ee
      real(wp) :: kk, bb, dd
      if (mc <= 0.0_wp) then
         ee = 1.0_wp
         return
      end if
      call complete_elliptic(mc, kk, ee, bb, dd)
   end function elliptic_e

end module shcontact_math_elliptic
