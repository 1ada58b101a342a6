"""nanopush.sweep with progress, out=PATH (the table streamed to a file by the sweep runner, as
`nanopush sweep --out` writes it, byte for byte) and Ctrl-C (a real SIGINT to a child
process): the sweep stops, raises KeyboardInterrupt, keeps its journal, and the same call
resumes it to the table an uninterrupted sweep gives."""

import os
import signal
import subprocess
import sys
import textwrap
import time

import numpy as np
import pytest

import nanopush
from test_run import same


def friction_plan():
    return dict(vary={"R": "1e-9:1e-6:40", "alpha": "0:3:25"}, set={"a": 27.5e-9, "b": 50e-9})


def test_progress_is_called_to_the_end():
    calls = []
    res = nanopush.sweep("friction", progress=lambda d, n: calls.append((d, n)), jobs=2, **friction_plan())
    assert calls and calls[-1] == (1000, 1000) and len(res) == 1000
    done = [d for d, _ in calls]
    assert done == sorted(done) and all(n == 1000 for _, n in calls)
    with pytest.raises(nanopush.InputError, match="progress"):
        nanopush.sweep("friction", progress=3, **friction_plan())


def test_progress_exception_stops_the_sweep():
    def stop(done, total):
        raise ValueError("enough")

    scene = nanopush.Scene.preset("fig3_6a")
    with pytest.raises(ValueError, match="enough"):
        nanopush.sweep(scene, vary={"push.force": "1e-6:2e-6:400"}, progress=stop, jobs=1)


def test_out_streams_the_cli_table(cli, tmp_path):
    mine, theirs = tmp_path / "py.csv", tmp_path / "cli.csv"
    r = nanopush.sweep("friction", out=mine, jobs=2, **friction_plan())
    assert isinstance(r, nanopush.SweepFile) and r.complete and r.points == r.done == 1000 and r.failed == 0
    assert r.path == mine
    cli("sweep", "--task", "friction", "--vary", "R=1e-9:1e-6:40", "--vary", "alpha=0:3:25", "--set", "a=27.5e-9",
        "--set", "b=50e-9", "--out", theirs, "--quiet")
    assert mine.read_bytes() == theirs.read_bytes()
    assert (tmp_path / "py.schema.json").read_bytes() != b"" and not (tmp_path / "py.csv.journal").exists()
    mem = nanopush.sweep("friction", **friction_plan())
    import csv
    with open(mine) as f:
        rows = list(csv.reader(f))
    assert same(mem["fx"], [float(row[rows[0].index("fx")]) for row in rows[1:]])
    with pytest.raises(nanopush.InputError, match="check"):
        nanopush.sweep("friction", out=mine, check=True, **friction_plan())


def test_to_pandas_and_xarray():
    res = nanopush.sweep("friction", **friction_plan())
    import pandas as pd  # .ci/setup installs python3-pandas and python3-xarray
    import xarray as xr

    df = res.to_pandas()
    assert isinstance(df, pd.DataFrame) and list(df.columns) == res.columns and same(df["fx"].to_numpy(), res["fx"])
    ds = res.to_xarray()
    assert isinstance(ds, xr.Dataset) and same(ds["fx"].values, res["fx"]) and ds["fx"].attrs["units"] == "N"
    assert same(ds["point"].values, res["point"])


CHILD = textwrap.dedent("""
    import sys, time
    import nanopush
    out = sys.argv[1] if sys.argv[1] != "-" else None
    scene = nanopush.Scene.preset("fig3_6a")
    def progress(done, total):
        print("P", done, total, flush=True)
    try:
        r = nanopush.sweep(scene, vary={"push.force": "1e-6:2e-6:%d"}, jobs=2, progress=progress, out=out)
    except KeyboardInterrupt:
        print("INTERRUPTED", time.monotonic(), flush=True)
        sys.exit(130)
    print("DONE", flush=True)
""")


@pytest.mark.parametrize("to_file", [True, False])
def test_ctrl_c_stops_and_keeps_the_journal(tmp_path, to_file):
    # Enough points that the sweep runs for seconds on a fast idle host (3000 took 0.4 s here,
    # ending before its next look at the signal), interrupted once some are done.
    n = 30000
    out = tmp_path / "t.csv"
    script = tmp_path / "child.py"
    script.write_text(CHILD % n)
    p = subprocess.Popen([sys.executable, str(script), str(out) if to_file else "-"], stdout=subprocess.PIPE,
                         text=True, env=os.environ)
    report = p.stdout.readline()  # the sweep runs: its progress reports, the first at the start
    assert report.startswith("P "), report
    while int(report.split()[1]) == 0:
        report = p.stdout.readline()
        assert report.startswith("P "), report
    assert int(report.split()[1]) < n, "the sweep ended before it could be interrupted"
    sent = time.monotonic()
    p.send_signal(signal.SIGINT)
    rest, _ = p.communicate(timeout=60)
    assert p.returncode == 130, rest
    stopped = float(next(line for line in rest.splitlines() if line.startswith("INTERRUPTED")).split()[1])
    # Within about a second of the signal (generous here: the machine is shared).
    assert stopped - sent < 5.0
    if not to_file:
        return
    journal = tmp_path / "t.csv.journal"
    assert journal.is_file() and not out.exists()
    # records: after the header line and the plan record ("#plan ...")
    kept = sum(1 for line in journal.read_text().splitlines()[1:] if not line.startswith("#"))
    assert 0 < kept < n
    # The same call resumes from the journal to the uninterrupted table.
    r = nanopush.sweep(nanopush.Scene.preset("fig3_6a"), vary={"push.force": f"1e-6:2e-6:{n}"}, jobs=2, out=out)
    assert r.complete and r.resumed >= kept and not journal.exists()
    full = tmp_path / "full.csv"
    nanopush.sweep(nanopush.Scene.preset("fig3_6a"), vary={"push.force": f"1e-6:2e-6:{n}"}, jobs=2, out=full)
    strip = lambda path: [line.split(",")[:-3] for line in path.read_text().splitlines()]  # noqa: E731
    assert strip(out) == strip(full)
