!> Consumer of the installed nanopush Fortran module (nanopush::fortran): run a scene through
!> `use nanopush` and compare every number with the CSV written by
!> `nanopush run SCENE --engine ENGINE --out REFERENCE.csv` (printed with 17 significant digits,
!> so reading it back gives the same doubles: the comparison is exact).
!> Usage: consumer_fortran SCENE.toml ENGINE REFERENCE.csv [FRICTION.csv]
!> With FRICTION.csv (`nanopush friction` output: R,alpha,fx,fy,mf for the nanobar a = 27.5 nm,
!> b = 50 nm, muN = 1, sense +1) it also checks nanopush_friction_wrench at every row, exactly.
program consumer_fortran
  use nanopush
  use test_support, only: argument, compare_with_run
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: traj(:, :)
  character(len=:), allocatable :: scene_path, engine, ref_path
  character(len=512) :: header
  integer :: ios

  if (command_argument_count() < 3) error stop "usage: consumer_fortran SCENE.toml ENGINE REFERENCE.csv [FRICTION.csv]"
  scene_path = argument(1)
  engine = argument(2)
  ref_path = argument(3)

  call nanopush_load_scene(scene, scene_path)
  call nanopush_run(scene, traj, engine=engine)
  call nanopush_destroy(scene)
  print '(a,i0,a,a)', "consumer_fortran: ", size(traj, 2), " rows from engine ", engine
  print '(a,10es25.16e3)', "last row: ", traj(:, size(traj, 2))

  call compare_with_run(traj, ref_path, "consumer_fortran")
  print '(a)', "consumer_fortran: identical to nanopush run"
  if (command_argument_count() >= 4) call check_friction(argument(4))

  ! Main-program allocatables live until the end: free them so LeakSanitizer checks the library.
  if (allocated(traj)) deallocate(traj)
  if (allocated(scene_path)) deallocate(scene_path)
  if (allocated(engine)) deallocate(engine)
  if (allocated(ref_path)) deallocate(ref_path)

contains

  !> nanopush_friction_wrench at every row of `nanopush friction` output (sense +1).
  subroutine check_friction(path)
    character(len=*), intent(in) :: path
    real(dp) :: c(5), w(3)
    integer :: u, rows, bad
    open (newunit=u, file=path, status="old", action="read")
    read (u, '(a)') header
    if (trim(header) /= "R,alpha,fx,fy,mf") error stop "consumer_fortran: unexpected friction CSV header"
    rows = 0
    bad = 0
    do
      read (u, *, iostat=ios) c
      if (ios /= 0) exit
      rows = rows + 1
      call nanopush_friction_wrench(27.5e-9_dp, 50e-9_dp, 1.0_dp, c(1), c(2), 1, w)
      if (any(w /= c(3:5))) bad = bad + 1
    end do
    close (u)
    print '(a,i0,a,i0,a)', "consumer_fortran: friction wrench at ", rows, " points, ", bad, " differ"
    if (rows == 0 .or. bad /= 0) error stop "consumer_fortran: friction wrench differs from nanopush friction"
    print '(a)', "consumer_fortran: friction wrench identical to nanopush friction"
  end subroutine check_friction

end program consumer_fortran
