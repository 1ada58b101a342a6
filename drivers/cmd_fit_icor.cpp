// nanopush fit-icor DATA.csv: the friction coefficient from N quasi-static push observations
// (push force with the push offset yn and/or the observed iCOR distance R), for the thesis'
// known and unknown pressure distributions, combined by inverse-variance weighting with a
// chi^2 consistency check (models/icor_batch.hpp; docs/fitting.md, "Quasi-static estimates in
// batch (fit-icor)").
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_checks.hpp"
#include "icor_common.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/models/icor_batch.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/json.hpp"
#include "nanopush/outputs/plot.hpp"
#include "columns.hpp"
#include "registry.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct Options {
  std::string data;
  std::string pressure = "both";
  std::vector<std::string> sigma;
  icor::Rod rod;
  double length_sigma = 0.0, hamaker_sigma = 0.0;
  double alpha = 0.01;
  std::string json, out, format = "png";
};

// ---- reading the data ----------------------------------------------------------------------

const std::vector<std::string> kValues = {"F", "yn", "R"};
const std::map<std::string, std::string> kUnit = {{"F", "N"}, {"yn", "m"}, {"R", "m"}};

/// A finite number or nothing (empty cell); anything else is bad input naming the place.
std::optional<double> number(const std::string& cell, const std::string& where) {
  if (cell.empty()) return std::nullopt;
  errno = 0;
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (end == cell.c_str() || *end != '\0' || errno == ERANGE || !std::isfinite(v))
    throw InputError(where, cell, "must be a finite number");
  return v;
}

struct Data {
  std::vector<icor::Observation> obs;
  std::vector<int> lines;  ///< file line of each row
  bool has_yn = false, has_R = false;
};

std::map<std::string, double> parse_sigma_options(const std::vector<std::string>& items) {
  std::map<std::string, double> out;
  for (const auto& item : items) {
    const auto eq = item.find('=');
    const std::string key = eq == std::string::npos ? item : item.substr(0, eq);
    if (eq == std::string::npos || !kUnit.count(key))
      throw InputError("--sigma", item, "must be F=VALUE, yn=VALUE or R=VALUE (standard uncertainty, SI)");
    const auto v = number(item.substr(eq + 1), "--sigma " + key);
    if (!v || !(*v > 0.0)) throw InputError("--sigma " + key, item.substr(eq + 1), "must be > 0 (" + kUnit.at(key) + ")");
    if (out.count(key)) throw InputError("--sigma", item, "given twice for " + key);
    out[key] = *v;
  }
  return out;
}

Data read_data(const std::string& path, const std::map<std::string, double>& sigma_opt) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) throw InputError("DATA", path, "must be an existing regular file (CSV)");
  if (fs::file_size(path, ec) > (64u << 20)) throw InputError("DATA", path, "must be at most 64 MiB");
  std::ifstream in(path);
  if (!in) throw InputError("DATA", path, "cannot be read");
  // Records (RFC 4180, csv_reader.hpp); '#' comments and blank lines skipped.
  csv::ReadOptions ro;
  ro.comments = true;
  csv::Reader reader(in, path, ro);
  csv::Record rec;
  if (!reader.next(rec)) throw InputError("DATA", path, "has no header line");
  const std::vector<std::string> header = rec.fields;
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string& h = header[i];
    const bool known = kUnit.count(h) || (h.rfind("sigma_", 0) == 0 && kUnit.count(h.substr(6)));
    if (!known)
      throw InputError(path + ": column " + std::to_string(i + 1), h.empty() ? "\"\"" : h,
                       "must be one of F, yn, R, sigma_F, sigma_yn, sigma_R");
    if (col.count(h)) throw InputError(path + ": column " + std::to_string(i + 1), h, "appears twice");
    col[h] = i;
  }
  if (!col.count("F")) throw InputError(path + ": column F", "missing", "the push force column F [N] is required");
  Data d;
  d.has_yn = col.count("yn") > 0;
  d.has_R = col.count("R") > 0;
  if (!d.has_yn && !d.has_R)
    throw InputError(path + ": columns yn, R", "missing", "need yn (push offset) or R (iCOR distance), or both");
  for (const auto& q : kValues) {
    const bool has_value = col.count(q) > 0, has_col = col.count("sigma_" + q) > 0, has_opt = sigma_opt.count(q) > 0;
    if (has_col && has_opt)
      throw InputError("--sigma " + q, fmt(sigma_opt.at(q)),
                       "contradicts the column sigma_" + q + " of " + path + ": give one or the other");
    if (has_col && !has_value)
      throw InputError(path + ": column sigma_" + q, "present", "column " + q + " is missing");
    if (has_value && !has_col && !has_opt)
      throw InputError(path + ": column sigma_" + q, "missing",
                       "give the column or --sigma " + q + "=VALUE (standard uncertainty, " + kUnit.at(q) + ")");
  }
  int row = 0;
  while (reader.next(rec)) {
    ++row;
    const int lineno = static_cast<int>(rec.line);
    const std::vector<std::string>& cells = rec.fields;
    const std::string at = path + ": row " + std::to_string(row) + " (line " + std::to_string(lineno) + ")";
    if (cells.size() != header.size())
      throw InputError(at, std::to_string(cells.size()) + " cells",
                       "must have " + std::to_string(header.size()) + " cells, one per column");
    auto get = [&](const std::string& q) -> std::optional<icor::Measured> {
      if (!col.count(q)) return std::nullopt;
      const auto v = number(cells[col.at(q)], at + ", column " + q);
      const std::string sq = "sigma_" + q;
      std::optional<double> s;
      if (col.count(sq)) s = number(cells[col.at(sq)], at + ", column " + sq);
      else s = sigma_opt.at(q);
      if (!v) return std::nullopt;  // not observed in this row (its sigma cell, if any, is not used)
      if (!s) throw InputError(at + ", column " + sq, "empty", "must be > 0 (" + kUnit.at(q) + ")");
      if (!(*s > 0.0)) throw InputError(at + ", column " + sq, fmt(*s), "must be > 0 (" + kUnit.at(q) + ")");
      return icor::Measured{*v, *s};
    };
    icor::Observation o;
    const auto F = get("F");
    if (!F) throw InputError(at + ", column F", "empty", "the push force is required in every row");
    if (!(F->value > 0.0)) throw InputError(at + ", column F", fmt(F->value), "must be > 0 (N)");
    o.force = *F;
    o.yn = get("yn");
    o.R = get("R");
    if (o.yn && !(o.yn->value >= 0.0))
      throw InputError(at + ", column yn", fmt(o.yn->value), "must be >= 0 (m)");
    if (o.R && !(o.R->value > 0.0)) throw InputError(at + ", column R", fmt(o.R->value), "must be > 0 (m)");
    if (!o.yn && !o.R) throw InputError(at + ", columns yn, R", "both empty", "need yn or R in every row");
    d.obs.push_back(o);
    d.lines.push_back(lineno);
  }
  if (d.obs.size() < 2)
    throw InputError(path + ": rows", std::to_string(d.obs.size()),
                     "need at least 2 observations (for one, use nanopush icor estimate-mu)");
  return d;
}

// ---- output -----------------------------------------------------------------------------

std::string summary_json(const Options& o, const Data& d, const std::vector<icor::BatchEstimate>& est) {
  json doc = {{"data", o.data},
              {"rows", d.obs.size()},
              {"alpha", json_number(o.alpha)},
              {"load", json_number(o.rod.load())},
              {"rod",
               {{"length", json_number(o.rod.length)},
                {"radius", json_number(o.rod.radius)},
                {"density", json_number(o.rod.density)},
                {"hamaker", json_number(o.rod.hamaker)},
                {"z0", json_number(o.rod.z0)},
                {"gravity", json_number(o.rod.gravity)},
                {"length_sigma", json_number(o.length_sigma)},
                {"hamaker_sigma", json_number(o.hamaker_sigma)}}}};
  for (const auto& e : est) {
    std::map<std::string, int> eqs;
    for (const auto& r : e.rows) ++eqs[r.equation];
    json equations = json::object();
    for (const auto& [k, n] : eqs) equations[k] = n;
    doc[icor::to_string(e.pressure)] = {{"mu", {{"value", json_number(e.mu)}, {"stderr", json_number(e.sigma)}}},
                                        {"stderr_statistical", json_number(e.sigma_stat)},
                                        {"stderr_systematic", json_number(e.sigma_syst)},
                                        {"stderr_scaled", json_number(e.sigma_scaled)},
                                        {"chi2", json_number(e.chi2)},
                                        {"dof", e.dof},
                                        {"chi2_dof", json_number(e.chi2_dof)},
                                        {"p_value", json_number(e.p_value)},
                                        {"consistent", e.consistent},
                                        {"equations", std::move(equations)}};
  }
  return json_text(doc);
}

void write_outputs(const Options& o, const Data& d, const std::vector<icor::BatchEstimate>& est) {
  const fs::path dir(o.out);
  fs::create_directories(dir);
  const fs::path csv = dir / "fit_icor.csv";
  Columns cols = columns("fit_icor");
  for (const auto& e : est) {
    const std::string p = icor::to_string(e.pressure);
    cols.push_back({"mu_" + p, "1", "friction coefficient of this row, " + p + " pressure distribution"});
    cols.push_back({"sigma_" + p, "1", "its first-order standard uncertainty (F, yn, R; rod taken as exact)"});
    cols.push_back(text_column("equation_" + p, "thesis equation used: 4.8, 4.10 or 4.11"));
    cols.push_back({"weight_" + p, "1", "normalised inverse-variance weight in the combination"});
    cols.push_back({"pull_" + p, "1", "(mu_row - mu_combined) / sigma_row"});
  }
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < d.obs.size(); ++i) {
    const auto& ob = d.obs[i];
    std::vector<std::string> r = {std::to_string(i + 1), std::to_string(d.lines[i]), csv_number(ob.force.value),
                                  csv_number(ob.force.sigma)};
    for (const auto& m : {ob.yn, ob.R}) {
      r.push_back(m ? csv_number(m->value) : "");
      r.push_back(m ? csv_number(m->sigma) : "");
    }
    for (const auto& e : est) {
      const auto& x = e.rows[i];
      r.insert(r.end(), {csv_number(x.estimate.mu), csv_number(x.estimate.sigma), x.equation, csv_number(x.weight),
                         csv_number(x.pull)});
    }
    rows.push_back(std::move(r));
  }
  RunInfo run;
  for (const auto& e : est) {
    const std::string p = icor::to_string(e.pressure);
    run.push_back({"mu_" + p, e.mu});
    run.push_back({"stderr_" + p, e.sigma});
    if (std::isfinite(e.chi2_dof)) run.push_back({"chi2_dof_" + p, e.chi2_dof});
  }
  write_csv_atomic(csv, cols, rows, {}, run);
  write_file_atomic(dir / "fit_icor.json", summary_json(o, d, est));
  if (!plot::available()) {
    std::cerr << "nanopush fit-icor: gnuplot not found: fit_icor.png not drawn\n";
    return;
  }
  std::ostringstream g;
  g << "set grid\nset key outside right top box\nset datafile separator ','\n"
    << "set title " << icor_cli::gp_quote("friction coefficient per observation and combined (" + o.data + ")") << "\n"
    << "set xlabel 'observation'\nset ylabel '{/Symbol m}'\nset xrange [0.5:" << static_cast<double>(d.obs.size()) + 0.5 << "]\nplot ";
  const char* colours[] = {"#1f77b4", "#d62728"};
  for (std::size_t k = 0; k < est.size(); ++k) {
    const auto& e = est[k];
    const std::string p = icor::to_string(e.pressure), c = colours[k % 2];
    const std::size_t mu_col = 9 + 5 * k;  // 1-based: row, line, F, sF, yn, syn, R, sR, then 5 per distribution
    const double dx = est.size() > 1 ? (k == 0 ? -0.12 : 0.12) : 0.0;
    g << (k ? ", \\\n     " : "") << icor_cli::gp_quote(csv.string()) << " every ::1 using ($1+" << dx << "):"
      << mu_col << ":" << mu_col + 1 << " with yerrorbars pt 7 lc rgb '" << c << "' title "
      << icor_cli::gp_quote(p + " pressure: rows (1 sigma)") << ", \\\n     " << csv_number(e.mu) << " with lines lw 2 lc rgb '"
      << c << "' title " << icor_cli::gp_quote(p + ": combined") << ", \\\n     " << csv_number(e.mu + e.sigma)
      << " with lines dt 2 lc rgb '" << c << "' title " << icor_cli::gp_quote(p + ": combined +- 1 sigma") << ", \\\n     "
      << csv_number(e.mu - e.sigma) << " with lines dt 2 lc rgb '" << c << "' notitle";
  }
  g << "\n";
  plot::render_script(g.str(), dir / "fit_icor.png", 1000, 600);
}

int run(const Options& o) {
  plot::set_format(plot::parse_format(o.format));
  o.rod.validate();
  std::vector<icor::Pressure> which;
  if (o.pressure == "both") which = {icor::Pressure::Known, icor::Pressure::Unknown};
  else which = {icor::parse_pressure(o.pressure, "--pressure")};
  const auto sigma_opt = parse_sigma_options(o.sigma);
  const Data d = read_data(o.data, sigma_opt);
  if (!d.has_yn && std::find(which.begin(), which.end(), icor::Pressure::Unknown) != which.end())
    throw InputError(o.data + ": column yn", "missing",
                     "the unknown pressure distribution (eq 4.11) needs the push offset yn; or use --pressure known");
  std::vector<icor::BatchEstimate> est;
  for (const auto p : which) {
    try {
      est.push_back(icor::estimate_mu_batch(o.rod, d.obs, p, o.length_sigma, o.hamaker_sigma, o.alpha));
    } catch (const InputError& e) {
      // "row N: ..." -> name the file and its line
      std::string msg = e.what();
      if (msg.rfind("row ", 0) == 0) {
        const auto colon = msg.find(':');
        const int r = std::atoi(msg.c_str() + 4);
        if (r >= 1 && r <= static_cast<int>(d.lines.size()))
          msg = o.data + ": row " + std::to_string(r) + " (line " + std::to_string(d.lines[r - 1]) + ")" +
                msg.substr(colon);
      }
      throw InputError(msg + " [" + icor::to_string(p) + " pressure]");
    }
  }
  std::ostringstream s;
  s << std::setprecision(6);
  s << "friction coefficient from " << d.obs.size() << " quasi-static observations (" << o.data << "), load W = "
    << o.rod.load() << " N\n";
  for (const auto& e : est) {
    std::map<std::string, int> eqs;
    for (const auto& r : e.rows) ++eqs[r.equation];
    s << "  " << icor::to_string(e.pressure) << " pressure (eq";
    for (const auto& [k, n] : eqs) s << " " << k << " x" << n;
    s << "): mu = " << e.mu << " +- " << e.sigma << " (statistical " << e.sigma_stat << ", systematic "
      << e.sigma_syst << ")\n    chi2/dof = " << e.chi2_dof << " (dof " << e.dof << "), p = " << e.p_value << ": "
      << (e.consistent ? "consistent" : "INCONSISTENT at alpha = " + fmt(o.alpha) + "; Birge-scaled stderr " +
                                            fmt(e.sigma_scaled))
      << "\n";
  }
  std::cout << s.str();
  if (!o.out.empty()) write_outputs(o, d, est);
  if (!o.json.empty()) write_file_atomic(o.json, summary_json(o, d, est));
  return 0;
}

RegisterCommand reg{{"fit-icor",
                     "Friction coefficient from N quasi-static push observations (force with push offset and/or "
                     "iCOR distance), known and unknown pressure distributions, combined with a chi^2 check",
                     42, options_then<Options>(run, [](CLI::App& app, Options& o) {
                       app.add_option("data", o.data,
                                      "CSV: columns F [N] and yn and/or R [m], optional sigma_F, sigma_yn, sigma_R; "
                                      "an empty yn or R cell means not observed (docs/fitting.md)")
                           ->required();
                       app.add_option("--pressure", o.pressure,
                                      "known (eqs 4.8, 4.10) | unknown (eqs 4.11, 4.13) | both")
                           ->check(CLI::IsMember({"known", "unknown", "both"}))
                           ->capture_default_str();
                       app.add_option("--sigma", o.sigma,
                                      "standard uncertainty for a quantity without a sigma column: F=VALUE, yn=VALUE, "
                                      "R=VALUE (SI, > 0; one or more)");
                       icor_cli::add_rod_options(app, o.rod);
                       app.add_option("--length-sigma", o.length_sigma,
                                      "standard uncertainty of L [m]: systematic, added after the combination")
                           ->check(non_negative())
                           ->capture_default_str();
                       app.add_option("--hamaker-sigma", o.hamaker_sigma,
                                      "standard uncertainty of H [J]: systematic, added after the combination")
                           ->check(non_negative())
                           ->capture_default_str();
                       app.add_option("--alpha", o.alpha,
                                      "significance level of the chi^2 consistency check (0, 1)")
                           ->check(real_in(0.0, 1.0, true, true))
                           ->capture_default_str();
                       app.add_option("--json", o.json, "write the JSON summary to this file");
                       app.add_option("--out", o.out,
                                      "directory for fit_icor.csv (+ .schema.json), fit_icor.json and fit_icor.png");
                       app.add_option("--format", o.format, "figure format of fit_icor: png, svg or pdf (default png)");
                     })}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
