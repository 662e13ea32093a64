!> The operations the benchmark times, one [[kernel_type]] each. Every kernel owns copies of its
!> inputs and its workspace, set up before timing, so that `run` is exactly the library call(s)
!> a user would make per wheel position, per load or per creepage set.
module bench_kernels
   use shcontact, only: wp, error_type, material_type, prepared_profiles_type, &
      wheelset_position_type, patch_geometry_type, find_contact_patches, normal_options_type, &
      normal_contact_type, prepare_normal_contact, solve_load, normal_patch_type, &
      tangential_options_type, march_workspace_type, prepare_fastsim, prepare_fastsim_sh, &
      creepage_type, tangential_patch_type
   use shcontact_tangential_march, only: solve_prepared
   use bench_timing, only: kernel_type
   implicit none
   private

   public :: geometry_kernel, normal_prepare_kernel, normal_load_kernel, sh_prepare_kernel, &
      fastsim_prepare_kernel, solve_kernel, full_case_kernel, n_load_steps, load_step

   !> The normal and full-case kernels cycle through this many loads around the nominal one, as
   !> a vehicle-dynamics run would (each solve starts from scratch: nothing is cached between
   !> loads).
   integer, parameter :: n_load_steps = 16

   !> Contact search and strip tables for one wheelset position (profiles prepared).
   type, extends(kernel_type) :: geometry_kernel
      type(prepared_profiles_type) :: profiles
      type(wheelset_position_type) :: position
      type(patch_geometry_type), allocatable :: patches(:)
   contains
      procedure :: run => run_geometry
   end type geometry_kernel

   !> Reduction of a patch geometry for the strip method (once per geometry).
   type, extends(kernel_type) :: normal_prepare_kernel
      type(patch_geometry_type) :: geometry
      type(normal_options_type) :: options
      type(material_type) :: material
      type(normal_contact_type) :: contact
   contains
      procedure :: run => run_normal_prepare
   end type normal_prepare_kernel

   !> The normal solve for a prescribed normal force on a prepared patch.
   type, extends(kernel_type) :: normal_load_kernel
      type(normal_contact_type) :: contact
      real(wp) :: load = 0.0_wp
      type(normal_patch_type) :: patch
   contains
      procedure :: run => run_normal_load
   end type normal_load_kernel

   !> Filling the FASTSIM_SH workspace from a normal patch (once per normal solution).
   type, extends(kernel_type) :: sh_prepare_kernel
      type(normal_patch_type) :: patch
      type(material_type) :: material
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
   contains
      procedure :: run => run_sh_prepare
   end type sh_prepare_kernel

   !> Filling the classical FASTSIM workspace for a Hertz ellipse.
   type, extends(kernel_type) :: fastsim_prepare_kernel
      real(wp) :: semi_a = 0.0_wp, semi_b = 0.0_wp, load = 0.0_wp, y_centre = 0.0_wp, &
         gamma0 = 0.0_wp
      integer :: n_strips = 0
      type(material_type) :: material
      type(tangential_options_type) :: options
      type(march_workspace_type) :: ws
   contains
      procedure :: run => run_fastsim_prepare
   end type fastsim_prepare_kernel

   !> One creepage set on a prepared workspace (FASTSIM_SH or FASTSIM alike).
   type, extends(kernel_type) :: solve_kernel
      type(march_workspace_type) :: ws
      type(creepage_type) :: creepage
      type(tangential_patch_type) :: result
   contains
      procedure :: run => run_solve
   end type solve_kernel

   !> A full case on reused geometry: normal solve for a load, FASTSIM_SH preparation, solve;
   !> or, when `classical`, the Hertz normal solve (the contact prepared with method 'hertz') and
   !> classical FASTSIM on its ellipse.
   type, extends(kernel_type) :: full_case_kernel
      logical :: classical = .false.
      integer :: n_strips = 0
      type(normal_contact_type) :: contact
      real(wp) :: load = 0.0_wp
      type(material_type) :: material
      type(tangential_options_type) :: options
      type(creepage_type) :: creepage
      type(normal_patch_type) :: patch
      type(march_workspace_type) :: ws
      type(tangential_patch_type) :: result
   contains
      procedure :: run => run_full_case
   end type full_case_kernel

contains

   !> The load of call k: the nominal load times 0.9 … 1.1 in n_load_steps steps.
   pure real(wp) function load_step(load, k)
      real(wp), intent(in) :: load
      integer, intent(in) :: k
      load_step = load*(0.9_wp + 0.2_wp*real(mod(k, n_load_steps), wp)/real(n_load_steps - 1, wp))
   end function load_step

   subroutine run_geometry(self, k)
      class(geometry_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call find_contact_patches(self%profiles, self%position, self%patches, error)
      call record(self, error)
   end subroutine run_geometry

   subroutine run_normal_prepare(self, k)
      class(normal_prepare_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call prepare_normal_contact(self%contact, self%geometry, self%options, self%material, error)
      call record(self, error)
   end subroutine run_normal_prepare

   subroutine run_normal_load(self, k)
      class(normal_load_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call solve_load(self%contact, load_step(self%load, k), self%patch, error)
      call record(self, error)
   end subroutine run_normal_load

   subroutine run_sh_prepare(self, k)
      class(sh_prepare_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call prepare_fastsim_sh(self%ws, self%patch, self%material, self%options, error)
      call record(self, error)
   end subroutine run_sh_prepare

   subroutine run_fastsim_prepare(self, k)
      class(fastsim_prepare_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call prepare_fastsim(self%ws, self%semi_a, self%semi_b, self%load, self%material, &
         self%options, self%n_strips, error, y_centre=self%y_centre, gamma0=self%gamma0)
      call record(self, error)
   end subroutine run_fastsim_prepare

   subroutine run_solve(self, k)
      class(solve_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call solve_prepared(self%ws, self%creepage, self%result, error)
      call record(self, error)
   end subroutine run_solve

   subroutine run_full_case(self, k)
      class(full_case_kernel), intent(inout) :: self
      integer, intent(in) :: k
      type(error_type), allocatable :: error
      call solve_load(self%contact, load_step(self%load, k), self%patch, error)
      if (allocated(error)) then
         call record(self, error)
         return
      end if
      if (self%classical) then
         call prepare_fastsim(self%ws, self%patch%ellipse_a, self%patch%ellipse_b, &
            self%patch%load, self%material, self%options, self%n_strips, error, &
            y_centre=self%patch%ellipse_y_centre, gamma0=self%patch%gamma0)
      else
         call prepare_fastsim_sh(self%ws, self%patch, self%material, self%options, error)
      end if
      if (.not. allocated(error)) call solve_prepared(self%ws, self%creepage, self%result, error)
      call record(self, error)
   end subroutine run_full_case

   !> Keep the first library error of a kernel.
   subroutine record(kernel, error)
      class(kernel_type), intent(inout) :: kernel
      type(error_type), allocatable, intent(in) :: error
      if (.not. allocated(error) .or. kernel%failed) return
      kernel%failed = .true.
      kernel%message = error%message
   end subroutine record

end module bench_kernels
