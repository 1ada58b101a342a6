"""nanopush.fit's Python side: observations from a path, a dict of arrays, a NumPy structured
array or a pandas DataFrame; FitResult.report() (lmfit's layout) and FitResult.plot()."""

import io as _io
import math as _math
import os as _os
from collections.abc import Mapping as _Mapping

import numpy as _np

from . import _nanopush

_COLUMNS = ("t", "x", "y", "theta", "sigma_x", "sigma_y", "sigma_theta")
_UNITS = {"x": "m", "y": "m", "theta": "rad"}


def _input_error(message, field=""):
    e = _nanopush.InputError(message)
    e.field, e.index = field, None
    return e


def _columns(data):
    """{name: 1-d array} of `data` (not a path), or None for a type fit does not read."""
    if isinstance(data, _np.ndarray) and data.dtype.names:
        return {name: data[name] for name in data.dtype.names}
    if type(data).__module__.startswith("pandas") and hasattr(data, "columns"):  # a DataFrame, pandas optional
        return {str(name): data[name].to_numpy() for name in data.columns}
    if isinstance(data, _Mapping):
        return dict(data)
    return None


def observations_csv(data):
    """`data` (dict of arrays, structured array, DataFrame) as the CSV text the library's
    reader takes: the same checks and messages (row and column named) as a file, every number
    written shortest round-trip (exact)."""
    cols = _columns(data)
    if cols is None:
        raise _input_error(f"data = {data!r:.80}: must be a path, a dict of arrays, a NumPy structured array "
                           "or a pandas DataFrame", "data")
    if not cols:
        raise _input_error("data = {}: no columns (need t and any of x, y, theta)", "data")
    arrays, n = {}, None
    for name, values in cols.items():
        if not isinstance(name, str) or any(c in name for c in ',"\r\n'):
            raise _input_error(f"data column {name!r:.80}: must be one of {', '.join(_COLUMNS)}", "data")
        try:
            a = _np.asarray(values, dtype=_np.float64)
        except (TypeError, ValueError):
            raise _input_error(f"data[{name}] = {values!r:.80}: must be numbers", f"data.{name}") from None
        if a.ndim != 1:
            raise _input_error(f"data[{name}]: an array of shape {a.shape}: must be one value per row (1-d)",
                               f"data.{name}")
        if n is not None and len(a) != n:
            raise _input_error(f"data[{name}]: {len(a)} values: every column needs the same number of rows ({n})",
                               f"data.{name}")
        n = len(a)
        arrays[name] = a
    out = _io.StringIO()
    out.write(",".join(arrays) + "\n")
    rows = zip(*(a.tolist() for a in arrays.values()))
    out.writelines(",".join(map(repr, r)) + "\n" for r in rows)
    return out.getvalue()


def report(self, min_correl=0.1):
    """The fit as lmfit's fit_report lays it out: [[Fit Statistics]], [[Variables]] (value
    +/- stderr (relative), init) and [[Correlations]] above `min_correl`, largest first."""
    names, n, k = self.names, self.ndata, len(self.names)
    lines = ["[[Fit Statistics]]",
             "    # fitting method   = Levenberg-Marquardt (nanopush)",
             f"    # function evals   = {self.nfev}",
             f"    # data points      = {n}",
             f"    # variables        = {k}",
             f"    chi-square         = {self.chi2:.8g}",
             f"    reduced chi-square = {self.chi2_dof:.8g}"]
    if n > 0 and self.chi2 > 0 and _math.isfinite(self.chi2):
        base = n * _math.log(self.chi2 / n)
        lines += [f"    Akaike info crit   = {base + 2 * k:.8g}",
                  f"    Bayesian info crit = {base + _math.log(n) * k:.8g}"]
    if not self.success:
        lines.append(f"##  Warning: not converged: {self.message}")
    lines.append("[[Variables]]")
    width = max((len(name) for name in names), default=0) + 1
    for name in names:
        p = self.parameters[name]
        v, se = p["value"], p["stderr"]
        s = f"    {name + ':':<{width}} {v:.8g}"
        if _math.isfinite(se):
            s += f" +/- {se:.8g}"
            if v != 0:
                s += f" ({abs(se / v):.2%})"
        else:
            s += " +/- nan (not determined)"
        s += f" (init = {p['start']:.8g})"
        if p["at_bound"]:
            s += " (at bound)"
        lines.append(s)
    pairs = []
    corr = self.correlation
    for i in range(k):
        for j in range(i + 1, k):
            c = corr[i, j]
            if _math.isfinite(c) and abs(c) >= min_correl:
                pairs.append((abs(c), f"    C({names[i]}, {names[j]}) = {c:+.4f}"))
    if pairs:
        lines.append(f"[[Correlations]] (unreported correlations are < {min_correl:.3f})")
        lines += [text for _, text in sorted(pairs, key=lambda p: -p[0])]
    return "\n".join(lines)


def plot(self, path=None, figsize=None):
    """Data, fit and residual panels (matplotlib, imported here): per observed column (x, y,
    theta), the observations with their sigma and the fitted model over t, and below it the
    residuals (observed - model)/sigma. Returns the matplotlib Figure; with `path`, also
    writes it there (format from the extension, replaced atomically as every output)."""
    from matplotlib.figure import Figure

    t, obs, sig, model, res = self.t, self.observed, self.sigma, self.fitted, self.residuals
    cols = [c for c in range(3) if not _np.all(_np.isnan(obs[:, c]))]
    fig = Figure(figsize=figsize or (4.2 * max(len(cols), 1), 5.0), layout="constrained")
    grid = fig.add_gridspec(2, max(len(cols), 1), height_ratios=(3, 1))
    for j, c in enumerate(cols):
        name = ("x", "y", "theta")[c]
        top = fig.add_subplot(grid[0, j])
        top.errorbar(t, obs[:, c], yerr=sig[:, c], fmt="o", ms=3, lw=0.8, label="data")
        top.plot(t, model[:, c], "-", label="fit")
        top.set_ylabel(f"{name} [{_UNITS[name]}]")
        top.legend(loc="best")
        top.tick_params(labelbottom=False)
        bottom = fig.add_subplot(grid[1, j], sharex=top)
        bottom.axhline(0.0, color="0.6", lw=0.8)
        bottom.plot(t, res[:, c], "o", ms=3)
        bottom.set_xlabel("t [s]")
        bottom.set_ylabel("residual / sigma")
    if path is not None:
        path = _os.fspath(path)
        buf = _io.BytesIO()
        fmt = _os.path.splitext(path)[1].lstrip(".").lower() or "png"
        fig.savefig(buf, format=fmt)
        _nanopush._write_file(path, buf.getvalue())
    return fig
