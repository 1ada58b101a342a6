C=======================================================================
C     BSINT -- Bulirsch-Stoer (Gragg-Bulirsch-Stoer) extrapolation
C     integrator for y' = f(t, y), with adaptive step size and order.
C
C     Method (see docs/bulirsch_stoer.md, which this code follows
C     operation for operation; the C++ "faithful" engine does the same):
C     - Gragg's modified midpoint rule with the step-number sequence
C       n_j = 2j and a final smoothing step (BSMMID);
C     - extrapolation of the midpoint results in h**2, either rational
C       (the Stoer-Bulirsch formula, as used in the thesis) or
C       polynomial (Aitken-Neville) (BSXTRP);
C     - error estimate from the last two extrapolated values of a row,
C       convergence monitor, and order and step-size selection by work
C       per unit step (BSTRY, BSKOPT, and the driver BSINT).
C
C     References (the code was written from these descriptions, not
C     from any book's code):
C       J. Stoer, R. Bulirsch, Introduction to Numerical Analysis,
C         Springer, section 7.2.14 (extrapolation methods, rational
C         extrapolation of the Gragg midpoint rule).
C       P. Deuflhard, Order and stepsize control in extrapolation
C         methods, Numer. Math. 41 (1983) 399-422; Recent progress in
C         extrapolation methods for ODEs, SIAM Rev. 27 (1985) 505-535.
C       E. Hairer, S.P. Norsett, G. Wanner, Solving Ordinary
C         Differential Equations I, 2nd ed., Springer 1993, section
C         II.9 (order and step-size control; the constants SAFE1,
C         SAFE2, SAFE3, FAC4, ORDDEC, ORDINC are named after it).
C
C     Fixed-form FORTRAN 77, DOUBLE PRECISION, no COMMON, never STOP.
C     Workspace is local arrays of fixed size (NMAX components,
C     KMAXX columns); the library is compiled with -frecursive so the
C     routines are re-entrant.
C=======================================================================
C
C     SUBROUTINE BSINT(FCN, N, T0, Y, NOUT, TOUT, YOUT, RTOL, ATOL,
C    &                 H0, HMAX, KMAX, IEXTR, MAXSTP, RPAR, IPAR,
C    &                 NSTAT, IERR)
C
C     FCN    EXTERNAL SUBROUTINE FCN(N, T, Y, DYDT, RPAR, IPAR, IERR)
C            computes DYDT = f(T, Y); IERR = 0 on success, non-zero
C            on failure (BSINT then returns IERR = 4 at once).
C     N      number of components, 1 <= N <= NMAX (= 64).
C     T0     initial time.
C     Y(N)   in: state at T0. out: state at the last output time
C            reached (on failure, the last output time reached before
C            the failure, or the input state if none was reached).
C     NOUT   number of output times, >= 1.
C     TOUT(NOUT) output times, T0 <= TOUT(1) <= ... <= TOUT(NOUT).
C     YOUT(N,NOUT) out: state at each TOUT; columns not reached
C            because of a failure are left unchanged.
C     RTOL   relative tolerance (>= 0).
C     ATOL(N) absolute tolerance per component (>= 0; > 0 where
C            RTOL = 0).
C     H0     initial step (0 = default 0.01*(TOUT(NOUT)-T0)), >= 0.
C     HMAX   largest step (0 = no limit), >= 0.
C     KMAX   number of extrapolation columns, 3..12 (0 = default 8).
C     IEXTR  1 = rational extrapolation, 2 = polynomial.
C     MAXSTP maximum number of attempted steps (0 = default 100000).
C     RPAR, IPAR  passed unchanged to FCN.
C     NSTAT(3) out: NFCN (RHS evaluations), NACCPT (accepted steps),
C            NREJCT (rejected steps); set on every return.
C     IERR   out: 0 success; 1 bad input; 2 more than MAXSTP attempted
C            steps; 3 step size underflow; 4 FCN returned non-zero;
C            5 non-finite error estimate after 10 consecutive step
C            reductions (NNFMAX).
C=======================================================================
      SUBROUTINE BSINT(FCN, N, T0, Y, NOUT, TOUT, YOUT, RTOL, ATOL,
     &                 H0, HMAX, KMAX, IEXTR, MAXSTP, RPAR, IPAR,
     &                 NSTAT, IERR)
      INTEGER NMAX, KMAXX
      PARAMETER (NMAX = 64, KMAXX = 12)
      EXTERNAL FCN
      INTEGER N, NOUT, KMAX, IEXTR, MAXSTP, IPAR(*), NSTAT(3), IERR
      DOUBLE PRECISION T0, Y(*), TOUT(*), YOUT(N,*), RTOL, ATOL(*),
     &                 H0, HMAX, RPAR(*)
      DOUBLE PRECISION ORDINC, BIG, SAFE3, FAC4
      INTEGER NNFMAX
      PARAMETER (ORDINC = 0.9D0, BIG = 1.7976931348623157D308)
      PARAMETER (SAFE3 = 0.02D0, FAC4 = 4.0D0)
      PARAMETER (NNFMAX = 10)
      DOUBLE PRECISION YW(NMAX), F0(NMAX), YNEW(NMAX)
      DOUBLE PRECISION HH(KMAXX), W(KMAXX), A(KMAXX)
      DOUBLE PRECISION FCT(3, KMAXX), RSQ(KMAXX, KMAXX)
      INTEGER NSEQ(KMAXX)
      DOUBLE PRECISION T, H, HWANT, HNEW, TSPAN, Q, FACMIN
      INTEGER L
      INTEGER KM, MXS, NFCN, NACC, NREJ, NNF, K, KC, KOPT, IOUT, I, J
      INTEGER IE
      LOGICAL HAVEF0, LASTRJ, CLIP, ACCEPT, NONFIN
C
      NFCN = 0
      NACC = 0
      NREJ = 0
      IERR = 0
C
C     ---- Input checks (status 1).  A value V is finite iff V .LE. BIG
C     ---- and -V .LE. BIG (false for NaN and for infinities).
      KM = KMAX
      IF (KM .EQ. 0) KM = 8
      MXS = MAXSTP
      IF (MXS .EQ. 0) MXS = 100000
      IF (N .LT. 1 .OR. N .GT. NMAX .OR. NOUT .LT. 1 .OR.
     &    KM .LT. 3 .OR. KM .GT. KMAXX .OR. MXS .LT. 0 .OR.
     &    (IEXTR .NE. 1 .AND. IEXTR .NE. 2)) THEN
         IERR = 1
         GOTO 900
      END IF
      IF (.NOT. (RTOL .GE. 0D0 .AND. RTOL .LE. BIG) .OR.
     &    .NOT. (H0 .GE. 0D0 .AND. H0 .LE. BIG) .OR.
     &    .NOT. (HMAX .GE. 0D0 .AND. HMAX .LE. BIG) .OR.
     &    .NOT. (T0 .LE. BIG .AND. -T0 .LE. BIG)) THEN
         IERR = 1
         GOTO 900
      END IF
      DO 10 I = 1, N
         IF (.NOT. (ATOL(I) .GE. 0D0 .AND. ATOL(I) .LE. BIG)) IERR = 1
         IF (RTOL .EQ. 0D0 .AND. ATOL(I) .EQ. 0D0) IERR = 1
         IF (.NOT. (Y(I) .LE. BIG .AND. -Y(I) .LE. BIG)) IERR = 1
   10 CONTINUE
      IF (.NOT. (TOUT(1) .GE. T0 .AND. TOUT(1) .LE. BIG)) IERR = 1
      DO 20 IOUT = 2, NOUT
         IF (.NOT. (TOUT(IOUT) .GE. TOUT(IOUT-1) .AND.
     &              TOUT(IOUT) .LE. BIG)) IERR = 1
   20 CONTINUE
      IF (IERR .NE. 0) GOTO 900
C
C     ---- Constants: step numbers n_j = 2j, work A_j.
      DO 30 J = 1, KM
         NSEQ(J) = 2*J
   30 CONTINUE
      A(1) = DBLE(NSEQ(1) + 1)
      DO 40 J = 2, KM
         A(J) = A(J-1) + DBLE(NSEQ(J))
   40 CONTINUE
C     W(1) and HH(1) are never computed (no error estimate in column
C     1); give them defined values all the same.
      DO 45 J = 1, KMAXX
         HH(J) = 0D0
         W(J) = 0D0
         FCT(1, J) = 0D0
         FCT(2, J) = 0D0
         FCT(3, J) = 0D0
   45 CONTINUE
C     Step-invariant factors of BSTRY and BSXTRP, computed once here
C     with the very operations of doc steps 4b and 4c (so the values
C     are the same bits as when computed at every step):
C       FCT(1,j) = expo = 1/dble(2j-1), FCT(2,j) = facmin/FAC4,
C       FCT(3,j) = 1/facmin, facmin = SAFE3**expo (j = 2..KM);
C       RSQ(j,l) = r = q*q, q = dble(n_j)/dble(n_(j-l+1)) (2<=l<=j).
C     The loops run to KM, a run-time bound, so the compiler cannot
C     fold SAFE3**expo into a constant: pow is called at run time,
C     as the C++ engine does.
      DO 48 J = 2, KM
         FCT(1, J) = 1D0/DBLE(2*J - 1)
         FACMIN = SAFE3**FCT(1, J)
         FCT(2, J) = FACMIN/FAC4
         FCT(3, J) = 1D0/FACMIN
         DO 47 L = 2, J
            Q = DBLE(NSEQ(J))/DBLE(NSEQ(J-L+1))
            RSQ(J, L) = Q*Q
   47    CONTINUE
   48 CONTINUE
C
C     ---- Start.
      TSPAN = TOUT(NOUT) - T0
      K = MAX(2, MIN(KM - 1, INT(-LOG10(RTOL + 1D-40)*0.6D0 + 1.5D0)))
      IF (H0 .GT. 0D0) THEN
         H = H0
      ELSE
         H = 0.01D0*TSPAN
      END IF
      IF (HMAX .GT. 0D0) H = MIN(H, HMAX)
      T = T0
      DO 50 I = 1, N
         YW(I) = Y(I)
   50 CONTINUE
      HAVEF0 = .FALSE.
      LASTRJ = .FALSE.
      NNF = 0
C
C     ---- Integrate to each output time in turn.
      DO 200 IOUT = 1, NOUT
C
C        ---- One step (doc steps 1-7); repeat while T < TOUT(IOUT).
  100    CONTINUE
         IF (.NOT. (T .LT. TOUT(IOUT))) GOTO 190
C        1. Step budget.
         IF (NACC + NREJ .GE. MXS) THEN
            IERR = 2
            GOTO 900
         END IF
C        2. Derivative at the start of the step (reused after a
C           rejection).
         IF (.NOT. HAVEF0) THEN
            IE = 0
            CALL FCN(N, T, YW, F0, RPAR, IPAR, IE)
            NFCN = NFCN + 1
            IF (IE .NE. 0) THEN
               IERR = 4
               GOTO 900
            END IF
            HAVEF0 = .TRUE.
         END IF
C        3. Clip the step at the output time; underflow check.
  110    CONTINUE
         HWANT = H
         CLIP = .FALSE.
         IF (T + 1.01D0*H .GE. TOUT(IOUT)) THEN
            H = TOUT(IOUT) - T
            CLIP = .TRUE.
         END IF
         IF (H .LE. 0D0 .OR. H .LT. 1D-14*MAX(ABS(T), TSPAN)) THEN
            IERR = 3
            GOTO 900
         END IF
C        4. Build the extrapolation table and decide.
C        (Rows are grouped except on the retry after a non-finite
C        error estimate: NNF > 0.)
         CALL BSTRY(FCN, N, T, YW, F0, H, K, IEXTR, RTOL, ATOL, NSEQ,
     &              A, FCT, RSQ, RPAR, IPAR, YNEW, HH, W, KC, ACCEPT,
     &              NONFIN, NNF .EQ. 0, NFCN, IE)
         IF (IE .NE. 0) THEN
            IERR = 4
            GOTO 900
         END IF
         IF (NONFIN) THEN
C           Non-finite error estimate: quarter the step, keep k.
            NREJ = NREJ + 1
            NNF = NNF + 1
            LASTRJ = .TRUE.
            IF (NNF .GE. NNFMAX) THEN
               IERR = 5
               GOTO 900
            END IF
            H = 0.25D0*H
            GOTO 110
         END IF
         NNF = 0
C        5. Order proposal.
         CALL BSKOPT(KC, K, KM, W, LASTRJ, KOPT)
         IF (.NOT. ACCEPT) THEN
C           6. Rejected.
            NREJ = NREJ + 1
            K = MIN(KOPT, KC)
            H = MIN(H, HH(K))
            LASTRJ = .TRUE.
            GOTO 100
         END IF
C        7. Accepted.
         NACC = NACC + 1
         IF (CLIP) THEN
            T = TOUT(IOUT)
         ELSE
            T = T + H
         END IF
         DO 120 I = 1, N
            YW(I) = YNEW(I)
  120    CONTINUE
         HAVEF0 = .FALSE.
         IF (KOPT .LE. KC) THEN
            HNEW = HH(KOPT)
         ELSE
            HNEW = HH(KC)*A(KOPT)/A(KC)
            IF (KC .LT. K .AND. KC .GE. 3) THEN
               IF (W(KC) .LT. ORDINC*W(KC-1)) THEN
                  HNEW = HH(KC)*A(KOPT+1)/A(KC)
               END IF
            END IF
         END IF
         IF (LASTRJ) THEN
            KOPT = MIN(KOPT, KC)
            HNEW = MIN(HNEW, H)
         END IF
         K = KOPT
         IF (CLIP) HNEW = MAX(HNEW, HWANT)
         IF (HMAX .GT. 0D0) HNEW = MIN(HNEW, HMAX)
         H = HNEW
         LASTRJ = .FALSE.
         GOTO 100
C
C        ---- Output time reached: record.
  190    CONTINUE
         DO 195 I = 1, N
            YOUT(I, IOUT) = YW(I)
            Y(I) = YW(I)
  195    CONTINUE
  200 CONTINUE
C
  900 CONTINUE
      NSTAT(1) = NFCN
      NSTAT(2) = NACC
      NSTAT(3) = NREJ
      RETURN
      END
C
C=======================================================================
C     BSTRY -- one attempted step of size H from (T, Y) with F0 =
C     f(T, Y): builds rows j = 1..K+1 of the extrapolation table and
C     stops at the column KC where the convergence monitor decides
C     (doc step 4).  FCT and RSQ: the step-invariant factors BSINT
C     computes once (see there).
C     Out: YNEW = T(KC,KC) (the candidate new state), HH(j), W(j)
C     for j = 2..KC, KC, ACCEPT (decision), NONFIN (.TRUE. when an
C     error estimate was not finite: ACCEPT is then .FALSE. and the
C     other outputs are undefined), NFCN incremented by the RHS
C     evaluations made, IERR non-zero when FCN failed.
C=======================================================================
      SUBROUTINE BSTRY(FCN, N, T, Y, F0, H, K, IEXTR, RTOL, ATOL,
     &                 NSEQ, A, FCT, RSQ, RPAR, IPAR, YNEW, HH, W, KC,
     &                 ACCEPT, NONFIN, GROUP, NFCN, IERR)
      INTEGER NMAX, KMAXX
      PARAMETER (NMAX = 64, KMAXX = 12)
      EXTERNAL FCN
      INTEGER N, K, IEXTR, NSEQ(*), IPAR(*), KC, NFCN, IERR
      DOUBLE PRECISION T, Y(N), F0(N), H, RTOL, ATOL(N), A(*),
     &                 FCT(3, KMAXX), RSQ(KMAXX, KMAXX), RPAR(*),
     &                 YNEW(N), HH(*), W(*)
      LOGICAL ACCEPT, NONFIN, GROUP
      DOUBLE PRECISION SAFE1, SAFE2, BIG
      PARAMETER (SAFE1 = 0.65D0, SAFE2 = 0.94D0,
     &           BIG = 1.7976931348623157D308)
      DOUBLE PRECISION TAB(NMAX, KMAXX, KMAXX)
      DOUBLE PRECISION S, SC, Q, ERR, FAC, ERRS(KMAXX)
      INTEGER I, J, JG, JLO
C
      ACCEPT = .FALSE.
      NONFIN = .FALSE.
      IERR = 0
      KC = 0
C     a. Rows 1..JG = max(2, k-1) are needed by every attempt (the
C        first decision comes after row k-1, and none before row 2):
C        their midpoint chains are computed together (BSMGRP).
      JG = 0
      IF (GROUP) JG = MAX(2, K - 1)
      IF (JG .GT. 0) THEN
         CALL BSMGRP(FCN, N, T, Y, F0, H, JG, NSEQ, TAB, RPAR, IPAR,
     &               NFCN, IERR)
         IF (IERR .NE. 0) RETURN
      END IF
      DO 100 J = 1, K + 1
C        a. Modified midpoint rule with n_j substeps: T(j,1).
         IF (J .GT. JG) THEN
            CALL BSMMID(FCN, N, T, Y, F0, H, NSEQ(J), TAB(1, J, 1),
     &                  RPAR, IPAR, NFCN, IERR)
            IF (IERR .NE. 0) RETURN
         END IF
C        b. Extrapolate row j.
         CALL BSXTRP(N, J, IEXTR, RSQ, TAB)
         IF (J .LT. 2) GOTO 100
C        c. Error estimate for column j (its step proposal: e. below).
         S = 0D0
         DO 10 I = 1, N
            SC = ATOL(I) + RTOL*MAX(ABS(Y(I)), ABS(TAB(I, J, J)))
            Q = (TAB(I, J, J) - TAB(I, J, J-1))/SC
            S = S + Q*Q
   10    CONTINUE
         ERR = SQRT(S/DBLE(N))
         IF (.NOT. (ERR .LE. BIG)) THEN
            NONFIN = .TRUE.
            RETURN
         END IF
         ERRS(J) = ERR
C        d. Convergence monitor.
         IF (J .EQ. K - 1) THEN
            KC = J
            IF (ERR .LE. 1D0) THEN
               ACCEPT = .TRUE.
               GOTO 200
            END IF
            IF (ERR .GT. (DBLE(NSEQ(K+1)*NSEQ(K))/4D0)**2) GOTO 200
         ELSE IF (J .EQ. K) THEN
            KC = J
            IF (ERR .LE. 1D0) THEN
               ACCEPT = .TRUE.
               GOTO 200
            END IF
            IF (ERR .GT. (DBLE(NSEQ(K+1))/2D0)**2) GOTO 200
         ELSE IF (J .EQ. K + 1) THEN
            KC = J
            IF (ERR .LE. 1D0) ACCEPT = .TRUE.
            GOTO 200
         END IF
  100 CONTINUE
C
  200 CONTINUE
C     e. Step proposal and work of the columns the order and step-size
C        choice read: KC-1..KC, and KC-2 only when KC = K+1 (BSKOPT);
C        the others would cost a power each and are never used in this
C        step.
C        expo = FCT(1,J), facmin/FAC4 = FCT(2,J), 1/facmin = FCT(3,J).
      JLO = MAX(2, KC - 1)
      IF (KC .GT. K) JLO = MAX(2, KC - 2)
      DO 205 J = JLO, KC
         IF (ERRS(J) .EQ. 0D0) THEN
            FAC = FCT(3, J)
         ELSE
            FAC = SAFE2*(SAFE1/ERRS(J))**FCT(1, J)
         END IF
         FAC = MAX(FCT(2, J), MIN(FCT(3, J), FAC))
         HH(J) = H*FAC
         W(J) = A(J)/HH(J)
  205 CONTINUE
      DO 210 I = 1, N
         YNEW(I) = TAB(I, KC, KC)
  210 CONTINUE
      RETURN
      END
C
C=======================================================================
C     BSMMID -- Gragg's modified midpoint rule with M substeps of size
C     HS = H/M from (T, Y), F0 = f(T, Y), with the final smoothing
C     step (doc step 4a):
C       z0 = y, z1 = z0 + hs f0,
C       z(i+1) = z(i-1) + 2 hs f(t + i hs, z(i)),  i = 1..M-1,
C       TJ1 = 0.5 (z(M) + z(M-1) + hs f(t + H, z(M))).
C     M evaluations of FCN; NFCN counts each call made.  IERR is the
C     status of the first failing call (0 if none).
C=======================================================================
      SUBROUTINE BSMMID(FCN, N, T, Y, F0, H, M, TJ1, RPAR, IPAR,
     &                  NFCN, IERR)
      INTEGER NMAX
      PARAMETER (NMAX = 64)
      EXTERNAL FCN
      INTEGER N, M, IPAR(*), NFCN, IERR
      DOUBLE PRECISION T, Y(N), F0(N), H, TJ1(N), RPAR(*)
      DOUBLE PRECISION Z(NMAX, 2), FZ(NMAX), HS, H2
      INTEGER I, L, IC, IO
C
      IERR = 0
      HS = H/DBLE(M)
C     2D0*HS*FZ(L) is (2D0*HS)*FZ(L): the product 2D0*HS is hoisted.
      H2 = 2D0*HS
C     Z(.,1) holds z(i) for even i, Z(.,2) for odd i: z(i+1) replaces
C     z(i-1) in its column, so the substeps copy nothing.  z(0) = Y is
C     read in place by the first substep (i = 1), which writes z(2).
      DO 10 L = 1, N
         Z(L, 2) = Y(L) + HS*F0(L)
   10 CONTINUE
      IF (M .GT. 1) THEN
         CALL FCN(N, T + DBLE(1)*HS, Z(1, 2), FZ, RPAR, IPAR, IERR)
         NFCN = NFCN + 1
         IF (IERR .NE. 0) RETURN
         DO 15 L = 1, N
            Z(L, 1) = Y(L) + H2*FZ(L)
   15    CONTINUE
      ELSE
C        M = 1: no substep; the smoothing step below needs z(0).
         DO 16 L = 1, N
            Z(L, 1) = Y(L)
   16    CONTINUE
      END IF
      DO 30 I = 2, M - 1
C        IC: column of z(i); IO: column of z(i-1), then of z(i+1).
         IC = MOD(I, 2) + 1
         IO = 3 - IC
         CALL FCN(N, T + DBLE(I)*HS, Z(1, IC), FZ, RPAR, IPAR, IERR)
         NFCN = NFCN + 1
         IF (IERR .NE. 0) RETURN
         DO 20 L = 1, N
            Z(L, IO) = Z(L, IO) + H2*FZ(L)
   20    CONTINUE
   30 CONTINUE
C     Now z(M) is in column IC, z(M-1) in column IO.
      IC = MOD(M, 2) + 1
      IO = 3 - IC
      CALL FCN(N, T + H, Z(1, IC), FZ, RPAR, IPAR, IERR)
      NFCN = NFCN + 1
      IF (IERR .NE. 0) RETURN
      DO 40 L = 1, N
         TJ1(L) = 0.5D0*(Z(L, IC) + Z(L, IO) + HS*FZ(L))
   40 CONTINUE
      RETURN
      END
C
C=======================================================================
C     BSMGRP -- BSMMID for rows 1..JG of one attempt together: substep
C     I of every row that has one (the longest row first), then
C     substep I+1.  Each row does BSMMID's operations in BSMMID's
C     order, so TAB(., j, 1) gets the same bits and NFCN the same sum;
C     only the order of the FCN calls changes: the rows' dependency
C     chains are independent, and interleaved the processor overlaps
C     one row's FCN latency with another's (doc step 4a).
C=======================================================================
      SUBROUTINE BSMGRP(FCN, N, T, Y, F0, H, JG, NSEQ, TAB, RPAR, IPAR,
     &                  NFCN, IERR)
      INTEGER NMAX, KMAXX
      PARAMETER (NMAX = 64, KMAXX = 12)
      EXTERNAL FCN
      INTEGER N, JG, NSEQ(*), IPAR(*), NFCN, IERR
      DOUBLE PRECISION T, Y(N), F0(N), H, TAB(NMAX, KMAXX, KMAXX),
     &                 RPAR(*)
      DOUBLE PRECISION Z(NMAX, 2, KMAXX), FZ(NMAX), HS(KMAXX),
     &                 H2(KMAXX)
      INTEGER I, J, L, M, IC, IO
C
      IERR = 0
      DO 10 J = 1, JG
         HS(J) = H/DBLE(NSEQ(J))
         H2(J) = 2D0*HS(J)
         DO 5 L = 1, N
            Z(L, 2, J) = Y(L) + HS(J)*F0(L)
    5    CONTINUE
   10 CONTINUE
      DO 40 I = 1, NSEQ(JG)
         DO 30 J = JG, 1, -1
            M = NSEQ(J)
C           Rows are ordered by length: once one is done, so are the
C           rest.
            IF (I .GT. M) GOTO 40
            IC = MOD(I, 2) + 1
            IO = 3 - IC
            IF (I .LT. M) THEN
               CALL FCN(N, T + DBLE(I)*HS(J), Z(1, IC, J), FZ, RPAR,
     &                  IPAR, IERR)
               NFCN = NFCN + 1
               IF (IERR .NE. 0) RETURN
               IF (I .EQ. 1) THEN
                  DO 15 L = 1, N
                     Z(L, 1, J) = Y(L) + H2(J)*FZ(L)
   15             CONTINUE
               ELSE
                  DO 20 L = 1, N
                     Z(L, IO, J) = Z(L, IO, J) + H2(J)*FZ(L)
   20             CONTINUE
               END IF
            ELSE
               CALL FCN(N, T + H, Z(1, IC, J), FZ, RPAR, IPAR, IERR)
               NFCN = NFCN + 1
               IF (IERR .NE. 0) RETURN
               DO 25 L = 1, N
                  TAB(L, J, 1) = 0.5D0*(Z(L, IC, J) + Z(L, IO, J)
     &                                  + HS(J)*FZ(L))
   25          CONTINUE
            END IF
   30    CONTINUE
   40 CONTINUE
      RETURN
      END
C
C=======================================================================
C     BSXTRP -- extrapolate row J of the table TAB(i, j, l) (component
C     i, row j, column l) in h**2, columns l = 2..J (doc step 4b),
C     with d = T(j,l-1) - T(j-1,l-1), r = q*q = RSQ(j,l),
C     q = n_j / n_(j-l+1) (RSQ is computed once by BSINT):
C     IEXTR = 2, polynomial (Aitken-Neville):
C        T(j,l) = T(j,l-1) + d/(r - 1)
C     IEXTR = 1, rational (Stoer-Bulirsch), e = T(j,l-1) - T(j-1,l-2)
C        with T(j-1,0) = 0:
C        T(j,l) = T(j,l-1) + d/(r (1 - d/e) - 1),
C        falling back to the polynomial formula when e = 0 or the
C        denominator is 0.
C=======================================================================
      SUBROUTINE BSXTRP(N, J, IEXTR, RSQ, TAB)
      INTEGER NMAX, KMAXX
      PARAMETER (NMAX = 64, KMAXX = 12)
      INTEGER N, J, IEXTR
      DOUBLE PRECISION RSQ(KMAXX, KMAXX), TAB(NMAX, KMAXX, KMAXX)
      DOUBLE PRECISION R, D, E, DEN
      INTEGER I, L
C
      DO 20 L = 2, J
         R = RSQ(J, L)
         DO 10 I = 1, N
            D = TAB(I, J, L-1) - TAB(I, J-1, L-1)
            IF (IEXTR .EQ. 1) THEN
               IF (L .EQ. 2) THEN
                  E = TAB(I, J, L-1)
               ELSE
                  E = TAB(I, J, L-1) - TAB(I, J-1, L-2)
               END IF
               IF (E .NE. 0D0) THEN
                  DEN = R*(1D0 - D/E) - 1D0
                  IF (DEN .NE. 0D0) THEN
                     TAB(I, J, L) = TAB(I, J, L-1) + D/DEN
                     GOTO 10
                  END IF
               END IF
            END IF
            TAB(I, J, L) = TAB(I, J, L-1) + D/(R - 1D0)
   10    CONTINUE
   20 CONTINUE
      RETURN
      END
C
C=======================================================================
C     BSKOPT -- order proposal after an attempt decided in column KC
C     (doc step 5).  K is the current order, KM = kmax, W(j) the work
C     per unit step of column j (j = 2..KC), LASTRJ = the attempt
C     before this one was rejected.  Out: KOPT, 2 <= KOPT <= KM-1.
C=======================================================================
      SUBROUTINE BSKOPT(KC, K, KM, W, LASTRJ, KOPT)
      INTEGER KC, K, KM, KOPT
      DOUBLE PRECISION W(*)
      LOGICAL LASTRJ
      DOUBLE PRECISION ORDDEC, ORDINC
      PARAMETER (ORDDEC = 0.8D0, ORDINC = 0.9D0)
C
      IF (KC .EQ. 2) THEN
         KOPT = MIN(3, KM - 1)
         IF (LASTRJ) KOPT = 2
      ELSE IF (KC .LE. K) THEN
         KOPT = KC
         IF (W(KC-1) .LT. ORDDEC*W(KC)) KOPT = KC - 1
         IF (W(KC) .LT. ORDINC*W(KC-1)) KOPT = MIN(KC + 1, KM - 1)
      ELSE
         KOPT = KC - 1
         IF (KC .GT. 3) THEN
            IF (W(KC-2) .LT. ORDDEC*W(KC-1)) KOPT = KC - 2
         END IF
         IF (W(KC) .LT. ORDINC*W(KOPT)) KOPT = MIN(KC, KM - 1)
      END IF
      RETURN
      END
