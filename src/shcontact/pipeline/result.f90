!> The results of one contact solve: per patch, the main patch and the track-frame totals
!> ([[contact_result_type]]), and copies of the fields ([[contact_fields_type]]).
module shcontact_pipeline_result
   use shcontact_core_kinds, only: wp
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_geometry_contact, only: max_candidates
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_tangential_solver, only: track_forces_type
   use shcontact_tangential_lobes, only: joined_lobes_type
   implicit none
   private

   public :: contact_result_type, patch_result_type, contact_fields_type, max_patches

   !> Most patches one contact may have (the contact search follows at most 16 candidates).
   integer, parameter :: max_patches = max_candidates

   !> The solution of one patch (forces on the wheel, doc/theory.md decision 2).
   type :: patch_result_type
      !> Tangential forces F_x, F_y (N, contact frame) and spin moment M_z about the reference
      !> point (N·mm).
      real(wp) :: fx = 0.0_wp, fy = 0.0_wp, mz = 0.0_wp
      !> Normal force F_n (N).
      real(wp) :: fn = 0.0_wp
      !> Normalised forces F/(μ F_n).
      real(wp) :: fx_norm = 0.0_wp, fy_norm = 0.0_wp
      !> Lateral and vertical force in the track frame (N, z down), in the wheel's side frame: y
      !> towards the wheel's own field side (for the left wheel multiply F_y by −1 to get the
      !> track frame's y, doc/api.md).
      real(wp) :: fy_track = 0.0_wp, fz_track = 0.0_wp
      !> Approach δ (mm), contact area (mm²), largest strip peak pressure (MPa).
      real(wp) :: approach = 0.0_wp, area = 0.0_wp, p_max = 0.0_wp
      !> Contact angle γ₀ (rad, CONTACT's sign) and rolling radius r₀ (mm) at the reference point:
      !> the first contact of the contact search, and for a loaded patch the geometric contact
      !> point of the loaded state, where the creepages are given (doc/geometry.md "Vertical
      !> approach").
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp
      !> Contact angle of the contact plane (rad, CONTACT's sign): that of the first contact.
      !> F_n is normal to this plane, and a vertical load is shared as Σ F_n cos γ_plane = F_z.
      real(wp) :: gamma_plane = 0.0_wp
      !> Reference point in track coordinates (mm; y from the track centre, z down), the same
      !> point.
      real(wp) :: y_track = 0.0_wp, z_track = 0.0_wp
      !> Coulomb check max|p|/(μ p_n,e) and adhesion area fraction.
      real(wp) :: coulomb_ratio = 0.0_wp, adhesion_fraction = 0.0_wp
      !> Creepages used at the reference point (ν_x, ν_y, φ in rad/mm; wheel relative to rail):
      !> those given to [[solve]], or those of the wheelset's motion in [[solve_kinematic]].
      real(wp) :: nu_x = 0.0_wp, nu_y = 0.0_wp, phi = 0.0_wp
      !> Longitudinal position of the reference point in the track frame (mm, forward; nonzero
      !> with a yaw angle, shcontact_geometry_kinematics).
      real(wp) :: x_track = 0.0_wp
   end type patch_result_type

   !> The result of one solve. Fixed size: filling it allocates nothing.
   type :: contact_result_type
      !> Patches found by the contact search (deepest first).
      integer :: n_patches = 0
      !> Patches solved: 1 for a normal force or approach, n_patches for a vertical load.
      integer :: n_loaded = 0
      !> The most loaded patch (the app's "main" patch).
      integer :: main_patch = 0
      !> Rigid vertical approach Δz of the wheel (mm), vertical load only.
      real(wp) :: dz = 0.0_wp
      !> The main patch: patch(main_patch).
      type(patch_result_type) :: main
      !> Totals over the loaded patches, forces on the wheel in the track frame (N; side frame:
      !> the left wheel's F_y is the mirror image, see patch_result_type%fy_track).
      type(track_forces_type) :: track
      !> Every patch; patches beyond n_loaded carry their geometry only.
      type(patch_result_type) :: patch(max_patches)
      !> The wheel's contact as the exact theory reports it where it joins close lobes into one
      !> patch (CONTACT's 4 mm rule; shcontact_tangential_lobes, doc/lobes.md): the main patch and
      !> the loaded patches within 4 mm of it, forces summed, f = ΣF/(μΣF_n).
      type(joined_lobes_type) :: wheel
   end type contact_result_type

   !> Copies of the fields of one solve (doc/theory.md decision 12): per patch its strip tables, the
   !> normal strips and the tangential element fields. The arrays are reused from call to call and
   !> reallocated only when their size changes.
   type :: contact_fields_type
      !> Patches filled (the loaded ones).
      integer :: n_patches = 0
      !> Geometry tables of each patch.
      type(patch_geometry_type) :: geometry(max_patches)
      !> Normal solution (strips) of each patch.
      type(normal_patch_type) :: normal(max_patches)
      !> Tangential solution (elements) of each patch.
      type(tangential_patch_type) :: tangential(max_patches)
   end type contact_fields_type

end module shcontact_pipeline_result
