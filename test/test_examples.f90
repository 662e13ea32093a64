!> The interface examples built and run as separate programs (issue 8): the library of this build
!> is installed into a scratch prefix with `scripts/install --archive` (shared library, header,
!> pkg-config file), then the fixed-form Fortran 77 example, the C example and the Python ctypes
!> script are built with `pkg-config --cflags --libs shcontact` and run. Each prints the headline
!> case and three bad calls; the numbers must agree with each other bit for bit (one shared
!> library) and with the solver object of this tester to round-off, and every bad call must
!> return its status. A C driver also counts the heap allocations of shcontact_solve.
!>
!> The installed package is also used as a user's project would (issue 15): a modern Fortran
!> program through pkg-config, the CMake project examples/cmake (find_package(shcontact), target
!> shcontact::shcontact), the Makefile project examples/makefile, and the fpm project
!> examples/fpm_dependency (shcontact as a path dependency) built by fpm itself.
!>
!> The archive is the newest build/*/shcontact/libshcontact.a (the one `fpm test` just built),
!> or $SHCONTACT_ARCHIVE; the modules those of the directory of the newest build/*/shcontact*.mod
!> (gfortran leaves an unchanged .mod file alone, so shcontact.mod alone may point to another
!> profile's older build), or $SHCONTACT_MODULES. Missing tools (bash, gfortran, gcc, pkg-config, python3, cmake, make,
!> fpm) skip a test.
module test_examples
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp, i8
   use shcontact_api_solver, only: contact_result_type
   use shcontact_api_values, only: kinematic_value_count, kinematic_values, value_sum_fx, &
      value_sum_fy, value_sum_fz, value_fn, value_nu_x, value_nu_y, value_phi, value_x_track
   use test_api, only: headline_result, headline_t_y
   use test_api_kinematic, only: kinematic_case_result
   use test_external_data, only: external_file
   implicit none
   private

   public :: collect_examples

   !> Scratch directory (under build/, which git ignores) and the install prefix in it.
   character(len=*), parameter :: scratch = 'build/test_examples'
   character(len=*), parameter :: prefix = scratch//'/prefix'
   character(len=*), parameter :: pkg_config = 'PKG_CONFIG_PATH='//prefix// &
      '/lib/pkgconfig pkg-config'
   !> Keys printed by every example: the headline case, then the kinematic call.
   character(len=*), parameter :: keys(17) = [character(len=11) :: 'fx', 'fy', 'mz', 'fn', &
      'fx_norm', 'fy_norm', 'gamma0', 'n_patches', 'sum_fz', 'kin_sum_fx', 'kin_sum_fy', &
      'kin_sum_fz', 'kin_fn', 'kin_nu_x', 'kin_nu_y', 'kin_phi', 'kin_x_track']
   !> Where the kinematic keys' numbers are in the kinematic layout.
   integer, parameter :: kin_index(8) = [value_sum_fx, value_sum_fy, value_sum_fz, value_fn, &
      value_nu_x, value_nu_y, value_phi, value_x_track]
   !> Round-off between this tester and the installed library, which may come from a build with
   !> other optimisation flags (the same build agrees to the last bit).
   real(wp), parameter :: round_off = 1.0e-9_wp

   !> Install state of this run: 0 not tried, 1 installed, 2 failed, 3 tools missing.
   integer, save :: install_state = 0

contains

   !> Collect all exported unit tests.
   subroutine collect_examples(testsuite)
      !> The tests.
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('install_prefix', test_install), &
         new_unittest('fortran_api_example', test_fortran_api), &
         new_unittest('cmake_project', test_cmake), &
         new_unittest('makefile_project', test_makefile), &
         new_unittest('fpm_dependency_example', test_fpm_dependency), &
         new_unittest('legacy_f77_example', test_f77), &
         new_unittest('c_example', test_c), &
         new_unittest('python_ctypes_example', test_python), &
         new_unittest('python_finds_library_by_pkg_config', test_python_pkg_config), &
         new_unittest('flat_examples_fields_and_arrays', test_flat_extras), &
         new_unittest('flat_examples_wheelset', test_flat_wheelset), &
         new_unittest('interfaces_agree', test_agree), &
         new_unittest('doc_api_numbers', test_doc_numbers), &
         new_unittest('no_allocation_in_solve', test_allocations), &
         new_unittest('vehicle_wheelset_short_run', test_vehicle), &
         new_unittest('vehicle_wheelset_measured_pair', test_vehicle_measured) &
         ]
   end subroutine collect_examples

   !> The scratch install has the shared library, the header, the library's modules (and only
   !> them) in include/shcontact, a working pkg-config file and the CMake package files.
   subroutine test_install(error)
      type(error_type), allocatable, intent(out) :: error
      call ensure_installed(error)
      if (allocated(error)) return
      call check(error, exists(prefix//'/lib/libshcontact.so') .and. &
         exists(prefix//'/include/shcontact.h') .and. &
         exists(prefix//'/lib/pkgconfig/shcontact.pc'), &
         message='shared library, header or pkg-config file missing in '//prefix)
      if (allocated(error)) return
      call check(error, run(pkg_config//' --exists shcontact') == 0, &
         message='pkg-config does not find shcontact.pc')
      if (allocated(error)) return
      call check(error, exists(prefix//'/include/shcontact/shcontact.mod') .and. &
         exists(prefix//'/include/shcontact/shcontact_api_solver.mod'), &
         message='library modules missing in '//prefix//'/include/shcontact')
      if (allocated(error)) return
      ! No module of the app, the benchmark or the validation program; none flat in include/.
      call check(error, run('ls '//prefix//'/include/*.mod') /= 0 .and. &
         run('ls '//prefix//'/include/shcontact/ | grep -E "^(shcontact_app|bench_|'// &
         'validate_)"') /= 0, message='modules other than the library''s installed in '//prefix)
      if (allocated(error)) return
      ! One module per source file under src/ (doc/api.md §4 says so).
      call check(error, run('test $(ls '//prefix//'/include/shcontact/*.mod | wc -l) -eq '// &
         '$(find src -name "*.[fF]90" | wc -l)') == 0, message='the installed modules are '// &
         'not one per source file under src/ (doc/api.md §4)')
      if (allocated(error)) return
      call check(error, exists(prefix//'/lib/cmake/shcontact/shcontactConfig.cmake') .and. &
         exists(prefix//'/lib/cmake/shcontact/shcontactConfigVersion.cmake'), &
         message='CMake package files missing in '//prefix//'/lib/cmake/shcontact')
   end subroutine test_install

   !> examples/fortran_api/headline.f90 (`use shcontact`) built with pkg-config's flags.
   subroutine test_fortran_api(error)
      type(error_type), allocatable, intent(out) :: error
      call ensure_installed(error)
      if (allocated(error)) return
      call check(error, run('gfortran examples/fortran_api/headline.f90 $('//pkg_config// &
         ' --cflags --libs shcontact) -o '//scratch//'/fortran_headline 2> '// &
         output('fortran_build')), 0, message='building examples/fortran_api/headline.f90 '// &
         'failed: see '//output('fortran_build'))
      if (allocated(error)) return
      call run_headline(scratch//'/fortran_headline', 'fortran', error)
   end subroutine test_fortran_api

   !> The CMake project examples/cmake (modern Fortran, C and F77 programs linked to the
   !> imported target shcontact::shcontact) configured against the scratch prefix.
   subroutine test_cmake(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: dir = scratch//'/cmake'
      call ensure_installed(error)
      if (allocated(error)) return
      if (run('command -v cmake') /= 0) then
         call skip_test(error, 'cmake not found (apt-get install cmake)')
         return
      end if
      call check(error, run('rm -rf '//dir//' && cmake -S examples/cmake -B '//dir// &
         ' -DCMAKE_PREFIX_PATH=$(pwd)/'//prefix//' > '//output('cmake_configure')//' 2>&1'), 0, &
         message='cmake could not configure examples/cmake: see '//output('cmake_configure'))
      if (allocated(error)) return
      call check(error, run('cmake --build '//dir//' > '//output('cmake_build')//' 2>&1'), 0, &
         message='cmake --build failed: see '//output('cmake_build'))
      if (allocated(error)) return
      call run_headline(dir//'/headline_fortran', 'cmake_fortran', error)
      if (allocated(error)) return
      call run_headline(dir//'/headline_c', 'cmake_c', error)
      if (allocated(error)) return
      call run_headline(dir//'/headline_f77', 'cmake_f77', error)
   end subroutine test_cmake

   !> The Makefile project examples/makefile, with the scratch prefix's pkg-config file.
   subroutine test_makefile(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: dir = scratch//'/make'
      call ensure_installed(error)
      if (allocated(error)) return
      if (run('command -v make') /= 0) then
         call skip_test(error, 'make not found')
         return
      end if
      call check(error, run('rm -rf '//dir//' && PKG_CONFIG_PATH=$(pwd)/'//prefix// &
         '/lib/pkgconfig make -C examples/makefile OUT=$(pwd)/'//dir//' > '// &
         output('make_build')//' 2>&1'), 0, message='make failed: see '//output('make_build'))
      if (allocated(error)) return
      call run_headline(dir//'/headline_fortran', 'make_fortran', error)
      if (allocated(error)) return
      call run_headline(dir//'/headline_c', 'make_c', error)
      if (allocated(error)) return
      call run_headline(dir//'/headline_f77', 'make_f77', error)
   end subroutine test_makefile

   !> examples/fpm_dependency built and run by fpm: a copy under the scratch directory whose
   !> path dependency points back at this repository.
   subroutine test_fpm_dependency(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: dir = scratch//'/fpm_dependency'
      if (run('command -v fpm') /= 0) then
         call skip_test(error, 'fpm not found')
         return
      end if
      call check(error, run('grep -q ''^shcontact.path = "../.."'' examples/fpm_dependency/'// &
         'fpm.toml') == 0, message='examples/fpm_dependency/fpm.toml: shcontact.path is not '// &
         '"../.."')
      if (allocated(error)) return
      call check(error, run('mkdir -p '//scratch//' && rm -rf '//dir//' && mkdir '//dir// &
         ' && cp -r examples/fpm_dependency/fpm.toml examples/fpm_dependency/app '//dir// &
         ' && sed -i ''s|^shcontact.path = "../.."|shcontact.path = "../../.."|'' '//dir// &
         '/fpm.toml'), 0, message='cannot copy examples/fpm_dependency to '//dir)
      if (allocated(error)) return
      call check(error, run('cd '//dir//' && fpm build > ../fpm_dependency_build.out 2>&1'), 0, &
         message='fpm build of examples/fpm_dependency failed: see '// &
         output('fpm_dependency_build'))
      if (allocated(error)) return
      call run_headline('cd '//dir//' && fpm run --', 'fpm_dependency', error)
   end subroutine test_fpm_dependency

   !> Run a headline program and compare its forces with the solver object of this tester.
   subroutine run_headline(command, name, error)
      character(len=*), intent(in) :: command, name
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: expected
      character(len=2), parameter :: force_keys(4) = ['fx', 'fy', 'mz', 'fn']
      real(wp) :: found(4)
      integer :: i

      call check(error, run('( '//command//' ) > '//output(name)), 0, &
         message='the '//name//' program failed: see '//output(name))
      if (allocated(error)) return
      call headline_result(expected, error)
      if (allocated(error)) return
      do i = 1, 4
         found(i) = value_of(output(name), force_keys(i))
      end do
      call check(error, all(found < huge(1.0_wp)), message=output(name)//': fx, fy, mz or fn '// &
         'missing')
      if (allocated(error)) return
      call check(error, found(1), expected%main%fx, rel=.true., thr=round_off, &
         message=name//': fx')
      if (allocated(error)) return
      call check(error, found(2), expected%main%fy, rel=.true., thr=round_off, &
         message=name//': fy')
      if (allocated(error)) return
      call check(error, found(3), expected%main%mz, rel=.true., thr=round_off, &
         message=name//': mz')
      if (allocated(error)) return
      call check(error, found(4), expected%main%fn, rel=.true., thr=round_off, &
         message=name//': fn')
   end subroutine run_headline

   !> The fixed-form Fortran 77 example; it ends without gfortran's note on floating-point
   !> flags on stderr (it ends at END, not at STOP).
   subroutine test_f77(error)
      type(error_type), allocatable, intent(out) :: error
      call example_test('gfortran', 'gfortran examples/legacy_f77/headline.f $('//pkg_config// &
         ' --cflags --libs shcontact) -o '//scratch//'/f77_headline', &
         scratch//'/f77_headline', 'f77', error)
      if (allocated(error)) return
      call check(error, run(scratch//'/f77_headline > /dev/null 2> '//output('f77_stderr')// &
         ' && ! grep -q "floating-point" '//output('f77_stderr')), 0, &
         message='the F77 example ends with a note on stderr: see '//output('f77_stderr'))
   end subroutine test_f77

   !> The C example.
   subroutine test_c(error)
      type(error_type), allocatable, intent(out) :: error
      call example_test('gcc', 'gcc -std=c99 -Wall -Wextra -Werror examples/c_api/headline.c $('// &
         pkg_config//' --cflags --libs shcontact) -o '//scratch//'/c_headline', &
         scratch//'/c_headline', 'c', error)
   end subroutine test_c

   !> The Python ctypes script.
   subroutine test_python(error)
      type(error_type), allocatable, intent(out) :: error
      call example_test('python3', '', 'python3 examples/python_ctypes/headline.py --lib '// &
         prefix//'/lib/libshcontact.so', 'python', error)
   end subroutine test_python

   !> The Python script without --lib and without $SHCONTACT_LIB finds the installed library
   !> through pkg-config (`pkg-config --variable=libdir shcontact`) and prints what it prints
   !> with --lib.
   subroutine test_python_pkg_config(error)
      type(error_type), allocatable, intent(out) :: error
      call ensure_installed(error)
      if (allocated(error)) return
      if (run('command -v python3') /= 0) then
         call skip_test(error, 'python3 not found')
         return
      end if
      call check(error, run('env -u SHCONTACT_LIB PKG_CONFIG_PATH=$(pwd)/'//prefix// &
         '/lib/pkgconfig python3 examples/python_ctypes/headline.py > '// &
         output('python_pkg_config')), 0, message='headline.py without --lib failed: see '// &
         output('python_pkg_config'))
      if (allocated(error)) return
      if (.not. exists(output('python'))) return
      call check(error, run('cmp '//output('python')//' '//output('python_pkg_config')), 0, &
         message='headline.py prints other numbers with the library found by pkg-config')
   end subroutine test_python_pkg_config

   !> The F77 and C examples create their contact from profile arrays (the numbers above are
   !> the built-in profiles' by name, to round-off) and print the main patch's element fields:
   !> Σ px·area and Σ py·area equal F_x and F_y, and a one-point wheel array gives status 2.
   subroutine test_flat_extras(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=3), parameter :: names(2) = ['f77', 'c  ']
      character(len=:), allocatable :: file
      integer :: i
      call ensure_installed(error)
      if (allocated(error)) return
      do i = 1, size(names)
         file = output(trim(names(i)))
         if (.not. exists(file)) then
            call skip_test(error, 'no '//trim(names(i))//' example output (run the suite)')
            return
         end if
         call check(error, value_of(file, 'field_nx')*value_of(file, 'field_ny') > 0.0_wp .and. &
            value_of(file, 'field_slip_elements') > 0.0_wp, &
            message=file//': field sizes or slip elements missing')
         if (allocated(error)) return
         call check(error, value_of(file, 'field_sum_fx'), value_of(file, 'fx'), rel=.true., &
            thr=1.0e-10_wp, message=file//': sum of px*area is not fx')
         if (allocated(error)) return
         call check(error, value_of(file, 'field_sum_fy'), value_of(file, 'fy'), rel=.true., &
            thr=1.0e-10_wp, message=file//': sum of py*area is not fy')
         if (allocated(error)) return
         call check_bad_call(file, ['status_bad_array'], [2], error)
         if (allocated(error)) return
      end do
   end subroutine test_flat_extras

   !> The F77 and C examples' wheelset call (SHC_SOLVE_WS, shcontact_solve_wheelset and a wheel's
   !> value by name) prints the Fortran wheelset_solver_type's totals and wheels, the same in both.
   subroutine test_flat_wheelset(error)
      use shcontact_api_wheelset, only: wheelset_solver_type, wheelset_result_type, wheel_right, &
         wheel_left
      use shcontact_geometry_kinematics, only: wheelset_state_type
      use shcontact_core_error, only: lib_error => error_type
      use shcontact_api_solver, only: contact_load_type, load_vertical_force
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: ws_keys(6) = [character(len=17) :: 'ws_fx', 'ws_fy', &
         'ws_fz', 'ws_mz', 'ws_right_n_loaded', 'ws_left_sum_fy']
      character(len=3), parameter :: names(2) = ['f77', 'c  ']
      type(wheelset_solver_type) :: ws
      type(wheelset_result_type) :: r
      type(lib_error), allocatable :: err
      real(wp) :: expected(size(ws_keys)), found(size(ws_keys), 2)
      integer :: i, j

      call ensure_installed(error)
      if (allocated(error)) return
      if (.not. (exists(output('f77')) .and. exists(output('c')))) then
         call skip_test(error, 'no F77 or C example output (run the suite)')
         return
      end if
      call ws%init('builtin:S1002', 'builtin:UIC60', err)
      if (.not. allocated(err)) call ws%solve(wheelset_state_type(y_ws=5.0_wp, yaw=2.0e-3_wp, &
         roll=0.0_wp, v_forward=30.0e3_wp, v_lateral=10.0_wp, v_vertical=0.0_wp, &
         roll_rate=0.0_wp, yaw_rate=0.01_wp, pitch_rate=-30.0e3_wp/460.0_wp), &
         contact_load_type(load_vertical_force, 64.7e3_wp), &
         contact_load_type(load_vertical_force, 60.0e3_wp), r, err)
      if (allocated(err)) then
         call test_failed(error, 'Fortran wheelset: '//err%message)
         return
      end if
      expected = [r%fx, r%fy, r%fz, r%mz, real(r%wheel(wheel_right)%n_loaded, wp), &
         r%wheel(wheel_left)%track%fy]
      do j = 1, size(names)
         do i = 1, size(ws_keys)
            found(i, j) = value_of(output(trim(names(j))), trim(ws_keys(i)))
            call check(error, found(i, j), expected(i), rel=.true., thr=round_off, &
               message=trim(names(j))//' example: '//trim(ws_keys(i)))
            if (allocated(error)) return
         end do
      end do
      call check(error, all(transfer(found(:, 1), 0_i8, size(ws_keys)) == &
         transfer(found(:, 2), 0_i8, size(ws_keys))), message='F77 and C wheelset differ')
   end subroutine test_flat_wheelset

   !> The three interfaces print the same numbers, bit for bit.
   subroutine test_agree(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: f77(size(keys)), c(size(keys)), python(size(keys))
      logical :: have(3)
      integer :: i

      call ensure_installed(error)
      if (allocated(error)) return
      have = [exists(output('f77')), exists(output('c')), exists(output('python'))]
      if (count(have) < 2) then
         call skip_test(error, 'fewer than two example outputs (run the suite, not this test)')
         return
      end if
      if (have(1)) call read_values(output('f77'), f77, error)
      if (allocated(error)) return
      if (have(2)) call read_values(output('c'), c, error)
      if (allocated(error)) return
      if (have(3)) call read_values(output('python'), python, error)
      if (allocated(error)) return
      do i = 1, size(keys)
         if (all(have(1:2))) call check(error, transfer(f77(i), 0_i8) == transfer(c(i), 0_i8), &
            message='F77 and C differ in '//trim(keys(i)))
         if (allocated(error)) return
         if (all(have(2:3))) call check(error, transfer(c(i), 0_i8) == &
            transfer(python(i), 0_i8), message='C and Python differ in '//trim(keys(i)))
         if (allocated(error)) return
      end do
   end subroutine test_agree

   !> The numbers doc/api.md quotes (indented `key value` lines, 8 digits) are those the F77
   !> example prints.
   subroutine test_doc_numbers(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: doc = 'doc/api.md'
      real(wp) :: printed(size(keys)), x
      logical :: quoted(size(keys))
      character(len=512) :: line
      character(len=32) :: name
      integer :: unit, stat, i

      call ensure_installed(error)
      if (allocated(error)) return
      if (.not. exists(output('f77'))) then
         call skip_test(error, 'no F77 example output (run the suite, not this test)')
         return
      end if
      call read_values(output('f77'), printed, error)
      if (allocated(error)) return
      quoted = .false.
      open (newunit=unit, file=doc, status='old', action='read')
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (line(1:4) /= '    ' .or. line(5:5) == ' ') cycle
         read (line, *, iostat=stat) name, x
         if (stat /= 0) cycle
         do i = 1, size(keys)
            if (name /= keys(i)) cycle
            quoted(i) = .true.
            call check(error, x, printed(i), rel=.true., thr=1.0e-7_wp, &
               message=doc//': '//trim(line)//' differs from the example')
         end do
         if (allocated(error)) exit
      end do
      close (unit)
      if (allocated(error)) return
      call check(error, all(quoted), message=doc//': a quoted example number is missing')
   end subroutine test_doc_numbers

   !> shcontact_solve allocates nothing at a repeated wheel position (new loads, load modes and
   !> creepages), nor when the wheel moves among positions whose tables fit the workspaces
   !> (t_y = 0, 1, 2, 4.733 mm after a warm-up over them, both load modes). The count at new
   !> positions (workspaces may grow) is printed but not checked here.
   subroutine test_allocations(error)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: same, moved
      integer :: unit, stat(2)
      character(len=64) :: key(2)

      call ensure_installed(error)
      if (allocated(error)) return
      if (run('command -v gcc') /= 0) then
         call skip_test(error, 'no C compiler')
         return
      end if
      if (run('gcc -std=gnu99 examples/c_api/alloc_check.c $('//pkg_config// &
         ' --cflags --libs shcontact) -o '//scratch//'/alloc_check') /= 0) then
         call skip_test(error, 'the allocation counter needs glibc (__libc_malloc)')
         return
      end if
      call check(error, run(scratch//'/alloc_check > '//output('alloc')), 0, &
         message='alloc_check failed (a solve returned an error)')
      if (allocated(error)) return
      open (newunit=unit, file=output('alloc'), status='old', action='read')
      read (unit, *) key(1)
      read (unit, *, iostat=stat(1)) key(1), same
      read (unit, *, iostat=stat(2)) key(2), moved
      close (unit)
      call check(error, all(stat == 0) .and. key(1) == 'same_position' .and. &
         key(2) == 'moved_position', message='alloc_check output')
      if (allocated(error)) return
      call check(error, same, 0.0_wp, message='allocations per shcontact_solve at the same '// &
         'position')
      if (allocated(error)) return
      call check(error, moved, 0.0_wp, message='allocations per shcontact_solve moving among '// &
         'positions already visited')
   end subroutine test_allocations

   !> The vehicle example (examples/vehicle/wheelset.f, fixed-form Fortran 77 through
   !> SHC_SOLVE_WS, both wheels in one call) built against the installed library and run for 0.05 s from a 3 mm offset:
   !> no failed contact call, finite forces, each wheel carrying about its 64.7 kN, a lateral
   !> contact force that opposes the offset at the start, and the wheelset moving back towards
   !> the track centre; nothing on stderr about floating-point flags; `--help` prints the usage
   !> with status 0.
   subroutine test_vehicle(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: csv = scratch//'/vehicle.csv'
      real(wp), allocatable :: rows(:, :)
      real(wp) :: failed

      call build_vehicle(error)
      if (allocated(error)) return
      call check(error, run(scratch//'/wheelset --duration 0.05 --dt 2.5e-4 --every 1 --csv '// &
         csv//' > '//output('vehicle')//' 2> '//output('vehicle_stderr')), 0, &
         message='the vehicle example failed: see '//output('vehicle'))
      if (allocated(error)) return
      call check(error, run('! grep -q "floating-point" '//output('vehicle_stderr')), 0, &
         message='the vehicle example ends with a note on stderr: '//output('vehicle_stderr'))
      if (allocated(error)) return
      call check(error, run(scratch//'/wheelset --help > '//output('vehicle_help')//' 2>&1 '// &
         '&& grep -q "^usage: wheelset" '//output('vehicle_help')), 0, &
         message='wheelset --help: no usage, or a non-zero status: '//output('vehicle_help'))
      if (allocated(error)) return
      failed = value_of(output('vehicle'), 'failed_calls')
      call check(error, failed, 0.0_wp, message='failed contact calls')
      if (allocated(error)) return
      call check(error, value_of(output('vehicle'), 'wheelset_calls'), 201.0_wp, &
         message='wheelset calls: one per step, 201 steps')
      if (allocated(error)) return
      call read_vehicle_csv(csv, rows, error)
      if (allocated(error)) return
      call check(error, rows(2, 1) > 0.0_wp .and. rows(14, 1) < 0.0_wp, &
         message='the lateral contact force does not oppose the initial offset')
      if (allocated(error)) return
      call check(error, rows(2, size(rows, 2)) < 0.5_wp*rows(2, 1), &
         message='the wheelset does not move back towards the centre')
   end subroutine test_vehicle

   !> The vehicle example built against the installed library, as scratch/wheelset.
   subroutine build_vehicle(error)
      type(error_type), allocatable, intent(out) :: error
      call ensure_installed(error)
      if (allocated(error)) return
      call check(error, run('gfortran examples/vehicle/wheelset.f $('//pkg_config// &
         ' --cflags --libs shcontact) -o '//scratch//'/wheelset 2> '//output('vehicle_build')), &
         0, message='building examples/vehicle/wheelset.f failed: see '// &
         output('vehicle_build'))
   end subroutine build_vehicle

   !> The vehicle example on profile files (`--wheel`, `--rail`) with options (`--set`, through
   !> SHC_SET_OPTION on the wheelset handle): the external data's measured pair, a worn MiniProf
   !> wheel on a measured rail, smoothed and the rail taken as canted as `shcontact profiles`
   !> suggests, for 0.05 s from a 3 mm offset (doc/vehicle.md, "Other profiles"): the files and
   !> options named in its output, the centred rolling radius within 5 mm of the nominal 460 mm
   !> (the MiniProf wheel's flange back at its origin: 479 mm when an option moved it to the
   !> default −70 mm), no failed contact call, finite forces, each wheel carrying about its
   !> 64.7 kN. Skipped without the external data.
   subroutine test_vehicle_measured(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: csv = scratch//'/vehicle_measured.csv'
      character(len=:), allocatable :: wheel, rail
      real(wp), allocatable :: rows(:, :)

      wheel = external_file('profiles/Car7216_0001r.whl', error, absolute=.true.)
      if (allocated(error)) return
      rail = external_file('profiles/avg_HR.BAN', error, absolute=.true.)
      if (allocated(error)) return
      call build_vehicle(error)
      if (allocated(error)) return
      call check(error, run(scratch//'/wheelset --duration 0.05 --every 1 --wheel '''//wheel// &
         ''' --rail '''//rail//''' --set profiles%wheel_smoothing=2.9 --set '// &
         'profiles%rail_smoothing=8.1 --set track%rail_canted=.true. --csv '//csv//' > '// &
         output('vehicle_measured')//' 2>&1'), &
         0, message='the vehicle example on the measured pair failed: see '// &
         output('vehicle_measured'))
      if (allocated(error)) return
      call check(error, run('grep -q "^wheel .*Car7216_0001r.whl$" '// &
         output('vehicle_measured')//' && grep -q "^rail .*avg_HR.BAN$" '// &
         output('vehicle_measured')//' && grep -q "^set track%rail_canted=.true.$" '// &
         output('vehicle_measured')), 0, &
         message='the output does not name the profile files and options: '// &
         output('vehicle_measured'))
      if (allocated(error)) return
      call check(error, abs(value_of(output('vehicle_measured'), 'centred_rolling_radius_mm') - &
         460.0_wp) < 5.0_wp, message='centred rolling radius far from 460 mm: the wheel moved')
      if (allocated(error)) return
      call check(error, value_of(output('vehicle_measured'), 'failed_calls'), 0.0_wp, &
         message='failed contact calls on the measured pair')
      if (allocated(error)) return
      call read_vehicle_csv(csv, rows, error)
   end subroutine test_vehicle_measured

   !> The CSV of a 0.05 s run of the vehicle example (201 steps): every value finite and each
   !> wheel's vertical force within 5 % of 64.7 kN. Columns: t, y, yaw, vy, yaw rate, fx fy fz
   !> np right, fx fy fz np left, fy total, mz.
   subroutine read_vehicle_csv(csv, rows, error)
      character(len=*), intent(in) :: csv
      real(wp), allocatable, intent(out) :: rows(:, :)
      type(error_type), allocatable, intent(out) :: error
      call read_csv(csv, 15, rows, error)
      if (allocated(error)) return
      call check(error, size(rows, 2), 201, message='CSV rows of '//csv)
      if (allocated(error)) return
      call check(error, all(ieee_is_finite(rows)), message='non-finite value in '//csv)
      if (allocated(error)) return
      call check(error, all(abs(abs(rows([8, 12], :)) - 64.7e3_wp) < 0.05_wp*64.7e3_wp), &
         message='vertical wheel force far from 64.7 kN in '//csv)
   end subroutine read_vehicle_csv

   !> A CSV file with a header line and n numeric columns, as rows(n, lines).
   subroutine read_csv(file, n, rows, error)
      character(len=*), intent(in) :: file
      integer, intent(in) :: n
      real(wp), allocatable, intent(out) :: rows(:, :)
      type(error_type), allocatable, intent(out) :: error
      real(wp) :: row(n)
      real(wp), allocatable :: grown(:, :)
      integer :: unit, stat, m
      character(len=1024) :: line

      allocate (rows(n, 256))
      m = 0
      open (newunit=unit, file=file, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, file//': cannot open')
         return
      end if
      read (unit, '(a)', iostat=stat) line
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         read (line, *, iostat=stat) row
         if (stat /= 0) then
            call test_failed(error, file//': bad line: '//trim(line))
            exit
         end if
         m = m + 1
         if (m > size(rows, 2)) then
            allocate (grown(n, 2*size(rows, 2)))
            grown(:, 1:m - 1) = rows(:, 1:m - 1)
            call move_alloc(grown, rows)
         end if
         rows(:, m) = row
      end do
      close (unit)
      rows = rows(:, 1:m)
   end subroutine read_csv

   ! --- helpers ---------------------------------------------------------------------------------

   !> Build (unless `build` is empty) and run one example, then compare its numbers with the
   !> solver object and check its three bad calls.
   subroutine example_test(tool, build, command, name, error)
      character(len=*), intent(in) :: tool, build, command, name
      type(error_type), allocatable, intent(out) :: error
      type(contact_result_type) :: expected
      real(wp) :: values(size(keys)), kinematic(kinematic_value_count)
      integer :: i

      call ensure_installed(error)
      if (allocated(error)) return
      if (run('command -v '//tool) /= 0) then
         call skip_test(error, tool//' not found')
         return
      end if
      if (len(build) > 0) then
         call check(error, run(build//' 2> '//output(name//'_build')), 0, &
            message='building the '//name//' example failed: see '//output(name//'_build'))
         if (allocated(error)) return
      end if
      call check(error, run(command//' > '//output(name)), 0, &
         message='the '//name//' example failed')
      if (allocated(error)) return

      call headline_result(expected, error)
      if (allocated(error)) return
      call read_values(output(name), values, error)
      if (allocated(error)) return
      call check(error, values(1), expected%main%fx, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, values(2), expected%main%fy, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, values(3), expected%main%mz, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, values(4), expected%main%fn, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, values(5), expected%main%fx_norm, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, values(6), expected%main%fy_norm, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, values(7), expected%main%gamma0, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, nint(values(8)), expected%n_patches)
      if (allocated(error)) return
      call check(error, values(9), expected%track%fz, rel=.true., thr=round_off)
      if (allocated(error)) return
      call check(error, value_of(output(name), 't_y'), headline_t_y, thr=1.0e-12_wp)
      if (allocated(error)) return
      call kinematic_case_result(expected, error)
      if (allocated(error)) return
      call kinematic_values(expected, kinematic)
      do i = 1, size(kin_index)
         call check(error, values(9 + i), kinematic(kin_index(i)), rel=.true., thr=round_off, &
            message=name//' example: '//trim(keys(9 + i)))
         if (allocated(error)) return
      end do
      call check_bad_call(output(name), [character(len=21) :: 'status_invalid_handle', &
         'status_negative_load', 'status_nan_creepage', 'status_kin_zero_speed'], &
         [1, 2, 2, 2], error)
   end subroutine example_test

   !> Each bad-call line: `name status message` with the expected status and a message.
   subroutine check_bad_call(file, names, stats, error)
      character(len=*), intent(in) :: file
      character(len=*), intent(in) :: names(:)
      integer, intent(in) :: stats(:)
      type(error_type), allocatable, intent(out) :: error
      character(len=512) :: line
      integer :: unit, stat, i, status, found
      character(len=32) :: name

      found = 0
      open (newunit=unit, file=file, status='old', action='read')
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         read (line, *, iostat=stat) name, status
         if (stat /= 0) cycle
         do i = 1, size(names)
            if (name /= names(i)) cycle
            found = found + 1
            ! After the name and the status comes the message.
            call check(error, status == stats(i) .and. len_trim(line) > len_trim(name) + 4, &
               message=file//': '//trim(line))
            if (allocated(error)) exit
         end do
         if (allocated(error)) exit
      end do
      close (unit)
      if (allocated(error)) return
      call check(error, found, size(names), message=file//': bad-call lines missing')
   end subroutine check_bad_call

   !> The numbers of `keys` in an example's output.
   subroutine read_values(file, values, error)
      character(len=*), intent(in) :: file
      real(wp), intent(out) :: values(:)
      type(error_type), allocatable, intent(out) :: error
      integer :: i
      do i = 1, size(keys)
         values(i) = value_of(file, trim(keys(i)))
      end do
      if (any(values >= huge(1.0_wp))) call test_failed(error, file//': a value is missing')
   end subroutine read_values

   !> The number after `key` on its line of an output file; huge() when absent.
   function value_of(file, key) result(value)
      character(len=*), intent(in) :: file, key
      real(wp) :: value
      character(len=512) :: line
      character(len=32) :: name
      integer :: unit, stat
      real(wp) :: x

      value = huge(1.0_wp)
      open (newunit=unit, file=file, status='old', action='read', iostat=stat)
      if (stat /= 0) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         read (line, *, iostat=stat) name, x
         if (stat == 0 .and. name == key) then
            value = x
            exit
         end if
      end do
      close (unit)
   end function value_of

   !> Install this build's library into the scratch prefix, once per run.
   subroutine ensure_installed(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: find_archive = 'a=${SHCONTACT_ARCHIVE:-$(ls -t '// &
         'build/*/shcontact/libshcontact.a 2>/dev/null | head -1)}; [ -n "$a" ] && '// &
         'm=${SHCONTACT_MODULES:-$(dirname $(ls -t build/*/shcontact*.mod | head -1))}; '

      if (install_state == 0) then
         install_state = 3
         if (run('command -v gfortran && command -v pkg-config') == 0) then
            install_state = 2
            if (run('rm -rf '//scratch//' && mkdir -p '//scratch//' && '//find_archive// &
               'scripts/install --archive "$a" --modules "$m" --prefix '//prefix//' 2> '// &
               scratch//'/install.log') == 0) install_state = 1
         end if
      end if
      select case (install_state)
      case (2)
         call test_failed(error, 'scripts/install --archive failed: see '//scratch// &
            '/install.log')
      case (3)
         call skip_test(error, 'gfortran or pkg-config not found (or no shell)')
      end select
   end subroutine ensure_installed

   !> Run a shell command quietly; its exit status (−1 when there is no shell).
   integer function run(command) result(stat)
      character(len=*), intent(in) :: command
      integer :: cmdstat
      stat = -1
      call execute_command_line('( '//command//' ) > /dev/null 2>&1 < /dev/null', &
         exitstat=stat, cmdstat=cmdstat)
      if (cmdstat /= 0) stat = -1
   end function run

   !> Where an example's output goes.
   function output(name) result(file)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: file
      file = scratch//'/'//name//'.out'
   end function output

   !> True when the file exists.
   logical function exists(file)
      character(len=*), intent(in) :: file
      inquire (file=file, exist=exists)
   end function exists

end module test_examples
