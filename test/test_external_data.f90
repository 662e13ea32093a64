!> The one place where tests find data that is not the project's own: the sample measured
!> profiles and CONTACT's reference results, in a folder named by the environment variable
!> SHCONTACT_EXTERNAL_DATA (the folder that holds `profiles/` and `reference/`; `.ci/run` sets it
!> to the folder `shared` beside the clone). Without the variable a test that needs such data is
!> reported as skipped; with it, a missing file is a failure (the folder was named, so the data
!> must be there).
!>
!>     SHCONTACT_EXTERNAL_DATA=/path/to/data fpm test --profile debug --flag "..."
!>
!> A relative folder is taken from the working directory (the project root, where the tests
!> run); `external_file(..., absolute=.true.)` returns it as an absolute path for tests that run
!> the program in a scratch directory. doc/install.md, *External data*.
module test_external_data
   use testdrive, only: error_type, skip_test, test_failed
   implicit none
   private
   public :: external_data_variable, external_file, external_data_set

   !> Name of the environment variable that names the external-data folder.
   character(len=*), parameter :: external_data_variable = 'SHCONTACT_EXTERNAL_DATA'

contains

   !> Whether SHCONTACT_EXTERNAL_DATA is set to a non-empty value.
   logical function external_data_set()
      integer :: length, stat
      call get_environment_variable(external_data_variable, length=length, status=stat)
      external_data_set = stat == 0 .and. length > 0
   end function external_data_set

   !> The path of `relative` (e.g. 'profiles/MBench_S1002_v3.prw', 'reference/ty0_literal/')
   !> inside the external-data folder. When the variable is unset the test is marked skipped
   !> (error allocated, as skip_test does) and '' is returned; when it is set but the file or
   !> folder is absent the test fails with a message naming both.
   function external_file(relative, error, absolute) result(path)
      character(len=*), intent(in) :: relative
      type(error_type), allocatable, intent(out) :: error
      !> Prefix a relative folder with the working directory (default .false.).
      logical, intent(in), optional :: absolute
      character(len=:), allocatable :: path
      character(len=:), allocatable :: folder
      integer :: length, stat
      logical :: there

      path = ''
      if (.not. external_data_set()) then
         call skip_test(error, external_data_variable//' is not set (needs external data: '// &
            relative//')')
         return
      end if
      call get_environment_variable(external_data_variable, length=length)
      allocate (character(len=length) :: folder)
      call get_environment_variable(external_data_variable, folder)
      if (folder(length:length) /= '/') folder = folder//'/'
      if (present(absolute)) then
         if (absolute .and. folder(1:1) /= '/') folder = working_directory()//'/'//folder
      end if
      path = folder//relative
      inquire (file=path, exist=there)
      ! A folder: gfortran's inquire answers for directories too, others may not; try its '.'.
      if (.not. there .and. path(len(path):len(path)) == '/') inquire (file=path//'.', exist=there)
      if (.not. there) then
         call test_failed(error, external_data_variable//'='//folder//' has no '//relative)
         path = ''
      end if
   end function external_file

   !> The working directory ($PWD).
   function working_directory() result(dir)
      character(len=:), allocatable :: dir
      character(len=4096) :: buf
      integer :: length, stat
      call get_environment_variable('PWD', buf, length, stat)
      dir = buf(1:length)
   end function working_directory

end module test_external_data
