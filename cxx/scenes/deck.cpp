#include "nanopush/scenes/deck.hpp"

#include <algorithm>
#include <cstdio>
#include <sstream>

namespace nanopush {

static std::string e(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17E", v);
  return b;
}

/// The deck: each data line preceded by a comment line (see fortran/prog_nanobar.f).
std::string legacy_deck(const Scene& sc, double rtol, const std::vector<double>& atol,
                        const std::array<double, 3>& rest_direction) {
  std::ostringstream d;
  const double xn = sc.push.pbx, yn = -sc.push.pby;  // thesis mapping, inverted
  d << "* nanopush deck for scene " << sc.name << " (" << sc.source.string() << ")\n"
    << (sc.description.empty() ? sc.name : sc.description).substr(0, 72) << "\n"
    << "* XN YN [m] (thesis push coordinates: body point (XN, -YN))\n"
    << e(xn) << " " << e(yn) << "\n"
    << "* CMX CMY [m] THETA0 [rad]\n"
    << e(sc.initial[kX]) << " " << e(sc.initial[kY]) << " " << e(sc.initial[kTheta]) << "\n"
    << "* VX0 VY0 [m/s] OMEGA0 [rad/s]\n"
    << e(sc.initial[kVx]) << " " << e(sc.initial[kVy]) << " " << e(sc.initial[kOmega]) << "\n"
    << "* F [N] BETA [rad] FVDW [N] MU G [m/s^2]\n"
    << e(sc.push.force) << " " << e(sc.push.beta) << " " << e(sc.rough() ? sc.surface.f_vdw : 0.0) << " "
    << e(sc.rough() ? sc.surface.mu : 0.0) << " " << e(sc.surface.g) << "\n"
    << "* M [kg] I [kg m^2]\n"
    << e(sc.mass) << " " << e(sc.inertia) << "\n"
    << "* SA (width) SB (length) SC (height) [m]\n"
    << e(sc.width) << " " << e(sc.length) << " " << e(sc.height) << "\n"
    << "* TEND [s] NOUT RTOL\n"
    << e(sc.solver.t_end) << " " << sc.solver.samples << " " << e(rtol) << "\n"
    << "* ATOL(1..8)\n";
  for (std::size_t i = 0; i < 8; ++i) d << e(atol[i]) << (i + 1 < 8 ? " " : "\n");
  d << "* MAXSTP\n" << std::min<long>(sc.solver.max_steps, 2000000000L) << "\n"
    << "* VXR VYR OMR: velocity direction whose friction acts at rest (0 0 0: none, the thesis law)\n"
    << e(rest_direction[0]) << " " << e(rest_direction[1]) << " " << e(rest_direction[2]) << "\n";
  return d.str();
}

}  // namespace nanopush
