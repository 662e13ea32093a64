!> Benchmark items of a wheel in motion (issue 12): the kinematic call of the solver object at a
!> fixed wheelset position and along a hunting trajectory whose lateral shift and yaw change at
!> every call, and the scan of every 0.01 mm position that counts failed calls.
module bench_moving
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: wp, error_type, contact_solver_type, contact_load_type, &
      contact_result_type, wheelset_state_type, load_vertical_force, pure_rolling_pitch_rate, &
      normal_options_type, tangential_options_type
   use bench_timing, only: kernel_type
   implicit none
   private

   public :: kinematic_kernel, hunting_states, flange_states, scan_positions, trajectory_forces

   !> Vehicle speed (mm/s), nominal radius (mm) and vertical wheel load (N) of the items.
   real(wp), parameter :: speed = 30000.0_wp, r_nom = 460.0_wp, wheel_load = 64700.0_wp
   !> Friction coefficient of the solver's default material (f = F/(μF_n)).
   real(wp), parameter :: friction = 0.3_wp

   !> Step through a 1000-state trajectory: coprime with 1000, and 201 = 1000/5 + 1, so that
   !> five consecutive calls visit the five amplitude blocks of [[hunting_states]] and 1000
   !> calls visit every state once.
   integer, parameter :: trajectory_stride = 201

   !> Values per state of [[trajectory_forces]].
   integer, parameter, public :: values_per_state = 6

   !> One kinematic call per run(k): the next state of the list, taken with the stride
   !> trajectory_stride and continued from batch to batch (so every batch covers every part of
   !> the trajectory, and the batches together the whole of it), or always state 1.
   type, extends(kernel_type) :: kinematic_kernel
      type(contact_solver_type) :: solver
      type(wheelset_state_type), allocatable :: states(:)
      logical :: moving = .true.
      integer :: failures = 0
      !> Calls made, calls with two or more loaded patches, calls whose main patch has
      !> |γ₀| > 0.9 rad (flange contact).
      integer :: calls = 0, two_patches = 0, flange = 0
      real(wp) :: checksum = 0.0_wp
   contains
      procedure :: run => run_kinematic
   end type kinematic_kernel

contains

   !> Call k: the next state of the trajectory (or the fixed one).
   subroutine run_kinematic(self, k)
      class(kinematic_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(contact_result_type) :: result
      type(error_type), allocatable :: error
      integer :: i

      i = 1
      if (self%moving) i = modulo(self%calls*trajectory_stride, size(self%states)) + 1
      self%calls = self%calls + 1
      call self%solver%solve_kinematic(self%states(i), &
         contact_load_type(load_vertical_force, wheel_load), result, error)
      if (allocated(error)) then
         self%failures = self%failures + 1
         self%failed = .true.
         self%message = error%message
         return
      end if
      if (count(result%patch(1:result%n_loaded)%fn > 0.0_wp) >= 2) &
         self%two_patches = self%two_patches + 1
      if (abs(result%main%gamma0) > 0.9_wp) self%flange = self%flange + 1
      self%checksum = self%checksum + result%track%fy
   end subroutine run_kinematic

   !> A hunting trajectory sampled at time step dt: t_y = A sin(ωt), yaw = −Ψ cos(ωt) with the
   !> kinematic wavelength's phase lag, for a set of amplitudes A from 0.01 to 8 mm (Ψ up to
   !> 10 mrad), the velocities consistent with the motion (v_y = dt_y/dt, yaw rate) and a
   !> small longitudinal creep. Consecutive calls never repeat a position.
   pure function hunting_states(n) result(states)
      integer, intent(in) :: n
      type(wheelset_state_type) :: states(n)
      real(wp), parameter :: amplitudes(5) = [0.01_wp, 0.1_wp, 1.0_wp, 4.0_wp, 8.0_wp]
      real(wp), parameter :: two_pi = 6.283185307179586_wp, dt = 1.0e-3_wp, freq = 2.5_wp
      real(wp) :: t, a, psi, w
      integer :: i, j

      w = two_pi*freq
      do i = 1, n
         j = modulo((i - 1)*size(amplitudes)/n, size(amplitudes)) + 1
         a = amplitudes(j)
         psi = min(0.01_wp, 1.25e-3_wp*a)
         t = (i - 1)*dt
         states(i) = wheelset_state_type(y_ws=a*sin(w*t), yaw=-psi*cos(w*t), &
            v_forward=speed, v_lateral=a*w*cos(w*t), yaw_rate=psi*w*sin(w*t), &
            pitch_rate=pure_rolling_pitch_rate(speed, r_nom)*(1.0_wp + 2.0e-4_wp))
      end do
   end function hunting_states

   !> A wheelset approaching the flange: t_y = 7 + 2 sin(ω₁t) mm (5–9 mm) and yaw =
   !> 10 sin(ω₂t) mrad with two incommensurate frequencies, so that the states cover the
   !> rectangle of t_y and yaw, with the velocities of the motion and a small longitudinal creep.
   !> Tread and flange patches are loaded together on part of it, the flange alone on the rest.
   pure function flange_states(n) result(states)
      integer, intent(in) :: n
      type(wheelset_state_type) :: states(n)
      real(wp), parameter :: two_pi = 6.283185307179586_wp, dt = 1.0e-3_wp, f1 = 2.5_wp, &
         f2 = 1.6180339887_wp, centre = 7.0_wp, a = 2.0_wp, psi = 0.01_wp
      real(wp) :: t, w1, w2
      integer :: i

      w1 = two_pi*f1
      w2 = two_pi*f2
      do i = 1, n
         t = (i - 1)*dt
         states(i) = wheelset_state_type(y_ws=centre + a*sin(w1*t), yaw=psi*sin(w2*t), &
            v_forward=speed, v_lateral=a*w1*cos(w1*t), yaw_rate=psi*w2*cos(w2*t), &
            pitch_rate=pure_rolling_pitch_rate(speed, r_nom)*(1.0_wp + 2.0e-4_wp))
      end do
   end function flange_states

   !> Solve every position t_y = −10 … 10 mm in steps of 0.01 mm at the given yaw angles
   !> (pure rolling, vertical load) and report the failed calls with their messages.
   subroutine scan_positions(solver, yaws, failures)
      type(contact_solver_type), intent(inout) :: solver
      real(wp), intent(in) :: yaws(:)
      integer, intent(out) :: failures
      type(contact_result_type) :: result
      type(error_type), allocatable :: error
      integer :: i, j

      failures = 0
      do j = 1, size(yaws)
         do i = -1000, 1000
            call solver%solve_kinematic(wheelset_state_type(y_ws=0.01_wp*i, yaw=yaws(j), &
               v_forward=speed, pitch_rate=pure_rolling_pitch_rate(speed, r_nom)), &
               contact_load_type(load_vertical_force, wheel_load), result, error)
            if (allocated(error)) then
               failures = failures + 1
               write (output_unit, '(2x,a,f7.2,a,f7.4,a,a)') 'FAILED t_y = ', 0.01_wp*i, &
                  ' mm, yaw = ', yaws(j), ' rad: ', error%message
            end if
         end do
         write (output_unit, '(2x,a,f7.4,a,i0)') 'scan t_y = -10 ... 10 mm step 0.01 mm, '// &
            'yaw = ', yaws(j), ' rad: failed calls so far ', failures
      end do
   end subroutine scan_positions

   !> Per state: the track-frame totals F_x, F_y, F_z and ΣF_n (N), and the tangential forces
   !> of the patches in their contact planes, f_x = ΣF_x/(μΣF_n) and f_y = ΣF_y/(μΣF_n)
   !> ([[values_per_state]] values per state; a failed call gives huge values).
   function trajectory_forces(solver, states) result(values)
      !> The solver (its options are those compared).
      type(contact_solver_type), intent(inout) :: solver
      !> The states.
      type(wheelset_state_type), intent(in) :: states(:)
      real(wp) :: values(values_per_state*size(states))
      type(contact_result_type) :: result
      type(error_type), allocatable :: error
      real(wp) :: mu_fn
      integer :: i, n

            do i = 1, size(states)
         call solver%solve_kinematic(states(i), contact_load_type(load_vertical_force, &
            wheel_load), result, error)
         associate (v => values(values_per_state*(i - 1) + 1:values_per_state*i))
            if (allocated(error)) then
               v = huge(1.0_wp)
            else
               n = result%n_loaded
               mu_fn = friction*sum(result%patch(1:n)%fn)
               v = [result%track%fx, result%track%fy, result%track%fz, result%track%fn, &
                  sum(result%patch(1:n)%fx)/mu_fn, sum(result%patch(1:n)%fy)/mu_fn]
            end if
         end associate
      end do
   end function trajectory_forces

end module bench_moving
