!> Tests of classical three-flexibility FASTSIM on a Hertz ellipse (doc/theory.md §3).
module test_fastsim
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use testdrive, only: new_unittest, unittest_type, error_type, check
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_tangential_kalker, only: kalker_coefficients
   use shcontact_tangential_options, only: tangential_options_type, bound_ellipsoidal, &
      bound_parabolic, bound_clipped
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_fastsim, only: solve_fastsim
   implicit none
   private
   public :: collect_fastsim

   !> The reference case of doc/theory.md §3.5 (CONTACT examples/fastsim.inp).
   real(wp), parameter :: ref_a = 8.0_wp, ref_b = 4.0_wp, ref_load = 82000.0_wp
   real(wp), parameter :: ref_eta = -6.25e-4_wp, ref_phi = 6.25e-4_wp
   real(wp), parameter :: ref_g = 82000.0_wp

contains

   !> Collect the tests.
   subroutine collect_fastsim(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('linear_theory_forces', test_linear_forces), &
         new_unittest('linear_theory_short_ellipse', test_linear_short), &
         new_unittest('simplified_theory_moment', test_linear_moment), &
         new_unittest('full_slip', test_full_slip), &
         new_unittest('reference_case_200', test_reference_case), &
         new_unittest('convergence_first_order', test_convergence), &
         new_unittest('fields_optional', test_fields_optional), &
         new_unittest('invalid_input', test_invalid_input) &
         ]
   end subroutine collect_fastsim

   function reference_material() result(material)
      type(material_type) :: material
      material = material_type(shear_modulus=ref_g, poisson=0.28_wp, friction=0.3_wp)
   end function reference_material

   !> FASTSIM forces on an ellipse (totals only unless `fields`).
   subroutine fastsim_case(a, b, creepage, bound, n, result, error, fields)
      real(wp), intent(in) :: a, b
      type(creepage_type), intent(in) :: creepage
      integer, intent(in) :: bound, n
      type(tangential_patch_type), intent(inout) :: result
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: fields
      type(march_workspace_type) :: ws
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: lerr

      options%bound = bound
      options%n_elements = n
      options%fields = .false.
      if (present(fields)) options%fields = fields
      call solve_fastsim(ws, a, b, ref_load, reference_material(), creepage, options, n, result, &
         lerr)
      if (allocated(lerr)) call check(error, .false., message='solve_fastsim: '//lerr%message)
   end subroutine fastsim_case

   !> Unsaturated forces equal Kalker's linear theory F_x = −Gc²c₁₁ν_x, F_y = −Gc²c₂₂ν_y − Gc³c₂₃φ
   !> (doc/theory.md §2.1, §3.5): within 0.5 % at 50 × 50 and converging as the grid is refined.
   subroutine test_linear_forces(error)
      type(error_type), allocatable, intent(out) :: error
      call check_linear(error, ref_a, ref_b)
   end subroutine test_linear_forces

   !> The same for an ellipse short in the rolling direction (a/b = 0.5).
   subroutine test_linear_short(error)
      type(error_type), allocatable, intent(out) :: error
      call check_linear(error, 3.0_wp, 6.0_wp)
   end subroutine test_linear_short

   subroutine check_linear(error, a, b)
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in) :: a, b
      type(tangential_patch_type) :: res
      type(creepage_type) :: cr(3)
      real(wp) :: c11, c22, c23, c, g, f_lin(3), err(3, 3), f
      integer :: k, m, n(3)
      character(len=100) :: msg

      g = ref_g
      call kalker_coefficients(a/b, 0.28_wp, c11, c22, c23)
      c = sqrt(a*b)
      ! Creepages small enough that nothing slips (|F| ≪ μN = 24600 N).
      cr(1) = creepage_type(nu_x=1.0e-7_wp)
      cr(2) = creepage_type(nu_y=1.0e-7_wp)
      cr(3) = creepage_type(phi=1.0e-8_wp)
      f_lin = [-g*c**2*c11*1e-7_wp, -g*c**2*c22*1e-7_wp, -g*c**3*c23*1e-8_wp]
      n = [50, 100, 200]
      do m = 1, 3
         do k = 1, 3
            call fastsim_case(a, b, cr(k), bound_parabolic, n(m), res, error)
            if (allocated(error)) return
            call check(error, res%adhesion_fraction, 1.0_wp, message='linear case must not slip')
            if (allocated(error)) return
            f = res%fx
            if (k > 1) f = res%fy
            err(k, m) = abs(f/f_lin(k) - 1)
         end do
      end do
      do k = 1, 3
         write (msg, '(a,i0,a,3es10.2)') 'creepage ', k, ': |F/F_lin - 1| at n = 50/100/200:', &
            err(k, :)
         call check(error, err(k, 1) < 5e-3_wp .and. err(k, 2) < err(k, 1) .and. &
            err(k, 3) < err(k, 2), message=trim(msg))
         if (allocated(error)) return
      end do
   end subroutine check_linear

   !> Unsaturated spin moment about the centre against the simplified theory integrated in
   !> closed form (u = L p, §3.1): M_z = (π/4) a³b ν_y/L₂ − (8/15) a²b³ φ/L₃.
   subroutine test_linear_moment(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      real(wp) :: c11, c22, c23, g, l2, l3, expected
      integer :: k
      type(creepage_type) :: cr

      g = ref_g
      call kalker_coefficients(ref_a/ref_b, 0.28_wp, c11, c22, c23)
      l2 = 8*ref_a/(3*c22*g)
      l3 = pi*ref_a*sqrt(ref_a/ref_b)/(4*c23*g)
      do k = 1, 2
         if (k == 1) then
            cr = creepage_type(nu_y=1.0e-7_wp)
            expected = pi/4*ref_a**3*ref_b*1e-7_wp/l2
         else
            cr = creepage_type(phi=1.0e-8_wp)
            expected = -8.0_wp/15*ref_a**2*ref_b**3*1e-8_wp/l3
         end if
         call fastsim_case(ref_a, ref_b, cr, bound_ellipsoidal, 100, res, error)
         if (allocated(error)) return
         call check(error, res%mz, expected, thr=2e-3_wp, rel=.true., &
            message='unsaturated M_z against the simplified theory')
         if (allocated(error)) return
      end do
   end subroutine test_linear_moment

   !> Full slip: F → μN (|f| → 1) against ν_x for both bounds, f_y = 0, and never past μN (where
   !> the midpoint rule of the pressure overshoots it the Coulomb rule gives exactly μN,
   !> doc/tangential.md "Never past Coulomb").
   subroutine test_full_slip(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      real(wp) :: dev(2)
      integer :: bound, m

      do bound = bound_ellipsoidal, bound_parabolic
         do m = 1, 2
            call fastsim_case(ref_a, ref_b, creepage_type(nu_x=0.5_wp), bound, 50*4**(m - 1), &
               res, error)
            if (allocated(error)) return
            dev(m) = abs(res%fx_norm + 1)
            call check(error, res%fx_norm >= -1 - 1e-12_wp, message='full slip past Coulomb')
            if (allocated(error)) return
            call check(error, abs(res%fy_norm) < 1e-12_wp .and. res%adhesion_fraction < 1e-15_wp, &
               message='full slip in x: f_y = 0, no adhesion')
            if (allocated(error)) return
         end do
         call check(error, dev(1) < 1e-2_wp .and. dev(2) <= max(dev(1)/4, 1e-12_wp), &
            message='full slip: f_x -> -1 (forces oppose the creepage)')
         if (allocated(error)) return
      end do
   end subroutine test_full_slip

   !> doc/theory.md §3.5: f_y = −0.648 (parabolic) and −0.597 (ellipsoidal) at 200 × 200, ±0.005;
   !> f_x = 0 by symmetry (spin about the ellipse centre). Both Kalker schemes (a/b = 2 is a node).
   subroutine test_reference_case(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      type(march_workspace_type) :: ws
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: lerr
      real(wp), parameter :: expected(2) = [-0.597_wp, -0.648_wp]
      !> doc/tangential.md, "Classical FASTSIM": ellipsoidal, parabolic, W1, W2, W3.
      real(wp), parameter :: doc_fy(5) = [-0.5967_wp, -0.6480_wp, -0.5869_wp, -0.6181_wp, &
         -0.6235_wp]
      integer :: bound

      do bound = bound_ellipsoidal, bound_parabolic
         call fastsim_case(ref_a, ref_b, creepage_type(nu_y=ref_eta, phi=ref_phi), bound, 200, &
            res, error)
         if (allocated(error)) return
         call check(error, res%fy_norm, expected(bound), thr=5e-3_wp, message='§3.5 f_y')
         if (allocated(error)) return
         call check(error, abs(res%fx_norm) < 1e-12_wp, message='§3.5 f_x = 0')
         if (allocated(error)) return
      end do
      ! doc/tangential.md's f_y of every bound at 200 × 200, to the 4 decimals it prints.
      do bound = bound_ellipsoidal, bound_clipped
         call fastsim_case(ref_a, ref_b, creepage_type(nu_y=ref_eta, phi=ref_phi), bound, 200, &
            res, error)
         if (allocated(error)) return
         call check(error, res%fy_norm, doc_fy(bound), thr=5.0e-5_wp*(1.0_wp + 1.0e-9_wp), &
            message='doc/tangential.md, "Classical FASTSIM": the reference case''s f_y')
         if (allocated(error)) return
      end do
   end subroutine test_reference_case

   !> First-order convergence of the reference case: each doubling of n roughly halves the change.
   subroutine test_convergence(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      real(wp) :: f(4), d(3)
      integer :: bound, m
      character(len=120) :: msg

      do bound = bound_ellipsoidal, bound_parabolic
         do m = 1, 4
            call fastsim_case(ref_a, ref_b, creepage_type(nu_y=ref_eta, phi=ref_phi), bound, &
               25*2**(m - 1), res, error)
            if (allocated(error)) return
            f(m) = res%fy_norm
         end do
         d = abs(f(2:4) - f(1:3))
         write (msg, '(a,4f10.5)') 'f_y at n = 25, 50, 100, 200:', f
         call check(error, d(2) < 0.7_wp*d(1) .and. d(3) < 0.7_wp*d(2), message=trim(msg))
         if (allocated(error)) return
      end do
   end subroutine test_convergence

   !> fields = .false. gives the same totals and leaves no per-element arrays; fields = .true.
   !> fills them consistently (Σ p ΔA = F, |p| ≤ μ p_n,e for the ellipsoidal bound, states).
   subroutine test_fields_optional(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: on, off
      type(creepage_type) :: cr
      real(wp) :: fx

      cr = creepage_type(nu_x=2e-4_wp, nu_y=ref_eta, phi=ref_phi)
      call fastsim_case(ref_a, ref_b, cr, bound_ellipsoidal, 40, on, error, fields=.true.)
      if (allocated(error)) return
      call fastsim_case(ref_a, ref_b, cr, bound_ellipsoidal, 40, off, error, fields=.false.)
      if (allocated(error)) return
      call check(error, abs(on%fx - off%fx) + abs(on%fy - off%fy) <= 1e-15_wp*ref_load .and. &
         abs(on%mz - off%mz) <= 1e-15_wp*ref_load*ref_a, &
         message='totals depend on the fields option')
      if (allocated(error)) return
      call check(error, .not. allocated(off%px) .and. allocated(on%px), message='fields option')
      if (allocated(error)) return
      fx = sum(on%px*spread(on%dx, 1, on%nx))*on%dy
      call check(error, fx, on%fx, thr=1e-12_wp, rel=.true., message='sum of p_x dA = F_x')
      if (allocated(error)) return
      call check(error, all(hypot(on%px, on%py) <= 0.3_wp*on%pn*(1 + 1e-12_wp)), &
         message='ellipsoidal bound exceeded')
      if (allocated(error)) return
      call check(error, any(on%state == 1) .and. any(on%state == 2) .and. &
         all((on%slip > 0) .eqv. (on%state == 2)), message='stick/slip states and slip field')
   end subroutine test_fields_optional

   !> Bad inputs give error values naming the item.
   subroutine test_invalid_input(error)
      type(error_type), allocatable, intent(out) :: error
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: res
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: lerr
      real(wp) :: nan

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      call solve_fastsim(ws, 0.0_wp, ref_b, ref_load, reference_material(), creepage_type(), &
         options, 10, res, lerr)
      call check(error, allocated(lerr), message='a = 0 accepted')
      if (allocated(error)) return
      call check(error, index(lerr%message, 'semi-axis a') > 0, message=lerr%message)
      if (allocated(error)) return
      call solve_fastsim(ws, ref_a, nan, ref_load, reference_material(), creepage_type(), &
         options, 10, res, lerr)
      call check(error, allocated(lerr), message='b = NaN accepted')
      if (allocated(error)) return
      call solve_fastsim(ws, ref_a, ref_b, ref_load, reference_material(), creepage_type(), &
         options, 0, res, lerr)
      call check(error, allocated(lerr), message='n_strips = 0 accepted')
      if (allocated(error)) return
      call solve_fastsim(ws, ref_a, ref_b, ref_load, reference_material(), &
         creepage_type(nu_x=nan), options, 10, res, lerr)
      call check(error, allocated(lerr), message='NaN creepage accepted')
      if (allocated(error)) return
      options%n_elements = 0
      call solve_fastsim(ws, ref_a, ref_b, ref_load, reference_material(), creepage_type(), &
         options, 10, res, lerr)
      call check(error, allocated(lerr), message='n_elements = 0 accepted')
      if (allocated(error)) return
      options%n_elements = 10
      call solve_fastsim(ws, ref_a, ref_b, ref_load, material_type(friction=0.0_wp), &
         creepage_type(), options, 10, res, lerr)
      call check(error, allocated(lerr), message='mu = 0 accepted')
   end subroutine test_invalid_input

end module test_fastsim
