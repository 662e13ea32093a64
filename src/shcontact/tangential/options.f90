!> Options of the tangential solver (doc/theory.md decisions 8–11): method, traction bound, spin
!> model, discretisation. Each switch is an integer code; its names, codes, descriptions and
!> default are those of the registry [[shcontact_tangential_option_registry]], which this module
!> re-exports with the parsers (for the option setters) and name functions (for outputs).
module shcontact_tangential_options
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_choices, only: choice_type, choice_code, choice_name, choice_list, &
      choice_name_length
   use shcontact_core_ranges, only: check_int_range
   use shcontact_tangential_option_registry, only: method_fastsim_sh, method_fastsim, &
      bound_ellipsoidal, bound_parabolic, bound_weighted, bound_weighted_slip, bound_clipped, &
      spin_additive, spin_uniform, spin_scaled, spin_geometric, spin_flexibility_spin, &
      spin_flexibility_longitudinal, correction_none, correction_exact_ellipse, method_choices, &
      bound_choices, spin_model_choices, spin_flexibility_choices, correction_choices, &
      default_method, default_bound, default_spin_model, default_spin_flexibility, &
      default_correction, default_n_elements, surface_wheel, surface_interface, &
      contact_surface_choices, default_contact_surface
   implicit none
   private

   public :: tangential_options_type, check_tangential_options
   public :: method_fastsim_sh, method_fastsim
   public :: bound_ellipsoidal, bound_parabolic, bound_weighted, bound_weighted_slip, bound_clipped
   public :: spin_additive, spin_uniform, spin_scaled, spin_geometric
   public :: spin_flexibility_spin, spin_flexibility_longitudinal
   public :: correction_none, correction_exact_ellipse
   public :: surface_wheel, surface_interface
   public :: parse_method, parse_bound, parse_spin_model, parse_spin_flexibility, parse_correction
   public :: method_name, bound_name, spin_model_name, spin_flexibility_name, correction_name, &
      corrected_model

   !> The validated configuration of the tangential solver; the defaults are the registry's.
   type :: tangential_options_type
      !> [[method_fastsim_sh]] (default) or [[method_fastsim]].
      integer :: method = default_method
      !> Traction bound, `bound_*` (default [[bound_weighted]], decision 9: FASTSIM_SH's). With
      !> method_fastsim give it too: Kalker's FASTSIM is bound_parabolic (the namelist and the
      !> keyed interfaces default to it there); W1 on an ellipse makes the creep coefficients
      !> 1.39 times Kalker's.
      integer :: bound = default_bound
      !> Local spin model, `spin_*`. Default [[spin_uniform]]: it fits the exact theory best for
      !> prescribed creepages (doc/validation.md); use [[spin_additive]] (doc/theory.md decision 10)
      !> when the creepages come from wheelset kinematics.
      integer :: spin_model = default_spin_model
      !> Elements per strip n_x (default 50, decision 11).
      integer :: n_elements = default_n_elements
      !> Flexibility of the spin part of the longitudinal slip. Default
      !> [[spin_flexibility_longitudinal]] (seed eq 21 literally; best fit in doc/validation.md);
      !> [[spin_flexibility_spin]] makes FASTSIM_SH equal to FASTSIM on a Hertzian patch.
      integer :: spin_flexibility = default_spin_flexibility
      !> Correction of the totals, `correction_*`. Default [[correction_exact_ellipse]]; it is
      !> applied when the model is the one it was tabulated for ([[corrected_model]]).
      integer :: correction = default_correction
      !> The strips' contact surface, `surface_*` (the angle that resolves their forces in the
      !> track frame and gives their geometric spin): default [[surface_wheel]] (the wheel's
      !> γ_i); [[surface_interface]] the interface's γ_n,i where the normal solution gives it.
      integer :: contact_surface = default_contact_surface
      !> Fill the per-element fields of the result; .false. computes the totals only (faster).
      logical :: fields = .true.
   contains
      !> The code of a choice option by its `&tangential` name.
      procedure :: get_choice => get_tangential_choice
      !> Set a choice option's code by its `&tangential` name.
      procedure :: set_choice => set_tangential_choice
   end type tangential_options_type

contains

   !> Reject option values out of range, naming the option and the allowed values.
   pure subroutine check_tangential_options(options, error)
      !> The options to check.
      type(tangential_options_type), intent(in) :: options
      !> Set when an option is invalid.
      type(error_type), allocatable, intent(out) :: error

      call check_code('method', options%method, method_choices, error)
      if (allocated(error)) return
      call check_code('bound', options%bound, bound_choices, error)
      if (allocated(error)) return
      call check_code('spin_model', options%spin_model, spin_model_choices, error)
      if (allocated(error)) return
      call check_code('spin_flexibility', options%spin_flexibility, spin_flexibility_choices, &
         error)
      if (allocated(error)) return
      call check_code('correction', options%correction, correction_choices, error)
      if (allocated(error)) return
      call check_code('contact_surface', options%contact_surface, &
         contact_surface_choices, error)
      if (allocated(error)) return
      ! The app's range (shcontact_core_ranges): one table for the app and the library.
      call check_int_range('tangential%n_elements', options%n_elements, &
         'tangential option n_elements', error)
   end subroutine check_tangential_options

   !> The code held by the choice option `name` (the `&tangential` variable's name, lower
   !> case; its values are the registry's [[option_choices]]); 0 for any other name. The case
   !> file's reader, validation and resolved namelist reach every tangential choice through this
   !> and [[set_tangential_choice]].
   pure integer function get_tangential_choice(options, name) result(code)
      !> The options.
      class(tangential_options_type), intent(in) :: options
      !> Variable name.
      character(len=*), intent(in) :: name
      select case (name)
      case ('method'); code = options%method
      case ('bound'); code = options%bound
      case ('spin_model'); code = options%spin_model
      case ('spin_flexibility'); code = options%spin_flexibility
      case ('correction'); code = options%correction
      case ('contact_surface'); code = options%contact_surface
      case default; code = 0
      end select
   end function get_tangential_choice

   !> Store `code` in the choice option `name` ([[get_tangential_choice]]'s names; any other
   !> name is ignored).
   pure subroutine set_tangential_choice(options, name, code)
      !> The options.
      class(tangential_options_type), intent(inout) :: options
      !> Variable name.
      character(len=*), intent(in) :: name
      !> A code of the option's choices.
      integer, intent(in) :: code
      select case (name)
      case ('method'); options%method = code
      case ('bound'); options%bound = code
      case ('spin_model'); options%spin_model = code
      case ('spin_flexibility'); options%spin_flexibility = code
      case ('correction'); options%correction = code
      case ('contact_surface'); options%contact_surface = code
      end select
   end subroutine set_tangential_choice

   !> Parse `method`: 'fastsim-sh' or 'fastsim' (case-insensitive, '_' taken as '-').
   pure subroutine parse_method(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `method_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('method', text, method_choices, code, error)
   end subroutine parse_method

   !> Parse `bound`: 'ellipsoidal', 'parabolic', 'weighted', 'weighted-slip' or 'clipped'.
   pure subroutine parse_bound(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `bound_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('bound', text, bound_choices, code, error)
   end subroutine parse_bound

   !> Parse `spin_model`: 'additive', 'uniform', 'scaled' or 'geometric'.
   pure subroutine parse_spin_model(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `spin_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('spin_model', text, spin_model_choices, code, error)
   end subroutine parse_spin_model

   !> Parse `spin_flexibility`: 'longitudinal' or 'spin'.
   pure subroutine parse_spin_flexibility(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `spin_flexibility_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('spin_flexibility', text, spin_flexibility_choices, code, error)
   end subroutine parse_spin_flexibility

   !> Parse `correction`: 'exact-ellipse' or 'none'.
   pure subroutine parse_correction(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `correction_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('correction', text, correction_choices, code, error)
   end subroutine parse_correction

   !> True when the exact-ellipse correction applies: it is asked for and the model is the one
   !> its table was made for (FASTSIM_SH, bound 'weighted', spin flexibility 'longitudinal'; any
   !> spin model and n_x).
   pure logical function corrected_model(options)
      !> The options.
      type(tangential_options_type), intent(in) :: options
      corrected_model = options%correction == correction_exact_ellipse .and. &
         options%method == method_fastsim_sh .and. options%bound == bound_weighted .and. &
         options%spin_flexibility == spin_flexibility_longitudinal
   end function corrected_model

   !> Name of a method code ('?' when out of range).
   pure function method_name(code) result(name)
      !> A `method_*` code.
      integer, intent(in) :: code
      character(len=choice_name_length(method_choices, code)) :: name
      name = choice_name(method_choices, code)
   end function method_name

   !> Name of a bound code ('?' when out of range).
   pure function bound_name(code) result(name)
      !> A `bound_*` code.
      integer, intent(in) :: code
      character(len=choice_name_length(bound_choices, code)) :: name
      name = choice_name(bound_choices, code)
   end function bound_name

   !> Name of a spin-model code ('?' when out of range).
   pure function spin_model_name(code) result(name)
      !> A `spin_*` code.
      integer, intent(in) :: code
      character(len=choice_name_length(spin_model_choices, code)) :: name
      name = choice_name(spin_model_choices, code)
   end function spin_model_name

   !> Name of a spin-flexibility code ('?' when out of range).
   pure function spin_flexibility_name(code) result(name)
      !> A `spin_flexibility_*` code.
      integer, intent(in) :: code
      character(len=choice_name_length(spin_flexibility_choices, code)) :: name
      name = choice_name(spin_flexibility_choices, code)
   end function spin_flexibility_name

   !> Name of a correction code ('?' when out of range).
   pure function correction_name(code) result(name)
      !> A `correction_*` code.
      integer, intent(in) :: code
      character(len=choice_name_length(correction_choices, code)) :: name
      name = choice_name(correction_choices, code)
   end function correction_name

   !> Look `text` up in the choices; the error lists the allowed values.
   pure subroutine parse_choice(option, text, choices, code, error)
      character(len=*), intent(in) :: option, text
      type(choice_type), intent(in) :: choices(:)
      integer, intent(out) :: code
      type(error_type), allocatable, intent(out) :: error
      code = choice_code(choices, text)
      if (code /= 0) return
      call fatal_error(error, 'tangential option '//option//" = '"//trim(adjustl(text))// &
         "': expected one of "//choice_list(choices), stat_invalid_input)
   end subroutine parse_choice

   !> Error when a code is none of the choices'.
   pure subroutine check_code(option, code, choices, error)
      character(len=*), intent(in) :: option
      integer, intent(in) :: code
      type(choice_type), intent(in) :: choices(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: buf

      if (any(choices%code == code)) return
      write (buf, '(i0)') code
      call fatal_error(error, 'tangential option '//option//' has the invalid code '// &
         trim(buf)//': expected one of '//choice_list(choices), stat_invalid_input)
   end subroutine check_code

end module shcontact_tangential_options
