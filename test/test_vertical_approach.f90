!> The approach is a vertical translation of the wheel (doc/geometry.md "Vertical approach";
!> shcontact_normal_semihertz): the interpenetration δ − g(y) − (δ + g₀)c(y) with
!> c = tan γ₀ tan(γ(y) − γ₀), and the strips referred to the geometric contact point of the
!> loaded state. Checked on an analytic patch (closed form) and against CONTACT's undeformed
!> distance h of module 1 at eighteen wheel positions (data/exact/*/h_module1_row.csv).
module test_vertical_approach
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_real
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type
   use shcontact_geometry_contact, only: contact_options_type, find_contact_patches, &
      prepared_profiles_type, prepare_profiles, prepare_wheel
   use shcontact_geometry_kinematics, only: yawed_wheel_profile
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, reduction_local_hertz, &
      slide_exact, slide_linear
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_semihertz, only: loaded_gap
   use shcontact_normal_angles, only: vertical_tilt
   use test_semihertz, only: polynomial_patch
   use test_validation, only: read_columns, manchester_profiles, &
      skip_without_profiles, summary_values
   implicit none
   private
   public :: collect_vertical_approach

   !> The project's CONTACT positions (data/exact/, README there).
   !> Y_WS = 7 mm (yws7p0, a 69.7° flange) is not among them: there our loaded gap differs from
   !> CONTACT's h by more than this test's 4 % + 0.2 µm: the finite slide of the vertical approach
   !> carries the flange root towards the contact there (test flange_root_slide, doc/validation.md
   !> §6.8 "Yaw and the flange root").
   character(len=*), parameter :: positions(18) = [character(len=7) :: 'yws-6p0', 'yws-4p0', &
      'yws-2p0', 'yws-1p0', 'yws0p5', 'yws0p75', 'yws1p0', 'yws1p25', 'yws1p5', 'yws2p0', &
      'yws2p5', 'yws3p0', 'yws3p5', 'yws4p0', 'yws4p4', 'yws4p6', 'yws6p0', 'yws6p5']

contains

   !> Collect the tests.
   subroutine collect_vertical_approach(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('tilted_hertz_contact_follows_loaded_gap', test_tilted_hertz), &
         new_unittest('flat_contact_keeps_first_contact', test_flat), &
         new_unittest('loaded_gap_is_contacts_h', test_contact_h), &
         new_unittest('flange_root_slide', test_flange_root_slide), &
         new_unittest('flange_root_exact_slide', test_flange_root_exact_slide), &
         new_unittest('flange_loaded_gap_exact_slide', test_flange_loaded_gap) &
         ]
   end subroutine collect_vertical_approach

   !> g = B y², constant A and B, and a contact angle turning across the patch as on a flange
   !> root, γ = γ₀ + κ y (γ₀ = −0.5 rad, κ = 0.05 rad/mm). The loaded gap
   !> B y² + δ tan γ₀ tan(κ y) is a parabola whose minimum y* solves 2B y + δ tan γ₀ κ/cos²(κ y)
   !> = 0: the strips must be referred to y*, and the contact (where δ_i > 0) is symmetric about
   !> it up to the tangent's cubic term. Without the vertical approach both stay at y = 0.
   subroutine test_tilted_hertz(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: curv_a = 1.0_wp/920, curv_b = 0.005_wp, gamma0 = -0.5_wp, &
         kappa = 0.05_wp
      type(patch_geometry_type) :: geom
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(lib_error), allocatable :: err
      real(wp) :: y_star, y_lo, y_hi, s, d
      integer :: it, slide

      call polynomial_patch(geom, curv_a, curv_b, 12.0_wp, 0.01_wp, gamma0=gamma0)
      geom%gamma = gamma0 + kappa*geom%y
      do slide = slide_exact, slide_linear
         call prepare_normal_contact(contact, geom, normal_options_type(reduction= &
            reduction_local_hertz, slide=slide), material_type(), err)
         if (.not. allocated(err)) call solve_load(contact, 64700.0_wp, patch, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         s = patch%approach*tan(gamma0)*kappa
         ! The exact slide: the wheel point above y is the one at y + d, d = −δ tan γ₀, and the
         ! loaded gap's slope is 2B y − tan(κ(y + d)) + tan(κ y).
         d = 0.0_wp
         if (slide == slide_exact) d = -patch%approach*tan(gamma0)
         y_star = 0.0_wp
         do it = 1, 20
            if (slide == slide_exact) then
               y_star = y_star - (2*curv_b*y_star - tan(kappa*(y_star + d)) + &
                  tan(kappa*y_star))/(2*curv_b - kappa/cos(kappa*(y_star + d))**2 + &
                  kappa/cos(kappa*y_star)**2)
            else
               y_star = y_star - (2*curv_b*y_star + s/cos(kappa*y_star)**2)/ &
                  (2*curv_b + 2*s*kappa*tan(kappa*y_star)/cos(kappa*y_star)**2)
            end if
         end do
         call check(error, abs(y_star) > 0.1_wp, message='the test patch should shift by > 0.1 mm')
         if (allocated(error)) return
         call check(error, patch%y_shift, y_star, thr=2.0e-4_wp, &
            message='reference point at the minimum of the loaded gap')
         if (allocated(error)) return
         call check(error, patch%gamma0, gamma0 + kappa*(y_star + d), thr=1.0e-5_wp, &
            message='contact angle at the reference point (the wheel''s point there)')
         if (allocated(error)) return
         ! The rolling radius is the slid wheel point's with either slide (the wheel's material
         ! above y* after the vertical approach; the linear slide keeps only the gap unslid).
         call check(error, patch%r0, geom%r0 + 4.0e-2_wp*(y_star - patch%approach* &
            tan(gamma0)), thr=1.0e-5_wp, message='rolling radius at the reference point '// &
            '(the slid wheel point''s)')
         if (allocated(error)) return
         call check(error, patch%gamma_plane, gamma0, message='contact plane of the first contact')
         if (allocated(error)) return
         y_lo = patch%y(1) - 0.5_wp*patch%dy
         y_hi = patch%y(patch%n_strips) + 0.5_wp*patch%dy
         ! Strips are measured from y*: the contact is symmetric about 0.
         call check(error, 0.5_wp*(y_lo + y_hi), 0.0_wp, thr=0.01_wp, &
            message='contact symmetric about the loaded geometric point')
         if (allocated(error)) return
         call check(error, maxval(abs(patch%delta_r(1:patch%n_strips) - 4.0e-2_wp*patch%y(1: &
            patch%n_strips))), 0.0_wp, thr=1.0e-9_wp, message='delta_r from the reference point')
         if (allocated(error)) return
      end do
   end subroutine test_tilted_hertz

   !> A flat contact (γ₀ = 0): the tilt vanishes whatever γ(y) does, and the reference point
   !> stays at the first contact, bit for bit.
   subroutine test_flat(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geom
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(lib_error), allocatable :: err

      call polynomial_patch(geom, 1.0_wp/920, 1.0_wp/600, 12.0_wp, 0.01_wp)
      geom%gamma = 0.05_wp*geom%y
      call check(error, maxval(abs(vertical_tilt(geom%gamma, 0.0_wp))), 0.0_wp, &
         message='no tilt on a flat contact')
      if (allocated(error)) return
      call prepare_normal_contact(contact, geom, normal_options_type(), material_type(), err)
      if (.not. allocated(err)) call solve_load(contact, 64700.0_wp, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%y_shift, 0.0_wp, message='reference point moved on a flat contact')
   end subroutine test_flat

   !> Our loaded gap g(y) + δ c(y) at CONTACT's approach δ against CONTACT's undeformed
   !> distance h of module 1 along the row through its geometric point G (scripts/
   !> contact_gap_rows.py), both from their minima: |Δ| ≤ 0.04 h + 2e-4 mm where h ≤ 0.05 mm (linear interpolation of the 0.2 mm grid costs
   !> up to B·0.2²/4 ≈ 1e-4 mm). And the point itself: ours (first contact + y_shift along
   !> the plane) within 0.01 mm of CONTACT's G on the rail profile, where at Y_WS = 6.5 mm the
   !> first contact lies 0.25 mm away.
   subroutine test_contact_h(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(lib_error), allocatable :: err
      real(wp), allocatable :: rows(:, :), info(:, :), tilt(:), loaded(:)
      real(wp) :: y_ws, y_geo, pen, ycp_r, delt, ycp_tr, d, ours, theirs, worst, g_rail, first
      integer :: ip, k, best, im, j
      character(len=:), allocatable :: dir

      call skip_without_profiles(error)
      if (allocated(error)) return
      call manchester_profiles(wheel, rail, track, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do ip = 1, size(positions)
         dir = 'data/exact/'//trim(positions(ip))//'/'
         call summary_values(dir//'summary.csv', y_ws, y_geo, pen, ycp_r, delt, ycp_tr, error)
         if (allocated(error)) return
         call read_columns(dir//'h_module1_row.csv', [character(len=4) :: 'y_mm', 'h_mm'], &
            rows, error)
         if (allocated(error)) return
         call find_contact_patches(wheel, rail, track, wheelset_position_type(y_ws=y_ws), &
            contact_options_type(), geometry, err)
         if (allocated(err)) then
            call test_failed(error, trim(positions(ip))//': '//err%message); return
         end if
         best = 1
         do k = 2, size(geometry)
            if (abs(geometry(k)%y_track - ycp_tr) < abs(geometry(best)%y_track - ycp_tr)) best = k
         end do
         associate (g => geometry(best))
            call prepare_normal_contact(contact, g, normal_options_type(), material_type(), err)
            if (.not. allocated(err)) call solve_load(contact, 64700.0_wp, patch, err)
            if (allocated(err)) then
               call test_failed(error, trim(positions(ip))//': '//err%message); return
            end if
            tilt = vertical_tilt(g%gamma, g%gamma0)
            loaded = g%gap + pen*tilt
            im = minloc(loaded, dim=1)
            worst = 0.0_wp
            do j = -30, 30
               d = 0.1_wp*j
               theirs = interpolate(rows(:, 1), rows(:, 2), y_geo + d) - &
                  interpolate(rows(:, 1), rows(:, 2), y_geo)
               if (.not. (theirs <= 0.05_wp)) cycle
               ours = interpolate(g%y, loaded, g%y(im) + d) - loaded(im)
               worst = max(worst, abs(ours - theirs)/(0.04_wp*theirs + 2.0e-4_wp))
            end do
            call check(error, worst <= 1.0_wp, message=trim(positions(ip))// &
               ': loaded gap differs from CONTACT''s h by more than 4 % + 0.2 um')
            if (allocated(error)) return
            ! Rail-profile y of CONTACT's G and of ours.
            g_rail = ycp_r + y_geo*cos(delt)
            first = g%y_rail
            call check(error, g%y_rail + patch%y_shift*cos(g%gamma0), g_rail, thr=0.01_wp, &
               message=trim(positions(ip))//': loaded geometric point on the rail profile')
            if (allocated(error)) return
            if (positions(ip) == 'yws6p5') then
               call check(error, abs(first - g_rail) > 0.2_wp, message='yws6p5: the first '// &
                  'contact should lie > 0.2 mm from CONTACT''s G (the case the tilt is for)')
               if (allocated(error)) return
            end if
         end associate
      end do
   end subroutine test_contact_h

   !> S1002 / UIC60 1:40 at Y_WS = 7 mm, the straight 70° flange face against the gauge corner,
   !> yaw 0 and 8 mrad (the contact locus), against CONTACT's undeformed distance h of the loaded
   !> state at F_z = 30, 64.7 and 97 kN (frictionless, conformal approach; per grid row s the
   !> smallest h over x, data/exact/kinematic_flange/h_rows_7mm.csv, scripts/
   !> contact_flange_slide.py). The distance from the gap's minimum to the flange root (where the
   !> gap leaves the face's parabola by 0.003 mm, [[root_distance]]) in our first-contact table
   !> and in CONTACT's h: the face's curvature within 2 %; yaw's shift of the root (0.165 mm in
   !> ours) within 0.02 mm of CONTACT's at every load; and CONTACT's loaded distance is ours less
   !> the slide of the vertical approach along the face, δ tan|δ_cp| (0.28–0.57 mm), within
   !> 0.08 mm, while without the slide the two differ by more than 0.2 mm (doc/validation.md
   !> §6.8, "Yaw and the flange root": the slide that our tilt term, linear in the wheel's slope,
   !> does not make on the straight face).
   subroutine test_flange_root_slide(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: yaws(2) = [0.0_wp, 0.008_wp], loads(3) = [30000.0_wp, &
         64700.0_wp, 97000.0_wp]
      type(patch_geometry_type), allocatable :: geometry(:)
      real(wp), allocatable :: rows(:, :)
      real(wp) :: ours(2), b_ours(2), theirs(3, 2), b_theirs, slide(3, 2)
      logical, allocatable :: this(:)
      integer :: j, k

      do j = 1, size(yaws)
         call flange_geometry(7.0_wp, yaws(j), geometry, error)
         if (allocated(error)) return
         call root_distance(geometry(1)%y, geometry(1)%gap, 0.1_wp, ours(j), b_ours(j))
      end do
      call read_columns('data/exact/kinematic_flange/h_rows_7mm.csv', [character(len=11) :: &
         'fz_N', 'yaw_rad', 'approach_mm', 'delta_rad', 's_mm', 'h_mm'], rows, error)
      if (allocated(error)) return
      do k = 1, size(loads)
         do j = 1, size(yaws)
            this = abs(rows(:, 1) - loads(k)) < 1.0_wp .and. abs(rows(:, 2) - yaws(j)) < 1.0e-6_wp
            call check(error, count(this) > 20, message='too few CONTACT rows')
            if (allocated(error)) return
            associate (s => pack(rows(:, 5), this), h => pack(rows(:, 6), this))
               call root_distance(s, h, s(minloc(h, dim=1)) + 0.1_wp, theirs(k, j), b_theirs)
            end associate
            slide(k, j) = maxval(pack(rows(:, 3)*abs(tan(rows(:, 4))), this))
            call check(error, b_theirs, b_ours(j), rel=.true., thr=0.02_wp, &
               message='the flange face''s curvature B')
            if (allocated(error)) return
            call check(error, ours(j) - slide(k, j), theirs(k, j), thr=0.08_wp, &
               message='CONTACT''s loaded root distance = ours less the slide')
            if (allocated(error)) return
            call check(error, abs(ours(j) - theirs(k, j)) > 0.2_wp, &
               message='the slide should be what separates the root distances')
            if (allocated(error)) return
         end do
         call check(error, ours(2) - ours(1), theirs(k, 2) - theirs(k, 1), thr=0.02_wp, &
            message='yaw''s shift of the flange root')
         if (allocated(error)) return
      end do
      call check(error, ours(2) - ours(1) > 0.1_wp, message='yaw should move the root away')
   end subroutine test_flange_root_slide

   !> The same position and CONTACT rows as [[test_flange_root_slide]], now our undeformed
   !> distance of the loaded state itself (shcontact_normal_semihertz's loaded_gap at CONTACT's
   !> approach) against CONTACT's h: with `slide = 'exact'` the distance from its minimum to the
   !> flange root is CONTACT's within 0.03 mm (0.017 found) at every load and yaw (the wheel's offset taken
   !> where the vertical approach has slid it, doc/geometry.md "Vertical approach"); with the
   !> linear slide it stays more than 0.2 mm farther (the fillet does not move).
   subroutine test_flange_root_exact_slide(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: yaws(2) = [0.0_wp, 0.008_wp], loads(3) = [30000.0_wp, &
         64700.0_wp, 97000.0_wp]
      type(normal_contact_type) :: exact, linear
      real(wp), allocatable :: rows(:, :), y(:), gap(:)
      real(wp) :: theirs, ours, first, b, approach
      logical, allocatable :: this(:)
      integer :: j, k, n

      call read_columns('data/exact/kinematic_flange/h_rows_7mm.csv', [character(len=11) :: &
         'fz_N', 'yaw_rad', 'approach_mm', 'delta_rad', 's_mm', 'h_mm'], rows, error)
      if (allocated(error)) return
      do j = 1, size(yaws)
         call flange_both_slides(7.0_wp, yaws(j), exact, linear, y, error)
         if (allocated(error)) return
         n = size(y)
         allocate (gap(n))
         do k = 1, size(loads)
            this = abs(rows(:, 1) - loads(k)) < 1.0_wp .and. abs(rows(:, 2) - yaws(j)) < 1.0e-6_wp
            call check(error, count(this) > 20, message='too few CONTACT rows')
            if (allocated(error)) return
            associate (s => pack(rows(:, 5), this), h => pack(rows(:, 6), this))
               call root_distance(s, h, s(minloc(h, dim=1)) + 0.1_wp, theirs, b)
            end associate
            approach = maxval(pack(rows(:, 3), this))
            call loaded_gap(exact%geometry, approach, gap)
            call root_distance(y, gap, y(minloc(gap, dim=1)) + 0.1_wp, ours, b)
            call loaded_gap(linear%geometry, approach, gap)
            call root_distance(y, gap, y(minloc(gap, dim=1)) + 0.1_wp, first, b)
            call check(error, ours, theirs, thr=0.03_wp, &
               message='the root distance of the loaded gap, exact slide, against CONTACT''s')
            if (allocated(error)) return
            call check(error, first - theirs > 0.1_wp, &
               message='the linear slide should leave the root farther than CONTACT''s')
            if (allocated(error)) return
         end do
         deallocate (gap)
      end do
   end subroutine test_flange_root_exact_slide

   !> CONTACT's planar undeformed distance h of the loaded state on the flange (Y_WS 7.0, 7.5,
   !> 8.0, 8.5 mm, yaw 0 and 8 mrad, frictionless, F_z = 64.7 kN; data/exact/kinematic_flange/
   !> h_rows_planar.csv, scripts/contact_flange_slide.py --approach planar --write-rows) against
   !> our loaded gap at CONTACT's approach, both less their minimum (each refined by a parabola):
   !> with `slide = 'exact'` within 2 µm wherever |s − s_min| ≤ 1.6 mm (0.09–0.6 µm found;
   !> CONTACT's h reaches 0.09–0.16 mm there), with the linear slide more than 1.5 µm and three
   !> times as far off at every state (2.2–22 µm found, the least on 7.5 mm's straight face).
   !> The gap is right with the exact slide; what separates our flange F_n from CONTACT's is the
   !> direction CONTACT gives its pressure (doc/validation.md §6.8).
   subroutine test_flange_loaded_gap(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: reach = 1.6_wp
      type(normal_contact_type) :: exact, linear
      real(wp), allocatable :: rows(:, :), y(:), gap(:)
      real(wp) :: worst(2), s0, h0
      logical, allocatable :: this(:), done(:)
      integer :: k, n, m, r

      call read_columns('data/exact/kinematic_flange/h_rows_planar.csv', [character(len=11) :: &
         'y_ws_mm', 'yaw_rad', 'approach_mm', 's_mm', 'h_mm'], rows, error)
      if (allocated(error)) return
      allocate (done(size(rows, 1)), source=.false.)
      m = 0
      do r = 1, size(rows, 1)
         if (done(r)) cycle
         this = abs(rows(:, 1) - rows(r, 1)) < 1.0e-6_wp .and. &
            abs(rows(:, 2) - rows(r, 2)) < 1.0e-6_wp
         done = done .or. this
         m = m + 1
         call flange_both_slides(rows(r, 1), rows(r, 2), exact, linear, y, error)
         if (allocated(error)) return
         n = size(y)
         if (allocated(gap)) deallocate (gap)
         allocate (gap(n))
         associate (s => pack(rows(:, 4), this), h => pack(rows(:, 5), this))
            call check(error, size(s) > 12, message='too few CONTACT rows')
            if (allocated(error)) return
            call parabola_minimum(s, h, s0, h0)
            do k = 1, 2
               if (k == 1) then
                  call loaded_gap(exact%geometry, rows(r, 3), gap)
               else
                  call loaded_gap(linear%geometry, rows(r, 3), gap)
               end if
               worst(k) = gap_miss(y, gap, s, h, s0, h0, reach)
            end do
         end associate
         call check(error, worst(1) <= 2.0e-3_wp, message='Y_WS '//str_real(rows(r, 1))// &
            ' mm, yaw '//str_real(rows(r, 2))//': exact slide''s loaded gap '// &
            str_real(worst(1))//' mm from CONTACT''s h')
         if (allocated(error)) return
         call check(error, worst(2) > max(1.5e-3_wp, 3.0_wp*worst(1)), message='Y_WS '// &
            str_real(rows(r, 1))// &
            ' mm, yaw '//str_real(rows(r, 2))//': the linear slide should miss CONTACT''s h, '// &
            str_real(worst(2))//' mm')
         if (allocated(error)) return
      end do
      call check(error, m == 8, message='expected 8 flange states, found '// &
         str_real(real(m, wp)))
   end subroutine test_flange_loaded_gap

   !> The minimum (s0, h0) of rows h(s): the parabola through the smallest row and its neighbours.
   pure subroutine parabola_minimum(s, h, s0, h0)
      real(wp), intent(in) :: s(:), h(:)
      real(wp), intent(out) :: s0, h0
      real(wp) :: c(3)
      integer :: i
      i = min(max(minloc(h, dim=1), 2), size(h) - 1)
      c = solve3(reshape([s(i - 1:i + 1)**2, s(i - 1:i + 1), [1.0_wp, 1.0_wp, 1.0_wp]], [3, 3]), &
         h(i - 1:i + 1))
      s0 = -c(2)/(2.0_wp*c(1))
      h0 = c(3) - c(2)**2/(4.0_wp*c(1))
   end subroutine parabola_minimum

   !> The largest |(g − g_min) − (h − h0)| over CONTACT's rows within `reach` of s0, our gap g on
   !> the table y taken at y_min + (s − s0) (y_min, g_min: its parabola-refined minimum).
   pure real(wp) function gap_miss(y, g, s, h, s0, h0, reach) result(miss)
      real(wp), intent(in) :: y(:), g(:), s(:), h(:), s0, h0, reach
      real(wp) :: y0, g0
      integer :: k
      call parabola_minimum(y, g, y0, g0)
      miss = 0.0_wp
      do k = 1, size(s)
         if (abs(s(k) - s0) > reach) cycle
         miss = max(miss, abs(interpolate(y, g, y0 + s(k) - s0) - g0 - (h(k) - h0)))
      end do
   end function gap_miss

   !> The one patch of S1002 / UIC60 (canted) at Y_WS = y_ws (mm) with the wheel yawed by `yaw`
   !> (rad; its contact locus, shcontact_geometry_kinematics).
   !> The flange patch of [[flange_geometry]] prepared with the exact and with the linear slide
   !> of the vertical approach, and its table abscissae y (mm).
   subroutine flange_both_slides(y_ws, yaw, exact, linear, y, error)
      real(wp), intent(in) :: y_ws, yaw
      type(normal_contact_type), intent(out) :: exact, linear
      real(wp), allocatable, intent(out) :: y(:)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type), allocatable :: geometry(:)
      type(lib_error), allocatable :: err
      integer :: i, n
      call flange_geometry(y_ws, yaw, geometry, error)
      if (allocated(error)) return
      call prepare_normal_contact(exact, geometry(1), normal_options_type(slide=slide_exact), &
         material_type(), err)
      if (.not. allocated(err)) call prepare_normal_contact(linear, geometry(1), &
         normal_options_type(slide=slide_linear), material_type(), err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      n = exact%geometry%n_table
      y = [(exact%geometry%y_first + (i - 1)*exact%geometry%h, i=1, n)]
   end subroutine flange_both_slides

   subroutine flange_geometry(y_ws, yaw, geometry, error)
      real(wp), intent(in) :: y_ws, yaw
      type(patch_geometry_type), allocatable, intent(out) :: geometry(:)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: wheel, rail, locus
      type(track_type) :: track
      type(prepared_profiles_type) :: unyawed, yawed
      type(lib_error), allocatable :: err

      track%rail_canted = .true.
      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60-canted', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track, &
         contact_options_type(), unyawed, err)
      if (.not. allocated(err)) then
         yawed = unyawed
         call yawed_wheel_profile(wheel, unyawed%wheel, track, unyawed%z_tape, yaw, locus)
         call prepare_wheel(locus, track, contact_options_type(), yawed, err)
      end if
      if (.not. allocated(err)) call find_contact_patches(yawed, &
         wheelset_position_type(y_ws=y_ws), geometry, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, size(geometry) == 1, message='one patch expected on the flange')
   end subroutine flange_geometry

   !> Distance (mm) from the minimum of a gap h(s) to the flange root: a least-squares parabola
   !> through the points with s < s_face and h < 0.15 mm (the flange face), and the first s
   !> beyond its vertex where h lies 0.003 mm below it (linear interpolation); b its curvature.
   pure subroutine root_distance(s, h, s_face, distance, b)
      real(wp), intent(in) :: s(:), h(:), s_face
      real(wp), intent(out) :: distance, b
      real(wp) :: m(3, 3), r(3), c(3), s0, dev, dev_prev
      integer :: i, p, q

      m = 0.0_wp
      r = 0.0_wp
      do i = 1, size(s)
         if (.not. (s(i) < s_face .and. h(i) < 0.15_wp)) cycle
         do p = 1, 3
            do q = 1, 3
               m(p, q) = m(p, q) + s(i)**(p + q - 2)
            end do
            r(p) = r(p) + h(i)*s(i)**(p - 1)
         end do
      end do
      c = solve3(m, r)
      b = c(3)
      s0 = -c(2)/(2.0_wp*c(3))
      distance = huge(1.0_wp)
      dev_prev = 0.0_wp
      do i = 1, size(s)
         dev = c(1) + s(i)*(c(2) + s(i)*c(3)) - h(i)
         if (s(i) > s0 .and. dev > 0.003_wp .and. i > 1) then
            distance = s(i - 1) + (0.003_wp - dev_prev)/(dev - dev_prev)*(s(i) - s(i - 1)) - s0
            return
         end if
         dev_prev = dev
      end do
   end subroutine root_distance

   !> x with m x = r (3 × 3, Cramer's rule; m well conditioned here).
   pure function solve3(m, r) result(x)
      real(wp), intent(in) :: m(3, 3), r(3)
      real(wp) :: x(3), a(3, 3), d
      integer :: k
      d = det3(m)
      do k = 1, 3
         a = m
         a(:, k) = r
         x(k) = det3(a)/d
      end do
   end function solve3

   pure real(wp) function det3(a)
      real(wp), intent(in) :: a(3, 3)
      det3 = a(1, 1)*(a(2, 2)*a(3, 3) - a(2, 3)*a(3, 2)) - a(1, 2)*(a(2, 1)*a(3, 3) - &
         a(2, 3)*a(3, 1)) + a(1, 3)*(a(2, 1)*a(3, 2) - a(2, 2)*a(3, 1))
   end function det3

   !> Linear interpolation of (x, f) at t (x increasing; clamped at the ends).
   pure real(wp) function interpolate(x, f, t) result(v)
      real(wp), intent(in) :: x(:), f(:), t
      integer :: i
      if (t <= x(1)) then
         v = f(1)
         return
      end if
      do i = 2, size(x)
         if (t <= x(i)) then
            v = f(i - 1) + (f(i) - f(i - 1))*(t - x(i - 1))/(x(i) - x(i - 1))
            return
         end if
      end do
      v = f(size(x))
   end function interpolate

end module test_vertical_approach
