// nanopush: command-line entry point. Subcommands register themselves (registry.hpp).
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iostream>
#include <new>
#include <stdexcept>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "cli_checks.hpp"
#include "interrupt.hpp"
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
  app.footer(
      "Exit status: 0 ok; 1 a comparison past its tolerance (compare, legacy); 2 bad input (nothing written);\n"
      "3 solver failure; 4 a check against the thesis failed (reproduce, bench); 5 system error (a file or a\n"
      "program); 64+k sweep with k <= 5 failed points (65+k from 6 on, 127: 62 or more); 70 internal error;\n"
      "128+N ended by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP, 141 SIGPIPE, ...). docs/errors.md has\n"
      "the details.\n"
      "Tables are CSV with a Table Schema sidecar; a table file named FILE.nc is netCDF-4, and `nanopush\n"
      "convert` turns the tables of an output directory into netCDF-4 (docs/data.md).");
  auto& cmds = cli::commands();
  std::stable_sort(cmds.begin(), cmds.end(), [](auto& a, auto& b) { return a.order < b.order; });
  // A process starts light (docs/performance.md, "Process start"): only the command named
  // declares its options; `--version` and `--help` alone declare none (the help lists names and
  // descriptions). Anything else (no arguments, --help-all, a mistyped option) declares them all.
  const std::string first = argc > 1 ? argv[1] : "";
  const bool top_only = argc == 2 && (first == "--version" || first == "--help" || first == "-h");
  const bool named = !first.empty() && first[0] != '-';
  std::function<int()> action;
  for (auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    if (top_only || (named && c.name != first)) continue;
    auto act = c.setup(*sub);
    sub->callback([&action, act] { action = act; });
  }
  cli::install_interrupt_handler();  // temporaries removed, exit 128 + signal (interrupt.hpp)
  cli::harden(app);  // reals finite, counts bounded, everywhere (cli_checks.hpp)
  const auto known = [&](const char* name) {
    for (const auto& c : cmds)
      if (c.name == name) return true;
    return false;
  };
  if (argc > 1 && argv[1][0] != '-' && !known(argv[1])) {
    std::string names;
    for (const auto& c : cmds) names += (names.empty() ? "" : ", ") + c.name;
    std::cerr << "nanopush: error: unknown subcommand '" << argv[1] << "'; the subcommands are: " << names
              << "\nRun 'nanopush --help' for what each does.\n";
    return 2;
  }
  // The same for a command that has subcommands of its own (icor formulas, roots, ...).
  if (argc > 2 && argv[1][0] != '-' && argv[2][0] != '-') {
    CLI::App* cmd = app.get_subcommand(argv[1]);
    const auto subs = cmd ? cmd->get_subcommands([](CLI::App*) { return true; }) : std::vector<CLI::App*>{};
    if (!subs.empty() &&
        std::none_of(subs.begin(), subs.end(), [&](CLI::App* a) { return a->check_name(argv[2]); })) {
      std::string names;
      for (const auto* a : subs) names += (names.empty() ? "" : ", ") + a->get_name();
      std::cerr << "nanopush: error: unknown subcommand '" << argv[2] << "' of '" << argv[1]
                << "'; its subcommands are: " << names << "\nRun 'nanopush " << argv[1]
                << " --help' for what each does.\n";
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {  // --help, --help-all, --version
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // Every parse error is bad input (exit 2, docs/errors.md), said in the project's style.
    std::string where = "nanopush";
    for (const CLI::App* a = &app; !a->get_subcommands().empty();) {
      a = a->get_subcommands().front();
      where += " " + a->get_name();
    }
    std::string what = e.what();
    // A check of ours reads "VALUE: must be ..." and CLI11 puts "--option: " before it: the
    // project's form is "--option = VALUE: must be ..." (InputError's).
    if (dynamic_cast<const CLI::ValidationError*>(&e)) {
      const auto colon = what.find(": ");
      if (colon != std::string::npos && what.find(": must be", colon + 2) != std::string::npos)
        what.replace(colon, 2, " = ");
    }
    std::cerr << "nanopush: error: " << what << "\nRun '" << where << " --help' for the options and their ranges.\n";
    return 2;
  }
  try {
    return action ? action() : 0;
  } catch (const InputError& e) {
    std::cerr << "nanopush: error: " << e.what() << "\n";
    return 2;
  } catch (const SolverError& e) {  // a classified outcome names itself (docs/errors.md)
    std::cerr << "nanopush: " << (e.outcome() == "solver_failure" ? std::string("solver failure") : e.outcome()) << ": "
              << e.what() << "\n";
    return 3;
  } catch (const std::logic_error& e) {
    std::cerr << "nanopush: internal error (a bug: please report it with the command line): " << e.what() << "\n";
    return 70;
  } catch (const std::bad_alloc&) {
    std::cerr << "nanopush: system error: out of memory\n";
    return 5;
  } catch (const std::exception& e) {
    std::cerr << "nanopush: system error: " << e.what() << "\n";
    return 5;
  }
}
