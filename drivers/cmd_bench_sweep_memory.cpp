// nanopush bench-sweep-memory: the resident memory of a sweep against its number of points.
// Each size runs as its own process (`nanopush sweep --task friction`, a cheap closed-form
// task, so the machinery dominates), its peak RSS taken from wait4(); a run that passes the
// time limit is stopped with SIGINT after its points in flight (the sweep keeps its journal)
// and reported with the points it had done, so the largest grids measure memory growth
// honestly without running to the end. A benchmark, never a timed test. docs/performance.md.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <thread>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "bench_process.hpp"
#include "bench_report.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

using Clock = std::chrono::steady_clock;

constexpr double kRssTargetMb = 200;  // a 1e7-point grid under 200 MB (issue 34)

struct MemOptions {
  std::string out = "bench_sweep_memory";
  double max_points = 1e7;
  double time_limit = 60;
  unsigned jobs = 2;
  bool no_plot = false, quiet = false;
};

struct Run {
  std::size_t planned = 0, done = 0;
  bool completed = false;
  double wall = 0, cpu = 0, peak_mb = 0;
  int status = 0;
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// One sweep of `points` points (R x alpha, 1000 values of R) as a child process.
Run run_size(const fs::path& self, const fs::path& dir, std::size_t points, const MemOptions& o) {
  const std::size_t nr = std::min<std::size_t>(points, 1000), na = points / nr;
  Run r;
  r.planned = nr * na;
  const fs::path table = dir / ("t" + std::to_string(r.planned) + ".csv"), log = dir / "sweep.log";
  std::vector<std::string> argv = {self.string(), "sweep", "--task", "friction",
                                   "--vary", "R=1e-8:1e-6:" + std::to_string(nr),
                                   "--vary", "alpha=0:3:" + std::to_string(na),
                                   "--jobs", std::to_string(o.jobs), "--quiet", "--out", table.string()};
  const auto t0 = Clock::now();
  const pid_t pid = spawn_logged(argv, {}, log, "bench-sweep-memory");
  int status = 0;
  rusage ru{};
  bool stopped = false;
  for (;;) {
    const pid_t w = ::wait4(pid, &status, WNOHANG, &ru);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) throw std::runtime_error("bench-sweep-memory: wait4 failed");
    if (!stopped && std::chrono::duration<double>(Clock::now() - t0).count() > o.time_limit) {
      ::kill(pid, SIGINT);  // stop after the points in flight; the journal keeps them
      stopped = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  r.wall = std::chrono::duration<double>(Clock::now() - t0).count();
  r.cpu = static_cast<double>(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) +
          1e-6 * static_cast<double>(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
  r.peak_mb = static_cast<double>(ru.ru_maxrss) / 1024.0;  // Linux: kB
  r.status = exit_status(status);
  const std::string text = read_text(log);
  if (r.status == 0) {
    r.completed = true;
    r.done = r.planned;
  } else if (r.status == 130) {
    // "sweep: interrupted: X of N points are in ..."
    const auto at = text.find("interrupted: ");
    if (at == std::string::npos) throw std::runtime_error("bench-sweep-memory: stopped sweep said: " + text);
    r.done = std::strtoull(text.c_str() + at + 13, nullptr, 10);
  } else {
    throw std::runtime_error("bench-sweep-memory: the " + std::to_string(r.planned) + "-point sweep exited " +
                             std::to_string(r.status) + ": " + text);
  }
  std::error_code ec;
  for (const auto& p : {table, schema_path(table), fs::path(table.string() + ".journal")}) fs::remove(p, ec);
  return r;
}

std::string fixed(double v, int digits) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

int bench_memory(const MemOptions& o) {
  if (!(o.max_points >= 1000 && o.max_points <= 1e8))
    throw InputError("--max-points", fmt(o.max_points), "must be in [1000, 100000000]");
  const fs::path self = fs::read_symlink("/proc/self/exe");
  const fs::path out = o.out;
  fs::create_directories(out);
  std::string tmpl = (fs::temp_directory_path() / "nanopush-bench-memory-XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw std::runtime_error("bench-sweep-memory: cannot create a temporary directory");
  const fs::path dir = tmpl;
  std::vector<Run> runs;
  for (double n = 1000; n <= o.max_points * 1.0000001; n *= 10) {
    if (!o.quiet) std::cerr << "bench-sweep-memory: " << fmt(n) << " points ...\n";
    runs.push_back(run_size(self, dir, static_cast<std::size_t>(n), o));
    if (!o.quiet)
      std::cerr << "  done " << runs.back().done << (runs.back().completed ? " (complete)" : " (stopped)") << ", peak RSS "
                << fixed(runs.back().peak_mb, 1) << " MB, " << fixed(runs.back().wall, 1) << " s\n";
  }
  std::error_code ec;
  fs::remove_all(dir, ec);

  const Columns cols = columns("bench_sweep_memory");
  std::vector<std::vector<std::string>> rows;
  std::vector<double> growths;
  const Run& base = runs.front();
  for (const auto& r : runs) {
    const double growth = r.done > base.done ? (r.peak_mb - base.peak_mb) * 1048576.0 / double(r.done - base.done)
                                             : std::nan("");
    growths.push_back(growth);
    rows.push_back({std::to_string(r.planned), std::to_string(r.done), r.completed ? "yes" : "no", csv_number(r.wall),
                    csv_number(r.cpu), csv_number(double(r.done) / r.wall), csv_number(r.peak_mb), csv_number(growth)});
  }
  const fs::path csv = out / "sweep_memory.csv";
  write_csv_atomic(csv, cols, rows);

  const fs::path png = out / "sweep_memory.png";
  const std::string plot_note = plot_skipped(o.no_plot);
  if (plot_note.empty()) {
    std::ostringstream b;
    b << "set title 'nanopush sweep --task friction: peak resident memory against points' noenhanced\n"
      << "set xlabel 'points of the grid' noenhanced\nset ylabel 'peak RSS (MB)' noenhanced\nset logscale x\n"
      << "set grid\nset key outside bottom center horizontal\nset yrange [0:*]\n"
      << "plot '" << csv.string() << "' skip 1 using 1:7 with linespoints lw 2 pt 7 title 'peak RSS', \\\n"
      << "     " << kRssTargetMb << " with lines dt 2 lc rgb 'black' title 'target (200 MB)'\n";
    plot::render_script(b.str(), png, 900, 600);
  }

  const Run& last = runs.back();
  std::ostringstream md;
  md << "# Sweep memory benchmark\n\n`nanopush bench-sweep-memory`: `nanopush sweep --task friction` over R x alpha "
     << "grids of 10^3 to " << fmt(o.max_points) << " points, `--jobs " << o.jobs << "`, each a process of its own; "
     << "peak RSS from wait4(). A run longer than " << fmt(o.time_limit)
     << " s is stopped with SIGINT (the sweep keeps its journal) and reported with the points it did.\n\n"
     << "| points | done | complete | wall (s) | CPU (s) | points/s | peak RSS (MB) | growth (B/point) |\n"
     << "|---|---|---|---|---|---|---|---|\n";
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const auto& r = runs[k];
    md << "| " << r.planned << " | " << r.done << " | " << (r.completed ? "yes" : "no") << " | " << fixed(r.wall, 1)
       << " | " << fixed(r.cpu, 1) << " | " << fixed(double(r.done) / r.wall, 0) << " | " << fixed(r.peak_mb, 1) << " | "
       << (std::isnan(growths[k]) ? std::string("–") : fixed(growths[k], 2)) << " |\n";
  }
  md << "\n| target | measured | |\n|---|---|---|\n"
     << "| peak RSS of the " << last.planned << "-point grid < " << kRssTargetMb << " MB | " << fixed(last.peak_mb, 1)
     << " MB after " << last.done << " points" << (last.completed ? "" : " (stopped at the time limit)") << " | "
     << (last.peak_mb < kRssTargetMb ? "met" : "**NOT met**") << " |\n\nFiles: `sweep_memory.csv` (sidecar "
     << "`sweep_memory.schema.json`)" << (plot_note.empty() ? ", `sweep_memory.png`:\n\n![peak RSS against points](sweep_memory.png)\n" : "; " + plot_note + ".\n");
  write_and_print_report(out / "sweep_memory.md", md.str());
  return 0;
}

RegisterCommand reg{
    {"bench-sweep-memory",
     "Benchmark of a sweep's memory: peak RSS of `nanopush sweep --task friction` against the number of points "
     "(10^3 to 10^7), each run a process; CSV, PNG and sweep_memory.md (docs/performance.md)",
     92, options_then<MemOptions>(bench_memory, [](CLI::App& app, MemOptions& o) {
       app.add_option("--out", o.out, "output directory: sweep_memory.csv (+ .schema.json), sweep_memory.png, sweep_memory.md")
           ->capture_default_str();
       app.add_option("--max-points", o.max_points, "the largest grid (10^3, 10^4, ... up to this)")->capture_default_str();
       app.add_option("--time-limit", o.time_limit, "seconds a run may take before SIGINT stops it")
           ->check(CLI::Range(1.0, 86400.0))
           ->capture_default_str();
       app.add_option("--jobs", o.jobs, "threads of each sweep")->check(count(1, 1024))->capture_default_str();
       app.add_flag("--no-plot", o.no_plot, "no PNG (the CSV and report only)");
       app.add_flag("--quiet", o.quiet, "no progress on standard error");
     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
