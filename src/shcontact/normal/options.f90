!> Options of the normal-contact solver (doc/theory.md decisions 5, 6 and 11), validated once into
!> a typed configuration that the solvers then trust. Names, codes and defaults are those of the
!> registry [[shcontact_normal_option_registry]], re-exported here.
module shcontact_normal_options
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_ranges, only: check_range, check_int_range
   use shcontact_core_choices, only: choice_code, choice_name, choice_list, &
      choice_name_length
   use shcontact_normal_option_registry, only: method_semi_hertz, method_hertz, &
      reduction_local_hertz, reduction_constant, reduction_coupled, method_choices, &
      reduction_choices, default_method, default_reduction, default_epsilon, default_n_strips, &
      slide_exact, slide_linear, slide_choices, default_slide
   implicit none
   private

   public :: normal_options_type, new_normal_options, check_normal_options
   public :: method_semi_hertz, method_hertz, reduction_local_hertz, reduction_constant, &
      reduction_coupled
   public :: method_name, reduction_name
   public :: slide_exact, slide_linear

   !> The normal-contact options; build them with [[new_normal_options]] or check them with
   !> [[check_normal_options]] before use.
   type :: normal_options_type
      !> [[method_semi_hertz]] or [[method_hertz]].
      integer :: method = default_method
      !> [[reduction_local_hertz]], [[reduction_constant]] or [[reduction_coupled]] (semi-Hertz
      !> method only).
      integer :: reduction = default_reduction
      !> Constant penetration fraction ε of the `'constant'` reduction, 0 < ε ≤ 1.
      real(wp) :: epsilon = default_epsilon
      !> Number of strips per patch n_y (decision 11).
      integer :: n_strips = default_n_strips
      !> The vertical approach's slide along the contact plane: exact or to first order
      !> (`slide_exact`, `slide_linear`; issue 28).
      integer :: slide = default_slide
   contains
      !> The code of a choice option by its `&normal` name.
      procedure :: get_choice => get_normal_choice
      !> Set a choice option's code by its `&normal` name.
      procedure :: set_choice => set_normal_choice
   end type normal_options_type

contains

   !> The code held by the choice option `name` (the `&normal` variable's name, lower case;
   !> its values are the registry's [[option_choices]]); 0 for any other name. The case file's
   !> reader, validation and resolved namelist reach the normal solver's choices through this
   !> and [[set_normal_choice]].
   pure integer function get_normal_choice(options, name) result(code)
      !> The options.
      class(normal_options_type), intent(in) :: options
      !> Variable name.
      character(len=*), intent(in) :: name
      select case (name)
      case ('method'); code = options%method
      case ('reduction'); code = options%reduction
      case ('slide'); code = options%slide
      case default; code = 0
      end select
   end function get_normal_choice

   !> Store `code` in the choice option `name` ([[get_normal_choice]]'s names; any other name
   !> is ignored).
   pure subroutine set_normal_choice(options, name, code)
      !> The options.
      class(normal_options_type), intent(inout) :: options
      !> Variable name.
      character(len=*), intent(in) :: name
      !> A code of the option's choices.
      integer, intent(in) :: code
      select case (name)
      case ('method'); options%method = code
      case ('reduction'); options%reduction = code
      case ('slide'); options%slide = code
      end select
   end subroutine set_normal_choice

   !> Build the options from their textual form (as read from a namelist); absent arguments
   !> keep their defaults. Names are case-insensitive and accept `_` for `-`.
   subroutine new_normal_options(options, error, method, reduction, epsilon, n_strips)
      !> The validated options.
      type(normal_options_type), intent(out) :: options
      !> Set for an unknown name or an out-of-range value.
      type(error_type), allocatable, intent(out) :: error
      !> `'semi-hertz'` or `'hertz'`.
      character(len=*), intent(in), optional :: method
      !> `'local-hertz'`, `'constant'` or `'coupled'`.
      character(len=*), intent(in), optional :: reduction
      !> ε of the constant reduction.
      real(wp), intent(in), optional :: epsilon
      !> Strips per patch.
      integer, intent(in), optional :: n_strips

      if (present(method)) then
         options%method = choice_code(method_choices, method)
         if (options%method == 0) then
            call fatal_error(error, "normal option method = '"//trim(method)// &
               "': expected one of "//choice_list(method_choices), stat_invalid_input)
            return
         end if
      end if
      if (present(reduction)) then
         options%reduction = choice_code(reduction_choices, reduction)
         if (options%reduction == 0) then
            call fatal_error(error, "normal option reduction = '"//trim(reduction)// &
               "': expected one of "//choice_list(reduction_choices), stat_invalid_input)
            return
         end if
      end if
      if (present(epsilon)) options%epsilon = epsilon
      if (present(n_strips)) options%n_strips = n_strips
      call check_normal_options(options, error)
   end subroutine new_normal_options

   !> Reject options that are out of range (for options set component by component).
   pure subroutine check_normal_options(options, error)
      !> The options to check.
      type(normal_options_type), intent(in) :: options
      !> Set when a value is out of range.
      type(error_type), allocatable, intent(out) :: error
      character(len=32) :: buf

      if (.not. any(method_choices%code == options%method)) then
         write (buf, '(i0)') options%method
         call fatal_error(error, 'normal option method code '//trim(buf)// &
            ': expected the code of one of '//choice_list(method_choices), stat_invalid_input)
      else if (.not. any(reduction_choices%code == options%reduction)) then
         write (buf, '(i0)') options%reduction
         call fatal_error(error, 'normal option reduction code '//trim(buf)// &
            ': expected the code of one of '//choice_list(reduction_choices), &
            stat_invalid_input)
      else if (.not. any(slide_choices%code == options%slide)) then
         write (buf, '(i0)') options%slide
         call fatal_error(error, 'normal option slide code '//trim(buf)// &
            ': expected the code of one of '//choice_list(slide_choices), stat_invalid_input)
      else
         ! The app's ranges (shcontact_core_ranges): one table for the app and the library.
         call check_range('normal%epsilon', options%epsilon, 'normal option epsilon', error)
         if (.not. allocated(error)) call check_int_range('normal%n_strips', options%n_strips, &
            'normal option n_strips', error)
      end if
   end subroutine check_normal_options

   !> The textual name of a method code ('?' for an unknown code).
   pure function method_name(method) result(name)
      !> [[method_semi_hertz]] or [[method_hertz]].
      integer, intent(in) :: method
      character(len=choice_name_length(method_choices, method)) :: name
      name = choice_name(method_choices, method)
   end function method_name

   !> The textual name of a reduction code ('?' for an unknown code).
   pure function reduction_name(reduction) result(name)
      !> [[reduction_local_hertz]], [[reduction_constant]] or [[reduction_coupled]].
      integer, intent(in) :: reduction
      character(len=choice_name_length(reduction_choices, reduction)) :: name
      name = choice_name(reduction_choices, reduction)
   end function reduction_name

end module shcontact_normal_options
