"""nanopush: mechanics of pushing nano-objects (AFM manipulation), from Python.

The C++ solver of nanopush bound with pybind11: NumPy arrays in and out, SI units
everywhere, the same numbers (bit for bit) as the ``nanopush`` command line and the C,
C++ and Fortran interfaces.

>>> import nanopush
>>> scene = nanopush.Scene.preset("fig3_6a")
>>> scene.set("push.force", 2e-9)                  # any scene key, validated
>>> r = nanopush.run(scene, engine="cxx", method="faithful")
>>> r.theta[-1], r.nfcn                            # NumPy arrays, counts
>>> fx, fy, mf = nanopush.friction_wrench(27.5e-9, 50e-9, R, alpha)   # any shapes

Contents
--------
Scene, presets, scene_keys       scene files and the preset scenes (docs/scenes.md)
run, compare, Result             a scene integrated by the C++ or the F77 engine
friction_wrench, friction_from_velocity   closed-form friction over a rectangle
icor                             iCOR formulas of thesis ch. 4-5, the cubic, dynamic iCOR
estimate_mu                      mu from measurements, with its uncertainty
estimate_mu_batch, MuBatch       mu from N observations combined, chi^2 check (fit-icor)
fit, FitResult, synthesize       scene keys fitted to observed motion (docs/fitting.md)
sweep                            many points on C++ threads (docs/sweeps.md)
InputError (a ValueError), SolverError (a RuntimeError)   the library's errors

docs/python.md in the source tree has the install and the examples.
"""

import operator as _operator
import os as _os
import pathlib as _pathlib

from ._nanopush import (  # noqa: F401  (re-exported)
    FitResult,
    InputError,
    MuBatch,
    MuEstimate,
    MuEstimates,
    PlanResult,
    Result,
    Scene,
    SolverError,
    Wrench,
    __version__,
)
from . import _nanopush
from . import _fitting
from . import _scenes
from . import _signatures
from . import icor  # noqa: F401

# Every compiled callable with a signature inspect.signature reads (help(), IDEs), and
# pybind11's argument conversion failures raised as InputError naming the argument: the
# module's functions (the package's own calls to _nanopush._run, ... included), methods and
# constructors (_signatures).
_signatures.module(_nanopush)
_signatures.module(_nanopush.icor)
estimate_mu = _nanopush.estimate_mu
estimate_mu_batch = _nanopush.estimate_mu_batch
friction_from_velocity = _nanopush.friction_from_velocity
friction_wrench = _nanopush.friction_wrench
scene_keys = _nanopush.scene_keys
synthesize = _nanopush.synthesize
for _cls in (FitResult, MuBatch, MuEstimate, MuEstimates, PlanResult, Result, Scene, Wrench):
    _signatures.methods(_cls)
FitResult.report = _fitting.report
FitResult.plot = _fitting.plot


def _result_to_xarray(self):
    """The trajectory as an xarray.Dataset over the dimension ``t`` (its coordinate), every
    other column a variable with its ``units``, as ``nanopush run --out FILE.nc`` writes it
    (docs/data.md; xarray is imported here: an optional dependency)."""
    import xarray

    d = self.to_dict()
    return xarray.Dataset({k: ("t", d[k], {"units": self.units[k]}) for k in self.columns if k != "t"},
                          coords={"t": ("t", d["t"], {"units": self.units["t"]})})


Result.to_xarray = _result_to_xarray

_scenes.keep_description_true(Scene)

__all__ = [
    "Scene", "presets", "scenes_dir", "scene_keys", "run", "compare", "Result", "Comparison",
    "friction_wrench", "friction_from_velocity", "Wrench", "icor", "estimate_mu", "MuEstimate",
    "MuEstimates", "estimate_mu_batch", "MuBatch", "fit", "FitResult", "synthesize",
    "sweep", "SweepResult", "SweepFile", "plan", "PlanResult", "check_plan", "PlanCheck", "assemble", "Assembly", "InputError", "SolverError", "__version__",
]

# ---- presets ----------------------------------------------------------------------------


def scenes_dir():
    """The directory of the preset scenes: $NANOPUSH_SCENES if set, else the scenes shipped
    inside the package (the same files as ``nanopush presets`` lists)."""
    env = _os.environ.get("NANOPUSH_SCENES")
    if env:
        return _pathlib.Path(env)
    return _pathlib.Path(__file__).resolve().parent / "scenes"


def _input_error(message, field=""):
    e = InputError(message)
    e.field, e.index = field, None
    return e


def _count(name, value):
    """A whole number >= 0 (int, NumPy integer or 0-d array); InputError naming `name` otherwise."""
    try:
        v = _operator.index(value)
    except TypeError:
        raise _input_error(f"{name} = {value!r:.80}: must be a whole number >= 0", name) from None
    if v < 0:
        raise _input_error(f"{name} = {v}: must be a whole number >= 0", name)
    return v


def _mapping(name, value, form):
    """A dict argument (None: empty); InputError naming `name` for anything else."""
    if value is None:
        return {}
    if not isinstance(value, dict):
        raise _input_error(f"{name} = {value!r:.80}: must be a dict {form}", name)
    return dict(value)


def _resolve_preset(name, field="name"):
    """The file of a preset name, found by the rule of ``nanopush run`` (the library's
    find_preset: NAME.toml or NAME under scenes_dir(), then its thesis/, bench/ and examples/
    folders); InputError naming the argument `field` otherwise."""
    if not isinstance(name, (str, _os.PathLike)):
        raise _input_error(f"{field} = {name!r:.80}: must be a preset name (text; nanopush.presets() lists them)",
                           field)
    d = scenes_dir()
    found = _nanopush._find_preset(str(d), _os.fspath(name))
    if found is None:
        raise _input_error(f"{field} = {name}: no preset of that name under {d} (nanopush.presets() lists them)",
                           field)
    return _pathlib.Path(found)


def presets():
    """The preset scenes as a dict {name: one-line description}, sorted by name. Names are
    what Scene.preset and ``nanopush run`` accept: the short name (``fig3_6a``) when it finds
    the file, else the path under scenes_dir() (``examples/foo``). The list is the library's
    (the same as ``nanopush presets``)."""
    out = {short or name: desc for name, short, desc, _ in _nanopush._list_presets(str(scenes_dir()))}
    return dict(sorted(out.items()))


def _preset(name):
    """A preset scene by name (``fig3_6a``, ``thesis/fig3_6a``; nanopush.presets() lists them)."""
    return Scene.from_file(str(_resolve_preset(name)))


Scene.preset = staticmethod(_preset)


def _as_scene(scene):
    if isinstance(scene, Scene):
        return scene
    if isinstance(scene, (str, _os.PathLike)):
        p = _pathlib.Path(scene)
        if p.is_file():
            return Scene.from_file(str(p))
        return Scene.from_file(str(_resolve_preset(str(scene), "scene")))
    raise _input_error(f"scene = {scene!r:.80}: must be a nanopush.Scene, a preset name or a scene file", "scene")


# ---- run and compare ------------------------------------------------------------------


def run(scene, engine=None, method=None, law=None, rtol=None, atol=None, precision=None, accuracy=None,
        error_estimate=None, t_eval=None):
    """Integrate a scene and return its trajectory (a nanopush.Result).

    scene      a nanopush.Scene, a preset name (``"fig3_6a"``) or a scene file
    engine     ``"cxx"`` (the C++ solver) or ``"f77"`` (the FORTRAN 77 reproduction);
               default: the scene's solver.engine
    method     C++ engine: ``"faithful"`` (the F77 engine's steps exactly), ``"modern"``,
               ``"dop853"`` (Dormand-Prince 8(5,3), double, not under the coulomb law),
               ``"cvode"`` (rough scenes under the coulomb law) or ``"auto"`` (by rtol);
               default: the scene's (``"auto"`` unless it states one; the thesis
               presets state ``"faithful"``)
    law        rough scenes: ``"thesis"`` (eq 3.40 sign law), ``"printed"`` (the same with eqs
               3.45-3.48 as printed) or ``"coulomb"`` (event-located stick-slip;
               docs/rough.md); default: the scene's surface.law
    rtol       relative tolerance (> 0); default: the scene's solver.rtol
    atol       absolute tolerance [SI of each state] (>= 0; 0 = rtol times each component's
               natural scale); default: the scene's
    precision  ``"double"``, ``"long"`` or ``"quad"``; long and quad need the C++ engine and
               either a smooth scene (method faithful, modern or auto) or a rough scene under
               the thesis or coulomb law with method modern or auto (docs/accuracy.md,
               "References with more digits"); default: the scene's
    accuracy   the error asked for of the final pose (docs/accuracy.md), in [1e-14, 0.1]:
               rtol (and under method auto the method) is chosen to reach it; 0 = none
               (run at rtol); default: the scene's solver.accuracy. Not reached: SolverError
               with .outcome "accuracy_not_reached" and .partial the best answer
    error_estimate  estimate the global error (a companion run at rtol/100, in
               ``result.error``); default: the scene's solver.error_estimate (true)
    t_eval     the output times [s] (as solve_ivp's): strictly increasing, within [0,
               solver.t_end]; the integration runs from 0 to the last of them, stopping at
               each; default: the scene's solver.samples times over [0, solver.t_end]

    The result has NumPy arrays t, x, y, theta, vx, vy, omega, fx, fy, mf (SI, world axes),
    the counts nfcn, steps, rejected, the error estimate ``error`` (a dict; ``error_estimate``
    its norm), ``outcome`` (ok or at_rest), and to_dict() / to_csv(path) / to_xarray(); solve_ivp's names:
    ``states`` (6 x n: x, y, theta, vx, vy, omega; solve_ivp's ``y``), ``success``,
    ``status`` (0 or -1), ``message``, ``nfev``. The same numbers, bit
    for bit, as ``nanopush run SCENE --engine ... --method ...``. The GIL is released while
    the engine runs. Raises nanopush.InputError (a ValueError) for bad settings and
    nanopush.SolverError when the integrator gives up (with .status and .partial).
    """
    return _nanopush._run(_as_scene(scene), engine or "", method or "", law or "", rtol, atol, precision or "",
                          accuracy, error_estimate, t_eval)


# ---- fit --------------------------------------------------------------------------------


def fit(scene, data, free, *, law=None, sigma=None, gradients="auto", rtol=1e-10, max_evaluations=100,
        accuracy=-1.0):
    """Fit scene keys to observed motion (``nanopush fit``; docs/fitting.md).

    scene        a nanopush.Scene, a preset name or a scene file: the model and the starting
                 values (not changed)
    data         the observations: a CSV file's path, or columns as a dict of arrays, a NumPy
                 structured array or a pandas DataFrame: t [s] and any of x, y [m], theta
                 [rad], with sigma_x, sigma_y, sigma_theta (or ``sigma``); the same checks
                 and messages (row and column named) whichever form
    free         a scene key ("surface.mu") or a list of keys
    law          rough scenes: 'thesis' or 'coulomb' (default: the scene's)
    sigma        dict column -> standard deviation for columns without a sigma column
    gradients    'auto' | 'sensitivities' | 'differences'; rtol of the forward solves;
    max_evaluations of Levenberg-Marquardt
    accuracy     > 0: the error asked for of the model's poses at the observation times, in
                 [1e-14, 0.1] (docs/accuracy.md): the forward solves' rtol is chosen to reach
                 it (rtol is then ignored) and checked at the estimate; 0 = none; default:
                 the scene's solver.accuracy

    Returns a FitResult: ``x``, ``stderr``, ``covariance``, ``correlation`` (in the order of
    ``names``), ``success``, ``nfev``, ``report()`` (lmfit's layout), ``plot()`` (data, fit
    and residual panels), and the library's fields (parameters, chi2_dof, ...). A fit that
    does not converge says so (success False), it does not raise. Bad data or keys raise
    nanopush.InputError naming the row and column or the key.
    """
    if isinstance(data, (str, _os.PathLike)):
        arg, text = data, False
    else:
        arg, text = _fitting.observations_csv(data), True
    return _nanopush._fit(_as_scene(scene), arg, free, law=law or "", sigma=sigma, gradients=gradients, rtol=rtol,
                          max_evaluations=max_evaluations, accuracy=accuracy, text=text)


class Comparison:
    """The two engines side by side (nanopush.compare): ``cxx`` and ``f77`` (Results),
    ``columns`` (per trajectory column except t), ``kind``, ``tolerance``, ``law`` and ``agree``.

    kind "same-steps" (method faithful, or a ``tolerance`` given): per column max_abs_diff,
    unit, relative = max |diff| / scale, scale = max |value|, ok (relative <= tolerance).
    kind "convergence" (modern, dop853): per column error_cxx and error_f77 (each engine
    against itself at rtol 1e-14), diff and diff_tight (the engines apart at rtol and at
    1e-14), scale (largest norm of the column's vector), ok (diff_tight <= error_cxx +
    error_f77 + 1e-13), all relative to scale; tolerance is None. docs/rough.md. The verdict
    is the library's (the same function as ``nanopush compare``). ``accuracy``: None, or with
    compare(accuracy=E) a dict (requested, reached, rtol_used, runs)."""

    cxx: "Result"
    f77: "Result"
    columns: dict
    tolerance: "float | None"
    kind: str
    law: str
    agree: bool
    accuracy: "dict | None"

    def __init__(self, verdict):
        self.cxx, self.f77 = verdict["cxx"], verdict["f77"]
        self.columns, self.tolerance = verdict["columns"], verdict["tolerance"]
        self.kind, self.law, self.agree = verdict["kind"], verdict["law"], verdict["agree"]
        self.accuracy = verdict["accuracy"]

    def __bool__(self):
        return self.agree

    def __repr__(self):
        verdict = "agree" if self.agree else "DISAGREE"
        if self.kind == "convergence":
            worst = max((c["diff_tight"] for c in self.columns.values()), default=0.0)
            return (f"<nanopush.Comparison {self.cxx.engine} vs {self.f77.engine}: by convergence, tight runs "
                    f"{worst:.3g} apart -> {verdict}>")
        worst = max((c["relative"] for c in self.columns.values()), default=0.0)
        return (f"<nanopush.Comparison {self.cxx.engine} vs {self.f77.engine}: worst relative deviation "
                f"{worst:.3g}, tolerance {self.tolerance:.3g} -> {verdict}>")


def plan(scene, goal, *, tolerance=(1e-9, 0.01), objective="pushes", max_pushes=10, half_turn_symmetric=True,
         baseline=False, robust_tip_mu=None, robust_start=None):
    """Tip pushes that bring the scene's bar from its initial pose to `goal` = (x [m], y [m],
    theta [rad]) within `tolerance` = (distance [m], angle [rad]) (docs/planning.md), planned
    through the quasi-static tip model and verified by forward runs; the numbers of
    `nanopush plan SCENE --goal X,Y,THETA`. `objective`: "pushes", "travel", "time" or "force";
    `baseline=True` plans as the target-oriented baseline does. The scene needs a rough surface;
    its tip.* keys (push.mode = "tip") give the tip's radius, speed and friction. Returns a
    PlanResult (status "found" or "not_found" with the best plan); bad input is InputError.
    A robust plan reaches the goal in other worlds as well as the model's: `robust_tip_mu` =
    (lo, hi), the tip friction at both ends; `robust_start` = (dx [m], dy [m], dtheta [rad]),
    the start shifted by each, plus and minus, one at a time (``nanopush plan --robust``, whose
    shifts are 2 sigma of --noise); ``PlanResult.worlds`` says where the plan leaves each."""
    return _nanopush._plan(_as_scene(scene), goal, tolerance, str(objective), max_pushes, half_turn_symmetric, baseline,
                           robust_tip_mu, robust_start)


def check_plan(plan_result, scene, trials, *, noise=(0.0, 0.0, 0.0), mu_range=None, tip_mu_range=None, seed=1,
               jobs=None, progress=None):
    """How often `plan_result` (from nanopush.plan on `scene`) reaches its goal when made open
    loop in `trials` worlds that are not the model's: the start pose plus Gaussian noise
    `noise` = (sx [m], sy [m], stheta [rad]), the surface mu uniform in `mu_range` = (lo, hi)
    (None: the scene's), the tip's in `tip_mu_range` (None: the scene's), trial k drawn from its own stream (seed, k); the numbers of
    ``nanopush plan ... --check N`` (docs/planning.md). The trials run through the sweep
    engine on `jobs` threads (None: every core), with `progress` and Ctrl-C as in
    nanopush.sweep. Returns a PlanCheck: the per-trial table (a SweepResult: start_x, ...,
    final_distance, final_angle, success) with ``probability``, ``successes``, ``trials`` and
    ``interval`` (the 95 % Wilson interval)."""
    names, units, data, summary = plan_result._check(_as_scene(scene), trials, noise, mu_range, tip_mu_range, seed,
                                                     _count("jobs", 0 if jobs is None else jobs), progress)
    return PlanCheck(names, units, data, summary)


class Assembly:
    """nanopush.assemble's answer: ``status`` ("assembled" or "not_found"), ``message``,
    ``slot_of`` (per bar, its slot), ``order`` (the bars in the order they move), ``final_poses``
    ((n, 3): x [m], y [m], theta [rad]), ``plans`` (one PlanResult per move, in order) and
    ``assignment_cost`` [m]."""

    def __init__(self, status, message, slot_of, order, final_poses, plans, cost):
        self.status, self.message, self.slot_of, self.order = status, message, list(slot_of), list(order)
        self.final_poses, self.plans, self.assignment_cost = final_poses, list(plans), cost

    @property
    def assembled(self):
        return self.status == "assembled"

    def __repr__(self):
        return f"<nanopush.Assembly {self.status}, {len(self.slot_of)} bars, {len(self.plans)} moved>"


def assemble(scene, objects, slots, *, tolerance=(1e-9, 0.01), objective="pushes", max_pushes=10, gap=2e-9):
    """Move several bars of `scene`'s kind from `objects` into `slots` (both (n, 3) array-likes
    of x [m], y [m], theta [rad]), as ``nanopush assemble`` (docs/planning.md): the assignment
    of least summed distance, then bar by bar, each bar's pushes planned and kept `gap` [m]
    clear (bar and tip) of the others. Returns an Assembly; bad input is InputError."""
    return Assembly(*_nanopush._assemble(_as_scene(scene), objects, slots, tolerance, str(objective), max_pushes, gap))


def compare(scene, method="faithful", rtol=None, atol=None, tolerance=None, law=None, accuracy=None):
    """Run a scene with both engines, the C++ (``method``: faithful, modern or dop853) and
    the F77, under ``law`` (thesis or printed, the laws both implement; default the scene's,
    thesis for a coulomb scene), and judge them as ``nanopush compare`` does: faithful takes
    the F77 steps, so every column must agree within ``tolerance`` (default 100 rtol);
    modern and dop853 are judged by convergence (see Comparison). ``accuracy`` (in [1e-14,
    0.1], instead of ``rtol``): both engines run at the rtol where the C++ configuration
    reaches that error of the final pose (``nanopush compare --accuracy``, docs/accuracy.md);
    Comparison.accuracy says which. Returns a Comparison (true when the engines agree).
    Raises nanopush.SolverError when a run, or a reference run, does not complete, or the
    accuracy is not reached (nothing to compare), InputError for bad settings."""
    return Comparison(_nanopush._compare(_as_scene(scene), method or "faithful", law or "", rtol, atol, tolerance,
                                         accuracy))


# ---- sweeps ---------------------------------------------------------------------------


class SweepResult:
    """The table of a sweep, one row per point in point order (docs/sweeps.md): columns by
    name (``result["fx"]``: float arrays, NaN where a cell is missing; integer columns as
    int64 when complete; text columns as str arrays), ``columns`` (names, in order),
    ``units``, ``status`` and ``message`` per point, ``ok`` (a boolean mask: status ok or
    at_rest, the answers), ``failed`` (the number of other points), to_dict(), to_pandas() and
    to_xarray()."""

    columns: list
    units: dict

    def __init__(self, names, units, data):
        self.columns, self.units, self._data = list(names), dict(units), data

    def __getitem__(self, name):
        return self._data[name]

    def __contains__(self, name):
        return name in self._data

    def __len__(self):
        return len(self._data["point"])

    @property
    def status(self):
        return self._data["status"]

    @property
    def message(self):
        return self._data["message"]

    @property
    def ok(self):
        return (self._data["status"] == "ok") | (self._data["status"] == "at_rest")

    @property
    def failed(self):
        return int((~self.ok).sum())

    def to_dict(self):
        """The columns as a dict of arrays, in order (pandas.DataFrame(result.to_dict()))."""
        return {k: self._data[k] for k in self.columns}

    def to_pandas(self):
        """The table as a pandas.DataFrame, one row per point, columns in order (pandas is
        imported here: an optional dependency)."""
        import pandas

        return pandas.DataFrame(self.to_dict())

    def to_xarray(self):
        """The table as an xarray.Dataset over the dimension ``point``, each column a variable
        with its ``units`` attribute (xarray is imported here: an optional dependency)."""
        import xarray

        return xarray.Dataset({k: ("point", self._data[k], {"units": self.units.get(k, "")})
                               for k in self.columns if k != "point"},
                              coords={"point": self._data["point"]})

    def __repr__(self):
        return f"<nanopush.SweepResult {len(self)} points, {self.failed} failed, columns {self.columns}>"


class PlanCheck(SweepResult):
    """nanopush.check_plan's answer: the per-trial table (a SweepResult) and its summary,
    ``trials``, ``successes``, ``probability`` and ``interval`` (95 % Wilson)."""

    def __init__(self, names, units, data, summary):
        super().__init__(names, units, data)
        self.trials, self.successes = int(summary["trials"]), int(summary["successes"])
        self.probability, self.interval = float(summary["probability"]), tuple(summary["interval"])

    def __repr__(self):
        return (f"<nanopush.PlanCheck {self.successes}/{self.trials} reached, probability {self.probability:.3g} "
                f"(95 % interval {self.interval[0]:.3g} to {self.interval[1]:.3g})>")


class SweepFile:
    """What a sweep streamed to a file (``sweep(..., out=PATH)``) did: ``path`` (the CSV
    table, its Table Schema sidecar beside it, NAME.schema.json), ``points``, ``done``, ``resumed`` (rows
    taken from the journal of an interrupted run), ``failed`` (rows whose status is not an
    answer) and ``complete``. Read the table with ``pandas.read_csv(result.path)``."""

    path: "_pathlib.Path"
    points: int
    done: int
    resumed: int
    failed: int
    complete: bool

    def __init__(self, summary):
        self.path = _pathlib.Path(summary["path"])
        self.points, self.done, self.resumed = summary["points"], summary["done"], summary["resumed"]
        self.failed, self.complete = summary["failed"], summary["complete"]

    def __repr__(self):
        return (f"<nanopush.SweepFile {str(self.path)!r}: {self.done} of {self.points} points "
                f"({self.resumed} resumed), {self.failed} failed>")


_TASKS = ("friction", "icor", "estimate-mu")


def sweep(task, vary=None, *, vary_log=None, points=None, set=None, jobs=0, engine=None, method=None, law=None,
          accuracy=None, error_estimate=None, check=False, progress=None, out=None):
    """Evaluate a task at every point of a plan on C++ threads (the GIL released) and return
    the table as a SweepResult (the rows of ``nanopush sweep``), or stream it to a file.

    task      a nanopush.Scene, a preset name or a scene file: the ``run`` task (the final
              pose, distance, rotation, iCOR, stick time, peak friction, work, counts of
              each run); or ``"friction"``, ``"icor"``, ``"estimate-mu"``
    vary      {key: values}: the axes of a cartesian grid, the last varying fastest; values
              are a sequence (numbers, or text for text keys) or ``"FROM:TO:N"``
    vary_log  {key: "FROM:TO:N"}: geometrically spaced axes (after the ``vary`` axes)
    points    {key: values} of equal lengths: a list of points instead of a grid
    set       {key: value}: fixed for every point (scene keys for a run; the task's keys,
              e.g. {"a": 27.5e-9, "b": 50e-9}, otherwise)
    jobs      threads (0: every core); the table is the same for any number
    engine, method, law, accuracy, error_estimate   the run task's, as for nanopush.run
    check     raise nanopush.SolverError if any point failed, with .outcome, .status and
              .status_code the first failed point's (as for nanopush.run) and .partial the
              whole table (default: keep the status and message of each point in the table)
    progress  a callable progress(done, total), called about twice a second and at the end
              (from the calling thread); an exception it raises stops the sweep
    out       a path: the table goes to that CSV file (and its sidecar) as ``nanopush sweep
              --out`` writes it, with a journal beside it (PATH.journal), instead of into
              memory; returns a SweepFile. Run again with the same arguments to resume an
              interrupted sweep from its journal

    Ctrl-C (KeyboardInterrupt) stops a sweep within about a second: points in flight finish,
    no new point starts; with ``out`` the journal keeps every finished row.

    Keys and units per task: docs/sweeps.md. Bad keys or values raise nanopush.InputError
    before any point runs.
    """
    scene = None
    if isinstance(task, str) and task in _TASKS:
        name = task
    elif isinstance(task, str) and task == "run":
        raise _input_error("task = run: a run sweep takes a scene (nanopush.Scene, a preset name or a file)", "task")
    else:
        scene, name = _as_scene(task), "run"
    axes = [(k, v, False) for k, v in _mapping("vary", vary, "{key: values}").items()]
    axes += [(k, v, True) for k, v in _mapping("vary_log", vary_log, "{key: 'FROM:TO:N'}").items()]
    if points is not None:
        points = _mapping("points", points, "{key: values} of equal lengths")
    if out is not None:
        if check:
            raise _input_error("check = True: give it without out (read the failed rows from the file)", "check")
        out = _os.fspath(out)
    names, units, data = _nanopush._sweep(name, scene, axes, points, _mapping("set", set, "{key: value}"),
                                         _count("jobs", jobs), engine or "", method or "", law or "", accuracy,
                                         error_estimate, progress, out)
    if out is not None:
        return SweepFile(data)
    res = SweepResult(names, units, data)
    if check and res.failed:
        bad = [i for i, ok in enumerate(res.ok) if not ok]
        outcome, message = str(res.status[bad[0]]), str(res.message[bad[0]])
        e = SolverError(f"sweep: {res.failed} of {len(res)} points failed; first, point {bad[0]}: "
                        f"{outcome}: {message}")
        # the first failed point's status as the C API gives it for the same run
        e.status_code, e.status = _nanopush._status_code(outcome, message)
        e.outcome, e.t_reached, e.partial = outcome, None, res
        raise e
    return res
