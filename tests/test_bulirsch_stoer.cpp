// Numeric tier: the C++ Bulirsch–Stoer engine on problems with exact solutions.
#include <catch2/catch.hpp>

#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include "nanopush/numerics/bulirsch_stoer.hpp"
#include "support/support.hpp"

using namespace nanopush;

#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
// Allocation counter for the "no allocation per step" contract.
static std::atomic<long> g_allocs{0};
void* operator new(std::size_t n) {
  ++g_allocs;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  ++g_allocs;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocs;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocs;
  return std::malloc(n ? n : 1);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

using nanopush::test::Oscillator;

template <typename S, int N>
double oscillator_error(BsOptions<S> opt, double t_end, BsResult* out = nullptr) {
  BulirschStoer<S, N> bs(opt, 2);
  S y[2] = {1, 0};
  std::vector<S> tout;
  for (int i = 0; i <= 20; ++i) tout.push_back(S(t_end) * S(i) / S(20));
  double err = 0;
  auto res = bs.integrate(Oscillator{}, S(0), y, std::span<const S>(tout), [&](std::size_t, S t, const S* yy) {
    err = std::max(err, static_cast<double>(num::abs(yy[0] - num::cos(t))));
    err = std::max(err, static_cast<double>(num::abs(yy[1] + num::sin(t))));
  });
  REQUIRE(res.ok());
  if (out) *out = res;
  return err;
}

/// Integrates the oscillator from (1, 0) through tout with bs and checks that nothing was
/// allocated while integrating (the work space is allocated at construction).
void check_integrates_without_allocating(BulirschStoer<double, 2>& bs, std::span<const double> tout) {
  double y[2] = {1, 0};
  double sink = 0;
  const long before = g_allocs.load();
  auto r = bs.integrate(Oscillator{}, 0.0, y, tout, [&](std::size_t, double, const double* yy) { sink += yy[0]; });
  const long after = g_allocs.load();
  REQUIRE(r.ok());
  CHECK(r.naccpt > 10);
  CHECK(after == before);
  CHECK(std::isfinite(sink));
}

}  // namespace

TEST_CASE("BS: y' = y reaches e to the requested tolerance, both extrapolations", "[bs][numeric]") {
  for (auto ex : {Extrapolation::rational, Extrapolation::polynomial}) {
    for (double rtol : {1e-6, 1e-9, 1e-12}) {
      BsOptions<double> o;
      o.rtol = rtol;
      o.atol = {rtol};
      o.extrapolation = ex;
      BulirschStoer<double, 1> bs(o);
      double y[1] = {1.0};
      auto r = bs.integrate([](double, const double* yy, double* d) { d[0] = yy[0]; return 0; }, 0.0, y, 1.0);
      REQUIRE(r.ok());
      CHECK(std::fabs(y[0] - std::exp(1.0)) <= 10 * rtol * std::exp(1.0));
      CHECK(r.naccpt > 0);
      CHECK(r.nfcn >= r.naccpt);
    }
  }
}

TEST_CASE("BS: error falls as the tolerance tightens (harmonic oscillator)", "[bs][numeric]") {
  double prev = 1.0;
  long prev_nfcn = 0;
  for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
    BsResult r;
    const double e = oscillator_error<double, 2>(BsOptions<double>::faithful(rtol, {rtol}), 10.0, &r);
    INFO("rtol " << rtol << " error " << e);
    CHECK(e < prev);
    CHECK(e <= 100 * rtol);
    CHECK(r.nfcn > prev_nfcn);
    prev = e;
    prev_nfcn = r.nfcn;
  }
}

TEST_CASE("BS: modern configuration also converges", "[bs][numeric]") {
  for (double rtol : {1e-6, 1e-10, 1e-13}) {
    const double e = oscillator_error<double, 2>(BsOptions<double>::modern(rtol, {rtol}), 10.0);
    CHECK(e <= 100 * rtol);
  }
}

TEST_CASE("BS: extended precision (long double, __float128)", "[bs][numeric]") {
  const double el = oscillator_error<long double, 2>(BsOptions<long double>::modern(1e-17L, {1e-17L}), 10.0);
  CHECK(el <= 1e-15);
  using q = num::quad;
  const double eq = oscillator_error<q, 2>(BsOptions<q>::modern(q(1e-28), {q(1e-28)}), 10.0);
  CHECK(eq <= 1e-25);
}

TEST_CASE("BS: fixed and dynamic dimension take identical steps", "[bs][unit]") {
  BsResult a, b;
  const double ea = oscillator_error<double, 2>(BsOptions<double>::faithful(1e-9, {1e-9}), 5.0, &a);
  const double eb = oscillator_error<double, Dynamic>(BsOptions<double>::faithful(1e-9, {1e-9}), 5.0, &b);
  CHECK(ea == eb);
  CHECK(a.nfcn == b.nfcn);
  CHECK(a.naccpt == b.naccpt);
  CHECK(a.nrejct == b.nrejct);
}

TEST_CASE("BS: output times are hit exactly, including t0 and repeated times", "[bs][unit]") {
  BulirschStoer<double, 2> bs(BsOptions<double>::faithful(1e-10, {1e-10}));
  double y[2] = {1, 0};
  const std::vector<double> tout = {0.0, 0.1, 0.1, 0.35, 2.0};
  std::vector<double> seen;
  auto r = bs.integrate(Oscillator{}, 0.0, y, std::span<const double>(tout),
                        [&](std::size_t i, double t, const double*) {
                          CHECK(i == seen.size());
                          seen.push_back(t);
                        });
  REQUIRE(r.ok());
  REQUIRE(seen == tout);
  CHECK(r.t_reached == 2.0);
}

TEST_CASE("BS: no allocation while integrating (fixed size)", "[bs][unit]") {
  BulirschStoer<double, 2> bs(BsOptions<double>::faithful(1e-12, {1e-12}));
  const double tout[3] = {1.0, 2.0, 30.0};
  check_integrates_without_allocating(bs, std::span<const double>(tout, 3));
}

TEST_CASE("BS: no allocation while integrating (dense output, many outputs)", "[bs][dense][unit]") {
  BulirschStoer<double, 2> bs(BsOptions<double>::modern(1e-12, {1e-12}));
  std::vector<double> tout(1001);
  for (std::size_t i = 0; i < tout.size(); ++i) tout[i] = 30.0 * static_cast<double>(i) / 1000.0;
  check_integrates_without_allocating(bs, std::span<const double>(tout));
}

TEST_CASE("BS: failures come back as statuses", "[bs][unit]") {
  SECTION("bad input") {
    BsOptions<double> o = BsOptions<double>::faithful(1e-8, {1e-8});
    o.kmax = 2;
    BulirschStoer<double, 1> bs(o);
    double y[1] = {1};
    auto r = bs.integrate([](double, const double* yy, double* d) { d[0] = yy[0]; return 0; }, 0.0, y, 1.0);
    CHECK(r.status == BsStatus::bad_input);
    CHECK_FALSE(r.message.empty());
    BulirschStoer<double, 1> bs2(BsOptions<double>::faithful(1e-8, {1e-8}));
    const double tout[2] = {1.0, 0.5};
    auto r2 = bs2.integrate([](double, const double* yy, double* d) { d[0] = yy[0]; return 0; }, 0.0, y,
                            std::span<const double>(tout, 2), [](std::size_t, double, const double*) {});
    CHECK(r2.status == BsStatus::bad_input);
  }
  SECTION("the RHS's status is propagated") {
    BulirschStoer<double, 1> bs(BsOptions<double>::faithful(1e-8, {1e-8}));
    double y[1] = {1};
    int calls = 0;
    auto r = bs.integrate(
        [&](double, const double* yy, double* d) {
          d[0] = yy[0];
          return ++calls > 40 ? 7 : 0;
        },
        0.0, y, 10.0);
    CHECK(r.status == BsStatus::rhs_failed);
    CHECK(r.rhs_status == 7);
  }
  SECTION("too many steps") {
    BsOptions<double> o = BsOptions<double>::faithful(1e-12, {1e-12});
    o.maxstp = 5;
    BulirschStoer<double, 2> bs(o);
    double y[2] = {1, 0};
    auto r = bs.integrate(Oscillator{}, 0.0, y, 100.0);
    CHECK(r.status == BsStatus::too_many_steps);
  }
  SECTION("non-finite RHS") {
    BulirschStoer<double, 1> bs(BsOptions<double>::faithful(1e-8, {1e-8}));
    double y[1] = {1};
    auto r = bs.integrate([](double t, const double*, double* d) { d[0] = t > 0.5 ? NAN : 1.0; return 0; }, 0.0, y, 1.0);
    CHECK(r.status != BsStatus::success);
  }
  SECTION("non-finite RHS from the start: the F77 engine's counts") {
    // As tests/fortran/test_bsint.f90 test_nonfinite: k = 7 at rtol 1e-10; the first attempt
    // computes rows 1..6 together (42 RHS), each of the 9 retries rows 1, 2 (6 RHS).
    BulirschStoer<double, 1> bs(BsOptions<double>::faithful(1e-10, {1e-10}));
    double y[1] = {1};
    auto r = bs.integrate([](double, const double*, double* d) { d[0] = NAN; return 0; }, 0.0, y, 1.0);
    CHECK(r.status == BsStatus::not_finite);
    CHECK(r.naccpt == 0);
    CHECK(r.nrejct == 10);
    CHECK(r.nfcn == 1 + 42 + 9 * 6);
    CHECK(y[0] == 1.0);
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
