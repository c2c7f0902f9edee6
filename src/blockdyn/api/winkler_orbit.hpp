// SPDX-License-Identifier: Apache-2.0
#pragma once
// The orbit a Winkler study follows (response, poincare, energy-surface): the block (--r --mu --k),
// the integrator (--rtol --atol --method) and the initial state (--ic and its overrides, with the
// same names and meaning as `simulate`; `--ic surface` puts the state on a prescribed energy).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/api/study_command.hpp"
#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"
#include "blockdyn/simulation/simulate.hpp"

namespace blockdyn {

struct WinklerOrbit {
  BlockParams p;
  IntegratorOptions integrator;
  std::string ic;  // ic1, ic2, custom, surface
  BlockStateVec z0{};
};

std::vector<StudyOption> winkler_orbit_options();
// Throws std::invalid_argument naming the option at fault.
WinklerOrbit winkler_orbit(const StudyOptions& o);
// Options of a run to t_end without an event log (validated).
SimulationOptions orbit_run_options(double t_end, const IntegratorOptions& integ);
// The opening of every orbit study's summary: run info, block, initial state, integrator.
nlohmann::ordered_json orbit_summary_head(const WinklerOrbit& orbit);

}  // namespace blockdyn
