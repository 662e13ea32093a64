!> Profiles out: plain 2-column text that [[read_profile]] reads back to the printed digits.
!>
!> The file starts with `#` comment lines (source, units, convention, and `# kind = rail` or
!> `# kind = wheel`, which the reader uses when no kind is given), then one `y z` pair per line
!> with 15 significant digits: reading a written file and writing it again gives the same text.
!>
!> The points are written with the origin a plain file has (shcontact_profile_points'
!> tape_circle_origin): a MiniProf wheel, whose origin is at its flange back, is written moved
!> by −70 mm (flange back at y = −70, the default flange-back position), and a header line says
!> so, so that a case reading the file places the wheel where the MiniProf file put it.
module shcontact_profile_writer
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_io, stat_invalid_input
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, tape_circle_origin, &
      flange_back_to_tape_circle
   use shcontact_profile_builtin, only: builtin_profile
   implicit none
   private

   public :: write_profile_plain, write_builtin_profiles, written_builtins

   !> Names of the built-in profiles written by [[write_builtin_profiles]], and their files.
   character(len=*), parameter :: written_builtins(3) = [character(len=12) :: 'S1002', 'UIC60', &
      'UIC60-canted']

contains

   !> Write a profile as plain `y z` text with a commented header.
   subroutine write_profile_plain(read_profile, filename, error)
      !> The profile (canonical form).
      type(profile_type), intent(in) :: read_profile
      !> The file to create or replace.
      character(len=*), intent(in) :: filename
      !> stat_io when the file cannot be written; stat_invalid_input for an empty profile.
      type(error_type), allocatable, intent(out) :: error

      character(len=256) :: message
      character(len=:), allocatable :: source, order
      type(profile_type) :: profile
      integer :: unit, stat, i

      profile = tape_circle_origin(read_profile)
      if (profile%size() == 0 .or. .not. allocated(profile%z)) then
         call fatal_error(error, filename//': refusing to write a profile without points', &
            stat_invalid_input)
         return
      end if
      source = 'unknown'
      if (allocated(profile%source)) source = profile%source
      if (profile%kind == profile_kind_wheel) then
         order = 'from the field side to the flange back'
      else
         order = 'from the track centre to the field side'
      end if

      open (newunit=unit, file=filename, status='replace', action='write', form='formatted', &
         iostat=stat, iomsg=message)
      if (stat /= 0) then
         call fatal_error(error, filename//': cannot create the file: '//trim(message), stat_io)
         return
      end if
      write (unit, '(a)', iostat=stat, iomsg=message) &
         '# shcontact profile, source: '//source, &
         '# kind = '//trim(merge('wheel', 'rail ', profile%kind == profile_kind_wheel)), &
         '# units: mm; right-side profile, y towards the field side, z positive downward', &
         '# points ordered '//order//' (material on the right)'
      if (stat == 0 .and. read_profile%origin_at_flange_back) write (unit, '(a)', iostat=stat, &
         iomsg=message) '# origin: on the tape circle, flange back at y = -'// &
         mm_text(flange_back_to_tape_circle)//' mm (the source had its origin at the flange '// &
         'back, MiniProf: y moved by -'//mm_text(flange_back_to_tape_circle)//' mm)'
      if (stat == 0) write (unit, '(a)', iostat=stat, iomsg=message) &
         '#                    y                      z'
      do i = 1, profile%size()
         if (stat /= 0) exit
         write (unit, '(2es23.14e3)', iostat=stat, iomsg=message) profile%y(i), profile%z(i)
      end do
      if (stat /= 0) then
         close (unit)
         call fatal_error(error, filename//': cannot write the file: '//trim(message), stat_io)
         return
      end if
      close (unit, iostat=stat, iomsg=message)
      if (stat /= 0) call fatal_error(error, filename//': cannot close the file: '// &
         trim(message), stat_io)
   end subroutine write_profile_plain

   !> A length in mm, as few digits as it needs (70 → '70').
   pure function mm_text(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(g0)') x
      text = trim(adjustl(buf))
      do while (len(text) > 1 .and. index(text, '.') > 0 .and. text(len(text):) == '0')
         text = text(:len(text) - 1)
      end do
      if (text(len(text):) == '.') text = text(:len(text) - 1)
   end function mm_text

   !> Write the built-in S1002, upright UIC60 and canted UIC60 profiles as `S1002.txt`,
   !> `UIC60.txt` and `UIC60-canted.txt`.
   subroutine write_builtin_profiles(directory, error)
      !> An existing directory ('' or '.' for the working directory).
      character(len=*), intent(in) :: directory
      !> stat_io when a file cannot be written.
      type(error_type), allocatable, intent(out) :: error

      type(profile_type) :: profile
      character(len=:), allocatable :: prefix
      integer :: i

      prefix = trim(directory)
      if (len(prefix) > 0) then
         if (prefix(len(prefix):) /= '/') prefix = prefix//'/'
      end if
      do i = 1, size(written_builtins)
         call builtin_profile(trim(written_builtins(i)), profile, error)
         if (allocated(error)) return
         call write_profile_plain(profile, prefix//trim(written_builtins(i))//'.txt', error)
         if (allocated(error)) return
      end do
   end subroutine write_builtin_profiles

end module shcontact_profile_writer
