// Where a command's table goes, chosen by the extension of its output name (docs/data.md):
// TableOutput, the one place every command that writes a table file (sweep, run, icor, bench,
// friction --bench-csv, fit --synthesize) decides between FILE.csv (or a name without
// extension) the CSV and its Table Schema sidecar, FILE.nc netCDF-4 converted from the finished
// CSV (outputs/netcdf.hpp), and `-` the CSV on standard output; any other extension is bad
// input (exit 2), refused before any work. And the pieces of a sweep's run: progress, stop
// signals, grid axes.
#pragma once
#include <atomic>
#include <csignal>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "nanopush/outputs/netcdf.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::cli {

/// A sweep's exit status (docs/errors.md): 0, or 64 + k for k = 1..5 failed points and
/// 65 + k for k = 6..61, so that 70 stays the internal error's; 127 for 62 or more.
inline int sweep_exit_status(std::size_t failed) {
  if (failed == 0) return 0;
  if (failed <= 5) return 64 + static_cast<int>(failed);
  return failed >= 62 ? 127 : 65 + static_cast<int>(failed);
}

class TableOutput {
 public:
  enum class Kind { csv, netcdf, standard_output };
  /// What `out` names: FILE.nc netCDF; FILE.csv or no extension CSV; "-" standard output where
  /// `standard_output` (the commands whose `--out -` prints the table), else a file named `-`
  /// (CSV). Any other extension: InputError naming `option`, what was written and the allowed
  /// extensions. Creates nothing: a command calls it before its work.
  static Kind kind_of(const std::filesystem::path& out, const std::string& option = "--out",
                      bool standard_output = true);
  explicit TableOutput(const std::filesystem::path& out, const std::string& option = "--out",
                       bool standard_output = true);
  TableOutput(const TableOutput&) = delete;
  TableOutput& operator=(const TableOutput&) = delete;
  ~TableOutput();  // removes the temporary directory of a table for standard output

  /// The CSV table the command writes (a sweep's journal beside it): the output itself for
  /// CSV; FILE.nc.csv for FILE.nc (so an interrupted sweep resumes from FILE.nc.csv.journal); a
  /// file in a temporary directory for standard output.
  [[nodiscard]] const std::filesystem::path& table() const { return table_; }
  [[nodiscard]] bool netcdf() const { return kind_ == Kind::netcdf; }
  /// After the table is finished: the CSV is the output; or it is converted into the .nc (a
  /// grid over `axes`; none: a `point` dimension) and removed with its sidecar; or it is copied
  /// to standard output. Returns what to name in a summary.
  /// `trajectories` (netCDF only): one trajectory CSV per row, into the .nc's `trajectory`.
  std::string finish(const std::vector<NetcdfAxis>& axes = {},
                     const std::vector<std::filesystem::path>& trajectories = {}) const;

 private:
  Kind kind_ = Kind::csv;
  std::filesystem::path out_, table_, tmpdir_;
};

/// Every file a command will write, checked where it goes (resolve_output, docs/errors.md
/// "Outputs") before the command's work: a directory, a FIFO, a path ending in '/', ... is
/// refused (OutputError, exit 5) before anything is computed, made or written. A CSV's sidecar
/// is checked with it (csv_with_sidecar). Makes nothing.
void check_outputs(const std::vector<std::filesystem::path>& files);
/// `csv` and its Table Schema sidecar (none for a device), for check_outputs.
std::vector<std::filesystem::path> csv_with_sidecar(const std::filesystem::path& csv);
/// An output directory (`--out DIR`): a directory, a link to one, or a path that does not exist
/// yet (made with the first file). Anything else is refused (OutputError) before any work.
void check_output_directory(const std::filesystem::path& dir);

/// Progress of a sweep on stderr ("LABEL: done/total, rate, time left"), on a terminal only
/// (an empty function when quiet or not a terminal). The rate is over the last ten seconds from
/// the first report, which the runner makes when the work starts (sweep::ProgressRate), so
/// setting up and resumed points do not dilute it.
std::function<void(std::size_t, std::size_t)> progress_line(bool quiet, const std::string& label);

/// SIGINT and SIGTERM stop a sweep between points (points in flight finish and are kept in the
/// journal; a second signal ends the process at once): installs the handler and returns the
/// flag for sweep::Options::stop.
const std::atomic<bool>* install_sweep_stop();
/// The signal that stopped the sweep (0: none), for run_mpi_sweep and the exit status.
const volatile std::sig_atomic_t* sweep_signal();

/// True unless this process is an MPI rank other than 0 (the rank that writes the table).
bool table_rank();

/// The grid axes of a `--vary`/`--vary-log` sweep, in the order the plan takes them (every
/// --vary, then every --vary-log), each named after its table column (`columns`, from
/// sweep::table_columns: the point index, then one column per key).
std::vector<NetcdfAxis> grid_axes(const std::vector<std::string>& vary, const std::vector<std::string>& vary_log,
                                  const Columns& columns);

}  // namespace nanopush::cli
