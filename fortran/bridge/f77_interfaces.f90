!> Explicit interfaces of the FORTRAN 77 routines (the fortran directory) that the bridge
!> modules and the Fortran tests call: written once here, used everywhere
!> (`use nanopush_f77_interfaces`). The F77 sources stay period-faithful (no modules); these
!> interfaces let the compiler check every call made to them from modern Fortran.
module nanopush_f77_interfaces
  implicit none
  public

  abstract interface
    !> A derivative routine BSINT calls (EXTERNAL fcn of fortran/bsint.f): dydt = f(t, y), rpar
    !> and ipar passed through, ierr /= 0 stops the integration.
    subroutine f77_rhs(n, t, y, dydt, rpar, ipar, ierr)
      integer, intent(in) :: n
      double precision, intent(in) :: t
      double precision, intent(in) :: y(n)
      double precision, intent(out) :: dydt(n)
      double precision, intent(in) :: rpar(*)
      integer, intent(inout) :: ipar(*)
      integer, intent(inout) :: ierr
    end subroutine f77_rhs

    !> An iCOR formula of fortran/icor.f: r from the push point yn and one rod parameter p
    !> (its length, or k^2 for icr505).
    subroutine f77_icor_formula(yn, p, r, ierr)
      double precision, intent(in) :: yn, p
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine f77_icor_formula
  end interface

  !> FORTRAN 77 smooth-nanobar RHS (fortran/smbar.f) and rough-surface nanobar RHS (fortran/rgbar.f).
  procedure(f77_rhs) :: smbar, rgbar
  !> FORTRAN 77 iCOR formulas (fortran/icor.f): eqs 4.1, 4.2, 4.3, 4.13 (rl = L) and 5.5 (rk2 = k^2).
  procedure(f77_icor_formula) :: icr401, icr402, icr403, icr413, icr505

  interface
    !> FORTRAN 77 driver (fortran/bsint.f); argument list documented there.
    subroutine bsint(fcn, n, t0, y, nout, tout, yout, rtol, atol, h0, hmax, kmax, iextr, &
                     maxstp, rpar, ipar, nstat, ierr)
      import :: f77_rhs
      procedure(f77_rhs) :: fcn
      integer, intent(in) :: n, nout, kmax, iextr, maxstp
      double precision, intent(in) :: t0, tout(*), rtol, atol(*), h0, hmax
      double precision, intent(inout) :: y(*)
      double precision, intent(inout) :: yout(n, *)
      double precision, intent(in) :: rpar(*)
      integer, intent(inout) :: ipar(*)
      integer, intent(out) :: nstat(3), ierr
    end subroutine bsint

    !> Sets rpar(7:8), the push force of smbar, from rpar(3:4) (fortran/smbar.f).
    subroutine smbarp(rpar)
      double precision, intent(inout) :: rpar(8)
    end subroutine smbarp
  end interface

  !> FORTRAN 77 rolling formulas (fortran/rolling.f).
  interface
    subroutine rlfs(f, h, r, fs, ierr)
      double precision, intent(in) :: f, h, r
      double precision, intent(out) :: fs
      integer, intent(out) :: ierr
    end subroutine rlfs
    subroutine rlres(w, ak, r, fs, ierr)
      double precision, intent(in) :: w, ak, r
      double precision, intent(out) :: fs
      integer, intent(out) :: ierr
    end subroutine rlres
    subroutine rlmin(w, ak, r, amarg, f, ierr)
      double precision, intent(in) :: w, ak, r, amarg
      double precision, intent(out) :: f
      integer, intent(out) :: ierr
    end subroutine rlmin
    subroutine rldec(f, h, r, amu, ans, wr, ak, mode, froll, fslid, fsreq, ierr)
      double precision, intent(in) :: f, h, r, amu, ans, wr, ak
      integer, intent(out) :: mode
      double precision, intent(out) :: froll, fslid, fsreq
      integer, intent(out) :: ierr
    end subroutine rldec
    subroutine rlvdw(ah, al, d, z0, fv, ierr)
      double precision, intent(in) :: ah, al, d, z0
      double precision, intent(out) :: fv
      integer, intent(out) :: ierr
    end subroutine rlvdw
    subroutine rljkrl(r, es, w, p, b, ierr)
      double precision, intent(in) :: r, es, w, p
      double precision, intent(out) :: b
      integer, intent(out) :: ierr
    end subroutine rljkrl

    !> FORTRAN 77 rectangle friction wrench (fortran/rectfr.f): by iCOR and by velocity.
    subroutine rectfr(a, b, fmun, r, alpha, isense, fx, fy, fm, ierr)
      double precision, intent(in) :: a, b, fmun, r, alpha
      integer, intent(in) :: isense
      double precision, intent(out) :: fx, fy, fm
      integer, intent(out) :: ierr
    end subroutine rectfr
    subroutine rectfv(a, b, fmun, vx, vy, omega, fx, fy, fm, ierr)
      double precision, intent(in) :: a, b, fmun, vx, vy, omega
      double precision, intent(out) :: fx, fy, fm
      integer, intent(out) :: ierr
    end subroutine rectfv

    !> FORTRAN 77 iCOR formulas and cubics (fortran/icor.f, fortran/brent.f); the formulas of one
    !> rod parameter are declared above (f77_icor_formula).
    subroutine icr407(rmu, w, yn, f, rl, r, ierr)
      double precision, intent(in) :: rmu, w, yn, f, rl
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine icr407
    subroutine icr408(rmu, w, yn, rl, f, ierr)
      double precision, intent(in) :: rmu, w, yn, rl
      double precision, intent(out) :: f
      integer, intent(out) :: ierr
    end subroutine icr408
    subroutine icr410(rmu, w, r, rl, f, ierr)
      double precision, intent(in) :: rmu, w, r, rl
      double precision, intent(out) :: f
      integer, intent(out) :: ierr
    end subroutine icr410
    subroutine icr411(rmu, w, r, yn, rl, f, ierr)
      double precision, intent(in) :: rmu, w, r, yn, rl
      double precision, intent(out) :: f
      integer, intent(out) :: ierr
    end subroutine icr411
    subroutine icr502(rmu, w, r, yn, rl, rk2, f, ierr)
      double precision, intent(in) :: rmu, w, r, yn, rl, rk2
      double precision, intent(out) :: f
      integer, intent(out) :: ierr
    end subroutine icr502
    subroutine icrlap(yn, rl, rk2, roots, nreal, ncplx, ninf, resmax, ierr)
      double precision, intent(in) :: yn, rl, rk2
      double precision, intent(out) :: roots(3), resmax
      integer, intent(out) :: nreal, ncplx, ninf, ierr
    end subroutine icrlap
    subroutine icrbrt(yn, rl, rk2, roots, nreal, ncplx, ninf, resmax, niter, ierr)
      double precision, intent(in) :: yn, rl, rk2
      double precision, intent(out) :: roots(3), resmax
      integer, intent(out) :: nreal, ncplx, ninf, niter, ierr
    end subroutine icrbrt
  end interface

end module nanopush_f77_interfaces
