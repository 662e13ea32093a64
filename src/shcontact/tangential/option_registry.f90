!> The registry of the tangential solver's option choices (issue 26): for every choice option
!> (`&tangential method, bound, spin_model, spin_flexibility, correction, contact_surface`)
!> its allowed values
!> with their integer codes and descriptions, and its default. [[shcontact_tangential_options]]
!> (the library's options and parsers), the case file's variable table
!> (shcontact_input_config_variables), the documentation's tables and the headers' option lists are
!> built from or checked against this one list (test `registry`).
module shcontact_tangential_option_registry
   use shcontact_core_choices, only: choice_type
   use shcontact_core_ranges, only: variables
   implicit none
   private

   public :: method_fastsim_sh, method_fastsim
   public :: bound_ellipsoidal, bound_parabolic, bound_weighted, bound_weighted_slip, bound_clipped
   public :: spin_additive, spin_uniform, spin_scaled, spin_geometric
   public :: spin_flexibility_spin, spin_flexibility_longitudinal
   public :: correction_none, correction_exact_ellipse
   public :: surface_wheel, surface_interface
   public :: method_choices, bound_choices, spin_model_choices, spin_flexibility_choices, &
      correction_choices, contact_surface_choices, option_choices
   public :: default_method, default_bound, default_spin_model, default_spin_flexibility, &
      default_correction, default_contact_surface, default_n_elements

   !> `method = 'fastsim-sh'`: FASTSIM_SH on the strips of the normal patch (doc/theory.md §6.5).
   integer, parameter :: method_fastsim_sh = 1
   !> `method = 'fastsim'`: classical three-flexibility FASTSIM on the Hertz ellipse (§3).
   integer, parameter :: method_fastsim = 2

   !> `bound = 'ellipsoidal'`: μ times the strip's semi-elliptic pressure (seed eq 28).
   integer, parameter :: bound_ellipsoidal = 1
   !> `bound = 'parabolic'`: μ times the parabolic pressure (seed eq 27).
   integer, parameter :: bound_parabolic = 2
   !> `bound = 'weighted'` (W1): parabolic march, every traction times p_n,e/p_n,p (§6.4).
   integer, parameter :: bound_weighted = 3
   !> `bound = 'weighted-slip'` (W2): weight only in slip elements, adhesion clipped to μp_n,e.
   integer, parameter :: bound_weighted_slip = 4
   !> `bound = 'clipped'` (W3): parabolic march, tractions clipped to μp_n,e.
   integer, parameter :: bound_clipped = 5

   !> `spin_model = 'additive'` (C): φ_i = φ + (φ_geo,i − φ_geo,0) (doc/theory.md §6.2).
   integer, parameter :: spin_additive = 1
   !> `spin_model = 'uniform'` (D): φ_i = φ, ν_xi = ν_x − φ y_i, ν_yi = ν_y.
   integer, parameter :: spin_uniform = 2
   !> `spin_model = 'scaled'` (B): φ_i = λ φ_geo,i with λ = φ/φ_geo,0.
   integer, parameter :: spin_scaled = 3
   !> `spin_model = 'geometric'` (G): φ_i = φ_geo,i, the input φ is ignored (seed eqs 18–19).
   integer, parameter :: spin_geometric = 4

   !> `spin_flexibility = 'spin'`: the spin part −φ y_i of the longitudinal slip builds up with
   !> the strip's spin flexibility L_φ,i, as in Kalker's three-flexibility FASTSIM (§3.1), so that
   !> FASTSIM_SH reduces to FASTSIM on a Hertzian patch.
   integer, parameter :: spin_flexibility_spin = 1
   !> `spin_flexibility = 'longitudinal'`: all of ν_xi builds up with L_x,i (seed eq 21 literally).
   integer, parameter :: spin_flexibility_longitudinal = 2

   !> `correction = 'none'`: the forces of the march itself.
   integer, parameter :: correction_none = 1
   !> `correction = 'exact-ellipse'`: add the exact theory's defect of the patch's equivalent
   !> ellipse (shcontact_tangential_ellipse_correction; doc/tangential.md). It is tabulated for
   !> the default model (FASTSIM_SH, bound 'weighted', spin flexibility 'longitudinal') and
   !> applies to that model only.
   integer, parameter :: correction_exact_ellipse = 2

   !> `contact_surface = 'wheel'`: each strip's normal and tangential forces are resolved in
   !> the track frame, and its geometric spin taken, with the wheel surface's local contact
   !> angle γ_i.
   integer, parameter :: surface_wheel = 1
   !> `contact_surface = 'interface'`: with the angle γ_n,i of the interface midway between
   !> the undeformed surfaces (equal elastic constants; doc/geometry.md, "The direction of the
   !> pressure").
   integer, parameter :: surface_interface = 2

   !> `&tangential method`.
   type(choice_type), parameter :: method_choices(*) = [ &
      choice_type('fastsim-sh', method_fastsim_sh, 'FASTSIM_SH on the strips of the '// &
      'semi-Hertzian patch (doc/theory.md §6.5)'), &
      choice_type('fastsim', method_fastsim, 'classical FASTSIM on the Hertz ellipse; needs '// &
      "&normal method = 'hertz'")]
   !> `&tangential bound` (doc/theory.md decision 9).
   type(choice_type), parameter :: bound_choices(*) = [ &
      choice_type('ellipsoidal', bound_ellipsoidal, "mu times the strip's semi-elliptic "// &
      'pressure (seed eq 28)'), &
      choice_type('parabolic', bound_parabolic, 'mu times the parabolic pressure (seed eq 27)'), &
      choice_type('weighted', bound_weighted, 'W1: parabolic march, every traction times '// &
      'p_n,e/p_n,p (doc/theory.md §6.4)'), &
      choice_type('weighted-slip', bound_weighted_slip, 'W2: weight only in slip elements, '// &
      'adhesion clipped to mu p_n,e'), &
      choice_type('clipped', bound_clipped, 'W3: parabolic march, tractions clipped to mu p_n,e')]
   !> `&tangential spin_model` (doc/theory.md §6.2, decision 10).
   type(choice_type), parameter :: spin_model_choices(*) = [ &
      choice_type('additive', spin_additive, 'C: phi_i = phi + (phi_geo,i - phi_geo,0); the '// &
      'only one of kinematic mode'), &
      choice_type('uniform', spin_uniform, 'D: phi_i = phi; fits the exact theory best for '// &
      'prescribed creepages'), &
      choice_type('scaled', spin_scaled, 'B: phi_i = phi_geo,i phi/phi_geo,0'), &
      choice_type('geometric', spin_geometric, 'G: phi_i = phi_geo,i, the input phi is ignored')]
   !> `&tangential spin_flexibility`.
   type(choice_type), parameter :: spin_flexibility_choices(*) = [ &
      choice_type('longitudinal', spin_flexibility_longitudinal, 'the spin part of the '// &
      'longitudinal slip builds up with L_x (seed eq 21)'), &
      choice_type('spin', spin_flexibility_spin, "with L_phi, as Kalker's FASTSIM (equal to "// &
      'FASTSIM on a Hertzian patch)')]
   !> `&tangential correction` (doc/tangential.md).
   type(choice_type), parameter :: correction_choices(*) = [ &
      choice_type('exact-ellipse', correction_exact_ellipse, "add the exact theory's defect "// &
      'of the equivalent Hertz ellipse (default model only)'), &
      choice_type('none', correction_none, "the march's forces")]
   !> `&tangential contact_surface` (doc/geometry.md, "The direction of the pressure").
   type(choice_type), parameter :: contact_surface_choices(*) = [ &
      choice_type('wheel', surface_wheel, "the wheel surface's local contact angle gamma_i"), &
      choice_type('interface', surface_interface, 'the interface midway between the '// &
      'undeformed surfaces, gamma_0 + atan(w'' + g''/2), for the forces and the spin')]

   !> The defaults (decisions 8–11; doc/validation.md for the spin model and flexibility).
   integer, parameter :: default_method = method_fastsim_sh
   integer, parameter :: default_bound = bound_weighted
   integer, parameter :: default_spin_model = spin_uniform
   integer, parameter :: default_spin_flexibility = spin_flexibility_longitudinal
   integer, parameter :: default_correction = correction_exact_ellipse
   !> 'wheel': 'interface' moves the flange normal forces by up to 4.6 %, but not nearer the
   !> exact theory on every position (doc/validation.md §6.8).
   integer, parameter :: default_contact_surface = surface_wheel
   !> Elements per strip n_x (decision 11): the default and range of `tangential%n_elements` in
   !> the variable table (shcontact_core_ranges).
   integer, parameter :: default_n_elements = nint(variables(findloc(variables%name, &
      'n_elements', 1, mask=variables%group == 'tangential'))%default)

contains

   !> The choices of the `&tangential` variable `name` (none for a variable without choices):
   !> the case file's variable table (shcontact_input_config_variables) takes a tangential
   !> choice's values from here, so that a new choice option is added in this layer only.
   pure function option_choices(name) result(choices)
      !> Variable name, lower case (`bound`, `correction`, ...).
      character(len=*), intent(in) :: name
      type(choice_type), allocatable :: choices(:)
      select case (name)
      case ('method'); choices = method_choices
      case ('bound'); choices = bound_choices
      case ('spin_model'); choices = spin_model_choices
      case ('spin_flexibility'); choices = spin_flexibility_choices
      case ('correction'); choices = correction_choices
      case ('contact_surface'); choices = contact_surface_choices
      case default; allocate (choices(0))
      end select
   end function option_choices

end module shcontact_tangential_option_registry
