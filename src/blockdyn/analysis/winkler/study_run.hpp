// SPDX-License-Identifier: Apache-2.0
#pragma once
// One simulation run of the flight and stability studies.
#include "blockdyn/analysis/winkler/ic_choice.hpp"
#include "blockdyn/analysis/winkler/study_options.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

// Simulation options of a study run: t_end and integrator from o, no energy tracking or event log.
WinklerRunOptions lean_study_options(const StudyRunOptions& o);

// simulate() from ic's state, throwing std::runtime_error (naming ic, r, mu, k and t) on a
// numerical failure.
WinklerResult run_checked(const WinklerParams& p, const IcChoice& ic, const WinklerRunOptions& s,
                          WinklerSink* sink = nullptr);

}  // namespace blockdyn
