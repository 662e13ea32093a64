!> Tests of the normal loading cases (doc/theory.md §4.5–4.6): the Hertz method on a patch, and a
!> vertical wheel load shared by several patches through one rigid approach.
module test_normal_loading
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: lib_error => error_type, stat_invalid_input, stat_no_contact, &
      stat_usage
   use shcontact_core_material, only: material_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_options, only: normal_options_type, method_hertz, reduction_local_hertz, &
      reduction_coupled
   use shcontact_normal_coupling, only: couple_strips
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_builtin, only: builtin_profile
   use shcontact_geometry_track, only: track_type, wheelset_position_type
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      prepare_profiles, find_contact_patches
   use shcontact_normal_hertz, only: hertz_type, hertz_shape_type, hertz_shape, hertz_from_load, &
      hertz_from_approach
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, &
      solve_approach, solve_load, solve_vertical_load
   use test_semihertz, only: polynomial_patch
   implicit none
   private
   public :: collect_normal_loading

   !> Tread patch: seed-like curvatures (doc/theory.md §1.5), contact angle −0.03 rad.
   real(wp), parameter :: tread_a = 1.0_wp/920, tread_b = 1.0_wp/600, tread_gamma = -0.03_wp
   !> Flange-root patch: sharper lateral curvature, contact angle −0.9 rad, 0.01 mm gap.
   real(wp), parameter :: flange_a = 0.62_wp/920, flange_b = 1.0_wp/60, flange_gamma = -0.9_wp
   real(wp), parameter :: flange_gap = 0.01_wp
   !> The seed's load, as a normal force and as a vertical wheel load (N).
   real(wp), parameter :: scan_load = 64700.0_wp

contains

   !> Collect the tests.
   subroutine collect_normal_loading(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('hertz_method_force', test_hertz_force), &
         new_unittest('hertz_method_approach', test_hertz_approach), &
         new_unittest('two_patches_balance', test_two_patches), &
         new_unittest('two_patches_hertz_method', test_two_patches_hertz), &
         new_unittest('coupled_patches_far_apart', test_coupled_far), &
         new_unittest('coupled_patches_close', test_coupled_close), &
         new_unittest('second_patch_apart', test_patch_apart), &
         new_unittest('vertical_load_errors', test_vertical_errors), &
         new_unittest('workspace_reuse', test_reuse), &
         new_unittest('patch_confined_to_basin', test_confined), &
         new_unittest('table_prefix_and_capacity', test_table_prefix), &
         new_unittest('default_case_ty_scan', test_ty_scan), &
         new_unittest('default_case_known_positions', test_known_positions), &
         new_unittest('default_case_force_continuous', test_force_continuous), &
         new_unittest('tabulated_shapes_solve_as_root_search', test_tabulated_solve) &
         ]
   end subroutine collect_normal_loading

   !> Prepare the tread and flange patches with the given options.
   subroutine two_contacts(contacts, options, error, gap_flange, y_flange)
      type(normal_contact_type), intent(inout) :: contacts(2)
      type(normal_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error
      real(wp), intent(in), optional :: gap_flange
      !> Rail-profile y of the flange patch's reference point (mm; the tread patch's is 0).
      real(wp), intent(in), optional :: y_flange
      type(patch_geometry_type) :: geom
      type(lib_error), allocatable :: err
      type(material_type) :: mat
      real(wp) :: gap

      gap = flange_gap
      if (present(gap_flange)) gap = gap_flange
      call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.01_wp, gamma0=tread_gamma)
      call prepare_normal_contact(contacts(1), geom, options, mat, err)
      if (.not. allocated(err)) then
         call polynomial_patch(geom, flange_a, flange_b, 4.0_wp, 0.005_wp, gamma0=flange_gamma, &
            gap0=gap)
         geom%y_rail = -40.0_wp
         if (present(y_flange)) geom%y_rail = y_flange
         ! The right wheel, the rail upright: track y = rail-profile y.
         geom%y_track = geom%y_rail
         call prepare_normal_contact(contacts(2), geom, options, mat, err)
      end if
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine two_contacts

   !> `method = 'hertz'` with a prescribed force: the ellipse of the reference curvatures
   !> (whatever the gap does away from y = 0), with its strip table k_i = √(1 − y_i²/b²).
   subroutine test_hertz_force(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(material_type) :: mat
      real(wp), parameter :: load = 64700.0_wp
      integer :: i

      options%method = method_hertz
      call polynomial_patch(geom, tread_a, tread_b, 10.0_wp, 0.05_wp, c3=5.0e-5_wp, &
         gamma0=tread_gamma)
      call prepare_normal_contact(contact, geom, options, mat, err)
      if (.not. allocated(err)) call solve_load(contact, load, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%is_hertz, message='is_hertz')
      if (allocated(error)) return
      call check(error, patch%ellipse_a, 6.2329_wp, thr=5.01e-5_wp, message='a')
      if (allocated(error)) return
      call check(error, patch%ellipse_b, 4.6885_wp, thr=5.01e-5_wp, message='b')
      if (allocated(error)) return
      call check(error, patch%approach, 0.07886_wp, thr=5.01e-6_wp, message='delta')
      if (allocated(error)) return
      call check(error, patch%p_max, 1057.1_wp, thr=0.1_wp, message='p_max')
      if (allocated(error)) return
      call check(error, patch%load, load, thr=1.0e-12_wp, rel=.true., message='load')
      if (allocated(error)) return
      call check(error, patch%area, pi*patch%ellipse_a*patch%ellipse_b, thr=1.0e-12_wp, &
         rel=.true., message='area')
      if (allocated(error)) return
      ! Midpoint rule over the ellipse: Σ N_i = N (1 + O((δy/b)²)).
      call check(error, sum(patch%strip_load), load, thr=1.0e-4_wp, rel=.true., message='sum N_i')
      if (allocated(error)) return
      call check(error, patch%gamma0, tread_gamma, message='gamma0')
      if (allocated(error)) return
      do i = 1, patch%n_strips
         call check(error, patch%k(i), sqrt(1.0_wp - (patch%y(i)/patch%ellipse_b)**2), &
            thr=1.0e-12_wp, message='k_i')
         if (allocated(error)) return
         call check(error, patch%a(i), patch%k(i)*patch%ellipse_a, thr=1.0e-12_wp, message='a_i')
         if (allocated(error)) return
         call check(error, patch%gamma(i), tread_gamma + 2.0e-3_wp*patch%y(i), thr=1.0e-12_wp, &
            message='gamma_i from the geometry')
         if (allocated(error)) return
         call check(error, patch%delta_r(i), 4.0e-2_wp*patch%y(i), thr=1.0e-12_wp, &
            message='delta r_i')
         if (allocated(error)) return
      end do
   end subroutine test_hertz_force

   !> `method = 'hertz'` with a prescribed approach: Hertz's load for δ = 0.07886 mm.
   subroutine test_hertz_approach(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(material_type) :: mat

      options%method = method_hertz
      call polynomial_patch(geom, tread_a, tread_b, 10.0_wp, 0.05_wp)
      call prepare_normal_contact(contact, geom, options, mat, err)
      if (.not. allocated(err)) call solve_approach(contact, 0.07886_wp, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%load, 64700.0_wp, thr=2.0e-4_wp, rel=.true., message='N(delta)')
   end subroutine test_hertz_approach

   !> Tread and flange patches under F_z = 80 kN: Σ N_k cos γ_k = F_z to 1e-10, each patch at
   !> δ_k = Δz cos γ_k − g₀,k, and each patch's load is Hertz's at its approach (the patches are
   !> quadratic) within 0.5 %.
   subroutine test_two_patches(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options
      type(normal_contact_type) :: contacts(2)
      type(normal_patch_type) :: patches(2)
      type(hertz_type) :: hz
      type(material_type) :: mat
      real(wp), parameter :: f_z = 80000.0_wp, gammas(2) = [tread_gamma, flange_gamma]
      real(wp), parameter :: gaps(2) = [0.0_wp, flange_gap]
      real(wp), parameter :: curv(2, 2) = reshape([tread_a, tread_b, flange_a, flange_b], [2, 2])
      real(wp) :: dz
      integer :: k

      ! The strips of each patch on their own (local-Hertz): each patch is then Hertz's at its
      ! approach. The coupled default is tested below.
      options%reduction = reduction_local_hertz
      call two_contacts(contacts, options, error)
      if (allocated(error)) return
      call solve_vertical_load(contacts, f_z, patches, dz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patches(1)%load*cos(tread_gamma) + patches(2)%load*cos(flange_gamma), &
         f_z, thr=1.0e-10_wp, rel=.true., message='vertical balance')
      if (allocated(error)) return
      do k = 1, 2
         call check(error, patches(k)%approach, dz*cos(gammas(k)) - gaps(k), thr=1.0e-14_wp, &
            message='common rigid approach')
         if (allocated(error)) return
         call check(error, patches(k)%load > 0.1_wp*f_z, message='both patches should carry')
         if (allocated(error)) return
         call hertz_from_approach(curv(1, k), curv(2, k), patches(k)%approach, mat, hz, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, patches(k)%load, hz%load, thr=5.0e-3_wp, rel=.true., &
            message='patch load against Hertz at its approach')
         if (allocated(error)) return
      end do
   end subroutine test_two_patches

   !> `reduction = 'coupled'` with the two patches 500 mm apart along the profile, beyond the
   !> separation distance: each is its own coupled solution (the local-Hertz patch coupled
   !> alone) to rounding; the vertical balance and the common rigid approach are kept exactly.
   subroutine test_coupled_far(error)
      type(error_type), allocatable, intent(out) :: error
      call coupled_pair(500.0_wp, error)
   end subroutine test_coupled_far

   !> The same 8 mm apart between reference points (a tread contact and a second one beside it,
   !> as on the S1002 at t_y = 5 mm; their loaded extents are closer than 4 mm): each patch's
   !> surface is pressed down by the other's load, so the smaller patch carries less than alone
   !> (by more than 5 %) and the larger one more, while the vertical balance and the rigid
   !> approaches stay those of the strips.
   subroutine test_coupled_close(error)
      type(error_type), allocatable, intent(out) :: error
      call coupled_pair(8.0_wp, error)
   end subroutine test_coupled_close

   !> Two patches `distance` mm apart along the profile, vertical load, coupled reduction,
   !> against the same patches with the local-Hertz strips each coupled alone.
   subroutine coupled_pair(distance, error)
      real(wp), intent(in) :: distance
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options
      type(normal_contact_type) :: contacts(2)
      type(normal_patch_type) :: joint(2), alone(2)
      real(wp), parameter :: f_z = 80000.0_wp, gaps(2) = [0.0_wp, flange_gap]
      real(wp) :: dz, dz_alone, change(2)
      integer :: k

      options%reduction = reduction_local_hertz
      call two_contacts(contacts, options, error, y_flange=-distance)
      if (allocated(error)) return
      call solve_vertical_load(contacts, f_z, alone, dz_alone, err)
      do k = 1, 2
         if (.not. allocated(err)) call couple_strips(alone(k), contacts(k)%e_star, err)
         contacts(k)%options%reduction = reduction_coupled
      end do
      if (.not. allocated(err)) call solve_vertical_load(contacts, f_z, joint, dz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, dz, dz_alone, thr=1.0e-14_wp, rel=.true., message='rigid approach')
      if (allocated(error)) return
      call check(error, joint(1)%load*cos(tread_gamma) + joint(2)%load*cos(flange_gamma), &
         f_z, thr=1.0e-10_wp, rel=.true., message='vertical balance')
      if (allocated(error)) return
      do k = 1, 2
         call check(error, joint(k)%approach, dz*cos(merge(tread_gamma, flange_gamma, k == 1)) &
            - gaps(k), thr=1.0e-14_wp, message='common rigid approach')
         if (allocated(error)) return
         change(k) = joint(k)%load/alone(k)%load - 1.0_wp
      end do
      if (distance > 100.0_wp) then
         call check(error, maxval(abs(change)) < 1.0e-12_wp, message='patches far apart '// &
            'should carry their own coupled loads')
      else
         call check(error, change(2) < -0.05_wp .and. change(1) > 0.0_wp, message='the '// &
            'smaller patch should give load to the larger one')
      end if
   end subroutine coupled_pair

   !> The same with `method = 'hertz'`: the patch loads are Hertz's at δ_k to rounding.
   subroutine test_two_patches_hertz(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options
      type(normal_contact_type) :: contacts(2)
      type(normal_patch_type) :: patches(2)
      type(hertz_type) :: h1, h2
      type(material_type) :: mat
      real(wp), parameter :: f_z = 80000.0_wp
      real(wp) :: dz

      options%method = method_hertz
      call two_contacts(contacts, options, error)
      if (allocated(error)) return
      call solve_vertical_load(contacts, f_z, patches, dz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call hertz_from_approach(tread_a, tread_b, dz*cos(tread_gamma), mat, h1, err)
      if (.not. allocated(err)) call hertz_from_approach(flange_a, flange_b, &
         dz*cos(flange_gamma) - flange_gap, mat, h2, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, h1%load*cos(tread_gamma) + h2%load*cos(flange_gamma), f_z, &
         thr=1.0e-10_wp, rel=.true., message='balance from closed-form Hertz loads')
      if (allocated(error)) return
      call check(error, patches(2)%ellipse_a, h2%a, thr=1.0e-12_wp, rel=.true.)
   end subroutine test_two_patches_hertz

   !> A patch whose gap is larger than the wheel's approach stays out of contact (cleared, zero
   !> load); the other carries F_z/cos γ.
   subroutine test_patch_apart(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options
      type(normal_contact_type) :: contacts(2)
      type(normal_patch_type) :: patches(2)
      real(wp), parameter :: f_z = 60000.0_wp
      real(wp) :: dz

      call two_contacts(contacts, options, error, gap_flange=2.0_wp)
      if (allocated(error)) return
      call solve_vertical_load(contacts, f_z, patches, dz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patches(2)%load, 0.0_wp, message='the apart patch carries nothing')
      if (allocated(error)) return
      call check(error, maxval(patches(2)%a) <= 0.0_wp, message='apart patch strips a_i = 0')
      if (allocated(error)) return
      call check(error, patches(2)%approach < 0.0_wp, message='negative approach when apart')
      if (allocated(error)) return
      call check(error, patches(1)%load, f_z/cos(tread_gamma), thr=1.0e-10_wp, rel=.true.)
   end subroutine test_patch_apart

   !> Bad vertical-load input and a load the tables cannot carry are error values.
   subroutine test_vertical_errors(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_options_type) :: options
      type(normal_contact_type) :: contacts(2)
      type(normal_patch_type) :: patches(2), one(1)
      real(wp) :: dz

      call two_contacts(contacts, options, error)
      if (allocated(error)) return
      call solve_vertical_load(contacts, -1.0_wp, patches, dz, err)
      call check(error, allocated(err), message='F_z < 0 must be an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
      if (allocated(error)) return
      call solve_vertical_load(contacts, 1.0e4_wp, one, dz, err)
      call check(error, allocated(err), message='size mismatch must be an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_usage)
      if (allocated(error)) return
      ! The flange table (±4 mm) cannot hold the patch of a 2 MN load.
      call solve_vertical_load(contacts, 2.0e6_wp, patches, dz, err)
      call check(error, allocated(err), message='an overload must be an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_no_contact)
      if (allocated(error)) return
      call check(error, index(err%message, 'load too large') > 0, message=err%message)
      if (allocated(error)) return
      contacts(2)%geometry%gamma0 = 0.5_wp*pi + 0.1_wp
      call solve_vertical_load(contacts, 1.0e4_wp, patches, dz, err)
      call check(error, allocated(err), message='a contact angle beyond 90 deg must be an error')
   end subroutine test_vertical_errors

   !> One prepared contact and one patch serve many cases; changing n_strips resizes the table.
   subroutine test_reuse(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(hertz_type) :: hz
      type(material_type) :: mat
      integer :: i

      call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.01_wp)
      call prepare_normal_contact(contact, geom, options, mat, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do i = 1, 20
         call solve_load(contact, 5.0e3_wp*i, patch, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, patch%load, 5.0e3_wp*i, thr=1.0e-10_wp, rel=.true.)
         if (allocated(error)) return
      end do
      call hertz_from_load(tread_a, tread_b, 1.0e5_wp, mat, hz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, patch%approach, hz%approach, thr=5.0e-3_wp, rel=.true.)
      if (allocated(error)) return
      options%n_strips = 37
      call prepare_normal_contact(contact, geom, options, mat, err)
      if (.not. allocated(err)) call solve_load(contact, 1.0e4_wp, patch, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, size(patch%a), 37)
      if (allocated(error)) return
      call check(error, patch%n_strips, 37)
   end subroutine test_reuse

   !> A patch is confined to its own basin: with basin_upper = L = 1 mm on g = B y² (constant
   !> A, B), the contact interval at an approach that would reach y = c > L stops at U within h
   !> of L (the closing point beyond L has the table's largest gap, so ψ crosses zero a small
   !> fraction of h past L), and since strips are independent and N'(y) ∝ δ_i ∝ c² − y², the
   !> load is the unconfined one times [c²(c + U) − (c³ + U³)/3]/(4c³/3) (midpoint rule: 1e-4).
   !> A prescribed force beyond that approach is matched with the interval still ending at L.
   subroutine test_confined(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom
      type(normal_options_type) :: options
      type(normal_contact_type) :: free, confined
      type(normal_patch_type) :: p_free, p_conf
      type(material_type) :: mat
      real(wp), parameter :: limit = 1.0_wp, approach = 0.02_wp
      real(wp) :: c, u, ratio

      call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.01_wp)
      call prepare_normal_contact(free, geom, options, mat, err)
      geom%basin_upper = limit
      if (.not. allocated(err)) call prepare_normal_contact(confined, geom, options, mat, err)
      if (.not. allocated(err)) call solve_approach(free, approach, p_free, err)
      if (.not. allocated(err)) call solve_approach(confined, approach, p_conf, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      c = -(p_free%y(1) - 0.5_wp*p_free%dy)
      call check(error, c > 2.0_wp*limit, message='the free contact reaches beyond the limit')
      if (allocated(error)) return
      call check(error, p_conf%y(1) - 0.5_wp*p_conf%dy, -c, thr=1.0e-12_wp, &
         message='lower end unchanged')
      if (allocated(error)) return
      u = p_conf%y(p_conf%n_strips) + 0.5_wp*p_conf%dy
      call check(error, u >= limit .and. u < limit + geom%h, message='upper end at the limit')
      if (allocated(error)) return
      ratio = (c**2*(c + u) - (c**3 + u**3)/3.0_wp)/(4.0_wp*c**3/3.0_wp)
      call check(error, p_conf%load, ratio*p_free%load, thr=1.0e-4_wp, rel=.true., &
         message='load of the confined strips')
      if (allocated(error)) return
      call solve_load(confined, 2.0_wp*p_free%load, p_conf, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, p_conf%load, 2.0_wp*p_free%load, thr=1.0e-10_wp, rel=.true., &
         message='force matched')
      if (allocated(error)) return
      u = p_conf%y(p_conf%n_strips) + 0.5_wp*p_conf%dy
      call check(error, u >= limit .and. u < limit + geom%h, &
         message='upper end at the limit under the larger force')
   end subroutine test_confined

   !> The default case (built-in S1002 on the built-in UIC60 1:40) at t_y = −10…10 mm in steps
   !> of 0.25 mm solves at every position under N = 64.7 kN on the deepest patch and under
   !> F_z = 64.7 kN shared by all patches ([[solve_position]]). At t_y = 5 mm the tread and the
   !> gauge corner (0.004 mm off) both carry, and the tread contact reaches the ridge between
   !> them (the two regions meet): there each patch stops at its basin limit, so no region is
   !> counted twice.
   subroutine test_ty_scan(error)
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: prep
      type(normal_contact_type), allocatable :: contacts(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(patch_geometry_type), allocatable :: geom(:)
      integer :: i

      call default_profiles(prep, error)
      if (allocated(error)) return
      do i = -40, 40
         call solve_position(prep, 0.25_wp*i, geom, contacts, patches, error)
         if (allocated(error)) return
         if (i == 20) then
            call check(error, size(geom), 2, message='t_y = 5: tread and gauge corner')
            if (allocated(error)) return
            call check(error, patches(2)%load > 0.2_wp*scan_load, message='t_y = 5: both carry')
            if (allocated(error)) return
            call check(error, patches(1)%y(1) - 0.5_wp*patches(1)%dy, geom(1)%basin_lower, &
               thr=geom(1)%h, message='t_y = 5: the tread contact reaches the ridge')
            if (allocated(error)) return
         end if
      end do
   end subroutine test_ty_scan

   !> The positions where the force or the vertical-load match used to fail: touch = g/ε_b of
   !> the tread patch is not monotonic (ε_b jumps where B does between the S1002 arcs, 3.87 and
   !> 3.88 mm; a shallower second minimum inside the basin, 5.98, 6.49 and 6.65 mm), and the
   !> contact interval jumped past the bump. Both loads are matched to 1e-10 in both modes.
   subroutine test_known_positions(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: positions(*) = [3.87_wp, 3.88_wp, 5.98_wp, 6.49_wp, 6.65_wp]
      type(prepared_profiles_type) :: prep
      type(normal_contact_type), allocatable :: contacts(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(patch_geometry_type), allocatable :: geom(:)
      integer :: i

      call default_profiles(prep, error)
      if (allocated(error)) return
      do i = 1, size(positions)
         call solve_position(prep, positions(i), geom, contacts, patches, error)
         if (allocated(error)) return
      end do
   end subroutine test_known_positions

   !> At t_y = 3.87 mm the tread patch's N(δ) is continuous and increasing while its strips
   !> grow across the points out of contact to the region beyond them (δ ≈ 0.048–0.054 mm),
   !> and that region carries load before the bump between them does.
   subroutine test_force_continuous(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(prepared_profiles_type) :: prep
      type(patch_geometry_type), allocatable :: geom(:)
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(material_type) :: mat
      real(wp), parameter :: step = 2.5e-5_wp
      real(wp) :: approach, n_prev
      integer :: i, j
      logical :: gap_seen

      call default_profiles(prep, error)
      if (allocated(error)) return
      call find_contact_patches(prep, wheelset_position_type(y_ws=3.87_wp), geom, err)
      if (.not. allocated(err)) call prepare_normal_contact(contact, geom(1), &
         normal_options_type(), mat, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      n_prev = 0.0_wp
      gap_seen = .false.
      do i = 1, 3600
         approach = i*step
         call solve_approach(contact, approach, patch, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, patch%load > n_prev, message='N(delta) not increasing')
         if (allocated(error)) return
         ! Hertz-like growth: dN/dδ ≈ 3N/(2δ); a jump would exceed it many times.
         call check(error, patch%load - n_prev < 2.0_wp*1.5_wp*patch%load/approach*step, &
            message='N(delta) jumps')
         if (allocated(error)) return
         n_prev = patch%load
         ! A strip out of contact between loaded ones on the field side.
         do j = 2, patch%n_strips - 1
            if (patch%a(j) > 0.0_wp) cycle
            gap_seen = gap_seen .or. (any(patch%a(1:j - 1) > 0.0_wp) .and. &
               any(patch%a(j + 1:) > 0.0_wp))
         end do
      end do
      call check(error, gap_seen, message='no unloaded strip between loaded ones was seen')
   end subroutine test_force_continuous

   !> The built-in S1002 wheel on the built-in UIC60 rail (1:40), prepared.
   subroutine default_profiles(prep, error)
      type(prepared_profiles_type), intent(out) :: prep
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(profile_type) :: wheel, rail

      call builtin_profile('S1002', wheel, err)
      if (.not. allocated(err)) call builtin_profile('UIC60', rail, err)
      if (.not. allocated(err)) call prepare_profiles(wheel, rail, track_type(), &
         contact_options_type(), prep, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine default_profiles

   !> The default case at t_y: the patches found, N = 64.7 kN on the deepest one matched to
   !> 1e-10, and F_z = 64.7 kN shared by all matched to 1e-10 with every loaded patch inside its
   !> basin. Returns the contacts and the vertical-load patches.
   subroutine solve_position(prep, t_y, geom, contacts, patches, error)
      type(prepared_profiles_type), intent(in) :: prep
      real(wp), intent(in) :: t_y
      type(patch_geometry_type), allocatable, intent(inout) :: geom(:)
      type(normal_contact_type), allocatable, intent(inout) :: contacts(:)
      type(normal_patch_type), allocatable, intent(inout) :: patches(:)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(normal_patch_type) :: single
      type(material_type) :: mat
      character(len=20) :: at
      real(wp) :: dz, f_z, y_lo, y_hi
      integer :: k

      write (at, '(a,f6.2,a)') 't_y = ', t_y, ': '
      call find_contact_patches(prep, wheelset_position_type(y_ws=t_y), geom, err)
      if (allocated(err)) then
         call test_failed(error, at//err%message); return
      end if
      if (allocated(contacts)) deallocate (contacts, patches)
      allocate (contacts(size(geom)), patches(size(geom)))
      do k = 1, size(geom)
         call prepare_normal_contact(contacts(k), geom(k), normal_options_type(), mat, err)
         if (allocated(err)) exit
      end do
      if (.not. allocated(err)) call solve_load(contacts(1), scan_load, single, err)
      if (allocated(err)) then
         call test_failed(error, at//'force: '//err%message); return
      end if
      call check(error, single%load, scan_load, thr=1.0e-10_wp, rel=.true., message=at//'N')
      if (allocated(error)) return
      call solve_vertical_load(contacts, scan_load, patches, dz, err)
      if (allocated(err)) then
         call test_failed(error, at//'vertical: '//err%message); return
      end if
      f_z = 0.0_wp
      do k = 1, size(geom)
         f_z = f_z + patches(k)%load*cos(geom(k)%gamma0)
         if (.not. (patches(k)%load > 0.0_wp)) cycle
         ! Strips are measured from the loaded reference point, y_shift from the table's origin.
         y_lo = patches(k)%y_shift + patches(k)%y(1) - 0.5_wp*patches(k)%dy
         y_hi = patches(k)%y_shift + patches(k)%y(patches(k)%n_strips) + 0.5_wp*patches(k)%dy
         call check(error, y_lo > geom(k)%basin_lower - geom(k)%h .and. &
            y_hi < geom(k)%basin_upper + geom(k)%h, message=at//'contact inside its basin')
         if (allocated(error)) return
      end do
      call check(error, f_z, scan_load, thr=1.0e-10_wp, rel=.true., message=at//'F_z')
   end subroutine solve_position

   !> Tables given as the first n_points entries of longer arrays (the contact search's reused
   !> storage) prepare exactly the contact the exact-size tables give, bit for bit, free and
   !> confined to a basin, whatever the arrays hold beyond; a contact prepared again on a
   !> shorter table keeps its arrays (no reallocation) and equals a fresh one.
   subroutine test_table_prefix(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      type(patch_geometry_type) :: geom, padded, short
      type(normal_options_type) :: options
      type(normal_contact_type) :: exact, prefix, reused, fresh
      type(material_type) :: mat
      integer :: n, pad, case, capacity

      pad = 50
      call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.01_wp, curv_a1=2.0e-6_wp, &
         c3=1.0e-5_wp)
      n = size(geom%y)
      do case = 1, 2
         if (case == 2) then
            geom%basin_lower = -3.0_wp
            geom%basin_upper = 1.0_wp
         end if
         padded = geom
         call pad_tables(padded, pad)
         call prepare_normal_contact(exact, geom, options, mat, err)
         if (.not. allocated(err)) call prepare_normal_contact(prefix, padded, options, mat, err, &
            n_points=n)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call compare(exact, prefix, 'prefix of longer arrays', error)
         if (allocated(error)) return
      end do

      geom%basin_lower = -huge(1.0_wp)
      geom%basin_upper = huge(1.0_wp)
      call prepare_normal_contact(reused, geom, options, mat, err)
      capacity = size(reused%geometry%gap)
      call polynomial_patch(short, tread_a, tread_b, 6.0_wp, 0.01_wp, c3=1.0e-5_wp)
      if (.not. allocated(err)) call prepare_normal_contact(reused, short, options, mat, err)
      if (.not. allocated(err)) call prepare_normal_contact(fresh, short, options, mat, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      call check(error, size(reused%geometry%gap) == capacity .and. &
         reused%geometry%n_table == size(short%y), message='shorter table: arrays reallocated')
      if (allocated(error)) return
      call compare(fresh, reused, 'reused contact', error)
      if (allocated(error)) return

      call prepare_normal_contact(prefix, geom, options, mat, err, n_points=n + 1)
      call check(error, allocated(err), message='n_points beyond the arrays: expected an error')
      if (allocated(error)) return
      call check(error, err%stat, stat_invalid_input)
   contains
      !> Lengthen every table by m entries that no valid table holds.
      subroutine pad_tables(g, m)
         type(patch_geometry_type), intent(inout) :: g
         integer, intent(in) :: m
         g%y = [g%y, (-1.0_wp, n = 1, m)]
         g%gap = [g%gap, (-1.0_wp, n = 1, m)]
         g%curv_a = [g%curv_a, (-1.0_wp, n = 1, m)]
         g%curv_b = [g%curv_b, (-1.0_wp, n = 1, m)]
         g%gamma = [g%gamma, (9.0_wp, n = 1, m)]
         g%r_wheel = [g%r_wheel, (-1.0_wp, n = 1, m)]
         n = size(g%y) - m
      end subroutine pad_tables
      !> The two contacts solve three loads to the same bits.
      subroutine compare(a, b, what, error)
         type(normal_contact_type), intent(in) :: a, b
         character(len=*), intent(in) :: what
         type(error_type), allocatable, intent(out) :: error
         type(normal_patch_type) :: pa, pb
         integer :: i, j
         do i = 1, 3
            call solve_load(a, 2.0e4_wp*i, pa, err)
            if (.not. allocated(err)) call solve_load(b, 2.0e4_wp*i, pb, err)
            if (allocated(err)) then
               call test_failed(error, what//': '//err%message); return
            end if
            call check(error, bits(pa%approach) == bits(pb%approach) .and. &
               bits(pa%load) == bits(pb%load) .and. bits(pa%area) == bits(pb%area), &
               message=what//': approach, load or area differ')
            if (allocated(error)) return
            do j = 1, pa%n_strips
               call check(error, bits(pa%y(j)) == bits(pb%y(j)) .and. &
                  bits(pa%a(j)) == bits(pb%a(j)) .and. bits(pa%p0(j)) == bits(pb%p0(j)) .and. &
                  bits(pa%gamma(j)) == bits(pb%gamma(j)), message=what//': strips differ')
               if (allocated(error)) return
            end do
         end do
      end subroutine compare
      elemental integer(i8) function bits(x)
         real(wp), intent(in) :: x
         bits = transfer(x, 0_i8)
      end function bits
   end subroutine test_table_prefix

   !> prepare_normal_contact takes the strips' Hertz shapes from the polynomial table
   !> (hertz_strip_shapes): on the default case at the default position (t_y = 4.733 mm) and at
   !> t_y = 3.87 mm every table point's ε_a, ε_b, m, n and pressure factor equal the root
   !> search's (hertz_shape) to a relative 1e-11, and with the root search's values put in their
   !> place the force-matched approach, area and peak pressure, and the loads at three
   !> approaches, agree to a relative 1e-9.
   subroutine test_tabulated_solve(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: positions(2) = [4.733_wp, 3.87_wp]
      type(lib_error), allocatable :: err
      type(prepared_profiles_type) :: prep
      type(patch_geometry_type), allocatable :: geom(:)
      type(normal_contact_type) :: fast, exact
      type(normal_patch_type) :: p_fast, p_exact
      type(hertz_shape_type) :: shape
      type(material_type) :: mat
      integer :: ip, i, j

      call default_profiles(prep, error)
      if (allocated(error)) return
      do ip = 1, size(positions)
         call find_contact_patches(prep, wheelset_position_type(y_ws=positions(ip)), geom, err)
         if (.not. allocated(err)) call prepare_normal_contact(fast, geom(1), &
            normal_options_type(), mat, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         exact = fast
         associate (g => exact%geometry)
            do i = 1, g%n_table
               j = nint((g%y_first + (i - 1)*g%h - geom(1)%y(1))/geom(1)%h) + 1
               call hertz_shape(geom(1)%curv_a(j)/geom(1)%curv_b(j), shape, err)
               if (allocated(err)) then
                  call test_failed(error, err%message); return
               end if
               call check(error, g%eps_a(i), shape%eps_a, thr=1.0e-11_wp, rel=.true., &
                  message='eps_a')
               if (allocated(error)) return
               call check(error, g%eps_b(i), shape%eps_b, thr=1.0e-11_wp, rel=.true., &
                  message='eps_b')
               if (allocated(error)) return
               call check(error, g%m(i), shape%m, thr=1.0e-11_wp, rel=.true., message='m')
               if (allocated(error)) return
               call check(error, g%n(i), shape%n, thr=1.0e-11_wp, rel=.true., message='n')
               if (allocated(error)) return
               g%eps_a(i) = shape%eps_a
               g%eps_b(i) = shape%eps_b
               g%m(i) = shape%m
               g%n(i) = shape%n
               g%p_factor(i) = sqrt((geom(1)%curv_a(j) + geom(1)%curv_b(j))/(shape%ee*shape%kk))
               call check(error, fast%geometry%p_factor(i), g%p_factor(i), thr=1.0e-11_wp, &
                  rel=.true., message='p_factor')
               if (allocated(error)) return
            end do
         end associate
         call solve_load(fast, scan_load, p_fast, err)
         if (.not. allocated(err)) call solve_load(exact, scan_load, p_exact, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         call check(error, p_fast%approach, p_exact%approach, thr=1.0e-9_wp, rel=.true., &
            message='approach')
         if (allocated(error)) return
         call check(error, p_fast%area, p_exact%area, thr=1.0e-9_wp, rel=.true., message='area')
         if (allocated(error)) return
         call check(error, p_fast%p_max, p_exact%p_max, thr=1.0e-9_wp, rel=.true., &
            message='p_max')
         if (allocated(error)) return
         do i = 1, 3
            call solve_approach(fast, 0.04_wp*i, p_fast, err)
            if (.not. allocated(err)) call solve_approach(exact, 0.04_wp*i, p_exact, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            call check(error, p_fast%load, p_exact%load, thr=1.0e-9_wp, rel=.true., &
               message='load at a given approach')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_tabulated_solve

end module test_normal_loading
