// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn fragility`: every record of a suite scaled to every intensity level (multiple
// stripes), one run each of a block (housner, rigid) or an assembly, and the lognormal fragility
// curve fitted by maximum likelihood with its bootstrap band. A grid study: threads, MPI,
// journal and --resume on the command line; in memory from Python.
#include "blockdyn/commands/grid_studies.hpp"

namespace blockdyn {

GridStudyCommand fragility_command();

}  // namespace blockdyn
