!> A rough-surface scene runs from Fortran with the friction law chosen by the caller, and gives
!> the numbers of `nanopush run SCENE --law LAW` exactly (the reference CSV has 17 significant
!> digits). The other law must give a different trajectory (the choice reaches the solver), and a
!> bad law comes back as stat + errmsg.
!> Usage: capi_test_rough SCENE.toml LAW REFERENCE.csv
program test_fortran_rough
  use nanopush
  use test_support, only: argument
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: traj(:, :), other(:, :)
  real(dp) :: row(NANOPUSH_TRAJECTORY_COLUMNS)
  character(len=:), allocatable :: law, other_law, msg
  character(len=512) :: header
  integer :: unit, ios, nref, differ, stat

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

  open (newunit=unit, file=argument(3), status="old", action="read")
  read (unit, '(a)') header
  if (trim(header) /= "t,x,y,theta,vx,vy,omega,fx,fy,mf") error stop "test_fortran_rough: unexpected CSV header"
  nref = 0
  differ = 0
  do
    read (unit, *, iostat=ios) row
    if (ios /= 0) exit
    nref = nref + 1
    if (nref > size(traj, 2)) exit
    if (any(row /= traj(:, nref))) differ = differ + 1
  end do
  close (unit)
  print '(a,i0,a,i0)', "reference rows ", nref, ", rows that differ ", differ
  if (nref /= size(traj, 2)) error stop "test_fortran_rough: row count differs from nanopush run"
  if (differ /= 0) error stop "test_fortran_rough: numbers differ from nanopush run"
  print '(3a)', "rough scene, law ", law, ": identical to nanopush run"

  ! Main-program allocatables live until the end (they are implicitly saved): free them so
  ! LeakSanitizer checks the library, not the program.
  if (allocated(traj)) deallocate(traj)
  if (allocated(other)) deallocate(other)
  if (allocated(law)) deallocate(law)
  if (allocated(other_law)) deallocate(other_law)
  if (allocated(msg)) deallocate(msg)

end program test_fortran_rough
