!> Hertz theory of an elliptical contact between identical elastic bodies (doc/theory.md §1.3–1.5).
!>
!> The ellipse shape depends only on the curvature ratio A/B; it is solved by [[hertz_shape]]
!> (a bracketed root search on the shape equation) and then scaled by the load or the approach
!> in closed form. [[hertz_shape_fast]] gives the same shape from a precomputed table (to
!> ≈ 1e-12): the strip method needs it at every point of every new geometry.
module shcontact_normal_hertz
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_material, only: material_type
   use shcontact_math_elliptic, only: complete_elliptic
   use shcontact_math_roots, only: scalar_function_type, find_root
   use shcontact_normal_hertz_table, only: shape_octaves, shape_cells, shape_functions, shape_coef, &
      shape_eps_minor, shape_c_major, shape_g, shape_inv_sqrt_ek, shape_k, shape_e, &
      shape_strip_functions
   implicit none
   private

   public :: hertz_shape_type, hertz_type
   public :: hertz_shape, hertz_shape_fast, hertz_strip_shapes, hertz_from_load, hertz_from_approach, hertz_from_semiaxes

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

   !> The residual of the shape equation g² 𝔇/𝔅 − ρ (doc/theory.md §1.3 item 1), increasing in g.
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
   !> m, n, r in closed form (doc/theory.md §1.3–1.5). ρ = 1 gives the circle without iteration.
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

   !> The Hertz shape at the curvature ratio A/B > 0, as [[hertz_shape]] gives it to a relative
   !> ≈ 1e-12 (m, n, r, ε_a, ε_b, g, K, E), without a root search: g, K, E, c_major, ε_minor and
   !> 1/√(EK) are polynomials of degree 8 in ρ = min(A,B)/max(A,B) on 4 cells per binary octave,
   !> generated once from 40-digit values (scripts/hertz_table.py, shcontact_normal_hertz_table).
   !> The cell follows from the bits of ρ, so that an evaluation costs a division and a few
   !> polynomial terms; a `parameter` table needs no initialisation, allocates nothing and is
   !> safe in any thread. Outside the table (ρ < 2⁻¹⁴, an ellipse more than 400 times longer
   !> than wide; the circle ρ = 1) the root search answers.
   subroutine hertz_shape_fast(ratio, shape, error)
      !> A/B, positive.
      real(wp), intent(in) :: ratio
      !> The shape.
      type(hertz_shape_type), intent(out) :: shape
      !> Set for a non-positive ratio (or a failed root search outside the table).
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: v(shape_functions)
      logical :: inside

      ! (An invalid ratio is reported by the root search, before any division.)
      inside = ratio > 0.0_wp .and. ratio < huge(1.0_wp)
      if (inside) call tabulated_shape(min(ratio, 1.0_wp/ratio), shape_functions, v, inside)
      if (inside) then
         call shape_from_integrals(v(shape_g), v(shape_k), v(shape_e), v(shape_c_major), &
            v(shape_eps_minor), ratio, shape)
      else
         call hertz_shape(ratio, shape, error)
      end if
   end subroutine hertz_shape_fast

   !> What the strip method needs of the Hertz shape at every point of a geometry table
   !> (doc/theory.md §4.3 steps 2, 5 and 7): ε_a, ε_b, m, n and the pressure factor
   !> √((A+B)/(E(k)K(k))) at the ratios A_i/B_i, as [[hertz_shape_fast]] gives them, in one
   !> loop: no call and no division but ρ per point, so that the points' independent polynomial
   !> sums overlap in the processor (≈ 10 ns a point).
   subroutine hertz_strip_shapes(curv_a, curv_b, eps_a, eps_b, m, n, p_factor, error)
      !> Curvatures A_i, B_i (1/mm), positive.
      real(wp), intent(in) :: curv_a(:), curv_b(:)
      !> ε_a, ε_b, m, n per point (sizes of curv_a at least).
      real(wp), intent(out) :: eps_a(:), eps_b(:), m(:), n(:)
      !> √((A+B)/(E K)) per point (1/mm).
      real(wp), intent(out) :: p_factor(:)
      !> Set for a non-positive curvature ratio (or a failed root search outside the table).
      type(error_type), allocatable, intent(out) :: error
      type(hertz_shape_type) :: shape
      real(wp) :: v(shape_strip_functions), rho, t
      logical :: inside
      integer :: i, cell

      do i = 1, size(curv_a)
         rho = 0.0_wp
         if (max(curv_a(i), curv_b(i)) > 0.0_wp) rho = min(curv_a(i), curv_b(i))/ &
            max(curv_a(i), curv_b(i))
         ! tabulated_shape's two steps written out: no call per point.
         call shape_cell(rho, cell, t, inside)
         if (inside) then
            v = shape_polynomials(cell, t)
            call orient(v(shape_g), v(shape_c_major), v(shape_eps_minor), curv_a(i) <= curv_b(i), &
               eps_a(i), eps_b(i), m(i), n(i))
            p_factor(i) = sqrt(curv_a(i) + curv_b(i))*v(shape_inv_sqrt_ek)
         else
            call check_positive(curv_a(i), 'curvature A', '1/mm', error)
            if (.not. allocated(error)) call check_positive(curv_b(i), 'curvature B', '1/mm', &
               error)
            if (.not. allocated(error)) call hertz_shape(curv_a(i)/curv_b(i), shape, error)
            if (allocated(error)) return
            eps_a(i) = shape%eps_a
            eps_b(i) = shape%eps_b
            m(i) = shape%m
            n(i) = shape%n
            p_factor(i) = sqrt((curv_a(i) + curv_b(i))/(shape%ee*shape%kk))
         end if
      end do
   end subroutine hertz_strip_shapes

   !> The first n_values tabulated functions (shcontact_normal_hertz_table) at ρ ∈ [2⁻¹⁴, 1);
   !> `inside` is false elsewhere (and for NaN), `values` then unset.
   pure subroutine tabulated_shape(rho, n_values, values, inside)
      real(wp), intent(in) :: rho
      integer, intent(in) :: n_values
      real(wp), intent(out) :: values(n_values)
      logical, intent(out) :: inside
      real(wp) :: t
      integer :: cell, f

      call shape_cell(rho, cell, t, inside)
      if (.not. inside) return
      ! The strip method's functions in a loop of fixed length (unrolled and vectorised whole),
      ! the others after them.
      if (n_values >= shape_strip_functions) then
         values(1:shape_strip_functions) = shape_polynomials(cell, t)
      else
         do f = 1, n_values
            values(f) = shape_polynomial(f, cell, t, t*t, (t*t)*(t*t))
         end do
      end if
      do f = shape_strip_functions + 1, n_values
         values(f) = shape_polynomial(f, cell, t, t*t, (t*t)*(t*t))
      end do
   end subroutine tabulated_shape

   !> The cell of the shape table holding ρ ∈ [2⁻¹⁴, 1) and the position t ∈ [−1, 1) in it;
   !> `inside` is false elsewhere (and for NaN).
   pure subroutine shape_cell(rho, cell, t, inside)
      real(wp), intent(in) :: rho
      integer, intent(out) :: cell
      real(wp), intent(out) :: t
      logical, intent(out) :: inside
      !> Bits of the significand of an IEEE double, and its exponent bias.
      integer(i8), parameter :: significand_mask = 2_i8**52 - 1
      integer, parameter :: exponent_bias = 1023
      real(wp), parameter :: significand_scale = real(shape_cells, wp)*2.0_wp**(-52)
      real(wp) :: u
      integer(i8) :: bits
      integer :: octave, j

      cell = 1
      t = 0.0_wp
      inside = rho > 0.0_wp .and. rho < 1.0_wp
      if (.not. inside) return
      ! ρ = (1 + s)·2^(−1 − octave) with s ∈ [0, 1) (ρ < 1 is normal, positive): the octave and
      ! the position in it straight from the bits, as exponent() and fraction() would give them
      ! through a library call each.
      bits = transfer(rho, bits)
      octave = exponent_bias - 1 - int(shiftr(bits, 52))
      inside = octave < shape_octaves
      if (.not. inside) return
      u = real(iand(bits, significand_mask), wp)*significand_scale
      j = min(int(u), shape_cells - 1)
      t = 2.0_wp*(u - j) - 1.0_wp
      cell = octave*shape_cells + j + 1
   end subroutine shape_cell

   !> The strip method's shape_strip_functions tabulated functions of a cell at t.
   pure function shape_polynomials(cell, t) result(values)
      integer, intent(in) :: cell
      real(wp), intent(in) :: t
      real(wp) :: values(shape_strip_functions)
      real(wp) :: t2, t4
      integer :: f
      t2 = t*t
      t4 = t2*t2
      do f = 1, shape_strip_functions
         values(f) = shape_polynomial(f, cell, t, t2, t4)
      end do
   end function shape_polynomials

   !> Function f of a cell at t (t2 = t², t4 = t⁴) by Estrin's scheme for degree 8: a dependency
   !> chain of 4 steps instead of Horner's 8.
   pure real(wp) function shape_polynomial(f, cell, t, t2, t4) result(value)
      integer, intent(in) :: f, cell
      real(wp), intent(in) :: t, t2, t4
      value = ((shape_coef(f, 0, cell) + shape_coef(f, 1, cell)*t) &
         + (shape_coef(f, 2, cell) + shape_coef(f, 3, cell)*t)*t2) &
         + ((shape_coef(f, 4, cell) + shape_coef(f, 5, cell)*t) &
         + (shape_coef(f, 6, cell) + shape_coef(f, 7, cell)*t)*t2)*t4 &
         + shape_coef(f, 8, cell)*(t4*t4)
   end function shape_polynomial

   !> Everything else from g and the orientation (doc/theory.md §1.3 items 3, 6 and §1.4).
   pure subroutine shape_from_g(g, ratio, shape)
      !> minor/major, in (0, 1].
      real(wp), intent(in) :: g
      !> A/B (only whether it exceeds 1 matters beyond being stored).
      real(wp), intent(in) :: ratio
      !> The shape.
      type(hertz_shape_type), intent(out) :: shape
      real(wp) :: kk, ee, bb, dd

      call complete_elliptic(g*g, kk, ee, bb, dd)
      ! §1.4 for the major axis; the minor axis carries ε = B b²/δ (A ≤ B) = E/((1 + ρ)K)
      ! (§1.3 items 3 and 6 combined).
      call shape_from_integrals(g, kk, ee, (2.0_wp*ee/(pi*g*g))**(1.0_wp/3.0_wp), &
         ee/((1.0_wp + min(ratio, 1.0_wp/ratio))*kk), ratio, shape)
   end subroutine shape_from_g

   !> The shape from g, K(k), E(k), the major axis' Hertz coefficient c_major = (2E/(πg²))^{1/3}
   !> (§1.4), the minor axis' penetration fraction ε_minor = E/((1 + ρ)K) and the orientation.
   pure subroutine shape_from_integrals(g, kk, ee, c_major, eps_minor, ratio, shape)
      !> minor/major, in (0, 1].
      real(wp), intent(in) :: g
      !> K(k), E(k) at k² = 1 − g².
      real(wp), intent(in) :: kk, ee
      !> c_major and ε_minor.
      real(wp), intent(in) :: c_major, eps_minor
      !> A/B (only whether it exceeds 1 matters beyond being stored).
      real(wp), intent(in) :: ratio
      !> The shape.
      type(hertz_shape_type), intent(out) :: shape

      shape%ratio = ratio
      shape%g = g
      shape%kk = kk
      shape%ee = ee
      shape%r = 2.0_wp*kk/(pi*c_major)
      call orient(g, c_major, eps_minor, ratio <= 1.0_wp, shape%eps_a, shape%eps_b, shape%m, &
         shape%n)
   end subroutine shape_from_integrals

   !> ε_a, ε_b, m, n from the major/minor quantities: a is the major semi-axis iff A ≤ B.
   pure subroutine orient(g, c_major, eps_minor, a_major, eps_a, eps_b, m, n)
      real(wp), intent(in) :: g, c_major, eps_minor
      logical, intent(in) :: a_major
      real(wp), intent(out) :: eps_a, eps_b, m, n
      if (a_major) then
         m = c_major
         n = c_major*g
         eps_b = eps_minor
         eps_a = 1.0_wp - eps_minor
      else
         m = c_major*g
         n = c_major
         eps_a = eps_minor
         eps_b = 1.0_wp - eps_minor
      end if
   end subroutine orient

   !> Hertz solution for curvatures A, B and a normal force N (doc/theory.md §1.4):
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

   !> Hertz solution for curvatures A, B and an approach δ (doc/theory.md §1.3 item 5):
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
   !> (doc/theory.md §1.3 items 1–2; CONTACT `hzcalc3d`).
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

   !> Sizes from the shape and the load (doc/theory.md §1.4); `sol%shape` must be set.
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
