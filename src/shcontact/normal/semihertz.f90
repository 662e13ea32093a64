!> The semi-Hertzian strip method (doc/theory.md §4.3) on one patch, for a given approach.
!>
!> The geometry tables are first reduced once, by [[prepare_semihertz]], to what every load
!> iteration needs: the penetration split ε_a(y), ε_b(y) (which depends only on A(y)/B(y),
!> decision 5), the Hertz coefficients m(y), n(y) and the pressure factor √((A+B)/(E K)). The
!> strips for one approach are then laid out by [[semihertz_strips]] without any elliptic
!> integral or allocation. [[ellipse_strips]] gives the strip table of one Hertz ellipse
!> (`method = 'hertz'`) on the same geometry.
!>
!> **The approach is a vertical translation of the wheel** (doc/geometry.md, "Vertical approach").
!> The wheelset moves down under its load; it does not move along each strip's normal. Where the
!> contact angle varies across the patch, such a translation closes the gap along the contact
!> normal by Δ(1 − c(y)), c = tan γ₀ tan(γ(y) − γ₀), not by Δ, so the interpenetration is
!> δ − g(y) − (δ + g₀)c(y) (g₀ the gap at the reference point when several patches share one
!> vertical approach). This is the undeformed distance of the loaded state, CONTACT's h of
!> module 1 (test vertical_approach/loaded_gap_is_contacts_h); on a flange root it moves the
!> contact point by more than 0.2 mm. The geometric contact point of the loaded state, the
!> minimum of that distance, is where [[refer_to_loaded_point]] puts the strips' origin.
module shcontact_normal_semihertz
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_no_contact, stat_invalid_input
   use shcontact_core_strings, only: str_real
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, method_semi_hertz, reduction_constant, &
      slide_exact
   use shcontact_normal_hertz, only: hertz_type, hertz_strip_shapes
   use shcontact_normal_patch, only: normal_patch_type, reserve_strips, clear_strips, clear_totals, &
      clear_arrays, strip_totals
   use shcontact_normal_strip_cover, only: cover_ramp, outward_cover, reached_end
   use shcontact_normal_angles, only: tilt_terms, interface_angles
   use shcontact_normal_patch_tables, only: check_geometry, reference_curvatures
   use shcontact_normal_reference, only: reference_index, blend_depth
   use shcontact_normal_slide, only: secant_tilt, running_integral
   implicit none
   private

   public :: semihertz_geometry_type, prepare_semihertz, semihertz_strips, semihertz_load, &
      ellipse_strips
   public :: reserve_strips, clear_strips, refer_to_loaded_point, use_interface_angles, &
      loaded_gap

   !> Smallest ψ per unit approach, as a fraction of ε_b: a point where the tilt term c reaches
   !> ε_b (far out on a steep flank) would never come into contact; it then comes in only at
   !> approaches far beyond any load.
   real(wp), parameter :: min_slope = 0.01_wp
   !> d/(δ + g₀) = slide_sign tan γ₀ ([[prepare_slide]]).
   real(wp), parameter :: slide_sign = -1.0_wp

   !> A patch geometry prepared for the strip method: the tables of the input on the same uniform
   !> grid, plus the per-point quantities that depend only on A/B. Reused across loads.
   type :: semihertz_geometry_type
      !> Number of table points (the arrays below may be longer: only the first n_table entries
      !> belong to the table).
      integer :: n_table = 0
      !> Table point where contact starts (smallest g/ε_b; the reference point y = 0 for a
      !> well-formed table).
      integer :: i_first = 0
      !> First table abscissa and spacing (mm).
      real(wp) :: y_first = 0.0_wp, h = 0.0_wp
      !> Contact angle γ₀ (rad), rolling radius r₀ (mm) and gap g₀ (mm) of the reference point.
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp, gap0 = 0.0_wp
      !> The geometry's tables are conformal (shcontact_geometry_patch).
      logical :: conformal = .false.
      !> Curvatures A, B at the reference point y = 0 (1/mm), for `method = 'hertz'`.
      real(wp) :: curv_a0 = 0.0_wp, curv_b0 = 0.0_wp
      !> Approach at which contact starts, min g/ε_b (mm); 0 for a well-formed table.
      real(wp) :: approach_touch = 0.0_wp
      !> Largest approach whose contact interval stays inside the table (mm).
      real(wp) :: approach_max = 0.0_wp
      !> Approach beyond which a table ended by the touch approach (the geometry's touch_reach)
      !> may miss a region that its strips would sweep towards ([[outward_cover]]): (1 −
      !> cover_ramp) touch_reach (mm; huge for a table ended by the gap). A larger approach is
      !> treated as the table's end, so that every such table gives the full table's strips.
      real(wp) :: approach_reach = huge(1.0_wp)
      !> True when the per-point strip quantities below were computed (semi-Hertz method).
      logical :: has_strip_data = .false.
      !> g(y) (mm), A(y) (1/mm), γ(y) (rad), r_w(y) (mm).
      real(wp), allocatable :: gap(:), curv_a(:), gamma(:), r_wheel(:)
      !> γ_n(y): the direction of the pressure, the angle of the interface midway between the
      !> undeformed surfaces ([[interface_angles]]) (rad).
      real(wp), allocatable :: gamma_n(:)
      !> Penetration split used by the strips: local Hertz ε_a, ε_b, or the constant ε.
      real(wp), allocatable :: eps_a(:), eps_b(:)
      !> Tilt term c(y) = tan γ₀ tan(γ(y) − γ₀) of the vertical approach ([[vertical_tilt]]):
      !> a vertical translation of the wheel that closes the gap by Δ at the reference point
      !> closes it by Δ(1 − c(y)) at y, along the contact normal.
      real(wp), allocatable :: tilt(:)
      !> Whether the approach slides the wheel exactly ([[slide_tilt]], `&normal slide =
      !> 'exact'`): the loaded gap g + (δ + g₀)c̄(d) with the secant tilt c̄ over the slide d,
      !> instead of the tilt's linear term (δ + g₀)c.
      logical :: exact_slide = .false.
      !> The slide per unit approach d/(δ + g₀) = −tan γ₀ (mm/mm): a vertical translation of
      !> the wheel that closes the gap by δ + g₀ at the reference point carries the wheel's
      !> surface by d along the contact plane: the wheel point above table point y after it is
      !> the one at y + d before.
      real(wp) :: slide_rate = 0.0_wp
      !> Running integral of the tilt, Q(y_j) = ∫ c dy from the first point (trapezoids of the
      !> piecewise linear c) (mm), for the secant tilt of the exact slide.
      real(wp), allocatable :: tilt_integral(:)
      !> ψ per unit approach, ε_b − c (clamped at a small fraction of ε_b).
      real(wp), allocatable :: psi_slope(:)
      !> Approach at which each table point comes into contact, (g + g₀c)/(ε_b − c) (mm).
      real(wp), allocatable :: touch(:)
      !> Approach from which the strips cover each table point ([[outward_cover]]): at most
      !> touch, monotonic on each side of i_first, so the strips' interval for an approach δ is
      !> where cover < δ, found by bisection. It holds every point in contact (touch < δ), also
      !> beyond a point out of contact, and its ends move continuously with δ.
      real(wp), allocatable :: cover(:)
      !> Local Hertz coefficients m(y), n(y).
      real(wp), allocatable :: m(:), n(:)
      !> Pressure factor √((A+B)/(E(k)K(k))) (1/√mm²): p₀ = E*·factor·√δ (doc/theory.md §4.3
      !> step 5 with §1.3 items 3–4).
      real(wp), allocatable :: p_factor(:)
   end type semihertz_geometry_type

contains

   !> Check a patch geometry and reduce it to a [[semihertz_geometry_type]]: once per geometry.
   !> The tables used are points first..last of the geometry's (all of them by default), with
   !> the gap at the two ends optionally replaced (a table cut at a basin limit, see
   !> shcontact_normal_loading). The arrays of `prepared` only grow: a reused one allocates
   !> nothing once it has held a table as long.
   subroutine prepare_semihertz(geometry, options, prepared, error, first, last, gap_first, &
         gap_last)
      !> The patch geometry (uniform y grid containing y = 0).
      type(patch_geometry_type), intent(in) :: geometry
      !> Method and reduction.
      type(normal_options_type), intent(in) :: options
      !> The prepared geometry.
      type(semihertz_geometry_type), intent(inout) :: prepared
      !> Set for an inconsistent or non-Hertzian table.
      type(error_type), allocatable, intent(out) :: error
      !> First and last table point used (default 1 and size(geometry%y); with `last` the
      !> arrays may be longer than the table).
      integer, intent(in), optional :: first, last
      !> Gap to use at the first and the last point used instead of the table's (mm).
      real(wp), intent(in), optional :: gap_first, gap_last

      integer :: n, i1, i2

      i1 = 1
      if (present(first)) i1 = first
      call check_geometry(geometry, i1, last, error)
      if (allocated(error)) return
      i2 = size(geometry%y)
      if (present(last)) i2 = last
      n = i2 - i1 + 1
      call reserve_table(prepared, n)
      prepared%y_first = geometry%y(i1)
      prepared%h = geometry%h
      prepared%gamma0 = geometry%gamma0
      prepared%conformal = geometry%conformal
      prepared%r0 = geometry%r0
      prepared%gap0 = geometry%gap0
      call reference_curvatures(geometry, i1, i2, prepared%curv_a0, prepared%curv_b0)
      prepared%gap(1:n) = geometry%gap(i1:i2)
      if (present(gap_first)) prepared%gap(1) = gap_first
      if (present(gap_last)) prepared%gap(n) = gap_last
      prepared%curv_a(1:n) = geometry%curv_a(i1:i2)
      prepared%gamma(1:n) = geometry%gamma(i1:i2)
      prepared%r_wheel(1:n) = geometry%r_wheel(i1:i2)
      ! The interface angles only where a caller asks for them ([[use_interface_angles]]):
      ! a tangent and an arctangent per table point are not for the default path.
      prepared%gamma_n(1:n) = prepared%gamma(1:n)

      prepared%has_strip_data = options%method == method_semi_hertz
      if (.not. prepared%has_strip_data) then
         prepared%i_first = 0
         prepared%approach_touch = 0.0_wp
         prepared%approach_max = huge(1.0_wp)
         prepared%approach_reach = huge(1.0_wp)
         return
      end if

      ! The shape depends only on A/B (decision 5): from the table, no root search.
      call hertz_strip_shapes(geometry%curv_a(i1:i2), geometry%curv_b(i1:i2), &
         prepared%eps_a(1:n), prepared%eps_b(1:n), prepared%m(1:n), prepared%n(1:n), &
         prepared%p_factor(1:n), error)
      if (allocated(error)) return
      if (options%reduction == reduction_constant) then
         ! Kik–Piotrowski: the virtual penetration ε·δ in both directions (doc/theory.md §4.2).
         prepared%eps_a(1:n) = options%epsilon
         prepared%eps_b(1:n) = options%epsilon
      end if
      call tilt_terms(geometry, i1, i2, prepared%gamma0, prepared%tilt(1:n))
      prepared%psi_slope(1:n) = max(prepared%eps_b(1:n) - prepared%tilt(1:n), &
         min_slope*prepared%eps_b(1:n))
      prepared%touch(1:n) = (prepared%gap(1:n) + prepared%gap0*prepared%tilt(1:n))/ &
         prepared%psi_slope(1:n)
      prepared%exact_slide = options%slide == slide_exact
      if (prepared%exact_slide .and. prepared%conformal) then
         call fatal_error(error, "normal options: slide = 'exact' needs planar strip tables "// &
            "(the contact search's conformal_tables off)", stat_invalid_input)
         return
      end if
      if (prepared%exact_slide) call prepare_slide(prepared)
      prepared%i_first = minloc(prepared%touch(1:n), dim=1)
      prepared%approach_touch = prepared%touch(prepared%i_first)
      associate (i0 => prepared%i_first)
         call outward_cover(prepared%touch(i0:1:-1), prepared%cover(i0:1:-1))
         call outward_cover(prepared%touch(i0:n), prepared%cover(i0:n))
      end associate
      ! The strips reach a table end once δ exceeds the touch value there (cover = touch at the
      ! ends).
      prepared%approach_reach = huge(1.0_wp)
      if (geometry%touch_reach < huge(1.0_wp)) prepared%approach_reach = &
         (1.0_wp - cover_ramp)*geometry%touch_reach
      prepared%approach_max = min(prepared%cover(1), prepared%cover(n), prepared%approach_reach)
   end subroutine prepare_semihertz

   !> Give the prepared tables the interface angles γ_n ([[interface_angles]]) in place of the
   !> wheel's γ that [[prepare_semihertz]] puts there (`&tangential contact_surface =
   !> 'interface'`; the pipeline calls it after preparing).
   pure subroutine use_interface_angles(prepared)
      type(semihertz_geometry_type), intent(inout) :: prepared
      integer :: n
      n = prepared%n_table
      if (n < 1) return
      call interface_angles(prepared%gap(1:n), prepared%gamma(1:n), prepared%gamma0, &
         prepared%h, prepared%conformal, prepared%gamma_n(1:n))
   end subroutine use_interface_angles

   !> The strips of the semi-Hertzian method for approach δ (doc/theory.md §4.3 steps 3–8):
   !> `n_strips` strips of equal width cover every table point where
   !> δ_i = δ − (g(y) + (δ + g₀)c(y))/ε_b(y) > 0 (c the tilt term of the vertical approach)
   !> (strips over a point out of contact carry no load), on an interval that grows continuously
   !> with δ ([[outward_cover]]), so N(δ) is continuous.
   !> Below contact the patch is cleared (zero load) without error. The patch arrays must hold
   !> `n_strips` entries; they are allocated only when that size changes.
   subroutine semihertz_strips(prepared, options, e_star, approach, patch, error)
      !> Prepared geometry (with strip data).
      type(semihertz_geometry_type), intent(in) :: prepared
      !> Reduction and number of strips.
      type(normal_options_type), intent(in) :: options
      !> E* (MPa).
      real(wp), intent(in) :: e_star
      !> Approach δ (mm).
      real(wp), intent(in) :: approach
      !> The strip table (reused: arrays are reallocated only when n_strips changes).
      type(normal_patch_type), intent(inout) :: patch
      !> Set when the contact interval reaches the end of the table.
      type(error_type), allocatable, intent(out) :: error

      integer :: i, c, n
      real(wp) :: y_lo, dy, t, delta_i, a_max, reference
      logical :: touching

      n = options%n_strips
      call reserve_strips(patch, n)
      call clear_totals(patch, prepared%gamma0, prepared%r0)
      ! With gamma_plane the coupling's closure needs the table's kind (before
      ! refer_to_loaded_point, which sets it again).
      patch%conformal = prepared%conformal
      patch%approach = approach
      call contact_interval(prepared, approach, n, touching, y_lo, dy, error)
      if (.not. touching .or. allocated(error)) then
         call clear_arrays(patch, prepared%gamma0, prepared%r0)
         return
      end if

      ! Every strip array is written below: no clearing needed.
      patch%dy = dy
      a_max = 0.0_wp
      do i = 1, n
         patch%y(i) = y_lo + (i - 0.5_wp)*dy
         call strip_load(prepared, e_star, approach, patch%y(i), dy, c, t, delta_i, &
            patch%eps_a(i), patch%a(i), patch%p0(i), patch%strip_load(i))
         ! δ_i for now; k_i = √(δ_i/δ_ref) below.
         patch%k(i) = delta_i
         patch%m(i) = lerp(prepared%m, c, t)
         patch%n(i) = lerp(prepared%n, c, t)
         ! As wheel_point, written out: this loop is on every solve's path.
         patch%gamma(i) = lerp(prepared%gamma, c, t)
         patch%gamma_n(i) = lerp(prepared%gamma_n, c, t)
         patch%r_wheel(i) = lerp(prepared%r_wheel, c, t)
         patch%delta_r(i) = patch%r_wheel(i) - prepared%r0
         a_max = max(a_max, patch%a(i))
      end do
      if (prepared%exact_slide) call slid_strips(prepared, e_star, approach, patch, a_max)
      ! k_i against the deepest penetration: the approach at the reference point, unless the
      ! vertical approach's tilt takes a strip beside it deeper (then k_i ≤ 1 all the same, and
      ! with δ ≤ 0 there is no 0/0).
      reference = max(approach, maxval(patch%k(1:n)))
      patch%approach_reference = reference
      if (reference > 0.0_wp) then
         patch%k(1:n) = sqrt(patch%k(1:n)/reference)
      else
         patch%k(1:n) = 0.0_wp
      end if
      ! Decision 6: without a local ellipse, k_i is measured against the longest strip.
      if (options%reduction == reduction_constant .and. a_max > 0.0_wp) &
         patch%k(1:n) = patch%a(1:n)/a_max
      call strip_totals(patch)
   end subroutine semihertz_strips

   !> The strips of [[semihertz_strips]] again with the exact slide ([[prepare_slide]]): their
   !> loads from its ψ, and the wheel's γ, γ_n, r_w at the slid point y + d (a pass of its own:
   !> the linear path's loop stays as it was). m, n belong to the table point under the strip.
   pure subroutine slid_strips(prepared, e_star, approach, patch, a_max)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: e_star, approach
      type(normal_patch_type), intent(inout) :: patch
      !> The longest strip (mm).
      real(wp), intent(out) :: a_max
      integer :: i, c
      real(wp) :: t, slide, delta_i

      slide = slide_at(prepared, approach)
      a_max = 0.0_wp
      do i = 1, patch%n_strips
         call strip_load_slid(prepared, e_star, approach, patch%y(i), patch%dy, c, t, delta_i, &
            patch%eps_a(i), patch%a(i), patch%p0(i), patch%strip_load(i))
         patch%k(i) = delta_i
         call locate(prepared, patch%y(i) + slide, c, t)
         call wheel_point(prepared, c, t, patch, i)
         a_max = max(a_max, patch%a(i))
      end do
   end subroutine slid_strips

   !> Strip i's wheel point: γ, γ_n, r_w at cell c, fraction t, and δr_i = r_w − r₀.
   pure subroutine wheel_point(prepared, c, t, patch, i)
      type(semihertz_geometry_type), intent(in) :: prepared
      integer, intent(in) :: c, i
      real(wp), intent(in) :: t
      type(normal_patch_type), intent(inout) :: patch
      patch%gamma(i) = lerp(prepared%gamma, c, t)
      patch%gamma_n(i) = lerp(prepared%gamma_n, c, t)
      patch%r_wheel(i) = lerp(prepared%r_wheel, c, t)
      patch%delta_r(i) = patch%r_wheel(i) - prepared%r0
   end subroutine wheel_point

   !> The normal force Σ N_i of the strips of [[semihertz_strips]] alone, bit for bit the same,
   !> for the load iteration (the other strip quantities are needed only at its end). Zero below
   !> contact.
   pure subroutine semihertz_load(prepared, options, e_star, approach, load, error)
      !> Prepared geometry (with strip data).
      type(semihertz_geometry_type), intent(in) :: prepared
      !> Number of strips.
      type(normal_options_type), intent(in) :: options
      !> E* (MPa).
      real(wp), intent(in) :: e_star
      !> Approach δ (mm).
      real(wp), intent(in) :: approach
      !> Σ N_i (N).
      real(wp), intent(out) :: load
      !> Set when the contact interval reaches the end of the table.
      type(error_type), allocatable, intent(out) :: error

      integer :: i, c, n
      real(wp) :: y_lo, dy, t, delta_i, eps_a, a, p0, strip_n
      logical :: touching

      load = 0.0_wp
      n = options%n_strips
      call contact_interval(prepared, approach, n, touching, y_lo, dy, error)
      if (.not. touching .or. allocated(error)) return
      if (prepared%exact_slide) then
         call slid_load(prepared, e_star, approach, n, y_lo, dy, load)
         return
      end if
      ! Summed in strip order, as strip_totals does.
      do i = 1, n
         call strip_load(prepared, e_star, approach, y_lo + (i - 0.5_wp)*dy, dy, c, t, delta_i, &
            eps_a, a, p0, strip_n)
         load = load + strip_n
      end do
   end subroutine semihertz_load

   !> [[semihertz_load]] with the exact slide ([[strip_load_slid]]; a procedure of its own, so
   !> that the linear path's loop stays as it was).
   pure subroutine slid_load(prepared, e_star, approach, n, y_lo, dy, load)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: e_star, approach, y_lo, dy
      integer, intent(in) :: n
      real(wp), intent(out) :: load
      integer :: i, c
      real(wp) :: t, delta_i, eps_a, a, p0, strip_n
      load = 0.0_wp
      do i = 1, n
         call strip_load_slid(prepared, e_star, approach, y_lo + (i - 0.5_wp)*dy, dy, c, t, &
            delta_i, eps_a, a, p0, strip_n)
         load = load + strip_n
      end do
   end subroutine slid_load

   !> The interval of the strips for approach δ, cut into n strips: its start y_lo and the strip
   !> width dy; `touching` is false below contact. ψ = ε_b δ − g − (δ + g₀)c is linear on
   !> each cell: where touch increases outwards the interval ends at its exact crossings of the
   !> table model ([[end_fraction]]).
   pure subroutine contact_interval(prepared, approach, n, touching, y_lo, dy, error)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      integer, intent(in) :: n
      logical, intent(out) :: touching
      real(wp), intent(out) :: y_lo, dy
      type(error_type), allocatable, intent(out) :: error
      integer :: j_lo, j_hi
      real(wp) :: y_hi

      y_lo = 0.0_wp
      dy = 0.0_wp
      touching = approach > prepared%approach_touch
      if (.not. touching) return
      ! The table points covered: outwards from the first-contact point while cover < δ.
      j_lo = reached_end(prepared%cover, prepared%i_first, 1, approach)
      j_hi = reached_end(prepared%cover, prepared%i_first, prepared%n_table, approach)
      ! An interval that ends on the first or last point found it in contact (δ > touch there),
      ! or an approach beyond what the table holds.
      if (j_lo == 1 .or. j_hi == prepared%n_table .or. approach > prepared%approach_reach) then
         call table_end_error(prepared, approach, error)
         return
      end if
      y_lo = table_y(prepared, j_lo) - prepared%h*end_fraction(prepared, approach, j_lo, j_lo - 1)
      y_hi = table_y(prepared, j_hi) + prepared%h*end_fraction(prepared, approach, j_hi, j_hi + 1)
      dy = (y_hi - y_lo)/n
   end subroutine contact_interval

   !> Where the strips end in the cell from the covered point j_in (cover < δ) to j_out
   !> (cover ≥ δ), as a fraction of the cell from j_in: the zero of the linear ψ when both points
   !> have cover = touch, else the larger of that and the crossing of the linear cover (which
   !> keeps the end continuous in δ where cover < touch, and still covers the contact).
   pure real(wp) function end_fraction(prepared, approach, j_in, j_out) result(t)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      integer, intent(in) :: j_in, j_out
      real(wp) :: c_in, c_out

      if (prepared%exact_slide) then
         t = crossing(psi_slid(prepared, approach, j_in), psi_slid(prepared, approach, j_out))
      else
         t = crossing(psi_at(prepared, approach, j_in), psi_at(prepared, approach, j_out))
      end if
      c_in = prepared%cover(j_in)
      c_out = prepared%cover(j_out)
      if (c_in == prepared%touch(j_in) .and. c_out == prepared%touch(j_out)) return
      t = max(t, min(1.0_wp, (approach - c_in)/(c_out - c_in)))
   end function end_fraction

   !> Steps 4–6 on the strip centred at y (doc/theory.md §4.3): δ_i = max(0, ψ/ε_b),
   !> a_i = √(ε_a δ_i/A_i), p₀,ᵢ = the local Hertz peak at δ_i, N_i = (π/2) p₀,ᵢ a_i δy; also the
   !> table cell c and fraction t of y.
   pure subroutine strip_load(prepared, e_star, approach, y, dy, c, t, delta_i, eps_a, a, p0, &
      load)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: e_star, approach, y, dy
      integer, intent(out) :: c
      real(wp), intent(out) :: t, delta_i, eps_a, a, p0, load

      real(wp) :: psi, eps_b

      call locate(prepared, y, c, t)
      psi = (1.0_wp - t)*psi_at(prepared, approach, c) + t*psi_at(prepared, approach, c + 1)
      eps_b = lerp(prepared%eps_b, c, t)
      delta_i = max(0.0_wp, psi/eps_b)
      eps_a = lerp(prepared%eps_a, c, t)
      a = sqrt(eps_a*delta_i/lerp(prepared%curv_a, c, t))
      p0 = e_star*lerp(prepared%p_factor, c, t)*sqrt(delta_i)
      load = 0.5_wp*pi*p0*a*dy
   end subroutine strip_load

   !> [[strip_load]] with the exact slide's ψ ([[psi_slid]]): a procedure of its own, so that
   !> the linear path's loop stays as it was (inlined, no test per strip).
   pure subroutine strip_load_slid(prepared, e_star, approach, y, dy, c, t, delta_i, eps_a, a, &
      p0, load)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: e_star, approach, y, dy
      integer, intent(out) :: c
      real(wp), intent(out) :: t, delta_i, eps_a, a, p0, load

      call locate(prepared, y, c, t)
      call strip_of_psi(prepared, e_star, dy, c, t, (1.0_wp - t)*psi_slid(prepared, approach, &
         c) + t*psi_slid(prepared, approach, c + 1), delta_i, eps_a, a, p0, load)
   end subroutine strip_load_slid

   !> Steps 4–6 from the strip's ψ at cell c, fraction t.
   pure subroutine strip_of_psi(prepared, e_star, dy, c, t, psi, delta_i, eps_a, a, p0, load)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: e_star, dy
      integer, intent(in) :: c
      real(wp), intent(in) :: t, psi
      real(wp), intent(out) :: delta_i, eps_a, a, p0, load

      delta_i = max(0.0_wp, psi/lerp(prepared%eps_b, c, t))
      eps_a = lerp(prepared%eps_a, c, t)
      a = sqrt(eps_a*delta_i/lerp(prepared%curv_a, c, t))
      p0 = e_star*lerp(prepared%p_factor, c, t)*sqrt(delta_i)
      load = 0.5_wp*pi*p0*a*dy
   end subroutine strip_of_psi

   !> Refer a solved strip table to the geometric contact point of the loaded state (module
   !> text): the minimum over the table of the undeformed distance g(y) + (δ + g₀)c(y),
   !> refined by a parabola through its neighbours, as CONTACT defines the point where creepages
   !> are given (doc/geometry.md, "Vertical approach"), blended continuously with another
   !> minimum of nearly the same depth (shcontact_normal_reference). The strips' y is then measured from
   !> there, and γ₀, r₀ and δr_i are those of that point; `y_shift` keeps where it lies from the
   !> table's origin (the first contact) and `gamma_plane` the contact plane's angle. A patch out
   !> of contact, a Hertz ellipse and a table without strip data keep the table's origin.
   pure subroutine refer_to_loaded_point(prepared, patch)
      !> Prepared geometry.
      type(semihertz_geometry_type), intent(in) :: prepared
      !> The solved strip table.
      type(normal_patch_type), intent(inout) :: patch
      !> Most table points of the exact slide's window (a fixed buffer on the stack: the
      !> strips' window is a few hundred points; a longer one keeps the linear tilt).
      integer, parameter :: most = 4096
      integer :: n, c, j_lo, j_hi, j, lo, hi
      real(wp) :: t, slide, loaded_tilt(most)

      patch%gamma_plane = prepared%gamma0
      patch%conformal = prepared%conformal
      patch%y_shift = 0.0_wp
      if (patch%is_hertz .or. .not. prepared%has_strip_data .or. .not. (patch%load > 0.0_wp)) &
         return
      n = prepared%n_table
      ! The minimum lies where the strips are: the loaded gap is 0 at the first contact, and
      ! wherever it is ≤ 0 the strip penetration δ_i ≥ δ > 0. So only the table points under
      ! the strips are searched (and one more on each side, for the parabola).
      call locate(prepared, patch%y(1) - 0.5_wp*patch%dy, j_lo, t)
      call locate(prepared, patch%y(patch%n_strips) + 0.5_wp*patch%dy, j_hi, t)
      j_lo = max(1, j_lo - 1)
      j_hi = min(n, j_hi + 2)
      ! The deepest minimum, blended with others of nearly its depth (shcontact_normal_reference).
      slide = slide_at(prepared, patch%approach)
      lo = max(1, j_lo - 1)
      hi = min(n, j_hi + 1)
      if (slide == 0.0_wp .or. hi - lo + 1 > most) then
         patch%y_shift = prepared%y_first + (reference_index(prepared%gap(1:n), &
            prepared%tilt(1:n), patch%approach + prepared%gap0, j_lo, j_hi, &
            blend_depth*patch%approach_reference) - 1.0_wp)*prepared%h
      else
         ! The exact slide's loaded gap g + (δ + g₀)c̄ ([[prepare_slide]]) under the strips
         ! (and one point beyond each end), on that window of the table.
         do j = lo, hi
            loaded_tilt(j - lo + 1) = slide_tilt(prepared, j, patch%approach)
         end do
         patch%y_shift = prepared%y_first + (reference_index(prepared%gap(lo:hi), &
            loaded_tilt(1:hi - lo + 1), patch%approach + prepared%gap0, j_lo - lo + 1, &
            j_hi - lo + 1, blend_depth*patch%approach_reference) + real(lo - 2, wp))* &
            prepared%h
      end if
      ! The wheel's angle there (slid by d with the exact slide).
      call locate(prepared, patch%y_shift + slide, c, t)
      patch%gamma0 = lerp(prepared%gamma, c, t)
      ! The rolling radii of the rigid slip are the slid wheel points' with either slide: the
      ! linear slide keeps the gap and the angles of the unslid wheel, but the wheel's material
      ! above the strips after the vertical approach is the slid one all the same.
      slide = wheel_slide(prepared, patch%approach)
      call locate(prepared, patch%y_shift + slide, c, t)
      patch%r0 = lerp(prepared%r_wheel, c, t)
      if (.not. prepared%exact_slide) then
         ! (slid_strips has taken the exact slide's strips there already.)
         do j = 1, patch%n_strips
            call locate(prepared, patch%y(j) + slide, c, t)
            patch%r_wheel(j) = lerp(prepared%r_wheel, c, t)
         end do
      end if
      patch%y(1:patch%n_strips) = patch%y(1:patch%n_strips) - patch%y_shift
      patch%delta_r(1:patch%n_strips) = patch%r_wheel(1:patch%n_strips) - patch%r0
   end subroutine refer_to_loaded_point

   !> The strip table of one Hertz ellipse centred at the reference point (`method = 'hertz'`):
   !> y_i over [−b, b], k_i = √(1 − y_i²/b²), a_i = k_i a, p₀,ᵢ = k_i p₀ and the global m, n;
   !> γ_i and r_w,i from the geometry tables (clamped at the ends). `patch%load` is the ellipse's
   !> load N; Σ N_i equals it up to the midpoint rule's O((δy/b)²).
   subroutine ellipse_strips(prepared, sol, n_strips, patch)
      !> Prepared geometry (any method).
      type(semihertz_geometry_type), intent(in) :: prepared
      !> The Hertz solution.
      type(hertz_type), intent(in) :: sol
      !> Number of strips.
      integer, intent(in) :: n_strips
      !> The strip table.
      type(normal_patch_type), intent(inout) :: patch
      integer :: i, c
      real(wp) :: dy, eta, t, scale

      call reserve_strips(patch, n_strips)
      call clear_strips(patch, prepared%gamma0, prepared%r0)
      patch%is_hertz = .true.
      patch%ellipse_a = sol%a
      patch%ellipse_b = sol%b
      patch%ellipse_y_centre = 0.0_wp
      patch%approach = sol%approach
      patch%approach_reference = sol%approach
      dy = 2.0_wp*sol%b/n_strips
      patch%dy = dy
      do i = 1, n_strips
         ! Relative position in (−1, 1): no division by b and 1 − η² > 0.
         eta = (2.0_wp*i - 1.0_wp)/n_strips - 1.0_wp
         patch%y(i) = eta*sol%b
         patch%k(i) = sqrt((1.0_wp - eta)*(1.0_wp + eta))
         patch%a(i) = patch%k(i)*sol%a
         patch%p0(i) = patch%k(i)*sol%p0
         patch%strip_load(i) = 0.5_wp*pi*patch%p0(i)*patch%a(i)*dy
         patch%m(i) = sol%shape%m
         patch%n(i) = sol%shape%n
         patch%eps_a(i) = sol%shape%eps_a
         call locate(prepared, patch%y(i), c, t)
         patch%gamma(i) = lerp(prepared%gamma, c, t)
         patch%gamma_n(i) = lerp(prepared%gamma_n, c, t)
         patch%r_wheel(i) = lerp(prepared%r_wheel, c, t)
         patch%delta_r(i) = patch%r_wheel(i) - prepared%r0
      end do
      ! The strips' loads (the midpoint rule of the ellipse's load per unit width 1 − η², above
      ! its integral by 1/(2n²) relative: 5e-5 with 100 strips) scaled to carry the load: the
      ! tangential solvers bound the traction by μ times the strips' pressure, so the strips'
      ! surplus let |F_t| pass μ F_n (by 1.00005 at full slip).
      scale = sol%load/sum(patch%strip_load(1:n_strips))
      patch%p0(1:n_strips) = scale*patch%p0(1:n_strips)
      patch%strip_load(1:n_strips) = scale*patch%strip_load(1:n_strips)
      call strip_totals(patch)
      patch%load = sol%load
      patch%area = pi*sol%a*sol%b
   end subroutine ellipse_strips

   !> Make the prepared tables hold n points: the arrays only grow (their size is a capacity;
   !> n_table is the table's size), so a reused geometry allocates nothing once it has held a
   !> table as long. They grow by half at least, so that a scan over positions with ever
   !> longer tables reallocates rarely.
   pure subroutine reserve_table(prepared, n)
      type(semihertz_geometry_type), intent(inout) :: prepared
      integer, intent(in) :: n
      integer :: c
      prepared%n_table = n
      c = n
      if (allocated(prepared%gap)) then
         if (size(prepared%gap) >= n) return
         c = max(n, size(prepared%gap) + size(prepared%gap)/2)
         deallocate (prepared%gap, prepared%curv_a, prepared%gamma, prepared%gamma_n, &
            prepared%r_wheel, prepared%eps_a, prepared%eps_b, prepared%tilt, prepared%psi_slope, prepared%touch, &
            prepared%cover, prepared%m, prepared%n, prepared%p_factor, prepared%tilt_integral)
      end if
      allocate (prepared%gap(c), prepared%curv_a(c), prepared%gamma(c), prepared%gamma_n(c), &
         prepared%r_wheel(c), &
         prepared%eps_a(c), prepared%eps_b(c), prepared%tilt(c), prepared%psi_slope(c), &
         prepared%touch(c), prepared%cover(c), prepared%m(c), prepared%n(c), prepared%p_factor(c), &
         prepared%tilt_integral(c))
   end subroutine reserve_table

   !> "load too large for the patch geometry", with where the table ends.
   pure subroutine table_end_error(prepared, approach, error)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      type(error_type), allocatable, intent(out) :: error
      call fatal_error(error, 'load too large for the patch geometry: approach '// &
         str_real(approach)//' mm: the contact reaches the end of the geometry table ['// &
         str_real(table_y(prepared, 1))//', '//str_real(table_y(prepared, prepared%n_table))// &
         '] mm (largest approach '//str_real(prepared%approach_max)//' mm)', stat_no_contact)
   end subroutine table_end_error

   !> ψ_j = (ε_b,j − c_j)(δ − touch_j) = ε_b,j δ − g_j − (δ + g₀)c_j = ε_b,j δ_j: its sign is
   !> exactly that of δ − touch_j.
   !> The linear slide's ψ_j; with the exact slide ([[prepare_slide]]) see [[psi_slid]].
   pure real(wp) function psi_at(prepared, approach, j)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      integer, intent(in) :: j
      psi_at = prepared%psi_slope(j)*(approach - prepared%touch(j))
   end function psi_at

   !> ψ_j with the exact slide ([[prepare_slide]]): ε_b,j δ − g_j − (δ + g₀)c̄_j, the secant
   !> tilt c̄ in place of c (the clamp of ψ's slope kept), zero at touch_j.
   pure real(wp) function psi_slid(prepared, approach, j)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      integer, intent(in) :: j
      psi_slid = prepared%psi_slope(j)*approach - (prepared%gap(j) + prepared%gap0* &
         prepared%tilt(j)) - (approach + prepared%gap0)*(slide_tilt(prepared, j, approach) - &
         prepared%tilt(j))
   end function psi_slid

   !> The exact slide of the vertical approach (`&normal slide = 'exact'`, doc/geometry.md
   !> "Vertical approach"): a vertical translation of the wheel that closes the gap by
   !> δ + g₀ at the reference point also carries its surface along the contact plane by
   !> d = −(δ + g₀) tan γ₀ (2.7 (δ + g₀) on a 70° flange face), so the wheel point above table
   !> point y is then the one that was at y + d, and the undeformed distance of the loaded
   !> state is exactly g(y) + (δ + g₀)c̄(y), with the secant tilt
   !> c̄(y) = (1/d) ∫_y^{y+d} c(u) du of the tilt term c = tan γ₀ tan(γ − γ₀) (c is tan γ₀ times
   !> the wheel's slope in the table's frame, so (δ + g₀)c̄ is the wheel's offset difference
   !> between y + d and y). Its linear term is c(y), the tilt's: on a straight face (c
   !> constant) the two agree, but the slide carries a curvature change of the wheel (the
   !> flange root's fillet) by d towards or away from the contact, which the linear term
   !> cannot. Here: the tilt's running integral and each point's touch approach, the root of
   !> ψ_j(δ) = 0 (a fixed point from the linear term's touch, at most 40 steps).
   pure subroutine prepare_slide(prepared)
      type(semihertz_geometry_type), intent(inout) :: prepared
      integer, parameter :: most = 40
      real(wp) :: delta, next, c_bar
      integer :: n, j, it

      n = prepared%n_table
      prepared%slide_rate = slide_sign*tan(prepared%gamma0)
      call running_integral(prepared%tilt(1:n), prepared%h, prepared%tilt_integral(1:n))
      if (prepared%slide_rate == 0.0_wp) return
      do j = 1, n
         delta = prepared%touch(j)
         do it = 1, most
            c_bar = slide_tilt(prepared, j, delta)
            next = (prepared%gap(j) + prepared%gap0*c_bar)/max(prepared%psi_slope(j) - &
               (c_bar - prepared%tilt(j)), min_slope*prepared%eps_b(j))
            if (abs(next - delta) <= 1.0e-14_wp*(abs(next) + prepared%h)) exit
            delta = next
         end do
         prepared%touch(j) = next
      end do
   end subroutine prepare_slide

   !> The secant tilt c̄_j at approach δ ([[prepare_slide]]; shcontact_normal_slide's
   !> secant_tilt, in a module of its own so that this one's hot loops stay inlined).
   pure real(wp) function slide_tilt(prepared, j, approach) result(c_bar)
      type(semihertz_geometry_type), intent(in) :: prepared
      integer, intent(in) :: j
      real(wp), intent(in) :: approach
      c_bar = secant_tilt(prepared%tilt(1:prepared%n_table), &
         prepared%tilt_integral(1:prepared%n_table), prepared%h, j, &
         prepared%slide_rate*(approach + prepared%gap0))
   end function slide_tilt

   !> The undeformed distance of the loaded state at every table point, g + (δ + g₀)c with
   !> the linear slide, g + (δ + g₀)c̄ with the exact one ([[prepare_slide]]) (mm); the table's
   !> y is `prepared%y_first + (j − 1) prepared%h`.
   pure subroutine loaded_gap(prepared, approach, gap)
      !> Prepared geometry (with strip data).
      type(semihertz_geometry_type), intent(in) :: prepared
      !> Approach δ (mm).
      real(wp), intent(in) :: approach
      !> The loaded gap at the n_table points (mm).
      real(wp), intent(out) :: gap(:)
      integer :: j
      do j = 1, prepared%n_table
         if (prepared%exact_slide) then
            gap(j) = prepared%gap(j) + (approach + prepared%gap0)*slide_tilt(prepared, j, &
               approach)
         else
            gap(j) = prepared%gap(j) + (approach + prepared%gap0)*prepared%tilt(j)
         end if
      end do
   end subroutine loaded_gap

   !> The slide d of the wheel along the contact plane at approach δ (mm; 0 without the exact
   !> slide, [[prepare_slide]]).
   pure real(wp) function slide_at(prepared, approach) result(d)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      d = 0.0_wp
      if (prepared%exact_slide) d = wheel_slide(prepared, approach)
   end function slide_at

   !> How far the wheel has moved along the contact plane at approach δ, whichever slide the
   !> gap takes: d = −(δ + g₀) tan γ₀ (mm; [[prepare_slide]]). The wheel point above table
   !> point y is the one that was at y + d.
   pure real(wp) function wheel_slide(prepared, approach) result(d)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      d = slide_sign*tan(prepared%gamma0)*(approach + prepared%gap0)
   end function wheel_slide

   !> Fraction of a cell from the inside point (ψ_in > 0) to the zero of the linear ψ, in [0, 1].
   pure real(wp) function crossing(psi_in, psi_out)
      real(wp), intent(in) :: psi_in, psi_out
      if (psi_in - psi_out <= 0.0_wp) then
         crossing = 0.0_wp
      else
         crossing = min(1.0_wp, max(0.0_wp, psi_in/(psi_in - psi_out)))
      end if
   end function crossing

   !> Abscissa of table point j (mm).
   pure real(wp) function table_y(prepared, j)
      type(semihertz_geometry_type), intent(in) :: prepared
      integer, intent(in) :: j
      table_y = prepared%y_first + (j - 1)*prepared%h
   end function table_y

   !> Cell c (1 ≤ c < n) and fraction t ∈ [0, 1] of y in the table, clamped at the ends.
   pure subroutine locate(prepared, y, c, t)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: y
      integer, intent(out) :: c
      real(wp), intent(out) :: t
      real(wp) :: s
      s = (y - prepared%y_first)/prepared%h
      s = min(real(prepared%n_table - 1, wp), max(0.0_wp, s))
      c = min(prepared%n_table - 1, 1 + int(s))
      t = s - (c - 1)
   end subroutine locate

   !> Linear interpolation in cell c at fraction t.
   pure real(wp) function lerp(table, c, t)
      real(wp), intent(in) :: table(:)
      integer, intent(in) :: c
      real(wp), intent(in) :: t
      lerp = (1.0_wp - t)*table(c) + t*table(c + 1)
   end function lerp

end module shcontact_normal_semihertz
