// The scene argument every scene-taking subcommand shares: SCENE (a file or a preset name)
// and any number of --set KEY=VALUE, applied together and validated as the file is.
#pragma once
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

#include <ostream>

#include "nanopush/scenes/scene.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush::cli {

/// Declare `--set KEY=VALUE` (repeatable) on `app`, collected into `sets`.
void add_set_option(CLI::App& app, std::vector<std::string>& sets);

/// Split "KEY=VALUE" texts into typed settings (the key's type from the scene key table).
std::vector<SceneSetting> parse_settings(const std::vector<std::string>& sets, const std::string& option = "--set");

/// Load SCENE (resolve_scene) and apply the --set values.
Scene load_scene_arg(const std::string& scene, const std::vector<std::string>& sets);

/// --accuracy E (the scene's solver.accuracy when not given) and --no-error-estimate.
void add_accuracy_options(CLI::App& app, double& accuracy, bool& no_estimate);
/// The error estimate (and what --accuracy did) as lines of a run summary.
void print_error_estimate(const Trajectory& tr, std::ostream& os);

/// After a failed rough run under the thesis or printed law that stopped at rest: where the
/// bar came to rest and that --law coulomb continues honestly (nothing for other failures).
void print_rest_diagnosis(const Scene& sc, Law law, const Trajectory& tr, std::ostream& os);

}  // namespace nanopush::cli
