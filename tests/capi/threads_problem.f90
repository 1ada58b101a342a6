!> The Fortran side of the threads test: solve problem k through `use nanopush` (a Fortran RHS
!> integrated by the C++ Bulirsch-Stoer), callable from C. Problem 1: Van der Pol, mu = 5,
!> t in [0, 20]; problem 2: Kepler orbit, e = 0.8, two periods. All state is local.
module capi_threads_problem
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_int64_t
  use nanopush
  use capi_test_problems
  implicit none
  private
  public :: np_test_solve

contains

  !> Solve problem k (1 or 2); yout[nout*n] column-major (n, nout) with n = 2 or 4,
  !> nout = 201; counts[3]. Returns the nanopush status.
  integer(c_int) function np_test_solve(k, yout_flat, counts) bind(C, name="np_test_solve")
    integer(c_int), value, intent(in) :: k
    real(c_double), intent(out) :: yout_flat(*)
    integer(c_int64_t), intent(out) :: counts(3)
    integer, parameter :: nout = 201
    real(dp), parameter :: pi = acos(-1.0_dp)
    real(dp) :: tout(nout)
    real(dp), allocatable :: y(:), yout(:, :)
    type(ode_params) :: p
    integer :: i, stat
    if (k == 1) then
      p%mu = 5
      allocate (y(2))
      y(:) = [2.0_dp, 0.0_dp]
      tout = [(20.0_dp * (i - 1) / (nout - 1), i = 1, nout)]
      call nanopush_integrate(ode_rhs, 0.0_dp, y, tout, yout, rtol=1e-12_dp, atol=[1e-12_dp], ctx=p, &
                              counts=counts, stat=stat)
    else
      p%mu = 1
      allocate (y(4))
      y(:) = kepler_start(0.8_dp)
      tout = [(4 * pi * (i - 1) / (nout - 1), i = 1, nout)]
      call nanopush_integrate(ode_rhs, 0.0_dp, y, tout, yout, rtol=1e-12_dp, atol=[1e-12_dp], &
                              method="modern", ctx=p, counts=counts, stat=stat)
    end if
    if (p%evaluations /= counts(1)) stat = -1
    yout_flat(1:size(yout)) = reshape(yout, [size(yout)])
    np_test_solve = int(stat, c_int)
  end function np_test_solve

end module capi_threads_problem
