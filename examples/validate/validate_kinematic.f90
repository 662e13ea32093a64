!> The kinematic call against the exact theory (issue 12): `solve_kinematic` on the 36 cases of
!> the external data's reference/kinematic_sample/ (CONTACT module 1, wheelset position and velocities
!> prescribed, F_z = 64.7 kN vertical; README there). Writes kinematic_cases.csv (one row per
!> case), kinematic_summary.csv (statistics per position/yaw group and overall) and kinematic.md
!> (the same as Markdown tables) to the output directory.
!>
!> **Signs.** CONTACT reports the rail's side (forces on the rail, creepages of the rail relative
!> to the wheel); we report the wheel's side. Every "ours" value below is turned to CONTACT's
!> sign (creepages, f_x, f_y and the track forces times −1) before it is compared.
!>
!> **Reference points.** Our creepages are those at our reference point, the geometric contact
!> point; CONTACT's are at its own reference point, the weighted centre of its patch. The rigid
!> slip w_x = ξ − φ·y, w_y = η + φ·x (README of ../shared/reference §4) carries ours to CONTACT's
!> point: ξ_ref = ξ_geo + φ̄·y_g, η_ref = η_geo − φ̄·x_g, where (x_g, y_g) is our point in CONTACT's
!> contact coordinates. y_g is the distance of the two points along CONTACT's contact plane:
!> y_g = Δy cos δ + Δz sin δ (track frame, z down, tangent (0, cos δ, sin δ)), x_g = Δx.
!> On a curved profile the spin itself changes between the points: the wheel's geometric spin is
!> Ω sin γ / V (wheel side; Ω the angular velocity about the axle), so φ at CONTACT's contact
!> angle δ is φ_ref = φ_geo − (sin δ − sin γ₀)·|Ω|/V in CONTACT's sign, and φ̄ is the mean of the
!> two (the trapezoidal rule for ∫φ dy, exact when sin γ varies linearly between the points).
!>
!> The patch compared with CONTACT's single patch is our most loaded one; all our patches enter
!> the track totals.
!>
!> **Diagnostic.** solve_kinematic carries the rigid slip to the strips with the 'additive' spin
!> model; CONTACT's module 1 applies a uniform rigid slip on a planar patch. For the cases without
!> yaw (whose geometry `solve` reproduces exactly) each case is solved a second time with `solve`,
!> the same creepages at the same point and the 'uniform' spin model (the library default for
!> prescribed creepages): f_x, f_y "uniform" in the tables.
!>
!> **CONTACT's conformal approach.** The sample was solved with CONTACT's planar contact (one
!> contact plane, a uniform rigid slip over it). data/exact/kinematic_conformal/ holds the same
!> decks solved with CONTACT's conformal approach (a curved contact surface whose rigid slip
!> carries each point's own rolling radius and contact angle, as solve_kinematic's strips do;
!> doc/validation.md §6.3). Where it has a case, our compared patch is set against it too
!> (dfx_conformal, dfy_conformal in kinematic_cases.csv and a row of the summary of every set).
module validate_kinematic
   use, intrinsic :: iso_fortran_env, only: output_unit
   use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
   use shcontact, only: wp, error_type, fatal_error, stat_invalid_input, track_type, &
      material_type, contact_solver_type, contact_load_type, contact_result_type, &
      load_vertical_force, wheelset_state_type, creepage_type
   use validate_csv, only: csv_table_type, read_csv, column, column_index, csv_writer_type
   use validate_tangential, only: error_stats_type, error_stats
   use validate_sets, only: pool_errors
   implicit none
   private

   public :: run_kinematic, kinematic_case_type, kinematic_group_type, solve_sample, &
      group_statistics, ftext, itext

   !> The sample's vertical wheel load (N), README.
   real(wp), parameter :: vertical_load = 64700.0_wp
   !> CONTACT's conformal approach on the sample's decks (data/exact/kinematic_conformal/README.md),
   !> relative to the repository root.
   character(len=*), parameter :: conformal_file = &
      'data/exact/kinematic_conformal/kinematic_conformal.csv'
   !> Its row in the summary of every set (validate_sets, doc/validation.md Table 12).
   character(len=*), parameter :: set_conformal = 'kinematic sample against CONTACT''s '// &
      'conformal approach (data/exact/kinematic_conformal)'
   !> Friction coefficient of the sample (README).
   real(wp), parameter :: friction = 0.3_wp

   !> One case of the sample: CONTACT's row and our solution, in CONTACT's signs.
   type :: kinematic_case_type
      character(len=8) :: name = ''
      !> False for CONTACT's failed case (skipped).
      logical :: ok = .false.
      !> Inputs: Y_WS (mm), yaw (rad), the kinematic set (ξ_k, η_k, ω_k).
      real(wp) :: y_ws = 0.0_wp, yaw = 0.0_wp, xi_k = 0.0_wp, eta_k = 0.0_wp, omega_k = 0.0_wp
      !> Our patches found and loaded, and the one compared (the most loaded).
      integer :: n_patches = 0, n_loaded = 0, main = 0
      !> Share of the summed normal force carried by our main patch.
      real(wp) :: main_share = 0.0_wp
      !> Reference point in track coordinates (mm): ours (geometric point) and CONTACT's.
      real(wp) :: x_ours = 0.0_wp, y_ours = 0.0_wp, z_ours = 0.0_wp
      real(wp) :: x_ref = 0.0_wp, y_ref = 0.0_wp, z_ref = 0.0_wp
      !> Contact angle (rad): our γ₀, CONTACT's δ.
      real(wp) :: gamma_ours = 0.0_wp, delta_ref = 0.0_wp
      !> Our point in CONTACT's contact coordinates (mm).
      real(wp) :: x_g = 0.0_wp, y_g = 0.0_wp
      !> Creepages (CONTACT's sign; φ in rad/mm): ours at our point, ours transferred to
      !> CONTACT's point, CONTACT's.
      real(wp) :: nux = 0.0_wp, nuy = 0.0_wp, phi = 0.0_wp
      real(wp) :: nux_t = 0.0_wp, nuy_t = 0.0_wp, phi_t = 0.0_wp
      real(wp) :: nux_ref = 0.0_wp, nuy_ref = 0.0_wp, phi_ref = 0.0_wp
      !> Our rolling radius at our point (mm), and CONTACT's at its point as its ξ implies:
      !> −ξ = 2(V − |Ω|r)/(V + |Ω|r) without yaw rate (0 when the case has a yaw rate).
      real(wp) :: r_ours = 0.0_wp, r_ref = 0.0_wp
      !> Normal force of the compared patch (N), ours and CONTACT's.
      real(wp) :: fn = 0.0_wp, fn_ref = 0.0_wp
      !> Our other loaded patches: their summed normal force (N) and the y of the largest.
      real(wp) :: fn_other = 0.0_wp, y_other = 0.0_wp
      !> f = F/(μF_n) on the rail, ours and CONTACT's.
      real(wp) :: fx = 0.0_wp, fy = 0.0_wp, fx_ref = 0.0_wp, fy_ref = 0.0_wp
      !> f of the wheel's joined contact (contact_result_type%wheel, doc/lobes.md), CONTACT's sign,
      !> and its number of patches.
      real(wp) :: fx_wheel = 0.0_wp, fy_wheel = 0.0_wp
      integer :: n_joined = 0
      !> CONTACT's conformal approach on the same deck (data/exact/kinematic_conformal/, module
      !> text): f on the rail of its most loaded patch, when that file has the case.
      logical :: has_conformal = .false.
      real(wp) :: fx_conformal = 0.0_wp, fy_conformal = 0.0_wp
      !> Diagnostic (module text): ours with the 'uniform' spin model, cases without yaw.
      logical :: has_uniform = .false.
      real(wp) :: fx_uniform = 0.0_wp, fy_uniform = 0.0_wp
      !> Totals on the rail in the track frame (N), ours and CONTACT's.
      real(wp) :: fx_tr = 0.0_wp, fy_tr = 0.0_wp, fz_tr = 0.0_wp
      real(wp) :: fx_tr_ref = 0.0_wp, fy_tr_ref = 0.0_wp, fz_tr_ref = 0.0_wp
   end type kinematic_case_type

   !> Statistics of one group of cases (a position and yaw angle, or all).
   type :: kinematic_group_type
      character(len=24) :: label = ''
      integer :: n = 0
      !> |Δf_x|, |Δf_y|, |ΔF_n|/F_n (compared patch) and |ΣF_n − F_n,ref|/F_n,ref (all our
      !> patches): largest, P80 (nearest rank), mean.
      type(error_stats_type) :: fx, fy, fn, fn_total
      !> Largest |Δν_x|, |Δν_y| (raw and transferred) and |Δφ| (rad/mm).
      real(wp) :: nux_raw = 0.0_wp, nuy_raw = 0.0_wp, nux_t = 0.0_wp, nuy_t = 0.0_wp, &
         phi = 0.0_wp, phi_t = 0.0_wp
   end type kinematic_group_type

contains

   !> Solve the sample, write the three tables and print the overall statistics.
   subroutine run_kinematic(sample_dir, profiles_dir, out_dir, error)
      !> Directory of kinematic_sample.csv (with a trailing '/').
      character(len=*), intent(in) :: sample_dir
      !> Directory of the MBench profile files.
      character(len=*), intent(in) :: profiles_dir
      !> Output directory.
      character(len=*), intent(in) :: out_dir
      !> Set when a file cannot be read or written, or a case fails.
      type(error_type), allocatable, intent(out) :: error
      type(kinematic_case_type), allocatable :: cases(:)
      type(kinematic_group_type), allocatable :: groups(:)

      call solve_sample(sample_dir//'kinematic_sample.csv', profiles_dir, cases, error)
      if (allocated(error)) return
      call read_conformal(conformal_file, cases, error)
      if (allocated(error)) return
      call group_statistics(cases, groups)
      call write_cases(out_dir//'kinematic_cases.csv', cases, error)
      if (allocated(error)) return
      call write_groups(out_dir//'kinematic_summary.csv', groups, error)
      if (allocated(error)) return
      call write_markdown(out_dir//'kinematic.md', cases, groups, error)
      if (allocated(error)) return
      ! The summary of every set (validate_sets): the compared patch of every solved case.
      call pool_errors('kinematic sample: external data, module 1, Y_WS 0 / 4.733 / 8 mm', 1, &
         pack(abs(cases%fx - cases%fx_ref), cases%ok), pack(abs(cases%fy - cases%fy_ref), &
         cases%ok), maxval(hypot(cases%fx, cases%fy), mask=cases%ok))
      call pool_errors('kinematic sample: the wheel''s joined contact (doc/lobes.md)', 1, &
         pack(abs(cases%fx_wheel - cases%fx_ref), cases%ok), &
         pack(abs(cases%fy_wheel - cases%fy_ref), cases%ok), &
         maxval(hypot(cases%fx_wheel, cases%fy_wheel), mask=cases%ok))
      ! The same patches against CONTACT's conformal approach (module text), where it solved.
      if (any(cases%has_conformal)) call pool_errors(set_conformal, 1, &
         pack(abs(cases%fx - cases%fx_conformal), cases%has_conformal), &
         pack(abs(cases%fy - cases%fy_conformal), cases%has_conformal), &
         maxval(hypot(cases%fx, cases%fy), mask=cases%has_conformal))
      write (output_unit, '(a,i0,a)') 'kinematic sample: the joined contact holds more than '// &
         'one patch in ', count(cases%ok .and. cases%n_joined > 1), ' cases'
      associate (g => groups(size(groups)))
         write (output_unit, '(a,i0,a,4(f7.4,a),2(f7.4,a))') 'kinematic sample: ', g%n, &
            ' cases; max/P80 |dfx| ', g%fx%max, '/', g%fx%p80, ', |dfy| ', g%fy%max, '/', &
            g%fy%p80, '; |dFn|/Fn max ', g%fn%max, ', P80 ', g%fn%p80, ''
      end associate
   end subroutine run_kinematic

   !> Read the sample and solve every case CONTACT solved (its failed case is kept, ok = .false.).
   subroutine solve_sample(path, profiles_dir, cases, error)
      !> kinematic_sample.csv.
      character(len=*), intent(in) :: path
      !> Directory of the MBench profile files.
      character(len=*), intent(in) :: profiles_dir
      !> The cases, in the file's order.
      type(kinematic_case_type), allocatable, intent(out) :: cases(:)
      !> Set when the file cannot be read or a case fails.
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: table
      type(contact_solver_type) :: solver
      type(track_type) :: track
      integer :: i, j_case, j_status

      call read_case_table(path, table, j_case, j_status, error)
      if (allocated(error)) return
      ! README: the MBench profiles, the rail file already canted; G = 82670 MPa, ν = 0.27,
      ! μ = 0.3; R₀ = 460 mm, flange-back distance 1360, position −70 (track_type's defaults).
      track%rail_canted = .true.
      call solver%init(profiles_dir//'MBench_S1002_v3.prw', profiles_dir// &
         'MBench_UIC60_v3.prr', error, track=track, material=material_type( &
         shear_modulus=82670.0_wp, poisson=0.27_wp, friction=friction))
      if (allocated(error)) return
      allocate (cases(table%rows()))
      do i = 1, table%rows()
         cases(i)%name = table%cells(i, j_case)
         cases(i)%ok = trim(table%cells(i, j_status)) == 'ok'
         call read_row(table, i, cases(i), error)
         if (allocated(error)) return
         if (.not. cases(i)%ok) cycle
         call solve_case(solver, table, i, cases(i), error)
         if (allocated(error)) return
      end do
   end subroutine solve_sample

   !> The inputs of row i (also for a failed case).
   subroutine read_row(table, i, c, error)
      type(csv_table_type), intent(in) :: table
      integer, intent(in) :: i
      type(kinematic_case_type), intent(inout) :: c
      type(error_type), allocatable, intent(out) :: error
      c%y_ws = cell(table, i, 'y_ws_mm', error)
      if (.not. allocated(error)) c%yaw = cell(table, i, 'yaw_rad', error)
      if (.not. allocated(error)) c%xi_k = cell(table, i, 'xi_k', error)
      if (.not. allocated(error)) c%eta_k = cell(table, i, 'eta_k', error)
      if (.not. allocated(error)) c%omega_k = cell(table, i, 'omega_k', error)
   end subroutine read_row

   !> Solve case i with solve_kinematic and fill both sides of the comparison.
   subroutine solve_case(solver, table, i, c, error)
      type(contact_solver_type), intent(inout) :: solver
      type(csv_table_type), intent(in) :: table
      integer, intent(in) :: i
      type(kinematic_case_type), intent(inout) :: c
      type(error_type), allocatable, intent(out) :: error
      type(wheelset_state_type) :: state
      type(contact_result_type) :: result
      character(len=*), parameter :: names(19) = [character(len=13) :: 'vs_mm_s', 'vy_mm_s', &
         'vyaw_rad_s', 'vpitch_rad_s', 'xcp_tr_mm', 'ycp_tr_mm', 'zcp_tr_mm', 'delta_rad', &
         'cksi', 'ceta', 'cphi_per_mm', 'fn_N', 'fx_norm', 'fs_norm', 'fx_tr_total_N', &
         'fy_tr_total_N', 'fz_tr_total_N', 'npatch', 'patch']
      real(wp) :: v(size(names))
      integer :: j

      do j = 1, size(names)
         v(j) = cell(table, i, trim(names(j)), error)
         if (allocated(error)) return
      end do
      if (nint(v(18)) /= 1) then
         call fatal_error(error, table%source//', case '//trim(c%name)// &
            ': expected one CONTACT patch per case', stat_invalid_input)
         return
      end if
      state = wheelset_state_type(y_ws=c%y_ws, yaw=c%yaw, v_forward=v(1), v_lateral=v(2), &
         yaw_rate=v(3), pitch_rate=v(4))
      call solver%solve_kinematic(state, contact_load_type(load_vertical_force, vertical_load), &
         result, error)
      if (allocated(error)) then
         error%message = 'case '//trim(c%name)//': '//error%message
         return
      end if
      c%x_ref = v(5); c%y_ref = v(6); c%z_ref = v(7); c%delta_ref = v(8)
      c%nux_ref = v(9); c%nuy_ref = v(10); c%phi_ref = v(11)
      c%fn_ref = v(12); c%fx_ref = v(13); c%fy_ref = v(14)
      c%fx_tr_ref = v(15); c%fy_tr_ref = v(16); c%fz_tr_ref = v(17)
      if (v(3) == 0.0_wp) c%r_ref = (2.0_wp + c%nux_ref)/(2.0_wp - c%nux_ref)*v(1)/abs(v(4))
      call take_ours(result, abs(v(4))/v(1), c)
      if (c%yaw /= 0.0_wp) return
      associate (p => result%main)
         call solver%solve(c%y_ws, 0.0_wp, contact_load_type(load_vertical_force, &
            vertical_load), creepage_type(p%nu_x, p%nu_y, p%phi), result, error)
      end associate
      if (allocated(error)) return
      c%has_uniform = .true.
      c%fx_uniform = -result%main%fx_norm
      c%fy_uniform = -result%main%fy_norm
   end subroutine solve_case

   !> A CSV with one row per case: the table and the columns "case" and "status".
   subroutine read_case_table(path, table, j_case, j_status, error)
      character(len=*), intent(in) :: path
      type(csv_table_type), intent(out) :: table
      integer, intent(out) :: j_case, j_status
      type(error_type), allocatable, intent(out) :: error

      call read_csv(path, table, error)
      if (allocated(error)) return
      j_case = column_index(table, 'case')
      j_status = column_index(table, 'status')
      if (j_case == 0 .or. j_status == 0) then
         call fatal_error(error, path//': expected the columns "case" and "status"', &
            stat_invalid_input)
         return
      end if
   end subroutine read_case_table

   !> CONTACT's conformal approach on the sample's decks (module text), by case name; without
   !> the file nothing is read. Only its cases with status ok are compared.
   subroutine read_conformal(path, cases, error)
      character(len=*), intent(in) :: path
      type(kinematic_case_type), intent(inout) :: cases(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: table
      logical :: there
      integer :: i, k, j_case, j_status

      inquire (file=path, exist=there)
      if (.not. there) return
      call read_case_table(path, table, j_case, j_status, error)
      if (allocated(error)) return
      do i = 1, table%rows()
         if (trim(table%cells(i, j_status)) /= 'ok') cycle
         k = findloc(cases%name, trim(table%cells(i, j_case)), 1)
         if (k == 0) cycle
         if (.not. cases(k)%ok) cycle
         cases(k)%fx_conformal = cell(table, i, 'fx_norm', error)
         if (.not. allocated(error)) cases(k)%fy_conformal = cell(table, i, 'fs_norm', error)
         if (allocated(error)) return
         cases(k)%has_conformal = .true.
      end do
   end subroutine read_conformal

   !> Our main patch and totals, in CONTACT's signs, and the creepage transfer (module text).
   pure subroutine take_ours(result, spin_rate, c)
      type(contact_result_type), intent(in) :: result
      !> |Ω|/V (1/mm): the geometric spin per unit sin γ.
      real(wp), intent(in) :: spin_rate
      type(kinematic_case_type), intent(inout) :: c
      integer :: k, other
      real(wp) :: phi_mean

      other = 0
      do k = 1, result%n_loaded
         if (k == result%main_patch .or. .not. (result%patch(k)%fn > 0.0_wp)) cycle
         c%fn_other = c%fn_other + result%patch(k)%fn
         if (other == 0) then
            other = k
         else if (result%patch(k)%fn > result%patch(other)%fn) then
            other = k
         end if
      end do
      if (other > 0) c%y_other = result%patch(other)%y_track
      c%n_patches = result%n_patches
      c%n_loaded = count(result%patch(1:result%n_loaded)%fn > 0.0_wp)
      c%main = result%main_patch
      c%main_share = result%main%fn/result%track%fn
      associate (p => result%main)
         c%x_ours = p%x_track; c%y_ours = p%y_track; c%z_ours = p%z_track
         c%gamma_ours = p%gamma0
         c%r_ours = p%r0
         c%nux = -p%nu_x; c%nuy = -p%nu_y; c%phi = -p%phi
         c%fn = p%fn
         c%fx = -p%fx_norm; c%fy = -p%fy_norm
      end associate
      c%fx_wheel = -result%wheel%fx_norm
      c%fy_wheel = -result%wheel%fy_norm
      c%n_joined = result%wheel%n_members
      c%fx_tr = -result%track%fx
      c%fy_tr = -result%track%fy
      c%fz_tr = -result%track%fz
      c%x_g = c%x_ours - c%x_ref
      c%y_g = (c%y_ours - c%y_ref)*cos(c%delta_ref) + (c%z_ours - c%z_ref)*sin(c%delta_ref)
      c%phi_t = c%phi - (sin(c%delta_ref) - sin(c%gamma_ours))*spin_rate
      phi_mean = 0.5_wp*(c%phi + c%phi_t)
      c%nux_t = c%nux + phi_mean*c%y_g
      c%nuy_t = c%nuy - phi_mean*c%x_g
   end subroutine take_ours

   !> One numeric cell by column name.
   real(wp) function cell(table, i, name, error)
      type(csv_table_type), intent(in) :: table
      integer, intent(in) :: i
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error
      integer :: j, stat
      cell = 0.0_wp
      j = column_index(table, name)
      if (j == 0) then
         call fatal_error(error, table%source//': no column "'//name//'"', stat_invalid_input)
         return
      end if
      read (table%cells(i, j), *, iostat=stat) cell
      if (stat /= 0) call fatal_error(error, table%source//', row '//trim(table%cells(i, 1))// &
         ', column "'//name//'": "'//trim(table%cells(i, j))//'" is not a number', &
         stat_invalid_input)
   end function cell

   !> Statistics per (Y_WS, yaw) group in the order met, then over all solved cases (last).
   subroutine group_statistics(cases, groups)
      !> The cases.
      type(kinematic_case_type), intent(in) :: cases(:)
      !> The groups; the last one holds every solved case.
      type(kinematic_group_type), allocatable, intent(out) :: groups(:)
      real(wp), allocatable :: keys(:, :)
      logical :: member(size(cases))
      integer :: i, k, n_keys
      character(len=24) :: label

      allocate (keys(2, size(cases)))
      n_keys = 0
      do i = 1, size(cases)
         if (.not. cases(i)%ok) cycle
         if (any([(same_group(cases(i), keys(:, k)), k=1, n_keys)])) cycle
         n_keys = n_keys + 1
         keys(:, n_keys) = [cases(i)%y_ws, cases(i)%yaw]
      end do
      allocate (groups(n_keys + 1))
      do k = 1, n_keys
         member = [(cases(i)%ok .and. same_group(cases(i), keys(:, k)), i=1, size(cases))]
         label = 'Y_WS '//ftext(keys(1, k), 3)//', yaw '//ftext(1.0e3_wp*keys(2, k), 0)// &
            ' mrad'
         groups(k) = group_of(pack(cases, member), label)
      end do
      groups(n_keys + 1) = group_of(pack(cases, cases%ok), 'all')
   end subroutine group_statistics

   pure logical function same_group(c, key)
      type(kinematic_case_type), intent(in) :: c
      real(wp), intent(in) :: key(2)
      same_group = abs(c%y_ws - key(1)) < 1.0e-9_wp .and. abs(c%yaw - key(2)) < 1.0e-12_wp
   end function same_group

   !> The statistics of a set of solved cases.
   pure function group_of(cases, label) result(g)
      type(kinematic_case_type), intent(in) :: cases(:)
      character(len=*), intent(in) :: label
      type(kinematic_group_type) :: g
      g%label = label
      g%n = size(cases)
      g%fx = error_stats(abs(cases%fx - cases%fx_ref))
      g%fy = error_stats(abs(cases%fy - cases%fy_ref))
      g%fn = error_stats(abs(cases%fn - cases%fn_ref)/cases%fn_ref)
      g%fn_total = error_stats(abs(cases%fn + cases%fn_other - cases%fn_ref)/cases%fn_ref)
      g%nux_raw = maxval(abs(cases%nux - cases%nux_ref))
      g%nuy_raw = maxval(abs(cases%nuy - cases%nuy_ref))
      g%nux_t = maxval(abs(cases%nux_t - cases%nux_ref))
      g%nuy_t = maxval(abs(cases%nuy_t - cases%nuy_ref))
      g%phi = maxval(abs(cases%phi - cases%phi_ref))
      g%phi_t = maxval(abs(cases%phi_t - cases%phi_ref))
   end function group_of

   !> kinematic_cases.csv: one row per case (failed case: inputs only, status failed).
   subroutine write_cases(path, cases, error)
      character(len=*), intent(in) :: path
      type(kinematic_case_type), intent(in) :: cases(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      integer :: i

      call out%open(path, 'case,status,y_ws_mm,yaw_rad,xi_k,eta_k,omega_k,n_patches,'// &
         'n_loaded,main_patch,main_share,x_ours_mm,dx_mm,y_ours_mm,dy_mm,z_ours_mm,dz_mm,'// &
         'gamma_ours_rad,dgamma_rad,x_g_mm,y_g_mm,nux_ours,nux_ours_transferred,'// &
         'dnux_transferred,nuy_ours,nuy_ours_transferred,dnuy_transferred,phi_ours_per_mm,'// &
         'phi_ours_transferred_per_mm,dphi_transferred_per_mm,r_ours_mm,dr_mm,fn_ours_N,'// &
         'fn_rel_err,fn_other_patches_N,y_other_patch_mm,fx_ours_uniform,fy_ours_uniform,'// &
         'fx_ours,fy_ours,dfx,dfy,fx_tr_ours_N,dfx_tr_N,fy_tr_ours_N,dfy_tr_N,fz_tr_ours_N,'// &
         'dfz_tr_N,dfx_conformal,dfy_conformal', error)
      if (allocated(error)) return
      do i = 1, size(cases)
         associate (c => cases(i))
            if (.not. c%ok) then
               call out%row([c%y_ws, c%yaw, c%xi_k, c%eta_k, c%omega_k], &
                  text=[character(len=8) :: c%name, 'failed'])
               cycle
            end if
            ! Ours and ours minus CONTACT's (d...): the reference values themselves stay in
            ! ../shared/reference.
            call out%row([c%y_ws, c%yaw, c%xi_k, c%eta_k, c%omega_k, real(c%n_patches, wp), &
               real(c%n_loaded, wp), real(c%main, wp), c%main_share, c%x_ours, &
               c%x_ours - c%x_ref, c%y_ours, c%y_ours - c%y_ref, c%z_ours, c%z_ours - c%z_ref, &
               c%gamma_ours, c%gamma_ours - c%delta_ref, c%x_g, c%y_g, c%nux, c%nux_t, &
               c%nux_t - c%nux_ref, c%nuy, c%nuy_t, c%nuy_t - c%nuy_ref, c%phi, c%phi_t, &
               c%phi_t - c%phi_ref, c%r_ours, c%r_ours - c%r_ref, c%fn, &
               (c%fn - c%fn_ref)/c%fn_ref, c%fn_other, c%y_other, c%fx_uniform, c%fy_uniform, &
               c%fx, c%fy, c%fx - c%fx_ref, c%fy - c%fy_ref, c%fx_tr, c%fx_tr - c%fx_tr_ref, &
               c%fy_tr, c%fy_tr - c%fy_tr_ref, c%fz_tr, c%fz_tr - c%fz_tr_ref, &
               merge(c%fx - c%fx_conformal, ieee_value(1.0_wp, ieee_quiet_nan), &
               c%has_conformal), merge(c%fy - c%fy_conformal, &
               ieee_value(1.0_wp, ieee_quiet_nan), c%has_conformal)], &
               text=[character(len=8) :: c%name, 'ok'])
         end associate
      end do
      call out%close()
   end subroutine write_cases

   !> kinematic_summary.csv: one row per group.
   subroutine write_groups(path, groups, error)
      character(len=*), intent(in) :: path
      type(kinematic_group_type), intent(in) :: groups(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      integer :: k

      call out%open(path, 'group,n,dfx_max,dfx_p80,dfx_mean,dfy_max,dfy_p80,dfy_mean,'// &
         'dfn_rel_max,dfn_rel_p80,dfn_rel_mean,dfn_total_rel_max,dfn_total_rel_p80,dnux_raw_max,dnux_transferred_max,'// &
         'dnuy_raw_max,dnuy_transferred_max,dphi_raw_max_per_mm,dphi_transferred_max_per_mm', &
         error)
      if (allocated(error)) return
      do k = 1, size(groups)
         associate (g => groups(k))
            call out%row([real(g%n, wp), g%fx%max, g%fx%p80, g%fx%mean, g%fy%max, g%fy%p80, &
               g%fy%mean, g%fn%max, g%fn%p80, g%fn%mean, g%fn_total%max, g%fn_total%p80, &
               g%nux_raw, g%nux_t, g%nuy_raw, &
               g%nuy_t, g%phi, g%phi_t], text=[g%label], digits=5)
         end associate
      end do
      call out%close()
   end subroutine write_groups

   !> kinematic.md: the per-case tables (creepages; point, forces) and the statistics.
   subroutine write_markdown(path, cases, groups, error)
      character(len=*), intent(in) :: path
      type(kinematic_case_type), intent(in) :: cases(:)
      type(kinematic_group_type), intent(in) :: groups(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: msg
      integer :: unit, stat, i, k

      open (newunit=unit, file=path, status='replace', action='write', iostat=stat, iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, path//': cannot write ('//trim(msg)//')')
         return
      end if
      write (unit, '(a)') '<!-- written by `fpm run --example shcontact-validate --profile '// &
         'release -- --kinematic`; CONTACT''s signs (rail side) throughout -->', '', &
         'Statistics (f = F/(μF_n) of the compared patch; P80 = 80th percentile, nearest rank).', &
         '', '| group | cases | max \|Δf_x\| | P80 \|Δf_x\| | max \|Δf_y\| | P80 \|Δf_y\| | '// &
         'max \|ΔF_n\|/F_n | P80 \|ΔF_n\|/F_n | max \|ΔΣF_n\|/F_n | max \|Δξ\| raw / transferred (‰) | '// &
         'max \|Δη\| raw / transferred (‰) | max \|Δφ\| raw / transferred (1/m) |', &
         '|---|---|---|---|---|---|---|---|---|---|---|---|'
      do k = 1, size(groups)
         associate (g => groups(k))
            write (unit, '(a)') '| '//trim(g%label)//' | '//itext(g%n)//' | '// &
               ftext(g%fx%max, 3)//' | '//ftext(g%fx%p80, 3)//' | '//ftext(g%fy%max, 3)// &
               ' | '//ftext(g%fy%p80, 3)//' | '//ftext(g%fn%max, 3)//' | '// &
               ftext(g%fn%p80, 3)//' | '//ftext(g%fn_total%max, 3)//' | '// &
               ftext(1.0e3_wp*g%nux_raw, 3)//' / '// &
               ftext(1.0e3_wp*g%nux_t, 3)//' | '//ftext(1.0e3_wp*g%nuy_raw, 3)//' / '// &
               ftext(1.0e3_wp*g%nuy_t, 3)//' | '//ftext(1.0e3_wp*g%phi, 4)//' / '// &
               ftext(1.0e3_wp*g%phi_t, 4)//' |'
         end associate
      end do
      write (unit, '(a)') '', 'Creepages (‰; φ in 1/m): ours at our geometric point, ours '// &
         'transferred to CONTACT''s reference point, and that minus CONTACT''s (Δ; CONTACT''s '// &
         'values are in the external data''s reference/kinematic_sample).', '', &
         '| case | Y_WS | yaw (mrad) | ξ_k, η_k, ω_k (‰) | y_g (mm) | x_g (mm) | '// &
         'ξ ours / transf. / Δ | η ours / transf. / Δ | φ ours / transf. / Δ |', &
         '|---|---|---|---|---|---|---|---|---|'
      do i = 1, size(cases)
         associate (c => cases(i))
            if (.not. c%ok) then
               write (unit, '(a)') '| '//trim(c%name)//' | '//ftext(c%y_ws, 3)//' | '// &
                  ftext(1.0e3_wp*c%yaw, 0)//' | '//kin_text(c)//' | failed in CONTACT '// &
                  '(skipped) | | | | |'
               cycle
            end if
            write (unit, '(a)') '| '//trim(c%name)//' | '//ftext(c%y_ws, 3)//' | '// &
               ftext(1.0e3_wp*c%yaw, 0)//' | '//kin_text(c)//' | '//ftext(c%y_g, 3)//' | '// &
               ftext(c%x_g, 3)//' | '//ftext(1.0e3_wp*c%nux, 3)//' / '// &
               ftext(1.0e3_wp*c%nux_t, 3)//' / '// &
               ftext(1.0e3_wp*(c%nux_t - c%nux_ref), 3, signed=.true.)//' | '// &
               ftext(1.0e3_wp*c%nuy, 3)//' / '//ftext(1.0e3_wp*c%nuy_t, 3)//' / '// &
               ftext(1.0e3_wp*(c%nuy_t - c%nuy_ref), 3, signed=.true.)//' | '// &
               ftext(1.0e3_wp*c%phi, 4)//' / '//ftext(1.0e3_wp*c%phi_t, 4)//' / '// &
               ftext(1.0e3_wp*(c%phi_t - c%phi_ref), 4, signed=.true.)//' |'
         end associate
      end do
      write (unit, '(a)') '', 'Contact point, normal force and forces (ours / ours minus '// &
         'CONTACT; '// &
         'y in track coordinates, x = lead along the track; totals on the rail, kN). "patches" '// &
         'counts our loaded patches; the others carry F_n,other at y_other. "uniform": ours '// &
         'with the uniform spin model (cases without yaw, module text).', '', &
         '| case | patches (F_n,other kN @ y_other) | y (mm) | x (mm) | δ (°) | F_n (kN) | '// &
         'f_x | f_y | Δf_x, Δf_y | uniform: Δf_x, Δf_y | F_x,tr | F_y,tr | F_z,tr |', &
         '|---|---|---|---|---|---|---|---|---|---|---|---|---|'
      do i = 1, size(cases)
         associate (c => cases(i))
            if (.not. c%ok) cycle
            write (unit, '(a)') '| '//trim(c%name)//' | '//patches_text(c)//' | '// &
               pair(c%y_ours, c%y_ref, 2)//' | '//pair(c%x_ours, c%x_ref, 2)//' | '// &
               pair(degrees(c%gamma_ours), degrees(c%delta_ref), 1)//' | '// &
               pair(1.0e-3_wp*c%fn, 1.0e-3_wp*c%fn_ref, 1)//' | '//ftext(c%fx, 3)//' | '// &
               ftext(c%fy, 3)//' | '//ftext(c%fx - c%fx_ref, 3, signed=.true.)//', '// &
               ftext(c%fy - c%fy_ref, 3, signed=.true.)//' | '//uniform_text(c)//' | '// &
               pair(1.0e-3_wp*c%fx_tr, 1.0e-3_wp*c%fx_tr_ref, 2)//' | '// &
               pair(1.0e-3_wp*c%fy_tr, 1.0e-3_wp*c%fy_tr_ref, 2)//' | '// &
               pair(1.0e-3_wp*c%fz_tr, 1.0e-3_wp*c%fz_tr_ref, 2)//' |'
         end associate
      end do
      close (unit)
   end subroutine write_markdown

   !> "ours / ours − CONTACT's" with d decimals.
   function pair(ours, ref, d) result(text)
      real(wp), intent(in) :: ours, ref
      integer, intent(in) :: d
      character(len=:), allocatable :: text
      text = ftext(ours, d)//' / '//ftext(ours - ref, d, signed=.true.)
   end function pair

   !> Δf_x, Δf_y of the uniform-spin diagnostic, or a dash.
   function uniform_text(c) result(text)
      type(kinematic_case_type), intent(in) :: c
      character(len=:), allocatable :: text
      text = '–'
      if (c%has_uniform) text = ftext(c%fx_uniform - c%fx_ref, 3, signed=.true.)//', '// &
         ftext(c%fy_uniform - c%fy_ref, 3, signed=.true.)
   end function uniform_text

   !> Our loaded patches, and the others' load and position when there are several.
   function patches_text(c) result(text)
      type(kinematic_case_type), intent(in) :: c
      character(len=:), allocatable :: text
      text = itext(c%n_loaded)
      if (c%n_loaded > 1) text = text//' ('//ftext(1.0e-3_wp*c%fn_other, 1)//' @ '// &
         ftext(c%y_other, 1)//')'
   end function patches_text

   !> "ξ_k, η_k, ω_k" in ‰.
   function kin_text(c) result(text)
      type(kinematic_case_type), intent(in) :: c
      character(len=:), allocatable :: text
      text = ftext(1.0e3_wp*c%xi_k, 0)//', '//ftext(1.0e3_wp*c%eta_k, 0)//', '// &
         ftext(1.0e3_wp*c%omega_k, 0)
   end function kin_text

   pure real(wp) function degrees(rad)
      real(wp), intent(in) :: rad
      degrees = rad*45.0_wp/atan(1.0_wp)
   end function degrees

   !> x with `decimals` decimals, a typographic minus, "+" when signed and positive.
   function ftext(x, decimals, signed) result(text)
      real(wp), intent(in) :: x
      integer, intent(in) :: decimals
      logical, intent(in), optional :: signed
      character(len=:), allocatable :: text
      character(len=40) :: buf, fmt
      real(wp) :: r
      r = x
      ! No "−0.000": values that print as zero are zero.
      if (abs(x) < 0.5_wp*10.0_wp**(-decimals)) r = 0.0_wp
      write (fmt, '(a,i0,a)') '(f0.', decimals, ')'
      write (buf, fmt) abs(r)
      text = trim(buf)
      if (text(1:1) == '.') text = '0'//text
      if (text(len(text):len(text)) == '.') text = text(1:len(text) - 1)
      if (r < 0.0_wp) then
         text = '−'//text
      else if (present(signed)) then
         if (signed) text = '+'//text
      end if
   end function ftext

   function itext(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=16) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function itext

end module validate_kinematic
