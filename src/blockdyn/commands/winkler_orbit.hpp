// SPDX-License-Identifier: Apache-2.0
#pragma once
// The orbit a Winkler study follows (response, poincare, energy-surface): the block (--r --mu --k),
// the integrator (--rtol --atol --method) and the initial state (--ic and its overrides, with the
// same names and meaning as `simulate`; `--ic surface` puts the state on a prescribed energy).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

struct WinklerOrbit {
  WinklerParams p;
  IntegratorOptions integrator;
  std::string ic;  // ic1, ic2, custom, surface
  WinklerState z0{};
};

// method_option: the integrator's --method, or another name where the study has a --method of its
// own (lyapunov: --integrator-method).
std::vector<StudyOption> winkler_orbit_options(const std::string& method_option = "method");
// Throws std::invalid_argument naming the option at fault.
WinklerOrbit winkler_orbit(const StudyOptions& o, const std::string& method_option = "method");
// Options of a run to t_end without an event log (validated).
WinklerRunOptions orbit_run_options(double t_end, const IntegratorOptions& integ);
// The opening of every orbit study's summary: run info, block, initial state, integrator.
nlohmann::ordered_json orbit_summary_head(const WinklerOrbit& orbit);

}  // namespace blockdyn
