// Sweep plans: axes, cartesian grids, point lists; shards.
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {
namespace {

constexpr std::size_t kMaxPoints = kMaxPlanPoints;  // 1e8: a plan larger than this is a typo

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep)) out.push_back(cur);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

/// A whole cell as a number (shortest round-trip text reads back exactly).
double number_of(const std::string& field, const std::string& text) {
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size())
    throw InputError(field, text, "must be a number");
  return v;
}

/// A value of `key` from text: the scene key's type when the key is a scene key, else a number
/// when it reads as one, else text (the task checks it: Task::check_input).
SceneValue value_of(const std::string& key, const std::string& text) {
  if (find_scene_key(key)) return SceneValue::from_text(key, text);
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) return text;
  require_finite(key, v);  // NaN would read as "not given" to a task
  return v;
}

/// A range end: a number, finite, the message naming the option and the end.
double range_end(const std::string& opt, const std::string& spec, const std::string& key, const std::string& end,
                 const std::string& text) {
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  const SceneKey* k = find_scene_key(key);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size() ||
      (k && k->type != KeyType::number && k->type != KeyType::integer))
    throw InputError(opt, spec, "a range is FROM:TO:N of numbers, for a number-valued key");
  require_finite(opt + " " + key + " " + end, v);
  return v;
}

}  // namespace

Axis parse_axis(const std::string& spec, bool log) {
  const std::string opt = log ? "--vary-log" : "--vary";
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError(opt, spec, "must be KEY=FROM:TO:N or KEY=V1,V2,... (e.g. surface.mu=0.02:0.2:10)");
  Axis a;
  a.key = spec.substr(0, eq);
  const std::string rhs = spec.substr(eq + 1);
  if (rhs.find(':') != std::string::npos) {
    const auto parts = split(rhs, ':');
    if (parts.size() != 3) throw InputError(opt, spec, "a range is FROM:TO:N (three fields)");
    const double from = range_end(opt, spec, a.key, "FROM", parts[0]), to = range_end(opt, spec, a.key, "TO", parts[1]);
    double nd = 0;
    try {
      nd = number_of("N", parts[2]);
    } catch (const InputError&) {
      throw InputError(opt, spec, "N = " + parts[2] + " must be a whole number in [1, 1000000]");
    }
    if (!(nd >= 1 && nd <= 1e6) || std::floor(nd) != nd)
      throw InputError(opt, spec, "N = " + parts[2] + " must be a whole number in [1, 1000000]");
    const auto n = static_cast<std::size_t>(nd);
    if (log && !((from > 0 && to > 0) || (from < 0 && to < 0)))
      throw InputError(opt, spec, "a logarithmic range needs FROM and TO of one sign, neither 0");
    for (std::size_t i = 0; i < n; ++i) {
      const double t = n == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(n - 1);
      double v = log ? from * std::pow(to / from, t) : from + (to - from) * t;
      if (i + 1 == n) v = to;  // the end exactly as written
      if (i == 0) v = from;
      a.values.emplace_back(v);
    }
  } else {
    if (log) throw InputError(opt, spec, "--vary-log takes a range FROM:TO:N");
    for (const auto& item : split(rhs, ',')) {
      if (item.empty()) throw InputError(opt, spec, "an empty value in the list");
      a.values.push_back(value_of(a.key, item));
    }
  }
  if (a.values.empty()) throw InputError(opt, spec, "no values");
  return a;
}

std::vector<SceneSetting> Plan::settings(std::size_t i) const {
  std::vector<SceneSetting> s;
  s.reserve(keys.size());
  for (std::size_t k = 0; k < keys.size(); ++k) s.emplace_back(keys[k], points.at(i)[k]);
  return s;
}

Plan cartesian(const std::vector<Axis>& axes) {
  Plan p;
  std::size_t n = 1;
  for (const auto& a : axes) {
    for (const auto& k : p.keys)
      if (k == a.key) throw InputError("--vary", a.key, "the key is varied twice");
    p.keys.push_back(a.key);
    n *= a.values.size();
    if (n > kMaxPoints) throw InputError("--vary", a.key, "the grid exceeds 100000000 points");
  }
  if (axes.empty()) n = 1;  // no axis: the scene alone
  p.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<SceneValue> pt;
    std::size_t rest = i;
    std::vector<std::size_t> idx(axes.size());
    for (std::size_t k = axes.size(); k-- > 0;) {
      idx[k] = rest % axes[k].values.size();
      rest /= axes[k].values.size();
    }
    for (std::size_t k = 0; k < axes.size(); ++k) pt.push_back(axes[k].values[idx[k]]);
    p.points.push_back(std::move(pt));
  }
  return p;
}

Plan points_from_csv(const std::filesystem::path& path) {
  // Through the guarded reader: a regular file of at most 4 GiB (never a FIFO or /dev/zero).
  InputFile file(path, "--points", kMaxTableBytes);
  // One record at a time (RFC 4180: quoted keys and values, CRLF, a byte order mark; blank
  // lines skipped), so the file is never held whole.
  csv::Reader reader(file.stream(), "--points " + path.string());
  csv::Record rec;
  Plan p;
  if (!reader.next(rec)) throw InputError("--points", path.string(), "empty file: the first line names the keys");
  p.keys = rec.fields;
  for (std::size_t j = 0; j < p.keys.size(); ++j) {
    if (p.keys[j].empty()) throw InputError("--points", path.string(), "an empty key in the header");
    for (std::size_t k = 0; k < j; ++k)
      if (p.keys[k] == p.keys[j])
        throw InputError("--points", path.string() + ":1",
                         "the key " + p.keys[j] + " is in the header twice (columns " + std::to_string(k + 1) +
                             " and " + std::to_string(j + 1) + "): a point gives each key one value");
  }
  while (reader.next(rec)) {
    const auto& cells = rec.fields;
    if (cells.size() != p.keys.size())
      throw InputError("--points", path.string() + ":" + std::to_string(rec.line),
                       "has " + std::to_string(cells.size()) + " cells; the header has " + std::to_string(p.keys.size()));
    std::vector<SceneValue> pt;
    for (std::size_t k = 0; k < cells.size(); ++k) pt.push_back(value_of(p.keys[k], cells[k]));
    p.points.push_back(std::move(pt));
    if (p.points.size() > kMaxPoints) throw InputError("--points", path.string(), "more than 100000000 points");
  }
  if (p.points.empty()) throw InputError("--points", path.string(), "no points after the header");
  return p;
}

std::vector<std::size_t> shard_points(std::size_t n, std::size_t index, std::size_t count) {
  std::vector<std::size_t> out;
  for (std::size_t i = index; i < n; i += count) out.push_back(i);
  return out;
}

}  // namespace nanopush::sweep
