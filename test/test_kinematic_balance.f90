!> Tests of the kinematic call's vertical balance (issue 25): every state of the issue converges
!> with the total vertical force within 1e-5 of the load (the app's 33-case sweep at the flange,
!> state 937 of the benchmark's hunting trajectory, the case that missed by 1 %, a seeded loop of
!> random states), the vertical force is monotone in the vertical approach where the coupled
!> normal reduction made it jump, and a state without equilibrium (the wheel climbs) returns its
!> own status with the best state found.
module test_kinematic_balance
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use test_external_data, only: external_file
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type, stat_no_contact, stat_invalid_input
   use shcontact_core_material, only: material_type
   use shcontact_geometry_kinematics, only: wheelset_state_type, pure_rolling_pitch_rate
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      contact_fields_type, &
      load_vertical_force, load_vertical_position, load_approach
   use shcontact_core_strings, only: str_real, str_int
   use shcontact_geometry_contact, only: contact_options_type
   use shcontact_normal_options, only: normal_options_type, reduction_local_hertz
   use shcontact_tangential_options, only: tangential_options_type
   implicit none
   private

   public :: collect_kinematic_balance, random_balance_loop, flange_state

   !> Speed (mm/s), nominal radius (mm), the app's default wheel load (N) and the documented
   !> relative tolerance of the balance.
   real(wp), parameter :: speed = 30000.0_wp, r_nom = 460.0_wp, f_z = 64700.0_wp, &
      rtol = 1.0e-5_wp
   !> The six kinematic sets (ξ, η, ω) of the kinematic sample
   !> (the external data's reference/kinematic_sample/README.md): v_y = η V, yaw rate = ω V/750 mm,
   !> pitch rate = −(V/R₀)(1 + ξ).
   real(wp), parameter :: kinematic_sets(3, 6) = reshape([0.0_wp, 0.0_wp, 0.0_wp, &
      1.0e-3_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0e-3_wp, 0.0_wp, 0.0_wp, 0.0_wp, 1.0e-3_wp, &
      -1.0e-3_wp, -1.0e-3_wp, 0.0_wp, 1.0e-3_wp, 1.0e-3_wp, 1.0e-3_wp], [3, 6])
   !> States of the random loop in the test suite (debug build); the documented command of
   !> doc/kinematics.md runs 20 000.
   integer, parameter :: suite_states = 300

contains

   !> The tests of this suite.
   subroutine collect_kinematic_balance(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('app_sweep_at_the_flange', test_sweep), &
         new_unittest('vertical_force_monotone_in_approach', test_monotone), &
         new_unittest('vertical_force_dip_at_6_78_mm', test_dip_6_78), &
         new_unittest('hunting_state_937', test_state_937), &
         new_unittest('leaving_the_flange_root_at_60_m_s', test_leaving_flange_root), &
         new_unittest('balance_within_tolerance', test_one_percent_case), &
         new_unittest('random_states', test_random), &
         new_unittest('random_states_measured_pair', test_random_measured), &
         new_unittest('random_states_vehicle_velocities', test_random_wide), &
         new_unittest('climbing_wheel_has_no_equilibrium', test_climbing), &
         new_unittest('flange_states_other_table_steps', test_table_steps), &
         new_unittest('vertical_force_continuous_coarse_grid', test_coarse_continuity), &
         new_unittest('reference_point_continuous_flange_789', test_reference_789), &
         new_unittest('first_try_tables_give_full_tables_forces', test_first_try_tables), &
         new_unittest('flange_root_steps_as_documented', test_flange_root_steps), &
         new_unittest('flange_face_steps_as_documented', test_flange_face_steps), &
         new_unittest('lateral_scan_places_as_documented', test_lateral_scan_places), &
         new_unittest('flange_steps_come_from_the_coupling', test_steps_of_the_coupling), &
         new_unittest('coupled_loads_steep_in_the_strips', test_steep_coupling)]
   end subroutine collect_kinematic_balance

   !> The vertical force carried by the contact (N, up on the wheel).
   pure real(wp) function carried(result)
      type(contact_result_type), intent(in) :: result
      carried = -result%track%fz
   end function carried

   !> One call at load `load`; an error names the state.
   subroutine balanced(solver, state, load, result, error)
      type(contact_solver_type), intent(inout) :: solver
      type(wheelset_state_type), intent(in) :: state
      real(wp), intent(in) :: load
      type(contact_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      character(len=120) :: where

      write (where, '(a,f10.6,a,es13.6,a,f9.1,a)') 't_y = ', state%y_ws, ' mm, yaw = ', &
         state%yaw, ' rad, F_z = ', load, ' N'
      call solver%solve_kinematic(state, contact_load_type(load_vertical_force, load), &
         result, err)
      if (allocated(err)) then
         call test_failed(error, trim(where)//': '//err%message)
         return
      end if
      call check(error, abs(carried(result) - load) <= rtol*load, trim(where)// &
         ': vertical force off the load by more than 1e-5')
   end subroutine balanced

   !> The app's sweep `&kinematics mode='on' / &sweep t_y = 6.70, 6.80 t_y_points = 11
   !> yaw = -0.008, 0.0, 0.008 /` (30 m/s, pure rolling): 6 of 33 failed before issue 25, and
   !> where it converged the flange normal force jumped between neighbours (169, 176, 186, 188 kN,
   !> failed, 185 kN, failed, failed, 246 kN at yaw −8 mrad, 6.72…6.80 mm). Every call balances,
   !> and at every yaw the normal force grows with t_y (the wheel pressed further onto the
   !> flange) by less than 8 % from one neighbour 0.01 mm away to the next (doc/kinematics.md:
   !> 156.0 … 230.8 kN at −8 mrad, steps of at most 6.2 %; held to the digits it prints).
   subroutine test_sweep(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      real(wp), parameter :: yaws(3) = [-0.008_wp, 0.0_wp, 0.008_wp]
      !> doc/kinematics.md's normal forces at yaw −8 mrad, 6.70 … 6.80 mm (kN, as printed).
      real(wp), parameter :: doc_fn(0:10) = [156.0_wp, 164.0_wp, 169.6_wp, 176.5_wp, 187.4_wp, &
         194.5_wp, 202.4_wp, 209.2_wp, 215.9_wp, 223.9_wp, 230.8_wp]
      real(wp) :: fn(0:10)
      integer :: i, j

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      do j = 1, size(yaws)
         do i = 0, 10
            call balanced(solver, wheelset_state_type(y_ws=6.70_wp + 0.01_wp*i, yaw=yaws(j), &
               v_forward=speed, pitch_rate=pure_rolling_pitch_rate(speed, r_nom)), f_z, &
               result, error)
            if (allocated(error)) return
            fn(i) = result%track%fn
         end do
         do i = 1, 10
            call check(error, fn(i) >= fn(i - 1) .and. fn(i) < 1.08_wp*fn(i - 1), &
               'flange normal force not growing smoothly with t_y')
            if (allocated(error)) return
         end do
         if (j == 1) then
            call check(error, all(abs(fn/1000.0_wp - doc_fn) <= 0.05_wp + 1.0e-9_wp), &
               'the normal forces at yaw -8 mrad are not those of doc/kinematics.md')
            if (allocated(error)) return
         end if
      end do
   end subroutine test_sweep

   !> The vertical force carried C(Δz) as a function of the vertical approach at the states of
   !> the sweep where it jumped (t_y = 6.79 and 6.80 mm, yaw −8 mrad: C = 60 097, 52 273,
   !> 56 789, 55 622 N at Δz = 0.525 … 0.540 mm before, with a smooth normal force): sampled every
   !> 2.5 µm over 0.40–0.65 mm, the normal force and C never decrease (the normal force of a
   !> contact grows with its approach, and the tangential forces at fixed creepages follow it).
   subroutine test_monotone(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      type(wheelset_state_type) :: state
      real(wp), parameter :: states(2) = [6.79_wp, 6.80_wp]
      real(wp) :: c_last, n_last, dz
      character(len=80) :: where
      integer :: i, j

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      do j = 1, size(states)
         state = wheelset_state_type(y_ws=states(j), yaw=-0.008_wp, v_forward=speed, &
            pitch_rate=pure_rolling_pitch_rate(speed, r_nom))
         c_last = -huge(1.0_wp)
         n_last = -huge(1.0_wp)
         do i = 0, 100
            dz = 0.40_wp + 0.0025_wp*i
            write (where, '(a,f5.2,a,f7.4,a)') 't_y = ', states(j), ' mm, dz = ', dz, ' mm'
            call solver%solve_kinematic(state, contact_load_type(load_vertical_position, dz), &
               result, err)
            if (allocated(err)) then
               call test_failed(error, trim(where)//': '//err%message)
               return
            end if
            call check(error, result%track%fn >= n_last, trim(where)// &
               ': the normal force decreases with the approach')
            if (allocated(error)) return
            call check(error, carried(result) >= c_last, trim(where)// &
               ': the vertical force decreases with the approach')
            if (allocated(error)) return
            c_last = carried(result)
            n_last = result%track%fn
         end do
      end do
   end subroutine test_monotone

   !> doc/kinematics.md, "What is not smooth yet": at t_y = 6.78 mm, yaw −8 mrad (30 m/s, pure
   !> rolling) C(Δz) over Δz = 0.5360 … 0.5366 mm in steps of 1 nm peaks at 86 251 N at
   !> 0.53636 mm and falls to 85 914 N at 0.536488 mm (±5 N, ±2 nm) before it rises again.
   subroutine test_dip_6_78(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: m = 600
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      real(wp) :: c(0:m), dz(0:m)
      integer :: i, j, k

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      do k = 0, m
         dz(k) = 0.5360_wp + 1.0e-6_wp*k
         call solver%solve_kinematic(wheelset_state_type(y_ws=6.78_wp, yaw=-0.008_wp, &
            v_forward=speed, pitch_rate=pure_rolling_pitch_rate(speed, r_nom)), &
            contact_load_type(load_vertical_position, dz(k)), result, err)
         if (allocated(err)) then
            call test_failed(error, 'dz = '//str_real(dz(k))//' mm: '//err%message)
            return
         end if
         c(k) = carried(result)
      end do
      i = maxloc(c(0:599), 1) - 1
      j = i + minloc(c(i:m), 1) - 1
      call check(error, abs(c(i) - 86251.0_wp) <= 5.0_wp .and. abs(dz(i) - 0.53636_wp) <= &
         2.0e-6_wp .and. abs(c(j) - 85914.0_wp) <= 5.0_wp .and. abs(dz(j) - 0.536488_wp) <= &
         2.0e-6_wp, 'C peaks at '//str_real(c(i))//' N at dz '//str_real(dz(i))// &
         ' mm and falls to '//str_real(c(j))//' N at '//str_real(dz(j))// &
         ' mm (doc/kinematics.md: 86251 at 0.53636, 85914 at 0.536488)')
   end subroutine test_dip_6_78

   !> State 937 of the benchmark's hunting trajectory (failed before, also on a fresh solver).
   subroutine test_state_937(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      call balanced(solver, wheelset_state_type(y_ws=6.754623_wp, yaw=5.358268e-3_wp, &
         v_forward=speed, v_lateral=-67.33_wp, yaw_rate=0.1326_wp, &
         pitch_rate=pure_rolling_pitch_rate(speed, r_nom)*(1.0_wp + 2.0e-4_wp)), f_z, &
         result, error)
   end subroutine test_state_937

   !> A wheelset leaving the flange root at 60 m/s with about 0.5 m/s lateral speed (stop 49's
   !> Python vehicle run; doc/kinematics.md, "What is not smooth yet"): the two states of that
   !> run failed with status 5 (64 590 N for 64 700 N: C(Δz) jumped by ~140 N where two wiggles
   !> of the loaded gap's flat bottom crossed in depth and their bands swapped,
   !> shcontact_normal_reference), and so did 2 of the 110 states of t_y = 6.669 … 6.674 mm
   !> (steps of 0.5 µm) × v_y = −600 … −200 mm/s × yaw −0.58, +2.09 mrad (yaw rate −0.21 rad/s,
   !> pure rolling). Every call balances, and C(Δz) of the first state over Δz = 0.1775 …
   !> 0.1785 mm in steps of 1 nm changes by −9.8 … +17.9 N per step (doc/kinematics.md; held
   !> within −12 … +20 N: the jump was +129 N in one step at 0.177935 mm).
   subroutine test_leaving_flange_root(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      real(wp), parameter :: fast = 60000.0_wp, yaws(2) = [-0.58e-3_wp, 2.09e-3_wp]
      real(wp) :: c_last, step_lo, step_hi
      integer :: i, j, k

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      call balanced(solver, wheelset_state_type(y_ws=6.671_wp, yaw=-0.00058_wp, &
         v_forward=fast, v_lateral=-501.0_wp, yaw_rate=-0.214_wp, pitch_rate=-130.4614_wp), &
         f_z, result, error)
      if (allocated(error)) return
      step_lo = huge(1.0_wp)
      step_hi = -huge(1.0_wp)
      do i = 0, 1000
         call solver%solve_kinematic(wheelset_state_type(y_ws=6.671_wp, yaw=-0.00058_wp, &
            v_forward=fast, v_lateral=-501.0_wp, yaw_rate=-0.214_wp, &
            pitch_rate=-130.4614_wp), contact_load_type(load_vertical_position, &
            0.1775_wp + 1.0e-6_wp*i), result, err)
         if (allocated(err)) then
            call test_failed(error, 'the scan of C: '//err%message)
            return
         end if
         if (i > 0) then
            step_lo = min(step_lo, carried(result) - c_last)
            step_hi = max(step_hi, carried(result) - c_last)
         end if
         c_last = carried(result)
      end do
      call check(error, step_lo > -12.0_wp .and. step_hi < 20.0_wp, 'C(dz) at 6.671 mm steps '// &
         'by '//str_real(step_lo)//' ... '//str_real(step_hi)//' N per nm, beyond -12 ... 20 N')
      if (allocated(error)) return
      call balanced(solver, wheelset_state_type(y_ws=6.6692_wp, yaw=2.09e-3_wp, &
         v_forward=fast, v_lateral=-499.6_wp, yaw_rate=-0.203_wp, &
         pitch_rate=pure_rolling_pitch_rate(fast, r_nom)), f_z, result, error)
      if (allocated(error)) return
      do i = 0, 10
         do j = 0, 4
            do k = 1, size(yaws)
               call balanced(solver, wheelset_state_type(y_ws=6.669_wp + 0.0005_wp*i, &
                  yaw=yaws(k), v_forward=fast, v_lateral=-600.0_wp + 100.0_wp*j, &
                  yaw_rate=-0.21_wp, pitch_rate=pure_rolling_pitch_rate(fast, r_nom)), f_z, &
                  result, error)
               if (allocated(error)) return
            end do
         end do
      end do
   end subroutine test_leaving_flange_root

   !> t_y = 6.75 mm, yaw = 5 mrad returned status 0 with F_z = 65 183 N for 64 700 N (the old
   !> balance accepted 1 %); now within 1e-5.
   subroutine test_one_percent_case(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      call balanced(solver, wheelset_state_type(y_ws=6.75_wp, yaw=0.005_wp, v_forward=speed, &
         pitch_rate=pure_rolling_pitch_rate(speed, r_nom)), f_z, result, error)
   end subroutine test_one_percent_case

   !> A seeded loop of random states: t_y in ±10 mm, yaw in ±10 mrad, F_z in 32–97 kN, one of the
   !> six kinematic sets; `failures` calls failed, `worst` is the largest relative miss of the
   !> balance of the others, `misses` the calls beyond 1e-5. The states depend on `seed` alone.
   subroutine random_balance_loop(n, seed, failures, misses, worst, first_failure, wheel, rail, &
         largest_f, wide)
      integer, intent(in) :: n, seed
      integer, intent(out) :: failures, misses
      real(wp), intent(out) :: worst
      !> The state and message of the first failed call (empty when none).
      character(len=:), allocatable, intent(out) :: first_failure
      !> The wheel and rail profiles (files or builtin: names; default S1002 on UIC60).
      character(len=*), intent(in), optional :: wheel, rail
      !> The largest |f| = |F_t|/(μF_n) of any loaded patch of the calls that balanced.
      real(wp), intent(out), optional :: largest_f
      !> A vehicle code's velocities instead of the kinematic sets: V 20–80 m/s, v_y ±600 mm/s,
      !> yaw rate ±0.3 rad/s, pure rolling.
      logical, intent(in), optional :: wide
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      type(wheelset_state_type) :: state
      integer(kind=8) :: lcg
      real(wp) :: u(7), load, miss, v
      character(len=120) :: where
      integer :: i, j, s, draws
      logical :: vehicle

      failures = 0
      misses = 0
      worst = 0.0_wp
      first_failure = ''
      if (present(largest_f)) largest_f = 0.0_wp
      if (present(wheel) .and. present(rail)) then
         call solver%init(wheel, rail, err)
      else
         call solver%init('builtin:S1002', 'builtin:UIC60', err)
      end if
      if (allocated(err)) then
         failures = n
         first_failure = 'init: '//err%message
         return
      end if
      vehicle = .false.
      if (present(wide)) vehicle = wide
      draws = 4
      if (vehicle) draws = 7
      lcg = int(seed, kind=8)
      do i = 1, n
         do j = 1, draws
            ! Knuth's MMIX linear congruential generator, top 53 bits.
            lcg = lcg*6364136223846793005_8 + 1442695040888963407_8
            u(j) = real(ishft(lcg, -11), wp)*2.0_wp**(-53)
         end do
         s = 1 + min(5, int(6.0_wp*u(4)))
         if (vehicle) then
            v = 20000.0_wp + 60000.0_wp*u(5)
            state = wheelset_state_type(y_ws=-10.0_wp + 20.0_wp*u(1), &
               yaw=-0.01_wp + 0.02_wp*u(2), v_forward=v, v_lateral=-600.0_wp + 1200.0_wp*u(6), &
               yaw_rate=-0.3_wp + 0.6_wp*u(7), pitch_rate=pure_rolling_pitch_rate(v, r_nom))
         else
            state = wheelset_state_type(y_ws=-10.0_wp + 20.0_wp*u(1), &
               yaw=-0.01_wp + 0.02_wp*u(2), v_forward=speed, &
               v_lateral=kinematic_sets(2, s)*speed, &
               yaw_rate=kinematic_sets(3, s)*speed/750.0_wp, &
               pitch_rate=-(speed/r_nom)*(1.0_wp + kinematic_sets(1, s)))
         end if
         load = 32000.0_wp + 65000.0_wp*u(3)
         call solver%solve_kinematic(state, contact_load_type(load_vertical_force, load), &
            result, err)
         if (allocated(err)) then
            failures = failures + 1
            if (len(first_failure) == 0) then
               write (where, '(a,i0,a,f10.6,a,es13.6,a,f9.1,a)') 'state ', i, ': t_y = ', &
                  state%y_ws, ' mm, yaw = ', state%yaw, ' rad, F_z = ', load, ' N, '
               first_failure = trim(where)//' '//velocities()//': '//err%message
            end if
            cycle
         end if
         miss = abs(carried(result) - load)/load
         worst = max(worst, miss)
         if (present(largest_f)) largest_f = max(largest_f, largest_patch_f(result))
         if (miss > rtol) misses = misses + 1
      end do
   contains
      !> The state's velocities as the failure message gives them (the kinematic set's number
      !> too in the plain loop).
      function velocities() result(text)
         character(len=:), allocatable :: text
         character(len=160) :: line
         write (line, '(a,f9.1,a,f8.2,a,es11.4,a,es13.6,a)') 'V = ', state%v_forward, &
            ' mm/s, v_y = ', state%v_lateral, ' mm/s, yaw rate = ', state%yaw_rate, &
            ' rad/s, pitch rate = ', state%pitch_rate, ' rad/s'
         text = trim(line)
         if (.not. vehicle) text = text//', set '//str_int(s)
      end function velocities
   end subroutine random_balance_loop

   !> The seeded random loop, suite_states states, or as many as the environment variable
   !> SHCONTACT_BALANCE_STATES says (doc/kinematics.md runs 20 000 in the release build): no
   !> failed call, every balance within 1e-5.
   subroutine test_random(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: failures, misses, n
      real(wp) :: worst
      character(len=:), allocatable :: first

      n = loop_states()
      call random_balance_loop(n, 25, failures, misses, worst, first)
      call judge_loop(error, '', n, failures, misses, worst, first)
   end subroutine test_random

   !> The seeded random loop with a vehicle code's velocities (V 20–80 m/s, v_y ±600 mm/s, yaw
   !> rate ±0.3 rad/s, pure rolling; t_y ±10 mm, yaw ±10 mrad, F_z 32–97 kN), a robustness loop
   !> over what a vehicle code asks (the states of [[test_leaving_flange_root]] lie in its range,
   !> but a loop this size does not land on them: it passes with the old reference point too).
   !> No failed call, every balance within 1e-5 and no patch past Coulomb; suite_states states,
   !> or SHCONTACT_BALANCE_STATES.
   subroutine test_random_wide(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: failures, misses, n
      real(wp) :: worst, f_max
      character(len=:), allocatable :: first

      n = loop_states()
      call random_balance_loop(n, 27, failures, misses, worst, first, largest_f=f_max, &
         wide=.true.)
      call judge_loop(error, 'vehicle velocities', n, failures, misses, worst, first, f_max)
   end subroutine test_random_wide

   !> The seeded random loop of [[random_balance_loop]] on the measured pair of the external
   !> data, a worn wheel (MiniProf Car7216_0001r.whl) on a measured rail (avg_HR.BAN), read with
   !> the solver's defaults as a vehicle code would: no failed call, every balance within 1e-5,
   !> and no patch past Coulomb (|f| ≤ 1 + 1e-12). suite_states states, or as many as
   !> SHCONTACT_BALANCE_STATES says (doc/kinematics.md runs 20 000). Skipped without the
   !> external data.
   subroutine test_random_measured(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: failures, misses, n
      real(wp) :: worst, f_max
      character(len=:), allocatable :: first, wheel, rail

      wheel = external_file('profiles/Car7216_0001r.whl', error)
      if (allocated(error)) return
      rail = external_file('profiles/avg_HR.BAN', error)
      if (allocated(error)) return
      n = loop_states()
      call random_balance_loop(n, 26, failures, misses, worst, first, wheel, rail, f_max)
      call judge_loop(error, 'measured pair', n, failures, misses, worst, first, f_max)
   end subroutine test_random_measured

   !> Print a random loop's line ("LABEL, random states: n, failed calls …", the line
   !> doc/kinematics.md quotes) and check it: no failed call, no balance beyond 1e-5 and, when
   !> `f_max` is given, no patch past Coulomb (|f| ≤ 1 + 1e-12).
   subroutine judge_loop(error, label, n, failures, misses, worst, first, f_max)
      type(error_type), allocatable, intent(out) :: error
      !> The loop's name ('' for the plain loop).
      character(len=*), intent(in) :: label
      integer, intent(in) :: n, failures, misses
      real(wp), intent(in) :: worst
      !> The first failed call's state and message.
      character(len=*), intent(in) :: first
      real(wp), intent(in), optional :: f_max
      character(len=:), allocatable :: head, which

      head = 'random states: '
      which = 'in the random loop'
      if (len(label) > 0) then
         head = label//', '//head
         which = '('//label//')'
      end if
      if (present(f_max)) then
         write (*, '(4x,a,i0,a,i0,a,i0,a,es9.2,a,f10.7)') head, n, ', failed calls ', &
            failures, ', beyond 1e-5 ', misses, ', largest relative miss ', worst, &
            ', largest |f| ', f_max
      else
         write (*, '(4x,a,i0,a,i0,a,i0,a,es9.2)') head, n, ', failed calls ', failures, &
            ', beyond 1e-5 ', misses, ', largest relative miss ', worst
      end if
      call check(error, failures == 0, 'failed calls '//which//'; first: '//first)
      if (allocated(error)) return
      call check(error, misses == 0, 'balance beyond 1e-5 '//which)
      if (allocated(error) .or. .not. present(f_max)) return
      call check(error, f_max <= 1.0_wp + 1.0e-12_wp, 'a patch past Coulomb '//which)
   end subroutine judge_loop

   !> The random loops' state count: suite_states, or SHCONTACT_BALANCE_STATES when set.
   integer function loop_states() result(n)
      integer :: length, stat
      character(len=16) :: value
      n = suite_states
      call get_environment_variable('SHCONTACT_BALANCE_STATES', value, length, stat)
      if (stat == 0 .and. length > 0) then
         read (value, *, iostat=stat) n
         if (stat /= 0 .or. n < 1) n = suite_states
      end if
   end function loop_states

   !> The largest |f| = |F_t|/(μF_n) over the loaded patches of a result.
   pure real(wp) function largest_patch_f(result) result(f)
      type(contact_result_type), intent(in) :: result
      integer :: k
      f = 0.0_wp
      do k = 1, result%n_loaded
         f = max(f, hypot(result%patch(k)%fx_norm, result%patch(k)%fy_norm))
      end do
   end function largest_patch_f

   !> With μ = 0.8, t_y = 7 mm and a yaw of −60 mrad the flange (γ ≈ −1.08 rad) slides nearly
   !> fully (|f_y| ≈ 1): a patch then carries N (cos γ − μ |f_y| sin|γ|) < 0 vertically, the
   !> tangential force lifts the wheel more than the normal force carries it at any approach, and
   !> no vertical position balances the load. The call returns stat_no_contact with the reason,
   !> and its result holds the best state found: loaded, with a vertical force below the load and
   !> below what the normal forces alone carry.
   subroutine test_climbing(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      real(wp) :: normal_part
      integer :: k

      call solver%init('builtin:S1002', 'builtin:UIC60', err, &
         material=material_type(friction=0.8_wp))
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      call solver%solve_kinematic(wheelset_state_type(y_ws=7.0_wp, yaw=-0.06_wp, &
         v_forward=speed, pitch_rate=pure_rolling_pitch_rate(speed, r_nom)), &
         contact_load_type(load_vertical_force, f_z), result, err)
      call check(error, allocated(err), 'a climbing wheel must not balance')
      if (allocated(error)) return
      call check(error, err%stat == stat_no_contact, 'expected stat_no_contact')
      if (allocated(error)) return
      call check(error, index(err%message, 'climbs') > 0, 'the reason: '//err%message)
      if (allocated(error)) return
      call check(error, result%n_loaded >= 1 .and. result%track%fn > 0.0_wp, &
         'the best state found is returned')
      if (allocated(error)) return
      normal_part = 0.0_wp
      do k = 1, result%n_loaded
         normal_part = normal_part + result%patch(k)%fn*cos(result%patch(k)%gamma_plane)
      end do
      call check(error, carried(result) < f_z .and. carried(result) < normal_part, &
         'the tangential forces lift the wheel at the best state')
      if (allocated(error)) return
      ! A vertical position the user prescribes whose normal force passes the largest load
      ! (5 mm at Y_WS = 0: 31 MN) is refused in the kinematic call too, as in solve(); the
      ! balance's own trial positions are not (the climbing status above).
      call solver%solve_kinematic(wheelset_state_type(y_ws=0.0_wp, v_forward=speed, &
         pitch_rate=pure_rolling_pitch_rate(speed, r_nom)), &
         contact_load_type(load_vertical_position, 5.0_wp), result, err)
      call check(error, allocated(err), 'vertical position 5 mm accepted')
      if (allocated(error)) return
      call check(error, err%stat == stat_invalid_input .and. index(err%message, &
         'vertical position 5 mm gives the normal force') > 0, 'the reason: '//err%message)
   end subroutine test_climbing

   !> State i of the benchmark's flange trajectory (examples/bench/bench_moving.f90's
   !> flange_states: t_y = 7 + 2 sin(ω₁t) mm, yaw = 10 sin(ω₂t) mrad, t = (i − 1) ms, with the
   !> velocities of the motion).
   pure function flange_state(i) result(state)
      integer, intent(in) :: i
      type(wheelset_state_type) :: state
      real(wp), parameter :: two_pi = 6.283185307179586_wp, w1 = two_pi*2.5_wp, &
         w2 = two_pi*1.6180339887_wp
      real(wp) :: t
      t = (i - 1)*1.0e-3_wp
      state = wheelset_state_type(y_ws=7.0_wp + 2.0_wp*sin(w1*t), yaw=0.01_wp*sin(w2*t), &
         v_forward=speed, v_lateral=2.0_wp*w1*cos(w1*t), yaw_rate=0.01_wp*w2*cos(w2*t), &
         pitch_rate=pure_rolling_pitch_rate(speed, r_nom)*(1.0_wp + 2.0e-4_wp))
   end function flange_state

   !> The kinematic call's first try (strip tables to kinematic_table_gap, 0.25 mm) gives the
   !> forces of the full 2 mm tables (kinematic_table_gap = 2 mm: the full tables at once), and so
   !> does a first try to 0.12 mm, on flange states 396, 406, 607 and 997 of the benchmark
   !> (flange contact reaching towards the root) and 300, 310 (t_y ≈ 5 mm, two tread patches),
   !> each patch's table bounded by its load (shcontact_geometry_pair's load_reach) up to that
   !> cap: within 1e-4 in f and 1e-4 F_n, what the balance's 1e-5 F_z leaves. With tables ended by the gap, the first try cut off the flange
   !> root region that a vertical approach closes faster than the flank (state 396: 0.021 in
   !> f_y, 1 % in F_n); with tables ended by the touch approach but trusted up to their bound,
   !> a region just beyond it was missing from the strips' sweep (0.12 against 0.25 mm: 2.5e-3
   !> at state 406, 2.0e-3 at 997). Now a first-try table ends where the touch approach exceeds
   !> its bound (shcontact_geometry_pair's table_reach) and holds for approaches up to 99 % of
   !> the bound (shcontact_normal_semihertz's approach_reach; beyond, the full tables):
   !> doc/performance.md, "Tables bounded by the load's reach".
   subroutine test_first_try_tables(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: states(6) = [300, 310, 396, 406, 607, 997]
      real(wp), parameter :: first_gaps(2) = [0.25_wp, 0.12_wp]
      type(contact_solver_type) :: first, full
      type(contact_result_type) :: a, b
      type(contact_options_type) :: contact
      type(lib_error), allocatable :: err
      real(wp) :: df
      character(len=120) :: text
      integer :: i, j

      call full%init('builtin:S1002', 'builtin:UIC60', err)
      if (.not. allocated(err)) then
         contact = full%get_contact_options()
         contact%kinematic_table_gap = contact%table_gap
         call full%set_track(err, contact_options=contact)
      end if
      do j = 1, size(first_gaps)
         if (.not. allocated(err)) call first%init('builtin:S1002', 'builtin:UIC60', err)
         if (.not. allocated(err)) then
            contact = first%get_contact_options()
            contact%kinematic_table_gap = first_gaps(j)
            call first%set_track(err, contact_options=contact)
         end if
         if (allocated(err)) then
            call test_failed(error, 'set-up: '//err%message); return
         end if
         do i = 1, size(states)
            call balanced(first, flange_state(states(i)), f_z, a, error)
            if (.not. allocated(error)) call balanced(full, flange_state(states(i)), f_z, b, error)
            if (allocated(error)) return
            df = max(abs(a%main%fx/a%main%fn - b%main%fx/b%main%fn), &
               abs(a%main%fy/a%main%fn - b%main%fy/b%main%fn))/0.3_wp
            write (text, '(a,i0,a,f5.3,a,es9.2,a,es9.2)') 'flange state ', states(i), &
               ', first try to ', first_gaps(j), ' mm: |df| ', df, ', |dF_n|/F_n ', &
               abs(a%main%fn - b%main%fn)/b%main%fn
            call check(error, df < 1.0e-4_wp .and. &
               abs(a%main%fn - b%main%fn) < 1.0e-4_wp*b%main%fn, &
               'first try against the full tables', more=trim(text))
            if (allocated(error)) return
         end do
      end do
   end subroutine test_first_try_tables

   !> A solver on the vehicle preset's grid (60 strips × 40 elements) with strip tables every
   !> `step` mm (the contact option table_step, a user option).
   subroutine coarse_solver(solver, step, error)
      type(contact_solver_type), intent(out) :: solver
      real(wp), intent(in) :: step
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(contact_options_type) :: contact
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      if (.not. allocated(err)) then
         contact = solver%get_contact_options()
         contact%table_step = step
         call solver%set_track(err, contact_options=contact)
      end if
      if (.not. allocated(err)) then
         call solver%get_options(normal, tangential)
         normal%n_strips = 60
         tangential%n_elements = 40
         call solver%set_options(err, normal=normal, tangential=tangential)
      end if
      if (allocated(err)) call test_failed(error, 'set-up: '//err%message)
   end subroutine coarse_solver

   !> The flange trajectory's states 400–415 (state 408 failed with table_step = 0.04 mm: the
   !> bracket closed on a jump of C(Δz) at Δz = 0.71255 mm) and every 50th state, on 60 strips ×
   !> 40 elements with table steps 0.02, 0.04 and 0.05 mm: every call balances within 1e-5.
   subroutine test_table_steps(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: steps(3) = [0.02_wp, 0.04_wp, 0.05_wp]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      integer :: i, j

      do j = 1, size(steps)
         call coarse_solver(solver, steps(j), error)
         if (allocated(error)) return
         do i = 1, 1000
            if (.not. ((i >= 400 .and. i <= 415) .or. mod(i, 50) == 0)) cycle
            call balanced(solver, flange_state(i), f_z, result, error)
            if (allocated(error)) then
               write (*, '(4x,a,i0,a,f5.3,a)') 'flange state ', i, ', table_step ', steps(j), ' mm'
               return
            end if
         end do
      end do
   end subroutine test_table_steps

   !> C(Δz) of flange state 408 on 60 strips × 40 elements, tables every 0.04 mm, across the two
   !> places where it jumped: at Δz = 0.712545 mm by 5.2 N (the quadrature of the coupling
   !> kernel switched from Simpson's rule to the midpoint rule where two groups' distance crossed
   !> 2.5 widths) and at 0.7288765 mm by −103 N (a group at the patch's edge left the coupled
   !> set with its last strip, and its neighbours' strips lost the ratio interpolated towards
   !> its own). Over 1e-5 and 1e-6 mm there C changes by what its slope gives (≈ 0.9 N and
   !> 0.1 N): below 2 N.
   subroutine test_coarse_continuity(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: centre(2) = [0.712545_wp, 0.7288765_wp], half(2) = [5.0e-6_wp, &
         5.0e-7_wp]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      real(wp) :: c(2)
      character(len=80) :: where
      integer :: j, k

      call coarse_solver(solver, 0.04_wp, error)
      if (allocated(error)) return
      do j = 1, size(centre)
         do k = 1, 2
            call solver%solve_kinematic(flange_state(408), contact_load_type( &
               load_vertical_position, centre(j) + (2*k - 3)*half(j)), result, err)
            if (allocated(err)) then
               call test_failed(error, err%message)
               return
            end if
            c(k) = carried(result)
         end do
         write (where, '(a,f10.7,a,f8.3,a)') 'dz = ', centre(j), ' mm: C changes by ', &
            c(2) - c(1), ' N'
         call check(error, abs(c(2) - c(1)) < 2.0_wp, trim(where))
         if (allocated(error)) return
      end do
   end subroutine test_coarse_continuity

   !> Flange state 789 (default grid): the patch spans the flange root and the flange, and its
   !> loaded gap has two minima whose depths cross at Δz = 0.172083 mm; the reference point
   !> jumped there from the flange (γ₀ = −1.222 rad) to the root (−0.561 rad), C(Δz) dropped by
   !> 565 N and f_x by 0.035 (doc/kinematics.md, "The patch's reference point"). Across
   !> 0.172083 ± 5e-7 mm γ₀ now changes by less than 0.01 rad, C by less than 10 N and f_x by
   !> less than 0.002; over Δz = 0.155 … 0.195 mm in steps of 0.5 µm γ₀ moves from the flange
   !> to the root by less than 0.1 rad per step, and C grows at every step.
   subroutine test_reference_789(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(lib_error), allocatable :: err
      real(wp) :: c(2), gamma(2), fx(2), c_last, gamma_last, step_largest
      integer :: k
      logical :: growing

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      do k = 1, 2
         if (.not. allocated(err)) call solver%solve_kinematic(flange_state(789), &
            contact_load_type(load_vertical_position, 0.172083_wp + (2*k - 3)*5.0e-7_wp), &
            result, err)
         if (allocated(err)) exit
         c(k) = carried(result)
         gamma(k) = result%main%gamma0
         fx(k) = result%main%fx/(0.3_wp*result%main%fn)
      end do
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, abs(gamma(2) - gamma(1)) < 0.01_wp .and. abs(c(2) - c(1)) < 10.0_wp &
         .and. abs(fx(2) - fx(1)) < 0.002_wp, 'continuous at dz = 0.172083 mm')
      if (allocated(error)) then
         write (*, '(4x,a,2f9.4,a,2f10.1,a,2f8.4)') 'gamma0 ', gamma, ', C ', c, ', f_x ', fx
         return
      end if
      step_largest = 0.0_wp
      growing = .true.
      do k = 0, 80
         call solver%solve_kinematic(flange_state(789), contact_load_type( &
            load_vertical_position, 0.155_wp + k*5.0e-4_wp), result, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         if (k > 0) then
            step_largest = max(step_largest, abs(result%main%gamma0 - gamma_last))
            growing = growing .and. carried(result) > c_last
         end if
         c_last = carried(result)
         gamma_last = result%main%gamma0
         if (k == 0) gamma(1) = gamma_last
      end do
      call check(error, gamma(1) < -1.2_wp .and. gamma_last > -0.6_wp .and. &
         step_largest < 0.1_wp .and. growing, 'gamma0 from the flange to the root, C growing')
      if (.not. allocated(error)) return
      write (*, '(4x,a,3f9.4,l2)') 'gamma0 first, last, largest step ', gamma(1), gamma_last, &
         step_largest, growing
   end subroutine test_reference_789

   !> doc/kinematics.md, "Not continuous at the flange root", the scan of t_y = 5 … 9 mm in steps
   !> of 0.5 µm (yaw 0, pure rolling at 30 m/s, 64.7 kN; `shcontact-kinematic-count -- ty-scan 5
   !> 9 8000`): no failed call, and the places where F_y,track leaves its neighbours' trend by
   !> more than 300 N (|ΔF_i − (ΔF_{i−1} + ΔF_{i+1})/2|, ΔF_i = F_{i+1} − F_i) are as documented:
   !> 36, 6 of them at 6.613–6.616 mm, 26 at 6.7–7.0 mm up to 1.5 kN, one of 0.53 kN at
   !> 5.4475 mm, three of 0.35–0.37 kN at 7.11–7.12 mm, none elsewhere. A fix of any step makes
   !> it fail: then the document says what changed.
   subroutine test_lateral_scan_places(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: m = 8000
      type(contact_solver_type) :: solver
      type(lib_error), allocatable :: err
      real(wp) :: second(m - 2), t, face_largest
      integer :: k, places, root, face, tread, face_end
      character(len=200) :: message

      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      call check(error, .not. allocated(err), 'init failed')
      if (allocated(error)) return
      call lateral_second_differences(solver, 5.0_wp, second, error)
      if (allocated(error)) return
      places = 0
      root = 0
      face = 0
      tread = 0
      face_end = 0
      face_largest = 0.0_wp
      message = ''
      do k = 1, m - 2
         if (second(k) <= 300.0_wp) cycle
         t = 5.0_wp + 0.0005_wp*k
         places = places + 1
         if (t > 6.6125_wp .and. t < 6.6165_wp) then
            root = root + 1
         else if (t >= 6.7_wp .and. t < 7.0_wp) then
            face = face + 1
            face_largest = max(face_largest, second(k))
         else if (abs(t - 5.4475_wp) < 1.0e-6_wp .and. abs(second(k) - 530.0_wp) < 10.0_wp) then
            tread = tread + 1
         else if (t >= 7.11_wp .and. t < 7.125_wp .and. second(k) >= 345.0_wp .and. &
               second(k) < 375.0_wp) then
            face_end = face_end + 1
         else
            write (message, '(a,f9.5,a,f8.1,a)') 'an undocumented place at t_y = ', t, &
               ' mm (', second(k), ' N)'
         end if
      end do
      call check(error, len_trim(message) == 0, trim(message))
      if (allocated(error)) return
      write (message, '(5(a,i0),a,f7.1,a)') 'places ', places, ' (36), at the root ', root, &
         ' (6), on the face ', face, ' (26), at 5.4475 mm ', tread, ' (1), at 7.11-7.12 mm ', &
         face_end, ' (3); the face''s largest ', face_largest, ' N (up to 1.5 kN)'
      call check(error, places == 36 .and. root == 6 .and. face == 26 .and. tread == 1 .and. &
         face_end == 3 .and. face_largest > 1450.0_wp .and. face_largest < 1550.0_wp, &
         trim(message))
   end subroutine test_lateral_scan_places

   !> doc/kinematics.md, "Not continuous at the flange root": the kinematic call's steps at
   !> t_y = 6.614850 → 6.614855 mm (the coupled reduction changes branch) and 6.61510 → 6.61515 mm
   !> (the first contact moves from the root to the flange face), yaw 0, pure rolling, 64.7 kN:
   !> the table's F_y,track, ΣF_n (±0.01 kN), Δz (±1e-4 mm), the plane (±1e-3 rad) and the
   !> reference point (±0.01 mm); and, at a prescribed approach of 0.074 mm, the continuous
   !> normal force (87 043, 87 026, 87 007 N, ±1 N). A fix of either step makes it fail: then
   !> the document says what changed.
   subroutine test_flange_root_steps(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: t_y(4) = [6.614850_wp, 6.614855_wp, 6.615100_wp, 6.615150_wp]
      real(wp), parameter :: fy(4) = [-52.72e3_wp, -51.48e3_wp, -54.97e3_wp, -44.94e3_wp], &
         fn(4) = [85.60e3_wp, 84.60e3_wp, 87.40e3_wp, 80.05e3_wp], &
         dz(4) = [0.0994_wp, 0.0984_wp, 0.1051_wp, 0.0461_wp], &
         plane(4) = [-0.745_wp, -0.745_wp, -0.712_wp, -1.204_wp], &
         y_ref(4) = [723.53_wp, 723.53_wp, 723.60_wp, 721.08_wp]
      real(wp), parameter :: t_approach(3) = [6.614845_wp, 6.614850_wp, 6.614855_wp], &
         fn_approach(3) = [87043.0_wp, 87026.0_wp, 87007.0_wp]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lib
      character(len=16) :: text
      integer :: i

      call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      do i = 1, size(t_y)
         if (.not. allocated(lib)) call solver%solve_kinematic(state_at(t_y(i)), &
            contact_load_type(load_vertical_force, 64700.0_wp), r, lib)
         if (allocated(lib)) then
            call test_failed(error, lib%message)
            return
         end if
         write (text, '(f10.6)') t_y(i)
         call check(error, r%n_loaded == 1 .and. abs(r%track%fy - fy(i)) <= 10.0_wp .and. &
            abs(r%patch(1)%fn - fn(i)) <= 10.0_wp .and. abs(r%dz - dz(i)) <= 1.0e-4_wp .and. &
            abs(r%patch(1)%gamma_plane - plane(i)) <= 1.0e-3_wp .and. &
            abs(r%patch(1)%y_track - y_ref(i)) <= 0.01_wp, message='t_y = '//trim(text)// &
            ' mm: F_y,track, F_n, dz, plane, y_track = '//str_real(r%track%fy)//', '// &
            str_real(r%patch(1)%fn)//', '//str_real(r%dz)//', '// &
            str_real(r%patch(1)%gamma_plane)//', '//str_real(r%patch(1)%y_track)// &
            ' (doc/kinematics.md, "Not continuous at the flange root")')
         if (allocated(error)) return
      end do
      do i = 1, size(t_approach)
         call solver%solve_kinematic(state_at(t_approach(i)), contact_load_type(load_approach, &
            0.074_wp), r, lib)
         if (allocated(lib)) then
            call test_failed(error, lib%message)
            return
         end if
         call check(error, abs(r%patch(1)%fn - fn_approach(i)) <= 1.0_wp, message= &
            'approach 0.074 mm: F_n '//str_real(r%patch(1)%fn)//' N, documented '// &
            str_real(fn_approach(i)))
         if (allocated(error)) return
      end do
   contains
      !> Pure rolling at 30 m/s, yaw 0, at t_y.
      pure type(wheelset_state_type) function state_at(y) result(state)
         real(wp), intent(in) :: y
         state = wheelset_state_type(y_ws=y, v_forward=30000.0_wp, &
            pitch_rate=-30000.0_wp/460.0_wp)
      end function state_at
   end subroutine test_flange_root_steps

   !> doc/kinematics.md, "Not continuous at the flange root": between t_y = 6.75 and 6.81 mm
   !> (121 states 0.5 µm apart, yaw 0, pure rolling at 30 m/s, 64.7 kN) 9 second differences of
   !> F_y,track exceed 400 N (the next largest is about 340 N), the largest 1.49 kN; every call
   !> succeeds. Held within ±2 steps and ±0.1 kN so that a change of the balance's branches
   !> shows; and ΣF_n at t_y = 6.80210 mm falls from 159.0 to 158.6 kN as Δz grows from 0.4246 to
   !> 0.4251 mm (±0.05 kN).
   subroutine test_flange_face_steps(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 121
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lib
      real(wp) :: fy(n), second(n - 3)
      integer :: i, steps

      call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      call lateral_second_differences(solver, 6.75_wp, second, error)
      if (allocated(error)) return
      steps = count(second > 400.0_wp)
      call check(error, abs(steps - 9) <= 2 .and. abs(maxval(second) - 1490.0_wp) <= 100.0_wp, &
         message='second differences of F_y,track beyond 400 N: '//str_real(real(steps, wp))// &
         ', largest '//str_real(maxval(second))//' N (doc/kinematics.md: 9, 1.49 kN)')
      if (allocated(error)) return
      ! The normal force falls as the wheel is pressed in (t_y = 6.80210 mm).
      do i = 1, 2
         call solver%solve_kinematic(wheelset_state_type(y_ws=6.8021_wp, v_forward=30000.0_wp, &
            pitch_rate=-30000.0_wp/460.0_wp), contact_load_type(load_vertical_position, &
            merge(0.4246_wp, 0.4251_wp, i == 1)), r, lib)
         if (allocated(lib)) then
            call test_failed(error, lib%message)
            return
         end if
         fy(i) = r%track%fn
      end do
      call check(error, abs(fy(1) - 159.0e3_wp) <= 50.0_wp .and. abs(fy(2) - 158.6e3_wp) <= &
         50.0_wp, message='F_n at dz = 0.4246, 0.4251 mm: '//str_real(fy(1))//', '// &
         str_real(fy(2))//' N (doc/kinematics.md: 159.0, 158.6 kN)')
   end subroutine test_flange_face_steps

   !> |ΔF_i − (ΔF_{i−1} + ΔF_{i+1})/2| of F_y,track (N) over the size(second) + 3 states t_y =
   !> t0, t0 + 0.5 µm, … (yaw 0, pure rolling at 30 m/s, 64.7 kN) with the solver's options;
   !> second(k) is the step from t0 + k·0.5 µm to the next. A failed call fails the test.
   subroutine lateral_second_differences(solver, t0, second, error)
      type(contact_solver_type), intent(inout) :: solver
      real(wp), intent(in) :: t0
      real(wp), intent(out) :: second(:)
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lib
      real(wp) :: fy(size(second) + 3), d(size(second) + 2)
      integer :: i, n

      n = size(fy)
      do i = 1, n
         call solver%solve_kinematic(wheelset_state_type(y_ws=t0 + 0.0005_wp*(i - 1), &
            v_forward=30000.0_wp, pitch_rate=-30000.0_wp/460.0_wp), &
            contact_load_type(load_vertical_force, 64700.0_wp), r, lib)
         if (allocated(lib)) then
            call test_failed(error, 't_y = '//str_real(t0 + 0.0005_wp*(i - 1))//' mm: '// &
               lib%message)
            return
         end if
         fy(i) = r%track%fy
      end do
      d = fy(2:n) - fy(1:n - 1)
      second = abs(d(2:n - 2) - 0.5_wp*(d(1:n - 3) + d(3:n - 1)))
   end subroutine lateral_second_differences

   !> doc/kinematics.md, "Where the steps come from": the same states with the `local-hertz`
   !> reduction. Between 6.75 and 6.81 mm no second difference of F_y,track exceeds 400 N (9
   !> with the coupled reduction); at 6.614850 → 6.614855 mm F_y,track is the same within 10 N
   !> (1.2 kN step coupled) and at 6.61510 → 6.61515 mm, where the table plane changes, it
   !> steps from −44.34 to −42.92 kN (10 kN coupled). Held within 10 N.
   subroutine test_steps_of_the_coupling(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 121
      real(wp), parameter :: t_y(4) = [6.614850_wp, 6.614855_wp, 6.615100_wp, 6.615150_wp], &
         fy(4) = [-44.03e3_wp, -44.03e3_wp, -44.34e3_wp, -42.92e3_wp]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: lib
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      real(wp) :: second(n - 3)
      integer :: i

      call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      if (.not. allocated(lib)) then
         call solver%get_options(normal, tangential)
         normal%reduction = reduction_local_hertz
         call solver%set_options(lib, normal=normal, tangential=tangential)
      end if
      if (allocated(lib)) then
         call test_failed(error, lib%message)
         return
      end if
      call lateral_second_differences(solver, 6.75_wp, second, error)
      if (allocated(error)) return
      call check(error, count(second > 400.0_wp) == 0, message='local-hertz: '// &
         'second differences of F_y,track beyond 400 N between 6.75 and 6.81 mm, the '// &
         'largest '//str_real(maxval(second))//' N (doc/kinematics.md: none)')
      if (allocated(error)) return
      do i = 1, size(t_y)
         call solver%solve_kinematic(wheelset_state_type(y_ws=t_y(i), v_forward=30000.0_wp, &
            pitch_rate=-30000.0_wp/460.0_wp), contact_load_type(load_vertical_force, &
            64700.0_wp), r, lib)
         if (allocated(lib)) then
            call test_failed(error, lib%message)
            return
         end if
         call check(error, abs(r%track%fy - fy(i)) <= 10.0_wp, message='local-hertz at t_y = '// &
            str_real(t_y(i))//' mm: F_y,track '//str_real(r%track%fy)//' N, documented '// &
            str_real(fy(i)))
         if (allocated(error)) return
      end do
   end subroutine test_steps_of_the_coupling

   !> doc/kinematics.md, "One solution, steep in the strips": at t_y = 6.8024 mm, Δz 0.4245 →
   !> 0.4250 mm, the coupled strips' interval stretches by 0.26 mm while their total load changes
   !> by 0.04 %, and the strips over the fillet (y = 0.35 … 0.9 mm from the first contact)
   !> change their loads by 21–44 %, up and down in turn.
   subroutine test_steep_coupling(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(contact_fields_type) :: f
      type(lib_error), allocatable :: lib
      real(wp) :: width(2), total(2), change
      real(wp), allocatable :: load(:, :)
      logical, allocatable :: fillet(:)
      integer :: i, n

      call solver%init('builtin:S1002', 'builtin:UIC60', lib)
      do i = 1, 2
         if (.not. allocated(lib)) call solver%solve_kinematic(wheelset_state_type( &
            y_ws=6.8024_wp, v_forward=30000.0_wp, pitch_rate=-30000.0_wp/460.0_wp), &
            contact_load_type(load_vertical_position, merge(0.4245_wp, 0.4250_wp, i == 1)), r, &
            lib, fields=f)
         if (allocated(lib)) then
            call test_failed(error, lib%message)
            return
         end if
         n = f%normal(1)%n_strips
         if (.not. allocated(load)) then
            allocate (load(n, 2))
            fillet = f%normal(1)%y(1:n) >= 0.35_wp .and. f%normal(1)%y(1:n) <= 0.9_wp
         end if
         load(:, i) = f%normal(1)%strip_load(1:n)
         width(i) = n*f%normal(1)%dy
         total(i) = sum(load(:, i))
      end do
      change = minval(abs(load(:, 2) - load(:, 1))/load(:, 1), mask=fillet)
      call check(error, abs(width(2) - width(1) - 0.26_wp) <= 0.01_wp .and. &
         abs(total(2)/total(1) - 1.0_wp) <= 5.0e-4_wp .and. change >= 0.2_wp .and. &
         maxval(abs(load(:, 2) - load(:, 1))/load(:, 1), mask=fillet) <= 0.45_wp .and. &
         count(fillet) >= 6, message='interval '//str_real(width(1))//' -> '// &
         str_real(width(2))//' mm, total '//str_real(total(1))//' -> '//str_real(total(2))// &
         ' N, smallest change of a fillet strip '//str_real(change)// &
         ' (doc/kinematics.md: +0.26 mm, 0.04 %, 21-44 %)')
   end subroutine test_steep_coupling

end module test_kinematic_balance
