!> shcontact from modern Fortran (`use shcontact`, doc/api.md §1): the headline case with the
!> library's defaults (S1002 wheel on UIC60 canted 1:40, R0 = 460 mm, G = 82670 MPa, nu = 0.27,
!> mu = 0.3, FASTSIM_SH), t_y = 4.733 mm, normal force 64.7 kN, creepages 0.58e-3, 0.061e-3 and
!> spin 2.74e-4 1/mm. Prints `key value` lines.
!>
!> Built by the CMake project examples/cmake, the Makefile examples/makefile and the fpm project
!> examples/fpm_dependency; by hand:
!>     gfortran headline.f90 $(pkg-config --cflags --libs shcontact) -o headline
program headline
   use shcontact, only: contact_solver_type, contact_result_type, error_type, wp, &
      contact_load_type, load_normal_force, creepage_type
   implicit none
   type(contact_solver_type) :: wheel
   type(contact_result_type) :: result
   type(error_type), allocatable :: error

   call wheel%init('builtin:S1002', 'builtin:UIC60', error)
   if (allocated(error)) call stop_on(error)
   call wheel%solve(4.733_wp, 0.0_wp, contact_load_type(load_normal_force, 64.7e3_wp), &
      creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp), result, error)
   if (allocated(error)) call stop_on(error)
   print '(a)', '# headline case, modern Fortran interface'
   print '(a, es26.17e3)', 'fx ', result%main%fx
   print '(a, es26.17e3)', 'fy ', result%main%fy
   print '(a, es26.17e3)', 'mz ', result%main%mz
   print '(a, es26.17e3)', 'fn ', result%main%fn
   print '(a, i0)', 'n_patches ', result%n_patches

contains

   !> Report a library error and stop with its status.
   subroutine stop_on(error)
      type(error_type), intent(in) :: error
      write (*, '(a, i0, 2a)') 'error ', error%stat, ': ', error%message
      error stop 1
   end subroutine stop_on

end program headline
