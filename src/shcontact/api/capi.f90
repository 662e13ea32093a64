!> The C API (include/shcontact.h): `bind(C)` functions over the same engine as the Fortran API,
!> with opaque handles and integer status codes.
!>
!> A handle is the C address of a heap-allocated [[contact_context_type]]; there is no table and
!> no global state, so distinct handles may be used from distinct threads at once. Every call
!> returns a status (0 success, 1 usage, 2 invalid input, 3 I/O, 5 numerical, 6 no contact) and
!> keeps it, with its message, in the handle for [[shcontact_last_error]]. A NULL handle is
!> reported as status 1; a dangling (destroyed) handle cannot be detected.
module shcontact_api_capi
   use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_ptr, c_null_ptr, &
      c_null_char, c_loc, c_f_pointer, c_associated, c_size_t
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: stat_usage
   use shcontact_core_strings, only: str_int
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_api_values, only: patch_value_count, result_value_count, kinematic_value_count
   use shcontact_api_context, only: contact_context_type, context_create, context_set_material, &
      context_set_track, context_solve, context_solve_kinematic, &
      context_message, context_fail, context_create_arrays
   use shcontact_api_context_results, only: context_patch, context_patch_kinematic, &
      context_field_size, context_fields, context_get_profile
   use shcontact_api_context, only: context_create_wheelset, context_solve_wheelset
   use shcontact_api_keyed, only: context_set_option_by_key, context_set_value, &
      context_solve_state, context_get_value, &
      context_get_field, context_wheel
   use shcontact_version_info, only: shcontact_version
   implicit none
   private

   public :: shcontact_create_arrays, shcontact_field_size, shcontact_fields, &
      shcontact_get_profile
   public :: shcontact_create, shcontact_destroy, shcontact_set_material, shcontact_set_track, &
      shcontact_set_option, shcontact_solve, shcontact_solve_kinematic, shcontact_patch, &
      shcontact_patch_kinematic, shcontact_last_error, shcontact_version_string
   public :: shcontact_set_value, shcontact_solve_state, shcontact_get_value, &
      shcontact_get_field, shcontact_create_wheelset, shcontact_solve_wheelset, &
      shcontact_wheelset_wheel

   interface
      !> The C library's strlen.
      pure integer(c_size_t) function c_strlen(text) bind(C, name='strlen')
         import :: c_ptr, c_size_t
         type(c_ptr), value :: text
      end function c_strlen
   end interface

   !> Message for a NULL handle.
   character(len=*), parameter :: null_handle_message = 'invalid contact handle: NULL '// &
      '(expected a handle from shcontact_create that was not destroyed)'

contains

   !> Create a contact from profile names (NUL-terminated: `builtin:NAME` or file names) for the
   !> right (side = 1) or left (side = −1) wheel. *handle receives the new handle, also when the
   !> creation fails (then its last error tells why; destroy it); NULL only when memory is out.
   integer(c_int) function shcontact_create(handle, wheel, rail, side) &
         result(stat) bind(C, name='shcontact_create')
      !> Where to store the handle (shcontact_contact **).
      type(c_ptr), value :: handle
      !> Wheel and rail profile names (const char *).
      type(c_ptr), value :: wheel, rail
      !> 1 right, −1 left.
      integer(c_int), value :: side
      type(contact_context_type), pointer :: ctx

      stat = stat_usage
      call new_context(handle, ctx)
      if (.not. associated(ctx)) return
      if (.not. (c_associated(wheel) .and. c_associated(rail))) then
         stat = context_fail(ctx, 'shcontact_create: wheel or rail profile name is NULL; '// &
            "expected a name such as 'builtin:S1002' or a file name", stat_usage)
         return
      end if
      stat = context_create(ctx, from_c(wheel), from_c(rail), int(side))
   end function shcontact_create

   !> Create a contact from profiles given as arrays of points (mm, right-side canonical form:
   !> y towards the field side, z down; wheel points from the field side to the flange back, rail
   !> points from the track centre to the field side), checked and cleaned as profile files are.
   !> *handle as for [[shcontact_create]].
   integer(c_int) function shcontact_create_arrays(handle, n_wheel, wheel_y, wheel_z, n_rail, &
         rail_y, rail_z, side) result(stat) bind(C, name='shcontact_create_arrays')
      !> Where to store the handle (shcontact_contact **).
      type(c_ptr), value :: handle
      !> Number of wheel points and their coordinates (const double *).
      integer(c_int), value :: n_wheel
      type(c_ptr), value :: wheel_y, wheel_z
      !> Number of rail points and their coordinates (const double *).
      integer(c_int), value :: n_rail
      type(c_ptr), value :: rail_y, rail_z
      !> 1 right, −1 left.
      integer(c_int), value :: side
      type(contact_context_type), pointer :: ctx
      real(c_double), pointer :: wy(:), wz(:), ry(:), rz(:)

      stat = stat_usage
      call new_context(handle, ctx)
      if (.not. associated(ctx)) return
      if (n_wheel < 0 .or. n_rail < 0) then
         stat = context_fail(ctx, 'shcontact_create_arrays: negative number of points '// &
            '(n_wheel = '//str_int(int(n_wheel))//', n_rail = '//str_int(int(n_rail))//')', &
            stat_usage)
         return
      end if
      if ((n_wheel > 0 .and. .not. (c_associated(wheel_y) .and. c_associated(wheel_z))) .or. &
          (n_rail > 0 .and. .not. (c_associated(rail_y) .and. c_associated(rail_z)))) then
         stat = context_fail(ctx, 'shcontact_create_arrays: a coordinate array is NULL', &
            stat_usage)
         return
      end if
      call c_f_pointer(wheel_y, wy, [n_wheel])
      call c_f_pointer(wheel_z, wz, [n_wheel])
      call c_f_pointer(rail_y, ry, [n_rail])
      call c_f_pointer(rail_z, rz, [n_rail])
      stat = context_create_arrays(ctx, wy, wz, ry, rz, int(side))
   end function shcontact_create_arrays

   !> Allocate a new contact and store its address in *handle (shcontact_contact **): NULL
   !> first, so that the caller finds NULL when memory is out. `ctx` is null when `handle` is
   !> NULL or memory is out.
   subroutine new_context(handle, ctx)
      !> Where to store the handle.
      type(c_ptr), intent(in) :: handle
      !> The new contact.
      type(contact_context_type), pointer, intent(out) :: ctx
      type(c_ptr), pointer :: out
      integer :: alloc_stat
      ctx => null()
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, out)
      out = c_null_ptr
      allocate (ctx, stat=alloc_stat)
      if (alloc_stat /= 0) then
         ctx => null()
         return
      end if
      out = c_loc(ctx)
   end subroutine new_context

   !> Release a contact; NULL is accepted and ignored (status 0).
   integer(c_int) function shcontact_destroy(handle) result(stat) &
         bind(C, name='shcontact_destroy')
      !> The handle.
      type(c_ptr), value :: handle
      type(contact_context_type), pointer :: ctx
      stat = 0
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      deallocate (ctx)
   end function shcontact_destroy

   !> Set the shear modulus G (MPa), Poisson's ratio ν and the friction coefficient μ.
   integer(c_int) function shcontact_set_material(handle, shear_modulus, poisson, friction) &
         result(stat) bind(C, name='shcontact_set_material')
      !> The handle.
      type(c_ptr), value :: handle
      !> G, ν, μ.
      real(c_double), value :: shear_modulus, poisson, friction
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      stat = context_set_material(ctx, real(shear_modulus, wp), real(poisson, wp), &
         real(friction, wp))
   end function shcontact_set_material

   !> Set the track and wheelset dimensions (mm; inclination as a slope; rail_canted /= 0 when
   !> the rail profile is already canted).
   integer(c_int) function shcontact_set_track(handle, gauge, gauge_height, inclination, &
         rail_canted, flange_back_distance, flange_back_position, nominal_radius) result(stat) &
         bind(C, name='shcontact_set_track')
      !> The handle.
      type(c_ptr), value :: handle
      !> Gauge and gauge-point depth (mm), rail inclination.
      real(c_double), value :: gauge, gauge_height, inclination
      !> Non-zero: the rail profile is already canted.
      integer(c_int), value :: rail_canted
      !> Flange-back distance, flange-back position, nominal radius (mm).
      real(c_double), value :: flange_back_distance, flange_back_position, nominal_radius
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      stat = context_set_track(ctx, real(gauge, wp), real(gauge_height, wp), &
         real(inclination, wp), rail_canted /= 0, real(flange_back_distance, wp), &
         real(flange_back_position, wp), real(nominal_radius, wp))
   end function shcontact_set_track

   !> Set one option by name (`group%variable`, as in the app's case files) and textual value.
   integer(c_int) function shcontact_set_option(handle, key, value) result(stat) &
         bind(C, name='shcontact_set_option')
      !> The handle.
      type(c_ptr), value :: handle
      !> Option name and value (const char *, NUL-terminated).
      type(c_ptr), value :: key, value
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. (c_associated(key) .and. c_associated(value))) then
         stat = context_fail(ctx, 'shcontact_set_option: key or value is NULL', stat_usage)
         return
      end if
      stat = context_set_option_by_key(ctx, from_c(key), from_c(value))
   end function shcontact_set_option

   !> Solve one contact: lateral shift t_y (mm), roll (rad), load mode (1 normal force N,
   !> 2 vertical force N, 3 approach mm) and value, creepages ν_x, ν_y, φ (rad/mm). values
   !> receives SHCONTACT_RESULT_SIZE numbers (zeros on failure).
   integer(c_int) function shcontact_solve(handle, t_y, roll, load_mode, load, nu_x, nu_y, phi, &
         values) result(stat) bind(C, name='shcontact_solve')
      !> The handle.
      type(c_ptr), value :: handle
      !> Position, load and creepages.
      real(c_double), value :: t_y, roll
      integer(c_int), value :: load_mode
      real(c_double), value :: load, nu_x, nu_y, phi
      !> The result (result_value_count values).
      real(c_double), intent(out), optional :: values(result_value_count)
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. present(values)) then
         stat = context_fail(ctx, 'shcontact_solve: values is NULL', stat_usage)
         return
      end if
      stat = context_solve(ctx, real(t_y, wp), real(roll, wp), int(load_mode), real(load, wp), &
         real(nu_x, wp), real(nu_y, wp), real(phi, wp), values)
   end function shcontact_solve

   !> Solve one wheel from the wheelset's position and velocities (CONTACT module 1 meaning):
   !> lateral shift y_ws (mm), yaw and roll (rad), velocities of the wheelset centre (mm/s;
   !> v_forward > 0), roll, yaw and pitch rate (rad/s; pitch_rate < 0 rolling forward), load mode
   !> and value. values receives SHCONTACT_KIN_SIZE numbers (zeros on failure).
   integer(c_int) function shcontact_solve_kinematic(handle, y_ws, yaw, roll, v_forward, &
         v_lateral, v_vertical, roll_rate, yaw_rate, pitch_rate, load_mode, load, values) &
         result(stat) bind(C, name='shcontact_solve_kinematic')
      !> The handle.
      type(c_ptr), value :: handle
      !> Position (mm, rad).
      real(c_double), value :: y_ws, yaw, roll
      !> Velocities (mm/s) and rates (rad/s).
      real(c_double), value :: v_forward, v_lateral, v_vertical, roll_rate, yaw_rate, pitch_rate
      !> Load mode and value.
      integer(c_int), value :: load_mode
      real(c_double), value :: load
      !> The result (kinematic_value_count values).
      real(c_double), intent(out), optional :: values(kinematic_value_count)
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. present(values)) then
         stat = context_fail(ctx, 'shcontact_solve_kinematic: values is NULL', stat_usage)
         return
      end if
      stat = context_solve_kinematic(ctx, wheelset_state_type(y_ws=real(y_ws, wp), &
         yaw=real(yaw, wp), roll=real(roll, wp), v_forward=real(v_forward, wp), &
         v_lateral=real(v_lateral, wp), v_vertical=real(v_vertical, wp), &
         roll_rate=real(roll_rate, wp), yaw_rate=real(yaw_rate, wp), &
         pitch_rate=real(pitch_rate, wp)), int(load_mode), real(load, wp), values)
   end function shcontact_solve_kinematic

   !> The SHCONTACT_KIN_SIZE values of patch `patch` (1-based) of the last solve: the patch in
   !> the kinematic layout (its values, creepages and x lead; the result's counts and totals).
   integer(c_int) function shcontact_patch_kinematic(handle, patch, values) result(stat) &
         bind(C, name='shcontact_patch_kinematic')
      !> The handle.
      type(c_ptr), value :: handle
      !> Patch index, 1 to the number of patches.
      integer(c_int), value :: patch
      !> The values.
      real(c_double), intent(out), optional :: values(kinematic_value_count)
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. present(values)) then
         stat = context_fail(ctx, 'shcontact_patch_kinematic: values is NULL', stat_usage)
         return
      end if
      stat = context_patch_kinematic(ctx, int(patch), values)
   end function shcontact_patch_kinematic

   !> The SHCONTACT_PATCH_SIZE values of patch `patch` (1-based) of the last solve.
   integer(c_int) function shcontact_patch(handle, patch, values) result(stat) &
         bind(C, name='shcontact_patch')
      !> The handle.
      type(c_ptr), value :: handle
      !> Patch index, 1 to the number of patches.
      integer(c_int), value :: patch
      !> The patch values.
      real(c_double), intent(out), optional :: values(patch_value_count)
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. present(values)) then
         stat = context_fail(ctx, 'shcontact_patch: values is NULL', stat_usage)
         return
      end if
      stat = context_patch(ctx, int(patch), values)
   end function shcontact_patch

   !> The points of the contact's wheel (kind = 1) or rail (kind = 0) profile as created (mm,
   !> canonical form): *n points in y[0..*n-1], z[...], which hold `capacity` values; *n is set
   !> also when it exceeds the capacity (status 1, nothing copied): call with capacity 0 to ask.
   integer(c_int) function shcontact_get_profile(handle, kind, capacity, n, y, z) result(stat) &
         bind(C, name='shcontact_get_profile')
      !> The handle.
      type(c_ptr), value :: handle
      !> 1 wheel, 0 rail.
      integer(c_int), value :: kind
      !> Size of y and z.
      integer(c_int), value :: capacity
      !> Where to store the number of points (int *).
      type(c_ptr), value :: n
      !> The points (double *; may be NULL when capacity is 0).
      type(c_ptr), value :: y, z
      type(contact_context_type), pointer :: ctx
      integer(c_int), pointer :: count
      real(c_double), pointer :: fy(:), fz(:)
      integer :: m, points
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      m = max(int(capacity), 0)
      if (.not. c_associated(n) .or. (m > 0 .and. .not. (c_associated(y) .and. &
          c_associated(z)))) then
         stat = context_fail(ctx, 'shcontact_get_profile: n, y or z is NULL', stat_usage)
         return
      end if
      call c_f_pointer(n, count)
      call c_f_pointer(y, fy, [m])
      call c_f_pointer(z, fz, [m])
      stat = context_get_profile(ctx, int(kind), points, fy, fz)
      count = points
   end function shcontact_get_profile

   !> The size of the element fields of patch `patch` (1-based) of the last solve: *nx elements
   !> per strip (rolling direction), *ny strips; 0 × 0 for a patch without load. Needs the
   !> option output%fields = all before the solve.
   integer(c_int) function shcontact_field_size(handle, patch, nx, ny) result(stat) &
         bind(C, name='shcontact_field_size')
      !> The handle.
      type(c_ptr), value :: handle
      !> Patch index, 1 to the number of patches.
      integer(c_int), value :: patch
      !> Where to store the sizes (int *).
      type(c_ptr), value :: nx, ny
      type(contact_context_type), pointer :: ctx
      integer(c_int), pointer :: mx, my
      integer :: kx, ky
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. (c_associated(nx) .and. c_associated(ny))) then
         stat = context_fail(ctx, 'shcontact_field_size: nx or ny is NULL', stat_usage)
         return
      end if
      call c_f_pointer(nx, mx)
      call c_f_pointer(ny, my)
      stat = context_field_size(ctx, int(patch), kx, ky)
      mx = kx
      my = ky
   end function shcontact_field_size

   !> The element fields of patch `patch` (1-based) of the last solve, each an array of nx·ny
   !> values (the sizes of shcontact_field_size) in Fortran order: element j (0-based, from the
   !> leading edge) of strip i at [j + nx*i], i.e. C arrays [ny][nx]. x, y element centres (mm),
   !> area (mm²), pn, px, py (MPa, on the wheel), slip magnitude, state (0 exterior, 1 adhesion,
   !> 2 slip).
   integer(c_int) function shcontact_fields(handle, patch, nx, ny, x, y, area, pn, px, py, slip, &
         state) result(stat) bind(C, name='shcontact_fields')
      !> The handle.
      type(c_ptr), value :: handle
      !> Patch index, 1 to the number of patches.
      integer(c_int), value :: patch
      !> The sizes.
      integer(c_int), value :: nx, ny
      !> The arrays (double *, nx·ny each; none may be NULL).
      type(c_ptr), value :: x, y, area, pn, px, py, slip
      !> The element states (int *, nx·ny).
      type(c_ptr), value :: state
      type(contact_context_type), pointer :: ctx
      real(c_double), pointer :: fx(:, :), fy(:, :), fa(:, :), fpn(:, :), fpx(:, :), &
         fpy(:, :), fs(:, :)
      integer(c_int), pointer :: fst(:, :)
      integer :: mx, my
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      mx = max(int(nx), 0)
      my = max(int(ny), 0)
      ! Each size on its own (their product may pass the int range).
      if (mx > 0 .and. my > 0 .and. .not. (c_associated(x) .and. c_associated(y) .and. &
          c_associated(area) .and. c_associated(pn) .and. c_associated(px) .and. &
          c_associated(py) .and. c_associated(slip) .and. c_associated(state))) then
         stat = context_fail(ctx, 'shcontact_fields: an array is NULL', stat_usage)
         return
      end if
      call c_f_pointer(x, fx, [mx, my])
      call c_f_pointer(y, fy, [mx, my])
      call c_f_pointer(area, fa, [mx, my])
      call c_f_pointer(pn, fpn, [mx, my])
      call c_f_pointer(px, fpx, [mx, my])
      call c_f_pointer(py, fpy, [mx, my])
      call c_f_pointer(slip, fs, [mx, my])
      call c_f_pointer(state, fst, [mx, my])
      stat = context_fields(ctx, int(patch), int(nx), int(ny), fx, fy, fa, fpn, fpx, fpy, fs, &
         fst)
   end function shcontact_fields

   !> Set a number by key (`group%variable` as in the app's case files, or a variable name that
   !> only one group has, e.g. "t_y"): the same setter as shcontact_set_option.
   integer(c_int) function shcontact_set_value(handle, key, value) result(stat) &
         bind(C, name='shcontact_set_value')
      !> The handle.
      type(c_ptr), value :: handle
      !> The key (const char *).
      type(c_ptr), value :: key
      !> The value, in the key's units.
      real(c_double), value :: value
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. c_associated(key)) then
         stat = context_fail(ctx, 'shcontact_set_value: key is NULL', stat_usage)
         return
      end if
      stat = context_set_value(ctx, from_c(key), real(value, wp))
   end function shcontact_set_value

   !> Solve the state set by key (position, kinematics, load, creepages; doc/api.md); read the
   !> result with shcontact_get_value.
   integer(c_int) function shcontact_solve_state(handle) result(stat) &
         bind(C, name='shcontact_solve_state')
      !> The handle.
      type(c_ptr), value :: handle
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      stat = context_solve_state(ctx)
   end function shcontact_solve_state

   !> A result value of the last solve by name (doc/api.md), of the main patch (patch 0) or of
   !> patch `patch`; *value receives it (0 on failure).
   integer(c_int) function shcontact_get_value(handle, key, patch, value) result(stat) &
         bind(C, name='shcontact_get_value')
      !> The handle.
      type(c_ptr), value :: handle
      !> The name (const char *).
      type(c_ptr), value :: key
      !> 0: the main patch, else 1 to the number of patches.
      integer(c_int), value :: patch
      !> Where to store the value (double *).
      type(c_ptr), value :: value
      type(contact_context_type), pointer :: ctx
      real(c_double), pointer :: out
      real(wp) :: x
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. (c_associated(key) .and. c_associated(value))) then
         stat = context_fail(ctx, 'shcontact_get_value: key or value is NULL', stat_usage)
         return
      end if
      call c_f_pointer(value, out)
      stat = context_get_value(ctx, from_c(key), int(patch), x)
      out = x
   end function shcontact_get_value

   !> One element field of patch `patch` of the last solve by name (x, y, area, pn, px, py,
   !> slip, state), nx·ny values in the order of shcontact_fields.
   integer(c_int) function shcontact_get_field(handle, key, patch, nx, ny, field) result(stat) &
         bind(C, name='shcontact_get_field')
      !> The handle.
      type(c_ptr), value :: handle
      !> The field name (const char *).
      type(c_ptr), value :: key
      !> Patch index; the sizes of shcontact_field_size.
      integer(c_int), value :: patch, nx, ny
      !> The field (double *, nx·ny values).
      type(c_ptr), value :: field
      type(contact_context_type), pointer :: ctx
      real(c_double), pointer :: a(:, :)
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. c_associated(key) .or. (nx > 0 .and. ny > 0 .and. &
          .not. c_associated(field))) then
         stat = context_fail(ctx, 'shcontact_get_field: key or field is NULL', stat_usage)
         return
      end if
      call c_f_pointer(field, a, [max(int(nx), 0), max(int(ny), 0)])
      stat = context_get_field(ctx, from_c(key), int(patch), int(nx), int(ny), a)
   end function shcontact_get_field

   !> Create a wheelset handle: both wheels from the same profile names (the left wheel the
   !> mirror image), default track, material and options. *handle as for shcontact_create.
   integer(c_int) function shcontact_create_wheelset(handle, wheel, rail) result(stat) &
         bind(C, name='shcontact_create_wheelset')
      !> Where to store the handle (shcontact_contact **).
      type(c_ptr), value :: handle
      !> Wheel and rail profile names (const char *).
      type(c_ptr), value :: wheel, rail
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      call new_context(handle, ctx)
      if (.not. associated(ctx)) return
      if (.not. (c_associated(wheel) .and. c_associated(rail))) then
         stat = context_fail(ctx, 'shcontact_create_wheelset: wheel or rail profile name '// &
            "is NULL; expected a name such as 'builtin:S1002' or a file name", stat_usage)
         return
      end if
      stat = context_create_wheelset(ctx, from_c(wheel), from_c(rail))
   end function shcontact_create_wheelset

   !> Solve both wheels of a wheelset handle for one wheelset state (as shcontact_solve_kinematic)
   !> and each wheel's load; totals[4] receives F_x, F_y, F_z (N) on the
   !> wheelset, true track frame, and M_z (N mm) about the vertical axis through its centre.
   integer(c_int) function shcontact_solve_wheelset(handle, y_ws, yaw, roll, v_forward, &
         v_lateral, v_vertical, roll_rate, yaw_rate, pitch_rate, load_mode, load_right, &
         load_left, totals) result(stat) bind(C, name='shcontact_solve_wheelset')
      !> The handle.
      type(c_ptr), value :: handle
      !> Position (mm, rad).
      real(c_double), value :: y_ws, yaw, roll
      !> Velocities (mm/s) and rates (rad/s).
      real(c_double), value :: v_forward, v_lateral, v_vertical, roll_rate, yaw_rate, pitch_rate
      !> Load mode and the value of each wheel.
      integer(c_int), value :: load_mode
      real(c_double), value :: load_right, load_left
      !> The totals (4 values).
      real(c_double), intent(out), optional :: totals(4)
      type(contact_context_type), pointer :: ctx
      real(wp) :: t(4)
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. present(totals)) then
         stat = context_fail(ctx, 'shcontact_solve_wheelset: totals is NULL', stat_usage)
         return
      end if
      stat = context_solve_wheelset(ctx, wheelset_state_type(y_ws=real(y_ws, wp), &
         yaw=real(yaw, wp), roll=real(roll, wp), v_forward=real(v_forward, wp), &
         v_lateral=real(v_lateral, wp), v_vertical=real(v_vertical, wp), &
         roll_rate=real(roll_rate, wp), yaw_rate=real(yaw_rate, wp), &
         pitch_rate=real(pitch_rate, wp)), int(load_mode), real(load_right, wp), &
         real(load_left, wp), t)
      totals = t
   end function shcontact_solve_wheelset

   !> Wheel `side` (SHCONTACT_RIGHT, SHCONTACT_LEFT) of the last wheelset solve:
   !> values[SHCONTACT_KIN_SIZE] of its main patch (patch 0) or of patch `patch`, with the
   !> wheel's counts and totals (its side frame), as shcontact_patch_kinematic.
   integer(c_int) function shcontact_wheelset_wheel(handle, side, patch, values) result(stat) &
         bind(C, name='shcontact_wheelset_wheel')
      !> The handle.
      type(c_ptr), value :: handle
      !> 1 right, −1 left; 0 or a patch index.
      integer(c_int), value :: side, patch
      !> The values.
      real(c_double), intent(out), optional :: values(kinematic_value_count)
      type(contact_context_type), pointer :: ctx
      stat = stat_usage
      if (.not. c_associated(handle)) return
      call c_f_pointer(handle, ctx)
      if (.not. present(values)) then
         stat = context_fail(ctx, 'shcontact_wheelset_wheel: values is NULL', stat_usage)
         return
      end if
      stat = context_wheel(ctx, int(side), int(patch), values)
   end function shcontact_wheelset_wheel

   !> The status of the last call on a handle; its message is copied to buffer (NUL-terminated,
   !> cut to length − 1 characters; empty after a success). For a NULL handle: status 1.
   integer(c_int) function shcontact_last_error(handle, buffer, length) result(stat) &
         bind(C, name='shcontact_last_error')
      !> The handle (may be NULL).
      type(c_ptr), value :: handle
      !> Where to copy the message (char *; may be NULL, then nothing is copied).
      type(c_ptr), value :: buffer
      !> Size of buffer in bytes.
      integer(c_int), value :: length
      type(contact_context_type), pointer :: ctx

      if (.not. c_associated(handle)) then
         stat = stat_usage
         call to_c(null_handle_message, buffer, length)
         return
      end if
      call c_f_pointer(handle, ctx)
      stat = ctx%stat
      call to_c(context_message(ctx), buffer, length)
   end function shcontact_last_error

   !> The library version ("0.1.0"), copied like shcontact_last_error; returns its length.
   integer(c_int) function shcontact_version_string(buffer, length) result(n) &
         bind(C, name='shcontact_version')
      !> Where to copy the version (char *; may be NULL).
      type(c_ptr), value :: buffer
      !> Size of buffer in bytes.
      integer(c_int), value :: length
      call to_c(shcontact_version, buffer, length)
      n = len(shcontact_version)
   end function shcontact_version_string

   !> A Fortran string from a NUL-terminated C string.
   function from_c(text) result(str)
      type(c_ptr), intent(in) :: text
      character(len=:), allocatable :: str
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i
      n = int(c_strlen(text))
      call c_f_pointer(text, chars, [n])
      allocate (character(len=n) :: str)
      do i = 1, n
         str(i:i) = chars(i)
      end do
   end function from_c

   !> Copy a Fortran string to a C buffer of `length` bytes, NUL-terminated and cut to fit.
   subroutine to_c(str, buffer, length)
      character(len=*), intent(in) :: str
      type(c_ptr), intent(in) :: buffer
      integer(c_int), intent(in) :: length
      character(kind=c_char), pointer :: chars(:)
      integer :: n, i
      if (length < 1 .or. .not. c_associated(buffer)) return
      call c_f_pointer(buffer, chars, [length])
      n = min(len(str), int(length) - 1)
      do i = 1, n
         chars(i) = str(i:i)
      end do
      chars(n + 1) = c_null_char
   end subroutine to_c

end module shcontact_api_capi
