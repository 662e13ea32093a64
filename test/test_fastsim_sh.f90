!> Tests of FASTSIM_SH (doc/theory.md §6), its options, spin models and the multi-patch solver.
module test_fastsim_sh
   use, intrinsic :: iso_c_binding, only: c_loc, c_intptr_t
   use testdrive, only: new_unittest, unittest_type, error_type, check
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_kalker, only: kalker_coefficients
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options, &
      method_fastsim, method_fastsim_sh, bound_ellipsoidal, bound_parabolic, bound_weighted, &
      bound_weighted_slip, bound_clipped, spin_additive, spin_uniform, spin_scaled, &
      spin_geometric, spin_flexibility_longitudinal, spin_flexibility_spin, parse_method, parse_bound, &
      parse_spin_model, parse_spin_flexibility, bound_name, method_name, spin_model_name
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim, only: solve_fastsim
   use shcontact_tangential_fastsim_sh, only: solve_fastsim_sh, prepare_fastsim_sh
   use shcontact_tangential_solver, only: solve_tangential, solve_tangential_patches, &
      track_forces_type
   implicit none
   private
   public :: collect_fastsim_sh

   !> The Hertz case of doc/theory.md §3.5.
   real(wp), parameter :: ref_a = 8.0_wp, ref_b = 4.0_wp, ref_load = 82000.0_wp
   real(wp), parameter :: ref_g = 82000.0_wp, ref_nu = 0.28_wp, ref_mu = 0.3_wp
   real(wp), parameter :: ref_eta = -6.25e-4_wp, ref_phi = 6.25e-4_wp
   !> Rolling radius at the reference point (mm).
   real(wp), parameter :: ref_r0 = 460.0_wp

contains

   !> Collect the tests.
   subroutine collect_fastsim_sh(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('hertzian_patch_equals_fastsim', test_equals_fastsim), &
         new_unittest('linear_limit', test_linear_limit), &
         new_unittest('w1_small_creepage_factor', test_w1_factor), &
         new_unittest('w1_spin_total_unchanged', test_w1_spin), &
         new_unittest('coulomb_check', test_coulomb), &
         new_unittest('full_slip', test_full_slip), &
         new_unittest('parabolic_load_ratio', test_parabolic_ratio), &
         new_unittest('mirror_symmetry', test_mirror), &
         new_unittest('convergence_nx', test_convergence_nx), &
         new_unittest('convergence_ny', test_convergence_ny), &
         new_unittest('spin_model_identities', test_spin_models), &
         new_unittest('scaled_spin_singular', test_scaled_singular), &
         new_unittest('spin_flexibility_longitudinal', test_spin_flexibility), &
         new_unittest('option_parsing', test_options), &
         new_unittest('dispatch_and_patches', test_patches), &
         new_unittest('no_reallocation', test_no_reallocation), &
         new_unittest('invalid_patch', test_invalid_patch) &
         ]
   end subroutine collect_fastsim_sh

   pure function material() result(mat)
      type(material_type) :: mat
      mat = material_type(shear_modulus=ref_g, poisson=ref_nu, friction=ref_mu)
   end function material

   !> The strip table of a Hertz ellipse (semi-axes a, b, normal force `load` of the continuous
   !> ellipse): k_i = √(1 − y_i²/b²), a_i = a k_i, p₀,ᵢ = p₀ k_i, N_i = (π/2) p₀,ᵢ a_i dy,
   !> m/n = a/b, γ_i = γ₀, δr_i = y_i sin γ₀ (a linear rolling-radius profile).
   function hertz_patch(a, b, load, ny, gamma0) result(patch)
      real(wp), intent(in) :: a, b, load, gamma0
      integer, intent(in) :: ny
      type(normal_patch_type) :: patch
      real(wp) :: p0, dy
      integer :: i

      p0 = 3*load/(2*pi*a*b)
      dy = 2*b/ny
      call allocate_patch(patch, ny)
      patch%is_hertz = .true.
      patch%ellipse_a = a
      patch%ellipse_b = b
      patch%dy = dy
      patch%gamma0 = gamma0
      patch%r0 = ref_r0
      do i = 1, ny
         patch%y(i) = -b + (i - 0.5_wp)*dy
         patch%k(i) = sqrt(1 - (patch%y(i)/b)**2)
      end do
      patch%a = a*patch%k
      patch%p0 = p0*patch%k
      patch%strip_load = pi/2*patch%p0*patch%a*dy
      patch%m = a/sqrt(a*b)
      patch%n = b/sqrt(a*b)
      patch%gamma = gamma0
      patch%delta_r = patch%y*sin(gamma0)
      patch%r_wheel = ref_r0 + patch%delta_r
      call finish_patch(patch)
   end function hertz_patch

   !> A smooth non-Hertzian patch on |y| < 5 mm (u = y/5), discretised with ny strips: skewed
   !> half-lengths, k_i up to about 0.95, a/b of the local ellipses from 1.5 to 2.5, a curved
   !> contact angle and rolling radius, and one unloaded strip at the end.
   function skew_patch(ny) result(patch)
      integer, intent(in) :: ny
      type(normal_patch_type) :: patch
      real(wp), parameter :: half = 5.0_wp, gamma0 = -0.1_wp, p_ref = 1100.0_wp
      real(wp) :: u, dy
      integer :: i

      dy = 2*half/ny
      call allocate_patch(patch, ny)
      patch%dy = dy
      patch%gamma0 = gamma0
      patch%r0 = ref_r0
      do i = 1, ny
         patch%y(i) = -half + (i - 0.5_wp)*dy
         u = patch%y(i)/half
         patch%k(i) = 0.95_wp*sqrt(1 - u**2)*(1 + 0.2_wp*u)/1.2_wp*1.1_wp
         patch%a(i) = 6.0_wp*sqrt(1 - u**2)*(1 + 0.25_wp*u)
         patch%m(i) = 2.0_wp + 0.5_wp*u
         patch%n(i) = 1.0_wp
         patch%gamma(i) = gamma0 + 0.05_wp*u + 0.03_wp*u**2
         patch%delta_r(i) = patch%y(i)*sin(gamma0) + 0.002_wp*patch%y(i)**2 + &
            1e-4_wp*patch%y(i)**3
      end do
      patch%a(ny) = 0.0_wp
      patch%k(ny) = 0.0_wp
      patch%p0 = p_ref*patch%k
      patch%strip_load = pi/2*patch%p0*patch%a*dy
      patch%r_wheel = ref_r0 + patch%delta_r
      call finish_patch(patch)
   end function skew_patch

   !> The patch seen in a mirror y → −y: arrays reversed, γ → −γ, δr kept.
   function mirrored(patch) result(mirror)
      type(normal_patch_type), intent(in) :: patch
      type(normal_patch_type) :: mirror
      integer :: n

      n = patch%n_strips
      mirror = patch
      mirror%y = -patch%y(n:1:-1)
      mirror%a = patch%a(n:1:-1)
      mirror%k = patch%k(n:1:-1)
      mirror%p0 = patch%p0(n:1:-1)
      mirror%strip_load = patch%strip_load(n:1:-1)
      mirror%m = patch%m(n:1:-1)
      mirror%n = patch%n(n:1:-1)
      mirror%gamma = -patch%gamma(n:1:-1)
      mirror%delta_r = patch%delta_r(n:1:-1)
      mirror%r_wheel = patch%r_wheel(n:1:-1)
      mirror%gamma0 = -patch%gamma0
   end function mirrored

   subroutine allocate_patch(patch, ny)
      type(normal_patch_type), intent(inout) :: patch
      integer, intent(in) :: ny
      patch%n_strips = ny
      allocate (patch%y(ny), patch%a(ny), patch%k(ny), patch%p0(ny), patch%strip_load(ny), &
         patch%m(ny), patch%n(ny), patch%eps_a(ny), patch%gamma(ny), patch%delta_r(ny), &
         patch%r_wheel(ny))
      patch%eps_a = 0.5_wp
   end subroutine allocate_patch

   subroutine finish_patch(patch)
      type(normal_patch_type), intent(inout) :: patch
      patch%load = sum(patch%strip_load)
      patch%area = sum(2*patch%a*patch%dy)
      patch%p_max = maxval(patch%p0)
   end subroutine finish_patch

   !> FASTSIM_SH on a patch; the test fails on a library error.
   subroutine sh_case(patch, creepage, options, result, error)
      type(normal_patch_type), intent(in) :: patch
      type(creepage_type), intent(in) :: creepage
      type(tangential_options_type), intent(in) :: options
      type(tangential_patch_type), intent(inout) :: result
      type(error_type), allocatable, intent(out) :: error
      type(march_workspace_type) :: ws
      type(lib_error), allocatable :: lerr

      call solve_fastsim_sh(ws, patch, material(), creepage, options, result, lerr)
      if (allocated(lerr)) call check(error, .false., message='solve_fastsim_sh: '//lerr%message)
   end subroutine sh_case

   function options_with(bound, nx, spin_model, fields) result(options)
      integer, intent(in) :: bound, nx
      integer, intent(in), optional :: spin_model
      logical, intent(in), optional :: fields
      type(tangential_options_type) :: options
      options%bound = bound
      options%n_elements = nx
      ! Kalker's spin flexibility for the −φy slip: the setting under which FASTSIM_SH equals
      ! FASTSIM on a Hertzian patch (the library default follows seed eq 21 instead).
      options%spin_flexibility = spin_flexibility_spin
      options%spin_model = spin_additive
      if (present(spin_model)) options%spin_model = spin_model
      options%fields = .false.
      if (present(fields)) options%fields = fields
   end function options_with

   !> On a Hertzian patch (quadratic gap, constant γ, linear δr) FASTSIM_SH equals classical
   !> FASTSIM at the same n_x × n_y to round-off, for every bound, with the additive and uniform
   !> spin models at any φ and the scaled and geometric ones at φ = φ_geo,0 (doc/theory.md §6.2–6.3).
   subroutine test_equals_fastsim(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: nx = 30, ny = 24
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: sh, fs
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(lib_error), allocatable :: lerr
      type(creepage_type) :: cr
      real(wp) :: gamma0, scale
      integer :: bound, model
      character(len=80) :: msg

      ! γ₀ such that φ_geo,0 = sin γ₀/r₀ equals the reference spin.
      gamma0 = asin(ref_phi*ref_r0)
      patch = hertz_patch(ref_a, ref_b, ref_load, ny, gamma0)
      cr = creepage_type(nu_x=2.0e-4_wp, nu_y=ref_eta, phi=ref_phi)
      scale = ref_mu*ref_load
      do bound = bound_ellipsoidal, bound_clipped
         options = options_with(bound, nx, fields=.true.)
         call solve_fastsim(ws, ref_a, ref_b, ref_load, material(), cr, options, ny, fs, lerr)
         call check(error, .not. allocated(lerr), message='solve_fastsim failed')
         if (allocated(error)) return
         do model = spin_additive, spin_geometric
            options%spin_model = model
            call sh_case(patch, cr, options, sh, error)
            if (allocated(error)) return
            write (msg, '(a,a,a,a)') 'FASTSIM_SH /= FASTSIM, bound ', bound_name(bound), &
               ', spin model ', spin_model_name(model)
            call check(error, abs(sh%fx - fs%fx) < 1e-12_wp*scale .and. &
               abs(sh%fy - fs%fy) < 1e-12_wp*scale .and. &
               abs(sh%mz - fs%mz) < 1e-12_wp*scale*ref_a, message=trim(msg)//' (totals)')
            if (allocated(error)) return
            call check(error, maxval(abs(sh%px - fs%px)) < 1e-10_wp .and. &
               maxval(abs(sh%py - fs%py)) < 1e-10_wp .and. all(sh%state == fs%state) .and. &
               maxval(abs(sh%slip - fs%slip)) < 1e-14_wp, message=trim(msg)//' (fields)')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_equals_fastsim

   !> Unsaturated FASTSIM_SH on a Hertzian patch gives Kalker's linear forces (doc/theory.md §6.5
   !> test 2) for the bounds that keep the slope (all but W1), within 0.5 % at 50 × 50.
   subroutine test_linear_limit(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      type(creepage_type) :: cr(3)
      real(wp) :: c11, c22, c23, c, f_lin(3), f
      integer :: k, bound

      call kalker_coefficients(ref_a/ref_b, ref_nu, c11, c22, c23)
      c = sqrt(ref_a*ref_b)
      cr(1) = creepage_type(nu_x=1.0e-7_wp)
      cr(2) = creepage_type(nu_y=1.0e-7_wp)
      cr(3) = creepage_type(phi=1.0e-8_wp)
      f_lin = [-ref_g*c**2*c11*1e-7_wp, -ref_g*c**2*c22*1e-7_wp, -ref_g*c**3*c23*1e-8_wp]
      do bound = bound_ellipsoidal, bound_clipped
         if (bound == bound_weighted) cycle
         do k = 1, 3
            call sh_case(hertz_patch(ref_a, ref_b, ref_load, 50, -0.03_wp), cr(k), &
               options_with(bound, 50), res, error)
            if (allocated(error)) return
            f = res%fx
            if (k > 1) f = res%fy
            call check(error, f, f_lin(k), thr=5e-3_wp, rel=.true., &
               message='linear limit, bound '//bound_name(bound))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_linear_limit

   !> W1 raises the small-creepage ν_x and ν_y slopes by 9π²/64 on an ellipse (doc/theory.md §6.4):
   !> at a/b = 2, n_y = 50 the factor is 1.314 (n_x = 50), 1.351 (200), 1.370 (800); the error
   !> decays like n_x^{-1/2}, so 2 f(800) − f(200) extrapolates to 9π²/64.
   subroutine test_w1_factor(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: expected(3) = [1.314_wp, 1.351_wp, 1.370_wp]
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: res
      real(wp) :: c11, c22, c23, c, fx(3), fy(3)
      integer :: m
      character(len=100) :: msg

      call kalker_coefficients(ref_a/ref_b, ref_nu, c11, c22, c23)
      c = sqrt(ref_a*ref_b)
      patch = hertz_patch(ref_a, ref_b, ref_load, 50, 0.0_wp)
      do m = 1, 3
         call sh_case(patch, creepage_type(nu_x=1e-7_wp), options_with(bound_weighted, &
            50*4**(m - 1)), res, error)
         if (allocated(error)) return
         fx(m) = res%fx/(-ref_g*c**2*c11*1e-7_wp)
         call sh_case(patch, creepage_type(nu_y=1e-7_wp), options_with(bound_weighted, &
            50*4**(m - 1)), res, error)
         if (allocated(error)) return
         fy(m) = res%fy/(-ref_g*c**2*c22*1e-7_wp)
      end do
      write (msg, '(a,3f8.4)') 'W1 factor at n_x = 50, 200, 800:', fx
      call check(error, all(abs(fx - expected) < 1.5e-3_wp), message=trim(msg))
      if (allocated(error)) return
      call check(error, all(abs(fy - fx) < 1e-12_wp), message='W1 factor differs for nu_y')
      if (allocated(error)) return
      call check(error, 2*fx(3) - fx(2), 9*pi**2/64, thr=3e-3_wp, &
         message='W1 factor extrapolated to 9 pi^2/64')
   end subroutine test_w1_factor

   !> The W1 weighting changes the spin force strip by strip (factor 9π/(32 k_i)) but not its
   !> total on an ellipse (doc/theory.md §6.4): F_y(W1)/F_y(parabolic) → 1 for pure spin.
   subroutine test_w1_spin(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: w1, par
      real(wp) :: ratio(2)
      integer :: m
      character(len=80) :: msg

      patch = hertz_patch(ref_a, ref_b, ref_load, 50, 0.0_wp)
      do m = 1, 2
         call sh_case(patch, creepage_type(phi=1e-8_wp), options_with(bound_weighted, &
            100*8**(m - 1)), w1, error)
         if (allocated(error)) return
         call sh_case(patch, creepage_type(phi=1e-8_wp), options_with(bound_parabolic, &
            100*8**(m - 1)), par, error)
         if (allocated(error)) return
         ratio(m) = w1%fy/par%fy
      end do
      write (msg, '(a,2f9.5)') 'W1/parabolic spin force at n_x = 100, 800:', ratio
      call check(error, abs(ratio(2) - 1) < 1e-3_wp .and. abs(ratio(2) - 1) < abs(ratio(1) - 1), &
         message=trim(msg))
   end subroutine test_w1_spin

   !> max|p|/(μ p_n,e) ≤ 1 for ellipsoidal, W1, W2, W3 on a non-Hertzian patch in partial slip;
   !> = 1 for the ellipsoidal bound (some element slips); > 1 for the pure parabolic bound, whose
   !> peak exceeds the semi-elliptic pressure where k_i > 3/4 (doc/theory.md §6.4).
   subroutine test_coulomb(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      type(creepage_type) :: cr
      integer :: bound
      character(len=120) :: msg

      cr = creepage_type(nu_x=2.5e-3_wp, nu_y=-3e-3_wp, phi=3e-4_wp)
      do bound = bound_ellipsoidal, bound_clipped
         call sh_case(skew_patch(40), cr, options_with(bound, 40, fields=.true.), res, error)
         if (allocated(error)) return
         call check(error, res%adhesion_fraction > 0.05_wp .and. res%adhesion_fraction < 0.95_wp, &
            message='Coulomb test case must be in partial slip')
         if (allocated(error)) return
         call check(error, res%coulomb_ratio, field_coulomb_ratio(res), thr=1e-12_wp, &
            rel=.true., message='Coulomb ratio differs from the fields')
         if (allocated(error)) return
         if (bound == bound_parabolic) then
            write (msg, '(a,2f8.4)') 'parabolic bound: expected tractions above mu p_n,e; '// &
               'ratio, adhesion fraction', res%coulomb_ratio, res%adhesion_fraction
            call check(error, res%coulomb_ratio > 1.1_wp, message=trim(msg))
         else
            call check(error, res%coulomb_ratio <= 1 + 1e-12_wp, &
               message='Coulomb check > 1 for bound '//bound_name(bound))
         end if
         if (allocated(error)) return
      end do
   end subroutine test_coulomb

   !> max |p|/(μ p_n,e) over the contact elements of the fields (exterior ones have p_n,e = 0).
   pure real(wp) function field_coulomb_ratio(res) result(ratio)
      type(tangential_patch_type), intent(in) :: res
      integer :: i, j
      ratio = 0
      do i = 1, res%ny
         do j = 1, res%nx
            if (res%state(j, i) == 0) cycle
            ratio = max(ratio, hypot(res%px(j, i), res%py(j, i))/(ref_mu*res%pn(j, i)))
         end do
      end do
   end function field_coulomb_ratio

   !> Full slip: |F| = μF_n for ellipsoidal, W1 and W2 (they coincide in full slip; the midpoint
   !> rule's excess of Σ p_n,e over F_n, 1.0009 at n_x = 50, is projected away by the Coulomb rule,
   !> doc/tangential.md "Never past Coulomb"), μF_n × the parabolic load ratio for the pure
   !> parabolic bound (doc/theory.md §6.5 test 3) but never more than μF_n. W3 (clip) gives
   !> μ∬min(p_n,p, p_n,e) < μF_n, contrary to §6.5 test 3 (see doc/tangential.md).
   subroutine test_full_slip(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: res, ell
      real(wp) :: dev(2), f
      integer :: bound, m
      character(len=80) :: msg

      do m = 1, 2
         patch = skew_patch(50*4**(m - 1))
         ! Uniform spin model, no spin: every increment is along x, so the directions agree.
         call sh_case(patch, creepage_type(nu_x=0.5_wp), options_with(bound_ellipsoidal, &
            50*4**(m - 1), spin_uniform), ell, error)
         if (allocated(error)) return
         dev(m) = abs(hypot(ell%fx_norm, ell%fy_norm) - 1)
         do bound = bound_parabolic, bound_clipped
            call sh_case(patch, creepage_type(nu_x=0.5_wp), options_with(bound, 50*4**(m - 1), &
               spin_uniform), res, error)
            if (allocated(error)) return
            f = hypot(res%fx_norm, res%fy_norm)
            call check(error, res%adhesion_fraction < 1e-15_wp, message='expected full slip')
            if (allocated(error)) return
            if (bound == bound_parabolic) then
               call check(error, f, min(1.0_wp, res%parabolic_load_ratio), thr=2e-3_wp, &
                  rel=.true., message='parabolic full slip')
               if (allocated(error)) return
               call check(error, f <= 1.0_wp + 1e-12_wp, message='parabolic full slip past '// &
                  'Coulomb')
            else if (bound == bound_clipped) then
               ! W3 keeps min(p_n,p, p_n,e) in full slip, which carries less than F_n.
               call check(error, f < 0.95_wp*hypot(ell%fx_norm, ell%fy_norm), &
                  message='clipped bound in full slip: expected less than mu F_n')
            else
               call check(error, f, hypot(ell%fx_norm, ell%fy_norm), thr=1e-12_wp, rel=.true., &
                  message='full slip differs from the ellipsoidal bound: '//bound_name(bound))
            end if
            if (allocated(error)) return
         end do
      end do
      write (msg, '(a,2es10.2)') 'full slip: ||f| - 1| at n = 50, 200:', dev
      call check(error, dev(1) < 1e-12_wp .and. dev(2) < 1e-12_wp, message=trim(msg))
   end subroutine test_full_slip

   !> (32/(9π)) Σ k_i N_i / N → 1 on a Hertzian strip table (Σk³/Σk² → 9π/32, §6.4).
   subroutine test_parabolic_ratio(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      real(wp) :: dev(2)
      integer :: m
      character(len=80) :: msg

      do m = 1, 2
         call sh_case(hertz_patch(ref_a, ref_b, ref_load, 25*4**(m - 1), 0.0_wp), &
            creepage_type(), options_with(bound_parabolic, 10), res, error)
         if (allocated(error)) return
         dev(m) = abs(res%parabolic_load_ratio - 1)
      end do
      write (msg, '(a,2es10.2)') 'parabolic load ratio - 1 at n_y = 25, 100:', dev
      call check(error, dev(1) < 2e-3_wp .and. dev(2) < dev(1)/4, message=trim(msg))
   end subroutine test_parabolic_ratio

   !> Mirror symmetry (ν_y, φ, y) → (−ν_y, −φ, −y) with the mirrored geometry (γ → −γ): F_x and
   !> the p_x field keep their values, F_y, M_z and p_y change sign (doc/theory.md §6.5 test 4), for
   !> every spin model and bound.
   subroutine test_mirror(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: ny = 31
      type(normal_patch_type) :: patch, mirror
      type(tangential_patch_type) :: r1, r2
      type(creepage_type) :: cr
      real(wp) :: scale
      integer :: bound, model
      character(len=80) :: msg

      patch = skew_patch(ny)
      mirror = mirrored(patch)
      cr = creepage_type(nu_x=1e-4_wp, nu_y=ref_eta, phi=ref_phi)
      scale = ref_mu*patch%load
      do bound = bound_ellipsoidal, bound_clipped
         do model = spin_additive, spin_geometric
            call sh_case(patch, cr, options_with(bound, 20, model, .true.), r1, error)
            if (allocated(error)) return
            call sh_case(mirror, creepage_type(cr%nu_x, -cr%nu_y, -cr%phi), &
               options_with(bound, 20, model, .true.), r2, error)
            if (allocated(error)) return
            write (msg, '(a,a,a,a)') 'mirror symmetry, bound ', bound_name(bound), ', model ', &
               spin_model_name(model)
            call check(error, abs(r1%fx - r2%fx) < 1e-12_wp*scale .and. &
               abs(r1%fy + r2%fy) < 1e-12_wp*scale .and. &
               abs(r1%mz + r2%mz) < 1e-12_wp*scale*5 .and. abs(r1%fy) > 1e-3_wp*scale, &
               message=trim(msg))
            if (allocated(error)) return
            call check(error, maxval(abs(r1%px - r2%px(:, ny:1:-1))) < 1e-9_wp .and. &
               maxval(abs(r1%py + r2%py(:, ny:1:-1))) < 1e-9_wp .and. &
               all(r1%state == r2%state(:, ny:1:-1)), message=trim(msg)//' (fields)')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_mirror

   !> Convergence in n_x on a non-Hertzian patch: successive changes of f shrink as n_x doubles
   !> (first order for the ellipsoidal bound, about n_x^{-1/2} for W1).
   subroutine test_convergence_nx(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: res
      real(wp) :: f(4, 2), d(3, 2)
      integer :: m, ib, bounds(2)
      character(len=120) :: msg

      patch = skew_patch(50)
      bounds = [bound_ellipsoidal, bound_weighted]
      do ib = 1, 2
         do m = 1, 4
            call sh_case(patch, creepage_type(1e-4_wp, ref_eta, ref_phi), &
               options_with(bounds(ib), 25*2**(m - 1)), res, error)
            if (allocated(error)) return
            f(m, :) = [res%fx_norm, res%fy_norm]
         end do
         d = abs(f(2:4, :) - f(1:3, :))
         write (msg, '(a,a,a,4f9.5)') 'f_y(n_x = 25..200), ', bound_name(bounds(ib)), ':', f(:, 2)
         call check(error, all(d(2, :) < 0.8_wp*d(1, :)) .and. all(d(3, :) < 0.8_wp*d(2, :)), &
            message=trim(msg))
         if (allocated(error)) return
      end do
   end subroutine test_convergence_nx

   !> Convergence in n_y: the same continuous patch cut into 25…200 strips.
   subroutine test_convergence_ny(error)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type) :: res
      real(wp) :: f(4, 2), d(3, 2)
      integer :: m
      character(len=120) :: msg

      do m = 1, 4
         call sh_case(skew_patch(25*2**(m - 1)), creepage_type(1e-4_wp, ref_eta, ref_phi), &
            options_with(bound_ellipsoidal, 50), res, error)
         if (allocated(error)) return
         f(m, :) = [res%fx_norm, res%fy_norm]
      end do
      d = abs(f(2:4, :) - f(1:3, :))
      write (msg, '(a,4f9.5)') 'f_y(n_y = 25..200):', f(:, 2)
      call check(error, all(d(2, :) < 0.8_wp*d(1, :)) .and. all(d(3, :) < 0.8_wp*d(2, :)) .and. &
         all(d(3, :) < 2e-3_wp), message=trim(msg))
   end subroutine test_convergence_ny

   !> doc/theory.md §6.2 on a curved patch: additive and scaled equal geometric when φ = φ_geo,0;
   !> with φ = 0, the uniform model has no spin at all (F_y = 0 against ν_x alone) while the
   !> additive one keeps the geometric spin variation (F_y ≠ 0).
   subroutine test_spin_models(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: geo, res
      type(creepage_type) :: cr
      real(wp) :: phi_geo0, scale
      integer :: model

      patch = skew_patch(40)
      phi_geo0 = sin(patch%gamma0)/patch%r0
      scale = ref_mu*patch%load
      cr = creepage_type(nu_x=1e-4_wp, nu_y=-2e-4_wp, phi=phi_geo0)
      call sh_case(patch, cr, options_with(bound_ellipsoidal, 30, spin_geometric), geo, error)
      if (allocated(error)) return
      do model = spin_additive, spin_scaled
         if (model == spin_uniform) cycle
         call sh_case(patch, cr, options_with(bound_ellipsoidal, 30, model), res, error)
         if (allocated(error)) return
         call check(error, abs(res%fx - geo%fx) < 1e-12_wp*scale .and. &
            abs(res%fy - geo%fy) < 1e-12_wp*scale, &
            message=spin_model_name(model)//' /= geometric at phi = phi_geo,0')
         if (allocated(error)) return
      end do
      ! The geometric model ignores the input spin.
      call sh_case(patch, creepage_type(nu_x=1e-4_wp, nu_y=-2e-4_wp, phi=5e-3_wp), &
         options_with(bound_ellipsoidal, 30, spin_geometric), res, error)
      if (allocated(error)) return
      call check(error, abs(res%fx - geo%fx) + abs(res%fy - geo%fy) < 1e-15_wp*scale, &
         message='geometric model depends on the input spin')
      if (allocated(error)) return
      call sh_case(patch, creepage_type(nu_x=1e-4_wp), options_with(bound_ellipsoidal, 30, &
         spin_uniform), res, error)
      if (allocated(error)) return
      call check(error, abs(res%fy) < 1e-14_wp*scale, message='uniform model: F_y from nu_x')
      if (allocated(error)) return
      call sh_case(patch, creepage_type(nu_x=1e-4_wp), options_with(bound_ellipsoidal, 30, &
         spin_additive), res, error)
      if (allocated(error)) return
      call check(error, abs(res%fy) > 1e-4_wp*scale, &
         message='additive model lost the geometric spin variation')
   end subroutine test_spin_models

   !> The scaled model is singular without geometric spin at the reference point: a clear error.
   subroutine test_scaled_singular(error)
      type(error_type), allocatable, intent(out) :: error
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: res
      type(lib_error), allocatable :: lerr

      call solve_fastsim_sh(ws, hertz_patch(ref_a, ref_b, ref_load, 20, 0.0_wp), material(), &
         creepage_type(phi=ref_phi), options_with(bound_weighted, 20, spin_scaled), res, lerr)
      call check(error, allocated(lerr), message='scaled spin model accepted gamma0 = 0')
      if (allocated(error)) return
      call check(error, index(lerr%message, 'scaled') > 0 .and. index(lerr%message, 'additive') &
         > 0, message=lerr%message)
   end subroutine test_scaled_singular

   !> spin_flexibility = 'longitudinal' (seed eq 21 literally) builds the spin part of the
   !> longitudinal slip with L_x = L₁ instead of L₃: in the linear regime only the moment of p_x
   !> changes, so for pure spin M_z scales by L₃/L₁ while F_y is unchanged.
   subroutine test_spin_flexibility(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_patch_type) :: spin, longit
      type(tangential_options_type) :: options
      real(wp) :: c11, c22, c23, l1, l3

      call kalker_coefficients(ref_a/ref_b, ref_nu, c11, c22, c23)
      l1 = 8*ref_a/(3*c11*ref_g)
      l3 = pi*ref_a*sqrt(ref_a/ref_b)/(4*c23*ref_g)
      patch = hertz_patch(ref_a, ref_b, ref_load, 40, 0.0_wp)
      options = options_with(bound_ellipsoidal, 40)
      call sh_case(patch, creepage_type(phi=1e-8_wp), options, spin, error)
      if (allocated(error)) return
      options%spin_flexibility = spin_flexibility_longitudinal
      call sh_case(patch, creepage_type(phi=1e-8_wp), options, longit, error)
      if (allocated(error)) return
      call check(error, longit%fy, spin%fy, thr=1e-12_wp, rel=.true., message='F_y changed')
      if (allocated(error)) return
      call check(error, longit%mz/spin%mz, l3/l1, thr=1e-10_wp, rel=.true., &
         message='M_z ratio of the longitudinal and spin flexibilities')
   end subroutine test_spin_flexibility

   !> String options: every name, case and '_'/'-' variants, round trip, clear errors.
   subroutine test_options(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: lerr
      type(tangential_options_type) :: options
      integer :: code

      call parse_bound(' Weighted_Slip ', code, lerr)
      call check(error, .not. allocated(lerr) .and. code == bound_weighted_slip, &
         message='weighted_slip')
      if (allocated(error)) return
      do code = bound_ellipsoidal, bound_clipped
         block
            integer :: back
            call parse_bound(bound_name(code), back, lerr)
            call check(error, back == code, message='bound name round trip')
            if (allocated(error)) return
         end block
      end do
      call parse_method('FASTSIM-SH', code, lerr)
      call check(error, code == method_fastsim_sh .and. method_name(code) == 'fastsim-sh', &
         message='method fastsim-sh')
      if (allocated(error)) return
      call parse_method('fastsim', code, lerr)
      call check(error, code == method_fastsim, message='method fastsim')
      if (allocated(error)) return
      call parse_spin_model('geometric', code, lerr)
      call check(error, code == spin_geometric, message='spin model geometric')
      if (allocated(error)) return
      call parse_spin_flexibility('longitudinal', code, lerr)
      call check(error, code == spin_flexibility_longitudinal, message='spin flexibility')
      if (allocated(error)) return
      call parse_bound('elliptic', code, lerr)
      call check(error, allocated(lerr), message="bound 'elliptic' accepted")
      if (allocated(error)) return
      call check(error, index(lerr%message, "'elliptic'") > 0 .and. &
         index(lerr%message, "'weighted-slip'") > 0 .and. index(lerr%message, 'bound') > 0, &
         message=lerr%message)
      if (allocated(error)) return
      options%spin_model = 7
      call check_tangential_options(options, lerr)
      call check(error, allocated(lerr), message='spin_model code 7 accepted')
   end subroutine test_options

   !> Dispatch by method and several patches: method 'fastsim' needs a Hertz ellipse and then
   !> equals solve_fastsim; totals are the track-frame sums; the rotation keeps |(F_y, F_n)|; a
   !> flange contact (γ = −1.2) pushes the right wheel to the track centre and up.
   subroutine test_patches(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patches(2)
      type(creepage_type) :: creepages(2)
      type(tangential_patch_type) :: results(2), direct, wrong(1)
      type(tangential_options_type) :: options
      type(track_forces_type) :: track
      type(march_workspace_type) :: ws
      type(lib_error), allocatable :: lerr
      integer :: k

      patches(1) = hertz_patch(ref_a, ref_b, ref_load, 30, 0.0_wp)
      patches(1)%ellipse_y_centre = 0.5_wp
      patches(2) = hertz_patch(3.0_wp, 1.5_wp, 20000.0_wp, 20, -1.2_wp)
      creepages(1) = creepage_type(nu_x=1e-4_wp, nu_y=-2e-4_wp, phi=1e-4_wp)
      creepages(2) = creepage_type()
      options%n_elements = 30
      options%method = method_fastsim
      call solve_tangential_patches(ws, patches, material(), creepages, options, results, track, &
         lerr)
      call check(error, .not. allocated(lerr), message='solve_tangential_patches failed')
      if (allocated(error)) return
      call solve_fastsim(ws, ref_a, ref_b, patches(1)%load, material(), creepages(1), options, &
         30, direct, lerr, y_centre=0.5_wp)
      call check(error, abs(results(1)%fy - direct%fy) < 1e-15_wp*ref_load .and. &
         abs(results(1)%mz - direct%mz) < 1e-15_wp*ref_load*ref_a, &
         message="method 'fastsim' differs from solve_fastsim")
      if (allocated(error)) return
      call check(error, track%fx, sum(results%fx), thr=1e-12_wp, rel=.true.)
      if (allocated(error)) return
      call check(error, abs(track%fy - sum(results%fy_track)) < 1e-9_wp .and. &
         abs(track%fz - sum(results%fz_track)) < 1e-9_wp .and. &
         abs(track%fn - sum(results%fn)) < 1e-9_wp, message='track totals')
      if (allocated(error)) return
      do k = 1, 2
         call check(error, hypot(results(k)%fy_track, results(k)%fz_track), &
            hypot(results(k)%fy, results(k)%fn), thr=1e-12_wp, rel=.true., &
            message='rotation changes the force magnitude')
         if (allocated(error)) return
      end do
      call check(error, results(2)%fy_track < -0.9_wp*results(2)%fn .and. &
         results(2)%fz_track < 0, message='flange force direction in the track frame')
      if (allocated(error)) return
      call check(error, abs(results(1)%fy_track - results(1)%fy) < 1e-15_wp*ref_load .and. &
         abs(results(1)%fz_track + results(1)%fn) < 1e-15_wp*ref_load, &
         message='gamma = 0: track = (F_y, -F_n)')
      if (allocated(error)) return

      patches(1)%is_hertz = .false.
      call solve_tangential(ws, patches(1), material(), creepages(1), options, results(1), lerr)
      call check(error, allocated(lerr), message="method 'fastsim' without a Hertz ellipse")
      if (allocated(error)) return
      options%method = method_fastsim_sh
      call solve_tangential(ws, patches(1), material(), creepages(1), options, results(1), lerr)
      call check(error, .not. allocated(lerr), message="method 'fastsim-sh' failed")
      if (allocated(error)) return
      call solve_tangential_patches(ws, patches, material(), creepages, options, wrong, track, &
         lerr)
      call check(error, allocated(lerr), message='results of the wrong size accepted')
   end subroutine test_patches

   !> A second case of the same size reuses the result and workspace arrays; a smaller patch
   !> reuses the workspace (capacity only grows).
   subroutine test_no_reallocation(error)
      type(error_type), allocatable, intent(out) :: error
      type(march_workspace_type), target :: ws
      type(tangential_patch_type), target :: res
      type(lib_error), allocatable :: lerr
      type(tangential_options_type) :: options
      integer(c_intptr_t) :: px_addr, tx_addr, y_addr

      options%n_elements = 30
      call solve_fastsim_sh(ws, skew_patch(40), material(), creepage_type(1e-4_wp, 1e-4_wp, &
         0.0_wp), options, res, lerr)
      call check(error, .not. allocated(lerr), message='first solve failed')
      if (allocated(error)) return
      px_addr = transfer(c_loc(res%px), px_addr)
      tx_addr = transfer(c_loc(ws%tx), tx_addr)
      y_addr = transfer(c_loc(ws%y), y_addr)
      call solve_prepared(ws, creepage_type(-1e-4_wp, 2e-4_wp, 1e-4_wp), res, lerr)
      call check(error, .not. allocated(lerr), message='second solve failed')
      if (allocated(error)) return
      call check(error, transfer(c_loc(res%px), px_addr) == px_addr .and. &
         transfer(c_loc(ws%tx), tx_addr) == tx_addr, message='arrays reallocated')
      if (allocated(error)) return
      options%n_elements = 20
      call prepare_fastsim_sh(ws, skew_patch(30), material(), options, lerr)
      call check(error, transfer(c_loc(ws%tx), tx_addr) == tx_addr .and. &
         transfer(c_loc(ws%y), y_addr) == y_addr, message='workspace shrunk')
   end subroutine test_no_reallocation

   !> Inconsistent strip tables are rejected with the strip named; an unprepared workspace too.
   subroutine test_invalid_patch(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: res
      type(lib_error), allocatable :: lerr
      type(tangential_options_type) :: options

      patch = hertz_patch(ref_a, ref_b, ref_load, 10, 0.0_wp)
      patch%m(4) = 0.0_wp
      call solve_fastsim_sh(ws, patch, material(), creepage_type(), options, res, lerr)
      call check(error, allocated(lerr), message='m = 0 accepted')
      if (allocated(error)) return
      call check(error, index(lerr%message, 'strip 4') > 0, message=lerr%message)
      if (allocated(error)) return
      patch = hertz_patch(ref_a, ref_b, ref_load, 10, 0.0_wp)
      patch%a = 0.0_wp
      call solve_fastsim_sh(ws, patch, material(), creepage_type(), options, res, lerr)
      call check(error, allocated(lerr), message='unloaded patch accepted')
      if (allocated(error)) return
      block
         type(march_workspace_type) :: fresh
         call solve_prepared(fresh, creepage_type(), res, lerr)
         call check(error, allocated(lerr), message='unprepared workspace accepted')
         if (allocated(error)) return
      end block
      patch = hertz_patch(ref_a, ref_b, ref_load, 10, 0.0_wp)
      deallocate (patch%gamma)
      call solve_fastsim_sh(ws, patch, material(), creepage_type(), options, res, lerr)
      call check(error, allocated(lerr), message='missing gamma accepted')
   end subroutine test_invalid_patch

end module test_fastsim_sh
