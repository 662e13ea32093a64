!> Invariants the speed work must keep (doc/performance.md): the per-case solves work in place
!> (no array of the workspace, the normal patch or the result is reallocated), a solve does not
!> depend on what the workspace solved before, and the shortcuts of the fast paths (strip blocks,
!> the element grid kept between prepares, load-only evaluations and the bisected contact
!> interval of the normal solve, fields written during the march) give exactly the results of
!> the plain computation. No timing here: the timings are the benchmark's
!> (examples/bench, `fpm run --profile release --example shcontact-bench`).
module test_performance_invariants
   use, intrinsic :: iso_c_binding, only: c_loc, c_intptr_t
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, reduction_local_hertz
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load, &
      solve_approach, solve_vertical_load
   use shcontact_normal_semihertz, only: semihertz_strips, semihertz_load
   use shcontact_tangential_options, only: tangential_options_type, bound_ellipsoidal, &
      bound_parabolic, bound_weighted, bound_weighted_slip, bound_clipped, correction_none
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type, state_adhesion
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use test_semihertz, only: polynomial_patch
   implicit none
   private
   public :: collect_performance_invariants

   !> Seed-like tread patch (doc/theory.md §1.5) with a cubic term, and the seed's load.
   real(wp), parameter :: tread_a = 1.0_wp/920, tread_b = 1.0_wp/600, tread_c3 = 4.0e-5_wp
   real(wp), parameter :: seed_load = 64700.0_wp
   integer, parameter :: all_bounds(5) = [bound_ellipsoidal, bound_parabolic, bound_weighted, &
      bound_weighted_slip, bound_clipped]
   !> Creepage sets in partial slip (the first is the seed's headline case, rad/mm for φ).
   type(creepage_type), parameter :: case_a = creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp)
   type(creepage_type), parameter :: case_b = creepage_type(-1.5e-3_wp, 0.8e-3_wp, -1.0e-3_wp)

contains

   !> Collect the tests.
   subroutine collect_performance_invariants(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('tangential_solve_in_place', test_tangential_in_place), &
         new_unittest('grid_kept_between_prepares', test_grid_reuse), &
         new_unittest('strip_blocks_independent', test_blocks), &
         new_unittest('totals_match_fields', test_totals_match_fields), &
         new_unittest('fields_do_not_change_forces', test_fields_off), &
         new_unittest('normal_solve_in_place', test_normal_in_place), &
         new_unittest('load_only_equals_strip_table', test_load_only), &
         new_unittest('contact_interval_equals_walk', test_interval), &
         new_unittest('vertical_load_fills_patches', test_vertical_fill) &
         ]
   end subroutine collect_performance_invariants

   ! ------------------------------------------------------------------------------- helpers

   !> The semi-Hertz normal patch of the tread geometry at the seed load, n strips.
   subroutine tread_patch(n, patch, error)
      integer, intent(in) :: n
      type(normal_patch_type), intent(out) :: patch
      type(error_type), allocatable, intent(out) :: error
      type(normal_contact_type) :: contact
      call tread_contact(n, contact, error)
      if (allocated(error)) return
      call solve_or_fail(contact, seed_load, patch, error)
   end subroutine tread_patch

   subroutine tread_contact(n, contact, error)
      integer, intent(in) :: n
      type(normal_contact_type), intent(out) :: contact
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geom
      type(lib_error), allocatable :: err
      call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.02_wp, c3=tread_c3, &
         gamma0=-0.03_wp)
      call prepare_normal_contact(contact, geom, normal_options_type(n_strips=n), &
         material_type(), err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine tread_contact

   subroutine solve_or_fail(contact, load, patch, error)
      type(normal_contact_type), intent(in) :: contact
      real(wp), intent(in) :: load
      type(normal_patch_type), intent(inout) :: patch
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call solve_load(contact, load, patch, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine solve_or_fail

   !> Prepare a FASTSIM_SH workspace and solve one creepage set.
   subroutine sh_solve(ws, patch, options, creepage, result, error)
      type(march_workspace_type), intent(inout) :: ws
      type(normal_patch_type), intent(in) :: patch
      type(tangential_options_type), intent(in) :: options
      type(creepage_type), intent(in) :: creepage
      type(tangential_patch_type), intent(inout) :: result
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call prepare_fastsim_sh(ws, patch, material_type(), options, err)
      if (.not. allocated(err)) call solve_prepared(ws, creepage, result, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine sh_solve

   subroutine solve_or_fail_t(ws, creepage, result, error)
      type(march_workspace_type), intent(inout) :: ws
      type(creepage_type), intent(in) :: creepage
      type(tangential_patch_type), intent(inout) :: result
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: err
      call solve_prepared(ws, creepage, result, err)
      if (allocated(err)) call test_failed(error, err%message)
   end subroutine solve_or_fail_t

   !> Two tangential solutions are identical, totals and fields, bit for bit.
   subroutine check_same(error, r1, r2, what)
      type(error_type), allocatable, intent(out) :: error
      type(tangential_patch_type), intent(in) :: r1, r2
      character(len=*), intent(in) :: what
      logical :: same

      same = r1%fx == r2%fx .and. r1%fy == r2%fy .and. r1%mz == r2%mz .and. &
         r1%coulomb_ratio == r2%coulomb_ratio .and. &
         r1%adhesion_fraction == r2%adhesion_fraction .and. r1%fy_track == r2%fy_track
      if (same .and. allocated(r1%px) .and. allocated(r2%px)) then
         same = all(r1%px == r2%px) .and. all(r1%py == r2%py) .and. &
            all(r1%slip == r2%slip) .and. all(r1%state == r2%state) .and. &
            all(r1%x == r2%x) .and. all(r1%pn == r2%pn) .and. all(r1%y == r2%y) .and. &
            all(r1%dx == r2%dx)
      end if
      call check(error, same, message=what//': results differ')
   end subroutine check_same

   !> Addresses and sizes of every array of a workspace (it must be a target).
   function workspace_layout(ws) result(layout)
      type(march_workspace_type), intent(in), target :: ws
      integer(c_intptr_t), allocatable :: layout(:)
      layout = [address_r(ws%y_strip), address_i(ws%strip), address_i(ws%inactive), &
         address_r(ws%y), address_r(ws%a), address_r(ws%akx), address_r(ws%aky), &
         address_r(ws%akxs_y), address_r(ws%a2kphi), address_r(ws%flex_x), &
         address_r(ws%flex_y), address_r(ws%bound_peak), address_r(ws%pe_peak), &
         address_r(ws%weight), address_r(ws%cos_ratio), address_r(ws%phi_geo), &
         address_r(ws%dphi_geo), address_r(ws%rho), address_r(ws%cx), address_r(ws%cy), &
         address_r(ws%cphi), address_r(ws%mu_pe), address_r(ws%tx), address_r(ws%ty), &
         address_r(ws%xn), address_r(ws%hn), address_r(ws%hm), address_r(ws%shape), &
         address_r(ws%ell), address_r(ws%par), address_r(ws%inv_ell)]
   end function workspace_layout

   !> Addresses and sizes of the field arrays of a tangential result.
   function result_layout(r) result(layout)
      type(tangential_patch_type), intent(in), target :: r
      integer(c_intptr_t), allocatable :: layout(:)
      layout = [address_r2(r%x), address_r(r%y), address_r(r%dx), address_r2(r%pn), &
         address_r2(r%px), address_r2(r%py), address_r2(r%slip), &
         transfer(c_loc(r%state), 0_c_intptr_t), int(size(r%state), c_intptr_t)]
   end function result_layout

   !> Addresses and sizes of the strip arrays of a normal patch.
   function patch_layout(p) result(layout)
      type(normal_patch_type), intent(in), target :: p
      integer(c_intptr_t), allocatable :: layout(:)
      layout = [address_r(p%y), address_r(p%a), address_r(p%k), address_r(p%p0), &
         address_r(p%strip_load), address_r(p%m), address_r(p%n), address_r(p%eps_a), &
         address_r(p%gamma), address_r(p%delta_r), address_r(p%r_wheel)]
   end function patch_layout

   function address_r(a) result(pair)
      real(wp), intent(in), target :: a(:)
      integer(c_intptr_t) :: pair(2)
      pair = [transfer(c_loc(a), 0_c_intptr_t), int(size(a), c_intptr_t)]
   end function address_r

   function address_r2(a) result(pair)
      real(wp), intent(in), target :: a(:, :)
      integer(c_intptr_t) :: pair(2)
      pair = [transfer(c_loc(a), 0_c_intptr_t), int(size(a), c_intptr_t)]
   end function address_r2

   function address_i(a) result(pair)
      integer, intent(in), target :: a(:)
      integer(c_intptr_t) :: pair(2)
      pair = [transfer(c_loc(a), 0_c_intptr_t), int(size(a), c_intptr_t)]
   end function address_i

   ! --------------------------------------------------------------------------------- tests

   !> Solving A, B, then A again on one workspace and result changes no array (same address
   !> and size), and the second A equals the first and a fresh workspace's, bit for bit, for
   !> every bound (fields on).
   subroutine test_tangential_in_place(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(march_workspace_type), target :: ws
      type(march_workspace_type) :: fresh_ws
      type(tangential_patch_type), target :: result
      type(tangential_patch_type) :: first, fresh
      integer(c_intptr_t), allocatable :: ws_before(:), res_before(:)
      integer :: b

      call tread_patch(60, patch, error)
      if (allocated(error)) return
      do b = 1, size(all_bounds)
         call sh_solve(ws, patch, tangential_options_type(bound=all_bounds(b), n_elements=40), &
            case_a, result, error)
         if (allocated(error)) return
         first = result
         ws_before = workspace_layout(ws)
         res_before = result_layout(result)
         call solve_or_fail_t(ws, case_b, result, error)
         if (allocated(error)) return
         call solve_or_fail_t(ws, case_a, result, error)
         if (allocated(error)) return
         call check(error, all(workspace_layout(ws) == ws_before), &
            message='a workspace array was reallocated by solve_prepared')
         if (allocated(error)) return
         call check(error, all(result_layout(result) == res_before), &
            message='a result array was reallocated by solve_prepared')
         if (allocated(error)) return
         call check_same(error, result, first, 'A after B')
         if (allocated(error)) return
         call sh_solve(fresh_ws, patch, tangential_options_type(bound=all_bounds(b), &
            n_elements=40), case_a, fresh, error)
         if (allocated(error)) return
         call check_same(error, result, fresh, 'reused vs fresh workspace')
         if (allocated(error)) return
      end do
   end subroutine test_tangential_in_place

   !> The element grid is kept between prepares with the same n_x and bound shape and rebuilt
   !> otherwise: a sequence of prepares on one workspace (n_x and bound changing, the
   !> workspace growing and shrinking) gives the results of fresh workspaces.
   subroutine test_grid_reuse(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws, fresh_ws
      type(tangential_patch_type) :: result, fresh
      integer, parameter :: nx(6) = [30, 30, 30, 20, 45, 30]
      integer, parameter :: bound(6) = [bound_ellipsoidal, bound_weighted, bound_ellipsoidal, &
         bound_ellipsoidal, bound_clipped, bound_parabolic]
      integer :: i

      call tread_patch(40, patch, error)
      if (allocated(error)) return
      do i = 1, size(nx)
         call sh_solve(ws, patch, tangential_options_type(bound=bound(i), n_elements=nx(i)), &
            case_a, result, error)
         if (allocated(error)) return
         call sh_solve(fresh_ws, patch, tangential_options_type(bound=bound(i), &
            n_elements=nx(i)), case_a, fresh, error)
         if (allocated(error)) return
         call check_same(error, result, fresh, 'prepare sequence')
         if (allocated(error)) return
         ! A new workspace for the reference each time.
         fresh_ws = march_workspace_type()
      end do
   end subroutine test_grid_reuse

   !> Strips are marched in blocks of at most 64; the march of a strip does not depend on the
   !> other strips: with 150 strips (3 blocks), unloading all but a few strips of the first or
   !> the last block (and one strip among those, so that loaded strips are not consecutive)
   !> leaves the fields of the loaded strips unchanged, bit for bit. (The march's fields: the
   !> exact-ellipse correction, which spreads a patch-wide defect over the strips, is off.)
   subroutine test_blocks(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch, part
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: full, sub
      integer, parameter :: ranges(3, 2) = reshape([3, 17, 9, 121, 148, 130], [3, 2])
      integer :: r, lo, hi, hole, b, i
      logical :: same

      call tread_patch(150, patch, error)
      if (allocated(error)) return
      do b = 1, size(all_bounds)
         call sh_solve(ws, patch, tangential_options_type(bound=all_bounds(b), n_elements=25, &
            correction=correction_none), case_b, full, error)
         if (allocated(error)) return
         do r = 1, 2
            lo = ranges(1, r)
            hi = ranges(2, r)
            hole = ranges(3, r)
            part = patch
            part%a(:lo - 1) = 0.0_wp
            part%a(hi + 1:) = 0.0_wp
            part%a(hole) = 0.0_wp
            call sh_solve(ws, part, tangential_options_type(bound=all_bounds(b), &
               n_elements=25, correction=correction_none), case_b, sub, error)
            if (allocated(error)) return
            same = .true.
            do i = 1, part%n_strips
               if (part%a(i) > 0.0_wp) then
                  same = same .and. all(sub%px(:, i) == full%px(:, i)) .and. &
                     all(sub%py(:, i) == full%py(:, i)) .and. &
                     all(sub%slip(:, i) == full%slip(:, i)) .and. &
                     all(sub%state(:, i) == full%state(:, i))
               else
                  same = same .and. all(sub%px(:, i) == 0.0_wp) .and. all(sub%state(:, i) == 0)
               end if
            end do
            call check(error, same, message='strips depend on their neighbours or block')
            if (allocated(error)) return
         end do
      end do
   end subroutine test_blocks

   !> The totals, summed during the march, equal the sums of the stored fields:
   !> F = Σ p Δx δy, M_z = Σ (x p_y − y p_x) Δx δy and the adhesion fraction from the states
   !> (round-off of the different summation order only).
   subroutine test_totals_match_fields(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: r
      real(wp) :: fx, fy, mz, adh, area, scale
      integer :: b, i

      call tread_patch(70, patch, error)
      if (allocated(error)) return
      do b = 1, size(all_bounds)
         call sh_solve(ws, patch, tangential_options_type(bound=all_bounds(b), n_elements=35), &
            case_a, r, error)
         if (allocated(error)) return
         fx = 0.0_wp; fy = 0.0_wp; mz = 0.0_wp; adh = 0.0_wp; area = 0.0_wp
         do i = 1, r%ny
            fx = fx + sum(r%px(:, i))*r%dx(i)*r%dy
            fy = fy + sum(r%py(:, i))*r%dx(i)*r%dy
            mz = mz + sum(r%x(:, i)*r%py(:, i) - r%y(i)*r%px(:, i))*r%dx(i)*r%dy
            adh = adh + count(r%state(:, i) == state_adhesion)*r%dx(i)
            area = area + r%nx*r%dx(i)
         end do
         scale = 0.3_wp*r%fn
         call check(error, r%fx, fx, thr=1.0e-12_wp*scale, message='F_x')
         if (allocated(error)) return
         call check(error, r%fy, fy, thr=1.0e-12_wp*scale, message='F_y')
         if (allocated(error)) return
         call check(error, r%mz, mz, thr=1.0e-12_wp*scale*10.0_wp, message='M_z')
         if (allocated(error)) return
         call check(error, r%adhesion_fraction, adh/area, thr=1.0e-13_wp, &
            message='adhesion fraction')
         if (allocated(error)) return
      end do
   end subroutine test_totals_match_fields

   !> The forces-only path (fields off) gives the totals of the path with fields, bit for bit.
   subroutine test_fields_off(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: with, without
      integer :: b

      call tread_patch(90, patch, error)
      if (allocated(error)) return
      do b = 1, size(all_bounds)
         call sh_solve(ws, patch, tangential_options_type(bound=all_bounds(b), n_elements=50), &
            case_a, with, error)
         if (allocated(error)) return
         call sh_solve(ws, patch, tangential_options_type(bound=all_bounds(b), n_elements=50, &
            fields=.false.), case_a, without, error)
         if (allocated(error)) return
         call check(error, .not. allocated(without%px), message='fields left allocated')
         if (allocated(error)) return
         call check_same(error, without, with, 'fields on/off')
         if (allocated(error)) return
      end do
   end subroutine test_fields_off

   !> solve_load on a prepared contact reuses the patch arrays, and its result does not depend
   !> on the load solved before.
   subroutine test_normal_in_place(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_contact_type) :: contact
      type(normal_patch_type), target :: patch
      type(normal_patch_type) :: first, fresh
      integer(c_intptr_t), allocatable :: before(:)
      logical :: same

      call tread_contact(80, contact, error)
      if (allocated(error)) return
      call solve_or_fail(contact, seed_load, patch, error)
      if (allocated(error)) return
      first = patch
      before = patch_layout(patch)
      call solve_or_fail(contact, 0.3_wp*seed_load, patch, error)
      if (allocated(error)) return
      call solve_or_fail(contact, seed_load, patch, error)
      if (allocated(error)) return
      call check(error, all(patch_layout(patch) == before), &
         message='a patch array was reallocated by solve_load')
      if (allocated(error)) return
      call solve_or_fail(contact, seed_load, fresh, error)
      if (allocated(error)) return
      same = patch%load == first%load .and. patch%approach == fresh%approach .and. &
         all(patch%a == first%a) .and. all(patch%p0 == fresh%p0) .and. &
         all(patch%y == fresh%y) .and. all(patch%m == fresh%m) .and. &
         all(patch%gamma == fresh%gamma) .and. patch%dy == fresh%dy
      call check(error, same, message='solve_load depends on the previous solve')
   end subroutine test_normal_in_place

   !> The load-only evaluation used by the force iteration equals the load of the full strip
   !> table bit for bit, below contact (0), in contact and at the end of the table (both fail).
   subroutine test_load_only(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(lib_error), allocatable :: err_table, err_load
      real(wp) :: approach, load
      integer :: i

      call tread_contact(100, contact, error)
      if (allocated(error)) return
      do i = -2, 60
         approach = 0.005_wp*i
         call semihertz_strips(contact%geometry, contact%options, contact%e_star, approach, &
            patch, err_table)
         call semihertz_load(contact%geometry, contact%options, contact%e_star, approach, load, &
            err_load)
         call check(error, allocated(err_table) .eqv. allocated(err_load), &
            message='load-only and strip table disagree on the error')
         if (allocated(error)) return
         if (allocated(err_table)) cycle
         call check(error, load == patch%load, message='load-only differs from the strip table')
         if (allocated(error)) return
      end do
      call check(error, allocated(err_load), message='the table end was never reached')
   end subroutine test_load_only

   !> The strips' interval found by bisection on the cover table is the one of the walk outwards
   !> from the first-contact point while cover < δ; it holds every table point in contact
   !> (touch < δ), also when the gap is not monotonic (a second basin at |y| = 6 mm that comes
   !> into contact before the bump between them), and where cover = touch at both points of its
   !> end cell it ends where ψ = ε_b δ − g, linear on each cell, crosses zero (doc/theory.md §4.3).
   subroutine test_interval(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geom
      type(normal_contact_type) :: contact
      type(normal_patch_type) :: patch
      type(lib_error), allocatable :: err
      real(wp) :: approach, y_lo, y_hi
      integer :: i, j_lo, j_hi, n_checked

      call polynomial_patch(geom, tread_a, tread_b, 9.0_wp, 0.01_wp, gamma0=-0.03_wp)
      ! g = B y² (1 − (y/6)²)² + 0.002 |y|: rises, falls back near |y| = 6, rises again.
      geom%gap = tread_b*geom%y**2*(1.0_wp - (geom%y/6.0_wp)**2)**2 + 0.002_wp*abs(geom%y)
      call prepare_normal_contact(contact, geom, normal_options_type(n_strips=50), &
         material_type(), err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      n_checked = 0
      do i = 1, 80
         approach = 0.0025_wp*i
         call semihertz_strips(contact%geometry, contact%options, contact%e_star, approach, &
            patch, err)
         call walk(approach, j_lo, j_hi)
         if (j_lo == 1 .or. j_hi == contact%geometry%n_table) then
            call check(error, allocated(err), message='table end not reported')
            if (allocated(error)) return
            cycle
         end if
         if (allocated(err)) then
            call test_failed(error, 'unexpected error: '//err%message); return
         end if
         n_checked = n_checked + 1
         associate (g => contact%geometry, lo => patch%y(1) - 0.5_wp*patch%dy, &
               hi => patch%y(patch%n_strips) + 0.5_wp*patch%dy)
            call check(error, lo <= table_y(j_lo) .and. lo >= table_y(j_lo - 1) .and. &
               hi >= table_y(j_hi) .and. hi <= table_y(j_hi + 1), &
               message='interval outside the cells of the walk')
            if (allocated(error)) return
            call check(error, all(g%touch(1:j_lo - 1) >= approach) .and. &
               all(g%touch(j_hi + 1:g%n_table) >= approach), &
               message='a table point in contact outside the interval')
            if (allocated(error)) return
            if (g%cover(j_lo) == g%touch(j_lo) .and. g%cover(j_lo - 1) == g%touch(j_lo - 1)) then
               y_lo = table_y(j_lo) - g%h*crossing(psi(j_lo), psi(j_lo - 1))
               call check(error, lo, y_lo, thr=1.0e-12_wp, &
                  message='start of the interval differs from the walk')
               if (allocated(error)) return
            end if
            if (g%cover(j_hi) == g%touch(j_hi) .and. g%cover(j_hi + 1) == g%touch(j_hi + 1)) then
               y_hi = table_y(j_hi) + g%h*crossing(psi(j_hi), psi(j_hi + 1))
               call check(error, hi, y_hi, thr=1.0e-12_wp, &
                  message='end of the interval differs from the walk')
               if (allocated(error)) return
            end if
         end associate
      end do
      call check(error, n_checked > 40, message='too few approaches inside the table')
   contains
      !> The covered run of table points by walking outwards (the algorithm replaced).
      subroutine walk(approach, j_lo, j_hi)
         real(wp), intent(in) :: approach
         integer, intent(out) :: j_lo, j_hi
         associate (g => contact%geometry)
            j_lo = g%i_first
            do while (j_lo > 1)
               if (approach <= g%cover(j_lo - 1)) exit
               j_lo = j_lo - 1
            end do
            j_hi = g%i_first
            do while (j_hi < g%n_table)
               if (approach <= g%cover(j_hi + 1)) exit
               j_hi = j_hi + 1
            end do
         end associate
      end subroutine walk
      real(wp) function table_y(j)
         integer, intent(in) :: j
         table_y = contact%geometry%y_first + (j - 1)*contact%geometry%h
      end function table_y
      !> ψ_j = (ε_b,j − c_j)(δ − touch_j) at the current approach.
      real(wp) function psi(j)
         integer, intent(in) :: j
         psi = contact%geometry%psi_slope(j)*(approach - contact%geometry%touch(j))
      end function psi
      !> Fraction of a cell from the point inside (ψ > 0) to the zero of the linear ψ.
      real(wp) function crossing(psi_in, psi_out)
         real(wp), intent(in) :: psi_in, psi_out
         crossing = min(1.0_wp, max(0.0_wp, psi_in/(psi_in - psi_out)))
      end function crossing
   end subroutine test_interval

   !> solve_vertical_load iterates on forces alone and fills the patches at the end: they equal
   !> the patches solve_approach gives at the final approaches, bit for bit.
   subroutine test_vertical_fill(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geom
      type(normal_contact_type) :: contacts(2)
      type(normal_patch_type) :: patches(2), single
      type(lib_error), allocatable :: err
      real(wp) :: dz
      integer :: k
      logical :: same

      ! The strips of each patch on their own: with the coupled reduction the patches share
      ! load, and a patch is no longer its own solution at its approach.
      call polynomial_patch(geom, tread_a, tread_b, 12.0_wp, 0.01_wp, gamma0=-0.03_wp)
      call prepare_normal_contact(contacts(1), geom, normal_options_type(reduction= &
         reduction_local_hertz), material_type(), err)
      if (.not. allocated(err)) then
         call polynomial_patch(geom, 0.62_wp/920, 1.0_wp/60, 4.0_wp, 0.005_wp, gamma0=-0.9_wp, &
            gap0=0.01_wp)
         call prepare_normal_contact(contacts(2), geom, normal_options_type(reduction= &
            reduction_local_hertz), material_type(), err)
      end if
      if (.not. allocated(err)) call solve_vertical_load(contacts, 80000.0_wp, patches, dz, err)
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      do k = 1, 2
         call solve_approach(contacts(k), patches(k)%approach, single, err)
         if (allocated(err)) then
            call test_failed(error, err%message); return
         end if
         same = single%load == patches(k)%load .and. all(single%a == patches(k)%a) .and. &
            all(single%y == patches(k)%y) .and. all(single%gamma == patches(k)%gamma)
         call check(error, same, message='vertical-load patch not filled at the solution')
         if (allocated(error)) return
      end do
   end subroutine test_vertical_fill

end module test_performance_invariants
