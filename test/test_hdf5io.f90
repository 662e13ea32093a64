!> Tests of the HDF5 layer: datasets and attributes read back exactly, units on every dataset,
!> files appear under their final name only when complete, failures leave nothing behind, and
!> result files of one run merge into the file of an unsplit run; a merged file describes its
!> datasets (long_name), ties the tables to their coordinates (dimension scales), records its
!> provenance and gets an XDMF sidecar that matches it (and that ParaView opens, when pvbatch is
!> installed).
module test_hdf5io
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_error, only: lib_error => error_type, stat_io, stat_invalid_input
   use shcontact_output_hdf5, only: h5_file_type, h5_create, h5_commit, h5_discard, h5_open, &
      h5_close, h5_write, h5_write_attribute, h5_read, h5_read_attribute, h5_copy, h5_exists
   use shcontact_core_files, only: file_exists, delete_file, process_id
   use shcontact_core_text, only: string_type
   use shcontact_input_config, only: case_config_type, load_config, config_namelist
   use shcontact_output_results, only: run_info_type, write_result_file
   use shcontact_output_merge, only: merge_result_files, read_result_summary
   use shcontact_output_xdmf, only: xdmf_name
   use shcontact_case_result, only: case_result_type, case_summary_type
   use shcontact_tangential_patch, only: state_adhesion, state_slip
   implicit none
   private
   public :: collect_hdf5io

contains

   subroutine collect_hdf5io(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('round_trip', test_round_trip), &
         new_unittest('compressed_fields', test_compressed), &
         new_unittest('temporary_name_until_commit', test_temporary_name), &
         new_unittest('unwritable_output', test_unwritable), &
         new_unittest('copy_between_files', test_copy), &
         new_unittest('result_files_merge', test_merge), &
         new_unittest('descriptions_scales_provenance', test_described), &
         new_unittest('xdmf_sidecar_matches_file', test_xdmf), &
         new_unittest('merge_rejects_mismatch', test_merge_errors) &
         ]
   end subroutine collect_hdf5io

   function scratch(tag) result(name)
      character(len=*), intent(in) :: tag
      character(len=:), allocatable :: name
      character(len=16) :: pid
      write (pid, '(i0)') process_id()
      name = '/tmp/shcontact_test_hdf5io_'//trim(pid)//'_'//tag//'.h5'
   end function scratch

   !> Report a library error as a test failure.
   subroutine fail_on(error, lerr, what)
      type(error_type), allocatable, intent(inout) :: error
      type(lib_error), allocatable, intent(in) :: lerr
      character(len=*), intent(in) :: what
      if (allocated(lerr)) call test_failed(error, what//': '//lerr%message)
   end subroutine fail_on

   subroutine test_round_trip(error)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: f
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: name, text, units
      real(wp) :: a(3, 2), x
      real(wp), allocatable :: b(:, :), c(:)
      integer, allocatable :: k(:)
      integer :: n
      character(len=:), allocatable :: texts(:)

      name = scratch('round_trip')
      a = reshape([1.0_wp, -2.5e-300_wp, 3.0_wp/7.0_wp, 4.0_wp, huge(1.0_wp), 0.1_wp], [3, 2])
      call h5_create(f, name, lerr)
      call fail_on(error, lerr, 'create')
      if (allocated(error)) return
      call h5_write(f, 'g/sub/a', a, 'MPa', lerr)
      if (.not. allocated(lerr)) call h5_write(f, 'g/k', [3, -1, 7], '1', lerr)
      if (.not. allocated(lerr)) call h5_write(f, 'g/x', 2.5_wp, 'mm', lerr)
      if (.not. allocated(lerr)) call h5_write(f, 'g/text', 'line 1'//new_line('a')//'line 2', &
         lerr)
      if (.not. allocated(lerr)) call h5_write(f, 'g/texts', [character(len=8) :: 'ab', &
         'cdefgh', ''], lerr)
      if (.not. allocated(lerr)) call h5_write(f, 'g/state', reshape([0_i1, 1_i1, 2_i1, 1_i1], &
         [2, 2]), '1', lerr)
      if (.not. allocated(lerr)) call h5_write_attribute(f, '/', 'version', '0.1.0', lerr)
      if (.not. allocated(lerr)) call h5_write_attribute(f, 'g', 'n', 42, lerr)
      if (.not. allocated(lerr)) call h5_write_attribute(f, 'g/x', 'scale', 0.5_wp, lerr)
      if (allocated(lerr)) then
         call h5_discard(f)
         call fail_on(error, lerr, 'write')
         return
      end if
      call h5_commit(f, lerr)
      call fail_on(error, lerr, 'commit')
      if (allocated(error)) return

      call h5_open(f, name, lerr)
      call fail_on(error, lerr, 'open')
      if (allocated(error)) return
      call h5_read(f, 'g/sub/a', b, lerr)
      if (.not. allocated(lerr)) then
         call check(error, all(shape(b) == [3, 2]) .and. all(b == a), &
            message='2-D real read back exactly')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read(f, 'g/k', k, lerr)
         if (.not. allocated(lerr)) call check(error, all(k == [3, -1, 7]), message='integers')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read(f, 'g/text', text, lerr)
         if (.not. allocated(lerr)) call check(error, text == 'line 1'//new_line('a')// &
            'line 2', message='text')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read(f, 'g/texts', texts, lerr)
         if (.not. allocated(lerr)) call check(error, size(texts) == 3 .and. &
            texts(2) == 'cdefgh' .and. texts(3) == '', message='text list')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read_attribute(f, 'g/sub/a', 'units', units, lerr)
         if (.not. allocated(lerr)) call check(error, units == 'MPa', message='units attribute')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read_attribute(f, 'g', 'n', n, lerr)
         if (.not. allocated(lerr)) call check(error, n, 42, message='integer attribute')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read_attribute(f, 'g/x', 'scale', x, lerr)
         if (.not. allocated(lerr)) call check(error, x, 0.5_wp, message='real attribute')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call check(error, h5_exists(f, 'g/state') .and. .not. h5_exists(f, 'g/nothing/here'), &
            message='h5_exists')
      end if
      if (.not. allocated(error) .and. .not. allocated(lerr)) then
         call h5_read(f, 'g/sub/a', c, lerr)
         call check(error, allocated(lerr), message='rank mismatch is an error')
         if (allocated(lerr)) deallocate (lerr)
      end if
      call h5_close(f)
      call fail_on(error, lerr, 'read')
      if (delete_file(name)) continue
   end subroutine test_round_trip

   subroutine test_compressed(error)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: f
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: name
      real(wp) :: field(50, 100)
      real(wp), allocatable :: back(:, :)
      integer :: i, j, size_plain, size_packed
      name = scratch('compressed')
      do j = 1, 100
         do i = 1, 50
            field(i, j) = real(mod(i*j, 7), wp)
         end do
      end do
      call h5_create(f, name, lerr, compression=6)
      if (.not. allocated(lerr)) call h5_write(f, 'p', field, 'MPa', lerr, compress=.true.)
      if (.not. allocated(lerr)) call h5_commit(f, lerr)
      call fail_on(error, lerr, 'write compressed')
      if (allocated(error)) return
      inquire (file=name, size=size_packed)
      call h5_open(f, name, lerr)
      if (.not. allocated(lerr)) call h5_read(f, 'p', back, lerr)
      call h5_close(f)
      call fail_on(error, lerr, 'read compressed')
      if (allocated(error)) return
      call check(error, all(back == field), message='compressed field reads back exactly')
      if (allocated(error)) return
      call h5_create(f, name, lerr)
      if (.not. allocated(lerr)) call h5_write(f, 'p', field, 'MPa', lerr, compress=.true.)
      if (.not. allocated(lerr)) call h5_commit(f, lerr)
      call fail_on(error, lerr, 'write plain')
      if (allocated(error)) return
      inquire (file=name, size=size_plain)
      call check(error, size_packed < size_plain/2, message='deflate shrinks a repetitive field')
      if (delete_file(name)) continue
   end subroutine test_compressed

   subroutine test_temporary_name(error)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: f
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: name
      name = scratch('temporary')
      call h5_create(f, name, lerr)
      call fail_on(error, lerr, 'create')
      if (allocated(error)) return
      call h5_write(f, 'x', [1.0_wp, 2.0_wp], 'mm', lerr)
      call check(error, .not. file_exists(name), message='no file under the final name yet')
      if (allocated(error)) then
         call h5_discard(f)
         return
      end if
      call check(error, file_exists(f%temp_name), message='data go to the temporary name')
      call h5_discard(f)
      if (allocated(error)) return
      call check(error, .not. file_exists(name) .and. .not. file_exists(f%temp_name), &
         message='a discarded file leaves nothing')
   end subroutine test_temporary_name

   subroutine test_unwritable(error)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: f
      type(lib_error), allocatable :: lerr
      call h5_create(f, '/nonexistent_dir_shcontact/out.h5', lerr)
      call check(error, allocated(lerr), message='creating in a missing directory fails')
      if (allocated(error)) return
      call check(error, lerr%stat, stat_io)
      if (allocated(error)) return
      call check(error, index(lerr%message, '/nonexistent_dir_shcontact/out.h5') > 0, &
         message=lerr%message)
   end subroutine test_unwritable

   subroutine test_copy(error)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: a, b
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: na, nb, units
      real(wp), allocatable :: v(:)
      na = scratch('copy_a')
      nb = scratch('copy_b')
      call h5_create(a, na, lerr)
      if (.not. allocated(lerr)) call h5_write(a, 'cases/000001/p/v', [1.0_wp, 2.0_wp], 'N', &
         lerr)
      if (.not. allocated(lerr)) call h5_commit(a, lerr)
      call fail_on(error, lerr, 'source')
      if (allocated(error)) return
      call h5_open(a, na, lerr)
      if (.not. allocated(lerr)) call h5_create(b, nb, lerr)
      if (.not. allocated(lerr)) call h5_copy(a, 'cases/000001', b, 'cases/000001', lerr)
      call h5_close(a)
      if (.not. allocated(lerr)) then
         call h5_commit(b, lerr)
      else
         call h5_discard(b)
      end if
      call fail_on(error, lerr, 'copy')
      if (allocated(error)) return
      call h5_open(b, nb, lerr)
      if (.not. allocated(lerr)) call h5_read(b, 'cases/000001/p/v', v, lerr)
      if (.not. allocated(lerr)) call h5_read_attribute(b, 'cases/000001/p/v', 'units', units, &
         lerr)
      call h5_close(b)
      call fail_on(error, lerr, 'read copy')
      if (allocated(error)) return
      call check(error, all(v == [1.0_wp, 2.0_wp]) .and. units == 'N', message='copied group')
      if (delete_file(na)) continue
      if (delete_file(nb)) continue
   end subroutine test_copy

   !> Synthetic results of a 6-case sweep: summaries set to known numbers (the I/O is tested,
   !> not the physics), case 4 failed.
   subroutine synthetic_run(config, info, results)
      type(case_config_type), intent(out) :: config
      type(run_info_type), intent(out) :: info
      type(case_result_type), intent(out) :: results(6)
      type(lib_error), allocatable :: lerr
      integer :: i
      call load_config('', [character(len=40) :: 'sweep%nu_x=0,1e-3,2e-3', &
         'sweep%bound=weighted,clipped', 'output%fields=traction,state'], config, lerr)
      info%namelist = config_namelist(config)
      info%command_line = 'test'
      info%date = '2026-01-01T00:00:00Z'
      info%n_cases = 6
      do i = 1, 6
         results(i)%summary%stat = 0
         results(i)%summary%n_patches = 1
         results(i)%summary%n_loaded = 1
         results(i)%summary%main_patch = 1
         results(i)%summary%fx = -100.0_wp*i
         results(i)%summary%fy_norm = 0.01_wp*i
         allocate (results(i)%tangential(1))
         results(i)%tangential(1)%nx = 2
         results(i)%tangential(1)%ny = 1
         results(i)%tangential(1)%fx = -100.0_wp*i
         results(i)%tangential(1)%x = reshape([0.5_wp, -0.5_wp], [2, 1])
         results(i)%tangential(1)%y = [0.0_wp]
         results(i)%tangential(1)%dx = [1.0_wp]
         results(i)%tangential(1)%px = reshape([1.0_wp*i, 2.0_wp], [2, 1])
         results(i)%tangential(1)%py = reshape([0.0_wp, -1.0_wp], [2, 1])
         results(i)%tangential(1)%state = reshape([state_adhesion, state_slip], [2, 1])
      end do
      results(4)%summary%stat = 6
      results(4)%summary%n_patches = 0
      results(4)%summary%n_loaded = 0
      results(4)%message = 'the profiles do not touch'
   end subroutine synthetic_run

   subroutine test_merge(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(run_info_type) :: info
      type(case_result_type) :: results(6)
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: whole, part1, part2, merged, text
      character(len=:), allocatable :: messages(:)
      integer, allocatable :: indices(:), failed(:)
      type(case_summary_type), allocatable :: summaries(:)
      integer :: n_cases, stat
      real(wp), allocatable :: px(:, :)
      type(h5_file_type) :: f

      call synthetic_run(config, info, results)
      whole = scratch('whole')
      part1 = scratch('part1')
      part2 = scratch('part2')
      merged = scratch('merged')
      call write_result_file(whole, info, config, [1, 2, 3, 4, 5, 6], results, lerr)
      if (.not. allocated(lerr)) call write_result_file(part2, info, config, [4, 5, 6], &
         results(4:6), lerr)
      if (.not. allocated(lerr)) call write_result_file(part1, info, config, [1, 2, 3], &
         results(1:3), lerr)
      call fail_on(error, lerr, 'write')
      if (allocated(error)) return
      call read_result_summary(part2, text, n_cases, indices, summaries, failed, messages, lerr)
      call fail_on(error, lerr, 'read summary')
      if (allocated(error)) return
      call check(error, n_cases == 6 .and. all(indices == [4, 5, 6]) .and. &
         all(failed == [4]) .and. summaries(2)%fx == -500.0_wp, message='summary of a part')
      if (allocated(error)) return
      call check(error, messages(1) == 'the profiles do not touch', message='failure message')
      if (allocated(error)) return
      ! Parts given in any order.
      call merge_result_files(merged, [string_type(part2), string_type(part1)], 'test', &
         info%date, lerr)
      call fail_on(error, lerr, 'merge')
      if (allocated(error)) return
      call h5_open(f, merged, lerr)
      if (.not. allocated(lerr)) call h5_read(f, 'cases/000005/patch_1/tangential/px', px, lerr)
      call h5_close(f)
      call fail_on(error, lerr, 'read merged field')
      if (allocated(error)) return
      call check(error, px(1, 1), 5.0_wp, message='per-case field copied')
      if (allocated(error)) return
      call execute_command_line('h5diff --version > /dev/null 2>&1', exitstat=stat)
      if (stat == 0) then
         call execute_command_line('h5diff -q '//whole//' '//merged, exitstat=stat)
         call check(error, stat, 0, message='merged file equals the whole file (h5diff)')
      end if
      if (delete_file(whole)) continue
      if (delete_file(part1)) continue
      if (delete_file(part2)) continue
      if (delete_file(merged)) continue
      if (delete_file(xdmf_name(merged))) continue
   end subroutine test_merge

   !> A merged result file (per-case groups copied between files): every dataset has a
   !> `long_name`, the summary columns and the element fields have their dimension scales
   !> (summary/case, the strip centres y), the root records the provenance.
   subroutine test_described(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: merged
      call merged_run('described', merged, error)
      if (allocated(error)) return
      call check_described(merged, error)
      if (delete_file(merged)) continue
      if (delete_file(xdmf_name(merged))) continue
   end subroutine test_described

   subroutine check_described(merged, error)
      character(len=*), intent(in) :: merged
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: tan = 'cases/000005/patch_1/tangential/'
      character(len=*), parameter :: described(5) = [character(len=40) :: 'summary/fx', &
         'summary/nu_x', tan//'px', tan//'state', 'input/namelist']
      character(len=*), parameter :: field_scales(3) = [character(len=9) :: 'y', 'element', &
         'component']
      character(len=*), parameter :: root(5) = [character(len=16) :: 'git_revision', &
         'compiler', 'compiler_options', 'host', 'version']
      type(h5_file_type) :: f
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: text
      integer :: i, threads

      call h5_open(f, merged, lerr)
      call fail_on(error, lerr, 'open')
      if (allocated(error)) return
      do i = 1, size(described)
         call h5_read_attribute(f, trim(described(i)), 'long_name', text, lerr)
         if (allocated(lerr)) exit
         call check(error, len(text) > 10, message=trim(described(i))//': empty long_name')
         if (allocated(error)) exit
      end do
      ! Every dimension of the element fields has its scale (strips, elements, xy's components).
      do i = 1, size(field_scales)
         if (allocated(lerr) .or. allocated(error)) exit
         call h5_read_attribute(f, tan//trim(field_scales(i)), 'CLASS', text, lerr)
         if (.not. allocated(lerr)) call check(error, text, 'DIMENSION_SCALE', &
            message=tan//trim(field_scales(i))//' is not a dimension scale')
      end do
      if (.not. allocated(lerr) .and. .not. allocated(error)) then
         call h5_read_attribute(f, 'summary/case', 'CLASS', text, lerr)
         if (.not. allocated(lerr)) call check(error, text, 'DIMENSION_SCALE', &
            message='summary/case is not a dimension scale')
      end if
      do i = 1, size(root)
         if (allocated(lerr) .or. allocated(error)) exit
         call h5_read_attribute(f, '/', trim(root(i)), text, lerr)
         if (.not. allocated(lerr)) call check(error, len(text) > 0, &
            message='root attribute '//trim(root(i))//' is empty')
      end do
      if (.not. allocated(lerr) .and. .not. allocated(error)) then
         call h5_read_attribute(f, '/', 'threads', threads, lerr)
         if (.not. allocated(lerr)) call check(error, threads >= 1, message='threads')
      end if
      call h5_close(f)
      call fail_on(error, lerr, 'attribute')
      if (allocated(error)) return
      ! The references of the dimension scales, checked by h5py when it is there.
      if (have_python_h5py()) call check(error, run_quiet('python3 scripts/check_xdmf.py '// &
         '--attributes '//xdmf_name(merged)), 0, message='scripts/check_xdmf.py --attributes '// &
         xdmf_name(merged)//' reports a problem')
   end subroutine check_described

   !> The XDMF sidecar of a merged file: written under its final name only (no temporary
   !> left), every DataItem refers to a dataset of the HDF5 file with the declared shape and
   !> type (scripts/check_xdmf.py, with h5py) and ParaView opens it (with pvbatch).
   subroutine test_xdmf(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: merged, xmf, text
      integer :: unit, stat, n_grid
      character(len=512) :: line

      call merged_run('xdmf', merged, error)
      if (allocated(error)) return
      xmf = xdmf_name(merged)
      call check(error, file_exists(xmf), message='no sidecar '//xmf)
      if (allocated(error)) return
      call check(error, run_quiet('ls '//xmf//'.tmp*'), 2, message='temporary sidecar left')
      if (allocated(error)) return
      ! Five cases with fields (case 4 failed), one patch each.
      n_grid = 0
      text = ''
      open (newunit=unit, file=xmf, status='old', action='read')
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, 'TopologyType="2DSMesh" Dimensions="1 2"') > 0) n_grid = n_grid + 1
         if (index(line, '/cases/000004/') > 0) text = trim(line)
      end do
      close (unit)
      call check(error, n_grid, 5, message='patch grids in '//xmf)
      if (allocated(error)) return
      call check(error, len(text), 0, message='failed case 4 in the sidecar: '//text)
      if (allocated(error)) return
      if (have_python_h5py()) then
         call check(error, run_quiet('python3 scripts/check_xdmf.py '//xmf), 0, &
            message='scripts/check_xdmf.py '//xmf//' reports a problem')
         if (allocated(error)) return
      end if
      if (run_quiet('command -v pvbatch') == 0) then
         call check(error, run_quiet('pvbatch scripts/check_xdmf.py --paraview '//xmf), 0, &
            message='ParaView (pvbatch) cannot open '//xmf)
         if (allocated(error)) return
      end if
      if (delete_file(merged)) continue
      if (delete_file(xmf)) continue
   end subroutine test_xdmf

   !> The synthetic run written in two parts and merged into `merged` (as the app does).
   subroutine merged_run(tag, merged, error)
      character(len=*), intent(in) :: tag
      character(len=:), allocatable, intent(out) :: merged
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      type(run_info_type) :: info
      type(case_result_type) :: results(6)
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: part1, part2
      call synthetic_run(config, info, results)
      part1 = scratch(tag//'_part1')
      part2 = scratch(tag//'_part2')
      merged = scratch(tag//'_merged')
      call write_result_file(part1, info, config, [1, 2, 3], results(1:3), lerr)
      if (.not. allocated(lerr)) call write_result_file(part2, info, config, [4, 5, 6], &
         results(4:6), lerr)
      if (.not. allocated(lerr)) call merge_result_files(merged, [string_type(part1), &
         string_type(part2)], 'test', info%date, lerr, threads=3)
      if (delete_file(part1)) continue
      if (delete_file(part2)) continue
      call fail_on(error, lerr, 'write and merge')
   end subroutine merged_run

   !> True when python3 can import h5py (else the Python checks are left out).
   logical function have_python_h5py()
      have_python_h5py = run_quiet('python3 -c "import h5py, numpy"') == 0
   end function have_python_h5py

   !> Exit status of a shell command, its output discarded.
   integer function run_quiet(command) result(stat)
      character(len=*), intent(in) :: command
      integer :: cmdstat
      call execute_command_line(command//' > /dev/null 2>&1', exitstat=stat, cmdstat=cmdstat)
      if (cmdstat /= 0) stat = -1
   end function run_quiet

   subroutine test_merge_errors(error)
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config, other
      type(run_info_type) :: info, info2
      type(case_result_type) :: results(6)
      type(lib_error), allocatable :: lerr
      character(len=:), allocatable :: part1, part2, merged
      call synthetic_run(config, info, results)
      part1 = scratch('bad_part1')
      part2 = scratch('bad_part2')
      merged = scratch('bad_merged')
      call write_result_file(part1, info, config, [1, 2, 3], results(1:3), lerr)
      call fail_on(error, lerr, 'write')
      if (allocated(error)) return
      call merge_result_files(merged, [string_type(part1)], 'test', info%date, lerr)
      call check(error, allocated(lerr), message='missing cases')
      if (allocated(error)) return
      call check(error, index(lerr%message, '3 of 6 cases are missing') > 0 .and. &
         .not. file_exists(merged), message=lerr%message)
      if (allocated(error)) return
      call merge_result_files(merged, [string_type(part1), string_type(part1)], 'test', &
         info%date, lerr)
      call check(error, allocated(lerr), message='the same file twice')
      if (allocated(error)) return
      call check(error, index(lerr%message, '"'//part1//'" is given twice') > 0, &
         message=lerr%message)
      if (allocated(error)) return
      ! Two files holding one case.
      part2 = scratch('bad_part1b')
      call write_result_file(part2, info, config, [3], results(3:3), lerr)
      call fail_on(error, lerr, 'write')
      if (allocated(error)) return
      call merge_result_files(merged, [string_type(part1), string_type(part2)], 'test', &
         info%date, lerr)
      call check(error, allocated(lerr), message='duplicate cases')
      if (allocated(error)) return
      call check(error, index(lerr%message, 'case 3 is in both') > 0, message=lerr%message)
      if (allocated(error)) return
      info2 = info
      call load_config('', [character(len=40) :: 'sweep%nu_x=0,1e-3,3e-3', &
         'sweep%bound=weighted,clipped', 'output%fields=traction,state'], other, lerr)
      info2%namelist = config_namelist(other)
      call write_result_file(part2, info2, other, [4, 5, 6], results(4:6), lerr)
      call merge_result_files(merged, [string_type(part1), string_type(part2)], 'test', &
         info%date, lerr)
      call check(error, allocated(lerr), message='another configuration')
      if (allocated(error)) return
      call check(error, lerr%stat == stat_invalid_input .and. &
         index(lerr%message, 'another run') > 0 .and. .not. file_exists(merged), &
         message=lerr%message)
      if (delete_file(part1)) continue
      if (delete_file(part2)) continue
   end subroutine test_merge_errors

end module test_hdf5io
