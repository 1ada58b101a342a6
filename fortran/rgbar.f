C=======================================================================
C     RGBAR -- right-hand side of the nanobar sliding on a rough
C     surface (docs/models.md section C; thesis eqs 3.51-3.56 with errata
C     1-3): the smooth-surface equations plus the Coulomb friction
C     resultant over the 2A x 2B contact (RECTFV, fortran/rectfr.f)
C     at the iCOR implied by the rigid velocity, rotated to world axes.
C     This is the 'thesis' friction law: no stick handling.
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
         CALL RECTFV(RPAR(7), RPAR(8), RPAR(9), VBX, VBY, OM,
     &               FBX, FBY, FM, IERR)
         IF (IERR .NE. 0) RETURN
         FWX = C*FBX - S*FBY
         FWY = S*FBX + C*FBY
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
