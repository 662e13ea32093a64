!> Reading result files back and merging them (shards of a run, checkpoint blocks) into one
!> (doc/app.md, "Shards and merging"): the same file as one run writes, assembled from the
!> pieces shcontact_output_results writes.
module shcontact_output_merge
   use shcontact_core_kinds, only: wp
   use shcontact_profile_points, only: profile_type
   use shcontact_core_error, only: error_type, fatal_error, stat_invalid_input
   use shcontact_input_config, only: case_config_type, read_config_text, precision_single, &
      config_namelist
   use shcontact_output_hdf5, only: h5_file_type, h5_create, h5_discard, h5_open, h5_close, &
      h5_copy, h5_exists, h5_read, h5_read_attribute
   use shcontact_output_descriptions, only: describe_dataset
   use shcontact_output_output_checks, only: check_output_file, check_layout, check_result_file
   use shcontact_output_results, only: run_info_type, case_group_name, write_root_attributes, &
      attach_profile_scales, write_summary, sort_failures, write_failure_table, commit_output, &
      finish_output, profile_names
   use shcontact_output_patch_groups, only: attach_patch_scales
   use shcontact_core_strings, only: str_int
   use shcontact_core_text, only: string_type, string_list_type
   use shcontact_case_result, only: case_summary_type, summary_columns, n_summary_columns, &
      summary_column_used, &
      set_summary_value
   implicit none
   private

   public :: merge_result_files, read_result_summary, compare_finished_run, &
      missing_summary_column

contains


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
      character(len=:), allocatable :: reason
      integer :: k, i

      n_cases = 0
      call h5_open(file, name, error)
      if (allocated(error)) return
      call check_result_file(file, error)
      if (allocated(error)) then
         reason = error%message
         call fatal_error(error, '"'//name//'" is not a shcontact result file ('//reason//')', &
            stat_invalid_input)
         call h5_close(file)
         return
      end if
      call h5_read_attribute(file, '/', 'n_cases', n_cases, error)
      if (.not. allocated(error)) call h5_read(file, 'input/namelist', config_text, error)
      if (allocated(error)) then
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
                                 shard, temp_name, threads, force, n_failed, n_merged)
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
      !> The failed cases the merged file lists under /failures, and the cases it holds
      !> (solved or failed).
      integer, intent(out), optional :: n_failed, n_merged

      character(len=:), allocatable :: text, first_text, messages(:), all_messages(:), key, &
         first_key
      integer, allocatable :: indices(:), source(:), failed(:), all_failed(:)
      type(case_summary_type), allocatable :: summaries(:), all(:)
      type(case_config_type) :: config
      type(run_info_type) :: info
      type(h5_file_type) :: out, src
      integer :: f, n_cases, n_first, i, icase, open_index, n_fail, longest, k
      type(string_list_type) :: failure_messages
      integer, allocatable :: order(:)
      real(wp), allocatable :: first_profiles(:), profiles(:)
      character(len=:), allocatable :: missing
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
         call run_key(text, inputs(f)%text, key, error)
         if (allocated(error)) return
         call read_config_text(text, '"'//inputs(f)%text//'":/input/namelist', config, error)
         if (allocated(error)) return
         call missing_summary_column(inputs(f)%text, config%is_kinematic(), missing, error)
         if (allocated(error)) return
         if (len(missing) > 0) then
            call fatal_error(error, 'merge: "'//inputs(f)%text//'" has no /summary/'// &
               missing//' (written by an older version of shcontact); solve that shard '// &
               'again with this version', stat_invalid_input)
            return
         end if
         if (f == 1) then
            first_text = text
            first_key = key
            call read_input_profiles(inputs(f)%text, first_profiles, error)
            if (allocated(error)) return
            n_first = n_cases
            allocate (all(n_cases), source(n_cases))
            source = 0
            allocate (all_failed(0))
         else if (key /= first_key .or. n_cases /= n_first) then
            call fatal_error(error, 'merge: "'//inputs(f)%text//'" comes from another run '// &
               'than "'//inputs(1)%text//'" (configurations differ: '// &
               first_difference(key, first_key)//')', stat_invalid_input)
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
                  'profile points than "'//inputs(1)%text//'" (/input/profiles differ: another '// &
                  'profile file, or a file changed between the shards); solve them again with '// &
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
      if (present(n_failed)) n_failed = n_fail
      if (present(n_merged)) n_merged = size(order)
   end subroutine merge_result_files

   !> Whether the result file `name` already holds the run that `namelist` and `profiles`
   !> describe (`--resume` of a finished run): the configuration as merge compares it (without
   !> the output and profile file names), the same profile points, a run of `n_cases` cases
   !> and exactly its cases first..last. When it does, `summaries(first:last)` are the file's,
   !> `failed`/`messages` its failed cases; else `difference` says what differs.
   subroutine compare_finished_run(name, namelist, profiles, n_cases, first, last, same, &
                                   difference, summaries, failed, messages, error)
      !> The existing result file.
      character(len=*), intent(in) :: name
      !> This run's resolved namelist (as its file's /input/namelist would be).
      character(len=*), intent(in) :: namelist
      !> This run's profiles as read (wheel, rail).
      type(profile_type), intent(in) :: profiles(:)
      !> The run's size and this shard's cases.
      integer, intent(in) :: n_cases, first, last
      !> Whether the file is that run, finished.
      logical, intent(out) :: same
      !> What differs (when not `same`).
      character(len=:), allocatable, intent(out) :: difference
      !> The file's summaries of cases first..last (when `same`).
      type(case_summary_type), intent(inout) :: summaries(first:)
      !> The file's failed cases and their messages.
      integer, allocatable, intent(out) :: failed(:)
      character(len=:), allocatable, intent(out) :: messages(:)
      !> Set when the file cannot be read.
      type(error_type), allocatable, intent(out) :: error
      character(len=:), allocatable :: text, key, this_key
      integer, allocatable :: indices(:)
      type(case_summary_type), allocatable :: held(:)
      real(wp), allocatable :: points(:), expected(:)
      integer :: n, k, i
      logical :: complete
      type(case_config_type) :: config
      character(len=:), allocatable :: missing

      same = .false.
      difference = ''
      call read_result_summary(name, text, n, indices, held, failed, messages, error)
      if (allocated(error)) return
      call run_key(text, name, key, error)
      if (.not. allocated(error)) call run_key(namelist, 'this run', this_key, error)
      if (allocated(error)) return
      if (key /= this_key) then
         difference = 'configurations differ: '//first_difference(key, this_key)
         return
      end if
      if (n /= n_cases) then
         difference = 'a run of '//str_int(n)//' cases, this one has '//str_int(n_cases)
         return
      end if
      if (size(indices) /= last - first + 1) then
         difference = 'it holds '//str_int(size(indices))//' of the '// &
            str_int(last - first + 1)//' cases'
         return
      end if
      ! Every /summary column of this run there (an older version's file lacks the newer ones,
      ! which would read as 0).
      call read_config_text(namelist, 'this run', config, error)
      if (allocated(error)) return
      call missing_summary_column(name, config%is_kinematic(), missing, error)
      if (allocated(error)) return
      if (len(missing) > 0) then
         difference = 'it has no /summary/'//missing//': written by an older version'
         return
      end if
      if (any(indices /= [(i, i=first, last)])) then
         difference = 'it holds other cases (another shard)'
         return
      end if
      call read_input_profiles(name, points, error, complete)
      if (allocated(error)) return
      if (.not. complete) then
         difference = 'it has no /input/profiles to compare: written by an older version or '// &
            'by a library caller'
         return
      end if
      allocate (expected(0))
      do k = 1, min(2, size(profiles))
         n = profiles(k)%size()
         expected = [expected, real(2*n, wp)]
         do i = 1, n
            expected = [expected, profiles(k)%y(i), profiles(k)%z(i)]
         end do
      end do
      if (size(points) /= size(expected)) then
         difference = 'other profile points (/input/profiles)'
         return
      else if (any(points /= expected)) then
         difference = 'other profile points (/input/profiles)'
         return
      end if
      summaries(first:last) = held
      same = .true.
   end subroutine compare_finished_run

   !> The first `/summary` column a run (kinematic or not) has that the result file `name`
   !> lacks ('' when none): a file of an older version, whose missing columns would read as 0.
   subroutine missing_summary_column(name, kinematic, missing, error)
      character(len=*), intent(in) :: name
      logical, intent(in) :: kinematic
      character(len=:), allocatable, intent(out) :: missing
      type(error_type), allocatable, intent(out) :: error
      type(h5_file_type) :: file
      integer :: k
      missing = ''
      call h5_open(file, name, error)
      if (allocated(error)) return
      do k = 1, n_summary_columns
         if (.not. summary_column_used(k, kinematic)) cycle
         if (h5_exists(file, 'summary/'//trim(summary_columns(1, k)))) cycle
         missing = trim(summary_columns(1, k))
         exit
      end do
      call h5_close(file)
   end subroutine missing_summary_column

   !> The profiles a result file holds under /input/profiles (the points as the run read them):
   !> y, z of the wheel then of the rail, each preceded by its point count (−1 when the file
   !> holds none: a library caller's file), to tell two runs apart that name the same files.
   subroutine read_input_profiles(name, points, error, complete)
      character(len=*), intent(in) :: name
      real(wp), allocatable, intent(out) :: points(:)
      type(error_type), allocatable, intent(out) :: error
      !> Whether the file holds both profiles.
      logical, intent(out), optional :: complete
      type(h5_file_type) :: file
      real(wp), allocatable :: yz(:, :)
      character(len=:), allocatable :: path
      integer :: k
      allocate (points(0))
      if (present(complete)) complete = .true.
      call h5_open(file, name, error)
      if (allocated(error)) return
      do k = 1, size(profile_names)
         path = 'input/profiles/'//trim(profile_names(k))
         if (.not. h5_exists(file, path)) then
            points = [points, -1.0_wp]
            if (present(complete)) complete = .false.
            cycle
         end if
         call h5_read(file, path, yz, error)
         if (allocated(error)) exit
         points = [points, real(size(yz), wp), reshape(yz, [size(yz)])]
      end do
      call h5_close(file)
   end subroutine read_input_profiles

   !> The root attribute `threads` of a result file (left as it is when the file has none).
   subroutine first_threads(file, threads)
      type(h5_file_type), intent(in) :: file
      integer, intent(inout) :: threads
      type(error_type), allocatable :: error
      integer :: value
      call h5_read_attribute(file, '/', 'threads', value, error)
      if (.not. allocated(error)) threads = value
   end subroutine first_threads

   !> The configuration of a result file as merge compares it: its resolved namelist without
   !> the output name and the profile file names, so that the shards of one run made with
   !> other -o spellings or from other folders merge (the profiles are compared by their points
   !> in /input/profiles instead).
   subroutine run_key(text, name, key, error)
      !> The file's /input/namelist.
      character(len=*), intent(in) :: text
      !> The file (for messages).
      character(len=*), intent(in) :: name
      character(len=:), allocatable, intent(out) :: key
      type(error_type), allocatable, intent(out) :: error
      type(case_config_type) :: config
      call read_config_text(text, '"'//name//'":/input/namelist', config, error)
      if (allocated(error)) return
      config%output%file = '-'
      config%profiles%wheel = '-'
      config%profiles%rail = '-'
      key = config_namelist(config)
   end subroutine run_key

   !> The first line in which two namelist texts differ, both versions quoted.
   function first_difference(a, b) result(text)
      character(len=*), intent(in) :: a, b
      character(len=:), allocatable :: text
      character(len=1), parameter :: nl = new_line('a')
      integer :: ia, ib, ea, eb
      ia = 1
      ib = 1
      do
         ea = index(a(ia:), nl)
         eb = index(b(ib:), nl)
         ea = merge(len(a), ia + ea - 2, ea == 0)
         eb = merge(len(b), ib + eb - 2, eb == 0)
         if (a(ia:ea) /= b(ib:eb) .or. (ea >= len(a) .and. eb >= len(b))) exit
         ia = ea + 2
         ib = eb + 2
      end do
      if (a(ia:ea) == b(ib:eb)) then
         text = 'the number of cases'
      else
         text = '"'//trim(adjustl(a(ia:ea)))//'" against "'//trim(adjustl(b(ib:eb)))//'"'
      end if
   end function first_difference

end module shcontact_output_merge
