!> The sweep of a run: the sweepable quantities (axes), the values of each axis, and the cases
!> they span, either every combination ('grid') or the i-th value of every list ('list').
module shcontact_input_config_sweep
   use shcontact_core_kinds, only: wp
   use shcontact_core_choices, only: choice_name, choice_name_length
   use shcontact_input_config_limits, only: name_len
   use shcontact_input_config_choices, only: sweep_grid, sweep_list
   use shcontact_tangential_option_registry, only: bound_choices, spin_model_choices
   implicit none
   private

   public :: sweep_axis_type, sweep_config_type, case_point_type
   public :: n_sweep_axes, sweep_axis_names, axis_geometry, axis_load, axis_tangential, axis_stage
   public :: axis_index, case_point_value, case_point_label, is_kinematic_input

   !> Sweepable quantities, in loop order (outermost first): geometry, then load, then the
   !> tangential inputs, so that consecutive cases share geometry and normal solution.
   !> The wheelset velocities (`&kinematics`) are swept only in kinematic mode, the creepages
   !> (`&creepage`) only in prescribed-creepage mode.
   integer, parameter :: n_sweep_axes = 18
   character(len=*), parameter :: sweep_axis_names(n_sweep_axes) = [character(len=16) :: &
      't_y', 'roll', 'yaw', 'normal_force', 'approach', 'vertical_force', 'friction', 'bound', &
      'spin_model', 'v_forward', 'v_lateral', 'v_vertical', 'roll_rate', 'yaw_rate', &
      'pitch_rate', 'nu_x', 'nu_y', 'phi']
   !> The axes' indices in [[sweep_axis_names]] (so that a case is built without comparing names).
   integer, parameter :: ax_t_y = 1, ax_roll = 2, ax_yaw = 3, ax_normal_force = 4, &
      ax_approach = 5, ax_vertical_force = 6, ax_friction = 7, ax_bound = 8, ax_spin_model = 9, &
      ax_v_forward = 10, ax_v_lateral = 11, ax_v_vertical = 12, ax_roll_rate = 13, &
      ax_yaw_rate = 14, ax_pitch_rate = 15, ax_nu_x = 16, ax_nu_y = 17, ax_phi = 18
   !> Which stage an axis changes: 1 geometry, 2 normal load, 3 tangential only.
   integer, parameter :: axis_geometry = 1, axis_load = 2, axis_tangential = 3
   integer, parameter :: axis_stage(n_sweep_axes) = [1, 1, 1, 2, 2, 2, 3, 3, 3, 3, 3, 3, 3, &
      3, 3, 3, 3, 3]
   !> The wheelset inputs of a kinematic case (position and velocities), in axis order.
   character(len=*), parameter :: kinematic_inputs(9) = [character(len=10) :: 't_y', 'roll', &
      'yaw', 'v_forward', 'v_lateral', 'v_vertical', 'roll_rate', 'yaw_rate', 'pitch_rate']

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
      !> Values of a choice axis, as written (lower case); their codes (the tangential option
      !> registry's), set by the validation.
      character(len=name_len), allocatable :: labels(:)
      integer, allocatable :: codes(:)
   contains
      !> Number of values.
      procedure :: size => axis_size
      !> The i-th value of a real axis.
      procedure :: value => axis_value
   end type sweep_axis_type

   !> `&sweep`: the axes, indexed as [[sweep_axis_names]].
   type :: sweep_config_type
      !> `sweep_grid` or `sweep_list` (shcontact_input_config_choices).
      integer :: mode = sweep_grid
      type(sweep_axis_type) :: axes(n_sweep_axes)
   contains
      !> Number of cases of the sweep (1 without active axes).
      procedure :: n_cases => sweep_n_cases
      !> The inputs of case i: the given base point with the swept values put in.
      procedure :: vary_point
      !> Index of the first case that has the same inputs up to a stage.
      procedure :: shares_with => sweep_shares_with
      !> True when a geometry axis (t_y, roll or yaw) is swept.
      procedure :: geometry_swept => sweep_geometry_swept
   end type sweep_config_type

   !> The inputs of one case that a sweep may vary.
   type :: case_point_type
      real(wp) :: t_y = 0.0_wp, roll = 0.0_wp
      !> Wheelset yaw (rad), velocities (mm/s) and rates (rad/s) of a kinematic case; the pitch
      !> rate is resolved (pure rolling when not given).
      real(wp) :: yaw = 0.0_wp
      real(wp) :: normal_force = 0.0_wp, approach = 0.0_wp, vertical_force = 0.0_wp
      real(wp) :: friction = 0.0_wp
      !> Codes of the traction bound and the spin model (shcontact_tangential_option_registry).
      integer :: bound = 0, spin_model = 0
      real(wp) :: v_forward = 0.0_wp, v_lateral = 0.0_wp, v_vertical = 0.0_wp
      real(wp) :: roll_rate = 0.0_wp, yaw_rate = 0.0_wp, pitch_rate = 0.0_wp
      real(wp) :: nu_x = 0.0_wp, nu_y = 0.0_wp, phi = 0.0_wp
   end type case_point_type

contains

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
   !> with the last point exactly `last`, and a point that is a short decimal but for the
   !> rounding of that arithmetic taken as that decimal ([[decimal_value]]: roll = −0.1, 0.1
   !> in 5 points gave 0.05000000000000002, which a script's `grep 0.05` missed).
   pure real(wp) function axis_value(self, i)
      class(sweep_axis_type), intent(in) :: self
      integer, intent(in) :: i
      real(wp) :: step
      if (self%points > 0) then
         if (i == self%points) then
            axis_value = self%given(2)
         else
            step = (self%given(2) - self%given(1))/real(self%points - 1, wp)
            axis_value = decimal_value(self%given(1) + (self%given(2) - self%given(1))* &
               real(i - 1, wp)/real(self%points - 1, wp), step, &
               max(abs(self%given(1)), abs(self%given(2))))
         end if
      else
         axis_value = self%given(i)
      end if
   end function axis_value

   !> v, or the decimal with at most six digits below the decade of `step` nearest to v when
   !> that lies within 4 ulps of the range's largest end `size` (the rounding of the range's
   !> arithmetic, not a value of its own; relative to the range, so that a point that should
   !> be 0 and came out as 4.4e-16 is 0): v·10ᵉ rounded to an integer and divided by 10ᵉ, both
   !> exact for e ≤ 22.
   pure real(wp) function decimal_value(v, step, size) result(x)
      real(wp), intent(in) :: v, step, size
      real(wp) :: scale
      integer :: e
      x = v
      if (.not. (abs(step) > 0.0_wp .and. abs(step) < huge(1.0_wp))) return
      e = 6 - floor(log10(abs(step)))
      if (e < 0 .or. e > 22) return
      scale = 10.0_wp**e
      if (.not. (abs(v)*scale < 2.0_wp**52)) return
      x = anint(v*scale)/scale
      if (abs(x - v) > 4.0_wp*spacing(max(abs(v), size))) x = v
   end function decimal_value

   !> Number of cases: the product of the axis sizes ('grid') or the common length ('list').
   pure integer function sweep_n_cases(self) result(n_cases)
      class(sweep_config_type), intent(in) :: self
      integer :: ia
      integer(kind=8) :: n
      n = 1
      do ia = 1, n_sweep_axes
         if (.not. self%axes(ia)%active) cycle
         if (self%mode == sweep_list) then
            n = self%axes(ia)%size()
         else
            n = min(n*self%axes(ia)%size(), int(huge(1), kind=8))
         end if
      end do
      n_cases = int(n)
   end function sweep_n_cases

   !> Value index of every axis for case `icase` (grid: the last axis varies fastest).
   pure subroutine axis_indices(self, icase, idx)
      type(sweep_config_type), intent(in) :: self
      integer, intent(in) :: icase
      integer, intent(out) :: idx(n_sweep_axes)
      integer :: ia, rest, m
      idx = 0
      rest = icase - 1
      do ia = n_sweep_axes, 1, -1
         if (.not. self%axes(ia)%active) cycle
         if (self%mode == sweep_list) then
            idx(ia) = icase
         else
            m = self%axes(ia)%size()
            idx(ia) = mod(rest, m) + 1
            rest = rest/m
         end if
      end do
   end subroutine axis_indices

   !> Replace the base values of `p` by the swept values of case `icase`.
   pure subroutine vary_point(self, icase, p)
      class(sweep_config_type), intent(in) :: self
      !> Case index, 1 ≤ icase ≤ n_cases.
      integer, intent(in) :: icase
      !> The base values on entry, the inputs of the case on return.
      type(case_point_type), intent(inout) :: p
      integer :: idx(n_sweep_axes), ia

      call axis_indices(self, icase, idx)
      do ia = 1, n_sweep_axes
         if (idx(ia) == 0) cycle
         associate (axis => self%axes(ia))
            select case (ia)
            case (ax_t_y); p%t_y = axis%value(idx(ia))
            case (ax_roll); p%roll = axis%value(idx(ia))
            case (ax_yaw); p%yaw = axis%value(idx(ia))
            case (ax_normal_force); p%normal_force = axis%value(idx(ia))
            case (ax_approach); p%approach = axis%value(idx(ia))
            case (ax_vertical_force); p%vertical_force = axis%value(idx(ia))
            case (ax_friction); p%friction = axis%value(idx(ia))
            case (ax_bound); p%bound = axis%codes(idx(ia))
            case (ax_spin_model); p%spin_model = axis%codes(idx(ia))
            case (ax_v_forward); p%v_forward = axis%value(idx(ia))
            case (ax_v_lateral); p%v_lateral = axis%value(idx(ia))
            case (ax_v_vertical); p%v_vertical = axis%value(idx(ia))
            case (ax_roll_rate); p%roll_rate = axis%value(idx(ia))
            case (ax_yaw_rate); p%yaw_rate = axis%value(idx(ia))
            case (ax_pitch_rate); p%pitch_rate = axis%value(idx(ia))
            case (ax_nu_x); p%nu_x = axis%value(idx(ia))
            case (ax_nu_y); p%nu_y = axis%value(idx(ia))
            case (ax_phi); p%phi = axis%value(idx(ia))
            end select
         end associate
      end do
   end subroutine vary_point

   pure logical function sweep_geometry_swept(self) result(geometry_swept)
      class(sweep_config_type), intent(in) :: self
      integer :: ia
      geometry_swept = .false.
      do ia = 1, n_sweep_axes
         if (axis_stage(ia) == axis_geometry) geometry_swept = geometry_swept .or. &
            self%axes(ia)%active
      end do
   end function sweep_geometry_swept

   !> The smallest case index whose inputs up to `stage` (axis_geometry: t_y and roll;
   !> axis_load: also the load) equal those of case `icase`, so that its geometry (or normal
   !> solution) can be reused.
   pure integer function sweep_shares_with(self, icase, stage) result(shares_with)
      class(sweep_config_type), intent(in) :: self
      integer, intent(in) :: icase, stage
      integer :: idx(n_sweep_axes), jdx(n_sweep_axes), ia, j, m, stride
      call axis_indices(self, icase, idx)
      if (self%mode == sweep_grid) then
         ! In a grid the outer axes change slowest: zero the inner indices.
         shares_with = 1
         stride = 1
         do ia = n_sweep_axes, 1, -1
            if (.not. self%axes(ia)%active) cycle
            m = self%axes(ia)%size()
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
            if (axis_stage(ia) > stage .or. .not. self%axes(ia)%active) cycle
            if (self%axes(ia)%value(jdx(ia)) /= self%axes(ia)%value(idx(ia))) &
               shares_with = 0
         end do
         if (shares_with > 0) return
      end do
      shares_with = icase
   end function sweep_shares_with

   !> The value of real input axis `ia` (numbering of [[sweep_axis_names]]) of a case; 0 for
   !> the choice axes (bound, spin_model).
   pure real(wp) function case_point_value(p, ia) result(x)
      !> The inputs of the case.
      type(case_point_type), intent(in) :: p
      !> Axis index.
      integer, intent(in) :: ia
      select case (ia)
      case (ax_t_y); x = p%t_y
      case (ax_roll); x = p%roll
      case (ax_yaw); x = p%yaw
      case (ax_normal_force); x = p%normal_force
      case (ax_approach); x = p%approach
      case (ax_vertical_force); x = p%vertical_force
      case (ax_friction); x = p%friction
      case (ax_v_forward); x = p%v_forward
      case (ax_v_lateral); x = p%v_lateral
      case (ax_v_vertical); x = p%v_vertical
      case (ax_roll_rate); x = p%roll_rate
      case (ax_yaw_rate); x = p%yaw_rate
      case (ax_pitch_rate); x = p%pitch_rate
      case (ax_nu_x); x = p%nu_x
      case (ax_nu_y); x = p%nu_y
      case (ax_phi); x = p%phi
      case default; x = 0.0_wp
      end select
   end function case_point_value

   !> The length of [[case_point_label]]'s text (no deferred-length result: the report lines
   !> are formatted by threads; doc/performance.md, "Threads and strings").
   pure integer function label_length(p, ia)
      type(case_point_type), intent(in) :: p
      integer, intent(in) :: ia
      select case (ia)
      case (ax_bound); label_length = choice_name_length(bound_choices, p%bound)
      case (ax_spin_model); label_length = choice_name_length(spin_model_choices, p%spin_model)
      case default; label_length = 0
      end select
   end function label_length

   !> The value of choice axis `ia` (bound or spin_model) of a case as its name; '' for the
   !> real axes.
   pure function case_point_label(p, ia) result(label)
      !> The inputs of the case.
      type(case_point_type), intent(in) :: p
      !> Axis index.
      integer, intent(in) :: ia
      character(len=label_length(p, ia)) :: label
      select case (ia)
      case (ax_bound); label = choice_name(bound_choices, p%bound)
      case (ax_spin_model); label = choice_name(spin_model_choices, p%spin_model)
      case default; label = ''
      end select
   end function case_point_label

   !> True for the wheelset inputs of a kinematic case: t_y, roll, yaw, the velocities and
   !> the rates.
   pure logical function is_kinematic_input(name)
      !> An input (sweep axis) name.
      character(len=*), intent(in) :: name
      is_kinematic_input = any(kinematic_inputs == name)
   end function is_kinematic_input

   pure integer function axis_index(name)
      character(len=*), intent(in) :: name
      integer :: i
      axis_index = 0
      do i = 1, n_sweep_axes
         if (sweep_axis_names(i) == name) axis_index = i
      end do
   end function axis_index

end module shcontact_input_config_sweep
