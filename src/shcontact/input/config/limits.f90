!> Size limits of a case configuration: string lengths, list capacities, the most cases of a
!> run and the most grid cells of a patch (doc/app.md, "Limits").
module shcontact_input_config_limits
   use shcontact_core_ranges, only: max_grid_cells
   implicit none
   private

   public :: path_len, name_len, max_sweep_values, max_label_values, max_fields, max_cases
   public :: max_grid_cells, max_line_length

   !> Length of file-name variables.
   integer, parameter :: path_len = 512
   !> Length of choice variables (method names, modes).
   integer, parameter :: name_len = 32
   !> Most values one real sweep list may hold.
   integer, parameter :: max_sweep_values = 100000
   !> Most values one choice sweep list (bound, spin_model) may hold.
   integer, parameter :: max_label_values = 16
   !> Most entries of `output%fields`.
   integer, parameter :: max_fields = 16
   !> Most cases of one run (a sweep grid).
   integer, parameter :: max_cases = 100000000
   !> Longest line of a case file.
   integer, parameter :: max_line_length = 4095

end module shcontact_input_config_limits
