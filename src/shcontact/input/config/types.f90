!> The typed configuration of a run: one derived type per namelist group, with the defaults of
!> the seed's headline case (taken from the registries: the numbers' from the variable table of
!> shcontact_core_ranges, the choices' from the option registries; choices are held as their
!> integer codes; test `registry`), the whole
!> configuration with where each value was set, and the questions downstream code asks of it
!> (number of cases, inputs of a case, fields to store, the library's options).
module shcontact_input_config_types
   use shcontact_core_kinds, only: wp
   use shcontact_core_material, only: material_type
   use shcontact_core_ranges, only: variables
   use shcontact_geometry_kinematics, only: pure_rolling_pitch_rate
   use shcontact_geometry_track, only: track_type
   use shcontact_geometry_prepared, only: contact_options_type
   use shcontact_input_config_limits, only: path_len, name_len, max_fields
   use shcontact_input_config_choices, only: side_right, kinematics_off, kinematics_on, &
      load_mode_force, curvature_local, curvature_reference, tables_planar, tables_conformal, precision_double
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type, method_fastsim, &
      bound_parabolic
   use shcontact_pipeline_preset, only: default_preset, preset_strips, preset_elements, &
      preset_table_step
   use shcontact_input_config_sweep, only: sweep_config_type, case_point_type, sweep_axis_names, &
      axis_index, is_kinematic_input
   implicit none
   private

   public :: case_config_type, profiles_config_type, track_config_type, position_config_type
   public :: kinematics_config_type, load_config_type, creepage_config_type, normal_config_type
   public :: tangential_config_type, output_config_type
   public :: set_origin, origin, sweep_origin, choice_value, set_choice_value
   public :: number_value, string_value, logical_value
   public :: normal_options_of, tangential_options_of, table_step_of, contact_options_of, track_of

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
      real(wp) :: wheel_smoothing = variables(findloc(variables%name, 'wheel_smoothing', 1, &
         mask=variables%group == 'profiles'))%default
      real(wp) :: rail_smoothing = variables(findloc(variables%name, 'rail_smoothing', 1, &
         mask=variables%group == 'profiles'))%default
      !> Mirror y or z of a profile file: 'auto' (the file's or format's convention), 'yes',
      !> 'no' (CONTACT's MIRRORY/MIRRORZ).
      character(len=name_len) :: wheel_mirror_y = 'auto', wheel_mirror_z = 'auto'
      character(len=name_len) :: rail_mirror_y = 'auto', rail_mirror_z = 'auto'
      !> Factor from a profile file's units to mm; 0: the file's or format's (CONTACT's SCALE).
      real(wp) :: wheel_scale = variables(findloc(variables%name, 'wheel_scale', 1, &
         mask=variables%group == 'profiles'))%default
      real(wp) :: rail_scale = variables(findloc(variables%name, 'rail_scale', 1, &
         mask=variables%group == 'profiles'))%default
   end type profiles_config_type

   !> `&track`: track and wheelset dimensions (doc/theory.md §5.2).
   type :: track_config_type
      !> `side_right` or `side_left` (shcontact_input_config_choices).
      integer :: side = side_right
      !> Track gauge (mm), measured `gauge_height` below the rail top.
      real(wp) :: gauge = variables(findloc(variables%name, 'gauge', 1, &
         mask=variables%group == 'track'))%default
      real(wp) :: gauge_height = variables(findloc(variables%name, 'gauge_height', 1, &
         mask=variables%group == 'track'))%default
      !> Rail inclination as a slope towards the track centre (1:40).
      real(wp) :: inclination = variables(findloc(variables%name, 'inclination', 1, &
         mask=variables%group == 'track'))%default
      !> The rail profile is already canted: the inclination is not applied again.
      logical :: rail_canted = .false.
      !> Flange-back distance and flange-back position in wheel-profile coordinates (mm).
      real(wp) :: flange_back_distance = variables(findloc(variables%name, 'flange_back_distance', 1, &
         mask=variables%group == 'track'))%default
      real(wp) :: flange_back_position = variables(findloc(variables%name, 'flange_back_position', 1, &
         mask=variables%group == 'track'))%default
      !> Nominal rolling radius R₀ (mm).
      real(wp) :: nominal_radius = variables(findloc(variables%name, 'nominal_radius', 1, &
         mask=variables%group == 'track'))%default
   end type track_config_type

   !> `&position`: wheelset position.
   type :: position_config_type
      !> Lateral shift (mm), CONTACT's Y_WS (doc/theory.md decision 13). The seed's "t_y = 5.8 mm"
      !> measured between the profile origins corresponds to Y_WS = 10.533 − 5.8 = 4.733 mm,
      !> where the geometric spin equals the seed's φ = 0.274 1/m (doc/app.md, "Why 4.733 mm").
      real(wp) :: t_y = variables(findloc(variables%name, 't_y', 1, &
         mask=variables%group == 'position'))%default
      !> Roll angle (rad).
      real(wp) :: roll = variables(findloc(variables%name, 'roll', 1, &
         mask=variables%group == 'position'))%default
   end type position_config_type

   !> `&kinematics`: the wheelset's motion (CONTACT's module 1, doc/theory.md decision 14). With
   !> mode 'on' the creepages of every patch come from the rigid-body motion of the wheelset
   !> (the library's `solve_kinematic`) instead of `&creepage`; the lateral shift and the roll
   !> are those of `&position`. Track frame: x forward, y towards the right field side, z down.
   type :: kinematics_config_type
      !> `kinematics_off` (prescribed creepages, `&creepage`) or `kinematics_on`.
      integer :: mode = kinematics_off
      !> Yaw angle ψ (rad), CONTACT's YAW_WS.
      real(wp) :: yaw = variables(findloc(variables%name, 'yaw', 1, &
         mask=variables%group == 'kinematics'))%default
      !> Forward speed of the wheelset centre V (mm/s, > 0): 30 m/s.
      real(wp) :: v_forward = variables(findloc(variables%name, 'v_forward', 1, &
         mask=variables%group == 'kinematics'))%default
      !> Lateral and vertical velocity of the wheelset centre (mm/s).
      real(wp) :: v_lateral = variables(findloc(variables%name, 'v_lateral', 1, &
         mask=variables%group == 'kinematics'))%default
      real(wp) :: v_vertical = variables(findloc(variables%name, 'v_vertical', 1, &
         mask=variables%group == 'kinematics'))%default
      !> Roll and yaw rate (rad/s).
      real(wp) :: roll_rate = variables(findloc(variables%name, 'roll_rate', 1, &
         mask=variables%group == 'kinematics'))%default
      real(wp) :: yaw_rate = variables(findloc(variables%name, 'yaw_rate', 1, &
         mask=variables%group == 'kinematics'))%default
      !> Angular velocity about the axle (rad/s, < 0 rolling forward); used only when given
      !> (`pitch_rate_given`), else pure rolling −V/R₀ of each case's V.
      real(wp) :: pitch_rate = 0.0_wp
      !> True when `pitch_rate` was set (case file or override); set by [[validate_config]].
      logical :: pitch_rate_given = .false.
   end type kinematics_config_type

   !> `&load`: how the normal problem is loaded.
   type :: load_config_type
      !> `load_mode_force`, `load_mode_approach` or `load_mode_vertical`.
      integer :: mode = load_mode_force
      !> Normal force on the patch (N), rigid approach (mm), vertical wheel load (N).
      real(wp) :: normal_force = variables(findloc(variables%name, 'normal_force', 1, &
         mask=variables%group == 'load'))%default
      real(wp) :: approach = variables(findloc(variables%name, 'approach', 1, &
         mask=variables%group == 'load'))%default
      real(wp) :: vertical_force = variables(findloc(variables%name, 'vertical_force', 1, &
         mask=variables%group == 'load'))%default
   end type load_config_type

   !> `&creepage`: creepages at the geometric contact point (doc/theory.md decision 2).
   type :: creepage_config_type
      !> ν_x, ν_y (dimensionless), φ (rad/mm).
      real(wp) :: nu_x = variables(findloc(variables%name, 'nu_x', 1, &
         mask=variables%group == 'creepage'))%default
      real(wp) :: nu_y = variables(findloc(variables%name, 'nu_y', 1, &
         mask=variables%group == 'creepage'))%default
      real(wp) :: phi = variables(findloc(variables%name, 'phi', 1, &
         mask=variables%group == 'creepage'))%default
   end type creepage_config_type

   !> `&normal`: the normal solver. Its own options (method, reduction, epsilon, n_strips) are
   !> the library's type, so their fields, defaults and choice accessors are written once
   !> (shcontact_normal_options); the contact search's and the preset's follow.
   type, extends(normal_options_type) :: normal_config_type
      !> Clamp of B(y) (1/mm), doc/theory.md decision 4.
      real(wp) :: b_min = variables(findloc(variables%name, 'b_min', 1, &
         mask=variables%group == 'normal'))%default
      !> `curvature_local` (cos γ(y)) or `curvature_reference` (cos γ₀) in A(y).
      integer :: longitudinal_curvature = curvature_local
      !> `tables_planar` or `tables_conformal`: the strip tables of the contact search.
      integer :: strip_tables = tables_planar
      !> `preset_*` of shcontact_pipeline_preset: sets n_strips, tangential n_elements (where
      !> the case does not give them) and the strip-table spacing.
      integer :: preset = default_preset
   end type normal_config_type

   !> `&tangential`: the tangential solver: the library's options type itself (fields,
   !> defaults and choice accessors written once, in shcontact_tangential_options).
   type, extends(tangential_options_type) :: tangential_config_type
   end type tangential_config_type

   !> `&output`: the HDF5 file.
   type :: output_config_type
      character(len=path_len) :: file = 'shcontact.h5'
      !> Per-case fields to store ('auto': all for a single case, none in a sweep).
      character(len=name_len) :: fields(max_fields) = reshape([character(len=name_len) :: &
         'auto'], [max_fields], pad=[character(len=name_len) :: ''])
      !> `precision_double` or `precision_single`.
      integer :: precision = precision_double
      integer :: compression = nint(variables(findloc(variables%name, 'compression', 1, &
         mask=variables%group == 'output'))%default)
      integer :: checkpoint_cases = nint(variables(findloc(variables%name, 'checkpoint_cases', 1, &
         mask=variables%group == 'output'))%default)
   end type output_config_type

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

contains

   !> Number of cases of the run (1 without a sweep).
   pure integer function n_cases(self)
      class(case_config_type), intent(in) :: self
      n_cases = self%sweep%n_cases()
   end function n_cases

   !> The varying inputs of case `icase`: base values, replaced by the swept ones. The pitch
   !> rate, when not given, is that of pure rolling at the case's forward speed.
   pure function case_point(self, icase) result(p)
      class(case_config_type), intent(in) :: self
      !> Case index, 1 ≤ icase ≤ n_cases.
      integer, intent(in) :: icase
      type(case_point_type) :: p

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
      call self%sweep%vary_point(icase, p)
      if (.not. (self%kinematics%pitch_rate_given .or. &
                 self%sweep%axes(axis_index('pitch_rate'))%active)) &
         p%pitch_rate = pure_rolling_pitch_rate(p%v_forward, self%track%nominal_radius)
   end function case_point

   !> The first case with the inputs of case `icase` up to `stage`, whose geometry (or normal
   !> solution) can be reused.
   pure integer function shares_with(self, icase, stage)
      class(case_config_type), intent(in) :: self
      integer, intent(in) :: icase, stage
      shares_with = self%sweep%shares_with(icase, stage)
   end function shares_with

   pure logical function geometry_swept(self)
      class(case_config_type), intent(in) :: self
      geometry_swept = self%sweep%geometry_swept()
   end function geometry_swept

   pure logical function is_kinematic(self)
      class(case_config_type), intent(in) :: self
      is_kinematic = self%kinematics%mode == kinematics_on
   end function is_kinematic

   pure logical function reports_input(self, ia)
      class(case_config_type), intent(in) :: self
      !> Axis index.
      integer, intent(in) :: ia
      reports_input = self%sweep%axes(ia)%active
      if (self%is_kinematic()) reports_input = reports_input .or. &
         is_kinematic_input(trim(sweep_axis_names(ia)))
   end function reports_input

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

   !> The library's normal options of a configuration (`&normal`; b_min and the longitudinal
   !> curvature are options of the contact search). `&normal preset` gives n_strips unless the
   !> case gives it (an explicit value wins, doc/app.md).
   pure function normal_options_of(config) result(options)
      type(case_config_type), intent(in) :: config
      type(normal_options_type) :: options
      options = config%normal%normal_options_type
      if (origin(config, 'normal%n_strips') == 'default') &
         options%n_strips = preset_strips(config%normal%preset)
   end function normal_options_of

   !> The library's contact-search options of a configuration: the profiles' smoothing, the
   !> clamp of B and the longitudinal curvature (`&normal`), the strip-table spacing of
   !> `&normal preset`.
   pure function contact_options_of(config) result(options)
      type(case_config_type), intent(in) :: config
      type(contact_options_type) :: options
      options%l_filt_wheel = config%profiles%wheel_smoothing
      options%l_filt_rail = config%profiles%rail_smoothing
      options%b_min = config%normal%b_min
      options%a_reference_normal = config%normal%longitudinal_curvature == curvature_reference
      options%conformal_tables = config%normal%strip_tables == tables_conformal
      options%table_step = table_step_of(config)
   end function contact_options_of

   !> The library's track and wheelset dimensions of a configuration (`&track`).
   pure function track_of(config) result(track)
      type(case_config_type), intent(in) :: config
      type(track_type) :: track
      track%gauge = config%track%gauge
      track%gauge_height = config%track%gauge_height
      track%rail_inclination = config%track%inclination
      track%rail_canted = config%track%rail_canted
      track%flange_back_distance = config%track%flange_back_distance
      track%flange_back_position = config%track%flange_back_position
      track%nominal_radius = config%track%nominal_radius
   end function track_of

   !> The strip-table spacing (mm) of the contact search (`contact_options_type%table_step`):
   !> that of `&normal preset`.
   pure real(wp) function table_step_of(config) result(step)
      type(case_config_type), intent(in) :: config
      step = preset_table_step(config%normal%preset)
   end function table_step_of

   !> The library's tangential options of a configuration (`&tangential`); the bound and the
   !> spin model of a case may come from a sweep (case_point), the fields from `&output`.
   pure function tangential_options_of(config) result(options)
      type(case_config_type), intent(in) :: config
      type(tangential_options_type) :: options
      options = config%tangential%tangential_options_type
      if (origin(config, 'tangential%n_elements') == 'default') &
         options%n_elements = preset_elements(config%normal%preset)
      ! Classical FASTSIM is Kalker's: its parabolic traction bound, unless the case chooses
      ! another (the default W1 bound belongs to FASTSIM_SH's strips; on an ellipse it makes
      ! Kalker's creep coefficients 1.39 times too large, doc/theory.md §6.4).
      if (options%method == method_fastsim .and. origin(config, 'tangential%bound') == &
         'default') options%bound = bound_parabolic
   end function tangential_options_of

   !> The code held by the choice variable `group%name` (kind `k_choice` of the variable table);
   !> 0 for any other name.
   pure integer function choice_value(config, group, name) result(code)
      type(case_config_type), intent(in) :: config
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      select case (trim(group)//'%'//trim(name))
      case ('track%side'); code = config%track%side
      case ('kinematics%mode'); code = config%kinematics%mode
      case ('load%mode'); code = config%load%mode
      case ('normal%longitudinal_curvature'); code = config%normal%longitudinal_curvature
      case ('normal%strip_tables'); code = config%normal%strip_tables
      case ('normal%preset'); code = config%normal%preset
      case ('output%precision'); code = config%output%precision
      case ('sweep%mode'); code = config%sweep%mode
      case default
         ! The solvers' own choices: their options types' accessors.
         code = 0
         if (group == 'normal') code = config%normal%get_choice(name)
         if (group == 'tangential') code = config%tangential%get_choice(name)
      end select
   end function choice_value

   !> The value of the number `group%name` (kind k_real or k_int of the variable table, every
   !> group but `&sweep`; an integer as a real); 0 for any other name. The one accessor of each
   !> number by name: the validation's range checks and the resolved namelist loop over the
   !> variable table through it.
   pure real(wp) function number_value(config, group, name) result(x)
      type(case_config_type), intent(in) :: config
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      select case (trim(group)//'%'//trim(name))
      case ('profiles%wheel_smoothing'); x = config%profiles%wheel_smoothing
      case ('profiles%rail_smoothing'); x = config%profiles%rail_smoothing
      case ('profiles%wheel_scale'); x = config%profiles%wheel_scale
      case ('profiles%rail_scale'); x = config%profiles%rail_scale
      case ('track%gauge'); x = config%track%gauge
      case ('track%gauge_height'); x = config%track%gauge_height
      case ('track%inclination'); x = config%track%inclination
      case ('track%flange_back_distance'); x = config%track%flange_back_distance
      case ('track%flange_back_position'); x = config%track%flange_back_position
      case ('track%nominal_radius'); x = config%track%nominal_radius
      case ('position%t_y'); x = config%position%t_y
      case ('position%roll'); x = config%position%roll
      case ('kinematics%yaw'); x = config%kinematics%yaw
      case ('kinematics%v_forward'); x = config%kinematics%v_forward
      case ('kinematics%v_lateral'); x = config%kinematics%v_lateral
      case ('kinematics%v_vertical'); x = config%kinematics%v_vertical
      case ('kinematics%roll_rate'); x = config%kinematics%roll_rate
      case ('kinematics%yaw_rate'); x = config%kinematics%yaw_rate
      case ('kinematics%pitch_rate'); x = config%kinematics%pitch_rate
      case ('material%shear_modulus'); x = config%material%shear_modulus
      case ('material%poisson'); x = config%material%poisson
      case ('material%friction'); x = config%material%friction
      case ('load%normal_force'); x = config%load%normal_force
      case ('load%approach'); x = config%load%approach
      case ('load%vertical_force'); x = config%load%vertical_force
      case ('creepage%nu_x'); x = config%creepage%nu_x
      case ('creepage%nu_y'); x = config%creepage%nu_y
      case ('creepage%phi'); x = config%creepage%phi
      case ('normal%epsilon'); x = config%normal%epsilon
      case ('normal%n_strips'); x = config%normal%n_strips
      case ('normal%b_min'); x = config%normal%b_min
      case ('tangential%n_elements'); x = config%tangential%n_elements
      case ('output%compression'); x = config%output%compression
      case ('output%checkpoint_cases'); x = config%output%checkpoint_cases
      case default; x = 0.0_wp
      end select
   end function number_value

   !> The value of the string `group%name` (kind k_string of the variable table); '' for any
   !> other name.
   pure function string_value(config, group, name) result(text)
      type(case_config_type), intent(in) :: config
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      character(len=:), allocatable :: text
      select case (trim(group)//'%'//trim(name))
      case ('profiles%wheel'); text = config%profiles%wheel
      case ('profiles%rail'); text = config%profiles%rail
      case ('profiles%wheel_format'); text = config%profiles%wheel_format
      case ('profiles%rail_format'); text = config%profiles%rail_format
      case ('profiles%wheel_mirror_y'); text = config%profiles%wheel_mirror_y
      case ('profiles%wheel_mirror_z'); text = config%profiles%wheel_mirror_z
      case ('profiles%rail_mirror_y'); text = config%profiles%rail_mirror_y
      case ('profiles%rail_mirror_z'); text = config%profiles%rail_mirror_z
      case ('output%file'); text = config%output%file
      case default; text = ''
      end select
   end function string_value

   !> The value of the logical `group%name` (kind k_logical of the variable table); .false.
   !> for any other name.
   pure logical function logical_value(config, group, name) result(flag)
      type(case_config_type), intent(in) :: config
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      select case (trim(group)//'%'//trim(name))
      case ('track%rail_canted'); flag = config%track%rail_canted
      case default; flag = .false.
      end select
   end function logical_value

   !> Store `code` in the choice variable `group%name` ([[choice_value]]'s names).
   pure subroutine set_choice_value(config, group, name, code)
      type(case_config_type), intent(inout) :: config
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      !> A code of the variable's choices.
      integer, intent(in) :: code
      select case (trim(group)//'%'//trim(name))
      case ('track%side'); config%track%side = code
      case ('kinematics%mode'); config%kinematics%mode = code
      case ('load%mode'); config%load%mode = code
      case ('normal%longitudinal_curvature'); config%normal%longitudinal_curvature = code
      case ('normal%strip_tables'); config%normal%strip_tables = code
      case ('normal%preset'); config%normal%preset = code
      case ('output%precision'); config%output%precision = code
      case ('sweep%mode'); config%sweep%mode = code
      case default
         ! The solvers' own choices: their options types' accessors.
         if (group == 'normal') call config%normal%set_choice(name, code)
         if (group == 'tangential') call config%tangential%set_choice(name, code)
      end select
   end subroutine set_choice_value

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

end module shcontact_input_config_types
