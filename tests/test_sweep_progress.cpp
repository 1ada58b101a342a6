// The progress line's rate and time left (sweep::ProgressRate): exact on samples whose times are
// given, so no test waits on a clock.
#include <catch2/catch.hpp>

#include "nanopush/sweeps/progress.hpp"

using nanopush::sweep::ProgressRate;

TEST_CASE("progress: the first report after the start has the true rate", "[sweep][unit]") {
  ProgressRate p;
  p.sample(0.0, 0);  // the work starts
  CHECK_FALSE(p.rate());
  CHECK(p.line(1100) == "0/1100 points, rate ...");  // not "0 points/s"
  p.sample(0.5, 100);
  REQUIRE(p.rate());
  CHECK(*p.rate() == 200.0);
  CHECK(*p.seconds_left(1100) == 5.0);
  CHECK(p.line(1100) == "100/1100 points, 200 points/s, 5 s left");
}

TEST_CASE("progress: a resumed sweep counts only the points done since it started", "[sweep][unit]") {
  ProgressRate p;
  p.sample(0.0, 500);  // 500 points from the journal
  p.sample(1.0, 600);
  CHECK(*p.rate() == 100.0);
  CHECK(*p.seconds_left(1000) == 4.0);
}

TEST_CASE("progress: the rate follows a change of pace within its window", "[sweep][unit]") {
  ProgressRate p(10.0);
  std::size_t done = 0;
  double t = 0;
  p.sample(t, done);
  for (int i = 0; i < 40; ++i) p.sample(t += 0.5, done += 50);  // 100 points/s for 20 s
  CHECK(*p.rate() == Approx(100.0).epsilon(1e-12));
  for (int i = 0; i < 40; ++i) p.sample(t += 0.5, done += 5);  // then 10 points/s for 20 s
  CHECK(*p.rate() == Approx(10.0).epsilon(1e-12));
  // The whole-run average (2200 points in 40 s = 55/s) is what the old line showed.
  CHECK(*p.seconds_left(done + 100) == Approx(10.0).epsilon(1e-12));
}

TEST_CASE("progress: no progress means no time left, done means none left", "[sweep][unit]") {
  ProgressRate p;
  p.sample(0.0, 0);
  p.sample(2.0, 0);
  CHECK(*p.rate() == 0.0);
  CHECK_FALSE(p.seconds_left(10));
  CHECK(p.line(10) == "0/10 points, 0 points/s");
  p.sample(3.0, 10);
  CHECK(*p.seconds_left(10) == 0.0);
}
