!> Rigid motions of the lateral (y, z) plane: how profiles are canted, placed on the track, rolled
!> and turned into the frame of a contact patch (doc/theory.md §5.3–5.4).
!>
!> A map sends X = (y, z) to R(angle)·X + d with R = [cos −sin; sin cos]. With z pointing down,
!> a positive angle turns +y towards +z: a point on the field side goes down.
module shcontact_geometry_rigid
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: rigid_map_type, rotation_about, translation, to_frame

   !> X ↦ R(angle) X + (dy, dz).
   type :: rigid_map_type
      !> Rotation angle (rad), positive from +y towards +z.
      real(wp) :: angle = 0.0_wp
      !> cos(angle), sin(angle), kept with the angle.
      real(wp) :: c = 1.0_wp, s = 0.0_wp
      !> Translation (mm).
      real(wp) :: dy = 0.0_wp, dz = 0.0_wp
   contains
      !> Image of a point.
      procedure :: point
      !> Images of many points, in one loop.
      procedure :: points
      !> Image of a direction (rotation only).
      procedure :: vector
      !> This map followed by another.
      procedure :: then
      !> The inverse map.
      procedure :: inverse
   end type rigid_map_type

contains

   !> A rotation by `angle` about (y0, z0).
   elemental type(rigid_map_type) function rotation_about(angle, y0, z0) result(map)
      !> Angle (rad), positive from +y towards +z.
      real(wp), intent(in) :: angle
      !> Centre of rotation (mm).
      real(wp), intent(in) :: y0, z0
      map = rigid_map_type(angle, cos(angle), sin(angle), 0.0_wp, 0.0_wp)
      map%dy = y0 - (map%c*y0 - map%s*z0)
      map%dz = z0 - (map%s*y0 + map%c*z0)
   end function rotation_about

   !> A translation by (dy, dz).
   elemental type(rigid_map_type) function translation(dy, dz) result(map)
      !> Shift (mm).
      real(wp), intent(in) :: dy, dz
      map = rigid_map_type(0.0_wp, 1.0_wp, 0.0_wp, dy, dz)
   end function translation

   !> The map into a frame whose origin is (y0, z0) and whose lateral axis makes the angle θ
   !> with +y: the plane is rotated by −θ about (y0, z0), which is then moved to the origin.
   !> A line through (y0, z0) with slope tan θ becomes the horizontal axis (doc/theory.md §5.4).
   elemental type(rigid_map_type) function to_frame(theta, y0, z0) result(map)
      !> Angle of the frame's lateral axis (rad).
      real(wp), intent(in) :: theta
      !> Frame origin (mm).
      real(wp), intent(in) :: y0, z0
      map = rigid_map_type(-theta, cos(theta), -sin(theta), 0.0_wp, 0.0_wp)
      map%dy = -(map%c*y0 - map%s*z0)
      map%dz = -(map%s*y0 + map%c*z0)
   end function to_frame

   !> Image of the point (y, z).
   elemental subroutine point(self, y, z, y1, z1)
      class(rigid_map_type), intent(in) :: self
      !> Point (mm).
      real(wp), intent(in) :: y, z
      !> Its image (mm).
      real(wp), intent(out) :: y1, z1
      y1 = self%c*y - self%s*z + self%dy
      z1 = self%s*y + self%c*z + self%dz
   end subroutine point

   !> Images of the points (y_i, z_i), the formula of [[point]] in one loop (the elemental
   !> binding, called on arrays, costs a call per point).
   pure subroutine points(self, y, z, y1, z1)
      class(rigid_map_type), intent(in) :: self
      !> Points (mm).
      real(wp), intent(in) :: y(:), z(:)
      !> Their images (mm; the size of y).
      real(wp), intent(out) :: y1(:), z1(:)
      integer :: i
      do i = 1, size(y)
         y1(i) = self%c*y(i) - self%s*z(i) + self%dy
         z1(i) = self%s*y(i) + self%c*z(i) + self%dz
      end do
   end subroutine points

   !> Image of the direction (vy, vz).
   elemental subroutine vector(self, vy, vz, wy, wz)
      class(rigid_map_type), intent(in) :: self
      !> Direction.
      real(wp), intent(in) :: vy, vz
      !> Its rotated image.
      real(wp), intent(out) :: wy, wz
      wy = self%c*vy - self%s*vz
      wz = self%s*vy + self%c*vz
   end subroutine vector

   !> `self` first, then `next`: X ↦ next(self(X)).
   elemental type(rigid_map_type) function then(self, next) result(map)
      class(rigid_map_type), intent(in) :: self
      !> The map applied second.
      type(rigid_map_type), intent(in) :: next
      map%angle = self%angle + next%angle
      map%c = next%c*self%c - next%s*self%s
      map%s = next%s*self%c + next%c*self%s
      call next%point(self%dy, self%dz, map%dy, map%dz)
   end function then

   !> The inverse map.
   elemental type(rigid_map_type) function inverse(self) result(map)
      class(rigid_map_type), intent(in) :: self
      real(wp) :: dy, dz
      map = rigid_map_type(-self%angle, self%c, -self%s, 0.0_wp, 0.0_wp)
      call map%vector(-self%dy, -self%dz, dy, dz)
      map%dy = dy
      map%dz = dz
   end function inverse

end module shcontact_geometry_rigid
