!> The program's rule for the files its commands write (doc/app.md, "Files shcontact writes"):
!> it never overwrites a file it did not create in this run unless `--force` says so, and never
!> writes over one of its own inputs, whatever path names it (`./F`, a symbolic link, a hard link:
!> the same device and inode).
!>
!> Every command that writes a named or default output file checks it here before it computes
!> anything, so a refusal leaves every file as it was. Uses gfortran's `stat`/`lstat`.
module shcontact_app_output_guard
   use shcontact_core_error, only: error_type, fatal_error, stat_io
   use shcontact_core_files, only: path_kind
   implicit none
   private

   public :: path_exists, same_file, check_output_file

contains

   !> Whether anything exists at `path`: a file, a directory, a device, or a symbolic link (also
   !> one whose target is missing, which writing would create).
   logical function path_exists(path)
      !> The path.
      character(len=*), intent(in) :: path
      integer :: values(13)
      integer :: status
      path_exists = .false.
      if (len_trim(path) == 0) return
      call lstat(path, values, status)
      path_exists = status == 0
   end function path_exists

   !> Whether `a` and `b` name the same existing file: the same device and inode once symbolic
   !> links are followed, so also `./F`, another directory's path to it or a hard link.
   !> (gfortran's `stat` gives 32-bit values; size and modification time, which hard links
   !> share, are compared too, so that a truncated inode number cannot match another file.)
   logical function same_file(a, b)
      !> Two paths.
      character(len=*), intent(in) :: a, b
      integer :: va(13), vb(13)
      integer :: sa, sb
      same_file = .false.
      if (len_trim(a) == 0 .or. len_trim(b) == 0) return
      call stat(a, va, sa)
      if (sa /= 0) return
      call stat(b, vb, sb)
      if (sb /= 0) return
      same_file = va(1) == vb(1) .and. va(2) == vb(2) .and. va(8) == vb(8) .and. &
         va(10) == vb(10)
   end function same_file

   !> An error (stat_io) unless this run may write `path`: it must not be one of `inputs` (by
   !> device and inode), and must not exist unless `force` is set.
   subroutine check_output_file(path, what, force, inputs, error)
      !> The output file.
      character(len=*), intent(in) :: path
      !> How the command line names it, for the message: '-o', '--plot', 'the default output'.
      character(len=*), intent(in) :: what
      !> `--force`: an existing file may be replaced (an input never).
      logical, intent(in) :: force
      !> The files the command reads (blank entries are ignored).
      character(len=*), intent(in) :: inputs(:)
      !> Set when the file must not be written.
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      do k = 1, size(inputs)
         if (same_file(path, trim(inputs(k)))) then
            call fatal_error(error, path//': '//what//' names the input file '// &
               trim(inputs(k))//' (the same file); writing it would destroy the input: '// &
               'choose another output file', stat_io)
            return
         end if
      end do
      ! A directory (or a device) is never a file to replace, --force or not.
      if (path_exists(path)) then
         select case (path_kind(path, follow=.true.))
         case ('file', 'link', 'none')
         case default
            call fatal_error(error, path//': '//what//' is a '// &
               trim(path_kind(path, follow=.true.))//', not a file; give a file name', stat_io)
            return
         end select
      end if
      if (force .or. .not. path_exists(path)) return
      call fatal_error(error, path//': '//what//' exists and was not written by this run; '// &
         'choose another name, remove it, or pass --force to replace it', stat_io)
   end subroutine check_output_file

end module shcontact_app_output_guard
