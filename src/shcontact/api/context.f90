!> A solver with its last result and last status, as the flat interfaces (legacy Fortran entry
!> points, C API) need: every operation takes plain integers, reals and strings and returns an
!> integer status, 0 on success or one of the `stat_*` codes of shcontact_core_error, and keeps
!> the message in the context. The message lives in a fixed buffer, so a successful call
!> allocates nothing here.
module shcontact_api_context
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use, intrinsic :: ieee_exceptions, only: ieee_overflow, ieee_get_halting_mode, &
      ieee_set_halting_mode, ieee_get_flag, ieee_set_flag
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_usage
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: to_lower, str_int, visible, control_characters
   use shcontact_geometry_track, only: track_type
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_normal_options, only: normal_options_type, new_normal_options
   use shcontact_tangential_options, only: tangential_options_type, parse_method, parse_bound, &
      parse_spin_model
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, profile_kind_rail, &
      tape_circle_origin
   use shcontact_profile_source, only: profile_from_points
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_api_solver, only: contact_solver_type, contact_result_type, contact_load_type, &
      contact_fields_type, max_patches
   use shcontact_api_values, only: patch_value_count, result_value_count, kinematic_value_count, &
      patch_values, result_values, kinematic_values
   implicit none
   private

   public :: contact_context_type, option_keys
   public :: context_create, context_create_arrays, context_set_material, context_set_track, &
      context_set_option, context_solve, context_solve_kinematic, context_patch, &
      context_patch_kinematic, context_field_size, context_fields, context_get_profile, &
      context_message, context_fail

   !> Longest message kept (longer ones are cut).
   integer, parameter :: message_capacity = 1024

   !> Keys accepted by [[context_set_option]] (the app's `group%variable` names).
   character(len=*), parameter :: option_keys(12) = [character(len=24) :: 'normal%method', &
      'normal%reduction', 'normal%epsilon', 'normal%n_strips', 'normal%b_min', &
      'tangential%method', 'tangential%bound', 'tangential%spin_model', &
      'tangential%n_elements', 'profiles%wheel_smoothing', 'profiles%rail_smoothing', &
      'output%fields']

   !> One contact of a flat interface.
   type :: contact_context_type
      !> The solver.
      type(contact_solver_type) :: solver
      !> The result of the last successful solve.
      type(contact_result_type) :: result
      !> True when `result` holds a solution.
      logical :: has_result = .false.
      !> Keep the element fields of every solve (option `output%fields`); off by default, so
      !> that a solve costs what it costs without fields.
      logical :: keep_fields = .false.
      !> The fields of the last solve (valid when has_fields).
      type(contact_fields_type) :: fields
      logical :: has_fields = .false.
      !> Status of the last operation (0: success).
      integer :: stat = 0
      !> Message of the last operation ('' on success).
      character(len=message_capacity) :: message = ''
      integer :: message_len = 0
   end type contact_context_type

contains

   !> Create the solver from profile names (`builtin:NAME` or files) with default track, material
   !> and options.
   integer function context_create(ctx, wheel, rail, side) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Wheel and rail profile: `builtin:NAME` or a file name.
      character(len=*), intent(in) :: wheel, rail
      !> 1: right wheel, −1: left wheel.
      integer, intent(in) :: side
      type(error_type), allocatable :: error

      ctx%has_result = .false.
      ctx%has_fields = .false.
      call ctx%solver%init(trim(wheel), trim(rail), error, side=side)
      stat = record(ctx, error)
   end function context_create

   !> Create the solver from profiles given as arrays of points (mm, right-side canonical form,
   !> shcontact_profile_points), checked and cleaned as profile files are
   !> (shcontact_profile_source's profile_from_points), with default track, material and options.
   integer function context_create_arrays(ctx, wheel_y, wheel_z, rail_y, rail_z, side) &
         result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Wheel points from the field side to the flange back: y (towards the field side), z (down).
      real(wp), intent(in) :: wheel_y(:), wheel_z(:)
      !> Rail points from the track centre to the field side.
      real(wp), intent(in) :: rail_y(:), rail_z(:)
      !> 1: right wheel, −1: left wheel.
      integer, intent(in) :: side
      type(error_type), allocatable :: error
      type(profile_type) :: wheel, rail

      ctx%has_result = .false.
      ctx%has_fields = .false.
      call profile_from_points(wheel_y, wheel_z, profile_kind_wheel, wheel, error)
      if (.not. allocated(error)) call profile_from_points(rail_y, rail_z, profile_kind_rail, &
         rail, error)
      if (.not. allocated(error)) call ctx%solver%init(wheel, rail, error, side=side)
      stat = record(ctx, error)
   end function context_create_arrays

   !> Set the shear modulus G (MPa), Poisson's ratio ν and the friction coefficient μ.
   integer function context_set_material(ctx, shear_modulus, poisson, friction) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> G (MPa), ν, μ.
      real(wp), intent(in) :: shear_modulus, poisson, friction
      type(error_type), allocatable :: error

      if (usable(ctx, error)) call ctx%solver%set_material(material_type(shear_modulus, &
         poisson, friction), error)
      stat = record(ctx, error)
   end function context_set_material

   !> Set the track and wheelset dimensions (see shcontact_geometry_track's track_type).
   integer function context_set_track(ctx, gauge, gauge_height, inclination, rail_canted, &
         flange_back_distance, flange_back_position, nominal_radius) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Gauge (mm) and depth of the gauge point below the rail top (mm).
      real(wp), intent(in) :: gauge, gauge_height
      !> Rail inclination as a slope (1:40 = 0.025).
      real(wp), intent(in) :: inclination
      !> The rail profile is already canted.
      logical, intent(in) :: rail_canted
      !> Flange-back distance (mm) and flange-back position in wheel profile coordinates (mm).
      real(wp), intent(in) :: flange_back_distance, flange_back_position
      !> Nominal rolling radius R₀ (mm).
      real(wp), intent(in) :: nominal_radius
      type(error_type), allocatable :: error

      if (usable(ctx, error)) call ctx%solver%set_track(error, track=track_type( &
         gauge=gauge, gauge_height=gauge_height, rail_inclination=inclination, &
         rail_canted=rail_canted, flange_back_distance=flange_back_distance, &
         flange_back_position=flange_back_position, nominal_radius=nominal_radius))
      stat = record(ctx, error)
   end function context_set_track

   !> Set one option by its name in the app's case files (`group%variable`, see [[option_keys]])
   !> and its value as text, e.g. ('tangential%bound', 'ellipsoidal') or ('normal%n_strips', '200').
   integer function context_set_option(ctx, key, value) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Option name (case-insensitive).
      character(len=*), intent(in) :: key
      !> Its value.
      character(len=*), intent(in) :: value
      type(error_type), allocatable :: error
      type(normal_options_type) :: normal, parsed
      type(tangential_options_type) :: tangential
      type(contact_options_type) :: search
      character(len=:), allocatable :: name

      if (.not. usable(ctx, error)) then
         stat = record(ctx, error)
         return
      end if
      if (scan(value, control_characters) > 0) then
         call fatal_error(error, "option '"//trim(key)//"' = '"//visible(value)// &
            "': a control character in the value", stat_invalid_input)
         stat = record(ctx, error)
         return
      end if
      call ctx%solver%get_options(normal, tangential)
      search = ctx%solver%get_contact_options()
      name = trim(adjustl(to_lower(key)))
      select case (name)
      case ('normal%method')
         call new_normal_options(parsed, error, method=trim(value))
         normal%method = parsed%method
      case ('normal%reduction')
         call new_normal_options(parsed, error, reduction=trim(value))
         normal%reduction = parsed%reduction
      case ('normal%epsilon')
         call read_real(name, value, normal%epsilon, error)
      case ('normal%n_strips')
         call read_int(name, value, normal%n_strips, error)
      case ('normal%b_min')
         call read_real(name, value, search%b_min, error)
      case ('tangential%method')
         call parse_method(trim(value), tangential%method, error)
      case ('tangential%bound')
         call parse_bound(trim(value), tangential%bound, error)
      case ('tangential%spin_model')
         call parse_spin_model(trim(value), tangential%spin_model, error)
      case ('tangential%n_elements')
         call read_int(name, value, tangential%n_elements, error)
      case ('profiles%wheel_smoothing')
         call read_real(name, value, search%l_filt_wheel, error)
      case ('profiles%rail_smoothing')
         call read_real(name, value, search%l_filt_rail, error)
      case ('output%fields')
         call read_fields_choice(name, value, ctx%keep_fields, error)
         stat = record(ctx, error)
         return
      case default
         call fatal_error(error, "option '"//trim(key)//"': unknown; expected one of "// &
            key_list(), stat_invalid_input)
      end select
      if (.not. allocated(error)) then
         select case (name)
         case ('normal%b_min', 'profiles%wheel_smoothing', 'profiles%rail_smoothing')
            call ctx%solver%set_track(error, contact_options=search)
         case default
            call ctx%solver%set_options(error, normal=normal, tangential=tangential)
         end select
      end if
      stat = record(ctx, error)
   end function context_set_option

   !> Solve one contact and return the flat result ([[result_values]]).
   integer function context_solve(ctx, t_y, roll, load_mode, load, nu_x, nu_y, phi, values) &
         result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Lateral wheelset shift (mm) and roll (rad).
      real(wp), intent(in) :: t_y, roll
      !> 1: normal force (N), 2: vertical force (N), 3: approach (mm).
      integer, intent(in) :: load_mode
      !> The force or approach.
      real(wp), intent(in) :: load
      !> Creepages ν_x, ν_y and spin φ (rad/mm).
      real(wp), intent(in) :: nu_x, nu_y, phi
      !> The flat result (result_value_count values; zero on failure).
      real(wp), intent(out) :: values(result_value_count)
      type(error_type), allocatable :: error

      values = 0.0_wp
      ctx%has_result = .false.
      ctx%has_fields = .false.
      if (usable(ctx, error)) then
         if (ctx%keep_fields) then
            call ctx%solver%solve(t_y, roll, contact_load_type(load_mode, load), &
               creepage_type(nu_x, nu_y, phi), ctx%result, error, ctx%fields)
            ctx%has_fields = .not. allocated(error)
         else
            call ctx%solver%solve(t_y, roll, contact_load_type(load_mode, load), &
               creepage_type(nu_x, nu_y, phi), ctx%result, error)
         end if
         if (.not. allocated(error)) then
            ctx%has_result = .true.
            call result_values(ctx%result, values)
         end if
      end if
      stat = record(ctx, error)
   end function context_solve

   !> Solve one wheel from the wheelset's position and velocities and return the flat result in
   !> the kinematic layout ([[kinematic_values]]).
   integer function context_solve_kinematic(ctx, state, load_mode, load, values) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Wheelset position and velocities (track frame; mm, mm/s, rad, rad/s).
      type(wheelset_state_type), intent(in) :: state
      !> 1: normal force (N), 2: vertical force (N), 3: approach (mm).
      integer, intent(in) :: load_mode
      !> The force or approach.
      real(wp), intent(in) :: load
      !> The flat result (kinematic_value_count values; zero on failure).
      real(wp), intent(out) :: values(kinematic_value_count)
      type(error_type), allocatable :: error

      values = 0.0_wp
      ctx%has_result = .false.
      ctx%has_fields = .false.
      if (usable(ctx, error)) then
         if (ctx%keep_fields) then
            call ctx%solver%solve_kinematic(state, contact_load_type(load_mode, load), &
               ctx%result, error, ctx%fields)
            ctx%has_fields = .not. allocated(error)
         else
            call ctx%solver%solve_kinematic(state, contact_load_type(load_mode, load), &
               ctx%result, error)
         end if
         if (.not. allocated(error)) then
            ctx%has_result = .true.
            call kinematic_values(ctx%result, values)
         end if
      end if
      stat = record(ctx, error)
   end function context_solve_kinematic

   !> The flat values of patch k of the last solve ([[patch_values]]).
   integer function context_patch(ctx, k, values) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> The patch values (patch_value_count; zero on failure).
      real(wp), intent(out) :: values(patch_value_count)
      type(error_type), allocatable :: error

      values = 0.0_wp
      call check_patch_index(ctx, k, error)
      if (.not. allocated(error)) call patch_values(ctx%result%patch(k), values)
      stat = record(ctx, error)
   end function context_patch

   !> Patch k of the last solve in the kinematic layout ([[kinematic_values]]): its values in
   !> 1–17 and 26–29 (creepages and x_track), the result's counts and totals in 18–25.
   integer function context_patch_kinematic(ctx, k, values) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> The values (kinematic_value_count; zero on failure).
      real(wp), intent(out) :: values(kinematic_value_count)
      type(error_type), allocatable :: error

      values = 0.0_wp
      call check_patch_index(ctx, k, error)
      if (.not. allocated(error)) call kinematic_values(ctx%result, values, k)
      stat = record(ctx, error)
   end function context_patch_kinematic

   !> The size of patch k's element fields after the last solve: nx elements per strip (along
   !> the rolling direction) and ny strips. 0 × 0 for a patch that carries no load (found by the
   !> contact search but not loaded, or loaded with nothing). An error unless the last solve
   !> kept its fields (option `output%fields`).
   integer function context_field_size(ctx, k, nx, ny) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> Elements per strip and strips (0 on failure).
      integer, intent(out) :: nx, ny
      type(error_type), allocatable :: error

      nx = 0
      ny = 0
      call check_fields(ctx, k, error)
      if (.not. allocated(error)) call field_shape(ctx, k, nx, ny)
      stat = record(ctx, error)
   end function context_field_size

   !> Patch k's element fields after the last solve, as arrays (nx, ny) in Fortran order: element
   !> (j, i) is element j (from the leading edge) of strip i. nx and ny must be the sizes of
   !> [[context_field_size]]. Coordinates in the patch's contact frame (mm): x along the rolling
   !> direction from the strip's middle, y the strip centre across the patch from its reference
   !> point; area the element area (mm², so that Σ px·area = F_x); pressures and tractions on the
   !> wheel (MPa); slip |s| in slip elements; state 0 exterior, 1 adhesion, 2 slip.
   integer function context_fields(ctx, k, nx, ny, x, y, area, pn, px, py, slip, state) &
         result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> The field sizes (those of context_field_size).
      integer, intent(in) :: nx, ny
      !> Element centres and areas (mm, mm²); zero on failure.
      real(wp), intent(out) :: x(nx, ny), y(nx, ny), area(nx, ny)
      !> Normal pressure, tractions (MPa) and slip magnitude; zero on failure.
      real(wp), intent(out) :: pn(nx, ny), px(nx, ny), py(nx, ny), slip(nx, ny)
      !> Element state: 0 exterior, 1 adhesion, 2 slip.
      integer, intent(out) :: state(nx, ny)
      type(error_type), allocatable :: error
      integer :: mx, my, i

      x = 0.0_wp; y = 0.0_wp; area = 0.0_wp; pn = 0.0_wp; px = 0.0_wp; py = 0.0_wp
      slip = 0.0_wp
      state = 0
      call check_fields(ctx, k, error)
      if (.not. allocated(error)) then
         call field_shape(ctx, k, mx, my)
         if (nx /= mx .or. ny /= my) call fatal_error(error, 'fields of patch '//str_int(k)// &
            ': arrays of '//str_int(nx)//' x '//str_int(ny)//' given, the fields are '// &
            str_int(mx)//' x '//str_int(my)//' (ask their size first)', stat_usage)
      end if
      if (.not. allocated(error) .and. nx > 0 .and. ny > 0) then
         associate (t => ctx%fields%tangential(k))
            x = t%x
            do i = 1, ny
               y(:, i) = t%y(i)
               area(:, i) = t%dx(i)*t%dy
            end do
            pn = t%pn
            px = t%px
            py = t%py
            slip = t%slip
            state = int(t%state)
         end associate
      end if
      stat = record(ctx, error)
   end function context_fields

   !> The points of the wheel (kind = profile_kind_wheel, 1) or rail (profile_kind_rail, 0)
   !> profile of the contact, as it was created (read and cleaned; mm, canonical form), e.g. to
   !> pass them to [[context_create_arrays]] after a change. A MiniProf wheel, whose origin is at
   !> its flange back, comes moved by −70 mm to the origin arrays have (tape circle; flange back
   !> at −70 mm, the default flange-back position: shcontact_profile_points' tape_circle_origin),
   !> so that the arrays with the default track give the contact of the file. n receives the number of points
   !> also when it exceeds the capacity of y and z (then nothing is copied and the status is 1).
   integer function context_get_profile(ctx, kind, n, y, z) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> profile_kind_wheel (1) or profile_kind_rail (0).
      integer, intent(in) :: kind
      !> The number of points (0 on failure other than a small capacity).
      integer, intent(out) :: n
      !> The points (their size is the capacity); zero beyond n.
      real(wp), intent(out) :: y(:), z(:)
      type(error_type), allocatable :: error
      type(profile_type) :: wheel, rail

      n = 0
      y = 0.0_wp
      z = 0.0_wp
      if (kind /= profile_kind_wheel .and. kind /= profile_kind_rail) then
         call fatal_error(error, 'profile kind = '//str_int(kind)//': expected 1 (wheel) or '// &
            '0 (rail)', stat_usage)
      else if (usable(ctx, error)) then
         call ctx%solver%get_profiles(wheel, rail)
         wheel = tape_circle_origin(wheel)
         if (kind == profile_kind_rail) wheel = rail
         n = wheel%size()
         if (n > min(size(y), size(z))) then
            call fatal_error(error, 'profile points: the '//trim(merge('wheel', 'rail ', &
               kind == profile_kind_wheel))//' profile has '//str_int(n)//' points, the '// &
               'arrays hold '//str_int(min(size(y), size(z))), stat_usage)
         else
            y(1:n) = wheel%y
            z(1:n) = wheel%z
         end if
      end if
      stat = record(ctx, error)
   end function context_get_profile

   !> An error unless the last solve kept its fields and has a patch k.
   subroutine check_fields(ctx, k, error)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k
      type(error_type), allocatable, intent(out) :: error
      if (ctx%has_result .and. .not. ctx%has_fields) then
         call fatal_error(error, "fields: the last solve kept none; set the option "// &
            "'output%fields' to 'all' before solving", stat_usage)
         return
      end if
      call check_patch_index(ctx, k, error)
   end subroutine check_fields

   !> The element field size of patch k (0 × 0 when it carries no load).
   pure subroutine field_shape(ctx, k, nx, ny)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k
      integer, intent(out) :: nx, ny
      nx = 0
      ny = 0
      if (k > ctx%fields%n_patches) return
      nx = ctx%fields%tangential(k)%nx
      ny = ctx%fields%tangential(k)%ny
   end subroutine field_shape

   !> An error unless the context holds a result with a patch k.
   subroutine check_patch_index(ctx, k, error)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k
      type(error_type), allocatable, intent(out) :: error
      if (.not. ctx%has_result) then
         call fatal_error(error, 'patch values: no result yet (the last solve failed or none '// &
            'was made)', stat_usage)
      else if (k < 1 .or. k > min(ctx%result%n_patches, max_patches)) then
         call fatal_error(error, 'patch '//str_int(k)//': expected 1 to '// &
            str_int(ctx%result%n_patches)//' (the patches of the last solve)', stat_usage)
      end if
   end subroutine check_patch_index

   !> The message of the last operation ('' after a success).
   pure function context_message(ctx) result(message)
      !> The context.
      type(contact_context_type), intent(in) :: ctx
      character(len=:), allocatable :: message
      message = ctx%message(1:ctx%message_len)
   end function context_message

   !> Record a failure that happened outside the context (a bad argument of a flat call).
   integer function context_fail(ctx, message, stat) result(status)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> What went wrong.
      character(len=*), intent(in) :: message
      !> The status code.
      integer, intent(in) :: stat
      type(error_type), allocatable :: error
      call fatal_error(error, message, stat)
      status = record(ctx, error)
   end function context_fail

   !> True when the solver is ready; otherwise set error.
   logical function usable(ctx, error)
      type(contact_context_type), intent(in) :: ctx
      type(error_type), allocatable, intent(out) :: error
      usable = ctx%solver%is_ready()
      if (.not. usable) call fatal_error(error, 'contact not initialised: its creation failed ('// &
         'see the message of that call) or it was destroyed', stat_usage)
   end function usable

   !> Keep the status and message of an operation; return the status (0 on success).
   integer function record(ctx, error) result(stat)
      type(contact_context_type), intent(inout) :: ctx
      type(error_type), allocatable, intent(in) :: error
      if (.not. allocated(error)) then
         ctx%stat = 0
         ctx%message_len = 0
      else
         ctx%stat = error%stat
         ctx%message_len = min(len(error%message), message_capacity)
         ctx%message(1:ctx%message_len) = error%message(1:ctx%message_len)
      end if
      stat = ctx%stat
   end function record

   !> A real option value from text.
   subroutine read_real(key, text, value, error)
      character(len=*), intent(in) :: key, text
      real(wp), intent(inout) :: value
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      real(wp) :: x
      logical :: halting, overflow
      ! 1e309 overflows inside the conversion: refused, never trapped (debug builds halt).
      call ieee_get_halting_mode(ieee_overflow, halting)
      call ieee_set_halting_mode(ieee_overflow, .false.)
      call ieee_set_flag(ieee_overflow, .false.)
      read (text, *, iostat=stat) x
      call ieee_get_flag(ieee_overflow, overflow)
      call ieee_set_flag(ieee_overflow, .false.)
      call ieee_set_halting_mode(ieee_overflow, halting)
      if (stat == 0) then
         if (overflow .or. .not. ieee_is_finite(x)) stat = 1
      end if
      if (stat /= 0) then
         call fatal_error(error, "option "//key//" = '"//trim(text)// &
            "': expected a finite number", &
            stat_invalid_input)
         return
      end if
      value = x
   end subroutine read_real

   !> An integer option value from text.
   subroutine read_int(key, text, value, error)
      character(len=*), intent(in) :: key, text
      integer, intent(inout) :: value
      type(error_type), allocatable, intent(out) :: error
      integer :: stat, i
      read (text, *, iostat=stat) i
      if (stat /= 0) then
         call fatal_error(error, "option "//key//" = '"//trim(text)//"': expected an integer", &
            stat_invalid_input)
         return
      end if
      value = i
   end subroutine read_int

   !> The value of option `output%fields`: 'all' or '1' keeps the fields of every solve, 'none'
   !> or '0' none (the app's names for all and none of them).
   subroutine read_fields_choice(key, text, keep, error)
      character(len=*), intent(in) :: key, text
      logical, intent(inout) :: keep
      type(error_type), allocatable, intent(out) :: error
      select case (trim(adjustl(to_lower(text))))
      case ('all', '1')
         keep = .true.
      case ('none', '0')
         keep = .false.
      case default
         call fatal_error(error, "option "//key//" = '"//trim(text)//"': expected 'all' "// &
            "(or 1: keep the element fields of every solve) or 'none' (or 0)", &
            stat_invalid_input)
      end select
   end subroutine read_fields_choice

   !> The accepted keys, comma-separated.
   pure function key_list() result(text)
      character(len=:), allocatable :: text
      integer :: i
      text = trim(option_keys(1))
      do i = 2, size(option_keys)
         text = text//', '//trim(option_keys(i))
      end do
   end function key_list

end module shcontact_api_context
