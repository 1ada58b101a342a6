!> nanopush_compare from Fortran (module nanopush): the verdict of `nanopush compare` on a
!> thesis preset, and a bad method as stat + errmsg. Usage: test_fortran_compare SCENE.toml
program test_fortran_compare
  use nanopush
  implicit none
  type(nanopush_scene) :: scene
  character(len=512) :: path
  character(len=:), allocatable :: msg
  logical :: agree, convergence
  real(dp) :: figures(9)
  integer :: stat, failures
  failures = 0
  call get_command_argument(1, path)
  call nanopush_load_scene(scene, trim(path), stat, msg)
  call expect(stat == 0, "load " // trim(path))
  call nanopush_compare(scene, agree, rtol=1d-10, convergence=convergence, figures=figures, stat=stat, errmsg=msg)
  call expect(stat == 0, "compare: " // msg)
  call expect(agree, "faithful agrees with f77")
  call expect(.not. convergence, "faithful is judged by same steps")
  call expect(all(figures >= 0 .and. figures <= 100 * 1d-10), "figures within 100 rtol")
  call nanopush_compare(scene, agree, method="cvode", stat=stat, errmsg=msg)
  call expect(stat == NANOPUSH_BAD_INPUT, "method cvode is bad input")
  call expect(index(msg, "cvode") > 0, "the message names the method: " // msg)
  call expect(.not. agree, "no verdict on bad input")
  call nanopush_destroy(scene)
  if (failures > 0) error stop "test_fortran_compare: failures"
  print '(a)', "fortran compare: ok"
contains
  subroutine expect(cond, what)
    logical, intent(in) :: cond
    character(len=*), intent(in) :: what
    if (.not. cond) then
      failures = failures + 1
      print '(2a)', "FAIL: ", what
    end if
  end subroutine expect
end program test_fortran_compare
