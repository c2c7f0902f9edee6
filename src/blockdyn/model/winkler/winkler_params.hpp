// SPDX-License-Identifier: Apache-2.0
#pragma once
// Immutable, non-dimensional parameters of a block on a Winkler foundation.
#include <cmath>

namespace blockdyn {

struct BlockParams {
  double r = 0.5;    // aspect ratio width / height, > 0
  double mu = 0.2;   // friction coefficient, >= 0
  double k = 1e5;    // foundation stiffness k_phys a b / (m g), > 0

  double alpha() const { return std::atan(r); }               // overturning angle
  double inertia() const { return (1.0 + r * r) / 12.0; }     // centroidal, units m a^2
};

// Throws std::invalid_argument naming the field and its allowed range.
void validate(const BlockParams& p);

}  // namespace blockdyn
