!> Profiles ready for the contact search (doc/theory.md §5.2–5.5): the contact options, the
!> smoothed profiles, the placed rail, the wheel's tape circle and dense samples of both
!> profiles ([[prepare_profiles]], or [[prepare_wheel]] to redo only the wheel). The search
!> itself is [[shcontact_geometry_contact]]'s `find_contact_patches`.
module shcontact_geometry_prepared
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_invalid_input
   use shcontact_core_ranges, only: check_range, variables
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_spline, only: profile_spline_type, spline_point_type, &
      source_name => profile_label
   use shcontact_geometry_rigid, only: rigid_map_type
   use shcontact_geometry_flange, only: steep_end_radius
   use shcontact_geometry_search, only: polyline_envelope
   use shcontact_geometry_track, only: track_type, check_track, rail_placement, &
      tape_circle_position, str => real_text
   implicit none
   private

   public :: contact_options_type, prepared_profiles_type, check_contact_options
   public :: prepare_profiles, prepare_wheel, sampling_grid_size, sample_boxes
   public :: sample_block, box_pad

   !> Wheel samples per block of [[prepared_profiles_type]]'s `wheel_box`.
   integer, parameter :: sample_block = 32
   !> Margin of the block boxes (mm): far above the round-off of the boxes and of the maps
   !> applied to them, so that a box always holds its samples.
   real(wp), parameter :: box_pad = 1.0e-6_wp

   !> Options of the contact search and the strip tables.
   type :: contact_options_type
      !> Smoothing length of the wheel and the rail profile (mm, doc/theory.md §5.5); 0
      !> interpolates (analytic profiles), 1–3 mm suits measured ones. Defaults: the variable
      !> table's `profiles%wheel_smoothing` and `rail_smoothing`.
      real(wp) :: l_filt_wheel = variables(findloc(variables%name, 'wheel_smoothing', 1, &
         mask=variables%group == 'profiles'))%default
      real(wp) :: l_filt_rail = variables(findloc(variables%name, 'rail_smoothing', 1, &
         mask=variables%group == 'profiles'))%default
      !> Spacing h of the strip tables (mm).
      real(wp) :: table_step = 0.025_wp
      !> The tables stop where the gap exceeds this (mm), or earlier at a maximum of the gap.
      real(wp) :: table_gap = 2.0_wp
      !> Smallest lateral relative curvature B (1/mm); concave gap curvature is clamped to it.
      real(wp) :: b_min = variables(findloc(variables%name, 'b_min', 1, &
         mask=variables%group == 'normal'))%default
      !> Candidates whose gap exceeds the smallest one by more than this are ignored (mm).
      real(wp) :: max_gap = 1.0_wp
      !> Two minima separated by a maximum less than this above the shallower one are one
      !> patch (mm).
      real(wp) :: merge_gap = 0.005_wp
      !> Spacing of the dense sampling used to find the candidates (mm).
      real(wp) :: sample_step = 0.05_wp
      !> A(y) with the fixed reference normal, cos γ₀/(2 r_w(y)), instead of the local cos γ(y).
      logical :: a_reference_normal = .false.
      !> Strip tables along the rail's arc length, gaps along each point's rail normal
      !> (conformal tables) instead of a plane through the first contact.
      logical :: conformal_tables = .false.
      !> Search with the original (slow) algorithms: every table point and every common-normal
      !> step solved from scratch by bracketing. For tests of the fast search, which gives the
      !> same patches and tables to round-off.
      logical :: reference_search = .false.
      !> Strip tables of a kinematic call (shcontact_api_solver's solve_kinematic) end where the
      !> approach at which a point touches under the vertical approach exceeds this (mm; a lower
      !> bound of it, shcontact_geometry_pair's table_reach: the gap on the tread, more towards a
      !> flange root), or earlier at each patch's own bound from the vertical load
      !> (shcontact_geometry_pair's load_reach), unless the contact comes within 1 % of that end,
      !> when the call is solved again with table_gap. Enough for the approach of a wheel load: on S1002/UIC60 at
      !> 64.7 kN at most 0.25 mm (the flange), 0.05–0.1 mm on the tread. A value ≥ table_gap
      !> makes the kinematic call use the full tables at once.
      real(wp) :: kinematic_table_gap = 0.25_wp
   end type contact_options_type

   !> Profiles ready for the contact search at any wheelset position.
   type :: prepared_profiles_type
      !> Track and wheelset dimensions.
      type(track_type) :: track
      !> Options.
      type(contact_options_type) :: options
      !> Smoothed profiles, in their own coordinates.
      type(profile_spline_type) :: wheel, rail
      !> Rail profile coordinates → side frame.
      type(rigid_map_type) :: rail_map
      !> Wheel profile y and z of the tape circle (mm).
      real(wp) :: y_tape = 0.0_wp, z_tape = 0.0_wp
      !> Rolling radius (mm) where the wheel flange's steepest part ends towards its tip
      !> (shcontact_geometry_flange; huge for a wheel without a flange): a contact beyond it
      !> is a flange-climbing one.
      real(wp) :: steep_end_radius = huge(1.0_wp)
      !> Dense samples of the wheel, profile coordinates (mm).
      real(wp), allocatable :: wheel_s(:), wheel_y(:), wheel_z(:)
      !> Bounds (y_min, y_max, z_min, z_max) of each block of [[sample_block]] consecutive
      !> wheel samples, with a margin (see [[sample_boxes]]): the search maps and envelopes
      !> only the blocks that can lie over the rail.
      real(wp), allocatable :: wheel_box(:, :)
      !> Dense samples of the rail, side frame (mm).
      real(wp), allocatable :: rail_s(:), rail_y(:), rail_z(:)
      !> Smallest and largest y of the rail samples (mm).
      real(wp) :: rail_y_min = 0.0_wp, rail_y_max = 0.0_wp
      !> The rail's envelope on the sampling grid that starts at its leftmost sample, the grid of
      !> every position where the wheel overlaps the whole rail head (see [[polyline_envelope]]).
      real(wp), allocatable :: rail_env(:), rail_env_s(:)
      logical, allocatable :: rail_env_covered(:)
      !> The strip tables end where a lower bound of the approach at which a point touches under
      !> a vertical approach, (g + g₀c)/(1 − c) for c < 0, exceeds table_gap (instead of the gap g
      !> itself): the kinematic call's first try.
      logical :: table_end_by_touch = .false.
      !> With table_end_by_touch: the vertical wheel load (N) and E* (MPa) from which each patch's
      !> table takes its own bound (shcontact_geometry_pair's load_reach); 0: table_gap.
      real(wp) :: reach_load = 0.0_wp, reach_modulus = 0.0_wp
   end type prepared_profiles_type

contains

   !> Reject options out of their meaningful range.
   pure subroutine check_contact_options(options, error)
      !> The options.
      type(contact_options_type), intent(in) :: options
      !> Set on an invalid value, naming it.
      type(error_type), allocatable, intent(out) :: error

      ! The app's ranges (shcontact_core_ranges) for the options the app also sets.
      call check_range('profiles%wheel_smoothing', options%l_filt_wheel, 'l_filt_wheel', error)
      if (.not. allocated(error)) call check_range('profiles%rail_smoothing', &
         options%l_filt_rail, 'l_filt_rail', error)
      if (.not. allocated(error)) call check_range('normal%b_min', options%b_min, 'b_min', error)
      if (allocated(error)) then
         return
      else if (.not. (options%table_step >= 1.0e-4_wp .and. options%table_step <= 1.0_wp)) then
         call fatal_error(error, 'table_step = '//str(options%table_step)// &
            ' mm: expected 1e-4 to 1 mm (0.02-0.05 recommended)')
      else if (.not. (options%sample_step >= 1.0e-3_wp .and. options%sample_step <= 1.0_wp)) then
         call fatal_error(error, 'sample_step = '//str(options%sample_step)// &
            ' mm: expected 1e-3 to 1 mm')
      else if (.not. (options%table_gap > 0.0_wp .and. options%table_gap <= 100.0_wp)) then
         call fatal_error(error, 'table_gap = '//str(options%table_gap)// &
            ' mm: expected a positive gap of a few mm')
      else if (.not. (options%kinematic_table_gap > 0.0_wp .and. &
         options%kinematic_table_gap <= 100.0_wp)) then
         call fatal_error(error, 'kinematic_table_gap = '//str(options%kinematic_table_gap)// &
            ' mm: expected a positive gap (0.1-1 mm)')
      else if (.not. (options%max_gap >= 0.0_wp .and. options%max_gap <= 100.0_wp)) then
         call fatal_error(error, 'max_gap = '//str(options%max_gap)//' mm: expected 0 to 100 mm')
      else if (.not. (options%merge_gap >= 0.0_wp .and. options%merge_gap <= 1.0_wp)) then
         call fatal_error(error, 'merge_gap = '//str(options%merge_gap)// &
            ' mm: expected 0 to 1 mm')
      end if
   end subroutine check_contact_options

   !> Smooth the profiles, place the rail and sample both profiles, once for all wheel
   !> positions.
   subroutine prepare_profiles(wheel, rail, track, options, prepared, error)
      !> Wheel and rail profiles (right-side canonical form, doc/theory.md §5.1).
      type(profile_type), intent(in) :: wheel, rail
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      !> Options.
      type(contact_options_type), intent(in) :: options
      !> The result.
      type(prepared_profiles_type), intent(out) :: prepared
      !> Set on invalid input.
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: u(:), v(:)
      integer :: n

      call check_track(track, error)
      if (allocated(error)) return
      call check_contact_options(options, error)
      if (allocated(error)) return
      call check_builtin_cant(rail, track, error)
      if (allocated(error)) return
      prepared%track = track
      prepared%options = options
      call prepared%rail%fit(rail, options%l_filt_rail, error)
      if (allocated(error)) return
      call rail_placement(track, prepared%rail, prepared%rail_map, error)
      if (allocated(error)) then
         call prefix_error(error, source_name(rail))
         return
      end if
      call prepare_wheel(wheel, track, options, prepared, error)
      if (allocated(error)) return
      prepared%steep_end_radius = steep_end_radius(wheel, prepared%y_tape, prepared%z_tape, &
         track%nominal_radius)
      call sample_spline(prepared%rail, options%sample_step, prepared%rail_s, u, v)
      allocate (prepared%rail_y(size(u)), prepared%rail_z(size(u)))
      call prepared%rail_map%point(u, v, prepared%rail_y, prepared%rail_z)
      prepared%rail_y_min = minval(prepared%rail_y)
      prepared%rail_y_max = maxval(prepared%rail_y)
      n = sampling_grid_size(prepared)
      allocate (prepared%rail_env(n), prepared%rail_env_s(n), prepared%rail_env_covered(n))
      call polyline_envelope(prepared%rail_y, prepared%rail_z, prepared%rail_s, &
         minval(prepared%rail_y), options%sample_step, .false., prepared%rail_env, &
         prepared%rail_env_s, prepared%rail_env_covered)
   end subroutine prepare_profiles

   !> The built-in canted rail is canted by its name: with a track that cants the rail again (an
   !> inclination and rail_canted false) the head would lean 1:20, silently. Refused, saying
   !> what to set (a measured or other file gets the app's profile note instead, which looks
   !> at the head's shape).
   pure subroutine check_builtin_cant(rail, track, error)
      type(profile_type), intent(in) :: rail
      type(track_type), intent(in) :: track
      type(error_type), allocatable, intent(out) :: error
      if (.not. allocated(rail%source)) return
      if (rail%source /= 'builtin:UIC60-canted') return
      if (track%rail_canted .or. track%rail_inclination == 0.0_wp) return
      call fatal_error(error, "rail 'builtin:UIC60-canted' is the UIC60 head canted 1:40 "// &
         'already, and the track cants the rail by its inclination again: set the track''s '// &
         "rail_canted (&track rail_canted = .true.; shcontact_set_track's rail_canted = 1), or "// &
         "take 'builtin:UIC60'", stat_invalid_input)
   end subroutine check_builtin_cant

   !> Fit and sample only the wheel of already prepared profiles (the rail, its placement and
   !> its samples stay): the wheel spline, the tape-circle point (y_tape, z_tape) and the dense
   !> wheel samples. [[prepare_profiles]] calls it; a caller that changes the wheel profile (e.g.
   !> its section for yaw) calls it again. `track` and `options` must be those the profiles were
   !> prepared with (only the wheel's smoothing, the sampling step and the tape circle are used).
   subroutine prepare_wheel(wheel, track, options, prepared, error)
      !> Wheel profile (right-side canonical form, doc/theory.md §5.1).
      type(profile_type), intent(in) :: wheel
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      !> Options.
      type(contact_options_type), intent(in) :: options
      !> The prepared profiles; the wheel part is replaced.
      type(prepared_profiles_type), intent(inout) :: prepared
      !> Set on invalid input (the wheel part is then undefined).
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: s0
      logical :: found
      type(spline_point_type) :: p

      call check_track(track, error)
      if (allocated(error)) return
      call check_contact_options(options, error)
      if (allocated(error)) return
      call prepared%wheel%fit(wheel, options%l_filt_wheel, error)
      if (allocated(error)) return
      prepared%y_tape = tape_circle_position(track)
      call prepared%wheel%locate_y(prepared%y_tape, s0, found)
      if (.not. found) then
         call fatal_error(error, source_name(wheel)//': the wheel profile does not cross its '// &
            'tape circle y = '//str(prepared%y_tape)//' mm (flange_back_position '// &
            str(track%flange_back_position)//' + tape_circle_offset '// &
            str(track%tape_circle_offset)//' mm); expected the flange back at y = -70 mm for '// &
            'an origin on the tape circle (S1002), at y = 0 for a MiniProf wheel', &
            stat_invalid_input)
         return
      end if
      p = prepared%wheel%eval(s0)
      prepared%z_tape = p%z
      call sample_spline(prepared%wheel, options%sample_step, prepared%wheel_s, &
         prepared%wheel_y, prepared%wheel_z)
      if (allocated(prepared%wheel_box)) deallocate (prepared%wheel_box)
      allocate (prepared%wheel_box(4, (size(prepared%wheel_y) + sample_block - 1)/sample_block))
      call sample_boxes(prepared%wheel_y, prepared%wheel_z, prepared%wheel_box)
   end subroutine prepare_wheel

   !> The bounds (y_min, y_max, z_min, z_max) of each block of [[sample_block]] consecutive
   !> samples, widened by [[box_pad]].
   pure subroutine sample_boxes(y, z, box)
      !> Samples (mm).
      real(wp), intent(in) :: y(:), z(:)
      !> Bounds per block (mm); size(box, 2) = ⌈size(y)/sample_block⌉.
      real(wp), intent(out) :: box(:, :)
      integer :: b, i1, i2

      do b = 1, size(box, 2)
         i1 = (b - 1)*sample_block + 1
         i2 = min(size(y), b*sample_block)
         box(1, b) = minval(y(i1:i2)) - box_pad
         box(2, b) = maxval(y(i1:i2)) + box_pad
         box(3, b) = minval(z(i1:i2)) - box_pad
         box(4, b) = maxval(z(i1:i2)) + box_pad
      end do
   end subroutine sample_boxes

   !> Points of a sampling grid over the rail's whole width (the overlap with the wheel is never
   !> wider).
   pure integer function sampling_grid_size(prepared)
      type(prepared_profiles_type), intent(in) :: prepared
      sampling_grid_size = int((prepared%rail_y_max - prepared%rail_y_min)/ &
         prepared%options%sample_step) + 1
   end function sampling_grid_size

   !> Sample a spline at all knots and between them at spacing ≤ step.
   pure subroutine sample_spline(spline, step, s, y, z)
      type(profile_spline_type), intent(in) :: spline
      real(wp), intent(in) :: step
      real(wp), allocatable, intent(out) :: s(:), y(:), z(:)
      type(spline_point_type) :: p
      integer :: k, i, m, n, nsub(spline%size() - 1)

      n = spline%size()
      nsub = max(1, ceiling((spline%s(2:n) - spline%s(1:n - 1))/step))
      m = sum(nsub) + 1
      allocate (s(m), y(m), z(m))
      m = 0
      do k = 1, n - 1
         do i = 0, nsub(k) - 1
            m = m + 1
            s(m) = spline%s(k) + i*(spline%s(k + 1) - spline%s(k))/nsub(k)
            p = spline%eval(s(m), k)
            y(m) = p%y; z(m) = p%z
         end do
      end do
      p = spline%eval(spline%s(n))
      s(m + 1) = p%s; y(m + 1) = p%y; z(m + 1) = p%z
   end subroutine sample_spline

end module shcontact_geometry_prepared
