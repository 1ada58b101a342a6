"""Python like every other front end (issue 34, item 5): every argument converted with checks.
NumPy scalars and 0-d arrays are numbers (Scene.set('push.force', np.array(1e-6)) was a
segfault); any other type raises nanopush.InputError naming the argument, never RuntimeError
"Unable to cast"."""

import subprocess
import sys

import numpy as np
import pytest

import nanopush


def fresh():
    return nanopush.Scene.preset("fig3_6a")


def test_numpy_array_in_scene_set_does_not_crash():
    # In a child interpreter first: a crash there fails this test instead of killing pytest.
    code = ("import numpy as np, nanopush\n"
            "s = nanopush.Scene.preset('fig3_6a')\n"
            "s.set('push.force', np.array(1e-6))\n"
            "print(s.info()['push']['force'])\n")
    p = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, f"exit {p.returncode}: {p.stderr[-2000:]}"
    assert float(p.stdout.strip()) == 1e-6


@pytest.mark.parametrize("value", [np.array(1e-6), np.float64(1e-6), np.array([1e-6])[0],
                                   np.array(1e-6, dtype=np.float64)[()], np.float32(1e-6), np.array(1e-6, np.float32)])
def test_numpy_numbers_are_numbers_in_scene_set(value):
    a, b = fresh(), fresh()
    a.set("push.force", value)
    b.set("push.force", float(value))  # the same number as a Python float (float32: its exact value)
    assert a.info()["push"]["force"] == b.info()["push"]["force"] == float(value)
    assert abs(float(value) - 1e-6) < 1e-13


def test_numpy_integers_and_flags():
    a, b = fresh(), fresh()
    a.set({"solver.samples": np.int64(11), "solver.error_estimate": np.bool_(False)})
    b.set({"solver.samples": 11, "solver.error_estimate": False})
    a.set("solver.t_end", np.array(1e-9))
    b.set("solver.t_end", 1e-9)
    assert a.info()["solver"] == b.info()["solver"]
    c = fresh()
    c.set("solver.samples", np.array(11))  # a 0-d integer array
    assert c.info()["solver"]["samples"] == 11
    r_np, r_py = nanopush.run(a), nanopush.run(b)
    assert np.array_equal(r_np.array, r_py.array)


@pytest.mark.parametrize("value, says", [
    (np.array([1e-6, 2e-6]), r"push\.force = an array of shape \(2,\): must be one value"),
    (np.zeros((1, 1)), r"push\.force = an array of shape \(1, 1\): must be one value"),
    ([1e-6], r"push\.force = \[1e-06\]: must be a number, an integer, a flag or text"),
    (object(), r"push\.force = <object object at .*>: must be a number"),
    (None, r"push\.force = None: must be a number"),
])
def test_wrong_types_in_scene_set_are_input_errors(value, says):
    s = fresh()
    before = s.info()
    with pytest.raises(nanopush.InputError, match=says) as e:
        s.set("push.force", value)
    assert e.value.field == "push.force"
    assert s.info() == before  # left unchanged


def test_huge_integer_is_an_input_error():
    with pytest.raises(nanopush.InputError, match=r"solver\.samples = 1000000000000000000000000000000: an integer outside"):
        fresh().set("solver.samples", 10**30)


def test_run_arguments():
    s = fresh()
    s.set({"solver.samples": 11, "solver.t_end": 1e-9})
    ref = nanopush.run(s, rtol=1e-8)
    for rtol in (np.float64(1e-8), np.array(1e-8)):
        r = nanopush.run(s, rtol=rtol)
        assert np.array_equal(r.array, ref.array) and r.rtol == ref.rtol
    with pytest.raises(nanopush.InputError, match=r"^rtol = 'abc': must be a real number \(not text\)") as e:
        nanopush.run(s, rtol="abc")
    assert e.value.field == "rtol"
    with pytest.raises(nanopush.InputError, match=r"^atol = \[1e-09\]: must be a real number"):
        nanopush.run(s, atol=[1e-9])
    with pytest.raises(nanopush.InputError, match=r"^rtol = an array of shape \(2,\): must be one value"):
        nanopush.run(s, rtol=np.array([1e-8, 1e-9]))
    with pytest.raises(nanopush.InputError, match=r"^error_estimate = 'yes': must be True or False"):
        nanopush.run(s, error_estimate="yes")
    with pytest.raises(nanopush.InputError, match=r"^accuracy = True: must be a real number \(not a flag\)"):
        nanopush.run(s, accuracy=True)
    with pytest.raises(nanopush.InputError, match=r"^scene = 42: must be a nanopush\.Scene") as e:
        nanopush.run(42)
    assert e.value.field == "scene"
    with pytest.raises(nanopush.InputError, match=r"^tolerance = 'x': must be a real number"):
        nanopush.compare(s, tolerance="x")


def test_sweep_and_estimate_mu_arguments():
    a = nanopush.sweep("friction", vary={"R": np.array([1e-8, 2e-8])}, set={"a": np.float64(27.5e-9), "b": 50e-9},
                       jobs=np.int64(1))
    b = nanopush.sweep("friction", vary={"R": [1e-8, 2e-8]}, set={"a": 27.5e-9, "b": 50e-9}, jobs=1)
    assert a.to_dict().keys() == b.to_dict().keys()
    for k in b.to_dict():
        assert np.array_equal(a[k], b[k]), k
    with pytest.raises(nanopush.InputError, match=r"^jobs = 'two': must be a whole number >= 0"):
        nanopush.sweep("friction", vary={"R": [1e-8]}, jobs="two")
    with pytest.raises(nanopush.InputError, match=r"^R = an array of shape \(1,\): must be one value"):
        nanopush.sweep("friction", vary={"R": [np.array([1e-8])]})
    e1 = nanopush.estimate_mu(1e-6, 3e-8, yn=np.array(1e-7))
    e2 = nanopush.estimate_mu(1e-6, 3e-8, yn=1e-7)
    assert e1.mu == e2.mu
    with pytest.raises(nanopush.InputError, match=r"^yn = '1e-7': must be a real number \(not text\)"):
        nanopush.estimate_mu(1e-6, yn="1e-7")
    with pytest.raises(nanopush.InputError, match=r"^rod = 'nanorod': must be a nanopush\.Rod"):
        nanopush.estimate_mu(1e-6, yn=1e-7, rod="nanorod")


def test_fit_arguments(tmp_path):
    s = fresh()
    data = tmp_path / "d.csv"
    data.write_text("t,x\n0,0\n")
    with pytest.raises(nanopush.InputError, match=r"^free = 3: must be a scene key or a list of scene keys"):
        nanopush.fit(s, data, 3)
    with pytest.raises(nanopush.InputError, match=r"^sigma = 0\.1: must be a dict"):
        nanopush.fit(s, data, "surface.mu", sigma=0.1)
    with pytest.raises(nanopush.InputError, match=r"^sigma\[x\] = 'a': must be a real number"):
        nanopush.fit(s, data, "surface.mu", sigma={"x": "a"})


def test_synthesize_refuses_a_nan_sigma():
    s = fresh()
    s.set({"solver.samples": 5, "solver.t_end": 1e-9})
    with pytest.raises(nanopush.InputError, match=r"^sigma_x = nan: must be a finite number"):
        nanopush.synthesize(s, (float("nan"), 0.0, 0.0), 3)
    with pytest.raises(nanopush.InputError, match=r"^sigma_theta = inf: must be a finite number"):
        nanopush.synthesize(s, (1e-9, 0.0, float("inf")), 3)
    text = nanopush.synthesize(s, (np.float64(1e-9), 0.0, 0.0), 3)  # <= 0: not observed
    assert text.splitlines()[0].split(",")[:2] == ["t", "x"] and "theta" not in text.splitlines()[0]


# ---- pybind11's own conversions (issue: wrong types raised TypeError / AttributeError) ----
# One mechanism covers every compiled function, method, constructor and attribute setter
# (nanopush/_signatures.py): pybind11's "incompatible function arguments" becomes an
# InputError naming the first argument whose value does not fit its annotation. Integer
# arguments with a range are converted by the binding itself (arg_integer).

def _rod_set_length(value):
    rod = nanopush.icor.Rod()
    rod.length = value


@pytest.mark.parametrize("call, field, says", [
    (lambda: nanopush.run("fig3_6a", engine=3), "engine", r"^engine = 3: must be text$"),
    (lambda: fresh().set(5, 0.1), "key", r"^key = 5: must be text$"),
    (lambda: fresh().unset(None), "key", r"^key = None: must be text$"),
    (lambda: nanopush.Scene.from_toml(None), "text", r"^text = None: must be text$"),
    (lambda: nanopush.Scene.preset(None), "name", r"^name = None: must be a preset name"),
    (lambda: nanopush.Scene.from_file(3), "path", r"^path = 3: must be a path \(text or os\.PathLike\)$"),
    (lambda: nanopush.synthesize(fresh(), (1e-9, 0.0, 0.0), -1), "seed",
     r"^seed = -1: must be a whole number in \[0, 4611686018427387904\]$"),
    (lambda: nanopush.synthesize(fresh(), (1e-9, 0.0, 0.0), 2**70), "seed",
     r"^seed = 1180591620717411303424: must be a whole number in \[0, 4611686018427387904\]$"),
    (lambda: nanopush.synthesize(fresh(), (1e-9, 0.0), 1), "sigma", r"^sigma = \(1e-09, 0\.0\): must be 3 values"),
    (lambda: nanopush.synthesize("fig3_6a", (1e-9, 0.0, 0.0), 1), "scene",
     r"^scene = 'fig3_6a': must be a nanopush\.Scene$"),
    (lambda: nanopush.fit(fresh(), "unread.csv", "push.force", max_evaluations=2.5), "max_evaluations",
     r"^max_evaluations = 2\.5: must be a whole number in \[1, 100000\]$"),
    (lambda: nanopush.fit(fresh(), "unread.csv", "push.force", max_evaluations=10**30), "max_evaluations",
     r"^max_evaluations = 1000000000000000000000000000000: must be a whole number in \[1, 100000\]$"),
    (lambda: nanopush.fit(fresh(), "unread.csv", "push.force", rtol="tight"), "rtol",
     r"^rtol = 'tight': must be a real number \(not text\)$"),
    (lambda: nanopush.icor.cubic_roots(np.array([1e-7, 2e-7]), 590e-9, 1e-14), "yn",
     r"^yn = an array of shape \(2,\): must be one value \(a number, a NumPy scalar or a 0-d array\)$"),
    (lambda: nanopush.icor.cubic_roots(1e-7, 590e-9, 1e-14, solver=2), "solver", r"^solver = 2: must be text$"),
    (lambda: nanopush.icor.dynamic(1e-7, 1e-6, rod=5), "rod", r"^rod = 5: must be a nanopush\.icor\.Rod$"),
    (lambda: nanopush.icor.dynamic(1e-7, 1e-6, times=[1e-10, "x"]), "times",
     r"^times = \[1e-10, 'x'\]: element 1 = 'x': must be a real number \(not text\)$"),
    (lambda: nanopush.icor.error_analysis(590e-9, 1e-14, n=1.5), "n", r"^n = 1\.5: must be a whole number in \[2, "),
    (lambda: nanopush.icor.Rod(length="x"), "length", r"^length = 'x': must be a real number \(not text\)$"),
    (lambda: _rod_set_length(None), "length", r"^length = None: must be a real number$"),
    (lambda: nanopush.sweep("fig3_6a", vary=[("push.force", [1e-6])]), "vary",
     r"^vary = \[\('push\.force', \[1e-06\]\)\]: must be a dict \{key: values\}$"),
    (lambda: nanopush.sweep("fig3_6a", set=3), "set", r"^set = 3: must be a dict \{key: value\}$"),
    (lambda: nanopush.sweep("fig3_6a", points=[1]), "points", r"^points = \[1\]: must be a dict"),
    (lambda: nanopush.friction_wrench(27.5e-9, 50e-9, np.array([1e-7 + 1j]), 0.3), "R",
     r"^R = a complex array of shape \(1,\): must be real numbers \(a complex value is refused"),
    (lambda: nanopush.friction_wrench(27.5e-9, 50e-9, 1e-7, np.complex128(0.3)), "alpha",
     r"^alpha = .*0\.3.*: must be real numbers \(a complex value is refused"),
    (lambda: nanopush.icor.falvo(np.array([1e-7], dtype=np.complex64), 590e-9), "yn",
     r"^yn = a complex array of shape \(1,\)"),
    (lambda: nanopush.assemble("tip_push_nanorod", np.zeros((1, 3), complex), np.zeros((1, 3))), "objects",
     r"^objects = a complex array of shape \(1, 3\)"),
])
def test_wrong_types_are_input_errors_naming_the_argument(call, field, says):
    with pytest.raises(nanopush.InputError, match=says) as e:
        call()
    assert e.value.field == field and e.value.index is None
    assert isinstance(e.value, ValueError) and not isinstance(e.value, TypeError)


def test_a_complex_array_is_never_cut_to_its_real_part():
    # The real part alone passed before, as if the imaginary part were not there.
    with pytest.raises(nanopush.InputError):
        nanopush.friction_wrench(27.5e-9, 50e-9, np.array([1e-7 + 0j, 2e-7 + 0j]), 0.3)
    real = nanopush.friction_wrench(27.5e-9, 50e-9, np.array([1e-7, 2e-7]), 0.3)
    assert real.fx.shape == (2,)  # the same values as real numbers are fine


def test_calls_that_match_no_signature_stay_type_errors():
    # Argument names and counts are the caller's program, as for any Python function: TypeError
    # with Python's words, not pybind11's list of signatures.
    with pytest.raises(TypeError, match=r"^Rod\(\): got an unexpected keyword argument 'lenght'$"):
        nanopush.icor.Rod(lenght=1e-7)
    with pytest.raises(TypeError, match=r"^falvo\(\): got an unexpected keyword argument 'q'$"):
        nanopush.icor.falvo(1e-7, 590e-9, q=1)
    with pytest.raises(TypeError, match="too many positional arguments"):
        nanopush.friction_wrench(1, 2, 3, 4, 5, 6, 7, 8)


def test_right_types_still_convert():
    rod = nanopush.icor.Rod(length=np.float64(5e-7))
    rod.length = np.array(4e-7)  # a 0-d array is one value
    assert rod.length == 4e-7
    k2 = nanopush.icor.nanorod().k2
    a, b = nanopush.icor.cubic_roots(np.float64(1e-7), 590e-9, k2), nanopush.icor.cubic_roots(1e-7, 590e-9, k2)
    assert list(a.real_roots) == list(b.real_roots) and a.negative == b.negative
    s = fresh()
    s.set({"solver.samples": 5, "solver.t_end": 1e-9})
    assert nanopush.synthesize(s, (1e-9, 0, 0), np.int64(3)) == nanopush.synthesize(s, (1e-9, 0, 0), 3)


def test_the_command_lines_names_are_the_arguments_names(tmp_path):
    # The library names some inputs by `nanopush fit`'s flags (--free, --law, --sigma, DATA);
    # nanopush.fit and synthesize report their own argument names (message and .field).
    s = nanopush.Scene.preset("fig3_18")
    data = tmp_path / "d.csv"
    data.write_text("t,x\n0,0\n4e-12,1e-10\n")
    for kwargs, field, says in [
            (dict(free=["surface.mu", "surface.mu"]), "free", "free = surface.mu: named twice"),
            (dict(free="surface.muu"), "free", "free = surface.muu: not a scene key"),
            (dict(law="printed"), "law", "law = printed: must be thesis or coulomb"),
            (dict(sigma={"q": 1e-9}), "sigma", "sigma = q=1e-09: the column must be x, y or theta"),
            (dict(data=tmp_path / "absent.csv"), "data", f"data = {tmp_path / 'absent.csv'}: no such file")]:
        args = dict(data=data, free="surface.mu", sigma={"x": 1e-9})
        args.update(kwargs)
        with pytest.raises(nanopush.InputError) as e:
            nanopush.fit(s, args.pop("data"), args.pop("free"), **args)
        assert str(e.value).startswith(says) and e.value.field == field, str(e.value)
    with pytest.raises(nanopush.InputError, match=r"^law = printed: must be thesis or coulomb") as e:
        nanopush.synthesize(s, (1e-9, 0.0, 0.0), 1, law="printed")
    assert e.value.field == "law"
