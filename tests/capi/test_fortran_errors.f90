!> Errors raised in C++ (bad scene, bad argument, failing integration) reach the Fortran caller
!> of `use nanopush` as a status and a message when it passes stat/errmsg; nothing crashes, and
!> a successful call afterwards works and clears errmsg.
program test_fortran_errors
  use nanopush
  use capi_test_problems
  use, intrinsic :: ieee_arithmetic, only: ieee_is_nan
  use test_support, only: check, finish
  implicit none
  ! The program in a block: its allocatables are freed at the block's end (a main program's
  ! are saved), so LeakSanitizer checks the library, not the program.
  block
    integer :: stat
    character(len=:), allocatable :: msg
    type(nanopush_scene) :: scene, never_loaded
    real(dp), allocatable :: traj(:, :), yout(:, :)
    real(dp) :: y(2)
    character(len=*), parameter :: nl = new_line("a")
    character(len=*), parameter :: good_scene = &
      "[object]" // nl // "length = 1e-7" // nl // "width = 5e-8" // nl // "mass = 1e-18" // nl // &
      "[push]" // nl // "force = 1e-6" // nl // "xn = 1e-8" // nl // "yn = 2e-8" // nl // &
      "[solver]" // nl // "t_end = 1e-9" // nl // "samples = 11" // nl
    type(ode_params) :: p
    real(dp) :: w(3), r, rod(6), k2
    real(dp), allocatable :: roots(:)

    ! Bad scene value: the C++ InputError names the field, the value and the range.
    call nanopush_parse_scene(scene, replace(good_scene, "mass = 1e-18", "mass = -1"), "bad_mass.toml", &
                              stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "object.mass = -1: must be > 0 (kg)", "bad mass")
    ! Unknown key, TOML syntax error, missing file.
    call nanopush_parse_scene(scene, good_scene // "lenght = 3" // nl, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "lenght", "unknown key")
    call nanopush_parse_scene(scene, "[object" // nl, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "<string>", "TOML syntax error")
    call nanopush_load_scene(scene, "/nonexistent/scene.toml", stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "/nonexistent/scene.toml", "missing file")
    ! Using a scene that was never loaded: a null handle, not a crash.
    call nanopush_run(never_loaded, traj, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_NULL_HANDLE, msg, "scene = NULL", "run on a null scene")
    call check(size(traj, 2) == 0, "failed run: empty trajectory")

    ! A good scene, then bad run arguments.
    call nanopush_parse_scene(scene, good_scene, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_OK, msg, "", "good scene")
    call nanopush_run(scene, traj, engine="gpu", stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "engine = gpu: must be cxx or f77", "bad engine")
    call nanopush_run(scene, traj, engine="f77", method="modern", stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "method = modern: the f77 engine has one method", "f77 with modern")
    call nanopush_run(scene, traj, method="sloppy", stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "method = sloppy", "bad method")
    call nanopush_run(scene, traj, rtol=-1.0_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "rtol = -1: must be in [", "bad rtol")
    ! ... and the scene still runs afterwards.
    call nanopush_run(scene, traj, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_OK, msg, "", "good run")
    call check(size(traj, 1) == NANOPUSH_TRAJECTORY_COLUMNS .and. size(traj, 2) == 11, "good run: 10 x 11")
    call nanopush_destroy(scene)
    call nanopush_destroy(scene)  ! twice: a no-op

    ! Integrator arguments.
    p%mu = 1
    y = [2.0_dp, 0.0_dp]
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp, 0.5_dp], yout, ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "non-decreasing", "decreasing output times")
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp], yout, atol=[1e-9_dp, 1e-9_dp, 1e-9_dp], &
                            ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "natol = 3: must be 1 or n = 2", "atol of the wrong size")
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp], yout, method="euler", ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "method = ""euler""", "bad method")
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp], yout, kmax=20, ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "kmax = 20: must be in [3, 12]", "bad kmax")
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp], yout, rtol=-1e-3_dp, ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "rtol = -0.001: must be >= 0", "negative rtol")
    ! The checks SUNDIALS' CVODE makes before its first step, under their Fortran names.
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp], yout, rtol=1e-300_dp, atol=[0.0_dp], ctx=p, &
                            stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_TOO_MUCH_ACCURACY, msg, "more accuracy than double precision", "rtol 1e-300")
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [1.0_dp, nearest(1.0_dp, 2.0_dp)], yout, ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_TOUT_TOO_CLOSE, msg, "is too close to tout[0] = 1", "tout one ulp apart")
    call check(NANOPUSH_TOO_MUCH_ACCURACY == 11 .and. NANOPUSH_TOUT_TOO_CLOSE == 12, "status values as in nanopush.h")
    call nanopush_integrate(ode_rhs, 0.0_dp, y, [100.0_dp], yout, maxstp=5, ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_TOO_MANY_STEPS, msg, "more than 5 steps", "maxstp exceeded")
    ! The RHS reports a failure (stat = 7 once t > 0.5): the integration stops with status 4.
    y = [2.0_dp, 0.0_dp]
    call nanopush_integrate(failing_rhs, 0.0_dp, y, [0.25_dp, 1.0_dp], yout, ctx=p, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_RHS_FAILED, msg, "right-hand side returned status 7", "RHS failure")
    call check(all(yout(:, 1) /= 0) .and. all(yout(:, 2) == 0), "RHS failure: first output kept, second not reached")
    ! Friction and iCOR: bad arguments come back as stat + errmsg, the result is NaN; then a good
    ! call with the same variables succeeds and clears errmsg.
    call nanopush_friction_wrench(0.0_dp, 50e-9_dp, 1.0_dp, 1e-8_dp, 0.0_dp, 1, w, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "a = 0: must be > 0", "friction a = 0")
    call check(all(ieee_is_nan(w)), "friction a = 0: NaN wrench")
    call nanopush_friction_wrench(-2e-9_dp, 50e-9_dp, 1.0_dp, 1e-8_dp, 0.0_dp, 1, w, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "a = -2e-09: must be > 0", "friction a < 0")
    call nanopush_friction_wrench(27.5e-9_dp, 50e-9_dp, 1.0_dp, 1e-8_dp, 0.0_dp, 0, w, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "sense = 0: must be +1", "friction sense = 0")
    call nanopush_friction_from_velocity(27.5e-9_dp, -1.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, 1.0_dp, w, &
                                         stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "b = -1: must be > 0", "friction_from_velocity b < 0")
    call nanopush_friction_wrench(27.5e-9_dp, 50e-9_dp, 1.0_dp, 1e-8_dp, 0.0_dp, 1, w, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_OK, msg, "", "good friction call")
    call check(all(.not. ieee_is_nan(w)) .and. w(2) < 0, "good friction call: finite wrench")
    r = nanopush_icor_falvo(-1e-9_dp, 590e-9_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "yn = -1e-09", "falvo yn < 0")
    call check(ieee_is_nan(r), "falvo yn < 0: NaN")
    r = nanopush_icor_unknown_pressure(-1e-9_dp, 590e-9_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "yn = -1e-09", "unknown_pressure yn < 0")
    r = nanopush_icor_li(1e-9_dp, 0.0_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "L = 0: must be > 0", "li L = 0")
    r = nanopush_icor_experimental_fit(1e-9_dp, -3.0_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "L = -3: must be > 0", "experimental_fit L < 0")
    r = nanopush_icor_minimum_force(0.1_dp, 1e-6_dp, 1e-9_dp, 0.0_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "L = 0", "minimum_force L = 0")
    r = nanopush_icor_known_pressure(0.1_dp, 1e-6_dp, 0.0_dp, 1e-9_dp, 590e-9_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "minimum force", "known_pressure F below the minimum")
    r = nanopush_icor_force_unknown_pressure(0.1_dp, 1e-6_dp, -1e-9_dp, 0.0_dp, 590e-9_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "R + yn must be > 0", "force_unknown_pressure R + yn < 0")
    r = nanopush_icor_impulsive(-1e-9_dp, 2.9e-14_dp, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "yn = -1e-09", "impulsive yn < 0")
    call nanopush_icor_cubic_roots(-1e-9_dp, 590e-9_dp, 2.9e-14_dp, roots, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "yn = -1e-09", "cubic roots yn < 0")
    call check(size(roots) == 0, "cubic roots yn < 0: no roots")
    call nanopush_icor_cubic_roots(1e-9_dp, 0.0_dp, 2.9e-14_dp, roots, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "L = 0", "cubic roots L = 0")
    call nanopush_icor_cubic_roots(1e-9_dp, 590e-9_dp, 2.9e-14_dp, roots, method=7, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "method = 7", "cubic roots bad method")
    rod = nanopush_icor_nanorod()
    rod(1) = -1
    call nanopush_icor_rod_properties(rod, k2=k2, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_BAD_INPUT, msg, "rod.length = -1", "rod_properties L < 0")
    call check(ieee_is_nan(k2), "rod_properties L < 0: NaN")
    rod = nanopush_icor_nanorod()
    call nanopush_icor_rod_properties(rod, k2=k2, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_OK, msg, "", "rod_properties of the nanorod")
    call nanopush_icor_cubic_roots(1e-9_dp, rod(1), k2, roots, stat=stat, errmsg=msg)
    call expect(stat, NANOPUSH_OK, msg, "", "good cubic roots")
    call check(size(roots) == 3, "good cubic roots: three real roots at yn = 1 nm")

    ! Status names.
    call check(nanopush_status_name(NANOPUSH_BAD_INPUT) == "bad input", "status name")
    call check(nanopush_api_version() == 800, "API version 0.8.0")

    call finish("test_fortran_errors")
    print '(a)', "all checks hold"
  end block

contains

  subroutine failing_rhs(t, y, dydt, ctx, stat)
    real(dp), intent(in) :: t, y(:)
    real(dp), intent(out) :: dydt(:)
    class(nanopush_context), intent(inout) :: ctx
    integer, intent(inout) :: stat
    call ode_rhs(t, y, dydt, ctx, stat)
    if (t > 0.5_dp) stat = 7
  end subroutine failing_rhs


  !> The status is the expected one and the message contains `fragment` (empty when OK).
  subroutine expect(stat, want, msg, fragment, what)
    integer, intent(in) :: stat, want
    character(len=*), intent(in) :: msg, fragment, what
    print '(a,": stat = ",i0,", errmsg = """,a,"""")', what, stat, msg
    call check(stat == want, what // ": status")
    if (want == NANOPUSH_OK) then
      call check(len(msg) == 0, what // ": empty message on success")
    else
      call check(index(msg, fragment) > 0, what // ": message contains '" // fragment // "'")
    end if
  end subroutine expect

  function replace(s, old, new) result(r)
    character(len=*), intent(in) :: s, old, new
    character(len=:), allocatable :: r
    integer :: i
    i = index(s, old)
    r = s(:i - 1) // new // s(i + len(old):)
  end function replace

end program test_fortran_errors
