!> The result of one case: the summary numbers every case has, and the per-patch solutions that
!> are kept when fields are stored.
module shcontact_case_result
   use shcontact_core_kinds, only: wp
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_patch, only: tangential_patch_type
   use shcontact_pipeline_result, only: contact_result_type, patch_result_type, &
      patch_column_type, patch_columns, patch_value, set_patch_value, wheel_contact_type, &
      wheel_contact_of, wheel_columns, wheel_value, set_wheel_value
   implicit none
   private

   public :: case_summary_type, case_result_type, summary_columns, n_summary_columns
   public :: summary_value, set_summary_value, case_not_run, failure_type
   public :: summary_column_used, case_summary, summary_column_help, summary_column_counts

   !> Index of the implied loops of the column tables.
   integer, private :: k_

   !> Status of a case that has not been solved yet.
   integer, parameter :: case_not_run = -1

   !> The numbers of one case that go into the `/summary` table (forces on the wheel,
   !> doc/theory.md decision 2). The totals are summed over the loaded patches, the `wheel_*`
   !> values over the patches of the wheel's joined contact; the other values are those of the
   !> main patch (the one carrying the largest normal force): the inherited
   !> components, whose `/summary` columns are those of shcontact_pipeline_result's
   !> `patch_columns` (e.g. `fn`, `fx`, `approach` as column `delta`, `x_track`, `nu_x`).
   type, extends(patch_result_type) :: case_summary_type
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
      !> The wheel's joined contact (the patches the exact theory joins into one, doc/lobes.md;
      !> its `/summary` columns are shcontact_pipeline_result's `wheel_columns`).
      type(wheel_contact_type) :: wheel
      !> The main patch's contact lies on the flange beyond its steepest part
      !> (contact_result_type%climbing; column `climbing`, 1 or 0).
      logical :: climbing = .false.
   end type case_summary_type

   !> The totals' columns of `/summary` (name, units, description), before the main patch's.
   type(patch_column_type), parameter :: total_columns(*) = [ &
      patch_column_type('fn_total', 'fn_total', 'N', .false., &
      'sum of the normal forces of all patches'), &
      patch_column_type('fx_total', 'fx_total', 'N', .false., &
      'total longitudinal force on the wheel, track frame'), &
      patch_column_type('fy_total', 'fy_total', 'N', .false., &
      'total lateral force on the wheel, track frame (field side +)'), &
      patch_column_type('fz_total', 'fz_total', 'N', .false., &
      'total vertical force on the wheel, track frame (down +)')]
   !> The real columns of `/summary` in file order: the totals, then the main patch's values
   !> that have a `/summary` column, then the wheel's joined contact.
   !> The case's flags, after the joined contact's columns (stored as integers, 1 or 0).
   type(patch_column_type), parameter :: flag_columns(*) = [ &
      patch_column_type('climbing', 'climbing', '1', .false., &
      '1: the main patch lies on the flange beyond its steepest part (flange climbing)')]
   type(patch_column_type), parameter :: columns(*) = [total_columns, &
      pack(patch_columns, patch_columns%summary /= ''), wheel_columns, flag_columns]
   !> Index in `patch_columns` of each real column (0 for a total or a joined contact's value).
   integer, parameter :: column_patch_index(*) = [spread(0, 1, size(total_columns)), &
      pack([(k_, k_=1, size(patch_columns))], patch_columns%summary /= ''), &
      spread(0, 1, size(wheel_columns) + size(flag_columns))]
   !> Columns before the joined contact's.
   integer, parameter :: first_flag_column = size(columns) - size(flag_columns)
   integer, parameter :: first_wheel_column = first_flag_column - size(wheel_columns)
   integer, parameter :: n_summary_columns = size(columns)
   !> Names and units of the real summary columns, in file order.
   character(len=*), parameter :: summary_columns(2, n_summary_columns) = reshape( &
      [character(len=17) :: (columns(k_)%summary, columns(k_)%units, k_=1, n_summary_columns)], &
      [2, n_summary_columns])

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
      s%patch_result_type = contact%main
      s%wheel = wheel_contact_of(contact%wheel)
      s%climbing = contact%climbing
   end function case_summary

   !> True when real summary column `k` belongs to a run (kinematic or not).
   pure logical function summary_column_used(k, kinematic)
      !> Column number.
      integer, intent(in) :: k
      !> The run is kinematic.
      logical, intent(in) :: kinematic
      summary_column_used = kinematic .or. .not. columns(k)%kinematic
   end function summary_column_used

   !> True when summary column `k` is a count (stored as integers, as `n_loaded` is).
   pure logical function summary_column_counts(k)
      !> Column number.
      integer, intent(in) :: k
      summary_column_counts = columns(k)%summary == 'wheel_patches' .or. k > first_flag_column
   end function summary_column_counts

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
      case (first_flag_column + 1:)
         summary_value = merge(1.0_wp, 0.0_wp, s%climbing)
      case (first_wheel_column + 1:first_flag_column)
         summary_value = wheel_value(s%wheel, k - first_wheel_column)
      case default; summary_value = patch_value(s%patch_result_type, column_patch_index(k))
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
      case (first_flag_column + 1:)
         s%climbing = value /= 0.0_wp
      case (first_wheel_column + 1:first_flag_column)
         call set_wheel_value(s%wheel, k - first_wheel_column, value)
      case default; call set_patch_value(s%patch_result_type, column_patch_index(k), value)
      end select
   end subroutine set_summary_value

   !> The HDF5 description of real summary column `name` ('' when it is none).
   pure function summary_column_help(name) result(text)
      !> The column's name.
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: text
      integer :: k
      k = findloc(columns%summary, name, 1)
      text = ''
      if (k > 0) text = trim(columns(k)%help)
   end function summary_column_help

end module shcontact_case_result
