// Registration of subcommands and reproduce steps. Each cmd_*.cpp owns one subcommand
// (and the reproduce steps for the figures it can make) and registers them with a
// static object, so adding a model never edits the main program.
#pragma once
// Each command's file-local names live in `namespace { namespace NANOPUSH_UNITY_ID { ... } }`:
// the unity build (drivers/CMakeLists.txt) defines the macro per source file, so names such as
// `reg` or `Options` do not collide when several commands share one translation unit.
#ifndef NANOPUSH_UNITY_ID
#define NANOPUSH_UNITY_ID
#endif
#include <CLI/CLI.hpp>

#include <filesystem>
#include <functional>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace nanopush::cli {

namespace fs = std::filesystem;  ///< the commands' short name for std::filesystem

/// A subcommand: `setup` declares its options on `app` and returns the action to run
/// after parsing (returning the process exit code).
struct Command {
  std::string name, description;
  int order;  ///< position in --help
  std::function<std::function<int()>(CLI::App&)> setup;
};

struct ReproduceContext {
  std::filesystem::path out;   ///< output directory (exists)
  std::ostringstream report;   ///< Markdown appended by each step
  std::vector<std::string> failures;  ///< checks that did not hold (reported, exit != 0)
  bool quick = false;          ///< fewer samples (used by the test suite)
  /// Record a produced file for the report's index.
  void produced(const std::filesystem::path& p) { files.push_back(p); }
  std::vector<std::filesystem::path> files;
};

struct ReproduceStep {
  std::string name, description;
  int order;
  std::function<void(ReproduceContext&)> run;
  /// Typical wall time [s] on a 2-core machine: steps start longest first, so no long step
  /// starts last beside an idle core (0: under a second).
  double cost_s = 0;
};

std::vector<Command>& commands();
std::vector<ReproduceStep>& reproduce_steps();

/// The setup of the usual subcommand: its options fill a fresh `Options` (`declare(app, o)`
/// adds them to the app), which `run(o)` receives after parsing.
template <class Options, class Run, class Declare>
std::function<std::function<int()>(CLI::App&)> options_then(Run run, Declare declare) {
  return [run, declare](CLI::App& app) -> std::function<int()> {
    auto o = std::make_shared<Options>();
    declare(app, *o);
    return [o, run] { return run(*o); };
  };
}

struct RegisterCommand {
  RegisterCommand(Command c) { commands().push_back(std::move(c)); }
};
struct RegisterReproduce {
  RegisterReproduce(ReproduceStep s) { reproduce_steps().push_back(std::move(s)); }
};

/// Directory of the running executable (/proc/self/exe).
std::filesystem::path executable_dir();
/// Directory holding scene presets: $NANOPUSH_SCENES, else <prefix>/share/nanopush/scenes
/// beside the installed executable (<prefix>/bin), else <source>/drivers/scenes when run from
/// a build tree. No path is compiled in.
std::filesystem::path scenes_dir();
/// Resolve a scene argument: an existing path, or a preset name such as
/// "thesis/fig3_6a" or "fig3_6a" (searched under scenes_dir()).
std::filesystem::path resolve_scene(const std::string& arg);

}  // namespace nanopush::cli
