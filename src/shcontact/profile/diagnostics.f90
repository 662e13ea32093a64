!> What a measured profile's points say about how to use it (doc/profiles.md, *Measured profiles:
!> cant and smoothing*): whether a rail looks canted already, how noisy the points are, and the
!> smoothing length L_filt that noise calls for.
!>
!> * **Cant.** On a rail head the crown's highest point sits on the head's axis when the rail is
!>   upright and moves towards the field side by about R_crown·tan α when the head is turned by α
!>   towards the track centre (7.5 mm for a 300 mm crown at 1:40), while the gauge face moves
!>   little. The lateral distance d from the highest point (vertex of a parabola fitted to the
!>   crown's top 0.5 mm) to the gauge point 14 mm below it is measured and compared with the same
!>   distance of the built-in UIC60 (60E1) head turned through a range of angles, computed by the
!>   same procedure; the angle whose d matches is the estimate. It needs only the top and the
!>   gauge side, which partial measurements have; it assumes a 60E1-like head (crown R300, head
!>   72 mm wide), and side wear, which moves the gauge face towards the field, makes a canted
!>   rail look less canted.
!> * **Noise.** Cubic least-squares fits over 7 consecutive points in the frame of their chord;
!>   σ² is the median of the residual variances RSS/3 divided by 0.7887 (the median of χ²₃/3),
!>   so that corners and outliers do not inflate it.
!> * **Gaps and outliers.** The largest distance between consecutive points against their median
!>   spacing (a stretch where points are missing: the profile is a straight chord there), and
!>   the largest leave-one-out residual: each point against the cubic fitted to its six
!>   neighbours (three on each side) in their chord's frame (a single bad point, which the
!>   median noise estimate does not see, and which the spline turns into a curvature spike),
!>   among the points a running contact can reach (canonical z ≤ 25 mm; on a wheel, not beyond
!>   its flange tip) where the seven points
!>   turn by less than 30°.
!> * **Smoothing.** White noise σ at spacing h, smoothed by the spline (response
!>   1/(1 + (L_filt/L)⁴)), leaves a curvature noise σ_κ = C σ √h L_filt^(−5/2) with
!>   C² = (2π)⁴ π√2/8 (C ≈ 29.4); the suggested L_filt makes σ_κ equal to a tolerance, by default
!>   10 % of the curvature of a 300 mm rail crown.
module shcontact_profile_diagnostics
   use shcontact_core_kinds, only: wp
   use shcontact_math_statistics, only: median
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type
   use shcontact_profile_points, only: profile_type, profile_kind_wheel
   use shcontact_profile_builtin, only: builtin_profile
   implicit none
   private

   public :: noise_estimate_type, estimate_noise, curvature_noise, suggested_smoothing
   public :: rail_cant_type, estimate_rail_cant, head_offset
   public :: default_curvature_tolerance
   public :: point_anomaly_type, find_point_anomalies, gap_ratio, min_gap, outlier_sigmas, &
      min_outlier

   !> Curvature-noise tolerance (1/mm): 10 % of the curvature of a 300 mm rail crown.
   real(wp), parameter :: default_curvature_tolerance = 0.1_wp/300.0_wp
   !> Depth of the gauge point below the top (mm) and of the crown fit (mm).
   real(wp), parameter :: gauge_depth = 14.0_wp, crown_depth = 0.5_wp
   !> Points per noise window.
   integer, parameter :: window = 7
   !> A gap counts when it is this many median spacings long and at least min_gap (mm).
   real(wp), parameter :: gap_ratio = 10.0_wp, min_gap = 1.0_wp
   !> An outlier counts when its leave-one-out residual exceeds this many noise σ and
   !> min_outlier (mm): 0.02 mm at 0.3 mm spacing is a curvature spike of about 0.2 1/mm, 60
   !> times a 300 mm crown's.
   real(wp), parameter :: outlier_sigmas = 10.0_wp, min_outlier = 0.02_wp
   !> Outliers are sought where a running contact can be: canonical z up to this depth (mm)
   !> from the tape circle (wheel) or the top (rail). The last millimetres of a flange (S1002:
   !> 28 mm deep) touch only a climbing wheel, and its tip is where measurements are roughest.
   real(wp), parameter :: running_depth = 25.0_wp

   !> The largest gap and the largest outlier of a profile's points.
   type :: point_anomaly_type
      !> Largest distance between consecutive points (mm), from point gap_at to gap_at + 1.
      real(wp) :: gap = 0.0_wp
      integer :: gap_at = 0
      !> Median distance between consecutive points (mm).
      real(wp) :: spacing = 0.0_wp
      !> Largest leave-one-out residual (mm, normal to the chord) and its point (0: none).
      real(wp) :: outlier = 0.0_wp
      integer :: outlier_at = 0
      !> Whether the gap and the outlier count (gap_ratio, min_gap; outlier_sigmas,
      !> min_outlier against the noise σ).
      logical :: has_gap = .false., has_outlier = .false.
   end type point_anomaly_type

   !> The noise of a profile's points.
   type :: noise_estimate_type
      !> Noise normal to the profile (mm, rms).
      real(wp) :: sigma = 0.0_wp
      !> Median point spacing (mm).
      real(wp) :: spacing = 0.0_wp
      !> Number of 7-point windows used (0: too few points, sigma is 0).
      integer :: windows = 0
   end type noise_estimate_type

   !> The cant of a rail as its points show it.
   type :: rail_cant_type
      !> The estimate exists (the profile has a crown and a gauge face 14 mm deep).
      logical :: found = .false.
      !> Inclination of the head towards the track centre, as a slope (1:40 = 0.025; < 0: away
      !> from the track centre).
      real(wp) :: slope = 0.0_wp
      !> The measured distance from the highest point to the gauge point (mm), and the same
      !> distance of the built-in UIC60 upright.
      real(wp) :: offset = 0.0_wp, offset_upright = 0.0_wp
   end type rail_cant_type

contains

   !> The noise of the points of a profile (see the module description).
   pure subroutine estimate_noise(profile, estimate)
      !> A cleaned profile.
      type(profile_type), intent(in) :: profile
      !> The estimate.
      type(noise_estimate_type), intent(out) :: estimate
      real(wp), allocatable :: variances(:), gaps(:)
      real(wp) :: v
      integer :: i, n, m
      logical :: ok
      n = size(profile%y)
      if (n < window + 1) return
      gaps = hypot(profile%y(2:) - profile%y(:n - 1), profile%z(2:) - profile%z(:n - 1))
      estimate%spacing = median(gaps)
      allocate (variances(n))
      m = 0
      do i = 1, n - window + 1
         if (allocated(profile%kink)) then
            if (any(profile%kink(i + 1:i + window - 2))) cycle
         end if
         call window_variance(profile%y(i:i + window - 1), profile%z(i:i + window - 1), v, ok)
         if (.not. ok) cycle
         m = m + 1
         variances(m) = v
      end do
      estimate%windows = m
      if (m == 0) return
      ! Median of χ²₃/3 is 2.3660/3.
      estimate%sigma = sqrt(median(variances(:m))/(2.365974_wp/3.0_wp))
   end subroutine estimate_noise

   !> The largest gap and outlier of a profile's points (see the module description), judged
   !> against its median spacing and the noise σ of [[estimate_noise]].
   pure subroutine find_point_anomalies(read, cleaned, sigma, anomaly)
      !> The points as read (for the gaps: the clean-up refills long straight stretches) and
      !> as cleaned (for the outliers: the clean-up already merges zig-zags and back-steps).
      type(profile_type), intent(in) :: read, cleaned
      !> Their noise (mm rms).
      real(wp), intent(in) :: sigma
      !> The anomalies found.
      type(point_anomaly_type), intent(out) :: anomaly
      real(wp), allocatable :: gaps(:)
      real(wp) :: r
      integer :: n, j, last
      logical :: ok
      n = size(read%y)
      if (n < 2) return
      gaps = hypot(read%y(2:) - read%y(:n - 1), read%z(2:) - read%z(:n - 1))
      anomaly%spacing = median(gaps)
      anomaly%gap_at = maxloc(gaps, 1)
      anomaly%gap = gaps(anomaly%gap_at)
      anomaly%has_gap = anomaly%gap > max(gap_ratio*anomaly%spacing, min_gap)
      n = size(cleaned%y)
      ! A wheel (canonical order: field side to flange back) is judged up to its flange tip:
      ! the back face beyond it never touches the rail (a MiniProf wheel's note named a point
      ! of its flange back), whatever the profile's z origin.
      last = n - 3
      if (cleaned%kind == profile_kind_wheel) last = min(last, maxloc(cleaned%z, 1))
      do j = 4, last
         if (cleaned%z(j) > running_depth) cycle
         if (allocated(cleaned%kink)) then
            if (any(cleaned%kink(j - 2:j + 2))) cycle
         end if
         call leave_one_out(cleaned%y(j - 3:j + 3), cleaned%z(j - 3:j + 3), r, ok)
         if (ok .and. r > anomaly%outlier) then
            anomaly%outlier = r
            anomaly%outlier_at = j
         end if
      end do
      anomaly%has_outlier = anomaly%outlier > max(outlier_sigmas*sigma, min_outlier)
   end subroutine find_point_anomalies

   !> |residual| of the middle of seven points against the cubic fitted to the other six, in
   !> the frame of the seven points' chord; ok = .false. where they do not advance along it or
   !> turn by more than max_turn between their first and last segments (a flange tip, a
   !> corner: a cubic does not follow them, while a single bad point in the middle does not
   !> change that turn).
   pure subroutine leave_one_out(y, z, residual, ok)
      real(wp), intent(in) :: y(7), z(7)
      real(wp), intent(out) :: residual
      logical, intent(out) :: ok
      real(wp), parameter :: max_turn = 30.0_wp*pi/180.0_wp
      real(wp) :: xi(7), zeta(7), coef(4), turn
      integer, parameter :: others(6) = [1, 2, 3, 5, 6, 7]
      residual = 0.0_wp
      turn = abs(atan2((y(2) - y(1))*(z(7) - z(6)) - (z(2) - z(1))*(y(7) - y(6)), &
         (y(2) - y(1))*(y(7) - y(6)) + (z(2) - z(1))*(z(7) - z(6))))
      ok = turn <= max_turn
      if (ok) call chord_frame(y, z, xi, zeta, ok)
      if (.not. ok) return
      call polynomial_fit(xi(others), zeta(others), coef, ok)
      if (.not. ok) return
      residual = abs(zeta(4) - (coef(1) + xi(4)*(coef(2) + xi(4)*(coef(3) + xi(4)*coef(4)))))
   end subroutine leave_one_out

   !> Residual variance RSS/(7 − 4) of a cubic fitted to the points in their chord's frame;
   !> ok = .false. when the points do not advance along the chord (a turn of more than 90°).
   pure subroutine window_variance(y, z, variance, ok)
      real(wp), intent(in) :: y(:), z(:)
      real(wp), intent(out) :: variance
      logical, intent(out) :: ok
      real(wp) :: xi(size(y)), zeta(size(y)), coef(4)
      integer :: i
      variance = 0.0_wp
      call chord_frame(y, z, xi, zeta, ok)
      if (.not. ok) return
      call polynomial_fit(xi, zeta, coef, ok)
      if (.not. ok) return
      do i = 1, size(y)
         variance = variance + (zeta(i) - (coef(1) + xi(i)*(coef(2) + xi(i)*(coef(3) + &
            xi(i)*coef(4)))))**2
      end do
      variance = variance/real(size(y) - 4, wp)
   end subroutine window_variance

   !> Points in the frame of their chord: ξ along it (−1/2 … 1/2), ζ normal to it (mm);
   !> ok = .false. when the chord has no length or the points do not advance along it (a turn
   !> of more than 90°).
   pure subroutine chord_frame(y, z, xi, zeta, ok)
      real(wp), intent(in) :: y(:), z(:)
      real(wp), intent(out) :: xi(:), zeta(:)
      logical, intent(out) :: ok
      real(wp) :: c, s, length
      integer :: n
      n = size(y)
      xi = 0.0_wp
      zeta = 0.0_wp
      length = hypot(y(n) - y(1), z(n) - z(1))
      ok = length > 0.0_wp
      if (.not. ok) return
      c = (y(n) - y(1))/length
      s = (z(n) - z(1))/length
      xi = (c*(y - y(1)) + s*(z - z(1)))/length - 0.5_wp
      zeta = -s*(y - y(1)) + c*(z - z(1))
      ok = all(xi(2:) > xi(:n - 1))
   end subroutine chord_frame

   !> Least-squares polynomial f ≈ Σ coef(k) x^(k−1) of degree size(coef) − 1 (normal
   !> equations, Gaussian elimination with partial pivoting; a few coefficients only);
   !> ok = .false. when they are singular.
   pure subroutine polynomial_fit(x, f, coef, ok)
      real(wp), intent(in) :: x(:), f(:)
      real(wp), intent(out) :: coef(:)
      logical, intent(out) :: ok
      real(wp) :: a(size(coef), size(coef)), b(size(coef)), basis(size(coef)), row(size(coef)), &
         t, factor, scale
      integer :: i, k, p, n
      n = size(coef)
      a = 0.0_wp
      b = 0.0_wp
      do i = 1, size(x)
         basis = [(x(i)**(k - 1), k=1, n)]
         do k = 1, n
            a(:, k) = a(:, k) + basis*basis(k)
         end do
         b = b + basis*f(i)
      end do
      coef = 0.0_wp
      ok = .false.
      scale = maxval(abs(a))
      do k = 1, n
         p = k - 1 + maxloc(abs(a(k:, k)), 1)
         if (.not. abs(a(p, k)) > 1.0e-14_wp*scale) return
         row = a(k, :); a(k, :) = a(p, :); a(p, :) = row
         t = b(k); b(k) = b(p); b(p) = t
         do i = k + 1, n
            factor = a(i, k)/a(k, k)
            a(i, :) = a(i, :) - factor*a(k, :)
            b(i) = b(i) - factor*b(k)
         end do
      end do
      do k = n, 1, -1
         coef(k) = (b(k) - dot_product(a(k, k + 1:), coef(k + 1:)))/a(k, k)
      end do
      ok = .true.
   end subroutine polynomial_fit

   !> Curvature noise (1/mm, rms) left by smoothing white noise σ at spacing h with L_filt.
   elemental real(wp) function curvature_noise(sigma, spacing, l_filt) result(sigma_kappa)
      !> Noise (mm), point spacing (mm), smoothing length (mm, > 0).
      real(wp), intent(in) :: sigma, spacing, l_filt
      sigma_kappa = noise_constant()*sigma*sqrt(spacing)*l_filt**(-2.5_wp)
   end function curvature_noise

   !> The L_filt (mm) at which [[curvature_noise]] equals `tolerance` (1/mm; default
   !> [[default_curvature_tolerance]]).
   elemental real(wp) function suggested_smoothing(sigma, spacing, tolerance) result(l_filt)
      !> Noise (mm) and point spacing (mm).
      real(wp), intent(in) :: sigma, spacing
      !> Curvature-noise tolerance (1/mm).
      real(wp), intent(in), optional :: tolerance
      real(wp) :: tol
      tol = default_curvature_tolerance
      if (present(tolerance)) tol = tolerance
      l_filt = (noise_constant()*sigma*sqrt(spacing)/tol)**0.4_wp
   end function suggested_smoothing

   !> C = √((2π)⁴ π√2/8): ∫₀^∞ u⁴/(1 + u⁴)² du = π√2/16.
   pure real(wp) function noise_constant()
      noise_constant = sqrt((2.0_wp*pi)**4*pi*sqrt(2.0_wp)/8.0_wp)
   end function noise_constant

   !> The inclination of a rail head (see the module description).
   subroutine estimate_rail_cant(profile, cant)
      !> A cleaned rail profile in canonical form (gauge side first).
      type(profile_type), intent(in) :: profile
      !> The estimate; found = .false. without a crown or a gauge face 14 mm deep.
      type(rail_cant_type), intent(out) :: cant
      integer, parameter :: n_angles = 241
      real(wp) :: angles(n_angles), offsets(n_angles), d
      type(profile_type) :: reference
      type(error_type), allocatable :: error
      logical :: ok
      integer :: k
      call head_offset(profile%y, profile%z, d, ok)
      if (.not. ok) return
      call builtin_profile('UIC60', reference, error)
      if (allocated(error)) return
      do k = 1, n_angles
         angles(k) = -0.12_wp + 0.001_wp*(k - 1)
         call head_offset(cos(angles(k))*reference%y - sin(angles(k))*reference%z, &
            sin(angles(k))*reference%y + cos(angles(k))*reference%z, offsets(k), ok)
         if (.not. ok) return
      end do
      cant%offset = d
      cant%offset_upright = offsets(121)
      ! d falls as the angle grows (a canted head is turned by a negative angle).
      do k = 1, n_angles - 1
         if ((offsets(k) - d)*(offsets(k + 1) - d) <= 0.0_wp .and. offsets(k) /= offsets(k + 1)) &
            then
            cant%slope = -tan(angles(k) + (angles(k + 1) - angles(k))*(d - offsets(k))/ &
               (offsets(k + 1) - offsets(k)))
            cant%found = .true.
            return
         end if
      end do
   end subroutine estimate_rail_cant

   !> Lateral distance (mm) from the crown's highest point (vertex of a parabola fitted to the
   !> points within 0.5 mm of the top) to the gauge point 14 mm below it, walking from the top
   !> towards the first point; ok = .false. when the profile does not reach that deep there or
   !> does not fall by 0.5 mm on both sides of its highest point.
   pure subroutine head_offset(y, z, offset, ok)
      !> Rail points (mm, z down), gauge side first.
      real(wp), intent(in) :: y(:), z(:)
      !> The distance (mm).
      real(wp), intent(out) :: offset
      logical, intent(out) :: ok
      real(wp) :: y_top, z_top, level, basis(3), t, y0
      integer :: top, first, last, i
      offset = 0.0_wp
      ok = .false.
      top = minloc(z, 1)
      first = top
      last = top
      do while (first > 1)
         if (z(first - 1) > z(top) + crown_depth) exit
         first = first - 1
      end do
      do while (last < size(z))
         if (z(last + 1) > z(top) + crown_depth) exit
         last = last + 1
      end do
      ! A crown falls away on both sides; a top at the end of the points is no crown.
      if (first == 1 .or. last == size(z)) return
      y_top = y(top)
      z_top = z(top)
      if (last - first >= 4) then
         y0 = y(top)
         call polynomial_fit(y(first:last) - y0, z(first:last), basis, ok)
         if (ok .and. basis(3) > 0.0_wp) then
            t = -basis(2)/(2.0_wp*basis(3))
            if (y0 + t >= y(first) .and. y0 + t <= y(last)) then
               y_top = y0 + t
               z_top = basis(1) + t*(basis(2) + t*basis(3))
            end if
         end if
      end if
      ok = .false.
      level = z_top + gauge_depth
      do i = top, 2, -1
         if (z(i - 1) >= level .and. z(i) < level) then
            offset = y_top - (y(i) + (y(i - 1) - y(i))*(level - z(i))/(z(i - 1) - z(i)))
            ok = .true.
            return
         end if
      end do
   end subroutine head_offset

end module shcontact_profile_diagnostics

