C=======================================================================
C     SMBAR -- right-hand side of the smooth-surface nanobar
C     (docs/models.md section A; thesis eqs 3.22-3.26 with erratum 1).
C
C     State Y = (X, Y, THETA, VX, VY, OMEGA), SI units, world axes.
C     RPAR(1) = M      mass [kg]
C     RPAR(2) = RI     moment of inertia about the CM [kg m^2]
C     RPAR(3) = F      push magnitude [N]
C     RPAR(4) = BETA   push direction in world axes [rad]
C     RPAR(5) = PBX    push point, body x' [m]
C     RPAR(6) = PBY    push point, body y' [m]
C     RPAR(7) = FX     push force in world axes [N]: F COS(BETA) and
C     RPAR(8) = FY     F SIN(BETA), set by SMBARP from RPAR(3..4);
C                      call SMBARP once before the first SMBAR call
C                      and again whenever RPAR(3) or RPAR(4) changes.
C     The torque about the CM is (R(THETA) PB) x F (z component).
C     IERR is set to 0; the routine cannot fail.
C
C     The push force is constant: SMBARP computes it once per
C     integration instead of once per call (two libm calls saved per
C     right-hand side), with the very operations SMBAR made before, so
C     the results are the same bits.
C=======================================================================
      SUBROUTINE SMBAR(N, T, Y, DYDT, RPAR, IPAR, IERR)
      INTEGER N, IPAR(*), IERR
      DOUBLE PRECISION T, Y(N), DYDT(N), RPAR(*)
      DOUBLE PRECISION C, S, PWX, PWY, FX, FY, TAU
      C = COS(Y(3))
      S = SIN(Y(3))
      PWX = RPAR(5)*C - RPAR(6)*S
      PWY = RPAR(5)*S + RPAR(6)*C
      FX = RPAR(7)
      FY = RPAR(8)
      TAU = PWX*FY - PWY*FX
      DYDT(1) = Y(4)
      DYDT(2) = Y(5)
      DYDT(3) = Y(6)
      DYDT(4) = FX/RPAR(1)
      DYDT(5) = FY/RPAR(1)
      DYDT(6) = TAU/RPAR(2)
      IERR = 0
      RETURN
      END
C
C=======================================================================
C     SMBARP -- set the push force RPAR(7) = FX, RPAR(8) = FY of SMBAR
C     from RPAR(3) = F and RPAR(4) = BETA (RPAR as in SMBAR, 8 values).
C=======================================================================
      SUBROUTINE SMBARP(RPAR)
      DOUBLE PRECISION RPAR(8)
      RPAR(7) = RPAR(3)*COS(RPAR(4))
      RPAR(8) = RPAR(3)*SIN(RPAR(4))
      RETURN
      END
