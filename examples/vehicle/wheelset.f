C     A single wheelset in a frame running at constant speed on straight
C     track, integrated in time through the legacy entry points SHC_* as
C     an old vehicle code would call them (doc/vehicle.md).
C
C     Degrees of freedom: lateral shift Y (m) and yaw angle PSI (rad) of
C     the wheelset; the frame moves straight at speed V. Suspension:
C     lateral spring KY (N/m) and yaw spring KPSI (N m/rad) with dampers
C     CY, CPSI to the frame. Contact: by default S1002 wheels on UIC60 rails 1:40,
C     one wheelset handle for both wheels (SHC_CREATE_WS), vertical load
C     64.7 kN per wheel (SHC_LOAD_VERTICAL_FORCE), creepages from the
C     wheelset's motion, one call per step for both wheels
C     (SHC_SOLVE_WS: the forces on the wheelset and their yaw moment;
C     SHC_WS_WHEEL: each wheel's values). The wheelset turns about its axle at the
C     speed of pure rolling on the centred wheelset's radius; its roll
C     angle, vertical and longitudinal motion are not modelled.
C
C     Units: the dynamics in SI (m, kg, s, N); the library takes mm,
C     mm/s, rad, rad/s and N: Y and the velocities are multiplied by
C     1000 at the call, contact coordinates divided by 1000.
C
C     Integration: semi-implicit (symplectic) Euler, one contact
C     evaluation (both wheels) per step.
C
C     Build:  gfortran wheelset.f $(pkg-config --cflags --libs shcontact)
C     Run:    ./a.out [--duration S] [--dt S] [--speed M/S] [--y0 MM]
C                     [--ky N/M] [--kpsi NM/RAD] [--cy NS/M]
C                     [--cpsi NMS/RAD] [--every N] [--csv FILE]
C                     [--wheel FILE] [--rail FILE] [--set KEY=VALUE]
C     (--wheel and --rail: profile files or builtin: names as
C     SHC_CREATE_WS takes them; default the built-in S1002 and UIC60.
C     --set: an option of SHC_SET_OPTION, e.g.
C     --set profiles%wheel_smoothing=2.9; repeatable, at most 16.)
C
C     Prints the run's summary as 'key value' lines: calls, failed
C     calls, median cost per wheelset call (us) with the CPU model and
C     the load average, amplitudes; writes every N-th step to the CSV.
C
      PROGRAM WHLSET
      IMPLICIT NONE
      INCLUDE 'shcontact.fi'
C     Wheelset mass (kg), yaw inertia (kg m2), vertical load per wheel.
      DOUBLE PRECISION MASS, INERT, FLOAD
      PARAMETER (MASS = 1500.0D0, INERT = 700.0D0, FLOAD = 64.7D3)
C     Most contact-call timings kept for the median.
      INTEGER MAXT
      PARAMETER (MAXT = 2000000)
      DOUBLE PRECISION TUS(MAXT)
      COMMON /TIMES/ TUS
C     Run options (GETOPT).
      DOUBLE PRECISION TEND, DT, SPEED, Y0MM, KY, KPSI, CY, CPSI
      INTEGER NEVERY, NSET, ISET, IEQ
      CHARACTER*256 CSV, WHEEL, RAIL, SETS(16)
C     State: Y (m), PSI (rad), VY (m/s), R (rad/s).
      DOUBLE PRECISION Y, PSI, VY, R, T
C     Per wheel: forces in the track frame (N).
      DOUBLE PRECISION FX(2), FY(2), FZ(2), R0(2)
      INTEGER NP(2), IH, ISIDE(2)
      DOUBLE PRECISION V, PITCH, FYTOT, MZTOT, AY, AR, US
      DOUBLE PRECISION YMAX, PMAX, YLATE, PLATE, TLATE, YPREV, TCROSS
      DOUBLE PRECISION TFIRST, MEDIAN, RCEN
      INTEGER ISTAT, NSTEP, ISTEP, NCALL, NFAIL, NKEPT, NCROSS
      INTEGER IUCSV
      CHARACTER*512 MSG
      DATA ISIDE /1, -1/
C
      CALL GETOPT(TEND, DT, SPEED, Y0MM, KY, KPSI, CY, CPSI, NEVERY,
     &            CSV, WHEEL, RAIL, SETS, NSET)
      V = SPEED
      CALL SHC_CREATE_WS(IH, WHEEL(1:LEN_TRIM(WHEEL)),
     &                   RAIL(1:LEN_TRIM(RAIL)), ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      DO 2 ISET = 1, NSET
         IEQ = INDEX(SETS(ISET), '=')
         CALL SHC_SET_OPTION(IH, SETS(ISET)(1:IEQ - 1),
     &      SETS(ISET)(IEQ + 1:LEN_TRIM(SETS(ISET))), ISTAT)
         IF (ISTAT .NE. SHC_OK) GOTO 900
    2 CONTINUE
C
C     Rolling radius of the centred wheelset (any pitch rate will do
C     for this call), then the pitch rate of pure rolling on it.
      CALL CONTCT(IH, ISIDE, 0.0D0, 0.0D0, 0.0D0, 0.0D0, V, -V/0.46D0,
     &            FLOAD, FX, FY, FZ, R0, NP, FYTOT, MZTOT, US, ISTAT)
      IF (ISTAT .NE. SHC_OK) GOTO 900
      RCEN = 0.5D0*(R0(1) + R0(2))
      PITCH = -V/(RCEN*1.0D-3)
C
      OPEN (UNIT=11, FILE=CSV, STATUS='UNKNOWN')
      IUCSV = 11
      WRITE (IUCSV, '(A)') 't_s,y_mm,yaw_mrad,vy_mm_s,yaw_rate_rad_s,'
     &   // 'fx_right_N,fy_right_N,fz_right_N,np_right,'
     &   // 'fx_left_N,fy_left_N,fz_left_N,np_left,fy_total_N,'
     &   // 'mz_total_Nm'
C
      Y = Y0MM*1.0D-3
      PSI = 0.0D0
      VY = 0.0D0
      R = 0.0D0
      T = 0.0D0
      NSTEP = NINT(TEND/DT)
      NCALL = 0
      NFAIL = 0
      YMAX = 0.0D0
      PMAX = 0.0D0
      YLATE = 0.0D0
      PLATE = 0.0D0
      TLATE = 0.8D0*TEND
      NCROSS = 0
      TFIRST = 0.0D0
      TCROSS = 0.0D0
      YPREV = Y
      DO 200 ISTEP = 0, NSTEP
C        Contact forces at the current state, both wheels.
         CALL CONTCT(IH, ISIDE, Y, PSI, VY, R, V, PITCH, FLOAD, FX, FY,
     &               FZ, R0, NP, FYTOT, MZTOT, US, ISTAT)
         NCALL = NCALL + 1
         IF (NCALL .LE. MAXT) TUS(NCALL) = US
         IF (ISTAT .NE. SHC_OK) THEN
            NFAIL = NFAIL + 1
            IF (NFAIL .LE. 5) THEN
               CALL SHC_ERRMSG(IH, MSG)
               WRITE (*, '(A,F10.5,A,I3,2A)') '# t =', T,
     &            ' s: status', ISTAT, ': ', MSG(1:LEN_TRIM(MSG))
               WRITE (*, '(A,4(1X,1PE24.16))') '#   y_ws (mm), yaw,'
     &            // ' v_lateral (mm/s), yaw rate:', Y*1.0D3, PSI,
     &            VY*1.0D3, R
            END IF
C           Keep the forces of the last step.
         END IF
         IF (MOD(ISTEP, NEVERY) .EQ. 0) WRITE (IUCSV, 300) T,
     &      Y*1.0D3, PSI*1.0D3, VY*1.0D3, R, FX(1), FY(1), FZ(1),
     &      NP(1), FX(2), FY(2), FZ(2), NP(2), FYTOT, MZTOT
         YMAX = MAX(YMAX, ABS(Y))
         PMAX = MAX(PMAX, ABS(PSI))
         IF (T .GE. TLATE) THEN
            YLATE = MAX(YLATE, ABS(Y))
            PLATE = MAX(PLATE, ABS(PSI))
C           Upward zero crossings of Y: the hunting frequency.
            IF (YPREV .LT. 0.0D0 .AND. Y .GE. 0.0D0) THEN
               IF (NCROSS .EQ. 0) TFIRST = T
               NCROSS = NCROSS + 1
               TCROSS = T
            END IF
         END IF
         YPREV = Y
         IF (ISTEP .EQ. NSTEP) GOTO 210
C        Semi-implicit Euler: velocities first, then positions.
         AY = (FYTOT - KY*Y - CY*VY)/MASS
         AR = (MZTOT - KPSI*PSI - CPSI*R)/INERT
         VY = VY + DT*AY
         R = R + DT*AR
         Y = Y + DT*VY
         PSI = PSI + DT*R
         T = (ISTEP + 1)*DT
  200 CONTINUE
  210 CLOSE (IUCSV)
C
      NKEPT = MIN(NCALL, MAXT)
      CALL SORTD(TUS, NKEPT)
      IF (MOD(NKEPT, 2) .EQ. 1) THEN
         MEDIAN = TUS((NKEPT + 1)/2)
      ELSE
         MEDIAN = 0.5D0*(TUS(NKEPT/2) + TUS(NKEPT/2 + 1))
      END IF
      WRITE (*, '(A)') '# single wheelset, legacy API'
      WRITE (*, '(2A)') 'wheel ', WHEEL(1:LEN_TRIM(WHEEL))
      WRITE (*, '(2A)') 'rail ', RAIL(1:LEN_TRIM(RAIL))
      DO 3 ISET = 1, NSET
         WRITE (*, '(2A)') 'set ', SETS(ISET)(1:LEN_TRIM(SETS(ISET)))
    3 CONTINUE
      WRITE (*, 400) 'speed_m_s', V
      WRITE (*, 400) 'duration_s', TEND
      WRITE (*, 400) 'dt_s', DT
      WRITE (*, 400) 'y0_mm', Y0MM
      WRITE (*, 400) 'ky_N_m', KY
      WRITE (*, 400) 'kpsi_Nm_rad', KPSI
      WRITE (*, 400) 'cy_Ns_m', CY
      WRITE (*, 400) 'cpsi_Nms_rad', CPSI
      WRITE (*, 400) 'centred_rolling_radius_mm', RCEN
      WRITE (*, 500) 'wheelset_calls', NCALL
      WRITE (*, 500) 'failed_calls', NFAIL
      WRITE (*, 400) 'median_us_per_wheelset_call', MEDIAN
      WRITE (*, 400) 'max_abs_y_mm', YMAX*1.0D3
      WRITE (*, 400) 'max_abs_yaw_mrad', PMAX*1.0D3
      WRITE (*, 400) 'last20pc_max_abs_y_mm', YLATE*1.0D3
      WRITE (*, 400) 'last20pc_max_abs_yaw_mrad', PLATE*1.0D3
      IF (NCROSS .GE. 2) THEN
         WRITE (*, 400) 'last20pc_frequency_Hz',
     &      (NCROSS - 1)/(TCROSS - TFIRST)
      END IF
      CALL SYSINF
      CALL SHC_DESTROY(IH, ISTAT)
      IF (NFAIL .GT. 0) STOP 2
C     The normal end falls through to END: a STOP would make gfortran
C     print a note on the floating-point flags the solver left raised
C     (underflow, harmless).
      GOTO 999
C
  900 CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, '(A,I3,2A)') 'error: status', ISTAT, ': ',
     &   MSG(1:LEN_TRIM(MSG))
      STOP 1
  300 FORMAT (F10.5, 4(',', 1PE15.7), 3(',', 1PE15.7), ',', I2,
     &        3(',', 1PE15.7), ',', I2, 2(',', 1PE15.7))
  400 FORMAT (A, 1X, 1PE15.7)
  500 FORMAT (A, 1X, I10)
  999 CONTINUE
      END
C
C     Both wheels: SHC_SOLVE_WS at the wheelset state (SI units in,
C     the library's mm, mm/s inside), each wheel under FLOAD. FYTOT, MZTOT:
C     the lateral force on the wheelset (N, towards the right rail's
C     field side) and the yaw moment of the contact forces about the
C     wheelset centre (N m; the patches' spin moments left out). Per
C     wheel (SHC_WS_WHEEL, its values summed over the loaded patches):
C     FX, FY, FZ in the track frame (the library gives a left wheel's
C     lateral values in its side frame, a mirror image: ISIDE turns
C     them), R0, NP. US: the time of the SHC_SOLVE_WS call (us).
C
      SUBROUTINE CONTCT(IH, ISIDE, Y, PSI, VY, R, V, PITCH, FLOAD,
     &                  FX, FY, FZ, R0, NP, FYTOT, MZTOT, US, ISTAT)
      IMPLICIT NONE
      INCLUDE 'shcontact.fi'
      INTEGER IH, ISIDE(2), NP(2), ISTAT
      DOUBLE PRECISION Y, PSI, VY, R, V, PITCH, FLOAD
      DOUBLE PRECISION FX(2), FY(2), FZ(2), R0(2), FYTOT, MZTOT, US
      DOUBLE PRECISION TOTALS(4), VALUES(SHC_KIN_SIZE)
      INTEGER IW
      INTEGER*8 IC0, IC1, IRATE
C
      CALL SYSTEM_CLOCK(IC0, IRATE)
      CALL SHC_SOLVE_WS(IH, Y*1.0D3, PSI, 0.0D0, V*1.0D3, VY*1.0D3,
     &                  0.0D0, 0.0D0, R, PITCH,
     &                  SHC_LOAD_VERTICAL_FORCE, FLOAD, FLOAD, TOTALS,
     &                  ISTAT)
      CALL SYSTEM_CLOCK(IC1)
      US = DBLE(IC1 - IC0)/DBLE(IRATE)*1.0D6
      IF (ISTAT .NE. SHC_OK) RETURN
      FYTOT = TOTALS(2)
      MZTOT = TOTALS(4)*1.0D-3
      DO 10 IW = 1, 2
         CALL SHC_WS_WHEEL(IH, ISIDE(IW), 0, VALUES, ISTAT)
         IF (ISTAT .NE. SHC_OK) RETURN
         FX(IW) = VALUES(SHC_SUM_FX)
         FY(IW) = ISIDE(IW)*VALUES(SHC_SUM_FY)
         FZ(IW) = VALUES(SHC_SUM_FZ)
         R0(IW) = VALUES(SHC_R0)
         NP(IW) = NINT(VALUES(SHC_N_PATCHES))
   10 CONTINUE
      END
C
C     Command-line options, with the defaults of doc/vehicle.md.
C
      SUBROUTINE GETOPT(TEND, DT, SPEED, Y0MM, KY, KPSI, CY, CPSI,
     &                  NEVERY, CSV, WHEEL, RAIL, SETS, NSET)
      IMPLICIT NONE
      DOUBLE PRECISION TEND, DT, SPEED, Y0MM, KY, KPSI, CY, CPSI
      INTEGER NEVERY, NSET
      CHARACTER*(*) CSV, WHEEL, RAIL, SETS(16)
      CHARACTER*256 KEY, ARG
      INTEGER I, N, IOS
C
      TEND = 20.0D0
      DT = 2.5D-4
      SPEED = 40.0D0
      Y0MM = 3.0D0
      KY = 0.5D6
      KPSI = 0.4D6
      CY = 0.0D0
      CPSI = 0.0D0
      NEVERY = 4
      CSV = 'wheelset.csv'
      WHEEL = 'builtin:S1002'
      RAIL = 'builtin:UIC60'
      NSET = 0
      N = COMMAND_ARGUMENT_COUNT()
      DO 5 I = 1, N
         CALL GET_COMMAND_ARGUMENT(I, KEY)
         IF (KEY .EQ. '--help' .OR. KEY .EQ. '-h') THEN
            WRITE (*, '(A)') 'usage: wheelset [--duration S] [--dt S]'
     &         // ' [--speed M/S] [--y0 MM] [--ky N/M] [--kpsi NM/RAD]'
            WRITE (*, '(A)') '                [--cy NS/M]'
     &         // ' [--cpsi NMS/RAD] [--every N] [--csv FILE]'
            WRITE (*, '(A)') '                [--wheel FILE]'
     &         // ' [--rail FILE] [--set KEY=VALUE]'
            WRITE (*, '(A)') 'A wheelset integrated in time through'
     &         // ' SHC_SOLVE_WS (doc/vehicle.md). Defaults:'
     &         // ' --duration 20 --dt 2.5e-4 --speed 40 --y0 3'
            WRITE (*, '(A)') '  --ky 0.5e6 --kpsi 0.4e6 --cy 0'
     &         // ' --cpsi 0 --every 4 --csv wheelset.csv'
            WRITE (*, '(A)') '  --wheel builtin:S1002 --rail'
     &         // ' builtin:UIC60 (profile files or builtin: names);'
     &         // ' --set: an SHC_SET_OPTION key and value (up to 16).'
            WRITE (*, '(A)') 'Exit status: 1 library error,'
     &         // ' 2 failed calls, 3 bad option.'
            STOP
         END IF
    5 CONTINUE
      I = 1
   10 IF (I + 1 .GT. N) GOTO 20
      CALL GET_COMMAND_ARGUMENT(I, KEY)
      CALL GET_COMMAND_ARGUMENT(I + 1, ARG)
      IOS = 0
      IF (KEY .EQ. '--duration') THEN
         READ (ARG, *, IOSTAT=IOS) TEND
      ELSE IF (KEY .EQ. '--dt') THEN
         READ (ARG, *, IOSTAT=IOS) DT
      ELSE IF (KEY .EQ. '--speed') THEN
         READ (ARG, *, IOSTAT=IOS) SPEED
      ELSE IF (KEY .EQ. '--y0') THEN
         READ (ARG, *, IOSTAT=IOS) Y0MM
      ELSE IF (KEY .EQ. '--ky') THEN
         READ (ARG, *, IOSTAT=IOS) KY
      ELSE IF (KEY .EQ. '--kpsi') THEN
         READ (ARG, *, IOSTAT=IOS) KPSI
      ELSE IF (KEY .EQ. '--cy') THEN
         READ (ARG, *, IOSTAT=IOS) CY
      ELSE IF (KEY .EQ. '--cpsi') THEN
         READ (ARG, *, IOSTAT=IOS) CPSI
      ELSE IF (KEY .EQ. '--every') THEN
         READ (ARG, *, IOSTAT=IOS) NEVERY
      ELSE IF (KEY .EQ. '--csv') THEN
         CSV = ARG
      ELSE IF (KEY .EQ. '--wheel') THEN
         WHEEL = ARG
      ELSE IF (KEY .EQ. '--rail') THEN
         RAIL = ARG
      ELSE IF (KEY .EQ. '--set') THEN
         IF (NSET .EQ. 16 .OR. INDEX(ARG, '=') .LT. 2) THEN
            IOS = 1
         ELSE
            NSET = NSET + 1
            SETS(NSET) = ARG
         END IF
      ELSE
         IOS = 1
      END IF
      IF (IOS .NE. 0) THEN
         WRITE (*, '(4A)') 'wheelset: bad option ',
     &      KEY(1:LEN_TRIM(KEY)), ' ', ARG(1:LEN_TRIM(ARG))
         STOP 3
      END IF
      I = I + 2
      GOTO 10
   20 IF (I .EQ. N) THEN
         CALL GET_COMMAND_ARGUMENT(I, KEY)
         WRITE (*, '(2A)') 'wheelset: option without value: ',
     &      KEY(1:LEN_TRIM(KEY))
         STOP 3
      END IF
      IF (TEND .LE. 0.0D0 .OR. DT .LE. 0.0D0 .OR. SPEED .LE. 0.0D0
     &    .OR. NEVERY .LT. 1) THEN
         WRITE (*, '(A)') 'wheelset: expected duration, dt, speed > 0'
     &      // ' and every >= 1'
         STOP 3
      END IF
      END
C
C     Shell sort of A(1:N), ascending.
C
      SUBROUTINE SORTD(A, N)
      IMPLICIT NONE
      INTEGER N
      DOUBLE PRECISION A(N)
      DOUBLE PRECISION X
      INTEGER GAP, I, J
      GAP = N/2
   10 IF (GAP .LT. 1) RETURN
      DO 30 I = GAP + 1, N
         X = A(I)
         J = I
   20    IF (J .GT. GAP) THEN
            IF (A(J - GAP) .GT. X) THEN
               A(J) = A(J - GAP)
               J = J - GAP
               GOTO 20
            END IF
         END IF
         A(J) = X
   30 CONTINUE
      GAP = GAP/2
      GOTO 10
      END
C
C     The machine the timing comes from: CPU model, load average.
C
      SUBROUTINE SYSINF
      IMPLICIT NONE
      CHARACTER*256 LINE
      INTEGER IOS, K
      OPEN (UNIT=12, FILE='/proc/cpuinfo', STATUS='OLD', IOSTAT=IOS)
      IF (IOS .EQ. 0) THEN
   10    READ (12, '(A)', IOSTAT=IOS) LINE
         IF (IOS .EQ. 0) THEN
            IF (LINE(1:10) .NE. 'model name') GOTO 10
            K = INDEX(LINE, ':')
            WRITE (*, '(2A)') 'cpu_model ',
     &         LINE(K + 2:LEN_TRIM(LINE))
         END IF
         CLOSE (12)
      END IF
      OPEN (UNIT=12, FILE='/proc/loadavg', STATUS='OLD', IOSTAT=IOS)
      IF (IOS .EQ. 0) THEN
         READ (12, '(A)', IOSTAT=IOS) LINE
         IF (IOS .EQ. 0) WRITE (*, '(2A)') 'load_average ',
     &      LINE(1:LEN_TRIM(LINE))
         CLOSE (12)
      END IF
      END
