!> Loading a configuration: defaults, then a case file or namelist text, then the command line
!> overrides, then validation.
module shcontact_input_config_load
   use shcontact_core_error, only: error_type
   use shcontact_core_files, only: directory_part
   use shcontact_input_config_types, only: case_config_type
   use shcontact_input_config_parser, only: assignment_type, assignment_list_type, read_lines, &
      split_lines, parse_namelist, parse_override
   use shcontact_input_config_assign, only: apply_assignment
   use shcontact_input_config_validate, only: validate_config
   implicit none
   private

   public :: load_config, read_config_file, read_config_text, apply_override

contains

   !> Defaults, then the case file (when `filename` is not empty), then the overrides
   !> (`group%var=value`, in order), then validation.
   subroutine load_config(filename, overrides, config, error)
      !> Case file; '' for the built-in default case.
      character(len=*), intent(in) :: filename
      !> Overrides `group%var=value`.
      character(len=*), intent(in) :: overrides(:)
      !> The resolved configuration.
      type(case_config_type), intent(out) :: config
      !> Set on the first invalid input (stat_invalid_input) or unreadable file (stat_io).
      type(error_type), allocatable, intent(out) :: error
      integer :: i

      if (len_trim(filename) > 0) then
         call read_config_file(filename, config, error)
         if (allocated(error)) return
      end if
      do i = 1, size(overrides)
         call apply_override(config, overrides(i), error)
         if (allocated(error)) return
      end do
      call validate_config(config, error)
   end subroutine load_config

   !> Apply every assignment of a namelist case file onto `config`.
   subroutine read_config_file(filename, config, error)
      !> The case file.
      character(len=*), intent(in) :: filename
      !> Updated in place.
      type(case_config_type), intent(inout) :: config
      !> Set when the file cannot be read or holds an invalid assignment.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: lines(:)

      config%case_file = filename
      call read_lines(filename, lines, error)
      if (allocated(error)) return
      call apply_lines(config, lines, filename, case_directory(filename), error)
   end subroutine read_config_file

   !> The directory relative profile names are taken from: the case file's, or the current
   !> directory for a stream (/dev/stdin, a process substitution /dev/fd/N, /proc/self/fd/N).
   pure function case_directory(filename) result(dir)
      character(len=*), intent(in) :: filename
      character(len=:), allocatable :: dir
      dir = directory_part(filename)
      if (dir == '/dev' .or. index(dir, '/dev/') == 1 .or. index(dir, '/proc/') == 1) dir = ''
   end function case_directory

   !> A configuration from namelist text (as stored in an output file), validated.
   subroutine read_config_text(text, name, config, error)
      !> Namelist text, lines separated by new-line characters.
      character(len=*), intent(in) :: text
      !> What to call the text in messages.
      character(len=*), intent(in) :: name
      !> The configuration.
      type(case_config_type), intent(out) :: config
      !> Set when the text is not a valid configuration.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: lines(:)

      call split_lines(text, lines)
      call apply_lines(config, lines, name, '', error)
      if (allocated(error)) return
      call validate_config(config, error)
   end subroutine read_config_text

   !> Apply one override `group%var=value` (string values may be given without quotes).
   subroutine apply_override(config, text, error)
      !> Updated in place.
      type(case_config_type), intent(inout) :: config
      !> The override, e.g. `creepage%nu_x=1e-3` or `sweep%bound=weighted,clipped`.
      character(len=*), intent(in) :: text
      !> Set when the text is malformed or the assignment invalid.
      type(error_type), allocatable, intent(out) :: error
      type(assignment_type) :: a

      call parse_override(text, a, error)
      if (allocated(error)) return
      call apply_assignment(config, a, '', error)
   end subroutine apply_override

   !> Parse namelist lines and apply every assignment, in order.
   subroutine apply_lines(config, lines, name, base_dir, error)
      !> Updated in place.
      type(case_config_type), intent(inout) :: config
      !> The namelist lines.
      character(len=*), intent(in) :: lines(:)
      !> What to call the lines in messages (the file name).
      character(len=*), intent(in) :: name
      !> Directory of the case file, for relative profile names.
      character(len=*), intent(in) :: base_dir
      !> Set on the first malformed line or invalid assignment.
      type(error_type), allocatable, intent(out) :: error
      type(assignment_list_type) :: list
      integer :: i

      call parse_namelist(lines, name, list, error)
      if (allocated(error)) return
      do i = 1, list%n
         call apply_assignment(config, list%items(i), base_dir, error)
         if (allocated(error)) return
      end do
   end subroutine apply_lines

end module shcontact_input_config_load
