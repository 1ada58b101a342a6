"""nanopush.run, Result and compare against `nanopush run` / `nanopush compare`: the same
trajectory bit for bit, the same counts, the same messages."""

import re

import numpy as np
import pytest

import nanopush
from conftest import column, read_csv


def same(a, b):
    """Bit-for-bit equality of two float arrays (NaN equal to NaN, -0 distinct from 0)."""
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return a.shape == b.shape and np.array_equal(a, b, equal_nan=True) and np.array_equal(np.signbit(a), np.signbit(b))


def cli_counts(stderr):
    m = re.search(r"RHS evaluations (\d+), accepted steps (\d+), rejected steps (\d+)", stderr)
    assert m, stderr
    return tuple(int(x) for x in m.groups())


@pytest.mark.parametrize("preset, args, kwargs", [
    ("fig3_6a", ["--engine", "cxx", "--method", "faithful"], dict(engine="cxx", method="faithful")),
    ("fig3_6a", ["--engine", "f77"], dict(engine="f77")),
    ("fig3_6c", ["--method", "modern", "--rtol", "1e-9"], dict(method="modern", rtol=1e-9)),
    ("fig3_17", ["--law", "coulomb"], dict(law="coulomb")),
    ("fig3_17", ["--engine", "f77", "--law", "thesis"], dict(engine="f77", law="thesis")),
])
def test_trajectory_bit_for_bit(cli, tmp_path, preset, args, kwargs):
    out = tmp_path / "cli.csv"
    p = cli("run", preset, *args, "--out", out)
    r = nanopush.run(preset, **kwargs)
    header, rows = read_csv(out)
    assert header == nanopush.Result.columns
    for name in header:
        assert same(getattr(r, name), column(header, rows, name)), name
    assert same(r.array, np.array([[float(c) for c in row] for row in rows]))
    assert (r.nfcn, r.steps, r.rejected) == cli_counts(p.stderr)
    assert r.engine in p.stderr
    # The CSV the package writes is the command line's, byte for byte.
    r.to_csv(tmp_path / "py.csv")
    assert (tmp_path / "py.csv").read_bytes() == out.read_bytes()
    assert (tmp_path / "py.schema.json").exists()


def test_scene_set_matches_cli_set(cli, tmp_path):
    out = tmp_path / "cli.csv"
    cli("run", "fig3_18", "--set", "surface.mu=0.1", "--set", "push.yn=20e-9", "--out", out, "--quiet")
    scene = nanopush.Scene.preset("fig3_18")
    scene.set("surface.mu", 0.1)
    scene.set("push.yn", 20e-9)
    r = nanopush.run(scene)
    header, rows = read_csv(out)
    for name in header:
        assert same(getattr(r, name), column(header, rows, name)), name


def test_result_arrays_and_dict():
    r = nanopush.run("fig3_6a")
    n = len(r)
    assert n == nanopush.Scene.preset("fig3_6a").info()["solver"]["samples"]
    for name in nanopush.Result.columns:
        a = getattr(r, name)
        assert a.shape == (n,) and a.dtype == np.float64
        assert not a.flags.writeable
    with pytest.raises(ValueError):
        r.x[0] = 1.0
    assert r.array.shape == (n, 10)
    d = r.to_dict()
    assert list(d) == nanopush.Result.columns
    for name, a in d.items():
        assert a.flags.c_contiguous and a.flags.writeable and same(a, getattr(r, name))
    d["x"][0] = 123.0  # an independent copy
    assert r.x[0] != 123.0
    assert same(r.t, nanopush.Scene.preset("fig3_6a").output_times())
    assert nanopush.Result.units["mf"] == "N m"
    # Views keep the result alive.
    theta = nanopush.run("fig3_6a").theta
    assert theta[-1] == r.theta[-1]
    assert r.integrator_status == "success" and r.status == 0 and r.complete and r.wall_time > 0


@pytest.mark.parametrize("method", ["faithful", "modern", "dop853"])
@pytest.mark.parametrize("scene,law", [("fig3_6c", None), ("fig3_18", "printed")])
def test_compare_matches_cli(cli, method, scene, law):
    args = ("compare", scene, "--method", method) + (("--law", law) if law else ())
    p = cli(*args)
    c = nanopush.compare(scene, method=method, law=law)
    assert c.agree and bool(c) and "engines agree" in p.stdout
    m = re.search(r"RHS evaluations (\d+) vs (\d+)", p.stdout)
    assert (c.cxx.nfcn, c.f77.nfcn) == (int(m.group(1)), int(m.group(2)))
    lines = {ln[2:10].strip(): ln for ln in p.stdout.splitlines() if ln.startswith("  ") and len(ln) > 52}
    assert set(c.columns) <= set(lines)
    if method == "faithful":
        assert c.kind == "same-steps"
        for name, col in c.columns.items():
            ln = lines[name]  # fixed-width columns: name, max |diff|, unit, max |diff|/scale, scale
            assert f"{col['max_abs_diff']:.4g}" == f"{float(ln[10:26]):.4g}", name
            assert ln[26:36].strip() == col["unit"]
            assert f"{col['relative']:.4g}" == f"{float(ln[36:54]):.4g}", name
            assert f"{col['scale']:.4g}" == f"{float(ln[54:].split()[0]):.4g}", name
        tol = re.search(r"tolerance on max \|diff\|/scale: (\S+)", p.stdout).group(1)
        assert c.tolerance == pytest.approx(float(tol), rel=1e-4)
        return
    assert c.kind == "convergence" and c.tolerance is None
    for name, col in c.columns.items():
        ln = lines[name]  # fixed-width: name, error cxx, error f77, |cxx - f77|, the same tight, scale
        for key, lo, hi in (("error_cxx", 10, 24), ("error_f77", 24, 38), ("diff", 38, 54), ("diff_tight", 54, 72)):
            assert f"{col[key]:.3g}" == f"{float(ln[lo:hi]):.3g}", (name, key)
        assert f"{col['scale']:.3g}" == f"{float(ln[72:].split()[0]):.3g}", name


def test_compare_refuses_the_coulomb_law(cli):
    msg = cli.error("compare", "fig3_18", "--law", "coulomb")
    with pytest.raises(nanopush.InputError, match="CVODE cross-check"):
        nanopush.compare("fig3_18", law="coulomb")
    assert "--method cvode" in msg


def test_bad_settings_are_input_errors(cli):
    msg = cli.error("run", "fig3_6a", "--set", "object.mass=-1")
    scene = nanopush.Scene.preset("fig3_6a")
    with pytest.raises(nanopush.InputError) as e:
        scene.set("object.mass", -1)
    assert str(e.value) == msg and e.value.field == "object.mass"
    assert isinstance(e.value, ValueError)
    with pytest.raises(ValueError, match=r"^engine = gpu: must be cxx or f77$"):
        nanopush.run(scene, engine="gpu")
    msg = cli.error("run", "fig3_6a", "--engine", "f77", "--method", "modern")
    with pytest.raises(nanopush.InputError) as e:
        nanopush.run(scene, engine="f77", method="modern")
    assert str(e.value) == msg
    # engine f77 with the scene's own method other than faithful/auto: as the CLI (issue 34)
    msg = cli.error("run", "fig3_6a", "--engine", "f77", "--set", "solver.method=modern")
    own = nanopush.Scene.preset("fig3_6a")
    own.set("solver.method", "modern")
    with pytest.raises(nanopush.InputError) as e:
        nanopush.run(own, engine="f77")
    # the command line's message under the argument's Python name, engine (not --engine)
    assert msg.startswith("--engine = f77: ")
    assert str(e.value) == msg.replace("--engine = ", "engine = ", 1) and e.value.field == "engine"
    assert "conflicts with the scene's solver.method" in msg
    with pytest.raises(nanopush.InputError, match="rtol"):
        nanopush.run(scene, rtol=-1.0)
    with pytest.raises(nanopush.InputError, match="no preset"):
        nanopush.run("no_such_scene")


def test_solver_failure_carries_status_and_partial(cli):
    msg = cli.error("run", "fig3_6a", "--set", "solver.max_steps=5", "--out", "-", expect=3)
    scene = nanopush.Scene.preset("fig3_6a")
    scene.set("solver.max_steps", 5)
    with pytest.raises(nanopush.SolverError) as e:
        nanopush.run(scene)
    err = e.value
    assert str(err) == msg
    assert isinstance(err, RuntimeError)
    assert err.status == "too_many_steps" and err.status_code == 2
    assert err.partial is not None and not err.partial.complete
    assert 0 < len(err.partial) < 401 and err.t_reached < scene.info()["solver"]["t_end"]
    assert err.partial.t[-1] <= err.t_reached


def test_gil_released_during_a_run():
    from conftest import assert_runs_without_the_gil
    scene = nanopush.Scene.preset("fig3_6a")
    scene.set({"solver.t_end": 5e-7, "solver.max_steps": 10_000_000})
    r = assert_runs_without_the_gil(lambda: nanopush.run(scene))
    assert r.complete and r.t[-1] == 5e-7


def test_compare_cannot_judge_without_a_reference(cli):
    # fig3_29 under the printed law: dop853's reference run at rtol 1e-14 fails at t = 0, so
    # there is nothing to judge against (exit 3 on the command line, SolverError here).
    p = cli("compare", "fig3_29", "--law", "printed", "--method", "dop853", expect=3)
    assert "cannot judge" in p.stderr
    with pytest.raises(nanopush.SolverError, match="cannot judge"):
        nanopush.compare("fig3_29", law="printed", method="dop853")


def test_printed_readings_are_scene_keys():
    # The reading the thesis' figures support best runs fig3_29 (mu = 0.17) to 1.6 ns with a
    # bounded angle; each switch is a key, and a bad value names the key and the choices.
    scene = nanopush.Scene.preset("fig3_29")
    scene.set("surface.printed.reading", "as_drawn")
    r = nanopush.run(scene, law="printed", engine="f77")
    assert r.t[-1] == pytest.approx(1.6e-9) and max(abs(r.theta)) < 2.5
    scene.set("surface.printed.c4", "squares_nm")
    with pytest.raises(nanopush.InputError, match="squares_nm, cubes"):
        scene.set("surface.printed.c4", "square")


_INTERRUPTED_FAILING_RUN = """
import os, signal, sys, threading
import nanopush
s = nanopush.Scene.preset("tip_push_nanorod")
# the dynamic tip model spends its step budget (100000 steps: about a second) and fails
s.set({"tip.model": "dynamic", "tip.stiffness": 10.0, "tip.speed": 1.0, "tip.travel": 400e-9, "tip.mu": 0.3})
threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT)).start()  # Ctrl-C during the run
if sys.argv[1] == "catch":
    try:
        nanopush.run(s, error_estimate=False)
    except nanopush.SolverError as e:
        print("SolverError", e.status)
    except KeyboardInterrupt:
        print("KeyboardInterrupt at the call")
else:
    nanopush.run(s, error_estimate=False)
"""


@pytest.mark.parametrize("mode", ["catch", "uncaught"])
def test_interrupt_during_a_run_that_fails_is_a_keyboard_interrupt(mode):
    # Ctrl-C arriving while the engine runs (the GIL released) and the run then failing: the
    # interrupt wins, as over a run that succeeds. It used to set SolverError over the pending
    # interrupt: "object address ... SolverError ... lost sys.stderr", exit 1.
    import subprocess
    import sys
    p = subprocess.run([sys.executable, "-c", _INTERRUPTED_FAILING_RUN, mode], capture_output=True, text=True,
                       timeout=300)
    assert "lost sys.stderr" not in p.stderr and "object address" not in p.stderr, p.stderr
    if mode == "catch":
        assert p.returncode == 0 and p.stdout.strip() == "KeyboardInterrupt at the call", (p.stdout, p.stderr)
    else:
        # an uncaught KeyboardInterrupt: Python ends by SIGINT (exit 130 in a shell)
        assert p.returncode == -2, (p.returncode, p.stderr)
        assert p.stderr.rstrip().endswith("KeyboardInterrupt") and "SolverError" not in p.stderr, p.stderr


def test_a_tip_push_gives_the_tip_as_the_cli_table_does(cli, tmp_path):
    # the tip columns and events of `nanopush run tip_push_nanorod --out` (the same run, bit for bit)
    r = nanopush.run("tip_push_nanorod")
    out = tmp_path / "tip.csv"
    cli("run", "tip_push_nanorod", "--out", str(out))
    header, rows = read_csv(out)
    for key, col in (("x", "tip_x"), ("y", "tip_y"), ("fx", "tip_fx"), ("fy", "tip_fy"), ("contact", "contact")):
        assert np.array_equal(r.tip[key], np.array(column(header, rows, col))), key
        assert not r.tip[key].flags.writeable
    assert r.tip["contact"].dtype.kind == "i" and set(np.unique(r.tip["contact"])) <= {0, 1, 2}
    assert [what for _, what in r.tip_events] == ["contact", "release"]
    assert 0 < r.tip_events[0][0] < r.tip_events[1][0] <= r.t[-1]
    plain = nanopush.run("fig3_18")
    assert plain.tip is None and plain.tip_events == []
