!> Tests of the wheelset contact geometry over the lateral shift and of the equivalent conicity
!> (doc/geometry.md, *Wheelset contact geometry and equivalent conicity*): a conical wheel on a
!> circular rail head against the closed form with roll, both conicity methods against exact
!> results for a two-slope Δr, and S1002/UIC60 1:40 (symmetry, the comparison bounds, the
!> numbers doc/geometry.md quotes from the program).
module test_wheelset_geometry
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use test_external_data, only: external_file
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, profile_kind_rail
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_profile_source, only: load_profile
   use shcontact_geometry_track, only: track_type
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      prepare_profiles
   use shcontact_geometry_wheelset_table, only: wheelset_contact_type, wheelset_geometry_table, &
      roll_angle_parameter, contact_distance, wheelset_contact
   use shcontact_geometry_conicity, only: equivalent_conicity, conicity_en15302, &
      conicity_harmonic, first_harmonic_slope
   use test_geometry, only: arc_rail, cone_wheel, upright_track
   use test_app, only: unavailable, scratch_directory, run_program, file_text, expect_in
   implicit none
   private
   public :: collect_wheelset_geometry

   !> The cone: tread angle (rad) and the rail head radius (mm) of the closed-form case.
   real(wp), parameter :: cone_angle = 0.05_wp, head_radius = 80.0_wp
   !> Nominal radius (mm) and the lateral position of the tape circle from the wheelset centre
   !> (mm: flange-back distance/2 − flange-back position = 680 + 70).
   real(wp), parameter :: r_nom = 460.0_wp, tape_arm = 750.0_wp

contains

   subroutine collect_wheelset_geometry(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('cone_on_circle_closed_form', test_cone_closed_form), &
         new_unittest('cone_conicity', test_cone_conicity), &
         new_unittest('two_slope_conicity_exact', test_two_slope), &
         new_unittest('s1002_uic60_symmetry_and_bounds', test_s1002_bounds), &
         new_unittest('manchester_files_agree', test_manchester_files), &
         new_unittest('program_tables', test_program), &
         new_unittest('climbing_note_miniprof_wheel', test_climbing_miniprof)]
   end subroutine collect_wheelset_geometry

   ! ------------------------------------------------------------------------------------------
   ! Closed form: cone of slope λ = tan γc on a rail head circle of radius R (doc/geometry.md)
   ! ------------------------------------------------------------------------------------------

   !> The wheelset on a cone/circle pair at shift y, from the closed form: the roll φ solves
   !> (K + R)(1/cos α_L − 1/cos α_R) = tan α_L (Y + y) + tan α_R (Y − y), α_R,L = φ ∓ γc,
   !> K = r_nom cos γc + l_t sin γc, Y the circle centres' |y|; then the contact points, the
   !> rolling radii and the angles follow explicitly.
   subroutine cone_closed_form(y, row)
      real(wp), intent(in) :: y
      type(wheelset_contact_type), intent(out) :: row
      real(wp) :: lam, gc, k, yr, zr, lo, hi, phi, ar, al, zc, pr(2), pl(2), eta_r, eta_l
      integer :: it
      lam = tan(cone_angle)
      gc = cone_angle
      k = r_nom*cos(gc) + tape_arm*sin(gc)
      ! Gauge point 14 mm below the top at y = 717.5; the top at z = 0.
      yr = 717.5_wp + head_radius*sqrt(1.0_wp - (1.0_wp - 14.0_wp/head_radius)**2)
      zr = head_radius
      lo = -0.1_wp
      hi = 0.1_wp
      do it = 1, 200
         phi = 0.5_wp*(lo + hi)
         if (balance(phi)*balance(lo) > 0.0_wp) then
            lo = phi
         else
            hi = phi
         end if
      end do
      phi = 0.5_wp*(lo + hi)
      ar = phi - gc
      al = phi + gc
      zc = zr - (k + head_radius)/cos(ar) - tan(ar)*(yr - y)
      pr = [yr + head_radius*sin(ar), zr - head_radius*cos(ar)]
      pl = [-yr + head_radius*sin(al), zr - head_radius*cos(al)]
      eta_r = cos(gc)*(dot_product([cos(ar), sin(ar)], pr - [y, zc]) + sin(gc)*(r_nom + &
         lam*tape_arm))
      eta_l = cos(gc)*(dot_product([cos(al), sin(al)], pl - [y, zc]) - sin(gc)*(r_nom + &
         lam*tape_arm))
      row%y = y
      row%roll = phi
      row%z_centre = zc
      row%rail_y = [pr(1), pl(1)]
      row%wheel_y = [eta_r - tape_arm, -eta_l - tape_arm]
      row%radius = [r_nom - lam*(eta_r - tape_arm), r_nom - lam*(-eta_l - tape_arm)]
      row%gamma = [ar, -al]
   contains
      real(wp) function balance(p)
         real(wp), intent(in) :: p
         balance = (k + head_radius)*(1.0_wp/cos(p + gc) - 1.0_wp/cos(p - gc)) &
            - tan(p + gc)*(yr + y) - tan(p - gc)*(yr - y)
      end function balance
   end subroutine cone_closed_form

   !> The cone wheel and the circular rail head in the library.
   subroutine cone_table(y, table, error)
      real(wp), intent(in) :: y(:)
      type(wheelset_contact_type), allocatable, intent(out) :: table(:)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call wheelset_geometry_table(cone_wheel(-cone_angle, 40.0_wp, 161), &
         arc_rail(head_radius, -0.7_wp, 0.5_wp, 481), upright_track(), contact_options_type(), &
         y, table, err)
      if (allocated(err)) call test_failed(error, 'wheelset_geometry_table: '//err%message)
   end subroutine cone_table

   !> Every column against the closed form, −8 ≤ y ≤ 8 mm. Tolerances: the arc is sampled every
   !> 0.15 mm and splined (positions to ~1e-8 mm, doc/geometry.md); the roll to 1e-9 rad.
   subroutine test_cone_closed_form(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_contact_type), allocatable :: table(:)
      type(wheelset_contact_type) :: exact
      integer :: i
      call cone_table([(-8.0_wp + 2.0_wp*i, i=0, 8)], table, error)
      if (allocated(error)) return
      do i = 1, size(table)
         call cone_closed_form(table(i)%y, exact)
         call check(error, table(i)%roll, exact%roll, thr=1.0e-9_wp, message='roll')
         if (allocated(error)) return
         call check(error, table(i)%z_centre, exact%z_centre, thr=1.0e-6_wp, message='z_centre')
         if (allocated(error)) return
         call check(error, all(abs(table(i)%rail_y - exact%rail_y) < 1.0e-6_wp), &
            'rail contact points')
         if (allocated(error)) return
         call check(error, all(abs(table(i)%wheel_y - exact%wheel_y) < 1.0e-6_wp), &
            'wheel contact points')
         if (allocated(error)) return
         call check(error, all(abs(table(i)%radius - exact%radius) < 1.0e-7_wp), &
            'rolling radii')
         if (allocated(error)) return
         call check(error, table(i)%delta_r(), exact%delta_r(), thr=1.0e-7_wp, message='dr')
         if (allocated(error)) return
         call check(error, all(abs(table(i)%gamma - exact%gamma) < 1.0e-9_wp), 'contact angles')
         if (allocated(error)) return
         call check(error, all(table(i)%patches == 1), 'one patch per wheel')
         if (allocated(error)) return
      end do
      call single_row(error)
   contains
      !> One shift from prepared profiles (wheelset_contact) gives the table's row.
      subroutine single_row(error)
         type(error_type), allocatable, intent(out) :: error
         type(prepared_profiles_type), target :: prepared
         type(wheelset_contact_type) :: row
         type(lib_error), allocatable :: err
         call prepare_profiles(cone_wheel(-cone_angle, 40.0_wp, 161), &
            arc_rail(head_radius, -0.7_wp, 0.5_wp, 481), upright_track(), &
            contact_options_type(), prepared, err)
         if (.not. allocated(err)) call wheelset_contact(prepared, table(7)%y, row, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         call check(error, row%roll, table(7)%roll, thr=1.0e-12_wp, message='single row roll')
         if (allocated(error)) return
         call check(error, all(abs(row%radius - table(7)%radius) < 1.0e-9_wp), 'single row radii')
      end subroutine single_row
   end subroutine test_cone_closed_form

   !> The cone's Δr is linear in y to 1e-6 relative (its roll is), so both methods give its slope
   !> Δr(ŷ)/(2ŷ) at every amplitude: tan γc (1 + λ(R + r_nom)/(Y − λ(K + R))) to first order,
   !> 3.7 % above tan γc, the roll's share (without roll Δr = 2y tan γc exactly).
   subroutine test_cone_conicity(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_contact_type), allocatable :: table(:)
      type(wheelset_contact_type) :: exact
      type(lib_error), allocatable :: err
      real(wp), parameter :: amplitudes_cone(3) = [1.0_wp, 3.0_wp, 6.0_wp]
      real(wp) :: amplitude, tan_en, tan_h, slope
      integer :: i, k
      call cone_table([(-8.0_wp + 0.25_wp*i, i=0, 64)], table, error)
      if (allocated(error)) return
      do k = 1, 3
         amplitude = amplitudes_cone(k)
         call cone_closed_form(amplitude, exact)
         slope = exact%delta_r()/(2.0_wp*amplitude)
         call equivalent_conicity(shifts_of(table), dr_of(table), amplitude, tan_en, err, &
            conicity_en15302)
         if (.not. allocated(err)) call equivalent_conicity(shifts_of(table), dr_of(table), &
            amplitude, tan_h, err, conicity_harmonic)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         call check(error, tan_en, slope, thr=1.0e-7_wp, message='EN 15302 conicity of the cone')
         if (allocated(error)) return
         call check(error, tan_h, slope, thr=1.0e-7_wp, message='first-harmonic conicity')
         if (allocated(error)) return
         call check(error, abs(slope/tan(cone_angle) - 1.0367_wp) < 1.0e-3_wp, &
            'the roll adds 3.7 % to tan(cone angle)')
         if (allocated(error)) return
      end do
   end subroutine test_cone_conicity

   !> Δr = 2λ₁y for |y| ≤ a, slope 2λ₂ beyond (continuous), e·r₀ = 1: the motion is harmonic in
   !> each piece, so the half period is X = 2 asin(a/A)/ω₁ + 2 acos((a − y_s)/B)/ω₂ (ω² = 2λ,
   !> A² = a² + v_a²/ω₁², v_a² = 2∫_a^ŷ Δr, y_s = a(1 − λ₁/λ₂), B = ŷ − y_s) and the EN 15302
   !> conicity (π/X)²/2; the first harmonic is λ₂ + (λ₁ − λ₂)·(2/π)(asin ρ + ρ√(1 − ρ²)),
   !> ρ = a/ŷ (the saturation's describing function). Shifting Δr by y₀ moves the motion's
   !> centre, not its wavelength.
   subroutine test_two_slope(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: l1 = 0.05_wp, l2 = 0.4_wp, a = 2.0_wp, y0 = 0.75_wp
      real(wp), parameter :: amplitudes_two(3) = [2.5_wp, 4.0_wp, 7.0_wp]
      real(wp) :: y(161), dr(161), amplitude, w1, w2, va2, big_a, ys, big_b, x, rho, tan_en, &
         tan_h, expected_h
      type(lib_error), allocatable :: err
      integer :: i, k
      y = [(-20.0_wp + 0.25_wp*i, i=0, 160)]
      dr = two_slope(y)
      do k = 1, 3
         amplitude = amplitudes_two(k)
         w1 = sqrt(2.0_wp*l1)
         w2 = sqrt(2.0_wp*l2)
         va2 = 2.0_wp*(2.0_wp*l1*a*(amplitude - a) + l2*(amplitude - a)**2)
         big_a = sqrt(a**2 + va2/w1**2)
         ys = a*(1.0_wp - l1/l2)
         big_b = amplitude - ys
         x = 2.0_wp*asin(a/big_a)/w1 + 2.0_wp*acos((a - ys)/big_b)/w2
         rho = a/amplitude
         expected_h = l2 + (l1 - l2)*(2.0_wp/pi)*(asin(rho) + rho*sqrt(1.0_wp - rho**2))
         call equivalent_conicity(y, dr, amplitude, tan_en, err, conicity_en15302)
         if (.not. allocated(err)) call equivalent_conicity(y, dr, amplitude, tan_h, err, &
            conicity_harmonic)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         call check(error, tan_en, 0.5_wp*(pi/x)**2, rel=.true., thr=1.0e-6_wp, &
            message='EN 15302 conicity, two slopes')
         if (allocated(error)) return
         call check(error, tan_h, expected_h, rel=.true., thr=1.0e-6_wp, &
            message='first-harmonic conicity, two slopes')
         if (allocated(error)) return
         ! The same Δr about y0: the same wavelength.
         call equivalent_conicity(y, two_slope(y - y0), amplitude, tan_h, err, conicity_en15302)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         call check(error, tan_h, tan_en, rel=.true., thr=1.0e-6_wp, message='shifted dr')
         if (allocated(error)) return
      end do
      ! Beyond the table, and a Δr that does not turn the wheelset back.
      call equivalent_conicity(y, dr, 25.0_wp, tan_en, err)
      call check(error, allocated(err), 'amplitude beyond the table refused')
      if (allocated(error)) return
      call equivalent_conicity(y, -dr, 3.0_wp, tan_en, err)
      call check(error, allocated(err), 'a destabilising dr refused')
   contains
      elemental real(wp) function two_slope(s)
         real(wp), intent(in) :: s
         two_slope = 2.0_wp*l2*s + 2.0_wp*(l1 - l2)*max(-a, min(a, s))
      end function two_slope
   end subroutine test_two_slope

   ! ------------------------------------------------------------------------------------------
   ! S1002 / UIC60 1:40, gauge 1435 mm, flange-back distance 1360 mm
   ! ------------------------------------------------------------------------------------------

   subroutine s1002_table(y, table, error, wheel_spec, rail_spec)
      real(wp), intent(in) :: y(:)
      type(wheelset_contact_type), allocatable, intent(out) :: table(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: wheel_spec, rail_spec
      type(profile_type) :: wheel, rail
      type(track_type) :: track
      type(lib_error), allocatable :: err
      if (present(wheel_spec)) then
         call load_profile(wheel_spec, profile_kind_wheel, wheel, err)
         if (.not. allocated(err)) call load_profile(rail_spec, profile_kind_rail, rail, err)
         track%rail_canted = .true.
      else
         call builtin_profile('S1002', wheel, err)
         if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      end if
      if (.not. allocated(err)) call wheelset_geometry_table(wheel, rail, track, &
         contact_options_type(), y, table, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine s1002_table

   !> Δr and the roll are odd in y (the left wheel is the mirrored right one), both contact
   !> angles swap; and the EN 15302 conicity lies between the smallest and the largest secant
   !> slope Δr(y)/(2y) over 0 < y ≤ ŷ (Sturm comparison: k_min·y ≤ Δr ≤ k_max·y on the
   !> swing bounds the period between the linear ones), for every amplitude up to the flange.
   subroutine test_s1002_bounds(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_contact_type), allocatable :: table(:)
      type(lib_error), allocatable :: err
      real(wp) :: amplitude, tan_en, secant_min, secant_max
      integer :: i, k, n, i0
      call s1002_table([(-8.0_wp + 0.1_wp*i, i=0, 160)], table, error)
      if (allocated(error)) return
      n = size(table)
      i0 = 81
      do i = 1, n
         call check(error, table(i)%delta_r(), -table(n + 1 - i)%delta_r(), thr=1.0e-8_wp, &
            message='dr odd in y')
         if (allocated(error)) return
         call check(error, table(i)%roll, -table(n + 1 - i)%roll, thr=1.0e-11_wp, &
            message='roll odd in y')
         if (allocated(error)) return
         call check(error, abs(table(i)%gamma(1) - table(n + 1 - i)%gamma(2)) < 1.0e-9_wp, &
            'contact angles swap')
         if (allocated(error)) return
      end do
      do k = 1, 10
         amplitude = 0.5_wp*k
         call equivalent_conicity(shifts_of(table), dr_of(table), amplitude, tan_en, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         secant_min = huge(1.0_wp)
         secant_max = -huge(1.0_wp)
         do i = i0 + 1, n
            if (table(i)%y > amplitude + 1.0e-9_wp) exit
            secant_min = min(secant_min, table(i)%delta_r()/(2.0_wp*table(i)%y))
            secant_max = max(secant_max, table(i)%delta_r()/(2.0_wp*table(i)%y))
         end do
         call check(error, tan_en >= secant_min - 1.0e-6_wp .and. &
            tan_en <= secant_max + 1.0e-6_wp, 'conicity within the secant slopes')
         if (allocated(error)) return
      end do
      ! The contact jumps doc/geometry.md describes: Δr steps by > 0.3 mm first between 0.2 and
      ! 0.3 mm, by > 1 mm between 4.8 and 4.9 mm; the flange (γ < −1 rad) from 6.3 mm.
      call check(error, first_y(0.3_wp, 0.0_wp), 0.2_wp, thr=1.0e-9_wp, message='central jump')
      if (allocated(error)) return
      call check(error, first_y(1.0_wp, 0.0_wp), 4.8_wp, thr=1.0e-9_wp, message='flange root')
      if (allocated(error)) return
      call check(error, first_y(huge(1.0_wp), -1.0_wp), 6.3_wp, thr=1.0e-9_wp, message='flange')
      if (allocated(error)) return
      ! σ of a rigid roll about the contact points: positive, below the conicity's order.
      call check(error, roll_angle_parameter(table, 3.0_wp) > 0.0_wp .and. &
         roll_angle_parameter(table, 3.0_wp) < 0.1_wp, 'roll-angle parameter')
      if (allocated(error)) return
      call check(error, contact_distance(table), 1506.5_wp, thr=0.1_wp, &
         message='contact-point distance e0 at y = 0')
   contains
      !> The first y ≥ 0 of the table after which Δr steps by more than `step` (mm), or, with
      !> `step` = huge, the first y whose right contact angle is below `gamma` (rad).
      real(wp) function first_y(step, gamma) result(y)
         real(wp), intent(in) :: step, gamma
         integer :: j
         y = huge(1.0_wp)
         do j = i0, n - 1
            if (step < huge(1.0_wp)) then
               if (table(j + 1)%delta_r() - table(j)%delta_r() <= step) cycle
            else
               if (table(j)%gamma(1) >= gamma) cycle
            end if
            y = table(j)%y
            return
         end do
      end function first_y
   end subroutine test_s1002_bounds

   !> The Manchester benchmark's sampled S1002 and pre-canted UIC60 files give the built-in
   !> pair's conicity within EN 15302's acceptance tolerance ±min(0.05, 0.5 tan γ_e).
   subroutine test_manchester_files(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      type(wheelset_contact_type), allocatable :: built(:), files(:)
      type(lib_error), allocatable :: err
      real(wp) :: y(101), tan_b, tan_f
      integer :: i, k
      dir = external_file('profiles/', error)
      if (allocated(error)) return
      y = [(-5.0_wp + 0.1_wp*i, i=0, 100)]
      call s1002_table(y, built, error)
      if (.not. allocated(error)) call s1002_table(y, files, error, &
         dir//'MBench_S1002_v3.prw', dir//'MBench_UIC60_v3.prr')
      if (allocated(error)) return
      do k = 1, 3
         call equivalent_conicity(y, dr_of(built), real(k, wp), tan_b, err)
         if (.not. allocated(err)) call equivalent_conicity(y, dr_of(files), real(k, wp), &
            tan_f, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         call check(error, tan_f, tan_b, thr=min(0.05_wp, 0.5_wp*tan_b), &
            message='Manchester files vs built-in profiles')
         if (allocated(error)) return
      end do
   end subroutine test_manchester_files

   !> The program's tables as doc/geometry.md quotes them, and its usage errors.
   subroutine test_program(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, text
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('wheelset')
      stat = run_program(dir, 'geometry --wheelset -6,6,3 --conicity 1,3,5')
      call check(error, stat, 0, message='geometry --wheelset: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      ! doc/geometry.md, "Wheelset contact geometry and equivalent conicity".
      call expect_in(error, text, '    3.000   -0.18368 -459.90953    739.9802   -757.3659'// &
         '     -13.1044      10.4504   460.78061   459.78664    0.99397    -0.092203'// &
         '    -0.010576    1    1', 'row y = 3 mm')
      if (allocated(error)) return
      call expect_in(error, text, '    6.000   -0.65102 -460.23731    725.0611   -758.1122'// &
         '     -31.2411      14.4117   464.42744   459.74957    4.67787    -0.423583'// &
         '    -0.008088    1    1', 'row y = 6 mm')
      if (allocated(error)) return
      call expect_in(error, text, '         3.000              0.18360               0.18511'// &
         '         8.631      0.04500', 'conicity at 3 mm')
      if (allocated(error)) return
      call expect_in(error, text, '         1.000              0.36989               0.37479', &
         'conicity at 1 mm')
      if (allocated(error)) return
      call expect_in(error, text, '         5.000              0.21836               0.23132', &
         'conicity at 5 mm')
      if (allocated(error)) return
      call expect_in(error, text, 'e0 = 1506.51 mm, r0 = 459.906 mm', 'e0 and r0')
      if (allocated(error)) return
      stat = run_program(dir, 'geometry --wheelset 5,1,1')
      call check(error, stat, 1, message='--wheelset 5,1,1: exit status')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'expected Y_MIN,Y_MAX,STEP', &
         'bad --wheelset')
      if (allocated(error)) return
      stat = run_program(dir, 'geometry --conicity 3,x')
      call check(error, stat, 1, message='--conicity 3,x: exit status')
      if (allocated(error)) return
      stat = run_program(dir, 'geometry --conicity 3 -o w.txt')
      call check(error, stat, 1, message='--conicity with -o: exit status')
      if (allocated(error)) return
      call shell_absent(error, dir//'/w.txt')
      if (allocated(error)) return
      ! No note within the flangeway clearance (the table above).
      call check(error, index(text, 'note:') == 0, message='a note at |y| <= 6 mm: '//text)
      if (allocated(error)) return
      ! What a user met (stop 46): flange-climbing rows, conicity past the flange, shifts past
      ! t_y's range and a yaw angle were taken without a word, and the profile notes of `run`
      ! were not printed.
      stat = run_program(dir, 'geometry --wheelset -10,10,0.5 --conicity 3,8')
      call check(error, stat, 0, message='geometry --wheelset -10,10,0.5: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      call expect_in(error, text, '# note: from y = 6.500 mm the right wheel touches its '// &
         'flange beyond the flange''s steepest part', 'right wheel climbing')
      if (allocated(error)) return
      call expect_in(error, text, '# note: from y = -6.500 mm the left wheel touches its '// &
         'flange beyond', 'left wheel climbing')
      if (allocated(error)) return
      call expect_in(error, text, '# note: amplitude 8.000 mm reaches flange contact', &
         'conicity past the flange')
      if (allocated(error)) return
      call check(error, index(text, 'amplitude 3.000 mm reaches') == 0, &
         message='a flange note at 3 mm')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'shcontact: note: from y = 6.500 mm', &
         'the note on stderr')
      if (allocated(error)) return
      stat = run_program(dir, 'geometry --wheelset 20,40,20')
      call check(error, stat, 1, message='--wheelset 20,40,20: exit status')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the shifts must lie within -30', &
         '--wheelset past t_y''s range')
      if (allocated(error)) return
      ! The amplitudes of --conicity likewise (their shifts ±A).
      stat = run_program(dir, 'geometry --conicity 3,40')
      call check(error, stat, 1, message='--conicity 3,40: exit status')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '(0 < A <= 30, the range of &position '// &
         't_y)', '--conicity past t_y''s range')
      if (allocated(error)) return
      stat = run_program(dir, 'geometry --wheelset -1,1,1 --set kinematics%yaw=0.004')
      call check(error, stat, 2, message='--wheelset with yaw: exit status')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'writes the tables of a wheelset '// &
         'without yaw only', '--wheelset with yaw')
      if (allocated(error)) return
      ! `run` notes its solved cases in flange-climbing states (t_y 10, 20 and 30 mm: contact
      ! on the flange's tip side, 4.7 GPa at 20 mm; t_y 0 on the tread), and only those.
      stat = run_program(dir, 'run --no-output --set sweep%t_y=0,30 --set sweep%t_y_points=4')
      call check(error, stat == 0 .or. stat == 4, message='run to 30 mm: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'beyond its steepest part', &
         'the flange-climbing note of run')
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '3 solved case(s) (t_y 10.000 … '// &
         '30.000 mm)', 'the cases of the note')
      if (allocated(error)) return
      ! Where they begin for the default case (doc/app.md): between 8 and 8.5 mm.
      stat = run_program(dir, 'run --no-output --set sweep%t_y=8,8.5 --set sweep%t_y_points=2')
      call expect_in(error, file_text(dir//'/err.txt'), '1 solved case(s) (t_y 8.500 … '// &
         '8.500 mm)', 'the first climbing case of the default case')
      if (allocated(error)) return
      stat = run_program(dir, 'run --no-output --set sweep%t_y=0,4 --set sweep%t_y_points=3')
      call check(error, stat, 0, message='run on the tread: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, index(file_text(dir//'/err.txt'), 'steepest') == 0, &
         message='no flange-climbing note on the tread: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! The built-in canted rail on a track that cants it again is refused by its name (a
      ! file gets run's profile note, robustness tests).
      stat = run_program(dir, 'geometry --wheelset -1,1,1 --set profiles%rail=builtin:'// &
         'UIC60-canted')
      call check(error, stat, 2, message='canted twice: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'canted 1:40 already', &
         'the built-in canted rail canted again')
   end subroutine test_program

   !> The flange-climbing note of `geometry --wheelset` on a measured MiniProf wheel, whose
   !> profile coordinates start at the flange back (the tape circle at 70 mm): the same note
   !> at the same shift on both sides (external data: the measured pair).
   subroutine test_climbing_miniprof(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, wheel, rail, text
      integer :: stat
      if (unavailable(error, .false.)) return
      wheel = external_file('profiles/Car7216_0001r.whl', error, absolute=.true.)
      if (allocated(error)) return
      rail = external_file('profiles/avg_HR.BAN', error, absolute=.true.)
      if (allocated(error)) return
      dir = scratch_directory('wheelset_miniprof')
      stat = run_program(dir, 'geometry -q --wheelset -12,12,0.5 --set profiles%wheel='// &
         wheel//' --set profiles%rail='//rail//' --set track%rail_canted=.true.')
      call check(error, stat, 0, message='measured pair: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      call expect_in(error, text, '# note: from y = 5.500 mm the right wheel touches its '// &
         'flange beyond', 'right wheel, MiniProf coordinates')
      if (allocated(error)) return
      call expect_in(error, text, '# note: from y = -5.500 mm the left wheel touches its '// &
         'flange beyond', 'left wheel, MiniProf coordinates')
   end subroutine test_climbing_miniprof

   !> The shifts of a table.
   pure function shifts_of(table) result(y)
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp) :: y(size(table))
      y = table%y
   end function shifts_of

   !> Δr of a table.
   pure function dr_of(table) result(dr)
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp) :: dr(size(table))
      dr = table%delta_r()
   end function dr_of

   subroutine shell_absent(error, path)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: path
      logical :: there
      inquire (file=path, exist=there)
      call check(error, .not. there, path//' must not be written')
   end subroutine shell_absent

end module test_wheelset_geometry
