!> shcontact: wheel–rail rolling contact with the semi-Hertzian strip method and FASTSIM_SH.
!>
!> This facade re-exports the public API; users `use shcontact` and need nothing else. The data
!> flows one way: profiles → geometry → normal → tangential. The program `shcontact` (app/)
!> reaches the library only through this module and the utilities of core/ (kinds, errors,
!> strings, files): its case files, runs, sweeps and reports are re-exported at the end
!> (scripts/check_layers checks it).
module shcontact
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, &
      stat_numerical, stat_no_contact, stat_usage
   use shcontact_version_info, only: shcontact_version
   use shcontact_core_material, only: material_type, check_material
   ! profiles
   use shcontact_profile_points, only: profile_type, profile_kind_rail, profile_kind_wheel
   use shcontact_profile_reader, only: read_profile, profile_format_names, profile_file_format
   use shcontact_profile_cleanup, only: clean_profile
   use shcontact_profile_source, only: profile_from_points, load_profile_file => load_profile
   use shcontact_profile_builtin, only: builtin_profile, builtin_profile_names
   use shcontact_profile_writer, only: write_profile_plain, write_builtin_profiles, &
      written_builtins
   use shcontact_profile_diagnostics, only: noise_estimate_type, estimate_noise, &
      point_anomaly_type, find_point_anomalies, &
      suggested_smoothing, curvature_noise, rail_cant_type, estimate_rail_cant, &
      default_curvature_tolerance
   use shcontact_profile_spline, only: profile_spline_type
   ! geometry
   use shcontact_geometry_track, only: track_type, wheelset_position_type, side_right, side_left, &
      check_track, check_position
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      check_contact_options, prepare_profiles, find_contact_patches, positioned_profiles, &
      write_geometry_table
   use shcontact_geometry_patch, only: patch_geometry_type, geometry_sample_type
   use shcontact_geometry_wheelset_table, only: wheelset_contact_type, wheelset_geometry_table, &
      wheelset_contact, roll_angle_parameter, contact_distance, centre_radius
   use shcontact_geometry_conicity, only: equivalent_conicity, conicity_en15302, &
      conicity_harmonic, first_harmonic_slope, klingel_wavelength
   use shcontact_geometry_kinematics, only: wheelset_state_type, check_wheelset_state, &
      pure_rolling_pitch_rate, yawed_wheel_profile, contact_lead
   use shcontact_geometry_flange, only: flange_steepest, steep_end_radius, climbing_margin
   ! normal
   use shcontact_normal_hertz, only: hertz_shape_type, hertz_type, hertz_shape, hertz_from_load, &
      hertz_from_approach, hertz_from_semiaxes
   use shcontact_normal_options, only: normal_options_type, new_normal_options, &
      check_normal_options, normal_method_name => method_name, reduction_name
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, &
      solve_approach, solve_load, solve_vertical_load
   use shcontact_normal_pressure, only: element_pressure
   use shcontact_normal_patch, only: normal_patch_type
   ! tangential
   use shcontact_tangential_creepage, only: creepage_type, check_creepage
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options, &
      parse_method, parse_bound, parse_spin_model, tangential_method_name => method_name, &
      bound_name, spin_model_name
   use shcontact_tangential_kalker, only: kalker_coefficients
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_fastsim, only: prepare_fastsim, solve_fastsim
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh, solve_fastsim_sh
   use shcontact_tangential_solver, only: track_forces_type, solve_tangential, &
      solve_tangential_patches
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior, state_adhesion, &
      state_slip
   use shcontact_tangential_rigid_slip, only: contact_point_type, rigid_creepages
   ! api
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      patch_result_type, contact_fields_type, load_profile, load_normal_force, &
      load_vertical_position, load_shared_force, &
      load_vertical_force, load_approach, load_mode_name, max_patches
   use shcontact_api_values, only: patch_value_count, result_value_count, kinematic_value_count, &
      patch_values, result_values, kinematic_values
   use shcontact_api_wheelset, only: wheelset_solver_type, wheelset_result_type, wheel_right, &
      wheel_left
   use shcontact_api_preset, only: preset_names, apply_preset, set_preset
   ! case files, runs and output (the program's layers)
   use shcontact_input_config, only: case_config_type, load_config, config_namelist, &
      with_absolute_profiles, case_point_type
   use shcontact_case_result, only: case_summary_type
   use shcontact_case_runner, only: run_setup_type, prepare_run, solve_geometry, &
      read_case_profiles
   use shcontact_output_merge, only: merge_result_files
   use shcontact_output_hdf5, only: h5_skip_exit_cleanup
   use shcontact_output_report, only: report_header, report_line, report_lines, &
      report_case_text, report_units
   use shcontact_output_clock, only: iso_timestamp, wall_seconds
   use shcontact_batch_sweep, only: sweep_options_type, sweep_outcome_type, run_sweep, &
      max_threads
   implicit none
   private

   public :: wheelset_solver_type, wheelset_result_type, wheel_right, wheel_left
   public :: flange_steepest, steep_end_radius, climbing_margin
   public :: preset_names, apply_preset, set_preset
   public :: wp, error_type, fatal_error
   public :: stat_invalid_input, stat_io, stat_numerical, stat_no_contact, stat_usage
   public :: shcontact_version
   public :: h5_skip_exit_cleanup
   public :: material_type, check_material
   public :: profile_type, profile_kind_rail, profile_kind_wheel, read_profile, &
      profile_format_names, clean_profile, builtin_profile, builtin_profile_names, &
      write_profile_plain, write_builtin_profiles, profile_spline_type, profile_from_points
   public :: track_type, wheelset_position_type, side_right, side_left, check_track, &
      check_position, contact_options_type, prepared_profiles_type, check_contact_options, &
      prepare_profiles, find_contact_patches, positioned_profiles, write_geometry_table, &
      patch_geometry_type, geometry_sample_type
   public :: wheelset_contact_type, wheelset_geometry_table, wheelset_contact, &
      equivalent_conicity, conicity_en15302, conicity_harmonic, first_harmonic_slope, &
      klingel_wavelength
   public :: wheelset_state_type, check_wheelset_state, pure_rolling_pitch_rate, &
      yawed_wheel_profile, contact_lead, contact_point_type, rigid_creepages
   public :: hertz_shape_type, hertz_type, hertz_shape, hertz_from_load, hertz_from_approach, &
      hertz_from_semiaxes, normal_options_type, new_normal_options, check_normal_options, &
      normal_method_name, reduction_name, normal_contact_type, prepare_normal_contact, &
      solve_approach, solve_load, solve_vertical_load, element_pressure, normal_patch_type
   public :: creepage_type, check_creepage, tangential_options_type, check_tangential_options, &
      parse_method, parse_bound, parse_spin_model, tangential_method_name, bound_name, &
      spin_model_name, kalker_coefficients, march_workspace_type, prepare_fastsim, &
      solve_fastsim, prepare_fastsim_sh, solve_fastsim_sh, track_forces_type, &
      solve_tangential, solve_tangential_patches, tangential_patch_type, state_exterior, &
      state_adhesion, state_slip
   public :: contact_solver_type, contact_load_type, contact_result_type, patch_result_type, &
      contact_fields_type, load_profile, load_normal_force, load_vertical_force, load_approach, &
      load_vertical_position, load_shared_force, load_mode_name, max_patches, &
      patch_value_count, result_value_count, kinematic_value_count, &
      patch_values, result_values, kinematic_values
   public :: point_anomaly_type, find_point_anomalies
   public :: written_builtins, noise_estimate_type, estimate_noise, suggested_smoothing, &
      curvature_noise, rail_cant_type, estimate_rail_cant, default_curvature_tolerance, &
      profile_file_format, load_profile_file, roll_angle_parameter, contact_distance, &
      centre_radius
   public :: case_config_type, load_config, config_namelist, with_absolute_profiles, &
      case_point_type, case_summary_type, run_setup_type, prepare_run, &
      read_case_profiles, solve_geometry, merge_result_files, report_header, report_line, report_lines, &
      report_case_text, &
      report_units, iso_timestamp, wall_seconds, sweep_options_type, sweep_outcome_type, &
      run_sweep, max_threads

end module shcontact
