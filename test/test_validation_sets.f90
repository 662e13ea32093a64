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
      recommended_options, two_patch_solution, exact_positions
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
      0.030_wp, 0.011_wp, 0.007_wp, &
      0.128_wp, 0.067_wp, 0.017_wp, &
      0.057_wp, 0.012_wp, 0.029_wp &
      ], [3, 3])
   !> The two-lobe positions, the wheel's Σ against CONTACT's joined patch (432 cases).
   real(wp), parameter :: lobe_rows(3, 3) = reshape([ &
      0.022_wp, 0.010_wp, 0.008_wp, &
      0.070_wp, 0.057_wp, 0.037_wp, &
      0.046_wp, 0.016_wp, 0.021_wp &
      ], [3, 3])
   !> All 21 positions (4536 cases).
   real(wp), parameter :: all_rows(3, 3) = reshape([ &
      0.030_wp, 0.011_wp, 0.007_wp, &
      0.128_wp, 0.061_wp, 0.028_wp, &
      0.057_wp, 0.013_wp, 0.028_wp &
      ], [3, 3])

contains

   !> Collect the tests.
   subroutine collect_validation_sets(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [new_unittest('project_positions_pooled_vs_exact', test_pooled)]
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
   subroutine wheel_sum_errors(reduction, correction, ex, ey, error)
      character(len=*), intent(in) :: reduction
      integer, intent(in) :: correction
      real(wp), allocatable, intent(out) :: ex(:), ey(:)
      type(error_type), allocatable, intent(out) :: error
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
      end do
   end subroutine wheel_sum_errors

end module test_validation_sets
