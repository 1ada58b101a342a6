!> FORTRAN 77 RECTFR/RECTFV on their own (no C++): exact oracles and error statuses.
program test_rectfr
  use test_support, only: check, finish
  use nanopush_f77_interfaces, only: rectfr, rectfv  ! the one declaration (fortran/bridge)
  implicit none
  double precision :: fx, fy, fm, gx, gy, gm, expect, zero
  integer :: ierr
  zero = 0.0d0

  ! Rotation about the CM of a unit square: f = 0, mf = -(sqrt 2 + ln(1 + sqrt 2))/6.
  call rectfr(0.5d0, 0.5d0, 1.0d0, 0.0d0, 0.3d0, 1, fx, fy, fm, ierr)
  expect = -(sqrt(2.0d0) + log(1.0d0 + sqrt(2.0d0)))/6.0d0
  call check(ierr == 0 .and. fx == 0.0d0 .and. fy == 0.0d0, 'R = 0 force')
  call check(abs(fm - expect) <= 4.0d-16, 'R = 0 moment (square oracle)')

  ! Clockwise flips the whole wrench.
  call rectfr(27.5d-9, 50.0d-9, 2.0d0, 40.0d-9, 0.7d0, 1, fx, fy, fm, ierr)
  call rectfr(27.5d-9, 50.0d-9, 2.0d0, 40.0d-9, 0.7d0, -1, gx, gy, gm, ierr)
  call check(gx == -fx .and. gy == -fy .and. gm == -fm, 'sense antisymmetry')

  ! Far iCOR: translation limit f = muN (sin alpha, -cos alpha), mf -> -(a^2 s^2 + b^2 c^2)/(3R).
  call rectfr(27.5d-9, 50.0d-9, 1.0d0, 1.0d0, 0.4d0, 1, fx, fy, fm, ierr)
  call check(abs(fx - sin(0.4d0)) <= 1.0d-14 .and. abs(fy + cos(0.4d0)) <= 1.0d-14, 'translation limit')
  expect = -((27.5d-9*sin(0.4d0))**2 + (50.0d-9*cos(0.4d0))**2)/3.0d0
  call check(abs(fm - expect) <= 1.0d-13*abs(expect), 'far-field moment')

  ! Dissipation over a sweep: f.v + mf omega <= 0.
  call sweep()

  ! Velocity form: at rest zero; omega = 0 pure translation.
  call rectfv(1.0d0, 2.0d0, 1.0d0, zero, zero, zero, fx, fy, fm, ierr)
  call check(ierr == 0 .and. fx == 0.0d0 .and. fy == 0.0d0 .and. fm == 0.0d0, 'at rest')
  call rectfv(1.0d0, 2.0d0, 1.0d0, 3.0d0, -4.0d0, zero, fx, fy, fm, ierr)
  call check(abs(fx + 0.6d0) <= 1.0d-15 .and. abs(fy - 0.8d0) <= 1.0d-15 .and. fm == 0.0d0, 'translation')

  ! Bad input: status, zero wrench, no STOP.
  call rectfr(0.0d0, 1.0d0, 1.0d0, 1.0d0, 0.0d0, 1, fx, fy, fm, ierr)
  call check(ierr == 1 .and. fx == 0.0d0, 'a = 0')
  call rectfr(1.0d0, 1.0d0, 1.0d0, -1.0d0, 0.0d0, 1, fx, fy, fm, ierr)
  call check(ierr == 5, 'R < 0')
  call rectfr(1.0d0, 1.0d0, 1.0d0, 1.0d0, 0.0d0, 2, fx, fy, fm, ierr)
  call check(ierr == 7, 'sense = 2')

  call finish('test_rectfr')
  print '(a)', 'test_rectfr: all checks passed'

contains

  subroutine sweep()
    integer :: i, k, s, ie
    double precision :: r, al, om, p, w1, w2, w3, vx, vy
    do i = 0, 40
      r = 50.0d-9*10.0d0**(-3.0d0 + 10.0d0*dble(i)/40.0d0)
      do k = 0, 35
        al = 6.283185307179586d0*dble(k)/36.0d0
        do s = -1, 1, 2
          om = dble(s)*1.0d6
          call rectfr(27.5d-9, 50.0d-9, 1.0d0, r, al, s, w1, w2, w3, ie)
          vx = -om*r*sin(al)
          vy = om*r*cos(al)
          p = w1*vx + w2*vy + w3*om
          call check(ie == 0 .and. p <= 0.0d0, 'dissipation')
        end do
      end do
    end do
  end subroutine sweep

end program test_rectfr
