!> The results summary as text: a readable block or table (`text`), one CSV line per case
!> (`csv`, with a header line and optionally a units line), or one JSON object per line
!> (`json`, JSON Lines). The library builds the lines; the program prints them.
!>
!> CSV and JSON lines carry every input of the case that the mode uses, swept or not (t_y, roll,
!> the load of the load mode, friction, bound, and the creepages and spin model, or in
!> kinematic mode the wheelset inputs), so that lines of separate runs (a shell loop over
!> `--set`) line up under one header and say what they are.
module shcontact_output_report
   use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   use shcontact_input_config, only: case_config_type, case_point_type, n_sweep_axes, &
      sweep_axis_names, case_point_value, case_point_label, is_kinematic_input, &
      load_mode_force, load_mode_approach, load_mode_vertical, load_mode_shared
   use shcontact_core_text, only: format_real, format_real_buffer, json_string, string_type
   use shcontact_case_result, only: case_summary_type, summary_columns, n_summary_columns, &
      summary_value, summary_column_used, failure_type, summary_column_counts
   implicit none
   private

   public :: report_formats, report_header, report_line, report_lines, report_case_text, &
      report_units
   public :: reports_case_input

   !> Accepted values of the format.
   character(len=*), parameter :: report_formats(4) = [character(len=4) :: 'text', 'csv', &
      'json', 'none']

   !> Columns shown in the text table of a sweep (besides the swept inputs): the main patch's,
   !> then the f of the wheel's joined contact (the exact theory's, doc/lobes.md).
   character(len=*), parameter :: text_columns(9) = [character(len=17) :: 'fn', 'fx', 'fy', &
      'mz', 'fx_norm', 'fy_norm', 'adhesion_fraction', 'wheel_fx_norm', 'wheel_fy_norm']
   !> The same for a kinematic run: the patches found and loaded, the track-frame totals, the
   !> main patch's creepages and lead, and the f of the wheel's joined contact.
   character(len=*), parameter :: kinematic_text_columns(12) = [character(len=17) :: &
      'n_patches', 'n_loaded', 'fn_total', 'fx_total', 'fy_total', 'fz_total', 'nu_x', 'nu_y', &
      'phi', 'x_track', 'wheel_fx_norm', 'wheel_fy_norm']
   !> Units of the inputs, indexed as [[sweep_axis_names]] ('' for the choices).
   character(len=*), parameter :: input_units(n_sweep_axes) = [character(len=6) :: 'mm', &
      'rad', 'rad', 'N', 'mm', 'N', '1', '', '', 'mm/s', 'mm/s', 'mm/s', 'rad/s', 'rad/s', &
      'rad/s', '1', '1', 'rad/mm']

contains

   !> The line before the per-case lines ('' when the format has none).
   function report_header(config, format) result(line)
      !> The configuration (which inputs are swept).
      type(case_config_type), intent(in) :: config
      !> 'text', 'csv' or 'json'.
      character(len=*), intent(in) :: format
      character(len=:), allocatable :: line, units
      integer :: ia, k
      select case (format)
      case ('csv')
         line = 'case,status,n_patches,n_loaded,main_patch'
         do ia = 1, n_sweep_axes
            if (reports_case_input(config, ia)) line = line//','//trim(sweep_axis_names(ia))
         end do
         do k = 1, n_summary_columns
            if (summary_column_used(k, config%is_kinematic())) &
               line = line//','//trim(summary_columns(1, k))
         end do
         line = line//',message'
      case ('text')
         line = ''
         if (config%n_cases() == 1) return
         ! The names, then their units in brackets ([1]: dimensionless or a count).
         line = pad('case', 8)//pad('status', 7)
         units = pad('', 8)//pad('', 7)
         do ia = 1, n_sweep_axes
            if (.not. config%sweep%axes(ia)%active) cycle
            line = line//pad(trim(sweep_axis_names(ia)), 14)
            units = units//pad(bracketed(input_units(ia)), 14)
         end do
         if (config%is_kinematic()) then
            ! The counts first (not summary columns), then the summary's own.
            do k = 1, size(kinematic_text_columns)
               line = line//pad(trim(kinematic_text_columns(k)), &
                  column_width(kinematic_text_columns(k)))
               if (k <= 2) then
                  units = units//pad('[1]', column_width(kinematic_text_columns(k)))
               else
                  units = units//pad(bracketed(summary_columns(2, &
                     column_index(kinematic_text_columns(k)))), &
                     column_width(kinematic_text_columns(k)))
               end if
            end do
         else
            do k = 1, size(text_columns)
               line = line//pad(trim(text_columns(k)), column_width(text_columns(k)))
               units = units//pad(bracketed(summary_columns(2, column_index(text_columns(k)))), &
                  column_width(text_columns(k)))
            end do
         end if
         line = trim(line)//new_line('a')//trim(units)
      case default
         line = ''
      end select
   end function report_header

   !> The units line that may follow the CSV header: the unit of each column ('1' for
   !> dimensionless numbers, counts and codes, empty for the choices and the message).
   function report_units(config) result(line)
      !> The configuration (which columns there are).
      type(case_config_type), intent(in) :: config
      character(len=:), allocatable :: line
      integer :: ia, k
      line = '1,1,1,1,1'
      do ia = 1, n_sweep_axes
         if (reports_case_input(config, ia)) line = line//','//trim(input_units(ia))
      end do
      do k = 1, n_summary_columns
         if (summary_column_used(k, config%is_kinematic())) &
            line = line//','//trim(summary_columns(2, k))
      end do
      line = line//','
   end function report_units

   !> Whether the CSV and JSON lines carry input `ia` (numbering of [[sweep_axis_names]]):
   !> every input the mode uses, swept or not, and the load of the load mode only.
   pure logical function reports_case_input(config, ia)
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> Input index.
      integer, intent(in) :: ia
      character(len=:), allocatable :: name
      name = trim(sweep_axis_names(ia))
      reports_case_input = config%reports_input(ia)
      if (reports_case_input) return
      select case (name)
      case ('t_y', 'roll', 'friction', 'bound')
         reports_case_input = .true.
      case ('normal_force')
         reports_case_input = config%load%mode == load_mode_force .or. &
            config%load%mode == load_mode_shared
      case ('approach')
         reports_case_input = config%load%mode == load_mode_approach
      case ('vertical_force')
         reports_case_input = config%load%mode == load_mode_vertical
      case ('spin_model', 'nu_x', 'nu_y', 'phi')
         reports_case_input = .not. config%is_kinematic()
      case default
         reports_case_input = config%is_kinematic() .and. is_kinematic_input(name)
      end select
   end function reports_case_input

   !> One line for case `icase`.
   function report_line(config, icase, summary, format, message) result(line)
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> Case number.
      integer, intent(in) :: icase
      !> Its summary.
      type(case_summary_type), intent(in) :: summary
      !> 'text', 'csv' or 'json'.
      character(len=*), intent(in) :: format
      !> Why it failed (failed cases).
      character(len=*), intent(in), optional :: message
      character(len=:), allocatable :: line
      call report_line_into(config, icase, summary, format, line, message)
   end function report_line

   !> [[report_line]] as a subroutine: what [[report_lines]]' threads call (a function with a
   !> deferred-length result may not be called by threads; doc/performance.md, "Threads and
   !> strings"); nothing it calls returns one.
   subroutine report_line_into(config, icase, summary, format, line, message)
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> Case number.
      integer, intent(in) :: icase
      !> Its summary.
      type(case_summary_type), intent(in) :: summary
      !> 'text', 'csv' or 'json'.
      character(len=*), intent(in) :: format
      !> The line.
      character(len=:), allocatable, intent(out) :: line
      !> Why it failed (failed cases).
      character(len=*), intent(in), optional :: message
      character(len=:), allocatable :: value
      type(case_point_type) :: p
      integer :: ia, k
      logical :: ok

      p = config%case_point(icase)
      ok = summary%stat == 0
      select case (format)
      case ('csv')
         line = str_int(icase)//','//str_int(summary%stat)//','// &
            str_int(summary%n_patches)//','//str_int(summary%n_loaded)//','// &
            str_int(summary%main_patch)
         do ia = 1, n_sweep_axes
            if (reports_case_input(config, ia)) line = line//','// &
               trim(input_buffer(p, ia, .false., .false.))
         end do
         do k = 1, n_summary_columns
            if (.not. summary_column_used(k, config%is_kinematic())) cycle
            value = ''
            if (ok) call append_column(value, summary, k, .false.)
            line = line//','//value
         end do
         line = line//','
         if (present(message)) line = line//csv_quoted(message)
      case ('json')
         line = '{"case":'//str_int(icase)//',"status":'//str_int(summary%stat)// &
            ',"n_patches":'//str_int(summary%n_patches)//',"n_loaded":'// &
            str_int(summary%n_loaded)//',"main_patch":'//str_int(summary%main_patch)
         do ia = 1, n_sweep_axes
            if (reports_case_input(config, ia)) line = line//',"'//trim(sweep_axis_names(ia))// &
               '":'//trim(input_buffer(p, ia, .true., .false.))
         end do
         do k = 1, n_summary_columns
            if (.not. summary_column_used(k, config%is_kinematic())) cycle
            line = line//',"'//trim(summary_columns(1, k))//'":'
            if (ok) then
               call append_column(line, summary, k, .true.)
            else
               line = line//'null'
            end if
         end do
         ! Every line has the same keys: a solved case's message is null.
         if (present(message)) then
            line = line//',"message":'//json_string(message)
         else
            line = line//',"message":null'
         end if
         line = line//'}'
      case default
         line = pad(str_int(icase), 8)//pad(str_int(summary%stat), 7)
         do ia = 1, n_sweep_axes
            if (config%sweep%axes(ia)%active) line = line// &
               pad(trim(input_buffer(p, ia, .false., .true.)), 14)
         end do
         if (ok .and. config%is_kinematic()) then
            line = line//pad(str_int(summary%n_patches), column_width(kinematic_text_columns(1)))// &
               pad(str_int(summary%n_loaded), column_width(kinematic_text_columns(2)))
            do k = 3, size(kinematic_text_columns)
               line = line//pad(trim(short_buffer(summary_value(summary, &
                  column_index(kinematic_text_columns(k))))), &
                  column_width(kinematic_text_columns(k)))
            end do
         else if (ok) then
            do k = 1, size(text_columns)
               line = line//pad(trim(short_buffer(summary_value(summary, &
                  column_index(text_columns(k))))), column_width(text_columns(k)))
            end do
         else if (present(message)) then
            line = line//message
         end if
         line = trim(line)
      end select
   end subroutine report_line_into

   !> The report lines ([[report_line]]) of consecutive cases `first`, `first + 1`, ..., built
   !> by `threads` threads (issue 27): formatting a case's line costs about 20 µs, most of
   !> what solving a DOE case costs, so one thread made it a serial tail of a parallel run.
   !> The same lines as [[report_line]]'s, case by case (test `app/report_lines_threads`).
   subroutine report_lines(config, first, summaries, failures, format, threads, lines)
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> Case number of the first summary.
      integer, intent(in) :: first
      !> Summaries of the cases `first`, `first + 1`, ...
      type(case_summary_type), intent(in) :: summaries(:)
      !> The failed cases of the run and their messages (any order; others are ignored).
      type(failure_type), intent(in) :: failures(:)
      !> 'text', 'csv' or 'json'.
      character(len=*), intent(in) :: format
      !> OpenMP threads to use.
      integer, intent(in) :: threads
      !> One line per summary (at least size(summaries) elements).
      type(string_type), intent(inout) :: lines(:)
      integer, allocatable :: failure_of(:)
      integer :: i, k
      allocate (failure_of(size(summaries)), source=0)
      do k = 1, size(failures)
         i = failures(k)%case - first + 1
         if (i >= 1 .and. i <= size(summaries)) failure_of(i) = k
      end do
      !$omp parallel do default(none) schedule(dynamic, 64) num_threads(threads) &
      !$omp shared(config, first, summaries, failures, format, lines, failure_of) private(i)
      do i = 1, size(summaries)
         if (summaries(i)%stat > 0 .and. failure_of(i) > 0) then
            call report_line_into(config, first + i - 1, summaries(i), format, lines(i)%text, &
               failures(failure_of(i))%message)
         else
            call report_line_into(config, first + i - 1, summaries(i), format, lines(i)%text)
         end if
      end do
      !$omp end parallel do
   end subroutine report_lines

   !> A readable block for a single case (text format).
   function report_case_text(config, summary) result(text)
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> The summary of the case.
      type(case_summary_type), intent(in) :: summary
 character(len=:), allocatable :: text, inputs
      character(len=1), parameter :: nl = new_line('a')
      type(case_point_type) :: p
      associate (s => summary)
         if (config%is_kinematic()) then
            p = config%case_point(1)
            inputs = 'wheelset   t_y = '//format_real(p%t_y)//' mm, roll = '// &
               format_real(p%roll)//' rad, yaw = '//format_real(p%yaw)//' rad; V = '// &
               short_real(p%v_forward)//' mm/s, pitch rate = '//short_real(p%pitch_rate)// &
               ' rad/s'//velocity_text(p)//nl// &
               'creepages  nu_x = '//short_real(s%nu_x)//', nu_y = '//short_real(s%nu_y)// &
               ', phi = '//short_real(s%phi)//' rad/mm at the main patch (from the wheelset '// &
               'motion), lead x = '//short_real(s%x_track)//' mm; mu = '// &
               format_real(config%material%friction)//nl
         else
            inputs = 'creepages  nu_x = '//format_real(config%creepage%nu_x)//', nu_y = '// &
               format_real(config%creepage%nu_y)//', phi = '//format_real(config%creepage%phi)// &
               ' rad/mm; mu = '//format_real(config%material%friction)//nl
         end if
         text = 'wheel '//trim(config%profiles%wheel)//' on rail '//trim(config%profiles%rail)// &
            ', t_y = '//format_real(config%position%t_y)//' mm'//nl//inputs// &
            'contact    '//str_int(s%n_patches)//' patch(es) found, '//str_int(s%n_loaded)// &
            ' loaded; main patch '//str_int(s%main_patch)//': gamma0 = '// &
            short_real(s%gamma0)//' rad, r0 = '//short_real(s%r0)//' mm, y_track = '// &
            short_real(s%y_track)//' mm'//nl// &
            'normal     Fn = '//short_real(s%fn)//' N, approach = '//short_real(s%approach)// &
            ' mm, area = '//short_real(s%area)//' mm^2, p_max = '//short_real(s%p_max)// &
            ' MPa'//nl// &
            'tangential Fx = '//short_real(s%fx)//' N, Fy = '//short_real(s%fy)//' N, Mz = '// &
            short_real(s%mz)//' N mm (forces on the wheel)'//nl// &
            '           fx = '//short_real(s%fx_norm)//', fy = '//short_real(s%fy_norm)// &
            ' (F/(mu Fn)); adhesion fraction '//short_real(s%adhesion_fraction)// &
            ', Coulomb ratio '//short_real(s%coulomb_ratio)//nl// &
            'total      Fx = '//short_real(s%fx_total)//' N, Fy = '//short_real(s%fy_total)// &
            ' N, Fz = '//short_real(s%fz_total)//' N, Fn = '//short_real(s%fn_total)// &
            ' N (all patches, on the wheel, track frame: y to the field side, z down)'//nl// &
            'wheel      '//str_int(s%wheel%n_members)//' patch(es) joined (within 4 mm: the '// &
            'exact theory''s one patch): Fn = '//short_real(s%wheel%fn)//' N, Fx = '// &
            short_real(s%wheel%fx)//' N, Fy = '//short_real(s%wheel%fy)//' N, fx = '// &
            short_real(s%wheel%fx_norm)//', fy = '//short_real(s%wheel%fy_norm)// &
            ' (sum F/(mu sum Fn))'
      end associate
   end function report_case_text

   !> ", v_y = ..." for the velocities and rates that are not zero.
   function velocity_text(p) result(text)
      type(case_point_type), intent(in) :: p
      character(len=:), allocatable :: text
      text = ''
      if (p%v_lateral /= 0.0_wp) text = text//', v_lateral = '//short_real(p%v_lateral)//' mm/s'
      if (p%v_vertical /= 0.0_wp) text = text//', v_vertical = '//short_real(p%v_vertical)// &
         ' mm/s'
      if (p%roll_rate /= 0.0_wp) text = text//', roll rate = '//short_real(p%roll_rate)// &
         ' rad/s'
      if (p%yaw_rate /= 0.0_wp) text = text//', yaw rate = '//short_real(p%yaw_rate)//' rad/s'
   end function velocity_text

   !> [[input_text]]'s text, left-aligned in a fixed buffer.
   pure function input_buffer(p, ia, json, short) result(buffer)
      type(case_point_type), intent(in) :: p
      integer, intent(in) :: ia
      logical, intent(in) :: json, short
      character(len=64) :: buffer
      real(wp) :: x
      select case (trim(sweep_axis_names(ia)))
      case ('bound', 'spin_model')
         if (json) then
            buffer = json_string(case_point_label(p, ia))
         else
            buffer = case_point_label(p, ia)
         end if
         return
      case default
         x = case_point_value(p, ia)
      end select
      if (short) then
         buffer = short_buffer(x)
      else
         buffer = format_real_buffer(x)
      end if
   end function input_buffer

   !> A swept input of a case as text (quoted for JSON when it is a choice); `short`: five
   !> significant digits instead of the exact value. (No deferred-length results in what the
   !> report lines call: they are formatted by threads; doc/performance.md, "Threads and
   !> strings".)
   pure function input_text(p, ia, json, short) result(text)
      type(case_point_type), intent(in) :: p
      integer, intent(in) :: ia
      logical, intent(in) :: json, short
      character(len=len_trim(input_buffer(p, ia, json, short))) :: text
      text = input_buffer(p, ia, json, short)
   end function input_text

   !> [[json_number]]'s text, left-aligned in a fixed buffer.
   pure function json_number_buffer(x) result(buffer)
      real(wp), intent(in) :: x
      character(len=40) :: buffer
      if (ieee_is_finite(x)) then
         buffer = format_real_buffer(x)
      else
         buffer = 'null'
      end if
   end function json_number_buffer

   !> A number as JSON: `null` for NaN or an infinity (JSON has no such numbers).
   pure function json_number(x) result(text)
      real(wp), intent(in) :: x
      character(len=len_trim(json_number_buffer(x))) :: text
      text = json_number_buffer(x)
   end function json_number

   pure integer function column_index(name)
      character(len=*), intent(in) :: name
      integer :: k
      column_index = 1
      do k = 1, n_summary_columns
         if (summary_columns(1, k) == name) column_index = k
      end do
   end function column_index

   !> A unit in brackets for the text table's units line ('' for a choice).
   pure function bracketed(unit) result(text)
      character(len=*), intent(in) :: unit
      character(len=:), allocatable :: text
      text = ''
      if (len_trim(unit) > 0) text = '['//trim(unit)//']'
   end function bracketed

   !> [[short_real]]'s text, left-aligned in a fixed buffer.
   pure function short_buffer(x) result(buf)
      real(wp), intent(in) :: x
      character(len=24) :: buf
      integer :: n
      if (x == 0.0_wp) then
         buf = '0'
         return
      end if
      write (buf, '(1p,g14.5e2)') x
      buf = adjustl(buf)
      n = len_trim(buf)
      if (buf(n:n) == '.') buf(n:n) = ' '
   end function short_buffer

   !> Five significant digits, for reading (one formatted write: tables of sweeps are long).
   pure function short_real(x) result(text)
      real(wp), intent(in) :: x
      character(len=len_trim(short_buffer(x))) :: text
      text = short_buffer(x)
   end function short_real

   !> Width of a result column of the text table: 14, or its name and a blank when longer
   !> (`adhesion_fraction`), so that the header, the units and the values line up.
   pure integer function column_width(name)
      character(len=*), intent(in) :: name
      column_width = max(14, len_trim(name) + 1)
   end function column_width

   pure function pad(text, width) result(padded)
      character(len=*), intent(in) :: text
      integer, intent(in) :: width
      character(len=max(width, len(text) + 1)) :: padded
      padded = text
   end function pad

   !> Double quotes in the text (before its trailing blanks).
   pure integer function quote_count(text)
      character(len=*), intent(in) :: text
      integer :: i
      quote_count = 0
      do i = 1, len_trim(text)
         if (text(i:i) == '"') quote_count = quote_count + 1
      end do
   end function quote_count

   !> A CSV field in double quotes (embedded quotes doubled).
   pure function csv_quoted(text) result(q)
      character(len=*), intent(in) :: text
      character(len=2 + len_trim(text) + quote_count(text)) :: q
      integer :: i, at
      q(1:1) = '"'
      at = 1
      do i = 1, len_trim(text)
         if (text(i:i) == '"') then
            q(at + 1:at + 1) = '"'
            at = at + 1
         end if
         q(at + 1:at + 1) = text(i:i)
         at = at + 1
      end do
      q(at + 1:at + 1) = '"'
   end function csv_quoted

   !> Append summary column `k` to a CSV or JSON line: a count as an integer (as n_loaded is),
   !> any other value as a real. A subroutine, not a function with a deferred-length result:
   !> the sweep's threads build report lines (doc/performance.md, "Threads and strings").
   subroutine append_column(line, summary, k, json)
      character(len=:), allocatable, intent(inout) :: line
      type(case_summary_type), intent(in) :: summary
      integer, intent(in) :: k
      logical, intent(in) :: json
      if (summary_column_counts(k)) then
         line = line//str_int(nint(summary_value(summary, k)))
      else if (json) then
         line = line//trim(json_number_buffer(summary_value(summary, k)))
      else
         line = line//trim(format_real_buffer(summary_value(summary, k)))
      end if
   end subroutine append_column

end module shcontact_output_report
