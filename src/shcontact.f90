!> shcontact: wheel–rail rolling contact with the semi-Hertzian strip method and FASTSIM_SH.
!>
!> This facade re-exports the public API; users `use shcontact` and need nothing else.
module shcontact
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input, stat_io, &
      stat_numerical, stat_no_contact, stat_usage
   use shcontact_version_info, only: shcontact_version
   use shcontact_core_material, only: material_type
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_patch, only: tangential_patch_type
   implicit none
   private

   public :: wp, error_type, fatal_error
   public :: stat_invalid_input, stat_io, stat_numerical, stat_no_contact, stat_usage
   public :: shcontact_version
   public :: material_type, profile_type, patch_geometry_type, normal_patch_type
   public :: tangential_patch_type

end module shcontact
