// A trajectory as CSV: the columns of trajectory_columns(), one row per output time, with
// its Table Schema sidecar (docs/outputs.md).
#pragma once
#include <filesystem>
#include <string>

#include "nanopush/outputs/io.hpp"
#include "nanopush/scenes/simulate.hpp"

namespace nanopush {

/// The trajectory columns t, x, ..., mf with their units and meanings (SI, world frame).
const Columns& trajectory_column_specs();
/// The same followed by the tip's columns tip_x, tip_y, tip_fx, tip_fy, contact (push.mode = tip).
const Columns& tip_column_specs();

/// Write a trajectory CSV (header t,x,...,mf) and its sidecar atomically; `scene` names the
/// scene in the sidecar (default: the process-wide provenance).
/// What a trajectory's sidecar records of its run ("nanopush"."run"): engine, outcome, rtol,
/// counts, and the error estimate (docs/accuracy.md).
RunInfo trajectory_run_info(const Trajectory& tr);

void write_trajectory_csv(const Trajectory& tr, const std::filesystem::path& path, const std::string& scene = {});

}  // namespace nanopush
