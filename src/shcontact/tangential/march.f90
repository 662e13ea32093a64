!> The strip march shared by classical FASTSIM and FASTSIM_SH (physics.md §3.2, §6.5).
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
module shcontact_tangential_march
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_error, only: error_type, fatal_error, stat_usage
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior, state_adhesion, &
      state_slip
   use shcontact_tangential_creepage, only: creepage_type, check_creepage
   use shcontact_tangential_options, only: bound_ellipsoidal, bound_weighted, &
      bound_weighted_slip, bound_clipped, spin_additive, spin_scaled
   use shcontact_tangential_spin, only: local_creepages, scaled_spin_factor
   implicit none
   private

   public :: march_workspace_type, reserve_workspace, set_element_grid, solve_prepared

   !> Strips marched together (independent dependency chains; a multiple of the SIMD width).
   integer, parameter :: lanes = 8

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
      !> (32/(9π)) Σ k_i N_i / F_n (physics.md §6.4).
      real(wp) :: parabolic_load_ratio = 0.0_wp
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
      !> Strips without load (reported as exterior).
      integer, allocatable :: inactive(:)
      !> Per element: x'_j, step h_j/a, step times midpoint h_j x_mid,j/a², bound shape s_j,
      !> √(1 − x'²), 1 − x'², 1/√(1 − x'²).
      real(wp), allocatable :: xn(:), hn(:), hm(:), shape(:), ell(:), par(:), inv_ell(:)
      !> 1/√(1 − x'²) and 1 − x'² repeated for every lane, index (lane, element): lets the
      !> weighting loops run over contiguous lanes.
      real(wp), allocatable :: inv_ell_lanes(:), par_lanes(:)
      !> Work buffers of one group of [[lanes]] strips, index (lane, element): march tractions,
      !> projection factor (1 in adhesion, < 1 in slip), output tractions.
      real(wp), allocatable :: tx(:), ty(:), sc(:), ox(:), oy(:)
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
      call reserve(ws%xn, nx)
      call reserve(ws%hn, nx)
      call reserve(ws%hm, nx)
      call reserve(ws%shape, nx)
      call reserve(ws%ell, nx)
      call reserve(ws%par, nx)
      call reserve(ws%inv_ell, nx)
      call reserve(ws%inv_ell_lanes, lanes*nx)
      call reserve(ws%par_lanes, lanes*nx)
      call reserve(ws%tx, lanes*nx)
      call reserve(ws%ty, lanes*nx)
      call reserve(ws%sc, lanes*nx)
      call reserve(ws%ox, lanes*nx)
      call reserve(ws%oy, lanes*nx)
   end subroutine reserve_workspace

   !> Element centres, steps and bound shapes of the strip-adapted grid (physics.md §3.2, §6.5
   !> step 3), for ws%nx elements and ws%bound.
   pure subroutine set_element_grid(ws)
      !> The workspace (nx and bound set).
      type(march_workspace_type), intent(inout) :: ws
      real(wp) :: x_prev, step
      integer :: j

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
      do j = 1, ws%nx
         ws%inv_ell_lanes((j - 1)*lanes + 1:j*lanes) = ws%inv_ell(j)
         ws%par_lanes((j - 1)*lanes + 1:j*lanes) = ws%par(j)
      end do
      if (ws%bound == bound_ellipsoidal) then
         ws%shape(1:ws%nx) = ws%ell(1:ws%nx)
      else
         ws%shape(1:ws%nx) = ws%par(1:ws%nx)
      end if
   end subroutine set_element_grid

   !> Solve one set of creepages on a prepared workspace (physics.md §6.5): local creepages per
   !> strip, the march, the output weighting, totals, and the per-element fields when ws%fields.
   !> Strips are marched [[lanes]] at a time, branch-free, so that their dependency chains overlap
   !> and vectorise; a last incomplete group repeats its last strip in the unused lanes.
   pure subroutine solve_prepared(ws, creepage, result, error)
      !> The prepared workspace (its buffers are overwritten).
      type(march_workspace_type), intent(inout) :: ws
      !> Creepages at the reference point.
      type(creepage_type), intent(in) :: creepage
      !> The solution; its arrays are (re)allocated only when their shape changes.
      type(tangential_patch_type), intent(inout) :: result
      !> Set for an unprepared workspace, non-finite creepages, or a singular scaled spin model.
      type(error_type), allocatable, intent(out) :: error
      real(wp), dimension(lanes) :: cx, cy, cphi, peak, mu_pe, weight, sx, sy, sxy, cmax
      real(wp) :: lambda, nux, phix, nuy, phis, strip_area, fx, fy, mz, area, area_adh, &
         coulomb2, mu
      integer :: n_adh(lanes), s0, s, l, nx, n_used

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

      fx = 0.0_wp
      fy = 0.0_wp
      mz = 0.0_wp
      area = 0.0_wp
      area_adh = 0.0_wp
      coulomb2 = 0.0_wp
      do s0 = 1, ws%n_active, lanes
         n_used = min(lanes, ws%n_active - s0 + 1)
         do l = 1, lanes
            s = s0 + min(l, n_used) - 1
            call local_creepages(ws%spin_model, creepage%nu_x, creepage%nu_y, creepage%phi, &
               lambda, ws%cos_ratio(s), ws%phi_geo(s), ws%dphi_geo(s), ws%rho(s), ws%phi_geo0, &
               nux, phix, nuy, phis)
            ! Increments per unit normalised step: −a_s (R_x, R_y) and −a_s² R_φ (§6.5 step 2).
            cx(l) = -(ws%akx(s)*nux - ws%akxs_y(s)*phix)
            cy(l) = -ws%aky(s)*nuy
            cphi(l) = -ws%a2kphi(s)*phis
            peak(l) = ws%bound_peak(s)
            mu_pe(l) = mu*ws%pe_peak(s)
            weight(l) = ws%weight(s)
         end do
         call march_lanes(nx, ws%hn, ws%hm, ws%shape, cx, cy, cphi, peak, ws%tx, ws%ty, ws%sc)
         call weight_lanes(ws%bound, nx, mu_pe, weight, ws%par_lanes, ws%inv_ell_lanes, ws%tx, &
            ws%ty, ws%sc, ws%ox, ws%oy)
         call sum_lanes(nx, ws%xn, ws%inv_ell, ws%ox, ws%oy, ws%sc, sx, sy, sxy, cmax, n_adh)

         do l = 1, n_used
            s = s0 + l - 1
            strip_area = 2.0_wp*ws%a(s)/real(nx, wp)*ws%dy
            fx = fx + strip_area*sx(l)
            fy = fy + strip_area*sy(l)
            mz = mz + strip_area*(ws%a(s)*sxy(l) - (ws%y_offset + ws%y(s))*sx(l))
            area = area + 2.0_wp*ws%a(s)
            area_adh = area_adh + 2.0_wp*ws%a(s)*real(n_adh(l), wp)/real(nx, wp)
            coulomb2 = max(coulomb2, cmax(l)/mu_pe(l)**2)
            if (ws%fields) call store_strip(ws, s, l, result)
         end do
      end do
      if (ws%fields) call store_inactive(ws, result)

      result%fx = fx
      result%fy = fy
      result%mz = mz
      result%fn = ws%load
      result%fx_norm = fx/(mu*ws%load)
      result%fy_norm = fy/(mu*ws%load)
      result%coulomb_ratio = sqrt(coulomb2)
      result%adhesion_fraction = area_adh/area
      result%parabolic_load_ratio = ws%parabolic_load_ratio
      result%fy_track = fy*cos(ws%gamma0) + ws%load*sin(ws%gamma0)
      result%fz_track = fy*sin(ws%gamma0) - ws%load*cos(ws%gamma0)
      result%dy = ws%dy
   end subroutine solve_prepared

   !> March [[lanes]] strips from the leading edge (physics.md §3.2 steps 2–3). The projection
   !> onto the bound g_j is written branch-free as the factor f = √(g²/max(|p|², g²)): exactly 1
   !> in adhesion, g/|p_pred| < 1 in slip (radial projection, direction kept, seed eqs 14–15),
   !> and never a division by zero (g > 0 at element centres). t = the projected tractions.
   pure subroutine march_lanes(nx, hn, hm, shape, cx, cy, cphi, peak, tx, ty, sc)
      integer, intent(in) :: nx
      real(wp), intent(in) :: hn(nx), hm(nx), shape(nx)
      real(wp), dimension(lanes), intent(in) :: cx, cy, cphi, peak
      real(wp), dimension(lanes, nx), intent(out) :: tx, ty, sc
      real(wp), dimension(lanes) :: px, py
      real(wp) :: hj, mj, sj, g2, f
      integer :: j, l

      px = 0.0_wp
      py = 0.0_wp
      do j = 1, nx
         hj = hn(j)
         mj = hm(j)
         sj = shape(j)
         ! The lanes are independent: an explicit SIMD loop (with array syntax the vectoriser
         ! packed the lanes only partly, 1.7 times slower).
         !$omp simd private(g2, f)
         do l = 1, lanes
            px(l) = px(l) + cx(l)*hj
            py(l) = py(l) + cy(l)*hj + cphi(l)*mj
            g2 = (peak(l)*sj)**2
            f = sqrt(g2/max(px(l)*px(l) + py(l)*py(l), g2))
            px(l) = px(l)*f
            py(l) = py(l)*f
            tx(l, j) = px(l)
            ty(l, j) = py(l)
            sc(l, j) = f
         end do
      end do
   end subroutine march_lanes

   !> Output tractions o from the march tractions t (physics.md §6.4): unchanged for the
   !> ellipsoidal and parabolic bounds; W1 multiplies all by p_n,e/p_n,p = weight/√(1 − x'²); W2
   !> does so in slip elements (sc < 1) and clips adhesion elements to μp_n,e; W3 clips all to
   !> μp_n,e.
   pure subroutine weight_lanes(bound, nx, mu_pe, weight, par, inv_ell, tx, ty, sc, ox, oy)
      integer, intent(in) :: bound, nx
      !> μ times the peak of p_n,e, and p_n,e/p_n,p at the strip centre, per lane.
      real(wp), dimension(lanes), intent(in) :: mu_pe, weight
      !> 1 − x'² and 1/√(1 − x'²) per (lane, element).
      real(wp), dimension(lanes, nx), intent(in) :: par, inv_ell
      real(wp), dimension(lanes, nx), intent(in) :: tx, ty, sc
      real(wp), dimension(lanes, nx), intent(out) :: ox, oy
      real(wp) :: w
      integer :: j, l

      select case (bound)
      case (bound_weighted)
         do j = 1, nx
            !$omp simd private(w)
            do l = 1, lanes
               w = weight(l)*inv_ell(l, j)
               ox(l, j) = tx(l, j)*w
               oy(l, j) = ty(l, j)*w
            end do
         end do
      case (bound_weighted_slip)
         do j = 1, nx
            !$omp simd private(w)
            do l = 1, lanes
               if (sc(l, j) < 1.0_wp) then
                  w = weight(l)*inv_ell(l, j)
               else
                  w = clip_factor(tx(l, j), ty(l, j), mu_pe(l)**2*par(l, j))
               end if
               ox(l, j) = tx(l, j)*w
               oy(l, j) = ty(l, j)*w
            end do
         end do
      case (bound_clipped)
         do j = 1, nx
            !$omp simd private(w)
            do l = 1, lanes
               w = clip_factor(tx(l, j), ty(l, j), mu_pe(l)**2*par(l, j))
               ox(l, j) = tx(l, j)*w
               oy(l, j) = ty(l, j)*w
            end do
         end do
      case default
         ox = tx
         oy = ty
      end select
   end subroutine weight_lanes

   !> min(1, √(limit²/|p|²)) = √(limit²/max(|p|², limit²)), without dividing by zero (limit > 0).
   elemental real(wp) function clip_factor(px, py, limit2)
      real(wp), intent(in) :: px, py, limit2
      clip_factor = sqrt(limit2/max(px*px + py*py, limit2))
   end function clip_factor

   !> Per lane: Σ o_x, Σ o_y, Σ x' o_y, max |o|²/(1 − x'²) and the number of adhesion elements.
   pure subroutine sum_lanes(nx, xn, inv_ell, ox, oy, sc, sx, sy, sxy, cmax, n_adh)
      integer, intent(in) :: nx
      real(wp), intent(in) :: xn(nx), inv_ell(nx)
      real(wp), dimension(lanes, nx), intent(in) :: ox, oy, sc
      real(wp), dimension(lanes), intent(out) :: sx, sy, sxy, cmax
      integer, intent(out) :: n_adh(lanes)
      integer :: j

      sx = 0.0_wp
      sy = 0.0_wp
      sxy = 0.0_wp
      cmax = 0.0_wp
      n_adh = 0
      do j = 1, nx
         sx = sx + ox(:, j)
         sy = sy + oy(:, j)
         sxy = sxy + xn(j)*oy(:, j)
         cmax = max(cmax, (ox(:, j)**2 + oy(:, j)**2)*inv_ell(j)**2)
         n_adh = n_adh + merge(1, 0, sc(:, j) >= 1.0_wp)
      end do
   end subroutine sum_lanes

   !> Copy the fields of loaded strip s (lane l of the buffers) into column strip(s).
   pure subroutine store_strip(ws, s, l, result)
      type(march_workspace_type), intent(in) :: ws
      integer, intent(in) :: s, l
      type(tangential_patch_type), intent(inout) :: result
      call store_lane(ws%nx, ws%a(s), ws%flex_x(s), ws%flex_y(s), ws%pe_peak(s), ws%xn, &
         ws%hn, ws%ell, ws%tx, ws%ty, ws%sc, ws%ox, ws%oy, l, result%x(:, ws%strip(s)), &
         result%pn(:, ws%strip(s)), result%px(:, ws%strip(s)), result%py(:, ws%strip(s)), &
         result%slip(:, ws%strip(s)), result%state(:, ws%strip(s)))
      result%y(ws%strip(s)) = ws%y_strip(ws%strip(s))
      result%dx(ws%strip(s)) = 2.0_wp*ws%a(s)/real(ws%nx, wp)
   end subroutine store_strip

   !> The per-element fields of one lane: positions, p_n,e, output tractions, state and the slip
   !> magnitude |s| = |L (p_pred − p)|/h (physics.md §3.4), p_pred − p = (1/f − 1) p with the
   !> march tractions p and projection factor f.
   pure subroutine store_lane(nx, a, flex_x, flex_y, pe_peak, xn, hn, ell, tx, ty, sc, ox, oy, &
      l, x, pn, px, py, slip, state)
      integer, intent(in) :: nx, l
      real(wp), intent(in) :: a, flex_x, flex_y, pe_peak
      real(wp), intent(in) :: xn(nx), hn(nx), ell(nx)
      real(wp), dimension(lanes, nx), intent(in) :: tx, ty, sc, ox, oy
      real(wp), intent(out) :: x(nx), pn(nx), px(nx), py(nx), slip(nx)
      integer(i1), intent(out) :: state(nx)
      integer :: j

      do j = 1, nx
         x(j) = a*xn(j)
         pn(j) = pe_peak*ell(j)
         px(j) = ox(l, j)
         py(j) = oy(l, j)
         if (sc(l, j) < 1.0_wp) then
            state(j) = state_slip
            slip(j) = (1.0_wp/sc(l, j) - 1.0_wp)* &
               sqrt((flex_x*tx(l, j))**2 + (flex_y*ty(l, j))**2)/(a*hn(j))
         else
            state(j) = state_adhesion
            slip(j) = 0.0_wp
         end if
      end do
   end subroutine store_lane

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
