C=======================================================================
C     RECTFR -- Coulomb friction wrench of a 2A x 2B rectangular contact
C     with uniform pressure (docs/models.md section B; thesis eqs 3.27-3.50
C     and Appendix B, with the corrections of docs/errata.md).
C     Same algorithm as cxx/include/nanopush/models/friction.hpp:
C       RHO = R/MAX(A,B) below 3: exact corner closed form (asinh form);
C       3 <= RHO < 1D9: point-symmetrised N x N Gauss-Legendre form
C                       of the far-field series (no cancellation),
C                       N = 12, 8, 6, 4 from RHO = 3, 8, 24, 512;
C       RHO >= 1D9:     asymptotic form (translation + 1/R moment).
C
C     Body axes at the CM; x' across the width (half-width A), y' along
C     the length (half-length B). The iCOR is at
C     -R (COS ALPHA, SIN ALPHA).
C     FMUN   mu N, total friction force scale [N]
C     ISENSE +1 counter-clockwise rotation (omega > 0), -1 clockwise
C     FX, FY friction force in body axes [N]; FM moment about CM [N m]
C     IERR   0 ok; 1 A, 2 B not finite and > 0; 3 aspect ratio
C            MIN/MAX below 1D-12; 4 FMUN not finite and >= 0; 5 R not
C            finite and >= 0; 6 ALPHA not finite; 7 ISENSE not +-1.
C     On error FX = FY = FM = 0. The routine never stops.
C=======================================================================
      SUBROUTINE RECTFR(A, B, FMUN, R, ALPHA, ISENSE, FX, FY, FM, IERR)
      INTEGER ISENSE, IERR
      DOUBLE PRECISION A, B, FMUN, R, ALPHA, FX, FY, FM
      DOUBLE PRECISION SL, XI, YI, XK, SG
      LOGICAL FRBAD
      EXTERNAL FRBAD, FRMEAN
      FX = 0.0D0
      FY = 0.0D0
      FM = 0.0D0
      CALL FRCHKR(A, B, FMUN, IERR)
      IF (IERR .NE. 0) RETURN
      IF (FRBAD(R) .OR. .NOT. (R .GE. 0.0D0)) THEN
         IERR = 5
         RETURN
      END IF
      IF (FRBAD(ALPHA)) THEN
         IERR = 6
         RETURN
      END IF
      IF (ISENSE .NE. 1 .AND. ISENSE .NE. -1) THEN
         IERR = 7
         RETURN
      END IF
      SL = MAX(A, B)
      CALL FRMEAN(A/SL, B/SL, R/SL, COS(ALPHA), SIN(ALPHA), XI, YI, XK)
      SG = DBLE(ISENSE)
      FX = FMUN*SG*YI
      FY = -(FMUN*SG*XI)
      FM = -(FMUN*SG*XK*SL)
      RETURN
      END
C=======================================================================
C     RECTFV -- the same wrench from the body-axis rigid velocity: CM
C     velocity (VX, VY) [m/s] and angular rate OMEGA [rad/s]. The iCOR
C     is (-VY, VX)/OMEGA; OMEGA = 0 gives pure translation
C     F = -FMUN V/|V|, FM = 0; zero wrench at rest.
C     IERR as RECTFR, plus 8: VX, VY or OMEGA not finite.
C=======================================================================
      SUBROUTINE RECTFV(A, B, FMUN, VX, VY, OMEGA, FX, FY, FM, IERR)
      INTEGER IERR
      DOUBLE PRECISION A, B, FMUN, VX, VY, OMEGA, FX, FY, FM
      DOUBLE PRECISION SL, V, SG, C, S, RHO, XI, YI, XK
      DOUBLE PRECISION FRHYPT
      LOGICAL FRBAD
      EXTERNAL FRBAD, FRMEAN, FRHYPT
      FX = 0.0D0
      FY = 0.0D0
      FM = 0.0D0
      CALL FRCHKR(A, B, FMUN, IERR)
      IF (IERR .NE. 0) RETURN
      IF (FRBAD(VX) .OR. FRBAD(VY) .OR. FRBAD(OMEGA)) THEN
         IERR = 8
         RETURN
      END IF
      V = FRHYPT(VX, VY)
      IF (OMEGA .EQ. 0.0D0) THEN
         IF (V .GT. 0.0D0) THEN
            FX = -(FMUN*(VX/V))
            FY = -(FMUN*(VY/V))
         END IF
         RETURN
      END IF
      SL = MAX(A, B)
      SG = 1.0D0
      IF (OMEGA .LT. 0.0D0) SG = -1.0D0
      C = 1.0D0
      S = 0.0D0
      IF (V .GT. 0.0D0) THEN
         C = SG*VY/V
         S = -SG*VX/V
      END IF
      RHO = (V/ABS(OMEGA))/SL
      CALL FRMEAN(A/SL, B/SL, RHO, C, S, XI, YI, XK)
      FX = FMUN*SG*YI
      FY = -(FMUN*SG*XI)
      FM = -(FMUN*SG*XK*SL)
      RETURN
      END
C=======================================================================
C     FRCHKR -- common input checks of RECTFR and RECTFV (IERR 1-4).
C=======================================================================
      SUBROUTINE FRCHKR(A, B, FMUN, IERR)
      INTEGER IERR
      DOUBLE PRECISION A, B, FMUN
      LOGICAL FRBAD
      EXTERNAL FRBAD
      IERR = 0
      IF (FRBAD(A) .OR. .NOT. (A .GT. 0.0D0)) THEN
         IERR = 1
      ELSE IF (FRBAD(B) .OR. .NOT. (B .GT. 0.0D0)) THEN
         IERR = 2
      ELSE IF (.NOT. (MIN(A, B)/MAX(A, B) .GE. 1.0D-12)) THEN
         IERR = 3
      ELSE IF (FRBAD(FMUN) .OR. .NOT. (FMUN .GE. 0.0D0)) THEN
         IERR = 4
      END IF
      RETURN
      END
C=======================================================================
C     FRBAD -- .TRUE. when X is NaN or infinite.
C=======================================================================
      LOGICAL FUNCTION FRBAD(X)
      DOUBLE PRECISION X
      FRBAD = (X .NE. X) .OR. (ABS(X) .GT. 1.7976931348623157D308)
      RETURN
      END
C=======================================================================
C     FRHYPT -- SQRT(X**2 + Y**2) without overflow or underflow.
C=======================================================================
      DOUBLE PRECISION FUNCTION FRHYPT(X, Y)
      DOUBLE PRECISION X, Y, AX, AY, T
      AX = ABS(X)
      AY = ABS(Y)
      IF (AX .LT. AY) THEN
         T = AX
         AX = AY
         AY = T
      END IF
      IF (AX .EQ. 0.0D0) THEN
         FRHYPT = 0.0D0
      ELSE
         T = AY/AX
         FRHYPT = AX*SQRT(1.0D0 + T*T)
      END IF
      RETURN
      END
C=======================================================================
C     FRLG1P -- LOG(1 + X) accurate for small X (Kahan's device:
C     U = 1 + X rounded, then LOG(U) * X / (U - 1)).
C=======================================================================
      DOUBLE PRECISION FUNCTION FRLG1P(X)
      DOUBLE PRECISION X, U
      U = 1.0D0 + X
      IF (U .EQ. 1.0D0) THEN
         FRLG1P = X
      ELSE
         FRLG1P = LOG(U)*(X/(U - 1.0D0))
      END IF
      RETURN
      END
C=======================================================================
C     FRASNH -- inverse hyperbolic sine, accurate over the whole range
C     (ASINH is not a FORTRAN 77 intrinsic).
C=======================================================================
      DOUBLE PRECISION FUNCTION FRASNH(Q)
      DOUBLE PRECISION Q, AQ, T
      DOUBLE PRECISION FRLG1P
      EXTERNAL FRLG1P
      AQ = ABS(Q)
      IF (AQ .GT. 1.0D8) THEN
         T = LOG(2.0D0*AQ) + 0.25D0/(AQ*AQ)
      ELSE IF (AQ .GE. 0.5D0) THEN
         T = LOG(AQ + SQRT(AQ*AQ + 1.0D0))
      ELSE
         T = FRLG1P(AQ + AQ*AQ/(1.0D0 + SQRT(1.0D0 + AQ*AQ)))
      END IF
      FRASNH = SIGN(T, Q)
      RETURN
      END
C=======================================================================
C     FRSQAS -- U**2 * ASINH(V/|U|), continuous with value 0 at U = 0.
C=======================================================================
      DOUBLE PRECISION FUNCTION FRSQAS(U, V)
      DOUBLE PRECISION U, V, AU, Q
      DOUBLE PRECISION FRASNH
      EXTERNAL FRASNH
      AU = ABS(U)
      IF (AU .EQ. 0.0D0) THEN
         FRSQAS = 0.0D0
         RETURN
      END IF
      Q = V/AU
      IF (ABS(Q) .LT. 1.0D150) THEN
         FRSQAS = U*U*FRASNH(Q)
      ELSE
         FRSQAS = SIGN(U*U*(LOG(2.0D0*ABS(V)) - LOG(AU)), V)
      END IF
      RETURN
      END
C=======================================================================
C     FRMEAN -- the three contact integrals as means over the rectangle,
C     lengths in units of MAX(A,B):  XI = <X/r>, YI = <Y/r>,
C     XK = <(x X + y Y)/r>; (C, S) = (COS, SIN) ALPHA, RHO = R/MAX(A,B).
C=======================================================================
      SUBROUTINE FRMEAN(A, B, RHO, C, S, XI, YI, XK)
      DOUBLE PRECISION A, B, RHO, C, S, XI, YI, XK, XC, YC
      DOUBLE PRECISION G4X(2), G4W(2), G6X(3), G6W(3), G8X(4), G8W(4)
      DOUBLE PRECISION G12X(6), G12W(6)
      EXTERNAL FRCLSD, FRFAR
      DATA G4X /0.3399810435848562648026658D0,
     &          0.8611363115940525752239465D0/
      DATA G4W /0.6521451548625461426269361D0,
     &          0.3478548451374538573730639D0/
      DATA G6X /0.2386191860831969086305017D0,
     &          0.6612093864662645136613996D0,
     &          0.9324695142031520278123016D0/
      DATA G6W /0.4679139345726910473898703D0,
     &          0.3607615730481386075698335D0,
     &          0.1713244923791703450402961D0/
      DATA G8X /0.1834346424956498049394761D0,
     &          0.525532409916328985817739D0,
     &          0.7966664774136267395915539D0,
     &          0.9602898564975362316835609D0/
      DATA G8W /0.3626837833783619829651504D0,
     &          0.3137066458778872873379622D0,
     &          0.222381034453374470544356D0,
     &          0.1012285362903762591525314D0/
      DATA G12X /0.1252334085114689154724414D0,
     &           0.3678314989981801937526915D0,
     &           0.5873179542866174472967024D0,
     &           0.7699026741943046870368938D0,
     &           0.9041172563704748566784659D0,
     &           0.9815606342467192506905491D0/
      DATA G12W /0.2491470458134027850005624D0,
     &           0.2334925365383548087608499D0,
     &           0.2031674267230659217490645D0,
     &           0.1600783285433462263346525D0,
     &           0.1069393259953184309602547D0,
     &           0.04717533638651182719461596D0/
      IF (.NOT. (RHO .LT. 1.0D9)) THEN
         XI = C
         YI = S
         XK = (A*A*S*S + B*B*C*C)/(3.0D0*RHO)
         RETURN
      END IF
      XC = RHO*C
      YC = RHO*S
      IF (RHO .LT. 3.0D0) THEN
         CALL FRCLSD(A, B, XC, YC, XI, YI, XK)
      ELSE IF (RHO .LT. 8.0D0) THEN
         CALL FRFAR(A, B, XC, YC, 6, G12X, G12W, XI, YI, XK)
      ELSE IF (RHO .LT. 24.0D0) THEN
         CALL FRFAR(A, B, XC, YC, 4, G8X, G8W, XI, YI, XK)
      ELSE IF (RHO .LT. 512.0D0) THEN
         CALL FRFAR(A, B, XC, YC, 3, G6X, G6W, XI, YI, XK)
      ELSE
         CALL FRFAR(A, B, XC, YC, 2, G4X, G4W, XI, YI, XK)
      END IF
      RETURN
      END
C=======================================================================
C     FRCLSD -- corner-term closed form. Antiderivatives (corner terms)
C       FX = (Y r + X**2 asinh(Y/|X|))/2
C       FY = (X r + Y**2 asinh(X/|Y|))/2
C       FR = X Y r/3 + (X**3 asinh(Y/|X|) + Y**3 asinh(X/|Y|))/6
C     combined as (F(x1,.) differenced across y) - (F(x0,.) differenced
C     across y), the y difference taken across the thinner side
C     (x and y transposed when A < B) by FRYDIF, without cancellation.
C=======================================================================
      SUBROUTINE FRCLSD(A, B, XC, YC, XI, YI, XK)
      DOUBLE PRECISION A, B, XC, YC, XI, YI, XK
      DOUBLE PRECISION TA, TB, TXC, TYC, G1X, G1Y, G1R, G0X, G0Y, G0R
      DOUBLE PRECISION AREA, TIX, TIY
      LOGICAL TRANSP
      EXTERNAL FRYDIF
      TRANSP = A .LT. B
      IF (TRANSP) THEN
         TA = B
         TB = A
         TXC = YC
         TYC = XC
      ELSE
         TA = A
         TB = B
         TXC = XC
         TYC = YC
      END IF
      CALL FRYDIF(TXC + TA, TYC, TB, G1X, G1Y, G1R)
      CALL FRYDIF(TXC - TA, TYC, TB, G0X, G0Y, G0R)
      AREA = 4.0D0*A*B
      TIX = (G1X - G0X)/AREA
      TIY = (G1Y - G0Y)/AREA
      XK = (G1R - G0R)/AREA - TXC*TIX - TYC*TIY
      IF (TRANSP) THEN
         XI = TIY
         YI = TIX
      ELSE
         XI = TIX
         YI = TIY
      END IF
      RETURN
      END
C=======================================================================
C     FRYDIF -- differences across y of the corner antiderivatives at
C     fixed X, y0 = YC - B, y1 = YC + B (GX, GY, GR for FX, FY, FR),
C     without cancellation when B << |YC|: y1 - y0 = 2B, y1 + y0 = 2YC,
C     r1 - r0 = 4 B YC/(r0 + r1), and for y0, y1 of one sign
C       asinh(y1/|X|) - asinh(y0/|X|) = asinh(4 B YC/(y1 r0 + y0 r1))
C       asinh(X/|y1|) - asinh(X/|y0|)
C                          = asinh(-4 B YC X/(y0 y1 (r0 + r1)))
C=======================================================================
      SUBROUTINE FRYDIF(X, YC, B, GX, GY, GR)
      DOUBLE PRECISION X, YC, B, GX, GY, GR
      DOUBLE PRECISION Y0, Y1, R0, R1, RS, DR, DYR, X2DA, DY2B, DY3B
      DOUBLE PRECISION AX, YMIN, Y01, DA, B0, B1, DB
      DOUBLE PRECISION FRASNH, FRSQAS
      EXTERNAL FRASNH, FRSQAS
      Y0 = YC - B
      Y1 = YC + B
      R0 = SQRT(X*X + Y0*Y0)
      R1 = SQRT(X*X + Y1*Y1)
      RS = R0 + R1
      DR = 0.0D0
      IF (RS .GT. 0.0D0) DR = 4.0D0*B*YC/RS
      DYR = B*RS + YC*DR
      AX = ABS(X)
      YMIN = MIN(ABS(Y0), ABS(Y1))
      IF ((Y0 .GT. 0.0D0 .OR. Y1 .LT. 0.0D0) .AND.
     &    YMIN .GE. 1.0D-150*AX) THEN
         Y01 = Y0*Y1
         DA = FRASNH(4.0D0*B*YC/(Y1*R0 + Y0*R1))
         B0 = FRASNH(X/ABS(Y0))
         B1 = FRASNH(X/ABS(Y1))
         DB = FRASNH(-4.0D0*B*YC*X/(Y01*RS))
         X2DA = X*X*DA
         DY2B = 2.0D0*B*YC*(B1 + B0) + 0.5D0*(Y1*Y1 + Y0*Y0)*DB
         DY3B = B*(Y1*Y1 + Y1*Y0 + Y0*Y0)*(B1 + B0)
     &        + 0.5D0*(Y1*Y1*Y1 + Y0*Y0*Y0)*DB
      ELSE
         X2DA = FRSQAS(X, Y1) - FRSQAS(X, Y0)
         DY2B = FRSQAS(Y1, X) - FRSQAS(Y0, X)
         DY3B = Y1*FRSQAS(Y1, X) - Y0*FRSQAS(Y0, X)
      END IF
      GX = 0.5D0*(DYR + X2DA)
      GY = 0.5D0*(X*DR + DY2B)
      GR = X*DYR/3.0D0 + (X*X2DA + DY3B)/6.0D0
      RETURN
      END
C=======================================================================
C     FRFAR -- far field: 2NH x 2NH Gauss-Legendre rule (positive
C     nodes GX, weights GW) applied to the point-symmetrised integrands
C     at (x, y) and (-x, -y). With d = x XC + y YC, e = x YC - y XC,
C     rho**2 = x**2 + y**2, R = |XC,YC|:
C       h(+) + h(-) = e**2/R**2 (1/r+ + 1/r-)
C         + 8 d**2 e**2/(R**2 r+ r- (r+ + r-)(r+ r- + R**2 - rho**2))
C=======================================================================
      SUBROUTINE FRFAR(A, B, XC, YC, NH, GX, GW, XI, YI, XK)
      INTEGER NH
      DOUBLE PRECISION A, B, XC, YC, GX(NH), GW(NH), XI, YI, XK
      DOUBLE PRECISION R, RINV2, SX, SY, SK, X, Y, WY, TX, TY, TK
      DOUBLE PRECISION XP, YP, XM, YM, RP, RM, PI, PM, D, E, RHO, RR
      DOUBLE PRECISION EE
      INTEGER I, J
      R = SQRT(XC*XC + YC*YC)
      RINV2 = 1.0D0/(R*R)
      SX = 0.0D0
      SY = 0.0D0
      SK = 0.0D0
      DO 20 I = 1, NH
         X = A*GX(I)
         TX = 0.0D0
         TY = 0.0D0
         TK = 0.0D0
         DO 10 J = 1, 2*NH
            IF (J .LE. NH) THEN
               Y = B*GX(J)
               WY = GW(J)
            ELSE
               Y = -(B*GX(J-NH))
               WY = GW(J-NH)
            END IF
            XP = XC + X
            YP = YC + Y
            XM = XC - X
            YM = YC - Y
            RP = SQRT(XP*XP + YP*YP)
            RM = SQRT(XM*XM + YM*YM)
            PI = 1.0D0/RP
            PM = 1.0D0/RM
            D = X*XC + Y*YC
            E = X*YC - Y*XC
            RHO = SQRT(X*X + Y*Y)
            RR = RP*RM
            TX = TX + WY*(XP*PI + XM*PM)
            TY = TY + WY*(YP*PI + YM*PM)
            EE = E*E*RINV2
            TK = TK + WY*(EE*(PI + PM) + 8.0D0*D*D*EE/
     &           (RR*(RP + RM)*(RR + (R - RHO)*(R + RHO))))
   10    CONTINUE
         SX = SX + GW(I)*TX
         SY = SY + GW(I)*TY
         SK = SK + GW(I)*TK
   20 CONTINUE
      XI = 0.25D0*SX
      YI = 0.25D0*SY
      XK = 0.25D0*SK
      RETURN
      END
