// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/body_rest.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "blockdyn/base/number_text.hpp"
#include "blockdyn/excitation/first_failure.hpp"
#include "blockdyn/excitation/rest_exit.hpp"

namespace blockdyn {

namespace {

// One rest condition f(t) = c (1 + a_V) - u . a_H (linear), c (1 + a_V) - |a_H| (norm), or
// 1 + a_V (vertical), in the world frame; a_H = a_h(t) dh + a_h2(t) dh2.
struct Body3dRestCondition {
  enum Kind { Linear, Norm, Vertical };
  // What failing means: lifting (the ground falls faster than g), sliding, rocking about the rim,
  // or rocking with the ground beyond the threshold towards +e1, +e2, -e1, -e2.
  enum Role { Lifts, Slides, RocksRim, RocksPosX, RocksPosY, RocksNegX, RocksNegY };
  const GroundMotion3d* g = nullptr;
  Kind kind = Vertical;
  Role role = Lifts;
  double c = 0;
  double ux = 0, uy = 0;  // linear: u in the (dh, dh2) frame
  double value(double t) const {
    const double gv = 1.0 + g->v.at(t);
    if (kind == Vertical) return gv;
    const double h = g->h.at(t), h2 = g->h2.at(t);
    return c * gv - (kind == Linear ? ux * h + uy * h2 : std::hypot(h, h2));
  }
  bool fails(double t) const {
    const double v = value(t);
    return kind == Vertical ? !(v > 0.0) : !(v >= 0.0);
  }
  double rate(double t) const {
    const double rv = g->v.rate(t);
    if (kind == Vertical) return rv;
    const double rh = g->h.rate(t), rh2 = g->h2.rate(t);
    return c * rv - (kind == Linear ? ux * rh + uy * rh2 : std::hypot(rh, rh2));
  }
  double curvature() const {
    const double mv = g->v.curvature_bound(), mh = g->h.curvature_bound(), mh2 = g->h2.curvature_bound();
    if (kind == Vertical) return mv;
    return c * mv + (kind == Linear ? std::fabs(ux) * mh + std::fabs(uy) * mh2 : std::hypot(mh, mh2));
  }
};

// The conditions of a body turned by yaw: (kind, c, u) with u the body axis in the (dh, dh2) frame.
template <class F>
void for_each_condition(const Body3d& b, double mu_s, const GroundMotion3d& g, double yaw, F&& f) {
  using C = Body3dRestCondition;
  f(C{&g, C::Vertical, C::Lifts});
  f(C{&g, C::Norm, C::Slides, mu_s});
  if (b.shape == BodyShape3d::Cylinder) {
    f(C{&g, C::Norm, C::RocksRim, 2 * b.radius / b.height});
    return;
  }
  // e1 and e2 in the (dh, dh2) frame of the ground motion's components.
  const double rel = yaw - g.azimuth * (M_PI / 180), cr = std::cos(rel), sr = std::sin(rel);
  const double kx = b.width / b.height, ky = b.depth / b.height;
  f(C{&g, C::Linear, C::RocksPosX, kx, cr, sr});
  f(C{&g, C::Linear, C::RocksPosY, ky, -sr, cr});
  f(C{&g, C::Linear, C::RocksNegX, kx, -cr, -sr});
  f(C{&g, C::Linear, C::RocksNegY, ky, sr, -cr});
}

// Axis conditions this close to failing (relative to their coefficient) when another fails fail
// with it: the body leaves on the corner between them.
constexpr double kSimultaneous = 1e-12;

}  // namespace

BodyRestSearch::BodyRestSearch(const Body3d& b, double mu_s, const GroundMotion3d& g, double yaw_hint)
    : body_(b), mu_s_(mu_s), g_(g), yaw_hint_(yaw_hint) {
  listed_ = !g_.is_zero() && g_.h.piecewise_linear() && g_.h2.piecewise_linear() && g_.v.piecewise_linear();
  if (!listed_) return;
  auto holds = [&](double t) { return failure(t, yaw_hint_).way == RestExitWay::None; };
  list_failing_breakpoints([&](double t) { return g_.next_break(t); }, holds, {&g_.h, &g_.h2, &g_.v}, fail_, before_);
}

RestFailure BodyRestSearch::failure(double t, double yaw) const {
  using C = Body3dRestCondition;
  RestFailure out;
  bool rocks = false, slides = false, lifts = false;
  int near_x = 0, near_y = 0;  // box: an axis condition within rounding of failing
  for_each_condition(body_, mu_s_, g_, yaw, [&](const C& c) {
    const bool fails = c.fails(t);
    if (c.role >= C::RocksPosX) {
      // Two axis conditions crossing at one instant (a corner) cross a few ulps apart in floating point.
      const bool near = c.value(t) <= kSimultaneous * c.c;
      const int side = c.role == C::RocksPosX || c.role == C::RocksPosY ? 1 : -1;
      if (near) (c.role == C::RocksPosX || c.role == C::RocksNegX ? near_x : near_y) = side;
    }
    if (!fails) return;
    switch (c.role) {
      case C::Lifts:
        lifts = true;
        break;
      case C::Slides:
        slides = true;
        break;
      case C::RocksRim:
        rocks = true;
        break;
      case C::RocksPosX:
        rocks = true, out.x_side = 1;
        break;
      case C::RocksNegX:
        rocks = true, out.x_side = -1;
        break;
      case C::RocksPosY:
        rocks = true, out.y_side = 1;
        break;
      case C::RocksNegY:
        rocks = true, out.y_side = -1;
        break;
    }
  });
  if (out.x_side != 0 || out.y_side != 0) {
    if (out.x_side == 0) out.x_side = near_x;
    if (out.y_side == 0) out.y_side = near_y;
  }
  const double az = g_.azimuth * (M_PI / 180), h = g_.h.at(t), h2 = g_.h2.at(t);
  out.towards = {h * std::cos(az) - h2 * std::sin(az), h * std::sin(az) + h2 * std::cos(az), 0};
  out.way = lifts ? RestExitWay::Lifts : rocks ? RestExitWay::Rocks : slides ? RestExitWay::Slides : RestExitWay::None;
  return out;
}

double BodyRestSearch::first_failure(double yaw, double t0, double t1) const {
  if (g_.is_zero()) return INFINITY;
  // The conditions once (their directions need the yaw's sine and cosine), then piece by piece.
  std::array<Body3dRestCondition, 7> conditions{};
  std::size_t n = 0;
  for_each_condition(body_, mu_s_, g_, yaw, [&](const Body3dRestCondition& c) { conditions[n++] = c; });
  double t = t0;
  while (t < t1) {
    const double b = std::fmin(g_.next_break(t), t1);
    double first = INFINITY;
    for (std::size_t i = 0; i < n; ++i) first = std::fmin(first, first_failure_on_piece(conditions[i], t, b));
    if (first < b) return first;
    if (b >= t1) break;
    t = b;  // at the breakpoint itself (a jump of the input) the next piece's first value decides
  }
  return INFINITY;
}

double BodyRestSearch::checkpoint(double t, double yaw) const {
  if (g_.is_zero()) return INFINITY;
  if (listed_ && std::fabs(yaw - yaw_hint_) <= 1e-12) {
    // Rest holds on every piece before the one that ends at the next failing breakpoint (and
    // from t = 0 to the first breakpoint and after the last: linear there too).
    const auto it = std::upper_bound(fail_.begin(), fail_.end(), t);
    if (it == fail_.end()) return INFINITY;  // every later breakpoint holds, so every later piece
    const double tb = *it, from = std::fmax(t, before_[std::size_t(it - fail_.begin())]);
    return std::fmin(first_failure(yaw, from, tb), tb);
  }
  const double scale = std::fmin(std::fmin(g_.h.time_scale(), g_.h2.time_scale()), g_.v.time_scale());
  const double t1 = t + kRestLookahead * scale;  // infinite for records and constants: to the end
  return std::fmin(first_failure(yaw, t, t1), t1);
}

BodyRestExit first_rest_exit(const Body3d& b, double yaw, double mu_s, const GroundMotion3d& g, double t0, double t1) {
  validate(b);
  validate(g);
  if (!(mu_s >= 0 && std::isfinite(mu_s)))
    throw std::invalid_argument("mu-s = " + number_text(mu_s) + " is out of range: finite and >= 0");
  const BodyRestSearch search(b, mu_s, g);
  BodyRestExit out;
  out.t = search.first_failure(yaw, t0, t1);
  if (std::isfinite(out.t)) out.way = search.failure(out.t, yaw).way;
  return out;
}

}  // namespace blockdyn
