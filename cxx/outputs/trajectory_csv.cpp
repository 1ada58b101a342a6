#include "nanopush/outputs/trajectory_csv.hpp"

#include <vector>

#include "nanopush/outputs/io.hpp"

namespace nanopush {

void write_trajectory_csv(const Trajectory& tr, const std::filesystem::path& path) {
  CsvWriter w(path, trajectory_columns());
  for (const auto& r : tr.rows) w.row(std::vector<double>(r.begin(), r.end()));
  w.commit();
}

}  // namespace nanopush
