!> The case configuration: Fortran namelist case files, `group%var=value` overrides, defaults,
!> validation into a typed configuration, and the resolved configuration printed as a namelist.
!>
!> A case file holds any of the groups `&profiles &track &position &kinematics &material &load
!> &creepage &normal &tangential &output &sweep`, each optional and partial; whatever is not
!> given keeps its default (the seed's headline case). `&kinematics mode = 'on'` switches from
!> prescribed creepages (`&creepage`) to creepages from the wheelset motion; that mode's own
!> rules (no `&creepage`, spin model 'additive', vertical load by default) are applied by
!> [[validate_config]]. Every assignment is read on its own, through a
!> one-assignment namelist on an internal file, so that an error names the file, the line, the
!> group, the variable, the value found and what is allowed. The same path serves the overrides
!> of the command line. After all assignments, [[validate_config]] checks ranges and choices once;
!> downstream code trusts the result.
module shcontact_io_config
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: to_lower, str_int
   use shcontact_io_text, only: format_real, quote_string, strip_quotes
   use shcontact_io_files, only: directory_part, join_path
   use shcontact_core_textfile, only: text_line_type, read_text_lines
   use shcontact_geometry_kinematics, only: max_yaw, pure_rolling_pitch_rate
   use shcontact_profile_reader, only: profile_file_format
   implicit none
   private

   public :: case_config_type, sweep_axis_type, case_point_type
   public :: load_config, read_config_file, read_config_text, apply_override, validate_config
   public :: config_namelist
   public :: n_sweep_axes, sweep_axis_names, axis_geometry, axis_load, axis_tangential
   public :: path_len, name_len, max_sweep_values, bound_choices, spin_model_choices
   public :: case_point_value, is_kinematic_input
   public :: max_cases, max_grid_cells

   !> Length of file-name variables.
   integer, parameter :: path_len = 512
   !> Length of choice variables (method names, modes).
   integer, parameter :: name_len = 32
   !> Most values one real sweep list may hold.
   integer, parameter :: max_sweep_values = 100000
   !> Most values one choice sweep list (bound, spin_model) may hold.
   integer, parameter :: max_label_values = 16
   !> Most entries of `output%fields`.
   integer, parameter :: max_fields = 16
   !> Most cases of one run (a sweep grid).
   integer, parameter :: max_cases = 100000000
   !> Most cells of one patch grid, &normal n_strips × &tangential n_elements: every thread
   !> holds a few arrays of this size per patch (doc/app.md, "Limits").
   integer, parameter :: max_grid_cells = 1000000
   !> Longest line of a case file.
   integer, parameter :: max_line_length = 4095

   ! Kinds of namelist variables.
   integer, parameter :: k_real = 1, k_int = 2, k_string = 3, k_logical = 4, k_real_list = 5, &
      k_string_list = 6

   !> Sweepable quantities, in loop order (outermost first): geometry, then load, then the
   !> tangential inputs, so that consecutive cases share geometry and normal solution.
   !> The wheelset velocities (`&kinematics`) are swept only in kinematic mode, the creepages
   !> (`&creepage`) only in prescribed-creepage mode.
   integer, parameter :: n_sweep_axes = 18
   character(len=*), parameter :: sweep_axis_names(n_sweep_axes) = [character(len=16) :: &
      't_y', 'roll', 'yaw', 'normal_force', 'approach', 'vertical_force', 'friction', 'bound', &
      'spin_model', 'v_forward', 'v_lateral', 'v_vertical', 'roll_rate', 'yaw_rate', &
      'pitch_rate', 'nu_x', 'nu_y', 'phi']
   !> Which stage an axis changes: 1 geometry, 2 normal load, 3 tangential only.
   integer, parameter :: axis_geometry = 1, axis_load = 2, axis_tangential = 3
   integer, parameter :: axis_stage(n_sweep_axes) = [1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, &
      3, 3, 3, 3, 3]
   !> The wheelset inputs of a kinematic case (position and velocities), in axis order.
   character(len=*), parameter :: kinematic_inputs(9) = [character(len=10) :: 't_y', 'roll', &
      'yaw', 'v_forward', 'v_lateral', 'v_vertical', 'roll_rate', 'yaw_rate', 'pitch_rate']

   !> Where a variable lives and what it is (messages, printing, documentation).
   type :: variable_info_type
      character(len=12) :: group = ''
      character(len=24) :: name = ''
      integer :: kind = k_real
      character(len=12) :: units = ''
      character(len=100) :: help = ''
   end type variable_info_type

   type(variable_info_type), parameter :: variables(*) = [ &
      variable_info_type('profiles', 'wheel', k_string, '', &
      "'builtin:S1002' or a wheel profile file (.prw, .whl, 2-column y z)"), &
      variable_info_type('profiles', 'rail', k_string, '', &
      "'builtin:UIC60' or a rail profile file (.prr, .ban, 2-column y z)"), &
      variable_info_type('profiles', 'wheel_format', k_string, '', &
      "'auto' (by extension), 'plain', 'simpack', 'miniprof'"), &
      variable_info_type('profiles', 'rail_format', k_string, '', &
      "'auto' (by extension), 'plain', 'simpack', 'miniprof'"), &
      variable_info_type('profiles', 'wheel_smoothing', k_real, 'mm', &
      'smoothing length L_filt of the wheel spline (0 = interpolation)'), &
      variable_info_type('profiles', 'rail_smoothing', k_real, 'mm', &
      'smoothing length L_filt of the rail spline (0 = interpolation)'), &
      variable_info_type('profiles', 'wheel_mirror_y', k_string, '', &
      "wheel file: 'auto' (as the file/format says), 'yes' (y -> -y) or 'no'"), &
      variable_info_type('profiles', 'wheel_mirror_z', k_string, '', &
      "wheel file: 'auto' (as the file/format says), 'yes' (z -> -z) or 'no'"), &
      variable_info_type('profiles', 'wheel_scale', k_real, '', &
      'wheel file: factor from its units to mm (0 = as the file/format says)'), &
      variable_info_type('profiles', 'rail_mirror_y', k_string, '', &
      "rail file: 'auto' (as the file/format says), 'yes' (y -> -y) or 'no'"), &
      variable_info_type('profiles', 'rail_mirror_z', k_string, '', &
      "rail file: 'auto' (as the file/format says), 'yes' (z -> -z) or 'no'"), &
      variable_info_type('profiles', 'rail_scale', k_real, '', &
      'rail file: factor from its units to mm (0 = as the file/format says)'), &
      variable_info_type('track', 'side', k_string, '', "'right' or 'left' wheel and rail"), &
      variable_info_type('track', 'gauge', k_real, 'mm', 'track gauge'), &
      variable_info_type('track', 'gauge_height', k_real, 'mm', &
      'gauge measured this far below the rail top'), &
      variable_info_type('track', 'inclination', k_real, '1', &
      'rail inclination as a slope towards the track centre (1:40 = 0.025)'), &
      variable_info_type('track', 'rail_canted', k_logical, '', &
      '.true. when the rail profile is already canted (Manchester .prr)'), &
      variable_info_type('track', 'flange_back_distance', k_real, 'mm', &
      'distance between the flange backs of the wheelset'), &
      variable_info_type('track', 'flange_back_position', k_real, 'mm', &
      'flange-back position in wheel-profile coordinates (S1002: -70)'), &
      variable_info_type('track', 'nominal_radius', k_real, 'mm', &
      'nominal wheel rolling radius R0 (at the tape circle)'), &
      variable_info_type('position', 't_y', k_real, 'mm', &
      "lateral wheelset shift (CONTACT's Y_WS), + moves the wheel to the field side"), &
      variable_info_type('position', 'roll', k_real, 'rad', 'wheelset roll angle'), &
      variable_info_type('kinematics', 'mode', k_string, '', &
      "'off' (prescribed &creepage) or 'on' (creepages from the wheelset motion)"), &
      variable_info_type('kinematics', 'yaw', k_real, 'rad', &
      "wheelset yaw angle (CONTACT's YAW_WS), + turns the front towards +y"), &
      variable_info_type('kinematics', 'v_forward', k_real, 'mm/s', &
      "forward speed of the wheelset centre V (CONTACT's VS)"), &
      variable_info_type('kinematics', 'v_lateral', k_real, 'mm/s', &
      'lateral velocity of the wheelset centre, + towards the right field side'), &
      variable_info_type('kinematics', 'v_vertical', k_real, 'mm/s', &
      'vertical velocity of the wheelset centre, + downwards'), &
      variable_info_type('kinematics', 'roll_rate', k_real, 'rad/s', 'wheelset roll rate'), &
      variable_info_type('kinematics', 'yaw_rate', k_real, 'rad/s', 'wheelset yaw rate'), &
      variable_info_type('kinematics', 'pitch_rate', k_real, 'rad/s', &
      'angular velocity about the axle, < 0 rolling forward (default -v_forward/nominal_radius)'), &
      variable_info_type('material', 'shear_modulus', k_real, 'MPa', &
      'shear modulus G of wheel and rail'), &
      variable_info_type('material', 'poisson', k_real, '1', "Poisson's ratio nu"), &
      variable_info_type('material', 'friction', k_real, '1', 'coefficient of friction mu'), &
      variable_info_type('load', 'mode', k_string, '', &
      "'force' (normal force on the patch), 'approach', 'vertical' (wheel load)"), &
      variable_info_type('load', 'normal_force', k_real, 'N', "normal force N (mode 'force')"), &
      variable_info_type('load', 'approach', k_real, 'mm', "rigid approach (mode 'approach')"), &
      variable_info_type('load', 'vertical_force', k_real, 'N', &
      "vertical wheel load shared by the patches (mode 'vertical')"), &
      variable_info_type('creepage', 'nu_x', k_real, '1', 'longitudinal creepage'), &
      variable_info_type('creepage', 'nu_y', k_real, '1', 'lateral creepage'), &
      variable_info_type('creepage', 'phi', k_real, 'rad/mm', 'spin creepage'), &
      variable_info_type('normal', 'method', k_string, '', "'semi-hertz' or 'hertz'"), &
      variable_info_type('normal', 'reduction', k_string, '', &
      "'local-hertz', 'constant' or 'coupled'"), &
      variable_info_type('normal', 'epsilon', k_real, '1', &
      "penetration reduction of reduction = 'constant'"), &
      variable_info_type('normal', 'n_strips', k_int, '', 'number of strips per patch'), &
      variable_info_type('normal', 'b_min', k_real, '1/mm', &
      'smallest lateral relative curvature B (concave gap curvature is clamped to it)'), &
      variable_info_type('normal', 'longitudinal_curvature', k_string, '', &
      "A(y) = cos(gamma)/(2 r_w): 'local' gamma(y) or 'reference' gamma0"), &
      variable_info_type('tangential', 'method', k_string, '', "'fastsim-sh' or 'fastsim'"), &
      variable_info_type('tangential', 'bound', k_string, '', &
      "'ellipsoidal', 'parabolic', 'weighted', 'weighted-slip', 'clipped'"), &
      variable_info_type('tangential', 'spin_model', k_string, '', &
      "'additive', 'uniform', 'scaled', 'geometric'"), &
      variable_info_type('tangential', 'spin_flexibility', k_string, '', &
      "flexibility of the spin part of the longitudinal slip: 'longitudinal' (L_x, seed eq 21) "// &
      "or 'spin' (L_phi, Kalker's FASTSIM)"), &
      variable_info_type('tangential', 'n_elements', k_int, '', &
      'number of elements per strip (n_x)'), &
      variable_info_type('output', 'file', k_string, '', 'HDF5 output file'), &
      variable_info_type('output', 'fields', k_string_list, '', &
      "'auto', 'all', 'none' or from 'geometry', 'strips', 'pressure', 'traction', 'state', 'slip'"), &
      variable_info_type('output', 'precision', k_string, '', &
      "'double' or 'single' (per-element fields)"), &
      variable_info_type('output', 'compression', k_int, '', &
      'deflate level of the fields, 0 (off) to 9'), &
      variable_info_type('output', 'checkpoint_cases', k_int, '', &
      'cases per checkpoint block of a sweep (0 = automatic)'), &
      variable_info_type('sweep', 'mode', k_string, '', &
      "'grid' (every combination) or 'list' (i-th value of every list)"), &
      variable_info_type('sweep', 't_y', k_real_list, 'mm', 'values of position%t_y'), &
      variable_info_type('sweep', 't_y_points', k_int, '', &
      't_y = first, last with this many points (0: t_y is a list)'), &
      variable_info_type('sweep', 'roll', k_real_list, 'rad', 'values of position%roll'), &
      variable_info_type('sweep', 'roll_points', k_int, '', &
      'roll = first, last with this many points'), &
      variable_info_type('sweep', 'yaw', k_real_list, 'rad', 'values of kinematics%yaw'), &
      variable_info_type('sweep', 'yaw_points', k_int, '', &
      'yaw = first, last with this many points'), &
      variable_info_type('sweep', 'normal_force', k_real_list, 'N', &
      'values of load%normal_force'), &
      variable_info_type('sweep', 'normal_force_points', k_int, '', &
      'normal_force = first, last with this many points'), &
      variable_info_type('sweep', 'approach', k_real_list, 'mm', 'values of load%approach'), &
      variable_info_type('sweep', 'approach_points', k_int, '', &
      'approach = first, last with this many points'), &
      variable_info_type('sweep', 'vertical_force', k_real_list, 'N', &
      'values of load%vertical_force'), &
      variable_info_type('sweep', 'vertical_force_points', k_int, '', &
      'vertical_force = first, last with this many points'), &
      variable_info_type('sweep', 'friction', k_real_list, '1', 'values of material%friction'), &
      variable_info_type('sweep', 'friction_points', k_int, '', &
      'friction = first, last with this many points'), &
      variable_info_type('sweep', 'bound', k_string_list, '', 'values of tangential%bound'), &
      variable_info_type('sweep', 'spin_model', k_string_list, '', &
      'values of tangential%spin_model'), &
      variable_info_type('sweep', 'v_forward', k_real_list, 'mm/s', &
      'values of kinematics%v_forward'), &
      variable_info_type('sweep', 'v_forward_points', k_int, '', &
      'v_forward = first, last with this many points'), &
      variable_info_type('sweep', 'v_lateral', k_real_list, 'mm/s', &
      'values of kinematics%v_lateral'), &
      variable_info_type('sweep', 'v_lateral_points', k_int, '', &
      'v_lateral = first, last with this many points'), &
      variable_info_type('sweep', 'v_vertical', k_real_list, 'mm/s', &
      'values of kinematics%v_vertical'), &
      variable_info_type('sweep', 'v_vertical_points', k_int, '', &
      'v_vertical = first, last with this many points'), &
      variable_info_type('sweep', 'roll_rate', k_real_list, 'rad/s', &
      'values of kinematics%roll_rate'), &
      variable_info_type('sweep', 'roll_rate_points', k_int, '', &
      'roll_rate = first, last with this many points'), &
      variable_info_type('sweep', 'yaw_rate', k_real_list, 'rad/s', &
      'values of kinematics%yaw_rate'), &
      variable_info_type('sweep', 'yaw_rate_points', k_int, '', &
      'yaw_rate = first, last with this many points'), &
      variable_info_type('sweep', 'pitch_rate', k_real_list, 'rad/s', &
      'values of kinematics%pitch_rate'), &
      variable_info_type('sweep', 'pitch_rate_points', k_int, '', &
      'pitch_rate = first, last with this many points'), &
      variable_info_type('sweep', 'nu_x', k_real_list, '1', 'values of creepage%nu_x'), &
      variable_info_type('sweep', 'nu_x_points', k_int, '', &
      'nu_x = first, last with this many points'), &
      variable_info_type('sweep', 'nu_y', k_real_list, '1', 'values of creepage%nu_y'), &
      variable_info_type('sweep', 'nu_y_points', k_int, '', &
      'nu_y = first, last with this many points'), &
      variable_info_type('sweep', 'phi', k_real_list, 'rad/mm', 'values of creepage%phi'), &
      variable_info_type('sweep', 'phi_points', k_int, '', &
      'phi = first, last with this many points') &
      ]

   character(len=*), parameter :: group_names(*) = [character(len=12) :: 'profiles', 'track', &
      'position', 'kinematics', 'material', 'load', 'creepage', 'normal', 'tangential', &
      'output', 'sweep']

   !> Allowed values of the choice variables.
   character(len=*), parameter :: mirror_choices(*) = [character(len=4) :: 'auto', 'yes', 'no']
   character(len=*), parameter :: formats(*) = [character(len=8) :: 'auto', 'plain', 'simpack', &
      'miniprof']
   character(len=*), parameter :: sides(*) = [character(len=5) :: 'right', 'left']
   character(len=*), parameter :: load_modes(*) = [character(len=8) :: 'force', 'approach', &
      'vertical']
   character(len=*), parameter :: normal_methods(*) = [character(len=10) :: 'semi-hertz', 'hertz']
   character(len=*), parameter :: curvature_modes(*) = [character(len=9) :: 'local', &
      'reference']
   character(len=*), parameter :: reductions(*) = [character(len=11) :: 'local-hertz', 'constant', &
      'coupled']
   character(len=*), parameter :: tangential_methods(*) = [character(len=10) :: 'fastsim-sh', &
      'fastsim']
   !> The traction bounds and spin models (physics.md decisions 9, 10).
   character(len=*), parameter :: bounds(*) = [character(len=13) :: 'ellipsoidal', 'parabolic', &
      'weighted', 'weighted-slip', 'clipped']
   character(len=*), parameter :: spin_models(*) = [character(len=9) :: 'additive', 'uniform', &
      'scaled', 'geometric']
   character(len=*), parameter :: spin_flexibilities(*) = [character(len=12) :: &
      'longitudinal', 'spin']
   character(len=*), parameter :: bound_choices(*) = bounds, spin_model_choices(*) = spin_models
   character(len=*), parameter :: field_names(*) = [character(len=8) :: 'auto', 'all', 'none', &
      'geometry', 'strips', 'pressure', 'traction', 'state', 'slip']
   character(len=*), parameter :: precisions(*) = [character(len=6) :: 'double', 'single']
   character(len=*), parameter :: sweep_modes(*) = [character(len=4) :: 'grid', 'list']
   character(len=*), parameter :: kinematics_modes(*) = [character(len=3) :: 'off', 'on']

   !> Sentinel of unset sweep-list entries.
   real(wp), parameter :: unset = huge(1.0_wp)

   !> `&profiles`: which profiles, read how.
   type :: profiles_config_type
      !> Wheel profile: `builtin:S1002` or a file name (relative names are taken from the
      !> directory of the case file that sets them).
      character(len=path_len) :: wheel = 'builtin:S1002'
      !> Rail profile: `builtin:UIC60` or a file name.
      character(len=path_len) :: rail = 'builtin:UIC60'
      !> File formats: 'auto', 'plain', 'simpack', 'miniprof'.
      character(len=name_len) :: wheel_format = 'auto', rail_format = 'auto'
      !> Smoothing lengths L_filt (mm); 0 interpolates.
      real(wp) :: wheel_smoothing = 0.0_wp, rail_smoothing = 0.0_wp
      !> Mirror y or z of a profile file: 'auto' (the file's or format's convention), 'yes',
      !> 'no' (CONTACT's MIRRORY/MIRRORZ).
      character(len=name_len) :: wheel_mirror_y = 'auto', wheel_mirror_z = 'auto'
      character(len=name_len) :: rail_mirror_y = 'auto', rail_mirror_z = 'auto'
      !> Factor from a profile file's units to mm; 0: the file's or format's (CONTACT's SCALE).
      real(wp) :: wheel_scale = 0.0_wp, rail_scale = 0.0_wp
   end type profiles_config_type

   !> `&track`: track and wheelset dimensions (physics.md §5.2).
   type :: track_config_type
      !> 'right' or 'left'.
      character(len=name_len) :: side = 'right'
      !> Track gauge (mm), measured `gauge_height` below the rail top.
      real(wp) :: gauge = 1435.0_wp, gauge_height = 14.0_wp
      !> Rail inclination as a slope towards the track centre (1:40).
      real(wp) :: inclination = 0.025_wp
      !> The rail profile is already canted: the inclination is not applied again.
      logical :: rail_canted = .false.
      !> Flange-back distance and flange-back position in wheel-profile coordinates (mm).
      real(wp) :: flange_back_distance = 1360.0_wp, flange_back_position = -70.0_wp
      !> Nominal rolling radius R₀ (mm).
      real(wp) :: nominal_radius = 460.0_wp
   end type track_config_type

   !> `&position`: wheelset position.
   type :: position_config_type
      !> Lateral shift (mm), CONTACT's Y_WS (physics.md decision 13). The seed's "t_y = 5.8 mm"
      !> measured between the profile origins corresponds to Y_WS = 10.533 − 5.8 = 4.733 mm,
      !> where the geometric spin equals the seed's φ = 0.274 1/m (../shared/reference/README.md).
      real(wp) :: t_y = 4.733_wp
      !> Roll angle (rad).
      real(wp) :: roll = 0.0_wp
   end type position_config_type

   !> `&kinematics`: the wheelset's motion (CONTACT's module 1, physics.md decision 14). With
   !> mode 'on' the creepages of every patch come from the rigid-body motion of the wheelset
   !> (the library's `solve_kinematic`) instead of `&creepage`; the lateral shift and the roll
   !> are those of `&position`. Track frame: x forward, y towards the right field side, z down.
   type :: kinematics_config_type
      !> 'off' (prescribed creepages, `&creepage`) or 'on'.
      character(len=name_len) :: mode = 'off'
      !> Yaw angle ψ (rad), CONTACT's YAW_WS.
      real(wp) :: yaw = 0.0_wp
      !> Forward speed of the wheelset centre V (mm/s, > 0): 30 m/s.
      real(wp) :: v_forward = 30000.0_wp
      !> Lateral and vertical velocity of the wheelset centre (mm/s).
      real(wp) :: v_lateral = 0.0_wp, v_vertical = 0.0_wp
      !> Roll and yaw rate (rad/s).
      real(wp) :: roll_rate = 0.0_wp, yaw_rate = 0.0_wp
      !> Angular velocity about the axle (rad/s, < 0 rolling forward); used only when given
      !> (`pitch_rate_given`), else pure rolling −V/R₀ of each case's V.
      real(wp) :: pitch_rate = 0.0_wp
      !> True when `pitch_rate` was set (case file or override); set by [[validate_config]].
      logical :: pitch_rate_given = .false.
   end type kinematics_config_type

   !> `&load`: how the normal problem is loaded.
   type :: load_config_type
      !> 'force', 'approach' or 'vertical'.
      character(len=name_len) :: mode = 'force'
      !> Normal force on the patch (N), rigid approach (mm), vertical wheel load (N).
      real(wp) :: normal_force = 64700.0_wp, approach = 0.05_wp, vertical_force = 64700.0_wp
   end type load_config_type

   !> `&creepage`: creepages at the geometric contact point (physics.md decision 2).
   type :: creepage_config_type
      !> ν_x, ν_y (dimensionless), φ (rad/mm).
      real(wp) :: nu_x = 0.58e-3_wp, nu_y = 0.061e-3_wp, phi = 2.74e-4_wp
   end type creepage_config_type

   !> `&normal`: the normal solver.
   type :: normal_config_type
      character(len=name_len) :: method = 'semi-hertz'
      character(len=name_len) :: reduction = 'local-hertz'
      real(wp) :: epsilon = 0.55_wp
      integer :: n_strips = 100
      !> Clamp of B(y) (1/mm), physics.md decision 4.
      real(wp) :: b_min = 1.0e-4_wp
      !> 'local' (cos γ(y)) or 'reference' (cos γ₀) in A(y).
      character(len=name_len) :: longitudinal_curvature = 'local'
   end type normal_config_type

   !> `&tangential`: the tangential solver.
   type :: tangential_config_type
      character(len=name_len) :: method = 'fastsim-sh'
      character(len=name_len) :: bound = 'weighted'
      character(len=name_len) :: spin_model = 'uniform'
      character(len=name_len) :: spin_flexibility = 'longitudinal'
      integer :: n_elements = 50
   end type tangential_config_type

   !> `&output`: the HDF5 file.
   type :: output_config_type
      character(len=path_len) :: file = 'shcontact.h5'
      !> Per-case fields to store ('auto': all for a single case, none in a sweep).
      character(len=name_len) :: fields(max_fields) = reshape([character(len=name_len) :: &
         'auto'], [max_fields], pad=[character(len=name_len) :: ''])
      character(len=name_len) :: precision = 'double'
      integer :: compression = 4
      integer :: checkpoint_cases = 0
   end type output_config_type

   !> One swept quantity.
   type :: sweep_axis_type
      !> True when values were given (the axis takes part in the sweep).
      logical :: active = .false.
      !> True for a choice axis (bound, spin_model): `labels` hold the values.
      logical :: is_label = .false.
      !> Values as given: a list, or (first, last) when `points` > 0.
      real(wp), allocatable :: given(:)
      !> Number of evenly spaced points from given(1) to given(2); 0 for a list.
      integer :: points = 0
      !> Values of a choice axis.
      character(len=name_len), allocatable :: labels(:)
   contains
      !> Number of values.
      procedure :: size => axis_size
      !> The i-th value of a real axis.
      procedure :: value => axis_value
   end type sweep_axis_type

   !> `&sweep`: the axes, indexed as [[sweep_axis_names]].
   type :: sweep_config_type
      character(len=name_len) :: mode = 'grid'
      type(sweep_axis_type) :: axes(n_sweep_axes)
   end type sweep_config_type

   !> Where a variable got its value (for messages).
   type :: origin_type
      character(len=40) :: key = ''
      character(len=:), allocatable :: where
   end type origin_type

   !> The resolved, validated configuration of a run.
   type :: case_config_type
      type(profiles_config_type) :: profiles
      type(track_config_type) :: track
      type(position_config_type) :: position
      type(kinematics_config_type) :: kinematics
      type(material_type) :: material
      type(load_config_type) :: load
      type(creepage_config_type) :: creepage
      type(normal_config_type) :: normal
      type(tangential_config_type) :: tangential
      type(output_config_type) :: output
      type(sweep_config_type) :: sweep
      !> Where each assigned variable was set.
      type(origin_type), allocatable :: origins(:)
      !> The case file ('' for the built-in default case), for messages about the case as a
      !> whole.
      character(len=:), allocatable :: case_file
   contains
      !> Number of cases of the run (1 without a sweep).
      procedure :: n_cases
      !> The inputs that vary, for case i (1-based).
      procedure :: case_point
      !> True when the named field is to be stored for each case.
      procedure :: wants_field
      !> Index of the first case of the run that has the same geometry (or normal solution).
      procedure :: shares_with
      !> True in kinematic mode (`&kinematics mode = 'on'`).
      procedure :: is_kinematic
      !> True when a sweep changes the contact geometry (t_y, roll or yaw) from case to case.
      procedure :: geometry_swept
      !> True when input axis `ia` is reported per case: swept, or a wheelset input of a
      !> kinematic run.
      procedure :: reports_input
   end type case_config_type

   !> The inputs of one case that a sweep may vary.
   type :: case_point_type
      real(wp) :: t_y = 0.0_wp, roll = 0.0_wp
      !> Wheelset yaw (rad), velocities (mm/s) and rates (rad/s) of a kinematic case; the pitch
      !> rate is resolved (pure rolling when not given).
      real(wp) :: yaw = 0.0_wp
      real(wp) :: normal_force = 0.0_wp, approach = 0.0_wp, vertical_force = 0.0_wp
      real(wp) :: friction = 0.0_wp
      character(len=name_len) :: bound = '', spin_model = ''
      real(wp) :: v_forward = 0.0_wp, v_lateral = 0.0_wp, v_vertical = 0.0_wp
      real(wp) :: roll_rate = 0.0_wp, yaw_rate = 0.0_wp, pitch_rate = 0.0_wp
      real(wp) :: nu_x = 0.0_wp, nu_y = 0.0_wp, phi = 0.0_wp
   end type case_point_type

   !> One `name = value` of a group, with where it came from.
   type :: assignment_type
      character(len=:), allocatable :: group, name, value, where
      integer :: n_items = 0
      integer :: longest_string = 0
   end type assignment_type

   !> Growable list of assignments.
   type :: assignment_list_type
      type(assignment_type), allocatable :: items(:)
      integer :: n = 0
   end type assignment_list_type

contains

   ! ------------------------------------------------------------------------------------------
   ! Public entry points
   ! ------------------------------------------------------------------------------------------

   !> Defaults, then the case file (when `filename` is not empty), then the overrides
   !> (`group%var=value`, in order), then validation.
   subroutine load_config(filename, overrides, config, error)
      !> Case file; '' for the built-in default case.
      character(len=*), intent(in) :: filename
      !> Overrides `group%var=value`.
      character(len=*), intent(in) :: overrides(:)
      !> The resolved configuration.
      type(case_config_type), intent(out) :: config
      !> Set on the first invalid input (stat_invalid_input) or unreadable file (stat_io).
      type(error_type), allocatable, intent(out) :: error
      integer :: i

      if (len_trim(filename) > 0) then
         call read_config_file(filename, config, error)
         if (allocated(error)) return
      end if
      do i = 1, size(overrides)
         call apply_override(config, overrides(i), error)
         if (allocated(error)) return
      end do
      call validate_config(config, error)
   end subroutine load_config

   !> Apply every assignment of a namelist case file onto `config`.
   subroutine read_config_file(filename, config, error)
      !> The case file.
      character(len=*), intent(in) :: filename
      !> Updated in place.
      type(case_config_type), intent(inout) :: config
      !> Set when the file cannot be read or holds an invalid assignment.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: lines(:)
      type(assignment_list_type) :: list
      integer :: i

      config%case_file = filename
      call read_lines(filename, lines, error)
      if (allocated(error)) return
      call parse_namelist(lines, filename, list, error)
      if (allocated(error)) return
      do i = 1, list%n
         call apply_assignment(config, list%items(i), directory_part(filename), error)
         if (allocated(error)) return
      end do
   end subroutine read_config_file

   !> A configuration from namelist text (as stored in an output file), validated.
   subroutine read_config_text(text, name, config, error)
      !> Namelist text, lines separated by new-line characters.
      character(len=*), intent(in) :: text
      !> What to call the text in messages.
      character(len=*), intent(in) :: name
      !> The configuration.
      type(case_config_type), intent(out) :: config
      !> Set when the text is not a valid configuration.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: lines(:)
      type(assignment_list_type) :: list
      integer :: i, n, start, next, longest

      n = 0
      longest = 1
      start = 1
      do while (start <= len(text))
         next = index(text(start:), new_line('a'))
         if (next == 0) next = len(text) - start + 2
         n = n + 1
         longest = max(longest, next - 1)
         start = start + next
      end do
      allocate (character(len=longest) :: lines(n))
      start = 1
      do i = 1, n
         next = index(text(start:), new_line('a'))
         if (next == 0) next = len(text) - start + 2
         lines(i) = text(start:start + next - 2)
         start = start + next
      end do
      call parse_namelist(lines, name, list, error)
      if (allocated(error)) return
      do i = 1, list%n
         call apply_assignment(config, list%items(i), '', error)
         if (allocated(error)) return
      end do
      call validate_config(config, error)
   end subroutine read_config_text

   !> Apply one override `group%var=value` (string values may be given without quotes).
   subroutine apply_override(config, text, error)
      !> Updated in place.
      type(case_config_type), intent(inout) :: config
      !> The override, e.g. `creepage%nu_x=1e-3` or `sweep%bound=weighted,clipped`.
      character(len=*), intent(in) :: text
      !> Set when the text is malformed or the assignment invalid.
      type(error_type), allocatable, intent(out) :: error
      type(assignment_type) :: a
      integer :: ipct, ieq, iv

      ipct = index(text, '%')
      ieq = index(text, '=')
      a%where = 'command line --set '//trim(text)
      if (ipct < 2 .or. ieq < ipct + 2) then
         call fatal_error(error, a%where//': expected group%variable=value, e.g. '// &
            'creepage%nu_x=1e-3')
         return
      end if
      a%group = to_lower(trim(adjustl(text(1:ipct - 1))))
      a%name = to_lower(trim(adjustl(text(ipct + 1:ieq - 1))))
      a%value = trim(adjustl(text(ieq + 1:)))
      if (len(a%value) == 0) then
         call fatal_error(error, a%where//': no value after "="; give one, e.g. '// &
            trim(text)//'VALUE (quote an empty text: '//trim(text)//"'')")
         return
      end if
      if (.not. any(group_names == a%group)) then
         call fatal_error(error, a%where//': unknown group "'//a%group//'"; the groups are '// &
            join_words(group_names, '', ''))
         return
      end if
      iv = find_variable(a%group, a%name)
      if (iv > 0) then
         if (variables(iv)%kind == k_string) then
            if (index("'"//'"', a%value(1:min(1, len(a%value)))) == 0) &
               a%value = quote_string(a%value)
         else if (variables(iv)%kind == k_string_list) then
            a%value = quote_items(a%value)
         end if
      end if
      call count_items(a%value, a%n_items, a%longest_string)
      call apply_assignment(config, a, '', error)
   end subroutine apply_override

   ! ------------------------------------------------------------------------------------------
   ! Reading a namelist file into assignments
   ! ------------------------------------------------------------------------------------------

   !> All lines of a case file (line ends and byte-order mark as shcontact_core_textfile).
   subroutine read_lines(filename, lines, error)
      character(len=*), intent(in) :: filename
      character(len=:), allocatable, intent(out) :: lines(:)
      type(error_type), allocatable, intent(out) :: error
      type(text_line_type), allocatable :: text(:)
      integer :: i, longest

      call read_text_lines(filename, 'case file', text, error)
      if (allocated(error)) return
      longest = 1
      do i = 1, size(text)
         if (len(text(i)%text) > max_line_length) then
            call fatal_error(error, filename//':'//str_int(i)//': line longer than '// &
               str_int(max_line_length)//' characters')
            return
         end if
         longest = max(longest, len(text(i)%text))
      end do
      allocate (character(len=longest) :: lines(size(text)))
      do i = 1, size(text)
         lines(i) = text(i)%text
      end do
   end subroutine read_lines

   !> Split namelist text into group assignments, checking the structure (groups opened with
   !> `&name`, closed with `/`, nothing but comments outside groups, each group at most once).
   subroutine parse_namelist(lines, filename, list, error)
      character(len=*), intent(in) :: lines(:)
      character(len=*), intent(in) :: filename
      type(assignment_list_type), intent(inout) :: list
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: group, token, value, vname
      character(len=12) :: seen(size(group_names))
      integer :: seen_line(size(group_names))
      integer :: il, pos, n, kind, vline, nseen, ig, n_items, longest, tok_items
      logical :: inside
      integer, parameter :: t_none = 0, t_word = 1, t_string = 2, t_equals = 3, t_comma = 4, &
         t_slash = 5, t_amp = 6

      inside = .false.
      nseen = 0
      group = ''
      vname = ''
      value = ''
      vline = 0
      n_items = 0
      longest = 0
      do il = 1, size(lines)
         pos = 1
         n = len_trim(lines(il))
         do
            call next_token(lines(il), pos, n, kind, token, error)
            if (allocated(error)) then
               error%message = line_ref(il)//': '//error%message
               return
            end if
            if (kind == t_none) exit
            if (.not. inside) then
               if (kind /= t_amp) then
                  call fatal_error(error, line_ref(il)//': "'//token//'" outside a group; a group '// &
                     'starts with &name and ends with /')
                  return
               end if
               group = to_lower(token)
               if (.not. any(group_names == group)) then
                  call fatal_error(error, line_ref(il)//': unknown group &'//group// &
                     '; the groups are '//join_words(group_names, '&', ''))
                  return
               end if
               do ig = 1, nseen
                  if (seen(ig) == group) then
                     call fatal_error(error, line_ref(il)//': group &'//group// &
                        ' appears twice (first at line '//str_int(seen_line(ig))// &
                        '); put all its variables in one group')
                     return
                  end if
               end do
               nseen = nseen + 1
               seen(nseen) = group
               seen_line(nseen) = il
               inside = .true.
               cycle
            end if
            select case (kind)
            case (t_slash)
               call finish(error)
               if (allocated(error)) return
               inside = .false.
            case (t_amp)
               if (to_lower(token) == 'end') then
                  call finish(error)
                  if (allocated(error)) return
                  inside = .false.
               else
                  call fatal_error(error, line_ref(il)//': group &'//group// &
                     ' is not closed with / before &'//token)
                  return
               end if
            case (t_equals)
               call fatal_error(error, line_ref(il)//': "=" without a variable name in &'//group)
               return
            case (t_word)
               if (starts_assignment(lines, il, pos)) then
                  call finish(error)
                  if (allocated(error)) return
                  vname = to_lower(token)
                  vline = il
                  call skip_equals(lines(il), pos)
               else
                  if (len(vname) == 0) then
                     call fatal_error(error, line_ref(il)//': "'//token//'" in &'//group// &
                        ' is not an assignment variable = value')
                     return
                  end if
                  call word_items(token, tok_items)
                  n_items = n_items + tok_items
                  value = value//' '//token
               end if
            case (t_string)
               if (len(vname) == 0) then
                  call fatal_error(error, line_ref(il)//': '//token//' in &'//group// &
                     ' is not an assignment variable = value')
                  return
               end if
               n_items = n_items + 1
               longest = max(longest, len(strip_quotes(token)))
               value = value//' '//token
            case (t_comma)
               value = value//' ,'
            end select
         end do
      end do
      if (inside) then
         call fatal_error(error, filename//': group &'//group//' (line '// &
            str_int(seen_line(nseen))//') is not closed with /')
      end if

   contains

      function line_ref(line) result(w)
         integer, intent(in) :: line
         character(len=:), allocatable :: w
         w = filename//':'//str_int(line)
      end function line_ref

      !> Store the pending assignment, if any.
      subroutine finish(error)
         type(error_type), allocatable, intent(out) :: error
         type(assignment_type) :: a
         if (len(vname) == 0) return
         if (len_trim(value) == 0) then
            call fatal_error(error, line_ref(vline)//': &'//group//' '//vname//' = has no value')
            return
         end if
         a%group = group
         a%name = vname
         a%value = trim(adjustl(value))
         a%where = line_ref(vline)
         a%n_items = n_items
         a%longest_string = longest
         call push(list, a)
         vname = ''
         value = ''
         n_items = 0
         longest = 0
      end subroutine finish

      !> The next token of a line from `pos`: a word, a quoted string, '=', ',', '/' or '&name'.
      subroutine next_token(line, pos, n, kind, token, error)
         character(len=*), intent(in) :: line
         integer, intent(inout) :: pos
         integer, intent(in) :: n
         integer, intent(out) :: kind
         character(len=:), allocatable, intent(out) :: token
         type(error_type), allocatable, intent(out) :: error
         integer :: start
         character(len=1) :: q

         kind = t_none
         token = ''
         do while (pos <= n)
            if (line(pos:pos) /= ' ' .and. iachar(line(pos:pos)) /= 9) exit
            pos = pos + 1
         end do
         if (pos > n) return
         select case (line(pos:pos))
         case ('!')
            pos = n + 1
            return
         case ('=')
            kind = t_equals
            pos = pos + 1
         case (',')
            kind = t_comma
            pos = pos + 1
         case ('/')
            kind = t_slash
            pos = pos + 1
         case ('&', '$')
            start = pos + 1
            pos = start
            do while (pos <= n)
               if (.not. is_name_char(line(pos:pos))) exit
               pos = pos + 1
            end do
            kind = t_amp
            token = line(start:pos - 1)
            if (len(token) == 0) call fatal_error(error, 'a group name must follow "&"')
         case ("'", '"')
            q = line(pos:pos)
            start = pos
            pos = pos + 1
            do
               if (pos > n) then
                  call fatal_error(error, 'unterminated string '//line(start:n))
                  return
               end if
               if (line(pos:pos) == q) then
                  if (pos < n) then
                     if (line(pos + 1:pos + 1) == q) then
                        pos = pos + 2
                        cycle
                     end if
                  end if
                  exit
               end if
               pos = pos + 1
            end do
            kind = t_string
            token = line(start:pos)
            pos = pos + 1
         case default
            start = pos
            do while (pos <= n)
               if (index(" =,/!'""&"//achar(9), line(pos:pos)) > 0) exit
               pos = pos + 1
            end do
            kind = t_word
            token = line(start:pos - 1)
         end select
      end subroutine next_token

   end subroutine parse_namelist

   !> True when the word just read is followed by '=' (possibly on the same line only).
   logical function starts_assignment(lines, il, pos)
      character(len=*), intent(in) :: lines(:)
      integer, intent(in) :: il, pos
      integer :: p, n
      n = len_trim(lines(il))
      p = pos
      do while (p <= n)
         if (lines(il)(p:p) /= ' ' .and. iachar(lines(il)(p:p)) /= 9) exit
         p = p + 1
      end do
      starts_assignment = .false.
      if (p <= n) starts_assignment = lines(il)(p:p) == '='
   end function starts_assignment

   !> Move past the '=' that follows a variable name.
   subroutine skip_equals(line, pos)
      character(len=*), intent(in) :: line
      integer, intent(inout) :: pos
      pos = index(line(pos:), '=') + pos
   end subroutine skip_equals

   pure logical function is_name_char(c)
      character(len=1), intent(in) :: c
      is_name_char = (c >= 'a' .and. c <= 'z') .or. (c >= 'A' .and. c <= 'Z') .or. &
         (c >= '0' .and. c <= '9') .or. c == '_'
   end function is_name_char

   !> Number of values a bare word stands for: `r*v` is r values, anything else one.
   subroutine word_items(word, n)
      character(len=*), intent(in) :: word
      integer, intent(out) :: n
      integer :: istar, ios
      n = 1
      istar = index(word, '*')
      if (istar > 1) then
         read (word(1:istar - 1), *, iostat=ios) n
         if (ios /= 0 .or. n < 1) n = 1
      end if
   end subroutine word_items

   !> Count the values of a value text (for overrides) and the longest quoted string.
   subroutine count_items(value, n, longest)
      character(len=*), intent(in) :: value
      integer, intent(out) :: n, longest
      integer :: pos, start, k
      character(len=1) :: q
      n = 0
      longest = 0
      pos = 1
      do while (pos <= len_trim(value))
         select case (value(pos:pos))
         case (' ', ',')
            pos = pos + 1
         case ("'", '"')
            q = value(pos:pos)
            start = pos
            pos = pos + 1
            do while (pos <= len(value))
               if (value(pos:pos) == q) then
                  if (pos < len(value)) then
                     if (value(pos + 1:pos + 1) == q) then
                        pos = pos + 2
                        cycle
                     end if
                  end if
                  exit
               end if
               pos = pos + 1
            end do
            n = n + 1
            longest = max(longest, len(strip_quotes(value(start:min(pos, len(value))))))
            pos = pos + 1
         case default
            start = pos
            do while (pos <= len(value))
               if (value(pos:pos) == ' ' .or. value(pos:pos) == ',') exit
               pos = pos + 1
            end do
            call word_items(value(start:pos - 1), k)
            n = n + k
         end select
      end do
   end subroutine count_items

   !> Quote each comma-separated item of an override value that is not quoted yet.
   function quote_items(value) result(q)
      character(len=*), intent(in) :: value
      character(len=:), allocatable :: q
      integer :: start, comma
      character(len=:), allocatable :: item
      if (len(value) > 0) then
         if (value(1:1) == "'" .or. value(1:1) == '"') then
            q = value
            return
         end if
      end if
      q = ''
      start = 1
      do
         comma = index(value(start:), ',')
         if (comma == 0) then
            item = trim(adjustl(value(start:)))
         else
            item = trim(adjustl(value(start:start + comma - 2)))
         end if
         if (len(q) > 0) q = q//', '
         q = q//quote_string(item)
         if (comma == 0) exit
         start = start + comma
      end do
   end function quote_items

   subroutine push(list, a)
      type(assignment_list_type), intent(inout) :: list
      type(assignment_type), intent(in) :: a
      type(assignment_type), allocatable :: tmp(:)
      if (.not. allocated(list%items)) allocate (list%items(16))
      if (list%n == size(list%items)) then
         allocate (tmp(2*list%n))
         tmp(1:list%n) = list%items
         call move_alloc(tmp, list%items)
      end if
      list%n = list%n + 1
      list%items(list%n) = a
   end subroutine push

   ! ------------------------------------------------------------------------------------------
   ! Applying one assignment
   ! ------------------------------------------------------------------------------------------

   !> Index of a variable in [[variables]], 0 when unknown.
   pure integer function find_variable(group, name)
      character(len=*), intent(in) :: group, name
      integer :: i
      find_variable = 0
      do i = 1, size(variables)
         if (variables(i)%group == group .and. variables(i)%name == name) then
            find_variable = i
            return
         end if
      end do
   end function find_variable

   !> Check one assignment against the variable table, read it through a one-assignment
   !> namelist, and record where it came from.
   subroutine apply_assignment(config, a, base_dir, error)
      type(case_config_type), intent(inout) :: config
      type(assignment_type), intent(in) :: a
      !> Directory of the case file, for relative profile names.
      character(len=*), intent(in) :: base_dir
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text
      character(len=256) :: msg
      integer :: iv, stat, capacity

      if (index(a%name, '(') > 0 .or. index(a%name, '%') > 0) then
         call fatal_error(error, a%where//': &'//a%group//' '//a%name//': give the whole '// &
            'variable, e.g. '//a%name(1:scan(a%name, '(%') - 1)//' = v1, v2, ...')
         return
      end if
      iv = find_variable(a%group, a%name)
      if (iv == 0) then
         call fatal_error(error, a%where//': &'//a%group//': unknown variable "'//a%name// &
            '"'//suggestion(a%group, a%name)//'; the variables of &'//a%group//' are '// &
            group_variable_list(a%group))
         return
      end if
      select case (variables(iv)%kind)
      case (k_real_list)
         capacity = max_sweep_values
      case (k_string_list)
         capacity = max_label_values
         if (a%group == 'output') capacity = max_fields
      case default
         capacity = 1
      end select
      if (a%n_items > capacity) then
         if (capacity == 1) then
            call fatal_error(error, value_context(a)//': expected one value ('// &
               type_phrase(variables(iv))//'), found '//str_int(a%n_items))
         else
            call fatal_error(error, value_context(a)//': at most '//str_int(capacity)// &
               ' values allowed, found '//str_int(a%n_items))
         end if
         return
      end if
      if (a%longest_string > string_capacity(variables(iv))) then
         call fatal_error(error, value_context(a)//': longer than '// &
            str_int(string_capacity(variables(iv)))//' characters')
         return
      end if

      text = '&'//a%group//' '//a%name//' = '//a%value//' /'
      msg = ''
      select case (a%group)
      case ('profiles')
         call read_profiles(config%profiles, text, stat, msg)
         if (stat == 0) call resolve_profile_path(config%profiles, a%name, base_dir)
      case ('track')
         call read_track(config%track, text, stat, msg)
      case ('position')
         call read_position(config%position, text, stat, msg)
      case ('kinematics')
         call read_kinematics(config%kinematics, text, stat, msg)
      case ('material')
         call read_material(config%material, text, stat, msg)
      case ('load')
         call read_load(config%load, text, stat, msg)
      case ('creepage')
         call read_creepage(config%creepage, text, stat, msg)
      case ('normal')
         call read_normal(config%normal, text, stat, msg)
      case ('tangential')
         call read_tangential(config%tangential, text, stat, msg)
      case ('output')
         call read_output(config%output, a%name, text, stat, msg)
      case ('sweep')
         call read_sweep(config%sweep, a%name, text, stat, msg)
      end select
      if (stat /= 0) then
         call fatal_error(error, value_context(a)//': expected '// &
            type_phrase(variables(iv))//hint(variables(iv)%kind, a%value))
         return
      end if
      call set_origin(config, a%group//'%'//a%name, a%where)
   end subroutine apply_assignment

   !> "file:line: &group name = value".
   pure function value_context(a) result(c)
      type(assignment_type), intent(in) :: a
      character(len=:), allocatable :: c
      c = a%where//': &'//a%group//' '//a%name//' = '//a%value
   end function value_context

   !> A hint for the most common slip of each kind.
   pure function hint(kind, value) result(h)
      integer, intent(in) :: kind
      character(len=*), intent(in) :: value
      character(len=:), allocatable :: h
      h = ''
      if ((kind == k_string .or. kind == k_string_list) .and. index(value, "'") == 0 .and. &
          index(value, '"') == 0) h = " (strings are quoted: 'text')"
   end function hint

   !> Words that describe the expected type.
   pure function type_phrase(v) result(p)
      type(variable_info_type), intent(in) :: v
      character(len=:), allocatable :: p
      select case (v%kind)
      case (k_real)
         p = 'a real number'
      case (k_int)
         p = 'an integer'
      case (k_logical)
         p = 'a logical (.true. or .false.)'
      case (k_string)
         p = 'a quoted string'
      case (k_real_list)
         p = 'a list of real numbers'
      case default
         p = 'a list of quoted strings'
      end select
      if (len_trim(v%units) > 0 .and. v%units /= '1') p = p//' in '//trim(v%units)
   end function type_phrase

   pure integer function string_capacity(v)
      type(variable_info_type), intent(in) :: v
      string_capacity = name_len
      if (v%name == 'wheel' .or. v%name == 'rail' .or. v%name == 'file') string_capacity = path_len
   end function string_capacity

   !> "; did you mean X?" for a close variable name of the group.
   pure function suggestion(group, name) result(s)
      character(len=*), intent(in) :: group, name
      character(len=:), allocatable :: s
      integer :: i, best, d, dbest
      s = ''
      best = 0
      dbest = 3
      do i = 1, size(variables)
         if (variables(i)%group /= group) cycle
         d = edit_distance(name, trim(variables(i)%name))
         if (d < dbest) then
            dbest = d
            best = i
         end if
      end do
      if (best > 0) s = ' (did you mean "'//trim(variables(best)%name)//'"?)'
   end function suggestion

   !> Levenshtein distance (short names only).
   pure integer function edit_distance(a, b)
      character(len=*), intent(in) :: a, b
      integer :: d(0:len(a), 0:len(b)), i, j
      do i = 0, len(a)
         d(i, 0) = i
      end do
      do j = 0, len(b)
         d(0, j) = j
      end do
      do j = 1, len(b)
         do i = 1, len(a)
            d(i, j) = min(d(i - 1, j) + 1, d(i, j - 1) + 1, &
               d(i - 1, j - 1) + merge(0, 1, a(i:i) == b(j:j)))
         end do
      end do
      edit_distance = d(len(a), len(b))
   end function edit_distance

   pure function group_variable_list(group) result(s)
      character(len=*), intent(in) :: group
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(variables)
         if (variables(i)%group /= group) cycle
         if (len(s) > 0) s = s//', '
         s = s//trim(variables(i)%name)
      end do
   end function group_variable_list

   pure function join_words(words, prefix, quote) result(s)
      character(len=*), intent(in) :: words(:), prefix, quote
      character(len=:), allocatable :: s
      integer :: i
      s = ''
      do i = 1, size(words)
         if (i > 1) s = s//', '
         s = s//quote//prefix//trim(words(i))//quote
      end do
   end function join_words

   subroutine set_origin(config, key, where)
      type(case_config_type), intent(inout) :: config
      character(len=*), intent(in) :: key, where
      type(origin_type), allocatable :: tmp(:)
      integer :: i
      if (.not. allocated(config%origins)) allocate (config%origins(0))
      do i = 1, size(config%origins)
         if (config%origins(i)%key == key) then
            config%origins(i)%where = where
            return
         end if
      end do
      allocate (tmp(size(config%origins) + 1))
      tmp(1:size(config%origins)) = config%origins
      tmp(size(tmp))%key = key
      tmp(size(tmp))%where = where
      call move_alloc(tmp, config%origins)
   end subroutine set_origin

   !> Where a variable was set: 'file:line', 'command line --set ...', or 'default'.
   pure function origin(config, key) result(where)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: key
      character(len=:), allocatable :: where
      integer :: i
      where = 'default'
      if (.not. allocated(config%origins)) return
      do i = 1, size(config%origins)
         if (config%origins(i)%key == key) where = config%origins(i)%where
      end do
   end function origin

   !> Where the sweep was set: the last `&sweep` assignment, else the case file, else the
   !> command line (never 'default': a sweep is always someone's input).
   pure function sweep_origin(config) result(where)
      type(case_config_type), intent(in) :: config
      character(len=:), allocatable :: where
      integer :: i
      where = 'command line'
      if (allocated(config%case_file)) then
         if (len(config%case_file) > 0) where = config%case_file
      end if
      if (.not. allocated(config%origins)) return
      do i = 1, size(config%origins)
         if (index(config%origins(i)%key, 'sweep%') == 1) where = config%origins(i)%where
      end do
   end function sweep_origin

   !> Relative profile file names are taken from the directory of the case file.
   subroutine resolve_profile_path(profiles, name, base_dir)
      type(profiles_config_type), intent(inout) :: profiles
      character(len=*), intent(in) :: name, base_dir
      select case (name)
      case ('wheel')
         if (index(to_lower(profiles%wheel), 'builtin:') /= 1) profiles%wheel = join_path(base_dir, &
            trim(profiles%wheel))
      case ('rail')
         if (index(to_lower(profiles%rail), 'builtin:') /= 1) profiles%rail = join_path(base_dir, &
            trim(profiles%rail))
      end select
   end subroutine resolve_profile_path

   ! One reader per group: copy to locals, read the one-assignment namelist, copy back.

   subroutine read_profiles(g, text, stat, msg)
      type(profiles_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=path_len) :: wheel, rail
      character(len=name_len) :: wheel_format, rail_format
      real(wp) :: wheel_smoothing, rail_smoothing, wheel_scale, rail_scale
      character(len=name_len) :: wheel_mirror_y, wheel_mirror_z, rail_mirror_y, rail_mirror_z
      namelist /profiles/ wheel, rail, wheel_format, rail_format, wheel_smoothing, &
         rail_smoothing, wheel_mirror_y, wheel_mirror_z, wheel_scale, rail_mirror_y, &
         rail_mirror_z, rail_scale
      wheel_mirror_y = g%wheel_mirror_y; wheel_mirror_z = g%wheel_mirror_z
      rail_mirror_y = g%rail_mirror_y; rail_mirror_z = g%rail_mirror_z
      wheel_scale = g%wheel_scale; rail_scale = g%rail_scale
      wheel = g%wheel; rail = g%rail
      wheel_format = g%wheel_format; rail_format = g%rail_format
      wheel_smoothing = g%wheel_smoothing; rail_smoothing = g%rail_smoothing
      read (text, nml=profiles, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%wheel = wheel; g%rail = rail
      g%wheel_format = to_lower(wheel_format); g%rail_format = to_lower(rail_format)
      g%wheel_smoothing = wheel_smoothing; g%rail_smoothing = rail_smoothing
      g%wheel_mirror_y = to_lower(wheel_mirror_y); g%wheel_mirror_z = to_lower(wheel_mirror_z)
      g%rail_mirror_y = to_lower(rail_mirror_y); g%rail_mirror_z = to_lower(rail_mirror_z)
      g%wheel_scale = wheel_scale; g%rail_scale = rail_scale
   end subroutine read_profiles

   subroutine read_track(g, text, stat, msg)
      type(track_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: side
      real(wp) :: gauge, gauge_height, inclination, flange_back_distance, &
         flange_back_position, nominal_radius
      logical :: rail_canted
      namelist /track/ side, gauge, gauge_height, inclination, rail_canted, &
         flange_back_distance, flange_back_position, nominal_radius
      side = g%side; gauge = g%gauge; gauge_height = g%gauge_height
      inclination = g%inclination; rail_canted = g%rail_canted
      flange_back_distance = g%flange_back_distance
      flange_back_position = g%flange_back_position; nominal_radius = g%nominal_radius
      read (text, nml=track, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%side = to_lower(side); g%gauge = gauge; g%gauge_height = gauge_height
      g%inclination = inclination; g%rail_canted = rail_canted
      g%flange_back_distance = flange_back_distance
      g%flange_back_position = flange_back_position; g%nominal_radius = nominal_radius
   end subroutine read_track

   subroutine read_position(g, text, stat, msg)
      type(position_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      real(wp) :: t_y, roll
      namelist /position/ t_y, roll
      t_y = g%t_y; roll = g%roll
      read (text, nml=position, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%t_y = t_y; g%roll = roll
   end subroutine read_position

   subroutine read_kinematics(g, text, stat, msg)
      type(kinematics_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: mode
      real(wp) :: yaw, v_forward, v_lateral, v_vertical, roll_rate, yaw_rate, pitch_rate
      namelist /kinematics/ mode, yaw, v_forward, v_lateral, v_vertical, roll_rate, yaw_rate, &
         pitch_rate
      mode = g%mode; yaw = g%yaw; v_forward = g%v_forward; v_lateral = g%v_lateral
      v_vertical = g%v_vertical; roll_rate = g%roll_rate; yaw_rate = g%yaw_rate
      pitch_rate = g%pitch_rate
      read (text, nml=kinematics, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%mode = to_lower(mode); g%yaw = yaw; g%v_forward = v_forward; g%v_lateral = v_lateral
      g%v_vertical = v_vertical; g%roll_rate = roll_rate; g%yaw_rate = yaw_rate
      g%pitch_rate = pitch_rate
   end subroutine read_kinematics

   subroutine read_material(g, text, stat, msg)
      type(material_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      real(wp) :: shear_modulus, poisson, friction
      namelist /material/ shear_modulus, poisson, friction
      shear_modulus = g%shear_modulus; poisson = g%poisson; friction = g%friction
      read (text, nml=material, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%shear_modulus = shear_modulus; g%poisson = poisson; g%friction = friction
   end subroutine read_material

   subroutine read_load(g, text, stat, msg)
      type(load_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: mode
      real(wp) :: normal_force, approach, vertical_force
      namelist /load/ mode, normal_force, approach, vertical_force
      mode = g%mode; normal_force = g%normal_force; approach = g%approach
      vertical_force = g%vertical_force
      read (text, nml=load, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%mode = to_lower(mode); g%normal_force = normal_force; g%approach = approach
      g%vertical_force = vertical_force
   end subroutine read_load

   subroutine read_creepage(g, text, stat, msg)
      type(creepage_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      real(wp) :: nu_x, nu_y, phi
      namelist /creepage/ nu_x, nu_y, phi
      nu_x = g%nu_x; nu_y = g%nu_y; phi = g%phi
      read (text, nml=creepage, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%nu_x = nu_x; g%nu_y = nu_y; g%phi = phi
   end subroutine read_creepage

   subroutine read_normal(g, text, stat, msg)
      type(normal_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: method, reduction, longitudinal_curvature
      real(wp) :: epsilon, b_min
      integer :: n_strips
      namelist /normal/ method, reduction, epsilon, n_strips, b_min, longitudinal_curvature
      method = g%method; reduction = g%reduction; epsilon = g%epsilon; n_strips = g%n_strips
      b_min = g%b_min; longitudinal_curvature = g%longitudinal_curvature
      read (text, nml=normal, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%method = to_lower(method); g%reduction = to_lower(reduction); g%epsilon = epsilon
      g%n_strips = n_strips; g%b_min = b_min
      g%longitudinal_curvature = to_lower(longitudinal_curvature)
   end subroutine read_normal

   subroutine read_tangential(g, text, stat, msg)
      type(tangential_config_type), intent(inout) :: g
      character(len=*), intent(in) :: text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: method, bound, spin_model, spin_flexibility
      integer :: n_elements
      namelist /tangential/ method, bound, spin_model, spin_flexibility, n_elements
      method = g%method; bound = g%bound; spin_model = g%spin_model; n_elements = g%n_elements
      spin_flexibility = g%spin_flexibility
      read (text, nml=tangential, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%method = to_lower(method); g%bound = to_lower(bound)
      g%spin_model = to_lower(spin_model); g%n_elements = n_elements
      g%spin_flexibility = to_lower(spin_flexibility)
   end subroutine read_tangential

   subroutine read_output(g, name, text, stat, msg)
      type(output_config_type), intent(inout) :: g
      character(len=*), intent(in) :: name, text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=path_len) :: file
      character(len=name_len) :: fields(max_fields), precision
      integer :: compression, checkpoint_cases, i
      namelist /output/ file, fields, precision, compression, checkpoint_cases
      file = g%file; precision = g%precision; compression = g%compression
      checkpoint_cases = g%checkpoint_cases
      fields = g%fields
      ! A list replaces the whole list.
      if (name == 'fields') fields = ''
      read (text, nml=output, iostat=stat, iomsg=msg)
      if (stat /= 0) return
      g%file = file; g%precision = to_lower(precision); g%compression = compression
      g%checkpoint_cases = checkpoint_cases
      do i = 1, max_fields
         g%fields(i) = to_lower(fields(i))
      end do
   end subroutine read_output

   subroutine read_sweep(g, name, text, stat, msg)
      type(sweep_config_type), intent(inout) :: g
      character(len=*), intent(in) :: name, text
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      character(len=name_len) :: mode
      real(wp), allocatable, dimension(:) :: t_y, roll, yaw, normal_force, approach, &
         vertical_force, friction, v_forward, v_lateral, v_vertical, roll_rate, yaw_rate, &
         pitch_rate, nu_x, nu_y, phi
      integer :: t_y_points, roll_points, yaw_points, normal_force_points, approach_points, &
         vertical_force_points, friction_points, v_forward_points, v_lateral_points, &
         v_vertical_points, roll_rate_points, yaw_rate_points, pitch_rate_points, nu_x_points, &
         nu_y_points, phi_points
      character(len=name_len) :: bound(max_label_values), spin_model(max_label_values)
      integer :: ia, points(n_sweep_axes)
      namelist /sweep/ mode, t_y, t_y_points, roll, roll_points, yaw, yaw_points, &
         normal_force, normal_force_points, approach, approach_points, vertical_force, &
         vertical_force_points, friction, friction_points, bound, spin_model, v_forward, &
         v_forward_points, v_lateral, v_lateral_points, v_vertical, v_vertical_points, &
         roll_rate, roll_rate_points, yaw_rate, yaw_rate_points, pitch_rate, pitch_rate_points, &
         nu_x, nu_x_points, nu_y, nu_y_points, phi, phi_points

      ! Only the variable being assigned is read; it gets room for every value and starts
      ! unset, so a list replaces the whole list.
      mode = g%mode
      call prepare(t_y, 't_y'); call prepare(roll, 'roll'); call prepare(yaw, 'yaw')
      call prepare(normal_force, 'normal_force'); call prepare(approach, 'approach')
      call prepare(vertical_force, 'vertical_force'); call prepare(friction, 'friction')
      call prepare(v_forward, 'v_forward'); call prepare(v_lateral, 'v_lateral')
      call prepare(v_vertical, 'v_vertical'); call prepare(roll_rate, 'roll_rate')
      call prepare(yaw_rate, 'yaw_rate'); call prepare(pitch_rate, 'pitch_rate')
      call prepare(nu_x, 'nu_x'); call prepare(nu_y, 'nu_y'); call prepare(phi, 'phi')
      bound = ''; spin_model = ''
      t_y_points = 0; roll_points = 0; yaw_points = 0; normal_force_points = 0
      approach_points = 0; vertical_force_points = 0; friction_points = 0
      v_forward_points = 0; v_lateral_points = 0; v_vertical_points = 0; roll_rate_points = 0
      yaw_rate_points = 0; pitch_rate_points = 0; nu_x_points = 0; nu_y_points = 0
      phi_points = 0
      read (text, nml=sweep, iostat=stat, iomsg=msg)
      if (stat /= 0) return

      ! The `_points` values in axis order (label axes have none).
      points = [t_y_points, roll_points, yaw_points, normal_force_points, approach_points, &
         vertical_force_points, friction_points, 0, 0, v_forward_points, v_lateral_points, &
         v_vertical_points, roll_rate_points, yaw_rate_points, pitch_rate_points, nu_x_points, &
         nu_y_points, phi_points]
      if (name == 'mode') then
         g%mode = to_lower(mode)
      else if (name == 'bound') then
         call store_labels(g%axes(axis_index('bound')), bound)
      else if (name == 'spin_model') then
         call store_labels(g%axes(axis_index('spin_model')), spin_model)
      else if (index(name, '_points') > 0) then
         ia = axis_index(name(1:index(name, '_points') - 1))
         g%axes(ia)%points = points(ia)
      else
         ia = axis_index(name)
         select case (name)
         case ('t_y'); call store_values(g%axes(ia), t_y, stat, msg)
         case ('roll'); call store_values(g%axes(ia), roll, stat, msg)
         case ('yaw'); call store_values(g%axes(ia), yaw, stat, msg)
         case ('normal_force'); call store_values(g%axes(ia), normal_force, stat, msg)
         case ('approach'); call store_values(g%axes(ia), approach, stat, msg)
         case ('vertical_force'); call store_values(g%axes(ia), vertical_force, stat, msg)
         case ('friction'); call store_values(g%axes(ia), friction, stat, msg)
         case ('v_forward'); call store_values(g%axes(ia), v_forward, stat, msg)
         case ('v_lateral'); call store_values(g%axes(ia), v_lateral, stat, msg)
         case ('v_vertical'); call store_values(g%axes(ia), v_vertical, stat, msg)
         case ('roll_rate'); call store_values(g%axes(ia), roll_rate, stat, msg)
         case ('yaw_rate'); call store_values(g%axes(ia), yaw_rate, stat, msg)
         case ('pitch_rate'); call store_values(g%axes(ia), pitch_rate, stat, msg)
         case ('nu_x'); call store_values(g%axes(ia), nu_x, stat, msg)
         case ('nu_y'); call store_values(g%axes(ia), nu_y, stat, msg)
         case ('phi'); call store_values(g%axes(ia), phi, stat, msg)
         end select
      end if

   contains

      subroutine prepare(values, axis)
         real(wp), allocatable, intent(out) :: values(:)
         character(len=*), intent(in) :: axis
         if (name == axis) then
            allocate (values(max_sweep_values), source=unset)
         else
            allocate (values(0))
         end if
      end subroutine prepare

   end subroutine read_sweep

   !> Keep the leading set values of a sweep list; a gap (null value) is an error.
   subroutine store_values(axis, values, stat, msg)
      type(sweep_axis_type), intent(inout) :: axis
      real(wp), intent(in) :: values(:)
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: msg
      integer :: n
      n = 0
      do while (n < size(values))
         if (values(n + 1) == unset) exit
         n = n + 1
      end do
      stat = 0
      if (any(values(n + 1:) /= unset)) then
         stat = 1
         msg = 'a value is missing in the list'
         return
      end if
      axis%given = values(1:n)
      axis%is_label = .false.
   end subroutine store_values

   subroutine store_labels(axis, labels)
      type(sweep_axis_type), intent(inout) :: axis
      character(len=*), intent(in) :: labels(:)
      integer :: i, n
      n = count(len_trim(labels) > 0)
      allocate (axis%labels(n))
      n = 0
      do i = 1, size(labels)
         if (len_trim(labels(i)) == 0) cycle
         n = n + 1
         axis%labels(n) = to_lower(labels(i))
      end do
      axis%is_label = .true.
   end subroutine store_labels

   pure integer function axis_index(name)
      character(len=*), intent(in) :: name
      integer :: i
      axis_index = 0
      do i = 1, n_sweep_axes
         if (sweep_axis_names(i) == name) axis_index = i
      end do
   end function axis_index

   ! ------------------------------------------------------------------------------------------
   ! Validation
   ! ------------------------------------------------------------------------------------------

   !> Check every value against its allowed range or choices, and the sweep for consistency.
   !> Messages name where the value was set, the group, the variable, the value and what is
   !> allowed.
   subroutine validate_config(config, error)
      !> The configuration; choice values are normalised to lower case, sweep axes activated.
      type(case_config_type), intent(inout) :: config
      !> Set on the first problem found.
      type(error_type), allocatable, intent(out) :: error

      associate (c => config)
         call check_choice(c, 'profiles', 'wheel_format', c%profiles%wheel_format, formats, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'rail_format', c%profiles%rail_format, formats, error)
         if (allocated(error)) return
         call check_profile_name(c, 'wheel', c%profiles%wheel, 'builtin:S1002', error)
         if (allocated(error)) return
         call check_profile_name(c, 'rail', c%profiles%rail, 'builtin:UIC60', error, &
            also='builtin:UIC60-canted')
         if (allocated(error)) return
         call resolve_wheel_origin(c)
         call check_real_var(c, 'profiles', 'wheel_smoothing', c%profiles%wheel_smoothing, error)
         if (allocated(error)) return
         call check_real_var(c, 'profiles', 'rail_smoothing', c%profiles%rail_smoothing, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'wheel_mirror_y', c%profiles%wheel_mirror_y, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'wheel_mirror_z', c%profiles%wheel_mirror_z, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'rail_mirror_y', c%profiles%rail_mirror_y, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_choice(c, 'profiles', 'rail_mirror_z', c%profiles%rail_mirror_z, &
            mirror_choices, error)
         if (allocated(error)) return
         call check_real_var(c, 'profiles', 'wheel_scale', c%profiles%wheel_scale, error)
         if (allocated(error)) return
         call check_real_var(c, 'profiles', 'rail_scale', c%profiles%rail_scale, error)
         if (allocated(error)) return
         call check_choice(c, 'track', 'side', c%track%side, sides, error)
         if (allocated(error)) return
         call check_real_var(c, 'track', 'gauge', c%track%gauge, error)
         if (allocated(error)) return
         call check_real_var(c, 'track', 'gauge_height', c%track%gauge_height, error)
         if (allocated(error)) return
         call check_real_var(c, 'track', 'inclination', c%track%inclination, error)
         if (allocated(error)) return
         call check_real_var(c, 'track', 'flange_back_distance', c%track%flange_back_distance, &
            error)
         if (allocated(error)) return
         call check_real_var(c, 'track', 'flange_back_position', c%track%flange_back_position, &
            error)
         if (allocated(error)) return
         call check_real_var(c, 'track', 'nominal_radius', c%track%nominal_radius, error)
         if (allocated(error)) return
         call check_real_var(c, 'position', 't_y', c%position%t_y, error)
         if (allocated(error)) return
         call check_real_var(c, 'position', 'roll', c%position%roll, error)
         if (allocated(error)) return
         call check_kinematics(c, error)
         if (allocated(error)) return
         call check_real_var(c, 'material', 'shear_modulus', c%material%shear_modulus, error)
         if (allocated(error)) return
         call check_real_var(c, 'material', 'poisson', c%material%poisson, error)
         if (allocated(error)) return
         call check_real_var(c, 'material', 'friction', c%material%friction, error)
         if (allocated(error)) return
         call check_choice(c, 'load', 'mode', c%load%mode, load_modes, error)
         if (allocated(error)) return
         call check_real_var(c, 'load', 'normal_force', c%load%normal_force, error)
         if (allocated(error)) return
         call check_real_var(c, 'load', 'approach', c%load%approach, error)
         if (allocated(error)) return
         call check_real_var(c, 'load', 'vertical_force', c%load%vertical_force, error)
         if (allocated(error)) return
         call check_real_var(c, 'creepage', 'nu_x', c%creepage%nu_x, error)
         if (allocated(error)) return
         call check_real_var(c, 'creepage', 'nu_y', c%creepage%nu_y, error)
         if (allocated(error)) return
         call check_real_var(c, 'creepage', 'phi', c%creepage%phi, error)
         if (allocated(error)) return
         call check_choice(c, 'normal', 'method', c%normal%method, normal_methods, error)
         if (allocated(error)) return
         call check_choice(c, 'normal', 'reduction', c%normal%reduction, reductions, error)
         if (allocated(error)) return
         call check_real_var(c, 'normal', 'epsilon', c%normal%epsilon, error)
         if (allocated(error)) return
         call check_int_var(c, 'normal', 'n_strips', c%normal%n_strips, 2, 100000, error)
         if (allocated(error)) return
         call check_real_var(c, 'normal', 'b_min', c%normal%b_min, error)
         if (allocated(error)) return
         call check_choice(c, 'normal', 'longitudinal_curvature', &
            c%normal%longitudinal_curvature, curvature_modes, error)
         if (allocated(error)) return
         call check_choice(c, 'tangential', 'method', c%tangential%method, tangential_methods, &
            error)
         if (allocated(error)) return
         call check_choice(c, 'tangential', 'bound', c%tangential%bound, bounds, error)
         if (allocated(error)) return
         call check_choice(c, 'tangential', 'spin_model', c%tangential%spin_model, spin_models, &
            error)
         if (allocated(error)) return
         call check_choice(c, 'tangential', 'spin_flexibility', c%tangential%spin_flexibility, &
            spin_flexibilities, error)
         if (allocated(error)) return
         call check_int_var(c, 'tangential', 'n_elements', c%tangential%n_elements, 2, 100000, &
            error)
         if (allocated(error)) return
         call check_grid_size(c, error)
         if (allocated(error)) return
         if (c%tangential%method == 'fastsim' .and. c%normal%method /= 'hertz') then
            call fatal_error(error, origin(c, 'tangential%method')//": &tangential method = "// &
               "'fastsim' works on the Hertz ellipse of the reference point: set &normal "// &
               "method = 'hertz' (now '"//trim(c%normal%method)//"')")
            return
         end if
         call check_output(c, error)
         if (allocated(error)) return
         call resolve_kinematic_mode(c, error)
         if (allocated(error)) return
         call check_sweep(c, error)
      end associate
   end subroutine validate_config

   !> A MiniProf wheel has its origin at the flange back: unless `&track flange_back_position`
   !> is given, it is 0 for such a wheel (the default −70 mm is S1002's, whose origin is at the
   !> tape circle). The resolved namelist shows the value used.
   subroutine resolve_wheel_origin(config)
      type(case_config_type), intent(inout) :: config
      if (origin(config, 'track%flange_back_position') /= 'default') return
      if (index(to_lower(config%profiles%wheel), 'builtin:') == 1) return
      if (profile_file_format(trim(config%profiles%wheel), trim(config%profiles%wheel_format)) &
          == 'miniprof') config%track%flange_back_position = 0.0_wp
   end subroutine resolve_wheel_origin

   !> n_strips × n_elements within [[max_grid_cells]], checked before anything is allocated.
   subroutine check_grid_size(config, error)
      type(case_config_type), intent(in) :: config
      type(error_type), allocatable, intent(out) :: error
      integer(i8) :: cells
      character(len=:), allocatable :: where
      cells = int(config%normal%n_strips, i8)*int(config%tangential%n_elements, i8)
      if (cells <= max_grid_cells) return
      where = origin(config, 'tangential%n_elements')
      if (where == 'default') where = origin(config, 'normal%n_strips')
      call fatal_error(error, where//': &normal n_strips × &tangential n_elements = '// &
         str_int(config%normal%n_strips)//' × '//str_int(config%tangential%n_elements)// &
         ' = '//str_int(cells)//' grid cells per patch; at most '//str_int(max_grid_cells)// &
         ' are allowed (memory grows with it on every thread)')
   end subroutine check_grid_size

   !> The `&kinematics` values in their ranges; whether the pitch rate was given.
   subroutine check_kinematics(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      associate (k => config%kinematics)
         call check_choice(config, 'kinematics', 'mode', k%mode, kinematics_modes, error)
         if (allocated(error)) return
         call check_real_var(config, 'kinematics', 'yaw', k%yaw, error)
         if (allocated(error)) return
         call check_real_var(config, 'kinematics', 'v_forward', k%v_forward, error)
         if (allocated(error)) return
         call check_real_var(config, 'kinematics', 'v_lateral', k%v_lateral, error)
         if (allocated(error)) return
         call check_real_var(config, 'kinematics', 'v_vertical', k%v_vertical, error)
         if (allocated(error)) return
         call check_real_var(config, 'kinematics', 'roll_rate', k%roll_rate, error)
         if (allocated(error)) return
         call check_real_var(config, 'kinematics', 'yaw_rate', k%yaw_rate, error)
         if (allocated(error)) return
         k%pitch_rate_given = origin(config, 'kinematics%pitch_rate') /= 'default'
         if (k%pitch_rate_given) call check_real_var(config, 'kinematics', 'pitch_rate', &
            k%pitch_rate, error)
      end associate
   end subroutine check_kinematics

   !> Kinematic mode takes the creepages from the wheelset motion: `&creepage` must not be
   !> given (it would be silently ignored), the spin model is 'additive' (that of the library's
   !> `solve_kinematic`, which carries the rigid slip to each strip) and the load defaults to
   !> the vertical wheel load shared by all patches.
   subroutine resolve_kinematic_mode(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: creepages(3) = [character(len=4) :: 'nu_x', 'nu_y', 'phi']
      character(len=:), allocatable :: where
      integer :: i

      if (.not. config%is_kinematic()) return
      do i = 1, size(creepages)
         where = origin(config, 'creepage%'//trim(creepages(i)))
         if (where == 'default') cycle
         call fatal_error(error, where//': &creepage '//trim(creepages(i))//' is given, but '// &
            "&kinematics mode = 'on' computes the creepages of every patch from the wheelset "// &
            "motion; remove &creepage, or set &kinematics mode = 'off' to prescribe them")
         return
      end do
      where = origin(config, 'tangential%spin_model')
      if (where /= 'default' .and. config%tangential%spin_model /= 'additive') then
         call fatal_error(error, where//": &tangential spin_model = '"// &
            trim(config%tangential%spin_model)//"': &kinematics mode = 'on' needs "// &
            "spin_model = 'additive' (the rigid slip carried to each strip, as the library's "// &
            "solve_kinematic); remove it or set 'additive'")
         return
      end if
      config%tangential%spin_model = 'additive'
      if (origin(config, 'load%mode') == 'default') config%load%mode = 'vertical'
   end subroutine resolve_kinematic_mode

   !> Allowed range of each real variable (also used for its sweep values).
   pure subroutine real_limits(name, lo, hi, lo_open, hi_open)
      character(len=*), intent(in) :: name
      real(wp), intent(out) :: lo, hi
      logical, intent(out) :: lo_open, hi_open
      lo_open = .false.
      hi_open = .false.
      select case (name)
      case ('wheel_smoothing', 'rail_smoothing')
         lo = 0.0_wp; hi = 100.0_wp
      case ('wheel_scale', 'rail_scale')
         lo = 0.0_wp; hi = 1.0e6_wp
      case ('gauge')
         lo = 500.0_wp; hi = 2000.0_wp
      case ('gauge_height')
         lo = 0.0_wp; hi = 50.0_wp
      case ('inclination')
         lo = -0.2_wp; hi = 0.2_wp
      case ('b_min')
         lo = 0.0_wp; hi = 1.0_wp; lo_open = .true.
      case ('flange_back_distance')
         lo = 400.0_wp; hi = 2000.0_wp
      case ('flange_back_position')
         lo = -200.0_wp; hi = 200.0_wp
      case ('nominal_radius')
         lo = 100.0_wp; hi = 2000.0_wp
      case ('t_y')
         lo = -30.0_wp; hi = 30.0_wp
      case ('roll')
         lo = -0.1_wp; hi = 0.1_wp
      case ('shear_modulus')
         lo = 0.0_wp; hi = 1.0e6_wp; lo_open = .true.
      case ('poisson')
         lo = 0.0_wp; hi = 0.5_wp; hi_open = .true.
      case ('friction')
         lo = 0.0_wp; hi = 10.0_wp; lo_open = .true.
      case ('normal_force', 'vertical_force')
         lo = 0.0_wp; hi = 1.0e7_wp; lo_open = .true.
      case ('approach')
         lo = 0.0_wp; hi = 5.0_wp; lo_open = .true.
      case ('nu_x', 'nu_y')
         lo = -1.0_wp; hi = 1.0_wp
      case ('phi')
         lo = -0.1_wp; hi = 0.1_wp
      case ('epsilon')
         lo = 0.0_wp; hi = 1.0_wp; lo_open = .true.
      case ('yaw')
         lo = -max_yaw; hi = max_yaw
      case ('v_forward')
         ! Creepages are velocities divided by the rolling speed: V > 0 (720 km/h at most).
         lo = 0.0_wp; hi = 2.0e5_wp; lo_open = .true.
      case ('v_lateral', 'v_vertical')
         lo = -1.0e4_wp; hi = 1.0e4_wp
      case ('roll_rate', 'yaw_rate')
         lo = -10.0_wp; hi = 10.0_wp
      case ('pitch_rate')
         ! Rolling forward turns the wheel backwards about the axle: −V/r.
         lo = -2000.0_wp; hi = 0.0_wp; hi_open = .true.
      case default
         lo = -huge(1.0_wp); hi = huge(1.0_wp)
      end select
   end subroutine real_limits

   !> A real in its allowed range, finite.
   subroutine check_real(config, group, name, label, x, error)
      type(case_config_type), intent(in) :: config
      !> Group and variable (for the range and the origin).
      character(len=*), intent(in) :: group, name
      !> How to show the variable in the message (e.g. 'nu_x(3)').
      character(len=*), intent(in) :: label
      real(wp), intent(in) :: x
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: lo, hi
      logical :: lo_open, hi_open, ok
      integer :: iv
      character(len=:), allocatable :: units

      call real_limits(name, lo, hi, lo_open, hi_open)
      ok = ieee_is_finite(x)
      if (ok) then
         if (lo_open) then
            ok = x > lo
         else
            ok = x >= lo
         end if
         if (hi_open) then
            ok = ok .and. x < hi
         else
            ok = ok .and. x <= hi
         end if
      end if
      if (ok) return
      iv = find_variable(group, name)
      units = ''
      if (iv > 0) then
         if (len_trim(variables(iv)%units) > 0 .and. variables(iv)%units /= '1') &
            units = ' '//trim(variables(iv)%units)
      end if
      call fatal_error(error, origin(config, group//'%'//name)//': &'//group//' '//label// &
         ' = '//format_real(x)//' is out of range; expected '//format_real(lo)// &
         less(lo_open)//name//less(hi_open)//format_real(hi)//units)
   end subroutine check_real

   !> ' < ' or ' <= '.
   pure function less(strict) result(op)
      logical, intent(in) :: strict
      character(len=:), allocatable :: op
      if (strict) then
         op = ' < '
      else
         op = ' <= '
      end if
   end function less

   subroutine check_real_var(config, group, name, x, error)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: group, name
      real(wp), intent(in) :: x
      type(error_type), allocatable, intent(out) :: error
      call check_real(config, group, name, name, x, error)
   end subroutine check_real_var

   subroutine check_int_var(config, group, name, i, lo, hi, error)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: group, name
      integer, intent(in) :: i, lo, hi
      type(error_type), allocatable, intent(out) :: error
      if (i >= lo .and. i <= hi) return
      call fatal_error(error, origin(config, group//'%'//name)//': &'//group//' '//name// &
         ' = '//str_int(i)//' is out of range; expected '//str_int(lo)//' <= '//name// &
         ' <= '//str_int(hi))
   end subroutine check_int_var

   !> A choice among a fixed list.
   subroutine check_choice(config, group, name, value, allowed, error)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: group, name, value
      character(len=*), intent(in) :: allowed(:)
      type(error_type), allocatable, intent(out) :: error
      if (any(allowed == value)) return
      call fatal_error(error, origin(config, group//'%'//name)//': &'//group//' '//name// &
         " = '"//trim(value)//"' is not allowed; expected one of "// &
         join_words(allowed, '', "'"))
   end subroutine check_choice

   !> A built-in name is one we have; anything else is a file name (checked when it is read).
   subroutine check_profile_name(config, name, value, builtin, error, also)
      type(case_config_type), intent(in) :: config
      character(len=*), intent(in) :: name, builtin
      !> The profile name; a built-in name is spelt canonically on return.
      character(len=*), intent(inout) :: value
      type(error_type), allocatable, intent(out) :: error
      !> Another accepted built-in name.
      character(len=*), intent(in), optional :: also
      if (to_lower(value) == to_lower(builtin)) value = builtin
      if (present(also)) then
         if (to_lower(value) == to_lower(also)) then
            value = also
            return
         end if
      end if
      if (len_trim(value) == 0) then
         call fatal_error(error, origin(config, 'profiles%'//name)//': &profiles '//name// &
            " is empty; expected '"//builtin//"' or a file name")
      else if (index(to_lower(value), 'builtin:') == 1 .and. &
               to_lower(value) /= to_lower(builtin)) then
         call fatal_error(error, origin(config, 'profiles%'//name)//': &profiles '//name// &
            " = '"//trim(value)//"': unknown built-in profile; expected '"//builtin// &
            "'"//alternative(also)//" or a file name")
      end if
   end subroutine check_profile_name

   pure function alternative(also) result(text)
      character(len=*), intent(in), optional :: also
      character(len=:), allocatable :: text
      text = ''
      if (present(also)) text = ", '"//also//"'"
   end function alternative

   subroutine check_output(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      integer :: i, n
      if (len_trim(config%output%file) == 0) then
         call fatal_error(error, origin(config, 'output%file')//': &output file is empty; '// &
            'expected a file name')
         return
      end if
      call check_choice(config, 'output', 'precision', config%output%precision, precisions, &
         error)
      if (allocated(error)) return
      call check_int_var(config, 'output', 'compression', config%output%compression, 0, 9, error)
      if (allocated(error)) return
      call check_int_var(config, 'output', 'checkpoint_cases', config%output%checkpoint_cases, &
         0, huge(1), error)
      if (allocated(error)) return
      n = 0
      do i = 1, max_fields
         if (len_trim(config%output%fields(i)) == 0) cycle
         n = n + 1
         call check_choice(config, 'output', 'fields', config%output%fields(i), field_names, &
            error)
         if (allocated(error)) return
      end do
      if (n == 0) config%output%fields(1) = 'none'
   end subroutine check_output

   !> Every sweep value in the range of its variable; ranges well formed; list lengths equal
   !> in 'list' mode; load axes that match the load mode.
   subroutine check_sweep(config, error)
      type(case_config_type), intent(inout) :: config
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: where, name
      integer :: ia, i, n_list

      call check_choice(config, 'sweep', 'mode', config%sweep%mode, sweep_modes, error)
      if (allocated(error)) return
      n_list = -1
      do ia = 1, n_sweep_axes
         associate (axis => config%sweep%axes(ia))
            name = trim(sweep_axis_names(ia))
            where = origin(config, 'sweep%'//name)
            if (where == 'default') where = origin(config, 'sweep%'//name//'_points')
            if (where == 'default') where = sweep_origin(config)
            axis%active = .false.
            if (axis%is_label) then
               axis%active = size(axis%labels) > 0
               do i = 1, axis%size()
                  if (name == 'bound') then
                     call check_choice(config, 'sweep', name, axis%labels(i), bounds, error)
                  else
                     call check_choice(config, 'sweep', name, axis%labels(i), spin_models, error)
                  end if
                  if (allocated(error)) return
               end do
            else
               if (.not. allocated(axis%given)) allocate (axis%given(0))
               if (axis%points /= 0) then
                  if (axis%points < 2 .or. axis%points > max_sweep_values) then
                     call fatal_error(error, origin(config, 'sweep%'//name//'_points')// &
                        ': &sweep '//name//'_points = '//str_int(axis%points)// &
                        ' is out of range; expected 0 (a list) or 2 to '// &
                        str_int(max_sweep_values))
                     return
                  end if
                  if (size(axis%given) /= 2) then
                     call fatal_error(error, where//': &sweep '//name//' has '// &
                        str_int(size(axis%given))//' values; with '//name// &
                        '_points > 0 it must hold exactly two: first, last')
                     return
                  end if
               end if
               axis%active = size(axis%given) > 0
               do i = 1, size(axis%given)
                  call check_real(config, 'sweep', name, name//'('//str_int(i)//')', &
                     axis%given(i), error)
                  if (allocated(error)) return
               end do
            end if
            if (.not. axis%active) cycle
            if (config%is_kinematic() .and. any(name == ['nu_x      ', 'nu_y      ', &
                'phi       ', 'spin_model'])) then
               call fatal_error(error, where//': &sweep '//name//" is given, but &kinematics "// &
                  "mode = 'on' takes the creepages from the wheelset motion (spin model "// &
                  "'additive'); sweep the wheelset inputs (t_y, roll, yaw, v_forward, ...) instead")
               return
            end if
            if (.not. config%is_kinematic() .and. is_kinematic_input(name) .and. &
                name /= 't_y' .and. name /= 'roll') then
               call fatal_error(error, where//': &sweep '//name//" is given, but &kinematics "// &
                  "mode = 'off' (prescribed creepages); set &kinematics mode = 'on' to solve "// &
                  'from the wheelset motion')
               return
            end if
            if (axis_stage(ia) == axis_load .and. .not. load_axis_matches(name, &
                config%load%mode)) then
               call fatal_error(error, where//': &sweep '//name//' is given but &load mode = '// &
                  "'"//trim(config%load%mode)//"'; sweep the quantity of the load mode")
               return
            end if
            if (config%sweep%mode == 'list') then
               if (n_list < 0) then
                  n_list = axis%size()
               else if (axis%size() /= n_list) then
                  call fatal_error(error, where//": &sweep mode = 'list' needs lists of equal "// &
                     'length; '//name//' has '//str_int(axis%size())//' values, an '// &
                     'earlier list '//str_int(n_list))
                  return
               end if
            end if
         end associate
      end do
      if (config%n_cases() > max_cases) then
         call fatal_error(error, sweep_origin(config)//': the sweep has more than '// &
            str_int(max_cases)//' cases; split it into several runs')
      end if
   end subroutine check_sweep

   pure logical function load_axis_matches(name, mode)
      character(len=*), intent(in) :: name, mode
      select case (name)
      case ('normal_force')
         load_axis_matches = mode == 'force'
      case ('approach')
         load_axis_matches = mode == 'approach'
      case default
         load_axis_matches = mode == 'vertical'
      end select
   end function load_axis_matches

   ! ------------------------------------------------------------------------------------------
   ! Sweep expansion
   ! ------------------------------------------------------------------------------------------

   pure integer function axis_size(self)
      class(sweep_axis_type), intent(in) :: self
      axis_size = 0
      if (self%is_label) then
         if (allocated(self%labels)) axis_size = size(self%labels)
      else if (self%points > 0) then
         axis_size = self%points
      else if (allocated(self%given)) then
         axis_size = size(self%given)
      end if
   end function axis_size

   !> The i-th value: given(i) for a list; first + (last − first)·(i−1)/(points−1) for a range,
   !> with the last point exactly `last`.
   pure real(wp) function axis_value(self, i)
      class(sweep_axis_type), intent(in) :: self
      integer, intent(in) :: i
      if (self%points > 0) then
         if (i == self%points) then
            axis_value = self%given(2)
         else
            axis_value = self%given(1) + (self%given(2) - self%given(1))*real(i - 1, wp)/ &
               real(self%points - 1, wp)
         end if
      else
         axis_value = self%given(i)
      end if
   end function axis_value

   !> Number of cases: the product of the axis sizes ('grid') or the common length ('list').
   pure integer function n_cases(self)
      class(case_config_type), intent(in) :: self
      integer :: ia
      integer(kind=8) :: n
      n = 1
      do ia = 1, n_sweep_axes
         if (.not. self%sweep%axes(ia)%active) cycle
         if (self%sweep%mode == 'list') then
            n = self%sweep%axes(ia)%size()
         else
            n = min(n*self%sweep%axes(ia)%size(), int(huge(1), kind=8))
         end if
      end do
      n_cases = int(n)
   end function n_cases

   !> Value index of every axis for case `icase` (grid: the last axis varies fastest).
   pure subroutine axis_indices(self, icase, idx)
      class(case_config_type), intent(in) :: self
      integer, intent(in) :: icase
      integer, intent(out) :: idx(n_sweep_axes)
      integer :: ia, rest, m
      idx = 0
      rest = icase - 1
      do ia = n_sweep_axes, 1, -1
         if (.not. self%sweep%axes(ia)%active) cycle
         if (self%sweep%mode == 'list') then
            idx(ia) = icase
         else
            m = self%sweep%axes(ia)%size()
            idx(ia) = mod(rest, m) + 1
            rest = rest/m
         end if
      end do
   end subroutine axis_indices

   !> The varying inputs of case `icase`: base values, replaced by the swept ones. The pitch
   !> rate, when not given, is that of pure rolling at the case's forward speed.
   pure function case_point(self, icase) result(p)
      class(case_config_type), intent(in) :: self
      !> Case index, 1 ≤ icase ≤ n_cases.
      integer, intent(in) :: icase
      type(case_point_type) :: p
      integer :: idx(n_sweep_axes), ia

      p%t_y = self%position%t_y
      p%roll = self%position%roll
      p%yaw = self%kinematics%yaw
      p%normal_force = self%load%normal_force
      p%approach = self%load%approach
      p%vertical_force = self%load%vertical_force
      p%friction = self%material%friction
      p%bound = self%tangential%bound
      p%spin_model = self%tangential%spin_model
      p%v_forward = self%kinematics%v_forward
      p%v_lateral = self%kinematics%v_lateral
      p%v_vertical = self%kinematics%v_vertical
      p%roll_rate = self%kinematics%roll_rate
      p%yaw_rate = self%kinematics%yaw_rate
      p%pitch_rate = self%kinematics%pitch_rate
      p%nu_x = self%creepage%nu_x
      p%nu_y = self%creepage%nu_y
      p%phi = self%creepage%phi
      call axis_indices(self, icase, idx)
      do ia = 1, n_sweep_axes
         if (idx(ia) == 0) cycle
         associate (axis => self%sweep%axes(ia))
            select case (trim(sweep_axis_names(ia)))
            case ('t_y'); p%t_y = axis%value(idx(ia))
            case ('roll'); p%roll = axis%value(idx(ia))
            case ('yaw'); p%yaw = axis%value(idx(ia))
            case ('normal_force'); p%normal_force = axis%value(idx(ia))
            case ('approach'); p%approach = axis%value(idx(ia))
            case ('vertical_force'); p%vertical_force = axis%value(idx(ia))
            case ('friction'); p%friction = axis%value(idx(ia))
            case ('bound'); p%bound = axis%labels(idx(ia))
            case ('spin_model'); p%spin_model = axis%labels(idx(ia))
            case ('v_forward'); p%v_forward = axis%value(idx(ia))
            case ('v_lateral'); p%v_lateral = axis%value(idx(ia))
            case ('v_vertical'); p%v_vertical = axis%value(idx(ia))
            case ('roll_rate'); p%roll_rate = axis%value(idx(ia))
            case ('yaw_rate'); p%yaw_rate = axis%value(idx(ia))
            case ('pitch_rate'); p%pitch_rate = axis%value(idx(ia))
            case ('nu_x'); p%nu_x = axis%value(idx(ia))
            case ('nu_y'); p%nu_y = axis%value(idx(ia))
            case ('phi'); p%phi = axis%value(idx(ia))
            end select
         end associate
      end do
      if (.not. (self%kinematics%pitch_rate_given .or. &
                 self%sweep%axes(axis_index('pitch_rate'))%active)) &
         p%pitch_rate = pure_rolling_pitch_rate(p%v_forward, self%track%nominal_radius)
   end function case_point

   !> The value of real input axis `ia` (numbering of [[sweep_axis_names]]) of a case; 0 for
   !> the choice axes (bound, spin_model).
   pure real(wp) function case_point_value(p, ia) result(x)
      !> The inputs of the case.
      type(case_point_type), intent(in) :: p
      !> Axis index.
      integer, intent(in) :: ia
      select case (trim(sweep_axis_names(ia)))
      case ('t_y'); x = p%t_y
      case ('roll'); x = p%roll
      case ('yaw'); x = p%yaw
      case ('normal_force'); x = p%normal_force
      case ('approach'); x = p%approach
      case ('vertical_force'); x = p%vertical_force
      case ('friction'); x = p%friction
      case ('v_forward'); x = p%v_forward
      case ('v_lateral'); x = p%v_lateral
      case ('v_vertical'); x = p%v_vertical
      case ('roll_rate'); x = p%roll_rate
      case ('yaw_rate'); x = p%yaw_rate
      case ('pitch_rate'); x = p%pitch_rate
      case ('nu_x'); x = p%nu_x
      case ('nu_y'); x = p%nu_y
      case ('phi'); x = p%phi
      case default; x = 0.0_wp
      end select
   end function case_point_value

   !> True for the wheelset inputs of a kinematic case: t_y, roll, yaw, the velocities and
   !> the rates.
   pure logical function is_kinematic_input(name)
      !> An input (sweep axis) name.
      character(len=*), intent(in) :: name
      is_kinematic_input = any(kinematic_inputs == name)
   end function is_kinematic_input

   pure logical function is_kinematic(self)
      class(case_config_type), intent(in) :: self
      is_kinematic = self%kinematics%mode == 'on'
   end function is_kinematic

   pure logical function geometry_swept(self)
      class(case_config_type), intent(in) :: self
      integer :: ia
      geometry_swept = .false.
      do ia = 1, n_sweep_axes
         if (axis_stage(ia) == axis_geometry) geometry_swept = geometry_swept .or. &
            self%sweep%axes(ia)%active
      end do
   end function geometry_swept

   pure logical function reports_input(self, ia)
      class(case_config_type), intent(in) :: self
      !> Axis index.
      integer, intent(in) :: ia
      reports_input = self%sweep%axes(ia)%active
      if (self%is_kinematic()) reports_input = reports_input .or. &
         is_kinematic_input(trim(sweep_axis_names(ia)))
   end function reports_input

   !> The smallest case index whose inputs up to `stage` (axis_geometry: t_y and roll;
   !> axis_load: also the load) equal those of case `icase`, so that its geometry (or normal
   !> solution) can be reused.
   pure integer function shares_with(self, icase, stage)
      class(case_config_type), intent(in) :: self
      integer, intent(in) :: icase, stage
      integer :: idx(n_sweep_axes), jdx(n_sweep_axes), ia, j, m, stride
      call axis_indices(self, icase, idx)
      if (self%sweep%mode == 'grid') then
         ! In a grid the outer axes change slowest: zero the inner indices.
         shares_with = 1
         stride = 1
         do ia = n_sweep_axes, 1, -1
            if (.not. self%sweep%axes(ia)%active) cycle
            m = self%sweep%axes(ia)%size()
            if (axis_stage(ia) <= stage) shares_with = shares_with + (idx(ia) - 1)*stride
            stride = stride*m
         end do
         return
      end if
      ! In a list, search the earlier cases for equal values.
      do j = 1, icase
         call axis_indices(self, j, jdx)
         shares_with = j
         do ia = 1, n_sweep_axes
            if (axis_stage(ia) > stage .or. .not. self%sweep%axes(ia)%active) cycle
            if (self%sweep%axes(ia)%value(jdx(ia)) /= self%sweep%axes(ia)%value(idx(ia))) &
               shares_with = 0
         end do
         if (shares_with > 0) return
      end do
      shares_with = icase
   end function shares_with

   !> Whether a per-case field ('geometry', 'strips', 'pressure', 'traction', 'state', 'slip')
   !> is stored: 'auto' stores them all for a single case and none in a sweep.
   pure logical function wants_field(self, field)
      class(case_config_type), intent(in) :: self
      character(len=*), intent(in) :: field
      associate (f => self%output%fields)
         if (any(f == 'none')) then
            wants_field = .false.
         else if (any(f == 'all')) then
            wants_field = .true.
         else if (any(f == 'auto') .and. self%n_cases() == 1) then
            wants_field = .true.
         else
            wants_field = any(f == field)
         end if
      end associate
   end function wants_field

   ! ------------------------------------------------------------------------------------------
   ! Printing
   ! ------------------------------------------------------------------------------------------

   !> The resolved configuration as namelist text (every variable, one per line, with its
   !> units as a comment); reading it back gives the same configuration. In kinematic mode the
   !> unused `&creepage` group is left out, and a pitch rate that was not given stays a comment
   !> (pure rolling follows each case's forward speed).
   function config_namelist(config) result(text)
      !> A validated configuration.
      type(case_config_type), intent(in) :: config
      character(len=:), allocatable :: text
      character(len=1), parameter :: nl = new_line('a')
      integer :: i, ia, n
      character(len=:), allocatable :: value, name
      type(variable_info_type) :: v
      character(len=12) :: previous

      text = ''
      previous = ''
      do i = 1, size(variables)
         v = variables(i)
         if (config%is_kinematic() .and. v%group == 'creepage') then
            if (len_trim(previous) > 0) then
               text = text//'/'//nl//"! &creepage: not used, &kinematics mode = 'on' "// &
                  'computes the creepages'//nl
               previous = ''
            end if
            cycle
         end if
         if (v%group == 'kinematics' .and. v%name == 'pitch_rate' .and. &
             .not. config%kinematics%pitch_rate_given) then
            text = text//'  ! pitch_rate not given: pure rolling, -v_forward/nominal_radius '// &
               '[rad/s]'//nl
            cycle
         end if
         if (v%group /= previous) then
            if (len_trim(previous) > 0) text = text//'/'//nl
            text = text//'&'//trim(v%group)//nl
            previous = v%group
         end if
         name = trim(v%name)
         select case (trim(v%group))
         case ('profiles')
            select case (name)
            case ('wheel'); value = quote_string(config%profiles%wheel)
            case ('rail'); value = quote_string(config%profiles%rail)
            case ('wheel_format'); value = quote_string(config%profiles%wheel_format)
            case ('rail_format'); value = quote_string(config%profiles%rail_format)
            case ('wheel_smoothing'); value = format_real(config%profiles%wheel_smoothing)
            case ('rail_smoothing'); value = format_real(config%profiles%rail_smoothing)
            case ('wheel_mirror_y'); value = quote_string(config%profiles%wheel_mirror_y)
            case ('wheel_mirror_z'); value = quote_string(config%profiles%wheel_mirror_z)
            case ('wheel_scale'); value = format_real(config%profiles%wheel_scale)
            case ('rail_mirror_y'); value = quote_string(config%profiles%rail_mirror_y)
            case ('rail_mirror_z'); value = quote_string(config%profiles%rail_mirror_z)
            case ('rail_scale'); value = format_real(config%profiles%rail_scale)
            end select
         case ('track')
            select case (name)
            case ('side'); value = quote_string(config%track%side)
            case ('gauge'); value = format_real(config%track%gauge)
            case ('gauge_height'); value = format_real(config%track%gauge_height)
            case ('inclination'); value = format_real(config%track%inclination)
            case ('rail_canted'); value = format_logical(config%track%rail_canted)
            case ('flange_back_distance')
               value = format_real(config%track%flange_back_distance)
            case ('flange_back_position')
               value = format_real(config%track%flange_back_position)
            case ('nominal_radius'); value = format_real(config%track%nominal_radius)
            end select
         case ('position')
            select case (name)
            case ('t_y'); value = format_real(config%position%t_y)
            case ('roll'); value = format_real(config%position%roll)
            end select
         case ('kinematics')
            select case (name)
            case ('mode'); value = quote_string(config%kinematics%mode)
            case ('yaw'); value = format_real(config%kinematics%yaw)
            case ('v_forward'); value = format_real(config%kinematics%v_forward)
            case ('v_lateral'); value = format_real(config%kinematics%v_lateral)
            case ('v_vertical'); value = format_real(config%kinematics%v_vertical)
            case ('roll_rate'); value = format_real(config%kinematics%roll_rate)
            case ('yaw_rate'); value = format_real(config%kinematics%yaw_rate)
            case ('pitch_rate'); value = format_real(config%kinematics%pitch_rate)
            end select
         case ('material')
            select case (name)
            case ('shear_modulus'); value = format_real(config%material%shear_modulus)
            case ('poisson'); value = format_real(config%material%poisson)
            case ('friction'); value = format_real(config%material%friction)
            end select
         case ('load')
            select case (name)
            case ('mode'); value = quote_string(config%load%mode)
            case ('normal_force'); value = format_real(config%load%normal_force)
            case ('approach'); value = format_real(config%load%approach)
            case ('vertical_force'); value = format_real(config%load%vertical_force)
            end select
         case ('creepage')
            select case (name)
            case ('nu_x'); value = format_real(config%creepage%nu_x)
            case ('nu_y'); value = format_real(config%creepage%nu_y)
            case ('phi'); value = format_real(config%creepage%phi)
            end select
         case ('normal')
            select case (name)
            case ('method'); value = quote_string(config%normal%method)
            case ('reduction'); value = quote_string(config%normal%reduction)
            case ('epsilon'); value = format_real(config%normal%epsilon)
            case ('n_strips'); value = str_int(config%normal%n_strips)
            case ('b_min'); value = format_real(config%normal%b_min)
            case ('longitudinal_curvature')
               value = quote_string(config%normal%longitudinal_curvature)
            end select
         case ('tangential')
            select case (name)
            case ('method'); value = quote_string(config%tangential%method)
            case ('bound'); value = quote_string(config%tangential%bound)
            case ('spin_model'); value = quote_string(config%tangential%spin_model)
            case ('spin_flexibility')
               value = quote_string(config%tangential%spin_flexibility)
            case ('n_elements'); value = str_int(config%tangential%n_elements)
            end select
         case ('output')
            select case (name)
            case ('file'); value = quote_string(config%output%file)
            case ('fields')
               value = ''
               do n = 1, max_fields
                  if (len_trim(config%output%fields(n)) == 0) cycle
                  if (len(value) > 0) value = value//', '
                  value = value//quote_string(config%output%fields(n))
               end do
            case ('precision'); value = quote_string(config%output%precision)
            case ('compression'); value = str_int(config%output%compression)
            case ('checkpoint_cases'); value = str_int(config%output%checkpoint_cases)
            end select
         case ('sweep')
            if (name == 'mode') then
               value = quote_string(config%sweep%mode)
            else if (index(name, '_points') > 0) then
               ia = axis_index(name(1:index(name, '_points') - 1))
               if (.not. config%sweep%axes(ia)%active) cycle
               if (config%sweep%axes(ia)%points == 0) cycle
               value = str_int(config%sweep%axes(ia)%points)
            else
               ia = axis_index(name)
               if (.not. config%sweep%axes(ia)%active) cycle
               value = axis_text(config%sweep%axes(ia))
            end if
         end select
         text = text//'  '//name//' = '//value//'  ! '
         if (len_trim(v%units) > 0) then
            if (v%units == '1') then
               text = text//'[-] '
            else
               text = text//'['//trim(v%units)//'] '
            end if
         end if
         text = text//trim(v%help)//nl
      end do
      text = text//'/'//nl
   end function config_namelist

   pure function format_logical(flag) result(text)
      logical, intent(in) :: flag
      character(len=:), allocatable :: text
      if (flag) then
         text = '.true.'
      else
         text = '.false.'
      end if
   end function format_logical

   !> The values of an axis as a namelist value list.
   pure function axis_text(axis) result(value)
      type(sweep_axis_type), intent(in) :: axis
      character(len=:), allocatable :: value
      integer :: i
      value = ''
      if (axis%is_label) then
         do i = 1, size(axis%labels)
            if (i > 1) value = value//', '
            value = value//quote_string(axis%labels(i))
         end do
      else
         do i = 1, size(axis%given)
            if (i > 1) value = value//', '
            value = value//format_real(axis%given(i))
         end do
      end if
   end function axis_text

end module shcontact_io_config
