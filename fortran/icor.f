C=======================================================================
C     ICOR -- instantaneous centre of rotation of a pushed nanorod
C     (docs/models.md section D; thesis chapters 4 and 5).
C
C     Geometry: rod of length RL = 2B along its axis, push perpendicular
C     to the rod at distance YN >= 0 from the centre of mass (CM).
C     Chapter 4 convention: R > 0 is the CM-to-iCOR distance on the far
C     side of the CM from the push. The cubic (5.4) roots keep their own
C     signs; its negative root is the one Table 5.1 tabulates.
C
C     Status IERR (all routines):
C       0 success
C       1 bad input (YN < 0, RL <= 0, non-positive parameter, ...)
C       2 LAPACK DGEEV failed (INFO /= 0)
C       3 Brent failed (no convergence)
C       4 push force below the minimum force of eq 4.8
C       5 LAPACK workspace too small
C       6 eq 5.2 is 0/0
C       7 the result is infinite (pure translation, YN = 0 in 5.5)
C     No routine STOPs; none uses COMMON.
C=======================================================================

C-----------------------------------------------------------------------
C     ICR413 -- eq 4.13, unknown pressure: R = SQRT(B**2+YN**2) - YN,
C     evaluated as B**2/(SQRT(B**2+YN**2) + YN).
C-----------------------------------------------------------------------
      SUBROUTINE ICR413(YN, RL, R, IERR)
      DOUBLE PRECISION YN, RL, R, B
      INTEGER IERR
      R = 0.0D0
      IERR = 1
      IF (.NOT. (RL .GT. 0.0D0) .OR. .NOT. (YN .GE. 0.0D0)) RETURN
      IF (YN - YN .NE. 0.0D0 .OR. RL - RL .NE. 0.0D0) RETURN
      B = 0.5D0*RL
      R = B*B/(SQRT(B*B + YN*YN) + YN)
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR401 -- eq 4.1, experimental fit ALPHA = 0.5 SQRT(BETA - 0.5),
C     BETA = (B + YN)/RL, R = B - ALPHA*RL. Needs 0 <= YN <= B.
C-----------------------------------------------------------------------
      SUBROUTINE ICR401(YN, RL, R, IERR)
      DOUBLE PRECISION YN, RL, R, B, BETA, ALPHA
      INTEGER IERR
      R = 0.0D0
      IERR = 1
      IF (.NOT. (RL .GT. 0.0D0)) RETURN
      B = 0.5D0*RL
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (YN .LE. B)) RETURN
      BETA = (B + YN)/RL
      ALPHA = 0.5D0*SQRT(MAX(0.0D0, BETA - 0.5D0))
      R = B - ALPHA*RL
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR402 -- eq 4.2 (Falvo et al.) in its own coordinates, mapped to
C     R: X1 = (B + YN)/RL, X0 = X1 - SQRT(X1**2 - (2 X1 - 1)/2),
C     R = B - RL*X0. Needs 0 <= YN <= B.
C-----------------------------------------------------------------------
      SUBROUTINE ICR402(YN, RL, R, IERR)
      DOUBLE PRECISION YN, RL, R, B, X1, X0
      INTEGER IERR
      R = 0.0D0
      IERR = 1
      IF (.NOT. (RL .GT. 0.0D0)) RETURN
      B = 0.5D0*RL
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (YN .LE. B)) RETURN
      X1 = (B + YN)/RL
      X0 = X1 - SQRT(X1*X1 - 0.5D0*(2.0D0*X1 - 1.0D0))
      R = B - RL*X0
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR403 -- eq 4.3 (Li et al.) mapped to R: push at EL = B - YN from
C     the left end (branch EL <= RL/2), S = EL + SQRT(EL**2 - EL*RL
C     + RL**2/2), R = S - B. Needs 0 <= YN <= B.
C-----------------------------------------------------------------------
      SUBROUTINE ICR403(YN, RL, R, IERR)
      DOUBLE PRECISION YN, RL, R, B, EL, S
      INTEGER IERR
      R = 0.0D0
      IERR = 1
      IF (.NOT. (RL .GT. 0.0D0)) RETURN
      B = 0.5D0*RL
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (YN .LE. B)) RETURN
      EL = B - YN
      S = EL + SQRT(EL*EL - EL*RL + 0.5D0*RL*RL)
      R = S - B
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR408 -- eq 4.8, minimum force F = RMU W (SQRT(YN**2+B**2) - YN)/B
C-----------------------------------------------------------------------
      SUBROUTINE ICR408(RMU, W, YN, RL, F, IERR)
      DOUBLE PRECISION RMU, W, YN, RL, F, R
      INTEGER IERR
      F = 0.0D0
      IERR = 1
      IF (.NOT. (RMU .GT. 0.0D0) .OR. .NOT. (W .GT. 0.0D0)) RETURN
      CALL ICR413(YN, RL, R, IERR)
      IF (IERR .NE. 0) RETURN
      F = RMU*W*R/(0.5D0*RL)
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR407 -- eq 4.7, known pressure:
C     R = (B F + SQRT(B**2 F**2 - RMU W (RMU W B**2 - 2 B YN F)))/(RMU W)
C     IERR = 4 when F is below the minimum force of eq 4.8.
C-----------------------------------------------------------------------
      SUBROUTINE ICR407(RMU, W, YN, F, RL, R, IERR)
      DOUBLE PRECISION RMU, W, YN, F, RL, R, B, FMIN, DISC, RMW
      INTEGER IERR
      R = 0.0D0
      IF (.NOT. (F .GT. 0.0D0)) THEN
        IERR = 1
        RETURN
      END IF
      CALL ICR408(RMU, W, YN, RL, FMIN, IERR)
      IF (IERR .NE. 0) RETURN
      B = 0.5D0*RL
      RMW = RMU*W
      DISC = B*B*F*F - RMW*(RMW*B*B - 2.0D0*B*YN*F)
      IF (DISC .LT. 0.0D0) THEN
        IF (F .GE. FMIN*(1.0D0 - 8.0D0*2.220446049250313D-16)) THEN
          DISC = 0.0D0
        ELSE
          IERR = 4
          RETURN
        END IF
      END IF
      R = (B*F + SQRT(DISC))/RMW
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR410 -- eq 4.10, F = RMU W R / B
C-----------------------------------------------------------------------
      SUBROUTINE ICR410(RMU, W, R, RL, F, IERR)
      DOUBLE PRECISION RMU, W, R, RL, F
      INTEGER IERR
      F = 0.0D0
      IERR = 1
      IF (.NOT. (RMU .GT. 0.0D0) .OR. .NOT. (W .GT. 0.0D0)) RETURN
      IF (.NOT. (R .GE. 0.0D0) .OR. .NOT. (RL .GT. 0.0D0)) RETURN
      F = RMU*W*R/(0.5D0*RL)
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR411 -- eq 4.11, F = RMU W (B**2 + R**2)/(2 B (R + YN))
C-----------------------------------------------------------------------
      SUBROUTINE ICR411(RMU, W, R, YN, RL, F, IERR)
      DOUBLE PRECISION RMU, W, R, YN, RL, F, B
      INTEGER IERR
      F = 0.0D0
      IERR = 1
      IF (.NOT. (RMU .GT. 0.0D0) .OR. .NOT. (W .GT. 0.0D0)) RETURN
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (RL .GT. 0.0D0)) RETURN
      IF (.NOT. (R + YN .GT. 0.0D0)) RETURN
      B = 0.5D0*RL
      F = RMU*W*(B*B + R*R)/(2.0D0*B*(R + YN))
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR505 -- eq 5.5 (erratum 6: K**2 = I/M), R = RK2/YN.
C     YN = 0: IERR = 7 (R infinite, pure translation), R = 0 returned.
C-----------------------------------------------------------------------
      SUBROUTINE ICR505(YN, RK2, R, IERR)
      DOUBLE PRECISION YN, RK2, R
      INTEGER IERR
      R = 0.0D0
      IERR = 1
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (RK2 .GT. 0.0D0)) RETURN
      IF (YN .EQ. 0.0D0) THEN
        IERR = 7
        RETURN
      END IF
      R = RK2/YN
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICR502 -- eq 5.2 (erratum 5), push force for an assumed iCOR R:
C     F = -RMU W R (R**2 + 2 RK2 - B**2) / (2 B (YN R - RK2)).
C     At the pole YN R = RK2 (the impulsive iCOR) the force is infinite:
C     IERR = 7 and F = +1 or -1 carries its sign.
C-----------------------------------------------------------------------
      SUBROUTINE ICR502(RMU, W, R, YN, RL, RK2, F, IERR)
      DOUBLE PRECISION RMU, W, R, YN, RL, RK2, F, B, FNUM, FDEN
      INTEGER IERR
      F = 0.0D0
      IERR = 1
      IF (.NOT. (RMU .GT. 0.0D0) .OR. .NOT. (W .GT. 0.0D0)) RETURN
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (RL .GT. 0.0D0)) RETURN
      IF (.NOT. (RK2 .GT. 0.0D0)) RETURN
      B = 0.5D0*RL
      FNUM = -RMU*W*R*(R*R + 2.0D0*RK2 - B*B)
      FDEN = 2.0D0*B*(YN*R - RK2)
      IF (FDEN .EQ. 0.0D0) THEN
        IF (FNUM .EQ. 0.0D0) THEN
          IERR = 6
        ELSE
          IERR = 7
          F = SIGN(1.0D0, FNUM)
        END IF
        RETURN
      END IF
      F = FNUM/FDEN
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRCUB -- dimensionless coefficients of the constrained cubic
C     (5.4) divided by M**2 W B**4, in r = R/B (ascending order):
C     C(1) + C(2) r + C(3) r**2 + C(4) r**3 with
C     C(1) = KAP (1 - 2 KAP), C(2) = 0, C(3) = -3 KAP, C(4) = 2 YN/B,
C     KAP = RK2/B**2 (RK2 = I/M).
C-----------------------------------------------------------------------
      SUBROUTINE ICRCUB(YN, RL, RK2, C, IERR)
      DOUBLE PRECISION YN, RL, RK2, C(4), B, AKAP
      INTEGER IERR
      IERR = 1
      C(1) = 0.0D0
      C(2) = 0.0D0
      C(3) = 0.0D0
      C(4) = 0.0D0
      IF (.NOT. (YN .GE. 0.0D0) .OR. .NOT. (RL .GT. 0.0D0)) RETURN
      IF (.NOT. (RK2 .GT. 0.0D0)) RETURN
      IF (YN - YN .NE. 0.0D0 .OR. RL - RL .NE. 0.0D0) RETURN
      IF (RK2 - RK2 .NE. 0.0D0) RETURN
      B = 0.5D0*RL
      AKAP = RK2/(B*B)
      C(1) = AKAP*(1.0D0 - 2.0D0*AKAP)
      C(2) = 0.0D0
      C(3) = -3.0D0*AKAP
      C(4) = 2.0D0*YN/B
C     Overflowed scaled coefficients (absurd YN/RL or RK2/RL**2): reject.
      IF (C(4) - C(4) .NE. 0.0D0 .OR. C(1) - C(1) .NE. 0.0D0) THEN
        IERR = 1
        RETURN
      END IF
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRPV -- the cubic p(X) = C(1) + C(2) X + C(3) X**2 + C(4) X**3
C     divided by MAX(1,|X|)**3: the same sign and zeros as p, without
C     overflow for huge |X| (Horner in 1/X on the reversed coefficients).
C     The EXTERNAL function handed to ZBRENT.
C-----------------------------------------------------------------------
      DOUBLE PRECISION FUNCTION ICRPV(X, C)
      DOUBLE PRECISION X, C(4), U
      IF (ABS(X) .LE. 1.0D0) THEN
        ICRPV = ((C(4)*X + C(3))*X + C(2))*X + C(1)
      ELSE
        U = 1.0D0/X
        ICRPV = SIGN(1.0D0, X)*(((C(1)*U + C(2))*U + C(3))*U + C(4))
      END IF
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRDEF -- degree of the cubic after deflating a leading coefficient
C     that is zero or so small that C(I)/C(N+1) would overflow (those
C     roots are at infinity). Returns N (0..3) and NINF = 3 - N.
C-----------------------------------------------------------------------
      SUBROUTINE ICRDEF(C, N, NINF)
      DOUBLE PRECISION C(4), BIG
      INTEGER N, NINF, I
      LOGICAL INF
      PARAMETER (BIG = 1.7976931348623157D308/16.0D0)
      N = 3
   10 CONTINUE
      IF (N .LT. 0) GO TO 20
      INF = (C(N+1) .EQ. 0.0D0)
      IF (.NOT. INF) THEN
        DO 15 I = 1, N
          IF (ABS(C(I)) .GT. BIG*ABS(C(N+1))) INF = .TRUE.
   15   CONTINUE
      END IF
      IF (.NOT. INF) GO TO 20
      N = N - 1
      GO TO 10
   20 CONTINUE
      IF (N .LT. 0) N = 0
      NINF = 3 - N
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRSUM -- sorts the real roots X(1..NR) ascending, scales them by B
C     into ROOTS (metres) and returns RESMAX = max |p(x)|/sum|c_i x^i|
C     (evaluated in 1/x for |x| > 1, so nothing overflows). A root that
C     is finite in units of B but overflows in metres is moved to NINF.
C-----------------------------------------------------------------------
      SUBROUTINE ICRSUM(C, X, NR, B, ROOTS, RESMAX, NINF)
      DOUBLE PRECISION C(4), X(*), B, ROOTS(*), RESMAX, T, P, S, AX, U
      DOUBLE PRECISION BIG
      INTEGER NR, NINF, I, J, NOUT
      PARAMETER (BIG = 1.7976931348623157D308)
      DO 20 I = 2, NR
        T = X(I)
        J = I - 1
   10   CONTINUE
        IF (J .GE. 1) THEN
          IF (X(J) .GT. T) THEN
            X(J+1) = X(J)
            J = J - 1
            GO TO 10
          END IF
        END IF
        X(J+1) = T
   20 CONTINUE
      RESMAX = 0.0D0
      NOUT = 0
      DO 30 I = 1, NR
        AX = ABS(X(I))
        IF (AX .LE. 1.0D0) THEN
          P = ((C(4)*X(I) + C(3))*X(I) + C(2))*X(I) + C(1)
          S = ((ABS(C(4))*AX + ABS(C(3)))*AX + ABS(C(2)))*AX
     &        + ABS(C(1))
        ELSE
          U = 1.0D0/X(I)
          P = ((C(1)*U + C(2))*U + C(3))*U + C(4)
          U = ABS(U)
          S = ((ABS(C(1))*U + ABS(C(2)))*U + ABS(C(3)))*U + ABS(C(4))
        END IF
        IF (S .GT. 0.0D0) RESMAX = MAX(RESMAX, ABS(P)/S)
        IF (AX .GT. 1.0D0 .AND. AX .GT. BIG/B) THEN
          NINF = NINF + 1
        ELSE
          NOUT = NOUT + 1
          ROOTS(NOUT) = B*X(I)
        END IF
   30 CONTINUE
      NR = NOUT
      RETURN
      END

C-----------------------------------------------------------------------
C     ICREIG -- eigenvalues WR + i WI of the companion matrix of the
C     polynomial P(1) + P(2) x + ... + P(N+1) x**N (P(N+1) /= 0), by
C     LAPACK DGEEV (which balances the matrix, DGEBAL, before the
C     Hessenberg QR iteration). Workspace: queried (LWORK = -1) and
C     checked against the local array. IERR 0, 2 (INFO /= 0) or 5.
C-----------------------------------------------------------------------
      SUBROUTINE ICREIG(P, N, WR, WI, IERR)
      INTEGER N, IERR
      DOUBLE PRECISION P(*), WR(3), WI(3)
      INTEGER LWMAX
      PARAMETER (LWMAX = 256)
      DOUBLE PRECISION A(3,3), VL(1,1), VR(1,1), WORK(LWMAX)
      INTEGER INFO, LWORK, I, J
C     Companion matrix, first-row form: A(1,J) = -P(N+1-J)/P(N+1),
C     ones on the subdiagonal.
      DO 20 J = 1, N
        DO 10 I = 1, N
          A(I,J) = 0.0D0
   10   CONTINUE
        A(1,J) = -P(N+1-J)/P(N+1)
        IF (J .LT. N) A(J+1,J) = 1.0D0
   20 CONTINUE
      CALL DGEEV('N', 'N', N, A, 3, WR, WI, VL, 1, VR, 1, WORK, -1,
     &           INFO)
      IF (INFO .NE. 0) THEN
        IERR = 2
        RETURN
      END IF
      LWORK = INT(WORK(1))
      IF (LWORK .GT. LWMAX) THEN
        IERR = 5
        RETURN
      END IF
      LWORK = LWMAX
      CALL DGEEV('N', 'N', N, A, 3, WR, WI, VL, 1, VR, 1, WORK, LWORK,
     &           INFO)
      IF (INFO .NE. 0) THEN
        IERR = 2
        RETURN
      END IF
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRLAP -- all roots of the constrained cubic (5.4) as eigenvalues
C     of companion matrices, LAPACK DGEEV (ICREIG). Roots of modulus > 1
C     come from the companion matrix of p, the others as reciprocals of
C     the eigenvalues of the companion matrix of the reversed polynomial
C     x**N p(1/x): each root comes from the matrix in which it is among
C     the largest eigenvalues, so the O(1) roots stay exact while the
C     third root runs off to infinity (YN -> 0).
C
C     In:  YN [m] >= 0, RL [m] > 0, RK2 = I/M [m**2] > 0.
C     Out: ROOTS(3) real roots ascending [m], NREAL of them;
C          NCPLX non-real roots; NINF roots at infinity (YN -> 0);
C          RESMAX max relative residual of the real roots; IERR.
C-----------------------------------------------------------------------
      SUBROUTINE ICRLAP(YN, RL, RK2, ROOTS, NREAL, NCPLX, NINF,
     &                  RESMAX, IERR)
      DOUBLE PRECISION YN, RL, RK2, ROOTS(3), RESMAX
      INTEGER NREAL, NCPLX, NINF, IERR
      DOUBLE PRECISION C(4), CR(4), WR(3), WI(3), VR(3), VI(3), X(3)
      DOUBLE PRECISION B, T, BIG
      INTEGER N, I, J, K, NZ
      LOGICAL REVOK
      PARAMETER (BIG = 1.7976931348623157D308/16.0D0)
      NREAL = 0
      NCPLX = 0
      NINF = 0
      RESMAX = 0.0D0
      DO 5 I = 1, 3
        ROOTS(I) = 0.0D0
    5 CONTINUE
      CALL ICRCUB(YN, RL, RK2, C, IERR)
      IF (IERR .NE. 0) RETURN
      B = 0.5D0*RL
      CALL ICRDEF(C, N, NINF)
      IF (N .EQ. 0) RETURN
C     Exact zero roots (zero constant terms).
      NZ = 0
    6 CONTINUE
      IF (NZ .LT. N .AND. C(NZ+1) .EQ. 0.0D0) THEN
        NZ = NZ + 1
        NREAL = NREAL + 1
        X(NREAL) = 0.0D0
        GO TO 6
      END IF
C     Shift out the zero roots: CR(1..N-NZ+1) is the remaining factor.
      DO 7 I = 1, N - NZ + 1
        CR(I) = C(I + NZ)
    7 CONTINUE
      N = N - NZ
      IF (N .EQ. 0) GO TO 90
      CALL ICREIG(CR, N, WR, WI, IERR)
      IF (IERR .NE. 0) RETURN
C     Reversed polynomial, unless its companion matrix would overflow.
      REVOK = .TRUE.
      DO 8 I = 2, N + 1
        IF (ABS(CR(I)) .GT. BIG*ABS(CR(1))) REVOK = .FALSE.
    8 CONTINUE
      IF (REVOK) THEN
        DO 9 I = 1, N + 1
          C(I) = CR(N + 2 - I)
    9   CONTINUE
        CALL ICREIG(C, N, VR, VI, IERR)
        IF (IERR .NE. 0) RETURN
      END IF
C     Sort both sets by decreasing modulus (insertion sort, N <= 3).
      DO 20 I = 2, N
        DO 15 J = I, 2, -1
          IF (WR(J)**2 + WI(J)**2 .GT. WR(J-1)**2 + WI(J-1)**2) THEN
            T = WR(J)
            WR(J) = WR(J-1)
            WR(J-1) = T
            T = WI(J)
            WI(J) = WI(J-1)
            WI(J-1) = T
          END IF
          IF (REVOK) THEN
            IF (VR(J)**2 + VI(J)**2 .GT. VR(J-1)**2 + VI(J-1)**2) THEN
              T = VR(J)
              VR(J) = VR(J-1)
              VR(J-1) = T
              T = VI(J)
              VI(J) = VI(J-1)
              VI(J-1) = T
            END IF
          END IF
   15   CONTINUE
   20 CONTINUE
C     K roots of modulus > 1 from p's matrix; N - K from the reversed.
      K = 0
   25 CONTINUE
      IF (K .LT. N) THEN
        IF (.NOT. REVOK .OR. WR(K+1)**2 + WI(K+1)**2 .GT. 1.0D0) THEN
          K = K + 1
          GO TO 25
        END IF
      END IF
      DO 30 I = 1, K
        IF (WI(I) .EQ. 0.0D0) THEN
          NREAL = NREAL + 1
          X(NREAL) = WR(I)
        ELSE
          NCPLX = NCPLX + 1
        END IF
   30 CONTINUE
      DO 40 I = 1, N - K
        IF (VI(I) .EQ. 0.0D0) THEN
          NREAL = NREAL + 1
          X(NREAL) = 1.0D0/VR(I)
        ELSE
          NCPLX = NCPLX + 1
        END IF
   40 CONTINUE
   90 CONTINUE
C     Residuals against the full cubic.
      CALL ICRCUB(YN, RL, RK2, C, IERR)
      CALL ICRSUM(C, X, NREAL, B, ROOTS, RESMAX, NINF)
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRXPD -- outward geometric bracketing (Numerical Recipes ZBRAC,
C     one-sided): from X0 step DIR*MAX(1,|X0|), doubling, until the sign
C     of the cubic changes. IFOUND = 1 with the bracket [XL, XH], or 0
C     when |X| passes 1D300 first (the root is at infinity).
C-----------------------------------------------------------------------
      SUBROUTINE ICRXPD(C, X0, DIR, XL, XH, IFOUND)
      DOUBLE PRECISION C(4), X0, DIR, XL, XH, STEP, XIN, FIN, XOUT, FO
      INTEGER IFOUND
      DOUBLE PRECISION ICRPV
      EXTERNAL ICRPV
      IFOUND = 0
      XIN = X0
      FIN = ICRPV(X0, C)
      STEP = DIR*MAX(1.0D0, ABS(X0))
   10 CONTINUE
      XOUT = X0 + STEP
      IF (ABS(XOUT) .GT. 1.0D300) RETURN
      FO = ICRPV(XOUT, C)
      IF (FO .EQ. 0.0D0 .OR. ((FO .GT. 0.0D0) .NEQV. (FIN .GT. 0.0D0)))
     &  THEN
        XL = MIN(XIN, XOUT)
        XH = MAX(XIN, XOUT)
        IFOUND = 1
        RETURN
      END IF
      XIN = XOUT
      FIN = FO
      STEP = 2.0D0*STEP
      GO TO 10
      END

C-----------------------------------------------------------------------
C     ICRBRT -- the real roots of the constrained cubic (5.4) by Brent
C     (ZBRENT) on brackets found automatically: the cubic is monotone
C     between its critical points (roots of p'); bounded pieces with a
C     sign change are bracketed at once, unbounded ones by ICRXPD.
C     Arguments as ICRLAP, plus NITER (total Brent iterations).
C-----------------------------------------------------------------------
      SUBROUTINE ICRBRT(YN, RL, RK2, ROOTS, NREAL, NCPLX, NINF,
     &                  RESMAX, NITER, IERR)
      DOUBLE PRECISION YN, RL, RK2, ROOTS(3), RESMAX
      INTEGER NREAL, NCPLX, NINF, NITER, IERR
      DOUBLE PRECISION C(4), X(3), CR(2), B, A2, A1, A0, DISC, Q, T
      DOUBLE PRECISION XL, XH, XR, FR, F0, SINF, DIR
      INTEGER N, NC, I, IT, IFOUND, K
      DOUBLE PRECISION ICRPV
      EXTERNAL ICRPV
      NREAL = 0
      NCPLX = 0
      NINF = 0
      NITER = 0
      RESMAX = 0.0D0
      DO 5 I = 1, 3
        ROOTS(I) = 0.0D0
    5 CONTINUE
      CALL ICRCUB(YN, RL, RK2, C, IERR)
      IF (IERR .NE. 0) RETURN
      B = 0.5D0*RL
      CALL ICRDEF(C, N, NINF)
      IF (N .EQ. 0) RETURN
C     Critical points.
      NC = 0
      IF (N .EQ. 2) THEN
        NC = 1
        CR(1) = -C(2)/(2.0D0*C(3))
      ELSE IF (N .EQ. 3) THEN
        A2 = 3.0D0*C(4)
        A1 = 2.0D0*C(3)
        A0 = C(2)
        DISC = A1*A1 - 4.0D0*A2*A0
        IF (DISC .GT. 0.0D0) THEN
          Q = -0.5D0*(A1 + SIGN(SQRT(DISC), A1))
          NC = 2
          CR(1) = Q/A2
          IF (Q .NE. 0.0D0) THEN
            CR(2) = A0/Q
          ELSE
            CR(2) = -Q/A2
          END IF
          IF (CR(1) .GT. CR(2)) THEN
            T = CR(1)
            CR(1) = CR(2)
            CR(2) = T
          END IF
        ELSE IF (DISC .EQ. 0.0D0) THEN
          NC = 1
          CR(1) = -A1/(2.0D0*A2)
        END IF
      END IF
C     Exact zeros at the critical points.
      DO 10 I = 1, NC
        IF (ICRPV(CR(I), C) .EQ. 0.0D0) THEN
          NREAL = NREAL + 1
          X(NREAL) = CR(I)
        END IF
   10 CONTINUE
C     Bounded piece.
      IF (NC .EQ. 2) THEN
        F0 = ICRPV(CR(1), C)
        FR = ICRPV(CR(2), C)
        IF (F0 .NE. 0.0D0 .AND. FR .NE. 0.0D0 .AND.
     &      ((F0 .GT. 0.0D0) .NEQV. (FR .GT. 0.0D0))) THEN
          CALL ZBRENT(ICRPV, CR(1), CR(2), 0.0D0, 5000, C, XR, FR,
     &                IT, IERR)
          NITER = NITER + IT
          IF (IERR .NE. 0) THEN
            IERR = 3
            RETURN
          END IF
          NREAL = NREAL + 1
          X(NREAL) = XR
        END IF
      END IF
C     Unbounded pieces: K = 1 towards -infinity, K = 2 towards +infinity.
      DO 30 K = 1, 2
        IF (K .EQ. 1) THEN
          DIR = -1.0D0
        ELSE
          DIR = 1.0D0
        END IF
        IF (NC .EQ. 0) THEN
          IF (K .EQ. 2) GO TO 30
          XL = 0.0D0
          F0 = ICRPV(XL, C)
          IF (F0 .EQ. 0.0D0) THEN
            NREAL = NREAL + 1
            X(NREAL) = 0.0D0
            GO TO 30
          END IF
          SINF = SIGN(1.0D0, C(N+1))
          IF ((F0 .GT. 0.0D0) .EQV. (SINF .GT. 0.0D0)) THEN
            DIR = -1.0D0
          ELSE
            DIR = 1.0D0
          END IF
          T = XL
        ELSE IF (K .EQ. 1) THEN
          T = CR(1)
        ELSE
          T = CR(NC)
        END IF
        F0 = ICRPV(T, C)
        IF (F0 .EQ. 0.0D0) GO TO 30
C       Sign of p at infinity in direction DIR.
        SINF = SIGN(1.0D0, C(N+1))
        IF (DIR .LT. 0.0D0 .AND. MOD(N, 2) .EQ. 1) SINF = -SINF
        IF ((F0 .GT. 0.0D0) .EQV. (SINF .GT. 0.0D0)) GO TO 30
        CALL ICRXPD(C, T, DIR, XL, XH, IFOUND)
        IF (IFOUND .EQ. 0) THEN
          NINF = NINF + 1
          GO TO 30
        END IF
        CALL ZBRENT(ICRPV, XL, XH, 0.0D0, 5000, C, XR, FR, IT, IERR)
        NITER = NITER + IT
        IF (IERR .NE. 0) THEN
          IERR = 3
          RETURN
        END IF
        NREAL = NREAL + 1
        X(NREAL) = XR
   30 CONTINUE
      NCPLX = 3 - NINF - NREAL
      CALL ICRSUM(C, X, NREAL, B, ROOTS, RESMAX, NINF)
      IERR = 0
      RETURN
      END

C-----------------------------------------------------------------------
C     ICRBRN -- the two branches of the cubic from ascending real roots:
C     RNEG = negative root closest to 0 (Table 5.1's branch), RPOS =
C     smallest positive root. IHNEG/IHPOS = 1 when the branch exists.
C-----------------------------------------------------------------------
      SUBROUTINE ICRBRN(ROOTS, NREAL, RNEG, IHNEG, RPOS, IHPOS)
      DOUBLE PRECISION ROOTS(*), RNEG, RPOS
      INTEGER NREAL, IHNEG, IHPOS, I
      IHNEG = 0
      IHPOS = 0
      RNEG = 0.0D0
      RPOS = 0.0D0
      DO 10 I = 1, NREAL
        IF (ROOTS(I) .LT. 0.0D0) THEN
          RNEG = ROOTS(I)
          IHNEG = 1
        END IF
        IF (ROOTS(I) .GT. 0.0D0 .AND. IHPOS .EQ. 0) THEN
          RPOS = ROOTS(I)
          IHPOS = 1
        END IF
   10 CONTINUE
      RETURN
      END
