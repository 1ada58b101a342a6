"""nanopush.fit shaped like SciPy and lmfit: data as a path, a dict of arrays, a NumPy
structured array or a pandas DataFrame (the same fit, bit for bit); FitResult's x, stderr,
covariance (against the inverse of J^T W J from an independent Jacobian: central differences
of runs at the observation times), report() in lmfit's layout and plot() (Agg, into a file)."""

import numpy as np
import pytest

import nanopush
from test_run import same


def short_scene():
    s = nanopush.Scene.preset("fig3_6a")
    s.set({"solver.t_end": 0.4e-9, "solver.samples": 21})
    return s


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    path = tmp_path_factory.mktemp("fit") / "data.csv"
    nanopush.synthesize(short_scene(), (2e-9, 2e-9, 0.0), 3, path=path)
    header, *rows = [line.split(",") for line in path.read_text().splitlines()]
    cols = {h: np.array([float(r[i]) for r in rows]) for i, h in enumerate(header)}
    return path, cols


def start():
    s = short_scene()
    s.set("push.force", 4e-6)
    return s


def test_every_data_form_gives_the_same_fit(data):
    path, cols = data
    ref = nanopush.fit(start(), path, "push.force")
    structured = np.zeros(len(cols["t"]), dtype=[(k, "f8") for k in cols])
    for k, v in cols.items():
        structured[k] = v
    forms = [str(path), cols, {k: list(v) for k, v in cols.items()}, structured]
    import pandas as pd  # .ci/setup installs python3-pandas

    forms.append(pd.DataFrame(cols))
    for form in forms:
        r = nanopush.fit(start(), form, "push.force")
        assert same(r.x, ref.x) and same(r.stderr, ref.stderr) and r.chi2 == ref.chi2, type(form)
        assert same(r.observed, ref.observed) and same(r.sigma, ref.sigma)


def test_bad_data_forms_name_what_is_wrong(data):
    _, cols = data
    with pytest.raises(nanopush.InputError, match="unknown|speed"):
        nanopush.fit(start(), {**cols, "speed": cols["t"]}, "push.force")
    bad = {k: v.copy() for k, v in cols.items()}
    bad["x"][1] = np.nan
    with pytest.raises(nanopush.InputError, match="row 2"):
        nanopush.fit(start(), bad, "push.force")
    with pytest.raises(nanopush.InputError, match="same number of rows"):
        nanopush.fit(start(), {**cols, "x": cols["x"][:-1]}, "push.force")
    with pytest.raises(nanopush.InputError, match=r"data\[x\].*must be numbers"):
        nanopush.fit(start(), {**cols, "x": ["a"] * len(cols["t"])}, "push.force")
    with pytest.raises(nanopush.InputError, match="must be a path, a dict of arrays"):
        nanopush.fit(start(), 42, "push.force")


def test_covariance_is_the_inverse_of_the_weighted_normal_matrix(data):
    """x, y observed, free push.force and initial.x: J by central differences of runs at
    the observation times (run(t_eval=...)), cov = (J^T W J)^-1 (not rescaled by chi2/dof)."""
    path, cols = data
    free = ["push.force", "initial.x"]
    s = start()
    s.set("initial.x", 1e-9)
    r = nanopush.fit(s, path, free)
    assert r.success and r.converged and r.nfev == r.n_forward_solves > 0
    assert r.names == free and same(r.x, [r.parameters[k]["value"] for k in free])
    assert same(r.stderr, [r.parameters[k]["stderr"] for k in free])
    cov = r.covariance
    assert same(np.diag(cov), r.stderr ** 2) and same(cov, cov.T)
    assert np.allclose(cov / np.outer(r.stderr, r.stderr), r.correlation, rtol=1e-15, atol=1e-15)
    # The oracle.
    t = cols["t"]
    def poses(p):
        sc = short_scene()
        sc.set({"push.force": float(p[0]), "initial.x": float(p[1])})
        run = nanopush.run(sc, t_eval=t, rtol=1e-13, method="modern", error_estimate=False)
        return np.concatenate([run.x, run.y])
    w = np.concatenate([1 / cols["sigma_x"], 1 / cols["sigma_y"]])
    J = np.empty((2 * len(t), 2))
    for k in range(2):
        h = 1e-5 * abs(r.x[k]) if k == 0 else 1e-11  # push.force [N]; initial.x [m]
        up, down = r.x.copy(), r.x.copy()
        up[k] += h
        down[k] -= h
        J[:, k] = (poses(up) - poses(down)) / (2 * h) * w
    oracle = np.linalg.inv(J.T @ J)
    assert np.allclose(cov, oracle, rtol=1e-4, atol=0), (cov, oracle)


def test_report_has_lmfit_layout(data):
    path, _ = data
    r = nanopush.fit(start(), path, ["push.force", "initial.omega"])
    text = r.report()
    lines = text.splitlines()
    assert lines[0] == "[[Fit Statistics]]"
    assert f"    # function evals   = {r.nfev}" in lines
    assert f"    # data points      = {r.ndata}" in lines and r.ndata == 42
    assert "    # variables        = 2" in lines
    assert any(line.startswith("    chi-square         = ") for line in lines)
    assert any(line.startswith("    reduced chi-square = ") for line in lines)
    v = lines.index("[[Variables]]")
    assert lines[v + 1].startswith("    push.force:    ") and "+/-" in lines[v + 1] and "(init = 4e-06)" in lines[v + 1]
    assert lines[v + 2].startswith("    initial.omega: ")
    c = r.correlation[0, 1]
    if abs(c) >= 0.1:
        assert f"    C(push.force, initial.omega) = {c:+.4f}" in lines
    assert "[[Correlations]]" not in r.report(min_correl=1.1)


def test_plot_writes_data_fit_and_residual_panels(data, tmp_path):
    path, _ = data
    r = nanopush.fit(start(), path, "push.force")
    out = tmp_path / "fit.png"
    fig = r.plot(out)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert len(fig.axes) == 4  # x and y observed: data + fit above, residuals below, each
    labels = [ax.get_ylabel() for ax in fig.axes]
    assert labels == ["x [m]", "residual / sigma", "y [m]", "residual / sigma"]
    assert len(fig.axes[0].lines) >= 1 and fig.axes[0].get_legend() is not None
    svg = tmp_path / "fit.svg"
    r.plot(svg)
    assert svg.read_text().lstrip().startswith("<?xml")
