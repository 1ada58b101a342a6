"""nanopush.icor and nanopush.estimate_mu against `nanopush icor formulas | roots | dynamic |
rectangle | estimate-mu`: the same doubles, bit for bit; broadcasting; the library's messages."""

import math

import numpy as np
import pytest

import nanopush
from nanopush import icor
from conftest import column, read_csv
from test_run import same

ROD = icor.nanorod()
L, K2, W = ROD.length, ROD.k2, ROD.load


def test_rod():
    assert (ROD.length, ROD.radius) == (590e-9, 13.5e-9)
    assert ROD.half_length == L / 2 and ROD.k2 == ROD.inertia / ROD.mass
    assert ROD.load == ROD.mass * ROD.gravity + ROD.vdw_force
    r = icor.Rod(length=400e-9)
    assert r.length == 400e-9 and r.radius == ROD.radius
    with pytest.raises(nanopush.InputError, match="length"):
        icor.Rod(length=-1.0)


@pytest.mark.parametrize("mu, ratio, rod_args", [(0.1, 1.0, []), (0.25, 1.5, ["--length", "4e-07"])])
def test_formulas_bit_for_bit(cli, tmp_path, mu, ratio, rod_args):
    out = tmp_path / "f.csv"
    cli("icor", "formulas", "--n", 41, "--mu", mu, "--force-ratio", ratio, *rod_args, "--out", out)
    h, rows = read_csv(out)
    rod = icor.Rod(length=4e-7) if rod_args else icor.nanorod()
    Lr, k2, W = rod.length, rod.k2, rod.load
    yn = np.array(column(h, rows, "yn"))
    F = ratio * mu * W
    Fmin = icor.minimum_force(mu, W, yn, Lr)
    assert same(icor.experimental_fit(yn, Lr), column(h, rows, "R_experimental_fit"))
    assert same(icor.falvo(yn, Lr), column(h, rows, "R_falvo"))
    assert same(icor.li(yn, Lr), column(h, rows, "R_li"))
    r413 = icor.unknown_pressure(yn, Lr)
    assert same(r413, column(h, rows, "R_unknown_pressure"))
    assert same(Fmin, column(h, rows, "F_min"))
    known = np.array([icor.known_pressure(mu, W, y, F, Lr) if F >= f else np.nan for y, f in zip(yn, Fmin)])
    assert same(known, column(h, rows, "R_known_pressure"))
    assert same(icor.force_from_icor(mu, W, r413, Lr), column(h, rows, "F_from_icor"))
    neg, pos = icor.cubic_branches(yn, Lr, k2)
    assert same(neg, column(h, rows, "R_constrained_negative"))
    assert same(pos, column(h, rows, "R_constrained_positive"))
    f52 = np.where(np.isnan(neg), np.nan, icor.constrained_force(mu, W, np.nan_to_num(neg), yn, Lr, k2))
    assert same(f52, column(h, rows, "F_constrained_negative"))
    assert same(icor.impulsive(yn, k2), column(h, rows, "R_impulsive"))


def test_roots_by_every_solver_bit_for_bit(cli, tmp_path):
    yns = [0.0, 1e-15, 1e-9, 100e-9, 200e-9, 295e-9]
    out = tmp_path / "r.csv"
    cli("icor", "roots", *[a for y in yns for a in ("--yn", repr(y))], "--out", out)
    h, rows = read_csv(out)
    solver_of = {("brent", "cxx"): "brent", ("eigen", "cxx"): "eigen", ("brent", "f77"): "brent_f77",
                 ("lapack", "f77"): "lapack_f77"}
    assert len(rows) == 4 * len(yns)
    assert set(icor.cubic_solvers) == set(solver_of.values())
    for row in rows:
        cell = dict(zip(h, row))
        s = icor.cubic_roots(float(cell["yn"]), L, K2, solver=solver_of[cell["solver"], cell["language"]])
        assert len(s.real_roots) == int(cell["n_real"])
        assert (s.complex_roots, s.at_infinity) == (int(cell["n_complex"]), int(cell["n_infinite"]))
        for i in range(3):
            got = s.real_roots[i] if i < len(s.real_roots) else math.nan
            assert same(got, float(cell[f"root_{i + 1}"] or "nan"))
        assert same(math.nan if s.negative is None else s.negative, float(cell["negative_branch"] or "nan"))
        assert same(math.nan if s.positive is None else s.positive, float(cell["positive_branch"] or "nan"))
        assert same(s.max_residual, float(cell["max_relative_residual"]))


def test_estimate_mu_bit_for_bit(cli, tmp_path):
    cases = [(["--yn", "2e-7", "--yn-sigma", "5e-9", "--length-sigma", "5e-9"],
              dict(yn=2e-7, sigma_yn=5e-9, sigma_L=5e-9), "force"),
             (["--icor", "2.5e-6", "--icor-sigma", "1e-7", "--hamaker-sigma", "1e-19"],
              dict(R=2.5e-6, sigma_R=1e-7, sigma_H=1e-19), "icor")]
    for args, kwargs, basis in cases:
        out = tmp_path / f"{basis}.csv"
        cli("icor", "estimate-mu", "--force", "1e-6", "--force-sigma", "3e-8", *args, "--out", out)
        h, rows = read_csv(out)
        cells = {r[0]: dict(zip(h, r)) for r in rows}
        e = nanopush.estimate_mu(1e-6, 3e-8, **kwargs)
        assert e.basis == basis
        assert same(e.mu, float(cells["mu"]["value"])) and same(e.sigma, float(cells["mu"]["sigma"]))
        assert same(e.load, float(cells["W"]["value"]))
        assert [c["input"] for c in e.contributions] == [r[0] for r in rows[2:]]
        for c in e.contributions:
            row = cells[c["input"]]
            assert same(c["value"], float(row["value"])) and same(c["sigma"], float(row["sigma"]))
            assert same(c["derivative"], float(row["dmu_dinput"]))
            assert same(c["contribution"], float(row["contribution"]))
            assert e.derivatives[c["input"]] == c["derivative"]


def test_estimate_mu_errors(cli):
    msg = cli.error("icor", "estimate-mu", "--force", "1e-6", "--yn", "1")
    with pytest.raises(nanopush.InputError) as e:
        nanopush.estimate_mu(1e-6, yn=1.0)
    assert str(e.value) == msg
    with pytest.raises(ValueError, match="exactly one"):
        nanopush.estimate_mu(1e-6)
    with pytest.raises(ValueError, match="exactly one"):
        nanopush.estimate_mu(1e-6, yn=1e-7, R=1e-7)
    with pytest.raises(nanopush.InputError, match=r"^F = -1"):
        nanopush.estimate_mu(-1.0, R=1e-7)


def test_rectangle_bit_for_bit(cli, tmp_path):
    out = tmp_path / "q.csv"
    cli("icor", "rectangle", "--aspect", "0.1", "--aspect", "1", "--n", 5, "--out", out)
    h, rows = read_csv(out)
    for row in rows:
        c = dict(zip(h, row))
        q = icor.rectangle(float(c["a"]), float(c["b"]), float(c["yn"]))
        assert same(q.R if math.isfinite(q.R) else math.nan, float(c["R"] or "nan"))
        assert same(q.alpha, float(c["alpha"])) and same(q.force, float(c["F_min_ratio"]))
        assert q.converged == (c["converged"] == "1") and same(q.residual, float(c["residual"]))


def test_dynamic_bit_for_bit(cli, tmp_path):
    out = tmp_path / "d.csv"
    cli("icor", "dynamic", "--yn", "1e-7", "--force-ratio", "2", "--samples", "4", "--out", out)
    h, rows = read_csv(out)
    times = column(h, rows, "t")
    d = icor.dynamic(1e-7, 2 * 0.1 * W, mu=0.1, times=times)
    assert same(d["t"], times)
    assert same(d["R"], column(h, rows, "R")) and same(d["axial"], column(h, rows, "R_axial"))
    assert same(d["offset"], column(h, rows, "offset")) and same(d["theta"], column(h, rows, "theta"))
    assert d["integrator"] == rows[0][h.index("integrator")]
    assert same(d["half_width"], float(rows[0][h.index("half_width")]))
    assert d["half_width"] == icor.rod_contact_half_width(ROD)
    assert all(d["moving"]) and not d["stuck"]


def test_broadcasting_and_errors(cli):
    yn = np.linspace(0, L / 2, 12).reshape(3, 4)
    Ls = np.array([L, 0.8 * L, 0.6 * L, 0.5 * L])
    r = icor.unknown_pressure(yn, Ls)
    assert r.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            assert r[i, j] == icor.unknown_pressure(float(yn[i, j]), float(Ls[j]))
    assert isinstance(icor.falvo(1e-7, L), float)
    mus = np.array([0.1, 0.2])[:, None, None]
    assert icor.minimum_force(mus, W, yn, L).shape == (2, 3, 4)
    neg, pos = icor.cubic_branches(yn, L, K2, solver="eigen")
    assert neg.shape == pos.shape == (3, 4)
    cx, cy, R = icor.from_velocity(np.array([1.0, 0.0]), 2.0, np.array([[4.0], [0.0]]))
    assert cx.shape == (2, 2) and cx[0, 0] == -0.5 and cy[0, 0] == 0.25
    assert R[1, 0] == math.inf and (cx[1, 0], cy[1, 0]) == (0.0, 0.0)
    msg = cli.error("icor", "roots", "--yn", "1e-9", "--length", "-1")
    with pytest.raises(nanopush.InputError):
        icor.unknown_pressure(1e-9, -1.0)
    with pytest.raises(nanopush.InputError) as e:
        icor.unknown_pressure(np.array([1e-9, -1e-9]), L)
    assert str(e.value) == "yn = -1e-09: must be >= 0 (m)" and e.value.index == (1,)
    with pytest.raises(nanopush.InputError) as e:
        icor.cubic_roots(-1e-9, L, K2)
    assert str(e.value) == cli.error("icor", "roots", "--yn", "-1e-9").replace("--yn", "yn")
    # Beyond the rod's end (yn > L/2) is refused as by the CLI and the C API (issue 34).
    with pytest.raises(nanopush.InputError) as e:
        icor.cubic_roots(1.0, L, K2)
    assert str(e.value) == cli.error("icor", "roots", "--yn", "1").replace("--yn", "yn")
    assert "at most b = L/2" in str(e.value)
    assert msg  # the CLI refuses the rod too
    with pytest.raises(nanopush.InputError, match="solver = newton"):
        icor.cubic_roots(1e-9, L, K2, solver="newton")
    with pytest.raises(nanopush.InputError, match="F_min|minimum"):
        icor.known_pressure(0.1, W, 1e-7, 1e-12, L)
