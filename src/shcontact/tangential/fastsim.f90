!> Classical FASTSIM (Kalker 1982) with three flexibilities on a Hertz ellipse (doc/theory.md §3,
!> decision 8: `method = 'fastsim'`).
!>
!> The ellipse |x/a|² + |y/b|² ≤ 1 is cut into n_y strips of width 2b/n_y; strip i (centre y_i
!> from the ellipse centre, half-length a_i = a k_i, k_i = √(1 − y_i²/b²)) has n_x elements. The
!> rates are those of Kalker's simplified theory with the flexibilities L₁, L₂, L₃ (§3.1):
!> ∂p_x/∂x = ν_x/L₁ − φ y/L₃, ∂p_y/∂x = ν_y/L₂ + φ x/L₃; the bound is μ times the Hertz pressure
!> p₀ k_i √(1 − x'²) (ellipsoidal) or (4/3) p₀ k_i² (1 − x'²) (parabolic). The weighted bounds
!> W1–W3 apply with p_n,e/p_n,p = 3/(4 k_i) (§6.4). The creepages act about the ellipse centre
!> (the seed's comparison); options%spin_model and options%spin_flexibility do not apply.
module shcontact_tangential_fastsim
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_material, only: material_type, check_material
   use shcontact_tangential_kalker, only: kalker_coefficients
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options, &
      bound_ellipsoidal, spin_uniform
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_ellipse_correction, only: ellipse_correction_type
   use shcontact_tangential_march, only: march_workspace_type, reserve_workspace, &
      set_element_grid, solve_prepared
   implicit none
   private

   public :: prepare_fastsim, solve_fastsim, fastsim_flexibilities

   !> Largest accepted number of strips.
   integer, parameter :: max_strips = 1000000

contains

   !> Kalker's three flexibilities L₁ = 8a/(3c₁₁G), L₂ = 8a/(3c₂₂G), L₃ = πa√(a/b)/(4c₂₃G)
   !> (doc/theory.md §3.1), in mm/MPa.
   elemental subroutine fastsim_flexibilities(semi_a, semi_b, material, l1, l2, l3)
      !> Semi-axes a (rolling direction) and b (lateral) (mm), > 0.
      real(wp), intent(in) :: semi_a, semi_b
      !> G and ν.
      type(material_type), intent(in) :: material
      !> The flexibilities (mm/MPa).
      real(wp), intent(out) :: l1, l2, l3
      real(wp) :: c11, c22, c23, g

      call kalker_coefficients(semi_a/semi_b, material%poisson, c11, c22, c23)
      g = material%shear_modulus
      l1 = 8.0_wp*semi_a/(3.0_wp*c11*g)
      l2 = 8.0_wp*semi_a/(3.0_wp*c22*g)
      l3 = pi*semi_a*sqrt(semi_a/semi_b)/(4.0_wp*c23*g)
   end subroutine fastsim_flexibilities

   !> Fill a workspace for FASTSIM on the ellipse (a, b) carrying the normal force `load`.
   pure subroutine prepare_fastsim(ws, semi_a, semi_b, load, material, options, n_strips, error, &
      y_centre, gamma0)
      !> The workspace (allocated only when its capacity grows).
      type(march_workspace_type), intent(inout) :: ws
      !> Semi-axes a (rolling direction) and b (lateral) (mm), > 0.
      real(wp), intent(in) :: semi_a, semi_b
      !> Normal force N (N), > 0.
      real(wp), intent(in) :: load
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Bound, n_x (= n_elements), fields.
      type(tangential_options_type), intent(in) :: options
      !> Number of strips n_y across the ellipse.
      integer, intent(in) :: n_strips
      !> Set for invalid input.
      type(error_type), allocatable, intent(out) :: error
      !> Lateral position of the ellipse centre from the reference point (mm, default 0): shifts
      !> the reported y and the moment arm of M_z (taken about the reference point).
      real(wp), intent(in), optional :: y_centre
      !> Reference contact angle γ₀ (rad, CONTACT's sign, default 0), for the track-frame forces.
      real(wp), intent(in), optional :: gamma0
      real(wp) :: l1, l2, l3, p0, dy, yl, k, ai
      integer :: i

      call check_material(material, error)
      if (allocated(error)) return
      call check_tangential_options(options, error)
      if (allocated(error)) return
      call check_ellipse(semi_a, semi_b, load, n_strips, error)
      if (allocated(error)) return

      call reserve_workspace(ws, n_strips, options%n_elements)
      ws%bound = options%bound
      ws%spin_model = spin_uniform
      ws%fields = options%fields
      ws%friction = material%friction
      ws%load = load
      ws%y_offset = 0.0_wp
      if (present(y_centre)) ws%y_offset = y_centre
      ws%gamma0 = 0.0_wp
      if (present(gamma0)) ws%gamma0 = gamma0
      ws%phi_geo0 = 0.0_wp

      call fastsim_flexibilities(semi_a, semi_b, material, l1, l2, l3)
      p0 = 3.0_wp*load/(2.0_wp*pi*semi_a*semi_b)
      dy = 2.0_wp*semi_b/real(n_strips, wp)
      ws%dy = dy
      ws%n_active = n_strips
      ws%parabolic_load_ratio = 0.0_wp
      do i = 1, n_strips
         yl = -semi_b + (real(i, wp) - 0.5_wp)*dy
         k = sqrt((1.0_wp - yl/semi_b)*(1.0_wp + yl/semi_b))
         ai = semi_a*k
         ws%strip(i) = i
         ws%y_strip(i) = ws%y_offset + yl
         ws%y(i) = yl
         ws%a(i) = ai
         ws%akx(i) = ai/l1
         ws%aky(i) = ai/l2
         ws%a2kphi(i) = ai*ai/l3
         ! Kalker: the spin part −φy of the longitudinal slip goes with L₃ (§3.1).
         ws%akxs_y(i) = ai*yl/l3
         ws%flex_x(i) = l1
         ws%flex_y(i) = l2
         ws%pe_peak(i) = p0*k
         if (options%bound == bound_ellipsoidal) then
            ws%bound_peak(i) = material%friction*p0*k
         else
            ws%bound_peak(i) = material%friction*(4.0_wp/3.0_wp)*p0*k*k
         end if
         ws%weight(i) = 0.75_wp/k
         ws%cos_ratio(i) = 1.0_wp
         ws%phi_geo(i) = 0.0_wp
         ws%dphi_geo(i) = 0.0_wp
         ws%rho(i) = 0.0_wp
         ! One contact angle for the whole ellipse: any split of the load gives its forces.
         ws%strip_normal(i) = load/real(n_strips, wp)
         ws%sin_gamma(i) = sin(ws%gamma0)
         ws%cos_gamma(i) = cos(ws%gamma0)
         ! Strip load of the Hertz pressure: N_i = (π/2) p₀ k_i a_i dy.
         ws%parabolic_load_ratio = ws%parabolic_load_ratio + k*0.5_wp*pi*p0*k*ai*dy
      end do
      ws%parabolic_load_ratio = 32.0_wp/(9.0_wp*pi)*ws%parabolic_load_ratio/load
      call set_element_grid(ws)
      ws%correction = ellipse_correction_type()
   end subroutine prepare_fastsim

   !> Classical FASTSIM in one call: [[prepare_fastsim]] then solve_prepared.
   pure subroutine solve_fastsim(ws, semi_a, semi_b, load, material, creepage, options, n_strips, &
      result, error, y_centre, gamma0)
      !> The workspace (allocated only when its capacity grows).
      type(march_workspace_type), intent(inout) :: ws
      !> Semi-axes a (rolling direction) and b (lateral) (mm), > 0.
      real(wp), intent(in) :: semi_a, semi_b
      !> Normal force N (N), > 0.
      real(wp), intent(in) :: load
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Creepages, applied about the ellipse centre.
      type(creepage_type), intent(in) :: creepage
      !> Bound, n_x, fields.
      type(tangential_options_type), intent(in) :: options
      !> Number of strips n_y.
      integer, intent(in) :: n_strips
      !> The solution (arrays reallocated only when their shape changes).
      type(tangential_patch_type), intent(inout) :: result
      !> Set for invalid input.
      type(error_type), allocatable, intent(out) :: error
      !> Lateral position of the ellipse centre from the reference point (mm, default 0).
      real(wp), intent(in), optional :: y_centre
      !> Reference contact angle γ₀ (rad, default 0).
      real(wp), intent(in), optional :: gamma0

      call prepare_fastsim(ws, semi_a, semi_b, load, material, options, n_strips, error, &
         y_centre, gamma0)
      if (allocated(error)) return
      call solve_prepared(ws, creepage, result, error)
   end subroutine solve_fastsim

   !> Semi-axes and load positive, strip count in range.
   pure subroutine check_ellipse(semi_a, semi_b, load, n_strips, error)
      real(wp), intent(in) :: semi_a, semi_b, load
      integer, intent(in) :: n_strips
      type(error_type), allocatable, intent(out) :: error
      character(len=24) :: buf

      if (.not. positive(semi_a)) then
         write (buf, '(es12.4)') semi_a
         call fatal_error(error, 'FASTSIM ellipse: semi-axis a = '//trim(adjustl(buf))// &
            ' mm, expected a positive length', stat_invalid_input)
      else if (.not. positive(semi_b)) then
         write (buf, '(es12.4)') semi_b
         call fatal_error(error, 'FASTSIM ellipse: semi-axis b = '//trim(adjustl(buf))// &
            ' mm, expected a positive length', stat_invalid_input)
      else if (.not. positive(load)) then
         write (buf, '(es12.4)') load
         call fatal_error(error, 'FASTSIM ellipse: normal force = '//trim(adjustl(buf))// &
            ' N, expected a positive force', stat_invalid_input)
      else if (n_strips < 1 .or. n_strips > max_strips) then
         write (buf, '(i0)') n_strips
         call fatal_error(error, 'FASTSIM ellipse: n_strips = '//trim(buf)// &
            ', expected 1 to 1000000 strips', stat_invalid_input)
      end if
   end subroutine check_ellipse

   !> x is finite and > 0 (tested without comparing a NaN, which would raise "invalid").
   elemental logical function positive(x)
      real(wp), intent(in) :: x
      positive = ieee_is_finite(x)
      if (positive) positive = x > 0.0_wp
   end function positive

end module shcontact_tangential_fastsim
