// No C++ exception crosses the C API: exceptions thrown inside (here by C++ right-hand-side
// callbacks, which run inside the library's C++ frames) come back as a status and a message.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>

#include "nanopush.h"
#include "nanopush/numerics/error.hpp"

namespace {

int failures = 0;
void check(bool ok, const char* what) {
  if (!ok) {
    ++failures;
    std::fprintf(stderr, "FAIL: %s\n", what);
  }
}

// udata selects what to throw once t > 0.5.
int throwing_rhs(int n, double t, const double* y, double* dydt, void* udata) {
  for (int i = 0; i < n; ++i) dydt[i] = -y[i];
  if (t <= 0.5) return 0;
  switch (*static_cast<const int*>(udata)) {
    case 0: throw std::runtime_error("the model broke");
    case 1: throw std::bad_alloc();
    case 2: throw nanopush::InputError("model.k", "-3", "must be > 0");
    default: throw 42;  // not even a std::exception
  }
}

std::string message(nanopush_error err) {
  char buf[256];
  nanopush_get_error(err, buf, sizeof buf);
  return buf;
}

}  // namespace

int main() {
  nanopush_error err = nanopush_new_error();
  const double atol = 1e-10;
  nanopush_integrator bs = nanopush_new_integrator(err, 2, nullptr, 1e-10, &atol, 1);
  check(bs != nullptr, "integrator created");
  const double tout[2] = {0.25, 1.0};
  struct Case {
    int what, status;
    const char* fragment;
  } cases[] = {{0, NANOPUSH_INTERNAL, "the model broke"},
               {1, NANOPUSH_OUT_OF_MEMORY, "out of memory"},
               {2, NANOPUSH_BAD_INPUT, "model.k = -3: must be > 0"},
               {3, NANOPUSH_INTERNAL, "unknown C++ exception"}};
  for (const Case& c : cases) {
    double y[2] = {1, 2}, yout[4] = {0, 0, 0, 0};
    int what = c.what;
    nanopush_clear_error(err);
    const int st = nanopush_integrate(err, bs, throwing_rhs, &what, 0.0, y, 2, tout, yout, nullptr);
    const std::string msg = message(err);
    std::printf("throw case %d: status %d (%s), message \"%s\"\n", c.what, st, nanopush_status_name(st), msg.c_str());
    check(st == c.status && nanopush_check_error(err) == c.status, "status");
    check(msg.find(c.fragment) != std::string::npos, "message");
    check(std::fabs(yout[0] - std::exp(-0.25)) < 1e-8, "output before the throw kept");
  }
  // The integrator is still usable afterwards.
  int never = -1;
  double y[2] = {1, 2}, yout[4];
  const double t_short[2] = {0.1, 0.5};
  check(nanopush_integrate(err, bs, throwing_rhs, &never, 0.0, y, 2, t_short, yout, nullptr) == NANOPUSH_OK,
        "integrator reusable after exceptions");
  check(std::fabs(y[1] - 2 * std::exp(-0.5)) < 1e-8, "and correct");
  nanopush_delete_integrator(&bs);
  nanopush_delete_error(&err);
  if (failures) return 1;
  std::printf("all checks hold\n");
  return 0;
}
