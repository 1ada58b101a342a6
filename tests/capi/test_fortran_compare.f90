!> nanopush_compare from Fortran (module nanopush): the verdict of `nanopush compare` on a
!> thesis preset, and a bad method as stat + errmsg. Usage: test_fortran_compare SCENE.toml
program test_fortran_compare
  use nanopush
  use test_support, only: check, finish
  implicit none
  type(nanopush_scene) :: scene
  character(len=512) :: path
  character(len=:), allocatable :: msg
  logical :: agree, convergence
  real(dp) :: figures(9)
  integer :: stat
  call get_command_argument(1, path)
  call nanopush_load_scene(scene, trim(path), stat, msg)
  call check(stat == 0, "load " // trim(path))
  call nanopush_compare(scene, agree, rtol=1d-10, convergence=convergence, figures=figures, stat=stat, errmsg=msg)
  call check(stat == 0, "compare: " // msg)
  call check(agree, "faithful agrees with f77")
  call check(.not. convergence, "faithful is judged by same steps")
  call check(all(figures >= 0 .and. figures <= 100 * 1d-10), "figures within 100 rtol")
  call nanopush_compare(scene, agree, method="cvode", stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT, "method cvode is bad input")
  call check(index(msg, "cvode") > 0, "the message names the method: " // msg)
  call check(.not. agree, "no verdict on bad input")
  call nanopush_destroy(scene)
  if (allocated(msg)) deallocate (msg)  ! the main program's locals are not freed at its end (LeakSanitizer)
  call finish("test_fortran_compare")
  print '(a)', "fortran compare: ok"
end program test_fortran_compare
