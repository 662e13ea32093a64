!> Where a patch's reference point lies on its loaded gap (issue 25; doc/kinematics.md, "The
!> patch's reference point"): the minimum of the undeformed distance of the loaded state, as
!> CONTACT defines the geometric contact point, blended continuously with other minima of
!> nearly the same depth.
!>
!> The creepages of the rigid-body motion are given at the reference point and carried to the
!> strips by the rigid slip to first order in the distance (shcontact_tangential_spin), and the
!> patch's contact plane is the tangent plane there. The exact theory does not depend on the
!> point; the strip model does, a little, through those first-order terms. On a patch with one
!> minimum of the loaded gap (every tread patch, every patch of a Hertzian kind) the minimum is
!> the unambiguous centre of the contact, and it is kept exactly. On a patch that spans a flange
!> root and the flange the loaded gap has two minima whose depths change with the approach (its
!> tilt term): where they cross, the deepest one jumps from one to the other, and so did the
!> creepages and the forces (flange state 789 of the benchmark: γ₀ −1.222 → −0.561 rad and
!> the vertical force by 565 N between two approaches 1e-6 mm apart) although nothing physical
!> changes there: both points are as much the centre of the contact. Each further minimum k
!> therefore takes a weight w_k = φ((g_k − g_min)/B_k) in a weighted mean of the minima's
!> positions, the deepest with weight 1: φ falls smoothly from 1 at 0 to 0 at 1 (1 − 3x² + 2x³)
!> and B_k is the minimum's band, at most s = [[blend_depth]] times the patch's approach. At a
!> crossing of the deepest both weights are 1 (the point lies midway, whichever was the deepest
!> an instant before); a minimum s or more above the deepest has weight 0.
!>
!> The band measures the basin of minimum k of its own: B_k is the smaller over the two
!> sides of E[min(s, r − g_k)], r the highest loaded gap on the way from k to where a walk
!> outwards stops. In the elder rule of persistence the walk stops at the first point deeper
!> than g_k, so a shallow wiggle beside a deeper point has a small band and a minimum that
!> vanishes into a flank has none. That rule is discontinuous where two other minima cross in
!> depth: each walk stops at the other or runs past it, and their bands swap (the flange-root
!> state of doc/kinematics.md, "What is not smooth yet", failed there: a wiggle's weight went
!> from 0.78 to 0 between approaches 5e-6 mm apart). Here the walk stops at a point i deeper than
!> g_k with the probability S((g_k − g_i)/τ), S rising smoothly from 0 at 0 to 1 at 1, where
!> τ = min(η s, r − g_k) with η = [[tie_depth]]: every term is continuous in the loaded gap, so
!> two minima whose depths cross share their bands for a moment instead of swapping them, and a
!> minimum that vanishes into a flank (r − g_k → 0 on the flank's side) still stops at once and
!> has no band. The point therefore moves continuously with the approach and the position, and
!> equals the deepest minimum wherever no other one comes within s of it. Continuous, not
!> smooth: where the ridge r − g_k beside a shallow minimum is small, τ is small and its band
!> changes steeply with the depths (a steep, continuous swing of the point). Two conditions
!> are the caller's: the searched window's end points lie more than s above its deepest point
!> (the callers search the loaded strips and a point beyond each end, where the loaded gap is
!> well above its minimum; a minimum is judged with its neighbours outside the window and a
!> walk that runs off the window counts as finding no deeper point), and the loaded gap is
!> not exactly straight over the minimum (then every point is the minimum at one approach and
!> the point jumps along it, as any minimum would).
module shcontact_normal_reference
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: reference_index

   !> Depth band of the blend, as a fraction of the patch's approach: a second minimum of the
   !> loaded gap less than this much above the deepest one takes part in the reference point
   !> (module text).
   real(wp), parameter, public :: blend_depth = 0.25_wp
   !> The walk's stopping band η as a fraction of s (module text): two minima whose depths differ
   !> by less than η s (or than the ridge between them) share their bands.
   real(wp), parameter, public :: tie_depth = 0.01_wp
   !> A walk whose survival has fallen below this adds survival·s and stops (its remaining terms
   !> lie between 0 and that): the band is then within 1e-12 s of the full walk's.
   real(wp), parameter :: survival_floor = 1.0e-12_wp

contains

   !> The reference point on the loaded gap g_i + a c_i of a table (module text): a fractional
   !> table index (a minimum is refined by the parabola through its neighbours, within half a
   !> step), searched over the points first … last. `scale` is the depth band s (mm); s ≤ 0 gives
   !> the deepest minimum alone.
   pure real(wp) function reference_index(gap, tilt, approach, first, last, scale) result(x)
      !> Gap g_i (mm) and tilt term c_i at the table points.
      real(wp), intent(in) :: gap(:), tilt(:)
      !> The approach a that multiplies the tilt term (mm).
      real(wp), intent(in) :: approach
      !> The table points searched (1 ≤ first ≤ last ≤ the table's length).
      integer, intent(in) :: first, last
      !> The depth band s (mm).
      real(wp), intent(in) :: scale
      !> Most minima gathered in the search itself; more (a noisy table) take a second pass.
      integer, parameter :: max_gathered = 8
      real(wp) :: total, g_min, g_k, g_prev, g_next, depth(max_gathered)
      integer :: n, k, jm, found, at(max_gathered)
      logical :: overflow

      n = min(size(gap), size(tilt))
      ! One pass: the deepest point, and the local minima that may lie within the band of it
      ! (within s of the deepest so far, which is never below the final one).
      found = 0
      overflow = .false.
      g_prev = huge(1.0_wp)
      if (first > 1) g_prev = loaded(first - 1)
      g_k = loaded(first)
      g_min = g_k
      jm = first
      do k = first, last
         g_next = huge(1.0_wp)
         if (k < n) g_next = loaded(k + 1)
         if (g_k < g_min) then
            g_min = g_k
            jm = k
         end if
         if (g_k < g_prev .and. g_k <= g_next .and. g_k - g_min < scale .and. k > 1 .and. &
               k < n) then
            if (found < max_gathered) then
               found = found + 1
               at(found) = k
               depth(found) = g_k
            else
               overflow = .true.
            end if
         end if
         g_prev = g_k
         g_k = g_next
      end do
      x = vertex(jm)
      if (.not. (scale > 0.0_wp)) return
      total = 1.0_wp
      if (overflow) then
         do k = max(first, 2), min(last, n - 1)
            g_k = loaded(k)
            if (g_k < loaded(k - 1) .and. g_k <= loaded(k + 1)) call add(k, g_k, x, total)
         end do
      else
         do k = 1, found
            call add(at(k), depth(k), x, total)
         end do
      end if
      x = x/total
   contains
      !> Add minimum j (loaded gap g_j), other than the deepest, with its weight (module text)
      !> to the weighted sum x of positions and the sum of the weights.
      pure subroutine add(j, g_j, x, total)
         integer, intent(in) :: j
         real(wp), intent(in) :: g_j
         real(wp), intent(inout) :: x, total
         real(wp) :: band, t, weight
         if (j == jm .or. .not. (g_j - g_min < scale)) return
         band = min(scale, side_band(j, g_j, -1), side_band(j, g_j, 1))
         if (.not. (band > 0.0_wp)) return
         t = min(1.0_wp, max(0.0_wp, (g_j - g_min)/band))
         weight = 1.0_wp - t*t*(3.0_wp - 2.0_wp*t)
         x = x + weight*vertex(j)
         total = total + weight
      end subroutine add

      !> The loaded gap at table point i (mm, up to a constant).
      pure real(wp) function loaded(i)
         integer, intent(in) :: i
         loaded = gap(i) + approach*tilt(i)
      end function loaded

      !> The parabola's vertex through j and its neighbours, within half a step of j.
      pure real(wp) function vertex(j)
         integer, intent(in) :: j
         real(wp) :: g_lo, g_mid, g_hi, curvature
         vertex = real(j, wp)
         if (j <= 1 .or. j >= n) return
         g_lo = loaded(j - 1)
         g_mid = loaded(j)
         g_hi = loaded(j + 1)
         curvature = g_lo - 2.0_wp*g_mid + g_hi
         if (curvature > 0.0_wp) vertex = vertex + max(-0.5_wp, min(0.5_wp, &
            0.5_wp*(g_lo - g_hi)/curvature))
      end function vertex

      !> E[min(s, r − g_j)] of a walk from minimum j in direction `step` (module text): r the
      !> highest loaded gap passed, the walk stopping at a point i below g_j with probability
      !> S((g_j − g_i)/τ), τ = min(η s, r − g_j) (probability 1 when τ = 0); s where it runs
      !> off the searched points or where the walk's survival falls below [[survival_floor]]
      !> (a flat, noisy stretch would otherwise be walked to its end from every minimum).
      pure real(wp) function side_band(j, g_j, step) result(band)
         integer, intent(in) :: j, step
         real(wp), intent(in) :: g_j
         integer :: i
         real(wp) :: top, alive, below, stop_here, tie, g_i
         band = 0.0_wp
         alive = 1.0_wp
         top = g_j
         i = j + step
         do while (i >= first .and. i <= last)
            g_i = loaded(i)
            top = max(top, g_i)
            ! Every later stop adds s: the rest of the walk is s.
            if (.not. (top - g_j < scale)) exit
            below = g_j - g_i
            if (below > 0.0_wp) then
               tie = min(tie_depth*scale, top - g_j)
               stop_here = 1.0_wp
               if (below < tie) stop_here = (below/tie)**2*(3.0_wp - 2.0_wp*below/tie)
               band = band + alive*stop_here*(top - g_j)
               alive = alive*(1.0_wp - stop_here)
               if (.not. (alive > survival_floor)) exit
            end if
            i = i + step
         end do
         band = band + alive*scale
      end function side_band

   end function reference_index

end module shcontact_normal_reference
