!> The tangential solution of one contact patch: element fields and totals (doc/theory.md decision 12).
module shcontact_tangential_patch
   use shcontact_core_kinds, only: wp, i1
   implicit none
   private

   public :: tangential_patch_type
   public :: state_exterior, state_adhesion, state_slip

   !> Element state codes, as CONTACT: exterior.
   integer(i1), parameter :: state_exterior = 0_i1
   !> Adhesion (stick).
   integer(i1), parameter :: state_adhesion = 1_i1
   !> Slip.
   integer(i1), parameter :: state_slip = 2_i1

   !> Fields on the strip-adapted grid: element (j, i) is element j (from the leading edge) of
   !> strip i. Forces act on the wheel (doc/theory.md decision 2).
   type :: tangential_patch_type
      !> Elements per strip and strips.
      integer :: nx = 0, ny = 0
      !> Total tangential forces (N) and spin moment about the reference point (N·mm).
      real(wp) :: fx = 0.0_wp, fy = 0.0_wp, mz = 0.0_wp
      !> Normal force of the patch (N).
      real(wp) :: fn = 0.0_wp
      !> Normalised forces f = F/(μ F_n).
      real(wp) :: fx_norm = 0.0_wp, fy_norm = 0.0_wp
      !> Coulomb check max |p|/(μ p_n,e) over contact elements, of the tractions as reported:
      !> after the exact-ellipse correction and the Coulomb limit of the totals (doc/tangential.md).
      real(wp) :: coulomb_ratio = 0.0_wp
      !> Adhesion area / contact area.
      real(wp) :: adhesion_fraction = 0.0_wp
      !> Parabolic-bound load ratio (32/(9π)) Σ k_i N_i / F_n (doc/theory.md §6.4): the full-slip
      !> force of the pure parabolic bound over μF_n (1 on a Hertz ellipse).
      real(wp) :: parabolic_load_ratio = 0.0_wp
      !> Forces on the wheel in the track frame (x rolling, y lateral towards the field side,
      !> z down, CONTACT's track frame), each strip's lateral force F_y,i and normal force N_i
      !> turned by the strip's own contact angle γ_i (N): fy_track = Σ F_y,i cos γ_i + N_i sin γ_i,
      !> fz_track = Σ F_y,i sin γ_i − N_i cos γ_i (γ_i = γ₀ on a Hertz ellipse). The strips of a
      !> curved patch push along their own normals, so the totals do not jump when the reference
      !> point moves across the patch.
      real(wp) :: fy_track = 0.0_wp, fz_track = 0.0_wp
      !> Element centres (mm): x(j, i) and the strip centres y(i).
      real(wp), allocatable :: x(:, :)
      real(wp), allocatable :: y(:)
      !> Element lengths Δx_i (mm) and the strip width (mm).
      real(wp), allocatable :: dx(:)
      real(wp) :: dy = 0.0_wp
      !> Normal pressure p_n,e (semi-ellipsoidal, MPa) and tractions on the wheel (MPa).
      real(wp), allocatable :: pn(:, :), px(:, :), py(:, :)
      !> Slip magnitude |s| (dimensionless, slip velocity / rolling speed) in slip elements.
      real(wp), allocatable :: slip(:, :)
      !> State: [[state_exterior]], [[state_adhesion]] or [[state_slip]].
      integer(i1), allocatable :: state(:, :)
   end type tangential_patch_type

end module shcontact_tangential_patch
