!> Weighted smoothing spline of a profile in arc length (doc/theory.md §5.5, project decision 4).
!>
!> Both coordinates y(s) and z(s) are fitted as functions of the summed chord length s of the
!> raw points. With L_filt > 0 each minimises
!>
!>     Σ_i w_i |x_i − f(s_i)|² + λ ∫ |f''|² ds,   w_i = (s_{i+1} − s_{i−1})/2,   λ = (L_filt/2π)⁴
!>
!> (Reinsch's formulation: a natural cubic spline with knots at the points, one symmetric
!> positive definite pentadiagonal system for both coordinates). It is a low-pass filter whose
!> response to a wavelength L is 1/(1 + (L_filt/L)⁴): half at L = L_filt. With L_filt = 0 it
!> interpolates with not-a-knot end conditions, so it reproduces any cubic exactly (a natural
!> spline would not). The spline splits at the profile's kink points, so genuine corners survive.
!>
!> Curvature sign: κ = (y'z'' − z'y'')/(y'² + z'²)^{3/2}. Walking the points with the material on
!> the right (doc/theory.md §5.1), κ > 0 where the surface is convex (bulges away from its
!> material), for the rail and the wheel alike.
module shcontact_profile_spline
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: two_pi
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_invalid_input
   use shcontact_math_lapack, only: solve_spd_banded, solve_general_banded
   use shcontact_profile_points, only: profile_type
   implicit none
   private

   public :: profile_spline_type, spline_point_type, profile_label

   !> Position and derivatives with respect to arc length of a spline at one parameter value.
   type :: spline_point_type
      !> Arc-length parameter (mm).
      real(wp) :: s = 0.0_wp
      !> Position (mm).
      real(wp) :: y = 0.0_wp, z = 0.0_wp
      !> First derivatives dy/ds, dz/ds.
      real(wp) :: dy = 0.0_wp, dz = 0.0_wp
      !> Second derivatives d²y/ds², d²z/ds² (1/mm).
      real(wp) :: d2y = 0.0_wp, d2z = 0.0_wp
   end type spline_point_type

   !> A profile as a piecewise cubic in arc length, one cubic per interval between raw points.
   type :: profile_spline_type
      !> Smoothing length used for the fit (mm); 0 interpolates.
      real(wp) :: l_filt = 0.0_wp
      !> Knots: the arc length of the raw points (mm), strictly increasing.
      real(wp), allocatable :: s(:)
      !> Coefficients of y on interval k: y = cy(1,k) + cy(2,k) t + cy(3,k) t² + cy(4,k) t³,
      !> t = s − s(k).
      real(wp), allocatable :: cy(:, :)
      !> Coefficients of z, as for y.
      real(wp), allocatable :: cz(:, :)
      !> True at knots where the spline was split (slope may jump there).
      logical, allocatable :: kink(:)
   contains
      !> Fit the spline to a profile's points.
      procedure :: fit
      !> Number of knots.
      procedure :: size => knot_count
      !> Total arc length (mm).
      procedure :: length
      !> Interval holding a parameter value.
      procedure :: interval
      !> Position and derivatives at an arc length.
      procedure :: eval
      !> Curvature at an arc length.
      procedure :: curvature
      !> Arc length at which y(s) takes a value.
      procedure :: locate_y
      !> ay·y(s) + az·z(s) on one interval.
      procedure :: projection
      !> Where ay·y(s) + az·z(s) takes a value inside one interval.
      procedure :: solve_in_interval
      !> z, dz/dy, d²z/dy² at a lateral position on a single-valued part.
      procedure :: z_of_y
   end type profile_spline_type

contains

   !> Fit the smoothing spline to `profile` (its y, z, s and kink flags; s is recomputed from the
   !> points when it is not allocated). Fails on fewer than 2 points, non-increasing s
   !> (duplicate points) or a negative L_filt.
   subroutine fit(self, profile, l_filt, error)
      !> The spline, replaced.
      class(profile_spline_type), intent(out) :: self
      !> The raw profile points.
      type(profile_type), intent(in) :: profile
      !> Smoothing length L_filt (mm, ≥ 0); 0 interpolates.
      real(wp), intent(in) :: l_filt
      !> Set on invalid input or a failed linear solve.
      type(error_type), allocatable, intent(out) :: error
      integer :: n, i, first, last
      character(len=48) :: buf

      n = profile%size()
      if (n < 2) then
         write (buf, '(i0)') n
         call fatal_error(error, 'spline fit: the profile has '//trim(buf)// &
            ' point(s); at least 2 are needed')
         call prefix_error(error, profile_label(profile))
         return
      end if
      if (.not. (l_filt >= 0.0_wp)) then
         write (buf, '(es12.4)') l_filt
         call fatal_error(error, 'spline fit: L_filt = '//trim(adjustl(buf))// &
            ' mm; expected a length ≥ 0')
         return
      end if
      self%l_filt = l_filt
      if (allocated(profile%s)) then
         if (size(profile%s) == n) then
            self%s = profile%s
         end if
      end if
      if (.not. allocated(self%s)) call chord_lengths(profile%y, profile%z, self%s)
      do i = 2, n
         if (.not. (self%s(i) > self%s(i - 1))) then
            write (buf, '(i0,a,i0)') i - 1, ' and ', i
            call fatal_error(error, 'spline fit: points '//trim(buf)// &
               ' coincide (arc length does not increase); remove duplicate points')
            call prefix_error(error, profile_label(profile))
            return
         end if
      end do

      allocate (self%cy(4, n - 1), self%cz(4, n - 1))
      allocate (self%kink(n), source=.false.)
      if (allocated(profile%kink)) then
         if (size(profile%kink) == n) self%kink(2:n - 1) = profile%kink(2:n - 1)
      end if

      ! One independent spline per piece between kinks (doc/theory.md §5.5: kinks survive).
      first = 1
      do last = 2, n
         if (last < n .and. .not. self%kink(last)) cycle
         call fit_piece(self%s(first:last), profile%y(first:last), profile%z(first:last), &
            smoothing_weight(l_filt), self%cy(:, first:last - 1), self%cz(:, first:last - 1), &
            error)
         if (allocated(error)) then
            call prefix_error(error, profile_label(profile))
            return
         end if
         first = last
      end do
   end subroutine fit

   !> λ = (L_filt/2π)⁴ (doc/theory.md §5.5).
   pure real(wp) function smoothing_weight(l_filt)
      real(wp), intent(in) :: l_filt
      smoothing_weight = (l_filt/two_pi)**4
   end function smoothing_weight

   !> Name of a profile for messages: its source, or "profile".
   pure function profile_label(profile) result(name)
      !> The profile.
      type(profile_type), intent(in) :: profile
      character(len=:), allocatable :: name
      if (allocated(profile%source)) then
         name = profile%source
      else
         name = 'profile'
      end if
   end function profile_label

   !> Summed chord length of a point list.
   pure subroutine chord_lengths(y, z, s)
      real(wp), intent(in) :: y(:), z(:)
      real(wp), allocatable, intent(out) :: s(:)
      integer :: i
      allocate (s(size(y)))
      s(1) = 0.0_wp
      do i = 2, size(y)
         s(i) = s(i - 1) + hypot(y(i) - y(i - 1), z(i) - z(i - 1))
      end do
   end subroutine chord_lengths

   !> Fit one piece (no interior kinks): knot values and second derivatives of y and z, then
   !> the polynomial coefficients of each interval.
   pure subroutine fit_piece(s, y, z, lambda, cy, cz, error)
      real(wp), intent(in) :: s(:), y(:), z(:), lambda
      real(wp), intent(out) :: cy(:, :), cz(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: val(size(s), 2), m2(size(s), 2)
      integer :: n

      n = size(s)
      val(:, 1) = y
      val(:, 2) = z
      if (n == 2) then
         m2 = 0.0_wp
      else if (n == 3 .and. .not. lambda > 0.0_wp) then
         call parabola(s, val, m2)
      else if (.not. lambda > 0.0_wp) then
         call not_a_knot(s, val, m2, error)
      else
         call reinsch(s, lambda, val, m2, error)
      end if
      if (allocated(error)) return
      call coefficients(s, val(:, 1), m2(:, 1), cy)
      call coefficients(s, val(:, 2), m2(:, 2), cz)
   end subroutine fit_piece

   !> Three points, no smoothing: the interpolating parabola (constant second derivative).
   pure subroutine parabola(s, val, m2)
      real(wp), intent(in) :: s(3), val(3, 2)
      real(wp), intent(out) :: m2(3, 2)
      integer :: j
      do j = 1, 2
         m2(:, j) = 2.0_wp*((val(3, j) - val(2, j))/(s(3) - s(2)) &
            - (val(2, j) - val(1, j))/(s(2) - s(1)))/(s(3) - s(1))
      end do
   end subroutine parabola

   !> Interpolating cubic spline with not-a-knot ends (third derivative continuous at the second
   !> and the last-but-one knot): second derivatives M from a band system with kl = ku = 2.
   pure subroutine not_a_knot(s, val, m2, error)
      real(wp), intent(in) :: s(:), val(:, :)
      real(wp), intent(out) :: m2(:, :)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: kl = 2, ku = 2, row0 = kl + ku + 1
      real(wp) :: ab(2*kl + ku + 1, size(s)), h(size(s) - 1)
      integer :: i, n

      n = size(s)
      h = s(2:n) - s(1:n - 1)
      ! Band storage: a(i, j) goes to ab(kl + ku + 1 + i − j, j).
      ab = 0.0_wp
      ! Row 1: h₂ M₁ − (h₁ + h₂) M₂ + h₁ M₃ = 0.
      ab(row0, 1) = h(2); ab(row0 - 1, 2) = -(h(1) + h(2)); ab(row0 - 2, 3) = h(1)
      m2(1, :) = 0.0_wp
      do i = 2, n - 1
         ab(row0 + 1, i - 1) = h(i - 1)
         ab(row0, i) = 2.0_wp*(h(i - 1) + h(i))
         ab(row0 - 1, i + 1) = h(i)
         m2(i, :) = 6.0_wp*((val(i + 1, :) - val(i, :))/h(i) - (val(i, :) - val(i - 1, :))/h(i - 1))
      end do
      ! Row n: h_{n−1} M_{n−2} − (h_{n−2} + h_{n−1}) M_{n−1} + h_{n−2} M_n = 0.
      ab(row0 + 2, n - 2) = h(n - 1); ab(row0 + 1, n - 1) = -(h(n - 2) + h(n - 1))
      ab(row0, n) = h(n - 2)
      m2(n, :) = 0.0_wp
      call solve_general_banded(ab, kl, ku, m2, error)
   end subroutine not_a_knot

   !> Reinsch's smoothing spline: (R + λ Qᵀ W⁻¹ Q) M = Qᵀ x for the interior second derivatives
   !> (natural ends M₁ = M_n = 0), then the knot values a = x − λ W⁻¹ Q M. `val` holds x on
   !> entry and a on return.
   pure subroutine reinsch(s, lambda, val, m2, error)
      real(wp), intent(in) :: s(:), lambda
      real(wp), intent(inout) :: val(:, :)
      real(wp), intent(out) :: m2(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: h(size(s) - 1), w(size(s)), qlo(size(s) - 2), qmid(size(s) - 2), &
         qhi(size(s) - 2), ab(3, size(s) - 2), qm(size(s), 2), rhs(size(s) - 2, 2)
      integer :: j, m, n

      n = size(s); m = n - 2
      h = s(2:n) - s(1:n - 1)
      w(1) = 0.5_wp*h(1)
      w(n) = 0.5_wp*h(n - 1)
      w(2:n - 1) = 0.5_wp*(h(1:n - 2) + h(2:n - 1))
      ! Column j of Q (knot j + 1) has entries in rows j, j + 1, j + 2.
      qlo = 1.0_wp/h(1:m)
      qhi = 1.0_wp/h(2:m + 1)
      qmid = -qlo - qhi
      ! Upper band storage: diagonal in row 3, first and second super-diagonals in rows 2, 1.
      ab = 0.0_wp
      do j = 1, m
         ab(3, j) = (h(j) + h(j + 1))/3.0_wp + lambda*(qlo(j)**2/w(j) + qmid(j)**2/w(j + 1) &
            + qhi(j)**2/w(j + 2))
         rhs(j, :) = qlo(j)*val(j, :) + qmid(j)*val(j + 1, :) + qhi(j)*val(j + 2, :)
      end do
      do j = 2, m
         ab(2, j) = h(j)/6.0_wp + lambda*(qmid(j - 1)*qlo(j)/w(j) + qhi(j - 1)*qmid(j)/w(j + 1))
      end do
      do j = 3, m
         ab(1, j) = lambda*qhi(j - 2)*qlo(j)/w(j)
      end do
      call solve_spd_banded(ab, rhs, error)
      if (allocated(error)) return
      m2(2:n - 1, :) = rhs
      m2(1, :) = 0.0_wp
      m2(n, :) = 0.0_wp
      ! (Q M)_r from the three columns touching row r.
      qm = 0.0_wp
      do j = 1, m
         qm(j, :) = qm(j, :) + qlo(j)*m2(j + 1, :)
         qm(j + 1, :) = qm(j + 1, :) + qmid(j)*m2(j + 1, :)
         qm(j + 2, :) = qm(j + 2, :) + qhi(j)*m2(j + 1, :)
      end do
      do j = 1, 2
         val(:, j) = val(:, j) - lambda*qm(:, j)/w
      end do
   end subroutine reinsch

   !> Polynomial coefficients per interval from knot values a and second derivatives M.
   pure subroutine coefficients(s, a, m2, c)
      real(wp), intent(in) :: s(:), a(:), m2(:)
      real(wp), intent(out) :: c(:, :)
      integer :: k
      real(wp) :: h
      do k = 1, size(s) - 1
         h = s(k + 1) - s(k)
         c(1, k) = a(k)
         c(2, k) = (a(k + 1) - a(k))/h - h*(2.0_wp*m2(k) + m2(k + 1))/6.0_wp
         c(3, k) = 0.5_wp*m2(k)
         c(4, k) = (m2(k + 1) - m2(k))/(6.0_wp*h)
      end do
   end subroutine coefficients

   !> Number of knots.
   pure integer function knot_count(self)
      class(profile_spline_type), intent(in) :: self
      knot_count = 0
      if (allocated(self%s)) knot_count = size(self%s)
   end function knot_count

   !> Total arc length (mm).
   pure real(wp) function length(self)
      class(profile_spline_type), intent(in) :: self
      length = self%s(size(self%s)) - self%s(1)
   end function length

   !> Index k of the interval [s(k), s(k+1)] holding s (clamped to the first and last interval;
   !> at a knot, the interval to its right). `hint` speeds up searches that move little.
   pure integer function interval(self, s, hint) result(k)
      class(profile_spline_type), intent(in) :: self
      !> Arc length (mm).
      real(wp), intent(in) :: s
      !> A guess of the interval.
      integer, intent(in), optional :: hint
      integer :: lo, hi, mid, n

      n = size(self%s)
      if (present(hint)) then
         k = min(max(hint, 1), n - 1)
         if (s >= self%s(k) .and. s < self%s(k + 1)) return
         if (k < n - 1) then
            if (s >= self%s(k + 1) .and. s < self%s(k + 2)) then
               k = k + 1
               return
            end if
         end if
         if (k > 1) then
            if (s >= self%s(k - 1) .and. s < self%s(k)) then
               k = k - 1
               return
            end if
         end if
      end if
      lo = 1; hi = n
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (s >= self%s(mid)) then
            lo = mid
         else
            hi = mid
         end if
      end do
      k = min(lo, n - 1)
   end function interval

   !> Position and derivatives at arc length s; s is clamped to the spline's range.
   pure type(spline_point_type) function eval(self, s, hint) result(p)
      class(profile_spline_type), intent(in) :: self
      !> Arc length (mm).
      real(wp), intent(in) :: s
      !> A guess of the interval (see [[interval]]).
      integer, intent(in), optional :: hint
      integer :: k
      real(wp) :: t

      p%s = min(max(s, self%s(1)), self%s(size(self%s)))
      k = self%interval(p%s, hint)
      t = p%s - self%s(k)
      call cubic(self%cy(:, k), t, p%y, p%dy, p%d2y)
      call cubic(self%cz(:, k), t, p%z, p%dz, p%d2z)
   end function eval

   !> Value and two derivatives of c1 + c2 t + c3 t² + c4 t³.
   pure subroutine cubic(c, t, f, df, d2f)
      real(wp), intent(in) :: c(4), t
      real(wp), intent(out) :: f, df, d2f
      f = c(1) + t*(c(2) + t*(c(3) + t*c(4)))
      df = c(2) + t*(2.0_wp*c(3) + 3.0_wp*t*c(4))
      d2f = 2.0_wp*c(3) + 6.0_wp*t*c(4)
   end subroutine cubic

   !> Signed curvature κ (1/mm) at arc length s, > 0 where convex (see the module header).
   pure real(wp) function curvature(self, s)
      class(profile_spline_type), intent(in) :: self
      !> Arc length (mm).
      real(wp), intent(in) :: s
      type(spline_point_type) :: p
      p = self%eval(s)
      curvature = (p%dy*p%d2z - p%dz*p%d2y)/hypot(p%dy, p%dz)**3
   end function curvature

   !> The first arc length in [s_lo, s_hi] (default: the whole spline) where y(s) = y.
   !> `found` is false when y is not crossed there.
   pure subroutine locate_y(self, y, s, found, s_lo, s_hi)
      class(profile_spline_type), intent(in) :: self
      !> Lateral position sought (mm).
      real(wp), intent(in) :: y
      !> Arc length of the crossing (mm).
      real(wp), intent(out) :: s
      !> Whether a crossing was found.
      logical, intent(out) :: found
      !> Search range (mm).
      real(wp), intent(in), optional :: s_lo, s_hi
      real(wp) :: lo, hi, ya, yb
      integer :: k

      lo = self%s(1); hi = self%s(size(self%s))
      if (present(s_lo)) lo = max(lo, s_lo)
      if (present(s_hi)) hi = min(hi, s_hi)
      found = .false.
      s = lo
      if (hi < lo) return
      do k = self%interval(lo), self%interval(hi)
         ya = self%projection(max(lo, self%s(k)), 1.0_wp, 0.0_wp, k)
         yb = self%projection(min(hi, self%s(k + 1)), 1.0_wp, 0.0_wp, k)
         if ((ya - y)*(yb - y) > 0.0_wp) cycle
         s = self%solve_in_interval(k, 1.0_wp, 0.0_wp, y, max(lo, self%s(k)), &
            min(hi, self%s(k + 1)))
         found = .true.
         return
      end do
   end subroutine locate_y

   !> ay·y(s) + az·z(s): the position projected on a direction, using interval k's cubic.
   pure real(wp) function projection(self, s, ay, az, k)
      class(profile_spline_type), intent(in) :: self
      !> Arc length (mm), inside or at the ends of interval k.
      real(wp), intent(in) :: s
      !> Direction components.
      real(wp), intent(in) :: ay, az
      !> Interval whose cubic is used.
      integer, intent(in) :: k
      real(wp) :: t, c(4)
      t = s - self%s(k)
      c = ay*self%cy(:, k) + az*self%cz(:, k)
      projection = c(1) + t*(c(2) + t*(c(3) + t*c(4)))
   end function projection

   !> The arc length in [a, b] ⊂ interval k where ay·y(s) + az·z(s) = target, given that the
   !> projection changes sign there (default [a, b] = the whole interval). Newton steps from
   !> `guess` (default: the middle) kept inside a shrinking bracket, bisection when a step would
   !> leave it.
   pure real(wp) function solve_in_interval(self, k, ay, az, target, a, b, guess) result(s)
      class(profile_spline_type), intent(in) :: self
      !> Interval.
      integer, intent(in) :: k
      !> Direction components.
      real(wp), intent(in) :: ay, az
      !> Value sought.
      real(wp), intent(in) :: target
      !> Sub-range of the interval (mm).
      real(wp), intent(in), optional :: a, b
      !> Starting point (mm), e.g. the previous solution when following a curve.
      real(wp), intent(in), optional :: guess
      real(wp) :: c(4), lo, hi, f, df, d2f, flo, step
      integer :: it

      c = ay*self%cy(:, k) + az*self%cz(:, k)
      c(1) = c(1) - target
      lo = self%s(k); hi = self%s(k + 1)
      if (present(a)) lo = a
      if (present(b)) hi = b
      call cubic(c, lo - self%s(k), flo, df, d2f)
      s = 0.5_wp*(lo + hi)
      if (present(guess)) then
         if (guess > lo .and. guess < hi) s = guess
      end if
      do it = 1, 100
         call cubic(c, s - self%s(k), f, df, d2f)
         if ((f < 0.0_wp) .eqv. (flo < 0.0_wp)) then
            lo = s; flo = f
         else
            hi = s
         end if
         if (abs(df)*(hi - lo) > abs(f)) then
            ! The Newton step stays inside the bracket only if |f/df| < hi − lo.
            step = f/df
            if (s - step > lo .and. s - step < hi) then
               s = s - step
               if (abs(step) <= 8.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(s))) return
               cycle
            end if
         end if
         s = 0.5_wp*(lo + hi)
         if (hi - lo <= 4.0_wp*epsilon(1.0_wp)*max(1.0_wp, abs(s))) return
      end do
   end function solve_in_interval

   !> z(y), dz/dy and d²z/dy² at the first crossing of y in [s_lo, s_hi] (see [[locate_y]]).
   !> `found` is false where y is not crossed or the profile is vertical there.
   pure subroutine z_of_y(self, y, z, dzdy, d2zdy2, found, s_lo, s_hi)
      class(profile_spline_type), intent(in) :: self
      !> Lateral position (mm).
      real(wp), intent(in) :: y
      !> Height (mm), slope, and second derivative (1/mm) of the profile as a graph z(y).
      real(wp), intent(out) :: z, dzdy, d2zdy2
      !> Whether y lies on the profile with a finite slope.
      logical, intent(out) :: found
      !> Search range in arc length (mm).
      real(wp), intent(in), optional :: s_lo, s_hi
      type(spline_point_type) :: p
      real(wp) :: s

      z = 0.0_wp; dzdy = 0.0_wp; d2zdy2 = 0.0_wp
      call self%locate_y(y, s, found, s_lo, s_hi)
      if (.not. found) return
      p = self%eval(s)
      found = abs(p%dy) > 1.0e-12_wp
      if (.not. found) return
      z = p%z
      dzdy = p%dz/p%dy
      d2zdy2 = (p%d2z*p%dy - p%dz*p%d2y)/p%dy**3
   end subroutine z_of_y

end module shcontact_profile_spline
