!> Kalker's creepage coefficients c₁₁, c₂₂, c₂₃ of the linear theory of rolling contact for an
!> elliptical contact with semi-axes a (rolling direction) and b (lateral), doc/theory.md §2.
!>
!> Linear theory (doc/theory.md §2.1, forces on the wheel, decision 2), with c = √(ab):
!> F_x = −G c² c₁₁ ν_x,  F_y = −G c² c₂₂ ν_y − G c³ c₂₃ φ.
!>
!> Interpolation of Kalker's Table E.3 (doc/theory.md §2.2, decision 7): g = min(a/b, b/a). On
!> the a > b branch the scaled quantities g·c₁₁, g·c₂₂ and g^{3/2}·c₂₃, which stay bounded as
!> g → 0, are interpolated linearly in g; on the a ≤ b branch c itself. Below g = 0.1 the
!> slender-ellipse asymptotes take over, blended linearly with the table's first interval
!> (extended) over g ∈ [0.08, 0.1], so that the coefficients are continuous in a/b. In ν a
!> quadratic Lagrange polynomial through ν = 0, 0.25, 0.5 of the reciprocals 1/c (doc/theory.md
!> §2.3), after the interpolation in g. (CONTACT's `linrol` scheme, which no input reached, was
!> removed in issue 26.)
module shcontact_tangential_kalker
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   implicit none
   private

   public :: kalker_coefficients, kalker_asymptotes
   public :: kalker_table_short, kalker_table_long, kalker_table_g, kalker_table_poisson
   public :: kalker_blend_start, kalker_blend_end, kalker_g_min


   !> Poisson ratios of the table columns.
   real(wp), parameter :: kalker_table_poisson(3) = [0.0_wp, 0.25_wp, 0.5_wp]
   !> g = min(a/b, b/a) of the table rows 1..10.
   real(wp), parameter :: kalker_table_g(10) = [0.1_wp, 0.2_wp, 0.3_wp, 0.4_wp, 0.5_wp, &
      0.6_wp, 0.7_wp, 0.8_wp, 0.9_wp, 1.0_wp]
   !> Below this g the scaled scheme uses the asymptotes alone.
   real(wp), parameter :: kalker_blend_start = 0.08_wp
   !> From this g up the scaled scheme uses the table alone.
   real(wp), parameter :: kalker_blend_end = 0.1_wp
   !> Smallest g used: more slender ellipses are evaluated at this g (no contact is that slender).
   real(wp), parameter :: kalker_g_min = 1.0e-8_wp

   !> Kalker 1990 Table E.3, branch a ≤ b (row r: a/b = r/10): index (ν column, coefficient
   !> c₁₁/c₂₂/c₂₃, row), doc/theory.md §2.2.
   real(wp), parameter :: kalker_table_short(3, 3, 10) = reshape([ &
      2.51_wp, 3.31_wp, 4.85_wp, 2.51_wp, 2.52_wp, 2.53_wp, 0.334_wp, 0.473_wp, 0.731_wp, &
      2.59_wp, 3.37_wp, 4.81_wp, 2.59_wp, 2.63_wp, 2.66_wp, 0.483_wp, 0.603_wp, 0.809_wp, &
      2.68_wp, 3.44_wp, 4.80_wp, 2.68_wp, 2.75_wp, 2.81_wp, 0.607_wp, 0.715_wp, 0.889_wp, &
      2.78_wp, 3.53_wp, 4.82_wp, 2.78_wp, 2.88_wp, 2.98_wp, 0.720_wp, 0.823_wp, 0.977_wp, &
      2.88_wp, 3.62_wp, 4.83_wp, 2.88_wp, 3.01_wp, 3.14_wp, 0.827_wp, 0.929_wp, 1.07_wp, &
      2.98_wp, 3.72_wp, 4.91_wp, 2.98_wp, 3.14_wp, 3.31_wp, 0.930_wp, 1.03_wp, 1.18_wp, &
      3.09_wp, 3.81_wp, 4.97_wp, 3.09_wp, 3.28_wp, 3.48_wp, 1.03_wp, 1.14_wp, 1.29_wp, &
      3.19_wp, 3.91_wp, 5.05_wp, 3.19_wp, 3.41_wp, 3.65_wp, 1.13_wp, 1.25_wp, 1.40_wp, &
      3.29_wp, 4.01_wp, 5.12_wp, 3.29_wp, 3.54_wp, 3.82_wp, 1.23_wp, 1.36_wp, 1.51_wp, &
      3.40_wp, 4.12_wp, 5.20_wp, 3.40_wp, 3.67_wp, 3.98_wp, 1.33_wp, 1.47_wp, 1.63_wp], &
      [3, 3, 10])

   !> Kalker 1990 Table E.3, branch a ≥ b (row r: b/a = r/10; row 10 is the circle, as in
   !> [[kalker_table_short]]): index (ν column, coefficient, row), doc/theory.md §2.2.
   real(wp), parameter :: kalker_table_long(3, 3, 10) = reshape([ &
      10.7_wp, 11.7_wp, 12.9_wp, 10.7_wp, 12.8_wp, 16.0_wp, 12.2_wp, 14.6_wp, 18.0_wp, &
      6.96_wp, 7.78_wp, 8.82_wp, 6.96_wp, 8.14_wp, 9.79_wp, 5.72_wp, 6.63_wp, 7.89_wp, &
      5.57_wp, 6.34_wp, 7.34_wp, 5.57_wp, 6.40_wp, 7.51_wp, 3.79_wp, 4.32_wp, 5.01_wp, &
      4.84_wp, 5.57_wp, 6.57_wp, 4.84_wp, 5.48_wp, 6.31_wp, 2.88_wp, 3.24_wp, 3.70_wp, &
      4.37_wp, 5.10_wp, 6.11_wp, 4.37_wp, 4.90_wp, 5.56_wp, 2.35_wp, 2.62_wp, 2.96_wp, &
      4.06_wp, 4.78_wp, 5.80_wp, 4.06_wp, 4.50_wp, 5.04_wp, 2.01_wp, 2.23_wp, 2.50_wp, &
      3.82_wp, 4.54_wp, 5.58_wp, 3.82_wp, 4.21_wp, 4.67_wp, 1.76_wp, 1.95_wp, 2.18_wp, &
      3.65_wp, 4.36_wp, 5.42_wp, 3.65_wp, 3.99_wp, 4.39_wp, 1.58_wp, 1.75_wp, 1.94_wp, &
      3.51_wp, 4.22_wp, 5.30_wp, 3.51_wp, 3.81_wp, 4.16_wp, 1.44_wp, 1.59_wp, 1.77_wp, &
      3.40_wp, 4.12_wp, 5.20_wp, 3.40_wp, 3.67_wp, 3.98_wp, 1.33_wp, 1.47_wp, 1.63_wp], &
      [3, 3, 10])


contains

   !> Kalker's coefficients c₁₁, c₂₂, c₂₃ at ellipticity a/b and Poisson ratio ν (doc/theory.md §2.3).
   !> a/b is clamped to [g_min, 1/g_min] (see [[kalker_g_min]]); callers validate a/b > 0.
   elemental subroutine kalker_coefficients(a_over_b, poisson, c11, c22, c23)
      !> Ellipticity a/b (semi-axis along x over semi-axis along y), > 0.
      real(wp), intent(in) :: a_over_b
      !> Poisson's ratio ν, 0 ≤ ν ≤ 0.5.
      real(wp), intent(in) :: poisson
      !> Longitudinal creepage coefficient c₁₁.
      real(wp), intent(out) :: c11
      !> Lateral creepage coefficient c₂₂.
      real(wp), intent(out) :: c22
      !> Lateral–spin coupling coefficient c₂₃.
      real(wp), intent(out) :: c23
      real(wp) :: g, w, c(3), c_asym(3)
      logical :: long

      call branch(a_over_b, g, long)

      if (g >= kalker_blend_end) then
         call table_interpolation(g, poisson, long, long, c)
      else if (g <= kalker_blend_start) then
         call asymptotes(g, poisson, long, c)
      else
         ! doc/theory.md §2.3, decision 7: blend over [0.08, 0.1] with the table's first interval
         ! extended below g = 0.1, so the coefficients are continuous at both ends.
         call table_interpolation(g, poisson, long, long, c)
         call asymptotes(g, poisson, long, c_asym)
         w = (g - kalker_blend_start)/(kalker_blend_end - kalker_blend_start)
         c = w*c + (1.0_wp - w)*c_asym
      end if
      c11 = c(1)
      c22 = c(2)
      c23 = c(3)
   end subroutine kalker_coefficients

   !> Kalker's slender-ellipse asymptotes (doc/theory.md §2.3; Kalker 1990 App. E) on the branch of
   !> a/b: a/b → 0 when a/b ≤ 1, b/a → 0 otherwise. Valid for small g = min(a/b, b/a).
   elemental subroutine kalker_asymptotes(a_over_b, poisson, c11, c22, c23)
      !> Ellipticity a/b, > 0.
      real(wp), intent(in) :: a_over_b
      !> Poisson's ratio ν.
      real(wp), intent(in) :: poisson
      !> Asymptotic c₁₁, c₂₂, c₂₃.
      real(wp), intent(out) :: c11, c22, c23
      real(wp) :: g, c(3)
      logical :: long

      call branch(a_over_b, g, long)
      call asymptotes(g, poisson, long, c)
      c11 = c(1)
      c22 = c(2)
      c23 = c(3)
   end subroutine kalker_asymptotes

   !> g = min(a/b, b/a), clamped to ≥ g_min, and whether a > b (the "long" branch).
   elemental subroutine branch(a_over_b, g, long)
      real(wp), intent(in) :: a_over_b
      real(wp), intent(out) :: g
      logical, intent(out) :: long

      long = a_over_b > 1.0_wp
      if (long) then
         g = 1.0_wp/a_over_b
      else
         g = a_over_b
      end if
      g = max(g, kalker_g_min)
   end subroutine branch

   !> Interpolate the table linearly in g (of g^p·c when `scaled`), then in ν (on 1/c). Below
   !> g = 0.1 the first interval is extended (used only inside the blend interval).
   pure subroutine table_interpolation(g, poisson, long, scaled, c)
      real(wp), intent(in) :: g, poisson
      logical, intent(in) :: long, scaled
      real(wp), intent(out) :: c(3)
      real(wp) :: t, c_nu(3, 3), lo(3, 3), hi(3, 3), w_lo(3), w_hi(3), g_lo, g_hi
      integer :: row, k

      row = min(max(int(10.0_wp*g), 1), 9)
      t = 10.0_wp*g - real(row, wp)
      if (long) then
         lo = kalker_table_long(:, :, row)
         hi = kalker_table_long(:, :, row + 1)
      else
         lo = kalker_table_short(:, :, row)
         hi = kalker_table_short(:, :, row + 1)
      end if
      ! Linear weights in g, of g·c₁₁, g·c₂₂, g^{3/2}·c₂₃ when scaled (doc/theory.md §2.3).
      w_lo = 1.0_wp - t
      w_hi = t
      if (scaled) then
         g_lo = kalker_table_g(row)
         g_hi = kalker_table_g(row + 1)
         w_lo = w_lo*scaling(g_lo)/scaling(g)
         w_hi = w_hi*scaling(g_hi)/scaling(g)
      end if
      do k = 1, 3
         c_nu(:, k) = w_lo(k)*lo(:, k) + w_hi(k)*hi(:, k)
      end do
      c = poisson_interpolation(c_nu, poisson)
   end subroutine table_interpolation

   !> The scale factors g, g, g^{3/2} of c₁₁, c₂₂, c₂₃ on the a > b branch (doc/theory.md §2.3).
   pure function scaling(g) result(f)
      real(wp), intent(in) :: g
      real(wp) :: f(3)
      f = [g, g, g*sqrt(g)]
   end function scaling

   !> Quadratic Lagrange interpolation in ν of 1/c through ν = 0, 0.25, 0.5 (doc/theory.md §2.3).
   pure function poisson_interpolation(c_nu, poisson) result(c)
      !> Coefficients at the three table columns: index (ν column, coefficient).
      real(wp), intent(in) :: c_nu(3, 3)
      real(wp), intent(in) :: poisson
      real(wp) :: c(3)
      real(wp) :: l0, l1, l2

      ! Lagrange basis on the nodes 0, 1/4, 1/2 (exactly 0 or 1 at the nodes).
      l0 = 8.0_wp*(poisson - 0.25_wp)*(poisson - 0.5_wp)
      l1 = -16.0_wp*poisson*(poisson - 0.5_wp)
      l2 = 8.0_wp*poisson*(poisson - 0.25_wp)
      c = 1.0_wp/(l0/c_nu(1, :) + l1/c_nu(2, :) + l2/c_nu(3, :))
   end function poisson_interpolation

   !> The asymptotes of doc/theory.md §2.3 at g (> 0) on the chosen branch.
   pure subroutine asymptotes(g, poisson, long, c)
      real(wp), intent(in) :: g, poisson
      logical, intent(in) :: long
      real(wp), intent(out) :: c(3)
      real(wp) :: lam, d, e
      real(wp), parameter :: ln4 = 1.386294361119890618834464242916_wp

      if (long) then
         ! b/a = g → 0, Λ = ln(16/g²).
         lam = log(16.0_wp/g**2)
         d = (1.0_wp - poisson)*lam + 2.0_wp*poisson
         e = lam - 2.0_wp*poisson
         c(1) = 2.0_wp*pi/(e*g)*(1.0_wp + (3.0_wp - ln4)/e)
         c(2) = 2.0_wp*pi/(g*d)*(1.0_wp + (1.0_wp - poisson)*(3.0_wp - ln4)/d)
         c(3) = 2.0_wp*pi/(3.0_wp*g**1.5_wp*((1.0_wp - poisson)*lam - 2.0_wp + 4.0_wp*poisson))
      else
         ! a/b = g → 0.
         c(1) = pi**2/(4.0_wp*(1.0_wp - poisson))
         c(2) = pi**2/4.0_wp
         c(3) = pi*sqrt(g)/(3.0_wp*(1.0_wp - poisson))*(1.0_wp + poisson*(log(16.0_wp/g) - 5.0_wp))
      end if
   end subroutine asymptotes

end module shcontact_tangential_kalker
