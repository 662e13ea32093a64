!> The yawed wheel profile at any yaw angle from a few prepared ones (issue 12: a wheelset that
!> yaws at every time step).
!>
!> The contact locus of a yawed wheel (shcontact_geometry_kinematics) moves every wheel point by
!> an even function of the yaw angle ψ, hence a smooth function of u = ψ². Its spline keeps the
!> unyawed knots, and an interpolating spline with fixed knots is linear in its points, so the
!> spline coefficients and the dense samples of the effective profile are smooth functions of u
!> too. [[build_yaw_table]] prepares the effective profile exactly at the nodes ψ_j of
!> [[yaw_nodes]] (once per wheel, at the first yawed call); [[apply_yaw]] then interpolates the
!> coefficients and the samples in u with the cubic Lagrange polynomial of the four nodes around
!> u — a few µs instead of a new fit and sampling of the whole wheel (~0.25 ms for the built-in
!> S1002's 1597 points). The test `kinematics/yaw_table_matches_direct_fit` bounds its error
!> against the direct fit.
module shcontact_geometry_yaw
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, prefix_error
   use shcontact_core_strings, only: str_real
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_track, only: track_type
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      prepare_wheel
   use shcontact_geometry_kinematics, only: yawed_wheel_profile
   use shcontact_geometry_prepared, only: box_pad
   implicit none
   private

   public :: yaw_table_type, build_yaw_table, apply_yaw, yaw_nodes

   !> Yaw angles ψ_j (rad) of the prepared effective profiles: dense where wheelsets run (≤ 10 mrad).
   real(wp), parameter :: yaw_nodes(*) = [0.0_wp, 0.0025_wp, 0.005_wp, 0.0075_wp, 0.01_wp, &
      0.0125_wp, 0.015_wp, 0.02_wp, 0.025_wp, 0.03_wp]
   !> The table serves |ψ| ≤ yaw_table_limit (rad); larger yaw angles (far beyond a running
   !> wheelset's) are prepared directly. On S1002 the interpolated samples and coefficients are
   !> within 2e-8 mm of the direct fit up to 10 mrad and 1.5e-5 mm up to 25 mrad.
   real(wp), parameter, public :: yaw_table_limit = 0.025_wp

   !> The effective wheel profile's spline coefficients and dense samples at every node.
   type :: yaw_table_type
      !> True once built.
      logical :: ready = .false.
      !> Spline coefficients cy(4, k, j), cz(4, k, j) of node j.
      real(wp), allocatable :: cy(:, :, :), cz(:, :, :)
      !> Dense samples y(i, j), z(i, j) of node j (at the unyawed wheel's sample parameters).
      real(wp), allocatable :: y(:, :), z(:, :)
      !> The bounds of the blocks of samples of node j, box(:, b, j) (prepared_profiles_type's
      !> `wheel_box`).
      real(wp), allocatable :: box(:, :, :)
   end type yaw_table_type

contains

   !> Prepare the effective wheel profile at every node, from the wheel profile as given and its
   !> unyawed preparation (whose knots and sample parameters every node keeps).
   subroutine build_yaw_table(wheel, unyawed, track, options, table, error)
      !> The wheel profile (right-side canonical form).
      type(profile_type), intent(in) :: wheel
      !> The profiles prepared without yaw.
      type(prepared_profiles_type), intent(in) :: unyawed
      !> Track and wheelset dimensions, and the contact-search options of `unyawed`.
      type(track_type), intent(in) :: track
      type(contact_options_type), intent(in) :: options
      !> The table (replaced).
      type(yaw_table_type), intent(inout) :: table
      !> Set when a yawed profile cannot be prepared.
      type(error_type), allocatable, intent(out) :: error
      type(prepared_profiles_type) :: node
      type(profile_type) :: locus
      type(contact_options_type) :: interpolate
      integer :: j, n_knots, n_samples

      table%ready = .false.
      n_knots = size(unyawed%wheel%cy, 2)
      n_samples = size(unyawed%wheel_y)
      if (allocated(table%cy)) deallocate (table%cy, table%cz, table%y, table%z, table%box)
      allocate (table%cy(4, n_knots, size(yaw_nodes)), table%cz(4, n_knots, size(yaw_nodes)), &
         table%y(n_samples, size(yaw_nodes)), table%z(n_samples, size(yaw_nodes)), &
         table%box(4, size(unyawed%wheel_box, 2), size(yaw_nodes)))
      interpolate = options
      interpolate%l_filt_wheel = 0.0_wp
      node = unyawed
      do j = 1, size(yaw_nodes)
         call yawed_wheel_profile(wheel, unyawed%wheel, track, unyawed%z_tape, yaw_nodes(j), &
            locus)
         call prepare_wheel(locus, track, interpolate, node, error)
         if (allocated(error)) then
            call prefix_error(error, 'yawed wheel (yaw '//str_real(yaw_nodes(j))//' rad)')
            return
         end if
         table%cy(:, :, j) = node%wheel%cy
         table%cz(:, :, j) = node%wheel%cz
         table%y(:, j) = node%wheel_y
         table%z(:, j) = node%wheel_z
         table%box(:, :, j) = node%wheel_box
      end do
      table%ready = .true.
   end subroutine build_yaw_table

   !> The effective wheel profile at yaw ψ (|ψ| ≤ yaw_table_limit) into `yawed`, a copy of the unyawed
   !> preparation: its wheel spline coefficients and samples interpolated in ψ² (nothing is
   !> allocated; the knots, sample parameters, tape circle and rail stay those of the copy), and
   !> bounds of its blocks of samples from those of the nodes.
   pure subroutine apply_yaw(table, yaw, yawed)
      !> The table from [[build_yaw_table]].
      type(yaw_table_type), intent(in) :: table
      !> Yaw angle of the side frame (rad).
      real(wp), intent(in) :: yaw
      !> The prepared profiles to update.
      type(prepared_profiles_type), intent(inout) :: yawed
      real(wp) :: u, nodes(4), weight(4)
      integer :: j0, j, m

      u = min(yaw*yaw, yaw_table_limit**2)
      j0 = 1
      do j = 2, size(yaw_nodes) - 1
         if (yaw_nodes(j)**2 <= u) j0 = j
      end do
      ! Four nodes around u, inside the table.
      j0 = max(1, min(size(yaw_nodes) - 3, j0 - 1))
      nodes = yaw_nodes(j0:j0 + 3)**2
      do m = 1, 4
         weight(m) = product(u - nodes, mask=[(j /= m, j=1, 4)])/ &
            product(nodes(m) - nodes, mask=[(j /= m, j=1, 4)])
      end do
      ! `yawed` is a copy of the table's unyawed preparation: the shapes agree (checked anyway).
      if (any(shape(yawed%wheel%cy) /= shape(table%cy(:, :, 1))) .or. &
         any(shape(yawed%wheel%cz) /= shape(table%cz(:, :, 1))) .or. &
         size(yawed%wheel_y) /= size(table%y, 1) .or. size(yawed%wheel_z) /= size(table%z, 1) &
         .or. any(shape(yawed%wheel_box) /= shape(table%box(:, :, 1)))) then
         yawed%wheel%cy = table%cy(:, :, 1)
         yawed%wheel%cz = table%cz(:, :, 1)
         yawed%wheel_y = table%y(:, 1)
         yawed%wheel_z = table%z(:, 1)
         yawed%wheel_box = table%box(:, :, 1)
      end if
      call combine(size(table%cy(:, :, 1)), weight, table%cy(:, :, j0), table%cy(:, :, j0 + 1), &
         table%cy(:, :, j0 + 2), table%cy(:, :, j0 + 3), yawed%wheel%cy)
      call combine(size(table%cz(:, :, 1)), weight, table%cz(:, :, j0), table%cz(:, :, j0 + 1), &
         table%cz(:, :, j0 + 2), table%cz(:, :, j0 + 3), yawed%wheel%cz)
      call combine(size(table%y, 1), weight, table%y(:, j0), table%y(:, j0 + 1), &
         table%y(:, j0 + 2), table%y(:, j0 + 3), yawed%wheel_y)
      call combine(size(table%z, 1), weight, table%z(:, j0), table%z(:, j0 + 1), &
         table%z(:, j0 + 2), table%z(:, j0 + 3), yawed%wheel_z)
      call combine_boxes(weight, table%box(:, :, j0:j0 + 3), yawed%wheel_box)
   end subroutine apply_yaw

   !> c = w₁a₁ + w₂a₂ + w₃a₃ + w₄a₄ over n values, one flat loop (the arrays are contiguous).
   pure subroutine combine(n, w, a1, a2, a3, a4, c)
      integer, intent(in) :: n
      real(wp), intent(in) :: w(4), a1(n), a2(n), a3(n), a4(n)
      real(wp), intent(inout) :: c(n)
      integer :: i
      do i = 1, n
         c(i) = w(1)*a1(i) + w(2)*a2(i) + w(3)*a3(i) + w(4)*a4(i)
      end do
   end subroutine combine

   !> Bounds of the blocks of Σ w_m x_m from the bounds of each x_m's blocks (interval
   !> arithmetic), widened by box_pad against round-off.
   pure subroutine combine_boxes(w, node_box, box)
      real(wp), intent(in) :: w(4), node_box(:, :, :)
      real(wp), intent(inout) :: box(:, :)
      integer :: b, c, m
      real(wp) :: lo, hi

      do b = 1, size(box, 2)
         do c = 1, 3, 2
            lo = 0.0_wp
            hi = 0.0_wp
            do m = 1, 4
               lo = lo + min(w(m)*node_box(c, b, m), w(m)*node_box(c + 1, b, m))
               hi = hi + max(w(m)*node_box(c, b, m), w(m)*node_box(c + 1, b, m))
            end do
            box(c, b) = lo - box_pad
            box(c + 1, b) = hi + box_pad
         end do
      end do
   end subroutine combine_boxes

end module shcontact_geometry_yaw
