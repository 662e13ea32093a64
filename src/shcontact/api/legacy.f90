!> Legacy Fortran entry points: external subroutines `shc_*` with default `integer` and
!> `double precision` explicit-shape arguments and an integer status, callable from fixed-form
!> Fortran 77 without modules. Contacts are referred to by integer handles, as CONTACT's `cntc_*`
!> library does (doc/api.md lists the calls and the layout of the result arrays).
!>
!> This module holds the handle table: [[max_handles]] slots, each an allocatable
!> [[contact_context_type]] (so an unused slot costs a few bytes). Handles are 1 to max_handles;
!> 0 is never valid. Creating and destroying a handle is serialised by a named OpenMP critical
!> section; every other call touches only its own slot, so distinct handles may be used from
!> distinct threads at once. One handle must not be used by two threads at the same time.
!>
!> Status codes: 0 success, 1 usage (bad handle, bad argument), 2 invalid input, 3 I/O,
!> 5 numerical, 6 no contact (shcontact_core_error).
module shcontact_api_legacy
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: stat_usage
   use shcontact_core_strings, only: str_int
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_api_values, only: patch_value_count, result_value_count, kinematic_value_count
   use shcontact_api_context, only: contact_context_type, context_create, context_set_material, &
      context_set_track, context_solve, context_solve_kinematic, &
      context_message, context_create_arrays, context_fail
   use shcontact_api_context_results, only: context_patch, context_patch_kinematic, &
      context_field_size, context_fields, context_get_profile
   use shcontact_api_context, only: context_create_wheelset, context_solve_wheelset
   use shcontact_api_keyed, only: context_set_option_by_key, context_set_value, &
      context_solve_state, context_get_value, &
      context_get_field, context_wheel
   implicit none
   private

   public :: legacy_set_value, legacy_solve_state, legacy_get_value, legacy_get_field, &
      legacy_create_wheelset, legacy_solve_wheelset, legacy_wheelset_wheel
   public :: max_handles
   public :: legacy_create, legacy_create_arrays, legacy_field_size, legacy_fields, &
      legacy_get_profile
   public :: legacy_destroy, legacy_set_material, legacy_set_track, &
      legacy_set_option, legacy_solve, legacy_solve_kinematic, legacy_patch, &
      legacy_patch_kinematic, legacy_message

   !> Capacity of the handle table.
   integer, parameter :: max_handles = 1024

   !> One slot of the table.
   type :: slot_type
      !> The contact; allocated while the handle is in use.
      type(contact_context_type), allocatable :: ctx
   end type slot_type

   !> The handle table (the only global state of the library, and only of this layer).
   type(slot_type), save, target :: slots(max_handles)

contains

   !> Reserve a handle and create its contact from profile names. A handle is returned (> 0)
   !> even when the creation fails, so that shc_errmsg can tell why; destroy it. ihandle = 0
   !> means that all handles are in use.
   subroutine legacy_create(ihandle, wheel, rail, iside, istat)
      !> The new handle (0 when the table is full).
      integer, intent(out) :: ihandle
      !> Wheel and rail profile: `builtin:NAME` or a file name.
      character(len=*), intent(in) :: wheel, rail
      !> 1 right wheel, −1 left wheel.
      integer, intent(in) :: iside
      !> Status (0 success).
      integer, intent(out) :: istat

      call reserve(ihandle)
      if (ihandle == 0) then
         istat = stat_usage
         return
      end if
      istat = context_create(slots(ihandle)%ctx, wheel, rail, iside)
   end subroutine legacy_create

   !> Reserve a handle and create its contact from profiles given as arrays of points (mm,
   !> right-side canonical form; see context_create_arrays). Handles as [[legacy_create]].
   subroutine legacy_create_arrays(ihandle, nw, yw, zw, nr, yr, zr, iside, istat)
      !> The new handle (0 when the table is full).
      integer, intent(out) :: ihandle
      !> Number of wheel points, their y and z (from the field side to the flange back).
      integer, intent(in) :: nw
      real(wp), intent(in) :: yw(*), zw(*)
      !> Number of rail points, their y and z (from the track centre to the field side).
      integer, intent(in) :: nr
      real(wp), intent(in) :: yr(*), zr(*)
      !> 1 right wheel, −1 left wheel.
      integer, intent(in) :: iside
      !> Status (0 success).
      integer, intent(out) :: istat

      call reserve(ihandle)
      if (ihandle == 0) then
         istat = stat_usage
      else if (nw < 0 .or. nr < 0) then
         istat = context_fail(slots(ihandle)%ctx, 'shc_create_arrays: negative number of '// &
            'points (nw = '//str_int(nw)//', nr = '//str_int(nr)//')', stat_usage)
      else
         istat = context_create_arrays(slots(ihandle)%ctx, yw(1:nw), zw(1:nw), yr(1:nr), &
            zr(1:nr), iside)
      end if
   end subroutine legacy_create_arrays

   !> The first free handle, its slot allocated (0 when the table is full).
   subroutine reserve(ihandle)
      integer, intent(out) :: ihandle
      integer :: i
      ihandle = 0
      !$omp critical (shcontact_legacy_handles)
      do i = 1, max_handles
         if (.not. allocated(slots(i)%ctx)) then
            allocate (slots(i)%ctx)
            ihandle = i
            exit
         end if
      end do
      !$omp end critical (shcontact_legacy_handles)
   end subroutine reserve

   !> Release a handle (status 1 for an invalid one).
   subroutine legacy_destroy(ihandle, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (.not. valid(ihandle)) return
      !$omp critical (shcontact_legacy_handles)
      deallocate (slots(ihandle)%ctx)
      !$omp end critical (shcontact_legacy_handles)
      istat = 0
   end subroutine legacy_destroy

   !> Set G (MPa), ν and μ.
   subroutine legacy_set_material(ihandle, g, poiss, fric, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> G (MPa), ν, μ.
      real(wp), intent(in) :: g, poiss, fric
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_set_material(slots(ihandle)%ctx, g, poiss, fric)
   end subroutine legacy_set_material

   !> Set the track: gauge, gauge-point depth, rail inclination (slope), rail already canted
   !> (icant /= 0), flange-back distance and position, nominal radius (mm).
   subroutine legacy_set_track(ihandle, gauge, gheight, slope, icant, fbdist, fbpos, rnom, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Gauge, gauge-point depth (mm), rail inclination (slope).
      real(wp), intent(in) :: gauge, gheight, slope
      !> Non-zero: the rail profile is already canted.
      integer, intent(in) :: icant
      !> Flange-back distance and position, nominal radius (mm).
      real(wp), intent(in) :: fbdist, fbpos, rnom
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_set_track(slots(ihandle)%ctx, gauge, gheight, slope, &
         icant /= 0, fbdist, fbpos, rnom)
   end subroutine legacy_set_track

   !> Set one option by name and textual value (shcontact_api_context's option_keys).
   subroutine legacy_set_option(ihandle, key, value, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Option name (`group%variable`) and value.
      character(len=*), intent(in) :: key, value
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_set_option_by_key(slots(ihandle)%ctx, key, value)
   end subroutine legacy_set_option

   !> Solve one contact; values(1:result_value_count) receives the flat result.
   subroutine legacy_solve(ihandle, ty, roll, imode, fload, cksi, ceta, cphi, values, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Lateral shift (mm) and roll (rad).
      real(wp), intent(in) :: ty, roll
      !> Load mode: 1 normal force, 2 vertical force, 3 approach.
      integer, intent(in) :: imode
      !> Load (N or mm) and creepages ν_x, ν_y, φ (rad/mm).
      real(wp), intent(in) :: fload, cksi, ceta, cphi
      !> The flat result.
      real(wp), intent(out) :: values(result_value_count)
      !> Status (0 success).
      integer, intent(out) :: istat
      values = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_solve(slots(ihandle)%ctx, ty, roll, imode, fload, &
         cksi, ceta, cphi, values)
   end subroutine legacy_solve

   !> Solve one wheel from the wheelset's position and velocities (CONTACT module 1 meaning);
   !> values(1:kinematic_value_count) receives the kinematic layout.
   subroutine legacy_solve_kinematic(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, &
         imode, fload, values, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Lateral shift (mm), yaw and roll (rad) of the wheelset.
      real(wp), intent(in) :: yws, yaw, roll
      !> Forward (> 0), lateral and vertical velocity of the wheelset centre (mm/s).
      real(wp), intent(in) :: vs, vy, vz
      !> Roll, yaw and pitch rate (rad/s; vpitch < 0 rolling forward).
      real(wp), intent(in) :: vroll, vyaw, vpitch
      !> Load mode: 1 normal force, 2 vertical force, 3 approach.
      integer, intent(in) :: imode
      !> Load (N or mm).
      real(wp), intent(in) :: fload
      !> The flat result.
      real(wp), intent(out) :: values(kinematic_value_count)
      !> Status (0 success).
      integer, intent(out) :: istat
      values = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_solve_kinematic(slots(ihandle)%ctx, &
         wheelset_state_type(y_ws=yws, yaw=yaw, roll=roll, v_forward=vs, v_lateral=vy, &
         v_vertical=vz, roll_rate=vroll, yaw_rate=vyaw, pitch_rate=vpitch), imode, fload, values)
   end subroutine legacy_solve_kinematic

   !> Patch ipatch of the last solve in the kinematic layout.
   subroutine legacy_patch_kinematic(ihandle, ipatch, values, istat)
      !> The handle and the patch index.
      integer, intent(in) :: ihandle, ipatch
      !> The values.
      real(wp), intent(out) :: values(kinematic_value_count)
      !> Status (0 success).
      integer, intent(out) :: istat
      values = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_patch_kinematic(slots(ihandle)%ctx, ipatch, values)
   end subroutine legacy_patch_kinematic

   !> The flat values of patch ipatch of the last solve.
   subroutine legacy_patch(ihandle, ipatch, values, istat)
      !> The handle and the patch index.
      integer, intent(in) :: ihandle, ipatch
      !> The patch values.
      real(wp), intent(out) :: values(patch_value_count)
      !> Status (0 success).
      integer, intent(out) :: istat
      values = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_patch(slots(ihandle)%ctx, ipatch, values)
   end subroutine legacy_patch

   !> The size of patch ipatch's element fields after the last solve (nx elements per strip,
   !> ny strips; 0 × 0 for a patch without load). Needs option output%fields = 'all'.
   subroutine legacy_field_size(ihandle, ipatch, nx, ny, istat)
      !> The handle and the patch index.
      integer, intent(in) :: ihandle, ipatch
      !> The sizes (0 on failure).
      integer, intent(out) :: nx, ny
      !> Status (0 success).
      integer, intent(out) :: istat
      nx = 0
      ny = 0
      istat = stat_usage
      if (valid(ihandle)) istat = context_field_size(slots(ihandle)%ctx, ipatch, nx, ny)
   end subroutine legacy_field_size

   !> Patch ipatch's element fields after the last solve, arrays (nx, ny) (context_fields).
   subroutine legacy_fields(ihandle, ipatch, nx, ny, x, y, area, pn, px, py, slip, state, istat)
      !> The handle and the patch index.
      integer, intent(in) :: ihandle, ipatch
      !> The sizes, as legacy_field_size gives them.
      integer, intent(in) :: nx, ny
      !> Element centres (mm), areas (mm²), pressure and tractions (MPa), slip magnitude; not
      !> written on failure (arrays of a wrong size may be smaller than nx·ny).
      real(wp), intent(inout) :: x(nx, ny), y(nx, ny), area(nx, ny), pn(nx, ny), px(nx, ny), &
         py(nx, ny), slip(nx, ny)
      !> Element state: 0 exterior, 1 adhesion, 2 slip.
      integer, intent(inout) :: state(nx, ny)
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_fields(slots(ihandle)%ctx, ipatch, nx, ny, x, y, &
         area, pn, px, py, slip, state)
   end subroutine legacy_fields

   !> The points of the handle's wheel (ikind = 1) or rail (ikind = 0) profile as created;
   !> n receives their number also when it exceeds nmax (status 1, nothing copied).
   subroutine legacy_get_profile(ihandle, ikind, nmax, n, y, z, istat)
      !> The handle, the profile kind, the capacity of y and z.
      integer, intent(in) :: ihandle, ikind, nmax
      !> The number of points.
      integer, intent(out) :: n
      !> The points (mm).
      real(wp), intent(out) :: y(*), z(*)
      !> Status (0 success).
      integer, intent(out) :: istat
      n = 0
      istat = stat_usage
      if (valid(ihandle)) istat = context_get_profile(slots(ihandle)%ctx, ikind, n, &
         y(1:max(nmax, 0)), z(1:max(nmax, 0)))
   end subroutine legacy_get_profile

   !> Set a number by key (context_set_value: `group%variable` or a variable of one group).
   subroutine legacy_set_value(ihandle, key, x, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> The key.
      character(len=*), intent(in) :: key
      !> The value, in the key's units.
      real(wp), intent(in) :: x
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_set_value(slots(ihandle)%ctx, key, x)
   end subroutine legacy_set_value

   !> Solve the state set by key (context_solve_state).
   subroutine legacy_solve_state(ihandle, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_solve_state(slots(ihandle)%ctx)
   end subroutine legacy_solve_state

   !> A result value by name, of the main patch (ipatch = 0) or of patch ipatch
   !> (context_get_value).
   subroutine legacy_get_value(ihandle, key, ipatch, x, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> The name.
      character(len=*), intent(in) :: key
      !> 0 or the patch index.
      integer, intent(in) :: ipatch
      !> The value (0 on failure).
      real(wp), intent(out) :: x
      !> Status (0 success).
      integer, intent(out) :: istat
      x = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_get_value(slots(ihandle)%ctx, key, ipatch, x)
   end subroutine legacy_get_value

   !> One element field by name, array (nx, ny) (context_get_field).
   subroutine legacy_get_field(ihandle, key, ipatch, nx, ny, a, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> The field name.
      character(len=*), intent(in) :: key
      !> The patch index and the field sizes.
      integer, intent(in) :: ipatch, nx, ny
      !> The field (not written on failure).
      real(wp), intent(inout) :: a(nx, ny)
      !> Status (0 success).
      integer, intent(out) :: istat
      istat = stat_usage
      if (valid(ihandle)) istat = context_get_field(slots(ihandle)%ctx, key, ipatch, nx, ny, a)
   end subroutine legacy_get_field

   !> Reserve a handle and create a wheelset (both wheels) from profile names; handles as
   !> [[legacy_create]].
   subroutine legacy_create_wheelset(ihandle, wheel, rail, istat)
      !> The new handle (0 when the table is full).
      integer, intent(out) :: ihandle
      !> Wheel and rail profile: `builtin:NAME` or a file name.
      character(len=*), intent(in) :: wheel, rail
      !> Status (0 success).
      integer, intent(out) :: istat
      call reserve(ihandle)
      if (ihandle == 0) then
         istat = stat_usage
         return
      end if
      istat = context_create_wheelset(slots(ihandle)%ctx, wheel, rail)
   end subroutine legacy_create_wheelset

   !> Solve both wheels of a wheelset handle; totals(4) receives F_x, F_y, F_z (N) and M_z
   !> (N·mm) on the wheelset (context_solve_wheelset).
   subroutine legacy_solve_wheelset(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, &
         imode, fright, fleft, totals, istat)
      !> The handle.
      integer, intent(in) :: ihandle
      !> Lateral shift (mm), yaw and roll (rad) of the wheelset.
      real(wp), intent(in) :: yws, yaw, roll
      !> Forward (> 0), lateral and vertical velocity of the wheelset centre (mm/s).
      real(wp), intent(in) :: vs, vy, vz
      !> Roll, yaw and pitch rate (rad/s; vpitch < 0 rolling forward).
      real(wp), intent(in) :: vroll, vyaw, vpitch
      !> Load mode: 1 normal force, 2 vertical force, 3 approach.
      integer, intent(in) :: imode
      !> Load of the right and of the left wheel (N or mm).
      real(wp), intent(in) :: fright, fleft
      !> The totals.
      real(wp), intent(out) :: totals(4)
      !> Status (0 success).
      integer, intent(out) :: istat
      totals = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_solve_wheelset(slots(ihandle)%ctx, &
         wheelset_state_type(y_ws=yws, yaw=yaw, roll=roll, v_forward=vs, v_lateral=vy, &
         v_vertical=vz, roll_rate=vroll, yaw_rate=vyaw, pitch_rate=vpitch), imode, fright, &
         fleft, totals)
   end subroutine legacy_solve_wheelset

   !> Wheel iside (1 right, −1 left) of the last wheelset solve in the kinematic layout, main
   !> patch (ipatch = 0) or patch ipatch (context_wheel).
   subroutine legacy_wheelset_wheel(ihandle, iside, ipatch, values, istat)
      !> The handle, the wheel and the patch.
      integer, intent(in) :: ihandle, iside, ipatch
      !> The values.
      real(wp), intent(out) :: values(kinematic_value_count)
      !> Status (0 success).
      integer, intent(out) :: istat
      values = 0.0_wp
      istat = stat_usage
      if (valid(ihandle)) istat = context_wheel(slots(ihandle)%ctx, iside, ipatch, values)
   end subroutine legacy_wheelset_wheel

   !> The message of the last call on a handle (blank after a success), or why the handle is
   !> not valid. Cut to len(msg).
   subroutine legacy_message(ihandle, msg)
      !> The handle.
      integer, intent(in) :: ihandle
      !> The message.
      character(len=*), intent(out) :: msg
      if (valid(ihandle)) then
         msg = context_message(slots(ihandle)%ctx)
      else if (ihandle == 0 .and. all_in_use()) then
         msg = 'handle 0: shc_create found all '//str_int(max_handles)//' handles in use; '// &
            'destroy the handles no longer needed (shc_destroy)'
      else
         msg = 'invalid contact handle '//str_int(ihandle)//': expected a handle from '// &
            'shc_create or shc_create_ws that was not destroyed (1 to '// &
            str_int(max_handles)//'; they return 0 when all handles are in use)'
      end if
   end subroutine legacy_message

   !> True when every handle is taken (shc_create then returns handle 0).
   logical function all_in_use()
      integer :: i
      all_in_use = .true.
      !$omp critical (shcontact_legacy_handles)
      do i = 1, max_handles
         if (.not. allocated(slots(i)%ctx)) then
            all_in_use = .false.
            exit
         end if
      end do
      !$omp end critical (shcontact_legacy_handles)
   end function all_in_use

   !> True for a handle of a created, not destroyed contact.
   logical function valid(ihandle)
      integer, intent(in) :: ihandle
      valid = .false.
      if (ihandle < 1 .or. ihandle > max_handles) return
      valid = allocated(slots(ihandle)%ctx)
   end function valid

end module shcontact_api_legacy

! The external entry points (no module, implicit interfaces allowed to the caller). Each one
! forwards to its legacy_* procedure above; the argument lists are the same.

!> Create a contact from profile names ('builtin:S1002', 'builtin:UIC60' or file names) for
!> the right (iside = 1) or left (iside = -1) wheel. See legacy_create.
subroutine shc_create(ihandle, wheel, rail, iside, istat)
   use shcontact_api_legacy, only: legacy_create
   implicit none
   integer, intent(out) :: ihandle
   character(len=*), intent(in) :: wheel, rail
   integer, intent(in) :: iside
   integer, intent(out) :: istat
   call legacy_create(ihandle, wheel, rail, iside, istat)
end subroutine shc_create

!> Create a contact from profiles given as arrays of points: nw wheel points yw, zw (from the
!> field side to the flange back) and nr rail points yr, zr (from the track centre to the field
!> side), mm, y towards the field side, z down, right-side form; checked and cleaned as profile
!> files are. See legacy_create_arrays.
subroutine shc_create_arrays(ihandle, nw, yw, zw, nr, yr, zr, iside, istat)
   use shcontact_api_legacy, only: legacy_create_arrays
   implicit none
   integer, intent(out) :: ihandle
   integer, intent(in) :: nw
   double precision, intent(in) :: yw(*), zw(*)
   integer, intent(in) :: nr
   double precision, intent(in) :: yr(*), zr(*)
   integer, intent(in) :: iside
   integer, intent(out) :: istat
   call legacy_create_arrays(ihandle, nw, yw, zw, nr, yr, zr, iside, istat)
end subroutine shc_create_arrays

!> The size of the element fields of patch ipatch of the last solve: nx elements per strip,
!> ny strips (needs SHC_SET_OPTION(IH, 'output%fields', 'all', ISTAT) before the solve).
subroutine shc_field_size(ihandle, ipatch, nx, ny, istat)
   use shcontact_api_legacy, only: legacy_field_size
   implicit none
   integer, intent(in) :: ihandle, ipatch
   integer, intent(out) :: nx, ny
   integer, intent(out) :: istat
   call legacy_field_size(ihandle, ipatch, nx, ny, istat)
end subroutine shc_field_size

!> The element fields of patch ipatch of the last solve, arrays (nx, ny): element centres x, y
!> (mm), element areas (mm**2), normal pressure pn and tractions px, py (MPa), slip magnitude,
!> state (0 exterior, 1 adhesion, 2 slip). doc/api.md.
subroutine shc_fields(ihandle, ipatch, nx, ny, x, y, area, pn, px, py, slip, state, istat)
   use shcontact_api_legacy, only: legacy_fields
   implicit none
   integer, intent(in) :: ihandle, ipatch
   integer, intent(in) :: nx, ny
   double precision, intent(inout) :: x(nx, ny), y(nx, ny), area(nx, ny), pn(nx, ny), &
      px(nx, ny), py(nx, ny), slip(nx, ny)
   integer, intent(inout) :: state(nx, ny)
   integer, intent(out) :: istat
   call legacy_fields(ihandle, ipatch, nx, ny, x, y, area, pn, px, py, slip, state, istat)
end subroutine shc_fields

!> The points of the contact's wheel (ikind = 1, SHC_PROFILE_WHEEL) or rail (ikind = 0,
!> SHC_PROFILE_RAIL) profile as created (mm, canonical form): n points in y(1:n), z(1:n), which
!> hold nmax; n is set also when it exceeds nmax (status 1).
subroutine shc_get_profile(ihandle, ikind, nmax, n, y, z, istat)
   use shcontact_api_legacy, only: legacy_get_profile
   implicit none
   integer, intent(in) :: ihandle, ikind, nmax
   integer, intent(out) :: n
   double precision, intent(out) :: y(*), z(*)
   integer, intent(out) :: istat
   call legacy_get_profile(ihandle, ikind, nmax, n, y, z, istat)
end subroutine shc_get_profile

!> Release a contact.
subroutine shc_destroy(ihandle, istat)
   use shcontact_api_legacy, only: legacy_destroy
   implicit none
   integer, intent(in) :: ihandle
   integer, intent(out) :: istat
   call legacy_destroy(ihandle, istat)
end subroutine shc_destroy

!> Set the shear modulus G (MPa), Poisson's ratio and the friction coefficient.
subroutine shc_set_material(ihandle, g, poiss, fric, istat)
   use shcontact_api_legacy, only: legacy_set_material
   implicit none
   integer, intent(in) :: ihandle
   double precision, intent(in) :: g, poiss, fric
   integer, intent(out) :: istat
   call legacy_set_material(ihandle, g, poiss, fric, istat)
end subroutine shc_set_material

!> Set the track and wheelset dimensions (mm; slope e.g. 0.025; icant /= 0: rail already canted).
subroutine shc_set_track(ihandle, gauge, gheight, slope, icant, fbdist, fbpos, rnom, istat)
   use shcontact_api_legacy, only: legacy_set_track
   implicit none
   integer, intent(in) :: ihandle
   double precision, intent(in) :: gauge, gheight, slope
   integer, intent(in) :: icant
   double precision, intent(in) :: fbdist, fbpos, rnom
   integer, intent(out) :: istat
   call legacy_set_track(ihandle, gauge, gheight, slope, icant, fbdist, fbpos, rnom, istat)
end subroutine shc_set_track

!> Set one option: key 'group%variable' as in the app's case files, value as text.
subroutine shc_set_option(ihandle, key, value, istat)
   use shcontact_api_legacy, only: legacy_set_option
   implicit none
   integer, intent(in) :: ihandle
   character(len=*), intent(in) :: key, value
   integer, intent(out) :: istat
   call legacy_set_option(ihandle, key, value, istat)
end subroutine shc_set_option

!> Solve: lateral shift ty (mm), roll (rad), load mode imode (1 normal force N, 2 vertical
!> force N, 3 approach mm) and its value fload, creepages cksi, ceta (-) and cphi (rad/mm);
!> values(25) receives the result (doc/api.md).
subroutine shc_solve(ihandle, ty, roll, imode, fload, cksi, ceta, cphi, values, istat)
   use shcontact_api_legacy, only: legacy_solve
   implicit none
   integer, intent(in) :: ihandle
   double precision, intent(in) :: ty, roll
   integer, intent(in) :: imode
   double precision, intent(in) :: fload, cksi, ceta, cphi
   double precision, intent(out) :: values(25)
   integer, intent(out) :: istat
   call legacy_solve(ihandle, ty, roll, imode, fload, cksi, ceta, cphi, values, istat)
end subroutine shc_solve

!> Solve one wheel from the wheelset's kinematics: lateral shift yws (mm), yaw and roll (rad),
!> velocities vs (forward, > 0), vy, vz (mm/s), rates vroll, vyaw, vpitch (rad/s, vpitch < 0
!> rolling forward), load mode imode and value fload; values(29) receives the kinematic layout
!> (doc/api.md, include/shcontact.fi).
subroutine shc_solve_kin(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, imode, fload, &
      values, istat)
   use shcontact_api_legacy, only: legacy_solve_kinematic
   implicit none
   integer, intent(in) :: ihandle
   double precision, intent(in) :: yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch
   integer, intent(in) :: imode
   double precision, intent(in) :: fload
   double precision, intent(out) :: values(29)
   integer, intent(out) :: istat
   call legacy_solve_kinematic(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, imode, &
      fload, values, istat)
end subroutine shc_solve_kin

!> The values(29) of patch ipatch of the last solve in the kinematic layout (doc/api.md).
subroutine shc_patch_kin(ihandle, ipatch, values, istat)
   use shcontact_api_legacy, only: legacy_patch_kinematic
   implicit none
   integer, intent(in) :: ihandle, ipatch
   double precision, intent(out) :: values(29)
   integer, intent(out) :: istat
   call legacy_patch_kinematic(ihandle, ipatch, values, istat)
end subroutine shc_patch_kin

!> The values(17) of patch ipatch of the last solve (doc/api.md).
subroutine shc_patch(ihandle, ipatch, values, istat)
   use shcontact_api_legacy, only: legacy_patch
   implicit none
   integer, intent(in) :: ihandle, ipatch
   double precision, intent(out) :: values(17)
   integer, intent(out) :: istat
   call legacy_patch(ihandle, ipatch, values, istat)
end subroutine shc_patch

!> The message of the last call on a handle (blank after a success).
subroutine shc_errmsg(ihandle, msg)
   use shcontact_api_legacy, only: legacy_message
   implicit none
   integer, intent(in) :: ihandle
   character(len=*), intent(out) :: msg
   call legacy_message(ihandle, msg)
end subroutine shc_errmsg

!> Set a number by key: 'group%variable' as in the app's case files (or a variable name that
!> only one group has, e.g. 't_y'), value x in the key's units (doc/api.md).
subroutine shc_set_value(ihandle, key, x, istat)
   use shcontact_api_legacy, only: legacy_set_value
   implicit none
   integer, intent(in) :: ihandle
   character(len=*), intent(in) :: key
   double precision, intent(in) :: x
   integer, intent(out) :: istat
   call legacy_set_value(ihandle, key, x, istat)
end subroutine shc_set_value

!> Solve the state set by key (position, kinematics, load, creepages; doc/api.md).
subroutine shc_solve_state(ihandle, istat)
   use shcontact_api_legacy, only: legacy_solve_state
   implicit none
   integer, intent(in) :: ihandle
   integer, intent(out) :: istat
   call legacy_solve_state(ihandle, istat)
end subroutine shc_solve_state

!> A result value of the last solve by name (doc/api.md), main patch (ipatch = 0) or patch
!> ipatch.
subroutine shc_get_value(ihandle, key, ipatch, x, istat)
   use shcontact_api_legacy, only: legacy_get_value
   implicit none
   integer, intent(in) :: ihandle
   character(len=*), intent(in) :: key
   integer, intent(in) :: ipatch
   double precision, intent(out) :: x
   integer, intent(out) :: istat
   call legacy_get_value(ihandle, key, ipatch, x, istat)
end subroutine shc_get_value

!> One element field of patch ipatch by name ('x', 'y', 'area', 'pn', 'px', 'py', 'slip',
!> 'state'), array a(nx, ny) as SHC_FIELDS gives it.
subroutine shc_get_field(ihandle, key, ipatch, nx, ny, a, istat)
   use shcontact_api_legacy, only: legacy_get_field
   implicit none
   integer, intent(in) :: ihandle
   character(len=*), intent(in) :: key
   integer, intent(in) :: ipatch, nx, ny
   double precision, intent(inout) :: a(nx, ny)
   integer, intent(out) :: istat
   call legacy_get_field(ihandle, key, ipatch, nx, ny, a, istat)
end subroutine shc_get_field

!> Create a wheelset handle: both wheels from the same profile names (doc/api.md).
subroutine shc_create_ws(ihandle, wheel, rail, istat)
   use shcontact_api_legacy, only: legacy_create_wheelset
   implicit none
   integer, intent(out) :: ihandle
   character(len=*), intent(in) :: wheel, rail
   integer, intent(out) :: istat
   call legacy_create_wheelset(ihandle, wheel, rail, istat)
end subroutine shc_create_ws

!> Solve both wheels of a wheelset handle: the wheelset state as SHC_SOLVE_KIN, load mode imode
!> and the load of the right (fright) and left (fleft) wheel; totals(4) receives F_x, F_y, F_z
!> (N, on the wheelset, true track frame) and M_z (N mm) about its vertical axis.
subroutine shc_solve_ws(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, imode, &
      fright, fleft, totals, istat)
   use shcontact_api_legacy, only: legacy_solve_wheelset
   implicit none
   integer, intent(in) :: ihandle
   double precision, intent(in) :: yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch
   integer, intent(in) :: imode
   double precision, intent(in) :: fright, fleft
   double precision, intent(out) :: totals(4)
   integer, intent(out) :: istat
   call legacy_solve_wheelset(ihandle, yws, yaw, roll, vs, vy, vz, vroll, vyaw, vpitch, imode, &
      fright, fleft, totals, istat)
end subroutine shc_solve_ws

!> The values(29) of wheel iside (SHC_RIGHT, SHC_LEFT) of the last wheelset solve, kinematic
!> layout: its main patch (ipatch = 0) or patch ipatch.
subroutine shc_ws_wheel(ihandle, iside, ipatch, values, istat)
   use shcontact_api_legacy, only: legacy_wheelset_wheel
   implicit none
   integer, intent(in) :: ihandle, iside, ipatch
   double precision, intent(out) :: values(29)
   integer, intent(out) :: istat
   call legacy_wheelset_wheel(ihandle, iside, ipatch, values, istat)
end subroutine shc_ws_wheel
