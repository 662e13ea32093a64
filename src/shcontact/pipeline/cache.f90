!> The stages of one wheel–rail contact and their cache: the contact search at a position
!> ([[update_geometry]], yawed profiles by [[prepare_yaw]]), the normal problem for a load
!> ([[update_normal]]), the tangential problem of a patch ([[solve_patch]]) and the summary
!> ([[summarise]]). [[contact_cache_type]] keeps the last geometry and normal solution with their
!> keys, so a call that repeats them reuses them.
module shcontact_pipeline_cache
   use shcontact_core_kinds, only: wp, i8
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_no_contact, &
      stat_usage
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_track, only: track_type, wheelset_position_type, side_right
   use shcontact_geometry_contact, only: contact_options_type, prepared_profiles_type, &
      contact_patches_type, find_contact_patches, extract_patch, prepare_wheel
   use shcontact_geometry_yaw, only: yaw_table_type, build_yaw_table, apply_yaw, yaw_table_limit
   use shcontact_geometry_flange, only: climbing_margin
   use shcontact_geometry_kinematics, only: yawed_wheel_profile, axle_offset, true_radius_scale, &
      scale_to_true_radius
   use shcontact_normal_options, only: normal_options_type
   use shcontact_normal_loading, only: normal_contact_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_coupling, only: coupling_start_type
   use shcontact_tangential_options, only: tangential_options_type, surface_interface
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_pipeline_load, only: contact_load_type
   use shcontact_pipeline_result, only: contact_result_type, contact_fields_type, max_patches
   use shcontact_pipeline_stages, only: loaded_count, prepare_normal_stage, solve_normal_stage, &
      solve_patch_stage, reference_axle_of, summarise_stages
   implicit none
   private

   public :: contact_cache_type, update_geometry, update_normal, solve_patch, reference_axle, &
      summarise, copy_fields, same, forget_normal

   !> One wheel–rail contact: its data, its prepared geometry, the stage results of the last
   !> call (with their keys) and all its workspace.
   type :: contact_cache_type
      !> The profiles as given (kept to prepare again when the track changes).
      type(profile_type) :: wheel, rail
      !> Track, side, material and options.
      type(track_type) :: track
      type(contact_options_type) :: contact_options
      integer :: side = side_right
      type(material_type) :: material
      type(normal_options_type) :: normal_options
      type(tangential_options_type) :: tangential_options
      !> Profiles ready for the contact search.
      type(prepared_profiles_type) :: prepared
      !> The profiles prepared for the yaw angle `yaw` (side frame) of the last kinematic call:
      !> the wheel replaced by its contact locus (shcontact_geometry_kinematics).
      type(prepared_profiles_type) :: yawed
      logical :: has_yawed = .false.
      !> Effective wheel profiles at the yaw nodes (built at the first yawed call).
      type(yaw_table_type) :: yaw_table
      real(wp) :: yawed_angle = 0.0_wp
      !> Geometry of the last position (valid when has_geometry).
      logical :: has_geometry = .false.
      real(wp) :: t_y = 0.0_wp, roll = 0.0_wp, yaw = 0.0_wp
      !> The strip tables end at the options' kinematic_table_gap (a kinematic call's first try).
      logical :: short_tables = .false.
      !> The vertical load the first-try tables were bounded by (N; 0: none).
      real(wp) :: reach_load = 0.0_wp
      type(contact_patches_type) :: patches
      !> Patches whose normal problem is prepared for this geometry.
      integer :: n_prepared = 0
      type(normal_contact_type) :: contacts(max_patches)
      !> Normal solution of the last load (valid when has_normal).
      logical :: has_normal = .false.
      !> A vertical load of that solution was carried by the strips' vertical force.
      logical :: strips_balanced = .false.
      type(contact_load_type) :: load
      integer :: n_loaded = 0
      real(wp) :: dz = 0.0_wp
      type(normal_patch_type) :: normal(max_patches)
      !> While `warm_coupling` (the vertical balance of one kinematic call, which empties
      !> `coupling_start` first), each coupled normal solve starts its length iterations where
      !> the last one ended (shcontact_normal_coupling's coupling_start_type).
      logical :: warm_coupling = .false.
      type(coupling_start_type) :: coupling_start
      !> Tangential workspace and solutions.
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: tangential(max_patches)
      !> Creepages of each solved patch at its reference point.
      type(creepage_type) :: creepage(max_patches)
   end type contact_cache_type

contains

   !> The contact patches at (t_y, roll, yaw), unless they are those of the last call. With a yaw
   !> angle the search runs on the yawed wheel's contact locus (profiles prepared once per yaw
   !> angle, [[prepare_yaw]]); the table's rolling radii are then turned back into the true
   !> ones, and each reference point gets its longitudinal lead.
   subroutine update_geometry(self, t_y, roll, yaw, error, short_tables, reach_load)
      type(contact_cache_type), intent(inout) :: self
      !> Lateral shift (mm) and roll (rad), track frame.
      real(wp), intent(in) :: t_y, roll
      !> Yaw angle of the side frame (rad).
      real(wp), intent(in) :: yaw
      type(error_type), allocatable, intent(out) :: error
      !> Strip tables to kinematic_table_gap at most (default: the options' table_gap).
      logical, intent(in), optional :: short_tables
      !> With short_tables: the vertical wheel load (N) from which each patch's first-try table
      !> takes its bound (shcontact_geometry_pair's load_reach); absent or 0: kinematic_table_gap.
      real(wp), intent(in), optional :: reach_load
      type(wheelset_position_type) :: position
      real(wp) :: table_gap, sin_yaw, load
      logical :: short
      integer :: k

      short = .false.
      if (present(short_tables)) short = short_tables
      load = 0.0_wp
      if (short .and. present(reach_load)) load = reach_load
      if (self%has_geometry .and. same(t_y, self%t_y) .and. same(roll, self%roll) .and. &
         same(yaw, self%yaw) .and. (short .eqv. self%short_tables) .and. &
         same(load, self%reach_load)) return
      self%has_geometry = .false.
      self%has_normal = .false.
      self%n_prepared = 0
      position = wheelset_position_type(side=self%side, y_ws=t_y, roll=roll)
      if (yaw == 0.0_wp) then
         table_gap = self%prepared%options%table_gap
         if (short) self%prepared%options%table_gap = min(table_gap, &
            self%prepared%options%kinematic_table_gap)
         self%prepared%table_end_by_touch = short
         self%prepared%reach_load = load
         self%prepared%reach_modulus = self%material%e_star()
         call find_contact_patches(self%prepared, position, self%patches, error)
         self%prepared%table_end_by_touch = .false.
         self%prepared%reach_load = 0.0_wp
         self%prepared%options%table_gap = table_gap
      else
         call prepare_yaw(self, yaw, error)
         if (allocated(error)) return
         table_gap = self%yawed%options%table_gap
         if (short) self%yawed%options%table_gap = min(table_gap, &
            self%yawed%options%kinematic_table_gap)
         self%yawed%table_end_by_touch = short
         self%yawed%reach_load = load
         self%yawed%reach_modulus = self%material%e_star()
         call find_contact_patches(self%yawed, position, self%patches, error)
         self%yawed%table_end_by_touch = .false.
         self%yawed%reach_load = 0.0_wp
         self%yawed%options%table_gap = table_gap
      end if
      if (allocated(error)) return
      if (self%patches%count < 1) then
         call fatal_error(error, 'contact search at t_y = '//str_real(t_y)//' mm, roll = '// &
            str_real(roll)//' rad: no contact patch found', stat_no_contact)
         return
      end if
      if (self%patches%count > max_patches) then
         call fatal_error(error, 'contact search: '//str_int(self%patches%count)// &
            ' patches; the solver holds at most '//str_int(max_patches), stat_usage)
         return
      end if
      if (yaw /= 0.0_wp) then
         sin_yaw = sin(yaw)
         do k = 1, self%patches%count
            associate (g => self%patches%patch(k), n => self%patches%points(k))
               call scale_to_true_radius(g%tan_gamma(1:n), sin_yaw, g%r_wheel(1:n))
               g%r0 = g%r0*true_radius_scale(g%gamma0, sin_yaw)
            end associate
         end do
      end if
      self%t_y = t_y
      self%roll = roll
      self%yaw = yaw
      self%short_tables = short
      self%reach_load = load
      self%has_geometry = .true.
   end subroutine update_geometry

   !> Prepare the profiles for a yaw angle (side frame): the wheel replaced by its contact locus
   !> (shcontact_geometry_kinematics), interpolated in ψ² from the effective profiles prepared
   !> at a few yaw angles at the first yawed call (shcontact_geometry_yaw; beyond its
   !> yaw_table_limit prepared directly), with the unyawed tape
   !> circle height, so that the table's rolling radius is r cos θ.
   subroutine prepare_yaw(self, yaw, error)
      type(contact_cache_type), intent(inout) :: self
      real(wp), intent(in) :: yaw
      type(error_type), allocatable, intent(out) :: error
      type(profile_type) :: locus
      type(contact_options_type) :: options

      if (self%has_yawed .and. same(yaw, self%yawed_angle)) return
      if (.not. self%has_yawed) self%yawed = self%prepared
      self%has_yawed = .false.
      if (abs(yaw) <= yaw_table_limit) then
         if (.not. self%yaw_table%ready) then
            call build_yaw_table(self%wheel, self%prepared, self%track, self%contact_options, &
               self%yaw_table, error)
            if (allocated(error)) return
         end if
         call apply_yaw(self%yaw_table, yaw, self%yawed)
      else
         call yawed_wheel_profile(self%wheel, self%prepared%wheel, self%track, &
            self%prepared%z_tape, yaw, locus)
         options = self%contact_options
         options%l_filt_wheel = 0.0_wp
         call prepare_wheel(locus, self%track, options, self%yawed, error)
         if (allocated(error)) then
            call prefix_error(error, 'yawed wheel (yaw '//str_real(yaw)//' rad)')
            return
         end if
      end if
      self%yawed%z_tape = self%prepared%z_tape
      self%yawed_angle = yaw
      self%has_yawed = .true.
   end subroutine prepare_yaw

   !> The normal solution for the load, unless it is that of the last call on this geometry.
   !> Force and approach load the first (deepest) patch, a vertical load all patches, a shared
   !> normal force those that touch (shcontact_pipeline_stages's solve_normal_stage).
   subroutine update_normal(self, load, error, dz_guess, strips)
      type(contact_cache_type), intent(inout) :: self
      type(contact_load_type), intent(in) :: load
      type(error_type), allocatable, intent(out) :: error
      !> A close guess of the vertical approach Δz (mm) for a vertical load.
      real(wp), intent(in), optional :: dz_guess
      !> A vertical load carried by the strips' vertical force (solve_normal_stage's `strips`;
      !> the one-wheel calls).
      logical, intent(in), optional :: strips
      integer :: n, used
      logical :: by_strips

      by_strips = .false.
      if (present(strips)) by_strips = strips
      if (self%has_normal .and. load%mode == self%load%mode .and. &
         same(load%value, self%load%value) .and. (self%strips_balanced .eqv. by_strips)) return
      self%has_normal = .false.
      n = loaded_count(load, self%patches%count)
      call prepare_normal_stage(self%patches%patch, self%normal_options, self%material, &
         self%contacts, self%n_prepared, n, error, self%patches%points, interface= &
         self%tangential_options%contact_surface == surface_interface)
      if (allocated(error)) return
      if (self%warm_coupling) then
         call solve_normal_stage(self%contacts(1:n), load, self%normal(1:n), self%dz, error, &
            self%coupling_start, used=used, dz_guess=dz_guess, strips=by_strips)
      else
         call solve_normal_stage(self%contacts(1:n), load, self%normal(1:n), self%dz, error, &
            used=used, dz_guess=dz_guess, strips=by_strips)
      end if
      if (allocated(error)) return
      self%load = load
      self%strips_balanced = by_strips
      self%n_loaded = used
      self%has_normal = .true.
   end subroutine update_normal

   !> The tangential problem of loaded patch k for its creepages.
   subroutine solve_patch(self, k, creepage, options, error)
      type(contact_cache_type), intent(inout) :: self
      integer, intent(in) :: k
      type(creepage_type), intent(in) :: creepage
      type(tangential_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error

      if (.not. (self%normal(k)%load > 0.0_wp)) return
      call solve_patch_stage(self%ws, self%normal(k), self%material, creepage, options, &
         self%tangential(k), k, self%n_loaded, error)
      if (allocated(error)) return
      self%creepage(k) = creepage
   end subroutine solve_patch

   !> Axle coordinate L (mm) of loaded patch k's reference point (shcontact_pipeline_stages).
   pure real(wp) function reference_axle(self, k) result(axle)
      type(contact_cache_type), intent(in) :: self
      integer, intent(in) :: k
      axle = reference_axle_of(self%patches%patch(k), axle_offset(self%track), self%normal(k))
   end function reference_axle

   !> The result of the last call: the summary stage (shcontact_pipeline_stages) of the cached
   !> stage results, with the wheel's joined contact (doc/lobes.md).
   pure subroutine summarise(self, result)
      type(contact_cache_type), intent(in) :: self
      type(contact_result_type), intent(inout) :: result
      integer :: n

      n = self%n_loaded
      call summarise_stages(self%patches%patch(1:self%patches%count), self%normal(1:n), &
         self%tangential(1:n), self%creepage(1:n), self%side, axle_offset(self%track), &
         self%yaw, self%dz, self%material%friction, result, self%patches%points(1:n))
      result%climbing = result%n_loaded > 0 .and. &
         result%main%r0 > self%prepared%steep_end_radius + climbing_margin
   end subroutine summarise

   !> Copy the fields of the loaded patches, reusing the arrays of `fields`.
   pure subroutine copy_fields(self, fields)
      type(contact_cache_type), intent(in) :: self
      type(contact_fields_type), intent(inout) :: fields
      integer :: k

      fields%n_patches = self%n_loaded
      do k = 1, self%n_loaded
         call extract_patch(self%patches, k, fields%geometry(k))
         call copy_normal(self%normal(k), fields%normal(k))
         if (self%normal(k)%load > 0.0_wp) then
            call copy_tangential(self%tangential(k), fields%tangential(k))
         else
            fields%tangential(k)%nx = 0
            fields%tangential(k)%ny = 0
         end if
      end do
   end subroutine copy_fields

   !> Copy a normal solution into reused arrays.
   pure subroutine copy_normal(src, dst)
      type(normal_patch_type), intent(in) :: src
      type(normal_patch_type), intent(inout) :: dst
      dst%n_strips = src%n_strips
      dst%is_hertz = src%is_hertz
      dst%ellipse_a = src%ellipse_a
      dst%ellipse_b = src%ellipse_b
      dst%ellipse_y_centre = src%ellipse_y_centre
      dst%approach = src%approach
      dst%approach_reference = src%approach_reference
      dst%load = src%load
      dst%area = src%area
      dst%p_max = src%p_max
      dst%dy = src%dy
      dst%gamma0 = src%gamma0
      dst%r0 = src%r0
      dst%y_shift = src%y_shift
      dst%gamma_plane = src%gamma_plane
      dst%conformal = src%conformal
      call copy_vector(src%y, dst%y)
      call copy_vector(src%a, dst%a)
      call copy_vector(src%k, dst%k)
      call copy_vector(src%p0, dst%p0)
      call copy_vector(src%strip_load, dst%strip_load)
      call copy_vector(src%m, dst%m)
      call copy_vector(src%n, dst%n)
      call copy_vector(src%eps_a, dst%eps_a)
      call copy_vector(src%gamma, dst%gamma)
      call copy_vector(src%gamma_n, dst%gamma_n)
      call copy_vector(src%delta_r, dst%delta_r)
      call copy_vector(src%r_wheel, dst%r_wheel)
   end subroutine copy_normal

   !> Copy a tangential solution into reused arrays.
   pure subroutine copy_tangential(src, dst)
      type(tangential_patch_type), intent(in) :: src
      type(tangential_patch_type), intent(inout) :: dst
      dst%nx = src%nx
      dst%ny = src%ny
      dst%fx = src%fx
      dst%fy = src%fy
      dst%mz = src%mz
      dst%fn = src%fn
      dst%fx_norm = src%fx_norm
      dst%fy_norm = src%fy_norm
      dst%coulomb_ratio = src%coulomb_ratio
      dst%adhesion_fraction = src%adhesion_fraction
      dst%parabolic_load_ratio = src%parabolic_load_ratio
      dst%fy_track = src%fy_track
      dst%fz_track = src%fz_track
      dst%dy = src%dy
      call copy_matrix(src%x, dst%x)
      call copy_vector(src%y, dst%y)
      call copy_vector(src%dx, dst%dx)
      call copy_matrix(src%pn, dst%pn)
      call copy_matrix(src%px, dst%px)
      call copy_matrix(src%py, dst%py)
      call copy_matrix(src%slip, dst%slip)
      if (.not. allocated(src%state)) then
         if (allocated(dst%state)) deallocate (dst%state)
         return
      end if
      if (allocated(dst%state)) then
         if (any(shape(dst%state) /= shape(src%state))) deallocate (dst%state)
      end if
      if (.not. allocated(dst%state)) allocate (dst%state(size(src%state, 1), &
         size(src%state, 2)))
      dst%state(:, :) = src%state
   end subroutine copy_tangential

   !> dst(:) = src, reallocating dst only when its size differs (or src is unallocated).
   pure subroutine copy_vector(src, dst)
      real(wp), allocatable, intent(in) :: src(:)
      real(wp), allocatable, intent(inout) :: dst(:)
      if (.not. allocated(src)) then
         if (allocated(dst)) deallocate (dst)
         return
      end if
      if (allocated(dst)) then
         if (size(dst) /= size(src)) deallocate (dst)
      end if
      if (.not. allocated(dst)) allocate (dst(size(src)))
      dst(:) = src
   end subroutine copy_vector

   !> dst(:, :) = src, reallocating dst only when its shape differs (or src is unallocated).
   pure subroutine copy_matrix(src, dst)
      real(wp), allocatable, intent(in) :: src(:, :)
      real(wp), allocatable, intent(inout) :: dst(:, :)
      if (.not. allocated(src)) then
         if (allocated(dst)) deallocate (dst)
         return
      end if
      if (allocated(dst)) then
         if (any(shape(dst) /= shape(src))) deallocate (dst)
      end if
      if (.not. allocated(dst)) allocate (dst(size(src, 1), size(src, 2)))
      dst(:, :) = src
   end subroutine copy_matrix

   !> Bitwise equality: the cache keys of the last call are reused only for the very same input.
   elemental logical function same(a, b)
      real(wp), intent(in) :: a, b
      same = transfer(a, 0_i8) == transfer(b, 0_i8)
   end function same

   !> The normal problem must be prepared and solved again.
   pure subroutine forget_normal(self)
      type(contact_cache_type), intent(inout) :: self
      self%n_prepared = 0
      self%has_normal = .false.
   end subroutine forget_normal

end module shcontact_pipeline_cache
