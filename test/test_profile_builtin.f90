!> Tests of the built-in analytic profiles: the S1002 section definition (joints, flange tip,
!> slopes), the UIC60 arcs, the 1:40 cant, and both against the Manchester samples in
!> the external data's profiles/ (skipped without SHCONTACT_EXTERNAL_DATA).
!>
!> Set SHCONTACT_TEST_VERBOSE=1 to print the deviations from the Manchester samples:
!>     SHCONTACT_TEST_VERBOSE=1 fpm test -- profile_builtin s1002_vs_mbench
module test_profile_builtin
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_builtin, only: builtin_profile, builtin_spacing, s1002_section, &
      s1002_bounds, s1002_section_count, s1002_tip_s, uic60_cant
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile
   use test_external_data, only: external_file
   implicit none
   private
   public :: collect_profile_builtin

   !> Bound on the vertical deviation from the Manchester samples (mm), issue 3.
   real(wp), parameter :: mbench_tolerance = 0.01_wp

contains

   subroutine collect_profile_builtin(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('names', test_names), &
         new_unittest('spacing_and_clean', test_spacing_and_clean), &
         new_unittest('s1002_joints', test_s1002_joints), &
         new_unittest('s1002_tip_and_ends', test_s1002_tip), &
         new_unittest('uic60_arcs_and_flank', test_uic60_arcs), &
         new_unittest('uic60_canted', test_uic60_canted), &
         new_unittest('s1002_vs_mbench', test_s1002_vs_mbench), &
         new_unittest('uic60_canted_vs_mbench', test_uic60_vs_mbench) &
         ]
   end subroutine collect_profile_builtin

   !> Names are case-insensitive; an unknown name lists the valid ones.
   subroutine test_names(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      call builtin_profile(' s1002 ', p, err)
      call check(error, .not. allocated(err) .and. p%kind == profile_kind_wheel .and. &
         p%source == 'builtin:S1002', 's1002')
      if (allocated(error)) return
      call builtin_profile('uic60-CANTED', p, err)
      call check(error, .not. allocated(err) .and. p%kind == profile_kind_rail .and. &
         p%source == 'builtin:UIC60-canted', 'uic60-CANTED')
      if (allocated(error)) return
      call builtin_profile('S1003', p, err)
      if (.not. allocated(err)) then
         call test_failed(error, 'S1003 accepted')
         return
      end if
      call check(error, err%stat == stat_invalid_input .and. &
         index(err%message, "unknown built-in profile 'S1003'") > 0 .and. &
         index(err%message, 'S1002, UIC60, UIC60-canted') > 0, err%message)
   end subroutine test_names

   !> Chords at most builtin_spacing; the clean-up accepts the profiles unchanged, no kinks
   !> (every joint is tangent).
   subroutine test_spacing_and_clean(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=12), parameter :: names(3) = [character(len=12) :: 'S1002', 'UIC60', &
         'UIC60-canted']
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer :: i, n
      real(wp) :: longest
      do i = 1, size(names)
         call builtin_profile(names(i), p, err)
         if (lib_failed(error, err)) return
         n = p%size()
         longest = maxval(p%s(2:) - p%s(:n - 1))
         call check(error, longest <= builtin_spacing*(1.0_wp + 1.0e-9_wp), &
            trim(names(i))//': chord longer than the spacing')
         if (allocated(error)) return
         call clean_profile(p, err)
         if (lib_failed(error, err)) return
         call check(error, p%size(), n, trim(names(i))//': points changed by the clean-up')
         if (allocated(error)) return
         call check(error, .not. any(p%kink), trim(names(i))//': kink found')
         if (allocated(error)) return
      end do
   end subroutine test_spacing_and_clean

   !> doc/theory.md §5.7: adjacent sections meet (jumps below 1.2e-4 mm at B/C and C/D, 1e-7 mm
   !> elsewhere) with the same slope (to 1e-5).
   subroutine test_s1002_joints(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      real(wp) :: s, f1, d1, f2, d2, thr
      character(len=1), parameter :: letter(8) = ['A', 'B', 'C', 'D', 'E', 'F', 'G', 'H']
      do k = 1, s1002_section_count - 1
         s = s1002_bounds(k + 1)
         call s1002_section(k, s, f1, d1)
         call s1002_section(k + 1, s, f2, d2)
         thr = merge(1.2e-4_wp, 1.0e-7_wp, k == 2 .or. k == 3)
         call check(error, f1, f2, 'height jump at joint '//letter(k)//'/'//letter(k + 1), &
            thr=thr)
         if (allocated(error)) return
         call check(error, d1, d2, 'slope jump at joint '//letter(k)//'/'//letter(k + 1), &
            thr=1.0e-5_wp)
         if (allocated(error)) return
      end do
   end subroutine test_s1002_joints

   !> Flange tip F_G(−55) = 28.000 with zero slope and a sample there; section A slope −1/15;
   !> the sampled profile runs from S = 60 to the flange back S = −70 (y_fbpos = −70).
   subroutine test_s1002_tip(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      real(wp) :: f, df, f_end
      integer :: n, i
      call s1002_section(7, s1002_tip_s, f, df)
      call check(error, f, 28.0_wp, 'flange tip height', thr=1.0e-12_wp)
      if (allocated(error)) return
      call check(error, df, 0.0_wp, 'flange tip slope', thr=1.0e-12_wp)
      if (allocated(error)) return
      call s1002_section(1, 45.0_wp, f, df)
      call check(error, df, -1.0_wp/15.0_wp, 'section A slope', thr=1.0e-9_wp)
      if (allocated(error)) return

      call builtin_profile('S1002', p, err)
      if (lib_failed(error, err)) return
      n = p%size()
      i = maxloc(p%z, dim=1)
      call check(error, p%y(i), -55.0_wp, 'lowest sample at the tip', thr=1.0e-12_wp)
      if (allocated(error)) return
      call check(error, p%z(i), 28.0_wp, 'tip sample z', thr=1.0e-12_wp)
      if (allocated(error)) return
      call s1002_section(8, -70.0_wp, f_end, df)
      call check(error, p%y(1) == 60.0_wp .and. abs(p%y(n) + 70.0_wp) < 1.0e-12_wp .and. &
         abs(p%z(n) - f_end) < 1.0e-12_wp, 'ends at S = 60 and at the flange back S = −70')
   end subroutine test_s1002_tip

   !> Upright UIC60: circles through sample triples have radius 300 on the crown, 80 beyond
   !> |y| = 10.5, 13 at the corner; the flank rises 1:20; the profile is symmetric with its top
   !> at the origin.
   subroutine test_uic60_arcs(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer :: i, n
      real(wp) :: centre(2), radius, slope
      call builtin_profile('UIC60', p, err)
      if (lib_failed(error, err)) return
      n = p%size()
      call check(error, all(abs(p%y + p%y(n:1:-1)) < 1.0e-12_wp) .and. &
         all(abs(p%z - p%z(n:1:-1)) < 1.0e-12_wp), 'symmetric about y = 0')
      if (allocated(error)) return
      i = minloc(p%z, dim=1)
      call check(error, abs(p%y(i)) < 1.0e-12_wp .and. abs(p%z(i)) < 1.0e-12_wp, &
         'top at the origin')
      if (allocated(error)) return
      do i = 2, n - 1
         radius = 0.0_wp
         if (p%z(i) < 14.1_wp) call circle(p, i, centre, radius)
         if (abs(p%y(i)) < 10.4_wp) then
            call check(error, radius, 300.0_wp, 'crown radius', rel=.true., thr=1.0e-6_wp)
         else if (abs(p%y(i)) > 10.6_wp .and. abs(p%y(i)) < 25.85_wp) then
            call check(error, radius, 80.0_wp, 'side radius', rel=.true., thr=1.0e-6_wp)
         else if (abs(p%y(i)) > 26.1_wp .and. p%z(i) < 14.1_wp) then
            call check(error, radius, 13.0_wp, 'corner radius', rel=.true., thr=1.0e-6_wp)
         else if (p%z(i) > 14.4_wp) then
            slope = (abs(p%y(i + 1)) - abs(p%y(i - 1)))/(p%z(i + 1) - p%z(i - 1))
            call check(error, slope, 1.0_wp/20.0_wp, 'flank 1:20', thr=1.0e-9_wp)
         end if
         if (allocated(error)) return
      end do
      call check(error, maxval(p%z), 37.5_wp, 'head depth', thr=1.0e-12_wp)
   end subroutine test_uic60_arcs

   !> Canted UIC60: origin at the highest point with the crown centre straight below it, and
   !> the line through the two R13 corner centres (horizontal upright) inclined 1:40, down
   !> towards the field side.
   subroutine test_uic60_canted(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: up, canted
      type(lib_error), allocatable :: err
      integer :: i, itop, gauge, field
      real(wp) :: centre(2), radius, c_gauge(2), c_field(2)
      call builtin_profile('UIC60', up, err)
      if (lib_failed(error, err)) return
      call builtin_profile('UIC60-canted', canted, err)
      if (lib_failed(error, err)) return
      itop = minloc(canted%z, dim=1)
      call check(error, abs(canted%y(itop)) < 1.0e-12_wp .and. abs(canted%z(itop)) < 1.0e-12_wp, &
         'highest point at the origin')
      if (allocated(error)) return
      call circle(canted, itop, centre, radius)
      call check(error, centre(1), 0.0_wp, 'crown centre below the origin', thr=1.0e-6_wp)
      if (allocated(error)) return
      call check(error, centre(2), 300.0_wp, 'crown centre depth', thr=1.0e-4_wp)
      if (allocated(error)) return
      ! Corner samples: the same indices as in the upright profile.
      gauge = 0
      field = 0
      do i = 2, up%size() - 1
         if (abs(up%y(i) - 31.0_wp) < 0.06_wp .and. up%z(i) < 14.2_wp) field = i
         if (abs(up%y(i) + 31.0_wp) < 0.06_wp .and. up%z(i) < 14.2_wp) gauge = i
      end do
      if (gauge == 0 .or. field == 0) then
         call test_failed(error, 'no corner samples near |y| = 31')
         return
      end if
      call circle(canted, gauge, c_gauge, radius)
      call circle(canted, field, c_field, radius)
      call check(error, (c_field(2) - c_gauge(2))/(c_field(1) - c_gauge(1)), &
         -tan(uic60_cant), 'corner centres inclined 1:40', thr=1.0e-6_wp)
   end subroutine test_uic60_canted

   !> Built-in S1002 against MBench_S1002_v3.prw (same origin by definition: the tape circle):
   !> vertical deviation on the tread and flange, S from −62.76 (end of section G, past the
   !> flange tip) to 60, below 0.01 mm; and the section formulas at the sample's S below
   !> 1e-5 mm. Measured figures in doc/profiles.md.
   subroutine test_s1002_vs_mbench(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: built, sample
      type(lib_error), allocatable :: err
      real(wp) :: worst, f, df
      integer :: i, k
      if (.not. have_shared(error, 'MBench_S1002_v3.prw')) return
      call builtin_profile('S1002', built, err)
      if (lib_failed(error, err)) return
      call read_profile(sample_file('MBench_S1002_v3.prw'), sample, err)
      if (lib_failed(error, err)) return
      worst = max_vertical_deviation(built, sample, [0.0_wp, 0.0_wp], s1002_bounds(8), 60.0_wp)
      call report('S1002 vs MBench_S1002_v3.prw, max |dz| (mm) on -62.76 <= y <= 60', worst)
      call check(error, worst, 0.0_wp, 'S1002: largest vertical deviation (mm)', &
         thr=mbench_tolerance)
      if (allocated(error)) return
      ! The section formulas themselves, at the sample's own S (all of it, flange back included).
      worst = 0.0_wp
      do i = 1, sample%size()
         k = count(s1002_bounds(2:s1002_section_count) > sample%y(i)) + 1
         call s1002_section(k, sample%y(i), f, df)
         worst = max(worst, abs(f - sample%z(i)))
      end do
      call report('S1002 section formulas vs MBench_S1002_v3.prw, max |dz| (mm)', worst)
      call check(error, worst, 0.0_wp, 'S1002 formulas: largest deviation (mm)', thr=1.0e-5_wp)
   end subroutine test_s1002_vs_mbench

   !> Built-in UIC60-canted against MBench_UIC60_v3.prr after aligning origins (the sample's
   !> origin is its highest sample; its true crown top, the vertex of the parabola through the
   !> three highest samples, lies 0.006 mm beside it): vertical deviation from the gauge
   !> corner (y = −43.1, end of the R13 arc) over the crown to the end of the field-side R80
   !> arc (y = 18.5) below 0.01 mm. Measured: see doc/profiles.md.
   subroutine test_uic60_vs_mbench(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: built, sample
      type(lib_error), allocatable :: err
      real(wp) :: worst, top(2)
      if (.not. have_shared(error, 'MBench_UIC60_v3.prr')) return
      call builtin_profile('UIC60-canted', built, err)
      if (lib_failed(error, err)) return
      call read_profile(sample_file('MBench_UIC60_v3.prr'), sample, err)
      if (lib_failed(error, err)) return
      top = parabola_vertex(sample)
      worst = max_vertical_deviation(built, sample, top, -43.1_wp, 18.5_wp)
      call report('UIC60-canted vs MBench_UIC60_v3.prr, max |dz| (mm) on -43.1 <= y <= 18.5', &
         worst)
      call report('  MBench crown top offset y (mm)', top(1))
      call check(error, worst, 0.0_wp, 'UIC60: largest vertical deviation (mm)', &
         thr=mbench_tolerance)
   end subroutine test_uic60_vs_mbench

   ! --- helpers --------------------------------------------------------------------------------

   !> Largest |z_sample − z_built| over the sample points with y_lo ≤ y ≤ y_hi, the built-in
   !> profile shifted by `shift` and interpolated linearly in y (it is single-valued there).
   real(wp) function max_vertical_deviation(built, sample, shift, y_lo, y_hi) result(worst)
      type(profile_type), intent(in) :: built, sample
      real(wp), intent(in) :: shift(2), y_lo, y_hi
      real(wp) :: y(built%size()), t
      integer :: i, j
      y = built%y + shift(1)
      worst = 0.0_wp
      do i = 1, sample%size()
         if (sample%y(i) < y_lo .or. sample%y(i) > y_hi) cycle
         do j = 1, size(y) - 1
            if ((y(j) - sample%y(i))*(y(j + 1) - sample%y(i)) > 0.0_wp) cycle
            if (y(j + 1) == y(j)) cycle
            t = (sample%y(i) - y(j))/(y(j + 1) - y(j))
            worst = max(worst, abs(sample%z(i) - (built%z(j) + shift(2) + &
               t*(built%z(j + 1) - built%z(j)))))
            exit
         end do
      end do
   end function max_vertical_deviation

   !> Vertex of the parabola z(y) through the highest sample and its two neighbours.
   function parabola_vertex(p) result(vertex)
      type(profile_type), intent(in) :: p
      real(wp) :: vertex(2)
      real(wp) :: y1, y2, y3, z1, z2, z3, a, b, c, d
      integer :: i
      i = minloc(p%z, dim=1)
      y1 = p%y(i - 1); y2 = p%y(i); y3 = p%y(i + 1)
      z1 = p%z(i - 1); z2 = p%z(i); z3 = p%z(i + 1)
      d = (y1 - y2)*(y1 - y3)*(y2 - y3)
      a = (y3*(z2 - z1) + y2*(z1 - z3) + y1*(z3 - z2))/d
      b = (y3**2*(z1 - z2) + y2**2*(z3 - z1) + y1**2*(z2 - z3))/d
      c = (y2*y3*(y2 - y3)*z1 + y3*y1*(y3 - y1)*z2 + y1*y2*(y1 - y2)*z3)/d
      vertex = [-b/(2*a), c - b**2/(4*a)]
   end function parabola_vertex

   !> Circle through points i−1, i, i+1.
   subroutine circle(p, i, centre, radius)
      type(profile_type), intent(in) :: p
      integer, intent(in) :: i
      real(wp), intent(out) :: centre(2), radius
      real(wp) :: ax, ay, bx, by, cx, cy, d
      ax = p%y(i - 1); ay = p%z(i - 1)
      bx = p%y(i); by = p%z(i)
      cx = p%y(i + 1); cy = p%z(i + 1)
      d = 2*(ax*(by - cy) + bx*(cy - ay) + cx*(ay - by))
      centre(1) = ((ax**2 + ay**2)*(by - cy) + (bx**2 + by**2)*(cy - ay) + &
         (cx**2 + cy**2)*(ay - by))/d
      centre(2) = ((ax**2 + ay**2)*(cx - bx) + (bx**2 + by**2)*(ax - cx) + &
         (cx**2 + cy**2)*(bx - ax))/d
      radius = hypot(ax - centre(1), ay - centre(2))
   end subroutine circle

   !> Print a figure when SHCONTACT_TEST_VERBOSE is set (the numbers quoted in doc/profiles.md).
   subroutine report(label, value)
      character(len=*), intent(in) :: label
      real(wp), intent(in) :: value
      integer :: length, stat
      call get_environment_variable('SHCONTACT_TEST_VERBOSE', length=length, status=stat)
      if (stat /= 0 .or. length == 0) return
      write (*, '(4x,a,": ",es10.3)') label, value
   end subroutine report

   !> Whether the external data's sample profile `name` is there (test_external_data); the test is
   !> skipped when SHCONTACT_EXTERNAL_DATA is unset, failed when the folder lacks them.
   logical function have_shared(error, name)
      type(error_type), allocatable, intent(out) :: error
      !> The sample profile the test reads.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      path = external_file('profiles/'//name, error)
      have_shared = .not. allocated(error)
   end function have_shared

   !> A sample profile of the external data, once have_shared has let the test run.
   function sample_file(name) result(path)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      type(error_type), allocatable :: missing
      path = external_file('profiles/'//name, missing)
   end function sample_file

   logical function lib_failed(error, err)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable, intent(in) :: err
      lib_failed = allocated(err)
      if (lib_failed) call test_failed(error, 'unexpected error: '//err%message)
   end function lib_failed

end module test_profile_builtin
