// SPDX-License-Identifier: Apache-2.0
#pragma once
// The Winkler block's contact mode: reactions with the lowest corner held fixed (stick).
// The corner on side s sits at (-s A_s, -B_s) from the centre.
#include <cmath>

#include "blockdyn/model/common/coulomb.hpp"
#include "blockdyn/model/winkler/region.hpp"

namespace blockdyn {

// Accelerations and horizontal reaction with the pivot corner held fixed (contact mode):
// unknowns w'', Rx from  I w'' = T + B Rx  and  Rx = x'' + a_h = -B w'' - s A w'^2 + a_h.
struct StickReaction {
  double ww;  // w''
  double Rx;
};

inline StickReaction stick_reaction(double inertia, const CornerArms& arm, int side, double torque, double vw,
                                    double a_h) {
  const double ww = (torque - side * arm.A * arm.B * vw * vw + arm.B * a_h) / (inertia + arm.B * arm.B);
  return {ww, -arm.B * ww - side * arm.A * vw * vw + a_h};
}

}  // namespace blockdyn
