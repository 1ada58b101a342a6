// Figures through gnuplot (Debian's gnuplot-nox): we write a gnuplot script next to
// the PNG (so a person can restyle and re-run it) and render it; both files appear
// atomically. Plot data always comes from a CSV the same step wrote.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace nanopush::plot {

struct Series {
  std::filesystem::path csv;  ///< data file (comma separated, one header line)
  std::string x;              ///< gnuplot column expression, e.g. "1" or "($1*1e9)"
  std::string y;              ///< idem
  std::string title;
  std::string style = "lines lw 2";
};

struct Panel {
  std::string title, xlabel, ylabel;
  bool logx = false, logy = false;
  std::string extra;  ///< raw gnuplot lines (ranges, keys...)
  std::vector<Series> series;
};

struct Figure {
  std::string title;
  int rows = 1, cols = 1;
  int width = 1000, height = 700;
  std::vector<Panel> panels;
};

/// Render `fig` to `png`; writes `png` with extension .gp beside it. Throws on failure
/// (gnuplot missing or reporting an error); nothing is left half-written.
void render(const Figure& fig, const std::filesystem::path& png);

/// Render a raw gnuplot body (everything after terminal/output setup) to `png`.
void render_script(const std::string& body, const std::filesystem::path& png, int width = 1000,
                   int height = 700);

/// True when a usable gnuplot is on PATH.
bool available();

}  // namespace nanopush::plot
