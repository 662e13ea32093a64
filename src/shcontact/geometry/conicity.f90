!> Equivalent conicity of a rolling-radius-difference function Δr(y) (doc/geometry.md,
!> *Wheelset contact geometry and equivalent conicity*).
!>
!> Two linearisations of Δr over a wheelset motion of amplitude ŷ:
!>
!> * [[conicity_en15302]] (the default): the wavelength of the nonlinear kinematic (Klingel)
!>   motion, as EN 15302 / UIC 519 compute it by integrating the equation of motion
!>   y'' = −Δr(y)/(e r₀) between the turning points y₁ < y₂ with y₂ − y₁ = 2ŷ and
!>   ∫_{y₁}^{y₂} Δr dy = 0; the equivalent conicity is the cone's whose Klingel wavelength
!>   L = 2π √(e r₀/(2 tan γ_e)) is the same: tan γ_e = (2π/L)² e r₀/2. e and r₀ cancel, so
!>   tan γ_e depends on Δr(y) only.
!> * [[conicity_harmonic]]: the first-harmonic (describing-function) balance, tan γ_e equal to
!>   the first Fourier coefficient of Δr(ŷ sin θ) divided by 2ŷ.
!>
!> Both give tan γ for a cone (Δr = 2y tan γ) at every amplitude.
module shcontact_geometry_conicity
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_numerical
   use shcontact_geometry_track, only: str => real_text
   implicit none
   private

   public :: conicity_en15302, conicity_harmonic, equivalent_conicity, first_harmonic_slope
   public :: klingel_wavelength, conicity_method_name, linear_value

   !> Wavelength of the kinematic motion (EN 15302 / UIC 519, Klingel integration).
   integer, parameter :: conicity_en15302 = 1
   !> First-harmonic balance of Δr over y = ŷ sin θ.
   integer, parameter :: conicity_harmonic = 2

   !> Quadrature points over half a period (θ or the phase of the motion).
   integer, parameter :: n_quad = 4000

contains

   !> The name of a conicity method for tables and messages.
   pure function conicity_method_name(method) result(name)
      !> [[conicity_en15302]] or [[conicity_harmonic]].
      integer, intent(in) :: method
      character(len=:), allocatable :: name
      select case (method)
      case (conicity_en15302)
         name = 'EN 15302 wavelength'
      case (conicity_harmonic)
         name = 'first harmonic'
      case default
         name = 'unknown'
      end select
   end function conicity_method_name

   !> Equivalent conicity tan γ_e of Δr(y) for the amplitude ŷ.
   pure subroutine equivalent_conicity(y, delta_r, amplitude, tan_gamma_e, error, method)
      !> Lateral shifts (mm), strictly increasing.
      real(wp), intent(in) :: y(:)
      !> Rolling-radius difference r_R − r_L at y (mm); Δr is linear between the points.
      real(wp), intent(in) :: delta_r(:)
      !> Amplitude ŷ of the wheelset motion (mm), half its peak-to-peak excursion.
      real(wp), intent(in) :: amplitude
      !> The equivalent conicity (−).
      real(wp), intent(out) :: tan_gamma_e
      !> stat_invalid_input for bad tables or an amplitude beyond the table; stat_numerical when
      !> Δr does not turn the wheelset back (no oscillation of that amplitude).
      type(error_type), allocatable, intent(out) :: error
      !> [[conicity_en15302]] (default) or [[conicity_harmonic]].
      integer, intent(in), optional :: method
      integer :: m
      tan_gamma_e = 0.0_wp
      m = conicity_en15302
      if (present(method)) m = method
      call check_table(y, delta_r, amplitude, error)
      if (allocated(error)) return
      select case (m)
      case (conicity_en15302)
         call wavelength_conicity(y, delta_r, amplitude, tan_gamma_e, error)
      case (conicity_harmonic)
         if (-amplitude < y(1) .or. amplitude > y(size(y))) then
            call fatal_error(error, 'equivalent conicity: amplitude '//str(amplitude)// &
               ' mm beyond the table ('//str(y(1))//' to '//str(y(size(y)))//' mm)', &
               stat_invalid_input)
            return
         end if
         tan_gamma_e = 0.5_wp*first_harmonic_slope(y, delta_r, amplitude)
      case default
         call fatal_error(error, 'equivalent conicity: unknown method', stat_invalid_input)
      end select
   end subroutine equivalent_conicity

   !> The Klingel wavelength L = 2π √(e r₀/(2 tan γ_e)) (mm) of a wheelset with equivalent
   !> conicity tan γ_e, contact-point distance e and rolling radius r₀.
   elemental real(wp) function klingel_wavelength(tan_gamma_e, e, r0) result(wavelength)
      !> Equivalent conicity (−), > 0.
      real(wp), intent(in) :: tan_gamma_e
      !> Distance between the contact points (mm).
      real(wp), intent(in) :: e
      !> Rolling radius (mm).
      real(wp), intent(in) :: r0
      wavelength = 2.0_wp*pi*sqrt(e*r0/(2.0_wp*tan_gamma_e))
   end function klingel_wavelength

   !> (1/(π ŷ)) ∫₀^{2π} f(ŷ sin θ) sin θ dθ: the slope of the first-harmonic linearisation of
   !> f(y) over y = ŷ sin θ (k for f = k·y + c), f linear between the table points and constant
   !> beyond them.
   pure real(wp) function first_harmonic_slope(y, f, amplitude) result(slope)
      !> Abscissae (mm), strictly increasing.
      real(wp), intent(in) :: y(:)
      !> Values at y.
      real(wp), intent(in) :: f(:)
      !> Amplitude ŷ (mm), > 0.
      real(wp), intent(in) :: amplitude
      real(wp) :: theta, total
      integer :: i
      ! Midpoint rule on the periodic integrand: exact for the first harmonic, and the odd part
      ! f(ŷ sin θ) − f(−ŷ sin θ) makes the half period [−π/2, π/2] enough.
      total = 0.0_wp
      do i = 1, n_quad
         theta = -0.5_wp*pi + pi*(i - 0.5_wp)/n_quad
         total = total + (linear_value(y, f, amplitude*sin(theta)) &
            - linear_value(y, f, -amplitude*sin(theta)))*sin(theta)
      end do
      slope = total*(pi/n_quad)/(pi*amplitude)
   end function first_harmonic_slope

   !> EN 15302: the turning points y₁ = c − ŷ, y₂ = c + ŷ with ∫_{y₁}^{y₂} Δr dy = 0, then half
   !> the wavelength X = ∫ dy/ψ with ψ² = 2 (V(y₂) − V(y)), V = ∫ Δr dy (e r₀ = 1, which cancels),
   !> on y = c + ŷ sin t so that the ends are regular; tan γ_e = (2π/(2X))²/2.
   pure subroutine wavelength_conicity(y, delta_r, amplitude, tan_gamma_e, error)
      real(wp), intent(in) :: y(:), delta_r(:), amplitude
      real(wp), intent(out) :: tan_gamma_e
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: cum(size(y)), lo, hi, c, g_lo, g_hi, g, v2, t, yy, dv, half
      integer :: i, n

      tan_gamma_e = 0.0_wp
      n = size(y)
      cum(1) = 0.0_wp
      do i = 2, n
         cum(i) = cum(i - 1) + 0.5_wp*(delta_r(i) + delta_r(i - 1))*(y(i) - y(i - 1))
      end do
      lo = y(1) + amplitude
      hi = y(n) - amplitude
      if (lo > hi) then
         call fatal_error(error, 'equivalent conicity: amplitude '//str(amplitude)// &
            ' mm needs a table at least '//str(2*amplitude)//' mm wide', stat_invalid_input)
         return
      end if
      g_lo = swing(lo)
      g_hi = swing(hi)
      if (.not. (g_lo < 0.0_wp .and. g_hi > 0.0_wp)) then
         call fatal_error(error, 'equivalent conicity: the rolling-radius difference does '// &
            'not turn the wheelset back within the table for amplitude '//str(amplitude)// &
            ' mm (expected Δr < 0 on the left and > 0 on the right); widen the table', &
            stat_numerical)
         return
      end if
      ! The centre c of the motion: g(c) = ∫_{c−ŷ}^{c+ŷ} Δr dy = 0, by bisection (g grows).
      do i = 1, 200
         c = 0.5_wp*(lo + hi)
         g = swing(c)
         if (g < 0.0_wp) then
            lo = c
         else
            hi = c
         end if
         if (hi - lo <= 1.0e-13_wp*max(1.0_wp, abs(c))) exit
      end do
      c = 0.5_wp*(lo + hi)
      v2 = potential(c + amplitude)
      half = 0.0_wp
      do i = 1, n_quad
         t = -0.5_wp*pi + pi*(i - 0.5_wp)/n_quad
         yy = c + amplitude*sin(t)
         dv = v2 - potential(yy)
         if (.not. dv > 0.0_wp) then
            call fatal_error(error, 'equivalent conicity: no oscillation of amplitude '// &
               str(amplitude)//' mm (Δr does not push the wheelset back at y = '//str(yy)// &
               ' mm)', stat_numerical)
            return
         end if
         half = half + amplitude*cos(t)/sqrt(2.0_wp*dv)
      end do
      half = half*pi/n_quad
      tan_gamma_e = 0.5_wp*(pi/half)**2
   contains
      !> V(x) = ∫_{y₁}^{x} Δr dy, Δr linear between the points.
      pure real(wp) function potential(x)
         real(wp), intent(in) :: x
         integer :: k
         k = locate(y, x)
         potential = cum(k) + 0.5_wp*(delta_r(k) + linear_value(y, delta_r, x))*(x - y(k))
      end function potential
      !> ∫_{x−ŷ}^{x+ŷ} Δr dy.
      pure real(wp) function swing(x)
         real(wp), intent(in) :: x
         swing = potential(x + amplitude) - potential(x - amplitude)
      end function swing
   end subroutine wavelength_conicity

   !> Reject tables and amplitudes the methods cannot use.
   pure subroutine check_table(y, delta_r, amplitude, error)
      real(wp), intent(in) :: y(:), delta_r(:), amplitude
      type(error_type), allocatable, intent(out) :: error
      if (size(y) /= size(delta_r) .or. size(y) < 3) then
         call fatal_error(error, 'equivalent conicity: expected y and Δr of the same size, '// &
            'at least 3 points', stat_invalid_input)
      else if (any(y(2:) <= y(:size(y) - 1))) then
         call fatal_error(error, 'equivalent conicity: expected strictly increasing shifts y', &
            stat_invalid_input)
      else if (.not. all(abs(delta_r) < huge(1.0_wp))) then
         call fatal_error(error, 'equivalent conicity: expected finite Δr values', &
            stat_invalid_input)
      else if (.not. (amplitude > 0.0_wp .and. amplitude < huge(1.0_wp))) then
         call fatal_error(error, 'equivalent conicity: amplitude '//str(amplitude)// &
            ' mm: expected a positive amplitude in mm', stat_invalid_input)
      end if
   end subroutine check_table

   !> The interval k (y(k) ≤ x < y(k+1), clamped to 1..n−1) of x.
   pure integer function locate(y, x) result(k)
      real(wp), intent(in) :: y(:), x
      integer :: lo, hi, mid
      lo = 1
      hi = size(y)
      do while (hi - lo > 1)
         mid = (lo + hi)/2
         if (y(mid) <= x) then
            lo = mid
         else
            hi = mid
         end if
      end do
      k = lo
   end function locate

   !> f at x, linear between the points, constant beyond the ends.
   pure real(wp) function linear_value(y, f, x) result(fx)
      !> Abscissae, strictly increasing.
      real(wp), intent(in) :: y(:)
      !> Values at y.
      real(wp), intent(in) :: f(:)
      !> Where.
      real(wp), intent(in) :: x
      integer :: k
      real(wp) :: t
      if (x <= y(1)) then
         fx = f(1)
      else if (x >= y(size(y))) then
         fx = f(size(f))
      else
         k = locate(y, x)
         t = (x - y(k))/(y(k + 1) - y(k))
         fx = (1.0_wp - t)*f(k) + t*f(k + 1)
      end if
   end function linear_value

end module shcontact_geometry_conicity
