!> Consumer of the installed nanopush Fortran module (nanopush::fortran): run a scene through
!> `use nanopush` and compare every number with the CSV written by
!> `nanopush run SCENE --engine ENGINE --out REFERENCE.csv` (printed with 17 significant digits,
!> so reading it back gives the same doubles: the comparison is exact).
!> Usage: consumer_fortran SCENE.toml ENGINE REFERENCE.csv
program consumer_fortran
  use nanopush
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: traj(:, :)
  real(dp) :: row(NANOPUSH_TRAJECTORY_COLUMNS), worst
  character(len=:), allocatable :: scene_path, engine, ref_path
  character(len=512) :: header
  integer :: unit, ios, nref, differ

  if (command_argument_count() /= 3) error stop "usage: consumer_fortran SCENE.toml ENGINE REFERENCE.csv"
  scene_path = argument(1)
  engine = argument(2)
  ref_path = argument(3)

  call nanopush_load_scene(scene, scene_path)
  call nanopush_run(scene, traj, engine=engine)
  call nanopush_destroy(scene)
  print '(a,i0,a,a)', "consumer_fortran: ", size(traj, 2), " rows from engine ", engine
  print '(a,10es25.16e3)', "last row: ", traj(:, size(traj, 2))

  open (newunit=unit, file=ref_path, status="old", action="read")
  read (unit, '(a)') header
  if (trim(header) /= "t,x,y,theta,vx,vy,omega,fx,fy,mf") error stop "consumer_fortran: unexpected CSV header"
  nref = 0
  differ = 0
  worst = 0
  do
    read (unit, *, iostat=ios) row
    if (ios /= 0) exit
    nref = nref + 1
    if (nref > size(traj, 2)) exit
    if (any(row /= traj(:, nref))) differ = differ + 1
    worst = max(worst, maxval(abs(row - traj(:, nref))))
  end do
  close (unit)
  print '(a,i0,a,i0,a,es10.3)', "reference rows ", nref, ", rows that differ ", differ, ", largest |difference| ", worst
  if (nref /= size(traj, 2)) error stop "consumer_fortran: row count differs from nanopush run"
  if (differ /= 0) error stop "consumer_fortran: numbers differ from nanopush run"
  print '(a)', "consumer_fortran: identical to nanopush run"

contains

  function argument(i) result(a)
    integer, intent(in) :: i
    character(len=:), allocatable :: a
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: a)
    call get_command_argument(i, a)
  end function argument

end program consumer_fortran
