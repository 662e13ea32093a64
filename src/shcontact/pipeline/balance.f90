!> The stages of a kinematic call: the contact of a wheelset state ([[kinematic_contact]]), with
!> the creepages of the wheelset motion at each loaded reference point ([[kinematic_tangential]])
!> and, for a vertical wheel load, the vertical balance ([[vertical_balance]]).
module shcontact_pipeline_balance
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_no_contact, stat_numerical
   use shcontact_core_strings, only: str_real
   use shcontact_geometry_kinematics, only: wheelset_state_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_rigid_slip, only: contact_point_type, rigid_creepages
   use shcontact_pipeline_load, only: contact_load_type, load_vertical_force, &
      load_vertical_position
   use shcontact_pipeline_cache, only: contact_cache_type, update_geometry, update_normal, &
      solve_patch, reference_axle, same
   implicit none
   private

   public :: kinematic_contact, kinematic_tangential

   !> The total vertical force of a kinematic call matches the load to this relative tolerance
   !> (0.65 N of 64.7 kN), within at most max_vertical_iterations solutions.
   real(wp), parameter :: vertical_rtol = 1.0e-5_wp
   integer, parameter :: max_vertical_iterations = 30
   !> Most solutions of the balance's load steps (step 2 of [[vertical_balance]]), the first
   !> one included, before it brackets the approach.
   integer, parameter :: max_load_steps = 5
   !> The balance's first solution (the normal problem carrying F_z, a predictor that only
   !> chooses the next load) iterates the coupled reduction's strip lengths to this step of
   !> ln a instead of the reduction's 1e-7 (shcontact_normal_coupling's coupling_start_type):
   !> its vertical force C₁ then lies within 0.054 |C₁ − F_z| (and 1.1e-4 F_z) of the converged
   !> one on the bench's 2000 states (doc/performance.md, "Speed-up 8"). Where |C₁ − F_z| ≤
   !> refine_margin tolerances, it is solved again to the full tolerance before it may end the
   !> balance: the balance ends only on solutions to the full tolerance.
   real(wp), parameter :: predictor_tolerance = 1.0e-3_wp
   real(wp), parameter :: refine_margin = 10.0_wp

contains

   !> Geometry, normal and tangential problems of a kinematic call. With `short_tables` the strip
   !> tables end at kinematic_table_gap (a search of its own, cached apart from the full one).
   !> A vertical load is balanced by [[vertical_balance]]; `climbs` is set with its error when
   !> no equilibrium exists within the tables (the solver then holds the best state found).
   subroutine kinematic_contact(self, state, local, load, options, short_tables, climbs, error)
      type(contact_cache_type), intent(inout) :: self
      !> The state in the track frame and in the wheel's side frame.
      type(wheelset_state_type), intent(in) :: state, local
      type(contact_load_type), intent(in) :: load
      type(tangential_options_type), intent(in) :: options
      logical, intent(in) :: short_tables
      logical, intent(out) :: climbs
      type(error_type), allocatable, intent(out) :: error

      climbs = .false.
      if (load%mode == load_vertical_force) then
         call update_geometry(self, state%y_ws, state%roll, local%yaw, error, short_tables, &
            load%value)
      else
         call update_geometry(self, state%y_ws, state%roll, local%yaw, error, short_tables)
      end if
      if (allocated(error)) return
      if (load%mode == load_vertical_force) then
         ! Each solve of the balance starts the coupling's length iterations from the last
         ! one's; none from a solve before this call.
         call self%coupling_start%reset()
         self%warm_coupling = .true.
         call vertical_balance(self, local, load%value, options, climbs, error)
         self%warm_coupling = .false.
         return
      end if
      call update_normal(self, load, error)
      if (allocated(error)) return
      call kinematic_tangential(self, local, options, error)
   end subroutine kinematic_contact

   !> The vertical balance of a kinematic call: the rigid vertical approach Δz of the wheel at
   !> which the total vertical force, tangential forces included (as CONTACT's FZ), carries the
   !> load: C(Δz) = −Σ F_z,track = F_z to vertical_rtol.
   !>
   !> Every state is a function of Δz alone (normal problem at the vertical position Δz, then the
   !> tangential problem with the creepages at the loaded reference points), so the root is
   !> bracketed in Δz, not in the load: at the first touch Δz₀ nothing is carried (C = 0), and
   !> an upper end is found by growing Δz monotonically. On a flange (γ ≈ −70°) a patch carries
   !> only N(cos γ − μ sin γ) vertically, which nearly vanishes, so the load is a steep function
   !> of C and a load iteration diverges; in Δz the function stays well behaved. The residual is
   !> r = s(C) − s(F_z), s(c) = sign(|c|^{2/3}, c), nearly linear in Δz for a Hertzian
   !> contact; the root finder is the Illinois regula falsi on the bracket. The first points
   !> come from load steps: the normal problem alone carrying F_z (its coupled reduction only
   !> to predictor_tolerance, unless it nearly carries the load), then carrying F_z²/C (the
   !> tangential share taken proportional to the load), then the loads of the secant of ln C in
   !> ln q while each halves the miss (C/q varies slowly with q, also on the flange, where C(Δz)
   !> is far from linear). Every point found joins the bracket. No state of an earlier call is
   !> used (the coupled solves of one call start their length iterations from the last one's,
   !> shcontact_normal_coupling's coupling_start_type, emptied at the start of the call).
   !>
   !> C(Δz) is continuous (the normal force of a contact is a continuous function of the
   !> approach, and so are the tangential forces at fixed creepages; doc/kinematics.md), so the
   !> bracket always holds a root. Should the bracket close to round-off without meeting
   !> vertical_rtol (C jumping across F_z, a defect of the model), the call fails with
   !> stat_numerical and names the bracket: no state outside the tolerance is returned.
   !>
   !> If C stays below F_z up to the end of the strip tables (the contact cannot carry the load:
   !> friction on the flange lifts the wheel), `climbs` is set, the error has stat_no_contact
   !> and the reason, and the solver holds the state with the largest C found.
   subroutine vertical_balance(self, local, f_z, options, climbs, error)
      type(contact_cache_type), intent(inout) :: self
      !> The state in the wheel's side frame.
      type(wheelset_state_type), intent(in) :: local
      !> Vertical wheel load (N, > 0).
      real(wp), intent(in) :: f_z
      type(tangential_options_type), intent(in) :: options
      logical, intent(out) :: climbs
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: x_lo, r_lo, x_hi, r_hi, x, r, c, q, x_cap, x_best, c_best, step, tol, touch, &
         c_at_lo, c_at_hi, q_last, c_last, slope
      integer :: it, side
      logical :: bracketed

      climbs = .false.
      tol = vertical_rtol*f_z
      ! 1. The normal problem alone carrying F_z (the start from the geometry), a predictor
      !    (predictor_tolerance).
      self%coupling_start%tolerance = predictor_tolerance
      call update_normal(self, contact_load_type(load_vertical_force, f_z), error)
      self%coupling_start%tolerance = 0.0_wp
      if (allocated(error)) return
      call touch_and_reach(self, touch, x_cap)
      x_lo = touch
      c_at_lo = 0.0_wp
      c_at_hi = huge(1.0_wp)
      r_lo = -signed_23(f_z)
      x_best = x_lo
      c_best = -huge(1.0_wp)
      bracketed = .false.
      x_hi = x_cap
      r_hi = 0.0_wp
      x = self%dz
      call tangential_at(x, c, r, error)
      if (allocated(error)) return
      ! The predictor's normal solution is not a result: solved again to the full tolerance
      ! (warm, at the same Δz) where it nearly carries F_z, and never reused.
      self%has_normal = .false.
      if (abs(c - f_z) <= refine_margin*tol) then
         call tangential_at(x, c, r, error)
         if (allocated(error)) return
         if (abs(c - f_z) <= tol) return
      end if
      call keep(x, c, r)
      ! 2. The normal problem alone carrying the load q at which C(q) = F_z by the secant of
      !    ln C in ln q: C/q (the share the tangential forces and the strips' own contact
      !    angles add) varies slowly with q, so ln C is nearly linear in ln q with slope 1. The
      !    first step takes that slope (q = F_z²/C: the tangential share proportional to the
      !    load); the next ones the secant of the last two points, while each step at least
      !    halves the miss and its C̃ lies inside the bracket in Δz.
      q_last = f_z
      c_last = c
      slope = 1.0_wp
      do it = 2, max_load_steps
         if (.not. (c_last > 0.0_wp)) exit
         q = q_last*(f_z/c_last)**(1.0_wp/slope)
         if (it == 2) q = first_load_step(self, q_last, c_last, f_z)
         ! Δz guessed from the last solution by Hertz's δ ∝ q^{2/3} from the first touch.
         call update_normal(self, contact_load_type(load_vertical_force, q), error, &
            dz_guess=touch + (x - touch)*(q/q_last)**(2.0_wp/3.0_wp))
         if (allocated(error)) then
            if (error%stat /= stat_no_contact) return
            deallocate (error)
            exit
         end if
         x = self%dz
         if (.not. (x > x_lo .and. x < x_hi)) exit
         call tangential_at(x, c, r, error)
         if (allocated(error)) return
         if (abs(c - f_z) <= tol) return
         call keep(x, c, r)
         if (.not. (c > 0.0_wp .and. abs(c - f_z) < 0.5_wp*abs(c_last - f_z) .and. &
                    q /= q_last)) exit
         slope = log(c/c_last)/log(q/q_last)
         if (.not. (slope >= 0.25_wp .and. slope <= 4.0_wp)) exit
         q_last = q
         c_last = c
      end do
      ! 3. Grow Δz monotonically until C exceeds F_z (or the tables end).
      step = max(0.25_wp*(x_lo - touch), 1.0e-3_wp)
      do it = 1, max_vertical_iterations
         if (bracketed .or. .not. (x_lo < x_cap)) exit
         x = min(x_lo + step, x_cap)
         call tangential_at(x, c, r, error)
         if (allocated(error)) then
            if (error%stat /= stat_no_contact) return
            ! Beyond what the tables carry: the reach ends before x.
            deallocate (error)
            x_cap = x_lo + 0.5_wp*(x - x_lo)
            step = x_cap - x_lo
            if (step <= 1.0e-9_wp*max(x_cap, 1.0_wp)) exit
            cycle
         end if
         if (abs(c - f_z) <= tol) return
         call keep(x, c, r)
         step = 2.0_wp*step
      end do
      if (.not. bracketed) then
         ! No Δz within the tables carries F_z: leave the best state found.
         call tangential_at(x_best, c, r, error)
         if (allocated(error)) return
         climbs = .true.
         call fatal_error(error, 'vertical load '//str_real(f_z)//' N: no equilibrium, the '// &
            'wheel climbs: the contact carries at most '//str_real(c_best)//' N vertically '// &
            '(at the vertical approach '//str_real(x_best)//' mm, the end of the strip '// &
            'tables at '//str_real(x_cap)//' mm); the tangential forces on the flange lift '// &
            'the wheel', stat_no_contact)
         return
      end if
      ! 4. Illinois regula falsi on the bracket [x_lo, x_hi].
      side = 0
      do it = 1, 4*max_vertical_iterations
         x = x_hi - r_hi*(x_hi - x_lo)/(r_hi - r_lo)
         if (.not. (x > x_lo .and. x < x_hi)) x = 0.5_wp*(x_lo + x_hi)
         call tangential_at(x, c, r, error)
         if (allocated(error)) return
         if (abs(c - f_z) <= tol) return
         if (r > 0.0_wp) then
            x_hi = x
            r_hi = r
            c_at_hi = c
            if (side == 1) r_lo = 0.5_wp*r_lo
            side = 1
         else
            x_lo = x
            r_lo = r
            c_at_lo = c
            if (side == -1) r_hi = 0.5_wp*r_hi
            side = -1
         end if
         if (x_hi - x_lo <= 4.0_wp*spacing(x_hi)) exit
      end do
      ! The bracket closed without a root: C(Δz) jumps across F_z there (a defect of the model).
      if (abs(c_at_lo - f_z) <= abs(c_at_hi - f_z)) then
         c = c_at_lo
      else
         c = c_at_hi
      end if
      call fatal_error(error, 'vertical load matching with tangential forces did not '// &
         'converge: '//str_real(c)//' N instead of '//str_real(f_z)//' N (vertical approach '// &
         'bracketed in ['//str_real(x_lo)//', '//str_real(x_hi)//'] mm)', stat_numerical)
   contains
      !> The normal problem at the vertical position x (mm), the tangential problem, the
      !> vertical force carried c (N) and the residual r.
      subroutine tangential_at(x, c, r, error)
         real(wp), intent(in) :: x
         real(wp), intent(out) :: c, r
         type(error_type), allocatable, intent(out) :: error
         integer :: k
         c = 0.0_wp
         r = 0.0_wp
         if (.not. (self%has_normal .and. self%load%mode == load_vertical_force .and. &
                    same(self%dz, x))) then
            call update_normal(self, contact_load_type(load_vertical_position, x), error)
            if (allocated(error)) return
         end if
         call kinematic_tangential(self, local, options, error)
         if (allocated(error)) return
         do k = 1, self%n_loaded
            if (self%normal(k)%load > 0.0_wp) c = c - self%tangential(k)%fz_track
         end do
         r = signed_23(c) - signed_23(f_z)
      end subroutine tangential_at

      !> Record an evaluated point: the bracket ends and the best state.
      subroutine keep(x, c, r)
         real(wp), intent(in) :: x, c, r
         if (c > c_best) then
            c_best = c
            x_best = x
         end if
         if (r > 0.0_wp) then
            if (x < x_hi .or. .not. bracketed) then
               x_hi = x
               r_hi = r
               c_at_hi = c
            end if
            bracketed = .true.
         else if (x > x_lo) then
            x_lo = x
            r_lo = r
            c_at_lo = c
         end if
      end subroutine keep
   end subroutine vertical_balance

   !> Δz (mm) at which the first patch touches, and the largest Δz the strip tables of every
   !> patch reach (slightly inside it), for the patches prepared by a vertical load.
   pure subroutine touch_and_reach(self, touch, reach)
      type(contact_cache_type), intent(in) :: self
      real(wp), intent(out) :: touch, reach
      real(wp) :: cos_g
      integer :: k

      touch = huge(1.0_wp)
      reach = huge(1.0_wp)
      do k = 1, self%n_prepared
         associate (g => self%contacts(k)%geometry)
            cos_g = cos(g%gamma0)
            touch = min(touch, (g%approach_touch + g%gap0)/cos_g)
            if (g%has_strip_data) reach = min(reach, (g%approach_max + g%gap0)/cos_g)
         end associate
      end do
      touch = max(touch, 0.0_wp)
      if (reach < huge(1.0_wp)) then
         reach = touch + (reach - touch)*(1.0_wp - 1.0e-9_wp)
      else
         reach = touch + 10.0_wp
      end if
   end subroutine touch_and_reach

   !> The balance's second load q₂ from its first solution (the normal problem carrying q₁,
   !> with C₁ carried vertically): the load at which a model of C(q) built from that solution
   !> carries F_z. Each loaded patch k carries v_k = Σ N_i cos γ_i of q₁ (taken ∝ N_k cos γ₀,k
   !> and scaled so that Σ v_k = q₁) and t_k = C_k − v_k through its tangential forces. Under a
   !> further vertical approach x its normal force grows as Hertz's, N_k ∝ (1 + x/d_k)^{3/2}
   !> with d_k the vertical approach since its first touch, v_k in proportion to N_k, and t_k
   !> as N_k^{s_k}: at fixed creepages the tangential force grows as N^{2/3} while it is linear
   !> in the creepages (F ∝ G c² ν, c² ∝ N^{2/3}) and as N when saturated (F = μN); between,
   !> s_k = 1 − (1 − u)u²/f from the saturation law f = 1 − u³, u = 1 − ξ/3, ξ ∝ N^{−1/3}, at
   !> the patch's f = |F_t|/(μN). The root x of Σ(v_k + t_k) = F_z gives q₂ = Σ v_k(x). On
   !> one patch the normal part is exact in q, so only the tangential share's growth is
   !> modelled (the step F_z²/C₁ takes s = 1); on several patches the split of the load between
   !> them follows Hertz's law. Falls back to F_z²/C₁ where the model does not apply.
   function first_load_step(self, q1, c1, f_z) result(q2)
      type(contact_cache_type), intent(in) :: self
      !> The first load and what it carried vertically (N); the target (N).
      real(wp), intent(in) :: q1, c1, f_z
      real(wp) :: q2
      integer, parameter :: most = 8
      real(wp) :: v(most), t(most), d(most), s(most), f, u, sum_v, x, res, dres, r, dx, g0
      integer :: k, n, it

      q2 = f_z*(f_z/c1)
      n = 0
      sum_v = 0.0_wp
      do k = 1, self%n_loaded
         if (.not. (self%normal(k)%load > 0.0_wp)) cycle
         if (n == most .or. k > self%n_prepared) return
         n = n + 1
         g0 = self%contacts(k)%geometry%gamma0
         v(n) = self%normal(k)%load*cos(g0)
         t(n) = -self%tangential(k)%fz_track
         d(n) = (self%normal(k)%approach - self%contacts(k)%geometry%approach_touch)/cos(g0)
         f = min(hypot(self%tangential(k)%fx_norm, self%tangential(k)%fy_norm), 1.0_wp)
         if (f > 1.0e-6_wp) then
            u = (1.0_wp - f)**(1.0_wp/3.0_wp)
            s(n) = 1.0_wp - (1.0_wp - u)*u*u/f
         else
            s(n) = 2.0_wp/3.0_wp
         end if
         if (.not. (d(n) > 0.0_wp .and. v(n) > 0.0_wp)) return
         sum_v = sum_v + v(n)
      end do
      if (n == 0 .or. .not. (sum_v > 0.0_wp)) return
      v(1:n) = v(1:n)*(q1/sum_v)
      t(1:n) = t(1:n) - v(1:n)
      ! Newton on Σ_k v_k r_k + t_k r_k^{s_k} − F_z, r_k = (1 + x/d_k)^{3/2}, from x = 0.
      x = 0.0_wp
      do it = 1, 20
         res = -f_z
         dres = 0.0_wp
         do k = 1, n
            r = 1.0_wp + x/d(k)
            if (.not. (r > 0.0_wp)) return
            res = res + v(k)*r**1.5_wp + t(k)*r**(1.5_wp*s(k))
            dres = dres + (1.5_wp*v(k)*sqrt(r) + 1.5_wp*s(k)*t(k)*r**(1.5_wp*s(k) - 1.0_wp))/d(k)
         end do
         if (.not. (dres > 0.0_wp)) return
         dx = -res/dres
         x = x + dx
         if (abs(dx) <= 1.0e-12_wp*maxval(d(1:n))) exit
      end do
      if (abs(dx) > 1.0e-9_wp*maxval(d(1:n))) return
      r = 0.0_wp
      do k = 1, n
         if (.not. (1.0_wp + x/d(k) > 0.0_wp)) return
         r = r + v(k)*(1.0_wp + x/d(k))**1.5_wp
      end do
      if (r > 0.0_wp .and. c1 > 0.0_wp) q2 = r
   end function first_load_step

   !> sign(|c|^{2/3}, c): the load's power that is nearly linear in the approach.
   elemental real(wp) function signed_23(c)
      real(wp), intent(in) :: c
      signed_23 = sign(abs(c)**(2.0_wp/3.0_wp), c)
   end function signed_23

   !> The tangential problem of every loaded patch with the creepages of the wheelset's motion
   !> at its reference point: the geometric contact point of the loaded state (the normal
   !> solution's y_shift from the first contact along the contact plane, its rolling radius
   !> and contact angle; shcontact_normal_semihertz's refer_to_loaded_point). The point's axle
   !> coordinate moves by y_shift cos γ_plane from the first contact's.
   subroutine kinematic_tangential(self, local, options, error)
      type(contact_cache_type), intent(inout) :: self
      !> The state in the wheel's side frame.
      type(wheelset_state_type), intent(in) :: local
      type(tangential_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error
      type(contact_point_type) :: point
      type(creepage_type) :: creepage
      real(wp) :: speed
      integer :: k

      do k = 1, self%n_loaded
         if (.not. (self%normal(k)%load > 0.0_wp)) cycle
         point = contact_point_type(axle=reference_axle(self, k), radius=self%normal(k)%r0, &
            gamma=self%normal(k)%gamma0)
         call rigid_creepages(local, point, creepage, speed, error)
         if (allocated(error)) return
         call solve_patch(self, k, creepage, options, error)
         if (allocated(error)) return
      end do
   end subroutine kinematic_tangential

end module shcontact_pipeline_balance
