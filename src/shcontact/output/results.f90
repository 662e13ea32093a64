!> The layout of shcontact's HDF5 result files and their writing; reading them back and merging
!> several files of one run (shards, checkpoint blocks) into one is shcontact_output_merge's.
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
   use shcontact_core_kinds, only: wp
   use shcontact_core_error, only: error_type
   use shcontact_version_info, only: shcontact_version
   use shcontact_profile_points, only: profile_type
   use shcontact_geometry_patch, only: patch_geometry_type
   use shcontact_input_config, only: case_config_type, n_sweep_axes, sweep_axis_names, &
      case_point_type, case_point_value, case_point_label, precision_single
   use shcontact_output_hdf5, only: h5_file_type, h5_create, h5_commit, h5_discard, h5_write, &
      h5_write_attribute
   use shcontact_output_descriptions, only: describe_dataset
   use shcontact_output_patch_groups, only: field_choice_type, attach_scale, write_geometry, &
      write_case
   use shcontact_output_provenance, only: git_revision, build_compiler, build_flags, host_name, &
      available_threads
   use shcontact_output_xdmf, only: write_xdmf_sidecar, xdmf_name, is_xdmf_sidecar
   use shcontact_core_files, only: delete_file
   use shcontact_output_output_checks, only: check_output_file
   use shcontact_core_strings, only: str_int
   use shcontact_core_text, only: string_type
   use shcontact_case_result, only: case_summary_type, case_result_type, summary_columns, &
      n_summary_columns, summary_value, summary_column_used, failure_type, summary_column_counts
   implicit none
   private

   public :: run_info_type, write_result_file, begin_run_file, end_run_file, &
      end_summary_file
   ! For shcontact_output_merge, which assembles a file from others with the same pieces.
   public :: write_root_attributes, attach_profile_scales, write_summary, sort_failures, &
      write_failure_table, commit_output, finish_output, profile_names
   public :: check_output_file
   public :: case_group_name, case_groups, units_text, sign_convention_text

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
      call write_xdmf_sidecar(output, order, case_groups(order, n_cases), error)
      if (allocated(error)) then
         if (delete_file(output)) continue
      end if
   end subroutine finish_output

   !> The per-case groups ([[case_group_name]]) of cases `cases` of a run of `n_cases`.
   pure function case_groups(cases, n_cases) result(groups)
      integer, intent(in) :: cases(:), n_cases
      type(string_type), allocatable :: groups(:)
      integer :: i
      allocate (groups(size(cases)))
      do i = 1, size(cases)
         groups(i)%text = case_group_name(cases(i), n_cases)
      end do
   end function case_groups

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
