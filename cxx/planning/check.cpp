// plan --check as a sweep (planning/check.hpp; docs/planning.md): trials are the points of a
// grid over one axis `trial`, each world drawn from the trial's own random stream.
#include "nanopush/planning/check.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/scenes/simulate.hpp"
#include "pushes.hpp"

namespace nanopush::plan {

namespace {

constexpr int kMaxTrials = 1000000;

std::string text(double v) {
  std::ostringstream s;
  s.precision(17);
  s << v;
  return s.str();
}

/// Trial k's generator: seeded from (seed, k) through std::seed_seq, whose mixing the standard
/// specifies, so a trial's world is the same on every platform, thread and rank.
std::mt19937_64 trial_stream(std::uint64_t seed, std::uint64_t trial) {
  std::seed_seq s{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                  static_cast<std::uint32_t>(trial), static_cast<std::uint32_t>(trial >> 32)};
  return std::mt19937_64(s);
}

class CheckTask final : public sweep::Task {
 public:
  CheckTask(const Scene& scene, const PlanResult& plan, const PlanOptions& o, const CheckWorlds& w)
      : scene_(scene), plan_(plan), o_(o), w_(w) {
    check_worlds(scene, w);
    vary_mu_ = !(w.mu_lo == 0 && w.mu_hi == 0);
    vary_tip_mu_ = w.tip_mu_lo >= 0;
  }
  [[nodiscard]] std::string name() const override { return "plan-check"; }
  [[nodiscard]] std::string scene_name() const override { return scene_.name; }
  [[nodiscard]] Column input_column(const std::string& key) const override {
    if (key != "trial") throw InputError(key, "(varied)", "plan --check varies only `trial`");
    return count_column("trial", "trial number (its world is drawn from the stream (seed, trial))");
  }
  [[nodiscard]] std::vector<std::string> evaluate(const std::vector<SceneSetting>& point,
                                                  std::size_t index) const override {
    return evaluate_point(point, index).cells;
  }
  [[nodiscard]] PointResult evaluate_point(const std::vector<SceneSetting>& point, std::size_t) const override {
    const auto trial = static_cast<std::uint64_t>(point.at(0).second.number());
    std::mt19937_64 rng = trial_stream(w_.seed, trial);
    const Pose start{plan_.start.x + w_.noise.x * detail::standard_normal(rng),
                     plan_.start.y + w_.noise.y * detail::standard_normal(rng),
                     plan_.start.theta + w_.noise.theta * detail::standard_normal(rng)};
    Scene world = scene_;
    if (vary_mu_) world.set("surface.mu", w_.mu_lo + (w_.mu_hi - w_.mu_lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53);
    if (vary_tip_mu_)
      world.set("tip.mu", w_.tip_mu_lo + (w_.tip_mu_hi - w_.tip_mu_lo) * static_cast<double>(rng() >> 11) * 0x1.0p-53);
    const double tip_mu = world.push_mode == PushMode::tip ? world.tip.mu : 0.0;
    PointResult r;
    Pose at = start;
    std::size_t made = 0;
    for (const PlannedPush& p : plan_.pushes) {
      try {
        const Trajectory tr = run_scene(push_scene(world, at, p));
        const auto& row = tr.rows.back();
        at = {row[col::x], row[col::y], row[col::theta]};
        ++made;
      } catch (const InputError& e) {  // the tip would touch down on the bar
        r.message = "push " + std::to_string(made + 1) + " not made: " + e.what();
        break;
      } catch (const SolverError& e) {  // the model cannot follow the push in this world
        r.message = "push " + std::to_string(made + 1) + " not made: " + e.what();
        break;
      }
    }
    const double d = std::hypot(at.x - plan_.goal.x, at.y - plan_.goal.y);
    const double a = std::fabs(angle_error(at.theta, plan_.goal.theta, o_.half_turn_symmetric));
    const bool ok = made == plan_.pushes.size() && d <= o_.tolerance_distance && a <= o_.tolerance_angle;
    r.cells = {csv_number(start.x), csv_number(start.y), csv_number(start.theta), csv_number(world.surface.mu),
               csv_number(tip_mu), std::to_string(made), csv_number(at.x), csv_number(at.y), csv_number(at.theta),
               csv_number(d), csv_number(a), ok ? "1" : "0"};
    return r;
  }
  [[nodiscard]] std::string identity() const override {
    std::string s = "plan-check\n" + scene_.to_toml() + "\ngoal=" + text(plan_.goal.x) + "," + text(plan_.goal.y) + "," +
                    text(plan_.goal.theta) + " tolerance=" + text(o_.tolerance_distance) + "," +
                    text(o_.tolerance_angle) + " half_turn=" + (o_.half_turn_symmetric ? "1" : "0") + "\n" + worlds();
    for (const auto& p : plan_.pushes)
      s += "\npush " + text(p.start_x) + " " + text(p.start_y) + " " + text(p.direction) + " " + text(p.speed) + " " +
           text(p.travel);
    return s;
  }
  [[nodiscard]] std::vector<std::pair<std::string, std::string>> describe() const override {
    return {{"task", "plan-check"}, {"scene", scene_.name}, {"pushes", std::to_string(plan_.pushes.size())},
            {"worlds", worlds()}};
  }

 private:
  [[nodiscard]] std::string worlds() const {
    return "noise=" + text(w_.noise.x) + "," + text(w_.noise.y) + "," + text(w_.noise.theta) +
           " mu=" + (vary_mu_ ? text(w_.mu_lo) + ":" + text(w_.mu_hi) : std::string("scene")) +
           (vary_tip_mu_ ? " tip_mu=" + text(w_.tip_mu_lo) + ":" + text(w_.tip_mu_hi) : std::string()) +
           " seed=" + std::to_string(w_.seed);
  }
  Scene scene_;
  PlanResult plan_;
  PlanOptions o_;
  CheckWorlds w_;
  bool vary_mu_ = false, vary_tip_mu_ = false;
};

}  // namespace

void check_worlds(const Scene& scene, const CheckWorlds& w) {
  for (double s : {w.noise.x, w.noise.y, w.noise.theta})
    if (!(s >= 0 && std::isfinite(s))) throw InputError("--noise", fmt(s), "standard deviations must be >= 0");
  const bool vary_mu = !(w.mu_lo == 0 && w.mu_hi == 0);
  if (vary_mu && !(w.mu_lo > 0 && w.mu_hi >= w.mu_lo && w.mu_hi <= 10))
    throw InputError("--mu-range", fmt(w.mu_lo) + ":" + fmt(w.mu_hi), "must be LO:HI with 0 < LO <= HI <= 10");
  check_tip_mu_range(w.tip_mu_lo, w.tip_mu_hi);  // a negative end is refused, not "not varied"
  const bool vary_tip_mu = w.tip_mu_lo >= 0;
  if (vary_tip_mu && scene.push_mode != PushMode::tip)
    throw InputError("--tip-mu-range", scene.name, "varies the tip's friction: the scene must be a tip scene (push.mode = \"tip\")");
}

sweep::Plan check_points(int trials) {
  if (trials < 1 || trials > kMaxTrials)
    throw InputError("--check", std::to_string(trials), "must be in [1, " + std::to_string(kMaxTrials) + "] trials");
  sweep::Axis a{"trial", {}, "trial=1:" + std::to_string(trials) + ":" + std::to_string(trials)};
  a.values.reserve(static_cast<std::size_t>(trials));
  for (int k = 1; k <= trials; ++k) a.values.emplace_back(k);
  return sweep::cartesian({a});
}

std::unique_ptr<sweep::Task> make_check_task(const Scene& scene, const PlanResult& plan, const PlanOptions& options,
                                             const CheckWorlds& worlds) {
  return std::make_unique<CheckTask>(scene, plan, options, worlds);
}

void wilson_interval(PlanCheck& c) {
  const double n = c.trials, p = n > 0 ? c.successes / n : 0, z = 1.959963984540054;
  c.probability = p;
  if (n <= 0) return;
  const double centre = (p + z * z / (2 * n)) / (1 + z * z / n);
  const double half = z * std::sqrt(p * (1 - p) / n + z * z / (4 * n * n)) / (1 + z * z / n);
  c.low = std::max(0.0, centre - half);
  c.high = std::min(1.0, centre + half);
}

PlanCheck read_check_table(const std::filesystem::path& table) {
  std::ifstream in(table, std::ios::binary);
  if (!in) throw InputError(table.string(), "(unreadable)", "the check's table could not be read");
  csv::Reader reader(in, table.string());
  csv::Record rec;
  if (!reader.next(rec)) throw InputError(table.string(), "(empty)", "a check table has a header");
  auto column = [&](const std::string& name) {
    const auto it = std::find(rec.fields.begin(), rec.fields.end(), name);
    if (it == rec.fields.end()) throw InputError(table.string(), "(header)", "a check table has a column " + name);
    return static_cast<std::size_t>(it - rec.fields.begin());
  };
  const std::size_t cs = column("success"), cd = column("final_distance"), ca = column("final_angle");
  const std::size_t width = rec.fields.size();
  PlanCheck c;
  while (reader.next(rec)) {
    if (rec.fields.size() != width)
      throw InputError(table.string() + ":" + std::to_string(rec.line), csv::join(rec.fields), "a row of the header's width");
    ++c.trials;
    if (rec.fields[cs] == "1") ++c.successes;
    c.final_distance.push_back(sweep::cell_number(rec.fields[cd]));
    c.final_angle.push_back(sweep::cell_number(rec.fields[ca]));
  }
  wilson_interval(c);
  return c;
}

PlanCheck check_plan(const Scene& scene, const PlanResult& plan, const PlanOptions& o, const Noise& noise, int trials,
                     double mu_lo, double mu_hi, std::uint64_t seed, unsigned jobs) {
  return check_plan(scene, plan, o, CheckWorlds{noise, mu_lo, mu_hi, seed}, trials, jobs);
}

PlanCheck check_plan(const Scene& scene, const PlanResult& plan, const PlanOptions& o, const CheckWorlds& w, int trials,
                     unsigned jobs) {
  const sweep::Plan points = check_points(trials);
  const auto task = make_check_task(scene, plan, o, w);
  const std::size_t cs = sweep::column_index(points, *task, "success"),
                    cd = sweep::column_index(points, *task, "final_distance"),
                    ca = sweep::column_index(points, *task, "final_angle");
  PlanCheck c;
  for (const auto& row : sweep::evaluate_points(points, *task, jobs)) {
    if (sweep::row_failed(row))  // not the plan failing in a world: the engine's own failure
      throw SolverError("plan --check: trial " + row.at(1) + ": " + row.back());
    ++c.trials;
    if (row[cs] == "1") ++c.successes;
    c.final_distance.push_back(sweep::cell_number(row[cd]));
    c.final_angle.push_back(sweep::cell_number(row[ca]));
  }
  wilson_interval(c);
  return c;
}

}  // namespace nanopush::plan
