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

   public :: frame_point_type, frame_point, locate_eta, seek_eta

   !> Newton steps of [[seek_eta]] before it falls back to [[locate_eta]].
   integer, parameter :: max_newton = 8
   !> [[seek_eta]] stops after a Newton step this small (mm): the error of the next one would be
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
      type(spline_point_type) :: q
      real(wp) :: de, dz, d2e, d2z

      p%k = spline%interval(s, hint)
      q = spline%eval(s, p%k)
      p%s = q%s
      p%u = q%y; p%v = q%z
      call map%point(q%y, q%z, p%eta, p%zeta)
      call map%vector(q%dy, q%dz, de, dz)
      call map%vector(q%d2y, q%d2z, d2e, d2z)
      p%deta = dir*de
      if (de**2 > 1.0e-24_wp*(de**2 + dz**2)) then
         ! ζ' = ζ_s/η_s, ζ'' = (ζ_ss η_s − ζ_s η_ss)/η_s³.
         p%slope = dz/de
         p%curv = (d2z*de - dz*d2e)/de**3
      else
         p%slope = 0.0_wp; p%curv = 0.0_wp
      end if
   end function frame_point

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

   !> [[locate_eta]] for a walk that moves little: Newton steps on the spline's cubics from the
   !> tangent's prediction s + (eta − eta0)/(dη/ds), which converge in two or three steps where
   !> [[locate_eta]] brackets and solves from scratch. The crossing is the one [[locate_eta]]
   !> finds (it falls back to it when Newton leaves the profile, moves against the walk, jumps
   !> further than twice the prediction or does not converge); the two agree to ~1e-14 mm.
   pure subroutine seek_eta(spline, map, eta, dir, eta0, deta0, s, k, found)
      !> The profile.
      type(profile_spline_type), intent(in) :: spline
      !> Profile coordinates to frame coordinates.
      type(rigid_map_type), intent(in) :: map
      !> Frame lateral coordinate sought (mm).
      real(wp), intent(in) :: eta
      !> +1 when η grows with s near the start, −1 when it falls.
      integer, intent(in) :: dir
      !> η at the start and dir·dη/ds there (> 0 where the walk may use Newton steps).
      real(wp), intent(in) :: eta0, deta0
      !> Start on entry, the crossing on return (mm).
      real(wp), intent(inout) :: s
      !> Interval of s (guess on entry).
      integer, intent(inout) :: k
      !> Whether the crossing was found.
      logical, intent(out) :: found
      real(wp) :: ay, az, target, x, ds, predicted, t, f, df, c(4)
      integer :: it, kx, kc, n

      found = .false.
      if (deta0 > 0.0_wp) then
         ay = map%c; az = -map%s
         target = eta - map%dy
         n = spline%size()
         predicted = dir*(eta - eta0)/deta0
         x = s + predicted
         kx = k
         kc = 0
         do it = 1, max_newton
            if (x < spline%s(1) .or. x > spline%s(n)) exit
            kx = spline%interval(x, kx)
            if (kx /= kc) then
               c = ay*spline%cy(:, kx) + az*spline%cz(:, kx)
               c(1) = c(1) - target
               kc = kx
            end if
            t = x - spline%s(kx)
            f = c(1) + t*(c(2) + t*(c(3) + t*c(4)))
            df = c(2) + t*(2.0_wp*c(3) + 3.0_wp*t*c(4))
            if (.not. (dir*df > 0.0_wp)) exit
            ds = f/df
            x = x - ds
            if (abs(ds) <= newton_tol) then
               found = x >= spline%s(1) .and. x <= spline%s(n) .and. &
                  (x - s)*predicted >= 0.0_wp .and. abs(x - s) <= 2.0_wp*abs(predicted) + newton_tol
               exit
            end if
         end do
         if (found) then
            s = x
            k = spline%interval(x, kx)
            return
         end if
      end if
      call locate_eta(spline, map, eta, dir, s, k, found)
   end subroutine seek_eta

end module shcontact_geometry_curve
