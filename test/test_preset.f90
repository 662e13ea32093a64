!> Tests of the named option presets (issue 25 item 4, shcontact_api_preset): what the vehicle
!> preset sets, that the default preset restores the library's defaults, that a bad name is
!> rejected without changing anything, and that the vehicle preset's kinematic forces stay
!> within 0.01 in f = F/(μF_n) of the default's on states of the hunting trajectory (tread and
!> flange, yaw up to 10 mrad) with the vertical load balanced as tightly.
module test_preset
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_geometry_kinematics, only: wheelset_state_type, pure_rolling_pitch_rate
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      load_vertical_force
   use shcontact_api_preset, only: set_preset, apply_preset, preset_names
   implicit none
   private

   public :: collect_preset

   !> Vertical wheel load (N), speed (mm/s) and friction coefficient of the default material.
   real(wp), parameter :: wheel_load = 64.7e3_wp, speed = 30.0e3_wp, mu = 0.3_wp

contains

   !> Collect all exported unit tests.
   subroutine collect_preset(testsuite)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('vehicle_preset_options', test_options), &
         new_unittest('unknown_preset_rejected', test_unknown), &
         new_unittest('vehicle_forces_near_default', test_forces) &
         ]
   end subroutine collect_preset

   !> The vehicle preset sets fewer strips and elements and coarser tables, keeps the other
   !> options, and the default preset gives back the library's defaults.
   subroutine test_options(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_options_type) :: normal, normal0
      type(tangential_options_type) :: tangential, tangential0
      type(contact_options_type) :: contact, contact0
      type(lib_error), allocatable :: lib

      call check(error, size(preset_names) == 2 .and. preset_names(2) == 'vehicle')
      if (allocated(error)) return
      tangential%bound = 1
      call apply_preset('Vehicle', normal, tangential, contact, lib)
      call check(error, .not. allocated(lib), 'the name is not case-sensitive')
      if (allocated(error)) return
      call check(error, normal%n_strips < normal0%n_strips .and. &
         tangential%n_elements < tangential0%n_elements .and. &
         contact%table_step > contact0%table_step, 'fewer strips, elements, table points')
      if (allocated(error)) return
      call check(error, tangential%bound == 1 .and. normal%reduction == normal0%reduction .and. &
         contact%kinematic_table_gap == contact0%kinematic_table_gap, 'other options kept')
      if (allocated(error)) return
      call apply_preset('default', normal, tangential, contact, lib)
      call check(error, .not. allocated(lib) .and. normal%n_strips == normal0%n_strips .and. &
         tangential%n_elements == tangential0%n_elements .and. &
         contact%table_step == contact0%table_step, 'the default preset restores the defaults')
   end subroutine test_options

   !> An unknown name: stat_invalid_input naming the presets, the solver unchanged.
   subroutine test_unknown(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      type(contact_options_type) :: contact
      type(lib_error), allocatable :: lib

      call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      call check(error, .not. allocated(lib), 'init')
      if (allocated(error)) return
      call set_preset(solver, 'fast', lib)
      call check(error, allocated(lib), 'an unknown preset is an error')
      if (allocated(error)) return
      call check(error, lib%stat == stat_invalid_input .and. index(lib%message, 'vehicle') > 0, &
         lib%message)
      if (allocated(error)) return
      call solver%get_options(normal, tangential)
      contact = solver%get_contact_options()
      call check(error, normal%n_strips == 100 .and. tangential%n_elements == 50 .and. &
         contact%table_step == 0.025_wp, 'solver unchanged')
   end subroutine test_unknown

   !> States of the benchmark's hunting trajectory, tread to flange (t_y = 0.5 … 8 mm, yaw up to
   !> 10 mrad, with lateral velocity and yaw rate): the vehicle preset's tangential forces (sum
   !> over the loaded patches in their contact planes, over μΣF_n) within 0.01 of the default's,
   !> both balancing the vertical load to 1e-5.
   subroutine test_forces(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: default, vehicle
      type(contact_result_type) :: a, b
      type(wheelset_state_type) :: state
      type(lib_error), allocatable :: lib
      real(wp), parameter :: amplitudes(4) = [0.5_wp, 2.0_wp, 4.0_wp, 8.0_wp], &
         phases(3) = [0.3_wp, 1.2_wp, 2.5_wp], w = 15.707963267948966_wp
      real(wp) :: psi, df
      integer :: i, j

      call default%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) call vehicle%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) call set_preset(vehicle, 'vehicle', lib)
      call check(error, .not. allocated(lib), 'init and preset')
      if (allocated(error)) return
      do i = 1, size(amplitudes)
         do j = 1, size(phases)
            psi = min(0.01_wp, 1.25e-3_wp*amplitudes(i))
            state = wheelset_state_type(y_ws=amplitudes(i)*sin(phases(j)), &
               yaw=-psi*cos(phases(j)), v_forward=speed, &
               v_lateral=amplitudes(i)*w*cos(phases(j)), yaw_rate=psi*w*sin(phases(j)), &
               pitch_rate=pure_rolling_pitch_rate(speed, 460.0_wp)*(1.0_wp + 2.0e-4_wp))
            call default%solve_kinematic(state, contact_load_type(load_vertical_force, &
               wheel_load), a, lib)
            if (.not. allocated(lib)) call vehicle%solve_kinematic(state, &
               contact_load_type(load_vertical_force, wheel_load), b, lib)
            call check(error, .not. allocated(lib), 'kinematic call')
            if (allocated(error)) return
            df = max(abs(f_of(b, 1) - f_of(a, 1)), abs(f_of(b, 2) - f_of(a, 2)))
            call check(error, df <= 0.01_wp, 'vehicle preset: |df| > 0.01 at state', &
               more=state_text(state, df))
            if (allocated(error)) return
            call check(error, abs(b%track%fz + wheel_load) <= 1.0e-5_wp*wheel_load .and. &
               abs(a%track%fz + wheel_load) <= 1.0e-5_wp*wheel_load, 'vertical balance')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_forces

   !> f_x (c = 1) or f_y (c = 2): the loaded patches' tangential forces over μΣF_n.
   pure real(wp) function f_of(r, c) result(f)
      type(contact_result_type), intent(in) :: r
      integer, intent(in) :: c
      associate (p => r%patch(1:r%n_loaded))
         if (c == 1) then
            f = sum(p%fx)/(mu*sum(p%fn))
         else
            f = sum(p%fy)/(mu*sum(p%fn))
         end if
      end associate
   end function f_of

   !> The state and the difference, for a failure message.
   pure function state_text(state, df) result(text)
      type(wheelset_state_type), intent(in) :: state
      real(wp), intent(in) :: df
      character(len=96) :: text
      write (text, '(a,f8.4,a,f8.5,a,f8.5)') 't_y = ', state%y_ws, ' mm, yaw = ', state%yaw, &
         ' rad, |df| = ', df
   end function state_text

end module test_preset
