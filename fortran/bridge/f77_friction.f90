!> Bridge to the FORTRAN 77 rectangle friction wrench (fortran/rectfr.f).
!> C prototypes, units and status codes: fortran/bridge/f77_friction.h.
module nanopush_f77_friction
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_char, c_null_char
  use nanopush_f77_interfaces, only: rectfr, rectfv
  implicit none
  private
  public :: np_f77_rectangle_friction, np_f77_rectangle_friction_velocity, np_f77_friction_message

contains

  !> Friction wrench for iCOR (R, alpha) and sense +-1. wrench(3) = (fx [N], fy [N], mf [N m]),
  !> body axes. Returns 0 or the RECTFR status (1..7); wrench is zero on error.
  integer(c_int) function np_f77_rectangle_friction(a, b, mun, r, alpha, sense, wrench) &
      bind(C, name="np_f77_rectangle_friction")
    real(c_double), value, intent(in) :: a, b, mun, r, alpha
    integer(c_int), value, intent(in) :: sense
    real(c_double), intent(out) :: wrench(3)
    integer :: ierr
    call rectfr(a, b, mun, r, alpha, int(sense), wrench(1), wrench(2), wrench(3), ierr)
    np_f77_rectangle_friction = int(ierr, c_int)
  end function np_f77_rectangle_friction

  !> Friction wrench from the body-axis rigid velocity (vx, vy [m/s], omega [rad/s]).
  !> Returns 0 or the RECTFV status (1..4, 8).
  integer(c_int) function np_f77_rectangle_friction_velocity(a, b, mun, vx, vy, omega, wrench) &
      bind(C, name="np_f77_rectangle_friction_velocity")
    real(c_double), value, intent(in) :: a, b, mun, vx, vy, omega
    real(c_double), intent(out) :: wrench(3)
    integer :: ierr
    call rectfv(a, b, mun, vx, vy, omega, wrench(1), wrench(2), wrench(3), ierr)
    np_f77_rectangle_friction_velocity = int(ierr, c_int)
  end function np_f77_rectangle_friction_velocity

  !> Copy the message for a status code into buf (buflen bytes including the terminating NUL;
  !> truncated if too short). Returns the full message length.
  integer(c_int) function np_f77_friction_message(status, buf, buflen) bind(C, name="np_f77_friction_message")
    integer(c_int), value, intent(in) :: status
    integer(c_int), value, intent(in) :: buflen
    character(kind=c_char), intent(out) :: buf(*)
    character(len=:), allocatable :: msg
    integer :: i, n
    select case (status)
    case (0)
      msg = "ok"
    case (1)
      msg = "a: must be a finite number > 0 (m, half-width along body x')"
    case (2)
      msg = "b: must be a finite number > 0 (m, half-length along body y')"
    case (3)
      msg = "b/a: aspect ratio must be in [1e-12, 1e12]"
    case (4)
      msg = "muN: must be a finite number >= 0 (N)"
    case (5)
      msg = "R: must be a finite number >= 0 (m)"
    case (6)
      msg = "alpha: must be a finite number (rad)"
    case (7)
      msg = "sense: must be +1 (counter-clockwise) or -1 (clockwise)"
    case (8)
      msg = "vx, vy, omega: must be finite numbers (m/s, rad/s)"
    case default
      msg = "unknown status"
    end select
    n = min(len(msg), int(buflen) - 1)
    do i = 1, n
      buf(i) = msg(i:i)
    end do
    if (buflen > 0) buf(max(n, 0) + 1) = c_null_char
    np_f77_friction_message = int(len(msg), c_int)
  end function np_f77_friction_message

end module nanopush_f77_friction
