// A trajectory as CSV: the columns of trajectory_columns(), one row per output time.
#pragma once
#include <filesystem>

#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

/// Write a trajectory CSV (header t,x,...,mf) atomically.
void write_trajectory_csv(const Trajectory& tr, const std::filesystem::path& path);

}  // namespace nanopush
