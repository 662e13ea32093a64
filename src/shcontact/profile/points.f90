!> A wheel or rail profile as a list of points (the project's canonical form, doc/theory.md §5.1).
module shcontact_profile_points
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: replaced
   implicit none
   private

   public :: profile_type, profile_kind_rail, profile_kind_wheel, option_hint, array_hints
   public :: tape_circle_origin, flange_back_to_tape_circle

   !> The profile is a rail profile.
   integer, parameter :: profile_kind_rail = 0
   !> The profile is a wheel profile.
   integer, parameter :: profile_kind_wheel = 1

   !> Lateral distance from a wheel's flange back to its tape circle (mm; EN 13715: 70): a wheel
   !> with its origin on the tape circle has its flange back at y = −70 mm (S1002), the default
   !> flange-back position of the track.
   real(wp), parameter :: flange_back_to_tape_circle = 70.0_wp

   !> The `option_prefix` of profiles given as arrays (shcontact_profile_source's
   !> profile_from_points): [[option_hint]] then says what to do to the arrays.
   character(len=*), parameter :: array_hints = '(arrays)'

   !> A right-side profile: y lateral towards the field side, z positive **downward**, mm.
   !>
   !> Points are ordered along the profile with the material on the right when walking them
   !> (CONTACT's convention): rail points run from the track-centre side to the field side
   !> (y ascending overall), wheel points from the field side to the flange back (y descending
   !> overall). The profile may be multi-valued in y (vertical flange back), hence `s`.
   !> Rail origin: highest point of the rail as placed in its file; wheel origin: on the tape
   !> circle (S1002: flange back at y = −70 mm).
   type :: profile_type
      !> Where it came from: a file name or `builtin:NAME`.
      character(len=:), allocatable :: source
      !> [[profile_kind_rail]] or [[profile_kind_wheel]].
      integer :: kind = profile_kind_rail
      !> Lateral coordinate, mm.
      real(wp), allocatable :: y(:)
      !> Vertical coordinate, positive downward, mm.
      real(wp), allocatable :: z(:)
      !> Summed chord length from the first point, mm (s(1) = 0).
      real(wp), allocatable :: s(:)
      !> True at points kept as genuine corners (kinks) by the clean-up, where smoothing splits.
      logical, allocatable :: kink(:)
      !> A wheel whose origin is at its flange back (a MiniProf `.whl` file), not on the tape
      !> circle; [[tape_circle_origin]] moves it there.
      logical :: origin_at_flange_back = .false.
   contains
      !> Number of points.
      procedure :: size => profile_size
      !> Recompute `s` from y and z.
      procedure :: update_arc_length
   end type profile_type

contains

   !> Number of points.
   pure integer function profile_size(self)
      class(profile_type), intent(in) :: self
      profile_size = 0
      if (allocated(self%y)) profile_size = size(self%y)
   end function profile_size

   !> s₁ = 0, s_{i+1} = s_i + √(Δy² + Δz²) (doc/theory.md §5.1).
   pure subroutine update_arc_length(self)
      class(profile_type), intent(inout) :: self
      integer :: i, n
      n = self%size()
      if (allocated(self%s)) deallocate (self%s)
      allocate (self%s(n))
      if (n == 0) return
      self%s(1) = 0.0_wp
      do i = 2, n
         self%s(i) = self%s(i - 1) + hypot(self%y(i) - self%y(i - 1), self%z(i) - self%z(i - 1))
      end do
   end subroutine update_arc_length

   !> The profile with its origin on the tape circle, where a profile given as points or as a
   !> plain file has it (flange back at y = −70 mm, the track's default flange-back position): a
   !> wheel with its origin at the flange back (MiniProf) is moved by −[[flange_back_to_tape_circle]]
   !> in y; any other profile is returned as it is.
   pure function tape_circle_origin(profile) result(moved)
      !> The profile.
      type(profile_type), intent(in) :: profile
      type(profile_type) :: moved
      moved = profile
      if (.not. (profile%origin_at_flange_back .and. allocated(profile%y))) return
      moved%y = profile%y - flange_back_to_tape_circle
      moved%origin_at_flange_back = .false.
   end function tape_circle_origin

   !> How to set a reading option in a message: the library's argument (`mirror_z = .true.`)
   !> or, with `prefix` (e.g. '&profiles wheel_'), the caller's variable
   !> (`&profiles wheel_mirror_z = 'yes'`). `value` is 'yes', 'no' or, for the scale, a
   !> placeholder such as 'FACTOR'. The prefix '--' names command-line options
   !> (`--mirror-z yes`, `--scale FACTOR`); the prefix [[array_hints]] names what to do to
   !> arrays given by a program (`pass -z`, `pass the coordinates times FACTOR`).
   pure function option_hint(prefix, name, value) result(text)
      !> The caller's prefix ('' or absent: the library's arguments).
      character(len=*), intent(in), optional :: prefix
      !> 'mirror_y', 'mirror_z' or 'scale'.
      character(len=*), intent(in) :: name
      !> The value to suggest.
      character(len=*), intent(in) :: value
      character(len=:), allocatable :: text
      logical :: library
      library = .not. present(prefix)
      if (.not. library) library = len_trim(prefix) == 0
      if (library) then
         select case (value)
         case ('yes'); text = name//' = .true.'
         case ('no'); text = name//' = .false.'
         case default; text = name//' = '//value
         end select
      else if (trim(prefix) == array_hints) then
         select case (name)
         case ('mirror_y'); text = 'pass -y'
         case ('mirror_z'); text = 'pass -z (z is positive downward)'
         case default; text = 'pass the coordinates times '//value//' (mm)'
         end select
      else if (trim(prefix) == '--') then
         text = '--'//replaced(name, '_', '-')//' '//value
      else if (name == 'scale') then
         text = trim(prefix)//name//' = '//value
      else
         text = trim(prefix)//name//" = '"//value//"'"
      end if
   end function option_hint

end module shcontact_profile_points
