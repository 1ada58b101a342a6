!> What every Fortran test program shares (tests/CMakeLists.txt links it into each):
!> check() counts and reports failed checks, finish() ends the program with a nonzero status
!> when any failed, and the thresholds below name the agreement the tests ask for.
module test_support
  use, intrinsic :: iso_fortran_env, only: real64
  implicit none
  private
  public :: check, finish, failures, checks, tol_agree, tol_round_trip

  !> Two implementations of the same double-precision computation (C++ against F77, Brent
  !> against LAPACK, one integration through two front ends): the arithmetic is reordered, so
  !> a few thousand ulps of slack, and nothing a wrong formula could hide in.
  real(real64), parameter :: tol_agree = 1e-12_real64
  !> A value through a closed form and back through its inverse (a friction coefficient from
  !> the forces it gave): a few hundred ulps, two evaluations' rounding.
  real(real64), parameter :: tol_round_trip = 1e-13_real64

  integer, save :: failures = 0  !< checks that failed so far
  integer, save :: checks = 0    !< checks made so far

contains

  !> Counts the check; when `ok` is false, counts a failure and prints "FAIL: what".
  subroutine check(ok, what)
    logical, intent(in) :: ok
    character(len=*), intent(in) :: what
    checks = checks + 1
    if (.not. ok) then
      failures = failures + 1
      print '(2a)', "FAIL: ", what
    end if
  end subroutine check

  !> Prints "N checks, M failures" and, when any check failed, stops with a nonzero status
  !> naming the program.
  subroutine finish(program_name)
    character(len=*), intent(in) :: program_name
    print '(i0,a,i0,a)', checks, " checks, ", failures, " failures"
    if (failures > 0) error stop program_name // ": failures above"
  end subroutine finish

end module test_support
