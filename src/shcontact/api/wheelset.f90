!> Both wheels of a wheelset in one call (issue 12): the vehicle code's view of the contact, one
!> wheelset state in, the forces on each wheel and on the wheelset out.
!>
!> A [[wheelset_solver_type]] holds two [[contact_solver_type]] objects, the right wheel
!> (side_right) and the left one (side_left), created from the same profiles; [[solve]] runs the
!> kinematic call of each with the same wheelset state (each wheel's object mirrors it for the
!> left wheel, shcontact_geometry_kinematics) and its own load, then adds the forces in the true
!> track frame (x forward, y towards the right rail's field side, z down; forces on the
!> wheelset) and their moment about the vertical axis through the wheelset centre. The results
!> of each wheel stay in that wheel's side frame, as everywhere in the library (doc/api.md).
module shcontact_api_wheelset
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, prefix_error
   use shcontact_core_material, only: material_type
   use shcontact_core_ranges, only: find_range, ranges
   use shcontact_geometry_track, only: track_type, side_right, side_left
   use shcontact_geometry_contact, only: contact_options_type
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_geometry_kinematics, only: wheelset_state_type, check_wheelset_state
   use shcontact_normal_options, only: normal_options_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_api_solver, only: contact_solver_type, contact_load_type, contact_result_type, &
      load_vertical_force
   implicit none
   private

   public :: wheelset_solver_type, wheelset_result_type, wheel_right, wheel_left

   !> Index of the right and the left wheel in the arrays of this module.
   integer, parameter :: wheel_right = 1, wheel_left = 2
   !> Names of the wheels in messages, by index.
   character(len=5), parameter :: wheel_names(2) = ['right', 'left ']

   !> The result of one wheelset call.
   type :: wheelset_result_type
      !> Each wheel's result (its own side frame): wheel(wheel_right), wheel(wheel_left).
      type(contact_result_type) :: wheel(2)
      !> Total force on the wheelset, true track frame (N): longitudinal, lateral (towards the
      !> right rail's field side) and vertical (z down; about −(both wheel loads)).
      real(wp) :: fx = 0.0_wp, fy = 0.0_wp, fz = 0.0_wp
      !> Moment of the contact forces F_x, F_y about the vertical axis through the wheelset
      !> centre (N·mm, about +z, i.e. turning x towards y), from each patch's position
      !> (x_track, y_track − y_ws); the patches' spin moments are not included.
      real(wp) :: mz = 0.0_wp
   end type wheelset_result_type

   !> The two wheels of one wheelset.
   type :: wheelset_solver_type
      private
      type(contact_solver_type) :: wheel(2)
   contains
      !> Create both wheels from profile names (`builtin:NAME` or files).
      procedure :: init
      !> Solve both wheels for one wheelset state.
      procedure :: solve
      !> The track the wheels took (a MiniProf wheel's flange back at 0 when none was given).
      procedure :: get_track
      !> Change G, ν and μ of both wheels (as contact_solver_type%set_material).
      procedure :: set_material
      !> Change the track or the contact-search options of both wheels (as
      !> contact_solver_type%set_track: the profiles as first read are prepared again).
      procedure :: set_track
      !> Change the normal and tangential options of both wheels (as
      !> contact_solver_type%set_options).
      procedure :: set_options
   end type wheelset_solver_type

contains

   !> Create the right and the left wheel from the same profiles and data (see
   !> contact_solver_type%init).
   subroutine init(self, wheel, rail, error, track, material, contact_options, normal_options, &
         tangential_options)
      !> The wheelset (any earlier content is replaced).
      class(wheelset_solver_type), intent(inout) :: self
      !> Wheel and rail profile (right-side canonical form; the left wheel is the mirror image).
      character(len=*), intent(in) :: wheel, rail
      !> Set when a wheel cannot be created; the message names it.
      type(error_type), allocatable, intent(out) :: error
      !> As contact_solver_type%init.
      type(track_type), intent(in), optional :: track
      type(material_type), intent(in), optional :: material
      type(contact_options_type), intent(in), optional :: contact_options
      type(normal_options_type), intent(in), optional :: normal_options
      type(tangential_options_type), intent(in), optional :: tangential_options
      integer :: k
      integer, parameter :: sides(2) = [side_right, side_left]

      do k = 1, 2
         call self%wheel(k)%init(wheel, rail, error, track=track, material=material, &
            side=sides(k), contact_options=contact_options, normal_options=normal_options, &
            tangential_options=tangential_options)
         if (allocated(error)) then
            call prefix_error(error, trim(wheel_names(k))//' wheel')
            return
         end if
      end do
   end subroutine init

   !> The track and wheelset dimensions the wheels took ([[init]]; the right wheel's, the left
   !> wheel's differing only in its side).
   pure function get_track(self) result(track)
      !> The wheelset.
      class(wheelset_solver_type), intent(in) :: self
      type(track_type) :: track
      track = self%wheel(1)%get_track()
   end function get_track

   !> Change G, ν and μ of both wheels, as contact_solver_type%set_material does for one: the
   !> prepared profiles stay (nothing is read again). Checked on the first wheel; nothing
   !> changes on error.
   subroutine set_material(self, material, error)
      !> The wheelset, from [[init]].
      class(wheelset_solver_type), intent(inout) :: self
      !> The new data.
      type(material_type), intent(in) :: material
      !> Set for non-physical data.
      type(error_type), allocatable, intent(out) :: error
      call self%wheel(1)%set_material(material, error)
      if (.not. allocated(error)) call self%wheel(2)%set_material(material, error)
   end subroutine set_material

   !> Change the track and/or the contact-search options of both wheels; the profiles are not
   !> read again. On error the caller discards the wheelset (a wheel may have changed).
   subroutine set_track(self, error, track, contact_options)
      !> The wheelset, from [[init]].
      class(wheelset_solver_type), intent(inout) :: self
      !> Set for invalid data.
      type(error_type), allocatable, intent(out) :: error
      !> The new track (right-side form, as given to [[init]]).
      type(track_type), intent(in), optional :: track
      !> The new contact-search options.
      type(contact_options_type), intent(in), optional :: contact_options
      integer :: k
      do k = 1, size(self%wheel)
         call self%wheel(k)%set_track(error, track=track, contact_options=contact_options)
         if (allocated(error)) return
      end do
   end subroutine set_track

   !> Change the normal and/or tangential options of both wheels. On error the caller discards
   !> the wheelset (a wheel may have changed).
   subroutine set_options(self, error, normal, tangential)
      !> The wheelset, from [[init]].
      class(wheelset_solver_type), intent(inout) :: self
      !> Set for invalid options.
      type(error_type), allocatable, intent(out) :: error
      !> The new options.
      type(normal_options_type), intent(in), optional :: normal
      type(tangential_options_type), intent(in), optional :: tangential
      integer :: k
      do k = 1, size(self%wheel)
         call self%wheel(k)%set_options(error, normal=normal, tangential=tangential)
         if (allocated(error)) return
      end do
   end subroutine set_options

   !> Solve both wheels for the wheelset state (track frame) and add up the forces.
   subroutine solve(self, state, load_right, load_left, result, error)
      !> The wheelset, from [[init]].
      class(wheelset_solver_type), intent(inout) :: self
      !> Wheelset position and velocities (track frame).
      type(wheelset_state_type), intent(in) :: state
      !> The load of each wheel (load_vertical_force: its total vertical force). A vertical
      !> force below 1 N (0 or less included) lifts the wheel: no contact, its result all
      !> zeros (n_patches 0), the other wheel solved as usual.
      type(contact_load_type), intent(in) :: load_right, load_left
      !> Both wheels and the totals.
      type(wheelset_result_type), intent(out) :: result
      !> Set when a wheel's call fails; the message names the wheel.
      type(error_type), allocatable, intent(out) :: error
      integer :: k, p
      real(wp) :: side, fy

      call check_wheelset_state(state, error)
      if (allocated(error)) return
      do k = 1, 2
         if (k == wheel_right) then
            if (lifted(load_right)) cycle
            call self%wheel(k)%solve_kinematic(state, load_right, result%wheel(k), error)
         else
            if (lifted(load_left)) cycle
            call self%wheel(k)%solve_kinematic(state, load_left, result%wheel(k), error)
         end if
         if (allocated(error)) then
            call prefix_error(error, trim(wheel_names(k))//' wheel')
            return
         end if
      end do
      do k = 1, 2
         side = merge(1.0_wp, -1.0_wp, k == wheel_right)
         associate (w => result%wheel(k))
            result%fx = result%fx + w%track%fx
            result%fy = result%fy + side*w%track%fy
            result%fz = result%fz + w%track%fz
            do p = 1, w%n_loaded
               if (.not. (w%patch(p)%fn > 0.0_wp)) cycle
               fy = side*w%patch(p)%fy_track
               result%mz = result%mz + w%patch(p)%x_track*fy &
                  - (w%patch(p)%y_track - state%y_ws)*w%patch(p)%fx
            end do
         end associate
      end do
   end subroutine solve

   !> A wheel lifted off its rail by the vehicle code: a finite vertical load below the
   !> smallest one the contact is solved for (the lower bound of `load%vertical_force`, 1 N),
   !> so that a wheel unloading smoothly through 0 passes from solved to lifted without a
   !> failed call in between (0.5 N failed both wheels with status 2).
   pure logical function lifted(load)
      type(contact_load_type), intent(in) :: load
      integer :: k
      lifted = load%mode == load_vertical_force .and. ieee_is_finite(load%value)
      if (.not. lifted) return
      k = find_range('load%vertical_force')
      lifted = load%value < ranges(k)%lo
   end function lifted

end module shcontact_api_wheelset
