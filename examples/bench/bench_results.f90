!> What the benchmark keeps across its sections: the figures the targets of issue 9 are about,
!> printed at the end against the targets, and the forces of the checked cases, saved to a file
!> or compared with another build's (--save-results, --compare-results).
module bench_results
   use, intrinsic :: iso_fortran_env, only: output_unit
   use shcontact, only: wp
   use shcontact_core_strings, only: str_int
   use bench_timing, only: median_of
   use bench_config, only: bench_config_type, sizes, n_bounds
   use bench_report, only: section, verdict, fail
   implicit none
   private

   public :: summary_type, force_record_type, check_results, print_summary

   !> The figures the targets of issue 9 are about (negative: not measured in this run).
   type :: summary_type
      !> FASTSIM_SH solve at 50 x 50: weighted bound and the slowest bound (s).
      real(wp) :: sh50_weighted = -1.0_wp, sh50_worst = -1.0_wp
      !> FASTSIM_SH/FASTSIM ratios for every size and bound: solve, prepare + solve.
      real(wp) :: ratio_solve(size(sizes)*n_bounds) = -1.0_wp
      real(wp) :: ratio_prep_solve(size(sizes)*n_bounds) = -1.0_wp
      !> Full FASTSIM_SH case at 50 x 50 and 100 x 50, forces only (s).
      real(wp) :: full50 = -1.0_wp, full100 = -1.0_wp
      !> DOE through the app's sweep driver with 1 and 2 threads (s).
      real(wp) :: doe1 = -1.0_wp, doe2 = -1.0_wp
      !> Kinematic call along the hunting trajectory (s), and over the same-position call.
      real(wp) :: moving = -1.0_wp, moving_ratio = -1.0_wp
   end type summary_type

   !> The forces of the checked cases, in the order the sections compute them.
   type :: force_record_type
      real(wp), allocatable :: values(:)
   contains
      procedure :: keep
      procedure :: keep_array
   end type force_record_type

contains

   !> Record the forces of one case.
   subroutine keep(self, fx, fy, mz)
      !> The record.
      class(force_record_type), intent(inout) :: self
      !> Forces (N) and spin moment (N mm).
      real(wp), intent(in) :: fx, fy, mz
      call self%keep_array([fx, fy, mz])
   end subroutine keep

   !> Record a column of forces.
   subroutine keep_array(self, values)
      !> The record.
      class(force_record_type), intent(inout) :: self
      !> The forces.
      real(wp), intent(in) :: values(:)
      if (allocated(self%values)) then
         self%values = [self%values, values]
      else
         self%values = values
      end if
   end subroutine keep_array

   !> Save the checked forces, or compare them with another build's.
   subroutine check_results(config, record, scale)
      !> The options of the run (the files).
      type(bench_config_type), intent(in) :: config
      !> The forces of this run.
      type(force_record_type), intent(in) :: record
      !> Force scale of the comparison, mu F_n (N).
      real(wp), intent(in) :: scale
      real(wp), allocatable :: saved(:), other(:)
      integer :: unit, stat, n, i
      real(wp) :: diff

      saved = record%values
      if (.not. allocated(saved)) allocate (saved(0))
      if (len(config%save_file) > 0) then
         open (newunit=unit, file=config%save_file, status='replace', action='write', iostat=stat)
         if (stat /= 0) call fail('cannot write '//config%save_file)
         write (unit, '(i0)') size(saved)
         write (unit, '(es24.16e3)') saved
         close (unit)
         write (output_unit, '(2x,a,i0,a)') 'saved ', size(saved), ' forces to '// &
            config%save_file
      end if
      if (len(config%compare_file) > 0) then
         open (newunit=unit, file=config%compare_file, status='old', action='read', iostat=stat)
         if (stat /= 0) call fail('cannot read '//config%compare_file)
         read (unit, *, iostat=stat) n
         if (stat /= 0 .or. n /= size(saved)) call fail(config%compare_file// &
            ': expected '//str_int(size(saved))//' forces')
         allocate (other(n))
         read (unit, *, iostat=stat) other
         close (unit)
         if (stat /= 0) call fail('cannot read the forces of '//config%compare_file)
         diff = 0.0_wp
         do i = 1, n
            diff = max(diff, abs(other(i) - saved(i))/scale)
         end do
         write (output_unit, '(2x,a,i0,a,es9.2,a,i0,a)') 'this build vs '// &
            config%compare_file//': ', n, ' forces (N, N mm), max |d|/(mu Fn) = ', diff, &
            ' (', count(other == saved), ' bitwise equal)'
      end if
   end subroutine check_results

   !> The targets of issue 9 against this run's medians.
   subroutine print_summary(summary)
      !> The figures of this run.
      type(summary_type), intent(in) :: summary
      call section('targets (issue 9; medians of this run)')
      if (summary%sh50_worst > 0.0_wp) write (output_unit, '(2x,a,f6.2,a,f6.2,a,a)') &
         'FASTSIM_SH solve 50 x 50 <= 15 us: weighted ', 1.0e6_wp*summary%sh50_weighted, &
         ' us, slowest bound ', 1.0e6_wp*summary%sh50_worst, ' us: ', &
         verdict(summary%sh50_worst <= 15.0e-6_wp)
      if (summary%full50 > 0.0_wp) write (output_unit, '(2x,a,f6.2,a,a,a,f6.2,a,a)') &
         'full case (normal + tangential, geometry reused) <= 30 us: 50 strips ', &
         1.0e6_wp*summary%full50, ' us: ', verdict(summary%full50 <= 30.0e-6_wp), &
         '; the default 100 strips ', 1.0e6_wp*summary%full100, ' us: ', &
         verdict(summary%full100 <= 30.0e-6_wp)
      if (summary%ratio_solve(1) > 0.0_wp) then
         write (output_unit, '(2x,a,f5.2,a,f5.2,a,a)') 'FASTSIM_SH/FASTSIM <= 1.2 (median and '// &
            'largest over the 3 sizes x 5 bounds): solve ', median_of(summary%ratio_solve), &
            ', largest ', maxval(summary%ratio_solve), ': ', &
            verdict(median_of(summary%ratio_solve) <= 1.2_wp)
         write (output_unit, '(2x,a,f5.2,a,f5.2,a,a)') '  with the preparation from the '// &
            'normal solution (prepare + solve): ', median_of(summary%ratio_prep_solve), &
            ', largest ', maxval(summary%ratio_prep_solve), ': ', &
            verdict(median_of(summary%ratio_prep_solve) <= 1.2_wp)
      end if
      if (summary%moving > 0.0_wp) write (output_unit, '(2x,a,f8.1,a,f6.2,a)') &
         'wheel in motion (hunting, 100 x 50): ', 1.0e6_wp*summary%moving, &
         ' us per call, moving/fixed = ', summary%moving_ratio, &
         ' (targets <= 100 us and <= 3)'
      if (summary%doe2 > 0.0_wp) write (output_unit, '(2x,a,f6.1,a,f6.1,a,a)') &
         'DOE end to end with the HDF5 file <= 0.5 s with 2 threads: ', 1.0e3_wp*summary%doe2, &
         ' ms (1 thread: ', 1.0e3_wp*summary%doe1, ' ms): ', verdict(summary%doe2 <= 0.5_wp)
      write (output_unit, '(2x,a)') 'no heap allocation per case: run --alloc-check N and 2N '// &
         'under valgrind (doc/performance.md)'
   end subroutine print_summary

end module bench_results
