!> Test problems shared by the C API test programs: right-hand sides written once, called both
!> through `use nanopush` (C++ Bulirsch-Stoer) and as F77 EXTERNAL routines for BSINT, so both
!> engines see the same arithmetic. The problem is told by its dimension: 4 is Kepler, 2 Van der
!> Pol (ode_rhs for `nanopush_integrate`, f77_problem below for BSINT, rpar(1) = mu).
module capi_test_problems
  use nanopush, only: dp, nanopush_context
  implicit none
  private
  public :: kepler, van_der_pol, ode_params, kepler_start, ode_rhs, problem

  !> Parameters of a test problem, handed to the RHS as its nanopush context.
  type, extends(nanopush_context), public :: ode_params
    real(dp) :: mu = 1                 !< Van der Pol damping / Kepler gravitational parameter
    integer :: evaluations = 0         !< counted by the RHS (a context the RHS writes to)
  end type ode_params

contains

  !> Kepler problem y = (q1, q2, p1, p2): q' = p, p' = -mu q / |q|^3.
  pure subroutine kepler(y, dydt, mu)
    real(dp), intent(in) :: y(4), mu
    real(dp), intent(out) :: dydt(4)
    real(dp) :: r3
    r3 = sqrt(y(1)**2 + y(2)**2)**3
    dydt(1) = y(3)
    dydt(2) = y(4)
    dydt(3) = -mu * y(1) / r3
    dydt(4) = -mu * y(2) / r3
  end subroutine kepler

  !> Start of a Kepler orbit of eccentricity e (mu = 1) at pericentre: period 2 pi.
  pure function kepler_start(e) result(y)
    real(dp), intent(in) :: e
    real(dp) :: y(4)
    y = [1 - e, 0.0_dp, 0.0_dp, sqrt((1 + e) / (1 - e))]
  end function kepler_start

  !> Van der Pol oscillator y = (x, v): x' = v, v' = mu (1 - x^2) v - x.
  pure subroutine van_der_pol(y, dydt, mu)
    real(dp), intent(in) :: y(2), mu
    real(dp), intent(out) :: dydt(2)
    dydt(1) = y(2)
    dydt(2) = mu * (1 - y(1)**2) * y(2) - y(1)
  end subroutine van_der_pol

  !> dydt of the problem of dimension size(y) (4: Kepler, 2: Van der Pol) with parameter mu.
  pure subroutine problem(y, dydt, mu)
    real(dp), intent(in) :: y(:), mu
    real(dp), intent(out) :: dydt(:)
    if (size(y) == 4) then
      call kepler(y, dydt, mu)
    else
      call van_der_pol(y, dydt, mu)
    end if
  end subroutine problem

  !> The nanopush right-hand side of the problem of dimension size(y), mu and an evaluation
  !> count in the ode_params context (another context type: stat 99).
  subroutine ode_rhs(t, y, dydt, ctx, stat)
    real(dp), intent(in) :: t, y(:)
    real(dp), intent(out) :: dydt(:)
    class(nanopush_context), intent(inout) :: ctx
    integer, intent(inout) :: stat
    select type (ctx)
    type is (ode_params)
      call problem(y, dydt, ctx%mu)
      ctx%evaluations = ctx%evaluations + 1
    class default
      stat = 99
    end select
  end subroutine ode_rhs

end module capi_test_problems

!> The same problems as F77-style EXTERNAL derivative routine for BSINT (n = 4: Kepler, n = 2:
!> Van der Pol; rpar(1) = mu).
subroutine f77_problem(n, t, y, dydt, rpar, ipar, ierr)
  use capi_test_problems, only: problem
  implicit none
  integer, intent(in) :: n
  double precision, intent(in) :: t, y(n), rpar(*)
  double precision, intent(out) :: dydt(n)
  integer, intent(inout) :: ipar(*), ierr
  call problem(y, dydt, rpar(1))
end subroutine f77_problem
