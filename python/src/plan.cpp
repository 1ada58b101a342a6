// nanopush.plan: tip pushes that bring a bar to a goal pose (cxx/include/nanopush/planning/plan.hpp;
// the numbers of `nanopush plan`, docs/planning.md).
#include "common.hpp"

#include <cmath>
#include <tuple>

#include "nanopush/planning/assemble.hpp"
#include "nanopush/planning/check.hpp"
#include "nanopush/planning/plan.hpp"

namespace nanopush::python {

namespace {

plan::Pose pose_arg(const py::handle& g, const std::string& name) {
  const py::object v = plain_value(g, name);
  if (py::isinstance<py::str>(v) || !py::isinstance<py::sequence>(v) || py::len(v) != 3)
    throw InputError(name, py::repr(v).cast<std::string>(), "must be (x [m], y [m], theta [rad])");
  const auto s = v.cast<py::sequence>();
  return {arg_double(s[0], name + "[0] (x)"), arg_double(s[1], name + "[1] (y)"), arg_double(s[2], name + "[2] (theta)")};
}

py::tuple pose_tuple(const plan::Pose& p) { return py::make_tuple(p.x, p.y, p.theta); }

/// The pushes as plan.csv's columns: start_x, start_y, direction, speed, travel, x_end,
/// y_end, theta_end (one row per push).
py::array_t<double> push_table(const plan::PlanResult& r) {
  const auto n = static_cast<py::ssize_t>(r.pushes.size());
  py::array_t<double> a({n, static_cast<py::ssize_t>(8)});
  auto m = a.mutable_unchecked<2>();
  for (py::ssize_t i = 0; i < n; ++i) {
    const auto& p = r.pushes[static_cast<std::size_t>(i)];
    const double row[8] = {p.start_x, p.start_y, p.direction, p.speed, p.travel, p.end.x, p.end.y, p.end.theta};
    for (py::ssize_t c = 0; c < 8; ++c) m(i, c) = row[c];
  }
  return a;
}

py::dict push_dict(const plan::PlannedPush& p) {
  py::dict d;
  d["start_x"] = p.start_x;
  d["start_y"] = p.start_y;
  d["direction"] = p.direction;
  d["speed"] = p.speed;
  d["travel"] = p.travel;
  d["end"] = pose_tuple(p.end);
  d["face"] = p.face;
  d["offset"] = p.offset;
  d["max_force"] = p.max_force;
  d["verified_deviation"] = p.verified_deviation;
  return d;
}

/// (lo, hi) of `name`, or {-1, -1} for None.
std::pair<double, double> range_arg(const py::object& v, const std::string& name, const std::string& none_means) {
  const py::object m = plain_value(v, name);
  if (m.is_none()) return {-1, -1};
  if (py::isinstance<py::str>(m) || !py::isinstance<py::sequence>(m) || py::len(m) != 2)
    throw InputError(name, py::repr(m).cast<std::string>(), "must be (lo, hi) or None (" + none_means + ")");
  return {arg_double(m.cast<py::sequence>()[0], name + "[0]"), arg_double(m.cast<py::sequence>()[1], name + "[1]")};
}

plan::PlanResult plan_scene_named(const Scene& scene, const py::object& goal, const py::object& tolerance,
                                  const std::string& objective, const py::object& max_pushes,
                                  const py::object& half_turn, const py::object& baseline,
                                  const py::object& robust_tip_mu, const py::object& robust_start) {
  const plan::Pose g = pose_arg(goal, "goal");
  plan::PlanOptions o;
  const py::object tol = plain_value(tolerance, "tolerance");
  if (py::isinstance<py::str>(tol) || !py::isinstance<py::sequence>(tol) || py::len(tol) != 2)
    throw InputError("tolerance", py::repr(tol).cast<std::string>(), "must be (distance [m], angle [rad])");
  o.tolerance_distance = arg_double(tol.cast<py::sequence>()[0], "tolerance[0] (distance)");
  o.tolerance_angle = arg_double(tol.cast<py::sequence>()[1], "tolerance[1] (angle)");
  o.objective = plan::parse_objective(objective);
  const double n = arg_double(max_pushes, "max_pushes");
  if (!(n >= 1 && n <= 1000 && n == std::floor(n)))
    throw InputError("max_pushes", py::repr(max_pushes).cast<std::string>(), "must be a whole number in [1, 1000]");
  o.max_pushes = static_cast<int>(n);
  o.half_turn_symmetric = arg_bool(half_turn, "half_turn_symmetric");
  const bool base = arg_bool(baseline, "baseline");
  std::tie(o.robust_tip_mu_lo, o.robust_tip_mu_hi) = range_arg(robust_tip_mu, "robust_tip_mu", "the model's tip.mu only");
  if (!plain_value(robust_start, "robust_start").is_none()) {
    const plan::Pose d = pose_arg(robust_start, "robust_start");
    o.robust_start_x = d.x;
    o.robust_start_y = d.y;
    o.robust_start_theta = d.theta;
  }
  if (base && o.robust())
    throw InputError("baseline", "True", "the baseline plans for the model only: drop robust_tip_mu and robust_start");
  py::gil_scoped_release release;
  return base ? plan::plan_baseline(scene, g, o) : plan::plan_pushes(scene, g, o);
}

/// nanopush.plan: the library names some inputs as `nanopush plan` does (--goal, --noise, ...);
/// here they are nanopush.plan's arguments.
plan::PlanResult plan_scene(const Scene& scene, const py::object& goal, const py::object& tolerance,
                            const std::string& objective, const py::object& max_pushes, const py::object& half_turn,
                            const py::object& baseline, const py::object& robust_tip_mu, const py::object& robust_start) {
  return bindings::with_argument_names(
      {{"--goal", "goal"}, {"--tolerance", "tolerance"}, {"--objective", "objective"}, {"--max-pushes", "max_pushes"},
       {"--tip-mu-range", "robust_tip_mu"}, {"--noise", "robust_start"}},
      [&] {
        return plan_scene_named(scene, goal, tolerance, objective, max_pushes, half_turn, baseline, robust_tip_mu,
                                robust_start);
      });
}

/// PlanResult._check: plan --check in memory (planning/check.hpp): (names, units, columns,
/// summary) with the summary's trials, successes, probability and Wilson interval.
py::tuple check_plan_named(const plan::PlanResult& r, const Scene& scene, const py::object& trials,
                           const py::object& noise, const py::object& mu_range, const py::object& tip_mu_range,
                           const py::object& seed, const py::object& jobs, const py::object& progress) {
  const double n = arg_double(trials, "trials");
  if (!(n >= 1 && n <= 1000000 && n == std::floor(n)))
    throw InputError("trials", py::repr(trials).cast<std::string>(), "must be a whole number in [1, 1000000]");
  plan::CheckWorlds w;
  const plan::Pose sd = pose_arg(noise, "noise");
  w.noise = {sd.x, sd.y, sd.theta};
  if (!plain_value(mu_range, "mu_range").is_none()) {
    const py::object m = plain_value(mu_range, "mu_range");
    if (py::isinstance<py::str>(m) || !py::isinstance<py::sequence>(m) || py::len(m) != 2)
      throw InputError("mu_range", py::repr(m).cast<std::string>(), "must be (lo, hi) or None (the scene's mu)");
    w.mu_lo = arg_double(m.cast<py::sequence>()[0], "mu_range[0]");
    w.mu_hi = arg_double(m.cast<py::sequence>()[1], "mu_range[1]");
  }
  std::tie(w.tip_mu_lo, w.tip_mu_hi) = range_arg(tip_mu_range, "tip_mu_range", "the scene's tip.mu");
  const double s = arg_double(seed, "seed");
  if (!(s >= 0 && s <= 1e12 && s == std::floor(s)))
    throw InputError("seed", py::repr(seed).cast<std::string>(), "must be a whole number in [0, 1e12]");
  w.seed = static_cast<std::uint64_t>(s);
  const double j = arg_double(jobs, "jobs");
  if (!(j >= 0 && j <= 1024 && j == std::floor(j)))
    throw InputError("jobs", py::repr(jobs).cast<std::string>(), "must be a whole number in [0, 1024] (0: every core)");
  const sweep::Plan points = plan::check_points(static_cast<int>(n));
  const auto task = plan::make_check_task(scene, r, r.options, w);
  const py::tuple t = sweep_in_memory(points, *task, static_cast<unsigned>(j), progress);
  plan::PlanCheck c;
  const auto success = t[2].cast<py::dict>()["success"].cast<py::array_t<double>>();
  for (py::ssize_t i = 0; i < success.size(); ++i) {
    ++c.trials;
    if (success.at(i) == 1) ++c.successes;
  }
  plan::wilson_interval(c);
  py::dict summary;
  summary["trials"] = c.trials;
  summary["successes"] = c.successes;
  summary["probability"] = c.probability;
  summary["interval"] = py::make_tuple(c.low, c.high);
  return py::make_tuple(t[0], t[1], t[2], summary);
}

/// The same under nanopush.check_plan's names for the inputs `plan --check` names by its flags.
py::tuple check_plan(const plan::PlanResult& r, const Scene& scene, const py::object& trials, const py::object& noise,
                     const py::object& mu_range, const py::object& tip_mu_range, const py::object& seed,
                     const py::object& jobs, const py::object& progress) {
  return bindings::with_argument_names(
      {{"--noise", "noise"}, {"--mu-range", "mu_range"}, {"--tip-mu-range", "tip_mu_range"}, {"--check", "trials"}},
      [&] { return check_plan_named(r, scene, trials, noise, mu_range, tip_mu_range, seed, jobs, progress); });
}

/// Poses from an (n, 3) array-like of (x, y, theta).
std::vector<plan::Pose> poses_arg(const py::object& v, const std::string& name) {
  py::array_t<double> a;
  refuse_complex(v, name);
  try {
    a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  } catch (const py::error_already_set&) {
  }
  if (!a || a.ndim() != 2 || a.shape(1) != 3)
    throw InputError(name, py::repr(v).cast<std::string>().substr(0, 80), "must be an (n, 3) array of (x [m], y [m], theta [rad])");
  std::vector<plan::Pose> p;
  for (py::ssize_t i = 0; i < a.shape(0); ++i) p.push_back({a.at(i, 0), a.at(i, 1), a.at(i, 2)});
  return p;
}

/// nanopush.assemble: (status, message, slot_of, order, final poses (n, 3), the moves' plans).
py::tuple assemble_named(const Scene& scene, const py::object& objects, const py::object& slots,
                         const py::object& tolerance, const std::string& objective, const py::object& max_pushes,
                         const py::object& gap) {
  plan::AssemblyOptions o;
  const py::object tol = plain_value(tolerance, "tolerance");
  if (py::isinstance<py::str>(tol) || !py::isinstance<py::sequence>(tol) || py::len(tol) != 2)
    throw InputError("tolerance", py::repr(tol).cast<std::string>(), "must be (distance [m], angle [rad])");
  o.plan.tolerance_distance = arg_double(tol.cast<py::sequence>()[0], "tolerance[0] (distance)");
  o.plan.tolerance_angle = arg_double(tol.cast<py::sequence>()[1], "tolerance[1] (angle)");
  o.plan.objective = plan::parse_objective(objective);
  const double n = arg_double(max_pushes, "max_pushes");
  if (!(n >= 1 && n <= 1000 && n == std::floor(n)))
    throw InputError("max_pushes", py::repr(max_pushes).cast<std::string>(), "must be a whole number in [1, 1000]");
  o.plan.max_pushes = static_cast<int>(n);
  o.gap = arg_double(gap, "gap");
  const auto obj = poses_arg(objects, "objects"), sl = poses_arg(slots, "slots");
  plan::AssemblyResult r;
  {
    py::gil_scoped_release release;
    r = plan::assemble(scene, obj, sl, o);
  }
  py::array_t<double> final_poses({static_cast<py::ssize_t>(r.final_poses.size()), static_cast<py::ssize_t>(3)});
  for (std::size_t i = 0; i < r.final_poses.size(); ++i) {
    const auto k = static_cast<py::ssize_t>(i);
    final_poses.mutable_at(k, 0) = r.final_poses[i].x;
    final_poses.mutable_at(k, 1) = r.final_poses[i].y;
    final_poses.mutable_at(k, 2) = r.final_poses[i].theta;
  }
  py::list order, plans;
  for (const auto& m : r.moves) {
    order.append(m.object);
    plans.append(py::cast(m.plan));
  }
  return py::make_tuple(to_string(r.status), r.message, py::cast(r.slot_of), order, final_poses, plans, r.assignment_cost);
}

/// The same under nanopush.assemble's names for the inputs `nanopush assemble` names its own way.
py::tuple assemble_bars(const Scene& scene, const py::object& objects, const py::object& slots, const py::object& tolerance,
                        const std::string& objective, const py::object& max_pushes, const py::object& gap) {
  return bindings::with_argument_names(
      {{"--gap", "gap"}, {"--tolerance", "tolerance"}, {"--objective", "objective"}, {"--max-pushes", "max_pushes"},
       {"pattern", "slots"}},
      [&] { return assemble_named(scene, objects, slots, tolerance, objective, max_pushes, gap); });
}

}  // namespace

void register_plan(py::module_& m) {
  py::class_<plan::PlanResult>(m, "PlanResult", R"doc(A push plan (nanopush.plan; docs/planning.md).

status          "found" or "not_found" (then the best plan found); found: the same as a flag
verified        every push re-run by the full model matches, and the chain ends within tolerance
start, goal     poses (x [m], y [m], theta [rad]); final_pose: where the pushes end, end to end
final_distance  |CM - goal| [m]; final_angle: |theta - goal| [rad] (modulo pi when half-turn symmetric)
pushes          one dict per push: start_x, start_y, direction, speed, travel (the scene's tip.* keys),
                end (pose), face, offset, max_force [N], verified_deviation
table           the pushes as an (n, 8) array: start_x, start_y, direction, speed, travel, x_end,
                y_end, theta_end (plan.csv's columns after `push`)
tip_travel [m], time [s], forward_runs, planning_seconds
worlds          robust plans: one dict per world planned for (tip_mu, start, final_pose,
                final_distance, final_angle, reached), the model's first; [] otherwise)doc")
      .def_property_readonly("status", [](const plan::PlanResult& r) { return to_string(r.status); })
      .def_property_readonly("found", &plan::PlanResult::found)
      .def_property_readonly("message", [](const plan::PlanResult& r) { return r.message; })
      .def_property_readonly("verified", [](const plan::PlanResult& r) { return r.verified; })
      .def_property_readonly("start", [](const plan::PlanResult& r) { return pose_tuple(r.start); })
      .def_property_readonly("goal", [](const plan::PlanResult& r) { return pose_tuple(r.goal); })
      .def_property_readonly("final_pose", [](const plan::PlanResult& r) { return pose_tuple(r.final_pose); })
      .def_property_readonly("final_distance", [](const plan::PlanResult& r) { return r.final_distance; })
      .def_property_readonly("final_angle", [](const plan::PlanResult& r) { return r.final_angle; })
      .def_property_readonly("tip_travel", [](const plan::PlanResult& r) { return r.tip_travel; })
      .def_property_readonly("time", [](const plan::PlanResult& r) { return r.time; })
      .def_property_readonly("forward_runs", [](const plan::PlanResult& r) { return r.forward_runs; })
      .def_property_readonly("planning_seconds", [](const plan::PlanResult& r) { return r.planning_seconds; })
      .def_property_readonly("pushes",
                             [](const plan::PlanResult& r) {
                               py::list l;
                               for (const auto& p : r.pushes) l.append(push_dict(p));
                               return l;
                             })
      .def_property_readonly("table", &push_table)
      .def_property_readonly("worlds",
                             [](const plan::PlanResult& r) {
                               py::list l;
                               for (const auto& w : r.worlds) {
                                 py::dict d;
                                 d["tip_mu"] = w.tip_mu;
                                 d["start"] = pose_tuple(w.start);
                                 d["final_pose"] = pose_tuple(w.final_pose);
                                 d["final_distance"] = w.final_distance;
                                 d["final_angle"] = w.final_angle;
                                 d["reached"] = w.reached;
                                 l.append(d);
                               }
                               return l;
                             })
      .def(
          "push_scene",
          [](const plan::PlanResult& r, const Scene& scene, const py::object& k) {
            const double i = arg_double(k, "k");
            if (!(i >= 0 && i < static_cast<double>(r.pushes.size()) && i == std::floor(i)))
              throw InputError("k", py::repr(k).cast<std::string>(),
                               "must be a push index in [0, " + std::to_string(r.pushes.size()) + ")");
            const auto n = static_cast<std::size_t>(i);
            return plan::push_scene(scene, n == 0 ? r.start : r.pushes[n - 1].end, r.pushes[n]);
          },
          py::arg("scene"), py::arg("k"),
          "The scene that replays push k (from the pose push k-1 left): push.mode = tip and the push's tip keys; "
          "nanopush.run(it) is the forward run that verified it.")
      .def("_check", &check_plan, py::arg("scene"), py::arg("trials"), py::arg("noise"), py::arg("mu_range"),
           py::arg("tip_mu_range"), py::arg("seed"), py::arg("jobs"), py::arg("progress"))
      .def("__repr__", [](const plan::PlanResult& r) {
        return "<nanopush.PlanResult " + to_string(r.status) + (r.verified ? " (verified)" : "") + ", " +
               std::to_string(r.pushes.size()) + " pushes, final distance " + py::repr(py::float_(r.final_distance)).cast<std::string>() +
               " m, angle " + py::repr(py::float_(r.final_angle)).cast<std::string>() + " rad>";
      });
  m.def("_assemble", &assemble_bars, py::arg("scene"), py::arg("objects"), py::arg("slots"), py::arg("tolerance"),
        py::arg("objective"), py::arg("max_pushes"), py::arg("gap"));
  m.def("_plan", &plan_scene, py::arg("scene"), py::arg("goal"), py::arg("tolerance"), py::arg("objective"),
        py::arg("max_pushes"), py::arg("half_turn_symmetric"), py::arg("baseline"), py::arg("robust_tip_mu"),
        py::arg("robust_start"));
}

}  // namespace nanopush::python
