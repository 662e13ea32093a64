!> The normal solution of one contact patch: the strip table of the semi-Hertzian method
!> (doc/theory.md §4.3), which is also everything FASTSIM_SH needs (§6.5).
module shcontact_normal_patch
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   implicit none
   private

   public :: normal_patch_type, ellipse_strip_patch
   public :: reserve_strips, clear_strips, clear_totals, clear_arrays, strip_totals

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
      !> The penetration the strips' k_i are measured against (mm): k_i² = δ_i/δ_ref with
      !> δ_ref = max(δ, max_i δ_i), the approach unless a strip beside the reference point
      !> penetrates deeper (the vertical approach's tilt can do that, even with δ ≤ 0).
      real(wp) :: approach_reference = 0.0_wp
      !> Total normal force Σ N_i (N).
      real(wp) :: load = 0.0_wp
      !> Contact area Σ 2 a_i dy (mm²).
      real(wp) :: area = 0.0_wp
      !> Largest strip peak pressure (MPa).
      real(wp) :: p_max = 0.0_wp
      !> Strip width (mm).
      real(wp) :: dy = 0.0_wp
      !> Contact angle and rolling radius at the reference point: the geometric contact point
      !> of the loaded state (shcontact_normal_semihertz's refer_to_loaded_point), where the
      !> strips' y = 0 and where creepages are given.
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp
      !> Where the reference point lies from the geometry table's origin (the first contact),
      !> along the contact plane (mm), and the contact plane's angle (rad).
      real(wp) :: y_shift = 0.0_wp, gamma_plane = 0.0_wp
      !> Strips on a conformal table (shcontact_geometry_patch).
      logical :: conformal = .false.
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
      !> Local contact angle γ_i (rad): the wheel surface's (its rolling radius, A, the tilt).
      real(wp), allocatable :: gamma(:)
      !> The interface's angle γ_n,i (rad, CONTACT's sign): the deformed interface lies midway
      !> between the undeformed surfaces (doc/geometry.md, "The direction of the pressure"). With
      !> `&tangential contact_surface = 'interface'` the strip's forces are resolved in the
      !> track frame, and its spin taken, with it; a table built without it (unallocated) uses
      !> γ_i.
      real(wp), allocatable :: gamma_n(:)
      !> Rolling-radius variation δr_i = r_w(y_i) − r₀ (mm).
      real(wp), allocatable :: delta_r(:)
      !> Local wheel rolling radius r_w,i (mm).
      real(wp), allocatable :: r_wheel(:)
   contains
      !> How far the reference point lies from the first contact across the track (mm).
      procedure :: lateral_offset
      !> How far it lies from the first contact vertically (mm).
      procedure :: vertical_offset
   end type normal_patch_type

contains

   !> The strip table of a Hertz ellipse with given semi-axes and load on a flat, straight patch
   !> (γ = 0, constant rolling radius): strips over [−b, b], k_i = √(1 − y_i²/b²), a_i = k_i a,
   !> p₀,ᵢ = k_i p₀ with p₀ = 3N/(2πab), n_i/m_i = b/a. Used to run FASTSIM_SH on canonical
   !> ellipses (the exact-ellipse table and its tests).
   pure subroutine ellipse_strip_patch(semi_a, semi_b, load, n_strips, r0, patch)
      !> Semi-axes along x and y (mm), > 0.
      real(wp), intent(in) :: semi_a, semi_b
      !> Normal force (N), > 0.
      real(wp), intent(in) :: load
      !> Number of strips, ≥ 1.
      integer, intent(in) :: n_strips
      !> Rolling radius (mm), > 0.
      real(wp), intent(in) :: r0
      !> The strip table.
      type(normal_patch_type), intent(out) :: patch
      real(wp) :: eta, p0
      integer :: i

      patch%n_strips = n_strips
      patch%is_hertz = .true.
      patch%ellipse_a = semi_a
      patch%ellipse_b = semi_b
      patch%r0 = r0
      patch%dy = 2.0_wp*semi_b/n_strips
      p0 = 1.5_wp*load/(pi*semi_a*semi_b)
      allocate (patch%y(n_strips), patch%a(n_strips), patch%k(n_strips), patch%p0(n_strips), &
         patch%strip_load(n_strips), patch%m(n_strips), patch%n(n_strips), &
         patch%eps_a(n_strips), patch%gamma(n_strips), patch%gamma_n(n_strips), &
         patch%delta_r(n_strips), patch%r_wheel(n_strips))
      do i = 1, n_strips
         eta = (2.0_wp*i - 1.0_wp)/n_strips - 1.0_wp
         patch%y(i) = eta*semi_b
         patch%k(i) = sqrt((1.0_wp - eta)*(1.0_wp + eta))
         patch%a(i) = patch%k(i)*semi_a
         patch%p0(i) = patch%k(i)*p0
         patch%strip_load(i) = 0.5_wp*pi*patch%p0(i)*patch%a(i)*patch%dy
      end do
      patch%m = 1.0_wp
      patch%n = semi_b/semi_a
      patch%eps_a = 0.5_wp
      patch%gamma = 0.0_wp
      patch%gamma_n = 0.0_wp
      patch%delta_r = 0.0_wp
      patch%r_wheel = r0
      patch%load = sum(patch%strip_load)
      patch%area = 2.0_wp*sum(patch%a)*patch%dy
      patch%p_max = maxval(patch%p0)
   end subroutine ellipse_strip_patch

   !> The reference point's move from the geometry table's origin (the first contact) across
   !> the track (mm): y_shift along the contact plane, y_shift cos γ_plane (positive towards the
   !> field side of the wheel).
   pure real(wp) function lateral_offset(self) result(offset)
      class(normal_patch_type), intent(in) :: self
      offset = self%y_shift*cos(self%gamma_plane)
   end function lateral_offset

   !> The reference point's move from the first contact vertically (mm): y_shift sin γ_plane.
   pure real(wp) function vertical_offset(self) result(offset)
      class(normal_patch_type), intent(in) :: self
      offset = self%y_shift*sin(self%gamma_plane)
   end function vertical_offset

   !> Make the patch arrays hold n_strips entries, allocating only when the size changes.
   pure subroutine reserve_strips(patch, n_strips)
      !> The patch.
      type(normal_patch_type), intent(inout) :: patch
      !> Number of strips.
      integer, intent(in) :: n_strips
      patch%n_strips = n_strips
      if (allocated(patch%gamma_n)) then
         if (size(patch%gamma_n) /= n_strips) deallocate (patch%gamma_n)
      end if
      if (.not. allocated(patch%gamma_n)) allocate (patch%gamma_n(n_strips))
      if (allocated(patch%y)) then
         if (size(patch%y) == n_strips) return
         deallocate (patch%y, patch%a, patch%k, patch%p0, patch%strip_load, patch%m, patch%n, &
            patch%eps_a, patch%gamma, patch%delta_r, patch%r_wheel)
      end if
      allocate (patch%y(n_strips), patch%a(n_strips), patch%k(n_strips), patch%p0(n_strips), &
         patch%strip_load(n_strips), patch%m(n_strips), patch%n(n_strips), &
         patch%eps_a(n_strips), patch%gamma(n_strips), patch%delta_r(n_strips), &
         patch%r_wheel(n_strips))
   end subroutine reserve_strips

   !> A patch out of contact: zero strips (a_i = 0 carries no load), zero totals, and the
   !> reference-point data. Arrays must be reserved ([[reserve_strips]]).
   pure subroutine clear_strips(patch, gamma0, r0)
      !> The patch.
      type(normal_patch_type), intent(inout) :: patch
      !> Contact angle (rad) and rolling radius (mm) of the reference point.
      real(wp), intent(in) :: gamma0, r0
      call clear_totals(patch, gamma0, r0)
      call clear_arrays(patch, gamma0, r0)
   end subroutine clear_strips

   !> The scalars of a patch out of contact.
   pure subroutine clear_totals(patch, gamma0, r0)
      type(normal_patch_type), intent(inout) :: patch
      real(wp), intent(in) :: gamma0, r0
      patch%is_hertz = .false.
      patch%ellipse_a = 0.0_wp
      patch%ellipse_b = 0.0_wp
      patch%ellipse_y_centre = 0.0_wp
      patch%approach = 0.0_wp
      patch%approach_reference = 0.0_wp
      patch%load = 0.0_wp
      patch%area = 0.0_wp
      patch%p_max = 0.0_wp
      patch%dy = 0.0_wp
      patch%gamma0 = gamma0
      patch%r0 = r0
      patch%gamma_plane = gamma0
      patch%y_shift = 0.0_wp
   end subroutine clear_totals

   !> The strip arrays of a patch out of contact.
   pure subroutine clear_arrays(patch, gamma0, r0)
      type(normal_patch_type), intent(inout) :: patch
      real(wp), intent(in) :: gamma0, r0
      patch%y(:) = 0.0_wp
      patch%a(:) = 0.0_wp
      patch%k(:) = 0.0_wp
      patch%p0(:) = 0.0_wp
      patch%strip_load(:) = 0.0_wp
      patch%m(:) = 1.0_wp
      patch%n(:) = 1.0_wp
      patch%eps_a(:) = 0.5_wp
      patch%gamma(:) = gamma0
      patch%gamma_n(:) = gamma0
      patch%delta_r(:) = 0.0_wp
      patch%r_wheel(:) = r0
   end subroutine clear_arrays

   !> Load, area Σ 2a_i δy and peak pressure from the strips.
   pure subroutine strip_totals(patch)
      type(normal_patch_type), intent(inout) :: patch
      integer :: n
      n = patch%n_strips
      patch%load = sum(patch%strip_load(1:n))
      patch%area = 2.0_wp*sum(patch%a(1:n))*patch%dy
      patch%p_max = maxval(patch%p0(1:n))
   end subroutine strip_totals

end module shcontact_normal_patch
