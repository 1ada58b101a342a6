#include "nanopush/outputs/trajectory_csv.hpp"

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

void write_trajectory_csv(const Trajectory& tr, const std::filesystem::path& path, const std::string& scene) {
  CsvWriter w(path, trajectory_column_specs(), scene);
  for (const auto& r : tr.rows) w.row(std::vector<double>(r.begin(), r.end()));
  w.commit();
}

}  // namespace nanopush
