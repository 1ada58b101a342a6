#include "nanopush/outputs/trajectory_csv.hpp"

#include <cmath>
#include <stdexcept>
#include <vector>

namespace nanopush {

const Columns& trajectory_column_specs() {
  static const Columns c = [] {
    const std::vector<std::string> what = {
        "time",
        "x of the centre of mass (world axes)",
        "y of the centre of mass (world axes)",
        "orientation of the body's long axis (world axes)",
        "x velocity of the centre of mass",
        "y velocity of the centre of mass",
        "angular velocity (counter-clockwise positive)",
        "friction force on the body, x component (world axes)",
        "friction force on the body, y component (world axes)",
        "friction moment about the centre of mass",
    };
    const auto& names = trajectory_columns();
    const auto& units = trajectory_units();
    if (names.size() != what.size() || units.size() != what.size())
      throw std::logic_error("trajectory_column_specs: the column lists differ in length");
    Columns s;
    for (std::size_t i = 0; i < what.size(); ++i) s.push_back({names[i], units[i], what[i]});
    return s;
  }();
  return c;
}

RunInfo trajectory_run_info(const Trajectory& tr) {
  RunInfo info{{"engine", tr.engine_label},
               {"precision", to_string(tr.precision)},
               {"outcome", to_string(tr.outcome)},
               {"rtol", tr.rtol},
               {"nfcn", tr.stats.nfcn},
               {"nfcn_total", tr.nfcn_total()}};
  const ErrorEstimate& e = tr.error;
  if (e.available || !e.note.empty()) {
    info.push_back({"error_estimate", e.norm});
    info.push_back({"error_x_m", e.x});
    info.push_back({"error_y_m", e.y});
    info.push_back({"error_theta_rad", e.theta});
    info.push_back({"error_trajectory", e.trajectory});
    info.push_back({"error_length_scale_m", e.length_scale});
    info.push_back({"error_basis", e.basis});
    info.push_back({"error_companion", e.companion});
    info.push_back({"error_companion_rtol", e.companion_rtol});
    if (!e.note.empty()) info.push_back({"error_note", e.note});
  }
  if (tr.accuracy.requested > 0) {
    info.push_back({"accuracy_requested", tr.accuracy.requested});
    info.push_back({"accuracy_reached", tr.accuracy.reached});
    info.push_back({"accuracy_runs", tr.accuracy.runs});
  }
  return info;
}

const Columns& tip_column_specs() {
  static const Columns c = [] {
    Columns s = trajectory_column_specs();
    s.push_back({"tip_x", "m", "x of the tip centre (world axes)"});
    s.push_back({"tip_y", "m", "y of the tip centre (world axes)"});
    s.push_back({"tip_fx", "N", "force of the tip on the body, x component (world axes)"});
    s.push_back({"tip_fy", "N", "force of the tip on the body, y component (world axes)"});
    s.push_back({"contact", "1", "tip contact: 0 none, 1 sticking, 2 sliding"});
    return s;
  }();
  return c;
}

void write_trajectory_csv(const Trajectory& tr, const std::filesystem::path& path, const std::string& scene) {
  const bool tip = !tr.tip.empty();
  if (tip && tr.tip.size() != tr.rows.size())
    throw std::logic_error("write_trajectory_csv: tip samples and rows differ in number");
  CsvWriter w(path, tip ? tip_column_specs() : trajectory_column_specs(), scene);
  w.run_info(trajectory_run_info(tr));
  for (std::size_t i = 0; i < tr.rows.size(); ++i) {
    std::vector<double> v(tr.rows[i].begin(), tr.rows[i].end());
    if (tip) {
      const TipSample& s = tr.tip[i];
      v.insert(v.end(), {s.x, s.y, s.fx, s.fy, static_cast<double>(s.contact)});
    }
    w.row(v);
  }
  w.commit();
}

}  // namespace nanopush
