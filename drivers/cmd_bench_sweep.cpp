// nanopush bench-sweep: how fast the sweep machinery runs a grid of rough-surface scenes
// (points/s) on 1 and 2 threads in one process and on 1 and 2 MPI ranks (mpirun, one thread
// per rank), its overhead over evaluating the points alone, and the parallel efficiency.
// A benchmark, never a timed test: every configuration's table must equal the 1-thread table
// byte for byte (otherwise the driver fails), and the targets are reported, not asserted.
// docs/sweeps.md ("Benchmark") documents the results.
#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <thread>
#include <tuple>
#include <utility>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/sweeps/sweep.hpp"
#include "bench_process.hpp"
#include "bench_report.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "scene_args.hpp"
#include "sweep_mpi.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

using Clock = std::chrono::steady_clock;

constexpr double kOverheadTarget = 0.02;   // (wall - sum of point times) / sum of point times
constexpr double kEfficiencyTarget = 0.9;  // (points/s at N) / (N x points/s at 1)
constexpr double kCpuEfficiencyTarget = 0.95;  // CPU of the points alone / CPU of the run (every rank)
constexpr double kIdleRankTarget = 0.01;  // CPU time / wall time of a rank waiting for the others
constexpr const char* kScene = "fig3_18";
constexpr const char* kLaw = "surface.law=coulomb";

struct BenchSweepOptions {
  std::string out = "bench_sweep";
  int repeats = 3;
  int per_axis = 10;
  bool no_mpi = false, no_plot = false, quiet = false;
};

/// The grid: mu x push offset x push angle, K values each (K^3 points).
std::vector<std::string> axis_specs(int k) {
  const std::string n = std::to_string(k);
  return {"surface.mu=0.02:0.2:" + n, "push.yn=0:45e-9:" + n, "push.direction=0:0.5:" + n};
}

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// CPU time (user + system, s) of this process's threads and of its waited-for children.
double cpu_seconds() {
  double t = 0;
  for (int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    if (::getrusage(who, &u) != 0) continue;
    t += static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return t;
}

std::string load_text(const std::array<double, 3>& a) {
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << a[0] << " " << a[1] << " " << a[2];
  return s.str();
}

std::string fixed(double v, int digits) {
  if (!std::isfinite(v)) return "n/a";
  std::ostringstream s;
  s << std::fixed << std::setprecision(digits) << v;
  return s.str();
}

std::string read_file(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  if (!in) throw std::runtime_error("bench-sweep: cannot read " + p.string());
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// An executable `name` on PATH, or empty.
fs::path find_on_path(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (!path) return {};
  std::stringstream ss(path);
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const fs::path c = fs::path(dir.empty() ? "." : dir) / name;
    std::error_code ec;
    if (fs::is_regular_file(c, ec) && ::access(c.c_str(), X_OK) == 0) return c;
  }
  return {};
}

/// Run argv (spawn_logged) and wait for it. Returns the exit status (128 + signal when killed).
int spawn_and_wait(const std::vector<std::string>& argv, const std::vector<std::string>& extra_env, const fs::path& log) {
  const pid_t pid = spawn_logged(argv, extra_env, log, "bench-sweep");
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("bench-sweep: waitpid failed for " + argv[0]);
  }
  return exit_status(status);
}

/// The MPI rank (OMPI_COMM_WORLD_RANK in its environment) of a child of process `parent`, and
/// its CPU time (user + system, clock ticks) from /proc; rank -1 where unreadable.
struct RankSample {
  int rank = -1;
  long long ticks = 0;
};
std::vector<RankSample> rank_samples(pid_t parent) {
  std::vector<RankSample> out;
  std::error_code ec;
  for (const auto& e : fs::directory_iterator("/proc", ec)) {
    const std::string name = e.path().filename().string();
    if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
    std::ifstream st(e.path() / "stat");
    std::string line;
    if (!std::getline(st, line)) continue;
    const auto close = line.rfind(')');  // the command name may hold spaces
    if (close == std::string::npos) continue;
    std::istringstream f(line.substr(close + 2));
    std::vector<std::string> v;  // from field 3 (state) on
    for (std::string x; f >> x && v.size() < 13;) v.push_back(x);
    if (v.size() < 13 || std::atoll(v[1].c_str()) != parent) continue;
    RankSample r;
    r.ticks = std::atoll(v[11].c_str()) + std::atoll(v[12].c_str());  // utime + stime
    std::ifstream env(e.path() / "environ", std::ios::binary);
    for (std::string kv; std::getline(env, kv, '\0');)
      if (kv.rfind("OMPI_COMM_WORLD_RANK=", 0) == 0) r.rank = std::atoi(kv.c_str() + 21);
    if (r.rank >= 0) out.push_back(r);
  }
  return out;
}

/// A waiting rank's CPU: `mpirun -np 2 nanopush-mpi sweep` of one slow point (rank 0's thread
/// computes it; rank 1, given no work, waits for the exit status), rank 1's CPU time over the
/// wall time from the journal's appearance (every rank past MPI_Init) to the last look before
/// the job ends, read from /proc every 50 ms. Returns (share of a core, seconds watched);
/// NaN when the job was too short to watch.
std::pair<double, double> idle_rank_cpu(const fs::path& mpirun, const fs::path& mpi_exe,
                                        const std::vector<std::string>& env, const fs::path& dir) {
  const fs::path table = dir / "idle.csv", log = dir / "idle.log";
  const std::vector<std::string> argv = {
      mpirun.string(), "--oversubscribe", "-np", "2", mpi_exe.string(), "sweep", kScene, "--set", kLaw,
      "--set", "solver.t_end=3e-5", "--set", "solver.max_steps=100000000", "--set", "solver.samples=3",
      "--vary", "surface.mu=0.02", "--no-error-estimate", "--task", "run", "--jobs", "1", "--quiet", "--out",
      table.string()};
  const pid_t pid = spawn_logged(argv, env, log, "bench-sweep");
  const long hz = ::sysconf(_SC_CLK_TCK);
  bool watching = false;
  long long t0 = 0, t1 = 0;
  Clock::time_point w0{}, w1{};
  int status = 0;
  for (;;) {
    const pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) throw std::runtime_error("bench-sweep: waitpid failed for mpirun");
    std::error_code ec;
    if (fs::exists(fs::path(table.string() + ".journal"), ec)) {
      for (const auto& r : rank_samples(pid)) {
        if (r.rank != 1) continue;
        if (!watching) {
          watching = true;
          t0 = r.ticks;
          w0 = Clock::now();
        }
        t1 = r.ticks;
        w1 = Clock::now();
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (exit_status(status) != 0)
    throw std::runtime_error("bench-sweep: the idle-rank sweep exited with " + std::to_string(exit_status(status)) +
                             "; its output:\n" + read_file(log));
  const double seconds = std::chrono::duration<double>(w1 - w0).count();
  if (!watching || seconds < 0.5) return {std::numeric_limits<double>::quiet_NaN(), seconds};
  return {static_cast<double>(t1 - t0) / static_cast<double>(hz) / seconds, seconds};
}

/// A timing the sweep recorded in its sidecar ("run": {"wall_s": ..., "cpu_s": ...}).
double sidecar_number(const fs::path& table, const std::string& name) {
  const std::string j = read_file(schema_path(table));
  const std::string key = "\"" + name + "\": ";
  const auto at = j.find(key);
  if (at == std::string::npos)
    throw std::runtime_error("bench-sweep: no run." + name + " in " + schema_path(table).string());
  return std::strtod(j.c_str() + at + key.size(), nullptr);
}

/// One measured configuration.
struct Config {
  std::string mode;  ///< direct | threads | mpi
  unsigned threads = 1, ranks = 1;
  std::vector<double> walls;  ///< one per repeat (direct: the sum of the points' own times)
  std::vector<double> launches;  ///< mpi: mpirun -np RANKS nanopush-mpi --version, one per repeat
  std::vector<double> mpirun_walls;  ///< mpi: mpirun from launch to exit, one per repeat
  std::vector<double> cpus;      ///< CPU time of the run (all threads and processes), one per repeat
  double load1 = std::numeric_limits<double>::quiet_NaN();
  [[nodiscard]] unsigned workers() const { return threads * ranks; }
};

/// Temporary directory for the tables of the runs (removed at the end unless a check failed).
struct TempDir {
  fs::path path;
  bool keep = false;
  TempDir() {
    std::string tmpl = (fs::temp_directory_path() / "nanopush-bench-sweep-XXXXXX").string();
    if (!::mkdtemp(tmpl.data())) throw std::runtime_error("bench-sweep: cannot create a temporary directory");
    path = tmpl;
  }
  ~TempDir() {
    std::error_code ec;
    if (!keep) fs::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

int bench_sweep(const BenchSweepOptions& o) {
  if (o.repeats < 1) throw InputError("--repeats", std::to_string(o.repeats), "must be >= 1");
  const auto load_start = load_average();
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());

  // The plan and the task, exactly as `nanopush sweep fig3_18 --set ... --vary ...` builds them.
  const auto specs = axis_specs(o.per_axis);
  Scene sc = load_scene_arg(kScene, {kLaw});
  set_provenance_scene(kScene);
  RunSettings rs;
  rs.error_estimate = false;  // the throughput of plain points (docs/performance.md)
  (void)resolve_settings(sc, rs);
  const auto task = sweep::make_run_task(sc, rs);
  std::vector<sweep::Axis> axes;
  for (const auto& s : specs) axes.push_back(sweep::parse_axis(s, false));
  const sweep::Plan plan = sweep::cartesian(axes);
  const std::size_t n = plan.size();
  const auto columns = sweep::table_columns(plan, *task);

  // MPI: mpirun on PATH and nanopush-mpi (the command line with MPI) beside this executable.
  fs::path mpirun;
  std::string mpi_note;
  const fs::path mpi_exe = executable_dir() / kMpiProgram;
  std::error_code mpi_ec;
  if (o.no_mpi) {
    mpi_note = "MPI configurations skipped (--no-mpi)";
  } else if (!fs::is_regular_file(mpi_exe, mpi_ec)) {
    mpi_note = std::string("MPI configurations skipped: no ") + kMpiProgram + " beside this nanopush (NANOPUSH_MPI=OFF)";
  } else {
    mpirun = find_on_path("mpirun");
    if (mpirun.empty()) mpi_note = "MPI configurations skipped: no mpirun on PATH";
  }

  TempDir tmp;
  const fs::path out_dir = o.out;
  fs::create_directories(out_dir);
  if (!o.quiet) {
    std::cerr << "bench-sweep: " << n << " points (" << kScene << ", " << kLaw;
    for (const auto& s : specs) std::cerr << ", " << s;
    std::cerr << "), task run, " << o.repeats << " repeats; host: " << cores << " cores, load average "
              << load_text(load_start) << "\n";
    if (!mpi_note.empty()) std::cerr << "bench-sweep: " << mpi_note << "\n";
  }

  // Configurations, measured interleaved (repeat r of every configuration before repeat r+1)
  // so that a change in the host's load touches every configuration alike.
  std::vector<Config> configs;
  auto add = [&](const char* mode, unsigned threads, unsigned ranks) {
    Config c;
    c.mode = mode;
    c.threads = threads;
    c.ranks = ranks;
    configs.push_back(std::move(c));
  };
  add("threads", 1, 1);
  add("direct", 1, 1);
  add("threads", 2, 1);
  if (!mpirun.empty()) {
    add("mpi", 1, 1);
    add("mpi", 1, 2);
  }

  std::string reference;  // the 1-thread table (CSV bytes)
  std::size_t failed_points = 0;
  auto check_same = [&](const std::string& text, const std::string& what, const fs::path& file) {
    if (text == reference) return;
    tmp.keep = true;
    throw std::runtime_error("bench-sweep: the table of " + what + " differs from the 1-thread table (" +
                             (file.empty() ? std::string("in memory") : file.string()) + " vs " +
                             (tmp.path / "threads1_r0.csv").string() +
                             "): the sweep got different answers; the tables are kept in " + tmp.path.string());
  };

  // Warm-up (not timed): page in the code and the scene's first evaluations.
  for (std::size_t i = 0; i < std::min<std::size_t>(n, 3); ++i) (void)sweep::evaluate_row(plan, *task, i);

  for (int r = 0; r < o.repeats; ++r) {
    for (auto& c : configs) {
      const std::string tag = c.mode + std::to_string(c.mode == "mpi" ? c.ranks : c.threads) + "_r" + std::to_string(r);
      const fs::path table = tmp.path / (tag + ".csv");
      double wall = 0, cpu = 0;
      if (c.mode == "direct") {
        // The points alone: evaluate_row on this thread, each call timed, the times summed.
        std::vector<std::vector<std::string>> rows;
        rows.reserve(n);
        const double c0 = cpu_seconds();
        for (std::size_t i = 0; i < n; ++i) {
          const auto t0 = Clock::now();
          auto row = sweep::evaluate_row(plan, *task, i);
          wall += seconds_since(t0);
          rows.push_back(std::move(row));
        }
        cpu = cpu_seconds() - c0;
        check_same(csv_document(columns, rows), "the points evaluated alone (evaluate_row)", {});
      } else if (c.mode == "threads") {
        sweep::Options opt;
        opt.jobs = c.threads;
        opt.out = table;
        const double c0 = cpu_seconds();
        const auto t0 = Clock::now();
        const auto res = sweep::run_local(plan, *task, opt);
        wall = seconds_since(t0);
        cpu = cpu_seconds() - c0;
        if (!res.complete || res.done != n)
          throw std::runtime_error("bench-sweep: the " + tag + " sweep did not complete");
        const std::string text = read_file(table);
        if (reference.empty()) {
          reference = text;
          failed_points = res.failed;
        }
        check_same(text, std::to_string(c.threads) + " threads (repeat " + std::to_string(r + 1) + ")", table);
      } else {
        std::vector<std::string> argv = {mpirun.string(), "--oversubscribe", "-np", std::to_string(c.ranks),
                                         mpi_exe.string(), "sweep", kScene, "--set", kLaw};
        for (const auto& s : specs) {
          argv.push_back("--vary");
          argv.push_back(s);
        }
        // The same settings as the in-process runs (rs.error_estimate = false above).
        for (const char* a : {"--no-error-estimate", "--task", "run", "--jobs", "1", "--quiet", "--out"})
          argv.emplace_back(a);
        argv.push_back(table.string());
        std::vector<std::string> env;
        if (::geteuid() == 0) env = {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"};
        const fs::path log = tmp.path / (tag + ".log");
        {
          // The launch alone (mpirun starting RANKS processes that do nothing), for the report.
          const auto l0 = Clock::now();
          const int lrc = spawn_and_wait({mpirun.string(), "--oversubscribe", "-np", std::to_string(c.ranks),
                                          mpi_exe.string(), "--version"},
                                         env, log);
          if (lrc != 0) {
            tmp.keep = true;
            throw std::runtime_error("bench-sweep: mpirun -np " + std::to_string(c.ranks) +
                                     " nanopush-mpi --version exited with " + std::to_string(lrc) + "; its output:\n" +
                                     read_file(log));
          }
          c.launches.push_back(seconds_since(l0));
        }
        const auto t0 = Clock::now();
        const int rc = spawn_and_wait(argv, env, log);
        c.mpirun_walls.push_back(seconds_since(t0));
        // Open MPI's ranks are reaped by its launcher daemon, not always by mpirun (this
        // process's RUSAGE_CHILDREN may miss them): the sweep records every rank's CPU time
        // (process start to its last row) in its sidecar.
        // The sweep's exit status: 0, or 64 + the number of failed points (sweep_exit_status).
        const int expected = sweep_exit_status(failed_points);
        std::error_code ec;
        if (rc != expected || !fs::exists(table, ec)) {
          tmp.keep = true;
          throw std::runtime_error("bench-sweep: mpirun -np " + std::to_string(c.ranks) + " ... sweep exited with " +
                                   std::to_string(rc) + " (expected " + std::to_string(expected) + "); its output:\n" +
                                   (fs::exists(log, ec) ? read_file(log) : std::string("(no log)")));
        }
        check_same(read_file(table), std::to_string(c.ranks) + " MPI ranks (repeat " + std::to_string(r + 1) + ")",
                   table);
        // The sweep's own time (rank 0, MPI_Init to the table), like the threads' run_local:
        // without the process launch and without mpirun's ending of the job, which takes ~2 s
        // whenever a rank exits non-zero (here: 64 + the failed points).
        wall = sidecar_number(table, "wall_s");
        cpu = sidecar_number(table, "cpu_s");
      }
      c.walls.push_back(wall);
      c.cpus.push_back(cpu);
      c.load1 = load_average()[0];
      if (!o.quiet)
        std::cerr << "bench-sweep: repeat " << (r + 1) << "/" << o.repeats << " " << std::left << std::setw(8)
                  << c.mode << std::right << " threads " << c.threads << " ranks " << c.ranks << ": "
                  << fixed(wall, 3) << " s, " << fixed(static_cast<double>(n) / wall, 1)
                  << " points/s, CPU " << fixed(cpu, 3) << " s (load " << fixed(c.load1, 2) << ")\n";
      // Only the first table of each kind is kept until the end (the reference); drop the rest.
      std::error_code ec;
      if (tag != "threads1_r0") fs::remove(table, ec);
      fs::remove(schema_path(table), ec);
    }
  }
  // MPI alone, without the points: the fixed CPU of a job (every rank's process start-up,
  // MPI_Init, the scene, the table), from a sweep of the grid's first point, less that point's
  // own CPU; and a waiting rank's CPU (idle_rank_cpu).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double startup_m2 = nan, idle_share = nan, idle_seconds = 0;
  if (!mpirun.empty()) {
    std::vector<std::string> env;
    if (::geteuid() == 0) env = {"OMPI_ALLOW_RUN_AS_ROOT=1", "OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1"};
    std::vector<double> fixed_cpu;
    const double c0 = cpu_seconds();
    (void)sweep::evaluate_row(plan, *task, 0);
    const double point0 = cpu_seconds() - c0;
    for (int r = 0; r < o.repeats; ++r) {
      const fs::path table = tmp.path / "startup.csv", log = tmp.path / "startup.log";
      const int rc = spawn_and_wait({mpirun.string(), "--oversubscribe", "-np", "2", mpi_exe.string(), "sweep", kScene,
                                     "--set", kLaw, "--vary", "surface.mu=0.02", "--no-error-estimate", "--task", "run",
                                     "--jobs", "1", "--quiet", "--out", table.string()},
                                    env, log);
      if (rc != 0) {
        tmp.keep = true;
        throw std::runtime_error("bench-sweep: the one-point MPI sweep exited with " + std::to_string(rc) +
                                 "; its output:\n" + read_file(log));
      }
      fixed_cpu.push_back(sidecar_number(table, "cpu_s") - point0);
    }
    startup_m2 = median(fixed_cpu);
    std::tie(idle_share, idle_seconds) = idle_rank_cpu(mpirun, mpi_exe, env, tmp.path);
    if (!o.quiet)
      std::cerr << "bench-sweep: MPI start-up, 2 ranks: CPU " << fixed(startup_m2, 3) << " s; a waiting rank: "
                << fixed(100 * idle_share, 2) << " % of a core over " << fixed(idle_seconds, 1) << " s\n";
  }
  const auto load_end = load_average();

  // ---- figures
  auto find = [&](const std::string& mode, unsigned threads, unsigned ranks) -> const Config* {
    for (const auto& c : configs)
      if (c.mode == mode && c.threads == threads && c.ranks == ranks) return &c;
    return nullptr;
  };
  auto pps = [&](const Config* c) {
    return c ? static_cast<double>(n) / median(c->walls) : std::numeric_limits<double>::quiet_NaN();
  };
  const Config* t1 = find("threads", 1, 1);
  const Config* t2 = find("threads", 2, 1);
  const Config* m1 = find("mpi", 1, 1);
  const Config* m2 = find("mpi", 1, 2);
  const Config* direct = find("direct", 1, 1);
  const double eff_t2 = pps(t2) / (2 * pps(t1));
  const double eff_m2 = m1 && m2 ? pps(m2) / (2 * pps(m1)) : nan;
  // Overhead: per repeat, the 1-thread sweep against the points alone measured right after it
  // (a change of the host's load between repeats cancels), the median over the repeats; and
  // the same in CPU time (insensitive to how much of a core the host gave the run).
  std::vector<double> paired, paired_cpu;
  for (std::size_t r = 0; r < t1->walls.size(); ++r) {
    paired.push_back((t1->walls[r] - direct->walls[r]) / direct->walls[r]);
    paired_cpu.push_back((t1->cpus[r] - direct->cpus[r]) / direct->cpus[r]);
  }
  const double overhead = median(paired), overhead_cpu = median(paired_cpu);
  // CPU-time efficiency: CPU at 1 worker / CPU at N (1 when parallel work costs no extra CPU).
  const double cpu_eff_t2 = median(t1->cpus) / median(t2->cpus);
  // CPU efficiency of a configuration: the points' own CPU (direct) / the run's CPU, every
  // thread and rank (1 when nothing but the points costs CPU: no polling, no machinery).
  auto cpu_eff = [&](const Config* c) { return c ? median(direct->cpus) / median(c->cpus) : nan; };
  const double cpu_eff_m2 = cpu_eff(m2);

  // ---- the CSV (and its sidecar)
  const Columns cols = cli::columns("bench_sweep");  // (a local `columns` is in scope)
  std::vector<std::vector<std::string>> rows;
  // Order: threads, mpi, direct (the plot's series read contiguous rows).
  std::vector<const Config*> order;
  for (const char* mode : {"threads", "mpi", "direct"})
    for (const auto& c : configs)
      if (c.mode == mode) order.push_back(&c);
  for (const Config* c : order) {
    const double p = pps(c);
    double eff = nan;
    if (c->mode == "threads") eff = p / (c->workers() * pps(t1));
    if (c->mode == "mpi") eff = p / (c->workers() * pps(m1));
    rows.push_back({csv_quote(c->mode), std::to_string(c->threads), std::to_string(c->ranks),
                    std::to_string(c->workers()), std::to_string(n), std::to_string(c->walls.size()),
                    csv_number(median(c->walls)), csv_number(*std::min_element(c->walls.begin(), c->walls.end())),
                    csv_number(*std::max_element(c->walls.begin(), c->walls.end())), csv_number(p), csv_number(eff),
                    csv_number(c->mode == "direct" ? overhead : nan),
                    csv_number(c->mode == "direct" ? overhead_cpu : nan), csv_number(median(c->cpus)),
                    csv_number(cpu_eff(c)),
                    csv_number(c->launches.empty() ? nan : median(c->launches)),
                    csv_number(c->mpirun_walls.empty() ? nan : median(c->mpirun_walls)), csv_number(c->load1)});
  }
  const fs::path csv = out_dir / "sweep_bench.csv";
  write_csv_atomic(csv, cols, rows, kScene);

  // ---- the plot: points/s against workers, threads and ranks, the ideal line dashed
  const fs::path png = out_dir / "sweep_bench.png";
  const std::string plot_note = plot_skipped(o.no_plot);
  if (plot_note.empty()) {
    auto q = [](const std::string& s) {
      std::string r = "'";
      for (char ch : s) r += ch == '\'' ? std::string("''") : std::string(1, ch);
      return r + "'";
    };
    const std::string f = q(csv.string());
    std::ostringstream b;
    b << "set title " << q("nanopush sweep: " + std::to_string(n) + " rough-surface points (" + kScene +
                           ", coulomb law), task run; median of " + std::to_string(o.repeats) +
                           (o.repeats == 1 ? " run" : " runs"))
      << " noenhanced\n"
      << "set xlabel 'workers (threads in one process, or MPI ranks of one thread)'\n"
      << "set ylabel 'points/s'\nset grid\nset key left top\nset xrange [0.8:2.2]\nset xtics 1\nset yrange [0:*]\n"
      << "P1 = " << csv_number(pps(t1)) << "\n"
      << "plot " << f
      << " skip 1 using (strcol(1) eq 'threads' ? $4 : 1/0):($5/$7):($5/$9):($5/$8) with yerrorlines lw 2 pt 7 "
         "title 'threads (one process)', \\\n";
    if (m1)
      b << "     " << f
        << " skip 1 using (strcol(1) eq 'mpi' ? $4 : 1/0):($5/$7):($5/$9):($5/$8) with yerrorlines lw 2 pt 5 "
           "title 'MPI ranks (mpirun -np R, one thread each)', \\\n";
    b << "     P1*x with lines dt 2 lw 1.5 lc rgb 'black' title 'ideal: workers x 1-thread rate'\n";
    plot::render_script(b.str(), png, 900, 600);
  }

  // ---- the report
  auto met = [](bool ok) { return ok ? std::string("met") : std::string("**NOT met**"); };
  std::ostringstream md;
  md << "# Sweep benchmark\n\n"
     << "`nanopush bench-sweep`: " << n << " points of " << kScene << " with `" << kLaw << "`, axes";
  for (const auto& s : specs) md << " `" << s << "`";
  md << " (the run task), median of " << o.repeats << (o.repeats == 1 ? " run" : " runs")
     << " per configuration. Host: " << cores
     << " cores; load average (1, 5, 15 min) " << load_text(load_start) << " at the start, " << load_text(load_end)
     << " at the end.";
  if (load_end[0] > cores || load_start[0] > cores)
    md << " The host was busy (load above its core count): the times and efficiencies understate an idle machine.";
  md << "\n\n"
     << "| mode | threads | ranks | wall (s, median) | min–max (s) | points/s | efficiency | CPU (s) | CPU efficiency | cores used | "
        "mpirun launch (s) | mpirun to exit (s) | load (1 min) |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Config* c : order) {
    const double p = pps(c);
    double eff = nan;
    if (c->mode == "threads") eff = p / (c->workers() * pps(t1));
    if (c->mode == "mpi") eff = p / (c->workers() * pps(m1));
    md << "| " << c->mode << " | " << c->threads << " | " << c->ranks << " | " << fixed(median(c->walls), 3) << " | "
       << fixed(*std::min_element(c->walls.begin(), c->walls.end()), 3) << "–"
       << fixed(*std::max_element(c->walls.begin(), c->walls.end()), 3) << " | " << fixed(p, 1) << " | "
       << (c->mode == "direct" ? std::string("–") : fixed(eff, 3)) << " | " << fixed(median(c->cpus), 3) << " | "
       << fixed(cpu_eff(c), 3) << " | " << fixed(median(c->cpus) / median(c->walls), 2) << " | "
       << (c->launches.empty() ? std::string("–") : fixed(median(c->launches), 3)) << " | "
       << (c->mpirun_walls.empty() ? std::string("–") : fixed(median(c->mpirun_walls), 3)) << " | " << fixed(c->load1, 2)
       << " |\n";
  }
  md << "\n`direct` is the sum of the points' own evaluation times (`sweep::evaluate_row` on one thread, "
        "no queue, journal or table); `mpi` is the sweep's own time as rank 0 records it in the table's sidecar "
        "(MPI_Init to the table written), as `threads` is `run_local`'s; the launch alone (`mpirun -np R nanopush-mpi "
        "--version`) and `mpirun` from launch to exit are in their own columns (mpirun takes ~2 s to end a job "
        "whose rank exits non-zero, as a sweep with failed points does). CPU is the run's CPU time (every thread; for MPI every rank's, as the sweep records it in its sidecar); cores used = "
        "CPU / wall, at most the worker count: below it, the host gave the run less than a core per worker.\n\n"
     << "| target | measured | |\n|---|---|---|\n"
     << "| sweep overhead (1 thread) <= " << fixed(100 * kOverheadTarget, 0) << " % | " << fixed(100 * overhead, 2)
     << " % (CPU time: " << fixed(100 * overhead_cpu, 2) << " %) | " << met(overhead <= kOverheadTarget) << " |\n"
     << "| machinery CPU (1 thread, CPU time over the points') <= " << fixed(100 * kOverheadTarget, 0) << " % | "
     << fixed(100 * overhead_cpu, 2) << " % | " << met(overhead_cpu <= kOverheadTarget) << " |\n"
     << "| parallel efficiency, 2 threads >= " << fixed(kEfficiencyTarget, 2) << " | " << fixed(eff_t2, 3)
     << " (CPU time: " << fixed(cpu_eff_t2, 3) << ") | "
     << met(eff_t2 >= kEfficiencyTarget) << " |\n";
  md << "| CPU efficiency (points' CPU / the run's CPU): 1 thread, 2 threads" << (m1 ? ", 1 MPI rank, 2 MPI ranks" : "")
     << " | " << fixed(cpu_eff(t1), 3) << ", " << fixed(cpu_eff(t2), 3);
  if (m1) md << ", " << fixed(cpu_eff(m1), 3) << ", " << fixed(cpu_eff(m2), 3);
  md << " | |\n";
  if (m2)
    md << "| parallel efficiency, 2 MPI ranks >= " << fixed(kEfficiencyTarget, 2) << " | " << fixed(eff_m2, 3)
       << " | " << met(eff_m2 >= kEfficiencyTarget) << " |\n"
       << "| CPU efficiency, 2 MPI ranks (points' CPU / every rank's CPU) >= " << fixed(kCpuEfficiencyTarget, 2)
       << " | " << fixed(cpu_eff_m2, 3) << " (without the job's fixed start-up, " << fixed(startup_m2, 3)
       << " s CPU for 2 ranks: " << fixed(median(direct->cpus) / (median(m2->cpus) - startup_m2), 3) << ") | "
       << met(cpu_eff_m2 >= kCpuEfficiencyTarget) << " |\n"
       << "| a waiting rank's CPU (rank 1 of 2 with no work, while rank 0 computes) <= "
       << fixed(100 * kIdleRankTarget, 0) << " % of a core | " << fixed(100 * idle_share, 2) << " % over "
       << fixed(idle_seconds, 1) << " s | " << met(idle_share <= kIdleRankTarget) << " |\n";
  else
    md << "| parallel efficiency, 2 MPI ranks >= " << fixed(kEfficiencyTarget, 2) << " | n/a | " << mpi_note
       << " |\n";
  md << "\nThe overhead is the median over the repeats of (1-thread sweep − points alone) / points alone, "
        "each pair measured back to back; a negative value means the host's noise exceeds the overhead. The "
        "CPU-time figures (overhead in CPU seconds; efficiency = CPU at 1 worker / CPU at 2) do not depend on how "
        "much of a core the host gave the run: a CPU-time efficiency near 1 with a low wall-time efficiency means "
        "the host, not the sweep, held the run back.\n";
  md << "\nEvery configuration's table equals the 1-thread table byte for byte (" << failed_points
     << " of " << n << " points failed).";
  if (!mpi_note.empty()) md << " " << mpi_note << ".";
  md << "\n\nFiles: `" << csv.filename().string() << "` (sidecar `" << schema_path(csv).filename().string() << "`)";
  if (plot_note.empty())
    md << ", `" << png.filename().string() << "`:\n\n![points/s against workers](" << png.filename().string() << ")\n";
  else
    md << "; " << plot_note << ".\n";
  write_and_print_report(out_dir / "report.md", md.str());
  return 0;
}

RegisterCommand reg{
    {"bench-sweep",
     "Benchmark of the sweep machinery: points/s of a rough-surface grid (fig3_18, coulomb law; mu x push offset x "
     "push angle) on 1 and 2 threads and 1 and 2 MPI ranks, the overhead over the points alone and the parallel "
     "efficiency; CSV, PNG and report.md (docs/sweeps.md)",
     91, options_then<BenchSweepOptions>(bench_sweep, [](CLI::App& app, BenchSweepOptions& o) {
       app.add_option("--out", o.out,
                      "output directory: sweep_bench.csv (+ .schema.json), sweep_bench.png (+ .gp), report.md")
           ->capture_default_str();
       app.add_option("--repeats", o.repeats, "timed runs per configuration; the median wall time (s) is reported")
           ->check(count(1, 100))
           ->capture_default_str();
       app.add_option("--points-per-axis", o.per_axis,
                      "values per axis K (K^3 points): surface.mu 0.02-0.2 (1), push.yn 0-45e-9 m, push.direction "
                      "0-0.5 rad")
           ->check(count(2, 40))
           ->capture_default_str();
       app.add_flag("--no-mpi", o.no_mpi, "skip the MPI configurations (mpirun -np 1 and 2)");
       app.add_flag("--no-plot", o.no_plot, "no PNG (the CSV and report only)");
       app.add_flag("--quiet", o.quiet, "no progress on standard error");
     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
