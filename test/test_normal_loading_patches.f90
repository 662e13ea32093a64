!> Tests of a vertical wheel load shared by more patches than the coupled reduction solves
!> together (doc/theory.md §4.6, shcontact_normal_coupling): beyond [[max_patches]] the least loaded
!> patches are coupled alone, and beyond the patches the loading can place along the profile
!> every patch is. The vertical balance holds in every case.
module test_normal_loading_patches
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_options, only: normal_options_type, reduction_local_hertz, &
      reduction_coupled
   use shcontact_normal_coupling, only: couple_strips, max_patches, coupling_start_type
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, &
      solve_vertical_load
   use test_semihertz, only: polynomial_patch
   use shcontact_geometry_track, only: track_type
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_api_solver, only: contact_solver_type, contact_result_type, contact_load_type, &
      load_vertical_force
   implicit none
   private
   public :: collect_normal_loading_patches

   !> Tread-like patches (seed curvatures, doc/theory.md §1.5) in a row along the profile.
   real(wp), parameter :: tread_a = 1.0_wp/920, tread_b = 1.0_wp/600
   !> Spacing of the reference points along the profile (mm): neighbours' loaded extents are
   !> within the combination distance, so placed patches press each other.
   real(wp), parameter :: spacing = 12.0_wp
   !> Vertical load per patch (N).
   real(wp), parameter :: load_per_patch = 20000.0_wp

contains

   !> Collect the tests.
   subroutine collect_normal_loading_patches(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('more_than_max_patches_balance', test_more_than_joint), &
         new_unittest('patches_not_placed_coupled_alone', test_not_placed), &
         new_unittest('warm_coupling_same_fixed_point', test_warm_coupling), &
         new_unittest('predictor_then_guessed_load_same_solution', test_predictor), &
         new_unittest('canted_rail_two_ways_same_coupling', test_canted_two_ways) &
         ]
   end subroutine collect_normal_loading_patches

   !> Six loaded patches, two more than the joint problem holds: Σ N_k cos γ_k = F_z to 1e-10
   !> and the rigid approach is the strips'; the two least loaded (in the local-Hertz solution)
   !> are their own coupled solutions, the four others share their load (one of them changes by
   !> more than 0.1 %).
   subroutine test_more_than_joint(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = max_patches + 2
      type(normal_patch_type) :: alone(n), joint(n)
      real(wp) :: dz, dz_alone
      logical :: joint_member(n)
      integer :: k

      call solve_row(n, alone, dz_alone, joint, dz, error)
      if (allocated(error)) return
      call check(error, all(joint%load > 0.0_wp), message='every patch should carry')
      if (allocated(error)) return
      call check_balance(joint, n*load_per_patch, dz, dz_alone, error)
      if (allocated(error)) return
      joint_member = .false.
      do k = 1, max_patches
         joint_member(maxloc(alone%load, mask=.not. joint_member, dim=1)) = .true.
      end do
      do k = 1, n
         if (joint_member(k)) cycle
         call check(error, joint(k)%load, alone(k)%load, thr=1.0e-12_wp, rel=.true., &
            message='a patch beyond the joint problem should be coupled alone')
         if (allocated(error)) return
      end do
      call check(error, maxval(abs(joint%load/alone%load - 1.0_wp), mask=joint_member) > &
         1.0e-3_wp, message='the most loaded patches should press each other')
   end subroutine test_more_than_joint

   !> More patches (33) than the loading places along the profile: each is coupled alone, and
   !> the vertical balance holds.
   subroutine test_not_placed(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 33
      type(normal_patch_type) :: alone(n), joint(n)
      real(wp) :: dz, dz_alone
      integer :: k

      call solve_row(n, alone, dz_alone, joint, dz, error)
      if (allocated(error)) return
      call check_balance(joint, n*load_per_patch, dz, dz_alone, error)
      if (allocated(error)) return
      do k = 1, n
         call check(error, joint(k)%load, alone(k)%load, thr=1.0e-12_wp, rel=.true., &
            message='a patch not placed should be coupled alone')
         if (allocated(error)) return
      end do
   end subroutine test_not_placed

   !> The row of solve_row's patches prepared with the given normal reduction (n = size of
   !> contacts): contact angles −0.03 − 0.02 (k − 1) rad, gaps 0.5 (k − 1) µm, y_rail (and
   !> y_track) spaced by `spacing`.
   subroutine prepare_row(contacts, reduction, err)
      type(normal_contact_type), intent(out) :: contacts(:)
      integer, intent(in) :: reduction
      type(lib_error), allocatable, intent(out) :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(material_type) :: mat
      integer :: k

      options%reduction = reduction
      do k = 1, size(contacts)
         call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.01_wp, &
            gamma0=-0.03_wp - 0.02_wp*(k - 1), gap0=0.0005_wp*(k - 1))
         geom%y_rail = -spacing*(k - 1)
         ! The right wheel, the rail upright: track y = rail-profile y.
         geom%y_track = geom%y_rail
         call prepare_normal_contact(contacts(k), geom, options, mat, err)
         if (allocated(err)) return
      end do
   end subroutine prepare_row

   !> n tread-like patches in a row (contact angles −0.03 − 0.02 (k − 1) rad, gaps
   !> 0.5 (k − 1) µm) under n·load_per_patch: the coupled solution, and the local-Hertz one with
   !> each patch then coupled alone.
   subroutine solve_row(n, alone, dz_alone, joint, dz, error)
      integer, intent(in) :: n
      type(normal_patch_type), intent(out) :: alone(n), joint(n)
      real(wp), intent(out) :: dz_alone, dz
      type(error_type), allocatable, intent(out) :: error
      type(normal_contact_type) :: contacts(n)
      type(normal_options_type) :: options
      type(lib_error), allocatable :: err
      integer :: k

      call prepare_row(contacts, reduction_local_hertz, err)
      if (.not. allocated(err)) call solve_vertical_load(contacts, n*load_per_patch, alone, &
         dz_alone, err)
      do k = 1, n
         if (.not. allocated(err)) call couple_strips(alone(k), contacts(k)%e_star, err)
         contacts(k)%options%reduction = reduction_coupled
      end do
      if (.not. allocated(err)) call solve_vertical_load(contacts, n*load_per_patch, joint, dz, &
         err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine solve_row

   !> The coupled solve started from the strip lengths of another one (coupling_start_type, as
   !> the kinematic call's vertical balance does between its solves): three patches that press
   !> each other (single solves, then the joint one), first at 3 % more load, then at the load
   !> itself. The warm solve reaches the cold solve's fixed point: every strip load within
   !> 1e-6 of the largest, the patch loads within 1e-6 of F_z (the length iteration stops at
   !> 1e-7 in ln a), the balance exact.
   subroutine test_warm_coupling(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 3
      type(normal_contact_type) :: contacts(n)
      type(normal_patch_type) :: cold(n), other(n), warm(n)
      type(coupling_start_type) :: start
      type(lib_error), allocatable :: err
      real(wp) :: dz_cold, dz_warm, dz_other, f_z, largest
      integer :: k, m

      f_z = n*load_per_patch
      call prepare_row(contacts, reduction_coupled, err)
      if (.not. allocated(err)) call solve_vertical_load(contacts, f_z, cold, dz_cold, err)
      call start%reset()
      if (.not. allocated(err)) call solve_vertical_load(contacts, 1.03_wp*f_z, other, dz_other, &
         err, start)
      if (.not. allocated(err)) call solve_vertical_load(contacts, f_z, warm, dz_warm, err, start)
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, start%n_slots >= 2, message='the joint problem and its single solves '// &
         'should have recorded their lengths')
      if (allocated(error)) return
      call check(error, all(cold%load > 0.0_wp), message='every patch should carry')
      if (allocated(error)) return
      call check(error, maxval(abs(warm%load - cold%load)) <= 1.0e-6_wp*f_z, &
         message='patch loads of the warm solve differ from the cold one''s')
      if (allocated(error)) return
      call check_balance(warm, f_z, dz_warm, dz_cold, error)
      if (allocated(error)) return
      do k = 1, n
         m = cold(k)%n_strips
         call check(error, warm(k)%n_strips == m, message='strip counts differ')
         if (allocated(error)) return
         largest = maxval(cold(k)%strip_load(1:m))
         call check(error, maxval(abs(warm(k)%strip_load(1:m) - cold(k)%strip_load(1:m))) <= &
            1.0e-6_wp*largest, message='strip loads of the warm solve differ from the cold one''s')
         if (allocated(error)) return
      end do
   end subroutine test_warm_coupling

   !> The vertical balance's sequence (shcontact_pipeline_balance): a predictor solve at
   !> 1.03 F_z with the coupling's lengths to coupling_start_type%tolerance = 1e-3 (its loads
   !> differ from the converged ones, by less than 1e-3 F_z), then F_z with the tolerance
   !> reset, started from the predictor's lengths and with Δz bracketed from the predictor's
   !> Δz scaled by Hertz's q^{2/3} (dz_guess): the same Δz to 1e-12 and the same loads to
   !> 1e-6 F_z as a cold solve at F_z; reset() empties the tolerance.
   subroutine test_predictor(error)
      type(error_type), allocatable, intent(out) :: error
      integer, parameter :: n = 3
      type(normal_contact_type) :: contacts(n)
      type(normal_patch_type) :: cold(n), tight(n), loose(n), guessed(n)
      type(coupling_start_type) :: start
      type(lib_error), allocatable :: err
      real(wp) :: dz_cold, dz_tight, dz_loose, dz_guessed, f_z

      f_z = n*load_per_patch
      call prepare_row(contacts, reduction_coupled, err)
      if (.not. allocated(err)) call solve_vertical_load(contacts, f_z, cold, dz_cold, err)
      if (.not. allocated(err)) call solve_vertical_load(contacts, 1.03_wp*f_z, tight, &
         dz_tight, err)
      call start%reset()
      start%tolerance = 1.0e-3_wp
      if (.not. allocated(err)) call solve_vertical_load(contacts, 1.03_wp*f_z, loose, &
         dz_loose, err, start)
      start%tolerance = 0.0_wp
      if (.not. allocated(err)) call solve_vertical_load(contacts, f_z, guessed, dz_guessed, &
         err, start, dz_guess=dz_loose*(1.0_wp/1.03_wp)**(2.0_wp/3.0_wp))
      if (allocated(err)) then
         call test_failed(error, err%message)
         return
      end if
      call check(error, any(loose%load /= tight%load) .and. &
         maxval(abs(loose%load - tight%load)) <= 1.0e-3_wp*f_z, &
         message='the predictor''s loads should differ a little from the converged ones')
      if (allocated(error)) return
      call check(error, dz_guessed, dz_cold, thr=1.0e-12_wp, rel=.true., &
         message='the guessed bracket should find the same vertical approach')
      if (allocated(error)) return
      call check(error, maxval(abs(guessed%load - cold%load)) <= 1.0e-6_wp*f_z, &
         message='patch loads after the predictor differ from a cold solve''s')
      if (allocated(error)) return
      call check_balance(guessed, f_z, dz_guessed, dz_guessed, error)
      if (allocated(error)) return
      start%tolerance = 1.0e-3_wp
      call start%reset()
      call check(error, start%tolerance == 0.0_wp, message='reset should empty the tolerance')
   end subroutine test_predictor

   !> Σ N_k cos γ_k = F_z and the rigid approach of the strips, kept by the coupling.
   subroutine check_balance(patches, f_z, dz, dz_alone, error)
      type(normal_patch_type), intent(in) :: patches(:)
      real(wp), intent(in) :: f_z, dz, dz_alone
      type(error_type), allocatable, intent(out) :: error

      call check(error, sum(patches%load*cos(patches%gamma_plane)), f_z, thr=1.0e-10_wp, rel=.true., &
         message='vertical balance')
      if (allocated(error)) return
      call check(error, dz, dz_alone, thr=1.0e-14_wp, rel=.true., message='rigid approach')
   end subroutine check_balance

   !> The same canted rail given two ways, UIC60 canted 1:40 by the track (the default set-up)
   !> and the built-in UIC60-canted with track%rail_canted, carries the same loads on the same
   !> two patches (t_y = 5.0 and 4.75 mm, vertical load 64.7 kN, ν_x = 1e-3, the coupled
   !> reduction): the patches' distance is taken in the track frame (normal/loading.f90
   !> patch_offset). It mixed the rail profile's y with the track's z before: 3e-4 apart.
   subroutine test_canted_two_ways(error)
      type(error_type), allocatable, intent(out) :: error
      type(contact_solver_type) :: by_track, given
      type(contact_result_type) :: a, b
      type(lib_error), allocatable :: err
      real(wp), parameter :: t_y(2) = [5.0_wp, 4.75_wp]
      integer :: i, k

      call by_track%init('builtin:S1002', 'builtin:UIC60', err)
      if (.not. allocated(err)) call given%init('builtin:S1002', 'builtin:UIC60-canted', err, &
         track=track_type(rail_canted=.true.))
      do i = 1, size(t_y)
         if (.not. allocated(err)) call by_track%solve(t_y(i), 0.0_wp, contact_load_type( &
            load_vertical_force, 64.7e3_wp), creepage_type(1.0e-3_wp, 0.0_wp, 0.0_wp), a, err)
         if (.not. allocated(err)) call given%solve(t_y(i), 0.0_wp, contact_load_type( &
            load_vertical_force, 64.7e3_wp), creepage_type(1.0e-3_wp, 0.0_wp, 0.0_wp), b, err)
         if (allocated(err)) then
            call test_failed(error, err%message)
            return
         end if
         call check(error, a%n_loaded == 2 .and. b%n_loaded == 2, &
            message='two loaded patches expected')
         if (allocated(error)) return
         do k = 1, 2
            call check(error, b%patch(k)%fn, a%patch(k)%fn, rel=.true., thr=1.0e-8_wp, &
               message='a patch''s normal force depends on how the rail cant is given')
            if (allocated(error)) return
         end do
         call check(error, b%wheel%fn, a%wheel%fn, rel=.true., thr=1.0e-8_wp, &
            message='the joined contact depends on how the rail cant is given')
         if (allocated(error)) return
      end do
   end subroutine test_canted_two_ways

end module test_normal_loading_patches
