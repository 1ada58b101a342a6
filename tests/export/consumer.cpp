// Consumer of the installed nanopush C++ library (nanopush::core): run a scene and print the
// trajectory exactly as `nanopush run SCENE --engine E --out - --quiet` does.
// Usage: consumer_cxx SCENE.toml [cxx|f77]
#include <iomanip>
#include <iostream>

#include <nanopush/error.hpp>
#include <nanopush/simulate.hpp>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: consumer_cxx SCENE.toml [cxx|f77]\n";
    return 2;
  }
  try {
    const nanopush::Scene scene = nanopush::load_scene(argv[1]);
    nanopush::RunSettings settings;
    settings.engine = argc > 2 ? argv[2] : "";
    const nanopush::Trajectory tr = nanopush::run_scene(scene, settings);
    std::cout << "t,x,y,theta,vx,vy,omega,fx,fy,mf\n" << std::setprecision(17);
    for (const auto& r : tr.rows) {
      for (std::size_t i = 0; i < r.size(); ++i) std::cout << (i ? "," : "") << r[i];
      std::cout << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "consumer_cxx: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
