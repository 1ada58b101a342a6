// A sweep across MPI ranks (mpirun -np R nanopush-mpi sweep ...): rank 0 hands out point
// indices on request (dynamic scheduling: points differ 100x in cost), every rank computes on
// its own threads, finished rows return to rank 0, which keeps the journal and writes the
// same table as a run on one process. Built into nanopush-mpi when NANOPUSH_MPI is on
// (OpenMPI); the plain nanopush links no MPI and names nanopush-mpi when mpirun starts it.
#pragma once
#include <csignal>

#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::cli {

/// The command line with MPI, installed beside nanopush.
inline constexpr char kMpiProgram[] = "nanopush-mpi";

/// True when this process was started by mpirun with more than one rank.
bool mpi_launched();

/// Run the sweep over the ranks; every rank calls it and returns the same exit status: 0,
/// 64 + failed points, or 128 + N when a signal N to any rank (or to mpirun, which passes it
/// on) stopped every rank. `signal` is where this rank's handler records its signal.
int run_mpi_sweep(const sweep::Plan& plan, const sweep::Task& task, const sweep::Options& options, bool quiet,
                  const volatile std::sig_atomic_t* signal);

}  // namespace nanopush::cli
