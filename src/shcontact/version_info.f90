!> The version of shcontact (kept equal to fpm.toml's `version`; a test checks it).
module shcontact_version_info
   implicit none
   private

   public :: shcontact_version

   !> Semantic version of the library and the program.
   character(len=*), parameter :: shcontact_version = '0.1.0'

end module shcontact_version_info
