// The reference of the Python binding benchmark (python/bench/bench_python.py): the friction
// wrench over n iCORs in a plain C++ loop (the unchecked hot path, three output arrays), the
// same iCORs the benchmark hands to nanopush.friction_wrench.
//   nanopush_py_friction_loop A B R.f64 ALPHA.f64 OUT.f64 REPEATS
// R.f64, ALPHA.f64: n raw doubles each; OUT.f64: fx[n], fy[n], mf[n] of the last repeat.
// Prints "evaluations_per_s <best of REPEATS>".
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "nanopush/models/friction.hpp"

namespace {

std::vector<double> read_doubles(const char* path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) throw std::runtime_error(std::string("cannot read ") + path);
  const auto bytes = static_cast<std::size_t>(in.tellg());
  std::vector<double> v(bytes / sizeof(double));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(v.data()), static_cast<std::streamsize>(v.size() * sizeof(double)));
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 7) {
    std::cerr << "usage: " << argv[0] << " A B R.f64 ALPHA.f64 OUT.f64 REPEATS\n";
    return 2;
  }
  try {
    const double a = std::strtod(argv[1], nullptr), b = std::strtod(argv[2], nullptr);
    const std::vector<double> R = read_doubles(argv[3]), alpha = read_doubles(argv[4]);
    const int repeats = std::max(1, std::atoi(argv[6]));
    if (R.size() != alpha.size()) throw std::runtime_error("R and alpha differ in length");
    const std::size_t n = R.size();
    std::vector<double> fx(n), fy(n), mf(n);
    double best = 0.0;
    for (int k = 0; k < repeats; ++k) {
      const auto t0 = std::chrono::steady_clock::now();
      for (std::size_t i = 0; i < n; ++i) {
        const auto w = nanopush::rectangle_friction_wrench(a, b, 1.0, R[i], alpha[i], 1);
        fx[i] = w.fx;
        fy[i] = w.fy;
        mf[i] = w.mf;
      }
      const double dt = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      best = std::max(best, static_cast<double>(n) / dt);
    }
    std::ofstream out(argv[5], std::ios::binary);
    for (const auto* v : {&fx, &fy, &mf})
      out.write(reinterpret_cast<const char*>(v->data()), static_cast<std::streamsize>(n * sizeof(double)));
    if (!out) throw std::runtime_error(std::string("cannot write ") + argv[5]);
    std::printf("evaluations_per_s %.17g\n", best);
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "nanopush_py_friction_loop: " << e.what() << "\n";
    return 1;
  }
}
