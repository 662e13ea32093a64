!> The half-space influence between groups of strips of the coupled reduction
!> (shcontact_normal_coupling): the surface displacement on the centre line x = 0 of a target
!> group per unit peak pressure of a source group, whose pressure is semi-elliptic in x,
!> P √(1 − x²/a²), over its length 2a and uniform across its width w.
!>
!> The displacement of such a strip at lateral distance y is (1/(π E*)) times
!> ∫∫ √(1 − x²/a²)/r dx dy' over the strip, and its line integral along x is
!> ∫ √(1 − x²/a²)/√(x² + y²) dx = 2a/a F(|y|/a) = 2 F(|y|/a) with
!> F(u) = ∫₀¹ √(1 − t²)/√(t² + u²) dt = √(1 + u²) (K(m) − E(m)), m = 1/(1 + u²)
!> ([[line_kernels]]). The integral across the width is a quadrature in y' ([[influence_column]]).
!>
!> One column of the influence matrix (one source group, all its targets) is evaluated at once:
!> the quadrature points of every target are gathered into one array and the kernel runs over it
!> without branches, so that the compiler vectorises it (the elliptic kernel was half the cost of
!> a coupled normal solve when it was evaluated point by point, doc/performance.md).
module shcontact_normal_strip_influence
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   implicit none
   private

   public :: influence_column, line_kernels

   !> Hastings' coefficients of K(m) and E(m) in m₁ = 1 − m (Abramowitz & Stegun 17.3.34, 17.3.36).
   real(wp), parameter :: hastings_ka(0:4) = [1.38629436112_wp, 0.09666344259_wp, &
      0.03590092383_wp, 0.03742563713_wp, 0.01451196212_wp]
   real(wp), parameter :: hastings_kb(0:4) = [0.5_wp, 0.12498593597_wp, 0.06880248576_wp, &
      0.03328355346_wp, 0.00441787012_wp]
   real(wp), parameter :: hastings_ea(1:4) = [0.44325141463_wp, 0.06260601220_wp, &
      0.04757383546_wp, 0.01736506451_wp]
   real(wp), parameter :: hastings_eb(1:4) = [0.24998368310_wp, 0.09200180037_wp, &
      0.04069697526_wp, 0.00526449639_wp]
   !> Below this m the kernel uses the series of (K − E)/m and E in m (Hastings' K − E loses
   !> its relative accuracy to cancellation as m → 0).
   real(wp), parameter :: series_below = 0.1_wp
   !> Gauss–Legendre nodes and weights on (0, 1) for the self term, in t with |y| = (w/2) t³
   !> ([[influence_column]]): 6 points, relative error 6e-6 to 5e-5 on the self influence for
   !> groups from 1/100 to 2 times as wide as long (the earlier rule, 8 points in t with
   !> |y| = (w/2) t², had 3e-5 to 2e-4; 6 points of that rule, 1e-4 to 6e-4, moved the coupled
   !> strips on a Hertz gap by more than 2 % at the ellipse's ends).
   integer, parameter :: n_self = 6
   real(wp), parameter :: self_t(n_self) = 0.5_wp*(1.0_wp + [-0.9324695142031521_wp, &
      -0.6612093864662645_wp, -0.2386191860831969_wp, 0.2386191860831969_wp, &
      0.6612093864662645_wp, 0.9324695142031521_wp])
   real(wp), parameter :: self_w(n_self) = 0.5_wp*[0.1713244923791704_wp, &
      0.3607615730481386_wp, 0.4679139345726910_wp, 0.4679139345726910_wp, &
      0.3607615730481386_wp, 0.1713244923791704_wp]
   !> Targets nearer than near_widths source widths get Simpson's rule across the width, those
   !> beyond far_widths the midpoint rule, and those between a blend of the two whose weight
   !> goes linearly from Simpson's at near_widths to the midpoint rule's at far_widths
   !> ([[influence_column]]). The two rules differ by 0.4–1.4 % at 2.5 widths: switching at
   !> one distance made the kernel, and with it the coupled loads and the kinematic call's
   !> vertical force, jump where the distance of two groups crossed it (doc/kinematics.md,
   !> "Robustness with other table steps"). The band is narrow so that the rules validated
   !> before (doc/validation.md) hold everywhere else: a band to 4 widths moved the coupled
   !> strips of a Hertz gap by 0.2 % of the peak strip load (the midpoint rule's error there
   !> partly offsets that of the groups' means), and together with a wider ratio blend
   !> (shcontact_normal_coupling_groups' ratio_share at 3 %) it moved the DOE positions' P80
   !> |Δf_x| at Y_WS = −1 mm from 0.002 to 0.004; any band makes the column continuous.
   real(wp), parameter :: near_widths = 2.5_wp, far_widths = 2.6_wp
   !> Targets gathered per kernel sweep: the work arrays have a fixed size (nothing is
   !> allocated), longer columns are done in chunks.
   integer, parameter :: chunk = 32
   integer, parameter :: max_points = n_self + 3*chunk

contains

   !> The influence of one source group on every target (mm; divide by π E* for the
   !> displacement per unit peak pressure, mm/MPa), and its derivative with respect to ln a of
   !> the source. Across the source's width: on the source itself (`self_index`)
   !> Gauss–Legendre in t with |y| = (w/2) t³ (which takes out F's logarithmic singularity),
   !> Simpson's rule for targets up to [[near_widths]] widths away, the midpoint rule beyond
   !> [[far_widths]], a blend of the two between (the column is continuous in the distance).
   !> Measured against the full integral: Simpson within 0.1–1.1 % at one width, the midpoint rule
   !> within 0.4–1.4 % at 2.5 widths and less farther out (the kernel falls like 1/η there).
   pure subroutine influence_column(a, w, s_source, s_target, self_index, column, column_slope)
      !> Half-length a (mm, > 0) and width w (mm, > 0) of the source group, and its centre
      !> along the profile (mm).
      real(wp), intent(in) :: a, w, s_source
      !> Centres of the targets along the profile (mm).
      real(wp), intent(in) :: s_target(:)
      !> The position of the source among the targets, 0 when it is not one of them.
      integer, intent(in) :: self_index
      !> The influence on each target (mm) and its derivative with respect to ln a (mm).
      real(wp), intent(out) :: column(:), column_slope(:)
      real(wp), dimension(max_points) :: u, weight, f, df
      integer :: target(max_points)
      real(wp) :: d, h, inv_a, simpson
      integer :: j0, j1, j, k, np

      inv_a = 1.0_wp/a
      h = 0.5_wp*w
      do j0 = 1, size(s_target), chunk
         j1 = min(size(s_target), j0 + chunk - 1)
         np = 0
         do j = j0, j1
            d = abs(s_target(j) - s_source)
            if (j == self_index) then
               ! 2 ∫_0^{w/2} 2F(y/a) dy with y = h t³ (dy = 3h t² dt).
               do k = 1, n_self
                  u(np + k) = h*self_t(k)**3*inv_a
                  weight(np + k) = 12.0_wp*h*self_w(k)*self_t(k)**2
                  target(np + k) = j
               end do
               np = np + n_self
            else if (d < far_widths*w) then
               ! Groups of two patches may overlap along the profile: the near edge stays apart.
               u(np + 1) = max(d - h, 0.05_wp*w)*inv_a
               u(np + 2) = max(d, 0.1_wp*w)*inv_a
               u(np + 3) = (d + h)*inv_a
               ! Simpson's weights (w/3)[1, 4, 1] up to near_widths, blended (share simpson)
               ! into the midpoint rule's 2w on the middle point (the same point there).
               simpson = min(1.0_wp, (far_widths*w - d)/((far_widths - near_widths)*w))
               weight(np + 1) = simpson*w/3.0_wp
               weight(np + 2) = simpson*(4.0_wp*w/3.0_wp) + (1.0_wp - simpson)*2.0_wp*w
               weight(np + 3) = simpson*w/3.0_wp
               target(np + 1:np + 3) = j
               np = np + 3
            else
               u(np + 1) = d*inv_a
               weight(np + 1) = 2.0_wp*w
               target(np + 1) = j
               np = np + 1
            end if
         end do
         call line_kernels(u(1:np), f(1:np), df(1:np))
         column(j0:j1) = 0.0_wp
         column_slope(j0:j1) = 0.0_wp
         do k = 1, np
            column(target(k)) = column(target(k)) + weight(k)*f(k)
            column_slope(target(k)) = column_slope(target(k)) + weight(k)*df(k)
         end do
      end do
   end subroutine influence_column

   !> F(u) = ∫₀¹ √(1 − t²)/√(t² + u²) dt = √(1 + u²)(K(m) − E(m)), m = 1/(1 + u²), for every
   !> u > 0, and −u F'(u) = √m (E − (1 − m)(K − E)/m), the derivative of F(y/a) with respect to
   !> ln a (d(K − E)/dm = E/(2(1 − m))). Hastings' approximations of K and E (Abramowitz &
   !> Stegun 17.3.34, 17.3.36, |error| ≤ 2e-8) for m > [[series_below]], the series of (K − E)/m
   !> and E in m below (relative error ≤ 2e-6 overall). Both are evaluated at every point and
   !> one is selected, so that the loop has no branch and vectorises.
   pure subroutine line_kernels(u, f, df)
      real(wp), intent(in) :: u(:)
      real(wp), intent(out) :: f(:), df(:)
      real(wp) :: select, m, m1, l, kk, ee, d, q, root_m, d_series, e_series
      integer :: k
      ! √m and the logarithms first, in a loop of their own (df holds √m and f holds −ln m₁
      ! until the second loop): the vectorised log is a call, and a loop without other work
      ! keeps few values live across it. One square root and one division per point:
      ! √m = 1/√(1 + u²), m₁ = u² m, and /m is ·(1 + u²).
      do k = 1, size(u)
         root_m = 1.0_wp/sqrt(1.0_wp + u(k)*u(k))
         df(k) = root_m
         f(k) = -log(max(u(k)*u(k)*(root_m*root_m), tiny(1.0_wp)))
      end do
      do k = 1, size(u)
         q = 1.0_wp + u(k)*u(k)
         root_m = df(k)
         m = root_m*root_m
         m1 = u(k)*u(k)*m
         d_series = 0.25_wp*pi*(1.0_wp + m*(3.0_wp/8.0_wp + m*(15.0_wp/64.0_wp + &
            m*(175.0_wp/1024.0_wp + m*(2205.0_wp/16384.0_wp)))))
         e_series = 0.5_wp*pi*(1.0_wp - m*(0.25_wp + m*(3.0_wp/64.0_wp + m*(5.0_wp/256.0_wp + &
            m*(175.0_wp/16384.0_wp)))))
         l = f(k)
         kk = hastings_ka(0) + m1*(hastings_ka(1) + m1*(hastings_ka(2) + m1*(hastings_ka(3) + &
            m1*hastings_ka(4)))) + l*(hastings_kb(0) + m1*(hastings_kb(1) + m1*(hastings_kb(2) &
            + m1*(hastings_kb(3) + m1*hastings_kb(4)))))
         ee = 1.0_wp + m1*(hastings_ea(1) + m1*(hastings_ea(2) + m1*(hastings_ea(3) + &
            m1*hastings_ea(4)))) + l*m1*(hastings_eb(1) + m1*(hastings_eb(2) + &
            m1*(hastings_eb(3) + m1*hastings_eb(4))))
         d = (kk - ee)*q
         ! Select the series below series_below by arithmetic (a merge or an if is a branch
         ! that stops the vectorisation): select is 1 there, 0 above.
         select = 0.5_wp + sign(0.5_wp, series_below - m)
         d = d + select*(d_series - d)
         ee = ee + select*(e_series - ee)
         f(k) = d*root_m
         df(k) = root_m*(ee - m1*d)
      end do
   end subroutine line_kernels

end module shcontact_normal_strip_influence
