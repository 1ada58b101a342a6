"""nanopush.estimate_mu_batch against `nanopush fit-icor` (the same doubles, bit for bit), against
the one-observation nanopush.estimate_mu, and its messages for bad input."""

import json
import math

import numpy as np
import pytest

import nanopush
from nanopush import icor
from conftest import column, read_csv

ROD = icor.nanorod()
L, W = ROD.length, ROD.load


def pushes(mu=0.2, seed=7, n=12):
    """Line-contact pushes (iCOR of eq 4.13, minimum force of eq 4.8) with seeded noise."""
    rng = np.random.default_rng(seed)
    yn = rng.uniform(0.1, 0.95, n) * L / 2
    R = icor.unknown_pressure(yn, L)
    F = icor.minimum_force(mu, W, yn, L)
    sF, sy, sR = 0.02 * F, np.full(n, 2e-9), np.full(n, 3e-9)
    return F + sF * rng.standard_normal(n), sF, yn + sy * rng.standard_normal(n), sy, R + sR * rng.standard_normal(n), sR


def test_cli_bit_for_bit(cli, tmp_path):
    F, sF, yn, sy, R, sR = pushes()
    R[3] = np.nan  # row 4: iCOR not observed
    data = tmp_path / "push.csv"
    with open(data, "w") as f:
        f.write("F,sigma_F,yn,sigma_yn,R,sigma_R\n")
        for row in zip(F, sF, yn, sy, R, sR):
            f.write(",".join("" if math.isnan(v) else repr(float(v)) for v in row) + "\n")
    out = tmp_path / "out"
    cli("fit-icor", data, "--out", out, "--hamaker-sigma", "3e-20", "--alpha", "0.05")
    summary = json.loads((out / "fit_icor.json").read_text())
    h, rows = read_csv(out / "fit_icor.csv")
    for p in ("known", "unknown"):
        b = nanopush.estimate_mu_batch(F, sF, yn=yn, sigma_yn=sy, R=R, sigma_R=sR, pressure=p, sigma_H=3e-20,
                                       alpha=0.05)
        s = summary[p]
        assert (b.mu, b.sigma) == (s["mu"]["value"], s["mu"]["stderr"])
        assert (b.sigma_stat, b.sigma_syst, b.sigma_scaled) == (s["stderr_statistical"], s["stderr_systematic"],
                                                                s["stderr_scaled"])
        assert (b.chi2, b.dof, b.chi2_dof, b.p_value, b.consistent) == (s["chi2"], s["dof"], s["chi2_dof"],
                                                                        s["p_value"], s["consistent"])
        assert list(b.row_mu) == column(h, rows, "mu_" + p)
        assert list(b.row_sigma) == column(h, rows, "sigma_" + p)
        assert list(b.row_pull) == column(h, rows, "pull_" + p)
        assert abs(b.mu - 0.2) < 3 * b.sigma
    b = nanopush.estimate_mu_batch(F, sF, yn=yn, sigma_yn=sy, R=R, sigma_R=sR)
    assert b.equations[3] == "4.8" and b.equations[0] == "4.10"
    assert b.pressure == "known" and "MuBatch known pressure" in repr(b)


def test_one_and_identical_observations():
    one = nanopush.estimate_mu(1e-6, 3e-8, R=150e-9, sigma_R=4e-9)
    b = nanopush.estimate_mu_batch([1e-6], 3e-8, R=[150e-9], sigma_R=4e-9)
    assert (b.mu, b.sigma) == (one.mu, one.sigma) and math.isnan(b.chi2_dof) and b.dof == 0
    b = nanopush.estimate_mu_batch(np.full(16, 1e-6), 3e-8, R=np.full(16, 150e-9), sigma_R=4e-9)
    assert b.mu == one.mu and b.sigma == pytest.approx(one.sigma / 4, rel=1e-14) and b.chi2 == 0.0


def test_bad_input():
    with pytest.raises(nanopush.InputError, match=r"row 2: yn = not given"):
        nanopush.estimate_mu_batch([1e-6, 1e-6], 1e-8, yn=[1e-7, np.nan], sigma_yn=1e-9, R=[1e-7, 1e-7],
                                   sigma_R=1e-9, pressure="unknown")
    with pytest.raises(nanopush.InputError, match=r"sigma_yn = None: must be given with yn"):
        nanopush.estimate_mu_batch([1e-6, 1e-6], 1e-8, yn=[1e-7, 1e-7])
    with pytest.raises(nanopush.InputError, match=r"sigma_force .*len\(force\) = 2"):
        nanopush.estimate_mu_batch([1e-6, 1e-6], [1e-8, 1e-8, 1e-8], yn=[1e-7, 1e-7], sigma_yn=1e-9)
    with pytest.raises(nanopush.InputError, match=r"pressure = both: must be known or unknown"):
        nanopush.estimate_mu_batch([1e-6], 1e-8, yn=[1e-7], sigma_yn=1e-9, pressure="both")
    with pytest.raises(nanopush.InputError, match=r"row 1: sigma of mu = 0"):
        nanopush.estimate_mu_batch([1e-6], 0.0, yn=[1e-7], sigma_yn=0.0)
