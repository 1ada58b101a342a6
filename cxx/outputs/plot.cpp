#include "nanopush/outputs/plot.hpp"

#include <cstdlib>
#include <vector>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>

#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/process.hpp"

namespace nanopush::plot {

namespace {
std::string quote(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r + "\"";
}

}  // namespace

bool available() { return run_program({"gnuplot", "--version"}) == 0; }

void render_script(const std::string& body, const std::filesystem::path& png, int width, int height) {
  if (png.has_parent_path()) std::filesystem::create_directories(png.parent_path());
  const std::string pid = std::to_string(::getpid());
  TemporaryPath tmp_png(png.string() + ".tmp." + pid + ".png");
  std::ostringstream gp;
  gp << "set terminal pngcairo size " << width << "," << height << " enhanced font 'Sans,10'\n"
     << "set datafile separator ','\n"
     << "set output " << quote(tmp_png.path().string()) << "\n"
     << body << "\nunset output\n";
  std::filesystem::path script = png;
  script.replace_extension(".gp");
  // The kept script writes the final name, so re-running it by hand just works.
  std::string kept = gp.str();
  const auto pos = kept.find(quote(tmp_png.path().string()));
  if (pos != std::string::npos) kept.replace(pos, quote(tmp_png.path().string()).size(), quote(png.string()));
  TemporaryPath tmp_script(script.string() + ".tmp." + pid), tmp_err(script.string() + ".tmp." + pid + ".err");
  {
    std::ofstream f(tmp_script.path());
    f << gp.str();
    if (!f.flush()) throw std::runtime_error("cannot write " + tmp_script.path().string());
  }
  const int rc = run_program({"gnuplot", tmp_script.path().string()}, "/dev/null", "/dev/null", tmp_err.path().string());
  std::string err;
  {
    std::ifstream e(tmp_err.path());
    std::ostringstream ss;
    ss << e.rdbuf();
    err = ss.str();
  }
  if (rc != 0 || !std::filesystem::exists(tmp_png.path()))
    throw std::runtime_error("gnuplot failed for " + png.string() + " (gnuplot " + describe_exit(rc) + "): " + err);
  write_file_atomic(script, kept);
  std::filesystem::rename(tmp_png.path(), png);
  tmp_png.release();
}

void render(const Figure& fig, const std::filesystem::path& png) {
  std::ostringstream b;
  if (fig.rows * fig.cols > 1) {
    b << "set multiplot layout " << fig.rows << "," << fig.cols;
    if (!fig.title.empty()) b << " title " << quote(fig.title);
    b << "\n";
  }
  const bool single = fig.rows * fig.cols <= 1;
  for (const auto& p : fig.panels) {
    b << "reset session\nset datafile separator ','\nset grid\nset key\n";
    if (!p.title.empty())
      b << "set title " << quote(p.title) << "\n";
    else if (single && !fig.title.empty())
      b << "set title " << quote(fig.title) << "\n";
    b << "set xlabel " << quote(p.xlabel) << "\nset ylabel " << quote(p.ylabel) << "\n";
    if (p.logx) b << "set logscale x\nset format x '10^{%L}'\n";
    if (p.logy) b << "set logscale y\nset format y '10^{%L}'\n";
    if (!p.extra.empty()) b << p.extra << "\n";
    b << "plot ";
    for (std::size_t i = 0; i < p.series.size(); ++i) {
      const auto& s = p.series[i];
      b << (i ? ", \\\n     " : "") << quote(s.csv.string()) << " skip 1 using " << s.x << ":" << s.y
        << " with " << s.style << " title " << quote(s.title);
    }
    b << "\n";
  }
  if (fig.rows * fig.cols > 1) b << "unset multiplot\n";
  render_script(b.str(), png, fig.width, fig.height);
}

}  // namespace nanopush::plot
