!> shcontact-ellipse-table: makes the exact-ellipse correction table
!> (src/shcontact/tangential/ellipse_table.f90; doc/tangential.md "Exact-ellipse correction").
!>
!>     shcontact-ellipse-table decks DIR [EXACT]    CONTACT decks DIR/part1.inp, part2.inp and
!>                                                  the case list DIR/cases.csv: every node of
!>                                                  the grid, or those missing from EXACT
!>     shcontact-ellipse-table source EXACT OUT     the table module OUT from CONTACT's forces
!>                                                  EXACT (data/exact/ellipse_table.csv)
!>
!> scripts/contact_ellipse_table.py runs both around CONTACT. The grid: a/b at the nine
!> table_ratio nodes; t_x = 0, 0.1, …, 0.9; t_y = −0.9, …, 0.9; t_φ at the table_t_phi nodes
!> (t = s/(1 + |s|) inverted: s = t/(1 − |t|), the scaled creepage of
!> shcontact_tangential_ellipse_correction); t_y < 0 at t_φ = 0 is the mirror of t_y > 0 and is
!> not run. EXACT has one line per node: i_ratio,k_x,k_y,t_phi,fx,fy (CONTACT's sign). Each ellipse has area 36 mm² and carries
!> F_n = 64.7 kN; G = 82670 MPa, ν = 0.27, μ = 0.3 (the reference material of
!> ../shared/reference/README.md). Our side is FASTSIM_SH with the default options and no
!> correction on 100 strips.
program ellipse_table
   use, intrinsic :: iso_fortran_env, only: error_unit
   use shcontact, only: wp, error_type, material_type, tangential_options_type, normal_patch_type
   use shcontact_tangential_options, only: correction_none
   use shcontact_tangential_march, only: march_workspace_type, solve_prepared
   use shcontact_tangential_fastsim_sh, only: prepare_fastsim_sh
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_ellipse_table, only: table_ratio, table_t_phi, n_table_ratio, &
      n_table_t, n_table_ty, n_table_phi, table_unit, table_poisson
   use shcontact_tangential_ellipse_correction, only: table_node_case, ellipse_correction_type, &
      prepare_ellipse_correction
   use shcontact_core_strings, only: str_int
   implicit none

   !> One table case: its grid indices (i_φ the t_φ node) and creepages (CONTACT's sign: rail
   !> relative to wheel).
   type :: grid_case_type
      integer :: ir = 0, kx = 0, ky = 0, ip = 0
      real(wp) :: semi_a = 0.0_wp, semi_b = 0.0_wp, nu_x = 0.0_wp, nu_y = 0.0_wp, phi = 0.0_wp
   end type grid_case_type

   character(len=512) :: mode, arg1, arg2
   type(grid_case_type), allocatable :: cases(:)
   type(error_type), allocatable :: error

   call get_command_argument(1, mode)
   call get_command_argument(2, arg1)
   call get_command_argument(3, arg2)
   call grid_cases(cases)
   select case (trim(mode))
   case ('decks')
      if (len_trim(arg1) == 0) call usage()
      call write_decks(trim(arg1), trim(arg2), cases, error)
   case ('source')
      if (len_trim(arg1) == 0 .or. len_trim(arg2) == 0) call usage()
      call write_source(trim(arg1), trim(arg2), cases, error)
   case default
      call usage()
   end select
   if (allocated(error)) then
      write (error_unit, '(a)') 'shcontact-ellipse-table: '//error%message
      stop 1
   end if

contains

   subroutine usage()
      write (error_unit, '(a)') 'usage: shcontact-ellipse-table decks DIR [EXACT_CSV] | '// &
         'source EXACT_CSV OUT_F90'
      stop 2
   end subroutine usage

   !> The reference material.
   pure type(material_type) function material()
      material = material_type(shear_modulus=82670.0_wp, poisson=table_poisson, friction=0.3_wp)
   end function material

   !> Every case of the grid, in table order (t_φ fastest, then t_y, t_x, a/b), in CONTACT's
   !> sign (shcontact_tangential_ellipse_correction's table_node_case).
   subroutine grid_cases(cases)
      type(grid_case_type), allocatable, intent(out) :: cases(:)
      type(normal_patch_type) :: patch
      type(creepage_type) :: creepage
      integer :: ir, kx, ky, ip, n

      allocate (cases(n_table_ratio*n_table_t*n_table_ty*n_table_phi))
      n = 0
      do ir = 1, n_table_ratio
         do kx = 0, n_table_t - 1
            do ky = -(n_table_ty/2), n_table_ty/2
               do ip = 1, n_table_phi
                  if (ip == 1 .and. ky < 0) cycle
                  call table_node_case(ir, kx, ky, ip, material(), patch, creepage)
                  n = n + 1
                  cases(n) = grid_case_type(ir, kx, ky, ip, patch%ellipse_a, patch%ellipse_b, &
                     -creepage%nu_x, -creepage%nu_y, -creepage%phi)
               end do
            end do
         end do
      end do
      cases = cases(1:n)
   end subroutine grid_cases

   !> CONTACT module-3 decks, Hertzian with prescribed semi-axes (IPOTCN = −3), 50 × 50
   !> elements, cases split over two files to run in parallel; and DIR/cases.csv with the node
   !> of each case. With EXACT, only the nodes it lacks.
   subroutine write_decks(dir, exact_path, cases, error)
      character(len=*), intent(in) :: dir, exact_path
      type(grid_case_type), intent(in) :: cases(:)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: fx(size(cases)), fy(size(cases))
      logical :: known(size(cases))
      integer :: units(2), u, i, k, ios, n

      known = .false.
      if (len(exact_path) > 0) then
         call read_exact(exact_path, cases, fx, fy, known, error)
         if (allocated(error)) return
      end if
      open (newunit=u, file=dir//'/cases.csv', status='new', action='write', iostat=ios)
      if (ios /= 0) then
         error = error_type(1, dir//'/cases.csv: cannot create (does it exist already?)')
         return
      end if
      write (u, '(a)') 'i_ratio,k_x,k_y,t_phi,a_mm,b_mm,nu_x,nu_y,phi_per_mm'
      do k = 1, 2
         open (newunit=units(k), file=dir//'/part'//achar(48 + k)//'.inp', status='new', &
            action='write', iostat=ios)
         if (ios /= 0) then
            error = error_type(1, dir//'/part'//achar(48 + k)//'.inp: cannot create')
            return
         end if
      end do
      n = 0
      do i = 1, size(cases)
         if (known(i)) cycle
         associate (c => cases(i))
            write (u, '(3(i0,","),f5.3,*(:,",",es18.10))') c%ir, c%kx, c%ky, table_t_phi(c%ip), &
               c%semi_a, c%semi_b, c%nu_x, c%nu_y, c%phi
            call write_deck(units(1 + mod(n, 2)), c)
            n = n + 1
         end associate
      end do
      close (u)
      do k = 1, 2
         write (units(k), '(a)') '  0  MODULE'
         close (units(k))
      end do
   end subroutine write_decks

   subroutine write_deck(u, c)
      integer, intent(in) :: u
      type(grid_case_type), intent(in) :: c
      write (u, '(a)') '  3  MODULE'
      write (u, '(a)') '  203100     P-B-T-N-F-S   PVTIME, BOUND , TANG  , NORM  , FORCE , STRESS'
      write (u, '(a)') '  022020     L-D-C-M-Z-E   FRCLAW, DISCNS, INFLCF, MATER , RZNORM, EXRHS'
      write (u, '(a)') ' 00000201   X-H-G-I-A-O-W-R   HEAT, GAUSEI, IESTIM, MATFIL, OUTPUT, FLOW, RETURN'
      write (u, '(a)') '  999   100    30    1   1e-06             MAXGS, MAXIN, MAXNR, MAXOUT, EPS'
      write (u, '(a,3(1x,es18.10),a)') '  64700.0000', c%nu_x, c%nu_y, c%phi, &
         '   FN, CKSI, CETA, CPHI'
      write (u, '(a)') '  0.300  0.300                                FSTAT, FKIN'
      write (u, '(a)') '  0.000  0.100000  2000.0                    CHI, DQ, VELOC'
      write (u, '(a)') '  0.270  0.270  82670.0  82670.0          POISS 1,2,  GG 1,2'
      write (u, '(a)') '  -3                                            IPOTCN'
      write (u, '(a,2(1x,es18.10),a)') '  50  50', c%semi_a, c%semi_b, &
         '  1.05        MX, MY, AA, BB, SCALE'
   end subroutine write_deck

   !> Read CONTACT's f_x, f_y per case, solve our side, write the table module.
   subroutine write_source(exact_path, out_path, cases, error)
      character(len=*), intent(in) :: exact_path, out_path
      type(grid_case_type), intent(in) :: cases(:)
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: dfx(:, :, :, :), dfy(:, :, :, :)
      real(wp) :: fx_exact(size(cases)), fy_exact(size(cases)), fx, fy, linear(3, n_table_ratio)
      logical :: known(size(cases))
      type(normal_patch_type) :: patch
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      type(creepage_type) :: creepage
      integer :: i, ir, h

      call read_exact(exact_path, cases, fx_exact, fy_exact, known, error)
      if (allocated(error)) return
      if (.not. all(known)) then
         error = error_type(1, exact_path//': '//str_int(count(.not. known))//' of the '// &
            str_int(size(cases))//' table nodes are missing (run the decks of the missing ones)')
         return
      end if
      h = n_table_ty/2
      allocate (dfx(n_table_phi, n_table_ty, n_table_t, n_table_ratio), source=0)
      allocate (dfy, mold=dfx)
      options%fields = .false.
      options%correction = correction_none
      ir = 0
      do i = 1, size(cases)
         associate (c => cases(i))
            call table_node_case(c%ir, c%kx, c%ky, c%ip, material(), patch, creepage)
            if (c%ir /= ir) then
               ir = c%ir
               call prepare_fastsim_sh(ws, patch, material(), options, error)
               if (allocated(error)) return
            end if
            ! Our sign convention is the wheel's: every creepage and force flips (creepage.f90).
            call solve_prepared(ws, creepage, result, error)
            if (allocated(error)) return
            fx = -result%fx_norm
            fy = -result%fy_norm
            dfx(c%ip, c%ky + h + 1, c%kx + 1, c%ir) = nint((fx_exact(i) - fx)/table_unit)
            dfy(c%ip, c%ky + h + 1, c%kx + 1, c%ir) = nint((fy_exact(i) - fy)/table_unit)
            if (c%ip == 1 .and. c%ky > 0) then
               ! Mirror in y at φ = 0: D_x(ν_x, −ν_y, 0) = D_x, D_y = −D_y.
               dfx(1, h + 1 - c%ky, c%kx + 1, c%ir) = dfx(1, c%ky + h + 1, c%kx + 1, c%ir)
               dfy(1, h + 1 - c%ky, c%kx + 1, c%ir) = -dfy(1, c%ky + h + 1, c%kx + 1, c%ir)
            end if
         end associate
      end do
      call linear_slopes(linear, error)
      if (allocated(error)) return
      call write_module(out_path, dfx, dfy, linear, error)
   end subroutine write_source

   !> Per a/b node, the defect's slopes dD/ds at zero creepage, exact minus FASTSIM_SH: s_x → D_x,
   !> s_y → D_y, s_φ → D_y. The exact linear theory is f = −3s in every one (Kalker's
   !> coefficients scale s); FASTSIM_SH's is measured at s = 1e-4 (CONTACT's sign throughout).
   subroutine linear_slopes(linear, error)
      real(wp), intent(out) :: linear(3, n_table_ratio)
      type(error_type), allocatable, intent(out) :: error
      real(wp), parameter :: s = 1.0e-4_wp
      type(normal_patch_type) :: patch
      type(creepage_type) :: creepage
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: r
      type(ellipse_correction_type) :: scale
      integer :: ir

      options%fields = .false.
      options%correction = correction_none
      do ir = 1, n_table_ratio
         call table_node_case(ir, 0, 0, 1, material(), patch, creepage)
         call prepare_fastsim_sh(ws, patch, material(), options, error)
         if (allocated(error)) return
         call prepare_ellipse_correction(scale, patch%ellipse_a, patch%ellipse_b, patch%load, &
            material(), 0.0_wp, 1.0_wp, 0.0_wp)
         ! CONTACT's creepage +s is ours −s/scale; CONTACT's force is minus ours.
         call solve_prepared(ws, creepage_type(-s/scale%scale_x, 0.0_wp, 0.0_wp), r, error)
         if (allocated(error)) return
         linear(1, ir) = (-3.0_wp*s + r%fx_norm)/s
         call solve_prepared(ws, creepage_type(0.0_wp, -s/scale%scale_y, 0.0_wp), r, error)
         if (allocated(error)) return
         linear(2, ir) = (-3.0_wp*s + r%fy_norm)/s
         call solve_prepared(ws, creepage_type(0.0_wp, 0.0_wp, -s/scale%scale_phi), r, error)
         if (allocated(error)) return
         linear(3, ir) = (-3.0_wp*s + r%fy_norm)/s
      end do
   end subroutine linear_slopes

   !> data/exact/ellipse_table.csv: a header, then i_ratio,k_x,k_y,t_phi,fx,fy per line in any
   !> order; known(i) tells which grid cases it has.
   subroutine read_exact(path, cases, fx, fy, known, error)
      character(len=*), intent(in) :: path
      type(grid_case_type), intent(in) :: cases(:)
      real(wp), intent(out) :: fx(:), fy(:)
      logical, intent(out) :: known(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: u, ios, i, line, ir, kx, ky, ip
      real(wp) :: t_phi, x, y

      known = .false.
      fx = 0.0_wp
      fy = 0.0_wp
      open (newunit=u, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         error = error_type(1, path//': cannot open')
         return
      end if
      read (u, *, iostat=ios)
      line = 1
      do
         read (u, *, iostat=ios) ir, kx, ky, t_phi, x, y
         if (is_iostat_end(ios)) exit
         line = line + 1
         ip = findloc(nint(1000*table_t_phi), nint(1000*t_phi), dim=1)
         if (ios /= 0 .or. ip == 0) then
            close (u)
            error = error_type(1, path//': line '//str_int(line)// &
               ': expected "i_ratio,k_x,k_y,t_phi,fx,fy" at a node of the table')
            return
         end if
         do i = 1, size(cases)
            if (cases(i)%ir == ir .and. cases(i)%kx == kx .and. cases(i)%ky == ky .and. &
               cases(i)%ip == ip) then
               fx(i) = x
               fy(i) = y
               known(i) = .true.
               exit
            end if
         end do
      end do
      close (u)
   end subroutine read_exact

   !> Write the module source: the sizes, nodes and the defects in units of table_unit.
   subroutine write_module(path, dfx, dfy, linear, error)
      character(len=*), intent(in) :: path
      integer, intent(in) :: dfx(:, :, :, :), dfy(:, :, :, :)
      real(wp), intent(in) :: linear(:, :)
      type(error_type), allocatable, intent(out) :: error
      integer :: u, ios, ir, kx

      open (newunit=u, file=path, status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         error = error_type(1, path//': cannot write')
         return
      end if
      write (u, '(a)') '!> GENERATED by shcontact-ellipse-table (scripts/contact_ellipse_table.py) from', &
         '!> data/exact/ellipse_table.csv: do not edit. The exact-ellipse defect', &
         '!> D = f_exact − f_FASTSIM_SH (normalised by μF_n) on Hertz ellipses, in units of', &
         '!> table_unit, indexed (t_φ node, t_y node, t_x node, a/b node); see', &
         '!> shcontact_tangential_ellipse_correction for the nodes and their use.', &
         'module shcontact_tangential_ellipse_table', &
         '   use shcontact_core_kinds, only: wp', &
         '   implicit none', &
         '   private', '', &
         '   public :: n_table_ratio, n_table_t, n_table_ty, n_table_phi, table_ratio, &', &
         '      table_t_phi, table_unit, table_poisson, table_dfx, table_dfy, table_linear', '', &
         '   !> Nodes in a/b, in t_x (0, 0.1, …, 0.9), in t_y (−0.9, …, 0.9) and in t_φ.'
      write (u, '(a,i0,a,i0,a,i0,a,i0)') '   integer, parameter :: n_table_ratio = ', &
         n_table_ratio, ', n_table_t = ', n_table_t, ', n_table_ty = ', n_table_ty, &
         ', n_table_phi = ', n_table_phi
      write (u, '(a)') '   !> The a/b nodes of the table.'
      write (u, '(a)') '   real(wp), parameter :: table_ratio(n_table_ratio) = [ &'
      call write_nodes(u, table_ratio)
      write (u, '(a)') '   !> The t_φ nodes of the table: finer where the pure-spin force peaks.'
      write (u, '(a)') '   real(wp), parameter :: table_t_phi(n_table_phi) = [ &'
      call write_nodes(u, table_t_phi)
      write (u, '(a)') '   !> Unit of the stored defects; Poisson ratio of the exact runs.'
      write (u, '(a)') '   real(wp), parameter :: table_unit = 1.0e-5_wp, table_poisson = 0.27_wp'
      write (u, '(a)') '   !> Per a/b node, the defect''s slopes at zero creepage (exact linear theory minus', &
         '   !> FASTSIM_SH): dD_x/ds_x, dD_y/ds_y, dD_y/ds_φ.', &
         '   real(wp), parameter :: table_linear(3, n_table_ratio) = reshape([ &'
      do ir = 1, n_table_ratio
         write (u, '(6x,3(f9.5,"_wp",:,", "))', advance='no') linear(:, ir)
         if (ir < n_table_ratio) then
            write (u, '(a)') ', &'
         else
            write (u, '(a)') '], [3, n_table_ratio])'
         end if
      end do
      write (u, '(a)') '   !> D_x and D_y at the nodes (units of table_unit).'
      write (u, '(a)') '   integer, protected :: table_dfx(n_table_phi, n_table_ty, n_table_t, n_table_ratio)'
      write (u, '(a)') '   integer, protected :: table_dfy(n_table_phi, n_table_ty, n_table_t, n_table_ratio)'
      write (u, '(a)') '   integer, private :: i, j'
      do ir = 1, n_table_ratio
         do kx = 1, n_table_t
            call write_data(u, 'table_dfx', dfx(:, :, kx, ir), kx, ir)
            call write_data(u, 'table_dfy', dfy(:, :, kx, ir), kx, ir)
         end do
      end do
      write (u, '(a)') '', 'end module shcontact_tangential_ellipse_table'
      close (u)
   end subroutine write_module

   !> The values of a node array, ten per line, and the closing bracket.
   subroutine write_nodes(u, values)
      integer, intent(in) :: u
      real(wp), intent(in) :: values(:)
      character(len=8) :: text
      integer :: k, i

      do k = 1, size(values), 10
         write (u, '(6x)', advance='no')
         do i = k, min(size(values), k + 9)
            write (text, '(f8.2)') values(i)
            write (u, '(a)', advance='no') trim(adjustl(text))//'_wp'
            if (i == size(values)) then
               write (u, '(a)') ']'
            else if (i == k + 9) then
               write (u, '(a)') ', &'
            else
               write (u, '(a)', advance='no') ', '
            end if
         end do
      end do
   end subroutine write_nodes

   subroutine write_data(u, name, values, kx, ir)
      integer, intent(in) :: u, kx, ir
      character(len=*), intent(in) :: name
      integer, intent(in) :: values(:, :)
      integer :: j, k, n
      integer :: flat(size(values))

      flat = reshape(values, [size(values)])
      n = size(flat)
      write (u, '(a,a,a,i0,a,i0,a)') '   data ((', name, '(i, j, ', kx, ', ', ir, &
         '), i = 1, n_table_phi), j = 1, n_table_ty) / &'
      do k = 1, n, 16
         j = min(n, k + 15)
         if (j < n) then
            write (u, '(6x,*(i0,:,", "))', advance='no') flat(k:j)
            write (u, '(a)') ', &'
         else
            write (u, '(6x,*(i0,:,", "))', advance='no') flat(k:j)
            write (u, '(a)') ' /'
         end if
      end do
   end subroutine write_data


end program ellipse_table
