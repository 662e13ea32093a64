!> Tests of the kinematic call through the flat interfaces (issue 12 items 6–7): the legacy entry
!> points SHC_SOLVE_KIN / SHC_PATCH_KIN and the C functions shcontact_solve_kinematic /
!> shcontact_patch_kinematic against the solver object's solve_kinematic, bit for bit; their bad
!> arguments; and the constants of include/shcontact.fi and include/shcontact.h against the
!> library's modules.
module test_api_kinematic
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_ptr, c_loc, &
      c_associated
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_finite
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_io, &
      stat_usage, stat_numerical, stat_no_contact
   use shcontact_geometry_track, only: side_right, side_left
   use shcontact_geometry_kinematics, only: wheelset_state_type, pure_rolling_pitch_rate
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      contact_fields_type, &
      load_normal_force, load_vertical_force, load_approach, load_vertical_position, &
      load_shared_force
   use shcontact_api_values, only: kinematic_value_count, kinematic_values, patch_value_count, &
      result_value_count, value_fx, value_fy, value_mz, value_fn, value_fx_norm, &
      value_fy_norm, value_fy_track, value_fz_track, value_approach, value_area, value_p_max, &
      value_gamma0, value_r0, value_y_track, value_z_track, value_coulomb, value_adhesion, &
      value_n_patches, value_n_loaded, value_main_patch, value_sum_fx, value_sum_fy, &
      value_sum_fz, value_sum_fn, value_dz, value_nu_x, value_nu_y, value_phi, value_x_track
   use shcontact_api_legacy, only: max_handles
   use shcontact_tangential_patch, only: state_exterior, state_adhesion, state_slip
   use shcontact_profile_points, only: profile_kind_rail, profile_kind_wheel
   use shcontact_api_capi, only: shcontact_create, shcontact_destroy, shcontact_last_error, &
      shcontact_solve_kinematic, shcontact_patch_kinematic
   use test_flat_api, only: shc_create, shc_destroy, shc_solve_kin, shc_patch_kin, shc_errmsg, &
      shc_set_option, shc_field_size, shc_fields, to_chars, from_chars, bitwise_equal
   implicit none
   private

   public :: collect_api_kinematic, kinematic_case_state, kinematic_case_load, &
      kinematic_case_result

   !> Forward speed of the test states (mm/s): 40 m/s.
   real(wp), parameter :: speed = 40.0e3_wp
   !> Vertical wheel load (N).
   real(wp), parameter :: kinematic_case_load = 64.7e3_wp
   !> The examples' kinematic case: t_y = 4.733 mm with a yaw angle of 4 mrad, pure rolling.
   type(wheelset_state_type), parameter :: kinematic_case_state = wheelset_state_type( &
      y_ws=4.733_wp, yaw=4.0e-3_wp, v_forward=speed, pitch_rate=-speed/460.0_wp)

contains

   !> Collect all exported unit tests.
   subroutine collect_api_kinematic(testsuite)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('legacy_equals_modern', test_legacy), &
         new_unittest('c_equals_modern', test_c), &
         new_unittest('legacy_fields_equal_modern', test_legacy_fields), &
         new_unittest('legacy_bad_arguments', test_legacy_bad), &
         new_unittest('c_bad_arguments', test_c_bad), &
         new_unittest('include_file_constants', test_include_file), &
         new_unittest('c_header_constants', test_c_header) &
         ]
   end subroutine collect_api_kinematic

   !> The test states: (wheel side, state). Tread (t_y = 0, with lateral and yaw velocities),
   !> t_y = 4.733 mm with 4 mrad yaw, flange (t_y = 8 mm), tread and flange root (t_y = 5 mm,
   !> two patches), and the left wheel.
   subroutine test_states(sides, states)
      integer, allocatable, intent(out) :: sides(:)
      type(wheelset_state_type), allocatable, intent(out) :: states(:)
      real(wp) :: pitch
      pitch = pure_rolling_pitch_rate(speed, 460.0_wp)
      sides = [side_right, side_right, side_right, side_right, side_left, side_left]
      states = [ &
         wheelset_state_type(y_ws=0.0_wp, v_forward=speed, v_lateral=30.0_wp, yaw_rate=0.02_wp, &
         pitch_rate=pitch), &
         kinematic_case_state, &
         wheelset_state_type(y_ws=8.0_wp, yaw=-2.0e-3_wp, v_forward=speed, pitch_rate=pitch), &
         wheelset_state_type(y_ws=5.0_wp, yaw=-2.0e-3_wp, v_forward=speed, pitch_rate=pitch), &
         kinematic_case_state, &
         wheelset_state_type(y_ws=-8.0_wp, yaw=2.0e-3_wp, roll=1.0e-3_wp, v_forward=speed, &
         v_vertical=5.0_wp, roll_rate=0.01_wp, pitch_rate=pitch)]
   end subroutine test_states

   !> The examples' kinematic case through a fresh right-wheel solver object.
   subroutine kinematic_case_result(result, error)
      !> Its result.
      type(contact_result_type), intent(out) :: result
      !> Set when the solver fails.
      type(error_type), allocatable, intent(out) :: error
      call modern_result(side_right, kinematic_case_state, result, error)
   end subroutine kinematic_case_result

   !> A fresh solver object's solve_kinematic with the vertical load.
   subroutine modern_result(side, state, result, error)
      integer, intent(in) :: side
      type(wheelset_state_type), intent(in) :: state
      type(contact_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(lib_error), allocatable :: err
      call solver%init('builtin:S1002', 'builtin:UIC60', err, side=side)
      if (.not. allocated(err)) call solver%solve_kinematic(state, &
         contact_load_type(load_vertical_force, kinematic_case_load), result, err)
      if (allocated(err)) call test_failed(error, 'library error: '//err%message)
   end subroutine modern_result

   !> SHC_SOLVE_KIN and SHC_PATCH_KIN give the solver object's numbers, bit for bit, one handle
   !> per side moving through the states.
   subroutine test_legacy(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type), allocatable :: states(:)
      integer, allocatable :: sides(:)
      type(contact_result_type) :: result
      double precision :: values(29), patch(29)
      real(wp) :: expected(kinematic_value_count)
      integer :: ih(-1:1), istat, i, k, most_patches
      character(len=8) :: label

      call test_states(sides, states)
      call shc_create(ih(1), 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_create(ih(-1), 'builtin:S1002', 'builtin:UIC60', -1, istat)
      call check(error, istat, 0)
      if (allocated(error)) return
      most_patches = 0
      do i = 1, size(states)
         write (label, '(a,i0)') 'state ', i
         call modern_result(sides(i), states(i), result, error)
         if (allocated(error)) exit
         call kinematic_values(result, expected)
         most_patches = max(most_patches, result%n_loaded)
         associate (s => states(i))
            call shc_solve_kin(ih(sides(i)), s%y_ws, s%yaw, s%roll, s%v_forward, s%v_lateral, &
               s%v_vertical, s%roll_rate, s%yaw_rate, s%pitch_rate, 2, kinematic_case_load, &
               values, istat)
         end associate
         call check(error, istat == 0 .and. bitwise_equal(values, expected), &
            message=trim(label)//': SHC_SOLVE_KIN differs from solve_kinematic')
         if (allocated(error)) exit
         call check(error, all(ieee_is_finite(values)) .and. values(value_nu_x) /= 0.0_wp, &
            message=trim(label)//': creepages missing')
         if (allocated(error)) exit
         do k = 1, result%n_patches
            call shc_patch_kin(ih(sides(i)), k, patch, istat)
            call kinematic_values(result, expected, k)
            call check(error, istat == 0 .and. bitwise_equal(patch, expected), &
               message=trim(label)//': SHC_PATCH_KIN differs')
            if (allocated(error)) exit
         end do
         if (allocated(error)) exit
      end do
      if (.not. allocated(error)) call check(error, most_patches >= 2, &
         message='no state with two loaded patches')
      call shc_destroy(ih(1), istat)
      call shc_destroy(ih(-1), istat)
   end subroutine test_legacy

   !> After SHC_SOLVE_KIN with option output%fields = all, SHC_FIELDS gives every loaded patch's
   !> element fields as solve_kinematic's `fields`, bit for bit, and Σ px·area, Σ py·area are
   !> the patch's F_x, F_y; the values equal those of a solve without fields.
   subroutine test_legacy_fields(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type), allocatable :: states(:)
      integer, allocatable :: sides(:)
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(contact_fields_type) :: fields
      type(lib_error), allocatable :: err
      double precision :: values(29), expected(29), patch(29)
      double precision, allocatable :: x(:, :), y(:, :), area(:, :), pn(:, :), px(:, :), &
         py(:, :), slip(:, :)
      integer, allocatable :: state(:, :)
      integer :: ih, istat, i, k, nx, ny

      call test_states(sides, states)
      do i = 1, size(states)
         call modern_result(sides(i), states(i), result, error)
         if (allocated(error)) return
         call kinematic_values(result, expected)
         call solver%init('builtin:S1002', 'builtin:UIC60', err, side=sides(i))
         if (.not. allocated(err)) call solver%solve_kinematic(states(i), &
            contact_load_type(load_vertical_force, kinematic_case_load), result, err, fields)
         if (allocated(err)) then
            call test_failed(error, 'library error: '//err%message)
            return
         end if
         call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', sides(i), istat)
         call shc_set_option(ih, 'output%fields', 'all', istat)
         associate (s => states(i))
            call shc_solve_kin(ih, s%y_ws, s%yaw, s%roll, s%v_forward, s%v_lateral, &
               s%v_vertical, s%roll_rate, s%yaw_rate, s%pitch_rate, 2, kinematic_case_load, &
               values, istat)
         end associate
         call check(error, istat == 0 .and. bitwise_equal(values, expected), &
            message='SHC_SOLVE_KIN with fields differs from solve_kinematic without')
         if (allocated(error)) return
         do k = 1, result%n_loaded
            call shc_field_size(ih, k, nx, ny, istat)
            call check(error, istat == 0 .and. nx == fields%tangential(k)%nx .and. &
               ny == fields%tangential(k)%ny, message='kinematic field size')
            if (allocated(error)) return
            allocate (x(nx, ny), y(nx, ny), area(nx, ny), pn(nx, ny), px(nx, ny), py(nx, ny), &
               slip(nx, ny), state(nx, ny))
            call shc_fields(ih, k, nx, ny, x, y, area, pn, px, py, slip, state, istat)
            call shc_patch_kin(ih, k, patch, istat)
            associate (t => fields%tangential(k))
               call check(error, bitwise_equal(reshape(px, [nx*ny]), reshape(t%px, [nx*ny])) &
                  .and. bitwise_equal(reshape(py, [nx*ny]), reshape(t%py, [nx*ny])) .and. &
                  bitwise_equal(reshape(x, [nx*ny]), reshape(t%x, [nx*ny])) .and. &
                  all(state == int(t%state)), message='kinematic fields differ')
            end associate
            if (allocated(error)) return
            if (nx*ny > 0) then
               call check(error, sum(px*area), patch(value_fx), rel=.true., thr=1.0e-10_wp, &
                  message='kinematic: sum of px*area is not F_x')
               if (allocated(error)) return
               call check(error, sum(py*area), patch(value_fy), rel=.true., thr=1.0e-10_wp, &
                  message='kinematic: sum of py*area is not F_y')
               if (allocated(error)) return
            end if
            deallocate (x, y, area, pn, px, py, slip, state)
         end do
         call shc_destroy(ih, istat)
      end do
   end subroutine test_legacy_fields

   !> shcontact_solve_kinematic and shcontact_patch_kinematic: the same, bit for bit.
   subroutine test_c(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type), allocatable :: states(:)
      integer, allocatable :: sides(:)
      type(contact_result_type) :: result
      character(kind=c_char), target :: wheel(14), rail(14)
      type(c_ptr), target :: handle
      real(c_double) :: values(29), patch(29)
      real(wp) :: expected(kinematic_value_count)
      integer(c_int) :: stat
      integer :: i, k

      call test_states(sides, states)
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      do i = 1, size(states)
         call modern_result(sides(i), states(i), result, error)
         if (allocated(error)) return
         stat = shcontact_create(c_loc(handle), c_loc(wheel), c_loc(rail), int(sides(i), c_int))
         call check(error, stat == 0 .and. c_associated(handle), message='shcontact_create')
         if (allocated(error)) return
         associate (s => states(i))
            stat = shcontact_solve_kinematic(handle, s%y_ws, s%yaw, s%roll, s%v_forward, &
               s%v_lateral, s%v_vertical, s%roll_rate, s%yaw_rate, s%pitch_rate, 2_c_int, &
               kinematic_case_load, values)
         end associate
         call kinematic_values(result, expected)
         call check(error, stat == 0 .and. bitwise_equal(values, expected), &
            message='shcontact_solve_kinematic differs from solve_kinematic')
         do k = 1, result%n_patches
            if (allocated(error)) exit
            stat = shcontact_patch_kinematic(handle, int(k, c_int), patch)
            call kinematic_values(result, expected, k)
            call check(error, stat == 0 .and. bitwise_equal(patch, expected), &
               message='shcontact_patch_kinematic differs')
         end do
         stat = shcontact_destroy(handle)
         if (allocated(error)) return
      end do
   end subroutine test_c

   !> Bad arguments through SHC_SOLVE_KIN: NaN, a speed ≤ 0, a yaw beyond 0.1 rad, a bad
   !> handle, a bad load mode; then SHC_PATCH_KIN without a result and out of range. Each gives
   !> its status and a message naming the problem; the handle stays usable.
   subroutine test_legacy_bad(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type) :: s
      double precision :: values(29), nan
      integer :: ih, istat, k, n_taken
      integer, allocatable :: taken(:)
      character(len=512) :: msg

      allocate (taken(max_handles))
      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      s = kinematic_case_state
      call shc_create(ih, 'builtin:S1002', 'builtin:UIC60', 1, istat)
      call shc_patch_kin(ih, 1, values, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'no result') > 0, &
         message='patch before a solve: '//trim(msg))
      if (allocated(error)) return
      call bad(nan, s%yaw, s%v_forward, 2, stat_invalid_input, 'NaN')
      if (allocated(error)) return
      call bad(s%y_ws, s%yaw, 0.0_wp, 2, stat_invalid_input, 'positive speed')
      if (allocated(error)) return
      call bad(s%y_ws, s%yaw, -s%v_forward, 2, stat_invalid_input, 'positive speed')
      if (allocated(error)) return
      call bad(s%y_ws, 0.2_wp, s%v_forward, 2, stat_invalid_input, 'yaw')
      if (allocated(error)) return
      ! Just past the limit: the message gives the value as it is, not rounded to the limit.
      call bad(s%y_ws, 0.10000001_wp, s%v_forward, 2, stat_invalid_input, 'yaw = 0.10000001')
      if (allocated(error)) return
      ! The case file's velocity ranges hold on this path too (200001 mm/s was solved).
      call bad(s%y_ws, s%yaw, 200001.0_wp, 2, stat_invalid_input, &
         'wheelset forward speed = 200001')
      if (allocated(error)) return
      ! A forward speed far below the wheel's rolling speed (the pitch rate of 30 m/s): a
      ! creepage beyond the prescribed calls' range, refused rather than solved.
      call bad(s%y_ws, s%yaw, 1.0e-9_wp, 2, stat_invalid_input, &
         'longitudinal creepage at the contact point')
      if (allocated(error)) return
      call bad(s%y_ws, s%yaw, s%v_forward, 7, stat_invalid_input, 'load mode')
      if (allocated(error)) return
      ! Still usable; then a patch index beyond the patches found.
      call shc_solve_kin(ih, s%y_ws, s%yaw, s%roll, s%v_forward, 0.0d0, 0.0d0, 0.0d0, 0.0d0, &
         s%pitch_rate, 2, kinematic_case_load, values, istat)
      call check(error, istat, 0, message='solve after the bad calls')
      if (allocated(error)) return
      call shc_patch_kin(ih, nint(values(value_n_patches)) + 1, values, istat)
      call shc_errmsg(ih, msg)
      call check(error, istat == stat_usage .and. index(msg, 'expected 1 to') > 0, &
         message='patch out of range: '//trim(msg))
      if (allocated(error)) return
      ! Invalid handles: 0, beyond the table, destroyed.
      call shc_destroy(ih, istat)
      call bad_handle(0)
      if (allocated(error)) return
      call bad_handle(max_handles + 1)
      if (allocated(error)) return
      call bad_handle(ih)
      if (allocated(error)) return
      ! A full table: shc_create returns handle 0, and the message of handle 0 says why
      ! (failed creations hold their handles too, cheaply: a missing profile).
      n_taken = 0
      do k = 1, max_handles + 1
         call shc_create(ih, 'no-such-wheel.txt', 'builtin:UIC60', 1, istat)
         if (ih == 0) exit
         n_taken = n_taken + 1
         taken(n_taken) = ih
      end do
      call shc_errmsg(0, msg)
      do k = 1, n_taken
         call shc_destroy(taken(k), istat)
      end do
      call check(error, ih == 0 .and. index(msg, 'handles in use') > 0, &
         message='a full handle table: '//trim(msg))
   contains
      subroutine bad(y_ws, yaw, v_forward, mode, stat, word)
         real(wp), intent(in) :: y_ws, yaw, v_forward
         integer, intent(in) :: mode, stat
         character(len=*), intent(in) :: word
         values = 1.0_wp
         call shc_solve_kin(ih, y_ws, yaw, s%roll, v_forward, 0.0d0, 0.0d0, 0.0d0, 0.0d0, &
            s%pitch_rate, mode, kinematic_case_load, values, istat)
         call shc_errmsg(ih, msg)
         call check(error, istat == stat .and. index(msg, word) > 0 .and. &
            all(values == 0.0_wp), message=word//': status and message: '//trim(msg))
      end subroutine bad
      subroutine bad_handle(handle)
         integer, intent(in) :: handle
         call shc_solve_kin(handle, s%y_ws, s%yaw, s%roll, s%v_forward, 0.0d0, 0.0d0, 0.0d0, &
            0.0d0, s%pitch_rate, 2, kinematic_case_load, values, istat)
         call shc_errmsg(handle, msg)
         call check(error, istat == stat_usage .and. index(msg, 'invalid contact handle') > 0, &
            message='invalid handle: '//trim(msg))
         if (allocated(error)) return
         call shc_patch_kin(handle, 1, values, istat)
         call check(error, istat, stat_usage, message='SHC_PATCH_KIN with an invalid handle')
      end subroutine bad_handle
   end subroutine test_legacy_bad

   !> Bad arguments through shcontact_solve_kinematic: the same statuses and messages, and a NULL
   !> handle.
   subroutine test_c_bad(error)
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type) :: s
      character(kind=c_char), target :: wheel(14), rail(14), message(512)
      type(c_ptr), target :: handle
      real(c_double) :: values(29)
      integer(c_int) :: stat
      real(wp) :: nan

      nan = ieee_value(1.0_wp, ieee_quiet_nan)
      s = kinematic_case_state
      wheel = to_chars('builtin:S1002', 14)
      rail = to_chars('builtin:UIC60', 14)
      stat = shcontact_create(c_loc(handle), c_loc(wheel), c_loc(rail), 1_c_int)
      call check(error, stat, 0_c_int)
      if (allocated(error)) return
      call bad(handle, s%y_ws, nan, s%v_forward, 2, stat_invalid_input, 'NaN')
      if (.not. allocated(error)) call bad(handle, s%y_ws, s%yaw, 0.0_wp, 2, &
         stat_invalid_input, 'positive speed')
      if (.not. allocated(error)) call bad(handle, s%y_ws, -0.15_wp, s%v_forward, 2, &
         stat_invalid_input, 'yaw')
      if (.not. allocated(error)) call bad(handle, s%y_ws, s%yaw, s%v_forward, 0, &
         stat_invalid_input, 'load mode')
      if (.not. allocated(error)) call bad(c_null_ptr, s%y_ws, s%yaw, s%v_forward, 2, &
         stat_usage, 'NULL')
      if (.not. allocated(error)) then
         stat = shcontact_patch_kinematic(c_null_ptr, 1_c_int, values)
         call check(error, stat, int(stat_usage, c_int), message='patch with a NULL handle')
      end if
      stat = shcontact_destroy(handle)
   contains
      subroutine bad(h, y_ws, yaw, v_forward, mode, expected, word)
         type(c_ptr), intent(in) :: h
         real(wp), intent(in) :: y_ws, yaw, v_forward
         integer, intent(in) :: mode, expected
         character(len=*), intent(in) :: word
         values = 1.0_wp
         stat = shcontact_solve_kinematic(h, y_ws, yaw, s%roll, v_forward, 0.0_c_double, &
            0.0_c_double, 0.0_c_double, 0.0_c_double, s%pitch_rate, int(mode, c_int), &
            kinematic_case_load, values)
         call check(error, stat, int(expected, c_int), message=word//': status')
         if (allocated(error)) return
         if (c_associated(h)) call check(error, all(values == 0.0_wp), &
            message=word//': values not zeroed')
         if (allocated(error)) return
         stat = shcontact_last_error(h, c_loc(message), size(message, kind=c_int))
         call check(error, stat == expected .and. index(from_chars(message), word) > 0, &
            message=word//': message: '//from_chars(message))
      end subroutine bad
   end subroutine test_c_bad

   !> include/shcontact.fi compiled here: every constant equals the library's.
   subroutine test_include_file(error)
      type(error_type), allocatable, intent(out) :: error
      include '../include/shcontact.fi'
      integer :: i
      integer, parameter :: n = 40
      integer :: got(n), expected(n)

      got = [SHC_OK, SHC_USAGE, SHC_INVALID_INPUT, SHC_IO, SHC_NUMERICAL, SHC_NO_CONTACT, &
         SHC_RIGHT, SHC_LEFT, SHC_LOAD_NORMAL_FORCE, SHC_LOAD_VERTICAL_FORCE, SHC_LOAD_APPROACH, &
         SHC_MAX_HANDLES, SHC_FX, SHC_FY, SHC_MZ, SHC_FN, SHC_FX_NORM, SHC_FY_NORM, &
         SHC_FY_TRACK, SHC_FZ_TRACK, SHC_APPROACH, SHC_AREA, SHC_P_MAX, SHC_GAMMA0, SHC_R0, &
         SHC_Y_TRACK, SHC_Z_TRACK, SHC_COULOMB, SHC_ADHESION, SHC_PATCH_SIZE, SHC_N_PATCHES, &
         SHC_N_LOADED, SHC_MAIN_PATCH, SHC_SUM_FX, SHC_SUM_FY, SHC_SUM_FZ, SHC_SUM_FN, SHC_DZ, &
         SHC_RESULT_SIZE, SHC_KIN_SIZE]
      expected = [0, stat_usage, stat_invalid_input, stat_io, stat_numerical, stat_no_contact, &
         side_right, side_left, load_normal_force, load_vertical_force, load_approach, &
         max_handles, value_fx, value_fy, value_mz, value_fn, value_fx_norm, value_fy_norm, &
         value_fy_track, value_fz_track, value_approach, value_area, value_p_max, value_gamma0, &
         value_r0, value_y_track, value_z_track, value_coulomb, value_adhesion, &
         patch_value_count, value_n_patches, value_n_loaded, value_main_patch, value_sum_fx, &
         value_sum_fy, value_sum_fz, value_sum_fn, value_dz, result_value_count, &
         kinematic_value_count]
      do i = 1, n
         call check(error, got(i), expected(i), message='shcontact.fi constant number '// &
            char(48 + i/10)//char(48 + mod(i, 10))//' differs from the library')
         if (allocated(error)) return
      end do
      call check(error, all([SHC_NU_X, SHC_NU_Y, SHC_PHI, SHC_X_TRACK] == [value_nu_x, &
         value_nu_y, value_phi, value_x_track]), message='shcontact.fi kinematic indices')
      if (allocated(error)) return
      call check(error, SHC_LOAD_VERTICAL_POSITION, load_vertical_position, &
         message='shcontact.fi SHC_LOAD_VERTICAL_POSITION')
      if (allocated(error)) return
      call check(error, SHC_LOAD_SHARED_FORCE, load_shared_force, &
         message='shcontact.fi SHC_LOAD_SHARED_FORCE')
      if (allocated(error)) return
      call check(error, all([SHC_STATE_EXTERIOR, SHC_STATE_ADHESION, SHC_STATE_SLIP] == &
         int([state_exterior, state_adhesion, state_slip])), &
         message='shcontact.fi element states')
      if (allocated(error)) return
      call check(error, all([SHC_PROFILE_RAIL, SHC_PROFILE_WHEEL] == [profile_kind_rail, &
         profile_kind_wheel]), message='shcontact.fi profile kinds')
   end subroutine test_include_file

   !> include/shcontact.h read as text: each #define equals the library's constant (indices
   !> 0-based), and every define is checked.
   subroutine test_c_header(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=24), parameter :: names(49) = [character(len=24) :: 'OK', 'USAGE', &
         'INVALID_INPUT', 'IO', 'NUMERICAL', 'NO_CONTACT', 'RIGHT', 'LEFT', &
         'LOAD_NORMAL_FORCE', 'LOAD_VERTICAL_FORCE', 'LOAD_APPROACH', 'FX', 'FY', 'MZ', 'FN', &
         'FX_NORM', 'FY_NORM', 'FY_TRACK', 'FZ_TRACK', 'APPROACH', 'AREA', 'P_MAX', 'GAMMA0', &
         'R0', 'Y_TRACK', 'Z_TRACK', 'COULOMB', 'ADHESION', 'PATCH_SIZE', 'N_PATCHES', &
         'N_LOADED', 'MAIN_PATCH', 'SUM_FX', 'SUM_FY', 'SUM_FZ', 'SUM_FN', 'DZ', 'RESULT_SIZE', &
         'NU_X', 'NU_Y', 'PHI', 'X_TRACK', 'LOAD_VERTICAL_POSITION', 'STATE_EXTERIOR', &
         'STATE_ADHESION', 'STATE_SLIP', 'PROFILE_RAIL', 'PROFILE_WHEEL', 'LOAD_SHARED_FORCE']
      integer :: expected(50), found(50), unit, stat, i, value, n_defines
      character(len=256) :: line
      character(len=64) :: word, name

      expected = [0, stat_usage, stat_invalid_input, stat_io, stat_numerical, stat_no_contact, &
         side_right, side_left, load_normal_force, load_vertical_force, load_approach, &
         value_fx - 1, value_fy - 1, value_mz - 1, value_fn - 1, value_fx_norm - 1, &
         value_fy_norm - 1, value_fy_track - 1, value_fz_track - 1, value_approach - 1, &
         value_area - 1, value_p_max - 1, value_gamma0 - 1, value_r0 - 1, value_y_track - 1, &
         value_z_track - 1, value_coulomb - 1, value_adhesion - 1, patch_value_count, &
         value_n_patches - 1, value_n_loaded - 1, value_main_patch - 1, value_sum_fx - 1, &
         value_sum_fy - 1, value_sum_fz - 1, value_sum_fn - 1, value_dz - 1, &
         result_value_count, value_nu_x - 1, value_nu_y - 1, value_phi - 1, value_x_track - 1, &
         load_vertical_position, int(state_exterior), int(state_adhesion), int(state_slip), &
         profile_kind_rail, profile_kind_wheel, load_shared_force, kinematic_value_count]
      found = huge(1)
      n_defines = 0
      open (newunit=unit, file='include/shcontact.h', status='old', action='read', iostat=stat)
      call check(error, stat, 0, message='include/shcontact.h not found (run from the root)')
      if (allocated(error)) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, '#define SHCONTACT_') /= 1) cycle
         ! "#define SHCONTACT_NAME value": the value may be parenthesised, (-1).
         read (line(9:), *, iostat=stat) name
         i = index(line(9:), ' ') + 8
         word = adjustl(line(i:))
         word = word(1:index(word, ' '))
         call strip_parentheses(word)
         read (word, *, iostat=stat) value
         if (stat /= 0) cycle
         n_defines = n_defines + 1
         name = name(len('SHCONTACT_') + 1:)
         if (trim(name) == 'KIN_SIZE') then
            found(size(found)) = value
            cycle
         end if
         do i = 1, size(names)
            if (trim(name) == trim(names(i))) found(i) = value
         end do
      end do
      close (unit)
      do i = 1, size(expected)
         call check(error, found(i), expected(i), message='shcontact.h: SHCONTACT_'// &
            trim(merge(names(min(i, size(names))), 'KIN_SIZE                ', i <= size(names))))
         if (allocated(error)) return
      end do
      call check(error, n_defines, size(expected), message='shcontact.h defines a constant '// &
         'this test does not check')
   end subroutine test_c_header

   !> "(-1)" → "-1".
   pure subroutine strip_parentheses(word)
      character(len=*), intent(inout) :: word
      integer :: i
      do i = 1, len(word)
         if (word(i:i) == '(' .or. word(i:i) == ')') word(i:i) = ' '
      end do
      word = adjustl(word)
   end subroutine strip_parentheses

end module test_api_kinematic
