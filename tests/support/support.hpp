// What the C++ tests share: named tolerances, rel(), the base scene, the thesis presets and
// the error helpers. Header only: the test files compile in unity batches, so everything here
// is inline (tests/CMakeLists.txt).
#pragma once
#include <catch2/catch.hpp>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string>

#include "nanopush/numerics/error.hpp"
#include "nanopush/scenes/scene.hpp"

namespace nanopush::test {

// ---- Named tolerances -------------------------------------------------------------------
// Each says why it is that value; a test that needs another writes its own, with its reason.

/// Machine epsilon of double: closed forms are held to small multiples of it.
inline constexpr double kEps = std::numeric_limits<double>::epsilon();
/// The same double computation done two ways (C++ against F77, Brent against Eigen/LAPACK,
/// two solvers of one cubic): reordered arithmetic, a few thousand ulps, no room for a wrong
/// formula.
inline constexpr double kRelAgree = 1e-12;

// ---- Relative differences ---------------------------------------------------------------

/// |a - b| / max(|a|, |b|): symmetric, for two values neither of which is the reference
/// (NaN when both are 0).
inline double rel(double a, double b) { return std::fabs(a - b) / std::max(std::fabs(a), std::fabs(b)); }

/// |a - b| <= tol * max(|a|, |b|): rel(a, b) <= tol without dividing (true when both are 0).
inline bool rel_close(double a, double b, double tol) {
  return std::abs(a - b) <= tol * std::max(std::abs(a), std::abs(b));
}

/// |x - ref| <= tol * |ref|: x against a reference value.
inline bool close_to_ref(double x, double ref, double tol) { return std::abs(x - ref) <= tol * std::abs(ref); }

// ---- Test problems ----------------------------------------------------------------------

/// y1' = y2, y2' = -y1: exact (cos t, -sin t) from (1, 0); in any scalar type S.
struct Oscillator {
  template <typename S>
  int operator()(S, const S* y, S* d) const {
    d[0] = y[1];
    d[1] = -y[0];
    return 0;
  }
};

// ---- Scenes -----------------------------------------------------------------------------

/// The base scene as scene-file text: the smooth nanobar of the thesis' Fig 3.6 (100 x 55 x
/// 50 nm graphite, 5 uN at xn = 27.5 nm, yn = 45 nm), no [solver] table; tests append theirs.
inline const std::string kBaseSceneText = R"(
[object]
length = 100e-9
width = 55e-9
height = 50e-9
density = 2267.0
[push]
force = 5e-6
xn = 27.5e-9
yn = 45e-9
)";

/// A tip-push scene as text: a 100 x 10 x 10 nm graphite bar on a rough surface (mu N = 1 nN),
/// an AFM tip (radius 5 nm, 1 um/s) starting 20 nm beside it, 15 nm off its centre, for 60 nm.
inline const std::string kTipSceneText = R"(
[object]
length = 100e-9
width = 10e-9
height = 10e-9
density = 2267.0
[push]
mode = "tip"
[tip]
start_x = -20e-9
start_y = 15e-9
speed = 1e-6
travel = 60e-9
radius = 5e-9
[surface]
kind = "rough"
mu = 0.1
f_vdw = 1e-8
[solver]
samples = 101
)";

/// The base rough scene as text: the nanobar by mass (6e-19 kg), the same push, a rough
/// surface with mu = 0.1, t_end = 1 ns.
inline const std::string kBaseRoughSceneText = R"(
[object]
length = 100e-9
width = 55e-9
mass = 6e-19
[push]
force = 5e-6
xn = 27.5e-9
yn = 45e-9
[surface]
kind = "rough"
mu = 0.1
[solver]
t_end = 1e-9
)";

/// `text` with its first `from` replaced by `to`; `from` must occur.
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto p = text.find(from);
  REQUIRE(p != std::string::npos);
  text.replace(p, from.size(), to);
  return text;
}

/// A preset scene by its path under drivers/scenes/ (e.g. "thesis/fig3_6c.toml").
inline Scene preset(const std::string& rel_path) {
  return load_scene(std::string(NANOPUSH_SOURCE_DIR) + "/drivers/scenes/" + rel_path);
}

/// The thesis preset of Fig 3.`fig` (drivers/scenes/thesis/fig3_<fig>.toml).
inline Scene thesis_preset(int fig) { return preset("thesis/fig3_" + std::to_string(fig) + ".toml"); }

// ---- Scratch directories ----------------------------------------------------------------

/// An empty scratch directory of this process under the system's temporary directory
/// (nanopush_<what>_<pid>): device nodes, FIFOs and links of a test are made there only.
inline std::filesystem::path scratch_dir(const std::string& what) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("nanopush_" + what + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// ---- Errors -----------------------------------------------------------------------------

/// The message of the InputError `f` throws (`none` when it throws none).
template <class F>
std::string input_error_of(F&& f, const std::string& none = {}) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return none;
}

}  // namespace nanopush::test
