!> First look for contact: the vertical gap between two positioned profiles sampled on a uniform
!> lateral grid, and its separate local minima, the candidate contact patches (doc/theory.md §4.6,
!> §5.3 step 4–5).
!>
!> The profiles come as dense polylines in one frame. Each is reduced to the envelope that
!> faces the other body (the rail's highest and the wheel's lowest point over each grid line),
!> so multi-valued parts such as a vertical flange back do no harm. The candidates are refined
!> along their own normals afterwards; this coarse stage only has to find every basin.
module shcontact_geometry_search
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: polyline_envelope, envelope_segments, gap_minima

contains

   !> Sample a polyline on the grid y_j = y0 + (j − 1) h, j = 1..size(env): at every grid line
   !> crossed by a segment, the linearly interpolated z and arc length, keeping the largest z
   !> (`lowest`, the wheel: z points down) or the smallest z (the rail). Grid lines that no
   !> segment crosses are left uncovered.
   pure subroutine polyline_envelope(y, z, s, y0, h, lowest, env, env_s, covered)
      !> Polyline points (mm) and their arc lengths on the profile (mm).
      real(wp), intent(in) :: y(:), z(:), s(:)
      !> First grid line and spacing (mm).
      real(wp), intent(in) :: y0, h
      !> Keep the largest z (true) or the smallest (false).
      logical, intent(in) :: lowest
      !> Envelope height and the arc length where it is attained.
      real(wp), intent(out) :: env(:), env_s(:)
      !> Whether any segment crosses the grid line.
      logical, intent(out) :: covered(:)

      covered = .false.
      env = 0.0_wp
      env_s = 0.0_wp
      call envelope_segments(y, z, s, 1, size(y) - 1, y0, h, lowest, env, env_s, covered)
   end subroutine polyline_envelope

   !> Add the segments i → i + 1, i = i1 … i2, of a polyline to an envelope of
   !> [[polyline_envelope]] (in this order: a polyline's segments taken in increasing runs give
   !> the envelope of [[polyline_envelope]] bit for bit, as long as the segments left out cross
   !> no grid line).
   pure subroutine envelope_segments(y, z, s, i1, i2, y0, h, lowest, env, env_s, covered)
      !> Polyline points (mm) and their arc lengths on the profile (mm); only points i1 … i2 + 1
      !> are read.
      real(wp), intent(in) :: y(:), z(:), s(:)
      !> First and last segment.
      integer, intent(in) :: i1, i2
      !> First grid line and spacing (mm).
      real(wp), intent(in) :: y0, h
      !> Keep the largest z (true) or the smallest (false).
      logical, intent(in) :: lowest
      !> Envelope height and the arc length where it is attained, updated.
      real(wp), intent(inout) :: env(:), env_s(:)
      !> Whether any segment crosses the grid line, updated.
      logical, intent(inout) :: covered(:)
      integer :: i, j, j1, j2, m
      real(wp) :: g0, g1, t, zj

      m = size(env)
      if (i2 < i1) return
      ! Grid coordinates (y − y0)/h of the points, one division per point: the same values as
      ! (min(y_i, y_i+1) − y0)/h, since both operations are monotone.
      g1 = (y(i1) - y0)/h
      do i = i1, i2
         g0 = g1
         g1 = (y(i + 1) - y0)/h
         ! A vertical segment crosses no grid line that its neighbours do not.
         if (abs(y(i + 1) - y(i)) <= tiny(1.0_wp)) cycle
         j1 = max(1, ceiling(min(g0, g1)) + 1)
         j2 = min(m, floor(max(g0, g1)) + 1)
         do j = j1, j2
            t = (y0 + (j - 1)*h - y(i))/(y(i + 1) - y(i))
            zj = z(i) + t*(z(i + 1) - z(i))
            if (covered(j)) then
               if (lowest .neqv. (zj > env(j))) cycle
            end if
            covered(j) = .true.
            env(j) = zj
            env_s(j) = s(i) + t*(s(i + 1) - s(i))
         end do
      end do
   end subroutine envelope_segments

   !> Indices of the separate local minima of a sampled gap, deepest first. A minimum counts
   !> only inside a run of valid points (not at its ends), and only if every path from it to a
   !> deeper point climbs more than `merge_gap` (a minimum behind a negligible maximum belongs to
   !> its deeper neighbour's patch). `global_interior` tells whether the smallest valid value is
   !> such an interior minimum (otherwise the profiles touch at the end of one of them).
   pure subroutine gap_minima(gap, valid, merge_gap, minima, count, global_interior)
      !> Sampled gap (mm).
      real(wp), intent(in) :: gap(:)
      !> Where the gap is defined.
      logical, intent(in) :: valid(:)
      !> Negligible height of a separating maximum (mm).
      real(wp), intent(in) :: merge_gap
      !> Indices of the minima kept, deepest first (the first `count` entries are set; the size
      !> of the gap array is always enough).
      integer, intent(out) :: minima(:)
      !> Number of minima kept.
      integer, intent(out) :: count
      !> Whether the global minimum is an interior local minimum.
      logical, intent(out) :: global_interior
      integer :: j, n, i, best, n_local
      real(wp) :: gmin
      logical :: any_valid

      n = size(gap)
      ! One pass: the smallest valid gap, and the interior local minima (in `minima`, in order).
      any_valid = .false.
      gmin = 0.0_wp
      n_local = 0
      if (n >= 1) then
         if (valid(1)) then
            any_valid = .true.
            gmin = gap(1)
         end if
      end if
      do j = 2, n - 1
         if (.not. valid(j)) cycle
         if (.not. any_valid) then
            any_valid = .true.
            gmin = gap(j)
         else if (gap(j) < gmin) then
            gmin = gap(j)
         end if
         if (.not. (gap(j) <= gap(j - 1) .and. gap(j) < gap(j + 1))) cycle
         if (.not. (valid(j - 1) .and. valid(j + 1))) cycle
         n_local = n_local + 1
         minima(n_local) = j
      end do
      if (n >= 2) then
         if (valid(n)) then
            if (.not. any_valid) then
               gmin = gap(n)
            else if (gap(n) < gmin) then
               gmin = gap(n)
            end if
         end if
      end if
      ! Keep those behind a separating maximum higher than merge_gap.
      count = 0
      global_interior = .false.
      do i = 1, n_local
         j = minima(i)
         if (saddle_height(j) - gap(j) < merge_gap) cycle
         count = count + 1
         minima(count) = j
         if (gap(j) <= gmin) global_interior = .true.
      end do
      ! Deepest first (insertion sort: there are few).
      do i = 2, count
         best = minima(i)
         j = i - 1
         do while (j >= 1)
            if (gap(minima(j)) <= gap(best)) exit
            minima(j + 1) = minima(j)
            j = j - 1
         end do
         minima(j + 1) = best
      end do
   contains
      !> The lowest pass from point j0 to any deeper point: the highest value met on the way,
      !> the smaller over both directions; +huge when no deeper point is reachable.
      pure real(wp) function saddle_height(j0)
         integer, intent(in) :: j0
         integer :: jj
         real(wp) :: top
         saddle_height = huge(1.0_wp)
         top = gap(j0)
         do jj = j0 - 1, 1, -1
            if (.not. valid(jj)) exit
            top = max(top, gap(jj))
            if (gap(jj) < gap(j0)) then
               saddle_height = top
               exit
            end if
         end do
         top = gap(j0)
         do jj = j0 + 1, n
            if (.not. valid(jj)) exit
            top = max(top, gap(jj))
            if (gap(jj) < gap(j0)) then
               saddle_height = min(saddle_height, top)
               exit
            end if
         end do
      end function saddle_height
   end subroutine gap_minima

end module shcontact_geometry_search
