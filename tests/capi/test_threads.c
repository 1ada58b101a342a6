/* Two POSIX threads integrate different problems at the same time through the Fortran API
 * (`use nanopush`: a Fortran RHS with its context, the C++ Bulirsch-Stoer underneath), each
 * many times over, and every result must equal the sequential run bit for bit (same numbers,
 * same counts). Real concurrency: pthreads, not `do concurrent`. */
#include <pthread.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

int np_test_solve(int k, double* yout, int64_t* counts); /* tests/capi/threads_problem.f90 */

enum { kNout = 201, kMaxN = 4, kRepeats = 150 };

/* Both threads start together; `in_flight` counts solves under way, so `overlapped` counts the
 * solves that began while the other thread was inside one (evidence of real interleaving). */
static pthread_barrier_t start_line;
static atomic_int in_flight;
static const int kDim[3] = {0, 2, 4};

typedef struct {
  int problem;
  const double* reference;
  const int64_t* ref_counts;
  int mismatches, failures, overlapped;
} Job;

static void* worker(void* arg) {
  Job* job = (Job*)arg;
  double yout[kMaxN * kNout];
  int64_t counts[3];
  const size_t bytes = sizeof(double) * (size_t)(kDim[job->problem] * kNout);
  pthread_barrier_wait(&start_line);
  for (int r = 0; r < kRepeats; ++r) {
    memset(yout, 0, sizeof yout);
    if (atomic_fetch_add(&in_flight, 1) > 0) ++job->overlapped;
    if (np_test_solve(job->problem, yout, counts) != 0) ++job->failures;
    atomic_fetch_sub(&in_flight, 1);
    if (memcmp(yout, job->reference, bytes) != 0 || memcmp(counts, job->ref_counts, sizeof counts) != 0)
      ++job->mismatches;
  }
  return NULL;
}

int main(void) {
  static double ref[3][kMaxN * kNout];
  int64_t ref_counts[3][3];
  for (int p = 1; p <= 2; ++p) {
    if (np_test_solve(p, ref[p], ref_counts[p]) != 0) {
      fprintf(stderr, "sequential run of problem %d failed\n", p);
      return 1;
    }
    printf("problem %d sequential: %lld RHS evaluations, %lld accepted, %lld rejected steps\n", p,
           (long long)ref_counts[p][0], (long long)ref_counts[p][1], (long long)ref_counts[p][2]);
  }
  Job jobs[2] = {{1, ref[1], ref_counts[1], 0, 0, 0}, {2, ref[2], ref_counts[2], 0, 0, 0}};
  pthread_barrier_init(&start_line, NULL, 2);
  pthread_t th[2];
  for (int i = 0; i < 2; ++i)
    if (pthread_create(&th[i], NULL, worker, &jobs[i]) != 0) {
      fprintf(stderr, "pthread_create failed\n");
      return 1;
    }
  for (int i = 0; i < 2; ++i) pthread_join(th[i], NULL);
  int bad = 0;
  for (int i = 0; i < 2; ++i) {
    printf("thread %d (problem %d): %d runs (%d begun while the other thread was solving), %d failed, %d differ "
           "from the sequential run\n",
           i, jobs[i].problem, kRepeats, jobs[i].overlapped, jobs[i].failures, jobs[i].mismatches);
    bad += jobs[i].failures + jobs[i].mismatches;
  }
  pthread_barrier_destroy(&start_line);
  if (bad) return 1;
  if (jobs[0].overlapped + jobs[1].overlapped == 0) {
    fprintf(stderr, "the two threads never ran at the same time: the test proved nothing\n");
    return 1;
  }
  printf("all checks hold\n");
  return 0;
}
