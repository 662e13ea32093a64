!> One case, stage by stage: configuration → profiles → geometry (contact search, strip tables)
!> → normal solution → tangential solution → summary.
!>
!> [[prepare_run]] does everything that is the same for every case of a run (reading and
!> smoothing the profiles, placing the rail, and translating the options with the C / Fortran 77
!> handles' one translation, shcontact_api_settings' library_setup). A sweep then solves the
!> geometry and the normal problem once per distinct (t_y, roll, load) ([[solve_stage]]) and the
!> tangential problem and the summary once per case ([[solve_case]]), through the stages of
!> shcontact_pipeline_stages that the library's solver object calls too (doc/architecture.md),
!> so a case gives the library's numbers bit for bit. None of these procedures print or touch
!> global state, so cases can be solved by several threads at once.
!>
!> **Prepared workspaces.** Each thread keeps a [[case_workspace_type]]: one FASTSIM_SH
!> workspace per patch, with what it was prepared for (`prepare_fastsim_sh` reads the patch's
!> normal solution, the material and the tangential options, nothing else). [[solve_case]]
!> prepares a patch's workspace again only when one of these differs from the last case's on
!> that thread, then calls `solve_prepared`: the normal solution is named by its stage's key
!> (the run's first case with that t_y, roll and load), the material (with the case's
!> friction) and the options (with the case's bound and spin model) are compared bit for bit,
!> whole. A sweep hands its cases out in grid order, so consecutive cases of a thread mostly
!> share the preparation. The result is that of a fresh preparation, bit for bit.
!>
!> **Kinematic cases** (`&kinematics mode = 'on'`) are solved by the library's solver object
!> ([[solve_kinematic_case]] → `contact_solver_type%solve_kinematic`), so that the program gives
!> exactly what a vehicle code calling the library gets: the yawed contact search, the
!> creepages of the wheelset motion at each patch and the 'additive' spin model live there
!> only. Each thread holds its own copy of the prototype solver prepared by [[prepare_run]]; the
!> solver reuses the geometry and the normal solution of consecutive cases that share them.
module shcontact_case_runner
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_invalid_input, &
      stat_io
   use shcontact_core_strings, only: str_int
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_source, only: load_profile
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_track, only: wheelset_position_type
   use shcontact_geometry_contact, only: prepared_profiles_type, prepare_profiles, &
      find_contact_patches
   use shcontact_geometry_kinematics, only: axle_offset
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_normal_loading, only: normal_contact_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_options, only: tangential_options_type, surface_interface
   use shcontact_tangential_option_registry, only: method_fastsim
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_pipeline_load, only: contact_load_type
   use shcontact_pipeline_result, only: contact_result_type, contact_fields_type, max_patches
   use shcontact_pipeline_stages, only: loaded_count, prepare_normal_stage, solve_normal_stage, &
      solve_patch_stage, summarise_stages, carry_creepage_stage
   use shcontact_input_config, only: case_config_type, case_point_type, load_mode_force
   use shcontact_input_config_types, only: origin
   use shcontact_case_result, only: case_result_type, case_summary
   use shcontact_api_solver, only: contact_solver_type
   use shcontact_api_settings, only: library_setup_type, library_setup, point_load, &
      kinematic_state => config_state
   implicit none
   private

   public :: run_setup_type, stage_type, prepare_run, solve_geometry, solve_stage
   public :: read_case_profiles
   public :: solve_case, case_workspace_type, tangential_patch_type
   public :: solve_kinematic_case, kinematic_state, contact_solver_type

   !> What every case of a run shares.
   type :: run_setup_type
      !> The profiles as read (or built in).
      type(profile_type) :: wheel, rail
      !> Smoothed, placed profiles ready for the contact search.
      type(prepared_profiles_type) :: prepared
      !> Side of the wheel (the lateral shift and roll come with each case).
      type(wheelset_position_type) :: position
      !> Normal and tangential options (bound and spin model come with each case).
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      !> Elastic constants (the friction comes with each case).
      type(material_type) :: material
      !> `load_mode_force`, `load_mode_approach` or `load_mode_vertical` (shcontact_input_config).
      integer :: load_mode = load_mode_force
      !> Kinematic mode: cases are solved by copies of `solver`, prepared with the run's
      !> profiles, track, material and options (bound and friction come with each case).
      logical :: kinematic = .false.
      type(contact_solver_type) :: solver
   end type run_setup_type

   !> Geometry and normal solution of one (t_y, roll, load), shared by the cases that have them.
   type :: stage_type
      !> 0 when solved, else the error status.
      integer :: stat = 0
      !> Why it failed.
      character(len=:), allocatable :: message
      !> The candidate patches.
      type(patch_geometry_type), allocatable :: geometry(:)
      !> The normal solution of each loaded patch.
      type(normal_patch_type), allocatable :: normal(:)
      !> Rigid vertical approach Δz of the wheel (mm), vertical load only.
      real(wp) :: dz = 0.0_wp
   end type stage_type

   !> Words of the bit patterns that key a preparation.
   integer, parameter :: options_words = storage_size(tangential_options_type())/storage_size(0)
   integer, parameter :: material_words = storage_size(material_type())/storage_size(0)

   !> A FASTSIM_SH workspace and what it was prepared for.
   type :: prepared_patch_type
      type(march_workspace_type) :: ws
      !> The key of the stage whose patch's normal solution it holds (0: nothing prepared).
      integer :: stage = 0
      !> The bits of the tangential options and of the material it was prepared with.
      integer :: options(options_words) = 0
      integer :: material(material_words) = 0
   end type prepared_patch_type

   !> A thread's tangential workspaces, one per patch (patch k of a stage is prepared in
   !> patch(k) only), reused from case to case (module text).
   type :: case_workspace_type
      type(prepared_patch_type) :: patch(max_patches)
   end type case_workspace_type

contains

   !> A profile of the case: `&profiles` names, format, mirrors ('auto' leaves them to the
   !> file and its format) and scale (0 likewise).
   subroutine load_case_profile(spec, kind, format, mirror_y, mirror_z, scale, prefix, &
         profile, error, as_read)
      character(len=*), intent(in) :: spec, format, mirror_y, mirror_z, prefix
      integer, intent(in) :: kind
      real(wp), intent(in) :: scale
      type(profile_type), intent(out) :: profile
      type(error_type), allocatable, intent(out) :: error
      !> The points as read, before the clean-up.
      type(profile_type), intent(out), optional :: as_read
      ! Unallocated, they are absent arguments of load_profile.
      logical, allocatable :: flip_y, flip_z
      real(wp), allocatable :: factor
      if (trim(mirror_y) /= 'auto') flip_y = trim(mirror_y) == 'yes'
      if (trim(mirror_z) /= 'auto') flip_z = trim(mirror_z) == 'yes'
      if (scale > 0.0_wp) factor = scale
      call load_profile(spec, kind, profile, error, format, mirror_y=flip_y, mirror_z=flip_z, &
         scale=factor, option_prefix=prefix, as_read=as_read)
   end subroutine load_case_profile

   !> The wheel and rail profiles of a case as a run reads them (`&profiles`: names, formats,
   !> mirrors, scales; read, checked and cleaned), and optionally their points as read.
   subroutine read_case_profiles(config, wheel, rail, error, wheel_read, rail_read)
      !> The validated configuration.
      type(case_config_type), intent(in) :: config
      !> The profiles.
      type(profile_type), intent(out) :: wheel, rail
      !> Set for an unreadable or bad profile.
      type(error_type), allocatable, intent(out) :: error
      !> The points as read, before the clean-up.
      type(profile_type), intent(out), optional :: wheel_read, rail_read
      call load_case_profile(config%profiles%wheel, profile_kind_wheel, &
         config%profiles%wheel_format, config%profiles%wheel_mirror_y, &
         config%profiles%wheel_mirror_z, config%profiles%wheel_scale, '&profiles wheel_', &
         wheel, error, wheel_read)
      if (allocated(error)) then
         call name_setting(error, 'wheel')
         return
      end if
      call load_case_profile(config%profiles%rail, profile_kind_rail, &
         config%profiles%rail_format, config%profiles%rail_mirror_y, &
         config%profiles%rail_mirror_z, config%profiles%rail_scale, '&profiles rail_', &
         rail, error, rail_read)
      if (allocated(error)) call name_setting(error, 'rail')
   contains
      !> A file that cannot be read: the message begins with where the profile was named
      !> ('case.nml:3: &profiles wheel'), unless it is the default's. (Errors in a file's
      !> contents name its line; those of the scale or the format name their option.)
      subroutine name_setting(error, name)
         type(error_type), allocatable, intent(inout) :: error
         character(len=*), intent(in) :: name
         character(len=:), allocatable :: where
         if (error%stat /= stat_io) return
         where = origin(config, 'profiles%'//name)
         if (where /= 'default') call prefix_error(error, where//': &profiles '//name)
      end subroutine name_setting
   end subroutine read_case_profiles

   !> Read the profiles and prepare everything the cases share.
   subroutine prepare_run(config, setup, error)
      !> The validated configuration.
      type(case_config_type), intent(in) :: config
      !> The shared data.
      type(run_setup_type), intent(out) :: setup
      !> Set for unreadable or bad profiles, or profiles that cannot be placed.
      type(error_type), allocatable, intent(out) :: error
      type(library_setup_type) :: lib

      call read_case_profiles(config, setup%wheel, setup%rail, error)
      if (allocated(error)) return

      call library_setup(config, lib, error)
      if (allocated(error)) return
      call prepare_profiles(setup%wheel, setup%rail, lib%track, lib%contact_options, &
         setup%prepared, error)
      if (allocated(error)) return
      setup%position%side = lib%side
      setup%normal = lib%normal
      ! The bound and the spin model of each case replace the configuration's.
      setup%tangential = lib%tangential
      setup%tangential%fields = config%wants_field('pressure') .or. &
         config%wants_field('traction') .or. config%wants_field('state') .or. &
         config%wants_field('slip')
      setup%material = lib%material
      setup%load_mode = config%load%mode
      setup%kinematic = config%is_kinematic()
      if (setup%kinematic) then
         call setup%solver%init(setup%wheel, setup%rail, error, track=lib%track, &
            material=setup%material, side=setup%position%side, &
            contact_options=lib%contact_options, &
            normal_options=setup%normal, tangential_options=setup%tangential)
      end if
   end subroutine prepare_run

   !> One kinematic case through the library's solver object (`solve_kinematic`): the geometry
   !> of the yawed wheelset, the normal problem for the load, and every loaded patch with the
   !> creepages of the wheelset motion at its reference point. `fields` keeps the per-patch
   !> solutions and creepages in the result.
   subroutine solve_kinematic_case(setup, point, solver, result, fields)
      !> Shared data.
      type(run_setup_type), intent(in) :: setup
      !> The case inputs (position, velocities, load, friction, bound).
      type(case_point_type), intent(in) :: point
      !> The thread's solver (a copy of setup%solver), reused from case to case.
      type(contact_solver_type), intent(inout) :: solver
      !> The result (summary%stat > 0 on failure, with a message).
      type(case_result_type), intent(out) :: result
      !> Keep the solutions in the result.
      logical, intent(in) :: fields
      type(error_type), allocatable :: error
      type(material_type) :: material
      type(tangential_options_type) :: options
      type(contact_load_type) :: load
      type(contact_result_type) :: contact
      type(contact_fields_type), allocatable :: copies
      integer :: k, n

      call case_options(setup, point, options, material)
      call solver%set_material(material, error)
      if (.not. allocated(error)) then
         call solver%set_options(error, tangential=options)
      end if
      if (.not. allocated(error)) then
         load = point_load(setup%load_mode, point)
         if (fields) then
            allocate (copies)
            call solver%solve_kinematic(kinematic_state(point), load, contact, error, copies)
         else
            call solver%solve_kinematic(kinematic_state(point), load, contact, error)
         end if
      end if
      if (allocated(error)) then
         result%summary%stat = error%stat
         result%message = error%message
         return
      end if
      result%summary = case_summary(contact)
      if (fields) then
         n = contact%n_loaded
         result%geometry = copies%geometry(1:n)
         result%normal = copies%normal(1:n)
         result%tangential = copies%tangential(1:n)
         result%nu_x = contact%patch(1:n)%nu_x
         result%nu_y = contact%patch(1:n)%nu_y
         result%phi = contact%patch(1:n)%phi
         result%x_track = contact%patch(1:n)%x_track
      end if
   end subroutine solve_kinematic_case

   !> The tangential options and the material of a case: the run's, with the case's bound, spin
   !> model (codes since the configuration was read) and friction. A kinematic solve takes the
   !> spin model 'additive' whatever it is given.
   pure subroutine case_options(setup, point, options, material)
      !> Shared data.
      type(run_setup_type), intent(in) :: setup
      !> The case inputs (bound, spin model, friction).
      type(case_point_type), intent(in) :: point
      !> The case's options and material.
      type(tangential_options_type), intent(out) :: options
      type(material_type), intent(out) :: material
      options = setup%tangential
      options%bound = point%bound
      options%spin_model = point%spin_model
      material = setup%material
      material%friction = point%friction
   end subroutine case_options

   !> The contact patches of one wheelset position.
   subroutine solve_geometry(setup, point, geometry, error)
      !> Shared data.
      type(run_setup_type), intent(in) :: setup
      !> The case inputs (t_y, roll).
      type(case_point_type), intent(in) :: point
      !> The patches, deepest first.
      type(patch_geometry_type), allocatable, intent(out) :: geometry(:)
      !> Set when the profiles do not touch or the search fails.
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_position_type) :: position
      position = setup%position
      position%y_ws = point%t_y
      position%roll = point%roll
      call find_contact_patches(setup%prepared, position, geometry, error)
      if (allocated(error)) return
      if (size(geometry) == 0) call fatal_error(error, 'no contact patch found', stat_invalid_input)
   end subroutine solve_geometry

   !> Normal solution for one (t_y, roll, load) on its geometry. Loading 'force' and
   !> 'approach' act on the first (deepest) patch, 'vertical' on all patches at once
   !> (doc/theory.md §4.6).
   subroutine solve_stage(setup, point, geometry, stage)
      !> Shared data.
      type(run_setup_type), intent(in) :: setup
      !> The case inputs (load).
      type(case_point_type), intent(in) :: point
      !> The patches of this wheelset position.
      type(patch_geometry_type), intent(in) :: geometry(:)
      !> The result; stage%stat > 0 on failure.
      type(stage_type), intent(out) :: stage
      type(normal_contact_type), allocatable :: contacts(:)
      type(contact_load_type) :: load
      type(error_type), allocatable :: error
      integer :: n, n_prepared, used

      stage%geometry = geometry
      load = point_load(setup%load_mode, point)
      n = loaded_count(load, size(geometry))
      allocate (contacts(n), stage%normal(n))
      n_prepared = 0
      call prepare_normal_stage(geometry, setup%normal, setup%material, contacts, n_prepared, n, &
         error, interface=setup%tangential%contact_surface == surface_interface)
      if (failed(stage, error)) return
      call solve_normal_stage(contacts, load, stage%normal, stage%dz, error, used=used, &
         strips=.true.)
      if (failed(stage, error)) return
      ! A shared normal force that the first patch carries alone loads it alone.
      if (used < n) stage%normal = stage%normal(1:used)
   end subroutine solve_stage

   !> Record an error in the stage; true when there was one.
   logical function failed(stage, error)
      type(stage_type), intent(inout) :: stage
      type(error_type), allocatable, intent(in) :: error
      failed = allocated(error)
      if (.not. failed) return
      stage%stat = error%stat
      stage%message = error%message
   end function failed

   !> The tangential solution of one case on its stage, and its summary. `fields` keeps the
   !> geometry, normal and tangential solutions in the result.
   subroutine solve_case(setup, point, stage, stage_key, ws, tangential, result, fields)
      !> Shared data.
      type(run_setup_type), intent(in) :: setup
      !> The case inputs (friction, bound, spin model, creepages).
      type(case_point_type), intent(in) :: point
      !> Its geometry and normal solution.
      type(stage_type), intent(in) :: stage
      !> The stage's name in the run, the same for every stage with the same normal solution
      !> and different for every other (the sweep: its first case); 0 prepares afresh.
      integer, intent(in) :: stage_key
      !> The thread's tangential workspaces, reused from case to case (module text).
      type(case_workspace_type), intent(inout) :: ws
      !> The thread's tangential solutions, one per patch, reused from case to case.
      type(tangential_patch_type), allocatable, intent(inout) :: tangential(:)
      !> The result (summary%stat > 0 on failure, with a message).
      type(case_result_type), intent(out) :: result
      !> Keep the solutions in the result.
      logical, intent(in) :: fields
      type(error_type), allocatable :: error
      type(tangential_options_type) :: options
      type(material_type) :: material
      type(creepage_type) :: creepage, creepages(max_patches)
      type(contact_result_type) :: contact
      integer :: k, n

      if (stage%stat /= 0) then
         result%summary%stat = stage%stat
         result%message = stage%message
         return
      end if
      call case_options(setup, point, options, material)
      creepage = creepage_type(point%nu_x, point%nu_y, point%phi)
      n = size(stage%normal)
      if (allocated(tangential)) then
         if (size(tangential) < n) deallocate (tangential)
      end if
      if (.not. allocated(tangential)) allocate (tangential(n))
      call carry_creepage_stage(stage%geometry, stage%normal, creepage, options%spin_model, &
         setup%position%side, creepages(1:n), error)
      do k = 1, n
         if (allocated(error)) exit
         if (.not. (stage%normal(k)%load > 0.0_wp)) then
            ! A patch that carries nothing (vertical loading) has no tractions.
            tangential(k) = tangential_patch_type()
            cycle
         end if
         call solve_patch(ws%patch(k), stage_key, k, n, stage%normal(k), material, options, &
            creepages(k), tangential(k), error)
      end do
      if (allocated(error)) then
         result%summary%stat = error%stat
         result%message = error%message
         return
      end if
      call summarise_stages(stage%geometry, stage%normal, tangential(1:n), creepages(1:n), &
         setup%position%side, axle_offset(setup%prepared%track), 0.0_wp, stage%dz, &
         material%friction, contact)
      result%summary = case_summary(contact)
      if (fields) then
         result%geometry = stage%geometry
         result%normal = stage%normal
         result%tangential = tangential(1:n)
      end if
   end subroutine solve_case

   !> Loaded patch k of n on its prepared workspace ([[solve_patch_stage]]'s numbers):
   !> FASTSIM_SH is prepared again only when the stage, the options or the material differ from
   !> the workspace's; classical FASTSIM is solved afresh.
   subroutine solve_patch(prepared, stage_key, k, n, normal, material, options, creepage, &
         tangential, error)
      !> The patch's workspace and what it holds.
      type(prepared_patch_type), intent(inout) :: prepared
      !> The stage's key (0: prepare afresh), the patch number and the number of patches.
      integer, intent(in) :: stage_key, k, n
      !> The patch's normal solution.
      type(normal_patch_type), intent(in) :: normal
      !> The case's material and options.
      type(material_type), intent(in) :: material
      type(tangential_options_type), intent(in) :: options
      !> The case's creepages.
      type(creepage_type), intent(in) :: creepage
      !> The patch's solution.
      type(tangential_patch_type), intent(inout) :: tangential
      !> Set on failure (prefixed with the patch number when n > 1).
      type(error_type), allocatable, intent(out) :: error
      integer :: options_bits(options_words), material_bits(material_words)

      if (options%method == method_fastsim .or. stage_key == 0) then
         prepared%stage = 0
         call solve_patch_stage(prepared%ws, normal, material, creepage, options, tangential, &
            k, n, error)
         return
      end if
      options_bits = transfer(options, options_bits)
      material_bits = transfer(material, material_bits)
      if (prepared%stage /= stage_key .or. any(prepared%options /= options_bits) .or. &
          any(prepared%material /= material_bits)) then
         prepared%stage = 0
         call prepare_fastsim_sh(prepared%ws, normal, material, options, error)
         if (allocated(error)) then
            if (n > 1) call prefix_error(error, 'patch '//str_int(k))
            return
         end if
         prepared%stage = stage_key
         prepared%options = options_bits
         prepared%material = material_bits
      end if
      call solve_prepared(prepared%ws, creepage, tangential, error)
      if (allocated(error) .and. n > 1) call prefix_error(error, 'patch '//str_int(k))
   end subroutine solve_patch

end module shcontact_case_runner
