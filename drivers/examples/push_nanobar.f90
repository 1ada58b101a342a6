!> Example: push a nanobar from Fortran through `use nanopush` and print its instantaneous
!> centre of rotation (iCOR) over time.
!>
!> Usage: push_nanobar [SCENE.toml]   (default: $NANOPUSH_SCENES/thesis/fig3_6c.toml)
!>
!> The iCOR is the point of the plane (rigidly attached to the bar) whose velocity is zero:
!> v + omega e_z x c = 0 gives c = (-vy, vx) / omega relative to the centre of mass, in world
!> axes, at distance R = |c|. With omega = 0 the bar translates (no iCOR).
!>
!> Check (the example is also a test): starting from rest, the first motion is the response to
!> an impulse, so the iCOR starts at the centre of percussion, R0 = I / (m d), with d the lever
!> arm of the push about the centre of mass (d = |tau0| / F). As the bar turns by dtheta the
!> torque changes; to second order in t (v = F t / m exactly on a smooth surface, and
!> omega = (tau0 t + tau0' (tau0 / I) t^3 / 6) / I) the iCOR distance at the first sample is
!>     R = R0 (1 - (tau0' / tau0) dtheta / 3),     dtheta = theta(t) - theta(0).
!> The example stops with an error if the computed R differs from that by more than 1e-5 R0
!> (the neglected terms are O(dtheta^2), about 1e-6 for Fig 3.6 (c)).
program push_nanobar
  use nanopush
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: traj(:, :)
  character(len=:), allocatable :: path, name
  real(dp) :: mass, inertia, initial(6), push(4), lever, r0, c(2), r, vx, vy, omega, pwx, pwy
  real(dp) :: fx, fy, tau0, dtau0, dtheta, r_pred
  integer :: i, n, every

  path = scene_path()
  call nanopush_load_scene(scene, path)            ! no stat: an error stops with its message
  call nanopush_scene_info(scene, name=name, mass=mass, inertia=inertia, initial=initial, push=push)
  call nanopush_run(scene, traj)                    ! the scene's engine and tolerances
  call nanopush_destroy(scene)
  n = size(traj, 2)

  print '(a,a,a,i0,a)', "scene ", name, ": ", n, " samples"
  print '(a10,a13,a13,a13,a13,2x,a)', "t [ns]", "omega [1/s]", "cx [nm]", "cy [nm]", "R [nm]", "motion"
  every = max(1, (n - 1) / 20)
  do i = 1, n
    if (mod(i - 1, every) /= 0 .and. i /= 2 .and. i /= n) cycle
    vx = traj(NANOPUSH_VX, i)
    vy = traj(NANOPUSH_VY, i)
    omega = traj(NANOPUSH_OMEGA, i)
    if (omega /= 0) then
      c = [-vy, vx] / omega
      r = norm2(c)
      print '(f10.4,es13.4,3f13.4,2x,a)', traj(NANOPUSH_T, i) * 1e9_dp, omega, c * 1e9_dp, r * 1e9_dp, "rotation"
    else if (vx /= 0 .or. vy /= 0) then
      print '(f10.4,es13.4,3a13,2x,a)', traj(NANOPUSH_T, i) * 1e9_dp, omega, "-", "-", "-", "translation"
    else
      print '(f10.4,es13.4,3a13,2x,a)', traj(NANOPUSH_T, i) * 1e9_dp, omega, "-", "-", "-", "at rest"
    end if
  end do

  ! Centre of percussion: lever arm of the push about the CM at the initial orientation.
  if (any(initial(4:6) /= 0)) then
    print '(a)', "the bar does not start at rest: no centre-of-percussion check"
  else
    pwx = push(3) * cos(initial(3)) - push(4) * sin(initial(3))
    pwy = push(3) * sin(initial(3)) + push(4) * cos(initial(3))
    fx = push(1) * cos(push(2))
    fy = push(1) * sin(push(2))
    tau0 = pwx * fy - pwy * fx                 ! torque about the CM [N m]
    dtau0 = -pwy * fy - pwx * fx               ! its derivative with respect to theta [N m/rad]
    lever = abs(tau0) / push(1)
    r0 = inertia / (mass * lever)
    dtheta = traj(NANOPUSH_THETA, 2) - traj(NANOPUSH_THETA, 1)
    r_pred = r0 * (1 - dtau0 / tau0 * dtheta / 3)
    r = norm2([traj(NANOPUSH_VY, 2), traj(NANOPUSH_VX, 2)]) / abs(traj(NANOPUSH_OMEGA, 2))
    print '(a,f10.4,a)', "centre of percussion I/(m d) = ", r0 * 1e9_dp, " nm"
    print '(a,f12.6,a,f12.6,a,es9.2)', "first sample: R = ", r * 1e9_dp, " nm; expected R0 (1 - tau0''/tau0 dtheta/3) = ", &
      r_pred * 1e9_dp, " nm; |difference| / R0 = ", abs(r - r_pred) / r0
    if (abs(r - r_pred) > 1e-5_dp * r0) error stop "push_nanobar: the iCOR does not start at the centre of percussion"
    print '(a)', "the iCOR starts at the centre of percussion: check holds"
  end if

  ! Main-program allocatables live until the end (they are implicitly saved): free them so
  ! LeakSanitizer checks the library, not the program.
  if (allocated(traj)) deallocate(traj)
  if (allocated(path)) deallocate(path)
  if (allocated(name)) deallocate(name)

contains

  function scene_path() result(p)
    character(len=:), allocatable :: p
    integer :: length, st
    if (command_argument_count() >= 1) then
      call get_command_argument(1, length=length)
      allocate (character(len=length) :: p)
      call get_command_argument(1, p)
    else
      call get_environment_variable("NANOPUSH_SCENES", length=length, status=st)
      if (st /= 0 .or. length == 0) error stop "usage: push_nanobar SCENE.toml (or set NANOPUSH_SCENES)"
      allocate (character(len=length) :: p)
      call get_environment_variable("NANOPUSH_SCENES", p)
      p = p // "/thesis/fig3_6c.toml"
    end if
  end function scene_path

end program push_nanobar
