"""The binding benchmark's script still runs and its two sides still compute the same numbers
(a small run; its timings are recorded by hand in docs/python.md, never asserted here)."""

import csv
import os
import subprocess
import sys


def test_benchmark_script_runs(source_dir, tmp_path):
    script = os.path.join(source_dir, "python", "bench", "bench_python.py")
    p = subprocess.run([sys.executable, script, "--cli", os.environ["NANOPUSH_CLI"],
                        "--loop", os.environ["NANOPUSH_PY_FRICTION_LOOP"], "--out", str(tmp_path),
                        "--n", "5000", "--repeats", "1", "--repeats-run", "3"], capture_output=True, text=True)
    assert p.returncode == 0, p.stdout + p.stderr
    with open(tmp_path / "python_bench.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert [r["benchmark"].split(",")[0].split(" (")[0] for r in rows] == ["friction_wrench", "run fig3_6a"]
    assert all(r["identical"] == "1" for r in rows)
    assert all(float(r["python_s"]) > 0 and float(r["reference_s"]) > 0 for r in rows)
