!> The benchmark's sections on the wheel in motion (issues 12 and 13): the kinematic call at a
!> fixed position and along a hunting trajectory, the new defaults against the old ones, and the
!> scan of every 0.01 mm position (kernels in [[bench_moving]]).
module bench_moving_items
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: wp, error_type, normal_options_type, contact_solver_type, set_preset, &
      wheelset_state_type
   use shcontact_normal_options, only: reduction_local_hertz
   use shcontact_tangential_options, only: tangential_options_type, correction_none
   use bench_timing, only: timing_type, time_kernel, time_side_by_side, wall_time
   use bench_kernels, only: full_case_kernel
   use bench_moving, only: kinematic_kernel, hunting_states, flange_states, scan_positions, &
      trajectory_forces, values_per_state
   use bench_config, only: bench_config_type, sizes
   use bench_case, only: bench_case_type
   use bench_results, only: summary_type, force_record_type
   use bench_report, only: section, report, stop_on
   implicit none
   private

   public :: moving_section, defaults_section, scan_section

contains

   !> The kinematic call (issue 12), 100 strips x 50 elements, vertical load 64.7 kN, 30 m/s:
   !> at one fixed wheelset position with the trajectory's velocities (new creepages at every
   !> call; the geometry and the prepared normal problem are reused), along the whole hunting
   !> trajectory (t_y and yaw new every call, amplitudes 0.01-8 mm, up to 10 mrad, taken with a
   !> stride so that every batch covers every amplitude, issue 25), and along a wheelset
   !> approaching the flange (t_y 5-9 mm, yaw +-10 mrad: two patches and flange contact),
   !> measured in the same run, with the ratios to the fixed call. The forces of all 2000
   !> states of both trajectories go to the record (--save-results, --compare-results).
   subroutine moving_section(config, summary, record)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The figures of the targets.
      type(summary_type), intent(inout) :: summary
      !> The forces of the checked cases.
      type(force_record_type), intent(inout) :: record
      type(kinematic_kernel) :: fixed, moving, flange, vehicle(2, 2)
      type(timing_type) :: t_fixed, t_moving, t_flange, t_vehicle(2, 2)
      real(wp) :: r_vehicle(3, 2, 2)
      type(error_type), allocatable :: error
      real(wp), allocatable :: forces(:), preset_forces(:)
      real(wp) :: t_init
      integer :: k

      call section('wheel in motion: kinematic call (solve_kinematic), 100 strips x 50 '// &
         'elements, vertical load 64.7 kN, 30 m/s')
      t_init = wall_time()
      call moving%solver%init('builtin:S1002', 'builtin:UIC60', error)
      t_init = wall_time() - t_init
      call stop_on(error, 'solver init')
      call fixed%solver%init('builtin:S1002', 'builtin:UIC60', error)
      call stop_on(error, 'solver init')
      call flange%solver%init('builtin:S1002', 'builtin:UIC60', error)
      call stop_on(error, 'solver init')
      moving%states = hunting_states(1000)
      flange%states = flange_states(1000)
      ! At least 50 calls per batch: with the stride every 9 consecutive calls cover all five
      ! amplitudes, and the 15 batches together 750 states spread over the whole trajectory.
      moving%min_calls = 50
      flange%min_calls = 50
      ! Same position (that of state 200), the velocities of the trajectory: new creepages at
      ! every call, as a vehicle code's call when the wheelset has not moved.
      fixed%states = moving%states
      fixed%states%y_ws = moving%states(200)%y_ws
      fixed%states%yaw = moving%states(200)%yaw
      write (output_unit, '(2x,a,f8.1,a)') 'set-up (init: profiles smoothed and sampled): ', &
         1.0e6_wp*t_init, ' us, once per wheel'
      t_init = wall_time()
      call moving%run(1)
      t_init = wall_time() - t_init
      write (output_unit, '(2x,a,f8.1,a)') 'first yawed call (also prepares the yaw table): ', &
         1.0e6_wp*t_init, ' us, once per wheel'
      call flange%run(1)
      t_fixed = time_kernel(fixed, config%runs, config%batch_time)
      call report(fixed, t_fixed, 'same position, new velocities (creepages) every call')
      t_moving = time_kernel(moving, config%runs, config%batch_time)
      call report(moving, t_moving, 'whole hunting trajectory, t_y and yaw new every call')
      t_flange = time_kernel(flange, config%runs, config%batch_time)
      call report(flange, t_flange, 'approaching the flange, t_y 5-9 mm, yaw +-10 mrad')
      write (output_unit, '(2x,a,i0,a,i0,a)') 'hunting: ', moving%calls, ' calls (', &
         min(moving%calls, size(moving%states)), ' distinct states)'
      write (output_unit, '(2x,a,i0,a,f5.1,a,f5.1,a)') 'flange: ', flange%calls, &
         ' calls, two or more loaded patches in ', 100.0_wp*flange%two_patches/flange%calls, &
         ' %, main patch on the flange (|gamma0| > 0.9 rad) in ', &
         100.0_wp*flange%flange/flange%calls, ' %'
      write (output_unit, '(2x,a,f7.2,a,f7.2,a,i0)') 'ratio moving/fixed: hunting ', &
         t_moving%median/t_fixed%median, ', flange ', t_flange%median/t_fixed%median, &
         '; failed calls: ', moving%failures + fixed%failures + flange%failures
      summary%moving = t_moving%median
      summary%moving_ratio = t_moving%median/t_fixed%median
      forces = [trajectory_forces(moving%solver, moving%states), &
         trajectory_forces(flange%solver, flange%states)]
      call record%keep_array(forces)
      call check_history(forces, [moving%states, flange%states])
      ! The vehicle preset (set_preset) against the default, side by side (batch after batch in
      ! turn, so that a change of the shared machine's speed reaches both), on both
      ! trajectories; then its forces against the default's on every state.
      do k = 1, 2
         call vehicle(1, k)%solver%init('builtin:S1002', 'builtin:UIC60', error)
         call stop_on(error, 'solver init')
         call set_preset(vehicle(1, k)%solver, 'vehicle', error)
         call stop_on(error, 'set_preset')
         call vehicle(2, k)%solver%init('builtin:S1002', 'builtin:UIC60', error)
         call stop_on(error, 'solver init')
         vehicle(:, k)%min_calls = 50
      end do
      vehicle(1, 1)%states = moving%states
      vehicle(2, 1)%states = moving%states
      vehicle(1, 2)%states = flange%states
      vehicle(2, 2)%states = flange%states
      do k = 1, 2
         call vehicle(1, k)%run(1)
         call vehicle(2, k)%run(1)
         call time_side_by_side(vehicle(:, k), config%runs, config%batch_time, t_vehicle(:, k), &
            r_vehicle(:, :, k))
      end do
      call report(vehicle(1, 1), t_vehicle(1, 1), 'vehicle preset (60 x 40, tables 0.05 mm): '// &
         'hunting')
      call report(vehicle(2, 1), t_vehicle(2, 1), '  default, side by side with it: hunting')
      call report(vehicle(1, 2), t_vehicle(1, 2), 'vehicle preset (60 x 40, tables 0.05 mm): '// &
         'flange')
      call report(vehicle(2, 2), t_vehicle(2, 2), '  default, side by side with it: flange')
      write (output_unit, '(2x,a,3(f5.2,a),a,3(f5.2,a),a,i0)') 'ratio preset/default, median '// &
         '[min, max] of the rounds: hunting ', r_vehicle(1, 1, 1), ' [', r_vehicle(2, 1, 1), &
         ',', r_vehicle(3, 1, 1), ']', ', flange ', r_vehicle(1, 1, 2), ' [', &
         r_vehicle(2, 1, 2), ',', r_vehicle(3, 1, 2), ']', '; failed calls: ', &
         sum(vehicle%failures)
      preset_forces = [trajectory_forces(vehicle(1, 1)%solver, moving%states), &
         trajectory_forces(vehicle(1, 2)%solver, flange%states)]
      k = values_per_state*size(moving%states)
      call compare_forces('hunting', moving%states, forces(:k), preset_forces(:k))
      call compare_forces('flange', flange%states, forces(k + 1:), preset_forces(k + 1:))
   end subroutine moving_section

   !> The same forces from a fresh solver that takes the states in reverse order (each call then
   !> follows another state than before): the results must not depend on the call history.
   subroutine check_history(forces, states)
      !> [[trajectory_forces]] of the states in their order.
      real(wp), intent(in) :: forces(:)
      type(wheelset_state_type), intent(in) :: states(:)
      type(contact_solver_type) :: solver
      type(error_type), allocatable :: error
      real(wp) :: again(size(forces))
      integer :: i, j, n

      call solver%init('builtin:S1002', 'builtin:UIC60', error)
      call stop_on(error, 'solver init')
      n = values_per_state
      again = trajectory_forces(solver, states(size(states):1:-1))
      j = 0
      do i = 1, size(states)
         associate (a => forces(n*(i - 1) + 1:n*i), &
                    b => again(n*(size(states) - i) + 1:n*(size(states) - i + 1)))
            j = j + count(a == b)
         end associate
      end do
      write (output_unit, '(2x,a,i0,a,i0,a)') 'history: a fresh solver, the states in reverse '// &
         'order: ', j, ' of ', size(forces), ' values bitwise equal'
   end subroutine check_history

   !> Largest difference of the preset's tangential forces f_x, f_y (patches, contact planes,
   !> f = F/(μF_n)) from the default's over the states of a trajectory, their 99th
   !> percentile, the states beyond 0.01, and the largest difference of F_z in F_z.
   subroutine compare_forces(label, states, default, preset)
      !> The trajectory and its states.
      character(len=*), intent(in) :: label
      type(wheelset_state_type), intent(in) :: states(:)
      !> [[trajectory_forces]] of the default and of the preset.
      real(wp), intent(in) :: default(:), preset(:)
      real(wp) :: df(size(default)/values_per_state), dz
      integer :: i, worst

      dz = 0.0_wp
      do i = 1, size(df)
         associate (a => default(values_per_state*(i - 1) + 1:values_per_state*i), &
                    b => preset(values_per_state*(i - 1) + 1:values_per_state*i))
            df(i) = max(abs(b(5) - a(5)), abs(b(6) - a(6)))
            dz = max(dz, abs(b(3) - a(3))/abs(a(3)))
         end associate
      end do
      worst = maxloc(df, 1)
      write (output_unit, '(2x,a,a,a,f7.4,a,i0,a,f6.3,a,f7.3,a)') 'vehicle preset vs '// &
         'default, ', label, ': max |df| ', df(worst), ' (state ', worst, ', t_y ', &
         states(worst)%y_ws, ' mm, yaw ', 1.0e3_wp*states(worst)%yaw, ' mrad)'
      write (output_unit, '(4x,a,f7.4,a,i0,a,i0,a,es9.2)') '99 % of the states within ', &
         percentile_99(df), ', beyond 0.01: ', count(df > 0.01_wp), ' of ', size(df), &
         '; max |dF_z|/F_z ', dz
   end subroutine compare_forces

   !> The 99th percentile (the value below which 99 % of the values lie).
   pure real(wp) function percentile_99(values) result(p)
      real(wp), intent(in) :: values(:)
      integer :: k, i

      k = max(1, ceiling(0.99_wp*size(values)))
      do i = 1, size(values)
         p = values(i)
         if (count(values <= p) >= k .and. count(values < p) < k) return
      end do
   end function percentile_99

   !> The defaults of issue 13 against the old ones, same run: the new defaults (normal reduction
   !> `coupled`, tangential correction `exact-ellipse`), the same without the correction, and
   !> the defaults when the issue was filed (`local-hertz`, no correction), on the full case at a
   !> fixed position (normal solve for the load + tangential) and on the kinematic call along
   !> the hunting trajectory, with the ratios to the old defaults.
   subroutine defaults_section(config, bench)
      !> The options of the run.
      type(bench_config_type), intent(in) :: config
      !> The case.
      type(bench_case_type), intent(in) :: bench
      integer, parameter :: n_configs = 3
      type(full_case_kernel) :: full(n_configs)
      type(kinematic_kernel) :: moving(n_configs)
      type(timing_type) :: t_full(n_configs), t_moving(n_configs)
      real(wp) :: r_full(3, n_configs), r_moving(3, n_configs)
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      type(error_type), allocatable :: error
      character(len=*), parameter :: names(n_configs) = [character(len=40) :: &
         'new defaults (coupled, exact-ellipse)', 'coupled, correction none', &
         'old defaults (local-hertz, none)']
      integer :: c

      call section('defaults: new (issue 13) against old, 100 strips x 50 elements, same run')
      do c = 1, n_configs
         normal = bench%normal_options
         tangential = bench%tangential_options
         if (c >= 2) tangential%correction = correction_none
         if (c == 3) normal%reduction = reduction_local_hertz
         full(c)%n_strips = sizes(3)
         full(c)%contact = bench%normal_contact(sizes(3), reduction=normal%reduction)
         full(c)%load = bench%load
         full(c)%material = bench%material
         full(c)%options = tangential
         full(c)%options%fields = .false.
         full(c)%creepage = bench%headline
         call moving(c)%solver%init('builtin:S1002', 'builtin:UIC60', error)
         call stop_on(error, 'solver init')
         call moving(c)%solver%set_options(error, normal=normal, tangential=tangential)
         call stop_on(error, 'set_options')
         moving(c)%states = hunting_states(1000)
         call moving(c)%run(1)
      end do
      ! The configurations of each item are timed side by side, batch after batch in turn: a
      ! change of the shared machine's speed during the item reaches every configuration.
      call time_side_by_side(full, config%runs, config%batch_time, t_full, r_full)
      do c = 1, n_configs
         call report(full(c), t_full(c), 'full case, fixed position, '//trim(names(c)))
      end do
      call time_side_by_side(moving, config%runs, config%batch_time, t_moving, r_moving)
      do c = 1, n_configs
         call report(moving(c), t_moving(c), 'kinematic call, hunting, '//trim(names(c)))
      end do
      write (output_unit, '(2x,a,i0,a)') 'ratios new/old defaults, median [min, max] over the ', &
         config%runs, ' rounds of the same run:'
      write (output_unit, '(4x,a,3(f6.2,a))') 'full case        ', r_full(1, 1), ' [', &
         r_full(2, 1), ',', r_full(3, 1), ']'
      write (output_unit, '(4x,a,3(f6.2,a),i0)') 'wheel in motion  ', r_moving(1, 1), ' [', &
         r_moving(2, 1), ',', r_moving(3, 1), ']; failed calls: ', sum(moving%failures)
      write (output_unit, '(2x,a,f6.2,a,f6.2)') 'ratio with/without the correction (medians): '// &
         'full case ', r_full(1, 1)/r_full(1, 2), ', wheel in motion ', &
         r_moving(1, 1)/r_moving(1, 2)
   end subroutine defaults_section

   !> Every 0.01 mm position from -10 to 10 mm at yaw 0 and +-10 mrad: the failed calls.
   subroutine scan_section()
      type(contact_solver_type) :: solver
      type(error_type), allocatable :: error
      integer :: failures
      real(wp) :: t

      call section('scan: kinematic call at every 0.01 mm, t_y = -10 ... 10 mm, yaw 0 and '// &
         '+-10 mrad, vertical load 64.7 kN')
      call solver%init('builtin:S1002', 'builtin:UIC60', error)
      call stop_on(error, 'solver init')
      t = wall_time()
      call scan_positions(solver, [0.0_wp, 0.01_wp, -0.01_wp], failures)
      write (output_unit, '(2x,a,i0,a,f8.1,a)') 'failed calls: ', failures, ' of 6003 (', &
         wall_time() - t, ' s)'
   end subroutine scan_section

end module bench_moving_items
