!> Tests of the exact-ellipse correction (shcontact_tangential_ellipse_correction): the table is
!> the exact theory minus today's FASTSIM_SH, the corrected forces follow the exact theory on
!> ellipses off the table's nodes, and the symmetries and limits hold.
module test_ellipse_correction
   use testdrive, only: new_unittest, unittest_type, error_type, check
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_material, only: material_type
   use shcontact_normal_patch, only: normal_patch_type, ellipse_strip_patch
   use shcontact_tangential_options, only: tangential_options_type, correction_none, &
      correction_exact_ellipse, bound_ellipsoidal, parse_correction, correction_name, &
      corrected_model
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use shcontact_tangential_ellipse_correction, only: ellipse_correction_type, &
      prepare_ellipse_correction, ellipse_defect, table_node_case
   use test_validation, only: percentile, read_columns
   use shcontact_tangential_ellipse_table, only: n_table_ratio, n_table_t, n_table_ty, &
      n_table_phi, table_t_phi, table_unit, table_poisson, table_linear
   implicit none
   private
   public :: collect_ellipse_correction

   !> CONTACT's forces at the table's nodes, and on ellipses between them.
   character(len=*), parameter :: table_csv = 'data/exact/ellipse_table.csv'
   character(len=*), parameter :: check_csv = 'data/exact/ellipse_check.csv'

contains

   !> Collect the tests.
   subroutine collect_ellipse_correction(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('table_is_exact_minus_fastsim_sh', test_table_current), &
         new_unittest('exact_on_ellipses_between_nodes', test_between_nodes), &
         new_unittest('symmetries', test_symmetries), &
         new_unittest('limits', test_limits), &
         new_unittest('other_models_uncorrected', test_other_models), &
         new_unittest('option_parsing', test_option), &
         new_unittest('equivalent_ellipse_of_an_ellipse', test_equivalent_ellipse) &
         ]
   end subroutine collect_ellipse_correction

   !> The reference material of the table.
   pure type(material_type) function table_material()
      table_material = material_type(shear_modulus=82670.0_wp, poisson=table_poisson, &
         friction=0.3_wp)
   end function table_material

   !> Every 7th node of the table: CONTACT's force (data/exact/ellipse_table.csv) minus
   !> FASTSIM_SH without correction equals the tabulated defect to its rounding, and the file
   !> has every node of the grid. Fails when FASTSIM_SH changes and the table was not remade
   !> (scripts/contact_ellipse_table.py --skip-contact).
   subroutine test_table_current(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: rows(:, :), values(:, :)
      type(normal_patch_type) :: patch
      type(creepage_type) :: creepage
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(ellipse_correction_type) :: node
      type(lib_error), allocatable :: lerr
      real(wp) :: dfx, dfy, worst
      integer :: i, ip, n_checked, n_nodes

      call read_columns(table_csv, [character(len=7) :: 'i_ratio', 'k_x', 'k_y', 't_phi', 'fx', &
         'fy'], values, error)
      if (allocated(error)) return
      rows = transpose(values)
      n_nodes = n_table_ratio*n_table_t*(n_table_ty*n_table_phi - n_table_ty/2)
      call check(error, size(rows, 2) == n_nodes, message='the table CSV has '// &
         str_int(size(rows, 2))//' nodes, the grid '//str_int(n_nodes))
      if (allocated(error)) return
      options%fields = .false.
      options%correction = correction_none
      n_checked = 0
      worst = 0.0_wp
      do i = 1, size(rows, 2), 7
         ip = findloc(nint(1000*table_t_phi), nint(1000*rows(4, i)), dim=1)
         call check(error, ip > 0, message='t_phi of a CSV line is not a node')
         if (allocated(error)) return
         call table_node_case(nint(rows(1, i)), nint(rows(2, i)), nint(rows(3, i)), ip, &
            table_material(), patch, creepage)
         call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
         if (allocated(lerr)) exit
         call solve_prepared(ws, creepage, result, lerr)
         if (allocated(lerr)) exit
         ! The table's defect at the node, in our sign (D is odd: the same table).
         call prepare_ellipse_correction(node, patch%ellipse_a, patch%ellipse_b, patch%load, &
            table_material(), 0.0_wp, 1.0_wp, 0.0_wp)
         call ellipse_defect(node, creepage%nu_x, creepage%nu_y, creepage%phi, dfx, dfy)
         worst = max(worst, abs((-rows(5, i) - result%fx_norm) - dfx), &
            abs((-rows(6, i) - result%fy_norm) - dfy))
         n_checked = n_checked + 1
      end do
      call check(error, .not. allocated(lerr), message='solve failed on a table node')
      if (allocated(error)) return
      call check(error, n_checked > 3000 .and. worst <= 1.2_wp*table_unit, &
         message='table defect differs from exact − FASTSIM_SH by '//str_real(worst)// &
         '; remake the table (scripts/contact_ellipse_table.py --skip-contact)')
   end subroutine test_table_current

   !> Ellipses that are not table nodes, 37 cases each (pure spin sweeps and a 3³ set of ν_x, ν_y,
   !> φ), exact by CONTACT at 60 × 60 elements (data/exact/ellipse_check.csv). FASTSIM_SH with the
   !> correction is within
   !> * 0.008 of the exact f_x, f_y in every case and 0.002 in 80 % on the six of a/b = 0.29 … 6.9
   !>   (measured 0.0066 and 0.0012; without it 0.059 and 0.023);
   !> * 0.012 and 0.004 on the three long ones of a/b = 9.5, 15 and 18.8 (flange patches; measured
   !>   0.0105 and 0.0036);
   !> * 0.017 and 0.006 on a/b = 31.2, past the table's last node 25 (measured 0.0159, 0.0058).
   subroutine test_between_nodes(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: cols(:, :), values(:, :), e(:)
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(lib_error), allocatable :: lerr
      integer :: i, n

      call read_columns(check_csv, [character(len=10) :: 'a_mm', 'b_mm', 'nu_x', 'nu_y', &
         'phi_per_mm', 'fx', 'fy'], values, error)
      if (allocated(error)) return
      cols = transpose(values)
      n = size(cols, 2)
      allocate (e(2*n))
      options%fields = .false.
      do i = 1, n
         if (i == 1 .or. cols(1, i) /= cols(1, max(1, i - 1))) then
            call ellipse_strip_patch(cols(1, i), cols(2, i), 64700.0_wp, 100, 460.0_wp, patch)
            call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
            if (allocated(lerr)) exit
         end if
         call solve_prepared(ws, creepage_type(-cols(3, i), -cols(4, i), -cols(5, i)), result, &
            lerr)
         if (allocated(lerr)) exit
         e(2*i - 1) = abs(-result%fx_norm - cols(6, i))
         e(2*i) = abs(-result%fy_norm - cols(7, i))
      end do
      call check(error, .not. allocated(lerr), message='solve failed')
      if (allocated(error)) return
      call check(error, n == 370, message='ellipse_check.csv: expected 370 cases')
      if (allocated(error)) return
      call check_range(0.0_wp, 7.0_wp, 0.008_wp, 0.002_wp, error)
      if (allocated(error)) return
      call check_range(7.0_wp, 25.0_wp, 0.012_wp, 0.004_wp, error)
      if (allocated(error)) return
      call check_range(25.0_wp, huge(1.0_wp), 0.017_wp, 0.006_wp, error)
   contains
      !> max and P80 of the errors of the ellipses with lo < a/b ≤ hi.
      subroutine check_range(lo, hi, max_bound, p80_bound, error)
         real(wp), intent(in) :: lo, hi, max_bound, p80_bound
         type(error_type), allocatable, intent(out) :: error
         logical :: inside(2*n)
         real(wp), allocatable :: ein(:)
         integer :: k
         do k = 1, n
            inside(2*k - 1:2*k) = cols(1, k)/cols(2, k) > lo .and. cols(1, k)/cols(2, k) <= hi
         end do
         ein = pack(e, inside)
         call check(error, size(ein) > 0, message='no check ellipse with a/b in the range')
         if (allocated(error)) return
         k = (maxloc(merge(e, -1.0_wp, inside), dim=1) + 1)/2
         call check(error, maxval(ein) <= max_bound .and. percentile(ein, 0.8_wp) <= p80_bound, &
            message='max / P80 |Δf| on ellipses of a/b in ('//str_real(lo)//', '// &
            str_real(hi)//'] '//str_real(maxval(ein))//' / '//str_real(percentile(ein, 0.8_wp))// &
            ', expected <= '//str_real(max_bound)//' / '//str_real(p80_bound)// &
            '; the largest at a, b, nu_x, nu_y, phi = '//str_real(cols(1, k))//', '// &
            str_real(cols(2, k))//', '//str_real(cols(3, k))//', '//str_real(cols(4, k))//', '// &
            str_real(cols(5, k)))
      end subroutine check_range
   end subroutine test_between_nodes

   !> D is odd in the creepages; mirroring y flips ν_y, φ and D_y; ν_x → −ν_x flips D_x only.
   subroutine test_symmetries(error)
      type(error_type), allocatable, intent(out) :: error
      type(ellipse_correction_type) :: c
      real(wp) :: x0, y0, x1, y1
      real(wp), parameter :: nx = 7.0e-4_wp, ny = -4.0e-4_wp, ph = 9.0e-4_wp

      call prepare_ellipse_correction(c, 6.0_wp, 4.5_wp, 64700.0_wp, table_material(), &
         0.0_wp, 1.0_wp, 0.0_wp)
      call ellipse_defect(c, nx, ny, ph, x0, y0)
      call check(error, abs(x0) + abs(y0) > 1.0e-3_wp, message='defect expected here')
      if (allocated(error)) return
      call ellipse_defect(c, -nx, -ny, -ph, x1, y1)
      call check(error, abs(x1 + x0) + abs(y1 + y0) < 1.0e-14_wp, message='odd')
      if (allocated(error)) return
      call ellipse_defect(c, nx, -ny, -ph, x1, y1)
      call check(error, abs(x1 - x0) + abs(y1 + y0) < 1.0e-14_wp, message='mirror in y')
      if (allocated(error)) return
      call ellipse_defect(c, -nx, ny, ph, x1, y1)
      call check(error, abs(x1 + x0) + abs(y1 - y0) < 1.0e-14_wp, message='nu_x reversed')
   end subroutine test_symmetries

   !> No defect without creepage; none at full slip (t → 1), where both theories give μp along
   !> the rigid slip; and at small creepage (s = 0.005) the corrected forces are Kalker's linear
   !> theory, F_x = −G ab c₁₁ ν_x, F_y = −G ab c₂₂ ν_y − G (ab)^{3/2} c₂₃ φ, i.e. f = −3s, within
   !> 2 % for each creepage alone, where FASTSIM_SH alone (W1) is 31 % stiffer in ν_x and ν_y
   !> and within 0.1 % in spin (table_linear, doc/validation.md §6.4).
   subroutine test_limits(error)
      type(error_type), allocatable, intent(out) :: error
      type(ellipse_correction_type) :: c
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: r
      type(lib_error), allocatable :: lerr
      real(wp) :: dx, dy
      real(wp), parameter :: s = 0.005_wp, f_linear = -3.0_wp*s

      call ellipse_strip_patch(6.0_wp, 4.5_wp, 64700.0_wp, 100, 460.0_wp, patch)
      call prepare_ellipse_correction(c, 6.0_wp, 4.5_wp, patch%load, table_material(), &
         0.0_wp, 1.0_wp, 0.0_wp)
      call check(error, all(abs(table_linear(1:2, :)/3.0_wp - 0.31_wp) < 0.005_wp) .and. &
         all(abs(table_linear(3, :))/3.0_wp < 0.001_wp), &
         message='FASTSIM_SH linear slopes differ from the documented 31 % / 0.1 %')
      if (allocated(error)) return
      call ellipse_defect(c, 0.0_wp, 0.0_wp, 0.0_wp, dx, dy)
      call check(error, dx == 0.0_wp .and. dy == 0.0_wp, message='defect at zero creepage')
      if (allocated(error)) return
      call ellipse_defect(c, 1.0_wp, -1.0_wp, 0.1_wp, dx, dy)
      call check(error, abs(dx) + abs(dy) < 1.0e-3_wp, message='defect at full slip '// &
         str_real(dx)//', '//str_real(dy))
      if (allocated(error)) return
      options%fields = .false.
      call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
      call solve_prepared(ws, creepage_type(s/c%scale_x, 0.0_wp, 0.0_wp), r, lerr)
      call check(error, .not. allocated(lerr), message='solve failed')
      if (allocated(error)) return
      call check(error, r%fx_norm, f_linear, rel=.true., thr=0.02_wp, &
         message='f_x at small nu_x against the linear theory')
      if (allocated(error)) return
      call solve_prepared(ws, creepage_type(0.0_wp, s/c%scale_y, 0.0_wp), r, lerr)
      call check(error, r%fy_norm, f_linear, rel=.true., thr=0.02_wp, &
         message='f_y at small nu_y against the linear theory')
      if (allocated(error)) return
      call solve_prepared(ws, creepage_type(0.0_wp, 0.0_wp, s/c%scale_phi), r, lerr)
      call check(error, r%fy_norm, f_linear, rel=.true., thr=0.02_wp, &
         message='f_y at small phi against the linear theory')
   end subroutine test_limits

   !> Another bound gets no correction: its totals are the march's (the sum of its fields).
   subroutine test_other_models(error)
      type(error_type), allocatable, intent(out) :: error
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: plain, corrected
      type(lib_error), allocatable :: lerr
      type(creepage_type), parameter :: creepage = creepage_type(-5.0e-4_wp, 3.0e-4_wp, &
         -8.0e-4_wp)

      call ellipse_strip_patch(6.0_wp, 4.0_wp, 64700.0_wp, 60, 460.0_wp, patch)
      options%bound = bound_ellipsoidal
      call check(error, .not. corrected_model(options), message='ellipsoidal is not corrected')
      if (allocated(error)) return
      options%correction = correction_none
      call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
      call solve_prepared(ws, creepage, plain, lerr)
      options%correction = correction_exact_ellipse
      call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
      call solve_prepared(ws, creepage, corrected, lerr)
      call check(error, .not. allocated(lerr), message='solve failed')
      if (allocated(error)) return
      call check(error, corrected%fx == plain%fx .and. corrected%fy == plain%fy, &
         message='ellipsoidal bound changed by the correction')
      if (allocated(error)) return
      ! The default model is corrected, by a defect of the size the table holds here.
      options = tangential_options_type()
      call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
      call solve_prepared(ws, creepage, corrected, lerr)
      options%correction = correction_none
      call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
      call solve_prepared(ws, creepage, plain, lerr)
      call check(error, abs(corrected%fy_norm - plain%fy_norm) > 1.0e-3_wp, &
         message='default model not corrected')
   end subroutine test_other_models

   !> The option's names.
   subroutine test_option(error)
      type(error_type), allocatable, intent(out) :: error
      type(lib_error), allocatable :: lerr
      integer :: code

      call parse_correction('Exact_Ellipse', code, lerr)
      call check(error, .not. allocated(lerr) .and. code == correction_exact_ellipse .and. &
         correction_name(code) == 'exact-ellipse', message='exact-ellipse')
      if (allocated(error)) return
      call parse_correction('none', code, lerr)
      call check(error, code == correction_none, message='none')
      if (allocated(error)) return
      call parse_correction('hertz', code, lerr)
      call check(error, allocated(lerr), message='unknown correction accepted')
      if (allocated(error)) return
      call check(error, index(lerr%message, 'exact-ellipse') > 0, &
         message='the error names the choices: '//lerr%message)
   end subroutine test_option

   !> The equivalent ellipse of a Hertz ellipse's strip table is that ellipse (doc/tangential.md
   !> step 1: b_e from the load's lateral variance, a_e from the load-weighted strip length over
   !> 9π/32): the correction set up by the solver's preparation equals the one set up from the
   !> true semi-axes, at a/b = 0.3, 1 and 6 with 200 strips, to the strips' midpoint rule
   !> (scales within 0.2 %, ln(a/b) within 0.003). A wrong factor (the area's π/4 instead of 9π/32,
   !> 12 % in a_e) fails it.
   subroutine test_equivalent_ellipse(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: ratios(3) = [0.3_wp, 1.0_wp, 6.0_wp], area = 36.0_wp
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(ellipse_correction_type) :: exact
      type(lib_error), allocatable :: lerr
      real(wp) :: a, b
      integer :: i

      options%fields = .false.
      do i = 1, size(ratios)
         b = sqrt(area/(acos(-1.0_wp)*ratios(i)))
         a = ratios(i)*b
         call ellipse_strip_patch(a, b, 64700.0_wp, 200, 460.0_wp, patch)
         call prepare_fastsim_sh(ws, patch, table_material(), options, lerr)
         call check(error, .not. allocated(lerr), message='prepare_fastsim_sh failed')
         if (allocated(error)) return
         call check(error, ws%correction%active, message='correction not active')
         if (allocated(error)) return
         call prepare_ellipse_correction(exact, a, b, patch%load, table_material(), 0.0_wp, &
            1.0_wp, 0.0_wp)
         call check(error, abs(ws%correction%log_ratio - exact%log_ratio) <= 3.0e-3_wp .and. &
            abs(ws%correction%scale_x/exact%scale_x - 1.0_wp) <= 2.0e-3_wp .and. &
            abs(ws%correction%scale_phi/exact%scale_phi - 1.0_wp) <= 2.0e-3_wp, &
            message='a/b = '//str_real(ratios(i))//': equivalent ln(a/b), s_x, s_phi '// &
            str_real(ws%correction%log_ratio)//', '//str_real(ws%correction%scale_x)//', '// &
            str_real(ws%correction%scale_phi)//' against the ellipse''s '// &
            str_real(exact%log_ratio)//', '//str_real(exact%scale_x)//', '// &
            str_real(exact%scale_phi))
         if (allocated(error)) return
      end do
   end subroutine test_equivalent_ellipse

end module test_ellipse_correction
