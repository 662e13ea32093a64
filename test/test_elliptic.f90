!> Tests of the complete elliptic integrals (Carlson's forms).
module test_elliptic
   use testdrive, only: new_unittest, unittest_type, error_type, check
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_math_elliptic, only: complete_elliptic, elliptic_k, elliptic_e, carlson_rf, &
      carlson_rd
   implicit none
   private
   public :: collect_elliptic

contains

   !> Collect the tests.
   subroutine collect_elliptic(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('circle_values', test_circle), &
         new_unittest('tabulated_k_e', test_tabulated), &
         new_unittest('legendre_relation', test_legendre), &
         new_unittest('associated_near_circle', test_associated_small_k), &
         new_unittest('associated_near_slender', test_associated_k_to_one), &
         new_unittest('carlson_special_values', test_carlson_special) &
         ]
   end subroutine collect_elliptic

   subroutine test_circle(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: kk, ee, bb, dd
      call complete_elliptic(1.0_wp, kk, ee, bb, dd)
      call check(error, kk, pi/2, thr=4*epsilon(1.0_wp), rel=.true.)
      if (allocated(error)) return
      call check(error, ee, pi/2, thr=4*epsilon(1.0_wp), rel=.true.)
      if (allocated(error)) return
      call check(error, bb, pi/4, thr=4*epsilon(1.0_wp), rel=.true.)
      if (allocated(error)) return
      call check(error, dd, pi/4, thr=4*epsilon(1.0_wp), rel=.true.)
   end subroutine test_circle

   !> K(m), E(m) at several parameters m = k², against 30-digit values (mpmath), to 1e-13.
   subroutine test_tabulated(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: m(5) = [0.1_wp, 0.5_wp, 0.9_wp, 0.99_wp, 0.999999_wp]
      real(wp), parameter :: k_ref(5) = [1.61244134872021940068_wp, 1.85407467730137191843_wp, &
         2.57809211334817329268_wp, 3.69563736298987423864_wp, 8.29405146360106220190_wp]
      real(wp), parameter :: e_ref(5) = [1.53075763689776320020_wp, 1.35064388104767550252_wp, &
         1.10477473270407330792_wp, 1.01599354502522394766_wp, 1.00000389702617216603_wp]
      integer :: i
      do i = 1, size(m)
         call check(error, elliptic_k(1.0_wp - m(i)), k_ref(i), thr=1.0e-13_wp, rel=.true., &
            message='K at tabulated parameter')
         if (allocated(error)) return
         call check(error, elliptic_e(1.0_wp - m(i)), e_ref(i), thr=1.0e-13_wp, rel=.true., &
            message='E at tabulated parameter')
         if (allocated(error)) return
      end do
   end subroutine test_tabulated

   !> Legendre: E K' + E' K − K K' = π/2.
   subroutine test_legendre(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: m, k1, e1, k2, e2, b, d
      integer :: i
      do i = 1, 19
         m = 0.05_wp*i
         call complete_elliptic(1.0_wp - m, k1, e1, b, d)
         call complete_elliptic(m, k2, e2, b, d)
         call check(error, e1*k2 + e2*k1 - k1*k2, pi/2, thr=1.0e-14_wp, rel=.true., &
            message='Legendre relation')
         if (allocated(error)) return
      end do
   end subroutine test_legendre

   !> 𝔅 = π/4 + πm/32 + O(m²), 𝔇 = π/4 + 3πm/32 + O(m²) as k → 0; no cancellation.
   subroutine test_associated_small_k(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: kk, ee, bb, dd, m
      integer :: i
      do i = 4, 14, 2
         m = 10.0_wp**(-i)
         call complete_elliptic(1.0_wp - m, kk, ee, bb, dd)
         call check(error, bb, pi/4 + pi*m/32, thr=max(1.0e-15_wp, m*m), rel=.true., &
            message='B near the circle')
         if (allocated(error)) return
         call check(error, dd, pi/4 + 3*pi*m/32, thr=max(1.0e-15_wp, m*m), rel=.true., &
            message='D near the circle')
         if (allocated(error)) return
      end do
   end subroutine test_associated_small_k

   !> As k → 1: 𝔅 → 1, 𝔇 ≈ ln(4/g) − 1 (g² = mc), both finite.
   subroutine test_associated_k_to_one(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: kk, ee, bb, dd, mc
      integer :: i
      do i = 8, 20, 4
         mc = 10.0_wp**(-i)
         call complete_elliptic(mc, kk, ee, bb, dd)
         call check(error, bb, 1.0_wp, thr=50*mc*log(1/mc) + 1.0e-14_wp, &
            message='B for a slender ellipse')
         if (allocated(error)) return
         call check(error, dd, log(4/sqrt(mc)) - 1, thr=50*mc*log(1/mc) + 1.0e-13_wp, &
            message='D for a slender ellipse')
         if (allocated(error)) return
      end do
   end subroutine test_associated_k_to_one

   !> R_F(x, x, x) = 1/√x, R_D(x, x, x) = x^(−3/2), R_F(0, 1, 1) = π/2.
   subroutine test_carlson_special(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, carlson_rf(4.0_wp, 4.0_wp, 4.0_wp), 0.5_wp, thr=1.0e-15_wp, rel=.true.)
      if (allocated(error)) return
      call check(error, carlson_rd(4.0_wp, 4.0_wp, 4.0_wp), 0.125_wp, thr=1.0e-15_wp, rel=.true.)
      if (allocated(error)) return
      call check(error, carlson_rf(0.0_wp, 1.0_wp, 1.0_wp), pi/2, thr=1.0e-15_wp, rel=.true.)
   end subroutine test_carlson_special

end module test_elliptic
