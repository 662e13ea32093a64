!> The results of one contact solve: per patch, the main patch, the track-frame totals and the
!> wheel's joined contact ([[contact_result_type]]), and copies of the fields
!> ([[contact_fields_type]]).
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
   public :: patch_column_type, patch_columns, patch_value, set_patch_value, find_patch_column
   public :: wheel_contact_type, wheel_contact_of, wheel_columns, wheel_value, set_wheel_value, &
      find_wheel_column

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
      !> F_n is normal to this plane; a vertical load is carried by the strips' vertical force
      !> Σ N_i cos γ_i (doc/theory.md §4.6).
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

   !> One value of a patch by name (issue 26: the one column table of the per-patch results):
   !> the name of the C / Fortran 77 keyed getter (`shcontact_get_value`, `SHC_GET_VALUE`), the
   !> main patch's `/summary` column ('' when it has none), units, whether the column belongs to
   !> kinematic runs only (prescribed creepages are inputs), and the HDF5 description of the
   !> column. [[patch_value]] and [[set_patch_value]] are the one accessor of each.
   type :: patch_column_type
      character(len=17) :: name = ''
      character(len=17) :: summary = ''
      character(len=8) :: units = ''
      logical :: kinematic = .false.
      character(len=120) :: help = ''
   end type patch_column_type

   !> The per-patch values, the `/summary` columns first and in the file's order (after the
   !> totals of shcontact_case_result). A new per-patch output is a field of
   !> [[patch_result_type]], a row here and its line in [[patch_value]] and [[set_patch_value]]:
   !> `/summary` (with its HDF5 description), the CSV / JSON reports and the keyed getters take it
   !> from here. The flat value arrays (shcontact_api_values) are a frozen binary layout.
   type(patch_column_type), parameter :: patch_columns(*) = [ &
      patch_column_type('fn', 'fn', 'N', .false., 'normal force of the main patch'), &
      patch_column_type('fx', 'fx', 'N', .false., &
      'longitudinal creep force on the wheel, main patch, contact frame'), &
      patch_column_type('fy', 'fy', 'N', .false., &
      'lateral creep force on the wheel, main patch, contact frame'), &
      patch_column_type('mz', 'mz', 'N mm', .false., &
      'spin moment on the wheel about the reference point, main patch'), &
      patch_column_type('fx_norm', 'fx_norm', '1', .false., &
      'normalised longitudinal force F_x/(mu F_n), main patch'), &
      patch_column_type('fy_norm', 'fy_norm', '1', .false., &
      'normalised lateral force F_y/(mu F_n), main patch'), &
      patch_column_type('coulomb', 'coulomb_ratio', '1', .false., &
      'largest |p|/(mu p_n) over contact elements, of the corrected tractions (the totals '// &
      'keep |F_t| <= mu F_n)'), &
      patch_column_type('adhesion', 'adhesion_fraction', '1', .false., &
      'adhesion (stick) area / contact area, main patch'), &
      patch_column_type('approach', 'delta', 'mm', .false., 'approach delta of the main patch'), &
      patch_column_type('area', 'area', 'mm^2', .false., 'contact area of the main patch'), &
      patch_column_type('p_max', 'p_max', 'MPa', .false., &
      'largest peak pressure of the main patch'), &
      patch_column_type('gamma0', 'gamma0', 'rad', .false., &
      'contact angle at the main patch reference point (CONTACT sign)'), &
      patch_column_type('r0', 'r0', 'mm', .false., &
      'wheel rolling radius at the main patch reference point'), &
      patch_column_type('y_track', 'y_track', 'mm', .false., &
      'lateral track position of the main patch reference point'), &
      patch_column_type('x_track', 'x_track', 'mm', .true., &
      'longitudinal position of the main patch reference point (track frame, + forward)'), &
      patch_column_type('nu_x', 'nu_x', '1', .true., &
      'longitudinal creepage nu_x of the wheel relative to the rail (input, or from the '// &
      'wheelset motion in a kinematic run)'), &
      patch_column_type('nu_y', 'nu_y', '1', .true., &
      'lateral creepage nu_y (input, or from the wheelset motion in a kinematic run)'), &
      patch_column_type('phi', 'phi', 'rad/mm', .true., &
      'spin creepage phi (input, or from the wheelset motion in a kinematic run)'), &
      patch_column_type('fy_track', '', 'N', .false., 'lateral force, track frame'), &
      patch_column_type('fz_track', '', 'N', .false., 'vertical force, track frame, z down'), &
      patch_column_type('z_track', '', 'mm', .false., 'reference point, track z (down)')]

   !> The wheel's joined contact (contact_result_type%wheel, doc/lobes.md) as the outputs carry
   !> it: the values of [[wheel_columns]] and no more (a sweep keeps one per case).
   type :: wheel_contact_type
      !> Patches joined (0: none loaded).
      integer :: n_members = 0
      !> Σ F_n, Σ F_x, Σ F_y (N), f = ΣF/(μΣF_n), Σ area (mm²), largest peak pressure (MPa).
      real(wp) :: fn = 0.0_wp, fx = 0.0_wp, fy = 0.0_wp, fx_norm = 0.0_wp, fy_norm = 0.0_wp
      real(wp) :: area = 0.0_wp, p_max = 0.0_wp
   end type wheel_contact_type

   !> The values of the wheel's joined contact by name (issue 28 item 3): the keyed getters'
   !> name, the `/summary` column (the same), units and HDF5 description. Like
   !> [[patch_columns]], a row here reaches `/summary`, the CSV / JSON reports and the keyed
   !> getters; [[wheel_value]] and [[set_wheel_value]] are the one accessor of each.
   type(patch_column_type), parameter :: wheel_columns(*) = [ &
      patch_column_type('wheel_patches', 'wheel_patches', '1', .false., &
      'patches in the wheel''s joined contact: the main patch and the loaded ones within 4 mm '// &
      '(exact theory''s one patch)'), &
      patch_column_type('wheel_fn', 'wheel_fn', 'N', .false., &
      'normal force of the wheel''s joined contact (sum over its patches)'), &
      patch_column_type('wheel_fx', 'wheel_fx', 'N', .false., &
      'longitudinal creep force on the wheel, joined contact (sum over its patches, each '// &
      'contact frame)'), &
      patch_column_type('wheel_fy', 'wheel_fy', 'N', .false., &
      'lateral creep force on the wheel, joined contact (sum over its patches, each contact '// &
      'frame)'), &
      patch_column_type('wheel_fx_norm', 'wheel_fx_norm', '1', .false., &
      'normalised longitudinal force of the joined contact, sum F_x/(mu sum F_n): the exact '// &
      'theory''s f_x'), &
      patch_column_type('wheel_fy_norm', 'wheel_fy_norm', '1', .false., &
      'normalised lateral force of the joined contact, sum F_y/(mu sum F_n): the exact '// &
      'theory''s f_y'), &
      patch_column_type('wheel_area', 'wheel_area', 'mm^2', .false., &
      'contact area of the wheel''s joined contact (sum over its patches)'), &
      patch_column_type('wheel_p_max', 'wheel_p_max', 'MPa', .false., &
      'largest peak pressure of the wheel''s joined contact')]

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
      !> The main patch's contact lies on the wheel flange beyond its steepest part (its rolling
      !> radius exceeds the steep end's by more than 0.1 mm, shcontact_geometry_flange): a
      !> flange-climbing state, which a rigid wheelset reaches only by climbing the flange.
      logical :: climbing = .false.
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

contains

   !> Index of the per-patch value `name` in [[patch_columns]] (by its getter name, or by its
   !> `/summary` column when `summary` is true); 0 when there is none.
   pure integer function find_patch_column(name, summary) result(k)
      !> The name.
      character(len=*), intent(in) :: name
      !> Look the name up among the `/summary` columns.
      logical, intent(in) :: summary
      if (summary) then
         k = findloc(patch_columns%summary, name, 1)
      else
         k = findloc(patch_columns%name, name, 1)
      end if
   end function find_patch_column

   !> The joined contact's values that the outputs carry.
   pure function wheel_contact_of(joined) result(w)
      !> The joined contact (contact_result_type%wheel).
      type(joined_lobes_type), intent(in) :: joined
      type(wheel_contact_type) :: w
      w = wheel_contact_type(joined%n_members, joined%fn, joined%fx, joined%fy, &
         joined%fx_norm, joined%fy_norm, joined%area, joined%p_max)
   end function wheel_contact_of

   !> Index of value `name` in [[wheel_columns]]; 0 when there is none.
   pure integer function find_wheel_column(name) result(k)
      !> The name (getter and `/summary` column alike).
      character(len=*), intent(in) :: name
      k = findloc(wheel_columns%name, name, 1)
   end function find_wheel_column

   !> Value `k` ([[wheel_columns]]) of the wheel's joined contact.
   pure real(wp) function wheel_value(w, k) result(x)
      !> The joined contact.
      type(wheel_contact_type), intent(in) :: w
      !> Index in [[wheel_columns]].
      integer, intent(in) :: k
      select case (k)
      case (findloc(wheel_columns%name, 'wheel_patches', 1)); x = real(w%n_members, wp)
      case (findloc(wheel_columns%name, 'wheel_fn', 1)); x = w%fn
      case (findloc(wheel_columns%name, 'wheel_fx', 1)); x = w%fx
      case (findloc(wheel_columns%name, 'wheel_fy', 1)); x = w%fy
      case (findloc(wheel_columns%name, 'wheel_fx_norm', 1)); x = w%fx_norm
      case (findloc(wheel_columns%name, 'wheel_fy_norm', 1)); x = w%fy_norm
      case (findloc(wheel_columns%name, 'wheel_area', 1)); x = w%area
      case (findloc(wheel_columns%name, 'wheel_p_max', 1)); x = w%p_max
      case default; x = 0.0_wp
      end select
   end function wheel_value

   !> Set value `k` ([[wheel_columns]]) of the wheel's joined contact (a `/summary` row read back
   !> from a file).
   pure subroutine set_wheel_value(w, k, x)
      !> The joined contact.
      type(wheel_contact_type), intent(inout) :: w
      !> Index in [[wheel_columns]].
      integer, intent(in) :: k
      !> The value.
      real(wp), intent(in) :: x
      select case (k)
      case (findloc(wheel_columns%name, 'wheel_patches', 1)); w%n_members = nint(x)
      case (findloc(wheel_columns%name, 'wheel_fn', 1)); w%fn = x
      case (findloc(wheel_columns%name, 'wheel_fx', 1)); w%fx = x
      case (findloc(wheel_columns%name, 'wheel_fy', 1)); w%fy = x
      case (findloc(wheel_columns%name, 'wheel_fx_norm', 1)); w%fx_norm = x
      case (findloc(wheel_columns%name, 'wheel_fy_norm', 1)); w%fy_norm = x
      case (findloc(wheel_columns%name, 'wheel_area', 1)); w%area = x
      case (findloc(wheel_columns%name, 'wheel_p_max', 1)); w%p_max = x
      end select
   end subroutine set_wheel_value

   !> Value `k` ([[patch_columns]]) of a patch. The cases are the rows' indices, constant
   !> expressions on the table, so that a lookup costs no string comparison (/summary reads
   !> every value of every case); test `registry/output_column_table` reads every row.
   pure real(wp) function patch_value(p, k) result(x)
      !> The patch.
      type(patch_result_type), intent(in) :: p
      !> Index in [[patch_columns]].
      integer, intent(in) :: k
      select case (k)
      case (findloc(patch_columns%name, 'fn', 1)); x = p%fn
      case (findloc(patch_columns%name, 'fx', 1)); x = p%fx
      case (findloc(patch_columns%name, 'fy', 1)); x = p%fy
      case (findloc(patch_columns%name, 'mz', 1)); x = p%mz
      case (findloc(patch_columns%name, 'fx_norm', 1)); x = p%fx_norm
      case (findloc(patch_columns%name, 'fy_norm', 1)); x = p%fy_norm
      case (findloc(patch_columns%name, 'coulomb', 1)); x = p%coulomb_ratio
      case (findloc(patch_columns%name, 'adhesion', 1)); x = p%adhesion_fraction
      case (findloc(patch_columns%name, 'approach', 1)); x = p%approach
      case (findloc(patch_columns%name, 'area', 1)); x = p%area
      case (findloc(patch_columns%name, 'p_max', 1)); x = p%p_max
      case (findloc(patch_columns%name, 'gamma0', 1)); x = p%gamma0
      case (findloc(patch_columns%name, 'r0', 1)); x = p%r0
      case (findloc(patch_columns%name, 'y_track', 1)); x = p%y_track
      case (findloc(patch_columns%name, 'x_track', 1)); x = p%x_track
      case (findloc(patch_columns%name, 'nu_x', 1)); x = p%nu_x
      case (findloc(patch_columns%name, 'nu_y', 1)); x = p%nu_y
      case (findloc(patch_columns%name, 'phi', 1)); x = p%phi
      case (findloc(patch_columns%name, 'fy_track', 1)); x = p%fy_track
      case (findloc(patch_columns%name, 'fz_track', 1)); x = p%fz_track
      case (findloc(patch_columns%name, 'z_track', 1)); x = p%z_track
      case default; x = 0.0_wp
      end select
   end function patch_value

   !> Set value `k` ([[patch_columns]]) of a patch (a `/summary` row read back from a file).
   pure subroutine set_patch_value(p, k, x)
      !> The patch.
      type(patch_result_type), intent(inout) :: p
      !> Index in [[patch_columns]].
      integer, intent(in) :: k
      !> The value.
      real(wp), intent(in) :: x
      select case (k)
      case (findloc(patch_columns%name, 'fn', 1)); p%fn = x
      case (findloc(patch_columns%name, 'fx', 1)); p%fx = x
      case (findloc(patch_columns%name, 'fy', 1)); p%fy = x
      case (findloc(patch_columns%name, 'mz', 1)); p%mz = x
      case (findloc(patch_columns%name, 'fx_norm', 1)); p%fx_norm = x
      case (findloc(patch_columns%name, 'fy_norm', 1)); p%fy_norm = x
      case (findloc(patch_columns%name, 'coulomb', 1)); p%coulomb_ratio = x
      case (findloc(patch_columns%name, 'adhesion', 1)); p%adhesion_fraction = x
      case (findloc(patch_columns%name, 'approach', 1)); p%approach = x
      case (findloc(patch_columns%name, 'area', 1)); p%area = x
      case (findloc(patch_columns%name, 'p_max', 1)); p%p_max = x
      case (findloc(patch_columns%name, 'gamma0', 1)); p%gamma0 = x
      case (findloc(patch_columns%name, 'r0', 1)); p%r0 = x
      case (findloc(patch_columns%name, 'y_track', 1)); p%y_track = x
      case (findloc(patch_columns%name, 'x_track', 1)); p%x_track = x
      case (findloc(patch_columns%name, 'nu_x', 1)); p%nu_x = x
      case (findloc(patch_columns%name, 'nu_y', 1)); p%nu_y = x
      case (findloc(patch_columns%name, 'phi', 1)); p%phi = x
      case (findloc(patch_columns%name, 'fy_track', 1)); p%fy_track = x
      case (findloc(patch_columns%name, 'fz_track', 1)); p%fz_track = x
      case (findloc(patch_columns%name, 'z_track', 1)); p%z_track = x
      end select
   end subroutine set_patch_value

end module shcontact_pipeline_result
