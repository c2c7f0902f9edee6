// SPDX-License-Identifier: Apache-2.0
// Validation of the Region geometry (issue 2, item 1): the closed-form integrals of
// geometry/region.cpp against an independent computation of the lower envelope of the rotated
// rectangle, the closed forms of the spec, symmetry, continuity at border states, and the
// energy derivatives of the foundation force (Ry = -dV/dh, non-potential torque).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/foundation_force.hpp"
#include "blockdyn/model/winkler/region.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

// ---- Independent reference -------------------------------------------------------------
// The rectangle's corners from a plain rotation; the envelope y_low(X) as the lowest crossing
// of the vertical line X with the four edges; integrals by Simpson's rule on pieces split at
// every corner abscissa and at every surface crossing (found by bisection). On each piece the
// compression is linear, so Simpson is exact up to rounding: this is a second, independent
// way to the same numbers, sharing no code with region.cpp.
struct Ref {
  double area = 0, moment = 0, s2 = 0;
  int below = 0;
};

struct Poly {
  double cx[4], cy[4];
};

Poly corners(double r, double h, double w) {
  Poly p;
  const double bx[4] = {-r / 2, r / 2, r / 2, -r / 2}, by[4] = {-0.5, -0.5, 0.5, 0.5};
  for (int i = 0; i < 4; ++i) {
    p.cx[i] = bx[i] * std::cos(w) - by[i] * std::sin(w);
    p.cy[i] = (h + 0.5) + bx[i] * std::sin(w) + by[i] * std::cos(w);
  }
  return p;
}

double compression(const Poly& p, double X) {
  double ylow = INFINITY;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double x0 = p.cx[i], x1 = p.cx[j];
    const double lo = std::min(x0, x1), hi = std::max(x0, x1);
    if (X < lo || X > hi || x0 == x1) continue;
    const double u = (X - x0) / (x1 - x0);
    ylow = std::min(ylow, p.cy[i] + u * (p.cy[j] - p.cy[i]));
  }
  return std::isfinite(ylow) ? std::max(0.0, -ylow) : 0.0;
}

// Signed envelope height (negative below the surface), for locating surface crossings.
double envelope(const Poly& p, double X) {
  double ylow = INFINITY;
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    const double x0 = p.cx[i], x1 = p.cx[j];
    if (X < std::min(x0, x1) || X > std::max(x0, x1) || x0 == x1) continue;
    ylow = std::min(ylow, p.cy[i] + (X - x0) / (x1 - x0) * (p.cy[j] - p.cy[i]));
  }
  return ylow;
}

Ref reference(double r, double h, double w) {
  const Poly p = corners(r, h, w);
  std::vector<double> xs(p.cx, p.cx + 4);
  std::sort(xs.begin(), xs.end());
  std::vector<double> cuts(xs.begin(), xs.end());
  for (int i = 0; i + 1 < 4; ++i) {  // surface crossings inside each linear piece
    double a = xs[i], b = xs[i + 1];
    if (b - a <= 0) continue;
    const double ea = envelope(p, a), eb = envelope(p, b);
    if ((ea < 0) == (eb < 0)) continue;
    for (int it = 0; it < 200 && b - a > 1e-17; ++it) {
      const double m = 0.5 * (a + b);
      if ((envelope(p, m) < 0) == (ea < 0))
        a = m;
      else
        b = m;
    }
    cuts.push_back(0.5 * (a + b));
  }
  std::sort(cuts.begin(), cuts.end());
  Ref out;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double a = cuts[i], b = cuts[i + 1], L = b - a;
    if (L <= 0) continue;
    const double m = 0.5 * (a + b);
    // Interior points only (the envelope may jump at a vertical wall at the piece ends).
    const double e = 1e-12 * L;
    const double sa = compression(p, a + e), sm = compression(p, m), sb = compression(p, b - e);
    out.area += L / 6 * (sa + 4 * sm + sb);
    out.moment += L / 6 * (a * sa + 4 * m * sm + b * sb);
    out.s2 += L / 6 * (sa * sa + 4 * sm * sm + sb * sb);
  }
  for (int i = 0; i < 4; ++i) out.below += int(p.cy[i] < 0);
  return out;
}

// Heights of the three lowest corners above the lowest one, for tilt a = |w|.
struct Gaps {
  double other_bottom, upper_pivot;
};
Gaps gaps(double r, double a) { return {r * std::sin(a), std::cos(a)}; }

// h (= y - 1/2) that puts the lowest corner at depth d below the surface.
double h_for_depth(double r, double w, double d) {
  const double a = std::fabs(w);
  return 0.5 * (std::cos(a) + r * std::sin(a)) - 0.5 - d;
}

struct Pose {
  double r, w, h, d;
  int submerged;
};

// Random poses with one or two submerged corners, kept away from the borders between cases.
std::vector<Pose> random_poses(int n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  std::vector<Pose> out;
  while (int(out.size()) < n) {
    const double r = 0.05 + (3.0 - 0.05) * U(rng);
    const double alpha = std::atan(r);
    const double w = (2 * U(rng) - 1) * alpha * 0.999;
    if (std::fabs(w) < 1e-3) continue;
    const Gaps g = gaps(r, std::fabs(w));
    const double d1 = std::min(g.other_bottom, g.upper_pivot), d2 = std::max(g.other_bottom, g.upper_pivot);
    const int submerged = 1 + int(out.size() % 2);
    const double lo = submerged == 1 ? 0.0 : d1, hi = submerged == 1 ? d1 : d2;
    const double d = lo + (hi - lo) * (0.02 + 0.96 * U(rng));
    out.push_back({r, w, h_for_depth(r, w, d), d, submerged});
  }
  return out;
}

}  // namespace

TEST(Geometry, ClosedFormsMatchIndependentEnvelopeOnRandomPoses) {
  const auto poses = random_poses(4000, 20240611u);
  double worst_area = 0, worst_moment = 0, worst_s2 = 0;
  int n1 = 0, n2 = 0;
  for (const Pose& q : poses) {
    const RegionIntegrals c = region_integrals(q.r, q.h, q.w);
    const Ref ref = reference(q.r, q.h, q.w);
    ASSERT_EQ(c.corners_below, q.submerged) << "r=" << q.r << " w=" << q.w << " d=" << q.d;
    ASSERT_EQ(ref.below, q.submerged);
    (q.submerged == 1 ? n1 : n2)++;
    // Scales: area ~ width * depth, moment ~ area * width, s2 ~ area * depth.
    const double width = q.r + 1.0;
    worst_area = std::max(worst_area, std::fabs(c.area - ref.area) / ref.area);
    worst_moment = std::max(worst_moment, std::fabs(c.moment - ref.moment) / (ref.area * width));
    worst_s2 = std::max(worst_s2, std::fabs(c.s2 - ref.s2) / ref.s2);
  }
  record("worst_rel_area", worst_area);
  record("worst_rel_moment", worst_moment);
  record("worst_rel_s2", worst_s2);
  EXPECT_EQ(n1, 2000);
  EXPECT_EQ(n2, 2000);
  EXPECT_LT(worst_area, 1e-10);
  EXPECT_LT(worst_moment, 1e-10);
  EXPECT_LT(worst_s2, 1e-10);
}

TEST(Geometry, ClosedFormsMatchLibraryBruteForceQuadrature) {
  // The midpoint quadrature shipped for tests: a coarse but fully separate check, including
  // the moment's sign for w < 0. Its error is first order in the cell width dx where the
  // Region ends in a vertical wall and second order at kinks: bounded by dx * depth per end.
  const int n = 20000;
  for (const Pose& q : random_poses(300, 7u)) {
    const RegionIntegrals c = region_integrals(q.r, q.h, q.w);
    const RegionIntegrals b = region_integrals_quadrature(q.r, q.h, q.w, n);
    const double a = std::fabs(q.w);
    const double dx = (q.r * std::cos(a) + std::sin(a)) / n;
    const double width = q.r + 1.0;
    EXPECT_NEAR(c.area, b.area, 2 * dx * q.d) << q.r << " " << q.w << " " << q.d;
    EXPECT_NEAR(c.moment, b.moment, 2 * dx * q.d * width);
    EXPECT_NEAR(c.s2, b.s2, 2 * dx * q.d * q.d);
    EXPECT_EQ(c.corners_below, b.corners_below);
  }
}

TEST(Geometry, MirrorSymmetry) {
  for (const Pose& q : random_poses(1000, 99u)) {
    const RegionIntegrals a = region_integrals(q.r, q.h, q.w), b = region_integrals(q.r, q.h, -q.w);
    EXPECT_DOUBLE_EQ(a.area, b.area);
    EXPECT_DOUBLE_EQ(a.s2, b.s2);
    EXPECT_DOUBLE_EQ(a.moment, -b.moment);
    // The reference knows nothing about the |w| folding of region.cpp.
    const Ref ra = reference(q.r, q.h, q.w), rb = reference(q.r, q.h, -q.w);
    EXPECT_NEAR(ra.area, rb.area, 1e-12 * ra.area);
    EXPECT_NEAR(ra.moment, -rb.moment, 1e-12 * ra.area * (1 + q.r));
  }
}

TEST(Geometry, UprightClosedForm) {
  for (double r : {0.05, 0.3, 1.0, 2.7}) {
    for (double h : {-1e-9, -1e-5, -0.01, -0.3}) {
      const RegionIntegrals c = region_integrals(r, h, 0.0);
      // y = 1/2 + h: area r (1/2 - y) = -r h, s^2 integral r h^2, centroid under the centre.
      EXPECT_NEAR(c.area, -r * h, 1e-15 * r * std::fabs(h));
      EXPECT_NEAR(c.s2, r * h * h, 1e-15 * r * h * h);
      EXPECT_EQ(c.moment, 0.0);
      EXPECT_EQ(c.corners_below, 2);
    }
    EXPECT_EQ(region_integrals(r, 1e-12, 0.0).area, 0.0);
  }
}

TEST(Geometry, OneCornerClosedFormAndSpringEnergy) {
  for (const Pose& q : random_poses(2000, 5u)) {
    if (q.submerged != 1) continue;
    const double a = std::fabs(q.w);
    const double sc = std::sin(a) * std::cos(a);
    // Depth from the library's own corner heights (exact in h), so rounding in h_for_depth
    // does not enter the comparison.
    const double d = -corner_heights(q.r, q.h, q.w).lowest;
    EXPECT_NEAR(d, q.d, 1e-12);
    const RegionIntegrals c = region_integrals(q.r, q.h, q.w);
    EXPECT_NEAR(c.area, d * d / (2 * sc), 1e-12 * c.area);
    const WinklerParams p{q.r, 0.0, 1e4};
    EXPECT_NEAR(spring_energy(p, q.h, q.w), p.k * d * d * d / (6 * q.r * sc), 1e-12 * spring_energy(p, q.h, q.w));
  }
}

TEST(Geometry, ContinuousAcrossBorderStates) {
  // A second corner exactly at the surface: the one- and two-corner formulas must agree there,
  // and the integrals and the wetted width (dArea/dh) must be continuous through the border.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> U(0.0, 1.0);
  for (int n = 0; n < 500; ++n) {
    const double r = 0.05 + 2.9 * U(rng);
    const double w = (U(rng) < 0.5 ? -1 : 1) * std::atan(r) * (0.01 + 0.98 * U(rng));
    const Gaps g = gaps(r, std::fabs(w));
    const double db = std::min(g.other_bottom, g.upper_pivot);  // second corner at the surface
    const double hb = h_for_depth(r, w, db);
    const double sc = std::sin(std::fabs(w)) * std::cos(w);
    const RegionIntegrals at = region_integrals(r, hb, w);
    const double d = -corner_heights(r, hb, w).lowest;
    EXPECT_NEAR(at.area, d * d / (2 * sc), 1e-10 * at.area) << r << " " << w;
    const double del = 1e-9 * db;
    const RegionIntegrals above = region_integrals(r, hb + del, w), below = region_integrals(r, hb - del, w);
    const double width = std::fabs(d / std::tan(std::fabs(w))) + std::fabs(d * std::tan(std::fabs(w)));
    EXPECT_NEAR(above.area, below.area, 4 * width * del + 1e-13 * at.area);
    EXPECT_NEAR(above.s2, below.s2, 4 * width * d * del + 1e-13 * at.s2);
    EXPECT_NEAR(above.moment, below.moment, 4 * width * (r + 1) * del + 1e-13 * at.area * (r + 1));
    // Wetted width from one-sided differences on each side of the border.
    const double e = 1e-6 * db;
    const double slope_out = (region_integrals(r, hb + 2 * e, w).area - region_integrals(r, hb + e, w).area) / e;
    const double slope_in = (region_integrals(r, hb - e, w).area - region_integrals(r, hb - 2 * e, w).area) / e;
    EXPECT_NEAR(slope_out, slope_in, 1e-4 * std::fabs(slope_in)) << r << " " << w;
  }
  // Tilt through zero: the tilted formulas tend to the upright ones.
  for (double r : {0.1, 1.0, 2.5}) {
    const double h = -3e-4;
    const RegionIntegrals up = region_integrals(r, h, 0.0);
    for (double w : {1e-13, -1e-13}) {
      const RegionIntegrals c = region_integrals(r, h, w);
      EXPECT_NEAR(c.area, up.area, 1e-12 * up.area);
      EXPECT_NEAR(c.s2, up.s2, 1e-12 * up.s2);
      // First order in w: linear pressure across the base (-w r^3/12) plus the base midpoint
      // sitting sin(w)/2 beside the centre (area * w / 2).
      EXPECT_NEAR(c.moment, -w * (r * r * r / 12 + r * h / 2),
                  1e-6 * std::fabs(w) * r * r * r + 1e-14 * r * up.area);  // + rounding of the sums
    }
  }
}

namespace {
// Central difference with one Richardson extrapolation (error O(step^4)).
template <class F>
double derivative(F&& f, double x, double step) {
  auto d = [&](double s) { return (f(x + s) - f(x - s)) / (2 * s); };
  return (4 * d(step / 2) - d(step)) / 3;
}
}  // namespace

TEST(Geometry, VerticalReactionIsMinusEnergyGradient) {
  for (const Pose& q : random_poses(400, 11u)) {
    const WinklerParams p{q.r, 0.0, 1.0};
    const FoundationForce f = foundation_force(p, q.h, q.w);
    const Gaps g = gaps(q.r, std::fabs(q.w));
    const double step = 1e-3 * std::min({q.d, std::fabs(q.d - g.other_bottom), std::fabs(q.d - g.upper_pivot)});
    const double dVdh = derivative([&](double h) { return spring_energy(p, h, q.w); }, q.h, step);
    EXPECT_NEAR(f.Ry, -dVdh, 1e-7 * f.Ry) << q.r << " " << q.w << " " << q.d;
  }
}

TEST(Geometry, NonPotentialTorqueIsTorquePlusEnergyGradient) {
  // torque_nonpot = torque + dV/dw: zero with one submerged corner (the model is conservative),
  // non-zero with two (the Region ends in a vertical wall), with dV/dw from finite differences.
  int two_nonzero = 0;
  for (const Pose& q : random_poses(600, 13u)) {
    const WinklerParams p{q.r, 0.0, 1.0};
    const FoundationForce f = foundation_force(p, q.h, q.w);
    const double torque_nonpot = f.torque_nonpot(q.w > 0.0 ? 1 : -1);  // the lowest corner's side
    // Step limited so that no corner crosses the surface within the stencil.
    const double a = std::fabs(q.w);
    const double margin = std::min({q.d, std::fabs(q.d - q.r * std::sin(a)), std::fabs(q.d - std::cos(a))});
    const double step = std::min(1e-3 * margin, 1e-3 * std::min(a, std::atan(q.r) - a));
    const double dVdw = derivative([&](double w) { return spring_energy(p, q.h, w); }, q.w, step);
    const double scale = std::fabs(f.torque) + std::fabs(dVdw);
    if (q.submerged == 1) {
      EXPECT_EQ(torque_nonpot, 0.0);
      EXPECT_NEAR(f.torque + dVdw, 0.0, 1e-7 * scale) << q.r << " " << q.w << " " << q.d;
    } else {
      EXPECT_NEAR(torque_nonpot, f.torque + dVdw, 1e-7 * scale) << q.r << " " << q.w << " " << q.d;
      if (std::fabs(torque_nonpot) > 1e-3 * scale) ++two_nonzero;
    }
    if (q.submerged == 2) {
      EXPECT_NE(torque_nonpot, 0.0);
    }
  }
  EXPECT_GT(two_nonzero, 100);  // the mismatch is a real effect, not rounding
}

// The tilt's sin and cos (every right-hand side takes one) against libm: within one ulp of
// std::sin / std::cos on 4 million angles over a quarter turn and a quarter radian beyond, in
// both branches (the series up to pi/4, the complement above), exact where the series is trivial
// (tiny angles), and libm's own answer outside the range (and NaN for NaN).
TEST(Geometry, QuarterTurnSincosIsWithinOneUlpOfLibm) {
  auto ulps = [](double got, double want) {
    if (got == want) return 0.0;
    return std::fabs(got - want) / (std::nextafter(std::fabs(want), INFINITY) - std::fabs(want));
  };
  const int n = 4'000'001;
  const double lo = -M_PI / 2 - 0.25, hi = M_PI / 2 + 0.25;
  double worst_s = 0.0, worst_c = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = lo + (hi - lo) * i / (n - 1);
    double s, c;
    sincos_quarter_turn(x, s, c);
    worst_s = std::fmax(worst_s, ulps(s, std::sin(x)));
    worst_c = std::fmax(worst_c, ulps(c, std::cos(x)));
  }
  EXPECT_LE(worst_s, 1.0);
  EXPECT_LE(worst_c, 1.0);
  for (const double x : {0.0, -0.0, 1e-300, -1e-20, 1e-9, 3.0, -10.0, 1e6}) {
    double s, c;
    sincos_quarter_turn(x, s, c);
    EXPECT_EQ(s, std::sin(x)) << x;
    EXPECT_EQ(c, std::cos(x)) << x;
  }
  double s, c;
  sincos_quarter_turn(NAN, s, c);
  EXPECT_TRUE(std::isnan(s) && std::isnan(c));
}
