// Rolling of nanotubes: docs/models.md section E (thesis eqs 3.10-3.21, section 3.3.1).
#include "nanopush/models/rolling.hpp"

#include <cmath>

#include "nanopush/numerics/error.hpp"

namespace nanopush::rolling {

double static_friction(double F, double h, double r) {
  require_nonnegative("push force F", F, "N");
  require_positive("tube radius r", r, "m");
  require_finite("push height h", h, "m");
  if (std::abs(h) > r)
    throw InputError("push height h", fmt(h), "must be in [-r, r] = [" + fmt(-r) + ", " + fmt(r) + "] (m)");
  return F / 3.0 * (1.0 - 2.0 * h / r);
}

double rolling_resistance(double W_load, double k, double r) {
  require_nonnegative("rolling load W", W_load, "N");
  require_nonnegative("contact half-width k", k, "m");
  require_positive("tube radius r", r, "m");
  return W_load * k / r;
}

double minimum_rolling_force(double W_load, double k, double r, double margin) {
  require_nonnegative("margin", margin);
  return (1.0 + margin) * rolling_resistance(W_load, k, r);
}

double sliding_threshold(double mu, double N) {
  require_nonnegative("friction coefficient mu", mu);
  require_nonnegative("normal load N", N, "N");
  return mu * N;
}

std::string_view motion_name(Motion m) {
  switch (m) {
    case Motion::stuck: return "stuck";
    case Motion::rolling: return "rolling";
    case Motion::rolling_with_slip: return "rolling_with_slip";
    case Motion::sliding: return "sliding";
  }
  return "?";
}

Decision decide(const Push& p) {
  Decision d;
  d.fs_required = static_friction(p.F, p.h, p.r);
  d.F_roll = rolling_resistance(p.W_roll, p.k, p.r);
  d.F_slide = sliding_threshold(p.mu, p.N_slide);
  d.fs_available = d.F_slide;
  if (p.F < d.F_roll && p.F < d.F_slide) {
    d.motion = Motion::stuck;
  } else if (d.F_roll <= d.F_slide) {
    d.motion = std::abs(d.fs_required) <= d.fs_available ? Motion::rolling : Motion::rolling_with_slip;
  } else {
    d.motion = Motion::sliding;
  }
  return d;
}

}  // namespace nanopush::rolling
