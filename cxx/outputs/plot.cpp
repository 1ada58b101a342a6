#include "nanopush/outputs/plot.hpp"

#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/process.hpp"

namespace nanopush::plot {

namespace {
std::atomic<int> g_format{static_cast<int>(Format::png)};

std::string quote(const std::string& s) {
  std::string r = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') r += '\\';
    r += c;
  }
  return r + "\"";
}

/// Text shown as written (noenhanced): drop the enhanced-text escapes some callers add
/// ("\_" for a literal underscore).
std::string plain(const std::string& s) {
  std::string r;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size() && std::string("_^{}@&~").find(s[i + 1]) != std::string::npos) continue;
    r += s[i];
  }
  return r;
}

std::string terminal(Format f, int width, int height) {
  std::ostringstream t;
  switch (f) {
    case Format::png: t << "pngcairo size " << width << "," << height << " enhanced font 'Sans,10'"; break;
    case Format::svg:
      t << "svg size " << width << "," << height << " dynamic enhanced font 'Sans,10' background '#ffffff'";
      break;
    case Format::pdf: t << "pdfcairo size " << width / 100.0 << "in," << height / 100.0 << "in enhanced font 'Sans,10'"; break;
  }
  return t.str();
}

/// Rewrite every quoted string of `body` that names an existing file as a path relative to
/// `dir` (the figure's folder), keeping its quote character.
std::string relative_paths(const std::string& body, const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  std::string out;
  std::size_t i = 0;
  while (i < body.size()) {
    const char q = body[i];
    if (q != '"' && q != '\'') {
      out += body[i++];
      continue;
    }
    // Find the closing quote: "..." with backslash escapes, '...' with '' for a quote.
    std::string text;
    std::size_t j = i + 1;
    bool closed = false;
    while (j < body.size()) {
      if (q == '"' && body[j] == '\\' && j + 1 < body.size()) {
        text += body[j + 1];
        j += 2;
        continue;
      }
      if (body[j] == q) {
        if (q == '\'' && j + 1 < body.size() && body[j + 1] == '\'') {
          text += '\'';
          j += 2;
          continue;
        }
        closed = true;
        break;
      }
      text += body[j++];
    }
    if (!closed) {
      out += body.substr(i);
      break;
    }
    std::error_code ec;
    if (!text.empty() && text.find('\n') == std::string::npos && fs::is_regular_file(text, ec)) {
      const fs::path rel = fs::relative(fs::path(text), dir.empty() ? fs::path(".") : dir, ec);
      if (!ec && !rel.empty()) {
        out += quote(rel.generic_string());
        i = j + 1;
        continue;
      }
    }
    out += body.substr(i, j + 1 - i);
    i = j + 1;
  }
  return out;
}

/// First line of every kept script: change to the script's own folder (ARG0 is the script
/// path gnuplot was given), so its relative paths hold wherever it is run from.
constexpr const char* kCdToScript =
    "# Paths below are relative to this file's folder; run it from anywhere: gnuplot <path>/<this file>\n"
    "if (strstrt(ARG0, \"/\") > 0) { _d = ARG0; while (_d[strlen(_d):strlen(_d)] ne \"/\") "
    "{ _d = _d[1:strlen(_d)-1] }; cd _d }\n";
}  // namespace

Format parse_format(const std::string& text, const std::string& field) {
  if (const auto f = choice_from_name<Format>(text)) return *f;
  throw InputError(field, text, "must be one of " + choice_names<Format>(", "));
}
void set_format(Format f) { g_format.store(static_cast<int>(f)); }
Format format() { return static_cast<Format>(g_format.load()); }
std::string extension(Format f) { return std::string(name_of(f)); }
std::filesystem::path figure_path(const std::filesystem::path& p) {
  std::string ext(1, '.');  // (not "." + ...: GCC 12 warns -Wrestrict on that)
  ext += extension(format());
  std::filesystem::path r = p;
  r.replace_extension(ext);
  return r;
}

bool available() { return run_program({"gnuplot", "--version"}) == 0; }

std::filesystem::path render_script(const std::string& body, const std::filesystem::path& png_in, int width,
                                    int height) {
  const Format f = format();
  const std::filesystem::path png = figure_path(png_in);
  const std::filesystem::path dir = png.parent_path();
  if (!dir.empty()) std::filesystem::create_directories(dir);
  const std::string pid = std::to_string(::getpid());
  // Where the figure goes (a directory or a FIFO is refused before gnuplot runs); the
  // temporaries of a killed run are swept up.
  const OutputTarget target = resolve_output(png);
  remove_stale_temporaries(png);
  TemporaryPath tmp_png(png.string() + ".tmp." + pid + png.extension().string());
  std::filesystem::path script = png;
  script.replace_extension(".gp");
  const std::string rel_body = relative_paths(body, dir);
  auto text = [&](const std::string& output) {
    std::ostringstream gp;
    gp << kCdToScript << "set terminal " << terminal(f, width, height) << "\n"
       << "set datafile separator ','\n"
       << "set output " << quote(output) << "\n"
       << rel_body << "\nunset output\n";
    return gp.str();
  };
  // The kept script writes the final name; the rendering run writes a temporary one.
  const std::string kept = text(png.filename().string());
  TemporaryPath tmp_script(script.string() + ".tmp." + pid), tmp_err(script.string() + ".tmp." + pid + ".err");
  {
    std::ofstream fs(tmp_script.path());
    fs << text(tmp_png.path().filename().string());
    if (!fs.flush()) throw std::runtime_error("cannot write " + tmp_script.path().string());
  }
  // A relative path goes as ./PATH: one starting with '-' (an output directory named "-") would
  // otherwise be read by gnuplot as an option.
  const std::filesystem::path& sp = tmp_script.path();
  const std::string script_arg = sp.is_absolute() ? sp.string() : (std::filesystem::path(".") / sp).string();
  const int rc = run_program({"gnuplot", script_arg}, "/dev/null", "/dev/null", tmp_err.path().string());
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
  if (target.write_through || target.path != png) {
    // A link (its target replaced, the link kept) or a device (written through): as every output.
    std::ifstream in(tmp_png.path(), std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    write_file_atomic(png, bytes.str());
  } else {
    std::filesystem::rename(tmp_png.path(), png);
    tmp_png.release();
  }
  return png;
}

std::filesystem::path render(const Figure& fig, const std::filesystem::path& png) {
  std::ostringstream b;
  const bool single = fig.rows * fig.cols <= 1;
  if (!single) {
    b << "set multiplot layout " << fig.rows << "," << fig.cols;
    if (!fig.title.empty()) b << " title " << quote(plain(fig.title)) << " noenhanced";
    b << "\n";
  }
  for (const auto& p : fig.panels) {
    b << "reset session\nset datafile separator ','\nset grid\n";
    // Keys off the curves: in the right margin of each plot.
    b << "set key outside right top vertical\n";
    if (!p.title.empty())
      b << "set title " << quote(plain(p.title)) << " noenhanced\n";
    else if (single && !fig.title.empty())
      b << "set title " << quote(plain(fig.title)) << " noenhanced\n";
    b << "set xlabel " << quote(plain(p.xlabel)) << " noenhanced\nset ylabel " << quote(plain(p.ylabel))
      << " noenhanced\n";
    if (p.logx) b << "set logscale x\nset format x '10^{%L}'\n";
    if (p.logy) b << "set logscale y\nset format y '10^{%L}'\n";
    if (!p.extra.empty()) b << p.extra << "\n";
    b << "plot ";
    for (std::size_t i = 0; i < p.series.size(); ++i) {
      const auto& s = p.series[i];
      b << (i ? ", \\\n     " : "") << quote(s.csv.string()) << " skip 1 using " << s.x << ":" << s.y
        << " with " << s.style << " title " << quote(plain(s.title)) << " noenhanced";
    }
    b << "\n";
  }
  if (!single) b << "unset multiplot\n";
  return render_script(b.str(), png, fig.width, fig.height);
}

}  // namespace nanopush::plot
