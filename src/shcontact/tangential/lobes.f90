!> The wheel's contact where the exact theory joins close lobes into one patch (issue 28 item 3,
!> doc/lobes.md).
!>
!> CONTACT makes one contact patch of the rigid interpenetration regions whose extents along the
!> profile lie at most D_COMB = 4 mm apart (a connected region is one), solves it with one
!> reference point, and reports one creep force for it, f = F/(μF_n) with F_n the patch's total.
!> The contact search here finds one patch per minimum of the gap, so at such a position (Y_WS =
!> 5.0 and 5.3 mm on S1002/UIC60: one connected interpenetration region with two minima, whose
!> elastic solution has two lobes 4.4 mm apart) it finds two; the most loaded one alone is not
!> what the exact theory reports (up to 0.44 off in f, doc/validation.md §6.5). [[join_lobes]]
!> gives what a reader of the wheel should take there: the main (most loaded) patch and every
!> loaded patch whose rigid interpenetration lies within D_COMB of the group's, their forces
!> summed, f = Σ F/(μ Σ F_n). The interpenetration of a patch is the run of its gap table
!> around its reference point where g(y) < δ, its approach; the table runs on past the gap
!> maximum into a neighbour's basin, so two regions that connect overlap. Each patch's tangential problem is still solved
!> in its own plane with its own creepages; the sum adds the tangential forces as they are, each
!> in its own plane, as CONTACT's one plane averages them (its lobes' planes lie ~10° apart, so
!> the lateral force of the smaller lobe is counted with cos 10° = 0.985 of itself at most).
!> Where the main patch stands alone the joined contact is that patch.
module shcontact_tangential_lobes
   use shcontact_core_kinds, only: wp
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   implicit none
   private

   public :: join_distance, joined_lobes_type, interpenetration_extent, lobe_gap, join_lobes

   !> Patches whose loaded extents lie at most this far apart along the profile (mm) are one
   !> contact patch for the exact theory (CONTACT's D_COMB).
   real(wp), parameter :: join_distance = 4.0_wp

   !> Most patches considered (the solver's patches per wheel, shcontact_geometry_pair's
   !> max_candidates); beyond these a patch is not joined.
   integer, parameter :: max_members = 16

   !> The joined contact of one wheel.
   type :: joined_lobes_type
      !> Loaded patches joined, and which (indices into the patches given).
      integer :: n_members = 0
      integer :: members(max_members) = 0
      !> Σ F_x, Σ F_y (N, each patch's contact frame), Σ F_n (N).
      real(wp) :: fx = 0.0_wp, fy = 0.0_wp, fn = 0.0_wp
      !> f = Σ F/(μ Σ F_n).
      real(wp) :: fx_norm = 0.0_wp, fy_norm = 0.0_wp
      !> Σ of the contact areas (mm²) and the largest peak pressure (MPa).
      real(wp) :: area = 0.0_wp, p_max = 0.0_wp
   end type joined_lobes_type

contains

   !> The extent [lo, hi] along the profile (mm) of a patch's rigid interpenetration: the run of
   !> its gap table around the reference point (y = 0) where g(y) < δ, placed at `offset`, the
   !> position of the reference point along the profile. Empty (lo > hi) when δ ≤ 0.
   pure subroutine interpenetration_extent(geometry, n_points, approach, offset, lo, hi)
      !> The patch's geometry (tables y, gap; the first n_points entries are its own).
      type(patch_geometry_type), intent(in) :: geometry
      integer, intent(in) :: n_points
      !> Its approach δ (mm).
      real(wp), intent(in) :: approach
      !> Position of its reference point along the profile (mm).
      real(wp), intent(in) :: offset
      real(wp), intent(out) :: lo, hi
      integer :: i0, i, j

      lo = huge(1.0_wp)
      hi = -huge(1.0_wp)
      if (n_points < 1 .or. .not. (approach > 0.0_wp)) return
      i0 = minloc(abs(geometry%y(1:n_points)), dim=1)
      if (.not. (geometry%gap(i0) < approach)) return
      i = i0
      do while (i > 1)
         if (.not. (geometry%gap(i - 1) < approach)) exit
         i = i - 1
      end do
      j = i0
      do while (j < n_points)
         if (.not. (geometry%gap(j + 1) < approach)) exit
         j = j + 1
      end do
      lo = offset + geometry%y(i) - 0.5_wp*geometry%h
      hi = offset + geometry%y(j) + 0.5_wp*geometry%h
   end subroutine interpenetration_extent

   !> The gap (mm) between two loaded extents along the profile, 0 when they overlap; huge when
   !> either is empty.
   pure real(wp) function lobe_gap(lo1, hi1, lo2, hi2) result(gap)
      real(wp), intent(in) :: lo1, hi1, lo2, hi2
      if (lo1 > hi1 .or. lo2 > hi2) then
         gap = huge(1.0_wp)
      else
         gap = max(0.0_wp, lo2 - hi1, lo1 - hi2)
      end if
   end function lobe_gap

   !> The joined contact (module text): starting from the most loaded patch, every loaded patch
   !> whose interpenetration lies within [[join_distance]] of a patch already joined, and their
   !> summed forces. patches(k)%load > 0 marks a loaded patch; fx, fy are its tangential forces.
   pure subroutine join_lobes(geometry, n_points, patches, offset, fx, fy, friction, joined)
      !> The geometry of the wheel's patches and their table lengths.
      type(patch_geometry_type), intent(in) :: geometry(:)
      integer, intent(in) :: n_points(:)
      !> Their normal solutions (load, approach).
      type(normal_patch_type), intent(in) :: patches(:)
      !> Position of each patch's first contact along the profile (mm; the signed distance in the
      !> track's y–z plane from the first patch's, as the coupled reduction places them).
      real(wp), intent(in) :: offset(:)
      !> Tangential forces of each patch (N; 0 for an unloaded one).
      real(wp), intent(in) :: fx(:), fy(:)
      !> Friction coefficient μ.
      real(wp), intent(in) :: friction
      type(joined_lobes_type), intent(out) :: joined
      ! Fixed-size work arrays: the solver's summary allocates nothing (doc/api.md).
      real(wp) :: lo(max_members), hi(max_members)
      logical :: in(max_members), grown
      integer :: k, j, main, n

      n = min(size(patches), max_members)
      main = 0
      do k = 1, n
         call interpenetration_extent(geometry(k), n_points(k), patches(k)%approach, offset(k), &
            lo(k), hi(k))
         if (.not. (patches(k)%load > 0.0_wp)) cycle
         if (main == 0) then
            main = k
         else if (patches(k)%load > patches(main)%load) then
            main = k
         end if
      end do
      if (main == 0) return
      in = .false.
      in(main) = .true.
      grown = .true.
      do while (grown)
         grown = .false.
         do k = 1, n
            if (in(k) .or. .not. (patches(k)%load > 0.0_wp)) cycle
            do j = 1, n
               if (.not. in(j)) cycle
               if (lobe_gap(lo(k), hi(k), lo(j), hi(j)) <= join_distance) then
                  in(k) = .true.
                  grown = .true.
                  exit
               end if
            end do
         end do
      end do
      do k = 1, n
         if (.not. in(k)) cycle
         joined%n_members = joined%n_members + 1
         joined%members(joined%n_members) = k
         joined%fx = joined%fx + fx(k)
         joined%fy = joined%fy + fy(k)
         joined%fn = joined%fn + patches(k)%load
         joined%area = joined%area + patches(k)%area
         joined%p_max = max(joined%p_max, patches(k)%p_max)
      end do
      joined%fx_norm = joined%fx/(friction*joined%fn)
      joined%fy_norm = joined%fy/(friction*joined%fn)
   end subroutine join_lobes

end module shcontact_tangential_lobes
