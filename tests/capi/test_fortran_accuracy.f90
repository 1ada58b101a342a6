!> The error estimate, the accuracy asked for and the outcomes from Fortran (module nanopush):
!> nanopush_run's accuracy=, error_estimate=, error= and outcome=, and the stat of
!> no_static_friction, with the outcome of a failed run named. Usage: test_fortran_accuracy
!> ROUGH_SCENE.toml (fig3_18)
program test_fortran_accuracy
  use nanopush
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use test_support, only: check, finish
  implicit none
  type(nanopush_scene) :: scene
  character(len=512) :: path
  character(len=:), allocatable :: msg, outcome
  real(dp), allocatable :: traj(:, :)
  real(dp) :: e(NANOPUSH_ERROR_SIZE)
  integer :: stat
  call get_command_argument(1, path)
  call nanopush_load_scene(scene, trim(path), stat, msg)
  call check(stat == 0, "load " // trim(path))
  call nanopush_run(scene, traj, law="coulomb", error=e, outcome=outcome, stat=stat, errmsg=msg)
  call check(stat == 0, "run: " // msg)
  call check(e(1) > 0 .and. e(1) < 1d-6, "an error estimate of the final pose")
  call check(e(5) >= e(1), "the trajectory's max >= the final pose's")
  call check(outcome == "ok", "outcome ok: " // outcome)
  call nanopush_run(scene, traj, law="coulomb", error_estimate=.false., error=e, stat=stat, errmsg=msg)
  call check(stat == 0 .and. ieee_is_nan(e(1)), "no estimate when not asked")
  call nanopush_run(scene, traj, law="coulomb", accuracy=1d-9, error=e, stat=stat, errmsg=msg)
  call check(stat == 0 .and. e(1) <= 1d-9 .and. e(6) < 1d-9, "accuracy 1e-9 reached at a tighter rtol")
  ! CVODE stops at rtol 1e-14, in double: 1e-14 is not reached
  call nanopush_run(scene, traj, law="coulomb", method="cvode", accuracy=1d-14, outcome=outcome, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_ACCURACY_NOT_REACHED, "accuracy 1e-14 not reached: " // msg)
  ! a failed run names its outcome, as C's status and Python's SolverError.outcome do (it was "")
  call check(outcome == "accuracy_not_reached", "outcome accuracy_not_reached: '" // outcome // "'")
  call nanopush_run(scene, traj, law="coulomb", method="modern", outcome=outcome, &
                    precision="long", error_estimate=.false., stat=stat, errmsg=msg)
  call check(stat == 0 .and. outcome == "ok", "a rough scene in long double (coulomb law, modern): " // msg)
  call nanopush_run(scene, traj, engine="gpu", outcome=outcome, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_BAD_INPUT .and. outcome == "", "no run made, no outcome: '" // outcome // "'")
  call nanopush_scene_set(scene, "push.force", 1d-7, stat=stat, errmsg=msg)
  call check(stat == 0, "set push.force: " // msg)
  call nanopush_run(scene, traj, law="coulomb", outcome=outcome, stat=stat, errmsg=msg)
  call check(stat == 0 .and. outcome == "at_rest", "a weak push is at_rest under the coulomb law")
  call nanopush_run(scene, traj, law="thesis", outcome=outcome, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_NO_STATIC_FRICTION, "and no_static_friction under the thesis law: " // msg)
  call check(outcome == "no_static_friction", "outcome no_static_friction: '" // outcome // "'")
  call check(size(traj, 2) == 0, "no trajectory on failure")
  call nanopush_scene_set(scene, "solver.max_steps", 5, stat=stat, errmsg=msg)
  call nanopush_scene_set(scene, "push.force", 5d-6, stat=stat, errmsg=msg)
  call nanopush_run(scene, traj, law="coulomb", outcome=outcome, stat=stat, errmsg=msg)
  call check(stat == NANOPUSH_TOO_MANY_STEPS .and. outcome == "solver_failure", &
             "the integrator's failure: solver_failure: '" // outcome // "' " // msg)
  call nanopush_destroy(scene)
  if (allocated(msg)) deallocate (msg)
  if (allocated(outcome)) deallocate (outcome)
  if (allocated(traj)) deallocate (traj)
  call finish("test_fortran_accuracy")
  print '(a)', "fortran accuracy: ok"
end program test_fortran_accuracy
