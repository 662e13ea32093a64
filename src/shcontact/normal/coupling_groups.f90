!> The groups of strips of the coupled reduction (shcontact_normal_coupling, module text there):
!> a fixed partition of each patch's strips by index ([[group_strips]]), each group one strip of
!> its summed width and load-weighted mean centre, length, interpenetration and contact angle
!> ([[add_patch_groups]]); where the patches of a wheel press each other ([[patch_weights]]); and
!> the strips scaled back by their groups' coupled/local load ratios ([[scale_patch]]).
module shcontact_normal_coupling_groups
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_semihertz, only: vertical_tilt
   implicit none
   private

   public :: add_patch_groups, copy_patch_groups, patch_weights, scale_patch

   !> Most groups of strips per patch in the coupled solve (shcontact_normal_coupling).
   integer, parameter, public :: max_groups = 16
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
      integer :: first(max_groups), last(max_groups)
      integer :: ng, i, j, g, n, g1
      real(wp) :: load_i

      n = patch%n_strips
      call open_patch(set, sum(patch%strip_load(1:n)), offset, gamma)
      if (.not. (set%patch_load(set%n_patches) > 0.0_wp)) return
      ! A fixed partition of all the strips (module text): an odd number of strips needs an odd
      ! number of groups for a mirror-symmetric partition (a middle group).
      ng = min(n, max_groups)
      if (mod(n, 2) == 1 .and. mod(ng, 2) == 0) ng = ng - 1
      call group_strips(n, ng, first, last)
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
         do i = first(j), last(j)
            if (.not. (patch%a(i) > 0.0_wp .and. patch%k(i) > 0.0_wp)) cycle
            load_i = patch%strip_load(i)
            set%yc(g) = set%yc(g) + load_i*patch%y(i)
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
         set%width(g) = real(last(j) - first(j) + 1, wp)*patch%dy
         set%yc(g) = set%yc(g)/set%local(g)
         set%ac(g) = set%ac(g)/set%local(g)
         set%gc(g) = set%gc(g)/set%local(g)
         ! 1 − c at the group's mean contact angle (γ varies little across a group).
         set%wc(g) = 1.0_wp - vertical_tilt(set%wc(g)/set%local(g), patch%gamma_plane)
         ! The strips are still measured from the first contact: the coupling comes before
         ! refer_to_loaded_point (shcontact_normal_loading).
         set%s(g) = offset + set%yc(g)
         ! The local-Hertz strips have a_i = (a_H,i/p₀H,i) p₀,ᵢ: the group's own ratio.
         set%length_per_peak(g) = 0.5_wp*pi*set%ac(g)**2*set%width(g)/set%local(g)
         set%in_contact(g) = .true.
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
   !> largest load blended with its inner neighbour's), and their half-lengths by its square root;
   !> strips whose ratio vanishes leave the contact. The patch's load becomes the sum of its coupled groups' loads.
   pure subroutine scale_patch(set, ip, patch)
      type(group_set_type), intent(in) :: set
      integer, intent(in) :: ip
      type(normal_patch_type), intent(inout) :: patch
      real(wp) :: load, total, t, r, g, root, full, share
      real(wp) :: ratio(max_total)
      integer :: i, jg, g1, g2, n, gm

      n = patch%n_strips
      g1 = set%first_group(ip)
      g2 = set%last_group(ip)
      if (g2 < g1) return
      load = sum(set%ratio(g1:g2)*set%local(g1:g2))
      ! The ratios interpolated between the group centres: a group whose local load is below
      ! ratio_share of the patch's largest enters with its own ratio in proportion to that
      ! share and otherwise takes that of its neighbour towards the largest group, as its
      ! interpenetration enters ([[add_patch_groups]]). Its own ratio is that of a load that
      ! tends to 0 with the group's (0 when it is out of the coupled contact); taken at full
      ! weight, it pulled the interpolated ratios of its neighbours' strips towards it and let
      ! them jump when the group left the set (its strips out of contact): the coupled loads
      ! then jumped with the approach (doc/kinematics.md, "Robustness with other table steps").
      full = ratio_share*maxval(set%local(g1:g2))
      gm = g1 - 1 + maxloc(set%local(g1:g2), 1)
      ratio(gm) = set%ratio(gm)
      do jg = gm + 1, g2
         share = min(1.0_wp, set%local(jg)/full)
         ratio(jg) = share*set%ratio(jg) + (1.0_wp - share)*ratio(jg - 1)
      end do
      do jg = gm - 1, g1, -1
         share = min(1.0_wp, set%local(jg)/full)
         ratio(jg) = share*set%ratio(jg) + (1.0_wp - share)*ratio(jg + 1)
      end do
      ! The ratio of every strip first (p0 holds it until the last loop), 0 for a strip out of
      ! contact or whose ratio vanishes.
      jg = g1
      do i = 1, n
         r = 0.0_wp
         if (patch%a(i) > 0.0_wp .and. patch%k(i) > 0.0_wp) then
            do while (jg < g2)
               if (patch%y(i) < set%yc(jg + 1)) exit
               jg = jg + 1
            end do
            if (g1 == g2 .or. patch%y(i) <= set%yc(g1)) then
               r = ratio(g1)
            else if (jg >= g2) then
               r = ratio(g2)
            else
               t = (patch%y(i) - set%yc(jg))/(set%yc(jg + 1) - set%yc(jg))
               r = (1.0_wp - t)*ratio(jg) + t*ratio(jg + 1)
            end if
         end if
         patch%p0(i) = max(r, 0.0_wp)
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

   !> The groups of a patch's n strips: a fixed partition by strip index, ng groups whose
   !> widths grade from about 4 % of the strips at the ends to 8 % in the middle (half uniform,
   !> half Chebyshev-spaced boundaries, t_j = j/(2ng) + (1 − cos(πj/ng))/4): the strips move
   !> continuously with the approach and so do the groups, and the ends of the contact, where
   !> the lengths change fastest, get narrower groups. Mirror-symmetric; every group holds at
   !> least one strip.
   pure subroutine group_strips(n, ng, first, last)
      integer, intent(in) :: n, ng
      integer, intent(out) :: first(:), last(:)
      integer :: j, b(0:max_groups)

      b(0) = 0
      b(ng) = n
      do j = 1, ng - 1
         if (2*j <= ng) then
            b(j) = max(b(j - 1) + 1, nint(n*boundary(j)))
         end if
      end do
      do j = ng - 1, 1, -1
         if (2*j > ng) b(j) = min(b(j + 1) - 1, n - b(ng - j))
      end do
      do j = 1, ng
         first(j) = b(j - 1) + 1
         last(j) = b(j)
      end do
   contains
      pure real(wp) function boundary(j)
         integer, intent(in) :: j
         boundary = 0.5_wp*real(j, wp)/ng + 0.25_wp*(1.0_wp - cos(pi*real(j, wp)/ng))
      end function boundary
   end subroutine group_strips

end module shcontact_normal_coupling_groups
