// A --points file read by index (points_table.hpp).
#include "points_table.hpp"

#include <charconv>

#include "hash.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/scenes/scene_keys.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {

SceneValue point_value(const std::string& key, const std::string& text) {
  if (find_scene_key(key)) return SceneValue::from_text(key, text);
  double v = 0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) return text;
  require_finite(key, v);  // NaN would read as "not given" to a task
  return v;
}

PointTable::PointTable(const std::filesystem::path& path, std::vector<std::string>& keys) : path_(path) {
  // Through the guarded reader: a regular file of at most 4 GiB (never a FIFO or /dev/zero).
  // Checked there, then read through a seekable stream (the checkpoints are byte offsets).
  { InputFile check(path, "--points", kMaxTableBytes); }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--points", path.string(), "cannot be read");
  // One record at a time (RFC 4180: quoted keys and values, CRLF, a byte order mark; blank
  // lines skipped), so the file is never held whole.
  csv::Reader reader(in, "--points " + path.string());
  csv::Record rec;
  if (!reader.next(rec)) throw InputError("--points", path.string(), "empty file: the first line names the keys");
  keys = rec.fields;
  for (std::size_t j = 0; j < keys.size(); ++j) {
    if (keys[j].empty()) throw InputError("--points", path.string(), "an empty key in the header");
    for (std::size_t k = 0; k < j; ++k)
      if (keys[k] == keys[j])
        throw InputError("--points", path.string() + ":1",
                         "the key " + keys[j] + " is in the header twice (columns " + std::to_string(k + 1) +
                             " and " + std::to_string(j + 1) + "): a point gives each key one value");
  }
  keys_ = keys;
  hash_ = kFnvBasis;
  for (;;) {
    if (rows_ % kCheckpoint == 0) {
      const std::streamoff at = in.tellg();
      if (at < 0 && in.eof()) break;  // the last record ended the file
      checkpoints_.push_back(at);
      if (at < 0 || static_cast<std::uint64_t>(at) > kMaxTableBytes)
        throw InputError("--points", path.string(), "larger than " + byte_size_text(kMaxTableBytes) + " (or unreadable)");
    }
    if (!reader.next(rec)) break;
    const auto& cells = rec.fields;
    if (cells.size() != keys.size())
      throw InputError("--points", path.string() + ":" + std::to_string(rec.line),
                       "has " + std::to_string(cells.size()) + " cells; the header has " + std::to_string(keys.size()));
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const SceneValue v = point_value(keys[k], cells[k]);
      hash_ = fnv1a(v.to_string(), hash_);
      hash_ = fnv1a(k + 1 < cells.size() ? "," : "\n", hash_);
    }
    if (++rows_ > kMaxPlanPoints) throw InputError("--points", path.string(), "more than 100000000 points");
  }
  if (rows_ == 0) throw InputError("--points", path.string(), "no points after the header");
}

void PointTable::seek(std::size_t row) {
  in_.close();
  in_.clear();
  in_.open(path_, std::ios::binary);
  if (!in_) throw InputError("--points", path_.string(), "cannot be read again (removed during the sweep?)");
  in_.seekg(checkpoints_.at(row / kCheckpoint));
  reader_ = std::make_unique<csv::Reader>(in_, "--points " + path_.string());
  cursor_ = row / kCheckpoint * kCheckpoint;
}

std::vector<SceneValue> PointTable::row(std::size_t i) {
  if (i >= rows_) throw std::out_of_range("--points row " + std::to_string(i));
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& [k, v] : cache_)
    if (k == i) return v;
  if (!reader_ || i < cursor_ || i - cursor_ >= kCheckpoint) seek(i);
  csv::Record rec;
  for (;;) {
    if (!reader_->next(rec) || rec.fields.size() != keys_.size())
      throw InputError("--points", path_.string(), "changed during the sweep: row " + std::to_string(cursor_) + " differs");
    std::vector<SceneValue> v;
    v.reserve(keys_.size());
    for (std::size_t k = 0; k < keys_.size(); ++k) v.push_back(point_value(keys_[k], rec.fields[k]));
    cache_.emplace_back(cursor_, v);
    if (cache_.size() > 64) cache_.pop_front();
    if (cursor_++ == i) return v;
  }
}

}  // namespace nanopush::sweep
