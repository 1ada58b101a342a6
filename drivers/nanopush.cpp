// nanopush: command-line entry point. Subcommands register themselves (registry.hpp).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "registry.hpp"

int main(int argc, char** argv) {
  using namespace nanopush;
  // Provenance of every CSV sidecar this run writes (docs/outputs.md).
  set_provenance(NANOPUSH_VERSION, join_command_line(argc, argv));
  CLI::App app{
      "nanopush " NANOPUSH_VERSION
      ": mechanics of pushing nano-objects with an AFM tip.\n"
      "Two engines (modern C++ and FORTRAN 77 Bulirsch-Stoer) on the same scenes. SI units throughout."};
  app.set_version_flag("--version", std::string("nanopush ") + NANOPUSH_VERSION);
  app.require_subcommand(1);
  auto& cmds = cli::commands();
  std::stable_sort(cmds.begin(), cmds.end(), [](auto& a, auto& b) { return a.order < b.order; });
  std::function<int()> action;
  for (auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    auto act = c.setup(*sub);
    sub->callback([&action, act] { action = act; });
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    return action ? action() : 0;
  } catch (const InputError& e) {
    std::cerr << "nanopush: error: " << e.what() << "\n";
    return 2;
  } catch (const SolverError& e) {
    std::cerr << "nanopush: solver failure: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "nanopush: error: " << e.what() << "\n";
    return 1;
  }
}
