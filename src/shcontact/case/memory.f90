!> What a sweep's results hold in memory, in bytes, and what of it the file will not need: the
!> bookkeeping behind the sweep's memory bound (shcontact_batch_sweep: a checkpoint block is cut
!> so that it and the block being written hold at most `block_bytes` of results).
module shcontact_case_memory
   use, intrinsic :: iso_fortran_env, only: int64
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_input_config, only: case_config_type
   use shcontact_case_result, only: case_result_type
   use shcontact_case_runner, only: stage_type
   implicit none
   private

   public :: keep_stored, result_bytes, estimated_result_bytes, stage_bytes

contains

   !> Drop from a result what the file will not store: the geometry when it is the run's
   !> common one (or not asked for), the strip tables when `strips` is not asked for.
   elemental subroutine keep_stored(result, keep_geometry, keep_strips)
      type(case_result_type), intent(inout) :: result
      logical, intent(in) :: keep_geometry, keep_strips
      integer :: k
      if (.not. keep_geometry .and. allocated(result%geometry)) deallocate (result%geometry)
      if (keep_strips .or. .not. allocated(result%normal)) return
      do k = 1, size(result%normal)
         associate (n => result%normal(k))
            if (allocated(n%y)) deallocate (n%y)
            if (allocated(n%a)) deallocate (n%a)
            if (allocated(n%k)) deallocate (n%k)
            if (allocated(n%p0)) deallocate (n%p0)
            if (allocated(n%strip_load)) deallocate (n%strip_load)
            if (allocated(n%m)) deallocate (n%m)
            if (allocated(n%n)) deallocate (n%n)
            if (allocated(n%eps_a)) deallocate (n%eps_a)
            if (allocated(n%gamma)) deallocate (n%gamma)
            if (allocated(n%gamma_n)) deallocate (n%gamma_n)
            if (allocated(n%delta_r)) deallocate (n%delta_r)
            if (allocated(n%r_wheel)) deallocate (n%r_wheel)
         end associate
      end do
   end subroutine keep_stored

   !> Bytes held by a result beyond its summary: the arrays of its geometry, normal and
   !> tangential solutions, plus a fixed share for the descriptors and message.
   elemental function result_bytes(result) result(bytes)
      !> The result.
      type(case_result_type), intent(in) :: result
      integer(int64) :: bytes
      integer :: k
      bytes = 1024 + tables_bytes(result%geometry, result%normal)
      if (allocated(result%tangential)) then
         do k = 1, size(result%tangential)
            associate (t => result%tangential(k))
               if (allocated(t%x)) bytes = bytes + 8_int64*size(t%x, kind=int64)
               if (allocated(t%y)) bytes = bytes + 8_int64*size(t%y, kind=int64)
               if (allocated(t%dx)) bytes = bytes + 8_int64*size(t%dx, kind=int64)
               if (allocated(t%pn)) bytes = bytes + 8_int64*size(t%pn, kind=int64)
               if (allocated(t%px)) bytes = bytes + 8_int64*size(t%px, kind=int64)
               if (allocated(t%py)) bytes = bytes + 8_int64*size(t%py, kind=int64)
               if (allocated(t%slip)) bytes = bytes + 8_int64*size(t%slip, kind=int64)
               if (allocated(t%state)) bytes = bytes + size(t%state, kind=int64)
            end associate
         end do
      end if
   end function result_bytes

   !> A result's bytes estimated from the grid before any is solved: one patch's element
   !> fields (five reals and a state byte per element) and strip tables, a quarter more for the
   !> stage's share and the rest.
   pure function estimated_result_bytes(config) result(bytes)
      type(case_config_type), intent(in) :: config
      integer(int64) :: bytes
      integer(int64) :: strips, elements
      strips = config%normal%n_strips
      elements = config%tangential%n_elements
      bytes = 1024 + 41*strips*elements + 2*8*strips
      if (config%wants_field('strips')) bytes = bytes + 11*8*strips
      bytes = bytes + bytes/4
   end function estimated_result_bytes

   !> Bytes of a stage's geometry tables and normal solutions.
   pure function stage_bytes(stage) result(bytes)
      type(stage_type), intent(in) :: stage
      integer(int64) :: bytes
      bytes = tables_bytes(stage%geometry, stage%normal)
   end function stage_bytes

   !> Bytes of the geometry tables and strip tables of some patches (either may be unallocated).
   pure function tables_bytes(geometry, normal) result(bytes)
      type(patch_geometry_type), allocatable, intent(in) :: geometry(:)
      type(normal_patch_type), allocatable, intent(in) :: normal(:)
      integer(int64) :: bytes
      integer :: k
      bytes = 0
      if (allocated(geometry)) then
         do k = 1, size(geometry)
            if (allocated(geometry(k)%y)) bytes = bytes + 6_int64*8_int64*size(geometry(k)%y, &
               kind=int64)
         end do
      end if
      if (allocated(normal)) then
         do k = 1, size(normal)
            if (allocated(normal(k)%y)) bytes = bytes + 11_int64*8_int64*size(normal(k)%y, &
               kind=int64)
         end do
      end if
   end function tables_bytes

end module shcontact_case_memory
