!> Driver for instruction counts of the kinematic call (doc/performance.md, "Speed of the
!> kinematic call"): one set-up call, then `solve_kinematic` on the first n states of a
!> trajectory of the benchmark (shcontact-bench's hunting and flange trajectories, or the
!> hunting velocities at the fixed position of state 200), in order. Run it under callgrind with
!> the collection toggled on `solve_kinematic`, once with n = 0 and once with n = 1000; the
!> difference divided by n is the count per call, the set-up call (and the yaw table it builds)
!> left out:
!>
!>     fpm run --profile release --example shcontact-kinematic-count --runner \
!>        "valgrind --tool=callgrind --collect-atstart=no --toggle-collect='*solve_kinematic'" \
!>        -- hunting default 1000
!>
!> Arguments: hunting | flange | fixed, default | vehicle (the preset), n (default 1000), and
!> optionally the contact option table_step (mm; default: the preset's). It prints n, the failed
!> calls, the largest relative miss of the vertical load |F_z − 64.7 kN|/64.7 kN over the
!> solved calls and the sum of the track-frame F_y (N) as a check. Robustness with other table
!> steps (doc/kinematics.md):
!>
!>     fpm run --profile release --example shcontact-kinematic-count -- flange vehicle 1000 0.04
!>
!> With `deviation` in place of the preset it solves the n states with the default and with the
!> vehicle preset (the fourth argument, if given, its strip count instead of 60) and prints the
!> largest |Δf| of f_x, f_y (ΣF/(μΣF_n) over the loaded patches, contact planes), the states
!> beyond 0.01 and the worst state's patches (doc/performance.md, "The preset's deviation"):
!>
!>     fpm run --profile release --example shcontact-kinematic-count -- flange deviation 1000
!>
!> With `ty-scan T0 T1 N` it solves N + 1 states from t_y = T0 to T1 (yaw 0, pure rolling at
!> 30 m/s) and lists where F_y,track leaves its neighbours' trend by more than 300 N
!> (doc/kinematics.md, "Not continuous at the flange root"):
!>
!>     fpm run --profile release --example shcontact-kinematic-count -- ty-scan 5 9 8000
!>
!> A fifth argument names the normal reduction (`local-hertz`; default `coupled`):
!>
!>     fpm run --profile release --example shcontact-kinematic-count -- ty-scan 6.6 7 800 local-hertz
!>
!> With N ≤ 20 it also prints every state (F_y,track, ΣF_n, Δz, the main patch's table plane and
!> reference point).
!>
!> With `scan` it solves state n at prescribed vertical positions (doc/kinematics.md, "The
!> patch's reference point"):
!>
!>     fpm run --profile release --example shcontact-kinematic-count -- flange scan 789 0.1715 0.1725 10
program kinematic_count
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact, only: wp, error_type, contact_solver_type, contact_load_type, &
      contact_result_type, wheelset_state_type, load_vertical_force, set_preset, &
      contact_options_type, load_vertical_position, normal_options_type, &
      tangential_options_type, new_normal_options
   use bench_moving, only: hunting_states, flange_states, trajectory_forces, values_per_state
   implicit none
   !> Vertical wheel load of the benchmark (N).
   real(wp), parameter :: wheel_load = 64700.0_wp
   type(contact_solver_type) :: solver
   type(wheelset_state_type), allocatable :: states(:)
   type(error_type), allocatable :: error
   type(contact_result_type) :: result
   character(len=32) :: which, preset, count_text, step_text
   type(contact_options_type) :: contact
   integer :: n, stat, failed
   real(wp) :: checksum, miss, table_step

   call get_command_argument(1, which)
   call get_command_argument(2, preset)
   call get_command_argument(3, count_text)
   call get_command_argument(4, step_text)
   if (trim(which) == 'ty-scan') then
      call solver%init('builtin:S1002', 'builtin:UIC60', error)
      if (allocated(error)) call fail(error)
      call scan_reduction(solver)
      call lateral_scan(solver, preset, count_text, step_text)
      stop
   end if
   n = 1000
   if (len_trim(count_text) > 0) then
      read (count_text, *, iostat=stat) n
      if (stat /= 0 .or. n < 0 .or. n > 1000) call usage()
   end if
   select case (trim(which))
   case ('flange')
      states = flange_states(1000)
   case ('hunting', 'fixed')
      states = hunting_states(1000)
      if (trim(which) == 'fixed') then
         states%y_ws = states(200)%y_ws
         states%yaw = states(200)%yaw
      end if
   case default
      call usage()
   end select
   call solver%init('builtin:S1002', 'builtin:UIC60', error)
   if (allocated(error)) call fail(error)
   if (trim(preset) == 'scan') then
      if (n < 1) call usage()
      call scan(solver, states(n))
      stop
   end if
   if (trim(preset) == 'deviation') then
      call deviation(solver, states(1:n))
      stop
   end if
   select case (trim(preset))
   case ('vehicle')
      call set_preset(solver, 'vehicle', error)
      if (allocated(error)) call fail(error)
   case ('default', '')
   case default
      call usage()
   end select
   if (len_trim(step_text) > 0) then
      read (step_text, *, iostat=stat) table_step
      if (stat /= 0) call usage()
      contact = solver%get_contact_options()
      contact%table_step = table_step
      call solver%set_track(error, contact_options=contact)
      if (allocated(error)) call fail(error)
   end if
   call solver%solve_kinematic(states(1), contact_load_type(load_vertical_force, wheel_load), &
      result, error)
   if (allocated(error)) call fail(error)
   call loop(solver, states(1:n), failed, checksum, miss)
   write (output_unit, '(a,i0,a,i0,a,es9.2,a,es24.16)') 'calls ', n, ', failed ', failed, &
      ', largest relative miss of F_z ', miss, ', sum of F_y (N) ', checksum

contains

   !> The counted calls.
   subroutine loop(solver, states, failed, checksum, miss)
      type(contact_solver_type), intent(inout) :: solver
      type(wheelset_state_type), intent(in) :: states(:)
      integer, intent(out) :: failed
      real(wp), intent(out) :: checksum, miss
      type(error_type), allocatable :: error
      type(contact_result_type) :: result
      integer :: i

      failed = 0
      checksum = 0.0_wp
      miss = 0.0_wp
      do i = 1, size(states)
         call solver%solve_kinematic(states(i), contact_load_type(load_vertical_force, &
            wheel_load), result, error)
         if (allocated(error)) then
            failed = failed + 1
         else
            checksum = checksum + result%track%fy
            miss = max(miss, abs(-result%track%fz - wheel_load)/wheel_load)
         end if
      end do
   end subroutine loop

   !> The preset's f_x, f_y against the default's on the states (module text).
   subroutine deviation(solver, states)
      type(contact_solver_type), intent(inout) :: solver
      type(wheelset_state_type), intent(in) :: states(:)
      real(wp), allocatable :: reference(:), preset(:)
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      real(wp) :: d, worst
      integer :: i, beyond, failed, i_worst

      reference = trajectory_forces(solver, states)
      call set_preset(solver, 'vehicle', error)
      if (allocated(error)) call fail(error)
      if (len_trim(step_text) > 0) then
         ! The preset with another strip count.
         call solver%get_options(normal, tangential)
         read (step_text, *, iostat=stat) normal%n_strips
         if (stat /= 0) call usage()
         call solver%set_options(error, normal=normal, tangential=tangential)
         if (allocated(error)) call fail(error)
      end if
      preset = trajectory_forces(solver, states)
      worst = 0.0_wp
      i_worst = 0
      beyond = 0
      failed = 0
      do i = 1, size(states)
         associate (r => reference(values_per_state*(i - 1) + 5:values_per_state*i), &
               p => preset(values_per_state*(i - 1) + 5:values_per_state*i))
            if (any(r == huge(1.0_wp)) .or. any(p == huge(1.0_wp))) then
               failed = failed + 1
               cycle
            end if
            d = maxval(abs(p - r))
         end associate
         if (d > 0.01_wp) beyond = beyond + 1
         if (d > worst) then
            worst = d
            i_worst = i
         end if
      end do
      write (output_unit, '(a,i0,a,i0,a,f7.4,a,i0,a,i0)') 'states ', size(states), ', failed ', &
         failed, ', largest |df| ', worst, ' (state ', i_worst, '), beyond 0.01: ', beyond
      if (i_worst > 0) then
         call show(solver, states(i_worst), 'preset')
         call set_preset(solver, 'default', error)
         if (allocated(error)) call fail(error)
         call show(solver, states(i_worst), 'default')
      end if
   end subroutine deviation

   !> The loaded patches of one state: γ₀ (rad), F_n (N), f_x, f_y.
   subroutine show(solver, state, label)
      type(contact_solver_type), intent(inout) :: solver
      type(wheelset_state_type), intent(in) :: state
      character(len=*), intent(in) :: label
      integer :: k
      call solver%solve_kinematic(state, contact_load_type(load_vertical_force, wheel_load), &
         result, error)
      if (allocated(error)) call fail(error)
      do k = 1, result%n_loaded
         write (output_unit, '(2x,a,a,i0,a,f9.5,a,f10.1,a,2f9.5)') label, ' patch ', k, &
            ': gamma0 ', result%patch(k)%gamma0, ' rad, F_n ', result%patch(k)%fn, &
            ' N, f_x, f_y ', result%patch(k)%fx/(0.3_wp*result%patch(k)%fn), &
            result%patch(k)%fy/(0.3_wp*result%patch(k)%fn)
      end do
   end subroutine show

   !> `scan`: state n (the third argument) at the vertical positions Δz = dz0 … dz1 (mm) in m
   !> steps (arguments 4–6; a seventh `vehicle` takes the preset): Δz, the carried vertical
   !> force C (N), then per loaded patch γ₀ (rad), F_n (N), f_x, f_y.
   subroutine scan(solver, state)
      type(contact_solver_type), intent(inout) :: solver
      type(wheelset_state_type), intent(in) :: state
      character(len=32) :: a4, a5, a6, a7
      real(wp) :: dz0, dz1, dz
      integer :: m, j, k
      call get_command_argument(4, a4)
      call get_command_argument(5, a5)
      call get_command_argument(6, a6)
      call get_command_argument(7, a7)
      read (a4, *, iostat=stat) dz0
      if (stat == 0) read (a5, *, iostat=stat) dz1
      if (stat == 0) read (a6, *, iostat=stat) m
      if (stat /= 0 .or. state%v_forward <= 0.0_wp) call usage()
      if (trim(a7) == 'vehicle') call set_preset(solver, 'vehicle', error)
      if (allocated(error)) call fail(error)
      do j = 0, m
         dz = dz0 + (dz1 - dz0)*j/max(m, 1)
         call solver%solve_kinematic(state, contact_load_type(load_vertical_position, dz), &
            result, error)
         if (allocated(error)) then
            write (output_unit, '(f12.7,1x,a)') dz, error%message
            cycle
         end if
         write (output_unit, '(f12.7,f12.2,99(1x,f9.5,f10.1,2f9.5))') dz, -result%track%fz, &
            (result%patch(k)%gamma0, result%patch(k)%fn, &
            result%patch(k)%fx/(0.3_wp*result%patch(k)%fn), &
            result%patch(k)%fy/(0.3_wp*result%patch(k)%fn), k = 1, result%n_loaded)
      end do
   end subroutine scan

   !> F_y,track along t_y = t0 + (t1 − t0) i/n, i = 0 … n (yaw 0, pure rolling at 30 m/s,
   !> 64.7 kN): the failed calls and every place where F_y,track leaves its neighbours' trend by
   !> more than 300 N, |ΔF_i − (ΔF_{i−1} + ΔF_{i+1})/2| with ΔF_i = F_{i+1} − F_i
   !> (doc/kinematics.md, "Not continuous at the flange root").
   subroutine lateral_scan(solver, t0_text, t1_text, n_text)
      type(contact_solver_type), intent(inout) :: solver
      character(len=*), intent(in) :: t0_text, t1_text, n_text
      real(wp), parameter :: threshold = 300.0_wp
      real(wp), allocatable :: fy(:), t(:)
      real(wp) :: t0, t1, second
      integer :: m, i, failed, places, stat(3)

      read (t0_text, *, iostat=stat(1)) t0
      read (t1_text, *, iostat=stat(2)) t1
      read (n_text, *, iostat=stat(3)) m
      if (any(stat /= 0)) call usage()
      if (m < 1 .or. .not. t1 > t0) call usage()
      allocate (fy(0:m), t(0:m))
      failed = 0
      do i = 0, m
         t(i) = t0 + (t1 - t0)*real(i, wp)/real(m, wp)
         call solver%solve_kinematic(wheelset_state_type(y_ws=t(i), v_forward=30000.0_wp, &
            pitch_rate=-30000.0_wp/460.0_wp), contact_load_type(load_vertical_force, &
            wheel_load), result, error)
         if (allocated(error)) then
            failed = failed + 1
            fy(i) = huge(1.0_wp)
            deallocate (error)
         else
            fy(i) = result%track%fy
            ! A short scan lists its states (doc/kinematics.md's table).
            if (m <= 20) write (output_unit, '(a,f10.6,a,f9.2,a,f8.2,a,f7.4,a,f7.3,a,f8.2)') &
               '  t_y ', t(i), ' mm: F_y,track ', 1.0e-3_wp*fy(i), ' kN, F_n ', &
               1.0e-3_wp*result%track%fn, ' kN, dz ', result%dz, ' mm, plane ', &
               result%patch(1)%gamma_plane, ' rad, y_track ', result%patch(1)%y_track
         end if
      end do
      places = 0
      do i = 1, m - 2
         if (any(fy(i - 1:i + 2) == huge(1.0_wp))) cycle
         second = (fy(i + 1) - fy(i)) - 0.5_wp*((fy(i) - fy(i - 1)) + (fy(i + 2) - fy(i + 1)))
         if (abs(second) <= threshold) cycle
         places = places + 1
         write (output_unit, '(a,f10.5,a,f10.5,a,f9.1,a)') '  t_y ', t(i), ' -> ', t(i + 1), &
            ' mm: ', second, ' N off the trend'
      end do
      write (output_unit, '(a,i0,a,i0,a,i0)') 'states ', m + 1, ', failed ', failed, &
         ', second differences of F_y,track beyond 300 N: ', places
   end subroutine lateral_scan

   !> `ty-scan`'s optional fifth argument: the normal reduction by its `&normal` name
   !> (`coupled`, the default, or `local-hertz`).
   subroutine scan_reduction(solver)
      type(contact_solver_type), intent(inout) :: solver
      type(normal_options_type) :: normal, chosen
      type(tangential_options_type) :: tangential
      character(len=32) :: name

      call get_command_argument(5, name)
      if (len_trim(name) == 0) return
      call new_normal_options(chosen, error, reduction=trim(name))
      if (allocated(error)) call fail(error)
      call solver%get_options(normal, tangential)
      normal%reduction = chosen%reduction
      call solver%set_options(error, normal=normal, tangential=tangential)
      if (allocated(error)) call fail(error)
   end subroutine scan_reduction

   subroutine usage()
      write (error_unit, '(a)') 'usage: shcontact-kinematic-count hunting|flange|fixed '// &
         '[default|vehicle|deviation|scan] [n = 0..1000] '// &
         '[table_step mm | strips | dz0 dz1 steps [vehicle]]', &
         '       shcontact-kinematic-count ty-scan t0 t1 n [reduction]   (mm; n + 1 states)'
      stop 1
   end subroutine usage

   subroutine fail(error)
      type(error_type), intent(in) :: error
      write (error_unit, '(a)') 'shcontact-kinematic-count: '//error%message
      stop 5
   end subroutine fail

end program kinematic_count
