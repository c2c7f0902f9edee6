// SPDX-License-Identifier: Apache-2.0
// The rigid3d box sliding flat on its base (model/rigid3d/base_slide.hpp), each check against
// something independent: a rectangular pulse's slide in closed form (stick time A T / mu_k, slide
// distance g T^2 (A - mu_k) A / (2 mu_k), at any azimuth, without twisting); the planar 3-DOF
// block's slides and sticks under a harmonic motion (the planar limit); a spinning box's spin
// decay in closed form (the corners' friction torque mu_k m g rho); the rotated response of a
// square base to the rotated motion; a slide that goes round under a circular motion, its
// direction followed through many turns; and the closed energy balance in every run.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "blockdyn/analysis/forced/forced_body3d.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "blockdyn/simulation/rigid_ground_model.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "model/rigid3d/body3d_run.hpp"

using blockdyn::Body3dEventKind;
using blockdyn::Body3dResult;
using blockdyn::BodyOnGround;
using blockdyn::BodyOnGroundOptions;
using blockdyn::GroundMotion3d;

namespace slide_test {

using blockdyn::test::balance_error;
using blockdyn::test::friction;
using blockdyn::test::times_of;

using blockdyn::test::kG;
using blockdyn::test::run_body;

GroundMotion3d rect_pulse(double a, double duration, double azimuth_deg) {
  GroundMotion3d g;
  g.h.amplitude = a;
  g.h.duration = duration;
  g.h.pulse = blockdyn::PulseShape::Rect;
  g.azimuth = azimuth_deg;
  return g;
}

}  // namespace slide_test

using namespace slide_test;

TEST(Rigid3dSlide, RectangularPulseSlidesInClosedForm) {
  // Phase 1: relative acceleration (A - mu_k) g for T; phase 2: decelerating at mu_k g to a stop
  // at A T / mu_k, having slid g T^2 (A - mu_k) A / (2 mu_k), against the ground's acceleration.
  const double A = 0.4, T = 0.5, mu_s = 0.3, mu_k = 0.25;
  for (double az : {0.0, 37.0, 90.0, -120.0}) {
    const BodyOnGround m(blockdyn::box_body(1.0, 0.8, 1.2, 500), rect_pulse(A, T, az), friction(mu_s, mu_k));
    const Body3dResult r = run_body(m, {}, 2.0);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    const auto sticks = times_of(r, Body3dEventKind::Stick);
    ASSERT_EQ(sticks.size(), 1u) << az;
    EXPECT_NEAR(sticks[0], A * T / mu_k, 1e-12) << az;
    EXPECT_EQ(r.first_slide_time, 0.0);
    const double d = kG * T * T * (A - mu_k) * A / (2 * mu_k), a = az * M_PI / 180;
    EXPECT_NEAR(r.z[BodyOnGround::kX], -d * std::cos(a), 1e-12) << az;
    EXPECT_NEAR(r.z[BodyOnGround::kY], -d * std::sin(a), 1e-12) << az;
    EXPECT_NEAR(r.max_slide, d, 1e-12) << az;
    // No twist: the friction's resultant passes through the centroid's line.
    EXPECT_NEAR(r.z[BodyOnGround::kQz], 0.0, 1e-13) << az;
    EXPECT_EQ(r.mode.contact, blockdyn::BodyContact::Rest);
    EXPECT_LT(balance_error(r, m), 1e-12) << az;
    // The friction's work is the ground's: everything it put in is dissipated.
    EXPECT_NEAR(r.z[BodyOnGround::kWorkFriction], -r.z[BodyOnGround::kWorkGround], 1e-9);
  }
}

TEST(Rigid3dSlide, APulseBeyondTheRockingThresholdOnLowFrictionSlidesFlat) {
  // A at 0.9 g exceeds both b/h = 0.83 (rocking fails first) and mu 0.3, but the friction's
  // tipping moment mu < b/h cannot lift the base: the edge the rocking would pivot on cannot
  // stick and its slip would press the other corners into the ground, so the base slides flat,
  // as the closed form above (before: the run stopped at t = 0, the edge and the rest taking
  // turns). Along x and at 30 degrees (about a corner).
  const double A = 0.9, T = 0.5, mu = 0.3;
  for (double az : {0.0, 30.0}) {
    const BodyOnGround m(blockdyn::box_body(1.0, 1.0, 1.2, 500), rect_pulse(A, T, az), friction(mu, mu));
    const Body3dResult r = run_body(m, {}, 4.0);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    const auto sticks = times_of(r, Body3dEventKind::Stick);
    ASSERT_EQ(sticks.size(), 1u) << az;
    EXPECT_NEAR(sticks[0], A * T / mu, 1e-12) << az;
    const double d = kG * T * T * (A - mu) * A / (2 * mu), a = az * M_PI / 180;
    EXPECT_NEAR(r.z[BodyOnGround::kX], -d * std::cos(a), 1e-12) << az;
    EXPECT_NEAR(r.z[BodyOnGround::kY], -d * std::sin(a), 1e-12) << az;
    EXPECT_EQ(r.max_tilt, 0.0) << az;
    EXPECT_LT(balance_error(r, m), 1e-12) << az;
  }
}

TEST(Rigid3dSlide, ABaseLandingFlatWhileMovingSlidesOnWithCoulombsImpulse) {
  // Dropped flat from 5 cm while moving at 1 m/s: the landing is plastic along the normal (the
  // impulse m |v_z|, v_z = -g t_land) with Coulomb's friction impulse mu m |v_z| against the slide,
  // which then decelerates at mu g to its stop: all in closed form (before, a flat landing stopped
  // the body dead, its horizontal velocity lost).
  const double lift = 0.05, v0 = 1.0, mu = 0.3, az = 25 * M_PI / 180;
  const BodyOnGround m(blockdyn::box_body(1.0, 0.8, 0.5, 300), {}, friction(mu, mu));
  blockdyn::Body3dStart s;
  s.lift = lift;
  s.velocity = {v0 * std::cos(az), v0 * std::sin(az), 0};
  const Body3dResult r = run_body(m, s, 1.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  const double t_land = std::sqrt(2 * lift / kG), fall = kG * t_land, v1 = v0 - mu * fall;
  ASSERT_GE(r.events.size(), 2u);
  EXPECT_EQ(r.events[0].kind, Body3dEventKind::Impact);
  EXPECT_EQ(r.events[0].to, blockdyn::BodyContact::Slide);
  EXPECT_NEAR(r.events[0].t, t_land, 1e-12);
  const auto sticks = times_of(r, Body3dEventKind::Stick);
  ASSERT_EQ(sticks.size(), 1u);
  EXPECT_NEAR(sticks[0], t_land + v1 / (mu * kG), 1e-12);
  const double d = v0 * t_land + v1 * v1 / (2 * mu * kG);
  EXPECT_NEAR(r.z[BodyOnGround::kX], d * std::cos(az), 1e-12);
  EXPECT_NEAR(r.z[BodyOnGround::kY], d * std::sin(az), 1e-12);
  EXPECT_EQ(r.mode.contact, blockdyn::BodyContact::Rest);
  // The landing's loss: the fall's kinetic energy and what the friction impulse took of the slide.
  const double loss = 0.5 * 300 * (fall * fall + v0 * v0 - v1 * v1);
  EXPECT_NEAR(r.z[BodyOnGround::kWorkImpact], -loss, 1e-9 * loss);
  EXPECT_LT(balance_error(r, m), 1e-12);
}

TEST(Rigid3dSlide, PlanarLimitIsTheThreeDofBlock) {
  // A squat box under a harmonic motion along its x axis slides and sticks (mu_s < b/h: it never
  // rocks) as the planar 3-DOF block of the same section does.
  const double b = 1.0, d = 0.8, h = 1.2, mu_s = 0.3, mu_k = 0.25, A = 0.35, f = 1.0, t_end = 4.0;
  GroundMotion3d g3;
  g3.h.amplitude = A;
  g3.h.frequency = f;
  const BodyOnGround m(blockdyn::box_body(b, d, h, 500), g3, friction(mu_s, mu_k));
  const Body3dResult r = run_body(m, {}, t_end);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;

  blockdyn::GroundMotion g2;
  g2.horizontal.amplitude = A;
  g2.horizontal.frequency = f;
  const blockdyn::RigidResult planar = blockdyn::test::planar_block_run(b, h, 500, mu_s, mu_k, g2, {}, t_end);
  ASSERT_EQ(planar.status, blockdyn::SimStatus::TEnd);
  // Its mechanism changes: rest -> slide at the onset, slide -> rest at each stick.
  std::vector<double> starts, stops;
  for (const auto& e : planar.events) {
    if (e.from == blockdyn::Mechanism::Rest && e.to == blockdyn::Mechanism::Slide) starts.push_back(e.t);
    if (e.from == blockdyn::Mechanism::Slide && e.to == blockdyn::Mechanism::Rest) stops.push_back(e.t);
  }
  std::vector<double> starts3, stops3 = times_of(r, Body3dEventKind::Stick);
  for (const auto& e : r.events)
    if (e.from == blockdyn::BodyContact::Rest && e.to == blockdyn::BodyContact::Slide) starts3.push_back(e.t);
  ASSERT_GE(stops.size(), 3u);
  ASSERT_EQ(stops3.size(), stops.size());
  ASSERT_EQ(starts3.size(), starts.size());
  for (std::size_t i = 0; i < stops.size(); ++i) EXPECT_NEAR(stops3[i], stops[i], 1e-9) << "stick " << i;
  for (std::size_t i = 0; i < starts.size(); ++i) EXPECT_NEAR(starts3[i], starts[i], 1e-9) << "onset " << i;
  EXPECT_NEAR(r.z[BodyOnGround::kX], planar.final_state[blockdyn::RigidBlock::kX], 1e-9);
  EXPECT_NEAR(r.z[BodyOnGround::kVx], planar.final_state[blockdyn::RigidBlock::kVX], 1e-9);
  EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-13);
  EXPECT_LT(balance_error(r, m), 1e-11);
}

TEST(Rigid3dSlide, SpinDecaysAtTheCornersTorque) {
  // A square box spun on its base: each corner carries m g / 4 and its friction mu_k m g / 4 acts
  // across its arm rho; the spin decays at mu_k m g rho / I_z and stops at I_z w0 / (mu_k m g rho),
  // the box turned by w0 t / 2, its centroid unmoved.
  const double b = 0.6, h = 1.0, mass = 100, mu = 0.4, w0 = 3.0;
  const BodyOnGround m(blockdyn::box_body(b, b, h, mass), {}, friction(mu, mu));
  blockdyn::Body3dStart s;
  s.angular_velocity = {0, 0, w0};
  const Body3dResult r = run_body(m, s, 2.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  const double rho = b / std::sqrt(2.0), iz = mass * (b * b + b * b) / 12, t_stop = iz * w0 / (mu * mass * kG * rho);
  const auto sticks = times_of(r, Body3dEventKind::Stick);
  ASSERT_EQ(sticks.size(), 1u);
  EXPECT_NEAR(sticks[0], t_stop, 1e-12);
  const double turn = 0.5 * w0 * t_stop;
  EXPECT_NEAR(2 * std::atan2(r.z[BodyOnGround::kQz], r.z[BodyOnGround::kQw]), turn, 1e-12);
  EXPECT_NEAR(r.z[BodyOnGround::kX], 0.0, 1e-14);
  EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-14);
  EXPECT_NEAR(r.max_slide, 0.0, 1e-14);  // the base's centre did not move
  EXPECT_NEAR(-r.z[BodyOnGround::kWorkFriction], 0.5 * iz * w0 * w0, 1e-9);
  EXPECT_LT(balance_error(r, m), 1e-12);
}

TEST(Rigid3dSlide, SquareBaseRotatedMotionGivesTheRotatedSlide) {
  // Two components (a pulse along h, a harmonic across): turning the motion by 90 degrees turns
  // the slide (position and twist) by 90 degrees.
  auto motion = [](double az) {
    GroundMotion3d g = rect_pulse(0.45, 0.6, az);
    g.h2.amplitude = 0.2;
    g.h2.frequency = 1.3;
    return g;
  };
  const Body3dResult r0 =
      run_body(BodyOnGround(blockdyn::box_body(0.9, 0.9, 1.0, 300), motion(0), friction(0.3, 0.25)), {}, 3);
  const Body3dResult r90 =
      run_body(BodyOnGround(blockdyn::box_body(0.9, 0.9, 1.0, 300), motion(90), friction(0.3, 0.25)), {}, 3);
  ASSERT_EQ(r0.status, blockdyn::SimStatus::TEnd) << r0.note;
  ASSERT_EQ(r90.status, blockdyn::SimStatus::TEnd) << r90.note;
  EXPECT_GT(r0.max_slide, 0.05);
  EXPECT_NEAR(r90.z[BodyOnGround::kX], -r0.z[BodyOnGround::kY], 1e-12);
  EXPECT_NEAR(r90.z[BodyOnGround::kY], r0.z[BodyOnGround::kX], 1e-12);
  EXPECT_NEAR(r90.max_slide, r0.max_slide, 1e-12);
  EXPECT_EQ(times_of(r90, Body3dEventKind::Stick).size(), times_of(r0, Body3dEventKind::Stick).size());
}

TEST(Rigid3dSlide, CircularMotionSlidesRoundWithItsBalanceClosed) {
  // The ground accelerating round a circle (two components in quadrature) drags the base round;
  // its direction turns through many reference changes, the balance stays closed.
  GroundMotion3d g;
  g.h.amplitude = 0.5;
  g.h.frequency = 1.0;
  g.h2.amplitude = 0.5;
  g.h2.frequency = 1.0;
  g.h2.phase = 0.5 * M_PI;
  const BodyOnGround m(blockdyn::box_body(1.0, 0.7, 1.2, 400), g, friction(0.3, 0.25));
  const Body3dResult r = run_body(m, {}, 5.0);
  ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
  EXPECT_GT(r.max_slide, 0.1);
  EXPECT_TRUE(times_of(r, Body3dEventKind::Stick).empty());  // it never stops
  EXPECT_LT(balance_error(r, m), 1e-10);
  EXPECT_LT(r.z[BodyOnGround::kWorkFriction], 0.0);
}

// The 3D body as the forced analyses' model (analysis/forced/forced_body3d.hpp): under a pulse
// along a principal axis, with friction that holds, each run is Housner's block's of that section
// (overturned or not, the largest rotation), and its slenderness and frequency parameter are the
// section's.
TEST(Rigid3dSlide, ForcedModelAlongAnAxisIsHousnersBlock) {
  const double b = 0.4, d = 0.35, h = 1.2;
  BodyOnGroundOptions stick;  // mu_s 1e6: the contacts hold
  for (double incidence : {0.0, 90.0, 180.0}) {
    const blockdyn::ForcedModel m3 = blockdyn::forced_body3d_model(blockdyn::box_body(b, d, h, 100), stick, incidence);
    blockdyn::RigidBlockParams p;
    p.shape.width = incidence == 90 ? d : b;
    p.shape.height = h;
    p.shape.mass = 100;
    const blockdyn::ForcedModel m2 = blockdyn::forced_block_model(p, blockdyn::housner_on_rigid_ground());
    EXPECT_NEAR(m3.alpha, m2.alpha, 1e-15);
    EXPECT_NEAR(m3.p, m2.p, 1e-14);
    // One-sine pulses whose rocking keeps the edge on the ground (a stronger swing lifts it off,
    // which Housner's pivot cannot do: a difference of model, not of the planar limit).
    int overturned = 0;
    // (The amplitudes scale with the section's slenderness: the same motions relative to it.)
    for (const auto& [a0, duration] : {std::pair{0.3, 1.5}, {0.34, 1.5}, {0.38, 1.5}, {0.34, 2.5}, {0.42, 2.5}}) {
      const double a = a0 * p.shape.width / b;
      blockdyn::GroundMotion g;
      g.horizontal.amplitude = a;
      g.horizontal.duration = duration;
      g.horizontal.pulse = blockdyn::PulseShape::OneSine;
      const blockdyn::SurvivalOutcome o3 = m3.run(g, 8.0), o2 = m2.run(g, 8.0);
      ASSERT_FALSE(o3.invalid) << incidence << " " << a;
      EXPECT_EQ(o3.collapse_mode.has_value(), o2.collapse_mode.has_value()) << incidence << " " << a;
      overturned += o3.collapse_mode.has_value();
      if (o3.collapse_mode) {
        EXPECT_NEAR(*o3.t_failure, *o2.t_failure, 1e-9) << incidence << " " << a;
      } else {
        EXPECT_NEAR(o3.max_abs_rotation, o2.max_abs_rotation, 1e-9) << incidence << " " << a;
      }
    }
    EXPECT_EQ(overturned, 1) << incidence;
  }
}
