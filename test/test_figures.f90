!> The committed figures show what the library computes now, and the plot script fails cleanly.
!>
!> `scripts/plot_case.py` writes, beside the field figures of a case, NAME_numbers.csv: every
!> number the figures print (`quantity,value,printed,shown,tolerance`: the full value, the text
!> on the figure, that text in the value's units, half a unit of its last printed digit). The
!> headline figures doc/figures/plot_headline_*.png come with doc/figures/plot_headline_numbers.csv
!> (regenerated with them by `scripts/plot_figures`, doc/plots.md); the test solves the headline
!> case and requires each printed number to be the current value to its last printed digit.
module test_figures
   use testdrive, only: new_unittest, unittest_type, error_type, check, test_failed, skip_test
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   use shcontact_api_solver, only: contact_result_type
   use test_api, only: headline_t_y, headline_load, headline_creepage, headline_result
   use test_app, only: shell, file_text, scratch_directory, run_program, unavailable, &
      current_directory
   implicit none
   private
   public :: collect_figures

   !> The numbers of the committed headline figures.
   character(len=*), parameter :: headline_numbers = 'doc/figures/plot_headline_numbers.csv'

contains

   subroutine collect_figures(testsuite)
      type(unittest_type), allocatable, intent(out) :: testsuite(:)
      testsuite = [ &
         new_unittest('headline_figures_show_current_numbers', test_headline_numbers), &
         new_unittest('plot_script_without_matplotlib', test_without_matplotlib), &
         new_unittest('plot_script_patch_and_folder', test_patch_and_folder), &
         new_unittest('plot_script_refuses_clearly', test_plot_refusals) &
         ]
   end subroutine collect_figures

   !> Every number printed on the committed headline figures (case title, strip table title,
   !> traction title) equals the headline case solved now to within half a unit of its last
   !> printed digit, and the file has all twelve of them.
   subroutine test_headline_numbers(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: expected(12) = [character(len=17) :: 't_y', &
         'normal_force', 'nu_x', 'nu_y', 'phi', 'fn', 'p_max', 'fx', 'fy', 'fx_norm', &
         'fy_norm', 'adhesion_fraction']
      type(contact_result_type) :: result
      character(len=256) :: line
      character(len=32) :: quantity, printed
      real(wp) :: value, shown, tolerance, current
      logical :: seen(size(expected))
      integer :: unit, stat, k, c(4)

      call headline_result(result, error)
      if (allocated(error)) return
      open (newunit=unit, file=headline_numbers, status='old', action='read', iostat=stat)
      if (stat /= 0) then
         call test_failed(error, headline_numbers//' is missing (scripts/plot_figures)')
         return
      end if
      read (unit, '(a)', iostat=stat) line
      seen = .false.
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         c(1) = index(line, ',')
         c(2) = c(1) + index(line(c(1) + 1:), ',')
         c(3) = c(2) + index(line(c(2) + 1:), ',')
         c(4) = c(3) + index(line(c(3) + 1:), ',')
         quantity = line(:c(1) - 1)
         printed = line(c(2) + 1:c(3) - 1)
         read (line(c(1) + 1:c(2) - 1), *, iostat=stat) value
         if (stat == 0) read (line(c(3) + 1:c(4) - 1), *, iostat=stat) shown
         if (stat == 0) read (line(c(4) + 1:), *, iostat=stat) tolerance
         if (stat /= 0 .or. c(4) <= c(3)) then
            call test_failed(error, headline_numbers//': cannot read the line '//trim(line))
            exit
         end if
         select case (trim(quantity))
         case ('t_y'); current = headline_t_y
         case ('normal_force'); current = headline_load
         case ('nu_x'); current = headline_creepage%nu_x
         case ('nu_y'); current = headline_creepage%nu_y
         case ('phi'); current = headline_creepage%phi
         case ('fn'); current = result%main%fn
         case ('p_max'); current = result%main%p_max
         case ('fx'); current = result%main%fx
         case ('fy'); current = result%main%fy
         case ('fx_norm'); current = result%main%fx_norm
         case ('fy_norm'); current = result%main%fy_norm
         case ('adhesion_fraction'); current = result%main%adhesion_fraction
         case default
            call test_failed(error, headline_numbers//': unknown quantity '//trim(quantity)// &
               ' (teach this test what it is)')
            exit
         end select
         where (expected == quantity) seen = .true.
         call check(error, abs(current - shown) <= tolerance*(1.0_wp + 1.0e-9_wp), &
            message='the headline figures show '//trim(quantity)//' = '//trim(printed)// &
            '; it is now '//real_text(current)//': regenerate them (scripts/plot_figures)')
         if (allocated(error)) exit
      end do
      close (unit)
      if (allocated(error)) return
      do k = 1, size(expected)
         call check(error, seen(k), message=headline_numbers//' lacks '//trim(expected(k)))
         if (allocated(error)) return
      end do
   contains
      function real_text(x) result(text)
         real(wp), intent(in) :: x
         character(len=:), allocatable :: text
         character(len=32) :: buf
         write (buf, '(g0.8)') x
         text = trim(adjustl(buf))
      end function real_text
   end subroutine test_headline_numbers

   !> Without matplotlib (made unimportable) the plot script prints one line naming what is
   !> missing and how to install it, no traceback, and exits with status 1.
   subroutine test_without_matplotlib(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, err_text
      integer :: stat

      call shell('python3 -c "import sys" > /dev/null 2>&1', stat)
      if (stat /= 0) then
         call skip_test(error, 'no python3')
         return
      end if
      dir = scratch_directory('figures_nompl')
      call shell('python3 -c "import sys; sys.modules[''matplotlib''] = None; '// &
         'sys.argv = [''plot_case.py'', ''x.h5'']; '// &
         'exec(open(''scripts/plot_case.py'').read())" > '//dir//'/out.txt 2> '//dir// &
         '/err.txt', stat)
      err_text = file_text(dir//'/err.txt')
      call check(error, stat, 1, message='exit status without matplotlib')
      if (allocated(error)) return
      call check(error, index(err_text, 'Traceback') == 0 .and. &
         index(err_text, 'scripts/setup --plot') > 0 .and. &
         (index(err_text, "'matplotlib'") > 0 .or. index(err_text, "'h5py'") > 0 .or. &
         index(err_text, "'numpy'") > 0), message='message without matplotlib: '//err_text)
      call shell('rm -rf '//dir)
   end subroutine test_without_matplotlib

   !> What a user met (stop 46): `--compare` of files of other cases drew them against each
   !> other by case number; a file that is not HDF5, or a missing --compare file (after the
   !> other PNGs were written), gave a Python traceback; `--case N` on a file without fields was
   !> ignored. Each is now one line naming the file, status 1, and nothing written; two solutions
   !> of the same case compare.
   subroutine test_plot_refusals(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, here
      character(len=*), parameter :: cases(4, 2) = reshape([character(len=150) :: &
         'h.h5 --compare ty.h5', 'ty.h5 --compare missing.h5', 'nothdf.h5', 'ty.h5 --case 3', &
         'case 1 has t_y = 4.733 in h.h5 and 0.0 in ty.h5: the files hold other cases', &
         'plot_case: missing.h5: no such file', &
         'plot_case: nothdf.h5 is not an HDF5 file (not a shcontact result file)', &
         'plot_case: --case 3: ty.h5 holds no element fields'], [4, 2])
      integer :: stat, k

      if (plotting_unavailable(error)) return
      here = current_directory()
      dir = scratch_directory('figures_refusals')
      stat = run_program(dir, 'run -q -o h.h5')
      if (stat == 0) stat = run_program(dir, 'run -q -o hf.h5 --set tangential%bound=clipped')
      if (stat == 0) stat = run_program(dir, 'run -q -o ty.h5 --set sweep%t_y=0,8 '// &
         '--set sweep%t_y_points=3')
      call check(error, stat, 0, message='the runs: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call shell('echo "not hdf5" > '//dir//'/nothdf.h5')
      do k = 1, size(cases, 1)
         call shell('cd '//dir//' && python3 '//here//'/scripts/plot_case.py '// &
            trim(cases(k, 1))//' -o figs > out.txt 2> err.txt', stat)
         call check(error, stat == 1 .and. index(file_text(dir//'/err.txt'), &
            trim(cases(k, 2))) > 0 .and. index(file_text(dir//'/err.txt'), 'Traceback') == 0, &
            message='plot_case.py '//trim(cases(k, 1))//': status '//str_int(stat)//', '// &
            file_text(dir//'/err.txt'))
         if (allocated(error)) return
         call shell('test ! -e '//dir//'/figs', stat)
         call check(error, stat, 0, message='plot_case.py '//trim(cases(k, 1))//' wrote figures')
         if (allocated(error)) return
      end do
      call shell('cd '//dir//' && python3 '//here//'/scripts/plot_case.py h.h5 --compare hf.h5 '// &
         '-o figs > out.txt 2> err.txt && test -s figs/h_vs_hf_forces.png', stat)
      call check(error, stat, 0, message='two solutions of one case: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      ! A sweep whose failed cases the figures leave out says so (they were dropped silently).
      stat = run_program(dir, 'run -q -o fail.h5 --set load%mode=approach '// &
         '--set sweep%approach=0.05,5 --set sweep%approach_points=4')
      call check(error, stat, 4, message='a sweep with failed cases: '//file_text(dir//'/err.txt'))
      if (allocated(error)) return
      call shell('cd '//dir//' && python3 '//here//'/scripts/plot_case.py fail.h5 -o figs2 '// &
         '> out.txt 2> err.txt', stat)
      call check(error, stat == 0 .and. index(file_text(dir//'/err.txt'), &
         '2 of 4 case(s) failed and are left out') > 0, message='failed cases not named: '// &
         file_text(dir//'/err.txt'))
      call shell('rm -rf '//dir)
   end subroutine test_plot_refusals

   !> The kinematic example (two patches with different creepages) plotted with --patch 2: the
   !> figures go next to the result file, not into the working directory, and the creepages in
   !> the title (NAME_numbers.csv) are patch 2's, not patch 1's (nor the case's main patch's).
   subroutine test_patch_and_folder(error)
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: dir, here
      real(wp) :: title(3), patch(2, 3)
      integer :: stat, k

      if (plotting_unavailable(error)) return
      here = current_directory()
      dir = scratch_directory('figures_patch')
      call check(error, run_program(dir, 'run '//here//'/examples/kinematic.nml -q -o k.h5'), 0, &
         message='the kinematic example did not run')
      if (allocated(error)) return
      call shell('python3 scripts/plot_case.py '//dir//'/k.h5 --patch 2 > '//dir// &
         '/plot.txt 2>&1', stat)
      call check(error, stat, 0, message='plot_case.py --patch 2: '//file_text(dir//'/plot.txt'))
      if (allocated(error)) return
      call shell('test -s '//dir//'/k_traction.png && test -s '//dir//'/k_pressure.png && '// &
         'test ! -e k_traction.png && test ! -e k_numbers.csv', stat)
      call check(error, stat, 0, message='the figures are not next to the result file')
      if (allocated(error)) return
      call shell('python3 -c "import h5py; f = h5py.File('''//dir//'/k.h5''); '// &
         '[print(*[f[''cases/000001/patch_%d/tangential/%s'' % (p, q)][()] for q in '// &
         '(''nu_x'', ''nu_y'', ''phi'')]) for p in (1, 2)]" > '//dir//'/patches.txt && '// &
         'grep -E "^(nu_x|nu_y|phi)," '//dir//'/k_numbers.csv | cut -d, -f4 > '//dir// &
         '/title.txt', stat)
      if (stat == 0) call read_reals(dir//'/patches.txt', patch, stat)
      if (stat == 0) call read_reals(dir//'/title.txt', title, stat)
      call check(error, stat, 0, message='cannot read the creepages back')
      if (allocated(error)) return
      do k = 1, 3
         call check(error, abs(title(k) - patch(2, k)) <= 5.0e-3_wp*abs(patch(2, k)) .and. &
            abs(title(k) - patch(1, k)) > 5.0e-3_wp*abs(patch(1, k)), message= &
            'the title''s creepages are not patch 2''s')
         if (allocated(error)) return
      end do
      call shell('rm -rf '//dir)
   contains
      subroutine read_reals(file, values, stat)
         character(len=*), intent(in) :: file
         real(wp), intent(out) :: values(..)
         integer, intent(out) :: stat
         integer :: unit
         open (newunit=unit, file=file, status='old', action='read', iostat=stat)
         if (stat /= 0) return
         select rank (values)
         rank (1)
            read (unit, *, iostat=stat) values
         rank (2)
            read (unit, *, iostat=stat) values(1, :), values(2, :)
         end select
         close (unit)
      end subroutine read_reals
   end subroutine test_patch_and_folder

   !> Skip (true) when the program or python3 with h5py, numpy and matplotlib is not available.
   logical function plotting_unavailable(error)
      type(error_type), allocatable, intent(out) :: error
      integer :: stat
      plotting_unavailable = unavailable(error, .false.)
      if (plotting_unavailable) return
      call shell('python3 -c "import h5py, numpy, matplotlib" > /dev/null 2>&1', stat)
      plotting_unavailable = stat /= 0
      if (plotting_unavailable) call skip_test(error, 'python3 with h5py, numpy and matplotlib '// &
         'is not available')
   end function plotting_unavailable

end module test_figures
