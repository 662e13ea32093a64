!> Tests of Hertz theory (doc/theory.md §1.3–1.5) against the published values and the closed forms.
module test_hertz
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input
   use shcontact_core_material, only: material_type
   use shcontact_math_elliptic, only: complete_elliptic
   use shcontact_normal_hertz, only: hertz_shape_type, hertz_type, hertz_shape, &
      hertz_shape_fast, hertz_strip_shapes, hertz_from_load, hertz_from_approach, &
      hertz_from_semiaxes
   implicit none
   private
   public :: collect_hertz

contains

   !> Collect the tests.
   subroutine collect_hertz(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('mnr_table', test_mnr_table), &
         new_unittest('eps_a_table', test_eps_table), &
         new_unittest('swapped_ratio', test_swapped_ratio), &
         new_unittest('contact_fastsim_case', test_fastsim_case), &
         new_unittest('seed_case', test_seed_case), &
         new_unittest('circle_r460', test_circle), &
         new_unittest('closed_forms_section_1_3', test_closed_forms), &
         new_unittest('identity_over_ratio_range', test_identity_range), &
         new_unittest('near_circle_continuity', test_near_circle), &
         new_unittest('inverse_round_trips', test_round_trips), &
         new_unittest('invalid_input', test_invalid), &
         new_unittest('fast_shape_equals_root_search', test_fast_shape), &
         new_unittest('strip_shapes_equal_root_search', test_strip_shapes), &
         new_unittest('fast_shape_invalid_input', test_fast_invalid) &
         ]
   end subroutine collect_hertz

   !> doc/theory.md §1.4: m, n, r and b/a against θ, cos θ = |B − A|/(A + B), to the table's
   !> 4 decimals.
   subroutine test_mnr_table(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: theta(10) = [10, 20, 30, 40, 45, 50, 60, 70, 80, 90]
      real(wp), parameter :: m_ref(10) = [6.6115_wp, 3.8160_wp, 2.7306_wp, 2.1357_wp, 1.9265_wp, &
         1.7541_wp, 1.4858_wp, 1.2851_wp, 1.1278_wp, 1.0_wp]
      real(wp), parameter :: n_ref(10) = [0.3110_wp, 0.4121_wp, 0.4931_wp, 0.5673_wp, 0.6038_wp, &
         0.6407_wp, 0.7171_wp, 0.7999_wp, 0.8927_wp, 1.0_wp]
      real(wp), parameter :: r_ref(10) = [0.4280_wp, 0.6038_wp, 0.7263_wp, 0.8177_wp, 0.8547_wp, &
         0.8867_wp, 0.9376_wp, 0.9726_wp, 0.9932_wp, 1.0_wp]
      real(wp), parameter :: ba_ref(10) = [0.0470_wp, 0.1080_wp, 0.1806_wp, 0.2656_wp, 0.3134_wp, &
         0.3652_wp, 0.4826_wp, 0.6225_wp, 0.7915_wp, 1.0_wp]
      real(wp), parameter :: thr = 5.01e-5_wp
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: shape
      real(wp) :: c
      integer :: i

      do i = 1, size(theta)
         c = cos(theta(i)*pi/180.0_wp)
         call hertz_shape((1.0_wp - c)/(1.0_wp + c), shape, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, shape%m, m_ref(i), thr=thr, message='m')
         if (allocated(error)) return
         call check(error, shape%n, n_ref(i), thr=thr, message='n')
         if (allocated(error)) return
         call check(error, shape%r, r_ref(i), thr=thr, message='r')
         if (allocated(error)) return
         call check(error, shape%n/shape%m, ba_ref(i), thr=thr, message='b/a')
         if (allocated(error)) return
      end do
   end subroutine test_mnr_table

   !> doc/theory.md §1.4: a/b (4 significant digits) and ε_a (4 decimals) against A/B ≤ 1.
   subroutine test_eps_table(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: ratio(13) = [0.01_wp, 0.02_wp, 0.05_wp, 0.1_wp, 0.2_wp, 0.3_wp, &
         0.4_wp, 0.5_wp, 0.6_wp, 0.7_wp, 0.8_wp, 0.9_wp, 1.0_wp]
      real(wp), parameter :: ab_ref(13) = [18.19_wp, 12.07_wp, 6.929_wp, 4.499_wp, 2.890_wp, &
         2.220_wp, 1.838_wp, 1.586_wp, 1.405_wp, 1.268_wp, 1.160_wp, 1.073_wp, 1.0_wp]
      real(wp), parameter :: eps_ref(13) = [0.7679_wp, 0.7445_wp, 0.7059_wp, 0.6694_wp, &
         0.6256_wp, 0.5966_wp, 0.5746_wp, 0.5570_wp, 0.5423_wp, 0.5296_wp, 0.5186_wp, &
         0.5088_wp, 0.5_wp]
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: shape
      integer :: i

      do i = 1, size(ratio)
         call hertz_shape(ratio(i), shape, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, shape%m/shape%n, ab_ref(i), thr=5.01e-4_wp, rel=.true., message='a/b')
         if (allocated(error)) return
         call check(error, shape%eps_a, eps_ref(i), thr=5.01e-5_wp, message='eps_a')
         if (allocated(error)) return
         call check(error, shape%eps_a + shape%eps_b, 1.0_wp, thr=4*epsilon(1.0_wp))
         if (allocated(error)) return
      end do
   end subroutine test_eps_table

   !> Exchanging A and B exchanges the axes: m ↔ n, ε_a ↔ ε_b; g and r are unchanged.
   subroutine test_swapped_ratio(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: s1, s2
      real(wp), parameter :: ratios(4) = [1.0e-3_wp, 0.37_wp, 0.9999_wp, 0.01_wp]
      integer :: i

      do i = 1, size(ratios)
         call hertz_shape(ratios(i), s1, err)
         if (.not. allocated(err)) call hertz_shape(1.0_wp/ratios(i), s2, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, s2%m, s1%n, thr=1.0e-13_wp, rel=.true.)
         if (allocated(error)) return
         call check(error, s2%n, s1%m, thr=1.0e-13_wp, rel=.true.)
         if (allocated(error)) return
         call check(error, s2%eps_a, s1%eps_b, thr=1.0e-13_wp, rel=.true.)
         if (allocated(error)) return
         call check(error, s2%r, s1%r, thr=1.0e-13_wp, rel=.true.)
         if (allocated(error)) return
      end do
   end subroutine test_swapped_ratio

   !> doc/theory.md §1.5, CONTACT examples/fastsim (G = 82 000, ν = 0.28, N = 82 kN): the curvatures
   !> A = 0.8464e-3, B = 2.406e-3 1/mm give a = 8.0000, b = 4.0001, δ = 0.092668 mm,
   !> p₀ = 1223.46 MPa; the inverse problem from a = 8, b = 4 gives those curvatures back (to their
   !> 4 digits), ρ_eff = 614.9 mm and c = 5.657 mm.
   subroutine test_fastsim_case(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: sol
      type(material_type) :: mat

      mat = material_type(shear_modulus=82000.0_wp, poisson=0.28_wp, friction=0.3_wp)
      call hertz_from_load(0.8464e-3_wp, 2.406e-3_wp, 82000.0_wp, mat, sol, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, sol%a, 8.0_wp, thr=5.01e-5_wp, message='a')
      if (allocated(error)) return
      call check(error, sol%b, 4.0001_wp, thr=5.01e-5_wp, message='b')
      if (allocated(error)) return
      call check(error, sol%approach, 0.092668_wp, thr=5.01e-7_wp, message='delta')
      if (allocated(error)) return
      call check(error, sol%p0, 1223.46_wp, thr=5.01e-3_wp, message='p0')
      if (allocated(error)) return

      call hertz_from_semiaxes(8.0_wp, 4.0_wp, 82000.0_wp, mat, sol, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, sol%curv_a, 0.8464e-3_wp, thr=5.01e-8_wp, message='A')
      if (allocated(error)) return
      call check(error, sol%curv_b, 2.406e-3_wp, thr=5.01e-7_wp, message='B')
      if (allocated(error)) return
      call check(error, 2.0_wp/(sol%curv_a + sol%curv_b), 614.9_wp, thr=0.051_wp, &
         message='rho_eff')
      if (allocated(error)) return
      call check(error, sqrt(sol%a*sol%b), 5.657_wp, thr=5.01e-4_wp, message='c')
      if (allocated(error)) return
      call check(error, sol%p0, 1223.0_wp, thr=0.51_wp, message='p0 (CONTACT: 1223)')
      if (allocated(error)) return
      call check(error, sol%a, 8.0_wp, thr=1.0e-12_wp, message='a round trip')
      if (allocated(error)) return
      call check(error, sol%b, 4.0_wp, thr=1.0e-12_wp, message='b round trip')
   end subroutine test_fastsim_case

   !> doc/theory.md §1.5, seed-like data: A = 1/920, B = 1/600, G = 82 670, ν = 0.27, N = 64.7 kN
   !> ⇒ a = 6.2329, b = 4.6885, δ = 0.07886, p₀ = 1057.1.
   subroutine test_seed_case(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: sol
      type(material_type) :: mat

      call hertz_from_load(1.0_wp/920, 1.0_wp/600, 64700.0_wp, mat, sol, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, sol%a, 6.2329_wp, thr=5.01e-5_wp, message='a')
      if (allocated(error)) return
      call check(error, sol%b, 4.6885_wp, thr=5.01e-5_wp, message='b')
      if (allocated(error)) return
      call check(error, sol%approach, 0.07886_wp, thr=5.01e-6_wp, message='delta')
      if (allocated(error)) return
      call check(error, sol%p0, 1057.1_wp, thr=0.0501_wp, message='p0')
   end subroutine test_seed_case

   !> doc/theory.md §1.5: circle R = 460 mm (A = B = 1/920) ⇒ a = b = 5.8197, δ = 0.07363 = a²/R.
   subroutine test_circle(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: sol
      type(material_type) :: mat

      call hertz_from_load(1.0_wp/920, 1.0_wp/920, 64700.0_wp, mat, sol, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, sol%a, 5.8197_wp, thr=5.01e-5_wp, message='a')
      if (allocated(error)) return
      call check(error, sol%b, sol%a, thr=1.0e-14_wp, rel=.true., message='b = a')
      if (allocated(error)) return
      call check(error, sol%approach, 0.07363_wp, thr=5.01e-6_wp, message='delta')
      if (allocated(error)) return
      call check(error, sol%approach, sol%a**2/460.0_wp, thr=1.0e-14_wp, rel=.true., &
         message='delta = a^2/R')
      if (allocated(error)) return
      call check(error, sol%shape%g, 1.0_wp, thr=0.0_wp, message='g = 1 exactly')
   end subroutine test_circle

   !> The solution satisfies the §1.3 formulas written with K, E at its own g: the shape equation,
   !> c³ = 3N E/(2πE*(A+B)√g), δ = minor² K (A+B)/E, p₀ = 3N/(2πab).
   subroutine test_closed_forms(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: sol
      type(material_type) :: mat
      real(wp), parameter :: curv(2, 3) = reshape([3.0e-4_wp, 5.0e-3_wp, 2.0e-3_wp, 1.0e-3_wp, &
         1.0e-2_wp, 1.0e-5_wp], [2, 3])
      real(wp) :: kk, ee, bb, dd, g, c3
      integer :: i

      do i = 1, size(curv, 2)
         call hertz_from_load(curv(1, i), curv(2, i), 5.0e4_wp, mat, sol, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         g = min(sol%a, sol%b)/max(sol%a, sol%b)
         call complete_elliptic(g*g, kk, ee, bb, dd)
         call check(error, g*g*dd/bb, min(curv(1, i), curv(2, i))/max(curv(1, i), curv(2, i)), &
            thr=1.0e-12_wp, rel=.true., message='shape equation')
         if (allocated(error)) return
         c3 = 3.0_wp*sol%load*ee/(2.0_wp*pi*mat%e_star()*(curv(1, i) + curv(2, i))*sqrt(g))
         call check(error, (sol%a*sol%b)**1.5_wp, c3, thr=1.0e-12_wp, rel=.true., message='c^3')
         if (allocated(error)) return
         call check(error, sol%approach, min(sol%a, sol%b)**2*kk*(curv(1, i) + curv(2, i))/ee, &
            thr=1.0e-12_wp, rel=.true., message='approach')
         if (allocated(error)) return
         call check(error, sol%p0, 3.0_wp*sol%load/(2.0_wp*pi*sol%a*sol%b), thr=1.0e-13_wp, &
            rel=.true., message='p0')
         if (allocated(error)) return
         ! A ≤ B ⇔ a is the major axis.
         call check(error, (curv(1, i) <= curv(2, i)) .eqv. (sol%a >= sol%b), &
            message='the smaller curvature gives the longer axis')
         if (allocated(error)) return
      end do
   end subroutine test_closed_forms

   !> A/B from 1e-4 to 1e4: no failure, δ = A a² + B b², ε_a + ε_b = 1, g in (0, 1] and
   !> increasing towards the circle.
   subroutine test_identity_range(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: sol
      type(material_type) :: mat
      real(wp) :: ratio, curv_b, g_prev
      integer :: i
      integer, parameter :: n = 80

      g_prev = 0.0_wp
      do i = 0, n
         ratio = 10.0_wp**(-4.0_wp + 8.0_wp*i/n)
         curv_b = 1.0e-3_wp
         call hertz_from_load(ratio*curv_b, curv_b, 1.0e4_wp, mat, sol, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, sol%approach, sol%curv_a*sol%a**2 + sol%curv_b*sol%b**2, &
            thr=1.0e-12_wp, rel=.true., message='delta = A a^2 + B b^2')
         if (allocated(error)) return
         call check(error, sol%shape%eps_a + sol%shape%eps_b, 1.0_wp, thr=4*epsilon(1.0_wp))
         if (allocated(error)) return
         call check(error, sol%shape%g > 0.0_wp .and. sol%shape%g <= 1.0_wp, message='g in (0,1]')
         if (allocated(error)) return
         if (i <= n/2) then
            call check(error, sol%shape%g > g_prev, message='g increases towards the circle')
            if (allocated(error)) return
         end if
         g_prev = sol%shape%g
      end do
   end subroutine test_identity_range

   !> No cancellation at the circle: ratios 1 ± 1e-10 give g within 1e-9 of 1 and ε_a within
   !> 1e-9 of ½, on the correct side.
   subroutine test_near_circle(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: below, above
      call hertz_shape(1.0_wp - 1.0e-10_wp, below, err)
      if (.not. allocated(err)) call hertz_shape(1.0_wp + 1.0e-10_wp, above, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, below%g, 1.0_wp, thr=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, below%eps_a, 0.5_wp, thr=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, above%eps_a, 0.5_wp, thr=1.0e-9_wp)
      if (allocated(error)) return
      ! A slightly below B: a slightly longer, so ε_a slightly above ½.
      call check(error, below%eps_a > 0.5_wp .and. above%eps_a < 0.5_wp, &
         message='eps_a on the wrong side of 1/2 near the circle')
   end subroutine test_near_circle

   !> load → approach → load, and load → (a, b) → curvatures, for several ratios.
   subroutine test_round_trips(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: s1, s2, s3
      type(material_type) :: mat
      real(wp), parameter :: ratios(6) = [1.0e-4_wp, 0.01_wp, 0.5_wp, 1.0_wp, 3.0_wp, 1.0e4_wp]
      integer :: i

      do i = 1, size(ratios)
         call hertz_from_load(ratios(i)*2.0e-3_wp, 2.0e-3_wp, 6.47e4_wp, mat, s1, err)
         if (.not. allocated(err)) &
            call hertz_from_approach(s1%curv_a, s1%curv_b, s1%approach, mat, s2, err)
         if (.not. allocated(err)) call hertz_from_semiaxes(s1%a, s1%b, s1%load, mat, s3, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, s2%load, s1%load, thr=1.0e-12_wp, rel=.true., message='approach: N')
         if (allocated(error)) return
         call check(error, s2%a, s1%a, thr=1.0e-12_wp, rel=.true., message='approach: a')
         if (allocated(error)) return
         call check(error, s2%b, s1%b, thr=1.0e-12_wp, rel=.true., message='approach: b')
         if (allocated(error)) return
         call check(error, s3%curv_a, s1%curv_a, thr=1.0e-10_wp, rel=.true., message='axes: A')
         if (allocated(error)) return
         call check(error, s3%curv_b, s1%curv_b, thr=1.0e-10_wp, rel=.true., message='axes: B')
         if (allocated(error)) return
         call check(error, s3%approach, s1%approach, thr=1.0e-10_wp, rel=.true., &
            message='axes: delta')
         if (allocated(error)) return
      end do
   end subroutine test_round_trips

   !> Non-Hertzian input is an error value, not a crash.
   subroutine test_invalid(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_type) :: sol
      type(hertz_shape_type) :: shape
      type(material_type) :: mat

      call hertz_from_load(-1.0e-3_wp, 1.0e-3_wp, 1.0e4_wp, mat, sol, err)
      call check(error, allocated(err), message='A < 0 must be an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(err%message, 'curvature A') > 0, message=err%message)
      if (allocated(error)) return
      call hertz_from_approach(1.0e-3_wp, 0.0_wp, 0.1_wp, mat, sol, err)
      call check(error, allocated(err), message='B = 0 must be an error')
      if (allocated(error)) return
      call hertz_from_load(1.0e-3_wp, 1.0e-3_wp, 0.0_wp, mat, sol, err)
      call check(error, allocated(err), message='N = 0 must be an error')
      if (allocated(error)) return
      call hertz_shape(0.0_wp, shape, err)
      call check(error, allocated(err), message='ratio 0 must be an error')
   end subroutine test_invalid

   !> hertz_shape_fast (the polynomial table) gives hertz_shape's (the root search's) shape to a
   !> relative 1e-11 over ρ ∈ [1e-4, 1e4], on a fine logarithmic grid (not aligned with the
   !> table's cells), at the cell and octave edges of the table (2^-k (1 + j/4) and their
   !> neighbours), around the circle, and below the table (ρ < 2^-14: the root search answers,
   !> bit for bit).
   subroutine test_fast_shape(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: ratio, edge
      integer :: i, k, j

      do i = -40000, 40000
         ratio = 10.0_wp**(i*1.0e-4_wp + 3.7e-6_wp)
         call compare_shapes(ratio, 1.0e-11_wp, error)
         if (allocated(error)) return
      end do
      do k = 0, 14
         do j = 0, 3
            edge = 2.0_wp**(-k)*(1.0_wp + j/4.0_wp)
            if (edge > 1.0_wp) cycle
            do i = -1, 1
               ratio = edge + i*spacing(edge)
               call compare_shapes(ratio, 1.0e-11_wp, error)
               if (allocated(error)) return
               call compare_shapes(1.0_wp/ratio, 1.0e-11_wp, error)
               if (allocated(error)) return
            end do
         end do
      end do
      do i = 1, 10
         ratio = 2.0_wp**(-14)*(1.0_wp - 0.05_wp*i)
         call compare_shapes(ratio, 0.0_wp, error)
         if (allocated(error)) return
         call compare_shapes(1.0_wp/ratio, 0.0_wp, error)
         if (allocated(error)) return
      end do
   end subroutine test_fast_shape

   !> Every component of the two shapes at A/B = ratio agrees to a relative tol.
   subroutine compare_shapes(ratio, tol, error)
      real(wp), intent(in) :: ratio, tol
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: exact, fast
      character(len=24) :: at

      call hertz_shape(ratio, exact, err)
      if (.not. allocated(err)) call hertz_shape_fast(ratio, fast, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      write (at, '(a,es14.7,a)') 'A/B =', ratio, ': '
      call check(error, fast%ratio, exact%ratio, message=at//'ratio')
      if (allocated(error)) return
      call check(error, fast%g, exact%g, thr=tol, rel=.true., message=at//'g')
      if (allocated(error)) return
      call check(error, fast%kk, exact%kk, thr=tol, rel=.true., message=at//'K')
      if (allocated(error)) return
      call check(error, fast%ee, exact%ee, thr=tol, rel=.true., message=at//'E')
      if (allocated(error)) return
      call check(error, fast%eps_a, exact%eps_a, thr=tol, rel=.true., message=at//'eps_a')
      if (allocated(error)) return
      call check(error, fast%eps_b, exact%eps_b, thr=tol, rel=.true., message=at//'eps_b')
      if (allocated(error)) return
      call check(error, fast%m, exact%m, thr=tol, rel=.true., message=at//'m')
      if (allocated(error)) return
      call check(error, fast%n, exact%n, thr=tol, rel=.true., message=at//'n')
      if (allocated(error)) return
      call check(error, fast%r, exact%r, thr=tol, rel=.true., message=at//'r')
   end subroutine compare_shapes

   !> hertz_strip_shapes over a table of curvatures (A/B from 1e-4 to 1e4, and the circle)
   !> gives the root search's ε_a, ε_b, m, n and √((A+B)/(E K)) to a relative 1e-11.
   subroutine test_strip_shapes(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 2001
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: exact
      real(wp) :: curv_a(n), curv_b(n), eps_a(n), eps_b(n), m(n), nn(n), p_factor(n)
      integer :: i

      do i = 1, n
         curv_b(i) = 1.0_wp/600.0_wp
         curv_a(i) = curv_b(i)*10.0_wp**(8.0_wp*(i - 1)/(n - 1) - 4.0_wp)
      end do
      ! ρ = 1 (outside the table: the circle of the root search).
      curv_a(1001) = curv_b(1001)
      call hertz_strip_shapes(curv_a, curv_b, eps_a, eps_b, m, nn, p_factor, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 1, n
         call hertz_shape(curv_a(i)/curv_b(i), exact, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, eps_a(i), exact%eps_a, thr=1.0e-11_wp, rel=.true., message='eps_a')
         if (allocated(error)) return
         call check(error, eps_b(i), exact%eps_b, thr=1.0e-11_wp, rel=.true., message='eps_b')
         if (allocated(error)) return
         call check(error, m(i), exact%m, thr=1.0e-11_wp, rel=.true., message='m')
         if (allocated(error)) return
         call check(error, nn(i), exact%n, thr=1.0e-11_wp, rel=.true., message='n')
         if (allocated(error)) return
         call check(error, p_factor(i), sqrt((curv_a(i) + curv_b(i))/(exact%ee*exact%kk)), &
            thr=1.0e-11_wp, rel=.true., message='p_factor')
         if (allocated(error)) return
      end do
   end subroutine test_strip_shapes

   !> The fast shape rejects what the root search rejects (non-positive ratios).
   subroutine test_fast_invalid(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(hertz_shape_type) :: shape
      real(wp), parameter :: bad(3) = [0.0_wp, -2.0_wp, -1.0e-3_wp]
      real(wp) :: eps(2, 5)
      integer :: i

      do i = 1, size(bad)
         call hertz_shape_fast(bad(i), shape, err)
         call check(error, allocated(err), message='expected an error')
         if (allocated(error)) return
         call check(error, err%stat, stat_invalid_input)
         if (allocated(error)) return
      end do
      call hertz_strip_shapes([1.0e-3_wp, 0.0_wp], [1.0e-3_wp, 0.0_wp], eps(:, 1), eps(:, 2), &
         eps(:, 3), eps(:, 4), eps(:, 5), err)
      call check(error, allocated(err), message='strip shapes: expected an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
   end subroutine test_fast_invalid

end module test_hertz
