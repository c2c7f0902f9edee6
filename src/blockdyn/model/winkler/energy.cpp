// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/winkler/energy.hpp"

#include "blockdyn/model/winkler/region.hpp"

namespace blockdyn {

double spring_energy(const WinklerParams& p, double h, double w) {
  return 0.5 * p.k / p.r * region_integrals(p.r, h, w).s2;
}

Energy energy(const WinklerParams& p, const WinklerState& z) {
  Energy e;
  e.kinetic_x = 0.5 * z[kVX] * z[kVX];
  e.kinetic_y = 0.5 * z[kVY] * z[kVY];
  e.rotation = 0.5 * p.inertia() * z[kVW] * z[kVW];
  e.gravity = z[kH];
  e.springs = spring_energy(p, z[kH], z[kW]);
  return e;
}

}  // namespace blockdyn
