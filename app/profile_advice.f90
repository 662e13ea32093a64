!> `shcontact profiles FILE`: what the points suggest for a case (doc/profiles.md, *Measured
!> profiles: cant and smoothing*): whether a rail looks canted already, the noise of the points
!> and the smoothing length it calls for; and `shcontact run`'s notes where a case's settings
!> disagree with that ([[profile_notes]]).
module shcontact_app_profile_advice
   use shcontact_core_kinds, only: wp
   use shcontact_core_strings, only: str_format, to_lower
   use shcontact, only: profile_type, profile_kind_wheel, noise_estimate_type, estimate_noise, &
      suggested_smoothing, curvature_noise, rail_cant_type, estimate_rail_cant, &
      default_curvature_tolerance, case_config_type, point_anomaly_type, find_point_anomalies
   implicit none
   private

   public :: profile_advice, profile_notes

   !> A head within this slope of upright (mm/mm) looks upright; half of the usual 1:40.
   real(wp), parameter :: upright_band = 0.0125_wp
   !> Suggested smoothing below this length (mm) is not worth setting.
   real(wp), parameter :: negligible_smoothing = 0.5_wp

   !> What a gap that counts means.
   character(len=*), parameter :: gap_meaning = 'points are missing there, and the '// &
      'profile is a straight chord across the gap (check the measurement)'
   !> What an outlier that counts means.
   character(len=*), parameter :: outlier_meaning = 'a single bad point? the spline '// &
      'turns it into a curvature spike and the contact there into a pressure peak (remove '// &
      'the point, or smooth the profile)'

contains

   !> The advice lines ("cant ...", "noise ...", "smoothing ..."), newline-separated.
   function profile_advice(read, cleaned) result(text)
      !> The points as read (canonical form, before the clean-up) and the cleaned profile.
      type(profile_type), intent(in) :: read, cleaned
      character(len=:), allocatable :: text
      character(len=1), parameter :: nl = new_line('a')
      text = ''
      if (cleaned%kind /= profile_kind_wheel) text = cant_line(cleaned)//nl
      text = text//noise_lines(read, cleaned%kind)//nl//anomaly_lines(read, cleaned)
   end function profile_advice

   !> The 'gap' and 'outlier' lines: the largest of each among the points as read, with what
   !> it means when it counts.
   function anomaly_lines(read, cleaned) result(text)
      type(profile_type), intent(in) :: read, cleaned
      character(len=:), allocatable :: text
      type(noise_estimate_type) :: noise
      type(point_anomaly_type) :: anomaly
      call estimate_noise(read, noise)
      call find_point_anomalies(read, cleaned, noise%sigma, anomaly)
      text = 'gap        largest '//str_format(anomaly%gap, '(f0.3)')//' mm '// &
         between_points(read, anomaly%gap_at)//', median spacing '// &
         str_format(anomaly%spacing, '(f0.3)')//' mm'
      if (anomaly%has_gap) text = text//': '//gap_meaning
      text = text//new_line('a')//'outlier    largest '// &
         str_format(anomaly%outlier, '(es9.2)')//' mm off the cubic through its six '// &
         'neighbours (within 25 mm of the running surface, not beyond a wheel''s flange tip)'
      if (anomaly%outlier_at > 0) text = text//' '//at_point(cleaned, anomaly%outlier_at)
      if (anomaly%has_outlier) text = text//': '//outlier_meaning
   end function anomaly_lines

   !> "between points k and k+1 (y = a … b mm)" of the points as read.
   function between_points(profile, k) result(text)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      text = 'between points '//str_format(real(k, wp), '(f0.0)')//' and '// &
         str_format(real(k + 1, wp), '(f0.0)')//' of the '// &
         str_format(real(size(profile%y), wp), '(f0.0)')//' read (y = '//str_format(profile%y(k), '(f0.2)')//' to '// &
         str_format(profile%y(k + 1), '(f0.2)')//' mm)'
   end function between_points

   !> "at point k of n (y, z = a, b mm)" of the cleaned points.
   function at_point(profile, k) result(text)
      type(profile_type), intent(in) :: profile
      integer, intent(in) :: k
      character(len=:), allocatable :: text
      text = 'at point '//str_format(real(k, wp), '(f0.0)')//' of the '// &
         str_format(real(size(profile%y), wp), '(f0.0)')//' after clean-up (y, z = '// &
         str_format(profile%y(k), '(f0.3)')//', '//str_format(profile%z(k), '(f0.3)')//' mm)'
   end function at_point

   function cant_line(rail) result(text)
      type(profile_type), intent(in) :: rail
      character(len=:), allocatable :: text, evidence
      type(rail_cant_type) :: cant
      call estimate_rail_cant(rail, cant)
      if (.not. cant%found) then
         text = 'cant       not estimated (no crown with a gauge face 14 mm below it)'
         return
      end if
      evidence = ' (crown top '//str_format(cant%offset, '(f0.1)')//' mm from the gauge point; '// &
         'upright 60E1 head: '//str_format(cant%offset_upright, '(f0.1)')//' mm)'
      if (cant%slope >= upright_band) then
         text = 'cant       the rail head looks inclined by about 1:'// &
            str_format(1.0_wp/cant%slope, '(f0.0)')//' towards the track centre'//evidence// &
            ': the points look already canted; set the rail cant with track%rail_canted '// &
            '= .true. (--set track%rail_canted=.true.) so that rail_inclination is not '// &
            'applied again'
      else if (cant%slope <= -upright_band) then
         text = 'cant       the rail head looks inclined by about 1:'// &
            str_format(-1.0_wp/cant%slope, '(f0.0)')//' away from the track centre'//evidence// &
            ': check the side (--mirror-y) and the measurement'
      else
         text = 'cant       the rail head looks upright (inclination below 1:'// &
            str_format(1.0_wp/upright_band, '(f0.0)')//')'//evidence//': keep track%rail_canted '// &
            '= .false.; the track''s rail_inclination (1:40 by default) sets the rail cant'
      end if
   end function cant_line

   function noise_lines(read, kind) result(text)
      type(profile_type), intent(in) :: read
      integer, intent(in) :: kind
      character(len=:), allocatable :: text, variable
      type(noise_estimate_type) :: noise
      real(wp) :: l_filt
      call estimate_noise(read, noise)
      if (noise%windows == 0) then
         text = 'noise      not estimated (too few points)'
         return
      end if
      variable = 'profiles%rail_smoothing'
      if (kind == profile_kind_wheel) variable = 'profiles%wheel_smoothing'
      l_filt = suggested_smoothing(noise%sigma, noise%spacing)
      text = 'noise      '//str_format(noise%sigma, '(es9.2)')//' mm rms normal to the profile '// &
         '(cubic fits over 7 points), point spacing '//str_format(noise%spacing, '(f0.2)')//' mm'// &
         new_line('a')
      if (l_filt < negligible_smoothing) then
         text = text//'smoothing  not needed: the curvature noise is below '// &
            str_format(default_curvature_tolerance, '(es8.1)')//' 1/mm already with L_filt = '// &
            str_format(l_filt, '(f0.2)')//' mm (doc/profiles.md)'
      else
         text = text//'smoothing  '//variable//' = '//str_format(l_filt, '(f0.1)')//' mm keeps the '// &
            'curvature noise below '//str_format(default_curvature_tolerance, '(es8.1)')// &
            ' 1/mm (10 % of a 300 mm crown; '//str_format(curvature_noise(noise%sigma, &
            noise%spacing, 2.0_wp), '(es8.1)')//' 1/mm at 2 mm); doc/profiles.md'
      end if
   end function noise_lines

   !> The notes `shcontact run` prints (one per line, each starting 'note: ') where the case's
   !> settings disagree with what its profiles' points suggest: a profile file whose measurement
   !> noise calls for smoothing while its smoothing length is 0 (the spline then interpolates
   !> the noise into the curvatures), and a rail whose head looks canted already while
   !> track%rail_canted is false (the track's inclination is then applied a second time), or
   !> upright while it is true. Built-in profiles get the cant note only.
   function profile_notes(config, wheel_read, rail_read, wheel, rail) result(text)
      !> The case, its profiles' points as read and as the run cleans them (the noise and the
      !> gaps from the points read, the outliers from the clean points and the cant from the
      !> clean rail, as [[profile_advice]]).
      type(case_config_type), intent(in) :: config
      type(profile_type), intent(in) :: wheel_read, rail_read, wheel, rail
      character(len=:), allocatable :: text
      type(rail_cant_type) :: cant
      text = smoothing_note('wheel', config%profiles%wheel, wheel_read, &
         config%profiles%wheel_smoothing, 'profiles%wheel_smoothing')
      text = text//smoothing_note('rail', config%profiles%rail, rail_read, &
         config%profiles%rail_smoothing, 'profiles%rail_smoothing')
      text = text//anomaly_notes('wheel', config%profiles%wheel, wheel_read, wheel)
      text = text//anomaly_notes('rail', config%profiles%rail, rail_read, rail)
      call estimate_rail_cant(rail, cant)
      if (.not. cant%found) return
      if (cant%slope >= upright_band .and. .not. config%track%rail_canted) then
         text = text//'note: rail profile '//trim(config%profiles%rail)//': the head looks '// &
            'inclined by about 1:'//str_format(1.0_wp/cant%slope, '(f0.0)')//' already, and '// &
            'track%rail_canted = .false. inclines it by the track''s rail_inclination again; '// &
            'set track%rail_canted = .true. if the points are canted (shcontact profiles '// &
            'FILE, doc/profiles.md)'//new_line('a')
      else if (abs(cant%slope) < upright_band .and. config%track%rail_canted) then
         text = text//'note: rail profile '//trim(config%profiles%rail)//': the head looks '// &
            'upright, and track%rail_canted = .true. leaves it so (no rail cant); set '// &
            'track%rail_canted = .false. for the track''s rail_inclination (doc/profiles.md)'// &
            new_line('a')
      end if
   end function profile_notes

   !> The gap and outlier notes of one profile file ('' when it is built in or has neither).
   function anomaly_notes(what, spec, read, cleaned) result(text)
      character(len=*), intent(in) :: what, spec
      type(profile_type), intent(in) :: read, cleaned
      character(len=:), allocatable :: text
      type(noise_estimate_type) :: noise
      type(point_anomaly_type) :: anomaly
      text = ''
      if (index(to_lower(adjustl(spec)), 'builtin:') == 1) return
      call estimate_noise(read, noise)
      call find_point_anomalies(read, cleaned, noise%sigma, anomaly)
      if (anomaly%has_gap) text = text//'note: '//what//' profile '//trim(spec)//': a gap of '// &
         str_format(anomaly%gap, '(f0.2)')//' mm '//between_points(read, anomaly%gap_at)// &
         ' where the points are '//str_format(anomaly%spacing, '(f0.2)')//' mm apart: '// &
         gap_meaning//'; shcontact profiles FILE, doc/profiles.md'//new_line('a')
      if (anomaly%has_outlier) text = text//'note: '//what//' profile '//trim(spec)// &
         ': a point '//str_format(anomaly%outlier, '(f0.3)')//' mm off the cubic through its '// &
         'six neighbours '//at_point(cleaned, anomaly%outlier_at)//': '//outlier_meaning// &
         '; shcontact profiles FILE, doc/profiles.md'//new_line('a')
   end function anomaly_notes

   !> The smoothing note of one profile file ('' when it is built in, smoothed or clean).
   function smoothing_note(what, spec, profile, smoothing, variable) result(text)
      character(len=*), intent(in) :: what, spec, variable
      type(profile_type), intent(in) :: profile
      real(wp), intent(in) :: smoothing
      character(len=:), allocatable :: text
      type(noise_estimate_type) :: noise
      real(wp) :: l_filt
      text = ''
      if (smoothing > 0.0_wp .or. index(to_lower(adjustl(spec)), 'builtin:') == 1) return
      call estimate_noise(profile, noise)
      if (noise%windows == 0) return
      l_filt = suggested_smoothing(noise%sigma, noise%spacing)
      if (l_filt < negligible_smoothing) return
      text = 'note: '//what//' profile '//trim(spec)//': measurement noise '// &
         str_format(noise%sigma, '(es9.2)')//' mm rms and '//variable//' = 0: the spline '// &
         'interpolates the noise into the curvatures ('//str_format(curvature_noise( &
         noise%sigma, noise%spacing, 2.0_wp), '(es8.1)')//' 1/mm at 2 mm); '//variable// &
         ' = '//str_format(l_filt, '(f0.1)')//' mm keeps it below '// &
         str_format(default_curvature_tolerance, '(es8.1)')//' 1/mm (shcontact profiles '// &
         'FILE, doc/profiles.md)'//new_line('a')
   end function smoothing_note

end module shcontact_app_profile_advice
