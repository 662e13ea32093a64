C     shcontact from fixed-form Fortran 77 through the legacy entry
C     points SHC_* (doc/api.md) and the include file shcontact.fi: the
C     profiles passed as arrays (here the built-in ones, fetched from a
C     contact created by name), a kinematic call as a vehicle code makes
C     it, the headline case with prescribed creepages and its element
C     fields, both wheels of a wheelset in one call, then five bad calls
C     that must come back with a status and a message.
C
C     S1002 wheel on a UIC60 rail canted 1:40 by the track, R0 = 460 mm,
C     G = 82670 MPa, nu = 0.27, mu = 0.3, FASTSIM_SH (the defaults).
C     Kinematic call: wheelset at Y_WS = 4.733 mm, yaw 4 mrad, 40 m/s,
C     pure rolling on R0, vertical wheel load 64.7 kN. Headline case:
C     normal force 64.7 kN, creepages 0.58e-3, 0.061e-3, 2.74e-4 1/mm.
C
C     Build:  gfortran headline.f $(pkg-config --cflags --libs shcontact)
C
      PROGRAM HEADLN
      IMPLICIT NONE
      INCLUDE 'shcontact.fi'
      DOUBLE PRECISION TY, ROLL, FN, CKSI, CETA, CPHI
C     Lateral wheelset shift Y_WS (mm): the app's default (doc/theory.md
C     decision 13).
      PARAMETER (TY = 4.733D0, ROLL = 0.0D0, FN = 64.7D3)
      PARAMETER (CKSI = 0.58D-3, CETA = 0.061D-3, CPHI = 2.74D-4)
C     The wheelset of the kinematic call (mm, rad, mm/s, rad/s, N).
      DOUBLE PRECISION YWS, YAW, VS, VPITCH, FZ
      PARAMETER (YWS = 4.733D0, YAW = 4.0D-3, VS = 40.0D3)
      PARAMETER (VPITCH = -VS/460.0D0, FZ = 64.7D3)
      DOUBLE PRECISION VALUES(SHC_RESULT_SIZE), G, POISS, FRIC, CNAN
      DOUBLE PRECISION VKIN(SHC_KIN_SIZE)
      INTEGER IH, ISTAT, IHWS
      DOUBLE PRECISION WSTOT(4), WSLFY
C     Profile points (mm): wheel and rail.
      INTEGER MAXPT, NW, NR, IHNAME
      PARAMETER (MAXPT = 4000)
      DOUBLE PRECISION YW(MAXPT), ZW(MAXPT), YR(MAXPT), ZR(MAXPT)
C     Element fields of patch 1, NX elements per strip by NY strips.
      INTEGER MAXEL, NX, NY, I, NSLIP
      PARAMETER (MAXEL = 20000)
      DOUBLE PRECISION X(MAXEL), Y(MAXEL), AREA(MAXEL), PN(MAXEL)
      DOUBLE PRECISION PX(MAXEL), PY(MAXEL), SLIP(MAXEL)
      DOUBLE PRECISION SUMFX, SUMFY
      INTEGER ISTATE(MAXEL)
      CHARACTER*200 MSG
      CHARACTER*3 STRNAN
      DATA STRNAN /'NaN'/
C
C     The profiles as arrays: a vehicle code has its own; here they are
C     the built-in ones, taken from a contact created from their names.
      CALL SHC_CREATE(IH, 'builtin:S1002', 'builtin:UIC60', 1, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      CALL SHC_GET_PROFILE(IH, SHC_PROFILE_WHEEL, MAXPT, NW, YW, ZW,
     &                     ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      CALL SHC_GET_PROFILE(IH, SHC_PROFILE_RAIL, MAXPT, NR, YR, ZR,
     &                     ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      IHNAME = IH
C     Wheel points from the field side to the flange back, rail points
C     from the track centre to the field side; y to the field side, z
C     down (mm). Checked and cleaned as profile files are.
      CALL SHC_CREATE_ARRAYS(IH, NW, YW, ZW, NR, YR, ZR, SHC_RIGHT,
     &                       ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      CALL SHC_DESTROY(IHNAME, ISTAT)
      G = 82670.0D0
      POISS = 0.27D0
      FRIC = 0.3D0
      CALL SHC_SET_MATERIAL(IH, G, POISS, FRIC, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      CALL SHC_SET_OPTION(IH, 'tangential%method', 'fastsim-sh', ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
C     Keep the element fields of every solve (off by default: no cost).
      CALL SHC_SET_OPTION(IH, 'output%fields', 'all', ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
C
C     The kinematic call: position, velocities, vertical wheel load.
C     Arguments: Y_WS, YAW, ROLL, VS, VY, VZ, VROLL, VYAW, VPITCH.
      CALL SHC_SOLVE_KIN(IH, YWS, YAW, 0.0D0, VS, 0.0D0, 0.0D0,
     &                   0.0D0, 0.0D0, VPITCH,
     &                   SHC_LOAD_VERTICAL_FORCE, FZ, VKIN, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      WRITE (*, '(A)') '# kinematic call, legacy Fortran 77 interface'
      WRITE (*, 100) 'kin_sum_fx', VKIN(SHC_SUM_FX)
      WRITE (*, 100) 'kin_sum_fy', VKIN(SHC_SUM_FY)
      WRITE (*, 100) 'kin_sum_fz', VKIN(SHC_SUM_FZ)
      WRITE (*, 100) 'kin_fn', VKIN(SHC_FN)
      WRITE (*, 100) 'kin_nu_x', VKIN(SHC_NU_X)
      WRITE (*, 100) 'kin_nu_y', VKIN(SHC_NU_Y)
      WRITE (*, 100) 'kin_phi', VKIN(SHC_PHI)
      WRITE (*, 100) 'kin_x_track', VKIN(SHC_X_TRACK)
C
C     The headline case: position, normal force, creepages.
      CALL SHC_SOLVE(IH, TY, ROLL, SHC_LOAD_NORMAL_FORCE, FN, CKSI,
     &               CETA, CPHI, VALUES, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      WRITE (*, '(A)') '# headline case, legacy Fortran 77 interface'
      WRITE (*, 100) 't_y', TY
      WRITE (*, 100) 'fx', VALUES(SHC_FX)
      WRITE (*, 100) 'fy', VALUES(SHC_FY)
      WRITE (*, 100) 'mz', VALUES(SHC_MZ)
      WRITE (*, 100) 'fn', VALUES(SHC_FN)
      WRITE (*, 100) 'fx_norm', VALUES(SHC_FX_NORM)
      WRITE (*, 100) 'fy_norm', VALUES(SHC_FY_NORM)
      WRITE (*, 100) 'gamma0', VALUES(SHC_GAMMA0)
      WRITE (*, 100) 'n_patches', VALUES(SHC_N_PATCHES)
      WRITE (*, 100) 'sum_fz', VALUES(SHC_SUM_FZ)
C
C     The element fields of the main patch: tractions times element
C     areas add up to its forces.
      CALL SHC_FIELD_SIZE(IH, NINT(VALUES(SHC_MAIN_PATCH)), NX, NY,
     &                    ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      IF (NX*NY .GT. MAXEL) THEN
         WRITE (*, '(A,2I6)') 'error: fields larger than MAXEL:', NX, NY
         STOP 1
      END IF
      CALL SHC_FIELDS(IH, NINT(VALUES(SHC_MAIN_PATCH)), NX, NY, X, Y,
     &                AREA, PN, PX, PY, SLIP, ISTATE, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      SUMFX = 0.0D0
      SUMFY = 0.0D0
      NSLIP = 0
      DO 10 I = 1, NX*NY
         SUMFX = SUMFX + PX(I)*AREA(I)
         SUMFY = SUMFY + PY(I)*AREA(I)
         IF (ISTATE(I) .EQ. SHC_STATE_SLIP) NSLIP = NSLIP + 1
   10 CONTINUE
      WRITE (*, '(A,1X,I6)') 'field_nx', NX
      WRITE (*, '(A,1X,I6)') 'field_ny', NY
      WRITE (*, '(A,1X,I6)') 'field_slip_elements', NSLIP
      WRITE (*, 100) 'field_sum_fx', SUMFX
      WRITE (*, 100) 'field_sum_fy', SUMFY
C
C     Both wheels in one call (a wheelset handle): the wheelset 5 mm
C     to the right, yaw 2 mrad, lateral velocity 10 mm/s, yaw rate
C     0.01 rad/s at 30 m/s; 64.7 kN on the right wheel, 60 kN on the
C     left. WSTOT: F_x, F_y, F_z (N) on the wheelset, M_z (N mm).
      CALL SHC_CREATE_WS(IHWS, 'builtin:S1002', 'builtin:UIC60', ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 910
      CALL SHC_SOLVE_WS(IHWS, 5.0D0, 2.0D-3, 0.0D0, 30.0D3, 10.0D0,
     &                  0.0D0, 0.0D0, 0.01D0, -30.0D3/460.0D0,
     &                  SHC_LOAD_VERTICAL_FORCE, 64.7D3, 60.0D3,
     &                  WSTOT, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 910
C     A wheel's values by name (keyed: 'right%...', 'left%...').
      CALL SHC_GET_VALUE(IHWS, 'left%sum_fy', 0, WSLFY, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 910
      CALL SHC_WS_WHEEL(IHWS, SHC_RIGHT, 0, VKIN, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 910
      WRITE (*, '(A)') '# wheelset call, legacy Fortran 77 interface'
      WRITE (*, 100) 'ws_fx', WSTOT(1)
      WRITE (*, 100) 'ws_fy', WSTOT(2)
      WRITE (*, 100) 'ws_fz', WSTOT(3)
      WRITE (*, 100) 'ws_mz', WSTOT(4)
      WRITE (*, 100) 'ws_right_n_loaded', VKIN(SHC_N_LOADED)
      WRITE (*, 100) 'ws_left_sum_fy', WSLFY
      CALL SHC_DESTROY(IHWS, ISTAT)
C
C     Bad calls: an invalid handle, a negative load, a NaN creepage,
C     a wheelset that does not move forward, a wheel of one point.
      CALL SHC_SOLVE(IH + 999, TY, ROLL, SHC_LOAD_NORMAL_FORCE, FN,
     &               CKSI, CETA, CPHI, VALUES, ISTAT)
      CALL SHC_ERRMSG(IH + 999, MSG)
      WRITE (*, 200) 'status_invalid_handle', ISTAT, MSG
      CALL SHC_SOLVE(IH, TY, ROLL, SHC_LOAD_NORMAL_FORCE, -FN, CKSI,
     &               CETA, CPHI, VALUES, ISTAT)
      CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, 200) 'status_negative_load', ISTAT, MSG
      READ (STRNAN, *) CNAN
      CALL SHC_SOLVE(IH, TY, ROLL, SHC_LOAD_NORMAL_FORCE, FN, CNAN,
     &               CETA, CPHI, VALUES, ISTAT)
      CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, 200) 'status_nan_creepage', ISTAT, MSG
      CALL SHC_SOLVE_KIN(IH, YWS, YAW, 0.0D0, 0.0D0, 0.0D0, 0.0D0,
     &                   0.0D0, 0.0D0, VPITCH,
     &                   SHC_LOAD_VERTICAL_FORCE, FZ, VKIN, ISTAT)
      CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, 200) 'status_kin_zero_speed', ISTAT, MSG
      CALL SHC_CREATE_ARRAYS(IHNAME, 1, YW, ZW, NR, YR, ZR, SHC_RIGHT,
     &                       ISTAT)
      CALL SHC_ERRMSG(IHNAME, MSG)
      WRITE (*, 200) 'status_bad_array', ISTAT, MSG
      CALL SHC_DESTROY(IHNAME, ISTAT)
C
      CALL SHC_DESTROY(IH, ISTAT)
C     The normal end falls through to END: a STOP would make gfortran
C     print a note on the floating-point flags the solver left raised
C     (underflow, harmless).
      GOTO 999
C
  900 CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, '(A,I3,2A)') 'error: status', ISTAT, ': ', MSG
      STOP 1
  910 CALL SHC_ERRMSG(IHWS, MSG)
      WRITE (*, '(A,I3,2A)') 'error: status', ISTAT, ': ', MSG
      STOP 1
  100 FORMAT (A, 1X, 1PE25.17)
  200 FORMAT (A, 1X, I3, 1X, A)
  999 CONTINUE
      END
