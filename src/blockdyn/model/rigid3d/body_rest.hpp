// SPDX-License-Identifier: Apache-2.0
#pragma once
// The exit from rest of the 3D body standing on its base (docs/3d.md), found on the ground motion
// itself as the planar families' is (excitation/rest_exit.hpp), at the first crossing whatever
// the motion's shape. This step covers a motion along one horizontal direction (the `h` component
// at its azimuth, with any vertical `v`): then every rest condition is |a_h(t)| > c (1 + a_v(t))
// with one coefficient c per way of leaving, and the first to fail is the one of the smallest c.
#include <limits>

#include "blockdyn/excitation/ground_motion_3d.hpp"
#include "blockdyn/model/rigid3d/body_shape.hpp"

namespace blockdyn {

enum class RestExitWay { None, Rocks, Slides };

struct BodyRestExit {
  double t = std::numeric_limits<double>::infinity();  // infinity: rests throughout
  RestExitWay way = RestExitWay::None;
  double coefficient = 0;  // the c that fails first: rest_threshold() or mu_s
};

// The first time in [t0, t1) at which the body (turned by `yaw` rad about Z) under `g` leaves
// rest: it rocks where |a_h| > rest_threshold(azimuth - yaw) (1 + a_v), slides where
// |a_h| > mu_s (1 + a_v) (rocking first when both coefficients are equal). Throws
// std::invalid_argument for a motion with a second horizontal component (h2), not yet covered.
BodyRestExit first_rest_exit(const Body3d& b, double yaw, double mu_s, const GroundMotion3d& g, double t0, double t1);

}  // namespace blockdyn
