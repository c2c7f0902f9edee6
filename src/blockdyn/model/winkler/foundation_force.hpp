// SPDX-License-Identifier: Apache-2.0
#pragma once
// Foundation reaction of the thesis's Winkler model: vertical force Ry = (k/r) * area acting
// at the Region's centroid, its torque about the centre, and the non-potential part of that
// torque (non-zero only when the Region ends in a vertical wall, i.e. two corners submerged).
#include "blockdyn/model/winkler/region.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"

namespace blockdyn {

struct FoundationForce {
  double Ry = 0.0;      // vertical reaction, units of weight
  double torque = 0.0;  // (x_R - x) * Ry
  // (k / 6r) (s_far^3 - s_pivot_end^3): the non-potential torque for the lowest corner on side +1.
  double wall_mismatch = 0.0;
  int corners_below = 0;

  // The non-potential torque torque + dV/dw (V the spring energy) with the lowest corner on side
  // `side` (sign(w) away from the upright). It does not vanish as w -> 0 with two corners
  // submerged (a wall at the far end only), so at w = 0 the side the block tips to decides it.
  double torque_nonpot(int side) const { return side * wall_mismatch; }
};

// The stiffness per unit length k / r and k / (6 r), fixed for a block (computed once by the model).
struct FoundationStiffness {
  double kr = 0.0, kr6 = 0.0;
  explicit FoundationStiffness(const WinklerParams& p) : kr(p.k / p.r), kr6(kr / 6.0) {}
};

inline FoundationForce foundation_force(const FoundationStiffness& ks, double r, double h, const Tilt& t) {
  const RegionIntegrals g = region_integrals(r, h, t);
  FoundationForce f;
  f.Ry = ks.kr * g.area;
  f.torque = ks.kr * g.moment;
  // dV/dw = -torque + sign(w) (k / 6r) (s_far^3 - s_pivot_end^3): virtual work of a rigid
  // rotation on the clipped envelope, with the moving wall at each submerged Region end.
  const double a = g.depth_far_end, b = g.depth_pivot_end;
  f.wall_mismatch = ks.kr6 * (a * a * a - b * b * b);
  f.corners_below = g.corners_below;
  return f;
}

inline FoundationForce foundation_force(const WinklerParams& p, double h, const Tilt& t) {
  return foundation_force(FoundationStiffness(p), p.r, h, t);
}

inline FoundationForce foundation_force(const WinklerParams& p, double h, double w) {
  return foundation_force(p, h, make_tilt(w));
}

}  // namespace blockdyn
