!> nanopush: the modern C++ solver from Fortran (`use nanopush`).
!>
!> Thin idiomatic wrappers over the C API (bindings/nanopush.h, target nanopush::capi), reached
!> through bind(C) interfaces; no mangled names. All quantities SI.
!>
!> Errors: every wrapper takes optional `stat` (integer) and `errmsg` (deferred-length
!> character, allocated by the call) arguments.
!>   - With `stat` present, the caller decides: stat = NANOPUSH_OK (0) on success, else one of
!>     the NANOPUSH_* codes below, and errmsg (if present) holds the message from C++, e.g.
!>     "object.mass = -1: must be > 0 (kg)".
!>   - Without `stat`, an error stops the program with `error stop "nanopush: <message>"`.
!>
!> Scenes: type(nanopush_scene) holds an opaque C handle; create it with nanopush_load_scene or
!> nanopush_parse_scene and free it with nanopush_destroy (there is no finalizer: do not copy a
!> scene by assignment). nanopush_run returns the trajectory as an allocatable array
!> traj(NANOPUSH_TRAJECTORY_COLUMNS, nrows), one output time per column; rows of traj are
!> t, x, y, theta, vx, vy, omega, fx, fy, mf (s, m, m, rad, m/s, m/s, rad/s, N, N, N m).
!>
!> Rough-surface scenes: nanopush_run(..., law="thesis"|"printed"|"coulomb") chooses the friction law.
!> Extended precision (smooth scenes): nanopush_run(..., precision="long"|"quad", state_ext=q)
!> integrates in long double or __float128 and returns the state in q(6, nrows), kind nanopush_qp.
!>
!> Closed forms (same numbers as the C++ library, bit for bit): nanopush_friction_wrench and
!> nanopush_friction_from_velocity (friction resultant over a rectangle), the iCOR formulas
!> nanopush_icor_<name> (eqs 4.1, 4.2, 4.3, 4.13, 4.7, 4.8, 4.10, 4.11, 5.2, 5.5: functions
!> returning the value, NaN on failure) and nanopush_icor_cubic_roots (eq 5.4, Brent or Eigen).
!> Friction coefficient from measurements, with its propagated uncertainty (the numbers of
!> `nanopush icor estimate-mu`): nanopush_estimate_mu_from_force (Fig 4.4) and
!> nanopush_estimate_mu_from_icor (Fig 4.5); N observations combined, with a chi^2 consistency
!> check (the numbers of `nanopush fit-icor`): nanopush_estimate_mu_batch.
!> Scene keys fitted to observed motion (the numbers of `nanopush fit`): nanopush_fit.
!>
!> Your own ODE with the C++ Bulirsch-Stoer (nanopush_integrate): write a subroutine with the
!> interface nanopush_rhs_fn,
!>
!>     subroutine my_rhs(t, y, dydt, ctx, stat)
!>       real(dp), intent(in) :: t, y(:)
!>       real(dp), intent(out) :: dydt(:)
!>       class(nanopush_context), intent(inout) :: ctx
!>       integer, intent(inout) :: stat      ! 0 on entry; set non-zero to stop the integration
!>
!> Its data travel in `ctx`: extend nanopush_context with your fields
!> (`type, extends(nanopush_context) :: my_data; real(dp) :: k; end type`), pass your object as
!> the ctx argument of nanopush_integrate and reach the fields with `select type (ctx)`.
!> A bind(C) trampoline receives the address of a closure (your procedure and your ctx) as the C
!> callback's udata, so there is no module or global state: integrations are re-entrant, may be
!> nested, and may run on several threads at once (one ctx per thread, or a read-only one).
module nanopush
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_int64_t, c_char, c_ptr, c_funptr, &
                                         c_null_ptr, c_null_char, c_associated, c_loc, c_funloc, &
                                         c_f_pointer
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
  implicit none
  private

  !> Real kind of every nanopush quantity.
  integer, parameter, public :: dp = c_double
  !> Quadruple precision (gfortran: real(16), __float128): the kind of the extended-precision
  !> states of nanopush_run(..., precision="long"|"quad", state_ext=...).
  integer, parameter, public :: nanopush_qp = selected_real_kind(30)

  !> Status codes (bindings/nanopush.h). 1..5 are the Bulirsch-Stoer codes (as the F77 IERR).
  integer, parameter, public :: NANOPUSH_OK = 0, NANOPUSH_BAD_INPUT = 1, &
                                NANOPUSH_TOO_MANY_STEPS = 2, NANOPUSH_STEP_UNDERFLOW = 3, &
                                NANOPUSH_RHS_FAILED = 4, NANOPUSH_NOT_FINITE = 5, &
                                NANOPUSH_SOLVER_FAILED = 6, NANOPUSH_NULL_HANDLE = 7, &
                                NANOPUSH_BUFFER_TOO_SMALL = 8, NANOPUSH_OUT_OF_MEMORY = 9, &
                                NANOPUSH_INTERNAL = 10, NANOPUSH_TOO_MUCH_ACCURACY = 11, &
                                NANOPUSH_TOUT_TOO_CLOSE = 12, NANOPUSH_NO_STATIC_FRICTION = 13, &
                                NANOPUSH_LAW_BLOWUP = 14, NANOPUSH_ACCURACY_NOT_REACHED = 15
  !> Entries of nanopush_run's error estimate (docs/accuracy.md): the final pose in the accuracy
  !> norm, |dx| [m], |dy| [m], |dtheta| [rad], the norm's max over the trajectory, the rtol used,
  !> RHS evaluations in all; NaN where not estimated.
  integer, parameter, public :: NANOPUSH_ERROR_SIZE = 7
  !> Rows of a trajectory array and their meaning.
  integer, parameter, public :: NANOPUSH_TRAJECTORY_COLUMNS = 10
  !> Components of the state (x, y, theta, vx, vy, omega), the rows of state_ext.
  integer, parameter, public :: NANOPUSH_STATE_SIZE = 6
  integer, parameter, public :: NANOPUSH_T = 1, NANOPUSH_X = 2, NANOPUSH_Y = 3, &
                                NANOPUSH_THETA = 4, NANOPUSH_VX = 5, NANOPUSH_VY = 6, &
                                NANOPUSH_OMEGA = 7, NANOPUSH_FX = 8, NANOPUSH_FY = 9, NANOPUSH_MF = 10

  !> Solvers of the constrained cubic (eq 5.4) for nanopush_icor_cubic_roots.
  integer, parameter, public :: NANOPUSH_CUBIC_BRENT = 1, NANOPUSH_CUBIC_EIGEN = 2

  !> Pressure distributions of nanopush_estimate_mu_batch (thesis 4.2.3.1 and 4.2.3.2).
  integer, parameter, public :: NANOPUSH_PRESSURE_KNOWN = 0, NANOPUSH_PRESSURE_UNKNOWN = 1

  !> A scene (object, push, initial state, solver settings): opaque C handle.
  type, public :: nanopush_scene
    private
    type(c_ptr) :: ptr = c_null_ptr
  end type nanopush_scene

  !> Base type of the user data handed to a right-hand side; extend it with your fields.
  type, public :: nanopush_context
  end type nanopush_context

  abstract interface
    !> A right-hand side dydt = f(t, y) for nanopush_integrate. Set stat non-zero to stop the
    !> integration (nanopush_integrate then reports NANOPUSH_RHS_FAILED quoting the value).
    subroutine nanopush_rhs_fn(t, y, dydt, ctx, stat)
      import :: dp, nanopush_context
      real(dp), intent(in) :: t
      real(dp), intent(in) :: y(:)
      real(dp), intent(out) :: dydt(:)
      class(nanopush_context), intent(inout) :: ctx
      integer, intent(inout) :: stat
    end subroutine nanopush_rhs_fn
  end interface

  public :: nanopush_rhs_fn
  public :: nanopush_api_version, nanopush_status_name
  public :: nanopush_load_scene, nanopush_parse_scene, nanopush_scene_preset, nanopush_destroy, nanopush_scene_info
  public :: nanopush_scene_set
  public :: nanopush_run, nanopush_integrate, nanopush_compare
  public :: nanopush_friction_wrench, nanopush_friction_from_velocity
  public :: nanopush_icor_experimental_fit, nanopush_icor_falvo, nanopush_icor_li, &
            nanopush_icor_unknown_pressure, nanopush_icor_known_pressure, nanopush_icor_minimum_force, &
            nanopush_icor_force_from_icor, nanopush_icor_force_unknown_pressure, &
            nanopush_icor_constrained_force, nanopush_icor_impulsive, nanopush_icor_cubic_roots, &
            nanopush_icor_nanorod, nanopush_icor_rod_properties
  public :: nanopush_estimate_mu_from_force, nanopush_estimate_mu_from_icor
  public :: nanopush_estimate_mu_batch, nanopush_fit, nanopush_plan, nanopush_assemble

  !> Set a scene key after loading, validated as in the file (docs/scenes.md):
  !> call nanopush_scene_set(scene, "surface.mu", 0.1_dp, stat=stat); a value may be real(dp),
  !> an integer, or text read as the key's type ("coulomb", "0.1").
  interface nanopush_scene_set
    module procedure scene_set_real, scene_set_integer, scene_set_text
  end interface nanopush_scene_set

  !> Free a handle (safe on a handle never created or already freed).
  interface nanopush_destroy
    module procedure destroy_scene
  end interface nanopush_destroy

  !> What the trampoline needs: the user's procedure and context (address passed as udata).
  type :: rhs_closure
    procedure(nanopush_rhs_fn), pointer, nopass :: f => null()
    class(nanopush_context), pointer :: ctx => null()
  end type rhs_closure

  ! ---- The C API (bindings/nanopush.h) --------------------------------------------------
  interface
    integer(c_int) function c_get_api_version() bind(C, name="nanopush_get_api_version")
      import :: c_int
    end function c_get_api_version
    type(c_ptr) function c_status_name(status) bind(C, name="nanopush_status_name")
      import :: c_int, c_ptr
      integer(c_int), value, intent(in) :: status
    end function c_status_name
    type(c_ptr) function c_new_error() bind(C, name="nanopush_new_error")
      import :: c_ptr
    end function c_new_error
    integer(c_int) function c_check_error(error) bind(C, name="nanopush_check_error")
      import :: c_int, c_ptr
      type(c_ptr), value, intent(in) :: error
    end function c_check_error
    integer(c_int) function c_get_error(error, buffer, size) bind(C, name="nanopush_get_error")
      import :: c_int, c_ptr, c_char
      type(c_ptr), value, intent(in) :: error
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int), value, intent(in) :: size
    end function c_get_error
    subroutine c_delete_error(error) bind(C, name="nanopush_delete_error")
      import :: c_ptr
      type(c_ptr), intent(inout) :: error
    end subroutine c_delete_error
    type(c_ptr) function c_load_scene(error, path) bind(C, name="nanopush_load_scene")
      import :: c_ptr, c_char
      type(c_ptr), value, intent(in) :: error
      character(kind=c_char), intent(in) :: path(*)
    end function c_load_scene
    type(c_ptr) function c_parse_scene(error, text, source) bind(C, name="nanopush_parse_scene")
      import :: c_ptr, c_char
      type(c_ptr), value, intent(in) :: error
      character(kind=c_char), intent(in) :: text(*), source(*)
    end function c_parse_scene
    type(c_ptr) function c_scene_preset(error, name, dir) bind(C, name="nanopush_scene_preset")
      import :: c_ptr, c_char
      type(c_ptr), value, intent(in) :: error
      character(kind=c_char), intent(in) :: name(*), dir(*)
    end function c_scene_preset
    integer(c_int) function c_scene_set_real(error, scene, key, value) bind(C, name="nanopush_scene_set_real")
      import :: c_ptr, c_char, c_int, c_double
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: key(*)
      real(c_double), value, intent(in) :: value
    end function c_scene_set_real
    integer(c_int) function c_scene_set_string(error, scene, key, value) bind(C, name="nanopush_scene_set_string")
      import :: c_ptr, c_char, c_int
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: key(*), value(*)
    end function c_scene_set_string
    subroutine c_delete_scene(scene) bind(C, name="nanopush_delete_scene")
      import :: c_ptr
      type(c_ptr), intent(inout) :: scene
    end subroutine c_delete_scene
    integer(c_int) function c_scene_get_name(error, scene, buffer, size) &
        bind(C, name="nanopush_scene_get_name")
      import :: c_int, c_ptr, c_char
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int), value, intent(in) :: size
    end function c_scene_get_name
    integer(c_int) function c_scene_get_info(error, scene, t_end, samples, mass, inertia, &
                                             initial) bind(C, name="nanopush_scene_get_info")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error, scene
      real(c_double), intent(out) :: t_end, mass, inertia, initial(6)
      integer(c_int), intent(out) :: samples
    end function c_scene_get_info
    integer(c_int) function c_scene_get_push(error, scene, push) bind(C, name="nanopush_scene_get_push")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error, scene
      real(c_double), intent(out) :: push(4)
    end function c_scene_get_push
    integer(c_int) function c_compare(error, scene, method, law, rtol, atol, tolerance, agree, kind, figures) &
        bind(C, name="nanopush_compare")
      import :: c_int, c_ptr, c_char, c_double
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: method(*), law(*)
      real(c_double), value, intent(in) :: rtol, atol, tolerance
      integer(c_int), intent(out) :: agree, kind
      real(c_double), intent(out) :: figures(9)
    end function c_compare
    type(c_ptr) function c_run_scene_ex(error, scene, engine, method, law, rtol, atol) &
        bind(C, name="nanopush_run_scene_ex")
      import :: c_ptr, c_char, c_double
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: engine(*), method(*), law(*)
      real(c_double), value, intent(in) :: rtol, atol
    end function c_run_scene_ex
    type(c_ptr) function c_run_scene_precision(error, scene, engine, method, law, precision, rtol, atol) &
        bind(C, name="nanopush_run_scene_precision")
      import :: c_ptr, c_char, c_double
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: engine(*), method(*), law(*), precision(*)
      real(c_double), value, intent(in) :: rtol, atol
    end function c_run_scene_precision
    type(c_ptr) function c_run_scene_accuracy(error, scene, engine, method, law, precision, rtol, atol, &
                                              accuracy, error_estimate) bind(C, name="nanopush_run_scene_accuracy")
      import :: c_ptr, c_char, c_double, c_int
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: engine(*), method(*), law(*), precision(*)
      real(c_double), value, intent(in) :: rtol, atol, accuracy
      integer(c_int), value, intent(in) :: error_estimate
    end function c_run_scene_accuracy
    integer(c_int) function c_trajectory_get_error(error, trajectory, estimate) &
        bind(C, name="nanopush_trajectory_get_error")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error, trajectory
      real(c_double), intent(out) :: estimate(*)
    end function c_trajectory_get_error
    integer(c_int) function c_trajectory_get_outcome(error, trajectory, buffer, size) &
        bind(C, name="nanopush_trajectory_get_outcome")
      import :: c_int, c_ptr, c_char
      type(c_ptr), value, intent(in) :: error, trajectory
      character(kind=c_char), intent(out) :: buffer(*)
      integer(c_int), value, intent(in) :: size
    end function c_trajectory_get_outcome
    integer(c_int) function c_trajectory_get_state_extended(error, trajectory, capacity, hi, lo) &
        bind(C, name="nanopush_trajectory_get_state_extended")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error, trajectory
      integer(c_int), value, intent(in) :: capacity
      real(c_double), intent(out) :: hi(*), lo(*)
    end function c_trajectory_get_state_extended
    subroutine c_delete_trajectory(trajectory) bind(C, name="nanopush_delete_trajectory")
      import :: c_ptr
      type(c_ptr), intent(inout) :: trajectory
    end subroutine c_delete_trajectory
    integer(c_int) function c_trajectory_get_size(error, trajectory, rows) &
        bind(C, name="nanopush_trajectory_get_size")
      import :: c_int, c_ptr
      type(c_ptr), value, intent(in) :: error, trajectory
      integer(c_int), intent(out) :: rows
    end function c_trajectory_get_size
    integer(c_int) function c_trajectory_get_data(error, trajectory, capacity, data) &
        bind(C, name="nanopush_trajectory_get_data")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error, trajectory
      integer(c_int), value, intent(in) :: capacity
      real(c_double), intent(out) :: data(*)
    end function c_trajectory_get_data
    integer(c_int) function c_trajectory_get_counts(error, trajectory, counts) &
        bind(C, name="nanopush_trajectory_get_counts")
      import :: c_int, c_ptr, c_int64_t
      type(c_ptr), value, intent(in) :: error, trajectory
      integer(c_int64_t), intent(out) :: counts(3)
    end function c_trajectory_get_counts
    type(c_ptr) function c_new_integrator(error, n, method, rtol, atol, natol) &
        bind(C, name="nanopush_new_integrator")
      import :: c_ptr, c_int, c_char, c_double
      type(c_ptr), value, intent(in) :: error
      integer(c_int), value, intent(in) :: n, natol
      character(kind=c_char), intent(in) :: method(*)
      real(c_double), value, intent(in) :: rtol
      real(c_double), intent(in) :: atol(*)
    end function c_new_integrator
    subroutine c_delete_integrator(integrator) bind(C, name="nanopush_delete_integrator")
      import :: c_ptr
      type(c_ptr), intent(inout) :: integrator
    end subroutine c_delete_integrator
    integer(c_int) function c_integrator_set_steps(error, integrator, h0, hmax, maxstp) &
        bind(C, name="nanopush_integrator_set_steps")
      import :: c_int, c_ptr, c_double, c_int64_t
      type(c_ptr), value, intent(in) :: error, integrator
      real(c_double), value, intent(in) :: h0, hmax
      integer(c_int64_t), value, intent(in) :: maxstp
    end function c_integrator_set_steps
    integer(c_int) function c_integrator_set_extrapolation(error, integrator, kmax, extrap) &
        bind(C, name="nanopush_integrator_set_extrapolation")
      import :: c_int, c_ptr
      type(c_ptr), value, intent(in) :: error, integrator
      integer(c_int), value, intent(in) :: kmax, extrap
    end function c_integrator_set_extrapolation
    integer(c_int) function c_integrate(error, integrator, rhs, udata, t0, y, nout, tout, yout, &
                                        counts) bind(C, name="nanopush_integrate")
      import :: c_int, c_ptr, c_funptr, c_double, c_int64_t
      type(c_ptr), value, intent(in) :: error, integrator, udata
      type(c_funptr), value, intent(in) :: rhs
      real(c_double), value, intent(in) :: t0
      real(c_double), intent(inout) :: y(*)
      integer(c_int), value, intent(in) :: nout
      real(c_double), intent(in) :: tout(*)
      real(c_double), intent(inout) :: yout(*)
      integer(c_int64_t), intent(out) :: counts(3)
    end function c_integrate
    integer(c_int) function c_friction_wrench(error, a, b, muN, R, alpha, sense, w) &
        bind(C, name="nanopush_friction_wrench")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: a, b, muN, R, alpha
      integer(c_int), value, intent(in) :: sense
      real(c_double), intent(inout) :: w(3)
    end function c_friction_wrench
    integer(c_int) function c_friction_from_velocity(error, a, b, muN, vx, vy, omega, w) &
        bind(C, name="nanopush_friction_from_velocity")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: a, b, muN, vx, vy, omega
      real(c_double), intent(inout) :: w(3)
    end function c_friction_from_velocity
    ! iCOR formulas: inputs by value, the result through a pointer (left unchanged on failure).
    integer(c_int) function c_icor_experimental_fit(error, yn, L, R) &
        bind(C, name="nanopush_icor_experimental_fit")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: yn, L
      real(c_double), intent(inout) :: R
    end function c_icor_experimental_fit
    integer(c_int) function c_icor_falvo(error, yn, L, R) bind(C, name="nanopush_icor_falvo")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: yn, L
      real(c_double), intent(inout) :: R
    end function c_icor_falvo
    integer(c_int) function c_icor_li(error, yn, L, R) bind(C, name="nanopush_icor_li")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: yn, L
      real(c_double), intent(inout) :: R
    end function c_icor_li
    integer(c_int) function c_icor_unknown_pressure(error, yn, L, R) &
        bind(C, name="nanopush_icor_unknown_pressure")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: yn, L
      real(c_double), intent(inout) :: R
    end function c_icor_unknown_pressure
    integer(c_int) function c_icor_known_pressure(error, mu, W, yn, F, L, R) &
        bind(C, name="nanopush_icor_known_pressure")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: mu, W, yn, F, L
      real(c_double), intent(inout) :: R
    end function c_icor_known_pressure
    integer(c_int) function c_icor_minimum_force(error, mu, W, yn, L, F) &
        bind(C, name="nanopush_icor_minimum_force")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: mu, W, yn, L
      real(c_double), intent(inout) :: F
    end function c_icor_minimum_force
    integer(c_int) function c_icor_force_from_icor(error, mu, W, R, L, F) &
        bind(C, name="nanopush_icor_force_from_icor")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: mu, W, R, L
      real(c_double), intent(inout) :: F
    end function c_icor_force_from_icor
    integer(c_int) function c_icor_force_unknown_pressure(error, mu, W, R, yn, L, F) &
        bind(C, name="nanopush_icor_force_unknown_pressure")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: mu, W, R, yn, L
      real(c_double), intent(inout) :: F
    end function c_icor_force_unknown_pressure
    integer(c_int) function c_icor_constrained_force(error, mu, W, R, yn, L, k2, F) &
        bind(C, name="nanopush_icor_constrained_force")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: mu, W, R, yn, L, k2
      real(c_double), intent(inout) :: F
    end function c_icor_constrained_force
    integer(c_int) function c_icor_impulsive(error, yn, k2, R) bind(C, name="nanopush_icor_impulsive")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: yn, k2
      real(c_double), intent(inout) :: R
    end function c_icor_impulsive
    integer(c_int) function c_icor_cubic_roots(error, yn, L, k2, method, roots, nroots, ncomplex, &
        at_infinity, negative, positive, max_residual) bind(C, name="nanopush_icor_cubic_roots")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), value, intent(in) :: yn, L, k2
      integer(c_int), value, intent(in) :: method
      real(c_double), intent(inout) :: roots(3), negative, positive, max_residual
      integer(c_int), intent(inout) :: nroots, ncomplex, at_infinity
    end function c_icor_cubic_roots
    integer(c_int) function c_icor_nanorod(error, rod) bind(C, name="nanopush_icor_nanorod")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), intent(inout) :: rod(6)
    end function c_icor_nanorod
    integer(c_int) function c_icor_rod_properties(error, rod, props) &
        bind(C, name="nanopush_icor_rod_properties")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), intent(in) :: rod(6)
      real(c_double), intent(inout) :: props(5)
    end function c_icor_rod_properties
    integer(c_int) function c_estimate_mu_from_force(error, rod, force, sigma_force, yn, sigma_yn, &
        sigma_L, sigma_H, mu, sigma, load, derivatives) bind(C, name="nanopush_estimate_mu_from_force")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), intent(in) :: rod(6)
      real(c_double), value, intent(in) :: force, sigma_force, yn, sigma_yn, sigma_L, sigma_H
      real(c_double), intent(inout) :: mu, sigma, load, derivatives(4)
    end function c_estimate_mu_from_force
    integer(c_int) function c_estimate_mu_from_icor(error, rod, force, sigma_force, R, sigma_R, &
        sigma_L, sigma_H, mu, sigma, load, derivatives) bind(C, name="nanopush_estimate_mu_from_icor")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), intent(in) :: rod(6)
      real(c_double), value, intent(in) :: force, sigma_force, R, sigma_R, sigma_L, sigma_H
      real(c_double), intent(inout) :: mu, sigma, load, derivatives(4)
    end function c_estimate_mu_from_icor
    integer(c_int) function c_estimate_mu_batch(error, rod, n, force, sigma_force, yn, sigma_yn, R, sigma_R, &
        pressure, sigma_L, sigma_H, alpha, result, dof, consistent, rows, equations) &
        bind(C, name="nanopush_estimate_mu_batch")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error
      real(c_double), intent(in) :: rod(6)
      integer(c_int), value, intent(in) :: n, pressure
      real(c_double), intent(in) :: force(*), sigma_force(*), yn(*), sigma_yn(*), R(*), sigma_R(*)
      real(c_double), value, intent(in) :: sigma_L, sigma_H, alpha
      real(c_double), intent(inout) :: result(11), rows(*)
      integer(c_int), intent(inout) :: dof, consistent, equations(*)
    end function c_estimate_mu_batch
    integer(c_int) function c_fit_trajectory(error, scene, data_path, free_keys, law, sigma, nfree, values, &
        stderrs, summary, converged, json, json_size, json_length) bind(C, name="nanopush_fit_trajectory")
      import :: c_int, c_ptr, c_double, c_char
      type(c_ptr), value, intent(in) :: error, scene
      character(kind=c_char), intent(in) :: data_path(*), free_keys(*), law(*), sigma(*)
      integer(c_int), value, intent(in) :: nfree, json_size
      real(c_double), intent(inout) :: values(*), stderrs(*), summary(6)
      integer(c_int), intent(inout) :: converged, json_length
      character(kind=c_char), intent(inout) :: json(*)
    end function c_fit_trajectory
    integer(c_int) function c_plan_robust(error, scene, goal, tolerance, objective, max_pushes, tip_mu_range, &
        start_shift, capacity, pushes, n_pushes, summary) bind(C, name="nanopush_plan_robust")
      import :: c_int, c_ptr, c_double, c_char
      type(c_ptr), value, intent(in) :: error, scene, tip_mu_range, start_shift
      real(c_double), intent(in) :: goal(3), tolerance(2)
      character(kind=c_char), intent(in) :: objective(*)
      integer(c_int), value, intent(in) :: max_pushes, capacity
      real(c_double), intent(inout) :: pushes(*), summary(8)
      integer(c_int), intent(inout) :: n_pushes
    end function c_plan_robust
    integer(c_int) function c_assemble(error, scene, n, objects, slots, tolerance, max_pushes, gap, capacity, &
        pushes, n_pushes, slot_of, final_poses, assembled) bind(C, name="nanopush_assemble")
      import :: c_int, c_ptr, c_double
      type(c_ptr), value, intent(in) :: error, scene
      integer(c_int), value, intent(in) :: n, max_pushes, capacity
      real(c_double), intent(in) :: objects(*), slots(*), tolerance(2)
      real(c_double), value, intent(in) :: gap
      real(c_double), intent(inout) :: pushes(*), final_poses(*)
      integer(c_int), intent(inout) :: n_pushes, slot_of(*), assembled
    end function c_assemble
    integer(c_int) function c_strlen(s) bind(C, name="strlen")
      import :: c_int, c_ptr
      type(c_ptr), value, intent(in) :: s
    end function c_strlen
  end interface

contains

  !> Version of the C API: major * 10000 + minor * 100 + patch.
  integer function nanopush_api_version()
    nanopush_api_version = int(c_get_api_version())
  end function nanopush_api_version

  !> Short description of a status code, e.g. "bad input".
  function nanopush_status_name(status) result(name)
    integer, intent(in) :: status
    character(len=:), allocatable :: name
    name = c_string(c_status_name(int(status, c_int)))
  end function nanopush_status_name

  !> Load a scene from a TOML file (docs/scenes.md).
  subroutine nanopush_load_scene(scene, path, stat, errmsg)
    type(nanopush_scene), intent(inout) :: scene
    character(len=*), intent(in) :: path
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    call destroy_scene(scene)
    err = c_new_error()
    scene%ptr = c_load_scene(err, to_c(path))
    call finish(err, "nanopush_load_scene", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_load_scene

  !> Load a preset scene by name ("fig3_6a"; `nanopush presets` lists them), as the command line
  !> finds it. scenes_dir (optional): the presets directory; absent = $NANOPUSH_SCENES, else the
  !> installed presets of the library's prefix (<prefix>/share/nanopush/scenes).
  subroutine nanopush_scene_preset(scene, name, scenes_dir, stat, errmsg)
    type(nanopush_scene), intent(inout) :: scene
    character(len=*), intent(in) :: name
    character(len=*), intent(in), optional :: scenes_dir
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    call destroy_scene(scene)
    err = c_new_error()
    if (present(scenes_dir)) then
      scene%ptr = c_scene_preset(err, to_c(name), to_c(scenes_dir))
    else
      scene%ptr = c_scene_preset(err, to_c(name), to_c(""))
    end if
    call finish(err, "nanopush_scene_preset", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_scene_preset

  !> Parse a scene from TOML text; source_name (default "<string>") is quoted in messages.
  subroutine nanopush_parse_scene(scene, toml_text, source_name, stat, errmsg)
    type(nanopush_scene), intent(inout) :: scene
    character(len=*), intent(in) :: toml_text
    character(len=*), intent(in), optional :: source_name
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    call destroy_scene(scene)
    err = c_new_error()
    if (present(source_name)) then
      scene%ptr = c_parse_scene(err, to_c(toml_text), to_c(source_name))
    else
      scene%ptr = c_parse_scene(err, to_c(toml_text), to_c("<string>"))
    end if
    call finish(err, "nanopush_parse_scene", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_parse_scene

  subroutine scene_set_real(scene, key, value, stat, errmsg)
    type(nanopush_scene), intent(inout) :: scene
    character(len=*), intent(in) :: key
    real(dp), intent(in) :: value
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    integer(c_int) :: st
    err = c_new_error()
    st = c_scene_set_real(err, scene%ptr, to_c(key), real(value, c_double))
    call finish(err, "nanopush_scene_set", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine scene_set_real

  subroutine scene_set_integer(scene, key, value, stat, errmsg)
    type(nanopush_scene), intent(inout) :: scene
    character(len=*), intent(in) :: key
    integer, intent(in) :: value
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    call scene_set_real(scene, key, real(value, dp), stat, errmsg)
  end subroutine scene_set_integer

  subroutine scene_set_text(scene, key, value, stat, errmsg)
    type(nanopush_scene), intent(inout) :: scene
    character(len=*), intent(in) :: key, value
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    integer(c_int) :: st
    err = c_new_error()
    st = c_scene_set_string(err, scene%ptr, to_c(key), to_c(value))
    call finish(err, "nanopush_scene_set", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine scene_set_text

  subroutine destroy_scene(scene)
    type(nanopush_scene), intent(inout) :: scene
    call c_delete_scene(scene%ptr)
  end subroutine destroy_scene

  !> Scene summary: name, t_end [s], samples (output times 0..t_end), mass [kg], inertia
  !> [kg m^2], initial(6) = (x [m], y [m], theta [rad], vx [m/s], vy [m/s], omega [rad/s]),
  !> push(4) = (F [N], beta [rad] world direction, pbx [m], pby [m] body-axes point of action).
  subroutine nanopush_scene_info(scene, name, t_end, samples, mass, inertia, initial, push, stat, &
                                 errmsg)
    type(nanopush_scene), intent(in) :: scene
    character(len=:), allocatable, intent(out), optional :: name
    real(dp), intent(out), optional :: t_end, mass, inertia, initial(6), push(4)
    integer, intent(out), optional :: samples
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double) :: te, m, inert, y0(6), pu(4)
    integer(c_int) :: ns, len_name, st
    character(kind=c_char), allocatable :: buf(:)
    err = c_new_error()
    st = c_scene_get_info(err, scene%ptr, te, ns, m, inert, y0)
    if (st == 0) st = c_scene_get_push(err, scene%ptr, pu)
    if (st == 0 .and. present(name)) then
      allocate (buf(1))
      len_name = c_scene_get_name(err, scene%ptr, buf, 1_c_int)
      if (len_name >= 0) then
        deallocate (buf)
        allocate (buf(len_name + 1))
        len_name = c_scene_get_name(err, scene%ptr, buf, len_name + 1_c_int)
        name = from_c(buf, int(len_name))
      end if
    end if
    if (present(t_end)) t_end = te
    if (present(samples)) samples = int(ns)
    if (present(mass)) mass = m
    if (present(inertia)) inertia = inert
    if (present(initial)) initial = y0
    if (present(push)) push = pu
    call finish(err, "nanopush_scene_info", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_scene_info

  !> Integrate a scene as `nanopush run` does. traj(NANOPUSH_TRAJECTORY_COLUMNS, nrows) is
  !> allocated: traj(:, i) = (t, x, y, theta, vx, vy, omega, fx, fy, mf) at output time i.
  !>   engine "cxx" or "f77", method "faithful", "modern" or "dop853" (Dormand-Prince 8(5,3),
  !>   double, not under the coulomb law) (or "cvode": rough scenes, coulomb law, engine cxx)
  !>   or "auto" (by rtol) (default: the scene's; auto unless it states one); law, for rough scenes, "thesis", "printed" or "coulomb"
  !>   (default: the scene's [surface] law);
  !>   rtol (default or 0: the scene's); atol (default or < 0: the scene's; 0 = automatic);
  !>   counts(3) = (RHS evaluations, accepted steps, rejected steps);
  !>   precision "double", "long" (x87 80-bit) or "quad" (__float128) (default: the scene's
  !>   [solver] precision; long and quad need engine "cxx" and, on a smooth scene, method
  !>   "faithful", "modern" or "auto", on a rough scene the thesis or coulomb law with method
  !>   "modern" or "auto" (docs/accuracy.md, "References with more digits")): traj holds the
  !>   values rounded to double, and state_ext(6, nrows), if present, the state
  !>   (x, y, theta, vx, vy, omega) at each output time in kind nanopush_qp, with the digits of
  !>   the integration (to about 1e-32 relative for quad; exact for long and double).
  !>   accuracy: the error asked for of the final pose, in [1e-14, 0.1] (0: none; default: the
  !>   scene's solver.accuracy); error_estimate: estimate the error (default: the scene's);
  !>   error(NANOPUSH_ERROR_SIZE): the estimate (docs/accuracy.md); outcome: "ok" or "at_rest";
  !>   for a failed run the outcome its stat stands for (docs/errors.md): "no_static_friction",
  !>   "law_blowup", "accuracy_not_reached" (stat 13-15) or "solver_failure" (stat 2-6), and ""
  !>   when no run was made (bad input, a null scene).
  !> On failure traj (and state_ext) are allocated with zero columns.
  subroutine nanopush_run(scene, traj, engine, method, rtol, atol, counts, stat, errmsg, law, &
                          precision, state_ext, accuracy, error_estimate, error, outcome)
    type(nanopush_scene), intent(in) :: scene
    real(dp), allocatable, intent(out) :: traj(:, :)
    character(len=*), intent(in), optional :: engine, method, law, precision
    real(dp), intent(in), optional :: accuracy
    logical, intent(in), optional :: error_estimate
    real(dp), intent(out), optional :: error(NANOPUSH_ERROR_SIZE)
    character(len=:), allocatable, intent(out), optional :: outcome
    real(nanopush_qp), allocatable, intent(out), optional :: state_ext(:, :)
    real(dp), intent(in), optional :: rtol, atol
    integer(c_int64_t), intent(out), optional :: counts(3)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err, tr
    character(len=:), allocatable :: msg
    real(c_double) :: r, a
    integer(c_int) :: nrows, st
    integer(c_int64_t) :: cnt(3)
    real(c_double), allocatable :: hi(:, :), lo(:, :)
    real(c_double) :: acc, est(NANOPUSH_ERROR_SIZE)
    integer(c_int) :: want_estimate, nchar
    character(kind=c_char, len=32) :: oc
    r = 0
    a = -1
    acc = -1
    want_estimate = -1
    if (present(rtol)) r = rtol
    if (present(atol)) a = atol
    if (present(accuracy)) acc = accuracy
    if (present(error_estimate)) want_estimate = merge(1_c_int, 0_c_int, error_estimate)
    cnt = 0
    nrows = 0
    est = ieee_value(est, ieee_quiet_nan)
    err = c_new_error()
    tr = c_run_scene_accuracy(err, scene%ptr, to_c(opt(engine)), to_c(opt(method)), to_c(opt(law)), &
                              to_c(opt(precision)), r, a, acc, want_estimate)
    if (c_associated(tr)) then
      st = c_trajectory_get_size(err, tr, nrows)
      if (st == 0) st = c_trajectory_get_counts(err, tr, cnt)
      if (st == 0) st = c_trajectory_get_error(err, tr, est)
      if (st == 0 .and. present(outcome)) then
        nchar = c_trajectory_get_outcome(err, tr, oc, len(oc, kind=c_int))
        if (nchar >= 0) outcome = oc(1:min(nchar, len(oc)))
      end if
      if (st /= 0) nrows = 0
      allocate (traj(NANOPUSH_TRAJECTORY_COLUMNS, nrows))
      if (st == 0) st = c_trajectory_get_data(err, tr, nrows, traj)
      if (present(state_ext) .and. st == 0) then
        allocate (hi(NANOPUSH_STATE_SIZE, nrows), lo(NANOPUSH_STATE_SIZE, nrows))
        st = c_trajectory_get_state_extended(err, tr, nrows, hi, lo)
        if (st == 0) then
          state_ext = real(hi, nanopush_qp) + real(lo, nanopush_qp)
        end if
      end if
      call c_delete_trajectory(tr)
    end if
    if (.not. allocated(traj)) allocate (traj(NANOPUSH_TRAJECTORY_COLUMNS, 0))
    if (present(state_ext)) then
      if (.not. allocated(state_ext)) allocate (state_ext(NANOPUSH_STATE_SIZE, 0))
    end if
    if (present(counts)) counts = cnt
    if (present(error)) error = est
    if (present(outcome)) then
      ! A failed run: the outcome its status stands for, as C's status and Python's
      ! SolverError.outcome give it (docs/errors.md); "" when no run was made (bad input).
      if (.not. allocated(outcome)) outcome = failed_outcome(err)
    end if
    call finish(err, "nanopush_run", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_run

  !> Both engines on one scene, judged column by column as `nanopush compare` does
  !> (nanopush_compare in nanopush.h): method "faithful" (default; same steps, judged against
  !> tolerance, default 100 rtol), "modern" or "dop853" (judged by convergence against both
  !> engines at rtol 1e-14); law "thesis" or "printed" (default the scene's). agree: .true.
  !> when the engines agree; convergence: .true. for a convergence verdict; figures(9): per
  !> column x .. mf the figure judged (relative to the column's scale).
  subroutine nanopush_compare(scene, agree, method, law, rtol, atol, tolerance, convergence, figures, &
                              stat, errmsg)
    type(nanopush_scene), intent(in) :: scene
    logical, intent(out) :: agree
    character(len=*), intent(in), optional :: method, law
    real(dp), intent(in), optional :: rtol, atol, tolerance
    logical, intent(out), optional :: convergence
    real(dp), intent(out), optional :: figures(9)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double) :: r, a, tol, fig(9)
    integer(c_int) :: ag, kd, st
    r = 0
    a = -1
    tol = 0
    if (present(rtol)) r = rtol
    if (present(atol)) a = atol
    if (present(tolerance)) tol = tolerance
    ag = 0
    kd = 0
    fig = 0
    err = c_new_error()
    st = c_compare(err, scene%ptr, to_c(opt(method)), to_c(opt(law)), r, a, tol, ag, kd, fig)
    agree = st == 0 .and. ag /= 0
    if (present(convergence)) convergence = kd /= 0
    if (present(figures)) figures = fig
    call finish(err, "nanopush_compare", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_compare

  !> Integrate y' = rhs(t, y, ctx) with the C++ Bulirsch-Stoer engine (dimension size(y)).
  !>   t0 initial time; y in: state at t0, out: state at the last output time reached;
  !>   tout(:) output times, t0 <= tout(1) <= ... ; yout(size(y), size(tout)) allocated,
  !>   yout(:, k) = y(tout(k)) (columns not reached on failure are zero);
  !>   rtol (default 1e-10), atol (size 1 or size(y), units of each component; default 1e-10);
  !>   method "faithful" (default: the thesis configuration, the same steps as the F77 BSINT
  !>   with iextr = 1, kmax = 8) or "modern"; h0 (0 = 1% of the span), hmax (0 = none),
  !>   maxstp (default 100000), kmax (3..12), extrapolation (1 rational, 2 polynomial) override
  !>   the method's; ctx is handed to rhs unchanged; counts(3) = (RHS evaluations, accepted,
  !>   rejected steps).
  subroutine nanopush_integrate(rhs, t0, y, tout, yout, rtol, atol, method, h0, hmax, maxstp, &
                                kmax, extrapolation, ctx, counts, stat, errmsg)
    procedure(nanopush_rhs_fn) :: rhs
    real(dp), intent(in) :: t0
    real(dp), intent(inout) :: y(:)
    real(dp), intent(in) :: tout(:)
    real(dp), allocatable, intent(out) :: yout(:, :)
    real(dp), intent(in), optional :: rtol, atol(:)
    character(len=*), intent(in), optional :: method
    real(dp), intent(in), optional :: h0, hmax
    integer, intent(in), optional :: maxstp, kmax, extrapolation
    class(nanopush_context), intent(inout), target, optional :: ctx
    integer(c_int64_t), intent(out), optional :: counts(3)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(rhs_closure), target :: closure
    type(nanopush_context), target :: no_ctx
    type(c_ptr) :: err, integ
    character(len=:), allocatable :: msg
    real(c_double) :: r, ycopy(size(y))
    real(c_double), allocatable :: a(:)
    integer(c_int64_t) :: cnt(3)
    integer(c_int) :: st
    r = 1e-10_dp
    if (present(rtol)) r = rtol
    if (present(atol)) then
      allocate (a(size(atol)))
      a(:) = atol
    else
      allocate (a(1))
      a(1) = 1e-10_dp
    end if
    cnt = 0
    allocate (yout(size(y), size(tout)))
    yout = 0
    err = c_new_error()
    integ = c_new_integrator(err, int(size(y), c_int), to_c(opt(method, "faithful")), r, a, &
                             int(size(a), c_int))
    if (c_associated(integ)) then
      st = 0
      if (present(h0) .or. present(hmax) .or. present(maxstp)) &
        st = c_integrator_set_steps(err, integ, opt_real(h0, 0.0_dp), opt_real(hmax, 0.0_dp), &
                                    int(opt_int(maxstp, 100000), c_int64_t))
      if (st == 0 .and. (present(kmax) .or. present(extrapolation))) then
        if (opt(method, "faithful") == "modern") then
          st = c_integrator_set_extrapolation(err, integ, int(opt_int(kmax, 10), c_int), &
                                              int(opt_int(extrapolation, 2), c_int))
        else
          st = c_integrator_set_extrapolation(err, integ, int(opt_int(kmax, 8), c_int), &
                                              int(opt_int(extrapolation, 1), c_int))
        end if
      end if
      if (st == 0) then
        closure%f => rhs
        if (present(ctx)) then
          closure%ctx => ctx
        else
          closure%ctx => no_ctx
        end if
        ycopy = y
        st = c_integrate(err, integ, c_funloc(rhs_trampoline), c_loc(closure), t0, ycopy, &
                         int(size(tout), c_int), tout, yout, cnt)
        y = ycopy
      end if
      call c_delete_integrator(integ)
    end if
    if (present(counts)) counts = cnt
    call finish(err, "nanopush_integrate", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_integrate

  !> The C callback handed to nanopush_integrate: udata is the address of a rhs_closure.
  integer(c_int) function rhs_trampoline(n, t, y, dydt, udata) bind(C)
    integer(c_int), value, intent(in) :: n
    real(c_double), value, intent(in) :: t
    real(c_double), intent(in) :: y(n)
    real(c_double), intent(out) :: dydt(n)
    type(c_ptr), value, intent(in) :: udata
    type(rhs_closure), pointer :: closure
    integer :: st
    call c_f_pointer(udata, closure)
    st = 0
    call closure%f(t, y, dydt, closure%ctx, st)
    rhs_trampoline = int(st, c_int)
  end function rhs_trampoline

  ! ---- Friction resultant (C: nanopush_friction_*) -------------------------------------

  !> Friction resultant w(3) = (fx [N], fy [N], mf [N m]) in body axes, moment about the CM, over
  !> a 2a x 2b rectangle (a [m] half-width along x', b [m] half-length along y') with uniform
  !> pressure: muN [N] = mu N, iCOR at -R (cos alpha, sin alpha) [m, rad] from the CM, sense +1
  !> (counter-clockwise) or -1. On failure w = NaN. (A subroutine, not a function: gfortran 12
  !> corrupts the optional deferred-length errmsg of an array-valued function.)
  subroutine nanopush_friction_wrench(a, b, muN, R, alpha, sense, w, stat, errmsg)
    real(dp), intent(in) :: a, b, muN, R, alpha
    integer, intent(in) :: sense
    real(dp), intent(out) :: w(3)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    w = nan()
    err = c_new_error()
    if (c_friction_wrench(err, a, b, muN, R, alpha, int(sense, c_int), w) /= 0) continue
    call finish(err, "nanopush_friction_wrench", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_friction_wrench

  !> The same from the body-axis rigid velocity: CM velocity (vx, vy) [m/s], omega [rad/s];
  !> translation (omega = 0) and rest included; w(3) as above. On failure w = NaN.
  subroutine nanopush_friction_from_velocity(a, b, muN, vx, vy, omega, w, stat, errmsg)
    real(dp), intent(in) :: a, b, muN, vx, vy, omega
    real(dp), intent(out) :: w(3)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    w = nan()
    err = c_new_error()
    if (c_friction_from_velocity(err, a, b, muN, vx, vy, omega, w) /= 0) continue
    call finish(err, "nanopush_friction_from_velocity", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_friction_from_velocity

  ! ---- iCOR of a pushed nanorod (C: nanopush_icor_*) -----------------------------------
  ! Rod of length L [m], push at yn [m] (>= 0) from the CM, R [m] CM-to-iCOR distance (> 0 on
  ! the far side), mu [-], load W [N], push force F [N], k2 = I/m [m^2]. Each function returns
  ! the formula's value (NaN on failure, with stat/errmsg or error stop as everywhere).

  !> Eq 4.1 (experimental fit): R [m]; 0 <= yn <= L/2.
  real(dp) function nanopush_icor_experimental_fit(yn, L, stat, errmsg) result(R)
    real(dp), intent(in) :: yn, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    R = nan()
    err = c_new_error()
    if (c_icor_experimental_fit(err, yn, L, R) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_experimental_fit", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_experimental_fit

  !> Eq 4.2 (Falvo et al.): R [m]; 0 <= yn <= L/2.
  real(dp) function nanopush_icor_falvo(yn, L, stat, errmsg) result(R)
    real(dp), intent(in) :: yn, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    R = nan()
    err = c_new_error()
    if (c_icor_falvo(err, yn, L, R) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_falvo", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_falvo

  !> Eq 4.3 (Li et al.): R [m]; 0 <= yn <= L/2.
  real(dp) function nanopush_icor_li(yn, L, stat, errmsg) result(R)
    real(dp), intent(in) :: yn, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    R = nan()
    err = c_new_error()
    if (c_icor_li(err, yn, L, R) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_li", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_li

  !> Eq 4.13 (unknown pressure, minimum force): R = sqrt(b^2 + yn^2) - yn [m].
  real(dp) function nanopush_icor_unknown_pressure(yn, L, stat, errmsg) result(R)
    real(dp), intent(in) :: yn, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    R = nan()
    err = c_new_error()
    if (c_icor_unknown_pressure(err, yn, L, R) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_unknown_pressure", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_unknown_pressure

  !> Eq 4.7 (known pressure): R [m] for a push F >= the minimum force (eq 4.8).
  real(dp) function nanopush_icor_known_pressure(mu, W, yn, F, L, stat, errmsg) result(R)
    real(dp), intent(in) :: mu, W, yn, F, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    R = nan()
    err = c_new_error()
    if (c_icor_known_pressure(err, mu, W, yn, F, L, R) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_known_pressure", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_known_pressure

  !> Eq 4.8: minimum push force that starts motion, F [N].
  real(dp) function nanopush_icor_minimum_force(mu, W, yn, L, stat, errmsg) result(F)
    real(dp), intent(in) :: mu, W, yn, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    F = nan()
    err = c_new_error()
    if (c_icor_minimum_force(err, mu, W, yn, L, F) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_minimum_force", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_minimum_force

  !> Eq 4.10: F = mu W R / b [N].
  real(dp) function nanopush_icor_force_from_icor(mu, W, R, L, stat, errmsg) result(F)
    real(dp), intent(in) :: mu, W, R, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    F = nan()
    err = c_new_error()
    if (c_icor_force_from_icor(err, mu, W, R, L, F) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_force_from_icor", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_force_from_icor

  !> Eq 4.11: F = mu W (b^2 + R^2) / (2 b (R + yn)) [N]; R + yn > 0.
  real(dp) function nanopush_icor_force_unknown_pressure(mu, W, R, yn, L, stat, errmsg) result(F)
    real(dp), intent(in) :: mu, W, R, yn, L
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    F = nan()
    err = c_new_error()
    if (c_icor_force_unknown_pressure(err, mu, W, R, yn, L, F) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_force_unknown_pressure", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_force_unknown_pressure

  !> Eq 5.2 (erratum 5): push force F [N] for an assumed (signed) iCOR R; +-Inf at yn R = k2.
  real(dp) function nanopush_icor_constrained_force(mu, W, R, yn, L, k2, stat, errmsg) result(F)
    real(dp), intent(in) :: mu, W, R, yn, L, k2
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    F = nan()
    err = c_new_error()
    if (c_icor_constrained_force(err, mu, W, R, yn, L, k2, F) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_constrained_force", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_constrained_force

  !> Eq 5.5 (erratum 6): impulsive iCOR R = k2 / yn [m]; +Inf at yn = 0.
  real(dp) function nanopush_icor_impulsive(yn, k2, stat, errmsg) result(R)
    real(dp), intent(in) :: yn, k2
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    R = nan()
    err = c_new_error()
    if (c_icor_impulsive(err, yn, k2, R) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_icor_impulsive", msg, stat)
    if (present(errmsg)) errmsg = msg
  end function nanopush_icor_impulsive

  !> Roots of the constrained cubic (eq 5.4): roots(:) allocated with the finite real roots,
  !> ascending [m]. method NANOPUSH_CUBIC_BRENT (default) or NANOPUSH_CUBIC_EIGEN; ncomplex
  !> non-real roots (0 or 2); at_infinity roots lost as yn -> 0; negative = Table 5.1's branch
  !> (negative root closest to 0), positive = the smallest positive root [m] (NaN when absent);
  !> max_residual = max |p(R)| / sum |c_i R^i| over the real roots. On failure size(roots) = 0.
  subroutine nanopush_icor_cubic_roots(yn, L, k2, roots, method, ncomplex, at_infinity, negative, &
                                       positive, max_residual, stat, errmsg)
    real(dp), intent(in) :: yn, L, k2
    real(dp), allocatable, intent(out) :: roots(:)
    integer, intent(in), optional :: method
    integer, intent(out), optional :: ncomplex, at_infinity
    real(dp), intent(out), optional :: negative, positive, max_residual
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double) :: r3(3), neg, pos, res
    integer(c_int) :: nr, nc, ni
    r3 = nan()
    neg = nan()
    pos = nan()
    res = nan()
    nr = 0
    nc = 0
    ni = 0
    err = c_new_error()
    if (c_icor_cubic_roots(err, yn, L, k2, int(opt_int(method, NANOPUSH_CUBIC_BRENT), c_int), r3, nr, nc, &
                           ni, neg, pos, res) /= 0) continue
    roots = r3(1:nr)
    if (present(ncomplex)) ncomplex = int(nc)
    if (present(at_infinity)) at_infinity = int(ni)
    if (present(negative)) negative = neg
    if (present(positive)) positive = pos
    if (present(max_residual)) max_residual = res
    call finish(err, "nanopush_icor_cubic_roots", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_icor_cubic_roots

  !> The thesis' nanorod: rod(6) = (L [m], radius [m], density [kg/m^3], Hamaker H [J],
  !> rod-plane separation z0 [m], g [m/s^2]); edit it and pass it to nanopush_icor_rod_properties.
  function nanopush_icor_nanorod() result(rod)
    real(dp) :: rod(6)
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    rod = nan()
    err = c_new_error()
    if (c_icor_nanorod(err, rod) /= 0) continue
    call finish(err, "nanopush_icor_nanorod", msg)
  end function nanopush_icor_nanorod

  !> Derived quantities of a rod(6) (as nanopush_icor_nanorod): mass [kg], inertia about the CM
  !> [kg m^2], k2 = I/m [m^2], f_vdw van der Waals force [N], load W = m g + F_vdw [N]: the k2
  !> and W that `nanopush icor` uses. Outputs are NaN on failure.
  subroutine nanopush_icor_rod_properties(rod, mass, inertia, k2, f_vdw, load, stat, errmsg)
    real(dp), intent(in) :: rod(6)
    real(dp), intent(out), optional :: mass, inertia, k2, f_vdw, load
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double) :: p(5)
    p = nan()
    err = c_new_error()
    if (c_icor_rod_properties(err, rod, p) /= 0) continue
    if (present(mass)) mass = p(1)
    if (present(inertia)) inertia = p(2)
    if (present(k2)) k2 = p(3)
    if (present(f_vdw)) f_vdw = p(4)
    if (present(load)) load = p(5)
    call finish(err, "nanopush_icor_rod_properties", msg, stat)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_icor_rod_properties

  ! ---- Friction coefficient from measurements (C: nanopush_estimate_mu_*) ----------------
  ! rod(6) as nanopush_icor_nanorod (its load W = m g + F_vdw(L, H) is recomputed); force [N] > 0
  ! and the standard uncertainties sigma_force [N], sigma_L [m] (rod length), sigma_H [J]
  ! (Hamaker constant), all >= 0 (sigma_L, sigma_H default 0). Outputs: mu [-], sigma [-] its
  ! first-order standard uncertainty (inputs uncorrelated), load W [N], derivatives(4) =
  ! (dmu/dF [1/N], dmu/dyn or dmu/dR [1/m], dmu/dL [1/m], dmu/dH [1/J]); all NaN on failure.

  !> Fig 4.4 (eq 4.8 inverted): mu = F (sqrt(yn^2 + b^2) + yn) / (W b), b = L/2, from the minimum
  !> push force F measured at yn [m] from the CM (0 <= yn <= b), sigma_yn [m] >= 0.
  subroutine nanopush_estimate_mu_from_force(rod, force, sigma_force, yn, sigma_yn, mu, sigma, sigma_L, &
                                             sigma_H, load, derivatives, stat, errmsg)
    real(dp), intent(in) :: rod(6), force, sigma_force, yn, sigma_yn
    real(dp), intent(out) :: mu, sigma
    real(dp), intent(in), optional :: sigma_L, sigma_H
    real(dp), intent(out), optional :: load, derivatives(4)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    character(len=:), allocatable :: msg
    call estimate_mu_single(.false., rod, force, sigma_force, yn, sigma_yn, mu, sigma, sigma_L, sigma_H, load, &
                            derivatives, stat, msg)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_estimate_mu_from_force

  !> Fig 4.5 (eq 4.10 inverted): mu = F b / (W R) from a push force F and the observed CM-to-iCOR
  !> distance R [m] > 0, sigma_R [m] >= 0. dmu/dL = 0 exactly (b and W both scale with L).
  subroutine nanopush_estimate_mu_from_icor(rod, force, sigma_force, R, sigma_R, mu, sigma, sigma_L, &
                                            sigma_H, load, derivatives, stat, errmsg)
    real(dp), intent(in) :: rod(6), force, sigma_force, R, sigma_R
    real(dp), intent(out) :: mu, sigma
    real(dp), intent(in), optional :: sigma_L, sigma_H
    real(dp), intent(out), optional :: load, derivatives(4)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    character(len=:), allocatable :: msg
    call estimate_mu_single(.true., rod, force, sigma_force, R, sigma_R, mu, sigma, sigma_L, sigma_H, load, &
                            derivatives, stat, msg)
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_estimate_mu_from_icor

  !> The two single-measurement estimates: from the minimum force at yn = x (from_icor false) or
  !> from the force and the observed iCOR at R = x (from_icor true); outputs NaN on failure, the
  !> message in msg.
  subroutine estimate_mu_single(from_icor, rod, force, sigma_force, x, sigma_x, mu, sigma, sigma_L, sigma_H, &
                                load, derivatives, stat, msg)
    logical, intent(in) :: from_icor
    real(dp), intent(in) :: rod(6), force, sigma_force, x, sigma_x
    real(dp), intent(out) :: mu, sigma
    real(dp), intent(in), optional :: sigma_L, sigma_H
    real(dp), intent(out), optional :: load, derivatives(4)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out) :: msg  !< the error message ("" on success)
    type(c_ptr) :: err
    real(c_double) :: m, s, w, d(4), sL, sH
    m = nan()
    s = nan()
    w = nan()
    d = nan()
    sL = opt_real(sigma_L, 0.0_dp)
    sH = opt_real(sigma_H, 0.0_dp)
    err = c_new_error()
    ! The C status is in err, which finish reads.
    if (from_icor) then
      if (c_estimate_mu_from_icor(err, rod, force, sigma_force, x, sigma_x, sL, sH, m, s, w, d) /= 0) continue
      call finish(err, "nanopush_estimate_mu_from_icor", msg, stat)
    else
      if (c_estimate_mu_from_force(err, rod, force, sigma_force, x, sigma_x, sL, sH, m, s, w, d) /= 0) continue
      call finish(err, "nanopush_estimate_mu_from_force", msg, stat)
    end if
    mu = m
    sigma = s
    if (present(load)) load = w
    if (present(derivatives)) derivatives = d
  end subroutine estimate_mu_single

  !> N observations combined (C: nanopush_estimate_mu_batch; docs/fitting.md, `nanopush fit-icor`).
  !> force(n), sigma_force(n) [N]; yn, sigma_yn and R, sigma_R [m] optional arrays of size n (a NaN
  !> in yn or R: not observed in that row; each row needs one of them); pressure
  !> NANOPUSH_PRESSURE_KNOWN or NANOPUSH_PRESSURE_UNKNOWN; sigma_L [m], sigma_H [J] systematic
  !> (default 0); alpha the consistency check's significance level (default 0.01).
  !> Outputs: mu and sigma = sqrt(sigma_stat^2 + sigma_syst^2); optional sigma_stat, sigma_syst,
  !> sigma_scaled (Birge-scaled), chi2_dof and p_value (NaN for n = 1), consistent, and per row
  !> (allocated to n) row_mu, row_sigma, row_weight, row_pull and equations (8: eq 4.8, 10: eq 4.10,
  !> 11: eq 4.11). On failure every real output is NaN (arrays allocated to 0).
  subroutine nanopush_estimate_mu_batch(rod, force, sigma_force, pressure, mu, sigma, yn, sigma_yn, R, sigma_R, &
                                        sigma_L, sigma_H, alpha, sigma_stat, sigma_syst, sigma_scaled, chi2_dof, &
                                        p_value, consistent, row_mu, row_sigma, row_weight, row_pull, equations, &
                                        stat, errmsg)
    real(dp), intent(in) :: rod(6), force(:), sigma_force(:)
    integer, intent(in) :: pressure
    real(dp), intent(out) :: mu, sigma
    real(dp), intent(in), optional :: yn(:), sigma_yn(:), R(:), sigma_R(:), sigma_L, sigma_H, alpha
    real(dp), intent(out), optional :: sigma_stat, sigma_syst, sigma_scaled, chi2_dof, p_value
    logical, intent(out), optional :: consistent
    real(dp), allocatable, intent(out), optional :: row_mu(:), row_sigma(:), row_weight(:), row_pull(:)
    integer, allocatable, intent(out), optional :: equations(:)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double) :: res(11)
    real(c_double), allocatable :: y(:), sy(:), rr(:), sr(:), rows(:)
    integer(c_int), allocatable :: eq(:)
    integer(c_int) :: d, c
    integer :: n, m, st
    character(len=12) :: nbuf
    n = size(force)
    res = nan()
    d = 0
    c = 0
    m = 0
    msg = ""
    st = NANOPUSH_OK
    ! Array sizes are checked here (C reads n of each); a mismatch is bad input.
    if (size(sigma_force) /= n) msg = "sigma_force"
    if (present(yn) .neqv. present(sigma_yn)) msg = "yn/sigma_yn (give both or neither)"
    if (present(R) .neqv. present(sigma_R)) msg = "R/sigma_R (give both or neither)"
    if (present(yn)) then
      if (size(yn) /= n) msg = "yn"
    end if
    if (present(sigma_yn)) then
      if (size(sigma_yn) /= n) msg = "sigma_yn"
    end if
    if (present(R)) then
      if (size(R) /= n) msg = "R"
    end if
    if (present(sigma_R)) then
      if (size(sigma_R) /= n) msg = "sigma_R"
    end if
    allocate (y(n), sy(n), rr(n), sr(n), rows(4 * n), eq(n))
    y = nan()
    sy = 0.0_dp
    rr = nan()
    sr = 0.0_dp
    rows = nan()
    eq = 0
    if (present(yn) .and. present(sigma_yn) .and. len(msg) == 0) then
      y = yn
      sy = sigma_yn
    end if
    if (present(R) .and. present(sigma_R) .and. len(msg) == 0) then
      rr = R
      sr = sigma_R
    end if
    if (len(msg) > 0) then
      st = NANOPUSH_BAD_INPUT
      write (nbuf, '(i0)') n
      msg = msg // ": size does not match size(force) = " // trim(nbuf)
      if (present(stat)) then
        stat = st
      else
        error stop "nanopush: nanopush_estimate_mu_batch: " // msg
      end if
    else
      err = c_new_error()
      if (c_estimate_mu_batch(err, rod, int(n, c_int), force, sigma_force, y, sy, rr, sr, int(pressure, c_int), &
                              opt_real(sigma_L, 0.0_dp), opt_real(sigma_H, 0.0_dp), opt_real(alpha, 0.01_dp), res, &
                              d, c, rows, eq) /= 0) continue  ! the status is in err
      call finish(err, "nanopush_estimate_mu_batch", msg, st)
      if (present(stat)) then
        stat = st
      else if (st /= NANOPUSH_OK) then
        error stop "nanopush: nanopush_estimate_mu_batch: " // msg
      end if
    end if
    if (st == NANOPUSH_OK) m = n
    mu = res(1)
    sigma = res(2)
    if (present(sigma_stat)) sigma_stat = res(3)
    if (present(sigma_syst)) sigma_syst = res(4)
    if (present(sigma_scaled)) sigma_scaled = res(5)
    if (present(chi2_dof)) chi2_dof = res(7)
    if (present(p_value)) p_value = res(8)
    if (present(consistent)) consistent = st == NANOPUSH_OK .and. c /= 0
    if (present(row_mu)) row_mu = rows(1:m)
    if (present(row_sigma)) row_sigma = rows(n + 1:n + m)
    if (present(row_weight)) row_weight = rows(2 * n + 1:2 * n + m)
    if (present(row_pull)) row_pull = rows(3 * n + 1:3 * n + m)
    if (present(equations)) equations = int(eq(1:m))
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_estimate_mu_batch

  ! ---- Trajectory fit (C: nanopush_fit_trajectory; docs/fitting.md, `nanopush fit`) ----------

  !> Fit the comma-separated scene keys `free` ("surface.mu" or "surface.mu,surface.f_vdw") to the
  !> observations in the CSV file `data` (t and any of x, y, theta with sigma_ columns), starting
  !> from the scene's values; law ("thesis" | "coulomb", rough scenes) and sigma ("x=2e-9,theta=0.01",
  !> for columns without a sigma column) as `nanopush fit`. values(:) and stderrs(:) are allocated
  !> to the number of free keys; a stderr is NaN where the data do not determine that key
  !> separately (the JSON names the combination they do determine) or the fit did not converge.
  !> Optional: chi2_dof, converged (a non-converged fit is not an error: its last state is
  !> returned), summary(6) = (chi2, chi2/dof, dof, iterations, forward solves, identifiable 1/0),
  !> json (the summary of `nanopush fit --json`, at most 1 MiB). On failure values and stderrs
  !> are allocated to size 0 and the real outputs are NaN.
  subroutine nanopush_fit(scene, data, free, values, stderrs, law, sigma, chi2_dof, converged, summary, json, &
                          stat, errmsg)
    type(nanopush_scene), intent(in) :: scene
    character(len=*), intent(in) :: data, free
    real(dp), allocatable, intent(out) :: values(:), stderrs(:)
    character(len=*), intent(in), optional :: law, sigma
    real(dp), intent(out), optional :: chi2_dof, summary(6)
    logical, intent(out), optional :: converged
    character(len=:), allocatable, intent(out), optional :: json
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double), allocatable :: v(:), e(:)
    real(c_double) :: s(6)
    integer(c_int) :: conv, jlen, jsize
    character(kind=c_char), allocatable :: buf(:)
    integer :: nfree, i, st
    nfree = 1
    do i = 1, len(free)
      if (free(i:i) == ",") nfree = nfree + 1
    end do
    allocate (v(nfree), e(nfree))
    v = nan()
    e = nan()
    s = nan()
    conv = 0
    jlen = 0
    jsize = 0
    if (present(json)) jsize = 1048576
    allocate (buf(max(jsize, 1)))
    buf(1) = c_null_char
    err = c_new_error()
    if (c_fit_trajectory(err, scene%ptr, to_c(data), to_c(free), to_c(opt(law)), to_c(opt(sigma)), &
                         int(nfree, c_int), v, e, s, conv, buf, jsize, jlen) /= 0) continue  ! the status is in err
    call finish(err, "nanopush_fit", msg, st)
    if (present(stat)) then
      stat = st
    else if (st /= NANOPUSH_OK) then
      error stop "nanopush: nanopush_fit: " // msg
    end if
    if (st == NANOPUSH_OK) then
      values = v
      stderrs = e
    else
      allocate (values(0), stderrs(0))
    end if
    if (present(chi2_dof)) chi2_dof = s(2)
    if (present(summary)) summary = s
    if (present(converged)) converged = st == NANOPUSH_OK .and. conv /= 0
    if (present(json)) json = from_c(buf, int(min(jlen, max(jsize - 1, 0))))
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_fit

  ! ---- Push planning (C: nanopush_plan; docs/planning.md, `nanopush plan`) ------------------

  !> Tip pushes that bring the scene's bar from its initial pose to goal = (x [m], y [m],
  !> theta [rad]), as `nanopush plan`. pushes(n, 8) is allocated to the plan's pushes, one row
  !> each: start_x, start_y [m], direction [rad], speed [m/s], travel [m] (the tip.* keys), then
  !> the pose it leaves (x_end, y_end [m], theta_end [rad]): plan.csv's columns. Optional:
  !> tolerance(2) (distance [m], angle [rad]; default 1e-9 m, 0.01 rad), objective ("pushes",
  !> "travel", "time", "force"), max_pushes (default 10), found and verified, summary(8) = (found
  !> 1/0, verified 1/0, final x, y, theta, distance and angle from the goal, forward runs). A goal
  !> no plan reaches is not an error: found = .false. and the best plan is returned. On failure
  !> pushes is allocated to (0, 8) and the real outputs are NaN. A robust plan (`plan --robust`,
  !> C: nanopush_plan_robust): tip_mu_range(2) = (lo, hi), the tip friction at both ends, and
  !> start_shift(3) = (dx [m], dy [m], dtheta [rad]), the start shifted by each, plus and minus,
  !> one at a time; found then means within tolerance in every world.
  subroutine nanopush_plan(scene, goal, pushes, tolerance, objective, max_pushes, found, verified, summary, &
                           stat, errmsg, tip_mu_range, start_shift)
    type(nanopush_scene), intent(in) :: scene
    real(dp), intent(in) :: goal(3)
    real(dp), allocatable, intent(out) :: pushes(:, :)
    real(dp), intent(in), optional :: tolerance(2)
    real(dp), intent(in), optional :: tip_mu_range(2), start_shift(3)
    character(len=*), intent(in), optional :: objective
    integer, intent(in), optional :: max_pushes
    logical, intent(out), optional :: found, verified
    real(dp), intent(out), optional :: summary(8)
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double), allocatable :: rows(:, :)
    real(c_double) :: s(8), tol(2)
    real(c_double), target :: range(2), shift(3)
    type(c_ptr) :: range_ptr, shift_ptr
    integer(c_int) :: n, maxp
    integer :: st
    range_ptr = c_null_ptr
    shift_ptr = c_null_ptr
    if (present(tip_mu_range)) then
      range = tip_mu_range
      range_ptr = c_loc(range)
    end if
    if (present(start_shift)) then
      shift = start_shift
      shift_ptr = c_loc(shift)
    end if
    maxp = 10
    if (present(max_pushes)) maxp = int(max_pushes, c_int)
    tol = [1e-9_dp, 0.01_dp]
    if (present(tolerance)) tol = tolerance
    allocate (rows(8, max(maxp, 1)))  ! C's row-major rows are Fortran's columns
    s = nan()
    n = 0
    err = c_new_error()
    if (c_plan_robust(err, scene%ptr, goal, tol, to_c(opt(objective)), maxp, range_ptr, shift_ptr, max(maxp, 0_c_int), &
                      rows, n, s) /= 0) continue
    call finish(err, "nanopush_plan", msg, st)
    if (present(stat)) then
      stat = st
    else if (st /= NANOPUSH_OK) then
      error stop "nanopush: nanopush_plan: " // msg
    end if
    if (st == NANOPUSH_OK) then
      pushes = transpose(rows(:, 1:n))
    else
      allocate (pushes(0, 8))
    end if
    if (present(found)) found = st == NANOPUSH_OK .and. s(1) == 1
    if (present(verified)) verified = st == NANOPUSH_OK .and. s(2) == 1
    if (present(summary)) summary = s
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_plan

  !> Several bars of the scene's kind from objects(3, n) into slots(3, n) (columns x, y, theta),
  !> as `nanopush assemble` (docs/planning.md): pushes(k, 1:10) the pushes in the order made
  !> (bar, slot, then nanopush_plan's eight columns), slot_of(n) each bar's slot, final(3, n)
  !> where each bar ends, assembled every bar in its slot. slot_of and final, when given, must
  !> have exactly those shapes (n = size(objects, 2)): another size is NANOPUSH_BAD_INPUT naming it.
  subroutine nanopush_assemble(scene, objects, slots, pushes, slot_of, final, assembled, tolerance, max_pushes, &
                               gap, stat, errmsg)
    type(nanopush_scene), intent(in) :: scene
    real(dp), intent(in) :: objects(:, :), slots(:, :)
    real(dp), allocatable, intent(out) :: pushes(:, :)
    integer, intent(out), optional :: slot_of(:)
    real(dp), intent(out), optional :: final(:, :)
    logical, intent(out), optional :: assembled
    real(dp), intent(in), optional :: tolerance(2), gap
    integer, intent(in), optional :: max_pushes
    integer, intent(out), optional :: stat
    character(len=:), allocatable, intent(out), optional :: errmsg
    type(c_ptr) :: err
    character(len=:), allocatable :: msg
    real(c_double), allocatable :: rows(:, :), ends(:, :)
    integer(c_int), allocatable :: slots_c(:)
    real(c_double) :: tol(2), g
    integer(c_int) :: n, maxp, k, done
    integer :: st
    n = int(size(objects, 2), c_int)
    maxp = 10
    if (present(max_pushes)) maxp = int(max_pushes, c_int)
    tol = [1e-9_dp, 0.01_dp]
    if (present(tolerance)) tol = tolerance
    g = 2e-9_dp
    if (present(gap)) g = gap
    allocate (rows(10, max(n * maxp, 1)), ends(3, max(n, 1)), slots_c(max(n, 1)))
    ends = nan()
    slots_c = 0
    k = 0
    done = 0
    msg = ""
    ! Shapes are Fortran's to check (C reads 3 n values of each and writes n of slot_of and
    ! final): a mismatch is bad input, nothing read or written beyond an array.
    if (size(objects, 1) /= 3 .or. size(slots, 1) /= 3 .or. size(slots, 2) /= n) then
      msg = "objects, slots: must be (3, n) arrays of the same n (columns x, y, theta)"
    else if (present(slot_of)) then
      if (size(slot_of) /= n) msg = "size(slot_of) = " // shape_text([size(slot_of)]) // &
                                    ": must be n = " // shape_text([int(n)]) // " (one slot per bar)"
    end if
    if (len(msg) == 0 .and. present(final)) then
      if (size(final, 1) /= 3 .or. size(final, 2) /= n) &
        msg = "shape(final) = " // shape_text(shape(final)) // ": must be (3, n) = " // shape_text([3, int(n)]) // &
              " (x, y, theta of each bar)"
    end if
    if (len(msg) > 0) then
      st = NANOPUSH_BAD_INPUT
      if (present(stat)) then
        stat = st
      else
        error stop "nanopush: nanopush_assemble: " // msg
      end if
    else
      err = c_new_error()
      if (c_assemble(err, scene%ptr, n, objects, slots, tol, maxp, g, max(n * maxp, 0_c_int), rows, k, slots_c, &
                     ends, done) /= 0) continue
      call finish(err, "nanopush_assemble", msg, st)
      if (present(stat)) then
        stat = st
      else if (st /= NANOPUSH_OK) then
        error stop "nanopush: nanopush_assemble: " // msg
      end if
    end if
    if (st == NANOPUSH_OK) then
      pushes = transpose(rows(:, 1:k))
    else
      allocate (pushes(0, 10))
    end if
    if (present(slot_of) .and. st == NANOPUSH_OK) slot_of = int(slots_c(1:n))
    if (present(final) .and. st == NANOPUSH_OK) final = ends(:, 1:n)
    if (present(assembled)) assembled = st == NANOPUSH_OK .and. done == 1
    if (present(errmsg)) errmsg = msg
  end subroutine nanopush_assemble

  ! ---- helpers --------------------------------------------------------------------------

  !> The outcome of a run that failed with the status held by err (docs/errors.md, "Outcomes
  !> of a run"): no_static_friction, law_blowup, accuracy_not_reached (13-15), solver_failure
  !> (2-6); "" for any other status (the run was not made).
  function failed_outcome(err) result(name)
    type(c_ptr), intent(in) :: err
    character(len=:), allocatable :: name
    integer :: st
    st = NANOPUSH_OUT_OF_MEMORY
    if (c_associated(err)) st = int(c_check_error(err))
    select case (st)
    case (NANOPUSH_NO_STATIC_FRICTION)
      name = "no_static_friction"
    case (NANOPUSH_LAW_BLOWUP)
      name = "law_blowup"
    case (NANOPUSH_ACCURACY_NOT_REACHED)
      name = "accuracy_not_reached"
    case (NANOPUSH_TOO_MANY_STEPS, NANOPUSH_STEP_UNDERFLOW, NANOPUSH_RHS_FAILED, NANOPUSH_NOT_FINITE, &
          NANOPUSH_SOLVER_FAILED)
      name = "solver_failure"
    case default
      name = ""
    end select
  end function failed_outcome

  !> The extents of an array shape as text: "5" or "(3, 5)".
  function shape_text(extents) result(s)
    integer, intent(in) :: extents(:)
    character(len=:), allocatable :: s
    character(len=24) :: buf
    integer :: k
    s = ""
    do k = 1, size(extents)
      write (buf, '(i0)') extents(k)
      if (k > 1) s = s // ", "
      s = s // trim(buf)
    end do
    if (size(extents) > 1) s = "(" // s // ")"
  end function shape_text

  !> Quiet NaN: the value of an output that a failed call did not produce.
  real(dp) function nan()
    nan = ieee_value(0.0_dp, ieee_quiet_nan)
  end function nan

  !> The outcome recorded in err: msg (empty on success) and the status in stat, or, without
  !> stat, error stop with the message. Frees err. (Wrappers copy msg to their optional errmsg
  !> themselves: gfortran 12 mishandles an optional deferred-length errmsg passed on.)
  subroutine finish(err, where, msg, stat)
    type(c_ptr), intent(inout) :: err
    character(len=*), intent(in) :: where
    character(len=:), allocatable, intent(out) :: msg
    integer, intent(out), optional :: stat
    integer :: st
    if (.not. c_associated(err)) then
      st = NANOPUSH_OUT_OF_MEMORY
      msg = "out of memory"
    else
      st = int(c_check_error(err))
      msg = ""
      if (st /= NANOPUSH_OK) msg = error_message(err)
      call c_delete_error(err)
    end if
    if (present(stat)) then
      stat = st
    else if (st /= NANOPUSH_OK) then
      error stop "nanopush: " // where // ": " // msg
    end if
  end subroutine finish

  !> The message held by an error handle (query the length, then copy).
  function error_message(err) result(msg)
    type(c_ptr), intent(in) :: err
    character(len=:), allocatable :: msg
    character(kind=c_char) :: probe(1)
    character(kind=c_char), allocatable :: buf(:)
    integer(c_int) :: n
    n = c_get_error(err, probe, 1_c_int)
    allocate (buf(max(n, 0_c_int) + 1))
    n = c_get_error(err, buf, int(size(buf), c_int))
    msg = from_c(buf, int(max(n, 0_c_int)))
  end function error_message

  !> Fortran string -> NUL-terminated C character array (trailing blanks kept).
  pure function to_c(s) result(cs)
    character(len=*), intent(in) :: s
    character(kind=c_char) :: cs(len(s) + 1)
    integer :: i
    do i = 1, len(s)
      cs(i) = s(i:i)
    end do
    cs(len(s) + 1) = c_null_char
  end function to_c

  !> First n characters of a C character array -> Fortran string.
  pure function from_c(cs, n) result(s)
    character(kind=c_char), intent(in) :: cs(:)
    integer, intent(in) :: n
    character(len=:), allocatable :: s
    integer :: i
    allocate (character(len=n) :: s)
    do i = 1, n
      s(i:i) = cs(i)
    end do
  end function from_c

  !> A static C string (char*) -> Fortran string.
  function c_string(p) result(s)
    type(c_ptr), intent(in) :: p
    character(len=:), allocatable :: s
    character(kind=c_char), pointer :: chars(:)
    integer :: n
    n = int(c_strlen(p))
    call c_f_pointer(p, chars, [n])
    s = from_c(chars, n)
  end function c_string

  pure function opt(s, default) result(r)
    character(len=*), intent(in), optional :: s, default
    character(len=:), allocatable :: r
    if (present(s)) then
      r = trim(s)
    else if (present(default)) then
      r = default
    else
      r = ""
    end if
  end function opt

  pure real(dp) function opt_real(x, default)
    real(dp), intent(in), optional :: x
    real(dp), intent(in) :: default
    opt_real = default
    if (present(x)) opt_real = x
  end function opt_real

  pure integer function opt_int(x, default)
    integer, intent(in), optional :: x
    integer, intent(in) :: default
    opt_int = default
    if (present(x)) opt_int = x
  end function opt_int


end module nanopush
