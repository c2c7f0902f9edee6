// SPDX-License-Identifier: Apache-2.0
// The rigid3d box slipping while it rocks on an edge or pivots on a corner
// (model/rigid3d/contact_slip.hpp, body_contact_slip.cpp), each check against something
// independent: the planar 3-DOF block's slide-rock (the planar limit: its mechanism change and
// impacts at the same instants, the same slip); a frictionless ground (no horizontal force: the
// centroid falls straight down, the vertical angular momentum and the energy kept); a square base
// turned by a quarter turn with its start (the turned response); refinement of the tolerances;
// and the closed energy balance with the friction's work under a two-component record.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "blockdyn/excitation/stochastic_motion.hpp"
#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/contact_slip.hpp"
#include "blockdyn/simulation/rigid3d_simulation.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "model/rigid3d/body3d_run.hpp"

using blockdyn::Body3dEventKind;
using blockdyn::Body3dResult;
using blockdyn::BodyContact;
using blockdyn::BodyOnGround;
using blockdyn::BodyOnGroundOptions;

namespace slip_test {

using blockdyn::test::friction;

using blockdyn::operator*;

using blockdyn::test::kG;

Body3dResult released(const BodyOnGround& m, double tilt, double azimuth, double t_end, double rtol = 1e-12) {
  blockdyn::Body3dStart s;
  s.tilt = tilt;
  s.tilt_azimuth = azimuth;
  blockdyn::Body3dRunOptions o;
  o.t_end = t_end;
  o.integ.rtol = rtol;
  o.integ.atol = rtol * 1e-2;
  return blockdyn::simulate_body3d(m, blockdyn::initial_state(m.body(), s), o);
}

bool slips(const blockdyn::Body3dEventRecord& e) { return e.to_slipping != 0; }

// The distinct instants of the impacts (the planar block's double impacts share one).
template <class Events, class IsImpact>
std::vector<double> impact_instants(const Events& events, IsImpact is_impact) {
  std::vector<double> t;
  for (const auto& e : events)
    if (is_impact(e) && (t.empty() || e.t - t.back() > 1e-12)) t.push_back(e.t);
  return t;
}

double balance_error(const Body3dResult& r, const BodyOnGround& m) {
  return r.max_abs_energy_error / (m.body().mass * kG * m.size());
}

TEST(Rigid3dSlip, PlanarLimitIsTheThreeDofBlocksSlideRock) {
  // A slender square column released from a tilt on low friction: its edge starts slipping while
  // it rocks, then lands and rocks on, slipping; the planar 3-DOF block of the same section does
  // the same (rock -> slide-rock, then impacts) at the same instants, and slips as far - under
  // Newton's and Coulomb's impact law (the planar block's newton law, e = 0) and under Housner's.
  const double b = 0.4, h = 1.6, tilt = 0.15, mu = 0.1, t_end = 0.8;
  for (const bool newton : {true, false}) {
    SCOPED_TRACE(newton ? "newton" : "housner");
    BodyOnGroundOptions o = friction(mu, mu);
    o.impact = newton ? blockdyn::Body3dImpactLaw::Newton : blockdyn::Body3dImpactLaw::Housner;
    const BodyOnGround m(blockdyn::box_body(b, b, h, 400), {}, o);
    const Body3dResult r = released(m, tilt, 0.0, t_end);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;

    blockdyn::RigidInitial init;
    init.w0 = tilt;
    const blockdyn::RigidResult planar = blockdyn::test::planar_block_run(
        b, h, 400, mu, mu, {}, init, t_end, newton ? blockdyn::ImpactLaw::Newton : blockdyn::ImpactLaw::Housner);
    ASSERT_EQ(planar.status, blockdyn::SimStatus::TEnd);

    double onset = -1, onset3 = -1;
    for (const auto& e : planar.events)
      if (onset < 0 && e.to == blockdyn::Mechanism::SlideRock) onset = e.t;
    for (const auto& e : r.events)
      if (onset3 < 0 && slips(e)) onset3 = e.t;
    ASSERT_GT(onset, 0.0);
    EXPECT_NEAR(onset3, onset, 1e-9);
    // Both ends of the edge start slipping together (a planar motion loads them alike).
    const auto first = std::find_if(r.events.begin(), r.events.end(), slips);
    EXPECT_EQ(first->to_slipping, 3u);
    EXPECT_EQ(first->to, BodyContact::Line);

    const auto impacts =
        impact_instants(planar.events, [](const auto& e) { return e.kind == blockdyn::RigidEventKind::Impact; });
    const auto impacts3 = impact_instants(r.events, [](const auto& e) { return e.kind == Body3dEventKind::Impact; });
    ASSERT_GE(impacts.size(), 2u);
    ASSERT_EQ(impacts3.size(), impacts.size());
    for (std::size_t i = 0; i < impacts.size(); ++i) EXPECT_NEAR(impacts3[i], impacts[i], 1e-9) << "impact " << i;
    // The same slip: the centroid's horizontal position and velocity (the planar block's positive
    // rotation leans it towards -x, the tilt here towards +x: a mirror image).
    EXPECT_NEAR(r.z[BodyOnGround::kX], -planar.final_state[blockdyn::RigidBlock::kX], 1e-9);
    EXPECT_NEAR(r.z[BodyOnGround::kVx], -planar.final_state[blockdyn::RigidBlock::kVX], 1e-9);
    EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-13);
    EXPECT_GT(r.max_slide, 1e-3);
    EXPECT_LT(balance_error(r, m), 1e-11);
  }
}

TEST(Rigid3dSlip, AThrownStartOnAnEdgeSlipsAsThePlanarBlock) {
  // A box resting tilted on an edge and thrown across it, either way: the edge slips from t = 0
  // (both ends alike) until friction stops it, then the box rocks and lands; the planar 3-DOF
  // block started with the mirrored velocity does the same at the same instants. Before, the start
  // took the velocities the edge allows (the throw's slip was dropped).
  const double b = 0.4, d = 0.3, h = 1.2, tilt = 0.1, mu = 0.3, t_end = 1.0;
  for (const double v : {0.3, -0.3}) {
    SCOPED_TRACE(v);
    const BodyOnGround m(blockdyn::box_body(b, d, h, 400), {}, friction(mu, mu));
    blockdyn::Body3dStart s;
    s.tilt = tilt;
    s.velocity = {v, 0, 0};
    const Body3dResult r = blockdyn::test::run_body(m, s, t_end, true);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    blockdyn::RigidInitial init;
    init.w0 = tilt;
    init.vx0 = -v;
    const blockdyn::RigidResult planar = blockdyn::test::planar_block_run(b, h, 400, mu, mu, {}, init, t_end);
    ASSERT_EQ(planar.status, blockdyn::SimStatus::TEnd);
    ASSERT_EQ(r.events.size(), planar.events.size());
    ASSERT_GE(r.events.size(), 3u);
    // The slip's end, then the impacts.
    EXPECT_EQ(r.events[0].kind, Body3dEventKind::Stick);
    EXPECT_EQ(r.events[0].from_slipping, 3u);
    EXPECT_EQ(planar.events[0].from, blockdyn::Mechanism::SlideRock);
    for (std::size_t i = 0; i < r.events.size(); ++i) EXPECT_NEAR(r.events[i].t, planar.events[i].t, 1e-9) << i;
    EXPECT_NEAR(r.z[BodyOnGround::kX], -planar.final_state[blockdyn::RigidBlock::kX], 1e-9);
    EXPECT_NEAR(r.z[BodyOnGround::kVx], -planar.final_state[blockdyn::RigidBlock::kVX], 1e-9);
    EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-13);
    EXPECT_LT(balance_error(r, m), 1e-11);
  }
}

TEST(Rigid3dSlip, FrictionlessGroundLetsTheCentroidFallStraightDown) {
  // Without friction the ground pushes only upwards: the centroid's horizontal position and
  // velocity and the vertical angular momentum stay as they started, here zero; the edge and the
  // corner slip from the start and the energy is kept (no friction work). Up to the first impact
  // (Housner's law there makes the contact point stop: an impulse that needs friction).
  const BodyOnGround m(blockdyn::box_body(0.5, 0.3, 1.2, 200), {}, friction(0.0, 0.0));
  for (double az : {0.0, 0.6, 2.0}) {  // an edge's side, towards a corner, another corner
    const Body3dResult r = released(m, 0.1, az, 0.08);
    ASSERT_EQ(r.status, blockdyn::SimStatus::TEnd) << r.note;
    EXPECT_TRUE(r.events.empty()) << az;
    EXPECT_TRUE(r.mode.slips()) << az;
    EXPECT_GT(r.max_slide, 1e-4) << az;
    EXPECT_EQ(r.first_slide_time, 0.0) << az;
    EXPECT_NEAR(r.z[BodyOnGround::kX], 0.0, 1e-13) << az;
    EXPECT_NEAR(r.z[BodyOnGround::kY], 0.0, 1e-13) << az;
    EXPECT_NEAR(r.z[BodyOnGround::kVx], 0.0, 1e-13) << az;
    EXPECT_NEAR(r.z[BodyOnGround::kVy], 0.0, 1e-13) << az;
    // L_z = (I w)_z in the world frame: the inertia's third row R diag(I) R^T times w.
    const auto& z = r.z;
    const blockdyn::Mat3 q =
        blockdyn::rotation({z[BodyOnGround::kQw], z[BodyOnGround::kQx], z[BodyOnGround::kQy], z[BodyOnGround::kQz]});
    const blockdyn::Vec3 w{z[BodyOnGround::kWx], z[BodyOnGround::kWy], z[BodyOnGround::kWz]};
    const blockdyn::Vec3 in = m.body().inertia(), wb = blockdyn::transposed_times(q, w);
    const blockdyn::Vec3 lb{in[0] * wb[0], in[1] * wb[1], in[2] * wb[2]};
    EXPECT_NEAR((q * lb)[2], 0.0, 1e-12 * m.body().mass * m.size()) << az;
    EXPECT_NEAR(z[BodyOnGround::kWorkFriction], 0.0, 1e-15) << az;
    EXPECT_LT(balance_error(r, m), 1e-11) << az;
  }
}

TEST(Rigid3dSlip, QuarterTurnOfASquareAndItsStartTurnsTheSlip) {
  // A square column released towards a corner (off the diagonal) on moderate friction pivots,
  // slips and lands; the start turned by 90 degrees gives the turned motion, under either law.
  for (const bool newton : {true, false}) {
    SCOPED_TRACE(newton ? "newton" : "housner");
    BodyOnGroundOptions o = friction(0.25, 0.2);
    o.impact = newton ? blockdyn::Body3dImpactLaw::Newton : blockdyn::Body3dImpactLaw::Housner;
    const BodyOnGround m(blockdyn::box_body(0.4, 0.4, 1.4, 300), {}, o);
    const double az = 0.5;
    const Body3dResult r0 = released(m, 0.2, az, 1.5), r90 = released(m, 0.2, az + M_PI / 2, 1.5);
    ASSERT_EQ(r0.status, blockdyn::SimStatus::TEnd) << r0.note;
    ASSERT_EQ(r90.status, blockdyn::SimStatus::TEnd) << r90.note;
    ASSERT_TRUE(std::any_of(r0.events.begin(), r0.events.end(), slips));
    // Inside an accumulation of impacts the instants are as ill-conditioned as their gaps are
    // short (rounding of 1e-16 grows to 1e-12 where they are 1e-7 s apart, and the count of its
    // last impacts to one or two either way): the events compared are those more than a
    // millisecond after the one before, kinds and instants.
    auto spaced = [](const Body3dResult& r) {
      std::vector<const blockdyn::Body3dEventRecord*> v;
      for (std::size_t i = 0; i < r.events.size(); ++i)
        if (i == 0 || r.events[i].t - r.events[i - 1].t >= 1e-3) v.push_back(&r.events[i]);
      return v;
    };
    // Housner's law ends an accumulation at rest (the same state either way); under Newton's a
    // corner can come out of one still slipping, its state as ill-conditioned as the accumulation's
    // last gaps (measured: 8e-12 s after a 1e-7 s accumulation): 1e-12 up to the first
    // accumulation, then 1e-9.
    const auto e0 = spaced(r0), e90 = spaced(r90);
    ASSERT_EQ(e90.size(), e0.size());
    double tol = 1e-12;
    for (std::size_t i = 0, k = 0; i < e0.size(); ++i) {
      while (newton && k < r0.events.size() && &r0.events[k] != e0[i]) {
        if (k > 0 && r0.events[k].t - r0.events[k - 1].t < 1e-3) tol = 1e-9;
        ++k;
      }
      EXPECT_EQ(e90[i]->kind, e0[i]->kind) << i;
      EXPECT_EQ(e90[i]->to_slipping, e0[i]->to_slipping) << i;
      EXPECT_NEAR(e90[i]->t, e0[i]->t, tol) << i;
    }
    EXPECT_GE(e0.size(), 8u);
    EXPECT_NEAR(r90.z[BodyOnGround::kX], -r0.z[BodyOnGround::kY], tol);
    EXPECT_NEAR(r90.z[BodyOnGround::kY], r0.z[BodyOnGround::kX], tol);
    EXPECT_NEAR(r90.max_slide, r0.max_slide, tol);
    EXPECT_LT(balance_error(r0, m), 1e-11);
  }
}

TEST(Rigid3dSlip, SlipOnsetAndImpactsConvergeUnderRefinement) {
  // The same corner release at tolerances 1e-9, 1e-11 and 1e-13: the slip onset and the first
  // impacts move by less than the looser tolerance allows, and by less as it tightens.
  const BodyOnGround m(blockdyn::box_body(0.4, 0.5, 1.4, 300), {}, friction(0.25, 0.2));
  auto first_times = [&](double rtol) {
    const Body3dResult r = released(m, 0.2, 0.7, 1.0, rtol);
    std::vector<double> t;
    for (const auto& e : r.events)
      if (t.size() < 4) t.push_back(e.t);
    return t;
  };
  const auto a = first_times(1e-9), b = first_times(1e-11), c = first_times(1e-13);
  ASSERT_EQ(a.size(), 4u);
  ASSERT_EQ(b.size(), a.size());
  ASSERT_EQ(c.size(), a.size());
  double coarse = 0, fine = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    coarse = std::fmax(coarse, std::fabs(a[i] - c[i]));
    fine = std::fmax(fine, std::fabs(b[i] - c[i]));
  }
  EXPECT_LT(coarse, 1e-6);
  EXPECT_LT(fine, 1e-8);
  EXPECT_LE(fine, coarse);
}

TEST(Rigid3dSlip, TwoRecordComponentsSlipWithTheBalanceClosed) {
  // A square column under the fixture record along 30 degrees (x 2) and
  // across it: its edges and corners stick and slip; the friction's work enters the balance.
  const auto rec = blockdyn::test::fixture_record();
  blockdyn::GroundMotion3d g;
  g.azimuth = 30;
  g.h.record = g.h2.record = rec;
  g.h.scale = 2.0;
  const BodyOnGround m(blockdyn::box_body(0.4, 0.4, 1.2, 300), g, friction(0.5, 0.4));
  const Body3dResult r = blockdyn::test::run_body(m, {}, 30.0);
  ASSERT_NE(r.status, blockdyn::SimStatus::Invalid) << r.note;
  EXPECT_TRUE(std::any_of(r.events.begin(), r.events.end(), slips));
  EXPECT_LT(r.z[BodyOnGround::kWorkFriction], 0.0);
  EXPECT_GT(r.max_slide, 0.0);
  EXPECT_LT(balance_error(r, m), 1e-9);
}

TEST(Rigid3dSlip, AStickNearedOffItsReferenceDoesNotChatter) {
  // A corner's slip that nears its stick turning away from its reference (record 11 of a seeded
  // two-component suite, x 2.05): once it ran on with steps that never grew, its friction's
  // direction jumping where the slip entered the noise. The run ends (it overturns) in a few
  // thousand steps, its balance closed.
  blockdyn::RezaeianParams h;
  h.arias = 1.2;
  h.d5_95 = 6;
  h.t_mid = 5;
  h.f_mid = 2.5;
  h.f_slope = -0.05;
  h.t_end = 15;
  blockdyn::RezaeianParams h2 = h;
  h2.arias = 0.8;
  auto record = [](const blockdyn::RezaeianParams& p, std::uint64_t index) {
    const auto r = blockdyn::rezaeian_record(p, blockdyn::fit_modulation(p.arias, p.d5_95, p.t_mid, p.g), 2026, index);
    return std::make_shared<const blockdyn::Accelerogram>(r.a, p.dt, "suite record 11");
  };
  blockdyn::GroundMotion3d g;
  g.h.record = record(h, 10);
  g.h2.record = record(h2, 10 + (std::uint64_t(1) << 40));
  g.h.scale = g.h2.scale = 2.0457282429569172;
  const BodyOnGround m(blockdyn::box_body(0.4, 0.4, 1.2, 100), g, friction(0.7, 0.7));
  blockdyn::Body3dRunOptions o;
  o.t_end = 20;
  const Body3dResult r = blockdyn::simulate_body3d(m, blockdyn::initial_state(m.body(), {}), o);
  EXPECT_STREQ(to_string(r.status), "overturned") << r.note;
  EXPECT_LT(r.stats.accepted, 20000);
  EXPECT_TRUE(std::any_of(r.events.begin(), r.events.end(), slips));
  EXPECT_LT(balance_error(r, m), 1e-9);
}

// An edge's two end reactions (axis x, ends at +-L): the total force and the moment about the
// midpoint they make, and each end's friction margin mu N - |T|.
struct EdgeEnds {
  blockdyn::Vec3 plus, minus;
};
double margin(const blockdyn::Vec3& f, double mu) { return mu * f[2] - std::hypot(f[0], f[1]); }
blockdyn::LineLoads split_of(const EdgeEnds& e, double half_length, double mu) {
  const blockdyn::Vec3 axis{1, 0, 0};
  const blockdyn::Vec3 force = blockdyn::plus(e.plus, e.minus);
  const blockdyn::Vec3 moment = blockdyn::cross(blockdyn::scaled(axis, half_length), blockdyn::minus(e.plus, e.minus));
  return blockdyn::split_line_reaction(force, moment, axis, half_length, mu);
}

TEST(Rigid3dSlip, AnEdgeSplitsItsForceAlongItSoBothEndsHoldWhereAnySplitWould) {
  // The force along a sticking edge can be carried in any split (a rigid edge's ends cannot move
  // apart); the split kept leaves the most friction to spare at the worse end. Closed forms:
  // ends loaded alike with tangential forces 0.3 and 0.5 normal to the edge and 0.6 along it:
  // x^2 + 0.3^2 = (0.6 - x)^2 + 0.5^2 gives x = 0.52 / 1.2 at the first end, margins equal.
  const double mu = 0.7, l = 0.2;
  const blockdyn::LineLoads even = split_of({{0.3, 0.3, 1}, {0.3, -0.5, 1}}, l, mu);
  EXPECT_NEAR(even.plus[0], 0.52 / 1.2, 1e-14);
  EXPECT_NEAR(even.minus[0], 0.6 - 0.52 / 1.2, 1e-14);
  EXPECT_NEAR(margin(even.plus, mu), margin(even.minus, mu), 1e-14);
  for (int k = 0; k <= 1000; ++k) {  // no split leaves more at the worse end
    const double x = 0.6 * k / 1000;
    const double worse = std::fmin(margin({x, 0.3, 1}, mu), margin({0.6 - x, -0.5, 1}, mu));
    EXPECT_LE(worse, margin(even.plus, mu) + 1e-15);
  }
  // The second end near its limit by its normal part alone (0.69 of mu 0.7): sharing the 0.5
  // along the edge by the loads (0.25 each) would need 0.734 there; the first end takes it all.
  const blockdyn::LineLoads uneven = split_of({{0.25, 0.1, 1}, {0.25, 0.69, 1}}, l, mu);
  EXPECT_DOUBLE_EQ(uneven.plus[0], 0.5);
  EXPECT_EQ(uneven.minus[0], 0.0);
  EXPECT_GT(margin(uneven.plus, mu), 0.18);
  EXPECT_NEAR(margin(uneven.minus, mu), 0.01, 1e-14);
  // Whatever the split, the ends carry the total force and the moment given, and the loads and
  // the forces normal to the edge are the given ones (planar: nothing along the edge).
  for (const EdgeEnds& e : {EdgeEnds{{0.3, 0.3, 1}, {0.3, -0.5, 1}}, EdgeEnds{{0.25, 0.1, 1}, {0.25, 0.69, 1}},
                            EdgeEnds{{0, 0.2, 0.4}, {0, 0.1, 0.6}}}) {
    const blockdyn::LineLoads s = split_of(e, l, mu);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(s.plus[c] + s.minus[c], e.plus[c] + e.minus[c], 1e-15);
    for (int c = 1; c < 3; ++c) {
      EXPECT_NEAR(s.plus[c], e.plus[c], 1e-15);
      EXPECT_NEAR(s.minus[c], e.minus[c], 1e-15);
    }
  }
  const blockdyn::LineLoads planar = split_of({{0, 0.2, 0.4}, {0, 0.1, 0.6}}, l, mu);
  EXPECT_EQ(planar.plus[0], 0.0);
  EXPECT_EQ(planar.minus[0], 0.0);
}

// The closed form (docs/3d.md, derived from the Delassus matrix of the end B with the end A
// held): an upright box of half sizes a (normal to the edge), b (along it), c (height) on an
// edge, A sticking and B slipping outwards (normal to the edge, the only slip a rigid edge lets
// one end make), has a consistent load at B only below
//   mu* = (16 a^4 + 16 a^2 b^2 + 16 a^2 c^2 + 7 b^2 c^2) / (3 a c (4 a^2 + 3 b^2 + 4 c^2)).
double one_end_critical_friction(double a, double b, double c) {
  return (16 * a * a * a * a + 16 * a * a * b * b + 16 * a * a * c * c + 7 * b * b * c * c) /
         (3 * a * c * (4 * a * a + 3 * b * b + 4 * c * c));
}

TEST(Rigid3dSlip, OneEndSlippingOffAnEdgeIsConsistentBelowItsClosedFormFriction) {
  const double mass = 2.0;
  for (const auto& half : {std::array<double, 3>{0.2, 0.2, 0.6}, std::array<double, 3>{0.15, 0.4, 0.5},
                           std::array<double, 3>{0.3, 0.1, 1.5}}) {
    const double a = half[0], b = half[1], c = half[2];
    const blockdyn::Vec3 inertia{mass * (b * b + c * c) / 3, mass * (a * a + c * c) / 3, mass * (a * a + b * b) / 3};
    blockdyn::ContactPoints p;
    p.n = 2;
    p.arm = {blockdyn::Vec3{-a, -b, -c}, blockdyn::Vec3{-a, b, -c}};
    p.sticks = {true, false};
    p.dir = {blockdyn::Vec3{0, 0, 0}, blockdyn::Vec3{-1, 0, 0}};
    const blockdyn::Mat3 upright{blockdyn::Vec3{1, 0, 0}, blockdyn::Vec3{0, 1, 0}, blockdyn::Vec3{0, 0, 1}};
    auto consistency = [&](double mu) {
      return blockdyn::slipping_contact_motion(inertia, mass, upright, p, {0, 0, 0}, {0, 0, -kG}, mu).consistency;
    };
    const double mu_star = one_end_critical_friction(a, b, c);
    EXPECT_GT(consistency(mu_star * (1 - 1e-8)), 0) << a << " " << b << " " << c;
    EXPECT_LT(consistency(mu_star * (1 + 1e-8)), 0) << a << " " << b << " " << c;
    EXPECT_GT(consistency(0.0), 0);
  }
  EXPECT_NEAR(one_end_critical_friction(0.2, 0.2, 0.6), 0.6175710594315245, 1e-15);  // the census's column
}

}  // namespace slip_test
