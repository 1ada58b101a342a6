#include "sweep_mpi.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdlib>
#include <deque>
#include <iostream>
#include <set>
#include <thread>

#include "nanopush/numerics/error.hpp"

#ifdef NANOPUSH_HAVE_MPI
#include <mpi.h>
#endif

namespace nanopush::cli {

bool mpi_launched() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    const char* s = std::getenv(v);
    if (s && std::atoi(s) > 1) return true;
  }
  return false;
}

#ifndef NANOPUSH_HAVE_MPI

int run_mpi_sweep(const sweep::Plan&, const sweep::Task&, const sweep::Options&, bool) {
  throw InputError("mpirun", "(several ranks)",
                   "this nanopush was built without MPI (configure with NANOPUSH_MPI=ON and OpenMPI installed); use "
                   "--shard i/n and --merge for job arrays instead");
}

#else

namespace {

enum Tag : int { kRequest = 1, kWork = 2, kRow = 3 };

/// Threads of one rank: take indices from `queue`, put finished rows into `outbox`.
struct LocalWork {
  std::mutex m;
  std::condition_variable cv;
  std::deque<std::size_t> queue;
  std::vector<std::pair<std::size_t, std::vector<std::string>>> outbox;
  bool no_more = false;  // no index will be added any more
  unsigned busy = 0;     // threads evaluating a point
  std::exception_ptr failure;
};

void worker(LocalWork& w, const sweep::Plan& plan, const sweep::Task& task, const std::atomic<bool>* stop) {
  for (;;) {
    std::size_t i;
    {
      std::unique_lock<std::mutex> lock(w.m);
      w.cv.wait(lock, [&] { return !w.queue.empty() || w.no_more || (stop && stop->load()); });
      if ((stop && stop->load()) || w.queue.empty()) return;
      i = w.queue.front();
      w.queue.pop_front();
      ++w.busy;
    }
    std::vector<std::string> row;
    try {
      row = sweep::evaluate_row(plan, task, i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(w.m);
      if (!w.failure) w.failure = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(w.m);
    --w.busy;
    if (!row.empty()) w.outbox.emplace_back(i, std::move(row));
  }
}

unsigned threads_per_rank(unsigned asked) {
  if (asked) return asked;
  unsigned local = 1;
  if (const char* s = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE")) local = std::max(1, std::atoi(s));
  return std::max(1u, std::thread::hardware_concurrency() / local);
}

void send_row(std::size_t i, const std::vector<std::string>& row) {
  std::string msg = std::to_string(i) + "\n" + sweep::join_cells(row);
  MPI_Send(msg.data(), static_cast<int>(msg.size()), MPI_CHAR, 0, kRow, MPI_COMM_WORLD);
}

}  // namespace

int run_mpi_sweep(const sweep::Plan& plan, const sweep::Task& task, const sweep::Options& o, bool quiet) {
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const unsigned jobs = threads_per_rank(o.jobs);
  LocalWork w;
  std::vector<std::thread> threads;
  int status = 0;

  if (rank == 0) {
    // The coordinator: journal, the list of pending points, the rows.
    const auto pts = sweep::shard_points(plan.size(), o.shard_index, o.shard_count);
    (void)sweep::table_columns(plan, task);
    sweep::Journal journal(o.out.string() + ".journal",
                           sweep::sweep_identity(plan, task, o.shard_index, o.shard_count));
    std::map<std::size_t, std::vector<std::string>> rows;
    const std::set<std::size_t> mine(pts.begin(), pts.end());
    for (const auto& [i, r] : journal.resumed())
      if (mine.count(i)) rows[i] = r;
    std::deque<std::size_t> pending;
    for (std::size_t i : pts)
      if (!rows.count(i)) pending.push_back(i);
    const std::size_t resumed = rows.size();
    // Rank 0's own threads draw from the same pending list, a few at a time.
    for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(worker, std::ref(w), std::cref(plan), std::cref(task), o.stop);
    int done_ranks = 0;  // workers told there is no more work
    auto last = std::chrono::steady_clock::now();
    while (true) {
      const bool stopping = o.stop && o.stop->load();
      {  // feed local threads and collect their rows
        std::lock_guard<std::mutex> lock(w.m);
        while (!stopping && w.queue.size() < jobs && !pending.empty()) {
          w.queue.push_back(pending.front());
          pending.pop_front();
        }
        if (pending.empty() || stopping) w.no_more = true;
        for (auto& [i, r] : w.outbox) {
          journal.append(i, r);
          rows[i] = std::move(r);
        }
        w.outbox.clear();
        if (w.failure) std::rethrow_exception(w.failure);
      }
      w.cv.notify_all();
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      if (flag) {
        if (st.MPI_TAG == kRequest) {
          int want = 0;
          MPI_Recv(&want, 1, MPI_INT, st.MPI_SOURCE, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          std::vector<long long> give;
          while (!stopping && static_cast<int>(give.size()) < want && !pending.empty()) {
            give.push_back(static_cast<long long>(pending.front()));
            pending.pop_front();
          }
          if (give.empty()) ++done_ranks;  // an empty answer: no more work for that rank
          MPI_Send(give.data(), static_cast<int>(give.size()), MPI_LONG_LONG, st.MPI_SOURCE, kWork, MPI_COMM_WORLD);
        } else if (st.MPI_TAG == kRow) {
          int len = 0;
          MPI_Get_count(&st, MPI_CHAR, &len);
          std::string msg(static_cast<std::size_t>(len), '\0');
          MPI_Recv(msg.data(), len, MPI_CHAR, st.MPI_SOURCE, kRow, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          const auto nl = msg.find('\n');
          const std::size_t i = std::stoull(msg.substr(0, nl));
          auto row = sweep::split_cells(msg.substr(nl + 1));
          journal.append(i, row);
          rows[i] = std::move(row);
        }
        continue;
      }
      bool local_idle;
      {
        std::lock_guard<std::mutex> lock(w.m);
        local_idle = w.queue.empty() && w.busy == 0 && w.outbox.empty();
      }
      if (done_ranks == size - 1 && local_idle && (pending.empty() || stopping)) break;
      if (o.progress && std::chrono::steady_clock::now() - last > std::chrono::milliseconds(500)) {
        last = std::chrono::steady_clock::now();
        o.progress(rows.size(), pts.size());
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    {
      std::lock_guard<std::mutex> lock(w.m);
      w.no_more = true;
    }
    w.cv.notify_all();
    for (auto& t : threads) t.join();
    std::size_t failed = 0;
    for (const auto& [i, r] : rows) failed += sweep::row_failed(r) ? 1 : 0;
    if (rows.size() < pts.size()) {
      std::cerr << "sweep: interrupted: " << rows.size() << " of " << pts.size() << " points are in "
                << journal.path().string() << "; run the same command again to resume\n";
      status = 130;
    } else {
      sweep::write_table(o.out, plan, task, rows, o.shard_index, o.shard_count);
      journal.remove();
      if (!quiet)
        std::cerr << "sweep: " << pts.size() << " points (" << resumed << " from the journal) over " << size
                  << " MPI ranks x " << jobs << " threads, " << failed << " failed: " << o.out.string() << "\n";
      status = failed ? 64 + static_cast<int>(std::min<std::size_t>(failed, 63)) : 0;
    }
  } else {
    // A worker rank: keep its threads supplied, send rows back as they finish.
    for (unsigned t = 0; t < jobs; ++t) threads.emplace_back(worker, std::ref(w), std::cref(plan), std::cref(task), o.stop);
    bool finished = false;
    while (true) {
      const bool stopping = o.stop && o.stop->load();
      std::vector<std::pair<std::size_t, std::vector<std::string>>> out;
      int want = 0;
      {
        std::lock_guard<std::mutex> lock(w.m);
        out.swap(w.outbox);
        if (w.failure) std::rethrow_exception(w.failure);
        want = static_cast<int>(jobs) - static_cast<int>(w.queue.size()) - static_cast<int>(w.busy);
      }
      for (const auto& [i, r] : out) send_row(i, r);
      if (!finished && (want > 0 || stopping)) {
        if (stopping) want = 0;
        MPI_Send(&want, 1, MPI_INT, 0, kRequest, MPI_COMM_WORLD);
        MPI_Status st;
        MPI_Probe(0, kWork, MPI_COMM_WORLD, &st);
        int n = 0;
        MPI_Get_count(&st, MPI_LONG_LONG, &n);
        std::vector<long long> got(static_cast<std::size_t>(n));
        MPI_Recv(got.data(), n, MPI_LONG_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        std::lock_guard<std::mutex> lock(w.m);
        if (n == 0) {
          finished = true;
          w.no_more = true;
        }
        for (long long i : got) w.queue.push_back(static_cast<std::size_t>(i));
        w.cv.notify_all();
        continue;
      }
      {
        std::lock_guard<std::mutex> lock(w.m);
        if (finished && w.queue.empty() && w.busy == 0 && w.outbox.empty()) break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
    w.cv.notify_all();
    for (auto& t : threads) t.join();
  }
  MPI_Bcast(&status, 1, MPI_INT, 0, MPI_COMM_WORLD);
  MPI_Finalize();
  return rank == 0 ? status : 0;
}

#endif

}  // namespace nanopush::cli
