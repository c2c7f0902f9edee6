// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/masonry/limit_analysis.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <stdexcept>

#include "blockdyn/model/assembly/interface_faces.hpp"

namespace blockdyn {

namespace {

// The lambda at which the programme's bound stands for "no mechanism" (rest_limit.cpp's cap).
constexpr double kNoMechanism = 1e6;
// Rates below this fraction of the mechanism's largest point speed are zero.
constexpr double kRateZero = 1e-7;

Vec2 velocity_at(const std::vector<double>& u, const StaticProblem& sp, int b, const Vec2& P) {
  if (b < 0) return {};
  return point_velocity(u[3 * b], u[3 * b + 1], u[3 * b + 2], P - sp.centre[b]);
}

}  // namespace

StaticProblem static_problem_at_start(const Assembly& a) {
  StaticProblem sp;
  sp.g = a.g;
  for (const AssemblyBlock& k : a.blocks) {
    sp.mass.push_back(k.mass);
    sp.centre.push_back({k.x, k.y});
  }
  for (int j = 0; j < int(a.interfaces.size()); ++j) {
    const AssemblyInterface& f = a.interfaces[j];
    const InterfaceFaces faces = interface_faces(a, j);
    const Face L = face_at(initial_pose(a, f.lower), faces.lower), U = face_at(initial_pose(a, f.upper), faces.upper);
    sp.mu.push_back(f.law.mu_s);
    for (int end = 0; end < 2; ++end) {
      const int side = end == 0 ? -1 : +1;
      StaticContact c;
      c.upper = f.upper;
      c.lower = f.lower;
      c.iface = j;
      // The end of the overlap: the upper block's corner on the lower face, or past the lower
      // face's end the lower block's corner on the upper face.
      if (owner_margin(L, U, end, 0) >= 0) {
        c.P = face_corner(U, side);
        c.n = L.n;
        c.t = L.t;
      } else {
        c.P = face_corner(L, side);
        c.n = -1.0 * U.n;
        c.t = U.t;
      }
      sp.contacts.push_back(c);
    }
  }
  return sp;
}

LimitAnalysis limit_analysis(const Assembly& a, int direction, bool exact) {
  if (direction != 1 && direction != -1)
    throw std::invalid_argument("direction = " + std::to_string(direction) + " must be 1 or -1");
  const StaticProblem sp = static_problem_at_start(a);
  const LoadMultiplier lm = max_load_multiplier(sp, direction, exact);
  LimitAnalysis out;
  out.direction = direction;
  if (!lm.feasible) return out;
  out.lambda = lm.lambda;
  out.status = lm.lambda < 0 ? "unstable" : lm.lambda >= kNoMechanism * (1 - 1e-12) ? "no_mechanism" : "ok";
  const int nb = int(a.blocks.size()), ni = int(a.interfaces.size());
  // The mechanism, scaled so that its fastest point moves at unit speed.
  std::vector<double> u = lm.mechanism;
  double top = 0;
  for (int b = 0; b < nb; ++b)
    for (const Vec2& v : initial_outline(a.blocks[b])) {
      const Vec2 w = velocity_at(u, sp, b, v);
      top = std::fmax(top, std::hypot(w.x, w.y));
    }
  if (top > 0)
    for (double& v : u) v /= top;
  out.mechanism = u;
  for (int j = 0; j < ni; ++j) {
    InterfaceMotion m;
    InterfaceThrust th;
    double slip = 0;
    for (int end = 0; end < 2; ++end) {
      const StaticContact& c = sp.contacts[2 * j + end];
      const Vec2 rel = velocity_at(u, sp, c.upper, c.P) - velocity_at(u, sp, c.lower, c.P);
      m.normal_rate[end] = dot(rel, c.n);
      slip += 0.5 * dot(rel, c.t);
      th.normal[end] = lm.normal[2 * j + end];
      th.point[end] = c.P;
    }
    m.slip_rate = slip;
    const bool open0 = m.normal_rate[0] > kRateZero, open1 = m.normal_rate[1] > kRateZero;
    if (std::fabs(slip) > kRateZero) {
      m.state = "sliding";
      out.sliding = true;
    } else if (open0 && open1) {
      m.state = "separating";
    } else if (open0 || open1) {
      m.state = "hinge";
      m.hinge_end = open0 ? 1 : 0;
    } else {
      m.state = "closed";
    }
    out.interfaces.push_back(m);
    th.tangential = lm.tangential[j];
    const double n_sum = th.normal[0] + th.normal[1];
    th.bears = n_sum > 0;
    const Vec2 mid = 0.5 * (th.point[0] + th.point[1]);
    th.centre = th.bears ? (1.0 / n_sum) * (th.normal[0] * th.point[0] + th.normal[1] * th.point[1]) : mid;
    const Vec2 half = 0.5 * (th.point[1] - th.point[0]);
    const double hl = std::hypot(half.x, half.y);
    th.eccentricity = hl > 0 ? dot(th.centre - mid, half) / (hl * hl) : 0.0;
    out.thrust.push_back(th);
  }
  out.exact_for_non_associative = out.status == "ok" && !out.sliding;
  return out;
}

namespace {

// The root of the margin extrapolated from the standing arches (ratio, margin), thinnest first:
// the quadratic through the three thinnest, the secant through two; NaN without one.
double root_estimate(const std::vector<std::pair<double, double>>& standing) {
  if (standing.size() < 2) return double(NAN);
  const auto [t1, f1] = standing[0];
  const auto [t2, f2] = standing[1];
  const double a = (f2 - f1) / (t2 - t1);
  if (standing.size() >= 3) {
    const auto [t3, f3] = standing[2];
    const double b = ((f3 - f2) / (t3 - t2) - a) / (t3 - t1);
    // f1 + a x + b x (x + t1 - t2) = 0 with x = t - t1 < 0: the root nearest x = 0.
    const double B = a + b * (t1 - t2), disc = B * B - 4.0 * b * f1;
    if (b != 0.0 && disc >= 0.0) {
      const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B));
      const double r1 = q / b, r2 = f1 / q;
      const double x = std::fabs(r1) < std::fabs(r2) ? r1 : r2;
      if (std::isfinite(x)) return t1 + x;
    }
  }
  return a > 0 ? t1 - f1 / a : double(NAN);
}

}  // namespace

MinThickness min_thickness_ratio(const PresetOptions& arch, double tol) {
  if (!(tol > 0 && tol < 0.1)) throw std::invalid_argument("tolerance must be in (0, 0.1)");
  MinThickness out;
  auto build = [&](double ratio) {
    PresetOptions o = arch;
    o.thickness_ratio = ratio;
    Assembly a = make_preset("arch", o);
    validate(a, kMaxStaticBlocks);
    return a;
  };
  // The margin of an arch of this thickness: the smaller load multiplier of the two directions
  // (negative: it cannot stand under its own weight; NaN: no equilibrium at all). It rises with
  // the thickness through 0 at the minimum.
  struct Trial {
    double margin;
    LimitAnalysis analysis;
    Assembly arch;
  };
  auto trial = [&](double ratio) {
    ++out.evaluations;
    Trial t{NAN, {}, build(ratio)};
    // The floating-point simplex: its 1e-9 on lambda is far inside the search's tolerance.
    const LimitAnalysis pos = limit_analysis(t.arch, +1, false), neg = limit_analysis(t.arch, -1, false);
    t.analysis = pos.lambda <= neg.lambda ? pos : neg;
    const bool feasible = !pos.interfaces.empty() && !neg.interfaces.empty();
    if (feasible) t.margin = std::fmin(pos.lambda, neg.lambda);
    return t;
  };
  auto stands = [](const Trial& t) { return t.margin >= 0.0; };
  double hi = 1.9, lo = 0.02;
  Trial th = trial(hi);
  if (!stands(th))
    throw std::invalid_argument("the arch does not stand under its own weight even at thickness-ratio = 1.9");
  // A flat arch stands thinner than a semicircular one: halve until it falls (or its voussoirs
  // fall below the smallest block size, 1 mm, where the search stops at the last ratio tried).
  Trial tl;
  while (true) {
    try {
      tl = trial(lo);
    } catch (const std::invalid_argument&) {
      throw std::invalid_argument("the arch stands at thickness-ratio = " + number_text(hi, 6) +
                                  " and its voussoirs are too thin to try less (1 mm)");
    }
    if (!stands(tl)) break;
    hi = lo;
    th = std::move(tl);
    lo *= 0.5;
  }
  // Below the minimum no equilibrium exists at all (the programme is infeasible): the margin is
  // known on the standing side only, where it falls smoothly to 0. The quadratic through the three
  // thinnest standing arches (the secant through two, at first) extrapolates to the root; a trial a
  // quarter tolerance above that estimate, then one below it, brackets the root in two steps once
  // the estimate is good; an estimate outside the bracket splits it instead.
  std::vector<std::pair<double, double>> standing{{hi, th.margin}};  // (ratio, margin), thinnest first
  auto try_at = [&](double t) {
    Trial x = trial(t);
    if (!stands(x)) {
      lo = t;
      return false;
    }
    hi = t;
    standing.insert(standing.begin(), {t, x.margin});
    th = std::move(x);
    return true;
  };
  while (hi - lo > tol && out.evaluations < 200) {
    double est = root_estimate(standing);
    const double inset = std::fmin(0.25 * tol, 0.25 * (hi - lo));
    // Without an estimate, the bracket's geometric middle (thicknesses span two decades).
    if (!(est > lo + inset && est < hi - inset)) est = hi > 2.0 * lo ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
    const double above = std::fmin(hi - inset, est + 0.25 * tol);
    if (!try_at(above) || hi - lo <= tol || standing.size() < 2) continue;
    // The trial below the estimate only where the one above it lies within a tolerance of the
    // root, as the local slope puts it (else a better estimate comes first).
    const double slope = (standing[1].second - standing[0].second) / (standing[1].first - standing[0].first);
    if (slope > 0 && standing[0].second / slope < tol) try_at(std::fmax(lo + inset, est - 0.25 * tol));
  }
  out.ratio = hi;
  out.at_minimum = th.analysis;
  out.arch = th.arch;
  return out;
}

}  // namespace blockdyn
