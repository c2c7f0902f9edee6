// SPDX-License-Identifier: Apache-2.0
#pragma once
// One simulation run of the flight and stability studies.
#include "blockdyn/analysis/winkler/ic_choice.hpp"
#include "blockdyn/analysis/winkler/study_options.hpp"
#include "blockdyn/simulation/simulate.hpp"

namespace blockdyn {

// Simulation options of a study run: t_end and integrator from o, no energy tracking or event log.
SimulationOptions lean_study_options(const StudyRunOptions& o);

// simulate() from ic's state, throwing std::runtime_error (naming ic, r, mu, k and t) on a
// numerical failure.
SimulationResult run_checked(const BlockParams& p, const IcChoice& ic, const SimulationOptions& s,
                             SimulationSink* sink = nullptr);

}  // namespace blockdyn
