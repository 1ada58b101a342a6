// nanopush bench-atlas: a stability atlas (docs/accuracy.md, "Atlas"). Over two planes of the
// physical space, on log axes,
//   map mu_ratio:     friction coefficient mu x push F / (mu N)          (fig3_18 otherwise)
//   map length_force: object length (width 0.55 L, height 0.5 L) x push force  (mu = 0.06)
// each point run under the coulomb and the thesis law with an accuracy asked for (1e-8 by
// default): its outcome, the achieved error estimate over the accuracy asked and the RHS
// evaluations (the slowest point's wall time in the sidecar). Writes atlas.csv (+ sidecar),
// atlas_outcome.png, atlas_error.png, atlas_cost.png and atlas.md; also a reproduce step with a report section.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

#include "nanopush/engines/engines.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "bench_options.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct AtlasOptions : BenchDirectoryOptions {
  int points = 16;  ///< per axis
  double accuracy = 1e-8;
};

double log_point(double lo, double hi, int i, int n) {
  return n == 1 ? lo : std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * i / (n - 1));
}

struct MapSpec {
  std::string name, xkey, ykey, xlabel, ylabel;
  double xlo, xhi, ylo, yhi;
};

const std::vector<MapSpec>& maps() {
  static const std::vector<MapSpec> m = {
      {"mu_ratio", "mu", "F/(mu N)", "mu", "push F / (mu N)", 1e-3, 2.0, 0.1, 10.0},
      {"length_force", "length [m]", "force [N]", "object length L [m]", "push force [N]", 10e-9, 10e-6, 1e-12, 1e-3},
  };
  return m;
}

/// The scene of a point of a map.
Scene atlas_scene(const Scene& base, const MapSpec& m, double x, double y) {
  Scene sc = base;
  if (m.name == "mu_ratio") {
    sc.set("surface.mu", x);
    sc.set("push.force", y * sc.friction_limit());
  } else {
    sc.set({{"object.length", x},
            {"object.width", 0.55 * x},
            {"object.height", 0.5 * x},
            {"push.xn", 0.275 * x},
            {"push.yn", 0.45 * x},
            {"push.force", y}});
  }
  return sc;
}

struct Cell {
  std::map<std::string, int> outcomes;
  double worst_ratio = 0, max_wall = 0;
  std::vector<double> cost;
};

bool bench_atlas(const AtlasOptions& o, const fs::path& dir, std::ostream& md, ReproduceContext* ctx) {
  const Scene base = load_scene(resolve_scene("fig3_18"));
  CsvWriter w(dir / "atlas.csv",
              columns("bench_atlas"));
  std::map<std::string, Cell> cells;
  for (const MapSpec& m : maps())
    for (const Law law : {Law::coulomb, Law::thesis}) {
      Cell& c = cells[m.name + " / " + to_string(law)];
      for (int i = 0; i < o.points; ++i)
        for (int j = 0; j < o.points; ++j) {
          const double x = log_point(m.xlo, m.xhi, i, o.points), y = log_point(m.ylo, m.yhi, j, o.points);
          const Scene sc = atlas_scene(base, m, x, y);
          RunSettings rs;
          rs.law = law;
          rs.accuracy = o.accuracy;
          rs.allow_partial = true;
          const auto t0 = std::chrono::steady_clock::now();
          const Trajectory tr = run_engine(sc, rs);
          const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
          ++c.outcomes[to_string(tr.outcome)];
          c.max_wall = std::max(c.max_wall, wall);
          const double ratio = tr.error.norm / o.accuracy;
          if (is_answer(tr.outcome) && !std::isnan(ratio)) c.worst_ratio = std::max(c.worst_ratio, ratio);
          if (is_answer(tr.outcome)) c.cost.push_back(static_cast<double>(tr.nfcn_total()));
          w.cells({m.name, to_string(law), csv_number(x), csv_number(y), to_string(tr.outcome),
                   std::to_string(static_cast<int>(tr.outcome)), csv_number(tr.error.norm), csv_number(ratio),
                   csv_number(tr.rtol), std::to_string(tr.nfcn_total())});
        }
    }
  // Timings go to the sidecar, never into the table or the report (both are reproducible).
  RunInfo info;
  for (auto& [name, c] : cells) {
    std::string key = "slowest_point_s_" + name;
    for (char& ch : key)
      if (ch == ' ' || ch == '/') ch = '_';
    info.push_back({key, c.max_wall});
  }
  w.run_info(info);
  w.commit();
  const bool ok = true;
  md << "Two planes of the physical space on log axes, " << o.points << " x " << o.points
     << " points each, every point run with method auto and `--accuracy " << o.accuracy
     << "`: (mu 1e-3-2) x (push F / (mu N) 0.1-10) on fig3_18, and (object length 10 nm-10 um, width 0.55 L, "
        "height 0.5 L, push point scaled) x (push force 1e-12-1e-3 N) at mu = 0.06.\n\n"
     << "| map / law | ok | at_rest | no_static_friction | accuracy_not_reached | solver_failure | worst achieved / "
        "asked | median RHS evals |\n|---|---|---|---|---|---|---|---|\n";
  for (auto& [name, c] : cells) {
    std::sort(c.cost.begin(), c.cost.end());
    const double med = c.cost.empty() ? std::nan("") : c.cost[c.cost.size() / 2];
    md << "| " << name << " | " << c.outcomes["ok"] << " | " << c.outcomes["at_rest"] << " | "
       << c.outcomes["no_static_friction"] << " | " << c.outcomes["accuracy_not_reached"] << " | "
       << c.outcomes["solver_failure"] << " | " << std::setprecision(3) << c.worst_ratio << " | " << med << " |\n";
  }
  md << "\nThe wall time of the slowest point of each map and law is in the sidecar of atlas.csv.\n\n";
  if (plot::available()) {
    const fs::path csv = dir / "atlas.csv";
    auto figure = [&](const std::string& file, const std::string& title, const std::string& value,
                      const std::string& cb) {
      plot::Figure f;
      f.title = title;
      f.rows = 2;
      f.cols = 2;
      f.width = 1200;
      f.height = 1000;
      for (const MapSpec& m : maps())
        for (const Law law : {Law::coulomb, Law::thesis}) {
          plot::Panel p;
          p.title = m.name + ", " + to_string(law) + " law";
          p.xlabel = m.xlabel;
          p.ylabel = m.ylabel;
          p.logx = p.logy = true;
          std::ostringstream range;  // the map's own extent, a half step of margin on log axes
          const double mx = std::pow(m.xhi / m.xlo, 0.5 / std::max(1, o.points - 1)),
                       my = std::pow(m.yhi / m.ylo, 0.5 / std::max(1, o.points - 1));
          range << "set xrange [" << m.xlo / mx << ":" << m.xhi * mx << "]\nset yrange [" << m.ylo / my << ":"
                << m.yhi * my << "]\n";
          p.extra = cb + range.str() + "unset key\n";
          p.series.push_back({csv, "(strcol(1) eq '" + m.name + "' && strcol(2) eq '" + to_string(law) + "' ? $3 : 1/0)",
                              "4:(" + value + ")", "", "points pt 5 ps 2.2 palette"});
          f.panels.push_back(p);
        }
      const fs::path out = plot::render(f, dir / file);
      md << "![" << title << "](" << (ctx ? "atlas/" : "") << out.filename().string() << ")\n\n";
      if (ctx) ctx->produced(out);
    };
    figure("atlas_outcome.png", "outcome (0 ok, 1 at_rest, 2 no_static_friction, 4 accuracy_not_reached, 5 solver_failure)",
           "$6", "set cbrange [0:5]\nset palette maxcolors 6 defined (0 '#228b22', 1 '#87ceeb', 2 '#ffa500', 3 '#a52a2a', 4 '#ff00ff', 5 '#ff0000')\n");
    figure("atlas_error.png", "log10 of the achieved error estimate over the accuracy asked", "log10($8)",
           "set cbrange [-8:1]\n");
    figure("atlas_cost.png", "log10 of the RHS evaluations of each point (estimate included)", "log10($10)", "");
  }
  if (ctx) ctx->produced(dir / "atlas.csv");
  return ok;  // the atlas records limits; it checks nothing
}

int run_bench_atlas(const AtlasOptions& o) {
  const fs::path dir = o.out;
  fs::create_directories(dir);
  std::ostringstream md;
  md << "# Stability atlas\n\n";
  bench_atlas(o, dir, md, nullptr);
  write_file_atomic(dir / "atlas.md", md.str());
  std::cerr << "bench-atlas: " << (dir / "atlas.md").string() << ", atlas.csv, atlas_*.png\n";
  return 0;
}

RegisterCommand reg{{"bench-atlas",
                     "Stability atlas: outcome, achieved error over the accuracy asked and cost over (mu, F/(mu N)) "
                     "and (length, force), both friction laws (docs/accuracy.md)",
                     95, options_then<AtlasOptions>(run_bench_atlas, [](CLI::App& app, AtlasOptions& o) {
                       add_bench_directory_option(app, o);
                       app.add_option("--points", o.points, "points per axis")->check(count(2, 200))->capture_default_str();
                       app.add_option("--accuracy", o.accuracy, "the accuracy asked at every point")
                           ->check(CLI::Range(kAccuracyMin, kAccuracyMax))
                           ->capture_default_str();
                     })}};

RegisterReproduce step{{"atlas",
                        "stability atlas: outcome, achieved error and cost over (mu, F/(mu N)) and (length, force)", 81,
                        [](ReproduceContext& c) {
                          AtlasOptions o;
                          o.points = c.quick ? 4 : 10;
                          const fs::path dir = c.out / "atlas";
                          fs::create_directories(dir);
                          c.report << "\n## Stability atlas (docs/accuracy.md)\n\n";
                          bench_atlas(o, dir, c.report, &c);
                        },
                        5.0}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
