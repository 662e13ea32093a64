!> A solver with its last result and last status, as the flat interfaces (legacy Fortran entry
!> points, C API) need: every operation takes plain integers, reals and strings and returns an
!> integer status, 0 on success or one of the `stat_*` codes of shcontact_core_error, and keeps
!> the message in the context. The message lives in a fixed buffer, so a successful call
!> allocates nothing here. The context keeps its settings as the app's configuration
!> (shcontact_api_settings): options by key take the case files' one-assignment reader, and
!> every setter gives the solver what the configuration translates to. A wheelset context
!> ([[context_create_wheelset]]) holds both wheels of shcontact_api_wheelset instead.
module shcontact_api_context
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_usage
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: to_lower
   use shcontact_geometry_track, only: track_type, side_left
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, profile_kind_rail
   use shcontact_profile_source, only: profile_from_points
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_api_solver, only: contact_solver_type, contact_result_type, contact_load_type, &
      contact_fields_type
   use shcontact_input_config, only: case_config_type
   use shcontact_input_config_types, only: origin
   use shcontact_tangential_option_registry, only: spin_additive, spin_model_choices
   use shcontact_core_choices, only: choice_name
   use shcontact_api_wheelset, only: wheelset_solver_type, wheelset_result_type
   use shcontact_api_settings, only: library_setup_type, library_setup, set_config_value, &
      split_key, key_use, key_solver, key_fields, key_creation, key_app
   use shcontact_api_values, only: result_value_count, kinematic_value_count, result_values, &
      kinematic_values
   implicit none
   private

   public :: contact_context_type, context_record, context_usable
   public :: context_create, context_create_arrays, context_set_material, context_set_track, &
      context_set_option, context_solve, context_solve_kinematic, context_message, &
      context_fail, context_create_wheelset, context_solve_wheelset

   !> Longest message kept (longer ones are cut).
   integer, parameter :: message_capacity = 1024

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
      !> The settings, as the app's configuration (shcontact_api_settings): every option set
      !> by key, the positional setters' data and the state of a keyed solve.
      type(case_config_type) :: config
      !> A wheelset handle (context_create_wheelset): both wheels, their last result.
      logical :: is_wheelset = .false.
      logical :: wheelset_ready = .false.
      type(wheelset_solver_type), allocatable :: wheelset
      type(wheelset_result_type) :: wheelset_result
      !> Status of the last operation (0: success).
      integer :: stat = 0
      !> Message of the last operation ('' on success).
      character(len=message_capacity) :: message = ''
      integer :: message_len = 0
      !> Why the creation failed ('' when it succeeded), repeated by every later call.
      character(len=:), allocatable :: creation_failure
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
      call start_config(ctx, wheel, rail, side)
      stat = record(ctx, error)
      call keep_creation_failure(ctx, error)
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
      call start_config(ctx, '(arrays)', '(arrays)', side)
      stat = record(ctx, error)
      call keep_creation_failure(ctx, error)
   end function context_create_arrays

   !> Create a wheelset handle: both wheels (shcontact_api_wheelset's wheelset_solver_type) from
   !> profile names (`builtin:NAME` or files), default track, material and options; the options
   !> of [[context_set_option]] apply to both wheels.
   integer function context_create_wheelset(ctx, wheel, rail) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Wheel and rail profile (right-side canonical form; the left wheel is its mirror image).
      character(len=*), intent(in) :: wheel, rail
      type(error_type), allocatable :: error

      ctx%has_result = .false.
      ctx%has_fields = .false.
      ctx%is_wheelset = .true.
      if (.not. allocated(ctx%wheelset)) allocate (ctx%wheelset)
      call ctx%wheelset%init(trim(wheel), trim(rail), error)
      ctx%wheelset_ready = .not. allocated(error)
      call start_config(ctx, wheel, rail, 1)
      stat = record(ctx, error)
      call keep_creation_failure(ctx, error)
   end function context_create_wheelset

   !> Solve both wheels of a wheelset handle for one wheelset state (track frame) and loads;
   !> totals receives the forces on the wheelset (N, true track frame) and their moment about
   !> the vertical axis (N·mm): F_x, F_y, F_z, M_z (zeros on failure).
   integer function context_solve_wheelset(ctx, state, load_mode, load_right, load_left, &
         totals) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Wheelset position and velocities (track frame; mm, mm/s, rad, rad/s).
      type(wheelset_state_type), intent(in) :: state
      !> 1: normal force (N), 2: vertical force (N), 3: approach (mm), of each wheel.
      integer, intent(in) :: load_mode
      !> The force or approach of the right and of the left wheel.
      real(wp), intent(in) :: load_right, load_left
      !> F_x, F_y, F_z (N), M_z (N·mm).
      real(wp), intent(out) :: totals(4)
      type(error_type), allocatable :: error

      totals = 0.0_wp
      ctx%has_result = .false.
      if (.not. ctx%is_wheelset) then
         call fatal_error(error, 'a one-wheel handle: create a wheelset handle '// &
            '(shcontact_create_wheelset, shc_create_ws) for the wheelset call', stat_usage)
      else if (usable(ctx, error, wheelset=.true.)) then
         call check_kinematic_spin_model(ctx, error)
      end if
      if (.not. allocated(error)) then
         call ctx%wheelset%solve(state, contact_load_type(load_mode, load_right), &
            contact_load_type(load_mode, load_left), ctx%wheelset_result, error)
         if (.not. allocated(error)) then
            ctx%has_result = .true.
            totals = [ctx%wheelset_result%fx, ctx%wheelset_result%fy, ctx%wheelset_result%fz, &
               ctx%wheelset_result%mz]
         end if
      end if
      stat = record(ctx, error)
   end function context_solve_wheelset

   !> Set the shear modulus G (MPa), Poisson's ratio ν and the friction coefficient μ.
   integer function context_set_material(ctx, shear_modulus, poisson, friction) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> G (MPa), ν, μ.
      real(wp), intent(in) :: shear_modulus, poisson, friction
      type(error_type), allocatable :: error

      type(case_config_type) :: config

      if (usable(ctx, error, wheelset=.true.)) then
         config = ctx%config
         config%material = material_type(shear_modulus, poisson, friction)
         call apply_config(ctx, config, error, material_only=.true.)
         if (.not. allocated(error)) ctx%config = config
      end if
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

      type(case_config_type) :: config

      if (usable(ctx, error, wheelset=.true.)) then
         config = ctx%config
         config%track%gauge = gauge
         config%track%gauge_height = gauge_height
         config%track%inclination = inclination
         config%track%rail_canted = rail_canted
         config%track%flange_back_distance = flange_back_distance
         config%track%flange_back_position = flange_back_position
         config%track%nominal_radius = nominal_radius
         call apply_config(ctx, config, error)
         if (.not. allocated(error)) ctx%config = config
      end if
      stat = record(ctx, error)
   end function context_set_track

   !> Set one option by its name in the app's case files (`group%variable`, any variable of the
   !> namelist's variable table but the sweep's) and its value as text, as on the app's command
   !> line (`--set`), e.g. ('tangential%bound', 'ellipsoidal') or ('normal%n_strips', '200'):
   !> the namelist's single-assignment reader sets it in the handle's configuration, which goes
   !> to the solver as the app translates it (shcontact_api_settings). Keys of the track,
   !> material, smoothing and the normal and tangential options change the solver; keys of
   !> `&position`, `&kinematics`, `&load` and `&creepage` the state of [[context_solve_state]];
   !> `output%fields` ('all' or 1, 'none' or 0) whether solves keep their element fields.
   !> Profile files and track%side are given at creation; the output file, its format and the
   !> sweep are the app's. Nothing changes on error.
   integer function context_set_option(ctx, key, value) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Option name (case-insensitive).
      character(len=*), intent(in) :: key
      !> Its value.
      character(len=*), intent(in) :: value
      type(error_type), allocatable :: error
      type(case_config_type) :: config
      character(len=:), allocatable :: group, name
      logical :: keep

      if (.not. usable(ctx, error, wheelset=.true.)) then
         stat = record(ctx, error)
         return
      end if
      config = ctx%config
      call set_config_value(config, key, value, error)
      if (.not. allocated(error)) then
         call split_key(key, group, name)
         select case (key_use(group, name))
         case (key_solver)
            call apply_config(ctx, config, error, material_only=group == 'material')
         case (key_fields)
            keep = ctx%keep_fields
            call read_fields_choice(group//'%'//name, value, keep, error)
            ! A wheelset handle returns no fields (its field calls are refused): keeping them
            ! would only cost time.
            if (.not. allocated(error) .and. keep .and. ctx%is_wheelset) call fatal_error( &
               error, 'option '//group//'%'//name//': a wheelset handle returns no element '// &
               'fields (shcontact_field_size, shcontact_fields and shcontact_get_field take '// &
               'a one-wheel handle); create one per wheel for fields', stat_usage)
            if (.not. allocated(error)) ctx%keep_fields = keep
         case (key_creation)
            call fatal_error(error, 'option '//group//'%'//name//': given when the contact '// &
               'is created (shcontact_create, shc_create: profile names and side)', &
               stat_invalid_input)
         case (key_app)
            call fatal_error(error, 'option '//group//'%'//name//": the app's only (its "// &
               'output file or sweep); a handle returns its results to the caller', &
               stat_invalid_input)
         end select
      end if
      if (.not. allocated(error)) ctx%config = config
      stat = record(ctx, error)
   end function context_set_option

   !> Give the solver (or both wheels of a wheelset handle) the data of a configuration:
   !> only what changed is set again (a new track or contact-search option prepares the
   !> profiles again).
   subroutine apply_config(ctx, config, error, material_only)
      type(contact_context_type), intent(inout) :: ctx
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      !> Only the material changed (the library takes the configuration's material_type as it
      !> is): the solver, or both wheels of a wheelset, just get it, with no other comparison
      !> (a few µs).
      logical, intent(in), optional :: material_only
      type(library_setup_type) :: setup, old
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      type(wheelset_solver_type), allocatable :: wheelset

      call library_setup(config, setup, error)
      if (allocated(error)) return
      if (present(material_only)) then
         if (material_only) then
            ! Both wheels of a wheelset handle too: the profiles are not read again (a
            ! vehicle code may change the friction at every step).
            if (ctx%is_wheelset) then
               call ctx%wheelset%set_material(setup%material, error)
            else
               call ctx%solver%set_material(setup%material, error)
            end if
            return
         end if
      end if
      call library_setup(ctx%config, old, error)
      if (allocated(error)) return
      if (ctx%is_wheelset) then
         ! Both wheels changed in a copy, kept only if that succeeds: a refused value leaves the
         ! handle as it was (nothing changes on error). The profiles as first read are prepared
         ! again; the files are not read again (they may have moved or changed since).
         allocate (wheelset, source=ctx%wheelset)
         if (differ(setup%track, old%track) .or. &
             differ(setup%contact_options, old%contact_options)) &
            call wheelset%set_track(error, track=setup%track, &
            contact_options=setup%contact_options)
         if (.not. allocated(error) .and. (differ(setup%normal, old%normal) .or. &
             differ(setup%tangential, old%tangential))) &
            call wheelset%set_options(error, normal=setup%normal, tangential=setup%tangential)
         if (.not. allocated(error)) call wheelset%set_material(setup%material, error)
         if (allocated(error)) return
         ctx%has_result = .false.
         call move_alloc(wheelset, ctx%wheelset)
         ctx%wheelset_ready = .true.
         return
      end if
      if (differ(setup%track, old%track) .or. &
          differ(setup%contact_options, old%contact_options)) then
         call ctx%solver%set_track(error, track=setup%track, &
            contact_options=setup%contact_options)
         if (allocated(error)) return
      end if
      call ctx%solver%get_options(normal, tangential)
      if (differ(setup%normal, normal) .or. differ(setup%tangential, tangential)) then
         call ctx%solver%set_options(error, normal=setup%normal, tangential=setup%tangential)
         if (allocated(error)) return
      end if
      call ctx%solver%set_material(setup%material, error)
   end subroutine apply_config

   !> True when two option objects (derived types without allocatable parts) differ in any
   !> component: compared as list-directed text, which shows every component (no padding).
   logical function differ(a, b)
      class(*), intent(in) :: a, b
      character(len=2048) :: ta, tb
      ta = ''
      tb = ''
      select type (a)
      type is (track_type)
         write (ta, *) a
      type is (contact_options_type)
         write (ta, *) a
      type is (normal_options_type)
         write (ta, *) a
      type is (tangential_options_type)
         write (ta, *) a
      end select
      select type (b)
      type is (track_type)
         write (tb, *) b
      type is (contact_options_type)
         write (tb, *) b
      type is (normal_options_type)
         write (tb, *) b
      type is (tangential_options_type)
         write (tb, *) b
      end select
      differ = ta /= tb
   end function differ

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
      if (usable(ctx, error)) call check_kinematic_spin_model(ctx, error)
      if (.not. allocated(error)) then
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

   !> A kinematic call takes the spin of every strip from the wheelset motion (the additive
   !> model, doc/kinematics.md): a spin model set otherwise on the handle is refused, as the
   !> program refuses it in kinematic mode, rather than ignored.
   subroutine check_kinematic_spin_model(ctx, error)
      type(contact_context_type), intent(in) :: ctx
      type(error_type), allocatable, intent(out) :: error
      if (origin(ctx%config, 'tangential%spin_model') == 'default' .or. &
         ctx%config%tangential%spin_model == spin_additive) return
      call fatal_error(error, "tangential%spin_model = '"// &
         choice_name(spin_model_choices, ctx%config%tangential%spin_model)// &
         "': the kinematic call needs spin_model = 'additive' (the rigid slip of the wheelset "// &
         "motion carried to each strip); set 'additive' for kinematic calls", stat_invalid_input)
   end subroutine check_kinematic_spin_model

   !> The configuration of a new contact: the defaults, its profile names and side, and the
   !> track the solver took (a MiniProf wheel's flange back at 0).
   subroutine start_config(ctx, wheel, rail, side)
      type(contact_context_type), intent(inout) :: ctx
      character(len=*), intent(in) :: wheel, rail
      integer, intent(in) :: side
      type(track_type) :: track
      ctx%config = case_config_type()
      ctx%config%profiles%wheel = wheel
      ctx%config%profiles%rail = rail
      ctx%config%track%side = side
      if (ctx%is_wheelset) then
         ! The options of a wheelset handle create both wheels again from this configuration.
         if (.not. ctx%wheelset_ready) return
         track = ctx%wheelset%get_track()
      else
         if (.not. ctx%solver%is_ready()) return
         track = ctx%solver%get_track()
      end if
      ctx%config%track%flange_back_position = track%flange_back_position
   end subroutine start_config

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

   !> True when the contact (solver or wheelset) is ready; otherwise set error.
   logical function context_usable(ctx, error, wheelset)
      !> The context.
      type(contact_context_type), intent(in) :: ctx
      !> Set when it is not.
      type(error_type), allocatable, intent(out) :: error
      !> The call also takes a wheelset handle (default .true.; .false.: a one-wheel call, which
      !> a wheelset handle refuses).
      logical, intent(in), optional :: wheelset
      logical :: both
      both = .true.
      if (present(wheelset)) both = wheelset
      context_usable = usable(ctx, error, wheelset=both)
   end function context_usable

   !> Keep the status and message of an operation; return the status (0 on success).
   integer function context_record(ctx, error) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> The error of the operation (unallocated on success).
      type(error_type), allocatable, intent(in) :: error
      stat = record(ctx, error)
   end function context_record

   !> True when the solver is ready; otherwise set error.
   logical function usable(ctx, error, wheelset)
      type(contact_context_type), intent(in) :: ctx
      type(error_type), allocatable, intent(out) :: error
      !> The call also takes a wheelset handle (default: a one-wheel handle only).
      logical, intent(in), optional :: wheelset
      logical :: both
      both = .false.
      if (present(wheelset)) both = wheelset
      if (ctx%is_wheelset .and. .not. both) then
         usable = .false.
         call fatal_error(error, 'a wheelset handle (shcontact_create_wheelset, shc_create_ws) '// &
            'takes the wheelset calls (shcontact_solve_wheelset, shc_solve_ws; doc/api.md), '// &
            'not the one-wheel ones', stat_usage)
         return
      end if
      usable = ctx%solver%is_ready() .or. (ctx%is_wheelset .and. ctx%wheelset_ready)
      if (usable) return
      if (allocated(ctx%creation_failure)) then
         call fatal_error(error, 'contact not initialised: its creation failed: '// &
            ctx%creation_failure, stat_usage)
      else
         call fatal_error(error, 'contact not initialised: its creation failed (see the '// &
            'message of that call) or it was destroyed', stat_usage)
      end if
   end function usable

   !> Remember why a creation failed, so that every later call on the handle says it (a
   !> vehicle code that only checks its solve calls still reads the cause).
   subroutine keep_creation_failure(ctx, error)
      type(contact_context_type), intent(inout) :: ctx
      type(error_type), allocatable, intent(in) :: error
      if (allocated(ctx%creation_failure)) deallocate (ctx%creation_failure)
      if (allocated(error)) ctx%creation_failure = error%message
   end subroutine keep_creation_failure

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

   !> The value of option `output%fields`: 'all' or '1' keeps the fields of every solve, 'none'
   !> or '0' none (the app's names for all and none of them).
   subroutine read_fields_choice(key, text, keep, error)
      character(len=*), intent(in) :: key, text
      logical, intent(inout) :: keep
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: word
      ! Quotes optional, as for every text option (doc/api.md): 'all' or all.
      word = trim(adjustl(to_lower(text)))
      if (len(word) >= 2) then
         if ((word(1:1) == "'" .or. word(1:1) == '"') .and. word(len(word):) == word(1:1)) &
            word = trim(adjustl(word(2:len(word) - 1)))
      end if
      select case (word)
      case ('all', '1', 'true', '.true.')
         keep = .true.
      case ('none', '0', 'false', '.false.')
         keep = .false.
      case default
         call fatal_error(error, "option "//key//" = '"//trim(text)//"': expected 'all' "// &
            "(or 1: keep the element fields of every solve) or 'none' (or 0)", &
            stat_invalid_input)
      end select
   end subroutine read_fields_choice

end module shcontact_api_context
