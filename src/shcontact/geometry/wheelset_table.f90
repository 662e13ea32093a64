!> The rigid wheelset on the track: contact geometry of both wheels as a function of the lateral
!> shift y (doc/geometry.md, *Wheelset contact geometry and equivalent conicity*).
!>
!> For each shift the wheelset rolls until both wheels touch their rails: the right and the left
!> wheel are searched with the same profiles (the left one mirrored, as everywhere in the
!> library) at the same (y, φ), each lowered onto its rail by the contact search, and the roll φ
!> is the root of F(φ) = s_R(φ) − s_L(φ), the difference of the two vertical shifts of the
!> wheelset centre that make each wheel touch (a rigid axle has one centre). F falls by about
!> twice the half distance between the contact points per radian of roll, so Brent's method on a
!> bracket found by secant steps converges in a few contact searches.
!>
!> Each row gives, per wheel, the contact point on the rail (track y) and on the wheel (wheel
!> profile y), the rolling radius and the contact angle of the deepest patch, plus the roll and
!> Δr = r_R − r_L. Angles have the library's sign (side frame, z down: the tread of a new wheel
!> on a canted rail gives γ < 0 on both wheels, the flange about −1.2 rad).
module shcontact_geometry_wheelset_table
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_invalid_input
   use shcontact_math_roots, only: scalar_function_type, find_root
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type, side_right, &
      side_left, str => real_text
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_conicity, only: first_harmonic_slope, linear_value
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      contact_patches_type, prepare_profiles, find_contact_patches
   implicit none
   private

   public :: wheelset_contact_type, wheelset_geometry_table, wheelset_contact
   public :: roll_angle_parameter, contact_distance, centre_radius

   !> The contact geometry of the wheelset at one lateral shift.
   type :: wheelset_contact_type
      !> Lateral shift of the wheelset y (mm), CONTACT's Y_WS: towards the right rail.
      real(wp) :: y = 0.0_wp
      !> Roll of the wheelset φ (rad) with both wheels on their rails; positive lowers the right
      !> wheel (so φ < 0 for y > 0 on a new profile pair).
      real(wp) :: roll = 0.0_wp
      !> Vertical position of the wheelset centre (mm, z down) in the frame where the rail tops
      !> are at z = 0 and the centre of a wheel resting with its tape circle on the rail top
      !> would be at −r_nom.
      real(wp) :: z_centre = 0.0_wp
      !> Contact point on the rail, track y (mm, from the track centre line; < 0 on the left).
      real(wp) :: rail_y(2) = 0.0_wp
      !> Contact point on the wheel, wheel profile y (mm; the profile's own coordinates).
      real(wp) :: wheel_y(2) = 0.0_wp
      !> Rolling radius (mm).
      real(wp) :: radius(2) = 0.0_wp
      !> Contact angle γ (rad), side frame, CONTACT's sign (doc/geometry.md, *Conventions*).
      real(wp) :: gamma(2) = 0.0_wp
      !> Number of contact patches found on each wheel (2 or more: a second contact point
      !> within max_gap, e.g. tread and flange).
      integer :: patches(2) = 0
   contains
      !> Rolling-radius difference Δr = r_R − r_L (mm).
      procedure :: delta_r
   end type wheelset_contact_type

   !> Index of the right and the left wheel in the arrays of [[wheelset_contact_type]].
   integer, parameter :: right = 1, left = 2

   !> F(φ) = s_R(φ) − s_L(φ) for one lateral shift, with the storage of both searches.
   type, extends(scalar_function_type) :: roll_balance_type
      type(prepared_profiles_type), pointer :: prepared => null()
      real(wp) :: y = 0.0_wp
      type(contact_patches_type) :: work(2)
      type(error_type), allocatable :: error
   contains
      procedure :: eval => roll_balance
   end type roll_balance_type

   !> The wheelset geometry over a list of lateral shifts: from prepared profiles, or from raw
   !> profiles in one go.
   interface wheelset_geometry_table
      module procedure table_prepared
      module procedure table_raw
   end interface wheelset_geometry_table

contains

   !> Δr = r_R − r_L (mm).
   elemental real(wp) function delta_r(self)
      class(wheelset_contact_type), intent(in) :: self
      delta_r = self%radius(right) - self%radius(left)
   end function delta_r

   !> Distance between the two contact points e₀ = y_R − y_L (mm, track y) at y = 0 (the
   !> table interpolated linearly; its nearest end when it does not reach 0).
   pure real(wp) function contact_distance(table) result(e0)
      !> A table from [[wheelset_geometry_table]], y increasing.
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp) :: y(size(table)), e(size(table))
      y = table%y
      e = table%rail_y(right) - table%rail_y(left)
      e0 = linear_value(y, e, 0.0_wp)
   end function contact_distance

   !> Mean rolling radius r₀ = (r_R + r_L)/2 (mm) at y = 0 (as [[contact_distance]]).
   pure real(wp) function centre_radius(table) result(r0)
      !> A table from [[wheelset_geometry_table]], y increasing.
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp) :: y(size(table)), r(size(table))
      y = table%y
      r = 0.5_wp*(table%radius(right) + table%radius(left))
      r0 = linear_value(y, r, 0.0_wp)
   end function centre_radius

   !> Roll-angle parameter σ for the amplitude ŷ: φ ≈ −σ·y/(e₀/2), the roll φ(y) linearised by
   !> its first harmonic over y = ŷ sin θ like the conicity (e₀ from [[contact_distance]]). It is
   !> the slope of the roll relative to a rigid body turned about one contact point; σ > 0 when
   !> the wheel moving towards its flange rises.
   pure real(wp) function roll_angle_parameter(table, amplitude) result(sigma)
      !> A table from [[wheelset_geometry_table]], y increasing, covering ±amplitude.
      type(wheelset_contact_type), intent(in) :: table(:)
      !> Amplitude ŷ (mm), > 0.
      real(wp), intent(in) :: amplitude
      real(wp) :: y(size(table)), roll(size(table))
      y = table%y
      roll = table%roll
      sigma = -0.5_wp*contact_distance(table)*first_harmonic_slope(y, roll, amplitude)
   end function roll_angle_parameter

   !> The table from raw profiles (smoothing and placement as [[prepare_profiles]]).
   subroutine table_raw(wheel, rail, track, options, y, table, error)
      !> Wheel and rail profiles (right-side canonical form; the left side is their mirror).
      type(profile_type), intent(in) :: wheel, rail
      !> Track and wheelset dimensions.
      type(track_type), intent(in) :: track
      !> Contact search options.
      type(contact_options_type), intent(in) :: options
      !> Lateral shifts (mm).
      real(wp), intent(in) :: y(:)
      !> One row per shift.
      type(wheelset_contact_type), allocatable, intent(out) :: table(:)
      !> Set as [[prepare_profiles]] and [[table_prepared]] do.
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type), target :: prepared
      call prepare_profiles(wheel, rail, track, options, prepared, error)
      if (allocated(error)) return
      call table_prepared(prepared, y, table, error)
   end subroutine table_raw

   !> The table over the shifts y (in the order given; each search starts from the previous
   !> roll).
   subroutine table_prepared(prepared, y, table, error)
      !> Profiles from [[prepare_profiles]] (the same for both wheels).
      type(prepared_profiles_type), intent(in), target :: prepared
      !> Lateral shifts (mm).
      real(wp), intent(in) :: y(:)
      !> One row per shift.
      type(wheelset_contact_type), allocatable, intent(out) :: table(:)
      !> Set when a wheel does not touch its rail (stat_no_contact), on invalid input or when
      !> the roll does not converge (stat_numerical); the message names the shift.
      type(error_type), allocatable, intent(out) :: error
      type(roll_balance_type) :: balance
      real(wp) :: guess
      integer :: i

      allocate (table(size(y)))
      balance%prepared => prepared
      guess = 0.0_wp
      do i = 1, size(y)
         call solve_row(balance, y(i), guess, table(i), error)
         if (allocated(error)) then
            call prefix_error(error, 'wheelset at y = '//str(y(i))//' mm')
            deallocate (table)
            return
         end if
         guess = table(i)%roll
      end do
   end subroutine table_prepared

   !> The wheelset geometry at one shift.
   subroutine wheelset_contact(prepared, y, row, error)
      !> Profiles from [[prepare_profiles]].
      type(prepared_profiles_type), intent(in), target :: prepared
      !> Lateral shift (mm).
      real(wp), intent(in) :: y
      !> The contact geometry.
      type(wheelset_contact_type), intent(out) :: row
      !> As [[table_prepared]].
      type(error_type), allocatable, intent(out) :: error
      type(roll_balance_type) :: balance
      balance%prepared => prepared
      call solve_row(balance, y, 0.0_wp, row, error)
   end subroutine wheelset_contact

   !> Bracket the roll by secant steps from `guess`, refine it by Brent's method, and fill the
   !> row from the two searches at the root.
   subroutine solve_row(balance, y, guess, row, error)
      type(roll_balance_type), intent(inout) :: balance
      real(wp), intent(in) :: y, guess
      type(wheelset_contact_type), intent(out) :: row
      type(error_type), allocatable, intent(out) :: error
      !> Roll tolerance (rad): F changes by ~1.5 mm per mrad, so 1e-13 rad is ~1e-10 mm.
      real(wp), parameter :: roll_tol = 1.0e-13_wp
      real(wp) :: a, b, fa, fb, slope, phi, step
      integer :: k

      balance%y = y
      a = guess
      fa = balance%eval(a)
      if (allocated(balance%error)) then
         call move_alloc(balance%error, error)
         return
      end if
      ! dF/dφ ≈ −(distance between the contact points).
      slope = -(balance%work(right)%patch(1)%y_track - balance%work(left)%patch(1)%y_track)
      step = -fa/slope
      if (step == 0.0_wp) step = roll_tol
      b = a
      fb = fa
      do k = 1, 60
         b = a + 1.5_wp*step
         fb = balance%eval(b)
         if (allocated(balance%error)) then
            call move_alloc(balance%error, error)
            return
         end if
         if (sign(1.0_wp, fa) /= sign(1.0_wp, fb) .or. fb == 0.0_wp) exit
         a = b
         fa = fb
         step = 2.0_wp*step
      end do
      call find_root(balance, min(a, b), max(a, b), phi, error, xtol=roll_tol, &
         f_lower=merge(fa, fb, a < b), f_upper=merge(fb, fa, a < b))
      if (.not. allocated(error) .and. allocated(balance%error)) &
         call move_alloc(balance%error, error)
      if (allocated(error)) then
         call prefix_error(error, 'roll with both wheels on their rails')
         return
      end if
      ! The searches at the root itself (Brent's last evaluation may be elsewhere).
      fa = balance%eval(phi)
      if (allocated(balance%error)) then
         call move_alloc(balance%error, error)
         return
      end if
      row%y = y
      row%roll = phi
      row%z_centre = centre_height(balance%prepared, balance%work(right)%patch(1), side_right, &
         phi) - balance%prepared%track%nominal_radius
      call fill_wheel(balance%work(right), row, right)
      call fill_wheel(balance%work(left), row, left)
   end subroutine solve_row

   !> One wheel's columns from its deepest patch.
   pure subroutine fill_wheel(work, row, k)
      type(contact_patches_type), intent(in) :: work
      type(wheelset_contact_type), intent(inout) :: row
      integer, intent(in) :: k
      row%rail_y(k) = work%patch(1)%y_track
      row%wheel_y(k) = work%patch(1)%y_wheel
      row%radius(k) = work%patch(1)%r0
      row%gamma(k) = work%patch(1)%gamma0
      row%patches(k) = work%count
   end subroutine fill_wheel

   !> F(φ) = s_R(φ) − s_L(φ) (mm): the vertical shifts that make each wheel touch at roll φ.
   !> On a failed search the error is kept and 0 returned (which ends Brent's iteration).
   function roll_balance(self, x) result(fx)
      class(roll_balance_type), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      real(wp) :: s(2)
      integer :: k, side
      fx = 0.0_wp
      if (allocated(self%error)) return
      do k = right, left
         side = merge(side_right, side_left, k == right)
         call find_contact_patches(self%prepared, wheelset_position_type(side, self%y, x), &
            self%work(k), self%error)
         if (.not. allocated(self%error) .and. self%work(k)%count == 0) call fatal_error( &
            self%error, 'no contact patch found', stat_invalid_input)
         if (allocated(self%error)) then
            call prefix_error(self%error, trim(merge('right wheel', 'left wheel ', k == right)))
            return
         end if
         s(k) = centre_height(self%prepared, self%work(k)%patch(1), side, x)
      end do
      fx = s(right) - s(left)
   end function roll_balance

   !> The vertical shift (mm, down) of the wheelset centre that puts the wheel's contact point
   !> of `patch` on the rail, i.e. the shift the contact search applied: the wheel point
   !> (y_w, z_w) lies at v = (y_w + b/2 − y_fb, z_w + r_nom) from the roll centre in the wheel
   !> (b the flange-back distance, y_fb the flange-back position, z_w = r₀ − r_nom + z_tape), is
   !> turned by the side's roll θ = side·φ, and must meet the rail point z_track:
   !> shift = z_track − (−r_nom + sin θ·v_y + cos θ·v_z) (shcontact_geometry_track,
   !> wheel_placement).
   pure real(wp) function centre_height(prepared, patch, side, roll) result(shift)
      type(prepared_profiles_type), intent(in) :: prepared
      type(patch_geometry_type), intent(in) :: patch
      integer, intent(in) :: side
      real(wp), intent(in) :: roll
      real(wp) :: vy, vz, theta
      theta = side*roll
      vy = patch%y_wheel + 0.5_wp*prepared%track%flange_back_distance &
         - prepared%track%flange_back_position
      vz = patch%r0 + prepared%z_tape
      shift = patch%z_track - (-prepared%track%nominal_radius + sin(theta)*vy + cos(theta)*vz)
   end function centre_height

end module shcontact_geometry_wheelset_table
