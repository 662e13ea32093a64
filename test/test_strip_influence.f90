!> Tests of the influence kernel of the coupled reduction (shcontact_normal_strip_influence)
!> against Carlson's complete elliptic integrals and against the influence integrals computed by
!> fine quadrature.
module test_strip_influence
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_math_elliptic, only: complete_elliptic
   use shcontact_normal_strip_influence, only: influence_column, line_kernels
   implicit none
   private
   public :: collect_strip_influence

   !> Arguments of the line kernel on both sides of the series/Hastings switch (u = 3).
   real(wp), parameter :: sample_u(10) = [1.0e-3_wp, 0.01_wp, 0.1_wp, 0.5_wp, 1.0_wp, &
      2.9_wp, 3.0_wp, 3.1_wp, 10.0_wp, 40.0_wp]

contains

   !> Collect the tests.
   subroutine collect_strip_influence(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('line_kernel_against_carlson', test_line_kernel), &
         new_unittest('line_kernel_log_derivative', test_log_derivative), &
         new_unittest('self_influence_against_quadrature', test_self), &
         new_unittest('neighbour_influence_against_quadrature', test_neighbours), &
         new_unittest('slope_is_derivative_in_ln_a', test_slope), &
         new_unittest('long_columns_in_chunks', test_chunks), &
         new_unittest('column_continuous_in_distance', test_continuous) &
         ]
   end subroutine collect_strip_influence

   !> F(u) = √m D(k), D = (K − E)/k² (Carlson's R_D, no cancellation), m = k² = 1/(1 + u²).
   elemental real(wp) function exact_f(u)
      real(wp), intent(in) :: u
      real(wp) :: kk, ee, bb, dd
      call complete_elliptic(u*u/(1.0_wp + u*u), kk, ee, bb, dd)
      exact_f = dd/sqrt(1.0_wp + u*u)
   end function exact_f

   !> The kernel within its stated relative error 2e-6 of F, and −u F' = √m (E − (1 − m) D)
   !> within 2e-6 of F(u) as well (Hastings' E error ≤ 2e-8).
   subroutine test_line_kernel(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: f(size(sample_u)), df(size(sample_u)), kk, ee, bb, dd, m, exact_df
      integer :: k
      call line_kernels(sample_u, f, df)
      do k = 1, size(sample_u)
         call check(error, f(k), exact_f(sample_u(k)), thr=2.0e-6_wp, rel=.true.)
         if (allocated(error)) return
         m = 1.0_wp/(1.0_wp + sample_u(k)**2)
         call complete_elliptic(1.0_wp - m, kk, ee, bb, dd)
         exact_df = sqrt(m)*(ee - (1.0_wp - m)*dd)
         call check(error, df(k), exact_df, thr=2.0e-6_wp*exact_f(sample_u(k)))
         if (allocated(error)) return
      end do
   end subroutine test_line_kernel

   !> df = −u F'(u) against a central difference of F, within 3e-5 (the series below m = 0.1 and
   !> Hastings' K and E above are approximations of their own: their derivatives agree with the
   !> returned df to 1e-5; the difference across the switch at u = 3 is skipped).
   subroutine test_log_derivative(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: h = 1.0e-4_wp
      real(wp) :: f(3), df(3), u3(3)
      integer :: k
      do k = 1, size(sample_u)
         if (abs(sample_u(k) - 3.0_wp) < 0.01_wp) cycle
         u3 = sample_u(k)*[1.0_wp, exp(h), exp(-h)]
         call line_kernels(u3, f, df)
         ! d F/d ln a = −dF/d ln u.
         call check(error, df(1), -(f(2) - f(3))/(2.0_wp*h), thr=3.0e-5_wp*f(1))
         if (allocated(error)) return
      end do
   end subroutine test_log_derivative

   !> A group's influence on itself, ∫∫ √(1 − x²/a²)/r over the group = 4a ∫₀^{h/a} F(u) du,
   !> against composite Simpson with u = r t² (2000 intervals, Carlson's F), for groups from
   !> 1/80 to 2 times as wide as long: within 1e-4 (the 6-point rule in t with u = r t³, 6e-6 to
   !> 5e-5 by scipy).
   subroutine test_self(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: widths(4) = [0.05_wp, 0.5_wp, 2.0_wp, 8.0_wp]
      real(wp) :: column(1), slope(1), a, r
      integer :: k
      a = 2.0_wp
      do k = 1, size(widths)
         call influence_column(a, widths(k), 0.3_wp, [0.3_wp], 1, column, slope)
         r = 0.5_wp*widths(k)/a
         call check(error, column(1), 4.0_wp*a*integral_f(0.0_wp, r), thr=1.0e-4_wp, rel=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_self

   !> Groups one, 2.5 and 10 widths away: Simpson within 1.2 %, the midpoint rule within 1.5 %
   !> and 0.2 % of the width integral ∫ 2F(|y|/a) dy (module text of the kernel).
   subroutine test_neighbours(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: a = 3.0_wp, w = 0.8_wp, distance(3) = [1.0_wp, 2.5_wp, 10.0_wp]*w, &
         tolerance(3) = [0.012_wp, 0.015_wp, 0.002_wp]
      real(wp) :: column(3), slope(3), exact
      integer :: k
      call influence_column(a, w, 1.0_wp, 1.0_wp + distance, 0, column, slope)
      do k = 1, 3
         exact = 2.0_wp*a*integral_f((distance(k) - 0.5_wp*w)/a, (distance(k) + 0.5_wp*w)/a)
         call check(error, column(k), exact, thr=tolerance(k), rel=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_neighbours

   !> The slope column is the derivative of the column with respect to ln a (central difference),
   !> within 1e-5.
   subroutine test_slope(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: h = 1.0e-5_wp, s(5) = [-3.0_wp, -0.4_wp, 0.0_wp, 0.5_wp, 7.0_wp]
      real(wp), dimension(5) :: column, slope, up, down, dummy
      integer :: k
      call influence_column(2.0_wp, 0.6_wp, 0.0_wp, s, 3, column, slope)
      call influence_column(2.0_wp*exp(h), 0.6_wp, 0.0_wp, s, 3, up, dummy)
      call influence_column(2.0_wp*exp(-h), 0.6_wp, 0.0_wp, s, 3, down, dummy)
      do k = 1, 5
         call check(error, slope(k), (up(k) - down(k))/(2.0_wp*h), thr=1.0e-5_wp*column(k))
         if (allocated(error)) return
      end do
   end subroutine test_slope

   !> A column longer than one kernel sweep (70 targets) equals the columns of its pieces.
   subroutine test_chunks(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 70
      real(wp) :: s(n), column(n), slope(n), piece(n), piece_slope(n)
      integer :: j
      do j = 1, n
         s(j) = 0.25_wp*(j - 1) + 0.01_wp*mod(j*7, 5)
      end do
      call influence_column(1.5_wp, 0.25_wp, s(40), s, 40, column, slope)
      do j = 1, n
         if (j == 40) then
            call influence_column(1.5_wp, 0.25_wp, s(40), s(j:j), 1, piece(j:j), &
               piece_slope(j:j))
         else
            call influence_column(1.5_wp, 0.25_wp, s(40), s(j:j), 0, piece(j:j), &
               piece_slope(j:j))
         end if
      end do
      if (maxval(abs(column - piece)/piece) > 1.0e-13_wp .or. &
         maxval(abs(slope - piece_slope)/abs(piece)) > 1.0e-13_wp) then
         call test_failed(error, 'a 70-target column differs from its single-target pieces')
      end if
   end subroutine test_chunks

   !> ∫_{u0}^{u1} F(u) du by composite Simpson in t with u = u0 + (u1 − u0) t² (takes out the
   !> logarithmic singularity of F at u = 0), 2000 intervals, Carlson's F.
   real(wp) function integral_f(u0, u1) result(total)
      real(wp), intent(in) :: u0, u1
      integer, parameter :: n = 2000
      real(wp) :: t, g
      integer :: i
      total = 0.0_wp
      do i = 0, n
         t = real(i, wp)/n
         g = 0.0_wp
         if (i > 0) g = 2.0_wp*t*(u1 - u0)*exact_f(u0 + (u1 - u0)*t*t)
         if (i == 0 .or. i == n) then
            total = total + g
         else if (mod(i, 2) == 1) then
            total = total + 4.0_wp*g
         else
            total = total + 2.0_wp*g
         end if
      end do
      total = total/(3.0_wp*n)
   end function integral_f

   !> The column is continuous in the distance of the target: at 2.5 and 2.6 widths (where the
   !> rule across the width blends from Simpson's into the midpoint rule; a switch at one
   !> distance made it jump by 0.4–1.4 %) it changes by less than 1e-7 over 1e-9 of the
   !> distance, and from 2.5 to 4 widths it stays within 1.5 % of the width integral.
   subroutine test_continuous(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: a = 3.0_wp, w = 0.8_wp, at(2) = [2.5_wp, 2.6_wp]*w
      real(wp) :: column(2), slope(2), exact(1), one(1), one_slope(1), d
      integer :: k

      do k = 1, 2
         call influence_column(a, w, 0.0_wp, at(k)*[1.0_wp - 1.0e-9_wp, 1.0_wp + 1.0e-9_wp], &
            0, column, slope)
         call check(error, abs(column(2) - column(1)) < 1.0e-7_wp*column(1), &
            'the column jumps at a distance of the rule change')
         if (allocated(error)) return
      end do
      do k = 0, 15
         d = (2.5_wp + 0.1_wp*k)*w
         call influence_column(a, w, 0.0_wp, [d], 0, one, one_slope)
         exact(1) = 2.0_wp*a*integral_f((d - 0.5_wp*w)/a, (d + 0.5_wp*w)/a)
         call check(error, one(1), exact(1), thr=0.015_wp, rel=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_continuous

end module test_strip_influence
