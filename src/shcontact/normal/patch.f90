!> The normal solution of one contact patch: the strip table of the semi-Hertzian method
!> (physics.md §4.3), which is also everything FASTSIM_SH needs (§6.5).
module shcontact_normal_patch
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: normal_patch_type

   !> Strips of equal width dy centred at y(i); a strip with a(i) = 0 carries no load.
   type :: normal_patch_type
      !> Number of strips.
      integer :: n_strips = 0
      !> True when the patch is one Hertz ellipse (`method = 'hertz'`).
      logical :: is_hertz = .false.
      !> Hertz ellipse semi-axes when is_hertz (mm): along x (rolling) and y (lateral).
      real(wp) :: ellipse_a = 0.0_wp, ellipse_b = 0.0_wp
      !> Lateral offset of the ellipse centre from the reference point (mm), when is_hertz.
      real(wp) :: ellipse_y_centre = 0.0_wp
      !> Approach δ of the patch (mm).
      real(wp) :: approach = 0.0_wp
      !> Total normal force Σ N_i (N).
      real(wp) :: load = 0.0_wp
      !> Contact area Σ 2 a_i dy (mm²).
      real(wp) :: area = 0.0_wp
      !> Largest strip peak pressure (MPa).
      real(wp) :: p_max = 0.0_wp
      !> Strip width (mm).
      real(wp) :: dy = 0.0_wp
      !> Contact angle and rolling radius at the reference point (copied from the geometry).
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp
      !> Strip centres, from the reference point (mm).
      real(wp), allocatable :: y(:)
      !> Strip half-lengths a_i (mm).
      real(wp), allocatable :: a(:)
      !> k_i = a_i / a_H,i = √(δ_i/δ) (dimensionless, 0..1).
      real(wp), allocatable :: k(:)
      !> Strip peak pressures p₀,ᵢ (MPa).
      real(wp), allocatable :: p0(:)
      !> Strip loads N_i = (π/2) p₀,ᵢ a_i dy (N).
      real(wp), allocatable :: strip_load(:)
      !> Local Hertz coefficients m_i, n_i (n_i/m_i = b_H,i/a_H,i).
      real(wp), allocatable :: m(:), n(:)
      !> Local penetration split ε_a,i (dimensionless).
      real(wp), allocatable :: eps_a(:)
      !> Local contact angle γ_i (rad).
      real(wp), allocatable :: gamma(:)
      !> Rolling-radius variation δr_i = r_w(y_i) − r₀ (mm).
      real(wp), allocatable :: delta_r(:)
      !> Local wheel rolling radius r_w,i (mm).
      real(wp), allocatable :: r_wheel(:)
   end type normal_patch_type

end module shcontact_normal_patch
