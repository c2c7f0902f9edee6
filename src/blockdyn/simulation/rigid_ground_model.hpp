// SPDX-License-Identifier: Apache-2.0
#pragma once
// A block on rigid ground as the analyses run it, whichever family it is: Housner's 1-DOF block
// or the 3-DOF block with friction. The families register one each (family_registry.cpp); sweeps,
// rocking spectra, fragility and the outputs ask these traits and never the family's name.
#include <nlohmann/json.hpp>

#include "blockdyn/simulation/rigid_simulation.hpp"

namespace blockdyn {

struct RigidGroundModel {
  const char* name;  // the family's --model value
  // Coulomb friction (mu_s, mu_k), an impact law and the centre's translation (x, y, and their
  // rates) are degrees of freedom or parameters of this model.
  bool friction;
  // How the absolute tolerance scales each state component (for the outputs).
  const char* atol_scaling;
  // Thread-safe: one run (throws std::invalid_argument for invalid input).
  RigidResult (*simulate)(const RigidBlockParams&, const GroundMotion&, const RigidInitial&, const RigidRunOptions&);
  // Throws std::invalid_argument when the initial state does not fit the block.
  void (*check_initial)(const RigidBlockParams&, const GroundMotion&, const RigidInitial&);
};

const RigidGroundModel& housner_on_rigid_ground();
const RigidGroundModel& three_dof_on_rigid_ground();

// The block's parameters as the outputs record them.
nlohmann::ordered_json parameters_json(const RigidBlockParams& p, const RigidGroundModel& m);

}  // namespace blockdyn
