// SPDX-License-Identifier: Apache-2.0
#pragma once
// The exit from rest of the 3D body standing on its base (docs/3d.md), found on the ground motion
// itself as the planar families' is (excitation/first_failure.hpp), at the first crossing
// whatever the motion's shape, under all three components at once. With a_H the horizontal
// ground acceleration (two components), a_V the vertical and c = h/2, the body rests while
//   box: e1 . a_H <= (b/h)(1 + a_V) and -e1 . a_H <= (b/h)(1 + a_V), the same along e2 with d
//        (four linear conditions: leaving by one is rocking about the opposite edge, by two at
//        once pivoting on a corner);
//   cylinder: |a_H| <= (2a/h)(1 + a_V) (rocking about the rim point at -a_H);
//   both: |a_H| <= mu_s (1 + a_V) (sliding) and 1 + a_V > 0.
// A norm condition's lower bound uses |a_H'| for its rate (the bound stays valid; the search
// then converges linearly where a_H' is not along a_H).
#include <limits>
#include <vector>

#include "blockdyn/excitation/ground_motion_3d.hpp"
#include "blockdyn/model/rigid3d/body_shape.hpp"

namespace blockdyn {

enum class RestExitWay { None, Rocks, Slides, Lifts };

// Which rest conditions fail at an instant.
struct RestFailure {
  RestExitWay way = RestExitWay::None;
  int x_side = 0, y_side = 0;  // box: the ground beyond the threshold towards +-e1, +-e2 (0: within)
  Vec3 towards{};              // the horizontal ground acceleration (world, g): the body tips away from it
};

class BodyRestSearch {
 public:
  BodyRestSearch() = default;
  // For a piecewise-linear motion (records, constants) every condition is concave between
  // breakpoints, so rest fails inside a piece only if it fails at an end: the failing
  // breakpoints for a body at `yaw_hint` are listed once, and a query at that yaw searches only
  // the piece before the next of them (as the planar RestExit does).
  BodyRestSearch(const Body3d& b, double mu_s, const GroundMotion3d& g, double yaw_hint = 0);
  // At t for the body turned by yaw (rad).
  RestFailure failure(double t, double yaw) const;
  // The first failure in [t0, t1), or infinity.
  double first_failure(double yaw, double t0, double t1) const;
  // Where a body at rest at t must next be looked at: its first failure, or the end of a
  // look-ahead span (kRestLookahead of the input's shortest time scale) after which the search
  // goes on.
  double checkpoint(double t, double yaw) const;

 private:
  Body3d body_;
  double mu_s_ = 0;
  GroundMotion3d g_;
  bool listed_ = false;  // piecewise linear: the failing breakpoints at yaw_hint_ are listed
  double yaw_hint_ = 0;
  std::vector<double> fail_, before_;  // failing breakpoints and the breakpoint before each
};

struct BodyRestExit {
  double t = std::numeric_limits<double>::infinity();  // infinity: rests throughout
  RestExitWay way = RestExitWay::None;
};

// The first time in [t0, t1) at which the body (turned by `yaw` rad about Z) under `g` leaves
// rest, and how (rocking first when it and sliding fail at once).
BodyRestExit first_rest_exit(const Body3d& b, double yaw, double mu_s, const GroundMotion3d& g, double t0, double t1);

}  // namespace blockdyn
