!> Tangential runs of the validation: many creepage cases on one fixed normal patch (the
!> reference's module-3 set-up, README §2), by FASTSIM_SH on the strip table or by classical
!> FASTSIM on the Hertz ellipse, and the error statistics against the exact theory.
!>
!> **Sign mapping.** The reference gives CONTACT's rail side: creepages of the rail relative to
!> the wheel, forces on the rail. We solve the same physical case from the wheel's side (doc/theory.md
!> decision 2): creepages −ν_ref, and compare −F (the force on the rail) with F_ref. With the
!> uniform spin model the solver is odd in the creepages, so this equals "same numbers in, same
!> numbers out" to round-off; the other spin models add the geometric spin variation of the wheel
!> (φ_geo,i = sin γ_i / r₀, wheel relative to rail), which only the physical mapping puts on the
!> right side.
module validate_tangential
   use shcontact, only: wp, error_type, fatal_error, stat_invalid_input, material_type, &
      normal_patch_type, tangential_options_type, march_workspace_type, tangential_patch_type, &
      creepage_type, prepare_fastsim, prepare_fastsim_sh
   use shcontact_tangential_march, only: solve_prepared
   use shcontact_tangential_options, only: method_fastsim
   use validate_csv, only: csv_table_type, read_csv, column
   implicit none
   private

   public :: case_set_type, read_case_set, solve_set, abs_errors, error_stats_type, error_stats
   public :: nearest_rank, sort_ascending

   !> Creepage cases with the reference's normalised forces.
   type :: case_set_type
      !> Name (the reference file's base name without the method).
      character(len=:), allocatable :: name
      !> CONTACT's creepages (rail relative to wheel): ν_x, ν_y (dimensionless), φ (rad/mm).
      real(wp), allocatable :: nux(:), nuy(:), phi(:)
      !> Reference f_x = F_x/(μF_n), f_y (forces on the rail).
      real(wp), allocatable :: fx(:), fy(:)
   end type case_set_type

   !> Statistics of absolute errors.
   type :: error_stats_type
      !> Largest, 80th percentile (nearest rank), mean.
      real(wp) :: max = 0.0_wp, p80 = 0.0_wp, mean = 0.0_wp
   end type error_stats_type

contains

   !> Read a reference sweep or DOE file (README §3 columns; φ in 1/m converted to rad/mm).
   subroutine read_case_set(path, name, set, error)
      !> The file.
      character(len=*), intent(in) :: path
      !> The set's name.
      character(len=*), intent(in) :: name
      !> The cases.
      type(case_set_type), intent(out) :: set
      !> Set when the file cannot be read.
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: table

      set%name = name
      call read_csv(path, table, error)
      if (allocated(error)) return
      call column(table, 'nux', set%nux, error)
      if (allocated(error)) return
      call column(table, 'nuy', set%nuy, error)
      if (allocated(error)) return
      call column(table, 'phi_1_per_m', set%phi, error)
      if (allocated(error)) return
      set%phi = 1.0e-3_wp*set%phi
      call column(table, 'fx', set%fx, error)
      if (allocated(error)) return
      call column(table, 'fy', set%fy, error)
   end subroutine read_case_set

   !> Solve every case of a set on one normal patch, mapped as the module text says: FASTSIM_SH
   !> on the strip table, or classical FASTSIM on the patch's Hertz ellipse when options%method
   !> asks for it (the patch must then be a Hertz solution).
   subroutine solve_set(patch, material, options, set, fx, fy, error, adhesion)
      !> The normal solution (fixed for all cases).
      type(normal_patch_type), intent(in) :: patch
      !> G, ν, μ.
      type(material_type), intent(in) :: material
      !> Tangential options (fields are not needed: set .false. for speed).
      type(tangential_options_type), intent(in) :: options
      !> The cases.
      type(case_set_type), intent(in) :: set
      !> f_x, f_y on the rail, one per case.
      real(wp), allocatable, intent(out) :: fx(:), fy(:)
      !> Set for invalid input.
      type(error_type), allocatable, intent(out) :: error
      !> Adhesion area fraction per case.
      real(wp), allocatable, intent(out), optional :: adhesion(:)
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
      integer :: i, n

      call prepare(ws, patch, material, options, error)
      if (allocated(error)) return
      n = size(set%nux)
      allocate (fx(n), fy(n))
      if (present(adhesion)) allocate (adhesion(n))
      do i = 1, n
         call solve_prepared(ws, creepage_type(-set%nux(i), -set%nuy(i), -set%phi(i)), result, &
            error)
         if (allocated(error)) return
         fx(i) = -result%fx_norm
         fy(i) = -result%fy_norm
         if (present(adhesion)) adhesion(i) = result%adhesion_fraction
      end do
   end subroutine solve_set

   !> Fill the workspace for FASTSIM_SH or, with options%method = 'fastsim', for classical FASTSIM
   !> on the Hertz ellipse of the patch (centred at the reference point).
   subroutine prepare(ws, patch, material, options, error)
      type(march_workspace_type), intent(inout) :: ws
      type(normal_patch_type), intent(in) :: patch
      type(material_type), intent(in) :: material
      type(tangential_options_type), intent(in) :: options
      type(error_type), allocatable, intent(out) :: error
      if (options%method == method_fastsim) then
         if (.not. patch%is_hertz) then
            call fatal_error(error, 'classical FASTSIM needs a Hertz normal solution', &
               stat_invalid_input)
            return
         end if
         call prepare_fastsim(ws, patch%ellipse_a, patch%ellipse_b, patch%load, material, &
            options, patch%n_strips, error, y_centre=patch%ellipse_y_centre, gamma0=patch%gamma0)
      else
         call prepare_fastsim_sh(ws, patch, material, options, error)
      end if
   end subroutine prepare

   !> |ours − reference| element by element.
   pure function abs_errors(ours, reference) result(e)
      !> Our values.
      real(wp), intent(in) :: ours(:)
      !> Reference values (same size).
      real(wp), intent(in) :: reference(:)
      real(wp) :: e(size(ours))
      e = abs(ours - reference)
   end function abs_errors

   !> Largest, 80th percentile (nearest rank) and mean of absolute errors.
   pure function error_stats(e) result(stats)
      !> Absolute errors (at least one).
      real(wp), intent(in) :: e(:)
      type(error_stats_type) :: stats
      real(wp) :: sorted(size(e))
      sorted = e
      call sort_ascending(sorted)
      stats%max = sorted(size(e))
      stats%p80 = nearest_rank(sorted, 0.8_wp)
      stats%mean = sum(e)/size(e)
   end function error_stats

   !> The nearest-rank percentile of sorted values: the smallest value with at least a fraction
   !> q of the values at or below it (q = 0 gives the smallest).
   pure real(wp) function nearest_rank(sorted, q)
      !> Values in ascending order.
      real(wp), intent(in) :: sorted(:)
      !> Fraction 0..1.
      real(wp), intent(in) :: q
      integer :: k
      k = min(size(sorted), max(1, ceiling(q*size(sorted) - 1.0e-9_wp)))
      nearest_rank = sorted(k)
   end function nearest_rank

   !> Sort in place, ascending (insertion sort within a shell sort: the sets hold ≤ 10⁴ values).
   pure subroutine sort_ascending(values)
      !> The values.
      real(wp), intent(inout) :: values(:)
      integer :: gap, i, j
      real(wp) :: v
      gap = size(values)/2
      do while (gap > 0)
         do i = gap + 1, size(values)
            v = values(i)
            j = i
            do while (j > gap)
               if (values(j - gap) <= v) exit
               values(j) = values(j - gap)
               j = j - gap
            end do
            values(j) = v
         end do
         gap = gap/2
      end do
   end subroutine sort_ascending

end module validate_tangential
