!> Checks of the files `run` and `merge` write and read (doc/app.md, "Files shcontact writes"):
!> an output name (and its XDMF sidecar) may be written only when it is new or a file shcontact
!> wrote, never a directory, pipe or device, a symbolic link or a foreign file only when forced;
!> a result file read back (a shard, a checkpoint block) must have the layout its reader
!> expects, dataset by dataset, before anything is read from it.
module shcontact_output_output_checks
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, &
      stat_usage
   use shcontact_core_strings, only: str_int, control_characters
   use shcontact_core_files, only: canonical_path, path_kind
   use shcontact_output_hdf5, only: h5_file_type, h5_open, h5_close, h5_exists, &
      h5_read_attribute, h5_dataset_info
   use shcontact_output_xdmf, only: xdmf_name, is_xdmf_sidecar, sidecar_target
   use shcontact_core_text, only: string_type
   use shcontact_case_result, only: summary_columns, n_summary_columns
   implicit none
   private

   public :: check_output_file, check_layout, check_result_file

contains

   !> An output name that may be written, with its XDMF sidecar (OUT.xmf): no control
   !> character in the name; each a new name, or an existing regular file that shcontact wrote
   !> (a result file, a sidecar), which a new run replaces. Anything else is refused: a
   !> directory, pipe, device or socket always, a symbolic link or a file shcontact did not
   !> write unless `force`. The output must not be one of `inputs`. Nothing that is not
   !> shcontact's is overwritten unless asked.
   subroutine check_output_file(output, error, inputs, force)
      !> The output file.
      character(len=*), intent(in) :: output
      !> stat_io (refused name) or stat_usage (also an input), naming the file.
      type(error_type), allocatable, intent(out) :: error
      !> Files read to make the output.
      type(string_type), intent(in), optional :: inputs(:)
      !> Replace a symbolic link or a file that shcontact did not write.
      logical, intent(in), optional :: force
      character(len=:), allocatable :: kind, described
      integer :: f
      logical :: forced
      forced = .false.
      if (present(force)) forced = force
      f = scan(output, control_characters)
      if (f > 0) then
         call fatal_error(error, 'the output name "'//output(1:f - 1)//'?'//output(f + 1:)// &
            '" holds a control character (byte '//str_int(iachar(output(f:f)))//' at '// &
            'position '//str_int(f)//'); choose a name without one', stat_invalid_input)
         return
      end if
      if (xdmf_name(output) == output) then
         call fatal_error(error, 'the output name "'//output//'" ends in .xmf, the name its '// &
            'XDMF sidecar takes (OUT.xmf, written next to a result file with element fields), '// &
            'so the sidecar would replace the results; choose a name such as "'// &
            output(1:len(output) - 4)//'.h5"', stat_invalid_input)
         return
      end if
      kind = path_kind(output)
      call check_kind('the output "'//output//'"', kind, forced, error)
      if (allocated(error)) return
      if (kind /= 'none') then
         call check_not_input(output, 'the output "'//output//'"', inputs, error)
         if (allocated(error)) return
         if (kind == 'file' .and. .not. forced .and. .not. is_result_file(output)) then
            call fatal_error(error, 'the output "'//output//'" exists and is not a '// &
               'shcontact result file; it is not overwritten (remove it, choose another '// &
               'name, or use --force)', stat_io)
            return
         end if
      end if
      kind = path_kind(xdmf_name(output))
      call check_kind('the XDMF sidecar "'//xdmf_name(output)//'" of the output "'// &
         output//'"', kind, forced, error)
      if (allocated(error)) return
      if (kind /= 'none') call check_not_input(xdmf_name(output), 'the XDMF sidecar "'// &
         xdmf_name(output)//'" of the output "'//output//'"', inputs, error)
      if (allocated(error)) return
      if (kind /= 'file' .or. forced) return
      if (.not. is_xdmf_sidecar(xdmf_name(output))) then
         call fatal_error(error, 'the XDMF sidecar "'//xdmf_name(output)//'" of the output "'// &
            output//'" exists and was not written by shcontact; it is not overwritten (remove '// &
            'it, choose another output name, or use --force)', stat_io)
         return
      end if
      ! A sidecar of another result file that shares the name (OUT.h5 and OUT.hdf5).
      described = sidecar_target(xdmf_name(output))
      if (described /= output(index(output, '/', back=.true.) + 1:)) call fatal_error(error, &
         'the XDMF sidecar "'//xdmf_name(output)//'" of the output "'//output//'" exists '// &
         'and describes another result file ("'//described//'"); it is not overwritten (remove '// &
         'it, choose another output name, or use --force)', stat_io)
   end subroutine check_output_file

   !> An error (stat_usage) when the existing file `path` is one of `inputs` (the same file
   !> once links and relative parts are resolved): a file the command reads is never
   !> replaced, not even with --force.
   subroutine check_not_input(path, what, inputs, error)
      !> The file to be written (it exists).
      character(len=*), intent(in) :: path
      !> How the message names it.
      character(len=*), intent(in) :: what
      !> Files read to make the output.
      type(string_type), intent(in), optional :: inputs(:)
      !> Set when `path` is an input.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: target
      integer :: f
      if (.not. present(inputs)) return
      target = canonical_path(path)
      do f = 1, size(inputs)
         if (len_trim(inputs(f)%text) == 0) cycle
         if (path_kind(inputs(f)%text, follow=.true.) /= 'file') cycle
         if (canonical_path(inputs(f)%text) == target) then
            call fatal_error(error, what//' is also an input of this command ('// &
               inputs(f)%text//'); it is never replaced, not even with --force: choose '// &
               'another output name', stat_usage)
            return
         end if
      end do
   end subroutine check_not_input

   !> Refuse an output name that names a directory, pipe, device or socket, or (unless forced)
   !> a symbolic link.
   subroutine check_kind(what, kind, forced, error)
      character(len=*), intent(in) :: what, kind
      logical, intent(in) :: forced
      type(error_type), allocatable, intent(out) :: error
      select case (kind)
      case ('none', 'file')
      case ('link')
         if (.not. forced) call fatal_error(error, 'cannot write '//what//': it is a '// &
            'symbolic link, which would be replaced by a file (remove it, choose another '// &
            'name, or use --force)', stat_io)
      case ('directory')
         call fatal_error(error, 'cannot write '//what//': it is a directory', stat_io)
      case default
         call fatal_error(error, 'cannot write '//what//': it is a '// &
            kind//', not a regular file (results are written under a temporary name and '// &
            'renamed; give a file name)', stat_io)
      end select
   end subroutine check_kind


   !> True for an HDF5 file written by shcontact: its root attribute `software` is
   !> 'shcontact', it has the root attribute `n_cases` and the dataset /input/namelist (every
   !> result file, shard and merged file has them). Another program's file that merely has a
   !> `software` attribute (h5py, CONTACT, a data logger) is not taken for ours.
   function is_result_file(name) result(yes)
      character(len=*), intent(in) :: name
      logical :: yes
      type(h5_file_type) :: file
      type(error_type), allocatable :: error
      yes = .false.
      call h5_open(file, name, error)
      if (allocated(error)) return
      call check_result_file(file, error)
      yes = .not. allocated(error)
      call h5_close(file)
   end function is_result_file

   !> Why an open HDF5 file is not a shcontact result file ([[is_result_file]]'s test): an error
   !> whose message is the reason (the `software` attribute missing or another program's, no
   !> `n_cases`, no /input/namelist); none for a result file.
   subroutine check_result_file(file, error)
      type(h5_file_type), intent(in) :: file
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: software
      integer :: n_cases
      call h5_read_attribute(file, '/', 'software', software, error)
      if (allocated(error)) return
      if (software /= 'shcontact') then
         call fatal_error(error, 'its software attribute is "'//software//'"')
         return
      end if
      call h5_read_attribute(file, '/', 'n_cases', n_cases, error)
      if (allocated(error)) return
      if (.not. h5_exists(file, 'input/namelist')) call fatal_error(error, &
         'it has no /input/namelist')
   end subroutine check_result_file


   !> Check the shape and type of every dataset [[read_result_summary]] reads before it is
   !> read: /summary/case and every summary column numbers of one length (one per case),
   !> /failures/case numbers and /failures/message texts of one length. A damaged file (a
   !> shard or checkpoint block edited or cut short) gets one stat_invalid_input error naming
   !> the file and the dataset.
   subroutine check_layout(file, name, error)
      !> The open file.
      type(h5_file_type), intent(in) :: file
      !> Its name, for the message.
      character(len=*), intent(in) :: name
      !> stat_invalid_input naming the file and the dataset.
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: counts(4) = [character(len=10) :: 'status', &
         'n_patches', 'n_loaded', 'main_patch']
      integer :: n, k, n_failed
      n = -1
      call check_dataset(file, name, 'summary/case', 'number', n, error)
      do k = 1, size(counts)
         if (allocated(error)) return
         if (trim(counts(k)) /= 'n_loaded' .or. h5_exists(file, 'summary/n_loaded')) &
            call check_dataset(file, name, 'summary/'//trim(counts(k)), 'number', n, error)
      end do
      do k = 1, n_summary_columns
         if (allocated(error)) return
         if (h5_exists(file, 'summary/'//trim(summary_columns(1, k)))) call check_dataset(file, &
            name, 'summary/'//trim(summary_columns(1, k)), 'number', n, error)
      end do
      if (allocated(error) .or. .not. h5_exists(file, 'failures/case')) return
      n_failed = -1
      call check_dataset(file, name, 'failures/case', 'number', n_failed, error)
      if (.not. allocated(error)) call check_dataset(file, name, 'failures/message', 'text', &
         n_failed, error)
   end subroutine check_layout

   !> A 1-D dataset of `kind` ('number' or 'text') with `n` values (any length when n < 0:
   !> n is then set to its length).
   subroutine check_dataset(file, name, path, kind, n, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: name, path, kind
      integer, intent(inout) :: n
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: dims(:)
      integer :: type_size
      logical :: is_float
      character(len=:), allocatable :: class, found
      call h5_dataset_info(file, path, dims, type_size, is_float, error, type_class=class)
      if (allocated(error)) then
         deallocate (error)
         found = 'is missing'
      else if (size(dims) /= 1) then
         found = 'has '//str_int(size(dims))//' dimensions'
      else if ((kind == 'number' .and. class /= 'integer' .and. class /= 'float') .or. &
               (kind == 'text' .and. class /= 'text')) then
         found = 'holds '//class//' values'
      else if (n >= 0 .and. dims(1) /= n) then
         found = 'has '//str_int(dims(1))//' values'
      else
         if (n < 0) n = dims(1)
         return
      end if
      if (n >= 0) then
         found = found//'; expected 1-D '//kind//'s, '//str_int(n)//' of them (one per '// &
            'row of its table)'
      else
         found = found//'; expected 1-D '//kind//'s'
      end if
      call fatal_error(error, '"'//name//'": /'//path//' '//found//'; the file is damaged '// &
         'or is not a result file of this version', stat_invalid_input)
   end subroutine check_dataset


end module shcontact_output_output_checks
