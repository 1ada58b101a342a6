// The FORTRAN 77 Bulirsch-Stoer engine through its C bridge (fortran/bridge/f77_bsint.h):
// C++ callbacks via udata, accuracy against exact solutions, counts, errors, re-entrancy,
// and the F77 smooth nanobar (Fig 3.6, theta0 = 0.5) against the exact pendulum.
#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <stdexcept>
#include <thread>
#include <vector>

#include "f77_bsint.h"

// File-local: its own namespace in the unity build (tests/CMakeLists.txt).
namespace {
namespace NANOPUSH_UNITY_ID {
namespace {

// A C callback that forwards to any callable F(int n, double t, const double* y, double* dydt)
// stored behind udata. Exceptions never cross into Fortran: they become status -1.
template <class F>
int forward(int n, double t, const double* y, double* dydt, void* udata) noexcept {
  try {
    return (*static_cast<F*>(udata))(n, t, y, dydt);
  } catch (...) {
    return -1;
  }
}

struct Run {
  int status = -99;
  std::vector<double> y;     // final state
  std::vector<double> yout;  // n * nout, column-major
  std::array<int, 3> nstat{-1, -1, -1};
  double at(int i, int k) const { return yout[static_cast<std::size_t>(i + static_cast<int>(y.size()) * k)]; }
};

template <class F>
Run integrate(F& f, std::vector<double> y0, double t0, const std::vector<double>& tout, double rtol,
              const std::vector<double>& atol, int iextr, int kmax = 8, int maxstp = 0) {
  Run r;
  const int n = static_cast<int>(y0.size());
  const int nout = static_cast<int>(tout.size());
  r.y = std::move(y0);
  r.yout.assign(static_cast<std::size_t>(n * nout), -1.0);
  r.status = np_f77_bsint(n, t0, r.y.data(), nout, tout.data(), r.yout.data(), rtol, atol.data(),
                          0.0, 0.0, kmax, iextr, maxstp, &forward<F>, &f, r.nstat.data());
  return r;
}

std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) v[static_cast<std::size_t>(i)] = a + (b - a) * i / (n - 1);
  return v;
}

// ---- Exact pendulum (docs/models.md section A) -------------------------------------------------

// Jacobi sn(u | m), 0 <= m < 1, and K(m), by the AGM / descending Landen transformation
// (Abramowitz & Stegun 16.4): a0 = 1, b0 = sqrt(1 - m), c0 = sqrt(m); iterate to c_N ~ 0;
// phi_N = 2^N a_N u; phi_{n-1} = (phi_n + asin(c_n sin(phi_n) / a_n)) / 2; sn = sin(phi_0);
// K = pi / (2 a_N).
struct Agm {
  std::array<double, 40> a{}, c{};
  int steps = 0;
  explicit Agm(double m) {
    a[0] = 1.0;
    double b = std::sqrt(1.0 - m);
    c[0] = std::sqrt(m);
    while (std::abs(c[static_cast<std::size_t>(steps)]) > 1e-17 * a[static_cast<std::size_t>(steps)] &&
           steps < 38) {
      const auto s = static_cast<std::size_t>(steps);
      a[s + 1] = 0.5 * (a[s] + b);
      c[s + 1] = 0.5 * (a[s] - b);
      b = std::sqrt(a[s] * b);
      ++steps;
    }
  }
  double K() const { return std::numbers::pi / (2.0 * a[static_cast<std::size_t>(steps)]); }
  double sn(double u) const {
    double phi = std::ldexp(a[static_cast<std::size_t>(steps)] * u, steps);
    for (int i = steps; i >= 1; --i) {
      const auto s = static_cast<std::size_t>(i);
      phi = 0.5 * (phi + std::asin(c[s] * std::sin(phi) / a[s]));
    }
    return std::sin(phi);
  }
};

// Incomplete elliptic integral F(phi | m) by composite Simpson (independent check of sn).
double ellip_f(double phi, double m) {
  const int n = 4000;
  const double h = phi / n;
  auto g = [m](double x) { return 1.0 / std::sqrt(1.0 - m * std::sin(x) * std::sin(x)); };
  double s = g(0.0) + g(phi);
  for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * g(i * h);
  return s * h / 3.0;
}

// Thesis nanobar (docs/models.md section A), push point (xn, -yn) in body axes, F along +X.
struct Bar {
  double m = 0.623425e-18;
  double I = 0.623425e-18 * (100e-9 * 100e-9 + 55e-9 * 55e-9) / 12.0;
  double F = 5e-6, beta = 0.0, xn = 27.5e-9, yn = 45e-9;
  std::array<double, 6> params() const { return {m, I, F, beta, xn, -yn}; }
  double d() const { return std::hypot(xn, yn); }
  double theta_star() const { return std::numbers::pi / 2 - std::atan(xn / yn); }
  double w0() const { return std::sqrt(F * d() / I); }
};

// theta(t) from rest at theta0: phi = theta - theta*, sin(phi/2) = k sn(K - w0 t | k^2).
struct Pendulum {
  double ts, w0, k;
  Agm agm;
  Pendulum(const Bar& b, double theta0)
      : ts(b.theta_star()), w0(b.w0()), k(std::sin((theta0 - b.theta_star()) / 2)), agm(k * k) {}
  double theta(double t) const { return ts + 2.0 * std::asin(k * agm.sn(agm.K() - w0 * t)); }
};

// Per-component absolute tolerance scales for the nanobar state (brief of issue 2).
constexpr std::array<double, 6> kBarScale{1e-9, 1e-9, 1.0, 1e-9 / 1e-10, 1e-9 / 1e-10, 1e10};

struct BarRun {
  int status = -99;
  std::vector<double> tout, yout;
  std::array<int, 3> nstat{-1, -1, -1};
};

BarRun run_bar(double theta0, double rtol, int iextr) {
  const Bar bar;
  BarRun r;
  r.tout = linspace(0.0, 1.6e-9, 101);
  r.yout.assign(6 * r.tout.size(), -1.0);
  std::array<double, 6> y{0, 0, theta0, 0, 0, 0}, atol{};
  for (std::size_t i = 0; i < 6; ++i) atol[i] = rtol * kBarScale[i];
  const auto p = bar.params();
  r.status = np_f77_bsint_smooth_bar(6, 0.0, y.data(), static_cast<int>(r.tout.size()), r.tout.data(),
                                     r.yout.data(), rtol, atol.data(), 0.0, 0.0, 8, iextr, 0, p.data(),
                                     r.nstat.data());
  return r;
}

void check_counts(const std::array<int, 3>& nstat, int calls) {
  CHECK(nstat[0] == calls);                          // nfcn = callback invocations
  CHECK(nstat[1] >= 1);                              // accepted steps
  CHECK(nstat[2] >= 0);                              // rejected steps
  CHECK(nstat[0] >= 6 * (nstat[1] + nstat[2]));      // f0 + columns 1 and 2 at least
}

}  // namespace

TEST_CASE("Jacobi sn helper: sn(K) = 1, m = 0 gives sin, inverse of F(phi|m)", "[f77][bsint][unit]") {
  const Agm zero(0.0);
  CHECK(zero.sn(0.7) == Approx(std::sin(0.7)).epsilon(1e-15));
  for (double m : {0.01, 0.0638, 0.5, 0.9}) {
    const Agm agm(m);
    CHECK(agm.sn(agm.K()) == Approx(1.0).epsilon(1e-15));
    CHECK(agm.K() == Approx(ellip_f(std::numbers::pi / 2, m)).epsilon(1e-13));
    for (double phi : {0.1, 0.7, 1.3}) {
      CHECK(agm.sn(ellip_f(phi, m)) == Approx(std::sin(phi)).epsilon(1e-13));
    }
  }
}

TEST_CASE("F77 BS via C callback: y' = y is exp(t), both extrapolations", "[f77][bsint][numeric]") {
  for (int iextr : {1, 2}) {
    int calls = 0;
    auto f = [&calls](int n, double, const double* y, double* dy) {
      ++calls;
      for (int i = 0; i < n; ++i) dy[i] = y[i];
      return 0;
    };
    const std::vector<double> tout{0.0, 0.3, 0.3, 1.0, 2.0};
    const double rtol = 1e-10;
    const Run r = integrate(f, {1.0}, 0.0, tout, rtol, {1e-12}, iextr);
    INFO("iextr = " << iextr);
    REQUIRE(r.status == 0);
    CHECK(r.at(0, 0) == 1.0);  // output at t0 recorded without a step
    for (std::size_t k = 0; k < tout.size(); ++k) {
      CHECK(std::abs(r.at(0, static_cast<int>(k)) - std::exp(tout[k])) <= 10 * rtol * std::exp(tout[k]));
    }
    CHECK(r.y[0] == r.at(0, 4));
    check_counts(r.nstat, calls);
  }
}

TEST_CASE("F77 BS via C callback: harmonic oscillator is (sin, cos), energy kept", "[f77][bsint][numeric]") {
  for (int iextr : {1, 2}) {
    int calls = 0;
    const double w = 3.0;  // y1' = w y2, y2' = -w y1: y = (sin wt, cos wt)
    auto f = [&calls, w](int, double, const double* y, double* dy) {
      ++calls;
      dy[0] = w * y[1];
      dy[1] = -w * y[0];
      return 0;
    };
    const auto tout = linspace(0.0, 5.0, 26);
    const Run r = integrate(f, {0.0, 1.0}, 0.0, tout, 1e-11, {1e-12, 1e-12}, iextr);
    INFO("iextr = " << iextr);
    REQUIRE(r.status == 0);
    double err = 0, eerr = 0;
    for (int k = 0; k < 26; ++k) {
      const double t = tout[static_cast<std::size_t>(k)];
      err = std::max({err, std::abs(r.at(0, k) - std::sin(w * t)), std::abs(r.at(1, k) - std::cos(w * t))});
      eerr = std::max(eerr, std::abs(r.at(0, k) * r.at(0, k) + r.at(1, k) * r.at(1, k) - 1.0));
    }
    CHECK(err <= 1e-9);
    CHECK(eerr <= 2e-9);
    check_counts(r.nstat, calls);
  }
}

TEST_CASE("F77 BS: error falls as rtol tightens (tolerance proportionality)", "[f77][bsint][numeric]") {
  auto f = [](int, double, const double* y, double* dy) {
    dy[0] = y[1];
    dy[1] = -y[0];
    return 0;
  };
  for (int iextr : {1, 2}) {
    double prev = 1.0;
    for (double rtol : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) {
      const Run r = integrate(f, {0.0, 1.0}, 0.0, {10.0}, rtol, {rtol, rtol}, iextr);
      REQUIRE(r.status == 0);
      const double err = std::max(std::abs(r.y[0] - std::sin(10.0)), std::abs(r.y[1] - std::cos(10.0)));
      INFO("iextr = " << iextr << ", rtol = " << rtol << ", err = " << err);
      CHECK(err <= 100 * rtol);
      CHECK(err < prev);
      prev = err;
    }
  }
}

TEST_CASE("F77 BS: a failing C++ callback gives status 4, an exception too", "[f77][bsint][unit]") {
  int calls = 0;
  auto fails = [&calls](int n, double t, const double* y, double* dy) {
    ++calls;
    for (int i = 0; i < n; ++i) dy[i] = y[i];
    return t > 0.5 ? 3 : 0;
  };
  Run r = integrate(fails, {1.0}, 0.0, {0.25, 0.5, 1.0}, 1e-10, {1e-12}, 1);
  CHECK(r.status == 4);
  CHECK(r.nstat[0] == calls);
  CHECK(std::abs(r.at(0, 1) - std::exp(0.5)) < 1e-8);  // output before the failure kept
  CHECK(r.at(0, 2) == -1.0);                           // output not reached untouched
  CHECK(r.y[0] == r.at(0, 1));                          // y = last output reached

  auto throws = [](int, double t, const double* y, double* dy) {
    if (t > 0.1) throw std::runtime_error("boom");
    dy[0] = y[0];
    return 0;
  };
  r = integrate(throws, {1.0}, 0.0, {1.0}, 1e-10, {1e-12}, 2);
  CHECK(r.status == 4);
}

// The same callable as BSINT's own FCN (np_f77_bsint_fcn): udata's bits in ipar.
template <class F>
void forward_fcn(const int* n, const double* t, const double* y, double* dydt, const double*, int* ipar,
                 int* ierr) noexcept {
  void* udata;
  std::memcpy(&udata, ipar, sizeof udata);
  try {
    *ierr = (*static_cast<F*>(udata))(*n, *t, y, dydt);
  } catch (...) {
    *ierr = -1;
  }
}

TEST_CASE("F77 BS with the RHS as its FCN (np_f77_bsint_fcn) equals the C callback bit for bit",
          "[f77][bsint][unit]") {
  // harmonic oscillator with a parameter reached through udata; both extrapolations
  for (int iextr : {1, 2}) {
    struct Osc {
      double w2;
      int calls = 0;
      int operator()(int, double, const double* y, double* dy) {
        ++calls;
        dy[0] = y[1];
        dy[1] = -w2 * y[0];
        return 0;
      }
    };
    Osc a{4.0}, b{4.0};
    const std::vector<double> tout = linspace(0.0, 10.0, 41);
    const std::vector<double> atol{1e-11, 1e-11};
    const Run ra = integrate(a, {1.0, 0.0}, 0.0, tout, 1e-11, atol, iextr);
    Run rb;
    rb.y = {1.0, 0.0};
    rb.yout.assign(2 * tout.size(), -1.0);
    rb.status = np_f77_bsint_fcn(2, 0.0, rb.y.data(), static_cast<int>(tout.size()), tout.data(), rb.yout.data(), 1e-11,
                                 atol.data(), 0.0, 0.0, 8, iextr, 0, &forward_fcn<Osc>, &b, rb.nstat.data());
    INFO("iextr = " << iextr);
    REQUIRE(ra.status == 0);
    REQUIRE(rb.status == 0);
    CHECK(rb.nstat == ra.nstat);
    CHECK(b.calls == a.calls);
    CHECK(rb.nstat[0] == b.calls);
    CHECK(rb.yout == ra.yout);
    CHECK(std::abs(rb.at(0, 40) - std::cos(20.0)) < 1e-8);
  }
  // a failing FCN: status 4, outputs before it kept
  int calls = 0;
  auto fails = [&calls](int n, double t, const double* y, double* dy) {
    ++calls;
    for (int i = 0; i < n; ++i) dy[i] = y[i];
    return t > 0.5 ? 3 : 0;
  };
  const std::vector<double> tout{0.25, 0.5, 1.0};
  const std::vector<double> atol{1e-12};
  std::vector<double> y{1.0}, yout(3, -1.0);
  std::array<int, 3> nstat{};
  const int st = np_f77_bsint_fcn(1, 0.0, y.data(), 3, tout.data(), yout.data(), 1e-10, atol.data(), 0.0, 0.0, 8, 1,
                                  0, &forward_fcn<decltype(fails)>, &fails, nstat.data());
  CHECK(st == 4);
  CHECK(nstat[0] == calls);
  CHECK(std::abs(yout[1] - std::exp(0.5)) < 1e-8);
  CHECK(yout[2] == -1.0);
}

TEST_CASE("F77 BS: bad input and step budget through the bridge", "[f77][bsint][unit]") {
  int calls = 0;
  auto f = [&calls](int, double, const double* y, double* dy) {
    ++calls;
    dy[0] = y[1];
    dy[1] = -y[0];
    return 0;
  };
  CHECK(integrate(f, {0.0, 1.0}, 0.0, {1.0}, 1e-8, {1e-8, 1e-8}, 1, 2).status == 1);   // kmax
  CHECK(integrate(f, {0.0, 1.0}, 0.0, {1.0}, -1e-8, {1e-8, 1e-8}, 1).status == 1);     // rtol
  CHECK(integrate(f, {0.0, 1.0}, 0.0, {2.0, 1.0}, 1e-8, {1e-8, 1e-8}, 1).status == 1); // tout
  CHECK(integrate(f, {0.0, 1.0}, 0.0, {1.0}, 1e-8, {1e-8, 1e-8}, 0).status == 1);      // iextr
  CHECK(calls == 0);
  std::vector<double> none;
  std::array<int, 3> nstat{};
  double tout = 1.0, yout = 0.0;
  CHECK(np_f77_bsint(0, 0.0, none.data(), 1, &tout, &yout, 1e-8, none.data(), 0, 0, 8, 1, 0,
                     &forward<decltype(f)>, &f, nstat.data()) == 1);
  const Run r = integrate(f, {0.0, 1.0}, 0.0, {100.0}, 1e-10, {1e-10, 1e-10}, 1, 8, 4);
  CHECK(r.status == 2);
  CHECK(r.nstat[1] + r.nstat[2] == 4);
  // The smooth-bar entry point insists on n = 6.
  std::array<double, 6> y6{}, a6{1, 1, 1, 1, 1, 1}, p6{1, 1, 1, 0, 0, 0}, yo6{};
  CHECK(np_f77_bsint_smooth_bar(5, 0.0, y6.data(), 1, &tout, yo6.data(), 1e-8, a6.data(), 0, 0, 8, 1, 0,
                                p6.data(), nstat.data()) == 1);
}

TEST_CASE("F77 BS is re-entrant: an integration inside another's callback", "[f77][bsint][unit]") {
  // B: y' = -2 y on [0, 1]. A: oscillator on [0, 6]; every 25th call of A's RHS runs B.
  auto fb = [](int, double, const double* y, double* dy) {
    dy[0] = -2.0 * y[0];
    return 0;
  };
  const Run ref_b = integrate(fb, {1.0}, 0.0, {0.5, 1.0}, 1e-9, {1e-12}, 2);
  REQUIRE(ref_b.status == 0);
  CHECK(std::abs(ref_b.y[0] - std::exp(-2.0)) < 1e-8);

  int a_calls = 0, nested = 0, nested_bad = 0;
  auto fa = [&](int, double, const double* y, double* dy) {
    if (++a_calls % 25 == 0) {
      const Run b = integrate(fb, {1.0}, 0.0, {0.5, 1.0}, 1e-9, {1e-12}, 2);
      ++nested;
      if (b.status != 0 || b.yout != ref_b.yout || b.nstat != ref_b.nstat) ++nested_bad;
    }
    dy[0] = y[1];
    dy[1] = -y[0];
    return 0;
  };
  auto fa_plain = [](int, double, const double* y, double* dy) {
    dy[0] = y[1];
    dy[1] = -y[0];
    return 0;
  };
  const auto tout = linspace(0.0, 6.0, 7);
  const Run a = integrate(fa, {0.0, 1.0}, 0.0, tout, 1e-10, {1e-12, 1e-12}, 1);
  const Run ref_a = integrate(fa_plain, {0.0, 1.0}, 0.0, tout, 1e-10, {1e-12, 1e-12}, 1);
  REQUIRE(a.status == 0);
  CHECK(nested > 5);
  CHECK(nested_bad == 0);
  CHECK(a.yout == ref_a.yout);   // bitwise: the nested runs did not disturb A
  CHECK(a.nstat == ref_a.nstat);
}

TEST_CASE("F77 BS is thread-safe: concurrent integrations with different udata", "[f77][bsint][unit]") {
  // Each thread integrates y' = lambda y with its own lambda (held in its own udata) and must
  // get bit for bit what a serial run gets.
  struct Decay {
    double lambda;
    int operator()(int, double, const double* y, double* dy) const {
      dy[0] = lambda * y[0];
      return 0;
    }
  };
  const auto tout = linspace(0.0, 2.0, 21);
  Decay d1{-1.0}, d2{0.7};
  const Run s1 = integrate(d1, {1.0}, 0.0, tout, 1e-11, {1e-13}, 1);
  const Run s2 = integrate(d2, {1.0}, 0.0, tout, 1e-11, {1e-13}, 1);
  std::vector<Run> p1(20), p2(20);
  {
    std::thread t1([&] {
      for (auto& r : p1) r = integrate(d1, {1.0}, 0.0, tout, 1e-11, {1e-13}, 1);
    });
    std::thread t2([&] {
      for (auto& r : p2) r = integrate(d2, {1.0}, 0.0, tout, 1e-11, {1e-13}, 1);
    });
    t1.join();
    t2.join();
  }
  for (std::size_t i = 0; i < p1.size(); ++i) {
    CHECK(p1[i].yout == s1.yout);
    CHECK(p2[i].yout == s2.yout);
    CHECK(p1[i].nstat == s1.nstat);
    CHECK(p2[i].nstat == s2.nstat);
  }
  CHECK(std::abs(s1.y[0] - std::exp(-2.0)) < 1e-9);
  CHECK(std::abs(s2.y[0] - std::exp(1.4)) < 1e-9 * std::exp(1.4));
}

TEST_CASE("F77 BS smooth nanobar, Fig 3.6 theta0 = 0.5: exact pendulum and translation",
          "[f77][bsint][smooth_bar][numeric]") {
  const Bar bar;
  const Pendulum exact(bar, 0.5);
  for (int iextr : {1, 2}) {
    const BarRun r = run_bar(0.5, 1e-12, iextr);
    REQUIRE(r.status == 0);
    double eth = 0, ex = 0, eh = 0;
    const double e0 = -bar.F * bar.d() * std::cos(0.5 - bar.theta_star());
    for (std::size_t k = 0; k < r.tout.size(); ++k) {
      const double t = r.tout[k];
      const double* y = &r.yout[6 * k];
      eth = std::max(eth, std::abs(y[2] - exact.theta(t)));
      const double xex = 0.5 * bar.F / bar.m * t * t;
      if (t > 0) ex = std::max(ex, std::abs(y[0] - xex) / xex);
      const double energy = 0.5 * bar.I * y[5] * y[5] - bar.F * bar.d() * std::cos(y[2] - bar.theta_star());
      eh = std::max(eh, std::abs(energy - e0) / std::abs(e0));
      CHECK(y[1] == 0.0);  // no force along y: y stays exactly 0
    }
    INFO("iextr " << iextr << ": max |theta - exact| = " << eth << " rad, max rel x error = " << ex
                  << ", max rel energy drift = " << eh << ", nfcn/nacc/nrej = " << r.nstat[0] << "/"
                  << r.nstat[1] << "/" << r.nstat[2]);
    CHECK(eth <= 1e-10);
    CHECK(ex <= 1e-12);
    CHECK(eh <= 1e-10);
  }
}

// Regression tier: the counts recorded in docs/bulirsch_stoer.md ("Reference counts"), which the
// faithful C++ engine must also reproduce. A change here means the algorithm changed: update
// the doc and both engines together.
TEST_CASE("F77 BS reference counts (docs/bulirsch_stoer.md)", "[f77][bsint][regression]") {
  struct Case {
    double theta0;
    int nout, iextr;
    double rtol;
    std::array<int, 3> nstat;
  };
  const Case cases[] = {
      {0.5, 101, 1, 1e-6, {1308, 100, 0}},  {0.5, 101, 1, 1e-9, {2130, 100, 0}},
      {0.5, 101, 1, 1e-12, {3136, 100, 0}}, {0.5, 101, 2, 1e-6, {1308, 100, 0}},
      {0.5, 101, 2, 1e-9, {2110, 100, 0}},  {0.5, 101, 2, 1e-12, {3112, 100, 0}},
      {-0.5, 2, 1, 1e-6, {825, 17, 1}},     {-0.5, 2, 1, 1e-9, {1679, 27, 4}},
      {-0.5, 2, 1, 1e-12, {3021, 63, 13}},  {-0.5, 2, 2, 1e-9, {1703, 27, 5}},
      {0.5, 2, 1, 1e-9, {1199, 23, 1}},     {0.75, 2, 1, 1e-6, {719, 17, 4}},
      {1.5, 2, 2, 1e-12, {2066, 42, 4}},
  };
  const Bar bar;
  const auto p = bar.params();
  for (const Case& c : cases) {
    const auto tout = linspace(0.0, 1.6e-9, c.nout);
    std::vector<double> yout(6 * tout.size());
    std::array<double, 6> y{0, 0, c.theta0, 0, 0, 0}, atol{};
    for (std::size_t i = 0; i < 6; ++i) atol[i] = c.rtol * kBarScale[i];
    std::array<int, 3> nstat{};
    const int st = np_f77_bsint_smooth_bar(6, 0.0, y.data(), c.nout, tout.data(), yout.data(), c.rtol,
                                           atol.data(), 0.0, 0.0, 8, c.iextr, 0, p.data(), nstat.data());
    INFO("bar theta0 " << c.theta0 << " nout " << c.nout << " iextr " << c.iextr << " rtol " << c.rtol);
    CHECK(st == 0);
    CHECK(nstat == c.nstat);
  }
  auto osc = [](int, double, const double* y, double* dy) {
    dy[0] = y[1];
    dy[1] = -y[0];
    return 0;
  };
  const std::array<int, 3> osc_ref[2][3] = {{{276, 8, 0}, {527, 11, 0}, {933, 17, 0}},
                                            {{289, 11, 0}, {682, 14, 0}, {1300, 24, 0}}};
  const double rtols[3] = {1e-4, 1e-8, 1e-12};
  for (int e = 0; e < 2; ++e) {
    for (int i = 0; i < 3; ++i) {
      const double rtol = rtols[i];
      const Run r = integrate(osc, {0.0, 1.0}, 0.0, {20.0}, rtol, {rtol, rtol}, e + 1);
      INFO("oscillator iextr " << e + 1 << " rtol " << rtol);
      CHECK(r.status == 0);
      CHECK(r.nstat == osc_ref[e][i]);
    }
  }
}

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
