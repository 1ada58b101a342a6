// Observations: the data CSV (t, any of x, y, theta, their sigmas), its checks, synthetic
// data from the forward model.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <system_error>

#include "nanopush/fitting/fit.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/numerics/normal.hpp"
#include "nanopush/outputs/io.hpp"

namespace nanopush::fit {

std::size_t Observations::count() const {
  std::size_t n = 0;
  for (int c = 0; c < 3; ++c)
    if (has[static_cast<std::size_t>(c)]) n += t.size();
  return n;
}

namespace {

int pose_index(std::string_view name) {
  for (int c = 0; c < 3; ++c)
    if (name == kPoseColumns[static_cast<std::size_t>(c)]) return c;
  return -1;
}

std::string where(const std::string& source, std::size_t row, std::size_t line, const std::string& column) {
  return source + " row " + std::to_string(row) + " (line " + std::to_string(line) + "), column " + column;
}

}  // namespace

Observations parse_observations(std::string_view text, const std::string& source, const SigmaOverrides& overrides) {
  Observations obs;
  obs.source = source;
  for (const auto& [col, s] : overrides) {
    if (pose_index(col) < 0) throw InputError("--sigma", col + "=" + fmt(s), "the column must be x, y or theta");
    require_positive("--sigma " + col, s, col == "theta" ? "rad" : "m");
  }
  // Records (RFC 4180, csv_reader.hpp); '#' comments and blank lines are skipped (their numbers
  // still count).
  csv::ReadOptions ro;
  ro.comments = true;
  const std::vector<csv::Record> lines = csv::parse(text, source, ro);
  if (lines.empty()) throw InputError(source, "(empty)", "needs a header line: t and any of x, y, theta, sigma_x, ...");
  const std::vector<std::string>& header = lines[0].fields;
  const std::size_t hline = lines[0].line;
  int col_t = -1;
  std::array<int, 3> col_v{-1, -1, -1}, col_s{-1, -1, -1};
  for (std::size_t j = 0; j < header.size(); ++j) {
    const std::string& h = header[j];
    const std::string here = source + " line " + std::to_string(hline) + ", column " + std::to_string(j + 1);
    int* slot = nullptr;
    if (h == "t") {
      slot = &col_t;
    } else if (const int c = pose_index(h); c >= 0) {
      slot = &col_v[static_cast<std::size_t>(c)];
    } else if (h.rfind("sigma_", 0) == 0 && pose_index(h.substr(6)) >= 0) {
      slot = &col_s[static_cast<std::size_t>(pose_index(h.substr(6)))];
    } else {
      throw InputError(here, "\"" + h + "\"", "allowed columns: t, x, y, theta, sigma_x, sigma_y, sigma_theta");
    }
    if (*slot >= 0) throw InputError(here, "\"" + h + "\"", "the column appears twice");
    *slot = static_cast<int>(j);
  }
  if (col_t < 0) throw InputError(source + " header", "(no t)", "needs a time column t [s]");
  for (int c = 0; c < 3; ++c) {
    const auto cu = static_cast<std::size_t>(c);
    const std::string name = kPoseColumns[cu];
    obs.has[cu] = col_v[cu] >= 0;
    if (col_s[cu] >= 0 && !obs.has[cu])
      throw InputError(source + " header", "sigma_" + name, "a sigma column needs its value column " + name);
    const bool over = overrides.count(name) > 0;
    if (over && !obs.has[cu])
      throw InputError("--sigma", name, "the data have no column " + name);
    if (over && col_s[cu] >= 0)
      throw InputError("--sigma", name, "the data already give sigma_" + name + ": use one or the other");
    if (obs.has[cu] && !over && col_s[cu] < 0)
      throw InputError(source + " column " + name, "(no sigma)",
                       "needs its standard deviation: a column sigma_" + name + " or --sigma " + name + "=VALUE");
  }
  if (!obs.has[0] && !obs.has[1] && !obs.has[2])
    throw InputError(source + " header", "(no pose column)", "needs at least one of the columns x, y, theta");
  if (lines.size() < 2) throw InputError(source, "(no rows)", "needs at least one data row");

  for (std::size_t r = 1; r < lines.size(); ++r) {
    const std::vector<std::string>& cells = lines[r].fields;
    const std::size_t line = lines[r].line;
    if (cells.size() != header.size())
      throw InputError(source + " row " + std::to_string(r) + " (line " + std::to_string(line) + ")",
                       std::to_string(cells.size()) + " cells", "the header has " + std::to_string(header.size()));
    auto number = [&](int j) {
      const std::string& cell = cells[static_cast<std::size_t>(j)];
      const std::string col = header[static_cast<std::size_t>(j)];
      if (cell.empty()) throw InputError(where(source, r, line, col), "(empty)", "missing value: every cell needs a number");
      double v = 0;
      const char* b = cell.data();
      const char* e = b + cell.size();
      if (*b == '+') ++b;
      const auto res = std::from_chars(b, e, v);
      if (res.ec != std::errc() || res.ptr != e)
        throw InputError(where(source, r, line, col), cell, "not a number");
      if (!std::isfinite(v)) throw InputError(where(source, r, line, col), cell, "must be a finite number");
      return v;
    };
    const double t = number(col_t);
    if (!obs.t.empty() && !(t > obs.t.back()))
      throw InputError(where(source, r, line, "t"), fmt(t),
                       t == obs.t.back() ? "duplicate time (row " + std::to_string(r - 1) + " has the same): times must be strictly increasing"
                                         : "unsorted: before row " + std::to_string(r - 1) + "'s t = " + fmt(obs.t.back()) +
                                               "; times must be strictly increasing");
    obs.t.push_back(t);
    for (int c = 0; c < 3; ++c) {
      const auto cu = static_cast<std::size_t>(c);
      if (!obs.has[cu]) continue;
      obs.value[cu].push_back(number(col_v[cu]));
      double s = 0;
      if (col_s[cu] >= 0) {
        s = number(col_s[cu]);
        if (!(s > 0))
          throw InputError(where(source, r, line, "sigma_" + std::string(kPoseColumns[cu])), fmt(s),
                           "a standard deviation must be > 0");
      } else {
        s = overrides.at(kPoseColumns[cu]);
      }
      obs.sigma[cu].push_back(s);
    }
  }
  return obs;
}

Observations read_observations(const std::filesystem::path& path, const SigmaOverrides& sigma) {
  // The guarded reader: a regular file of at most 64 MiB (never a FIFO, /dev/zero, a directory).
  return parse_observations(read_input_file(path, "DATA", kMaxDataBytes), path.filename().string(), sigma);
}

void check_observations(const Observations& obs, const Scene& scene, std::size_t n_free) {
  const double tend = scene.solver.t_end;
  for (std::size_t i = 0; i < obs.t.size(); ++i)
    if (obs.t[i] < 0 || obs.t[i] > tend)
      throw InputError(obs.source + " row " + std::to_string(i + 1) + ", column t", fmt(obs.t[i]),
                       "outside the scene's time span [0, " + fmt(tend) + "] s (solver.t_end)");
  if (obs.count() <= n_free)
    throw InputError(obs.source, std::to_string(obs.count()) + " observed values",
                     "too few for " + std::to_string(n_free) + " free parameter" + (n_free == 1 ? "" : "s") +
                         ": need more values than free parameters");
}

Observations synthesize(const Scene& scene, const std::array<double, 3>& sigma, std::uint64_t seed,
                        std::optional<Law> law, const std::vector<double>& times_in, double rtol) {
  Observations obs;
  obs.source = "synthetic";
  obs.t = times_in.empty() ? scene.output_times() : times_in;
  // NaN or a negative sigma is bad input, never a column silently left out; 0: not observed.
  // Data with no column observed is no data.
  for (std::size_t c = 0; c < 3; ++c) {
    require_nonnegative(std::string("sigma_") + kPoseColumns[c], sigma[c], c == 2 ? "rad; 0: not observed" : "m; 0: not observed");
    obs.has[c] = sigma[c] > 0;
  }
  if (!obs.has[0] && !obs.has[1] && !obs.has[2])
    throw InputError("sigma", "0,0,0", "observe at least one column: give x, y or theta a sigma > 0 (m, m, rad)");
  const ModelPoses m = model_poses(scene, {}, {}, obs.t, law, rtol, false);
  num::PortableNormal normal(seed);  // the same data for a seed on every platform
  for (std::size_t i = 0; i < obs.t.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const auto cu = static_cast<std::size_t>(c);
      if (!obs.has[cu]) continue;
      obs.value[cu].push_back(m.pose[i][cu] + sigma[cu] * normal());
      obs.sigma[cu].push_back(sigma[cu]);
    }
  return obs;
}

std::string observations_csv(const Observations& obs) {
  std::ostringstream s;
  s << "t";
  for (int c = 0; c < 3; ++c)
    if (obs.has[static_cast<std::size_t>(c)]) s << ',' << kPoseColumns[static_cast<std::size_t>(c)] << ",sigma_" << kPoseColumns[static_cast<std::size_t>(c)];
  s << '\n';
  for (std::size_t i = 0; i < obs.t.size(); ++i) {
    s << csv_number(obs.t[i]);
    for (int c = 0; c < 3; ++c) {
      const auto cu = static_cast<std::size_t>(c);
      if (obs.has[cu]) s << ',' << csv_number(obs.value[cu][i]) << ',' << csv_number(obs.sigma[cu][i]);
    }
    s << '\n';
  }
  return s.str();
}

}  // namespace nanopush::fit
