!> Tests of the profile clean-up (doc/theory.md §5.1): every rejection names the source, the line
!> and the reason; zig-zag pairs are merged, true kinks kept and flagged.
module test_profile_cleanup
   use, intrinsic :: iso_fortran_env, only: int64
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_usage
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile, is_finite_value, max_profile_points
   implicit none
   private
   public :: collect_profile_cleanup

   character(len=*), parameter :: tmp = 'build/test_profile_cleanup_'
   character(len=*), parameter :: rail_head = '# kind = rail'//achar(10)

contains

   subroutine collect_profile_cleanup(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('finite_by_bits', test_finite_bits), &
         new_unittest('nan_inf_rejected', test_nan_inf), &
         new_unittest('too_few_points', test_too_few), &
         new_unittest('too_many_points', test_too_many), &
         new_unittest('duplicate_rejected', test_duplicate), &
         new_unittest('loop_rejected', test_loop), &
         new_unittest('unit_mistake_rejected', test_units), &
         new_unittest('wrong_order_rejected', test_order), &
         new_unittest('zigzag_pair_merged', test_zigzag), &
         new_unittest('true_kink_flagged', test_kink), &
         new_unittest('near_corners_not_kinks', test_no_kink), &
         new_unittest('line_of_point_size', test_line_size) &
         ]
   end subroutine collect_profile_cleanup

   !> The bit test separates finite values from NaN and ±Inf without arithmetic.
   subroutine test_finite_bits(error)
      type(error_type), allocatable, intent(out) :: error
      call check(error, all(is_finite_value([0.0_wp, -1.0_wp, huge(1.0_wp), -huge(1.0_wp), &
         tiny(1.0_wp)])), 'finite values')
      if (allocated(error)) return
      call check(error, .not. any(is_finite_value([nan(), inf(), -inf()])), 'NaN and Inf')
   end subroutine test_finite_bits

   !> A NaN or Inf coordinate is reported with its line (or point number without lines).
   subroutine test_nan_inf(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)
      integer :: i

      p = line_profile(8)
      p%z(3) = nan()
      lines = [(10 + 2*i, i = 1, 8)]
      call clean_profile(p, err, lines)
      call expect_error(error, err, stat_invalid_input, [character(len=50) :: &
         'memory, line 16:', 'point 3', 'NaN or infinite'])
      if (allocated(error)) return
      p = line_profile(8)
      p%y(5) = -inf()
      call clean_profile(p, err)
      call expect_error(error, err, stat_invalid_input, [character(len=50) :: &
         'memory, point 5:', 'NaN or infinite'])
   end subroutine test_nan_inf

   subroutine test_too_few(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)
      p = line_profile(3)
      lines = [4, 5, 7]
      call clean_profile(p, err, lines)
      call expect_error(error, err, stat_invalid_input, [character(len=50) :: &
         'memory, line 7:', 'after 3 point(s)', 'at least 4'])
   end subroutine test_too_few

   !> Issue 24 item 9: a 2-million-point profile ran for minutes (pairwise loop checks); more
   !> than max_profile_points points are refused at once, with the count and the bound.
   subroutine test_too_many(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)
      p = line_profile(max_profile_points + 1)
      allocate (lines(max_profile_points + 1), source=0)
      call clean_profile(p, err, lines)
      call expect_error(error, err, stat_invalid_input, [character(len=50) :: &
         'the profile has 50001 points', 'at most 50000 are accepted'])
   end subroutine test_too_many

   !> A repeated line in a file: both lines named.
   subroutine test_duplicate(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call load_and_clean(tmp//'dup.txt', rail_head//'-10 2'//achar(10)//'-5 0.5'// &
         achar(10)//'-5 0.5'//achar(10)//'0 0'//achar(10)//'5 0.5'//achar(10)//'10 2', err)
      call expect_error(error, err, stat_invalid_input, [character(len=60) :: &
         'dup.txt, line 4:', 'duplicate point (-5, 0.5)', 'repeats the point of line 3;'])
   end subroutine test_duplicate

   !> A profile that runs back across itself.
   subroutine test_loop(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call load_and_clean(tmp//'loop.txt', rail_head//'-20 4'//achar(10)//'-10 0'// &
         achar(10)//'10 0'//achar(10)//'0 -2'//achar(10)//'0 2'//achar(10)//'20 4', err)
      call expect_error(error, err, stat_invalid_input, [character(len=60) :: &
         'loop.txt, line 3:', 'crosses itself', 'point 4 (0, -2) at line 5', &
         'loops are not allowed'])
   end subroutine test_loop

   !> A rail in metres or micrometres: total arc length out of 5–500 mm; scale fixes it.
   subroutine test_units(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(profile_type) :: p
      integer, allocatable :: lines(:)
      character(len=*), parameter :: metres = rail_head//'-0.01 0.002'//achar(10)// &
         '-0.005 0.0005'//achar(10)//'0 0'//achar(10)//'0.005 0.0005'//achar(10)//'0.01 0.002'
      call load_and_clean(tmp//'metres.txt', metres, err)
      call expect_error(error, err, stat_invalid_input, [character(len=60) :: &
         'metres.txt, line 2 to line 6:', 'total arc length 0.0204', 'outside 5–500 mm', &
         'scale factor'])
      if (allocated(error)) return
      ! In metres, two measured points 5e-5 mm apart are closer than the duplicate distance:
      ! the unit is named, not "remove one of them".
      call load_and_clean(tmp//'metres_close.txt', rail_head//'-0.01 0.002'//achar(10)// &
         '-0.00500005 0.0005'//achar(10)//'-0.005 0.0005'//achar(10)//'0 0'//achar(10)// &
         '0.005 0.0005'//achar(10)//'0.01 0.002', err)
      call expect_error(error, err, stat_invalid_input, [character(len=60) :: &
         'metres_close.txt, line 2 to line 7:', 'another length unit'])
      if (allocated(error)) return
      call load_and_clean(tmp//'microns.txt', rail_head//'-10000 2000'//achar(10)// &
         '-5000 500'//achar(10)//'0 0'//achar(10)//'5000 500'//achar(10)//'10000 2000', err)
      call expect_error(error, err, stat_invalid_input, [character(len=60) :: &
         'microns.txt, line 2 to line 6:', 'total arc length 2049', 'outside 5–500 mm'])
      if (allocated(error)) return
      call read_profile(tmp//'metres.txt', p, err, scale=1000.0_wp, line_of_point=lines)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call clean_profile(p, err, lines)
      call check(error, .not. allocated(err), 'scale = 1000 repairs the metre file')
      if (allocated(error)) return
      ! The wrong factor given (the file in µm, scaled by 1000): the message names the factor
      ! given instead of asking for one.
      call read_profile(tmp//'microns.txt', p, err, scale=1000.0_wp, line_of_point=lines)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call clean_profile(p, err, lines, scale=1000.0_wp)
      call expect_error(error, err, stat_invalid_input, [character(len=60) :: &
         'microns.txt, line 2 to line 6:', 'multiplied by the scale factor given, 1000', &
         '0.001 for µm'])
   end subroutine test_units

   subroutine test_order(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      ! 12 points: 5.5 mm, within the arc-length range, which is checked first.
      p = line_profile(12)
      p%y = p%y(12:1:-1)
      call clean_profile(p, err)
      call expect_error(error, err, stat_invalid_input, [character(len=70) :: &
         'memory, point 1:', 'rail points must run from the track centre to the field side'])
      if (allocated(error)) return
      p = line_profile(12)
      p%kind = profile_kind_wheel
      call clean_profile(p, err)
      call expect_error(error, err, stat_invalid_input, [character(len=70) :: &
         'wheel points must run from the field side to the flange back'])
   end subroutine test_order

   !> Points 32 and 33 of a straight line swapped with a small vertical offset (a stitching
   !> error): the pair is replaced by its mean, nothing else changes, no kink remains.
   subroutine test_zigzag(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)
      integer :: i
      p = line_profile(41)
      p%y(32) = 6.0_wp
      p%z(32) = 0.02_wp
      p%y(33) = 5.5_wp
      p%z(33) = -0.02_wp
      lines = [(100 + i, i = 1, 41)]
      call clean_profile(p, err, lines)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, p%size(), 40, 'one point fewer')
      if (allocated(error)) return
      call check(error, p%y(32), 5.75_wp, 'merged y = mean', thr=1.0e-15_wp)
      if (allocated(error)) return
      call check(error, p%z(32), 0.0_wp, 'merged z = mean', thr=1.0e-15_wp)
      if (allocated(error)) return
      call check(error, lines(32) == 132 .and. lines(33) == 134 .and. size(lines) == 40, &
         'lines follow the points')
      if (allocated(error)) return
      call check(error, all(p%y(33:) == [(-10.0_wp + 0.5_wp*i, i = 33, 40)]), 'rest unchanged')
      if (allocated(error)) return
      call check(error, .not. any(p%kink), 'no kink after the merge')
   end subroutine test_zigzag

   !> A 40° corner in otherwise straight lines (0.25 mm spacing) is kept and flagged; a smooth
   !> R5 arc with the same spacing has no kink.
   subroutine test_kink(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      real(wp), parameter :: slope = tan(40.0_wp*acos(-1.0_wp)/180.0_wp)
      integer :: i, n
      n = 81
      p%source = 'memory'
      p%kind = profile_kind_rail
      p%y = [(-10.0_wp + 0.25_wp*i, i = 0, n - 1)]
      p%z = merge(slope*p%y, 0.0_wp*p%y, p%y > 0.0_wp)
      call clean_profile(p, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, count(p%kink), 1, 'one kink')
      if (allocated(error)) return
      call check(error, p%kink(41), 'the kink is the corner at y = 0')
      if (allocated(error)) return
      call check(error, p%size(), n, 'no point removed')
      if (allocated(error)) return

      p%y = [(5.0_wp*sin(-1.2_wp + 0.05_wp*i), i = 0, 48)]
      p%z = [(5.0_wp*(1.0_wp - cos(-1.2_wp + 0.05_wp*i)), i = 0, 48)]
      call clean_profile(p, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, .not. any(p%kink), 'a smooth arc has no kink')
   end subroutine test_kink

   !> Two 40° corners 1 mm apart: each has a large turn within 2 mm, so neither is a kink.
   subroutine test_no_kink(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      real(wp), parameter :: slope = tan(40.0_wp*acos(-1.0_wp)/180.0_wp)
      integer :: i
      p%source = 'memory'
      p%kind = profile_kind_rail
      p%y = [(-10.0_wp + 0.25_wp*i, i = 0, 80)]
      p%z = slope*min(max(p%y, 0.0_wp), 1.0_wp)
      call clean_profile(p, err)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, .not. any(p%kink), 'no kink flagged')
   end subroutine test_no_kink

   subroutine test_line_size(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p
      type(lib_error), allocatable :: err
      integer, allocatable :: lines(:)
      p = line_profile(8)
      lines = [1, 2, 3]
      call clean_profile(p, err, lines)
      call expect_error(error, err, stat_usage, [character(len=50) :: &
         'line_of_point has 3 entries for 8 points'])
   end subroutine test_line_size

   ! --- helpers --------------------------------------------------------------------------------

   !> A straight rail z = 0 from y = −10 in steps of 0.5 mm.
   function line_profile(n) result(p)
      integer, intent(in) :: n
      type(profile_type) :: p
      integer :: i
      p%source = 'memory'
      p%kind = profile_kind_rail
      p%y = [(-10.0_wp + 0.5_wp*i, i = 0, n - 1)]
      allocate (p%z(n), source=0.0_wp)
   end function line_profile

   subroutine load_and_clean(file, text, err)
      character(len=*), intent(in) :: file, text
      type(lib_error), allocatable, intent(out) :: err
      type(profile_type) :: p
      integer, allocatable :: lines(:)
      integer :: unit
      open (newunit=unit, file=file, status='replace', access='stream', form='unformatted')
      write (unit) text//achar(10)
      close (unit)
      call read_profile(file, p, err, line_of_point=lines)
      if (allocated(err)) return
      call clean_profile(p, err, lines)
   end subroutine load_and_clean

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
         call test_failed(error, 'wrong status: '//err%message)
         return
      end if
      do i = 1, size(fragments)
         if (index(err%message, trim(fragments(i))) == 0) then
            call test_failed(error, 'message lacks "'//trim(fragments(i))//'": '//err%message)
            return
         end if
      end do
   end subroutine expect_error

   !> A quiet NaN and +Inf from their bit patterns (no arithmetic, no trap).
   real(wp) function nan()
      nan = transfer(int(z'7FF8000000000000', int64), 1.0_wp)
   end function nan

   real(wp) function inf()
      inf = transfer(int(z'7FF0000000000000', int64), 1.0_wp)
   end function inf

end module test_profile_cleanup
