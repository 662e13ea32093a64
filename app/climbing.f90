!> Flange climbing: where a wheel's flange is steepest, and the states whose contact lies beyond
!> it (towards the flange tip), which a rigid wheelset reaches only by climbing the flange
!> (doc/app.md; `geometry --wheelset` and `run` note them).
module shcontact_app_climbing
   use, intrinsic :: iso_fortran_env, only: error_unit
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int, str_format
   use shcontact, only: case_config_type, run_setup_type, case_point_type, case_summary_type, &
      climbing_margin
   implicit none
   private

   public :: note_climbing_cases

contains

   !> A note on stderr when solved cases of a run have their main contact beyond the flange's
   !> steepest part (rolling radius above the solver's steep-end radius, shcontact_geometry_flange): how many, their t_y range.
   subroutine note_climbing_cases(config, setup, summaries, first)
      type(case_config_type), intent(in) :: config
      type(run_setup_type), intent(in) :: setup
      !> The summaries of cases first, first + 1, ...
      type(case_summary_type), intent(in) :: summaries(:)
      integer, intent(in) :: first
      real(wp) :: radius, lo, hi
      type(case_point_type) :: point
      integer :: k, n
      ! The steep end's radius of the solver's prepared profiles (huge without a flange).
      radius = setup%prepared%steep_end_radius
      if (radius >= huge(1.0_wp)) return
      n = 0
      lo = huge(1.0_wp)
      hi = -huge(1.0_wp)
      do k = 1, size(summaries)
         if (summaries(k)%stat /= 0) cycle
         if (.not. (summaries(k)%r0 > radius + climbing_margin)) cycle
         n = n + 1
         point = config%case_point(first + k - 1)
         lo = min(lo, point%t_y)
         hi = max(hi, point%t_y)
      end do
      if (n == 0) return
      write (error_unit, '(a)') 'shcontact: note: '//str_int(n)//' solved case(s) (t_y '// &
         str_format(lo, '(f0.3)')//' … '//str_format(hi, '(f0.3)')//' mm) touch the '// &
         'wheel''s flange beyond its steepest part (rolling radius above '// &
         str_format(radius, '(f0.2)')//' mm): flange-climbing states, which a rigid wheelset '// &
         'reaches only by climbing the flange (geometry --wheelset gives the shift where they begin)'
   end subroutine note_climbing_cases

end module shcontact_app_climbing
