// SPDX-License-Identifier: Apache-2.0
#pragma once
// MPI driver of `blockdyn sweep`: rank 0 owns the journal/CSV/sidecar (SweepSession) and also
// computes; every rank takes the pending points i with (position in the pending list) % size ==
// rank and computes them on its own threads; rows travel to rank 0 as they finish. The rows are
// the same bytes as in a single-process run, and the final CSV is sorted, so the output is
// byte-identical to a single-process run; resume works the same because rank 0 reads the journal.
// An adaptive plan runs stage after stage: rank 0 chooses each stage and broadcasts it.
#include "blockdyn/analysis/sweep/sweep_runner.hpp"

namespace blockdyn::cli {

// True when the environment shows an MPI launcher (mpirun/mpiexec/srun with PMI/PMIx) started
// this process. Checked before any MPI call, so a plain launch never initialises MPI.
bool launched_by_mpi();
// Size the launcher announced (1 if none or unknown).
int launcher_world_size();
// True if this binary was built with MPI.
bool mpi_built();

struct MpiSweepResult {
  bool root = true;  // only the root prints, plots and reports
  SweepOutcome outcome;
  int ranks = 1;
};

// Initialises MPI, runs the sweep (the plan's stages; nullptr: every point) across ranks and
// finalises MPI. Usage errors (e.g. existing output) are thrown on rank 0; the other ranks then
// exit quietly with the same status. The plan is consulted on rank 0 only.
MpiSweepResult run_sweep_mpi(const PointTable& ev, SweepRunOptions o, PointPlan* plan = nullptr);

}  // namespace blockdyn::cli
