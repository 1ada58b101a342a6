// A --points file read by index: one pass through at load (every row checked, counted and
// hashed, a checkpoint every kCheckpoint rows), then rows read back on demand near the last
// one read (a few cached), so nothing of the file's size is held.
#pragma once
#include <cstddef>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "nanopush/outputs/csv_reader.hpp"
#include "nanopush/scenes/scene.hpp"

namespace nanopush::sweep {

/// A cell of --points read as the value of `key` (the key's type for a scene key).
SceneValue point_value(const std::string& key, const std::string& text);

class PointTable {
 public:
  static constexpr std::size_t kCheckpoint = 1024;
  /// Read `path` through once; `keys` gets the header. InputError for a bad file.
  PointTable(const std::filesystem::path& path, std::vector<std::string>& keys);
  [[nodiscard]] std::size_t size() const { return rows_; }
  /// The FNV-1a hash of every value (as text), in order: the plan's identity.
  [[nodiscard]] std::uint64_t hash() const { return hash_; }
  /// The values of row i (thread-safe).
  [[nodiscard]] std::vector<SceneValue> row(std::size_t i);

 private:
  void seek(std::size_t row);  // position the reader before `row`'s record (a checkpoint's multiple)
  std::filesystem::path path_;
  std::vector<std::string> keys_;
  std::size_t rows_ = 0;
  std::uint64_t hash_ = 0;
  std::vector<std::streamoff> checkpoints_;  ///< byte offset of row k * kCheckpoint
  std::mutex mutex_;
  std::ifstream in_;
  std::unique_ptr<csv::Reader> reader_;
  std::size_t cursor_ = 0;  ///< the row the reader reads next
  std::deque<std::pair<std::size_t, std::vector<SceneValue>>> cache_;  ///< the last rows read
};

}  // namespace nanopush::sweep
