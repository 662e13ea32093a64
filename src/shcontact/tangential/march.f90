!> The strip march shared by classical FASTSIM and FASTSIM_SH (doc/theory.md §3.2, §6.5).
!>
!> A [[march_workspace_type]] holds everything that does not depend on the creepages: per loaded
!> strip the flexibility rates, the bound peaks and the geometric spin terms, and per element the
!> normalised positions and bound shapes, which are the same for every strip because every strip
!> has n_x elements of length 2a_i/n_x (strip-adapted grid). shcontact_tangential_fastsim and
!> shcontact_tangential_fastsim_sh fill it; [[solve_prepared]] then solves one set of creepages
!> without allocating (the result is allocated only when its size changes).
!>
!> March on strip i (element-centred, half first step, spin rate at step midpoints, §3.2):
!> x'_j = 1 − (2j − 1)/n_x, p ← p − h_j (R_x, R_y + R_φ x_mid,j), then the radial projection onto
!> the bound g_j = μ p̂_i s_j with s_j = √(1 − x'_j²) (ellipsoidal) or 1 − x'_j² (parabolic and
!> the weighted bounds, whose weighting is applied to the output only, §6.4).
!>
!> **Speed** (doc/performance.md). The march along a strip is a chain of dependent steps, each
!> waiting for a division and a square root; the strips are independent. So the loops run over
!> the elements outside and over the strips inside: every inner loop is one SIMD loop across the
!> strips of a block (up to [[max_block]] of them, enough independent chains to keep the
!> divider busy, few enough for the block's buffers to stay in L1), and each element step runs
!> in stages (march, output weighting, sums, fields), each a simple loop the compiler vectorises.
module shcontact_tangential_march
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_constants, only: half_pi
   use shcontact_core_error, only: error_type, fatal_error, stat_usage
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior, state_adhesion, &
      state_slip
   use shcontact_tangential_creepage, only: creepage_type, check_creepage
   use shcontact_tangential_options, only: bound_ellipsoidal, bound_parabolic, bound_weighted, &
      bound_weighted_slip, bound_clipped, spin_additive, spin_scaled
   use shcontact_tangential_spin, only: local_creepages, scaled_spin_factor
   use shcontact_tangential_ellipse_correction, only: ellipse_correction_type, ellipse_defect
   implicit none
   private

   public :: march_workspace_type, reserve_workspace, set_element_grid, solve_prepared

   !> Most strips marched together by one SIMD loop.
   integer, parameter :: max_block = 64

   !> Creepage-independent data of one patch. Per-strip arrays are indexed by the loaded strip
   !> s = 1..n_active (strip(s) is its index in the patch); they are allocated with a capacity
   !> that only grows, so several patches can share one workspace.
   type :: march_workspace_type
      !> Elements per strip, strips of the patch (loaded or not), loaded strips.
      integer :: nx = 0, n_strips = 0, n_active = 0
      !> Traction bound (`bound_*`), spin model (`spin_*`), fill per-element fields.
      integer :: bound = bound_weighted
      integer :: spin_model = spin_additive
      logical :: fields = .true.
      !> Friction coefficient μ, strip width (mm), normal force F_n (N).
      real(wp) :: friction = 0.0_wp, dy = 0.0_wp, load = 0.0_wp
      !> Lateral offset (mm) added to y(s) for the moment arm and the output coordinates (the
      !> ellipse centre for classical FASTSIM, 0 for FASTSIM_SH).
      real(wp) :: y_offset = 0.0_wp
      !> Reference contact angle γ₀ (rad) and geometric spin φ_geo,0 (rad/mm).
      real(wp) :: gamma0 = 0.0_wp, phi_geo0 = 0.0_wp
      !> (32/(9π)) Σ k_i N_i / F_n (doc/theory.md §6.4).
      real(wp) :: parabolic_load_ratio = 0.0_wp
      !> n_x and ellipsoidal shape (or not) of the element grid held in xn … inv_ell; 0 when
      !> none: [[set_element_grid]] recomputes the grid only when they change.
      integer :: grid_nx = 0
      logical :: grid_ellipsoidal = .false.
      !> Centres of all strips as reported (mm).
      real(wp), allocatable :: y_strip(:)
      !> Index in the patch of loaded strip s.
      integer, allocatable :: strip(:)
      !> y_s used in the rates (mm) and half-length a_s (mm).
      real(wp), allocatable :: y(:), a(:)
      !> a_s/L_x,s and a_s/L_y,s (MPa): the rates R_x = ν/L_x times a_s.
      real(wp), allocatable :: akx(:), aky(:)
      !> a_s y_s/L_xφ,s (MPa·mm): the rigid-spin part of the longitudinal rate times a_s.
      real(wp), allocatable :: akxs_y(:)
      !> a_s²/L_φ,s (MPa·mm).
      real(wp), allocatable :: a2kphi(:)
      !> Flexibilities L_x,s, L_y,s (mm/MPa), for the slip magnitude.
      real(wp), allocatable :: flex_x(:), flex_y(:)
      !> μ times the peak of the march bound (MPa).
      real(wp), allocatable :: bound_peak(:)
      !> Peak of the semi-elliptic pressure p_n,e (MPa).
      real(wp), allocatable :: pe_peak(:)
      !> p_n,e/p_n,p peak ratio 3/(4k_s) (the W1 weight is weight(s)/√(1 − x'²)).
      real(wp), allocatable :: weight(:)
      !> cos γ₀/cos γ_s, φ_geo,s, φ_geo,s − φ_geo,0 (rad/mm), ρ_s = δr_s/r₀ − φ_geo,0 y_s.
      real(wp), allocatable :: cos_ratio(:), phi_geo(:), dphi_geo(:), rho(:)
      !> Normal force N_s (N) and sin γ_s, cos γ_s of each strip's own contact angle: the strip's
      !> forces act along its own normal and tangent, which gives the track-frame forces.
      real(wp), allocatable :: strip_normal(:), sin_gamma(:), cos_gamma(:)
      !> Strips without load (reported as exterior).
      integer, allocatable :: inactive(:)
      !> Per loaded strip, for the creepages being solved: increments of p_x, p_y per unit
      !> normalised step, −a_s (R_x, R_y), and of p_y per unit step·x', −a_s² R_φ (§6.5 step 2);
      !> μ times the peak of p_n,e; the march tractions t_x, t_y at the current element.
      real(wp), allocatable :: cx(:), cy(:), cphi(:), mu_pe(:), tx(:), ty(:)
      !> Per element: x'_j, step h_j/a, step times midpoint h_j x_mid,j/a², bound shape s_j,
      !> √(1 − x'²), 1 − x'², 1/√(1 − x'²).
      real(wp), allocatable :: xn(:), hn(:), hm(:), shape(:), ell(:), par(:), inv_ell(:)
      !> (π/2)/Σ_j (2/n_x) √(1 − x'_j²): the element pressures p_n,e of a strip sum to its load N_s
      !> times 1/field_ratio (the midpoint rule of the semi-ellipse, 1.0009 at n_x = 50), so a
      !> force ΔF spread in proportion to p_n adds field_ratio ΔF/(μF_n) times μp_n to each
      !> element.
      real(wp) :: field_ratio = 1.0_wp
      !> The exact-ellipse correction of the totals (inactive unless the preparation set it).
      type(ellipse_correction_type) :: correction
      !> Load-weighted means of the strips' local creepages ν_x − φ_x y, ν_y, φ for the case
      !> being solved: the creepages of the load centre.
      real(wp) :: centre_nu_x = 0.0_wp, centre_nu_y = 0.0_wp, centre_phi = 0.0_wp
   end type march_workspace_type

contains

   !> Make room for n_strips strips and nx elements (allocates only when the capacity grows) and
   !> record the sizes.
   pure subroutine reserve_workspace(ws, n_strips, nx)
      !> The workspace.
      type(march_workspace_type), intent(inout) :: ws
      !> Strips of the patch and elements per strip.
      integer, intent(in) :: n_strips, nx

      ws%n_strips = n_strips
      ws%nx = nx
      call reserve(ws%y_strip, n_strips)
      call reserve_int(ws%strip, n_strips)
      call reserve_int(ws%inactive, n_strips)
      call reserve(ws%y, n_strips)
      call reserve(ws%a, n_strips)
      call reserve(ws%akx, n_strips)
      call reserve(ws%aky, n_strips)
      call reserve(ws%akxs_y, n_strips)
      call reserve(ws%a2kphi, n_strips)
      call reserve(ws%flex_x, n_strips)
      call reserve(ws%flex_y, n_strips)
      call reserve(ws%bound_peak, n_strips)
      call reserve(ws%pe_peak, n_strips)
      call reserve(ws%weight, n_strips)
      call reserve(ws%cos_ratio, n_strips)
      call reserve(ws%phi_geo, n_strips)
      call reserve(ws%dphi_geo, n_strips)
      call reserve(ws%rho, n_strips)
      call reserve(ws%strip_normal, n_strips)
      call reserve(ws%sin_gamma, n_strips)
      call reserve(ws%cos_gamma, n_strips)
      call reserve(ws%cx, n_strips)
      call reserve(ws%cy, n_strips)
      call reserve(ws%cphi, n_strips)
      call reserve(ws%mu_pe, n_strips)
      call reserve(ws%tx, n_strips)
      call reserve(ws%ty, n_strips)
      ! A grid array that grows loses its contents: the grid must then be recomputed.
      if (allocated(ws%xn)) then
         if (size(ws%xn) < nx) ws%grid_nx = 0
      else
         ws%grid_nx = 0
      end if
      call reserve(ws%xn, nx)
      call reserve(ws%hn, nx)
      call reserve(ws%hm, nx)
      call reserve(ws%shape, nx)
      call reserve(ws%ell, nx)
      call reserve(ws%par, nx)
      call reserve(ws%inv_ell, nx)
   end subroutine reserve_workspace

   !> Element centres, steps and bound shapes of the strip-adapted grid (doc/theory.md §3.2, §6.5
   !> step 3), for ws%nx elements and ws%bound; kept when n_x and the bound shape are unchanged.
   pure subroutine set_element_grid(ws)
      !> The workspace (nx and bound set).
      type(march_workspace_type), intent(inout) :: ws
      real(wp) :: x_prev, step
      logical :: ellipsoidal
      integer :: j

      ellipsoidal = ws%bound == bound_ellipsoidal
      if (ws%grid_nx == ws%nx .and. (ws%grid_ellipsoidal .eqv. ellipsoidal)) return
      step = 2.0_wp/real(ws%nx, wp)
      x_prev = 1.0_wp
      do j = 1, ws%nx
         ws%xn(j) = 1.0_wp - (real(j, wp) - 0.5_wp)*step
         ws%hn(j) = x_prev - ws%xn(j)
         ! The y-rate R_y + R_φ x is linear in x: its value at the step midpoint integrates it
         ! exactly over the step (§3.2).
         ws%hm(j) = ws%hn(j)*0.5_wp*(x_prev + ws%xn(j))
         ws%par(j) = (1.0_wp - ws%xn(j))*(1.0_wp + ws%xn(j))
         ws%ell(j) = sqrt(ws%par(j))
         ws%inv_ell(j) = 1.0_wp/ws%ell(j)
         x_prev = ws%xn(j)
      end do
      if (ellipsoidal) then
         ws%shape(1:ws%nx) = ws%ell(1:ws%nx)
      else
         ws%shape(1:ws%nx) = ws%par(1:ws%nx)
      end if
      ws%field_ratio = half_pi/(step*sum(ws%ell(1:ws%nx)))
      ws%grid_nx = ws%nx
      ws%grid_ellipsoidal = ellipsoidal
   end subroutine set_element_grid

   !> Solve one set of creepages on a prepared workspace (doc/theory.md §6.5): local creepages per
   !> strip, the march, the output weighting, totals, and the per-element fields when ws%fields.
   pure subroutine solve_prepared(ws, creepage, result, error)
      !> The prepared workspace (its buffers are overwritten).
      type(march_workspace_type), intent(inout) :: ws
      !> Creepages at the reference point.
      type(creepage_type), intent(in) :: creepage
      !> The solution; its arrays are (re)allocated only when their shape changes.
      type(tangential_patch_type), intent(inout) :: result
      !> Set for an unprepared workspace, non-finite creepages, or a singular scaled spin model.
      type(error_type), allocatable, intent(out) :: error
      real(wp), dimension(max_block) :: sx, sy, sxy, cmax, n_adh
      real(wp) :: lambda, strip_area, fx, fy, mz, area, area_adh, coulomb2, mu, fy_s, dfx, dfy, &
         tan_y, tan_z, normal_y, normal_z, shift(2), c
      integer :: b0, s, l, m, nx, n_blocks, block

      if (ws%n_active < 1) then
         call fatal_error(error, 'solve_prepared: the workspace holds no loaded strip; call '// &
            'prepare_fastsim or prepare_fastsim_sh first', stat_usage)
         return
      end if
      call check_creepage(creepage, error)
      if (allocated(error)) return
      lambda = 0.0_wp
      if (ws%spin_model == spin_scaled) then
         call scaled_spin_factor(creepage%phi, ws%phi_geo0, lambda, error)
         if (allocated(error)) return
      end if
      nx = ws%nx
      mu = ws%friction
      call size_result(result, nx, ws%n_strips, ws%fields)
      call strip_increments(ws, creepage, lambda)
      ! The exact-ellipse defect (units of μF_n) depends only on the creepages of the load centre,
      ! so it is known before the march. Its share of each element's traction, spread in
      ! proportion to p_n ([[spread_defect]]), is the same fraction of μp_n everywhere: shift =
      ! D times [[march_workspace_type]]%field_ratio. The Coulomb check is taken on the
      ! corrected tractions, march output plus shift.
      dfx = 0.0_wp
      dfy = 0.0_wp
      if (ws%correction%active) call ellipse_defect(ws%correction, ws%centre_nu_x, &
         ws%centre_nu_y, ws%centre_phi, dfx, dfy)
      shift = ws%field_ratio*[dfx, dfy]

      fx = 0.0_wp
      fy = 0.0_wp
      mz = 0.0_wp
      tan_y = 0.0_wp
      tan_z = 0.0_wp
      normal_y = 0.0_wp
      normal_z = 0.0_wp
      area = 0.0_wp
      area_adh = 0.0_wp
      coulomb2 = 0.0_wp
      ! Blocks of equal size, at most max_block strips each.
      n_blocks = (ws%n_active + max_block - 1)/max_block
      block = (ws%n_active + n_blocks - 1)/n_blocks
      do b0 = 1, ws%n_active, block
         m = min(block, ws%n_active - b0 + 1)
         call march_block(ws, b0, m, shift, result, sx, sy, sxy, cmax, n_adh)
         do l = 1, m
            s = b0 + l - 1
            strip_area = 2.0_wp*ws%a(s)/real(nx, wp)*ws%dy
            fx = fx + strip_area*sx(l)
            fy_s = strip_area*sy(l)
            fy = fy + fy_s
            tan_y = tan_y + fy_s*ws%cos_gamma(s)
            tan_z = tan_z + fy_s*ws%sin_gamma(s)
            normal_y = normal_y + ws%strip_normal(s)*ws%sin_gamma(s)
            normal_z = normal_z - ws%strip_normal(s)*ws%cos_gamma(s)
            mz = mz + strip_area*(ws%a(s)*sxy(l) - (ws%y_offset + ws%y(s))*sx(l))
            area = area + 2.0_wp*ws%a(s)
            area_adh = area_adh + 2.0_wp*ws%a(s)*n_adh(l)/real(nx, wp)
            coulomb2 = max(coulomb2, cmax(l)/ws%mu_pe(s)**2)
            if (ws%fields) call store_strip(ws, s, result)
         end do
      end do
      if (ws%fields) call store_inactive(ws, result)
      if (ws%correction%active) then
         ! The defect in N: F_x's acts at the load centre, F_y's along the load-weighted tangent.
         dfx = mu*ws%load*dfx
         dfy = mu*ws%load*dfy
         fx = fx + dfx
         fy = fy + dfy
         mz = mz - ws%correction%y_centre*dfx
         tan_y = tan_y + dfy*ws%correction%cos_gamma
         tan_z = tan_z + dfy*ws%correction%sin_gamma
         if (ws%fields) call spread_defect(ws, dfx, dfy, result)
      end if
      c = coulomb_scale(fx, fy, mu*ws%load)
      if (ws%fields .and. c < 1.0_wp) then
         result%px = c*result%px
         result%py = c*result%py
      end if

      result%fx = c*fx
      result%fy = c*fy
      result%mz = c*mz
      result%fn = ws%load
      result%fx_norm = result%fx/(mu*ws%load)
      result%fy_norm = result%fy/(mu*ws%load)
      result%coulomb_ratio = c*sqrt(coulomb2)
      result%adhesion_fraction = area_adh/area
      result%parabolic_load_ratio = ws%parabolic_load_ratio
      result%fy_track = c*tan_y + normal_y
      result%fz_track = c*tan_z + normal_z
      result%dy = ws%dy
   end subroutine solve_prepared

   !> The increments of every loaded strip for these creepages, from its local creepages
   !> (shcontact_tangential_spin), and μ p_n,e.
   pure subroutine strip_increments(ws, creepage, lambda)
      type(march_workspace_type), intent(inout) :: ws
      type(creepage_type), intent(in) :: creepage
      real(wp), intent(in) :: lambda
      real(wp) :: nux, phix, nuy, phis, centre_x, centre_y, centre_phi
      integer :: s

      centre_x = 0.0_wp
      centre_y = 0.0_wp
      centre_phi = 0.0_wp
      do s = 1, ws%n_active
         call local_creepages(ws%spin_model, creepage%nu_x, creepage%nu_y, creepage%phi, &
            lambda, ws%cos_ratio(s), ws%phi_geo(s), ws%dphi_geo(s), ws%rho(s), ws%phi_geo0, &
            nux, phix, nuy, phis)
         ! Increments per unit normalised step: −a_s (R_x, R_y) and −a_s² R_φ (§6.5 step 2).
         ws%cx(s) = -(ws%akx(s)*nux - ws%akxs_y(s)*phix)
         ws%cy(s) = -ws%aky(s)*nuy
         ws%cphi(s) = -ws%a2kphi(s)*phis
         ws%mu_pe(s) = ws%friction*ws%pe_peak(s)
         centre_x = centre_x + ws%strip_normal(s)*(nux - phix*ws%y(s))
         centre_y = centre_y + ws%strip_normal(s)*nuy
         centre_phi = centre_phi + ws%strip_normal(s)*phis
      end do
      ws%centre_nu_x = centre_x/ws%load
      ws%centre_nu_y = centre_y/ws%load
      ws%centre_phi = centre_phi/ws%load
   end subroutine strip_increments

   !> Never past Coulomb (doc/tangential.md): the factor c ≤ 1 that brings the total traction
   !> F_t = (F_x, F_y) onto the traction bound when it lies outside, |c F_t| ≤ μF_n. Any traction
   !> field within Coulomb's law, |p_t| ≤ μp_n, has |F_t| ≤ ∫|p_t| ≤ μF_n, and so has the exact
   !> theory's; a total outside (the exact-ellipse correction added to a nearly saturated patch,
   !> the parabolic bound, the midpoint rule of p_n at full slip) is moved radially onto the bound,
   !> its direction (at saturation the rigid slip's) kept.
   pure real(wp) function coulomb_scale(fx, fy, limit) result(c)
      !> Total tangential force (N).
      real(wp), intent(in) :: fx, fy
      !> μF_n (N).
      real(wp), intent(in) :: limit
      real(wp) :: t
      c = 1.0_wp
      t = hypot(fx, fy)
      if (t > limit) c = limit/t
   end function coulomb_scale

   !> The fields' share of the exact-ellipse correction: each loaded strip takes the part
   !> N_s/F_n of ΔF_x and ΔF_y, spread over its elements in proportion to p_n. The fields then
   !> sum to the corrected totals, with the moment −y_c ΔF_x of [[correct_totals]] (p_n of a strip
   !> is symmetric in x, so ΔF_y adds none). Slip and stick/slip state stay the march's.
   pure subroutine spread_defect(ws, dfx, dfy, result)
      type(march_workspace_type), intent(in) :: ws
      !> ΔF_x, ΔF_y (N).
      real(wp), intent(in) :: dfx, dfy
      type(tangential_patch_type), intent(inout) :: result
      real(wp) :: w
      integer :: s, i

      do s = 1, ws%n_active
         i = ws%strip(s)
         w = ws%strip_normal(s)/(ws%load*sum(result%pn(:, i))*result%dx(i)*ws%dy)
         result%px(:, i) = result%px(:, i) + dfx*w*result%pn(:, i)
         result%py(:, i) = result%py(:, i) + dfy*w*result%pn(:, i)
      end do
   end subroutine spread_defect

   !> March the m strips b0 … b0 + m − 1 from the leading edge and sum their output tractions
   !> (doc/theory.md §3.2 steps 2–3, §6.4), element by element, all strips of the block at once.
   pure subroutine march_block(ws, b0, m, shift, result, sx, sy, sxy, cmax, n_adh)
      type(march_workspace_type), intent(inout) :: ws
      integer, intent(in) :: b0, m
      !> The correction's share of every traction, in units of μp_n (0 without a correction).
      real(wp), intent(in) :: shift(2)
      !> The solution, whose element fields are filled when ws%fields.
      type(tangential_patch_type), intent(inout) :: result
      !> Per strip: Σ o_x, Σ o_y, Σ x' o_y, max |o|²/(1 − x'²) and the number of adhesion
      !> elements (a real: an integer count in a SIMD loop over reals stops the vectoriser; it is
      !> exact up to 2⁵³).
      real(wp), dimension(max_block), intent(out) :: sx, sy, sxy, cmax, n_adh
      integer :: b1

      b1 = b0 + m - 1
      call march_strips(ws%bound, ws%fields, m, ws%nx, ws%hn, ws%hm, ws%shape, ws%xn, &
         ws%inv_ell, ws%par, ws%cx(b0:b1), ws%cy(b0:b1), ws%cphi(b0:b1), ws%bound_peak(b0:b1), &
         ws%weight(b0:b1), ws%mu_pe(b0:b1), ws%a(b0:b1), ws%flex_x(b0:b1), ws%flex_y(b0:b1), &
         ws%strip(b0:b1), ws%tx(b0:b1), ws%ty(b0:b1), shift, result, sx, sy, sxy, cmax, n_adh)
   end subroutine march_block

   !> The element loop of [[march_block]] on the block's own arrays (distinct dummies: the
   !> compiler knows they do not overlap).
   pure subroutine march_strips(bound, fields, m, nx, hn, hm, shape, xn, inv_ell, par, cx, cy, &
      cphi, peak, weight, mu_pe, a, flex_x, flex_y, strip, tx, ty, shift, result, sx, sy, sxy, &
      cmax, n_adh)
      integer, intent(in) :: bound, m, nx
      logical, intent(in) :: fields
      real(wp), dimension(nx), intent(in) :: hn, hm, shape, xn, inv_ell, par
      real(wp), dimension(m), intent(in) :: cx, cy, cphi, peak, weight, mu_pe, a, flex_x, flex_y
      integer, intent(in) :: strip(m)
      !> The march tractions of the block's strips.
      real(wp), dimension(m), intent(out) :: tx, ty
      real(wp), intent(in) :: shift(2)
      type(tangential_patch_type), intent(inout) :: result
      real(wp), dimension(max_block), intent(out) :: sx, sy, sxy, cmax, n_adh
      real(wp), dimension(max_block) :: f, qx, qy
      logical :: weighted
      integer :: j

      tx = 0.0_wp
      ty = 0.0_wp
      sx(1:m) = 0.0_wp
      sy(1:m) = 0.0_wp
      sxy(1:m) = 0.0_wp
      cmax(1:m) = 0.0_wp
      n_adh(1:m) = 0.0_wp
      ! The ellipsoidal and parabolic bounds report the march tractions themselves.
      weighted = bound /= bound_ellipsoidal .and. bound /= bound_parabolic
      do j = 1, nx
         call march_step(m, hn(j), hm(j), shape(j), cx, cy, cphi, peak, tx, ty, f)
         if (weighted) then
            call output_step(bound, m, inv_ell(j), par(j), weight, mu_pe, tx, ty, f, qx, qy)
            call accumulate_step(m, xn(j), inv_ell(j), qx, qy, f, shift, mu_pe, sx, sy, sxy, &
               cmax, n_adh)
            if (fields) call keep_step(m, j, hn(j), a, flex_x, flex_y, strip, tx, ty, f, qx, &
               qy, result)
         else
            call accumulate_step(m, xn(j), inv_ell(j), tx, ty, f, shift, mu_pe, sx, sy, sxy, &
               cmax, n_adh)
            if (fields) call keep_step(m, j, hn(j), a, flex_x, flex_y, strip, tx, ty, f, tx, &
               ty, result)
         end if
      end do
   end subroutine march_strips

   !> One element of every strip of a block: p ← p + h (c_x, c_y) + h x_mid c_φ, then the
   !> radial projection onto the bound g = peak·shape, as the branch-free factor
   !> f = √(g²/max(|p|², g²)): exactly 1 in adhesion, g/|p_pred| < 1 in slip (direction kept,
   !> seed eqs 14–15), never a division by zero (g > 0 at element centres).
   pure subroutine march_step(m, h, hm, shape, cx, cy, cphi, peak, px, py, f)
      integer, intent(in) :: m
      real(wp), intent(in) :: h, hm, shape
      real(wp), dimension(m), intent(in) :: cx, cy, cphi, peak
      real(wp), dimension(m), intent(inout) :: px, py
      real(wp), dimension(m), intent(out) :: f
      integer :: l

      !$omp simd
      do l = 1, m
         px(l) = px(l) + cx(l)*h
         py(l) = py(l) + cy(l)*h + cphi(l)*hm
         f(l) = projection(px(l), py(l), (peak(l)*shape)**2)
         px(l) = px(l)*f(l)
         py(l) = py(l)*f(l)
      end do
   end subroutine march_step

   !> Output tractions o from the march tractions t for the weighted bounds (doc/theory.md §6.4;
   !> the ellipsoidal and parabolic bounds report t itself): W1 multiplies all by p_n,e/p_n,p = weight/√(1 − x'²); W2
   !> does so in slip elements (f < 1) and clips adhesion elements to μp_n,e; W3 clips all to
   !> μp_n,e.
   pure subroutine output_step(bound, m, inv_ell, par, weight, mu_pe, px, py, f, qx, qy)
      integer, intent(in) :: bound, m
      !> 1/√(1 − x'²) and 1 − x'² of the element.
      real(wp), intent(in) :: inv_ell, par
      !> Per strip: p_n,e/p_n,p at the strip centre, μ times the peak of p_n,e.
      real(wp), dimension(m), intent(in) :: weight, mu_pe
      real(wp), dimension(m), intent(in) :: px, py, f
      real(wp), dimension(m), intent(out) :: qx, qy
      real(wp) :: w
      integer :: l

      select case (bound)
      case (bound_weighted)
         !$omp simd private(w)
         do l = 1, m
            w = weight(l)*inv_ell
            qx(l) = px(l)*w
            qy(l) = py(l)*w
         end do
      case (bound_weighted_slip)
         !$omp simd private(w)
         do l = 1, m
            w = merge(weight(l)*inv_ell, projection(px(l), py(l), mu_pe(l)**2*par), &
               f(l) < 1.0_wp)
            qx(l) = px(l)*w
            qy(l) = py(l)*w
         end do
      case (bound_clipped)
         !$omp simd private(w)
         do l = 1, m
            w = projection(px(l), py(l), mu_pe(l)**2*par)
            qx(l) = px(l)*w
            qy(l) = py(l)*w
         end do
      end select
   end subroutine output_step

   !> Add the output tractions of one element to the sums of every strip of a block; cmax takes
   !> |q/√(1 − x'²) + shift μp̂_n,e|², the corrected traction over the semi-elliptic shape.
   pure subroutine accumulate_step(m, xn, inv_ell, qx, qy, f, shift, mu_pe, sx, sy, sxy, cmax, &
      n_adh)
      integer, intent(in) :: m
      real(wp), intent(in) :: xn, inv_ell
      real(wp), dimension(m), intent(in) :: qx, qy, f
      !> The correction's share of the traction in units of μp_n, and μ p̂_n,e per strip.
      real(wp), intent(in) :: shift(2)
      real(wp), dimension(m), intent(in) :: mu_pe
      real(wp), dimension(m), intent(inout) :: sx, sy, sxy, cmax, n_adh
      integer :: l

      !$omp simd
      do l = 1, m
         sx(l) = sx(l) + qx(l)
         sy(l) = sy(l) + qy(l)
         sxy(l) = sxy(l) + xn*qy(l)
         cmax(l) = max(cmax(l), (qx(l)*inv_ell + shift(1)*mu_pe(l))**2 + &
            (qy(l)*inv_ell + shift(2)*mu_pe(l))**2)
         n_adh(l) = n_adh(l) + merge(1.0_wp, 0.0_wp, f(l) >= 1.0_wp)
      end do
   end subroutine accumulate_step

   !> Store one element of every strip of a block in the fields: output tractions, state and the
   !> slip magnitude |s| = |L (p_pred − p)|/h (doc/theory.md §3.4), with p_pred − p = (1/f − 1) p
   !> = ((1 − f)/f) p, exactly 0 in adhesion (f = 1).
   pure subroutine keep_step(m, j, hn, a, flex_x, flex_y, strip, px, py, f, qx, qy, result)
      integer, intent(in) :: m, j
      real(wp), intent(in) :: hn
      real(wp), dimension(m), intent(in) :: a, flex_x, flex_y, px, py, f, qx, qy
      integer, intent(in) :: strip(m)
      type(tangential_patch_type), intent(inout) :: result
      real(wp) :: slip(max_block)
      integer :: l, i

      !$omp simd
      do l = 1, m
         slip(l) = (1.0_wp - f(l))*sqrt((flex_x(l)*px(l))**2 + (flex_y(l)*py(l))**2)/ &
            (f(l)*a(l)*hn)
      end do
      do l = 1, m
         i = strip(l)
         result%px(j, i) = qx(l)
         result%py(j, i) = qy(l)
         result%slip(j, i) = slip(l)
         if (f(l) < 1.0_wp) then
            result%state(j, i) = state_slip
         else
            result%state(j, i) = state_adhesion
         end if
      end do
   end subroutine keep_step

   !> min(1, √(limit²/|p|²)) = √(limit²/max(|p|², limit²)), without dividing by zero (limit > 0):
   !> the march's projection factor and the clip factor of W2/W3.
   elemental real(wp) function projection(px, py, limit2)
      real(wp), intent(in) :: px, py, limit2
      projection = sqrt(limit2/max(px*px + py*py, limit2))
   end function projection

   !> The creepage-independent fields of loaded strip s: element positions, p_n,e, y, Δx.
   pure subroutine store_strip(ws, s, result)
      type(march_workspace_type), intent(in) :: ws
      integer, intent(in) :: s
      type(tangential_patch_type), intent(inout) :: result
      integer :: i, nx

      i = ws%strip(s)
      nx = ws%nx
      result%x(:, i) = ws%a(s)*ws%xn(1:nx)
      result%pn(:, i) = ws%pe_peak(s)*ws%ell(1:nx)
      result%y(i) = ws%y_strip(i)
      result%dx(i) = 2.0_wp*ws%a(s)/real(nx, wp)
   end subroutine store_strip

   !> Unloaded strips: exterior, zero fields.
   pure subroutine store_inactive(ws, result)
      type(march_workspace_type), intent(in) :: ws
      type(tangential_patch_type), intent(inout) :: result
      integer :: k, i

      do k = 1, ws%n_strips - ws%n_active
         i = ws%inactive(k)
         result%y(i) = ws%y_strip(i)
         result%dx(i) = 0.0_wp
         result%x(:, i) = 0.0_wp
         result%pn(:, i) = 0.0_wp
         result%px(:, i) = 0.0_wp
         result%py(:, i) = 0.0_wp
         result%slip(:, i) = 0.0_wp
         result%state(:, i) = state_exterior
      end do
   end subroutine store_inactive

   !> Record the grid size; allocate the fields when wanted and their shape differs, release them
   !> when not wanted (so stale fields are never left behind).
   pure subroutine size_result(result, nx, ny, fields)
      type(tangential_patch_type), intent(inout) :: result
      integer, intent(in) :: nx, ny
      logical, intent(in) :: fields
      logical :: fits

      result%nx = nx
      result%ny = ny
      fits = allocated(result%px)
      if (fits) fits = size(result%px, 1) == nx .and. size(result%px, 2) == ny
      if (fields .and. fits) return
      if (allocated(result%x)) deallocate (result%x)
      if (allocated(result%y)) deallocate (result%y)
      if (allocated(result%dx)) deallocate (result%dx)
      if (allocated(result%pn)) deallocate (result%pn)
      if (allocated(result%px)) deallocate (result%px)
      if (allocated(result%py)) deallocate (result%py)
      if (allocated(result%slip)) deallocate (result%slip)
      if (allocated(result%state)) deallocate (result%state)
      if (.not. fields) return
      allocate (result%x(nx, ny), result%y(ny), result%dx(ny), result%pn(nx, ny), &
         result%px(nx, ny), result%py(nx, ny), result%slip(nx, ny), result%state(nx, ny))
   end subroutine size_result

   !> Grow a real array to at least n elements (contents not kept).
   pure subroutine reserve(array, n)
      real(wp), allocatable, intent(inout) :: array(:)
      integer, intent(in) :: n
      if (allocated(array)) then
         if (size(array) >= n) return
         deallocate (array)
      end if
      allocate (array(max(n, 1)))
   end subroutine reserve

   !> Grow an integer array to at least n elements (contents not kept).
   pure subroutine reserve_int(array, n)
      integer, allocatable, intent(inout) :: array(:)
      integer, intent(in) :: n
      if (allocated(array)) then
         if (size(array) >= n) return
         deallocate (array)
      end if
      allocate (array(max(n, 1)))
   end subroutine reserve_int

end module shcontact_tangential_march
