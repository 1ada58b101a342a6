!> nanopush_fit through `use nanopush`: noise-free observations of x from nanopush_run at the true
!> push force, the fit started 30 % away returns the truth (within 3 standard errors and 1e-5
!> relative); the JSON summary; bad input as stat + errmsg naming the key.
!> Usage: capi_test_fit_fortran SCENE.toml WORK_DIR
program test_fortran_fit
  use nanopush
  use test_support, only: check, finish
  implicit none
  ! The program in a block: its allocatables are freed at the block's end (a main program's
  ! are saved), so LeakSanitizer checks the library, not the program.
  block
    integer :: stat, i, u
    type(nanopush_scene) :: scene
    real(dp), allocatable :: traj(:, :), values(:), stderrs(:)
    real(dp) :: truth, chi, summary(6)
    logical :: conv
    character(len=:), allocatable :: path, dir, data, json, msg
    character(len=4096) :: arg

    if (command_argument_count() /= 2) error stop "usage: capi_test_fit_fortran SCENE.toml WORK_DIR"
    call get_command_argument(1, arg)
    path = trim(arg)
    call get_command_argument(2, arg)
    dir = trim(arg)
    data = dir // "/fortran_fit_data.csv"

    call nanopush_load_scene(scene, path)
    call nanopush_scene_set(scene, "solver.t_end", 0.4e-9_dp)
    call nanopush_scene_set(scene, "solver.samples", 21)
    call nanopush_run(scene, traj, engine="cxx")
    open (newunit=u, file=data, status="replace", action="write")
    write (u, '(a)') "t,x,sigma_x"
    do i = 1, size(traj, 2)
      write (u, '(es24.16e3,",",es24.16e3,",2e-9")') traj(NANOPUSH_T, i), traj(NANOPUSH_X, i)
    end do
    close (u)

    truth = push_force(scene)
    call nanopush_scene_set(scene, "push.force", 1.3_dp * truth)
    call nanopush_fit(scene, data, "push.force", values, stderrs, chi2_dof=chi, converged=conv, summary=summary, &
                      json=json, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_OK, "fit: stat " // msg)
    call check(size(values) == 1 .and. size(stderrs) == 1, "fit: one estimate")
    if (size(values) == 1) then
      call check(abs(values(1) - truth) < 3 * stderrs(1) .and. abs(values(1) / truth - 1) < 1e-5_dp, &
                 "fit: the truth back")
    end if
    call check(conv .and. chi < 1e-3_dp .and. summary(5) >= 2 .and. summary(6) == 1, "fit: converged, chi2/dof ~ 0")
    call check(index(json, '"parameters": {') > 0 .and. index(json, '"converged": true') > 0, "fit: JSON")
    ! The scene's solver.accuracy is the fit's: its rtol chosen, the record in the JSON.
    call nanopush_scene_set(scene, "solver.accuracy", 1e-9_dp)
    call nanopush_fit(scene, data, "push.force", values, stderrs, json=json, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_OK .and. index(json, '"accuracy": {') > 0 .and. index(json, '"requested": 1e-09') > 0, &
               "fit: accuracy " // msg)
    call nanopush_scene_set(scene, "solver.accuracy", 0.0_dp)

    call nanopush_fit(scene, data, "push.nonsense", values, stderrs, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_BAD_INPUT .and. index(msg, "push.nonsense") > 0 .and. size(values) == 0, &
               "bad key: " // msg)
    call nanopush_fit(scene, dir // "/absent.csv", "push.force", values, stderrs, stat=stat, errmsg=msg)
    call check(stat == NANOPUSH_BAD_INPUT .and. size(stderrs) == 0, "absent data: " // msg)
    call nanopush_destroy(scene)

    call finish("test_fortran_fit")
    print '(a)', "fortran fit: all checks hold"
  end block

contains

  !> The scene's push force [N] (push(1) of nanopush_scene_info).
  real(dp) function push_force(s)
    type(nanopush_scene), intent(in) :: s
    real(dp) :: p(4)
    call nanopush_scene_info(s, push=p)
    push_force = p(1)
  end function push_force


end program test_fortran_fit
