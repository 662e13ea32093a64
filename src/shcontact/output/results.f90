!> The layout of shcontact's HDF5 result files, and the merge of several files of one run
!> (shards, checkpoint blocks) into one.
!>
!> Every result file of a run has the same layout, whatever subset of cases it holds:
!>
!>     /                     attributes: software, version, date, command_line, units,
!>                           sign_convention, n_cases (cases of the whole run), cases_in_file
!>                           (and shard = 'I/N' in a shard file)
!>     /input/namelist       the resolved configuration (namelist text)
!>     /input/profiles/wheel, rail       (n, 2) arrays of y, z (mm), attribute `source`; scales
!>                           wheel_point, rail_point, column
!>     /geometry/patch_K/... the patch geometry tables, when every case shares them
!>     /summary/...          one row per case: case, status, n_patches (found), n_loaded
!>                           (solved; /cases/.../patch_1..n_loaded), main_patch, a column
!>                           per swept input (and per wheelset input of a kinematic run), a
!>                           column per result (totals in the track frame, the main patch's
!>                           forces, normalised forces...; its creepages in a kinematic run)
!>     /failures/case, message           the cases that failed, and why
!>     /cases/NNNNNN/patch_K/{geometry,normal,tangential}/...   per-case fields, when asked
!>
!> Every dataset has a `units` attribute ('1' for dimensionless numbers, '' for text) and a
!> `long_name` saying what it is (shcontact_output_descriptions). Dimension scales (HDF5 H5DS) tie
!> the tables to their coordinate: the summary columns to `summary/case`, the strip tables to
!> their `y`, the element fields (pn, px, py, slip, state, x, xy) to the strip centres `y`
!> along their strip dimension and to `element` along the other (xy's components to
!> `component`): every dimension has its scale (xarray opens the groups). Every dimension is
!> labelled, and the fields' `coordinates` attribute names x (2-D) and y. `xy` holds the
!> element centres (x, y) interleaved, the mesh of the XDMF sidecar. The root also records
!> provenance:
!> git_revision, compiler, compiler_options, host, threads (shcontact_output_provenance).
!> The final file of a run (a merge) gets an XDMF sidecar NAME.xmf (shcontact_output_xdmf) when it
!> holds element fields, so ParaView opens them directly. A merge
!> of the files of one run is identical, dataset for dataset, to the file of an uninterrupted,
!> unsharded run: the summary rows are gathered in case order and the per-case groups copied.
module shcontact_output_results
   use shcontact_core_kinds, only: wp, i1
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_version_info, only: shcontact_version
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_normal_patch, only: normal_patch_type
   use shcontact_tangential_patch, only: tangential_patch_type, state_exterior, &
      state_adhesion, state_slip
   use shcontact_input_config, only: case_config_type, read_config_text, n_sweep_axes, &
      sweep_axis_names, axis_geometry, case_point_type, case_point_value, &
      case_point_label, precision_single
   use shcontact_output_hdf5, only: h5_file_type, h5_create, h5_commit, h5_discard, h5_open, &
      h5_close, h5_write, h5_write_attribute, h5_make_group, h5_copy, h5_exists, h5_read, &
      h5_read_attribute, h5_set_scale, h5_attach_scale, h5_set_dim_label, h5_delete_attribute
   use shcontact_output_descriptions, only: describe_dataset
   use shcontact_output_provenance, only: git_revision, build_compiler, build_flags, host_name, &
      available_threads
   use shcontact_output_xdmf, only: write_xdmf_sidecar, xdmf_name, is_xdmf_sidecar
   use shcontact_core_files, only: delete_file
   use shcontact_output_output_checks, only: check_output_file, check_layout
   use shcontact_core_strings, only: str_int
   use shcontact_core_text, only: string_type, string_list_type
   use shcontact_case_result, only: case_summary_type, case_result_type, summary_columns, &
      n_summary_columns, summary_value, set_summary_value, case_not_run, summary_column_used, &
      failure_type, summary_column_counts
   implicit none
   private

   public :: run_info_type, write_result_file, begin_run_file, end_run_file, &
      end_summary_file, merge_result_files, read_result_summary
   public :: check_output_file
   public :: case_group_name, units_text, sign_convention_text

   !> The units system, stored as a root attribute (doc/theory.md decision 1).
   character(len=*), parameter :: units_text = 'mm, N, MPa (N/mm^2), rad; creepages '// &
      'dimensionless, spin creepage rad/mm; forces N, moments N mm'
   !> The sign convention, stored as a root attribute (doc/theory.md decision 2).
   character(len=*), parameter :: sign_convention_text = 'body 1 = wheel, body 2 = rail. '// &
      'Creepages: velocity of the wheel surface relative to the rail surface at the '// &
      'geometric contact point divided by the rolling speed, in the contact frame (x rolling '// &
      'direction, y lateral in the tangent plane towards the field side, z = x cross y into '// &
      'the rail). Tractions and forces act on the wheel (F_x = -G c^2 c11 nu_x in linear '// &
      'theory). CONTACT reports the rail side of both: both signs flip.'

   !> Tables of a patch geometry group, of the normal strips and element fields: the datasets
   !> their group's `y` is the dimension scale of.
   !> The profiles under /input/profiles.
   character(len=*), parameter :: profile_names(2) = ['wheel', 'rail ']
   character(len=*), parameter :: geometry_tables(5) = [character(len=8) :: 'gap', 'curv_a', &
      'curv_b', 'gamma', 'r_wheel']
   character(len=*), parameter :: strip_tables(10) = [character(len=10) :: 'a', 'k', 'p0', &
      'strip_load', 'm', 'n', 'eps_a', 'gamma', 'delta_r', 'r_wheel']
   character(len=*), parameter :: element_fields(6) = [character(len=5) :: 'x', 'pn', 'px', &
      'py', 'slip', 'state']

   !> The fields a configuration stores, looked up once per file (not per case).
   type :: field_choice_type
      logical :: any = .false., geometry = .false., strips = .false., pressure = .false.
      logical :: traction = .false., slip = .false., state = .false., elements = .false.
   end type field_choice_type

   !> What every result file of a run carries besides the cases.
   type :: run_info_type
      !> The resolved configuration as namelist text.
      character(len=:), allocatable :: namelist
      !> The command that produced the file, and when (ISO 8601).
      character(len=:), allocatable :: command_line, date
      !> Number of cases of the whole run.
      integer :: n_cases = 1
      !> 'I/N' for a shard file, '' otherwise.
      character(len=:), allocatable :: shard
      !> The profiles used (wheel, rail), when loaded.
      type(profile_type), allocatable :: profiles(:)
      !> The patch geometry, when every case shares it.
      type(patch_geometry_type), allocatable :: geometry(:)
      !> OpenMP threads of the run (0: those available when the file is written).
      integer :: threads = 0
   end type run_info_type

contains

   !> Group of case `icase` ('cases/000042'); at least six digits, more for huge runs.
   pure function case_group_name(icase, n_cases) result(name)
      !> Case index.
      integer, intent(in) :: icase
      !> Cases of the run (sets the width).
      integer, intent(in) :: n_cases
      character(len=:), allocatable :: name
      integer :: width, i, v
      ! Digits written by hand: this runs once per case when a file is written or merged,
      ! where a formatted internal write cost more than the rest of the merge.
      width = 6
      v = n_cases/1000000
      do while (v > 0)
         width = width + 1
         v = v/10
      end do
      allocate (character(len=6 + width) :: name)
      name(1:6) = 'cases/'
      v = abs(icase)
      do i = 6 + width, 7, -1
         name(i:i) = achar(iachar('0') + mod(v, 10))
         v = v/10
      end do
   end function case_group_name

   !> The fields `config` stores.
   pure function field_choice(config) result(f)
      type(case_config_type), intent(in) :: config
      type(field_choice_type) :: f
      f%geometry = config%wants_field('geometry')
      f%strips = config%wants_field('strips')
      f%pressure = config%wants_field('pressure')
      f%traction = config%wants_field('traction')
      f%slip = config%wants_field('slip')
      f%state = config%wants_field('state')
      f%elements = f%pressure .or. f%traction .or. f%slip .or. f%state
      f%any = f%elements .or. f%geometry .or. f%strips
      ! Per-case geometry only when the sweep moves the wheelset (else /geometry holds it).
      f%geometry = f%geometry .and. config%geometry_swept()
   end function field_choice

   !> Write one result file holding the cases `results` (case numbers `indices`), under a
   !> temporary name renamed when complete.
   subroutine write_result_file(name, info, config, indices, results, error, temp_name, &
                                checkpoint)
      !> File name.
      character(len=*), intent(in) :: name
      !> Run information (header, profiles, common geometry).
      type(run_info_type), intent(in) :: info
      !> The configuration (fields, compression, sweep axes).
      type(case_config_type), intent(in) :: config
      !> Case numbers of the results, ascending.
      integer, intent(in) :: indices(:)
      !> The results.
      type(case_result_type), intent(in) :: results(:)
      !> Set on failure; no file is left under `name` then.
      type(error_type), allocatable, intent(out) :: error
      !> Temporary name (default `name.tmp<pid>`).
      character(len=*), intent(in), optional :: temp_name
      !> A checkpoint block: no dimension scales (the merge attaches them in the final file;
      !> making them was a third of a summary-only block's cost).
      logical, intent(in), optional :: checkpoint
      type(h5_file_type) :: file
      call begin_result_file(file, name, info, config, size(indices), error, temp_name, &
         checkpoint)
      if (.not. allocated(error)) call end_result_file(file, info, config, indices, results, &
         error)
   end subroutine write_result_file

   !> Create a result file (under its temporary name) and write its header: root attributes,
   !> /input and the common /geometry ([[end_result_file]] adds the cases and commits it).
   subroutine begin_result_file(file, name, info, config, cases_in_file, error, temp_name, &
                                checkpoint)
      !> The file, open for writing.
      type(h5_file_type), intent(out) :: file
      !> File name.
      character(len=*), intent(in) :: name
      !> Run information (header, profiles, common geometry).
      type(run_info_type), intent(in) :: info
      !> The configuration (compression, precision).
      type(case_config_type), intent(in) :: config
      !> The number of cases the file will hold.
      integer, intent(in) :: cases_in_file
      !> Set on failure; no file is left then.
      type(error_type), allocatable, intent(out) :: error
      !> Temporary name (default `name.tmp<pid>`).
      character(len=*), intent(in), optional :: temp_name
      !> A checkpoint block: no dimension scales.
      logical, intent(in), optional :: checkpoint
      logical :: scales
      scales = .true.
      if (present(checkpoint)) scales = .not. checkpoint
      call h5_create(file, name, error, compression=config%output%compression, &
         single=config%output%precision == precision_single, temp_name=temp_name, &
         describe=describe_dataset, scales=scales)
      if (allocated(error)) return
      call write_header(file, info, cases_in_file, error)
      if (allocated(error)) call h5_discard(file)
   end subroutine begin_result_file

   !> Write the cases `results` (case numbers `indices`) into a file begun by
   !> [[begin_result_file]] and commit it under its name (discarded on failure).
   subroutine end_result_file(file, info, config, indices, results, error)
      !> The file (closed on return).
      type(h5_file_type), intent(inout) :: file
      !> Run information (the number of cases of the run).
      type(run_info_type), intent(in) :: info
      !> The configuration (fields, sweep axes).
      type(case_config_type), intent(in) :: config
      !> Case numbers of the results, ascending.
      integer, intent(in) :: indices(:)
      !> The results.
      type(case_result_type), intent(in) :: results(:)
      !> Set on failure; no file is left then.
      type(error_type), allocatable, intent(out) :: error
      type(case_summary_type), allocatable :: summaries(:)
      type(field_choice_type) :: fields
      integer :: i

      fields = field_choice(config)
      summaries = results%summary
      call write_summary(file, config, indices, summaries, error)
      if (.not. allocated(error)) call write_failures(file, indices, results, error)
      do i = 1, size(results)
         if (allocated(error)) exit
         if (.not. fields%any) exit
         call write_case(file, fields, case_group_name(indices(i), info%n_cases), results(i), &
            error)
      end do
      if (allocated(error)) then
         call h5_discard(file)
         return
      end if
      call commit_output(file, error)
   end subroutine end_result_file

   !> Root attributes, /input and the common /geometry.
   subroutine write_header(file, info, cases_in_file, error)
      type(h5_file_type), intent(in) :: file
      type(run_info_type), intent(in) :: info
      integer, intent(in) :: cases_in_file
      type(error_type), allocatable, intent(out) :: error
      integer :: k

      call write_root_attributes(file, info, cases_in_file, error)
      if (allocated(error)) return
      call h5_write(file, 'input/namelist', info%namelist, error)
      if (allocated(error)) return
      if (allocated(info%profiles)) then
         do k = 1, min(2, size(info%profiles))
            call write_profile(file, 'input/profiles/'//trim(profile_names(k)), &
               info%profiles(k), error)
            if (allocated(error)) return
         end do
         call h5_write(file, 'input/profiles/column', [character(len=1) :: 'y', 'z'], error)
         if (.not. allocated(error)) call attach_profile_scales(file, error)
         if (allocated(error)) return
      end if
      if (allocated(info%geometry)) then
         do k = 1, size(info%geometry)
            call write_geometry(file, 'geometry/patch_'//str_int(k), info%geometry(k), error)
            if (allocated(error)) return
         end do
      end if
   end subroutine write_header

   subroutine write_root_attributes(file, info, cases_in_file, error)
      type(h5_file_type), intent(in) :: file
      type(run_info_type), intent(in) :: info
      integer, intent(in) :: cases_in_file
      type(error_type), allocatable, intent(out) :: error
      call h5_write_attribute(file, '/', 'software', 'shcontact', error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'version', &
         shcontact_version, error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'date', info%date, error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'command_line', &
         info%command_line, error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'units', units_text, error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'sign_convention', &
         sign_convention_text, error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'n_cases', info%n_cases, &
         error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'cases_in_file', &
         cases_in_file, error)
      if (allocated(info%shard)) then
         if (len(info%shard) > 0 .and. .not. allocated(error)) &
            call h5_write_attribute(file, '/', 'shard', info%shard, error)
      end if
      if (.not. allocated(error)) call write_provenance(file, info, error)
   end subroutine write_root_attributes

   !> Where the file comes from: sources, compiler and flags, host, threads.
   subroutine write_provenance(file, info, error)
      type(h5_file_type), intent(in) :: file
      type(run_info_type), intent(in) :: info
      type(error_type), allocatable, intent(out) :: error
      integer :: threads
      threads = info%threads
      if (threads <= 0) threads = available_threads()
      call h5_write_attribute(file, '/', 'git_revision', git_revision(), error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'compiler', &
         build_compiler(), error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'compiler_options', &
         build_flags(), error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'host', host_name(), error)
      if (.not. allocated(error)) call h5_write_attribute(file, '/', 'threads', threads, error)
   end subroutine write_provenance

   !> Make `group/scale` a dimension scale and attach it to dimension `dim` of those datasets
   !> of `names` that exist in the group (their earlier attachments are dropped first, unless
   !> `keep` is true: a second dimension of the same datasets).
   subroutine attach_scale(file, group, scale, dimension_name, names, dim, error, keep)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: group, scale, dimension_name
      character(len=*), intent(in) :: names(:)
      integer, intent(in) :: dim
      type(error_type), allocatable, intent(out) :: error
      logical, intent(in), optional :: keep
      character(len=*), parameter :: scale_attributes(3) = [character(len=14) :: &
         'REFERENCE_LIST', 'CLASS', 'NAME']
      integer :: i
      logical :: keep_attached
      if (.not. file%scales) return
      keep_attached = .false.
      if (present(keep)) keep_attached = keep
      if (.not. h5_exists(file, group//'/'//scale)) return
      ! A group copied from another file keeps its attributes but not the objects their
      ! references point to: start afresh.
      do i = 1, size(scale_attributes)
         call h5_delete_attribute(file, group//'/'//scale, trim(scale_attributes(i)), error)
         if (allocated(error)) return
      end do
      call h5_set_scale(file, group//'/'//scale, dimension_name, error)
      do i = 1, size(names)
         if (allocated(error)) return
         if (.not. h5_exists(file, group//'/'//trim(names(i)))) cycle
         if (.not. keep_attached) call h5_delete_attribute(file, group//'/'//trim(names(i)), &
            'DIMENSION_LIST', error)
         if (.not. allocated(error)) call h5_attach_scale(file, group//'/'//trim(names(i)), &
            group//'/'//scale, dim, error)
      end do
   end subroutine attach_scale

   !> The dimension scales of a patch group (`.../patch_K` with geometry, normal, tangential),
   !> or of a common geometry group (`geometry/patch_K`): again after a copy between files.
   subroutine attach_patch_scales(file, patch, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: patch
      type(error_type), allocatable, intent(out) :: error
      call attach_scale(file, patch, 'y', 'y (lateral, from the reference point)', &
         geometry_tables, 1, error)
      if (.not. allocated(error)) call attach_scale(file, patch//'/geometry', 'y', &
         'y (lateral, from the reference point)', geometry_tables, 1, error)
      if (.not. allocated(error)) call attach_scale(file, patch//'/normal', 'y', &
         'y (strip centre)', strip_tables, 1, error)
      if (.not. allocated(error)) call attach_field_scales(file, patch//'/tangential', error)
   end subroutine attach_patch_scales

   !> Scales of the element fields of a tangential group: y on the strip dimension (and dx's),
   !> `element` on the element dimension, `component` on the first dimension of `xy` (every
   !> dimension has its scale, so netCDF readers such as xarray open the group).
   subroutine attach_field_scales(file, path, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(error_type), allocatable, intent(out) :: error
      if (.not. file%scales) return
      if (.not. h5_exists(file, path//'/xy')) return
      call attach_scale(file, path, 'y', 'strip (y, lateral)', element_fields, 2, error)
      if (.not. allocated(error)) call attach_scale(file, path, 'element', &
         'element (j from the leading edge)', element_fields, 1, error, keep=.true.)
      if (allocated(error)) return
      call h5_delete_attribute(file, path//'/xy', 'DIMENSION_LIST', error)
      if (.not. allocated(error)) call h5_attach_scale(file, path//'/xy', path//'/y', 3, error)
      if (.not. allocated(error)) call h5_delete_attribute(file, path//'/dx', 'DIMENSION_LIST', &
         error)
      if (.not. allocated(error)) call h5_attach_scale(file, path//'/dx', path//'/y', 1, error)
      if (.not. allocated(error) .and. h5_exists(file, path//'/element')) &
         call h5_attach_scale(file, path//'/xy', path//'/element', 2, error)
      if (.not. allocated(error)) call attach_scale(file, path, 'component', 'x, y', &
         [character(len=2) :: 'xy'], 1, error, keep=.true.)
   end subroutine attach_field_scales

   !> Scales of the profiles (n, 2) under /input/profiles: `column` ('y', 'z') and the point
   !> indices `wheel_point`, `rail_point` (0, 1, ...); again after a copy between files.
   subroutine attach_profile_scales(file, error)
      type(h5_file_type), intent(in) :: file
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: group = 'input/profiles'
      call attach_scale(file, group, 'column', 'y, z', [character(len=5) :: 'wheel', 'rail'], &
         1, error)
      if (.not. allocated(error)) call attach_scale(file, group, 'wheel_point', &
         'point of the wheel profile', ['wheel'], 2, error, keep=.true.)
      if (.not. allocated(error)) call attach_scale(file, group, 'rail_point', &
         'point of the rail profile', ['rail'], 2, error, keep=.true.)
   end subroutine attach_profile_scales

   !> A profile as an (n, 2) array of (y, z) seen from C/h5py.
   !> The profiles a result file holds under /input/profiles (the points as the run read them):
   !> y, z of the wheel then of the rail, each preceded by its point count (−1 when the file
   !> holds none: a library caller's file), to tell two runs apart that name the same files.
   subroutine read_input_profiles(name, points, error)
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(out) :: points(:)
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: file
      real(wp), allocatable :: yz(:, :)
      character(len=:), allocatable :: path
      integer :: k
      allocate (points(0))
      call h5_open(file, name, error)
      if (allocated(error)) return
      do k = 1, size(profile_names)
         path = 'input/profiles/'//trim(profile_names(k))
         if (.not. h5_exists(file, path)) then
            points = [points, -1.0_wp]
            cycle
         end if
         call h5_read(file, path, yz, error)
         if (allocated(error)) exit
         points = [points, real(size(yz), wp), reshape(yz, [size(yz)])]
      end do
      call h5_close(file)
   end subroutine read_input_profiles

   subroutine write_profile(file, path, profile, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(profile_type), intent(in) :: profile
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: yz(:, :)
      integer :: n, i
      n = profile%size()
      allocate (yz(2, n))
      if (n > 0) then
         yz(1, :) = profile%y
         yz(2, :) = profile%z
      end if
      call h5_write(file, path, yz, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'_point', [(i - 1, i = 1, n)], '1', &
         error)
      if (allocated(error)) return
      call h5_write_attribute(file, path, 'columns', 'y (lateral, to the field side), '// &
         'z (vertical, positive downward)', error)
      if (allocated(error)) return
      if (allocated(profile%source)) then
         call h5_write_attribute(file, path, 'source', profile%source, error)
      else
         call h5_write_attribute(file, path, 'source', '', error)
      end if
   end subroutine write_profile

   !> The patch geometry tables and reference point.
   subroutine write_geometry(file, path, g, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(patch_geometry_type), intent(in) :: g
      type(error_type), allocatable, intent(out) :: error
      if (.not. allocated(g%y)) then
         call h5_make_group(file, path, error)
         return
      end if
      call h5_write(file, path//'/y', g%y, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gap', g%gap, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/curv_a', g%curv_a, '1/mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/curv_b', g%curv_b, '1/mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma', g%gamma, 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/r_wheel', g%r_wheel, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_track', g%y_track, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/z_track', g%z_track, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_rail', g%y_rail, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_wheel', g%y_wheel, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma0', g%gamma0, 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/r0', g%r0, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gap0', g%gap0, 'mm', error)
      if (.not. allocated(error)) call attach_scale(file, path, 'y', 'y (lateral, from the '// &
         'reference point)', geometry_tables, 1, error)
   end subroutine write_geometry

   !> The /summary table: one row per case of the file.
   subroutine write_summary(file, config, indices, summaries, error)
      type(h5_file_type), intent(in) :: file
      type(case_config_type), intent(in) :: config
      integer, intent(in) :: indices(:)
      type(case_summary_type), intent(in) :: summaries(:)
      type(error_type), allocatable, intent(out) :: error
      real(wp), allocatable :: values(:, :), inputs(:, :)
      character(len=32), allocatable :: labels(:, :)
      type(case_point_type) :: p
      integer :: ia, i, k, n_in
      integer, allocatable :: axes(:), slot(:)
      character(len=:), allocatable :: name
      integer, allocatable :: ints(:)

      call h5_write(file, 'summary/case', indices, '1', error)
      ints = summaries%stat
      if (.not. allocated(error)) call h5_write(file, 'summary/status', ints, '1', error)
      ints = summaries%n_patches
      if (.not. allocated(error)) call h5_write(file, 'summary/n_patches', ints, '1', error)
      ints = summaries%n_loaded
      if (.not. allocated(error)) call h5_write(file, 'summary/n_loaded', ints, '1', error)
      ints = summaries%main_patch
      if (.not. allocated(error)) call h5_write(file, 'summary/main_patch', ints, '1', error)
      if (allocated(error)) return
      ! The reported inputs, each case's point built once (not once per column).
      axes = pack([(ia, ia=1, n_sweep_axes)], [(config%reports_input(ia), ia=1, n_sweep_axes)])
      n_in = size(axes)
      ! Column of each reported input in `inputs` or (text inputs) in `labels`.
      allocate (slot(n_in))
      do k = 1, n_in
         if (config%sweep%axes(axes(k))%is_label) then
            slot(k) = count([(config%sweep%axes(axes(i))%is_label, i=1, k)])
         else
            slot(k) = count([(.not. config%sweep%axes(axes(i))%is_label, i=1, k)])
         end if
      end do
      allocate (inputs(size(indices), count(.not. [(config%sweep%axes(axes(k))%is_label, &
         k=1, n_in)])), labels(size(indices), count([(config%sweep%axes(axes(k))%is_label, &
         k=1, n_in)])))
      ! The numeric rows are built by the run's threads (the file is then written by one). The
      ! labels are not: a call of a function with a deferred-length result (case_point_label)
      ! keeps the result's length in a static variable of the calling procedure under gfortran
      ! 12, so two threads at that call would race (doc/performance.md, "Threads and strings").
      !$omp parallel do default(none) schedule(static) shared(indices, n_in, config, axes, &
      !$omp inputs, slot) private(i, k, p)
      do i = 1, size(indices)
         if (n_in == 0) cycle
         p = config%case_point(indices(i))
         do k = 1, n_in
            if (.not. config%sweep%axes(axes(k))%is_label) inputs(i, slot(k)) = &
               case_point_value(p, axes(k))
         end do
      end do
      !$omp end parallel do
      if (size(labels, 2) > 0) then
         do i = 1, size(indices)
            p = config%case_point(indices(i))
            do k = 1, n_in
               if (config%sweep%axes(axes(k))%is_label) labels(i, slot(k)) = &
                  case_point_label(p, axes(k))
            end do
         end do
      end if
      do k = 1, n_in
         ia = axes(k)
         name = trim(sweep_axis_names(ia))
         if (config%sweep%axes(ia)%is_label) then
            call h5_write(file, 'summary/'//name, labels(:, slot(k)), error)
         else
            call h5_write(file, 'summary/'//name, inputs(:, slot(k)), axis_units(name), error)
         end if
         if (allocated(error)) return
      end do
      allocate (values(size(summaries), n_summary_columns))
      !$omp parallel do default(none) schedule(static) shared(summaries, values) private(i, k)
      do i = 1, size(summaries)
         do k = 1, n_summary_columns
            values(i, k) = summary_value(summaries(i), k)
         end do
      end do
      !$omp end parallel do
      do k = 1, n_summary_columns
         if (.not. summary_column_used(k, config%is_kinematic())) cycle
         if (summary_column_counts(k)) then
            ints = nint(values(:, k))
            call h5_write(file, 'summary/'//trim(summary_columns(1, k)), ints, &
               trim(summary_columns(2, k)), error)
         else
            call h5_write(file, 'summary/'//trim(summary_columns(1, k)), values(:, k), &
               trim(summary_columns(2, k)), error)
         end if
         if (allocated(error)) return
      end do
      call attach_scale(file, 'summary', 'case', 'case', [character(len=17) :: 'status', &
         'n_patches', 'n_loaded', 'main_patch', sweep_axis_names, summary_columns(1, :)], 1, error)
   end subroutine write_summary

   pure function axis_units(name) result(units)
      character(len=*), intent(in) :: name
      character(len=:), allocatable :: units
      select case (name)
      case ('t_y', 'approach'); units = 'mm'
      case ('roll', 'yaw'); units = 'rad'
      case ('normal_force', 'vertical_force'); units = 'N'
      case ('v_forward', 'v_lateral', 'v_vertical'); units = 'mm/s'
      case ('roll_rate', 'yaw_rate', 'pitch_rate'); units = 'rad/s'
      case ('phi'); units = 'rad/mm'
      case default; units = '1'
      end select
   end function axis_units

   !> /failures: the failed cases and their messages (only when some failed).
   subroutine write_failures(file, indices, results, error)
      type(h5_file_type), intent(in) :: file
      integer, intent(in) :: indices(:)
      type(case_result_type), intent(in) :: results(:)
      type(error_type), allocatable, intent(out) :: error
      integer, allocatable :: failed(:)
      character(len=:), allocatable :: messages(:)
      integer :: i, n, longest
      failed = pack([(i, i=1, size(results))], results%summary%stat > 0)
      if (size(failed) == 0) return
      longest = 1
      do i = 1, size(failed)
         if (allocated(results(failed(i))%message)) longest = max(longest, &
            len(results(failed(i))%message))
      end do
      allocate (character(len=longest) :: messages(size(failed)))
      do i = 1, size(failed)
         n = failed(i)
         messages(i) = ''
         if (allocated(results(n)%message)) messages(i) = results(n)%message
      end do
      call write_failure_table(file, indices(failed), messages, error)
   end subroutine write_failures

   subroutine write_failure_table(file, cases, messages, error)
      type(h5_file_type), intent(in) :: file
      integer, intent(in) :: cases(:)
      character(len=*), intent(in) :: messages(:)
      type(error_type), allocatable, intent(out) :: error
      call h5_write(file, 'failures/case', cases, '1', error)
      if (.not. allocated(error)) call h5_write(file, 'failures/message', messages, error)
      if (.not. allocated(error)) call attach_scale(file, 'failures', 'case', 'case', &
         ['message'], 1, error)
   end subroutine write_failure_table

   !> The per-case group: the fields the configuration asks for, per patch.
   subroutine write_case(file, fields, group, result, error)
      type(h5_file_type), intent(in) :: file
      type(field_choice_type), intent(in) :: fields
      character(len=*), intent(in) :: group
      type(case_result_type), intent(in) :: result
      type(error_type), allocatable, intent(out) :: error
      integer :: k
      character(len=:), allocatable :: patch

      if (.not. fields%any .or. result%summary%stat /= 0) return
      do k = 1, result%summary%n_loaded
         patch = group//'/patch_'//str_int(k)
         if (fields%geometry .and. allocated(result%geometry)) then
            call write_geometry(file, patch//'/geometry', result%geometry(k), error)
            if (allocated(error)) return
         end if
         if (allocated(result%normal)) then
            call write_normal(file, fields, patch//'/normal', result%normal(k), error)
            if (allocated(error)) return
         end if
         if (allocated(result%tangential)) then
            call write_tangential(file, fields, patch//'/tangential', result%tangential(k), &
               error)
            if (allocated(error)) return
         end if
         if (allocated(result%nu_x)) then
            ! Kinematic case: the creepages of the wheelset motion at this patch.
            call h5_write(file, patch//'/tangential/nu_x', result%nu_x(k), '1', error)
            if (.not. allocated(error)) call h5_write(file, patch//'/tangential/nu_y', &
               result%nu_y(k), '1', error)
            if (.not. allocated(error)) call h5_write(file, patch//'/tangential/phi', &
               result%phi(k), 'rad/mm', error)
            if (.not. allocated(error)) call h5_write(file, patch//'/tangential/x_track', &
               result%x_track(k), 'mm', error)
            if (allocated(error)) return
         end if
      end do
   end subroutine write_case

   subroutine write_normal(file, fields, path, n, error)
      type(h5_file_type), intent(in) :: file
      type(field_choice_type), intent(in) :: fields
      character(len=*), intent(in) :: path
      type(normal_patch_type), intent(in) :: n
      type(error_type), allocatable, intent(out) :: error
      integer :: m
      call h5_write(file, path//'/approach', n%approach, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/load', n%load, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/area', n%area, 'mm^2', error)
      if (.not. allocated(error)) call h5_write(file, path//'/p_max', n%p_max, 'MPa', error)
      if (.not. allocated(error)) call h5_write(file, path//'/dy', n%dy, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/y_shift', n%y_shift, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma0', n%gamma0, 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/r0', n%r0, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/is_hertz', merge(1, 0, &
         n%is_hertz), '1', error)
      if (n%is_hertz .and. .not. allocated(error)) then
         call h5_write(file, path//'/ellipse_a', n%ellipse_a, 'mm', error)
         if (.not. allocated(error)) call h5_write(file, path//'/ellipse_b', n%ellipse_b, 'mm', &
            error)
         if (.not. allocated(error)) call h5_write(file, path//'/ellipse_y_centre', &
            n%ellipse_y_centre, 'mm', error)
      end if
      if (allocated(error) .or. .not. fields%strips) return
      if (.not. allocated(n%y)) return
      m = n%n_strips
      call h5_write(file, path//'/y', n%y(1:m), 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/a', n%a(1:m), 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/k', n%k(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/p0', n%p0(1:m), 'MPa', error)
      if (.not. allocated(error)) call h5_write(file, path//'/strip_load', n%strip_load(1:m), &
         'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/m', n%m(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/n', n%n(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/eps_a', n%eps_a(1:m), '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/gamma', n%gamma(1:m), 'rad', error)
      if (.not. allocated(error)) call h5_write(file, path//'/delta_r', n%delta_r(1:m), 'mm', &
         error)
      if (.not. allocated(error)) call h5_write(file, path//'/r_wheel', n%r_wheel(1:m), 'mm', &
         error)
      if (.not. allocated(error)) call attach_scale(file, path, 'y', 'y (strip centre)', &
         strip_tables, 1, error)
   end subroutine write_normal

   subroutine write_tangential(file, fields, path, t, error)
      type(h5_file_type), intent(in) :: file
      type(field_choice_type), intent(in) :: fields
      character(len=*), intent(in) :: path
      type(tangential_patch_type), intent(in) :: t
      type(error_type), allocatable, intent(out) :: error
      call h5_write(file, path//'/fx', t%fx, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fy', t%fy, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/mz', t%mz, 'N mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fn', t%fn, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fx_norm', t%fx_norm, '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fy_norm', t%fy_norm, '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/coulomb_ratio', t%coulomb_ratio, &
         '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/adhesion_fraction', &
         t%adhesion_fraction, '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fy_track', t%fy_track, 'N', error)
      if (.not. allocated(error)) call h5_write(file, path//'/fz_track', t%fz_track, 'N', error)
      if (allocated(error) .or. .not. allocated(t%x)) return
      if (.not. fields%elements) return
      call h5_write(file, path//'/x', t%x, 'mm', error, compress=.true.)
      if (.not. allocated(error)) call h5_write(file, path//'/y', t%y, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/dx', t%dx, 'mm', error)
      if (.not. allocated(error)) call h5_write(file, path//'/dy', t%dy, 'mm', error)
      if (allocated(error)) return
      if (fields%pressure .and. allocated(t%pn)) then
         call h5_write(file, path//'/pn', t%pn, 'MPa', error, compress=.true.)
         if (allocated(error)) return
      end if
      if (fields%traction .and. allocated(t%px)) then
         call h5_write(file, path//'/px', t%px, 'MPa', error, compress=.true.)
         if (.not. allocated(error)) call h5_write(file, path//'/py', t%py, 'MPa', error, &
            compress=.true.)
         if (allocated(error)) return
      end if
      if (fields%slip .and. allocated(t%slip)) then
         call h5_write(file, path//'/slip', t%slip, '1', error, compress=.true.)
         if (allocated(error)) return
      end if
      if (fields%state .and. allocated(t%state)) then
         call h5_write(file, path//'/state', t%state, '1', error, compress=.true.)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'codes', &
            str_int(int(state_exterior))//' exterior, '// &
            str_int(int(state_adhesion))//' adhesion, '// &
            str_int(int(state_slip))//' slip', error)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'exterior', &
            int(state_exterior), error)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'adhesion', &
            int(state_adhesion), error)
         if (.not. allocated(error)) call h5_write_attribute(file, path//'/state', 'slip', &
            int(state_slip), error)
         if (allocated(error)) return
      end if
      call write_field_grid(file, path, t, error)
   end subroutine write_tangential

   !> The element grid of the fields: `xy`, the element centres (x, y) interleaved (the mesh
   !> geometry of the XDMF sidecar: ParaView's XDMF reader wants the coordinates of a point
   !> together), y as the dimension scale of the strip dimension of every field, `element`
   !> (j = 0, 1, ...) that of the element dimension, `component` ('x', 'y') that of xy's first,
   !> every dimension labelled, and a `coordinates` attribute (x, y) on every field.
   subroutine write_field_grid(file, path, t, error)
      type(h5_file_type), intent(in) :: file
      character(len=*), intent(in) :: path
      type(tangential_patch_type), intent(in) :: t
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: fields(6) = [character(len=5) :: 'x', 'pn', 'px', 'py', &
         'slip', 'state']
      real(wp), allocatable :: xy(:, :, :)
      integer :: i
      allocate (xy(2, size(t%x, 1), size(t%x, 2)))
      xy(1, :, :) = t%x
      xy(2, :, :) = spread(t%y, 1, size(t%x, 1))
      call h5_write(file, path//'/xy', xy, 'mm', error, compress=.true.)
      if (.not. allocated(error)) call h5_write(file, path//'/element', &
         [(i - 1, i = 1, size(t%x, 1))], '1', error)
      if (.not. allocated(error)) call h5_write(file, path//'/component', &
         [character(len=1) :: 'x', 'y'], error)
      if (.not. allocated(error)) call attach_field_scales(file, path, error)
      if (.not. allocated(error)) call h5_set_dim_label(file, path//'/xy', 1, 'x, y', error)
      if (.not. allocated(error)) call h5_set_dim_label(file, path//'/xy', 2, &
         'element (j from the leading edge)', error)
      if (.not. allocated(error)) call h5_set_dim_label(file, path//'/xy', 3, 'strip (y)', error)
      do i = 1, size(fields)
         if (allocated(error)) return
         if (.not. h5_exists(file, path//'/'//trim(fields(i)))) cycle
         call h5_set_dim_label(file, path//'/'//trim(fields(i)), 1, &
            'element (j from the leading edge)', error)
         if (.not. allocated(error)) call h5_set_dim_label(file, path//'/'//trim(fields(i)), &
            2, 'strip (y)', error)
         if (.not. allocated(error) .and. i > 1) call h5_write_attribute(file, &
            path//'/'//trim(fields(i)), 'coordinates', 'x y', error)
      end do
   end subroutine write_field_grid

   ! ------------------------------------------------------------------------------------------
   ! Reading and merging
   ! ------------------------------------------------------------------------------------------

   !> The configuration, run size, case numbers, summaries and failures of a result file.
   subroutine read_result_summary(name, config_text, n_cases, indices, summaries, &
                                  failed_cases, failed_messages, error)
      !> File name.
      character(len=*), intent(in) :: name
      !> The resolved configuration it was made with.
      character(len=:), allocatable, intent(out) :: config_text
      !> Cases of its run.
      integer, intent(out) :: n_cases
      !> Case numbers it holds.
      integer, allocatable, intent(out) :: indices(:)
      !> Their summaries.
      type(case_summary_type), allocatable, intent(out) :: summaries(:)
      !> Failed cases and their messages.
      integer, allocatable, intent(out) :: failed_cases(:)
      character(len=:), allocatable, intent(out) :: failed_messages(:)
      !> Set when the file cannot be read or is not a shcontact result file.
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: file
      integer, allocatable :: ints(:)
      real(wp), allocatable :: column(:)
      character(len=:), allocatable :: software
      integer :: k, i

      n_cases = 0
      call h5_open(file, name, error)
      if (allocated(error)) return
      call h5_read_attribute(file, '/', 'software', software, error)
      if (.not. allocated(error)) then
         if (software /= 'shcontact') call fatal_error(error, 'its software attribute is "'// &
            software//'"')
      end if
      if (allocated(error)) then
         call fatal_error(error, '"'//name//'" is not a shcontact result file', stat_invalid_input)
         call h5_close(file)
         return
      end if
      call h5_read_attribute(file, '/', 'n_cases', n_cases, error)
      if (.not. allocated(error)) call h5_read(file, 'input/namelist', config_text, error)
      if (allocated(error)) then
         ! Every result file has both (a foreign file that says software = 'shcontact').
         software = error%message
         call fatal_error(error, '"'//name//'" is not a shcontact result file ('// &
            software//')', stat_invalid_input)
         call h5_close(file)
         return
      end if
      call check_layout(file, name, error)
      if (.not. allocated(error)) call h5_read(file, 'summary/case', indices, error)
      if (allocated(error)) then
         call h5_close(file)
         return
      end if
      allocate (summaries(size(indices)))
      call h5_read(file, 'summary/status', ints, error)
      if (.not. allocated(error)) then
         summaries%stat = ints
         call h5_read(file, 'summary/n_patches', ints, error)
      end if
      if (.not. allocated(error)) then
         summaries%n_patches = ints
         ! Files of versions before n_loaded counted the loaded patches in n_patches.
         summaries%n_loaded = ints
         if (h5_exists(file, 'summary/n_loaded')) call h5_read(file, 'summary/n_loaded', ints, &
            error)
      end if
      if (.not. allocated(error)) then
         summaries%n_loaded = ints
         call h5_read(file, 'summary/main_patch', ints, error)
      end if
      if (.not. allocated(error)) summaries%main_patch = ints
      do k = 1, n_summary_columns
         if (allocated(error)) exit
         ! The kinematic columns are only in the files of kinematic runs.
         if (.not. h5_exists(file, 'summary/'//trim(summary_columns(1, k)))) cycle
         call h5_read(file, 'summary/'//trim(summary_columns(1, k)), column, error)
         if (allocated(error)) exit
         do i = 1, size(summaries)
            call set_summary_value(summaries(i), k, column(i))
         end do
      end do
      if (.not. allocated(error)) then
         if (h5_exists(file, 'failures/case')) then
            call h5_read(file, 'failures/case', failed_cases, error)
            if (.not. allocated(error)) call h5_read(file, 'failures/message', failed_messages, &
               error)
         else
            allocate (failed_cases(0))
            allocate (character(len=1) :: failed_messages(0))
         end if
      end if
      call h5_close(file)
   end subroutine read_result_summary

   !> Merge result files of one run (shards, checkpoint blocks) into `output`. The inputs
   !> must come from the same configuration and together hold every case exactly once.
   subroutine merge_result_files(output, inputs, command_line, date, error, allow_partial, &
                                 shard, temp_name, threads, force)
      !> The merged file (written under a temporary name, renamed when complete).
      character(len=*), intent(in) :: output
      !> The files to merge.
      type(string_type), intent(in) :: inputs(:)
      !> Command line and date recorded in the merged file.
      character(len=*), intent(in) :: command_line, date
      !> Set when the inputs do not fit together or cannot be read or written.
      type(error_type), allocatable, intent(out) :: error
      !> Accept a run with cases missing (they are absent from the summary).
      logical, intent(in), optional :: allow_partial
      !> 'I/N' when the merged file is one shard of a run.
      character(len=*), intent(in), optional :: shard
      !> Temporary name of the merged file (default `output.tmp<pid>`).
      character(len=*), intent(in), optional :: temp_name
      !> OpenMP threads of the run, recorded in the file (default: those available now).
      integer, intent(in), optional :: threads
      !> Replace an output (or sidecar) that shcontact did not write ([[check_output_file]]).
      logical, intent(in), optional :: force

      character(len=:), allocatable :: text, first_text, messages(:), all_messages(:)
      integer, allocatable :: indices(:), source(:), failed(:), all_failed(:)
      type(case_summary_type), allocatable :: summaries(:), all(:)
      type(case_config_type) :: config
      type(run_info_type) :: info
      type(h5_file_type) :: out, src
      integer :: f, n_cases, n_first, i, icase, open_index, n_fail, longest, k
      type(string_list_type) :: failure_messages
      integer, allocatable :: order(:)
      real(wp), allocatable :: first_profiles(:), profiles(:)
      logical :: partial, src_has_cases, same

      partial = .false.
      if (present(allow_partial)) partial = allow_partial
      if (size(inputs) == 0) then
         call fatal_error(error, 'merge: no input files', stat_invalid_input)
         return
      end if
      call check_output_file(output, error, inputs, force)
      if (allocated(error)) return
      n_first = 0
      n_fail = 0
      longest = 1
      do f = 1, size(inputs)
         call read_result_summary(inputs(f)%text, text, n_cases, indices, summaries, failed, &
            messages, error)
         if (allocated(error)) return
         if (f == 1) then
            first_text = text
            call read_input_profiles(inputs(f)%text, first_profiles, error)
            if (allocated(error)) return
            n_first = n_cases
            allocate (all(n_cases), source(n_cases))
            source = 0
            allocate (all_failed(0))
         else if (text /= first_text .or. n_cases /= n_first) then
            call fatal_error(error, 'merge: "'//inputs(f)%text//'" comes from another run '// &
               'than "'//inputs(1)%text//'" (configurations differ)', stat_invalid_input)
            return
         else
            ! A profile file rewritten under its name between the shards: the same
            ! configuration text, other points.
            call read_input_profiles(inputs(f)%text, profiles, error)
            if (allocated(error)) return
            if (size(profiles) /= size(first_profiles)) then
               same = .false.
            else
               same = .not. any(profiles /= first_profiles)
            end if
            if (.not. same) then
               call fatal_error(error, 'merge: "'//inputs(f)%text//'" was solved with other '// &
                  'profiles than "'//inputs(1)%text//'" (the same file names, other points in '// &
                  '/input/profiles: a file changed between the shards); solve them again with '// &
                  'one set of profile files', stat_invalid_input)
               return
            end if
         end if
         do i = 1, size(indices)
            icase = indices(i)
            if (icase < 1 .or. icase > n_cases) then
               call fatal_error(error, 'merge: "'//inputs(f)%text//'" holds case '// &
                  str_int(icase)//' of a run of '//str_int(n_cases), stat_invalid_input)
               return
            end if
            if (source(icase) /= 0) then
               if (inputs(source(icase))%text == inputs(f)%text) then
                  call fatal_error(error, 'merge: "'//inputs(f)%text//'" is given twice; '// &
                     'give each shard once', stat_invalid_input)
               else
                  call fatal_error(error, 'merge: case '//str_int(icase)//' is in both "'// &
                     inputs(source(icase))%text//'" and "'//inputs(f)%text//'"', &
                     stat_invalid_input)
               end if
               return
            end if
            source(icase) = f
            all(icase) = summaries(i)
         end do
         all_failed = [all_failed, failed]
         do i = 1, size(messages)
            longest = max(longest, len_trim(messages(i)))
         end do
         do i = 1, size(failed)
            call failure_messages%push(trim(messages(i)))
         end do
         n_fail = n_fail + size(failed)
      end do
      if (.not. partial .and. any(source == 0)) then
         icase = findloc(source, 0, dim=1)
         call fatal_error(error, 'merge: '//str_int(count(source == 0))//' of '// &
            str_int(n_first)//' cases are missing (the first is case '// &
            str_int(icase)//'); give every shard', stat_invalid_input)
         return
      end if

      call read_config_text(first_text, '"'//inputs(1)%text//'":/input/namelist', config, error)
      if (allocated(error)) return
      order = pack([(i, i=1, n_first)], source > 0)

      ! Header: copy /input and /geometry from the first file.
      info%namelist = first_text
      info%command_line = command_line
      info%date = date
      info%n_cases = n_first
      info%shard = ''
      if (present(shard)) info%shard = shard
      if (present(threads)) info%threads = threads
      call h5_create(out, output, error, compression=config%output%compression, &
         single=config%output%precision == precision_single, temp_name=temp_name, &
         describe=describe_dataset)
      if (allocated(error)) return
      call h5_open(src, inputs(1)%text, error)
      ! Shards merged by `shcontact merge`: the threads the first shard was solved with.
      if (.not. allocated(error) .and. .not. present(threads)) &
         call first_threads(src, info%threads)
      if (.not. allocated(error)) call write_root_attributes(out, info, size(order), error)
      if (.not. allocated(error)) call h5_copy(src, 'input', out, 'input', error)
      if (.not. allocated(error)) call attach_profile_scales(out, error)
      if (.not. allocated(error) .and. h5_exists(src, 'geometry')) then
         call h5_copy(src, 'geometry', out, 'geometry', error)
         k = 1
         do while (.not. allocated(error) .and. h5_exists(out, 'geometry/patch_'//str_int(k)))
            call attach_patch_scales(out, 'geometry/patch_'//str_int(k), error)
            k = k + 1
         end do
      end if
      call h5_close(src)
      if (.not. allocated(error)) call write_summary(out, config, order, all(order), error)
      ! Built here at its final length (growing a deferred-length array across calls left its
      ! length undefined under gfortran; valgrind saw len_trim read uninitialised memory).
      allocate (character(len=longest) :: all_messages(n_fail))
      do i = 1, n_fail
         all_messages(i) = failure_messages%items(i)%text
      end do
      if (.not. allocated(error) .and. n_fail > 0) then
         call sort_failures(all_failed(1:n_fail), all_messages)
         call write_failure_table(out, all_failed(1:n_fail), all_messages, error)
      end if
      ! Per-case groups, in case order, reading each input file while its cases come (a file
      ! without /cases, the summary-only run, is looked at once, not once per case).
      open_index = 0
      src_has_cases = .false.
      do i = 1, size(order)
         if (allocated(error)) exit
         icase = order(i)
         if (source(icase) /= open_index) then
            call h5_close(src)
            open_index = source(icase)
            call h5_open(src, inputs(open_index)%text, error)
            if (allocated(error)) exit
            src_has_cases = h5_exists(src, 'cases')
         end if
         if (.not. src_has_cases) cycle
         if (.not. h5_exists(src, case_group_name(icase, n_first))) cycle
         call h5_copy(src, case_group_name(icase, n_first), out, &
            case_group_name(icase, n_first), error)
         k = 1
         do while (.not. allocated(error) .and. h5_exists(out, case_group_name(icase, n_first) &
                                                          //'/patch_'//str_int(k)))
            call attach_patch_scales(out, case_group_name(icase, n_first)//'/patch_'// &
               str_int(k), error)
            k = k + 1
         end do
      end do
      call h5_close(src)
      if (allocated(error)) then
         call h5_discard(out)
         return
      end if
      call commit_output(out, error)
      if (allocated(error)) return
      call finish_output(output, order, n_first, error)
   end subroutine merge_result_files

   !> Begin the output of a run written straight from its results, as [[merge_result_files]]
   !> would assemble it from block files holding them (a run that never needed a checkpoint):
   !> the output checked, created under `temp_name` and its header written; [[end_run_file]]
   !> completes it. The header can so be written while the run's last cases are solved.
   subroutine begin_run_file(file, output, info, config, cases_in_file, error, temp_name, force)
      !> The file, open for writing.
      type(h5_file_type), intent(out) :: file
      !> The output file (written under `temp_name`, renamed when complete).
      character(len=*), intent(in) :: output
      !> Run information (header, profiles, common geometry).
      type(run_info_type), intent(in) :: info
      !> The configuration (compression, precision).
      type(case_config_type), intent(in) :: config
      !> The number of cases the file will hold.
      integer, intent(in) :: cases_in_file
      !> Set on failure; no file is left under `output` then.
      type(error_type), allocatable, intent(out) :: error
      !> Temporary name of the file while it is written.
      character(len=*), intent(in) :: temp_name
      !> Replace an output (or sidecar) that shcontact did not write ([[check_output_file]]).
      logical, intent(in), optional :: force
      call check_output_file(output, error, force=force)
      if (allocated(error)) return
      call begin_result_file(file, output, info, config, cases_in_file, error, temp_name)
   end subroutine begin_run_file

   !> Complete the output begun by [[begin_run_file]]: the cases, the commit under its name and
   !> the XDMF sidecar.
   subroutine end_run_file(file, info, config, indices, results, error)
      !> The file (closed on return).
      type(h5_file_type), intent(inout) :: file
      !> Run information.
      type(run_info_type), intent(in) :: info
      !> The configuration.
      type(case_config_type), intent(in) :: config
      !> Case numbers of the results, ascending.
      integer, intent(in) :: indices(:)
      !> The results.
      type(case_result_type), intent(in) :: results(:)
      !> Set on failure; no file is left under the output's name then.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: output
      output = file%name
      call end_result_file(file, info, config, indices, results, error)
      if (allocated(error)) return
      call finish_output(output, indices, info%n_cases, error)
   end subroutine end_run_file

   !> Complete the output begun by [[begin_run_file]] from the summaries of a run that stores
   !> no per-case fields, every one of which the run holds in memory (its checkpoint block
   !> files, if it wrote any, are not read back): `/summary`, `/failures`, the commit under its
   !> name and the XDMF sidecar. The same file as [[merge_result_files]] makes of the blocks.
   subroutine end_summary_file(file, info, config, indices, summaries, failures, error)
      !> The file (closed on return).
      type(h5_file_type), intent(inout) :: file
      !> Run information.
      type(run_info_type), intent(in) :: info
      !> The configuration (sweep axes).
      type(case_config_type), intent(in) :: config
      !> Case numbers of the summaries, ascending.
      integer, intent(in) :: indices(:)
      !> The cases' summaries.
      type(case_summary_type), intent(in) :: summaries(:)
      !> The failed cases and their messages, in any order.
      type(failure_type), intent(in) :: failures(:)
      !> Set on failure; no file is left under the output's name then.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: output, messages(:)
      integer, allocatable :: cases(:)
      integer :: i, longest
      output = file%name
      call write_summary(file, config, indices, summaries, error)
      if (.not. allocated(error) .and. size(failures) > 0) then
         longest = 1
         do i = 1, size(failures)
            if (allocated(failures(i)%message)) longest = max(longest, &
               len_trim(failures(i)%message))
         end do
         ! Built at its final length (see merge_result_files).
         allocate (character(len=longest) :: messages(size(failures)))
         cases = failures%case
         do i = 1, size(failures)
            messages(i) = ''
            if (allocated(failures(i)%message)) messages(i) = failures(i)%message
         end do
         call sort_failures(cases, messages)
         call write_failure_table(file, cases, messages, error)
      end if
      if (allocated(error)) then
         call h5_discard(file)
         return
      end if
      call commit_output(file, error)
      if (allocated(error)) return
      call finish_output(output, indices, info%n_cases, error)
   end subroutine end_summary_file

   !> The root attribute `threads` of a result file (left as it is when the file has none).
   subroutine first_threads(file, threads)
      type(h5_file_type), intent(in) :: file
      integer, intent(inout) :: threads
      type(error_type), allocatable :: error
      integer :: value
      call h5_read_attribute(file, '/', 'threads', value, error)
      if (.not. allocated(error)) threads = value
   end subroutine first_threads

   !> Give a finished file its name, after removing the output's own XDMF sidecar of an earlier
   !> run: a process killed between the two steps then leaves no sidecar that describes
   !> other cases than the new file's (the next run or `--resume` writes it again).
   subroutine commit_output(file, error)
      type(h5_file_type), intent(inout) :: file
      type(error_type), allocatable, intent(out) :: error
      if (is_xdmf_sidecar(xdmf_name(file%name))) then
         if (delete_file(xdmf_name(file%name))) continue
      end if
      call h5_commit(file, error)
   end subroutine commit_output

   !> The XDMF sidecar of a complete output holding cases `order` of a run of `n_cases`; on
   !> failure the output goes too (no output from a failed command).
   subroutine finish_output(output, order, n_cases, error)
      character(len=*), intent(in) :: output
      integer, intent(in) :: order(:), n_cases
      type(error_type), allocatable, intent(out) :: error
      type(string_type), allocatable :: groups(:)
      integer :: i
      allocate (groups(size(order)))
      do i = 1, size(order)
         groups(i)%text = case_group_name(order(i), n_cases)
      end do
      call write_xdmf_sidecar(output, order, groups, error)
      if (allocated(error)) then
         if (delete_file(output)) continue
      end if
   end subroutine finish_output

   !> Sort the failure table by case number (insertion sort: it is short and nearly sorted).
   subroutine sort_failures(cases, messages)
      integer, intent(inout) :: cases(:)
      character(len=*), intent(inout) :: messages(:)
      integer :: i, j, c
      character(len=len(messages)) :: m
      do i = 2, size(cases)
         c = cases(i)
         m = messages(i)
         j = i - 1
         do while (j >= 1)
            if (cases(j) <= c) exit
            cases(j + 1) = cases(j)
            messages(j + 1) = messages(j)
            j = j - 1
         end do
         cases(j + 1) = c
         messages(j + 1) = m
      end do
   end subroutine sort_failures

end module shcontact_output_results
