// The classic input deck of the FORTRAN 77 main program fortran/prog_nanobar.f (built as
// `nanobar`, and as `nanobar_quad` in extended precision): every number with 17 significant
// digits, so both programs run exactly the scene nanopush runs.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "nanopush/scenes/scene.hpp"

namespace nanopush {

/// The deck of `scene` at tolerance rtol with absolute tolerances atol (8 entries). The
/// rest direction (world vx, vy, omega) is the velocity direction whose friction acts when
/// the body is exactly at rest; zero = none (the thesis law).
std::string legacy_deck(const Scene& scene, double rtol, const std::vector<double>& atol,
                        const std::array<double, 3>& rest_direction = {0.0, 0.0, 0.0});

}  // namespace nanopush
