// SPDX-License-Identifier: Apache-2.0
#pragma once
// Impact maps under harmonic forcing a_H = A cos(Omega t + phase) (issue 9 item 5; seed 002
// Fig. 15b): the forcing phase Phi = (Omega t + phase) mod 2 pi of each impact against the
// angular velocity just before it (seed 002 writes Phi = Omega t mod 2 pi, its phase being 0);
// and the forced Poincare map, the state sampled once per forcing period at the forcing phase
// phi0: t_k = t0 + k T with t0 the first time >= 0 at which Omega t + phase = phi0 (mod 2 pi).
#include <vector>

#include "blockdyn/analysis/forced/forced_trace.hpp"

namespace blockdyn {

// (Omega t + phase) mod 2 pi, in [0, 2 pi).
double forcing_phase(double t, double Omega, double phase);
// The first time >= 0 at which the forcing phase is phi0.
double section_time(double Omega, double phase, double phi0);

struct ImpactMapPoint {
  double t = 0, phase = 0, omega_before = 0, omega_after = 0;
};
// The impacts at or after t_from, with their forcing phase.
std::vector<ImpactMapPoint> impact_map(const std::vector<Impact>& impacts, double Omega, double phase,
                                       double t_from = 0.0);

}  // namespace blockdyn
