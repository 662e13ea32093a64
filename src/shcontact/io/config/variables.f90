!> The namelist variables: for every variable of every group its kind, units and help text
!> (for messages, the resolved namelist and the documentation), the allowed values of the
!> choice variables, and the lookups and phrases built on them.
module shcontact_io_config_variables
   use shcontact_io_config_limits, only: path_len, name_len
   implicit none
   private

   public :: variable_info_type, variables, group_names, find_variable
   public :: k_real, k_int, k_string, k_logical, k_real_list, k_string_list
   public :: type_phrase, string_capacity, is_choice, suggestion, group_variable_list, join_words
   public :: mirror_choices, formats, sides, load_modes, normal_methods, curvature_modes
   public :: reductions, tangential_methods, bounds, spin_models, spin_flexibilities, corrections
   public :: bound_choices, spin_model_choices, field_names, precisions, sweep_modes
   public :: kinematics_modes

   !> Kinds of namelist variables.
   integer, parameter :: k_real = 1, k_int = 2, k_string = 3, k_logical = 4, k_real_list = 5, &
      k_string_list = 6

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
      variable_info_type('tangential', 'correction', k_string, '', &
      "'exact-ellipse' (add the exact theory's defect of the equivalent Hertz ellipse to the "// &
      "forces; default model only) or 'none' (the march's forces)"), &
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
   !> The traction bounds and spin models (doc/theory.md decisions 9, 10).
   character(len=*), parameter :: bounds(*) = [character(len=13) :: 'ellipsoidal', 'parabolic', &
      'weighted', 'weighted-slip', 'clipped']
   character(len=*), parameter :: spin_models(*) = [character(len=9) :: 'additive', 'uniform', &
      'scaled', 'geometric']
   character(len=*), parameter :: spin_flexibilities(*) = [character(len=12) :: &
      'longitudinal', 'spin']
   !> The corrections of the tangential forces (doc/tangential.md).
   character(len=*), parameter :: corrections(*) = [character(len=13) :: 'exact-ellipse', 'none']
   character(len=*), parameter :: bound_choices(*) = bounds, spin_model_choices(*) = spin_models
   character(len=*), parameter :: field_names(*) = [character(len=8) :: 'auto', 'all', 'none', &
      'geometry', 'strips', 'pressure', 'traction', 'state', 'slip']
   character(len=*), parameter :: precisions(*) = [character(len=6) :: 'double', 'single']
   character(len=*), parameter :: sweep_modes(*) = [character(len=4) :: 'grid', 'list']
   character(len=*), parameter :: kinematics_modes(*) = [character(len=3) :: 'off', 'on']

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

   !> True for a string variable that names a choice (every string but the file names): its
   !> values are case-insensitive and stored in lower case.
   pure logical function is_choice(v)
      type(variable_info_type), intent(in) :: v
      is_choice = (v%kind == k_string .or. v%kind == k_string_list) .and. &
         string_capacity(v) == name_len
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

end module shcontact_io_config_variables
