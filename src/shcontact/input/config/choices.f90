!> The registry of the case file's own choice options (issue 26): those that are not options of
!> a solver layer (whose registries are shcontact_normal_option_registry and
!> shcontact_tangential_option_registry): the wheel side, the kinematic and load modes, the
!> longitudinal curvature, the output precision and fields, the sweep mode, and the profile
!> files' formats and mirroring. Each choice has its name, its integer code (the value the
!> configuration holds after reading, [[shcontact_input_config_types]]) and a description.
module shcontact_input_config_choices
   use shcontact_core_choices, only: choice_type, choice_name
   use shcontact_geometry_track, only: side_right, side_left
   implicit none
   private

   public :: side_choices, kinematics_mode_choices, load_mode_choices, curvature_choices, &
      strip_table_choices
   public :: precision_choices, sweep_mode_choices, format_choices, mirror_choices, field_choices
   public :: side_right, side_left
   public :: kinematics_off, kinematics_on
   public :: load_mode_force, load_mode_vertical, load_mode_approach, load_mode_shared
   public :: load_mode_uses, load_quantities, load_mode_reading
   public :: curvature_local, curvature_reference, tables_planar, tables_conformal
   public :: precision_double, precision_single
   public :: sweep_grid, sweep_list

   !> `&kinematics mode`: prescribed creepages, or creepages from the wheelset motion.
   integer, parameter :: kinematics_off = 1, kinematics_on = 2
   !> `&load mode`; the codes are those of the library's `contact_load_type` (`load_normal_force`,
   !> `load_vertical_force`, `load_approach` of shcontact_api_solver; test `registry`).
   integer, parameter :: load_mode_force = 1, load_mode_vertical = 2, load_mode_approach = 3, &
      load_mode_shared = 4
   !> The `&load` quantities, each read by some modes only ([[load_mode_uses]]), and the mode
   !> that reads each (`normal_force` also by 'shared-force').
   character(len=*), parameter :: load_quantities(3) = [character(len=14) :: 'normal_force', &
      'approach', 'vertical_force']
   integer, parameter :: load_quantity_modes(3) = [load_mode_force, load_mode_approach, &
      load_mode_vertical]
   !> `&normal longitudinal_curvature`: γ(y) or γ₀ in A(y).
   integer, parameter :: curvature_local = 1, curvature_reference = 2
   !> `&normal strip_tables`: in the plane of the first contact or along the rail's surface.
   integer, parameter :: tables_planar = 1, tables_conformal = 2
   !> `&output precision` of the per-element fields.
   integer, parameter :: precision_double = 1, precision_single = 2
   !> `&sweep mode`.
   integer, parameter :: sweep_grid = 1, sweep_list = 2

   !> `&track side` (codes: the side factor of shcontact_geometry_track).
   type(choice_type), parameter :: side_choices(*) = [ &
      choice_type('right', side_right, 'the right wheel on the right rail'), &
      choice_type('left', side_left, 'the left wheel on the left rail (mirrored)')]
   !> `&kinematics mode`.
   type(choice_type), parameter :: kinematics_mode_choices(*) = [ &
      choice_type('off', kinematics_off, 'prescribed creepages (&creepage)'), &
      choice_type('on', kinematics_on, 'creepages from the wheelset motion')]
   !> `&load mode`.
   type(choice_type), parameter :: load_mode_choices(*) = [ &
      choice_type('force', load_mode_force, 'normal force on the first (deepest) patch'), &
      choice_type('approach', load_mode_approach, 'rigid approach of that patch'), &
      choice_type('vertical', load_mode_vertical, 'vertical wheel load shared by all patches'), &
      choice_type('shared-force', load_mode_shared, &
      'normal force shared by the patches that touch (sum = normal_force)')]
   !> `&normal longitudinal_curvature`.
   type(choice_type), parameter :: curvature_choices(*) = [ &
      choice_type('local', curvature_local, 'A(y) = cos(gamma(y))/(2 r_w)'), &
      choice_type('reference', curvature_reference, 'A(y) = cos(gamma0)/(2 r_w)')]
   !> `&normal strip_tables`.
   type(choice_type), parameter :: strip_table_choices(*) = [ &
      choice_type('planar', tables_planar, 'strips in the plane of the first contact, gaps '// &
      'along its normal'), &
      choice_type('conformal', tables_conformal, 'strips along the rail''s arc length, gaps '// &
      'along each point''s rail normal')]
   !> `&output precision`.
   type(choice_type), parameter :: precision_choices(*) = [ &
      choice_type('double', precision_double, '64-bit per-element fields'), &
      choice_type('single', precision_single, '32-bit per-element fields')]
   !> `&sweep mode`.
   type(choice_type), parameter :: sweep_mode_choices(*) = [ &
      choice_type('grid', sweep_grid, 'every combination of the lists'), &
      choice_type('list', sweep_list, 'case i takes the i-th value of every list')]
   !> `&profiles wheel_format, rail_format` (kept as text: the profile reader's format names).
   type(choice_type), parameter :: format_choices(*) = [ &
      choice_type('auto', 1, 'by extension: .prw/.prr SIMPACK, .whl/.ban MiniProf, else plain'), &
      choice_type('plain', 2, 'two columns y z'), &
      choice_type('simpack', 3, 'SIMPACK .prw/.prr'), &
      choice_type('miniprof', 4, 'MiniProf .whl/.ban')]
   !> `&profiles *_mirror_y, *_mirror_z` (kept as text).
   type(choice_type), parameter :: mirror_choices(*) = [ &
      choice_type('auto', 1, 'as the file or its format says'), &
      choice_type('yes', 2, 'mirror'), &
      choice_type('no', 3, 'do not mirror')]
   !> `&output fields` (a list, kept as text).
   type(choice_type), parameter :: field_choices(*) = [ &
      choice_type('auto', 1, 'all for a single case, none in a sweep'), &
      choice_type('all', 2, 'every field'), &
      choice_type('none', 3, 'no field'), &
      choice_type('geometry', 4, 'the contact geometry'), &
      choice_type('strips', 5, 'the strip table'), &
      choice_type('pressure', 6, 'the pressure'), &
      choice_type('traction', 7, 'the tractions'), &
      choice_type('state', 8, 'the stick/slip state'), &
      choice_type('slip', 9, 'the slip')]

contains

   !> Whether `&load mode` (its code) reads the load quantity `name` (one of [[load_quantities]],
   !> or the sweep axis of the same name): `normal_force` by 'force' and 'shared-force',
   !> `approach` by 'approach', `vertical_force` by 'vertical'.
   pure logical function load_mode_uses(name, mode)
      character(len=*), intent(in) :: name
      integer, intent(in) :: mode
      integer :: k
      k = findloc(load_quantities, name, dim=1)
      load_mode_uses = .false.
      if (k == 0) return
      load_mode_uses = mode == load_quantity_modes(k) .or. &
         (mode == load_mode_shared .and. load_quantity_modes(k) == load_mode_force)
   end function load_mode_uses

   !> The `&load mode` name that reads a load quantity ([[load_mode_uses]]; `normal_force` is
   !> read by 'shared-force' too): 'force', 'approach' or 'vertical' ('force' for a name that
   !> is none of [[load_quantities]]).
   pure function load_mode_reading(name) result(mode)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: mode
      integer :: k
      k = findloc(load_quantities, name, dim=1)
      if (k == 0) k = 1
      mode = trim(choice_name(load_mode_choices, load_quantity_modes(k)))
   end function load_mode_reading

end module shcontact_input_config_choices
