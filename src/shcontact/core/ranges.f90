!> The one table of the numeric inputs' ranges (issue 24 item 8, a step towards issue 26's
!> registry): for every real and integer input that both the app (namelist) and the library
!> (option setter, `set_material`, `set_track`, the option types' checks) accept, its key
!> `group%name` (the case-file name), units, default, and allowed interval. The namelist
!> validation and the library's checks both ask this table, so that a value is accepted by
!> one exactly when it is accepted by the other (test `input`, `ranges_app_equals_library`).
!>
!> The limits are physical or practical, never numerical accidents (doc/app.md, "Ranges"):
!> e.g. μ ≥ 0.001 lies an order of magnitude below the lowest wheel–rail friction measured
!> (leaves, lubricated rail: μ ≈ 0.02–0.05), G ≥ 1000 MPa below any wheel or rail material,
!> N ≥ 1 N far below any wheel load; values below them only produced overflow, NaN forces or
!> minutes of computing.
module shcontact_core_ranges
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_strings, only: str_real
   implicit none
   private

   public :: range_type, ranges, find_range, in_range, range_text, check_range, check_int_range
   public :: max_grid_cells

   !> One numeric input: key, units, default and the allowed interval.
   type :: range_type
      !> `group%name` as in the case file (e.g. 'material%friction').
      character(len=32) :: key = ''
      !> Units ('1' for dimensionless, '' for counts).
      character(len=8) :: units = ''
      !> The default value of the app and of the library.
      real(wp) :: default = 0.0_wp
      !> Lower and upper limit.
      real(wp) :: lo = 0.0_wp, hi = 0.0_wp
      !> True when the limit itself is excluded.
      logical :: lo_open = .false., hi_open = .false.
      !> True for a count (an integer input).
      logical :: whole = .false.
   end type range_type

   !> Most cells of one patch grid, &normal n_strips × &tangential n_elements: every thread
   !> holds a few arrays of this size per patch (doc/app.md, "Limits").
   integer, parameter :: max_grid_cells = 1000000

   !> The table (doc/app.md, "Ranges", lists it).
   type(range_type), parameter :: ranges(*) = [ &
      range_type('profiles%wheel_smoothing', 'mm', 0.0_wp, 0.0_wp, 100.0_wp), &
      range_type('profiles%rail_smoothing', 'mm', 0.0_wp, 0.0_wp, 100.0_wp), &
      range_type('profiles%wheel_scale', '1', 0.0_wp, 0.0_wp, 1.0e6_wp), &
      range_type('profiles%rail_scale', '1', 0.0_wp, 0.0_wp, 1.0e6_wp), &
      range_type('track%gauge', 'mm', 1435.0_wp, 500.0_wp, 2000.0_wp), &
      range_type('track%gauge_height', 'mm', 14.0_wp, 0.0_wp, 50.0_wp), &
      range_type('track%inclination', '1', 0.025_wp, -0.2_wp, 0.2_wp), &
      range_type('track%flange_back_distance', 'mm', 1360.0_wp, 400.0_wp, 2000.0_wp), &
      range_type('track%flange_back_position', 'mm', -70.0_wp, -200.0_wp, 200.0_wp), &
      range_type('track%nominal_radius', 'mm', 460.0_wp, 100.0_wp, 2000.0_wp), &
      range_type('position%t_y', 'mm', 4.733_wp, -30.0_wp, 30.0_wp), &
      range_type('position%roll', 'rad', 0.0_wp, -0.1_wp, 0.1_wp), &
      range_type('kinematics%yaw', 'rad', 0.0_wp, -0.1_wp, 0.1_wp), &
      ! Creepages are velocities divided by the rolling speed: V > 0 (720 km/h at most).
      range_type('kinematics%v_forward', 'mm/s', 30000.0_wp, 0.0_wp, 2.0e5_wp, lo_open=.true.), &
      range_type('kinematics%v_lateral', 'mm/s', 0.0_wp, -1.0e4_wp, 1.0e4_wp), &
      range_type('kinematics%v_vertical', 'mm/s', 0.0_wp, -1.0e4_wp, 1.0e4_wp), &
      range_type('kinematics%roll_rate', 'rad/s', 0.0_wp, -10.0_wp, 10.0_wp), &
      range_type('kinematics%yaw_rate', 'rad/s', 0.0_wp, -10.0_wp, 10.0_wp), &
      ! Rolling forward turns the wheel backwards about the axle: −V/R₀ (default).
      range_type('kinematics%pitch_rate', 'rad/s', -30000.0_wp/460.0_wp, -2000.0_wp, 0.0_wp, &
      hi_open=.true.), &
      range_type('material%shear_modulus', 'MPa', 82670.0_wp, 1.0e3_wp, 1.0e6_wp), &
      range_type('material%poisson', '1', 0.27_wp, 0.0_wp, 0.5_wp, hi_open=.true.), &
      range_type('material%friction', '1', 0.3_wp, 1.0e-3_wp, 10.0_wp), &
      range_type('load%normal_force', 'N', 64700.0_wp, 1.0_wp, 1.0e7_wp), &
      range_type('load%approach', 'mm', 0.05_wp, 0.0_wp, 5.0_wp, lo_open=.true.), &
      range_type('load%vertical_force', 'N', 64700.0_wp, 1.0_wp, 1.0e7_wp), &
      range_type('creepage%nu_x', '1', 5.8e-4_wp, -1.0_wp, 1.0_wp), &
      range_type('creepage%nu_y', '1', 6.1e-5_wp, -1.0_wp, 1.0_wp), &
      range_type('creepage%phi', 'rad/mm', 2.74e-4_wp, -0.1_wp, 0.1_wp), &
      range_type('normal%epsilon', '1', 0.55_wp, 0.01_wp, 1.0_wp), &
      range_type('normal%n_strips', '', 100.0_wp, 2.0_wp, 1.0e5_wp, whole=.true.), &
      range_type('normal%b_min', '1/mm', 1.0e-4_wp, 1.0e-8_wp, 1.0_wp), &
      range_type('tangential%n_elements', '', 50.0_wp, 2.0_wp, 1.0e5_wp, whole=.true.), &
      range_type('output%compression', '', 4.0_wp, 0.0_wp, 9.0_wp, whole=.true.), &
      range_type('output%checkpoint_cases', '', 0.0_wp, 0.0_wp, real(huge(1), wp), &
      whole=.true.)]

contains

   !> Index of `key` (`group%name`, lower case) in [[ranges]], 0 when it has no range.
   pure integer function find_range(key)
      !> The key.
      character(len=*), intent(in) :: key
      integer :: i
      find_range = 0
      do i = 1, size(ranges)
         if (ranges(i)%key == key) then
            find_range = i
            return
         end if
      end do
   end function find_range

   !> True when `x` is finite and inside the range.
   elemental logical function in_range(r, x)
      !> The range.
      type(range_type), intent(in) :: r
      !> The value.
      real(wp), intent(in) :: x
      in_range = ieee_is_finite(x)
      if (.not. in_range) return
      if (r%lo_open) then
         in_range = x > r%lo
      else
         in_range = x >= r%lo
      end if
      if (r%hi_open) then
         in_range = in_range .and. x < r%hi
      else
         in_range = in_range .and. x <= r%hi
      end if
   end function in_range

   !> The range as text, e.g. '0.001 <= friction <= 10', with `name` in the middle.
   pure function range_text(r, name, lo, hi) result(text)
      !> The range.
      type(range_type), intent(in) :: r
      !> The variable's name.
      character(len=*), intent(in) :: name
      !> The limits as text (the caller's number format).
      character(len=*), intent(in) :: lo, hi
      character(len=:), allocatable :: text
      text = lo//merge(' <  ', ' <= ', r%lo_open)
      text = trim(text)//' '//name//merge(' <  ', ' <= ', r%hi_open)
      text = trim(text)//' '//hi
      if (len_trim(r%units) > 0 .and. r%units /= '1') text = text//' '//trim(r%units)
   end function range_text

   !> An error (stat_invalid_input) when the real input `key` is outside its range:
   !> '<label> = <x> is out of range; expected <lo> <= <name> <= <hi> <units>'.
   pure subroutine check_range(key, x, label, error)
      !> The key (must be in the table).
      character(len=*), intent(in) :: key
      !> The value.
      real(wp), intent(in) :: x
      !> What to call it in the message.
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      i = find_range(key)
      if (i == 0) return
      if (in_range(ranges(i), x)) return
      call fatal_error(error, label//' = '//str_real(x)//' is out of range; expected '// &
         range_text(ranges(i), key(index(key, '%') + 1:), str_real(ranges(i)%lo), &
         str_real(ranges(i)%hi)), stat_invalid_input)
   end subroutine check_range

   !> [[check_range]] for an integer input.
   pure subroutine check_int_range(key, n, label, error)
      !> The key (must be in the table).
      character(len=*), intent(in) :: key
      !> The value.
      integer, intent(in) :: n
      !> What to call it in the message.
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      call check_range(key, real(n, wp), label, error)
   end subroutine check_int_range

end module shcontact_core_ranges
