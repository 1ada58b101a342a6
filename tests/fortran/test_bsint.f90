! Tests of the FORTRAN 77 Bulirsch-Stoer driver BSINT (fortran/bsint.f), called directly.
! Oracles: exact solutions (exponential, harmonic oscillator), the oscillator's energy
! invariant, convergence as rtol tightens, and the status table of docs/bulirsch_stoer.md.
module bsint_test_rhs
  implicit none
  private
  public :: rhs, p_exp, p_osc, p_fail, p_nan, p_blowup

  !> The test problems, chosen by ipar(2); ipar(1) counts the calls (to check NFCN).
  integer, parameter :: p_exp = 1     !< y' = lambda y, lambda = rpar(1)
  integer, parameter :: p_osc = 2     !< harmonic oscillator y1' = y2, y2' = -y1
  integer, parameter :: p_fail = 3    !< y' = y until t > rpar(1), then fails with status 7
  integer, parameter :: p_nan = 4     !< NaN derivatives (without failing)
  integer, parameter :: p_blowup = 5  !< y' = y**2, y(0) = 1: y = 1/(1 - t), blows up at t = 1

contains

  !> The derivative of problem ipar(2) (above); counts the call in ipar(1).
  subroutine rhs(n, t, y, dydt, rpar, ipar, ierr)
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    integer, intent(in) :: n
    double precision, intent(in) :: t
    double precision, intent(in) :: y(n)
    double precision, intent(out) :: dydt(n)
    double precision, intent(in) :: rpar(*)
    integer, intent(inout) :: ipar(*)
    integer, intent(inout) :: ierr
    ipar(1) = ipar(1) + 1
    ierr = 0
    select case (ipar(2))
    case (p_exp)
      dydt = rpar(1) * y
    case (p_osc)
      dydt(1) = y(2)
      dydt(2) = -y(1)
    case (p_fail)
      dydt = y
      if (t > rpar(1)) ierr = 7
    case (p_nan)
      dydt = ieee_value(1d0, ieee_quiet_nan)
    case default
      dydt = y * y
    end select
  end subroutine rhs

end module bsint_test_rhs

program test_bsint
  use bsint_test_rhs
  use nanopush_f77_interfaces, only: bsint
  use test_support, only: check, finish
  implicit none

  call test_exponential()
  call test_oscillator()
  call test_convergence()
  call test_bad_input()
  call test_rhs_failure()
  call test_maxstp()
  call test_nonfinite()
  call test_blowup()
  call test_step_limits()

  call finish('test_bsint')
  write (*, '(a)') 'test_bsint: all checks passed'

contains

  !> One BSINT run of problem `kind` from t = 0 through the output times tout at rtol 1e-10, rational
  !> extrapolation, kmax 8: rpar(1) = r1, every atol = atol1, and h0, hmax, maxstp as BSINT takes
  !> them. yout starts at -1 (an output not reached stays so); ipar = (RHS calls, kind).
  subroutine solve(kind, r1, atol1, h0, hmax, maxstp, y, tout, yout, ipar, nstat, ierr)
    integer, intent(in) :: kind, maxstp
    double precision, intent(in) :: r1, atol1, h0, hmax, tout(:)
    double precision, intent(inout) :: y(:)
    double precision, intent(out) :: yout(size(y), size(tout))
    integer, intent(out) :: ipar(2), nstat(3), ierr
    double precision :: atol(size(y)), rpar(1)
    rpar(1) = r1
    atol = atol1
    yout = -1d0
    ipar = [0, kind]
    call bsint(rhs, size(y), 0d0, y, size(tout), tout, yout, 1d-10, atol, h0, hmax, 8, 1, maxstp, &
               rpar, ipar, nstat, ierr)
  end subroutine solve

  !> Counts are consistent: NFCN equals the calls counted by the RHS, at least one accepted
  !> step, and every attempted step costs at least 1 + 2 + 4 evaluations (f0 and two columns).
  subroutine check_counts(nstat, ncalls, what)
    integer, intent(in) :: nstat(3), ncalls
    character(*), intent(in) :: what
    call check(nstat(1) == ncalls, what // ': NFCN = number of RHS calls')
    call check(nstat(2) >= 1, what // ': NACCPT >= 1')
    call check(nstat(3) >= 0, what // ': NREJCT >= 0')
    call check(nstat(1) >= 6 * (nstat(2) + nstat(3)), what // ': NFCN >= 6 per attempted step')
  end subroutine check_counts

  !> y' = y on [0, 1], outputs at 0 (= T0), 0.25, 0.5, 0.5 (repeated), 1; both modes.
  subroutine test_exponential()
    double precision :: y(1), yout(1, 5), tout(5), atol(1), rpar(1), rtol, err
    integer :: ipar(2), nstat(3), ierr, iextr, k
    character(64) :: tag
    tout = [0d0, 0.25d0, 0.5d0, 0.5d0, 1d0]
    rpar(1) = 1d0
    do iextr = 1, 2
      write (tag, '(a, i0)') 'exp, iextr=', iextr
      rtol = 1d-10
      atol = 1d-12
      y = 1d0
      yout = -1d0
      ipar = [0, p_exp]
      call bsint(rhs, 1, 0d0, y, 5, tout, yout, rtol, atol, 0d0, 0d0, 8, iextr, 0, &
                 rpar, ipar, nstat, ierr)
      call check(ierr == 0, trim(tag) // ': status 0')
      call check(yout(1, 1) == 1d0, trim(tag) // ': output at T0 is y0 exactly')
      err = 0d0
      do k = 1, 5
        err = max(err, abs(yout(1, k) - exp(tout(k))) / exp(tout(k)))
      end do
      write (*, '(a, a, es10.3, a, 3i7)') trim(tag), ': max rel err', err, '  nstat', nstat
      call check(err <= 10 * rtol, trim(tag) // ': |y - e^t| <= 10 rtol e^t')
      call check(yout(1, 3) == yout(1, 4), trim(tag) // ': repeated output time')
      call check(y(1) == yout(1, 5), trim(tag) // ': Y returns the last output')
      call check_counts(nstat, ipar(1), trim(tag))
    end do
  end subroutine test_exponential

  !> Harmonic oscillator over [0, 20] with 41 outputs: sin/cos and the energy.
  subroutine test_oscillator()
    integer, parameter :: nout = 41
    double precision :: y(2), yout(2, nout), tout(nout), atol(2), rpar(1), err, eerr
    integer :: ipar(2), nstat(3), ierr, iextr, k
    character(64) :: tag
    do k = 1, nout
      tout(k) = 0.5d0 * (k - 1)
    end do
    rpar = 0d0
    do iextr = 1, 2
      write (tag, '(a, i0)') 'oscillator, iextr=', iextr
      y = [0d0, 1d0]
      atol = 1d-12
      ipar = [0, p_osc]
      call bsint(rhs, 2, 0d0, y, nout, tout, yout, 1d-11, atol, 0d0, 0d0, 8, iextr, 0, &
                 rpar, ipar, nstat, ierr)
      call check(ierr == 0, trim(tag) // ': status 0')
      err = 0d0
      eerr = 0d0
      do k = 1, nout
        err = max(err, abs(yout(1, k) - sin(tout(k))), abs(yout(2, k) - cos(tout(k))))
        eerr = max(eerr, abs(yout(1, k)**2 + yout(2, k)**2 - 1d0))
      end do
      write (*, '(a, a, es10.3, a, es10.3, a, 3i7)') trim(tag), ': max err', err, &
        '  energy err', eerr, '  nstat', nstat
      call check(err <= 1d-9, trim(tag) // ': |y - (sin, cos)| <= 1e-9 over 20 time units')
      call check(eerr <= 2d-9, trim(tag) // ': energy y1^2 + y2^2 = 1 within 2e-9')
      call check_counts(nstat, ipar(1), trim(tag))
    end do
  end subroutine test_oscillator

  !> Error at t = 10 of the oscillator for rtol = 1e-3 ... 1e-13: decreases as rtol tightens
  !> and stays within a fixed multiple of the tolerance (tolerance proportionality).
  subroutine test_convergence()
    integer, parameter :: nr = 6
    double precision :: y(2), yout(2, 1), tout(1), atol(2), rpar(1), rtol, err(nr)
    integer :: ipar(2), nstat(3), ierr, iextr, i, nf(nr)
    character(64) :: tag
    tout = 10d0
    rpar = 0d0
    do iextr = 1, 2
      do i = 1, nr
        rtol = 10d0**(-3 - 2 * (i - 1))
        atol = rtol
        y = [0d0, 1d0]
        ipar = [0, p_osc]
        call bsint(rhs, 2, 0d0, y, 1, tout, yout, rtol, atol, 0d0, 0d0, 8, iextr, 0, &
                   rpar, ipar, nstat, ierr)
        write (tag, '(a, i0, a, es8.1)') 'convergence, iextr=', iextr, ' rtol=', rtol
        call check(ierr == 0, trim(tag) // ': status 0')
        err(i) = max(abs(yout(1, 1) - sin(10d0)), abs(yout(2, 1) - cos(10d0)))
        nf(i) = nstat(1)
        write (*, '(a, a, es10.3, a, 3i7)') trim(tag), ': err', err(i), '  nstat', nstat
        call check(err(i) <= 100 * rtol, trim(tag) // ': err <= 100 rtol')
        if (i > 1) then
          call check(err(i) < err(i - 1), trim(tag) // ': error decreases')
          call check(nf(i) > nf(i - 1), trim(tag) // ': work increases')
        end if
      end do
      call check(err(nr) < 1d-8 * err(1), 'convergence: ten decades of rtol gain >= 8 in error')
    end do
  end subroutine test_convergence

  !> Bad input gives status 1, with zero counts and Y untouched.
  subroutine test_bad_input()
    double precision :: y(2), yout(2, 3), tout(3), atol(2), rpar(1)
    integer :: ipar(2), nstat(3), ierr
    rpar = 0d0
    ipar = [0, p_osc]
    atol = 1d-8
    tout = [0d0, 1d0, 2d0]
    y = [0d0, 1d0]
    ! N = 0
    call bsint(rhs, 0, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: N = 0')
    call check(all(nstat == 0), 'bad input: counts are zero')
    call check(ipar(1) == 0, 'bad input: RHS never called')
    ! N > NMAX (64): the check happens before any array is touched.
    call bsint(rhs, 65, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: N = 65 > NMAX')
    ! KMAX = 2 and KMAX = 13
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 2, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: KMAX = 2')
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 13, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: KMAX = 13')
    ! IEXTR = 3
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 3, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: IEXTR = 3')
    ! decreasing TOUT
    tout = [0d0, 2d0, 1d0]
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: decreasing TOUT')
    ! TOUT(1) before T0
    tout = [0d0, 1d0, 2d0]
    call bsint(rhs, 2, 0.5d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: TOUT(1) < T0')
    ! RTOL < 0
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, -1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: RTOL < 0')
    ! ATOL < 0; RTOL = ATOL = 0
    atol = [1d-8, -1d-8]
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: ATOL < 0')
    atol = [1d-8, 0d0]
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 0d0, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: RTOL = ATOL(2) = 0')
    ! negative H0 / HMAX, negative MAXSTP, NOUT = 0
    atol = 1d-8
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, -1d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: H0 < 0')
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, -1d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: HMAX < 0')
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, -1, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: MAXSTP < 0')
    call bsint(rhs, 2, 0d0, y, 0, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: NOUT = 0')
    ! non-finite initial state
    y(2) = huge(1d0)
    y(2) = y(2) * 2d0
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 8, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 1, 'bad input: Y0 infinite')
    call check(ipar(1) == 0, 'bad input: RHS never called in any case')
    ! KMAX = 0 means the default (8), and kmax = 3 and 12 are allowed.
    y = [0d0, 1d0]
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 0, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 0, 'KMAX = 0 (default) accepted')
    y = [0d0, 1d0]
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 3, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 0 .and. abs(y(1) - sin(2d0)) < 1d-6, 'KMAX = 3 works')
    y = [0d0, 1d0]
    call bsint(rhs, 2, 0d0, y, 3, tout, yout, 1d-8, atol, 0d0, 0d0, 12, 1, 0, &
               rpar, ipar, nstat, ierr)
    call check(ierr == 0 .and. abs(y(1) - sin(2d0)) < 1d-6, 'KMAX = 12 works')
  end subroutine test_bad_input

  !> An FCN returning IERR = 7 gives status 4 at once; outputs before the failure are kept.
  subroutine test_rhs_failure()
    double precision :: y(1), yout(1, 3)
    integer :: ipar(2), nstat(3), ierr
    y = 1d0
    call solve(p_fail, 0.6d0, 1d-12, 0d0, 0d0, 0, y, [0.25d0, 0.5d0, 1d0], yout, ipar, nstat, ierr)  ! fails for t > 0.6
    call check(ierr == 4, 'RHS failure: status 4')
    call check(nstat(1) == ipar(1), 'RHS failure: NFCN counts the failing call')
    call check(abs(yout(1, 2) - exp(0.5d0)) < 1d-8, 'RHS failure: output before it kept')
    call check(yout(1, 3) == -1d0, 'RHS failure: output not reached left unchanged')
    call check(y(1) == yout(1, 2), 'RHS failure: Y = state at the last output reached')
  end subroutine test_rhs_failure

  !> MAXSTP exceeded gives status 2 with exactly MAXSTP attempted steps.
  subroutine test_maxstp()
    double precision :: y(2), yout(2, 1)
    integer :: ipar(2), nstat(3), ierr
    y = [0d0, 1d0]
    call solve(p_osc, 0d0, 1d-10, 0d0, 0d0, 5, y, [100d0], yout, ipar, nstat, ierr)
    call check(ierr == 2, 'MAXSTP: status 2')
    call check(nstat(2) + nstat(3) == 5, 'MAXSTP: exactly MAXSTP attempts made')
  end subroutine test_maxstp

  !> An RHS returning NaN: every error estimate is non-finite. The first attempt computes
  !> rows 1..k-1 = 1..6 together (k = 7 at rtol 1e-10: 2+4+...+12 = 42 evaluations) before
  !> it sees the non-finite estimate at column 2; each retry (quartered step, same f0) goes
  !> row by row and stops at column 2 (2 + 4); the 10th such rejection in a row gives
  !> status 5: nfcn = 1 + 42 + 9 * 6 = 97 (the C++ faithful engine: the same, in
  !> tests/test_bulirsch_stoer.cpp).
  subroutine test_nonfinite()
    double precision :: y(1), yout(1, 1)
    integer :: ipar(2), nstat(3), ierr
    y = 1d0
    call solve(p_nan, 0d0, 1d-10, 0d0, 0d0, 0, y, [1d0], yout, ipar, nstat, ierr)
    call check(ierr == 5, 'non-finite: status 5')
    call check(nstat(2) == 0 .and. nstat(3) == 10, 'non-finite: 10 rejections, no acceptance')
    call check(nstat(1) == 97 .and. ipar(1) == 97, 'non-finite: nfcn = 1 + 42 + 9 * (2 + 4)')
    call check(y(1) == 1d0, 'non-finite: Y untouched')
  end subroutine test_nonfinite

  !> y' = y^2 from y(0) = 1 up to t = 2 crosses the pole at t = 1: the integration must stop
  !> with a failure status (step size underflow or non-finite values) before t = 1, having
  !> recorded the outputs before the pole accurately.
  subroutine test_blowup()
    double precision :: y(1), yout(1, 2)
    integer :: ipar(2), nstat(3), ierr
    y = 1d0
    call solve(p_blowup, 0d0, 1d-12, 0d0, 0d0, 0, y, [0.5d0, 2d0], yout, ipar, nstat, ierr)
    write (*, '(a, i0, a, 3i7)') 'blow-up: status ', ierr, '  nstat', nstat
    call check(ierr == 3 .or. ierr == 5, 'blow-up: status 3 or 5')
    call check(abs(yout(1, 1) - 2d0) < 1d-8, 'blow-up: y(0.5) = 2')
    call check(yout(1, 2) == -1d0, 'blow-up: output past the pole not written')
  end subroutine test_blowup

  !> H0 and HMAX are honoured: with HMAX = 0.01 on [0, 1] at least 100 steps are accepted
  !> and the answer is as accurate; a tiny H0 costs at least the steps to grow out of it
  !> (the step grows by at most 1/facmin = 50**(1/(2k-1)) <= 50 per step).
  subroutine test_step_limits()
    double precision :: y(1), yout(1, 1)
    integer :: ipar(2), nstat(3), ierr
    y = 1d0
    call solve(p_exp, 1d0, 1d-12, 0d0, 1d-2, 0, y, [1d0], yout, ipar, nstat, ierr)
    call check(ierr == 0 .and. nstat(2) >= 100, 'HMAX = 0.01: at least 100 steps on [0, 1]')
    call check(abs(y(1) - exp(1d0)) <= 1d-9 * exp(1d0), 'HMAX = 0.01: accurate')
    y = 1d0
    call solve(p_exp, 1d0, 1d-12, 1d-12, 0d0, 0, y, [1d0], yout, ipar, nstat, ierr)
    call check(ierr == 0 .and. nstat(2) >= 7, 'H0 = 1e-12: at least log50(1e12) = 7 steps')
    call check(abs(y(1) - exp(1d0)) <= 1d-9 * exp(1d0), 'H0 = 1e-12: accurate')
  end subroutine test_step_limits

end program test_bsint
