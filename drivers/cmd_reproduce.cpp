// nanopush reproduce: every thesis table and figure the project reproduces, both engines,
// into one directory with a Markdown report. Steps are registered by the cmd_*.cpp files.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <iostream>
#include <mutex>
#include <thread>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "cli_checks.hpp"
#include "interrupt.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct Options {
  std::string out = "out";
  std::vector<std::string> only;
  bool quick = false;
  bool list = false;
  bool no_bench = false;  ///< thesis content only: skip the work-precision benchmarks (bench_*)
  int jobs = 0;           ///< steps run at once (0: the machine's cores)
  std::string format = "png";  ///< figure format: png | svg | pdf
};

bool is_benchmark(const std::string& step) { return step.rfind("bench_", 0) == 0; }

int run_reproduce(const Options& o) {
  auto steps = reproduce_steps();
  std::stable_sort(steps.begin(), steps.end(), [](auto& a, auto& b) { return a.order < b.order; });
  if (o.list) {
    for (auto& s : steps) std::cout << s.name << "\t" << s.description << "\n";
    return 0;
  }
  for (auto& name : o.only) {
    if (std::none_of(steps.begin(), steps.end(), [&](auto& s) { return s.name == name; })) {
      std::string names;
      for (auto& s : steps) names += (names.empty() ? "" : ", ") + s.name;
      throw InputError("--only", name, "must be one of: " + names);
    }
  }
  plot::set_format(plot::parse_format(o.format));
  ReproduceContext ctx;
  ctx.out = o.out;
  ctx.quick = o.quick;
  std::filesystem::create_directories(ctx.out);
  // While it runs the directory says it is not a reproduction: INCOMPLETE exists and a
  // report.md of an earlier run is gone; report.md is written last, then INCOMPLETE removed.
  const auto marker = ctx.out / "INCOMPLETE";
  write_file_atomic(marker, "nanopush reproduce is writing this directory (or was interrupted): it is not a complete\n"
                            "reproduction. Command: " + provenance().command + "\nRun it again; report.md appears and "
                            "this file goes when every step has run.\n");
  std::error_code ec;
  std::filesystem::remove(ctx.out / "report.md", ec);
  set_interrupt_note(ctx.out.string() + " is incomplete (" + marker.string() + " says so); run reproduce again");
  ctx.report << "# nanopush reproduce\n\n"
             << "Every table and figure below is computed by `nanopush reproduce` from the code in this\n"
             << "repository (C++ engine and FORTRAN 77 engine); nothing is pasted from the thesis except\n"
             << "the printed values we compare against, which are labelled as such.\n\n";
  const auto t_all = std::chrono::steady_clock::now();
  const auto selected = [&](const std::string& name) {
    if (o.no_bench && is_benchmark(name)) return false;
    return o.only.empty() || std::find(o.only.begin(), o.only.end(), name) != o.only.end();
  };
  std::vector<const ReproduceStep*> run;
  for (auto& s : steps)
    if (selected(s.name)) run.push_back(&s);
  // Independent steps run at once, each into its own context (report section, files,
  // failures); the report joins them in step order, so it reads the same for any --jobs.
  // The benchmarks (single-threaded) and the rough figures start first; with --jobs at most the
  // machine's cores no two steps share a core, but a benchmark's wall times are then taken
  // beside other work (--jobs 1 measures on an otherwise idle process).
  const std::size_t n = run.size();
  std::vector<ReproduceContext> parts(n);
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < n; ++k) order[k] = k;
  // Longest first (ReproduceStep::cost_s), then in step order.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    if (run[i]->cost_s != run[j]->cost_s) return run[i]->cost_s > run[j]->cost_s;
    return run[i]->order < run[j]->order;
  });
  std::atomic<std::size_t> next{0};
  std::mutex print;
  std::size_t done = 0;
  const auto worker = [&] {
    for (std::size_t q; (q = next.fetch_add(1)) < n;) {
      const std::size_t k = order[q];
      const ReproduceStep& s = *run[k];
      ReproduceContext& part = parts[k];
      part.out = ctx.out;
      part.quick = ctx.quick;
      const auto t0 = std::chrono::steady_clock::now();
      try {
        s.run(part);
      } catch (const std::exception& e) {
        part.failures.push_back(s.name + ": " + e.what());
        part.report << "\n**Step `" << s.name << "` failed:** " << e.what() << "\n";
      }
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::lock_guard<std::mutex> lock(print);
      std::cerr << "[" << ++done << "/" << n << "] " << s.name << ": " << s.description
                << (part.failures.empty() ? " done" : " FAILED") << " (" << dt << " s)\n";
    }
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t jobs = std::min<std::size_t>(n, o.jobs > 0 ? static_cast<std::size_t>(o.jobs) : cores);
  std::cerr << "reproduce: " << n << " steps, " << std::max<std::size_t>(jobs, 1) << " at a time\n";
  {
    std::vector<std::jthread> pool;
    for (std::size_t j = 1; j < jobs; ++j) pool.emplace_back(worker);
    worker();
  }
  for (auto& part : parts) {
    ctx.report << part.report.str();
    ctx.files.insert(ctx.files.end(), part.files.begin(), part.files.end());
    ctx.failures.insert(ctx.failures.end(), part.failures.begin(), part.failures.end());
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_all).count();
  ctx.report << "\n## Files\n\n";
  for (auto& f : ctx.files) {
    // A step that names its figure "x.png" got figure_path("x.png") under --format svg|pdf.
    const auto g = f.extension() == ".png" && !std::filesystem::exists(f) ? plot::figure_path(f) : f;
    ctx.report << "- `" << std::filesystem::relative(g, ctx.out).string() << "`\n";
  }
  ctx.report << "\nWall time of this reproduce run: " << total << " s.\n";
  if (!ctx.failures.empty()) {
    ctx.report << "\n## Checks that failed\n\n";
    for (auto& f : ctx.failures) ctx.report << "- " << f << "\n";
  }
  std::string report = ctx.report.str();
  if (plot::format() != plot::Format::png) {  // image links of steps that name "x.png"
    const std::string to = "." + plot::extension(plot::format()) + ")";
    for (std::size_t p = report.find(".png)"); p != std::string::npos; p = report.find(".png)", p + to.size()))
      report.replace(p, 5, to);
  }
  write_file_atomic(ctx.out / "report.md", report);
  std::filesystem::remove(marker, ec);
  set_interrupt_note("");
  std::cerr << "reproduce: " << ctx.files.size() << " files and report.md in " << ctx.out.string() << " ("
            << total << " s)\n";
  if (!ctx.failures.empty()) {
    std::cerr << "reproduce: " << ctx.failures.size() << " check(s) failed:\n";
    for (auto& f : ctx.failures) std::cerr << "  " << f << "\n";
    return 4;
  }
  return 0;
}

RegisterCommand reg{{"reproduce",
                     "Regenerate every thesis table and figure (both engines) into a directory, with report.md",
                     90, options_then<Options>(run_reproduce, [](CLI::App& app, Options& o) {
                       app.add_option("--out", o.out, "output directory")->capture_default_str();
                       app.add_option("--only", o.only, "run only these steps (see --list)");
                       app.add_flag("--quick", o.quick, "fewer samples per figure (for tests)");
                       app.add_flag("--list", o.list, "list the steps and exit");
                       app.add_option("--jobs,-j", o.jobs,
                                      "steps run at once (default 0: the machine's cores; 1 times the benchmarks "
                                      "on an otherwise idle process)")
                           ->check(count(0, 1024))
                           ->capture_default_str();
                       app.add_option("--format", o.format, "figure format: png, svg or pdf (a .gp script beside "
                                                             "each figure re-runs it)")
                           ->capture_default_str();
                       app.add_flag("--no-bench", o.no_bench,
                                    "thesis content only: skip the work-precision benchmarks (the bench_* steps, most "
                                    "of the run time)");
                     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
