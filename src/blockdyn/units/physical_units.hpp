// SPDX-License-Identifier: Apache-2.0
#pragma once
// Physical block -> non-dimensional parameters, and the scales to convert results back.
// Lengths in units of the height a, forces of the weight m g, time of sqrt(a / g).
#include <optional>

#include "blockdyn/model/winkler/winkler_params.hpp"

namespace blockdyn {

struct PhysicalBlock {
  double height = 0;                       // a [m]
  double width = 0;                        // b [m]
  std::optional<double> mass;              // m [kg]; or density * height * width * thickness
  std::optional<double> density;           // [kg/m^3]
  std::optional<double> thickness;         // out-of-plane depth [m]
  std::optional<double> subgrade_modulus;  // Winkler modulus [N/m^3] (needs thickness)
  std::optional<double> line_stiffness;    // foundation stiffness per unit length and depth [N/m^2]
  double g = 9.81;                         // [m/s^2]
  double mu = 0.2;
};

struct UnitScales {
  double length = 1, time = 1, velocity = 1, angular_velocity = 1, force = 1, energy = 1, mass = 1;
};

// Throws std::invalid_argument naming the missing or out-of-range field.
WinklerParams to_nondimensional(const PhysicalBlock& b);
UnitScales scales_of(const PhysicalBlock& b);
double mass_of(const PhysicalBlock& b);

}  // namespace blockdyn
