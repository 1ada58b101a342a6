// Scene environment and bodies; normal-load assembly from only the models a scene needs.
#include "nanopush/models/environment.hpp"

#include <array>
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
namespace {

// The normal load of one body in one environment, assembled in two passes over one list of
// terms: every term evaluated (gravity and buoyancy, van der Waals, capillary, the contact
// and its adhesion); then the external terms below the threshold dropped and the contact
// redone, the drop kept only if N moves less than the threshold. The object holds the terms
// and the report, which its steps write as they run.
class LoadAssembly {
 public:
  LoadAssembly(const Environment& env, const Body& body, const LoadOptions& opt)
      : env_(env), body_(body), opt_(opt), mb_(body.material), ms_(env.has_substrate ? env.substrate : body.material),
        elastic_(mb_.youngs_modulus > 0.0 && ms_.youngs_modulus > 0.0), in_liquid_(env.medium == Medium::liquid),
        humid_(env.medium == Medium::humid_air && env.humidity > 0.0), z0_(env.gap) {
    r_.work_of_adhesion = kNaN;
    r_.hamaker = kNaN;
  }
  LoadAssembly(const LoadAssembly&) = delete;
  LoadAssembly& operator=(const LoadAssembly&) = delete;

  LoadReport run() {
    weight();
    vdw_ = make("van_der_waals", "-");
    cap_ = make("capillary", "-");
    adh_ = make("contact_adhesion", "-");
    if (!env_.adhesion) {
      vdw_.note = cap_.note = adh_.note = "scene without adhesion";
    } else {
      van_der_waals();
      capillary();
    }
    // Pass 1: everything evaluated. Pass 2: drop the external terms below the threshold and
    // redo the contact; the drop stands only if N and the sliding load change by less than the
    // threshold too (the contact model can amplify a change of the external load).
    r_.contact_half_width = contact(external_sum(false));
    const double adh_all = adh_.status == TermStatus::evaluated ? adh_.value : 0.0;
    const double sliding_all = external_sum(false);
    const double N_all = sliding_all + adh_all;
    r_.drop_threshold = opt_.drop_negligible ? opt_.drop_fraction * opt_.rtol * std::abs(N_all) : 0.0;
    drop_negligible(N_all, sliding_all);
    return report();
  }

 private:
  static LoadTerm make(std::string name, std::string model) {
    LoadTerm t;
    t.name = std::move(name);
    t.model = std::move(model);
    t.value = kNaN;
    t.share = kNaN;
    return t;
  }

  // Gravity (always) and buoyancy (liquid only).
  void weight() {
    grav_ = make("gravity", "m g");
    grav_.value = body_.mass() * env_.gravity;
    grav_.status = TermStatus::evaluated;
    buoy_ = make("buoyancy", in_liquid_ ? "-rho_liquid V g (Archimedes)" : "-");
    if (in_liquid_) {
      buoy_.value = -env_.liquid.density * body_.volume() * env_.gravity;
      buoy_.status = TermStatus::evaluated;
    } else {
      buoy_.note = "not in a liquid";
    }
  }

  // Work of adhesion, evaluated only when a contact model asks for it (never for bars or
  // rigid cylinders): vacuum/humid air W12 = 2 sqrt(g1 g2) (2.35, = 2 gamma for like solids);
  // in a liquid W132 = 2 A132 / 1.9302e-18 (eq 3.9 applied to A132).
  double work_of_adhesion() {
    if (!W_cache_) {
      auto gamma_of = [](const forces::Material& m) {
        return std::isnan(m.surface_energy) ? forces::surface_energy_corrected(m.hamaker) : m.surface_energy;
      };
      if (in_liquid_) {
        W_cache_ = r_.hamaker > 0.0 ? 2.0 * forces::surface_energy_corrected(r_.hamaker) : 0.0;
      } else {
        W_cache_ = forces::work_of_adhesion_dispersion(gamma_of(mb_), gamma_of(ms_));
      }
      r_.work_of_adhesion = *W_cache_;
    }
    return *W_cache_;
  }

  // Van der Waals attraction with the Hamaker constant of body/substrate across the medium
  // (combining relation).
  void van_der_waals() {
    const double A33 = in_liquid_ ? env_.liquid.hamaker : 0.0;
    const double A = forces::hamaker_combined(mb_.hamaker, ms_.hamaker, A33);
    r_.hamaker = A;
    switch (body_.shape) {
      case Shape::sphere:
        vdw_.model = "sphere-flat A R/(6 z0^2) (2.22)";
        vdw_.value = (A >= 0 ? 1.0 : -1.0) * forces::sphere_flat_vdw_force(std::abs(A), body_.radius, z0_);
        break;
      case Shape::rod:
      case Shape::tube:
        vdw_.model = "rod-plane L A d^0.5/(16 z0^2.5) (Parsegian)";
        vdw_.value = (A >= 0 ? 1.0 : -1.0) * forces::rod_plane_vdw_force(std::abs(A), body_.length, 2.0 * body_.radius, z0_);
        break;
      case Shape::bar:
        vdw_.model = "flat-flat A/(6 pi z0^3) x area (2.26)";
        vdw_.value = (A >= 0 ? 1.0 : -1.0) * forces::flat_flat_vdw_pressure(std::abs(A), z0_) * body_.length * body_.width;
        break;
    }
    vdw_.status = TermStatus::evaluated;
  }

  // The capillary force of a meniscus condensed from humid air (else a note why none).
  void capillary() {
    if (!humid_) {
      cap_.note = env_.medium == Medium::humid_air ? "humidity = 0" : std::string("no vapour in ") + std::string(medium_name(env_.medium));
      return;
    }
    const auto& L = env_.liquid;
    const double r1 = std::abs(forces::kelvin_radius(L.surface_tension, L.molar_volume, env_.temperature, env_.humidity));
    if (std::isinf(r1)) {
      cap_.note = "saturated vapour: meniscus radius unbounded, maximum force used";
    }
    switch (body_.shape) {
      case Shape::sphere:
        cap_.model = "4 pi R gamma cos(theta)/(1 + z0/d) (2.69)";
        cap_.value = std::isinf(r1) ? forces::capillary_force_max(body_.radius, L.surface_tension, L.contact_angle)
                                    : forces::capillary_force_sphere(body_.radius, L.surface_tension, L.contact_angle, r1, z0_);
        break;
      case Shape::rod:
      case Shape::tube:
        cap_.model = "cylinder meniscus 2 x_m L gamma/r1";
        if (std::isinf(r1)) throw InputError("environment.humidity", "1", "must be < 1 for a cylinder meniscus (radius unbounded)");
        cap_.value = forces::capillary_force_cylinder(body_.radius, body_.length, L.surface_tension, L.contact_angle, r1, z0_);
        break;
      case Shape::bar:
        cap_.model = "plate 2 gamma cos(theta)/z0 x area";
        cap_.value = forces::capillary_force_plate(body_.length * body_.width, L.surface_tension, L.contact_angle,
                                                   std::isinf(r1) ? std::numeric_limits<double>::max() : r1, z0_);
        break;
    }
    cap_.status = TermStatus::evaluated;
  }

  // The external load on the contact: everything except the contact adhesion itself.
  std::array<LoadTerm*, 4> external() { return {&grav_, &buoy_, &vdw_, &cap_}; }
  double external_sum(bool honour_drops) {
    double s = 0.0;
    for (auto* t : external())
      if (t->status == TermStatus::evaluated || (!honour_drops && t->status == TermStatus::dropped)) s += t->value;
    return s;
  }

  // The contact under the external load P: its half-width (returned) and its adhesion term.
  double contact(double P) {
    adh_.value = kNaN;
    double a = 0.0;
    if (body_.shape == Shape::bar) {
      r_.contact_model = "flat face: geometric half-width = width/2";
      a = 0.5 * body_.width;
      if (env_.adhesion) adh_.note = "flat contact: adhesion is the van der Waals pressure term";
      return a;
    }
    if (!elastic_) {
      r_.contact_model = "rigid (no Young's modulus): point/line contact";
      if (env_.adhesion && body_.shape == Shape::sphere && work_of_adhesion() > 0.0) {
        adh_.model = "Derjaguin/DMT 2 pi R W (2.45)";
        adh_.value = forces::derjaguin_adhesion_force(body_.radius, work_of_adhesion());
        adh_.status = TermStatus::evaluated;
      } else if (env_.adhesion && body_.shape != Shape::sphere) {
        adh_.note = "rigid cylinder: line adhesion needs an elastic contact model";
      }
      return 0.0;
    }
    return elastic_contact(P);
  }

  // An elastic sphere or cylinder: JKR with adhesion, Hertz without.
  double elastic_contact(double P) {
    double a = 0.0;
    const double Es = forces::effective_modulus(mb_.youngs_modulus, mb_.poisson_ratio, ms_.youngs_modulus, ms_.poisson_ratio);
    if (env_.adhesion && work_of_adhesion() > 0.0) {
      const double W = work_of_adhesion();
      if (body_.shape == Shape::sphere) {
        r_.contact_model = "JKR sphere (2.50)";
        a = forces::jkr_contact_radius(body_.radius, Es, W, P);
        const double K = 4.0 * Es / 3.0;
        adh_.model = "JKR: K a^3/R - P (2.50)";
        adh_.value = K * a * a * a / body_.radius - P;
      } else {
        r_.contact_model = "JKR line contact (thesis ref [72])";
        a = forces::jkr_line_half_width(body_.radius, Es, W, P / body_.length);
        adh_.model = "JKR line: L sqrt(2 pi E* b W)";
        adh_.value = body_.length * std::sqrt(2.0 * forces::kPi * Es * a * W);
      }
      adh_.status = TermStatus::evaluated;
    } else {
      if (env_.adhesion) adh_.note = "work of adhesion is 0";
      const double Pc = std::max(P, 0.0);
      if (body_.shape == Shape::sphere) {
        r_.contact_model = "Hertz (2.57)";
        a = forces::hertz_contact_radius(body_.radius, Es, Pc);
      } else {
        r_.contact_model = "Hertz line contact";
        a = forces::hertz_line_half_width(body_.radius, Es, Pc / body_.length);
      }
    }
    return a;
  }

  // Pass 2: the external terms below the threshold dropped, the contact redone; the drop
  // stands only if N (N_all in pass 1) and the sliding load (sliding_all) move by less than
  // the threshold, else the terms are kept and the contact of pass 1 restored.
  void drop_negligible(double N_all, double sliding_all) {
    const bool load_dependent_contact = elastic_ && body_.shape != Shape::bar;
    std::vector<LoadTerm*> candidates;
    for (auto* t : external())
      if (t->status == TermStatus::evaluated && std::abs(t->value) < r_.drop_threshold) candidates.push_back(t);
    if (candidates.empty()) return;
    for (auto* t : candidates) t->status = TermStatus::dropped;
    // Only an elastic contact depends on the external load; a bar's or a rigid body's
    // contact (and its Derjaguin adhesion) is not evaluated again.
    if (load_dependent_contact) r_.contact_half_width = contact(external_sum(true));
    const double N_red = external_sum(true) + (adh_.status == TermStatus::evaluated ? adh_.value : 0.0);
    if (std::abs(N_red - N_all) < r_.drop_threshold && std::abs(external_sum(true) - sliding_all) < r_.drop_threshold) {
      for (auto* t : candidates) t->note = "|effect on N| < drop_fraction * rtol * N";
    } else {
      for (auto* t : candidates) {
        t->status = TermStatus::evaluated;
        t->note = "below the threshold, kept: the contact model amplifies its effect on N";
      }
      if (load_dependent_contact) r_.contact_half_width = contact(external_sum(false));
    }
  }

  // The loads and every term's share of N.
  LoadReport report() {
    r_.sliding_load = external_sum(true);
    r_.normal_load = r_.sliding_load + (adh_.status == TermStatus::evaluated ? adh_.value : 0.0);
    r_.terms = {grav_, buoy_, vdw_, cap_, adh_};
    for (auto& t : r_.terms)
      if (t.status != TermStatus::not_needed) t.share = r_.normal_load != 0.0 ? t.value / r_.normal_load : kNaN;
    return std::move(r_);
  }

  const Environment& env_;
  const Body& body_;
  const LoadOptions& opt_;
  const forces::Material& mb_;
  const forces::Material& ms_;
  const bool elastic_;
  const bool in_liquid_;
  const bool humid_;
  const double z0_;
  LoadReport r_;
  LoadTerm grav_, buoy_, vdw_, cap_, adh_;
  std::optional<double> W_cache_;
};

}  // namespace

LoadReport assemble_normal_load(const Environment& env, const Body& body, const LoadOptions& opt) {
  require_positive("rtol", opt.rtol);
  require_nonnegative("drop_fraction", opt.drop_fraction);
  return LoadAssembly(env, body, opt).run();
}

}  // namespace nanopush
