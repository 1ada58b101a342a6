// Running a sweep on threads: the journal (resume), the work queue, the ordered table; and
// joining shard tables.
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <chrono>
#include <cinttypes>
#include <cerrno>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <thread>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {
namespace {

constexpr const char* kJournalMagic = "nanopush-sweep-journal 1";

std::uint64_t fnv1a(std::string_view s) {
  std::uint64_t h = 1469598103934665603ULL;
  for (unsigned char c : s) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  return h;
}

std::string hex(std::uint64_t v) {
  char b[17];
  std::snprintf(b, sizeof b, "%016" PRIx64, v);
  return b;
}

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

Journal::Journal(std::filesystem::path path, const std::string& identity) : path_(std::move(path)) {
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
    if (!next_line() || !ended || overlong || line != header)
      throw InputError("journal", path_.string(),
                       "belongs to a different sweep (scene, axes, task, options or shard differ): remove it to "
                       "start this sweep afresh");
    complete = bytes;
    // Records: "index<TAB>checksum<TAB>row\n"; keep only complete records that match (any other
    // line is skipped, and its point computed again).
    while (next_line()) {
      if (!ended) break;  // a record cut short by a kill
      complete = bytes;
      if (overlong) continue;
      const auto t1 = line.find('\t'), t2 = t1 == std::string::npos ? t1 : line.find('\t', t1 + 1);
      if (t2 == std::string::npos) continue;
      const std::string sum = line.substr(t1 + 1, t2 - t1 - 1), row = line.substr(t2 + 1);
      const auto index = parse_count(std::string_view(line).substr(0, t1), kMaxPlanPoints - 1);
      if (!index) continue;  // not a point index of any plan (text, or out of range)
      if (sum != hex(fnv1a(record_text(*index, row)))) continue;
      resumed_[*index] = split_cells(row);
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
    const std::string h = header + "\n";
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

void Journal::append(std::size_t index, const std::vector<std::string>& row) {
  const std::string line = join_cells(row);
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
  std::ostringstream s;
  s << task.identity() << "\nshard " << shard_index << "/" << shard_count << "\nkeys";
  for (const auto& k : plan.keys) s << " " << k;
  s << "\npoints " << plan.size() << "\n";
  for (const auto& pt : plan.points) {
    for (const auto& v : pt) s << v.to_string() << ",";
    s << "\n";
  }
  return s.str();
}

// ---- tables --------------------------------------------------------------------------------

void write_table(const std::filesystem::path& out, const Plan& plan, const Task& task,
                 const std::map<std::size_t, std::vector<std::string>>& rows, std::size_t shard_index,
                 std::size_t shard_count, const RunInfo& timings) {
  std::vector<std::vector<std::string>> ordered;
  ordered.reserve(rows.size());
  std::size_t failed = 0;
  for (const auto& [i, r] : rows) {
    ordered.push_back(r);
    failed += row_failed(r) ? 1 : 0;
  }
  RunInfo run = {{"task", json_string(task.name())},
                 {"plan", json_string(plan_identity(plan, task))},
                 {"plan_points", std::to_string(plan.size())},
                 {"shard", json_string(std::to_string(shard_index) + "/" + std::to_string(shard_count))},
                 {"rows", std::to_string(rows.size())},
                 {"failed", std::to_string(failed)}};
  run.insert(run.end(), timings.begin(), timings.end());
  write_csv_atomic(out, table_columns(plan, task), ordered, task.scene_name(), run);
}

RunInfo sweep_timings(double wall_s, unsigned threads, int ranks, std::size_t resumed) {
  return {{"wall_s", csv_number(wall_s)},
          {"threads", std::to_string(threads)},
          {"ranks", std::to_string(ranks)},
          {"resumed", std::to_string(resumed)}};
}

namespace {

/// The value of `"name": ` on a sidecar's run line: a JSON string's text or a bare number's
/// digits; nullopt when absent.
std::optional<std::string> run_field(const std::string& line, const std::string& name) {
  const std::string key = "\"" + name + "\": ";
  const auto at = line.find(key);
  if (at == std::string::npos) return std::nullopt;
  std::size_t p = at + key.size();
  if (p < line.size() && line[p] == '"') {
    const auto end = line.find('"', p + 1);
    if (end == std::string::npos) return std::nullopt;
    return line.substr(p + 1, end - p - 1);
  }
  const auto end = line.find_first_of(",}", p);
  return line.substr(p, end == std::string::npos ? std::string::npos : end - p);
}

bool known_status(const std::string& s) {
  for (const char* k : {"ok", "at_rest", "no_static_friction", "law_blowup", "accuracy_not_reached",
                        "solver_failure", "bad_input", "error"})
    if (s == k) return true;
  return false;
}

/// What a shard's sidecar says of its sweep: the plan's identity and size, the shard i/n, its
/// rows; the sidecar's text with the run line marked (merge writes it back as the whole's).
struct ShardRecord {
  std::string plan, task, schema_before, schema_after;
  std::uint64_t plan_points = 0, rows = 0, index = 0, count = 1;
};

ShardRecord read_shard_sidecar(const std::filesystem::path& table) {
  const auto side = schema_path(table);
  if (!input_exists(side))
    throw InputError("--merge", table.string(),
                     "has no sidecar " + side.string() +
                         ": merge checks each shard's plan and size there; copy it with the table");
  InputFile file(side, "--merge sidecar", kMaxSidecarBytes);
  ShardRecord r;
  std::string line;
  std::size_t lineno = 0;
  bool seen = false;
  while (read_line(file.stream(), line, "--merge sidecar", side.string(), ++lineno)) {
    const auto at = line.find("\"run\": {");
    if (at == std::string::npos || seen) {
      (seen ? r.schema_after : r.schema_before) += line + "\n";
      continue;
    }
    seen = true;
    r.schema_before += line.substr(0, at);
    const std::string where = side.string() + ":" + std::to_string(lineno);
    auto need = [&](const char* name) {
      auto v = run_field(line, name);
      if (!v)
        throw InputError("--merge", where,
                         std::string("no \"") + name + "\" in the run record: not the sidecar of a sweep shard (or "
                         "one written before merge checked plans: run that shard again)");
      return *v;
    };
    auto count = [&](const char* name, std::uint64_t max) {
      const std::string v = need(name);
      const auto n = parse_count(v, max);
      if (!n)
        throw InputError("--merge", where,
                         std::string(name) + " = " + v.substr(0, 40) + ": must be a whole number in [0, " +
                             std::to_string(max) + "]");
      return *n;
    };
    r.plan = need("plan");
    r.task = need("task");
    r.plan_points = count("plan_points", kMaxPlanPoints);
    r.rows = count("rows", kMaxPlanPoints);
    const std::string shard = need("shard");
    if (shard.rfind("merged from ", 0) == 0) {
      r.index = 0;
      r.count = 1;
    } else {
      const auto slash = shard.find('/');
      const auto i = parse_count(shard.substr(0, slash), 99999), n = slash == std::string::npos
                                                                          ? std::nullopt
                                                                          : parse_count(shard.substr(slash + 1), 100000);
      if (!i || !n || *n == 0 || *i >= *n)
        throw InputError("--merge", where, "shard = " + shard.substr(0, 40) + ": must be i/n with 0 <= i < n <= 100000");
      r.index = *i;
      r.count = *n;
    }
  }
  if (!seen) throw InputError("--merge", side.string(), "no run record: not the sidecar of a sweep shard");
  return r;
}

}  // namespace

std::string plan_identity(const Plan& plan, const Task& task) { return hex(fnv1a(sweep_identity(plan, task, 0, 1))); }

std::size_t merge_tables(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out) {
  if (shards.empty()) throw InputError("--merge", "(none)", "give the shard tables to join");
  // Each table a regular file (a FIFO or a device refused before anything is read), then the
  // sidecars: every table a shard of one sweep (one plan), each shard once.
  for (const auto& path : shards) InputFile check(path, "--merge", kMaxTableBytes);
  std::vector<ShardRecord> rec;
  for (const auto& path : shards) rec.push_back(read_shard_sidecar(path));
  const ShardRecord& first = rec.front();
  std::map<std::uint64_t, std::size_t> shard_of;  // shard index -> position in `shards`
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const ShardRecord& r = rec[k];
    if (r.plan != first.plan || r.plan_points != first.plan_points || r.task != first.task)
      throw InputError("--merge", shards[k].string(),
                       "is a shard of another sweep than " + shards.front().string() +
                           " (its plan differs: scene, values, task or options): merge the shards of one sweep");
    if (r.count != first.count)
      throw InputError("--merge", shards[k].string(),
                       "is shard " + std::to_string(r.index) + "/" + std::to_string(r.count) + ", " +
                           shards.front().string() + " one of " + std::to_string(first.count) +
                           ": merge the shards of one split");
    if (!shard_of.emplace(r.index, k).second)
      throw InputError("--merge", shards[k].string(),
                       "is shard " + std::to_string(r.index) + "/" + std::to_string(r.count) + " as " +
                           shards[shard_of[r.index]].string() + " is: give each shard once");
  }
  for (std::uint64_t i = 0; i < first.count; ++i)
    if (!shard_of.count(i))
      throw InputError("--merge", "shard " + std::to_string(i) + "/" + std::to_string(first.count),
                       "is missing: give every shard's table (the plan has " + std::to_string(first.plan_points) +
                           " points)");
  std::string header;
  std::size_t columns = 0, status_col = 0;
  std::map<std::size_t, std::string> lines;
  std::size_t failed = 0;
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const auto& path = shards[k];
    InputFile file(path, "--merge", kMaxTableBytes);  // a regular file (never a FIFO or a device)
    std::string h, line;
    std::size_t lineno = 1, rows = 0;
    if (!read_line(file.stream(), h, "--merge", path.string(), lineno))
      throw InputError("--merge", path.string(), "empty file");
    if (header.empty()) {
      header = h;
      const auto cols = split_cells(h);
      columns = cols.size();
      if (cols.size() < 3 || cols.front() != "point" || cols[cols.size() - 2] != "status" || cols.back() != "message")
        throw InputError("--merge", path.string() + ":1", "not a sweep table: its columns are point, ..., status, message");
      status_col = cols.size() - 2;
    }
    if (h != header)
      throw InputError("--merge", path.string(), "its columns differ from " + shards.front().string() + "'s");
    bool complete = true;
    while (read_line(file.stream(), line, "--merge", path.string(), ++lineno, kMaxInputLine, &complete)) {
      const std::string where = path.string() + ":" + std::to_string(lineno);
      if (!complete) throw InputError("--merge", where, "the last row is cut short (no line end): the table is incomplete");
      if (line.empty()) continue;
      const auto cells = split_cells(line);
      if (cells.size() != columns)
        throw InputError("--merge", where,
                         "a row of " + std::to_string(cells.size()) + " cells; the header has " +
                             std::to_string(columns) + " (a row cut short or edited)");
      const std::string& idx = cells.front();
      const auto i = parse_count(idx, kMaxPlanPoints - 1);
      if (!i)
        throw InputError("--merge", where,
                         "point index = " + idx.substr(0, 40) + (idx.size() > 40 ? "..." : "") +
                             ": must be a whole number in [0, " + std::to_string(kMaxPlanPoints - 1) + "]");
      if (*i >= first.plan_points || *i % rec[k].count != rec[k].index)
        throw InputError("--merge", where,
                         "point " + idx + " is not a point of shard " + std::to_string(rec[k].index) + "/" +
                             std::to_string(rec[k].count) + " of a " + std::to_string(first.plan_points) +
                             "-point plan");
      if (!known_status(cells[status_col]))
        throw InputError("--merge", where,
                         "status = " + cells[status_col].substr(0, 40) +
                             ": not a status of a sweep row (ok, at_rest, ..., error; docs/errors.md)");
      if (!lines.emplace(*i, line).second)
        throw InputError("--merge", where, "point " + idx + " appears twice");
      if (row_failed(cells)) ++failed;
      ++rows;
    }
    if (rows != rec[k].rows)
      throw InputError("--merge", path.string(),
                       "has " + std::to_string(rows) + " rows; its sidecar says " + std::to_string(rec[k].rows) +
                           " (the table is cut short or edited)");
  }
  // Every point 0 .. n-1 exactly once (a shard cut short leaves a gap).
  std::size_t expect = 0;
  for (const auto& [i, l] : lines) {
    if (i != expect) break;
    ++expect;
  }
  if (expect != first.plan_points)
    throw InputError("--merge", "point " + std::to_string(expect),
                     "is in no shard: the plan has " + std::to_string(first.plan_points) +
                         " points; give every shard's complete table");
  const std::string schema = first.schema_before + "\"run\": {\"task\": " + json_string(first.task) +
                             ", \"plan\": " + json_string(first.plan) +
                             ", \"plan_points\": " + std::to_string(lines.size()) + ", \"shard\": \"merged from " +
                             std::to_string(shards.size()) + "\", \"rows\": " + std::to_string(lines.size()) +
                             ", \"failed\": " + std::to_string(failed) + "},\n" + first.schema_after;
  std::string text = header + "\n";
  for (const auto& [i, l] : lines) text += l + "\n";
  write_file_atomic(out, text);
  // A device or a descriptor (written through) gets the table only, as standard output does.
  if (!resolve_output(out).write_through) write_file_atomic(schema_path(out), schema);
  return failed;
}

// ---- threads -------------------------------------------------------------------------------

std::vector<std::vector<std::string>> evaluate_points(const Plan& plan, const Task& task, unsigned jobs) {
  (void)table_columns(plan, task);  // every varied key is the task's, before any work
  std::vector<std::vector<std::string>> rows(plan.size());
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(plan.size(), 1)));
  std::atomic<std::size_t> next{0};
  std::mutex mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    try {
      for (;;) {
        const std::size_t k = next.fetch_add(1);
        if (k >= rows.size()) break;
        rows[k] = evaluate_row(plan, task, k);  // each slot written by one thread only
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
      next = rows.size();  // stop taking points
    }
  };
  if (jobs <= 1) {
    worker();
  } else {
    std::vector<std::thread> threads;
    for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
  }
  if (failure) std::rethrow_exception(failure);
  return rows;
}

std::size_t column_index(const Plan& plan, const Task& task, const std::string& name) {
  const Columns cols = table_columns(plan, task);
  for (std::size_t i = 0; i < cols.size(); ++i)
    if (cols[i].name == name) return i;
  throw InputError("column", name, "not a column of --task " + task.name());
}

double cell_number(const std::string& cell) {
  if (cell.empty()) return std::numeric_limits<double>::quiet_NaN();
  double v = 0;
  const auto r = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (r.ec != std::errc() || r.ptr != cell.data() + cell.size())
    throw InputError("cell", cell, "must be a number");
  return v;
}

Result run_local(const Plan& plan, const Task& task, const Options& o) {
  const auto start = std::chrono::steady_clock::now();
  if (o.shard_count == 0 || o.shard_index >= o.shard_count)
    throw InputError("--shard", std::to_string(o.shard_index) + "/" + std::to_string(o.shard_count),
                     "must be i/n with 0 <= i < n");
  (void)table_columns(plan, task);  // every varied key is the task's, before any work
  const auto pts = shard_points(plan.size(), o.shard_index, o.shard_count);
  // journal_path: a directory or a FIFO as --out is refused before any point (exit 5).
  Journal journal(journal_path(o.out), sweep_identity(plan, task, o.shard_index, o.shard_count));
  std::map<std::size_t, std::vector<std::string>> rows;
  std::vector<std::size_t> pending;
  const std::set<std::size_t> mine(pts.begin(), pts.end());
  for (const auto& [i, r] : journal.resumed())
    if (mine.count(i)) rows[i] = r;
  for (std::size_t i : pts)
    if (!rows.count(i)) pending.push_back(i);
  Result res;
  res.points = pts.size();
  res.resumed = rows.size();

  unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(pending.size(), 1)));
  std::atomic<std::size_t> next{0}, done{rows.size()};
  std::atomic<unsigned> running{jobs};
  std::mutex mutex;
  std::exception_ptr failure;
  auto worker = [&] {
    try {
      while (!(o.stop && o.stop->load())) {
        const std::size_t k = next.fetch_add(1);
        if (k >= pending.size()) break;
        auto row = evaluate_row(plan, task, pending[k]);
        journal.append(pending[k], row);
        std::lock_guard<std::mutex> lock(mutex);
        rows[pending[k]] = std::move(row);
        ++done;
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
    }
    --running;
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(worker);
  auto last = std::chrono::steady_clock::now();
  while (running.load() > 0) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (o.progress && std::chrono::steady_clock::now() - last > std::chrono::milliseconds(500)) {
      last = std::chrono::steady_clock::now();
      o.progress(done.load(), pts.size());
    }
  }
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  if (o.progress) o.progress(done.load(), pts.size());
  res.done = rows.size();
  for (const auto& [i, r] : rows) res.failed += row_failed(r) ? 1 : 0;
  if (rows.size() < pts.size()) return res;  // stopped: the journal keeps what was done
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  write_table(o.out, plan, task, rows, o.shard_index, o.shard_count,
              sweep_timings(wall.count(), jobs, 1, res.resumed));
  journal.remove();
  res.complete = true;
  return res;
}

}  // namespace nanopush::sweep
