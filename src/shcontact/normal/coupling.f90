!> Elastic coupling between the strips of a semi-Hertzian patch (`reduction = 'coupled'`,
!> issue 13; doc/validation.md §6.4).
!>
!> The local-Hertz strips (doc/theory.md §4.3) are elastically independent: each strip takes the
!> deflection of its own local Hertz ellipse. Where the gap is nearly flat (B at its clamp) that
!> ellipse is a construct much wider than the patch, and the lateral load distribution goes wrong:
!> on the ty0 tread too little load in the conformal middle, at the ty5p8 flange root a tail of
!> 1 mm past the exact contact edge. Here the strips are coupled through the half-space, in the
!> spirit of Kik–Piotrowski's method, whose single displacement condition is imposed on the centre
!> line x = 0 of every strip (a 1-D boundary-element method across the strips):
!>
!> * each strip keeps a semi-elliptic pressure P_i √(1 − x²/a_i²);
!> * the half-space displacement of all strips at (0, y_j) equals the rigid interpenetration there,
!>   Σ_i K_ji P_i = δ' − g_j on every loaded strip, with K_ji = (1/(π E*)) ∫∫ √(1 − x²/a_i²)/r
!>   over strip i, and P_i ≥ 0 (strips with a negative solution leave the contact);
!> * the total stays the local-Hertz solution's load, Σ (π/2) P_i a_i δy = N, which fixes δ' (so
!>   every loading mode keeps its force balance and its load–approach relation);
!> * the strip lengths follow the loads: a_i = c_i P_i with c_i = a_H,i/p₀H,i, the ratio of the
!>   strip's local Hertz ellipse, which depends on its curvatures A_i, B_i alone (a_H and p₀H both
!>   grow as √δ). Every local-Hertz strip satisfies this, and so does every slice y = const of a
!>   Hertz ellipse, a(y)/p(0, y) = a/p₀: a strip that the coupling unloads also shortens, one it
!>   loads lengthens, as it would in Hertz's solution. With fixed lengths a strip could lose
!>   most of its load and keep its full length (its pressure then too flat in x), and load pushed
!>   to the end of a long plateau (Y_WS = 1 mm) piled up on the last strips instead of spreading.
!>   The lengths make the problem nonlinear; [[consistent_lengths]] solves it by a secant
!>   iteration on ln a_i, with the kernel linear in ln a_i about the local-Hertz lengths, run to
!>   its fixed point with the linear system solved at every step. (A plain update a ← c P
!>   alternates between two lengths on a narrow patch, where the displacement fixes the load per
!>   unit width P a rather than P: that was why an earlier attempt "lengthened without bound".)
!>
!> On a Hertzian patch the Hertz pressure satisfies these conditions, so the coupling leaves it
!> unchanged up to the discretisation. The gap of strip i comes from the strip table itself,
!> g_i = ε_b,i δ (1 − k_i²) (§4.3 step 3), and k_i = a_i/a_H,i follows the lengths.
!>
!> The conditions are imposed on at most [[max_groups]] groups of neighbouring strips (the load
!> moves over distances of the patch width, which the groups resolve) and the strips take their
!> group's coupled/local load ratio, interpolated between group centres and applied to their local
!> loads averaged over a group's width (doc/validation.md §6.9: the local loads step where the
!> gap's curvature steps), and their lengths the square root of the change. The groups are a partition of the patch's strip interval fixed in
!> position, narrower at the ends, a strip across a boundary shared by the two groups
!> (shcontact_normal_coupling_groups), and their centre, length, interpenetration and
!> contact angle are means weighted by the strip loads: the strips move continuously with the approach, and a
!> strip entering or leaving the contact changes its group continuously, so the coupled loads
!> are a continuous function of the wheel's position (a partition of the loaded strips by
!> count shifted every group when one strip came or went, which the kinematic call's vertical
!> balance saw as jumps of the carried load). A change Δ of the approach reaches group J as
!> Δ cos γ_J w_J, w_J = 1 − c of the vertical approach (shcontact_normal_semihertz). The
!> kernel is the line integral along each group in closed form (complete elliptic integrals),
!> integrated across its width by quadrature (shcontact_normal_strip_influence), so one coupling costs about as much as the local-Hertz solve itself (doc/performance.md); it
!> is the default reduction since issue 13 (doc/validation.md §6.4–6.5).
module shcontact_normal_coupling
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type
   use shcontact_math_lapack, only: solve_dense_leading, solve_factored_leading
   use shcontact_math_anderson, only: anderson_step
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_strip_influence, only: influence_column
   use shcontact_normal_coupling_groups, only: group_set_type, max_groups, max_patches, &
      max_total, add_patch_groups, copy_patch_groups, patch_weights, scale_patch
   implicit none
   private

   public :: couple_strips, couple_patches, max_groups, max_patches, coupling_start_type

   !> Most length updates of [[consistent_lengths]], and the change of ln a below which the
   !> lengths have converged. The iteration is run to its fixed point (each step divides the error
   !> of ln a by about 3, so the error left after a step of 1e-7 is about 5e-8 in ln a, and the
   !> loads, far inside the kinematic call's balance tolerance of 1e-5 F_z; a tighter tolerance
   !> costs a step per factor 3 and moves no force by more than that), so the result is a
   !> smooth function of the strips up to that round-off: a
   !> fixed number of steps (four, before issue 25) left an iterate of an iteration that need not
   !> have converged, and at flange states (a wide conformal patch) the chord steps on the first
   !> factorisation diverged, so the loads jumped from one approach to the next.
   integer, parameter :: max_length_iterations = 60
   real(wp), parameter :: length_tolerance = 1.0e-7_wp
   !> The sensitivity d ln P/d ln a assumed by the length steps: −1/2, halfway between a narrow
   !> patch (−1) and a wide one (0), so that every step divides the error of ln a by at least 3
   !> ([[consistent_lengths]]).
   real(wp), parameter :: length_sensitivity = -0.5_wp
   !> Steps remembered by the Anderson acceleration of the length steps
   !> ([[consistent_lengths]]).
   integer, parameter :: anderson_memory = 3
   !> Most groups that one factorisation holds out of contact by the capacitance method
   !> ([[hold_negative_groups]]); beyond them the system is factorised again without them.
   integer, parameter :: max_held = 8
   !> Peak, relative to the largest group peak of the first solve, below which a group's
   !> length step is damped (weight peak/(entry_weight peak_max)): the step in ln a of a group
   !> with a tiny peak tends to −∞. The fixed point is the same ([[consistent_lengths]]).
   real(wp), parameter :: entry_weight = 1.0e-3_wp
   !> Length iterations of one [[couple_patches]] that a [[coupling_start_type]] records (the
   !> single solves of a joint problem and the joint one: max_patches + 1).
   integer, parameter :: max_start_slots = max_patches + 1

   !> The factorised linear system of the groups in contact ([[solve_groups]]): the peaks and
   !> the shift Δ solve it.
   type :: group_system_type
      !> Number of groups in contact and their indices in the set.
      integer :: mg
      integer :: idx(max_total)
      !> LU factors of the (mg + 1)-order system and their pivots.
      real(wp) :: lu(max_total + 1, max_total + 1)
      integer :: pivots(max_total + 1)
      !> The solution: peaks P of the groups in contact (MPa), then Δ (mm).
      real(wp) :: x(max_total + 1)
      !> Groups of the factorised system held out of contact without a new factorisation
      !> ([[hold_negative_groups]]): their number, their positions in idx, the columns A⁻¹e_h of
      !> the factorised matrix A, and the LU factors of the capacitance matrix C = (A⁻¹)_HH.
      !> (No default values in this type: a default would make every local system be
      !> initialised as a whole, some 100 kB, on every solve.)
      integer :: n_held
      integer :: held(max_held)
      real(wp) :: inverse_columns(max_total + 1, max_held)
      real(wp) :: capacitance(max_held, max_held)
      integer :: capacitance_pivots(max_held)
   end type group_system_type

   !> Coupled solves that repeat: the converged strip lengths of each length iteration of
   !> the last [[couple_patches]], as the start of the same iteration in the next one. Within
   !> one kinematic call the vertical balance solves the same wheel at loads that differ by
   !> little, and the lengths of one solve are within a fraction of a percent of the next
   !> one's: the iteration then starts next to its fixed point (the same fixed point to
   !> length_tolerance, fewer steps; doc/performance.md, "Speed-up 5"). The caller empties it
   !> ([[reset_start]]) where a new problem begins, so that no result depends on an earlier one.
   type :: coupling_start_type
      !> Iterations recorded, and the one [[couple_patches]] reaches next.
      integer :: n_slots = 0, next = 0
      !> Where larger than length_tolerance, the step of ln a below which the iterations stop
      !> (the vertical balance's predictor solve, whose loads only choose the next load:
      !> shcontact_pipeline_balance); 0, the default: length_tolerance.
      real(wp) :: tolerance = 0.0_wp
      !> Per iteration: its groups and patches, ln(a/a_fill) and the groups in contact.
      integer :: n(max_start_slots) = 0, n_patches(max_start_slots) = 0
      real(wp) :: stretch_log(max_total, max_start_slots)
      logical :: in_contact(max_total, max_start_slots)
   contains
      !> Forget every recorded iteration.
      procedure :: reset => reset_start
   end type coupling_start_type

contains

   !> Redistribute the load of a local-Hertz strip table through the half-space coupling (module
   !> text). The table keeps its strips, its total load and γ_i, δr_i, m_i, n_i, ε_a,i; a_i, k_i,
   !> p₀,ᵢ, N_i, area and p_max change. The approach stays the local-Hertz one: the coupling
   !> redistributes a given load, and the load–approach relation of every loading mode (and so
   !> its continuity and its force balances) is that of the local-Hertz strips.
   !>
   !> The coupled problem is solved on at most [[max_groups]] groups of neighbouring loaded
   !> strips (each group one strip of its summed width, mean length, mean gap): the coupling
   !> redistributes load over distances of the patch width, which the groups resolve, and the
   !> cost stays a few microseconds. Each strip's load and half-length are then scaled by its
   !> group's coupled/local ratios, interpolated linearly between group centres; strips whose
   !> load ratio vanishes leave the contact. With one strip per group this is the strip-wise coupled problem itself.
   pure subroutine couple_strips(patch, e_star, error)
      !> The strip table: local Hertz on entry, coupled on return.
      type(normal_patch_type), intent(inout) :: patch
      !> E* = G/(1 − ν) (MPa).
      real(wp), intent(in) :: e_star
      !> Set when the dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      type(group_set_type) :: set

      call set%reset()
      call add_patch_groups(set, patch, 0.0_wp, 0.0_wp)
      call couple_single(set, patch, e_star, error)
   end subroutine couple_strips

   !> The coupled solve of a set that holds the groups of one patch alone (at offset 0 and
   !> contact angle 0, as [[couple_strips]] places them), scaled back onto the patch's strips.
   pure subroutine couple_single(set, patch, e_star, error, start)
      !> The groups of the patch.
      type(group_set_type), intent(inout) :: set
      !> The patch's strip table: local Hertz on entry, coupled on return.
      type(normal_patch_type), intent(inout) :: patch
      !> E* = G/(1 − ν) (MPa).
      real(wp), intent(in) :: e_star
      !> Set when the dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the length iterations ([[coupling_start_type]]).
      type(coupling_start_type), intent(inout), optional :: start

      if (set%n < 1) return
      call consistent_lengths(set, e_star, error, start=start)
      if (allocated(error)) return
      call scale_patch(set, 1, patch)
   end subroutine couple_single

   !> The patches of one wheel coupled together (module text): the strips of every loaded patch
   !> in one half-space problem, so that neighbouring patches press each other's surfaces down
   !> and share the load as one contact would. The patches are placed along the profile by
   !> `offset` (mm, the position of each reference point along the rail profile); a strip's
   !> influence on another patch's strip is taken along that patch's normal, cos(γ_k − γ_l)
   !> times the in-plane kernel. The patches move as one rigid body: their coupled approaches
   !> differ from the local-Hertz ones by Δ cos γ_k with one vertical shift Δ, and the vertical
   !> normal load Σ_k N_k cos γ_k is kept (so every loading mode keeps its balance) while each
   !> patch's own load may change. A single loaded patch is [[couple_strips]]; loaded patches
   !> beyond [[max_patches]] (the least loaded) are coupled alone, and so is every patch when
   !> `offset` is absent (patches not placed press no other).
   pure subroutine couple_patches(patches, e_star, error, offset, start)
      !> The strip tables of the wheel's patches (unloaded ones are skipped).
      type(normal_patch_type), intent(inout) :: patches(:)
      !> E* = G/(1 − ν) (MPa).
      real(wp), intent(in) :: e_star
      !> Set when a dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      !> Position of each patch's reference point along the rail profile (mm).
      real(wp), intent(in), optional :: offset(:)
      !> Starts of the length iterations from the last coupling of the same wheel
      !> ([[coupling_start_type]]); updated with this one's.
      type(coupling_start_type), intent(inout), optional :: start
      type(group_set_type) :: set, single
      real(wp) :: weight(max_patches, max_patches), place
      integer :: order(max_patches), component(max_patches), chosen(max_patches), n_joint, k, &
         i, j, c, old, members

      call set%reset()
      if (present(start)) start%next = 0
      ! The most loaded patches, at most max_patches of them, in one problem.
      n_joint = 0
      do k = 1, size(patches)
         if (.not. (patches(k)%load > 0.0_wp) .or. patches(k)%is_hertz) cycle
         if (n_joint < max_patches) then
            n_joint = n_joint + 1
            order(n_joint) = k
         else
            i = 1
            do j = 2, n_joint
               if (patches(order(j))%load < patches(order(i))%load) i = j
            end do
            if (patches(k)%load > patches(order(i))%load) then
               call couple_strips(patches(order(i)), e_star, error)
               order(i) = k
            else
               call couple_strips(patches(k), e_star, error)
            end if
            if (allocated(error)) return
         end if
      end do
      if (n_joint < 1) return
      ! Which patches press each other (patch_weights > 0): the connected groups of patches
      ! are solved each on its own, a patch that presses no other alone. The groups of every
      ! patch are built here once; the problems below take copies of them.
      do i = 1, n_joint
         k = order(i)
         place = 0.0_wp
         if (present(offset)) place = offset(k)
         call add_patch_groups(set, patches(k), place, patches(k)%gamma0)
      end do
      if (present(offset)) then
         call patch_weights(set, weight)
      else
         weight = 0.0_wp
      end if
      do i = 1, n_joint
         component(i) = i
      end do
      do i = 1, n_joint
         do j = 1, n_joint
            if (weight(i, j) > 0.0_wp .and. component(i) /= component(j)) then
               c = min(component(i), component(j))
               old = max(component(i), component(j))
               do k = 1, n_joint
                  if (component(k) == old) component(k) = c
               end do
            end if
         end do
      end do
      do c = 1, n_joint
         members = count(component(1:n_joint) == c)
         if (members == 0) cycle
         if (members == 1) then
            i = findloc(component(1:n_joint), c, dim=1)
            call single%reset()
            call copy_patch_groups(single, set, i, 0.0_wp, 0.0_wp)
            call couple_single(single, patches(order(i)), e_star, error, start)
            if (allocated(error)) return
            cycle
         end if
         members = 0
         do i = 1, n_joint
            if (component(i) /= c) cycle
            members = members + 1
            chosen(members) = i
         end do
         call couple_component(set, chosen(1:members), order, patches, e_star, error, start)
         if (allocated(error)) return
      end do
   end subroutine couple_patches

   !> Patches that press each other, coupled in one problem ([[couple_patches]]): each patch
   !> alone first, for the shift c_k = δ'_k − δ_k of its own coupled solution; the joint
   !> problem starts from those, so that the patches' own load–approach relations stay the
   !> strips'.
   pure subroutine couple_component(all, members, order, patches, e_star, error, start)
      !> The groups of every jointly coupled patch, placed along the profile.
      type(group_set_type), intent(in) :: all
      !> The patches of `all` coupled together (at most max_patches).
      integer, intent(in) :: members(:)
      !> Index in `patches` of each patch of `all`.
      integer, intent(in) :: order(:)
      !> The strip tables of the wheel's patches.
      type(normal_patch_type), intent(inout) :: patches(:)
      !> E* = G/(1 − ν) (MPa).
      real(wp), intent(in) :: e_star
      !> Set when a dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the length iterations ([[coupling_start_type]]).
      type(coupling_start_type), intent(inout), optional :: start
      type(group_set_type) :: set, single
      real(wp) :: shift(max_patches)
      integer :: i, p, g1

      call set%reset()
      do i = 1, size(members)
         p = members(i)
         call single%reset()
         call copy_patch_groups(single, all, p, 0.0_wp, all%gamma(p))
         shift(i) = 0.0_wp
         if (single%n < 1) cycle
         call consistent_lengths(single, e_star, error, shift(i), start)
         if (allocated(error)) return
         shift(i) = shift(i)*single%cos_gamma(1)
      end do
      do i = 1, size(members)
         p = members(i)
         g1 = set%n + 1
         call copy_patch_groups(set, all, p, all%offset(p), all%gamma(p))
         set%gc(g1:set%n) = set%gc(g1:set%n) + shift(i)*set%wc(g1:set%n)
      end do
      if (set%n < 1) return
      call consistent_lengths(set, e_star, error, start=start)
      if (allocated(error)) return
      do i = 1, size(members)
         call scale_patch(set, i, patches(order(members(i))))
      end do
   end subroutine couple_component

   !> The coupled solution of a set with strip lengths that follow their loads (module text):
   !> a local-Hertz strip has a_i = c_i p₀,ᵢ, with c_i = a_H,i/p₀H,i fixed by its curvatures
   !> alone (both grow as √δ), and so does a slice y = const of a Hertz ellipse, a(y)/p(0, y) =
   !> a/p₀. The coupling moves load between the strips; their lengths follow it.
   !>
   !> The fixed point a = c P(a) is found in ln a, group by group, by steps
   !> (ln(c P) − ln a)/(1 − s) with the assumed sensitivity s = d ln P/d ln a =
   !> [[length_sensitivity]], halfway between −1 (a narrow patch, where the displacement fixes the
   !> load per unit width P a, and a ← c P would alternate between two lengths) and 0 (a wide
   !> one, where it fixes P). The kernel is taken linear in ln a about the local-Hertz lengths
   !> ([[fill_kernel]]'s slope), and the peaks at new lengths are solved exactly (the set in
   !> contact checked again), until the steps fall below [[length_tolerance]]: the fixed point,
   !> not an iterate. The steps are accelerated by Anderson's method (shcontact_math_anderson,
   !> memory [[anderson_memory]], restarted when a step does not shrink): the plain step leaves
   !> 1/3 of the error in the modes whose sensitivity is −1 or 0, the accelerated one
   !> removes them together (9.5 instead of 14.3 solves per coupling on the hunting trajectory,
   !> doc/performance.md "Speed-up 3"); the fixed point is the same. The strips' lengths follow
   !> their loads in [[scale_patch]].
   pure subroutine consistent_lengths(set, e_star, error, shift, start)
      type(group_set_type), intent(inout) :: set
      real(wp), intent(in) :: e_star
      type(error_type), allocatable, intent(out) :: error
      !> The vertical shift Δ of the solution (mm).
      real(wp), intent(out), optional :: shift
      !> Where this iteration ended the last time ([[coupling_start_type]]): its start when it
      !> has the same groups, and updated with this one's fixed point.
      type(coupling_start_type), intent(inout), optional :: start
      real(wp) :: kern(max_total, max_total), slope(max_total, max_total), &
         weight(max_patches, max_patches)
      real(wp), dimension(max_total) :: ac_fill, log_a_fill, stretch_log, step, last_x, last_f, &
         next_log
      real(wp) :: history_x(max_total, anderson_memory), history_f(max_total, anderson_memory)
      type(group_system_type) :: system
      real(wp) :: peak, log_a, log_peak, take, peak_ref, largest, last_largest
      real(wp) :: converged_step
      integer :: it, g, n, used, slot

      n = set%n
      converged_step = length_tolerance
      if (present(start)) converged_step = max(converged_step, start%tolerance)
      call patch_weights(set, weight)
      call fill_kernel(set, e_star, weight, kern, slope)
      ac_fill(1:n) = set%ac(1:n)
      log_a_fill(1:n) = log(ac_fill(1:n))
      stretch_log(1:n) = 0.0_wp
      slot = 0
      if (present(start)) then
         start%next = start%next + 1
         slot = start%next
         if (slot > max_start_slots) slot = 0
      end if
      if (slot > 0) then
         if (slot <= start%n_slots .and. start%n(slot) == n .and. &
             start%n_patches(slot) == set%n_patches) then
            stretch_log(1:n) = start%stretch_log(1:n, slot)
            set%in_contact(1:n) = start%in_contact(1:n, slot)
            do g = 1, n
               set%ac(g) = ac_fill(g)*exp(stretch_log(g))
            end do
         end if
      end if
      call solve_groups(set, kern, slope, stretch_log, system, error)
      if (allocated(error)) return
      ! A group's step is weighted by min(1, peak/p_ref): the step in ln a grows like ln(peak)
      ! as a group's peak tends to 0, so a full step for any positive peak and none at 0 made
      ! the coupled loads jump where a group enters the contact (the kinematic call's vertical
      ! balance then had no root). The weight goes to 0 with the peak (peak ln peak → 0) and is
      ! exactly 1 for every group above p_ref, so those keep the plain iteration.
      peak_ref = 0.0_wp
      do g = 1, n
         peak_ref = max(peak_ref, set%ratio(g)*set%local(g)/(0.5_wp*pi*set%ac(g)*set%width(g)))
      end do
      peak_ref = max(entry_weight*peak_ref, tiny(1.0_wp))
      used = 0
      last_largest = huge(1.0_wp)
      do it = 1, max_length_iterations
         ! Loops without branches over the groups (their log and exp vectorise): a group
         ! without a positive peak takes no step (take = 0).
         do g = 1, n
            peak = set%ratio(g)*set%local(g)/(0.5_wp*pi*set%ac(g)*set%width(g))
            take = min(1.0_wp, max(peak, 0.0_wp)/peak_ref)
            log_a = log_a_fill(g) + stretch_log(g)
            log_peak = log(set%length_per_peak(g)*max(peak, tiny(1.0_wp)))
            step(g) = take*(log_peak - log_a)/(1.0_wp - length_sensitivity)
         end do
         largest = maxval(abs(step(1:n)))
         if (largest <= converged_step) exit
         ! The plain steps accelerated (Anderson), restarted where they stop shrinking.
         if (.not. (largest < last_largest)) used = 0
         last_largest = largest
         call anderson_step(stretch_log(1:n), step(1:n), last_x(1:n), last_f(1:n), &
            history_x(1:n, :), history_f(1:n, :), used, next_log(1:n))
         stretch_log(1:n) = next_log(1:n)
         do g = 1, n
            set%ac(g) = ac_fill(g)*exp(stretch_log(g))
         end do
         ! The peaks at the new lengths, solved exactly with the set in contact checked again
         ! (chord steps on the first factorisation diverged where the lengths change much).
         call solve_groups(set, kern, slope, stretch_log, system, error)
         if (allocated(error)) return
      end do
      if (present(shift)) shift = system%x(system%mg + 1)
      if (slot > 0) then
         start%n_slots = max(start%n_slots, slot)
         start%n(slot) = n
         start%n_patches(slot) = set%n_patches
         start%stretch_log(1:n, slot) = stretch_log(1:n)
         start%in_contact(1:n, slot) = set%in_contact(1:n)
      end if
   end subroutine consistent_lengths

   !> Forget the starts recorded in a [[coupling_start_type]].
   pure subroutine reset_start(self)
      class(coupling_start_type), intent(inout) :: self
      self%n_slots = 0
      self%next = 0
      self%tolerance = 0.0_wp
   end subroutine reset_start

   !> The coupled group loads of a set: Σ_I K_JI P_I − Δ cos γ_J w_J = δ_J − g_J on every group in
   !> contact, Σ_J cos γ_J (π/2) P_J a_J w_J = Σ_k cos γ_k N_k, P ≥ 0 (an active set, started
   !> from the last solve's: groups with a negative peak leave, groups out of contact whose
   !> surface would interpenetrate come back); set%ratio = coupled over local-Hertz load of each
   !> group. The kernel is K₀ + S ln(a/a_fill); `system` keeps the factors and the compact K₀, S
   !> of the groups in contact.
   pure subroutine solve_groups(set, kern, slope, stretch_log, system, error)
      type(group_set_type), intent(inout) :: set
      !> The kernel at the lengths of the fill ([[fill_kernel]]), its slope in ln a, and
      !> ln(a/a_fill) of every group.
      real(wp), intent(in) :: kern(:, :), slope(:, :), stretch_log(:)
      type(group_system_type), intent(inout) :: system
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: vertical, cos_contact
      logical :: readmitted, held_all
      integer :: n, i, j, mg, pass

      n = set%n
      system%n_held = 0
      vertical = sum(set%patch_load(1:set%n_patches)*set%cos_gamma(1:set%n_patches))
      do pass = 1, 2*n + 1
         mg = 0
         do j = 1, n
            if (.not. set%in_contact(j)) cycle
            mg = mg + 1
            system%idx(mg) = j
         end do
         system%mg = mg
         if (mg < 1) exit
         associate (idx => system%idx, kmat => system%lu, rhs => system%x)
            do i = 1, mg
               do j = 1, mg
                  kmat(j, i) = kern(idx(j), idx(i)) + slope(idx(j), idx(i))*stretch_log(idx(i))
               end do
               cos_contact = set%cos_gamma(set%patch(idx(i)))
               kmat(mg + 1, i) = 0.5_wp*pi*set%ac(idx(i))*set%width(idx(i))*cos_contact
               ! How a vertical shift Δ of the wheel reaches the group: cos γ (1 − c).
               kmat(i, mg + 1) = -cos_contact*set%wc(idx(i))
               rhs(i) = set%gc(idx(i))
            end do
            kmat(mg + 1, mg + 1) = 0.0_wp
            rhs(mg + 1) = vertical
            call solve_dense_leading(mg + 1, kmat, rhs, system%pivots, error)
            if (allocated(error)) return
            call hold_negative_groups(system, held_all, error)
            if (allocated(error)) return
            if (.not. held_all) then
               do i = 1, mg
                  if (rhs(i) < 0.0_wp) set%in_contact(idx(i)) = .false.
               end do
               cycle
            end if
         end associate
         call readmit(set, kern, slope, stretch_log, system, readmitted)
         if (.not. readmitted) exit
      end do
      ! The next solve starts without the held groups; this one keeps them in its factors.
      do i = 1, system%n_held
         set%in_contact(system%idx(system%held(i))) = .false.
      end do
      call set_ratios(set, system)
   end subroutine solve_groups

   !> Groups with a negative peak held out of contact on the factors of the system with them
   !> (the capacitance method: with H the held groups and A the factorised matrix, the solution
   !> of the system without them is x = z − A⁻¹E_H C⁻¹ z_H, z = A⁻¹b, C = (A⁻¹)_HH, their
   !> equations relaxed and x_H = 0), repeated while the solution has negative peaks: a
   !> factorisation for every change of the contact set cost most of a coupled solve. `held_all`
   !> is false when more than [[max_held]] groups, or every group, would be held (the caller
   !> then factorises the smaller system). On entry system%x is z.
   pure subroutine hold_negative_groups(system, held_all, error)
      type(group_system_type), intent(inout) :: system
      logical, intent(out) :: held_all
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: z(max_total + 1), w(max_held)
      integer :: i, k, l, mg, nh

      mg = system%mg
      system%n_held = 0
      held_all = .true.
      z(1:mg + 1) = system%x(1:mg + 1)
      do
         nh = system%n_held
         do i = 1, mg
            ! Held groups have x = 0 exactly.
            if (.not. (system%x(i) < 0.0_wp)) cycle
            if (nh == max_held .or. nh + 1 >= mg) then
               held_all = .false.
               system%n_held = 0
               system%x(1:mg + 1) = z(1:mg + 1)
               return
            end if
            nh = nh + 1
            system%held(nh) = i
            system%inverse_columns(1:mg + 1, nh) = 0.0_wp
            system%inverse_columns(i, nh) = 1.0_wp
            call solve_factored_leading(mg + 1, system%lu, system%pivots, &
               system%inverse_columns(:, nh))
         end do
         if (nh == system%n_held) return
         system%n_held = nh
         do l = 1, nh
            do k = 1, nh
               system%capacitance(k, l) = system%inverse_columns(system%held(k), l)
            end do
            w(l) = z(system%held(l))
         end do
         call solve_dense_leading(nh, system%capacitance, w, system%capacitance_pivots, error)
         if (allocated(error)) return
         system%x(1:mg + 1) = z(1:mg + 1)
         call subtract_held(mg, system%held(1:nh), system%inverse_columns, w(1:nh), system%x)
      end do
   end subroutine hold_negative_groups

   !> v ← v − A⁻¹E_H w over the first mg + 1 entries, with the held entries set to 0 exactly.
   pure subroutine subtract_held(mg, held, inverse_columns, w, v)
      integer, intent(in) :: mg
      !> Positions of the held groups in the system.
      integer, intent(in) :: held(:)
      !> A⁻¹e_h of every held group, and the weights w.
      real(wp), intent(in) :: inverse_columns(:, :), w(:)
      real(wp), intent(inout) :: v(:)
      integer :: k
      do k = 1, size(held)
         v(1:mg + 1) = v(1:mg + 1) - inverse_columns(1:mg + 1, k)*w(k)
      end do
      do k = 1, size(held)
         v(held(k)) = 0.0_wp
      end do
   end subroutine subtract_held

   !> Whether a group out of contact, or held out of it ([[hold_negative_groups]]), would
   !> interpenetrate under the system's solution. If one would, the groups out of contact that
   !> would are marked in contact again, and the held groups that would not are marked out of
   !> it (the caller factorises again).
   pure subroutine readmit(set, kern, slope, stretch_log, system, readmits)
      type(group_set_type), intent(inout) :: set
      real(wp), intent(in) :: kern(:, :), slope(:, :), stretch_log(:)
      type(group_system_type), intent(in) :: system
      !> True when a group came back.
      logical, intent(out) :: readmits
      logical :: candidate(max_total), comes_back(max_total)
      real(wp) :: displacement
      integer :: i, j, k

      candidate(1:set%n) = .not. set%in_contact(1:set%n)
      do k = 1, system%n_held
         candidate(system%idx(system%held(k))) = .true.
      end do
      comes_back(1:set%n) = .false.
      do j = 1, set%n
         if (.not. candidate(j)) cycle
         displacement = -set%cos_gamma(set%patch(j))*set%wc(j)*system%x(system%mg + 1)
         do i = 1, system%mg
            k = system%idx(i)
            displacement = displacement + (kern(j, k) + slope(j, k)*stretch_log(k))*system%x(i)
         end do
         comes_back(j) = displacement < set%gc(j) - 1.0e-9_wp*max(abs(set%gc(j)), 1.0e-6_wp)
      end do
      readmits = any(comes_back(1:set%n))
      if (.not. readmits) return
      do j = 1, set%n
         if (candidate(j)) set%in_contact(j) = comes_back(j)
      end do
   end subroutine readmit

   !> set%ratio from the peaks of the system: coupled over local-Hertz load of every group (0
   !> out of contact).
   pure subroutine set_ratios(set, system)
      type(group_set_type), intent(inout) :: set
      type(group_system_type), intent(in) :: system
      integer :: i, j
      set%ratio(1:set%n) = 0.0_wp
      do i = 1, system%mg
         j = system%idx(i)
         set%ratio(j) = max(0.0_wp, 0.5_wp*pi*system%x(i)*set%ac(j)*set%width(j))/set%local(j)
      end do
   end subroutine set_ratios

   !> The influence matrix of a set, kern(j, i) = K_ji (module text): the displacement at group
   !> j per unit peak of group i. Between two patches p ∋ j and q ∋ i it is taken along p's
   !> normal, cos(γ_p − γ_q) times the in-plane kernel, times their weight ([[patch_weights]]).
   !> The groups of a patch are consecutive in the set: the matrix is filled block by block.
   pure subroutine fill_kernel(set, e_star, weight, kern, slope)
      type(group_set_type), intent(in) :: set
      !> E* = G/(1 − ν) (MPa).
      real(wp), intent(in) :: e_star
      !> How much the set's patches press each other.
      real(wp), intent(in) :: weight(max_patches, max_patches)
      real(wp), intent(out) :: kern(max_total, max_total)
      !> ∂K_ji/∂ln a_i, the kernel's change with the half-length of the loaded group.
      real(wp), intent(out) :: slope(max_total, max_total)
      real(wp) :: c
      integer :: p, q, i, fp, lp, self_index

      do q = 1, set%n_patches
         do p = 1, set%n_patches
            c = 1.0_wp/(pi*e_star)
            if (p /= q) c = c*cos(set%gamma(p) - set%gamma(q))*weight(p, q)
            fp = set%first_group(p)
            lp = set%last_group(p)
            if (lp < fp) cycle
            do i = set%first_group(q), set%last_group(q)
               self_index = 0
               if (p == q) self_index = i - fp + 1
               call influence_column(set%ac(i), set%width(i), set%s(i), set%s(fp:lp), &
                  self_index, kern(fp:lp, i), slope(fp:lp, i))
               kern(fp:lp, i) = c*kern(fp:lp, i)
               slope(fp:lp, i) = c*slope(fp:lp, i)
            end do
         end do
      end do
   end subroutine fill_kernel

end module shcontact_normal_coupling
