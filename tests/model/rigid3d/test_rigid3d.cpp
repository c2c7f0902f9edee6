// SPDX-License-Identifier: Apache-2.0
// The rigid3d body (issue 40, first step): its geometry against brute force, the rest threshold
// by direction against a bisection on the resultant's line, and the flight mode against the
// conservation laws and the closed forms of torque-free motion (docs/3d.md).
#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <cmath>
#include <random>

#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "blockdyn/model/rigid3d/body_flight.hpp"
#include "blockdyn/model/rigid3d/body_rest.hpp"

namespace {

using blockdyn::Body3d;
using blockdyn::BodyFlight;
using blockdyn::BodyShape3d;
using blockdyn::Quat;
using blockdyn::Vec3;

Body3d box(double b, double d, double h) { return blockdyn::box_body(b, d, h, 250); }

Body3d cylinder(double a, double h) { return blockdyn::cylinder_body(a, h, 80); }

Quat random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return blockdyn::normalized({n(rng), n(rng), n(rng), n(rng)});
}

// Keeps the last segment's end; stops nothing.
struct Last {
  bool on_step(const blockdyn::DenseSegment<BodyFlight::kDim>&, double, double, const BodyFlight::Mode&) {
    return true;
  }
  bool on_event(const blockdyn::EventInfo<BodyFlight::Mode, BodyFlight::kDim>& e) {
    events.push_back(e.t);
    return true;
  }
  std::vector<double> events;
};

struct Flown {
  double t;
  BodyFlight::State z;
  std::vector<double> events;
  blockdyn::RunStatus status;
};

Flown fly(const BodyFlight& m, BodyFlight::State z, double t_end, double rtol = 1e-13, double atol = 1e-15) {
  // (the model's ground motion is the one it was built with)
  blockdyn::IntegratorOptions o;
  o.rtol = rtol;
  o.atol = atol;
  blockdyn::HybridIntegrator<BodyFlight> integ(m, o);
  BodyFlight::Mode mode;
  m.complete(mode, z);
  double t = 0;
  Last obs;
  const auto status = integ.run(t, t_end, mode, z, obs);
  return {t, z, obs.events, status};
}

TEST(Rigid3dGeometry, CylinderInertiaMatchesVolumeQuadrature) {
  const Body3d c = cylinder(0.3, 1.4);
  // I1 = integral of (y^2 + z^2) dm over the solid, by the midpoint rule in (r, phi, z).
  const int nr = 400, nf = 64, nz = 400;
  const double a = c.radius, h = c.height, rho = c.mass / (M_PI * a * a * h);
  double i1 = 0, i3 = 0;
  for (int i = 0; i < nr; ++i)
    for (int j = 0; j < nf; ++j)
      for (int k = 0; k < nz; ++k) {
        const double r = (i + 0.5) * a / nr, f = (j + 0.5) * 2 * M_PI / nf, z = -h / 2 + (k + 0.5) * h / nz;
        const double dm = rho * r * (a / nr) * (2 * M_PI / nf) * (h / nz);
        const double y = r * std::sin(f);
        i1 += (y * y + z * z) * dm;
        i3 += r * r * dm;
      }
  const Vec3 in = c.inertia();
  EXPECT_NEAR(in[0], i1, 1e-5 * in[0]);
  EXPECT_NEAR(in[1], i1, 1e-5 * in[1]);
  EXPECT_NEAR(in[2], i3, 1e-5 * in[2]);
}

TEST(Rigid3dGeometry, LowestPointIsTheLowestOfTheBaseBoundary) {
  std::mt19937_64 rng(40);
  const Body3d b = box(0.4, 0.7, 1.5), c = cylinder(0.25, 1.2);
  for (int n = 0; n < 200; ++n) {
    const auto r = blockdyn::rotation(random_orientation(rng));
    double best_box = -INFINITY;
    for (double sx : {-1.0, 1.0})
      for (double sy : {-1.0, 1.0}) {
        const Vec3 p{sx * b.width / 2, sy * b.depth / 2, -b.height / 2};
        best_box = std::fmax(best_box, -blockdyn::dot(r[2], p));
      }
    EXPECT_DOUBLE_EQ(blockdyn::lowest_point(b, r).depth, best_box);
    // The rim sampled finely: none lower than the closed form, the best within the sampling error.
    const blockdyn::LowestPoint lc = blockdyn::lowest_point(c, r);
    double best_rim = -INFINITY;
    for (int k = 0; k < 20000; ++k) {
      const double f = 2 * M_PI * k / 20000;
      const Vec3 p{c.radius * std::cos(f), c.radius * std::sin(f), -c.height / 2};
      best_rim = std::fmax(best_rim, -blockdyn::dot(r[2], p));
    }
    EXPECT_GE(lc.depth, best_rim - 1e-15);
    EXPECT_LT(lc.depth - best_rim, 0.5 * c.radius * std::pow(2 * M_PI / 20000, 2));
    EXPECT_NEAR(-blockdyn::dot(r[2], lc.body), lc.depth, 1e-15);
  }
}

// The ratio A / g at which the resultant's line leaves the base: bisection on whether the point
// where it meets the ground, -(A/g) c u from the base centre, lies in the base.
double threshold_by_bisection(const Body3d& b, double phi) {
  auto inside = [&](double lambda) {
    const double x = -lambda * b.half_height() * std::cos(phi), y = -lambda * b.half_height() * std::sin(phi);
    if (b.shape == BodyShape3d::Cylinder) return std::hypot(x, y) <= b.radius;
    return std::fabs(x) <= b.width / 2 && std::fabs(y) <= b.depth / 2;
  };
  double lo = 0, hi = 100;
  for (int i = 0; i < 200; ++i) (inside(0.5 * (lo + hi)) ? lo : hi) = 0.5 * (lo + hi);
  return lo;
}

TEST(Rigid3dRest, ThresholdByDirectionMatchesTheBaseGeometry) {
  const Body3d rect = box(0.4, 0.7, 1.5), square = box(0.5, 0.5, 1.5), cyl = cylinder(0.25, 1.2);
  for (int k = 0; k <= 72; ++k) {
    const double phi = k * M_PI / 36;
    for (const Body3d* b : {&rect, &square, &cyl})
      EXPECT_NEAR(blockdyn::rest_threshold(*b, phi), threshold_by_bisection(*b, phi), 1e-12) << k;
  }
  // Along an axis b/h; through a square's corner sqrt(2) b/h; a cylinder 2a/h everywhere.
  EXPECT_DOUBLE_EQ(blockdyn::rest_threshold(rect, 0), 0.4 / 1.5);
  EXPECT_DOUBLE_EQ(blockdyn::rest_threshold(rect, M_PI / 2), 0.7 / 1.5);
  EXPECT_NEAR(blockdyn::rest_threshold(square, M_PI / 4), std::sqrt(2.0) * 0.5 / 1.5, 1e-15);
  EXPECT_NEAR(blockdyn::rest_threshold(rect, std::atan2(0.7, 0.4)), std::hypot(0.4, 0.7) / 1.5, 1e-15);
  EXPECT_DOUBLE_EQ(blockdyn::rest_threshold(cyl, 1.0), 2 * 0.25 / 1.2);
}

TEST(Rigid3dFlight, TorqueFreeFlightConservesMomentumAndAngularMomentum) {
  const BodyFlight m(box(0.3, 0.5, 1.2));
  BodyFlight::State z = blockdyn::standing_state(m.body(), 0.3, 100.0);
  const Quat q = blockdyn::axis_angle({0.6, 0.0, 0.8}, 0.7);
  z[BodyFlight::kQw] = q.w, z[BodyFlight::kQx] = q.x, z[BodyFlight::kQy] = q.y, z[BodyFlight::kQz] = q.z;
  z[BodyFlight::kVx] = 0.4, z[BodyFlight::kVy] = -0.2, z[BodyFlight::kVz] = 1.0;
  z[BodyFlight::kWx] = 3.0, z[BodyFlight::kWy] = -7.0, z[BodyFlight::kWz] = 5.0;
  const Vec3 l0 = m.angular_momentum(z), p0 = m.momentum(z);
  const double e0 = m.energy(z);
  const Flown f = fly(m, z, 3.0);
  ASSERT_EQ(f.status, blockdyn::RunStatus::ReachedEnd);
  ASSERT_TRUE(f.events.empty());
  const Vec3 l = m.angular_momentum(f.z), p = m.momentum(f.z);
  const double ln = std::sqrt(blockdyn::dot(l0, l0));
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(l[i], l0[i], 1e-12 * ln) << i;
  EXPECT_NEAR(p[0], p0[0], 1e-12 * std::fabs(p0[0]));
  EXPECT_NEAR(p[1], p0[1], 1e-12 * std::fabs(p0[1]));
  EXPECT_NEAR(p[2], p0[2] - m.body().mass * m.body().g * 3.0, 1e-12 * m.body().mass * m.body().g * 3.0);
  EXPECT_NEAR(m.energy(f.z), e0, 1e-12 * e0);
}

TEST(Rigid3dFlight, IntermediateAxisFlipsWithTheJacobiEllipticPeriod) {
  // Principal axes e3 (I smallest), e1, e2 for a box b < d < h: I1 > I2 > I3 here, so relabel in
  // ascending order (A, B, C) = (I3, I2, I1) and spin near the intermediate axis e2.
  const BodyFlight m(box(0.3, 0.5, 1.2));
  const Vec3 in = m.body().inertia();
  const double ia = in[2], ib = in[1], ic = in[0];
  ASSERT_LT(ia, ib);
  ASSERT_LT(ib, ic);
  BodyFlight::State z = blockdyn::standing_state(m.body(), 0.0, 1000.0);
  const Vec3 om{0.02, 6.0, 0.05};  // body = world at the start (no rotation)
  z[BodyFlight::kWx] = om[0], z[BodyFlight::kWy] = om[1], z[BodyFlight::kWz] = om[2];
  const double l2 = std::pow(in[0] * om[0], 2) + std::pow(in[1] * om[1], 2) + std::pow(in[2] * om[2], 2);
  const double e2 = in[0] * om[0] * om[0] + in[1] * om[1] * om[1] + in[2] * om[2] * om[2];  // 2 E
  double lo = ia, hi = ic;  // L^2 > 2 E I_B: as given; else exchange the roles of A and C
  if (!(l2 > e2 * ib)) std::swap(lo, hi);
  const double lambda2 = (hi - ib) * (l2 - e2 * lo) / (lo * ib * hi);
  const double mpar = (ib - lo) * (e2 * hi - l2) / ((hi - ib) * (l2 - e2 * lo));
  ASSERT_GT(mpar, 0.9);  // near the separatrix: a flip
  const double period = 4 * boost::math::ellint_1(std::sqrt(mpar)) / std::sqrt(std::fabs(lambda2));
  // Over one period the body-frame angular velocity comes back; half-way the spin has reversed.
  auto body_rate = [&](const BodyFlight::State& s) {
    const auto r = blockdyn::rotation({s[BodyFlight::kQw], s[BodyFlight::kQx], s[BodyFlight::kQy], s[BodyFlight::kQz]});
    return blockdyn::transposed_times(r, {s[BodyFlight::kWx], s[BodyFlight::kWy], s[BodyFlight::kWz]});
  };
  const Flown half = fly(m, z, 0.5 * period);
  EXPECT_LT(body_rate(half.z)[1], -0.9 * om[1]);
  const Flown full = fly(m, z, period);
  const Vec3 back = body_rate(full.z);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(back[i], om[i], 1e-8 * om[1]) << i;
}

TEST(Rigid3dFlight, TouchdownAtTheClosedFormInstant) {
  // Dropped without rotation from a lift L the base lands at sqrt(2 L / g).
  for (const Body3d& b : {box(0.4, 0.7, 1.5), cylinder(0.25, 1.2)}) {
    const BodyFlight m(b);
    const double lift = 0.37;
    const Flown f = fly(m, blockdyn::standing_state(b, 0.4, lift), 5.0);
    ASSERT_EQ(f.events.size(), 1u);
    EXPECT_NEAR(f.events[0], std::sqrt(2 * lift / b.g), 1e-13);
  }
  // Tilted and spinning: the run stops where the lowest point reaches the ground.
  const BodyFlight m(cylinder(0.25, 1.2));
  BodyFlight::State z = blockdyn::standing_state(m.body(), 0.0, 0.8);
  const Quat q = blockdyn::axis_angle({1, 0, 0}, 0.3);
  z[BodyFlight::kQw] = q.w, z[BodyFlight::kQx] = q.x, z[BodyFlight::kQy] = q.y, z[BodyFlight::kQz] = q.z;
  z[BodyFlight::kWx] = 0.5, z[BodyFlight::kWz] = 9.0;
  const Flown f = fly(m, z, 5.0);
  ASSERT_EQ(f.events.size(), 1u);
  std::array<double, 1> g{};
  m.events(f.t, {}, f.z, g);
  EXPECT_NEAR(g[0], 0.0, 1e-12);
}

TEST(Rigid3dFlight, GroundMotionInThreeComponentsActsReversedOnTheBody) {
  // In the ground's frame a constant ground acceleration a (g) is felt as -g a: the centroid's path
  // is a parabola, and the touchdown under a vertical a_v comes at sqrt(2 L / (g (1 + a_v))).
  blockdyn::GroundMotion3d gm;
  gm.azimuth = 30;
  gm.h.constant = 0.2;
  gm.h2.constant = -0.1;
  gm.v.constant = 0.5;
  const Body3d b = box(0.4, 0.7, 1.5);
  const BodyFlight m(b, gm);
  const double lift = 0.6, t_land = std::sqrt(2 * lift / (b.g * 1.5));
  const Flown f = fly(m, blockdyn::standing_state(b, 0.0, lift), 5.0);
  ASSERT_EQ(f.events.size(), 1u);
  EXPECT_NEAR(f.events[0], t_land, 1e-13);
  const double az = 30 * M_PI / 180;
  const double ax = 0.2 * std::cos(az) + 0.1 * std::sin(az), ay = 0.2 * std::sin(az) - 0.1 * std::cos(az);
  EXPECT_NEAR(f.z[BodyFlight::kX], -0.5 * b.g * ax * t_land * t_land, 1e-13);
  EXPECT_NEAR(f.z[BodyFlight::kY], -0.5 * b.g * ay * t_land * t_land, 1e-13);
  // The components rotate with the azimuth: h along it, h2 at +90 degrees.
  blockdyn::GroundMotion3d r;
  r.azimuth = 90;
  r.h.constant = 1.0;
  const auto a = r.at(0.0);
  EXPECT_NEAR(a[0], 0.0, 1e-16);
  EXPECT_DOUBLE_EQ(a[1], 1.0);
  r.azimuth = std::nan("");
  EXPECT_THROW(blockdyn::validate(r), std::invalid_argument);
}

TEST(Rigid3dRest, OnsetByDirectionAtTheClosedFormCrossing) {
  // a_h = A sin(2 pi f t) along the azimuth: the body leaves rest where A sin(2 pi f t) = c, c the
  // smallest coefficient of that direction: t = asin(c / A) / (2 pi f).
  const double amp = 0.6, f = 1.3, tp = 1.0 / f;
  for (double az : {0.0, 30.0, 45.0, 60.0, 90.0}) {
    for (const Body3d& b : {box(0.4, 0.7, 1.5), box(0.5, 0.5, 1.5), cylinder(0.25, 1.2)}) {
      blockdyn::GroundMotion3d g;
      g.azimuth = az;
      g.h.amplitude = amp;
      g.h.frequency = f;
      const double c = blockdyn::rest_threshold(b, az * M_PI / 180);
      const blockdyn::BodyRestExit e = blockdyn::first_rest_exit(b, 0.0, 0.9, g, 0.0, 10 * tp);
      ASSERT_EQ(e.way, blockdyn::RestExitWay::Rocks) << az;
      EXPECT_NEAR(e.t, std::asin(c / amp) / (2 * M_PI * f), 1e-12) << az;
    }
  }
  // Friction below the rocking coefficient: it slides first, at asin(mu_s / A) / (2 pi f).
  blockdyn::GroundMotion3d g;
  g.h.amplitude = amp;
  g.h.frequency = f;
  const blockdyn::BodyRestExit s = blockdyn::first_rest_exit(box(0.4, 0.7, 1.5), 0.0, 0.2, g, 0.0, 10 * tp);
  EXPECT_EQ(s.way, blockdyn::RestExitWay::Slides);
  EXPECT_NEAR(s.t, std::asin(0.2 / amp) / (2 * M_PI * f), 1e-12);
  // A yaw of the body is the azimuth taken back: a square turned by 45 degrees under motion along x
  // resists as along its diagonal, sqrt(2) b / h, and leaves on a corner (two conditions at once).
  const blockdyn::BodyRestExit d = blockdyn::first_rest_exit(box(0.5, 0.5, 1.5), M_PI / 4, 0.9, g, 0.0, 10 * tp);
  EXPECT_NEAR(d.t, std::asin(std::sqrt(2.0) * 0.5 / 1.5 / amp) / (2 * M_PI * f), 1e-12);
  const blockdyn::RestFailure df = blockdyn::BodyRestSearch(box(0.5, 0.5, 1.5), 0.9, g).failure(d.t, M_PI / 4);
  EXPECT_TRUE(df.x_side != 0 && df.y_side != 0);
  // Below every threshold it rests throughout.
  g.h.amplitude = 0.1;
  EXPECT_EQ(blockdyn::first_rest_exit(box(0.4, 0.7, 1.5), 0.0, 0.9, g, 0.0, 10 * tp).way, blockdyn::RestExitWay::None);
}

TEST(Rigid3dRest, OnsetUnderTwoHorizontalComponentsAtTheClosedFormCrossing) {
  // h = A sin(2 pi f t) along the azimuth and a constant B across it: the box leaves by the first
  // of its axis conditions, the cylinder where sqrt(A^2 sin^2 + B^2) = 2a/h (the norm condition),
  // sliding where it equals mu_s.
  const double amp = 0.7, f = 1.1, B = 0.2, tp = 1.0 / f;
  for (double az : {0.0, 20.0, 90.0}) {
    blockdyn::GroundMotion3d g;
    g.azimuth = az;
    g.h.amplitude = amp;
    g.h.frequency = f;
    g.h2.constant = B;
    auto crossing = [&](double c) { return std::asin(std::sqrt(c * c - B * B) / amp) / (2 * M_PI * f); };
    const Body3d cyl = cylinder(0.25, 1.2);
    const blockdyn::BodyRestExit e = blockdyn::first_rest_exit(cyl, 0.3, 0.9, g, 0.0, 10 * tp);
    EXPECT_EQ(e.way, blockdyn::RestExitWay::Rocks);
    EXPECT_NEAR(e.t, crossing(2 * 0.25 / 1.2), 1e-12) << az;
    const blockdyn::BodyRestExit s = blockdyn::first_rest_exit(cyl, 0.0, 0.3, g, 0.0, 10 * tp);
    EXPECT_EQ(s.way, blockdyn::RestExitWay::Slides);
    EXPECT_NEAR(s.t, crossing(0.3), 1e-12) << az;
  }
  // The box at yaw 0 with the motion along x (azimuth 0): x fails at asin((b/h) / A); the
  // constant B < d/h across keeps the y conditions.
  blockdyn::GroundMotion3d g;
  g.h.amplitude = amp;
  g.h.frequency = f;
  g.h2.constant = B;
  const Body3d bx = box(0.45, 0.5, 1.5);
  const blockdyn::BodyRestExit e = blockdyn::first_rest_exit(bx, 0.0, 0.9, g, 0.0, 10 * tp);
  EXPECT_NEAR(e.t, std::asin(0.3 / amp) / (2 * M_PI * f), 1e-12);
  const blockdyn::RestFailure fx = blockdyn::BodyRestSearch(bx, 0.9, g).failure(e.t, 0.0);
  EXPECT_EQ(fx.x_side, 1);
  EXPECT_EQ(fx.y_side, 0);
}

}  // namespace
