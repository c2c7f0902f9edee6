// SPDX-License-Identifier: Apache-2.0
#pragma once
// The five energy components of the thesis (section 4) and the energy balance.
#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"

namespace blockdyn {

struct Energy {
  double kinetic_x = 0, kinetic_y = 0, rotation = 0, gravity = 0, springs = 0;
  double total() const { return kinetic_x + kinetic_y + rotation + gravity + springs; }
};

// Energy relative to the block standing upright on rigid ground (gravity term y - 1/2).
Energy energy(const WinklerParams& p, const WinklerState& z);

// Spring energy (k / 2r) * integral s^2 dX of the Region.
double spring_energy(const WinklerParams& p, double h, double w);

}  // namespace blockdyn
