#include "bench/bench.hpp"

#include <algorithm>
#include <array>
#include <functional>
#include <sstream>
#include <cmath>
#include <limits>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/plot.hpp"
#include "columns.hpp"

namespace nanopush::bench {

std::vector<double> Problem::atol(double rtol) const {
  std::vector<double> a(scale.size());
  for (std::size_t i = 0; i < scale.size(); ++i) a[i] = rtol * scale[i];
  return a;
}

double scaled_max_error(const Problem& p, const std::vector<quad>& a, const std::vector<quad>& b) {
  const std::size_t n = static_cast<std::size_t>(p.n);
  const std::size_t want = p.nout() * n;
  if (a.size() != want || b.size() != want)
    throw InputError("trajectory size", std::to_string(a.size()) + " / " + std::to_string(b.size()),
                     "must be nout * n = " + std::to_string(want));
  quad e = 0;
  for (std::size_t k = 0; k < p.nout(); ++k)
    for (std::size_t i = 0; i < n; ++i) {
      const quad d = num::abs(a[k * n + i] - b[k * n + i]) / (quad(p.scale[i]) + num::abs(b[k * n + i]));
      if (!num::isfinite(d)) return std::numeric_limits<double>::infinity();
      e = std::max(e, d);
    }
  return static_cast<double>(e);
}

Acceptance accept_reference(const Problem& p, const std::vector<quad>& a, const std::vector<quad>& b,
                            double smallest_error) {
  Acceptance acc;
  acc.disagreement = scaled_max_error(p, a, b);
  acc.threshold = 1e-3 * smallest_error;
  acc.accepted = std::isfinite(acc.disagreement) && smallest_error > 0 && acc.disagreement <= acc.threshold;
  acc.explanation = "two reference runs disagree by " + fmt(acc.disagreement) + " (weighted max-abs); 1e-3 of the smallest "
                    "plotted error " + fmt(smallest_error) + " is " + fmt(acc.threshold) + ": " +
                    (acc.accepted ? "accepted" : "REJECTED");
  return acc;
}

Reference extended_reference(const Problem& p, const Solve& a, const Solve& b, const std::string& how) {
  if (a.status != 0 || b.status != 0)
    throw SolverError("extended-precision reference failed: " + (a.status != 0 ? a.message : b.message));
  Reference r;
  r.kind = "extended";
  r.how = how;
  r.y = a.y;
  r.disagreement = scaled_max_error(p, a.y, b.y);
  return r;
}

double smallest_plotted_error(const std::vector<Row>& rows) {
  double m = std::numeric_limits<double>::infinity();
  for (const auto& r : rows)
    if (r.status == 0 && r.precision == Precision::double_ && std::isfinite(r.error) && r.error > 0) m = std::min(m, r.error);
  return m;
}

Acceptance accept_reference(const Reference& ref, const std::vector<Row>& rows) {
  Acceptance acc;
  const double smallest = smallest_plotted_error(rows);
  acc.disagreement = ref.disagreement;
  acc.threshold = 1e-3 * smallest;
  if (ref.kind == "exact") {
    acc.accepted = true;
    acc.explanation = "exact reference";
    return acc;
  }
  acc.accepted = std::isfinite(smallest) && ref.disagreement <= acc.threshold;
  acc.explanation = "two reference runs disagree by " + fmt(ref.disagreement) + " (weighted max-abs); 1e-3 of the "
                    "smallest plotted error " + fmt(smallest) + " is " + fmt(acc.threshold) + ": " +
                    (acc.accepted ? "accepted" : "REJECTED");
  return acc;
}

int mark_below_reference(const Reference& ref, std::vector<Row>& rows) {
  if (ref.kind == "exact") return 0;
  const double floor = 1e3 * ref.disagreement;
  int marked = 0;
  for (auto& r : rows)
    if (r.status == 0 && r.precision == Precision::double_ && std::isfinite(r.error) && r.error < floor) {
      r.status = kStatusBelowReference;
      ++marked;
    }
  return marked;
}

std::optional<double> overhead_within_from(const std::vector<Row>& rows, const std::string& engine,
                                           Precision precision, double bound_ns, double Row::*field) {
  if (!std::isfinite(bound_ns)) throw InputError("overhead bound", fmt(bound_ns), "must be a finite number of ns");
  // The engine's successful rows from the tightest tolerance up; the same rows as the
  // report's overhead table (status 0, at least one RHS call).
  std::vector<const Row*> v;
  for (const auto& r : rows)
    if (r.engine == engine && r.precision == precision && r.status == 0 && r.nfcn > 0) v.push_back(&r);
  std::sort(v.begin(), v.end(), [](const Row* a, const Row* b) { return a->rtol < b->rtol; });
  std::optional<double> from;
  for (const Row* r : v) {
    if (!(r->*field <= bound_ns)) break;
    from = r->rtol;
  }
  return from;
}

std::vector<double> tolerance_sweep(int kmin, int kmax, int kstep, double rtol_min) {
  if (kstep < 1) throw InputError("kstep", std::to_string(kstep), "must be >= 1");
  std::vector<double> v;
  for (int k = kmin; k <= kmax; k += kstep) {
    const double r = std::pow(10.0, -0.5 * k);
    if (r < rtol_min * (1 - 1e-9)) break;
    v.push_back(r);
  }
  return v;
}

const std::vector<std::string>& csv_columns() {
  static const std::vector<std::string> c = [] {
    std::vector<std::string> names;
    for (const auto& col : csv_column_specs()) names.push_back(col.name);
    return names;
  }();
  return c;
}

namespace {
double median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}
/// (Q3 - Q1) / median, quartiles by linear interpolation; NaN below 4 values.
double relative_iqr(std::vector<double> v) {
  if (v.size() < 4) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  const auto q = [&v](double f) {
    const double x = f * static_cast<double>(v.size() - 1);
    const auto i = static_cast<std::size_t>(x);
    const double r = x - static_cast<double>(i);
    return i + 1 < v.size() ? v[i] + r * (v[i + 1] - v[i]) : v[i];
  };
  const double med = median(v);
  return med > 0 ? (q(0.75) - q(0.25)) / med : std::numeric_limits<double>::quiet_NaN();
}
}  // namespace

std::vector<Row> run_sweep(const Problem& p, const std::vector<Engine>& engines, const Reference& ref,
                           const SweepSettings& s) {
  if (s.repeats < 1) throw InputError("repeats", std::to_string(s.repeats), "must be >= 1");
  if (s.repeats_extended < 0)
    throw InputError("repeats_extended", std::to_string(s.repeats_extended), "must be >= 0 (0 = repeats)");
  // Each engine's tolerances and repeats.
  struct Plan {
    const Engine* e;
    std::vector<double> rtols;
    int repeats;
  };
  std::vector<Plan> plans;
  for (const auto& e : engines) {
    const bool extended = e.precision != Precision::double_;
    const int kmax = extended ? std::max(s.kmax, s.kmax_extended) : s.kmax;
    const int kstep = extended && s.kstep_extended > 0 ? s.kstep_extended : s.kstep;
    plans.push_back({&e, tolerance_sweep(s.kmin, kmax, kstep, e.rtol_min),
                     extended && s.repeats_extended > 0 ? s.repeats_extended : s.repeats});
  }
  // One untimed solve per engine first: the first call of a process pays page faults,
  // lazy symbol binding and cold caches (several ms), which is not the integrator's cost.
  for (const auto& pl : plans)
    if (!pl.rtols.empty()) {
      const Solve w = pl.e->solve(pl.rtols.front());
      if (pl.e->time_rhs && w.nfcn > 0) (void)pl.e->time_rhs(w.nfcn);
    }
  // Tolerance by tolerance, the timed solves of the engines of one precision are
  // interleaved (repeat i of every engine, then repeat i+1): a change of machine load during
  // the sweep then reaches every engine compared at that tolerance alike, so their ratios
  // stay fair on a busy machine. Precisions run one after the other (a __float128 solve
  // between two double ones would leave them colder caches than their neighbours').
  std::vector<Precision> precisions;
  for (const auto& pl : plans)
    if (std::find(precisions.begin(), precisions.end(), pl.e->precision) == precisions.end())
      precisions.push_back(pl.e->precision);
  std::vector<std::vector<Row>> per_engine(plans.size());
  for (const Precision prec : precisions) {
    std::vector<double> all;
    for (const auto& pl : plans)
      if (pl.e->precision == prec) all.insert(all.end(), pl.rtols.begin(), pl.rtols.end());
    std::sort(all.begin(), all.end(), std::greater<>());
    all.erase(std::unique(all.begin(), all.end()), all.end());
    for (const double rtol : all) {
      struct Point {
        std::size_t engine;
        Row row;
        Solve first;
        std::vector<double> wall, rhs, own;
      };
      std::vector<Point> pts;
      int most = 0;
      for (std::size_t ie = 0; ie < plans.size(); ++ie)
        if (plans[ie].e->precision == prec &&
            std::find(plans[ie].rtols.begin(), plans[ie].rtols.end(), rtol) != plans[ie].rtols.end()) {
          Point pt;
          pt.engine = ie;
          pt.row.engine = plans[ie].e->name;
          pt.row.precision = plans[ie].e->precision;
          pt.row.rtol = rtol;
          pt.row.repeats = plans[ie].repeats;
          if (plans[ie].repeats > 1) (void)plans[ie].e->solve(rtol);  // warm-up at this tolerance
          pts.push_back(std::move(pt));
          most = std::max(most, plans[ie].repeats);
        }
      for (int i = 0; i < most; ++i)
        for (auto& pt : pts) {
          if (i >= plans[pt.engine].repeats) continue;
          Solve sv = plans[pt.engine].e->solve(rtol);
          pt.wall.push_back(sv.seconds);
          if (i == 0) pt.first = std::move(sv);
        }
      for (int i = 0; i < most; ++i)
        for (auto& pt : pts)
          if (i < plans[pt.engine].repeats && plans[pt.engine].e->time_rhs && pt.first.nfcn > 0)
            pt.rhs.push_back(plans[pt.engine].e->time_rhs(pt.first.nfcn));
      if (s.replay) {
        // The integrator alone: the recorded RHS values replayed (Engine::replay), the
        // engines interleaved as above.
        std::vector<std::function<double()>> timers(pts.size());
        for (std::size_t j = 0; j < pts.size(); ++j) {
          const Engine& e = *plans[pts[j].engine].e;
          if (e.replay && pts[j].first.status == 0 && pts[j].first.nfcn > 0) timers[j] = e.replay(rtol, pts[j].first);
        }
        for (int i = 0; i < most; ++i)
          for (std::size_t j = 0; j < pts.size(); ++j)
            if (timers[j] && i < plans[pts[j].engine].repeats) pts[j].own.push_back(timers[j]());
      }
      for (auto& pt : pts) {
        Row& r = pt.row;
        r.status = pt.first.status;
        r.nfcn = pt.first.nfcn;
        r.naccpt = pt.first.naccpt;
        r.nrejct = pt.first.nrejct;
        r.error = pt.first.status == 0 ? scaled_max_error(p, pt.first.y, ref.y) : std::numeric_limits<double>::quiet_NaN();
        r.wall_s = median(pt.wall);
        r.wall_spread = relative_iqr(pt.wall);
        r.rhs_s = median(pt.rhs);
        r.overhead_ns_per_rhs = r.nfcn > 0 ? (r.wall_s - r.rhs_s) / static_cast<double>(r.nfcn) * 1e9
                                           : std::numeric_limits<double>::quiet_NaN();
        if (!pt.own.empty()) r.own_ns_per_rhs = median(pt.own) / static_cast<double>(r.nfcn) * 1e9;
        if (s.progress) s.progress(r);
        per_engine[pt.engine].push_back(r);
      }
    }
  }
  // Rows grouped by engine, in the engines' order, each by decreasing rtol (the CSV layout).
  std::vector<Row> rows;
  for (auto& v : per_engine) rows.insert(rows.end(), v.begin(), v.end());
  return rows;
}

const Columns& csv_column_specs() {
  static const Columns c = cli::columns("bench");
  return c;
}

void write_csv(const std::vector<Row>& rows, const std::filesystem::path& path, const std::string& scene) {
  CsvWriter w(path, csv_column_specs(), scene);
  for (const auto& r : rows)
    w.cells({csv_quote(r.engine), csv_quote(to_string(r.precision)), csv_number(r.rtol), csv_number(r.error),
             std::to_string(r.nfcn), std::to_string(r.naccpt), std::to_string(r.nrejct), csv_number(r.wall_s),
             csv_number(r.rhs_s), csv_number(r.overhead_ns_per_rhs), std::to_string(r.repeats),
             std::to_string(r.status), csv_number(r.wall_spread), csv_number(r.own_ns_per_rhs)});
  w.commit();
}

namespace {
/// One distinct colour per line of the benchmark figures (gnuplot's default cycle repeats after 8).
constexpr std::array<const char*, 14> kColours = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd",
                                                  "#8c564b", "#e377c2", "#7f7f7f", "#bcbd22", "#17becf",
                                                  "#000000", "#aec7e8", "#ffbb78", "#98df8a"};
/// gnuplot enhanced text: a literal underscore.
std::string gp_text(const std::string& s) {
  std::string r;
  for (const char c : s) {
    if (c == '_') r += '\\';
    r += c;
  }
  return r;
}
}  // namespace

void plot_work_precision(const std::vector<Row>& rows, const std::filesystem::path& csv,
                         const std::filesystem::path& png, const std::string& title) {
  std::vector<std::pair<std::string, Precision>> lines;
  for (const auto& r : rows)
    if (std::find(lines.begin(), lines.end(), std::make_pair(r.engine, r.precision)) == lines.end())
      lines.emplace_back(r.engine, r.precision);
  plot::Figure fig;
  fig.title = gp_text(title);
  fig.cols = 2;
  fig.width = 1500;
  fig.height = 650;
  plot::Panel work, wall;
  work.title = "error against RHS evaluations";
  work.xlabel = "RHS evaluations";
  wall.title = "error against wall time (median of repeated solves)";
  wall.xlabel = "wall time [ms]";
  for (auto* p : {&work, &wall}) {
    p->ylabel = "error: max over outputs and components of |y - yref| / (scale + |yref|)";
    p->logx = p->logy = true;
    p->extra = "set key bottom left font ',8'\nset format y '10^{%L}'\nset format x '10^{%L}'";
  }
  // One distinct point type per line, beside its colour.
  static const char* points[] = {"5", "7", "9", "11", "13", "4", "6", "8", "10", "12", "2", "3", "1", "14"};
  std::size_t i = 0;
  for (const auto& [eng, prec] : lines) {
    const std::string filt =
        "(strcol(1) eq '" + eng + "' && strcol(2) eq '" + to_string(prec) + "' && $12 == 0 && $4 > 0 ? ";
    const std::string y = filt + "$4 : 1/0)";
    const std::string label = prec == Precision::double_ ? eng : eng + " (" + to_string(prec) + ")";
    const std::string style = std::string("linespoints lw 1.5 pt ") + points[i % 14] + " ps 0.8 lc rgb '" +
                              kColours[i % kColours.size()] + "'" + (prec == Precision::double_ ? "" : " dt 2");
    work.series.push_back({csv, "5", y, label, style});
    wall.series.push_back({csv, "($8*1e3)", y, label, style});
    ++i;
  }
  fig.panels = {work, wall};
  plot::render(fig, png);
}

void plot_overhead(const std::vector<Row>& rows, const std::filesystem::path& csv, const std::filesystem::path& png,
                   const std::string& title, double target_ns) {
  std::vector<std::string> engines;
  bool alone = false;
  for (const auto& r : rows)
    if (r.precision == Precision::double_) {
      if (std::find(engines.begin(), engines.end(), r.engine) == engines.end()) engines.push_back(r.engine);
      alone = alone || std::isfinite(r.own_ns_per_rhs);
    }
  if (engines.empty()) throw InputError("overhead plot", "(rows)", "needs rows in double precision");
  // One y range for both panels (so that they compare at a glance), in whole decades: from
  // below the smaller of the target and the smallest value to a decade above the largest
  // (room for the key).
  // The x range: the double rows' rtol span (the CSV also holds long/quad rows down to 1e-28).
  double lo = target_ns, hi = target_ns;
  double rlo = std::numeric_limits<double>::infinity(), rhi = 0;
  for (const auto& r : rows) {
    if (r.precision != Precision::double_) continue;
    if (r.rtol > 0) {
      rlo = std::min(rlo, r.rtol);
      rhi = std::max(rhi, r.rtol);
    }
    if (r.status == 0)
      for (const double v : {r.overhead_ns_per_rhs, r.own_ns_per_rhs})
        if (std::isfinite(v) && v > 0) {
          lo = std::min(lo, v);
          hi = std::max(hi, v);
        }
  }
  const double ylo = std::pow(10.0, std::floor(std::log10(lo) - 1e-9)), yhi = std::pow(10.0, std::ceil(std::log10(hi)) + 1);
  plot::Figure fig;
  fig.title = gp_text(title);
  fig.cols = alone ? 2 : 1;
  fig.width = alone ? 1500 : 900;
  fig.height = 650;
  plot::Panel sub, own;
  sub.title = "wall time minus as many bare RHS calls, per RHS call";
  own.title = "the integrator alone: RHS values of the same solve replayed (--replay)";
  for (auto* p : {&sub, &own}) {
    p->xlabel = "rtol";
    p->ylabel = "integrator overhead [ns per RHS evaluation]";
    p->logx = p->logy = true;
    // rtol decreases to the right, as the work-precision plots' error does to the left.
    std::ostringstream ex;
    ex << "set key top right font ',8'\nset format x '10^{%L}'\nset xrange [" << rhi * 2 << ":" << rlo / 2
       << "]\nset yrange [" << ylo << ":" << yhi << "]\n"
       << "set arrow from graph 0, first " << target_ns << " to graph 1, first " << target_ns
       << " nohead dt 2 lw 1.5 lc rgb 'black'\nset label 'target " << target_ns << " ns' at graph 0.02, first "
       << target_ns * 1.15 << " font ',9'";
    p->extra = ex.str();
  }
  std::size_t i = 0;
  for (const auto& eng : engines) {
    // Successful double rows; a non-positive value (a disturbed timing, or an RHS timed
    // through another path, f77-native) has no place on a log axis.
    const std::string filt = "(strcol(1) eq '" + eng + "' && strcol(2) eq 'double' && $12 == 0 && ";
    const std::string style = std::string("linespoints lw 1.5 pt 7 ps 0.6 lc rgb '") + kColours[i % kColours.size()] + "'";
    sub.series.push_back({csv, "3", filt + "$10 > 0 ? $10 : 1/0)", gp_text(eng), style});
    const bool has_own = std::any_of(rows.begin(), rows.end(), [&eng](const Row& r) {
      return r.engine == eng && r.precision == Precision::double_ && std::isfinite(r.own_ns_per_rhs);
    });
    if (alone && has_own) own.series.push_back({csv, "3", filt + "$14 > 0 ? $14 : 1/0)", gp_text(eng), style});
    ++i;
  }
  fig.panels = {sub};
  if (alone) fig.panels.push_back(own);
  plot::render(fig, png);
}

}  // namespace nanopush::bench
