"""nanopush.friction_wrench / friction_from_velocity: the numbers of `nanopush friction` bit
for bit, NumPy broadcasting of every argument, the library's messages, the GIL released."""

import math
import threading

import numpy as np
import pytest

import nanopush
from conftest import assert_runs_without_the_gil, column, read_csv
from test_run import same

A, B = 27.5e-9, 50e-9
L = max(A, B)


def icors(n=400, seed=7):
    """iCORs over every evaluation form: R from 1e-3 L to 1e12 L (log), R = 0, any alpha."""
    rng = np.random.default_rng(seed)
    R = L * 10.0 ** rng.uniform(-3, 12, n)
    R[:3] = [0.0, 3 * L, 1e9 * L]  # the centre, the form switches
    alpha = rng.uniform(-4, 4, n)
    return R, alpha


@pytest.mark.parametrize("engine, a, b, sense", [
    ("cxx", A, B, 1), ("cxx", A, B, -1), ("cxx", 1e-9, 3e-7, 1), ("f77", A, B, 1), ("f77", A, B, -1)])
def test_bit_for_bit_with_cli(cli, engine, a, b, sense):
    R, alpha = icors()
    rows = "R,alpha\n" + "".join(f"{r!r},{t!r}\n" for r, t in zip(R, alpha))
    p = cli("friction", "--a", repr(a), "--b", repr(b), "--sense", sense, "--engine", engine, input=rows)
    header, cells = read_csv(p.stdout)
    assert same(column(header, cells, "R"), R) and same(column(header, cells, "alpha"), alpha)
    w = nanopush.friction_wrench(a, b, R, alpha, sense=sense, engine=engine)
    assert isinstance(w, nanopush.Wrench)
    for name in ("fx", "fy", "mf"):
        assert same(getattr(w, name), column(header, cells, name)), name


def test_mu_n_scales():
    R, alpha = icors(50)
    w1 = nanopush.friction_wrench(A, B, R, alpha)
    w2 = nanopush.friction_wrench(A, B, R, alpha, mu_n=0.25)
    for x, y in zip(w1, w2):  # muN enters as a factor: exact for a power of two
        assert same(0.25 * x, y)


def test_broadcasting_shapes():
    R, alpha = icors(24)
    ref = nanopush.friction_wrench(A, B, R, alpha)
    # Any shapes that broadcast, against the element-by-element scalar calls.
    Rg = R[:6].reshape(6, 1)
    al = alpha[:4]
    w = nanopush.friction_wrench(A, B, Rg, al)
    assert all(c.shape == (6, 4) for c in w)
    for i in range(6):
        for j in range(4):
            s = nanopush.friction_wrench(A, B, float(Rg[i, 0]), float(al[j]))
            assert all(isinstance(c, float) for c in s)
            assert (w.fx[i, j], w.fy[i, j], w.mf[i, j]) == tuple(s)
    # a and b broadcast too; sense as an array of +-1.
    a = np.array([A, 2 * A])[:, None, None]
    sense = np.array([1, -1])[None, :, None]
    w = nanopush.friction_wrench(a, B, R[None, None, :5], alpha[:5], sense=sense)
    assert w.fx.shape == (2, 2, 5)
    assert same(w.mf[0, 1], -nanopush.friction_wrench(A, B, R[:5], alpha[:5]).mf)
    # 3-d, non-contiguous, reversed, integer and list input give the same numbers.
    R3 = R.reshape(2, 3, 4)
    assert same(nanopush.friction_wrench(A, B, R3, alpha.reshape(2, 3, 4)).fy, ref.fy.reshape(2, 3, 4))
    assert same(nanopush.friction_wrench(A, B, R[::2], alpha[::2]).mf, ref.mf[::2])
    assert same(nanopush.friction_wrench(A, B, R[::-1], alpha[::-1]).fx, ref.fx[::-1])
    Rt = np.asfortranarray(R3.transpose(2, 0, 1))
    assert same(nanopush.friction_wrench(A, B, Rt, alpha.reshape(2, 3, 4).transpose(2, 0, 1)).fx,
                ref.fx.reshape(2, 3, 4).transpose(2, 0, 1))
    assert same(nanopush.friction_wrench(A, B, [1e-9, 2e-9], 0).fx, nanopush.friction_wrench(A, B, np.array([1e-9, 2e-9]), 0.0).fx)
    assert same(nanopush.friction_wrench(A, B, np.arange(3, dtype=np.int32), 1).fy,
                nanopush.friction_wrench(A, B, np.arange(3.0), 1.0).fy)
    # 0-d arrays give floats; empty arrays give empty arrays of the broadcast shape.
    assert isinstance(nanopush.friction_wrench(A, B, np.float64(1e-9), np.array(0.5)).fx, float)
    assert nanopush.friction_wrench(A, B, np.zeros((0, 3)), 0.1).fx.shape == (0, 3)
    with pytest.raises(ValueError, match="broadcast"):
        nanopush.friction_wrench(A, B, np.zeros(3), np.zeros(4))


def test_errors_carry_the_library_message(cli):
    msg = cli.error("friction", "--a", "-1", input="")
    with pytest.raises(nanopush.InputError) as e:
        nanopush.friction_wrench(-1, B, 1e-9, 0.0)
    assert str(e.value) == msg and e.value.field == "a" and e.value.index is None  # checked once, not per element
    R = np.full((2, 3), 1e-9)
    R[1, 2] = -1.0
    with pytest.raises(ValueError) as e:
        nanopush.friction_wrench(A, B, R, 0.0)
    assert str(e.value) == "R = -1: must be >= 0 (m, distance from the iCOR to the centre of mass)"
    assert e.value.index == (1, 2) and e.value.field == "R"
    with pytest.raises(nanopush.InputError, match=r"^sense = 0\.5: must be \+1"):
        nanopush.friction_wrench(A, B, 1e-9, 0.0, sense=0.5)
    with pytest.raises(nanopush.InputError, match=r"^alpha = nan: must be a finite number"):
        nanopush.friction_wrench(A, B, 1e-9, math.nan)
    with pytest.raises(nanopush.InputError, match=r"^muN = -1: must be >= 0"):
        nanopush.friction_wrench(A, B, 1e-9, 0.0, mu_n=-1)
    with pytest.raises(nanopush.InputError, match=r"^b/a = "):
        nanopush.friction_wrench(1.0, 1e-13, 1e-9, 0.0)
    with pytest.raises(nanopush.InputError, match="must be a real number"):
        nanopush.friction_wrench(A, B, "far", 0.0)
    with pytest.raises(nanopush.InputError, match="must be a real number"):
        nanopush.friction_wrench(A, B, None, 0.0)
    with pytest.raises(nanopush.InputError, match=r"^engine = gpu"):
        nanopush.friction_wrench(A, B, 1e-9, 0.0, engine="gpu")
    with pytest.raises(nanopush.InputError, match=r"^omega = inf"):
        nanopush.friction_from_velocity(A, B, 1.0, 0.0, math.inf)


def test_from_velocity():
    rng = np.random.default_rng(3)
    vx, vy = rng.uniform(-1, 1, 200), rng.uniform(-1, 1, 200)
    omega = rng.uniform(-1, 1, 200) / L * 10.0 ** rng.uniform(-6, 1, 200)
    w = nanopush.friction_from_velocity(A, B, vx, vy, omega, mu_n=2.0)
    assert w.fx.shape == (200,)
    # Against the iCOR form: c = (-vy, vx)/omega = -R (cos alpha, sin alpha), sense = sign(omega).
    R = np.hypot(vx, vy) / np.abs(omega)
    s = np.sign(omega)
    alpha = np.arctan2(-s * vx, s * vy)
    ref = nanopush.friction_wrench(A, B, R, alpha, sense=s, mu_n=2.0)
    for x, y in zip(w, ref):
        np.testing.assert_allclose(x, y, rtol=1e-12, atol=1e-12 * 2.0 * L)
    # Pure translation: f = -muN v/|v|, no moment; rest: zero.
    t = nanopush.friction_from_velocity(A, B, 3.0, -4.0, 0.0, mu_n=2.0)
    assert t == (-1.2, 1.6, 0.0)
    assert nanopush.friction_from_velocity(A, B, 0.0, 0.0, 0.0) == (0.0, 0.0, 0.0)


def test_gil_released_during_a_long_call():
    R = np.full(3_000_000, 1e-9)
    alpha = np.linspace(0, 6, R.size)
    w = assert_runs_without_the_gil(lambda: nanopush.friction_wrench(A, B, R, alpha))
    assert w.fx.shape == R.shape


def test_threads_give_the_same_numbers():
    R, alpha = icors(5000)
    ref = nanopush.friction_wrench(A, B, R, alpha)
    out = [None] * 4

    def worker(k):
        out[k] = nanopush.friction_wrench(A, B, R, alpha)

    ts = [threading.Thread(target=worker, args=(k,)) for k in range(4)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    for w in out:
        assert all(same(x, y) for x, y in zip(w, ref))
