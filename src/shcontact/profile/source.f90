!> A profile named by a source string: `builtin:NAME` or a file name (read, checked, cleaned).
!>
!> Profiles from files are also checked for plausibility (shcontact_profile_plausibility).
!>
!> The one place where the app's case runner and the library's solver object turn a profile
!> specification into a [[profile_type]].
module shcontact_profile_source
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type
   use shcontact_profile_plausibility, only: check_plausible
   use shcontact_core_strings, only: to_lower
   use shcontact_profile_points, only: profile_type
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile, drop_collinear
   use shcontact_profile_builtin, only: builtin_profile
   implicit none
   private

   public :: load_profile

contains

   !> A profile from `builtin:NAME` (case-insensitive prefix) or from a file, which is read and
   !> then checked and cleaned (messages name the file line).
   subroutine load_profile(spec, kind, profile, error, format, mirror_y, mirror_z, scale, &
         option_prefix)
      !> `builtin:NAME` or a file name.
      character(len=*), intent(in) :: spec
      !> profile_kind_wheel or profile_kind_rail; absent: as the file or its extension says
      !> (an error when neither does).
      integer, intent(in), optional :: kind
      !> The profile.
      type(profile_type), intent(out) :: profile
      !> Set for a missing, unreadable or malformed profile, or an unknown built-in name.
      type(error_type), allocatable, intent(out) :: error
      !> File format: 'auto' (default), 'plain', 'simpack', 'miniprof'.
      character(len=*), intent(in), optional :: format
      !> Mirror y, mirror z, scale to mm of a file, replacing the file's and format's settings
      !> (as [[read_profile]]).
      logical, intent(in), optional :: mirror_y, mirror_z
      real(wp), intent(in), optional :: scale
      !> How the caller names these options in messages (as [[read_profile]]).
      character(len=*), intent(in), optional :: option_prefix
      integer, allocatable :: lines(:)
      character(len=:), allocatable :: fmt, text

      text = trim(adjustl(spec))
      if (index(to_lower(text), 'builtin:') == 1) then
         call builtin_profile(text(9:), profile, error)
         return
      end if
      fmt = 'auto'
      if (present(format)) fmt = trim(format)
      call read_profile(text, profile, error, format=fmt, kind=kind, mirror_y=mirror_y, &
         mirror_z=mirror_z, scale=scale, line_of_point=lines, option_prefix=option_prefix)
      if (allocated(error)) return
      call clean_profile(profile, error, lines, option_prefix=option_prefix)
      if (allocated(error)) return
      call drop_collinear(profile, lines)
      call check_plausible(profile, error, lines, option_prefix=option_prefix)
   end subroutine load_profile

end module shcontact_profile_source
