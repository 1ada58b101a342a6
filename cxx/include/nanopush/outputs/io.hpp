// Output that is never lost and never half-written: every file goes to a temporary
// name in the same directory and is renamed over the target only when complete.
#pragma once
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace nanopush {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile();  // removes the temporary if commit() was never called

  std::ofstream& stream() { return out_; }
  [[nodiscard]] const std::filesystem::path& temp_path() const { return tmp_; }
  [[nodiscard]] const std::filesystem::path& target() const { return target_; }
  /// Flush, close and rename onto the target. Throws std::runtime_error on failure.
  void commit();

 private:
  std::filesystem::path target_, tmp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// Write `text` to `path` atomically.
void write_file_atomic(const std::filesystem::path& path, const std::string& text);

/// CSV writer over an AtomicFile: header once, rows of doubles at 17 significant digits.
class CsvWriter {
 public:
  CsvWriter(const std::filesystem::path& path, const std::vector<std::string>& header);
  void row(const std::vector<double>& values);
  /// Row with a leading text cell (e.g. an engine or material name).
  void row(const std::string& label, const std::vector<double>& values);
  void commit() { file_.commit(); }

 private:
  AtomicFile file_;
};

/// Format a double for CSV/reports: %.17g (round-trip exact).
std::string csv_number(double v);

}  // namespace nanopush
