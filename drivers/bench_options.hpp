// Options the bench-* commands share, declared once.
#pragma once
#include <string>

#include <CLI/CLI.hpp>

namespace nanopush::cli {

/// The options of a bench-* command that writes its report, tables and figures into a directory.
struct BenchDirectoryOptions {
  std::string out = "docs/figures";  ///< --out: the output directory
};

/// Declare --out, the output directory (default docs/figures), of a bench-* command.
inline void add_bench_directory_option(CLI::App& app, BenchDirectoryOptions& o) {
  app.add_option("--out", o.out, "output directory")->capture_default_str();
}

}  // namespace nanopush::cli
