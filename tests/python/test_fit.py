"""nanopush.fit against `nanopush fit --json` (the same estimates, bit for bit), the truth back from
synthetic data, and the messages for bad input."""

import json
import math

import pytest

import nanopush


def short_scene():
    s = nanopush.Scene.preset("fig3_6a")
    s.set({"solver.t_end": 0.4e-9, "solver.samples": 21})
    return s


def test_fit_matches_cli(cli, tmp_path):
    truth = short_scene()
    data = tmp_path / "data.csv"
    text = nanopush.synthesize(truth, (2e-9, 0.0, 0.0), 3, path=data)
    assert text.startswith("t,") and data.read_text() == text
    force = truth.info()["push"]["force"]
    start = truth.copy()
    start.set("push.force", 4e-6)
    r = nanopush.fit(start, data, "push.force")
    assert r.converged and r.identifiable
    p = r.parameters["push.force"]
    assert abs(p["value"] - force) < 3 * p["stderr"]
    assert r.fitted.shape == (21, 3) and r.t.shape == (21,) and r.correlation.shape == (1, 1)
    assert "push.force" in repr(r)
    summary = tmp_path / "fit.json"
    cli("fit", "fig3_6a", data, "--free", "push.force", "--set", "solver.t_end=4e-10", "--set", "solver.samples=21",
        "--set", "push.force=4e-6", "--json", summary, "--out", tmp_path / "out")
    j = json.loads(summary.read_text())
    assert j["parameters"]["push.force"]["value"] == p["value"]
    assert j["parameters"]["push.force"]["stderr"] == p["stderr"]
    assert j["chi2_dof"] == r.chi2_dof and j["converged"] is True
    assert json.loads(r.json)["parameters"]["push.force"]["value"] == p["value"]


def test_fit_bad_input(tmp_path):
    s = short_scene()
    data = tmp_path / "data.csv"
    nanopush.synthesize(s, (2e-9, 0.0, 0.0), 3, path=data)
    with pytest.raises(nanopush.InputError, match="push.nonsense"):
        nanopush.fit(s, data, ["push.nonsense"])
    with pytest.raises(nanopush.InputError, match="sigma"):
        nanopush.fit(s, data, "push.force", sigma={"x": 1e-9})
    bad = tmp_path / "bad.csv"
    bad.write_text("t,x,sigma_x\n0,0,1e-9\n1e-10,nan,1e-9\n")
    with pytest.raises(nanopush.InputError, match="row 2"):
        nanopush.fit(s, bad, "push.force")
    assert math.isfinite(nanopush.fit(s, data, "push.force").chi2)


def test_fit_accuracy(tmp_path):
    """fit(accuracy=E): the forward solves' rtol chosen for E, checked at the estimate; the
    same rtol and estimate as the C++ library's FitResult says in its JSON."""
    truth = short_scene()
    data = tmp_path / "data.csv"
    nanopush.synthesize(truth, (2e-9, 0.0, 0.0), 3, path=data)
    start = truth.copy()
    start.set("push.force", 4e-6)
    r = nanopush.fit(start, data, "push.force", accuracy=1e-9)
    assert r.converged
    a = r.accuracy
    assert a["requested"] == 1e-9 and a["reached"] and a["estimate"] <= 1e-9 and a["rtol_used"] <= 1e-9
    assert json.loads(r.json)["accuracy"]["rtol_used"] == a["rtol_used"]
    assert nanopush.fit(start, data, "push.force").accuracy is None
    with pytest.raises(nanopush.InputError, match=r"^accuracy = 1: must be in \[1e-14, 0.1\]"):
        nanopush.fit(start, data, "push.force", accuracy=1.0)
