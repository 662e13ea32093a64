!> Track and wheelset: where the rail and the wheel profiles sit in track coordinates
!> (doc/theory.md §5.2–5.3, project decision 13).
!>
!> Track coordinates: y lateral from the track centre line, z down, mm. Every case is solved as a
!> right-side case (CONTACT mirrors the problem, not the profiles, doc/theory.md §5.1): the "side
!> frame" is the track frame for the right wheel and its mirror image y ↦ −y for the left one,
!> so y in the side frame always points to the field side and both profiles are used as given
!> (right-side canonical form).
!>
!> * Rail: canted about its profile origin by the rail inclination (unless the profile is already
!>   canted), then shifted so that its gauge point (the point of the gauge face `gauge_height`
!>   below the rail top) lies at y = gauge/2 and its top at z = 0.
!> * Wheel: profile origin at y = y_c + flange_back_distance/2 − flange_back_position (so the
!>   flange back lies at y_c + flange_back_distance/2), z = 0, with the wheelset centre at
!>   y_c = ±y_ws (side frame), z = −nominal_radius; the wheelset roll turns the wheel about that
!>   centre. The contact search then lowers or lifts the wheel until the smallest gap is zero.
!> * Tape circle (where the rolling radius is nominal_radius): tape_circle_offset (70 mm, the
!>   EN 13715 measuring plane) from the flange back towards the field side, i.e. at
!>   y_w = flange_back_position + tape_circle_offset in wheel profile coordinates
!>   ([[tape_circle_position]]): y_w = 0 for S1002 (flange back at −70), 70 mm for a MiniProf
!>   wheel (origin at the flange back, flange_back_position = 0).
module shcontact_geometry_track
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_ranges, only: check_range, variables
   use shcontact_core_strings, only: str_format, format_length
   use shcontact_profile_spline, only: profile_spline_type
   use shcontact_geometry_rigid, only: rigid_map_type, rotation_about, translation
   implicit none
   private

   public :: track_type, wheelset_position_type, side_right, side_left
   public :: check_track, check_position, rail_placement, wheel_placement, tape_circle_position
   public :: real_text

   !> The right wheel and rail (track y > 0).
   integer, parameter :: side_right = 1
   !> The left wheel and rail (track y < 0), solved as the mirrored right-side case.
   integer, parameter :: side_left = -1

   !> Track and wheelset dimensions (defaults: the Manchester benchmark, doc/theory.md §5.2; those
   !> of the case file's `&track` are the variable table's, shcontact_core_ranges).
   type :: track_type
      !> Track gauge (mm), between the gauge points of the two rails.
      real(wp) :: gauge = variables(findloc(variables%name, 'gauge', 1, &
         mask=variables%group == 'track'))%default
      !> Depth of the gauge point below the rail top (mm).
      real(wp) :: gauge_height = variables(findloc(variables%name, 'gauge_height', 1, &
         mask=variables%group == 'track'))%default
      !> Rail inclination as a slope (1:40 = 0.025), towards the track centre.
      real(wp) :: rail_inclination = variables(findloc(variables%name, 'inclination', 1, &
         mask=variables%group == 'track'))%default
      !> The rail profile is already canted (the inclination is not applied again).
      logical :: rail_canted = .false.
      !> Distance between the flange backs of the two wheels (mm).
      real(wp) :: flange_back_distance = variables(findloc(variables%name, 'flange_back_distance', 1, &
         mask=variables%group == 'track'))%default
      !> Flange-back position in wheel profile coordinates (mm; S1002: −70).
      real(wp) :: flange_back_position = variables(findloc(variables%name, 'flange_back_position', 1, &
         mask=variables%group == 'track'))%default
      !> Nominal rolling radius at the tape circle (mm).
      real(wp) :: nominal_radius = variables(findloc(variables%name, 'nominal_radius', 1, &
         mask=variables%group == 'track'))%default
      !> Lateral distance from the flange back to the tape circle (mm; EN 13715: 70).
      real(wp) :: tape_circle_offset = 70.0_wp
   end type track_type

   !> Where the wheelset is, and which of its wheels is solved.
   type :: wheelset_position_type
      !> [[side_right]] (default) or [[side_left]].
      integer :: side = side_right
      !> Lateral shift of the wheelset (mm), CONTACT's Y_WS: positive moves the right wheel
      !> towards its field side and the left wheel towards the track centre.
      real(wp) :: y_ws = 0.0_wp
      !> Wheelset roll (rad) about the track x axis (x = y × z, forward): positive lowers the
      !> right wheel and lifts the left one.
      real(wp) :: roll = 0.0_wp
   end type wheelset_position_type

contains

   !> Reject track data that cannot describe a track, naming the value and the expected range.
   pure subroutine check_track(track, error)
      !> The track.
      type(track_type), intent(in) :: track
      !> Set on an invalid value.
      type(error_type), allocatable, intent(out) :: error

      ! The app's ranges (shcontact_core_ranges): one table for the app and the library.
      call check_range('track%gauge', track%gauge, 'track gauge', error)
      if (.not. allocated(error)) call check_range('track%gauge_height', track%gauge_height, &
         'gauge height', error)
      if (.not. allocated(error)) call check_range('track%inclination', &
         track%rail_inclination, 'rail inclination', error)
      if (.not. allocated(error)) call check_range('track%flange_back_distance', &
         track%flange_back_distance, 'flange-back distance', error)
      if (.not. allocated(error)) call check_range('track%flange_back_position', &
         track%flange_back_position, 'flange-back position', error)
      if (.not. allocated(error)) call check_range('track%nominal_radius', &
         track%nominal_radius, 'nominal wheel radius', error)
      if (allocated(error)) then
         return
      else if (.not. (track%tape_circle_offset > 0.0_wp .and. &
         track%tape_circle_offset < 1000.0_wp)) then
         call fatal_error(error, 'tape-circle offset = '//real_text(track%tape_circle_offset)// &
            ' mm: expected the positive distance from the flange back to the tape circle '// &
            '(EN 13715: 70)')
      end if
   end subroutine check_track

   !> Reject a wheelset position with an unknown side or non-finite values.
   pure subroutine check_position(position, error)
      !> The position.
      type(wheelset_position_type), intent(in) :: position
      !> Set on an invalid value.
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: buf

      if (position%side /= side_right .and. position%side /= side_left) then
         write (buf, '(i0)') position%side
         call fatal_error(error, 'wheel side = '//trim(buf)//': expected 1 (right) or -1 (left)')
      else if (.not. (abs(position%y_ws) < 1000.0_wp)) then
         call fatal_error(error, 'lateral wheelset shift y_ws = '//real_text(position%y_ws)// &
            ' mm: expected a finite shift of a few mm')
      else if (.not. (abs(position%roll) < 0.5_wp)) then
         call fatal_error(error, 'wheelset roll = '//real_text(position%roll)// &
            ' rad: expected a small angle (|roll| < 0.5 rad)')
      end if
   end subroutine check_position

   !> The map from rail profile coordinates to the side frame: cant about the profile origin
   !> (unless already canted; the field side rises, the head leans towards the track centre),
   !> then the gauge point to y = gauge/2 and the rail top to z = 0 (doc/theory.md §5.2–5.3).
   pure subroutine rail_placement(track, rail, map, error)
      !> Track dimensions.
      type(track_type), intent(in) :: track
      !> The rail profile.
      type(profile_spline_type), intent(in) :: rail
      !> Rail profile coordinates → side frame.
      type(rigid_map_type), intent(out) :: map
      !> Set when the rail has no gauge face down to the gauge point.
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: s_top, z_top, s_gauge, y_gauge, z_gauge
      logical :: found

      if (track%rail_canted) then
         map = translation(0.0_wp, 0.0_wp)
      else
         map = rotation_about(-atan(track%rail_inclination), 0.0_wp, 0.0_wp)
      end if
      call highest_point(rail, map, s_top, z_top)
      call gauge_point(rail, map, s_top, z_top + track%gauge_height, s_gauge, found)
      if (.not. found) then
         call fatal_error(error, 'rail profile: no gauge face reaches '// &
            real_text(track%gauge_height)//' mm below the rail top (the profile ends first); '// &
            'expected a rail head profile that includes the gauge face', stat_invalid_input)
         return
      end if
      block
         real(wp) :: yg, zg
         yg = rail%projection(s_gauge, 1.0_wp, 0.0_wp, rail%interval(s_gauge))
         zg = rail%projection(s_gauge, 0.0_wp, 1.0_wp, rail%interval(s_gauge))
         call map%point(yg, zg, y_gauge, z_gauge)
      end block
      map = map%then(translation(0.5_wp*track%gauge - y_gauge, -z_top))
   end subroutine rail_placement

   !> The map from wheel profile coordinates to the side frame for a wheel with its tape circle
   !> at the rail-top level (z = 0) before any roll; the contact search adds the vertical shift
   !> that makes the smallest gap zero.
   elemental type(rigid_map_type) function wheel_placement(track, position) result(map)
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      !> Wheelset position and side.
      type(wheelset_position_type), intent(in) :: position
      real(wp) :: y_centre

      ! Mirroring y ↦ −y turns Y_WS and the roll into their negatives for the left wheel.
      y_centre = position%side*position%y_ws
      map = translation(y_centre + 0.5_wp*track%flange_back_distance &
         - track%flange_back_position, 0.0_wp)
      map = map%then(rotation_about(position%side*position%roll, y_centre, &
         -track%nominal_radius))
   end function wheel_placement

   !> The tape circle's lateral position in wheel profile coordinates (mm):
   !> flange_back_position + tape_circle_offset (0 for S1002, 70 for a MiniProf wheel).
   elemental real(wp) function tape_circle_position(track) result(y_tape)
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      y_tape = track%flange_back_position + track%tape_circle_offset
   end function tape_circle_position

   !> The highest point (smallest z) of a mapped profile: the best knot, refined by golden-section
   !> search over its two neighbouring intervals.
   pure subroutine highest_point(spline, map, s_top, z_top)
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(out) :: s_top, z_top
      real(wp), parameter :: ratio = 0.6180339887498949_wp
      real(wp) :: a, b, x1, x2, f1, f2
      integer :: k, n, best, it

      n = spline%size()
      best = 1
      z_top = height(spline%s(1))
      do k = 2, n
         if (height(spline%s(k)) < z_top) then
            z_top = height(spline%s(k)); best = k
         end if
      end do
      a = spline%s(max(1, best - 1)); b = spline%s(min(n, best + 1))
      x1 = b - ratio*(b - a); x2 = a + ratio*(b - a)
      f1 = height(x1); f2 = height(x2)
      do it = 1, 80
         if (f1 < f2) then
            b = x2; x2 = x1; f2 = f1
            x1 = b - ratio*(b - a); f1 = height(x1)
         else
            a = x1; x1 = x2; f1 = f2
            x2 = a + ratio*(b - a); f2 = height(x2)
         end if
         if (b - a < 1.0e-10_wp) exit
      end do
      s_top = 0.5_wp*(a + b)
      if (height(s_top) < z_top) then
         z_top = height(s_top)
      else
         s_top = spline%s(best)
      end if
   contains
      !> z of the mapped profile at arc length s.
      pure real(wp) function height(s)
         real(wp), intent(in) :: s
         integer :: kk
         kk = spline%interval(s)
         height = map%s*spline%projection(s, 1.0_wp, 0.0_wp, kk) &
            + map%c*spline%projection(s, 0.0_wp, 1.0_wp, kk) + map%dz
      end function height
   end subroutine highest_point

   !> Walking from the top towards the start of the profile (the track-centre side of a rail),
   !> the first point where the mapped z reaches `level`.
   pure subroutine gauge_point(spline, map, s_top, level, s_gauge, found)
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: s_top, level
      real(wp), intent(out) :: s_gauge
      logical, intent(out) :: found
      real(wp) :: target
      integer :: k

      ! z = sin·y + cos·z + dz in the mapped frame: the profile projected on (sin, cos).
      target = level - map%dz
      found = .false.
      s_gauge = s_top
      do k = spline%interval(s_top), 1, -1
         if (spline%projection(spline%s(k), map%s, map%c, k) >= target) then
            s_gauge = spline%solve_in_interval(k, map%s, map%c, target, spline%s(k), &
               min(s_top, spline%s(k + 1)))
            found = .true.
            return
         end if
      end do
   end subroutine gauge_point

   !> A real value as short text for messages (six significant digits).
   !> (No deferred-length result: doc/performance.md, "Threads and strings".)
   pure function real_text(x) result(text)
      !> The value.
      real(wp), intent(in) :: x
      character(len=format_length(x, '(g0.6)')) :: text
      text = str_format(x, '(g0.6)')
   end function real_text

end module shcontact_geometry_track
