!> Tests of the semi-Hertzian strip method (doc/theory.md §4.3) and of its options, on patch
!> geometries built from analytic gaps.
module test_semihertz
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_no_contact
   use shcontact_core_material, only: material_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_options, only: normal_options_type, new_normal_options, &
      reduction_constant, reduction_local_hertz, reduction_coupled, method_hertz
   use shcontact_normal_hertz, only: hertz_type, hertz_shape_type, hertz_from_load, &
      hertz_from_approach, hertz_shape
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, &
      solve_approach, solve_load
   use shcontact_normal_pressure, only: element_pressure
   use shcontact_normal_reference, only: reference_index
   implicit none
   private
   public :: collect_semihertz, polynomial_patch

   !> Seed-like curvatures (doc/theory.md §1.5): A = 1/920, B = 1/600 1/mm, N = 64.7 kN.
   real(wp), parameter :: seed_a = 1.0_wp/920, seed_b = 1.0_wp/600, seed_load = 64700.0_wp

contains

   !> Collect the tests.
   subroutine collect_semihertz(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('quadratic_gap_is_hertz', test_quadratic_default), &
         new_unittest('quadratic_gap_local_hertz_k', test_quadratic_local_hertz_k), &
         new_unittest('quadratic_gap_converges', test_quadratic_convergence), &
         new_unittest('load_matched_1e-10', test_load_matched), &
         new_unittest('mirror_symmetry', test_mirror), &
         new_unittest('n_of_delta_continuous', test_continuity), &
         new_unittest('local_eps_from_local_ratio', test_local_eps), &
         new_unittest('constant_eps_half_is_exact_on_circle', test_constant_half), &
         new_unittest('constant_eps_055_on_circle', test_constant_055), &
         new_unittest('table_too_short', test_table_too_short), &
         new_unittest('approach_below_contact', test_below_contact), &
         new_unittest('invalid_geometry', test_invalid_geometry), &
         new_unittest('coupled_is_hertz_on_quadratic_gap', test_coupled_hertz), &
         new_unittest('coupled_smooth_across_curvature_step', test_coupled_step), &
         new_unittest('options_parser', test_options), &
         new_unittest('element_pressure', test_element_pressure), &
         new_unittest('reference_point_continuous_between_minima', test_reference_blend), &
         new_unittest('reference_point_continuous_where_wiggles_tie', test_reference_ties) &
         ]
   end subroutine collect_semihertz

   !> A patch geometry from the polynomial gap g = B₀y² + c₃y³ + c₄y⁴, so that
   !> B(y) = ½g'' = B₀ + 3c₃y + 6c₄y², with A(y) = A₀ + A₁y, on y = −half … half (spacing h;
   !> half a multiple of h). γ and r_w vary mildly and linearly; the reference point is y = 0.
   subroutine polynomial_patch(geom, curv_a0, curv_b0, half, h, curv_a1, c3, c4, gamma0, gap0)
      !> The geometry.
      type(patch_geometry_type), intent(out) :: geom
      !> A₀, B₀ (1/mm), table half-width and spacing (mm).
      real(wp), intent(in) :: curv_a0, curv_b0, half, h
      !> A₁ (1/mm²), c₃ (1/mm²), c₄ (1/mm³), γ₀ (rad), g₀ (mm); zero when absent.
      real(wp), intent(in), optional :: curv_a1, c3, c4, gamma0, gap0
      real(wp) :: a1, k3, k4
      integer :: i, n

      a1 = 0.0_wp; k3 = 0.0_wp; k4 = 0.0_wp
      if (present(curv_a1)) a1 = curv_a1
      if (present(c3)) k3 = c3
      if (present(c4)) k4 = c4
      if (present(gamma0)) geom%gamma0 = gamma0
      if (present(gap0)) geom%gap0 = gap0
      geom%r0 = 460.0_wp
      geom%h = h
      n = 2*nint(half/h) + 1
      allocate (geom%y(n), geom%gap(n), geom%curv_a(n), geom%curv_b(n), geom%gamma(n), &
         geom%r_wheel(n))
      do i = 1, n
         geom%y(i) = (i - (n + 1)/2)*h
      end do
      geom%gap = curv_b0*geom%y**2 + k3*geom%y**3 + k4*geom%y**4
      geom%curv_b = curv_b0 + 3*k3*geom%y + 6*k4*geom%y**2
      geom%curv_a = curv_a0 + a1*geom%y
      geom%gamma = geom%gamma0 + 2.0e-3_wp*geom%y
      geom%r_wheel = geom%r0 + 4.0e-2_wp*geom%y
   end subroutine polynomial_patch

   !> Prepare a contact, turning a library error into a test failure.
   subroutine prepare(contact, geom, options, error)
      type(normal_contact_type), intent(inout) :: contact
      type(patch_geometry_type), intent(in) :: geom
      type(normal_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(material_type) :: mat
      call prepare_normal_contact(contact, geom, options, mat, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine prepare

   !> The seed's curvatures on g = B y² (A, B constant): the Hertz solution at the seed's load,
   !> and the strips of `options` solved for that load.
   subroutine seed_quadratic(options, contact, patch, hz, error)
      type(normal_options_type), intent(in) :: options
      type(normal_contact_type), intent(out) :: contact
      type(normal_patch_type), intent(out) :: patch
      type(hertz_type), intent(out) :: hz
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(material_type) :: mat

      call hertz_from_load(seed_a, seed_b, seed_load, mat, hz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call polynomial_patch(geom, seed_a, seed_b, 10.0_wp, 0.01_wp)
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, patch, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine seed_quadratic

   !> The local-Hertz strips on g = B y² (no coupling): k_i = √(1 − y_i²/b²) within 0.005 on
   !> every strip, the seed's requirement, exactly as doc/theory.md §4.3's "Hertz check" states.
   subroutine test_quadratic_local_hertz_k(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(hertz_type) :: hz

      call seed_quadratic(normal_options_type(reduction=reduction_local_hertz), contact, patch, &
         hz, error)
      if (allocated(error)) return
      call check(error, maxval(abs(patch%k - sqrt(1.0_wp - (patch%y/hz%b)**2))) < 5.0e-3_wp, &
         message='local-Hertz k_i differs from sqrt(1 - y^2/b^2)')
   end subroutine test_quadratic_local_hertz_k

   !> On g = B y² with constant A, B the default strips reproduce Hertz (§4.3 "Hertz check"):
   !> at N = 64.7 kN the approach, a, b and p₀ within 0.5 %; at the Hertz approach the load.
   subroutine test_quadratic_default(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(hertz_type) :: hz

      call seed_quadratic(normal_options_type(), contact, patch, hz, error)
      if (allocated(error)) return
      call check(error, patch%n_strips, 100)
      if (allocated(error)) return
      call check(error, patch%approach, hz%approach, thr=5.0e-3_wp, rel=.true., message='delta')
      if (allocated(error)) return
      call check(error, maxval(patch%a), hz%a, thr=5.0e-3_wp, rel=.true., message='a')
      if (allocated(error)) return
      call check(error, 0.5_wp*patch%n_strips*patch%dy, hz%b, thr=5.0e-3_wp, rel=.true., &
         message='b')
      if (allocated(error)) return
      call check(error, patch%p_max, hz%p0, thr=5.0e-3_wp, rel=.true., message='p0')
      if (allocated(error)) return
      ! Hertz's k_i = a_i/a = √(1 − y_i²/b²) (the seed's requirement): within 0.005 on the
      ! inner 80 % of the width (0.0034 measured). The coupled reduction's strip lengths follow
      ! the coupled loads; on the outer strips (k 0.16–0.6, half-lengths of 0.7–2.8 mm over
      ! 0.2 mm wide strips) the coupled solution, collocated on a few narrow groups, is off by up
      ! to 0.045 in k (measured; 0.047 with the former partition by index): within 0.05 there. The local-Hertz strips themselves are exact
      ! (test quadratic_gap_local_hertz_k).
      call check(error, maxval(abs(patch%k - sqrt(1.0_wp - (patch%y/hz%b)**2)), &
         mask=abs(patch%y) < 0.8_wp*hz%b) < 5.0e-3_wp, &
         message='k_i differs from sqrt(1 - y^2/b^2) inside 0.8 b')
      if (allocated(error)) return
      call check(error, maxval(abs(patch%k - sqrt(1.0_wp - (patch%y/hz%b)**2))) < 5.0e-2_wp, &
         message='k_i differs from sqrt(1 - y^2/b^2) near the ends')
      if (allocated(error)) return

      call solve_approach(contact, hz%approach, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%load, hz%load, thr=5.0e-3_wp, rel=.true., message='N at delta_H')
   end subroutine test_quadratic_default

   !> `reduction = 'coupled'` (shcontact_normal_coupling) on g = B y²: the Hertz pressure satisfies
   !> the half-space condition on every strip's centre line, so the coupled strips stay Hertz's:
   !> the load exactly (it is kept), the approach and p₀ within 2 %, and every strip keeps load.
   !> Against the local-Hertz strips (Hertz's own on this gap): the approach is theirs (the
   !> coupling keeps the load–approach relation) and every strip load within 2.5 % of the largest
!> at 50 strips (2.14 % measured, at the ellipse's ends: the end group's single length and
!> width), and within 6 % at every even strip count 40 … 64 (2.1–5.5 % measured with the groups
!> fixed in position, shcontact_normal_coupling_groups, the worst at 56–58 strips; 2.0–8.6 % with
!> the former partition by index, which this check held at its 2.0 % of 50 strips alone:
!> doc/performance.md, "The preset's deviation and the strip count").
   subroutine test_coupled_hertz(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch, local
      type(hertz_type) :: hz
      type(material_type) :: mat

      call hertz_from_load(seed_a, seed_b, seed_load, mat, hz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call new_normal_options(options, err, reduction='coupled', n_strips=50)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call polynomial_patch(geom, seed_a, seed_b, 10.0_wp, 0.01_wp)
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%load, seed_load, thr=1.0e-10_wp, rel=.true., message='N kept')
      if (allocated(error)) return
      call check(error, patch%approach, hz%approach, thr=2.0e-2_wp, rel=.true., message='delta')
      if (allocated(error)) return
      call check(error, patch%p_max, hz%p0, thr=2.0e-2_wp, rel=.true., message='p0')
      if (allocated(error)) return
      call check(error, count(patch%strip_load > 0.0_wp), 50, message='loaded strips')
      if (allocated(error)) return
      options%reduction = reduction_local_hertz
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, local, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%approach, local%approach, thr=1.0e-14_wp, rel=.true., &
         message='approach of the local-Hertz strips')
      if (allocated(error)) return
      call check(error, maxval(abs(patch%strip_load - local%strip_load)) <= &
         2.5e-2_wp*maxval(local%strip_load), message='strip loads differ from Hertz by > 2.5 %')
      if (allocated(error)) return
      block
         integer :: n
         character(len=80) :: buf
         do n = 40, 64, 2
            call solve_both_reductions(geom, 'coupled', 'local-hertz', n, patch, local, error)
            if (allocated(error)) return
            write (buf, '(a, i0, a, f6.2, a)') 'strip loads at ', n, ' strips differ from Hertz by ', &
               1.0e2_wp*maxval(abs(patch%strip_load - local%strip_load))/maxval(local%strip_load), ' %'
            call check(error, maxval(abs(patch%strip_load - local%strip_load)) <= &
               6.0e-2_wp*maxval(local%strip_load), message=trim(buf)//' (> 6 %)')
            if (allocated(error)) return
         end do
      end block
   end subroutine test_coupled_hertz

   !> The gap solved at the seed load on n strips with two reductions, `first` then `second`.
   subroutine solve_both_reductions(geom, first, second, n, first_patch, second_patch, error)
      type(patch_geometry_type), intent(in) :: geom
      character(len=*), intent(in) :: first, second
      integer, intent(in) :: n
      type(normal_patch_type), intent(out) :: first_patch, second_patch
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact

      call new_normal_options(options, err, reduction=first, n_strips=n)
      if (.not. allocated(err)) then
         call prepare(contact, geom, options, error)
         if (allocated(error)) return
         call solve_load(contact, seed_load, first_patch, err)
      end if
      if (.not. allocated(err)) call new_normal_options(options, err, reduction=second, n_strips=n)
      if (.not. allocated(err)) then
         call prepare(contact, geom, options, error)
         if (allocated(error)) return
         call solve_load(contact, seed_load, second_patch, err)
      end if
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine solve_both_reductions

   !> A gap whose lateral curvature steps from B to B/4 at y_s = b/3 inside the patch (g and g'
   !> continuous, as where two arcs of a profile meet): the local-Hertz strips step there, the
   !> coupled ones, whose load within a group is the group-width mean of the local one
   !> (doc/validation.md §6.9), do not. Measured by the largest ratio of neighbouring strip
   !> loads among the strips carrying at least a fifth of the largest (the contact's edges
   !> excluded): at least 1.5 for the local-Hertz strips (1.54, the step), at most 1.25 coupled
   !> (1.19; 1.49 when the groups scaled the local loads themselves).
   subroutine test_coupled_step(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_patch_type) :: coupled, local
      type(hertz_type) :: hz
      type(material_type) :: mat
      real(wp) :: ys, step_local, step_coupled
      character(len=120) :: buf

      call hertz_from_load(seed_a, seed_b, seed_load, mat, hz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      ys = hz%b/3.0_wp
      call polynomial_patch(geom, seed_a, seed_b, 10.0_wp, 0.01_wp)
      where (geom%y > ys)
         geom%gap = seed_b*ys**2 + 2.0_wp*seed_b*ys*(geom%y - ys) + 0.25_wp*seed_b*(geom%y - ys)**2
         geom%curv_b = 0.25_wp*seed_b
      end where
      call solve_both_reductions(geom, 'local-hertz', 'coupled', 100, local, coupled, error)
      if (allocated(error)) return
      step_local = largest_step(local%strip_load)
      step_coupled = largest_step(coupled%strip_load)
      write (buf, '(a, f7.4, a, f7.4)') 'largest neighbour ratio: local-Hertz ', step_local, &
         ', coupled ', step_coupled
      call check(error, step_local >= 1.5_wp, message=trim(buf)//' (no step to smooth)')
      if (allocated(error)) return
      call check(error, step_coupled <= 1.25_wp, message=trim(buf))
      if (allocated(error)) return
      call check(error, coupled%load, seed_load, thr=1.0e-10_wp, rel=.true., message='N kept')
   contains
      !> The largest ratio of neighbouring strip loads above a fifth of the largest.
      pure real(wp) function largest_step(q) result(step)
         real(wp), intent(in) :: q(:)
         integer :: i
         step = 1.0_wp
         do i = 1, size(q) - 1
            if (min(q(i), q(i + 1)) < 0.2_wp*maxval(q)) cycle
            step = max(step, q(i)/q(i + 1), q(i + 1)/q(i))
         end do
      end function largest_step
   end subroutine test_coupled_step

   !> Refining the strips (20 → 160, even so that no strip sits on the axis) converges to Hertz: the errors of the load at the Hertz
   !> approach, of max a_i and of p_max fall at least by half per doubling (the midpoint rule
   !> gives a quarter).
   subroutine test_quadratic_convergence(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(hertz_type) :: hz
      type(material_type) :: mat
      real(wp) :: e_load(4), e_a(4), e_p(4)
      integer :: i
      character(len=200) :: buf

      call hertz_from_load(seed_a, seed_b, seed_load, mat, hz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call polynomial_patch(geom, seed_a, seed_b, 10.0_wp, 0.01_wp)
      do i = 1, 4
         ! The convergence of the strip method itself (the coupled reduction has its own tests).
         options%reduction = reduction_local_hertz
         options%n_strips = 20*2**(i - 1)
         call prepare(contact, geom, options, error)
         if (allocated(error)) return
         call solve_approach(contact, hz%approach, patch, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         e_load(i) = abs(patch%load/hz%load - 1.0_wp)
         e_a(i) = abs(maxval(patch%a)/hz%a - 1.0_wp)
         e_p(i) = abs(patch%p_max/hz%p0 - 1.0_wp)
      end do
      write (buf, '(a,4es10.2,a,4es10.2,a,4es10.2)') 'load errors', e_load, '; a', e_a, '; p0', e_p
      call check(error, all(e_load(2:4) < 0.5_wp*e_load(1:3)) .and. &
         all(e_a(2:4) < 0.5_wp*e_a(1:3)) .and. all(e_p(2:4) < 0.5_wp*e_p(1:3)), &
         message='no convergence in n_strips: '//trim(buf))
      if (allocated(error)) return
      call check(error, e_load(4) < 1.0e-4_wp, message='160 strips: '//trim(buf))
   end subroutine test_quadratic_convergence

   !> Σ N_i equals the prescribed force to 1e-10 (relative) on a non-Hertzian patch, from a light
   !> to a heavy load.
   subroutine test_load_matched(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      real(wp), parameter :: loads(5) = [10.0_wp, 1.0e3_wp, 1.0e4_wp, 64.7e3_wp, 2.0e5_wp]
      integer :: i, red

      call polynomial_patch(geom, seed_a, seed_b, 12.0_wp, 0.02_wp, curv_a1=2.0e-5_wp, &
         c3=4.0e-5_wp, c4=2.0e-6_wp)
      do red = 1, 2
         if (red == 2) options%reduction = reduction_constant
         call prepare(contact, geom, options, error)
         if (allocated(error)) return
         do i = 1, size(loads)
            call solve_load(contact, loads(i), patch, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            call check(error, sum(patch%strip_load), loads(i), thr=1.0e-10_wp, rel=.true., &
               message='sum N_i')
            if (allocated(error)) return
            call check(error, patch%load, loads(i), thr=1.0e-10_wp, rel=.true., message='load')
            if (allocated(error)) return
            call check(error, patch%area, 2*sum(patch%a)*patch%dy, thr=1.0e-12_wp, rel=.true., &
               message='area')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_load_matched

   !> Mirroring the geometry (y → −y) mirrors the strip table.
   subroutine test_mirror(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: g1, g2
      type(normal_options_type) :: options
      type(normal_contact_type) :: c1, c2
      type(normal_patch_type) :: p1, p2
      integer :: n

      call polynomial_patch(g1, seed_a, seed_b, 9.0_wp, 0.02_wp, curv_a1=3.0e-5_wp, &
         c3=6.0e-5_wp)
      call polynomial_patch(g2, seed_a, seed_b, 9.0_wp, 0.02_wp, curv_a1=-3.0e-5_wp, &
         c3=-6.0e-5_wp)
      call prepare(c1, g1, options, error)
      if (allocated(error)) return
      call prepare(c2, g2, options, error)
      if (allocated(error)) return
      call solve_load(c1, seed_load, p1, err)
      if (.not. allocated(err)) call solve_load(c2, seed_load, p2, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      n = p1%n_strips
      call check(error, maxval(abs(p1%y + p2%y(n:1:-1))) < 1.0e-12_wp, message='y_i not mirrored')
      if (allocated(error)) return
      call check(error, maxval(abs(p1%a - p2%a(n:1:-1))) < 1.0e-11_wp, message='a_i not mirrored')
      if (allocated(error)) return
      call check(error, maxval(abs(p1%p0 - p2%p0(n:1:-1))) < 1.0e-8_wp, message='p0 not mirrored')
      if (allocated(error)) return
      call check(error, p1%approach, p2%approach, thr=1.0e-13_wp, rel=.true.)
      if (allocated(error)) return
      ! The asymmetric gap shifts the patch to the flatter side (c₃ > 0: y < 0).
      call check(error, sum(p1%y*p1%strip_load) < 0.0_wp, message='load centre on the wrong side')
   end subroutine test_mirror

   !> N(δ) is increasing and continuous (strips of equal width over the whole interval), also
   !> across the table points where the interval enters a new cell.
   subroutine test_continuity(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      real(wp) :: delta, n_prev, step
      integer :: i

      call polynomial_patch(geom, seed_a, seed_b, 12.0_wp, 0.5_wp, curv_a1=2.0e-5_wp, &
         c3=4.0e-5_wp, c4=2.0e-6_wp)
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      step = 1.0e-4_wp
      n_prev = 0.0_wp
      do i = 1, 1000
         delta = i*step
         call solve_approach(contact, delta, patch, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, patch%load > n_prev, message='N(delta) not increasing')
         if (allocated(error)) return
         ! Hertz-like growth: dN/dδ ≈ 3N/(2δ); a jump would exceed it many times.
         call check(error, patch%load - n_prev < 3.0_wp*1.5_wp*patch%load/delta*step + 1.0_wp, &
            message='N(delta) jumps')
         if (allocated(error)) return
         n_prev = patch%load
      end do
   end subroutine test_continuity

   !> With A/B varying along y, each strip's ε_a, m, n are Hertz's at the local ratio
   !> A(y_i)/B(y_i) (to the table's interpolation error).
   subroutine test_local_eps(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(hertz_shape_type) :: shape
      real(wp) :: ratio
      integer :: i

      call polynomial_patch(geom, seed_a, seed_b, 12.0_wp, 0.02_wp, curv_a1=8.0e-5_wp, &
         c4=5.0e-6_wp)
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, maxval(patch%eps_a) - minval(patch%eps_a) > 0.02_wp, &
         message='test geometry should vary eps_a')
      if (allocated(error)) return
      do i = 1, patch%n_strips, 7
         ratio = (seed_a + 8.0e-5_wp*patch%y(i))/(seed_b + 30.0e-6_wp*patch%y(i)**2)
         call hertz_shape(ratio, shape, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, patch%eps_a(i), shape%eps_a, thr=1.0e-5_wp, message='eps_a')
         if (allocated(error)) return
         call check(error, patch%m(i), shape%m, thr=1.0e-4_wp, rel=.true., message='m')
         if (allocated(error)) return
         call check(error, patch%n(i), shape%n, thr=1.0e-4_wp, rel=.true., message='n')
         if (allocated(error)) return
      end do
   end subroutine test_local_eps

   !> On a circle (A = B) ε_a = ε_b = ½, so the constant reduction with ε = 0.5 is the
   !> local-Hertz method, strip for strip.
   subroutine test_constant_half(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: o1, o2
      type(normal_contact_type) :: c1, c2
      type(normal_patch_type) :: p1, p2

      call polynomial_patch(geom, seed_a, seed_a, 10.0_wp, 0.01_wp)
      o1%reduction = reduction_local_hertz
      call new_normal_options(o2, err, reduction='constant', epsilon=0.5_wp)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call prepare(c1, geom, o1, error)
      if (allocated(error)) return
      call prepare(c2, geom, o2, error)
      if (allocated(error)) return
      call solve_load(c1, seed_load, p1, err)
      if (.not. allocated(err)) call solve_load(c2, seed_load, p2, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, p2%approach, p1%approach, thr=1.0e-12_wp, rel=.true.)
      if (allocated(error)) return
      call check(error, maxval(abs(p1%a - p2%a)) < 1.0e-11_wp, message='a_i differ')
      if (allocated(error)) return
      call check(error, maxval(abs(p1%p0 - p2%p0)) < 1.0e-8_wp, message='p0_i differ')
      if (allocated(error)) return
      ! Decision 6: k_i = a_i/max a_j, which is √(1 − y²/b²) on the circle as well.
      call check(error, maxval(abs(p1%k - p2%k)) < 1.0e-4_wp, message='k_i differ')
   end subroutine test_constant_half

   !> Constant ε on a circle of curvature A (closed form): the contact is the circle of radius
   !> ρ_c = √(εδ/A) and p₀,ᵢ = (2√2/π)E*√(A)·a_i, hence N = (4√2/3)E* ε δ^{3/2}/√A — 2ε times
   !> Hertz's load at the same approach. ε = 0.55 gives a smaller approach and a larger patch.
   subroutine test_constant_055(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(material_type) :: mat
      type(hertz_type) :: hz
      real(wp), parameter :: eps = 0.55_wp
      real(wp) :: delta, radius

      call polynomial_patch(geom, seed_a, seed_a, 10.0_wp, 0.01_wp)
      call new_normal_options(options, err, reduction='constant')
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, options%epsilon, eps, message='default epsilon')
      if (allocated(error)) return
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, patch, err)
      if (.not. allocated(err)) call hertz_from_load(seed_a, seed_a, seed_load, mat, hz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      delta = (3.0_wp*seed_load*sqrt(seed_a)/(4.0_wp*sqrt(2.0_wp)*mat%e_star()*eps))**(2.0_wp/3)
      radius = sqrt(eps*delta/seed_a)
      call check(error, patch%approach, delta, thr=5.0e-3_wp, rel=.true., message='delta')
      if (allocated(error)) return
      call check(error, 0.5_wp*patch%n_strips*patch%dy, radius, thr=5.0e-3_wp, rel=.true., &
         message='patch half-width')
      if (allocated(error)) return
      call check(error, maxval(patch%a), radius, thr=5.0e-3_wp, rel=.true., message='max a_i')
      if (allocated(error)) return
      call check(error, patch%p_max, 2*sqrt(2.0_wp)/pi*mat%e_star()*sqrt(seed_a*delta), &
         thr=5.0e-3_wp, rel=.true., message='p_max')
      if (allocated(error)) return
      call check(error, maxval(patch%k), 1.0_wp, thr=0.0_wp, message='max k_i = 1')
      if (allocated(error)) return
      ! Against local-Hertz (= Hertz here): approach ×(2ε)^{-2/3} ≈ 0.938, patch ×1.02.
      call check(error, patch%approach/hz%approach, (2*eps)**(-2.0_wp/3), thr=5.0e-3_wp, &
         rel=.true., message='approach ratio to Hertz')
      if (allocated(error)) return
      call check(error, radius > 1.01_wp*hz%a, message='constant 0.55 should widen the patch')
   end subroutine test_constant_055

   !> A table narrower than the patch: "load too large for the patch geometry" (stat_no_contact),
   !> both for a prescribed force and a prescribed approach.
   subroutine test_table_too_short(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch

      call polynomial_patch(geom, seed_a, seed_b, 3.0_wp, 0.01_wp)
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, patch, err)
      call check(error, allocated(err), message='a 4.7 mm wide patch on a 3 mm table must fail')
      if (allocated(error)) return
      call check(error, err%stat, stat_no_contact)
      if (allocated(error)) return
      call check(error, index(err%message, 'load too large for the patch geometry') > 0, &
         message=err%message)
      if (allocated(error)) return
      call solve_approach(contact, 0.1_wp, patch, err)
      call check(error, allocated(err), message='approach beyond the table must fail')
      if (allocated(error)) return
      call check(error, index(err%message, 'load too large for the patch geometry') > 0, &
         message=err%message)
      if (allocated(error)) return
      ! A load the table can carry still works.
      call solve_load(contact, 0.1_wp*seed_load, patch, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine test_table_too_short

   !> A prescribed approach at or below first contact is stat_no_contact, not a crash.
   subroutine test_below_contact(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      real(wp), parameter :: approaches(2) = [0.0_wp, -0.05_wp]
      integer :: i, m

      call polynomial_patch(geom, seed_a, seed_b, 10.0_wp, 0.05_wp)
      do m = 1, 2
         if (m == 2) options%method = method_hertz
         call prepare(contact, geom, options, error)
         if (allocated(error)) return
         do i = 1, size(approaches)
            call solve_approach(contact, approaches(i), patch, err)
            call check(error, allocated(err), message='no contact must be an error')
            if (allocated(error)) return
            call check(error, err%stat, stat_no_contact)
            if (allocated(error)) return
            call check(error, index(err%message, 'do not touch') > 0, message=err%message)
            if (allocated(error)) return
         end do
      end do
   end subroutine test_below_contact

   !> Tables the strip method cannot use are input errors naming the problem.
   subroutine test_invalid_geometry(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(material_type) :: mat

      call prepare_normal_contact(contact, geom, options, mat, err)
      call check(error, allocated(err), message='empty geometry must be an error')
      if (allocated(error)) return
      call polynomial_patch(geom, seed_a, seed_b, 5.0_wp, 0.1_wp)
      geom%curv_b(7) = 0.0_wp
      call prepare_normal_contact(contact, geom, options, mat, err)
      call check(error, allocated(err), message='B = 0 must be an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(err%message, 'B > 0') > 0, message=err%message)
      if (allocated(error)) return
      call polynomial_patch(geom, seed_a, seed_b, 5.0_wp, 0.1_wp)
      geom%y = geom%y + 6.0_wp
      call prepare_normal_contact(contact, geom, options, mat, err)
      call check(error, allocated(err), message='a table without y = 0 must be an error')
      if (allocated(error)) return
      call polynomial_patch(geom, seed_a, seed_b, 5.0_wp, 0.1_wp)
      geom%y(3) = geom%y(3) + 0.01_wp
      call prepare_normal_contact(contact, geom, options, mat, err)
      call check(error, allocated(err), message='a non-uniform grid must be an error')
   end subroutine test_invalid_geometry

   !> The textual options: known names (any case, `_` for `-`) and clear errors otherwise.
   subroutine test_options(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options

      call new_normal_options(options, err, method='Semi_Hertz', reduction='CONSTANT', &
         epsilon=0.5_wp, n_strips=40)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, options%reduction, reduction_constant)
      if (allocated(error)) return
      call check(error, options%n_strips, 40)
      if (allocated(error)) return
      call new_normal_options(options, err, method='stripes')
      call check(error, allocated(err), message='unknown method must be an error')
      if (allocated(error)) return
      call check(error, index(err%message, "'stripes'") > 0 .and. &
         index(err%message, "'semi-hertz', 'hertz'") > 0, message=err%message)
      if (allocated(error)) return
      call new_normal_options(options, err, reduction='kp')
      call check(error, allocated(err), message='unknown reduction must be an error')
      if (allocated(error)) return
      call check(error, index(err%message, "'coupled', 'local-hertz', 'constant'") > 0, &
         message=err%message)
      if (allocated(error)) return
      call new_normal_options(options, err, epsilon=1.5_wp)
      call check(error, allocated(err), message='epsilon > 1 must be an error')
      if (allocated(error)) return
      call new_normal_options(options, err, n_strips=0)
      call check(error, allocated(err), message='n_strips = 0 must be an error')
   end subroutine test_options

   !> Element pressures: symmetric about x = 0, below p₀,ᵢ, and Σ p Δx δy → Σ N_i as n_x grows
   !> (midpoint rule on the semi-ellipse, error ~ n_x^{-3/2}).
   subroutine test_element_pressure(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      real(wp), allocatable :: pn(:, :), x(:, :)
      real(wp) :: rel(3), total
      integer :: k, nx, i

      call polynomial_patch(geom, seed_a, seed_b, 10.0_wp, 0.02_wp, c4=3.0e-6_wp)
      call prepare(contact, geom, options, error)
      if (allocated(error)) return
      call solve_load(contact, seed_load, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do k = 1, 3
         nx = 25*4**(k - 1)
         allocate (pn(nx, patch%n_strips), x(nx, patch%n_strips))
         call element_pressure(patch, pn, x)
         total = 0.0_wp
         do i = 1, patch%n_strips
            total = total + sum(pn(:, i))*2*patch%a(i)/nx*patch%dy
         end do
         rel(k) = abs(total/patch%load - 1.0_wp)
         call check(error, maxval(abs(pn - pn(nx:1:-1, :))) < 1.0e-9_wp, &
            message='pressure not symmetric in x')
         if (allocated(error)) return
         call check(error, all(pn(1, :) <= patch%p0), message='pressure above p0')
         if (allocated(error)) return
         call check(error, x(1, 50), patch%a(50)*(1.0_wp - 1.0_wp/nx), thr=1.0e-12_wp, &
            message='first centre at a_i - dx/2')
         if (allocated(error)) return
         deallocate (pn, x)
      end do
      call check(error, rel(2) < rel(1)/4 .and. rel(3) < rel(2)/4 .and. rel(2) < 2.0e-3_wp, &
         message='element pressure does not integrate to the strip loads')
   end subroutine test_element_pressure

   !> The reference point on a loaded gap with two minima whose depths cross
   !> (shcontact_normal_reference): g(x) = (x² − 1)²/4 + e x on x = −2 … 2 (the table's tilt
   !> term times the approach is the e x), minima near ±1 and a ridge of 1/4 between them. For
   !> e beyond the band s = 0.05 (the minima's depths differ by ≈ 2|e| > s) it is the deepest
   !> minimum refined by the parabola, exactly as the minimum search alone; at e = 0 it lies
   !> midway; over e = −0.05 … 0.05 in steps of 1e-4 it moves by less than 2 steps of the
   !> table between neighbours (the minimum alone jumps by 80 steps at e = 0), and
   !> monotonically. A single minimum (e = 0.5: the left one only) is the parabola's vertex.
   subroutine test_reference_blend(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 161
      real(wp), parameter :: band = 0.05_wp
      real(wp) :: x(n), gap(n), slope(n), here, last, alone, largest
      integer :: i, k
      logical :: monotone

      do i = 1, n
         x(i) = -2.0_wp + 4.0_wp*(i - 1)/(n - 1)
         gap(i) = 0.25_wp*(x(i)**2 - 1.0_wp)**2
         slope(i) = x(i)
      end do
      ! Far from the crossing: the deepest minimum as the search alone gives it.
      do k = -1, 1, 2
         here = reference_index(gap, slope, k*0.06_wp, 1, n, band)
         alone = reference_index(gap, slope, k*0.06_wp, 1, n, 0.0_wp)
         call check(error, here == alone .and. abs(here - (81 - k*40)) < 2.0_wp, &
            'beyond the band: the deepest minimum')
         if (allocated(error)) return
      end do
      here = reference_index(gap, slope, 0.0_wp, 1, n, band)
      call check(error, abs(here - 81.0_wp) < 1.0e-12_wp, 'equal depths: midway')
      if (allocated(error)) return
      largest = 0.0_wp
      monotone = .true.
      last = reference_index(gap, slope, -0.05_wp, 1, n, band)
      do k = -499, 500
         here = reference_index(gap, slope, k*1.0e-4_wp, 1, n, band)
         largest = max(largest, abs(here - last))
         monotone = monotone .and. here <= last
         last = here
      end do
      call check(error, largest < 2.0_wp .and. monotone, 'continuous across the crossing')
      if (allocated(error)) return
      here = reference_index(gap, slope, 0.5_wp, 1, n, band)
      alone = reference_index(gap, slope, 0.5_wp, 1, n, 0.0_wp)
      call check(error, here == alone, 'one minimum: its vertex')
   end subroutine test_reference_blend

   !> A double well with wiggles of three wavelengths (three seeds of the phases), tilted by a
   !> over −0.1 … 0.1 in steps of 1e-5: minima are born, vanish and cross in depth. Each of the
   !> ten largest steps of the reference point is zoomed into four times, cutting the step that
   !> moves most into 10: a continuous point moves by about a tenth of the step in the largest
   !> cut (at most half is allowed), a jump keeps the whole move in one cut at every level. The
   !> elder rule of persistence jumped by 1.9 table points at seeds 0 and 1 (two wiggles of the
   !> same side crossing in depth: their bands swapped; doc/kinematics.md, "A jump of the
   !> reference point at the flange root"); seed 7 has the steepest continuous swings (up to 3.9
   !> points per step).
   subroutine test_reference_ties(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 401, steps = 20000, largest = 10, levels = 4, cuts = 10
      integer, parameter :: seeds(3) = [0, 1, 7]
      real(wp), parameter :: band = 0.3_wp, step = 1.0e-5_wp
      real(wp) :: x(n), gap(n), point(0:steps), moves(steps), lo, width, move, cut_move, &
         here, last, at
      integer :: i, k, m, level, seed
      character(len=120) :: message

      do m = 1, size(seeds)
         seed = seeds(m)
         do i = 1, n
            x(i) = -2.0_wp + 4.0_wp*(i - 1)/(n - 1)
            gap(i) = 0.5_wp*(x(i)**2 - 1.0_wp)**2 + 0.02_wp*sin(7.3_wp*x(i) + seed) + &
               0.015_wp*sin(13.1_wp*x(i) + 1.0_wp + 2*seed) + 0.004_wp*sin(41.0_wp*x(i) + 3*seed)
         end do
         do k = 0, steps
            point(k) = reference_index(gap, x, -0.1_wp + k*step, 1, n, band)
         end do
         moves = abs(point(1:steps) - point(0:steps - 1))
         do i = 1, largest
            k = maxloc(moves, 1)
            move = moves(k)
            moves(k) = -1.0_wp
            lo = -0.1_wp + (k - 1)*step
            width = step
            do level = 1, levels
               if (.not. (move > 1.0e-6_wp)) exit
               cut_move = 0.0_wp
               at = lo
               last = reference_index(gap, x, lo, 1, n, band)
               do k = 1, cuts
                  here = reference_index(gap, x, lo + k*width/cuts, 1, n, band)
                  if (abs(here - last) > cut_move) then
                     cut_move = abs(here - last)
                     at = lo + (k - 1)*width/cuts
                  end if
                  last = here
               end do
               write (message, '(a,i0,a,es10.3,a,i0,a,es10.3,a)') 'seed ', seed, &
                  ': a step of ', move, ' table points keeps ', nint(100*cut_move/move), &
                  ' % in one tenth at a = ', at, ': a jump'
               call check(error, cut_move <= 0.5_wp*move, trim(message))
               if (allocated(error)) return
               lo = at
               width = width/cuts
               move = cut_move
            end do
         end do
      end do
   end subroutine test_reference_ties

end module test_semihertz
