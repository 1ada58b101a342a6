#!/usr/bin/env python3
"""What a process of the command line costs beyond its work: `--version`, and a rough preset's
`run` against the integration time the run itself reports. A benchmark, never a test.

    python3 drivers/bench/bench_startup.py BUILD_DIR [--doc docs/performance.md] [--csv OUT.csv]

Measures nanopush-mpi (the commands with Open MPI linked, as every command was before the
command line was split) and nanopush (no MPI), each against /bin/true started the same way, so
the overhead is what the program adds to an exec. Each figure is the median of --repeats
starts (wall clock; CPU = user + system of the child, from wait4). Writes a CSV and, with
--doc, replaces the block between the `bench_startup` markers of that Markdown file.
"""

import argparse
import os
import pathlib
import re
import statistics
import sys
import tempfile
import time

SCENE = "fig3_17"  # rough surface, thesis law (docs/rough.md)
BEGIN, END = "<!-- bench_startup: begin (drivers/bench/bench_startup.py) -->", "<!-- bench_startup: end -->"


def start(argv, env=None, cwd=None):
    """Wall time [s], CPU time [s], exit status and stderr (where `run` reports) of one process."""
    out = tempfile.TemporaryFile()
    devnull = os.open(os.devnull, os.O_RDWR)
    actions = [(os.POSIX_SPAWN_DUP2, devnull, 0), (os.POSIX_SPAWN_DUP2, devnull, 1),
               (os.POSIX_SPAWN_DUP2, out.fileno(), 2)]
    here = os.getcwd()
    if cwd:
        os.chdir(cwd)
    try:
        t0 = time.perf_counter()
        pid = os.posix_spawn(argv[0], argv, env if env is not None else os.environ, file_actions=actions)
        _, status, ru = os.wait4(pid, 0)
        wall = time.perf_counter() - t0
    finally:
        os.chdir(here)
        os.close(devnull)
    out.seek(0)
    return wall, ru.ru_utime + ru.ru_stime, os.waitstatus_to_exitcode(status), out.read().decode(errors="replace")


def loaded_objects(argv, work):
    """Shared objects the loader initialises for the command (LD_DEBUG=libs)."""
    env = dict(os.environ, LD_DEBUG="libs", LD_DEBUG_OUTPUT=str(work / "ld"))
    start(argv, env, cwd=work)
    names = set()
    for f in work.glob("ld.*"):
        names |= set(re.findall(r"calling init: (\S+)", f.read_text(errors="replace")))
        f.unlink()
    return names


def reported_ms(report):
    """The integration's wall time as `nanopush run` reports it (ms; the run and its error
    estimate's companion run)."""
    m = re.search(r"wall time ([0-9.eE+-]+) (ms|s)\b", report)
    if not m:
        raise SystemExit(f"bench_startup: no 'wall time' in the run's report:\n{report}")
    return float(m.group(1)) * (1.0 if m.group(2) == "ms" else 1e3)


def median_ms(xs):
    return statistics.median(xs) * 1e3


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("build_dir", type=pathlib.Path, help="the build tree holding nanopush and nanopush-mpi")
    ap.add_argument("--repeats", type=int, default=41, help="starts per figure (median; default 41)")
    ap.add_argument("--csv", type=pathlib.Path, default=pathlib.Path("docs/figures/startup.csv"))
    ap.add_argument("--doc", type=pathlib.Path, help="Markdown file whose bench_startup block is replaced")
    a = ap.parse_args()
    if a.repeats < 3:
        raise SystemExit("bench_startup: --repeats must be >= 3")
    programs = [("nanopush-mpi", "with Open MPI linked (as every command before the split)"), ("nanopush", "without MPI")]
    programs = [(a.build_dir.resolve() / p, what) for p, what in programs]
    for p, _ in programs:
        if not os.access(p, os.X_OK):
            raise SystemExit(f"bench_startup: no {p} (build the release preset with MPI first)")
    true = "/bin/true"
    rows = []
    with tempfile.TemporaryDirectory() as tmp:
        work = pathlib.Path(tmp)
        env = {k: v for k, v in os.environ.items() if not k.startswith(("OMPI_", "PMIX_", "PMI_"))}
        base = [start([true], env) for _ in range(a.repeats)]
        base_wall, base_cpu = median_ms([b[0] for b in base]), median_ms([b[1] for b in base])
        for prog, what in programs:
            version = [start([str(prog), "--version"], env) for _ in range(a.repeats)]
            run_argv = [str(prog), "run", SCENE, "--out", str(work / "run.csv")]
            runs = []
            for _ in range(a.repeats):
                wall, cpu, rc, out = start(run_argv, env, cwd=work)
                if rc != 0:
                    raise SystemExit(f"bench_startup: {' '.join(run_argv)} exited {rc}")
                runs.append((wall, cpu, reported_ms(out)))
            n_libs = len(loaded_objects([str(prog), "--version"], work))
            n_mpi = sum("mpi" in n or "open-pal" in n or "pmix" in n
                        for n in loaded_objects([str(prog), "--version"], work))
            v_wall = median_ms([v[0] for v in version])
            r_wall = median_ms([r[0] for r in runs])
            r_integ = statistics.median(r[2] for r in runs)
            r_over = statistics.median((r[0] * 1e3 - r[2]) for r in runs) - base_wall
            # The same for CPU time, start by start: the integration runs on one thread, so on a
            # host with a core free its wall time is its CPU time (on a loaded one its wall time
            # also holds waiting, and this overhead is a lower bound).
            r_cpu_over = statistics.median((r[1] * 1e3 - r[2]) for r in runs) - base_cpu
            rows.append({
                "program": prog.name, "what": what, "shared_objects": n_libs, "mpi_objects": n_mpi,
                "version_wall_ms": v_wall, "version_cpu_ms": median_ms([v[1] for v in version]),
                "version_overhead_ms": v_wall - base_wall,
                "version_cpu_overhead_ms": median_ms([v[1] for v in version]) - base_cpu,
                "run_wall_ms": r_wall, "run_cpu_ms": median_ms([r[1] for r in runs]),
                "run_integration_ms": r_integ, "run_overhead_ms": r_over, "run_cpu_overhead_ms": r_cpu_over,
            })
    cols = list(rows[0].keys())
    a.csv.parent.mkdir(parents=True, exist_ok=True)
    tmp_csv = a.csv.with_name(a.csv.name + f".tmp.{os.getpid()}")
    with open(tmp_csv, "w") as f:
        f.write(",".join(cols) + "\n")
        for r in rows:
            f.write(",".join(f"{r[c]:.4g}" if isinstance(r[c], float) else str(r[c]) for c in cols) + "\n")
    os.replace(tmp_csv, a.csv)

    load = os.getloadavg()[0]
    md = [BEGIN,
          f"`{SCENE}`: `nanopush run {SCENE} --out FILE` (rough surface, thesis law). Median of {a.repeats} starts "
          f"each; /bin/true started the same way takes {base_wall:.2f} ms (wall), {base_cpu:.2f} ms (CPU), and is "
          f"subtracted from the overheads. Load average {load:.2f} on {os.cpu_count()} cores.",
          "",
          "| program | shared objects loaded (MPI's) | `--version` wall / CPU (ms) | `--version` overhead, wall / CPU (ms) | "
          "`run` wall / CPU (ms) | integration, as `run` reports it (ms) | `run` overhead, wall / CPU (ms) |",
          "|---|---|---|---|---|---|---|"]
    for r in rows:
        md.append(f"| `{r['program']}` {r['what']} | {r['shared_objects']} ({r['mpi_objects']}) | "
                  f"{r['version_wall_ms']:.2f} / {r['version_cpu_ms']:.2f} | "
                  f"{r['version_overhead_ms']:.2f} / {r['version_cpu_overhead_ms']:.2f} | "
                  f"{r['run_wall_ms']:.2f} / {r['run_cpu_ms']:.2f} | {r['run_integration_ms']:.2f} | "
                  f"{r['run_overhead_ms']:.2f} / {r['run_cpu_overhead_ms']:.2f} |")
    md += ["", f"Overhead: `--version`'s wall (CPU) − /bin/true's wall (CPU); `run`'s wall (CPU) − the integration it reports − "
           f"/bin/true's wall (CPU), start by start (loading, reading the scene, writing the CSV and its sidecar). "
           f"On a loaded host the wall times include waiting for a core; the CPU times (user + system) do not, but "
           f"the integration's time is a wall time, so `run`'s CPU overhead is then a lower bound. "
           f"CSV: {a.csv.as_posix()}.", END]
    block = "\n".join(md)
    print(block)
    if a.doc:
        text = a.doc.read_text()
        if BEGIN not in text or END not in text:
            raise SystemExit(f"bench_startup: {a.doc} has no bench_startup block ({BEGIN} ... {END})")
        head, rest = text.split(BEGIN, 1)
        _, tail = rest.split(END, 1)
        tmp_doc = a.doc.with_name(a.doc.name + f".tmp.{os.getpid()}")
        tmp_doc.write_text(head + block + tail)
        os.replace(tmp_doc, a.doc)
    return 0


if __name__ == "__main__":
    sys.exit(main())
