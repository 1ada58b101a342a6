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
