// SPDX-License-Identifier: Apache-2.0
// Stroboscopic sampling, (m, n) cycles and impact maps (issue 9 items 4-5): the detector on
// constructed sequences with known cycles and a change of type; real periodic rocking of the
// Housner block under harmonic forcing whose period is established from the impacts themselves
// (a symmetric (1,1) orbit: impacts every T/2 with opposite velocities; a (1,3) orbit: the
// impact pattern repeats after 3 T); strobe samples of a periodic orbit repeat; the impact
// map's phases against the ground motion's own cosine; every forced model family on one case.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "blockdyn/analysis/forced/cycle_detection.hpp"
#include "blockdyn/analysis/forced/forced_trace.hpp"
#include "blockdyn/analysis/forced/impact_map.hpp"
#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "blockdyn/simulation/rigid_probe.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "test_support.hpp"

using namespace blockdyn;

namespace {

// ------------------------------------------------------------------ constructed sequences

// A (1,3) orbit for k < kc (strobe pattern of period 3, 2 impacts per 3 periods), then a (2,6)
// orbit (period 6, 4 impacts per 6 periods), up to K samples.
struct Synthetic {
  StrobeSeries s;
  std::vector<double> impacts;
};

Synthetic one_three_then_two_six(long kc, long K, double scale = 1.0) {
  Synthetic y;
  y.s.t0 = 0.0;
  y.s.period = 0.25;
  const double a3[3] = {0.8, -0.3, 0.5}, w3[3] = {-1.0, 1.5, 0.2};
  // No sample of the (2,6) orbit comes within 5% of the (1,3) orbit's at the same index.
  const double a6[6] = {0.6, -0.1, 0.3, 0.95, -0.45, 0.65}, w6[6] = {-0.7, 1.2, 0.5, -1.3, 1.8, -0.1};
  for (long k = 0; k < K; ++k) {
    const bool first = k < kc;
    y.s.theta.push_back(scale * (first ? a3[k % 3] : a6[k % 6]));
    y.s.omega.push_back(scale * (first ? w3[k % 3] : w6[k % 6]));
    y.s.theta_amp.push_back(scale * 1.0);
    y.s.omega_amp.push_back(scale * 2.0);
  }
  const double T = y.s.period;
  for (long q = 0; 3 * q < kc; ++q)
    for (double f : {0.4, 1.9}) y.impacts.push_back((3 * q + f) * T);
  for (long q = 0; kc + 6 * q < K; ++q)
    for (double f : {0.4, 1.9, 3.3, 4.8}) y.impacts.push_back((kc + 6 * q + f) * T);
  return y;
}

}  // namespace

TEST(CycleDetection, FindsAOneThreeCycleThenATwoSixCycleThenCollapse) {
  const long kc = 120, K = 200;
  const Synthetic y = one_three_then_two_six(kc, K);
  const double T = y.s.period, t_fail = (K + 0.5) * T;
  const CycleReport r = detect_cycles(y.s, y.impacts, CycleOptions{}, t_fail);
  // Windows of 24 periods: the last (1,3) window ends at sample kc - 1 (its returns after 3
  // periods stay before the change), the first (2,6) window starts at kc.
  ASSERT_EQ(r.segments.size(), 4u);
  EXPECT_EQ(r.segments[0].label(), "(1,3)");
  EXPECT_EQ(r.segments[0].m(), 1.0);
  EXPECT_EQ(r.segments[0].n, 3);
  EXPECT_DOUBLE_EQ(r.segments[0].t_start, 0.0);
  EXPECT_DOUBLE_EQ(r.segments[0].t_end, (kc - 1) * T);
  EXPECT_EQ(r.segments[0].return_distance, 0.0);
  EXPECT_EQ(r.segments[1].type, "non-periodic");
  EXPECT_EQ(r.segments[2].label(), "(2,6)");
  EXPECT_DOUBLE_EQ(r.segments[2].t_start, kc * T);
  EXPECT_DOUBLE_EQ(r.segments[2].t_end, (K - 1) * T);
  EXPECT_EQ(r.segments[3].type, "collapse");
  EXPECT_EQ(r.segments[3].t_start, t_fail);
  ASSERT_EQ(r.changes.size(), 3u);
  EXPECT_EQ(r.changes[0].from, "(1,3)");
  EXPECT_EQ(r.changes[1].to, "(2,6)");
  EXPECT_EQ(r.changes[2].to, "collapse");
  EXPECT_EQ(r.dominant, "(1,3)");
  // 2 impacts per 3 periods over the (1,3) segment [0, 119 T): at (3q + 0.4) T and (3q + 1.9) T, q = 0..39.
  EXPECT_EQ(r.segments[0].impacts, 80);
}

TEST(CycleDetection, ToleranceIsRelativeToTheAmplitudeAndAcceptsSmallNoise) {
  const long kc = 120, K = 200;
  for (double scale : {1e-7, 1.0, 1e5}) {
    Synthetic y = one_three_then_two_six(kc, K, scale);
    // Noise of 1% of the amplitude (deterministic) keeps the cycles at the default 5%.
    for (std::size_t k = 0; k < y.s.theta.size(); ++k) y.s.theta[k] += 0.01 * scale * std::sin(1.7 * double(k) * k);
    const CycleReport r = detect_cycles(y.s, y.impacts, CycleOptions{});
    ASSERT_EQ(r.segments.size(), 3u) << scale;
    EXPECT_EQ(r.segments[0].label(), "(1,3)") << scale;
    EXPECT_EQ(r.segments[2].label(), "(2,6)") << scale;
    EXPECT_GT(r.segments[0].return_distance, 0.005);
    EXPECT_LE(r.segments[0].return_distance, 0.05);
    // A strict tolerance sees the noise: nothing periodic.
    CycleOptions strict;
    strict.tolerance = 1e-3;
    EXPECT_EQ(detect_cycles(y.s, y.impacts, strict).dominant, "non-periodic") << scale;
  }
}

TEST(CycleDetection, ChaoticSamplesAreNonPeriodicAndNoImpactsIsSaid) {
  StrobeSeries s;
  s.period = 1.0;
  std::vector<double> impacts;
  double x = 0.3141;
  for (int k = 0; k < 150; ++k) {
    x = 4.0 * x * (1.0 - x);  // the logistic map at r = 4: chaotic
    s.theta.push_back(x - 0.5);
    s.omega.push_back(std::sqrt(x));
    s.theta_amp.push_back(0.5);
    s.omega_amp.push_back(1.0);
    impacts.push_back(k + 0.5);
  }
  const CycleReport r = detect_cycles(s, impacts, CycleOptions{});
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_EQ(r.segments[0].type, "non-periodic");
  EXPECT_EQ(r.dominant, "non-periodic");
  EXPECT_EQ(r.windows, 150 - 1 - 24 + 1);
  const CycleReport none = detect_cycles(s, {}, CycleOptions{});
  ASSERT_EQ(none.segments.size(), 1u);
  EXPECT_EQ(none.segments[0].type, "no-impacts");
}

TEST(CycleDetection, TransientIsSkippedAndShortRunsFitTheWindow) {
  StrobeSeries s;
  s.period = 0.5;
  std::vector<double> impacts;
  double x = 0.2;
  for (int k = 0; k < 80; ++k) {
    x = 4.0 * x * (1.0 - x);
    const bool settled = k >= 30;
    s.theta.push_back(settled ? 0.25 : x - 0.5);
    s.omega.push_back(settled ? -0.75 : x);
    s.theta_amp.push_back(0.5);
    s.omega_amp.push_back(1.0);
    impacts.push_back((k + 0.3) * s.period);
    impacts.push_back((k + 0.8) * s.period);
  }
  CycleOptions o;
  o.transient = 30;
  const CycleReport r = detect_cycles(s, impacts, o);
  ASSERT_EQ(r.segments.size(), 1u);
  EXPECT_EQ(r.segments[0].label(), "(1,1)");
  EXPECT_DOUBLE_EQ(r.segments[0].t_start, 30 * s.period);
  // 10 periods after the transient: the window shrinks to 10, periods up to 5.
  const CycleOptions f = fitted(CycleOptions{}, 10);
  EXPECT_EQ(f.window, 10);
  EXPECT_EQ(f.max_period, 5);
  EXPECT_EQ(fitted(CycleOptions{}, 100).window, 24);
  for (auto bad : {CycleOptions{1, 1, 0.05, 0}, CycleOptions{24, 13, 0.05, 0}, CycleOptions{24, 12, 0.0, 0},
                   CycleOptions{24, 12, 0.05, -1}})
    EXPECT_THROW(validate(bad), std::invalid_argument);
}

// ------------------------------------------------------------------ real rocking orbits

namespace {

const BlockShape kShape{0.3, 1.5, 1.0, 9.81};

struct HousnerCase {
  ForcedTrace trace;
  RigidResult result;
  double Omega, T, phase;
  GroundMotion g;
};

// Housner's block from rest under a_H = beta alpha g cos(omega p t + phase), `periods` periods,
// sampled `per` times per period from the forcing phase phi0.
HousnerCase housner_case(double beta, double omega, double periods, double phase = 0.0, double phi0 = 0.0,
                         int per = 1) {
  SurvivalOptions so;
  so.phase = phase;
  const GroundMotion g = survival_motion(so, beta, omega, kShape.alpha(), kShape.p());
  const double T = 1.0 / g.horizontal.frequency, Omega = 2 * M_PI * g.horizontal.frequency;
  HousnerCase c{ForcedTrace(section_time(Omega, phase, phi0), T, per), {}, Omega, T, phase, g};
  RigidProbeObserver<HousnerBlock> obs(c.trace);
  RigidRunOptions ro;
  ro.t_end = periods * T;
  ro.record_events = false;
  ro.integrator.rtol = 1e-12;  // the orbit then repeats to about 1e-11
  ro.integrator.atol = 1e-14;
  c.result = simulate_housner(kShape, std::nullopt, g, {}, ro, &obs);
  return c;
}

}  // namespace

TEST(HousnerCycles, SymmetricOneOneOrbitIsFoundAndRepeatsToRoundoff) {
  // beta = 2, omega = 5: the block settles on a symmetric (1,1) orbit. Independently of the
  // detector: its last impacts come every T/2 with opposite velocities of equal magnitude.
  const HousnerCase c = housner_case(2.0, 5.0, 400);
  ASSERT_EQ(c.result.status, SimStatus::TEnd);
  const auto imp = impacts_of(c.trace, 0, ImpactRule::VelocityJump);
  ASSERT_GT(imp.size(), 100u);
  EXPECT_EQ(long(imp.size()), c.result.impacts);
  for (std::size_t i = imp.size() - 20; i + 1 < imp.size(); ++i) {
    EXPECT_NEAR(imp[i + 1].t - imp[i].t, 0.5 * c.T, 1e-9 * c.T);
    EXPECT_NEAR(imp[i + 1].omega_before, -imp[i].omega_before, 1e-9 * std::fabs(imp[i].omega_before));
  }
  // The strobe samples repeat.
  const std::size_t K = c.trace.strobes();
  for (std::size_t k = K - 20; k < K; ++k) {
    EXPECT_NEAR(c.trace.strobe(k, 0)[2], c.trace.strobe(k - 1, 0)[2], 1e-9 * c.result.max_abs_rotation);
    EXPECT_NEAR(c.trace.strobe(k, 0)[5], c.trace.strobe(k - 1, 0)[5], 1e-9);
  }
  const CycleReport r = cycles_of(c.trace, 0, ImpactRule::VelocityJump, CycleOptions{});
  ASSERT_FALSE(r.segments.empty());
  const CycleSegment& last = r.segments.back();
  EXPECT_EQ(last.label(), "(1,1)");
  EXPECT_GT(last.t_end - last.t_start, 300 * c.T);
  EXPECT_EQ(r.dominant, "(1,1)");
  // Past the transient, at a tolerance of 1e-6 of the amplitude: one (1,1) segment.
  CycleOptions strict;
  strict.transient = 300;
  strict.tolerance = 1e-6;
  const CycleReport rs = cycles_of(c.trace, 0, ImpactRule::VelocityJump, strict);
  ASSERT_EQ(rs.segments.size(), 1u);
  EXPECT_EQ(rs.segments[0].label(), "(1,1)");
  EXPECT_LT(rs.segments[0].return_distance, 1e-9);
  EXPECT_EQ(rs.segments[0].impacts, 2 * (long(c.trace.strobes()) - 1 - 300));
  EXPECT_EQ(dominant_cycle(c.trace, 0, ImpactRule::VelocityJump, CycleOptions{}), "(1,1)");
}

TEST(HousnerCycles, SubharmonicOneThreeOrbitIsFound) {
  // beta = 3, omega = 8: 2 impacts per 3 forcing periods; independently, the impact times repeat
  // after 3 T and the two impacts of an orbit have opposite velocities.
  const HousnerCase c = housner_case(3.0, 8.0, 1500);
  ASSERT_EQ(c.result.status, SimStatus::TEnd);
  const auto imp = impacts_of(c.trace, 0, ImpactRule::VelocityJump);
  for (std::size_t i = imp.size() - 20; i + 2 < imp.size(); ++i) {
    EXPECT_NEAR(imp[i + 2].t - imp[i].t, 3 * c.T, 1e-9 * c.T);
    EXPECT_NEAR(imp[i + 1].omega_before, -imp[i].omega_before, 1e-9);
  }
  const CycleReport r = cycles_of(c.trace, 0, ImpactRule::VelocityJump, CycleOptions{});
  EXPECT_EQ(r.segments.back().label(), "(1,3)");
  EXPECT_EQ(r.segments.back().n, 3);
  CycleOptions strict;
  strict.transient = 1200;
  strict.tolerance = 1e-6;
  const CycleReport rs = cycles_of(c.trace, 0, ImpactRule::VelocityJump, strict);
  ASSERT_EQ(rs.segments.size(), 1u);
  EXPECT_EQ(rs.segments[0].label(), "(1,3)");
}

TEST(ImpactMap, PhasesAreTheGroundMotionsAndInZeroTwoPi) {
  for (double phase : {0.0, 1.0, -2.5}) {
    const HousnerCase c = housner_case(2.0, 5.0, 400, phase, 0.7, 4);
    const auto imp = impacts_of(c.trace, 0, ImpactRule::VelocityJump);
    const auto map = impact_map(imp, c.Omega, phase);
    ASSERT_EQ(map.size(), imp.size());
    const double A = c.g.horizontal.amplitude;
    for (const ImpactMapPoint& p : map) {
      EXPECT_GE(p.phase, 0.0);
      EXPECT_LT(p.phase, 2 * M_PI);
      // a_H = A cos(Phi): the phase is the ground motion's own.
      EXPECT_NEAR(c.g.ah(p.t), A * std::cos(p.phase), 1e-9 * A);
      EXPECT_NEAR(std::sin(p.phase), std::sin(c.Omega * p.t + phase), 1e-9);
    }
    // The (1,1) orbit: two phases, pi apart, repeating.
    const std::size_t n = map.size();
    EXPECT_NEAR(std::remainder(map[n - 1].phase - map[n - 3].phase, 2 * M_PI), 0.0, 1e-9);
    EXPECT_NEAR(std::fabs(std::remainder(map[n - 1].phase - map[n - 2].phase, 2 * M_PI)), M_PI, 1e-9);
    // The Poincare section is taken at the forcing phase 0.7 and converges to a point.
    for (std::size_t k = 0; k < c.trace.strobes(); ++k)
      EXPECT_NEAR(std::remainder(c.Omega * c.trace.strobe_t(k) + phase - 0.7, 2 * M_PI), 0.0, 1e-9);
    const std::size_t K = c.trace.strobes();
    EXPECT_NEAR(c.trace.strobe(K - 1, 0)[2], c.trace.strobe(K - 2, 0)[2], 1e-10);
    // Fine samples: 4 per period, the strobes every 4th.
    EXPECT_EQ(c.trace.samples(), 4 * (K - 1) + 1 + (c.trace.samples() - 1) % 4);
    EXPECT_EQ(c.trace.strobe_t(3), c.trace.sample_t(12));
  }
  EXPECT_EQ(forcing_phase(-1e-17, 1.0, 0.0), 0.0);  // never 2 pi
  EXPECT_NEAR(section_time(2.0, 1.0, 0.5), (2 * M_PI - 0.5) / 2.0, 1e-15);
}

TEST(ForcedModels, EveryFamilyFindsTheSameOneOneOrbit) {
  // A 0.12 x 0.48 m block (seed 002's column) at beta = 2, omega = 8: Housner's block, the 3-DOF
  // rigid block (no sliding), the single-block assembly with deformable and with rigid contacts
  // all settle on a (1,1) orbit with 2 impacts per period.
  SurvivalOptions so;
  PresetOptions po;
  const Assembly blk = make_preset("block", po);
  const BlockShape shape{blk.blocks[0].width, blk.blocks[0].height, 1.0, blk.g};
  const GroundMotion g = survival_motion(so, 2.0, 8.0, shape.alpha(), shape.p());
  const double T = 1.0 / g.horizontal.frequency, t_end = 60 * T;
  auto cycle = [&](ForcedTrace& tr, ImpactRule rule) {
    // Two impacts in each of the last 20 periods, whatever the family's impact rule.
    long late = 0;
    for (const Impact& i : impacts_of(tr, 0, rule)) late += i.t >= t_end - 20 * T;
    EXPECT_EQ(late, 40);
    const CycleReport r = cycles_of(tr, 0, rule, CycleOptions{});
    EXPECT_FALSE(r.segments.empty());
    return r.segments.empty() ? std::string() : r.segments.back().label();
  };
  RigidRunOptions ro;
  ro.t_end = t_end;
  ro.record_events = false;
  {
    ForcedTrace tr(0.0, T, 1);
    RigidProbeObserver<HousnerBlock> obs(tr);
    simulate_housner(shape, std::nullopt, g, {}, ro, &obs);
    EXPECT_EQ(cycle(tr, ImpactRule::VelocityJump), "(1,1)");
  }
  {
    RigidBlockParams rp;
    rp.shape = shape;
    rp.interface = {2.0, 2.0};
    ForcedTrace tr(0.0, T, 1);
    RigidProbeObserver<RigidBlock> obs(tr);
    simulate_rigid(rp, g, {}, ro, &obs);
    EXPECT_EQ(cycle(tr, ImpactRule::VelocityJump), "(1,1)");
  }
  for (bool rigid : {false, true}) {
    PresetOptions p2;
    p2.contact = rigid ? blockdyn::ContactKind::Rigid : blockdyn::ContactKind::Deformable;
    if (rigid) p2.ground_law.restitution = p2.block_law.restitution = 0.8;
    const Assembly a = make_preset("block", p2);
    AssemblyRunOptions ao;
    ao.t_end = t_end;
    ao.record_events = false;
    ForcedTrace tr(0.0, T, 1);
    const AssemblyResult r = simulate_assembly(a, g, ao, nullptr, &tr);
    EXPECT_EQ(r.status, SimStatus::TEnd);
    EXPECT_EQ(cycle(tr, ImpactRule::Passage), "(1,1)") << (rigid ? "rigid" : "deformable");
    // Impacts every half period at the end, with opposite velocities before them.
    const auto imp = impacts_of(tr, 0, ImpactRule::Passage);
    ASSERT_GT(imp.size(), 60u);
    const std::size_t n = imp.size();
    EXPECT_NEAR(imp[n - 1].t - imp[n - 2].t, 0.5 * T, 0.02 * T);
    EXPECT_LT(imp[n - 1].omega_before * imp[n - 2].omega_before, 0.0);
    // theta' keeps its sign across the impact (the pivot changes, the rotation goes on).
    EXPECT_GT(imp[n - 1].omega_after * imp[n - 1].omega_before, 0.0);
    if (rigid) {  // the impulse of the hitting corner (restitution 0.8) slows the rotation
      EXPECT_LT(std::fabs(imp[n - 1].omega_after), 0.95 * std::fabs(imp[n - 1].omega_before));
    }
  }
}

TEST(ForcedModels, AnAssemblyBelowUpliftHasPassagesButNoImpacts) {
  // The trilith tilts elastically back and forth under a weak motion: its columns' rotations
  // pass through 0 every half period, but no column lifts, so none of it is an impact.
  PresetOptions po;
  const Assembly a = make_preset("trilith", po);
  SurvivalOptions so;
  const double alpha = std::atan2(a.blocks[0].width, a.blocks[0].height);
  const double p = std::sqrt(0.75 * a.g / (0.5 * std::hypot(a.blocks[0].width, a.blocks[0].height)));
  const GroundMotion g = survival_motion(so, 0.2, 6.0, alpha, p);
  const double T = 1.0 / g.horizontal.frequency;
  AssemblyRunOptions ao;
  ao.t_end = 30 * T;
  ForcedTrace tr(0.0, T, 1);
  simulate_assembly(a, g, ao, nullptr, &tr);
  long passages = 0;
  for (const ProbeEvent& e : tr.events()) passages += e.block == 0 && e.kind == ProbeEvent::Passage;
  EXPECT_GT(passages, 20);
  EXPECT_TRUE(impacts_of(tr, 0, ImpactRule::Passage).empty());
  EXPECT_EQ(cycles_of(tr, 0, ImpactRule::Passage, CycleOptions{}).dominant, "no-impacts");
}

TEST(ForcedModels, WithRigidContactsEveryPassageIsAnImpact) {
  // Rigid contacts do not deform: a block's rotation changes only once it has lifted, so every
  // passage of a column through 0 ends a swing and is an impact (the law reports a step's
  // contact changes at the step's end, after the crossing it interpolates inside the step).
  PresetOptions po;
  po.contact = blockdyn::ContactKind::Rigid;
  po.ground_law.restitution = po.block_law.restitution = 0.0;
  const Assembly a = make_preset("trilith", po);
  SurvivalOptions so;
  const double alpha = std::atan2(a.blocks[0].width, a.blocks[0].height);
  const double p = std::sqrt(0.75 * a.g / (0.5 * std::hypot(a.blocks[0].width, a.blocks[0].height)));
  const GroundMotion g = survival_motion(so, 4.0, 10.0, alpha, p);
  AssemblyRunOptions ao;
  ao.t_end = 10;
  ao.record_events = false;
  ForcedTrace tr(0.0, 1.0 / g.horizontal.frequency, 1);
  simulate_assembly(a, g, ao, nullptr, &tr);
  for (int b : {0, 1}) {
    long passages = 0;
    for (const ProbeEvent& e : tr.events()) passages += e.block == b && e.kind == ProbeEvent::Passage;
    EXPECT_GT(passages, 40);
    EXPECT_EQ(long(impacts_of(tr, b, ImpactRule::Passage).size()), passages) << b;
  }
}
