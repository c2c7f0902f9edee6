// SPDX-License-Identifier: Apache-2.0
// The rigid3d cylinder sliding flat on its base (model/rigid3d/disc_slide.hpp), each check against
// something independent: the friction field's mean direction and twist against a brute-force sum
// over the disc and their closed values (a pure slide, a pure spin, the slip's centre on the
// rim); a slide's stop and distance, a spin's decay and a rectangular pulse's slide in closed
// form; the box's base (its four corners) under the same motion along an axis (a pure slide does
// not see the base's shape); the thin disc's sliding and spinning stopping together at
// v / (a omega) = 0.6530 (the uniform pressure's fixed point, Farkas et al. 2003); the tip onto the
// rim where mu_k c reaches a; and the closed energy balance in every run.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blockdyn/model/rigid3d/disc_slide.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "model/rigid3d/body3d_run.hpp"

using blockdyn::Body3dEventKind;
using blockdyn::Body3dResult;
using blockdyn::BodyContact;
using blockdyn::BodyOnGround;
using blockdyn::BodyOnGroundOptions;
using blockdyn::GroundMotion3d;
using blockdyn::Vec3;

namespace disc_slide_test {

using blockdyn::test::balance_error;
using blockdyn::test::friction;
using blockdyn::test::times_of;

using blockdyn::test::kG;

// The mean friction direction and twist over the unit disc by a midpoint sum on a polar grid about
// its centre (n rings): independent of the closed forms, accurate to about 1/n^2 away from the
// slip's centre.
std::array<double, 3> brute_field(const Vec3& v, double w, int n) {
  double gx = 0, gy = 0, tw = 0;
  for (int i = 0; i < n; ++i) {
    const double r = (i + 0.5) / n;
    const int m = 4 * n;
    for (int j = 0; j < m; ++j) {
      const double th = 2 * M_PI * (j + 0.5) / m, x = r * std::cos(th), y = r * std::sin(th);
      const double sx = v[0] - w * y, sy = v[1] + w * x, s = std::hypot(sx, sy);
      const double da = r * (1.0 / n) * (2 * M_PI / m);
      gx += sx / s * da;
      gy += sy / s * da;
      tw += (x * sy - y * sx) / s * da;
    }
  }
  return {gx / M_PI, gy / M_PI, tw / M_PI};
}

}  // namespace disc_slide_test

namespace ds = disc_slide_test;

TEST(Rigid3dDiscSlide, FrictionFieldMatchesTheDiscSumAndItsClosedValues) {
  // Slip centres inside, outside and near the rim, both senses of spin, and a radius that scales.
  const double cases[][4] = {{0.3, 0.2, 1.0, 1.0},  {0.3, 0.2, -2.0, 1.0}, {1.0, 0.5, 0.8, 1.0}, {2.0, -1.0, 0.3, 1.0},
                             {0.05, 0.0, 3.0, 1.0}, {0.6, 0.8, 1.05, 1.0}, {0.6, 0.16, 2.0, 0.4}};
  for (const auto& c : cases) {
    const double a = c[3];
    const auto f = blockdyn::disc_friction_field(a, {c[0], c[1], 0}, c[2]);
    const auto b = ds::brute_field({c[0], c[1], 0}, c[2] * a, 800);
    EXPECT_NEAR(f.mean_direction[0], b[0], 2e-6) << c[0] << " " << c[2];
    EXPECT_NEAR(f.mean_direction[1], b[1], 2e-6) << c[0] << " " << c[2];
    EXPECT_NEAR(f.mean_twist, b[2], 2e-6) << c[0] << " " << c[2];
    // The mean direction lies along the centre's slip (the field's mirror symmetry).
    EXPECT_NEAR(f.mean_direction[0] * c[1] - f.mean_direction[1] * c[0], 0.0, 1e-15);
  }
  // A pure slide; a pure spin (int |r| dA / (pi a^3) = 2/3); the centre on the rim: 8/(3 pi), 8/(9 pi).
  auto slide = blockdyn::disc_friction_field(0.3, {0.6, -0.8, 0}, 0.0);
  EXPECT_EQ(slide.mean_direction[0], 0.6);
  EXPECT_EQ(slide.mean_direction[1], -0.8);
  EXPECT_EQ(slide.mean_twist, 0.0);
  auto spin = blockdyn::disc_friction_field(0.3, {0, 0, 0}, -4.0);
  EXPECT_NEAR(spin.mean_twist, -2.0 / 3, 1e-15);
  EXPECT_EQ(spin.mean_direction[0], 0.0);
  auto rim = blockdyn::disc_friction_field(0.5, {0.3, 0.4, 0}, 1.0);
  EXPECT_NEAR(std::hypot(rim.mean_direction[0], rim.mean_direction[1]), 8 / (3 * M_PI), 1e-15);
  EXPECT_NEAR(rim.mean_twist, 8 / (9 * M_PI), 1e-15);
  // The series and the closed forms meet where one hands over to the other (x = 0.3: the slip's
  // centre at sqrt(0.3) a inside, at a / sqrt(0.3) outside): one ulp of the slip apart.
  for (double d : {std::sqrt(0.3), 1 / std::sqrt(0.3)}) {
    const auto lo = blockdyn::disc_friction_field(1.0, {std::nextafter(d, 0.0), 0, 0}, 1.0);
    const auto hi = blockdyn::disc_friction_field(1.0, {std::nextafter(d, 2.0), 0, 0}, 1.0);
    EXPECT_NEAR(lo.mean_direction[0], hi.mean_direction[0], 1e-14) << d;
    EXPECT_NEAR(lo.mean_twist, hi.mean_twist, 1e-14) << d;
  }
}

TEST(Rigid3dDiscSlide, ASlideStopsAtItsClosedFormWhateverItsDirection) {
  // Thrown at v0: decelerates at mu_k g, stops at v0 / (mu_k g) having slid v0^2 / (2 mu_k g).
  const double mu = 0.3, v0 = 0.5;
  const BodyOnGround m(blockdyn::cylinder_body(0.25, 0.8, 120), {}, ds::friction(0.35, mu));
  for (double az : {0.0, 40.0, -135.0}) {
    blockdyn::Body3dStart s;
    const double c = std::cos(az * M_PI / 180), sn = std::sin(az * M_PI / 180);
    s.velocity = {v0 * c, v0 * sn, 0};
    const Body3dResult r = blockdyn::test::run_body(m, s, 1.0);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    const auto sticks = ds::times_of(r, Body3dEventKind::Stick);
    ASSERT_EQ(sticks.size(), 1u);
    EXPECT_NEAR(sticks[0], v0 / (mu * ds::kG), 1e-12);
    const double d = v0 * v0 / (2 * mu * ds::kG);
    EXPECT_NEAR(r.z[BodyOnGround::kX], d * c, 1e-12);
    EXPECT_NEAR(r.z[BodyOnGround::kY], d * sn, 1e-12);
    EXPECT_NEAR(r.z[BodyOnGround::kQz], 0.0, 1e-15);  // no twist
    EXPECT_LT(ds::balance_error(r, m), 1e-12);
  }
}

TEST(Rigid3dDiscSlide, ASpinDecaysAtTheUniformPressuresTorque) {
  // Spun in place: the friction's moment (2/3) mu_k m g a (the resultant stays at the centre)
  // stops it at I_z w0 / ((2/3) mu_k m g a), turned by w0 t / 2, its centre unmoved.
  const double a = 0.3, mass = 80, mu = 0.4, w0 = -5.0;
  const BodyOnGround m(blockdyn::cylinder_body(a, 1.5, mass), {}, ds::friction(mu, mu));
  blockdyn::Body3dStart s;
  s.angular_velocity = {0, 0, w0};
  const Body3dResult r = blockdyn::test::run_body(m, s, 2.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  const double iz = 0.5 * mass * a * a, t_stop = iz * std::fabs(w0) / (2.0 / 3 * mu * mass * ds::kG * a);
  const auto sticks = ds::times_of(r, Body3dEventKind::Stick);
  ASSERT_EQ(sticks.size(), 1u);
  EXPECT_NEAR(sticks[0], t_stop, 1e-12);
  EXPECT_NEAR(2 * std::atan2(r.z[BodyOnGround::kQz], r.z[BodyOnGround::kQw]), 0.5 * w0 * t_stop, 1e-12);
  EXPECT_EQ(r.max_slide, 0.0);
  EXPECT_NEAR(-r.z[BodyOnGround::kWorkFriction], 0.5 * iz * w0 * w0, 1e-9);
}

TEST(Rigid3dDiscSlide, APulseAlongAnyAzimuthSlidesAsTheBoxBase) {
  // A rectangular pulse A g for T from rest: the slide starts at once (A > mu_s), stops at
  // A T / mu_k, having slid g T^2 (A - mu_k) A / (2 mu_k) against the pulse (closed form), and the
  // box's base under the same pulse along an axis slides identically (a pure slide does not see
  // the base's shape).
  const double A = 0.4, T = 0.5, mu_s = 0.3, mu_k = 0.25;
  for (double az : {0.0, 37.0, -120.0}) {
    GroundMotion3d g;
    g.h.amplitude = A;
    g.h.duration = T;
    g.h.pulse = blockdyn::PulseShape::Rect;
    g.azimuth = az;
    const BodyOnGround m(blockdyn::cylinder_body(0.5, 1.2, 500), g, ds::friction(mu_s, mu_k));
    const Body3dResult r = blockdyn::test::run_body(m, {}, 2.0);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    const auto sticks = ds::times_of(r, Body3dEventKind::Stick);
    ASSERT_EQ(sticks.size(), 1u);
    EXPECT_NEAR(sticks[0], A * T / mu_k, 1e-12);
    EXPECT_EQ(r.first_slide_time, 0.0);
    const double d = ds::kG * T * T * (A - mu_k) * A / (2 * mu_k), c = std::cos(az * M_PI / 180);
    EXPECT_NEAR(r.z[BodyOnGround::kX], -d * c, 1e-12);
    EXPECT_NEAR(r.z[BodyOnGround::kY], -d * std::sin(az * M_PI / 180), 1e-12);
    EXPECT_LT(ds::balance_error(r, m), 1e-12);
    const BodyOnGround box(blockdyn::box_body(1.0, 1.0, 1.2, 500), g, ds::friction(mu_s, mu_k));
    const Body3dResult rb = blockdyn::test::run_body(box, {}, 2.0);
    EXPECT_NEAR(rb.z[BodyOnGround::kX], r.z[BodyOnGround::kX], 1e-12);
    EXPECT_NEAR(rb.z[BodyOnGround::kY], r.z[BodyOnGround::kY], 1e-12);
  }
}

TEST(Rigid3dDiscSlide, AThinDiscStopsSlidingAndSpinningTogether) {
  // Uniform pressure (a thin disc: the friction's tilting moment c F vanishes): v / (a omega) tends
  // to the fixed point e* of g(e) = 2 e t(e) (g, t the mean direction and twist; I_z = m a^2 / 2):
  // 0.653 in Farkas, Bartels, Unger and Wolf, Phys. Rev. Lett. 90, 248302 (2003); 0.6530018 with
  // SciPy's elliptic integrals. Both stop at one instant.
  const double a = 0.2, mass = 10;
  const BodyOnGround m(blockdyn::cylinder_body(a, 1e-7, mass), {}, ds::friction(0.3, 0.3));
  blockdyn::Body3dStart s;
  s.velocity = {0.3, 0, 0};
  s.angular_velocity = {0, 0, 6.0};
  const Body3dResult r = blockdyn::test::run_body(m, s, 1.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  const auto sticks = ds::times_of(r, Body3dEventKind::Stick);
  ASSERT_EQ(sticks.size(), 1u);
  // Approaching the stop the ratio closes on the fixed point from below (its gap about a quarter
  // per decade of the time left: 2e-3, 5e-4, 1.2e-4, 3e-5 at 1e-5 ... 1e-8 of the stop's time).
  double gap_before = 1;
  for (double left : {1e-6, 1e-7, 1e-8}) {
    const Body3dResult b = blockdyn::test::run_body(m, s, sticks[0] * (1 - left));
    const double v = std::hypot(b.z[BodyOnGround::kVx], b.z[BodyOnGround::kVy]);
    const double gap = 0.6530018 - v / (a * b.z[BodyOnGround::kWz]);
    EXPECT_GT(gap, 0.0) << left;
    EXPECT_LT(gap, 0.35 * gap_before) << left;
    gap_before = gap;
  }
  EXPECT_LT(gap_before, 5e-5);
  EXPECT_LT(ds::balance_error(r, m), 1e-12);
}

TEST(Rigid3dDiscSlide, ASlideTipsOntoTheRimWhereMuKTimesCReachesTheRadius) {
  // A pure slide puts mu_k c / a of the load on the leading rim point: below one it slides to a
  // stop flat, at or above it the base tips forward onto that point (as the planar block's slide
  // rocks where mu_k > b / h).
  const double a = 0.2, h = 1.2, c = h / 2;
  for (double ratio : {0.95, 1.05}) {
    const double mu = ratio * a / c;
    const BodyOnGround m(blockdyn::cylinder_body(a, h, 100), {}, ds::friction(mu, mu));
    blockdyn::Body3dStart s;
    s.velocity = {0, 0.4, 0};
    const Body3dResult r = blockdyn::test::run_body(m, s, 2.0);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    ASSERT_FALSE(r.events.empty());
    if (ratio < 1) {
      EXPECT_EQ(r.events.size(), 1u);
      EXPECT_EQ(r.events[0].kind, Body3dEventKind::Stick);
      EXPECT_EQ(r.max_tilt, 0.0);
    } else {
      EXPECT_EQ(r.events[0].t, 0.0);
      EXPECT_EQ(r.events[0].to, BodyContact::Roll);  // slipping on the rim point ahead (+y)
      EXPECT_GT(r.max_tilt, 1e-3);
      EXPECT_GT(r.max_tilt_azimuth, 89.999);
      EXPECT_LT(r.max_tilt_azimuth, 90.001);
    }
    EXPECT_LT(ds::balance_error(r, m), 1e-10);
  }
}

TEST(Rigid3dDiscSlide, TwoComponentsSlideAndTwistWithTheBalanceClosed) {
  // A squat drum (2a/h = 1.67 > mu_s: it slides rather than rocks) under two harmonic components
  // at different frequencies: slides that turn and twist, sticks, and the balance closed;
  // refining the tolerance moves the final position by less than 1e-7 m.
  GroundMotion3d g;
  g.h.amplitude = 0.6;
  g.h.frequency = 1.3;
  g.h2.amplitude = 0.45;
  g.h2.frequency = 2.1;
  g.azimuth = 25;
  const BodyOnGround m(blockdyn::cylinder_body(0.5, 0.6, 300), g, ds::friction(0.5, 0.45));
  const Body3dResult r = blockdyn::test::run_body(m, {}, 4.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  EXPECT_GT(r.max_slide, 0.02);
  EXPECT_FALSE(ds::times_of(r, Body3dEventKind::Stick).empty());
  EXPECT_LT(ds::balance_error(r, m), 1e-11);
  blockdyn::Body3dRunOptions o;
  o.t_end = 4.0;
  o.integ.rtol = 1e-9;
  o.integ.atol = 1e-11;
  const Body3dResult coarse = blockdyn::simulate_body3d(m, blockdyn::initial_state(m.body(), {}), o);
  EXPECT_NEAR(coarse.z[BodyOnGround::kX], r.z[BodyOnGround::kX], 1e-7);
  EXPECT_NEAR(coarse.z[BodyOnGround::kY], r.z[BodyOnGround::kY], 1e-7);
  // A square box's base on the same motion slides the same way (pure translations), and gets
  // through the slip's passage near zero off its reference (which once chattered without end).
  const BodyOnGround box(blockdyn::box_body(1.0, 1.0, 0.6, 300), g, ds::friction(0.5, 0.45));
  const Body3dResult rb = blockdyn::test::run_body(box, {}, 4.0);
  ASSERT_EQ(rb.status, blockdyn::SimStatus::TEnd) << rb.note;
  EXPECT_NEAR(rb.z[BodyOnGround::kX], r.z[BodyOnGround::kX], 1e-9);
  EXPECT_NEAR(rb.z[BodyOnGround::kY], r.z[BodyOnGround::kY], 1e-9);
  EXPECT_NEAR(rb.max_slide, r.max_slide, 1e-9);
}
