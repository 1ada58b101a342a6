// Output that is never lost and never half-written: every file goes to a temporary
// name in the same directory and is renamed over the target only when complete.
//
// CSV files follow one convention (docs/outputs.md): a header of plain identifiers, numbers
// in the shortest form that reads back to the same double, the empty cell for a missing
// value, and beside FILE.csv a Frictionless Table Schema FILE.schema.json naming each
// column's type, unit and meaning plus the run's provenance (version, command line, scene,
// time). Dates and timings go only into the sidecar, never into the CSV.
#pragma once
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <streambuf>
#include <string>
#include <variant>
#include <type_traits>
#include <vector>

namespace nanopush {

/// Remove every temporary file an AtomicFile of this process has open (their CSVs were never
/// committed). Async-signal-safe: for a signal handler, which then exits.
void remove_temporary_files() noexcept;

/// An output that cannot be written where it was asked to go (a directory or a FIFO where a
/// file is expected, a write or rename that fails): a system error, exit 5 on the command
/// line (docs/errors.md), OSError in Python.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Where an output named `target` goes (docs/errors.md, "Outputs"):
///  - a regular file, or a path that does not exist: replaced whole, by a temporary in its
///    directory renamed over it (`write_through` false, `path` the target);
///  - a symbolic link: followed (every hop); its final target is replaced the same way, in
///    the target's directory, and the link is kept (`path` the final target);
///  - a character device (/dev/null, a terminal), or a descriptor of this process
///    (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N): written through, opened and
///    written in place, never renamed over (`write_through` true; such a CSV has no sidecar);
///  - a directory, a FIFO, a socket or a block device: OutputError, nothing touched.
struct OutputTarget {
  std::filesystem::path path;
  bool write_through = false;
};
OutputTarget resolve_output(const std::filesystem::path& target);

/// Remove the temporaries `NAME.tmp.PID[.EXT]` of `target` left in its directory by a process
/// that no longer exists (killed with SIGKILL): the next write of the same output sweeps them.
void remove_stale_temporaries(const std::filesystem::path& target) noexcept;

/// An output file: whole or not at all (see resolve_output). Writes go to a temporary that
/// commit() renames over the target; a written-through target receives them directly.
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // removes the temporary if commit() was never called

  std::ostream& stream() { return *out_; }
  [[nodiscard]] const std::filesystem::path& temp_path() const { return tmp_; }
  [[nodiscard]] const std::filesystem::path& target() const { return target_; }
  /// True when the target is a device or descriptor written in place (no temporary, no sidecar).
  [[nodiscard]] bool write_through() const { return through_; }
  /// Flush and close the temporary, leaving it in place (OutputError on a write error); commit() renames.
  void finish();
  /// Flush, close and rename onto the target. Throws OutputError on failure.
  void commit();

 private:
  std::filesystem::path target_, final_, tmp_;
  std::unique_ptr<std::streambuf> buf_;
  std::unique_ptr<std::ostream> out_;
  bool through_ = false, finished_ = false, committed_ = false;
  int fd_ = -1;
  int slot_ = -1;  ///< where remove_temporary_files() finds tmp_ (-1: not registered)
};

/// A temporary file name that remove_temporary_files() knows of: removed by the destructor
/// (unless release()d) or by an interrupt handler, whichever comes first.
class TemporaryPath {
 public:
  explicit TemporaryPath(std::filesystem::path path);
  TemporaryPath(const TemporaryPath&) = delete;
  TemporaryPath& operator=(const TemporaryPath&) = delete;
  ~TemporaryPath();
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// The file was renamed away (or is kept): no longer remove it.
  void release();

 private:
  std::filesystem::path path_;
  int slot_ = -1;
};

/// Write `text` to `path` atomically.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

/// One CSV column as the sidecar declares it. `unit`: SI symbol ("m", "s", "rad", "N", "N m",
/// "J", "kg", "m/s", ...), "1" for a dimensionless number, "" for text. `type`: a Table
/// Schema type: "number", "integer" or "string". `parameters`: values that the column is
/// taken at when the header is a family (e.g. {"mu", 0.1}), written as the field's
/// "nanopush:parameters" object.
struct Column {
  std::string name, unit, description;
  std::string type = "number";
  std::map<std::string, double> parameters = {};
};
using Columns = std::vector<Column>;

/// Shorthands: a text column and a count column.
inline Column text_column(std::string name, std::string description) {
  return {std::move(name), "", std::move(description), "string"};
}
inline Column count_column(std::string name, std::string description) {
  return {std::move(name), "1", std::move(description), "integer"};
}

/// The process-wide provenance that every sidecar records. main() sets the program's
/// version and command line; whoever loads a scene sets it (a writer may name its own).
struct Provenance {
  std::string version;  ///< NANOPUSH_VERSION
  std::string command;  ///< argv joined by spaces (arguments with blanks quoted)
  std::string scene;    ///< scene name or path, "" if none
};
void set_provenance(std::string version, std::string command);
void set_provenance_scene(std::string scene);
const Provenance& provenance();
/// argv joined into one line: arguments with spaces or quotes are single-quoted.
std::string join_command_line(int argc, const char* const* argv);

/// The sidecar of a CSV: FILE.csv -> FILE.schema.json (any other name: NAME.schema.json).
std::filesystem::path schema_path(const std::filesystem::path& csv);
/// One value of a sidecar's "run" record: text, a real number (null when not finite), a whole
/// number, a truth value, or an object of named texts (a sweep's plan record). The sidecar is
/// written by nlohmann-json from these values.
class RunValue {
 public:
  using Object = std::vector<std::pair<std::string, std::string>>;
  using Value = std::variant<std::string, double, long long, unsigned long long, bool, Object>;
  RunValue(std::string v) : v_(std::move(v)) {}
  RunValue(const char* v) : v_(std::string(v)) {}
  RunValue(double v) : v_(v) {}
  RunValue(bool v) : v_(v) {}
  RunValue(Object v) : v_(std::move(v)) {}
  template <class I, std::enable_if_t<std::is_integral_v<I> && !std::is_same_v<I, bool>, int> = 0>
  RunValue(I v) : v_(std::is_signed_v<I> ? Value(static_cast<long long>(v)) : Value(static_cast<unsigned long long>(v))) {}
  [[nodiscard]] const Value& value() const { return v_; }

 private:
  Value v_;
};
/// What a run measured about itself (timings, counts), recorded in the sidecar's
/// "nanopush"."run" object and never in the table: name and value, in order.
using RunInfo = std::vector<std::pair<std::string, RunValue>>;

/// The Table Schema JSON for `columns` (with provenance; `scene` overrides the context's).
std::string table_schema_json(const Columns& columns, const std::string& scene = {}, const RunInfo& run = {});

/// A CSV file and its sidecar, both written atomically: rows go to a temporary file; commit()
/// writes the schema to its own temporary, then renames the CSV and then the schema into
/// place (the sidecar never appears without its CSV). Without commit() nothing appears.
class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& path, Columns columns, std::string scene = {});
  /// Row of numbers (csv_number each; NaN becomes the empty cell).
  void row(const std::vector<double>& values);
  /// Row with a leading text cell (e.g. an engine or material name).
  void row(const std::string& label, const std::vector<double>& values);
  /// Row of cells already formatted (csv_number, csv_text, "" for missing).
  void cells(const std::vector<std::string>& cells);
  /// A row already joined: cells as formatted, separated by commas, no line end (a streamed
  /// table's row; the caller keeps it to the columns).
  void line(const std::string& text);
  /// A blank line (gnuplot's scan separator in grid files; readers skip it).
  void blank_line();
  void commit();
  [[nodiscard]] const Columns& columns() const { return columns_; }
  /// Timings and counts for the sidecar (RunInfo), set before commit().
  void run_info(RunInfo info) { run_ = std::move(info); }

 private:
  void check_width(std::size_t n) const;
  AtomicFile file_;
  Columns columns_;
  std::string scene_;
  RunInfo run_;
  std::string line_;  ///< row()'s buffer, kept between rows
};

/// Write a complete CSV (header from `columns`, then `rows` of formatted cells) and its sidecar.
void write_csv_atomic(const std::filesystem::path& path, const Columns& columns,
                      const std::vector<std::vector<std::string>>& rows, const std::string& scene = {},
                      const RunInfo& run = {});

/// The CSV text (header and rows, no sidecar), e.g. for standard output.
std::string csv_document(const Columns& columns, const std::vector<std::vector<std::string>>& rows);

/// Format a double for CSV/reports: the shortest decimal that reads back (strtod) to the same
/// double (std::to_chars), e.g. 3e-08, 0.1, -0, 1e+300; integral values up to 2^53 in plain
/// digits (100000, not 1e+05); "inf"/"-inf" for infinities; NaN
/// (a missing value) is the empty string.
std::string csv_number(double v);
/// csv_number's characters written at `first` (room for kCsvNumberChars); returns the end.
char* csv_number_to(char* first, double v);
inline constexpr std::size_t kCsvNumberChars = 32;  ///< the longest csv_number (24) and room

/// Quote a text cell when it needs it (comma, quote, newline or leading/trailing blank).
std::string csv_quote(const std::string& s);


}  // namespace nanopush
