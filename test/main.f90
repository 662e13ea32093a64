!> The one tester: runs every suite, one suite, or one test of a suite.
!>
!>     tester                 every suite
!>     tester SUITE           one suite
!>     tester SUITE TEST      one test
!>
!> Ends with the line `N passed, N failed` (`, N skipped` when some were skipped) and a non-zero
!> exit status on any failure.
program tester
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use testdrive, only: testsuite_type, unittest_type, error_type, new_testsuite, select_suite, &
      select_test
   use test_elliptic, only: collect_elliptic
   use test_roots, only: collect_roots
   use test_lapack, only: collect_lapack
   use test_testdrive, only: collect_testdrive
   use test_layout, only: collect_layout
   use test_registry, only: collect_registry
   use test_hertz, only: collect_hertz
   use test_semihertz, only: collect_semihertz
   use test_strip_influence, only: collect_strip_influence
   use test_normal_loading, only: collect_normal_loading
   use test_normal_loading_patches, only: collect_normal_loading_patches
   use test_profile_reader, only: collect_profile_reader
   use test_profile_invariance, only: collect_profile_invariance
   use test_profile_cleanup, only: collect_profile_cleanup
   use test_profile_builtin, only: collect_profile_builtin
   use test_spline, only: collect_spline
   use test_geometry, only: collect_geometry
   use test_kalker, only: collect_kalker
   use test_fastsim, only: collect_fastsim
   use test_fastsim_sh, only: collect_fastsim_sh
   use test_ellipse_correction, only: collect_ellipse_correction
   use test_coulomb, only: collect_coulomb
   use test_config, only: collect_config
   use test_hdf5io, only: collect_hdf5io
   use test_app, only: collect_app
   use test_output_files, only: collect_output_files
   use test_cli, only: collect_cli
   use test_api, only: collect_api
   use test_kinematics, only: collect_kinematics
   use test_kinematic_balance, only: collect_kinematic_balance
   use test_api_kinematic, only: collect_api_kinematic
   use test_flat_keys, only: collect_flat_keys
   use test_examples, only: collect_examples
   use test_validation, only: collect_validation
   use test_validation_normal, only: collect_validation_normal
   use test_validation_sets, only: collect_validation_sets
   use test_validation_kinematic_sets, only: collect_validation_kinematic_sets
   use test_contact_surface, only: collect_contact_surface
   use test_vertical_approach, only: collect_vertical_approach
   use test_performance_invariants, only: collect_performance_invariants
   use test_robustness, only: collect_robustness
   use test_input, only: collect_input
   use test_wheelset_geometry, only: collect_wheelset_geometry
   use test_profile_diagnostics, only: collect_profile_diagnostics
   use test_figures, only: collect_figures
   use test_preset, only: collect_preset
   use test_prescribed_patches, only: collect_prescribed_patches
   implicit none

   integer, parameter :: skipped_stat = 77
   type(testsuite_type), allocatable :: suites(:)
   character(len=:), allocatable :: suite_name, test_name
   integer :: is, n_pass, n_fail, n_skip

   suites = [ &
      new_testsuite('testdrive', collect_testdrive), &
      new_testsuite('preset', collect_preset), &
      new_testsuite('prescribed_patches', collect_prescribed_patches), &
      new_testsuite('layout', collect_layout), &
      new_testsuite('registry', collect_registry), &
      new_testsuite('elliptic', collect_elliptic), &
      new_testsuite('roots', collect_roots), &
      new_testsuite('lapack', collect_lapack), &
      new_testsuite('hertz', collect_hertz), &
      new_testsuite('semihertz', collect_semihertz), &
      new_testsuite('strip_influence', collect_strip_influence), &
      new_testsuite('normal_loading', collect_normal_loading), &
      new_testsuite('normal_loading_patches', collect_normal_loading_patches), &
      new_testsuite('profile_reader', collect_profile_reader), &
      new_testsuite('profile_invariance', collect_profile_invariance), &
      new_testsuite('profile_cleanup', collect_profile_cleanup), &
      new_testsuite('profile_builtin', collect_profile_builtin), &
      new_testsuite('spline', collect_spline), &
      new_testsuite('geometry', collect_geometry), &
      new_testsuite('kalker', collect_kalker), &
      new_testsuite('fastsim', collect_fastsim), &
      new_testsuite('fastsim_sh', collect_fastsim_sh), &
      new_testsuite('ellipse_correction', collect_ellipse_correction), &
      new_testsuite('coulomb', collect_coulomb), &
      new_testsuite('config', collect_config), &
      new_testsuite('hdf5io', collect_hdf5io), &
      new_testsuite('app', collect_app), &
      new_testsuite('output_files', collect_output_files), &
      new_testsuite('cli', collect_cli), &
      new_testsuite('api', collect_api), &
      new_testsuite('kinematics', collect_kinematics), &
      new_testsuite('kinematic_balance', collect_kinematic_balance), &
      new_testsuite('api_kinematic', collect_api_kinematic), &
      new_testsuite('flat_keys', collect_flat_keys), &
      new_testsuite('examples', collect_examples), &
      new_testsuite('validation', collect_validation), &
      new_testsuite('validation_normal', collect_validation_normal), &
      new_testsuite('validation_sets', collect_validation_sets), &
      new_testsuite('validation_kinematic_sets', collect_validation_kinematic_sets), &
      new_testsuite('contact_surface', collect_contact_surface), &
      new_testsuite('vertical_approach', collect_vertical_approach), &
      new_testsuite('performance_invariants', collect_performance_invariants), &
      new_testsuite('input', collect_input), &
      new_testsuite('wheelset_geometry', collect_wheelset_geometry), &
      new_testsuite('profile_diagnostics', collect_profile_diagnostics), &
      new_testsuite('figures', collect_figures), &
      new_testsuite('robustness', collect_robustness) &
      ]

   call read_selection(suite_name, test_name)
   n_pass = 0; n_fail = 0; n_skip = 0
   if (len(suite_name) == 0) then
      do is = 1, size(suites)
         call run_suite(suites(is), '')
      end do
   else
      is = select_suite(suites, suite_name)
      if (is == 0) then
         write (error_unit, '(a)') 'tester: no suite called "'//suite_name//'"; suites are:'
         do is = 1, size(suites)
            write (error_unit, '(a)') '  '//suites(is)%name
         end do
         error stop 2
      end if
      call run_suite(suites(is), test_name)
   end if

   if (n_skip > 0) then
      write (output_unit, '(i0,a,i0,a,i0,a)') n_pass, ' passed, ', n_fail, ' failed, ', n_skip, &
         ' skipped'
   else
      write (output_unit, '(i0,a,i0,a)') n_pass, ' passed, ', n_fail, ' failed'
   end if
   if (n_fail > 0) error stop 1

contains

   subroutine read_selection(suite_name, test_name)
      character(len=:), allocatable, intent(out) :: suite_name, test_name
      character(len=256) :: buf
      suite_name = ''
      test_name = ''
      if (command_argument_count() >= 1) then
         call get_command_argument(1, buf)
         suite_name = trim(buf)
      end if
      if (command_argument_count() >= 2) then
         call get_command_argument(2, buf)
         test_name = trim(buf)
      end if
   end subroutine read_selection

   subroutine run_suite(suite, only)
      type(testsuite_type), intent(in) :: suite
      character(len=*), intent(in) :: only
      type(unittest_type), allocatable :: tests(:)
      integer :: it

      call suite%collect(tests)
      if (len(only) > 0) then
         it = select_test(tests, only)
         if (it == 0) then
            write (error_unit, '(a)') 'tester: suite "'//suite%name//'" has no test "'//only// &
               '"; tests are:'
            do it = 1, size(tests)
               write (error_unit, '(a)') '  '//tests(it)%name
            end do
            error stop 2
         end if
         call run_one(suite%name, tests(it))
      else
         do it = 1, size(tests)
            call run_one(suite%name, tests(it))
         end do
      end if
   end subroutine run_suite

   subroutine run_one(suite_name, test)
      character(len=*), intent(in) :: suite_name
      type(unittest_type), intent(in) :: test
      type(error_type), allocatable :: error
      logical :: failed

      call test%test(error)
      if (allocated(error)) then
         if (error%stat == skipped_stat) then
            n_skip = n_skip + 1
            write (output_unit, '(a)') '  '//suite_name//' / '//test%name//' ... [SKIPPED]'
            if (allocated(error%message)) write (output_unit, '(a)') '      '//error%message
            return
         end if
      end if
      failed = allocated(error) .neqv. test%should_fail
      if (failed) then
         n_fail = n_fail + 1
         write (output_unit, '(a)') '  '//suite_name//' / '//test%name//' ... [FAILED]'
         if (allocated(error)) then
            if (allocated(error%message)) write (output_unit, '(a)') '      '//error%message
         end if
      else
         n_pass = n_pass + 1
         write (output_unit, '(a)') '  '//suite_name//' / '//test%name//' ... [PASSED]'
      end if
   end subroutine run_one

end program tester
