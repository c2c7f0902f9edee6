// SPDX-License-Identifier: Apache-2.0
#pragma once
// The elastic response spectrum of a record: a linear oscillator of period T and damping ratio
// zeta under the ground acceleration, u'' + 2 zeta w u' + w^2 u = -a_g(t), from rest. The
// response is the closed form of each linear segment of the input (exact, no time step), its
// peak |u| found where the velocity vanishes inside a segment, over the record and the free
// vibration after it (the record ends at a = 0). Sa = w^2 max |u| (pseudo-acceleration).
#include <vector>

#include "blockdyn/excitation/accelerogram.hpp"

namespace blockdyn {

struct SpectralOrdinate {
  double period = 0;  // T (s)
  double sa = 0;      // pseudo-spectral acceleration (g)
  double sd = 0;      // spectral displacement max |u| (m)
  double t_peak = 0;  // when |u| peaks (s)
};

// Periods > 0 (s); damping in [0, 1); g converts the record's units. std::invalid_argument
// naming "period" or "damping".
SpectralOrdinate spectral_ordinate(const Accelerogram& rec, double period, double damping, double g = 9.81);
std::vector<SpectralOrdinate> response_spectrum(const Accelerogram& rec, const std::vector<double>& periods,
                                                double damping, double g = 9.81);

}  // namespace blockdyn
