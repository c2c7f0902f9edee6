// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/excitation/rest_exit.hpp"

#include "blockdyn/excitation/first_failure.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace blockdyn {

namespace {

// One condition f(t) = c (1 + a_V) - sigma a_H (sigma = +-1), or 1 + a_V (sigma = 0), that must
// stay >= 0 (> 0 for the second): its value and rate, and a bound on its curvature.
struct RestCondition {
  const GroundMotion& g;
  double c;
  int sigma;
  double value(double t) const { return sigma == 0 ? 1.0 + g.av(t) : c * (1.0 + g.av(t)) - sigma * g.ah(t); }
  bool fails(double t) const {
    const double v = value(t);
    return sigma == 0 ? !(v > 0.0) : !(v >= 0.0);
  }
  double rate(double t) const {
    return sigma == 0 ? g.vertical.rate(t) : c * g.vertical.rate(t) - sigma * g.horizontal.rate(t);
  }
  double curvature() const {
    return sigma == 0 ? g.vertical.curvature_bound()
                      : c * g.vertical.curvature_bound() + g.horizontal.curvature_bound();
  }
};

}  // namespace

double first_rest_failure(const GroundMotion& g, double c, double t0, double t1) {
  return first_rest_failure(g, c, c, t0, t1);
}

double first_rest_failure(const GroundMotion& g, double c_pos, double c_neg, double t0, double t1) {
  double t = t0;
  while (t < t1) {
    const double b = std::fmin(g.next_break(t), t1);
    double first = INFINITY;
    for (int sigma : {1, -1, 0}) {
      if (sigma != 0 && g.horizontal.is_zero() && g.vertical.is_zero()) continue;
      first = std::fmin(first, first_failure_on_piece(RestCondition{g, sigma < 0 ? c_neg : c_pos, sigma}, t, b));
    }
    if (first < b) return first;
    if (b >= t1) break;
    // At the breakpoint itself (a jump of the input) the next piece's first value decides.
    t = b;
  }
  return INFINITY;
}

RestExit::RestExit(const GroundMotion& g, double c) : RestExit(g, c, c) {}

RestExit::RestExit(const GroundMotion& g, double c_pos, double c_neg)
    : g_(g), active_(true), c_pos_(c_pos), c_neg_(c_neg), piecewise_linear_(g.piecewise_linear()) {
  if (!piecewise_linear_) return;
  auto holds = [&](double t) {
    const double gv = 1.0 + g.av(t), a = g.ah(t);
    return gv > 0.0 && c_pos * gv - a >= 0.0 && c_neg * gv + a >= 0.0;
  };
  list_failing_breakpoints([&](double t) { return g.next_break(t); }, holds, {&g.horizontal, &g.vertical}, fail_,
                           before_);
}

double RestExit::checkpoint(double t) const {
  if (!active_) return INFINITY;
  if (!piecewise_linear_) {
    const double span = kRestLookahead * std::fmin(g_.horizontal.time_scale(), g_.vertical.time_scale());
    const double t1 = t + span;
    return std::fmin(first_rest_failure(g_, c_pos_, c_neg_, t, t1), t1);
  }
  // Rest holds on every piece before the one that ends at the next failing breakpoint.
  // (From t = 0 to the first breakpoint and after the last one the input is linear too: rest
  // holds there if it holds at their ends.)
  const auto it = std::upper_bound(fail_.begin(), fail_.end(), t);
  if (it == fail_.end()) return INFINITY;
  const double tb = *it;
  const double from = std::fmax(t, before_[std::size_t(it - fail_.begin())]);
  // A failure seen only in the left limit at tb (a jump back to rest) leaves tb as the checkpoint.
  return std::fmin(first_rest_failure(g_, c_pos_, c_neg_, from, tb), tb);
}

}  // namespace blockdyn
