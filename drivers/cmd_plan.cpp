// nanopush plan: tip pushes that bring a bar to a goal pose (docs/planning.md).
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <tuple>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/io.hpp"
#include "nanopush/outputs/json.hpp"
#include "nanopush/outputs/plot.hpp"
#include "nanopush/planning/check.hpp"
#include "nanopush/planning/plan.hpp"
#include "cli_checks.hpp"
#include "columns.hpp"
#include "registry.hpp"
#include "scene_args.hpp"
#include "sweep_mpi.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct PlanCliOptions {
  std::string scene, goal, tolerance = "1e-9,0.01", objective = "pushes", out, format = "png";
  std::vector<std::string> sets;
  int max_pushes = 10;
  bool distinguish_ends = false;
  bool closed_loop = false;
  bool no_refit = false;
  std::string truth, noise = "x=0,theta=0";
  std::uint64_t seed = 1;
  int check = 0;
  std::string mu_range, tip_mu_range;
  bool robust = false;
  unsigned jobs = 0;
  bool quiet = false;
};

Columns plan_columns() {
  return columns("plan");
}

void write_outputs(const Scene& sc, const plan::PlanResult& r, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  {
    CsvWriter w(dir / "plan.csv", plan_columns(), sc.name);
    w.run_info({{"status", to_string(r.status)},
                {"verified", r.verified},
                {"goal_x_m", r.goal.x},
                {"goal_y_m", r.goal.y},
                {"goal_theta_rad", r.goal.theta},
                {"final_distance_m", r.final_distance},
                {"final_angle_rad", r.final_angle},
                {"forward_runs", r.forward_runs},
                {"planning_seconds", r.planning_seconds}});
    int i = 1;
    for (const auto& p : r.pushes)
      w.row({double(i++), p.start_x, p.start_y, p.direction, p.speed, p.travel, p.end.x, p.end.y, p.end.theta});
    w.commit();
  }
  {  // The tip's waypoints an AFM script follows: lower at start, move to end, lift.
    CsvWriter w(dir / "tip_path.csv",
                columns("plan_tip_path"),
                sc.name);
    int i = 1;
    for (const auto& p : r.pushes) {
      w.row({double(i), p.start_x, p.start_y, 1.0});
      w.row({double(i), p.start_x + p.travel * std::cos(p.direction), p.start_y + p.travel * std::sin(p.direction), 0.0});
      w.blank_line();  // the tip lifts between pushes (gnuplot draws each push apart)
      ++i;
    }
    w.commit();
  }
  {  // Outlines of the bar at the start, after each push, and the goal (gnuplot blocks).
    CsvWriter w(dir / "poses.csv",
                columns("plan_poses"),
                sc.name);
    auto outline = [&](int k, const plan::Pose& p) {
      const double a = sc.geometry.a, b = sc.geometry.b, c = std::cos(p.theta), s = std::sin(p.theta);
      const double cx[] = {-a, a, a, -a, -a}, cy[] = {-b, -b, b, b, -b};
      for (int j = 0; j < 5; ++j) w.row({double(k), p.x + c * cx[j] - s * cy[j], p.y + s * cx[j] + c * cy[j]});
      w.blank_line();
    };
    outline(0, r.start);
    int k = 1;
    for (const auto& p : r.pushes) outline(k++, p.end);
    outline(-1, r.goal);
    w.commit();
  }
  const auto pose = [](const plan::Pose& p) { return json::array({json_number(p.x), json_number(p.y), json_number(p.theta)}); };
  json pushes = json::array();
  for (const auto& p : r.pushes)
    pushes.push_back({{"start", json::array({json_number(p.start_x), json_number(p.start_y)})},
                      {"direction", json_number(p.direction)},
                      {"speed", json_number(p.speed)},
                      {"travel", json_number(p.travel)},
                      {"end", pose(p.end)},
                      {"face", p.face},
                      {"offset", json_number(p.offset)},
                      {"max_force_N", json_number(p.max_force)},
                      {"verified_deviation", json_number(p.verified_deviation)}});
  json worlds = json::array();  // robust planning: each world's start and where the plan leaves it
  for (const auto& w : r.worlds)
    worlds.push_back({{"tip_mu", json_number(w.tip_mu)}, {"start", pose(w.start)}, {"final", pose(w.final_pose)},
                      {"error", json::array({json_number(w.final_distance), json_number(w.final_angle)})},
                      {"reached", w.reached}});
  json doc = {{"scene", sc.name},
                    {"status", to_string(r.status)},
                    {"verified", r.verified},
                    {"message", r.message},
                    {"start", pose(r.start)},
                    {"goal", pose(r.goal)},
                    {"final", pose(r.final_pose)},
                    {"final_distance_m", json_number(r.final_distance)},
                    {"final_angle_rad", json_number(r.final_angle)},
                    {"tip_travel_m", json_number(r.tip_travel)},
                    {"time_s", json_number(r.time)},
                    {"forward_runs", r.forward_runs},
                    {"planning_seconds", json_number(r.planning_seconds)},
                    {"pushes", std::move(pushes)}};
  if (!r.worlds.empty()) doc["robust_worlds"] = std::move(worlds);
  write_file_atomic(dir / "plan.json", json_text(doc));
  const std::string body =
      "set size ratio -1\nset xlabel 'x (nm)'\nset ylabel 'y (nm)'\nset key outside right noenhanced\n"
      "set datafile separator ','\n"
      "plot '" + (dir / "poses.csv").string() +
      "' skip 1 using ($2*1e9):($3*1e9):1 with lines lc variable lw 2 title 'bar: start, after each push, goal (-1)', \\\n"
      "     '" + (dir / "tip_path.csv").string() +
      "' skip 1 using ($2*1e9):($3*1e9) with linespoints lc rgb 'black' dt 2 pt 7 ps 0.6 title 'tip paths'\n";
  plot::render_script(body, dir / "plan.png");
}

/// --truth: a scene (file or preset) or KEY=VALUE,... applied to the model scene.
Scene truth_scene(const Scene& model, const std::string& text) {
  if (text.empty()) return model;
  if (text.find('=') == std::string::npos) return load_scene_arg(text, {});
  std::vector<std::string> sets;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) sets.push_back(part);
  Scene t = model;
  t.set(parse_settings(sets, "--truth"));
  return t;
}

/// --noise x=SX,y=SY,theta=ST (y defaults to x).
plan::Noise parse_noise(const std::string& text) {
  plan::Noise n;
  bool y_given = false;
  std::stringstream ss(text);
  std::string part;
  while (std::getline(ss, part, ',')) {
    const auto eq = part.find('=');
    const std::string key = part.substr(0, eq);
    const double v = eq == std::string::npos ? -1 : number_list("--noise", part.substr(eq + 1), 1, "x=SX,y=SY,theta=ST (m, m, rad), each >= 0")[0];
    if (!(v >= 0)) throw InputError("--noise", text, "must be x=SX,y=SY,theta=ST (m, m, rad), each >= 0");
    if (key == "x") n.x = v;
    else if (key == "y") {
      n.y = v;
      y_given = true;
    }
    else if (key == "theta") n.theta = v;
    else throw InputError("--noise", text, "unknown component '" + key + "': x, y or theta");
  }
  if (!y_given) n.y = n.x;
  return n;
}

int closed_loop_cmd(const PlanCliOptions& o, const Scene& sc, const plan::Pose& goal, const plan::PlanOptions& po) {
  const Scene truth = truth_scene(sc, o.truth);
  const plan::Noise noise = parse_noise(o.noise);
  plan::Refit refit;
  refit.enabled = !o.no_refit;
  const plan::ClosedLoopResult r = plan::closed_loop(sc, truth, goal, po, noise, o.seed, refit);
  const std::filesystem::path dir = o.out.empty() ? sc.name + ".plan" : o.out;
  std::filesystem::create_directories(dir);
  CsvWriter w(dir / "closed_loop.csv",
              columns("plan_closed_loop"),
              sc.name);
  w.run_info({{"status", to_string(r.status)}, {"final_distance_m", r.final_distance},
              {"final_angle_rad", r.final_angle}, {"seed", o.seed}, {"pushes_not_made", r.unsimulated},
              {"tip_mu_final", r.tip_mu < 0 ? std::nan("") : r.tip_mu}, {"refit", !o.no_refit}});
  int k = 1;
  for (const auto& s : r.steps)
    w.row({double(k++), s.observed.x, s.observed.y, s.observed.theta, s.truth.x, s.truth.y, s.truth.theta, s.push.start_x,
           s.push.start_y, s.push.direction, s.push.travel, double(s.plan_pushes), s.tip_mu < 0 ? std::nan("") : s.tip_mu});
  w.commit();
  if (!o.quiet) {
    std::cerr << std::setprecision(6) << sc.name << " closed loop: " << to_string(r.status) << ", " << r.steps.size()
              << " push(es), tip travel " << r.tip_travel << " m, time " << r.time << " s, planning " << r.planning_seconds
              << " s\n  true final pose " << r.final_truth.x << " m, " << r.final_truth.y << " m, " << r.final_truth.theta
              << " rad: " << r.final_distance << " m and " << r.final_angle << " rad from the goal\n"
              << (r.tip_mu >= 0 ? "  model's tip friction: " + std::to_string(r.tip_mu) +
                                      (o.no_refit ? " (kept)\n" : " (re-fitted to the images)\n")
                                : std::string())
              << "  steps: "
              << (dir / "closed_loop.csv").string() << "\n";
    if (r.unsimulated)
      std::cerr << "  " << r.unsimulated << " planned push(es) not made: the tip would start inside the true bar, or the "
                << "model could not follow the push there; the bar was imaged again\n";
    if (!r.reached()) std::cerr << "nanopush: not_reached: " << r.message << "\n";
  }
  return r.reached() ? 0 : 3;
}

/// The plan's summary on standard error: status, pushes, and each robust world's end.
void print_plan_summary(const Scene& sc, const plan::PlanResult& r) {
  std::cerr << std::setprecision(6) << sc.name << ": " << to_string(r.status) << (r.verified ? " (verified)" : "") << ", "
            << r.pushes.size() << " push(es), tip travel " << r.tip_travel << " m, time " << r.time << " s\n"
            << "  final pose " << r.final_pose.x << " m, " << r.final_pose.y << " m, " << r.final_pose.theta
            << " rad: " << r.final_distance << " m and " << r.final_angle << " rad from the goal\n"
            << "  planning " << r.planning_seconds << " s, " << r.forward_runs << " model runs\n";
  int i = 1;
  for (const auto& p : r.pushes)
    std::cerr << "  push " << i++ << ": face " << p.face << " at " << p.offset << ", tip from (" << p.start_x << ", "
              << p.start_y << ") m, direction " << p.direction << " rad, travel " << p.travel << " m\n";
  for (const auto& w : r.worlds)
    std::cerr << "  world tip.mu " << w.tip_mu << ", start (" << w.start.x << ", " << w.start.y << ", " << w.start.theta
              << "): ends " << w.final_distance << " m and " << w.final_angle << " rad from the goal"
              << (w.reached ? "" : " (NOT within tolerance)") << "\n";
}

/// LO:HI of `flag` (empty: not given, {-1, -1}).
std::pair<double, double> parse_range(const char* flag, const std::string& text) {
  if (text.empty()) return {-1, -1};
  const auto colon = text.find(':');
  if (colon == std::string::npos || text.find(':', colon + 1) != std::string::npos)
    throw InputError(flag, text, "must be LO:HI");
  double lo = 0, hi = 0;
  try {
    lo = number_list(flag, text.substr(0, colon), 1, "LO:HI, two numbers")[0];
    hi = number_list(flag, text.substr(colon + 1), 1, "LO:HI, two numbers")[0];
  } catch (const InputError&) {  // named as written, not by the half that failed
    throw InputError(flag, text, "must be LO:HI, two numbers");
  }
  return {lo, hi};  // their values are checked by the planner (check_worlds, check_plan_task)
}

/// --check N: the plan made open loop in N worlds, as a sweep of trials (planning/check.hpp) on
/// --jobs threads, or across the ranks when mpirun started nanopush-mpi: DIR/check.csv (a sweep
/// table with its sidecar; interrupted, it resumes from its journal) and DIR/check.json (the
/// success probability and its 95 % Wilson interval). Returns 0, or the sweep's exit status.
int check_cmd(const PlanCliOptions& o, const Scene& sc, const plan::PlanResult& r, const plan::PlanOptions& po,
              const plan::CheckWorlds& w, const std::filesystem::path& dir) {
  const sweep::Plan trials = plan::check_points(o.check);
  const auto task = plan::make_check_task(sc, r, po, w);
  sweep::Options opt;
  opt.jobs = o.jobs;
  opt.out = dir / "check.csv";
  opt.progress = progress_line(o.quiet || !table_rank(), "check");
  opt.stop = install_sweep_stop();
  opt.fixed = {"--noise " + o.noise, "--mu-range " + o.mu_range, "--tip-mu-range " + o.tip_mu_range,
               "--seed " + std::to_string(o.seed)};
  if (mpi_launched()) {
    const int rc = run_mpi_sweep(trials, *task, opt, o.quiet, sweep_signal());
    if (rc != 0 || !table_rank()) return rc;
  } else {
    const auto res = sweep::run_local(trials, *task, opt);
    if (!res.complete) {
      std::cerr << "plan: check interrupted: " << res.done << " of " << res.points << " trials are in "
                << sweep::journal_path(opt.out).string() << "; run the same command again to resume\n";
      return 128 + (*sweep_signal() ? static_cast<int>(*sweep_signal()) : SIGINT);
    }
  }
  const plan::PlanCheck c = plan::read_check_table(opt.out);
  json j;
  j["trials"] = c.trials;
  j["successes"] = c.successes;
  j["probability"] = json_number(c.probability);
  j["wilson95_low"] = json_number(c.low);
  j["wilson95_high"] = json_number(c.high);
  j["noise"] = o.noise;
  j["mu_range"] = o.mu_range;
  j["tip_mu_range"] = o.tip_mu_range;
  j["seed"] = o.seed;
  j["table"] = "check.csv";
  write_file_atomic(dir / "check.json", json_text(j));
  if (!o.quiet)
    std::cerr << "  check: success " << c.successes << "/" << c.trials << " = " << c.probability << " (95 % interval "
              << c.low << " to " << c.high << ") over start noise " << o.noise
              << (o.mu_range.empty() ? std::string() : " and mu in " + o.mu_range)
              << (o.tip_mu_range.empty() ? std::string() : " and tip mu in " + o.tip_mu_range) << ": " << opt.out.string()
              << "\n";
  return 0;
}

/// --check's worlds from --noise, --seed, --mu-range and --tip-mu-range, checked against the
/// scene (before planning: a bad range costs no plan and leaves no output).
plan::CheckWorlds check_worlds(const PlanCliOptions& o, const Scene& sc) {
  plan::CheckWorlds w;
  w.noise = parse_noise(o.noise);
  w.seed = o.seed;
  if (!o.mu_range.empty()) std::tie(w.mu_lo, w.mu_hi) = parse_range("--mu-range", o.mu_range);
  std::tie(w.tip_mu_lo, w.tip_mu_hi) = parse_range("--tip-mu-range", o.tip_mu_range);
  plan::check_worlds(sc, w);
  return w;
}

/// Every file plan writes into `dir` (--check's too; the closed loop's table alone), checked
/// where it goes before planning (docs/errors.md, "Outputs").
void check_plan_outputs(const PlanCliOptions& o, const std::filesystem::path& dir) {
  check_output_directory(dir);
  std::vector<std::filesystem::path> files;
  const auto csv = [&](const char* name) {
    for (auto& f : csv_with_sidecar(dir / name)) files.push_back(std::move(f));
  };
  if (o.closed_loop) {
    csv("closed_loop.csv");
  } else {
    for (const char* name : {"plan.csv", "tip_path.csv", "poses.csv"}) csv(name);
    files.push_back(dir / "plan.json");
    const auto figure = plot::figure_path(dir / "plan.png");
    files.push_back(figure);
    files.push_back(std::filesystem::path(figure).replace_extension(".gp"));
    if (o.check > 0) {
      csv("check.csv");
      files.push_back(dir / "check.json");
    }
  }
  check_outputs(files);
}

int plan_cmd(const PlanCliOptions& o) {
  const Scene sc = load_scene_arg(o.scene, o.sets);
  set_provenance_scene(o.scene);
  plot::set_format(plot::parse_format(o.format));
  const auto g = number_list("--goal", o.goal, 3, "three numbers X,Y,THETA (m, m, rad)");
  const auto tol = number_list("--tolerance", o.tolerance, 2, "two numbers D,A (m, rad)");
  plan::PlanOptions po;
  po.tolerance_distance = tol[0];
  po.tolerance_angle = tol[1];
  po.objective = plan::parse_objective(o.objective);
  po.max_pushes = o.max_pushes;
  po.half_turn_symmetric = !o.distinguish_ends;
  // --robust: plan for the ends of --tip-mu-range and the start shifted by 2 sigma of --noise
  // in each component as well as for the model (docs/planning.md, "Robust plans").
  if (o.robust) {
    if (o.closed_loop) throw InputError("--robust", "with --closed-loop", "the closed loop re-plans from each image: drop --robust");
    std::tie(po.robust_tip_mu_lo, po.robust_tip_mu_hi) = parse_range("--tip-mu-range", o.tip_mu_range);
    const plan::Noise n = parse_noise(o.noise);
    po.robust_start_x = 2 * n.x;
    po.robust_start_y = 2 * n.y;
    po.robust_start_theta = 2 * n.theta;
    if (o.tip_mu_range.empty() && !po.robust())  // neither written (a range's values: check_plan_task)
      throw InputError("--robust", "--noise " + o.noise, "plans for the worlds of --noise or --tip-mu-range: give either");
  }
  // Every option checked before planning: the options of --check (none is ignored), its worlds,
  // the task (goal, tolerance) and where each output goes.
  if (o.check > 0 && o.closed_loop)
    throw InputError("--check", std::to_string(o.check), "the closed loop re-plans from each image: drop --check");
  if (!o.mu_range.empty() && o.check == 0)
    throw InputError("--mu-range", o.mu_range, "is for --check N (the surface mu of its worlds): add --check N");
  if (!o.tip_mu_range.empty() && o.check == 0 && !o.robust)
    throw InputError("--tip-mu-range", o.tip_mu_range,
                     "is for --check N or --robust (the tip mu of their worlds): add either");
  const plan::CheckWorlds worlds = o.check > 0 ? check_worlds(o, sc) : plan::CheckWorlds{};
  const plan::Pose goal{g[0], g[1], g[2]};
  plan::check_plan_task(sc, goal, po);
  const std::filesystem::path dir = o.out.empty() ? sc.name + ".plan" : o.out;
  if (!o.closed_loop && !o.truth.empty()) throw InputError("--truth", o.truth, "is the closed loop's: add --closed-loop");
  check_plan_outputs(o, dir);
  if (o.closed_loop) return closed_loop_cmd(o, sc, goal, po);
  const plan::PlanResult r = plan::plan_pushes(sc, goal, po);
  // Under mpirun every rank plans (the search is deterministic) for --check's sweep; rank 0
  // writes and speaks.
  const bool speaker = table_rank();
  if (speaker) write_outputs(sc, r, dir);
  if (!o.quiet && speaker) {
    print_plan_summary(sc, r);
    std::cerr << "  plan: " << (dir / "plan.csv").string() << " (and plan.json, tip_path.csv, "
              << plot::figure_path(dir / "plan.png").filename().string() << ")\n";
    if (!r.found()) std::cerr << "nanopush: not_found: " << r.message << "\n";
  }
  if (o.check > 0 && r.found()) {
    const int rc = check_cmd(o, sc, r, po, worlds, dir);
    if (rc != 0) return rc;
  }
  return r.found() ? 0 : 3;
}

/// reproduce: one planning task on the example nanorod, its plan verified and drawn.
void reproduce_plan(ReproduceContext& ctx) {
  const Scene sc = load_scene(resolve_scene("tip_push_nanorod"));
  plan::PlanOptions po;
  po.tolerance_distance = 2e-9;
  po.tolerance_angle = 0.02;
  const plan::Pose goal{60e-9, 40e-9, 0.3};
  const plan::PlanResult r = plan::plan_pushes(sc, goal, po);
  const auto dir = ctx.out / "plan";
  write_outputs(sc, r, dir);
  for (const char* f : {"plan.csv", "plan.json", "tip_path.csv"}) ctx.produced(dir / f);
  ctx.produced(plot::figure_path(dir / "plan.png"));
  std::ostringstream t;
  t << std::setprecision(4);
  t << "## Planning a push sequence (beyond the thesis)\n\n"
    << "The thesis' nanorod (590 nm x 27 nm) at the origin, an AFM tip (radius 10 nm, 1 um/s); goal: centre at "
       "(60, 40) nm, theta = 0.3 rad, within 2 nm and 0.02 rad (`nanopush plan tip_push_nanorod --goal "
       "60e-9,40e-9,0.3 --tolerance 2e-9,0.02`; docs/planning.md).\n\n"
    << "Status: **" << to_string(r.status) << "**" << (r.verified ? ", verified by forward runs" : ", NOT verified") << "; "
    << r.pushes.size() << " pushes, tip travel " << r.tip_travel * 1e9 << " nm, final error " << r.final_distance * 1e9
    << " nm and " << r.final_angle << " rad; " << r.forward_runs << " model runs.\n\n"
    << "| push | face | offset | tip start (nm) | direction (rad) | travel (nm) | pose after (nm, nm, rad) |\n|---|---|---|---|---|---|---|\n";
  int i = 1;
  for (const auto& p : r.pushes)
    t << "| " << i++ << " | " << p.face << " | " << p.offset << " | (" << p.start_x * 1e9 << ", " << p.start_y * 1e9 << ") | "
      << p.direction << " | " << p.travel * 1e9 << " | (" << p.end.x * 1e9 << ", " << p.end.y * 1e9 << ", " << p.end.theta
      << ") |\n";
  t << "\n![plan](plan/" << plot::figure_path(dir / "plan.png").filename().string() << ")\n\n";
  ctx.report << t.str();
  if (!r.found() || !r.verified) ctx.failures.push_back("plan: the demonstration task was not planned and verified: " + r.message);
}

RegisterReproduce reg_plan_step{{"plan", "a push sequence to a goal pose, planned and verified (beyond the thesis)", 90,
                                 reproduce_plan, 0.0}};

RegisterCommand reg_plan{
    {"plan", "Plan tip pushes that bring the bar to a goal pose, verified by forward runs (docs/planning.md)", 75,
     [](CLI::App& app) -> std::function<int()> {
       auto o = std::make_shared<PlanCliOptions>();
       app.add_option("SCENE", o->scene, "scene file or preset (a rough surface; its tip.* keys give the tip)")->required();
       add_set_option(app, o->sets);
       app.add_option("--goal", o->goal, "goal pose X,Y,THETA of the bar's centre (m, m, rad)")->required();
       app.add_option("--tolerance", o->tolerance, "D,A: distance (m) and angle (rad) within which the goal is reached")
           ->capture_default_str();
       app.add_option("--objective", o->objective, "pushes (fewest), travel or time (least tip travel), force (least force)")
           ->capture_default_str();
       app.add_option("--max-pushes", o->max_pushes, "largest number of pushes")->check(count(1, 1000))->capture_default_str();
       app.add_flag("--distinguish-ends", o->distinguish_ends,
                    "theta and theta + pi are different goals (default: the bar is symmetric under a half turn)");
       app.add_option("--check", o->check,
                      "after planning: the plan's success probability over N worlds (start pose noise from --noise, "
                      "mu uniform in --mu-range), made open loop, as a sweep of trials; check.csv, check.json")
           ->check(count(0, 1000000));
       app.add_option("--mu-range", o->mu_range, "--check: surface mu uniform in LO:HI (default: the scene's mu)");
       app.add_option("--tip-mu-range", o->tip_mu_range, "--check: tip mu uniform in LO:HI (default: the scene's tip.mu)");
       app.add_flag("--robust", o->robust,
                    "a plan that reaches the goal in every world of --tip-mu-range (its ends) and --noise (the start "
                    "shifted by 2 sigma, one component at a time) as well as in the model's");
       app.add_option("--jobs", o->jobs,
                      "--check: threads (default: every core; under mpirun -np R nanopush-mpi, the cores per rank)")
           ->check(count(1, 1024));
       app.add_flag("--closed-loop", o->closed_loop,
                    "simulate the AFM loop: image (truth + noise), re-plan, push the truth, repeat (closed_loop.csv)");
       app.add_flag("--no-refit", o->no_refit,
                    "closed loop: keep the model's tip friction (default: re-fit tip.mu to the images after each push)");
       app.add_option("--truth", o->truth,
                      "closed loop: the true scene (a file or preset), or KEY=VALUE,... changed from SCENE "
                      "(e.g. tip.mu=0.3,object.length=110e-9); default: SCENE itself");
       app.add_option("--noise", o->noise, "closed loop: imaging noise x=SX,y=SY,theta=ST (m, m, rad; y defaults to x)")
           ->capture_default_str();
       app.add_option("--seed", o->seed, "closed loop: seed of the imaging noise")
           ->check(count(0, 1000000000000LL))
           ->capture_default_str();
       app.add_option("--out", o->out, "output directory (default <scene>.plan)");
       app.add_option("--format", o->format, "figure format: png, svg or pdf")->capture_default_str();
       app.add_flag("--quiet", o->quiet, "no summary on standard error");
       return [o] { return plan_cmd(*o); };
     }}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
