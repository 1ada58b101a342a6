C=======================================================================
C     ZBRENT -- van Wijngaarden-Dekker-Brent zero of F on [A, B].
C
C     Brent, R. P. (1973), Algorithms for Minimization without
C     Derivatives, Prentice-Hall, chapter 4, procedure ZERO:
C     bisection, secant and inverse quadratic interpolation, keeping
C     a bracket at every step. Followed step by step.
C
C     F      EXTERNAL DOUBLE PRECISION FUNCTION F(X, RPAR)
C     A, B   bracket ends; F(A) and F(B) must not have the same sign
C     XTOL   absolute tolerance on X (0: full machine precision)
C     MAXIT  iteration cap
C     RPAR   parameters passed through to F (no COMMON: re-entrant)
C     X, FX  root estimate and F(X)
C     NITER  iterations used
C     IERR   0 converged; 1 F(A), F(B) same sign; 3 MAXIT reached
C            (X, FX then hold the last iterate)
C=======================================================================
      SUBROUTINE ZBRENT(F, A, B, XTOL, MAXIT, RPAR, X, FX, NITER, IERR)
      EXTERNAL F
      DOUBLE PRECISION F
      INTEGER MAXIT, NITER, IERR
      DOUBLE PRECISION A, B, XTOL, RPAR(*), X, FX
      DOUBLE PRECISION AA, BB, CC, FA, FB, FC, D, E, TOL, XM
      DOUBLE PRECISION P, Q, R, S, EPS
      INTEGER IT
C     EPS: IEEE double unit roundoff times 2 (machine epsilon)
      PARAMETER (EPS = 2.220446049250313D-16)
      AA = A
      BB = B
      FA = F(AA, RPAR)
      FB = F(BB, RPAR)
      NITER = 0
      IERR = 0
      IF (FA .EQ. 0.0D0) THEN
        X = AA
        FX = 0.0D0
        RETURN
      END IF
      IF (FB .EQ. 0.0D0) THEN
        X = BB
        FX = 0.0D0
        RETURN
      END IF
      IF ((FA .GT. 0.0D0) .EQV. (FB .GT. 0.0D0)) THEN
        IERR = 1
        X = BB
        FX = FB
        RETURN
      END IF
      CC = AA
      FC = FA
      D = BB - AA
      E = D
      DO 10 IT = 1, MAXIT
        NITER = IT
        IF ((FB .GT. 0.0D0) .EQV. (FC .GT. 0.0D0)) THEN
          CC = AA
          FC = FA
          D = BB - AA
          E = D
        END IF
        IF (ABS(FC) .LT. ABS(FB)) THEN
          AA = BB
          BB = CC
          CC = AA
          FA = FB
          FB = FC
          FC = FA
        END IF
        TOL = 2.0D0*EPS*ABS(BB) + 0.5D0*XTOL
        XM = 0.5D0*(CC - BB)
        IF (ABS(XM) .LE. TOL .OR. FB .EQ. 0.0D0) THEN
          X = BB
          FX = FB
          RETURN
        END IF
        IF (ABS(E) .LT. TOL .OR. ABS(FA) .LE. ABS(FB)) THEN
          D = XM
          E = XM
        ELSE
          S = FB/FA
          IF (AA .EQ. CC) THEN
            P = 2.0D0*XM*S
            Q = 1.0D0 - S
          ELSE
            Q = FA/FC
            R = FB/FC
            P = S*(2.0D0*XM*Q*(Q - R) - (BB - AA)*(R - 1.0D0))
            Q = (Q - 1.0D0)*(R - 1.0D0)*(S - 1.0D0)
          END IF
          IF (P .GT. 0.0D0) THEN
            Q = -Q
          ELSE
            P = -P
          END IF
          S = E
          E = D
          IF (2.0D0*P .LT. 3.0D0*XM*Q - ABS(TOL*Q) .AND.
     &        P .LT. ABS(0.5D0*S*Q)) THEN
            D = P/Q
          ELSE
            D = XM
            E = XM
          END IF
        END IF
        AA = BB
        FA = FB
        IF (ABS(D) .GT. TOL) THEN
          BB = BB + D
        ELSE IF (XM .GT. 0.0D0) THEN
          BB = BB + TOL
        ELSE
          BB = BB - TOL
        END IF
        FB = F(BB, RPAR)
   10 CONTINUE
      X = BB
      FX = FB
      IERR = 3
      RETURN
      END
