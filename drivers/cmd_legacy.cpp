// nanopush deck / legacy: write a scene as the classic input deck of the FORTRAN 77 main
// program (fortran/prog_nanobar.f), and run that program on it to check it reproduces the
// F77 engine as nanopush drives it.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "nanopush/scenes/deck.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/engines/engines.hpp"
#include "cli_checks.hpp"
#include "nanopush/outputs/process.hpp"
#include "registry.hpp"
#include "scene_args.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

void check_deck_scene(const Scene& sc) {
  if (sc.rough() && sc.surface.normal_load > 0)
    throw InputError("surface.normal_load", fmt(sc.surface.normal_load),
                     "the legacy deck carries N as m g + F_vdw; remove normal_load to write a deck");
  if (sc.solver.samples > 20001)
    throw InputError("solver.samples", std::to_string(sc.solver.samples), "the legacy program holds at most 20001 samples");
}

struct DeckOptions {
  std::string scene, out;
  std::vector<std::string> sets;  ///< --set KEY=VALUE
  double rtol = 0;
};

int deck_cmd(const DeckOptions& o) {
  const Scene sc = load_scene_arg(o.scene, o.sets);
  check_deck_scene(sc);
  const double rtol = o.rtol > 0 ? o.rtol : sc.solver.rtol;
  const std::string text = legacy_deck(sc, rtol, sc.atol_vector(rtol, sc.solver.atol, 8));
  if (o.out.empty() || o.out == "-")
    std::cout << text;
  else
    write_file_atomic(o.out, text);
  return 0;
}

std::filesystem::path self_dir() {
  char buf[4096];
  const ssize_t n = ::readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return ".";
  buf[n] = 0;
  return std::filesystem::path(buf).parent_path();
}

struct LegacyOptions {
  std::string scene, program;
  std::vector<std::string> sets;  ///< --set KEY=VALUE
  double tolerance = 0;
};

int legacy_cmd(const LegacyOptions& o) {
  namespace fs = std::filesystem;
  const Scene sc = load_scene_arg(o.scene, o.sets);
  check_deck_scene(sc);
  const fs::path prog = o.program.empty() ? self_dir() / "nanobar" : fs::path(o.program);
  if (!fs::exists(prog)) throw InputError("--program", prog.string(), "no such program (build target 'nanobar')");
  const double rtol = sc.solver.rtol;
  const auto atol = sc.atol_vector(rtol, sc.solver.atol, 8);
  const fs::path tmp = fs::temp_directory_path() / ("nanopush-legacy-" + std::to_string(::getpid()));
  fs::create_directories(tmp);
  write_file_atomic(tmp / "case.deck", legacy_deck(sc, rtol, atol));
  const int rc = run_program({prog.string()}, (tmp / "case.deck").string(), (tmp / "case.out").string(),
                             (tmp / "case.err").string());
  std::string err_text;
  {
    std::ifstream e(tmp / "case.err");
    std::getline(e, err_text, '\0');
  }
  std::ifstream in(tmp / "case.out");
  std::string line;
  std::vector<std::vector<double>> rows;
  bool data = false;
  std::cout << "legacy program " << prog.string() << " on " << sc.name << ":\n";
  while (std::getline(in, line)) {
    if (!data) {
      std::cout << "  | " << line << "\n";
      if (line.find("THETA [rad]") != std::string::npos) data = true;
      continue;
    }
    std::istringstream ls(line);
    std::vector<double> r;
    std::string tok;
    while (ls >> tok) r.push_back(std::strtod(tok.c_str(), nullptr));
    if (r.size() == 12) rows.push_back(r);
  }
  fs::remove_all(tmp);
  if (rc != 0 || rows.empty()) {
    // Nothing to compare: say why on stderr (a solver failure, exit 3), never a quiet exit 1.
    throw SolverError("the legacy program " + prog.string() + " " +
                      (rc != 0 ? describe_exit(rc) : std::string("wrote no trajectory rows")) + " on " + sc.name +
                      (err_text.empty() ? std::string() : "; its error output: " + err_text.substr(0, 2000)));
  }
  RunSettings rs;
  rs.engine = Engine::f77;
  rs.law = Law::thesis;
  rs.allow_partial = true;
  rs.error_estimate = false;
  const Trajectory tr = run_engine(sc, rs);
  const std::size_t n = std::min(rows.size(), tr.rows.size());
  double dev = 0;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t c = 0; c < 10; ++c) {
      const double a = rows[i][c], b = tr.rows[i][c];
      dev = std::max(dev, std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), 1e-300}));
    }
  const double tol = o.tolerance > 0 ? o.tolerance : 1e-15;
  std::cout << "  samples: legacy " << rows.size() << ", nanopush f77 engine " << tr.rows.size()
            << "; largest relative difference " << dev << " (tolerance " << tol << ")\n";
  const bool ok = rows.size() == tr.rows.size() && n > 0 && dev <= tol;
  std::cout << (ok ? "  -> the legacy program reproduces the F77 engine\n" : "  -> MISMATCH\n");
  return ok ? 0 : 1;
}

RegisterCommand reg_deck{{"deck", "Write a scene as the classic input deck of the FORTRAN 77 program 'nanobar'", 60,
                          options_then<DeckOptions>(deck_cmd, [](CLI::App& app, DeckOptions& o) {
                            app.add_option("SCENE", o.scene, "scene file or preset name")->required();
                            add_set_option(app, o.sets);
                            app.add_option("--out", o.out, "deck file (default: standard output)");
                            app.add_option("--rtol", o.rtol, "relative tolerance (default: the scene's)")
                                ->check(positive());
                          })}};

RegisterCommand reg_legacy{{"legacy",
                            "Run the FORTRAN 77 main program 'nanobar' on a scene's deck and compare it with the F77 "
                            "engine as nanopush drives it",
                            61, options_then<LegacyOptions>(legacy_cmd, [](CLI::App& app, LegacyOptions& o) {
                              app.add_option("SCENE", o.scene, "scene file or preset name")->required();
                            add_set_option(app, o.sets);
                              app.add_option("--program", o.program, "the legacy program (default: nanobar beside nanopush)");
                              app.add_option("--tolerance", o.tolerance, "largest relative difference (default 1e-15)")
                                  ->check(positive());
                            })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
