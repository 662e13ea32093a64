!> A profile spline seen through a rigid map: its points, slopes and curvatures as the graph
!> ζ(η) in some frame (track coordinates, or a contact patch's frame, physics.md §5.4).
!>
!> Profiles are splines in arc length, so they may be multi-valued in y; in a frame they are
!> read as graphs only locally, by following them from a known point ([[locate_eta]]).
module shcontact_geometry_curve
   use shcontact_core_kinds, only: wp
   use shcontact_profile_spline, only: profile_spline_type, spline_point_type
   use shcontact_geometry_rigid, only: rigid_map_type
   implicit none
   private

   public :: frame_point_type, frame_point, locate_eta, walk_to_eta

   !> Newton steps of [[walk_to_eta]] before it falls back to [[locate_eta]].
   integer, parameter :: max_newton = 8
   !> [[walk_to_eta]] stops after a Newton step this small (mm): the error of the next one would be
   !> below 1e-14 mm for any profile the walk follows (|dη/ds| > 0.05, curvature < 10/mm).
   real(wp), parameter :: newton_tol = 1.0e-8_wp

   !> A profile point in a frame, with the profile's local shape as a graph ζ(η).
   type :: frame_point_type
      !> Arc length on the profile (mm) and the spline interval holding it.
      real(wp) :: s = 0.0_wp
      integer :: k = 1
      !> Profile coordinates (mm).
      real(wp) :: u = 0.0_wp, v = 0.0_wp
      !> Frame coordinates (mm).
      real(wp) :: eta = 0.0_wp, zeta = 0.0_wp
      !> dη/ds: the tangent's lateral component in the frame (≤ 0 where the profile runs
      !> against the direction it is followed in).
      real(wp) :: deta = 0.0_wp
      !> dζ/dη and d²ζ/dη² (1/mm); zero where dη/ds = 0.
      real(wp) :: slope = 0.0_wp, curv = 0.0_wp
      !> d²η/ds² (1/mm), for the second-order prediction of a walk's next point.
      real(wp) :: d2eta = 0.0_wp
   end type frame_point_type

contains

   !> The point of `spline` at arc length s, mapped by `map`; `dir` = ±1 is the sense in which
   !> s runs along +η (the slope and curvature of the graph do not depend on it; `deta` does).
   pure type(frame_point_type) function frame_point(spline, map, s, dir, hint) result(p)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Arc length (mm).
      real(wp), intent(in) :: s
      !> +1 when η grows with s, −1 when it falls.
      integer, intent(in) :: dir
      !> A guess of the spline interval.
      integer, intent(in), optional :: hint
      real(wp) :: sc

      sc = min(max(s, spline%s(1)), spline%s(spline%size()))
      p = point_in_interval(spline, map, sc, spline%interval(sc, hint), dir)
   end function frame_point

   !> [[frame_point]] at s on interval k (s inside it or at its ends), without searching.
   pure type(frame_point_type) function point_in_interval(spline, map, s, k, dir) result(p)
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: s
      integer, intent(in) :: k, dir
      real(wp) :: t, y, dy, d2y, z, dz, d2z, de, d2e, d2z_frame

      p%k = k
      p%s = s
      t = s - spline%s(k)
      associate (cy => spline%cy(:, k), cz => spline%cz(:, k))
         y = cy(1) + t*(cy(2) + t*(cy(3) + t*cy(4)))
         dy = cy(2) + t*(2.0_wp*cy(3) + 3.0_wp*t*cy(4))
         d2y = 2.0_wp*cy(3) + 6.0_wp*t*cy(4)
         z = cz(1) + t*(cz(2) + t*(cz(3) + t*cz(4)))
         dz = cz(2) + t*(2.0_wp*cz(3) + 3.0_wp*t*cz(4))
         d2z = 2.0_wp*cz(3) + 6.0_wp*t*cz(4)
      end associate
      p%u = y; p%v = z
      ! The map (rigid_map_type's point and vector), written out: this is the walk's inner loop.
      p%eta = map%c*y - map%s*z + map%dy
      p%zeta = map%s*y + map%c*z + map%dz
      de = map%c*dy - map%s*dz
      dz = map%s*dy + map%c*dz
      d2e = map%c*d2y - map%s*d2z
      d2z_frame = map%s*d2y + map%c*d2z
      p%deta = dir*de
      p%d2eta = d2e
      if (de**2 > 1.0e-24_wp*(de**2 + dz**2)) then
         ! ζ' = ζ_s/η_s, ζ'' = (ζ_ss η_s − ζ_s η_ss)/η_s³.
         p%slope = dz/de
         p%curv = (d2z_frame*de - dz*d2e)/de**3
      else
         p%slope = 0.0_wp; p%curv = 0.0_wp
      end if
   end function point_in_interval

   !> Follow the profile from arc length `s` to the point where η = `eta`, walking the spline
   !> intervals in the sense `dir` says η grows. `found` is false when the profile ends first.
   !> The point found is the crossing nearest to the start in that walk, so stepping η in
   !> small increments follows one branch of a multi-valued profile.
   pure subroutine locate_eta(spline, map, eta, dir, s, k, found)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Frame lateral coordinate sought (mm).
      real(wp), intent(in) :: eta
      !> +1 when η grows with s near the start, −1 when it falls.
      integer, intent(in) :: dir
      !> Start on entry, the crossing on return (mm).
      real(wp), intent(inout) :: s
      !> Interval of s (guess on entry).
      integer, intent(inout) :: k
      !> Whether the crossing was found.
      logical, intent(out) :: found
      real(wp) :: ay, az, target
      integer :: n

      ! η = c·y − s·z + dy: the position projected on (c, −s).
      ay = map%c; az = -map%s
      target = eta - map%dy
      n = spline%size()
      k = spline%interval(s, k)
      found = .false.
      do while (f(spline%s(k), k) > 0.0_wp)
         k = k - 1
         if (k < 1) return
      end do
      do while (f(spline%s(k + 1), k) < 0.0_wp)
         k = k + 1
         if (k > n - 1) return
      end do
      s = spline%solve_in_interval(k, ay, az, target, guess=s)
      found = .true.
   contains
      !> dir·(η(s) − eta), increasing in s where the profile is followed the right way.
      pure real(wp) function f(sv, kv)
         real(wp), intent(in) :: sv
         integer, intent(in) :: kv
         f = dir*(spline%projection(sv, ay, az, kv) - target)
      end function f
   end subroutine locate_eta

   !> The next point of a walk along a profile: where η = eta, from the walk's last point
   !> `last` (followed in the sense `dir`), evaluated like [[frame_point]]. Where [[locate_eta]]
   !> brackets and solves from scratch, this predicts the arc length to second order from
   !> `last` and corrects it by Newton steps on the spline's cubics (one or two). The crossing
   !> is the one [[locate_eta]] finds, to ~1e-14 mm: it falls back to [[locate_eta]] when Newton
   !> leaves the profile, moves against the walk or further than twice the prediction, meets
   !> dη/ds ≤ 0 or does not converge. `found` is false when the profile ends first.
   pure subroutine walk_to_eta(spline, map, eta, dir, last, p, found)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Frame lateral coordinate sought (mm).
      real(wp), intent(in) :: eta
      !> +1 when η grows with s near `last`, −1 when it falls.
      integer, intent(in) :: dir
      !> The walk's last point (from [[frame_point]] or this routine, with the same `dir`).
      type(frame_point_type), intent(in) :: last
      !> The point found.
      type(frame_point_type), intent(out) :: p
      !> Whether the crossing was found.
      logical, intent(out) :: found
      real(wp) :: x, s
      integer :: k

      x = last%s
      k = last%k
      call newton_eta(spline, map, eta, dir, last, x, k, found)
      if (.not. found) then
         s = last%s
         k = last%k
         call locate_eta(spline, map, eta, dir, s, k, found)
         if (found) p = frame_point(spline, map, s, dir, k)
         return
      end if
      p = point_in_interval(spline, map, x, k, dir)
   end subroutine walk_to_eta

   !> Newton's method for η(s) = eta from the second-order prediction at `last` (see
   !> [[walk_to_eta]]); `found` is false where it cannot be trusted. On success x is the crossing
   !> and k the interval holding it ([[profile_spline_type]]'s `interval`).
   pure subroutine newton_eta(spline, map, eta, dir, last, x, k, found)
      type(profile_spline_type), intent(in) :: spline
      type(rigid_map_type), intent(in) :: map
      real(wp), intent(in) :: eta
      integer, intent(in) :: dir
      type(frame_point_type), intent(in) :: last
      real(wp), intent(out) :: x
      integer, intent(inout) :: k
      logical, intent(out) :: found
      real(wp) :: ay, az, target, ds, predicted, d_eta, t, f, df, c(4)
      integer :: it, kc, n

      found = .false.
      x = last%s
      if (.not. last%deta > 0.0_wp) return
      ay = map%c; az = -map%s
      target = eta - map%dy
      n = spline%size()
      ! η(σ) ≈ η₀ + η'σ + η''σ²/2 along σ = dir·(s − s₀), inverted to second order.
      d_eta = eta - last%eta
      predicted = dir*(d_eta/last%deta - 0.5_wp*last%d2eta*d_eta**2/last%deta**3)
      x = last%s + predicted
      kc = 0
      do it = 1, max_newton
         if (x < spline%s(1) .or. x > spline%s(n)) return
         if (.not. (x >= spline%s(k) .and. x < spline%s(k + 1))) k = spline%interval(x, k)
         if (k /= kc) then
            c = ay*spline%cy(:, k) + az*spline%cz(:, k)
            c(1) = c(1) - target
            kc = k
         end if
         t = x - spline%s(k)
         f = c(1) + t*(c(2) + t*(c(3) + t*c(4)))
         df = c(2) + t*(2.0_wp*c(3) + 3.0_wp*t*c(4))
         if (.not. (dir*df > 0.0_wp)) return
         ds = f/df
         x = x - ds
         if (abs(ds) <= newton_tol) then
            if (x < spline%s(1) .or. x > spline%s(n)) return
            if ((x - last%s)*predicted < 0.0_wp) return
            if (abs(x - last%s) > 2.0_wp*abs(predicted) + newton_tol) return
            k = spline%interval(x, k)
            found = .true.
            return
         end if
      end do
   end subroutine newton_eta

end module shcontact_geometry_curve
