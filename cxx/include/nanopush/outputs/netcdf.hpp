// NetCDF-4 for studies (docs/data.md): a finished CSV table and its Table Schema sidecar,
// converted into one netCDF-4 file through the netCDF C library, written atomically. A grid
// becomes variables over dimensions named after its axes (xarray.open_dataset gives a labelled
// N-d array); a list of points, variables over one dimension `point`.
#pragma once
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace nanopush {

/// One dimension of a grid table: the column that holds the axis, and its number of values
/// (0: the number of distinct values in the column, as written).
struct NetcdfAxis {
  std::string column;
  std::size_t size = 0;
};

/// Convert the CSV table `csv` (as CsvWriter writes it: a header, one row per record, the empty
/// cell for a missing value) and its sidecar schema_path(csv) into the netCDF-4 file `nc`.
///  - `axes` empty: one dimension `point` of the table's rows, every column a variable over it;
///  - `axes` given: the rows are the grid in row-major order, the last axis fastest (as
///    `nanopush sweep` writes a grid); each axis is a dimension named after its column with a
///    coordinate variable of its values, every other column a variable over the axes' dimensions.
/// Types: number -> NC_DOUBLE (the CSV's doubles exactly; a missing value is NaN, the
/// _FillValue), integer -> NC_INT64 (with a missing cell: _FillValue -9223372036854775806), string ->
/// NC_STRING. Attributes: `units` (the sidecar's unit, absent for text), `long_name` (its
/// description); global: `Conventions` "CF-1.8", `title`, the sidecar's provenance
/// (`nanopush_version`, `command`, `scene`, `created`, `run_<name>` for each timing or count).
/// `trajectories`: empty, or one trajectory CSV per row of the table (a sweep's
/// --trajectories files in point order; a file that does not exist: a point without one). They
/// become one variable `trajectory` over the table's dimensions, `time` (the samples, as many as
/// the longest) and `column` (string coordinate `column`, units in `column_units`), NaN after a
/// trajectory's end, and `samples`, each point's number of samples.
/// InputError when the table is not the grid the axes describe (nothing written); OutputError
/// when the file cannot be written. The file appears whole or not at all.
void write_netcdf_from_table(const std::filesystem::path& csv, const std::filesystem::path& nc,
                             const std::vector<NetcdfAxis>& axes = {},
                             const std::vector<std::filesystem::path>& trajectories = {});

}  // namespace nanopush
