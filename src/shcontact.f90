!> shcontact: wheel–rail rolling contact with the semi-Hertzian strip method and FASTSIM_SH.
!>
!> This facade re-exports the public API; users `use shcontact` and need nothing else.
module shcontact
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, &
      stat_numerical, stat_no_contact, stat_usage
   use shcontact_version_info, only: shcontact_version
   implicit none
   private

   public :: wp, error_type, fatal_error
   public :: stat_invalid_input, stat_io, stat_numerical, stat_no_contact, stat_usage
   public :: shcontact_version

end module shcontact
