// Sweep plans: axes, cartesian grids, point lists; shards.
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/sweeps/sweep.hpp"
#include "hash.hpp"
#include "points_table.hpp"

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
  a.spec = (log ? "log:" : "") + spec;
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
    for (std::size_t i = 0; i < n; ++i)
      a.values.emplace_back(log ? geomspace_value(from, to, n, i) : linspace_value(from, to, n, i));
  } else {
    if (log) throw InputError(opt, spec, "--vary-log takes a range FROM:TO:N");
    for (const auto& item : split(rhs, ',')) {
      if (item.empty()) throw InputError(opt, spec, "an empty value in the list");
      a.values.push_back(point_value(a.key, item));
    }
  }
  if (a.values.empty()) throw InputError(opt, spec, "no values");
  return a;
}

double linspace_value(double from, double to, std::size_t n, std::size_t i) {
  // numpy.linspace (endpoint=True): step = (stop - start) / (n - 1); y = i * step + start, or
  // (i / (n - 1)) * delta + start when the step underflows to 0; the last value is stop.
  if (n <= 1 || i == 0) return from;
  if (i + 1 == n) return to;
  const double div = static_cast<double>(n - 1), delta = to - from, step = delta / div;
  const double y = static_cast<double>(i);
  return step == 0 ? (y / div) * delta + from : y * step + from;
}

double geomspace_value(double from, double to, std::size_t n, std::size_t i) {
  // numpy.geomspace: both negative -> the positive sequence negated; 10^linspace(log10 start,
  // log10 stop); the first and last values exactly start and stop.
  if (n <= 1 || i == 0) return from;
  if (i + 1 == n) return to;
  const double sign = (from < 0 && to < 0) ? -1.0 : 1.0;
  const double y = linspace_value(std::log10(sign * from), std::log10(sign * to), n, i);
  return sign * std::pow(10.0, y);
}

std::size_t Plan::size() const {
  if (table) return table->size();
  if (!grid) return points.size();
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<SceneValue> Plan::point(std::size_t i) const {
  if (table) return table->row(i);
  if (!grid) return points.at(i);
  if (i >= size()) throw std::out_of_range("plan point " + std::to_string(i));
  std::vector<SceneValue> pt(axes.size(), SceneValue(0.0));
  std::size_t rest = i;
  for (std::size_t k = axes.size(); k-- > 0;) {
    pt[k] = axes[k].values[rest % axes[k].values.size()];
    rest /= axes[k].values.size();
  }
  return pt;
}

std::vector<SceneSetting> Plan::settings(std::size_t i) const {
  const auto pt = point(i);
  std::vector<SceneSetting> s;
  s.reserve(keys.size());
  for (std::size_t k = 0; k < keys.size() && k < pt.size(); ++k) s.emplace_back(keys[k], pt[k]);
  return s;
}

void Plan::for_each_value(const std::function<void(const std::string&, const SceneValue&)>& f) const {
  if (grid && !table) {
    for (const auto& a : axes)
      for (const auto& v : a.values) f(a.key, v);
    return;
  }
  const std::size_t n = size();
  for (std::size_t i = 0; i < n; ++i) {
    const auto pt = point(i);
    for (std::size_t j = 0; j < pt.size() && j < keys.size(); ++j) f(keys[j], pt[j]);
  }
}

std::string Plan::identity_text() const {
  std::string s = "keys";
  for (const auto& k : keys) s += " " + k;
  s += "\npoints " + std::to_string(size()) + "\n";
  if (grid && !table) {
    for (const auto& a : axes) {
      s += "axis " + a.key + ":";
      for (const auto& v : a.values) {
        s += ' ';
        s += v.to_string();
      }
      s += "\n";
    }
    return s;
  }
  std::uint64_t h = kFnvBasis;
  if (table) {
    h = table->hash();
  } else {
    for (const auto& pt : points)
      for (std::size_t k = 0; k < pt.size(); ++k) {
        h = fnv1a(pt[k].to_string(), h);
        h = fnv1a(k + 1 < pt.size() ? "," : "\n", h);
      }
  }
  return s + "list " + hex(h) + "\n";
}

std::vector<std::pair<std::string, std::string>> Plan::describe() const {
  std::vector<std::pair<std::string, std::string>> d;
  if (grid && !table) {
    d.emplace_back("plan", "grid (the last axis fastest)");
    for (std::size_t k = 0; k < axes.size(); ++k) {
      const auto& a = axes[k];
      std::string v = a.spec;
      if (v.empty()) {
        v = a.key + "=";
        for (std::size_t j = 0; j < a.values.size(); ++j) {
          if (j) v += ',';
          v += a.values[j].to_string();
        }
      }
      d.emplace_back("axis " + std::to_string(k + 1), v);
    }
  } else {
    d.emplace_back("plan", table ? "points " + source : "points (a list)");
    std::string keylist;
    for (const auto& k : keys) keylist += (keylist.empty() ? "" : ",") + k;
    d.emplace_back("keys", keylist);
    const std::string t = identity_text();
    d.emplace_back("points_hash", t.substr(t.rfind("list ") + 5, 16));
  }
  d.emplace_back("plan_points", std::to_string(size()));
  return d;
}

Plan cartesian(const std::vector<Axis>& axes) {
  Plan p;
  p.grid = true;
  std::size_t n = 1;
  for (const auto& a : axes) {
    for (const auto& k : p.keys)
      if (k == a.key) throw InputError("--vary", a.key, "the key is varied twice");
    p.keys.push_back(a.key);
    n *= a.values.size();
    if (n > kMaxPoints) throw InputError("--vary", a.key, "the grid exceeds 100000000 points");
  }
  p.axes = axes;
  return p;
}

Plan points_from_csv(const std::filesystem::path& path) {
  Plan p;
  p.source = path.string();
  p.table = std::make_shared<PointTable>(path, p.keys);
  return p;
}

std::vector<std::size_t> shard_points(std::size_t n, std::size_t index, std::size_t count) {
  std::vector<std::size_t> out;
  for (std::size_t i = index; i < n; i += count) out.push_back(i);
  return out;
}

}  // namespace nanopush::sweep
