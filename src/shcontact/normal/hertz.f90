!> Hertz theory of an elliptical contact between identical elastic bodies (physics.md §1.3–1.5).
!>
!> The ellipse shape depends only on the curvature ratio A/B; it is solved once by
!> [[hertz_shape]] (which the strip method calls per geometry point) and then scaled by the
!> load or the approach in closed form.
module shcontact_normal_hertz
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_material, only: material_type
   use shcontact_math_elliptic, only: complete_elliptic
   use shcontact_math_roots, only: scalar_function_type, find_root
   implicit none
   private

   public :: hertz_shape_type, hertz_type
   public :: hertz_shape, hertz_from_load, hertz_from_approach, hertz_from_semiaxes

   !> The shape of a Hertz ellipse: everything that depends only on the ratio A/B.
   type :: hertz_shape_type
      !> Curvature ratio A/B (longitudinal over lateral).
      real(wp) :: ratio = 1.0_wp
      !> g = minor/major semi-axis ratio, in (0, 1].
      real(wp) :: g = 1.0_wp
      !> Complete elliptic integrals K(k), E(k) with k² = 1 − g².
      real(wp) :: kk = 0.5_wp*pi, ee = 0.5_wp*pi
      !> Penetration split ε_a = A a²/δ, ε_b = B b²/δ, ε_a + ε_b = 1 (§1.3 item 6).
      real(wp) :: eps_a = 0.5_wp, eps_b = 0.5_wp
      !> Hertz coefficients (§1.4): a = m L, b = n L, δ = r L² (A + B).
      real(wp) :: m = 1.0_wp, n = 1.0_wp, r = 1.0_wp
   end type hertz_shape_type

   !> A complete Hertz solution.
   type :: hertz_type
      !> Relative curvatures A (along x, rolling) and B (along y), 1/mm.
      real(wp) :: curv_a = 0.0_wp, curv_b = 0.0_wp
      !> Semi-axes along x and y (mm).
      real(wp) :: a = 0.0_wp, b = 0.0_wp
      !> Approach δ (mm).
      real(wp) :: approach = 0.0_wp
      !> Normal force N (N).
      real(wp) :: load = 0.0_wp
      !> Peak pressure p₀ = 3N/(2πab) (MPa).
      real(wp) :: p0 = 0.0_wp
      !> The shape at ratio A/B.
      type(hertz_shape_type) :: shape
   end type hertz_type

   !> The residual of the shape equation g² 𝔇/𝔅 − ρ (physics.md §1.3 item 1), increasing in g.
   type, extends(scalar_function_type) :: shape_residual
      !> ρ = min(A,B)/max(A,B).
      real(wp) :: rho = 1.0_wp
   contains
      procedure :: eval => shape_residual_eval
   end type shape_residual

   !> Growth factor of the bracket around the initial guess g₀ = ρ^{2/3} (Greenwood: within 3 %
   !> for moderate ratios, a factor ≈ 2 off at ρ = 1e-4).
   real(wp), parameter :: bracket_factor = 1.15_wp

contains

   !> The Hertz shape at the curvature ratio A/B > 0: g from the shape equation, then ε_a, ε_b,
   !> m, n, r in closed form (physics.md §1.3–1.5). ρ = 1 gives the circle without iteration.
   subroutine hertz_shape(ratio, shape, error)
      !> A/B, positive.
      real(wp), intent(in) :: ratio
      !> The shape.
      type(hertz_shape_type), intent(out) :: shape
      !> Set for a non-positive ratio or a failed root search.
      type(error_type), allocatable, intent(out) :: error

      type(shape_residual) :: f
      real(wp) :: lo, hi, flo, fhi, g
      character(len=32) :: buf
      integer :: i

      if (.not. (ratio > 0.0_wp .and. ratio < huge(1.0_wp))) then
         write (buf, '(es12.4)') ratio
         call fatal_error(error, 'Hertz: curvature ratio A/B = '//trim(adjustl(buf))// &
            ': expected a positive finite value (A, B > 0)', stat_invalid_input)
         return
      end if
      f%rho = min(ratio, 1.0_wp/ratio)
      if (f%rho >= 1.0_wp) then
         call shape_from_g(1.0_wp, ratio, shape)
         return
      end if

      ! Bracket the root around Greenwood's g₀ = ρ^{2/3}; f(g) → −ρ as g → 0 and f(1) = 1 − ρ > 0.
      lo = f%rho**(2.0_wp/3.0_wp)
      flo = f%eval(lo)
      if (flo > 0.0_wp) then
         hi = lo; fhi = flo
         do i = 1, 400
            lo = lo/bracket_factor
            flo = f%eval(lo)
            if (flo <= 0.0_wp) exit
            hi = lo; fhi = flo
         end do
      else
         do i = 1, 400
            hi = min(1.0_wp, lo*bracket_factor)
            fhi = f%eval(hi)
            if (fhi >= 0.0_wp) exit
            lo = hi; flo = fhi
         end do
      end if
      if (fhi < 0.0_wp) then
         ! ρ within rounding of 1: f(1) = 1 − ρ is lost in the last bit, the circle is the answer.
         call shape_from_g(1.0_wp, ratio, shape)
         return
      end if
      call find_root(f, lo, hi, g, error, xtol=0.0_wp, f_lower=flo, f_upper=fhi)
      if (allocated(error)) then
         error%message = 'Hertz shape equation: '//error%message
         return
      end if
      call shape_from_g(g, ratio, shape)
   end subroutine hertz_shape

   !> g² 𝔇(g)/𝔅(g) − ρ with Carlson's integrals at mc = g² (no cancellation at either end).
   function shape_residual_eval(self, x) result(fx)
      class(shape_residual), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      real(wp) :: kk, ee, bb, dd
      call complete_elliptic(x*x, kk, ee, bb, dd)
      fx = x*x*dd/bb - self%rho
   end function shape_residual_eval

   !> Everything else from g and the orientation (physics.md §1.3 items 3, 6 and §1.4).
   pure subroutine shape_from_g(g, ratio, shape)
      !> minor/major, in (0, 1].
      real(wp), intent(in) :: g
      !> A/B (only whether it exceeds 1 matters beyond being stored).
      real(wp), intent(in) :: ratio
      !> The shape.
      type(hertz_shape_type), intent(out) :: shape
      real(wp) :: kk, ee, bb, dd, rho, eps_minor, c_major

      call complete_elliptic(g*g, kk, ee, bb, dd)
      rho = min(ratio, 1.0_wp/ratio)
      ! The minor axis carries ε = B b²/δ (A ≤ B) = E/((1 + ρ)K): §1.3 items 3 and 6 combined.
      eps_minor = ee/((1.0_wp + rho)*kk)
      ! §1.4, written for the major axis.
      c_major = (2.0_wp*ee/(pi*g*g))**(1.0_wp/3.0_wp)
      shape%ratio = ratio
      shape%g = g
      shape%kk = kk
      shape%ee = ee
      shape%r = 2.0_wp*kk/(pi*c_major)
      if (ratio <= 1.0_wp) then
         ! A ≤ B: a is the major semi-axis.
         shape%m = c_major
         shape%n = c_major*g
         shape%eps_b = eps_minor
         shape%eps_a = 1.0_wp - eps_minor
      else
         shape%m = c_major*g
         shape%n = c_major
         shape%eps_a = eps_minor
         shape%eps_b = 1.0_wp - eps_minor
      end if
   end subroutine shape_from_g

   !> Hertz solution for curvatures A, B and a normal force N (physics.md §1.4):
   !> L = [3N/(4E*(A+B))]^{1/3}, a = mL, b = nL, δ = rL²(A+B), p₀ = 3N/(2πab).
   subroutine hertz_from_load(curv_a, curv_b, load, material, sol, error, shape)
      !> Relative curvatures A (x) and B (y), 1/mm, positive.
      real(wp), intent(in) :: curv_a, curv_b
      !> Normal force N (N), positive.
      real(wp), intent(in) :: load
      !> Elastic constants (E* = G/(1 − ν)).
      type(material_type), intent(in) :: material
      !> The solution.
      type(hertz_type), intent(out) :: sol
      !> Set for non-positive input.
      type(error_type), allocatable, intent(out) :: error
      !> The shape at A/B when already known (skips the shape equation).
      type(hertz_shape_type), intent(in), optional :: shape

      call check_positive(curv_a, 'curvature A', '1/mm', error)
      if (allocated(error)) return
      call check_positive(curv_b, 'curvature B', '1/mm', error)
      if (allocated(error)) return
      call check_positive(load, 'normal force N', 'N', error)
      if (allocated(error)) return
      call set_shape(curv_a/curv_b, sol, error, shape)
      if (allocated(error)) return
      call scale_by_load(curv_a, curv_b, load, material%e_star(), sol)
   end subroutine hertz_from_load

   !> Hertz solution for curvatures A, B and an approach δ (physics.md §1.3 item 5):
   !> L = √(δ/(r(A+B))), N = 4E*(A+B)L³/3.
   subroutine hertz_from_approach(curv_a, curv_b, approach, material, sol, error, shape)
      !> Relative curvatures A (x) and B (y), 1/mm, positive.
      real(wp), intent(in) :: curv_a, curv_b
      !> Approach δ (mm), positive.
      real(wp), intent(in) :: approach
      !> Elastic constants.
      type(material_type), intent(in) :: material
      !> The solution.
      type(hertz_type), intent(out) :: sol
      !> Set for non-positive input.
      type(error_type), allocatable, intent(out) :: error
      !> The shape at A/B when already known (skips the shape equation).
      type(hertz_shape_type), intent(in), optional :: shape
      real(wp) :: len_scale, e_star

      call check_positive(curv_a, 'curvature A', '1/mm', error)
      if (allocated(error)) return
      call check_positive(curv_b, 'curvature B', '1/mm', error)
      if (allocated(error)) return
      call check_positive(approach, 'approach', 'mm', error)
      if (allocated(error)) return
      call set_shape(curv_a/curv_b, sol, error, shape)
      if (allocated(error)) return
      e_star = material%e_star()
      len_scale = sqrt(approach/(sol%shape%r*(curv_a + curv_b)))
      call scale_by_load(curv_a, curv_b, 4.0_wp*e_star*(curv_a + curv_b)*len_scale**3/3.0_wp, &
         e_star, sol)
      ! Keep the prescribed value exactly rather than its round trip.
      sol%approach = approach
   end subroutine hertz_from_approach

   !> Hertz solution for given semi-axes a, b and normal force N: the curvatures follow from
   !> the shape equation at g = min(a,b)/max(a,b) and from c³ = 3N·E(k)/(2πE*(A+B)√g)
   !> (physics.md §1.3 items 1–2; CONTACT `hzcalc3d`).
   subroutine hertz_from_semiaxes(a, b, load, material, sol, error)
      !> Semi-axes along x and y (mm), positive.
      real(wp), intent(in) :: a, b
      !> Normal force N (N), positive.
      real(wp), intent(in) :: load
      !> Elastic constants.
      type(material_type), intent(in) :: material
      !> The solution.
      type(hertz_type), intent(out) :: sol
      !> Set for non-positive input.
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: g, kk, ee, bb, dd, rho, ratio, sum_ab, e_star

      call check_positive(a, 'semi-axis a', 'mm', error)
      if (allocated(error)) return
      call check_positive(b, 'semi-axis b', 'mm', error)
      if (allocated(error)) return
      call check_positive(load, 'normal force N', 'N', error)
      if (allocated(error)) return
      e_star = material%e_star()
      g = min(a, b)/max(a, b)
      call complete_elliptic(g*g, kk, ee, bb, dd)
      rho = g*g*dd/bb
      ! The smaller curvature goes with the longer axis.
      if (a >= b) then
         ratio = rho
      else
         ratio = 1.0_wp/rho
      end if
      sum_ab = 3.0_wp*load*ee/(2.0_wp*pi*e_star*(a*b)**1.5_wp*sqrt(g))
      call shape_from_g(g, ratio, sol%shape)
      call scale_by_load(sum_ab*ratio/(1.0_wp + ratio), sum_ab/(1.0_wp + ratio), load, e_star, &
         sol)
   end subroutine hertz_from_semiaxes

   !> The shape of sol: the one given, or solved at the ratio.
   subroutine set_shape(ratio, sol, error, shape)
      real(wp), intent(in) :: ratio
      type(hertz_type), intent(inout) :: sol
      type(error_type), allocatable, intent(out) :: error
      type(hertz_shape_type), intent(in), optional :: shape
      if (present(shape)) then
         sol%shape = shape
      else
         call hertz_shape(ratio, sol%shape, error)
      end if
   end subroutine set_shape

   !> Sizes from the shape and the load (physics.md §1.4); `sol%shape` must be set.
   pure subroutine scale_by_load(curv_a, curv_b, load, e_star, sol)
      real(wp), intent(in) :: curv_a, curv_b, load, e_star
      type(hertz_type), intent(inout) :: sol
      real(wp) :: len_scale

      len_scale = (3.0_wp*load/(4.0_wp*e_star*(curv_a + curv_b)))**(1.0_wp/3.0_wp)
      sol%curv_a = curv_a
      sol%curv_b = curv_b
      sol%load = load
      sol%a = sol%shape%m*len_scale
      sol%b = sol%shape%n*len_scale
      sol%approach = sol%shape%r*len_scale**2*(curv_a + curv_b)
      sol%p0 = 3.0_wp*load/(2.0_wp*pi*sol%a*sol%b)
   end subroutine scale_by_load

   !> Error unless value > 0 (and finite).
   pure subroutine check_positive(value, what, unit, error)
      real(wp), intent(in) :: value
      character(len=*), intent(in) :: what, unit
      type(error_type), allocatable, intent(out) :: error
      character(len=32) :: buf
      if (value > 0.0_wp .and. value < huge(1.0_wp)) return
      write (buf, '(es12.4)') value
      call fatal_error(error, 'Hertz: '//what//' = '//trim(adjustl(buf))//' '//unit// &
         ': expected a positive value', stat_invalid_input)
   end subroutine check_positive

end module shcontact_normal_hertz
