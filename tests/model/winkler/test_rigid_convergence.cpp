// SPDX-License-Identifier: Apache-2.0
// Convergence of the Winkler model to the rigid block on rigid ground (thesis sec. 3.3, "second
// test", Table 3.2; issue 2, item 5): ic1 with w0 = 0.8, r = 2, mu = 0.3. The block starts in
// contact, its lowest corner starts sliding left, stops and slides right. The time s_r of that
// slide reversal in the Winkler model approaches the R-R model's as k grows (1e3 ... 1e10),
// monotonically.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "blockdyn/integrate/hybrid_integrator.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/model/winkler/rigid_limit.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

constexpr double kW0 = 0.8;
constexpr double kR = 2.0;
constexpr double kMu = 0.3;

struct RigidTimes {
  double contact_to_slide = NAN, reversal = NAN;
  int slide_sign = 0, reversed_sign = 0;
  bool started_in_contact = false;
};

RigidTimes rigid_reference() {
  const WinklerParams p{kR, kMu, 1.0};  // k plays no role in the rigid model
  const RigidGroundBlock model(p);
  RigidGroundBlock::State z{corner_arms(kR, kW0, 1).A, kW0, 0.0, 0.0};  // pivot at x = 0, at rest
  RigidLimitMode mode = model.initial_mode(z);
  RigidTimes out;
  out.started_in_contact = mode.contact;
  struct Obs {
    RigidTimes* out;
    bool on_step(const DenseSegment<4>&, double, double, const RigidLimitMode&) { return true; }
    bool on_event(const EventInfo<RigidLimitMode, 4>& e) {
      if (e.kind == RigidGroundBlock::kContactToSlide && std::isnan(out->contact_to_slide)) {
        out->contact_to_slide = e.t;
        out->slide_sign = e.to.friction_sign;
      }
      if (e.kind == RigidGroundBlock::kSlideReversal && std::isnan(out->reversal)) {
        out->reversal = e.t;
        out->reversed_sign = e.to.friction_sign;
      }
      return true;
    }
  } obs{&out};
  IntegratorOptions o;
  o.rtol = 1e-12;
  o.atol = 1e-14;
  HybridIntegrator<RigidGroundBlock> integ(model, o);
  double t = 0;
  const RunStatus s = integ.run(t, 10.0, mode, z, obs);
  EXPECT_EQ(s, RunStatus::ModelStop);  // the R-R model stops at w = 0 (no impact treatment)
  return out;
}

// Stops the Winkler run at the first slide reversal.
struct UntilReversal : WinklerSink {
  bool done = false;
  void on_event(const WinklerBlock&, const WinklerEventRecord& e) override {
    done |= e.kind == WinklerEventKind::SlideReversal;
  }
  bool keep_going() const override { return !done; }
};

struct WinklerTimes {
  double contact_to_slide = NAN, reversal = NAN;
  int slide_sign = 0, reversed_sign = 0;
  Regime start{};
};

WinklerTimes winkler(double k) {
  const WinklerParams p{kR, kMu, k};
  WinklerRunOptions o;
  o.t_end = 3.0;
  UntilReversal sink;
  const WinklerResult r = simulate(p, {}, ic1(p, kW0), o, &sink);
  WinklerTimes out;
  out.start = r.initial_mode.regime;
  for (const WinklerEventRecord& e : r.events) {
    if (e.kind == WinklerEventKind::ContactToSlide && std::isnan(out.contact_to_slide)) {
      out.contact_to_slide = e.t;
      out.slide_sign = e.to.friction_sign;
    }
    if (e.kind == WinklerEventKind::SlideReversal && std::isnan(out.reversal)) {
      out.reversal = e.t;
      out.reversed_sign = e.to.friction_sign;
    }
  }
  return out;
}

}  // namespace

TEST(RigidConvergence, RigidModelSequence) {
  const RigidTimes rr = rigid_reference();
  EXPECT_TRUE(rr.started_in_contact);
  ASSERT_FALSE(std::isnan(rr.contact_to_slide));
  ASSERT_FALSE(std::isnan(rr.reversal));
  EXPECT_LT(rr.contact_to_slide, rr.reversal);
  EXPECT_EQ(rr.slide_sign, +1);     // corner slides left: friction points right
  EXPECT_EQ(rr.reversed_sign, -1);  // then slides right
}

TEST(RigidConvergence, SlideReversalTimeConvergesMonotonically) {
  const RigidTimes rr = rigid_reference();
  record("rigid_s_r", rr.reversal);
  record("rigid_contact_to_slide", rr.contact_to_slide);
  std::vector<double> d_rev, d_slide;
  for (double k : {1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10}) {
    const WinklerTimes w = winkler(k);
    EXPECT_EQ(w.start, Regime::Contact) << k;
    ASSERT_FALSE(std::isnan(w.reversal)) << k;
    EXPECT_LT(w.contact_to_slide, w.reversal);
    EXPECT_EQ(w.slide_sign, +1) << k;
    EXPECT_EQ(w.reversed_sign, -1) << k;
    const std::string e = "k1e" + std::to_string(int(std::lround(std::log10(k))));
    record((e + "_s_r").c_str(), w.reversal);
    record((e + "_contact_to_slide").c_str(), w.contact_to_slide);
    d_rev.push_back(std::fabs(w.reversal - rr.reversal));
    d_slide.push_back(std::fabs(w.contact_to_slide - rr.contact_to_slide));
  }
  for (std::size_t i = 1; i < d_rev.size(); ++i) {
    EXPECT_LT(d_rev[i], d_rev[i - 1]) << "k = 1e" << i + 3;
    EXPECT_LT(d_slide[i], d_slide[i - 1]) << "k = 1e" << i + 3;
    // The onset of sliding converges like the springs' time scale 1/sqrt(k).
    EXPECT_GT(d_slide[i - 1] / d_slide[i], 2.8) << "k = 1e" << i + 3;
    EXPECT_LT(d_slide[i - 1] / d_slide[i], 3.6) << "k = 1e" << i + 3;
  }
  EXPECT_LT(d_rev.back(), 2e-6 * rr.reversal);  // k = 1e10
  EXPECT_LT(d_slide.back(), 1e-5 * rr.contact_to_slide);
}

// The 3-DOF rigid block (model/rigid) and the thesis's R-R check model (model/winkler/rigid_limit,
// a separate formulation) give the same contact -> slide and slide-reversal times.
TEST(RigidConvergence, ThreeDofRigidBlockAgreesWithTheCheckModel) {
  const RigidTimes rr = rigid_reference();
  RigidBlockParams p;
  p.shape.height = 1.0;
  p.shape.width = kR;
  p.shape.g = 1.0;  // non-dimensional time sqrt(a / g) with a = g = 1
  p.interface = {kMu, kMu};
  RigidInitial in;
  in.w0 = kW0;
  RigidRunOptions o;
  o.t_end = rr.reversal + 0.1;
  o.integrator.rtol = 1e-12;
  o.integrator.atol = 1e-14;
  const RigidResult r = simulate_rigid(p, {}, in, o);
  EXPECT_EQ(r.initial_mode, Mechanism::Rock);
  std::vector<RigidEventRecord> modes;
  for (const auto& e : r.events)
    if (e.kind == RigidEventKind::Mode) modes.push_back(e);
  ASSERT_GE(modes.size(), 2u);
  EXPECT_EQ(modes[0].to, Mechanism::SlideRock);
  EXPECT_NEAR(modes[0].t, rr.contact_to_slide, 1e-10);
  EXPECT_EQ(modes[1].to, Mechanism::SlideRock);
  EXPECT_EQ(modes[1].slip, -modes[0].slip);  // the corner's slip reverses
  EXPECT_NEAR(modes[1].t, rr.reversal, 1e-10);
}

// The Winkler block tends to the rigid block on rigid ground as k grows: the first return to
// upright (Winkler w_zero, rigid impact) converges monotonically.
TEST(RigidConvergence, WinklerFirstRockingPhaseTendsToRigid) {
  const double r = 0.25, mu = 2.0;
  RigidBlockParams p;
  p.shape.height = 1.0;
  p.shape.width = r;
  p.shape.g = 1.0;
  p.interface = {mu, mu};
  RigidInitial in;
  in.w0 = 0.5 * std::atan(r);
  RigidRunOptions o;
  o.t_end = 10.0;
  const RigidResult rg = simulate_rigid(p, {}, in, o);
  double t_rigid = NAN;
  for (const auto& e : rg.events)
    if (e.kind == RigidEventKind::Impact) {
      t_rigid = e.t;
      break;
    }
  ASSERT_FALSE(std::isnan(t_rigid));
  double prev = INFINITY;
  for (double k : {1e4, 1e6, 1e8}) {
    const WinklerParams wp{r, mu, k};
    WinklerRunOptions so;
    so.t_end = t_rigid * 1.5;
    so.stop_at_upright_passages = 1;
    const WinklerResult w = simulate(wp, {}, ic1(wp, in.w0), so);
    double t_w = NAN;
    for (const auto& e : w.events)
      if (e.kind == WinklerEventKind::WZero) t_w = e.t;
    ASSERT_FALSE(std::isnan(t_w)) << k;
    const double d = std::fabs(t_w - t_rigid);
    EXPECT_LT(d, prev) << "k " << k;
    record(("winkler_vs_rigid_first_upright_k" + std::to_string(int(std::log10(k)))).c_str(), d);
    prev = d;
  }
  EXPECT_LT(prev, 1e-3 * t_rigid);
}
