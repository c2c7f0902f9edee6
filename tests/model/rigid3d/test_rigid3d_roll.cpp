// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder rolling on its rim without slipping (model/rigid3d/rim_rolling.hpp,
// body_roll.cpp), each check against something independent: the steady wobble in place (its
// centroid fixed) at the precession rate derived in docs/3d.md,
//   Omega^2 sin(alpha) (I1 cos(alpha) - I3 (c / a) sin(alpha)) = m g (a cos(alpha) - c sin(alpha)),
// held for 100 turns, and its thin-disk limit Omega^2 sin(alpha) = 4 g / a (Moffatt's Euler disk);
// the rolling constraint and the energy in a general rolling motion; the response turned with the
// start by a quarter turn; and the balance through rest, rocking on the rim and rolling under two
// ground components.
#include <gtest/gtest.h>

#include <cmath>

#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "model/rigid3d/body3d_run.hpp"

namespace roll_test {

using blockdyn::Body3dResult;
using blockdyn::BodyContact;
using blockdyn::BodyOnGround;
using blockdyn::Mat3;
using blockdyn::Vec3;
using blockdyn::operator*;

using blockdyn::test::kG;

struct Wobble {
  double omega;  // the precession rate (rad/s)
  blockdyn::Body3dStart start;
};

// The steady wobble in place of a cylinder (radius a, height h) tilted by alpha towards phi: the
// angular velocity along the contact's arm r = a d - c n (the centroid at rest), its size fixed by
// n's precession at Omega (docs/3d.md).
Wobble steady_wobble(double a, double h, double alpha, double phi) {
  const double m = 1, c = h / 2, i1 = m * (a * a / 4 + c * c / 3), i3 = m * a * a / 2;
  const double sa = std::sin(alpha), ca = std::cos(alpha);
  const double omega = std::sqrt(m * kG * (a * ca - c * sa) / (sa * (i1 * ca - i3 * (c / a) * sa)));
  const Vec3 er{std::cos(phi), std::sin(phi), 0};
  const Vec3 d{ca * er[0], ca * er[1], -sa}, n{sa * er[0], sa * er[1], ca};
  Wobble w;
  w.omega = omega;
  w.start.tilt = alpha;
  w.start.tilt_azimuth = phi;
  w.start.angular_velocity = blockdyn::plus(blockdyn::scaled(d, -omega * sa), blockdyn::scaled(n, omega * sa * c / a));
  return w;
}

BodyOnGround cylinder(double a, double h) {
  blockdyn::BodyOnGroundOptions o;
  o.mu_s = 10;
  return BodyOnGround(blockdyn::cylinder_body(a, h, 100), {}, o);
}

double tilt_of(const BodyOnGround::State& z) {
  return std::acos(blockdyn::rotation(
      {z[BodyOnGround::kQw], z[BodyOnGround::kQx], z[BodyOnGround::kQy], z[BodyOnGround::kQz]})[2][2]);
}

// The contact point's azimuth seen from the centroid.
double contact_azimuth(const BodyOnGround& m, const Body3dResult& r) {
  const Vec3 p = m.contact_point(r.mode, r.z);
  return std::atan2(p[1] - r.z[BodyOnGround::kY], p[0] - r.z[BodyOnGround::kX]);
}

TEST(Rigid3dRoll, SteadyWobbleInPlaceHoldsForAHundredTurns) {
  const double a = 0.2, h = 0.3, alpha = 0.3, phi = 0.4;
  const BodyOnGround m = cylinder(a, h);
  const Wobble w = steady_wobble(a, h, alpha, phi);
  const double t_end = 100 * 2 * M_PI / w.omega;
  const Body3dResult r = blockdyn::test::run_body(m, w.start, t_end);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  EXPECT_TRUE(r.events.empty());
  EXPECT_EQ(r.mode.contact, BodyContact::Roll);
  EXPECT_NEAR(r.z[BodyOnGround::kX], 0.0, 1e-12);
  EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-12);
  EXPECT_NEAR(tilt_of(r.z), alpha, 1e-12);
  // 628 rad of precession, the contact point where Omega t puts it.
  EXPECT_NEAR(std::remainder(contact_azimuth(m, r) - (phi + w.omega * t_end), 2 * M_PI), 0.0, 1e-9);
  EXPECT_LT(r.max_abs_energy_error, 1e-12 * m.body().mass * kG * h);
}

TEST(Rigid3dRoll, ThinDiskWobblesAtTheEulerDiskRate) {
  // A disk 1e-6 of its radius thick: the closed form is Moffatt's Omega^2 sin(alpha) = 4 g / a
  // to c / a; rolling in place it holds for 100 turns.
  const double a = 0.1, h = 1e-7, alpha = 0.2;
  const Wobble w = steady_wobble(a, h, alpha, 0.0);
  EXPECT_NEAR(w.omega * w.omega * std::sin(alpha) * a / (4 * kG), 1.0, 1e-5);
  const BodyOnGround m = cylinder(a, h);
  const double t_end = 100 * 2 * M_PI / w.omega;
  const Body3dResult r = blockdyn::test::run_body(m, w.start, t_end);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  EXPECT_NEAR(r.z[BodyOnGround::kX], 0.0, 1e-12);
  EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-12);
  EXPECT_NEAR(tilt_of(r.z), alpha, 1e-12);
  EXPECT_NEAR(std::remainder(contact_azimuth(m, r) - w.omega * t_end, 2 * M_PI), 0.0, 1e-9);
  EXPECT_LT(r.max_abs_energy_error, 1e-12 * m.body().mass * kG * a);
}

TEST(Rigid3dRoll, GeneralRollingKeepsItsConstraintAndItsEnergy) {
  // Tilted, spinning and wobbling: the contact's material point at rest, on the ground, and the
  // energy kept (a rolling contact does no work).
  const BodyOnGround m = cylinder(0.2, 0.8);
  blockdyn::Body3dStart s;
  s.tilt = 0.25;
  s.tilt_azimuth = 0.5;
  s.angular_velocity = {0.3, -0.2, 3.0};
  const Body3dResult r = blockdyn::test::run_body(m, s, 5.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  EXPECT_EQ(r.mode.contact, BodyContact::Roll);
  const auto& z = r.z;
  const Vec3 p = m.contact_point(r.mode, z), x{z[BodyOnGround::kX], z[BodyOnGround::kY], z[BodyOnGround::kZ]};
  const Vec3 arm = blockdyn::minus(p, x), w{z[BodyOnGround::kWx], z[BodyOnGround::kWy], z[BodyOnGround::kWz]};
  const Vec3 slip =
      blockdyn::plus({z[BodyOnGround::kVx], z[BodyOnGround::kVy], z[BodyOnGround::kVz]}, blockdyn::cross(w, arm));
  EXPECT_LT(std::sqrt(blockdyn::dot(slip, slip)), 1e-14);
  EXPECT_NEAR(p[2], 0.0, 1e-15);
  EXPECT_GT(std::hypot(z[BodyOnGround::kX], z[BodyOnGround::kY]), 1e-3);  // it rolled away
  EXPECT_LT(r.max_abs_energy_error, 1e-12 * m.body().mass * kG * 0.8);
}

TEST(Rigid3dRoll, QuarterTurnOfTheStartTurnsTheRolling) {
  const BodyOnGround m = cylinder(0.15, 0.6);
  blockdyn::Body3dStart s;
  s.tilt = 0.2;
  s.tilt_azimuth = 0.3;
  s.angular_velocity = {0.4, 0.1, 2.0};
  blockdyn::Body3dStart s90 = s;
  s90.tilt_azimuth += M_PI / 2;
  s90.angular_velocity = {-0.1, 0.4, 2.0};
  const Body3dResult r0 = blockdyn::test::run_body(m, s, 3.0), r90 = blockdyn::test::run_body(m, s90, 3.0);
  ASSERT_EQ(r0.status, blockdyn::SimStatus::TEnd) << r0.note;
  ASSERT_EQ(r90.status, blockdyn::SimStatus::TEnd) << r90.note;
  EXPECT_NEAR(r90.z[BodyOnGround::kX], -r0.z[BodyOnGround::kY], 1e-12);
  EXPECT_NEAR(r90.z[BodyOnGround::kY], r0.z[BodyOnGround::kX], 1e-12);
  EXPECT_NEAR(r90.z[BodyOnGround::kWx], -r0.z[BodyOnGround::kWy], 1e-11);
  EXPECT_NEAR(r90.z[BodyOnGround::kWy], r0.z[BodyOnGround::kWx], 1e-11);
  EXPECT_NEAR(r90.z[BodyOnGround::kWz], r0.z[BodyOnGround::kWz], 1e-11);
  EXPECT_NEAR(tilt_of(r90.z), tilt_of(r0.z), 1e-12);
}

TEST(Rigid3dRoll, TwoGroundComponentsRockThenRollWithTheBalanceClosed) {
  // From rest under two harmonic components the rim point rocks, then needs a moment and rolls.
  blockdyn::GroundMotion3d g;
  g.h.amplitude = 0.4;
  g.h.frequency = 1.5;
  g.h2.amplitude = 0.3;
  g.h2.frequency = 1.1;
  blockdyn::BodyOnGroundOptions o;
  o.mu_s = 5;
  const BodyOnGround m(blockdyn::cylinder_body(0.2, 1.2, 100), g, o);
  const Body3dResult r = blockdyn::test::run_body(m, {}, 1.5);
  bool rolled = false;
  for (const auto& e : r.events) rolled = rolled || (e.from == BodyContact::Line && e.to == BodyContact::Roll);
  EXPECT_TRUE(rolled);
  EXPECT_LT(r.max_abs_energy_error, 1e-9 * m.body().mass * kG * 1.2);
}

}  // namespace roll_test
