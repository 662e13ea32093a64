!> shcontact-validate: the validation against the exact theory (issues 4, 5, 7, 12, 13).
!>
!>     fpm run --example shcontact-validate --profile release [-- REFERENCE PROFILES OUTPUT]
!>     fpm run --example shcontact-validate --profile release -- --kinematic [DIR PROFILES OUTPUT]
!>
!> Defaults: REFERENCE = DATA/reference/, PROFILES = DATA/profiles/, OUTPUT = doc/validation/
!> (relative to the repository root), DIR = REFERENCE/kinematic_sample/, where DATA is the
!> folder the environment variable SHCONTACT_EXTERNAL_DATA names (doc/install.md §5), ../shared
!> without it. Runs
!> our cases matching the reference (S1002 on UIC60 1:40, Y_WS = 0, F_n = 64.7 kN, G = 82670 MPa,
!> ν = 0.27, μ = 0.3; README §2) and writes the CSV tables that doc/validation.md quotes and
!> scripts/validation_figures.py draws; the DOE on every shared patch (validate_patches); then
!> the kinematic sample (validate_kinematic). With --kinematic only the kinematic sample is run. When the reference data or the profiles are
!> absent it says so and ends normally (exit 0).
program validate
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   use shcontact, only: wp, error_type, material_type, prepared_profiles_type, &
      patch_geometry_type, normal_patch_type
   use validate_csv, only: csv_table_type, read_csv, summary_value, csv_writer_type
   use validate_case, only: load_manchester, deepest_patch, solve_normal
   use validate_normal, only: patch_summary_type, summarise_patch, reference_patch_summary, &
      write_strips, manchester_rows
   use validate_report, only: recommended_type, run_tangential
   use validate_kinematic, only: run_kinematic
   use validate_patches, only: run_patches
   use validate_sets, only: write_sets
   use validate_kinematic_sets, only: run_kinematic_sets
   implicit none

   character(len=:), allocatable :: ref_root, profiles_dir, out_dir, ref_dir
   type(prepared_profiles_type) :: prepared
   type(patch_geometry_type) :: geometry
   type(material_type) :: material
   type(recommended_type) :: rec
   type(error_type), allocatable :: error
   real(wp) :: y_geo
   logical :: there, kinematic_only, patches_only, sets_only

   call arguments(ref_root, profiles_dir, out_dir, kinematic_only, patches_only, sets_only)
   if (sets_only) then
      call kinematic_sets(out_dir)
      stop
   end if
   if (kinematic_only) then
      call kinematic_sample(ref_root, profiles_dir, out_dir)
      stop
   end if
   if (patches_only) then
      call load_manchester(profiles_dir, prepared, error)
      if (.not. allocated(error)) call run_patches(ref_root, prepared, out_dir, error)
      call stop_on(error)
      stop
   end if
   ref_dir = ref_root//'ty0_literal/'
   inquire (file=ref_dir//'summary.csv', exist=there)
   if (.not. there) then
      write (output_unit, '(a)') 'shcontact-validate: the exact-theory reference '//ref_dir// &
         'summary.csv is absent; nothing to validate (the reference data is not part of the '// &
         'repository: see doc/validation.md).'
      stop
   end if
   inquire (file=profiles_dir//'MBench_S1002_v3.prw', exist=there)
   if (.not. there) then
      write (output_unit, '(a)') 'shcontact-validate: the profiles '//profiles_dir// &
         'MBench_S1002_v3.prw are absent; nothing to validate.'
      stop
   end if

   ! The settings recommended as defaults in doc/validation.md.
   rec%bound = 'weighted'
   rec%spin_model = 'uniform'
   rec%spin_flexibility = 'longitudinal'
   rec%reduction = 'local-hertz'
   rec%n_strips = 100
   rec%n_elements = 50
   ! README §2: both bodies G = 82670 MPa, ν = 0.27; μ = 0.3.
   material = material_type(shear_modulus=82670.0_wp, poisson=0.27_wp, friction=0.3_wp)

   call load_manchester(profiles_dir, prepared, error)
   if (.not. allocated(error)) call deepest_patch(prepared, 0.0_wp, geometry, error)
   if (.not. allocated(error)) call reference_y_geo(ref_dir, y_geo, error)
   if (.not. allocated(error)) call normal_tables(ref_root, ref_dir, out_dir, geometry, &
      material, y_geo, rec, error)
   if (.not. allocated(error)) call manchester_rows(prepared, out_dir//'manchester_10kN.csv', &
      error)
   if (.not. allocated(error)) call run_tangential(ref_dir, out_dir, geometry, material, rec, &
      error)
   if (.not. allocated(error)) call run_patches(ref_root, prepared, out_dir, error)
   call stop_on(error)
   write (output_unit, '(a)') 'shcontact-validate: tables written to '//out_dir
   call kinematic_sample(ref_root//'kinematic_sample/', profiles_dir, out_dir)
   call kinematic_sets(out_dir)
   ! The summary of every exact-theory set (doc/validation.md §6.6), from the runs above.
   call write_sets(out_dir, error)
   call stop_on(error)
   write (output_unit, '(a)') 'shcontact-validate: the summary of every set written to '// &
      out_dir//'sets.csv, sets.md'

contains

   !> Optional arguments: --help; --kinematic or --patches; then REFERENCE PROFILES OUTPUT
   !> (directories; with --kinematic the first is the kinematic sample's directory).
   subroutine arguments(ref_root, profiles_dir, out_dir, kinematic_only, patches_only, sets_only)
      character(len=:), allocatable, intent(out) :: ref_root, profiles_dir, out_dir
      logical, intent(out) :: kinematic_only, patches_only, sets_only
      character(len=64) :: first
      integer :: shift

      first = ''
      if (command_argument_count() >= 1) call get_command_argument(1, first)
      if (first == '--help' .or. first == '-h') then
         write (output_unit, '(a)') &
            'usage: shcontact-validate [REFERENCE [PROFILES [OUTPUT]]]', &
            '       shcontact-validate --kinematic [DIR [PROFILES [OUTPUT]]]', &
            '       shcontact-validate --patches [REFERENCE [PROFILES [OUTPUT]]]', &
            '       shcontact-validate --kinematic-sets [OUTPUT]', &
            '', &
            'Compares shcontact with the exact theory (CONTACT) and writes the tables of', &
            'doc/validation.md. Without an option: every comparison, the kinematic sample', &
            'last. --kinematic: only solve_kinematic against the kinematic sample', &
            '(kinematic_cases.csv, kinematic_summary.csv, kinematic.md). --patches: only', &
            'the DOE on every shared patch (patches_doe.csv, .md, patches_strips_*.csv).', &
            '--kinematic-sets: only the project''s kinematic sets of data/exact/kinematic_*/', &
            '(kinematic_sets.csv, .md; no external data needed; run from the repository root).', &
            'Defaults: REFERENCE DATA/reference/, PROFILES DATA/profiles/, OUTPUT', &
            'doc/validation/, DIR DATA/reference/kinematic_sample/, where DATA is', &
            '$SHCONTACT_EXTERNAL_DATA (../shared when it is not set).'
         stop
      end if
      kinematic_only = first == '--kinematic'
      patches_only = first == '--patches'
      sets_only = first == '--kinematic-sets'
      if (sets_only) then
         ref_root = ''
         profiles_dir = ''
         out_dir = directory_argument(2, 'doc/validation/')
         return
      end if
      if (first(1:1) == '-' .and. .not. (kinematic_only .or. patches_only)) then
         write (error_unit, '(a)') 'shcontact-validate: unknown option "'//trim(first)// &
            '" (see --help)'
         error stop 2
      end if
      shift = merge(1, 0, kinematic_only .or. patches_only)
      if (kinematic_only) then
         ref_root = directory_argument(1 + shift, external_data()//'reference/kinematic_sample/')
      else
         ref_root = directory_argument(1 + shift, external_data()//'reference/')
      end if
      profiles_dir = directory_argument(2 + shift, external_data()//'profiles/')
      out_dir = directory_argument(3 + shift, 'doc/validation/')
   end subroutine arguments

   !> The external-data folder with a trailing '/': $SHCONTACT_EXTERNAL_DATA, else ../shared/.
   function external_data() result(dir)
      character(len=:), allocatable :: dir
      integer :: length, stat
      call get_environment_variable('SHCONTACT_EXTERNAL_DATA', length=length, status=stat)
      if (stat /= 0 .or. length == 0) then
         dir = '../shared/'
         return
      end if
      allocate (character(len=length) :: dir)
      call get_environment_variable('SHCONTACT_EXTERNAL_DATA', dir)
      if (dir(length:length) /= '/') dir = dir//'/'
   end function external_data

   !> Argument i as a directory with a trailing '/', or the default.
   function directory_argument(i, default) result(dir)
      integer, intent(in) :: i
      character(len=*), intent(in) :: default
      character(len=:), allocatable :: dir
      character(len=1024) :: buf
      dir = default
      if (command_argument_count() < i) return
      call get_command_argument(i, buf)
      dir = trim(buf)
      if (dir(len(dir):len(dir)) /= '/') dir = dir//'/'
   end function directory_argument

   !> The kinematic sample (issue 12), or a note when it is absent.
   subroutine kinematic_sample(sample_dir, profiles_dir, out_dir)
      character(len=*), intent(in) :: sample_dir, profiles_dir, out_dir
      type(error_type), allocatable :: error
      logical :: there
      inquire (file=sample_dir//'kinematic_sample.csv', exist=there)
      if (there) inquire (file=profiles_dir//'MBench_S1002_v3.prw', exist=there)
      if (.not. there) then
         write (output_unit, '(a)') 'shcontact-validate: the kinematic sample '//sample_dir// &
            'kinematic_sample.csv or the profiles are absent; skipped.'
         return
      end if
      call run_kinematic(sample_dir, profiles_dir, out_dir, error)
      call stop_on(error)
      write (output_unit, '(a)') 'shcontact-validate: kinematic tables written to '//out_dir
   end subroutine kinematic_sample

   !> Stop with the error's message and status 1 when there is one.
   subroutine stop_on(error)
      type(error_type), allocatable, intent(in) :: error
      if (.not. allocated(error)) return
      write (error_unit, '(a)') 'shcontact-validate: '//error%message
      error stop 1
   end subroutine stop_on

   !> The project's kinematic sets (data/exact/kinematic_*/), which need no external data.
   subroutine kinematic_sets(out_dir)
      character(len=*), intent(in) :: out_dir
      type(error_type), allocatable :: error
      call run_kinematic_sets(out_dir, error)
      call stop_on(error)
      write (output_unit, '(a)') 'shcontact-validate: the kinematic sets written to '// &
         out_dir//'kinematic_sets.csv, kinematic_sets.md'
   end subroutine kinematic_sets

   !> CONTACT's y of the geometric contact point in its local coordinates (summary.csv y_geo).
   subroutine reference_y_geo(ref_dir, y_geo, error)
      character(len=*), intent(in) :: ref_dir
      real(wp), intent(out) :: y_geo
      type(error_type), allocatable, intent(out) :: error
      type(csv_table_type) :: summary
      call read_csv(ref_dir//'summary.csv', summary, error)
      if (allocated(error)) return
      call summary_value(summary, 'y_geo', y_geo, error)
   end subroutine reference_y_geo

   !> normal_summary.csv (the reference's patch and ours by method and reduction) and the strip
   !> tables normal_strips_<variant>.csv for the pressure maps.
   subroutine normal_tables(ref_root, ref_dir, out_dir, geometry, material, y_geo, rec, error)
      character(len=*), intent(in) :: ref_root, ref_dir, out_dir
      type(patch_geometry_type), intent(in) :: geometry
      type(material_type), intent(in) :: material
      real(wp), intent(in) :: y_geo
      type(recommended_type), intent(in) :: rec
      type(error_type), allocatable, intent(out) :: error
      character(len=*), parameter :: labels(3) = [character(len=22) :: 'semi-hertz_local-hertz', &
         'semi-hertz_constant', 'hertz']
      character(len=*), parameter :: methods(3) = [character(len=10) :: 'semi-hertz', &
         'semi-hertz', 'hertz']
      character(len=*), parameter :: reductions(3) = [character(len=11) :: 'local-hertz', &
         'constant', 'local-hertz']
      type(csv_writer_type) :: out
      type(patch_summary_type) :: s
      type(normal_patch_type) :: patch
      integer :: k

      call out%open(out_dir//'normal_summary.csv', 'source,approach_mm,load_N,length_mm,'// &
         'width_mm,area_mm2,p_max_MPa,y_min_mm,y_max_mm,y_centre_mm', error)
      if (allocated(error)) return
      call reference_patch_summary(ref_root//'headline_summary.csv', 'module3_exact_nonhertz', &
         ref_dir//'grid_module3_exact_nonhertz.csv', s, error)
      if (allocated(error)) return
      call write_summary(out, 'contact-exact', s)
      call reference_patch_summary(ref_root//'headline_summary.csv', 'module3_exact_hertz', &
         ref_dir//'grid_module3_exact_hertz.csv', s, error)
      if (allocated(error)) return
      ! CONTACT's Hertz grid is centred at the ellipse centre, i.e. at the geometric point.
      s%y_min = s%y_min + y_geo
      s%y_max = s%y_max + y_geo
      s%y_centre = s%y_centre + y_geo
      call write_summary(out, 'contact-exact-hertz-ellipse', s)
      do k = 1, size(labels)
         call solve_normal(geometry, material, methods(k), reductions(k), rec%n_strips, &
            64700.0_wp, patch, error)
         if (allocated(error)) return
         call write_summary(out, 'shcontact_'//trim(labels(k)), summarise_patch(patch, y_geo))
         call write_strips(out_dir//'normal_strips_'//trim(labels(k))//'.csv', patch, y_geo, &
            error)
         if (allocated(error)) return
      end do
      call out%close()
   end subroutine normal_tables

   !> One row of normal_summary.csv.
   subroutine write_summary(out, label, s)
      type(csv_writer_type), intent(in) :: out
      character(len=*), intent(in) :: label
      type(patch_summary_type), intent(in) :: s
      call out%row([s%approach, s%load, s%length, s%width, s%area, s%p_max, s%y_min, s%y_max, &
         s%y_centre], text=[label], digits=5)
   end subroutine write_summary

end program validate
