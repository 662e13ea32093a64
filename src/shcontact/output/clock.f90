!> Time stamps and wall-clock time for the output layer.
module shcontact_output_clock
   use shcontact_core_kinds, only: wp, i8
   implicit none
   private

   public :: iso_timestamp, wall_seconds

contains

   !> The current date and time in ISO 8601 (`2026-03-01T12:00:00+01:00`). When the
   !> environment variable SOURCE_DATE_EPOCH holds a number of seconds since 1970 (the
   !> reproducible-builds convention), that UTC time is used instead, so that runs can produce
   !> byte-identical files.
   function iso_timestamp() result(stamp)
      character(len=:), allocatable :: stamp
      character(len=32) :: buf
      integer :: values(8), length, stat
      integer(i8) :: epoch

      call get_environment_variable('SOURCE_DATE_EPOCH', buf, length, stat)
      if (stat == 0 .and. length > 0) then
         read (buf(1:length), *, iostat=stat) epoch
         if (stat == 0 .and. epoch >= 0) then
            stamp = utc_from_epoch(epoch)
            return
         end if
      end if
      call date_and_time(values=values)
      write (buf, '(i4.4,"-",i2.2,"-",i2.2,"T",i2.2,":",i2.2,":",i2.2,a,i2.2,":",i2.2)') &
         values(1:3), values(5:7), merge('+', '-', values(4) >= 0), abs(values(4))/60, &
         mod(abs(values(4)), 60)
      stamp = trim(buf)
   end function iso_timestamp

   !> `YYYY-MM-DDThh:mm:ssZ` for seconds since 1970-01-01T00:00:00Z (proleptic Gregorian
   !> calendar; days to civil date after H. Hinnant's algorithm).
   pure function utc_from_epoch(epoch) result(stamp)
      integer(i8), intent(in) :: epoch
      character(len=:), allocatable :: stamp
      character(len=32) :: buf
      integer(i8) :: days, secs, z, era, doe, yoe, doy, mp, d, m, y
      days = epoch/86400
      secs = mod(epoch, 86400_i8)
      z = days + 719468
      era = z/146097
      doe = z - era*146097
      yoe = (doe - doe/1460 + doe/36524 - doe/146096)/365
      y = yoe + era*400
      doy = doe - (365*yoe + yoe/4 - yoe/100)
      mp = (5*doy + 2)/153
      d = doy - (153*mp + 2)/5 + 1
      m = merge(mp + 3, mp - 9, mp < 10)
      if (m <= 2) y = y + 1
      write (buf, '(i4.4,"-",i2.2,"-",i2.2,"T",i2.2,":",i2.2,":",i2.2,"Z")') y, m, d, &
         secs/3600, mod(secs, 3600_i8)/60, mod(secs, 60_i8)
      stamp = trim(buf)
   end function utc_from_epoch

   !> Wall-clock seconds from an arbitrary origin.
   function wall_seconds() result(t)
      real(wp) :: t
      integer(i8) :: count, rate
      call system_clock(count, rate)
      t = real(count, wp)/real(max(rate, 1_i8), wp)
   end function wall_seconds

end module shcontact_output_clock
