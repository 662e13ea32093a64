!> The semi-Hertzian strip method (physics.md §4.3) on one patch, for a given approach.
!>
!> The geometry tables are first reduced once, by [[prepare_semihertz]], to what every load
!> iteration needs: the penetration split ε_a(y), ε_b(y) (which depends only on A(y)/B(y),
!> decision 5), the Hertz coefficients m(y), n(y) and the pressure factor √((A+B)/(E K)). The
!> strips for one approach are then laid out by [[semihertz_strips]] without any elliptic
!> integral or allocation. [[ellipse_strips]] gives the strip table of one Hertz ellipse
!> (`method = 'hertz'`) on the same geometry.
module shcontact_normal_semihertz
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_no_contact
   use shcontact_geometry_patch, only: patch_geometry_type, geometry_sample_type
   use shcontact_normal_options, only: normal_options_type, method_semi_hertz, reduction_constant
   use shcontact_normal_hertz, only: hertz_shape_type, hertz_type, hertz_shape
   use shcontact_normal_patch, only: normal_patch_type
   implicit none
   private

   public :: semihertz_geometry_type, prepare_semihertz, semihertz_strips, ellipse_strips
   public :: reserve_strips, clear_strips

   !> A patch geometry prepared for the strip method: the tables of the input on the same uniform
   !> grid, plus the per-point quantities that depend only on A/B. Reused across loads.
   type :: semihertz_geometry_type
      !> Number of table points.
      integer :: n_table = 0
      !> Table point where contact starts (smallest g/ε_b; the reference point y = 0 for a
      !> well-formed table).
      integer :: i_first = 0
      !> First table abscissa and spacing (mm).
      real(wp) :: y_first = 0.0_wp, h = 0.0_wp
      !> Contact angle γ₀ (rad), rolling radius r₀ (mm) and gap g₀ (mm) of the reference point.
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp, gap0 = 0.0_wp
      !> Curvatures A, B at the reference point y = 0 (1/mm), for `method = 'hertz'`.
      real(wp) :: curv_a0 = 0.0_wp, curv_b0 = 0.0_wp
      !> Approach at which contact starts, min g/ε_b (mm); 0 for a well-formed table.
      real(wp) :: approach_touch = 0.0_wp
      !> Largest approach whose contact interval stays inside the table (mm).
      real(wp) :: approach_max = 0.0_wp
      !> True when the per-point strip quantities below were computed (semi-Hertz method).
      logical :: has_strip_data = .false.
      !> g(y) (mm), A(y) (1/mm), γ(y) (rad), r_w(y) (mm).
      real(wp), allocatable :: gap(:), curv_a(:), gamma(:), r_wheel(:)
      !> Penetration split used by the strips: local Hertz ε_a, ε_b, or the constant ε.
      real(wp), allocatable :: eps_a(:), eps_b(:)
      !> Approach at which each table point comes into contact, g/ε_b (mm).
      real(wp), allocatable :: touch(:)
      !> Local Hertz coefficients m(y), n(y).
      real(wp), allocatable :: m(:), n(:)
      !> Pressure factor √((A+B)/(E(k)K(k))) (1/√mm²): p₀ = E*·factor·√δ (physics.md §4.3
      !> step 5 with §1.3 items 3–4).
      real(wp), allocatable :: p_factor(:)
   end type semihertz_geometry_type

contains

   !> Check a patch geometry and reduce it to a [[semihertz_geometry_type]]: once per geometry.
   !> Arrays are reallocated only when the table size changes.
   subroutine prepare_semihertz(geometry, options, prepared, error)
      !> The patch geometry (uniform y grid containing y = 0).
      type(patch_geometry_type), intent(in) :: geometry
      !> Method and reduction.
      type(normal_options_type), intent(in) :: options
      !> The prepared geometry.
      type(semihertz_geometry_type), intent(inout) :: prepared
      !> Set for an inconsistent or non-Hertzian table.
      type(error_type), allocatable, intent(out) :: error

      type(hertz_shape_type) :: shape
      type(geometry_sample_type) :: ref
      real(wp) :: last_ratio, ratio
      integer :: i, n

      call check_geometry(geometry, error)
      if (allocated(error)) return
      n = size(geometry%y)
      call reserve_table(prepared, n)
      prepared%y_first = geometry%y(1)
      prepared%h = geometry%h
      prepared%gamma0 = geometry%gamma0
      prepared%r0 = geometry%r0
      prepared%gap0 = geometry%gap0
      ref = geometry%sample(0.0_wp)
      prepared%curv_a0 = ref%curv_a
      prepared%curv_b0 = ref%curv_b
      prepared%gap(:) = geometry%gap
      prepared%curv_a(:) = geometry%curv_a
      prepared%gamma(:) = geometry%gamma
      prepared%r_wheel(:) = geometry%r_wheel

      prepared%has_strip_data = options%method == method_semi_hertz
      if (.not. prepared%has_strip_data) then
         prepared%i_first = 0
         prepared%approach_touch = 0.0_wp
         prepared%approach_max = huge(1.0_wp)
         return
      end if

      ! The shape depends only on A/B: solve it per distinct ratio (runs of equal ratios, to the
      ! last bit, are common on circular arcs).
      last_ratio = -1.0_wp
      do i = 1, n
         ratio = geometry%curv_a(i)/geometry%curv_b(i)
         if (abs(ratio - last_ratio) > spacing(ratio)) then
            call hertz_shape(ratio, shape, error)
            if (allocated(error)) return
            last_ratio = ratio
         end if
         prepared%m(i) = shape%m
         prepared%n(i) = shape%n
         prepared%p_factor(i) = sqrt((geometry%curv_a(i) + geometry%curv_b(i))/(shape%ee*shape%kk))
         if (options%reduction == reduction_constant) then
            ! Kik–Piotrowski: the virtual penetration ε·δ in both directions (physics.md §4.2).
            prepared%eps_a(i) = options%epsilon
            prepared%eps_b(i) = options%epsilon
         else
            prepared%eps_a(i) = shape%eps_a
            prepared%eps_b(i) = shape%eps_b
         end if
         prepared%touch(i) = geometry%gap(i)/prepared%eps_b(i)
      end do
      prepared%i_first = minloc(prepared%touch, dim=1)
      prepared%approach_touch = prepared%touch(prepared%i_first)
      ! The interval reaches a table end once δ exceeds every touch value between it and i_first.
      prepared%approach_max = min(maxval(prepared%touch(1:prepared%i_first)), &
         maxval(prepared%touch(prepared%i_first:n)))
   end subroutine prepare_semihertz

   !> Reject tables the strip method cannot use, naming the item and the value.
   subroutine check_geometry(geometry, error)
      type(patch_geometry_type), intent(in) :: geometry
      type(error_type), allocatable, intent(out) :: error
      character(len=64) :: buf
      integer :: n, i

      if (.not. (allocated(geometry%y) .and. allocated(geometry%gap) .and. &
                 allocated(geometry%curv_a) .and. allocated(geometry%curv_b) .and. &
                 allocated(geometry%gamma) .and. allocated(geometry%r_wheel))) then
         call fatal_error(error, 'patch geometry: tables y, gap, curv_a, curv_b, gamma, r_wheel '// &
            'must all be allocated', stat_invalid_input)
         return
      end if
      n = size(geometry%y)
      if (n < 2 .or. any([size(geometry%gap), size(geometry%curv_a), size(geometry%curv_b), &
                          size(geometry%gamma), size(geometry%r_wheel)] /= n)) then
         write (buf, '(i0)') n
         call fatal_error(error, 'patch geometry: tables must have one common size of at least '// &
            '2 points (y has '//trim(buf)//')', stat_invalid_input)
         return
      end if
      if (.not. (geometry%h > 0.0_wp)) then
         write (buf, '(es12.4)') geometry%h
         call fatal_error(error, 'patch geometry: table spacing h = '//trim(adjustl(buf))// &
            ' mm: expected h > 0', stat_invalid_input)
         return
      end if
      do i = 2, n
         if (abs(geometry%y(i) - geometry%y(1) - (i - 1)*geometry%h) > 1.0e-6_wp*geometry%h) then
            write (buf, '(i0,a,es12.4)') i, ') = ', geometry%y(i)
            call fatal_error(error, 'patch geometry: y('//trim(buf)// &
               ' mm is off the uniform grid of spacing h', stat_invalid_input)
            return
         end if
      end do
      if (geometry%y(1) > 0.0_wp .or. geometry%y(n) < 0.0_wp) then
         call fatal_error(error, 'patch geometry: the table must contain the reference point y = 0', &
            stat_invalid_input)
         return
      end if
      do i = 1, n
         if (.not. (geometry%curv_a(i) > 0.0_wp .and. geometry%curv_b(i) > 0.0_wp)) then
            write (buf, '(3(es12.4,a))') geometry%y(i), ' mm: A = ', geometry%curv_a(i), &
               ', B = ', geometry%curv_b(i), ''
            call fatal_error(error, 'patch geometry at y = '//trim(adjustl(buf))// &
               ' 1/mm: expected A > 0 and B > 0 (B clamped to B_min)', stat_invalid_input)
            return
         end if
      end do
   end subroutine check_geometry

   !> The strips of the semi-Hertzian method for approach δ (physics.md §4.3 steps 3–8): the
   !> contact interval is the part of the table around the first-contact point where
   !> δ_i = δ − g(y)/ε_b(y) > 0; `n_strips` strips of equal width cover it, so N(δ) is continuous.
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

      integer :: i, j_lo, j_hi, c, n
      real(wp) :: y_lo, y_hi, dy, t, psi, eps_b, delta_i, a_max

      n = options%n_strips
      call reserve_strips(patch, n)
      call clear_strips(patch, prepared%gamma0, prepared%r0)
      patch%approach = approach
      if (approach <= prepared%approach_touch) return

      ! Walk out from the first-contact point while the table points are in contact.
      j_lo = prepared%i_first
      do while (j_lo > 1)
         if (approach <= prepared%touch(j_lo - 1)) exit
         j_lo = j_lo - 1
      end do
      j_hi = prepared%i_first
      do while (j_hi < prepared%n_table)
         if (approach <= prepared%touch(j_hi + 1)) exit
         j_hi = j_hi + 1
      end do
      ! A walk that ends on the first or last point found it in contact (δ > touch there).
      if (j_lo == 1 .or. j_hi == prepared%n_table) then
         call table_end_error(prepared, approach, error)
         return
      end if
      ! ψ = ε_b(δ − g/ε_b) = δ ε_b − g is linear on each cell: exact crossings of the table model.
      y_lo = table_y(prepared, j_lo)
      if (j_lo > 1) y_lo = y_lo - prepared%h*crossing(psi_at(prepared, approach, j_lo), &
                                                  psi_at(prepared, approach, j_lo - 1))
      y_hi = table_y(prepared, j_hi)
      if (j_hi < prepared%n_table) y_hi = y_hi + prepared%h*crossing( &
         psi_at(prepared, approach, j_hi), psi_at(prepared, approach, j_hi + 1))

      dy = (y_hi - y_lo)/n
      patch%dy = dy
      a_max = 0.0_wp
      do i = 1, n
         patch%y(i) = y_lo + (i - 0.5_wp)*dy
         call locate(prepared, patch%y(i), c, t)
         psi = (1.0_wp - t)*psi_at(prepared, approach, c) + t*psi_at(prepared, approach, c + 1)
         eps_b = lerp(prepared%eps_b, c, t)
         delta_i = max(0.0_wp, psi/eps_b)
         patch%eps_a(i) = lerp(prepared%eps_a, c, t)
         ! Steps 4–6: a_i = √(ε_a δ_i/A_i), p₀,ᵢ = local Hertz peak at δ_i, N_i = (π/2)p₀,ᵢ a_i δy.
         patch%a(i) = sqrt(patch%eps_a(i)*delta_i/lerp(prepared%curv_a, c, t))
         patch%k(i) = sqrt(delta_i/approach)
         patch%p0(i) = e_star*lerp(prepared%p_factor, c, t)*sqrt(delta_i)
         patch%strip_load(i) = 0.5_wp*pi*patch%p0(i)*patch%a(i)*dy
         patch%m(i) = lerp(prepared%m, c, t)
         patch%n(i) = lerp(prepared%n, c, t)
         patch%gamma(i) = lerp(prepared%gamma, c, t)
         patch%r_wheel(i) = lerp(prepared%r_wheel, c, t)
         patch%delta_r(i) = patch%r_wheel(i) - prepared%r0
         a_max = max(a_max, patch%a(i))
      end do
      ! Decision 6: without a local ellipse, k_i is measured against the longest strip.
      if (options%reduction == reduction_constant .and. a_max > 0.0_wp) &
         patch%k(1:n) = patch%a(1:n)/a_max
      call strip_totals(patch)
   end subroutine semihertz_strips

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
      real(wp) :: dy, eta, t

      call reserve_strips(patch, n_strips)
      call clear_strips(patch, prepared%gamma0, prepared%r0)
      patch%is_hertz = .true.
      patch%ellipse_a = sol%a
      patch%ellipse_b = sol%b
      patch%ellipse_y_centre = 0.0_wp
      patch%approach = sol%approach
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
         patch%r_wheel(i) = lerp(prepared%r_wheel, c, t)
         patch%delta_r(i) = patch%r_wheel(i) - prepared%r0
      end do
      call strip_totals(patch)
      patch%load = sol%load
      patch%area = pi*sol%a*sol%b
   end subroutine ellipse_strips

   !> Make the patch arrays hold n_strips entries, allocating only when the size changes.
   pure subroutine reserve_strips(patch, n_strips)
      !> The patch.
      type(normal_patch_type), intent(inout) :: patch
      !> Number of strips.
      integer, intent(in) :: n_strips
      patch%n_strips = n_strips
      if (allocated(patch%y)) then
         if (size(patch%y) == n_strips) return
         deallocate (patch%y, patch%a, patch%k, patch%p0, patch%strip_load, patch%m, patch%n, &
            patch%eps_a, patch%gamma, patch%delta_r, patch%r_wheel)
      end if
      allocate (patch%y(n_strips), patch%a(n_strips), patch%k(n_strips), patch%p0(n_strips), &
         patch%strip_load(n_strips), patch%m(n_strips), patch%n(n_strips), &
         patch%eps_a(n_strips), patch%gamma(n_strips), patch%delta_r(n_strips), &
         patch%r_wheel(n_strips))
   end subroutine reserve_strips

   !> A patch out of contact: zero strips (a_i = 0 carries no load), zero totals, and the
   !> reference-point data. Arrays must be reserved ([[reserve_strips]]).
   pure subroutine clear_strips(patch, gamma0, r0)
      !> The patch.
      type(normal_patch_type), intent(inout) :: patch
      !> Contact angle (rad) and rolling radius (mm) of the reference point.
      real(wp), intent(in) :: gamma0, r0
      patch%is_hertz = .false.
      patch%ellipse_a = 0.0_wp
      patch%ellipse_b = 0.0_wp
      patch%ellipse_y_centre = 0.0_wp
      patch%approach = 0.0_wp
      patch%load = 0.0_wp
      patch%area = 0.0_wp
      patch%p_max = 0.0_wp
      patch%dy = 0.0_wp
      patch%gamma0 = gamma0
      patch%r0 = r0
      patch%y(:) = 0.0_wp
      patch%a(:) = 0.0_wp
      patch%k(:) = 0.0_wp
      patch%p0(:) = 0.0_wp
      patch%strip_load(:) = 0.0_wp
      patch%m(:) = 1.0_wp
      patch%n(:) = 1.0_wp
      patch%eps_a(:) = 0.5_wp
      patch%gamma(:) = gamma0
      patch%delta_r(:) = 0.0_wp
      patch%r_wheel(:) = r0
   end subroutine clear_strips

   !> Load, area Σ 2a_i δy and peak pressure from the strips.
   pure subroutine strip_totals(patch)
      type(normal_patch_type), intent(inout) :: patch
      integer :: n
      n = patch%n_strips
      patch%load = sum(patch%strip_load(1:n))
      patch%area = 2.0_wp*sum(patch%a(1:n))*patch%dy
      patch%p_max = maxval(patch%p0(1:n))
   end subroutine strip_totals

   !> Allocate the prepared tables for n points (only when the size changes).
   pure subroutine reserve_table(prepared, n)
      type(semihertz_geometry_type), intent(inout) :: prepared
      integer, intent(in) :: n
      prepared%n_table = n
      if (allocated(prepared%gap)) then
         if (size(prepared%gap) == n) return
         deallocate (prepared%gap, prepared%curv_a, prepared%gamma, prepared%r_wheel, &
            prepared%eps_a, prepared%eps_b, prepared%touch, prepared%m, prepared%n, &
            prepared%p_factor)
      end if
      allocate (prepared%gap(n), prepared%curv_a(n), prepared%gamma(n), prepared%r_wheel(n), &
         prepared%eps_a(n), prepared%eps_b(n), prepared%touch(n), prepared%m(n), prepared%n(n), &
         prepared%p_factor(n))
   end subroutine reserve_table

   !> "load too large for the patch geometry", with where the table ends.
   subroutine table_end_error(prepared, approach, error)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      type(error_type), allocatable, intent(out) :: error
      character(len=160) :: buf
      write (buf, '(a,es12.4,a,es12.4,a,es12.4,a,es12.4,a)') 'approach ', approach, &
         ' mm: the contact reaches the end of the geometry table [', table_y(prepared, 1), ', ', &
         table_y(prepared, prepared%n_table), '] mm (largest approach ', prepared%approach_max, &
         ' mm)'
      call fatal_error(error, 'load too large for the patch geometry: '//trim(buf), &
         stat_no_contact)
   end subroutine table_end_error

   !> ψ_j = ε_b,j (δ − g_j/ε_b,j): its sign is exactly that of δ − touch_j.
   pure real(wp) function psi_at(prepared, approach, j)
      type(semihertz_geometry_type), intent(in) :: prepared
      real(wp), intent(in) :: approach
      integer, intent(in) :: j
      psi_at = prepared%eps_b(j)*(approach - prepared%touch(j))
   end function psi_at

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
