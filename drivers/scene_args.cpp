#include "scene_args.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "nanopush/numerics/error.hpp"
#include "registry.hpp"

namespace nanopush::cli {

void add_set_option(CLI::App& app, std::vector<std::string>& sets) {
  app.add_option("--set", sets,
                 "KEY=VALUE: set a scene key after loading, validated as in the file (repeatable; e.g. "
                 "--set surface.mu=0.1 --set push.yn=20e-9; `nanopush scene-keys` lists the keys)")
      ->type_name("KEY=VALUE");
}

std::vector<SceneSetting> parse_settings(const std::vector<std::string>& sets, const std::string& option) {
  std::vector<SceneSetting> out;
  for (const auto& s : sets) {
    const auto eq = s.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(option, s, "must be KEY=VALUE, e.g. surface.mu=0.1");
    const std::string key = s.substr(0, eq);
    out.emplace_back(key, SceneValue::from_text(key, s.substr(eq + 1)));
  }
  return out;
}

Scene load_scene_arg(const std::string& scene, const std::vector<std::string>& sets) {
  Scene sc = load_scene(resolve_scene(scene));
  if (!sets.empty()) sc.set(parse_settings(sets));
  return sc;
}

void add_accuracy_options(CLI::App& app, double& accuracy, bool& no_estimate) {
  app.add_option("--accuracy", accuracy,
                 "the error asked for of the final pose (positions relative to max(object length, distance "
                 "travelled), angle in rad), in [1e-14, 0.1]: rtol (and under method auto the method) is chosen to "
                 "reach it, checked by companion runs (docs/accuracy.md); default: the scene's solver.accuracy "
                 "(0: run at rtol)")
      ->check(CLI::Range(0.0, kAccuracyMax));
  app.add_flag("--no-error-estimate", no_estimate,
               "skip the companion run at rtol/100 that estimates the error of the answer (about halves the cost)");
}

void print_error_estimate(const Trajectory& tr, std::ostream& os) {
  const ErrorEstimate& e = tr.error;
  os << std::setprecision(3);
  if (tr.accuracy.requested > 0)
    os << "  accuracy asked " << tr.accuracy.requested << ": " << (tr.accuracy.reached ? "reached" : "NOT reached")
       << " with rtol " << tr.accuracy.rtol_used << " (" << tr.accuracy.runs << " runs, " << tr.nfcn_total()
       << " RHS evaluations in all)\n";
  if (e.available && e.basis == "exact") {
    os << "  error of the final pose 0: " << e.note << "\n";
  } else if (e.available) {
    os << "  error estimate of the final pose " << e.norm << " (|dx| " << e.x << " m, |dy| " << e.y
       << " m, |dtheta| " << e.theta << " rad; lengths over " << e.length_scale << " m), over the trajectory "
       << e.trajectory << (e.basis == "looser" ? "; the difference from the looser run [" : "; from a companion run [")
       << e.companion << "] at rtol " << e.companion_rtol << " (" << e.nfcn << " RHS evaluations beside the answer's)\n";
    if (!e.note.empty()) os << "  (" << e.note << ")\n";
  } else if (!e.note.empty()) {
    os << "  no error estimate: " << e.note << "\n";
  }
}

/// Why a rough run under the thesis (or printed) law gave up, when the bar came to rest: the sign
/// law of eq 3.40 has no direction at zero velocity, so once friction can hold the push
/// (mu N > F) the integrator chatters about rest until its step budget is spent
/// (docs/rough.md). Says where it came to rest and what continues honestly.
void print_rest_diagnosis(const Scene& sc, Law law, const Trajectory& tr, std::ostream& os) {
  if (!sc.rough() || law == Law::coulomb || tr.rows.size() < 2 || tr.stats.status != BsStatus::too_many_steps) return;
  const double muN = sc.friction_limit();
  if (!(muN > sc.push.force)) return;
  // The first sample from which the speed stays below 1e-3 of the largest speed of the run.
  const auto speed = [&](const TrajectoryRow& r) {
    const double L = std::max(sc.geometry.a, sc.geometry.b);
    return std::hypot(r[col::vx], r[col::vy]) + std::fabs(r[col::omega]) * L;
  };
  double vmax = 0;
  for (const auto& r : tr.rows) vmax = std::max(vmax, speed(r));
  std::size_t rest = tr.rows.size() - 1;
  while (rest > 0 && speed(tr.rows[rest - 1]) <= 1e-3 * vmax) --rest;
  const auto& r = tr.rows[rest];
  os << std::setprecision(6) << "  the bar came to rest near t = " << r[col::t] << " s at x = " << r[col::x] << " m, y = " << r[col::y]
     << " m, theta = " << r[col::theta] << " rad (last sample t = " << tr.rows.back()[col::t] << " s): mu N = " << muN
     << " N exceeds the push F = " << sc.push.force
     << " N, and the sign law of eq 3.40 has no direction at rest, so the integrator chatters there\n"
     << "  to continue: --law coulomb (event-located stick-slip: the bar stays stuck or slides off honestly; "
        "docs/rough.md)\n";
}

}  // namespace nanopush::cli
