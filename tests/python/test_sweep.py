"""nanopush.sweep against `nanopush sweep`: the same table, cell for cell (numbers bit for bit),
for every task; the same on any number of threads; failing points kept; errors before work."""

import math

import numpy as np
import pytest

import nanopush
from conftest import assert_runs_without_the_gil, read_csv
from test_run import same


def assert_same_table(res, path):
    header, rows = read_csv(path)
    assert res.columns == header
    assert len(res) == len(rows)
    for j, name in enumerate(header):
        got = res[name]
        cells = [r[j] for r in rows]
        if got.dtype.kind == "U":  # text cells as csv_quote wrote them
            assert [c[1:-1].replace('""', '"') if c.startswith('"') else c for c in cells] == list(got), name
        elif got.dtype.kind == "i":
            assert list(got) == [int(c) for c in cells], name
        else:
            assert same(got, [float(c) if c != "" else math.nan for c in cells]), name


def test_run_task(cli, tmp_path):
    out = tmp_path / "run.csv"
    cli("sweep", "fig3_18", "--set", "surface.law=coulomb", "--vary", "surface.mu=0.05:0.2:3",
        "--vary", "push.yn=0:45e-9:2", "--out", out, "--quiet")
    scene = nanopush.Scene.preset("fig3_18")
    res = nanopush.sweep(scene, vary={"surface.mu": "0.05:0.2:3", "push.yn": [0.0, 45e-9]},
                         set={"surface.law": "coulomb"})
    assert_same_table(res, out)
    assert res.failed == 0 and res.ok.all()
    assert res.units["x_final"] == "m"
    # The scene itself was not changed by `set`.
    assert scene.info()["surface"]["law"] == "thesis"


@pytest.mark.parametrize("task, cli_args, kwargs", [
    ("friction", ["--vary", "R=1e-9:1e-6:7", "--vary", "alpha=0,0.5,3.14159", "--set", "sense=-1"],
     dict(vary={"R": "1e-9:1e-6:7", "alpha": np.array([0, 0.5, 3.14159])}, set={"sense": -1})),
    ("icor", ["--vary", "yn=0:2.95e-7:5", "--vary", "cubic=brent,eigen", "--set", "mu=0.2"],
     dict(vary={"yn": "0:2.95e-7:5", "cubic": ["brent", "eigen"]}, set={"mu": 0.2})),
    ("estimate-mu", ["--vary", "force=1e-6,2e-6", "--set", "yn=1e-7", "--set", "sigma_force=1e-8"],
     dict(vary={"force": [1e-6, 2e-6]}, set={"yn": 1e-7, "sigma_force": 1e-8})),
])
def test_other_tasks(cli, tmp_path, task, cli_args, kwargs):
    out = tmp_path / "t.csv"
    cli("sweep", "--task", task, *cli_args, "--out", out, "--quiet")
    assert_same_table(nanopush.sweep(task, **kwargs), out)


def test_vary_log_and_points(cli, tmp_path):
    out = tmp_path / "log.csv"
    cli("sweep", "--task", "friction", "--vary-log", "R=1e-10:1e-3:9", "--out", out, "--quiet")
    assert_same_table(nanopush.sweep("friction", vary_log={"R": "1e-10:1e-3:9"}), out)
    pts = tmp_path / "pts.csv"
    pts.write_text("R,alpha\n1e-9,0\n2e-8,1.5\n3e-7,-2\n")
    out = tmp_path / "p.csv"
    cli("sweep", "--task", "friction", "--points", pts, "--out", out, "--quiet")
    res = nanopush.sweep("friction", points={"R": [1e-9, 2e-8, 3e-7], "alpha": [0, 1.5, -2]})
    assert_same_table(res, out)


def test_threads_do_not_change_the_table():
    kw = dict(vary={"R": "0:1e-6:40", "alpha": "0:6.28:25"}, set={"a": 1e-8})
    one = nanopush.sweep("friction", jobs=1, **kw)
    two = nanopush.sweep("friction", jobs=2, **kw)
    for name in one.columns:
        a, b = one[name], two[name]
        assert (list(a) == list(b)) if a.dtype.kind == "U" else same(a, b)


def test_failing_points_are_kept(cli, tmp_path):
    out = tmp_path / "bad.csv"
    cli("sweep", "--task", "friction", "--vary", "R=1e-9,-1,2e-9", "--out", out, "--quiet", expect=65)
    res = nanopush.sweep("friction", vary={"R": [1e-9, -1, 2e-9]})
    assert_same_table(res, out)
    assert res.failed == 1 and list(res.ok) == [True, False, True]
    assert res.status[1] == "bad_input" and res.message[1].startswith("R = -1: must be >= 0")
    with pytest.raises(nanopush.SolverError, match="1 of 3 points failed"):
        nanopush.sweep("friction", vary={"R": [1e-9, -1, 2e-9]}, check=True)


def test_errors_before_any_work(cli, tmp_path):
    out = tmp_path / "never_written.csv"  # a scratch path, never a real /dev node
    msg = cli.error("sweep", "--task", "friction", "--vary", "Q=1,2", "--out", str(out), "--quiet")
    assert not out.exists()
    with pytest.raises(nanopush.InputError) as e:
        nanopush.sweep("friction", vary={"Q": [1, 2]})
    assert str(e.value) == msg
    with pytest.raises(nanopush.InputError, match="needs|takes a scene"):
        nanopush.sweep("run", vary={"surface.mu": [0.1]})
    with pytest.raises(nanopush.InputError, match="engine"):
        nanopush.sweep("friction", vary={"R": [1e-9]}, engine="f77")
    with pytest.raises(nanopush.InputError):
        nanopush.sweep("fig3_18", vary={"surface.mu": [0.1]}, engine="gpu")
    with pytest.raises(nanopush.InputError, match="same number of values"):
        nanopush.sweep("friction", points={"R": [1e-9, 2e-9], "alpha": [0.0]})


def test_a_key_fixed_and_varied_is_refused(cli, tmp_path):
    # As `nanopush sweep --set K=V --vary K=...` (exit 2): the fixed value would be overwritten
    # at every point. The message names the key.
    out = tmp_path / "never_written.csv"
    cli.error("sweep", "fig3_18", "--set", "surface.mu=0.2", "--vary", "surface.mu=0.1", "--out", str(out), "--quiet")
    for kwargs, other in [(dict(vary={"surface.mu": [0.1]}), "vary"), (dict(points={"surface.mu": [0.1]}), "points")]:
        with pytest.raises(nanopush.InputError) as e:
            nanopush.sweep("fig3_18", set={"surface.mu": 0.2}, jobs=1, **kwargs)
        assert str(e.value) == (f"set = surface.mu=0.2: conflicts with {other}, which varies surface.mu: a key is "
                                "either fixed or varied") and e.value.field == "set"
    with pytest.raises(nanopush.InputError, match=r"^set = R=1e-08: conflicts with vary, which varies R"):
        nanopush.sweep("friction", vary={"R": [1e-9]}, set={"a": 27.5e-9, "b": 50e-9, "R": 1e-8})


@pytest.mark.parametrize("kwargs, field", [
    (dict(vary={"surface.mu": []}), "vary.surface.mu"),
    (dict(vary={"push.force": [1e-6], "surface.mu": np.array([])}), "vary.surface.mu"),
    (dict(points={"surface.mu": []}), "points.surface.mu"),
])
def test_an_axis_without_values_is_refused(kwargs, field):
    # It gave a table of 0 points, as if the sweep had been asked for nothing.
    with pytest.raises(nanopush.InputError, match=r": no values: give one or more$") as e:
        nanopush.sweep("fig3_18", jobs=1, **kwargs)
    assert e.value.field == field and str(e.value).startswith(field + " = ")


def test_the_command_lines_flags_are_named_as_sweeps_arguments():
    with pytest.raises(nanopush.InputError, match=r"^vary = surface\.mu=0\.1:0\.2:0: N = 0 must be") as e:
        nanopush.sweep("fig3_18", vary={"surface.mu": "0.1:0.2:0"}, jobs=1)
    assert e.value.field == "vary"
    with pytest.raises(nanopush.InputError, match=r"^vary_log = surface\.mu=0:0\.2:3: a logarithmic range") as e:
        nanopush.sweep("fig3_18", vary_log={"surface.mu": "0:0.2:3"}, jobs=1)
    assert e.value.field == "vary_log"


def test_gil_released():
    res = assert_runs_without_the_gil(
        lambda: nanopush.sweep("friction", vary={"R": "0:1e-6:400", "alpha": "0:6.28:100"}, jobs=1))
    assert len(res) == 40000 and res.failed == 0


def test_check_attaches_the_table():
    with pytest.raises(nanopush.SolverError) as e:
        nanopush.sweep("friction", vary={"R": [1e-9, -1]}, check=True)
    assert e.value.status == "bad_input" and e.value.partial.failed == 1
    with pytest.raises(nanopush.InputError) as e:
        nanopush.sweep("run")
    assert e.value.field == "task" and e.value.index is None
