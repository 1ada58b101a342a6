C=======================================================================
C     ROLLING -- rolling of nanotubes (docs/models.md section E; thesis
C     section 3.2-3.3, eqs 3.16, 3.19-3.21 and section 3.3.1), the
C     FORTRAN 77 counterpart of cxx/models/rolling.cpp and of the rod and
C     line-contact parts of cxx/models/surface_forces.cpp.
C
C     SI units. IERR = 0 success, 1 invalid argument, 2 load below the
C     pull-off load, 3 no convergence. No routine stops the program.
C=======================================================================
C
C     RLFS -- static friction for pure rolling, eq 3.16:
C             FS = (F/3) (1 - 2 H / R)   [N]
C     F push [N] (>= 0), H push height above the axis [m] (|H| <= R),
C     R tube radius [m] (> 0).
      SUBROUTINE RLFS(F, H, R, FS, IERR)
      DOUBLE PRECISION F, H, R, FS
      INTEGER IERR
      FS = 0.0D0
      IERR = 1
      IF (.NOT. (R .GT. 0.0D0)) RETURN
      IF (.NOT. (F .GE. 0.0D0)) RETURN
      IF (.NOT. (ABS(H) .LE. R)) RETURN
      FS = F/3.0D0*(1.0D0 - 2.0D0*H/R)
      IERR = 0
      RETURN
      END
C
C     RLRES -- rolling resistance FS = W K / R [N] (section 3.3.1).
C     W total load m g + F_vdw + F_adhesion [N], AK contact half-width
C     [m], R tube radius [m].
      SUBROUTINE RLRES(W, AK, R, FS, IERR)
      DOUBLE PRECISION W, AK, R, FS
      INTEGER IERR
      FS = 0.0D0
      IERR = 1
      IF (.NOT. (R .GT. 0.0D0)) RETURN
      IF (.NOT. (W .GE. 0.0D0)) RETURN
      IF (.NOT. (AK .GE. 0.0D0)) RETURN
      FS = W*AK/R
      IERR = 0
      RETURN
      END
C
C     RLMIN -- minimum push that rolls the tube, F = (1 + AMARG) W K / R
C     (the thesis takes AMARG = 0.01: F ~ fs + 1% fs).
      SUBROUTINE RLMIN(W, AK, R, AMARG, F, IERR)
      DOUBLE PRECISION W, AK, R, AMARG, F, FS
      INTEGER IERR
      F = 0.0D0
      IF (.NOT. (AMARG .GE. 0.0D0)) THEN
         IERR = 1
         RETURN
      END IF
      CALL RLRES(W, AK, R, FS, IERR)
      IF (IERR .NE. 0) RETURN
      F = (1.0D0 + AMARG)*FS
      RETURN
      END
C
C     RLDEC -- rolling versus sliding for one push.
C     In:  F push [N], H height [m], R radius [m], AMU friction coeff.,
C          ANS sliding load m g + F_vdw [N], WR rolling load
C          m g + F_vdw + F_adhesion [N], AK contact half-width [m].
C     Out: MODE 0 stuck, 1 rolling, 2 rolling with slip, 3 sliding;
C          FROLL = WR AK / R, FSLID = AMU ANS, FSREQ = eq 3.16 [N].
      SUBROUTINE RLDEC(F, H, R, AMU, ANS, WR, AK, MODE, FROLL, FSLID,
     &                 FSREQ, IERR)
      DOUBLE PRECISION F, H, R, AMU, ANS, WR, AK, FROLL, FSLID, FSREQ
      INTEGER MODE, IERR
      MODE = 0
      FROLL = 0.0D0
      FSLID = 0.0D0
      CALL RLFS(F, H, R, FSREQ, IERR)
      IF (IERR .NE. 0) RETURN
      CALL RLRES(WR, AK, R, FROLL, IERR)
      IF (IERR .NE. 0) RETURN
      IERR = 1
      IF (.NOT. (AMU .GE. 0.0D0)) RETURN
      IF (.NOT. (ANS .GE. 0.0D0)) RETURN
      IERR = 0
      FSLID = AMU*ANS
      IF (F .LT. FROLL .AND. F .LT. FSLID) THEN
         MODE = 0
      ELSE IF (FROLL .LE. FSLID) THEN
         IF (ABS(FSREQ) .LE. FSLID) THEN
            MODE = 1
         ELSE
            MODE = 2
         END IF
      ELSE
         MODE = 3
      END IF
      RETURN
      END
C
C     RLVDW -- Parsegian rod-plane van der Waals force (thesis 4.2.3):
C             FV = AL AH SQRT(D) / (16 Z0**2.5)   [N]
C     AH Hamaker constant [J] (>= 0), AL rod length [m], D diameter
C     [m], Z0 rod-plane gap [m].
      SUBROUTINE RLVDW(AH, AL, D, Z0, FV, IERR)
      DOUBLE PRECISION AH, AL, D, Z0, FV
      INTEGER IERR
      FV = 0.0D0
      IERR = 1
      IF (.NOT. (AH .GE. 0.0D0)) RETURN
      IF (.NOT. (AL .GT. 0.0D0)) RETURN
      IF (.NOT. (D .GT. 0.0D0)) RETURN
      IF (.NOT. (Z0 .GT. 0.0D0)) RETURN
      FV = AL*AH*SQRT(D)/(16.0D0*Z0**2.5D0)
      IERR = 0
      RETURN
      END
C
C     RLJKRL -- JKR line contact of a cylinder on a plane (thesis 3.3,
C     its ref [72]): half-width B [m] solving, for the load per length
C     P [N/m] (compressive positive),
C             P = PI ES B**2 / (4 R) - SQRT(2 PI ES W B)
C     on the stable branch. R radius [m], ES effective modulus [Pa],
C     W work of adhesion [J/m^2] (= 2 gamma for like materials).
C     With S = SQRT(B): G(S) = AL S**4 - BE S - P is convex; its
C     minimum is at S* = (BE/(4 AL))**(1/3); Newton safeguarded by
C     bisection on [S*, SHI].
      SUBROUTINE RLJKRL(R, ES, W, P, B, IERR)
      DOUBLE PRECISION R, ES, W, P, B
      INTEGER IERR
      DOUBLE PRECISION PI, AL, BE, SMIN, SLO, SHI, S, GS, DG, SN
      INTEGER IT
      PARAMETER (PI = 3.14159265358979323846D0)
      B = 0.0D0
      IERR = 1
      IF (.NOT. (R .GT. 0.0D0)) RETURN
      IF (.NOT. (ES .GT. 0.0D0)) RETURN
      IF (.NOT. (W .GE. 0.0D0)) RETURN
      IF (.NOT. (ABS(P) .LE. 1.0D300)) RETURN
      AL = PI*ES/(4.0D0*R)
      BE = SQRT(2.0D0*PI*ES*W)
      SMIN = (BE/(4.0D0*AL))**(1.0D0/3.0D0)
      IF (AL*SMIN**4 - BE*SMIN - P .GT. 0.0D0) THEN
         IERR = 2
         RETURN
      END IF
      SLO = SMIN
      SHI = MAX(2.0D0*SMIN, SQRT(SQRT(MAX(P, 0.0D0)/AL))
     &          + (BE/AL)**(1.0D0/3.0D0) + 1.0D-300)
   10 IF (AL*SHI**4 - BE*SHI - P .LT. 0.0D0) THEN
         SHI = 2.0D0*SHI
         GO TO 10
      END IF
      S = SHI
      DO 20 IT = 1, 200
         GS = AL*S**4 - BE*S - P
         IF (GS .GT. 0.0D0) THEN
            SHI = S
         ELSE
            SLO = S
         END IF
         DG = 4.0D0*AL*S**3 - BE
         SN = S - GS/DG
         IF (.NOT. (SN .GT. SLO .AND. SN .LT. SHI)) THEN
            SN = 0.5D0*(SLO + SHI)
         END IF
         IF (ABS(SN - S) .LE. 1.0D-16*S) THEN
            S = SN
            B = S*S
            IERR = 0
            RETURN
         END IF
         S = SN
   20 CONTINUE
      B = S*S
      IERR = 0
      RETURN
      END
