C     shcontact from fixed-form Fortran 77: the headline case through the
C     legacy entry points shc_* (doc/api.md), then three bad calls that
C     must come back with a status and a message.
C
C     S1002 wheel on a UIC60 rail canted 1:40 by the track, R0 = 460 mm,
C     G = 82670 MPa, nu = 0.27, mu = 0.3, normal force 64.7 kN, creepages
C     0.58e-3, 0.061e-3, spin 2.74e-4 1/mm, FASTSIM_SH (the defaults).
C
C     Build:  gfortran headline.f $(pkg-config --cflags --libs shcontact)
C
      PROGRAM HEADLN
      IMPLICIT NONE
      DOUBLE PRECISION TY, ROLL, FN, CKSI, CETA, CPHI
C     Lateral wheelset shift Y_WS (mm): the app's default (physics.md
C     decision 13).
      PARAMETER (TY = 4.733D0, ROLL = 0.0D0, FN = 64.7D3)
      PARAMETER (CKSI = 0.58D-3, CETA = 0.061D-3, CPHI = 2.74D-4)
C     Load mode 1: normal force on the deepest patch.
      INTEGER IFORCE
      PARAMETER (IFORCE = 1)
      DOUBLE PRECISION VALUES(25), G, POISS, FRIC, CNAN
      INTEGER IH, ISTAT
      CHARACTER*200 MSG
      CHARACTER*3 STRNAN
      DATA STRNAN /'NaN'/
C
      CALL SHC_CREATE(IH, 'builtin:S1002', 'builtin:UIC60', 1, ISTAT)
      IF (ISTAT .NE. 0) GOTO 900
      G = 82670.0D0
      POISS = 0.27D0
      FRIC = 0.3D0
      CALL SHC_SET_MATERIAL(IH, G, POISS, FRIC, ISTAT)
      IF (ISTAT .NE. 0) GOTO 900
      CALL SHC_SET_OPTION(IH, 'tangential%method', 'fastsim-sh', ISTAT)
      IF (ISTAT .NE. 0) GOTO 900
      CALL SHC_SOLVE(IH, TY, ROLL, IFORCE, FN, CKSI, CETA, CPHI,
     &               VALUES, ISTAT)
      IF (ISTAT .NE. 0) GOTO 900
      WRITE (*, '(A)') '# headline case, legacy Fortran 77 interface'
      WRITE (*, 100) 't_y', TY
      WRITE (*, 100) 'fx', VALUES(1)
      WRITE (*, 100) 'fy', VALUES(2)
      WRITE (*, 100) 'mz', VALUES(3)
      WRITE (*, 100) 'fn', VALUES(4)
      WRITE (*, 100) 'fx_norm', VALUES(5)
      WRITE (*, 100) 'fy_norm', VALUES(6)
      WRITE (*, 100) 'gamma0', VALUES(12)
      WRITE (*, 100) 'n_patches', VALUES(18)
      WRITE (*, 100) 'sum_fz', VALUES(23)
C
C     Bad calls: an invalid handle, a negative load, a NaN creepage.
      CALL SHC_SOLVE(IH + 999, TY, ROLL, IFORCE, FN, CKSI, CETA, CPHI,
     &               VALUES, ISTAT)
      CALL SHC_ERRMSG(IH + 999, MSG)
      WRITE (*, 200) 'status_invalid_handle', ISTAT, MSG
      CALL SHC_SOLVE(IH, TY, ROLL, IFORCE, -FN, CKSI, CETA, CPHI,
     &               VALUES, ISTAT)
      CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, 200) 'status_negative_load', ISTAT, MSG
      READ (STRNAN, *) CNAN
      CALL SHC_SOLVE(IH, TY, ROLL, IFORCE, FN, CNAN, CETA, CPHI,
     &               VALUES, ISTAT)
      CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, 200) 'status_nan_creepage', ISTAT, MSG
C
      CALL SHC_DESTROY(IH, ISTAT)
      STOP
C
  900 CALL SHC_ERRMSG(IH, MSG)
      WRITE (*, '(A,I3,2A)') 'error: status', ISTAT, ': ', MSG
      STOP 1
  100 FORMAT (A, 1X, 1PE25.17)
  200 FORMAT (A, 1X, I3, 1X, A)
      END
