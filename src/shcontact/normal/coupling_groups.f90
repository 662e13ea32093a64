!> The groups of strips of the coupled reduction (shcontact_normal_coupling, module text there):
!> a partition of each patch's strip interval fixed in position ([[group_bounds]]), each group one strip of
!> its summed width and load-weighted mean centre, length, interpenetration and contact angle
!> ([[add_patch_groups]]); where the patches of a wheel press each other ([[patch_weights]]); and
!> the strips scaled back by their groups' coupled/local load ratios ([[scale_patch]]).
module shcontact_normal_coupling_groups
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_angles, only: approach_closure
   implicit none
   private

   public :: add_patch_groups, copy_patch_groups, patch_weights, scale_patch

   !> Most groups of strips per patch in the coupled solve (shcontact_normal_coupling).
   integer, parameter, public :: max_groups = 16
   !> The strip count whose whole-strip groups every strip count shares ([[group_bounds]]): the
   !> default grid's 100 strips.
   integer, parameter :: reference_strips = 100
   !> Most patches of a wheel coupled together (shcontact_normal_coupling's couple_patches).
   integer, parameter, public :: max_patches = 4
   !> Most groups of one coupled problem.
   integer, parameter, public :: max_total = max_groups*max_patches
   !> Patches whose loaded extents lie at most this far apart along the profile (mm) press each
   !> other fully; beyond separate_distance not at all (CONTACT's D_COMB = 4 mm and D_SEP = 8 mm).
   real(wp), parameter :: combine_distance = 4.0_wp, separate_distance = 8.0_wp
   !> Share of the patch's most loaded group below which a group's interpenetration is blended
   !> in with its local load ([[add_patch_groups]]): below the share of every group of a
   !> Hertzian patch (its end groups carry some 8 % of its middle ones), so that an elliptic
   !> patch is left as it is. (1 % left jumps of 7e-5 of the load in the kinematic call and
   !> Y_WS = 1 mm's P80 |Δf_x| at 0.021; 10 % acts on the established tread groups and spoils
   !> Y_WS = 1.25–1.5 mm: doc/validation.md §6.4.)
   real(wp), parameter :: entry_share = 3.0e-2_wp
   !> Share of the patch's most loaded group below which a group's coupled/local load ratio is
   !> blended, in [[scale_patch]]'s interpolation, with its neighbour's towards that group: the
   !> ratio of a group whose load vanishes is that of a vanishing load and must not set its
   !> neighbours' strips. Far below entry_share, so that only groups that are leaving or
   !> entering the contact are touched (doc/validation.md's targets all hold); any positive
   !> share makes the loads continuous.
   real(wp), parameter :: ratio_share = 1.0e-3_wp

   !> The groups of one coupled problem (fixed size: nothing is allocated per solve). Group g
   !> belongs to patch patch(g) of the set; the groups of set patch p are first_group(p) …
   !> last_group(p), in the order of their strips.
   type, public :: group_set_type
      !> (No default values: a local set is emptied by [[reset_group_set]], and every array
      !> entry is written before it is read; a default would initialise some 7 kB per solve.)
      integer :: n, n_patches
      integer :: patch(max_total)
      !> Width (mm), centre along the patch y (mm) and along the profile s (mm), mean half-length
      !> a (mm), mean interpenetration δ − g (mm), local-Hertz load (N), coupled/local load ratio,
      !> and the mean share 1 − c of a change of approach that reaches the group (a vertical
      !> approach, shcontact_normal_semihertz's vertical_tilt).
      real(wp), dimension(max_total) :: width, yc, s, ac, gc, local, ratio, wc
      !> The group's local-Hertz length-to-peak ratio a/P (mm/MPa, shcontact_normal_coupling's
      !> consistent_lengths).
      real(wp), dimension(max_total) :: length_per_peak
      !> The groups in contact at the last solve (the next one starts from them).
      logical :: in_contact(max_total)
      !> The group's place 1 … ng in its patch's partition ([[group_bounds]]; groups without
      !> loaded strips are left out of the set, [[scale_patch]] places them back).
      integer :: slot(max_total)
      integer, dimension(max_patches) :: first_group, last_group
      !> Per set patch: local-Hertz load N_k (N), position of the reference point along the
      !> profile (mm), contact angle γ_k (rad) and cos γ_k.
      real(wp), dimension(max_patches) :: patch_load, offset, gamma, cos_gamma
   contains
      !> Empty the set (the arrays are kept).
      procedure :: reset => reset_group_set
   end type group_set_type

contains

   !> Append the groups of one patch's loaded strips to the set (module text). Group centres
   !> are offset + y (mm along the profile).
   pure subroutine add_patch_groups(set, patch, offset, gamma)
      type(group_set_type), intent(inout) :: set
      type(normal_patch_type), intent(in) :: patch
      !> Position of the patch's reference point along the profile (mm) and its contact angle.
      real(wp), intent(in) :: offset, gamma
      real(wp) :: bound(0:max_groups)
      integer :: ng, i, j, g, n, g1
      real(wp) :: load_i, share, lo, hi

      n = patch%n_strips
      call open_patch(set, sum(patch%strip_load(1:n)), offset, gamma)
      if (.not. (set%patch_load(set%n_patches) > 0.0_wp)) return
      call group_bounds(n, ng, bound)
      g = set%n
      do j = 1, ng
         g = g + 1
         set%patch(g) = set%n_patches
         set%yc(g) = 0.0_wp
         set%ac(g) = 0.0_wp
         set%gc(g) = 0.0_wp
         set%wc(g) = 0.0_wp
         set%local(g) = 0.0_wp
         ! Means weighted by the strip loads, so that a strip entering or leaving the contact
         ! (its load goes to zero with it) changes the group continuously.
         ! A strip across a boundary belongs to both groups in proportion to its overlap with
         ! each, at the centre of its part in each ([[group_bounds]]).
         do i = max(1, floor(bound(j - 1)) + 1), min(n, ceiling(bound(j)))
            if (.not. (patch%a(i) > 0.0_wp .and. patch%k(i) > 0.0_wp)) cycle
            lo = max(real(i - 1, wp), bound(j - 1))
            hi = min(real(i, wp), bound(j))
            share = hi - lo
            if (.not. (share > 0.0_wp)) cycle
            load_i = share*patch%strip_load(i)
            set%yc(g) = set%yc(g) + load_i*(patch%y(i) + (min(hi, max(lo, i - 0.5_wp)) - (i - 0.5_wp))*patch%dy)
            set%ac(g) = set%ac(g) + load_i*patch%a(i)
            ! δ_i = k_i² δ_ref = δ − g_i/ε_b,i (doc/theory.md §4.3 step 3): the
            ! interpenetration δ − g_i of the strip, its gap below the patch's approach.
            set%gc(g) = set%gc(g) + load_i*(patch%approach - (1.0_wp - patch%eps_a(i))* &
               (patch%approach - patch%k(i)**2*patch%approach_reference))
            set%wc(g) = set%wc(g) + load_i*patch%gamma(i)
            set%local(g) = set%local(g) + load_i
         end do
         if (.not. (set%local(g) > 0.0_wp)) then
            ! A group without load (its strips all out of contact) is left out.
            g = g - 1
            cycle
         end if
         set%width(g) = (bound(j) - bound(j - 1))*patch%dy
         set%yc(g) = set%yc(g)/set%local(g)
         set%ac(g) = set%ac(g)/set%local(g)
         set%gc(g) = set%gc(g)/set%local(g)
         ! 1 − c at the group's mean contact angle (γ varies little across a group).
         set%wc(g) = approach_closure(set%wc(g)/set%local(g), patch%gamma_plane, &
            patch%conformal)
         ! The strips are still measured from the first contact: the coupling comes before
         ! refer_to_loaded_point (shcontact_normal_loading).
         set%s(g) = offset + set%yc(g)
         ! The local-Hertz strips have a_i = (a_H,i/p₀H,i) p₀,ᵢ: the group's own ratio.
         set%length_per_peak(g) = 0.5_wp*pi*set%ac(g)**2*set%width(g)/set%local(g)
         set%in_contact(g) = .true.
         set%slot(g) = j
      end do
      set%n = g
      set%last_group(set%n_patches) = set%n
      ! A group enters the coupled problem when its first strip enters the local-Hertz contact,
      ! whose edge lies at the virtual interpenetration g = ε_b δ: the rigid interpenetration
      ! δ − g there is still δ (1 − ε_b) > 0, and the half-space solution gave the new group at
      ! once a finite load (up to 400 times its local one at a flange root), so the carried
      ! load jumped with the approach (issue 25). The group's interpenetration is therefore
      ! taken in proportion to its local load until that reaches entry_share of the patch's
      ! largest group: it enters the coupled contact from zero, continuously. Groups above that
      ! share (every group of a Hertzian patch) keep it.
      g1 = set%first_group(set%n_patches)
      if (set%n >= g1) then
         load_i = entry_share*maxval(set%local(g1:set%n))
         do g = g1, set%n
            set%gc(g) = set%gc(g)*min(1.0_wp, set%local(g)/load_i)
         end do
      end if
   end subroutine add_patch_groups

   !> Append the groups of patch p of another set, placed at `offset` along the profile with
   !> contact angle `gamma` (the groups themselves are the patch's, [[add_patch_groups]]).
   pure subroutine copy_patch_groups(set, source, p, offset, gamma)
      type(group_set_type), intent(inout) :: set
      !> The set that holds the patch's groups.
      type(group_set_type), intent(in) :: source
      !> The patch in `source`.
      integer, intent(in) :: p
      !> Position of the patch's reference point along the profile (mm) and its contact angle.
      real(wp), intent(in) :: offset, gamma
      integer :: g, h

      call open_patch(set, source%patch_load(p), offset, gamma)
      do g = source%first_group(p), source%last_group(p)
         h = set%n + 1
         set%patch(h) = set%n_patches
         set%width(h) = source%width(g)
         set%yc(h) = source%yc(g)
         set%ac(h) = source%ac(g)
         set%gc(h) = source%gc(g)
         set%wc(h) = source%wc(g)
         set%local(h) = source%local(g)
         set%length_per_peak(h) = source%length_per_peak(g)
         set%in_contact(h) = .true.
         set%slot(h) = source%slot(g)
         set%s(h) = offset + set%yc(h)
         set%n = h
      end do
      set%last_group(set%n_patches) = set%n
   end subroutine copy_patch_groups

   !> Start a new patch of the set, without groups yet.
   pure subroutine open_patch(set, load, offset, gamma)
      type(group_set_type), intent(inout) :: set
      !> Its local-Hertz load (N), the position of its reference point along the profile (mm)
      !> and its contact angle (rad).
      real(wp), intent(in) :: load, offset, gamma
      set%n_patches = set%n_patches + 1
      set%first_group(set%n_patches) = set%n + 1
      set%last_group(set%n_patches) = set%n
      set%patch_load(set%n_patches) = load
      set%offset(set%n_patches) = offset
      set%gamma(set%n_patches) = gamma
      set%cos_gamma(set%n_patches) = cos(gamma)
   end subroutine open_patch

   !> Scale the strips of the set's patch ip by their groups' load ratios, interpolated between
   !> group centres (constant beyond the outer ones; a group below ratio_share of the patch's
   !> largest load blended with its inner neighbour's), applied to the strips' local loads
   !> averaged over the groups' widths ([[group_width_means]]), and their half-lengths by the
   !> square root of the change; strips whose ratio vanishes leave the contact. The patch's load
   !> becomes the sum of its coupled groups' loads.
   pure subroutine scale_patch(set, ip, patch)
      type(group_set_type), intent(in) :: set
      integer, intent(in) :: ip
      type(normal_patch_type), intent(inout) :: patch
      real(wp) :: load, total, t, r, g, root, full, share, mean
      !> Per group of the patch's partition (in order along the strips; a group without loaded
      !> strips is not in the set): the interpolation node y (mm), local load (N), own and
      !> interpolated ratio.
      real(wp), dimension(max_groups) :: node_y, node_local, node_own, ratio
      real(wp) :: bound(0:max_groups)
      integer :: i, j, jg, g1, g2, n, ng, jm

      n = patch%n_strips
      g1 = set%first_group(ip)
      g2 = set%last_group(ip)
      if (g2 < g1) return
      load = sum(set%ratio(g1:g2)*set%local(g1:g2))
      ! The interpolation nodes: the groups of the set at their centres, and the groups of the
      ! partition without loaded strips (a gap between two lobes of the patch, or its unloaded
      ! ends) at the middle of their intervals, with no load. The ratios are interpolated
      ! between the nodes: a group whose local load is below ratio_share of the patch's
      ! largest enters with its own ratio in proportion to that share and otherwise takes that
      ! of its neighbour towards the largest group, as its interpenetration enters
      ! ([[add_patch_groups]]); a group without load takes its neighbour's. Its own ratio is
      ! that of a load that tends to 0 with the group's (0 when it is out of the coupled
      ! contact); taken at full weight, it pulled the interpolated ratios of its neighbours'
      ! strips towards it and let them jump when the group left the set (its strips out of
      ! contact): the coupled loads then jumped with the approach (doc/kinematics.md,
      ! "Robustness with other table steps"). Without the unloaded groups as nodes, a lobe's
      ! last strips took a ratio interpolated across the gap towards the next lobe's, and
      ! jumped when the lobe's last group emptied (flange state 599 of the benchmark with the
      ! vehicle preset: doc/performance.md, "Groups fixed in position, tried again").
      call group_bounds(n, ng, bound)
      do j = 1, ng
         node_y(j) = patch%y(1) + (0.5_wp*(bound(j - 1) + bound(j)) - 0.5_wp)*patch%dy
      end do
      node_local(1:ng) = 0.0_wp
      node_own(1:ng) = 0.0_wp
      do jg = g1, g2
         j = set%slot(jg)
         node_y(j) = set%yc(jg)
         node_local(j) = set%local(jg)
         node_own(j) = set%ratio(jg)
      end do
      full = ratio_share*maxval(node_local(1:ng))
      jm = maxloc(node_local(1:ng), 1)
      ratio(jm) = node_own(jm)
      do j = jm + 1, ng
         share = min(1.0_wp, node_local(j)/full)
         ratio(j) = share*node_own(j) + (1.0_wp - share)*ratio(j - 1)
      end do
      do j = jm - 1, 1, -1
         share = min(1.0_wp, node_local(j)/full)
         ratio(j) = share*node_own(j) + (1.0_wp - share)*ratio(j + 1)
      end do
      ! The local-Hertz loads averaged over the groups' widths ([[group_width_means]]; p0 holds
      ! them until the ratio loop below).
      call group_width_means(patch%strip_load(1:n), patch%p0(1:n))
      ! The ratio of every strip's coupled load to its local one (p0 holds it until the last
      ! loop), 0 for a strip out of contact or whose ratio vanishes. The coupled load is the
      ! interpolated group ratio r times the smaller of the strip's window mean q̄ and the
      ! geometric mean √(q̄ q) with its own local load q: a strip on the low side of a step of
      ! the local-Hertz loads is raised towards its neighbours, one at the contact's edge,
      ! whose local load vanishes, keeps a load that vanishes with it (the contact ends where
      ! the strips end, and a strip entering the contact enters with no load).
      j = 1
      do i = 1, n
         r = 0.0_wp
         if (patch%a(i) > 0.0_wp .and. patch%k(i) > 0.0_wp) then
            do while (j < ng)
               if (patch%y(i) < node_y(j + 1)) exit
               j = j + 1
            end do
            if (ng == 1 .or. patch%y(i) <= node_y(1)) then
               r = ratio(1)
            else if (j >= ng) then
               r = ratio(ng)
            else if (ratio(j) == ratio(j + 1)) then
               ! (Beyond a lobe's outer group: its ratio, as before the unloaded nodes.)
               r = ratio(j)
            else
               t = (patch%y(i) - node_y(j))/(node_y(j + 1) - node_y(j))
               r = (1.0_wp - t)*ratio(j) + t*ratio(j + 1)
            end if
         end if
         if (r > 0.0_wp) then
            mean = patch%p0(i)
            patch%p0(i) = r*min(mean, sqrt(mean*patch%strip_load(i)))/patch%strip_load(i)
         else
            patch%p0(i) = 0.0_wp
         end if
      end do
      ! The strip's length follows its load as its own a = c P does: q = (π/2) P a ∝ a², so
      ! a/a_local = √(q/q_local) (module text); k_i = a_i/a_H,i with it. A strip with ratio 0
      ! leaves the contact (load, a and k become 0). No branch: the loop vectorises.
      do i = 1, n
         root = sqrt(patch%p0(i))
         patch%strip_load(i) = patch%p0(i)*patch%strip_load(i)
         patch%a(i) = root*patch%a(i)
         patch%k(i) = root*patch%k(i)
      end do
      total = sum(patch%strip_load(1:n))
      if (.not. (total > 0.0_wp) .or. .not. (load > 0.0_wp)) then
         patch%strip_load(1:n) = 0.0_wp
         patch%a(1:n) = 0.0_wp
         patch%k(1:n) = 0.0_wp
         patch%p0(1:n) = 0.0_wp
         patch%load = 0.0_wp
         patch%area = 0.0_wp
         patch%p_max = 0.0_wp
         return
      end if
      ! The interpolation moved a little load between groups: restore the group sum (p₀ = 0
      ! where the load is 0).
      g = load/total
      do i = 1, n
         patch%strip_load(i) = g*patch%strip_load(i)
         patch%p0(i) = 2.0_wp*patch%strip_load(i)/(pi*max(patch%a(i), tiny(1.0_wp))*patch%dy)
      end do
      patch%load = load
      patch%area = 2.0_wp*sum(patch%a(1:n))*patch%dy
      patch%p_max = maxval(patch%p0(1:n))
   end subroutine scale_patch

   !> How much two patches of the set press each other (module text): 1 when the gap between
   !> their loaded extents along the profile is at most [[combine_distance]], 0 beyond
   !> [[separate_distance]], linear between (CONTACT's rule for combining and separating contact
   !> regions, D_COMB and D_SEP; beyond it the wheel and rail surfaces are no half-space).
   pure subroutine patch_weights(set, weight)
      type(group_set_type), intent(in) :: set
      real(wp), intent(out) :: weight(max_patches, max_patches)
      real(wp) :: lo(max_patches), hi(max_patches), d
      integer :: p, q, g

      lo = huge(1.0_wp)
      hi = -huge(1.0_wp)
      do g = 1, set%n
         p = set%patch(g)
         lo(p) = min(lo(p), set%s(g) - 0.5_wp*set%width(g))
         hi(p) = max(hi(p), set%s(g) + 0.5_wp*set%width(g))
      end do
      do q = 1, set%n_patches
         do p = 1, set%n_patches
            if (lo(p) > hi(p) .or. lo(q) > hi(q)) then
               ! A patch without loaded strips presses nothing.
               weight(p, q) = 0.0_wp
               cycle
            end if
            d = max(0.0_wp, lo(q) - hi(p), lo(p) - hi(q))
            weight(p, q) = min(1.0_wp, max(0.0_wp, (separate_distance - d)/ &
               (separate_distance - combine_distance)))
         end do
      end do
   end subroutine patch_weights

   !> Empty a group set.
   pure subroutine reset_group_set(set)
      class(group_set_type), intent(inout) :: set
      set%n = 0
      set%n_patches = 0
   end subroutine reset_group_set

   !> The strips' local-Hertz loads averaged over the width the coupled problem resolves: each
   !> strip's load replaced by the mean over a window centred on it of the largest odd number of
   !> strips that fits in its group's width (the group that holds the strip's centre,
   !> [[group_bounds]]; zeros beyond the strip interval). The coupled problem fixes the load of
   !> every group; within a group the shape is the local-Hertz one, which steps where the gap's
   !> lateral curvature steps (the arcs of a profile's section) or crosses its clamp B_min (the
   !> end of a conformal plateau): a local ellipse sees the curvature of its own strip, the
   !> half-space spreads the pressure over the contact (doc/validation.md §6.9). The mean is a
   !> continuous function of the loads, leaves a load linear across the window unchanged, and
   !> with groups narrower than three strips is no average at all.
   pure subroutine group_width_means(load, mean)
      !> Local-Hertz strip loads (N).
      real(wp), intent(in) :: load(:)
      !> Their means over the windows (N).
      real(wp), intent(out) :: mean(:)
      real(wp) :: bound(0:max_groups)
      integer :: n, ng, j, i, m, first, last
      real(wp) :: window

      n = size(load)
      call group_bounds(n, ng, bound)
      first = 1
      do j = 1, ng
         m = max(0, floor(0.5_wp*(bound(j) - bound(j - 1) - 1.0_wp)))
         ! The strips whose centres lie in the group (the last group takes the rest).
         last = first - 1
         do while (last < n)
            if (j < ng .and. real(last, wp) + 0.5_wp >= bound(j)) exit
            last = last + 1
         end do
         if (last < first) cycle
         ! A sliding sum over the group's strips.
         window = sum(load(max(1, first - m):min(n, first + m)))
         do i = first, last
            if (i > first) then
               if (i + m <= n) window = window + load(i + m)
               if (i - m - 1 >= 1) window = window - load(i - m - 1)
            end if
            mean(i) = window/real(2*m + 1, wp)
         end do
         first = last + 1
      end do
   end subroutine group_width_means

   !> The group boundaries of a patch's n strips, in strip widths from the outer edge of the first
   !> strip: ng = min(n, [[max_groups]]) groups fixed in position along the strips' interval
   !> (which moves continuously with the approach, and so do the groups). They are those of the
   !> default grid of [[reference_strips]] strips, whose group widths grade from 4 strips (4 %) at
   !> the ends to 8 in the middle (half uniform, half Chebyshev-spaced boundaries, t_j = j/(2ng)
   !> + (1 − cos(πj/ng))/4, rounded to whole strips of that grid, mirror-symmetric), scaled to n
   !> strips: every strip count resolves the same groups of the contact, and the default's groups
   !> are whole strips. A strip across a boundary is shared by the two groups
   !> ([[add_patch_groups]]). Boundaries rounded to whole strips of each grid instead moved with n
   !> by up to half a strip, so that the coupled solution did not converge smoothly with the strip
   !> count (doc/performance.md, "The preset's deviation and the strip count"). With fewer than
   !> ng strips every strip is a group.
   pure subroutine group_bounds(n, ng, bound)
      !> Number of strips.
      integer, intent(in) :: n
      !> Number of groups.
      integer, intent(out) :: ng
      !> Boundaries 0 = bound(0) < … < bound(ng) = n (strip widths).
      real(wp), intent(out) :: bound(0:)
      integer :: j, b(0:max_groups)

      ng = min(n, max_groups)
      if (ng < max_groups) then
         bound(0:ng) = [(real(j, wp), j = 0, ng)]
         return
      end if
      b(0) = 0
      b(ng) = reference_strips
      do j = 1, ng/2
         b(j) = max(b(j - 1) + 1, nint(reference_strips*(0.5_wp*real(j, wp)/ng + &
            0.25_wp*(1.0_wp - cos(pi*real(j, wp)/ng)))))
      end do
      do j = ng - 1, ng/2 + 1, -1
         b(j) = reference_strips - b(ng - j)
      end do
      ! Exact where n is the reference count: the default's groups are whole strips.
      bound(0:ng) = real(b(0:ng), wp)*real(n, wp)/real(reference_strips, wp)
   end subroutine group_bounds

end module shcontact_normal_coupling_groups
