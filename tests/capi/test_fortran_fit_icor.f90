!> nanopush_estimate_mu_batch through `use nanopush`: one observation is
!> nanopush_estimate_mu_from_icor / _from_force bit for bit, N identical ones shrink sigma by
!> sqrt(N), pushes on the line-contact model (eqs 4.8, 4.13) give back their mu for both pressure
!> distributions, and bad input comes back as stat + errmsg naming the row (or the array).
program test_fortran_fit_icor
  use nanopush
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
  use test_support, only: check, finish, tol_round_trip
  implicit none
  ! The program in a block: its allocatables are freed at the block's end (a main program's
  ! are saved), so LeakSanitizer checks the library, not the program.
  block
    integer :: stat, i
    real(dp) :: rod(6), W, L, b, mu, sigma, mu1, s1, sstat, chi, p
    real(dp) :: F(4), sF(4), yn(4), sy(4), R(4), sR(4)
    real(dp), allocatable :: row_mu(:), row_w(:)
    integer, allocatable :: eq(:)
    logical :: ok
    character(len=:), allocatable :: msg

    rod = nanopush_icor_nanorod()
    call nanopush_icor_rod_properties(rod, load=W)
    L = rod(1)
    b = 0.5_dp * L

    ! One observation = the one-observation estimates, bit for bit.
    call nanopush_estimate_mu_from_icor(rod, 1e-6_dp, 3e-8_dp, 150e-9_dp, 4e-9_dp, mu1, s1)
    call nanopush_estimate_mu_batch(rod, [1e-6_dp], [3e-8_dp], NANOPUSH_PRESSURE_KNOWN, mu, sigma, &
                                    R=[150e-9_dp], sigma_R=[4e-9_dp], chi2_dof=chi, stat=stat)
    call check(stat == NANOPUSH_OK .and. mu == mu1 .and. sigma == s1 .and. ieee_is_nan(chi), &
               "one observation = nanopush_estimate_mu_from_icor")
    call nanopush_estimate_mu_from_force(rod, 1e-6_dp, 3e-8_dp, 200e-9_dp, 5e-9_dp, mu1, s1)
    call nanopush_estimate_mu_batch(rod, [1e-6_dp], [3e-8_dp], NANOPUSH_PRESSURE_UNKNOWN, mu, sigma, &
                                    yn=[200e-9_dp], sigma_yn=[5e-9_dp], stat=stat)
    call check(stat == NANOPUSH_OK .and. mu == mu1 .and. sigma == s1, "one observation = nanopush_estimate_mu_from_force")

    ! Nine identical observations: same mu, sigma / 3.
    call nanopush_estimate_mu_batch(rod, spread(1e-6_dp, 1, 9), spread(3e-8_dp, 1, 9), NANOPUSH_PRESSURE_KNOWN, mu, &
                                    sigma, yn=spread(200e-9_dp, 1, 9), sigma_yn=spread(5e-9_dp, 1, 9), stat=stat)
    call check(stat == NANOPUSH_OK .and. mu == mu1 .and. abs(sigma - s1 / 3) <= 1e-14_dp * s1, "sqrt(N) shrinking")

    ! Pushes on the line-contact model with mu = 0.2: iCOR of eq 4.13, minimum force of eq 4.8.
    yn = [50e-9_dp, 120e-9_dp, 200e-9_dp, 280e-9_dp]
    do i = 1, 4
      R(i) = nanopush_icor_unknown_pressure(yn(i), L)
      F(i) = nanopush_icor_minimum_force(0.2_dp, W, yn(i), L)
    end do
    sF = 0.02_dp * F
    sy = 2e-9_dp
    sR = 3e-9_dp
    call nanopush_estimate_mu_batch(rod, F, sF, NANOPUSH_PRESSURE_KNOWN, mu, sigma, yn=yn, sigma_yn=sy, R=R, &
                                    sigma_R=sR, sigma_stat=sstat, p_value=p, consistent=ok, row_mu=row_mu, &
                                    row_weight=row_w, equations=eq, stat=stat)
    call check(stat == NANOPUSH_OK .and. abs(mu - 0.2_dp) < tol_round_trip, "known: mu = 0.2")
    call check(sstat == sigma .and. ok .and. p > 0.99_dp, "known: consistent, no systematic part")
    call check(size(row_mu) == 4 .and. all(abs(row_mu - 0.2_dp) < tol_round_trip), "known: every row 0.2")
    call check(abs(sum(row_w) - 1) < 1e-14_dp .and. all(eq == 10), "known: weights sum to 1, eq 4.10")
    call nanopush_estimate_mu_batch(rod, F, sF, NANOPUSH_PRESSURE_UNKNOWN, mu, sigma, yn=yn, sigma_yn=sy, R=R, &
                                    sigma_R=sR, sigma_H=2e-20_dp, sigma_stat=sstat, equations=eq, stat=stat)
    call check(stat == NANOPUSH_OK .and. abs(mu - 0.2_dp) < tol_round_trip .and. all(eq == 11), "unknown: mu = 0.2, eq 4.11")
    call check(sigma > sstat, "unknown: the Hamaker sigma adds a systematic part")

    ! Bad input: stat + errmsg naming the row; NaN outputs; arrays of size 0.
    R(3) = ieee_value(0.0_dp, ieee_quiet_nan)
    yn(3) = ieee_value(0.0_dp, ieee_quiet_nan)
    call nanopush_estimate_mu_batch(rod, F, sF, NANOPUSH_PRESSURE_KNOWN, mu, sigma, yn=yn, sigma_yn=sy, R=R, &
                                    sigma_R=sR, row_mu=row_mu, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "row 3: yn/R = neither given") == 1, "row 3: " // msg)
    call check(ieee_is_nan(mu) .and. ieee_is_nan(sigma) .and. size(row_mu) == 0, "failure: NaN, empty arrays")
    call nanopush_estimate_mu_batch(rod, F, sF(1:3), NANOPUSH_PRESSURE_KNOWN, mu, sigma, R=R, sigma_R=sR, stat=stat, &
                                    errmsg=msg)
    call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "sigma_force: size does not match size(force) = 4") == 1, &
               "sizes: " // msg)
    call nanopush_estimate_mu_batch(rod, F, sF, NANOPUSH_PRESSURE_KNOWN, mu, sigma, R=R, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "R/sigma_R") == 1, "R without sigma_R: " // msg)

    call finish("test_fortran_fit_icor")
    print '(a)', "fortran fit-icor: all checks hold"
  end block

contains

end program test_fortran_fit_icor
