!> The modern Fortran API: one solver object per wheel–rail contact (one wheel), created once and
!> called for every wheel position, load and creepage set (issue 8).
!>
!> [[contact_solver_type]] holds the prepared profiles (smoothing splines, placed rail, dense
!> samples), the patch geometry, the prepared normal problems, the normal and tangential solutions
!> and the tangential workspace. [[solve]] runs the same pipeline as the app's case runner
!> (`src/shcontact/case/runner.f90`):
!>
!> 1. contact search at (t_y, roll) → candidate patches, deepest first;
!> 2. normal problem: a prescribed normal force or approach on the first (deepest) patch, or a
!>    prescribed vertical wheel load shared by all patches through one rigid approach
!>    (doc/theory.md §4.5–4.6);
!> 3. tangential problem of every loaded patch with the same creepages (prescribed at the
!>    geometric contact point, doc/theory.md decision 13), forces on the wheel (decision 2);
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
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_invalid_input, &
      stat_no_contact, stat_usage, stat_numerical
   use shcontact_core_strings, only: str_int, str_real, to_lower
   use shcontact_core_ranges, only: max_grid_cells, check_range
   use shcontact_profile_reader, only: profile_file_format
   use shcontact_core_material, only: material_type, check_material
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_source, only: load_profile
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type, side_right, side_left
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      contact_patches_type, prepare_profiles, find_contact_patches, extract_patch, max_candidates, &
      prepare_wheel
   use shcontact_normal_options, only: normal_options_type, check_normal_options
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load, &
      solve_approach, solve_vertical_load, solve_vertical_approach
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options
   use shcontact_tangential_creepage, only: creepage_type, check_creepage
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_solver, only: track_forces_type, solve_tangential
   use shcontact_tangential_options, only: spin_additive
   use shcontact_tangential_rigid_slip, only: contact_point_type, rigid_creepages
   use shcontact_geometry_yaw, only: yaw_table_type, build_yaw_table, apply_yaw, yaw_table_limit
   use shcontact_geometry_kinematics, only: wheelset_state_type, check_wheelset_state, &
      side_state, yawed_wheel_profile, axle_offset, contact_lead, true_radius_scale, &
      scale_to_true_radius
   implicit none
   private

   public :: contact_solver_type, contact_load_type, contact_result_type, patch_result_type
   public :: contact_fields_type, load_profile
   public :: load_normal_force, load_vertical_force, load_approach, load_vertical_position, &
      load_mode_name
   public :: max_patches

   !> Load mode: normal force N (N) on the first (deepest) patch.
   integer, parameter :: load_normal_force = 1
   !> Load mode: vertical wheel load F_z (N) shared by all patches (doc/theory.md §4.6).
   integer, parameter :: load_vertical_force = 2
   !> Load mode: approach δ (mm) of the first patch.
   integer, parameter :: load_approach = 3
   !> Load mode: vertical position, the rigid vertical approach Δz (mm) of the wheel from first
   !> contact, shared by all patches (doc/theory.md §4.6).
   integer, parameter :: load_vertical_position = 4
   character(len=*), parameter :: load_mode_names(4) = [character(len=17) :: 'normal force', &
      'vertical force', 'approach', 'vertical position']

   !> Most patches one contact may have (the contact search follows at most 16 candidates).
   integer, parameter :: max_patches = max_candidates
   !> The total vertical force of a kinematic call matches the load to this relative tolerance
   !> (0.65 N of 64.7 kN), within at most max_vertical_iterations solutions.
   real(wp), parameter :: vertical_rtol = 1.0e-5_wp
   integer, parameter :: max_vertical_iterations = 30

   !> The load of one solve.
   type :: contact_load_type
      !> [[load_normal_force]], [[load_vertical_force]] or [[load_approach]].
      integer :: mode = load_normal_force
      !> The force (N, > 0) or the approach (mm).
      real(wp) :: value = 0.0_wp
   end type contact_load_type

   !> The solution of one patch (forces on the wheel, doc/theory.md decision 2).
   type :: patch_result_type
      !> Tangential forces F_x, F_y (N, contact frame) and spin moment M_z about the reference
      !> point (N·mm).
      real(wp) :: fx = 0.0_wp, fy = 0.0_wp, mz = 0.0_wp
      !> Normal force F_n (N).
      real(wp) :: fn = 0.0_wp
      !> Normalised forces F/(μ F_n).
      real(wp) :: fx_norm = 0.0_wp, fy_norm = 0.0_wp
      !> Lateral and vertical force in the track frame (N, z down), in the wheel's side frame: y
      !> towards the wheel's own field side (for the left wheel multiply F_y by −1 to get the
      !> track frame's y, doc/api.md).
      real(wp) :: fy_track = 0.0_wp, fz_track = 0.0_wp
      !> Approach δ (mm), contact area (mm²), largest strip peak pressure (MPa).
      real(wp) :: approach = 0.0_wp, area = 0.0_wp, p_max = 0.0_wp
      !> Contact angle γ₀ (rad, CONTACT's sign) and rolling radius r₀ (mm) at the reference point:
      !> the first contact of the contact search, and for a loaded patch the geometric contact
      !> point of the loaded state, where the creepages are given (doc/geometry.md "Vertical
      !> approach").
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp
      !> Contact angle of the contact plane (rad, CONTACT's sign): that of the first contact.
      !> F_n is normal to this plane, and a vertical load is shared as Σ F_n cos γ_plane = F_z.
      real(wp) :: gamma_plane = 0.0_wp
      !> Reference point in track coordinates (mm; y from the track centre, z down), the same
      !> point.
      real(wp) :: y_track = 0.0_wp, z_track = 0.0_wp
      !> Coulomb check max|p|/(μ p_n,e) and adhesion area fraction.
      real(wp) :: coulomb_ratio = 0.0_wp, adhesion_fraction = 0.0_wp
      !> Creepages used at the reference point (ν_x, ν_y, φ in rad/mm; wheel relative to rail):
      !> those given to [[solve]], or those of the wheelset's motion in [[solve_kinematic]].
      real(wp) :: nu_x = 0.0_wp, nu_y = 0.0_wp, phi = 0.0_wp
      !> Longitudinal position of the reference point in the track frame (mm, forward; nonzero
      !> with a yaw angle, shcontact_geometry_kinematics).
      real(wp) :: x_track = 0.0_wp
   end type patch_result_type

   !> The result of one solve. Fixed size: filling it allocates nothing.
   type :: contact_result_type
      !> Patches found by the contact search (deepest first).
      integer :: n_patches = 0
      !> Patches solved: 1 for a normal force or approach, n_patches for a vertical load.
      integer :: n_loaded = 0
      !> The most loaded patch (the app's "main" patch).
      integer :: main_patch = 0
      !> Rigid vertical approach Δz of the wheel (mm), vertical load only.
      real(wp) :: dz = 0.0_wp
      !> The main patch: patch(main_patch).
      type(patch_result_type) :: main
      !> Totals over the loaded patches, forces on the wheel in the track frame (N; side frame:
      !> the left wheel's F_y is the mirror image, see patch_result_type%fy_track).
      type(track_forces_type) :: track
      !> Every patch; patches beyond n_loaded carry their geometry only.
      type(patch_result_type) :: patch(max_patches)
   end type contact_result_type

   !> Copies of the fields of one solve (doc/theory.md decision 12): per patch its strip tables, the
   !> normal strips and the tangential element fields. The arrays are reused from call to call and
   !> reallocated only when their size changes.
   type :: contact_fields_type
      !> Patches filled (the loaded ones).
      integer :: n_patches = 0
      !> Geometry tables of each patch.
      type(patch_geometry_type) :: geometry(max_patches)
      !> Normal solution (strips) of each patch.
      type(normal_patch_type) :: normal(max_patches)
      !> Tangential solution (elements) of each patch.
      type(tangential_patch_type) :: tangential(max_patches)
   end type contact_fields_type

   !> One wheel–rail contact: its data, its prepared geometry and all its workspace.
   type :: contact_solver_type
      private
      !> True once [[init]] has succeeded.
      logical :: ready = .false.
      !> The profiles as given (kept to prepare again when the track changes).
      type(profile_type) :: wheel, rail
      !> Track, side, material and options.
      type(track_type) :: track
      type(contact_options_type) :: contact_options
      integer :: side = side_right
      type(material_type) :: material
      type(normal_options_type) :: normal_options
      type(tangential_options_type) :: tangential_options
      !> Profiles ready for the contact search.
      type(prepared_profiles_type) :: prepared
      !> The profiles prepared for the yaw angle `yaw` (side frame) of the last kinematic call:
      !> the wheel replaced by its contact locus (shcontact_geometry_kinematics).
      type(prepared_profiles_type) :: yawed
      logical :: has_yawed = .false.
      !> Effective wheel profiles at the yaw nodes (built at the first yawed call).
      type(yaw_table_type) :: yaw_table
      real(wp) :: yawed_angle = 0.0_wp
      !> Geometry of the last position (valid when has_geometry).
      logical :: has_geometry = .false.
      real(wp) :: t_y = 0.0_wp, roll = 0.0_wp, yaw = 0.0_wp
      !> The strip tables end at the options' kinematic_table_gap (a kinematic call's first try).
      logical :: short_tables = .false.
      type(contact_patches_type) :: patches
      !> Patches whose normal problem is prepared for this geometry.
      integer :: n_prepared = 0
      type(normal_contact_type) :: contacts(max_patches)
      !> Normal solution of the last load (valid when has_normal).
      logical :: has_normal = .false.
      type(contact_load_type) :: load
      integer :: n_loaded = 0
      real(wp) :: dz = 0.0_wp
      type(normal_patch_type) :: normal(max_patches)
      !> Tangential workspace and solutions.
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: tangential(max_patches)
      !> Creepages of each solved patch at its reference point.
      type(creepage_type) :: creepage(max_patches)
      !> Longitudinal position of each patch's reference point (mm, track frame).
      real(wp) :: x_track(max_patches) = 0.0_wp
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
      self%wheel = wheel
      self%rail = rail
      if (present(track)) then
         self%track = track
      else if (wheel%origin_at_flange_back) then
         ! A MiniProf wheel has its origin at the flange back: without a track given, its flange
         ! back is at 0 (the default −70 mm is S1002's, whose origin is on the tape circle), as
         ! in the app (doc/app.md).
         self%track%flange_back_position = 0.0_wp
      end if
      if (present(material)) self%material = material
      if (present(side)) self%side = side
      if (present(contact_options)) self%contact_options = contact_options
      if (present(normal_options)) self%normal_options = normal_options
      if (present(tangential_options)) self%tangential_options = tangential_options
      if (self%side /= side_right .and. self%side /= side_left) then
         call fatal_error(error, 'wheel side = '//str_int(self%side)// &
            ': expected 1 (right) or -1 (left)', stat_invalid_input)
         return
      end if
      call check_finite_data(self%material, self%track, error)
      if (allocated(error)) return
      call check_material(self%material, error)
      if (allocated(error)) return
      call check_normal_options(self%normal_options, error)
      if (allocated(error)) return
      call check_tangential_options(self%tangential_options, error)
      if (allocated(error)) return
      call check_grid_cells(self%normal_options, self%tangential_options, error)
      if (allocated(error)) return
      call prepare_profiles(self%wheel, self%rail, self%track, self%contact_options, &
         self%prepared, error)
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
      !> Creepages at the geometric contact point (ν_x, ν_y, φ in rad/mm), wheel relative to rail.
      type(creepage_type), intent(in) :: creepage
      !> The forces and the per-patch summary.
      type(contact_result_type), intent(out) :: result
      !> Set for bad input (status and message); the solver stays usable.
      type(error_type), allocatable, intent(out) :: error
      !> When present: filled with copies of the geometry, normal and tangential fields.
      type(contact_fields_type), intent(inout), optional :: fields
      type(tangential_options_type) :: options
      integer :: k

      call check_ready(self, error)
      if (allocated(error)) return
      call check_call(t_y, roll, load, creepage, error)
      if (allocated(error)) return
      call update_geometry(self, t_y, roll, 0.0_wp, error)
      if (allocated(error)) return
      call update_normal(self, load, error)
      if (allocated(error)) return

      options = self%tangential_options
      options%fields = present(fields)
      do k = 1, self%n_loaded
         call solve_patch(self, k, creepage, options, error)
         if (allocated(error)) return
      end do
      call summarise(self, result)
      if (present(fields)) call copy_fields(self, fields)
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
      local = side_state(state, self%side)
      ! The balance iterates on forces only; the fields, when asked for, come from one more
      ! solve of the final state (the totals are the same with and without fields).
      options = self%tangential_options
      options%fields = .false.
      options%spin_model = spin_additive
      ! First with strip tables to the options' kinematic_table_gap (0.25 mm by default; the
      ! approach of a wheel load is 0.05-0.25 mm), then, if a contact reaches the end of those
      ! tables, with the full ones.
      call kinematic_contact(self, state, local, load, options, .true., climbs, error)
      if (allocated(error)) then
         if (error%stat /= stat_no_contact) return
         deallocate (error)
         call kinematic_contact(self, state, local, load, options, .false., climbs, error)
         if (allocated(error)) then
            ! No equilibrium (the wheel climbs): the result holds the best state found.
            if (climbs) call summarise(self, result)
            return
         end if
      end if
      if (present(fields)) then
         options%fields = .true.
         call kinematic_tangential(self, local, options, error)
         if (allocated(error)) return
      end if
      call summarise(self, result)
      if (present(fields)) call copy_fields(self, fields)
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
      local = side_state(state, self%side)
      call update_geometry(self, state%y_ws, state%roll, local%yaw, error)
      if (allocated(error)) return
      allocate (geometry(self%patches%count))
      do k = 1, self%patches%count
         call extract_patch(self%patches, k, geometry(k))
      end do
   end subroutine locate_kinematic

   !> Geometry, normal and tangential problems of a kinematic call. With `short_tables` the strip
   !> tables end at kinematic_table_gap (a search of its own, cached apart from the full one).
   !> A vertical load is balanced by [[vertical_balance]]; `climbs` is set with its error when
   !> no equilibrium exists within the tables (the solver then holds the best state found).
   subroutine kinematic_contact(self, state, local, load, options, short_tables, climbs, error)
      type(contact_solver_type), intent(inout) :: self
      !> The state in the track frame and in the wheel's side frame.
      type(wheelset_state_type), intent(in) :: state, local
      type(contact_load_type), intent(in) :: load
      type(tangential_options_type), intent(in) :: options
      logical, intent(in) :: short_tables
      logical, intent(out) :: climbs
      type(error_type), allocatable, intent(out) :: error

      climbs = .false.
      call update_geometry(self, state%y_ws, state%roll, local%yaw, error, short_tables)
      if (allocated(error)) return
      if (load%mode == load_vertical_force) then
         call vertical_balance(self, local, load%value, options, climbs, error)
         return
      end if
      call update_normal(self, load, error)
      if (allocated(error)) return
      call kinematic_tangential(self, local, options, error)
   end subroutine kinematic_contact

   !> The vertical balance of a kinematic call: the rigid vertical approach Δz of the wheel at
   !> which the total vertical force, tangential forces included (as CONTACT's FZ), carries the
   !> load: C(Δz) = −Σ F_z,track = F_z to vertical_rtol.
   !>
   !> Every state is a function of Δz alone (normal problem at the vertical position Δz, then the
   !> tangential problem with the creepages at the loaded reference points), so the root is
   !> bracketed in Δz, not in the load: at the first touch Δz₀ nothing is carried (C = 0), and
   !> an upper end is found by growing Δz monotonically. On a flange (γ ≈ −70°) a patch carries
   !> only N(cos γ − μ sin γ) vertically, which nearly vanishes, so the load is a steep function
   !> of C and a load iteration diverges; in Δz the function stays well behaved. The residual is
   !> r = s(C) − s(F_z), s(c) = sign(|c|^{2/3}, c), nearly linear in Δz for a Hertzian
   !> contact; the root finder is the Illinois regula falsi on the bracket. The first two points
   !> come from the geometry: the normal problem alone carrying F_z, then carrying F_z²/C (the
   !> tangential share taken proportional to the load). No state of an earlier call is used.
   !>
   !> C(Δz) is continuous (the normal force of a contact is a continuous function of the
   !> approach, and so are the tangential forces at fixed creepages; doc/kinematics.md), so the
   !> bracket always holds a root. Should the bracket close to round-off without meeting
   !> vertical_rtol (C jumping across F_z, a defect of the model), the call fails with
   !> stat_numerical and names the bracket: no state outside the tolerance is returned.
   !>
   !> If C stays below F_z up to the end of the strip tables (the contact cannot carry the load:
   !> friction on the flange lifts the wheel), `climbs` is set, the error has stat_no_contact
   !> and the reason, and the solver holds the state with the largest C found.
   subroutine vertical_balance(self, local, f_z, options, climbs, error)
      type(contact_solver_type), intent(inout) :: self
      !> The state in the wheel's side frame.
      type(wheelset_state_type), intent(in) :: local
      !> Vertical wheel load (N, > 0).
      real(wp), intent(in) :: f_z
      type(tangential_options_type), intent(in) :: options
      logical, intent(out) :: climbs
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: x_lo, r_lo, x_hi, r_hi, x, r, c, q, x_cap, x_best, c_best, step, tol, touch, &
         c_at_lo, c_at_hi
      integer :: it, side
      logical :: bracketed

      climbs = .false.
      tol = vertical_rtol*f_z
      ! 1. The normal problem alone carrying F_z (the start from the geometry).
      call update_normal(self, contact_load_type(load_vertical_force, f_z), error)
      if (allocated(error)) return
      call touch_and_reach(self, touch, x_cap)
      x_lo = touch
      c_at_lo = 0.0_wp
      c_at_hi = huge(1.0_wp)
      r_lo = -signed_23(f_z)
      x_best = x_lo
      c_best = -huge(1.0_wp)
      bracketed = .false.
      x_hi = x_cap
      r_hi = 0.0_wp
      x = self%dz
      call tangential_at(x, c, r, error)
      if (allocated(error)) return
      if (abs(c - f_z) <= tol) return
      call keep(x, c, r)
      ! 2. The normal problem alone carrying F_z²/C (tangential share proportional to the load).
      if (c > 0.0_wp) then
         q = f_z*(f_z/c)
         call update_normal(self, contact_load_type(load_vertical_force, q), error)
         if (allocated(error)) then
            if (error%stat /= stat_no_contact) return
            deallocate (error)
         else
            x = self%dz
            if (x > x_lo .and. x < x_hi) then
               call tangential_at(x, c, r, error)
               if (allocated(error)) return
               if (abs(c - f_z) <= tol) return
               call keep(x, c, r)
            end if
         end if
      end if
      ! 3. Grow Δz monotonically until C exceeds F_z (or the tables end).
      step = max(0.25_wp*(x_lo - touch), 1.0e-3_wp)
      do it = 1, max_vertical_iterations
         if (bracketed .or. .not. (x_lo < x_cap)) exit
         x = min(x_lo + step, x_cap)
         call tangential_at(x, c, r, error)
         if (allocated(error)) then
            if (error%stat /= stat_no_contact) return
            ! Beyond what the tables carry: the reach ends before x.
            deallocate (error)
            x_cap = x_lo + 0.5_wp*(x - x_lo)
            step = x_cap - x_lo
            if (step <= 1.0e-9_wp*max(x_cap, 1.0_wp)) exit
            cycle
         end if
         if (abs(c - f_z) <= tol) return
         call keep(x, c, r)
         step = 2.0_wp*step
      end do
      if (.not. bracketed) then
         ! No Δz within the tables carries F_z: leave the best state found.
         call tangential_at(x_best, c, r, error)
         if (allocated(error)) return
         climbs = .true.
         call fatal_error(error, 'vertical load '//str_real(f_z)//' N: no equilibrium, the '// &
            'wheel climbs: the contact carries at most '//str_real(c_best)//' N vertically '// &
            '(at the vertical approach '//str_real(x_best)//' mm, the end of the strip '// &
            'tables at '//str_real(x_cap)//' mm); the tangential forces on the flange lift '// &
            'the wheel', stat_no_contact)
         return
      end if
      ! 4. Illinois regula falsi on the bracket [x_lo, x_hi].
      side = 0
      do it = 1, 4*max_vertical_iterations
         x = x_hi - r_hi*(x_hi - x_lo)/(r_hi - r_lo)
         if (.not. (x > x_lo .and. x < x_hi)) x = 0.5_wp*(x_lo + x_hi)
         call tangential_at(x, c, r, error)
         if (allocated(error)) return
         if (abs(c - f_z) <= tol) return
         if (r > 0.0_wp) then
            x_hi = x
            r_hi = r
            c_at_hi = c
            if (side == 1) r_lo = 0.5_wp*r_lo
            side = 1
         else
            x_lo = x
            r_lo = r
            c_at_lo = c
            if (side == -1) r_hi = 0.5_wp*r_hi
            side = -1
         end if
         if (x_hi - x_lo <= 4.0_wp*spacing(x_hi)) exit
      end do
      ! The bracket closed without a root: C(Δz) jumps across F_z there (a defect of the model).
      if (abs(c_at_lo - f_z) <= abs(c_at_hi - f_z)) then
         c = c_at_lo
      else
         c = c_at_hi
      end if
      call fatal_error(error, 'vertical load matching with tangential forces did not '// &
         'converge: '//str_real(c)//' N instead of '//str_real(f_z)//' N (vertical approach '// &
         'bracketed in ['//str_real(x_lo)//', '//str_real(x_hi)//'] mm)', stat_numerical)
   contains
      !> The normal problem at the vertical position x (mm), the tangential problem, the
      !> vertical force carried c (N) and the residual r.
      subroutine tangential_at(x, c, r, error)
         real(wp), intent(in) :: x
         real(wp), intent(out) :: c, r
         type(error_type), allocatable, intent(out) :: error
         integer :: k
         c = 0.0_wp
         r = 0.0_wp
         if (.not. (self%has_normal .and. self%load%mode == load_vertical_force .and. &
                    same(self%dz, x))) then
            call update_normal(self, contact_load_type(load_vertical_position, x), error)
            if (allocated(error)) return
         end if
         call kinematic_tangential(self, local, options, error)
         if (allocated(error)) return
         do k = 1, self%n_loaded
            if (self%normal(k)%load > 0.0_wp) c = c - self%tangential(k)%fz_track
         end do
         r = signed_23(c) - signed_23(f_z)
      end subroutine tangential_at

      !> Record an evaluated point: the bracket ends and the best state.
      subroutine keep(x, c, r)
         real(wp), intent(in) :: x, c, r
         if (c > c_best) then
            c_best = c
            x_best = x
         end if
         if (r > 0.0_wp) then
            if (x < x_hi .or. .not. bracketed) then
               x_hi = x
               r_hi = r
               c_at_hi = c
            end if
            bracketed = .true.
         else if (x > x_lo) then
            x_lo = x
            r_lo = r
            c_at_lo = c
         end if
      end subroutine keep
   end subroutine vertical_balance

   !> Δz (mm) at which the first patch touches, and the largest Δz the strip tables of every
   !> patch reach (slightly inside it), for the patches prepared by a vertical load.
   pure subroutine touch_and_reach(self, touch, reach)
      type(contact_solver_type), intent(in) :: self
      real(wp), intent(out) :: touch, reach
      real(wp) :: cos_g
      integer :: k

      touch = huge(1.0_wp)
      reach = huge(1.0_wp)
      do k = 1, self%n_prepared
         associate (g => self%contacts(k)%geometry)
            cos_g = cos(g%gamma0)
            touch = min(touch, (g%approach_touch + g%gap0)/cos_g)
            if (g%has_strip_data) reach = min(reach, (g%approach_max + g%gap0)/cos_g)
         end associate
      end do
      touch = max(touch, 0.0_wp)
      if (reach < huge(1.0_wp)) then
         reach = touch + (reach - touch)*(1.0_wp - 1.0e-9_wp)
      else
         reach = touch + 10.0_wp
      end if
   end subroutine touch_and_reach

   !> sign(|c|^{2/3}, c): the load's power that is nearly linear in the approach.
   elemental real(wp) function signed_23(c)
      real(wp), intent(in) :: c
      signed_23 = sign(abs(c)**(2.0_wp/3.0_wp), c)
   end function signed_23

   !> The tangential problem of every loaded patch with the creepages of the wheelset's motion
   !> at its reference point: the geometric contact point of the loaded state (the normal
   !> solution's y_shift from the first contact along the contact plane, its rolling radius
   !> and contact angle; shcontact_normal_semihertz's refer_to_loaded_point). The point's axle
   !> coordinate moves by y_shift cos γ_plane from the first contact's.
   subroutine kinematic_tangential(self, local, options, error)
      type(contact_solver_type), intent(inout) :: self
      !> The state in the wheel's side frame.
      type(wheelset_state_type), intent(in) :: local
      type(tangential_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error
      type(contact_point_type) :: point
      type(creepage_type) :: creepage
      real(wp) :: speed
      integer :: k

      do k = 1, self%n_loaded
         if (.not. (self%normal(k)%load > 0.0_wp)) cycle
         point = contact_point_type(axle=reference_axle(self, k), radius=self%normal(k)%r0, &
            gamma=self%normal(k)%gamma0)
         call rigid_creepages(local, point, creepage, speed, error)
         if (allocated(error)) return
         call solve_patch(self, k, creepage, options, error)
         if (allocated(error)) return
      end do
   end subroutine kinematic_tangential

   !> Axle coordinate L (mm) of loaded patch k's reference point: the first contact's, moved by
   !> y_shift cos γ_plane along the contact plane (shcontact_normal_semihertz's
   !> refer_to_loaded_point).
   pure real(wp) function reference_axle(self, k) result(axle)
      type(contact_solver_type), intent(in) :: self
      integer, intent(in) :: k
      axle = self%patches%patch(k)%y_wheel + axle_offset(self%track) + &
         self%normal(k)%lateral_offset()
   end function reference_axle

   !> The tangential problem of loaded patch k for its creepages.
   subroutine solve_patch(self, k, creepage, options, error)
      type(contact_solver_type), intent(inout) :: self
      integer, intent(in) :: k
      type(creepage_type), intent(in) :: creepage
      type(tangential_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error

      if (.not. (self%normal(k)%load > 0.0_wp)) return
      call solve_tangential(self%ws, self%normal(k), self%material, creepage, options, &
         self%tangential(k), error)
      if (allocated(error)) then
         if (self%n_loaded > 1) call prefix_error(error, 'patch '//str_int(k))
         return
      end if
      self%creepage(k) = creepage
   end subroutine solve_patch

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
      if (load%mode < 1 .or. load%mode > size(load_mode_names)) then
         call fatal_error(error, 'load mode = '//str_int(load%mode)//': expected 1 (normal '// &
            'force), 2 (vertical force), 3 (approach) or 4 (vertical position)', &
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

   !> The contact patches at (t_y, roll, yaw), unless they are those of the last call. With a yaw
   !> angle the search runs on the yawed wheel's contact locus (profiles prepared once per yaw
   !> angle, [[prepare_yaw]]); the table's rolling radii are then turned back into the true
   !> ones, and each reference point gets its longitudinal lead.
   subroutine update_geometry(self, t_y, roll, yaw, error, short_tables)
      type(contact_solver_type), intent(inout) :: self
      !> Lateral shift (mm) and roll (rad), track frame.
      real(wp), intent(in) :: t_y, roll
      !> Yaw angle of the side frame (rad).
      real(wp), intent(in) :: yaw
      type(error_type), allocatable, intent(out) :: error
      !> Strip tables to kinematic_table_gap at most (default: the options' table_gap).
      logical, intent(in), optional :: short_tables
      type(wheelset_position_type) :: position
      real(wp) :: table_gap, sin_yaw
      logical :: short
      integer :: k

      short = .false.
      if (present(short_tables)) short = short_tables
      if (self%has_geometry .and. same(t_y, self%t_y) .and. same(roll, self%roll) .and. &
         same(yaw, self%yaw) .and. (short .eqv. self%short_tables)) return
      self%has_geometry = .false.
      self%has_normal = .false.
      self%n_prepared = 0
      position = wheelset_position_type(side=self%side, y_ws=t_y, roll=roll)
      if (yaw == 0.0_wp) then
         table_gap = self%prepared%options%table_gap
         if (short) self%prepared%options%table_gap = min(table_gap, &
            self%prepared%options%kinematic_table_gap)
         call find_contact_patches(self%prepared, position, self%patches, error)
         self%prepared%options%table_gap = table_gap
      else
         call prepare_yaw(self, yaw, error)
         if (allocated(error)) return
         table_gap = self%yawed%options%table_gap
         if (short) self%yawed%options%table_gap = min(table_gap, &
            self%yawed%options%kinematic_table_gap)
         call find_contact_patches(self%yawed, position, self%patches, error)
         self%yawed%options%table_gap = table_gap
      end if
      if (allocated(error)) return
      if (self%patches%count < 1) then
         call fatal_error(error, 'contact search at t_y = '//str_real(t_y)//' mm, roll = '// &
            str_real(roll)//' rad: no contact patch found', stat_no_contact)
         return
      end if
      if (self%patches%count > max_patches) then
         call fatal_error(error, 'contact search: '//str_int(self%patches%count)// &
            ' patches; the solver holds at most '//str_int(max_patches), stat_usage)
         return
      end if
      sin_yaw = sin(yaw)
      do k = 1, self%patches%count
         associate (g => self%patches%patch(k), n => self%patches%points(k))
            if (yaw /= 0.0_wp) then
               call scale_to_true_radius(g%gamma(1:n), sin_yaw, g%r_wheel(1:n))
               g%r0 = g%r0*true_radius_scale(g%gamma0, sin_yaw)
            end if
            self%x_track(k) = contact_lead(g%y_wheel + axle_offset(self%track), g%r0, &
               g%gamma0, yaw)
         end associate
      end do
      self%t_y = t_y
      self%roll = roll
      self%yaw = yaw
      self%short_tables = short
      self%has_geometry = .true.
   end subroutine update_geometry

   !> Prepare the profiles for a yaw angle (side frame): the wheel replaced by its contact locus
   !> (shcontact_geometry_kinematics), interpolated in ψ² from the effective profiles prepared
   !> at a few yaw angles at the first yawed call (shcontact_geometry_yaw; beyond its
   !> yaw_table_limit prepared directly), with the unyawed tape
   !> circle height, so that the table's rolling radius is r cos θ.
   subroutine prepare_yaw(self, yaw, error)
      type(contact_solver_type), intent(inout) :: self
      real(wp), intent(in) :: yaw
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: locus
      type(contact_options_type) :: options

      if (self%has_yawed .and. same(yaw, self%yawed_angle)) return
      if (.not. self%has_yawed) self%yawed = self%prepared
      self%has_yawed = .false.
      if (abs(yaw) <= yaw_table_limit) then
         if (.not. self%yaw_table%ready) then
            call build_yaw_table(self%wheel, self%prepared, self%track, self%contact_options, &
               self%yaw_table, error)
            if (allocated(error)) return
         end if
         call apply_yaw(self%yaw_table, yaw, self%yawed)
      else
         call yawed_wheel_profile(self%wheel, self%prepared%wheel, self%track, &
            self%prepared%z_tape, yaw, locus)
         options = self%contact_options
         options%l_filt_wheel = 0.0_wp
         call prepare_wheel(locus, self%track, options, self%yawed, error)
         if (allocated(error)) then
            call prefix_error(error, 'yawed wheel (yaw '//str_real(yaw)//' rad)')
            return
         end if
      end if
      self%yawed%z_tape = self%prepared%z_tape
      self%yawed_angle = yaw
      self%has_yawed = .true.
   end subroutine prepare_yaw

   !> The normal solution for the load, unless it is that of the last call on this geometry.
   !> Force and approach load the first (deepest) patch, a vertical load all patches.
   subroutine update_normal(self, load, error)
      type(contact_solver_type), intent(inout) :: self
      type(contact_load_type), intent(in) :: load
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: vertical
      integer :: k, n

      if (self%has_normal .and. load%mode == self%load%mode .and. &
         same(load%value, self%load%value)) return
      self%has_normal = .false.
      n = 1
      if (load%mode == load_vertical_force .or. load%mode == load_vertical_position) &
         n = self%patches%count
      do k = self%n_prepared + 1, n
         call prepare_normal_contact(self%contacts(k), self%patches%patch(k), &
            self%normal_options, self%material, error, n_points=self%patches%points(k))
         if (allocated(error)) then
            if (n > 1) call prefix_error(error, 'patch '//str_int(k))
            return
         end if
         self%n_prepared = k
      end do
      self%dz = 0.0_wp
      select case (load%mode)
      case (load_normal_force)
         call solve_load(self%contacts(1), load%value, self%normal(1), error)
      case (load_approach)
         call solve_approach(self%contacts(1), load%value, self%normal(1), error)
      case (load_vertical_position)
         call solve_vertical_approach(self%contacts(1:n), load%value, self%normal(1:n), &
            vertical, error)
         self%dz = load%value
      case default
         call solve_vertical_load(self%contacts(1:n), load%value, self%normal(1:n), self%dz, &
            error)
      end select
      if (allocated(error)) return
      self%load = load
      self%n_loaded = n
      self%has_normal = .true.
   end subroutine update_normal

   !> The result: every patch, the most loaded one and the track-frame totals.
   pure subroutine summarise(self, result)
      type(contact_solver_type), intent(in) :: self
      type(contact_result_type), intent(inout) :: result
      integer :: k, m

      result%n_patches = self%patches%count
      result%n_loaded = self%n_loaded
      result%dz = self%dz
      do k = 1, result%n_patches
         associate (p => result%patch(k), g => self%patches%patch(k))
            p%gamma0 = g%gamma0
            p%gamma_plane = g%gamma0
            p%r0 = g%r0
            p%y_track = g%y_track
            p%z_track = g%z_track
            p%x_track = self%x_track(k)
         end associate
      end do
      m = 1
      do k = 1, self%n_loaded
         associate (p => result%patch(k), n => self%normal(k), t => self%tangential(k))
            p%fn = n%load
            if (n%load > 0.0_wp) then
               p%gamma0 = n%gamma0
               p%r0 = n%r0
               ! Along the contact plane towards the wheel's field side (y_track is in the
               ! track frame: towards −y on the left wheel).
               p%y_track = p%y_track + self%side*n%lateral_offset()
               p%z_track = p%z_track + n%vertical_offset()
               p%x_track = contact_lead(reference_axle(self, k), n%r0, n%gamma0, self%yaw)
            end if
            p%approach = n%approach
            p%area = n%area
            p%p_max = n%p_max
            if (.not. (n%load > 0.0_wp)) cycle
            p%fx = t%fx
            p%fy = t%fy
            p%mz = t%mz
            p%fx_norm = t%fx_norm
            p%fy_norm = t%fy_norm
            p%fy_track = t%fy_track
            p%fz_track = t%fz_track
            p%coulomb_ratio = t%coulomb_ratio
            p%adhesion_fraction = t%adhesion_fraction
            p%nu_x = self%creepage(k)%nu_x
            p%nu_y = self%creepage(k)%nu_y
            p%phi = self%creepage(k)%phi
            result%track%fx = result%track%fx + t%fx
            result%track%fy = result%track%fy + t%fy_track
            result%track%fz = result%track%fz + t%fz_track
            result%track%fn = result%track%fn + n%load
         end associate
         if (self%normal(k)%load > self%normal(m)%load) m = k
      end do
      result%main_patch = m
      result%main = result%patch(m)
   end subroutine summarise

   !> Copy the fields of the loaded patches, reusing the arrays of `fields`.
   pure subroutine copy_fields(self, fields)
      type(contact_solver_type), intent(in) :: self
      type(contact_fields_type), intent(inout) :: fields
      integer :: k

      fields%n_patches = self%n_loaded
      do k = 1, self%n_loaded
         call extract_patch(self%patches, k, fields%geometry(k))
         call copy_normal(self%normal(k), fields%normal(k))
         if (self%normal(k)%load > 0.0_wp) then
            call copy_tangential(self%tangential(k), fields%tangential(k))
         else
            fields%tangential(k)%nx = 0
            fields%tangential(k)%ny = 0
         end if
      end do
   end subroutine copy_fields

   !> Copy a normal solution into reused arrays.
   pure subroutine copy_normal(src, dst)
      type(normal_patch_type), intent(in) :: src
      type(normal_patch_type), intent(inout) :: dst
      dst%n_strips = src%n_strips
      dst%is_hertz = src%is_hertz
      dst%ellipse_a = src%ellipse_a
      dst%ellipse_b = src%ellipse_b
      dst%ellipse_y_centre = src%ellipse_y_centre
      dst%approach = src%approach
      dst%load = src%load
      dst%area = src%area
      dst%p_max = src%p_max
      dst%dy = src%dy
      dst%gamma0 = src%gamma0
      dst%r0 = src%r0
      dst%y_shift = src%y_shift
      dst%gamma_plane = src%gamma_plane
      call copy_vector(src%y, dst%y)
      call copy_vector(src%a, dst%a)
      call copy_vector(src%k, dst%k)
      call copy_vector(src%p0, dst%p0)
      call copy_vector(src%strip_load, dst%strip_load)
      call copy_vector(src%m, dst%m)
      call copy_vector(src%n, dst%n)
      call copy_vector(src%eps_a, dst%eps_a)
      call copy_vector(src%gamma, dst%gamma)
      call copy_vector(src%delta_r, dst%delta_r)
      call copy_vector(src%r_wheel, dst%r_wheel)
   end subroutine copy_normal

   !> Copy a tangential solution into reused arrays.
   pure subroutine copy_tangential(src, dst)
      type(tangential_patch_type), intent(in) :: src
      type(tangential_patch_type), intent(inout) :: dst
      dst%nx = src%nx
      dst%ny = src%ny
      dst%fx = src%fx
      dst%fy = src%fy
      dst%mz = src%mz
      dst%fn = src%fn
      dst%fx_norm = src%fx_norm
      dst%fy_norm = src%fy_norm
      dst%coulomb_ratio = src%coulomb_ratio
      dst%adhesion_fraction = src%adhesion_fraction
      dst%parabolic_load_ratio = src%parabolic_load_ratio
      dst%fy_track = src%fy_track
      dst%fz_track = src%fz_track
      dst%dy = src%dy
      call copy_matrix(src%x, dst%x)
      call copy_vector(src%y, dst%y)
      call copy_vector(src%dx, dst%dx)
      call copy_matrix(src%pn, dst%pn)
      call copy_matrix(src%px, dst%px)
      call copy_matrix(src%py, dst%py)
      call copy_matrix(src%slip, dst%slip)
      if (.not. allocated(src%state)) then
         if (allocated(dst%state)) deallocate (dst%state)
         return
      end if
      if (allocated(dst%state)) then
         if (any(shape(dst%state) /= shape(src%state))) deallocate (dst%state)
      end if
      if (.not. allocated(dst%state)) allocate (dst%state(size(src%state, 1), &
         size(src%state, 2)))
      dst%state(:, :) = src%state
   end subroutine copy_tangential

   !> dst(:) = src, reallocating dst only when its size differs (or src is unallocated).
   pure subroutine copy_vector(src, dst)
      real(wp), allocatable, intent(in) :: src(:)
      real(wp), allocatable, intent(inout) :: dst(:)
      if (.not. allocated(src)) then
         if (allocated(dst)) deallocate (dst)
         return
      end if
      if (allocated(dst)) then
         if (size(dst) /= size(src)) deallocate (dst)
      end if
      if (.not. allocated(dst)) allocate (dst(size(src)))
      dst(:) = src
   end subroutine copy_vector

   !> dst(:, :) = src, reallocating dst only when its shape differs (or src is unallocated).
   pure subroutine copy_matrix(src, dst)
      real(wp), allocatable, intent(in) :: src(:, :)
      real(wp), allocatable, intent(inout) :: dst(:, :)
      if (.not. allocated(src)) then
         if (allocated(dst)) deallocate (dst)
         return
      end if
      if (allocated(dst)) then
         if (any(shape(dst) /= shape(src))) deallocate (dst)
      end if
      if (.not. allocated(dst)) allocate (dst(size(src, 1), size(src, 2)))
      dst(:, :) = src
   end subroutine copy_matrix

   !> Change G, ν and μ. A new G or ν prepares the normal problem again at the next solve; μ
   !> alone only changes the tangential solution.
   subroutine set_material(self, material, error)
      !> The solver.
      class(contact_solver_type), intent(inout) :: self
      !> The new data.
      type(material_type), intent(in) :: material
      !> Set for non-physical data (the solver keeps its old data).
      type(error_type), allocatable, intent(out) :: error

      call check_finite_data(material, self%track, error)
      if (allocated(error)) return
      call check_material(material, error)
      if (allocated(error)) return
      if (.not. (same(material%shear_modulus, self%material%shear_modulus) .and. &
         same(material%poisson, self%material%poisson))) call forget_normal(self)
      self%material = material
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
         call check_grid_cells(normal, self%tangential_options, error)
      else if (present(tangential)) then
         call check_grid_cells(self%normal_options, tangential, error)
      end if
      if (allocated(error)) return
      if (present(normal)) then
         self%normal_options = normal
         call forget_normal(self)
      end if
      if (present(tangential)) self%tangential_options = tangential
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
      new_track = self%track
      new_options = self%contact_options
      if (present(track)) new_track = track
      if (present(contact_options)) new_options = contact_options
      call check_finite_data(self%material, new_track, error)
      if (allocated(error)) return
      call prepare_profiles(self%wheel, self%rail, new_track, new_options, prepared, error)
      if (allocated(error)) return
      self%track = new_track
      self%contact_options = new_options
      self%prepared = prepared
      self%has_geometry = .false.
      self%has_yawed = .false.
      self%yaw_table%ready = .false.
      call forget_normal(self)
   end subroutine set_track

   !> The current material.
   pure function get_material(self) result(material)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      type(material_type) :: material
      material = self%material
   end function get_material

   !> The current normal and tangential options.
   pure subroutine get_options(self, normal, tangential)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      !> The normal options.
      type(normal_options_type), intent(out) :: normal
      !> The tangential options.
      type(tangential_options_type), intent(out) :: tangential
      normal = self%normal_options
      tangential = self%tangential_options
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
      options = self%contact_options
   end function get_contact_options

   !> The current track.
   pure function get_track(self) result(track)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      type(track_type) :: track
      track = self%track
   end function get_track

   !> The wheel and rail profiles as [[init]] took them (a file's read and cleaned, a built-in
   !> one as it is; before smoothing and placing), e.g. to pass them on as arrays.
   pure subroutine get_profiles(self, wheel, rail)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      !> The profiles (canonical form, doc/theory.md §5.1).
      type(profile_type), intent(out) :: wheel, rail
      wheel = self%wheel
      rail = self%rail
   end subroutine get_profiles

   !> True once [[init]] has succeeded.
   pure logical function is_ready(self)
      !> The solver.
      class(contact_solver_type), intent(in) :: self
      is_ready = self%ready
   end function is_ready

   !> Bitwise equality: the cache keys of the last call are reused only for the very same input.
   elemental logical function same(a, b)
      real(wp), intent(in) :: a, b
      same = transfer(a, 0_i8) == transfer(b, 0_i8)
   end function same

   !> The normal problem must be prepared and solved again.
   pure subroutine forget_normal(self)
      type(contact_solver_type), intent(inout) :: self
      self%n_prepared = 0
      self%has_normal = .false.
   end subroutine forget_normal

   !> Back to the state of a new object (keeps no data of an earlier init).
   pure subroutine reset(self)
      class(contact_solver_type), intent(inout) :: self
      self%ready = .false.
      self%has_geometry = .false.
      self%has_yawed = .false.
      self%yaw_table%ready = .false.
      self%has_normal = .false.
      self%n_prepared = 0
      self%n_loaded = 0
      self%side = side_right
      self%track = track_type()
      self%material = material_type()
      self%contact_options = contact_options_type()
      self%normal_options = normal_options_type()
      self%tangential_options = tangential_options_type()
   end subroutine reset

   !> The name of a load mode, for messages.
   pure function load_mode_name(mode) result(name)
      !> A load mode code.
      integer, intent(in) :: mode
      character(len=:), allocatable :: name
      if (mode >= 1 .and. mode <= size(load_mode_names)) then
         name = trim(load_mode_names(mode))
      else
         name = 'unknown'
      end if
   end function load_mode_name

end module shcontact_api_solver
