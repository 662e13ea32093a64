!> Elastic coupling between the strips of a semi-Hertzian patch (`reduction = 'coupled'`,
!> issue 13; doc/validation.md §6.4).
!>
!> The local-Hertz strips (physics.md §4.3) are elastically independent: each strip takes the
!> deflection of its own local Hertz ellipse. Where the gap is nearly flat (B at its clamp) that
!> ellipse is a construct much wider than the patch, and the lateral load distribution goes wrong:
!> on the ty0 tread too little load in the conformal middle, at the ty5p8 flange root a tail of
!> 1 mm past the exact contact edge. Here the strips are coupled through the half-space, in the
!> spirit of Kik–Piotrowski's method, whose single displacement condition is imposed on the centre
!> line x = 0 of every strip (a 1-D boundary-element method across the strips):
!>
!> * each strip keeps a semi-elliptic pressure P_i √(1 − x²/a_i²);
!> * the half-space displacement of all strips at (0, y_j) equals the rigid interpenetration there,
!>   Σ_i K_ji P_i = δ' − g_j on every loaded strip, with K_ji = (1/(π E*)) ∫∫ √(1 − x²/a_i²)/r
!>   over strip i, and P_i ≥ 0 (strips with a negative solution leave the contact);
!> * the total stays the local-Hertz solution's load, Σ (π/2) P_i a_i δy = N, which fixes δ' (so
!>   every loading mode keeps its force balance);
!> * the strip lengths a_i stay those of the local-Hertz solution: they agree with the exact
!>   contact within about 0.2 mm on both shared patches, where the loads do not (doc/validation.md
!>   §6.4). Fixed lengths make the problem linear with a unique solution; letting a_i follow P_i
!>   (a_i ∝ P_i, 2-D Hertz) was tried and is unstable on the narrow flange-root patch (the strips
!>   lengthen without bound).
!>
!> On a Hertzian patch the Hertz pressure satisfies these conditions, so the coupling leaves it
!> unchanged up to the discretisation. The gap of strip i comes from the strip table itself,
!> g_i = ε_b,i δ (1 − k_i²) (§4.3 step 3). k_i = a_i/a_H,i is kept consistent (≤ 1).
!>
!> Cost: O(n³) for n loaded strips (dense LU, repeated when strips leave); about a millisecond
!> for 100 strips, so
!> this is a mode for sweeps at a fixed position, not the default of the vehicle call.
module shcontact_normal_coupling
   use shcontact_core_kinds, only: wp
   use shcontact_core_constants, only: pi
   use shcontact_core_error, only: error_type
   use shcontact_math_lapack, only: solve_dense
   use shcontact_normal_patch, only: normal_patch_type
   implicit none
   private

   public :: couple_strips

   !> Rebuilds of the kernel from the updated strip lengths.
   !> Gauss–Legendre points per quarter period of the x-integral of the kernel.
   integer, parameter :: n_gauss = 16
   !> Gauss–Legendre nodes and weights on [−1, 1] (n_gauss points, numpy's leggauss(16)).
   real(wp), parameter :: gauss_t(n_gauss) = [ &
      -0.9894009349916499_wp, -0.9445750230732326_wp, -0.8656312023878318_wp, &
      -0.7554044083550030_wp, -0.6178762444026438_wp, -0.4580167776572274_wp, &
      -0.2816035507792589_wp, -0.0950125098376374_wp, 0.0950125098376374_wp, &
      0.2816035507792589_wp, 0.4580167776572274_wp, 0.6178762444026438_wp, &
      0.7554044083550030_wp, 0.8656312023878318_wp, 0.9445750230732326_wp, &
      0.9894009349916499_wp]
   real(wp), parameter :: gauss_w(n_gauss) = [ &
      0.0271524594117541_wp, 0.0622535239386479_wp, 0.0951585116824928_wp, &
      0.1246289712555339_wp, 0.1495959888165767_wp, 0.1691565193950025_wp, &
      0.1826034150449236_wp, 0.1894506104550685_wp, 0.1894506104550685_wp, &
      0.1826034150449236_wp, 0.1691565193950025_wp, 0.1495959888165767_wp, &
      0.1246289712555339_wp, 0.0951585116824928_wp, 0.0622535239386479_wp, &
      0.0271524594117541_wp]

contains

   !> Redistribute the load of a local-Hertz strip table through the half-space coupling (module
   !> text). The table keeps its strips, its total load and γ_i, δr_i, m_i, n_i, ε_a,i; a_i, k_i,
   !> p₀,ᵢ, N_i, the approach (the coupled δ'), area and p_max change.
   subroutine couple_strips(patch, e_star, error)
      !> The strip table: local Hertz on entry, coupled on return.
      type(normal_patch_type), intent(inout) :: patch
      !> E* = G/(1 − ν) (MPa).
      real(wp), intent(in) :: e_star
      !> Set when the dense solve fails.
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: kmat(:, :), rhs(:, :), g(:), a(:), p(:), a0(:), p0(:), a_h(:)
      integer, allocatable :: idx(:)
      logical, allocatable :: active(:)
      real(wp) :: load, delta
      integer :: n, m, i, j, pass

      n = patch%n_strips
      load = sum(patch%strip_load(1:n))
      if (.not. (load > 0.0_wp)) return
      allocate (g(n), a(n), p(n), a_h(n), active(n))
      active = patch%a(1:n) > 0.0_wp .and. patch%k(1:n) > 0.0_wp
      a0 = patch%a(1:n)
      p0 = patch%p0(1:n)
      do i = 1, n
         g(i) = 0.0_wp
         a_h(i) = 1.0_wp
         if (.not. active(i)) cycle
         ! δ_i = k_i² δ = δ − g_i/ε_b,i (physics.md §4.3 step 3).
         g(i) = (1.0_wp - patch%eps_a(i))*patch%approach*(1.0_wp - patch%k(i)**2)
         a_h(i) = a0(i)/patch%k(i)
      end do
      a = a0
      p = p0
      delta = patch%approach
      ! Active set: strips whose peak comes out negative leave the contact.
      do pass = 1, n
         m = count(active)
         if (m < 1) exit
         idx = pack([(i, i=1, n)], active)
         allocate (kmat(m + 1, m + 1), rhs(m + 1, 1))
         do i = 1, m
            do j = 1, m
               kmat(j, i) = influence(a(idx(i)), patch%y(idx(j)) - patch%y(idx(i)), &
                  patch%dy)/(pi*e_star)
            end do
            kmat(m + 1, i) = 0.5_wp*pi*a(idx(i))*patch%dy
         end do
         kmat(1:m, m + 1) = -1.0_wp
         kmat(m + 1, m + 1) = 0.0_wp
         rhs(1:m, 1) = -g(idx)
         rhs(m + 1, 1) = load
         call solve_dense(kmat, rhs, error)
         if (allocated(error)) return
         p = 0.0_wp
         p(idx) = rhs(1:m, 1)
         delta = rhs(m + 1, 1)
         deallocate (kmat, rhs)
         if (all(p(idx) >= 0.0_wp)) exit
         where (p < 0.0_wp) active = .false.
      end do
      if (m < 1) return

      patch%approach = delta
      do i = 1, n
         if (active(i) .and. a(i) > 0.0_wp .and. p(i) > 0.0_wp) then
            patch%a(i) = a(i)
            patch%p0(i) = p(i)
            patch%k(i) = min(1.0_wp, a(i)/a_h(i))
            patch%strip_load(i) = 0.5_wp*pi*p(i)*a(i)*patch%dy
         else
            patch%a(i) = 0.0_wp
            patch%p0(i) = 0.0_wp
            patch%k(i) = 0.0_wp
            patch%strip_load(i) = 0.0_wp
         end if
      end do
      ! The lengths moved after the last solve: restore the exact total.
      patch%strip_load(1:n) = patch%strip_load(1:n)*(load/sum(patch%strip_load(1:n)))
      patch%p0(1:n) = merge(2.0_wp*patch%strip_load(1:n)/(pi*max(patch%a(1:n), tiny(1.0_wp))* &
         patch%dy), 0.0_wp, patch%a(1:n) > 0.0_wp)
      patch%load = load
      patch%area = 2.0_wp*sum(patch%a(1:n))*patch%dy
      patch%p_max = maxval(patch%p0(1:n))
   end subroutine couple_strips

   !> ∫∫ √(1 − x²/a²)/r over the strip [−a, a] × [η − δy/2, η + δy/2] seen from the origin
   !> (mm): x = a sin θ, the y-integral in closed form (asinh), Gauss–Legendre in θ ∈ (0, π/2)
   !> (the integrand is even in x).
   pure real(wp) function influence(a, eta, dy) result(s)
      real(wp), intent(in) :: a, eta, dy
      real(wp) :: x, th, c
      integer :: k
      s = 0.0_wp
      do k = 1, n_gauss
         th = 0.25_wp*pi*(gauss_t(k) + 1.0_wp)
         x = a*sin(th)
         c = cos(th)
         s = s + gauss_w(k)*c*c*(asinh((eta + 0.5_wp*dy)/x) - asinh((eta - 0.5_wp*dy)/x))
      end do
      ! 2 halves × (π/4) from the change of variable × a from dx = a cos θ dθ.
      s = 0.5_wp*pi*a*s
   end function influence

end module shcontact_normal_coupling
