// A sweep across MPI ranks (mpirun -np R nanopush sweep ...): rank 0 hands out point
// indices on request (dynamic scheduling: points differ 100x in cost), every rank computes on
// its own threads, finished rows return to rank 0, which keeps the journal and writes the
// same table as a run on one process. Built when NANOPUSH_MPI is on (OpenMPI).
#pragma once
#include "nanopush/sweeps/sweep.hpp"

namespace nanopush::cli {

/// True when this process was started by mpirun with more than one rank.
bool mpi_launched();

/// Run the sweep over the ranks; every rank calls it. Returns the exit status.
int run_mpi_sweep(const sweep::Plan& plan, const sweep::Task& task, const sweep::Options& options, bool quiet);

}  // namespace nanopush::cli
