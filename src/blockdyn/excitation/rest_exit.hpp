// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a block resting on the ground stops resting, found on the ground motion itself. At rest
// the state is constant, so nothing in the integrator's step control sees the forcing: a step at
// rest may grow over a whole window in which rest fails and end on the far side with every
// margin positive. The rest conditions depend on the input only; they are searched here, and the
// step at rest ends where the first one fails (the model's next_breakpoint).
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"

namespace blockdyn {

// The first time in [t0, t1) at which a block standing on the ground with the resistance
// coefficient c >= 0 (c = tan(alpha) for rocking, mu_s for sliding, the smaller of the two for
// a block that can do both) no longer rests: |a_H(t)| > c (1 + a_V(t)), or 1 + a_V(t) <= 0;
// infinity if it rests throughout. At the time returned the condition has failed (it is the
// right end of a bracket of a few ulps around the crossing), whatever the input's shape: between
// breakpoints each condition is bounded below by its value, its rate and the input's curvature
// bound, and the search steps to where that bound could first reach zero (quadratic convergence
// to a crossing, and no crossing is stepped over, however shallow or brief).
double first_rest_failure(const GroundMotion& g, double c, double t0, double t1);
// The same with a resistance that depends on the direction (an asymmetric assembly): rest fails
// where a_H > c_pos (1 + a_V) or -a_H > c_neg (1 + a_V).
double first_rest_failure(const GroundMotion& g, double c_pos, double c_neg, double t0, double t1);

// The search for one model (built once per run). checkpoint(t): where a block at rest at t must
// next be looked at: its first failure of rest, or the end of a look-ahead span after which the
// search goes on (kRestLookahead of the input's shortest period or pulse duration). A
// piecewise-linear input (constants, records) makes each condition linear between breakpoints,
// so a failure inside a piece shows at one of its ends: the breakpoints at which rest fails
// (either side) are listed once, and each query searches only the piece before the next of them
// (O(log n) per query instead of a scan of the record).
class RestExit {
 public:
  RestExit() = default;
  RestExit(const GroundMotion& g, double c);
  RestExit(const GroundMotion& g, double c_pos, double c_neg);
  double checkpoint(double t) const;

 private:
  GroundMotion g_;  // a copy (records are shared): the search outlives no model it serves
  bool active_ = false;
  double c_pos_ = 0.0, c_neg_ = 0.0;
  bool piecewise_linear_ = false;
  std::vector<double> fail_, before_;  // failing breakpoints and the breakpoint before each
};
inline constexpr double kRestLookahead = 16.0;

}  // namespace blockdyn
