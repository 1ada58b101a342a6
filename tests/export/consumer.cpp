// Consumer of the installed nanopush C++ library (nanopush::core, nanopush::engines) and C API
// (nanopush::capi). Built by tests/export (C, C++ and Fortran enabled) and by tests/export/cxx_only
// (C++ only), neither setting CMAKE_CXX_STANDARD: C++20 comes with the targets.
// Usage: consumer_cxx SCENE.toml [cxx|f77]
//          run a scene and print the trajectory exactly as `nanopush run SCENE --engine E --out -
//          --quiet` does
//        consumer_cxx --friction SENSE < POINTS.csv
//          friction wrench of the nanobar (a = 27.5 nm, b = 50 nm, muN = 1) at each "R,alpha"
//          line, through the C API (nanopush_friction_wrench) checked against the C++ library,
//          printed exactly as `nanopush friction --sense SENSE` does
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <string>

#include <nanopush.h>
#include <nanopush/numerics/error.hpp>
#include <nanopush/models/friction.hpp>
#include <nanopush/scenes/simulate.hpp>
#include <nanopush/engines/engines.hpp>
#include <nanopush/outputs/io.hpp>

namespace {
int friction(int sense) {
  std::cout << "R,alpha,fx,fy,mf\n";
  std::string line;
  nanopush_error err = nanopush_new_error();
  while (std::getline(std::cin, line)) {
    if (line.empty() || line == "R,alpha") continue;
    const auto comma = line.find(',');
    const double R = std::stod(line.substr(0, comma)), alpha = std::stod(line.substr(comma + 1));
    double w[3];
    if (nanopush_friction_wrench(err, 27.5e-9, 50e-9, 1.0, R, alpha, sense, w) != NANOPUSH_OK) {
      char msg[256];
      nanopush_get_error(err, msg, sizeof msg);
      std::cerr << "consumer_cxx: " << msg << "\n";
      return 1;
    }
    const nanopush::FrictionWrench ref = nanopush::rectangle_friction_wrench_checked(27.5e-9, 50e-9, 1.0, R, alpha, sense);
    if (w[0] != ref.fx || w[1] != ref.fy || w[2] != ref.mf) {
      std::cerr << "consumer_cxx: the C API and the C++ library differ at R = " << R << ", alpha = " << alpha << "\n";
      return 1;
    }
    // Numbers formatted as the CLI's CSV formats them (nanopush::csv_number, nanopush::outputs).
    using nanopush::csv_number;
    std::cout << csv_number(R) << ',' << csv_number(alpha) << ',' << csv_number(w[0]) << ',' << csv_number(w[1])
              << ',' << csv_number(w[2]) << '\n';
  }
  nanopush_delete_error(&err);
  return 0;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: consumer_cxx SCENE.toml [cxx|f77] | consumer_cxx --friction SENSE < POINTS.csv\n";
    return 2;
  }
  if (std::string(argv[1]) == "--friction") return friction(argc > 2 ? std::atoi(argv[2]) : 1);
  try {
    const nanopush::Scene scene = nanopush::load_scene(argv[1]);
    nanopush::RunSettings settings;
    settings.engine = nanopush::parse_optional_choice<nanopush::Engine>("engine", argc > 2 ? argv[2] : "");
    // The C++ engine through nanopush::core alone (simulate.hpp), the F77 one through nanopush::engines.
    const nanopush::Trajectory tr = settings.engine == nanopush::Engine::cxx ? nanopush::run_scene(scene, settings)
                                                                            : nanopush::run_engine(scene, settings);
    std::cout << "t,x,y,theta,vx,vy,omega,fx,fy,mf\n";
    for (const auto& r : tr.rows) {
      for (std::size_t i = 0; i < r.size(); ++i) std::cout << (i ? "," : "") << nanopush::csv_number(r[i]);
      std::cout << "\n";
    }
  } catch (const std::exception& e) {
    std::cerr << "consumer_cxx: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
