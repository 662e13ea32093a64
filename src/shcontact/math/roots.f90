!> Safeguarded scalar root finding: Brent's method on a sign-changing bracket.
!>
!> The function is supplied as an extension of [[scalar_function_type]], so that it can carry
!> its own data (no global state, no internal-procedure trampolines) and be used from several
!> threads at once.
module shcontact_math_roots
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_numerical
   implicit none
   private

   public :: scalar_function_type, find_root

   !> A real function of one real variable, with whatever data it needs as components.
   type, abstract :: scalar_function_type
   contains
      !> Evaluate the function at x.
      procedure(scalar_function_eval), deferred :: eval
   end type scalar_function_type

   abstract interface
      !> The value f(x).
      function scalar_function_eval(self, x) result(fx)
         import :: scalar_function_type, wp
         !> The function object (may update cached data, hence inout).
         class(scalar_function_type), intent(inout) :: self
         !> Where to evaluate.
         real(wp), intent(in) :: x
         real(wp) :: fx
      end function scalar_function_eval
   end interface

contains

   !> Find a root of f in [lower, upper] by Brent's method (inverse quadratic interpolation,
   !> secant and bisection), to |Δx| ≤ xtol + rtol·|x| or f(x) = 0.
   !>
   !> The bracket must hold a sign change; otherwise an error names both ends and their values.
   !> Values f(lower), f(upper) may be passed when already known to save two evaluations.
   subroutine find_root(f, lower, upper, root, error, xtol, rtol, f_lower, f_upper, max_iter, &
                        iterations)
      !> The function.
      class(scalar_function_type), intent(inout) :: f
      !> The bracket.
      real(wp), intent(in) :: lower, upper
      !> The root found.
      real(wp), intent(out) :: root
      !> Set when the bracket holds no sign change or the iteration does not converge.
      type(error_type), allocatable, intent(out) :: error
      !> Absolute tolerance on x (default 1e-14·(|lower| + |upper|)).
      real(wp), intent(in), optional :: xtol
      !> Relative tolerance on x (default 4·epsilon).
      real(wp), intent(in), optional :: rtol
      !> f(lower) and f(upper), when known.
      real(wp), intent(in), optional :: f_lower, f_upper
      !> Maximum number of iterations (default 200).
      integer, intent(in), optional :: max_iter
      !> Number of function evaluations used.
      integer, intent(out), optional :: iterations

      real(wp) :: a, b, c, d, e, fa, fb, fc, tol_abs, tol_rel, tol, m, p, q, r, s
      integer :: it, nmax
      character(len=160) :: msg

      tol_abs = 1.0e-14_wp*(abs(lower) + abs(upper))
      if (present(xtol)) tol_abs = xtol
      tol_rel = 4.0_wp*epsilon(1.0_wp)
      if (present(rtol)) tol_rel = rtol
      nmax = 200
      if (present(max_iter)) nmax = max_iter

      a = lower; b = upper
      if (present(f_lower)) then
         fa = f_lower
      else
         fa = f%eval(a)
      end if
      if (present(f_upper)) then
         fb = f_upper
      else
         fb = f%eval(b)
      end if
      root = a
      if (present(iterations)) iterations = 0
      if (fa == 0.0_wp) return
      root = b
      if (fb == 0.0_wp) return
      if (sign(1.0_wp, fa) == sign(1.0_wp, fb)) then
         write (msg, '(a,2(es12.4,a,es12.4,a))') 'root finder: no sign change in the bracket: f(', &
            a, ') = ', fa, ', f(', b, ') = ', fb, ''
         call fatal_error(error, trim(msg), stat_numerical)
         return
      end if

      c = a; fc = fa; d = b - a; e = d
      do it = 1, nmax
         if (sign(1.0_wp, fb) == sign(1.0_wp, fc)) then
            c = a; fc = fa; d = b - a; e = d
         end if
         if (abs(fc) < abs(fb)) then
            a = b; b = c; c = a
            fa = fb; fb = fc; fc = fa
         end if
         tol = 0.5_wp*(tol_abs + tol_rel*abs(b))
         m = 0.5_wp*(c - b)
         if (abs(m) <= tol .or. fb == 0.0_wp) then
            root = b
            if (present(iterations)) iterations = it
            return
         end if
         if (abs(e) >= tol .and. abs(fa) > abs(fb)) then
            s = fb/fa
            if (a == c) then
               p = 2.0_wp*m*s
               q = 1.0_wp - s
            else
               q = fa/fc
               r = fb/fc
               p = s*(2.0_wp*m*q*(q - r) - (b - a)*(r - 1.0_wp))
               q = (q - 1.0_wp)*(r - 1.0_wp)*(s - 1.0_wp)
            end if
            if (p > 0.0_wp) then
               q = -q
            else
               p = -p
            end if
            if (2.0_wp*p < min(3.0_wp*m*q - abs(tol*q), abs(e*q))) then
               e = d
               d = p/q
            else
               d = m; e = m
            end if
         else
            d = m; e = m
         end if
         a = b; fa = fb
         if (abs(d) > tol) then
            b = b + d
         else
            b = b + sign(tol, m)
         end if
         fb = f%eval(b)
      end do
      root = b
      if (present(iterations)) iterations = nmax
      write (msg, '(a,i0,a,es12.4)') 'root finder: no convergence in ', nmax, &
         ' iterations; last estimate ', b
      call fatal_error(error, trim(msg), stat_numerical)
   end subroutine find_root

end module shcontact_math_roots
