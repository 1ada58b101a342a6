// Fitting a scene to observed motion (docs/fitting.md): weighted nonlinear least squares of
// the forward model's pose (x, y, theta) at the observed times, any numeric scene key free.
// The optimiser is Eigen's Levenberg-Marquardt; the Jacobian comes from forward
// sensitivities (SUNDIALS CVODES) where the right-hand side is smooth, and from central
// differences of whole forward solves under the coulomb law (its rest events).
#pragma once
#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "nanopush/scenes/scene.hpp"

namespace nanopush::fit {

/// How the fit's Jacobian is computed: `automatic` ("auto") takes sensitivities where the
/// right-hand side is smooth and differences of whole solves under the coulomb law, whose
/// right-hand side jumps at its rest events.
enum class Gradients { automatic, sensitivities, differences };

}  // namespace nanopush::fit

namespace nanopush {
NANOPUSH_NAMES(fit::Gradients, {fit::Gradients::automatic, "auto"}, {fit::Gradients::sensitivities, "sensitivities"},
               {fit::Gradients::differences, "differences"});
}  // namespace nanopush

namespace nanopush::fit {

/// The observed pose components, in column order.
inline constexpr std::array<const char*, 3> kPoseColumns = {"x", "y", "theta"};

/// Observations: times and any subset of x, y, theta with a standard deviation per value.
/// Missing components have empty value/sigma vectors (has[c] == false).
struct Observations {
  std::vector<double> t;                        ///< [s], strictly increasing
  std::array<bool, 3> has{false, false, false}; ///< which of x, y, theta were observed
  std::array<std::vector<double>, 3> value;     ///< [m], [m], [rad]; size t.size() when has[c]
  std::array<std::vector<double>, 3> sigma;     ///< standard deviations, > 0, same units
  std::string source = "<data>";                ///< file name, for messages
  /// Number of observed values (sum over observed columns of t.size()).
  [[nodiscard]] std::size_t count() const;
};

/// Per-column sigma given on the command line (--sigma x=2e-9): column -> sigma. It fills a
/// column without a sigma_<c> column, and overrides none (both present is an InputError).
using SigmaOverrides = std::map<std::string, double>;

/// Parse observations from CSV text: a header naming `t` and any of x, y, theta, sigma_x,
/// sigma_y, sigma_theta (other columns are refused). Throws InputError naming the source,
/// the row (1 = first data row; the file line too) and the column for: a non-number or NaN,
/// unsorted or duplicate times, a missing column (no pose column, no t, a value without
/// its sigma), sigma <= 0, a short row.
Observations parse_observations(std::string_view csv, const std::string& source = "<data>",
                                const SigmaOverrides& sigma = {});
/// Read a data file (regular file of at most 64 MiB) with parse_observations.
Observations read_observations(const std::filesystem::path& path, const SigmaOverrides& sigma = {});
/// The checks against a scene and a fit: times within [0, solver.t_end] (row and column
/// named), more observed values than free parameters. Throws InputError.
void check_observations(const Observations& obs, const Scene& scene, std::size_t n_free);

/// How the Jacobian is obtained: auto (sensitivities where the RHS is smooth: smooth scenes
/// and the thesis law; differences under the coulomb law) | sensitivities | differences.
struct FitOptions {
  std::vector<std::string> free;  ///< scene keys to fit (numeric keys; solver.* refused)
  /// Bounds per key overriding the key's validation range (scene_keys: "> 0", "[0, 10]"...).
  std::map<std::string, std::array<double, 2>> bounds;
  std::optional<Law> law;        ///< unset = the scene's surface.law (rough scenes): thesis | coulomb
  double rtol = 1e-10;           ///< forward solves (and sensitivities)
  /// > 0: the error asked for of the model's poses at the observation times, in
  /// [kAccuracyMin, kAccuracyMax] (docs/accuracy.md's norm): the forward solves' rtol is chosen
  /// to reach it at the start values (choose_forward_rtol) and rtol is ignored; checked again
  /// at the estimate (FitResult::accuracy). 0: run at rtol; < 0: the scene's solver.accuracy
  /// (so C and Fortran, whose fit has no such argument, set it on the scene).
  double accuracy = -1;
  Gradients gradients = Gradients::automatic;
  int max_evaluations = 100;     ///< Levenberg-Marquardt function evaluations
  double xtol = 1e-8, ftol = 1e-10;  ///< Levenberg-Marquardt: relative step and reduction of chi2
  /// Singular values of the scaled Jacobian below this fraction of the largest are
  /// undetermined directions (identifiability).
  double identifiability_threshold = 1e-6;
};

struct ParameterEstimate {
  std::string key, unit;
  double start = 0, value = 0;
  double stderr_ = 0;           ///< NaN when undetermined (identifiability) or not converged
  double lower = 0, upper = 0;  ///< bounds used
  bool at_bound = false;
};

/// A combination the data determine when the parameters are not all identifiable: locally
/// prod_i key_i^exponent_i (exponents from the scaled Jacobian's SVD, largest = 1), named
/// physically where recognised (e.g. "mu*N": surface.mu times the normal load).
struct Combination {
  std::string name;  ///< e.g. "mu*N" or "surface.mu^1 * surface.f_vdw^0.998"
  std::vector<std::pair<std::string, double>> exponents;
  double value = 0;            ///< the combination at the estimate (SI)
  double stderr_relative = 0;  ///< standard error of ln(value)
};

struct Identifiability {
  bool identifiable = true;
  std::vector<double> singular_values;  ///< of the Jacobian scaled to relative parameters
  double condition = 0;                 ///< largest / smallest singular value
  std::vector<std::string> undetermined;  ///< keys in an undetermined direction
  std::vector<Combination> determined;    ///< what the data do determine about those keys
  std::string message;                    ///< plain words, "" when identifiable
};

/// How the forward solves' rtol was chosen for an accuracy (FitOptions::accuracy).
struct FitAccuracy {
  double requested = 0;  ///< 0: not asked
  double rtol_used = 0;
  double estimate = 0;   ///< the model's error at the observation times at rtol_used
  bool reached = false;
};

/// The error of the model's poses at `times` solved at rtol (max over the times of the pose
/// norm of docs/accuracy.md) against a solve 100x tighter (not below 1e-14, where the estimate
/// claims no less than rtol).
double forward_error(const Scene& scene, const std::vector<double>& times, std::optional<Law> law, double rtol);
/// The loosest rtol (from the accuracy down by 100 to 1e-14) whose forward_error is within
/// `accuracy`, or the tightest tried with reached = false.
FitAccuracy choose_forward_rtol(const Scene& scene, const std::vector<double>& times, std::optional<Law> law,
                                double accuracy);

struct FitResult {
  std::vector<ParameterEstimate> parameters;
  std::vector<std::vector<double>> correlation;  ///< NaN entries for undetermined keys
  double chi2 = 0, chi2_dof = 0;
  long dof = 0;
  bool converged = false;
  std::string status;              ///< the optimiser's words ("converged: relative reduction ...")
  int iterations = 0;
  std::int64_t n_forward_solves = 0;      ///< every solve of the model (with or without sensitivities)
  std::int64_t n_sensitivity_solves = 0;  ///< of those, solves with sensitivities
  double wall_seconds = 0;
  Gradients gradients = Gradients::sensitivities;  ///< those used: sensitivities | differences
  std::string law;                 ///< the law used (rough scenes), "" on smooth
  FitAccuracy accuracy;            ///< with FitOptions::accuracy: rtol chosen, estimate at the estimate
  Identifiability identifiability;
  std::vector<double> t;                          ///< observation times
  std::vector<std::array<double, 3>> fitted;      ///< model pose at t with the estimates
  std::vector<std::array<double, 3>> residuals;   ///< (obs - model)/sigma, NaN where unobserved
  Scene scene;                                    ///< the scene with the estimates set
};

/// Fit. Throws InputError for bad options or data (check_observations is called), never
/// for non-convergence: converged = false, status and the last state in parameters.
FitResult fit_trajectory(const Scene& scene, const Observations& obs, const FitOptions& options);

/// The model's pose at `times` for the scene with free keys = p, and (optionally) its
/// derivatives d pose / d p_k: jac[i][k] = {dx, dy, dtheta}. `gradients` as FitOptions. Counts solves in *solves if given.
struct ModelPoses {
  std::vector<std::array<double, 3>> pose;
  std::vector<std::vector<std::array<double, 3>>> jac;  ///< empty without derivatives
};
ModelPoses model_poses(const Scene& scene, const std::vector<std::string>& free, const std::vector<double>& p,
                       const std::vector<double>& times, std::optional<Law> law, double rtol, bool derivatives,
                       Gradients gradients = Gradients::automatic, std::int64_t* solves = nullptr);

/// Synthetic data: the scene's forward model at `times` (default: its output times) with
/// seeded Gaussian noise of the given sigma per column (x, y, theta; a column with sigma 0 is
/// not observed; a negative or NaN sigma, or all three 0, is InputError).
Observations synthesize(const Scene& scene, const std::array<double, 3>& sigma, std::uint64_t seed,
                        std::optional<Law> law = std::nullopt, const std::vector<double>& times = {},
                        double rtol = 1e-10);
/// Observations as CSV text (t, x, sigma_x, ...), readable by parse_observations.
std::string observations_csv(const Observations& obs);

/// The JSON summary: {"parameters": {"KEY": {"value", "stderr", "start", "lower", "upper",
/// "at_bound"}}, "correlation", "chi2", "chi2_dof", "dof", "converged", "status",
/// "identifiability": {...}, "n_forward_solves", ...}.
std::string fit_json(const FitResult& r);

}  // namespace nanopush::fit
