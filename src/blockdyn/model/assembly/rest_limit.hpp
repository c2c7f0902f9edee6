// SPDX-License-Identifier: Apache-2.0
#pragma once
// The static limit of an assembly of rigid blocks whose contacts are all closed: the largest
// horizontal ground acceleration, in units of g + a_V, under which a distribution of contact
// forces still holds every block in equilibrium (no tension: normal forces >= 0 at each
// interface's two contact points; Coulomb: |T| <= mu_s (N_1 + N_2) per interface). Where the
// assembly is statically indeterminate (a trilith: the lintel on two columns) the forces are not
// unique, and rest holds exactly while some distribution exists: a linear programme (the static
// theorem of limit analysis), solved by GLPK. Its dual is the mechanism that the limit sets in
// motion (a virtual velocity per block), which names the contacts that open and slide.
#include <vector>

#include "blockdyn/model/assembly/contact_point.hpp"

namespace blockdyn {

struct StaticContact {
  int upper = 0, lower = -1;  // blocks (-1: the ground)
  int iface = 0;
  Vec2 P, n, t;  // point, normal and tangent, both as seen by the upper block
};

struct StaticProblem {
  std::vector<double> mass;  // kg per block
  std::vector<Vec2> centre;  // centre of mass per block
  std::vector<StaticContact> contacts;
  std::vector<double> mu;  // static friction per interface (>= kNoSlipFriction: no sliding)
  double g = 9.81;
};

struct LoadMultiplier {
  bool feasible = false;           // false: no distribution holds the blocks even without a horizontal load
  double lambda = 0;               // largest a_H / (g + a_V) in the direction asked (capped at 1e6)
  std::vector<double> mechanism;   // virtual velocity (vx, vy, omega) per block, moving with the load
  std::vector<double> normal;      // a distribution of forces at the limit: N per contact (>= 0)
  std::vector<double> tangential;  // and T per interface, on the upper block along its t
};

// direction +1: a_H > 0 (inertial load towards -x); -1: a_H < 0. exact: refine the floating-point
// simplex's optimum with GLPK's exact (rational) simplex (the limit to the last bit; slower by
// far on large assemblies).
LoadMultiplier max_load_multiplier(const StaticProblem& p, int direction, bool exact = true);

}  // namespace blockdyn
