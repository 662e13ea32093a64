!> `shcontact profiles`: check, clean and export a measured profile (`profiles FILE [-o OUT]
!> [--plot SCRIPT.gp]`), or write the built-in profiles (`profiles --write DIR`).
!>
!> A profile file goes through the library's `load_profile`, exactly as a case reads it (reader,
!> clean-up, plausibility checks), so a file this command accepts is a file a case accepts, and
!> its messages are the ones a run would give.
module shcontact_app_profiles
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_io, stat_usage
   use shcontact_core_strings, only: str_int
   use shcontact_core_files, only: make_directory, join_path, canonical_path
   use shcontact, only: profile_type, profile_kind_wheel, profile_kind_rail, &
      profile_file_format, load_profile => load_profile_file, write_profile_plain, &
      write_builtin_profiles, written_builtins
   use shcontact_app_cli, only: cli_type
   use shcontact_app_commands, only: report_error
   use shcontact_app_profile_advice, only: profile_advice
   use shcontact_app_output_guard, only: check_output_file, same_file
   use shcontact_app_stdout, only: put_line
   implicit none
   private

   public :: profiles_command

contains

   !> `shcontact profiles FILE [-o OUT] [--plot SCRIPT]` or `shcontact profiles --write DIR`.
   integer function profiles_command(cli) result(status)
      !> The command line.
      type(cli_type), intent(in) :: cli
      type(error_type), allocatable :: error
      type(profile_type) :: read, cleaned
      integer :: k
      status = 0
      if (len(cli%write_dir) > 0) then
         call make_directory(cli%write_dir, error)
         do k = 1, size(written_builtins)
            if (.not. allocated(error)) call check_output_file(join_path(cli%write_dir, &
               trim(written_builtins(k))//'.txt'), 'the file of --write', cli%force, [''], error)
         end do
         if (.not. allocated(error)) call write_builtin_profiles(cli%write_dir, error)
         if (allocated(error)) then
            status = report_error(error)
            return
         end if
         if (.not. cli%quiet) write (error_unit, '(a)') 'shcontact: built-in profiles '// &
            'written to '//cli%write_dir
         return
      end if

      call check_outputs(cli, error)
      if (.not. allocated(error)) call load_file(cli, read, cleaned, error)
      if (.not. allocated(error) .and. len(cli%output) > 0) &
         call write_profile_plain(cleaned, cli%output, error)
      if (.not. allocated(error) .and. len(cli%plot_file) > 0) &
         call write_gnuplot_script(cli%plot_file, read, cleaned, error)
      if (allocated(error)) then
         status = report_error(error)
         return
      end if
      if (.not. cli%quiet) call put_line(profile_summary(cli, read, cleaned)// &
         new_line('a')//profile_advice(read, cleaned))
   end function profiles_command

   !> -o OUT and --plot SCRIPT: neither the profile read, nor one another, nor (without --force)
   !> a file that exists.
   subroutine check_outputs(cli, error)
      type(cli_type), intent(in) :: cli
      type(error_type), allocatable, intent(out) :: error
      if (len(cli%output) > 0 .and. len(cli%plot_file) > 0) then
         if (cli%output == cli%plot_file .or. same_file(cli%output, cli%plot_file)) then
            call fatal_error(error, cli%output//': -o and --plot name the same file; give '// &
               'them different names', stat_usage)
            return
         end if
      end if
      if (len(cli%output) > 0) call check_output_file(cli%output, '-o', cli%force, &
         [cli%profile_file], error)
      if (allocated(error)) return
      if (len(cli%plot_file) > 0) call check_output_file(cli%plot_file, '--plot', cli%force, &
         [cli%profile_file], error)
   end subroutine check_outputs

   !> The points as read (canonical form, not cleaned) and the profile a case would use.
   subroutine load_file(cli, read, cleaned, error)
      type(cli_type), intent(in) :: cli
      type(profile_type), intent(out) :: read, cleaned
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: kind
      real(wp), allocatable :: scale
      logical, allocatable :: mirror_y, mirror_z
      ! Unallocated, they are absent arguments: the file (or its extension) decides.
      if (cli%kind == 'wheel') kind = profile_kind_wheel
      if (cli%kind == 'rail') kind = profile_kind_rail
      if (cli%scale > 0.0_wp) scale = cli%scale
      if (len(cli%mirror_y) > 0) mirror_y = cli%mirror_y == 'yes'
      if (len(cli%mirror_z) > 0) mirror_z = cli%mirror_z == 'yes'
      call load_profile(cli%profile_file, kind, cleaned, error, cli%file_format, &
         mirror_y=mirror_y, mirror_z=mirror_z, scale=scale, option_prefix='--', as_read=read)
   end subroutine load_file

   !> What was read and what the clean-up made of it.
   function profile_summary(cli, read, cleaned) result(text)
      type(cli_type), intent(in) :: cli
      type(profile_type), intent(in) :: read, cleaned
      character(len=:), allocatable :: text, units
      character(len=1), parameter :: nl = new_line('a')
      if (cli%scale > 0.0_wp) then
         units = 'mm (file lengths x '//mm(cli%scale)//', --scale)'
      else if (profile_file_format(cli%profile_file, cli%file_format) == 'simpack') then
         units = 'mm (file lengths scaled by its units.len.f; mm when it has none)'
      else
         units = 'mm (as in the file; --scale F converts other units)'
      end if
      text = 'profile    '//cli%profile_file//': '//kind_name(cleaned%kind)//', format '// &
         profile_file_format(cli%profile_file, cli%file_format)//nl// &
         'points     '//str_int(read%size())//' read, '//str_int(cleaned%size())// &
         ' after clean-up (zig-zags merged, points on a chord dropped, straight pieces '// &
         'sampled evenly)'//nl// &
         'y          '//mm(minval(cleaned%y))//' to '//mm(maxval(cleaned%y))// &
         ' mm (right side, towards the field side)'//nl// &
         'z          '//mm(minval(cleaned%z))//' to '//mm(maxval(cleaned%z))// &
         ' mm (downward)'//nl// &
         'arc length '//mm(cleaned%s(cleaned%size()))//' mm'//nl// &
         'units      '//units//nl// &
         'checks     passed (point order, duplicates, loops, arc length, spikes, running '// &
         'surface)'
      ! The path a case file anywhere reads it by (a relative name is taken from the case
      ! file's folder, not from the working directory).
      if (len(cli%output) > 0) text = text//nl//'written    '//cli%output// &
         ' (y z in mm, z down; a case reads it as '//kind_name(cleaned%kind)//' = '''// &
         canonical_path(cli%output)//''')'
      if (len(cli%output) > 0 .and. cleaned%origin_at_flange_back) text = text//nl// &
         '           y moved by -70 mm: origin from the flange back (MiniProf) to the tape '// &
         'circle, where a plain file has it'
      if (len(cli%plot_file) > 0) text = text//nl//'plot       '//cli%plot_file// &
         ' (gnuplot '//cli%plot_file//' writes '//png_name(cli%plot_file)//')'
   end function profile_summary

   pure function kind_name(kind) result(text)
      integer, intent(in) :: kind
      character(len=:), allocatable :: text
      text = 'rail'
      if (kind == profile_kind_wheel) text = 'wheel'
   end function kind_name

   !> A length with three decimals.
   pure function mm(x) result(text)
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=32) :: buf
      write (buf, '(f0.3)') x
      text = trim(adjustl(buf))
      if (text(1:1) == '.') text = '0'//text
      if (text(1:2) == '-.') text = '-0'//text(2:)
   end function mm

   !> SCRIPT.gp → SCRIPT.png.
   pure function png_name(script) result(name)
      character(len=*), intent(in) :: script
      character(len=:), allocatable :: name
      integer :: dot
      dot = index(script, '.', back=.true.)
      if (dot > index(script, '/', back=.true.) + 1) then
         name = script(1:dot - 1)//'.png'
      else
         name = script//'.png'
      end if
   end function png_name

   !> A gnuplot script holding both point lists (no data files beside it): the points read as
   !> dots, the cleaned profile as a line, z downward, equal axes.
   subroutine write_gnuplot_script(script, read, cleaned, error)
      character(len=*), intent(in) :: script
      type(profile_type), intent(in) :: read, cleaned
      type(error_type), allocatable, intent(out) :: error
      character(len=256) :: message
      integer :: unit, stat
      open (newunit=unit, file=script, status='replace', action='write', iostat=stat, &
         iomsg=message)
      if (stat /= 0) then
         call fatal_error(error, script//': cannot create the file: '//trim(message), stat_io)
         return
      end if
      write (unit, '(a)', iostat=stat, iomsg=message) &
         '# Written by shcontact profiles: gnuplot '//script//' writes '//png_name(script), &
         'if (strstrt(GPVAL_TERMINALS, "pngcairo") > 0) {', &
         '    set terminal pngcairo size 1200,600', &
         '} else {', &
         '    set terminal png size 1200,600', &
         '}', &
         "set output '"//png_name(script)//"'", &
         "set title '"//kind_name(cleaned%kind)//' profile '//gnuplot_quoted(cleaned%source)// &
         "'", &
         "set xlabel 'y (mm, towards the field side)'", &
         "set ylabel 'z (mm, downward)'", &
         'set yrange [*:*] reverse', &
         'set size ratio -1', &
         'set grid', &
         'set key bottom right'
      if (stat == 0) call write_points(unit, '$read', read, stat, message)
      if (stat == 0) call write_points(unit, '$cleaned', cleaned, stat, message)
      if (stat == 0) write (unit, '(a)', iostat=stat, iomsg=message) &
         "plot $read with points pt 7 ps 0.5 title 'points read ("//str_int(read%size())// &
         ")', \", &
         "     $cleaned with lines lw 2 title 'cleaned ("//str_int(cleaned%size())//")'"
      if (stat /= 0) then
         close (unit)
         call fatal_error(error, script//': cannot write the file: '//trim(message), stat_io)
         return
      end if
      close (unit)
   end subroutine write_gnuplot_script

   subroutine write_points(unit, name, profile, stat, message)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      type(profile_type), intent(in) :: profile
      integer, intent(out) :: stat
      character(len=*), intent(inout) :: message
      integer :: i
      write (unit, '(a)', iostat=stat, iomsg=message) name//' << EOD'
      do i = 1, profile%size()
         if (stat /= 0) return
         write (unit, '(2es23.14e3)', iostat=stat, iomsg=message) profile%y(i), profile%z(i)
      end do
      if (stat == 0) write (unit, '(a)', iostat=stat, iomsg=message) 'EOD'
   end subroutine write_points

   !> A text for a single-quoted gnuplot string (quotes doubled).
   pure function gnuplot_quoted(text) result(q)
      character(len=*), intent(in) :: text
      character(len=:), allocatable :: q
      integer :: i
      q = ''
      do i = 1, len(text)
         if (text(i:i) == "'") q = q//"'"
         q = q//text(i:i)
      end do
   end function gnuplot_quoted

end module shcontact_app_profiles
