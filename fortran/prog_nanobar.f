C=======================================================================
C     NANOBAR -- legacy main program: one nanobar pushing case from a
C     classic input deck on standard input, integrated by BSINT
C     (Bulirsch-Stoer, rational extrapolation) with the rough-surface
C     right-hand side RGBAR (MU = 0 gives the smooth surface).
C
C     Usage:  nanobar < case.deck > case.out
C     'nanopush deck SCENE' writes the deck of a scene, so that this
C     program and nanopush run the same case.
C
C     Deck: every data line is preceded by one comment line.
C       title (A72)
C       XN YN                      thesis push coordinates [m]
C       CMX CMY THETA0             initial CM [m] and angle [rad]
C       VX0 VY0 OMEGA0             initial velocities [m/s, rad/s]
C       F BETA FVDW MU G           push [N], direction [rad],
C                                  adhesion [N], friction coef., g
C       RM RI                      mass [kg], inertia [kg m^2]
C       SA SB SC                   width, length, height [m]
C       TEND NOUT RTOL             end time [s], samples, tolerance
C       ATOL(1..8)                 absolute tolerances
C       MAXSTP                     step budget
C       VXR VYR OMR                friction direction at rest (0 0 0:
C                                  none, the thesis law)
C     Output: the caption header of the thesis' figures, then one
C     line per sample: T X Y THETA VX VY OMEGA FX FY MF WPUSH WFRIC
C     (work of the push and of friction) (SI, E25.17 in
C     double, E43.35 in the -freal-8-real-16 build: every digit).
C     A failure prints a message and stops with a non-zero code.
C=======================================================================
      PROGRAM NANOBR
      INTEGER NMAX, NOUTMX
      PARAMETER (NMAX = 8, NOUTMX = 20001)
      CHARACTER*72 TITLE, LINE
      DOUBLE PRECISION XN, YN, CMX, CMY, TH0, VX0, VY0, OM0
      DOUBLE PRECISION F, BETA, FVDW, FMU, G, RM, RI, SA, SB, SC
      DOUBLE PRECISION TEND, RTOL, ATOL(NMAX), Y(NMAX)
      DOUBLE PRECISION RPAR(12), TOUT(NOUTMX), YOUT(NMAX, NOUTMX)
      DOUBLE PRECISION C, S, VBX, VBY, FBX, FBY, FM, FWX, FWY, FN
      INTEGER NOUT, MAXSTP, IPAR(1), NSTAT(3), IERR, I, K, ND
      DOUBLE PRECISION EPS
      CHARACTER*24 FMTROW, FMTHDR
      EXTERNAL RGBAR
C
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, '(A)', ERR=900, END=900) TITLE
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) XN, YN
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) CMX, CMY, TH0
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) VX0, VY0, OM0
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) F, BETA, FVDW, FMU, G
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) RM, RI
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) SA, SB, SC
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) TEND, NOUT, RTOL
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) (ATOL(I), I = 1, NMAX)
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) MAXSTP
      READ (5, '(A)', ERR=900, END=900) LINE
      READ (5, *, ERR=900, END=900) RPAR(10), RPAR(11), RPAR(12)
      IF (NOUT .LT. 2 .OR. NOUT .GT. NOUTMX) THEN
         WRITE (6, '(A,I10,A,I7,A)') ' NANOBAR: NOUT =', NOUT,
     &      ' must be in [2,', NOUTMX, ']'
         STOP 1
      END IF
C
C     Digits enough to read every bit back: 17 in double precision, 35
C     when built with -freal-8-real-16 (nanobar_quad, the extended-
C     precision reference). EPS is found the classic way.
      EPS = 1D0
    5 CONTINUE
      IF (1D0 + 0.5D0*EPS .GT. 1D0) THEN
         EPS = 0.5D0*EPS
         GOTO 5
      END IF
      ND = INT(-LOG10(EPS)) + 2
      WRITE (FMTROW, '(A,I2,A,I2,A)') '(12E', ND + 8, '.', ND, ')'
      WRITE (FMTHDR, '(A,I2,A)') '(12A', ND + 8, ')'
C
C     Caption header, as printed under the thesis' figures.
      WRITE (6, '(A)') TITLE
      WRITE (6, 100) XN, YN, CMX, CMY, TH0, VX0, VY0, OM0, F, FVDW,
     &               FMU, RM, SA, SB, SC
  100 FORMAT (' Coordinates of Application Force: Xn=', E13.6,
     &   '[m] Yn=', E13.6, '[m].'/
     &   ' Initial Coordinates of C.M: CMx=', E9.2, '[m] CMy=', E9.2,
     &   '[m].'/' Initial orientation: Angle=', E13.6, '[rad].'/
     &   ' Initial velocity in x: Vx=', E13.6, '[m/s].'/
     &   ' Initial velocity in y: Vy=', E13.6, '[m/s].'/
     &   ' Initial angular velocity: wo =', E13.6, '[rad/s].'/
     &   ' Pulling/Pushing Force Applied: F=', E13.6, '[N].'/
     &   ' Adhesion Force (VdW): Fvdw=', E13.6, '[N].'/
     &   ' Coefficient Friction: mu=', E13.6, ' .'/
     &   ' Object mass: m=', E13.6, '[kg].'/
     &   ' Object dimensions: sa=', E13.6, '[m] sb=', E13.6,
     &   '[m] sc=', E13.6, '[m].')
C
C     Thesis mapping: body push point (XN, -YN); N = M G + FVDW.
      FN = RM*G + FVDW
      RPAR(1) = RM
      RPAR(2) = RI
      RPAR(3) = F
      RPAR(4) = BETA
      RPAR(5) = XN
      RPAR(6) = -YN
      RPAR(7) = 0.5D0*SA
      RPAR(8) = 0.5D0*SB
      RPAR(9) = FMU*FN
      Y(1) = CMX
      Y(2) = CMY
      Y(3) = TH0
      Y(4) = VX0
      Y(5) = VY0
      Y(6) = OM0
      Y(7) = 0D0
      Y(8) = 0D0
      DO 10 K = 1, NOUT
         TOUT(K) = TEND*DBLE(K - 1)/DBLE(NOUT - 1)
   10 CONTINUE
      TOUT(NOUT) = TEND
      DO 20 K = 1, NOUT
         DO 15 I = 1, NMAX
            YOUT(I, K) = 0D0
   15    CONTINUE
   20 CONTINUE
      IPAR(1) = 0
      CALL BSINT(RGBAR, NMAX, 0D0, Y, NOUT, TOUT, YOUT, RTOL, ATOL,
     &           0D0, 0D0, 8, 1, MAXSTP, RPAR, IPAR, NSTAT, IERR)
      WRITE (6, 110) NSTAT(1), NSTAT(2), NSTAT(3)
  110 FORMAT (' RHS evaluations', I10, ', accepted steps', I8,
     &        ', rejected steps', I8)
      WRITE (6, FMTHDR) 'T [s]', 'X [m]', 'Y [m]', 'THETA [rad]',
     &   'VX [m/s]', 'VY [m/s]', 'OMEGA [rad/s]', 'FX [N]', 'FY [N]',
     &   'MF [N m]', 'WPUSH [J]', 'WFRIC [J]'
      DO 30 K = 1, NOUT
         IF (IERR .NE. 0 .AND. TOUT(K) .GT. 0D0 .AND.
     &       YOUT(1, K) .EQ. 0D0 .AND. YOUT(3, K) .EQ. 0D0) GOTO 40
         C = COS(YOUT(3, K))
         S = SIN(YOUT(3, K))
         FWX = 0D0
         FWY = 0D0
         FM = 0D0
         IF (RPAR(9) .NE. 0D0 .AND. (YOUT(4, K) .NE. 0D0 .OR.
     &       YOUT(5, K) .NE. 0D0 .OR. YOUT(6, K) .NE. 0D0)) THEN
            VBX = C*YOUT(4, K) + S*YOUT(5, K)
            VBY = -S*YOUT(4, K) + C*YOUT(5, K)
            CALL RECTFV(RPAR(7), RPAR(8), RPAR(9), VBX, VBY,
     &                  YOUT(6, K), FBX, FBY, FM, I)
            FWX = C*FBX - S*FBY
            FWY = S*FBX + C*FBY
         END IF
         WRITE (6, FMTROW) TOUT(K), (YOUT(I, K), I = 1, 6),
     &      FWX, FWY, FM, YOUT(7, K), YOUT(8, K)
   30 CONTINUE
   40 CONTINUE
      IF (IERR .NE. 0) THEN
         WRITE (6, '(A,I3)') ' NANOBAR: BSINT failed with status', IERR
         STOP 3
      END IF
      STOP
  900 WRITE (6, '(A)') ' NANOBAR: cannot read the input deck'
      STOP 2
      END
