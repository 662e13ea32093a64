!> The results of a flat-interface context after a solve: a patch's values, its element fields
!> and the profiles the contact was created with (shcontact_api_context holds the context, its
!> creation, settings and solves). Every function returns the status it records in the context.
module shcontact_api_context_results
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type, fatal_error, stat_usage
   use shcontact_core_strings, only: str_int
   use shcontact_profile_points, only: profile_type, profile_kind_wheel, profile_kind_rail, &
      tape_circle_origin
   use shcontact_api_solver, only: max_patches
   use shcontact_api_values, only: patch_value_count, kinematic_value_count, patch_values, &
      kinematic_values
   use shcontact_api_context, only: contact_context_type, context_record, context_usable
   implicit none
   private

   public :: context_patch, context_patch_kinematic, context_field_size, context_fields, &
      context_check_field_arrays, context_get_profile

contains

   !> The flat values of patch k of the last solve ([[patch_values]]).
   integer function context_patch(ctx, k, values) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> The patch values (patch_value_count; zero on failure).
      real(wp), intent(out) :: values(patch_value_count)
      type(error_type), allocatable :: error

      values = 0.0_wp
      call check_patch_index(ctx, k, error)
      if (.not. allocated(error)) call patch_values(ctx%result%patch(k), values)
      stat = context_record(ctx, error)
   end function context_patch

   !> Patch k of the last solve in the kinematic layout ([[kinematic_values]]): its values in
   !> 1–17 and 26–29 (creepages and x_track), the result's counts and totals in 18–25.
   integer function context_patch_kinematic(ctx, k, values) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> The values (kinematic_value_count; zero on failure).
      real(wp), intent(out) :: values(kinematic_value_count)
      type(error_type), allocatable :: error

      values = 0.0_wp
      call check_patch_index(ctx, k, error)
      if (.not. allocated(error)) call kinematic_values(ctx%result, values, k)
      stat = context_record(ctx, error)
   end function context_patch_kinematic

   !> The size of patch k's element fields after the last solve: nx elements per strip (along
   !> the rolling direction) and ny strips. 0 × 0 for a patch that carries no load (found by the
   !> contact search but not loaded, or loaded with nothing). An error unless the last solve
   !> kept its fields (option `output%fields`).
   integer function context_field_size(ctx, k, nx, ny) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> Elements per strip and strips (0 on failure).
      integer, intent(out) :: nx, ny
      type(error_type), allocatable :: error

      nx = 0
      ny = 0
      call check_fields(ctx, k, error)
      if (.not. allocated(error)) call field_shape(ctx, k, nx, ny)
      stat = context_record(ctx, error)
   end function context_field_size

   !> Patch k's element fields after the last solve, as arrays (nx, ny) in Fortran order: element
   !> (j, i) is element j (from the leading edge) of strip i. nx and ny must be the sizes of
   !> [[context_field_size]]. Coordinates in the patch's contact frame (mm): x along the rolling
   !> direction from the strip's middle, y the strip centre across the patch from its reference
   !> point; area the element area (mm², so that Σ px·area = F_x); pressures and tractions on the
   !> wheel (MPa); slip |s| in slip elements; state 0 exterior, 1 adhesion, 2 slip.
   integer function context_fields(ctx, k, nx, ny, x, y, area, pn, px, py, slip, state) &
         result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> Patch index, 1 to the number of patches of the last result.
      integer, intent(in) :: k
      !> The field sizes (those of context_field_size).
      integer, intent(in) :: nx, ny
      !> Element centres and areas (mm, mm²); not written on failure.
      real(wp), intent(inout) :: x(nx, ny), y(nx, ny), area(nx, ny)
      !> Normal pressure, tractions (MPa) and slip magnitude; not written on failure.
      real(wp), intent(inout) :: pn(nx, ny), px(nx, ny), py(nx, ny), slip(nx, ny)
      !> Element state: 0 exterior, 1 adhesion, 2 slip.
      integer, intent(inout) :: state(nx, ny)
      type(error_type), allocatable :: error
      integer :: i

      ! The arrays are touched only when their sizes are the fields' (a caller's arrays of
      ! another size may be smaller than nx·ny: nothing is written on failure).
      call context_check_field_arrays(ctx, k, nx, ny, error)
      if (.not. allocated(error) .and. nx > 0 .and. ny > 0) then
         associate (t => ctx%fields%tangential(k))
            x = t%x
            do i = 1, ny
               y(:, i) = t%y(i)
               area(:, i) = t%dx(i)*t%dy
            end do
            pn = t%pn
            px = t%px
            py = t%py
            slip = t%slip
            state = int(t%state)
         end associate
      end if
      stat = context_record(ctx, error)
   end function context_fields

   !> An error unless patch k's fields are kept and are nx × ny.
   subroutine context_check_field_arrays(ctx, k, nx, ny, error)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k, nx, ny
      type(error_type), allocatable, intent(out) :: error
      integer :: mx, my
      call check_fields(ctx, k, error)
      if (allocated(error)) return
      call field_shape(ctx, k, mx, my)
      if (nx /= mx .or. ny /= my) call fatal_error(error, 'fields of patch '//str_int(k)// &
         ': arrays of '//str_int(nx)//' x '//str_int(ny)//' given, the fields are '// &
         str_int(mx)//' x '//str_int(my)//' (ask their size first; nothing was written)', &
         stat_usage)
   end subroutine context_check_field_arrays

   !> The points of the wheel (kind = profile_kind_wheel, 1) or rail (profile_kind_rail, 0)
   !> profile of the contact, as it was created (read and cleaned; mm, canonical form), e.g. to
   !> pass them to [[context_create_arrays]] after a change. A MiniProf wheel, whose origin is at
   !> its flange back, comes moved by −70 mm to the origin arrays have (tape circle; flange back
   !> at −70 mm, the default flange-back position: shcontact_profile_points' tape_circle_origin),
   !> so that the arrays with the default track give the contact of the file. n receives the number of points
   !> also when it exceeds the capacity of y and z (then nothing is copied and the status is 1).
   integer function context_get_profile(ctx, kind, n, y, z) result(stat)
      !> The context.
      type(contact_context_type), intent(inout) :: ctx
      !> profile_kind_wheel (1) or profile_kind_rail (0).
      integer, intent(in) :: kind
      !> The number of points (0 on failure other than a small capacity).
      integer, intent(out) :: n
      !> The points (their size is the capacity); zero beyond n.
      real(wp), intent(out) :: y(:), z(:)
      type(error_type), allocatable :: error
      type(profile_type) :: wheel, rail

      n = 0
      y = 0.0_wp
      z = 0.0_wp
      if (kind /= profile_kind_wheel .and. kind /= profile_kind_rail) then
         call fatal_error(error, 'profile kind = '//str_int(kind)//': expected 1 (wheel) or '// &
            '0 (rail)', stat_usage)
      else if (context_usable(ctx, error, wheelset=.false.)) then
         call ctx%solver%get_profiles(wheel, rail)
         wheel = tape_circle_origin(wheel)
         if (kind == profile_kind_rail) wheel = rail
         n = wheel%size()
         if (n > min(size(y), size(z))) then
            call fatal_error(error, 'profile points: the '//trim(merge('wheel', 'rail ', &
               kind == profile_kind_wheel))//' profile has '//str_int(n)//' points, the '// &
               'arrays hold '//str_int(min(size(y), size(z))), stat_usage)
         else
            y(1:n) = wheel%y
            z(1:n) = wheel%z
         end if
      end if
      stat = context_record(ctx, error)
   end function context_get_profile

   !> An error unless the last solve kept its fields and has a patch k.
   subroutine check_fields(ctx, k, error)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k
      type(error_type), allocatable, intent(out) :: error
      ! A wheelset handle takes the wheelset calls (its message says which).
      if (ctx%is_wheelset) then
         if (.not. context_usable(ctx, error, wheelset=.false.)) return
      end if
      if (ctx%has_result .and. .not. ctx%has_fields) then
         call fatal_error(error, "fields: the last solve kept none; set the option "// &
            "'output%fields' to 'all' before solving", stat_usage)
         return
      end if
      call check_patch_index(ctx, k, error)
   end subroutine check_fields

   !> The element field size of patch k (0 × 0 when it carries no load).
   pure subroutine field_shape(ctx, k, nx, ny)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k
      integer, intent(out) :: nx, ny
      nx = 0
      ny = 0
      if (k > ctx%fields%n_patches) return
      nx = ctx%fields%tangential(k)%nx
      ny = ctx%fields%tangential(k)%ny
   end subroutine field_shape

   !> An error unless the context holds a result with a patch k.
   subroutine check_patch_index(ctx, k, error)
      type(contact_context_type), intent(in) :: ctx
      integer, intent(in) :: k
      type(error_type), allocatable, intent(out) :: error
      if (ctx%is_wheelset) then
         if (.not. context_usable(ctx, error, wheelset=.false.)) return
      end if
      if (.not. ctx%has_result) then
         call fatal_error(error, 'patch values: no result yet (the last solve failed or none '// &
            'was made)', stat_usage)
      else if (k < 1 .or. k > min(ctx%result%n_patches, max_patches)) then
         call fatal_error(error, 'patch '//str_int(k)//': expected 1 to '// &
            str_int(ctx%result%n_patches)//' (the patches of the last solve)', stat_usage)
      end if
   end subroutine check_patch_index

end module shcontact_api_context_results
