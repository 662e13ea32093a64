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
!>
!> This module is the facade of the configuration subsystem; the work is done in
!> `input/config/`: [[shcontact_input_config_limits]] (sizes), [[shcontact_input_config_sweep]] (axes
!> and cases of a sweep), [[shcontact_input_config_types]] (the typed configuration and its
!> defaults), [[shcontact_input_config_choices]] (the registry of the case file's own choices),
!> [[shcontact_input_config_variables]] (the registry of the groups' variables),
!> [[shcontact_input_config_parser]] (namelist text into assignments), [[shcontact_input_config_assign]]
!> (one assignment into the configuration: [[read_group_variable]], the one entry point that
!> sets a variable from text), [[shcontact_input_config_validate]] (checks and derived settings),
!> [[shcontact_input_config_writer]] (the resolved namelist) and [[shcontact_input_config_load]] (the
!> entry points).
module shcontact_input_config
   use shcontact_input_config_limits, only: path_len, name_len, max_sweep_values, max_cases, &
      max_grid_cells
   use shcontact_input_config_sweep, only: sweep_axis_type, case_point_type, n_sweep_axes, &
      sweep_axis_names, axis_geometry, axis_load, axis_tangential, case_point_value, &
      case_point_label, is_kinematic_input
   use shcontact_input_config_types, only: case_config_type, normal_options_of, &
      tangential_options_of, table_step_of
   use shcontact_input_config_choices, only: load_mode_force, load_mode_approach, &
      load_mode_vertical, load_mode_shared, curvature_reference, precision_single, precision_double
   use shcontact_input_config_assign, only: read_group_variable, stat_unknown_choice
   use shcontact_input_config_validate, only: validate_config
   use shcontact_input_config_writer, only: config_namelist, with_absolute_profiles
   use shcontact_input_config_load, only: load_config, read_config_file, read_config_text, &
      apply_override
   implicit none
   private

   public :: case_config_type, sweep_axis_type, case_point_type
   public :: load_config, read_config_file, read_config_text, apply_override, validate_config
   public :: config_namelist, with_absolute_profiles
   public :: n_sweep_axes, sweep_axis_names, axis_geometry, axis_load, axis_tangential
   public :: path_len, name_len, max_sweep_values
   public :: case_point_value, case_point_label, is_kinematic_input
   public :: normal_options_of, tangential_options_of, table_step_of, read_group_variable, stat_unknown_choice
   public :: load_mode_force, load_mode_approach, load_mode_vertical, load_mode_shared, &
      curvature_reference
   public :: precision_single, precision_double
   public :: max_cases, max_grid_cells

end module shcontact_input_config
