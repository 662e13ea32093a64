!> The help texts of the shcontact program: the general usage (`shcontact --help`) and one text
!> per command (`shcontact COMMAND --help`).
module shcontact_app_help
   implicit none
   private

   public :: usage_text, command_help, exit_status_text

   character(len=1), parameter :: nl = new_line('a')

contains

   !> The usage text of `shcontact --help`: every command in one line, then where to look.
   function usage_text() result(text)
      character(len=:), allocatable :: text
      text = &
         'Usage:'//nl// &
         '  shcontact run [CASE.nml] [options]    solve the case (default: the built-in '// &
         'headline case)'//nl// &
         '  shcontact merge OUT.h5 SHARD.h5...    merge the shard files of one run'//nl// &
         '  shcontact profiles FILE [-o OUT]      check, clean and export a measured profile'// &
         nl// &
         '  shcontact profiles --write DIR        write the built-in profiles as 2-column files'// &
         nl// &
         '  shcontact geometry [CASE.nml] [-o FILE] [--set ...] [--force]'//nl// &
         '                                        write the strip geometry table of the case'// &
         nl// &
         '  shcontact geometry --wheelset -10,10,0.5 --conicity 1,2,3'//nl// &
         '                                        wheelset contact table, equivalent conicity'// &
         nl// &
         '  shcontact --help | --version'//nl//nl// &
         '`shcontact COMMAND --help` shows the options of a command. Documentation: doc/app.md.'// &
         nl//nl//exit_status_text()
   end function usage_text

   !> The exit statuses, as every help text ends.
   function exit_status_text() result(text)
      character(len=:), allocatable :: text
      text = &
         'Exit status: 0 ok, 1 usage error, 2 invalid input, 3 I/O failure, 4 some sweep '// &
         'cases failed,'//nl// &
         '             5 numerical failure, 6 no contact (profiles do not touch)'
   end function exit_status_text

   !> The help of one command ('' for an unknown one).
   function command_help(command) result(text)
      !> 'run', 'merge', 'profiles' or 'geometry'.
      character(len=*), intent(in) :: command
      character(len=:), allocatable :: text
      select case (command)
      case ('run')
         text = run_help()
      case ('merge')
         text = merge_help()
      case ('profiles')
         text = profiles_help()
      case ('geometry')
         text = geometry_help()
      case default
         text = ''
         return
      end select
      text = text//nl//nl//exit_status_text()
   end function command_help

   function run_help() result(text)
      character(len=:), allocatable :: text
      text = &
         'Usage: shcontact run [CASE.nml] [options]'//nl//nl// &
         'Solve the case or sweep of CASE.nml (default: the built-in headline case), write the'// &
         nl// &
         'results to an HDF5 file and print a summary on stdout.'//nl//nl// &
         'Options:'//nl// &
         '  -o, --output FILE        HDF5 output file (= --set output%file=FILE; default '// &
         'shcontact.h5'//nl// &
         '                           in the working directory)'//nl// &
         '  --set GROUP%VAR=VALUE    override a namelist variable (repeatable; lists as '// &
         'v1,v2,...)'//nl// &
         '  --check                  validate, print the resolved namelist, solve nothing'//nl// &
         '  --format text|csv|json|none'//nl// &
         '                           summary on stdout: readable, CSV, JSON lines, or nothing'// &
         nl// &
         '                           (csv/json lines carry every input of the case)'//nl// &
         '  --csv-units              with --format csv: a second header line with the units'// &
         nl// &
         '  -q, --quiet              errors only on stderr (no progress, no notes); no '// &
         'summary on'//nl// &
         '                           stdout either, unless --format is given'//nl// &
         '  -v, --verbose            more notes on stderr'//nl// &
         '  --threads N              OpenMP threads (default: OMP_NUM_THREADS or all cores)'// &
         nl// &
         '  --block-memory MB        results (element fields) held in memory at once, in MiB'// &
         nl// &
         '                           (default 64): the checkpoint blocks are cut to fit'//nl// &
         '  --shard I/N              solve the I-th of N slices of a sweep into '// &
         'OUT-shardIofN.h5'//nl// &
         '  --shard slurm            take I/N from the Slurm job array: SLURM_ARRAY_TASK_ID'// &
         nl// &
         '                           - SLURM_ARRAY_TASK_MIN, over SLURM_ARRAY_TASK_STEP, + 1,'// &
         nl// &
         '                           of SLURM_ARRAY_TASK_COUNT'//nl// &
         '                           (without --shard the Slurm variables are ignored)'//nl// &
         '  --resume                 complete an interrupted run from its checkpoint '// &
         'OUT.h5.partial/'//nl// &
         '                           (a finished run of this configuration is left as it is)'// &
         nl// &
         '  --force                  replace an OUT.h5 or OUT.xmf that shcontact did not '// &
         'write, or'//nl// &
         '                           start afresh over an interrupted run''s checkpoint'// &
         nl// &
         '  --no-output              write no result file (e.g. with --format csv in a shell '// &
         'loop)'//nl//nl// &
         'Progress goes to stderr: a bar on a terminal, else a line (cases done, rate, ETA)'// &
         nl// &
         'when the solved cases cross a tenth of the run, or after 10 s. The ETA is the '// &
         'solving''s;'//nl//'a run with element fields then writes its output (longer).'
   end function run_help

   function merge_help() result(text)
      character(len=:), allocatable :: text
      text = &
         'Usage: shcontact merge OUT.h5 SHARD.h5...'//nl//nl// &
         'Merge the shard files of one run (shcontact run --shard I/N, or the checkpoint'//nl// &
         'blocks of an interrupted run) into OUT.h5, identical dataset for dataset to the'//nl// &
         'file of an unsharded run. The shards must come from the same configuration and'//nl// &
         'hold every case exactly once; OUT.h5 must not be one of them.'//nl//nl// &
         'Options:'//nl// &
         '  --force                  replace an OUT.h5 or OUT.xmf that shcontact did not '// &
         'write'//nl// &
         '  -q, --quiet              errors only on stderr'
   end function merge_help

   function profiles_help() result(text)
      character(len=:), allocatable :: text
      text = &
         'Usage: shcontact profiles FILE [options]'//nl// &
         '       shcontact profiles --write DIR'//nl//nl// &
         'Read a measured wheel or rail profile (plain y z columns, SIMPACK .prr/.prw, '// &
         'MiniProf'//nl// &
         '.ban/.whl), check and clean it as a case does (point order, duplicates, loops, '// &
         'spikes,'//nl// &
         'running surface) and print a summary (points, range, units) on stdout, with '// &
         'whether'//nl// &
         'a rail looks canted already, the noise of the points and the smoothing length '// &
         'it calls'//nl// &
         'for (doc/profiles.md). With --write,'//nl// &
         'write the built-in profiles (S1002.txt, UIC60.txt, UIC60-canted.txt) into DIR instead.'//nl//nl// &
         'Options:'//nl// &
         '  -o, --output OUT         write the cleaned profile as a 2-column file (y z in mm,'// &
         nl// &
         '                           z down, right side), readable as a case input'//nl// &
         '  --plot SCRIPT.gp         write a gnuplot script plotting the points read and '// &
         'the'//nl// &
         '                           cleaned profile (gnuplot SCRIPT.gp makes SCRIPT.png)'// &
         nl// &
         '  --kind wheel|rail        the kind of profile, when the file does not say'//nl// &
         '  --file-format auto|plain|simpack|miniprof'//nl// &
         '                           file format (default auto: by extension)'//nl// &
         '  --scale F                factor from the file''s length unit to mm (default: '// &
         'as the'//nl// &
         '                           file says, else 1)'//nl// &
         '  --mirror-y yes|no        mirror y (y -> -y), replacing the file''s or format''s '// &
         'setting'//nl// &
         '  --mirror-z yes|no        mirror z (z -> -z), likewise'//nl// &
         '  --force                  replace OUT, SCRIPT.gp or the three files of --write DIR'// &
         nl// &
         '                           (S1002.txt, UIC60.txt, UIC60-canted.txt) when they exist'// &
         nl// &
         '                           (never the profile read)'//nl// &
         '  -q, --quiet              no summary; errors only'
   end function profiles_help

   function geometry_help() result(text)
      character(len=:), allocatable :: text
      text = &
         'Usage: shcontact geometry [CASE.nml] [-o FILE] [--set GROUP%VAR=VALUE]...'//nl// &
         '       shcontact geometry [CASE.nml] [--wheelset Y_MIN,Y_MAX,STEP] '// &
         '[--conicity A[,A...]] [--set ...]'//nl//nl// &
         'Write the contact-patch geometry of the case''s wheel position (gap, A(y), B(y),'// &
         nl// &
         'gamma(y), r_w(y), delta r per table point) as a text table, for plots of the '// &
         'profiles'//nl// &
         'and the lateral curvature. Uses t_y and roll only (no yaw).'//nl//nl// &
         'Options:'//nl// &
         '  -o, --output FILE        the table (default geometry.txt in the working '// &
         'directory)'//nl// &
         '  --set GROUP%VAR=VALUE    override a namelist variable (repeatable)'//nl// &
         '  --wheelset Y_MIN,Y_MAX,STEP'//nl// &
         '                           instead: the wheelset contact geometry on stdout, one '// &
         'line per'//nl// &
         '                           lateral shift y (mm): roll, contact points on rail and '// &
         'wheel,'//nl// &
         '                           rolling radii, dr = r_R - r_L, contact angles of both '// &
         'wheels'//nl// &
         '  --conicity A[,A...]      the equivalent conicity for these amplitudes (mm) on '// &
         'stdout:'//nl// &
         '                           EN 15302 wavelength method and first-harmonic balance,'// &
         nl// &
         '                           Klingel wavelength, roll-angle parameter '// &
         '(doc/geometry.md)'//nl// &
         '  --force                  replace the table when it exists (never the case file)'// &
         nl// &
         '  -q, --quiet              errors only on stderr'
   end function geometry_help

end module shcontact_app_help
