// SPDX-License-Identifier: Apache-2.0
// The 3-DOF rigid block on rigid ground (issue 7, sec. 3): the onset mechanism table and sliding
// closed forms of the spec, the Housner limit (large friction), the housner and newton impact laws,
// free flight, energy balance, symmetry, Painleve detection, and the contact problem's closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "blockdyn/model/rigid_ground/contact_problem.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "housner_reference.hpp"
#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

RigidBlockParams block(double b, double h, double mu_s, double mu_k, ImpactLaw law = ImpactLaw::Housner,
                       std::optional<double> e = std::nullopt) {
  RigidBlockParams p;
  p.shape.width = b;
  p.shape.height = h;
  p.shape.mass = 2.0;
  p.interface = {mu_s, mu_k};
  p.impact = law;
  p.restitution = e;
  return p;
}

RigidRunOptions rigid_run_to(double t) {
  RigidRunOptions o;
  o.t_end = t;
  return o;
}

GroundMotion constant_h(double A) {
  GroundMotion g;
  g.horizontal.constant = A;
  return g;
}

std::vector<RigidEventRecord> impacts(const RigidResult& r) {
  std::vector<RigidEventRecord> v;
  for (const auto& e : r.events)
    if (e.kind == RigidEventKind::Impact) v.push_back(e);
  return v;
}

// A* of the spec: above it a block with f_s >= s slide-rocks instead of rocking.
double a_star(double s, double fs) {
  const double kappa = 3.0 / (4.0 * (1.0 + s * s));
  return (fs * (1.0 - kappa * s * s) - kappa * s) / (1.0 - kappa - fs * kappa * s);
}

}  // namespace

// Onset from rest under a constant a_H = A g (spec closed form): rest, slide, rock or slide-rock.
TEST(RigidBlock, OnsetMechanismTable) {
  const double s = 0.25;  // b/h
  struct Case {
    double fs, fk, A;
    Mechanism expected;
  };
  const double as = a_star(s, 0.5);
  ASSERT_NEAR(as, 1.4642857142857142, 1e-12);
  const Case cases[] = {
      {0.2, 0.15, 0.19, Mechanism::Rest},
      {0.2, 0.15, 0.21, Mechanism::Slide},
      {0.2, 0.2, -0.21, Mechanism::Slide},
      {0.5, 0.5, 0.24, Mechanism::Rest},
      {0.5, 0.5, 0.26, Mechanism::Rock},
      {0.5, 0.5, -0.26, Mechanism::Rock},
      {0.5, 0.5, as * (1 - 1e-6), Mechanism::Rock},
      {0.5, 0.4, as * (1 + 1e-6), Mechanism::SlideRock},
      {0.5, 0.5, 3.0, Mechanism::SlideRock},
      {5.0, 5.0, 10.0, Mechanism::Rock},  // A* denominator < 0
  };
  for (const Case& c : cases) {
    const RigidResult r = simulate_rigid(block(0.3, 1.2, c.fs, c.fk), constant_h(c.A), {}, rigid_run_to(1e-3));
    EXPECT_EQ(to_string(r.initial_mode), std::string(to_string(c.expected)))
        << "f_s " << c.fs << " f_k " << c.fk << " A " << c.A;
    if (c.expected == Mechanism::Rock || c.expected == Mechanism::SlideRock) {
      EXPECT_EQ(r.final_state[2] > 0, c.A > 0) << "a_H > 0 tips the block counter-clockwise";
    }
  }
}

// Sliding (f_s < s) under constant A: relative displacement (f_k - A) g t^2 / 2, no rocking while
// f_k <= s; friction work equals -f_k m g |x|.
TEST(RigidBlock, SlidingUnderConstantAcceleration) {
  for (auto [fs, fk, A] : {std::tuple{0.2, 0.2, 0.3}, std::tuple{0.2, 0.1, 0.25}, std::tuple{0.15, 0.1, -0.4}}) {
    const RigidBlockParams p = block(0.3, 1.2, fs, fk);
    const double T = 1.5;
    const RigidResult r = simulate_rigid(p, constant_h(A), {}, rigid_run_to(T));
    const double sign = A > 0 ? 1.0 : -1.0;
    const double x_ref = -(std::fabs(A) - fk) * p.shape.g * T * T / 2.0 * sign;
    EXPECT_NEAR(r.final_state[0], x_ref, 1e-9 * std::fabs(x_ref)) << fs << " " << fk << " " << A;
    EXPECT_EQ(r.final_mode, Mechanism::Slide);
    EXPECT_EQ(r.mode_changes, 0);
    EXPECT_NEAR(r.work_friction, -fk * p.shape.mass * p.shape.g * std::fabs(x_ref), 1e-9 * std::fabs(x_ref));
  }
}

// A slide under a pulse stops when the relative velocity vanishes (stick) at the closed-form time:
// after a rectangular pulse A > f_s of duration tp, v = -(A - f_k) g tp, then decelerates at f_k g.
TEST(RigidBlock, SlideStopsWhenTheVelocityVanishes) {
  const RigidBlockParams p = block(0.3, 1.2, 0.2, 0.15);
  GroundMotion g;
  g.horizontal.pulse = PulseShape::Rect;
  g.horizontal.amplitude = 0.24;
  g.horizontal.duration = 0.5;
  const RigidResult r = simulate_rigid(p, g, {}, rigid_run_to(2.0));
  const double v = (0.24 - 0.15) * p.shape.g * 0.5;
  const double t_stop = 0.5 + v / (0.15 * p.shape.g);
  double t_rest = -1;
  for (const auto& e : r.events)
    if (e.kind == RigidEventKind::Mode && e.to == Mechanism::Rest) t_rest = e.t;
  EXPECT_NEAR(t_rest, t_stop, 1e-10);
  EXPECT_EQ(r.final_mode, Mechanism::Rest);
}

// With large friction and the housner law the 3-DOF model is Housner's model: the same impacts
// (free, and under forcing) and the same rest time.
TEST(RigidBlock, LargeFrictionReproducesHousner) {
  const RigidBlockParams p = block(0.3, 1.5, 10.0, 10.0);
  GroundMotion g;
  g.horizontal.amplitude = 0.3;
  g.horizontal.frequency = 1.2;
  g.horizontal.t_start = 0.2;
  g.horizontal.duration = 3.0;
  RigidInitial in;
  in.w0 = 0.05;
  const RigidResult a = simulate_rigid(p, g, in, rigid_run_to(12.0));
  const RigidResult b = simulate_housner(p.shape, std::nullopt, g, in, rigid_run_to(12.0));
  const auto ia = impacts(a), ib = impacts(b);
  ASSERT_GT(ib.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_NEAR(ia[k].t, ib[k].t, 1e-9);
    EXPECT_NEAR(ia[k].vw_after, ib[k].vw_after, 1e-8 * std::fabs(ib[k].vw_after) + 1e-12);
  }
  EXPECT_EQ(a.final_mode, b.final_mode);
  EXPECT_NEAR(a.max_abs_rotation, b.max_abs_rotation, 1e-9);
}

// Newton law with e_n = 0 and enough friction: the rocking impact loses exactly Housner's e_H.
TEST(RigidBlock, PlasticNewtonImpactGivesHousnerCoefficient) {
  for (double bh : {0.2, 0.6}) {
    const RigidBlockParams p = block(bh, 1.0, 5.0, 5.0, ImpactLaw::Newton, 0.0);
    RigidInitial in;
    in.w0 = 0.5 * p.shape.alpha();
    const RigidResult r = simulate_rigid(p, {}, in, rigid_run_to(1.0));
    const auto im = impacts(r);
    ASSERT_FALSE(im.empty());
    // Exact up to the rounding of the impulse solve (a 2x2 system).
    EXPECT_NEAR(im[0].vw_after / im[0].vw_before, p.shape.housner_restitution(), 1e-11) << "b/h " << bh;
    EXPECT_EQ(im[0].to, Mechanism::Rock);
  }
}

// Newton law, block dropped flat: it bounces with -e_n times its landing speed (friction plays no
// role: no tangential velocity), the flight between bounces is ballistic, impacts accumulate to rest.
TEST(RigidBlock, FlatDropBouncesWithNewtonRestitution) {
  const RigidBlockParams p = block(0.4, 1.0, 0.6, 0.6, ImpactLaw::Newton, 0.5);
  RigidInitial in;
  const double drop = 0.02;
  in.y0 = 0.5 + drop;
  in.vx0 = 0.0;
  in.vy0 = 0.0;
  const RigidResult r = simulate_rigid(p, {}, in, rigid_run_to(2.0));
  const auto im = impacts(r);
  ASSERT_GE(im.size(), 3u);
  const double g = p.shape.g;
  const double t1 = std::sqrt(2 * drop / g), v1 = std::sqrt(2 * g * drop);
  EXPECT_NEAR(im[0].t, t1, 1e-12);
  EXPECT_NEAR(im[0].state[4], 0.5 * v1, 1e-9);  // vy after the first impact
  EXPECT_NEAR(im[1].t, t1 + 2 * 0.5 * v1 / g, 1e-10);
  EXPECT_EQ(r.final_mode, Mechanism::Rest);
  EXPECT_NEAR(r.final_state[1], 0.5, 1e-15);
  EXPECT_LT(r.max_abs_energy_error, 1e-9 * p.shape.mass * g);
}

// Free flight with spin: the landing time of the first corner is the root of the closed-form gap.
TEST(RigidBlock, FreeFlightLandsWhereTheClosedFormSays) {
  const RigidBlockParams p = block(0.4, 1.0, 0.6, 0.6);
  RigidInitial in;
  in.y0 = 0.8;
  in.vx0 = 0.3;
  in.vy0 = 1.0;
  in.vw0 = 2.0;
  const RigidResult r = simulate_rigid(p, {}, in, rigid_run_to(2.0));
  const auto im = impacts(r);
  ASSERT_FALSE(im.empty());
  const double g = p.shape.g, bh = 0.2, hh = 0.5;
  auto gap = [&](double t, int side) {
    const double th = 2.0 * t, y = 0.8 + t - 0.5 * g * t * t;
    return y + (-side * bh) * std::sin(th) - hh * std::cos(th);
  };
  // First time either corner's gap vanishes, by bisection on a fine scan.
  double t_ref = -1;
  for (double t = 0.0; t < 2.0 && t_ref < 0; t += 1e-4) {
    for (int side : {1, -1}) {
      if (gap(t + 1e-4, side) < 0 && t_ref < 0) {
        double lo = t, hi = t + 1e-4;
        for (int k = 0; k < 100; ++k) ((gap(0.5 * (lo + hi), side) < 0) ? hi : lo) = 0.5 * (lo + hi);
        t_ref = lo;
      }
    }
  }
  EXPECT_NEAR(im[0].t, t_ref, 1e-12);
  EXPECT_NEAR(im[0].vw_before, 2.0, 1e-12);
}

// The closed balance E - E0 - W_friction - W_ground - W_impact stays at the integration error in
// every mechanism, under a record with slips, impacts and flights.
TEST(RigidBlock, EnergyBalanceUnderARecord) {
  GroundMotion g;
  g.horizontal.record = std::make_shared<const Accelerogram>(
      load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record"));
  g.horizontal.scale = 1.3;
  g.vertical.amplitude = 0.2;
  g.vertical.frequency = 3.1;
  for (auto law : {ImpactLaw::Housner, ImpactLaw::Newton}) {
    const RigidBlockParams p =
        block(0.35, 1.2, 0.3, 0.25, law, law == ImpactLaw::Newton ? std::optional(0.4) : std::nullopt);
    const RigidResult r = simulate_rigid(p, g, {}, rigid_run_to(30.0));
    EXPECT_GT(r.mode_changes, 5);
    EXPECT_GT(r.impacts, 3);
    const double scale = p.shape.mass * p.shape.g * p.shape.height;
    EXPECT_LT(r.max_abs_energy_error, 1e-8 * scale) << to_string(law);
    EXPECT_LT(r.work_friction, 0.0);
    EXPECT_LE(r.work_impact, 0.0);
    record((std::string("rigid_energy_balance_error_rel_") + to_string(law)).c_str(), r.max_abs_energy_error / scale);
  }
}

// A long earthquake-like record runs to its end with a finite number of events.
TEST(RigidBlock, LongRecordRunsToTheEnd) {
  GroundMotion g;
  g.horizontal.record = std::make_shared<const Accelerogram>(
      load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record"));
  for (double scale : {0.8, 1.0}) {
    g.horizontal.scale = scale;
    const RigidResult h = simulate_housner(block(0.3, 1.2, 1, 1).shape, std::nullopt, g, {}, rigid_run_to(60.0));
    const RigidResult r = simulate_rigid(block(0.3, 1.2, 0.5, 0.4), g, {}, rigid_run_to(60.0));
    for (const RigidResult* x : {&h, &r}) {
      EXPECT_NE(x->status, SimStatus::NumericalFailure) << x->model << " " << x->note;
      EXPECT_LT(x->events.size(), 100000u);
      if (x->status == SimStatus::TEnd) {
        EXPECT_DOUBLE_EQ(x->t_final, 60.0);
      }
    }
  }
}

// Mirrored ground motion mirrors the motion: x -> -x, theta -> -theta.
TEST(RigidBlock, MirroredGroundMotionMirrorsTheMotion) {
  GroundMotion g, gm;
  g.horizontal.amplitude = 0.7;
  g.horizontal.frequency = 2.0;
  gm = g;
  gm.horizontal.amplitude = -0.7;
  const RigidBlockParams p = block(0.3, 1.0, 0.35, 0.3);
  const RigidResult a = simulate_rigid(p, g, {}, rigid_run_to(6.0));
  const RigidResult b = simulate_rigid(p, gm, {}, rigid_run_to(6.0));
  ASSERT_EQ(a.events.size(), b.events.size());
  ASSERT_GT(a.mode_changes, 3);
  for (std::size_t k = 0; k < a.events.size(); ++k) {
    EXPECT_EQ(a.events[k].kind, b.events[k].kind);
    EXPECT_EQ(a.events[k].to, b.events[k].to);
    EXPECT_NEAR(a.events[k].t, b.events[k].t, 1e-11);
    EXPECT_NEAR(a.events[k].state[0], -b.events[k].state[0], 1e-11);
    EXPECT_NEAR(a.events[k].state[2], -b.events[k].state[2], 1e-11);
  }
}

// Painleve: a slender block slide-rocking with a large kinetic friction has no consistent
// mechanism: reported (status invalid, event painleve), never resolved silently.
TEST(RigidBlock, PainleveInconsistencyIsReported) {
  // s = 0.2: slide-rock about A with the corner slipping to -x has D <= 0 once f_k > (4 s^2 + 1) / (3 s).
  const RigidBlockParams p = block(0.2, 1.0, 3.0, 3.0);
  RigidInitial in;
  in.w0 = 0.05;
  in.vw0 = 0.0;
  in.vx0 = -1.0;
  in.vy0 = 0.0;
  in.y0 = 0.5 * std::cos(0.05) + 0.1 * std::sin(0.05);  // corner A on the ground
  bool reported = false;
  try {
    const RigidResult r = simulate_rigid(p, {}, in, rigid_run_to(1.0));
    reported = r.status == SimStatus::Invalid && r.event_counts[int(RigidEventKind::Painleve)] > 0;
  } catch (const std::invalid_argument& e) {
    reported = std::string(e.what()).find("Painleve") != std::string::npos;
  }
  EXPECT_TRUE(reported);
}

// The mechanisms' closed-form reactions equal the general contact problem solved for the same
// candidate (the enumeration used at every switch).
TEST(RigidBlock, ClosedFormsMatchTheContactProblem) {
  const RigidBlockParams p = block(0.3, 1.1, 0.6, 0.45);
  const RigidBlock m(p, constant_h(0.17));
  const double th = 0.13, w = -0.7;
  for (int side : {1, -1}) {
    for (Mechanism mech : {Mechanism::Rock, Mechanism::SlideRock}) {
      RigidMode md;
      md.mech = mech;
      md.side = side;
      md.slip = -1;
      RigidBlock::State z{};
      z[RigidBlock::kTheta] = side * th;
      z[RigidBlock::kOmega] = w;
      m.complete(md, z);
      const RigidReactions f = m.reactions(0.0, md, z);
      ContactProblem cp;
      cp.m = p.shape.mass;
      cp.I = p.shape.inertia_centre();
      cp.mu = p.interface;
      cp.n = 1;
      const Vec2 r = base_corner(BodyRotation::of(z[RigidBlock::kTheta]), 0.15, 0.55, side);
      cp.c[0] = ContactPoint{side, r, 0.0};
      cp.b = {-cp.m * p.shape.g * 0.17, -cp.m * p.shape.g, 0.0};
      cp.cn[0] = -w * w * r.y;
      cp.ct = -w * w * r.x;
      const bool closed[2] = {true, false};
      const auto s = solve_candidate(cp, closed, mech == Mechanism::Rock ? Tangential::Stick : Tangential::SlipNeg);
      ASSERT_TRUE(s);
      EXPECT_NEAR(s->u[0], f.ax, 1e-12);
      EXPECT_NEAR(s->u[1], f.ay, 1e-12);
      EXPECT_NEAR(s->u[2], f.alpha, 1e-12);
      EXPECT_NEAR(s->N[0], f.NA + f.NB, 1e-11);
      EXPECT_NEAR(s->T, f.TA + f.TB, 1e-11);
    }
  }
}

// Bad parameters name the field.
TEST(RigidBlock, InvalidParametersAreRejected) {
  auto msg = [](RigidBlockParams p) {
    try {
      validate(p);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  RigidBlockParams p = block(0.3, 1.0, 0.5, 0.5);
  p.interface.mu_k = 0.6;
  EXPECT_NE(msg(p).find("mu-k"), std::string::npos);
  p = block(-0.3, 1.0, 0.5, 0.5);
  EXPECT_NE(msg(p).find("width"), std::string::npos);
  p = block(0.3, 1.0, 0.5, 0.5);
  p.restitution = 1.2;
  EXPECT_NE(msg(p).find("restitution"), std::string::npos);
}
