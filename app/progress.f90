!> Progress of a run on stderr: a bar with the ETA on a terminal; in a batch log (stderr not a
!> terminal) a line `shcontact: progress: D of N cases (P %), R cases/s, elapsed E, ETA T`
!> at every tenth of the cases and at least every 10 s; nothing with -q.
module shcontact_app_progress
   use, intrinsic :: iso_fortran_env, only: error_unit
   use, intrinsic :: iso_c_binding, only: c_int
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_int
   use shcontact, only: wall_seconds
   use shcontact_app_environment, only: integer_variable
   implicit none
   private

   public :: start_progress, progress, end_progress, elapsed, run_seconds

   interface
      function c_isatty(fd) bind(c, name='isatty') result(yes)
         import :: c_int
         integer(c_int), value :: fd
         integer(c_int) :: yes
      end function c_isatty
   end interface

   !> Seconds between two lines in a batch log, at most.
   real(wp), parameter :: line_interval = 10.0_wp
   !> Seconds between two redraws of the bar, at least.
   real(wp), parameter :: bar_interval = 0.2_wp

   ! The display state (the program's own, single-threaded use: the library calls the progress
   ! procedure from one thread only).
   logical :: show_progress = .false., on_terminal = .false.
   real(wp) :: t_start = 0.0_wp, t_last = 0.0_wp
   !> Cases done at the first report (resumed from a checkpoint), and the tenths already shown.
   integer :: done_first = -1, tenths_shown = 0
   integer :: blocks_committed = 0, abort_after_blocks = 0

contains

   !> Start the clock; `quiet` shows nothing.
   subroutine start_progress(quiet)
      !> -q.
      logical, intent(in) :: quiet
      logical :: ok
      show_progress = .not. quiet
      on_terminal = c_isatty(2_c_int) == 1
      t_start = wall_seconds()
      t_last = t_start
      done_first = -1
      tenths_shown = 0
      blocks_committed = 0
      ! Test hook: end the process abruptly after this many checkpoint blocks, as a kill would
      ! (used by the tests of --resume; see doc/app.md).
      call integer_variable('SHCONTACT_TEST_ABORT_AFTER_BLOCKS', abort_after_blocks, ok)
      if (.not. ok) abort_after_blocks = 0
   end subroutine start_progress

   !> Seconds since [[start_progress]].
   real(wp) function run_seconds()
      run_seconds = wall_seconds() - t_start
   end function run_seconds

   !> The library's progress report (shcontact_batch_sweep's progress_interface).
   subroutine progress(done, total, committed)
      !> Cases finished (resumed ones included) and cases of the shard.
      integer, intent(in) :: done, total
      !> A checkpoint block has just been written.
      logical, intent(in) :: committed
      real(wp) :: now
      if (committed) then
         blocks_committed = blocks_committed + 1
         if (abort_after_blocks > 0 .and. blocks_committed >= abort_after_blocks) then
            write (error_unit, '(a)') 'shcontact: SHCONTACT_TEST_ABORT_AFTER_BLOCKS: stopping '// &
               'after '//str_int(blocks_committed)//' checkpoint block(s)'
            stop 9, quiet = .true.
         end if
      end if
      if (done_first < 0) then
         done_first = done
         tenths_shown = (10*done)/max(total, 1)
      end if
      if (.not. show_progress) return
      now = wall_seconds()
      if (on_terminal) then
         if (now - t_last < bar_interval .and. done < total) return
         call draw_bar(done, total, now)
      else
         ! A one-case run has nothing to report before its result.
         if (total < 2 .or. done <= done_first) return
         if ((10*done)/total <= tenths_shown .and. now - t_last < line_interval) return
         tenths_shown = (10*done)/total
         write (error_unit, '(a)') 'shcontact: progress: '//progress_text(done, total, now)
         flush (error_unit)
      end if
      t_last = now
   end subroutine progress

   subroutine draw_bar(done, total, now)
      integer, intent(in) :: done, total
      real(wp), intent(in) :: now
      integer, parameter :: width = 30
      integer :: filled
      filled = (width*done)/max(total, 1)
      write (error_unit, '(a)', advance='no') achar(13)//'shcontact: ['// &
         repeat('#', filled)//repeat('.', width - filled)//'] '//str_int(done)//'/'// &
         str_int(total)//'  ETA '//elapsed(eta(done, total, now))//'   '
      flush (error_unit)
   end subroutine draw_bar

   !> "D of N cases (P %), R cases/s, elapsed E, ETA T".
   function progress_text(done, total, now) result(text)
      integer, intent(in) :: done, total
      real(wp), intent(in) :: now
      character(len=:), allocatable :: text
      text = str_int(done)//' of '//str_int(total)//' cases ('//str_int((100*done)/total)// &
         ' %), '//rate_text(done, now)//', elapsed '//elapsed(now - t_start)//', ETA '// &
         elapsed(eta(done, total, now))
   end function progress_text

   !> Cases solved by this run per second (resumed cases do not count).
   function rate_text(done, now) result(text)
      integer, intent(in) :: done
      real(wp), intent(in) :: now
      character(len=:), allocatable :: text
      character(len=32) :: buf
      real(wp) :: rate
      rate = real(done - done_first, wp)/max(now - t_start, 1.0e-3_wp)
      if (rate >= 100.0_wp) then
         write (buf, '(i0)') nint(rate)
      else
         write (buf, '(f0.2)') rate
         if (buf(1:1) == '.') buf = '0'//buf
      end if
      text = trim(buf)//' cases/s'
   end function rate_text

   !> Seconds to go at the rate so far.
   real(wp) function eta(done, total, now)
      integer, intent(in) :: done, total
      real(wp), intent(in) :: now
      eta = 0.0_wp
      if (done > done_first) eta = (now - t_start)*real(total - done, wp)/ &
         real(done - done_first, wp)
   end function eta

   !> End the bar's line.
   subroutine end_progress()
      if (show_progress .and. on_terminal .and. t_last > t_start) then
         write (error_unit, '(a)') ''
      end if
   end subroutine end_progress

   !> Seconds as "0.03 s", "12.3 s", "4 min 05 s" or "2 h 03 min".
   function elapsed(seconds) result(text)
      !> Seconds.
      real(wp), intent(in) :: seconds
      character(len=:), allocatable :: text
      character(len=32) :: buf
      integer :: s
      if (seconds < 10.0_wp) then
         write (buf, '(f0.2,a)') max(seconds, 0.0_wp), ' s'
         text = trim(buf)
         if (text(1:1) == '.') text = '0'//text
         return
      else if (seconds < 60.0_wp) then
         write (buf, '(f0.1,a)') seconds, ' s'
         text = trim(buf)
         if (text(1:1) == '.') text = '0'//text
         return
      end if
      s = nint(seconds)
      if (s < 3600) then
         write (buf, '(i0,a,i2.2,a)') s/60, ' min ', mod(s, 60), ' s'
      else
         write (buf, '(i0,a,i2.2,a)') s/3600, ' h ', mod(s, 3600)/60, ' min'
      end if
      text = trim(buf)
   end function elapsed

end module shcontact_app_progress
