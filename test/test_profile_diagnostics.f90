!> Tests of what `shcontact profiles` says about a measured profile (doc/profiles.md, *Measured
!> profiles: cant and smoothing*): the rail cant on turned, truncated and noisy built-in heads and
!> on the sample files, the noise estimate on a circle with noise of known amplitude, and the
!> curvature noise the suggested smoothing length leaves.
module test_profile_diagnostics
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use test_external_data, only: external_file
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_profile_points, only: profile_type, profile_kind_rail
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_profile_source, only: load_profile
   use shcontact_profile_spline, only: profile_spline_type
   use shcontact_profile_diagnostics, only: noise_estimate_type, estimate_noise, &
      suggested_smoothing, curvature_noise, rail_cant_type, estimate_rail_cant, &
      default_curvature_tolerance, point_anomaly_type, find_point_anomalies
   use test_app, only: unavailable, scratch_directory, run_program, file_text, expect_in, &
      current_directory
   implicit none
   private
   public :: collect_profile_diagnostics


contains

   subroutine collect_profile_diagnostics(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('turned_rail_head', test_turned_rail), &
         new_unittest('noise_of_known_amplitude', test_noise), &
         new_unittest('suggested_smoothing_meets_tolerance', test_smoothing), &
         new_unittest('sample_files', test_sample_files), &
         new_unittest('gap_and_outlier', test_gap_and_outlier), &
         new_unittest('run_notes_gap_and_outlier', test_anomaly_notes)]
   end subroutine collect_profile_diagnostics

   !> Uniform pseudo-random numbers in [−1, 1] (a fixed linear congruential sequence).
   subroutine uniform(values)
      real(wp), intent(out) :: values(:)
      integer(8) :: state
      integer :: i
      state = 12345_8
      do i = 1, size(values)
         state = mod(1103515245_8*state + 12345_8, 2147483648_8)
         values(i) = 2.0_wp*real(state, wp)/2147483648.0_wp - 1.0_wp
      end do
   end subroutine uniform

   !> The built-in UIC60 turned by −atan(slope) (towards the track centre for slope > 0), its
   !> points with y ≤ y_max, and noise of amplitude `noise` (uniform, in z).
   function turned_uic60(slope, y_max, noise) result(rail)
      real(wp), intent(in) :: slope, y_max, noise
      type(profile_type) :: rail
      type(lib_error), allocatable :: err
      real(wp), allocatable :: y(:), z(:), e(:)
      real(wp) :: angle
      call builtin_profile('UIC60', rail, err)
      angle = -atan(slope)
      y = cos(angle)*rail%y - sin(angle)*rail%z
      z = sin(angle)*rail%y + cos(angle)*rail%z
      allocate (e(size(y)))
      call uniform(e)
      z = z + noise*e
      rail%y = pack(y, y <= y_max)
      rail%z = pack(z, y <= y_max)
      if (allocated(rail%kink)) deallocate (rail%kink)
      call rail%update_arc_length()
   end function turned_uic60

   !> Turned heads 1:20 and 1:40 towards the track centre, 1:60 away, upright; whole, cut 25 mm
   !> from the head's axis on the field side (avg_HR.BAN ends 16 mm beyond its top), and with
   !> MiniProf-like noise
   !> (±0.005 mm): the slope within 0.001 (clean) and 0.004 (noisy) — the detection threshold
   !> is 0.0125, half of 1:40.
   subroutine test_turned_rail(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: slopes(4) = [0.05_wp, 0.025_wp, 0.0_wp, -1.0_wp/60.0_wp]
      type(rail_cant_type) :: cant
      integer :: k, variant
      real(wp) :: y_max, noise, tol
      do k = 1, size(slopes)
         do variant = 1, 3
            y_max = merge(25.0_wp, 100.0_wp, variant >= 2)
            noise = merge(0.005_wp, 0.0_wp, variant == 3)
            tol = merge(0.004_wp, 0.001_wp, variant == 3)
            call estimate_rail_cant(turned_uic60(slopes(k), y_max, noise), cant)
            call check(error, cant%found, 'cant found')
            if (allocated(error)) return
            call check(error, cant%slope, slopes(k), thr=tol, message='estimated cant')
            if (allocated(error)) return
         end do
      end do
      ! Cut before the crown's top (1:20 moves it 15 mm to the field side): no estimate.
      call estimate_rail_cant(turned_uic60(0.05_wp, 10.0_wp, 0.0_wp), cant)
      call check(error, .not. cant%found, 'no crown, no estimate')
   end subroutine test_turned_rail

   !> A 300 mm arc sampled every 0.5 mm with uniform noise ±a normal to it: σ = a/√3 within
   !> 15 % (about 400 windows); without noise below 1e-6 mm.
   subroutine test_noise(error)
      type(error_type), allocatable, intent(out) :: error
      type(noise_estimate_type) :: noise
      real(wp), parameter :: amplitude = 0.01_wp
      call estimate_noise(noisy_arc(300.0_wp, 0.5_wp, 400, amplitude), noise)
      call check(error, noise%sigma, amplitude/sqrt(3.0_wp), rel=.true., thr=0.15_wp, &
         message='noise of a noisy arc')
      if (allocated(error)) return
      call check(error, noise%spacing, 0.5_wp, thr=0.01_wp, message='spacing')
      if (allocated(error)) return
      call estimate_noise(noisy_arc(300.0_wp, 0.5_wp, 400, 0.0_wp), noise)
      call check(error, noise%sigma < 1.0e-6_wp, 'no noise on a clean arc')
   end subroutine test_noise

   !> A measured-like noisy crown (300 mm arc, points 0.3 mm apart, noise 3e-4 mm) has neither
   !> a gap nor an outlier; one point moved by 0.05 mm along z is found at its index, one moved
   !> by 0.01 mm is not (below 0.02 mm), 10 mm of points taken out is a gap, and a flange-tip
   !> point deeper than 25 mm or a wheel's back-face point beyond its flange tip is not judged.
   subroutine test_gap_and_outlier(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: arc, damaged, wheel
      type(lib_error), allocatable :: err
      integer :: tip
      type(noise_estimate_type) :: noise
      type(point_anomaly_type) :: found
      integer, parameter :: n = 300, bad = 140
      arc = noisy_arc(300.0_wp, 0.3_wp, n, 3.0e-4_wp)
      call estimate_noise(arc, noise)
      call find_point_anomalies(arc, arc, noise%sigma, found)
      call check(error, .not. (found%has_gap .or. found%has_outlier) .and. &
         found%outlier < 2.0e-3_wp, message='a clean noisy crown flagged')
      if (allocated(error)) return
      damaged = arc
      damaged%z(bad) = damaged%z(bad) + 0.05_wp
      call find_point_anomalies(damaged, damaged, noise%sigma, found)
      call check(error, found%has_outlier .and. found%outlier_at == bad .and. &
         abs(found%outlier - 0.05_wp) < 0.005_wp, message='a 0.05 mm outlier not found')
      if (allocated(error)) return
      damaged%z(bad) = arc%z(bad) + 0.01_wp
      call find_point_anomalies(damaged, damaged, noise%sigma, found)
      call check(error, .not. found%has_outlier .and. found%outlier_at == bad, &
         message='a 0.01 mm outlier counted')
      if (allocated(error)) return
      ! The same arc 30 mm deeper: the tip of a flange, not judged.
      damaged%z = damaged%z + 30.0_wp
      damaged%z(bad) = arc%z(bad) + 30.5_wp
      call find_point_anomalies(damaged, damaged, noise%sigma, found)
      call check(error, found%outlier_at == 0, message='an outlier deeper than 25 mm judged')
      if (allocated(error)) return
      ! A wheel: a point of its back face (beyond the flange tip, never in running contact) is
      ! not judged (a MiniProf wheel's note named its flange back), a tread point is, whatever
      ! the profile's z origin.
      call builtin_profile('S1002', wheel, err)
      wheel%z = wheel%z - 30.0_wp
      tip = maxloc(wheel%z, 1)
      damaged = wheel
      damaged%z(tip + 100) = damaged%z(tip + 100) + 0.05_wp
      call find_point_anomalies(damaged, damaged, 1.0e-4_wp, found)
      call check(error, .not. found%has_outlier, message='a back-face point judged')
      if (allocated(error)) return
      damaged = wheel
      damaged%z(tip - 600) = damaged%z(tip - 600) + 0.05_wp
      call find_point_anomalies(damaged, damaged, 1.0e-4_wp, found)
      call check(error, found%has_outlier .and. found%outlier_at == tip - 600, &
         message='a tread point of a wheel whose z origin is 30 mm off not judged')
      if (allocated(error)) return
      ! 34 points (about 10 mm) taken out: a gap of 35 spacings, 10.5 mm, against 0.3 mm.
      damaged = arc
      damaged%y = [arc%y(:100), arc%y(135:)]
      damaged%z = [arc%z(:100), arc%z(135:)]
      call find_point_anomalies(damaged, damaged, noise%sigma, found)
      call check(error, found%has_gap .and. found%gap_at == 100 .and. &
         abs(found%gap - 10.5_wp) < 0.05_wp, message='a 10 mm gap not found')
   end subroutine test_gap_and_outlier

   !> `shcontact run` notes a gap and a bad point of a profile file (the worn wheel of
   !> data/profiles with 10 mm of tread points taken out, or one tread point moved by 0.1 mm),
   !> and none on the file itself; `shcontact profiles` flags them.
   subroutine test_anomaly_notes(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, wheel
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('diagnostics_anomaly_notes')
      wheel = current_directory()//'/data/profiles/worn/S1002-worn.txt'
      stat = run_program(dir, 'run --no-output --format none --set profiles%wheel='//wheel)
      call check(error, stat == 0 .and. index(file_text(dir//'/err.txt'), 'note:') == 0, &
         message='a note on the intact file: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! Column 1 is y (mm, falling from 60): the tread from 10 to 20 mm taken out; then the
      ! first point below y = 15 mm moved by 0.1 mm in z.
      call execute_command_line('awk ''/^ *#/ || NF < 2 {print; next} $1 > 10 && $1 < 20 '// &
         '{next} {print}'' '//wheel//' > '//dir//'/gap.txt && awk ''BEGIN {d = 0} /^ *#/ || '// &
         'NF < 2 {print; next} !d && $1 < 15 {printf "%.10f %.10f\n", $1, $2 + 0.1; d = 1; '// &
         'next} {print}'' '//wheel//' > '//dir//'/spike.txt', exitstat=stat)
      call check(error, stat, 0, message='cannot write the damaged copies')
      if (allocated(error)) return
      stat = run_program(dir, 'run --no-output --format none --set profiles%wheel=gap.txt')
      call expect_in(error, file_text(dir//'/err.txt'), 'note: wheel profile gap.txt: a gap '// &
         'of 10.', 'the gap note')
      if (allocated(error)) return
      stat = run_program(dir, 'run --no-output --format none --set profiles%wheel=spike.txt')
      call expect_in(error, file_text(dir//'/err.txt'), 'note: wheel profile spike.txt: a '// &
         'point 0.1', 'the outlier note')
      if (allocated(error)) return
      stat = run_program(dir, 'profiles spike.txt --kind wheel')
      call expect_in(error, file_text(dir//'/out.txt'), 'a single bad point?', &
         'profiles flags the outlier')
   end subroutine test_anomaly_notes

   !> A rail-like arc (points from the gauge side, material below), n points h apart along
   !> the arc, each moved along the normal by amplitude × uniform[−1, 1].
   function noisy_arc(radius, h, n, amplitude) result(rail)
      real(wp), intent(in) :: radius, h, amplitude
      integer, intent(in) :: n
      type(profile_type) :: rail
      real(wp) :: e(n), phi(n)
      integer :: i
      call uniform(e)
      phi = [((i - 0.5_wp*(n + 1))*h/radius, i=1, n)]
      rail%y = (radius - amplitude*e)*sin(phi)
      rail%z = radius - (radius - amplitude*e)*cos(phi)
      rail%kind = profile_kind_rail
      rail%source = 'noisy arc'
      call rail%update_arc_length()
   end function noisy_arc

   !> The reasoning behind the suggestion: the spline fitted with the suggested L_filt to an arc
   !> with noise σ leaves a curvature noise of the tolerance (the formula's white-noise model),
   !> checked on the interior (2 L_filt from the ends) within 35 % (about 15 independent
   !> stretches of L_filt); with L_filt/2 it is 2^(5/2) times larger.
   subroutine test_smoothing(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: rail
      type(noise_estimate_type) :: noise
      type(profile_spline_type) :: spline
      type(lib_error), allocatable :: err
      real(wp), parameter :: radius = 300.0_wp, h = 0.5_wp, amplitude = 0.01_wp
      real(wp) :: l_filt, rms
      integer :: k
      rail = noisy_arc(radius, h, 801, amplitude)
      call estimate_noise(rail, noise)
      l_filt = suggested_smoothing(amplitude/sqrt(3.0_wp), h)
      call check(error, curvature_noise(amplitude/sqrt(3.0_wp), h, l_filt), &
         default_curvature_tolerance, rel=.true., thr=1.0e-12_wp, message='formula inverse')
      if (allocated(error)) return
      do k = 1, 2
         call spline%fit(rail, l_filt/k, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         rms = curvature_rms(spline, 1.0_wp/radius, 2.0_wp*l_filt)
         call check(error, rms, default_curvature_tolerance*2.0_wp**(2.5_wp*(k - 1)), &
            rel=.true., thr=0.35_wp, message='curvature noise after smoothing')
         if (allocated(error)) return
      end do
   end subroutine test_smoothing

   !> rms of κ(s) − κ₀ over the spline, `margin` (mm) from each end, every 0.1 mm.
   real(wp) function curvature_rms(spline, kappa0, margin) result(rms)
      type(profile_spline_type), intent(in) :: spline
      real(wp), intent(in) :: kappa0, margin
      real(wp) :: s, total
      integer :: n
      total = 0.0_wp
      n = 0
      s = spline%s(1) + margin
      do while (s <= spline%s(spline%size()) - margin)
         total = total + (spline%curvature(s) - kappa0)**2
         n = n + 1
         s = s + 0.1_wp
      end do
      rms = sqrt(total/n)
   end function curvature_rms

   !> The sample files (with the external data, SHCONTACT_EXTERNAL_DATA): the Manchester UIC60, canted 1:40,
   !> reads 1:41; the measured avg_HR.BAN 1:48 with 0.0030 mm noise (its 0.01 mm digits:
   !> 0.01/√12 = 0.0029) and the program's lines doc/profiles.md quotes.
   subroutine test_sample_files(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: rail
      type(rail_cant_type) :: cant
      type(lib_error), allocatable :: err
      character(len=:), allocatable :: dir, text, profiles_dir
      integer :: stat
      profiles_dir = external_file('profiles/', error, absolute=.true.)
      if (allocated(error)) return
      call load_profile(profiles_dir//'MBench_UIC60_v3.prr', profile_kind_rail, rail, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call estimate_rail_cant(rail, cant)
      call check(error, 1.0_wp/cant%slope, 41.0_wp, thr=1.0_wp, message='Manchester rail 1:40')
      if (allocated(error)) return
      if (unavailable(error, .false.)) return
      dir = scratch_directory('profile_advice')
      stat = run_program(dir, 'profiles '//profiles_dir//'avg_HR.BAN')
      call check(error, stat, 0, message='profiles avg_HR.BAN: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/out.txt')
      call expect_in(error, text, 'the rail head looks inclined by about 1:48 towards the '// &
         'track centre (crown top 40.2 mm from the gauge point; upright 60E1 head: 36.0 mm)', &
         'avg_HR cant')
      if (allocated(error)) return
      call expect_in(error, text, 'noise      3.00E-03 mm rms', 'avg_HR noise')
      if (allocated(error)) return
      call expect_in(error, text, 'smoothing  profiles%rail_smoothing = 8.1 mm keeps the '// &
         'curvature noise below 3.3E-04 1/mm (10 % of a 300 mm crown; 1.1E-02 1/mm at 2 mm)', &
         'avg_HR smoothing')
      if (allocated(error)) return
      ! The other lines doc/profiles.md quotes.
      call expect_in(error, text, 'points     147 read, 110 after clean-up', 'avg_HR points')
      if (allocated(error)) return
      call expect_in(error, text, 'gap        largest 0.771 mm between points 1 and 2 of the 147 read '// &
         '(y = -46.59 to -46.46 mm), median spacing 0.500 mm'//new_line('a'), 'avg_HR gap')
      if (allocated(error)) return
      call expect_in(error, text, 'outlier    largest 1.20E-02 mm off the cubic through its '// &
         'six neighbours (within 25 mm of the running surface, not beyond a wheel''s '// &
         'flange tip) at point 22 of the 110 after '// &
         'clean-up (y, z = '// &
         '-44.510, 12.400 mm)'//new_line('a'), 'avg_HR outlier')
   end subroutine test_sample_files

end module test_profile_diagnostics
