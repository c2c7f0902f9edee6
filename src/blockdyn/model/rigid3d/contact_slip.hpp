// SPDX-License-Identifier: Apache-2.0
#pragma once
// The rigid3d body on one or two base points (a corner, or an edge's two corners; docs/3d.md),
// each sticking to the ground or slipping on it, at least one slipping: Newton-Euler with a
// sticking point's reaction (three components) and a slipping point's normal load N_i with its
// Coulomb friction -mu_k N_i d_i against its slip direction d_i (unit, horizontal). The unknowns
// follow from the constraints at acceleration level: a sticking point does not accelerate, a
// slipping one does not accelerate vertically (a linear system of at most 4 x 4). Where the
// system stops being solvable with a positive response (its determinant, in units of the mass,
// reaches zero) no load is consistent: Painleve's paradox. Vectors in the ground's frame.
#include <array>

#include "blockdyn/model/rigid3d/quaternion.hpp"

namespace blockdyn {

struct ContactPoints {
  int n = 1;                     // 1 or 2
  std::array<Vec3, 2> arm{};     // P_i - G
  std::array<bool, 2> sticks{};  // not both (an edge sticking at both ends is a line contact)
  std::array<Vec3, 2> dir{};     // a slipping point's slip direction (unit, horizontal)
};

struct SlipContactMotion {
  Vec3 accel{};                 // the centroid's acceleration
  Vec3 domega{};                // the angular acceleration
  std::array<Vec3, 2> force{};  // each point's reaction (N)
  double consistency = 1;       // det of the system, in units of the mass: positive where consistent
};

// The body of principal inertias `inertia` (body frame) and mass, at orientation r, spinning at
// omega, under the specific force f (gravity and the ground's acceleration reversed, m/s^2).
SlipContactMotion slipping_contact_motion(const Vec3& inertia, double mass, const Mat3& r, const ContactPoints& p,
                                          const Vec3& omega, const Vec3& f, double mu_k);

}  // namespace blockdyn
