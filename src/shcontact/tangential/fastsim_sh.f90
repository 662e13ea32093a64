!> FASTSIM_SH (seed §2.2; doc/theory.md §6, decision 8: `method = 'fastsim-sh'`): FASTSIM on the
!> strips of a semi-Hertzian normal patch, each strip with the three Kalker flexibilities of its
!> local Hertz ellipse.
!>
!> For loaded strip i (a_i > 0) of the [[normal_patch_type]] (doc/theory.md §6.3, §6.5):
!>
!> * local coefficients c₁₁ᵢ, c₂₂ᵢ, c₂₃ᵢ at a/b = m_i/n_i, s_i = √(n_i/m_i);
!> * rates R_x = (3/8) G c₁₁ᵢ k_i ν_x,c/a_i − R_xφ φ_x y_i, R_y = (3/8) G c₂₂ᵢ k_i ν_yi/a_i and
!>   R_φ = (4/π) G c₂₃ᵢ s_i k_i φ_i/a_i (∂p_y/∂x = R_y + R_φ x), with the local creepages of the
!>   spin model (shcontact_tangential_spin) and R_xφ = R_φ/φ_i (option spin_flexibility = 'spin',
!>   default: Kalker's L₃ for the spin part of the longitudinal slip, so that FASTSIM_SH equals
!>   FASTSIM on a Hertzian patch) or (3/8) G c₁₁ᵢ k_i/a_i ('longitudinal', seed eq 21 literally);
!> * bounds: p_n,e = (2/π) N_i/(a_i dy) √(1 − x'²) and p_n,p = (8/(3π)) k_i N_i/(a_i dy)(1 − x'²)
!>   (seed eqs 27–28), with the weightings W1–W3 of §6.4.
!>
!> y_i is measured from the reference point, and M_z is taken about it. Forces act on the wheel.
module shcontact_tangential_fastsim_sh
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int, str_format
   use shcontact_core_constants, only: pi, half_pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_no_contact
   use shcontact_core_material, only: material_type, check_material
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_kalker, only: kalker_coefficients
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options, &
      bound_ellipsoidal, spin_flexibility_spin, corrected_model, surface_interface
   use shcontact_tangential_ellipse_correction, only: ellipse_correction_type, &
      prepare_ellipse_correction
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_spin, only: geometric_spin, strip_spin_terms
   use shcontact_tangential_march, only: march_workspace_type, reserve_workspace, &
      set_element_grid, solve_prepared
   implicit none
   private

   public :: prepare_fastsim_sh, solve_fastsim_sh

contains

   !> Fill a workspace from a normal patch: everything of §6.5 that does not depend on the
   !> creepages. Reuse the workspace for many creepages with solve_prepared.
   pure subroutine prepare_fastsim_sh(ws, patch, material, options, error)
      !> The workspace (allocated only when its capacity grows).
      type(march_workspace_type), intent(inout) :: ws
      !> The strip table of the normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Bound, spin model, n_x, spin flexibility, fields.
      type(tangential_options_type), intent(in) :: options
      !> Set for invalid input; stat_no_contact when no strip is loaded.
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: c11, c22, c23, g, mu, k, a, y, strip_load, s_ratio, akphi, pe, pp, r0, sin0, &
         cos0, ae, be, y_c, spread
      integer :: i, s, n_inactive

      call check_material(material, error)
      if (allocated(error)) return
      call check_tangential_options(options, error)
      if (allocated(error)) return
      call check_normal_patch(patch, error)
      if (allocated(error)) return

      call reserve_workspace(ws, patch%n_strips, options%n_elements)
      g = material%shear_modulus
      mu = material%friction
      r0 = patch%r0
      sin0 = sin(patch%gamma0)
      cos0 = cos(patch%gamma0)
      ws%bound = options%bound
      ws%spin_model = options%spin_model
      ws%fields = options%fields
      ws%friction = mu
      ws%dy = patch%dy
      ws%y_offset = 0.0_wp
      ws%gamma0 = patch%gamma0
      ws%phi_geo0 = geometric_spin(patch%gamma0, r0)

      s = 0
      n_inactive = 0
      ws%load = 0.0_wp
      ws%parabolic_load_ratio = 0.0_wp
      do i = 1, patch%n_strips
         ws%y_strip(i) = patch%y(i)
         if (.not. (patch%a(i) > 0.0_wp)) then
            n_inactive = n_inactive + 1
            ws%inactive(n_inactive) = i
            cycle
         end if
         s = s + 1
         ws%strip(s) = i
         a = patch%a(i)
         y = patch%y(i)
         k = patch%k(i)
         strip_load = patch%strip_load(i)
         call kalker_coefficients(patch%m(i)/patch%n(i), material%poisson, c11, c22, c23)
         s_ratio = sqrt(patch%n(i)/patch%m(i))

         ! doc/theory.md §6.3/§6.5 step 2, each rate multiplied by a_i (a_i² for R_φ).
         ws%y(s) = y
         ws%a(s) = a
         ws%akx(s) = 0.375_wp*g*c11*k
         ws%aky(s) = 0.375_wp*g*c22*k
         akphi = 4.0_wp/pi*g*c23*s_ratio*k
         ws%a2kphi(s) = akphi*a
         if (options%spin_flexibility == spin_flexibility_spin) then
            ws%akxs_y(s) = akphi*y
         else
            ws%akxs_y(s) = ws%akx(s)*y
         end if
         ws%flex_x(s) = a/ws%akx(s)
         ws%flex_y(s) = a/ws%aky(s)

         ! doc/theory.md §6.4: semi-elliptic and parabolic strip pressures (seed eqs 28, 27).
         pe = 2.0_wp*strip_load/(pi*a*patch%dy)
         pp = 8.0_wp/(3.0_wp*pi)*k*strip_load/(a*patch%dy)
         ws%pe_peak(s) = pe
         if (options%bound == bound_ellipsoidal) then
            ws%bound_peak(s) = mu*pe
         else
            ws%bound_peak(s) = mu*pp
         end if
         ws%weight(s) = 0.75_wp/k

         ! Geometric spin terms (shcontact_tangential_spin; CONTACT's sign of γ) on the
         ! contact surface of [[surface_angle]].
         call strip_spin_terms(surface_angle(i), sin0, cos0, r0, ws%phi_geo(s), ws%dphi_geo(s), &
            ws%cos_ratio(s))
         ws%rho(s) = patch%delta_r(i)/r0 - ws%phi_geo0*y
         ws%strip_normal(s) = strip_load
         ! The strip's forces act along and across the surface of [[surface_angle]].
         ws%sin_gamma(s) = sin(surface_angle(i))
         ws%cos_gamma(s) = cos(surface_angle(i))

         ws%load = ws%load + strip_load
         ws%parabolic_load_ratio = ws%parabolic_load_ratio + k*strip_load
      end do
      ws%n_active = s
      ws%parabolic_load_ratio = 32.0_wp/(9.0_wp*pi)*ws%parabolic_load_ratio/ws%load
      call set_element_grid(ws)
      ws%correction = ellipse_correction_type()
      if (corrected_model(options)) then
         ! The correction's ellipse from two load-weighted moments that are exact on an
         ! ellipse (doc/tangential.md): b_e from the load's lateral spread (on an ellipse the
         ! load per unit width is ∝ 1 − y²/b², of variance b²/5), a_e from the load-weighted
         ! mean strip length (on an ellipse ∫(1 − t²)^{3/2} dt / ∫(1 − t²) dt = 9π/32 of a): the
         ! length over which the traction builds up where the load is. Both move continuously
         ! when an edge strip takes or loses a little load (the wheel in motion).
         y_c = load_mean(ws%y)
         spread = 0.0_wp
         do s = 1, ws%n_active
            spread = spread + ws%strip_normal(s)*(ws%y(s) - y_c)**2
         end do
         be = max(sqrt(5.0_wp*spread/ws%load), 0.5_wp*ws%dy)
         ae = load_mean(ws%a)/(9.0_wp*pi/32.0_wp)
         call prepare_ellipse_correction(ws%correction, ae, be, ws%load, material, y_c, &
            load_mean(ws%cos_gamma), load_mean(ws%sin_gamma))
      end if

   contains

      !> The angle of strip i's contact surface (the direction of its pressure, the plane of its
      !> traction and slip): the wheel's γ_i, or with `contact_surface = 'interface'` the
      !> interface's γ_n,i where the normal solution gave it (not on a strip table made by
      !> hand).
      pure real(wp) function surface_angle(i)
         integer, intent(in) :: i
         surface_angle = patch%gamma(i)
         if (options%contact_surface /= surface_interface) return
         if (allocated(patch%gamma_n)) then
            if (size(patch%gamma_n) >= patch%n_strips) surface_angle = patch%gamma_n(i)
         end if
      end function surface_angle

      !> Σ N_s v_s / Σ N_s over the loaded strips.
      pure real(wp) function load_mean(v)
         real(wp), intent(in) :: v(:)
         load_mean = sum(ws%strip_normal(1:ws%n_active)*v(1:ws%n_active))/ws%load
      end function load_mean

   end subroutine prepare_fastsim_sh

   !> FASTSIM_SH in one call: [[prepare_fastsim_sh]] then solve_prepared.
   pure subroutine solve_fastsim_sh(ws, patch, material, creepage, options, result, error)
      !> The workspace (allocated only when its capacity grows).
      type(march_workspace_type), intent(inout) :: ws
      !> The strip table of the normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Creepages at the reference point.
      type(creepage_type), intent(in) :: creepage
      !> Bound, spin model, n_x, spin flexibility, fields.
      type(tangential_options_type), intent(in) :: options
      !> The solution (arrays reallocated only when their shape changes).
      type(tangential_patch_type), intent(inout) :: result
      !> Set for invalid input.
      type(error_type), allocatable, intent(out) :: error

      call prepare_fastsim_sh(ws, patch, material, options, error)
      if (allocated(error)) return
      call solve_prepared(ws, creepage, result, error)
   end subroutine solve_fastsim_sh

   !> The strip table is complete and usable: sizes, dy, r₀, γ₀, and for every loaded strip
   !> k_i, N_i, m_i, n_i > 0 and |γ_i| < π/2.
   pure subroutine check_normal_patch(patch, error)
      type(normal_patch_type), intent(in) :: patch
      type(error_type), allocatable, intent(out) :: error
      integer :: i, n
      logical :: loaded

      n = patch%n_strips
      if (n < 1) then
         call fatal_error(error, 'normal patch: n_strips = '//str_int(n)// &
            ', expected at least one strip', stat_invalid_input)
         return
      end if
      if (.not. (have(patch%y, n) .and. have(patch%a, n) .and. have(patch%k, n) .and. &
         have(patch%strip_load, n) .and. have(patch%m, n) .and. have(patch%n, n) .and. &
         have(patch%gamma, n) .and. have(patch%delta_r, n))) then
         call fatal_error(error, 'normal patch: the strip arrays y, a, k, strip_load, m, n, '// &
            'gamma, delta_r must hold n_strips = '//str_int(n)//' values', stat_invalid_input)
         return
      end if
      if (.not. positive(patch%dy)) then
         call fatal_error(error, 'normal patch: strip width dy = '// &
            str_format(patch%dy, '(es12.4)')//' mm, expected a positive width', stat_invalid_input)
         return
      end if
      if (.not. positive(patch%r0)) then
         call fatal_error(error, 'normal patch: rolling radius r0 = '// &
            str_format(patch%r0, '(es12.4)')//' mm, expected a positive radius', &
            stat_invalid_input)
         return
      end if
      if (.not. below(abs(patch%gamma0), half_pi)) then
         call fatal_error(error, 'normal patch: contact angle gamma0 = '// &
            str_format(patch%gamma0, '(es12.4)')//' rad, expected |gamma0| < pi/2', &
            stat_invalid_input)
         return
      end if
      loaded = .false.
      do i = 1, n
         if (.not. ieee_is_finite(patch%a(i))) then
            call strip_error('half-length a', patch%a(i), 'a finite value >= 0', error)
         else if (patch%a(i) < 0.0_wp) then
            call strip_error('half-length a', patch%a(i), 'a finite value >= 0', error)
         else if (.not. (patch%a(i) > 0.0_wp)) then
            cycle
         else if (.not. (ieee_is_finite(patch%y(i)) .and. ieee_is_finite(patch%delta_r(i)))) then
            call strip_error('y or delta_r', patch%y(i), 'finite values', error)
         else if (.not. positive(patch%k(i))) then
            call strip_error('k', patch%k(i), 'k > 0 on a loaded strip', error)
         else if (.not. positive(patch%strip_load(i))) then
            call strip_error('load N_i', patch%strip_load(i), 'N_i > 0 on a loaded strip', error)
         else if (.not. positive(patch%m(i))) then
            call strip_error('Hertz coefficient m', patch%m(i), 'm > 0', error)
         else if (.not. positive(patch%n(i))) then
            call strip_error('Hertz coefficient n', patch%n(i), 'n > 0', error)
         else if (.not. below(abs(patch%gamma(i)), half_pi)) then
            call strip_error('contact angle gamma', patch%gamma(i), '|gamma| < pi/2', error)
         end if
         if (allocated(error)) return
         loaded = .true.
      end do
      if (.not. loaded) then
         call fatal_error(error, 'normal patch: no strip is loaded (all a_i = 0)', &
            stat_no_contact)
      end if

   contains

      pure subroutine strip_error(item, value, expected, error)
         character(len=*), intent(in) :: item, expected
         real(wp), intent(in) :: value
         type(error_type), allocatable, intent(out) :: error
         call fatal_error(error, 'normal patch, strip '//str_int(i)//': '//item//' = '// &
            str_format(value, '(es12.4)')//', expected '//expected, stat_invalid_input)
      end subroutine strip_error

   end subroutine check_normal_patch

   !> x is finite and > 0 (tested without comparing a NaN, which would raise "invalid").
   elemental logical function positive(x)
      real(wp), intent(in) :: x
      positive = ieee_is_finite(x)
      if (positive) positive = x > 0.0_wp
   end function positive

   !> x is finite and < limit.
   elemental logical function below(x, limit)
      real(wp), intent(in) :: x, limit
      below = ieee_is_finite(x)
      if (below) below = x < limit
   end function below

   pure logical function have(array, n)
      real(wp), allocatable, intent(in) :: array(:)
      integer, intent(in) :: n
      have = allocated(array)
      if (have) have = size(array) >= n
   end function have


end module shcontact_tangential_fastsim_sh
