!> The tangential solver's entry points: one patch by the configured method, or all patches of a
!> wheel, each in its own contact frame, with the totals also in the track frame.
!>
!> **Track frame** (CONTACT's): x rolling, y lateral towards the field side, z down. The contact
!> frame of patch k is turned about x by its reference contact angle γ_k (CONTACT's sign; the
!> tangent y axis is (cos γ_k, sin γ_k) in (y, z) and the normal into the rail is
!> (−sin γ_k, cos γ_k)). The wheel receives F_x, F_y along the tangent axes and the normal force
!> F_n against the normal, so in the track frame (forces on the wheel, z down):
!>
!>     F_y,track = F_y cos γ_k + F_n sin γ_k,   F_z,track = F_y sin γ_k − F_n cos γ_k,
!>
!> summed strip by strip with each strip's own contact angle γ_i in FASTSIM_SH (a curved patch
!> pushes along the normals of its strips; shcontact_tangential_patch).
!>
!> A right-wheel flange contact (γ ≈ −1.2 rad) thus pushes the wheel towards the track centre
!> (F_y,track < 0) and up (F_z,track < 0).
module shcontact_tangential_solver
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, prefix_error, stat_usage
   use shcontact_core_material, only: material_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_options, only: tangential_options_type, check_tangential_options, &
      method_fastsim
   use shcontact_tangential_creepage, only: creepage_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_march, only: march_workspace_type
   use shcontact_tangential_fastsim, only: solve_fastsim
   use shcontact_tangential_fastsim_sh, only: solve_fastsim_sh
   implicit none
   private

   public :: track_forces_type, solve_tangential, solve_tangential_patches

   !> Strips used by `method = 'fastsim'` when the normal patch has no strip table.
   integer, parameter :: default_fastsim_strips = 100

   !> Totals over the patches of one wheel, forces on the wheel (N).
   type :: track_forces_type
      !> Σ F_x (rolling direction, the same in every frame).
      real(wp) :: fx = 0.0_wp
      !> Σ F_y,track and Σ F_z,track (track frame, z down; see the module text).
      real(wp) :: fy = 0.0_wp, fz = 0.0_wp
      !> Σ F_n (the normal forces' magnitudes).
      real(wp) :: fn = 0.0_wp
   end type track_forces_type

contains

   !> Solve one patch with options%method: FASTSIM_SH on the strip table, or classical FASTSIM on
   !> the patch's Hertz ellipse (which needs a Hertz normal solution, patch%is_hertz).
   pure subroutine solve_tangential(ws, patch, material, creepage, options, result, error)
      !> The workspace (allocated only when its capacity grows).
      type(march_workspace_type), intent(inout) :: ws
      !> The normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Creepages at the reference point.
      type(creepage_type), intent(in) :: creepage
      !> The tangential options.
      type(tangential_options_type), intent(in) :: options
      !> The solution (arrays reallocated only when their shape changes).
      type(tangential_patch_type), intent(inout) :: result
      !> Set for invalid input or an impossible combination.
      type(error_type), allocatable, intent(out) :: error
      integer :: n_strips

      call check_tangential_options(options, error)
      if (allocated(error)) return
      if (options%method == method_fastsim) then
         if (.not. patch%is_hertz) then
            call fatal_error(error, "tangential method = 'fastsim' needs the Hertz ellipse of "// &
               "the reference point: solve the normal problem with method = 'hertz', or use "// &
               "method = 'fastsim-sh'", stat_usage)
            return
         end if
         n_strips = patch%n_strips
         if (n_strips < 1) n_strips = default_fastsim_strips
         call solve_fastsim(ws, patch%ellipse_a, patch%ellipse_b, patch%load, material, &
            creepage, options, n_strips, result, error, y_centre=patch%ellipse_y_centre, &
            gamma0=patch%gamma0)
      else
         call solve_fastsim_sh(ws, patch, material, creepage, options, result, error)
      end if
   end subroutine solve_tangential

   !> Solve every patch in its own contact frame with its own creepages and sum the forces in
   !> the track frame (module text). One workspace serves all patches.
   pure subroutine solve_tangential_patches(ws, patches, material, creepages, options, results, &
      track, error)
      !> The workspace (grows to the largest patch).
      type(march_workspace_type), intent(inout) :: ws
      !> The normal solutions of the patches.
      type(normal_patch_type), intent(in) :: patches(:)
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Creepages of each patch at its reference point, in its contact frame.
      type(creepage_type), intent(in) :: creepages(:)
      !> The tangential options.
      type(tangential_options_type), intent(in) :: options
      !> One solution per patch (size(patches) elements).
      type(tangential_patch_type), intent(inout) :: results(:)
      !> Totals over the patches, forces on the wheel in the track frame.
      type(track_forces_type), intent(out) :: track
      !> Set for invalid input; the message names the patch.
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: buf
      integer :: k

      if (size(creepages) /= size(patches) .or. size(results) /= size(patches)) then
         write (buf, '(i0)') size(patches)
         call fatal_error(error, 'solve_tangential_patches: expected one creepage set and one '// &
            'result per patch ('//trim(buf)//' patches)', stat_usage)
         return
      end if
      do k = 1, size(patches)
         call solve_tangential(ws, patches(k), material, creepages(k), options, results(k), error)
         if (allocated(error)) then
            write (buf, '(i0)') k
            call prefix_error(error, 'patch '//trim(buf))
            return
         end if
         track%fx = track%fx + results(k)%fx
         track%fy = track%fy + results(k)%fy_track
         track%fz = track%fz + results(k)%fz_track
         track%fn = track%fn + results(k)%fn
      end do
   end subroutine solve_tangential_patches

end module shcontact_tangential_solver
