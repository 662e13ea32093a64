!> The files `shcontact run` and `shcontact merge` write (doc/app.md, "Files shcontact writes"),
!> one test per rule, run as a user runs the program (issue 24, items 6, 11, 13, 14):
!>
!> * a damaged shard or checkpoint block (a /summary column cut short, or of the wrong type) is
!>   refused with one message naming the file and the dataset, status 2, no output;
!> * the XDMF sidecar OUT.xmf follows the rule of OUT.h5: a file shcontact did not write is
!>   neither overwritten nor deleted (unless --force), a directory is refused before anything
!>   is written;
!> * the work folder OUT.h5.partial is never followed through a symbolic link and never
!>   emptied unless this run made it (or --resume / --force takes it over);
!> * two runs with the same output: the second gets "another run is writing", the first is
!>   unaffected;
!> * output names with control characters, and outputs that are pipes, devices or symbolic
!>   links, are refused.
!>
!> The damaged files are made with the library's own HDF5 writer (shcontact_output_hdf5).
module test_output_files
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed
   use test_app, only: scratch_directory, shell, run_program, file_text, write_lines, &
      unavailable, expect_in, program_path
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: lib_error => error_type
   use shcontact_core_files, only: file_exists, process_id
   use shcontact_output_xdmf, only: write_xdmf_sidecar
   use shcontact_core_text, only: string_type
   use shcontact_output_hdf5, only: h5_file_type, h5_open, h5_create, h5_commit, h5_close, h5_copy, &
      h5_make_group, h5_exists, h5_read, h5_write, h5_read_attribute, h5_write_attribute
   use shcontact_output_results, only: case_group_name
   use shcontact_output_merge, only: read_result_summary
   use shcontact_case_result, only: case_summary_type, summary_columns, n_summary_columns
   implicit none
   private
   public :: collect_output_files

   !> A 6-case sweep in checkpoint blocks of 2 cases, fields (and so a sidecar) for every case.
   character(len=*), parameter :: small_sweep(*) = [character(len=72) :: &
      '&sweep nu_x = 0.0, 1.0e-3, 2.0e-3, phi = 0.0, 1.0e-3 /', &
      "&output fields = 'all', checkpoint_cases = 2 /", &
      '&normal n_strips = 40 /', &
      '&tangential n_elements = 20 /']

contains

   subroutine collect_output_files(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('damaged_checkpoint_block', test_damaged_block), &
         new_unittest('damaged_shard', test_damaged_shard), &
         new_unittest('foreign_sidecar', test_foreign_sidecar), &
         new_unittest('sidecar_directory', test_sidecar_directory), &
         new_unittest('output_named_like_its_sidecar', test_output_xmf), &
         new_unittest('sidecar_of_a_name_xml_escapes', test_sidecar_xml_name), &
         new_unittest('sidecar_of_another_output', test_sidecar_of_another_output), &
         new_unittest('merge_shards_of_other_output_names', test_merge_output_names), &
         new_unittest('control_characters', test_control_characters), &
         new_unittest('work_folder_symlink', test_work_folder_symlink), &
         new_unittest('existing_work_folder', test_existing_work_folder), &
         new_unittest('profile_file_changed_resume_merge', test_profile_changed), &
         new_unittest('threads_attribute_is_the_runs', test_threads_attribute), &
         new_unittest('two_runs_one_output', test_two_runs), &
         new_unittest('special_outputs', test_special_outputs), &
         new_unittest('own_files_replaced', test_own_files_replaced), &
         new_unittest('temporary_names_exclusive', test_temporary_names) &
         ]
   end subroutine collect_output_files

   ! ------------------------------------------------------------------------------------------
   ! Helpers
   ! ------------------------------------------------------------------------------------------

   !> Copy the result file `name` with the library's writer, /summary/`column` replaced: cut to
   !> its first value (`how` = 'cut') or by texts of the same length ('text'). The copy keeps
   !> what the summary reader needs (root software and n_cases, /input, /summary, /failures,
   !> /cases) and replaces `name`.
   subroutine damage(name, column, how, error)
      character(len=*), intent(in) :: name, column, how
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: counts(5) = [character(len=10) :: 'case', 'status', &
         'n_patches', 'n_loaded', 'main_patch']
      type(h5_file_type) :: src, out
      type(lib_error), allocatable :: e
      character(len=:), allocatable :: software, path
      real(wp), allocatable :: values(:)
      integer :: n_cases, k, stat
      call h5_open(src, name, e)
      if (.not. allocated(e)) call h5_read_attribute(src, '/', 'software', software, e)
      if (.not. allocated(e)) call h5_read_attribute(src, '/', 'n_cases', n_cases, e)
      if (.not. allocated(e)) call h5_read(src, 'summary/'//column, values, e)
      if (.not. allocated(e)) call h5_create(out, name//'.new', e)
      if (.not. allocated(e)) call h5_write_attribute(out, '/', 'software', software, e)
      if (.not. allocated(e)) call h5_write_attribute(out, '/', 'n_cases', n_cases, e)
      if (.not. allocated(e)) call h5_copy(src, 'input', out, 'input', e)
      do k = 1, size(counts) + n_summary_columns
         if (allocated(e)) exit
         if (k <= size(counts)) then
            path = 'summary/'//trim(counts(k))
         else
            path = 'summary/'//trim(summary_columns(1, k - size(counts)))
         end if
         if (path == 'summary/'//column .or. .not. h5_exists(src, path)) cycle
         call h5_copy(src, path, out, path, e)
      end do
      if (.not. allocated(e) .and. h5_exists(src, 'failures')) call h5_copy(src, 'failures', &
         out, 'failures', e)
      if (.not. allocated(e) .and. h5_exists(src, 'cases')) call h5_copy(src, 'cases', out, &
         'cases', e)
      if (.not. allocated(e)) then
         if (how == 'cut') then
            call h5_write(out, 'summary/'//column, values(1:1), 'N', e)
         else
            call h5_write(out, 'summary/'//column, [character(len=4) :: &
               ('text', k=1, size(values))], e)
         end if
      end if
      call h5_close(src)
      if (.not. allocated(e)) call h5_commit(out, e)
      if (allocated(e)) then
         call test_failed(error, 'cannot make the damaged file: '//e%message)
         return
      end if
      call shell('mv -f '//name//'.new '//name, stat)
      call check(error, stat, 0, message='replace '//name)
   end subroutine damage

   !> Copy the result file `name` with the library's writer, the field pn of the first case's
   !> patch_1 cut to its first strip (the other fields of that patch left out), and replace
   !> `name` by the copy.
   subroutine damage_field(name, error)
      character(len=*), intent(in) :: name
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: src, out
      type(lib_error), allocatable :: e
      character(len=:), allocatable :: software, group, tangential
      real(wp), allocatable :: pn(:, :)
      integer, allocatable :: cases(:)
      integer :: n_cases, k, stat
      call h5_open(src, name, e)
      if (.not. allocated(e)) call h5_read_attribute(src, '/', 'software', software, e)
      if (.not. allocated(e)) call h5_read_attribute(src, '/', 'n_cases', n_cases, e)
      if (.not. allocated(e)) call h5_read(src, 'summary/case', cases, e)
      if (.not. allocated(e)) call h5_create(out, name//'.new', e)
      if (.not. allocated(e)) call h5_write_attribute(out, '/', 'software', software, e)
      if (.not. allocated(e)) call h5_write_attribute(out, '/', 'n_cases', n_cases, e)
      if (.not. allocated(e)) call h5_copy(src, 'input', out, 'input', e)
      if (.not. allocated(e)) call h5_copy(src, 'summary', out, 'summary', e)
      if (.not. allocated(e) .and. h5_exists(src, 'geometry')) call h5_copy(src, 'geometry', &
         out, 'geometry', e)
      do k = 1, size(cases)
         if (allocated(e)) exit
         group = case_group_name(cases(k), n_cases)
         if (k > 1) then
            call h5_copy(src, group, out, group, e)
            cycle
         end if
         tangential = group//'/patch_1/tangential'
         call h5_make_group(out, tangential, e)
         if (.not. allocated(e) .and. h5_exists(src, group//'/patch_1/normal')) call h5_copy( &
            src, group//'/patch_1/normal', out, group//'/patch_1/normal', e)
         if (.not. allocated(e)) call h5_copy(src, tangential//'/xy', out, tangential//'/xy', e)
         if (.not. allocated(e)) call h5_copy(src, tangential//'/y', out, tangential//'/y', e)
         if (.not. allocated(e) .and. h5_exists(src, tangential//'/dx')) call h5_copy(src, &
            tangential//'/dx', out, tangential//'/dx', e)
         if (.not. allocated(e)) call h5_read(src, tangential//'/pn', pn, e)
         if (.not. allocated(e)) call h5_write(out, tangential//'/pn', pn(:, 1:1), 'MPa', e)
      end do
      call h5_close(src)
      if (.not. allocated(e)) call h5_commit(out, e)
      if (allocated(e)) then
         call test_failed(error, 'cannot make the damaged file: '//e%message)
         return
      end if
      call shell('mv -f '//name//'.new '//name, stat)
      call check(error, stat, 0, message='replace '//name)
   end subroutine damage_field

   !> No crash text (runtime error, backtrace, signal) on stderr.
   subroutine expect_clean(error, dir, what)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), intent(in) :: dir, what
      character(len=:), allocatable :: err
      err = file_text(dir//'/err.txt')
      if (index(err, 'Fortran runtime') > 0 .or. index(err, 'Backtrace') > 0 .or. &
          index(err, 'backtrace') > 0 .or. index(err, 'SIG') > 0 .or. &
          index(err, 'Error termination') > 0) call test_failed(error, what//': crash text '// &
         'on stderr: '//err)
   end subroutine expect_clean

   !> Run (stdout and stderr to dir/out.txt, err.txt) with a time limit: a program that hangs
   !> (on a pipe) fails the test instead of stopping the suite.
   integer function run_limited(dir, args) result(stat)
      character(len=*), intent(in) :: dir, args
      stat = run_program(dir, args, 'timeout 60')
   end function run_limited

   !> True when the shell test `condition` (run in `dir`) holds.
   logical function holds(dir, condition)
      character(len=*), intent(in) :: dir, condition
      integer :: stat
      call shell('cd '//dir//' && '//condition, stat)
      holds = stat == 0
   end function holds

   ! ------------------------------------------------------------------------------------------
   ! Damaged shards and checkpoint blocks (item 6)
   ! ------------------------------------------------------------------------------------------

   !> A checkpoint block whose /summary/fx was cut to one value: --resume read past its end
   !> (valgrind: invalid read in set_summary_value) and wrote garbage with status 0.
   subroutine test_damaged_block(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_block')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o out.h5', 'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=2')
      call check(error, file_exists(dir//'/out.h5.partial/block_000001.h5'), &
         message='the interrupted run keeps its blocks: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call damage(dir//'/out.h5.partial/block_000001.h5', 'fx', 'cut', error)
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o out.h5 --resume')
      call check(error, stat, 2, message='resume from a damaged block: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '"out.h5.partial/block_000001.h5": '// &
         '/summary/fx has 1 values; expected 1-D numbers, 2 of them', 'damaged block')
      if (allocated(error)) return
      call expect_clean(error, dir, 'damaged block')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5') .and. .not. file_exists(dir// &
         '/out.xmf'), message='no output from a damaged checkpoint')
      if (allocated(error)) return
      call check(error, file_exists(dir//'/out.h5.partial/block_000002.h5'), &
         message='the checkpoint is kept')
      call shell('rm -rf '//dir)
   end subroutine test_damaged_block

   !> Shards with a /summary column cut to one value (merge died with SIGSEGV on a 50 000-row
   !> shard, read garbage on a small one) or holding texts: refused, no merged file. A field of
   !> the wrong shape (found when the sidecar is written) left the merged file: no longer.
   subroutine test_damaged_shard(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_shard')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o s.h5 --shard 1/2')
      if (stat == 0) stat = run_program(dir, 'run sw.nml -q -o s.h5 --shard 2/2')
      call check(error, stat, 0, message='shards: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call shell('cp '//dir//'/s-shard2of2.h5 '//dir//'/t-shard2of2.h5 && cp '//dir// &
         '/s-shard2of2.h5 '//dir//'/v-shard2of2.h5')
      call damage(dir//'/s-shard2of2.h5', 'mz', 'cut', error)
      if (allocated(error)) return
      stat = run_program(dir, 'merge m.h5 s-shard1of2.h5 s-shard2of2.h5')
      call check(error, stat, 2, message='merge of a cut shard: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '"s-shard2of2.h5": /summary/mz has 1 '// &
         'values; expected 1-D numbers, 3 of them', 'cut shard')
      if (allocated(error)) return
      call expect_clean(error, dir, 'cut shard')
      if (allocated(error)) return
      call check(error, .not. holds(dir, 'ls m.* > /dev/null 2>&1'), &
         message='no merged file (or sidecar) from a damaged shard')
      if (allocated(error)) return
      call damage(dir//'/t-shard2of2.h5', 'fy', 'text', error)
      if (allocated(error)) return
      stat = run_program(dir, 'merge m.h5 s-shard1of2.h5 t-shard2of2.h5')
      call check(error, stat, 2, message='merge of a shard with texts: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '"t-shard2of2.h5": /summary/fy holds '// &
         'text values', 'shard with texts')
      if (allocated(error)) return
      call check(error, .not. holds(dir, 'ls m.* > /dev/null 2>&1'), &
         message='no merged file from a shard with texts')
      if (allocated(error)) return
      ! A field of the wrong shape: found when the sidecar is written, after the merged file;
      ! that file (written by this command) goes too.
      call shell('cp '//dir//'/s-shard1of2.h5 '//dir//'/u-shard1of2.h5')
      call damage_field(dir//'/u-shard1of2.h5', error)
      if (allocated(error)) return
      stat = run_program(dir, 'merge m.h5 u-shard1of2.h5 v-shard2of2.h5')
      call check(error, stat, 3, message='merge of a shard with a damaged field: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'pn does not have the shape of its '// &
         'element grid', 'damaged field')
      if (allocated(error)) return
      call check(error, .not. holds(dir, 'ls m.* > /dev/null 2>&1'), &
         message='no merged file from a shard with a damaged field: '// &
         file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_damaged_shard

   ! ------------------------------------------------------------------------------------------
   ! The XDMF sidecar (items 11 and 14)
   ! ------------------------------------------------------------------------------------------

   !> `echo mine > r.xmf; shcontact run examples/pure_spin.nml -o r.h5` deleted r.xmf.
   subroutine test_foreign_sidecar(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_sidecar')
      call shell('echo mine > '//dir//'/r.xmf && echo mine > '//dir//'/f.xmf && cp '// &
         'examples/pure_spin.nml '//dir//'/pure_spin.nml')
      stat = run_program(dir, 'run pure_spin.nml -q -o r.h5')
      call check(error, stat, 3, message='foreign sidecar: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the XDMF sidecar "r.xmf" of the '// &
         'output "r.h5" exists and was not written by shcontact; it is not overwritten', &
         'foreign sidecar')
      if (allocated(error)) return
      call check(error, file_text(dir//'/r.xmf') == 'mine'//new_line('a') .and. &
         .not. holds(dir, 'ls -d r.h5* > /dev/null 2>&1'), &
         message='the foreign sidecar is untouched and nothing is written')
      if (allocated(error)) return
      ! A run without fields writes no sidecar: with --force it runs, r.xmf stays as it was.
      stat = run_program(dir, 'run pure_spin.nml -q -o r.h5 --force')
      call check(error, stat, 0, message='--force without fields: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_text(dir//'/r.xmf') == 'mine'//new_line('a') .and. &
         file_exists(dir//'/r.h5'), message='no sidecar to write: the foreign one is kept')
      if (allocated(error)) return
      ! With fields the sidecar is written: refused the same way, replaced with --force.
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o f.h5')
      call check(error, stat, 3, message='foreign sidecar (fields): '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_text(dir//'/f.xmf') == 'mine'//new_line('a'), &
         message='foreign sidecar (fields) untouched')
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o f.h5 --force')
      call check(error, stat, 0, message='--force: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/f.xmf'), '<Xdmf', '--force writes the sidecar')
      call shell('rm -rf '//dir)
   end subroutine test_foreign_sidecar

   !> `shcontact run -o res.xmf` wrote the results as res.xmf, then renamed the sidecar (whose
   !> name is the output's with .xmf) over them: status 0, the results lost. Refused now.
   subroutine test_output_xmf(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_outxmf')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o res.xmf')
      call check(error, stat, 2, message='output named .xmf: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the output name "res.xmf" ends in '// &
         '.xmf, the name its XDMF sidecar takes', 'output named .xmf')
      if (allocated(error)) return
      call check(error, .not. holds(dir, 'ls -d res.* > /dev/null 2>&1'), &
         message='nothing is written for an output named .xmf')
      if (allocated(error)) return
      ! The same from the case file's &output file.
      call shell('printf "&output file = '//"'r2.xmf'"//' /\n" > '//dir//'/o.nml')
      stat = run_program(dir, 'run o.nml -q')
      call check(error, stat, 2, message='&output file .xmf: '//file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_output_xmf

   !> An output name with `--`, `&`, `<` and `>` gives a sidecar that is well-formed XML (the
   !> name escaped in its DataItems; in its header comment, which holds no `--`, the `-` too),
   !> and a second run recognises the sidecar as its own output's.
   subroutine test_sidecar_xml_name(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: output = "'a--b&<c>-.h5'", sidecar = "'a--b&<c>-.xmf'"
      character(len=:), allocatable :: dir, text, long_name
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_xmlname')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o '//output)
      call check(error, stat, 0, message='first run: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      text = file_text(dir//'/a--b&<c>-.xmf')
      call expect_in(error, text, 'Element fields of a&#45;&#45;b&amp;&lt;c&gt;&#45;.h5 '// &
         '(shcontact)', 'the header comment')
      if (allocated(error)) return
      call expect_in(error, text, 'Format="HDF">a--b&amp;&lt;c&gt;-.h5:/cases/', 'a DataItem')
      if (allocated(error)) return
      call check(error, index(text, '&<') == 0 .and. index(text, '<!-- Element fields of a--') &
         == 0, message='unescaped name in the sidecar')
      if (allocated(error)) return
      if (holds(dir, 'command -v python3 > /dev/null')) then
         call check(error, holds(dir, 'python3 -c "import sys, xml.dom.minidom as m; '// &
            'm.parse(sys.argv[1])" '//sidecar), message='the sidecar is not well-formed XML')
         if (allocated(error)) return
      end if
      ! Its own output's sidecar: replaced by the same run again without --force; also for a
      ! long name whose escaped form is longer than the first 400 bytes of the file.
      stat = run_program(dir, 'run sw.nml -q -o '//output)
      call check(error, stat, 0, message='second run: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      long_name = 's--'//repeat('a-', 110)//'.h5'
      stat = run_program(dir, 'run sw.nml -q -o '//long_name)
      call check(error, stat, 0, message='long name: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o '//long_name)
      call check(error, stat, 0, message='long name again: '//file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_sidecar_xml_name

   !> `-o r.h5` then `-o r.hdf5`: both outputs have the sidecar r.xmf, and the second run
   !> replaced (or, without fields, deleted) the first one's. Refused unless --force.
   subroutine test_sidecar_of_another_output(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, first
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_othersc')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o r.h5')
      call check(error, stat, 0, message='first run: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      first = file_text(dir//'/r.xmf')
      call expect_in(error, first, 'Element fields of r.h5 (shcontact)', 'the first sidecar')
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o r.hdf5')
      call check(error, stat, 3, message='sidecar of r.h5: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the XDMF sidecar "r.xmf" of the '// &
         'output "r.hdf5" exists and describes another result file ("r.h5")', 'other sidecar')
      if (allocated(error)) return
      call check(error, file_text(dir//'/r.xmf') == first .and. &
         .not. file_exists(dir//'/r.hdf5'), message='r.h5''s sidecar kept, nothing written')
      if (allocated(error)) return
      ! Without fields the run would have deleted it: refused the same way.
      stat = run_program(dir, 'run -q -o r.hdf5')
      call check(error, stat, 3, message='summary only: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_text(dir//'/r.xmf') == first, message='sidecar kept (no fields)')
      if (allocated(error)) return
      ! Its own output's sidecar is replaced as before; --force replaces the other one.
      stat = run_program(dir, 'run sw.nml -q -o r.h5')
      call check(error, stat, 0, message='same output again: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o r.hdf5 --force')
      call check(error, stat, 0, message='--force: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/r.xmf'), 'Element fields of r.hdf5 (shcontact)', &
         '--force writes the new sidecar')
      call shell('rm -rf '//dir)
   end subroutine test_sidecar_of_another_output

   !> Shards of one run made with -o spelled differently (relative, absolute, another name)
   !> were refused by merge ("configurations differ": the output name is in the stored
   !> namelist). They merge now, into the file of the run in one piece; shards of another
   !> configuration are still refused, naming the line that differs.
   subroutine test_merge_output_names(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .true.)) return
      dir = scratch_directory('of_mergenames')
      call write_lines(dir//'/sw.nml', small_sweep(1:1))
      call shell('mkdir -p '//dir//'/sub')
      stat = run_program(dir, 'run sw.nml -q -o s.h5 --shard 1/3')
      if (stat == 0) stat = run_program(dir, 'run sw.nml -q -o '//dir//'/s.h5 --shard 2/3')
      if (stat == 0) stat = run_program(dir, 'run sw.nml -q -o t.h5 --shard 3/3')
      call check(error, stat, 0, message='shards: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'merge m.h5 s-shard1of3.h5 s-shard2of3.h5 t-shard3of3.h5 -q')
      call check(error, stat, 0, message='merge: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o whole.h5')
      call check(error, stat, 0, message='whole run: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, holds(dir, 'h5dump -d /summary/fx -o a.txt m.h5 > /dev/null && '// &
         'h5dump -d /summary/fx -o b.txt whole.h5 > /dev/null && cmp -s a.txt b.txt'), &
         message='the merged shards give the forces of the run in one piece')
      if (allocated(error)) return
      call shell('printf "&sweep nu_x = 0.0, 1.0e-3, 3.0e-3, phi = 0.0, 1.0e-3 /\n" > '// &
         dir//'/sw3.nml')
      stat = run_program(dir, 'run sw3.nml -q -o u.h5 --shard 3/3')
      stat = run_program(dir, 'merge m2.h5 s-shard1of3.h5 s-shard2of3.h5 u-shard3of3.h5 -q')
      call check(error, stat, 2, message='another configuration: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'configurations differ: "nu_x = '// &
         '0.0, 0.001, 0.003', 'the differing line named')
      call shell('rm -rf '//dir)
   end subroutine test_merge_output_names

   !> A directory named like the sidecar: the run failed after writing OUT.h5 and left it and
   !> OUT.h5.partial (status 3); now refused before anything is written.
   subroutine test_sidecar_directory(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_sidedir')
      call shell('mkdir -p '//dir//'/d.xmf')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o d.h5')
      call check(error, stat, 3, message='sidecar is a directory: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'cannot write the XDMF sidecar '// &
         '"d.xmf" of the output "d.h5": it is a directory', 'sidecar is a directory')
      if (allocated(error)) return
      call check(error, .not. holds(dir, 'ls -d d.h5* > /dev/null 2>&1'), &
         message='neither d.h5 nor d.h5.partial is left')
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o d.h5 --force')
      call check(error, stat, 3, message='--force does not replace a directory')
      call shell('rm -rf '//dir)
   end subroutine test_sidecar_directory

   ! ------------------------------------------------------------------------------------------
   ! Output names (item 14)
   ! ------------------------------------------------------------------------------------------

   !> `-o $'x\ny.h5'` wrote xy.h5 with status 0.
   subroutine test_control_characters(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_control')
      stat = run_program(dir, 'run -q -o "x$(printf ''\ny'').h5"')
      call check(error, stat, 1, message='newline in -o: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '-o "x?y.h5": the name holds a '// &
         'control character (byte 10)', 'newline in -o')
      if (allocated(error)) return
      call check(error, holds(dir, 'test -z "$(ls | grep -v -e out.txt -e err.txt)"'), &
         message='no file written for a name with a newline')
      if (allocated(error)) return
      stat = run_program(dir, 'merge "m$(printf ''\t'').h5" a.h5 b.h5')
      call check(error, stat, 1, message='tab in the merge output: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'control character (byte 9)', &
         'tab in the merge output')
      if (allocated(error)) return
      ! The name from the configuration (&output file, here through --set): status 2.
      stat = run_program(dir, 'run -q --set output%file="a$(printf ''\t'')b.h5"')
      call check(error, stat, 2, message='tab in &output file: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'the output name "a?b.h5" holds a '// &
         'control character (byte 9', 'tab in &output file')
      if (allocated(error)) return
      call check(error, holds(dir, 'test -z "$(ls | grep -v -e out.txt -e err.txt)"'), &
         message='no file written for a name with a tab')
      if (allocated(error)) return
      ! A line break through --set was dropped by the namelist reading: ab.h5 was written.
      stat = run_program(dir, 'run -q --set output%file="$(printf ''a\nb.h5'')"')
      call check(error, stat, 2, message='newline in --set: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '--set "output%file=a?b.h5": the '// &
         'value holds a line break', 'newline in --set')
      if (allocated(error)) return
      call check(error, holds(dir, 'test -z "$(ls | grep -v -e out.txt -e err.txt)"'), &
         message='no file written for a --set value with a newline')
      call shell('rm -rf '//dir)
   end subroutine test_control_characters

   !> A FIFO as output hung the run (the check opened it), as a merge input too; a device, a
   !> symbolic link: refused.
   subroutine test_special_outputs(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_special')
      call shell('cd '//dir//' && mkfifo fifo.h5 && echo mine > target.h5 && '// &
         'ln -s target.h5 link.h5')
      stat = run_limited(dir, 'run -q -o fifo.h5')
      call check(error, stat, 3, message='pipe as output: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'cannot write the output "fifo.h5": '// &
         'it is a pipe, not a regular file', 'pipe as output')
      if (allocated(error)) return
      stat = run_limited(dir, 'run -q -o /dev/null --force')
      call check(error, stat, 3, message='device as output: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'it is a device, not a regular file', &
         'device as output')
      if (allocated(error)) return
      stat = run_limited(dir, 'run -q -o link.h5')
      call check(error, stat, 3, message='symbolic link as output: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'cannot write the output "link.h5": '// &
         'it is a symbolic link', 'symbolic link as output')
      if (allocated(error)) return
      ! A pipe as a merge input: refused, not waited on.
      stat = run_limited(dir, 'merge m.h5 fifo.h5')
      call check(error, stat, 3, message='pipe as merge input: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'cannot open "fifo.h5": it is a '// &
         'pipe, not a regular file', 'pipe as merge input')
      if (allocated(error)) return
      ! --force replaces the link by the result file; what it pointed to is untouched.
      stat = run_limited(dir, 'run -q -o link.h5 --force')
      call check(error, stat, 0, message='--force over a link: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, holds(dir, 'test -f link.h5 && ! test -L link.h5 && test -p fifo.h5') &
         .and. file_text(dir//'/target.h5') == 'mine'//new_line('a'), &
         message='the link is replaced, its target and the pipe are untouched')
      call shell('rm -rf '//dir)
   end subroutine test_special_outputs

   !> A result file and a sidecar that shcontact wrote are replaced by the next run; a foreign
   !> file under the output name only with --force.
   subroutine test_own_files_replaced(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: software_names(2) = [character(len=9) :: 'h5py', &
         'shcontact']
      character(len=:), allocatable :: dir
      type(lib_error), allocatable :: e
      integer :: stat, k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_own')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o own.h5')
      if (stat == 0) stat = run_program(dir, 'run sw.nml -q -o own.h5 --set material%'// &
         'friction=0.2')
      call check(error, stat, 0, message='a second run over its own files: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, holds(dir, 'test -f own.h5 && test -f own.xmf && ! test -e '// &
         'own.h5.partial'), message='result, sidecar, no work folder')
      if (allocated(error)) return
      call shell('echo mine > '//dir//'/notes.h5')
      stat = run_program(dir, 'run -q -o notes.h5')
      call check(error, stat, 3, message='foreign output: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_text(dir//'/notes.h5') == 'mine'//new_line('a'), &
         message='the foreign output is untouched')
      if (allocated(error)) return
      stat = run_program(dir, 'run -q -o notes.h5 --force')
      call check(error, stat, 0, message='--force over a foreign output: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! Another program's HDF5 files with a `software` attribute: not taken for ours, whatever
      ! it says, unless the file is laid out as ours (n_cases, /input/namelist).
      do k = 1, 2
         call foreign_hdf5(dir//'/other.h5', trim(software_names(k)), e)
         call check(error, .not. allocated(e), message='writing a foreign HDF5 file')
         if (allocated(error)) return
         call shell('cksum < '//dir//'/other.h5 > '//dir//'/before.txt')
         stat = run_program(dir, 'run -q -o other.h5')
         call check(error, stat, 3, message='foreign HDF5 output (software = '// &
            trim(software_names(k))//'): '//file_text(dir//'/err.txt'))
         if (allocated(error)) return
         call shell('cksum < '//dir//'/other.h5 > '//dir//'/after.txt')
         call check(error, file_text(dir//'/before.txt') == file_text(dir//'/after.txt') .and. &
            index(file_text(dir//'/err.txt'), 'is not a shcontact result file') > 0, &
            message='the foreign HDF5 file is untouched and named: '//file_text(dir//'/err.txt'))
         if (allocated(error)) return
         stat = run_program(dir, 'merge m.h5 other.h5')
         call check(error, stat /= 0 .and. .not. holds(dir, 'test -e m.h5') .and. &
            index(file_text(dir//'/err.txt'), 'not a shcontact result file') > 0, &
            message='a foreign HDF5 file as merge input: '//file_text(dir//'/err.txt'))
         if (allocated(error)) return
      end do
      ! merge: the same rule (a whole run's file is a valid single input).
      call shell('echo mine > '//dir//'/notes2.h5')
      stat = run_program(dir, 'merge notes2.h5 own.h5')
      call check(error, stat, 3, message='merge over a foreign output: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, file_text(dir//'/notes2.h5') == 'mine'//new_line('a'), &
         message='merge: the foreign output is untouched')
      if (allocated(error)) return
      stat = run_program(dir, 'merge notes2.h5 own.h5 --force')
      call check(error, stat, 0, message='merge --force: '//file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_own_files_replaced

   !> An HDF5 file of another program: one dataset and the root attribute `software`.
   subroutine foreign_hdf5(name, software, e)
      character(len=*), intent(in) :: name, software
      type(lib_error), allocatable, intent(out) :: e
      type(h5_file_type) :: out
      if (file_exists(name)) call shell('rm -f '//name)
      call h5_create(out, name, e)
      if (.not. allocated(e)) call h5_write_attribute(out, '/', 'software', software, e)
      if (.not. allocated(e)) call h5_write(out, 'measurements', [1.0_wp, 2.0_wp, 3.0_wp], 'm', e)
      if (.not. allocated(e)) call h5_commit(out, e)
   end subroutine foreign_hdf5

   !> The temporary names OUT.h5.tmpPID and OUT.xmf.tmpPID are created exclusively: a file of
   !> that name makes the write fail and is left as it was (it was truncated before).
   subroutine test_temporary_names(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, pid
      type(h5_file_type) :: file
      type(lib_error), allocatable :: e
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_temp')
      call write_lines(dir//'/sw.nml', small_sweep)
      stat = run_program(dir, 'run sw.nml -q -o fields.h5')
      call check(error, stat, 0, message='run: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      pid = str(process_id())
      call shell('cd '//dir//' && echo mine > new.h5.tmp'//pid//' && echo mine > fields.xmf.tmp'// &
         pid)
      call h5_create(file, dir//'/new.h5', e)
      call check(error, allocated(e), message='h5_create over an existing temporary name')
      if (allocated(error)) return
      call h5_close(file)
      call write_xdmf_sidecar(dir//'/fields.h5', [1], [string_type('cases/000001')], e)
      call check(error, allocated(e), message='sidecar over an existing temporary name')
      if (allocated(error)) return
      call check(error, file_text(dir//'/new.h5.tmp'//pid) == 'mine'//new_line('a') .and. &
         file_text(dir//'/fields.xmf.tmp'//pid) == 'mine'//new_line('a') .and. .not. &
         file_exists(dir//'/new.h5'), message='the files of the temporary names are untouched')
      call shell('rm -rf '//dir)
   end subroutine test_temporary_names

   function str(i) result(text)
      integer, intent(in) :: i
      character(len=:), allocatable :: text
      character(len=12) :: buf
      write (buf, '(i0)') i
      text = trim(buf)
   end function str

   ! ------------------------------------------------------------------------------------------
   ! The work folder OUT.h5.partial (items 13 and 14)
   ! ------------------------------------------------------------------------------------------

   !> OUT.h5.partial as a symbolic link to another folder: a fresh run wrote its blocks there
   !> and deleted block_000001.h5, blocks.txt, configuration.txt, merged.h5.tmp in it.
   subroutine test_work_folder_symlink(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      character(len=*), parameter :: names = 'block_000001.h5 blocks.txt configuration.txt '// &
         'merged.h5.tmp'
      character(len=*), parameter :: options(3) = [character(len=9) :: '', '--resume', &
         '--force']
      integer :: stat, k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_link')
      call shell('cd '//dir//' && mkdir elsewhere && (cd elsewhere && for f in '//names// &
         '; do echo mine > $f; done) && ln -s elsewhere out.h5.partial')
      do k = 1, size(options)
         stat = run_program(dir, 'run -q -o out.h5 '//trim(options(k)))
         call check(error, stat, 3, message='work folder a link '//trim(options(k))//': '// &
            file_text(dir//'/err.txt'))
         if (allocated(error)) return
         call expect_in(error, file_text(dir//'/err.txt'), 'its work folder "out.h5.partial" '// &
            'is a symbolic link, which shcontact does not follow', 'work folder a link')
         if (allocated(error)) return
         call check(error, holds(dir, 'export LC_ALL=C && cd elsewhere && test "$(ls | tr ''\n'' '' '')" = '// &
            '"'//names//' " && test "$(cat '//names//' | sort -u)" = mine && ! test -e '// &
            '../out.h5'), message='the linked folder is untouched '//trim(options(k)))
         if (allocated(error)) return
      end do
      call shell('rm -rf '//dir)
   end subroutine test_work_folder_symlink

   !> A real OUT.h5.partial holding checkpoint names was emptied by a run without --resume.
   subroutine test_existing_work_folder(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_folder')
      call write_lines(dir//'/sw.nml', small_sweep)
      call shell('cd '//dir//' && mkdir out.h5.partial && (cd out.h5.partial && for f in '// &
         'block_000001.h5 blocks.txt configuration.txt merged.h5.tmp notes.txt; do echo '// &
         'mine > $f; done)')
      stat = run_program(dir, 'run sw.nml -q -o out.h5')
      call check(error, stat, 3, message='existing work folder: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'its work folder "out.h5.partial" '// &
         'exists (the checkpoint of an interrupted run?); continue it with --resume', &
         'existing work folder')
      if (allocated(error)) return
      call check(error, holds(dir, 'cd out.h5.partial && test "$(cat block_000001.h5 '// &
         'blocks.txt configuration.txt merged.h5.tmp notes.txt | sort -u)" = mine && ! test '// &
         '-e ../out.h5'), message='the existing folder is untouched')
      if (allocated(error)) return
      ! --force starts afresh: shcontact's names go, other files and so the folder stay.
      stat = run_program(dir, 'run sw.nml -q -o out.h5 --force')
      call check(error, stat, 0, message='--force: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call check(error, holds(dir, 'test -f out.h5 && test "$(ls out.h5.partial)" = notes.txt'), &
         message='--force removes only shcontact''s names from the folder')
      if (allocated(error)) return
      ! An interrupted run's folder: refused without --resume, completed with it.
      call shell('rm -rf '//dir//'/out.h5.partial')
      stat = run_program(dir, 'run sw.nml -q -o out.h5', 'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=1')
      stat = run_program(dir, 'run sw.nml -q -o out.h5')
      call check(error, stat, 3, message='interrupted run, no --resume: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -o out.h5 --resume')
      call check(error, stat, 0, message='--resume: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), '(2 from the checkpoint)', '--resume')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/out.h5.partial'), &
         message='the completed run removes its work folder')
      call shell('rm -rf '//dir)
   end subroutine test_existing_work_folder

   !> A profile file rewritten under the same name between the blocks or shards of a run: the
   !> configuration text is the same, the points are not. `--resume` refuses the checkpoint
   !> (its key holds a fingerprint of the profiles as read) and `merge` refuses the shards (their
   !> /input/profiles differ), status 2, instead of mixing cases solved on two profiles; with the
   !> file restored the run resumes.
   subroutine test_profile_changed(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      character(len=*), parameter :: worn = 'data/profiles/worn/S1002-worn.txt'
      integer :: stat
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_profile_changed')
      call write_lines(dir//'/sw.nml', [character(len=72) :: small_sweep, &
         "&profiles wheel = 'wheel.txt' /"])
      call shell('cp data/profiles/S1002.txt '//dir//'/wheel.txt')
      stat = run_program(dir, 'run sw.nml -q -o out.h5', 'SHCONTACT_TEST_ABORT_AFTER_BLOCKS=1')
      call shell('cp '//worn//' '//dir//'/wheel.txt')
      stat = run_program(dir, 'run sw.nml -q -o out.h5 --resume')
      call check(error, stat, 2, message='resume after the profile changed: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'profile files whose points have '// &
         'changed', 'resume after the profile changed')
      if (allocated(error)) return
      call shell('cp data/profiles/S1002.txt '//dir//'/wheel.txt')
      stat = run_program(dir, 'run sw.nml -q -o out.h5 --resume')
      call check(error, stat, 0, message='resume with the profile restored: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run sw.nml -q -o s.h5 --shard 1/2')
      call shell('cp '//worn//' '//dir//'/wheel.txt')
      if (stat == 0) stat = run_program(dir, 'run sw.nml -q -o s.h5 --shard 2/2')
      call check(error, stat, 0, message='shards: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'merge m.h5 s-shard1of2.h5 s-shard2of2.h5')
      call check(error, stat, 2, message='merge of shards with another profile: '// &
         file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call expect_in(error, file_text(dir//'/err.txt'), 'was solved with other profile points', &
         'merge of shards with another profile')
      if (allocated(error)) return
      call check(error, .not. file_exists(dir//'/m.h5'), message='no merged file')
      call shell('rm -rf '//dir)
   end subroutine test_profile_changed

   !> The root attribute `threads` records the threads the run solved with: `--threads 1` under
   !> OMP_NUM_THREADS=2 gives 1, in a file written from memory and in one merged from checkpoint
   !> blocks (it recorded OMP_NUM_THREADS's 2).
   subroutine test_threads_attribute(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir
      type(h5_file_type) :: file
      type(lib_error), allocatable :: lerr
      integer :: stat, threads, k
      ! Without fields (written from memory), and with fields in blocks of 2 cases (merged).
      character(len=*), parameter :: blocks(2) = [character(len=40) :: &
         ' --set output%fields=none', '']
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_threads')
      call write_lines(dir//'/sw.nml', small_sweep)
      do k = 1, size(blocks)
         stat = run_program(dir, 'run sw.nml -q --force -o t.h5 --threads 1'//trim(blocks(k)))
         call check(error, stat, 0, message='run: '//file_text(dir//'/err.txt'))
         if (allocated(error)) return
         call h5_open(file, dir//'/t.h5', lerr)
         if (.not. allocated(lerr)) call h5_read_attribute(file, '/', 'threads', threads, lerr)
         call h5_close(file)
         if (allocated(lerr)) then
            call test_failed(error, lerr%message)
            return
         end if
         call check(error, threads, 1, message='the threads attribute'//trim(blocks(k)))
         if (allocated(error)) return
      end do
      call shell('rm -rf '//dir)
   end subroutine test_threads_attribute

   !> Two runs with the same -o: the loser failed with misleading messages, and once both
   !> failed. Now the second gets one message and the first completes.
   subroutine test_two_runs(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, text
      character(len=:), allocatable :: config_text, messages(:)
      integer, allocatable :: indices(:), failed(:)
      type(case_summary_type), allocatable :: summaries(:)
      type(lib_error), allocatable :: e
      integer :: stat, n_cases, k
      if (unavailable(error, .false.)) return
      dir = scratch_directory('of_two')
      call write_lines(dir//'/long.nml', [character(len=72) :: &
         '&sweep nu_x = 0.0, 2.0e-3, nu_x_points = 300 /', &
         '&output checkpoint_cases = 10 /'])
      ! The first run in the background; the second once the first has written a block.
      call shell('cd '//dir//' && (env OMP_NUM_THREADS=1 '//program_path()//' run long.nml '// &
         '-q -o out.h5 > first_out.txt 2> first_err.txt; echo $? > first_status.txt) &')
      do k = 1, 1200
         if (file_exists(dir//'/out.h5.partial/blocks.txt') .or. &
             file_exists(dir//'/first_status.txt')) exit
         call shell('sleep 0.05')
      end do
      call check(error, .not. file_exists(dir//'/first_status.txt'), message='the first run '// &
         'ended before the second started: '//file_text(dir//'/first_err.txt'))
      if (allocated(error)) return
      stat = run_program(dir, 'run long.nml -q -o out.h5')
      text = file_text(dir//'/err.txt')
      ! Until the first run's status is written (the file exists before `echo` has written it).
      do k = 1, 6000
         if (file_exists(dir//'/first_status.txt')) then
            if (len_trim(file_text(dir//'/first_status.txt')) > 0) exit
         end if
         call shell('sleep 0.1')
      end do
      call check(error, stat, 3, message='the second run: '//text)
      if (allocated(error)) return
      call expect_in(error, text, 'shcontact: error: another run is writing "out.h5"', &
         'the second run')
      if (allocated(error)) return
      call check(error, count([(text(k:k) == new_line('a'), k=1, len(text))]), 1, &
         message='one message: '//text)
      if (allocated(error)) return
      call check(error, trim(adjustl(file_text(dir//'/first_status.txt'))) == '0'// &
         new_line('a'), message='the first run is unaffected: '//file_text(dir// &
         '/first_err.txt'))
      if (allocated(error)) return
      call read_result_summary(dir//'/out.h5', config_text, n_cases, indices, summaries, &
         failed, messages, e)
      call check(error, .not. allocated(e), message='the first run''s file reads')
      if (allocated(error)) return
      call check(error, size(indices) == 300 .and. n_cases == 300 .and. &
         all(summaries%stat == 0), message='the first run''s file holds every case')
      call shell('rm -rf '//dir)
   end subroutine test_two_runs

end module test_output_files
