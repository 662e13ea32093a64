!> The modern Fortran API: one solver object per wheel–rail contact (one wheel), created once and
!> called for every wheel position, load and creepage set (issue 8).
!>
!> [[contact_solver_type]] holds the prepared profiles (smoothing splines, placed rail, dense
!> samples), the patch geometry, the prepared normal problems, the normal and tangential solutions
!> and the tangential workspace (a cache over the pipeline's stages, shcontact_pipeline_cache).
!> [[solve]] runs the stages of shcontact_pipeline_stages, the same the app's case runner
!> (`src/shcontact/case/runner.f90`) calls (doc/architecture.md):
!>
!> 1. contact search at (t_y, roll) → candidate patches, deepest first;
!> 2. normal problem: a prescribed normal force or approach on the first (deepest) patch, a
!>    prescribed vertical wheel load shared by all patches through one rigid approach
!>    (doc/theory.md §4.5–4.6), or a normal force of the wheel's contact shared by its patches
!>    through one rigid approach (load_shared_force, doc/lobes.md);
!> 3. tangential problem of every loaded patch with the prescribed creepages: given at the
!>    first (deepest) patch's reference point, the geometric contact point (doc/theory.md
!>    decision 13), and carried to every other loaded patch's reference point by the rigid slip
!>    (shcontact_pipeline_stages's carry_creepage_stage, doc/lobes.md); forces on the wheel
!>    (decision 2);
!> 4. summary: the most loaded ("main") patch, every patch, and the totals in the track frame.
!>
!> **The call path.** [[solve]] prints nothing, opens no file, touches no global state (the
!> library has none), so distinct solver objects can be used from several threads at once.
!> Everything it needs lives in the object: the tangential workspace grows to its size at the first
!> call and is then reused. The object remembers the last position and load: a call at the same
!> (t_y, roll) reuses the geometry, and one with the same load too reuses the normal solution
!> (creepage or friction sweeps cost only the tangential march). A call allocates nothing once the
!> workspaces are large enough: the contact search fills a reused contact_patches_type whose
!> tables only grow, and the prepared normal problems read those tables in place and only grow
!> too, so after the first call only a position needing longer tables than any before allocates
!> (see doc/api.md). Asking for the fields in some calls and not in others reallocates the element
!> fields when the choice changes; the geometry fields follow the table lengths.
module shcontact_api_solver
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_no_contact, &
      stat_usage
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_ranges, only: max_grid_cells, check_range
   use shcontact_core_material, only: material_type, check_material
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_source, only: load_profile
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_track, only: track_type, side_right, side_left
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      prepare_profiles, extract_patch
   use shcontact_geometry_kinematics, only: wheelset_state_type, check_wheelset_state, side_state
   use shcontact_normal_options, only: normal_options_type, check_normal_options
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options, &
      spin_additive
   use shcontact_tangential_creepage, only: creepage_type, check_creepage
   use shcontact_pipeline_load, only: contact_load_type, load_normal_force, load_vertical_force, &
      load_approach, load_vertical_position, load_shared_force, load_mode_name, load_mode_names
   use shcontact_pipeline_result, only: contact_result_type, patch_result_type, &
      contact_fields_type, max_patches
   use shcontact_pipeline_cache, only: contact_cache_type, update_geometry, update_normal, &
      solve_patch, summarise, copy_fields, same, forget_normal
   use shcontact_pipeline_balance, only: kinematic_contact, kinematic_tangential
   use shcontact_pipeline_stages, only: carry_creepage_stage, check_prescribed_approach
   implicit none
   private

   public :: contact_solver_type, contact_load_type, contact_result_type, patch_result_type
   public :: contact_fields_type, load_profile
   public :: load_normal_force, load_vertical_force, load_approach, load_vertical_position, &
      load_shared_force, &
      load_mode_name
   public :: max_patches

   !> One wheel–rail contact: its data, its prepared geometry and all its workspace (the cache
   !> of the pipeline's stages, shcontact_pipeline_cache).
   type :: contact_solver_type
      private
      !> True once [[init]] has succeeded.
      logical :: ready = .false.
      !> The data, the stage results of the last call and the workspace.
      type(contact_cache_type) :: cache
   contains
      !> Create the solver from profiles, or from profile names (`builtin:NAME` or files).
      generic :: init => init_profiles, init_names
      procedure, private :: init_profiles, init_names
      !> Solve one wheel position, load and creepage set.
      procedure :: solve
      !> Solve one wheel from the wheelset's position and velocities.
      procedure :: solve_kinematic
      !> The contact patches of a wheelset state (the geometry of solve_kinematic alone).
      procedure :: locate_kinematic
      !> Change the elastic constants and the friction coefficient.
      procedure :: set_material
      !> Change the normal and/or the tangential options.
      procedure :: set_options
      !> Change the track and/or the contact-search options (prepares the profiles again).
      procedure :: set_track
      !> Current data, for the flat interfaces.
      procedure :: get_material, get_options, get_track, get_contact_options
      !> The wheel and rail profiles as given to init (read and cleaned, before smoothing).
      procedure :: get_profiles
      !> True once init has succeeded.
      procedure :: is_ready
   end type contact_solver_type

contains

   !> Create the solver from profiles: check everything and prepare the profiles (smoothing,
   !> rail placement, sampling) once for all calls of [[solve]].
   subroutine init_profiles(self, wheel, rail, error, track, material, side, contact_options, &
         normal_options, tangential_options)
      !> The solver (any earlier content is replaced).
      class(contact_solver_type), intent(inout) :: self
      !> Wheel and rail profiles (right-side canonical form, doc/theory.md §5.1).
      type(profile_type), intent(in) :: wheel, rail
      !> Set for invalid data; the solver is then not ready.
      type(error_type), allocatable, intent(out) :: error
      !> Track and wheelset dimensions (default: track_type(), the Manchester benchmark; with a
      !> MiniProf wheel, whose origin is at its flange back, flange_back_position = 0).
      type(track_type), intent(in), optional :: track
      !> G, ν, μ (default: material_type(), the seed's steel with μ = 0.3).
      type(material_type), intent(in), optional :: material
      !> side_right (default) or side_left.
      integer, intent(in), optional :: side
      !> Contact-search options (smoothing, table spacing, ...).
      type(contact_options_type), intent(in), optional :: contact_options
      !> Normal options (method, reduction, strips).
      type(normal_options_type), intent(in), optional :: normal_options
      !> Tangential options (method, bound, spin model, elements). Its `fields` component is
      !> ignored: [[solve]] fills the fields when its `fields` argument is present.
      type(tangential_options_type), intent(in), optional :: tangential_options

      call reset(self)
      self%cache%wheel = wheel
      self%cache%rail = rail
      if (present(track)) then
         self%cache%track = track
      else if (wheel%origin_at_flange_back) then
         ! A MiniProf wheel has its origin at the flange back: without a track given, its flange
         ! back is at 0 (the default −70 mm is S1002's, whose origin is on the tape circle), as
         ! in the app (doc/app.md).
         self%cache%track%flange_back_position = 0.0_wp
      end if
      if (present(material)) self%cache%material = material
      if (present(side)) self%cache%side = side
      if (present(contact_options)) self%cache%contact_options = contact_options
      if (present(normal_options)) self%cache%normal_options = normal_options
      if (present(tangential_options)) self%cache%tangential_options = tangential_options
      if (self%cache%side /= side_right .and. self%cache%side /= side_left) then
         call fatal_error(error, 'wheel side = '//str_int(self%cache%side)// &
            ': expected 1 (right) or -1 (left)', stat_invalid_input)
         return
      end if
      call check_finite_data(self%cache%material, self%cache%track, error)
      if (allocated(error)) return
      call check_material(self%cache%material, error)
      if (allocated(error)) return
      call check_normal_options(self%cache%normal_options, error)
      if (allocated(error)) return
      call check_tangential_options(self%cache%tangential_options, error)
      if (allocated(error)) return
      call check_grid_cells(self%cache%normal_options, self%cache%tangential_options, error)
      if (allocated(error)) return
      call prepare_profiles(self%cache%wheel, self%cache%rail, self%cache%track, &
         self%cache%contact_options, self%cache%prepared, error)
      if (allocated(error)) return
      self%ready = .true.
   end subroutine init_profiles

   !> Create the solver from profile names: `builtin:NAME` (S1002, UIC60, UIC60-canted) or a file
   !> name (read, checked and cleaned as the app does). Profiles are read here, never in [[solve]].
   subroutine init_names(self, wheel, rail, error, track, material, side, contact_options, &
         normal_options, tangential_options, wheel_format, rail_format)
      !> The solver (any earlier content is replaced).
      class(contact_solver_type), intent(inout) :: self
      !> Wheel and rail profile: `builtin:NAME` or a file name.
      character(len=*), intent(in) :: wheel, rail
      !> Set for unreadable profiles or invalid data; the solver is then not ready.
      type(error_type), allocatable, intent(out) :: error
      !> See [[init_profiles]].
      type(track_type), intent(in), optional :: track
      !> See [[init_profiles]].
      type(material_type), intent(in), optional :: material
      !> See [[init_profiles]].
      integer, intent(in), optional :: side
      !> See [[init_profiles]].
      type(contact_options_type), intent(in), optional :: contact_options
      !> See [[init_profiles]].
      type(normal_options_type), intent(in), optional :: normal_options
      !> See [[init_profiles]].
      type(tangential_options_type), intent(in), optional :: tangential_options
      !> File formats: 'auto' (default), 'plain', 'simpack', 'miniprof'.
      character(len=*), intent(in), optional :: wheel_format, rail_format
      type(profile_type) :: wheel_profile, rail_profile

      call reset(self)
      call load_profile(wheel, profile_kind_wheel, wheel_profile, error, wheel_format)
      if (allocated(error)) return
      call load_profile(rail, profile_kind_rail, rail_profile, error, rail_format)
      if (allocated(error)) return
      ! Without a track, a MiniProf wheel's flange back is at 0 ([[init_profiles]]).
      call self%init_profiles(wheel_profile, rail_profile, error, track, material, side, &
         contact_options, normal_options, tangential_options)
   end subroutine init_names

   !> Solve one contact: geometry at (t_y, roll), normal problem for the load, tangential problem
   !> for the creepages, and the summary. See the module text for what is reused between calls.
   subroutine solve(self, t_y, roll, load, creepage, result, error, fields)
      !> The solver, from [[init]].
      class(contact_solver_type), intent(inout) :: self
      !> Lateral wheelset shift (mm), CONTACT's Y_WS (doc/theory.md decision 13).
      real(wp), intent(in) :: t_y
      !> Wheelset roll (rad), positive lowers the right wheel.
      real(wp), intent(in) :: roll
      !> The load: a normal force, a vertical wheel load or an approach.
      type(contact_load_type), intent(in) :: load
      !> Creepages at the geometric contact point (ν_x, ν_y, φ in rad/mm), wheel relative to rail:
      !> the first patch's reference point; other loaded patches get the rigid slip at their own.
      type(creepage_type), intent(in) :: creepage
      !> The forces and the per-patch summary.
      type(contact_result_type), intent(out) :: result
      !> Set for bad input (status and message); the solver stays usable.
      type(error_type), allocatable, intent(out) :: error
      !> When present: filled with copies of the geometry, normal and tangential fields.
      type(contact_fields_type), intent(inout), optional :: fields
      type(tangential_options_type) :: options
      type(creepage_type) :: carried(max_patches)
      integer :: k, n

      call check_ready(self, error)
      if (allocated(error)) return
      call check_call(t_y, roll, load, creepage, error)
      if (allocated(error)) return
      call update_geometry(self%cache, t_y, roll, 0.0_wp, error)
      if (allocated(error)) return
      call update_normal(self%cache, load, error, strips=.true.)
      if (allocated(error)) return
      if (load%mode == load_vertical_position) call check_prescribed_approach( &
         'vertical position', load%value, self%cache%normal(1:self%cache%n_loaded), error)
      if (allocated(error)) return

      options = self%cache%tangential_options
      options%fields = present(fields)
      n = self%cache%n_loaded
      call carry_creepage_stage(self%cache%patches%patch(1:n), self%cache%normal(1:n), &
         creepage, options%spin_model, self%cache%side, carried(1:n), error)
      if (allocated(error)) return
      do k = 1, n
         call solve_patch(self%cache, k, carried(k), options, error)
         if (allocated(error)) return
      end do
      call summarise(self%cache, result)
      if (present(fields)) call copy_fields(self%cache, fields)
   end subroutine solve

   !> Solve one wheel from the wheelset's kinematics (doc/theory.md decision 14): the contact
   !> search at the wheelset's lateral shift, roll and yaw (the yawed wheel's contact locus,
   !> shcontact_geometry_kinematics), the normal problem for the load (a vertical wheel load
   !> shared by all patches is what a vehicle code wants), then every loaded patch with the
   !> creepages of the wheelset's rigid-body motion at its own reference point
   !> (shcontact_tangential_rigid_slip) and the 'additive' spin model, which carries that rigid
   !> slip to each strip with the strip's own rolling radius, contact angle and spin. The
   !> result holds each patch's creepages and longitudinal position and the totals in the track
   !> frame (forces on the wheel).
   subroutine solve_kinematic(self, state, load, result, error, fields)
      !> The solver, from [[init]].
      class(contact_solver_type), intent(inout) :: self
      !> Wheelset position and velocities, track frame (mm, mm/s, rad, rad/s).
      type(wheelset_state_type), intent(in) :: state
      !> The load: load_vertical_force (recommended), load_normal_force or load_approach.
      type(contact_load_type), intent(in) :: load
      !> The forces, per patch and in total.
      type(contact_result_type), intent(out) :: result
      !> Set for bad input; the solver stays usable.
      type(error_type), allocatable, intent(out) :: error
      !> When present: filled with copies of the fields.
      type(contact_fields_type), intent(inout), optional :: fields
      type(wheelset_state_type) :: local
      type(tangential_options_type) :: options
      logical :: climbs

      call check_ready(self, error)
      if (allocated(error)) return
      call check_wheelset_state(state, error)
      if (allocated(error)) return
      call check_call(state%y_ws, state%roll, load, creepage_type(), error)
      if (allocated(error)) return
      local = side_state(state, self%cache%side)
      ! The balance iterates on forces only; the fields, when asked for, come from one more
      ! solve of the final state (the totals are the same with and without fields).
      options = self%cache%tangential_options
      options%fields = .false.
      options%spin_model = spin_additive
      ! First with strip tables to the options' kinematic_table_gap (0.25 mm by default; the
      ! approach of a wheel load is 0.05-0.25 mm), then, if a contact reaches the end of those
      ! tables, with the full ones.
      call kinematic_contact(self%cache, state, local, load, options, .true., climbs, error)
      if (allocated(error)) then
         if (error%stat /= stat_no_contact) return
         deallocate (error)
         call kinematic_contact(self%cache, state, local, load, options, .false., climbs, error)
         if (allocated(error)) then
            ! No equilibrium (the wheel climbs): the result holds the best state found.
            if (climbs) call summarise(self%cache, result)
            return
         end if
      end if
      if (load%mode == load_vertical_position) call check_prescribed_approach( &
         'vertical position', load%value, self%cache%normal(1:self%cache%n_loaded), error)
      if (allocated(error)) return
      if (present(fields)) then
         options%fields = .true.
         call kinematic_tangential(self%cache, local, options, error)
         if (allocated(error)) return
      end if
      call summarise(self%cache, result)
      if (present(fields)) call copy_fields(self%cache, fields)
   end subroutine solve_kinematic

   !> The candidate contact patches of a wheelset state, deepest first: the contact search of
   !> [[solve_kinematic]] (yawed wheel's contact locus, true rolling radii) without solving
   !> anything, e.g. to report the geometry of a run. Only the position and the yaw are used.
   subroutine locate_kinematic(self, state, geometry, error)
      !> The solver, from [[init]].
      class(contact_solver_type), intent(inout) :: self
      !> Wheelset position (and velocities), track frame.
      type(wheelset_state_type), intent(in) :: state
      !> Every candidate patch found.
      type(patch_geometry_type), allocatable, intent(out) :: geometry(:)
      !> Set for bad input or when no patch is found.
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type) :: local
      integer :: k

      call check_ready(self, error)
      if (allocated(error)) return
      call check_wheelset_state(state, error)
      if (allocated(error)) return
      call check_call(state%y_ws, state%roll, contact_load_type(load_normal_force, 1.0_wp), &
         creepage_type(), error)
      if (allocated(error)) return
      local = side_state(state, self%cache%side)
      call update_geometry(self%cache, state%y_ws, state%roll, local%yaw, error)
      if (allocated(error)) return
      allocate (geometry(self%cache%patches%count))
      do k = 1, self%cache%patches%count
         call extract_patch(self%cache%patches, k, geometry(k))
      end do
   end subroutine locate_kinematic

   !> An error unless [[init]] has succeeded.
   pure subroutine check_ready(self, error)
      type(contact_solver_type), intent(in) :: self
      type(error_type), allocatable, intent(out) :: error
      if (.not. self%ready) call fatal_error(error, 'contact solver: not initialised (call '// &
         'init first, and check its error)', stat_usage)
   end subroutine check_ready

   !> Reject non-finite positions and creepages and impossible loads before anything computes
   !> with them (the checks use ieee_is_finite, so NaN raises no floating-point exception).
   subroutine check_call(t_y, roll, load, creepage, error)
      real(wp), intent(in) :: t_y, roll
      type(contact_load_type), intent(in) :: load
      type(creepage_type), intent(in) :: creepage
      type(error_type), allocatable, intent(out) :: error

      if (.not. all(ieee_is_finite([t_y, roll]))) then
         call fatal_error(error, 'wheel position (t_y, roll): expected finite numbers, found '// &
            'NaN or Inf', stat_invalid_input)
         return
      end if
      ! The case file's ranges (a wheelset shifted beyond them has derailed), so that every
      ! interface refuses the same positions.
      call check_range('position%t_y', t_y, 'lateral shift t_y (y_ws)', error)
      if (.not. allocated(error)) call check_range('position%roll', roll, 'roll angle', error)
      if (allocated(error)) return
      if (load%mode < 1 .or. load%mode > size(load_mode_names)) then
         call fatal_error(error, 'load mode = '//str_int(load%mode)//': expected 1 (normal '// &
            'force), 2 (vertical force), 3 (approach), 4 (vertical position) or 5 (shared '// &
            'normal force)', &
            stat_invalid_input)
         return
      end if
      if (.not. ieee_is_finite(load%value)) then
         call fatal_error(error, trim(load_mode_names(load%mode))// &
            ': expected a finite number, found NaN or Inf', stat_invalid_input)
         return
      end if
      if (load%mode == load_vertical_position) then
         if (.not. (load%value >= 0.0_wp)) then
            call fatal_error(error, 'vertical position = '//str_real(load%value)// &
               ' mm: expected a downward displacement >= 0 from first contact', &
               stat_invalid_input)
            return
         end if
      else if (load%mode /= load_approach .and. .not. (load%value > 0.0_wp)) then
         call fatal_error(error, trim(load_mode_names(load%mode))//' = '// &
            str_real(load%value)//' N: expected a positive force', stat_invalid_input)
         return
      else if (load%mode == load_normal_force) then
         ! The program's range (shcontact_core_ranges): 1 N to 1e7 N.
         call check_range('load%normal_force', load%value, 'normal force', error)
         if (allocated(error)) return
      else if (load%mode == load_vertical_force) then
         call check_range('load%vertical_force', load%value, 'vertical force', error)
         if (allocated(error)) return
      else if (load%mode == load_approach) then
         ! The program's range: 0 < δ ≤ 5 mm (0 or less is no load, not a missed contact).
         call check_range('load%approach', load%value, 'approach', error)
         if (allocated(error)) return
      end if
      call check_creepage(creepage, error)
      if (allocated(error)) return
      ! The program's ranges of prescribed creepages (shcontact_core_ranges).
      call check_range('creepage%nu_x', creepage%nu_x, 'creepage nu_x', error)
      if (.not. allocated(error)) call check_range('creepage%nu_y', creepage%nu_y, &
         'creepage nu_y', error)
      if (.not. allocated(error)) call check_range('creepage%phi', creepage%phi, &
         'spin creepage phi', error)
   end subroutine check_call

   !> Change G, ν and μ. A new G or ν prepares the normal problem again at the next solve; μ
   !> alone only changes the tangential solution.
   subroutine set_material(self, material, error)
      !> The solver.
      class(contact_solver_type), intent(inout) :: self
      !> The new data.
      type(material_type), intent(in) :: material
      !> Set for non-physical data (the solver keeps its old data).
      type(error_type), allocatable, intent(out) :: error

      call check_finite_data(material, self%cache%track, error)
      if (allocated(error)) return
      call check_material(material, error)
      if (allocated(error)) return
      if (.not. (same(material%shear_modulus, self%cache%material%shear_modulus) .and. &
         same(material%poisson, self%cache%material%poisson))) call forget_normal(self%cache)
      self%cache%material = material
   end subroutine set_material

   !> Change the normal and/or tangential options (checked first; nothing changes on error).
   subroutine set_options(self, error, normal, tangential)
      !> The solver.
      class(contact_solver_type), intent(inout) :: self
      !> Set for an invalid option.
      type(error_type), allocatable, intent(out) :: error
      !> New normal options.
      type(normal_options_type), intent(in), optional :: normal
      !> New tangential options (`fields` is ignored, see [[init_profiles]]).
      type(tangential_options_type), intent(in), optional :: tangential

      if (present(normal)) then
         call check_normal_options(normal, error)
         if (allocated(error)) return
      end if
      if (present(tangential)) then
         call check_tangential_options(tangential, error)
         if (allocated(error)) return
      end if
      if (present(normal) .and. present(tangential)) then
         call check_grid_cells(normal, tangential, error)
      else if (present(normal)) then
         call check_grid_cells(normal, self%cache%tangential_options, error)
      else if (present(tangential)) then
         call check_grid_cells(self%cache%normal_options, tangential, error)
      end if
      if (allocated(error)) return
      if (present(normal)) then
         self%cache%normal_options = normal
         call forget_normal(self%cache)
      end if
      if (present(tangential)) self%cache%tangential_options = tangential
   end subroutine set_options

   !> Change the track and/or the contact-search options: the profiles are prepared again.
   subroutine set_track(self, error, track, contact_options)
      !> The solver.
      class(contact_solver_type), intent(inout) :: self
      !> Set for invalid data; the solver keeps its old track.
      type(error_type), allocatable, intent(out) :: error
      !> New track and wheelset dimensions.
      type(track_type), intent(in), optional :: track
      !> New contact-search options.
      type(contact_options_type), intent(in), optional :: contact_options
      type(prepared_profiles_type) :: prepared
      type(track_type) :: new_track
      type(contact_options_type) :: new_options

      if (.not. self%ready) then
         call fatal_error(error, 'contact solver: not initialised (call init first)', stat_usage)
         return
      end if
      new_track = self%cache%track
      new_options = self%cache%contact_options
      if (present(track)) new_track = track
      if (present(contact_options)) new_options = contact_options
      call check_finite_data(self%cache%material, new_track, error)
      if (allocated(error)) return
      call prepare_profiles(self%cache%wheel, self%cache%rail, new_track, new_options, prepared, &
         error)
      if (allocated(error)) return
      self%cache%track = new_track
      self%cache%contact_options = new_options
      self%cache%prepared = prepared
      self%cache%has_geometry = .false.
      self%cache%has_yawed = .false.
      self%cache%yaw_table%ready = .false.
      call forget_normal(self%cache)
   end subroutine set_track

   !> The current material.
   pure function get_material(self) result(material)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      type(material_type) :: material
      material = self%cache%material
   end function get_material

   !> The current normal and tangential options.
   pure subroutine get_options(self, normal, tangential)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      !> The normal options.
      type(normal_options_type), intent(out) :: normal
      !> The tangential options.
      type(tangential_options_type), intent(out) :: tangential
      normal = self%cache%normal_options
      tangential = self%cache%tangential_options
   end subroutine get_options

   !> n_strips × n_elements within max_grid_cells (shcontact_core_ranges), as the app checks.
   pure subroutine check_grid_cells(normal, tangential, error)
      type(normal_options_type), intent(in) :: normal
      type(tangential_options_type), intent(in) :: tangential
      type(error_type), allocatable, intent(out) :: error
      integer(i8) :: cells
      cells = int(normal%n_strips, i8)*int(tangential%n_elements, i8)
      if (cells <= max_grid_cells) return
      call fatal_error(error, 'options n_strips x n_elements = '//str_int(normal%n_strips)// &
         ' x '//str_int(tangential%n_elements)//' = '//str_int(cells)//' grid cells per '// &
         'patch; at most '//str_int(max_grid_cells)//' are allowed', stat_invalid_input)
   end subroutine check_grid_cells

   !> Reject NaN or Inf in the material or the track before the range checks compare them
   !> (a comparison with NaN would raise the invalid-operation exception).
   pure subroutine check_finite_data(material, track, error)
      type(material_type), intent(in) :: material
      type(track_type), intent(in) :: track
      type(error_type), allocatable, intent(out) :: error
      if (.not. all(ieee_is_finite([material%shear_modulus, material%poisson, &
         material%friction]))) then
         call fatal_error(error, 'material (G, nu, mu): expected finite numbers, found NaN '// &
            'or Inf', stat_invalid_input)
      else if (.not. all(ieee_is_finite([track%gauge, track%gauge_height, &
         track%rail_inclination, track%flange_back_distance, track%flange_back_position, &
         track%nominal_radius]))) then
         call fatal_error(error, 'track dimensions: expected finite numbers, found NaN or Inf', &
            stat_invalid_input)
      end if
   end subroutine check_finite_data

   !> The current contact-search options.
   pure function get_contact_options(self) result(options)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      type(contact_options_type) :: options
      options = self%cache%contact_options
   end function get_contact_options

   !> The current track.
   pure function get_track(self) result(track)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      type(track_type) :: track
      track = self%cache%track
   end function get_track

   !> The wheel and rail profiles as [[init]] took them (a file's read and cleaned, a built-in
   !> one as it is; before smoothing and placing), e.g. to pass them on as arrays.
   pure subroutine get_profiles(self, wheel, rail)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      !> The profiles (canonical form, doc/theory.md §5.1).
      type(profile_type), intent(out) :: wheel, rail
      wheel = self%cache%wheel
      rail = self%cache%rail
   end subroutine get_profiles

   !> True once [[init]] has succeeded.
   pure logical function is_ready(self)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      is_ready = self%ready
   end function is_ready

   !> Back to the state of a new object (keeps no data of an earlier init).
   pure subroutine reset(self)
      class(contact_solver_type), intent(inout) :: self
      self%ready = .false.
      self%cache%has_geometry = .false.
      self%cache%has_yawed = .false.
      self%cache%yaw_table%ready = .false.
      self%cache%has_normal = .false.
      self%cache%n_prepared = 0
      self%cache%n_loaded = 0
      self%cache%side = side_right
      self%cache%track = track_type()
      self%cache%material = material_type()
      self%cache%contact_options = contact_options_type()
      self%cache%normal_options = normal_options_type()
      self%cache%tangential_options = tangential_options_type()
   end subroutine reset

end module shcontact_api_solver
