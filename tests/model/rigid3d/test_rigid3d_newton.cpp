// SPDX-License-Identifier: Apache-2.0
// The rigid3d box's impact by Newton's and Coulomb's laws (body_newton_impact.cpp), checked
// against what defines it, on a corner landing whose state before the impact is known in closed
// form (a box in flight without spin keeps its orientation; its centroid falls freely): the
// impulse P = m (v+ - v-) acts at the corner, so the angular momentum about the corner is kept
// (J w+ = a x P); the corner's normal velocity after is -e times the one before; P lies in
// Coulomb's cone, on its edge and against the corner's slip when it slips.
#include <gtest/gtest.h>

#include <cmath>

#include "blockdyn/model/rigid3d/body_state.hpp"
#include "model/rigid3d/body3d_run.hpp"

namespace blockdyn::rigid3d_newton_test {

struct CornerLanding {
  Body3dResult run;
  Body3dEventRecord impact;
  double t_touch = 0;  // closed form
  Vec3 v_before{};     // closed form
  Body3d body;
};

CornerLanding land_on_corner(double mu, double e) {
  Body3d b = box_body(0.4, 0.3, 1.0, 400);
  BodyOnGroundOptions o;
  o.mu_s = o.mu_k = mu;
  o.restitution = e;
  const BodyOnGround m(b, {}, o);
  Body3dStart s;
  s.tilt = 0.15;
  s.tilt_azimuth = std::atan2(0.3, 0.4);  // towards the (+x, +y) corner: it alone lowest
  s.lift = 0.02;
  s.velocity = {0.8, -0.5, 0.0};
  CornerLanding c;
  c.body = m.body();
  c.run = test::run_body(m, s, 0.2);
  for (const auto& ev : c.run.events)
    if (ev.kind == Body3dEventKind::Impact) {
      c.impact = ev;
      break;
    }
  c.t_touch = std::sqrt(2 * s.lift / b.g);
  c.v_before = {0.8, -0.5, -b.g * c.t_touch};
  return c;
}

void expect_newton_coulomb(const CornerLanding& c, double mu, double e, bool slips) {
  using S = BodyOnGround;
  ASSERT_EQ(c.impact.kind, Body3dEventKind::Impact);
  EXPECT_EQ(c.impact.from, BodyContact::Flight);
  EXPECT_NEAR(c.impact.t, c.t_touch, 1e-12);
  const auto& z = c.impact.z;
  const Mat3 r = rotation(quat_at(z, S::kQw));
  const Vec3 corner{0.2, 0.15, -0.5};
  const Vec3 a = r * corner;  // the corner's arm (the orientation does not jump)
  const Vec3 v{z[S::kVx], z[S::kVy], z[S::kVz]}, w{z[S::kWx], z[S::kWy], z[S::kWz]};
  const double m = c.body.mass;
  const Vec3 p = scaled(minus(v, c.v_before), m);
  // J w+ = a x P, J = R diag(I) R^T (no spin before).
  const Vec3 in = c.body.inertia(), wb = transposed_times(r, w);
  const Vec3 jw = r * Vec3{in[0] * wb[0], in[1] * wb[1], in[2] * wb[2]};
  const Vec3 axp = cross(a, p);
  const double hs = m * std::sqrt(dot(c.v_before, c.v_before)) * 0.5;
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(jw[std::size_t(k)], axp[std::size_t(k)], 1e-12 * hs) << k;
  const Vec3 u = plus(v, cross(w, a));
  const double un_before = c.v_before[2], speed = std::fabs(un_before);
  EXPECT_GT(p[2], 0.0);
  EXPECT_NEAR(u[2], -e * un_before, 1e-12 * speed);
  const double pt = std::hypot(p[0], p[1]), ut = std::hypot(u[0], u[1]);
  EXPECT_LE(pt, mu * p[2] * (1 + 1e-12));
  if (slips) {
    EXPECT_GT(ut, 1e-3 * speed);
    EXPECT_NEAR(pt, mu * p[2], 1e-12 * p[2]);
    EXPECT_NEAR(p[0] * ut + pt * u[0], 0.0, 1e-11 * pt * speed);  // P_t = -|P_t| u_t / |u_t|
    EXPECT_NEAR(p[1] * ut + pt * u[1], 0.0, 1e-11 * pt * speed);
  } else {
    EXPECT_LT(ut, 1e-12 * speed);
  }
  EXPECT_LT(c.run.max_abs_energy_error, 1e-9 * m * c.body.g * c.body.height);
}

TEST(Rigid3dNewton, ACornerLandingSlipsWhereFrictionCannotStopIt) {
  const double mu = 0.1, e = 0.4;
  const CornerLanding c = land_on_corner(mu, e);
  expect_newton_coulomb(c, mu, e, true);
}

TEST(Rigid3dNewton, ACornerLandingSticksOnLargeFriction) {
  const double mu = 5.0, e = 0.0;
  const CornerLanding c = land_on_corner(mu, e);
  expect_newton_coulomb(c, mu, e, false);
  // Plastic and sticking: Housner's law in 3D (the angular momentum about the corner kept and the
  // corner at rest) - the same state as the Housner option gives.
  Body3d b = c.body;
  BodyOnGroundOptions o;
  o.mu_s = o.mu_k = mu;
  o.impact = Body3dImpactLaw::Housner;
  const BodyOnGround m(b, {}, o);
  Body3dStart s;
  s.tilt = 0.15;
  s.tilt_azimuth = std::atan2(0.3, 0.4);
  s.lift = 0.02;
  s.velocity = {0.8, -0.5, 0.0};
  const Body3dResult h = test::run_body(m, s, 0.2);
  const Body3dEventRecord* hi = nullptr;
  for (const auto& ev : h.events)
    if (ev.kind == Body3dEventKind::Impact) {
      hi = &ev;
      break;
    }
  ASSERT_NE(hi, nullptr);
  for (std::size_t k = BodyOnGround::kVx; k <= BodyOnGround::kWz; ++k) EXPECT_NEAR(c.impact.z[k], hi->z[k], 1e-12) << k;
}

TEST(Rigid3dNewton, RestitutionBouncesTheCornerOff) {
  // e > 0: the corner leaves the ground at e times its approach speed - the body flies on.
  const double mu = 5.0, e = 0.5;
  const CornerLanding c = land_on_corner(mu, e);
  expect_newton_coulomb(c, mu, e, false);
  EXPECT_EQ(c.impact.to, BodyContact::Flight);
}

TEST(Rigid3dNewton, AStartWithACornerMovingIntoTheGroundIsAnImpact) {
  // On a corner, the body moving down: the start is an impact at the corner - the angular momentum
  // about it kept, the corner at rest after it (e = 0, friction enough), or slipping on it
  // against the friction's impulse (little friction).
  Body3d b = box_body(0.4, 0.3, 1.0, 400);
  for (const double mu : {5.0, 0.05}) {
    SCOPED_TRACE(mu);
    BodyOnGroundOptions o;
    o.mu_s = o.mu_k = mu;
    const BodyOnGround m(b, {}, o);
    Body3dStart s;
    s.tilt = 0.15;
    s.tilt_azimuth = std::atan2(0.3, 0.4);
    s.velocity = {0.4, -0.1, -0.5};
    BodyOnGround::State z = initial_state(b, s);
    const BodyOnGround::State before = z;
    const auto tr = m.start(0.0, z, true);
    ASSERT_FALSE(tr.stop);
    using S = BodyOnGround;
    const Mat3 r = rotation(quat_at(z, S::kQw));
    const Vec3 a = r * Vec3{0.2, 0.15, -0.5};
    auto h_corner = [&](const BodyOnGround::State& y) {
      const Vec3 v{y[S::kVx], y[S::kVy], y[S::kVz]}, w{y[S::kWx], y[S::kWy], y[S::kWz]};
      const Vec3 in = b.inertia(), wb = transposed_times(r, w);
      const Vec3 jw = r * Vec3{in[0] * wb[0], in[1] * wb[1], in[2] * wb[2]};
      return minus(jw, scaled(cross(a, v), b.mass));  // J w + m (G - C) x v
    };
    const Vec3 h0 = h_corner(before), h1 = h_corner(z);
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(h1[std::size_t(k)], h0[std::size_t(k)], 1e-12 * b.mass) << k;
    const Vec3 u = plus(Vec3{z[S::kVx], z[S::kVy], z[S::kVz]}, cross(Vec3{z[S::kWx], z[S::kWy], z[S::kWz]}, a));
    EXPECT_NEAR(u[2], 0.0, 1e-12);
    if (mu > 1) {
      EXPECT_LT(std::hypot(u[0], u[1]), 1e-12);
      EXPECT_EQ(tr.next.contact, BodyContact::Point);
      EXPECT_FALSE(tr.next.slips());
    } else {
      EXPECT_GT(std::hypot(u[0], u[1]), 1e-3);
      EXPECT_TRUE(tr.next.slips());
    }
  }
}

TEST(Rigid3dNewton, ACornerArrivingAtRestOnATiltedBodyJoinsTheContactWithoutAnImpact) {
  // Tilted on its +x edge and turning about it, the box's edge hands over to one end (the other
  // lifted at rounding), and that end touches again at once, at rest: no impact (no corner moves
  // into the ground), the edge takes over - the tilt, the velocities and the energy unchanged,
  // not the base put flat (the end of an accumulation, which this is not).
  using S = BodyOnGround;
  const BodyOnGround m(box_body(0.4, 0.3, 1.0, 400), {}, test::friction(5.0, 5.0));
  Body3dStart s;
  s.tilt = 0.6;
  s.angular_velocity = {0.0, 0.4, 0.0};  // falling further towards +x
  S::State z = initial_state(m.body(), s);
  auto edge = m.start(0.0, z, false);
  ASSERT_FALSE(edge.stop);
  ASSERT_EQ(edge.next.contact, BodyContact::Line);
  const auto pivot = m.transition(0.0, edge.next, z, S::kEvLoadA);
  ASSERT_FALSE(pivot.stop);
  ASSERT_EQ(pivot.next.contact, BodyContact::Point);
  const int lifted = pivot.next.released;
  ASSERT_GE(lifted, 0);
  const S::State before = z;
  const auto joined = m.transition(0.0, pivot.next, z, S::kEvTouch0 + lifted);
  ASSERT_FALSE(joined.stop);
  EXPECT_EQ(joined.next.contact, BodyContact::Line);
  for (std::size_t k = S::kX; k <= S::kWz; ++k) EXPECT_NEAR(z[k], before[k], 1e-12) << k;
  EXPECT_NEAR(m.balance(z), m.balance(before), 1e-12 * 400 * m.body().g);
}

TEST(Rigid3dNewton, PlanarRockingWithRestitutionIsTheThreeDofBlocksImpactForImpact) {
  // A box released from a tilt about its +x edge, e > 0 and friction enough: each landing edge
  // bounces, the box flies and lands again, the bounces shrink until they would rise less than
  // 1e-12 of the size and the accumulation ends at rest. The planar 3-DOF block of the same
  // section (Newton's law, the same e) does the same at the same instants, until it lands on one
  // corner with the other within its gap tolerance (1e-9 h) and takes both into that impact; the
  // box resolves that gap (kImpactTouch, 1e-12 of its size), so the two part there by design.
  const double b = 0.4, d = 0.3, h = 1.2, tilt = 0.12, mu = 5.0;
  for (const double e : {0.3, 0.6}) {
    SCOPED_TRACE(e);
    BodyOnGroundOptions o = test::friction(mu, mu);
    o.restitution = e;
    const BodyOnGround m(box_body(b, d, h, 400), {}, o);
    Body3dStart s;
    s.tilt = tilt;
    const Body3dResult r = test::run_body(m, s, 4.0);
    RigidInitial init;
    init.w0 = tilt;
    const RigidResult planar = test::planar_block_run(b, h, 400, mu, mu, {}, init, 4.0, ImpactLaw::Newton, e);
    std::vector<double> mine, ref;
    for (const auto& ev : r.events)
      if (ev.kind == Body3dEventKind::Impact) mine.push_back(ev.t);
    std::size_t resolved = 0;
    for (const auto& ev : planar.events) {
      if (ev.kind != RigidEventKind::Impact) continue;
      ref.push_back(ev.t);
      const double gap = b * std::fabs(ev.state[RigidBlock::kTheta]);  // the corner not landing
      if (resolved == 0 && gap > 0 && gap <= 1e-9 * h) resolved = ref.size();
    }
    ASSERT_GE(resolved, 100u);
    ASSERT_GE(mine.size(), resolved);
    for (std::size_t i = 0; i < resolved; ++i) EXPECT_NEAR(mine[i], ref[i], 1e-9) << "impact " << i;
    ASSERT_EQ(r.events.back().kind, Body3dEventKind::Impact);  // the last, ending at rest
    ASSERT_EQ(r.events.back().to, BodyContact::Rest);
    EXPECT_EQ(planar.final_mode, Mechanism::Rest);
    EXPECT_LT(test::balance_error(r, m), 1e-11);
  }
}

}  // namespace blockdyn::rigid3d_newton_test
