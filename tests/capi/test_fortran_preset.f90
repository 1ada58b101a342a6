! Fortran: nanopush_scene_preset loads the file the command line's preset rule finds (the run
! equals that of nanopush_load_scene of the file, bit for bit); a preset that is not there
! comes back as NANOPUSH_BAD_INPUT naming it and the directory. Usage: prog SCENES_DIR
program test_fortran_preset
  use nanopush
  use test_support, only: check, finish
  implicit none
  type(nanopush_scene) :: a, b
  real(dp), allocatable :: ta(:, :), tb(:, :)
  character(len=512) :: dir
  character(len=:), allocatable :: msg
  integer :: stat
  call get_command_argument(1, dir)

  call nanopush_scene_preset(a, "fig3_18", scenes_dir=trim(dir), stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_OK, "preset fig3_18 loaded: " // msg)
  call nanopush_load_scene(b, trim(dir) // "/thesis/fig3_18.toml")
  call nanopush_run(a, ta, engine="cxx")
  call nanopush_run(b, tb, engine="cxx")
  call check(size(ta, 2) > 1, "the preset runs")
  call check(all(shape(ta) == shape(tb)), "same shape")
  if (all(shape(ta) == shape(tb))) call check(all(ta == tb), "preset and file give the same bits")

  call nanopush_scene_preset(a, "fig9_99", scenes_dir=trim(dir), stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT, "unknown preset refused")
  call check(index(msg, "name = fig9_99: no preset of that name under " // trim(dir)) == 1, "message: " // msg)

  call nanopush_destroy(a)
  call nanopush_destroy(b)
  ! The main program's allocatables are freed here (LeakSanitizer counts them as leaks).
  deallocate (ta, tb, msg)
  call finish("test_fortran_preset")
  print '(a)', "fortran preset: all checks hold"
end program test_fortran_preset
