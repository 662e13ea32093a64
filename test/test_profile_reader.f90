!> Tests of the profile readers and the plain writer: canonical orientation of every format read
!> from the external data's profiles/ (skipped without SHCONTACT_EXTERNAL_DATA), robustness to real-file variations, the
!> diagnostics for bad files, and the write → read round trip.
module test_profile_reader
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_io, stat_usage
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_profile_writer, only: write_profile_plain, write_builtin_profiles
   use test_external_data, only: external_file
   implicit none
   private
   public :: collect_profile_reader

   character(len=*), parameter :: tmp = 'build/test_profile_reader_'

contains

   subroutine collect_profile_reader(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('simpack_wheel_canonical', test_simpack_wheel), &
         new_unittest('simpack_rail_canonical', test_simpack_rail), &
         new_unittest('miniprof_rail_equals_simpack', test_ban_equals_prr), &
         new_unittest('measured_files_read_and_clean', test_measured), &
         new_unittest('crlf_tabs_commas_columns', test_file_variants), &
         new_unittest('simpack_crlf_equals_lf', test_simpack_crlf), &
         new_unittest('simpack_keys', test_simpack_keys), &
         new_unittest('options_override_file', test_overrides), &
         new_unittest('bad_numbers', test_bad_numbers), &
         new_unittest('bad_structure', test_bad_structure), &
         new_unittest('missing_file_and_format', test_missing), &
         new_unittest('round_trip_builtin', test_round_trip_builtin), &
         new_unittest('round_trip_file', test_round_trip_file) &
         ]
   end subroutine collect_profile_reader

   ! --- files of the external data -----------------------------------------------------------

   !> S1002 (.prw, mirror.y = 1, inversion = 1): flange at negative y, tip z ≈ +28, field side
   !> first.
   subroutine test_simpack_wheel(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer :: n, itip
      if (.not. have_shared(error)) return
      call read_profile(sample_file('MBench_S1002_v3.prw'), p, err)
      if (failed(error, err)) return
      n = p%size()
      call check(error, p%kind, profile_kind_wheel, 'kind from type = 1')
      if (allocated(error)) return
      call check(error, n, 399, 'points (one commented out)')
      if (allocated(error)) return
      call check(error, p%y(1), 60.0_wp, 'first point on the field side', thr=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, p%z(1), -2.6356764_wp, 'field-side height', thr=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, p%y(n), -69.612628_wp, 'last point at the flange back', thr=1.0e-9_wp)
      if (allocated(error)) return
      itip = maxloc(p%z, dim=1)
      call check(error, p%z(itip), 28.0_wp, 'flange tip z ≈ +28 (down)', thr=1.0e-3_wp)
      if (allocated(error)) return
      call check(error, p%y(itip), -55.0_wp, 'flange tip at y ≈ −55', thr=0.5_wp)
      if (allocated(error)) return
      call check(error, p%source, sample_file('MBench_S1002_v3.prw'))
   end subroutine test_simpack_wheel

   !> UIC60 (.prr, canted, no flags): crown near y = 0 at z ≈ 0, z growing away from it, gauge
   !> face at negative y, points ascending.
   subroutine test_simpack_rail(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer :: n, itop
      if (.not. have_shared(error)) return
      call read_profile(sample_file('MBench_UIC60_v3.prr'), p, err)
      if (failed(error, err)) return
      n = p%size()
      call check(error, p%kind, profile_kind_rail)
      if (allocated(error)) return
      call check(error, n, 495)
      if (allocated(error)) return
      itop = minloc(p%z, dim=1)
      call check(error, p%z(itop), 0.0_wp, 'crown at z ≈ 0', thr=1.0e-3_wp)
      if (allocated(error)) return
      call check(error, abs(p%y(itop)) < 1.0_wp, 'crown near y = 0')
      if (allocated(error)) return
      call check(error, p%y(1) < -43.0_wp .and. p%y(n) > 30.0_wp, &
         'gauge face first (negative y), field side last')
      if (allocated(error)) return
      call check(error, all(p%z(2:itop) - p%z(1:itop - 1) <= 1.0e-6_wp) .and. &
         all(p%z(itop + 1:n) - p%z(itop:n - 1) >= -1.0e-6_wp), &
         'z decreases towards the crown and increases away from it')
   end subroutine test_simpack_rail

   !> The MiniProf copy of the Manchester rail (X = −y, Y = z, points commented out with ")
   !> describes the same rail after the documented transforms (mirror y; z already down,
   !> detected): every .ban point equals a .prr point to 1e-9 mm (the files print the same
   !> digits), in the same order.
   subroutine test_ban_equals_prr(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: ban, prr
      type(lib_error), allocatable :: err
      integer :: i, j, last
      real(wp) :: worst, d
      if (.not. have_shared(error)) return
      call read_profile(sample_file('MBench_UIC60_v3.ban'), ban, err)
      if (failed(error, err)) return
      call read_profile(sample_file('MBench_UIC60_v3.prr'), prr, err)
      if (failed(error, err)) return
      call check(error, ban%kind, profile_kind_rail)
      if (allocated(error)) return
      call check(error, ban%size(), 495 - 19, '.ban points minus the 19 commented out')
      if (allocated(error)) return
      worst = 0.0_wp
      last = 0
      do i = 1, ban%size()
         j = minloc(hypot(prr%y - ban%y(i), prr%z - ban%z(i)), dim=1)
         d = hypot(prr%y(j) - ban%y(i), prr%z(j) - ban%z(i))
         worst = max(worst, d)
         if (j <= last) then
            call test_failed(error, '.ban point order differs from .prr at .ban point '// &
               int_text(i))
            return
         end if
         last = j
      end do
      call check(error, worst, 0.0_wp, 'largest distance .ban → .prr (mm)', thr=1.0e-9_wp)
   end subroutine test_ban_equals_prr

   !> The measured MiniProf files read and clean without error, in canonical orientation.
   subroutine test_measured(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)
      integer :: n, i
      if (.not. have_shared(error)) return

      ! Wheel: X from the flange back (≈ 0) to the field side (131 mm), Y down: only reversed.
      call read_profile(sample_file('Car7216_0001r.whl'), p, err, line_of_point=lines)
      if (failed(error, err)) return
      call clean_profile(p, err, lines)
      if (failed(error, err)) return
      n = p%size()
      call check(error, p%kind, profile_kind_wheel)
      if (allocated(error)) return
      call check(error, p%y(1) > 130.0_wp .and. abs(p%y(n)) < 0.2_wp, &
         'field side first, flange back (y ≈ 0) last')
      if (allocated(error)) return
      i = maxloc(p%z, dim=1)
      call check(error, abs(p%z(i) - 27.81_wp) <= 0.005_wp .and. abs(p%y(i) - 15.9_wp) <= &
         0.05_wp, 'flange tip (largest z 27.81 at y 15.9, doc/profiles.md)')
      if (allocated(error)) return
      call check(error, lines(1), 655, 'first point = last file line')
      if (allocated(error)) return

      ! Rail: MiniProf X points to the track centre (mirrored), Y up (mirror detected).
      call read_profile(sample_file('avg_HR.BAN'), p, err, line_of_point=lines)
      if (failed(error, err)) return
      call clean_profile(p, err, lines)
      if (failed(error, err)) return
      n = p%size()
      call check(error, p%kind, profile_kind_rail)
      if (allocated(error)) return
      ! XYPoints = 147; the pair at lines 135–136 (X = 29.27 then 29.26) is a zig-zag, merged.
      call check(error, n, 146, '147 points, one zig-zag pair merged')
      if (allocated(error)) return
      call check(error, count(lines == 135) + count(lines == 136) == 1, &
         'the merged point carries one of lines 135, 136')
      if (allocated(error)) return
      i = minloc(p%z, dim=1)
      call check(error, p%z(i), 0.21_wp, 'crown (Y = −0.21 in the file) at z = 0.21', &
         thr=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, p%y(1), -46.59_wp, 'gauge face first at y = −46.59', thr=1.0e-9_wp)
      if (allocated(error)) return
      call check(error, p%z(1) > 25.0_wp .and. p%y(n) > 11.0_wp, &
         'gauge face reaches z = 25.4 below the crown, field side at y = 11.7')
   end subroutine test_measured

   ! --- real-file variations -------------------------------------------------------------------

   !> CRLF ends, a byte-order mark, tabs, commas, semicolons, trailing comments, blank lines,
   !> extra numeric columns, D exponents and a kind comment: all read as plain y z.
   subroutine test_file_variants(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      character(len=*), parameter :: file = tmp//'variants.txt'
      character(len=2), parameter :: crlf = achar(13)//achar(10)
      integer, allocatable :: lines(:)

      call write_text(file, achar(239)//achar(187)//achar(191)//'% made by hand'//crlf// &
         '#  kind :  Rail '//crlf//crlf// &
         '-10.0'//achar(9)//'2.0'//crlf// &
         '-5.0, 0.5, 99 ! weight column'//crlf// &
         '  0.0 ;0.0'//crlf// &
         crlf// &
         '5.0D0   0.5   1  2  3'//crlf// &
         '10.0 2.0 # last'//crlf)
      call read_profile(file, p, err, line_of_point=lines)
      if (failed(error, err)) return
      call check(error, p%kind, profile_kind_rail, 'kind from the comment')
      if (allocated(error)) return
      call check(error, p%size(), 5)
      if (allocated(error)) return
      call check(error, all(abs(p%y - [-10.0_wp, -5.0_wp, 0.0_wp, 5.0_wp, 10.0_wp]) == 0) &
         .and. all(abs(p%z - [2.0_wp, 0.5_wp, 0.0_wp, 0.5_wp, 2.0_wp]) == 0), 'values')
      if (allocated(error)) return
      call check(error, all(lines == [4, 5, 6, 8, 9]), 'line numbers')
      if (allocated(error)) return
      call check(error, p%s(5), 2*hypot(5.0_wp, 1.5_wp) + 2*hypot(5.0_wp, 0.5_wp), &
         'arc length', thr=1.0e-12_wp)
      if (allocated(error)) return
      ! Decimal commas (a German locale): one message naming the line and the fix (they were
      ! read as four numbers per line, and the message blamed the length unit).
      call write_text(file, '# kind = rail'//crlf//'-10,0 2,0'//crlf//'-5,0;0,5'//crlf// &
         '0,0 0,0'//crlf//'5,0 0,5'//crlf//'10,0 2,0'//crlf)
      call read_profile(file, p, err)
      call check(error, allocated(err), 'decimal commas accepted')
      if (allocated(error)) return
      call check(error, index(err%message, 'line 2') > 0 .and. index(err%message, &
         'decimal commas') > 0 .and. index(err%message, "'-10.0 2.0'") > 0, err%message)
      if (allocated(error)) return
      ! Commas as separators (with decimal points, or between integers) still read.
      call write_text(file, '# kind = rail'//crlf//'-10,2'//crlf//'-5.0,0.5'//crlf// &
         '0,0'//crlf//'5.0, 0.5'//crlf//'10,2'//crlf)
      call read_profile(file, p, err)
      if (failed(error, err)) return
      call check(error, p%size(), 5, 'comma-separated points')
   end subroutine test_file_variants

   !> The SIMPACK wheel with CRLF line ends and tabs reads exactly as the original.
   subroutine test_simpack_crlf(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: a, b
      type(lib_error), allocatable :: err
      character(len=*), parameter :: copy = tmp//'crlf.prw'
      integer :: stat
      if (.not. have_shared(error)) return
      call execute_command_line("sed 's/$/\r/' "//sample_file('MBench_S1002_v3.prw')//' > '//copy, &
         exitstat=stat)
      if (stat /= 0) then
         call skip_test(error, 'no sed to make the CRLF copy')
         return
      end if
      call read_profile(sample_file('MBench_S1002_v3.prw'), a, err)
      if (failed(error, err)) return
      call read_profile(copy, b, err)
      if (failed(error, err)) return
      call check(error, a%size() == b%size(), 'same number of points')
      if (allocated(error)) return
      call check(error, all(a%y == b%y) .and. all(a%z == b%z), 'same points')
   end subroutine test_simpack_crlf

   !> The SIMPACK processing keys act as documented: shift, minimum distance, y bounds, z
   !> clipping, mirror, units (metres) and inversion.
   subroutine test_simpack_keys(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      character(len=*), parameter :: file = tmp//'keys.prr'
      integer, allocatable :: lines(:)

      call write_text(file, lines_of([character(len=60) :: &
         'header.begin', '  version = 1', '  type = 0   ! rail', 'header.end', &
         'spline.begin', "  comment = 'test ! not a comment'", &
         '  point.dist.min = 0.0001', '  shift.y = 0.001', '  shift.z = 0.0', &
         '  bound.y.min = -0.0205', '  bound.y.max = 0.0215', &
         '  bound.z.min = -0.0035', '  bound.z.max = 1.0', &
         '  mirror.y = 1', '  mirror.z = 1', '  inversion = 1', &
         '  units.len.f = +1.0e+00', '  point.begin', &
         '   0.0300  -0.0040', '   0.0200  -0.0040', '   0.01999995 -0.0040', &
         '   0.0100  -0.0010', '   0.0000   0.0000', '  -0.0100  -0.0010', &
         '  -0.0200  -0.0040', '  -0.0300  -0.0040', &
         '  point.end', 'spline.end']))
      call read_profile(file, p, err, line_of_point=lines)
      if (failed(error, err)) return
      ! y + 1 mm shift: 31 21 (21.00005 dropped: < 0.1 mm from 21) 11 1 −9 −19 −29 mm; y bounds
      ! delete 31 and −29; z clipped at −3.5 mm; then y and z mirrored, m → mm, inverted, and
      ! put back in ascending order for a rail.
      call check(error, p%size(), 5, 'points kept')
      if (allocated(error)) return
      call check(error, all(abs(p%y - [-21.0_wp, -11.0_wp, -1.0_wp, 9.0_wp, 19.0_wp]) < &
         1.0e-12_wp), 'y: shifted, bounded, mirrored, in mm')
      if (allocated(error)) return
      call check(error, all(abs(p%z - [3.5_wp, 1.0_wp, 0.0_wp, 1.0_wp, 3.5_wp]) < 1.0e-12_wp), &
         'z: clipped to 3.5 mm, mirrored')
      if (allocated(error)) return
      call check(error, all(lines == [20, 22, 23, 24, 25]), 'line numbers follow the points')
   end subroutine test_simpack_keys

   !> Arguments replace the file's settings; a kind that contradicts the file is an error.
   subroutine test_overrides(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p, q
      type(lib_error), allocatable :: err
      if (.not. have_shared(error)) return
      call read_profile(sample_file('MBench_S1002_v3.prw'), p, err)
      if (failed(error, err)) return
      ! mirror_y = .false. keeps the file's y: flange at positive y, no flange-side check.
      call read_profile(sample_file('MBench_S1002_v3.prw'), q, err, mirror_y=.false., scale=0.5_wp)
      if (failed(error, err)) return
      call check(error, q%size() == p%size(), 'same points')
      if (allocated(error)) return
      call check(error, all(abs(q%y(q%size():1:-1) + 0.5_wp*p%y) < 1.0e-12_wp) .and. &
         all(abs(q%z(q%size():1:-1) - 0.5_wp*p%z) < 1.0e-12_wp), &
         'unmirrored y, scale 0.5 instead of units.len.f')
      if (allocated(error)) return
      call read_profile(sample_file('MBench_S1002_v3.prw'), q, err, kind=profile_kind_rail)
      call expect_error(error, err, stat_invalid_input, [character(len=40) :: &
         'MBench_S1002_v3.prw, line 12:', 'wheel profile', 'rail profile was asked'])
      if (allocated(error)) return
      ! The .prw without its mirror.y is a wheel with its flange on the field side.
      call read_profile(sample_file('MBench_S1002_v3.prw'), q, err, format='plain', &
         kind=profile_kind_wheel)
      call expect_error(error, err, stat_invalid_input, [character(len=40) :: &
         'MBench_S1002_v3.prw, line 10:', "expected two numbers 'y z'"])
      if (allocated(error)) return
      ! A flat wheel (a cylinder, every z = 0) has no flange to be on the wrong side: read as it
      ! is (was refused, naming its first point "the flange").
      call write_text(tmp//'flat.txt', '# kind = wheel'//achar(10)//'60 0'//achar(10)// &
         '20 0'//achar(10)//'-20 0'//achar(10)//'-60 0'//achar(10))
      call read_profile(tmp//'flat.txt', q, err)
      if (allocated(err)) then
         call test_failed(error, 'flat wheel: '//err%message)
         return
      end if
      call check(error, q%size(), 4, 'flat wheel read')
   end subroutine test_overrides

   ! --- bad files ------------------------------------------------------------------------------

   !> Non-numbers, NaN, Inf, overflow and non-numeric extra columns: file, line and reason.
   subroutine test_bad_numbers(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: file = tmp//'bad.txt'
      character(len=*), parameter :: head = '# kind = rail'//achar(10)//'-10 1'//achar(10)// &
         '-5 0.2'//achar(10)

      call write_text(file, head//'0 abc'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "expected two numbers 'y z'", "found '0 abc'"])
      if (allocated(error)) return
      call write_text(file, head//'0 NaN'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "'NaN' is not a finite number"])
      if (allocated(error)) return
      call write_text(file, head//'-Inf 0'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "'-Inf' is not a finite number"])
      if (allocated(error)) return
      call write_text(file, head//'0 1e999'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "'1e999' is out of range"])
      if (allocated(error)) return
      call write_text(file, head//'0 0 label'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "column 3 holds 'label'"])
      if (allocated(error)) return
      call write_text(file, head//'0'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "expected two numbers 'y z', found '0'"])
      if (allocated(error)) return
      call write_text(file, head//'1.2.3 0'//achar(10)//'5 0.2'//achar(10))
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 4:', "found '1.2.3 0'"])
      if (allocated(error)) return
      call write_text(file, head)
      call expect_read_error(error, file, stat_invalid_input, &
         [character(len=50) :: 'bad.txt, line 3:', 'after 2 profile point(s)', 'at least 4'])
   end subroutine test_bad_numbers

   !> Structural errors of SIMPACK and MiniProf files, and an undecidable or upside-down kind.
   subroutine test_bad_structure(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: prr = tmp//'bad.prr', ban = tmp//'bad.ban', &
         txt = tmp//'nokind.txt'
      character(len=60), parameter :: pts(6) = [character(len=60) :: &
         '-10 2', '-5 0.5', '0 0', '5 0.5', '10 2', 'point.end']
      type(profile_type) :: p
      type(lib_error), allocatable :: err

      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 0', &
         'header.end', 'spline.begin', 'smoothing = 1', 'point.begin', pts, 'spline.end']))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, line 5:', "unknown key 'smoothing'", 'known keys are approx.smooth'])
      if (allocated(error)) return
      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 0', &
         'header.end', 'point.begin', pts, 'spline.end']))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, line 4:', "'point.begin' is out of place", 'outside any section'])
      if (allocated(error)) return
      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 0', &
         'header.end', 'spline.begin', 'mirror.y = 2', 'point.begin', pts, 'spline.end']))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, line 5:', 'mirror.y = 2 must be 0 or 1'])
      if (allocated(error)) return
      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 0', &
         'header.end', 'spline.begin', 'point.begin', pts(1:5)]))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, line 10:', 'the file ends inside the point block'])
      if (allocated(error)) return
      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 1', &
         'header.end', 'spline.begin', 'point.begin', pts, 'spline.end']))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, line 2:', "extension '.prr' stands for a rail"])
      if (allocated(error)) return
      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 0', &
         'header.end', 'spline.begin', 'rotate = 0.01', 'point.begin', pts, 'spline.end']))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, line 5:', 'rotate = 0.01 is not supported'])
      if (allocated(error)) return
      ! An upside-down rail (crown below the ends) without mirror_z.
      call write_text(prr, lines_of([character(len=60) :: 'header.begin', 'type = 0', &
         'header.end', 'spline.begin', 'point.begin', '-10 -2', '-5 -0.5', '0 0', '5 -0.5', &
         '10 -2', 'point.end', 'spline.end']))
      call expect_read_error(error, prr, stat_invalid_input, [character(len=50) :: &
         'bad.prr, lines 6–10:', 'looks upside down', 'mirror_z'])
      if (allocated(error)) return
      call write_text(ban, lines_of([character(len=60) :: 'XYPoints=5', 'ColumnDef=X,Y', '', &
         '10 2', '5 0.5', 'Gauge=1435', '0 0', '-5 0.5', '-10 2']))
      call expect_read_error(error, ban, stat_invalid_input, [character(len=50) :: &
         'bad.ban, line 6:', "header line 'Gauge=1435'", 'started (line 4)'])
      if (allocated(error)) return
      ! XYPoints counts the points commented out in the list too (MiniProf writes them so):
      ! five lines, one commented, read; six declared, or four, are a file cut short or one
      ! holding more than its header says.
      call write_text(ban, lines_of([character(len=60) :: 'XYPoints=5', 'ColumnDef=X,Y', '', &
         '10 2', '" 7.5 1.1', '5 0.5', '0 0', '-5 0.5', '-10 2']))
      call expect_read_error(error, ban, stat_invalid_input, [character(len=50) :: &
         'bad.ban: the header declares XYPoints=5', 'holds 6 point(s) (5 read, 1 commented', &
         'looks to hold more'])
      if (allocated(error)) return
      call write_text(ban, lines_of([character(len=60) :: 'XYPoints=7', 'ColumnDef=X,Y', '', &
         '10 2', '" 7.5 1.1', '5 0.5', '0 0', '-5 0.5', '-10 2']))
      call expect_read_error(error, ban, stat_invalid_input, [character(len=50) :: &
         'declares XYPoints=7', 'holds 6 point(s)', 'looks cut short'])
      if (allocated(error)) return
      call write_text(ban, lines_of([character(len=60) :: 'XYPoints=5.5', 'ColumnDef=X,Y', '', &
         '10 2', '5 0.5', '0 0', '-5 0.5', '-10 2']))
      call expect_read_error(error, ban, stat_invalid_input, [character(len=50) :: &
         'bad.ban, line 1:', "XYPoints = '5.5' is not a whole number"])
      if (allocated(error)) return
      call write_text(ban, lines_of([character(len=60) :: 'XYPoints=6', 'ColumnDef=X,Y', '', &
         '10 2', '" 7.5 1.1', '5 0.5', '0 0', '-5 0.5', '-10 2']))
      call read_profile(ban, p, err)
      if (allocated(err)) then
         call test_failed(error, 'six declared, five read and one commented: '//err%message)
         return
      end if
      call check(error, p%size(), 5, 'the five points read, the commented one left out')
      if (allocated(error)) return
      ! A MiniProf rail (.ban) asked for as a wheel: its extension's conventions say rail.
      call read_profile(ban, p, err, kind=profile_kind_wheel)
      call expect_error(error, err, stat_invalid_input, [character(len=50) :: &
         "bad.ban: the extension '.ban' stands for a rail", 'a wheel profile was asked for'])
      if (allocated(error)) return
      call write_text(ban, lines_of([character(len=60) :: 'ColumnDef=A,Y,C', '', '10 2 0']))
      call expect_read_error(error, ban, stat_invalid_input, [character(len=50) :: &
         'bad.ban, line 1:', "ColumnDef = 'A,Y,C' has no X and Y columns"])
      if (allocated(error)) return
      call write_text(txt, lines_of([character(len=60) :: '-10 2', '-5 0.5', '0 0', &
         '5 0.5', '10 2']))
      call expect_read_error(error, txt, stat_invalid_input, [character(len=50) :: &
         'nokind.txt:', 'rail or a wheel', '# kind = rail'])
   end subroutine test_bad_structure

   !> A missing file or a directory is an I/O error; an unknown format keyword, a bad scale or
   !> kind a usage error.
   subroutine test_missing(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      call read_profile(tmp//'does_not_exist.prr', p, err)
      call expect_error(error, err, stat_io, [character(len=50) :: &
         'does_not_exist.prr:', 'cannot open the profile file'])
      if (allocated(error)) return
      call read_profile('build', p, err, kind=profile_kind_rail)
      call expect_error(error, err, stat_io, [character(len=50) :: &
         'build: cannot read the profile file'])
      if (allocated(error)) return
      call read_profile(tmp//'variants.txt', p, err, format='csv')
      call expect_error(error, err, stat_usage, [character(len=50) :: 'variants.txt:', &
         "unknown profile format 'csv'", 'auto, plain, simpack or miniprof'])
      if (allocated(error)) return
      call read_profile(tmp//'variants.txt', p, err, scale=-1.0_wp)
      call expect_error(error, err, stat_usage, [character(len=50) :: 'variants.txt:', &
         'must be positive'])
      if (allocated(error)) return
      call read_profile(tmp//'variants.txt', p, err, kind=7)
      call expect_error(error, err, stat_usage, [character(len=50) :: 'kind = 7'])
   end subroutine test_missing

   ! --- round trips ----------------------------------------------------------------------------

   !> Built-in profiles written by write_builtin_profiles (all three files of doc/profiles.md)
   !> read back to the printed digits (15 significant), with kind from the header; writing again
   !> gives the same text.
   subroutine test_round_trip_builtin(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: original, again
      type(lib_error), allocatable :: err
      character(len=12), parameter :: names(3) = [character(len=12) :: 'S1002', 'UIC60', &
         'UIC60-canted']
      integer :: i
      call write_builtin_profiles('build', err)
      if (failed(error, err)) return
      do i = 1, size(names)
         call builtin_profile(names(i), original, err)
         if (failed(error, err)) return
         call read_profile('build/'//trim(names(i))//'.txt', again, err)
         if (failed(error, err)) return
         call check(error, again%kind, original%kind, names(i)//' kind from the header')
         if (allocated(error)) return
         call same_to_printed_digits(error, original, again, names(i))
         if (allocated(error)) return
         call write_profile_plain(again, tmp//'again.txt', err)
         if (failed(error, err)) return
         call same_data_lines(error, 'build/'//trim(names(i))//'.txt', tmp//'again.txt')
         if (allocated(error)) return
      end do
   end subroutine test_round_trip_builtin

   !> A file read, written and read again gives the same points to the printed digits.
   subroutine test_round_trip_file(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: original, again
      type(lib_error), allocatable :: err
      if (.not. have_shared(error)) return
      call read_profile(sample_file('MBench_S1002_v3.prw'), original, err)
      if (failed(error, err)) return
      call write_profile_plain(original, tmp//'prw.txt', err)
      if (failed(error, err)) return
      call read_profile(tmp//'prw.txt', again, err)
      if (failed(error, err)) return
      call check(error, again%kind, profile_kind_wheel)
      if (allocated(error)) return
      call same_to_printed_digits(error, original, again, 'MBench_S1002_v3.prw')
   end subroutine test_round_trip_file

   subroutine same_to_printed_digits(error, a, b, what)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type), intent(in) :: a, b
      character(len=*), intent(in) :: what
      real(wp), parameter :: half_digit = 5.0e-15_wp
      if (a%size() /= b%size()) then
         call test_failed(error, what//': '//int_text(b%size())//' points read back, '// &
            int_text(a%size())//' written')
         return
      end if
      call check(error, all(abs(a%y - b%y) <= half_digit*abs(a%y)) .and. &
         all(abs(a%z - b%z) <= half_digit*abs(a%z)), &
         what//': values differ beyond the 15th significant digit')
   end subroutine same_to_printed_digits

   !> The two files hold the same lines after their header comments.
   subroutine same_data_lines(error, file_a, file_b)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: file_a, file_b
      integer :: ua, ub, sa, sb, line
      character(len=200) :: a, b
      open (newunit=ua, file=file_a, status='old', action='read')
      open (newunit=ub, file=file_b, status='old', action='read')
      line = 0
      do
         read (ua, '(a)', iostat=sa) a
         read (ub, '(a)', iostat=sb) b
         line = line + 1
         if (sa /= 0 .or. sb /= 0) exit
         if (a(1:1) == '#' .and. b(1:1) == '#') cycle
         if (a /= b) exit
      end do
      close (ua)
      close (ub)
      call check(error, sa /= 0 .and. sb /= 0, file_b//' differs from '//file_a// &
         ' at line '//int_text(line))
   end subroutine same_data_lines

   ! --- helpers --------------------------------------------------------------------------------

   !> Whether the external data's sample profiles are there (test_external_data); the test is
   !> skipped when SHCONTACT_EXTERNAL_DATA is unset, failed when the folder lacks them.
   logical function have_shared(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: path
      path = external_file('profiles/MBench_UIC60_v3.prr', error)
      have_shared = .not. allocated(error)
   end function have_shared

   !> A sample profile of the external data, once have_shared has let the test run.
   function sample_file(name) result(path)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: path
      type(error_type), allocatable :: missing
      path = external_file('profiles/'//name, missing)
   end function sample_file

   !> Turn a library error into a test failure; true when there was one.
   logical function failed(error, err)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable, intent(in) :: err
      failed = allocated(err)
      if (failed) call test_failed(error, 'unexpected error: '//err%message)
   end function failed

   subroutine expect_read_error(error, file, stat, fragments)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: file
      integer, intent(in) :: stat
      character(len=*), intent(in) :: fragments(:)
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      call read_profile(file, p, err)
      call expect_error(error, err, stat, fragments)
   end subroutine expect_read_error

   !> The library error exists, has the status and contains every fragment.
   subroutine expect_error(error, err, stat, fragments)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable, intent(in) :: err
      integer, intent(in) :: stat
      character(len=*), intent(in) :: fragments(:)
      integer :: i
      if (.not. allocated(err)) then
         call test_failed(error, 'expected an error containing "'//trim(fragments(1))//'"')
         return
      end if
      if (err%stat /= stat) then
         call test_failed(error, 'status '//int_text(err%stat)//' instead of '// &
            int_text(stat)//': '//err%message)
         return
      end if
      do i = 1, size(fragments)
         if (index(err%message, trim(fragments(i))) == 0) then
            call test_failed(error, 'message lacks "'//trim(fragments(i))//'": '//err%message)
            return
         end if
      end do
   end subroutine expect_error

   subroutine write_text(file, text)
      character(len=*), intent(in) :: file, text
      integer :: unit
      open (newunit=unit, file=file, status='replace', access='stream', form='unformatted')
      write (unit) text
      close (unit)
   end subroutine write_text

   !> Lines joined with LF, each trimmed.
   pure function lines_of(items) result(text)
      character(len=*), intent(in) :: items(:)
      character(len=:), allocatable :: text
      integer :: i
      text = ''
      do i = 1, size(items)
         text = text//trim(items(i))//achar(10)
      end do
   end function lines_of

   pure function int_text(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=16) :: buffer
      write (buffer, '(i0)') i
      text = trim(buffer)
   end function int_text

end module test_profile_reader
