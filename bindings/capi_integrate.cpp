// C API: integrating a user's right-hand side (a C callback with udata) with the C++
// Bulirsch-Stoer engine, dimension chosen at run time (bindings/nanopush.h).
#include <cmath>
#include <vector>
#include <memory>
#include <span>

#include <limits>
#include <algorithm>
#include "capi_internal.hpp"
#include "nanopush/scenes/choices.hpp"
#include "nanopush/numerics/bulirsch_stoer.hpp"

using namespace nanopush::capi;

namespace {

/// The method name -> the engine's option presets.
/// What SUNDIALS' CVODE refuses before it starts, refused the same way (and named):
///  - a non-finite t0, state or output time (bad input);
///  - output times closer together than the integrator can step (CVODE's "tout too close to
///    t0 to start integration"): consecutive distinct times, t0 first, less than
///    1e-14 max(|t|, |t_prev|, span) apart, the Bulirsch-Stoer's smallest step (its step size
///    underflow rule, span = tout[nout-1] - t0);
///  - more accuracy than double precision gives: tolsf = eps ||y0||, the weighted RMS norm with
///    weights 1 / (rtol |y_i| + atol_i), above 1 (CVODE's "too much accuracy requested").
void check_start(const nanopush::BsOptions<double>& o, double t0, const double* y, int n, const double* tout,
                 int nout) {
  nanopush::require_finite("t0", t0);
  for (int i = 0; i < n; ++i) nanopush::require_finite("y[" + std::to_string(i) + "]", y[i]);
  constexpr double eps = std::numeric_limits<double>::epsilon();
  // Every output time finite first: an infinite last time made every span "too close".
  for (int k = 0; k < nout; ++k) nanopush::require_finite("tout[" + std::to_string(k) + "]", tout[k]);
  double prev = t0;
  const double span = std::fabs(tout[nout - 1] - t0);
  for (int k = 0; k < nout; ++k) {
    const double t = tout[k];
    if (t < prev)
      throw nanopush::InputError("tout[" + std::to_string(k) + "]", nanopush::fmt(t),
                                 "must be >= " + std::string(k ? "tout[" + std::to_string(k - 1) + "]" : "t0") +
                                     " = " + nanopush::fmt(prev) + " (output times non-decreasing from t0)");
    if (t != prev && t - prev < 1e-14 * std::max({std::fabs(t), std::fabs(prev), span}))
      throw StatusError(NANOPUSH_TOUT_TOO_CLOSE,
                        "tout[" + std::to_string(k) + "] = " + nanopush::fmt(t) + " is too close to " +
                            (k ? "tout[" + std::to_string(k - 1) + "]" : std::string("t0")) + " = " +
                            nanopush::fmt(prev) + ": less than 1e-14 max(|t|, span) apart, the smallest step the "
                            "integrator takes");
    prev = t;
  }
  std::vector<double> r(static_cast<std::size_t>(n), 0.0);  // y_i / w_i, scaled below (no overflow)
  double big = 0;
  for (int i = 0; i < n; ++i) {
    const double a = o.atol.size() == 1 ? o.atol[0] : o.atol[static_cast<std::size_t>(i)];
    const double w = o.rtol * std::fabs(y[i]) + a;
    if (y[i] != 0.0) r[static_cast<std::size_t>(i)] = w > 0 ? std::fabs(y[i]) / w : std::numeric_limits<double>::infinity();
    big = std::max(big, r[static_cast<std::size_t>(i)]);
  }
  double sum = 0;
  if (big > 0 && std::isfinite(big))
    for (double x : r) sum += (x / big) * (x / big);
  const double tolsf = std::isfinite(big) ? eps * big * std::sqrt(sum / n) : big;
  if (tolsf > 1.0)
    throw StatusError(NANOPUSH_TOO_MUCH_ACCURACY,
                      "rtol = " + nanopush::fmt(o.rtol) +
                          " with these atol asks for more accuracy than double precision gives (eps times the "
                          "weighted norm of y0 is " + nanopush::fmt(tolsf) +
                          " > 1): loosen rtol to >= 2.2e-16 relative, or give atol > 0 in each component's units");
}

nanopush::BsOptions<double> preset(const std::string& method, double rtol, std::vector<double> atol) {
  const auto m = method.empty() ? std::optional(nanopush::Method::faithful) : nanopush::choice_from_name<nanopush::Method>(method);
  if (m == nanopush::Method::faithful) return nanopush::BsOptions<double>::faithful(rtol, std::move(atol));
  if (m == nanopush::Method::modern) return nanopush::BsOptions<double>::modern(rtol, std::move(atol));
  throw nanopush::InputError("method", "\"" + method + "\"", "must be faithful or modern");
}

}  // namespace

extern "C" {

nanopush_integrator nanopush_new_integrator(nanopush_error error, int n, const char* method, double rtol,
                                            const double* atol, int natol) {
  nanopush_integrator out = nullptr;
  guarded(error, [&] {
    if (n < 1 || n > 1000000)
      throw nanopush::InputError("n", std::to_string(n), "must be in [1, 1000000] (number of ODE components)");
    nanopush::require_nonnegative("rtol", rtol);
    if (natol != 1 && natol != n)
      throw nanopush::InputError("natol", std::to_string(natol), "must be 1 or n = " + std::to_string(n));
    require_handle(atol, "atol");
    std::vector<double> a(atol, atol + natol);
    for (int i = 0; i < natol; ++i) {
      nanopush::require_nonnegative("atol[" + std::to_string(i) + "]", a[static_cast<std::size_t>(i)]);
      if (a[static_cast<std::size_t>(i)] == 0 && rtol == 0)
        throw nanopush::InputError("atol[" + std::to_string(i) + "]", "0", "must be > 0 when rtol = 0");
    }
    auto it = std::make_unique<nanopush_integrator_s>();
    it->n = n;
    it->options = preset(opt_string(method), rtol, std::move(a));
    out = it.release();
    return NANOPUSH_OK;
  });
  return out;
}

void nanopush_delete_integrator(nanopush_integrator* integrator) { delete_handle(integrator); }

int nanopush_integrator_set_steps(nanopush_error error, nanopush_integrator integrator, double h0, double hmax,
                                  int64_t maxstp) {
  return guarded(error, [&] {
    require_handle(integrator, "integrator");
    nanopush::require_nonnegative("h0", h0);
    nanopush::require_nonnegative("hmax", hmax);
    if (maxstp < 1) throw nanopush::InputError("maxstp", std::to_string(maxstp), "must be >= 1");
    integrator->options.h0 = h0;
    integrator->options.hmax = hmax;
    integrator->options.maxstp = maxstp;
    return NANOPUSH_OK;
  });
}

int nanopush_integrator_set_extrapolation(nanopush_error error, nanopush_integrator integrator, int kmax,
                                          int extrapolation) {
  return guarded(error, [&] {
    require_handle(integrator, "integrator");
    if (kmax < 3 || kmax > 12) throw nanopush::InputError("kmax", std::to_string(kmax), "must be in [3, 12]");
    if (extrapolation != 1 && extrapolation != 2)
      throw nanopush::InputError("extrapolation", std::to_string(extrapolation),
                                 "must be 1 (rational) or 2 (polynomial)");
    integrator->options.kmax = kmax;
    integrator->options.extrapolation = static_cast<nanopush::Extrapolation>(extrapolation);
    return NANOPUSH_OK;
  });
}

int nanopush_integrate(nanopush_error error, nanopush_integrator integrator, nanopush_rhs rhs, void* udata,
                       double t0, double* y, int nout, const double* tout, double* yout, int64_t* counts) {
  return guarded(error, [&] {
    require_handle(integrator, "integrator");
    if (!rhs) throw StatusError(NANOPUSH_NULL_HANDLE, "rhs = NULL: must be a right-hand-side function");
    require_handle(y, "y");
    if (nout < 1) throw nanopush::InputError("nout", std::to_string(nout), "must be >= 1 (number of output times)");
    require_handle(tout, "tout");
    if (counts) counts[0] = counts[1] = counts[2] = 0;
    const int n = integrator->n;
    check_start(integrator->options, t0, y, n, tout, nout);
    // A fresh engine per call: its work arrays are local, so calls never share state.
    nanopush::BulirschStoer<double, nanopush::Dynamic> bs(integrator->options, n);
    auto f = [rhs, udata, n](double t, const double* yy, double* dydt) { return rhs(n, t, yy, dydt, udata); };
    const std::size_t un = static_cast<std::size_t>(n);
    const nanopush::BsResult res =
        bs.integrate(f, t0, y, std::span<const double>(tout, static_cast<std::size_t>(nout)),
                     [yout, un](std::size_t k, double, const double* yy) {
                       if (yout) std::copy(yy, yy + un, yout + un * k);
                     });
    if (counts) {
      counts[0] = res.nfcn;
      counts[1] = res.naccpt;
      counts[2] = res.nrejct;
    }
    if (!res.ok()) throw StatusError(static_cast<int>(res.status), std::string(nanopush::to_string(res.status)) +
                                                                        (res.message.empty() ? "" : ": " + res.message));
    return NANOPUSH_OK;
  });
}

}  // extern "C"
