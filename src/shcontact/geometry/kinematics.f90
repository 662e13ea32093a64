!> Wheelset kinematics (doc/theory.md decision 14, CONTACT's module 1): the wheelset's position and
!> velocities, and what its yaw angle does to the contact geometry.
!>
!> **Frames.** Track frame: x along the track (forward), y lateral towards the right field side,
!> z down, mm; the wheelset centre C is at (0, y_ws, z_C). The wheelset frame is the track frame
!> turned by the yaw angle ψ about z (then the roll angle about the wheelset's x); its axle
!> direction is a = (−sin ψ cos ρ, cos ψ cos ρ, sin ρ). Every case is solved as a right-side
!> case (shcontact_geometry_track): for the left wheel the state is mirrored y ↦ −y, which turns
!> y_ws, v_y, ψ, ρ, ψ̇ and ρ̇ into their negatives and leaves x, z, v_x, v_z and the pitch rate
!> (an angular velocity about the axle) as they are ([[side_state]]).
!>
!> **Yawed wheel on a straight rail (the contact locus).** A wheel profile point at axle
!> coordinate L (from the wheelset centre) with rolling radius r describes a circle; with the
!> wheelset yawed, the point of that circle nearest to a rail whose surface slope is t = dz/dy
!> lies at the angle θ from the bottom of the circle with
!>
!>     tan θ = −t sin ψ,   x = −L sin ψ + r sin θ cos ψ,
!>     y = y_C + L cos ψ + r sin θ sin ψ,   z = z_C + r cos θ.
!>
!> At a contact point the rail and the wheel have the same slope, so t is taken from the wheel
!> profile itself: every profile point becomes a point of an effective plane profile (Wang's
!> contact locus), on which the ordinary plane contact search runs ([[yawed_wheel_profile]]).
!> The contact point leads (x > 0) or lags by r sin θ against the wheel's own plane, −L sin ψ:
!> at the flange (t ≈ 2.6) and ψ = 4 mrad the lead is about 5 mm ([[contact_lead]]). The
!> effective profile lies r(1 − cos θ) higher than the unyawed one, so it is on the flange that
!> the yaw changes the gap (0.17 mm at 10 mrad and 70°); the rolling radius of the contact point
!> stays r, while the effective profile's height gives r cos θ ([[true_radius_scale]]).
module shcontact_geometry_kinematics
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_text, only: format_real
   use shcontact_core_ranges, only: check_value_range, variable_info_type, variables
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_spline, only: profile_spline_type, spline_point_type
   use shcontact_geometry_track, only: track_type, side_left
   implicit none
   private

   public :: wheelset_state_type, check_wheelset_state, side_state, pure_rolling_pitch_rate
   public :: yawed_wheel_profile, contact_lead, locus_tangent, true_radius_scale, &
      scale_to_true_radius, &
      axle_offset, max_yaw, &
      max_slope

   !> Largest |yaw angle| accepted (rad): far beyond the ~10 mrad of a wheelset in a curve.
   real(wp), parameter :: max_yaw = 0.1_wp
   !> The &kinematics entries of the variable table that [[check_wheelset_state]] checks on every
   !> call: v_forward, pitch_rate, v_lateral, v_vertical, roll_rate, yaw_rate.
   type(variable_info_type), parameter :: velocity_range(6) = [ &
      variables(findloc(variables%name, 'v_forward', 1, mask=variables%group == 'kinematics')), &
      variables(findloc(variables%name, 'pitch_rate', 1, mask=variables%group == 'kinematics')), &
      variables(findloc(variables%name, 'v_lateral', 1, mask=variables%group == 'kinematics')), &
      variables(findloc(variables%name, 'v_vertical', 1, mask=variables%group == 'kinematics')), &
      variables(findloc(variables%name, 'roll_rate', 1, mask=variables%group == 'kinematics')), &
      variables(findloc(variables%name, 'yaw_rate', 1, mask=variables%group == 'kinematics'))]
   !> Profile slopes |dz/dy| are limited to this (84°) in the contact locus, so that the
   !> near-vertical flange back, which never touches the rail, does not run off (tan θ stays
   !> ≤ max_slope·sin ψ).
   real(wp), parameter :: max_slope = 10.0_wp

   !> Position and velocities of a wheelset (CONTACT module 1 meaning, doc/theory.md decision 14).
   !> Track frame: x forward, y towards the right field side, z down; mm, mm/s, rad, rad/s.
   type :: wheelset_state_type
      !> Lateral shift of the wheelset (mm), CONTACT's Y_WS.
      real(wp) :: y_ws = 0.0_wp
      !> Yaw angle ψ about z (rad), CONTACT's YAW_WS: positive turns the front towards +y, so the
      !> right wheel moves back and the left one forward.
      real(wp) :: yaw = 0.0_wp
      !> Roll angle ρ about x (rad), CONTACT's ROLL: positive lowers the right wheel.
      real(wp) :: roll = 0.0_wp
      !> Forward speed of the wheelset centre V (mm/s, > 0), CONTACT's VS.
      real(wp) :: v_forward = 0.0_wp
      !> Lateral and vertical velocity of the wheelset centre (mm/s), CONTACT's VY_WS, VZ_WS.
      real(wp) :: v_lateral = 0.0_wp, v_vertical = 0.0_wp
      !> Roll and yaw rate (rad/s), CONTACT's VROLL, VYAW_WS.
      real(wp) :: roll_rate = 0.0_wp, yaw_rate = 0.0_wp
      !> Angular velocity of the wheelset about its axle (rad/s), CONTACT's VPITCH_WS: negative
      !> when rolling forward; pure rolling on the nominal radius is −V/r_nom
      !> ([[pure_rolling_pitch_rate]]).
      real(wp) :: pitch_rate = 0.0_wp
   end type wheelset_state_type

contains

   !> Reject a state with non-finite values, a speed ≤ 0, an implausible angle, or a wheel that
   !> does not roll forward.
   pure subroutine check_wheelset_state(state, error)
      !> The state.
      type(wheelset_state_type), intent(in) :: state
      !> Set on an invalid value, naming it.
      type(error_type), allocatable, intent(out) :: error

      if (.not. all(ieee_is_finite([state%y_ws, state%yaw, state%roll, state%v_forward, &
         state%v_lateral, state%v_vertical, state%roll_rate, state%yaw_rate, &
         state%pitch_rate]))) then
         call fatal_error(error, 'wheelset state (y_ws, yaw, roll, v_forward, v_lateral, '// &
            'v_vertical, roll_rate, yaw_rate, pitch_rate): expected finite numbers, found NaN '// &
            'or Inf', stat_invalid_input)
      else if (.not. (abs(state%yaw) <= max_yaw)) then
         call fatal_error(error, 'wheelset yaw = '//format_real(state%yaw)//' rad: expected '// &
            '|yaw| <= '//format_real(max_yaw)//' rad (a wheelset yaws by ~0.01 rad in a curve)', &
            stat_invalid_input)
      else if (.not. (state%v_forward > 0.0_wp)) then
         call fatal_error(error, 'wheelset forward speed v_forward = '// &
            format_real(state%v_forward)//' mm/s: expected a positive speed (creepages are '// &
            'velocities divided by the rolling speed)', stat_invalid_input)
      else if (.not. (state%pitch_rate < 0.0_wp)) then
         call fatal_error(error, 'wheelset pitch rate = '//format_real(state%pitch_rate)// &
            ' rad/s: expected a negative angular velocity about the axle (forward rolling; '// &
            'pure rolling is -v_forward/nominal_radius)', stat_invalid_input)
      end if
      if (allocated(error)) return
      ! The ranges of the case file's &kinematics (doc/app.md), on every path.
      call check_value_range(velocity_range(1), state%v_forward, 'wheelset forward speed', error)
      if (.not. allocated(error)) call check_value_range(velocity_range(2), state%pitch_rate, &
         'wheelset pitch rate', error)
      if (.not. allocated(error)) call check_value_range(velocity_range(3), state%v_lateral, &
         'wheelset lateral velocity', error)
      if (.not. allocated(error)) call check_value_range(velocity_range(4), state%v_vertical, &
         'wheelset vertical velocity', error)
      if (.not. allocated(error)) call check_value_range(velocity_range(5), state%roll_rate, &
         'wheelset roll rate', error)
      if (.not. allocated(error)) call check_value_range(velocity_range(6), state%yaw_rate, &
         'wheelset yaw rate', error)
   end subroutine check_wheelset_state

   !> The pitch rate of pure rolling on the nominal radius, −V/r_nom (rad/s).
   elemental real(wp) function pure_rolling_pitch_rate(v_forward, nominal_radius) result(rate)
      !> Forward speed (mm/s).
      real(wp), intent(in) :: v_forward
      !> Nominal rolling radius (mm).
      real(wp), intent(in) :: nominal_radius
      rate = -v_forward/nominal_radius
   end function pure_rolling_pitch_rate

   !> The state seen from the side frame of a wheel (mirrored for the left wheel, module text).
   elemental type(wheelset_state_type) function side_state(state, side) result(mirrored)
      !> The state in the track frame.
      type(wheelset_state_type), intent(in) :: state
      !> side_right or side_left.
      integer, intent(in) :: side
      mirrored = state
      if (side /= side_left) return
      mirrored%y_ws = -state%y_ws
      mirrored%yaw = -state%yaw
      mirrored%roll = -state%roll
      mirrored%v_lateral = -state%v_lateral
      mirrored%roll_rate = -state%roll_rate
      mirrored%yaw_rate = -state%yaw_rate
   end function side_state

   !> Axle coordinate of the wheel profile origin: L = y_w + axle_offset (mm).
   elemental real(wp) function axle_offset(track)
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      axle_offset = 0.5_wp*track%flange_back_distance - track%flange_back_position
   end function axle_offset

   !> tan θ of the contact locus for a surface slope t = dz/dy (side frame) and sin ψ of the side
   !> frame's yaw: tan θ = −t sin ψ, t limited to ±[[max_slope]].
   elemental real(wp) function locus_tangent(slope, sin_yaw) result(tan_theta)
      !> Surface slope t = dz/dy (tan γ).
      real(wp), intent(in) :: slope
      !> sin ψ.
      real(wp), intent(in) :: sin_yaw
      tan_theta = -max(-max_slope, min(max_slope, slope))*sin_yaw
   end function locus_tangent

   !> sin θ and cos θ of the contact locus ([[locus_tangent]]).
   elemental subroutine locus_angle(slope, sin_yaw, sin_theta, cos_theta)
      real(wp), intent(in) :: slope, sin_yaw
      real(wp), intent(out) :: sin_theta, cos_theta
      real(wp) :: tan_theta
      tan_theta = locus_tangent(slope, sin_yaw)
      cos_theta = 1.0_wp/sqrt(1.0_wp + tan_theta**2)
      sin_theta = tan_theta*cos_theta
   end subroutine locus_angle

   !> The effective plane wheel profile of a yawed wheelset (module text): each point of the
   !> wheel profile moved to its contact-locus point, in wheel profile coordinates (y towards the
   !> field side, z down, the wheelset unyawed), so that the plane contact search places and
   !> rolls it as usual. The slopes come from the fitted spline at the profile's points, and the
   !> effective profile keeps the spline's knots as its parameter.
   !> z_tape stays that of the unyawed wheel, so the table's rolling radius r_nom + z − z_tape
   !> is r cos θ ([[true_radius_scale]]).
   pure subroutine yawed_wheel_profile(wheel, spline, track, z_tape, yaw, yawed)
      !> The wheel profile as given (right-side canonical form).
      type(profile_type), intent(in) :: wheel
      !> Its spline (knots at the profile's points).
      type(profile_spline_type), intent(in) :: spline
      !> Track and wheelset dimensions (flange-back distance and position, nominal radius).
      type(track_type), intent(in) :: track
      !> Profile z of the tape circle (mm), where the rolling radius is r_nom.
      real(wp), intent(in) :: z_tape
      !> Yaw angle of the side frame (rad).
      real(wp), intent(in) :: yaw
      !> The effective profile (same points, moved).
      type(profile_type), intent(out) :: yawed
      type(spline_point_type) :: p
      real(wp) :: slope, r, axle, sin_t, cos_t, cy, sy
      integer :: i, n

      yawed = wheel
      n = spline%size()
      cy = cos(yaw)
      sy = sin(yaw)
      do i = 1, n
         p = spline%eval(spline%s(i), i)
         slope = p%dz/sign(max(abs(p%dy), abs(p%dz)/max_slope), p%dy)
         call locus_angle(slope, sy, sin_t, cos_t)
         r = track%nominal_radius + p%z - z_tape
         axle = p%y + axle_offset(track)
         yawed%y(i) = axle*cy + r*sin_t*sy - axle_offset(track)
         yawed%z(i) = p%z - r*(1.0_wp - cos_t)
      end do
      ! The knots of the unyawed spline: the fitted spline is then linear in the points, so that
      ! yawed splines can be interpolated between yaw angles (shcontact_geometry_yaw).
      yawed%s = spline%s
   end subroutine yawed_wheel_profile

   !> Longitudinal position (mm, track x, forward) of a contact point of the yawed wheelset:
   !> −L sin ψ + r sin θ cos ψ, for the point's axle coordinate L, rolling radius r and contact
   !> angle γ (side frame; the surface slope is tan γ).
   elemental real(wp) function contact_lead(axle, radius, gamma, yaw) result(x)
      !> Axle coordinate L of the point (mm, from the wheelset centre towards the field side).
      real(wp), intent(in) :: axle
      !> Rolling radius r (mm).
      real(wp), intent(in) :: radius
      !> Contact angle γ (rad, CONTACT's sign, side frame).
      real(wp), intent(in) :: gamma
      !> Yaw angle of the side frame (rad).
      real(wp), intent(in) :: yaw
      real(wp) :: sin_t, cos_t, sy
      sy = sin(yaw)
      call locus_angle(tan(gamma), sy, sin_t, cos_t)
      x = -axle*sy + radius*sin_t*cos(yaw)
   end function contact_lead

   !> 1/cos θ = √(1 + tan²θ), tan θ = −t sin ψ with t = tan γ limited as in the contact locus:
   !> the factor that turns the effective profile's rolling radius r cos θ into the true r. Takes
   !> sin ψ, computed once for a whole table.
   elemental real(wp) function true_radius_scale(gamma, sin_yaw) result(scale)
      !> Contact angle γ (rad, CONTACT's sign, side frame).
      real(wp), intent(in) :: gamma
      !> sin ψ of the side frame's yaw angle.
      real(wp), intent(in) :: sin_yaw
      scale = radius_scale_of_tan(tan(gamma), sin_yaw)
   end function true_radius_scale

   !> [[true_radius_scale]] from t = tan γ.
   elemental real(wp) function radius_scale_of_tan(tan_gamma, sin_yaw) result(scale)
      real(wp), intent(in) :: tan_gamma, sin_yaw
      real(wp) :: tan_t
      tan_t = locus_tangent(tan_gamma, sin_yaw)
      scale = sqrt(1.0_wp + tan_t*tan_t)
   end function radius_scale_of_tan

   !> radius(i) ← radius(i)·[[true_radius_scale]](γ_i, sin ψ) over a whole table, from the
   !> table's tan γ_i (patch_geometry_type's tan_gamma: no tangent per point).
   pure subroutine scale_to_true_radius(tan_gamma, sin_yaw, radius)
      !> tan γ_i of the table points.
      real(wp), intent(in) :: tan_gamma(:)
      !> sin ψ.
      real(wp), intent(in) :: sin_yaw
      !> Rolling radii r cos θ on entry, r on return (mm).
      real(wp), intent(inout) :: radius(:)
      integer :: i
      do i = 1, size(radius)
         radius(i) = radius(i)*radius_scale_of_tan(tan_gamma(i), sin_yaw)
      end do
   end subroutine scale_to_true_radius

end module shcontact_geometry_kinematics
