// Pieces the nanopush icor subcommands and the iCOR reproduce steps share: rod options,
// the four solvers of the cubic, CSV tables with empty cells, sweeps, figure rendering.
#pragma once
#include <cmath>
#include <filesystem>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "nanopush/engines/f77_icor.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "registry.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli::icor_cli {

using icor::CubicMethod;
using icor::CubicSolution;

inline void add_rod_options(CLI::App& app, icor::Rod& rod) {
  app.add_option("--length", rod.length, "rod length L [m]")->capture_default_str();
  app.add_option("--radius", rod.radius, "rod radius [m]")->capture_default_str();
  app.add_option("--density", rod.density, "rod density [kg/m^3] (graphite 2267)")->capture_default_str();
  app.add_option("--hamaker", rod.hamaker,
                 "Hamaker constant H [J]; the thesis prints none for graphite, the default is an assumed "
                 "literature-order value (only absolute forces depend on it)")
      ->capture_default_str();
  app.add_option("--z0", rod.z0, "rod-plane separation z0 [m] (thesis: 0.2 nm)")->capture_default_str();
  app.add_option("--gravity", rod.gravity, "g [m/s^2]")->capture_default_str();
}

/// The four solvers of the cubic: {column name, solve(yn)}.
struct NamedSolver {
  std::string name;
  std::function<CubicSolution(double)> solve;
};
inline std::vector<NamedSolver> all_solvers(double L, double k2) {
  return {
      {"brent_cxx", [=](double yn) { return solve_cubic(yn, L, k2, CubicSolver::brent); }},
      {"eigen_cxx", [=](double yn) { return solve_cubic(yn, L, k2, CubicSolver::eigen); }},
      {"brent_f77", [=](double yn) { return solve_cubic(yn, L, k2, CubicSolver::brent_f77); }},
      {"lapack_f77", [=](double yn) { return solve_cubic(yn, L, k2, CubicSolver::lapack_f77); }},
  };
}

inline std::string cell(const std::optional<double>& v) { return v ? csv_number(*v) : std::string(); }

/// A CSV whose cells may be empty (a branch that does not exist), with its sidecar
/// (docs/outputs.md): written atomically, or to standard output (no sidecar) when the path is
/// empty or "-"; FILE.nc is netCDF-4 over a `point` dimension (docs/data.md). Any other
/// extension is refused when the table is made, before any work.
class Table {
 public:
  Table(const std::filesystem::path& path, Columns columns) : path_(path), columns_(std::move(columns)) {
    (void)TableOutput::kind_of(path_);
  }
  void row(std::vector<std::string> cells) {
    if (cells.size() != columns_.size())
      throw std::logic_error(path_.string() + ": row of " + std::to_string(cells.size()) + " cells for " +
                             std::to_string(columns_.size()) + " columns");
    rows_.push_back(std::move(cells));
  }
  std::string text() const { return csv_document(columns_, rows_); }
  void write() const {
    if (to_stdout()) {
      std::cout << text();
      return;
    }
    const TableOutput out(path_);  // the CSV itself, or FILE.nc.csv converted into FILE.nc
    write_csv_atomic(out.table(), columns_, rows_);
    (void)out.finish();
  }

 private:
  [[nodiscard]] bool to_stdout() const { return path_.empty() || path_ == "-"; }
  std::filesystem::path path_;
  Columns columns_;
  std::vector<std::vector<std::string>> rows_;
};

/// A column family's name part for a parameter value: 0.1 -> "0p1", 1e-4 -> "0p0001", 2 -> "2".
inline std::string value_name(double v) {
  std::ostringstream s;
  s << v;
  std::string r = s.str();
  for (char& c : r)
    if (c == '.') c = 'p';
    else if (c == '-') c = 'm';
    else if (c == '+') c = 'p';
  return r;
}

inline std::vector<double> sweep(double lo, double hi, int n, bool log) {
  if (n < 1) throw InputError("--n", std::to_string(n), "must be >= 1");
  if (log && !(lo > 0.0)) throw InputError("--yn-min", fmt(lo), "must be > 0 with --log");
  std::vector<double> v;
  for (int i = 0; i < n; ++i) {
    const double t = n == 1 ? 0.0 : static_cast<double>(i) / (n - 1);
    v.push_back(log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t);
  }
  if (n > 1) v.back() = hi;
  return v;
}

// ---- reproduce steps -------------------------------------------------------------------

inline void check(ReproduceContext& ctx, bool ok, const std::string& what) {
  if (!ok) ctx.failures.push_back(what);
}

/// A gnuplot string literal (for the scripts a command writes itself, e.g. fit-icor's).
inline std::string gp_quote(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r + "\"";
}

/// Draw a one-panel figure with the shared plot writer (plot::render), or say why not.
inline void render_if_possible(ReproduceContext& ctx, const std::string& title, const plot::Panel& panel,
                               const std::filesystem::path& png) {
  plot::Figure fig;
  fig.title = title;
  fig.panels.push_back(panel);
  if (!plot::available()) {
    ctx.report << "\n(gnuplot not found: " << png.filename().string() << " not drawn)\n";
    return;
  }
  plot::render(fig, png);
  ctx.produced(png);
  ctx.produced(std::filesystem::path(png).replace_extension(".gp"));
}

}  // namespace nanopush::cli::icor_cli
