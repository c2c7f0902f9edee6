// SPDX-License-Identifier: Apache-2.0
// The exit from rest (issue 25, item 1): a block at rest leaves it the instant the ground's
// demand exceeds the resistance, |a_H| > (g + a_V) tan(alpha) (rock) or mu_s (g + a_V) (slide),
// whatever the shape of the forcing. Every excitation kind at 1.0001 times the threshold, for
// the Housner block and the 3-DOF block (rock and slide onsets), against the crossing time
// computed here in closed form (or, for the Ricker wavelet, by bisection on its formula), to
// 1e-9 s. At 1.0001x the window above the threshold lasts 0.5 % of a period: a step that
// straddles it sees positive margins at both ends.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/excitation/rest_exit.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"

using namespace blockdyn;

namespace {

constexpr double kOver = 1.0001;  // amplitude over the threshold
constexpr double kTol = 1e-9;     // s

BlockShape block(double b, double h) {
  BlockShape s;
  s.width = b;
  s.height = h;
  s.mass = 100.0;
  return s;
}

struct Case {
  std::string name;
  GroundMotion g;
  double t_cross;  // first instant the threshold is exceeded
};

// Cases for a threshold `thr` (g) on |a_H| (vertical motion absent unless stated).
std::vector<Case> cases(double thr) {
  std::vector<Case> out;
  const double A = kOver * thr, r = thr / A;
  auto add = [&](std::string n, GroundMotion g, double t) { out.push_back({std::move(n), g, t}); };
  {
    GroundMotion g;  // harmonic from zero: the case
    g.horizontal.amplitude = A;
    g.horizontal.frequency = 1.2;
    add("harmonic", g, std::asin(r) / (2 * M_PI * 1.2));
  }
  {
    GroundMotion g;  // negative amplitude: the block is pushed the other way
    g.horizontal.amplitude = -A;
    g.horizontal.frequency = 0.7;
    add("harmonic, negative", g, std::asin(r) / (2 * M_PI * 0.7));
  }
  {
    GroundMotion g;  // a phase and a late start
    g.horizontal.amplitude = A;
    g.horizontal.frequency = 2.0;
    g.horizontal.phase = -1.0;
    g.horizontal.t_start = 0.3;
    add("harmonic, phase, t_start", g, 0.3 + (std::asin(r) + 1.0) / (2 * M_PI * 2.0));
  }
  const double tp = 0.8, t0 = 0.25;
  auto pulse = [&](PulseShape p) {
    GroundMotion g;
    g.horizontal.pulse = p;
    g.horizontal.amplitude = A;
    g.horizontal.duration = tp;
    g.horizontal.t_start = t0;
    return g;
  };
  add("half-sine", pulse(PulseShape::HalfSine), t0 + tp * std::asin(r) / M_PI);
  add("one-sine", pulse(PulseShape::OneSine), t0 + tp * std::asin(r) / (2 * M_PI));
  // Starting at their peak, these jump above the threshold at their start.
  add("rect", pulse(PulseShape::Rect), t0);
  add("half-cosine", pulse(PulseShape::HalfCosine), t0);
  add("cycloidal", pulse(PulseShape::Cycloidal), t0);
  {
    // Ricker: (1 - 2u^2) exp(-u^2) = r on the rise to its peak at u = 0 (its side lobes reach
    // 2 exp(-1.5) = 0.45 < r).
    auto f = [&](double u) { return (1 - 2 * u * u) * std::exp(-u * u) - r; };
    double lo = -0.7, hi = 0.0;  // f(lo) < 0 < f(hi)
    for (int k = 0; k < 200; ++k) {
      const double mid = 0.5 * (lo + hi);
      (f(mid) < 0 ? lo : hi) = mid;
    }
    add("ricker", pulse(PulseShape::Ricker), t0 + tp * (1.5 + lo / M_PI));
  }
  {
    // A record: a ramp from 0 to A over three samples, then back down; linear between samples.
    const double dt = 0.02;
    std::vector<double> a = {0.0, 0.0, 0.4 * A, 0.8 * A, A, 0.5 * A, 0.0, 0.0};
    GroundMotion g;
    g.horizontal.record = std::make_shared<Accelerogram>(a, dt, "ramp");
    const double frac = (thr - 0.8 * A) / (0.2 * A);
    add("record", g, (3 + frac) * dt);
  }
  {
    // A vertical motion lowers the resistance under a constant horizontal demand 0.9 thr:
    // 0.9 thr > thr (1 + a_V) once a_V = -B sin(w t) < -0.1, B = 0.1 kOver.
    GroundMotion g;
    g.horizontal.constant = 0.9 * thr;
    g.vertical.amplitude = -0.1 * kOver;
    g.vertical.frequency = 1.5;
    add("vertical harmonic", g, std::asin(1.0 / kOver) / (2 * M_PI * 1.5));
  }
  return out;
}

RigidRunOptions until(double t_end) {
  RigidRunOptions o;
  o.t_end = t_end;
  return o;
}

}  // namespace

// The numbers: 0.25 g and 0.2001 g at 1.2 Hz on b/h = 0.2 (0.9563 s and 17.29 s before).
TEST(RestExit, HousnerHarmonicFromZeroLeavesRestAtTheFirstCrossing) {
  const BlockShape s = block(0.3, 1.5);
  for (double A : {0.25, 0.2001}) {
    GroundMotion g;
    g.horizontal.amplitude = A;
    g.horizontal.frequency = 1.2;
    const RigidResult r = simulate_housner(s, std::nullopt, g, {}, until(3.0));
    ASSERT_TRUE(r.first_uplift_time) << A;
    EXPECT_NEAR(*r.first_uplift_time, std::asin(0.2 / A) / (2 * M_PI * 1.2), kTol) << A;
  }
}

TEST(RestExit, HousnerEveryExcitationKindAtTheThreshold) {
  const BlockShape s = block(0.3, 1.5);  // tan(alpha) = 0.2
  for (const Case& c : cases(0.2)) {
    SCOPED_TRACE(c.name);
    const RigidResult r = simulate_housner(s, std::nullopt, c.g, {}, until(c.t_cross + 0.2));
    ASSERT_TRUE(r.first_uplift_time);
    EXPECT_NEAR(*r.first_uplift_time, c.t_cross, kTol);
  }
}

// Just below the threshold the block never moves (the search does not invent a crossing).
TEST(RestExit, HousnerBelowTheThresholdStaysAtRest) {
  const BlockShape s = block(0.3, 1.5);
  for (Case c : cases(0.2 / (kOver * kOver))) {
    SCOPED_TRACE(c.name);
    const RigidResult r = simulate_housner(s, std::nullopt, c.g, {}, until(c.t_cross + 3.0));
    EXPECT_FALSE(r.first_motion_time);
    EXPECT_EQ(r.final_mode, Mechanism::Rest);
  }
}

TEST(RestExit, RigidBlockRockOnset) {
  RigidBlockParams p;
  p.shape = block(0.3, 1.5);
  p.interface = {1.0, 1.0};  // friction far above tan(alpha) = 0.2: rocking starts first
  for (const Case& c : cases(0.2)) {
    SCOPED_TRACE(c.name);
    const RigidResult r = simulate_rigid(p, c.g, {}, until(c.t_cross + 0.2));
    ASSERT_TRUE(r.first_uplift_time);
    EXPECT_NEAR(*r.first_uplift_time, c.t_cross, kTol);
    ASSERT_TRUE(r.first_motion_time);
    EXPECT_NEAR(*r.first_motion_time, c.t_cross, kTol);
  }
}

TEST(RestExit, RigidBlockSlideOnset) {
  RigidBlockParams p;
  p.shape = block(0.6, 1.2);  // tan(alpha) = 0.5
  p.interface = {0.3, 0.25};  // sliding starts at 0.3 g
  for (const Case& c : cases(0.3)) {
    SCOPED_TRACE(c.name);
    const RigidResult r = simulate_rigid(p, c.g, {}, until(c.t_cross + 0.2));
    ASSERT_TRUE(r.first_motion_time);
    EXPECT_NEAR(*r.first_motion_time, c.t_cross, kTol);
    EXPECT_FALSE(r.first_uplift_time);
    bool slid = false;
    for (const auto& e : r.events) slid |= e.kind == RigidEventKind::Mode && e.to == Mechanism::Slide;
    EXPECT_TRUE(slid);
  }
}

// The search itself, on a shallow double-crossing window far inside a long span: found, and the
// instant it returns fails the condition while the one before holds.
TEST(RestExit, FirstRestFailureBracketsTheCrossingToRounding) {
  GroundMotion g;
  g.horizontal.amplitude = 0.2 * kOver;
  g.horizontal.frequency = 3.0;
  const double t = first_rest_failure(g, 0.2, 0.0, 100.0);
  EXPECT_NEAR(t, std::asin(1.0 / kOver) / (2 * M_PI * 3.0), 1e-12);
  EXPECT_GT(std::fabs(g.ah(t)), 0.2);
  EXPECT_LE(std::fabs(g.ah(std::nextafter(t, 0.0))), 0.2);
  // Below the threshold: nothing in 100 periods.
  g.horizontal.amplitude = 0.2 / kOver;
  EXPECT_TRUE(std::isinf(first_rest_failure(g, 0.2, 0.0, 33.0)));
}

// A resistance that depends on the direction (an asymmetric assembly): each side fails at its own.
TEST(RestExit, AsymmetricResistanceFailsOnTheWeakerSideOfTheMotion) {
  GroundMotion g;
  g.horizontal.amplitude = 0.3;
  g.horizontal.frequency = 1.0;
  // a_H > 0 never exceeds 0.5; a_H < 0 exceeds 0.2 where sin(2 pi t) = -2/3.
  const double t = first_rest_failure(g, 0.5, 0.2, 0.0, 10.0);
  EXPECT_NEAR(t, (M_PI + std::asin(2.0 / 3.0)) / (2 * M_PI), 1e-12);
  EXPECT_NEAR(first_rest_failure(g, 0.2, 0.5, 0.0, 10.0), std::asin(2.0 / 3.0) / (2 * M_PI), 1e-12);
  const RestExit exit(g, 0.5, 0.2);
  EXPECT_NEAR(exit.checkpoint(0.0), t, 1e-12);
}

// The rigid assemblies, event-driven: the block, the frame and the column leave rest at the
// crossing of their static limit (b/h of the whole = 0.25, whatever the lintel).
TEST(RestExit, RigidAssemblyEveryExcitationKindAtTheThreshold) {
  PresetOptions o;
  o.contact = blockdyn::ContactKind::Rigid;
  o.ground_law.restitution = o.block_law.restitution = 0.0;
  for (const char* preset : {"block", "trilith", "column"}) {
    const Assembly a = make_preset(preset, o);
    for (const Case& c : cases(0.25)) {
      SCOPED_TRACE(std::string(preset) + ": " + c.name);
      AssemblyRunOptions run;
      run.t_end = c.t_cross + 0.05;
      run.scheme = AssemblyScheme::EventDriven;
      const AssemblyResult r = simulate_assembly(a, c.g, run);
      ASSERT_FALSE(r.events.empty());
      EXPECT_STREQ(blockdyn::assembly_event_name(r.events[0].kind), "open");
      EXPECT_NEAR(r.events[0].t, c.t_cross, kTol);
    }
  }
}
