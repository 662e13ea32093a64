!> Scratch timing (issue 13): solve_load with reduction 'local-hertz' against 'coupled' on the
!> two shared patches (Y_WS = 0 and 5.8 mm), 100 strips.
program scratch
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact, only: wp, error_type, profile_type, read_profile, clean_profile, track_type, &
      contact_options_type, prepared_profiles_type, prepare_profiles, find_contact_patches, &
      wheelset_position_type, patch_geometry_type, material_type, normal_options_type, &
      new_normal_options, normal_contact_type, prepare_normal_contact, solve_load, &
      normal_patch_type
   implicit none
   type(profile_type) :: wheel, rail
   type(track_type) :: track
   type(prepared_profiles_type) :: prepared
   type(patch_geometry_type), allocatable :: patches(:)
   type(normal_options_type) :: options
   type(normal_contact_type) :: contact
   type(normal_patch_type) :: patch
   type(error_type), allocatable :: error
   type(material_type) :: mat
   character(len=11), parameter :: reductions(2) = ['local-hertz', 'coupled    ']
   real(wp), parameter :: y_ws(2) = [0.0_wp, 5.8_wp]
   integer(int64) :: t0, t1, rate
   integer :: ip, ir, it, nrep

   mat = material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, friction=0.3_wp)
   call read_profile('../shared/profiles/MBench_S1002_v3.prw', wheel, error)
   call clean_profile(wheel, error)
   call read_profile('../shared/profiles/MBench_UIC60_v3.prr', rail, error)
   call clean_profile(rail, error)
   track%rail_canted = .true.
   call prepare_profiles(wheel, rail, track, contact_options_type(), prepared, error)
   do ip = 1, 2
      call find_contact_patches(prepared, wheelset_position_type(y_ws=y_ws(ip)), patches, error)
      do ir = 1, 2
         call new_normal_options(options, error, reduction=trim(reductions(ir)), n_strips=100)
         call prepare_normal_contact(contact, patches(1), options, mat, error)
         nrep = merge(2000, 50, ir == 1)
         call system_clock(t0, rate)
         do it = 1, nrep
            call solve_load(contact, 64700.0_wp*(0.95_wp + 0.1_wp*mod(it, 7)/7.0_wp), patch, &
               error)
         end do
         call system_clock(t1)
         if (allocated(error)) print '(a)', error%message
         print '(a,f5.1,a,a12,a,f10.1,a)', 'Y_WS ', y_ws(ip), ' ', reductions(ir), &
            ' solve_load ', 1.0e6_wp*real(t1 - t0, wp)/rate/nrep, ' us'
      end do
   end do
end program scratch
