"""The error estimate, accuracy= and the outcomes in Python (docs/accuracy.md, docs/errors.md):
the same numbers as the command line, the outcomes as attributes and exception fields."""
import math

import numpy as np
import pytest

import nanopush


def test_every_run_carries_its_error_estimate():
    r = nanopush.run("fig3_18", law="coulomb")
    e = r.error
    assert r.outcome == "ok" and e["available"]
    assert 0 < e["estimate"] < 1e-6 and e["trajectory"] >= e["estimate"]
    assert e["estimate"] == r.error_estimate
    assert e["basis"] == "companion" and e["companion_rtol"] == pytest.approx(1e-12)
    assert r.nfcn_total == r.nfcn + e["nfcn"]
    plain = nanopush.run("fig3_18", law="coulomb", error_estimate=False)
    assert plain.error_estimate is None and plain.nfcn_total == plain.nfcn
    assert np.array_equal(plain.array, r.array)  # the estimate never changes the answer


def test_accuracy_is_reached_or_refused():
    r = nanopush.run("fig3_18", law="coulomb", accuracy=1e-9)
    assert r.accuracy["reached"] and r.accuracy["requested"] == 1e-9
    assert r.error_estimate <= 1e-9 and r.rtol < 1e-9 and r.error["basis"] == "looser"
    with pytest.raises(nanopush.SolverError) as e:
        # the printed law runs in double only: 1e-14 is beyond its floor (the thesis and coulomb
        # laws go on in long double and reach it)
        nanopush.run("fig3_17", law="printed", accuracy=1e-14)
    assert e.value.outcome == "accuracy_not_reached"
    assert e.value.partial.error_estimate > 1e-14
    with pytest.raises(nanopush.InputError, match=r"^accuracy = 1: must be in \[1e-14, 0.1\]"):
        nanopush.run("fig3_18", accuracy=1.0)


def test_outcomes_at_rest_and_no_static_friction():
    scene = nanopush.Scene.preset("fig3_18")
    scene.set("push.force", 1e-7)
    r = nanopush.run(scene, law="coulomb")
    assert r.outcome == "at_rest" and np.all(r.x == 0) and np.all(r.theta == 0)
    assert r.error_estimate == 0 and r.error["basis"] == "exact" and r.nfcn_total == r.nfcn
    with pytest.raises(nanopush.SolverError) as e:
        nanopush.run(scene, law="thesis")
    assert e.value.outcome == "no_static_friction" and "--law coulomb" in str(e.value)


def test_sweep_rows_carry_estimates_and_outcomes():
    res = nanopush.sweep("fig3_18", vary={"push.force": [1e-7, 5e-6]}, law="coulomb")
    assert list(res.status) == ["at_rest", "ok"] and res.failed == 0 and res.ok.all()
    assert math.isnan(res["error_estimate"][0]) or res["error_estimate"][0] >= 0
    assert 0 < res["error_estimate"][1] < 1e-6
    th = nanopush.sweep("fig3_18", vary={"push.force": [1e-7, 5e-6]}, law="thesis")
    assert list(th.status) == ["no_static_friction", "ok"] and th.failed == 1


def _tip_dynamic(max_steps):
    s = nanopush.Scene.preset("tip_push_nanorod")
    s.set({"tip.model": "dynamic", "tip.stiffness": 10.0, "tip.speed": 1.0, "tip.travel": 400e-9, "tip.mu": 0.3,
           "solver.max_steps": max_steps})
    return s


def _printed_blowup():
    # A point of fig3_18's mu x yn grid where the printed law's friction injects energy
    # (tests/test_accuracy.cpp, "The printed law's failures are classified").
    s = nanopush.Scene.preset("fig3_18")
    s.set({"surface.mu": 0.005, "push.yn": -21e-9})
    return s


@pytest.mark.parametrize("scene, kwargs, outcome, status, code", [
    # the outcomes that are their own status in the C API (nanopush.h, docs/errors.md), whatever
    # the integrator's status was (success for the C++ engine, too_many_steps for the F77's)
    ("fig3_25", dict(error_estimate=False), "no_static_friction", "no_static_friction", 13),
    ("fig3_25", dict(engine="f77", error_estimate=False), "no_static_friction", "no_static_friction", 13),
    (_printed_blowup, dict(law="printed", error_estimate=False), "law_blowup", "law_blowup", 14),
    ("fig3_17", dict(law="printed", accuracy=1e-14), "accuracy_not_reached", "accuracy_not_reached", 15),
    # the integrator's own stop: its status (2-5)
    (lambda: nanopush.Scene.preset("fig3_6a"), dict(), "solver_failure", "too_many_steps", 2),
    # the dynamic tip model's step budget spent: too many steps, as C says (it said None, C 6)
    (lambda: _tip_dynamic(2000), dict(error_estimate=False), "solver_failure", "too_many_steps", 2),
])
def test_solver_error_reports_the_c_apis_status(scene, kwargs, outcome, status, code):
    if callable(scene):
        scene = scene()
        if scene.name == "fig3_6a":
            scene.set("solver.max_steps", 5)
    with pytest.raises(nanopush.SolverError) as e:
        nanopush.run(scene, **kwargs)
    assert (e.value.outcome, e.value.status, e.value.status_code) == (outcome, status, code), str(e.value)


def test_a_failed_sweep_point_reports_the_c_apis_status():
    with pytest.raises(nanopush.SolverError) as e:
        nanopush.sweep("fig3_18", vary={"push.force": [1e-7]}, law="thesis", check=True, jobs=1)
    assert (e.value.outcome, e.value.status, e.value.status_code) == ("no_static_friction", "no_static_friction", 13)
    assert len(e.value.partial) == 1


def test_extended_precision_runs_rough_scenes_as_documented():
    # long and quad are not for smooth scenes only: a rough scene under the thesis or coulomb
    # law runs in them with the modern method, or auto, which picks it (docs/accuracy.md,
    # "References with more digits"); run's docstring says so, and names the printed law.
    for law, method in [("coulomb", "modern"), ("thesis", "auto")]:
        r = nanopush.run("fig3_18", law=law, method=method, precision="long", error_estimate=False)
        assert r.precision == "long" and r.engine == f"cxx-modern-{law}-long" and r.complete
    with pytest.raises(nanopush.InputError, match=r"^precision = long: long and quad need .* \(the printed law's"):
        nanopush.run("fig3_18", law="printed", method="modern", precision="long")
    doc = nanopush.run.__doc__
    assert "smooth scenes)" not in doc and "rough scene under\n               the thesis or coulomb law" in doc
    assert '``"printed"``' in doc


def test_compare_runs_both_engines_at_the_rtol_an_accuracy_needs():
    # as `nanopush compare fig3_17 --accuracy 1e-7` (cli.accuracy.compare): the C++
    # configuration's rtol for that error, both engines run there and agree
    c = nanopush.compare("fig3_17", accuracy=1e-7)
    assert c.agree
    assert c.accuracy["requested"] == 1e-7 and c.accuracy["reached"]
    assert c.accuracy["rtol_used"] <= 1e-7 and c.accuracy["runs"] >= 2
    assert c.cxx.rtol == c.f77.rtol == c.accuracy["rtol_used"]
    assert nanopush.compare("fig3_17").accuracy is None
    with pytest.raises(nanopush.InputError, match=r"^accuracy = 1: must be in \[1e-14, 0.1\]"):
        nanopush.compare("fig3_17", accuracy=1.0)
    with pytest.raises(nanopush.InputError, match="accuracy chooses the rtol"):
        nanopush.compare("fig3_17", accuracy=1e-7, rtol=1e-9)
