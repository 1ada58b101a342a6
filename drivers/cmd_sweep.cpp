// nanopush sweep: many scenes (or closed-form evaluations) at once, on every core, in shards
// (job arrays) or across MPI ranks; one tidy table ordered by point index. docs/sweeps.md.
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "nanopush_toml.hpp"

#include "nanopush/numerics/error.hpp"
#include "nanopush/sweeps/sweep.hpp"
#include "cli_checks.hpp"
#include "registry.hpp"
#include "scene_args.hpp"
#include "sweep_mpi.hpp"
#include "sweep_output.hpp"

namespace nanopush::cli {
namespace {
namespace NANOPUSH_UNITY_ID {

struct SweepOptions {
  std::string scene, task = "run", out, trajectories, shard, engine, method, law;
  std::vector<std::string> sets, vary, vary_log, merge;
  std::vector<std::string> given;  ///< the options given on the command line (names as --help shows them)
  std::string points;
  unsigned jobs = 0;
  bool quiet = false;
  double accuracy = -1;  ///< task run: < 0 the scene's solver.accuracy
  bool no_estimate = false;
};

/// The [sweep] table of a scene file: vary, vary_log, points, set, task (docs/sweeps.md).
void read_sweep_table(const Scene& sc, SweepOptions& o) {
  if (!sc.document) return;
  const toml::node* n = sc.document->get("sweep");
  if (!n) return;
  const toml::table* t = n->as_table();
  if (!t) throw InputError("sweep", "(not a table)", "must be a [sweep] table");
  auto strings = [&](const char* key, std::vector<std::string>& into) {
    const toml::node* v = t->get(key);
    if (!v) return;
    const toml::array* a = v->as_array();
    if (!a) throw InputError(std::string("sweep.") + key, "(not an array)", "must be an array of \"KEY=...\" strings");
    for (const auto& e : *a) {
      auto s = e.value<std::string>();
      if (!s) throw InputError(std::string("sweep.") + key, "(a non-string)", "must be an array of strings");
      into.push_back(*s);
    }
  };
  for (auto&& [k, v] : *t) {
    const std::string key(k.str());
    if (key != "vary" && key != "vary_log" && key != "points" && key != "set" && key != "task")
      throw InputError("sweep." + key, "(present)", "unknown key; allowed here: vary, vary_log, points, set, task");
  }
  strings("vary", o.vary);
  strings("vary_log", o.vary_log);
  std::vector<std::string> sets;
  strings("set", sets);
  o.sets.insert(o.sets.begin(), sets.begin(), sets.end());  // the command line's --set wins
  if (auto p = t->get("points")) {
    auto s = p->value<std::string>();
    if (!s) throw InputError("sweep.points", "(not a string)", "must be a CSV file name");
    if (o.points.empty()) o.points = (sc.source.parent_path() / *s).string();
  }
  if (auto p = t->get("task")) {
    auto s = p->value<std::string>();
    if (!s) throw InputError("sweep.task", "(not a string)", "must be run, friction, icor or estimate-mu");
    o.task = *s;
  }
}

std::pair<std::size_t, std::size_t> parse_shard(const std::string& s) {
  const auto slash = s.find('/');
  try {
    if (slash != std::string::npos) {
      std::size_t p1 = 0, p2 = 0;
      const unsigned long i = std::stoul(s.substr(0, slash), &p1), n = std::stoul(s.substr(slash + 1), &p2);
      if (p1 == slash && p2 == s.size() - slash - 1 && n >= 1 && n <= 100000 && i < n) return {i, n};
    }
  } catch (const std::exception&) {
  }
  throw InputError("--shard", s, "must be i/n with 0 <= i < n <= 100000 (e.g. 0/4)");
}

int sweep_cmd(SweepOptions o) {
  if (!o.merge.empty()) {
    // Merge joins tables: a scene, an axis, a shard or a run option would be ignored, so it is
    // refused (the shards' sidecars say what their sweep was).
    for (const auto& g : o.given)
      if (g != "--merge" && g != "--out" && g != "--quiet")
        throw InputError(g, "(given with --merge)",
                         "--merge joins finished shard tables and takes only --out and --quiet: run the sweep "
                         "(with " + g + ") and merge its shards in a separate command");
    if (o.out.empty()) throw InputError("--out", "(missing)", "--merge writes the joined table to --out FILE");
    const TableOutput output(o.out);  // CSV, netCDF (over `point`) or standard output, by extension
    const auto failed = sweep::merge_tables({o.merge.begin(), o.merge.end()}, output.table());
    const std::string where = output.finish({});
    if (!o.quiet) std::cerr << "sweep: joined " << o.merge.size() << " shards into " << where << "\n";
    return sweep_exit_status(failed);
  }
  std::unique_ptr<sweep::Task> task;
  std::string default_out;
  const sweep::TaskKind kind = parse_choice<sweep::TaskKind>("--task", o.task);
  if (kind == sweep::TaskKind::run) {
    if (o.scene.empty()) throw InputError("SCENE", "(missing)", "--task run sweeps a scene: give a file or preset");
    Scene sc = load_scene(resolve_scene(o.scene));
    read_sweep_table(sc, o);
  }
  if (kind == sweep::TaskKind::run) {
    Scene sc = load_scene_arg(o.scene, o.sets);
    set_provenance_scene(o.scene);
    RunSettings rs;
    rs.engine = parse_optional_choice<Engine>("engine", o.engine);
    rs.method = parse_optional_choice<Method>("method", o.method);
    rs.law = parse_optional_choice<Law>("law", o.law);
    rs.accuracy = o.accuracy;
    if (o.no_estimate) rs.error_estimate = false;
    (void)resolve_settings(sc, rs);  // bad engine/method/law combinations before any work
    if (!o.trajectories.empty()) std::filesystem::create_directories(o.trajectories);
    task = sweep::make_run_task(sc, rs, o.trajectories);
    default_out = sc.name + "_sweep.csv";
  } else {
    if (!o.scene.empty()) throw InputError("SCENE", o.scene, "--task " + o.task + " takes no scene (use --set)");
    if (!o.engine.empty() || !o.method.empty() || !o.law.empty() || !o.trajectories.empty())
      throw InputError("--task", o.task, "--engine, --method, --law and --trajectories go with --task run only");
    std::vector<SceneSetting> fixed;
    for (const auto& s : o.sets) {
      const auto eq = s.find('=');
      if (eq == std::string::npos || eq == 0) throw InputError("--set", s, "must be KEY=VALUE");
      const auto axis = sweep::parse_axis(s, false);
      if (axis.values.size() != 1) throw InputError("--set", s, "one value (use --vary for several)");
      fixed.emplace_back(axis.key, axis.values.front());
    }
    task = sweep::make_task(kind, fixed);
    default_out = o.task + "_sweep.csv";
  }
  sweep::Plan plan;
  if (!o.points.empty()) {
    if (!o.vary.empty() || !o.vary_log.empty()) throw InputError("--points", o.points, "give either --points or --vary axes, not both");
    plan = sweep::points_from_csv(o.points);
  } else {
    std::vector<sweep::Axis> axes;
    for (const auto& v : o.vary) axes.push_back(sweep::parse_axis(v, false));
    for (const auto& v : o.vary_log) axes.push_back(sweep::parse_axis(v, true));
    plan = sweep::cartesian(axes);
  }
  // A key is fixed (--set, the [sweep] table's set) or varied, never both: the fixed value
  // would be overwritten at every point.
  for (const auto& set : o.sets) {
    const std::string key = set.substr(0, set.find('='));
    for (const auto& k : plan.keys)
      if (k == key)
        throw InputError("--set", set,
                         "conflicts with " + std::string(o.points.empty() ? "--vary" : "--points " + o.points) +
                             ", which varies " + key + ": a key is either fixed or varied");
  }
  sweep::Options opt;
  opt.jobs = o.jobs;
  if (!o.shard.empty()) std::tie(opt.shard_index, opt.shard_count) = parse_shard(o.shard);
  opt.out = o.out.empty() ? default_out : o.out;
  opt.progress = progress_line(o.quiet, "sweep");
  opt.fixed = o.sets;
  opt.stop = install_sweep_stop();

  // The table's format, by the extension of --out (docs/data.md): the sweep writes CSV, which
  // a .nc is converted from once complete; a grid's axes become its dimensions.
  const TableOutput output(opt.out);
  opt.out = output.table();
  const std::vector<NetcdfAxis> axes = output.netcdf() && o.points.empty() && o.shard.empty()
                                           ? grid_axes(o.vary, o.vary_log, sweep::table_columns(plan, *task))
                                           : std::vector<NetcdfAxis>{};
  // Each row's trajectory (--trajectories), for the .nc: point i of the shard's rows.
  std::vector<std::filesystem::path> trajectories;
  if (output.netcdf() && !o.trajectories.empty()) {
    const auto [index, count] = o.shard.empty() ? std::pair<std::size_t, std::size_t>{0, 1} : parse_shard(o.shard);
    for (std::size_t i = index; i < plan.size(); i += count)
      trajectories.push_back(std::filesystem::path(o.trajectories) / ("point_" + std::to_string(i) + ".csv"));
  }
  if (mpi_launched()) {
    const int rc = run_mpi_sweep(plan, *task, opt, o.quiet, sweep_signal());
    if (rc < 128 && table_rank()) (void)output.finish(axes, trajectories);
    return rc;
  }

  const auto r = sweep::run_local(plan, *task, opt);
  if (!r.complete) {
    std::cerr << "sweep: interrupted: " << r.done << " of " << r.points << " points are in "
              << sweep::journal_path(opt.out).string() << "; run the same command again to resume\n";
    return 128 + (*sweep_signal() ? static_cast<int>(*sweep_signal()) : SIGINT);
  }
  const std::string where = output.finish(axes, trajectories);
  if (!o.quiet) {
    std::cerr << "sweep: " << r.points << " points (" << r.resumed << " from the journal), " << r.failed
              << " failed: " << where << "\n";
  }
  return sweep_exit_status(r.failed);
}

RegisterCommand reg{
    {"sweep",
     "Many scenes at once: a grid (--vary) or list (--points) of points, on every core, in shards or over MPI "
     "ranks; one table ordered by point (docs/sweeps.md). Exit 0, or 64 + the number of failed points (65 + it from 6 on: 70 is an internal error; at most 127)",
     15, [](CLI::App& app) -> std::function<int()> {
       auto o = std::make_shared<SweepOptions>();
       app.add_option("SCENE", o->scene, "scene file or preset (task run); a [sweep] table in it adds axes");
       add_set_option(app, o->sets);
       app.add_option("--vary", o->vary,
                      "KEY=FROM:TO:N (N values, both ends) or KEY=V1,V2,...: an axis of the grid (repeatable; the "
                      "last axis varies fastest)")
           ->type_name("KEY=RANGE");
       app.add_option("--vary-log", o->vary_log, "KEY=FROM:TO:N: N geometrically spaced values")->type_name("KEY=RANGE");
       app.add_option("--points", o->points, "CSV file of points instead of a grid: header = keys, a row per point");
       app.add_option("--task", o->task, "what each point evaluates: run (default), friction, icor, estimate-mu")
           ->check(is_choice<sweep::TaskKind>());
       app.add_option("--engine", o->engine, "task run: cxx or f77 (default: the scene's)")
           ->check(is_choice<Engine>());
       app.add_option("--method", o->method, "task run: faithful, modern, dop853, cvode or auto (default: the scene's)")
           ->check(is_choice<Method>());
       app.add_option("--law", o->law, "task run, rough scenes: thesis, printed or coulomb (default: the scene's)")
           ->check(is_choice<Law>());
       add_accuracy_options(app, o->accuracy, o->no_estimate);
       app.add_option("--out", o->out,
                      "the table: FILE.csv (default <scene>_sweep.csv; its journal is FILE.csv.journal), FILE.nc "
                      "(netCDF-4: a grid's axes as dimensions; docs/data.md) or - (CSV on standard output)");
       app.add_option("--trajectories", o->trajectories, "task run: also keep each point's trajectory, DIR/point_<i>.csv");
       app.add_option("--jobs", o->jobs, "threads (default: every core; under MPI, the cores per rank)")
           ->check(count(1, 1024));
       app.add_option("--shard", o->shard, "i/n: run only the i-th of n disjoint parts (job arrays); join with --merge");
       app.add_option("--merge", o->merge, "join these shard tables into --out (and check every point is there once)");
       app.add_flag("--quiet", o->quiet, "no summary or progress on standard error");
       return [o, a = &app] {
         for (const CLI::Option* opt : a->get_options())
           if (opt->count() > 0 && opt->get_name() != "--help") o->given.push_back(opt->get_name());
         return sweep_cmd(*o);
       };
     }}};

}  // namespace NANOPUSH_UNITY_ID
}  // namespace
}  // namespace nanopush::cli
