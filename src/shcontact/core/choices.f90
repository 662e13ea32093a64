!> The choices of an option (issue 26): each allowed value with its name, the integer code the
!> code uses after validation, and a short description. The registries of the layers' options
!> (shcontact_normal_option_registry, shcontact_tangential_option_registry) and of the case
!> file's groups (shcontact_input_config_variables) are built from these, so that a choice's name,
!> code and description are written once; the namelist reader, the option setters, the resolved
!> namelist, the documentation's tables and the headers' option lists all come from them (test
!> `registry`).
module shcontact_core_choices
   implicit none
   private

   public :: choice_type, choice_code, choice_name, choice_name_length, choice_list, &
      normalised_choice

   !> Length of a choice's name.
   integer, parameter :: name_len = 16

   !> One allowed value of an option.
   type :: choice_type
      !> The value as written in a case file or given to an option setter (lower case).
      character(len=name_len) :: name = ''
      !> The integer code the library and the app use after validation.
      integer :: code = 0
      !> What it means, in a few words (documentation and `--check`).
      character(len=120) :: help = ''
   end type choice_type

contains

   !> Lower case, no surrounding blanks, '_' read as '-' (case files often use either).
   pure function normalised_choice(text) result(key)
      !> The value as written.
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: key
      integer :: i, ic
      key = trim(adjustl(text))
      do i = 1, len(key)
         ic = iachar(key(i:i))
         if (ic >= iachar('A') .and. ic <= iachar('Z')) key(i:i) = achar(ic + 32)
         if (key(i:i) == '_') key(i:i) = '-'
      end do
   end function normalised_choice

   !> The code of the choice named `text` (case-insensitive, '_' read as '-'); `unknown` (0
   !> unless given) when no choice has that name.
   pure integer function choice_code(choices, text, unknown) result(code)
      !> The choices of one option.
      type(choice_type), intent(in) :: choices(:)
      !> The value as written.
      character(len=*), intent(in) :: text
      !> Returned for an unknown name (default 0).
      integer, intent(in), optional :: unknown
      character(len=:), allocatable :: key
      integer :: i
      key = normalised_choice(text)
      do i = 1, size(choices)
         if (key == trim(choices(i)%name)) then
            code = choices(i)%code
            return
         end if
      end do
      code = 0
      if (present(unknown)) code = unknown
   end function choice_code

   !> The name of the choice with `code`, blank-padded; '?' when no choice has it.
   pure function padded_name(choices, code) result(name)
      type(choice_type), intent(in) :: choices(:)
      integer, intent(in) :: code
      character(len=name_len) :: name
      integer :: i
      name = '?'
      do i = 1, size(choices)
         if (choices(i)%code == code) then
            name = choices(i)%name
            return
         end if
      end do
   end function padded_name

   !> The length of [[choice_name]]'s result.
   pure integer function choice_name_length(choices, code)
      !> The choices of one option.
      type(choice_type), intent(in) :: choices(:)
      !> A code.
      integer, intent(in) :: code
      choice_name_length = len_trim(padded_name(choices, code))
   end function choice_name_length

   !> The name of the choice with `code`; '?' when no choice has it. (Its length comes from a
   !> specification function, not a deferred-length result, which gfortran 12 keeps in a static
   !> variable of the caller: option names are asked for by threads; doc/performance.md,
   !> "Threads and strings".)
   pure function choice_name(choices, code) result(name)
      !> The choices of one option.
      type(choice_type), intent(in) :: choices(:)
      !> A code.
      integer, intent(in) :: code
      character(len=choice_name_length(choices, code)) :: name
      name = padded_name(choices, code)
   end function choice_name

   !> The length of [[choice_list]]'s result.
   pure integer function list_length(choices)
      type(choice_type), intent(in) :: choices(:)
      integer :: i
      list_length = 2*max(size(choices) - 1, 0)
      do i = 1, size(choices)
         list_length = list_length + len_trim(choices(i)%name) + 2
      end do
   end function list_length

   !> "'a', 'b', 'c'": the names for messages and documentation.
   pure function choice_list(choices) result(list)
      !> The choices of one option.
      type(choice_type), intent(in) :: choices(:)
      character(len=list_length(choices)) :: list
      integer :: i, at, n
      at = 0
      do i = 1, size(choices)
         if (i > 1) then
            list(at + 1:at + 2) = ', '
            at = at + 2
         end if
         n = len_trim(choices(i)%name)
         list(at + 1:at + n + 2) = "'"//choices(i)%name(1:n)//"'"
         at = at + n + 2
      end do
   end function choice_list

end module shcontact_core_choices
