// SPDX-License-Identifier: Apache-2.0
#pragma once
// Immutable, non-dimensional parameters of a block on a Winkler foundation.
#include <cmath>

namespace blockdyn {

struct WinklerParams {
  double r = 0.5;   // aspect ratio width / height, > 0
  double mu = 0.2;  // friction coefficient, >= 0
  double k = 1e5;   // foundation stiffness k_phys a b / (m g), > 0

  double alpha() const { return std::atan(r); }            // overturning angle
  double inertia() const { return (1.0 + r * r) / 12.0; }  // centroidal, units m a^2
};

// The model's numeric range. Beyond k = 1e12 the static settlement 1/k is below 1e-12 of the
// block's height: the foundation is rigid for every purpose (use --model rigid), and the
// depths lose their meaning next to the rounding of the geometry. r outside [1e-3, 1e3] is a
// needle or a plate, not a block.
inline constexpr double kWinklerRMin = 1e-3, kWinklerRMax = 1e3;
inline constexpr double kWinklerKMin = 1e-6, kWinklerKMax = 1e12;
inline constexpr double kWinklerMuMax = 1e3;

// Throws std::invalid_argument naming the field and its allowed range.
void validate(const WinklerParams& p);

}  // namespace blockdyn
