!> Where the strips of a semi-Hertzian patch lie for an approach δ (doc/theory.md §4.3 step 3):
!> the cover values of the table points, from which the strips' interval grows continuously
!> with δ ([[outward_cover]]), and the interval's ends found by bisection in them.
module shcontact_normal_strip_cover
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: cover_ramp, outward_cover, reached_end

   !> Smallest relative growth of δ over which the strips sweep across table points out of
   !> contact towards a region farther out that comes into contact ([[outward_cover]]): large
   !> against the ≈ 2e-4 change of the midpoint error it spreads out, small enough that the
   !> strips seldom reach past the contact.
   real(wp), parameter :: cover_ramp = 0.01_wp

contains

   !> The approach from which the strips cover each table point, on one side of the
   !> first-contact point (`touch(1)`, the smallest value) outwards.
   !>
   !> Every table point with δ_j = δ − touch_j > 0 carries load (doc/theory.md §4.3 step 3), also
   !> beyond a point that does not: touch = g/ε_b is not monotonic where ε_b changes faster than
   !> the gap (a jump of B between profile arcs), nor where the basin holds a second, shallower
   !> minimum. The strips must then reach past the points out of contact, and their interval
   !> must grow continuously with δ: a jump, when a far region comes into contact, would move
   !> every strip of the near one and make N(δ) jump by the change of the midpoint rule's error
   !> (up to ≈ 2e-4 with 100 strips), which no root finder can match.
   !>
   !> So cover is the largest monotonic minorant of touch (its running minimum from the far
   !> end), except over points out of contact, where that minorant is flat (a region farther out,
   !> at touch value τ, comes into contact first): there cover rises on a straight line, from the
   !> last point before them with cover ≤ (1 − cover_ramp)τ up to τ, and the strips sweep across
   !> them (carrying no load there) while δ grows by at least that fraction. N(δ) is then
   !> continuous, so the load match always converges. On the tread it also stays increasing:
   !> the sweep changes ln N by the change of the midpoint error, ≈ 2e-4, over Δ ln δ ≥ 0.01,
   !> while d ln N/d ln δ ≈ 1.5. On nearly conformal flange-root contacts the midpoint rule's
   !> aliasing (strips moving across narrow pressure features) can make N dip by up to ≈ 1e-3
   !> where the strips sweep fast, as it could before where the contact grew fast; a load in
   !> such a dip has more than one approach, and the one found is as good as the others.
   !> Where touch increases outwards, cover = touch and the strips end where they always did
   !> (bit for bit); near a far region the strips may reach past the contact (δ within
   !> cover_ramp of τ), which costs them a little resolution.
   pure subroutine outward_cover(touch, cover)
      !> touch values from the first-contact point outwards (mm).
      real(wp), intent(in) :: touch(:)
      !> The cover values (mm): cover ≤ touch, cover(1) = touch(1), nondecreasing, and equal to
      !> touch at the last point.
      real(wp), intent(out) :: cover(:)
      integer :: n, j, j_far, j_ramp, i
      real(wp) :: far

      n = size(touch)
      cover(n) = touch(n)
      do j = n - 1, 1, -1
         cover(j) = min(touch(j), cover(j + 1))
      end do
      j = 2
      do while (j < n)
         if (.not. (cover(j) < touch(j))) then
            j = j + 1
            cycle
         end if
         ! Points j..j_far − 1 are out of contact until δ reaches far = touch(j_far).
         j_far = j + 1
         do while (cover(j_far) < touch(j_far))
            j_far = j_far + 1
         end do
         far = cover(j_far)
         j_ramp = j - 1
         do while (j_ramp > 1 .and. cover(j_ramp) > (1.0_wp - cover_ramp)*far)
            j_ramp = j_ramp - 1
         end do
         do i = j_ramp + 1, j_far - 1
            cover(i) = min(cover(i), cover(j_ramp) + (far - cover(j_ramp))* &
               real(i - j_ramp, wp)/real(j_far - j_ramp, wp))
         end do
         j = j_far + 1
      end do
   end subroutine outward_cover

   !> The table point farthest from i_inner towards i_outer that the approach reaches: the
   !> last j on the way from i_inner to i_outer (either side of it) with cover(j) < δ, where
   !> cover does not decrease from i_inner outwards and cover(i_inner) < δ. A bisection:
   !> `reached_end(cover, i_first, 1, δ)` is the first point of the strips' interval,
   !> `reached_end(cover, i_first, n, δ)` its last.
   pure integer function reached_end(cover, i_inner, i_outer, approach) result(j)
      real(wp), intent(in) :: cover(:)
      integer, intent(in) :: i_inner, i_outer
      real(wp), intent(in) :: approach
      integer :: inner, outer, mid

      ! Invariant: cover(inner) < δ; cover(outer) ≥ δ unless outer is i_outer.
      inner = i_inner
      outer = i_outer
      if (approach > cover(outer)) then
         j = outer
         return
      end if
      do while (abs(outer - inner) > 1)
         mid = (inner + outer)/2
         if (approach > cover(mid)) then
            inner = mid
         else
            outer = mid
         end if
      end do
      j = inner
   end function reached_end

end module shcontact_normal_strip_cover
