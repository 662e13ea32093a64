!> Options of the normal-contact solver (doc/theory.md decisions 5, 6 and 11), validated once into
!> a typed configuration that the solvers then trust.
module shcontact_normal_options
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_core_ranges, only: check_range, check_int_range
   implicit none
   private

   public :: normal_options_type, new_normal_options, check_normal_options
   public :: method_semi_hertz, method_hertz, reduction_local_hertz, reduction_constant, &
      reduction_coupled
   public :: method_name, reduction_name

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

   !> The normal-contact options; build them with [[new_normal_options]] or check them with
   !> [[check_normal_options]] before use.
   type :: normal_options_type
      !> [[method_semi_hertz]] or [[method_hertz]].
      integer :: method = method_semi_hertz
      !> [[reduction_local_hertz]], [[reduction_constant]] or [[reduction_coupled]] (semi-Hertz
      !> method only).
      integer :: reduction = reduction_coupled
      !> Constant penetration fraction ε of the `'constant'` reduction, 0 < ε ≤ 1.
      real(wp) :: epsilon = 0.55_wp
      !> Number of strips per patch n_y (decision 11).
      integer :: n_strips = 100
   end type normal_options_type

contains

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

      character(len=:), allocatable :: name

      if (present(method)) then
         name = normalised(method)
         select case (name)
         case ('semi-hertz')
            options%method = method_semi_hertz
         case ('hertz')
            options%method = method_hertz
         case default
            call fatal_error(error, "normal option method = '"//trim(method)// &
               "': expected 'semi-hertz' or 'hertz'", stat_invalid_input)
            return
         end select
      end if
      if (present(reduction)) then
         name = normalised(reduction)
         select case (name)
         case ('local-hertz')
            options%reduction = reduction_local_hertz
         case ('constant')
            options%reduction = reduction_constant
         case ('coupled')
            options%reduction = reduction_coupled
         case default
            call fatal_error(error, "normal option reduction = '"//trim(reduction)// &
               "': expected 'local-hertz', 'constant' or 'coupled'", stat_invalid_input)
            return
         end select
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

      if (options%method /= method_semi_hertz .and. options%method /= method_hertz) then
         write (buf, '(i0)') options%method
         call fatal_error(error, 'normal option method code '//trim(buf)// &
            ': expected method_semi_hertz or method_hertz', stat_invalid_input)
      else if (options%reduction /= reduction_local_hertz .and. &
               options%reduction /= reduction_constant .and. &
               options%reduction /= reduction_coupled) then
         write (buf, '(i0)') options%reduction
         call fatal_error(error, 'normal option reduction code '//trim(buf)// &
            ': expected reduction_local_hertz, reduction_constant or reduction_coupled', &
            stat_invalid_input)
      else
         ! The app's ranges (shcontact_core_ranges): one table for the app and the library.
         call check_range('normal%epsilon', options%epsilon, 'normal option epsilon', error)
         if (.not. allocated(error)) call check_int_range('normal%n_strips', options%n_strips, &
            'normal option n_strips', error)
      end if
   end subroutine check_normal_options

   !> The textual name of a method code.
   pure function method_name(method) result(name)
      !> [[method_semi_hertz]] or [[method_hertz]].
      integer, intent(in) :: method
      character(len=:), allocatable :: name
      select case (method)
      case (method_semi_hertz)
         name = 'semi-hertz'
      case (method_hertz)
         name = 'hertz'
      case default
         name = 'unknown'
      end select
   end function method_name

   !> The textual name of a reduction code.
   pure function reduction_name(reduction) result(name)
      !> [[reduction_local_hertz]], [[reduction_constant]] or [[reduction_coupled]].
      integer, intent(in) :: reduction
      character(len=:), allocatable :: name
      select case (reduction)
      case (reduction_local_hertz)
         name = 'local-hertz'
      case (reduction_constant)
         name = 'constant'
      case (reduction_coupled)
         name = 'coupled'
      case default
         name = 'unknown'
      end select
   end function reduction_name

   !> Lower case, blanks trimmed, `_` read as `-`.
   pure function normalised(text) result(name)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: name
      integer :: i, c
      name = trim(adjustl(text))
      do i = 1, len(name)
         c = iachar(name(i:i))
         if (c >= iachar('A') .and. c <= iachar('Z')) name(i:i) = achar(c + 32)
         if (name(i:i) == '_') name(i:i) = '-'
      end do
   end function normalised

end module shcontact_normal_options
