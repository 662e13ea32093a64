!> The same profile gives the same contact however it reaches the solver (issue 24, items 2 and
!> 5): a profile written by shcontact and read back (MiniProf wheels included, whose origin is at
!> the flange back), the library's get_profile → create_arrays round trip, and a profile with
!> points added on the chords between its samples.
!>
!> The contact is the headline case (builtin rail or wheel opposite, t_y = 4.733 mm, N = 64.7 kN,
!> the default creepages); its 25 flat values (forces, moment, p_max, γ₀, patch counts, ...) are
!> compared with a relative tolerance stated at each test.
module test_profile_invariance
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use test_external_data, only: external_file
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, profile_kind_rail, &
      tape_circle_origin
   use shcontact_profile_source, only: load_profile
   use shcontact_profile_collinear, only: drop_collinear
   use shcontact_profile_writer, only: write_profile_plain
   use shcontact_api_values, only: result_value_count
   use shcontact_api_context, only: contact_context_type, context_create, context_solve, &
      context_create_arrays, context_message
   use shcontact_api_context_results, only: context_get_profile
   use shcontact_core_files, only: file_exists
   implicit none
   private
   public :: collect_profile_invariance

   character(len=*), parameter :: tmp = 'build/test_profile_invariance_'
   !> The repository's S1002 samples (0.1 mm chords).
   character(len=*), parameter :: s1002_file = 'data/profiles/S1002.txt'
   !> Index of the patch count in the flat result (doc/api.md).
   integer, parameter :: i_patches = 18

contains

   subroutine collect_profile_invariance(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('written_profiles_read_back_to_the_same_contact', test_written), &
         new_unittest('get_profile_create_arrays_same_contact', test_arrays), &
         new_unittest('collinear_points_same_contact', test_collinear), &
         new_unittest('collinear_skeleton', test_skeleton) &
         ]
   end subroutine collect_profile_invariance

   ! --- item 2 ---------------------------------------------------------------------------------

   !> Every sample file of the external data (and S1002.txt) loaded, written by write_profile_plain and
   !> loaded again from the plain file: the same points (15 printed digits; a MiniProf wheel
   !> moved by −70 mm to the origin a plain file has) and the same contact to 1e-9 (the written
   !> digits; before the fix the MiniProf wheel landed 70 mm off: γ₀ +0.088 instead of −0.068,
   !> 3 patches instead of 2).
   subroutine test_written(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=24), parameter :: files(5) = [character(len=24) :: 'Car7216_0001r.whl', &
         'MBench_S1002_v3.prw', 'MBench_UIC60_v3.prr', 'MBench_UIC60_v3.ban', 'avg_HR.BAN']
      character(len=:), allocatable :: shared
      integer :: i
      call round_trip(error, s1002_file)
      if (allocated(error)) return
      shared = external_file('profiles/', error)
      if (allocated(error)) return
      do i = 1, size(files)
         call round_trip(error, shared//trim(files(i)))
         if (allocated(error)) return
      end do
   end subroutine test_written

   subroutine round_trip(error, file)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: file
      type(profile_type) :: loaded, again, expected
      type(lib_error), allocatable :: err
      real(wp) :: a(result_value_count), b(result_value_count)
      character(len=:), allocatable :: written

      call load_profile(file, profile=loaded, error=err)
      if (failed(error, err, file)) return
      written = tmp//'written.txt'
      call write_profile_plain(loaded, written, err)
      if (failed(error, err, file//' written')) return
      call load_profile(written, profile=again, error=err)
      if (failed(error, err, file//' read back')) return
      call check(error, again%kind, loaded%kind, file//': kind read back')
      if (allocated(error)) return
      expected = tape_circle_origin(loaded)
      call same_points(error, expected, again, file//' written and read back', 1.0e-12_wp)
      if (allocated(error)) return
      call solve_files(error, loaded%kind, file, a)
      if (allocated(error)) return
      call solve_files(error, loaded%kind, written, b)
      if (allocated(error)) return
      call same_values(error, a, b, 1.0e-9_wp, file//' and the file written from it')
   end subroutine round_trip

   !> context_get_profile → context_create_arrays of the MiniProf wheel and of S1002.txt (the
   !> header of shcontact_get_profile): the same contact (1e-9; bit for bit where no origin
   !> moves), and the MiniProf wheel's points are the file's moved by −70 mm.
   subroutine test_arrays(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: whl
      call arrays_round_trip(error, s1002_file, .true.)
      if (allocated(error)) return
      whl = external_file('profiles/Car7216_0001r.whl', error)
      if (allocated(error)) return
      call arrays_round_trip(error, whl, .false.)
   end subroutine test_arrays

   subroutine arrays_round_trip(error, wheel, bitwise)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: wheel
      logical, intent(in) :: bitwise
      type(contact_context_type) :: by_name, by_arrays
      type(profile_type) :: loaded
      type(lib_error), allocatable :: err
      real(wp) :: a(result_value_count), b(result_value_count)
      real(wp) :: wy(4000), wz(4000), ry(4000), rz(4000)
      integer :: nw, nr, stat(4)
      character(len=512) :: msg

      stat(1) = context_create(by_name, wheel, 'builtin:UIC60', 1)
      stat(2) = context_get_profile(by_name, profile_kind_wheel, nw, wy, wz)
      stat(3) = context_get_profile(by_name, profile_kind_rail, nr, ry, rz)
      msg = context_message(by_name)
      call check(error, all(stat(1:3) == 0), message=wheel//': create and get_profile: '// &
         trim(msg))
      if (allocated(error)) return
      stat(4) = context_create_arrays(by_arrays, wy(:nw), wz(:nw), ry(:nr), rz(:nr), 1)
      msg = context_message(by_arrays)
      call check(error, stat(4), 0, message=wheel//': create_arrays: '//trim(msg))
      if (allocated(error)) return
      call load_profile(wheel, profile_kind_wheel, loaded, err)
      if (failed(error, err, wheel)) return
      loaded = tape_circle_origin(loaded)
      call check(error, nw == loaded%size(), message=wheel//': number of points')
      if (allocated(error)) return
      call check(error, all(wy(:nw) == loaded%y) .and. all(wz(:nw) == loaded%z), &
         message=wheel//': get_profile gives the points of the file with the origin of arrays')
      if (allocated(error)) return
      stat(1) = context_solve(by_name, 4.733_wp, 0.0_wp, 1, 64.7e3_wp, 0.58e-3_wp, &
         0.061e-3_wp, 2.74e-4_wp, a)
      stat(2) = context_solve(by_arrays, 4.733_wp, 0.0_wp, 1, 64.7e3_wp, 0.58e-3_wp, &
         0.061e-3_wp, 2.74e-4_wp, b)
      call check(error, all(stat(1:2) == 0), message=wheel//': solve')
      if (allocated(error)) return
      if (bitwise) then
         call check(error, all(a == b), message=wheel//': arrays differ from the file '// &
            '(bit for bit expected)')
      else
         call same_values(error, a, b, 1.0e-9_wp, wheel//' by name and as arrays')
      end if
   end subroutine arrays_round_trip

   ! --- item 5 ---------------------------------------------------------------------------------

   !> k = 2 and 9 points added on every chord of S1002.txt, computed in double and written with
   !> 17 or with 10 significant digits: after the clean-up the points of the samples alone written
   !> with those digits (the same number; all but a few to 1e-12 mm, see nearly_same_points),
   !> and the same contact to 1e-9 at the headline position and in flange contact (t_y = 8 mm,
   !> on the straight flank) (before the fix, F_x
   !> moved from −5846.8 to −5729.9 N and −6938.8 N, M_z from −12 629 to −31 840 N·mm).
   subroutine test_collinear(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: original, samples, dense
      type(lib_error), allocatable :: err
      real(wp) :: a(result_value_count), b(result_value_count)
      integer, parameter :: ks(2) = [2, 9], digits(2) = [17, 10]
      !> Tread contact (headline) and flange contact on the straight flank (section E).
      real(wp), parameter :: t_ys(2) = [4.733_wp, 8.0_wp]
      character(len=:), allocatable :: base
      character(len=8) :: tag
      integer :: i, j, p

      call load_profile(s1002_file, profile=original, error=err)
      if (failed(error, err, s1002_file)) return
      do j = 1, size(digits)
         write (tag, '(a,i0,a,i0)') 'k', 0, 'd', digits(j)
         base = tmp//trim(tag)//'.txt'
         call write_dense(original, 0, digits(j), base)
         call load_profile(base, profile=samples, error=err)
         if (failed(error, err, base)) return
         do i = 1, size(ks)
            write (tag, '(a,i0,a,i0)') 'k', ks(i), 'd', digits(j)
            call write_dense(original, ks(i), digits(j), tmp//trim(tag)//'.txt')
            call load_profile(tmp//trim(tag)//'.txt', profile=dense, error=err)
            if (failed(error, err, trim(tag))) return
            call nearly_same_points(error, samples, dense, 'S1002.txt with points added ('// &
               trim(tag)//')')
            if (allocated(error)) return
            do p = 1, size(t_ys)
               call solve_files(error, profile_kind_wheel, base, a, t_ys(p))
               if (allocated(error)) return
               call solve_files(error, profile_kind_wheel, tmp//trim(tag)//'.txt', b, t_ys(p))
               if (allocated(error)) return
               call same_values(error, a, b, 1.0e-9_wp, 'S1002.txt and with points added ('// &
                  trim(tag)//'), t_y = '//merge('4.733', '8    ', p == 1))
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_collinear

   !> The skeleton on its own: samples of a circle keep every point; a straight line of 1001
   !> points becomes its end points and equally spaced points as far apart as its neighbours;
   !> a second pass changes nothing, bit for bit.
   subroutine test_skeleton(error)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: p, again
      integer, allocatable :: lines(:)
      real(wp) :: t
      integer :: i, n

      ! A circle of R = 300 mm sampled every 0.1 mm (sagitta 4e-6 mm): nothing dropped.
      n = 401
      allocate (p%y(n), p%z(n))
      do i = 1, n
         t = (i - 201)*0.1_wp/300.0_wp
         p%y(i) = 300.0_wp*sin(t)
         p%z(i) = 300.0_wp*(1.0_wp - cos(t))
      end do
      call p%update_arc_length()
      again = p
      call drop_collinear(again, lines)
      call check(error, again%size() == n .and. all(again%y == p%y) .and. all(again%z == p%z), &
         message='circle samples: every point kept')
      if (allocated(error)) return
      ! Circle arcs of 2 mm at both ends of a 30 mm straight line sampled every 0.03 mm.
      deallocate (p%y, p%z)
      allocate (p%y(0), p%z(0))
      do i = -20, -1
         t = i*0.1_wp/300.0_wp
         p%y = [p%y, 300.0_wp*sin(t)]
         p%z = [p%z, 300.0_wp*(1.0_wp - cos(t))]
      end do
      do i = 0, 1000
         p%y = [p%y, 0.03_wp*i]
         p%z = [p%z, 0.0_wp]
      end do
      do i = 1, 20
         t = i*0.1_wp/300.0_wp
         p%y = [p%y, 30.0_wp + 300.0_wp*sin(t)]
         p%z = [p%z, 300.0_wp*(1.0_wp - cos(t))]
      end do
      call p%update_arc_length()
      allocate (lines(p%size()))
      lines = [(i, i=1, p%size())]
      again = p
      call drop_collinear(again, lines)
      ! 30 mm in steps of about 0.1 mm (the neighbours'): 300 pieces.
      call check(error, again%size(), 20 + 301 + 20, message='straight line refilled')
      if (allocated(error)) return
      call check(error, maxval(abs(again%z(21:321))) == 0.0_wp .and. &
         abs(again%y(22) - again%y(21) - 0.1_wp) < 1.0e-12_wp, &
         message='the points filled in lie on the line, 0.1 mm apart')
      if (allocated(error)) return
      call check(error, size(lines) == again%size() .and. lines(21) == 21 .and. &
         lines(321) == 1021, message='file lines kept with their points')
      if (allocated(error)) return
      p = again
      call drop_collinear(again, lines)
      call check(error, again%size() == p%size() .and. all(again%y == p%y) .and. &
         all(again%z == p%z), message='a second pass changes nothing')
      if (allocated(error)) return
      ! A straight profile (a cone on a 1:40 line, 1201 points): its ends and two points
      ! between, equally spaced, the fewest a profile has (two were written by `profiles -o`
      ! and then refused on reading); again the same.
      deallocate (lines)
      p%y = [(0.1_wp*(i - 600), i=0, 1200)]
      p%z = -p%y/40.0_wp
      call p%update_arc_length()
      again = p
      call drop_collinear(again, lines)
      call check(error, again%size(), 4, message='a straight profile keeps four points')
      if (allocated(error)) return
      call check(error, abs(again%y(2) - (p%y(1) + (p%y(1201) - p%y(1))/3)) < 1.0e-12_wp .and. &
         abs(again%z(3) - (p%z(1) + 2*(p%z(1201) - p%z(1))/3)) < 1.0e-12_wp, &
         message='at thirds of the line')
      if (allocated(error)) return
      p = again
      call drop_collinear(again, lines)
      call check(error, again%size() == 4 .and. all(again%y == p%y) .and. all(again%z == p%z), &
         message='a straight profile: a second pass changes nothing')
      if (allocated(error)) return
      ! A V of two straight pieces (3 skeleton points): the longer halved.
      p%y = [(0.1_wp*i, i=0, 300)]
      p%z = merge(p%y, 2*(p%y(101) - p%y) + p%y(101), p%y <= p%y(101))
      call p%update_arc_length()
      again = p
      call drop_collinear(again, lines)
      call check(error, again%size(), 4, message='a V keeps four points')
   end subroutine test_skeleton

   ! --- helpers --------------------------------------------------------------------------------

   !> The profile with k points added on each chord, written with `digits` significant digits.
   subroutine write_dense(profile, k, digits, file)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: k, digits
      character(len=*), intent(in) :: file
      character(len=32) :: fmt
      real(wp) :: f
      integer :: unit, i, j
      write (fmt, '(a,i0,a,i0,a)') '(2es', digits + 9, '.', digits - 1, 'e3)'
      open (newunit=unit, file=file, status='replace', action='write')
      write (unit, '(a)') '# kind = wheel'
      do i = 1, profile%size() - 1
         write (unit, fmt) profile%y(i), profile%z(i)
         do j = 1, k
            f = real(j, wp)/(k + 1)
            write (unit, fmt) profile%y(i) + f*(profile%y(i + 1) - profile%y(i)), &
               profile%z(i) + f*(profile%z(i + 1) - profile%z(i))
         end do
      end do
      write (unit, fmt) profile%y(profile%size()), profile%z(profile%size())
      close (unit)
   end subroutine write_dense

   !> The headline case with the profile file opposite the built-in S1002 or UIC60.
   subroutine solve_files(error, kind, file, values, t_y)
      type(error_type), allocatable, intent(out) :: error
      integer, intent(in) :: kind
      character(len=*), intent(in) :: file
      real(wp), intent(out) :: values(result_value_count)
      !> Lateral shift (mm; default the headline 4.733).
      real(wp), intent(in), optional :: t_y
      real(wp) :: shift
      type(contact_context_type) :: ctx
      character(len=512) :: msg
      integer :: stat
      if (kind == profile_kind_wheel) then
         stat = context_create(ctx, file, 'builtin:UIC60', 1)
      else
         stat = context_create(ctx, 'builtin:S1002', file, 1)
      end if
      shift = 4.733_wp
      if (present(t_y)) shift = t_y
      if (stat == 0) stat = context_solve(ctx, shift, 0.0_wp, 1, 64.7e3_wp, 0.58e-3_wp, &
         0.061e-3_wp, 2.74e-4_wp, values)
      msg = context_message(ctx)
      call check(error, stat, 0, message=file//': '//trim(msg))
   end subroutine solve_files

   subroutine same_values(error, a, b, tol, what)
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in) :: a(:), b(:), tol
      character(len=*), intent(in) :: what
      character(len=64) :: buf
      integer :: i
      do i = 1, size(a)
         if (abs(a(i) - b(i)) <= tol*max(abs(a(i)), abs(b(i)), 1.0e-300_wp)) cycle
         write (buf, '(i0,2(1x,es22.14))') i, a(i), b(i)
         call test_failed(error, what//': value '//trim(buf)//' differs beyond '// &
            'the tolerance (index: doc/api.md)')
         return
      end do
      call check(error, nint(a(i_patches)) == nint(b(i_patches)), message=what//': patches')
   end subroutine same_values

   subroutine same_points(error, a, b, what, tol)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type), intent(in) :: a, b
      character(len=*), intent(in) :: what
      real(wp), intent(in) :: tol
      character(len=64) :: buf
      if (a%size() /= b%size()) then
         write (buf, '(i0,a,i0)') a%size(), ' points expected, ', b%size()
         call test_failed(error, what//': '//trim(buf))
         return
      end if
      write (buf, '(es10.2)') max(maxval(abs(a%y - b%y)), maxval(abs(a%z - b%z)))
      call check(error, maxval(abs(a%y - b%y)) <= tol .and. maxval(abs(a%z - b%z)) <= tol, &
         message=what//': points differ by '//trim(buf)//' mm')
   end subroutine same_points

   !> The same number of points, at most 1 % of them moved (where the curve is straight to
   !> 1e-8 mm over a few samples, near an inflection, the skeleton may keep a point added on a
   !> chord next to a sample instead of the sample: both lie on the curve to that distance), none
   !> by more than 0.1 mm along the profile.
   subroutine nearly_same_points(error, a, b, what)
      type(error_type), allocatable, intent(out) :: error
      type(profile_type), intent(in) :: a, b
      character(len=*), intent(in) :: what
      character(len=80) :: buf
      integer :: moved
      if (a%size() /= b%size()) then
         write (buf, '(i0,a,i0)') a%size(), ' points expected, ', b%size()
         call test_failed(error, what//': '//trim(buf))
         return
      end if
      moved = count(abs(a%y - b%y) > 1.0e-12_wp .or. abs(a%z - b%z) > 1.0e-12_wp)
      write (buf, '(i0,a,es10.2,a)') moved, ' points moved, by up to ', &
         maxval(hypot(a%y - b%y, a%z - b%z)), ' mm'
      call check(error, moved <= a%size()/100 .and. &
         maxval(hypot(a%y - b%y, a%z - b%z)) < 0.1_wp, message=what//': '//trim(buf))
   end subroutine nearly_same_points

   logical function failed(error, err, what)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable, intent(in) :: err
      character(len=*), intent(in) :: what
      failed = allocated(err)
      if (failed) call test_failed(error, what//': '//err%message)
   end function failed

end module test_profile_invariance
