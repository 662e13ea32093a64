!> Tests of the wheel–rail geometry (doc/theory.md §4.1, §5.2–5.4): rail placement, contact search
!> and strip tables on analytic profiles with exactly known gaps and curvatures.
module test_geometry
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_strings, only: str_real
   use shcontact_core_error, only: lib_error => error_type, stat_no_contact, stat_invalid_input
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_spline, only: profile_spline_type
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_geometry_rigid, only: rigid_map_type, to_frame
   use shcontact_geometry_curve, only: frame_point_type, frame_point, walk_to_eta, &
      frame_walk_type, start_walk, walk_points
   use shcontact_geometry_track, only: track_type, wheelset_position_type, side_left, &
      rail_placement
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      prepare_profiles, find_contact_patches, positioned_profiles, write_geometry_table, &
      contact_patches_type, extract_patch, prepare_wheel
   use shcontact_geometry_patch, only: patch_geometry_type, geometry_sample_type
   use shcontact_geometry_prepared, only: sample_block
   use shcontact_geometry_yaw, only: yaw_table_type, build_yaw_table, apply_yaw
   use test_external_data, only: external_file
   implicit none
   private
   public :: collect_geometry
   ! Analytic profiles shared with the wheelset suite (test_wheelset_geometry).
   public :: arc_rail, cone_wheel, upright_track

   !> Nominal rolling radius used by the analytic cases (mm).
   real(wp), parameter :: r_nom = 460.0_wp
   !> External data (SHCONTACT_EXTERNAL_DATA, test_external_data): sample profiles and
   !> CONTACT's reference results.
   character(len=*), parameter :: mbench_wheel = 'profiles/MBench_S1002_v3.prw', &
      mbench_rail = 'profiles/MBench_UIC60_v3.prr', &
      ty0_summary = 'reference/ty0_literal/summary.csv'
   !> Environment variable naming a file for the Manchester scan table (doc/geometry.md).
   character(len=*), parameter :: scan_file_variable = 'SHCONTACT_GEOMETRY_SCAN'

   ! Tolerances: the analytic profiles are sampled every 0.1–0.2 mm and interpolated by cubic
   ! splines, which reproduce circles to O(h⁴/R³) in position and O((h/R)²) in curvature. Angles
   ! and gaps are checked to 1e-8 (rad, mm), curvatures to 1e-4 relative; where the rail is placed
   ! by the gauge point of a sampled arc (circle on circle), positions to 1e-6 mm and gaps to
   ! 1e-7 mm.

contains

   subroutine collect_geometry(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('rail_gauge_point_placement', test_rail_placement), &
         new_unittest('rail_cant_applied', test_rail_cant), &
         new_unittest('cant_equals_precanted_rail', test_cant_equivalence), &
         new_unittest('circle_on_plane', test_circle_on_plane), &
         new_unittest('circle_on_circle', test_circle_on_circle), &
         new_unittest('conformal_table_circle_on_circle', test_conformal_circles), &
         new_unittest('cone_on_cylinder', test_cone_on_cylinder), &
         new_unittest('roll_about_wheelset_centre', test_roll), &
         new_unittest('left_wheel_mirrors_right', test_left_mirror), &
         new_unittest('two_patches_found', test_two_patches), &
         new_unittest('negligible_maximum_merges', test_merge), &
         new_unittest('a_with_reference_normal', test_a_reference_normal), &
         new_unittest('rail_without_gauge_face', test_no_gauge_face), &
         new_unittest('wheel_without_origin', test_wheel_without_origin), &
         new_unittest('tape_circle_from_flange_back', test_tape_circle), &
         new_unittest('miniprof_wheel_rolling_radius', test_miniprof_wheel), &
         new_unittest('no_overlap_is_no_contact', test_no_overlap), &
         new_unittest('geometry_table_written', test_write_table), &
         new_unittest('manchester_rail_position', test_manchester_rail), &
         new_unittest('manchester_ty0_geometric_point', test_manchester_ty0), &
         new_unittest('manchester_two_patches_ty5', test_manchester_two_patches), &
         new_unittest('manchester_scan_0_to_10', test_manchester_scan), &
         new_unittest('builtin_profiles_as_manchester', test_builtin_as_manchester), &
         new_unittest('reused_patch_storage', test_reused_storage), &
         new_unittest('fast_search_equals_reference_builtin', test_fast_builtin), &
         new_unittest('fast_search_equals_reference_manchester', test_fast_manchester), &
         new_unittest('prepare_wheel_equals_prepare_profiles', test_prepare_wheel), &
         new_unittest('walk_points_equals_pointwise_walk', test_walk_points), &
         new_unittest('fast_search_equals_reference_fine_scan', test_fast_fine_scan), &
         new_unittest('fast_search_equals_reference_yawed', test_fast_yawed), &
         new_unittest('fast_search_equals_reference_rolled', test_fast_rolled) &
         ]
   end subroutine collect_geometry

   ! ---------------------------------------------------------------- analytic profiles

   !> A rail head as a circular arc of radius r (centre below the origin, top at the origin),
   !> from angle phi1 to phi2 (rad, from the top, positive towards the field side).
   function arc_rail(r, phi1, phi2, n) result(prof)
      real(wp), intent(in) :: r, phi1, phi2
      integer, intent(in) :: n
      type(profile_type) :: prof
      real(wp) :: phi
      integer :: i
      allocate (prof%y(n), prof%z(n))
      do i = 1, n
         phi = phi1 + (phi2 - phi1)*(i - 1)/(n - 1)
         prof%y(i) = r*sin(phi)
         prof%z(i) = r*(1.0_wp - cos(phi))
      end do
      prof%kind = profile_kind_rail
      prof%source = 'arc rail'
      call prof%update_arc_length()
   end function arc_rail

   !> A flat-topped rail: a vertical gauge face 20 mm deep at y = −30, then a flat top to y = 30,
   !> the corner kept as a kink.
   function flat_rail() result(prof)
      type(profile_type) :: prof
      integer :: i
      prof%y = [(-30.0_wp, i=1, 20), (-30.0_wp + 0.5_wp*i, i=1, 120)]
      prof%z = [(20.0_wp - i, i=0, 19), (0.0_wp, i=1, 120)]
      allocate (prof%kink(size(prof%y)), source=.false.)
      prof%kink(20) = .true.
      prof%kind = profile_kind_rail
      prof%source = 'flat rail'
      call prof%update_arc_length()
   end function flat_rail

   !> A wheel whose profile is a circle of radius r, lowest point at the origin, |y| ≤ half_width,
   !> points from the field side (+y) to the flange side.
   function circle_wheel(r, half_width, n) result(prof)
      real(wp), intent(in) :: r, half_width
      integer, intent(in) :: n
      type(profile_type) :: prof
      integer :: i
      prof%y = [(half_width - 2.0_wp*half_width*(i - 1)/(n - 1), i=1, n)]
      prof%z = -r + sqrt(r**2 - prof%y**2)
      prof%kind = profile_kind_wheel
      prof%source = 'circle wheel'
      call prof%update_arc_length()
   end function circle_wheel

   !> A conical wheel: the straight line z = y·tan(alpha), |y| ≤ half_width.
   function cone_wheel(alpha, half_width, n) result(prof)
      real(wp), intent(in) :: alpha, half_width
      integer, intent(in) :: n
      type(profile_type) :: prof
      integer :: i
      prof%y = [(half_width - 2.0_wp*half_width*(i - 1)/(n - 1), i=1, n)]
      prof%z = prof%y*tan(alpha)
      prof%kind = profile_kind_wheel
      prof%source = 'cone wheel'
      call prof%update_arc_length()
   end function cone_wheel

   !> A pre-canted track (no inclination applied) with the default dimensions.
   pure type(track_type) function upright_track() result(track)
      track%rail_canted = .true.
      track%nominal_radius = r_nom
   end function upright_track

   !> Find the patches, turning a library error into a test failure.
   subroutine patches_for(wheel, rail, track, position, patches, error, options)
      type(profile_type), intent(in) :: wheel, rail
      type(track_type), intent(in) :: track
      type(wheelset_position_type), intent(in) :: position
      type(patch_geometry_type), allocatable, intent(out) :: patches(:)
      type(error_type), allocatable, intent(out) :: error
      type(contact_options_type), intent(in), optional :: options
      type(contact_options_type) :: opts
      type(lib_error), allocatable :: err
      if (present(options)) opts = options
      call find_contact_patches(wheel, rail, track, position, opts, patches, err)
      if (allocated(err)) call test_failed(error, 'find_contact_patches: '//err%message)
   end subroutine patches_for

   ! ---------------------------------------------------------------- placement

   !> Arc rail R = 20 (pre-canted): the gauge point 14 mm below the top, at sin φ = −√(1 − 0.3²)
   !> of the arc, goes to y = 717.5; the top goes to z = 0.
   subroutine test_rail_placement(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_spline_type) :: sp
      type(rigid_map_type) :: map
      type(lib_error), allocatable :: err
      real(wp) :: y, z

      call sp%fit(arc_rail(20.0_wp, -1.6_wp, 1.4_wp, 301), 0.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call rail_placement(upright_track(), sp, map, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call map%point(0.0_wp, 0.0_wp, y, z)
      call check(error, y, 717.5_wp + 20.0_wp*sqrt(1.0_wp - 0.3_wp**2), thr=1.0e-8_wp, &
         message='rail origin lateral position')
      if (allocated(error)) return
      call check(error, z, 0.0_wp, thr=1.0e-10_wp, message='rail top at z = 0')
   end subroutine test_rail_placement

   !> An upright arc rail canted 1:40: the highest point moves to the field side, to the arc
   !> angle atan(1/40), and the whole profile turns by −atan(1/40) about its origin.
   subroutine test_rail_cant(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_spline_type) :: sp
      type(rigid_map_type) :: map
      type(track_type) :: track
      type(lib_error), allocatable :: err
      real(wp), parameter :: r = 20.0_wp
      real(wp) :: y0, z0, y1, z1, cant, depth

      call sp%fit(arc_rail(r, -1.6_wp, 1.4_wp, 301), 0.0_wp, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call rail_placement(track, sp, map, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      cant = atan(1.0_wp/40.0_wp)
      call check(error, map%angle, -cant, thr=1.0e-14_wp, message='cant angle')
      if (allocated(error)) return
      ! The circle's centre (0, r) maps to (y_c, z_c); the top of the canted circle is r above
      ! it, and the gauge point 14 mm lower lies at y = 717.5.
      call map%point(0.0_wp, r, y0, z0)
      call check(error, z0, r, thr=1.0e-9_wp, message='canted top at z = 0')
      if (allocated(error)) return
      depth = r - 14.0_wp
      call check(error, y0 - sqrt(r**2 - depth**2), 717.5_wp, thr=1.0e-8_wp, &
         message='gauge point at 717.5')
      if (allocated(error)) return
      ! The profile origin was the old top: on the canted circle at angle −cant from the top.
      call map%point(0.0_wp, 0.0_wp, y1, z1)
      call check(error, y1 - y0, -r*sin(cant), thr=1.0e-9_wp, message='old top position')
   end subroutine test_rail_cant

   !> An upright rail canted by the track gives the same patch as the same rail turned 1:40 in
   !> the test and declared already canted (the origins differ only by the turn about the
   !> profile origin, which both keep).
   subroutine test_cant_equivalence(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: upright(:), canted(:)
      type(wheelset_position_type) :: position
      type(profile_type) :: rail, turned
      type(track_type) :: track
      real(wp) :: c, s
      real(wp), allocatable :: ry1(:), rz1(:), ry2(:), rz2(:)

      rail = arc_rail(40.0_wp, -1.2_wp, 1.0_wp, 401)
      turned = rail
      c = cos(atan(1.0_wp/40.0_wp)); s = -sin(atan(1.0_wp/40.0_wp))
      turned%y = c*rail%y - s*rail%z
      turned%z = s*rail%y + c*rail%z
      position%y_ws = 2.0_wp
      call patches_for(circle_wheel(60.0_wp, 30.0_wp, 601), rail, track, position, upright, &
         error)
      if (allocated(error)) return
      call patches_for(circle_wheel(60.0_wp, 30.0_wp, 601), turned, upright_track(), position, &
         canted, error)
      if (allocated(error)) return
      call check(error, upright(1)%y_track, canted(1)%y_track, thr=1.0e-9_wp, message='y_track')
      if (allocated(error)) return
      call check(error, upright(1)%z_track, canted(1)%z_track, thr=1.0e-9_wp, message='z_track')
      if (allocated(error)) return
      call check(error, upright(1)%gamma0, canted(1)%gamma0, thr=1.0e-11_wp, message='gamma0')
      if (allocated(error)) return
      call check(error, upright(1)%y_wheel, canted(1)%y_wheel, thr=1.0e-9_wp, message='y_wheel')
      if (allocated(error)) return
      ! The placed rails coincide point by point.
      call placed_rail(rail, track, ry1, rz1, error)
      if (allocated(error)) return
      call placed_rail(turned, upright_track(), ry2, rz2, error)
      if (allocated(error)) return
      call check(error, maxval(abs(ry1 - ry2)) + maxval(abs(rz1 - rz2)), 0.0_wp, &
         thr=1.0e-9_wp, message='placed rail profiles')
   end subroutine test_cant_equivalence

   !> The rail polyline in track coordinates, as positioned for plotting.
   subroutine placed_rail(rail, track, ry, rz, error)
      type(profile_type), intent(in) :: rail
      type(track_type), intent(in) :: track
      real(wp), allocatable, intent(out) :: ry(:), rz(:)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      type(lib_error), allocatable :: err
      real(wp), allocatable :: wy(:), wz(:)
      call prepare_profiles(circle_wheel(60.0_wp, 30.0_wp, 601), rail, track, &
         contact_options_type(), prep, err)
      if (.not. allocated(err)) call positioned_profiles(prep, wheelset_position_type(), ry, rz, &
         wy, wz, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine placed_rail

   ! ---------------------------------------------------------------- analytic contact

   !> A wheel whose profile is a circle (R = 50) on a flat rail: contact at the wheel's lowest
   !> point, γ₀ = 0, gap exactly R − √(R² − y²), B = ½ g'' = R²/(2 (R² − y²)^{3/2}) (1/(2R) at
   !> the reference point), γ(y) = −asin(y/R), r_w = r_nom − R + √(R² − y²).
   subroutine test_circle_on_plane(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      real(wp), parameter :: r = 50.0_wp
      real(wp) :: y
      integer :: i

      position%y_ws = 3.0_wp
      call patches_for(circle_wheel(r, 20.0_wp, 401), flat_rail(), upright_track(), position, &
         patches, error)
      if (allocated(error)) return
      call check(error, size(patches), 1, message='one patch')
      if (allocated(error)) return
      associate (p => patches(1))
         call check(error, p%y_track, 753.0_wp, thr=1.0e-8_wp, message='y_track')
         if (allocated(error)) return
         call check(error, p%y_wheel, 0.0_wp, thr=1.0e-8_wp, message='y_wheel')
         if (allocated(error)) return
         call check(error, p%gamma0, 0.0_wp, thr=1.0e-10_wp, message='gamma0')
         if (allocated(error)) return
         call check(error, p%gap0, 0.0_wp, thr=1.0e-9_wp, message='gap0')
         if (allocated(error)) return
         call check(error, p%r0, r_nom, thr=1.0e-9_wp, message='r0')
         if (allocated(error)) return
         call check(error, p%curv_b(minloc(abs(p%y), 1)), 0.5_wp/r, rel=.true., thr=1.0e-5_wp, &
            message='B(0) = 1/(2R)')
         if (allocated(error)) return
         ! The table reaches the gap limit (2 mm) on both sides.
         call check(error, p%gap(1) >= 2.0_wp .and. p%gap(p%size()) >= 2.0_wp, &
            message='table spans the basin up to table_gap')
         if (allocated(error)) return
         do i = 1, p%size(), 37
            y = p%y(i)
            call check(error, p%gap(i), r - sqrt(r**2 - y**2), thr=1.0e-8_wp, message='gap')
            if (allocated(error)) return
            call check(error, p%curv_b(i), 0.5_wp*r**2/(r**2 - y**2)**1.5_wp, rel=.true., &
               thr=1.0e-4_wp, message='B(y)')
            if (allocated(error)) return
            call check(error, p%gamma(i), -asin(y/r), thr=1.0e-8_wp, message='gamma(y)')
            if (allocated(error)) return
            call check(error, p%r_wheel(i), r_nom - r + sqrt(r**2 - y**2), thr=1.0e-8_wp, &
               message='r_w(y)')
            if (allocated(error)) return
            call check(error, p%curv_a(i), cos(p%gamma(i))/(2*p%r_wheel(i)), rel=.true., &
               thr=1.0e-12_wp, message='A(y)')
            if (allocated(error)) return
         end do
      end associate
   end subroutine test_circle_on_plane

   !> A circular wheel (R₁ = 60) on a circular rail head (R₂ = 20) beside its top: the common
   !> normal is the line of the centres, sin γ₀ = Δy/(R₁ + R₂), and in the contact frame the gap
   !> is exactly (R₁ − √(R₁² − y²)) + (R₂ − √(R₂² − y²)), B(0) = (1/R₁ + 1/R₂)/2.
   subroutine test_circle_on_circle(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      real(wp), parameter :: r1 = 60.0_wp, r2 = 20.0_wp
      real(wp) :: y, y_rail_origin, gamma0, g
      integer :: i

      position%y_ws = 1.0_wp
      call patches_for(circle_wheel(r1, 30.0_wp, 601), arc_rail(r2, -1.6_wp, 1.4_wp, 351), &
         upright_track(), position, patches, error)
      if (allocated(error)) return
      call check(error, size(patches), 1, message='one patch')
      if (allocated(error)) return
      y_rail_origin = 717.5_wp + r2*sqrt(1.0_wp - 0.3_wp**2)
      gamma0 = asin((750.0_wp + position%y_ws - y_rail_origin)/(r1 + r2))
      associate (p => patches(1))
         call check(error, p%gamma0, gamma0, thr=1.0e-8_wp, message='gamma0')
         if (allocated(error)) return
         call check(error, p%y_rail, r2*sin(gamma0), thr=1.0e-6_wp, message='y_rail')
         if (allocated(error)) return
         call check(error, p%y_wheel, -r1*sin(gamma0), thr=1.0e-6_wp, message='y_wheel')
         if (allocated(error)) return
         call check(error, p%y_track, y_rail_origin + r2*sin(gamma0), thr=1.0e-6_wp, &
            message='y_track')
         if (allocated(error)) return
         call check(error, p%z_track, r2*(1.0_wp - cos(gamma0)), thr=1.0e-6_wp, &
            message='z_track')
         if (allocated(error)) return
         call check(error, p%r0, r_nom - r1*(1.0_wp - cos(gamma0)), thr=1.0e-6_wp, message='r0')
         if (allocated(error)) return
         call check(error, p%curv_b(minloc(abs(p%y), 1)), 0.5_wp*(1/r1 + 1/r2), rel=.true., &
            thr=1.0e-5_wp, message='B(0)')
         if (allocated(error)) return
         do i = 1, p%size(), 23
            y = p%y(i)
            g = (r1 - sqrt(r1**2 - y**2)) + (r2 - sqrt(r2**2 - y**2))
            call check(error, p%gap(i), g, thr=1.0e-7_wp, message='gap')
            if (allocated(error)) return
            call check(error, p%gamma(i), gamma0 - asin(y/r1), thr=1.0e-7_wp, message='gamma(y)')
            if (allocated(error)) return
            call check(error, p%r_wheel(i), r_nom - r1*(1.0_wp - cos(p%gamma(i))), &
               thr=1.0e-6_wp, message='r_w(y)')
            if (allocated(error)) return
         end do
      end associate
   end subroutine test_circle_on_circle

   !> The conformal strip tables (`&normal strip_tables = 'conformal'`) of the circles of
   !> [[test_circle_on_circle]]: y is the rail's arc length s from the contact point, and the gap
   !> is measured along the rail's normal there, which passes through the rail circle's centre at
   !> the angle φ = s/r₂ from the line of centres (distance D = r₁ + r₂ + g₀): the wheel circle
   !> lies at t = D cos φ − √(r₁² − D² sin² φ) from the rail's centre, so g(s) = t − r₂ − g₀
   !> (within 0.5 mm of gap; the planar table's differs by more than 1e-3 mm). B(0) is
   !> (1/r₁ + 1/r₂)/2 as in the plane, and the wheel's angle at the point on the normal is γ₀
   !> less the turn of the wheel circle's radius to that point.
   subroutine test_conformal_circles(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:), planar(:)
      type(wheelset_position_type) :: position
      real(wp), parameter :: r1 = 60.0_wp, r2 = 20.0_wp
      real(wp) :: phi, d, t, g, most, wy, wz, gamma_w
      type(geometry_sample_type) :: sample
      integer :: i

      position%y_ws = 1.0_wp
      call patches_for(circle_wheel(r1, 30.0_wp, 601), arc_rail(r2, -1.6_wp, 1.4_wp, 351), &
         upright_track(), position, patches, error, contact_options_type(conformal_tables=.true.))
      if (allocated(error)) return
      call patches_for(circle_wheel(r1, 30.0_wp, 601), arc_rail(r2, -1.6_wp, 1.4_wp, 351), &
         upright_track(), position, planar, error)
      if (allocated(error)) return
      call check(error, size(patches), 1, message='one patch')
      if (allocated(error)) return
      associate (p => patches(1), q => planar(1))
         call check(error, p%conformal .and. .not. q%conformal, message='tables marked')
         if (allocated(error)) return
         call check(error, p%gamma0, q%gamma0, thr=1.0e-12_wp, message='the same reference point')
         if (allocated(error)) return
         call check(error, p%curv_b(minloc(abs(p%y), 1)), 0.5_wp*(1/r1 + 1/r2), rel=.true., &
            thr=1.0e-5_wp, message='B(0)')
         if (allocated(error)) return
         d = r1 + r2 + p%gap0
         most = 0.0_wp
         do i = 1, p%size(), 7
            phi = p%y(i)/r2
            if (abs(d*sin(phi)) >= r1) cycle
            t = d*cos(phi) - sqrt(r1**2 - (d*sin(phi))**2)
            g = t - r2 - p%gap0
            ! Within the reach of any load. The spline's parameter is the polygon's chord length,
            ! 3e-6 shorter than the circle's arc: φ is that much off at s, g by up to 3e-6 mm.
            if (g > 0.5_wp) cycle
            call check(error, p%gap(i), max(g, 0.0_wp), thr=1.0e-5_wp, message='gap along the '// &
               'rail normal at s = '//str_real(p%y(i)))
            if (allocated(error)) return
            ! The wheel point on that normal, from the wheel circle's centre: its outward normal
            ! makes the contact angle (the line of centres is at γ₀).
            wy = t*sin(phi)
            wz = t*cos(phi) - d
            gamma_w = p%gamma0 - atan2(wy, -wz)
            call check(error, p%gamma(i), gamma_w, thr=1.0e-6_wp, message='wheel angle at s = '// &
               str_real(p%y(i)))
            if (allocated(error)) return
            sample = q%sample(p%y(i))
            most = max(most, abs(p%gap(i) - sample%gap))
         end do
         call check(error, most > 1.0e-3_wp, message='the planar table is another table')
      end associate
      ! longitudinal_curvature = 'reference': A = cos γ₀/(2 r_w) on every point, as on planar
      ! tables (it took the rail's local angle).
      call patches_for(circle_wheel(r1, 30.0_wp, 601), arc_rail(r2, -1.6_wp, 1.4_wp, 351), &
         upright_track(), position, patches, error, contact_options_type(conformal_tables=.true., &
         a_reference_normal=.true.))
      if (allocated(error)) return
      associate (p => patches(1))
         call check(error, maxval(abs(2.0_wp*p%r_wheel*p%curv_a - cos(p%gamma0))) < 1.0e-12_wp, &
            message='A with cos(gamma0) on conformal tables')
      end associate
   end subroutine test_conformal_circles

   !> A conical wheel (slope tan α, α = −0.05) on a cylindrical rail head (R = 80): the contact
   !> is where the rail's slope is tan α, γ(y) = α on every strip, δr(y) = y·sin α exactly
   !> (linear), gap R − √(R² − y²).
   subroutine test_cone_on_cylinder(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      real(wp), parameter :: r = 80.0_wp, alpha = -0.05_wp
      real(wp) :: y
      integer :: i

      call patches_for(cone_wheel(alpha, 40.0_wp, 161), arc_rail(r, -0.7_wp, 0.5_wp, 481), &
         upright_track(), position, patches, error)
      if (allocated(error)) return
      call check(error, size(patches), 1, message='one patch')
      if (allocated(error)) return
      associate (p => patches(1))
         call check(error, p%gamma0, alpha, thr=1.0e-10_wp, message='gamma0')
         if (allocated(error)) return
         call check(error, p%y_rail, r*sin(alpha), thr=1.0e-7_wp, message='y_rail')
         if (allocated(error)) return
         call check(error, p%r0, r_nom + p%y_wheel*tan(alpha), thr=1.0e-9_wp, message='r0')
         if (allocated(error)) return
         do i = 1, p%size(), 41
            y = p%y(i)
            call check(error, p%gamma(i), alpha, thr=1.0e-12_wp, message='constant gamma')
            if (allocated(error)) return
            call check(error, p%delta_r(y), y*sin(alpha), thr=1.0e-10_wp, message='linear dr')
            if (allocated(error)) return
            call check(error, p%gap(i), r - sqrt(r**2 - y**2), thr=1.0e-8_wp, message='gap')
            if (allocated(error)) return
         end do
      end associate
   end subroutine test_cone_on_cylinder

   !> Roll φ turns the wheel about the wheelset centre (y_ws, −r_nom): for a circular wheel on a
   !> circular rail the contact angle follows from the rotated wheel centre,
   !> sin γ₀ = (y_centre,rotated − y_rail centre)/(R₁ + R₂).
   subroutine test_roll(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      real(wp), parameter :: r1 = 60.0_wp, r2 = 20.0_wp
      real(wp) :: y_rail_origin, yc, phi

      position%y_ws = 0.5_wp
      position%roll = 0.01_wp
      call patches_for(circle_wheel(r1, 30.0_wp, 601), arc_rail(r2, -1.6_wp, 1.4_wp, 351), &
         upright_track(), position, patches, error)
      if (allocated(error)) return
      y_rail_origin = 717.5_wp + r2*sqrt(1.0_wp - 0.3_wp**2)
      ! Wheel circle centre before roll: (y_ws + 750, −r1); turned about (y_ws, −r_nom).
      phi = position%roll
      yc = position%y_ws + cos(phi)*750.0_wp - sin(phi)*(r_nom - r1)
      call check(error, patches(1)%gamma0, asin((yc - y_rail_origin)/(r1 + r2)), thr=1.0e-8_wp, &
         message='gamma0 with roll')
      if (allocated(error)) return
      ! The rolling radius is measured in the wheel: unchanged by the roll for the same wheel point.
      call check(error, patches(1)%r0, r_nom - r1 + sqrt(r1**2 - patches(1)%y_wheel**2), &
         thr=1.0e-8_wp, message='r0 in wheel coordinates')
   end subroutine test_roll

   !> The left wheel is the mirrored right one: at y_ws = −a and roll −φ it has the same patch
   !> tables as the right wheel at +a, +φ, and its reference point and profiles are the mirror
   !> images in track coordinates.
   subroutine test_left_mirror(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: right(:), left(:)
      type(wheelset_position_type) :: pos_r, pos_l
      type(prepared_profiles_type) :: prep
      type(lib_error), allocatable :: err
      real(wp), allocatable :: ry_r(:), rz_r(:), wy_r(:), wz_r(:), ry_l(:), rz_l(:), wy_l(:), &
         wz_l(:)

      pos_r%y_ws = 1.5_wp; pos_r%roll = 0.002_wp
      pos_l = wheelset_position_type(side_left, -1.5_wp, -0.002_wp)
      call prepare_profiles(circle_wheel(60.0_wp, 30.0_wp, 601), &
         arc_rail(20.0_wp, -1.6_wp, 1.4_wp, 351), upright_track(), contact_options_type(), &
         prep, err)
      if (.not. allocated(err)) call find_contact_patches(prep, pos_r, right, err)
      if (.not. allocated(err)) call find_contact_patches(prep, pos_l, left, err)
      if (.not. allocated(err)) call positioned_profiles(prep, pos_r, ry_r, rz_r, wy_r, wz_r, err)
      if (.not. allocated(err)) call positioned_profiles(prep, pos_l, ry_l, rz_l, wy_l, wz_l, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, size(left), size(right), message='number of patches')
      if (allocated(error)) return
      call check(error, left(1)%y_track, -right(1)%y_track, thr=1.0e-12_wp, message='y_track')
      if (allocated(error)) return
      call check(error, right(1)%y_track > 0.0_wp, message='right wheel at y > 0')
      if (allocated(error)) return
      call check(error, left(1)%gamma0, right(1)%gamma0, thr=1.0e-14_wp, message='gamma0')
      if (allocated(error)) return
      call check(error, left(1)%size(), right(1)%size(), message='table size')
      if (allocated(error)) return
      call check(error, maxval(abs(left(1)%gap - right(1)%gap)), 0.0_wp, thr=1.0e-14_wp, &
         message='gap tables')
      if (allocated(error)) return
      call check(error, maxval(abs(left(1)%curv_b - right(1)%curv_b)), 0.0_wp, thr=1.0e-14_wp, &
         message='B tables')
      if (allocated(error)) return
      call check(error, maxval(abs(wy_l + wy_r)) + maxval(abs(wz_l - wz_r)), 0.0_wp, &
         thr=1.0e-9_wp, message='wheel profiles mirrored')
      if (allocated(error)) return
      call check(error, maxval(abs(ry_l + ry_r)), 0.0_wp, thr=1.0e-12_wp, &
         message='rail profiles mirrored')
   end subroutine test_left_mirror

   !> A wheel with two bumps on a flat rail, lowered onto it: two separate minima of the gap,
   !> both found, the deeper first with gap0 = 0 and the other with its known gap.
   subroutine test_two_patches(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      type(profile_type) :: wheel
      integer :: i

      ! Two parabolic bumps (radii 40 and 32 mm) meeting in a ridge at y = 0: the one at y = −8
      ! reaches 0.2 mm lower.
      wheel%y = [(20.0_wp - 0.05_wp*i, i=0, 800)]
      wheel%z = max(-(wheel%y - 8.0_wp)**2/80.0_wp, -(wheel%y + 8.0_wp)**2/64.0_wp + 0.2_wp)
      allocate (wheel%kink(size(wheel%y)), source=.false.)
      wheel%kink(401) = .true.
      call wheel%update_arc_length()
      wheel%source = 'two bumps'
      call patches_for(wheel, flat_rail(), upright_track(), position, patches, error)
      if (allocated(error)) return
      call check(error, size(patches), 2, message='two patches')
      if (allocated(error)) return
      call check(error, patches(1)%y_wheel, -8.0_wp, thr=1.0e-8_wp, message='deeper patch')
      if (allocated(error)) return
      call check(error, patches(2)%y_wheel, 8.0_wp, thr=1.0e-8_wp, message='second patch')
      if (allocated(error)) return
      call check(error, patches(2)%gap0, 0.2_wp, thr=1.0e-9_wp, message='second gap0')
      if (allocated(error)) return
      ! The two basins meet at the ridge y_wheel = 0 (γ₀ = 0: table y is track y)...
      call check(error, patches(1)%y_track + patches(1)%basin_upper, 750.0_wp, thr=0.06_wp, &
         message='first basin ends at the ridge')
      if (allocated(error)) return
      call check(error, patches(2)%y_track + patches(2)%basin_lower, 750.0_wp, thr=0.06_wp, &
         message='second basin starts at the ridge')
      if (allocated(error)) return
      call check(error, patches(1)%basin_lower <= patches(1)%y(1) .and. &
         patches(2)%basin_upper >= patches(2)%y(patches(2)%size()), &
         message='no neighbour on the outer sides: the basins reach the table ends')
      if (allocated(error)) return
      ! ...and the deeper patch's table runs on into the second basin, where its gap is the
      ! second minimum's 0.2 mm (the second bump's lowest point is at table y = 16).
      i = nint(16.0_wp/patches(1)%h) + nint(-patches(1)%y(1)/patches(1)%h) + 1
      call check(error, i <= patches(1)%size(), message='first table reaches the second minimum')
      if (allocated(error)) return
      call check(error, patches(1)%y(i), 16.0_wp, thr=1.0e-9_wp, message='table point at y = 16')
      if (allocated(error)) return
      call check(error, patches(1)%gap(i), 0.2_wp, thr=1.0e-8_wp, &
         message='second minimum in the first table')
   end subroutine test_two_patches

   !> A wheel shifted far beyond the rail: no contact, with a message.
   subroutine test_no_overlap(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      type(lib_error), allocatable :: err

      position%y_ws = 200.0_wp
      call find_contact_patches(circle_wheel(50.0_wp, 20.0_wp, 201), flat_rail(), &
         upright_track(), position, contact_options_type(), patches, err)
      call check(error, allocated(err), message='no error without overlap')
      if (allocated(error)) return
      call check(error, err%stat, stat_no_contact)
      if (allocated(error)) return
      call check(error, index(err%message, 'overlap') > 0, message='message: '//err%message)
   end subroutine test_no_overlap

   !> The table file has the header naming the columns and one line per table point.
   subroutine test_write_table(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(wheelset_position_type) :: position
      type(lib_error), allocatable :: err
      character(len=*), parameter :: file = 'test_geometry_table.tmp'
      character(len=400) :: line
      integer :: unit, stat, n_data, k
      real(wp) :: vals(8)
      logical :: header

      call patches_for(circle_wheel(50.0_wp, 20.0_wp, 201), flat_rail(), upright_track(), &
         position, patches, error)
      if (allocated(error)) return
      call write_geometry_table(patches, file, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      open (newunit=unit, file=file, status='old', action='read')
      n_data = 0
      header = .false.
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, '# columns: patch  y[mm]  gap[mm]  A[1/mm]  B[1/mm]') == 1) header = .true.
         if (line(1:1) == '#' .or. len_trim(line) == 0) cycle
         read (line, *) vals
         k = n_data + 1
         if (abs(vals(2) - patches(1)%y(k)) > 1.0e-6_wp .or. &
            abs(vals(5) - patches(1)%curv_b(k)) > 1.0e-9_wp) exit
         n_data = k
      end do
      close (unit, status='delete')
      call check(error, header, message='column header missing')
      if (allocated(error)) return
      call check(error, n_data, patches(1)%size(), message='data lines')
   end subroutine test_write_table

   !> Two bumps 1 mm apart whose basins are separated by a maximum only 0.002 mm above the
   !> shallower minimum: one patch (merge_gap = 0.005) whose table runs through both basins; with
   !> merge_gap = 0 they are two patches.
   subroutine test_merge(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(contact_options_type) :: options
      type(profile_type) :: wheel
      real(wp), parameter :: r_b = 0.125_wp/(0.003125_wp - 0.001_wp)
      integer :: i, j

      ! Gaps (y + 0.5)²/80 and (y − 0.5)²/(2 r_b) + 0.001 on a flat rail meet at y = 0 at 0.003125.
      wheel%y = [(10.0_wp - 0.05_wp*i, i=0, 400)]
      wheel%z = merge(-(wheel%y + 0.5_wp)**2/80.0_wp, &
         -(wheel%y - 0.5_wp)**2/(2.0_wp*r_b) - 0.001_wp, wheel%y < 0.0_wp)
      allocate (wheel%kink(size(wheel%y)), source=.false.)
      wheel%kink(201) = .true.
      call wheel%update_arc_length()
      call patches_for(wheel, flat_rail(), upright_track(), wheelset_position_type(), patches, &
         error)
      if (allocated(error)) return
      call check(error, size(patches), 1, message='one merged patch')
      if (allocated(error)) return
      call check(error, patches(1)%y_wheel, -0.5_wp, thr=1.0e-8_wp, message='deeper bump')
      if (allocated(error)) return
      j = 0
      do i = 1, patches(1)%size()
         if (abs(patches(1)%y(i) - 1.0_wp) < 1.0e-9_wp) j = i
      end do
      call check(error, j > 0, message='table reaches the second basin')
      if (allocated(error)) return
      call check(error, patches(1)%gap(j), 0.001_wp, thr=1.0e-8_wp, message='second basin gap')
      if (allocated(error)) return
      options%merge_gap = 0.0_wp
      call patches_for(wheel, flat_rail(), upright_track(), wheelset_position_type(), patches, &
         error, options)
      if (allocated(error)) return
      call check(error, size(patches), 2, message='two patches without merging')
      if (allocated(error)) return
      call check(error, patches(2)%gap0, 0.001_wp, thr=1.0e-8_wp, message='second gap0')
   end subroutine test_merge

   !> With a_reference_normal, A(y) = cos γ₀/(2 r_w(y)) on every strip.
   subroutine test_a_reference_normal(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(contact_options_type) :: options
      type(wheelset_position_type) :: position
      integer :: i

      options%a_reference_normal = .true.
      position%y_ws = 1.0_wp
      call patches_for(circle_wheel(60.0_wp, 30.0_wp, 601), arc_rail(20.0_wp, -1.6_wp, 1.4_wp, &
         351), upright_track(), position, patches, error, options)
      if (allocated(error)) return
      associate (p => patches(1))
         do i = 1, p%size(), 17
            call check(error, p%curv_a(i), cos(p%gamma0)/(2*p%r_wheel(i)), rel=.true., &
               thr=1.0e-13_wp, message='A with the reference normal')
            if (allocated(error)) return
         end do
         call check(error, abs(cos(p%gamma(1)) - cos(p%gamma0)) > 1.0e-3_wp, &
            message='the local angle differs at the table end')
      end associate
   end subroutine test_a_reference_normal

   !> A rail head only 10 mm deep has no gauge point 14 mm below its top: an error saying so.
   subroutine test_no_gauge_face(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(lib_error), allocatable :: err

      call find_contact_patches(circle_wheel(50.0_wp, 20.0_wp, 201), &
         arc_rail(20.0_wp, -1.0_wp, 1.0_wp, 101), upright_track(), wheelset_position_type(), &
         contact_options_type(), patches, err)
      call check(error, allocated(err), message='shallow rail accepted')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
      if (allocated(error)) return
      call check(error, index(err%message, 'arc rail') > 0 .and. &
         index(err%message, 'gauge face') > 0, message='message: '//err%message)
   end subroutine test_no_gauge_face

   !> A wheel profile that does not contain its origin (tape circle) cannot give rolling radii.
   subroutine test_wheel_without_origin(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: patches(:)
      type(lib_error), allocatable :: err
      type(profile_type) :: wheel

      wheel = circle_wheel(50.0_wp, 20.0_wp, 201)
      wheel%y = wheel%y + 30.0_wp
      call find_contact_patches(wheel, flat_rail(), upright_track(), wheelset_position_type(), &
         contact_options_type(), patches, err)
      call check(error, allocated(err), message='wheel without origin accepted')
      if (allocated(error)) return
      call check(error, index(err%message, 'circle wheel') > 0 .and. &
         index(err%message, 'tape circle y = 0') > 0, message='message: '//err%message)
   end subroutine test_wheel_without_origin

   !> The tape circle lies tape_circle_offset from the flange back: a circle wheel with its
   !> origin moved 70 mm onto the flange back (MiniProf style) and flange_back_position = 0 gives
   !> the patch of the same wheel with its origin on the tape circle and the default −70 (same
   !> place, r₀ = r_nom at the lowest point); with tape_circle_offset = 75 the tape circle is
   !> 5 mm to the field side of the lowest point, so r₀ = r_nom + R − √(R² − 5²).
   subroutine test_tape_circle(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: ref(:), moved(:)
      type(profile_type) :: wheel
      type(track_type) :: track
      real(wp), parameter :: radius = 50.0_wp
      integer :: n

      wheel = circle_wheel(radius, 20.0_wp, 201)
      call patches_for(wheel, flat_rail(), upright_track(), wheelset_position_type(), ref, error)
      if (allocated(error)) return
      call check(error, ref(1)%r0, r_nom, thr=1.0e-9_wp, message='r0 at the tape circle')
      if (allocated(error)) return
      wheel%y = wheel%y + 70.0_wp
      track = upright_track()
      track%flange_back_position = 0.0_wp
      call patches_for(wheel, flat_rail(), track, wheelset_position_type(), moved, error)
      if (allocated(error)) return
      n = ref(1)%size()
      call check(error, moved(1)%size(), n, message='table size')
      if (allocated(error)) return
      call check(error, moved(1)%y_track, ref(1)%y_track, thr=1.0e-9_wp, message='y_track')
      if (allocated(error)) return
      call check(error, moved(1)%y_wheel, ref(1)%y_wheel + 70.0_wp, thr=1.0e-9_wp, &
         message='y_wheel in the moved profile coordinates')
      if (allocated(error)) return
      call check(error, maxval(abs(moved(1)%r_wheel - ref(1)%r_wheel)) < 1.0e-9_wp, &
         message='rolling radii')
      if (allocated(error)) return
      track%tape_circle_offset = 75.0_wp
      call patches_for(wheel, flat_rail(), track, wheelset_position_type(), moved, error)
      if (allocated(error)) return
      call check(error, moved(1)%r0, r_nom + radius - sqrt(radius**2 - 25.0_wp), thr=1.0e-8_wp, &
         message='r0 with the tape circle 5 mm off the contact')
   end subroutine test_tape_circle

   !> A measured MiniProf wheel (origin at the flange back) on the built-in UIC60 1:40 at
   !> y_ws = 0 with flange_back_position = 0: a tread contact (γ₀ < 0, |γ₀| < 0.1 rad) with a
   !> rolling radius within 3 mm of the nominal 460 mm (with the tape circle taken at the origin,
   !> the flange back, r₀ was 479 mm). Skipped without the external data.
   subroutine test_miniprof_wheel(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: file
      type(patch_geometry_type), allocatable :: patches(:)
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)

      file = external_file('profiles/Car7216_0001r.whl', error)
      if (allocated(error)) return
      call read_profile(file, wheel, err, line_of_point=lines)
      if (.not. allocated(err)) call clean_profile(wheel, err, lines)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      track%flange_back_position = 0.0_wp
      call patches_for(wheel, rail, track, wheelset_position_type(), patches, error)
      if (allocated(error)) return
      call check(error, patches(1)%r0, 460.0_wp, thr=3.0_wp, message='r0 near nominal')
      if (allocated(error)) return
      call check(error, patches(1)%gamma0 < 0.0_wp .and. patches(1)%gamma0 > -0.1_wp, &
         message='tread contact angle (CONTACT sign: < 0 on the right tread)')
   end subroutine test_miniprof_wheel

   ! ---------------------------------------------------------------- Manchester benchmark

   !> S1002 (MBench_S1002_v3.prw) on UIC60 1:40 (MBench_UIC60_v3.prr, already canted) with the
   !> benchmark's track (doc/theory.md §5.2), read and cleaned as the program does; skipped without
   !> the external data.
   subroutine manchester(prep, error, options)
      type(prepared_profiles_type), intent(out) :: prep
      type(error_type), allocatable, intent(out) :: error
      !> Contact options (default: the defaults).
      type(contact_options_type), intent(in), optional :: options
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(contact_options_type) :: opts
      type(lib_error), allocatable :: err
      character(len=:), allocatable :: wheel_file, rail_file

      wheel_file = external_file(mbench_wheel, error)
      if (.not. allocated(error)) rail_file = external_file(mbench_rail, error)
      if (allocated(error)) return
      call read_profile(wheel_file, wheel, err)
      if (.not. allocated(err)) call clean_profile(wheel, err)
      if (.not. allocated(err)) call read_profile(rail_file, rail, err)
      if (.not. allocated(err)) call clean_profile(rail, err)
      track%rail_canted = .true.
      if (present(options)) opts = options
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track, opts, prep, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine manchester

   !> Patches of the Manchester case at one lateral shift.
   subroutine manchester_patches(prep, y_ws, patches, error)
      type(prepared_profiles_type), intent(in) :: prep
      real(wp), intent(in) :: y_ws
      type(patch_geometry_type), allocatable, intent(out) :: patches(:)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call find_contact_patches(prep, wheelset_position_type(y_ws=y_ws), patches, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine manchester_patches

   !> The gauge rule puts the Manchester rail origin at y = 760.53 mm (doc/theory.md §5.2).
   subroutine test_manchester_rail(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      real(wp) :: y, z

      call manchester(prep, error)
      if (allocated(error)) return
      call prep%rail_map%point(0.0_wp, 0.0_wp, y, z)
      call check(error, y, 760.53_wp, thr=0.01_wp, message='rail origin')
   end subroutine test_manchester_rail

   !> Centred wheelset (y_ws = 0, no yaw): the reference point is CONTACT's geometric contact
   !> point of the same case (the external data's reference/ty0_literal/summary.csv: the weighted
   !> centre ycp_tr plus y_geo along the contact plane at angle delt) within 0.05 mm; γ₀ is the slope of
   !> the R300 crown (doc/theory.md §5.2, top at the rail origin) at y_rail, atan(y_rail/300),
   !> within 0.3 mrad; A and B at the point agree with CONTACT's local curvatures A1_local
   !> (1 %) and B1_local (3 %: CONTACT fits a quadratic over ±0.6 mm).
   subroutine test_manchester_ty0(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      type(patch_geometry_type), allocatable :: patches(:)
      real(wp) :: ycp, delt, y_geo, a1, b1, y_expected
      integer :: i0
      logical :: found
      character(len=:), allocatable :: summary

      call manchester(prep, error)
      if (allocated(error)) return
      summary = external_file(ty0_summary, error)
      if (allocated(error)) return
      call reference_value(summary, 'ycp_tr', ycp, found)
      if (found) call reference_value(summary, 'delt', delt, found)
      if (found) call reference_value(summary, 'y_geo', y_geo, found)
      if (found) call reference_value(summary, 'A1_local', a1, found)
      if (found) call reference_value(summary, 'B1_local', b1, found)
      if (.not. found) then
         call test_failed(error, summary//' is incomplete')
         return
      end if
      y_expected = ycp + y_geo*cos(delt)
      call manchester_patches(prep, 0.0_wp, patches, error)
      if (allocated(error)) return
      associate (p => patches(1))
         call check(error, p%y_track, y_expected, thr=0.05_wp, message='y_track (geometric point)')
         if (allocated(error)) return
         call check(error, p%y_wheel, y_expected - 750.0_wp, thr=0.05_wp, message='y_wheel')
         if (allocated(error)) return
         call check(error, p%y_rail, y_expected - 760.53_wp, thr=0.05_wp, message='y_rail')
         if (allocated(error)) return
         call check(error, p%gamma0, atan(p%y_rail/300.0_wp), thr=3.0e-4_wp, &
            message='gamma0 = slope of the R300 crown')
         if (allocated(error)) return
         call check(error, p%gamma0 < 0.0_wp, message='tread contact angle < 0 (CONTACT sign)')
         if (allocated(error)) return
         i0 = minloc(abs(p%y), 1)
         call check(error, p%curv_a(i0), a1, rel=.true., thr=0.01_wp, message='A at the point')
         if (allocated(error)) return
         call check(error, p%curv_b(i0), b1, rel=.true., thr=0.03_wp, message='B at the point')
      end associate
   end subroutine test_manchester_ty0

   !> One value of a summary.csv of CONTACT's reference (`key,value,unit,note`).
   subroutine reference_value(file, key, val, found)
      character(len=*), intent(in) :: file, key
      real(wp), intent(out) :: val
      logical, intent(out) :: found
      character(len=400) :: line
      integer :: unit, stat, c1, c2

      val = 0.0_wp
      found = .false.
      open (newunit=unit, file=file, status='old', &
         action='read', iostat=stat)
      if (stat /= 0) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         c1 = index(line, ',')
         if (c1 == 0) cycle
         if (line(:c1 - 1) /= key) cycle
         c2 = index(line(c1 + 1:), ',') + c1
         read (line(c1 + 1:c2 - 1), *, iostat=stat) val
         found = stat == 0
         exit
      end do
      close (unit)
   end subroutine reference_value

   !> y_ws = 5 mm (cf. doc/theory.md §5.6, where CONTACT finds two regions near this shift): the
   !> tread and the gauge corner both touch or nearly so, and both are found, with basins that
   !> meet at the ridge between them and tables that run on into the neighbour's basin.
   subroutine test_manchester_two_patches(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      type(patch_geometry_type), allocatable :: patches(:)
      integer :: tread, corner, k

      call manchester(prep, error)
      if (allocated(error)) return
      call manchester_patches(prep, 5.0_wp, patches, error)
      if (allocated(error)) return
      call check(error, size(patches), 2, message='two candidate patches at y_ws = 5')
      if (allocated(error)) return
      tread = 0; corner = 0
      do k = 1, 2
         if (patches(k)%y_rail > -26.0_wp .and. patches(k)%y_rail < -18.0_wp) tread = k
         if (patches(k)%y_rail > -37.0_wp .and. patches(k)%y_rail < -32.0_wp) corner = k
      end do
      call check(error, tread > 0 .and. corner > 0, message='one on the tread, one at the '// &
         'gauge corner')
      if (allocated(error)) return
      call check(error, patches(1)%gap0, 0.0_wp, thr=1.0e-9_wp, message='deepest gap0')
      if (allocated(error)) return
      call check(error, patches(2)%gap0 > 0.0_wp .and. patches(2)%gap0 < 0.05_wp, &
         message='second patch nearly touching')
      if (allocated(error)) return
      call check(error, abs(patches(corner)%gamma0) > 2.0_wp*abs(patches(tread)%gamma0), &
         message='gauge corner steeper than the tread')
      if (allocated(error)) return
      ! Basins: the tread's (field side) begins where the corner's ends, at the ridge between
      ! them; the tables run on past it, each into the other's basin.
      associate (t => patches(tread), c => patches(corner))
         call check(error, t%y_track + t%basin_lower*cos(t%gamma0), &
            c%y_track + c%basin_upper*cos(c%gamma0), thr=0.1_wp, message='basins meet')
         if (allocated(error)) return
         call check(error, t%y_track + t%y(1)*cos(t%gamma0) < c%y_track .and. &
            c%y_track + c%y(c%size())*cos(c%gamma0) > t%y_track, &
            message='each table reaches the other reference point')
      end associate
   end subroutine test_manchester_two_patches

   !> Scan y_ws = 0…10 mm in steps of 0.05 mm: the deepest contact point moves continuously
   !> (less than 1 mm per step) except at three jumps — inside the tread near 0.25 mm, to the
   !> gauge corner near 5 mm and onto the flange between 6 and 7 mm (CONTACT's yawed rows,
   !> doc/theory.md §5.6: between 0 and 0.5, 4.5 and 5, 6 and 6.5) — and agrees with the table's
   !> unyawed-like rows on the tread (y_ws = 2, 4) within 1 mm. When the environment variable
   !> SHCONTACT_GEOMETRY_SCAN names a file, the scan is written there (doc/geometry.md).
   subroutine test_manchester_scan(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      type(patch_geometry_type), allocatable :: patches(:)
      integer, parameter :: n = 201
      real(wp) :: y_ws(n), y_rail(n), gamma0(n)
      integer :: i, k, n_jumps, unit, length, stat
      integer :: jump_at(8)
      character(len=512) :: file

      call manchester(prep, error)
      if (allocated(error)) return
      call get_environment_variable(scan_file_variable, file, length, stat)
      unit = -1
      if (stat == 0 .and. length > 0) then
         open (newunit=unit, file=trim(file), status='replace', action='write')
         write (unit, '(a)') '# Manchester S1002 / UIC60 1:40, no yaw: candidate patches per '// &
            'lateral shift (shcontact test geometry manchester_scan_0_to_10)', &
            '# y_ws[mm] patch y_track[mm] y_rail[mm] y_wheel[mm] gamma0[rad] r0[mm] gap0[mm]'
      end if
      n_jumps = 0
      do i = 1, n
         y_ws(i) = 0.05_wp*(i - 1)
         call manchester_patches(prep, y_ws(i), patches, error)
         if (allocated(error)) exit
         y_rail(i) = patches(1)%y_rail
         gamma0(i) = patches(1)%gamma0
         if (unit /= -1) then
            do k = 1, size(patches)
               write (unit, '(f6.2,i3,2f11.4,f10.4,f10.5,f10.4,f9.5)') y_ws(i), k, &
                  patches(k)%y_track, patches(k)%y_rail, patches(k)%y_wheel, patches(k)%gamma0, &
                  patches(k)%r0, patches(k)%gap0
            end do
         end if
         if (i > 1) then
            if (abs(y_rail(i) - y_rail(i - 1)) > 1.0_wp) then
               n_jumps = n_jumps + 1
               if (n_jumps <= size(jump_at)) jump_at(n_jumps) = i
            end if
         end if
      end do
      if (unit /= -1) close (unit)
      if (allocated(error)) return
      call check(error, n_jumps, 3, message='jumps of the contact point')
      if (allocated(error)) return
      call check(error, y_ws(jump_at(1)) > 0.0_wp .and. y_ws(jump_at(1)) <= 0.5_wp, &
         message='first jump (within the tread) between 0 and 0.5 mm')
      if (allocated(error)) return
      call check(error, y_ws(jump_at(2)) > 4.5_wp .and. y_ws(jump_at(2)) <= 5.5_wp, &
         message='jump to the gauge corner between 4.5 and 5.5 mm')
      if (allocated(error)) return
      call check(error, y_ws(jump_at(3)) > 6.0_wp .and. y_ws(jump_at(3)) <= 7.0_wp, &
         message='jump to the flange between 6 and 7 mm')
      if (allocated(error)) return
      call check(error, y_rail(41), -19.618_wp, thr=1.0_wp, message='y_ws = 2: tread')
      if (allocated(error)) return
      call check(error, y_rail(81), -21.794_wp, thr=1.0_wp, message='y_ws = 4: tread')
      if (allocated(error)) return
      call check(error, y_rail(121) < -32.0_wp .and. y_rail(121) > -38.0_wp, &
         message='y_ws = 6: gauge corner')
      if (allocated(error)) return
      call check(error, y_rail(n) < -39.0_wp .and. abs(gamma0(n)) > 0.7_wp, &
         message='y_ws = 10: flange')
   end subroutine test_manchester_scan

   !> The built-in S1002 on the built-in upright UIC60, canted 1:40 by the track, puts the contact
   !> where the Manchester files (rail already canted) do, within 0.05 mm, at shifts on the tread,
   !> the gauge corner and the flange (the built-ins match the files to 0.01 mm, issue 3).
   subroutine test_builtin_as_manchester(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: files, builtin
      type(patch_geometry_type), allocatable :: p_files(:), p_builtin(:)
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      real(wp), parameter :: shifts(4) = [0.0_wp, 2.0_wp, 6.0_wp, 9.0_wp]
      integer :: i

      call manchester(files, error)
      if (allocated(error)) return
      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), builtin, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 1, size(shifts)
         call manchester_patches(files, shifts(i), p_files, error)
         if (allocated(error)) return
         call manchester_patches(builtin, shifts(i), p_builtin, error)
         if (allocated(error)) return
         call check(error, p_builtin(1)%y_track, p_files(1)%y_track, thr=0.05_wp, &
            message='contact position, built-in vs files')
         if (allocated(error)) return
         call check(error, p_builtin(1)%gamma0, p_files(1)%gamma0, thr=2.0e-3_wp, &
            message='contact angle, built-in vs files')
         if (allocated(error)) return
      end do
   end subroutine test_builtin_as_manchester

   !> The search into reused storage (contact_patches_type) gives the patches of the search
   !> into fresh tables bit for bit, whatever the storage held before (positions with one and
   !> with two patches, in an order where tables shrink and grow, and after a failed search);
   !> a second pass over the same positions reallocates nothing (the capacities stay).
   subroutine test_reused_storage(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      type(contact_patches_type) :: reused
      type(patch_geometry_type), allocatable :: fresh(:)
      type(patch_geometry_type) :: copy
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      real(wp), parameter :: shifts(5) = [5.0_wp, 0.0_wp, 9.0_wp, 2.0_wp, 4.733_wp]
      integer :: capacity(2), pass, i, k, n, two_patches

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), prep, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      two_patches = 0
      capacity = 0
      do pass = 1, 2
         do i = 1, size(shifts)
            call find_contact_patches(prep, wheelset_position_type(y_ws=shifts(i)), reused, err)
            if (.not. allocated(err)) call find_contact_patches(prep, &
               wheelset_position_type(y_ws=shifts(i)), fresh, err)
            if (allocated(err)) then
               call test_failed(error, 'find_contact_patches: '//err%message); return
            end if
            call check(error, reused%count, size(fresh), message='number of patches')
            if (allocated(error)) return
            if (reused%count > 1) two_patches = two_patches + 1
            do k = 1, reused%count
               n = reused%points(k)
               call check(error, n, size(fresh(k)%y), message='table size')
               if (allocated(error)) return
               associate (r => reused%patch(k), f => fresh(k))
                  call check(error, same_bits([r%y_track, r%z_track, r%y_rail, r%y_wheel, &
                     r%gamma0, r%r0, r%gap0, r%h, r%basin_lower, r%basin_upper], &
                     [f%y_track, f%z_track, f%y_rail, f%y_wheel, f%gamma0, f%r0, f%gap0, f%h, &
                     f%basin_lower, f%basin_upper]) .and. same_bits(r%y(1:n), f%y) .and. &
                     same_bits(r%gap(1:n), f%gap) .and. same_bits(r%curv_a(1:n), f%curv_a) .and. &
                     same_bits(r%curv_b(1:n), f%curv_b) .and. &
                     same_bits(r%gamma(1:n), f%gamma) .and. same_bits(r%r_wheel(1:n), f%r_wheel), &
                     message='reused storage differs from fresh tables')
                  if (allocated(error)) return
               end associate
               call extract_patch(reused, k, copy)
               call check(error, size(copy%y) == n .and. same_bits(copy%gap, fresh(k)%gap) .and. &
                  same_bits(copy%curv_b, fresh(k)%curv_b), message='extract_patch')
               if (allocated(error)) return
            end do
         end do
         if (pass == 1) then
            capacity = [size(reused%patch(1)%y), size(reused%patch(2)%y)]
            ! A failed search leaves no patch and the storage usable.
            call find_contact_patches(prep, wheelset_position_type(y_ws=300.0_wp), reused, err)
            call check(error, allocated(err) .and. reused%count == 0, &
               message='a wheel far off the rail: expected an error and no patch')
            if (allocated(error)) return
            deallocate (err)
         end if
      end do
      call check(error, two_patches >= 2, message='expected positions with two patches')
      if (allocated(error)) return
      call check(error, size(reused%patch(1)%y) == capacity(1) .and. &
         size(reused%patch(2)%y) == capacity(2), message='the second pass reallocated tables')
   contains
      logical function same_bits(a, b)
         real(wp), intent(in) :: a(:), b(:)
         integer :: j
         same_bits = size(a) == size(b)
         if (.not. same_bits) return
         do j = 1, size(a)
            same_bits = same_bits .and. transfer(a(j), 0_i8) == transfer(b(j), 0_i8)
         end do
      end function same_bits
   end subroutine test_reused_storage

   ! ------------------------------------------------- fast search against the reference search

   !> The fast search (Newton walk, cached rail envelope) finds the patches of the original
   !> bracketing search (`reference_search`) with the same tables to 1e-9 (mm, rad; relative
   !> for the curvatures and the radius): built-in S1002 on UIC60 1:40, t_y = −10 … 10 mm.
   subroutine test_fast_builtin(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: fast, reference
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), fast, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(reference_search=.true.), reference, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check_fast_scan(fast, reference, error)
   end subroutine test_fast_builtin

   !> As [[test_fast_builtin]] for the Manchester files (MBench_S1002_v3 on MBench_UIC60_v3).
   subroutine test_fast_manchester(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: fast, reference

      call manchester(fast, error)
      if (allocated(error)) return
      call manchester(reference, error, contact_options_type(reference_search=.true.))
      if (allocated(error)) return
      call check_fast_scan(fast, reference, error)
   end subroutine test_fast_manchester

   !> Fast and reference search at t_y = −10 + 0.37 k mm (k = 0 … 54), right wheel, and a few
   !> positions of the left wheel with roll: the same outcome (error status), the same number of
   !> patches and table points, and every value within 1e-9.
   subroutine check_fast_scan(fast, reference, error, first, step, count)
      type(prepared_profiles_type), intent(in) :: fast, reference
      type(error_type), allocatable, intent(out) :: error
      !> Right-wheel positions t_y = first + step·k, k = 0 … count − 1 (default −10, 0.37, 55),
      !> then the left-wheel positions.
      real(wp), intent(in), optional :: first, step
      integer, intent(in), optional :: count
      real(wp), parameter :: tol = 1.0e-9_wp, ref_tol = 1.0e-10_wp
      real(wp) :: y_first, y_step
      integer :: n_right
      type(contact_patches_type) :: a, b
      type(wheelset_position_type) :: position
      type(lib_error), allocatable :: err_a, err_b
      integer :: i, k, n, found
      character(len=40) :: where

      y_first = -10.0_wp; y_step = 0.37_wp; n_right = 55
      if (present(first)) y_first = first
      if (present(step)) y_step = step
      if (present(count)) n_right = count
      found = 0
      do i = 0, n_right + 5
         if (i < n_right) then
            position = wheelset_position_type(y_ws=y_first + y_step*i)
         else
            position = wheelset_position_type(side=side_left, y_ws=-6.0_wp + 2.3_wp*(i - n_right), &
               roll=1.0e-3_wp*(i - n_right - 2))
         end if
         write (where, '(a,f8.3,a,i0)') ' at t_y = ', position%y_ws, ', side ', position%side
         call find_contact_patches(fast, position, a, err_a)
         call find_contact_patches(reference, position, b, err_b)
         call check(error, allocated(err_a) .eqv. allocated(err_b), &
            message='fast and reference search disagree on success'//trim(where))
         if (allocated(error)) return
         if (allocated(err_a)) then
            call check(error, err_a%stat, err_b%stat, message='error status'//trim(where))
            if (allocated(error)) return
            cycle
         end if
         found = found + 1
         call check(error, a%count, b%count, message='number of patches'//trim(where))
         if (allocated(error)) return
         do k = 1, a%count
            n = a%points(k)
            call check(error, n, b%points(k), message='table points'//trim(where))
            if (allocated(error)) return
            associate (p => a%patch(k), q => b%patch(k))
               call check(error, maxval(abs([p%y_track - q%y_track, p%z_track - q%z_track, &
                  p%y_rail - q%y_rail, p%y_wheel - q%y_wheel])) <= ref_tol, &
                  message='reference point'//trim(where))
               if (allocated(error)) return
               call check(error, maxval(abs([p%y_track - q%y_track, p%z_track - q%z_track, &
                  p%y_rail - q%y_rail, p%y_wheel - q%y_wheel, p%gamma0 - q%gamma0, &
                  p%gap0 - q%gap0, p%basin_lower - q%basin_lower, &
                  p%basin_upper - q%basin_upper, (p%r0 - q%r0)/q%r0])) <= tol, &
                  message='reference point, angle, radius or basin'//trim(where))
               if (allocated(error)) return
               call check(error, maxval(abs(p%y(1:n) - q%y(1:n))) <= tol .and. &
                  maxval(abs(p%gap(1:n) - q%gap(1:n))) <= tol .and. &
                  maxval(abs(p%gamma(1:n) - q%gamma(1:n))) <= tol .and. &
                  maxval(abs(p%r_wheel(1:n) - q%r_wheel(1:n))/q%r_wheel(1:n)) <= tol .and. &
                  maxval(abs(p%curv_a(1:n) - q%curv_a(1:n))/q%curv_a(1:n)) <= tol .and. &
                  maxval(abs(p%curv_b(1:n) - q%curv_b(1:n))/q%curv_b(1:n)) <= tol, &
                  message='strip tables differ'//trim(where))
               if (allocated(error)) return
            end associate
         end do
      end do
      call check(error, found >= min(50, n_right - 5), &
         message='expected contact at most positions')
   end subroutine check_fast_scan

   !> prepare_wheel on profiles prepared with another wheel gives the profiles that
   !> prepare_profiles gives for the new wheel: the same patches, bit for bit. The other wheel
   !> is the built-in S1002 with every second point and a tread hollowed by up to 0.3 mm (worn):
   !> other points, another point count, another shape.
   subroutine test_prepare_wheel(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: swapped, direct
      type(patch_geometry_type), allocatable :: p(:), q(:)
      type(profile_type) :: wheel, other, rail
      type(lib_error), allocatable :: err
      integer :: i, k

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) then
         other%source = 'worn S1002'
         other%kind = wheel%kind
         other%y = wheel%y(1::2)
         other%z = wheel%z(1::2) + 0.3_wp*exp(-(other%y/20.0_wp)**2)
         call other%update_arc_length()
         call clean_profile(other, err)
      end if
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), swapped, err)
      if (.not. allocated(err)) call prepare_wheel(other, swapped%track, swapped%options, &
         swapped, err)
      if (.not. allocated(err)) call prepare_profiles(other, rail, track_type(), &
         contact_options_type(), direct, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 1, 3
         call find_contact_patches(swapped, wheelset_position_type(y_ws=3.0_wp*(i - 2)), p, err)
         if (.not. allocated(err)) call find_contact_patches(direct, &
            wheelset_position_type(y_ws=3.0_wp*(i - 2)), q, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, size(p), size(q), message='number of patches')
         if (allocated(error)) return
         do k = 1, size(p)
            call check(error, size(p(k)%gap) == size(q(k)%gap) .and. &
               all(p(k)%gap == q(k)%gap) .and. all(p(k)%r_wheel == q(k)%r_wheel) .and. &
               p(k)%y_track == q(k)%y_track .and. p(k)%r0 == q(k)%r0, &
               message='prepare_wheel: tables differ from prepare_profiles')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_prepare_wheel

   ! ------------------------------------------------------ the table walk, point against chunk

   !> walk_points (per-interval start, Newton on the projected cubic, in chunks) gives the points
   !> of the point-by-point walk_to_eta (the former fast walk) to 1e-12 mm (slope and curvature
   !> to 1e-11 of their largest value: near the steep ends the curvature reaches ~500/mm, where
   !> round-off alone is ~1e-10/mm) and ends at the same
   !> point: the built-in S1002 and UIC60 splines in frames turned by −1.2 … 1.2 rad about
   !> points across the profile, walked both ways until the profile turns back (dη/ds ≤ 0.05)
   !> or ends, in chunks of uneven size; on the steep ends the walk takes its fallback.
   subroutine test_walk_points(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: min_deta = 0.05_wp, h = 0.025_wp, tol = 1.0e-12_wp, &
         rel_tol = 1.0e-11_wp
      integer, parameter :: n_max = 8000
      type(prepared_profiles_type) :: prep
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      type(rigid_map_type) :: map
      type(frame_point_type) :: p0, p, q
      type(frame_walk_type) :: walk
      type(profile_spline_type) :: spline
      real(wp) :: zeta(n_max), slope(n_max), curv(n_max), v(n_max), s(n_max), step, s0, theta
      integer :: prof, ia, is, sgn, dir, n, n_ref, j0, m, got, j, turned
      logical :: found
      character(len=120) :: where

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), prep, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      turned = 0
      do prof = 1, 2
         if (prof == 1) then
            spline = prep%wheel
         else
            spline = prep%rail
         end if
         block
            do ia = -4, 4
               theta = 0.3_wp*ia
               do is = 1, 9
                  s0 = spline%s(1) + 0.1_wp*is*spline%length()
                  p0 = frame_point(spline, rigid_map_type(), s0, 1)
                  map = to_frame(theta, p0%u, p0%v)
                  p0 = frame_point(spline, map, s0, 1)
                  dir = merge(1, -1, p0%deta >= 0.0_wp)
                  p0 = frame_point(spline, map, s0, dir)
                  if (.not. p0%deta > min_deta) cycle
                  do sgn = -1, 1, 2
                     step = sgn*h
                     write (where, '(a,i0,a,f5.2,a,f8.3,a,i0)') ' (profile ', prof, &
                        ', theta ', theta, ', s0 ', s0, ', step sign ', sgn
                     ! Reference: point after point.
                     p = p0
                     n_ref = 0
                     do j = 1, n_max
                        call walk_to_eta(spline, map, j*step, dir, p, q, found)
                        if (.not. found) exit
                        p = q
                        if (.not. p%deta > min_deta) exit
                        n_ref = j
                        zeta(j) = p%zeta; slope(j) = p%slope; curv(j) = p%curv
                        v(j) = p%v; s(j) = p%s
                     end do
                     if (n_ref < n_max .and. found) turned = turned + 1
                     ! The chunked walk, chunks of 1, 2, … 7 points and then 40.
                     call start_walk(spline, map, p0, dir, step, walk)
                     j0 = 0
                     n = 0
                     do
                        m = min(merge(40, j0/16 + 1, j0 > 200), n_max - j0)
                        if (m <= 0) exit
                        block
                           real(wp), dimension(m) :: z1, s1, c1, v1, a1
                           call walk_points(spline, map, walk, step, j0, m, min_deta, z1, &
                              c1, a1, got, s1, v1)
                           if (got > 0) then
                              write (where(72:), '(a,5es8.1)') ':', &
                                 maxval(abs(z1(1:got) - zeta(j0 + 1:j0 + got))), &
                                 maxval(abs(s1(1:got) - slope(j0 + 1:j0 + got))), &
                                 maxval(abs(c1(1:got) - curv(j0 + 1:j0 + got))), &
                                 maxval(abs(curv(j0 + 1:j0 + got))), &
                                 maxval(abs(a1(1:got) - s(j0 + 1:j0 + got)))
                              call check(error, maxval(abs(z1(1:got) - zeta(j0 + 1:j0 + got))) &
                                 <= tol .and. maxval(abs(s1(1:got) - slope(j0 + 1:j0 + got))) &
                                 <= rel_tol*max(1.0_wp, maxval(abs(slope(j0 + 1:j0 + got)))) &
                                 .and. maxval(abs(c1(1:got) - curv(j0 + 1:j0 + got))) <= &
                                 rel_tol*max(1.0_wp, maxval(abs(curv(j0 + 1:j0 + got)))) .and. &
                                 maxval(abs(v1(1:got) - v(j0 + 1:j0 + got))) <= tol .and. &
                                 maxval(abs(a1(1:got) - s(j0 + 1:j0 + got))) <= tol, &
                                 message='walk_points differs from walk_to_eta'//trim(where))
                              if (allocated(error)) return
                           end if
                        end block
                        n = j0 + got
                        if (got < m) exit
                        j0 = j0 + m
                     end do
                     call check(error, n, n_ref, message='walk_points ends elsewhere'//trim(where))
                     if (allocated(error)) return
                  end do
               end do
            end do
         end block
      end do
      call check(error, turned >= 50, message='expected walks that end where the profile turns')
   end subroutine test_walk_points

   !> Fast against reference search on a finer grid than [[test_fast_builtin]]: built-in S1002 on
   !> UIC60, t_y = −10 … 10 mm in steps of 0.13 mm (positions between the other test's).
   subroutine test_fast_fine_scan(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: fast, reference
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), fast, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(reference_search=.true.), reference, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check_fast_scan(fast, reference, error, first=-9.935_wp, step=0.13_wp, count=153)
   end subroutine test_fast_fine_scan

   !> The fast search on yawed wheels (spline coefficients, samples and the bounds of the blocks
   !> of samples interpolated by apply_yaw) against the reference search, which places and
   !> envelopes every wheel sample: built-in S1002 on UIC60 at yaw angles up to the table's limit,
   !> t_y = −9.3 … 9.6 mm. Every block's bounds hold its samples.
   subroutine test_fast_yawed(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: yaws(*) = [-0.025_wp, -0.0101_wp, 0.0031_wp, 0.0125_wp, 0.02_wp]
      type(prepared_profiles_type) :: prep, fast, reference
      type(yaw_table_type) :: table
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err
      integer :: j, b, i1, i2
      logical :: inside

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), prep, err)
      if (.not. allocated(err)) call build_yaw_table(wheel, prep, track_type(), &
         contact_options_type(), table, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      fast = prep
      do j = 1, size(yaws)
         call apply_yaw(table, yaws(j), fast)
         inside = .true.
         do b = 1, size(fast%wheel_box, 2)
            i1 = (b - 1)*sample_block + 1
            i2 = min(size(fast%wheel_y), b*sample_block)
            inside = inside .and. all(fast%wheel_y(i1:i2) >= fast%wheel_box(1, b)) .and. &
               all(fast%wheel_y(i1:i2) <= fast%wheel_box(2, b)) .and. &
               all(fast%wheel_z(i1:i2) >= fast%wheel_box(3, b)) .and. &
               all(fast%wheel_z(i1:i2) <= fast%wheel_box(4, b))
         end do
         call check(error, inside, message='a yawed wheel sample lies outside its block bounds')
         if (allocated(error)) return
         reference = fast
         reference%options%reference_search = .true.
         call check_fast_scan(fast, reference, error, first=-9.3_wp, step=1.49_wp, count=14)
         if (allocated(error)) return
      end do
   end subroutine test_fast_yawed

   !> The fast search against the reference search with the wheelset rolled (the block bounds
   !> of the wheel samples turned with it), right and left wheel, short tables.
   subroutine test_fast_rolled(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: rolls(*) = [-0.05_wp, -0.004_wp, 0.0025_wp, 0.03_wp]
      type(prepared_profiles_type) :: fast, reference
      type(profile_type) :: wheel, rail
      type(lib_error), allocatable :: err_a, err_b
      type(contact_patches_type) :: a, b
      type(wheelset_position_type) :: position
      integer :: i, j, k, side, n, found

      call builtin_profile('S1002', wheel, err_a)
      if (.not. allocated(err_a)) call builtin_profile('UIC60', rail, err_a)
      if (.not. allocated(err_a)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(table_gap=0.5_wp), fast, err_a)
      if (allocated(err_a)) then
         call test_failed(error, err_a%message); return
      end if
      reference = fast
      reference%options%reference_search = .true.
      found = 0
      do j = 1, size(rolls)
         do side = -1, 1, 2
            do i = -4, 4
               position = wheelset_position_type(side=side, y_ws=2.1_wp*i, roll=rolls(j))
               call find_contact_patches(fast, position, a, err_a)
               call find_contact_patches(reference, position, b, err_b)
               call check(error, allocated(err_a) .eqv. allocated(err_b), &
                  message='fast and reference search disagree on success (rolled)')
               if (allocated(error)) return
               if (allocated(err_a)) cycle
               found = found + 1
               call check(error, a%count, b%count, message='number of patches (rolled)')
               if (allocated(error)) return
               do k = 1, a%count
                  n = a%points(k)
                  call check(error, n, b%points(k), message='table points (rolled)')
                  if (allocated(error)) return
                  associate (p => a%patch(k), q => b%patch(k))
                     call check(error, abs(p%y_track - q%y_track) <= 1.0e-10_wp .and. &
                        abs(p%gamma0 - q%gamma0) <= 1.0e-9_wp .and. &
                        maxval(abs(p%gap(1:n) - q%gap(1:n))) <= 1.0e-9_wp .and. &
                        maxval(abs(p%curv_a(1:n) - q%curv_a(1:n))/q%curv_a(1:n)) <= 1.0e-9_wp &
                        .and. maxval(abs(p%curv_b(1:n) - q%curv_b(1:n))/q%curv_b(1:n)) <= &
                        1.0e-9_wp, message='rolled wheel: fast and reference patches differ')
                     if (allocated(error)) return
                  end associate
               end do
            end do
         end do
      end do
      call check(error, found >= 50, message='expected contact at most rolled positions')
   end subroutine test_fast_rolled

end module test_geometry
