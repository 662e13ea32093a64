!> The normal pressure on the strip-adapted element grid of the tangential solver
!> (doc/theory.md §3.2, §6.5 step 3): n_x elements per strip of length Δx_i = 2a_i/n_x, centres
!> x_j = a_i − (j − ½)Δx_i, numbered from the leading edge x = +a_i.
module shcontact_normal_pressure
   use shcontact_core_kinds, only: wp
   use shcontact_normal_patch, only: normal_patch_type
   implicit none
   private

   public :: element_pressure

contains

   !> Semi-elliptic strip pressure p₀,ᵢ √(1 − x_j²/a_i²) at the element centres (doc/theory.md §4.3
   !> step 6). n_x = size(pn, 1); column i is strip i; columns beyond the patch's strips, and
   !> strips with a_i = 0, get zero.
   pure subroutine element_pressure(patch, pn, x)
      !> The normal solution.
      type(normal_patch_type), intent(in) :: patch
      !> Pressure p_n(j, i) at element j of strip i (MPa).
      real(wp), intent(out) :: pn(:, :)
      !> Element centres x_j of strip i (mm), same shape as pn.
      real(wp), intent(out), optional :: x(:, :)
      integer :: i, j, nx, ns
      real(wp) :: xi

      nx = size(pn, 1)
      ns = min(size(pn, 2), patch%n_strips)
      pn(:, :) = 0.0_wp
      if (present(x)) x(:, :) = 0.0_wp
      do i = 1, ns
         if (.not. (patch%a(i) > 0.0_wp)) cycle
         do j = 1, nx
            ! x_j/a_i, in (−1, 1) by construction: no division by a_i.
            xi = 1.0_wp - (2*j - 1)/real(nx, wp)
            pn(j, i) = patch%p0(i)*sqrt((1.0_wp - xi)*(1.0_wp + xi))
            if (present(x)) x(j, i) = xi*patch%a(i)
         end do
      end do
   end subroutine element_pressure

end module shcontact_normal_pressure
