// The dynamic tip-driven push's entry point (tip_dynamic.hpp; docs/tip.md): the input checked,
// then the run of tip_dynamic_run.hpp for a frictionless tip (eight state components) or one
// with tip friction (nine).
#include <cmath>
#include <string>

#include "tip_dynamic_run.hpp"

namespace nanopush::tip {

namespace {

using detail::fmt;
using dyn::DynamicTipRun;
using dyn::kFricStateSize;

template <int N>
DynamicRunResult run_impl(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                          double y0, double theta0, double t_end, int samples, double rtol, std::int64_t max_steps) {
  DynamicTipRun<N> run(g, muN, bar, tip, x0, y0, theta0, t_end, samples, rtol, max_steps);
  return run.run();
}

}  // namespace

DynamicRunResult run_dynamic(const BarGeometry& g, double muN, const DynamicBar& bar, const TipPath& tip, double x0,
                             double y0, double theta0, double t_end, int samples, double rtol,
                             std::int64_t max_steps) {
  tip.validate();
  if (!(std::isfinite(bar.stiffness) && bar.stiffness > 0))
    throw InputError("tip.stiffness", fmt(bar.stiffness), "must be > 0 and finite (N/m)");
  if (!(std::isfinite(bar.mass) && bar.mass > 0)) throw InputError("object.mass", fmt(bar.mass), "must be > 0 (kg)");
  if (!(std::isfinite(bar.inertia) && bar.inertia > 0))
    throw InputError("object.inertia", fmt(bar.inertia), "must be > 0 (kg m^2)");
  if (!(g.a > 0 && g.b > 0)) throw InputError("object.width, object.length", fmt(2 * g.a) + ", " + fmt(2 * g.b), "must be > 0");
  if (!(muN > 0 && std::isfinite(muN))) throw InputError("surface.mu x normal load", fmt(muN), "must be > 0 for a tip push (N)");
  if (samples < 2) throw InputError("solver.samples", std::to_string(samples), "must be >= 2");
  if (!(t_end > 0)) t_end = dynamic_t_end(bar, muN, tip);
  if (!std::isfinite(t_end)) throw InputError("solver.t_end", fmt(t_end), "must be finite (s)");
  if (!(rtol >= rtol_in_eps<double>(kDop853RtolEps) && rtol <= 1e-2))
    throw InputError("solver.rtol", fmt(rtol),
                     "must be in [" + fmt(rtol_in_eps<double>(kDop853RtolEps)) + ", 1e-2] for the dynamic tip push");

  if (max_steps < 1) throw InputError("solver.max_steps", std::to_string(max_steps), "must be >= 1");
  return tip.mu > 0 ? run_impl<kFricStateSize>(g, muN, bar, tip, x0, y0, theta0, t_end, samples, rtol, max_steps)
                    : run_impl<kRoughStateSize>(g, muN, bar, tip, x0, y0, theta0, t_end, samples, rtol, max_steps);
}

}  // namespace nanopush::tip

