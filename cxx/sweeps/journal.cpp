// The sweep's journal (a killed sweep resumes from it) and its identity: which sweep a
// journal, a shard table or a sidecar belongs to, recorded field by field.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <optional>

#include "hash.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {
namespace {

constexpr const char* kJournalMagic = "nanopush-sweep-journal 1";

std::string record_text(std::size_t index, const std::string& line) { return std::to_string(index) + "\t" + line; }

}  // namespace

std::string join_cells(const std::vector<std::string>& row) {
  std::string s;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (i) s += ',';
    s += row[i];
  }
  return s;
}

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') quoted = !quoted;
    if (c == ',' && !quoted) {
      out.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// ---- journal -------------------------------------------------------------------------------

namespace {

/// The journal's second line: "#plan" and TAB-separated NAME=VALUE fields.
std::string record_line(const PlanRecord& r) {
  std::string s = "#plan";
  for (const auto& [k, v] : r) {
    std::string f = k + "=" + v;
    for (char& c : f)
      if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    s += "\t" + f;
  }
  return s;
}

PlanRecord parse_record_line(const std::string& line) {
  PlanRecord r;
  if (line.rfind("#plan", 0) != 0) return r;
  std::size_t p = 5;
  while (p < line.size() && line[p] == '\t') {
    const auto end = std::min(line.find('\t', p + 1), line.size());
    const std::string f = line.substr(p + 1, end - p - 1);
    const auto eq = f.find('=');
    if (eq != std::string::npos) r.emplace_back(f.substr(0, eq), f.substr(eq + 1));
    p = end;
  }
  return r;
}

}  // namespace

PlanRecord plan_record(const Plan& plan, const Task& task, const std::vector<std::string>& fixed) {
  PlanRecord r = task.describe();
  std::string sets;
  for (const auto& f : fixed) sets += (sets.empty() ? "" : " ") + f;
  r.emplace_back("set", sets);
  for (auto& f : plan.describe()) r.push_back(std::move(f));
  r.emplace_back("version", provenance().version);
  return r;
}

std::string plan_difference(const PlanRecord& theirs, const PlanRecord& ours) {
  std::string out;
  int shown = 0;
  auto value = [](const PlanRecord& r, const std::string& k) -> std::optional<std::string> {
    for (const auto& [n, v] : r)
      if (n == k) return v;
    return std::nullopt;
  };
  auto note = [&](const std::string& k, const std::optional<std::string>& a, const std::optional<std::string>& b) {
    if (shown++ >= 3) return;
    auto text = [](const std::optional<std::string>& v) { return v ? (v->empty() ? std::string("(none)") : *v) : std::string("(absent)"); };
    out += (out.empty() ? "" : "; ") + k + ": " + text(a) + " there, " + text(b) + " here";
  };
  for (const auto& [k, v] : ours) {
    const auto t = value(theirs, k);
    if (!t || *t != v) note(k, t, v);
  }
  for (const auto& [k, v] : theirs)
    if (!value(ours, k)) note(k, v, std::nullopt);
  return out;
}

Journal::Journal(std::filesystem::path path, const std::string& identity, const PlanRecord& record,
                 const RowCallback& on_row)
    : path_(std::move(path)) {
  const std::string header = std::string(kJournalMagic) + " " + hex(fnv1a(identity));
  if (input_exists(path_)) {
    // Through the guarded reader (a regular file: a FIFO or a device is refused, never
    // opened), one record at a time.
    InputFile file(path_, "journal", kMaxJournalBytes);
    std::streambuf* sb = file.stream().rdbuf();
    // One line into `line` (at most kMaxInputLine bytes kept; a longer one is marked bad);
    // `bytes` counts what was consumed. False at the end; `ended` says whether it had its LF.
    std::uint64_t bytes = 0, complete = 0;
    std::string line;
    bool ended = false, overlong = false;
    auto next_line = [&]() {
      line.clear();
      ended = overlong = false;
      bool any = false;
      for (;;) {
        const auto c = sb->sbumpc();
        if (std::char_traits<char>::eq_int_type(c, std::char_traits<char>::eof())) break;
        any = true;
        ++bytes;
        const char ch = std::char_traits<char>::to_char_type(c);
        if (ch == '\n') {
          ended = true;
          break;
        }
        if (line.size() < kMaxInputLine) line.push_back(ch);
        else overlong = true;
      }
      return any;
    };
    const bool header_ok = next_line() && ended && !overlong && line == header;
    complete = bytes;
    // The plan record (second line; absent in journals of older versions) names what differs.
    bool have = next_line();
    std::string diff;
    if (have && ended && !overlong && line.rfind("#plan", 0) == 0) {
      if (!record.empty()) diff = plan_difference(parse_record_line(line), record);
      complete = bytes;
      have = next_line();
    }
    if (!header_ok || !diff.empty())
      throw InputError("journal", path_.string(),
                       "belongs to a different sweep (" +
                           (diff.empty() ? std::string("scene, axes, task, options or shard differ") : diff) +
                           "): remove it to start this sweep afresh");
    // Records: "index<TAB>checksum<TAB>row\n"; keep only complete records that match (any other
    // line is skipped, and its point computed again).
    for (; have; have = next_line()) {
      if (!ended) break;  // a record cut short by a kill
      complete = bytes;
      if (overlong) continue;
      const auto t1 = line.find('\t'), t2 = t1 == std::string::npos ? t1 : line.find('\t', t1 + 1);
      if (t2 == std::string::npos) continue;
      const std::string sum = line.substr(t1 + 1, t2 - t1 - 1);
      const auto index = parse_count(std::string_view(line).substr(0, t1), kMaxPlanPoints - 1);
      if (!index) continue;  // not a point index of any plan (text, or out of range)
      std::string row = line.substr(t2 + 1);
      if (sum != hex(fnv1a(record_text(*index, row)))) continue;
      if (on_row) on_row(*index, std::move(row));
      else resumed_[*index] = std::move(row);
    }
    const std::uint64_t size = bytes;
    fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
    if (fd_ < 0)
      throw OutputError("journal = " + path_.string() + ": cannot be opened for appending (" + std::strerror(errno) + ")");
    if (complete < size && ::ftruncate(fd_, static_cast<off_t>(complete)) != 0)
      throw InputError("journal", path_.string(), "cannot drop its incomplete last record");
  } else {
    fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
    // A journal that cannot be made (no such directory, /proc, a read-only file system) is a
    // system error (exit 5), said before any point runs.
    if (fd_ < 0) throw OutputError("output = " + path_.string() + ": the sweep's journal cannot be created (" + std::strerror(errno) + ")");
    const std::string h = header + "\n" + (record.empty() ? std::string() : record_line(record) + "\n");
    if (::write(fd_, h.data(), h.size()) != static_cast<ssize_t>(h.size())) {
      const std::string why = std::strerror(errno);
      ::close(fd_);
      fd_ = -1;
      std::error_code ec;
      std::filesystem::remove(path_, ec);
      throw OutputError("output = " + path_.string() + ": the sweep's journal cannot be written (" + why + ")");
    }
  }
}

Journal::~Journal() {
  if (fd_ >= 0) ::close(fd_);
}

void Journal::append(std::size_t index, const std::vector<std::string>& row) { append_line(index, join_cells(row)); }

void Journal::append_line(std::size_t index, const std::string& line) {
  const std::string rec = std::to_string(index) + "\t" + hex(fnv1a(record_text(index, line))) + "\t" + line + "\n";
  std::lock_guard<std::mutex> lock(mutex_);
  // One write per record: a kill leaves at most the last record incomplete (then ignored).
  const char* p = rec.data();
  std::size_t left = rec.size();
  while (left > 0) {
    const ssize_t w = ::write(fd_, p, left);
    if (w < 0) throw std::runtime_error("journal " + path_.string() + ": write failed");
    p += w;
    left -= static_cast<std::size_t>(w);
  }
}

void Journal::remove() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

std::filesystem::path journal_path(const std::filesystem::path& out) {
  if (resolve_output(out).write_through) return std::filesystem::path(out.filename().string() + ".journal");
  return std::filesystem::path(out.string() + ".journal");
}

std::string sweep_identity(const Plan& plan, const Task& task, std::size_t shard_index, std::size_t shard_count) {
  return task.identity() + "\nshard " + std::to_string(shard_index) + "/" + std::to_string(shard_count) + "\n" +
         plan.identity_text();
}

}  // namespace nanopush::sweep
