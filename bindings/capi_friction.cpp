// C API: friction resultant over a rectangular contact (bindings/nanopush.h) through the checked
// entry points of cxx/include/nanopush/models/friction.hpp (bad input -> InputError -> status + message).
#include "capi_internal.hpp"
#include "nanopush/models/friction.hpp"

using namespace nanopush::capi;

namespace {
int store(const nanopush::FrictionWrench& w, double* wrench) {
  wrench[0] = w.fx;
  wrench[1] = w.fy;
  wrench[2] = w.mf;
  return NANOPUSH_OK;
}
}  // namespace

extern "C" {

int nanopush_friction_wrench(nanopush_error error, double a, double b, double muN, double R, double alpha,
                             int sense, double* wrench) {
  return guarded(error, [&] {
    require_handle(wrench, "wrench");
    return store(nanopush::rectangle_friction_wrench_checked(a, b, muN, R, alpha, sense), wrench);
  });
}

int nanopush_friction_from_velocity(nanopush_error error, double a, double b, double muN, double vx, double vy,
                                    double omega, double* wrench) {
  return guarded(error, [&] {
    require_handle(wrench, "wrench");
    return store(nanopush::rectangle_friction_from_velocity_checked(a, b, muN, vx, vy, omega), wrench);
  });
}

}  // extern "C"
