// Scene environment and bodies; normal-load assembly from only the models a scene needs.
#include "nanopush/models/environment.hpp"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <limits>
#include <optional>
#include <set>
#include <sstream>

#include "nanopush/numerics/error.hpp"

namespace nanopush {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}  // namespace


double Body::volume() const {
  switch (shape) {
    case Shape::bar: return length * width * height;
    case Shape::rod: return forces::kPi * radius * radius * length;
    case Shape::tube: return forces::kPi * (radius * radius - inner_radius * inner_radius) * length;
    case Shape::sphere: return 4.0 / 3.0 * forces::kPi * radius * radius * radius;
  }
  return 0.0;
}
double Body::mass() const { return material.density * volume(); }

const LoadTerm& LoadReport::term(std::string_view name) const {
  for (auto& t : terms)
    if (t.name == name) return t;
  throw std::out_of_range("LoadReport: no term " + std::string(name));
}

std::string LoadReport::to_text() const {
  std::ostringstream s;
  s << std::left << std::setw(18) << "term" << std::setw(44) << "model" << std::right << std::setw(14) << "value [N]"
    << std::setw(12) << "share of N" << "  status\n";
  for (auto& t : terms) {
    s << std::left << std::setw(18) << t.name << std::setw(44) << t.model << std::right;
    if (t.status == TermStatus::not_needed) {
      s << std::setw(14) << "-" << std::setw(12) << "-";
    } else {
      s << std::setw(14) << std::setprecision(6) << std::scientific << t.value << std::setw(12)
        << std::setprecision(3) << t.share;
    }
    s << std::defaultfloat << "  " << term_status_name(t.status) << (t.note.empty() ? "" : " (" + t.note + ")") << "\n";
  }
  s << std::setprecision(10);
  s << "normal load N = " << normal_load << " N (sliding load without contact adhesion: " << sliding_load << " N)\n";
  s << "contact half-width = " << contact_half_width << " m (" << contact_model << ")\n";
  s << "drop threshold = " << drop_threshold << " N\n";
  return s.str();
}

// ------------------------------------------------------------------ assembly
// One function on purpose (~200 lines): its passes (every term; then the terms below the
// threshold dropped and the contact redone, kept only if N moves less than the threshold)
// share one list of terms through the lambdas below, and the report is written as they run.
// Cutting it means a LoadAssembly object holding that list; worth it when a third pass or a
// second contact model per body comes.
LoadReport assemble_normal_load(const Environment& env, const Body& body, const LoadOptions& opt) {
  require_positive("rtol", opt.rtol);
  require_nonnegative("drop_fraction", opt.drop_fraction);
  const forces::Material& mb = body.material;
  const forces::Material& ms = env.has_substrate ? env.substrate : body.material;
  const bool elastic = mb.youngs_modulus > 0.0 && ms.youngs_modulus > 0.0;
  const bool in_liquid = env.medium == Medium::liquid;
  const bool humid = env.medium == Medium::humid_air && env.humidity > 0.0;
  const double z0 = env.gap;

  LoadReport r;
  r.work_of_adhesion = kNaN;
  r.hamaker = kNaN;
  auto make = [](std::string name, std::string model) {
    LoadTerm t;
    t.name = std::move(name);
    t.model = std::move(model);
    t.value = kNaN;
    t.share = kNaN;
    return t;
  };

  // Gravity (always) and buoyancy (liquid only).
  LoadTerm grav = make("gravity", "m g");
  grav.value = body.mass() * env.gravity;
  grav.status = TermStatus::evaluated;
  LoadTerm buoy = make("buoyancy", in_liquid ? "-rho_liquid V g (Archimedes)" : "-");
  if (in_liquid) {
    buoy.value = -env.liquid.density * body.volume() * env.gravity;
    buoy.status = TermStatus::evaluated;
  } else {
    buoy.note = "not in a liquid";
  }

  LoadTerm vdw = make("van_der_waals", "-");
  LoadTerm cap = make("capillary", "-");
  LoadTerm adh = make("contact_adhesion", "-");
  // Work of adhesion, evaluated only when a contact model asks for it (never for bars or
  // rigid cylinders): vacuum/humid air W12 = 2 sqrt(g1 g2) (2.35, = 2 gamma for like solids);
  // in a liquid W132 = 2 A132 / 1.9302e-18 (eq 3.9 applied to A132).
  std::optional<double> W_cache;
  auto work_of_adhesion = [&]() {
    if (!W_cache) {
      auto gamma_of = [](const forces::Material& m) {
        return std::isnan(m.surface_energy) ? forces::surface_energy_corrected(m.hamaker) : m.surface_energy;
      };
      if (in_liquid) {
        W_cache = r.hamaker > 0.0 ? 2.0 * forces::surface_energy_corrected(r.hamaker) : 0.0;
      } else {
        W_cache = forces::work_of_adhesion_dispersion(gamma_of(mb), gamma_of(ms));
      }
      r.work_of_adhesion = *W_cache;
    }
    return *W_cache;
  };
  if (!env.adhesion) {
    vdw.note = cap.note = adh.note = "scene without adhesion";
  } else {
    // Hamaker constant of body/substrate across the medium (combining relation).
    const double A33 = in_liquid ? env.liquid.hamaker : 0.0;
    const double A = forces::hamaker_combined(mb.hamaker, ms.hamaker, A33);
    r.hamaker = A;
    switch (body.shape) {
      case Shape::sphere:
        vdw.model = "sphere-flat A R/(6 z0^2) (2.22)";
        vdw.value = (A >= 0 ? 1.0 : -1.0) * forces::sphere_flat_vdw_force(std::abs(A), body.radius, z0);
        break;
      case Shape::rod:
      case Shape::tube:
        vdw.model = "rod-plane L A d^0.5/(16 z0^2.5) (Parsegian)";
        vdw.value = (A >= 0 ? 1.0 : -1.0) * forces::rod_plane_vdw_force(std::abs(A), body.length, 2.0 * body.radius, z0);
        break;
      case Shape::bar:
        vdw.model = "flat-flat A/(6 pi z0^3) x area (2.26)";
        vdw.value = (A >= 0 ? 1.0 : -1.0) * forces::flat_flat_vdw_pressure(std::abs(A), z0) * body.length * body.width;
        break;
    }
    vdw.status = TermStatus::evaluated;


    if (humid) {
      const auto& L = env.liquid;
      const double r1 = std::abs(forces::kelvin_radius(L.surface_tension, L.molar_volume, env.temperature, env.humidity));
      if (std::isinf(r1)) {
        cap.note = "saturated vapour: meniscus radius unbounded, maximum force used";
      }
      switch (body.shape) {
        case Shape::sphere:
          cap.model = "4 pi R gamma cos(theta)/(1 + z0/d) (2.69)";
          cap.value = std::isinf(r1) ? forces::capillary_force_max(body.radius, L.surface_tension, L.contact_angle)
                                     : forces::capillary_force_sphere(body.radius, L.surface_tension, L.contact_angle, r1, z0);
          break;
        case Shape::rod:
        case Shape::tube:
          cap.model = "cylinder meniscus 2 x_m L gamma/r1";
          if (std::isinf(r1)) throw InputError("environment.humidity", "1", "must be < 1 for a cylinder meniscus (radius unbounded)");
          cap.value = forces::capillary_force_cylinder(body.radius, body.length, L.surface_tension, L.contact_angle, r1, z0);
          break;
        case Shape::bar:
          cap.model = "plate 2 gamma cos(theta)/z0 x area";
          cap.value = forces::capillary_force_plate(body.length * body.width, L.surface_tension, L.contact_angle,
                                                    std::isinf(r1) ? std::numeric_limits<double>::max() : r1, z0);
          break;
      }
      cap.status = TermStatus::evaluated;
    } else {
      cap.note = env.medium == Medium::humid_air ? "humidity = 0" : std::string("no vapour in ") + std::string(medium_name(env.medium));
    }
  }

  // The external load on the contact: everything except the contact adhesion itself.
  std::vector<LoadTerm*> external = {&grav, &buoy, &vdw, &cap};
  auto external_sum = [&](bool honour_drops) {
    double s = 0.0;
    for (auto* t : external)
      if (t->status == TermStatus::evaluated || (!honour_drops && t->status == TermStatus::dropped)) s += t->value;
    return s;
  };

  auto contact = [&](double P) {
    adh.value = kNaN;
    double a = 0.0;
    if (body.shape == Shape::bar) {
      r.contact_model = "flat face: geometric half-width = width/2";
      a = 0.5 * body.width;
      if (env.adhesion) adh.note = "flat contact: adhesion is the van der Waals pressure term";
      return a;
    }
    if (!elastic) {
      r.contact_model = "rigid (no Young's modulus): point/line contact";
      if (env.adhesion && body.shape == Shape::sphere && work_of_adhesion() > 0.0) {
        adh.model = "Derjaguin/DMT 2 pi R W (2.45)";
        adh.value = forces::derjaguin_adhesion_force(body.radius, work_of_adhesion());
        adh.status = TermStatus::evaluated;
      } else if (env.adhesion && body.shape != Shape::sphere) {
        adh.note = "rigid cylinder: line adhesion needs an elastic contact model";
      }
      return 0.0;
    }
    const double Es = forces::effective_modulus(mb.youngs_modulus, mb.poisson_ratio, ms.youngs_modulus, ms.poisson_ratio);
    if (env.adhesion && work_of_adhesion() > 0.0) {
      const double W = work_of_adhesion();
      if (body.shape == Shape::sphere) {
        r.contact_model = "JKR sphere (2.50)";
        a = forces::jkr_contact_radius(body.radius, Es, W, P);
        const double K = 4.0 * Es / 3.0;
        adh.model = "JKR: K a^3/R - P (2.50)";
        adh.value = K * a * a * a / body.radius - P;
      } else {
        r.contact_model = "JKR line contact (thesis ref [72])";
        a = forces::jkr_line_half_width(body.radius, Es, W, P / body.length);
        adh.model = "JKR line: L sqrt(2 pi E* b W)";
        adh.value = body.length * std::sqrt(2.0 * forces::kPi * Es * a * W);
      }
      adh.status = TermStatus::evaluated;
    } else {
      if (env.adhesion) adh.note = "work of adhesion is 0";
      const double Pc = std::max(P, 0.0);
      if (body.shape == Shape::sphere) {
        r.contact_model = "Hertz (2.57)";
        a = forces::hertz_contact_radius(body.radius, Es, Pc);
      } else {
        r.contact_model = "Hertz line contact";
        a = forces::hertz_line_half_width(body.radius, Es, Pc / body.length);
      }
    }
    return a;
  };

  // Pass 1: everything evaluated. Pass 2: drop the external terms below the threshold and
  // redo the contact; the drop stands only if N and the sliding load change by less than the
  // threshold too (the contact model can amplify a change of the external load).
  const bool load_dependent_contact = elastic && body.shape != Shape::bar;
  r.contact_half_width = contact(external_sum(false));
  const double adh_all = adh.status == TermStatus::evaluated ? adh.value : 0.0;
  const double sliding_all = external_sum(false);
  const double N_all = sliding_all + adh_all;
  const double a_all = r.contact_half_width;
  r.drop_threshold = opt.drop_negligible ? opt.drop_fraction * opt.rtol * std::abs(N_all) : 0.0;
  std::vector<LoadTerm*> candidates;
  for (auto* t : external)
    if (t->status == TermStatus::evaluated && std::abs(t->value) < r.drop_threshold) candidates.push_back(t);
  if (!candidates.empty()) {
    for (auto* t : candidates) t->status = TermStatus::dropped;
    // Only an elastic contact depends on the external load; a bar's or a rigid body's
    // contact (and its Derjaguin adhesion) is not evaluated again.
    if (load_dependent_contact) r.contact_half_width = contact(external_sum(true));
    const double N_red = external_sum(true) + (adh.status == TermStatus::evaluated ? adh.value : 0.0);
    if (std::abs(N_red - N_all) < r.drop_threshold && std::abs(external_sum(true) - sliding_all) < r.drop_threshold) {
      for (auto* t : candidates) t->note = "|effect on N| < drop_fraction * rtol * N";
    } else {
      for (auto* t : candidates) {
        t->status = TermStatus::evaluated;
        t->note = "below the threshold, kept: the contact model amplifies its effect on N";
      }
      if (load_dependent_contact) r.contact_half_width = contact(external_sum(false));
      (void)a_all;
    }
  }

  r.sliding_load = external_sum(true);
  r.normal_load = r.sliding_load + (adh.status == TermStatus::evaluated ? adh.value : 0.0);
  r.terms = {grav, buoy, vdw, cap, adh};
  for (auto& t : r.terms)
    if (t.status != TermStatus::not_needed) t.share = r.normal_load != 0.0 ? t.value / r.normal_load : kNaN;
  return r;
}

}  // namespace nanopush
