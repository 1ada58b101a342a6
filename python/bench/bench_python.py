"""Benchmark of the Python binding against plain C++ (issue 20; a benchmark, not a test).

1. friction_wrench over N iCORs (default 10^6) from NumPy, against the same loop in C++
   (nanopush_py_friction_loop: the unchecked hot path into three arrays); both must give
   the same doubles. Target: Python throughput >= 0.9 x C++.
   The two sides alternate, pass by pass, so that both see the same load.
2. nanopush.run of fig3_6a against `nanopush run fig3_6a`'s integration time (the wall time
   it reports). Target: within 5 %.

    python3 python/bench/bench_python.py --cli build/py/nanopush \
        --loop build/py/python/nanopush_py_friction_loop --out bench_python

Writes OUT/python_bench.csv (one row per benchmark: seconds per call of the Python side and
of the reference, throughputs, the ratio, the target, whether met, whether both gave the same
numbers; for the run, engine_s: the engine's own time inside nanopush.run) and
OUT/python_bench.md. Friction: best of --repeats passes of each side (and the median ratio
of the paired passes); run: median of --repeats-run. The CLI's
integration time is one run in a fresh process each time; nanopush.run repeats in one process.
"""

import argparse
import csv
import os
import pathlib
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import time

import numpy as np

import nanopush


def friction(args, tmp):
    a, b = 27.5e-9, 50e-9
    L = max(a, b)
    rng = np.random.default_rng(1)
    R = L * 10.0 ** rng.uniform(-3.0, 3.0, args.n)  # closed form and the far-field bands
    alpha = rng.uniform(0.0, 2 * np.pi, args.n)
    R.tofile(tmp / "R.f64")
    alpha.tofile(tmp / "alpha.f64")
    # Interleaved, so that both sides see the same load: one C++ pass, one Python pass, ...
    cxx_rates, py_rates = [], []
    for _ in range(args.repeats):
        p = subprocess.run([args.loop, repr(a), repr(b), str(tmp / "R.f64"), str(tmp / "alpha.f64"),
                            str(tmp / "out.f64"), "1"], capture_output=True, text=True, check=True)
        cxx_rates.append(float(re.search(r"evaluations_per_s (\S+)", p.stdout).group(1)))
        t0 = time.perf_counter()
        w = nanopush.friction_wrench(a, b, R, alpha)
        py_rates.append(args.n / (time.perf_counter() - t0))
    ref = np.fromfile(tmp / "out.f64").reshape(3, args.n)
    best, cxx_rate = max(py_rates), max(cxx_rates)
    paired = statistics.median(p / c for p, c in zip(py_rates, cxx_rates))
    same = all(np.array_equal(x, y) for x, y in zip(w, ref))
    ratio = best / cxx_rate
    return {"benchmark": f"friction_wrench, {args.n} iCORs", "python_s": args.n / best, "reference_s": args.n / cxx_rate,
            "python_rate": best, "reference_rate": cxx_rate, "ratio": ratio,
            "target": "python_rate >= 0.9 reference_rate", "met": int(ratio >= 0.9), "identical": int(same),
            "repeats": args.repeats, "engine_s": "", "paired_ratio": paired}


def run(args, tmp):
    cli_times = []
    for _ in range(args.repeats_run):
        p = subprocess.run([args.cli, "run", "fig3_6a", "--out", str(tmp / "a.csv")], capture_output=True, text=True,
                           check=True)
        m = re.search(r"wall time ([0-9.eE+-]+) (ms|s)", p.stderr)
        cli_times.append(float(m.group(1)) * (1e-3 if m.group(2) == "ms" else 1.0))
    scene = nanopush.Scene.preset("fig3_6a")
    py_times, inner = [], []
    for _ in range(args.repeats_run):
        t0 = time.perf_counter()
        r = nanopush.run(scene)
        py_times.append(time.perf_counter() - t0)
        inner.append(r.wall_time)
    r.to_csv(tmp / "b.csv")
    same = (tmp / "a.csv").read_bytes() == (tmp / "b.csv").read_bytes()
    py, ref = statistics.median(py_times), statistics.median(cli_times)
    ratio = py / ref
    return {"benchmark": "run fig3_6a (median)", "python_s": py, "reference_s": ref, "python_rate": 1 / py,
            "reference_rate": 1 / ref, "ratio": ratio, "target": "python_s <= 1.05 reference_s",
            "met": int(ratio <= 1.05), "identical": int(same), "repeats": args.repeats_run,
            "engine_s": statistics.median(inner), "paired_ratio": statistics.median(
                p / c for p, c in zip(py_times, cli_times))}


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--cli", required=True, help="the nanopush command line")
    ap.add_argument("--loop", required=True, help="nanopush_py_friction_loop (the C++ reference loop)")
    ap.add_argument("--out", default="bench_python", help="output folder")
    ap.add_argument("--n", type=int, default=1_000_000, help="iCORs of the friction benchmark")
    ap.add_argument("--repeats", type=int, default=11, help="passes of each side of the friction benchmark")
    ap.add_argument("--repeats-run", type=int, default=41, help="repeats of the run benchmark (median)")
    args = ap.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as d:
        rows = [friction(args, pathlib.Path(d)), run(args, pathlib.Path(d))]
    cols = ["benchmark", "python_s", "reference_s", "python_rate", "reference_rate", "ratio", "target", "met",
            "identical", "repeats", "engine_s", "paired_ratio"]
    with open(out / "python_bench.csv", "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(cols)
        for r in rows:
            w.writerow([repr(r[c]) if isinstance(r[c], float) else r[c] for c in cols])
    machine = f"{platform.processor() or platform.machine()}, {os.cpu_count()} CPUs, load {os.getloadavg()[0]:.2f}"
    with open(out / "python_bench.md", "w") as f:
        f.write(f"# Python binding benchmark\n\nnanopush {nanopush.__version__}, Python {sys.version.split()[0]}, "
                f"NumPy {np.__version__}; {machine}.\n\n")
        f.write("| benchmark | Python | reference (C++) | ratio | target | met | same numbers |\n|---|---:|---:|---:|---|---|---|\n")
        fr, ru = rows
        f.write(f"| {fr['benchmark']} | {fr['python_rate']:.4g} /s | {fr['reference_rate']:.4g} /s | "
                f"{fr['ratio']:.3f} | {fr['target']} | {'yes' if fr['met'] else 'no'} | "
                f"{'yes' if fr['identical'] else 'NO'} |\n")
        f.write(f"| {ru['benchmark']} | {ru['python_s'] * 1e3:.4g} ms | {ru['reference_s'] * 1e3:.4g} ms | "
                f"{ru['ratio']:.3f} | {ru['target']} | {'yes' if ru['met'] else 'no'} | "
                f"{'yes' if ru['identical'] else 'NO'} |\n")
        f.write(f"\nfriction: best of {fr['repeats']} interleaved passes (median of the paired ratios "
                f"{fr['paired_ratio']:.3f}); run: median of {ru['repeats']} "
                f"(the CLI's own reported integration time; nanopush.run timed around the call, "
                f"engine alone {ru['engine_s'] * 1e3:.4g} ms).\n")
    print((out / "python_bench.md").read_text())
    return 0 if all(r["identical"] for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())
