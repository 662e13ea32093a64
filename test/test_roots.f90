!> Tests of the bracketed root finder.
module test_roots
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type_lib => error_type, stat_numerical
   use shcontact_math_roots, only: scalar_function_type, find_root
   use shcontact_math_anderson, only: anderson_step
   implicit none
   private
   public :: collect_roots

   !> x² − c.
   type, extends(scalar_function_type) :: square_minus
      real(wp) :: c = 2.0_wp
      integer :: calls = 0
   contains
      procedure :: eval => square_minus_eval
   end type square_minus

   !> A function with a kink at its root: slope 1 left of x0, slope 5 right of it.
   type, extends(scalar_function_type) :: kinked
      real(wp) :: x0 = 0.3_wp
   contains
      procedure :: eval => kinked_eval
   end type kinked

   !> |x − 1| − 0.5: a kink away from the roots 0.5 and 1.5.
   type, extends(scalar_function_type) :: vee
   contains
      procedure :: eval => vee_eval
   end type vee

contains

   subroutine collect_roots(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('smooth_sqrt2', test_smooth), &
         new_unittest('kink_at_root', test_kink_at_root), &
         new_unittest('kink_in_bracket', test_vee), &
         new_unittest('no_sign_change_is_error', test_no_bracket), &
         new_unittest('anderson_linear_fixed_point', test_anderson_linear) &
         ]
   end subroutine collect_roots

   function square_minus_eval(self, x) result(fx)
      class(square_minus), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      self%calls = self%calls + 1
      fx = x*x - self%c
   end function square_minus_eval

   function kinked_eval(self, x) result(fx)
      class(kinked), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      if (x < self%x0) then
         fx = x - self%x0
      else
         fx = 5*(x - self%x0)
      end if
   end function kinked_eval

   function vee_eval(self, x) result(fx)
      class(vee), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      fx = abs(x - 1.0_wp) - 0.5_wp
   end function vee_eval

   subroutine test_smooth(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type_lib), allocatable :: err
      type(square_minus) :: f
      real(wp) :: x
      call find_root(f, 0.0_wp, 2.0_wp, x, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, x, sqrt(2.0_wp), thr=1.0e-14_wp)
      if (allocated(error)) return
      call check(error, f%calls < 15, message='Brent should converge in a few evaluations')
   end subroutine test_smooth

   subroutine test_kink_at_root(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type_lib), allocatable :: err
      type(kinked) :: f
      real(wp) :: x
      call find_root(f, -2.0_wp, 1.0_wp, x, err, xtol=1.0e-13_wp)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, x, 0.3_wp, thr=1.0e-12_wp)
   end subroutine test_kink_at_root

   subroutine test_vee(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type_lib), allocatable :: err
      type(vee) :: f
      real(wp) :: x
      call find_root(f, 1.0_wp, 3.0_wp, x, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, x, 1.5_wp, thr=1.0e-13_wp)
   end subroutine test_vee

   subroutine test_no_bracket(error)
      type(error_type), allocatable, intent(out) :: error
      type(error_type_lib), allocatable :: err
      type(square_minus) :: f
      real(wp) :: x
      call find_root(f, 2.0_wp, 3.0_wp, x, err)
      call check(error, allocated(err), message='a bracket without sign change must be an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_numerical)
      if (allocated(error)) return
      call check(error, index(err%message, 'no sign change') > 0, message=err%message)
   end subroutine test_no_bracket

   !> Anderson's acceleration (shcontact_math_anderson) of a linear fixed-point iteration: the
   !> plain step f = r(x)/1.5 with r = b + (J − I)x, J diagonal with the factors −1, −0.5, 0, −1,
   !> so that the plain step keeps 1/3 of the error in the first, third and fourth modes. With
   !> memory 3 the accelerated iteration is at the fixed point to round-off after 5 steps (it is
   !> exact on a linear map once its differences span the modes); the plain one still has 3⁻⁵
   !> of the error then.
   subroutine test_anderson_linear(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 4, memory = 3
      real(wp), parameter :: s(n) = [-1.0_wp, -0.5_wp, 0.0_wp, -1.0_wp], &
         b(n) = [0.3_wp, -0.2_wp, 0.7_wp, 1.1_wp]
      real(wp) :: x(n), plain(n), f(n), x_new(n), last_x(n), last_f(n), dx(n, memory), &
         df(n, memory), fixed(n)
      integer :: it, used

      ! r(x) = b + (s − 1) x = 0 at x = b/(1 − s).
      fixed = b/(1.0_wp - s)
      x = 0.0_wp
      plain = 0.0_wp
      used = 0
      do it = 1, 5
         f = (b + (s - 1.0_wp)*x)/1.5_wp
         call anderson_step(x, f, last_x, last_f, dx, df, used, x_new)
         x = x_new
         plain = plain + (b + (s - 1.0_wp)*plain)/1.5_wp
      end do
      call check(error, maxval(abs(x - fixed)) < 1.0e-12_wp, &
         'Anderson: not at the fixed point after 5 steps')
      if (allocated(error)) return
      call check(error, maxval(abs(plain - fixed)) > 1.0e-3_wp, &
         'the plain iteration should still be off (the test would not show the acceleration)')
      if (allocated(error)) return
      ! A restart (used = 0) takes the plain step.
      used = 0
      x = 0.0_wp
      f = (b + (s - 1.0_wp)*x)/1.5_wp
      call anderson_step(x, f, last_x, last_f, dx, df, used, x_new)
      call check(error, maxval(abs(x_new - f)) == 0.0_wp, 'a restart must take the plain step')
   end subroutine test_anderson_linear

end module test_roots
