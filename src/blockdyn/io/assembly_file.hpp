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

// An interface's restitution the file does not give: the contact law's default (0.5 for the
// deformable law, 0 for the rigid one, as the presets), set by the caller that knows the law.
inline constexpr double kUnsetRestitution = -1.0;

// Every interface without a restitution of its own gets the law's default (see above).
void apply_default_restitution(Assembly& a, bool plastic);

Assembly read_assembly_file(const std::string& path);
// The same from the file's text (`source` names it in errors).
Assembly parse_assembly(const std::string& text, const std::string& source);

}  // namespace blockdyn
