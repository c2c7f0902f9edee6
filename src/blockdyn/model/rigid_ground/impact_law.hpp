// SPDX-License-Identifier: Apache-2.0
#pragma once
// Impact laws of a rigid block hitting rigid ground at one or two base corners (impulse level).
//   housner: the impacting corner sticks and the angular momentum about it is conserved
//            (Housner 1963); for a block rocking onto that corner this gives theta'+ = e_H theta'-,
//            and a user restitution e replaces e_H there (the post-impact rate is scaled by e/e_H,
//            never gaining kinetic energy). Two corners landing together: a plastic impact.
//   newton:  Newton restitution e_n at each impacting corner (normal velocity -e_n vn-), the other
//            corners touching the ground unilateral, Coulomb friction at impulse level (stick
//            while |P_T| <= mu_s P_N, else slip with mu_k), solved exactly by enumeration.
#include <array>
#include <optional>

#include "blockdyn/model/rigid_ground/contact_problem.hpp"
#include "blockdyn/model/rigid_ground/rigid_params.hpp"

namespace blockdyn {

struct ImpactContact {
  int side = 1;  // +1 corner A, -1 corner B
  Vec2 r;        // offset from the centre
};

// Post-impact (vx, vy, omega) from the pre-impact u, or nullopt when no consistent impulse exists.
// contacts: the corners touching the ground (1 or 2); u: pre-impact velocities.
std::optional<std::array<double, 3>> apply_impact(const RigidBlockParams& p, const ImpactContact* contacts, int n,
                                                  const std::array<double, 3>& u, double tol_v, bool plastic = false);

}  // namespace blockdyn
