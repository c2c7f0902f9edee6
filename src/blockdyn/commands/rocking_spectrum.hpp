// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn rocking-spectrum` (Makris & Konstantinidis 2003): for one record and one slenderness
// alpha, the largest rotation over alpha and overturning as functions of the block's size through
// its frequency parameter p = sqrt(3 g / (4 R)), optionally over record scale factors too (the
// overturning scale of a record). A grid study: threads, MPI, journal on the command line; in
// memory from Python.
#include "blockdyn/commands/grid_studies.hpp"

namespace blockdyn {

GridStudyCommand rocking_spectrum_command();

}  // namespace blockdyn
