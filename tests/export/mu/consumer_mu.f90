!> Friction coefficient from a measured push force, through the installed Fortran module, against
!> the CSV of `nanopush icor estimate-mu --out MU.csv` (the thesis nanorod, the CLI's default rod).
!> The CSV gives the inputs (value, sigma of F, yn or R, L, H) and the results (mu, sigma, W and
!> dmu/dinput, printed with 17 significant digits): every result must be the same double.
!> Usage: consumer_mu force|icor MU.csv
program consumer_mu
  use nanopush
  use test_support, only: argument
  implicit none
  character(len=:), allocatable :: kind, path, msg
  character(len=512) :: line
  character(len=64) :: fields(5)
  real(dp) :: rod(6), value(4), sig(4), dref(4), cref(4), mu_ref, sigma_ref, w_ref
  real(dp) :: mu, sigma, w, d(4)
  integer :: unit, ios, i, k, stat, nfound

  if (command_argument_count() < 2) error stop "usage: consumer_mu force|icor MU.csv"
  kind = argument(1)
  path = argument(2)

  ! Rows: mu,<mu>,<sigma>,, / W,<W>,,, / then F, yn|R, L, H: input,value,sigma,dmu_dinput,contribution.
  open (newunit=unit, file=path, status="old", action="read")
  read (unit, '(a)') line
  if (trim(line) /= "input,value,sigma,dmu_dinput,contribution") error stop "consumer_mu: unexpected CSV header"
  nfound = 0
  do
    read (unit, '(a)', iostat=ios) line
    if (ios /= 0) exit
    call split(trim(line), fields)
    select case (trim(fields(1)))
    case ("mu")
      mu_ref = number(fields(2))
      sigma_ref = number(fields(3))
    case ("W")
      w_ref = number(fields(2))
    case default
      k = index_of(trim(fields(1)))
      value(k) = number(fields(2))
      sig(k) = number(fields(3))
      dref(k) = number(fields(4))
      cref(k) = number(fields(5))
      nfound = nfound + 1
    end select
  end do
  close (unit)
  if (nfound /= 4) error stop "consumer_mu: expected the four inputs F, yn|R, L, H in the CSV"

  rod = nanopush_icor_nanorod()
  if (rod(1) /= value(3) .or. rod(4) /= value(4)) error stop "consumer_mu: the CSV's rod is not the thesis nanorod"
  if (kind == "force") then
    call nanopush_estimate_mu_from_force(rod, value(1), sig(1), value(2), sig(2), mu, sigma, &
                                         sigma_L=sig(3), sigma_H=sig(4), load=w, derivatives=d, &
                                         stat=stat, errmsg=msg)
  else if (kind == "icor") then
    call nanopush_estimate_mu_from_icor(rod, value(1), sig(1), value(2), sig(2), mu, sigma, &
                                        sigma_L=sig(3), sigma_H=sig(4), load=w, derivatives=d, &
                                        stat=stat, errmsg=msg)
  else
    error stop "consumer_mu: KIND is force or icor"
  end if
  if (stat /= NANOPUSH_OK) then
    print '(a)', "consumer_mu: " // msg
    error stop 1
  end if
  print '(a,es25.17,a,es25.17,a,es25.17)', "mu =", mu, " +-", sigma, ", W =", w
  if (mu /= mu_ref .or. sigma /= sigma_ref .or. w /= w_ref) error stop "consumer_mu: mu, sigma or W differ from the CLI"
  if (any(d /= dref)) error stop "consumer_mu: the derivatives differ from the CLI"
  if (any(abs(d) * sig /= cref)) error stop "consumer_mu: the contributions differ from the CLI"

  ! Bad input comes back through stat/errmsg, with NaN results.
  call nanopush_estimate_mu_from_force(rod, -1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, mu, sigma, stat=stat, errmsg=msg)
  if (stat /= NANOPUSH_BAD_INPUT .or. len(msg) == 0 .or. mu == mu) error stop "consumer_mu: bad input not reported"
  print '(a)', "consumer_mu: bad input reported: " // msg
  print '(a)', "consumer_mu: identical to nanopush icor estimate-mu"
  ! The main program's allocatables are freed here (LeakSanitizer counts them as leaks).
  deallocate (kind, path, msg)

contains

  integer function index_of(name)
    character(len=*), intent(in) :: name
    select case (name)
    case ("F")
      index_of = 1
    case ("yn", "R")
      index_of = 2
    case ("L")
      index_of = 3
    case ("H")
      index_of = 4
    case default
      error stop "consumer_mu: unknown input in the CSV"
    end select
  end function index_of

  subroutine split(s, f)
    character(len=*), intent(in) :: s
    character(len=*), intent(out) :: f(:)
    integer :: i, start, n
    f = ""
    n = 1
    start = 1
    do i = 1, len(s)
      if (s(i:i) == ",") then
        if (n <= size(f)) f(n) = s(start:i - 1)
        n = n + 1
        start = i + 1
      end if
    end do
    if (n <= size(f)) f(n) = s(start:)
  end subroutine split

  real(dp) function number(s)
    character(len=*), intent(in) :: s
    if (len_trim(s) == 0) then
      number = 0
    else
      read (s, *) number
    end if
  end function number

end program consumer_mu
