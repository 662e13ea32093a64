!> Options of the tangential solver (doc/theory.md decisions 8–11): method, traction bound, spin
!> model, discretisation. Each switch is an integer code with a string parser (for the namelist)
!> and a name function (for outputs).
module shcontact_tangential_options
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_ranges, only: check_int_range
   use shcontact_tangential_kalker, only: kalker_scheme_scaled
   implicit none
   private

   public :: tangential_options_type, check_tangential_options
   public :: method_fastsim_sh, method_fastsim
   public :: bound_ellipsoidal, bound_parabolic, bound_weighted, bound_weighted_slip, bound_clipped
   public :: spin_additive, spin_uniform, spin_scaled, spin_geometric
   public :: spin_flexibility_spin, spin_flexibility_longitudinal
   public :: flexibility_strip, flexibility_patch, flexibility_carter
   public :: correction_none, correction_exact_ellipse
   public :: parse_method, parse_bound, parse_spin_model, parse_kalker_scheme, &
      parse_spin_flexibility, parse_flexibility, parse_correction
   public :: method_name, bound_name, spin_model_name, kalker_scheme_name, spin_flexibility_name, &
      flexibility_name, correction_name, corrected_model

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

   !> `flexibility = 'strip'`: each strip's flexibilities L_x, L_y, L_φ are those of its own local
   !> Hertz ellipse (doc/theory.md §6.3, seed eq 21).
   integer, parameter :: flexibility_strip = 1
   !> `flexibility = 'patch'`: one set L_x, L_y, L_φ for the whole patch, Kalker's linear theory of
   !> the patch's equivalent ellipse (doc/tangential.md, "Flexibilities").
   integer, parameter :: flexibility_patch = 2
   !> `flexibility = 'carter'`: each strip's own flexibilities, stiffened per strip and case so
   !> that the strip's simplified-theory creep curve follows Carter's exact 2-D curve
   !> (doc/tangential.md, "Flexibilities"); equal to 'strip' at small creepage.
   integer, parameter :: flexibility_carter = 3

   !> `correction = 'none'`: the forces of the march itself.
   integer, parameter :: correction_none = 1
   !> `correction = 'exact-ellipse'`: add the exact theory's defect of the patch's equivalent
   !> ellipse (shcontact_tangential_ellipse_correction; doc/tangential.md). It is tabulated for
   !> the default model (FASTSIM_SH, bound 'weighted', flexibility 'strip', spin flexibility
   !> 'longitudinal') and applies to that model only ([[corrected_model]]).
   integer, parameter :: correction_exact_ellipse = 2

   character(len=*), parameter :: method_names(2) = [character(len=10) :: 'fastsim-sh', 'fastsim']
   character(len=*), parameter :: bound_names(5) = [character(len=13) :: 'ellipsoidal', &
      'parabolic', 'weighted', 'weighted-slip', 'clipped']
   character(len=*), parameter :: spin_model_names(4) = [character(len=9) :: 'additive', &
      'uniform', 'scaled', 'geometric']
   character(len=*), parameter :: kalker_scheme_names(2) = [character(len=7) :: 'scaled', &
      'contact']
   character(len=*), parameter :: spin_flexibility_names(2) = [character(len=12) :: 'spin', &
      'longitudinal']
   character(len=*), parameter :: flexibility_names(3) = [character(len=6) :: 'strip', 'patch', &
      'carter']
   character(len=*), parameter :: correction_names(2) = [character(len=13) :: 'none', &
      'exact-ellipse']

   !> The validated configuration of the tangential solver.
   type :: tangential_options_type
      !> [[method_fastsim_sh]] (default) or [[method_fastsim]].
      integer :: method = method_fastsim_sh
      !> Traction bound, `bound_*` (default [[bound_weighted]], decision 9).
      integer :: bound = bound_weighted
      !> Local spin model, `spin_*`. Default [[spin_uniform]]: it fits the exact theory best for
      !> prescribed creepages (doc/validation.md); use [[spin_additive]] (doc/theory.md decision 10)
      !> when the creepages come from wheelset kinematics.
      integer :: spin_model = spin_uniform
      !> Elements per strip n_x (default 50, decision 11).
      integer :: n_elements = 50
      !> Kalker-table interpolation, `kalker_scheme_*` of shcontact_tangential_kalker (default
      !> [[kalker_scheme_scaled]], decision 7); the names 'scaled', 'contact' are in code order.
      integer :: kalker_scheme = kalker_scheme_scaled
      !> Flexibility of the spin part of the longitudinal slip. Default
      !> [[spin_flexibility_longitudinal]] (seed eq 21 literally; best fit in doc/validation.md);
      !> [[spin_flexibility_spin]] makes FASTSIM_SH equal to FASTSIM on a Hertzian patch.
      integer :: spin_flexibility = spin_flexibility_longitudinal
      !> Where the flexibilities come from: [[flexibility_strip]] (default, each strip's local
      !> ellipse), [[flexibility_patch]] (the equivalent ellipse of the whole patch) or
      !> [[flexibility_carter]] (each strip's, stiffened towards saturation by Carter's curve).
      integer :: flexibility = flexibility_strip
      !> Correction of the totals, `correction_*`. Default [[correction_exact_ellipse]]; it is
      !> applied when the model is the one it was tabulated for ([[corrected_model]]).
      integer :: correction = correction_exact_ellipse
      !> Fill the per-element fields of the result; .false. computes the totals only (faster).
      logical :: fields = .true.
   end type tangential_options_type

contains

   !> Reject option values out of range, naming the option and the allowed values.
   pure subroutine check_tangential_options(options, error)
      !> The options to check.
      type(tangential_options_type), intent(in) :: options
      !> Set when an option is invalid.
      type(error_type), allocatable, intent(out) :: error

      call check_code('method', options%method, method_names, error)
      if (allocated(error)) return
      call check_code('bound', options%bound, bound_names, error)
      if (allocated(error)) return
      call check_code('spin_model', options%spin_model, spin_model_names, error)
      if (allocated(error)) return
      call check_code('kalker_scheme', options%kalker_scheme, kalker_scheme_names, error)
      if (allocated(error)) return
      call check_code('spin_flexibility', options%spin_flexibility, spin_flexibility_names, error)
      if (allocated(error)) return
      call check_code('flexibility', options%flexibility, flexibility_names, error)
      if (allocated(error)) return
      call check_code('correction', options%correction, correction_names, error)
      if (allocated(error)) return
      ! The app's range (shcontact_core_ranges): one table for the app and the library.
      call check_int_range('tangential%n_elements', options%n_elements, &
         'tangential option n_elements', error)
   end subroutine check_tangential_options

   !> Parse `method`: 'fastsim-sh' or 'fastsim' (case-insensitive, '_' taken as '-').
   pure subroutine parse_method(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `method_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('method', text, method_names, code, error)
   end subroutine parse_method

   !> Parse `bound`: 'ellipsoidal', 'parabolic', 'weighted', 'weighted-slip' or 'clipped'.
   pure subroutine parse_bound(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `bound_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('bound', text, bound_names, code, error)
   end subroutine parse_bound

   !> Parse `spin_model`: 'additive', 'uniform', 'scaled' or 'geometric'.
   pure subroutine parse_spin_model(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `spin_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('spin_model', text, spin_model_names, code, error)
   end subroutine parse_spin_model

   !> Parse `kalker_scheme`: 'scaled' or 'contact'.
   pure subroutine parse_kalker_scheme(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `kalker_scheme_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('kalker_scheme', text, kalker_scheme_names, code, error)
   end subroutine parse_kalker_scheme

   !> Parse `spin_flexibility`: 'spin' or 'longitudinal'.
   pure subroutine parse_spin_flexibility(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `spin_flexibility_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('spin_flexibility', text, spin_flexibility_names, code, error)
   end subroutine parse_spin_flexibility

   !> Parse `flexibility`: 'strip', 'patch' or 'carter'.
   pure subroutine parse_flexibility(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `flexibility_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('flexibility', text, flexibility_names, code, error)
   end subroutine parse_flexibility

   !> Parse `correction`: 'none' or 'exact-ellipse'.
   pure subroutine parse_correction(text, code, error)
      !> The option value as written.
      character(len=*), intent(in) :: text
      !> The code, `correction_*`.
      integer, intent(out) :: code
      !> Set for an unknown value.
      type(error_type), allocatable, intent(out) :: error
      call parse_choice('correction', text, correction_names, code, error)
   end subroutine parse_correction

   !> True when the exact-ellipse correction applies: it is asked for and the model is the one
   !> its table was made for (FASTSIM_SH, bound 'weighted', flexibility 'strip', spin flexibility
   !> 'longitudinal'; any spin model, Kalker scheme and n_x).
   pure logical function corrected_model(options)
      !> The options.
      type(tangential_options_type), intent(in) :: options
      corrected_model = options%correction == correction_exact_ellipse .and. &
         options%method == method_fastsim_sh .and. options%bound == bound_weighted .and. &
         options%flexibility == flexibility_strip .and. &
         options%spin_flexibility == spin_flexibility_longitudinal
   end function corrected_model

   !> Name of a method code ('?' when out of range).
   pure function method_name(code) result(name)
      !> A `method_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, method_names)
   end function method_name

   !> Name of a bound code ('?' when out of range).
   pure function bound_name(code) result(name)
      !> A `bound_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, bound_names)
   end function bound_name

   !> Name of a spin-model code ('?' when out of range).
   pure function spin_model_name(code) result(name)
      !> A `spin_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, spin_model_names)
   end function spin_model_name

   !> Name of a Kalker-scheme code ('?' when out of range).
   pure function kalker_scheme_name(code) result(name)
      !> A `kalker_scheme_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, kalker_scheme_names)
   end function kalker_scheme_name

   !> Name of a spin-flexibility code ('?' when out of range).
   pure function spin_flexibility_name(code) result(name)
      !> A `spin_flexibility_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, spin_flexibility_names)
   end function spin_flexibility_name

   !> Name of a flexibility code ('?' when out of range).
   pure function flexibility_name(code) result(name)
      !> A `flexibility_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, flexibility_names)
   end function flexibility_name

   !> Name of a correction code ('?' when out of range).
   pure function correction_name(code) result(name)
      !> A `correction_*` code.
      integer, intent(in) :: code
      character(len=:), allocatable :: name
      name = choice_name(code, correction_names)
   end function correction_name

   !> Look `text` up in `names` (the code is the position); error lists the allowed values.
   pure subroutine parse_choice(option, text, names, code, error)
      character(len=*), intent(in) :: option, text
      character(len=*), intent(in) :: names(:)
      integer, intent(out) :: code
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: key
      integer :: i

      key = normalised(text)
      do i = 1, size(names)
         if (key == trim(names(i))) then
            code = i
            return
         end if
      end do
      code = 0
      call fatal_error(error, 'tangential option '//option//" = '"//trim(adjustl(text))// &
         "': expected one of "//name_list(names), stat_invalid_input)
   end subroutine parse_choice

   !> Error when a code is not a position in `names`.
   pure subroutine check_code(option, code, names, error)
      character(len=*), intent(in) :: option
      integer, intent(in) :: code
      character(len=*), intent(in) :: names(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=16) :: buf

      if (code < 1 .or. code > size(names)) then
         write (buf, '(i0)') code
         call fatal_error(error, 'tangential option '//option//' has the invalid code '// &
            trim(buf)//': expected one of '//name_list(names), stat_invalid_input)
      end if
   end subroutine check_code

   !> 'a', 'b', 'c' for the error messages.
   pure function name_list(names) result(list)
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: list
      integer :: i

      list = "'"//trim(names(1))//"'"
      do i = 2, size(names)
         list = list//", '"//trim(names(i))//"'"
      end do
   end function name_list

   pure function choice_name(code, names) result(name)
      integer, intent(in) :: code
      character(len=*), intent(in) :: names(:)
      character(len=:), allocatable :: name

      if (code >= 1 .and. code <= size(names)) then
         name = trim(names(code))
      else
         name = '?'
      end if
   end function choice_name

   !> Lower case, no surrounding blanks, '_' read as '-' (namelist strings often use either).
   pure function normalised(text) result(key)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: key
      integer :: i, ic

      key = trim(adjustl(text))
      do i = 1, len(key)
         ic = iachar(key(i:i))
         if (ic >= iachar('A') .and. ic <= iachar('Z')) key(i:i) = achar(ic + 32)
         if (key(i:i) == '_') key(i:i) = '-'
      end do
   end function normalised

end module shcontact_tangential_options
