// SPDX-License-Identifier: Apache-2.0
#pragma once
// An assembly run with the rigid law by Moreau-Jean time-stepping (model/assembly/moreau_jean.hpp).
// Events are found between consecutive steps: contact ends opening and closing (an impact when
// the end approached), stick and slip, passages of theta through 0 and the collapse criteria, the
// crossings of theta interpolated linearly within the step.
#include "blockdyn/simulation/assembly_simulation.hpp"

namespace blockdyn {

AssemblyResult run_moreau_jean(const Assembly& a, const GroundMotion& g, const AssemblyRunOptions& o,
                               TrajectoryTable* trajectory, RunProbe* probe);

}  // namespace blockdyn
