"""Shared fixtures of the Python package's tests: the nanopush command line (the oracle the
package must match bit for bit), CSV readers that keep every number exact, and the check of an
installed copy of the package."""

import csv
import io
import os
import pathlib
import subprocess
import sys
import threading
import time

import pytest


def _required_env(name):
    value = os.environ.get(name)
    if not value:
        pytest.fail(f"{name} is not set: run these tests through CTest (ctest -R python)", pytrace=False)
    return value


class Cli:
    """Runs the nanopush command line built beside the package."""

    def __init__(self, path):
        self.path = path

    def __call__(self, *args, input=None, expect=0, cwd=None):
        p = subprocess.run([self.path, *map(str, args)], input=input, capture_output=True, text=True, cwd=cwd)
        assert p.returncode == expect, f"nanopush {' '.join(map(str, args))}: exit {p.returncode}\n{p.stderr}"
        return p

    def error(self, *args, expect=2, input=None):
        """The message of a failing command: stderr without the 'nanopush: error: ' prefix."""
        p = self(*args, expect=expect, input=input)
        lines = p.stderr.strip().splitlines()
        for line in lines:  # the message line; diagnosis lines may follow it
            for prefix in ("nanopush: error: ", "nanopush: solver failure: "):
                if line.startswith(prefix):
                    return line[len(prefix):]
        return lines[-1]


@pytest.fixture(scope="session")
def cli():
    return Cli(_required_env("NANOPUSH_CLI"))


@pytest.fixture(scope="session")
def source_dir():
    return _required_env("NANOPUSH_SOURCE_DIR")


def assert_installed_package_works(site, cwd):
    """A fresh interpreter with `site` alone on PYTHONPATH (no NANOPUSH_SCENES) imports nanopush
    from below `site`, finds its preset scenes and gives the numbers of the package under test."""
    import nanopush

    code = ("import nanopush; r = nanopush.run('fig3_6a'); print(nanopush.__file__); print(repr(r.theta[-1])); "
            "print(len(nanopush.presets()))")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "NANOPUSH_SCENES")}
    env["PYTHONPATH"] = str(site)
    q = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=cwd)
    assert q.returncode == 0, q.stderr
    where, theta, npresets = q.stdout.split()
    assert pathlib.Path(where).is_relative_to(site)
    assert float(theta) == nanopush.run("fig3_6a").theta[-1]
    assert int(npresets) == len(nanopush.presets())


def read_csv(text_or_path):
    """A CSV as (header, rows of cells), cells as text (numbers are compared by float(cell),
    which reads the shortest round-trip form back to the exact double)."""
    if os.path.exists(str(text_or_path)):
        with open(text_or_path, newline="") as f:
            text = f.read()
    else:
        text = text_or_path
    rows = [r for r in csv.reader(io.StringIO(text)) if r]
    return rows[0], rows[1:]


def column(header, rows, name, empty=float("nan")):
    i = header.index(name)
    return [float(r[i]) if r[i] != "" else empty for r in rows]


def assert_runs_without_the_gil(fn, min_seconds=0.05):
    """Call fn() on a second thread while this thread keeps running Python code, and check
    that this thread ran during the call: in at least 3 of its 10 ms intervals and a fifth of
    them. A call holding the GIL lets it run in one or two intervals at most (the switch
    interval is 5 ms); a call releasing it, in nearly all of them on an idle machine but in
    fewer on a loaded one (CTest runs two tests at once on two cores, beside other work), so
    the bound is set by the held case, not by an idle machine's timing."""
    state = {}

    def worker():
        state["start"] = time.perf_counter()
        state["result"] = fn()
        state["end"] = time.perf_counter()

    t = threading.Thread(target=worker)
    seen = set()
    t.start()
    while t.is_alive():
        seen.add(int(time.perf_counter() * 100))
    t.join()
    assert "end" in state, "the call failed"
    start, end = state["start"], state["end"]
    assert end - start >= min_seconds, f"call too short to tell ({end - start:.3f} s)"
    inside = {b for b in seen if start * 100 <= b < end * 100 - 1}
    intervals = int((end - start) * 100) - 1
    assert len(inside) >= max(3, 0.2 * intervals), (
        f"this thread ran in {len(inside)} of {intervals} 10-ms intervals of the call: GIL held?")
    return state["result"]
