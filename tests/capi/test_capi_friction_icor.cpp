// The friction and iCOR entry points of the C API (bindings/nanopush.h) return exactly the numbers
// of the C++ library (bit for bit: same doubles, NaN where both are NaN), and bad input comes back
// as a status and a message with the outputs untouched. Also the friction coefficient estimates
// (nanopush_estimate_mu_from_force / _from_icor = icor::estimate_mu_from_force / _from_icor).
//
// Usage: capi_test_friction_icor [POINTS.csv SENSE OUT.csv]
//   With arguments it also writes the library's friction wrench (muN = 1, the nanobar's a and b:
//   the defaults of `nanopush friction`) for each "R,alpha" line of POINTS.csv, in the CSV format
//   of `nanopush friction`, so the scripted test can compare the CLI and the Fortran module with it.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../support/capi_check.hpp"
#include "nanopush.h"
#include "nanopush/models/friction.hpp"
#include "nanopush/models/icor.hpp"
#include "nanopush/outputs/io.hpp"

namespace {

using nanopush_capi_test::check;
using nanopush_capi_test::message;
using nanopush_capi_test::same;

constexpr double kBarA = 27.5e-9, kBarB = 50e-9;  // the thesis nanobar (docs/models.md A)
constexpr double kPi = 3.14159265358979323846;

void friction_matches_library() {
  const double Rs[] = {0.0, 1e-9, 27.5e-9, 50e-9, 57e-9, 149.9e-9, 150e-9, 1e-6, 1e-3, 1.0};
  const double alphas[] = {0.0, 0.3, kPi / 2, 2.0, -1.1, kPi};
  for (const double muN : {1.0, 2.5e-6})
    for (const int sense : {1, -1})
      for (const double R : Rs)
        for (const double alpha : alphas) {
          double w[3] = {0, 0, 0};
          const int st = nanopush_friction_wrench(nullptr, kBarA, kBarB, muN, R, alpha, sense, w);
          const auto ref = nanopush::rectangle_friction_wrench_checked(kBarA, kBarB, muN, R, alpha, sense);
          std::ostringstream what;
          what << "friction_wrench R = " << R << ", alpha = " << alpha << ", sense " << sense << ", muN " << muN;
          check(st == NANOPUSH_OK && same(w[0], ref.fx) && same(w[1], ref.fy) && same(w[2], ref.mf), what.str());
        }
  // From the velocity: rotation either way, translation (omega = 0), rest, near-translation.
  const double vs[][3] = {{1e-3, 2e-3, 1e4},  {-3e-3, 1e-3, -2e5}, {0.0, 0.0, 5.0},  {2e-3, -1e-3, 0.0},
                          {0.0, 0.0, 0.0},     {1.0, 0.5, 1e-12},   {0.0, -4e-2, 8e5}, {7e-2, 0.0, -1e-3}};
  for (const auto& v : vs) {
    double w[3] = {0, 0, 0};
    const int st = nanopush_friction_from_velocity(nullptr, kBarA, kBarB, 3e-6, v[0], v[1], v[2], w);
    const auto ref = nanopush::rectangle_friction_from_velocity_checked(kBarA, kBarB, 3e-6, v[0], v[1], v[2]);
    std::ostringstream what;
    what << "friction_from_velocity (" << v[0] << ", " << v[1] << ", " << v[2] << ")";
    check(st == NANOPUSH_OK && same(w[0], ref.fx) && same(w[1], ref.fy) && same(w[2], ref.mf), what.str());
  }
}

void icor_matches_library() {
  namespace icor = nanopush::icor;
  const icor::Rod rod = icor::nanorod();
  double r6[6], props[5];
  check(nanopush_icor_nanorod(nullptr, r6) == NANOPUSH_OK, "nanorod");
  check(r6[0] == rod.length && r6[1] == rod.radius && r6[2] == rod.density && r6[3] == rod.hamaker &&
            r6[4] == rod.z0 && r6[5] == rod.gravity,
        "nanorod = icor::nanorod()");
  check(nanopush_icor_rod_properties(nullptr, r6, props) == NANOPUSH_OK, "rod_properties");
  check(props[0] == rod.mass() && props[1] == rod.inertia() && props[2] == rod.gyration_squared() &&
            props[3] == rod.vdw_force() && props[4] == rod.load(),
        "rod_properties = Rod::mass/inertia/gyration_squared/vdw_force/load");
  const double L = rod.length, b = 0.5 * L, k2 = rod.gyration_squared(), W = rod.load();
  for (const double mu : {0.1, 0.37})
    for (const double yn : {0.0, 1e-15, 1e-9, 50e-9, 98.3e-9, 200e-9, b}) {
      const std::string at = " at yn = " + nanopush::csv_number(yn) + ", mu = " + nanopush::csv_number(mu);
      double v = 0;
      check(nanopush_icor_experimental_fit(nullptr, yn, L, &v) == 0 && same(v, icor::experimental_fit(yn, L)),
            "eq 4.1" + at);
      check(nanopush_icor_falvo(nullptr, yn, L, &v) == 0 && same(v, icor::falvo(yn, L)), "eq 4.2" + at);
      check(nanopush_icor_li(nullptr, yn, L, &v) == 0 && same(v, icor::li(yn, L)), "eq 4.3" + at);
      check(nanopush_icor_unknown_pressure(nullptr, yn, L, &v) == 0 && same(v, icor::unknown_pressure(yn, L)),
            "eq 4.13" + at);
      const double Fmin = icor::minimum_force(mu, W, yn, L);
      check(nanopush_icor_minimum_force(nullptr, mu, W, yn, L, &v) == 0 && same(v, Fmin), "eq 4.8" + at);
      for (const double F : {Fmin, 1.7 * Fmin})
        check(nanopush_icor_known_pressure(nullptr, mu, W, yn, F, L, &v) == 0 &&
                  same(v, icor::known_pressure(mu, W, yn, F, L)),
              "eq 4.7" + at);
      for (const double R : {0.0, 30e-9, 1e-6}) {
        check(nanopush_icor_force_from_icor(nullptr, mu, W, R, L, &v) == 0 &&
                  same(v, icor::force_from_icor(mu, W, R, L)),
              "eq 4.10" + at);
        if (R + yn > 0)
          check(nanopush_icor_force_unknown_pressure(nullptr, mu, W, R, yn, L, &v) == 0 &&
                    same(v, icor::force_unknown_pressure(mu, W, R, yn, L)),
                "eq 4.11" + at);
      }
      for (const double R : {-9e-8, 1e-7, k2 / std::max(yn, 1e-30)})
        check(nanopush_icor_constrained_force(nullptr, mu, W, R, yn, L, k2, &v) == 0 &&
                  same(v, icor::constrained_force(mu, W, R, yn, L, k2)),
              "eq 5.2" + at);
      check(nanopush_icor_impulsive(nullptr, yn, k2, &v) == 0 && same(v, icor::impulsive(yn, k2)), "eq 5.5" + at);
      for (const int method : {NANOPUSH_CUBIC_BRENT, NANOPUSH_CUBIC_EIGEN}) {
        double roots[3], neg = 0, pos = 0, res = -1;
        int nr = -1, nc = -1, ni = -1;
        check(nanopush_icor_cubic_roots(nullptr, yn, L, k2, method, roots, &nr, &nc, &ni, &neg, &pos, &res) == 0,
              "eq 5.4 status" + at);
        const auto s = icor::solve_constrained_cubic(
            yn, L, k2, method == NANOPUSH_CUBIC_BRENT ? icor::CubicMethod::Brent : icor::CubicMethod::Eigen);
        const double nan = std::numeric_limits<double>::quiet_NaN();
        bool ok = nr == static_cast<int>(s.real_roots.size()) && nc == s.complex_roots && ni == s.at_infinity &&
                  same(neg, s.negative.value_or(nan)) && same(pos, s.positive.value_or(nan)) &&
                  same(res, s.max_residual);
        for (std::size_t i = 0; i < 3; ++i) ok = ok && same(roots[i], i < s.real_roots.size() ? s.real_roots[i] : nan);
        check(ok, "eq 5.4 roots (method " + std::to_string(method) + ")" + at);
        // Only roots is required: every other output may be NULL.
        check(nanopush_icor_cubic_roots(nullptr, yn, L, k2, method, roots, nullptr, nullptr, nullptr, nullptr,
                                        nullptr, nullptr) == 0,
              "eq 5.4 with NULL outputs" + at);
      }
    }
}

/// d mu / d input of the library's contribution named `input` (NaN if absent: fails every ==).
double library_derivative(const nanopush::icor::MuEstimate& e, const std::string& input) {
  for (const auto& c : e.contributions)
    if (c.input == input) return c.derivative;
  return std::numeric_limits<double>::quiet_NaN();
}

/// The estimate of the C API (all outputs) equals the library's, bit for bit; then the same call
/// with every output NULL, and with each output alone, succeeds and writes the same number.
template <class CallC>
void check_estimate(const nanopush::icor::MuEstimate& ref, const char* second, CallC&& call_c, const std::string& what) {
  double mu = -1, sigma = -1, load = -1, d[4] = {-1, -1, -1, -1};
  const int st = call_c(&mu, &sigma, &load, d);
  check(st == NANOPUSH_OK, what + ": status " + std::to_string(st));
  check(mu == ref.mu && sigma == ref.sigma && load == ref.load, what + ": mu, sigma, load = library");
  check(ref.contributions.size() == 4, what + ": the library has 4 contributions");
  check(d[0] == library_derivative(ref, "F") && d[1] == library_derivative(ref, second) &&
            d[2] == library_derivative(ref, "L") && d[3] == library_derivative(ref, "H"),
        what + ": derivatives = library's dmu/dF, dmu/d" + second + ", dmu/dL, dmu/dH");
  check(call_c(nullptr, nullptr, nullptr, nullptr) == NANOPUSH_OK, what + ": every output NULL");
  double v = -1, d2[4] = {-1, -1, -1, -1};
  check(call_c(&v, nullptr, nullptr, nullptr) == NANOPUSH_OK && v == ref.mu, what + ": mu alone");
  check(call_c(nullptr, &v, nullptr, nullptr) == NANOPUSH_OK && v == ref.sigma, what + ": sigma alone");
  check(call_c(nullptr, nullptr, &v, nullptr) == NANOPUSH_OK && v == ref.load, what + ": load alone");
  check(call_c(nullptr, nullptr, nullptr, d2) == NANOPUSH_OK && d2[0] == d[0] && d2[1] == d[1] && d2[2] == d[2] &&
            d2[3] == d[3],
        what + ": derivatives alone");
}

void estimate_mu_matches_library() {
  namespace icor = nanopush::icor;
  icor::Rod other;  // a rod unlike the thesis' one in every field
  other.length = 400e-9;
  other.radius = 10e-9;
  other.density = 2000.0;
  other.hamaker = 3e-19;
  other.z0 = 0.3e-9;
  other.gravity = 0.0;
  // The two estimators: the library's and the C API's, by the measured quantity beside F (yn or
  // R) and the values it takes.
  struct Estimator {
    const char* name;
    const char* second;
    icor::MuEstimate (*library)(const icor::Rod&, icor::Measured, icor::Measured, double, double);
    decltype(&nanopush_estimate_mu_from_force) c;
    std::vector<double> values;
  };
  int n = 0;
  for (const icor::Rod& rod : {icor::nanorod(), other}) {
    const double r6[6] = {rod.length, rod.radius, rod.density, rod.hamaker, rod.z0, rod.gravity};
    const double b = rod.half_length();
    const double sigmas[][4] = {{0, 0, 0, 0}, {3e-8, 5e-9, 5e-9, 1e-19}, {1e-7, 0, 2e-8, 0}};
    const Estimator estimators[] = {
        {"estimate_mu_from_force", "yn", icor::estimate_mu_from_force, nanopush_estimate_mu_from_force,
         {0.0, 1e-15, 1e-9, 98.3e-9, 0.5 * b, b}},
        {"estimate_mu_from_icor", "R", icor::estimate_mu_from_icor, nanopush_estimate_mu_from_icor,
         {1e-12, 30e-9, 120e-9, b, 1e-6, 1.0}}};
    for (const double F : {1e-9, 1e-6, 2.5e-6, 0.3})
      for (const auto& s : sigmas)
        for (const Estimator& e : estimators)
          for (const double x : e.values) {
            const auto ref = e.library(rod, {F, s[0]}, {x, s[1]}, s[2], s[3]);
            std::ostringstream what;
            what << e.name << " L = " << rod.length << ", F = " << F << ", " << e.second << " = " << x << ", sigmas "
                 << s[0] << " " << s[1] << " " << s[2] << " " << s[3];
            check_estimate(ref, e.second,
                           [&](double* mu, double* sigma, double* load, double* d) {
                             return e.c(nullptr, r6, F, s[0], x, s[1], s[2], s[3], mu, sigma, load, d);
                           },
                           what.str());
            ++n;
          }
  }
  std::printf("estimate_mu: %d estimates compared with the library\n", n);
}

/// status and message fragment of a failing call; the output must be left untouched.
void expect_error(nanopush_error err, int status, int want_status, const char* fragment, bool untouched,
                  const std::string& what) {
  const std::string m = message(err);
  check(status == want_status && nanopush_check_error(err) == want_status, what + ": status " + std::to_string(status));
  check(m.find(fragment) != std::string::npos, what + ": message '" + m + "' should contain '" + fragment + "'");
  check(untouched, what + ": output left unchanged");
  nanopush_clear_error(err);
}

void bad_input() {
  nanopush_error err = nanopush_new_error();
  double w[3] = {7, 7, 7}, v = 7, roots[3] = {7, 7, 7};
  const auto w_untouched = [&] { return w[0] == 7 && w[1] == 7 && w[2] == 7; };
  expect_error(err, nanopush_friction_wrench(err, 0.0, kBarB, 1.0, 1e-8, 0.0, 1, w), NANOPUSH_BAD_INPUT, "a = 0",
               w_untouched(), "friction a = 0");
  expect_error(err, nanopush_friction_wrench(err, -1e-9, kBarB, 1.0, 1e-8, 0.0, 1, w), NANOPUSH_BAD_INPUT, "a = -1e-09",
               w_untouched(), "friction a < 0");
  expect_error(err, nanopush_friction_wrench(err, kBarA, kBarB, 1.0, -1e-8, 0.0, 1, w), NANOPUSH_BAD_INPUT, "R = -1e-08",
               w_untouched(), "friction R < 0");
  expect_error(err, nanopush_friction_wrench(err, kBarA, kBarB, 1.0, 1e-8, 0.0, 2, w), NANOPUSH_BAD_INPUT, "sense = 2",
               w_untouched(), "friction sense = 2");
  expect_error(err, nanopush_friction_wrench(err, kBarA, kBarB, 1.0, 1e-8, 0.0, 1, nullptr), NANOPUSH_NULL_HANDLE,
               "wrench = NULL", true, "friction wrench = NULL");
  expect_error(err, nanopush_friction_from_velocity(err, kBarA, 0.0, 1.0, 1.0, 0.0, 1.0, w), NANOPUSH_BAD_INPUT,
               "b = 0", w_untouched(), "friction_from_velocity b = 0");
  expect_error(err, nanopush_icor_falvo(err, -1e-9, 590e-9, &v), NANOPUSH_BAD_INPUT, "yn = -1e-09", v == 7,
               "falvo yn < 0");
  expect_error(err, nanopush_icor_unknown_pressure(err, 1e-9, 0.0, &v), NANOPUSH_BAD_INPUT, "L = 0", v == 7,
               "unknown_pressure L = 0");
  expect_error(err, nanopush_icor_li(err, 1e-9, -5.0, &v), NANOPUSH_BAD_INPUT, "L = -5", v == 7, "li L < 0");
  expect_error(err, nanopush_icor_known_pressure(err, 0.1, 1e-6, 0.0, 1e-9, 590e-9, &v), NANOPUSH_BAD_INPUT,
               "minimum force", v == 7, "known_pressure F below the minimum");
  expect_error(err, nanopush_icor_impulsive(err, 1e-9, 0.0, &v), NANOPUSH_BAD_INPUT, "k2 = 0", v == 7,
               "impulsive k2 = 0");
  expect_error(err, nanopush_icor_falvo(err, 1e-9, 590e-9, nullptr), NANOPUSH_NULL_HANDLE, "result = NULL", true,
               "falvo result = NULL");
  expect_error(err, nanopush_icor_cubic_roots(err, -1e-9, 590e-9, 2.9e-14, 1, roots, nullptr, nullptr, nullptr,
                                              nullptr, nullptr, nullptr),
               NANOPUSH_BAD_INPUT, "yn = -1e-09", roots[0] == 7, "cubic yn < 0");
  expect_error(err, nanopush_icor_cubic_roots(err, 1e-9, 590e-9, 2.9e-14, 3, roots, nullptr, nullptr, nullptr,
                                              nullptr, nullptr, nullptr),
               NANOPUSH_BAD_INPUT, "method = 3", roots[0] == 7, "cubic method = 3");
  double rod[6];
  nanopush_icor_nanorod(nullptr, rod);
  rod[0] = 0.0;
  double props[5] = {7, 7, 7, 7, 7};
  expect_error(err, nanopush_icor_rod_properties(err, rod, props), NANOPUSH_BAD_INPUT, "rod.length = 0",
               props[0] == 7, "rod_properties L = 0");

  // Friction coefficient estimates: every bad input names the library's quantity, value and range
  // and writes no output.
  double mu = 7, sigma = 7, load = 7, d[4] = {7, 7, 7, 7};
  const auto untouched = [&] { return mu == 7 && sigma == 7 && load == 7 && d[0] == 7 && d[1] == 7 && d[2] == 7 && d[3] == 7; };
  double r6[6];
  nanopush_icor_nanorod(nullptr, r6);
  const auto from_force = [&](const double* r, double F, double sF, double yn, double syn, double sL, double sH) {
    return nanopush_estimate_mu_from_force(err, r, F, sF, yn, syn, sL, sH, &mu, &sigma, &load, d);
  };
  const auto from_icor = [&](const double* r, double F, double sF, double R, double sR, double sL, double sH) {
    return nanopush_estimate_mu_from_icor(err, r, F, sF, R, sR, sL, sH, &mu, &sigma, &load, d);
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto force_error = [&](int status, int want, const char* fragment, const char* what) {
    expect_error(err, status, want, fragment, untouched(), std::string("estimate_mu_from_force ") + what);
  };
  force_error(from_force(r6, 0.0, 0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "F = 0: must be > 0 (N)", "force = 0");
  force_error(from_force(r6, -1e-6, 0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "F = -1e-06: must be > 0 (N)", "force < 0");
  force_error(from_force(r6, nan, 0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "F = nan: must be a finite number (N)",
              "force NaN");
  force_error(from_force(r6, 1e-6, -1e-8, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT,
              "F uncertainty = -1e-08: must be >= 0 (N)", "sigma_force < 0");
  force_error(from_force(r6, 1e-6, 0, -1e-9, 0, 0, 0), NANOPUSH_BAD_INPUT, "yn = -1e-09: must be >= 0 (m)", "yn < 0");
  force_error(from_force(r6, 1e-6, 0, 3e-7, 0, 0, 0), NANOPUSH_BAD_INPUT,
              "yn = 3e-07: must be in [0, 2.95e-07] (m; push point on the rod", "yn > b");
  force_error(from_force(r6, 1e-6, 0, 1e-7, -5e-9, 0, 0), NANOPUSH_BAD_INPUT,
              "yn uncertainty = -5e-09: must be >= 0 (m)", "sigma_yn < 0");
  force_error(from_force(r6, 1e-6, 0, 1e-7, 0, -1e-9, 0), NANOPUSH_BAD_INPUT,
              "L uncertainty = -1e-09: must be >= 0 (m)", "sigma_L < 0");
  force_error(from_force(r6, 1e-6, 0, 1e-7, 0, 0, -1e-20), NANOPUSH_BAD_INPUT,
              "H uncertainty = -1e-20: must be >= 0 (J)", "sigma_H < 0");
  force_error(from_force(nullptr, 1e-6, 0, 1e-7, 0, 0, 0), NANOPUSH_NULL_HANDLE, "rod = NULL", "rod = NULL");
  double bad_rod[6];
  nanopush_icor_nanorod(nullptr, bad_rod);
  bad_rod[0] = 0.0;
  expect_error(err, from_force(bad_rod, 1e-6, 0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "rod.length = 0: must be > 0 (m)",
               untouched(), "estimate_mu_from_force rod.length = 0");
  bad_rod[0] = r6[0];
  bad_rod[3] = -4.7e-19;
  expect_error(err, from_icor(bad_rod, 1e-6, 0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "rod.hamaker = -4.7e-19: must be > 0 (J)",
               untouched(), "estimate_mu_from_icor rod.hamaker < 0");
  expect_error(err, from_icor(r6, 0.0, 0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "F = 0: must be > 0 (N)", untouched(),
               "estimate_mu_from_icor force = 0");
  expect_error(err, from_icor(r6, 1e-6, -1.0, 1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "F uncertainty = -1: must be >= 0 (N)",
               untouched(), "estimate_mu_from_icor sigma_force < 0");
  expect_error(err, from_icor(r6, 1e-6, 0, 0.0, 0, 0, 0), NANOPUSH_BAD_INPUT, "R = 0: must be > 0 (m)", untouched(),
               "estimate_mu_from_icor R = 0");
  expect_error(err, from_icor(r6, 1e-6, 0, -1e-7, 0, 0, 0), NANOPUSH_BAD_INPUT, "R = -1e-07: must be > 0 (m)",
               untouched(), "estimate_mu_from_icor R < 0");
  expect_error(err, from_icor(r6, 1e-6, 0, 1e-7, -1e-9, 0, 0), NANOPUSH_BAD_INPUT,
               "R uncertainty = -1e-09: must be >= 0 (m)", untouched(), "estimate_mu_from_icor sigma_R < 0");
  expect_error(err, from_icor(r6, 1e-6, 0, 1e-7, 0, -1e-9, 0), NANOPUSH_BAD_INPUT,
               "L uncertainty = -1e-09: must be >= 0 (m)", untouched(), "estimate_mu_from_icor sigma_L < 0");
  expect_error(err, from_icor(r6, 1e-6, 0, 1e-7, 0, 0, -1e-20), NANOPUSH_BAD_INPUT,
               "H uncertainty = -1e-20: must be >= 0 (J)", untouched(), "estimate_mu_from_icor sigma_H < 0");
  expect_error(err, from_icor(nullptr, 1e-6, 0, 1e-7, 0, 0, 0), NANOPUSH_NULL_HANDLE, "rod = NULL", untouched(),
               "estimate_mu_from_icor rod = NULL");
  // A success leaves the error handle as it was (here: cleared).
  check(from_icor(r6, 1e-6, 0, 1e-7, 0, 0, 0) == NANOPUSH_OK && nanopush_check_error(err) == NANOPUSH_OK && mu != 7,
        "estimate_mu_from_icor succeeds after the failures");
  nanopush_delete_error(&err);
}

/// The library's friction wrench for each "R,alpha" line, in `nanopush friction`'s CSV format.
int write_reference(const char* points, int sense, const char* out_path) {
  std::ifstream in(points);
  if (!in) {
    std::fprintf(stderr, "cannot read %s\n", points);
    return 2;
  }
  std::ostringstream o;
  o << "R,alpha,fx,fy,mf\n";
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line == "R,alpha") continue;
    const auto comma = line.find(',');
    const double R = std::stod(line.substr(0, comma)), alpha = std::stod(line.substr(comma + 1));
    const auto w = nanopush::rectangle_friction_wrench_checked(kBarA, kBarB, 1.0, R, alpha, sense);
    using nanopush::csv_number;
    o << csv_number(R) << ',' << csv_number(alpha) << ',' << csv_number(w.fx) << ',' << csv_number(w.fy) << ','
      << csv_number(w.mf) << '\n';
    ++n;
  }
  nanopush::write_file_atomic(out_path, o.str());
  std::printf("library friction wrench (sense %d) at %d points -> %s\n", sense, n, out_path);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  friction_matches_library();
  icor_matches_library();
  estimate_mu_matches_library();
  bad_input();
  if (nanopush_capi_test::finish() != 0) return 1;
  if (argc == 4) return write_reference(argv[1], std::atoi(argv[2]), argv[3]);
  return 0;
}
