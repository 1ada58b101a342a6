! Fortran: nanopush_scene_set (real, integer and text values) changes the scene as the C++
! Scene::set does: the same trajectory whichever form sets the same value, bit for bit; bad
! keys and values come back as NANOPUSH_BAD_INPUT with the key named. Usage: prog fig3_18.toml
program test_fortran_scene_set
  use nanopush
  use test_support, only: check, finish
  implicit none
  type(nanopush_scene) :: a, b
  real(dp), allocatable :: ta(:, :), tb(:, :)
  character(len=512) :: path
  character(len=:), allocatable :: msg
  integer :: stat
  call get_command_argument(1, path)

  call nanopush_load_scene(a, trim(path))
  call nanopush_scene_set(a, "surface.mu", 0.1_dp)
  call nanopush_scene_set(a, "push.yn", 20e-9_dp)
  call nanopush_run(a, ta, engine="cxx")

  call nanopush_load_scene(b, trim(path))
  call nanopush_scene_set(b, "surface.mu", "0.1")
  call nanopush_scene_set(b, "push.yn", "20e-9", stat=stat)
  call check(stat == NANOPUSH_OK, "text value accepted")
  call nanopush_run(b, tb, engine="cxx")
  call check(all(shape(ta) == shape(tb)), "same shape")
  if (all(shape(ta) == shape(tb))) call check(all(ta == tb), "real and text settings give the same bits")

  ! An integer key takes an integer.
  call nanopush_scene_set(b, "solver.samples", 11)
  call nanopush_run(b, tb, engine="cxx")
  call check(size(tb, 2) == 11, "solver.samples = 11 gives 11 rows")

  ! Bad input: stat and the library's message, the scene unchanged.
  call nanopush_scene_set(a, "surface.mu", -1.0_dp, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT, "out of range refused")
  call check(msg == "surface.mu = -1: must be in [0, 10]", "message: " // msg)
  call nanopush_scene_set(a, "surface.muu", 0.1_dp, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT, "unknown key refused")
  call check(index(msg, "surface.muu = 0.1: unknown scene key") == 1, "message: " // msg)
  call nanopush_scene_set(a, "solver.samples", 10.5_dp, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT, "fractional integer refused")
  call nanopush_run(a, tb, engine="cxx")
  call check(all(shape(ta) == shape(tb)), "unchanged scene: same shape")
  if (all(shape(ta) == shape(tb))) call check(all(ta == tb), "unchanged scene: same bits")

  call nanopush_destroy(a)
  call nanopush_destroy(b)
  ! The main program's allocatables are freed here (LeakSanitizer counts them as leaks).
  deallocate (ta, tb, msg)
  call finish("test_fortran_scene_set")
  print '(a)', "fortran scene_set: all checks hold"
contains
end program test_fortran_scene_set
