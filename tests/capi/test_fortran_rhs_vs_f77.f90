!> A right-hand side written in Fortran, integrated by the C++ Bulirsch-Stoer through
!> `use nanopush`, matches the same problem integrated by the FORTRAN 77 BSINT (fortran/bsint.f)
!> to 1e-12 (relative to each component's largest magnitude). Both run the thesis configuration
!> (rational extrapolation, kmax 8), so they also take the same steps: the counts must agree.
!> Independent check: the Kepler orbit returns to its start after one period 2 pi, and its
!> energy is conserved to the integration tolerance.
program test_fortran_rhs_vs_f77
  use nanopush
  use capi_test_problems
  use, intrinsic :: iso_fortran_env, only: int64
  use test_support, only: check, finish, tol_agree
  implicit none
  real(dp), parameter :: pi = acos(-1.0_dp)
  external :: f77_problem

  call compare_kepler(0.6_dp, 1e-10_dp)
  call compare_kepler(0.9_dp, 1e-12_dp)
  call compare_vdp(5.0_dp, 1e-10_dp)
  call finish("test_fortran_rhs_vs_f77")
  print '(a)', "all checks hold"

contains

  !> Largest deviation of a from b, per component relative to max(|b(i,:)|), over all outputs.
  real(dp) function max_rel_dev(a, b)
    real(dp), intent(in) :: a(:, :), b(:, :)
    integer :: i
    max_rel_dev = 0
    do i = 1, size(a, 1)
      max_rel_dev = max(max_rel_dev, maxval(abs(a(i, :) - b(i, :))) / max(maxval(abs(b(i, :))), tiny(1.0_dp)))
    end do
  end function max_rel_dev

  !> Integrates the problem of dimension size(y0) (parameter mu) from 0 through tout with the
  !> C++ Bulirsch-Stoer (Fortran RHS, nanopush_integrate) and with BSINT: both succeed, agree to
  !> tol_agree and take the same steps. Returns both output tables and final states, the
  !> context the RHS counted in and the C++ counts.
  subroutine both_engines(what, label, mu, y0, tout, rtol, yout, yout77, y, y77, p, counts)
    character(len=*), intent(in) :: what, label
    real(dp), intent(in) :: mu, y0(:), tout(:), rtol
    real(dp), allocatable, intent(out) :: yout(:, :)
    real(dp), intent(out) :: yout77(size(y0), size(tout)), y(size(y0)), y77(size(y0))
    type(ode_params), intent(out) :: p
    integer(int64), intent(out) :: counts(3)
    real(dp) :: atol(size(y0)), rpar(1), dev
    integer :: ipar(1), nstat(3), ierr, stat
    character(len=:), allocatable :: msg
    external :: bsint
    atol = rtol
    p%mu = mu
    y = y0
    call nanopush_integrate(ode_rhs, 0.0_dp, y, tout, yout, rtol=rtol, atol=atol, ctx=p, &
                            counts=counts, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_OK, what // ": nanopush_integrate status 0, got " // msg)
    y77 = y0
    rpar(1) = mu
    ipar(1) = 0
    call bsint(f77_problem, size(y0), 0.0_dp, y77, size(tout), tout, yout77, rtol, atol, 0.0_dp, 0.0_dp, 8, 1, &
               100000, rpar, ipar, nstat, ierr)
    call check(ierr == 0, what // ": BSINT ierr 0")
    dev = max_rel_dev(yout, yout77)
    print '(2a,es8.1,a,es10.3,a,3i8,a,3i8)', label, ", rtol = ", rtol, &
      ": max rel. deviation C++ vs F77 = ", dev, "; counts C++", counts, ", F77", nstat
    call check(dev <= tol_agree, what // ": C++ (Fortran RHS) and F77 agree to 1e-12")
    call check(all(counts == int(nstat, int64)), what // ": same RHS evaluations and steps")
  end subroutine both_engines

  subroutine compare_kepler(e, rtol)
    real(dp), intent(in) :: e, rtol
    integer, parameter :: nout = 41
    real(dp) :: tout(nout), y(4), y77(4), yout77(4, nout), energy0
    real(dp), allocatable :: yout(:, :)
    integer :: k
    integer(int64) :: counts(3)
    type(ode_params) :: p
    character(len=32) :: label
    tout = [(2 * pi * (k - 1) / (nout - 1), k = 1, nout)]
    write (label, '(a,f4.2)') "Kepler e = ", e
    call both_engines("kepler", trim(label), 1.0_dp, kepler_start(e), tout, rtol, yout, yout77, y, y77, p, counts)
    call check(p%evaluations == counts(1), "kepler: the RHS saw every evaluation through ctx")
    call check(all(abs(y - y77) <= tol_agree * max(1.0_dp, abs(y77))), "kepler: final state agrees")
    ! Independent oracles: periodic orbit and conserved energy.
    call check(maxval(abs(yout(:, nout) - kepler_start(e))) <= 1e4 * rtol / (1 - e)**2, &
               "kepler: back to the start after one period")
    energy0 = 0.5_dp * sum(yout(3:4, 1)**2) - 1 / norm2(yout(1:2, 1))
    call check(maxval(abs([(0.5_dp * sum(yout(3:4, k)**2) - 1 / norm2(yout(1:2, k)), k = 1, nout)] &
                          - energy0)) <= 1e3 * rtol / (1 - e), "kepler: energy conserved")
  end subroutine compare_kepler

  subroutine compare_vdp(mu, rtol)
    real(dp), intent(in) :: mu, rtol
    integer, parameter :: nout = 101
    real(dp) :: tout(nout), y(2), y77(2), yout77(2, nout)
    real(dp), allocatable :: yout(:, :)
    integer :: k
    integer(int64) :: counts(3)
    type(ode_params) :: p
    character(len=32) :: label
    tout = [(20.0_dp * (k - 1) / (nout - 1), k = 1, nout)]
    write (label, '(a,f4.1)') "Van der Pol mu = ", mu
    call both_engines("vdp", trim(label), mu, [2.0_dp, 0.0_dp], tout, rtol, yout, yout77, y, y77, p, counts)
  end subroutine compare_vdp

end program test_fortran_rhs_vs_f77

