!> Bridge to the FORTRAN 77 smooth-nanobar right-hand side (fortran/smbar.f).
module nanopush_f77_smooth_bar
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  use nanopush_f77_interfaces, only: smbar, smbarp
  implicit none
  private
  public :: np_f77_smooth_bar_rhs

contains

  !> Evaluate the F77 RHS once. y, dydt: 6 states (x, y, theta, vx, vy, omega; SI).
  !> params: 6 values (m [kg], I [kg m^2], F [N], beta [rad], pbx [m], pby [m]).
  !> Returns 0 on success.
  integer(c_int) function np_f77_smooth_bar_rhs(t, y, dydt, params) bind(C, name="np_f77_smooth_bar_rhs")
    real(c_double), value, intent(in) :: t
    real(c_double), intent(in) :: y(6)
    real(c_double), intent(out) :: dydt(6)
    real(c_double), intent(in) :: params(6)
    integer :: ipar(1), ierr
    double precision :: rpar(8)
    ! smbar reads the push force from rpar(7:8), which smbarp derives from params(3:4).
    rpar(1:6) = params
    call smbarp(rpar)
    ipar(1) = 0
    call smbar(6, t, y, dydt, rpar, ipar, ierr)
    np_f77_smooth_bar_rhs = int(ierr, c_int)
  end function np_f77_smooth_bar_rhs

end module nanopush_f77_smooth_bar
