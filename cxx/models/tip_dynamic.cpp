// The dynamic tip-driven push's contact geometry (tip_dynamic.hpp; docs/tip.md): the spring
// contact, the offset surface's points and coordinate, the sliding contact of a tip with
// friction, and the run's scales. The run itself, the event loop of rest and slide phases,
// is tip_dynamic_run.cpp's.
#include "nanopush/models/tip_dynamic.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "nanopush/numerics/error.hpp"
#include "tip_format.hpp"

namespace nanopush::tip {

namespace {

using detail::fmt;

/// The four faces counter-clockwise from x' = +a: outward normal, the corner the face starts
/// at (going counter-clockwise) and its length. The corner arc after face i is centred on the
/// face's end and turns the normal from i pi/2 to (i + 1) pi/2.
struct Face {
  double nx, ny, x0, y0, len;
};
std::array<Face, 4> faces(const BarGeometry& g) {
  return {Face{1, 0, g.a, -g.b, 2 * g.b}, Face{0, 1, g.a, g.b, 2 * g.a}, Face{-1, 0, -g.a, g.b, 2 * g.b},
          Face{0, -1, -g.a, -g.b, 2 * g.a}};
}
double cross(double ax, double ay, double bx, double by) { return ax * by - ay * bx; }

}  // namespace

SpringContact spring_contact(const BarGeometry& g, double radius, double stiffness, double bx, double by) {
  SpringContact s;
  const ContactGeometry c = contact_geometry(g, bx, by);
  double d = 0;  // signed distance from the base to the rectangle
  if (!c.inside) {
    s.px = c.px;
    s.py = c.py;
    s.nx = c.nx;
    s.ny = c.ny;
    d = c.distance;
  } else {  // the base inside the rectangle: the nearest face
    const double ex = g.a - std::fabs(bx), ey = g.b - std::fabs(by);
    if (ex <= ey) {
      s.nx = bx >= 0 ? 1.0 : -1.0;
      s.px = s.nx * g.a;
      s.py = by;
      d = -ex;
    } else {
      s.ny = by >= 0 ? 1.0 : -1.0;
      s.px = bx;
      s.py = s.ny * g.b;
      d = -ey;
    }
  }
  s.delta = radius - d;
  s.qx = bx;
  s.qy = by;
  if (!(s.delta > 0)) return s;
  s.touching = true;
  s.qx = s.px + radius * s.nx;
  s.qy = s.py + radius * s.ny;
  s.fx = -stiffness * s.delta * s.nx;
  s.fy = -stiffness * s.delta * s.ny;
  s.torque = s.px * s.fy - s.py * s.fx;
  return s;
}

double offset_perimeter(const BarGeometry& g, double radius) { return 4 * (g.a + g.b) + 2 * M_PI * radius; }

OffsetPoint offset_point(const BarGeometry& g, double radius, double s) {
  const double P = offset_perimeter(g, radius), arc = 0.5 * M_PI * radius;
  s = std::fmod(s, P);
  if (s < 0) s += P;
  OffsetPoint o;
  o.s = s;
  const auto F = faces(g);
  double u = s;
  for (int i = 0; i < 4; ++i) {
    const Face& f = F[static_cast<std::size_t>(i)];
    const double tx = -f.ny, ty = f.nx;
    if (u <= f.len) {
      o.nx = f.nx;
      o.ny = f.ny;
      o.px = f.x0 + u * tx;
      o.py = f.y0 + u * ty;
      o.joint = std::min(u, f.len - u);
      break;
    }
    u -= f.len;
    if (u <= arc || i == 3) {
      const double phi = i * 0.5 * M_PI + std::min(u, arc) / radius;
      o.corner = true;
      o.joint = -std::min(std::min(u, arc), arc - std::min(u, arc));
      o.nx = std::cos(phi);
      o.ny = std::sin(phi);
      o.px = f.x0 + f.len * tx;
      o.py = f.y0 + f.len * ty;
      break;
    }
    u -= arc;
  }
  o.qx = o.px + radius * o.nx;
  o.qy = o.py + radius * o.ny;
  return o;
}

double offset_coordinate(const BarGeometry& g, double radius, double x, double y) {
  const ContactGeometry c = contact_geometry(g, x, y);
  double nx = c.nx, ny = c.ny, px = c.px, py = c.py;
  if (c.inside) {  // the nearest face, as spring_contact
    const double ex = g.a - std::fabs(x), ey = g.b - std::fabs(y);
    nx = ny = 0;
    if (ex <= ey) {
      nx = x >= 0 ? 1.0 : -1.0;
      px = nx * g.a;
    } else {
      ny = y >= 0 ? 1.0 : -1.0;
      py = ny * g.b;
    }
  }
  const auto F = faces(g);
  const double arc = 0.5 * M_PI * radius;
  double s0 = 0;
  for (int i = 0; i < 4; ++i) {
    const Face& f = F[static_cast<std::size_t>(i)];
    if (nx == f.nx && ny == f.ny) return s0 + std::clamp((px - f.x0) * -f.ny + (py - f.y0) * f.nx, 0.0, f.len);
    s0 += f.len;
    const Face& h = F[static_cast<std::size_t>((i + 1) % 4)];
    if (cross(f.nx, f.ny, nx, ny) > 0 && cross(nx, ny, h.nx, h.ny) > 0) {
      double phi = std::atan2(ny, nx) - i * 0.5 * M_PI;
      if (phi < -M_PI) phi += 2 * M_PI;
      return s0 + radius * std::clamp(phi, 0.0, 0.5 * M_PI);
    }
    s0 += arc;
  }
  return 0;  // not reached: every normal is a face's or a corner's
}

SlipPoint slip_point(const BarGeometry& g, double radius, double mu, double sigma, double bx, double by) {
  const auto F = faces(g);
  const double arc = 0.5 * M_PI * radius, tol = 1e-12 * (g.a + g.b + radius);
  const double beta = std::atan(mu * sigma), sb = std::sin(beta);
  SlipPoint best;
  double best_abs = std::numeric_limits<double>::infinity();
  double s0 = 0;
  for (int i = 0; i < 4; ++i) {
    const Face& f = F[static_cast<std::size_t>(i)];
    const double tx = -f.ny, ty = f.nx;
    {  // the face: q = c0 + u t, lambda = (c0 - b).n, u = (b - c0).t - lambda mu sigma
      const double cx = f.x0 + radius * f.nx, cy = f.y0 + radius * f.ny;
      const double lambda = (cx - bx) * f.nx + (cy - by) * f.ny;
      const double u = (bx - cx) * tx + (by - cy) * ty - lambda * mu * sigma;
      if (u >= -tol && u <= f.len + tol && std::fabs(lambda) < best_abs) {
        best_abs = std::fabs(lambda);
        const double uc = std::clamp(u, 0.0, f.len);
        best.lambda = lambda;
        best.at = OffsetPoint{s0 + uc,        cx + uc * tx, cy + uc * ty, f.x0 + uc * tx, f.y0 + uc * ty,
                              f.nx,           f.ny,         false,        std::min(uc, f.len - uc)};
      }
    }
    s0 += f.len;
    {  // the corner arc about c: with w = b - c = rho (cos psi, sin psi) and alpha = psi - phi,
       // rho (sin alpha + mu sigma cos alpha) = mu sigma r, lambda = r - rho cos alpha
      const double cx = f.x0 + f.len * tx, cy = f.y0 + f.len * ty;
      const double wx = bx - cx, wy = by - cy, rho = std::hypot(wx, wy);
      if (rho > std::fabs(sb) * radius) {
        const double alpha = std::asin(sb * radius / rho) - beta;
        double d = std::atan2(wy, wx) - alpha - i * 0.5 * M_PI;
        d = std::remainder(d, 2 * M_PI);  // in [-pi, pi]
        const double lambda = radius - rho * std::cos(alpha);
        if (d * radius >= -tol && d * radius <= arc + tol && std::fabs(lambda) < best_abs) {
          best_abs = std::fabs(lambda);
          const double dc = std::clamp(d, 0.0, 0.5 * M_PI), phi = i * 0.5 * M_PI + dc;
          const double nx = std::cos(phi), ny = std::sin(phi);
          best.lambda = lambda;
          best.at = OffsetPoint{s0 + radius * dc, cx + radius * nx, cy + radius * ny, cx, cy, nx, ny, true,
                                -std::min(radius * dc, arc - radius * dc)};
        }
      }
    }
    s0 += arc;
  }
  if (!(best_abs < std::numeric_limits<double>::infinity()))
    throw SolverError("dynamic tip push: no sliding contact for the tip's base at (" + fmt(bx) + ", " + fmt(by) +
                      ") m (body axes): the spring is pressed into the bar by more than the friction cone allows");
  return best;
}

double inertia_ratio(double mass, double speed, double muN, double travel) {
  return mass * speed * speed / (muN * travel);
}

double dynamic_t_end(const DynamicBar& bar, double muN, const TipPath& tip) {
  const double stop = bar.mass * tip.speed / muN, period = 2 * M_PI * std::sqrt(bar.mass / bar.stiffness);
  return tip.t_stop() + 10 * (stop + period);
}

}  // namespace nanopush::tip
