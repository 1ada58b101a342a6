!> A rough-surface scene runs from Fortran with the friction law chosen by the caller, and gives
!> the numbers of `nanopush run SCENE --law LAW` exactly (the reference CSV has 17 significant
!> digits). The other law must give a different trajectory (the choice reaches the solver), and a
!> bad law comes back as stat + errmsg.
!> Usage: capi_test_rough SCENE.toml LAW REFERENCE.csv
program test_fortran_rough
  use nanopush
  use test_support, only: argument, compare_with_run
  implicit none
  ! The program in a block: its allocatables are freed at the block's end (a main program's
  ! are saved), so LeakSanitizer checks the library, not the program.
  block
    type(nanopush_scene) :: scene
    real(dp), allocatable :: traj(:, :), other(:, :)
    character(len=:), allocatable :: law, other_law, msg
    integer :: stat

    if (command_argument_count() /= 3) error stop "usage: capi_test_rough SCENE.toml LAW REFERENCE.csv"
    law = argument(2)
    other_law = "coulomb"
    if (law == "coulomb") other_law = "thesis"

    call nanopush_load_scene(scene, argument(1))
    call nanopush_run(scene, traj, engine="cxx", law=law)
    call nanopush_run(scene, other, law="sticky", stat=stat, errmsg=msg)
    print '(a,i0,2a)', "law = sticky: stat = ", stat, ", errmsg = ", msg
    if (stat /= NANOPUSH_BAD_INPUT .or. index(msg, "law = sticky: must be thesis, printed or coulomb") == 0) &
      error stop "test_fortran_rough: a bad law should come back as stat + errmsg"
    call nanopush_run(scene, other, engine="cxx", law=other_law)
    call nanopush_destroy(scene)
    print '(a,a,a,i0,a)', "law ", law, ": ", size(traj, 2), " rows"
    if (size(other, 2) == size(traj, 2)) then
      if (all(other == traj)) error stop "test_fortran_rough: both laws gave the same trajectory"
    end if

    call compare_with_run(traj, argument(3), "test_fortran_rough")
    print '(3a)', "rough scene, law ", law, ": identical to nanopush run"
  end block

end program test_fortran_rough
