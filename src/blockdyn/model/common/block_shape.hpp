// SPDX-License-Identifier: Apache-2.0
#pragma once
// A rectangular rigid block in SI units (width b, height h, mass m, gravity g) and the
// quantities every model of it uses (Housner's notation, see ../shared/spec/rigid-ground-block.md).
#include <cmath>

namespace blockdyn {

struct BlockShape {
  double width = 0.2;   // b [m]
  double height = 1.0;  // h [m]
  double mass = 1.0;    // m [kg]
  double g = 9.81;      // [m/s^2]

  double alpha() const { return std::atan2(width, height); }                                 // slenderness angle
  double half_diagonal() const { return 0.5 * std::hypot(width, height); }                   // R
  double p() const { return std::sqrt(0.75 * g / half_diagonal()); }                         // frequency parameter
  double inertia_centre() const { return mass * (width * width + height * height) / 12.0; }  // I_G
  double inertia_corner() const { return 4.0 * inertia_centre(); }                           // I_O = 4 m R^2 / 3
  // Housner's coefficient: angular momentum about the impacting corner conserved.
  double housner_restitution() const {
    const double s = std::sin(alpha());
    return 1.0 - 1.5 * s * s;
  }
};

// Throws std::invalid_argument naming width, height, mass or g and the allowed range.
void validate(const BlockShape& s);

}  // namespace blockdyn
