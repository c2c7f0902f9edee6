// SPDX-License-Identifier: Apache-2.0
#pragma once
// The first time a condition f(t) >= 0 of the ground motion fails, found on the input itself
// (excitation/rest_exit.hpp). Between breakpoints f is bounded below by its value, its rate and
// a bound M on its curvature (f(t + s) >= f(t) + f'(t) s - M s^2 / 2): the search steps to where
// that bound could first reach zero, so no crossing is stepped over, however shallow or brief,
// and it converges to the crossing (quadratically where the rate is exact). The rate may be any
// lower bound of the true one that keeps the inequality valid (a norm's rate, say).
#include <cmath>
#include <initializer_list>
#include <limits>
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"

namespace blockdyn {

// Condition: double value(t), double rate(t), double curvature(), bool fails(t).
// The first failure in [a, b) (an interval free of breakpoints; at the time returned the
// condition has failed, within a few ulps of the crossing), or infinity.
template <class Condition>
double first_failure_on_piece(const Condition& f, double a, double b) {
  const double M = f.curvature();
  double t = a;
  // Each iteration either moves at least a few ulps or ends; the count bounds a pathological input.
  for (int it = 0; it < 100000; ++it) {
    if (f.fails(t)) return t;
    const double v = f.value(t), d = f.rate(t);
    // Smallest s > 0 at which v + d s - M s^2 / 2 (a lower bound of f) may reach zero.
    double s;
    if (M > 0.0) {
      const double q = std::sqrt(d * d + 2.0 * M * v);
      s = d <= 0.0 ? 2.0 * v / (q - d) : (d + q) / M;
    } else {
      s = d < 0.0 ? v / -d : INFINITY;
    }
    if (!(s == s)) s = 0.0;  // NaN (non-finite input): probe pointwise below
    const double tiny = 64.0 * std::numeric_limits<double>::epsilon() * std::fmax(std::fabs(t), 1e-6);
    if (s > tiny) {
      if (!(t + s < b)) return INFINITY;
      t += s;
      continue;
    }
    // Within rounding of a crossing (or a tangency): probe just ahead.
    const double tp = t + tiny;
    if (!(tp < b)) return INFINITY;
    if (f.fails(tp)) {
      double lo = t, hi = tp;  // holds at lo, fails at hi: bisect to adjacent doubles
      while (true) {
        const double mid = lo + 0.5 * (hi - lo);
        if (!(mid > lo) || !(mid < hi)) break;
        (f.fails(mid) ? hi : lo) = mid;
      }
      return hi;
    }
    t = tp;
  }
  return t;  // not reached for a finite input; a safe answer: stop here and let the model decide
}

// For a piecewise-linear input (records, constants), whose conditions are concave between
// breakpoints: the breakpoints at which `holds(t)` fails, or fails just before (the input jumps
// only at the components' window ends), each with the breakpoint before it. `next_break(t)` is the
// input's first breakpoint after t.
template <class NextBreak, class Holds>
void list_failing_breakpoints(NextBreak&& next_break, Holds&& holds,
                              std::initializer_list<const GroundComponent*> components, std::vector<double>& fail,
                              std::vector<double>& before) {
  auto window_end = [&](double t) {
    for (const GroundComponent* k : components)
      if (!k->is_zero() && (t == k->t_start || t == k->t_stop())) return true;
    return false;
  };
  double prev = 0.0;
  for (double tb = next_break(0.0); std::isfinite(tb); tb = next_break(tb)) {
    if (!holds(tb) || (window_end(tb) && !holds(std::nextafter(tb, -INFINITY)))) {
      fail.push_back(tb);
      before.push_back(prev);
    }
    prev = tb;
  }
}

}  // namespace blockdyn
