!> Local creepages of FASTSIM_SH per strip: the spin models of doc/theory.md §6.2, written in the
!> project's sign convention.
!>
!> **Sign of γ.** The contact angle γ follows CONTACT (γ = atan(dz_rail/dy), z down, y towards
!> the field side; right-wheel tread γ₀ ≈ −0.029 rad; dr_w/dy ≈ tan γ). doc/theory.md §6.1 uses the
!> opposite sign (sin γ_§6.1 = −dr_w/dy), so its eq 19 φ_i = −sin γ_i/R₀ reads here
!>
!>     φ_geo,i = +sin γ_i / r₀,
!>
!> with r₀ the wheel rolling radius at the reference point and δr_i = r_w,i − r₀, so that ν_x is
!> exactly the longitudinal creepage at the reference point and δr_i/r₀ ≈ φ_geo,0·y_i to first
!> order (eq 17).
!>
!> **Models** (y_i from the reference point; ν_yi = ν_y cos γ₀/cos γ_i except in 'uniform'):
!>
!> | model | φ_i | ν_xi |
!> |---|---|---|
!> | additive (C) | φ + (φ_geo,i − φ_geo,0) | ν_x − φ y_i − ρ_i |
!> | uniform (D) | φ | ν_x − φ y_i |
!> | scaled (B) | λ φ_geo,i, λ = φ/φ_geo,0 | ν_x − φ y_i − λ ρ_i |
!> | geometric (G) | φ_geo,i | ν_x − φ_geo,0 y_i − ρ_i |
!>
!> with the second-order geometric remainder ρ_i = δr_i/r₀ − φ_geo,0·y_i (zero for a linear
!> rolling-radius profile). ν_xi is returned split as ν_xi = ν_x,c − φ_x·y_i: the "creep" part
!> ν_x,c and the rigid-spin part φ_x, because the two may build up with different flexibilities
!> (option `spin_flexibility`).
!>
!> **Other patches of the same wheel** ([[carried_creepages]], doc/lobes.md). Prescribed
!> creepages are the rigid slip of the wheel relative to the rail at one point, the reference
!> point of the first (deepest) patch. Another patch of the same wheel is more of the same
!> surface: it gets the slip the same model gives a strip at its reference point, a lateral
!> distance y_k from that point in its contact plane, with its own γ_k and r_k. Under the
!> default 'uniform' this is the planar rigid slip of CONTACT's joined patch,
!> (ν_x − φ y_k, ν_y, φ); under 'additive' the spin also changes with the contact angle,
!> φ_k = φ + (sin γ_k − sin γ₀)/r₀, as a rolling wheel's does.
module shcontact_tangential_spin
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_tangential_options, only: spin_uniform, spin_scaled, spin_geometric
   use shcontact_tangential_creepage, only: creepage_type
   implicit none
   private

   public :: geometric_spin, strip_spin_terms, local_creepages, scaled_spin_factor, &
      min_geometric_spin, carried_creepages

   !> Smallest |φ_geo,0| (rad/mm) accepted by the scaled spin model.
   real(wp), parameter :: min_geometric_spin = 1.0e-9_wp

contains

   !> Geometric spin φ_geo = sin γ / r₀ (rad/mm) in CONTACT's sign of γ (see the module text).
   elemental function geometric_spin(gamma, r0) result(phi_geo)
      !> Contact angle γ (rad), CONTACT's sign.
      real(wp), intent(in) :: gamma
      !> Rolling radius at the reference point r₀ (mm), > 0.
      real(wp), intent(in) :: r0
      real(wp) :: phi_geo
      phi_geo = sin(gamma)/r0
   end function geometric_spin

   !> The geometric terms of one strip used by the spin models: φ_geo,i = sin γ_i / r₀ (as
   !> [[geometric_spin]]), φ_geo,i − φ_geo,0 = (sin γ_i − sin γ₀)/r₀ and cos γ₀/cos γ_i. One
   !> sine and one cosine per strip (the compiler pairs them into one sincos call).
   elemental subroutine strip_spin_terms(gamma, sin0, cos0, r0, phi_geo, dphi_geo, cos_ratio)
      !> Contact angle of the strip γ_i (rad), CONTACT's sign, |γ_i| < π/2.
      real(wp), intent(in) :: gamma
      !> sin γ₀ and cos γ₀ of the reference point.
      real(wp), intent(in) :: sin0, cos0
      !> Rolling radius at the reference point r₀ (mm), > 0.
      real(wp), intent(in) :: r0
      !> φ_geo,i and φ_geo,i − φ_geo,0 (rad/mm).
      real(wp), intent(out) :: phi_geo, dphi_geo
      !> cos γ₀/cos γ_i.
      real(wp), intent(out) :: cos_ratio
      real(wp) :: sin_i

      sin_i = sin(gamma)
      phi_geo = sin_i/r0
      dphi_geo = (sin_i - sin0)/r0
      cos_ratio = cos0/cos(gamma)
   end subroutine strip_spin_terms

   !> λ = φ/φ_geo,0 of the scaled model B; an error when the geometric spin at the reference point
   !> vanishes (tread contact with γ₀ ≈ 0), where model B is singular (doc/theory.md §6.2).
   pure subroutine scaled_spin_factor(phi, phi_geo0, lambda, error)
      !> Input spin φ (rad/mm).
      real(wp), intent(in) :: phi
      !> Geometric spin at the reference point φ_geo,0 (rad/mm).
      real(wp), intent(in) :: phi_geo0
      !> λ = φ/φ_geo,0.
      real(wp), intent(out) :: lambda
      !> Set when |φ_geo,0| < [[min_geometric_spin]].
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: buf

      lambda = 0.0_wp
      if (abs(phi_geo0) < min_geometric_spin) then
         write (buf, '(es12.4)') phi_geo0
         call fatal_error(error, "spin_model = 'scaled' needs a geometric spin at the "// &
            'reference point: phi_geo,0 = sin(gamma0)/r0 = '//trim(adjustl(buf))// &
            " rad/mm, expected |phi_geo,0| >= 1e-9 rad/mm; use spin_model = 'additive' "// &
            'for (near-)flat tread contact', stat_invalid_input)
         return
      end if
      lambda = phi/phi_geo0
   end subroutine scaled_spin_factor

   !> Local creepages of one strip for the given spin model (table in the module text).
   elemental subroutine local_creepages(model, nu_x, nu_y, phi, lambda, cos_ratio, phi_geo, &
      dphi_geo, rho, phi_geo0, nu_x_creep, phi_x, nu_y_loc, phi_loc)
      !> Spin model, `spin_*` of shcontact_tangential_options.
      integer, intent(in) :: model
      !> Creepages at the reference point (ν_x, ν_y dimensionless, φ rad/mm).
      real(wp), intent(in) :: nu_x, nu_y, phi
      !> λ = φ/φ_geo,0 (model B only).
      real(wp), intent(in) :: lambda
      !> cos γ₀/cos γ_i.
      real(wp), intent(in) :: cos_ratio
      !> φ_geo,i and φ_geo,i − φ_geo,0 (rad/mm).
      real(wp), intent(in) :: phi_geo, dphi_geo
      !> Geometric remainder ρ_i = δr_i/r₀ − φ_geo,0 y_i.
      real(wp), intent(in) :: rho
      !> φ_geo,0 (rad/mm).
      real(wp), intent(in) :: phi_geo0
      !> Creep part ν_x,c of ν_xi = ν_x,c − φ_x y_i.
      real(wp), intent(out) :: nu_x_creep
      !> Rigid-spin part φ_x of the longitudinal slip (rad/mm).
      real(wp), intent(out) :: phi_x
      !> Local lateral creepage ν_yi.
      real(wp), intent(out) :: nu_y_loc
      !> Local spin φ_i (rad/mm).
      real(wp), intent(out) :: phi_loc

      select case (model)
      case (spin_uniform)
         nu_x_creep = nu_x
         phi_x = phi
         nu_y_loc = nu_y
         phi_loc = phi
      case (spin_scaled)
         ! λ φ_geo,0 = φ: the rigid part keeps the input spin.
         nu_x_creep = nu_x - lambda*rho
         phi_x = phi
         nu_y_loc = nu_y*cos_ratio
         phi_loc = lambda*phi_geo
      case (spin_geometric)
         nu_x_creep = nu_x - rho
         phi_x = phi_geo0
         nu_y_loc = nu_y*cos_ratio
         phi_loc = phi_geo
      case default ! spin_additive (validated by check_tangential_options)
         nu_x_creep = nu_x - rho
         phi_x = phi
         nu_y_loc = nu_y*cos_ratio
         phi_loc = phi + dphi_geo
      end select
   end subroutine local_creepages

   !> The creepages at another point of the same wheel (module text): those the spin model
   !> gives a strip there, ν_x,k = ν_x,c − φ_x y_k, ν_y,k, φ_k of [[local_creepages]] with the
   !> point's lateral distance y_k, contact angle γ_k and rolling-radius change r_k − r₀.
   !> Under 'uniform' (ν_x − φ y_k, ν_y, φ). At y_k = 0, γ_k = γ₀, r_k = r₀ the creepages are
   !> those given.
   pure subroutine carried_creepages(model, creepage, lateral, gamma0, r0, gamma, radius, &
         carried, error)
      !> Spin model, `spin_*` of shcontact_tangential_options.
      integer, intent(in) :: model
      !> Creepages at the reference point (ν_x, ν_y, φ in rad/mm).
      type(creepage_type), intent(in) :: creepage
      !> Lateral distance y_k of the point from the reference point in the reference contact
      !> plane (mm, towards the field side).
      real(wp), intent(in) :: lateral
      !> Contact angle γ₀ (rad, CONTACT's sign) and rolling radius r₀ (mm, > 0) at the reference
      !> point.
      real(wp), intent(in) :: gamma0, r0
      !> Contact angle γ_k (rad, |γ_k| < π/2) and rolling radius r_k (mm) at the point.
      real(wp), intent(in) :: gamma, radius
      !> The creepages at the point.
      type(creepage_type), intent(out) :: carried
      !> Set by the scaled model when φ_geo,0 vanishes ([[scaled_spin_factor]]).
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: phi_geo, dphi_geo, cos_ratio, phi_geo0, rho, lambda, nu_x_creep, phi_x

      phi_geo0 = geometric_spin(gamma0, r0)
      call strip_spin_terms(gamma, sin(gamma0), cos(gamma0), r0, phi_geo, dphi_geo, cos_ratio)
      rho = (radius - r0)/r0 - phi_geo0*lateral
      lambda = 0.0_wp
      if (model == spin_scaled) then
         call scaled_spin_factor(creepage%phi, phi_geo0, lambda, error)
         if (allocated(error)) return
      end if
      call local_creepages(model, creepage%nu_x, creepage%nu_y, creepage%phi, lambda, &
         cos_ratio, phi_geo, dphi_geo, rho, phi_geo0, nu_x_creep, phi_x, carried%nu_y, &
         carried%phi)
      carried%nu_x = nu_x_creep - phi_x*lateral
   end subroutine carried_creepages

end module shcontact_tangential_spin
