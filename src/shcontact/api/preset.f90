!> Named option presets of the contact solver (issue 25): one choice that sets the grid of the
!> normal and tangential problems and the spacing of the strip tables together.
!>
!> * `default`: the library's defaults, 100 strips × 50 elements, tables every 0.025 mm.
!> * `vehicle`: for the kinematic call of a vehicle code (doc/kinematics.md, "The vehicle
!>   preset"): fewer strips and elements and coarser strip tables, several times faster; its
!>   forces stay within 0.01 of the default in f = F/(μF_n) on the benchmark's trajectories
!>   (doc/performance.md) and within doc/validation.md's accuracy goals.
!>
!> Only the fields listed in [[preset_values]] change; every other option keeps its value.
module shcontact_api_preset
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_strings, only: to_lower
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_api_solver, only: contact_solver_type
   implicit none
   private

   public :: preset_names, apply_preset, set_preset

   !> The presets, in the order of [[preset_values]].
   character(len=*), parameter :: preset_names(2) = [character(len=7) :: 'default', 'vehicle']

   !> Strips n_y, elements per strip n_x and strip-table spacing (mm) of each preset.
   integer, parameter :: preset_strips(2) = [100, 60]
   integer, parameter :: preset_elements(2) = [50, 40]
   real(wp), parameter :: preset_table_step(2) = [0.025_wp, 0.05_wp]

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

      k = preset_index(name)
      if (k == 0) then
         call fatal_error(error, "preset = '"//trim(name)//"': expected 'default' or "// &
            "'vehicle'", stat_invalid_input)
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

   !> Index of a preset in [[preset_names]], 0 if unknown.
   pure integer function preset_index(name) result(k)
      character(len=*), intent(in) :: name
      do k = 1, size(preset_names)
         if (to_lower(trim(adjustl(name))) == trim(preset_names(k))) return
      end do
      k = 0
   end function preset_index

end module shcontact_api_preset
