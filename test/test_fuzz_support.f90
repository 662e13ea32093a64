!> Helpers of the fuzz tests (test_robustness, test_input): a reproducible random sequence,
!> the campaign settings, mutations that repeat an assignment, and the fuzz of the library's
!> option setter against the one range table (shcontact_core_ranges).
module test_fuzz_support
   use testdrive, only: error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   use shcontact_core_text, only: format_real
   use shcontact_core_error, only: shc_error_type => error_type
   use shcontact_core_ranges, only: ranges, find_range, range_key, k_int, in_range, max_grid_cells
   use shcontact_core_material, only: material_type
   use shcontact_geometry_track, only: track_type, check_track
   use shcontact_api_context, only: contact_context_type, context_create, context_set_option, &
      context_set_material, context_message
   implicit none
   private
   public :: next_random, fuzz_settings, repeated, names_input_file, library_option_fuzz
   public :: library_status, reset_library, samples, new_library

contains

   !> Next value of a 31-bit linear congruential generator (reproducible on every compiler).
   integer function next_random(seed, n) result(k)
      integer, intent(inout) :: seed
      !> The value is in 1..n.
      integer, intent(in) :: n
      seed = int(mod(1103515245_8*int(seed, 8) + 12345_8, 2147483648_8))
      k = 1 + int(mod(int(seed, 8)/65536_8, int(n, 8)))
   end function next_random

   !> The fuzz test's bounds: SHCONTACT_FUZZ_SECONDS (a campaign without a run limit) and
   !> SHCONTACT_FUZZ_SEED, else the suite's few seconds.
   subroutine fuzz_settings(default_seconds, default_runs, seconds, runs, seed, campaign)
      !> The suite's bounds: seconds and runs.
      real, intent(in) :: default_seconds
      integer, intent(in) :: default_runs
      real, intent(out) :: seconds
      integer, intent(out) :: runs, seed
      logical, intent(out) :: campaign
      character(len=32) :: buf
      integer :: length, stat
      seconds = default_seconds
      runs = default_runs
      seed = 20260514
      call get_environment_variable('SHCONTACT_FUZZ_SECONDS', buf, length, stat)
      campaign = stat == 0 .and. length > 0
      if (campaign) then
         read (buf, *, iostat=stat) seconds
         if (stat /= 0) seconds = default_seconds
         runs = huge(1)
      end if
      call get_environment_variable('SHCONTACT_FUZZ_SEED', buf, length, stat)
      if (stat == 0 .and. length > 0) then
         read (buf, *, iostat=stat) seed
         if (stat /= 0) seed = 20260514
      end if
   end subroutine fuzz_settings

   !> The text with `assignment` ('&group|name = value') added again after the group's
   !> name, when the text has that group.
   function repeated(text, assignment) result(m)
      character(len=*), intent(in) :: text, assignment
      character(len=:), allocatable :: m, group
      integer :: bar, at
      m = text
      bar = index(assignment, '|')
      group = assignment(1:bar - 1)
      at = index(m, group//' ')
      if (at == 0) return
      at = at + len(group)
      m = m(:at)//trim(assignment(bar + 1:))//', '//m(at + 1:)
   end function repeated

   !> True when the message starts with a file name (`error: NAME:`) that the input holds.
   pure logical function names_input_file(err, input) result(yes)
      character(len=*), intent(in) :: err, input
      integer :: start, colon
      yes = .false.
      start = index(err, 'error: ')
      if (start == 0) return
      start = start + 7
      colon = index(err(start:), ':')
      if (colon < 2) return
      yes = index(input, err(start:start + colon - 2)) > 0
      ! A case file's tabs count as blanks, inside quoted names too (doc/app.md, Case files).
      if (.not. yes) yes = index(tabs_as_blanks(input), err(start:start + colon - 2)) > 0
   end function names_input_file

   pure function tabs_as_blanks(text) result(blanked)
      character(len=*), intent(in) :: text
      character(len=len(text)) :: blanked
      integer :: k
      blanked = text
      do k = 1, len(text)
         if (text(k:k) == achar(9)) blanked(k:k) = ' '
      end do
   end function tabs_as_blanks

   !> 0 when the library accepts the value for `key` (option setter, set_material, or the
   !> track check), else its status; -1 when the library has no such input.
   integer function library_status(ctx, key, x, message) result(stat)
      type(contact_context_type), intent(inout) :: ctx
      character(len=*), intent(in) :: key
      real(wp), intent(in) :: x
      character(len=:), allocatable, intent(out) :: message
      type(material_type) :: m
      type(track_type) :: t
      type(shc_error_type), allocatable :: err
      message = ''
      select case (key)
      case ('normal%epsilon', 'normal%b_min', 'profiles%wheel_smoothing', &
            'profiles%rail_smoothing')
         stat = context_set_option(ctx, key, format_real(x))
         message = context_message(ctx)
      case ('normal%n_strips', 'tangential%n_elements')
         stat = context_set_option(ctx, key, str_int(nint(x)))
         message = context_message(ctx)
      case ('material%shear_modulus', 'material%poisson', 'material%friction')
         select case (key)
         case ('material%shear_modulus'); m%shear_modulus = x
         case ('material%poisson'); m%poisson = x
         case default; m%friction = x
         end select
         stat = context_set_material(ctx, m%shear_modulus, m%poisson, m%friction)
         message = context_message(ctx)
      case ('track%gauge', 'track%gauge_height', 'track%inclination', &
            'track%flange_back_distance', 'track%flange_back_position', 'track%nominal_radius')
         select case (key)
         case ('track%gauge'); t%gauge = x
         case ('track%gauge_height'); t%gauge_height = x
         case ('track%inclination'); t%rail_inclination = x
         case ('track%flange_back_distance'); t%flange_back_distance = x
         case ('track%flange_back_position'); t%flange_back_position = x
         case default; t%nominal_radius = x
         end select
         call check_track(t, err)
         stat = 0
         if (allocated(err)) then
            stat = err%stat
            message = err%message
         end if
      case default
         stat = -1
      end select
   end function library_status

   !> Put the library options back to their defaults after a sample was accepted.
   subroutine reset_library(ctx)
      type(contact_context_type), intent(inout) :: ctx
      type(material_type) :: m
      integer :: stat
      stat = context_set_option(ctx, 'normal%epsilon', '0.55')
      stat = context_set_option(ctx, 'normal%n_strips', '100')
      stat = context_set_option(ctx, 'normal%b_min', '1e-4')
      stat = context_set_option(ctx, 'tangential%n_elements', '50')
      stat = context_set_option(ctx, 'profiles%wheel_smoothing', '0')
      stat = context_set_option(ctx, 'profiles%rail_smoothing', '0')
      stat = context_set_material(ctx, m%shear_modulus, m%poisson, m%friction)
   end subroutine reset_library

   !> Values to try for range ir: just below, at and just above each limit, the middle, tiny
   !> and huge numbers of both signs.
   pure function samples(ir) result(x)
      integer, intent(in) :: ir
      real(wp), allocatable :: x(:)
      real(wp) :: lo, hi, d
      lo = ranges(ir)%lo
      hi = ranges(ir)%hi
      if (ranges(ir)%kind == k_int) then
         x = [lo - 1, lo, lo + 1, anint(0.5_wp*(lo + hi)), hi - 1, hi, hi + 1, 0.0_wp, 1.0_wp, &
            -1.0_wp, 1.0e6_wp, 1.0e9_wp]
      else
         d = 1.0e-9_wp*max(abs(lo), abs(hi), 1.0_wp)
         x = [lo - d, lo, lo + d, 0.5_wp*(lo + hi), hi - d, hi, hi + d, 0.0_wp, 1.0e-300_wp, &
            -1.0e-300_wp, 4.9e-324_wp, 1.0e308_wp, -1.0e308_wp, 1.0e9_wp]
      end if
   end function samples

   !> A library context on the built-in profiles.
   subroutine new_library(error, ctx)
      type(error_type), allocatable, intent(out) :: error
      type(contact_context_type), intent(out) :: ctx
      integer :: stat
      stat = context_create(ctx, 'builtin:S1002', 'builtin:UIC60', 1)
      call check(error, stat, 0, message='context_create: '//context_message(ctx))
   end subroutine new_library

   !> Random keys (known, mangled, unknown) and values (in and out of range, tiny, huge, NaN,
   !> text, empty, very long, control bytes) through the option setter, set_material and
   !> set_track: the status is 0 exactly when the value is in the table's range (or a known
   !> choice), otherwise a documented code with a message; a refused call changes nothing (the
   !> next in-range call and a coarse solve still succeed).
   subroutine library_option_fuzz(error, seed0, seconds, calls)
      type(error_type), allocatable, intent(out) :: error
      !> Seed of the sequence.
      integer, intent(in) :: seed0
      !> Wall-clock bound (s).
      real, intent(in) :: seconds
      !> Calls made.
      integer, intent(out) :: calls
      character(len=*), parameter :: lib_keys(6) = [character(len=24) :: 'normal%epsilon', &
         'normal%n_strips', 'normal%b_min', 'tangential%n_elements', &
         'profiles%wheel_smoothing', 'profiles%rail_smoothing']
      character(len=*), parameter :: junk(10) = [character(len=16) :: 'nan', 'inf', '-inf', &
         '', '1e309', '0x10', '1,2', '.true.', '1d-320', '5 5']
      type(contact_context_type) :: ctx
      character(len=:), allocatable :: key, text, message
      real(wp) :: x
      real(wp), allocatable :: s(:)
      integer :: seed, stat, ir, kind, mangle
      integer(kind=8) :: t0, t1, rate
      logical :: expect_ok
      call new_library(error, ctx)
      if (allocated(error)) return
      seed = seed0
      calls = 0
      call system_clock(t0, rate)
      do
         call system_clock(t1)
         if (real(t1 - t0)/real(rate) > seconds) exit
         calls = calls + 1
         kind = next_random(seed, 4)
         if (kind <= 2) then
            key = trim(lib_keys(next_random(seed, size(lib_keys))))
            ir = find_range(key)
            s = samples(ir)
            x = s(next_random(seed, size(s)))
            if (next_random(seed, 3) == 1) x = ranges(ir)%lo + (ranges(ir)%hi - ranges(ir)%lo)* &
               real(next_random(seed, 1000), wp)/1000.0_wp
            if (ranges(ir)%kind == k_int) then
               if (abs(x) > 1.0e9_wp) x = 1.0e9_wp
               x = anint(x)
               text = str_int(nint(x))
            else
               text = format_real(x)
            end if
            expect_ok = in_range(ranges(ir), x)
            if (key == 'normal%n_strips') expect_ok = expect_ok .and. &
               x*50.0_wp <= real(max_grid_cells, wp)
            if (key == 'tangential%n_elements') expect_ok = expect_ok .and. &
               x*100.0_wp <= real(max_grid_cells, wp)
            mangle = next_random(seed, 8)
            if (mangle == 1) then
               text = trim(junk(next_random(seed, size(junk))))
               expect_ok = .false.
               if (text == '1d-320') expect_ok = in_range(ranges(ir), 1.0e-320_wp)
            else if (mangle == 2) then
               text = text//achar(next_random(seed, 31))
               expect_ok = .false.
            else if (mangle == 3) then
               key = to_upper_first(key)
            end if
            stat = context_set_option(ctx, key, text)
            message = context_message(ctx)
            if (text == '1d-320' .and. ranges(ir)%kind == k_int) expect_ok = stat == 0
            if (index(text, ',') > 0 .or. index(text, ' ') > 0) expect_ok = stat == 0
            if (expect_ok .neqv. (stat == 0)) then
               call test_failed(error, 'set_option('//key//', '//text//'): status '// &
                  str_int(stat)//', expected '//trim(merge('accepted', 'refused ', &
                  expect_ok))//'; '//message)
               return
            end if
            if (stat /= 0 .and. (stat /= 2 .or. len(message) == 0)) then
               call test_failed(error, 'set_option('//key//', '//text//'): status '// &
                  str_int(stat)//' without the invalid-input code and a message')
               return
            end if
            if (stat == 0) call reset_library(ctx)
         else if (kind == 3) then
            ir = find_range(trim(merge('material%friction     ', 'material%shear_modulus', &
               next_random(seed, 2) == 1)))
            s = samples(ir)
            x = s(next_random(seed, size(s)))
            stat = library_status(ctx, trim(range_key(ranges(ir))), x, message)
            if (in_range(ranges(ir), x) .neqv. (stat == 0)) then
               call test_failed(error, trim(range_key(ranges(ir)))//' = '//format_real(x)// &
                  ': library status '//str_int(stat)//'; '//message)
               return
            end if
            if (stat == 0) call reset_library(ctx)
         else
            ! Unknown keys are refused with the list of keys.
            stat = context_set_option(ctx, 'normal%'//achar(96 + next_random(seed, 26))//'x', '1')
            if (stat /= 2) then
               call test_failed(error, 'unknown key accepted')
               return
            end if
         end if
      end do
      ! Nothing refused has stuck: the defaults solve (a coarse grid).
      stat = context_set_option(ctx, 'normal%n_strips', '30')
      if (stat == 0) stat = context_set_option(ctx, 'tangential%n_elements', '10')
      call check(error, stat, 0, message='after the fuzz: '//context_message(ctx))
   contains
      pure function to_upper_first(k) result(u)
         character(len=*), intent(in) :: k
         character(len=:), allocatable :: u
         u = k
         u(1:1) = achar(iachar(u(1:1)) - 32)
      end function to_upper_first
   end subroutine library_option_fuzz

end module test_fuzz_support
