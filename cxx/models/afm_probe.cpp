// AFM probe relations: thesis eqs 2.1-2.11 (see afm_probe.hpp).
#include "nanopush/models/afm_probe.hpp"

#include <cmath>

#include "nanopush/numerics/error.hpp"

namespace nanopush::afm {

SpringConstants spring_constants(const Cantilever& c) {
  require_positive("cantilever E", c.E, "Pa");
  require_finite("cantilever nu", c.nu);
  if (!(c.nu > -1.0 && c.nu <= 0.5)) throw InputError("cantilever nu", fmt(c.nu), "must be in (-1, 0.5]");
  require_positive("cantilever length", c.length, "m");
  require_positive("cantilever width", c.width, "m");
  require_positive("cantilever thickness", c.thickness, "m");
  require_positive("cantilever tip_height", c.tip_height, "m");
  const double l = c.length, w = c.width, t = c.thickness, H = c.tip_height;
  const double G = c.E / (2.0 * (1.0 + c.nu));
  SpringConstants k;
  k.Ls = l / H;
  k.kz = c.E * w * t * t * t / (4.0 * l * l * l);
  k.kxz = 2.0 * k.Ls / 3.0 * k.kz;
  k.ktheta = G * w * t * t * t / (3.0 * l * H * H);
  k.kby = c.E * t * w * w * w / (4.0 * l * l * l);
  return k;
}

double deflection_1d(const SpringConstants& k, double Fz, double Fx, double alpha) {
  require_finite("Fz", Fz, "N");
  require_finite("Fx", Fx, "N");
  require_finite("alpha", alpha, "rad");
  const double c = std::cos(alpha), s = std::sin(alpha);
  return (Fz * c - Fx * s) / k.kz - (Fz * s + Fx * c) / k.kxz;
}
double deflection_2d_normal(const SpringConstants& k, double Fz, double alpha) {
  require_finite("Fz", Fz, "N");
  require_finite("alpha", alpha, "rad");
  return Fz * std::cos(alpha) / k.kz - Fz * std::sin(alpha) / k.kxz;
}
double twist_2d(const SpringConstants& k, double Fy, double S_theta) {
  require_finite("Fy", Fy, "N");
  require_finite("S_theta", S_theta);
  return S_theta * Fy / k.ktheta;
}

std::string SphereModes::text() const {
  std::string s;
  auto add = [&s](bool on, const char* name) {
    if (on) s += (s.empty() ? "" : "+") + std::string(name);
  };
  add(stick, "stick");
  add(slide, "slide");
  add(roll, "roll");
  add(spin, "spin");
  return s.empty() ? "none" : s;
}

SphereModes sphere_modes(const SphereContact& c) {
  require_nonnegative("f1", c.f1, "N");
  require_nonnegative("f2", c.f2, "N");
  require_positive("R", c.R, "m");
  require_nonnegative("Fz", c.Fz, "N");
  require_finite("x0", c.x0, "m");
  require_nonnegative("a", c.a, "m");
  require_nonnegative("a2", c.a2, "m");
  require_nonnegative("tau_s", c.tau_s, "Pa");
  require_nonnegative("tau_s2", c.tau_s2, "Pa");
  require_nonnegative("tau_psi", c.tau_psi, "N/m");
  require_nonnegative("tau_theta", c.tau_theta, "N/m");
  const double pi = 3.14159265358979323846;
  const double A = pi * c.a * c.a, A2 = pi * c.a2 * c.a2;
  SphereModes m;
  const bool tip_holds = c.f2 < c.tau_s2 * A2;
  m.stick = c.f1 < c.tau_s * A && tip_holds;
  m.slide = c.f1 >= c.tau_s * A && tip_holds;
  m.roll = (c.f1 - c.f2) * c.R >= c.tau_psi * A && !tip_holds;
  m.spin = c.Fz * std::abs(c.x0) >= c.tau_theta * A && c.x0 != 0.0;
  return m;
}

}  // namespace nanopush::afm
