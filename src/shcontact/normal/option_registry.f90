!> The registry of the normal solver's option choices (issue 26): for `&normal method` and
!> `&normal reduction` the allowed values with their integer codes and descriptions, and the
!> defaults. [[shcontact_normal_options]], the case file's variable table
!> (shcontact_input_config_variables), the documentation's tables and the headers' option lists
!> are built from or checked against this one list (test `registry`).
module shcontact_normal_option_registry
   use shcontact_core_kinds, only: wp
   use shcontact_core_choices, only: choice_type
   use shcontact_core_ranges, only: variables
   implicit none
   private

   public :: method_semi_hertz, method_hertz, reduction_local_hertz, reduction_constant, &
      reduction_coupled
   public :: slide_exact, slide_linear
   public :: method_choices, reduction_choices, slide_choices, option_choices
   public :: default_method, default_reduction, default_epsilon, default_n_strips, default_slide

   !> `method = 'semi-hertz'`: the strip algorithm of doc/theory.md §4.3 (default).
   integer, parameter :: method_semi_hertz = 1
   !> `method = 'hertz'`: one Hertz ellipse from the curvatures at the reference point.
   integer, parameter :: method_hertz = 2
   !> `reduction = 'local-hertz'`: ε_a, ε_b from the local Hertz problem at A(y)/B(y) (the
   !> default before issue 13).
   integer, parameter :: reduction_local_hertz = 1
   !> `reduction = 'constant'`: ε_a = ε_b = `epsilon` everywhere (Kik–Piotrowski virtual
   !> penetration ε·δ).
   integer, parameter :: reduction_constant = 2
   !> `reduction = 'coupled'` (default since issue 13): the local-Hertz strips, then their load
   !> redistributed through the half-space coupling between strips (shcontact_normal_coupling;
   !> about 10 µs per solve; doc/validation.md §6.4).
   integer, parameter :: reduction_coupled = 3

   !> `slide = 'exact'`: the vertical approach carries the wheel along the contact plane by
   !> −(δ + g₀) tan γ₀, and the loaded gap takes the wheel's offset there (issue 28;
   !> shcontact_normal_semihertz's prepare_slide). Not the default: it moves the flange
   !> positions' F_n away from CONTACT's (doc/validation.md §6.8).
   integer, parameter :: slide_exact = 1
   !> `slide = 'linear'` (default): the slide to first order, the tilt term
   !> (δ + g₀) tan γ₀ tan(γ − γ₀) (issue 13).
   integer, parameter :: slide_linear = 2

   !> `&normal method`.
   type(choice_type), parameter :: method_choices(*) = [ &
      choice_type('semi-hertz', method_semi_hertz, 'strips of the semi-Hertzian patch '// &
      '(doc/theory.md §4.3)'), &
      choice_type('hertz', method_hertz, 'one Hertz ellipse at the reference point')]
   !> `&normal reduction` (semi-Hertz method only).
   type(choice_type), parameter :: reduction_choices(*) = [ &
      choice_type('coupled', reduction_coupled, 'local-Hertz strips, their load '// &
      'redistributed through the half-space (doc/validation.md §6.4)'), &
      choice_type('local-hertz', reduction_local_hertz, 'independent strips, each its local '// &
      'Hertz problem (the default before issue 13)'), &
      choice_type('constant', reduction_constant, "penetration reduced by the constant "// &
      "'epsilon' (Kik-Piotrowski)")]

   !> `&normal slide` (semi-Hertz method only).
   type(choice_type), parameter :: slide_choices(*) = [ &
      choice_type('linear', slide_linear, 'the slide to first order, the tilt term '// &
      '(doc/geometry.md, "Vertical approach")'), &
      choice_type('exact', slide_exact, 'the wheel''s slide along the contact plane under '// &
      'the vertical approach, exactly (doc/validation.md §6.8)')]

   !> The defaults (decisions 5, 6, 11); those of `epsilon` and `n_strips`, and their ranges,
   !> are the variable table's (shcontact_core_ranges, `normal%epsilon`, `normal%n_strips`).
   integer, parameter :: default_method = method_semi_hertz
   integer, parameter :: default_reduction = reduction_coupled
   integer, parameter :: default_slide = slide_linear
   real(wp), parameter :: default_epsilon = variables(findloc(variables%name, 'epsilon', 1, &
      mask=variables%group == 'normal'))%default
   integer, parameter :: default_n_strips = nint(variables(findloc(variables%name, 'n_strips', &
      1, mask=variables%group == 'normal'))%default)

contains

   !> The choices of the normal solver's `&normal` variable `name` (none for any other): the
   !> case file's variable table (shcontact_input_config_variables) takes them from here, so
   !> that a new choice option of the normal solver is added in this layer only.
   pure function option_choices(name) result(choices)
      !> Variable name, lower case (`method`, `reduction`).
      character(len=*), intent(in) :: name
      type(choice_type), allocatable :: choices(:)
      select case (name)
      case ('method'); choices = method_choices
      case ('reduction'); choices = reduction_choices
      case ('slide'); choices = slide_choices
      case default; allocate (choices(0))
      end select
   end function option_choices

end module shcontact_normal_option_registry
