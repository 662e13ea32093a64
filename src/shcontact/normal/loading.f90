!> Loading of the normal problem (doc/theory.md §4.5–4.6): a prescribed approach, a prescribed
!> normal force on one patch, or a prescribed vertical wheel load shared by several patches
!> through one rigid approach of the wheel.
!>
!> A [[normal_contact_type]] is prepared once per patch geometry ([[prepare_normal_contact]]);
!> the solves then allocate nothing unless the number of strips changes. Force matching solves
!> N(δ)^{2/3} = N_target^{2/3}: that residual is exactly linear in δ on Hertzian geometry (N ∝
!> δ^{3/2}) and nearly so otherwise, so Brent's secant/inverse-quadratic steps converge in a few
!> evaluations while its bracket safeguards the kinks of N(δ) where strips enter.
module shcontact_normal_loading
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_no_contact, &
      stat_numerical, stat_usage
   use shcontact_core_strings, only: str_real
   use shcontact_core_material, only: material_type, check_material
   use shcontact_math_roots, only: scalar_function_type, find_root
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_options, only: normal_options_type, check_normal_options, method_hertz, &
      reduction_coupled
   use shcontact_normal_coupling, only: couple_strips, couple_patches, coupling_start_type
   use shcontact_normal_hertz, only: hertz_shape_type, hertz_type, hertz_shape_fast, hertz_from_load, &
      hertz_from_approach
   use shcontact_normal_semihertz, only: semihertz_geometry_type, prepare_semihertz, &
      semihertz_strips, semihertz_load, ellipse_strips, reserve_strips, clear_strips, &
      refer_to_loaded_point, use_interface_angles
   use shcontact_normal_patch, only: normal_patch_type
   implicit none
   private

   public :: normal_contact_type, prepare_normal_contact, interface_contact_angles, patch_offset
   public :: solve_approach, solve_load, solve_vertical_load, solve_vertical_approach

   !> Relative accuracy of the force matching (the issue asks for 1e-10).
   real(wp), parameter :: load_rtol = 1.0e-10_wp
   !> Relative tolerance handed to Brent on the approach (well inside load_rtol).
   real(wp), parameter :: root_rtol = 1.0e-13_wp
   !> Bracket steps around the first guess (Hertz at the reference point).
   real(wp), parameter :: grow = 1.25_wp, shrink = 0.8_wp
   !> The first bracket step (relative) around a close guess ([[solve_vertical_load]]'s
   !> dz_guess), doubled at every further step up to the default steps.
   real(wp), parameter :: guess_step = 1.0e-3_wp
   !> Keep the bracket this far (relative) inside the largest approach the table allows.
   real(wp), parameter :: table_margin = 1.0e-12_wp

   !> One patch prepared for the normal solve: options, material, the reduced geometry and the
   !> Hertz shape at the reference point. It is also the solve's workspace.
   type :: normal_contact_type
      !> Method, reduction, strips.
      type(normal_options_type) :: options
      !> Elastic constants.
      type(material_type) :: material
      !> E* = G/(1 − ν) (MPa).
      real(wp) :: e_star = 0.0_wp
      !> The geometry reduced for the strip method.
      type(semihertz_geometry_type) :: geometry
      !> Hertz shape at A(0)/B(0): the `'hertz'` method and the first guess of force matching.
      type(hertz_shape_type) :: ref_shape
      !> The reference point's lateral and vertical track coordinates (mm) and its lateral
      !> coordinate on the rail profile (mm): where the patch lies along the profile, for the
      !> coupling between patches ([[patch_offset]]).
      real(wp) :: y_track = 0.0_wp, z_track = 0.0_wp, y_rail = 0.0_wp
   end type normal_contact_type

   !> N(δ)^{2/3} − N_target^{2/3} of one patch, with δ = origin + x.
   type, extends(scalar_function_type) :: patch_residual
      type(normal_contact_type), pointer :: contact => null()
      type(normal_patch_type), pointer :: patch => null()
      real(wp) :: origin = 0.0_wp, target_23 = 0.0_wp
      type(error_type), allocatable :: error
   contains
      procedure :: eval => patch_residual_eval
   end type patch_residual

   !> F_z(Δz)^{2/3} − F_z,target^{2/3} of several patches, with Δz = origin + x and
   !> δ_k = Δz cos γ_k − g₀,k (doc/theory.md §4.6). The patches are filled only when `fill` (the
   !> search needs the forces alone).
   type, extends(scalar_function_type) :: vertical_residual
      type(normal_contact_type), pointer :: contacts(:) => null()
      type(normal_patch_type), pointer :: patches(:) => null()
      real(wp) :: origin = 0.0_wp, target_23 = 0.0_wp, force = 0.0_wp
      logical :: fill = .false.
      type(error_type), allocatable :: error
   contains
      procedure :: eval => vertical_residual_eval
   end type vertical_residual

contains

   !> Prepare one patch: check the options, material and geometry, reduce the geometry
   !> (per-point ε_a, ε_b, m, n: once per geometry) and solve the reference Hertz shape. The
   !> contact of the patch is confined to its own basin ([[confine_to_basin]]). A reused
   !> `contact` allocates nothing once it has held a table as long.
   subroutine prepare_normal_contact(contact, geometry, options, material, error, n_points)
      !> The prepared patch (its arrays only grow: they are reused for any shorter table).
      type(normal_contact_type), intent(inout) :: contact
      !> Patch geometry.
      type(patch_geometry_type), intent(in) :: geometry
      !> Normal-contact options.
      type(normal_options_type), intent(in) :: options
      !> Elastic constants.
      type(material_type), intent(in) :: material
      !> Set for invalid options, material or geometry.
      type(error_type), allocatable, intent(out) :: error
      !> The tables are the first n_points entries of the geometry's arrays, which may be longer
      !> (shcontact_geometry_contact's contact_patches_type). Default: all entries.
      integer, intent(in), optional :: n_points
      real(wp) :: gap_first, gap_last
      integer :: first, last
      logical :: confined

      call check_normal_options(options, error)
      if (allocated(error)) return
      call check_material(material, error)
      if (allocated(error)) return
      contact%options = options
      contact%material = material
      contact%e_star = material%e_star()
      contact%y_track = geometry%y_track
      contact%z_track = geometry%z_track
      contact%y_rail = geometry%y_rail
      call confine_to_basin(geometry, n_points, first, last, gap_first, gap_last, confined)
      if (confined) then
         call prepare_semihertz(geometry, options, contact%geometry, error, first=first, &
            last=last, gap_first=gap_first, gap_last=gap_last)
      else
         call prepare_semihertz(geometry, options, contact%geometry, error, last=n_points)
      end if
      if (allocated(error)) return
      call hertz_shape_fast(contact%geometry%curv_a0/contact%geometry%curv_b0, contact%ref_shape, &
         error)
   end subroutine prepare_normal_contact

   !> The strips of this prepared contact carry the interface's angle γ_n (doc/geometry.md, "The
   !> direction of the pressure") instead of the wheel's γ in their `gamma_n`.
   pure subroutine interface_contact_angles(contact)
      type(normal_contact_type), intent(inout) :: contact
      call use_interface_angles(contact%geometry)
   end subroutine interface_contact_angles

   !> The normal solution for a prescribed approach δ of the patch (no iteration).
   subroutine solve_approach(contact, approach, patch, error)
      !> The prepared patch.
      type(normal_contact_type), intent(in) :: contact
      !> Approach δ (mm), measured from the first contact of the undeformed surfaces.
      real(wp), intent(in) :: approach
      !> The solution.
      type(normal_patch_type), intent(inout) :: patch
      !> stat_no_contact when the surfaces do not touch or the table is too short.
      type(error_type), allocatable, intent(out) :: error

      if (.not. (approach > contact%geometry%approach_touch)) then
         call fatal_error(error, 'the profiles do not touch: approach '//str_real(approach)// &
            ' mm is at or below first contact ('//str_real(contact%geometry%approach_touch)// &
            ' mm)', stat_no_contact)
         return
      end if
      call fill_patch(contact, approach, patch, error)
      if (.not. allocated(error)) call coupled_if_asked(contact, patch, error)
      if (.not. allocated(error)) call refer_to_loaded_point(contact%geometry, patch)
   end subroutine solve_approach

   !> The normal solution for a prescribed normal force N on one patch: δ such that
   !> Σ N_i = N to a relative 1e-10 (doc/theory.md §4.5).
   subroutine solve_load(contact, load, patch, error)
      !> The prepared patch.
      type(normal_contact_type), intent(in), target :: contact
      !> Normal force N (N), positive.
      real(wp), intent(in) :: load
      !> The solution.
      type(normal_patch_type), intent(inout), target :: patch
      !> stat_invalid_input for N ≤ 0, stat_no_contact when the table cannot carry N.
      type(error_type), allocatable, intent(out) :: error

      type(patch_residual) :: f
      type(hertz_type) :: guess
      real(wp) :: x_max, root
      character(len=64) :: buf

      call check_force(load, 'normal force N', error)
      if (allocated(error)) return
      call hertz_from_load(contact%geometry%curv_a0, contact%geometry%curv_b0, load, &
         contact%material, guess, error, shape=contact%ref_shape)
      if (allocated(error)) return
      if (contact%options%method == method_hertz) then
         call ellipse_strips(contact%geometry, guess, contact%options%n_strips, patch)
         return
      end if

      f%contact => contact
      f%patch => patch
      f%origin = contact%geometry%approach_touch
      f%target_23 = load**(2.0_wp/3.0_wp)
      x_max = (contact%geometry%approach_max - f%origin)*(1.0_wp - table_margin)
      call solve_increasing(f, guess%approach, x_max, root, error)
      if (allocated(f%error)) call move_alloc(f%error, error)
      if (allocated(error)) return
      ! Brent may stop without evaluating at its final estimate: fill the patch there.
      call fill_patch(contact, f%origin + root, patch, error)
      if (allocated(error)) return
      if (abs(patch%load - load) > load_rtol*load) then
         call fatal_error(error, 'normal force matching did not converge: '// &
            str_real(patch%load)//' N instead of '//str_real(load)//' N', &
            stat_numerical)
         return
      end if
      call coupled_if_asked(contact, patch, error)
      if (.not. allocated(error)) call refer_to_loaded_point(contact%geometry, patch)
   end subroutine solve_load

   !> `reduction = 'coupled'`: redistribute the load of the local-Hertz strips through the
   !> half-space (shcontact_normal_coupling); the load, hence every force balance, is kept.
   pure subroutine coupled_if_asked(contact, patch, error)
      !> The prepared patch.
      type(normal_contact_type), intent(in) :: contact
      !> Its solution (local-Hertz on entry).
      type(normal_patch_type), intent(inout) :: patch
      !> Set when the dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      if (contact%options%reduction /= reduction_coupled .or. patch%is_hertz) return
      call couple_strips(patch, contact%e_star, error)
   end subroutine coupled_if_asked

   !> `reduction = 'coupled'` for the patches of one wheel: their strips in one half-space problem
   !> (shcontact_normal_coupling's couple_patches), placed along the rail profile by their
   !> reference points; Σ_k N_k cos γ_k, hence the vertical balance, is kept.
   pure subroutine patches_coupled_if_asked(contacts, patches, error, start)
      !> The prepared patches of one wheel.
      type(normal_contact_type), intent(in) :: contacts(:)
      !> Their solutions (local-Hertz on entry).
      type(normal_patch_type), intent(inout) :: patches(:)
      !> Set when a dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the coupling's length iterations (shcontact_normal_coupling).
      type(coupling_start_type), intent(inout), optional :: start
      !> More patches than this on one wheel are not placed along the profile (a fixed-size work
      !> array): each is coupled alone.
      integer, parameter :: most = 32
      real(wp) :: offset(most)
      integer :: k

      if (contacts(1)%options%reduction /= reduction_coupled) return
      if (size(contacts) > most) then
         call couple_patches(patches, contacts(1)%e_star, error, start=start)
         return
      end if
      do k = 1, size(contacts)
         offset(k) = patch_offset(contacts(k)%y_track - contacts(1)%y_track, &
            contacts(k)%z_track - contacts(1)%z_track, contacts(k)%y_rail - contacts(1)%y_rail)
      end do
      call couple_patches(patches, contacts(1)%e_star, error, offset(1:size(contacts)), start)
   end subroutine patches_coupled_if_asked

   !> The position of a patch along the profile relative to another, for the coupling between
   !> them: their reference points' distance in the track frame, hypot(Δy_track, Δz_track) (mm;
   !> both differences in one frame, so that a rail canted by the track and the same rail given
   !> canted give the same distance), signed as their order on the rail profile, Δy_rail
   !> (positive towards the field side on either wheel).
   elemental real(wp) function patch_offset(dy_track, dz_track, dy_rail) result(offset)
      real(wp), intent(in) :: dy_track, dz_track, dy_rail
      offset = sign(hypot(dy_track, dz_track), dy_rail)
   end function patch_offset

   !> Several patches of one wheel under a prescribed vertical load F_z: one rigid approach Δz
   !> with δ_k = Δz cos γ_k − g₀,k and Σ_k N_k cos γ_k = F_z (doc/theory.md §4.6). Patches that do
   !> not touch at the solution come back cleared (zero strips, zero load). Each patch's contact
   !> stays inside its own basin ([[confine_to_basin]]): neighbours that meet under load split
   !> the merged region at the ridge between them, and no region is counted twice.
   subroutine solve_vertical_load(contacts, f_z, patches, dz, error, lengths, dz_guess)
      !> The prepared patches.
      type(normal_contact_type), intent(in), target :: contacts(:)
      !> Vertical wheel load F_z (N), positive.
      real(wp), intent(in) :: f_z
      !> The solutions, one per patch (same size as contacts).
      type(normal_patch_type), intent(inout), target :: patches(:)
      !> The common rigid approach Δz of the wheel (mm).
      real(wp), intent(out) :: dz
      !> Set for bad input or a load the tables cannot carry.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the coupling's length iterations (shcontact_normal_coupling's
      !> coupling_start_type): a solve that repeats one of the same wheel at a nearby load.
      type(coupling_start_type), intent(inout), optional :: lengths
      !> A close first guess of Δz (mm; the vertical balance's next load step): the root is then
      !> bracketed by steps of guess_step (relative) growing twofold, not by Hertz's guess and
      !> steps of 25 %. The root is the same to the search's 1e-13.
      real(wp), intent(in), optional :: dz_guess

      type(vertical_residual) :: f
      type(hertz_type) :: guess
      real(wp) :: cos_g, start, x_max, root, residual, x_guess
      integer :: k, k_first
      character(len=96) :: buf

      dz = 0.0_wp
      if (size(contacts) < 1 .or. size(patches) /= size(contacts)) then
         write (buf, '(i0,a,i0,a)') size(contacts), ' patches and ', size(patches), ' solutions'
         call fatal_error(error, 'vertical load: '//trim(buf)// &
            ': expected at least one patch and one solution per patch', stat_usage)
         return
      end if
      call check_force(f_z, 'vertical load F_z', error)
      if (allocated(error)) return

      ! Δz where each patch starts to touch, and where its table would run out.
      f%origin = huge(1.0_wp)
      x_max = huge(1.0_wp)
      k_first = 1
      do k = 1, size(contacts)
         cos_g = cos(contacts(k)%geometry%gamma0)
         if (.not. (cos_g > 0.0_wp)) then
            write (buf, '(i0,a,es12.4,a)') k, ': contact angle ', contacts(k)%geometry%gamma0, &
               ' rad'
            call fatal_error(error, 'vertical load: patch '//trim(buf)// &
               ': expected |gamma0| < pi/2 to carry a vertical load', stat_invalid_input)
            return
         end if
         start = (contacts(k)%geometry%approach_touch + contacts(k)%geometry%gap0)/cos_g
         if (start < f%origin) then
            f%origin = start
            k_first = k
         end if
      end do
      do k = 1, size(contacts)
         if (contacts(k)%geometry%has_strip_data) x_max = min(x_max, &
            (contacts(k)%geometry%approach_max + contacts(k)%geometry%gap0)/ &
            cos(contacts(k)%geometry%gamma0) - f%origin)
      end do
      x_max = x_max*(1.0_wp - table_margin)

      ! First guess: the first patch to touch carries everything, as a Hertz contact.
      cos_g = cos(contacts(k_first)%geometry%gamma0)
      call hertz_from_load(contacts(k_first)%geometry%curv_a0, contacts(k_first)%geometry%curv_b0, &
         f_z/cos_g, contacts(k_first)%material, guess, error, shape=contacts(k_first)%ref_shape)
      if (allocated(error)) return

      f%contacts => contacts
      f%patches => patches
      f%target_23 = f_z**(2.0_wp/3.0_wp)
      x_guess = -1.0_wp
      if (present(dz_guess)) x_guess = dz_guess - f%origin
      if (x_guess > 0.0_wp .and. x_guess < x_max) then
         call solve_increasing(f, x_guess, x_max, root, error, first_step=guess_step)
      else
         call solve_increasing(f, guess%approach/cos_g, x_max, root, error)
      end if
      if (allocated(f%error)) call move_alloc(f%error, error)
      if (allocated(error)) return
      f%fill = .true.
      residual = f%eval(root)
      if (allocated(f%error)) then
         call move_alloc(f%error, error)
         return
      end if
      dz = f%origin + root
      if (abs(f%force - f_z) > load_rtol*f_z) then
         call fatal_error(error, 'vertical load matching did not converge: '// &
            str_real(f%force)//' N instead of '//str_real(f_z)//' N', &
            stat_numerical)
         return
      end if
      call patches_coupled_if_asked(contacts, patches, error, lengths)
      if (.not. allocated(error)) call refer_patches(contacts, patches)
   end subroutine solve_vertical_load

   !> Several patches at a prescribed rigid vertical approach Δz of the wheel (a vertical
   !> position, doc/theory.md §4.6): δ_k = Δz cos γ_k − g₀,k, Δz measured from the height where the
   !> smallest gap is zero (the `dz` of [[solve_vertical_load]]). Patches that do not touch come
   !> back cleared; `f_z` = Σ_k N_k cos γ_k is the vertical load the position implies.
   subroutine solve_vertical_approach(contacts, dz, patches, f_z, error, lengths)
      !> The prepared patches.
      type(normal_contact_type), intent(in), target :: contacts(:)
      !> Vertical approach Δz (mm, ≥ 0).
      real(wp), intent(in) :: dz
      !> The solutions, one per patch (same size as contacts).
      type(normal_patch_type), intent(inout), target :: patches(:)
      !> Σ_k N_k cos γ_k (N).
      real(wp), intent(out) :: f_z
      !> Set for bad input or an approach the tables cannot carry.
      type(error_type), allocatable, intent(out) :: error
      !> Starts of the coupling's length iterations, as in [[solve_vertical_load]].
      type(coupling_start_type), intent(inout), optional :: lengths
      type(vertical_residual) :: f
      real(wp) :: residual
      character(len=64) :: buf

      f_z = 0.0_wp
      if (size(contacts) < 1 .or. size(patches) /= size(contacts)) then
         call fatal_error(error, 'vertical approach: expected at least one patch and one '// &
            'solution per patch', stat_usage)
         return
      end if
      if (.not. (dz >= 0.0_wp)) then
         write (buf, '(es12.4)') dz
         call fatal_error(error, 'vertical approach = '//trim(adjustl(buf))// &
            ' mm: expected a downward displacement >= 0 from first contact', stat_invalid_input)
         return
      end if
      f%contacts => contacts
      f%patches => patches
      f%fill = .true.
      residual = f%eval(dz)
      if (allocated(f%error)) then
         call move_alloc(f%error, error)
         return
      end if
      f_z = f%force
      call patches_coupled_if_asked(contacts, patches, error, lengths)
      if (.not. allocated(error)) call refer_patches(contacts, patches)
   end subroutine solve_vertical_approach

   !> Every patch of a wheel referred to its own geometric contact point of the loaded state.
   pure subroutine refer_patches(contacts, patches)
      type(normal_contact_type), intent(in) :: contacts(:)
      type(normal_patch_type), intent(inout) :: patches(:)
      integer :: k
      do k = 1, size(contacts)
         call refer_to_loaded_point(contacts(k)%geometry, patches(k))
      end do
   end subroutine refer_patches

   !> The tables of a patch confined to its own basin (doc/theory.md §4.6, doc/geometry.md
   !> "Neighbouring patches under load"): past a basin limit the table runs into a neighbouring
   !> patch's basin, which that patch carries, so it is cut one point beyond the limit and that
   !> point is raised to the table's largest gap. The strip method's contact interval then stops
   !> within h of the limit, N(δ) stays continuous when the contact reaches the ridge (growing
   !> across it would add the neighbour's already penetrated region at once), and the approach is
   !> bounded on that side as at an open table end. The cut table is points first..last of the
   !> geometry's, with gaps gap_first and gap_last at its ends (nothing is copied). `confined` is
   !> false, and the other results unset, when no limit lies inside the table or the table is
   !> malformed (prepare_semihertz reports).
   pure subroutine confine_to_basin(geometry, n_points, first, last, gap_first, gap_last, &
         confined)
      type(patch_geometry_type), intent(in) :: geometry
      !> The table's size when the arrays may be longer (see prepare_normal_contact).
      integer, intent(in), optional :: n_points
      integer, intent(out) :: first, last
      real(wp), intent(out) :: gap_first, gap_last
      logical, intent(out) :: confined
      integer :: n, i_lo, i_hi, i_ref
      integer :: sizes(5)

      confined = .false.
      first = 1
      last = 1
      gap_first = 0.0_wp
      gap_last = 0.0_wp
      if (.not. (allocated(geometry%y) .and. allocated(geometry%gap) .and. &
                 allocated(geometry%curv_a) .and. allocated(geometry%curv_b) .and. &
                 allocated(geometry%gamma) .and. allocated(geometry%r_wheel))) return
      sizes = [size(geometry%gap), size(geometry%curv_a), size(geometry%curv_b), &
         size(geometry%gamma), size(geometry%r_wheel)]
      if (present(n_points)) then
         n = n_points
         if (n > size(geometry%y) .or. any(sizes < n)) return
      else
         n = size(geometry%y)
         if (any(sizes /= n)) return
      end if
      if (n < 2) return
      if (.not. (geometry%h > 0.0_wp .and. geometry%y(1) <= 0.0_wp .and. &
                 geometry%y(n) >= 0.0_wp)) return
      ! Compare before dividing: the limits default to ±huge.
      if (geometry%basin_lower <= geometry%y(1) .and. geometry%basin_upper >= geometry%y(n)) return
      i_ref = 1 + nint(-geometry%y(1)/geometry%h)
      i_lo = 1
      i_hi = n
      if (geometry%basin_lower > geometry%y(1)) i_lo = min(i_ref, &
         1 + nint((min(geometry%basin_lower, geometry%y(n)) - geometry%y(1))/geometry%h))
      if (geometry%basin_upper < geometry%y(n)) i_hi = max(i_ref, &
         1 + nint((max(geometry%basin_upper, geometry%y(1)) - geometry%y(1))/geometry%h))
      first = max(1, i_lo - 1)
      last = min(n, i_hi + 1)
      gap_first = geometry%gap(first)
      gap_last = geometry%gap(last)
      if (first < i_lo) gap_first = maxval(geometry%gap(1:n))
      if (last > i_hi) gap_last = maxval(geometry%gap(1:n))
      confined = .true.
   end subroutine confine_to_basin

   !> Fill the patch for approach δ by the contact's method; below contact the patch is cleared.
   subroutine fill_patch(contact, approach, patch, error)
      type(normal_contact_type), intent(in) :: contact
      real(wp), intent(in) :: approach
      type(normal_patch_type), intent(inout) :: patch
      type(error_type), allocatable, intent(out) :: error
      type(hertz_type) :: sol

      if (contact%options%method == method_hertz) then
         if (approach > 0.0_wp) then
            call hertz_from_approach(contact%geometry%curv_a0, contact%geometry%curv_b0, approach, &
               contact%material, sol, error, shape=contact%ref_shape)
            if (allocated(error)) return
            call ellipse_strips(contact%geometry, sol, contact%options%n_strips, patch)
         else
            call reserve_strips(patch, contact%options%n_strips)
            call clear_strips(patch, contact%geometry%gamma0, contact%geometry%r0)
            patch%approach = approach
         end if
      else
         call semihertz_strips(contact%geometry, contact%options, contact%e_star, approach, patch, &
            error)
      end if
   end subroutine fill_patch

   !> The normal force of one patch at approach δ, for the load iterations: the semi-Hertz load
   !> without building the strip table (bit for bit the load [[fill_patch]] gives); the 'hertz'
   !> method fills the patch.
   subroutine patch_load(contact, approach, patch, load, error)
      type(normal_contact_type), intent(in) :: contact
      real(wp), intent(in) :: approach
      type(normal_patch_type), intent(inout) :: patch
      real(wp), intent(out) :: load
      type(error_type), allocatable, intent(out) :: error

      if (contact%options%method == method_hertz) then
         call fill_patch(contact, approach, patch, error)
         load = patch%load
      else
         call semihertz_load(contact%geometry, contact%options, contact%e_star, approach, load, &
            error)
      end if
   end subroutine patch_load

   !> Root of an increasing residual with f(0) < 0 on (0, x_max]: bracket from the guess by
   !> geometric steps, then Brent. Beyond x_max the geometry cannot carry the load.
   subroutine solve_increasing(f, x_guess, x_max, root, error, first_step)
      class(scalar_function_type), intent(inout) :: f
      real(wp), intent(in) :: x_guess, x_max
      real(wp), intent(out) :: root
      type(error_type), allocatable, intent(out) :: error
      !> The first step, relative (default grow − 1), doubled at each further step up to
      !> grow − 1.
      real(wp), intent(in), optional :: first_step
      real(wp) :: lo, hi, flo, fhi, up, down, d
      character(len=96) :: buf
      integer :: i

      root = 0.0_wp
      if (.not. (x_max > 0.0_wp)) then
         call fatal_error(error, 'load too large for the patch geometry: the geometry table '// &
            'ends where contact starts', stat_no_contact)
         return
      end if
      up = grow
      down = shrink
      d = grow - 1.0_wp
      if (present(first_step)) then
         d = min(first_step, d)
         up = 1.0_wp + d
         down = 1.0_wp/up
      end if
      hi = min(x_guess, x_max)
      fhi = f%eval(hi)
      if (fhi >= 0.0_wp) then
         lo = hi; flo = fhi
         do i = 1, 400
            hi = lo; fhi = flo
            lo = down*hi
            flo = f%eval(lo)
            if (flo < 0.0_wp) exit
            call widen()
         end do
      else
         do i = 1, 400
            if (hi >= x_max) then
               call fatal_error(error, 'load too large for the patch geometry: the contact '// &
                  'reaches the end of the geometry table at an approach of '// &
                  str_real(x_max)//' mm beyond first contact', &
                  stat_no_contact)
               return
            end if
            lo = hi; flo = fhi
            hi = min(x_max, up*hi)
            fhi = f%eval(hi)
            if (fhi >= 0.0_wp) exit
            call widen()
         end do
      end if
      call find_root(f, lo, hi, root, error, xtol=0.0_wp, rtol=root_rtol, f_lower=flo, &
         f_upper=fhi)
   contains
      !> The next bracket step twice the last, up to the default steps.
      subroutine widen()
         if (d >= grow - 1.0_wp) return
         d = min(2.0_wp*d, grow - 1.0_wp)
         up = 1.0_wp + d
         down = 1.0_wp/up
         if (d >= grow - 1.0_wp) then
            up = grow
            down = shrink
         end if
      end subroutine widen
   end subroutine solve_increasing

   !> Error unless a force is positive and finite.
   pure subroutine check_force(value, what, error)
      real(wp), intent(in) :: value
      character(len=*), intent(in) :: what
      type(error_type), allocatable, intent(out) :: error
      character(len=32) :: buf
      if (value > 0.0_wp .and. value < huge(1.0_wp)) return
      write (buf, '(es12.4)') value
      call fatal_error(error, what//' = '//trim(adjustl(buf))//' N: expected a positive value', &
         stat_invalid_input)
   end subroutine check_force

   function patch_residual_eval(self, x) result(fx)
      class(patch_residual), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      type(error_type), allocatable :: error
      real(wp) :: load

      call patch_load(self%contact, self%origin + x, self%patch, load, error)
      if (allocated(error)) then
         ! Report after the search; answer as if overloaded so that the search stays finite.
         if (.not. allocated(self%error)) call move_alloc(error, self%error)
         fx = self%target_23
         return
      end if
      fx = load**(2.0_wp/3.0_wp) - self%target_23
   end function patch_residual_eval

   function vertical_residual_eval(self, x) result(fx)
      class(vertical_residual), intent(inout) :: self
      real(wp), intent(in) :: x
      real(wp) :: fx
      type(error_type), allocatable :: error
      real(wp) :: dz, cos_g, approach, load
      integer :: k

      dz = self%origin + x
      self%force = 0.0_wp
      do k = 1, size(self%contacts)
         cos_g = cos(self%contacts(k)%geometry%gamma0)
         approach = dz*cos_g - self%contacts(k)%geometry%gap0
         if (self%fill) then
            call fill_patch(self%contacts(k), approach, self%patches(k), error)
            load = self%patches(k)%load
         else
            call patch_load(self%contacts(k), approach, self%patches(k), load, error)
         end if
         if (allocated(error)) then
            if (.not. allocated(self%error)) call move_alloc(error, self%error)
            fx = self%target_23
            return
         end if
         self%force = self%force + load*cos_g
      end do
      fx = self%force**(2.0_wp/3.0_wp) - self%target_23
   end function vertical_residual_eval

end module shcontact_normal_loading
