!> FORTRAN side of issue 5: the F77 iCOR routines called directly (no bridge), and the
!> bridge called as C would call it. Table 5.1 rows at yn = 0, 1 nm and 295 nm, bad input,
!> and Brent against LAPACK.
program test_icor
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use nanopush_f77_icor, only: np_f77_icor_cubic_lapack
  use test_support, only: check, finish, tol_agree
  implicit none
  external :: icrlap, icrbrt, icr413
  double precision, parameter :: rl = 590d-9, rk2 = rl*rl/12d0, b = 0.5d0*rl
  double precision :: rl3(3), rb3(3), res, r
  integer :: nr, nc, ni, it, ierr, nr2, nc2, ni2, i
  real(c_double) :: croots(3), cres
  integer(c_int) :: cnr, cnc, cni, st

  ! yn = 0: +-b/3, one root at infinity, both solvers.
  call icrlap(0d0, rl, rk2, rl3, nr, nc, ni, res, ierr)
  call check(ierr == 0 .and. nr == 2 .and. ni == 1, "LAPACK yn = 0: two real roots, one at infinity")
  call check(abs(rl3(2) - b/3d0) <= 4d0*epsilon(1d0)*b, "LAPACK yn = 0: +b/3")
  call icrbrt(0d0, rl, rk2, rb3, nr, nc, ni, res, it, ierr)
  call check(ierr == 0 .and. nr == 2 .and. ni == 1, "Brent yn = 0: two real roots, one at infinity")
  call check(abs(rb3(1) + b/3d0) <= 4d0*epsilon(1d0)*b, "Brent yn = 0: -b/3")

  ! yn = 1 nm (erratum 9) and 295 nm: Brent and LAPACK agree to 1e-12.
  do i = 1, 2
    if (i == 1) then
      call icrlap(1d-9, rl, rk2, rl3, nr, nc, ni, res, ierr)
      call icrbrt(1d-9, rl, rk2, rb3, nr2, nc2, ni2, res, it, ierr)
    else
      call icrlap(295d-9, rl, rk2, rl3, nr, nc, ni, res, ierr)
      call icrbrt(295d-9, rl, rk2, rb3, nr2, nc2, ni2, res, it, ierr)
    end if
    call check(ierr == 0 .and. nr == nr2 .and. nc == nc2 .and. ni == ni2, "same root counts")
    call check(all(abs(rl3(1:nr) - rb3(1:nr)) <= tol_agree*abs(rb3(1:nr))), "Brent = LAPACK to 1e-12")
    call check(res <= 1d-12, "residual <= 1e-12")
  end do
  call check(nr == 1 .and. abs(rl3(1) + 7.930032d-8) < 1d-13, "yn = 295 nm: -7.930032e-8 (Table 5.1: 7.93e-8)")

  ! Bad input: status 1, never STOP.
  call icrlap(-1d-9, rl, rk2, rl3, nr, nc, ni, res, ierr)
  call check(ierr == 1, "yn < 0 rejected (LAPACK)")
  call icrbrt(1d-9, 0d0, rk2, rb3, nr, nc, ni, res, it, ierr)
  call check(ierr == 1, "L = 0 rejected (Brent)")
  call icr413(1d-9, -1d0, r, ierr)
  call check(ierr == 1, "L < 0 rejected (4.13)")

  ! Through the bridge.
  st = np_f77_icor_cubic_lapack(1d-9, rl, rk2, croots, cnr, cnc, cni, cres)
  call check(st == 0 .and. cnr == 3 .and. abs(croots(2) - 9.8444759457197367d-8) < 1d-20, &
             "bridge: positive branch at yn = 1 nm")
  call finish("test_icor")
  print '(a)', "test_icor: all checks passed"

end program test_icor
