!> A profile named by a source string: `builtin:NAME` or a file name (read, checked, cleaned),
!> or given as arrays of points by a program (checked and cleaned the same way).
!>
!> Profiles from files and arrays are also checked for plausibility
!> (shcontact_profile_plausibility).
!>
!> The one place where the app's case runner and the library's interfaces turn a profile
!> specification into a [[profile_type]].
module shcontact_profile_source
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_profile_plausibility, only: check_plausible
   use shcontact_core_strings, only: to_lower
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, array_hints
   use shcontact_profile_reader, only: read_profile
   use shcontact_profile_cleanup, only: clean_profile
   use shcontact_profile_collinear, only: drop_collinear
   use shcontact_profile_builtin, only: builtin_profile
   implicit none
   private

   public :: load_profile, profile_from_points

contains

   !> A profile from `builtin:NAME` (case-insensitive prefix) or from a file, which is read and
   !> then checked and cleaned (messages name the file line).
   subroutine load_profile(spec, kind, profile, error, format, mirror_y, mirror_z, scale, &
         option_prefix, as_read)
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
      !> The points as read, before the clean-up (a built-in profile as it is), e.g. for the
      !> noise of a measured file (shcontact_profile_diagnostics).
      type(profile_type), intent(out), optional :: as_read
      integer, allocatable :: lines(:)
      character(len=:), allocatable :: fmt, text

      text = trim(adjustl(spec))
      if (len(text) == 0) then
         call fatal_error(error, 'empty profile name: expected builtin:NAME ('// &
            'builtin:S1002, builtin:UIC60, builtin:UIC60-canted) or a profile file name', &
            stat_invalid_input)
         return
      end if
      if (index(to_lower(text), 'builtin:') == 1) then
         call builtin_profile(text(9:), profile, error)
         if (present(as_read)) as_read = profile
         return
      end if
      fmt = 'auto'
      if (present(format)) fmt = trim(format)
      call read_profile(text, profile, error, format=fmt, kind=kind, mirror_y=mirror_y, &
         mirror_z=mirror_z, scale=scale, line_of_point=lines, option_prefix=option_prefix)
      if (allocated(error)) return
      if (present(as_read)) as_read = profile
      call clean_profile(profile, error, lines, option_prefix=option_prefix, scale=scale)
      if (allocated(error)) return
      call drop_collinear(profile, lines)
      call check_plausible(profile, error, lines, option_prefix=option_prefix)
   end subroutine load_profile

   !> A profile from arrays of points in the canonical form (mm, right side, y towards the
   !> field side, z down; wheel points from the field side to the flange back, rail points from
   !> the track centre to the field side), checked and cleaned as a profile file is
   !> ([[load_profile]]: clean_profile, check_plausible) with one difference: points on the
   !> chord of their neighbours are kept (drop_collinear is for files whose samples were
   !> resampled; a program's arrays are taken as they are), so that a profile exported to arrays,
   !> a built-in one for instance, gives the results of the profile itself bit for bit.
   !> Messages name the profile 'wheel array' or 'rail array' (or `name`) and the point by its
   !> 1-based index.
   subroutine profile_from_points(y, z, kind, profile, error, name)
      !> Lateral and vertical coordinates of the points (mm), in profile order.
      real(wp), intent(in) :: y(:), z(:)
      !> profile_kind_wheel or profile_kind_rail.
      integer, intent(in) :: kind
      !> The profile.
      type(profile_type), intent(out) :: profile
      !> stat_invalid_input for too few, non-finite, duplicate or misordered points, a wrong
      !> length or an implausible shape; stat_usage when y and z differ in length.
      type(error_type), allocatable, intent(out) :: error
      !> How messages name the profile (default 'wheel array' or 'rail array').
      character(len=*), intent(in), optional :: name
      integer, allocatable :: lines(:)

      if (present(name)) then
         profile%source = name
      else if (kind == profile_kind_wheel) then
         profile%source = 'wheel array'
      else
         profile%source = 'rail array'
      end if
      profile%kind = kind
      profile%y = y
      profile%z = z
      allocate (lines(size(y)), source=0)
      call clean_profile(profile, error, lines, option_prefix=array_hints)
      if (allocated(error)) return
      call check_plausible(profile, error, lines, option_prefix=array_hints)
   end subroutine profile_from_points

end module shcontact_profile_source
