"""The package shaped like SciPy: run(t_eval=...) against runs that end at each time (an
independent path), Result's solve_ivp names, estimate_mu broadcasting against the scalar call,
did-you-mean for a mistyped key, Scene.set kept in its document, and a signature for every
public callable (inspect.signature) that the .pyi stubs agree with."""

import ast
import inspect
import pathlib

import numpy as np
import pytest

import nanopush
from test_run import same


def short(preset="fig3_6a", **keys):
    s = nanopush.Scene.preset(preset)
    s.set({"solver.t_end": 0.4e-9, "solver.samples": 21, **keys})
    return s


# ---- Result: solve_ivp's names ------------------------------------------------------------


def test_result_has_solve_ivp_names():
    r = nanopush.run(short())
    assert r.success is True and r.status == 0 and isinstance(r.status, int)
    assert isinstance(r.message, str) and r.message
    assert r.nfev == r.nfcn > 0
    assert r.states.shape == (6, len(r)) and not r.states.flags.writeable
    for k, name in enumerate(nanopush.Result.state_names):
        assert same(r.states[k], getattr(r, name)), name
    assert same(r.y, r.array[:, 2])  # y stays the y coordinate


def test_partial_result_reports_failure():
    s = short()
    s.set("solver.max_steps", 5)
    with pytest.raises(nanopush.SolverError) as e:
        nanopush.run(s)
    p = e.value.partial
    assert p.success is False and p.status == -1 and p.message


# ---- run(t_eval=...) ------------------------------------------------------------------------


@pytest.mark.parametrize("engine", ["cxx", "f77"])
def test_t_eval_on_the_scene_grid_is_the_same_run(engine):
    s = short()
    a = nanopush.run(s, engine=engine)
    b = nanopush.run(s, engine=engine, t_eval=s.output_times())
    assert same(a.array, b.array) and a.nfev == b.nfev


@pytest.mark.parametrize("engine,preset,law", [("cxx", "fig3_6a", None), ("f77", "fig3_6a", None),
                                               ("cxx", "fig3_18", "coulomb")])
def test_t_eval_matches_runs_ending_at_each_time(engine, preset, law):
    """Each output of t_eval against a separate run whose t_end is that time (its last row)."""
    s = nanopush.Scene.preset(preset)
    tend = s.info()["solver"]["t_end"]
    times = np.array([0.13, 0.5, 0.77, 1.0]) * tend
    kw = dict(engine=engine, rtol=1e-12, law=law, error_estimate=False)
    r = nanopush.run(s, t_eval=times, **kw)
    assert same(r.t, times) and len(r) == 4
    for i, tau in enumerate(times):
        one = s.copy()
        one.set({"solver.t_end": float(tau), "solver.samples": 2})
        ref = nanopush.run(one, **kw)
        assert ref.t[-1] == tau
        for k, name in enumerate(nanopush.Result.state_names):
            scale = max(np.abs(ref.states[k]).max(), np.abs(r.states[k]).max(), 1e-300)
            assert abs(r.states[k, i] - ref.states[k, -1]) <= 1e-8 * scale, (name, tau)


def test_t_eval_from_zero_and_single_times():
    s = short()
    assert same(nanopush.run(s, t_eval=[0.0]).array, nanopush.run(s).array[:1])
    r = nanopush.run(s, t_eval=[2e-10])
    assert len(r) == 1 and r.t[0] == 2e-10


@pytest.mark.parametrize("t_eval,match", [
    ([1e-10, 5e-11], r"^t_eval\[1\] = 5e-11: must be greater than the time before it"),
    ([0.0, 1.0], r"^t_eval\[1\] = 1: must be in \[0, 4e-10\]"),
    ([0.0, float("nan")], r"^t_eval\[1\] = nan"),
    ([[0.0, 1e-10]], r"^t_eval = an array of shape \(1, 2\)"),
    ([], r"^t_eval = an array of shape \(0,\)"),
    ("soon", r"^t_eval = 'soon'"),
])
def test_bad_t_eval(t_eval, match):
    with pytest.raises(nanopush.InputError, match=match):
        nanopush.run(short(), t_eval=t_eval)


# ---- estimate_mu broadcasts -------------------------------------------------------------------


def test_estimate_mu_broadcasts_like_the_scalar_call():
    F = np.array([1e-6, 2e-6, 3e-6])[:, None]
    yn = np.array([0.0, 5e-8, 1e-7, 2e-7])
    e = nanopush.estimate_mu(F, 1e-8, yn=yn, sigma_yn=2e-9, sigma_L=1e-9)
    assert isinstance(e, nanopush.MuEstimates) and e.basis == "force"
    assert e.mu.shape == e.sigma.shape == e.load.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            one = nanopush.estimate_mu(float(F[i, 0]), 1e-8, yn=float(yn[j]), sigma_yn=2e-9, sigma_L=1e-9)
            assert (e.mu[i, j], e.sigma[i, j], e.load[i, j]) == (one.mu, one.sigma, one.load)
            for c in one.contributions:
                assert e.derivatives[c["input"]][i, j] == c["derivative"]
                assert e.contributions[c["input"]][i, j] == c["contribution"]
    r = nanopush.estimate_mu([1e-6, 2e-6], sigma_force=[1e-8, 2e-8], R=3e-7, sigma_R=1e-8)
    assert r.basis == "icor" and r.mu.shape == (2,)
    assert r.mu[1] == nanopush.estimate_mu(2e-6, 2e-8, R=3e-7, sigma_R=1e-8).mu
    assert isinstance(nanopush.estimate_mu(1e-6, yn=1e-7), nanopush.MuEstimate)  # scalars: as before


def test_estimate_mu_names_the_bad_element():
    with pytest.raises(nanopush.InputError) as e:
        nanopush.estimate_mu([1e-6, -1e-6], yn=1e-7)
    assert e.value.index == (1,) and "F" in str(e.value)
    with pytest.raises(ValueError, match="could not be broadcast"):
        nanopush.estimate_mu([1e-6, 2e-6], yn=[1e-7, 2e-7, 3e-7])


# ---- keys ---------------------------------------------------------------------------------


def test_unknown_key_suggests_the_nearest(cli):
    s = nanopush.Scene.preset("fig3_18")
    with pytest.raises(nanopush.InputError, match=r"did you mean surface\.mu\?"):
        s.set("surface.muu", 0.1)
    with pytest.raises(nanopush.InputError, match=r"did you mean solver\.samples\?"):
        s.set("solver.sampels", 11)
    assert "did you mean surface.mu?" in cli.error("run", "fig3_18", "--set", "surface.muu=0.1")


def test_scene_set_keeps_document_and_description_consistent():
    s = nanopush.Scene.preset("fig3_18")
    assert "mu = 0.06" in s.description
    s.set("surface.mu", 0.1)
    again = nanopush.Scene.from_toml(s.to_toml())
    assert again.info()["surface"]["mu"] == 0.1 == s.info()["surface"]["mu"]
    assert s.description == s.info()["description"] == again.description
    assert s.description.endswith("[set: surface.mu = 0.1]")  # the stale "mu = 0.06" is marked
    s.set({"surface.mu": np.float64(0.2), "solver.samples": 11})
    s.unset("solver.samples")
    assert s.description.endswith("[set: surface.mu = 0.2; solver.samples = (default)]")
    assert nanopush.Scene.from_toml(s.to_toml()).description == s.description
    with pytest.raises(nanopush.InputError):
        s.set("surface.mu", -1.0)
    assert s.description.endswith("[set: surface.mu = 0.2; solver.samples = (default)]")
    s.set("scene.description", "mu lowered to 0.1")
    assert s.description == "mu lowered to 0.1" == nanopush.Scene.from_toml(s.to_toml()).description


# ---- signatures and stubs --------------------------------------------------------------------


def public_callables():
    for name in nanopush.__all__:
        obj = getattr(nanopush, name)
        if inspect.isclass(obj):
            for m, attr in vars(obj).items():
                if not m.startswith("_") and callable(attr) and not isinstance(attr, property):
                    yield f"{name}.{m}", getattr(obj, m)
        elif callable(obj):
            yield name, obj
    for name in nanopush.icor.__all__:
        obj = getattr(nanopush.icor, name)
        if callable(obj) and not inspect.isclass(obj):
            yield f"icor.{name}", obj


def test_every_public_callable_has_a_signature():
    missing = []
    for name, f in public_callables():
        try:
            inspect.signature(f)
        except (ValueError, TypeError):
            missing.append(name)
    assert not missing, missing
    sig = inspect.signature(nanopush.friction_wrench)
    assert list(sig.parameters)[:4] == ["a", "b", "R", "alpha"] and sig.parameters["sense"].default == 1
    assert inspect.signature(nanopush.estimate_mu).parameters["yn"].kind is inspect.Parameter.KEYWORD_ONLY
    assert "t_eval" in inspect.signature(nanopush.run).parameters
    assert list(inspect.signature(nanopush.Scene.set).parameters)[:1] == ["self"]


def test_classes_have_their_constructors_signature():
    # python.md: inspect.signature works on every function; a class's is its constructor's.
    sig = inspect.signature(nanopush.icor.Rod)
    assert list(sig.parameters) == ["length", "radius", "density", "hamaker", "z0", "gravity"]
    assert sig.parameters["length"].default == 5.9e-07
    assert nanopush.icor.Rod(**{k: p.default for k, p in sig.parameters.items()}).length == 5.9e-07


def stub_functions(path):
    """{qualified name: [parameter names]} of the functions a .pyi declares."""
    out = {}
    tree = ast.parse(pathlib.Path(path).read_text())

    def params(fn):
        a = fn.args
        names = [x.arg for x in a.posonlyargs + a.args + a.kwonlyargs]
        return names + ([a.vararg.arg] if a.vararg else []) + ([a.kwarg.arg] if a.kwarg else [])

    for node in tree.body:
        if isinstance(node, ast.FunctionDef):
            out[node.name] = params(node)
        elif isinstance(node, ast.ClassDef):
            for sub in node.body:
                if isinstance(sub, ast.FunctionDef):
                    out[f"{node.name}.{sub.name}"] = params(sub)
    return out


def test_stubs_are_installed_and_agree_with_the_signatures():
    pkg = pathlib.Path(nanopush.__file__).parent
    assert (pkg / "py.typed").is_file()
    stubs = stub_functions(pkg / "__init__.pyi")
    stubs.update({f"icor.{k}": v for k, v in stub_functions(pkg / "icor.pyi").items()})
    absent, differ = [], []
    for name, f in public_callables():
        if name not in stubs:
            absent.append(name)
            continue
        sig = inspect.signature(f)
        expected = list(sig.parameters)
        if stubs[name] != expected:
            differ.append((name, stubs[name], expected))
    assert not absent, absent
    assert not differ, differ


def test_stubs_are_what_stubgen_writes(source_dir):
    """The committed stubs are current: python/stubgen.py run on this package writes them."""
    import importlib.util

    spec = importlib.util.spec_from_file_location("stubgen", pathlib.Path(source_dir) / "python" / "stubgen.py")
    stubgen = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(stubgen)
    for file, text in stubgen.stubs().items():
        committed = pathlib.Path(source_dir) / "python" / "nanopush" / file
        ast.parse(text)
        assert committed.read_text() == text, f"{file}: run python/stubgen.py python/nanopush (docs/python.md)"
