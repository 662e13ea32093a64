!> Small order statistics of a sample (the profile diagnostics' typical spacing, the
!> benchmark's median of repeats).
module shcontact_math_statistics
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: median

contains

   !> The median of a sample of up to a few thousand values (insertion sort of a copy; the mean
   !> of the two middle values for an even count).
   pure real(wp) function median(values)
      !> The sample (at least one value).
      real(wp), intent(in) :: values(:)
      real(wp) :: v(size(values)), t
      integer :: i, j, n
      v = values
      n = size(v)
      do i = 2, n
         t = v(i)
         j = i - 1
         do while (j >= 1)
            if (v(j) <= t) exit
            v(j + 1) = v(j)
            j = j - 1
         end do
         v(j + 1) = t
      end do
      if (mod(n, 2) == 1) then
         median = v((n + 1)/2)
      else
         median = 0.5_wp*(v(n/2) + v(n/2 + 1))
      end if
   end function median

end module shcontact_math_statistics
