!> Creepages of a contact patch from the wheelset's rigid-body motion (doc/theory.md decision 14;
!> CONTACT module 1's definitions, so that the same kinematics give comparable creepages).
!>
!> The wheel is a rigid body turning with ω = Ω a + ψ̇ e_z + ρ̇ e_x about its centre C, which
!> moves with v_C = (V, v_y, v_z); the rail is at rest. At a contact point P (axle coordinate L,
!> rolling radius r, contact-locus angle θ of the yawed wheel, shcontact_geometry_kinematics),
!>
!>     r = P − C = R_z(ψ) R_x(ρ) (r sin θ, L, r cos θ),   s = v_C + ω × r,
!>
!> is the velocity of the wheel surface relative to the rail. The contact frame of a patch with
!> contact angle γ₀ has x along the track, the tangent t = (0, cos γ₀, sin γ₀) and the normal
!> n = (0, −sin γ₀, cos γ₀) into the rail (doc/theory.md §0). The rolling speed is CONTACT's: the
!> mean of the speeds at which the rail and the wheel surface pass through the contact point,
!> V_r = (V − (ω × r)_x)/2. Then (wheel relative to rail, doc/theory.md decision 2):
!>
!>     ν_x = s_x/V_r,   ν_y = s·t/V_r,   φ = ω·n/V_r.
!>
!> Pure rolling of a coned wheel gives ν_x = 2(1 − r/r_nom)/(1 + r/r_nom) and
!> φ = 2 sin γ₀/(r_nom + r) (the geometric spin); a yaw angle ψ gives ν_y ≈ −ψ/cos γ₀.
!>
!> **Strips.** FASTSIM_SH applies these creepages at the patch's reference point and carries
!> them to each strip with the 'additive' spin model (shcontact_tangential_spin): the strip's own
!> rolling radius (ν_x,i − ν_x = −δr_i/r₀ − (φ − φ_geo,0) y_i), its own contact angle
!> (ν_y,i = ν_y cos γ₀/cos γ_i, which is exactly how a yaw angle's −ψ/cos γ_i varies) and its own
!> spin (φ_i = φ + (sin γ_i − sin γ₀)/r₀). That is the rigid-body slip of every strip to first
!> order in the creepages and the strip's distance from the reference point, so the rigid slip
!> is continuous where the contact is, whichever point is the reference.
module shcontact_tangential_rigid_slip
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_strings, only: str_real
   use shcontact_core_ranges, only: check_range
   use shcontact_geometry_kinematics, only: wheelset_state_type, locus_tangent
   use shcontact_tangential_creepage, only: creepage_type
   implicit none
   private

   public :: contact_point_type, rigid_creepages

   !> A contact point on the wheel, in the side frame (shcontact_geometry_track).
   type :: contact_point_type
      !> Axle coordinate L (mm): lateral distance from the wheelset centre along the axle.
      real(wp) :: axle = 0.0_wp
      !> Rolling radius r (mm): distance from the axle.
      real(wp) :: radius = 0.0_wp
      !> Contact angle γ₀ (rad, CONTACT's sign).
      real(wp) :: gamma = 0.0_wp
   end type contact_point_type

contains

   !> The creepages at a contact point (module text) and the rolling speed V_r (mm/s).
   pure subroutine rigid_creepages(state, point, creepage, rolling_speed, error)
      !> The wheelset state in the side frame of the wheel (side_state).
      type(wheelset_state_type), intent(in) :: state
      !> The contact point.
      type(contact_point_type), intent(in) :: point
      !> ν_x, ν_y, φ (rad/mm) in the patch's contact frame, wheel relative to rail.
      type(creepage_type), intent(out) :: creepage
      !> Rolling speed V_r (mm/s).
      real(wp), intent(out) :: rolling_speed
      !> Set when the wheel does not roll (V_r ≤ 0).
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: omega(3), axle(3), r(3), slip(3), tangent(3), normal(3), b(3), w_r(3)
      real(wp) :: cy, sy, cr, sr, tan_t, cos_t, sin_t

      cy = cos(state%yaw); sy = sin(state%yaw)
      cr = cos(state%roll); sr = sin(state%roll)
      ! Contact-locus angle θ of the point (tan θ = −tan γ sin ψ).
      tan_t = locus_tangent(tan(point%gamma), sy)
      cos_t = 1.0_wp/sqrt(1.0_wp + tan_t**2)
      sin_t = tan_t*cos_t
      b = [point%radius*sin_t, point%axle, point%radius*cos_t]
      ! R_z(ψ) R_x(ρ) b.
      r = turn([b(1), b(2)*cr - b(3)*sr, b(2)*sr + b(3)*cr])
      axle = turn([0.0_wp, cr, sr])
      omega = state%pitch_rate*axle + [state%roll_rate, 0.0_wp, state%yaw_rate]
      w_r = cross(omega, r)
      slip = [state%v_forward, state%v_lateral, state%v_vertical] + w_r
      rolling_speed = 0.5_wp*(state%v_forward - w_r(1))
      if (.not. (rolling_speed > 0.0_wp)) then
         call fatal_error(error, 'wheelset kinematics: rolling speed '// &
            str_real(rolling_speed)//' mm/s at the contact point; expected a wheel rolling '// &
            'forward (v_forward > 0 and pitch_rate < 0)', stat_invalid_input)
         return
      end if
      tangent = [0.0_wp, cos(point%gamma), sin(point%gamma)]
      normal = [0.0_wp, -sin(point%gamma), cos(point%gamma)]
      creepage%nu_x = slip(1)/rolling_speed
      creepage%nu_y = dot_product(slip, tangent)/rolling_speed
      creepage%phi = dot_product(omega, normal)/rolling_speed
      ! The creepages a prescribed call accepts (the ranges table): velocities that make the
      ! wheel slide faster than it rolls are refused, not solved (only the failure reads the
      ! table, so the hot path compares numbers).
      if (.not. (abs(creepage%nu_x) <= 1.0_wp .and. abs(creepage%nu_y) <= 1.0_wp .and. &
                 abs(creepage%phi) <= 0.1_wp)) then
         call check_range('creepage%nu_x', creepage%nu_x, 'wheelset kinematics: the '// &
            'longitudinal creepage at the contact point', error)
         if (.not. allocated(error)) call check_range('creepage%nu_y', creepage%nu_y, &
            'wheelset kinematics: the lateral creepage at the contact point', error)
         if (.not. allocated(error)) call check_range('creepage%phi', creepage%phi, &
            'wheelset kinematics: the spin creepage (rad/mm) at the contact point', error)
         if (allocated(error)) error%message = error%message//' (from the wheelset '// &
            'velocities and rates: check their units, mm/s and rad/s, and the forward speed)'
      end if
   contains
      !> R_z(ψ) v.
      pure function turn(v) result(w)
         real(wp), intent(in) :: v(3)
         real(wp) :: w(3)
         w = [v(1)*cy - v(2)*sy, v(1)*sy + v(2)*cy, v(3)]
      end function turn
   end subroutine rigid_creepages

   !> u × v.
   pure function cross(u, v) result(w)
      real(wp), intent(in) :: u(3), v(3)
      real(wp) :: w(3)
      w = [u(2)*v(3) - u(3)*v(2), u(3)*v(1) - u(1)*v(3), u(1)*v(2) - u(2)*v(1)]
   end function cross

end module shcontact_tangential_rigid_slip
