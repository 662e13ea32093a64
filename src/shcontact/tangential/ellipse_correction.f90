!> The exact-ellipse correction of FASTSIM_SH (`correction = 'exact-ellipse'`, doc/tangential.md
!> "Exact-ellipse correction").
!>
!> The simplified theory's error against Kalker's exact theory depends on the patch's shape and
!> on how far the creepages drive it into slip, much more than on the details of its pressure.
!> So it is measured where both theories can be run, on Hertz ellipses: the table
!> (shcontact_tangential_ellipse_table) holds D = f_exact − f_FASTSIM_SH, the normalised force
!> defect on an ellipse, against a/b and the creepages. A patch takes the defect of its equivalent
!> ellipse (semi-axes a_e, b_e: b_e half the loaded width, π a_e b_e the area) at the creepages of
!> its load centre, and adds it to its own FASTSIM_SH forces. On an ellipse this gives the exact
!> theory up to the table's interpolation; on other patches it keeps FASTSIM_SH's account of the
!> pressure shape and removes the simplified theory's error (doc/validation.md §6.4).
!>
!> The creepages are scaled by the linear theory of the equivalent ellipse, so that 1 means the
!> linear force reaches 3μF_n: s_x = G a b c₁₁ ν_x/(3μF_n), s_y = G a b c₂₂ ν_y/(3μF_n),
!> s_φ = G (ab)^{3/2} c₂₃ φ/(3μF_n), and mapped to t = s/(1 + |s|) ∈ (−1, 1). The table runs over
!> t_x ∈ [0, 0.9] and t_y ∈ [−0.9, 0.9] in steps of 0.1, and t_φ at the nodes table_t_phi (steps
!> of 0.05 up to 0.5, where the pure-spin force peaks and the defect changes fast, then 0.1); at
!> |t| = 1 (full slip) both theories give μp along the rigid slip, so D = 0 there. Other signs follow from the ellipse's symmetries:
!> D is odd in (ν_x, ν_y, φ) together, and mirroring y maps (ν_x, ν_y, φ) to (ν_x, −ν_y, −φ) and
!> (D_x, D_y) to (D_x, −D_y); together, ν_x → −ν_x maps D to (−D_x, D_y).
module shcontact_tangential_ellipse_correction
   use shcontact_core_kinds, only: wp
   use shcontact_core_material, only: material_type
   use shcontact_normal_patch, only: normal_patch_type, ellipse_strip_patch
   use shcontact_tangential_kalker, only: kalker_coefficients
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_ellipse_table, only: table_ratio, table_t_phi, table_dfx, table_dfy, &
      table_linear, table_unit, n_table_ratio, n_table_t, n_table_ty, n_table_phi
   implicit none
   private

   public :: ellipse_correction_type, prepare_ellipse_correction, ellipse_defect, table_node_case
   public :: table_area, table_load, table_strips

   !> The table's ellipses: area π a b (mm²), load (N) and strips of the FASTSIM_SH side, with
   !> the rolling radius r₀ = 460 mm (no effect: flat patch, uniform spin).
   real(wp), parameter :: table_area = 36.0_wp, table_load = 64700.0_wp
   integer, parameter :: table_strips = 100

   !> The equivalent ellipse of one patch, ready for [[ellipse_defect]].
   type :: ellipse_correction_type
      !> Apply the correction (set by [[prepare_ellipse_correction]]).
      logical :: active = .false.
      !> ln(a_e/b_e), clamped to the table's range; the lower a/b node and the weights of it
      !> and the next.
      real(wp) :: log_ratio = 0.0_wp
      integer :: ratio_node = 1
      real(wp) :: ratio_weight(2) = [1.0_wp, 0.0_wp]
      !> Near zero creepage: the defect's true slopes (table_linear) minus those of the table's
      !> first cell, dD_x/ds_x, dD_y/ds_y, dD_y/ds_φ ([[add_linear_regime]]).
      real(wp) :: slope_gap(3) = 0.0_wp
      !> Scaled creepage per unit creepage: s_x/ν_x, s_y/ν_y (dimensionless), s_φ/φ (mm).
      real(wp) :: scale_x = 0.0_wp, scale_y = 0.0_wp, scale_phi = 0.0_wp
      !> Load centre from the reference point (mm); mean cos γ and sin γ over the load, for the
      !> moment and the track-frame forces of the correction.
      real(wp) :: y_centre = 0.0_wp, cos_gamma = 1.0_wp, sin_gamma = 0.0_wp
   end type ellipse_correction_type

contains

   !> Set up the correction of a patch from its equivalent ellipse.
   pure subroutine prepare_ellipse_correction(correction, semi_a, semi_b, load, material, &
      y_centre, cos_gamma, sin_gamma)
      !> The correction (active on return).
      type(ellipse_correction_type), intent(out) :: correction
      !> Semi-axes a_e (rolling direction) and b_e (lateral) of the equivalent ellipse (mm), > 0.
      real(wp), intent(in) :: semi_a, semi_b
      !> Normal force of the patch (N), > 0.
      real(wp), intent(in) :: load
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Load centre from the reference point (mm), mean cos γ and sin γ over the load.
      real(wp), intent(in) :: y_centre, cos_gamma, sin_gamma
      real(wp) :: c11, c22, c23, saturation

      call kalker_coefficients(semi_a/semi_b, material%poisson, c11, c22, c23)
      saturation = 3.0_wp*material%friction*load
      correction%active = .true.
      correction%log_ratio = min(max(log(semi_a/semi_b), log(table_ratio(1))), &
         log(table_ratio(n_table_ratio)))
      call ratio_bracket(correction%log_ratio, correction%ratio_node, correction%ratio_weight)
      correction%slope_gap = linear_slope_gap(correction%ratio_node, correction%ratio_weight)
      correction%scale_x = material%shear_modulus*semi_a*semi_b*c11/saturation
      correction%scale_y = material%shear_modulus*semi_a*semi_b*c22/saturation
      correction%scale_phi = material%shear_modulus*(semi_a*semi_b)**1.5_wp*c23/saturation
      correction%y_centre = y_centre
      correction%cos_gamma = cos_gamma
      correction%sin_gamma = sin_gamma
   end subroutine prepare_ellipse_correction

   !> The force defect f_exact − f_FASTSIM_SH of the equivalent ellipse at the creepages of the
   !> load centre, normalised by μF_n (our sign convention, doc/theory.md §0).
   pure subroutine ellipse_defect(correction, nu_x, nu_y, phi, dfx, dfy)
      !> The prepared correction.
      type(ellipse_correction_type), intent(in) :: correction
      !> Creepages at the load centre: ν_x, ν_y (dimensionless), φ (rad/mm).
      real(wp), intent(in) :: nu_x, nu_y, phi
      !> Defects of f_x = F_x/(μF_n) and f_y.
      real(wp), intent(out) :: dfx, dfy
      real(wp) :: sx, sy, sp, sign_x, sign_y, w(2, 4)
      integer :: lo(4), ir, ix, iy, ip

      sx = correction%scale_x*nu_x
      sy = correction%scale_y*nu_y
      sp = correction%scale_phi*phi
      sign_y = 1.0_wp
      if (sp < 0.0_wp) then
         sy = -sy
         sp = -sp
         sign_y = -1.0_wp
      end if
      sign_x = sign(1.0_wp, sx)
      sx = abs(sx)
      lo(1) = correction%ratio_node
      w(:, 1) = correction%ratio_weight
      call t_bracket(sx/(1.0_wp + sx), 0, lo(2), w(:, 2))
      call t_bracket(sy/(1.0_wp + abs(sy)), -n_table_t, lo(3), w(:, 3))
      call phi_bracket(sp/(1.0_wp + sp), lo(4), w(:, 4))
      dfx = 0.0_wp
      dfy = 0.0_wp
      do ir = 0, 1
         do ix = 0, 1
            do iy = 0, 1
               do ip = 0, 1
                  call add_corner(lo(1) + ir, lo(2) + ix, lo(3) + iy, lo(4) + ip, &
                     w(ir + 1, 1)*w(ix + 1, 2)*w(iy + 1, 3)*w(ip + 1, 4), dfx, dfy)
               end do
            end do
         end do
      end do
      dfx = table_unit*dfx
      dfy = table_unit*dfy
      call add_linear_regime(correction%slope_gap, sx, sy, sp, dfx, dfy)
      dfx = sign_x*dfx
      dfy = sign_y*dfy
   end subroutine ellipse_defect

   !> Near zero creepage the defect is linear in s, with the slope of the exact linear theory
   !> minus FASTSIM_SH's (table_linear); the table's first cell, which reaches s ≈ 0.1 where
   !> saturation has begun, has another slope. Inside that cell (u = max(t_x/t₁, |t_y|/t₁,
   !> t_φ/t_φ,₁) < 1) add the difference of the slopes (slope_gap, [[linear_slope_gap]]) times
   !> s, weighted by 1 − u: the derivative at zero is then the linear theory's, and every node
   !> keeps its value.
   pure subroutine add_linear_regime(slope_gap, sx, sy, sp, dfx, dfy)
      !> Slope differences dD_x/ds_x, dD_y/ds_y, dD_y/ds_φ of the patch's a/b.
      real(wp), intent(in) :: slope_gap(3)
      !> Scaled creepages (s_x, s_φ ≥ 0).
      real(wp), intent(in) :: sx, sy, sp
      !> Defects from the table (units of μF_n), updated.
      real(wp), intent(inout) :: dfx, dfy
      real(wp) :: t1, weight

      t1 = 1.0_wp/n_table_t
      weight = 1.0_wp - max(sx/(1.0_wp + sx)/t1, abs(sy)/(1.0_wp + abs(sy))/t1, &
         sp/(1.0_wp + sp)/table_t_phi(2))
      if (weight <= 0.0_wp) return
      dfx = dfx + weight*slope_gap(1)*sx
      dfy = dfy + weight*(slope_gap(2)*sy + slope_gap(3)*sp)
   end subroutine add_linear_regime

   !> The true slopes of the defect at zero creepage (table_linear) minus the table's own along
   !> each axis (its first node over that node's s), interpolated in a/b.
   pure function linear_slope_gap(lo, w) result(gap)
      !> Lower a/b node and weights.
      integer, intent(in) :: lo
      real(wp), intent(in) :: w(2)
      real(wp) :: gap(3)
      real(wp) :: s1, s1_phi
      integer :: h, k

      h = n_table_ty/2
      s1 = 1.0_wp/(n_table_t - 1)
      s1_phi = table_t_phi(2)/(1.0_wp - table_t_phi(2))
      gap = 0.0_wp
      do k = 0, 1
         gap = gap + w(k + 1)*(table_linear(:, lo + k) - table_unit*[ &
            table_dfx(1, h + 1, 2, lo + k)/s1, table_dfy(1, h + 2, 1, lo + k)/s1, &
            table_dfy(2, h + 1, 1, lo + k)/s1_phi])
      end do
   end function linear_slope_gap

   !> The ellipse and the creepages (our sign) of table node (i_ratio, k_x, k_y, i_φ): semi-axes
   !> with a/b = table_ratio(i_ratio) and area table_area, table_load on table_strips strips, and
   !> the creepages whose scaled values are s = t/(1 − |t|) at t_x = k_x/n_table_t, t_y =
   !> k_y/n_table_t and t_φ = table_t_phi(i_φ). The exact side of the table
   !> (scripts/contact_ellipse_table.py) runs CONTACT on the same ellipse with the creepages of
   !> opposite sign (CONTACT's: rail relative to wheel).
   pure subroutine table_node_case(i_ratio, kx, ky, ip, material, patch, creepage)
      !> Node indices: 1..n_table_ratio; 0..n_table_t − 1; −(n_table_ty/2)..n_table_ty/2;
      !> 1..n_table_phi.
      integer, intent(in) :: i_ratio, kx, ky, ip
      !> G, ν, μ of the table (ν = table_poisson).
      type(material_type), intent(in) :: material
      !> The ellipse's strip table.
      type(normal_patch_type), intent(out) :: patch
      !> Creepages at the centre (our sign).
      type(creepage_type), intent(out) :: creepage
      type(ellipse_correction_type) :: scale
      real(wp) :: a, b

      a = sqrt(table_area*table_ratio(i_ratio))
      b = a/table_ratio(i_ratio)
      call ellipse_strip_patch(a, b, table_load, table_strips, 460.0_wp, patch)
      call prepare_ellipse_correction(scale, a, b, patch%load, material, 0.0_wp, 1.0_wp, 0.0_wp)
      creepage = creepage_type(-scaled(real(kx, wp)/n_table_t)/scale%scale_x, &
         -scaled(real(ky, wp)/n_table_t)/scale%scale_y, -scaled(table_t_phi(ip))/scale%scale_phi)

   contains

      pure real(wp) function scaled(t)
         real(wp), intent(in) :: t
         scaled = t/(1.0_wp - abs(t))
      end function scaled

   end subroutine table_node_case

   !> Lower node and weights (of it and the next) in ln(a/b); the value is inside the table.
   pure subroutine ratio_bracket(log_ratio, lo, w)
      real(wp), intent(in) :: log_ratio
      integer, intent(out) :: lo
      real(wp), intent(out) :: w(2)
      real(wp) :: l0, l1
      integer :: i

      lo = n_table_ratio - 1
      do i = 1, n_table_ratio - 2
         if (log_ratio < log(table_ratio(i + 1))) then
            lo = i
            exit
         end if
      end do
      l0 = log(table_ratio(lo))
      l1 = log(table_ratio(lo + 1))
      w(2) = min(max((log_ratio - l0)/(l1 - l0), 0.0_wp), 1.0_wp)
      w(1) = 1.0_wp - w(2)
   end subroutine ratio_bracket

   !> Lower node index (node k at t = k/n_table_t, k from first) and weights for t in (−1, 1);
   !> node ±n_table_t is the full-slip limit.
   pure subroutine t_bracket(t, first, lo, w)
      real(wp), intent(in) :: t
      integer, intent(in) :: first
      integer, intent(out) :: lo
      real(wp), intent(out) :: w(2)
      real(wp) :: u

      u = t*n_table_t
      lo = min(max(floor(u), first), n_table_t - 1)
      w(2) = min(max(u - lo, 0.0_wp), 1.0_wp)
      w(1) = 1.0_wp - w(2)
   end subroutine t_bracket

   !> Lower node index (1..n_table_phi) and weights for t_φ in [0, 1); node n_table_phi + 1 is
   !> the full-slip limit t_φ = 1.
   pure subroutine phi_bracket(t, lo, w)
      real(wp), intent(in) :: t
      integer, intent(out) :: lo
      real(wp), intent(out) :: w(2)
      real(wp) :: t_hi
      integer :: i

      lo = n_table_phi
      do i = 1, n_table_phi - 1
         if (t < table_t_phi(i + 1)) then
            lo = i
            exit
         end if
      end do
      t_hi = 1.0_wp
      if (lo < n_table_phi) t_hi = table_t_phi(lo + 1)
      w(2) = min(max((t - table_t_phi(lo))/(t_hi - table_t_phi(lo)), 0.0_wp), 1.0_wp)
      w(1) = 1.0_wp - w(2)
   end subroutine phi_bracket

   !> Add weight × the table's defects at one corner (t_x, t_y nodes k_x, k_y; t_φ node i_φ);
   !> zero at the full-slip nodes |k| = n_table_t and i_φ = n_table_phi + 1.
   pure subroutine add_corner(ir, kx, ky, ip, weight, dfx, dfy)
      integer, intent(in) :: ir, kx, ky, ip
      real(wp), intent(in) :: weight
      real(wp), intent(inout) :: dfx, dfy

      if (weight == 0.0_wp) return
      if (kx >= n_table_t .or. abs(ky) >= n_table_t .or. ip > n_table_phi) return
      dfx = dfx + weight*table_dfx(ip, ky + n_table_ty/2 + 1, kx + 1, ir)
      dfy = dfy + weight*table_dfy(ip, ky + n_table_ty/2 + 1, kx + 1, ir)
   end subroutine add_corner

end module shcontact_tangential_ellipse_correction
