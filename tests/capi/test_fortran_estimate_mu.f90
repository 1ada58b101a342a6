!> The friction coefficient estimates through `use nanopush` give the numbers of
!> `nanopush icor estimate-mu` exactly (its CSV holds 17 significant digits, so reading it back
!> gives the same doubles), and bad input comes back as stat + errmsg naming the quantity.
!> Usage: capi_test_estimate_mu_fortran OUT.csv MODE F SIGMA_F X SIGMA_X SIGMA_L SIGMA_H [ROD...]
!>   OUT.csv  `nanopush icor estimate-mu ... --out OUT.csv` run with the same numbers
!>   MODE     yn (--yn X --yn-sigma SIGMA_X, Fig 4.4) or icor (--icor X --icor-sigma SIGMA_X, Fig 4.5)
!>   ROD      six values L radius density H z0 g (--length --radius --density --hamaker --z0
!>            --gravity); default: the thesis nanorod (the CLI's defaults)
!> The numbers are given as the same decimal strings to both programs (both read them correctly
!> rounded).
program test_fortran_estimate_mu
  use nanopush
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use test_support, only: check, finish, same, argument, open_csv, field, fields
  implicit none
  integer :: i
  real(dp) :: rod(6), F, sF, x, sx, sL, sH
  character(len=:), allocatable :: mode, arg

  if (command_argument_count() /= 8 .and. command_argument_count() /= 14) &
    error stop "usage: capi_test_estimate_mu_fortran OUT.csv MODE F SIGMA_F X SIGMA_X SIGMA_L SIGMA_H [ROD(6)]"
  mode = argument(2)
  F = number(3)
  sF = number(4)
  x = number(5)
  sx = number(6)
  sL = number(7)
  sH = number(8)
  rod = nanopush_icor_nanorod()
  if (command_argument_count() == 14) then
    do i = 1, 6
      rod(i) = number(8 + i)
    end do
  end if
  call check(mode == "yn" .or. mode == "icor", "MODE is yn or icor")

  call compare_cli(argument(1))
  call defaults_and_optional_outputs()
  call bad_input()

  call finish("test_fortran_estimate_mu")
  print '(a)', "Fortran estimate_mu (" // mode // "): identical to nanopush icor estimate-mu"

  if (allocated(mode)) deallocate(mode)
  if (allocated(arg)) deallocate(arg)

contains

  !> One estimate with every output: from the iCOR R = x_ (from_icor) or the force at yn = x_.
  subroutine estimate(from_icor, r, F_, sF_, x_, sx_, sL_, sH_, mu, sigma, load, d, stat, errmsg)
    logical, intent(in) :: from_icor
    real(dp), intent(in) :: r(6), F_, sF_, x_, sx_, sL_, sH_
    real(dp), intent(out) :: mu, sigma, load, d(4)
    integer, intent(out) :: stat
    character(len=:), allocatable, intent(out) :: errmsg
    if (from_icor) then
      call nanopush_estimate_mu_from_icor(r, F_, sF_, x_, sx_, mu, sigma, sigma_L=sL_, sigma_H=sH_, load=load, &
                                          derivatives=d, stat=stat, errmsg=errmsg)
    else
      call nanopush_estimate_mu_from_force(r, F_, sF_, x_, sx_, mu, sigma, sigma_L=sL_, sigma_H=sH_, load=load, &
                                           derivatives=d, stat=stat, errmsg=errmsg)
    end if
  end subroutine estimate

  !> input,value,sigma,dmu_dinput,contribution: rows mu, W, F, yn|R, L, H.
  subroutine compare_cli(path)
    character(len=*), intent(in) :: path
    character(len=4096) :: line
    character(len=:), allocatable :: name, msg
    real(dp) :: mu, sigma, load, d(4), c(4), want_value, want_sigma, deriv
    integer :: unit, ios, stat, rows, k
    call estimate(mode == "icor", rod, F, sF, x, sx, sL, sH, mu, sigma, load, d, stat, msg)
    call check(stat == NANOPUSH_OK, "estimate: stat = NANOPUSH_OK (" // msg // ")")
    unit = open_csv(path, "input,value,sigma,dmu_dinput,contribution", "CLI CSV: header")
    rows = 0
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      rows = rows + 1
      name = field(line, 1)
      call fields(line, c, first=2)
      select case (name)
      case ("mu")
        call same(mu, c(1), "mu")
        call same(sigma, c(2), "sigma")
      case ("W")
        call same(load, c(1), "load W")
      case default
        k = 0
        if (name == "F") then
          k = 1
          want_value = F
          want_sigma = sF
        else if ((name == "yn" .and. mode == "yn") .or. (name == "R" .and. mode == "icor")) then
          k = 2
          want_value = x
          want_sigma = sx
        else if (name == "L") then
          k = 3
          want_value = rod(1)
          want_sigma = sL
        else if (name == "H") then
          k = 4
          want_value = rod(4)
          want_sigma = sH
        end if
        call check(k > 0, "CLI CSV: unexpected row '" // name // "'")
        if (k == 0) cycle
        deriv = d(k)
        call same(want_value, c(1), "value of " // name // " (the CLI read the same input)")
        call same(want_sigma, c(2), "sigma of " // name // " (the CLI read the same input)")
        call same(deriv, c(3), "dmu/d" // name)
        call same(abs(deriv) * want_sigma, c(4), "|dmu/d" // name // "| sigma_" // name)
      end select
    end do
    close (unit)
    call check(rows == 6, "CLI CSV: 6 rows (mu, W, F, yn or R, L, H)")
    print '(a,es24.17,a,es24.17,a)', "mu = ", mu, " +- ", sigma, " (= the CLI)"
  end subroutine compare_cli

  !> sigma_L and sigma_H default to 0; load, derivatives, stat and errmsg may be omitted.
  subroutine defaults_and_optional_outputs()
    real(dp) :: mu0, s0, w0, d0(4), mu, s, w, d(4)
    integer :: stat
    if (mode == "yn") then
      call nanopush_estimate_mu_from_force(rod, F, sF, x, sx, mu0, s0, sigma_L=0.0_dp, sigma_H=0.0_dp, load=w0, &
                                           derivatives=d0)
      call nanopush_estimate_mu_from_force(rod, F, sF, x, sx, mu, s, load=w, derivatives=d, stat=stat)
    else
      call nanopush_estimate_mu_from_icor(rod, F, sF, x, sx, mu0, s0, sigma_L=0.0_dp, sigma_H=0.0_dp, load=w0, &
                                          derivatives=d0)
      call nanopush_estimate_mu_from_icor(rod, F, sF, x, sx, mu, s, load=w, derivatives=d, stat=stat)
    end if
    call check(stat == NANOPUSH_OK, "defaults: stat")
    call check(mu == mu0 .and. s == s0 .and. w == w0 .and. all(d == d0), "sigma_L, sigma_H default to 0")
    if (mode == "yn") then
      call nanopush_estimate_mu_from_force(rod, F, sF, x, sx, mu, s, sL, sH)   ! positional sigma_L, sigma_H
    else
      call nanopush_estimate_mu_from_icor(rod, F, sF, x, sx, mu, s, sL, sH)
    end if
    call check(.not. ieee_is_nan(mu) .and. .not. ieee_is_nan(s), "no optional outputs")
  end subroutine defaults_and_optional_outputs

  !> Each bad input: stat = NANOPUSH_BAD_INPUT, errmsg the library's message, outputs NaN.
  subroutine bad_input()
    real(dp) :: bad(6)
    call expect_bad("force", rod, 0.0_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, "F = 0: must be > 0 (N)")
    call expect_bad("force", rod, -1e-6_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, "F = -1e-06: must be > 0 (N)")
    call expect_bad("force", rod, 1e-6_dp, -1e-8_dp, 1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, &
                    "F uncertainty = -1e-08: must be >= 0 (N)")
    call expect_bad("force", rod, 1e-6_dp, 0.0_dp, -1e-9_dp, 0.0_dp, 0.0_dp, 0.0_dp, "yn = -1e-09: must be >= 0 (m)")
    call expect_bad("force", rod, 1e-6_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, "yn = 1: must be in [0, ")
    call expect_bad("force", rod, 1e-6_dp, 0.0_dp, 1e-7_dp, -5e-9_dp, 0.0_dp, 0.0_dp, &
                    "yn uncertainty = -5e-09: must be >= 0 (m)")
    call expect_bad("force", rod, 1e-6_dp, 0.0_dp, 1e-7_dp, 0.0_dp, -1e-9_dp, 0.0_dp, &
                    "L uncertainty = -1e-09: must be >= 0 (m)")
    call expect_bad("force", rod, 1e-6_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, -1e-20_dp, &
                    "H uncertainty = -1e-20: must be >= 0 (J)")
    call expect_bad("icor", rod, 0.0_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, "F = 0: must be > 0 (N)")
    call expect_bad("icor", rod, 1e-6_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, "R = 0: must be > 0 (m)")
    call expect_bad("icor", rod, 1e-6_dp, 0.0_dp, -1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, "R = -1e-07: must be > 0 (m)")
    call expect_bad("icor", rod, 1e-6_dp, 0.0_dp, 1e-7_dp, -1e-9_dp, 0.0_dp, 0.0_dp, &
                    "R uncertainty = -1e-09: must be >= 0 (m)")
    call expect_bad("icor", rod, 1e-6_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, -1e-20_dp, &
                    "H uncertainty = -1e-20: must be >= 0 (J)")
    bad = rod
    bad(1) = 0
    call expect_bad("force", bad, 1e-6_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, "rod.length = 0: must be > 0 (m)")
    call expect_bad("icor", bad, 1e-6_dp, 0.0_dp, 1e-7_dp, 0.0_dp, 0.0_dp, 0.0_dp, "rod.length = 0: must be > 0 (m)")
  end subroutine bad_input

  !> Bad input to nanopush_estimate_mu_from_<basis> (basis "force": x = yn, "icor": x = R) comes
  !> back as NANOPUSH_BAD_INPUT, a message starting with `want` and NaN outputs.
  subroutine expect_bad(basis, r, F_, sF_, x, sx, sL_, sH_, want)
    character(len=*), intent(in) :: basis, want
    real(dp), intent(in) :: r(6), F_, sF_, x, sx, sL_, sH_
    real(dp) :: mu, s, w, d(4)
    integer :: stat
    character(len=:), allocatable :: msg
    character(len=:), allocatable :: where
    where = "estimate_mu_from_" // basis
    call estimate(basis == "icor", r, F_, sF_, x, sx, sL_, sH_, mu, s, w, d, stat, msg)
    call check(stat == NANOPUSH_BAD_INPUT, where // ": stat = NANOPUSH_BAD_INPUT for '" // want // "'")
    call check(index(msg, want) == 1, where // ": errmsg '" // msg // "' should start with '" // want // "'")
    call check(ieee_is_nan(mu) .and. ieee_is_nan(s) .and. ieee_is_nan(w) .and. all(ieee_is_nan(d)), &
               where // ": outputs NaN after '" // want // "'")
  end subroutine expect_bad

  real(dp) function number(i)
    integer, intent(in) :: i
    integer :: ios
    arg = argument(i)
    read (arg, *, iostat=ios) number
    if (ios /= 0) error stop "test_fortran_estimate_mu: argument is not a number"
  end function number

end program test_fortran_estimate_mu
