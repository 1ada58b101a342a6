// Joining shard tables (job arrays) into the table of the whole plan, one row at a time.
#include <algorithm>
#include <optional>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/input_file.hpp"
#include "nanopush/outputs/json.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {

namespace {

bool known_status(const std::string& s) {
  for (const char* k : {"ok", "at_rest", "no_static_friction", "law_blowup", "accuracy_not_reached",
                        "solver_failure", "bad_input", "error"})
    if (s == k) return true;
  return false;
}

/// What a shard's sidecar says of its sweep: the plan's identity and size, the shard i/n, its
/// rows; the whole sidecar (merge writes it back with the run record of the whole).
struct ShardRecord {
  std::string plan, task;
  json sidecar;
  PlanRecord record;  ///< the sidecar's plan_record (empty in sidecars of older versions)
  std::uint64_t plan_points = 0, rows = 0, index = 0, count = 1;
};

ShardRecord read_shard_sidecar(const std::filesystem::path& table) {
  const auto side = schema_path(table);
  if (!input_exists(side))
    throw InputError("--merge", table.string(),
                     "has no sidecar " + side.string() +
                         ": merge checks each shard's plan and size there; copy it with the table");
  ShardRecord r;
  try {
    r.sidecar = json::parse(read_input_file(side, "--merge sidecar", kMaxSidecarBytes));
  } catch (const json::exception& e) {  // parse_error, and out_of_range for a number past double's range
    throw InputError("--merge", side.string(), std::string("not JSON (") + e.what() + "): not the sidecar of a sweep shard");
  }
  const json* run = nullptr;
  if (r.sidecar.is_object() && r.sidecar.contains("nanopush") && r.sidecar["nanopush"].is_object() &&
      r.sidecar["nanopush"].contains("run") && r.sidecar["nanopush"]["run"].is_object())
    run = &r.sidecar["nanopush"]["run"];
  if (!run) throw InputError("--merge", side.string(), "no run record: not the sidecar of a sweep shard");
  const std::string where = side.string() + " (nanopush.run)";
  auto need = [&](const char* name) -> const json& {
    if (!run->contains(name))
      throw InputError("--merge", where,
                       std::string("no \"") + name + "\" in the run record: not the sidecar of a sweep shard (or "
                       "one written before merge checked plans: run that shard again)");
    return (*run)[name];
  };
  auto text = [&](const char* name) {
    const json& v = need(name);
    if (!v.is_string())
      throw InputError("--merge", where, std::string(name) + " = " + v.dump().substr(0, 40) + ": must be text");
    return v.get<std::string>();
  };
  auto count = [&](const char* name, std::uint64_t max) {
    const json& v = need(name);
    if (!v.is_number_unsigned() || v.get<std::uint64_t>() > max)
      throw InputError("--merge", where,
                       std::string(name) + " = " + v.dump().substr(0, 40) + ": must be a whole number in [0, " +
                           std::to_string(max) + "]");
    return v.get<std::uint64_t>();
  };
  r.plan = text("plan");
  r.task = text("task");
  r.plan_points = count("plan_points", kMaxPlanPoints);
  r.rows = count("rows", kMaxPlanPoints);
  const std::string shard = text("shard");
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
  // The plan record, field by field (to name what differs between shards of two sweeps).
  if (run->contains("plan_record") && (*run)["plan_record"].is_object())
    for (const auto& [k, v] : (*run)["plan_record"].items())
      if (v.is_string()) r.record.emplace_back(k, v.get<std::string>());
  return r;
}

/// Every table a shard of one sweep (one plan, one split), each shard once and none missing:
/// shard index -> position in `shards`.
std::map<std::uint64_t, std::size_t> shard_set(const std::vector<std::filesystem::path>& shards,
                                               const std::vector<ShardRecord>& rec) {
  std::map<std::uint64_t, std::size_t> shard_of;  // shard index -> position in `shards`
  const ShardRecord& first = rec.front();
  for (std::size_t k = 0; k < shards.size(); ++k) {
    const ShardRecord& r = rec[k];
    const std::string diff =
        r.record.empty() || first.record.empty() ? std::string() : plan_difference(r.record, first.record);
    if (r.plan != first.plan || r.plan_points != first.plan_points || r.task != first.task || !diff.empty())
      throw InputError("--merge", shards[k].string(),
                       "is a shard of another sweep than " + shards.front().string() + " (" +
                           (diff.empty() ? std::string("its plan differs: scene, values, task or options") : diff) +
                           "): merge the shards of one sweep");
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
  return shard_of;
}

/// What pass 1 learnt: the header every shard shares, and how many rows failed.
struct Checked {
  std::string header;
  std::size_t failed = 0;
};

/// Pass 1, each shard alone, one row at a time: the header, every row whole with a known
/// status, its points those of its shard in increasing order, as many as its sidecar says;
/// and every point of the plan in some shard.
Checked check_rows(const std::vector<std::filesystem::path>& shards, const std::vector<ShardRecord>& rec) {
  const ShardRecord& first = rec.front();
  std::string header;
  std::size_t columns = 0, status_col = 0;
  std::size_t failed = 0;
  std::uint64_t missing = first.plan_points;  // the smallest point no shard has
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
    bool complete = true, gap = false;
    std::uint64_t next = rec[k].index;  // the point this shard's next row should be
    std::optional<std::uint64_t> prev;
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
      if (prev && *i == *prev) throw InputError("--merge", where, "point " + idx + " appears twice");
      if (prev && *i < *prev)
        throw InputError("--merge", where,
                         "point " + idx + " comes after point " + std::to_string(*prev) +
                             ": a sweep writes its rows in point order (the table was edited)");
      prev = *i;
      if (!gap && *i != next) {
        gap = true;  // `next` is missing from this shard
        missing = std::min(missing, next);
      }
      next = *i + rec[k].count;
      if (row_failed(cells)) ++failed;
      ++rows;
    }
    if (rows != rec[k].rows)
      throw InputError("--merge", path.string(),
                       "has " + std::to_string(rows) + " rows; its sidecar says " + std::to_string(rec[k].rows) +
                           " (the table is cut short or edited)");
    if (!gap && next < first.plan_points) missing = std::min(missing, next);
  }
  // Every point 0 .. n-1 exactly once (a shard cut short leaves a gap).
  if (missing < first.plan_points)
    throw InputError("--merge", "point " + std::to_string(missing),
                     "is in no shard: the plan has " + std::to_string(first.plan_points) +
                         " points; give every shard's complete table");
  return {header, failed};
}

/// Pass 2: the rows in point order, point i from shard i mod n, each shard read once through,
/// into `out`; beside it the first shard's sidecar with the run record of the whole.
void join_rows(const std::vector<std::filesystem::path>& shards, const std::vector<ShardRecord>& rec,
               const std::map<std::uint64_t, std::size_t>& shard_of, const Checked& checked,
               const std::filesystem::path& out) {
  const ShardRecord& first = rec.front();
  const std::string& header = checked.header;
  const std::size_t failed = checked.failed;
  std::vector<std::unique_ptr<InputFile>> in;
  std::vector<std::size_t> lineno(first.count, 1);
  for (std::uint64_t s = 0; s < first.count; ++s) {
    const auto& path = shards[shard_of.at(s)];
    in.push_back(std::make_unique<InputFile>(path, "--merge", kMaxTableBytes));
    std::string skip;
    (void)read_line(in.back()->stream(), skip, "--merge", path.string(), 1);
  }
  AtomicFile table(out);
  std::ostream& os = table.stream();
  os << header << "\n";
  std::string line;
  for (std::uint64_t i = 0; i < first.plan_points; ++i) {
    const std::uint64_t s = i % first.count;
    const auto& path = shards[shard_of.at(s)];
    do {
      if (!read_line(in[s]->stream(), line, "--merge", path.string(), ++lineno[s]))
        throw InputError("--merge", path.string(), "changed while being merged");
    } while (line.empty());
    os << line << "\n";
  }
  // The first shard's sidecar with the run record of the whole (its timings were the shard's).
  json merged = first.sidecar;
  json run = {{"task", first.task},
              {"plan", first.plan},
              {"plan_points", first.plan_points},
              {"shard", "merged from " + std::to_string(shards.size())},
              {"rows", first.plan_points},
              {"failed", failed}};
  if (!first.record.empty()) {
    json record = json::object();
    for (const auto& [k, v] : first.record) record[k] = v;
    run["plan_record"] = std::move(record);
  }
  merged["nanopush"]["run"] = std::move(run);
  const std::string schema = json_text(merged);
  // A device or a descriptor (written through) gets the table only, as standard output does.
  const bool through = table.write_through();
  table.commit();
  if (!through) write_file_atomic(schema_path(out), schema);
}

}  // namespace

std::size_t merge_tables(const std::vector<std::filesystem::path>& shards, const std::filesystem::path& out) {
  if (shards.empty()) throw InputError("--merge", "(none)", "give the shard tables to join");
  // Each table a regular file (a FIFO or a device refused before anything is read), then the
  // sidecars.
  for (const auto& path : shards) InputFile check(path, "--merge", kMaxTableBytes);
  std::vector<ShardRecord> rec;
  for (const auto& path : shards) rec.push_back(read_shard_sidecar(path));
  const auto shard_of = shard_set(shards, rec);
  const Checked checked = check_rows(shards, rec);
  join_rows(shards, rec, shard_of, checked, out);
  return checked.failed;
}

}  // namespace nanopush::sweep
