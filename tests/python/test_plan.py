"""nanopush.plan against `nanopush plan` (the same pushes, bit for bit), each push replayed by
its own scene, and bad input as InputError naming the argument (docs/planning.md)."""

import math
import tomllib

import numpy as np
import pytest

import nanopush
from conftest import read_csv

SCENE = "tip_push_nanorod"
GOAL = (60e-9, 40e-9, 0.3)
TOL = (2e-9, 0.02)


def test_plan_equals_the_command_line(cli, tmp_path):
    r = nanopush.plan(SCENE, GOAL, tolerance=TOL)
    assert r.status == "found" and r.found and r.verified, r.message
    assert r.goal == GOAL and len(r.pushes) >= 1
    assert r.final_distance <= TOL[0] and r.final_angle <= TOL[1]
    cli("plan", SCENE, "--goal", ",".join(map(repr, GOAL)), "--tolerance", ",".join(map(repr, TOL)),
        "--out", tmp_path / "p", "--quiet")
    header, rows = read_csv(tmp_path / "p" / "plan.csv")
    assert header[1:] == ["start_x", "start_y", "direction", "speed", "travel", "x_end", "y_end", "theta_end"]
    table = np.array([[float(c) for c in row[1:]] for row in rows])
    assert r.table.shape == table.shape
    assert np.array_equal(r.table, table)  # bit for bit: one computation
    assert r.pushes[0]["start_x"] == r.table[0, 0] and r.pushes[-1]["end"] == tuple(r.table[-1, 5:])
    assert r.pushes[0]["face"] in ("-x'", "+x'", "-y'", "+y'")
    assert "found (verified)" in repr(r)


def test_each_push_replays_as_its_own_scene():
    r = nanopush.plan(SCENE, GOAL, tolerance=TOL)
    scene = nanopush.Scene.preset(SCENE)
    for k, p in enumerate(r.pushes):
        s = r.push_scene(scene, k)
        keys = tomllib.loads(s.to_toml())
        assert keys["push"]["mode"] == "tip"
        assert all(keys["tip"][k] == p[k] for k in ("start_x", "start_y", "direction", "speed", "travel"))
        run = nanopush.run(s)
        end = (run.x[-1], run.y[-1], run.theta[-1])
        assert all(math.isclose(a, b, rel_tol=0, abs_tol=1e-15) for a, b in zip(end[:2], p["end"][:2])), (k, end, p["end"])
        assert math.isclose(end[2], p["end"][2], rel_tol=0, abs_tol=1e-12)


def test_a_goal_out_of_reach_is_not_found_with_the_best_plan():
    r = nanopush.plan(SCENE, (400e-9, -300e-9, 1.2), tolerance=TOL, max_pushes=1)
    assert r.status == "not_found" and not r.found
    assert len(r.pushes) <= 1 and r.final_distance > TOL[0]


def test_bad_input_names_the_argument():
    with pytest.raises(nanopush.InputError, match="goal"):
        nanopush.plan(SCENE, (1e-9, 2e-9))
    with pytest.raises(nanopush.InputError, match="max_pushes"):
        nanopush.plan(SCENE, GOAL, max_pushes=0)
    with pytest.raises(nanopush.InputError, match="objective"):
        nanopush.plan(SCENE, GOAL, objective="fastest")
    with pytest.raises(nanopush.InputError, match="tolerance"):
        nanopush.plan(SCENE, GOAL, tolerance=1e-9)
    with pytest.raises(nanopush.InputError, match="goal"):
        nanopush.plan(SCENE, ("a", 0, 0))
    # what the library names by `nanopush plan`'s flags is named as plan's arguments
    for kwargs, field, says in [
            (dict(goal=(float("nan"), 0.0, 0.0)), "goal", "goal = nan,0,0: must be three finite numbers"),
            (dict(tolerance=(-1.0, 0.01)), "tolerance", "tolerance = -1 m: below what the model resolves"),
            (dict(objective="fastest"), "objective", "objective = fastest: must be one of: pushes, travel"),
            (dict(robust_start=(float("inf"), 0.0, 0.0)), "robust_start", "robust_start = inf: a robust plan's")]:
        args = dict(goal=GOAL, tolerance=TOL)
        args.update(kwargs)
        with pytest.raises(nanopush.InputError) as e:
            nanopush.plan(SCENE, args.pop("goal"), **args)
        assert str(e.value).startswith(says) and e.value.field == field, str(e.value)
    r = nanopush.plan(SCENE, GOAL, tolerance=TOL)
    with pytest.raises(nanopush.InputError, match="k"):
        r.push_scene(nanopush.Scene.preset(SCENE), len(r.pushes))


def test_check_plan_equals_the_command_line(cli, tmp_path):
    r = nanopush.plan(SCENE, GOAL, tolerance=TOL)
    c = nanopush.check_plan(r, SCENE, 6, noise=(1e-9, 1e-9, 0.01), seed=5, jobs=2)
    cli("plan", SCENE, "--goal", ",".join(map(repr, GOAL)), "--tolerance", ",".join(map(repr, TOL)),
        "--check", "6", "--noise", "x=1e-9,theta=0.01", "--seed", "5", "--out", tmp_path / "p", "--quiet")
    header, rows = read_csv(tmp_path / "p" / "check.csv")
    assert c.columns == header
    for name in ("start_x", "start_theta", "final_distance", "final_angle"):
        col = header.index(name)
        assert np.array_equal(c[name], np.array([float(row[col]) for row in rows]))  # bit for bit
    assert c.trials == 6 and c.successes == int(np.sum(c["success"]))
    assert c.interval[0] <= c.probability <= c.interval[1]
    with pytest.raises(nanopush.InputError, match="trials"):
        nanopush.check_plan(r, SCENE, 0)
    # the library's --mu-range named as check_plan's argument, mu_range
    with pytest.raises(nanopush.InputError, match=r"^mu_range = 0\.5:0\.1[0-9]*: must be LO:HI") as e:
        nanopush.check_plan(r, SCENE, 2, mu_range=(0.5, 0.1))
    assert e.value.field == "mu_range"
    with pytest.raises(nanopush.InputError, match=r"^noise = -1[0-9.]*e-09: standard deviations must be >= 0") as e:
        nanopush.check_plan(r, SCENE, 2, noise=(-1e-9, 0.0, 0.0))
    assert e.value.field == "noise"


def test_robust_plan_equals_the_command_line_and_reaches_every_world(cli, tmp_path):
    noise = (0.3e-9, 0.3e-9, 0.002)
    r = nanopush.plan(SCENE, GOAL, tolerance=TOL, robust_tip_mu=(0.0, 0.3),
                      robust_start=tuple(2 * s for s in noise))
    assert r.found and r.verified, r.message
    assert len(r.worlds) == 8  # the model's (tip.mu 0), tip.mu 0.3, the start shifted +-2 sigma in x, y, theta
    assert r.worlds[1]["tip_mu"] == 0.3 and all(w["reached"] for w in r.worlds)
    assert all(w["final_distance"] <= TOL[0] and w["final_angle"] <= TOL[1] for w in r.worlds)
    cli("plan", SCENE, "--goal", ",".join(map(repr, GOAL)), "--tolerance", ",".join(map(repr, TOL)), "--robust",
        "--tip-mu-range", "0:0.3", "--noise", "x=0.3e-9,theta=0.002", "--check", "8",
        "--seed", "2", "--out", tmp_path / "p", "--quiet")
    _, rows = read_csv(tmp_path / "p" / "plan.csv")
    assert np.array_equal(r.table, np.array([[float(c) for c in row[1:]] for row in rows]))  # bit for bit
    c = nanopush.check_plan(r, SCENE, 8, noise=noise, tip_mu_range=(0.0, 0.3), seed=2, jobs=1)
    header, rows = read_csv(tmp_path / "p" / "check.csv")
    col = header.index("tip_mu")
    assert np.array_equal(c["tip_mu"], np.array([float(row[col]) for row in rows]))
    assert np.all((c["tip_mu"] >= 0) & (c["tip_mu"] <= 0.3))
    with pytest.raises(nanopush.InputError, match="robust_tip_mu"):
        nanopush.plan(SCENE, GOAL, robust_tip_mu=0.3)
    # the library's --tip-mu-range named as plan's argument, robust_tip_mu
    with pytest.raises(nanopush.InputError, match=r"^robust_tip_mu = 0\.3:0\.1: must be LO:HI") as e:
        nanopush.plan(SCENE, GOAL, robust_tip_mu=(0.3, 0.1))
    assert e.value.field == "robust_tip_mu"


def test_assemble_equals_the_command_line(cli, tmp_path):
    objects = np.array([[0, 0, 0], [100e-9, 0, 0]])
    slots = np.array([[110e-9, 20e-9, 0.1], [10e-9, 20e-9, 0.1]])
    a = nanopush.assemble(SCENE, objects, slots, tolerance=TOL)
    assert a.assembled and a.slot_of == [1, 0] and len(a.plans) == 2, a.message
    for k, p in enumerate(a.plans):
        assert p.found and p.verified
    for name, arr in (("o.csv", objects), ("p.csv", slots)):
        (tmp_path / name).write_text("x,y,theta\n" + "".join(",".join(repr(float(v)) for v in row) + "\n" for row in arr))
    cli("assemble", tmp_path / "o.csv", tmp_path / "p.csv", "--tolerance", ",".join(map(repr, TOL)),
        "--out", tmp_path / "a", "--quiet")
    header, rows = read_csv(tmp_path / "a" / "assembly.csv")
    table = np.array([[float(c) for c in row[3:]] for row in rows])
    mine = np.vstack([p.table for p in a.plans])
    assert np.array_equal(mine, table)  # bit for bit: one computation
    ends = {int(r[0]) - 1: [float(c) for c in r[8:11]] for r in rows}
    for bar, end in ends.items():
        assert np.array_equal(a.final_poses[bar], np.array(end))
    with pytest.raises(nanopush.InputError, match="objects"):
        nanopush.assemble(SCENE, [[0, 0]], slots)
    # the library's PATTERN and --gap named as assemble's arguments, slots and gap
    with pytest.raises(nanopush.InputError, match=r"^slots = 1 slots: must have one slot per bar \(2\)$") as e:
        nanopush.assemble(SCENE, objects, slots[:1])
    assert e.value.field == "slots"
    with pytest.raises(nanopush.InputError, match=r"^gap = -1: must be >= 0 \(m\)$") as e:
        nanopush.assemble(SCENE, objects, slots, gap=-1.0)
    assert e.value.field == "gap"
