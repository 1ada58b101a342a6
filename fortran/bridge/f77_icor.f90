!> Bridge to the FORTRAN 77 iCOR routines (fortran/icor.f, fortran/brent.f).
!> Every name is np_f77_icor_*; status codes are those of icor.f (0 = ok, see f77_icor.h).
!> Infinite results (eq 5.5 at yn = 0, the pole of eq 5.2) come back as IEEE infinities
!> with status 0, never as NaN.
module nanopush_f77_icor
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use nanopush_f77_interfaces, only: icr401, icr402, icr403, icr413, icr505, icr407, icr408, icr410, icr411, &
                                     icr502, icrlap, icrbrt
  implicit none
  private
  public :: np_f77_icor_formula, np_f77_icor_force, np_f77_icor_cubic_lapack, np_f77_icor_cubic_brent

  character(len=*), parameter :: prefix = "np_f77_icor_"

  !> Formula selectors for np_f77_icor_formula (keep in step with f77_icor.h).
  integer(c_int), parameter :: eq_4_1 = 1, eq_4_2 = 2, eq_4_3 = 3, eq_4_13 = 13, eq_5_5 = 55

contains

  !> Status 7 of icr505 and icr502 (an infinite result, returned as 0 or +-1 carrying its sign)
  !> as an IEEE infinity of that sign with status 0.
  subroutine infinite_at_pole(v, ierr)
    double precision, intent(inout) :: v
    integer, intent(inout) :: ierr
    if (ierr /= 7) return
    v = sign(ieee_value(v, ieee_positive_inf), v)
    ierr = 0
  end subroutine infinite_at_pole

  !> The results of the cubic solvers icrlap and icrbrt in C kinds.
  subroutine cubic_out(r77, res77, nr, nc, ni, roots, resmax, nreal, ncplx, ninf)
    double precision, intent(in) :: r77(3), res77
    integer, intent(in) :: nr, nc, ni
    real(c_double), intent(out) :: roots(3), resmax
    integer(c_int), intent(out) :: nreal, ncplx, ninf
    roots = real(r77, c_double)
    resmax = real(res77, c_double)
    nreal = int(nr, c_int)
    ncplx = int(nc, c_int)
    ninf = int(ni, c_int)
  end subroutine cubic_out

  !> iCOR distance R [m] from one of the geometric formulas (4.1, 4.2, 4.3, 4.13, 5.5).
  !> which: 1, 2, 3, 13 or 55. yn [m], L [m]; k2 = I/m [m^2] (only for 5.5).
  integer(c_int) function np_f77_icor_formula(which, yn, L, k2, R) bind(C, name=prefix//"formula")
    integer(c_int), value, intent(in) :: which
    real(c_double), value, intent(in) :: yn, L, k2
    real(c_double), intent(out) :: R
    integer :: ierr
    double precision :: r77
    r77 = 0d0
    select case (which)
    case (eq_4_1)
      call icr401(yn, L, r77, ierr)
    case (eq_4_2)
      call icr402(yn, L, r77, ierr)
    case (eq_4_3)
      call icr403(yn, L, r77, ierr)
    case (eq_4_13)
      call icr413(yn, L, r77, ierr)
    case (eq_5_5)
      call icr505(yn, k2, r77, ierr)
      call infinite_at_pole(r77, ierr)
    case default
      ierr = 1
    end select
    R = real(r77, c_double)
    np_f77_icor_formula = int(ierr, c_int)
  end function np_f77_icor_formula

  !> Force relations: which = 407 returns R [m] of eq 4.7 (x = F [N]); 408 returns the
  !> minimum force [N] (x unused); 410 returns F [N] of eq 4.10 (x = R [m]); 411 returns F
  !> of eq 4.11 (x = R [m]); 502 returns F of eq 5.2 (x = R [m], needs k2).
  !> mu [-], W [N], yn [m], L [m], k2 [m^2].
  integer(c_int) function np_f77_icor_force(which, mu, W, yn, L, k2, x, out) &
      bind(C, name=prefix//"force")
    integer(c_int), value, intent(in) :: which
    real(c_double), value, intent(in) :: mu, W, yn, L, k2, x
    real(c_double), intent(out) :: out
    integer :: ierr
    double precision :: v
    v = 0d0
    select case (which)
    case (407)
      call icr407(mu, W, yn, x, L, v, ierr)
    case (408)
      call icr408(mu, W, yn, L, v, ierr)
    case (410)
      call icr410(mu, W, x, L, v, ierr)
    case (411)
      call icr411(mu, W, x, yn, L, v, ierr)
    case (502)
      call icr502(mu, W, x, yn, L, k2, v, ierr)
      call infinite_at_pole(v, ierr)
    case default
      ierr = 1
    end select
    out = real(v, c_double)
    np_f77_icor_force = int(ierr, c_int)
  end function np_f77_icor_force

  !> Roots of the constrained cubic (5.4) from the companion matrix with LAPACK DGEEV.
  !> roots[3]: real roots ascending [m] (first nreal valid); ncplx non-real roots;
  !> ninf roots at infinity; resmax max relative residual of the real roots.
  integer(c_int) function np_f77_icor_cubic_lapack(yn, L, k2, roots, nreal, ncplx, ninf, resmax) &
      bind(C, name=prefix//"cubic_lapack")
    real(c_double), value, intent(in) :: yn, L, k2
    real(c_double), intent(out) :: roots(3), resmax
    integer(c_int), intent(out) :: nreal, ncplx, ninf
    integer :: nr, nc, ni, ierr
    double precision :: r77(3), res77
    call icrlap(yn, L, k2, r77, nr, nc, ni, res77, ierr)
    call cubic_out(r77, res77, nr, nc, ni, roots, resmax, nreal, ncplx, ninf)
    np_f77_icor_cubic_lapack = int(ierr, c_int)
  end function np_f77_icor_cubic_lapack

  !> Real roots of the constrained cubic (5.4) by Brent (ZBRENT) on automatic brackets.
  !> Arguments as np_f77_icor_cubic_lapack, plus niter (total Brent iterations).
  integer(c_int) function np_f77_icor_cubic_brent(yn, L, k2, roots, nreal, ncplx, ninf, resmax, niter) &
      bind(C, name=prefix//"cubic_brent")
    real(c_double), value, intent(in) :: yn, L, k2
    real(c_double), intent(out) :: roots(3), resmax
    integer(c_int), intent(out) :: nreal, ncplx, ninf, niter
    integer :: nr, nc, ni, it, ierr
    double precision :: r77(3), res77
    call icrbrt(yn, L, k2, r77, nr, nc, ni, res77, it, ierr)
    call cubic_out(r77, res77, nr, nc, ni, roots, resmax, nreal, ncplx, ninf)
    niter = int(it, c_int)
    np_f77_icor_cubic_brent = int(ierr, c_int)
  end function np_f77_icor_cubic_brent

end module nanopush_f77_icor
