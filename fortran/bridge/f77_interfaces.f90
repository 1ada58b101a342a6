!> Explicit interfaces of the FORTRAN 77 routines (the fortran directory) that the bridge
!> modules and the Fortran tests call: written once here, used everywhere
!> (`use nanopush_f77_interfaces`). The F77 sources stay period-faithful (no modules); these
!> interfaces let the compiler check every call made to them from modern Fortran.
module nanopush_f77_interfaces
  implicit none
  public

  interface
    !> FORTRAN 77 driver (fortran/bsint.f); argument list documented there.
    subroutine bsint(fcn, n, t0, y, nout, tout, yout, rtol, atol, h0, hmax, kmax, iextr, &
                     maxstp, rpar, ipar, nstat, ierr)
      interface
        subroutine fcn(n, t, y, dydt, rpar, ipar, ierr)
          integer, intent(in) :: n
          double precision, intent(in) :: t
          double precision, intent(in) :: y(n)
          double precision, intent(out) :: dydt(n)
          double precision, intent(in) :: rpar(*)
          integer, intent(inout) :: ipar(*)
          integer, intent(inout) :: ierr
        end subroutine fcn
      end interface
      integer, intent(in) :: n, nout, kmax, iextr, maxstp
      double precision, intent(in) :: t0, tout(*), rtol, atol(*), h0, hmax
      double precision, intent(inout) :: y(*)
      double precision, intent(inout) :: yout(n, *)
      double precision, intent(in) :: rpar(*)
      integer, intent(inout) :: ipar(*)
      integer, intent(out) :: nstat(3), ierr
    end subroutine bsint

    !> FORTRAN 77 smooth-nanobar RHS (fortran/smbar.f).
    subroutine smbar(n, t, y, dydt, rpar, ipar, ierr)
      integer, intent(in) :: n
      double precision, intent(in) :: t
      double precision, intent(in) :: y(n)
      double precision, intent(out) :: dydt(n)
      double precision, intent(in) :: rpar(*)
      integer, intent(inout) :: ipar(*)
      integer, intent(inout) :: ierr
    end subroutine smbar

    !> Sets rpar(7:8), the push force of smbar, from rpar(3:4) (fortran/smbar.f).
    subroutine smbarp(rpar)
      double precision, intent(inout) :: rpar(8)
    end subroutine smbarp
  end interface

  interface
    !> FORTRAN 77 rough-surface nanobar RHS (fortran/rgbar.f).
    subroutine rgbar(n, t, y, dydt, rpar, ipar, ierr)
      integer, intent(in) :: n
      double precision, intent(in) :: t
      double precision, intent(in) :: y(n)
      double precision, intent(out) :: dydt(n)
      double precision, intent(in) :: rpar(*)
      integer, intent(inout) :: ipar(*)
      integer, intent(inout) :: ierr
    end subroutine rgbar
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

    !> FORTRAN 77 iCOR formulas and cubics (fortran/icor.f, fortran/brent.f).
    subroutine icr401(yn, rl, r, ierr)
      double precision, intent(in) :: yn, rl
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine icr401
    subroutine icr402(yn, rl, r, ierr)
      double precision, intent(in) :: yn, rl
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine icr402
    subroutine icr403(yn, rl, r, ierr)
      double precision, intent(in) :: yn, rl
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine icr403
    subroutine icr413(yn, rl, r, ierr)
      double precision, intent(in) :: yn, rl
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine icr413
    subroutine icr505(yn, rk2, r, ierr)
      double precision, intent(in) :: yn, rk2
      double precision, intent(out) :: r
      integer, intent(out) :: ierr
    end subroutine icr505
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
