!> FORTRAN 77 rolling formulas (fortran/rolling.f), called from Fortran: the exact points of
!> Fig 3.3, the JKR line relation's residual, the Parsegian closed form, and IERR paths.
!> Also calls the same routines through the bind(C) bridge module and compares.
program test_rolling
  use, intrinsic :: iso_c_binding, only: c_double, c_int
  use nanopush_f77_rolling, only: np_f77_rolling_static_friction, np_f77_jkr_line_half_width
  use nanopush_f77_interfaces, only: rlfs, rljkrl, rlvdw, rldec
  use test_support, only: check, finish
  implicit none
  double precision, parameter :: pi = 3.14159265358979323846d0
  double precision :: r, f, fs, b, p, fv, es, w, froll, fslid, fsreq
  real(c_double) :: fsc, bc
  integer :: ierr, mode

  r = 13.5d-9
  f = 3.88796d-7
  call rlfs(f, r/2, r, fs, ierr)
  call check(ierr == 0 .and. fs == 0.0d0, 'fs(h = r/2) = 0')
  call rlfs(f, r, r, fs, ierr)
  call check(ierr == 0 .and. fs == -f/3, 'fs(h = r) = -F/3')
  call rlfs(f, 0.0d0, r, fs, ierr)
  call check(ierr == 0 .and. fs == f/3, 'fs(h = 0) = F/3')
  call rlfs(f, 2*r, r, fs, ierr)
  call check(ierr == 1, 'h > r gives IERR = 1')
  ierr = int(np_f77_rolling_static_friction(f, 0.0d0, r, fsc))
  call check(ierr == 0 .and. fsc == f/3, 'bridge fs(h = 0) = F/3')

  es = 19.0d9
  w = 0.25d0
  p = 4.32d0
  call rljkrl(r, es, w, p, b, ierr)
  call check(ierr == 0, 'JKR line converges')
  call check(abs(pi*es*b*b/(4*r) - sqrt(2*pi*es*w*b) - p) <= 1.0d-12*p, 'JKR line residual')
  ierr = int(np_f77_jkr_line_half_width(r, es, w, p, bc))
  call check(ierr == 0 .and. bc == b, 'bridge JKR line = direct call')
  call rljkrl(r, es, w, -1.0d3, b, ierr)
  call check(ierr == 2, 'below the line pull-off gives IERR = 2')

  call rlvdw(2.38d-19, 590.0d-9, 27.0d-9, 0.2d-9, fv, ierr)
  call check(ierr == 0 .and. abs(fv - 590.0d-9*2.38d-19*sqrt(27.0d-9)/(16*(0.2d-9)**2.5d0)) <= 1.0d-15*fv, &
             'Parsegian closed form')
  call rlvdw(-1.0d-19, 590.0d-9, 27.0d-9, 0.2d-9, fv, ierr)
  call check(ierr == 1, 'negative Hamaker constant gives IERR = 1')

  call rldec(3.0d-7, 0.0d0, r, 0.1d0, 2.5d-6, 8.7d-6, 3.6d-9, mode, froll, fslid, fsreq, ierr)
  call check(ierr == 0 .and. mode == 3, 'mu = 0.1: sliding')
  call rldec(1.0d-8, 0.0d0, r, 0.1d0, 2.5d-6, 8.7d-6, 3.6d-9, mode, froll, fslid, fsreq, ierr)
  call check(ierr == 0 .and. mode == 0, 'small push: stuck')

  call finish('test_rolling')
  print '(a)', 'test_rolling: all checks passed'

end program test_rolling
