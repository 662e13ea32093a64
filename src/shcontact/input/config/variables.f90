!> The registry of the namelist groups (issue 26): for every variable of every group its kind,
!> units and help text (for messages, the resolved namelist and the documentation), the allowed
!> values of the choice variables ([[variable_choices]], from the layers' option registries and
!> shcontact_input_config_choices), and the lookups and phrases built on them. Ranges and defaults of
!> the numbers are those of shcontact_core_ranges; test `registry` checks the configuration's
!> defaults, the library's, doc/app.md's tables and the headers' option lists against them.
module shcontact_input_config_variables
   use shcontact_core_choices, only: choice_type
   use shcontact_input_config_limits, only: path_len, name_len
   use shcontact_normal_option_registry, only: normal_methods => method_choices, &
      reduction_choices
   use shcontact_tangential_option_registry, only: tangential_methods => method_choices, &
      bound_choices, spin_model_choices, spin_flexibility_choices, correction_choices
   use shcontact_pipeline_preset, only: preset_choices
   use shcontact_input_config_choices, only: side_choices, kinematics_mode_choices, &
      load_mode_choices, curvature_choices, precision_choices, sweep_mode_choices, &
      format_choices, mirror_choices, field_choices
   implicit none
   private

   public :: variable_info_type, variables, group_names, find_variable
   public :: k_real, k_int, k_string, k_logical, k_real_list, k_string_list, k_choice
   public :: type_phrase, string_capacity, is_choice, suggestion, group_variable_list, join_words
   public :: variable_choices, header_option_keys

   !> Kinds of namelist variables.
   !> k_choice: one of a registry's choices, held as its integer code after reading.
   integer, parameter :: k_real = 1, k_int = 2, k_string = 3, k_logical = 4, k_real_list = 5, &
      k_string_list = 6, k_choice = 7

   !> Where a variable lives and what it is (messages, printing, documentation).
   type :: variable_info_type
      character(len=12) :: group = ''
      character(len=24) :: name = ''
      integer :: kind = k_real
      character(len=12) :: units = ''
      character(len=200) :: help = ''
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
      variable_info_type('profiles', 'wheel_scale', k_real, '1', &
      'wheel file: factor from its units to mm (0 = as the file/format says)'), &
      variable_info_type('profiles', 'rail_mirror_y', k_string, '', &
      "rail file: 'auto' (as the file/format says), 'yes' (y -> -y) or 'no'"), &
      variable_info_type('profiles', 'rail_mirror_z', k_string, '', &
      "rail file: 'auto' (as the file/format says), 'yes' (z -> -z) or 'no'"), &
      variable_info_type('profiles', 'rail_scale', k_real, '1', &
      'rail file: factor from its units to mm (0 = as the file/format says)'), &
      variable_info_type('track', 'side', k_choice, '', 'wheel and rail of this side'), &
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
      variable_info_type('kinematics', 'mode', k_choice, '', &
      'prescribed creepages or creepages from the wheelset motion'), &
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
      variable_info_type('load', 'mode', k_choice, '', 'how the normal problem is loaded'), &
      variable_info_type('load', 'normal_force', k_real, 'N', "normal force N (mode 'force')"), &
      variable_info_type('load', 'approach', k_real, 'mm', "rigid approach (mode 'approach')"), &
      variable_info_type('load', 'vertical_force', k_real, 'N', &
      "vertical wheel load shared by the patches (mode 'vertical')"), &
      variable_info_type('creepage', 'nu_x', k_real, '1', 'longitudinal creepage'), &
      variable_info_type('creepage', 'nu_y', k_real, '1', 'lateral creepage'), &
      variable_info_type('creepage', 'phi', k_real, 'rad/mm', 'spin creepage'), &
      variable_info_type('normal', 'method', k_choice, '', 'normal contact model'), &
      variable_info_type('normal', 'reduction', k_choice, '', &
      'penetration reduction of the semi-Hertzian strips'), &
      variable_info_type('normal', 'epsilon', k_real, '1', &
      "penetration reduction of reduction = 'constant'"), &
      variable_info_type('normal', 'n_strips', k_int, '', 'number of strips per patch'), &
      variable_info_type('normal', 'b_min', k_real, '1/mm', &
      'smallest lateral relative curvature B (concave gap curvature is clamped to it)'), &
      variable_info_type('normal', 'longitudinal_curvature', k_choice, '', &
      'contact angle of A(y) = cos(gamma)/(2 r_w)'), &
      variable_info_type('normal', 'preset', k_choice, '', &
      'grid and strip tables at once: n_strips, tangential n_elements (unless given), '// &
      'table spacing'), &
      variable_info_type('tangential', 'method', k_choice, '', 'tangential contact model'), &
      variable_info_type('tangential', 'bound', k_choice, '', &
      'traction bound (doc/theory.md decision 9)'), &
      variable_info_type('tangential', 'spin_model', k_choice, '', &
      'local spin of the strips (doc/theory.md §6.2)'), &
      variable_info_type('tangential', 'spin_flexibility', k_choice, '', &
      'flexibility of the spin part of the longitudinal slip'), &
      variable_info_type('tangential', 'correction', k_choice, '', &
      'correction of the tangential forces (doc/tangential.md)'), &
      variable_info_type('tangential', 'n_elements', k_int, '', &
      'number of elements per strip (n_x)'), &
      variable_info_type('output', 'file', k_string, '', 'HDF5 output file'), &
      variable_info_type('output', 'fields', k_string_list, '', &
      "'auto', 'all', 'none' or from 'geometry', 'strips', 'pressure', 'traction', 'state', 'slip'"), &
      variable_info_type('output', 'precision', k_choice, '', &
      'storage of the per-element fields'), &
      variable_info_type('output', 'compression', k_int, '', &
      'deflate level of the fields, 0 (off) to 9'), &
      variable_info_type('output', 'checkpoint_cases', k_int, '', &
      'cases per checkpoint block of a sweep (0 = automatic)'), &
      variable_info_type('sweep', 'mode', k_choice, '', 'how the lists make cases'), &
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

   !> The options listed in the headers' option lists (include/shcontact.h, include/shcontact.fi):
   !> every choice and every number with a range that the option setters of the C and Fortran
   !> 77 interfaces take ("group%variable" as in a case file): all of the case file's but the
   !> profile files', the side's (both given at creation), the output's and the sweep's.
   character(len=*), parameter :: header_option_keys(*) = [character(len=30) :: &
      'profiles%wheel_smoothing', 'profiles%rail_smoothing', 'track%gauge', &
      'track%gauge_height', 'track%inclination', 'track%flange_back_distance', &
      'track%flange_back_position', 'track%nominal_radius', 'position%t_y', 'position%roll', &
      'kinematics%mode', 'kinematics%yaw', 'kinematics%v_forward', 'kinematics%v_lateral', &
      'kinematics%v_vertical', 'kinematics%roll_rate', 'kinematics%yaw_rate', &
      'kinematics%pitch_rate', 'material%shear_modulus', 'material%poisson', 'material%friction', &
      'load%mode', 'load%normal_force', 'load%approach', 'load%vertical_force', 'creepage%nu_x', &
      'creepage%nu_y', 'creepage%phi', 'normal%method', 'normal%reduction', 'normal%epsilon', &
      'normal%n_strips', 'normal%b_min', 'normal%longitudinal_curvature', 'normal%preset', &
      'tangential%method', &
      'tangential%bound', 'tangential%spin_model', 'tangential%spin_flexibility', &
      'tangential%correction', 'tangential%n_elements']

   character(len=*), parameter :: group_names(*) = [character(len=12) :: 'profiles', 'track', &
      'position', 'kinematics', 'material', 'load', 'creepage', 'normal', 'tangential', &
      'output', 'sweep']

contains

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

   !> The allowed values of a choice variable (`k_choice`, or a string or string list with a
   !> fixed set of values); none for any other variable. A `&sweep` list of choices takes the
   !> choices of the variable it sweeps.
   pure function variable_choices(group, name) result(choices)
      !> Group and variable.
      character(len=*), intent(in) :: group, name
      type(choice_type), allocatable :: choices(:)
      select case (trim(group)//'%'//trim(name))
      case ('profiles%wheel_format', 'profiles%rail_format')
         choices = format_choices
      case ('profiles%wheel_mirror_y', 'profiles%wheel_mirror_z', 'profiles%rail_mirror_y', &
            'profiles%rail_mirror_z')
         choices = mirror_choices
      case ('track%side')
         choices = side_choices
      case ('kinematics%mode')
         choices = kinematics_mode_choices
      case ('load%mode')
         choices = load_mode_choices
      case ('normal%method')
         choices = normal_methods
      case ('normal%reduction')
         choices = reduction_choices
      case ('normal%longitudinal_curvature')
         choices = curvature_choices
      case ('normal%preset')
         choices = preset_choices
      case ('tangential%method')
         choices = tangential_methods
      case ('tangential%bound', 'sweep%bound')
         choices = bound_choices
      case ('tangential%spin_model', 'sweep%spin_model')
         choices = spin_model_choices
      case ('tangential%spin_flexibility')
         choices = spin_flexibility_choices
      case ('tangential%correction')
         choices = correction_choices
      case ('output%fields')
         choices = field_choices
      case ('output%precision')
         choices = precision_choices
      case ('sweep%mode')
         choices = sweep_mode_choices
      case default
         allocate (choices(0))
      end select
   end function variable_choices

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
      case (k_choice)
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

   !> True for a string variable that names a choice (every string but the file names): its
   !> values are case-insensitive and stored in lower case.
   pure logical function is_choice(v)
      type(variable_info_type), intent(in) :: v
      is_choice = v%kind == k_choice .or. ((v%kind == k_string .or. v%kind == k_string_list) &
         .and. string_capacity(v) == name_len)
   end function is_choice

   !> " (it belongs to &position)" when other groups have a variable of that name, else
   !> " (did you mean X?)" for a close variable name of the group.
   pure function suggestion(group, name) result(s)
      character(len=*), intent(in) :: group, name
      character(len=:), allocatable :: s
      integer :: i, best, d, dbest
      s = ''
      do i = 1, size(variables)
         if (variables(i)%group == group .or. trim(variables(i)%name) /= name) cycle
         if (len(s) == 0) then
            s = ' (it belongs to &'//trim(variables(i)%group)
         else
            s = s//', &'//trim(variables(i)%group)
         end if
      end do
      if (len(s) > 0) then
         s = s//')'
         return
      end if
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

end module shcontact_input_config_variables
