!> The patch geometry tables (shcontact_geometry_patch) as the strip method takes them: their
!> checks, with a message naming what is wrong, and the curvatures at the reference point.
module shcontact_normal_patch_tables
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_geometry_patch, only: patch_geometry_type
   implicit none
   private

   public :: check_geometry, reference_curvatures

contains

   !> A(0) and B(0) of the table points i1..i2, interpolated exactly as
   !> patch_geometry_type%sample does on a table holding just those points.
   pure subroutine reference_curvatures(geometry, i1, i2, curv_a0, curv_b0)
      type(patch_geometry_type), intent(in) :: geometry
      integer, intent(in) :: i1, i2
      real(wp), intent(out) :: curv_a0, curv_b0
      real(wp), parameter :: y = 0.0_wp
      integer :: i
      real(wp) :: t

      if (y <= geometry%y(i1)) then
         i = i1; t = 0.0_wp
      else if (y >= geometry%y(i2)) then
         i = i2 - 1; t = 1.0_wp
      else
         i = i1 - 1 + min(i2 - i1, 1 + int((y - geometry%y(i1))/geometry%h))
         t = (y - geometry%y(i))/(geometry%y(i + 1) - geometry%y(i))
      end if
      curv_a0 = (1 - t)*geometry%curv_a(i) + t*geometry%curv_a(i + 1)
      curv_b0 = (1 - t)*geometry%curv_b(i) + t*geometry%curv_b(i + 1)
   end subroutine reference_curvatures

   !> Reject tables the strip method cannot use, naming the item and the value: points i1..last
   !> (all of them, in arrays of one common size, when `last` is absent).
   subroutine check_geometry(geometry, i1, last, error)
      type(patch_geometry_type), intent(in) :: geometry
      integer, intent(in) :: i1
      integer, intent(in), optional :: last
      type(error_type), allocatable, intent(out) :: error
      character(len=64) :: buf
      integer :: n, i, i2
      logical :: bad_size

      if (.not. (allocated(geometry%y) .and. allocated(geometry%gap) .and. &
                 allocated(geometry%curv_a) .and. allocated(geometry%curv_b) .and. &
                 allocated(geometry%gamma) .and. allocated(geometry%r_wheel))) then
         call fatal_error(error, 'patch geometry: tables y, gap, curv_a, curv_b, gamma, r_wheel '// &
            'must all be allocated', stat_invalid_input)
         return
      end if
      if (present(last)) then
         i2 = last
         bad_size = i1 < 1 .or. any([size(geometry%y), size(geometry%gap), &
            size(geometry%curv_a), size(geometry%curv_b), size(geometry%gamma), &
            size(geometry%r_wheel)] < i2)
      else
         i2 = size(geometry%y)
         bad_size = any([size(geometry%gap), size(geometry%curv_a), size(geometry%curv_b), &
            size(geometry%gamma), size(geometry%r_wheel)] /= i2)
      end if
      n = i2 - i1 + 1
      if (n < 2 .or. bad_size) then
         write (buf, '(i0)') n
         call fatal_error(error, 'patch geometry: tables must have one common size of at least '// &
            '2 points (y has '//trim(buf)//')', stat_invalid_input)
         return
      end if
      if (.not. (geometry%h > 0.0_wp)) then
         write (buf, '(es12.4)') geometry%h
         call fatal_error(error, 'patch geometry: table spacing h = '//trim(adjustl(buf))// &
            ' mm: expected h > 0', stat_invalid_input)
         return
      end if
      do i = i1 + 1, i2
         if (abs(geometry%y(i) - geometry%y(i1) - (i - i1)*geometry%h) > 1.0e-6_wp*geometry%h) then
            write (buf, '(i0,a,es12.4)') i - i1 + 1, ') = ', geometry%y(i)
            call fatal_error(error, 'patch geometry: y('//trim(buf)// &
               ' mm is off the uniform grid of spacing h', stat_invalid_input)
            return
         end if
      end do
      if (geometry%y(i1) > 0.0_wp .or. geometry%y(i2) < 0.0_wp) then
         call fatal_error(error, 'patch geometry: the table must contain the reference point y = 0', &
            stat_invalid_input)
         return
      end if
      do i = i1, i2
         if (.not. (geometry%curv_a(i) > 0.0_wp .and. geometry%curv_b(i) > 0.0_wp)) then
            write (buf, '(3(es12.4,a))') geometry%y(i), ' mm: A = ', geometry%curv_a(i), &
               ', B = ', geometry%curv_b(i), ''
            call fatal_error(error, 'patch geometry at y = '//trim(adjustl(buf))// &
               ' 1/mm: expected A > 0 and B > 0 (B clamped to B_min)', stat_invalid_input)
            return
         end if
      end do
   end subroutine check_geometry

end module shcontact_normal_patch_tables
