!> The summary of every exact-theory set of the repository (doc/validation.md §6.6,
!> doc/validation/sets.md, issue 28): the project's positions of data/exact/ with all their
!> cases pooled, max |Δf| (the larger of max |Δf_x| and max |Δf_y|), P80 |Δf_x|, P80 |Δf_y|,
!> recomputed for the defaults and the main alternatives (normal reduction `local-hertz`,
!> correction `none`) and held to the table's numbers within ±0.002 (its printed digits and the
!> round-off of another compiler). The shared sets' rows are those of Table 10 and Table 9, kept by
!> the suite `validation`. Needs the external data's sample profiles (SHCONTACT_EXTERNAL_DATA).
module test_validation_sets
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_real
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_options, only: tangential_options_type, correction_none, &
      correction_exact_ellipse
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use test_validation, only: percentile, read_columns, summary_values, position_errors, &
      recommended_options, two_patch_solution, exact_positions, skip_without_profiles, &
      reference_patch, summary_value
   use test_external_data, only: external_file
   use shcontact_geometry_track, only: track_type
   use shcontact_tangential_lobes, only: joined_lobes_type, join_lobes
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, &
      contact_result_type, load_vertical_force
   implicit none
   private
   public :: collect_validation_sets

   !> The configurations of the table: the defaults, normal reduction local-hertz, correction none.
   character(len=*), parameter :: reductions(3) = [character(len=11) :: 'coupled', &
      'local-hertz', 'coupled']
   integer, parameter :: corrections(3) = [correction_exact_ellipse, correction_exact_ellipse, &
      correction_none]

   !> doc/validation/sets.md: per configuration, max |Δf|, P80 |Δf_x|, P80 |Δf_y|.
   !> The 19 single-lobe positions (4104 cases).
   real(wp), parameter :: single_rows(3, 3) = reshape([ &
      0.028_wp, 0.008_wp, 0.006_wp, &
      0.127_wp, 0.067_wp, 0.015_wp, &
      0.058_wp, 0.011_wp, 0.030_wp &
      ], [3, 3])
   !> The two-lobe positions, the wheel's Σ against CONTACT's joined patch (432 cases).
   real(wp), parameter :: lobe_rows(3, 3) = reshape([ &
      0.015_wp, 0.007_wp, 0.007_wp, &
      0.075_wp, 0.059_wp, 0.039_wp, &
      0.045_wp, 0.014_wp, 0.020_wp &
      ], [3, 3])
   !> All 21 positions (4536 cases).
   real(wp), parameter :: all_rows(3, 3) = reshape([ &
      0.028_wp, 0.008_wp, 0.006_wp, &
      0.127_wp, 0.063_wp, 0.025_wp, &
      0.058_wp, 0.011_wp, 0.029_wp &
      ], [3, 3])

contains

   !> doc/validation/patches_normal.md (doc/validation.md §6.6, issue 28's normal goal): our
   !> p_max and area (defaults, 100 strips, F_n = 64.7 kN) against CONTACT's pressure grid at the
   !> 19 single-lobe positions of data/exact/ (in exact_positions' order) and the shared ty0 and
   !> ty5p8, held to the table's relative differences within ±0.3 points (so its counts within
   !> 10 % and 5 % too).
   subroutine test_normal_every_position(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: dp(21) = [-0.2_wp, -0.2_wp, -0.1_wp, -0.2_wp, 8.0_wp, -0.4_wp, &
         7.1_wp, -1.7_wp, 3.1_wp, -1.4_wp, -1.1_wp, -0.6_wp, -0.2_wp, -0.4_wp, -0.6_wp, &
         -0.3_wp, -0.9_wp, -2.2_wp, 0.4_wp, 2.3_wp, -1.2_wp]
      real(wp), parameter :: da(21) = [-1.1_wp, -0.6_wp, -0.5_wp, -2.6_wp, -2.1_wp, -3.7_wp, &
         -4.9_wp, -6.2_wp, -6.9_wp, -2.2_wp, 1.0_wp, 0.8_wp, 0.4_wp, -1.2_wp, -0.6_wp, 0.1_wp, &
         -1.0_wp, 2.8_wp, -6.7_wp, -1.6_wp, 1.2_wp]
      type(normal_patch_type) :: patch
      real(wp), allocatable :: grid(:, :)
      real(wp) :: y_ws, y_ref, got(2, 21)
      character(len=:), allocatable :: dir
      integer :: k

      call skip_without_profiles(error)
      if (allocated(error)) return
      do k = 1, size(dp)
         if (k <= size(exact_positions)) then
            dir = 'data/exact/'//trim(exact_positions(k))//'/'
         else
            dir = external_file('reference/'//trim(merge('ty0_literal  ', 'ty5p8_literal', &
               k == 20))//'/', error)
            if (allocated(error)) return
         end if
         call summary_value(dir//'summary.csv', 'y_ws', y_ws, error)
         if (.not. allocated(error)) call summary_value(dir//'summary.csv', 'ycp_tr', y_ref, &
            error)
         if (allocated(error)) return
         call read_columns(dir//'grid_module3_exact_nonhertz.csv', &
            [character(len=6) :: 'pn_MPa'], grid, error)
         if (allocated(error)) return
         call reference_patch(patch, error, y_ws=y_ws, y_ref=y_ref)
         if (allocated(error)) return
         ! CONTACT's elements are 0.2 × 0.2 mm (its summary's grid_dx, grid_dy).
         got(:, k) = 100.0_wp*[patch%p_max/maxval(grid(:, 1)) - 1.0_wp, &
            patch%area/(0.04_wp*count(grid(:, 1) > 0.0_wp)) - 1.0_wp]
         call check(error, abs(got(1, k) - dp(k)) <= 0.3_wp .and. abs(got(2, k) - da(k)) <= &
            0.3_wp, message=dir//': p_max, area against CONTACT (%) '// &
            str_real(got(1, k))//', '//str_real(got(2, k))//'; the table '//str_real(dp(k))// &
            ', '//str_real(da(k)))
         if (allocated(error)) return
      end do
   end subroutine test_normal_every_position


   !> Collect the tests.
   subroutine collect_validation_sets(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [new_unittest('project_positions_pooled_vs_exact', test_pooled), &
         new_unittest('two_lobe_wheel_contact_vs_joined_exact', test_wheel_contact), &
         new_unittest('join_lobes_rule', test_join_rule), &
         new_unittest('normal_pmax_area_every_position', test_normal_every_position)]
   end subroutine collect_validation_sets

   !> The three data/exact rows of the table, each configuration.
   subroutine test_pooled(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: ex(:), ey(:), sx(:), sy(:), wx(:), wy(:)
      integer :: ic, k

      do ic = 1, size(reductions)
         sx = [real(wp) ::]
         sy = [real(wp) ::]
         do k = 1, size(exact_positions)
            call position_errors(trim(exact_positions(k)), ex, ey, error, builtin=.false., &
               reduction=trim(reductions(ic)), correction=corrections(ic))
            if (allocated(error) .or. .not. allocated(ex)) return
            sx = [sx, ex]
            sy = [sy, ey]
         end do
         call check_pooled(sx, sy, 4104, single_rows(:, ic), 'single-lobe positions, '// &
            'configuration '//achar(48 + ic), error)
         if (allocated(error)) return
         call wheel_sum_errors(trim(reductions(ic)), corrections(ic), wx, wy, error)
         if (allocated(error)) return
         call check_pooled(wx, wy, 432, lobe_rows(:, ic), 'two-lobe positions (wheel sum), '// &
            'configuration '//achar(48 + ic), error)
         if (allocated(error)) return
         call check_pooled([sx, wx], [sy, wy], 4536, all_rows(:, ic), 'all 21 positions, '// &
            'configuration '//achar(48 + ic), error)
         if (allocated(error)) return
      end do
   end subroutine test_pooled

   !> The case count, max |Δf| and the P80s against a row of the table, each within ±0.002.
   subroutine check_pooled(ex, ey, n, row, label, error)
      real(wp), intent(in) :: ex(:), ey(:), row(3)
      integer, intent(in) :: n
      character(len=*), intent(in) :: label
      type(error_type), allocatable, intent(out) :: error
      call check(error, size(ex), n, message=label//': cases')
      if (allocated(error)) return
      call check(error, max(maxval(ex), maxval(ey)), row(1), thr=0.002_wp, &
         message=label//': max |Delta f|')
      if (allocated(error)) return
      call check(error, percentile(ex, 0.8_wp), row(2), thr=0.002_wp, &
         message=label//': P80 |Delta f_x|')
      if (allocated(error)) return
      call check(error, percentile(ey, 0.8_wp), row(3), thr=0.002_wp, &
         message=label//': P80 |Delta f_y|')
   end subroutine check_pooled

   !> At Y_WS = 5.0 and 5.3 mm (doc/validation.md §6.5): our patches under the vertical load for
   !> which Σ F_n = 64.7 kN, each with the DOE's creepages carried to its reference point by the
   !> rigid slip (ν_x,k = ξ − φ (y_k − y_G), y_k = (y_track,k − y_ref)/cos δ), and the wheel's
   !> Σ F/(μ Σ F_n) against CONTACT's one f of its joined patch: |Δf_x|, |Δf_y| of both
   !> positions' 216 cases.
   subroutine wheel_sum_errors(reduction, correction, ex, ey, error, sum_x, sum_y)
      character(len=*), intent(in) :: reduction
      integer, intent(in) :: correction
      real(wp), allocatable, intent(out) :: ex(:), ey(:)
      type(error_type), allocatable, intent(out) :: error
      !> The wheel's Σ F_x/(μ Σ F_n), Σ F_y/(μ Σ F_n) of every case (CONTACT's sign), both
      !> positions in turn.
      real(wp), allocatable, intent(out), optional :: sum_x(:), sum_y(:)
      character(len=*), parameter :: names(2) = [character(len=6) :: 'yws5p0', 'yws5p3']
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_patch_type), allocatable :: patches(:)
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: err
      real(wp), allocatable :: cases(:, :), wx(:), wy(:)
      real(wp) :: y_ws, y_geo, pen, ycp_r, delt, y_ref, y_k, nux, share
      integer :: ip, k, i

      allocate (ex(0), ey(0))
      if (present(sum_x)) allocate (sum_x(0), sum_y(0))
      call recommended_options(options)
      options%correction = correction
      do ip = 1, size(names)
         call summary_values('data/exact/'//names(ip)//'/summary.csv', y_ws, y_geo, pen, &
            ycp_r, delt, y_ref, error)
         if (allocated(error)) return
         call two_patch_solution(y_ws, geometry, patches, error, reduction=reduction)
         if (allocated(error) .or. .not. allocated(patches)) return
         call read_columns('data/exact/'//names(ip)//'/doe_6x6x6_exact_nonhertz.csv', &
            [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m', 'fx', 'fy'], cases, error)
         if (allocated(error)) return
         wx = [(0.0_wp, i=1, size(cases, 1))]
         wy = wx
         do k = 1, size(patches)
            if (.not. (patches(k)%load > 0.0_wp)) cycle
            y_k = (geometry(k)%y_track - y_ref)/cos(delt)
            share = patches(k)%load/sum(patches%load)
            call prepare_fastsim_sh(ws, patches(k), material_type(), options, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            do i = 1, size(cases, 1)
               nux = cases(i, 1) - 1.0e-3_wp*cases(i, 3)*(y_k - y_geo)
               call solve_prepared(ws, creepage_type(-nux, -cases(i, 2), &
                  -1.0e-3_wp*cases(i, 3)), result, err)
               if (allocated(err)) then
                  call test_failed(error, err%message); return
               end if
               ! CONTACT's sign: the force on the rail.
               wx(i) = wx(i) - share*result%fx_norm
               wy(i) = wy(i) - share*result%fy_norm
            end do
         end do
         ex = [ex, abs(wx - cases(:, 4))]
         ey = [ey, abs(wy - cases(:, 5))]
         if (present(sum_x)) then
            sum_x = [sum_x, wx]
            sum_y = [sum_y, wy]
         end if
      end do
   end subroutine wheel_sum_errors

   !> Issue 28 item 3 through the API: at Y_WS = 5.0 and 5.3 mm, where CONTACT joins two lobes
   !> into one patch, the solver's joined contact (contact_result_type%wheel,
   !> shcontact_tangential_lobes) holds both patches and its f = ΣF/(μΣF_n) follows CONTACT's one
   !> f of the joined patch, while the main (most loaded) patch's own f does not. Every case of
   !> the DOE (216 per position, with spin), under the vertical load for which Σ F_n = 64.7 kN
   !> (the load steps of the Table-12 comparison, test_validation's two_patch_solution), the
   !> prescribed creepages given at our first patch's reference point (CONTACT's, carried from
   !> its point G there by the rigid slip) and carried by the solver to the other patch
   !> (doc/lobes.md): max |Δf| of the joined contact ≤ 0.025 (measured 0.0223), of the main
   !> patch > 0.2 (measured 0.442). The joined f is also Table 12's two-lobe comparison's
   !> ([[wheel_sum_errors]], which carries CONTACT's creepages to each patch's first contact
   !> through CONTACT's contact plane) within 0.008 (measured 0.0052: the solver measures the
   !> second patch's distance from the first in the first patch's contact plane, 0.04 mm longer
   !> (5.0 mm) and 0.15 mm shorter (5.3 mm) than the table's in CONTACT's plane: at φ = 2 1/m
   !> 0.3‰ of ν_x).
   subroutine test_wheel_contact(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: names(2) = [character(len=6) :: 'yws5p0', 'yws5p3']
      type(contact_solver_type) :: solver
      type(contact_result_type) :: result
      type(track_type) :: track
      type(lib_error), allocatable :: err
      real(wp), allocatable :: cases(:, :), ex(:), ey(:), sum_x(:), sum_y(:)
      character(len=:), allocatable :: wheel, rail
      real(wp) :: y_ws, y_geo, pen, ycp_r, delt, y_ref, f_z, worst_joined, worst_main, &
         worst_table, y_1, nux, phi
      integer :: ip, i, it, n

      call skip_without_profiles(error)
      if (allocated(error)) return
      wheel = external_file('profiles/MBench_S1002_v3.prw', error)
      if (.not. allocated(error)) rail = external_file('profiles/MBench_UIC60_v3.prr', error)
      if (allocated(error)) return
      call wheel_sum_errors('coupled', correction_exact_ellipse, ex, ey, error, sum_x, sum_y)
      if (allocated(error)) return
      track%rail_canted = .true.
      call solver%init(wheel, rail, err, track=track, material=material_type())
      if (allocated(err)) then
         call test_failed(error, err%message); return
      end if
      worst_joined = 0.0_wp
      worst_main = 0.0_wp
      worst_table = 0.0_wp
      n = 0
      do ip = 1, size(names)
         call summary_values('data/exact/'//names(ip)//'/summary.csv', y_ws, y_geo, pen, &
            ycp_r, delt, y_ref, error)
         if (allocated(error)) return
         call read_columns('data/exact/'//names(ip)//'/doe_6x6x6_exact_nonhertz.csv', &
            [character(len=11) :: 'nux', 'nuy', 'phi_1_per_m', 'fx', 'fy'], cases, error)
         if (allocated(error)) return
         ! The load steps of two_patch_solution, so that the normal solution is the table's.
         f_z = 64700.0_wp
         do it = 1, 4
            call solver%solve(y_ws, 0.0_wp, contact_load_type(load_vertical_force, f_z), &
               creepage_type(), result, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            if (it < 4) f_z = f_z*64700.0_wp/result%track%fn
         end do
         ! Our first patch's reference point in CONTACT's local y (as y_k of the table).
         y_1 = (result%patch(1)%y_track - y_ref)/cos(delt)
         do i = 1, size(cases, 1)
            phi = 1.0e-3_wp*cases(i, 3)
            nux = cases(i, 1) - phi*(y_1 - y_geo)
            ! CONTACT's sign (rail relative to wheel): all three flip.
            call solver%solve(y_ws, 0.0_wp, contact_load_type(load_vertical_force, f_z), &
               creepage_type(-nux, -cases(i, 2), -phi), result, err)
            if (allocated(err)) then
               call test_failed(error, err%message); return
            end if
            call check(error, result%n_loaded == 2 .and. result%wheel%n_members == 2, &
               message=names(ip)//': the joined contact should hold both patches')
            if (allocated(error)) return
            n = n + 1
            ! CONTACT's sign: the force on the rail.
            worst_joined = max(worst_joined, abs(-result%wheel%fx_norm - cases(i, 4)), &
               abs(-result%wheel%fy_norm - cases(i, 5)))
            worst_main = max(worst_main, abs(-result%main%fx_norm - cases(i, 4)), &
               abs(-result%main%fy_norm - cases(i, 5)))
            worst_table = max(worst_table, abs(-result%wheel%fx_norm - sum_x(n)), &
               abs(-result%wheel%fy_norm - sum_y(n)))
         end do
      end do
      call check(error, n == 432 .and. size(sum_x) == 432, message='432 cases expected')
      if (allocated(error)) return
      call check(error, worst_joined <= 0.025_wp .and. worst_main > 0.2_wp, message= &
         'max |Delta f| of the joined contact '//str_real(worst_joined)//' (<= 0.025), '// &
         'of the main patch '//str_real(worst_main)//' (> 0.2)')
      if (allocated(error)) return
      call check(error, worst_table <= 0.008_wp, message='max |Delta f| of the joined '// &
         'contact from Table 12''s wheel sum '//str_real(worst_table)//' (<= 0.008)')
   end subroutine test_wheel_contact

   !> shcontact_tangential_lobes on two synthetic patches: a parabolic gap g = y²/(2R) around
   !> each reference point (R = 20 mm) tabulated every 0.1 mm, approach δ = 0.1 mm, so each
   !> interpenetration holds the table points |y| < √(2Rδ) = 2 mm, extent |y| ≤ 1.95 mm (half a
   !> step beyond the last). Placed 7.8 mm apart their extents lie 3.9 mm apart and join (4 mm
   !> rule); 8.1 mm apart (4.2 mm) they do not. Joined: Σ F_n, Σ F, f = ΣF/(μΣF_n); alone: the
   !> most loaded patch's own forces. An unloaded patch never joins.
   subroutine test_join_rule(error)
      type(error_type), allocatable, intent(out) :: error
      type(patch_geometry_type) :: geometry(2)
      type(normal_patch_type) :: patches(2)
      type(joined_lobes_type) :: joined
      integer :: k, i
      real(wp), parameter :: fx(2) = [1000.0_wp, -300.0_wp], fy(2) = [200.0_wp, 500.0_wp]

      do k = 1, 2
         geometry(k)%h = 0.1_wp
         geometry(k)%y = [(0.1_wp*i, i=-60, 60)]
         geometry(k)%gap = geometry(k)%y**2/40.0_wp
         patches(k)%approach = 0.1_wp
         patches(k)%area = 10.0_wp*k
         patches(k)%p_max = 1000.0_wp*k
      end do
      patches%load = [20000.0_wp, 40000.0_wp]
      call join_lobes(geometry, [121, 121], patches, [0.0_wp, 7.8_wp], fx, fy, 0.3_wp, joined)
      call check(error, joined%n_members == 2 .and. abs(joined%fn - 60000.0_wp) < 1e-9_wp .and. &
         abs(joined%fx - 700.0_wp) < 1e-9_wp .and. abs(joined%fy - 700.0_wp) < 1e-9_wp .and. &
         abs(joined%fx_norm - 700.0_wp/18000.0_wp) < 1e-12_wp .and. &
         abs(joined%area - 30.0_wp) < 1e-12_wp .and. abs(joined%p_max - 2000.0_wp) < 1e-9_wp, &
         message='3.9 mm apart: the two patches should be joined')
      if (allocated(error)) return
      call join_lobes(geometry, [121, 121], patches, [0.0_wp, 8.1_wp], fx, fy, 0.3_wp, joined)
      call check(error, joined%n_members == 1 .and. joined%members(1) == 2 .and. &
         abs(joined%fn - 40000.0_wp) < 1e-9_wp .and. &
         abs(joined%fy_norm - 500.0_wp/12000.0_wp) < 1e-12_wp, &
         message='4.2 mm apart: the most loaded patch alone')
      if (allocated(error)) return
      patches(1)%load = 0.0_wp
      call join_lobes(geometry, [121, 121], patches, [0.0_wp, 0.0_wp], fx, fy, 0.3_wp, joined)
      call check(error, joined%n_members == 1 .and. joined%members(1) == 2, &
         message='an unloaded patch is never joined')
   end subroutine test_join_rule

end module test_validation_sets
