!> One assignment applied to the configuration: checked against the variable table (known
!> name, number of values, string lengths), then read through a one-assignment namelist on an
!> internal file, so that the compiler's namelist reader converts the value and an error names
!> the file, the line, the group, the variable, the value found and what is allowed.
module shcontact_io_config_assign
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: to_lower, str_int
   use shcontact_io_files, only: join_path
   use shcontact_io_config_limits, only: path_len, name_len, max_sweep_values, &
      max_label_values, max_fields
   use shcontact_io_config_sweep, only: sweep_axis_type, sweep_config_type, n_sweep_axes, &
      axis_index
   use shcontact_io_config_types, only: case_config_type, profiles_config_type, &
      track_config_type, position_config_type, kinematics_config_type, load_config_type, &
      creepage_config_type, normal_config_type, tangential_config_type, output_config_type, &
      set_origin
   use shcontact_io_config_variables, only: variables, find_variable, type_phrase, &
      string_capacity, suggestion, group_variable_list, k_string, k_string_list, k_real_list
   use shcontact_io_config_parser, only: assignment_type
   implicit none
   private

   public :: apply_assignment

   !> Sentinel of unset sweep-list entries.
   real(wp), parameter :: unset = huge(1.0_wp)

contains

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

end module shcontact_io_config_assign
