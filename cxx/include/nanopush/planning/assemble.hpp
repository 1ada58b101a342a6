// Assembly (docs/planning.md, "Assembly"): several bars of one kind, from their observed poses
// into the slots of a pattern. Which bar goes to which slot (the assignment of least summed
// distance), in which order, each bar's pushes planned by plan_pushes and replayed so that no
// bar, and no tip path, touches another bar on the way.
#pragma once
#include <string>
#include <vector>

#include "nanopush/planning/plan.hpp"

namespace nanopush::plan {

struct AssemblyOptions {
  PlanOptions plan;     ///< tolerance, objective and push budget of each bar's plan
  double gap = 2e-9;    ///< the least distance kept between two bars, and between a tip and a bar [m]
  int samples = 64;     ///< poses checked along each push
};

/// One bar's moves: its plan (pushes, verified end pose).
struct BarMove {
  int object = 0;  ///< index into the objects (0-based)
  int slot = 0;    ///< index into the slots
  PlanResult plan;
};

/// An assembly's outcome: assembled, or not_found (the moves made so far are kept).
enum class AssemblyStatus { assembled, not_found };

struct AssemblyResult {
  AssemblyStatus status = AssemblyStatus::not_found;
  std::string message;
  std::vector<int> slot_of;   ///< per object, its slot
  std::vector<BarMove> moves; ///< in the order they are made
  std::vector<Pose> final_poses;  ///< per object, where it ends
  double assignment_cost = 0; ///< summed |dr| + (L/2)|dtheta| of the assignment [m]
  double planning_seconds = 0;
  [[nodiscard]] bool assembled() const { return status == AssemblyStatus::assembled; }
};

/// The slot of each object minimising the summed pose_cost: exact (every permutation) up to 8
/// bars, else greedy completed by pairwise exchanges while one lowers the sum.
std::vector<int> assign_slots(const std::vector<Pose>& objects, const std::vector<Pose>& slots, double half_length,
                              bool half_turn_symmetric);

/// Do two bars (half extents a along body x', b along body y') at poses p and q come closer
/// than `gap`? Separating axes of the two rectangles grown by gap/2.
bool bars_overlap(const Pose& p, const Pose& q, double a, double b, double gap);

/// Does a disc (centre cx, cy, radius r) come closer than `gap` to the bar at pose p?
bool disc_touches_bar(double cx, double cy, double r, const Pose& p, double a, double b, double gap);

/// Move the bars of `scene` (its object, surface and tip) from `objects` into `slots` (as many
/// slots as objects): assign_slots, then repeatedly the nearest unplaced bar whose plan is found
/// and whose pushes, replayed at `samples` poses each, keep it and the tip clear of every other
/// bar; a bar whose plan collides waits for the others to move. InputError for bad input (no
/// objects, counts that differ, bars or slots that overlap at the start, a non-finite pose).
AssemblyResult assemble(const Scene& scene, const std::vector<Pose>& objects, const std::vector<Pose>& slots,
                        const AssemblyOptions& options);

}  // namespace nanopush::plan

namespace nanopush {
NANOPUSH_NAMES(plan::AssemblyStatus, {plan::AssemblyStatus::assembled, "assembled"},
               {plan::AssemblyStatus::not_found, "not_found"});
}  // namespace nanopush
