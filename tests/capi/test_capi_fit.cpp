// nanopush_fit_trajectory (bindings/nanopush.h) returns exactly the estimates of
// nanopush::fit::fit_trajectory (bit for bit), its JSON summary, and bad input as a status and a
// message with the outputs untouched.
// Usage: capi_test_fit SCENE.toml WORK_DIR
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "../support/capi_check.hpp"
#include "nanopush.h"
#include "nanopush/fitting/fit.hpp"
#include "nanopush/scenes/scene.hpp"

namespace {

using nanopush_capi_test::check;
using nanopush_capi_test::message;
using nanopush_capi_test::same;

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: capi_test_fit SCENE.toml WORK_DIR\n");
    return 2;
  }
  namespace fit = nanopush::fit;
  const std::string scene_path = argv[1];
  const std::filesystem::path dir = argv[2];
  std::filesystem::create_directories(dir);
  const std::string data = (dir / "data.csv").string();

  // The truth: a short smooth scene; data: x only, sigma 2 nm, seed 3; start: push.force 4e-6.
  nanopush::Scene truth = nanopush::load_scene(scene_path);
  truth.set({{"solver.t_end", 0.4e-9}, {"solver.samples", 21}});
  {
    std::ofstream out(data);
    out << fit::observations_csv(fit::synthesize(truth, {2e-9, 0, 0}, 3));
  }
  nanopush::Scene start = truth;
  start.set("push.force", 4e-6);
  fit::FitOptions o;
  o.free = {"push.force"};
  const fit::FitResult want = fit::fit_trajectory(start, fit::read_observations(data), o);

  nanopush_error err = nanopush_new_error();
  nanopush_scene scene = nanopush_load_scene(err, scene_path.c_str());
  check(scene != nullptr, "load scene");
  check(nanopush_scene_set_real(err, scene, "solver.t_end", 0.4e-9) == NANOPUSH_OK &&
            nanopush_scene_set_real(err, scene, "solver.samples", 21) == NANOPUSH_OK &&
            nanopush_scene_set_real(err, scene, "push.force", 4e-6) == NANOPUSH_OK,
        "set keys");
  double value = 0, se = 0, summary[NANOPUSH_FIT_SUMMARY_SIZE];
  int converged = -1, len = -1;
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force", nullptr, nullptr, 1, &value, &se, summary,
                                &converged, nullptr, 0, &len) == NANOPUSH_OK,
        "fit: status " + message(err));
  check(same(value, want.parameters[0].value) && same(se, want.parameters[0].stderr_),
        "fit: estimate and stderr bit for bit");
  check(same(summary[0], want.chi2) && same(summary[1], want.chi2_dof) && summary[2] == static_cast<double>(want.dof) &&
            summary[4] == static_cast<double>(want.n_forward_solves) && summary[5] == 1.0,
        "fit: summary");
  check(converged == 1 && want.converged, "fit: converged");
  check(std::abs(value - truth.push.force) < 3 * se, "fit: truth within 3 stderr");
  // The JSON, queried then copied.
  std::vector<char> json(static_cast<std::size_t>(len) + 1);
  int len2 = -1;
  check(nanopush_fit_trajectory(err, scene, data.c_str(), " push.force ", "", "", 1, nullptr, nullptr, nullptr,
                                nullptr, json.data(), len + 1, &len2) == NANOPUSH_OK &&
            len2 == len && std::strlen(json.data()) == static_cast<std::size_t>(len),
        "fit: JSON length");
  const auto doc = nlohmann::json::parse(json.data());
  check(doc["parameters"]["push.force"]["value"].is_number() && doc["parameters"]["push.force"]["value"] == value &&
            doc["converged"] == true,
        "fit: JSON shape");
  // The scene's solver.accuracy is the fit's: its rtol chosen, the record in the JSON.
  check(nanopush_scene_set_real(err, scene, "solver.accuracy", 1e-9) == NANOPUSH_OK, "set solver.accuracy");
  std::vector<char> json_acc(1 << 16);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force", nullptr, nullptr, 1, nullptr, nullptr, nullptr,
                                nullptr, json_acc.data(), static_cast<int>(json_acc.size()), &len2) == NANOPUSH_OK &&
            len2 < static_cast<int>(json_acc.size()),
        "fit with accuracy");
  const auto acc = nlohmann::json::parse(json_acc.data())["accuracy"];
  check(acc["requested"] == 1e-9 && acc["reached"] == true && acc["rtol_used"].is_number(), "fit: accuracy record");
  check(nanopush_scene_set_real(err, scene, "solver.accuracy", 0.0) == NANOPUSH_OK, "unset solver.accuracy");

  // Bad input: the status, the message, nothing written.
  double v = 42, s = 42;
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.nonsense", nullptr, nullptr, 1, &v, &s, nullptr,
                                nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT &&
            message(err).find("push.nonsense") != std::string::npos,
        "bad key: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force,surface.mu", nullptr, nullptr, 1, &v, &s,
                                nullptr, nullptr, nullptr, 0, nullptr) == NANOPUSH_BUFFER_TOO_SMALL,
        "nfree too small");
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, (dir / "absent.csv").c_str(), "push.force", nullptr, nullptr, 1, &v, &s,
                                nullptr, nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT,
        "absent data file: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force", nullptr, "x=1e-9", 1, &v, &s, nullptr,
                                nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT &&
            message(err).find("sigma") != std::string::npos,
        "sigma for a column that has one: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force,", nullptr, nullptr, 2, &v, &s, nullptr,
                                nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT,
        "empty key in the list");
  // What the library names by `nanopush fit`'s flags (--free, --law, --sigma, DATA) is named as
  // this function's arguments.
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force,push.force", nullptr, nullptr, 2, &v, &s,
                                nullptr, nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT &&
            message(err).rfind("free_keys = push.force: named twice", 0) == 0,
        "a key twice: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force", "printed", nullptr, 1, &v, &s, nullptr,
                                nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT &&
            message(err).rfind("law = printed: must be thesis or coulomb", 0) == 0,
        "the printed law: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, data.c_str(), "push.force", nullptr, "x=1e-9", 1, &v, &s, nullptr,
                                nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT &&
            message(err).rfind("sigma = x: the data already give sigma_x", 0) == 0,
        "sigma named: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, scene, (dir / "absent.csv").c_str(), "push.force", nullptr, nullptr, 1, &v, &s,
                                nullptr, nullptr, nullptr, 0, nullptr) == NANOPUSH_BAD_INPUT &&
            message(err).rfind("data_path = ", 0) == 0,
        "data_path named: " + message(err));
  nanopush_clear_error(err);
  check(nanopush_fit_trajectory(err, nullptr, data.c_str(), "push.force", nullptr, nullptr, 1, &v, &s, nullptr,
                                nullptr, nullptr, 0, nullptr) == NANOPUSH_NULL_HANDLE,
        "NULL scene");
  check(v == 42 && s == 42, "failed calls write nothing");

  nanopush_delete_scene(&scene);
  nanopush_delete_error(&err);
  return nanopush_capi_test::finish("capi fit: all checks hold");
}
