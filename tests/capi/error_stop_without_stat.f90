!> Without `stat`, an error in a nanopush call stops the program with the C++ message
!> (`error stop`, non-zero exit). Run by two CTests: one checks the message, one the exit status.
program error_stop_without_stat
  use nanopush
  implicit none
  type(nanopush_scene) :: scene
  character(len=*), parameter :: nl = new_line("a")
  call nanopush_parse_scene(scene, "[object]" // nl // "length = 1e-7" // nl // "width = 5e-8" // nl // &
                            "mass = -1" // nl // "[push]" // nl // "force = 1e-6" // nl // "xn = 0" // nl // &
                            "yn = 0" // nl // "[solver]" // nl // "t_end = 1e-9" // nl)
  print '(a)', "not reached: the call above must stop the program"
end program error_stop_without_stat
