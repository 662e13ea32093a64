!> Prescribed creepages and a prescribed normal force on a wheel with several patches (issue 28
!> item 3, doc/lobes.md). The creepages are given at the first (deepest) patch's reference point
!> and every other loaded patch gets the rigid slip of the same wheel at its own reference point
!> (shcontact_pipeline_stages's carry_creepage_stage); the load mode shared normal force
!> (load_shared_force) shares N among the patches through one rigid vertical approach,
!> Σ_k N_k = N (share_normal_force), while the plain normal force loads the first patch. Through the solver
!> object at Y_WS = 5.0 and 5.3 mm on the built-in S1002 / UIC60 1:40 (a tread lobe and a
!> gauge-corner lobe): each patch's creepages against the closed form, each patch's forces
!> against its own tangential solve with those creepages, the right and the left wheel; the
!> normal force's sum, its equality with the vertical load that gives the same approach, and
!> the single-patch solve where only the first patch touches.
module test_prescribed_patches
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_real
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_geometry_track, only: side_left, side_right
   use shcontact_tangential_options, only: tangential_options_type, spin_additive, spin_uniform
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_solver, only: solve_tangential
   use shcontact_core_material, only: material_type
   use shcontact_normal_options, only: normal_options_type
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_pipeline_stages, only: shared_force_rtol
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_input_config, only: case_config_type, case_point_type, load_config
   use shcontact_case_result, only: case_result_type
   use shcontact_case_runner, only: run_setup_type, stage_type, prepare_run, solve_geometry, &
      solve_stage, solve_case, case_workspace_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, &
      contact_result_type, contact_fields_type, load_vertical_force, load_normal_force, &
      load_shared_force
   implicit none
   private
   public :: collect_prescribed_patches

   !> The two-lobe positions (mm) and the vertical load (N).
   real(wp), parameter :: positions(2) = [5.0_wp, 5.3_wp]
   real(wp), parameter :: f_z = 64.7e3_wp
   !> Creepages with spin (ν_x, ν_y, φ in rad/mm: 1.5 1/m).
   type(creepage_type), parameter :: given = creepage_type(1.0e-3_wp, 0.5e-3_wp, 1.5e-3_wp)

contains

   !> Collect the tests.
   subroutine collect_prescribed_patches(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [new_unittest('uniform_rigid_slip_closed_form', test_uniform), &
         new_unittest('no_spin_same_creepages', test_no_spin), &
         new_unittest('additive_rigid_slip_closed_form', test_additive), &
         new_unittest('patch_forces_use_carried_creepages', test_forces), &
         new_unittest('left_wheel_mirrors_right', test_left), &
         new_unittest('shared_force_sum', test_force_sum), &
         new_unittest('shared_force_is_a_common_approach', test_force_vertical), &
         new_unittest('shared_force_single_patch_unchanged', test_force_single), &
         new_unittest('program_shared_force_equals_library', test_program_shared), &
         new_unittest('vertical_load_carried_by_the_strips', test_strips_vertical)]
   end subroutine collect_prescribed_patches

   !> A solver on the built-in profiles for one wheel side and spin model.
   subroutine new_solver(solver, side, model, error)
      type(contact_solver_type), intent(out) :: solver
      integer, intent(in) :: side, model
      type(error_type), allocatable, intent(out) :: error
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: err
      options%spin_model = model
      call solver%init('builtin:S1002', 'builtin:UIC60', err, side=side, &
         tangential_options=options)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine new_solver

   !> Solve one two-lobe position; an error unless both patches are loaded.
   subroutine solve_two(solver, t_y, creepage, result, error, fields)
      type(contact_solver_type), intent(inout) :: solver
      real(wp), intent(in) :: t_y
      type(creepage_type), intent(in) :: creepage
      type(contact_result_type), intent(out) :: result
      type(error_type), allocatable, intent(out) :: error
      type(contact_fields_type), intent(inout), optional :: fields
      type(lib_error), allocatable :: err
      call solver%solve(t_y, 0.0_wp, contact_load_type(load_vertical_force, f_z), creepage, &
         result, err, fields)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, result%n_loaded == 2 .and. result%patch(1)%fn > 1000.0_wp .and. &
         result%patch(2)%fn > 1000.0_wp, message='t_y = '//str_real(t_y)// &
         ' mm: two loaded patches expected')
   end subroutine solve_two

   !> Lateral distance y_2 of patch 2's reference point from patch 1's in patch 1's contact
   !> plane (mm, towards the field side; the results' y_track is the track's, so the left
   !> wheel's is mirrored).
   pure real(wp) function lateral_distance(result, side) result(y2)
      type(contact_result_type), intent(in) :: result
      integer, intent(in) :: side
      associate (p1 => result%patch(1), p2 => result%patch(2))
         y2 = side*(p2%y_track - p1%y_track)*cos(p1%gamma_plane) + &
            (p2%z_track - p1%z_track)*sin(p1%gamma_plane)
      end associate
   end function lateral_distance

   !> Default spin model ('uniform'): patch 1 gets the creepages as given (bit for bit), patch 2
   !> ν_x − φ y_2, ν_y, φ with y_2 its lateral distance in patch 1's plane (the patches are
   !> 8–12 mm apart, so φ y_2 is about as large as ν_x).
   subroutine test_uniform(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      real(wp) :: y2
      integer :: ip

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      do ip = 1, size(positions)
         call solve_two(solver, positions(ip), given, r, error)
         if (allocated(error)) return
         y2 = lateral_distance(r, side_right)
         call check(error, abs(y2) > 5.0_wp .and. abs(y2) < 15.0_wp, message= &
            'lateral distance of the patches '//str_real(y2)//' mm, expected 5-15 mm')
         if (allocated(error)) return
         call check(error, r%patch(1)%nu_x == given%nu_x .and. r%patch(1)%nu_y == given%nu_y &
            .and. r%patch(1)%phi == given%phi, message='patch 1 should get the creepages as given')
         if (allocated(error)) return
         call check(error, r%patch(2)%nu_x, given%nu_x - given%phi*y2, thr=1.0e-15_wp, &
            message='patch 2: nu_x - phi y_2')
         if (allocated(error)) return
         call check(error, r%patch(2)%nu_y == given%nu_y .and. r%patch(2)%phi == given%phi, &
            message='patch 2: nu_y and phi as given under the uniform spin model')
         if (allocated(error)) return
      end do
   end subroutine test_uniform

   !> Pure longitudinal creepage, φ = 0: both patches get the same creepages, bit for bit.
   subroutine test_no_spin(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(creepage_type), parameter :: pure = creepage_type(1.0e-3_wp, 0.0_wp, 0.0_wp)
      integer :: ip

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      do ip = 1, size(positions)
         call solve_two(solver, positions(ip), pure, r, error)
         if (allocated(error)) return
         call check(error, all(r%patch(1:2)%nu_x == pure%nu_x) .and. &
            all(r%patch(1:2)%nu_y == 0.0_wp) .and. all(r%patch(1:2)%phi == 0.0_wp), &
            message='pure longitudinal creepage: both patches should get it unchanged')
         if (allocated(error)) return
      end do
   end subroutine test_no_spin

   !> Spin model 'additive': the spin changes with the contact angle as a rolling wheel's does,
   !> φ_2 = φ + (sin γ_2 − sin γ_1)/r_1, ν_x,2 = ν_x − φ y_2 − ρ with the geometric remainder
   !> ρ = (r_2 − r_1)/r_1 − y_2 sin γ_1/r_1, and ν_y,2 = ν_y cos γ_1/cos γ_2 (doc/theory.md
   !> §6.2, each strip's rule applied at patch 2's reference point).
   subroutine test_additive(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      real(wp) :: y2, rho
      integer :: ip

      call new_solver(solver, side_right, spin_additive, error)
      if (allocated(error)) return
      do ip = 1, size(positions)
         call solve_two(solver, positions(ip), given, r, error)
         if (allocated(error)) return
         y2 = lateral_distance(r, side_right)
         associate (p1 => r%patch(1), p2 => r%patch(2))
            rho = (p2%r0 - p1%r0)/p1%r0 - y2*sin(p1%gamma0)/p1%r0
            call check(error, p1%nu_x == given%nu_x .and. p1%nu_y == given%nu_y .and. &
               p1%phi == given%phi, message='additive: patch 1 gets the creepages as given')
            if (allocated(error)) return
            call check(error, p2%phi, given%phi + (sin(p2%gamma0) - sin(p1%gamma0))/p1%r0, &
               thr=1.0e-15_wp, message='additive: patch 2 phi')
            if (allocated(error)) return
            call check(error, p2%nu_x, given%nu_x - given%phi*y2 - rho, thr=1.0e-15_wp, &
               message='additive: patch 2 nu_x')
            if (allocated(error)) return
            call check(error, p2%nu_y, given%nu_y*cos(p1%gamma0)/cos(p2%gamma0), &
               thr=1.0e-15_wp, message='additive: patch 2 nu_y')
            if (allocated(error)) return
            ! The contact angles differ by 0.1-0.2 rad: the spin changes by 2e-4 rad/mm.
            call check(error, abs(p2%phi - given%phi) > 1.0e-4_wp, message= &
               'additive: the spin of patch 2 should differ from the given one')
            if (allocated(error)) return
         end associate
      end do
   end subroutine test_additive

   !> Each patch's forces are its own tangential solve (shcontact_tangential_solver) with its
   !> carried creepages, bit for bit; patch 2's differ from a solve with the creepages as given.
   subroutine test_forces(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(contact_fields_type), allocatable :: fields
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: own, as_given
      type(tangential_options_type) :: options
      type(lib_error), allocatable :: err
      integer :: ip, k

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      allocate (fields)
      do ip = 1, size(positions)
         call solve_two(solver, positions(ip), given, r, error, fields)
         if (allocated(error)) return
         do k = 1, 2
            call solve_tangential(ws, fields%normal(k), material_type(), creepage_type( &
               r%patch(k)%nu_x, r%patch(k)%nu_y, r%patch(k)%phi), options, own, err)
            if (.not. allocated(err)) call solve_tangential(ws, fields%normal(k), &
               material_type(), given, options, as_given, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            call check(error, own%fx == r%patch(k)%fx .and. own%fy == r%patch(k)%fy, &
               message='patch forces should be the solve with its carried creepages')
            if (allocated(error)) return
         end do
         call check(error, abs(as_given%fx - r%patch(2)%fx) > 0.01_wp*abs(as_given%fx), &
            message='patch 2: the carried creepages should change its F_x')
         if (allocated(error)) return
      end do
   end subroutine test_forces

   !> The left wheel at −Y_WS is the right wheel's mirror: its patches get the same creepages
   !> (the lateral distance is measured towards each wheel's own field side).
   subroutine test_left(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: right, left
      type(contact_result_type) :: rr, rl
      integer :: ip

      call new_solver(right, side_right, spin_uniform, error)
      if (.not. allocated(error)) call new_solver(left, side_left, spin_uniform, error)
      if (allocated(error)) return
      do ip = 1, size(positions)
         call solve_two(right, positions(ip), given, rr, error)
         if (.not. allocated(error)) call solve_two(left, -positions(ip), given, rl, error)
         if (allocated(error)) return
         call check(error, rl%patch(2)%nu_x, rr%patch(2)%nu_x, thr=1.0e-12_wp, &
            message='left wheel: patch 2 nu_x as the right wheel''s')
         if (allocated(error)) return
         call check(error, lateral_distance(rl, side_left), lateral_distance(rr, side_right), &
            thr=1.0e-9_wp, message='left wheel: the same lateral distance')
         if (allocated(error)) return
      end do
   end subroutine test_left

   !> A shared normal force N = 64.7 kN at the two-lobe positions and at the headline position
   !> (4.733 mm, where a second patch carries 2.5 kN): both patches loaded, Σ F_n = N to
   !> shared_force_rtol (1e-9), and the wheel's joined contact holds both (wheel F_n = N). The
   !> plain normal force (load_normal_force) still loads the first patch alone, with F_n = N.
   subroutine test_force_sum(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: t_y(3) = [5.0_wp, 5.3_wp, 4.733_wp]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: err
      integer :: ip

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      do ip = 1, size(t_y)
         call solver%solve(t_y(ip), 0.0_wp, contact_load_type(load_shared_force, f_z), given, &
            r, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, r%n_loaded == 2 .and. all(r%patch(1:2)%fn > 1000.0_wp), &
            message='t_y = '//str_real(t_y(ip))//' mm: a normal force should load both patches')
         if (allocated(error)) return
         call check(error, abs(r%track%fn - f_z) <= shared_force_rtol*f_z .and. &
            abs(r%patch(1)%fn + r%patch(2)%fn - f_z) <= shared_force_rtol*f_z, &
            message='t_y = '//str_real(t_y(ip))//' mm: sum of the normal forces '// &
            str_real(r%track%fn)//' N, expected 64700 N')
         if (allocated(error)) return
         call check(error, r%wheel%n_members == 2 .and. abs(r%wheel%fn - f_z) <= &
            shared_force_rtol*f_z, message='the joined contact should hold the normal force')
         if (allocated(error)) return
         call solver%solve(t_y(ip), 0.0_wp, contact_load_type(load_normal_force, f_z), given, &
            r, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, r%n_loaded == 1 .and. abs(r%patch(1)%fn - f_z) <= 1.0e-10_wp*f_z, &
            message='the plain normal force should load the first patch alone')
         if (allocated(error)) return
      end do
   end subroutine test_force_sum

   !> A vertical load is carried by the strips (doc/theory.md §4.6): without creep forces the
   !> track's F_z is −F_z to 1e-8 on the tread, at the flange root and on the flange, also at
   !> 6.615–6.65 mm, where one patch spans root and flange with its first contact on the flange
   !> and the patch-plane balance carried 2.25 F_z (6.65 mm: F_n 189 kN; now 93.4 kN).
   subroutine test_strips_vertical(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: t_y(6) = [0.0_wp, 3.0_wp, 6.0_wp, 6.61515_wp, 6.65_wp, 8.5_wp]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(lib_error), allocatable :: err
      integer :: ip

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      do ip = 1, size(t_y)
         call solver%solve(t_y(ip), 0.0_wp, contact_load_type(load_vertical_force, f_z), &
            creepage_type(0.0_wp, 0.0_wp, 0.0_wp), r, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, -r%track%fz, f_z, rel=.true., thr=1.0e-8_wp, &
            message='t_y = '//str_real(t_y(ip))//' mm: the track F_z')
         if (allocated(error)) return
         if (t_y(ip) > 6.6_wp .and. t_y(ip) < 6.7_wp) then
            call check(error, r%track%fn < 1.5_wp*f_z, message='t_y = '//str_real(t_y(ip))// &
               ' mm: F_n '//str_real(r%track%fn)//' N at the flange root')
            if (allocated(error)) return
         end if
         if (t_y(ip) == 6.65_wp) then
            ! doc/theory.md §4.6 quotes it.
            call check(error, r%track%fn, 93.4e3_wp, rel=.true., thr=1.0e-3_wp, &
               message='F_n at 6.65 mm')
            if (allocated(error)) return
         end if
      end do
   end subroutine test_strips_vertical

   !> The shared normal force is the vertical load's solution: the patches move as one rigid
   !> body, so a vertical load F_z equal to the strips' vertical force of the shared-force
   !> solution (its track F_z without creep forces) gives the same patch loads, approaches and
   !> vertical approach Δz to a relative 1e-7.
   subroutine test_force_vertical(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: rf, rv
      type(lib_error), allocatable :: err
      real(wp) :: vertical
      integer :: ip, k

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      do ip = 1, size(positions)
         ! Without creep forces the track's F_z is the strips' vertical force, which a
         ! vertical load matches (doc/theory.md §4.6).
         call solver%solve(positions(ip), 0.0_wp, contact_load_type(load_shared_force, f_z), &
            creepage_type(0.0_wp, 0.0_wp, 0.0_wp), rf, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         vertical = -rf%track%fz
         call solver%solve(positions(ip), 0.0_wp, contact_load_type(load_vertical_force, &
            vertical), creepage_type(0.0_wp, 0.0_wp, 0.0_wp), rv, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         do k = 1, 2
            call check(error, rv%patch(k)%fn, rf%patch(k)%fn, rel=.true., thr=1.0e-7_wp, &
               message='patch load: normal force vs vertical load')
            if (allocated(error)) return
            call check(error, rv%patch(k)%approach, rf%patch(k)%approach, rel=.true., &
               thr=1.0e-7_wp, message='patch approach: normal force vs vertical load')
            if (allocated(error)) return
         end do
         call check(error, rv%dz, rf%dz, rel=.true., thr=1.0e-7_wp, &
            message='vertical approach: normal force vs vertical load')
         if (allocated(error)) return
      end do
   end subroutine test_force_vertical

   !> Where only the first patch touches under the shared normal force (Y_WS = 4.5 mm: two candidates,
   !> the second above the rail at the first's approach) and where the search finds one patch
   !> (0 and 2 mm), the solver's result is the single-patch solve (solve_load on its first
   !> patch's geometry) bit for bit: one loaded patch, the same load, approach, area and peak
   !> pressure.
   subroutine test_force_single(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: t_y(3) = [4.5_wp, 0.0_wp, 2.0_wp]
      integer, parameter :: candidates(3) = [2, 1, 1]
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(contact_fields_type), allocatable :: fields
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: alone
      type(lib_error), allocatable :: err
      integer :: ip

      call new_solver(solver, side_right, spin_uniform, error)
      if (allocated(error)) return
      allocate (fields)
      do ip = 1, size(t_y)
         call solver%solve(t_y(ip), 0.0_wp, contact_load_type(load_shared_force, f_z), given, &
            r, err, fields)
         if (.not. allocated(err)) call prepare_normal_contact(contact, fields%geometry(1), &
            normal_options_type(), material_type(), err)
         if (.not. allocated(err)) call solve_load(contact, f_z, alone, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, r%n_patches == candidates(ip) .and. r%n_loaded == 1, &
            message='t_y = '//str_real(t_y(ip))//' mm: expected one loaded patch of '// &
            achar(48 + candidates(ip)))
         if (allocated(error)) return
         call check(error, r%patch(1)%fn == alone%load .and. r%patch(1)%approach == &
            alone%approach .and. r%patch(1)%area == alone%area .and. r%patch(1)%p_max == &
            alone%p_max, message='t_y = '//str_real(t_y(ip))//' mm: the single-patch solve '// &
            'bit for bit expected')
         if (allocated(error)) return
      end do
   end subroutine test_force_single

   !> The program's `&load mode = 'shared-force'` (its case runner, as a run solves a case) is
   !> the library's load_shared_force bit for bit at Y_WS = 5.0 mm with the seed's creepages:
   !> two loaded patches, the totals, the main patch and the joined contact.
   subroutine test_program_shared(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: solver
      type(contact_result_type) :: r
      type(case_config_type) :: config
      type(case_point_type) :: point
      type(run_setup_type) :: setup
      type(stage_type) :: stage
      type(patch_geometry_type), allocatable :: geometry(:)
      type(case_workspace_type) :: ws
      type(tangential_patch_type), allocatable :: tangential(:)
      type(case_result_type) :: app
      type(lib_error), allocatable :: err

      call load_config('', [character(len=40) :: 'load%mode=shared-force', &
         'position%t_y=5.0'], config, err)
      if (.not. allocated(err)) call prepare_run(config, setup, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      point = config%case_point(1)
      call solve_geometry(setup, point, geometry, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call solve_stage(setup, point, geometry, stage)
      call solve_case(setup, point, stage, 1, ws, tangential, app, .false.)
      call check(error, app%summary%stat, 0, message='the case runner failed')
      if (allocated(error)) return
      call solver%init('builtin:S1002', 'builtin:UIC60', err)
      if (.not. allocated(err)) call solver%solve(5.0_wp, 0.0_wp, contact_load_type( &
         load_shared_force, point%normal_force), creepage_type(point%nu_x, point%nu_y, &
         point%phi), r, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, app%summary%n_loaded == 2 .and. r%n_loaded == 2, &
         message='shared-force: two loaded patches expected')
      if (allocated(error)) return
      call check(error, all([app%summary%fn_total, app%summary%fx_total, app%summary%fx, &
         app%summary%fy, app%summary%fn, app%summary%wheel%fx_norm] == [r%track%fn, &
         r%track%fx, r%main%fx, r%main%fy, r%main%fn, r%wheel%fx_norm]), &
         message='the program''s shared force differs from the library''s')
   end subroutine test_program_shared

end module test_prescribed_patches
