!> Friction and iCOR through `use nanopush` give the numbers of the nanopush CLI (exactly: the CSV
!> files hold 17 significant digits, so reading them back gives the same doubles).
!> Usage: capi_test_friction_icor_fortran FORMULAS.csv MU RATIO ROOTS.csv FRICTION_PLUS.csv FRICTION_MINUS.csv
!>   FORMULAS.csv   `nanopush icor formulas --mu MU --force-ratio RATIO ...` (the thesis nanorod)
!>   ROOTS.csv      `nanopush icor roots ...` (rows of the C++ solvers brent and eigen are compared)
!>   FRICTION_*.csv `nanopush friction --sense +1/-1`:
!>                  R,alpha,fx,fy,mf for the nanobar (a = 27.5 nm, b = 50 nm), muN = 1
!> Also checks eq 4.11 at the iCOR of eq 4.13 against the minimum force of eq 4.8 (the identity the
!> thesis derives 4.13 from), to a few ulps.
program test_fortran_friction_icor
  use nanopush
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use test_support, only: check, finish, same, argument, open_csv, field, fields
  implicit none
  real(dp) :: rod(6), L, k2, W, mu, ratio
  real(dp), parameter :: a_bar = 27.5e-9_dp, b_bar = 50e-9_dp
  character(len=:), allocatable :: arg

  if (command_argument_count() /= 6) &
    error stop "usage: capi_test_friction_icor_fortran FORMULAS.csv MU RATIO ROOTS.csv FRICTION_PLUS.csv FRICTION_MINUS.csv"
  rod = nanopush_icor_nanorod()
  call nanopush_icor_rod_properties(rod, k2=k2, load=W)
  L = rod(1)
  arg = argument(2)
  read (arg, *) mu
  arg = argument(3)
  read (arg, *) ratio

  call compare_formulas(argument(1))
  call compare_roots(argument(4))
  call compare_friction(argument(5), 1)
  call compare_friction(argument(6), -1)

  call finish("test_fortran_friction_icor")
  print '(a)', "Fortran friction and iCOR: identical to the nanopush CLI"

  ! Main-program allocatables live until the end (they are implicitly saved): free them so
  ! LeakSanitizer checks the library, not the program.
  if (allocated(arg)) deallocate(arg)

contains

  !> Every column of `nanopush icor formulas`.
  subroutine compare_formulas(path)
    character(len=*), intent(in) :: path
    character(len=4096) :: line
    real(dp) :: c(12), F, Rneg, Rpos, r413, fmin, rel
    real(dp), allocatable :: roots(:)
    integer :: unit, ios, rows
    character(len=32) :: at
    unit = open_csv(path, "yn,R_experimental_fit,R_falvo,R_li,R_unknown_pressure,R_known_pressure," // &
                   "F_min,F_from_icor,R_constrained_negative,R_constrained_positive,F_constrained_negative," // &
                   "R_impulsive", "formulas: header")
    rows = 0
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      call fields(line, c)
      rows = rows + 1
      write (at, '(" at yn = ",es14.7)') c(1)
      F = ratio * mu * W
      call same(nanopush_icor_experimental_fit(c(1), L), c(2), "eq 4.1" // at)
      call same(nanopush_icor_falvo(c(1), L), c(3), "eq 4.2" // at)
      call same(nanopush_icor_li(c(1), L), c(4), "eq 4.3" // at)
      r413 = nanopush_icor_unknown_pressure(c(1), L)
      call same(r413, c(5), "eq 4.13" // at)
      fmin = nanopush_icor_minimum_force(mu, W, c(1), L)
      if (F >= fmin) then
        call same(nanopush_icor_known_pressure(mu, W, c(1), F, L), c(6), "eq 4.7" // at)
      else
        call check(ieee_is_nan(c(6)), "eq 4.7 absent below the minimum force" // at)
      end if
      call same(fmin, c(7), "eq 4.8" // at)
      call same(nanopush_icor_force_from_icor(mu, W, r413, L), c(8), "eq 4.10" // at)
      call nanopush_icor_cubic_roots(c(1), L, k2, roots, NANOPUSH_CUBIC_BRENT, negative=Rneg, positive=Rpos)
      call same(Rneg, c(9), "eq 5.4 negative branch" // at)
      call same(Rpos, c(10), "eq 5.4 positive branch" // at)
      if (.not. ieee_is_nan(Rneg)) then
        call same(nanopush_icor_constrained_force(mu, W, Rneg, c(1), L, k2), c(11), "eq 5.2" // at)
      else
        call check(ieee_is_nan(c(11)), "eq 5.2 absent without a negative branch" // at)
      end if
      call same(nanopush_icor_impulsive(c(1), k2), c(12), "eq 5.5" // at)
      ! Eq 4.11 (not printed by the CLI): at the iCOR of eq 4.13 it is the minimum force (4.8).
      rel = abs(nanopush_icor_force_unknown_pressure(mu, W, r413, c(1), L) - fmin) / fmin
      call check(rel <= 4 * epsilon(1.0_dp), "eq 4.11 at R(4.13) = F(4.8) to 4 eps" // at)
    end do
    close (unit)
    call check(rows >= 2, "formulas: rows read")
    print '(a,i0,a)', "formulas: ", rows, " push points"
  end subroutine compare_formulas

  !> Rows of `nanopush icor roots` from the C++ solvers (brent, eigen).
  subroutine compare_roots(path)
    character(len=*), intent(in) :: path
    character(len=4096) :: line
    character(len=16) :: solver, language
    real(dp) :: c(12), neg, pos, res
    real(dp), allocatable :: roots(:)
    integer :: unit, ios, rows, method, nc, ni, i
    character(len=48) :: at
    unit = open_csv(path, "yn,solver,language,n_real,n_complex,n_infinite,root_1,root_2,root_3," // &
                   "negative_branch,positive_branch,max_relative_residual", "roots: header")
    rows = 0
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      solver = field(line, 2)
      language = field(line, 3)
      if (language /= "cxx") cycle
      method = NANOPUSH_CUBIC_BRENT
      if (solver == "eigen") method = NANOPUSH_CUBIC_EIGEN
      call fields(line, c)
      rows = rows + 1
      write (at, '(" (",a,") at yn = ",es14.7)') trim(solver), c(1)
      call nanopush_icor_cubic_roots(c(1), L, k2, roots, method, ncomplex=nc, at_infinity=ni, negative=neg, &
                                     positive=pos, max_residual=res)
      call check(size(roots) == nint(c(4)), "roots: n_real" // at)
      call check(nc == nint(c(5)), "roots: n_complex" // at)
      call check(ni == nint(c(6)), "roots: n_infinite" // at)
      do i = 1, 3
        if (i <= size(roots)) then
          call same(roots(i), c(6 + i), "roots: root" // at)
        else
          call check(ieee_is_nan(c(6 + i)), "roots: no further root" // at)
        end if
      end do
      call same(neg, c(10), "roots: negative branch" // at)
      call same(pos, c(11), "roots: positive branch" // at)
      call same(res, c(12), "roots: residual" // at)
    end do
    close (unit)
    call check(rows >= 4, "roots: rows read")
    print '(a,i0,a)', "roots: ", rows, " rows of the C++ solvers"
  end subroutine compare_roots

  !> R,alpha,fx,fy,mf of `nanopush friction` (muN = 1, the nanobar).
  subroutine compare_friction(path, sense)
    character(len=*), intent(in) :: path
    integer, intent(in) :: sense
    character(len=4096) :: line
    real(dp) :: c(5), wr(3)
    integer :: unit, ios, rows
    character(len=64) :: at
    unit = open_csv(path, "R,alpha,fx,fy,mf", "friction: header")
    rows = 0
    do
      read (unit, '(a)', iostat=ios) line
      if (ios /= 0) exit
      call fields(line, c)
      rows = rows + 1
      write (at, '(" at R = ",es14.7,", alpha = ",f8.4,", sense ",i2)') c(1), c(2), sense
      call nanopush_friction_wrench(a_bar, b_bar, 1.0_dp, c(1), c(2), sense, wr)
      call same(wr(1), c(3), "friction fx" // at)
      call same(wr(2), c(4), "friction fy" // at)
      call same(wr(3), c(5), "friction mf" // at)
    end do
    close (unit)
    call check(rows >= 10, "friction: rows read")
    print '(a,i0,a,i0)', "friction: ", rows, " points, sense ", sense
  end subroutine compare_friction


end program test_fortran_friction_icor
