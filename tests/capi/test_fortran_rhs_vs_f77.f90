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

  subroutine compare_kepler(e, rtol)
    real(dp), intent(in) :: e, rtol
    integer, parameter :: nout = 41
    real(dp) :: tout(nout), y(4), y77(4), yout77(4, nout), atol(4), rpar(1), energy0, dev
    real(dp), allocatable :: yout(:, :)
    integer :: k, ipar(1), nstat(3), ierr, stat
    integer(int64) :: counts(3)
    type(ode_params) :: p
    character(len=:), allocatable :: msg
    external :: bsint
    tout = [(2 * pi * (k - 1) / (nout - 1), k = 1, nout)]
    atol = rtol
    p%mu = 1
    y = kepler_start(e)
    call nanopush_integrate(ode_rhs, 0.0_dp, y, tout, yout, rtol=rtol, atol=atol, ctx=p, &
                            counts=counts, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_OK, "kepler: nanopush_integrate status 0, got " // msg)
    y77 = kepler_start(e)
    rpar(1) = 1
    ipar(1) = 0
    call bsint(f77_problem, 4, 0.0_dp, y77, nout, tout, yout77, rtol, atol, 0.0_dp, 0.0_dp, 8, 1, &
               100000, rpar, ipar, nstat, ierr)
    call check(ierr == 0, "kepler: BSINT ierr 0")
    dev = max_rel_dev(yout, yout77)
    print '(a,f4.2,a,es8.1,a,es10.3,a,3i8,a,3i8)', "Kepler e = ", e, ", rtol = ", rtol, &
      ": max rel. deviation C++ vs F77 = ", dev, "; counts C++", counts, ", F77", nstat
    call check(dev <= tol_agree, "kepler: C++ (Fortran RHS) and F77 agree to 1e-12")
    call check(all(counts == int(nstat, int64)), "kepler: same RHS evaluations and steps")
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
    real(dp) :: tout(nout), y(2), y77(2), yout77(2, nout), atol(2), rpar(1), dev
    real(dp), allocatable :: yout(:, :)
    integer :: k, ipar(1), nstat(3), ierr, stat
    integer(int64) :: counts(3)
    type(ode_params) :: p
    external :: bsint
    tout = [(20.0_dp * (k - 1) / (nout - 1), k = 1, nout)]
    atol = rtol
    p%mu = mu
    y = [2.0_dp, 0.0_dp]
    call nanopush_integrate(ode_rhs, 0.0_dp, y, tout, yout, rtol=rtol, atol=atol, ctx=p, &
                            counts=counts, stat=stat)
    call check(stat == NANOPUSH_OK, "vdp: nanopush_integrate status 0")
    y77 = [2.0_dp, 0.0_dp]
    rpar(1) = mu
    ipar(1) = 0
    call bsint(f77_problem, 2, 0.0_dp, y77, nout, tout, yout77, rtol, atol, 0.0_dp, 0.0_dp, 8, 1, &
               100000, rpar, ipar, nstat, ierr)
    call check(ierr == 0, "vdp: BSINT ierr 0")
    dev = max_rel_dev(yout, yout77)
    print '(a,f4.1,a,es8.1,a,es10.3,a,3i8,a,3i8)', "Van der Pol mu = ", mu, ", rtol = ", rtol, &
      ": max rel. deviation C++ vs F77 = ", dev, "; counts C++", counts, ", F77", nstat
    call check(dev <= tol_agree, "vdp: C++ (Fortran RHS) and F77 agree to 1e-12")
    call check(all(counts == int(nstat, int64)), "vdp: same RHS evaluations and steps")
  end subroutine compare_vdp

end program test_fortran_rhs_vs_f77

