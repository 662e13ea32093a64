!> The result of one case: the summary numbers every case has, and the per-patch solutions that
!> are kept when fields are stored.
module shcontact_case_result
   use shcontact_core_kinds, only: wp
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_pipeline_result, only: contact_result_type
   implicit none
   private

   public :: case_summary_type, case_result_type, summary_columns, n_summary_columns
   public :: summary_value, set_summary_value, case_not_run, failure_type
   public :: summary_column_used, case_summary

   !> Status of a case that has not been solved yet.
   integer, parameter :: case_not_run = -1

   !> The numbers of one case that go into the `/summary` table (forces on the wheel,
   !> doc/theory.md decision 2). The totals are summed over the loaded patches; the other values
   !> are those of the main patch (the one carrying the largest normal force).
   type :: case_summary_type
      !> 0 when solved; otherwise the error status ([[case_not_run]] before it runs).
      integer :: stat = case_not_run
      !> Number of contact patches found by the contact search (/geometry/patch_1..n_patches).
      integer :: n_patches = 0
      !> Number of patches the load is applied to and solved (1..n_loaded; /cases/.../patch_K):
      !> 1 for `&load mode = 'force'` or `'approach'` (the deepest patch), n_patches for
      !> 'vertical'.
      integer :: n_loaded = 0
      !> Index of the main patch.
      integer :: main_patch = 0
      !> Total normal force of all patches (N).
      real(wp) :: fn_total = 0.0_wp
      !> Total forces in the track frame (N): ΣF_x (longitudinal), ΣF_y,track (lateral, towards
      !> the field side), ΣF_z,track (vertical, down).
      real(wp) :: fx_total = 0.0_wp, fy_total = 0.0_wp, fz_total = 0.0_wp
      !> Main patch: normal force (N), tangential forces (N), spin moment (N·mm).
      real(wp) :: fn = 0.0_wp, fx = 0.0_wp, fy = 0.0_wp, mz = 0.0_wp
      !> Main patch: normalised forces F/(μ F_n).
      real(wp) :: fx_norm = 0.0_wp, fy_norm = 0.0_wp
      !> Main patch: Coulomb check max|p|/(μ p_n) and adhesion area fraction.
      real(wp) :: coulomb_ratio = 0.0_wp, adhesion_fraction = 0.0_wp
      !> Main patch: approach δ (mm; column `delta` of /summary), contact area (mm²), peak
      !> pressure (MPa).
      real(wp) :: approach = 0.0_wp, area = 0.0_wp, p_max = 0.0_wp
      !> Main patch: contact angle γ₀ (rad), rolling radius r₀ (mm), lateral track position of
      !> the reference point (mm).
      real(wp) :: gamma0 = 0.0_wp, r0 = 0.0_wp, y_track = 0.0_wp
      !> Kinematic cases, main patch: longitudinal position of the reference point (mm, track
      !> frame, + forward: the lead of a yawed wheelset) and the creepages of the wheelset
      !> motion there (ν_x, ν_y; φ in rad/mm).
      real(wp) :: x_track = 0.0_wp, nu_x = 0.0_wp, nu_y = 0.0_wp, phi = 0.0_wp
   end type case_summary_type

   !> Names and units of the real summary columns, in file order.
   integer, parameter :: n_summary_columns = 22
   character(len=*), parameter :: summary_columns(2, n_summary_columns) = reshape( &
      [character(len=17) :: &
      'fn_total', 'N', 'fx_total', 'N', 'fy_total', 'N', 'fz_total', 'N', &
      'fn', 'N', 'fx', 'N', 'fy', 'N', 'mz', 'N mm', 'fx_norm', '1', &
      'fy_norm', '1', 'coulomb_ratio', '1', 'adhesion_fraction', '1', 'delta', 'mm', &
      'area', 'mm^2', 'p_max', 'MPa', 'gamma0', 'rad', 'r0', 'mm', 'y_track', 'mm', &
      'x_track', 'mm', 'nu_x', '1', 'nu_y', '1', 'phi', 'rad/mm'], &
      [2, n_summary_columns])
   !> The columns that only kinematic runs have (prescribed creepages are inputs).
   logical, parameter :: summary_column_kinematic(n_summary_columns) = &
      [spread(.false., 1, n_summary_columns - 4), spread(.true., 1, 4)]

   !> Everything one case produced.
   type :: case_result_type
      !> The summary numbers.
      type(case_summary_type) :: summary
      !> Why the case failed (when summary%stat > 0).
      character(len=:), allocatable :: message
      !> Per-patch geometry, normal and tangential solutions (kept when fields are stored).
      type(patch_geometry_type), allocatable :: geometry(:)
      type(normal_patch_type), allocatable :: normal(:)
      type(tangential_patch_type), allocatable :: tangential(:)
      !> Kinematic cases (kept with the fields): per patch the creepages of the wheelset motion
      !> at its reference point (ν_x, ν_y, φ in rad/mm) and the reference point's longitudinal
      !> position x_track (mm).
      real(wp), allocatable :: nu_x(:), nu_y(:), phi(:), x_track(:)
   end type case_result_type

   !> A failed case and why.
   type :: failure_type
      !> Case number.
      integer :: case = 0
      !> The error message.
      character(len=:), allocatable :: message
   end type failure_type

contains

   !> The summary numbers of a solved case: the track-frame totals and the main patch of the
   !> pipeline's result (shcontact_pipeline_stages), for prescribed and kinematic cases alike.
   pure function case_summary(contact) result(s)
      !> The stage results' summary.
      type(contact_result_type), intent(in) :: contact
      type(case_summary_type) :: s
      s%stat = 0
      s%n_patches = contact%n_patches
      s%n_loaded = contact%n_loaded
      s%main_patch = contact%main_patch
      s%fn_total = contact%track%fn
      s%fx_total = contact%track%fx
      s%fy_total = contact%track%fy
      s%fz_total = contact%track%fz
      associate (m => contact%main)
         s%fn = m%fn
         s%fx = m%fx
         s%fy = m%fy
         s%mz = m%mz
         s%fx_norm = m%fx_norm
         s%fy_norm = m%fy_norm
         s%coulomb_ratio = m%coulomb_ratio
         s%adhesion_fraction = m%adhesion_fraction
         s%approach = m%approach
         s%area = m%area
         s%p_max = m%p_max
         s%gamma0 = m%gamma0
         s%r0 = m%r0
         s%y_track = m%y_track
         s%x_track = m%x_track
         s%nu_x = m%nu_x
         s%nu_y = m%nu_y
         s%phi = m%phi
      end associate
   end function case_summary

   !> True when real summary column `k` belongs to a run (kinematic or not).
   pure logical function summary_column_used(k, kinematic)
      !> Column number.
      integer, intent(in) :: k
      !> The run is kinematic.
      logical, intent(in) :: kinematic
      summary_column_used = kinematic .or. .not. summary_column_kinematic(k)
   end function summary_column_used

   !> The value of real summary column `k` (numbering of [[summary_columns]]).
   pure real(wp) function summary_value(s, k)
      !> The summary.
      type(case_summary_type), intent(in) :: s
      !> Column number.
      integer, intent(in) :: k
      select case (k)
      case (1); summary_value = s%fn_total
      case (2); summary_value = s%fx_total
      case (3); summary_value = s%fy_total
      case (4); summary_value = s%fz_total
      case (5); summary_value = s%fn
      case (6); summary_value = s%fx
      case (7); summary_value = s%fy
      case (8); summary_value = s%mz
      case (9); summary_value = s%fx_norm
      case (10); summary_value = s%fy_norm
      case (11); summary_value = s%coulomb_ratio
      case (12); summary_value = s%adhesion_fraction
      case (13); summary_value = s%approach
      case (14); summary_value = s%area
      case (15); summary_value = s%p_max
      case (16); summary_value = s%gamma0
      case (17); summary_value = s%r0
      case (18); summary_value = s%y_track
      case (19); summary_value = s%x_track
      case (20); summary_value = s%nu_x
      case (21); summary_value = s%nu_y
      case default; summary_value = s%phi
      end select
   end function summary_value

   !> Set real summary column `k`.
   pure subroutine set_summary_value(s, k, value)
      !> The summary.
      type(case_summary_type), intent(inout) :: s
      !> Column number.
      integer, intent(in) :: k
      !> The value.
      real(wp), intent(in) :: value
      select case (k)
      case (1); s%fn_total = value
      case (2); s%fx_total = value
      case (3); s%fy_total = value
      case (4); s%fz_total = value
      case (5); s%fn = value
      case (6); s%fx = value
      case (7); s%fy = value
      case (8); s%mz = value
      case (9); s%fx_norm = value
      case (10); s%fy_norm = value
      case (11); s%coulomb_ratio = value
      case (12); s%adhesion_fraction = value
      case (13); s%approach = value
      case (14); s%area = value
      case (15); s%p_max = value
      case (16); s%gamma0 = value
      case (17); s%r0 = value
      case (18); s%y_track = value
      case (19); s%x_track = value
      case (20); s%nu_x = value
      case (21); s%nu_y = value
      case default; s%phi = value
      end select
   end subroutine set_summary_value

end module shcontact_case_result
