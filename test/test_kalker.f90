!> Tests of Kalker's creepage coefficients (doc/theory.md §2).
module test_kalker
   use testdrive, only: new_unittest, unittest_type, error_type, check
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_tangential_kalker, only: kalker_coefficients, kalker_asymptotes, &
      kalker_table_short, kalker_table_long, &
      kalker_table_g, kalker_table_poisson, kalker_blend_start, kalker_blend_end
   implicit none
   private
   public :: collect_kalker

contains

   !> Collect the tests.
   subroutine collect_kalker(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('table_nodes_scaled', test_nodes_scaled), &
         new_unittest('c11_equals_c22_at_nu_0', test_nu_zero), &
         new_unittest('blend_continuity', test_blend_continuity), &
         new_unittest('asymptotes_below_blend', test_asymptotes), &
         new_unittest('samples_scaled_scheme', test_samples_scaled) &
         ]
   end subroutine collect_kalker

   !> Every node of Table E.3 (19 rows × 3 ν × 3 coefficients), default scheme, to round-off.
   subroutine test_nodes_scaled(error)
      type(error_type), allocatable, intent(out) :: error
      call check_nodes(error, 1)
   end subroutine test_nodes_scaled

   subroutine check_nodes(error, first_row)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in) :: first_row
      real(wp) :: c(3), ab
      integer :: row, inu, long
      character(len=80) :: where

      do long = 0, 1
         do row = first_row, 10
            if (long == 1) then
               ab = 1.0_wp/kalker_table_g(row)
            else
               ab = kalker_table_g(row)
            end if
            do inu = 1, 3
               call kalker_coefficients(ab, kalker_table_poisson(inu), c(1), c(2), c(3))
               write (where, '(a,f8.4,a,f5.2)') 'table node a/b =', ab, ', nu =', &
                  kalker_table_poisson(inu)
               if (long == 1) then
                  call check(error, all(abs(c/kalker_table_long(inu, :, row) - 1) < 1e-13_wp), &
                     message=trim(where))
               else
                  call check(error, all(abs(c/kalker_table_short(inu, :, row) - 1) < 1e-13_wp), &
                     message=trim(where))
               end if
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine check_nodes

   !> At ν = 0 the two directions cannot be told apart: c₁₁ = c₂₂ for every a/b (table, blend
   !> and asymptotes; doc/theory.md §2.2).
   subroutine test_nu_zero(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: ab, c11, c22, c23
      integer :: i

      do i = -300, 300
         ab = 10.0_wp**(0.01_wp*i)
         call kalker_coefficients(ab, 0.0_wp, c11, c22, c23)
         call check(error, c11, c22, thr=1e-13_wp, rel=.true., message='c11 = c22 at nu = 0')
         if (allocated(error)) return
      end do
   end subroutine test_nu_zero

   !> The default scheme is continuous at the ends of the blend interval and across a = b; the
   !> blend stays between the asymptote and the extended table.
   subroutine test_blend_continuity(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: eps = 1e-10_wp
      real(wp) :: g(3), lo(3), hi(3), ab
      integer :: k, long, inu

      g = [kalker_blend_start, kalker_blend_end, 1.0_wp]
      do inu = 1, 3
         do long = 0, 1
            do k = 1, 3
               if (long == 1) then
                  ab = 1.0_wp/g(k)
               else
                  ab = g(k)
               end if
               call kalker_coefficients(ab*(1 - eps), kalker_table_poisson(inu), lo(1), lo(2), &
                  lo(3))
               call kalker_coefficients(ab*(1 + eps), kalker_table_poisson(inu), hi(1), hi(2), &
                  hi(3))
               call check(error, all(abs(hi - lo) < 1e-7_wp*abs(hi)), &
                  message='Kalker coefficients jump at a blend or branch boundary')
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_blend_continuity

   !> Below g = 0.08 the default is the asymptote itself; the asymptotes' values at g = 0.1, ν = 0
   !> are those of doc/theory.md §2.3 (c₁₁ 2.467 for a/b = 0.1, 10.38 for b/a = 0.1).
   subroutine test_asymptotes(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: ratios(6) = [0.001_wp, 0.05_wp, 0.079_wp, 1/0.079_wp, 20.0_wp, &
         1000.0_wp]
      real(wp) :: c(3), ca(3), ab
      integer :: i

      call kalker_asymptotes(0.1_wp, 0.0_wp, ca(1), ca(2), ca(3))
      call check(error, ca(1), pi**2/4, thr=1e-14_wp, rel=.true.)
      if (allocated(error)) return
      call check(error, abs(ca(1) - 2.467_wp) < 5e-4_wp, message='asymptote c11(a/b = 0.1)')
      if (allocated(error)) return
      call kalker_asymptotes(10.0_wp, 0.0_wp, ca(1), ca(2), ca(3))
      call check(error, abs(ca(1) - 10.38_wp) < 5e-3_wp, message='asymptote c11(b/a = 0.1)')
      if (allocated(error)) return
      do i = 1, size(ratios)
         ab = ratios(i)
         call kalker_coefficients(ab, 0.27_wp, c(1), c(2), c(3))
         call kalker_asymptotes(ab, 0.27_wp, ca(1), ca(2), ca(3))
         call check(error, all(abs(c - ca) <= 1e-15_wp*ca), &
            message='default scheme = asymptote below g = 0.08')
         if (allocated(error)) return
      end do
   end subroutine test_asymptotes

   !> doc/theory.md §2.3, "linear in g of g·c" column (ν = 0.27): a/b = 1.5: 4.681/4.333/2.051,
   !> 1.3294: 4.5091/4.1194/1.8542 (doc/tangential.md),
   !> 4: 6.988/7.187/5.274, 7: 9.43/10.15/9.73; at a/b = 1 and 2 the table rows (4 decimals as
   !> CONTACT prints them).
   subroutine test_samples_scaled(error)
      type(error_type), allocatable, intent(out) :: error
      call check_sample(error, 1.0_wp, 0.27_wp, &
         [4.1903_wp, 3.6932_wp, 1.4820_wp], 5.1e-5_wp)
      if (allocated(error)) return
      call check_sample(error, 2.0_wp, 0.28_wp, &
         [5.2037_wp, 4.9715_wp, 2.6566_wp], 5.1e-5_wp)
      if (allocated(error)) return
      call check_sample(error, 1.3294_wp, 0.27_wp, &
         [4.5091_wp, 4.1194_wp, 1.8542_wp], 5.1e-5_wp)
      if (allocated(error)) return
      call check_sample(error, 1.5_wp, 0.27_wp, &
         [4.681_wp, 4.333_wp, 2.051_wp], 5.1e-4_wp)
      if (allocated(error)) return
      call check_sample(error, 4.0_wp, 0.27_wp, &
         [6.988_wp, 7.187_wp, 5.274_wp], 5.1e-4_wp)
      if (allocated(error)) return
      call check_sample(error, 7.0_wp, 0.27_wp, &
         [9.43_wp, 10.15_wp, 9.73_wp], 5.1e-3_wp)
   end subroutine test_samples_scaled

   subroutine check_sample(error, ab, nu, expected, tol)
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in) :: ab, nu, expected(3), tol
      real(wp) :: c(3)
      character(len=120) :: msg

      call kalker_coefficients(ab, nu, c(1), c(2), c(3))
      write (msg, '(a,f7.4,a,f5.2,a,3f9.4)') 'a/b =', ab, ', nu =', nu, ': got', c
      call check(error, all(abs(c - expected) <= tol), message=trim(msg))
   end subroutine check_sample

end module test_kalker
