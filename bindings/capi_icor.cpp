// C API: the iCOR toolkit (bindings/nanopush.h) over cxx/include/nanopush/models/icor.hpp. Every formula
// is one line: evaluate (InputError on bad input -> status + message), then store the result.
#include <limits>
#include <string>

#include "capi_internal.hpp"
#include "nanopush/models/icor.hpp"

using namespace nanopush::capi;
namespace icor = nanopush::icor;

namespace {
/// One scalar formula: *out = f(), stored only on success.
template <class F>
int scalar(nanopush_error error, double* out, F&& f) {
  return guarded(error, [&] {
    require_handle(out, "result");
    const double v = f();
    *out = v;
    return NANOPUSH_OK;
  });
}

}  // namespace

extern "C" {

int nanopush_icor_experimental_fit(nanopush_error e, double yn, double L, double* R) {
  return scalar(e, R, [&] { return icor::experimental_fit(yn, L); });
}
int nanopush_icor_falvo(nanopush_error e, double yn, double L, double* R) {
  return scalar(e, R, [&] { return icor::falvo(yn, L); });
}
int nanopush_icor_li(nanopush_error e, double yn, double L, double* R) {
  return scalar(e, R, [&] { return icor::li(yn, L); });
}
int nanopush_icor_unknown_pressure(nanopush_error e, double yn, double L, double* R) {
  return scalar(e, R, [&] { return icor::unknown_pressure(yn, L); });
}
int nanopush_icor_known_pressure(nanopush_error e, double mu, double W, double yn, double F, double L, double* R) {
  return scalar(e, R, [&] { return icor::known_pressure(mu, W, yn, F, L); });
}
int nanopush_icor_minimum_force(nanopush_error e, double mu, double W, double yn, double L, double* F) {
  return scalar(e, F, [&] { return icor::minimum_force(mu, W, yn, L); });
}
int nanopush_icor_force_from_icor(nanopush_error e, double mu, double W, double R, double L, double* F) {
  return scalar(e, F, [&] { return icor::force_from_icor(mu, W, R, L); });
}
int nanopush_icor_force_unknown_pressure(nanopush_error e, double mu, double W, double R, double yn, double L,
                                         double* F) {
  return scalar(e, F, [&] { return icor::force_unknown_pressure(mu, W, R, yn, L); });
}
int nanopush_icor_constrained_force(nanopush_error e, double mu, double W, double R, double yn, double L,
                                    double k2, double* F) {
  return scalar(e, F, [&] { return icor::constrained_force(mu, W, R, yn, L, k2); });
}
int nanopush_icor_impulsive(nanopush_error e, double yn, double k2, double* R) {
  return scalar(e, R, [&] { return icor::impulsive(yn, k2); });
}

int nanopush_icor_cubic_roots(nanopush_error error, double yn, double L, double k2, int method, double* roots,
                              int* nroots, int* ncomplex, int* at_infinity, double* negative, double* positive,
                              double* max_residual) {
  return guarded(error, [&] {
    require_handle(roots, "roots");
    if (method != NANOPUSH_CUBIC_BRENT && method != NANOPUSH_CUBIC_EIGEN)
      throw nanopush::InputError("method", std::to_string(method),
                                 "must be NANOPUSH_CUBIC_BRENT (1) or NANOPUSH_CUBIC_EIGEN (2)");
    // The push point lies on the rod, as every chapter 4 formula requires (the C++ solver
    // itself stays defined beyond, for its robustness tests).
    nanopush::require_positive("L", L, "m");
    nanopush::require_range("yn", yn, 0.0, 0.5 * L, "m; push point on the rod, at most b = L/2");
    const icor::CubicSolution s = icor::solve_constrained_cubic(
        yn, L, k2, method == NANOPUSH_CUBIC_BRENT ? icor::CubicMethod::Brent : icor::CubicMethod::Eigen);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t i = 0; i < 3; ++i) roots[i] = i < s.real_roots.size() ? s.real_roots[i] : nan;
    if (nroots) *nroots = static_cast<int>(s.real_roots.size());
    if (ncomplex) *ncomplex = s.complex_roots;
    if (at_infinity) *at_infinity = s.at_infinity;
    if (negative) *negative = s.negative.value_or(nan);
    if (positive) *positive = s.positive.value_or(nan);
    if (max_residual) *max_residual = s.max_residual;
    return NANOPUSH_OK;
  });
}

int nanopush_icor_nanorod(nanopush_error error, double* rod) {
  return guarded(error, [&] {
    require_handle(rod, "rod");
    const icor::Rod r = icor::nanorod();
    const double v[6] = {r.length, r.radius, r.density, r.hamaker, r.z0, r.gravity};
    std::copy(v, v + 6, rod);
    return NANOPUSH_OK;
  });
}

int nanopush_icor_rod_properties(nanopush_error error, const double* rod, double* props) {
  return guarded(error, [&] {
    require_handle(rod, "rod");
    require_handle(props, "props");
    const icor::Rod r = rod_from(rod);
    const double v[5] = {r.mass(), r.inertia(), r.gyration_squared(), r.vdw_force(), r.load()};
    std::copy(v, v + 5, props);
    return NANOPUSH_OK;
  });
}

}  // extern "C"
