// SPDX-License-Identifier: Apache-2.0
#pragma once
// Assembly files (TOML): [assembly] g, collapse_rotation, min_bearing; [contact] the default law
// of every interface (k_normal, k_tangential, restitution, damping, phi / phi_kinetic in degrees
// or mu_s / mu_k); [[block]] name, width, height, mass (or density and thickness), x, y, theta,
// vx, vy, omega; [[interface]] lower ("ground" or a block index), upper, and any law key.
// Errors are std::invalid_argument naming the key.
#include <string>

#include "blockdyn/model/assembly/assembly_params.hpp"

namespace blockdyn {

inline constexpr double kNoSlip = kNoSlipFriction;

// tan(deg) for deg in [0, 90) and kNoSlip at 90; field names the value in errors.
double friction_of_angle(double deg, const std::string& field);

Assembly read_assembly_file(const std::string& path);

}  // namespace blockdyn
