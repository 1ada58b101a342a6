// C API: push planning (bindings/nanopush.h) over nanopush::plan::plan_pushes
// (cxx/include/nanopush/planning/plan.hpp, the numbers of `nanopush plan`). Everything is computed
// before anything is stored, so a failed call leaves every output untouched.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "capi_internal.hpp"
#include "nanopush/planning/assemble.hpp"
#include "nanopush/planning/plan.hpp"

using namespace nanopush::capi;
namespace plan = nanopush::plan;

extern "C" {

int nanopush_plan(nanopush_error error, nanopush_scene scene, const double* goal, const double* tolerance,
                  const char* objective, int max_pushes, int capacity, double* pushes, int* n_pushes, double* summary) {
  return nanopush_plan_robust(error, scene, goal, tolerance, objective, max_pushes, nullptr, nullptr, capacity, pushes,
                              n_pushes, summary);
}

int nanopush_plan_robust(nanopush_error error, nanopush_scene scene, const double* goal, const double* tolerance,
                         const char* objective, int max_pushes, const double* tip_mu_range, const double* start_shift,
                         int capacity, double* pushes, int* n_pushes, double* summary) {
  // The library names some inputs as `nanopush plan` does (--goal, --noise, ...): here they are
  // this function's arguments.
  return guarded(error, [&] {
    return nanopush::bindings::with_argument_names(
        {{"--goal", "goal"}, {"--tolerance", "tolerance"}, {"--objective", "objective"},
         {"--max-pushes", "max_pushes"}, {"--tip-mu-range", "tip_mu_range"}, {"--noise", "start_shift"}}, [&] {
      require_handle(scene, "scene");
      require_handle(goal, "goal");
      if (max_pushes < 1 || max_pushes > 1000)
        throw nanopush::InputError("max_pushes", std::to_string(max_pushes), "must be a whole number in [1, 1000]");
      if (capacity < 0) throw nanopush::InputError("capacity", std::to_string(capacity), "must be >= 0");
      if (pushes && capacity < max_pushes)
        throw StatusError(NANOPUSH_BUFFER_TOO_SMALL, "capacity = " + std::to_string(capacity) + ": pushes holds fewer " +
                                                         "rows than max_pushes = " + std::to_string(max_pushes));
      plan::PlanOptions o;
      if (tolerance) {
        o.tolerance_distance = tolerance[0];
        o.tolerance_angle = tolerance[1];
      }
      const std::string obj = opt_string(objective);
      if (!obj.empty()) o.objective = plan::parse_objective(obj);
      o.max_pushes = max_pushes;
      if (tip_mu_range) {
        o.robust_tip_mu_lo = tip_mu_range[0];
        o.robust_tip_mu_hi = tip_mu_range[1];
        if (!(o.robust_tip_mu_lo >= 0))  // (a negative lo would read as "no range")
          throw nanopush::InputError("tip_mu_range[0]", std::to_string(o.robust_tip_mu_lo), "must be >= 0");
      }
      if (start_shift) {
        o.robust_start_x = start_shift[0];
        o.robust_start_y = start_shift[1];
        o.robust_start_theta = start_shift[2];
      }
      const plan::PlanResult r = plan::plan_pushes(scene->scene, {goal[0], goal[1], goal[2]}, o);
      // everything computed: store
      if (pushes)
        for (std::size_t i = 0; i < r.pushes.size(); ++i) {
          const auto& p = r.pushes[i];
          const double row[NANOPUSH_PLAN_PUSH_SIZE] = {p.start_x, p.start_y, p.direction, p.speed,
                                                       p.travel,  p.end.x,   p.end.y,     p.end.theta};
          std::copy(row, row + NANOPUSH_PLAN_PUSH_SIZE, pushes + i * NANOPUSH_PLAN_PUSH_SIZE);
        }
      if (n_pushes) *n_pushes = static_cast<int>(r.pushes.size());
      if (summary) {
        const double s[NANOPUSH_PLAN_SUMMARY_SIZE] = {r.found() ? 1.0 : 0.0, r.verified ? 1.0 : 0.0, r.final_pose.x,
                                                      r.final_pose.y,         r.final_pose.theta,     r.final_distance,
                                                      r.final_angle,          static_cast<double>(r.forward_runs)};
        std::copy(s, s + NANOPUSH_PLAN_SUMMARY_SIZE, summary);
      }
      return NANOPUSH_OK;
    });
  });
}

int nanopush_assemble(nanopush_error error, nanopush_scene scene, int n, const double* objects, const double* slots,
                      const double* tolerance, int max_pushes, double gap, int capacity, double* pushes,
                      int* n_pushes, int* slot_of, double* final_poses, int* assembled) {
  // The library names some inputs as `nanopush assemble` does (--gap, PATTERN, ...): here they
  // are this function's arguments.
  return guarded(error, [&] {
    return nanopush::bindings::with_argument_names(
        {{"--gap", "gap"}, {"--tolerance", "tolerance"}, {"--objective", "objective"},
         {"--max-pushes", "max_pushes"}, {"pattern", "slots"}}, [&] {
      require_handle(scene, "scene");
      require_handle(objects, "objects");
      require_handle(slots, "slots");
      if (n < 1 || n > 20) throw nanopush::InputError("n", std::to_string(n), "must be a whole number in [1, 20] bars");
      if (max_pushes < 1 || max_pushes > 1000)
        throw nanopush::InputError("max_pushes", std::to_string(max_pushes), "must be a whole number in [1, 1000]");
      if (capacity < 0) throw nanopush::InputError("capacity", std::to_string(capacity), "must be >= 0");
      if (pushes && capacity < n * max_pushes)
        throw StatusError(NANOPUSH_BUFFER_TOO_SMALL, "capacity = " + std::to_string(capacity) + ": pushes holds fewer " +
                                                         "rows than n * max_pushes = " + std::to_string(n * max_pushes));
      plan::AssemblyOptions o;
      if (tolerance) {
        o.plan.tolerance_distance = tolerance[0];
        o.plan.tolerance_angle = tolerance[1];
      }
      o.plan.max_pushes = max_pushes;
      o.gap = gap;
      std::vector<plan::Pose> from, to;
      for (int i = 0; i < n; ++i) {
        from.push_back({objects[3 * i], objects[3 * i + 1], objects[3 * i + 2]});
        to.push_back({slots[3 * i], slots[3 * i + 1], slots[3 * i + 2]});
      }
      const plan::AssemblyResult r = plan::assemble(scene->scene, from, to, o);
      // everything computed: store
      int rows = 0;
      for (const auto& m : r.moves)
        for (const auto& p : m.plan.pushes) {
          if (pushes) {
            const double row[NANOPUSH_ASSEMBLY_PUSH_SIZE] = {double(m.object + 1), double(m.slot + 1), p.start_x, p.start_y,
                                                             p.direction, p.speed, p.travel, p.end.x, p.end.y, p.end.theta};
            std::copy(row, row + NANOPUSH_ASSEMBLY_PUSH_SIZE, pushes + rows * NANOPUSH_ASSEMBLY_PUSH_SIZE);
          }
          ++rows;
        }
      if (n_pushes) *n_pushes = rows;
      for (int i = 0; i < n; ++i) {
        if (slot_of) slot_of[i] = r.slot_of[static_cast<std::size_t>(i)] + 1;
        if (final_poses) {
          const auto& q = r.final_poses[static_cast<std::size_t>(i)];
          final_poses[3 * i] = q.x;
          final_poses[3 * i + 1] = q.y;
          final_poses[3 * i + 2] = q.theta;
        }
      }
      if (assembled) *assembled = r.assembled() ? 1 : 0;
      return NANOPUSH_OK;
    });
  });
}

}  // extern "C"
