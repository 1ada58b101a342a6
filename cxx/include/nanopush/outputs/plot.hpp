// Figures through gnuplot (Debian's gnuplot-nox): we write a gnuplot script next to
// the figure (so a person can restyle and re-run it) and render it; both files appear
// atomically. Plot data always comes from a CSV the same step wrote. The kept script names
// its data and output relative to its own folder and changes to that folder first, so
// `gnuplot fig/x.gp` re-runs from the output directory (or from anywhere).
// Figure format (png, svg or pdf) is a process-wide setting (`--format` of reproduce and the
// drawing subcommands); callers name the figure "x.png" and the file written is
// figure_path("x.png") (same stem, the current format's extension).
#pragma once
#include <filesystem>
#include <string>
#include <vector>

#include "nanopush/numerics/names.hpp"

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

enum class Format { png, svg, pdf };  // names: the table after this namespace
/// Parse "png" | "svg" | "pdf" (throws InputError naming `field` otherwise).
Format parse_format(const std::string& text, const std::string& field = "--format");
/// Set / read the figure format of this process (default png).
void set_format(Format f);
Format format();
/// "png", "svg" or "pdf".
std::string extension(Format f);
/// `p` with the extension of the current format.
std::filesystem::path figure_path(const std::filesystem::path& p);

/// Render `fig` to figure_path(`png`); writes the script (extension .gp) beside it and
/// returns the figure's path. Titles, axis labels and key entries are set noenhanced (they
/// render as written: F_min, theta_exact); keys sit in the right margin unless a panel's
/// `extra` places them. Throws on failure (gnuplot missing or reporting an error); nothing
/// is left half-written.
std::filesystem::path render(const Figure& fig, const std::filesystem::path& png);

/// Render a raw gnuplot body (everything after terminal/output setup) to figure_path(`png`).
/// Quoted names of existing files in `body` are rewritten relative to the figure's folder.
std::filesystem::path render_script(const std::string& body, const std::filesystem::path& png, int width = 1000,
                                    int height = 700);

/// True when a usable gnuplot is on PATH.
bool available();

}  // namespace nanopush::plot

namespace nanopush {
NANOPUSH_NAMES(plot::Format, {plot::Format::png, "png"}, {plot::Format::svg, "svg"}, {plot::Format::pdf, "pdf"});
}  // namespace nanopush
