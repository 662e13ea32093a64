!> Tests of the profile smoothing spline (doc/theory.md §5.5): exact interpolation of cubics,
!> curvature of a circle, the low-pass response of the smoothing, kinks, and bad input.
module test_spline
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi, two_pi
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_spline, only: profile_spline_type, spline_point_type
   implicit none
   private
   public :: collect_spline

contains

   subroutine collect_spline(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('cubic_reproduced_exactly', test_cubic), &
         new_unittest('circle_curvature', test_circle_curvature), &
         new_unittest('z_of_y_on_a_graph', test_z_of_y), &
         new_unittest('smoothing_damps_short_waves', test_low_pass), &
         new_unittest('smoothing_keeps_straight_line', test_smoothing_line), &
         new_unittest('kink_survives', test_kink), &
         new_unittest('duplicate_points_rejected', test_duplicates), &
         new_unittest('too_few_points_rejected', test_too_few), &
         new_unittest('negative_l_filt_rejected', test_negative_l_filt) &
         ]
   end subroutine collect_spline

   !> y = cubic in the parameter, on uneven knots: L_filt = 0 reproduces value, slope and second
   !> derivative everywhere (not-a-knot ends).
   subroutine test_cubic(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err
      type(spline_point_type) :: p
      integer, parameter :: n = 13
      real(wp) :: t(n), s
      integer :: i

      t = [(real(i - 1, wp) + 0.3_wp*sin(real(i, wp)), i=1, n)]
      t = t - t(1)
      prof%y = fy(t)
      prof%z = fz(t)
      prof%s = t
      call sp%fit(prof, 0.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 0, 40
         s = t(n)*i/40.0_wp
         p = sp%eval(s)
         call check(error, p%y, fy(s), thr=1.0e-11_wp, message='cubic value')
         if (allocated(error)) return
         call check(error, p%dy, 0.5_wp - 0.6_wp*s + 0.09_wp*s**2, thr=1.0e-10_wp, &
            message='cubic slope')
         if (allocated(error)) return
         call check(error, p%d2y, -0.6_wp + 0.18_wp*s, thr=1.0e-9_wp, message='cubic 2nd der.')
         if (allocated(error)) return
         call check(error, p%z, fz(s), thr=1.0e-11_wp, message='quadratic value')
         if (allocated(error)) return
      end do
   contains
      elemental real(wp) function fy(x)
         real(wp), intent(in) :: x
         fy = 1.0_wp + 0.5_wp*x - 0.3_wp*x**2 + 0.03_wp*x**3
      end function fy
      elemental real(wp) function fz(x)
         real(wp), intent(in) :: x
         fz = 2.0_wp - x + 0.25_wp*x**2
      end function fz
   end subroutine test_cubic

   !> A circular arc sampled every 0.2 mm (R = 13): the interpolating spline's curvature is 1/R
   !> to its O((h/R)²) interpolation error, 1e-4 relative, with the sign convention of the
   !> module (convex, material on the right, κ > 0).
   subroutine test_circle_curvature(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err
      real(wp), parameter :: r = 13.0_wp
      integer, parameter :: n = 161
      real(wp) :: phi
      integer :: i

      ! Rail-like head: walking +y over the top of a circle, centre below (z down).
      allocate (prof%y(n), prof%z(n))
      do i = 1, n
         phi = -1.2_wp + 2.4_wp*(i - 1)/(n - 1)
         prof%y(i) = r*sin(phi)
         prof%z(i) = r - r*cos(phi)
      end do
      call prof%update_arc_length()
      call sp%fit(prof, 0.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 1, 9
         call check(error, sp%curvature(sp%length()*i/10.0_wp), 1.0_wp/r, rel=.true., &
            thr=1.0e-4_wp, message='curvature of a circle')
         if (allocated(error)) return
      end do
   end subroutine test_circle_curvature

   !> z(y) on a parabola z = y²/(2R): value, slope y/R and second derivative 1/R.
   subroutine test_z_of_y(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err
      real(wp), parameter :: r = 300.0_wp
      real(wp) :: z, dz, d2z, y
      logical :: found
      integer :: i

      prof%y = [(-30.0_wp + 0.5_wp*i, i=0, 120)]
      prof%z = prof%y**2/(2*r)
      call prof%update_arc_length()
      call sp%fit(prof, 0.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = -5, 5
         y = 5.3_wp*i
         call sp%z_of_y(y, z, dz, d2z, found)
         call check(error, found, message='y inside the profile')
         if (allocated(error)) return
         call check(error, z, y**2/(2*r), thr=1.0e-9_wp, message='z(y)')
         if (allocated(error)) return
         call check(error, dz, y/r, thr=1.0e-8_wp, message='dz/dy')
         if (allocated(error)) return
         call check(error, d2z, 1.0_wp/r, thr=1.0e-6_wp, message='d2z/dy2')
         if (allocated(error)) return
      end do
      call sp%z_of_y(31.0_wp, z, dz, d2z, found)
      call check(error, .not. found, message='y beyond the profile end is not found')
   end subroutine test_z_of_y

   !> A wave of wavelength L on a straight line, smoothed with L_filt: the amplitude is scaled
   !> by 1/(1 + (L_filt/L)⁴) (continuous response, doc/theory.md §5.5), within 2 % of the input
   !> amplitude on fine sampling away from the ends.
   subroutine test_low_pass(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: l_filt = 2.0_wp
      real(wp) :: gain
      integer :: i
      real(wp), parameter :: wavelengths(3) = [1.0_wp, 2.0_wp, 20.0_wp]

      do i = 1, size(wavelengths)
         call wave_gain(wavelengths(i), l_filt, gain, error)
         if (allocated(error)) return
         call check(error, gain, 1.0_wp/(1.0_wp + (l_filt/wavelengths(i))**4), thr=0.02_wp, &
            message='smoothing-spline gain')
         if (allocated(error)) return
      end do
   end subroutine test_low_pass

   !> Gain of the smoothing spline on a sine of wavelength lw (amplitude 0.01 mm on z = 0).
   subroutine wave_gain(lw, l_filt, gain, error)
      real(wp), intent(in) :: lw, l_filt
      real(wp), intent(out) :: gain
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err
      type(spline_point_type) :: p
      integer, parameter :: n = 2001
      real(wp), parameter :: amp = 0.01_wp
      real(wp) :: num, den, ph
      integer :: i

      prof%y = [(0.05_wp*i, i=0, n - 1)]
      prof%z = amp*sin(two_pi*prof%y/lw)
      ! Parameterise by y so that the wave is exactly a function of the parameter.
      prof%s = prof%y
      call sp%fit(prof, l_filt, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      ! Project the smoothed z on the input wave over the middle half (points 501 to 1501 of 2001).
      num = 0; den = 0
      do i = 501, 1501
         p = sp%eval(prof%s(i))
         ph = sin(two_pi*prof%y(i)/lw)
         num = num + p%z*ph
         den = den + amp*ph*ph
      end do
      gain = num/den
   end subroutine wave_gain

   !> Smoothing leaves a straight line straight (it is in the null space of ∫f''²).
   subroutine test_smoothing_line(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err
      type(spline_point_type) :: p
      integer :: i

      prof%y = [(0.3_wp*i + 0.01_wp*mod(i, 3), i=0, 50)]
      prof%z = 0.2_wp*prof%y - 1.0_wp
      call prof%update_arc_length()
      call sp%fit(prof, 5.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 0, 10
         p = sp%eval(sp%length()*i/10.0_wp)
         call check(error, p%z, 0.2_wp*p%y - 1.0_wp, thr=1.0e-10_wp, message='line stays')
         if (allocated(error)) return
         call check(error, sp%curvature(p%s), 0.0_wp, thr=1.0e-9_wp, message='no curvature')
         if (allocated(error)) return
      end do
   end subroutine test_smoothing_line

   !> A V-shaped profile with its corner flagged as a kink: both legs stay straight up to the
   !> corner, even with smoothing.
   subroutine test_kink(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err
      real(wp) :: z, dz, d2z
      logical :: found
      integer :: i

      prof%y = [(-10.0_wp + 0.5_wp*i, i=0, 40)]
      prof%z = 0.1_wp*abs(prof%y)
      allocate (prof%kink(size(prof%y)), source=.false.)
      prof%kink(21) = .true.
      call prof%update_arc_length()
      call sp%fit(prof, 2.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = -9, 9, 2
         call sp%z_of_y(real(i, wp) + 0.25_wp, z, dz, d2z, found)
         call check(error, z, 0.1_wp*abs(i + 0.25_wp), thr=1.0e-10_wp, message='leg of the V')
         if (allocated(error)) return
         call check(error, dz, sign(0.1_wp, i + 0.25_wp), thr=1.0e-10_wp, message='leg slope')
         if (allocated(error)) return
      end do
   end subroutine test_kink

   !> Two equal consecutive points: an error naming them.
   subroutine test_duplicates(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err

      prof%source = 'dup.txt'
      prof%y = [0.0_wp, 1.0_wp, 1.0_wp, 2.0_wp]
      prof%z = [0.0_wp, 0.1_wp, 0.1_wp, 0.4_wp]
      call prof%update_arc_length()
      call sp%fit(prof, 0.0_wp, err)
      call check(error, allocated(err), message='duplicate points accepted')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(err%message, 'dup.txt') > 0 .and. &
         index(err%message, 'points 2 and 3') > 0, message='message: '//err%message)
   end subroutine test_duplicates

   !> One point is not a profile.
   subroutine test_too_few(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err

      prof%y = [1.0_wp]
      prof%z = [0.0_wp]
      call sp%fit(prof, 0.0_wp, err)
      call check(error, allocated(err), message='a single point accepted')
      if (allocated(error)) return
      call check(error, index(err%message, '1 point') > 0, message='message: '//err%message)
   end subroutine test_too_few

   !> L_filt < 0 is rejected.
   subroutine test_negative_l_filt(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: prof
      type(profile_spline_type) :: sp
      type(lib_error), allocatable :: err

      prof%y = [0.0_wp, 1.0_wp, 2.0_wp]
      prof%z = [0.0_wp, 0.0_wp, 0.0_wp]
      call sp%fit(prof, -1.0_wp, err)
      call check(error, allocated(err), message='negative L_filt accepted')
      if (allocated(error)) return
      call check(error, index(err%message, 'L_filt') > 0, message='message: '//err%message)
   end subroutine test_negative_l_filt

end module test_spline
