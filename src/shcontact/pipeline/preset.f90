!> The registry of the option presets (issue 25 item 4): one choice that sets the grid of the
!> normal and tangential problems and the spacing of the strip tables together. Written once
!> here, below the library's solver (shcontact_api_preset, `set_preset`) and the case file's
!> `&normal preset` (shcontact_input_config_types, `normal_options_of`, `tangential_options_of`,
!> `table_step_of`), so that both apply the same values.
!>
!> * `default`: the library's defaults, 100 strips × 50 elements, tables every 0.025 mm.
!> * `vehicle`: for the kinematic call of a vehicle code (doc/kinematics.md, "The vehicle
!>   preset"): 60 strips × 40 elements, tables every 0.05 mm.
module shcontact_pipeline_preset
   use shcontact_core_kinds, only: wp
   use shcontact_core_choices, only: choice_type
   use shcontact_normal_option_registry, only: default_n_strips
   use shcontact_tangential_option_registry, only: default_n_elements
   implicit none
   private

   public :: preset_choices, preset_default, preset_vehicle, default_preset
   public :: preset_strips, preset_elements, preset_table_step

   !> The codes of the presets (indices of the tables below).
   integer, parameter :: preset_default = 1, preset_vehicle = 2
   !> The preset of a configuration that names none.
   integer, parameter :: default_preset = preset_default

   !> `&normal preset` and `set_preset`'s names.
   type(choice_type), parameter :: preset_choices(*) = [ &
      choice_type('default', preset_default, '100 strips x 50 elements, strip tables every '// &
      '0.025 mm (the defaults)'), &
      choice_type('vehicle', preset_vehicle, '60 strips x 40 elements, strip tables every '// &
      '0.05 mm (doc/kinematics.md, "The vehicle preset")')]

   !> Strips n_y, elements per strip n_x and strip-table spacing (mm) of each preset, by code.
   integer, parameter :: preset_strips(2) = [default_n_strips, 60]
   integer, parameter :: preset_elements(2) = [default_n_elements, 40]
   real(wp), parameter :: preset_table_step(2) = [0.025_wp, 0.05_wp]

end module shcontact_pipeline_preset
