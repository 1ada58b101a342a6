"""nanopush.Scene, presets and scene_keys against the command line; reference counts and
memory over 10^4 calls (no leaks), the error paths included."""

import copy
import gc
import sys

import numpy as np
import pytest

import nanopush


def test_presets_match_cli(cli):
    lines = cli("presets").stdout.splitlines()[2:]
    listed = {}
    for ln in lines:
        name, short = ln.split()[:2]
        listed[short if short != "-" else name] = ln.split(None, 2)[2] if len(ln.split(None, 2)) > 2 else ""
    got = nanopush.presets()
    assert set(got) == set(listed)
    for name, desc in got.items():
        assert listed[name] == desc, name
        assert isinstance(nanopush.Scene.preset(name), nanopush.Scene)
    assert "fig3_6a" in got


def test_scene_from_file_toml_and_set(source_dir):
    path = f"{source_dir}/drivers/scenes/thesis/fig3_6a.toml"
    a = nanopush.Scene.from_file(path)
    b = nanopush.Scene.preset("thesis/fig3_6a")
    with open(path) as f:
        c = nanopush.Scene.from_toml(f.read(), "fig3_6a")
    assert a.to_toml() == b.to_toml() == c.to_toml()
    info = a.info()
    assert info["name"] == "fig3_6a" and info["model"] == "smooth"
    assert info["a"] == info["width"] / 2 and info["b"] == info["length"] / 2
    assert info["solver"]["samples"] == len(a.output_times())
    d = a.copy()
    d.set("push.force", 2 * info["push"]["force"])
    assert d.info()["push"]["force"] == 2 * info["push"]["force"]
    assert a.info()["push"]["force"] == info["push"]["force"]  # copies are independent
    e = copy.deepcopy(a)
    e.set({"solver.samples": 11, "solver.t_end": 1e-9})
    assert len(e.output_times()) == 11 and e.output_times()[-1] == 1e-9
    e.set("solver.method", "modern")
    assert e.info()["solver"]["method"] == "modern"
    e.unset("solver.method")
    assert e.info()["solver"]["method"] == "auto"  # the default of a scene that does not state it
    r = nanopush.Scene.preset("fig3_18")
    r.set("surface.law", "coulomb")
    r.set("surface.mu", "0.15")  # text is read as the key's type, as --set does
    assert r.info()["surface"]["mu"] == 0.15 and r.rough
    keys = [k["key"] for k in nanopush.scene_keys()]
    assert "surface.mu" in keys and keys == sorted(set(keys), key=keys.index)


def test_scene_errors_name_the_key(cli, tmp_path):
    s = nanopush.Scene.preset("fig3_6a")
    before = s.to_toml()
    for key, value, cli_value in [("surface.mu", 0.1, "0.1"), ("object.lenght", 1.0, "1"),
                                  ("solver.samples", 1, "1"), ("solver.engine", "gpu", "gpu")]:
        msg = cli.error("run", "fig3_6a", "--set", f"{key}={cli_value}", "--out", tmp_path / "x.csv")
        with pytest.raises(nanopush.InputError) as e:
            s.set(key, value)
        assert str(e.value) == msg, key
    assert s.to_toml() == before  # unchanged after every failed set
    with pytest.raises(nanopush.InputError, match=r"^object.length = \(missing\): required number"):
        nanopush.Scene.from_toml("[object]\nmass = 1e-18\n")
    with pytest.raises(nanopush.InputError):
        nanopush.Scene.from_file(tmp_path / "missing.toml")
    with pytest.raises(nanopush.InputError, match="no preset"):
        nanopush.Scene.preset("fig9_99")


def _rss_kib():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * 4


def _leak_check(fn, n=10_000, args=()):
    """Reference counts of the arguments and the process's resident memory stay flat over n calls."""
    for _ in range(200):
        fn(*args)
    gc.collect()
    refs = [sys.getrefcount(a) for a in args]
    objects = len(gc.get_objects())
    rss = _rss_kib()
    for _ in range(n):
        fn(*args)
    gc.collect()
    assert [sys.getrefcount(a) for a in args] == refs
    assert len(gc.get_objects()) - objects < 100
    grown = _rss_kib() - rss
    assert grown < 2048, f"resident memory grew by {grown} KiB over {n} calls"


def test_no_leaks_over_ten_thousand_calls():
    R = np.linspace(0, 1e-6, 64).reshape(8, 8)
    alpha = np.linspace(0, 6, 8)
    _leak_check(lambda r, a: nanopush.friction_wrench(27.5e-9, 50e-9, r, a), args=(R, alpha))
    _leak_check(lambda y: nanopush.icor.cubic_branches(y, 590e-9, 2.9e-14), args=(R * 0.29,))  # yn <= L/2
    scene = nanopush.Scene.preset("fig3_6a")
    scene.set({"solver.samples": 5, "solver.t_end": 1e-11})
    _leak_check(lambda s: nanopush.run(s).theta, args=(scene,))

    def bad(r):
        try:
            nanopush.friction_wrench(27.5e-9, 50e-9, r, 0.0)
        except nanopush.InputError:
            return
        raise AssertionError("no error")
    _leak_check(bad, args=(-R,))

    def bad_set(s):
        try:
            s.set("object.mass", -1.0)
        except ValueError:
            return
        raise AssertionError("no error")
    _leak_check(bad_set, args=(scene,))
    failing = scene.copy()
    failing.set("solver.max_steps", 1)

    def solver_failure(s):
        try:
            nanopush.run(s)
        except nanopush.SolverError as e:
            return e.partial
        raise AssertionError("no error")
    _leak_check(solver_failure, args=(failing,))
