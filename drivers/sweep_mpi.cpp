#include "sweep_mpi.hpp"
#include "registry.hpp"  // executable_dir(): nanopush-mpi beside nanopush
#include "sweep_output.hpp"

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iostream>
#include <list>
#include <optional>
#include <set>
#include <string>
#include <thread>

#include "nanopush/numerics/error.hpp"
#include "nanopush/outputs/input_file.hpp"

#ifdef NANOPUSH_HAVE_MPI
#include <sys/prctl.h>
#include <unistd.h>

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

int run_mpi_sweep(const sweep::Plan&, const sweep::Task&, const sweep::Options&, bool, const volatile std::sig_atomic_t*) {
  // The plain command line loads no MPI (drivers/CMakeLists.txt): its MPI twin runs the sweep.
  std::error_code ec;
  if (std::filesystem::is_regular_file(executable_dir() / kMpiProgram, ec))
    throw InputError("mpirun", "(several ranks)",
                     std::string("this nanopush is built without MPI, so that other commands start light: start the "
                                 "sweep with `mpirun -np R ") +
                         kMpiProgram + " sweep ...` (" + kMpiProgram +
                         ", beside nanopush, is the same command line with MPI)");
  throw InputError("mpirun", "(several ranks)",
                   std::string("this nanopush is built without MPI and no ") + kMpiProgram +
                       " is beside it (configure with NANOPUSH_MPI=ON and OpenMPI installed); use --shard i/n and "
                       "--merge for job arrays instead");
}

#else

namespace {

/// Worker rank -> rank 0: kRequest (int: points wanted; 0 when stopping, -N when this rank
/// stops on signal N, which stops every rank), kRow (a finished row), kDone (after its last
/// row: nothing more will come). Rank 0 -> worker: kWork (the point indices; none: no more
/// work), kStop (int N: stop, rank 0 or another rank had signal N), kFinal (int: the exit
/// status, after every kDone). Messages between two ranks arrive in order, so every row of a
/// rank is received before its kDone, and a kStop before the kFinal.
enum Tag : int { kRequest = 1, kWork = 2, kRow = 3, kDone = 4, kStop = 5, kFinal = 6 };

/// A kStop from rank 0 waiting to be received: receive it, true.
bool stop_from_rank0() {
  int flag = 0;
  MPI_Iprobe(0, kStop, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
  if (!flag) return false;
  int sig = 0;
  MPI_Recv(&sig, 1, MPI_INT, 0, kStop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

using std::chrono::microseconds;

/// How a rank waits for a message without a core: Open MPI's blocking calls (MPI_Recv,
/// MPI_Wait, MPI_Barrier) poll its shared-memory queues in a loop, so a rank waiting in one
/// burns a whole core (mpi_yield_when_idle only adds sched_yield to that loop: still 100 % of
/// an otherwise idle core). A waiting rank here looks (MPI_Iprobe) and sleeps, the sleep
/// doubling from `first` to `most` while nothing comes: an answer that comes at once is seen
/// within `first`, a long wait costs one look per `most` (docs/sweeps.md, "Benchmark").
class Backoff {
 public:
  Backoff(microseconds first, microseconds most) : first_(first), most_(most), next_(first) {}
  void reset() { next_ = first_; }
  /// The next sleep (then twice as long, up to `most`).
  microseconds next() {
    const microseconds d = next_;
    next_ = std::min(2 * next_, most_);
    return d;
  }
  void sleep() { std::this_thread::sleep_for(next()); }

 private:
  microseconds first_, most_, next_;
};

/// A message from rank 0 with `tag` (MPI_ANY_TAG: any), not yet received: its status. With
/// `wait`, looks and sleeps (backoff) until one comes; without, nothing when none is there.
std::optional<MPI_Status> from_rank0(int tag, Backoff& backoff, bool wait) {
  for (;;) {
    int flag = 0;
    MPI_Status st;
    MPI_Iprobe(0, tag, MPI_COMM_WORLD, &flag, &st);
    if (flag) return st;
    if (!wait) return std::nullopt;
    backoff.sleep();
  }
}

/// A worker rank after its kDone: wait for rank 0's kFinal (the exit status), which comes when
/// rank 0's last points are done (seconds, for a slow point), a late kStop received and dropped.
int final_status() {
  Backoff wait(microseconds(500), microseconds(20000));
  for (;;) {
    const MPI_Status st = *from_rank0(MPI_ANY_TAG, wait, true);
    int v = 0;
    MPI_Recv(&v, 1, MPI_INT, 0, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (st.MPI_TAG == kFinal) return v;
  }
}

/// The signal that stopped this rank (SIGINT if it was not recorded).
int signal_of(const volatile std::sig_atomic_t* sig) { return sig && *sig ? static_cast<int>(*sig) : SIGINT; }

/// Threads of one rank: take indices from `queue`, put finished rows into `outbox`.
struct LocalWork {
  std::mutex m;
  std::condition_variable cv;       // to the threads: work was added, or no more will be
  std::condition_variable done_cv;  // to the rank's main thread: a row is in the outbox
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
    {
      std::lock_guard<std::mutex> lock(w.m);
      --w.busy;
      if (!row.empty()) w.outbox.emplace_back(i, std::move(row));
    }
    w.done_cv.notify_one();
  }
}

/// How long the main thread of a rank sleeps between looks at MPI when no local row wakes it:
/// kPollFirst after a message (while points are handed out, requests come every few ms), then
/// twice as long while none comes, up to kPollMost (a rank 0 whose own thread computes a slow
/// point while the others are done). Its own core is shared with a worker thread (Open MPI
/// binds a rank to a core), so it must not spin: every look and wake-up is CPU the points do
/// not get.
constexpr microseconds kPollFirst(1000), kPollMost(4000);

/// Points a worker rank holds per thread (running and queued), asked for before its threads
/// run dry: a rank 0 that answers within kPollFirst (a worker's request follows its row, so
/// rank 0 is at its shortest sleep) then never leaves them idle, and at the end at most
/// kAhead - 1 points per thread wait behind a slow one. A single-threaded worker rank asks
/// again when half are left (one request per kAhead/2 points: at ~0.65 ms a point, faster than
/// rank 0's kPollFirst). Measured on the benchmark's grid (docs/sweeps.md): 2, 4 and 8 within
/// noise at a fixed 1 ms poll, a fixed 5 ms starves the threads.
constexpr int kAhead = 8;

/// Sleep until a local row is ready or `most` passes.
void wait_for_rows(LocalWork& w, microseconds most) {
  std::unique_lock<std::mutex> lock(w.m);
  w.done_cv.wait_for(lock, most, [&] { return !w.outbox.empty() || w.failure; });
}

unsigned threads_per_rank(unsigned asked) {
  if (asked) return asked;
  unsigned local = 1;
  if (const char* s = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE")) local = std::max(1, std::atoi(s));
  return std::max(1u, std::thread::hardware_concurrency() / local);
}

/// A worker rank's messages to rank 0, sent without blocking. Open MPI's MPI_Send of even a
/// small (eager) message spins in its progress loop until rank 0's own progress hands back a
/// send fragment, and rank 0 sleeps between its looks at MPI (kPollFirst..kPollMost): with
/// blocking sends a worker rank spent ~20 % of its CPU inside MPI_Send (perf, bench-sweep's
/// grid at 2 ranks). Each message keeps its buffer until MPI_Test says it is sent; messages to
/// one rank keep their order (MPI's non-overtaking rule holds for MPI_Isend as for MPI_Send).
class ToRank0 {
 public:
  ToRank0() = default;
  ToRank0(const ToRank0&) = delete;
  ToRank0& operator=(const ToRank0&) = delete;
  /// Normally drained already. Left by an exception (the job then ends in MPI_Abort), the
  /// messages still in flight keep their buffers: the list's nodes move to the heap, never freed.
  ~ToRank0() {
    if (!sent_.empty()) new std::list<Message>(std::move(sent_));
  }

  void row(std::size_t i, const std::vector<std::string>& cells) {
    post(std::to_string(i) + "\n" + sweep::join_cells(cells), MPI_CHAR, kRow);
  }
  void request(int want) { post(std::string(reinterpret_cast<const char*>(&want), sizeof want), MPI_INT, kRequest); }
  /// kDone carries the rank's CPU time [s], for the sidecar's cpu_s.
  void done() {
    const double cpu = sweep::process_cpu_seconds();
    post(std::string(reinterpret_cast<const char*>(&cpu), sizeof cpu), MPI_DOUBLE, kDone);
  }
  /// Forget the messages already sent.
  void progress() {
    std::erase_if(sent_, [](Message& m) {
      int flag = 0;
      MPI_Test(&m.req, &flag, MPI_STATUS_IGNORE);
      return flag != 0;
    });
  }
  /// Until every message is sent (looks and sleeps, never a blocking call).
  void drain() {
    Backoff wait(microseconds(50), microseconds(4000));
    for (progress(); !sent_.empty(); progress()) wait.sleep();
  }

 private:
  struct Message {
    std::string buf;
    MPI_Request req = MPI_REQUEST_NULL;
  };
  void post(std::string bytes, MPI_Datatype type, int tag) {
    progress();
    Message& m = sent_.emplace_back(Message{std::move(bytes)});  // std::list: the buffer stays put
    int size = 1;
    MPI_Type_size(type, &size);
    MPI_Isend(m.buf.data(), static_cast<int>(m.buf.size()) / size, type, 0, tag, MPI_COMM_WORLD, &m.req);
  }
  std::list<Message> sent_;
};

/// Open MPI on one node: its shared-memory path (pml ob1 with btl vader) starts in ~0.03 s where
/// the UCX pml that Debian's Open MPI prefers takes ~0.2 s per launch (measured with
/// `mpirun -np 2` on a 2-core host), a tenth of a 1,000-point sweep. So when every rank runs
/// on this node and the user chose no pml (OMPI_MCA_pml or `--mca pml`, which mpirun passes as
/// OMPI_MCA_pml), choose ob1. Every rank sees the same variables and decides alike. Across
/// nodes nothing is changed: there UCX is the fast transport.
void prefer_shared_memory_on_one_node() {
  const char* size = std::getenv("OMPI_COMM_WORLD_SIZE");
  const char* local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (!size || !local || std::string(size) != local) return;
  if (std::getenv("OMPI_MCA_pml")) return;
  ::setenv("OMPI_MCA_pml", "ob1", 0);
}

/// MPI_Init opens every component of every framework it may need (dlopen and symbol lookup:
/// most of a rank's ~30 ms of start-up CPU). The sweep uses point-to-point messages only:
/// no collective, no one-sided window, no reduction; so unless the user chose otherwise
/// (OMPI_MCA_x, or mpirun --mca x, which mpirun passes as OMPI_MCA_x), only the collective
/// components every communicator needs are opened (self, basic, libnbc), one one-sided
/// component (sm) and no AVX reduction ops.
void open_only_what_the_sweep_uses() {
  ::setenv("OMPI_MCA_coll", "self,basic,libnbc", 0);
  ::setenv("OMPI_MCA_osc", "sm", 0);
  ::setenv("OMPI_MCA_op", "^avx", 0);
}

/// The answer to a request sent to rank 0: the point indices (none: no more work), or nothing
/// yet. With `wait`, sleeps (Backoff) until it comes: never a blocking MPI call, which would
/// spin on a core another rank may need.
std::optional<std::vector<long long>> work_reply(bool wait) {
  Backoff backoff(microseconds(50), kPollMost);
  const std::optional<MPI_Status> st = from_rank0(kWork, backoff, wait);
  if (!st) return std::nullopt;
  int n = 0;
  MPI_Get_count(&*st, MPI_LONG_LONG, &n);
  std::vector<long long> got(static_cast<std::size_t>(n));
  MPI_Recv(got.data(), n, MPI_LONG_LONG, 0, kWork, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return got;
}

/// A worker rank of one thread: the main thread evaluates the points itself and talks to rank 0
/// between them (its next points asked for ahead), so no second thread shares its core.
void serve_on_main_thread(const sweep::Plan& plan, const sweep::Task& task, const std::atomic<bool>* stop,
                          const volatile std::sig_atomic_t* sig) {
  std::deque<std::size_t> queue;
  ToRank0 to0;
  bool finished = false, asked = false, remote = false;
  for (;;) {
    if (!remote) remote = stop_from_rank0();
    const bool local = stop && stop->load();
    const bool stopping = local || remote;
    if (stopping) queue.clear();  // not started: a resumed sweep computes them
    if (!finished && !asked) {
      // Refilled by half a batch at a time: one request per kAhead/2 points, not one per point.
      const int held = static_cast<int>(queue.size());
      const int want = stopping ? (local ? -signal_of(sig) : 0) : (held <= kAhead / 2 ? kAhead - held : 0);
      if (want > 0 || stopping) {
        to0.request(want);
        asked = true;
      }
    }
    if (asked) {
      if (auto got = work_reply(queue.empty())) {
        asked = false;
        if (got->empty()) finished = true;
        for (long long i : *got) queue.push_back(static_cast<std::size_t>(i));
      }
    }
    if (queue.empty()) {
      if (finished) break;
      continue;
    }
    const std::size_t i = queue.front();
    queue.pop_front();
    to0.row(i, sweep::evaluate_row(plan, task, i));
  }
  to0.done();
  to0.drain();
}

/// An error on a rank (a journal of another sweep, a table that cannot be written, a bug) ends
/// every rank: said as the command line says it (docs/errors.md), then MPI_Abort with the
/// status, so no rank waits for ever on one that is gone.
[[noreturn]] void abort_job(std::exception_ptr e) {
  int code = 70;
  try {
    std::rethrow_exception(e);
  } catch (const InputError& x) {
    std::cerr << "nanopush: error: " << x.what() << "\n";
    code = 2;
  } catch (const SolverError& x) {
    std::cerr << "nanopush: solver failure: " << x.what() << "\n";
    code = 3;
  } catch (const std::logic_error& x) {
    std::cerr << "nanopush: internal error (a bug: please report it with the command line): " << x.what() << "\n";
  } catch (const std::exception& x) {
    std::cerr << "nanopush: system error: " << x.what() << "\n";
    code = 5;
  } catch (...) {
    std::cerr << "nanopush: internal error (a bug: please report it with the command line)\n";
  }
  std::cerr.flush();
  MPI_Abort(MPI_COMM_WORLD, code);
  std::_Exit(code);
}

/// A worker rank's loop over its threads (serve_with_threads): rows out to rank 0 as they
/// finish, kAhead points per thread asked for before they run dry (one request in flight),
/// until rank 0 has no more work.
void feed_threads(LocalWork& w, std::atomic<bool>& stop_all, unsigned jobs, const std::atomic<bool>* stop,
                  const volatile std::sig_atomic_t* sig) {
  ToRank0 to0;
  bool finished = false, asked = false, remote = false;
  Backoff poll(kPollFirst, kPollMost);
  while (true) {
    if (!remote) remote = stop_from_rank0();
    const bool local = stop && stop->load();
    const bool stopping = local || remote;
    if (stopping) stop_all = true;
    std::vector<std::pair<std::size_t, std::vector<std::string>>> out;
    int want = 0;
    {
      std::lock_guard<std::mutex> lock(w.m);
      out.swap(w.outbox);
      if (w.failure) std::rethrow_exception(w.failure);
      if (stopping) w.queue.clear();  // not started: a resumed sweep computes them
      want = kAhead * static_cast<int>(jobs) - static_cast<int>(w.queue.size()) - static_cast<int>(w.busy);
    }
    if (stopping) w.cv.notify_all();
    for (const auto& [i, r] : out) to0.row(i, r);
    to0.progress();
    if (!finished && !asked && (want > 0 || stopping)) {
      if (stopping) want = local ? -signal_of(sig) : 0;
      to0.request(want);
      asked = true;
    }
    if (asked) {
      if (auto got = work_reply(false)) {
        asked = false;
        {
          std::lock_guard<std::mutex> lock(w.m);
          if (got->empty()) {
            finished = true;
            w.no_more = true;
          }
          for (long long i : *got) w.queue.push_back(static_cast<std::size_t>(i));
        }
        w.cv.notify_all();
        poll.reset();
        continue;
      }
    }
    {
      std::lock_guard<std::mutex> lock(w.m);
      if (finished && w.queue.empty() && w.busy == 0 && w.outbox.empty()) break;
    }
    wait_for_rows(w, poll.next());
  }
  to0.done();
  to0.drain();
}

/// A worker rank of several threads. An error ends the job here (abort_job never returns), so
/// the threads never outlive their work.
void serve_with_threads(const sweep::Plan& plan, const sweep::Task& task, unsigned jobs, const std::atomic<bool>* stop,
                        const volatile std::sig_atomic_t* sig) {
  LocalWork w;
  std::vector<std::thread> threads;
  std::atomic<bool> stop_all{false};
  try {
    for (unsigned t = 0; t < jobs; ++t)
      threads.emplace_back(worker, std::ref(w), std::cref(plan), std::cref(task), &stop_all);
    feed_threads(w, stop_all, jobs, stop, sig);
  } catch (...) {
    abort_job(std::current_exception());
  }
  w.cv.notify_all();
  for (auto& t : threads) t.join();
}

/// Rank 0: the journal, the ordered table, the next point to hand out to its own threads and
/// to the worker ranks, and the stop; run() returns the exit status.
class Coordinator {
 public:
  Coordinator(const sweep::Plan& plan, const sweep::Task& task, const sweep::Options& o, unsigned jobs, int size,
              const volatile std::sig_atomic_t* sig)
      : plan_(plan), task_(task), o_(o), jobs_(jobs), size_(size), sig_(sig),
        record_((void(sweep::table_columns(plan, task)), sweep::plan_record(plan, task, o.fixed))),
        journal_path_(sweep::journal_path(o.out)),  // a directory or a FIFO: refused here
        table_(o.out, plan, task, o.shard_index, o.shard_count, o.row_sink, o.window),
        journal_(journal_path_, sweep::sweep_identity(plan, task, o.shard_index, o.shard_count), journal_record(),
                 [this](std::size_t i, std::string line) { resume_row(i, std::move(line)); }) {}

  /// An error ends the job here (abort_job never returns), so the threads never outlive their
  /// work.
  int run(std::chrono::steady_clock::time_point start, bool quiet) {
    try {
      // Rank 0's own threads draw from the same positions, a few at a time; a stop (this
      // rank's signal, or one a worker rank reports) ends them after their points in flight.
      for (unsigned t = 0; t < jobs_; ++t)
        threads_.emplace_back(worker, std::ref(w_), std::cref(plan_), std::cref(task_), &stop_all_);
      loop();
      {
        std::lock_guard<std::mutex> lock(w_.m);
        w_.no_more = true;
      }
      w_.cv.notify_all();
      for (auto& t : threads_) t.join();
      threads_.clear();
      return finish(start, quiet);
    } catch (...) {
      abort_job(std::current_exception());
    }
  }

 private:
  sweep::PlanRecord journal_record() const {
    sweep::PlanRecord jrec = record_;
    jrec.emplace_back("shard", std::to_string(o_.shard_index) + "/" + std::to_string(o_.shard_count));
    return jrec;
  }

  /// A row of the journal: into the table as it is read (few wait: docs/sweeps.md, "Memory").
  void resume_row(std::size_t i, std::string line) {
    if (i >= plan_.size() || i % o_.shard_count != o_.shard_index || table_.has((i - o_.shard_index) / o_.shard_count))
      return;
    const bool failed = sweep::row_failed(sweep::split_cells(line));
    table_.add(i, std::move(line), failed);
    ++resumed_;
  }

  /// The next point that may start (within the table's window), or nullopt.
  std::optional<std::size_t> take() {
    while (next_ < table_.positions() && table_.has(next_)) ++next_;
    if (next_ >= table_.positions() || !table_.may_start(next_)) return std::nullopt;
    return table_.index_of(next_++);
  }
  bool all_handed_out() {
    while (next_ < table_.positions() && table_.has(next_)) ++next_;
    return next_ >= table_.positions();
  }
  void add_row(std::size_t i, std::string line) {
    journal_.append_line(i, line);
    const bool failed = sweep::row_failed(sweep::split_cells(line));
    table_.add(i, std::move(line), failed);
  }

  /// Up to `want` points to rank `dest` (none: no more work); false to wait for the window.
  bool answer(int dest, int want) {
    std::vector<long long> give;
    while (!stop_sig_ && static_cast<int>(give.size()) < want)
      if (auto i = take()) give.push_back(static_cast<long long>(*i));
      else break;
    if (want > 0 && give.empty() && !stop_sig_ && !all_handed_out()) return false;
    MPI_Send(give.data(), static_cast<int>(give.size()), MPI_LONG_LONG, dest, kWork, MPI_COMM_WORLD);
    return true;
  }

  void loop() {
    auto last = std::chrono::steady_clock::now();
    Backoff poll(kPollFirst, kPollMost);
    while (true) {
      if (!stop_sig_ && o_.stop && o_.stop->load()) stop_sig_ = signal_of(sig_);
      if (stop_sig_ && !told_) tell_stop();
      feed_local_threads();
      while (!asks_.empty() && answer(asks_.front().first, asks_.front().second)) asks_.pop_front();
      int flag = 0;
      MPI_Status st;
      MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st);
      if (flag) {
        receive(st);
        poll.reset();  // another message may follow at once
        continue;
      }
      if (done_ranks_ == size_ - 1 && local_idle() && (all_handed_out() || stop_sig_)) break;
      if (o_.progress && std::chrono::steady_clock::now() - last > std::chrono::milliseconds(500)) {
        last = std::chrono::steady_clock::now();
        o_.progress(table_.done(), table_.positions());
      }
      wait_for_rows(w_, poll.next());
    }
  }

  void tell_stop() {
    stop_all_ = true;
    for (int r = 1; r < size_; ++r) MPI_Send(&stop_sig_, 1, MPI_INT, r, kStop, MPI_COMM_WORLD);
    told_ = true;
  }

  /// The local threads' rows into the table; their queue refilled (cleared when stopping).
  void feed_local_threads() {
    std::vector<std::pair<std::size_t, std::vector<std::string>>> out;
    {
      std::lock_guard<std::mutex> lock(w_.m);
      out.swap(w_.outbox);
      if (w_.failure) std::rethrow_exception(w_.failure);
    }
    for (auto& [i, r] : out) add_row(i, sweep::join_cells(r));
    {
      std::lock_guard<std::mutex> lock(w_.m);
      if (stop_sig_) w_.queue.clear();  // not started: a resumed sweep computes them
      while (!stop_sig_ && w_.queue.size() < jobs_)
        if (auto i = take()) w_.queue.push_back(*i);
        else break;
      if (all_handed_out() || stop_sig_) w_.no_more = true;
    }
    w_.cv.notify_all();
  }

  /// One message from a worker rank: a request, a row, or its last word.
  void receive(const MPI_Status& st) {
    if (st.MPI_TAG == kRequest) {
      int want = 0;
      MPI_Recv(&want, 1, MPI_INT, st.MPI_SOURCE, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (want < 0 && !stop_sig_) stop_sig_ = -want;  // a worker rank's signal stops every rank
      if (!answer(st.MPI_SOURCE, want)) asks_.emplace_back(st.MPI_SOURCE, want);
    } else if (st.MPI_TAG == kRow) {
      int len = 0;
      MPI_Get_count(&st, MPI_CHAR, &len);
      std::string msg(static_cast<std::size_t>(len), '\0');
      MPI_Recv(msg.data(), len, MPI_CHAR, st.MPI_SOURCE, kRow, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const auto nl = msg.find('\n');
      const auto i =
          nl == std::string::npos ? std::nullopt : parse_count(std::string_view(msg).substr(0, nl), plan_.size() - 1);
      if (!i) throw std::logic_error("a row from rank " + std::to_string(st.MPI_SOURCE) + " without its point index");
      add_row(*i, msg.substr(nl + 1));
    } else if (st.MPI_TAG == kDone) {
      double cpu = 0;
      MPI_Recv(&cpu, 1, MPI_DOUBLE, st.MPI_SOURCE, kDone, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      worker_cpu_ += cpu;
      ++done_ranks_;
    }
  }

  bool local_idle() {
    std::lock_guard<std::mutex> lock(w_.m);
    return w_.queue.empty() && w_.busy == 0 && w_.outbox.empty();
  }

  /// The table committed (or the interrupt said): the exit status.
  int finish(std::chrono::steady_clock::time_point start, bool quiet) {
    if (!table_.complete()) {
      std::cerr << "sweep: interrupted: " << table_.done() << " of " << table_.positions() << " points are in "
                << journal_.path().string() << "; run the same command again to resume\n";
      return 128 + (stop_sig_ ? stop_sig_ : SIGINT);
    }
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - start;
    const double cpu = sweep::process_cpu_seconds() + worker_cpu_;  // every rank, start to end
    table_.commit(sweep::sweep_timings(wall.count(), jobs_, size_, resumed_, cpu), record_);
    journal_.remove();
    const std::size_t failed = table_.failed();
    if (!quiet)
      std::cerr << "sweep: " << table_.positions() << " points (" << resumed_ << " from the journal) over " << size_
                << " MPI ranks x " << jobs_ << " threads, " << failed << " failed: " << o_.out.string() << "\n";
    return sweep_exit_status(failed);
  }

  const sweep::Plan& plan_;
  const sweep::Task& task_;
  const sweep::Options& o_;
  const unsigned jobs_;
  const int size_;
  const volatile std::sig_atomic_t* sig_;
  const sweep::PlanRecord record_;
  const std::filesystem::path journal_path_;
  sweep::OrderedTable table_;
  std::size_t resumed_ = 0;  // declared before journal_: the journal's rows count into it
  sweep::Journal journal_;
  LocalWork w_;
  std::vector<std::thread> threads_;
  std::atomic<bool> stop_all_{false};
  std::size_t next_ = 0;                   // the next shard position to hand out
  int done_ranks_ = 0;                     // worker ranks that sent kDone (all their rows are in)
  int stop_sig_ = 0;                       // the signal that stops the sweep (here or on a worker rank)
  bool told_ = false;                      // the worker ranks were sent kStop
  double worker_cpu_ = 0;                  // the worker ranks' CPU time [s]
  std::deque<std::pair<int, int>> asks_;  // requests waiting for the window to move: (rank, points)
};

}  // namespace

int run_mpi_sweep(const sweep::Plan& plan, const sweep::Task& task, const sweep::Options& o, bool quiet,
                  const volatile std::sig_atomic_t* sig) {
  const auto start = std::chrono::steady_clock::now();
  prefer_shared_memory_on_one_node();
  open_only_what_the_sweep_uses();
  // mpirun (or its daemon) is this rank's parent: when it dies, even by SIGKILL, the rank gets
  // SIGTERM and stops as on any SIGTERM, instead of computing on as an orphan.
  const pid_t parent = ::getppid();
  ::prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (::getppid() != parent) std::raise(SIGTERM);
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const unsigned jobs = threads_per_rank(o.jobs);
  int status = 0;
  if (rank == 0) {
    try {
      Coordinator c(plan, task, o, jobs, size, sig);
      status = c.run(start, quiet);
    } catch (...) {
      abort_job(std::current_exception());
    }
    // Every worker rank has sent kDone: tell each the status it exits with.
    for (int r = 1; r < size; ++r) MPI_Send(&status, 1, MPI_INT, r, kFinal, MPI_COMM_WORLD);
  } else {
    try {
      if (jobs == 1) serve_on_main_thread(plan, task, o.stop, sig);
      else serve_with_threads(plan, task, jobs, o.stop, sig);
    } catch (...) {
      abort_job(std::current_exception());
    }
    status = final_status();
  }
  MPI_Finalize();
  return status;
}

#endif

}  // namespace nanopush::cli
