!> The geometry of one candidate contact patch, as the normal solver needs it (doc/theory.md §4.1,
!> §5.4): the gap and the curvatures as functions of the lateral coordinate in the contact plane.
module shcontact_geometry_patch
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: patch_geometry_type, geometry_sample_type

   !> Values of the patch geometry at one lateral position.
   type :: geometry_sample_type
      !> Gap g(y) along the reference normal, minus its minimum (mm, ≥ 0).
      real(wp) :: gap = 0.0_wp
      !> Longitudinal relative curvature A(y) (1/mm).
      real(wp) :: curv_a = 0.0_wp
      !> Lateral relative curvature B(y) = g''(y)/2, clamped to ≥ B_min (1/mm).
      real(wp) :: curv_b = 0.0_wp
      !> Local contact angle γ(y) (rad), CONTACT's sign: γ = atan(dz_rail/dy) in the track frame
      !> (z down, y to the field side), so the right wheel's tread contact has γ < 0 and
      !> dr_w/dy ≈ tan γ. (doc/theory.md §6.1's γ has the opposite sign: sin γ_§6.1 = −dr_w/dy.)
      real(wp) :: gamma = 0.0_wp
      !> Local wheel rolling radius r_w(y) (mm).
      real(wp) :: r_wheel = 0.0_wp
   end type geometry_sample_type

   !> One candidate patch: a reference (geometric contact) point and tables on a uniform grid in
   !> y, the lateral coordinate in the tangent plane at the reference point, measured from it
   !> (mm, towards the field side). The tables cover the basin of the gap minimum, wide enough
   !> for any load the patch can carry.
   type :: patch_geometry_type
      !> Reference point, lateral track coordinate (mm, from the track centre line).
      real(wp) :: y_track = 0.0_wp
      !> Reference point, vertical track coordinate (mm, down).
      real(wp) :: z_track = 0.0_wp
      !> Reference point on the rail profile, profile coordinates (mm).
      real(wp) :: y_rail = 0.0_wp
      !> Reference point on the wheel profile, profile coordinates (mm).
      real(wp) :: y_wheel = 0.0_wp
      !> Contact angle at the reference point γ₀ (rad), CONTACT's sign (see geometry_sample_type):
      !> Manchester right wheel at y_ws = 0 gives γ₀ = −0.0290.
      real(wp) :: gamma0 = 0.0_wp
      !> Wheel rolling radius at the reference point r₀ (mm).
      real(wp) :: r0 = 0.0_wp
      !> Smallest undeformed distance along the reference normal before any approach (mm);
      !> negative when the positioned profiles already interpenetrate.
      real(wp) :: gap0 = 0.0_wp
      !> Table spacing (mm).
      real(wp) :: h = 0.0_wp
      !> The patch's own basin, in table coordinates y (mm): the tables run on past a gap maximum
      !> that separates it from a neighbouring minimum (into the neighbour's basin, so that the
      !> patch can grow into it), and these mark those maxima; the table ends where there is none.
      !> The defaults (±huge) say "no neighbour".
      real(wp) :: basin_lower = -huge(1.0_wp)
      real(wp) :: basin_upper = huge(1.0_wp)
      !> The approach (mm) up to which the table holds every point that can touch: the bound of
      !> a kinematic call's first-try table, ended by the touch approach
      !> (shcontact_geometry_pair's table_reach); huge for a table ended by the gap.
      real(wp) :: touch_reach = huge(1.0_wp)
      !> Whether y is the rail's arc length and the gap is measured along each point's rail
      !> normal (a conformal table) rather than in the plane of the reference point.
      logical :: conformal = .false.
      !> Lateral coordinate of the table points (mm), uniform spacing h, y(i0) = 0.
      real(wp), allocatable :: y(:)
      !> g(y) ≥ 0 (mm).
      real(wp), allocatable :: gap(:)
      !> A(y) (1/mm).
      real(wp), allocatable :: curv_a(:)
      !> B(y) (1/mm), clamped to ≥ B_min.
      real(wp), allocatable :: curv_b(:)
      !> γ(y) (rad).
      real(wp), allocatable :: gamma(:)
      !> r_w(y) (mm).
      real(wp), allocatable :: r_wheel(:)
      !> tan γ(y), filled by the contact search from the profile slopes (so that no tangent is
      !> taken per point); a table built otherwise may leave it unallocated, and the normal
      !> preparation then takes tan γ itself (shcontact_normal_semihertz).
      real(wp), allocatable :: tan_gamma(:)
   contains
      !> Geometry at any y inside the table, linearly interpolated (clamped at the ends).
      procedure :: sample
      !> Rolling-radius variation δr(y) = r_w(y) − r₀ (mm).
      procedure :: delta_r
      !> Number of table points.
      procedure :: size => table_size
   end type patch_geometry_type

contains

   !> Number of table points.
   pure integer function table_size(self)
      class(patch_geometry_type), intent(in) :: self
      table_size = 0
      if (allocated(self%y)) table_size = size(self%y)
   end function table_size

   !> Linear interpolation of the tables at y; values at the nearest end outside the table.
   pure function sample(self, y) result(val)
      class(patch_geometry_type), intent(in) :: self
      !> Lateral coordinate from the reference point (mm).
      real(wp), intent(in) :: y
      type(geometry_sample_type) :: val
      integer :: i, n
      real(wp) :: t

      n = size(self%y)
      if (n == 1 .or. y <= self%y(1)) then
         i = 1; t = 0.0_wp
      else if (y >= self%y(n)) then
         i = n - 1; t = 1.0_wp
      else
         i = min(n - 1, 1 + int((y - self%y(1))/self%h))
         t = (y - self%y(i))/(self%y(i + 1) - self%y(i))
      end if
      if (n == 1) then
         val = geometry_sample_type(self%gap(1), self%curv_a(1), self%curv_b(1), self%gamma(1), &
            self%r_wheel(1))
         return
      end if
      val%gap = (1 - t)*self%gap(i) + t*self%gap(i + 1)
      val%curv_a = (1 - t)*self%curv_a(i) + t*self%curv_a(i + 1)
      val%curv_b = (1 - t)*self%curv_b(i) + t*self%curv_b(i + 1)
      val%gamma = (1 - t)*self%gamma(i) + t*self%gamma(i + 1)
      val%r_wheel = (1 - t)*self%r_wheel(i) + t*self%r_wheel(i + 1)
   end function sample

   !> δr(y) = r_w(y) − r₀ (mm).
   pure real(wp) function delta_r(self, y)
      class(patch_geometry_type), intent(in) :: self
      !> Lateral coordinate from the reference point (mm).
      real(wp), intent(in) :: y
      type(geometry_sample_type) :: val
      val = self%sample(y)
      delta_r = val%r_wheel - self%r0
   end function delta_r

end module shcontact_geometry_patch
