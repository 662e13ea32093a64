!> `shcontact geometry --wheelset Y_MIN,Y_MAX,STEP --conicity A[,A...]`: the wheelset's contact
!> geometry over the lateral shift and its equivalent conicity (doc/geometry.md, *Wheelset
!> contact geometry and equivalent conicity*). Both tables go to stdout, units in the headers.
module shcontact_app_wheelset
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type
   use shcontact_core_strings, only: str_int, str_format
   use shcontact, only: case_config_type, run_setup_type, prepare_run, wheelset_contact_type, &
      profile_type, &
      wheelset_geometry_table, roll_angle_parameter, contact_distance, centre_radius, &
      equivalent_conicity, conicity_en15302, conicity_harmonic, klingel_wavelength, &
      flange_steepest
   use shcontact_app_cli, only: cli_type
   use shcontact_app_commands, only: configure, report_error, refuse_yaw, print_profile_notes
   use shcontact_app_stdout, only: put_line
   implicit none
   private

   public :: wheelset_command

   !> Step of the internal table the conicity is computed on (mm), and its margin beyond the
   !> largest amplitude (mm; the motion's centre may move off y = 0 on asymmetric pairs).
   real(wp), parameter :: conicity_step = 0.05_wp, conicity_margin = 2.0_wp
   !> One row of the contact table (the widths of the header's columns).
   character(len=*), parameter :: row_format = '(f9.3,2(1x,f10.5),2(1x,f11.4),2(1x,f12.4),'// &
      '2(1x,f11.5),1x,f10.5,2(1x,f12.6),2i5)'

contains

   !> The command: the table over --wheelset, the conicity for --conicity.
   integer function wheelset_command(cli) result(status)
      !> The command line (--wheelset and/or --conicity given).
      type(cli_type), intent(in) :: cli
      type(case_config_type) :: config
      type(run_setup_type) :: setup
      type(wheelset_contact_type), allocatable :: table(:)
      type(error_type), allocatable :: error
      type(cli_type) :: plain
      real(wp) :: reach, steepest
      integer :: n_rows

      status = 0
      n_rows = 0
      plain = cli
      plain%output = ''
      call configure(plain, config, error)
      if (.not. allocated(error)) call refuse_yaw(cli, config, error)
      if (.not. allocated(error)) call prepare_run(config, setup, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) call print_profile_notes(config)
      steepest = flange_steepest(setup%wheel, setup%prepared%y_tape)
      call put_line('# wheelset contact geometry: wheel '// &
         trim(config%profiles%wheel)//', rail '//trim(config%profiles%rail)//'; gauge '// &
         str_format(setup%prepared%track%gauge, '(f0.2)')//' mm, flange-back distance '// &
         str_format(setup%prepared%track%flange_back_distance, '(f0.2)')// &
         ' mm, rail inclination '// &
         str_format(setup%prepared%track%rail_inclination, '(f0.4)')// &
         trim(merge(' (profile already canted)', '                         ', &
         setup%prepared%track%rail_canted)))
      if (cli%wheelset_given) then
         call wheelset_geometry_table(setup%prepared, shifts(cli%wheelset_range(1), &
            cli%wheelset_range(2), cli%wheelset_range(3)), table, error)
         if (allocated(error)) then
            status = report_error(error)
            return
         end if
         call print_table(table)
         call note_climbing(table, steepest, cli%quiet)
         n_rows = size(table)
      end if
      if (allocated(cli%amplitudes)) then
         reach = maxval(cli%amplitudes) + conicity_margin
         call wheelset_geometry_table(setup%prepared, shifts(-reach, reach, conicity_step), &
            table, error)
         if (allocated(error)) then
            status = report_error(error)
            return
         end if
         call print_conicity(table, cli%amplitudes, status)
         call note_flange_amplitudes(table, cli%amplitudes, cli%quiet)
         n_rows = n_rows + size(table)
      end if
      if (.not. cli%quiet .and. status == 0) write (error_unit, '(a)') 'shcontact: wheelset '// &
         'geometry at '//str_int(n_rows)//' lateral shift(s) computed'
   end function wheelset_command

   !> y_min, y_min + step, ... up to y_max (included when it lies on the grid to 1e-9 mm).
   pure function shifts(y_min, y_max, step) result(y)
      real(wp), intent(in) :: y_min, y_max, step
      real(wp), allocatable :: y(:)
      integer :: i, n
      n = floor((y_max - y_min)/step + 1.0e-9_wp) + 1
      y = [(y_min + (i - 1)*step, i=1, n)]
   end function shifts

   !> The contact table, one line per shift.
   subroutine print_table(table)
      type(wheelset_contact_type), intent(in) :: table(:)
      character(len=256) :: row
      integer :: i
      call put_line('# per wheel (R right, L left): contact point on the rail '// &
         '(track y, from the track centre line), on the wheel (wheel profile y), rolling '// &
         'radius, contact angle (side frame, < 0 on the tread), number of contact patches')
      call put_line('#    y_mm  roll_mrad    z_ws_mm  rail_yR_mm  rail_yL_mm  whe'// &
         'el_yR_mm  wheel_yL_mm      r_R_mm      r_L_mm      dr_mm  ga'// &
         'mma_R_rad  gamma_L_rad  n_R  n_L')
      do i = 1, size(table)
         associate (t => table(i))
            write (row, row_format) &
               t%y, tidy(1.0e3_wp*t%roll), t%z_centre, t%rail_y, t%wheel_y, t%radius, &
               tidy(t%delta_r()), &
               t%gamma, t%patches
            call put_line(trim(row))
         end associate
      end do
   end subroutine print_table

   !> Equivalent conicity (both methods), Klingel wavelength and roll-angle parameter per
   !> amplitude; an amplitude whose conicity fails is reported on stderr (status 5).
   subroutine print_conicity(table, amplitudes, status)
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp), intent(in) :: amplitudes(:)
      integer, intent(inout) :: status
      type(error_type), allocatable :: error
      real(wp) :: tan_en, tan_h, e0, r0, y(size(table)), dr(size(table))
      character(len=256) :: row
      integer :: k
      y = table%y
      dr = table%delta_r()
      e0 = contact_distance(table)
      r0 = centre_radius(table)
      call put_line('# equivalent conicity: EN 15302 (wavelength of the '// &
         'kinematic motion) and first-harmonic balance of dr; Klingel wavelength with '// &
         'e0 = '//str_format(e0, '(f0.2)')//' mm, r0 = '//str_format(r0, '(f0.3)')//' mm; roll-angle '// &
         'parameter sigma (roll = -sigma*y/(e0/2), first harmonic)')
      call put_line('# amplitude_mm  tan_gamma_e_EN15302  tan_gamma_e_harmonic  '// &
         'wavelength_m        sigma')
      do k = 1, size(amplitudes)
         call equivalent_conicity(y, dr, amplitudes(k), tan_en, error, conicity_en15302)
         if (.not. allocated(error)) call equivalent_conicity(y, dr, amplitudes(k), tan_h, &
            error, conicity_harmonic)
         if (allocated(error)) then
            status = report_error(error)
            cycle
         end if
         write (row, '(f14.3,f21.5,f22.5,f14.3,f13.5)') amplitudes(k), tan_en, tan_h, &
            1.0e-3_wp*klingel_wavelength(tan_en, e0, r0), &
            roll_angle_parameter(table, amplitudes(k))
         call put_line(trim(row))
      end do
   end subroutine print_conicity

   !> A note (a comment line of the table and, unless quiet, on stderr) naming, for each wheel,
   !> the smallest shift at which its contact lies beyond its flange's steepest part (towards
   !> the flange tip): the rigid wheelset can shift that far only by climbing the flange, so the
   !> rows from there on are flange-climbing states (the contact angle falls again, the wheelset
   !> is lifted).
   subroutine note_climbing(table, steepest, quiet)
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp), intent(in) :: steepest
      logical, intent(in) :: quiet
      character(len=*), parameter :: names(2) = [character(len=5) :: 'right', 'left']
      character(len=:), allocatable :: line
      integer :: k, i, first
      do k = 1, 2
         first = 0
         do i = 1, size(table)
            if (.not. (table(i)%wheel_y(k) < steepest - 0.1_wp)) cycle
            if (first == 0) then
               first = i
            else if (abs(table(i)%y) < abs(table(first)%y)) then
               first = i
            end if
         end do
         if (first == 0) cycle
         associate (t => table(first))
            line = 'note: from y = '//str_format(t%y, '(f0.3)')//' mm the '//trim(names(k))// &
               ' wheel touches its flange beyond the flange''s steepest part (wheel profile '// &
               'y = '//str_format(t%wheel_y(k), '(f0.3)')//' mm; the steep part ends at '// &
               str_format(steepest, '(f0.3)')//' mm; contact angle '// &
               str_format(t%gamma(k), '(f0.4)')//' rad): the rigid wheelset shifts further '// &
               'only by climbing the flange, so these rows are flange-climbing states'
         end associate
         call put_line('# '//line)
         if (.not. quiet) write (error_unit, '(a)') 'shcontact: '//line
      end do
   end subroutine note_climbing

   !> A note for each conicity amplitude that reaches flange contact (a contact angle above
   !> 0.5 rad within ±A): EN 15302 defines the equivalent conicity within the flangeway clearance.
   subroutine note_flange_amplitudes(table, amplitudes, quiet)
      type(wheelset_contact_type), intent(in) :: table(:)
      real(wp), intent(in) :: amplitudes(:)
      logical, intent(in) :: quiet
      real(wp), parameter :: flange_angle = 0.5_wp
      real(wp) :: onset
      character(len=:), allocatable :: line
      integer :: k, i
      onset = huge(1.0_wp)
      do i = 1, size(table)
         if (maxval(abs(table(i)%gamma)) > flange_angle) onset = min(onset, abs(table(i)%y))
      end do
      do k = 1, size(amplitudes)
         if (amplitudes(k) < onset) cycle
         line = 'note: amplitude '//str_format(amplitudes(k), '(f0.3)')//' mm reaches '// &
            'flange contact (a contact angle above '//str_format(flange_angle, '(f0.1)')// &
            ' rad from |y| = '//str_format(onset, '(f0.3)')//' mm): EN 15302 defines the '// &
            'equivalent conicity within the flangeway clearance'
         call put_line('# '//line)
         if (.not. quiet) write (error_unit, '(a)') 'shcontact: '//line
      end do
   end subroutine note_flange_amplitudes

   !> 0 for values that print as ±0.00000 (5 decimals), so that y = 0 shows no "-0.00000".
   elemental real(wp) function tidy(x)
      real(wp), intent(in) :: x
      tidy = merge(0.0_wp, x, abs(x) < 5.0e-6_wp)
   end function tidy

end module shcontact_app_wheelset
