C=======================================================================
C     RGBAR -- right-hand side of the nanobar sliding on a rough
C     surface (docs/models.md section C; thesis eqs 3.51-3.56 with errata
C     1-3): the smooth-surface equations plus the Coulomb friction
C     resultant over the 2A x 2B contact (RECTFV, fortran/rectfr.f)
C     at the iCOR implied by the rigid velocity, rotated to world axes.
C     This is the 'thesis' friction law: no stick handling. IPAR(1) = 1
C     selects the 'printed' law instead: the wrench of eqs 3.45-3.48
C     as printed (FRPRNT below; docs/rough.md), under the reading of
C     its slips in IPAR(2..5), each 1 = as printed, 0 = corrected:
C     IPAR(2) F1 (sign of fy'), IPAR(3) F3 (no sign(theta-dot)),
C     IPAR(4) F2 (squares in C4, lengths in nm; 0 = cubes: RECTFV's
C     Coulomb wrench with the sign slips), IPAR(5)
C     eq 3.50 (FY = FX' SIN - FY' COS; 0 = erratum 3's +).
C
C     State Y (N = 8): X, Y, THETA, VX, VY, OMEGA (world axes, SI),
C     WPUSH and WFRIC, the work done by the push and by friction [J].
C     RPAR(1) = M      mass [kg]
C     RPAR(2) = RI     moment of inertia about the CM [kg m^2]
C     RPAR(3) = F      push magnitude [N]
C     RPAR(4) = BETA   push direction in world axes [rad]
C     RPAR(5) = PBX    push point, body x' [m]
C     RPAR(6) = PBY    push point, body y' [m]
C     RPAR(7) = A      contact half-width (body x') [m]
C     RPAR(8) = B      contact half-length (body y') [m]
C     RPAR(9) = FMUN   mu times the normal load [N]
C     RPAR(10..12)     velocity direction (VX, VY, OMEGA) whose friction
C                      acts when the body is exactly at rest; all zero
C                      (the thesis law) gives no friction at rest
C                      (eq 3.40 has no direction there).
C     IERR: 0, or the status of RECTFV for bad friction input.
C     The arithmetic follows cxx/include/nanopush/models/rough_bar.hpp
C     operation for operation.
C=======================================================================
      SUBROUTINE RGBAR(N, T, Y, DYDT, RPAR, IPAR, IERR)
      INTEGER N, IPAR(*), IERR
      DOUBLE PRECISION T, Y(N), DYDT(N), RPAR(*)
      DOUBLE PRECISION C, S, PWX, PWY, FX, FY, TAU
      DOUBLE PRECISION VBX, VBY, FBX, FBY, FM, FWX, FWY, OM
      C = COS(Y(3))
      S = SIN(Y(3))
      PWX = RPAR(5)*C - RPAR(6)*S
      PWY = RPAR(5)*S + RPAR(6)*C
      FX = RPAR(3)*COS(RPAR(4))
      FY = RPAR(3)*SIN(RPAR(4))
      TAU = PWX*FY - PWY*FX
      IERR = 0
      IF (RPAR(9) .EQ. 0D0) THEN
         FWX = 0D0
         FWY = 0D0
         FM = 0D0
      ELSE
         IF (Y(4) .EQ. 0D0 .AND. Y(5) .EQ. 0D0 .AND. Y(6) .EQ. 0D0)
     &      THEN
            VBX = C*RPAR(10) + S*RPAR(11)
            VBY = -S*RPAR(10) + C*RPAR(11)
            OM = RPAR(12)
         ELSE
            VBX = C*Y(4) + S*Y(5)
            VBY = -S*Y(4) + C*Y(5)
            OM = Y(6)
         END IF
C        IPAR(2..5) are read only under the printed law (IPAR(1) = 1):
C        a caller of the thesis law may pass IPAR(1) alone.
         IF (IPAR(1) .EQ. 1) THEN
            IF (IPAR(4) .EQ. 0) THEN
C              Cubes in C4: the Coulomb wrench with the reading's sign
C              slips, by RECTFV's stable forms (the printed logarithms
C              with cubes cancel as (R/B)**3 where R is large).
               CALL RECTFV(RPAR(7), RPAR(8), RPAR(9), VBX, VBY, OM,
     &                     FBX, FBY, FM, IERR)
               IF (OM .NE. 0D0) THEN
                  IF (IPAR(2) .EQ. 1) FBY = -FBY
                  IF (IPAR(3) .EQ. 1 .AND. OM .LT. 0D0) FM = -FM
               END IF
            ELSE
               CALL FRPRNT(RPAR(7), RPAR(8), RPAR(9), VBX, VBY, OM,
     &                     IPAR(2), IPAR(3), FBX, FBY, FM)
            END IF
         ELSE
            CALL RECTFV(RPAR(7), RPAR(8), RPAR(9), VBX, VBY, OM,
     &                  FBX, FBY, FM, IERR)
         END IF
         IF (IERR .NE. 0) RETURN
         FWX = C*FBX - S*FBY
         FWY = S*FBX + C*FBY
         IF (IPAR(1) .EQ. 1) THEN
            IF (IPAR(5) .EQ. 1) FWY = S*FBX - C*FBY
         END IF
      END IF
      DYDT(1) = Y(4)
      DYDT(2) = Y(5)
      DYDT(3) = Y(6)
      DYDT(4) = (FX + FWX)/RPAR(1)
      DYDT(5) = (FY + FWY)/RPAR(1)
      DYDT(6) = (TAU + FM)/RPAR(2)
      DYDT(7) = FX*Y(4) + FY*Y(5) + TAU*Y(6)
      DYDT(8) = FWX*Y(4) + FWY*Y(5) + FM*Y(6)
      RETURN
      END
C=======================================================================
C     FRPRNT -- the 'printed' friction law: the wrench of eqs 3.45-3.48
C     as the thesis prints them, with squares in C4 (errata F2), each
C     sign slip (F1, F3 of docs/errata.md) as printed where its flag is
C     1 and corrected where 0: KF1 fy' with the printed sign (0: the
C     sign of 3.43), KF3 mf without sign(theta-dot) (0: times it), at
C     the iCOR implied by the body-axis velocity
C     (VX, VY, OM), SI in and out. C4 with squares is not dimensionally
C     consistent: the forms are evaluated with lengths in UL = 1 nm (the
C     unit of the thesis' captions; in metres the moment is ~1e6 times
C     too large and no run leaves t = 0). A term H**2 LN(U/V) whose
C     logarithm is undefined (an edge line of the contact) is taken as
C     its limit 0 (FRPTRM); at OM = 0 pure translation, F = -FMUN V/|V|,
C     FM = 0; zero at rest. Operation for operation as
C     nanopush::thesis_printed_friction_from_velocity (cxx/models/
C     friction.cpp), so both engines round identically.
C=======================================================================
      SUBROUTINE FRPRNT(A, B, FMUN, VX, VY, OM, KF1, KF3, FX, FY, FM)
      INTEGER KF1, KF3
      DOUBLE PRECISION A, B, FMUN, VX, VY, OM, FX, FY, FM
      DOUBLE PRECISION UL, AN, BN
      PARAMETER (UL = 1D-9)
      DOUBLE PRECISION V, SG, C, S, R, XC, YC, H1, H2, H3, H4
      DOUBLE PRECISION S12, S23, S34, S14, B45, B46, C3, C4, AB
      DOUBLE PRECISION FRHYPT, FRPTRM
      EXTERNAL FRHYPT, FRPTRM
      V = FRHYPT(VX, VY)
      IF (OM .EQ. 0D0) THEN
         IF (.NOT. (V .GT. 0D0)) THEN
            FX = 0D0
            FY = 0D0
         ELSE
            FX = -FMUN*(VX/V)
            FY = -FMUN*(VY/V)
         END IF
         FM = 0D0
         RETURN
      END IF
      IF (OM .GT. 0D0) THEN
         SG = 1D0
      ELSE
         SG = -1D0
      END IF
      C = 1D0
      S = 0D0
      IF (V .GT. 0D0) THEN
         C = SG*VY/V
         S = -SG*VX/V
      END IF
      AN = A/UL
      BN = B/UL
      R = V/ABS(OM)/UL
      XC = R*C
      YC = R*S
      H1 = YC - BN
      H2 = XC + AN
      H3 = YC + BN
      H4 = XC - AN
      S12 = SQRT(H1*H1 + H2*H2)
      S23 = SQRT(H2*H2 + H3*H3)
      S34 = SQRT(H3*H3 + H4*H4)
      S14 = SQRT(H1*H1 + H4*H4)
      B45 = H2*(S23 - S12) + H4*(S14 - S34)
     &      - FRPTRM(H1, S14 - H4, S12 - H2)
     &      + FRPTRM(H3, S34 - H4, S23 - H2)
      B46 = H1*(S14 - S12) + H3*(S23 - S34)
     &      + FRPTRM(H2, S23 + H3, S12 + H1)
     &      - FRPTRM(H4, S34 + H3, S14 + H1)
      C3 = -H1*H2*S12 + H2*H3*S23 - H3*H4*S34 + H1*H4*S14
      C4 = FRPTRM(H1, S12 - H2, S14 - H4)
     &     + FRPTRM(H2, S23 + H3, S12 + H1)
     &     + FRPTRM(H3, S34 - H4, S23 - H2)
     &     + FRPTRM(H4, S14 + H1, S34 + H3)
      AB = AN*BN
      FX = FMUN*SG*B45/(8D0*AB)
      FY = FMUN*SG*B46/(8D0*AB)
      IF (KF1 .EQ. 0) FY = -FY
      FM = UL*FMUN*(XC*B46/2D0 + YC*B45/2D0 - C3/3D0 - C4/6D0)
     &     /(4D0*AB)
      IF (KF3 .EQ. 0) FM = SG*FM
      RETURN
      END

C     FRPTRM -- H**2 LN(U/V), or 0 where the logarithm is undefined
C     (only on an edge line, where H -> 0 and the term's limit is 0).
      DOUBLE PRECISION FUNCTION FRPTRM(H, U, V)
      DOUBLE PRECISION H, U, V
      IF (H .EQ. 0D0 .OR. .NOT. (U .GT. 0D0)
     &    .OR. .NOT. (V .GT. 0D0)) THEN
         FRPTRM = 0D0
      ELSE
         FRPTRM = H*H*LOG(U/V)
      END IF
      RETURN
      END

