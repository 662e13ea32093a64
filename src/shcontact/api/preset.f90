!> Named option presets of the contact solver (issue 25): one choice that sets the grid of the
!> normal and tangential problems and the spacing of the strip tables together. The presets
!> and their values are those of the registry shcontact_pipeline_preset, which the case file's
!> `&normal preset` (and so the C and Fortran 77 key `normal%preset`) applies too.
!>
!> * `default`: the library's defaults, 100 strips × 50 elements, tables every 0.025 mm.
!> * `vehicle`: for the kinematic call of a vehicle code (doc/kinematics.md, "The vehicle
!>   preset"): fewer strips and elements and coarser strip tables, several times faster; its
!>   forces stay within 0.01 of the default in f = F/(μF_n) on the benchmark's trajectories
!>   (doc/performance.md) and within doc/validation.md's accuracy goals.
!>
!> Only n_strips, n_elements and table_step change; every other option keeps its value. A
!> call sets them whatever they were: options set after it (`set_options`) win.
module shcontact_api_preset
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_choices, only: choice_code, choice_list
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_pipeline_preset, only: preset_choices, preset_strips, preset_elements, &
      preset_table_step
   use shcontact_api_solver, only: contact_solver_type
   implicit none
   private

   public :: preset_names, apply_preset, set_preset

   !> The presets' names ('default', 'vehicle').
   character(len=*), parameter :: preset_names(*) = preset_choices%name

contains

   !> Set the fields of a preset in option values (the other fields are kept).
   pure subroutine apply_preset(name, normal, tangential, contact, error)
      !> The preset's name, one of [[preset_names]] (case is ignored).
      character(len=*), intent(in) :: name
      !> The options, changed in place.
      type(normal_options_type), intent(inout) :: normal
      type(tangential_options_type), intent(inout) :: tangential
      type(contact_options_type), intent(inout) :: contact
      !> Set for an unknown name; nothing changes then.
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      k = choice_code(preset_choices, name)
      if (k == 0) then
         call fatal_error(error, "preset = '"//trim(name)//"': unknown; expected one of "// &
            choice_list(preset_choices), stat_invalid_input)
         return
      end if
      normal%n_strips = preset_strips(k)
      tangential%n_elements = preset_elements(k)
      contact%table_step = preset_table_step(k)
   end subroutine apply_preset

   !> Give an initialised solver the options of a preset (its other options are kept): the
   !> one call a vehicle code needs, e.g. `call set_preset(solver, 'vehicle', error)`.
   subroutine set_preset(solver, name, error)
      !> The solver, from its init.
      type(contact_solver_type), intent(inout) :: solver
      !> The preset's name, one of [[preset_names]].
      character(len=*), intent(in) :: name
      !> Set for an unknown name or an uninitialised solver; the solver is then unchanged.
      type(error_type), allocatable, intent(out) :: error
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      type(contact_options_type) :: contact

      call solver%get_options(normal, tangential)
      contact = solver%get_contact_options()
      call apply_preset(name, normal, tangential, contact, error)
      if (allocated(error)) return
      call solver%set_track(error, contact_options=contact)
      if (allocated(error)) return
      call solver%set_options(error, normal=normal, tangential=tangential)
   end subroutine set_preset

end module shcontact_api_preset
