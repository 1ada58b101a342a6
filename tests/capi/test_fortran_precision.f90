!> Extended precision from Fortran: nanopush_run(..., precision="quad", state_ext=q) returns the
!> state in kind nanopush_qp with digits a double cannot hold, and those digits are real: two quad
!> runs at rtol 1e-20 and 1e-24 agree far more closely than either agrees with a double run.
!> Also: state_ext rounds to the double trajectory exactly; a bad combination comes back as
!> stat + errmsg naming the field.
program test_fortran_precision
  use nanopush
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: td(:, :), tq(:, :), t2(:, :)
  real(nanopush_qp), allocatable :: q(:, :), q2(:, :), qd(:, :)
  character(len=:), allocatable :: toml, msg
  character(len=*), parameter :: nl = new_line("a")
  real(nanopush_qp) :: dev_qq, dev_dq
  integer :: stat, k, i

  if (nanopush_qp < 0) error stop "test_fortran_precision: no quadruple-precision real kind"
  toml = '[scene]' // nl // 'name = "quad_bar"' // nl // &
         '[object]' // nl // 'shape = "bar"' // nl // 'length = 100e-9' // nl // 'width = 55e-9' // nl // &
         'height = 50e-9' // nl // 'density = 2267.0' // nl // &
         '[push]' // nl // 'force = 5e-6' // nl // 'direction = 0.0' // nl // 'xn = 27.5e-9' // nl // &
         'yn = 45e-9' // nl // '[initial]' // nl // 'theta = -0.5' // nl // &
         '[surface]' // nl // 'kind = "smooth"' // nl // &
         '[solver]' // nl // 't_end = 2e-10' // nl // 'samples = 21' // nl // 'rtol = 1e-12' // nl
  call nanopush_parse_scene(scene, toml)

  ! double: state_ext is the state itself
  call nanopush_run(scene, td, engine="cxx", method="modern", precision="double", state_ext=qd)
  if (size(qd, 1) /= NANOPUSH_STATE_SIZE .or. size(qd, 2) /= size(td, 2)) error stop "state_ext shape (double)"
  if (any(real(qd, dp) /= td(2:7, :))) error stop "double run: state_ext differs from the trajectory"

  call nanopush_run(scene, tq, engine="cxx", method="modern", precision="quad", rtol=1d-20, state_ext=q)
  call nanopush_run(scene, t2, engine="cxx", method="modern", precision="quad", rtol=1d-24, state_ext=q2)
  if (size(q, 2) /= size(tq, 2) .or. size(q2, 2) /= size(q, 2)) error stop "state_ext shape (quad)"
  ! the trajectory holds the quad values rounded to double
  do k = 1, size(q, 2)
    do i = 1, NANOPUSH_STATE_SIZE
      if (real(q(i, k), dp) /= tq(i + 1, k)) error stop "quad run: trajectory is not state_ext rounded"
    end do
  end do
  ! theta and omega (rows 3, 6), relative to their scales (1 rad; the largest |omega|)
  dev_qq = max(maxval(abs(q(3, :) - q2(3, :))), maxval(abs(q(6, :) - q2(6, :))) / maxval(abs(q2(6, :))))
  dev_dq = max(maxval(abs(qd(3, :) - q2(3, :))), maxval(abs(qd(6, :) - q2(6, :))) / maxval(abs(q2(6, :))))
  print '(a,es10.3,a,es10.3)', "quad 1e-20 vs quad 1e-24: ", real(dev_qq, dp), "; double 1e-12 vs quad 1e-24: ", &
    real(dev_dq, dp)
  if (.not. (dev_qq <= 1e-17_nanopush_qp)) error stop "the two quad runs should agree to 1e-17"
  if (.not. (dev_qq <= 1e-3_nanopush_qp * dev_dq)) error stop "quad digits beyond double should be meaningful"

  ! long and quad exist for the C++ engine only: stat + errmsg name the field
  call nanopush_run(scene, td, engine="f77", precision="quad", stat=stat, errmsg=msg)
  print '(a,i0,2a)', "f77 in quad: stat = ", stat, ", errmsg = ", msg
  if (stat /= NANOPUSH_BAD_INPUT .or. index(msg, "precision = quad") == 0) &
    error stop "precision quad with engine f77 should be a bad input naming the field"
  if (size(td, 2) /= 0) error stop "a failed run should give zero columns"
  call nanopush_run(scene, td, precision="octuple", stat=stat, errmsg=msg, state_ext=q)
  if (stat /= NANOPUSH_BAD_INPUT .or. index(msg, "precision = octuple: must be double, long or quad") == 0) &
    error stop "a bad precision should be a bad input naming the field"
  if (size(q, 2) /= 0) error stop "a failed run should give state_ext with zero columns"
  call nanopush_destroy(scene)
  ! main-program allocatables are not freed at exit (LeakSanitizer would report them)
  deallocate (td, tq, t2, q, q2, qd, toml, msg)
  print '(a)', "test_fortran_precision: all checks hold"
end program test_fortran_precision
