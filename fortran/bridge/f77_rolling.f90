!> Bridge to the FORTRAN 77 rolling formulas (fortran/rolling.f). C prototypes with units:
!> fortran/bridge/f77_rolling.h. Every function returns the F77 IERR (0 = ok, 1 = invalid
!> argument, 2 = load below pull-off, 3 = no convergence); none stops the program.
module nanopush_f77_rolling
  use nanopush_f77_interfaces, only: rlfs, rlres, rlmin, rldec, rlvdw, rljkrl
  use, intrinsic :: iso_c_binding, only: c_int, c_double
  implicit none
  private
  public :: np_f77_rolling_static_friction, np_f77_rolling_resistance, &
            np_f77_rolling_min_force, np_f77_rolling_decide, &
            np_f77_rod_plane_vdw, np_f77_jkr_line_half_width


contains

  integer(c_int) function np_f77_rolling_static_friction(f, h, r, fs) &
      bind(C, name="np_f77_rolling_static_friction")
    real(c_double), value, intent(in) :: f, h, r
    real(c_double), intent(out) :: fs
    integer :: ierr
    call rlfs(f, h, r, fs, ierr)
    np_f77_rolling_static_friction = int(ierr, c_int)
  end function np_f77_rolling_static_friction

  integer(c_int) function np_f77_rolling_resistance(w, k, r, fs) &
      bind(C, name="np_f77_rolling_resistance")
    real(c_double), value, intent(in) :: w, k, r
    real(c_double), intent(out) :: fs
    integer :: ierr
    call rlres(w, k, r, fs, ierr)
    np_f77_rolling_resistance = int(ierr, c_int)
  end function np_f77_rolling_resistance

  integer(c_int) function np_f77_rolling_min_force(w, k, r, margin, f) &
      bind(C, name="np_f77_rolling_min_force")
    real(c_double), value, intent(in) :: w, k, r, margin
    real(c_double), intent(out) :: f
    integer :: ierr
    call rlmin(w, k, r, margin, f, ierr)
    np_f77_rolling_min_force = int(ierr, c_int)
  end function np_f77_rolling_min_force

  integer(c_int) function np_f77_rolling_decide(f, h, r, mu, n_slide, w_roll, k, mode, &
      f_roll, f_slide, fs_required) bind(C, name="np_f77_rolling_decide")
    real(c_double), value, intent(in) :: f, h, r, mu, n_slide, w_roll, k
    integer(c_int), intent(out) :: mode
    real(c_double), intent(out) :: f_roll, f_slide, fs_required
    integer :: ierr, imode
    call rldec(f, h, r, mu, n_slide, w_roll, k, imode, f_roll, f_slide, fs_required, ierr)
    mode = int(imode, c_int)
    np_f77_rolling_decide = int(ierr, c_int)
  end function np_f77_rolling_decide

  integer(c_int) function np_f77_rod_plane_vdw(a, l, d, z0, fv) bind(C, name="np_f77_rod_plane_vdw")
    real(c_double), value, intent(in) :: a, l, d, z0
    real(c_double), intent(out) :: fv
    integer :: ierr
    call rlvdw(a, l, d, z0, fv, ierr)
    np_f77_rod_plane_vdw = int(ierr, c_int)
  end function np_f77_rod_plane_vdw

  integer(c_int) function np_f77_jkr_line_half_width(r, estar, w, p, b) &
      bind(C, name="np_f77_jkr_line_half_width")
    real(c_double), value, intent(in) :: r, estar, w, p
    real(c_double), intent(out) :: b
    integer :: ierr
    call rljkrl(r, estar, w, p, b, ierr)
    np_f77_jkr_line_half_width = int(ierr, c_int)
  end function np_f77_jkr_line_half_width

end module nanopush_f77_rolling
