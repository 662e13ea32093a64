!> The project's own kinematic exact-theory sets (doc/validation.md §6.7, issue 28): CONTACT
!> module 1 with the wheelset position and velocities prescribed, run by
!> scripts/contact_kinematic_set.py on profiles the project writes itself, in the columns of the
!> shared kinematic sample (data/exact/kinematic_*/README.md). No external data is needed.
!>
!> Each case is solved with `solve_kinematic` (defaults, F_z = 64.7 kN vertical). CONTACT may
!> report several patches per case (one row each). Every loaded patch of ours goes to the CONTACT
!> patch nearest to it in track y; the patches that go to one CONTACT patch are joined there as
!> the wheel's joined contact is (ΣF, ΣF_n, each force in its own plane), and compared with it:
!> f = F/(μF_n) on the rail (ours times −1), the normal force, the peak pressure and the area
!> (CONTACT's elements in contact × 0.04 mm²). A CONTACT patch with no patch of ours, and a
!> patch of ours carrying more than 1 % of the load more than 8 mm (CONTACT's separation
!> distance) from every CONTACT patch, are counted as missed and extra patches.
module validate_kinematic_sets
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: wp, error_type, fatal_error, stat_invalid_input, track_type, &
      material_type, contact_solver_type, contact_load_type, contact_result_type, &
      load_vertical_force, wheelset_state_type, normal_options_type, new_normal_options, &
      tangential_options_type, contact_options_type
   use shcontact_tangential_options, only: parse_correction
   use validate_csv, only: csv_table_type, read_csv, column_index, csv_writer_type
   use validate_tangential, only: error_stats_type, error_stats
   use validate_sets, only: pool_errors
   use validate_kinematic, only: ftext, itext
   implicit none
   private

   public :: run_kinematic_sets, kinematic_set_type, kinematic_sets, set_patches_type, &
      solve_kinematic_set, n_kinematic_sets

   !> The sets' vertical wheel load (N) and friction coefficient (scripts/contact_kinematic_set.py).
   real(wp), parameter :: vertical_load = 64700.0_wp, friction = 0.3_wp
   !> CONTACT's element area (mm²): the 0.2 mm grid.
   real(wp), parameter :: element_area = 0.04_wp
   !> CONTACT's patch separation distance (mm); the share of the load (1 %) that makes a patch
   !> of ours count as extra when no CONTACT patch lies within it.
   real(wp), parameter :: separation = 8.0_wp, extra_share = 0.01_wp

   !> One set: its file (relative to the repository root), its profiles and its label.
   type :: kinematic_set_type
      character(len=64) :: file = ''
      character(len=64) :: wheel = '', rail = ''
      character(len=120) :: label = ''
   end type kinematic_set_type

   integer, parameter :: n_kinematic_sets = 6
   !> The sets (data/exact/kinematic_flange/README.md, data/exact/kinematic_worn/README.md,
   !> data/exact/kinematic_root/README.md).
   type(kinematic_set_type), parameter :: kinematic_sets(n_kinematic_sets) = [ &
      kinematic_set_type('data/exact/kinematic_flange/kinematic_planar.csv', &
      'builtin:S1002', 'builtin:UIC60-canted', 'kinematic flange: S1002/UIC60, Y_WS 6.5'// &
      '–8.5 mm × yaw 0/±8 mrad × 6 sets, planar'), &
      kinematic_set_type('data/exact/kinematic_flange/kinematic_conformal.csv', &
      'builtin:S1002', 'builtin:UIC60-canted', 'kinematic flange: the same, CONTACT''s '// &
      'conformal approach'), &
      kinematic_set_type('data/exact/kinematic_worn/kinematic_planar.csv', &
      'data/profiles/worn/S1002-worn.txt', 'data/profiles/worn/UIC60-canted-worn.txt', &
      'kinematic worn pair: Y_WS −2…6 mm × yaw 0/4 mrad × 6 sets, planar'), &
      kinematic_set_type('data/exact/kinematic_worn/kinematic_conformal.csv', &
      'data/profiles/worn/S1002-worn.txt', 'data/profiles/worn/UIC60-canted-worn.txt', &
      'kinematic worn pair: the same, CONTACT''s conformal approach'), &
      kinematic_set_type('data/exact/kinematic_root/kinematic_planar.csv', &
      'builtin:S1002', 'builtin:UIC60-canted', 'kinematic flange root: S1002/UIC60, Y_WS '// &
      '6.55–6.9 mm × yaw 0/±8 mrad × sets 1, 3, 6, planar'), &
      kinematic_set_type('data/exact/kinematic_root/kinematic_conformal.csv', &
      'builtin:S1002', 'builtin:UIC60-canted', 'kinematic flange root: the same, CONTACT''s '// &
      'conformal approach')]

   !> Every CONTACT patch of a set compared: the case, its inputs, CONTACT's values and ours
   !> (CONTACT's signs: forces on the rail).
   type :: set_patches_type
      integer :: n = 0
      character(len=8), allocatable :: name(:)
      real(wp), allocatable :: y_ws(:), yaw(:), xi_k(:), eta_k(:), omega_k(:)
      !> CONTACT: track y of the reference point (mm), f_x, f_y, F_n (N), p_max (MPa), area (mm²).
      real(wp), allocatable :: y_ref(:), fx_ref(:), fy_ref(:), fn_ref(:), pmax_ref(:), &
         area_ref(:)
      !> Contact angle (rad): CONTACT's δ, ours (the normal-force-weighted γ₀ of the members).
      real(wp), allocatable :: delta_ref(:), gamma(:)
      !> The case's lateral force on the rail in the track frame (N): CONTACT's, ours.
      real(wp), allocatable :: fy_tr_ref(:), fy_tr(:)
      !> Ours, joined over the patches that go to it (0 members: missed).
      integer, allocatable :: members(:)
      real(wp), allocatable :: y(:), fx(:), fy(:), fn(:), pmax(:), area(:)
      !> Cases solved, CONTACT's failed cases, our extra patches, largest |f| of our patches.
      integer :: n_cases = 0, n_failed = 0, n_extra = 0
      real(wp) :: f_max = 0.0_wp
   end type set_patches_type

contains

   !> Solve every set present, pool its errors into the summary of every set (validate_sets;
   !> the defaults and the main alternatives, normal reduction `local-hertz` and correction
   !> `none`) and write kinematic_sets.csv and kinematic_sets.md (defaults) to out_dir.
   subroutine run_kinematic_sets(out_dir, error)
      character(len=*), intent(in) :: out_dir
      type(error_type), allocatable, intent(out) :: error
      type(set_patches_type) :: s(n_kinematic_sets), conformal(n_kinematic_sets)
      logical :: there(n_kinematic_sets)
      type(set_patches_type) :: alt
      integer :: k

      do k = 1, n_kinematic_sets
         inquire (file=trim(kinematic_sets(k)%file), exist=there(k))
         if (.not. there(k)) cycle
         call solve_kinematic_set(kinematic_sets(k), s(k), error)
         if (allocated(error)) return
         call pool_set(kinematic_sets(k), s(k), 1)
         call solve_kinematic_set(kinematic_sets(k), alt, error, reduction='local-hertz')
         if (allocated(error)) return
         call pool_set(kinematic_sets(k), alt, 2)
         call solve_kinematic_set(kinematic_sets(k), alt, error, correction='none')
         if (allocated(error)) return
         call pool_set(kinematic_sets(k), alt, 3)
         call solve_kinematic_set(kinematic_sets(k), conformal(k), error, conformal_tables=.true.)
         if (allocated(error)) return
         write (output_unit, '(a,i0,a,i0,a)') 'kinematic set '//trim(kinematic_sets(k)%file)// &
            ': ', s(k)%n_cases, ' cases, ', s(k)%n, ' CONTACT patches'
      end do
      call write_csv(out_dir//'kinematic_sets.csv', s, there, error)
      if (allocated(error)) return
      call write_markdown(out_dir//'kinematic_sets.md', s, there, error)
      if (allocated(error)) return
      ! The option `&normal strip_tables = 'conformal'` (doc/validation.md §6.7, "Conformal
      ! strip tables").
      call write_csv(out_dir//'kinematic_sets_conformal_tables.csv', conformal, there, error)
      if (allocated(error)) return
      call write_markdown(out_dir//'kinematic_sets_conformal_tables.md', conformal, there, error, &
         option='with `&normal strip_tables = ''conformal''`')
   end subroutine run_kinematic_sets

   !> Every CONTACT patch of the sets present and ours beside it, one row each.
   subroutine write_csv(path, s, there, error)
      character(len=*), intent(in) :: path
      type(set_patches_type), intent(in) :: s(:)
      logical, intent(in) :: there(:)
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      integer :: k, i
      call out%open(path, 'set,case,y_ws_mm,yaw_rad,xi_k,eta_k,'// &
         'omega_k,members,y_ref_mm,y_mm,fx_ref,fx,fy_ref,fy,fn_ref_N,fn_N,pmax_ref_MPa,'// &
         'pmax_MPa,area_ref_mm2,area_mm2,delta_ref_rad,gamma_rad,fy_tr_ref_N,fy_tr_N', error)
      if (allocated(error)) return
      do k = 1, n_kinematic_sets
         if (.not. there(k)) cycle
         do i = 1, s(k)%n
            call out%row([s(k)%y_ws(i), s(k)%yaw(i), s(k)%xi_k(i), s(k)%eta_k(i), &
               s(k)%omega_k(i), real(s(k)%members(i), wp), s(k)%y_ref(i), s(k)%y(i), &
               s(k)%fx_ref(i), s(k)%fx(i), s(k)%fy_ref(i), s(k)%fy(i), s(k)%fn_ref(i), &
               s(k)%fn(i), s(k)%pmax_ref(i), s(k)%pmax(i), s(k)%area_ref(i), s(k)%area(i), &
               s(k)%delta_ref(i), s(k)%gamma(i), s(k)%fy_tr_ref(i), s(k)%fy_tr(i)], [character(len=64) :: &
               kinematic_sets(k)%file(12:), s(k)%name(i)], digits=6)
         end do
      end do
      call out%close()
   end subroutine write_csv


   !> The matched patches' errors to the summary of every set, configuration config.
   subroutine pool_set(set, s, config)
      type(kinematic_set_type), intent(in) :: set
      type(set_patches_type), intent(in) :: s
      integer, intent(in) :: config
      logical :: ok(s%n)
      ok = s%members > 0
      call pool_errors(trim(set%label), config, pack(abs(s%fx - s%fx_ref), ok), &
         pack(abs(s%fy - s%fy_ref), ok), s%f_max)
   end subroutine pool_set

   !> Solve one set and compare every CONTACT patch (module text); the defaults, or another
   !> normal reduction or correction.
   subroutine solve_kinematic_set(set, s, error, reduction, correction, conformal_tables)
      type(kinematic_set_type), intent(in) :: set
      type(set_patches_type), intent(out) :: s
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in), optional :: reduction, correction
      !> `&normal strip_tables = 'conformal'` (the contact search's conformal_tables).
      logical, intent(in), optional :: conformal_tables
      type(contact_options_type) :: contact
      type(normal_options_type) :: normal
      type(tangential_options_type) :: tangential
      type(csv_table_type) :: table
      type(contact_solver_type) :: solver
      type(track_type) :: track
      type(contact_result_type) :: result
      real(wp), allocatable :: v(:, :)
      character(len=*), parameter :: names(19) = [character(len=13) :: 'y_ws_mm', 'yaw_rad', &
         'vs_mm_s', 'vy_mm_s', 'vyaw_rad_s', 'vpitch_rad_s', 'xi_k', 'eta_k', 'omega_k', &
         'npatch', 'ycp_tr_mm', 'fx_norm', 'fs_norm', 'fn_N', 'pmax_MPa', 'ncon', 'delta_rad', &
         'fy_tr_total_N', 'status']
      integer :: i, j, first, j_case, j_status

      call read_csv(trim(set%file), table, error)
      if (allocated(error)) return
      j_case = column_index(table, 'case')
      j_status = column_index(table, 'status')
      allocate (v(table%rows(), size(names) - 1))
      do j = 1, size(names) - 1
         if (column_index(table, trim(names(j))) == 0) then
            call fatal_error(error, trim(set%file)//': no column "'//trim(names(j))//'"', &
               stat_invalid_input)
            return
         end if
      end do
      if (j_case == 0 .or. j_status == 0) then
         call fatal_error(error, trim(set%file)//': expected the columns "case" and "status"', &
            stat_invalid_input)
         return
      end if
      do i = 1, table%rows()
         if (trim(table%cells(i, j_status)) /= 'ok') cycle
         do j = 1, size(names) - 1
            v(i, j) = number(table, i, column_index(table, trim(names(j))), error)
            if (allocated(error)) return
         end do
      end do
      ! The project's sets: the Manchester set-up (track_type's defaults: gauge 1435 mm at
      ! 14 mm, flange-back distance 1360 mm at −70 mm, R₀ = 460 mm), the rail canted in the
      ! profile; G = 82670 MPa, ν = 0.27, μ = 0.3.
      track%rail_canted = .true.
      if (present(reduction)) call new_normal_options(normal, error, reduction=reduction)
      if (allocated(error)) return
      if (present(correction)) call parse_correction(correction, tangential%correction, error)
      if (allocated(error)) return
      if (present(conformal_tables)) contact%conformal_tables = conformal_tables
      call solver%init(trim(set%wheel), trim(set%rail), error, track=track, contact_options=contact, &
         material=material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, friction=friction), &
         normal_options=normal, tangential_options=tangential)
      if (allocated(error)) return
      call allocate_patches(s, count(table%cells(:, j_status) == 'ok'))
      s%n = 0
      i = 1
      do while (i <= table%rows())
         first = i
         do while (i < table%rows())
            if (table%cells(i + 1, j_case) /= table%cells(first, j_case)) exit
            i = i + 1
         end do
         if (trim(table%cells(first, j_status)) /= 'ok') then
            s%n_failed = s%n_failed + 1
         else
            call solver%solve_kinematic(wheelset_state_type(y_ws=v(first, 1), &
               yaw=v(first, 2), v_forward=v(first, 3), v_lateral=v(first, 4), &
               yaw_rate=v(first, 5), pitch_rate=v(first, 6)), contact_load_type( &
               load_vertical_force, vertical_load), result, error)
            if (allocated(error)) then
               error%message = trim(set%file)//', case '//trim(table%cells(first, j_case))// &
                  ': '//error%message
               return
            end if
            s%n_cases = s%n_cases + 1
            call compare_case(result, v(first:i, :), table%cells(first, j_case), s)
         end if
         i = i + 1
      end do
   end subroutine solve_kinematic_set

   !> Match our loaded patches with CONTACT's rows of one case (v: the case's rows, the columns
   !> of solve_kinematic_set's names) and append the comparison to s.
   subroutine compare_case(result, v, name, s)
      type(contact_result_type), intent(in) :: result
      real(wp), intent(in) :: v(:, :)
      character(len=*), intent(in) :: name
      type(set_patches_type), intent(inout) :: s
      integer :: k, j, near, at
      real(wp) :: fx(size(v, 1)), fy(size(v, 1)), fn(size(v, 1)), pmax(size(v, 1)), &
         area(size(v, 1)), ysum(size(v, 1)), gsum(size(v, 1))
      integer :: members(size(v, 1))

      fx = 0.0_wp; fy = 0.0_wp; fn = 0.0_wp; pmax = 0.0_wp; area = 0.0_wp; ysum = 0.0_wp
      gsum = 0.0_wp
      members = 0
      do k = 1, result%n_loaded
         associate (p => result%patch(k))
            if (.not. (p%fn > 0.0_wp)) cycle
            s%f_max = max(s%f_max, hypot(p%fx_norm, p%fy_norm))
            near = minloc(abs(v(:, 11) - p%y_track), 1)
            if (abs(v(near, 11) - p%y_track) > separation .and. &
               p%fn > extra_share*result%track%fn) then
               s%n_extra = s%n_extra + 1
               cycle
            end if
            members(near) = members(near) + 1
            fx(near) = fx(near) - p%fx
            fy(near) = fy(near) - p%fy
            fn(near) = fn(near) + p%fn
            ysum(near) = ysum(near) + p%fn*p%y_track
            gsum(near) = gsum(near) + p%fn*p%gamma0
            pmax(near) = max(pmax(near), p%p_max)
            area(near) = area(near) + p%area
         end associate
      end do
      do j = 1, size(v, 1)
         s%n = s%n + 1
         at = s%n
         s%name(at) = name
         s%y_ws(at) = v(j, 1); s%yaw(at) = v(j, 2)
         s%xi_k(at) = v(j, 7); s%eta_k(at) = v(j, 8); s%omega_k(at) = v(j, 9)
         s%y_ref(at) = v(j, 11); s%fx_ref(at) = v(j, 12); s%fy_ref(at) = v(j, 13)
         s%fn_ref(at) = v(j, 14); s%pmax_ref(at) = v(j, 15)
         s%area_ref(at) = v(j, 16)*element_area
         s%members(at) = members(j)
         s%delta_ref(at) = v(j, 17); s%fy_tr_ref(at) = v(j, 18)
         s%fy_tr(at) = -result%track%fy
         s%gamma(at) = 0.0_wp
         if (members(j) > 0) s%gamma(at) = gsum(j)/fn(j)
         s%fn(at) = fn(j); s%pmax(at) = pmax(j); s%area(at) = area(j)
         if (members(j) > 0) then
            s%fx(at) = fx(j)/(friction*fn(j))
            s%fy(at) = fy(j)/(friction*fn(j))
            s%y(at) = ysum(j)/fn(j)
         else
            s%fx(at) = 0.0_wp; s%fy(at) = 0.0_wp; s%y(at) = 0.0_wp
         end if
      end do
   end subroutine compare_case

   subroutine allocate_patches(s, n)
      type(set_patches_type), intent(inout) :: s
      integer, intent(in) :: n
      allocate (s%name(n), s%y_ws(n), s%yaw(n), s%xi_k(n), s%eta_k(n), s%omega_k(n), &
         s%y_ref(n), s%fx_ref(n), s%fy_ref(n), s%fn_ref(n), s%pmax_ref(n), s%area_ref(n), &
         s%members(n), s%y(n), s%fx(n), s%fy(n), s%fn(n), s%pmax(n), s%area(n), &
         s%delta_ref(n), s%gamma(n), s%fy_tr_ref(n), s%fy_tr(n))
   end subroutine allocate_patches

   real(wp) function number(table, i, j, error)
      type(csv_table_type), intent(in) :: table
      integer, intent(in) :: i, j
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      read (table%cells(i, j), *, iostat=stat) number
      if (stat /= 0) call fatal_error(error, table%source//', row '//trim(table%cells(i, 1))// &
         ': "'//trim(table%cells(i, j))//'" is not a number', stat_invalid_input)
   end function number

   !> kinematic_sets.md: per set and per (Y_WS, yaw) group, the errors of the matched patches.
   subroutine write_markdown(path, s, there, error, option)
      character(len=*), intent(in) :: path
      type(set_patches_type), intent(in) :: s(:)
      logical, intent(in) :: there(:)
      type(error_type), allocatable, intent(out) :: error
      !> The option the sets were solved with, when not the defaults.
      character(len=*), intent(in), optional :: option
      character(len=:), allocatable :: solved
      integer :: unit, stat, k, g
      real(wp), allocatable :: keys(:, :)

      open (newunit=unit, file=path, status='replace', action='write', iostat=stat)
      if (stat /= 0) then
         call fatal_error(error, path//': cannot be written')
         return
      end if
      solved = 'the defaults'
      if (present(option)) solved = option
      write (unit, '(a)') '<!-- written by `fpm run --example shcontact-validate --profile '// &
         'release` (kinematic_sets.csv) -->', '', &
         'The project''s kinematic exact-theory sets (doc/validation.md §6.7), '//solved// &
         ': every CONTACT '// &
         'patch against our patches nearest to it, joined; f = F/(μF_n) on the rail; max ; '// &
         'P80 of |Δf_x|, |Δf_y|, |ΔF_n|/F_n, |Δp_max|/p_max, |ΔA|/A.', ''
      do k = 1, size(s)
         if (.not. there(k)) cycle
         write (unit, '(a)') '### '//trim(kinematic_sets(k)%label), '', &
            '| group | CONTACT patches | missed | \|Δf_x\| | \|Δf_y\| | \|ΔF_n\|/F_n | '// &
            '\|Δp_max\|/p_max | \|ΔA\|/A | \|ΔF_y,tr\|/F_z |', '|---|---|---|---|---|---|---|---|---|'
         call group_keys(s(k), keys)
         do g = 1, size(keys, 2)
            call table_row(unit, s(k), abs(s(k)%y_ws - keys(1, g)) < 1.0e-9_wp .and. &
               abs(s(k)%yaw - keys(2, g)) < 1.0e-12_wp, 'Y_WS '//ftext(keys(1, g), 2)// &
               ' mm, yaw '//ftext(1.0e3_wp*keys(2, g), 0)//' mrad')
         end do
         call table_row(unit, s(k), s(k)%y_ws == s(k)%y_ws, '**all**')
         write (unit, '(a,i0,a,i0,a,i0,a,a,a)') '', s(k)%n_cases, ' cases solved (', &
            s(k)%n_failed, ' failed in CONTACT), ', s(k)%n_extra, ' extra patches of ours; '// &
            'largest |f| of our patches ', ftext(s(k)%f_max, 5), '.'
         write (unit, '(a)') ''
      end do
      close (unit)
   end subroutine write_markdown

   !> The (Y_WS, yaw) pairs in the order met.
   pure subroutine group_keys(s, keys)
      type(set_patches_type), intent(in) :: s
      real(wp), allocatable, intent(out) :: keys(:, :)
      real(wp) :: k(2, s%n)
      integer :: i, n, j
      logical :: seen
      n = 0
      do i = 1, s%n
         seen = .false.
         do j = 1, n
            seen = seen .or. (abs(k(1, j) - s%y_ws(i)) < 1.0e-9_wp .and. &
               abs(k(2, j) - s%yaw(i)) < 1.0e-12_wp)
         end do
         if (seen) cycle
         n = n + 1
         k(:, n) = [s%y_ws(i), s%yaw(i)]
      end do
      keys = k(:, 1:n)
   end subroutine group_keys

   subroutine table_row(unit, s, in_group, label)
      integer, intent(in) :: unit
      type(set_patches_type), intent(in) :: s
      logical, intent(in) :: in_group(:)
      character(len=*), intent(in) :: label
      logical :: m(s%n)
      m = in_group .and. s%members > 0
      write (unit, '(a)') '| '//label//' | '//itext(count(in_group))//' | '// &
         itext(count(in_group .and. s%members == 0))//' | '// &
         pair(error_stats(pack(abs(s%fx - s%fx_ref), m)), 3)//' | '// &
         pair(error_stats(pack(abs(s%fy - s%fy_ref), m)), 3)//' | '// &
         pair(error_stats(pack(abs(s%fn - s%fn_ref)/s%fn_ref, m)), 3)//' | '// &
         pair(error_stats(pack(abs(s%pmax - s%pmax_ref)/s%pmax_ref, m)), 3)//' | '// &
         pair(error_stats(pack(abs(s%area - s%area_ref)/s%area_ref, m)), 3)//' | '// &
         pair(error_stats(pack(abs(s%fy_tr - s%fy_tr_ref)/vertical_load, in_group)), 3)//' |'
   end subroutine table_row

   function pair(e, decimals) result(text)
      type(error_stats_type), intent(in) :: e
      integer, intent(in) :: decimals
      character(len=:), allocatable :: text
      text = ftext(e%max, decimals)//' ; '//ftext(e%p80, decimals)
   end function pair

end module validate_kinematic_sets
