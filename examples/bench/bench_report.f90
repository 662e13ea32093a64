!> Output of the benchmark: section titles, one line per timed item, the machine's load and CPU,
!> number formatting, and the stop on a library error (the benchmark, unlike the library, stops).
module bench_report
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact, only: wp, error_type
   use bench_timing, only: kernel_type, timing_type
   implicit none
   private

   public :: section, report, triple, real_text, verdict, print_load, cpu_model, &
      stop_on, fail

contains

   !> A section title, after an empty line.
   subroutine section(title)
      !> The title.
      character(len=*), intent(in) :: title
      write (output_unit, '(/,a)') '== '//title
   end subroutine section

   !> One line: label, median [min, max] in microseconds, batch size and runs.
   subroutine report(kernel, t, label)
      !> The kernel timed (stops when it failed).
      class(kernel_type), intent(in) :: kernel
      !> Its timing.
      type(timing_type), intent(in) :: t
      !> What was timed.
      character(len=*), intent(in) :: label
      if (kernel%failed) call fail(label//': '//kernel%message)
      write (output_unit, '(2x,a,t70,a,a,i0,a,i0,a)') label, triple(t), '  (', t%batch, &
         ' calls x ', t%runs, ')'
   end subroutine report

   !> "median [min, max]" in microseconds.
   function triple(t) result(text)
      !> The timing.
      type(timing_type), intent(in) :: t
      character(len=21) :: text
      write (text, '(f7.2,a,f5.1,a,f5.1,a)') 1.0e6_wp*t%median, ' [', 1.0e6_wp*t%min, ',', &
         1.0e6_wp*t%max, ']'
      if (t%median >= 1.0e-4_wp) write (text, '(f7.0,a,f5.0,a,f5.0,a)') 1.0e6_wp*t%median, &
         ' [', 1.0e6_wp*t%min, ',', 1.0e6_wp*t%max, ']'
   end function triple

   !> A real as text with six significant digits.
   pure function real_text(x) result(text)
      !> The number.
      real(wp), intent(in) :: x
      character(len=:), allocatable :: text
      character(len=24) :: buf
      write (buf, '(g0.6)') x
      text = trim(adjustl(buf))
   end function real_text

   !> "met" or "NOT met".
   pure function verdict(met) result(text)
      !> Whether the target is met.
      logical, intent(in) :: met
      character(len=:), allocatable :: text
      if (met) then
         text = 'met'
      else
         text = 'NOT met'
      end if
   end function verdict

   !> /proc/loadavg: the machine is shared, so the load is part of every figure.
   subroutine print_load(label)
      !> What the line says before the load.
      character(len=*), intent(in) :: label
      character(len=128) :: line
      integer :: unit, stat
      line = 'unknown'
      open (newunit=unit, file='/proc/loadavg', status='old', action='read', iostat=stat)
      if (stat == 0) then
         read (unit, '(a)', iostat=stat) line
         close (unit)
      end if
      write (output_unit, '(a)') label//' (1, 5, 15 min): '//trim(line)
   end subroutine print_load

   !> The first "model name" of /proc/cpuinfo.
   subroutine cpu_model(model)
      !> The CPU model, or "unknown CPU".
      character(len=*), intent(out) :: model
      character(len=512) :: line
      integer :: unit, stat, c
      model = 'unknown CPU'
      open (newunit=unit, file='/proc/cpuinfo', status='old', action='read', iostat=stat)
      if (stat /= 0) return
      do
         read (unit, '(a)', iostat=stat) line
         if (stat /= 0) exit
         if (index(line, 'model name') /= 1) cycle
         c = index(line, ':')
         model = adjustl(line(c + 1:))
         exit
      end do
      close (unit)
   end subroutine cpu_model

   !> Stop with the library's message when the call reported an error.
   subroutine stop_on(error, what)
      !> The library's error, if any.
      type(error_type), allocatable, intent(in) :: error
      !> The call that reported it.
      character(len=*), intent(in) :: what
      if (allocated(error)) call fail(what//': '//error%message)
   end subroutine stop_on

   !> Write the message on stderr and stop with status 1.
   subroutine fail(message)
      !> The message.
      character(len=*), intent(in) :: message
      write (error_unit, '(a)') 'shcontact-bench: '//message
      error stop 1
   end subroutine fail

end module bench_report
