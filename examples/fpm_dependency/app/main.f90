!> The headline case through `use shcontact`, built by fpm with shcontact as a dependency
!> (`fpm run` in this directory). Prints `key value` lines, as examples/fortran_api/headline.f90.
program fpm_dependency
   use shcontact, only: contact_solver_type, contact_result_type, error_type, wp, &
      contact_load_type, load_normal_force, creepage_type
   implicit none
   type(contact_solver_type) :: wheel
   type(contact_result_type) :: result
   type(error_type), allocatable :: error

   call wheel%init('builtin:S1002', 'builtin:UIC60', error)
   if (.not. allocated(error)) call wheel%solve(4.733_wp, 0.0_wp, &
      contact_load_type(load_normal_force, 64.7e3_wp), &
      creepage_type(0.58e-3_wp, 0.061e-3_wp, 2.74e-4_wp), result, error)
   if (allocated(error)) then
      write (*, '(a, i0, 2a)') 'error ', error%stat, ': ', error%message
      error stop 1
   end if
   print '(a)', '# headline case, shcontact as an fpm dependency'
   print '(a, es26.17e3)', 'fx ', result%main%fx
   print '(a, es26.17e3)', 'fy ', result%main%fy
   print '(a, es26.17e3)', 'mz ', result%main%mz
   print '(a, es26.17e3)', 'fn ', result%main%fn
end program fpm_dependency
