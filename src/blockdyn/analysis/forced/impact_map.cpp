// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/impact_map.hpp"

#include "blockdyn/base/angles.hpp"

#include <cmath>

namespace blockdyn {

double forcing_phase(double t, double Omega, double phase) { return wrap_angle(Omega * t + phase); }

double section_time(double Omega, double phase, double phi0) { return wrap_angle(phi0 - phase) / Omega; }

std::vector<ImpactMapPoint> impact_map(const std::vector<Impact>& impacts, double Omega, double phase, double t_from) {
  std::vector<ImpactMapPoint> out;
  for (const Impact& i : impacts)
    if (i.t >= t_from) out.push_back({i.t, forcing_phase(i.t, Omega, phase), i.omega_before, i.omega_after});
  return out;
}

}  // namespace blockdyn
