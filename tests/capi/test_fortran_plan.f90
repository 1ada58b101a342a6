!> nanopush_plan through `use nanopush`: the plan of the C API row for row (found and verified,
!> within tolerance, the chain ending where its last push leaves the bar); a goal out of reach
!> in one push is not found, with the best plan; a robust plan found in every world; bad input as
!> stat + errmsg naming the argument.
!> Usage: capi_test_plan_fortran SCENE.toml
program test_fortran_plan
  use nanopush
  use test_support, only: check, finish
  implicit none
  type(nanopush_scene) :: scene
  real(dp), allocatable :: pushes(:, :)
  real(dp) :: summary(8)
  real(dp), parameter :: goal(3) = [60e-9_dp, 40e-9_dp, 0.3_dp], tol(2) = [2e-9_dp, 0.02_dp]
  logical :: found, verified
  integer :: stat, n
  character(len=:), allocatable :: msg
  character(len=4096) :: arg

  if (command_argument_count() /= 1) error stop "usage: capi_test_plan_fortran SCENE.toml"
  call get_command_argument(1, arg)
  call nanopush_load_scene(scene, trim(arg))

  call nanopush_plan(scene, goal, pushes, tolerance=tol, found=found, verified=verified, summary=summary, &
                     stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_OK, "plan: stat " // msg)
  call check(found .and. verified, "plan: found and verified")
  n = size(pushes, 1)
  call check(n >= 1 .and. size(pushes, 2) == 8, "plan: pushes(n, 8)")
  call check(summary(6) <= tol(1) .and. summary(7) <= tol(2), "plan: within tolerance")
  if (n >= 1) call check(all(pushes(n, 6:8) == summary(3:5)), "plan: the chain ends at the last push's pose")
  call check(all(pushes(:, 4) > 0) .and. all(pushes(:, 5) > 0), "plan: speeds and travels > 0")

  ! A robust plan: found and verified in every world (the tip friction 0 and 0.3, start shifts).
  call nanopush_plan(scene, goal, pushes, tolerance=tol, found=found, verified=verified, stat=stat, errmsg=msg, &
                     tip_mu_range=[0.0_dp, 0.3_dp], start_shift=[0.6e-9_dp, 0.6e-9_dp, 0.004_dp])
  call check(stat == NANOPUSH_OK .and. found .and. verified .and. size(pushes, 1) >= 1, "robust plan: " // msg)
  call nanopush_plan(scene, goal, pushes, tip_mu_range=[0.3_dp, 0.1_dp], stat=stat, errmsg=msg)
  ! the library's --tip-mu-range named as the argument, tip_mu_range
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "tip_mu_range = 0.3:0.1: ") == 1, "reversed tip_mu_range: " // msg)

  call nanopush_plan(scene, [400e-9_dp, -300e-9_dp, 1.2_dp], pushes, tolerance=tol, max_pushes=1, found=found, &
                     summary=summary, stat=stat)
  call check(stat == NANOPUSH_OK .and. .not. found .and. size(pushes, 1) <= 1 .and. summary(6) > tol(1), &
             "plan: out of reach in one push")

  call nanopush_plan(scene, goal, pushes, max_pushes=0, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "max_pushes") > 0 .and. size(pushes, 1) == 0, &
             "bad max_pushes: " // msg)
  call nanopush_plan(scene, goal, pushes, objective="fastest", stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "fastest") > 0, "bad objective: " // msg)

  call nanopush_destroy(scene)
  ! Main-program allocatables are not freed at the end (LeakSanitizer counts them): free them.
  if (allocated(pushes)) deallocate(pushes)
  if (allocated(msg)) deallocate(msg)
  call finish("test_fortran_plan")
end program test_fortran_plan
