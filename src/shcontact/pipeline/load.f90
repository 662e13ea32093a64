!> The load of one contact solve: its mode (a normal force, a vertical wheel load, an approach, a
!> vertical position or a normal force shared by the wheel's patches) and its value.
module shcontact_pipeline_load
   use shcontact_core_kinds, only: wp
   implicit none
   private

   public :: contact_load_type, load_normal_force, load_vertical_force, load_approach, &
      load_vertical_position, load_shared_force, load_mode_name, load_mode_names

   !> Load mode: normal force N (N) on the first (deepest) patch.
   integer, parameter :: load_normal_force = 1
   !> Load mode: vertical wheel load F_z (N) shared by all patches (doc/theory.md §4.6).
   integer, parameter :: load_vertical_force = 2
   !> Load mode: approach δ (mm) of the first patch.
   integer, parameter :: load_approach = 3
   !> Load mode: vertical position, the rigid vertical approach Δz (mm) of the wheel from first
   !> contact, shared by all patches (doc/theory.md §4.6).
   integer, parameter :: load_vertical_position = 4
   !> Load mode: normal force N (N) of the wheel's contact, shared by its patches through one
   !> rigid vertical approach, Σ_k N_k = N (doc/lobes.md, "A normal force shared by the patches").
   integer, parameter :: load_shared_force = 5
   character(len=*), parameter :: load_mode_names(5) = [character(len=19) :: 'normal force', &
      'vertical force', 'approach', 'vertical position', 'shared normal force']

   !> The load of one solve.
   type :: contact_load_type
      !> [[load_normal_force]], [[load_vertical_force]], [[load_approach]],
      !> [[load_vertical_position]] or [[load_shared_force]].
      integer :: mode = load_normal_force
      !> The force (N, > 0) or the approach (mm).
      real(wp) :: value = 0.0_wp
   end type contact_load_type

contains

   !> The name of a load mode, for messages.
   pure function load_mode_name(mode) result(name)
      !> A load mode code.
      integer, intent(in) :: mode
      character(len=:), allocatable :: name
      if (mode >= 1 .and. mode <= size(load_mode_names)) then
         name = trim(load_mode_names(mode))
      else
         name = 'unknown'
      end if
   end function load_mode_name

end module shcontact_pipeline_load
