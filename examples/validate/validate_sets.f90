!> The summary of every exact-theory set (doc/validation.md §6.6, issue 28): per set its cases,
!> max |Δf| (the larger of max |Δf_x| and max |Δf_y|), P80 |Δf_x| and P80 |Δf_y| (nearest rank)
!> over ALL its cases pooled, for the defaults and the main alternatives (the normal reduction
!> `local-hertz`, the correction `none`), and the largest |f| = |F_t|/(μF_n). The runs of
!> validate_patches, validate_lobes and validate_kinematic hand their per-case errors to
!> [[pool_errors]]; [[write_sets]] writes sets.csv and sets.md.
module validate_sets
   use shcontact, only: wp, error_type, fatal_error
   use validate_csv, only: csv_writer_type
   use validate_tangential, only: error_stats_type, error_stats
   implicit none
   private

   public :: n_set_configs, set_config_labels, pool_errors, write_sets, set_all_positions, &
      set_two_lobe, declare_set

   !> The set of every project position (validate_patches' single-lobe ones and validate_lobes'
   !> two-lobe ones, as the wheel's Σ against CONTACT's joined patch).
   character(len=*), parameter :: set_all_positions = &
      'data/exact: all 21 positions (two-lobe ones as the wheel''s Σ)'
   !> The two-lobe positions (validate_lobes).
   character(len=*), parameter :: set_two_lobe = 'data/exact: the two-lobe positions 5.0, '// &
      '5.3 mm, the wheel''s Σ against CONTACT''s joined patch, DOE 6³ each'

   !> The configurations of the summary: the defaults, then one setting changed.
   integer, parameter :: n_set_configs = 3
   character(len=*), parameter :: set_config_labels(n_set_configs) = [character(len=28) :: &
      'defaults', 'normal reduction local-hertz', 'correction none']

   !> The per-case errors of one set and configuration.
   type :: pool_type
      real(wp), allocatable :: ex(:), ey(:)
      real(wp) :: f_max = 0.0_wp
      logical :: used = .false.
   end type pool_type

   !> One exact-theory set (a fixed-length name: gfortran 12 mishandles deferred-length
   !> character components in array assignments).
   type :: set_type
      character(len=160) :: name = ''
      type(pool_type) :: pool(n_set_configs)
   end type set_type

   !> Most sets.
   integer, parameter :: max_sets = 16
   !> The sets in the order they were first given (this program's only state).
   type(set_type), save :: sets(max_sets)
   integer, save :: n_sets = 0

contains

   !> Add cases to set `name` for configuration `config` (1 … n_set_configs): their |Δf_x|,
   !> |Δf_y| and their largest |f|.
   subroutine pool_errors(name, config, ex, ey, f_max)
      character(len=*), intent(in) :: name
      integer, intent(in) :: config
      real(wp), intent(in) :: ex(:), ey(:)
      real(wp), intent(in) :: f_max
      integer :: is

      is = set_index(name)
      ! Component by component, no associate: gfortran 12 does not reallocate an allocatable
      ! component through an associate name reliably.
      if (.not. sets(is)%pool(config)%used) then
         sets(is)%pool(config)%ex = ex
         sets(is)%pool(config)%ey = ey
         sets(is)%pool(config)%f_max = f_max
      else
         sets(is)%pool(config)%ex = [sets(is)%pool(config)%ex, ex]
         sets(is)%pool(config)%ey = [sets(is)%pool(config)%ey, ey]
         sets(is)%pool(config)%f_max = max(sets(is)%pool(config)%f_max, f_max)
      end if
      sets(is)%pool(config)%used = .true.
   end subroutine pool_errors

   !> Give set `name` its place in the tables now (sets are listed in the order of their first
   !> mention).
   subroutine declare_set(name)
      character(len=*), intent(in) :: name
      integer :: is
      is = set_index(name)
   end subroutine declare_set

   !> The index of set `name`, created when new.
   integer function set_index(name) result(is)
      character(len=*), intent(in) :: name
      integer :: k
      is = 0
      do k = 1, n_sets
         if (sets(k)%name == name) is = k
      end do
      if (is == 0) then
         if (n_sets == max_sets) error stop 'validate_sets: more than max_sets sets'
         n_sets = n_sets + 1
         sets(n_sets)%name = name
         is = n_sets
      end if
   end function set_index

   !> sets.csv (one row per set and configuration) and sets.md (one row per set, the
   !> configurations side by side).
   subroutine write_sets(out_dir, error)
      character(len=*), intent(in) :: out_dir
      type(error_type), allocatable, intent(out) :: error
      type(csv_writer_type) :: out
      type(error_stats_type) :: sx, sy
      character(len=2048) :: line, msg
      character(len=64) :: cell
      character(len=200) :: cells(2)
      integer :: is, ic, unit, stat

      if (n_sets == 0) return
      call out%open(out_dir//'sets.csv', 'set,configuration,n_cases,df_max,dfx_p80,dfy_p80,'// &
         'dfx_max,dfy_max,f_max', error)
      if (allocated(error)) return
      do is = 1, n_sets
         do ic = 1, n_set_configs
            if (.not. sets(is)%pool(ic)%used) cycle
            sx = error_stats(sets(is)%pool(ic)%ex)
            sy = error_stats(sets(is)%pool(ic)%ey)
            ! Cell by cell (an array constructor of character expressions overruns its buffer
            ! in gfortran 12).
            cells(1) = '"'//trim(sets(is)%name)//'"'
            cells(2) = set_config_labels(ic)
            call out%row([real(size(sets(is)%pool(ic)%ex), wp), max(sx%max, sy%max), sx%p80, &
               sy%p80, sx%max, sy%max, sets(is)%pool(ic)%f_max], text=cells, digits=4)
         end do
      end do
      call out%close()
      open (newunit=unit, file=out_dir//'sets.md', status='replace', action='write', &
         iostat=stat, iomsg=msg)
      if (stat /= 0) then
         call fatal_error(error, out_dir//'sets.md: cannot write ('//trim(msg)//')')
         return
      end if
      write (unit, '(a)') '<!-- written by `fpm run --example shcontact-validate --profile '// &
         'release` (sets.csv) -->', '', 'Every exact-theory set, all its cases pooled: '// &
         'max \|Δf\| ; P80 \|Δf_x\| / P80 \|Δf_y\| (largest \|f\|), f = F/(μF_n)', ''
      line = '| exact-theory set | cases |'
      do ic = 1, n_set_configs
         line = trim(line)//' '//trim(set_config_labels(ic))//' |'
      end do
      write (unit, '(a)') trim(line), '|---|---|'//repeat('---|', n_set_configs)
      do is = 1, n_sets
         write (cell, '(i0)') size(sets(is)%pool(1)%ex)
         line = '| '//trim(sets(is)%name)//' | '//trim(cell)//' |'
         do ic = 1, n_set_configs
            if (sets(is)%pool(ic)%used) then
               sx = error_stats(sets(is)%pool(ic)%ex)
               sy = error_stats(sets(is)%pool(ic)%ey)
               write (cell, '(3(f5.3,a),f7.5,a)') max(sx%max, sy%max), ' ; ', sx%p80, ' / ', &
                  sy%p80, ' (', sets(is)%pool(ic)%f_max, ') |'
               line = trim(line)//' '//trim(cell)
            else
               line = trim(line)//' — |'
            end if
         end do
         write (unit, '(a)') trim(line)
      end do
      close (unit)
   end subroutine write_sets

end module validate_sets
