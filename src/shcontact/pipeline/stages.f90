!> The stages of one wheel–rail contact on plain data, shared by the library's solver object
!> (shcontact_pipeline_cache, which keeps their results between calls) and the program's sweep
!> runner (shcontact_case_runner, which shares them between the cases of a sweep):
!>
!> 1. geometry: the contact search (shcontact_geometry_contact) gives the candidate patches;
!> 2. normal: [[prepare_normal_stage]] prepares the normal problem of the patches the load may
!>    reach ([[loaded_count]]: the first one for a normal force or an approach, all for a
!>    vertical load, a position or a shared normal force), [[solve_normal_stage]] solves it for
!>    the load (doc/theory.md §4.5–4.6; a shared normal force as [[share_normal_force]] says);
!> 3. tangential: [[carry_creepage_stage]] gives every loaded patch its prescribed creepages
!>    (given at the first patch's reference point, carried to the others by the rigid slip,
!>    doc/lobes.md), [[solve_patch_stage]] solves one loaded patch for its creepages;
!> 4. summary: [[summarise_stages]] turns the stage results into the per-patch values, the main
!>    (most loaded) patch, the track-frame totals and the wheel's joined contact (the patches
!>    the exact theory joins into one, shcontact_tangential_lobes, doc/lobes.md) of a
!>    [[contact_result_type]].
!>
!> Being the only copy of each stage, the solver and the program give the same numbers for the
!> same case, bit for bit (test_app's app = library tests, both wheels).
module shcontact_pipeline_stages
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, prefix_error, fatal_error, stat_numerical, &
      stat_invalid_input
   use shcontact_core_ranges, only: max_normal_force
   use shcontact_core_material, only: material_type
   use shcontact_core_strings, only: str_int, str_real
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_kinematics, only: contact_lead
   use shcontact_normal_options, only: normal_options_type
   use shcontact_normal_loading, only: normal_contact_type, prepare_normal_contact, solve_load, &
      solve_approach, solve_vertical_load, solve_vertical_approach, interface_contact_angles, &
      patch_offset
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_normal_coupling, only: coupling_start_type
   use shcontact_tangential_options, only: tangential_options_type
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_solver, only: solve_tangential
   use shcontact_tangential_spin, only: carried_creepages
   use shcontact_tangential_lobes, only: join_lobes
   use shcontact_pipeline_load, only: contact_load_type, load_normal_force, load_vertical_force, &
      load_approach, load_vertical_position, load_shared_force
   use shcontact_pipeline_result, only: contact_result_type, max_patches
   implicit none
   private

   public :: loaded_count, prepare_normal_stage, solve_normal_stage, carry_creepage_stage, &
      solve_patch_stage, reference_axle_of, summarise_stages, check_prescribed_approach

   !> Relative accuracy of Σ_k N_k = N for a normal force shared by several patches
   !> ([[share_normal_force]]; doc/lobes.md).
   real(wp), parameter, public :: shared_force_rtol = 1.0e-9_wp
   !> Relative accuracy of the strips' vertical force Σ N_i cos γ_i = F_z of a prescribed
   !> vertical load ([[strip_vertical_load]]).
   real(wp), parameter, public :: strip_vertical_rtol = 1.0e-8_wp

contains

   !> Number of patches a load may act on (to prepare): the first (deepest) one for a normal force
   !> or an approach, every patch found for a vertical load, a position or a shared normal force
   !> (doc/theory.md §4.6). A shared normal force that only the first patch carries loads it
   !> alone ([[solve_normal_stage]]'s `used`).
   pure integer function loaded_count(load, n_patches) result(n)
      !> The load.
      type(contact_load_type), intent(in) :: load
      !> Patches found by the contact search.
      integer, intent(in) :: n_patches
      n = 1
      if (load%mode == load_vertical_force .or. load%mode == load_vertical_position .or. &
         load%mode == load_shared_force) n = n_patches
   end function loaded_count

   !> Prepare the normal problems of patches n_prepared+1..n (patches 1..n_prepared are
   !> prepared already). On error n_prepared is the last patch prepared.
   subroutine prepare_normal_stage(geometry, options, material, contacts, n_prepared, n, &
         error, points, interface)
      !> The patches of the contact search, deepest first.
      type(patch_geometry_type), intent(in) :: geometry(:)
      !> Normal options.
      type(normal_options_type), intent(in) :: options
      !> Elastic constants.
      type(material_type), intent(in) :: material
      !> The prepared normal problems (one per patch, at least n).
      type(normal_contact_type), intent(inout) :: contacts(:)
      !> Patches prepared so far; n on success.
      integer, intent(inout) :: n_prepared
      !> Patches to prepare (loaded_count).
      integer, intent(in) :: n
      !> Set when a patch cannot be prepared (prefixed with the patch number when n > 1).
      type(error_type), allocatable, intent(out) :: error
      !> Table points of each patch when the geometry's tables are longer (a reused search).
      integer, intent(in), optional :: points(:)
      !> The strips carry the interface's angles (`&tangential contact_surface = 'interface'`;
      !> default: the wheel's, at no cost).
      logical, intent(in), optional :: interface
      integer :: k

      do k = n_prepared + 1, n
         if (present(points)) then
            call prepare_normal_contact(contacts(k), geometry(k), options, material, error, &
               n_points=points(k))
         else
            call prepare_normal_contact(contacts(k), geometry(k), options, material, error)
         end if
         if (allocated(error)) then
            if (n > 1) call prefix_error(error, 'patch '//str_int(k))
            return
         end if
         if (present(interface)) then
            if (interface) call interface_contact_angles(contacts(k))
         end if
         n_prepared = k
      end do
   end subroutine prepare_normal_stage

   !> The normal solution for the load on the prepared patches (size loaded_count): a normal
   !> force or an approach on the first, a shared normal force as [[share_normal_force]] says, a
   !> vertical load or position on all.
   subroutine solve_normal_stage(contacts, load, normal, dz, error, start, used, dz_guess, &
         strips)
      !> The prepared normal problems of the loaded patches.
      type(normal_contact_type), intent(inout) :: contacts(:)
      !> The load.
      type(contact_load_type), intent(in) :: load
      !> The normal solution of each loaded patch.
      type(normal_patch_type), intent(inout) :: normal(:)
      !> Rigid vertical approach Δz of the wheel (mm) for a vertical load or position, else 0.
      real(wp), intent(out) :: dz
      !> Set when the load cannot be carried.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the coupling's length iterations for a vertical load or position
      !> (shcontact_normal_coupling's coupling_start_type).
      type(coupling_start_type), intent(inout), optional :: start
      !> The patches the solution loads, 1..used (all of `contacts` but for a shared normal force
      !> that only the first patch carries: 1, and patches 2.. are then not solved).
      integer, intent(out), optional :: used
      !> A close guess of Δz (mm) for a vertical load (shcontact_normal_loading's
      !> solve_vertical_load).
      real(wp), intent(in), optional :: dz_guess
      !> A vertical load is carried by the strips' normal forces resolved vertically with their
      !> own contact angles, Σ N_i cos γ_i = F_z ([[strip_vertical_load]]; the one-wheel calls
      !> with prescribed creepages). Default: Σ_k N_k cos γ_k over the patches' contact planes
      !> (the kinematic call's predictor, whose balance then matches the total F_z itself).
      logical, intent(in), optional :: strips
      real(wp) :: vertical
      integer :: n_used
      logical :: by_strips

      dz = 0.0_wp
      n_used = size(contacts)
      select case (load%mode)
      case (load_normal_force)
         call solve_load(contacts(1), load%value, normal(1), error)
      case (load_shared_force)
         call share_normal_force(contacts, load%value, normal, dz, n_used, error, start)
      case (load_approach)
         call solve_approach(contacts(1), load%value, normal(1), error)
         if (.not. allocated(error)) call check_prescribed_approach('approach', load%value, &
            normal(1:1), error)
      case (load_vertical_position)
         ! Not checked against max_normal_force here: the kinematic call's vertical balance
         ! takes its steps in this mode (the user's prescribed one is checked by the solver).
         call solve_vertical_approach(contacts, load%value, normal, vertical, error, start)
         dz = load%value
      case default
         by_strips = .false.
         if (present(strips)) by_strips = strips
         if (by_strips) then
            call strip_vertical_load(contacts, load%value, normal, dz, error, start, dz_guess)
         else
            call solve_vertical_load(contacts, load%value, normal, dz, error, start, dz_guess)
         end if
      end select
      if (present(used)) used = n_used
   end subroutine solve_normal_stage

   !> An error (stat_invalid_input) when an approach the user prescribed gives a normal force
   !> above [[max_normal_force]], the largest load a force mode takes: approach = 5 mm at
   !> Y_WS = 0 gave 31 MN and p_max 14.6 GPa with status 0. (Not for the vertical positions
   !> the kinematic call's balance tries: it finds where the wheel climbs by them.)
   subroutine check_prescribed_approach(what, approach, normal, error)
      character(len=*), intent(in) :: what
      !> The approach (mm).
      real(wp), intent(in) :: approach
      !> The solution of the patches it loads.
      type(normal_patch_type), intent(in) :: normal(:)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: total
      integer :: k
      total = 0.0_wp
      do k = 1, size(normal)
         total = total + normal(k)%load
      end do
      if (total <= max_normal_force) return
      call fatal_error(error, what//' '//str_real(approach)//' mm gives the normal force '// &
         str_real(total)//' N (p_max '//str_real(maxval(normal%p_max))//' MPa), above the '// &
         str_real(max_normal_force)//' N the program takes as a load; prescribe a smaller '// &
         what//' (mm)', stat_invalid_input)
   end subroutine check_prescribed_approach

   !> A prescribed vertical load F_z carried by the strips (doc/theory.md §4.6): the vertical
   !> force of the normal solution is that of its strips, Σ_k Σ_i N_k,i cos γ_k,i with each
   !> strip's own contact angle (the angle the tangential stage resolves it with, so that the
   !> reported F_z,track is −F_z where the creep forces vanish). The patch-plane balance
   !> Σ_k N_k cos γ_k = q of solve_vertical_load resolves a patch's load with the angle of its
   !> first contact; where a patch spans the flange root and the flange (γ from −30° to −70°)
   !> and its first contact lies on the flange while the load lies at the root, that differs
   !> from the strips' by a factor up to 2.3. So q is found by secant steps in ln q on
   !> ln(V(q)/F_z), V the strips' vertical force (V/q varies slowly with q), each a
   !> solve_vertical_load, to [[strip_vertical_rtol]].
   subroutine strip_vertical_load(contacts, f_z, normal, dz, error, start, dz_guess)
      type(normal_contact_type), intent(inout) :: contacts(:)
      !> Vertical load F_z (N).
      real(wp), intent(in) :: f_z
      type(normal_patch_type), intent(inout) :: normal(:)
      real(wp), intent(out) :: dz
      type(error_type), allocatable, intent(out) :: error
      type(coupling_start_type), intent(inout), optional :: start
      real(wp), intent(in), optional :: dz_guess
      integer, parameter :: max_steps = 40
      real(wp) :: x, x_old, r_old, v
      integer :: it

      x = log(f_z)
      x_old = 0.0_wp
      r_old = 0.0_wp
      do it = 1, max_steps
         if (it == 1) then
            call solve_vertical_load(contacts, exp(x), normal, dz, error, start, dz_guess)
         else
            call solve_vertical_load(contacts, exp(x), normal, dz, error, start)
         end if
         if (allocated(error)) return
         v = strips_vertical_force(normal)
         if (abs(v - f_z) <= strip_vertical_rtol*f_z) return
         if (.not. v > 0.0_wp) exit
         ! At most a factor e per step (a secant across a steep change of V/q).
         call secant_advance(x, x_old, log(v/f_z), r_old, it == 1, 1.0_wp)
      end do
      call fatal_error(error, 'vertical load: the vertical force of the strips did not '// &
         'converge to the prescribed F_z', stat_numerical)
   end subroutine strip_vertical_load

   !> One secant step on r(x) = 0 from (x, r) and the last point (x_old, r_old), which then
   !> become the last point: the first step (`first`) takes dr/dx = 1; a step is at most
   !> `limit` when given.
   pure subroutine secant_advance(x, x_old, r, r_old, first, limit)
      real(wp), intent(inout) :: x, x_old, r_old
      real(wp), intent(in) :: r
      logical, intent(in) :: first
      real(wp), intent(in), optional :: limit
      real(wp) :: step
      step = -r
      if (.not. first .and. r /= r_old) step = -r*(x - x_old)/(r - r_old)
      if (present(limit)) step = max(-limit, min(limit, step))
      x_old = x
      r_old = r
      x = x + step
   end subroutine secant_advance

   !> The vertical force of normal solutions (N, up positive): Σ N_i cos γ_i over the strips of
   !> every loaded patch, γ_i the strip's surface angle (`gamma_n`: the wheel's γ_i, or the
   !> interface's with `contact_surface = 'interface'`); a Hertz ellipse or a patch without
   !> strip data N cos γ of its contact plane.
   pure real(wp) function strips_vertical_force(normal) result(v)
      type(normal_patch_type), intent(in) :: normal(:)
      integer :: k, m
      v = 0.0_wp
      do k = 1, size(normal)
         associate (n => normal(k))
            if (.not. (n%load > 0.0_wp)) cycle
            m = n%n_strips
            if (n%is_hertz .or. .not. allocated(n%strip_load) .or. .not. allocated(n%gamma_n)) &
               then
               v = v + n%load*cos(n%gamma_plane)
            else if (size(n%strip_load) < m .or. size(n%gamma_n) < m) then
               v = v + n%load*cos(n%gamma_plane)
            else
               v = v + sum(n%strip_load(1:m)*cos(n%gamma_n(1:m)))
            end if
         end associate
      end do
   end function strips_vertical_force

   !> A normal force N of the wheel's contact, shared by its patches (load_shared_force;
   !> doc/lobes.md, "A normal force shared by the patches"): the wheel is one rigid body whose lateral position is given, so its
   !> patches share one rigid vertical approach Δz, as under a vertical load, and N is what they
   !> carry together along their normals, Σ_k N_k = N (CONTACT's module 3 prescribes F_n of its
   !> one patch, which holds every lobe it joins). The first patch is solved alone first
   !> (solve_load, the single-patch solve): when no other patch touches at the Δz where it
   !> carries N (δ_k = Δz cos γ_k − g₀,k at or below its first contact), that is the solution and
   !> `used` = 1. Otherwise the vertical load F_z for which the coupled solution's Σ_k N_k = N
   !> (to [[shared_force_rtol]]), by secant steps in ln F_z (Σ N_k/F_z, about 1/cos γ, varies
   !> slowly with F_z), each a vertical-load solve (solve_vertical_load).
   subroutine share_normal_force(contacts, force, normal, dz, used, error, start)
      !> The prepared patches, the first (deepest) first.
      type(normal_contact_type), intent(inout) :: contacts(:)
      !> Normal force N (N).
      real(wp), intent(in) :: force
      !> The normal solution of each patch (1..used filled).
      type(normal_patch_type), intent(inout) :: normal(:)
      !> Rigid vertical approach Δz of the wheel (mm) when shared, else 0.
      real(wp), intent(out) :: dz
      !> The patches loaded: 1, or all of them.
      integer, intent(out) :: used
      !> Set when the load cannot be carried or Σ N_k does not converge.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the coupling's length iterations.
      type(coupling_start_type), intent(inout), optional :: start
      integer, parameter :: max_steps = 40
      real(wp) :: dz_first, x, x_old, r_old
      integer :: k, it
      logical :: shared

      dz = 0.0_wp
      used = 1
      call solve_load(contacts(1), force, normal(1), error)
      if (allocated(error) .or. size(contacts) < 2) return
      associate (g => contacts(1)%geometry)
         if (.not. (cos(g%gamma0) > 0.0_wp)) return
         dz_first = (normal(1)%approach + g%gap0)/cos(g%gamma0)
      end associate
      shared = .false.
      do k = 2, size(contacts)
         associate (g => contacts(k)%geometry)
            shared = shared .or. (cos(g%gamma0) > 0.0_wp .and. &
               dz_first*cos(g%gamma0) - g%gap0 > g%approach_touch)
         end associate
      end do
      if (.not. shared) return
      used = size(contacts)
      ! r(x) = ln Σ N_k − ln N at F_z = e^x; the first step takes dr/dx = 1.
      x = log(force*cos(contacts(1)%geometry%gamma0))
      x_old = 0.0_wp
      r_old = 0.0_wp
      do it = 1, max_steps
         call solve_vertical_load(contacts, exp(x), normal, dz, error, start)
         if (allocated(error)) return
         if (abs(sum(normal%load) - force) <= shared_force_rtol*force) return
         call secant_advance(x, x_old, log(sum(normal%load)/force), r_old, it == 1)
      end do
      call fatal_error(error, 'normal force shared by the patches: their sum did not '// &
         'converge to the prescribed normal force', stat_numerical)
   end subroutine share_normal_force

   !> The prescribed creepages of every loaded patch (doc/lobes.md, "Prescribed creepages on
   !> several patches"). They are the rigid slip of the wheel relative to the rail at the
   !> reference point of the first (deepest) patch, the wheel's geometric contact point
   !> (doc/theory.md decision 13), and that patch gets them as given. Every other loaded patch
   !> gets the slip of the same rigid wheel at its own reference point:
   !> shcontact_tangential_spin's carried_creepages with its lateral distance y_k from the
   !> first reference point in the first patch's contact plane (the plane in which that patch's
   !> strips are placed), its own contact angle and rolling radius; under the default spin model
   !> ('uniform') ν_x,k = ν_x − φ y_k, ν_y,k = ν_y, φ_k = φ, CONTACT's rigid slip of one joined
   !> patch. The prescribed-creepage calls have no yaw, so every reference point lies at x = 0.
   !> One wheel's patches are in its own side frame (y towards its field side).
   pure subroutine carry_creepage_stage(geometry, normal, creepage, model, side, carried, error)
      !> The patches of the contact search (at least the loaded ones).
      type(patch_geometry_type), intent(in) :: geometry(:)
      !> The normal solutions of the loaded patches (n_loaded).
      type(normal_patch_type), intent(in) :: normal(:)
      !> The prescribed creepages (ν_x, ν_y, φ in rad/mm) at the first patch's reference point.
      type(creepage_type), intent(in) :: creepage
      !> Spin model, `spin_*` of shcontact_tangential_options.
      integer, intent(in) :: model
      !> side_right or side_left (geometry's y_track is in the track frame).
      integer, intent(in) :: side
      !> The creepages of each loaded patch (at least n_loaded; an unloaded one gets those given).
      type(creepage_type), intent(inout) :: carried(:)
      !> Set by the scaled spin model without geometric spin at the first reference point.
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: y1, z1, dy, dz, gamma0, r0, cos_p, sin_p
      integer :: k

      carried(1:size(normal)) = creepage
      if (count(normal(2:)%load > 0.0_wp) == 0) return
      y1 = side*geometry(1)%y_track + normal(1)%lateral_offset()
      z1 = geometry(1)%z_track + normal(1)%vertical_offset()
      cos_p = cos(geometry(1)%gamma0)
      sin_p = sin(geometry(1)%gamma0)
      gamma0 = geometry(1)%gamma0
      r0 = geometry(1)%r0
      if (normal(1)%load > 0.0_wp) then
         gamma0 = normal(1)%gamma0
         r0 = normal(1)%r0
      end if
      do k = 2, size(normal)
         if (.not. (normal(k)%load > 0.0_wp)) cycle
         dy = side*geometry(k)%y_track + normal(k)%lateral_offset() - y1
         dz = geometry(k)%z_track + normal(k)%vertical_offset() - z1
         call carried_creepages(model, creepage, dy*cos_p + dz*sin_p, gamma0, r0, &
            normal(k)%gamma0, normal(k)%r0, carried(k), error)
         if (allocated(error)) then
            call prefix_error(error, 'patch 1')
            return
         end if
      end do
   end subroutine carry_creepage_stage

   !> The tangential problem of loaded patch k of n for its creepages; nothing for a patch that
   !> carries no load.
   subroutine solve_patch_stage(ws, normal, material, creepage, options, tangential, k, n, error)
      !> The tangential workspace.
      type(march_workspace_type), intent(inout) :: ws
      !> The patch's normal solution.
      type(normal_patch_type), intent(in) :: normal
      !> Elastic constants and friction.
      type(material_type), intent(in) :: material
      !> Creepages at the patch's reference point.
      type(creepage_type), intent(in) :: creepage
      !> Tangential options.
      type(tangential_options_type), intent(in) :: options
      !> The patch's tangential solution.
      type(tangential_patch_type), intent(inout) :: tangential
      !> Patch number and number of loaded patches (for the message).
      integer, intent(in) :: k, n
      !> Set on failure (prefixed with the patch number when n > 1).
      type(error_type), allocatable, intent(out) :: error

      if (.not. (normal%load > 0.0_wp)) return
      call solve_tangential(ws, normal, material, creepage, options, tangential, error)
      if (allocated(error) .and. n > 1) call prefix_error(error, 'patch '//str_int(k))
   end subroutine solve_patch_stage

   !> Axle coordinate L (mm) of a loaded patch's reference point: the first contact's, moved by
   !> y_shift cos γ_plane along the contact plane (shcontact_normal_semihertz's
   !> refer_to_loaded_point).
   pure real(wp) function reference_axle_of(geometry, axle, normal) result(l)
      !> The patch.
      type(patch_geometry_type), intent(in) :: geometry
      !> Axle offset of the side frame's origin (mm, shcontact_geometry_kinematics's axle_offset).
      real(wp), intent(in) :: axle
      !> Its normal solution.
      type(normal_patch_type), intent(in) :: normal
      l = geometry%y_wheel + axle + normal%lateral_offset()
   end function reference_axle_of

   !> The summary of the stage results: every patch (geometry; for a loaded one its solution at
   !> its reference point), the most loaded ("main") patch, the track-frame totals and the
   !> wheel's joined contact ([[join_stage]]).
   pure subroutine summarise_stages(geometry, normal, tangential, creepage, side, axle, yaw, &
         dz, friction, result, points)
      !> Every patch of the contact search (n_patches).
      type(patch_geometry_type), intent(in) :: geometry(:)
      !> Normal solutions of the loaded patches (n_loaded).
      type(normal_patch_type), intent(in) :: normal(:)
      !> Tangential solutions and creepages of the loaded patches (n_loaded).
      type(tangential_patch_type), intent(in) :: tangential(:)
      type(creepage_type), intent(in) :: creepage(:)
      !> side_right or side_left (the reference point's y_track is in the track frame).
      integer, intent(in) :: side
      !> Axle offset (mm, as in [[reference_axle_of]]) and yaw angle of the side frame (rad).
      real(wp), intent(in) :: axle, yaw
      !> Rigid vertical approach Δz (mm).
      real(wp), intent(in) :: dz
      !> Friction coefficient μ of the solve (f = F/(μF_n) of the joined contact).
      real(wp), intent(in) :: friction
      !> The result (filled for patches 1..n_patches, the totals and the joined contact).
      type(contact_result_type), intent(inout) :: result
      !> Table points of each patch when the geometry's tables are longer (a reused search).
      integer, intent(in), optional :: points(:)
      integer :: k, m

      result%n_patches = size(geometry)
      result%n_loaded = size(normal)
      result%dz = dz
      do k = 1, result%n_patches
         associate (p => result%patch(k), g => geometry(k))
            p%gamma0 = g%gamma0
            p%gamma_plane = g%gamma0
            p%r0 = g%r0
            p%y_track = g%y_track
            p%z_track = g%z_track
            p%x_track = contact_lead(g%y_wheel + axle, g%r0, g%gamma0, yaw)
         end associate
      end do
      m = 1
      do k = 1, result%n_loaded
         associate (p => result%patch(k), n => normal(k), t => tangential(k))
            p%fn = n%load
            if (n%load > 0.0_wp) then
               p%gamma0 = n%gamma0
               p%r0 = n%r0
               ! Along the contact plane towards the wheel's field side (y_track is in the
               ! track frame: towards −y on the left wheel).
               p%y_track = p%y_track + side*n%lateral_offset()
               p%z_track = p%z_track + n%vertical_offset()
               p%x_track = contact_lead(reference_axle_of(geometry(k), axle, n), n%r0, &
                  n%gamma0, yaw)
            end if
            p%approach = n%approach
            p%area = n%area
            p%p_max = n%p_max
            if (.not. (n%load > 0.0_wp)) cycle
            p%fx = t%fx
            p%fy = t%fy
            p%mz = t%mz
            p%fx_norm = t%fx_norm
            p%fy_norm = t%fy_norm
            p%fy_track = t%fy_track
            p%fz_track = t%fz_track
            p%coulomb_ratio = t%coulomb_ratio
            p%adhesion_fraction = t%adhesion_fraction
            p%nu_x = creepage(k)%nu_x
            p%nu_y = creepage(k)%nu_y
            p%phi = creepage(k)%phi
            result%track%fx = result%track%fx + t%fx
            result%track%fy = result%track%fy + t%fy_track
            result%track%fz = result%track%fz + t%fz_track
            result%track%fn = result%track%fn + n%load
         end associate
         if (normal(k)%load > normal(m)%load) m = k
      end do
      result%main_patch = m
      result%main = result%patch(m)
      call join_stage(geometry, normal, tangential, friction, result, points)
   end subroutine summarise_stages

   !> The wheel's joined contact (issue 28 item 3, doc/lobes.md) of the loaded patches:
   !> shcontact_tangential_lobes's join_lobes, the patches placed along the profile by the signed
   !> distance of their first contacts from the first patch's in the track's y–z plane, as the
   !> coupled normal reduction places them (shcontact_normal_loading). The library's solver and
   !> the program's runner both get it here, from the same numbers.
   pure subroutine join_stage(geometry, normal, tangential, friction, result, points)
      !> Every patch of the contact search; the normal and tangential solutions of the loaded
      !> ones.
      type(patch_geometry_type), intent(in) :: geometry(:)
      type(normal_patch_type), intent(in) :: normal(:)
      type(tangential_patch_type), intent(in) :: tangential(:)
      !> Friction coefficient μ.
      real(wp), intent(in) :: friction
      !> The result; its `wheel` is set.
      type(contact_result_type), intent(inout) :: result
      !> Table points of each patch (default: the whole table).
      integer, intent(in), optional :: points(:)
      ! Fixed-size work arrays: the summary allocates nothing (doc/api.md).
      real(wp) :: offset(max_patches), fx(max_patches), fy(max_patches)
      integer :: n_points(max_patches)
      integer :: k, n
      logical :: several

      n = min(size(normal), max_patches)
      ! The patches' extents along the profile matter only where two loaded patches may be
      ! joined. With one loaded patch the joined contact is that patch, so its table is not
      ! searched (no points: an empty extent): the search is most of this stage's cost, a few µs
      ! per case on the default case (doc/lobes.md).
      several = count(normal(1:n)%load > 0.0_wp) > 1
      do k = 1, n
         n_points(k) = 0
         if (several .and. present(points)) then
            n_points(k) = points(k)
         else if (several) then
            n_points(k) = geometry(k)%size()
         end if
         fx(k) = 0.0_wp
         fy(k) = 0.0_wp
         if (normal(k)%load > 0.0_wp) then
            fx(k) = tangential(k)%fx
            fy(k) = tangential(k)%fy
         end if
         offset(k) = patch_offset(geometry(k)%y_track - geometry(1)%y_track, &
            geometry(k)%z_track - geometry(1)%z_track, geometry(k)%y_rail - geometry(1)%y_rail)
      end do
      call join_lobes(geometry(1:n), n_points(1:n), normal(1:n), offset(1:n), fx(1:n), &
         fy(1:n), friction, result%wheel)
   end subroutine join_stage

end module shcontact_pipeline_stages
