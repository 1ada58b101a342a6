// Running a sweep: the ordered table (rows written in point order as they complete, within a
// bounded window), the threads of one process, the sidecar's timings.
#include <sys/resource.h>

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <limits>
#include <optional>
#include <thread>

#include "hash.hpp"
#include "nanopush/numerics/error.hpp"
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::sweep {

// ---- the ordered table ---------------------------------------------------------------------

struct OrderedTable::Impl {
  std::optional<CsvWriter> csv;
  std::string task, plan_hash;
  std::size_t plan_points = 0;
};

OrderedTable::OrderedTable(const std::filesystem::path& out, const Plan& plan, const Task& task,
                           std::size_t shard_index, std::size_t shard_count, Sink sink, std::size_t window)
    : impl_(std::make_unique<Impl>()),
      index_(shard_index),
      count_(shard_count),
      positions_(plan.size() > shard_index ? (plan.size() - shard_index + shard_count - 1) / shard_count : 0),
      window_(std::max<std::size_t>(window, 1)),
      sink_(std::move(sink)) {
  impl_->task = task.name();
  impl_->plan_hash = plan_identity(plan, task);
  impl_->plan_points = plan.size();
  if (!out.empty()) impl_->csv.emplace(out, table_columns(plan, task, false), task.scene_name());
}

OrderedTable::~OrderedTable() = default;

void OrderedTable::add(std::size_t index, std::string line, bool failed) {
  const std::size_t pos = (index - index_) / count_;
  if (pos < written_ || !waiting_.emplace(pos, std::make_pair(std::move(line), failed)).second) return;  // twice
  for (auto it = waiting_.begin(); it != waiting_.end() && it->first == written_; it = waiting_.erase(it)) {
    if (impl_->csv) impl_->csv->line(it->second.first);
    if (sink_) sink_(index_of(written_), it->second.first);
    failed_ += it->second.second ? 1 : 0;
    ++written_;
  }
}

void OrderedTable::commit(const RunInfo& timings, const PlanRecord& record) {
  if (!complete()) throw std::logic_error("OrderedTable::commit before every row was written");
  if (!impl_->csv) return;
  RunInfo run = {{"task", impl_->task},
                 {"plan", impl_->plan_hash},
                 {"plan_points", impl_->plan_points},
                 {"shard", std::to_string(index_) + "/" + std::to_string(count_)},
                 {"rows", written_},
                 {"failed", failed_}};
  run.insert(run.end(), timings.begin(), timings.end());
  run.emplace_back("plan_record", RunValue::Object(record.begin(), record.end()));
  impl_->csv->run_info(run);
  impl_->csv->commit();
}

std::string plan_identity(const Plan& plan, const Task& task) { return hex(fnv1a(sweep_identity(plan, task, 0, 1))); }

RunInfo sweep_timings(double wall_s, unsigned threads, int ranks, std::size_t resumed, double cpu_s) {
  RunInfo r = {{"wall_s", wall_s}};
  if (cpu_s >= 0) r.emplace_back("cpu_s", cpu_s);
  r.emplace_back("threads", threads);
  r.emplace_back("ranks", ranks);
  r.emplace_back("resumed", resumed);
  return r;
}

double process_cpu_seconds() {
  rusage u{};
  if (::getrusage(RUSAGE_SELF, &u) != 0) return 0;
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// ---- threads -------------------------------------------------------------------------------

std::vector<std::vector<std::string>> evaluate_points(const Plan& plan, const Task& task, unsigned jobs) {
  (void)table_columns(plan, task);  // every varied key is the task's, before any work
  std::vector<std::vector<std::string>> rows(plan.size());  // in memory by request
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
  const double cpu0 = process_cpu_seconds();
  if (o.shard_count == 0 || o.shard_index >= o.shard_count)
    throw InputError("--shard", std::to_string(o.shard_index) + "/" + std::to_string(o.shard_count),
                     "must be i/n with 0 <= i < n");
  (void)table_columns(plan, task);  // every varied key and value is the task's, before any work
  const PlanRecord record = plan_record(plan, task, o.fixed);
  // journal_path: a directory or a FIFO as --out is refused before any point (exit 5).
  const auto out_path = o.out.empty() ? o.out : journal_path(o.out);  // a directory or FIFO: refused here
  OrderedTable table(o.out, plan, task, o.shard_index, o.shard_count, o.row_sink, o.window);
  Result res;
  res.points = table.positions();
  // The journal's rows go to the table as they are read: a sweep writes its rows in point order
  // within the window, so few wait, whatever the journal's length.
  std::optional<Journal> journal;
  if (!o.out.empty()) {
    PlanRecord jrec = record;
    jrec.emplace_back("shard", std::to_string(o.shard_index) + "/" + std::to_string(o.shard_count));
    journal.emplace(out_path, sweep_identity(plan, task, o.shard_index, o.shard_count), jrec,
                    [&](std::size_t i, std::string line) {
                      if (i >= plan.size() || i % o.shard_count != o.shard_index || table.has((i - o.shard_index) / o.shard_count))
                        return;
                      const bool failed = row_failed(split_cells(line));
                      table.add(i, std::move(line), failed);
                      ++res.resumed;
                    });
  }

  unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
  jobs = static_cast<unsigned>(std::min<std::size_t>(jobs, std::max<std::size_t>(res.points - res.resumed, 1)));
  std::mutex mutex;
  std::condition_variable cv;  // a row was written (the window moved), a thread ended, or a failure
  std::size_t next = 0;        // the next shard position to consider
  unsigned running = jobs;
  std::exception_ptr failure;
  auto stopped = [&] { return (o.stop && o.stop->load()) || failure; };
  auto worker = [&] {
    try {
      for (;;) {
        std::size_t pos = 0;
        {
          std::unique_lock<std::mutex> lock(mutex);
          for (;;) {
            while (next < table.positions() && table.has(next)) ++next;
            if (stopped() || next >= table.positions()) break;
            if (table.may_start(next)) break;
            cv.wait_for(lock, std::chrono::milliseconds(100));  // a slow point holds the window
          }
          if (stopped() || next >= table.positions()) break;
          pos = next++;
        }
        const std::size_t i = table.index_of(pos);
        const auto row = evaluate_row(plan, task, i);
        std::string line = join_cells(row);
        if (journal) journal->append_line(i, line);
        {
          std::lock_guard<std::mutex> lock(mutex);
          table.add(i, std::move(line), row_failed(row));
        }
        cv.notify_all();
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!failure) failure = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex);
      --running;
    }
    cv.notify_all();
  };
  std::vector<std::thread> threads;
  for (unsigned t = 0; t + 1 < jobs; ++t) threads.emplace_back(worker);
  if (o.progress) {
    // This thread reports progress when the work starts and then twice a second (not at each
    // finished point: a point's notification only ends the wait when the last worker is done).
    threads.emplace_back(worker);
    std::unique_lock<std::mutex> lock(mutex);
    auto report_at = std::chrono::steady_clock::now();
    while (running > 0) {
      if (cv.wait_until(lock, report_at, [&] { return running == 0; })) break;
      report_at += std::chrono::milliseconds(500);
      const std::size_t done = table.done();
      lock.unlock();
      o.progress(done, res.points);
      lock.lock();
    }
  } else {
    worker();  // this thread computes too
  }
  for (auto& t : threads) t.join();
  if (failure) std::rethrow_exception(failure);
  if (o.progress) o.progress(table.done(), res.points);
  res.done = table.done();
  res.failed = table.failed();
  if (!table.complete()) return res;  // stopped: the journal keeps what was done
  const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
  table.commit(sweep_timings(wall.count(), jobs, 1, res.resumed, process_cpu_seconds() - cpu0), record);
  if (journal) journal->remove();
  res.complete = true;
  return res;
}

}  // namespace nanopush::sweep
