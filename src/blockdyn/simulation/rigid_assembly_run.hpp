// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid law's runs: time-stepping (Moreau-Jean) throughout, or the event-driven run
// (model/assembly/rigid_assembly_model.hpp) with its
// time-stepping windows: where the event-driven scheme cannot go on (impacts that accumulate
// without settling, a contact problem with no consistent mode: friction chatter), the run hands
// over to Moreau-Jean time-stepping (model/assembly/moreau_jean.hpp) from the same state, and
// takes the events back once the contacts have kept their states for a while (moreau_jean_stepping.hpp). Both
// strategies feed the same observers: a time-stepping step is a segment (the cubic Hermite
// interpolant of its end states: exact at the step ends, as the scheme is), its contact changes
// are events at the step's end. The windows are reported (events `time_stepping` and
// `event_driven`, their count and duration).
#include "blockdyn/model/assembly/rigid_assembly_model.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "blockdyn/simulation/observer.hpp"
#include "blockdyn/simulation/run.hpp"

namespace blockdyn {

struct TimeSteppingWindows {
  long count = 0;     // windows handed to time-stepping
  double time = 0;    // their total duration (s)
  long steps = 0;     // their steps
  std::string first;  // why the first one was needed
  // How the steps' contact problems were solved (moreau_jean.hpp).
  long direct = 0, lemke = 0, gauss_seidel = 0, sweeps = 0, active_set_iterations = 0;
};

template <int MaxBlocks>
RunOutcome<RigidAssemblyModel<MaxBlocks>> run_rigid_assembly(const RigidAssemblyModel<MaxBlocks>& m,
                                                             typename RigidAssemblyModel<MaxBlocks>::Mode mode,
                                                             typename RigidAssemblyModel<MaxBlocks>::State z,
                                                             const AssemblyRunOptions& o,
                                                             Observer<RigidAssemblyModel<MaxBlocks>>& obs,
                                                             TimeSteppingWindows& windows);

}  // namespace blockdyn
