// SPDX-License-Identifier: Apache-2.0
// The event-driven rigid contact law for assemblies (issue 25, item 2) against independent
// references: Housner's free rocking (impact times by quadrature of the exact equation, the
// restitution 1 - 1.5 sin^2 alpha as the impact's energy loss), the rigid four-bar frame (a
// Housner block with p_f^2 = p^2 (1 + 2 gamma) / (1 + 3 gamma) and
// e_f = (1 - 1.5 sin^2 alpha + 3 gamma cos 2 alpha) / (1 + 3 gamma), gamma = m_lintel / (2 m_column),
// from the frame's Lagrangian and angular momentum about the new pivots), the static limits
// (tan alpha of the whole column or frame whatever the lintel; mu where sliding governs), rest
// below the limit and the energy balance.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "blockdyn/model/assembly/assembly_params.hpp"
#include "blockdyn/model/assembly/rigid_assembly_model.hpp"
#include "blockdyn/simulation/assembly_simulation.hpp"
#include "housner_reference.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

PresetOptions rigid_preset() {
  PresetOptions o;  // seed 002: b = 0.12 m, depth 0.06 m, 2700 kg/m^3, lambda = 4
  o.contact = blockdyn::ContactKind::Rigid;
  o.ground_law.restitution = o.block_law.restitution = 0.0;
  return o;
}

AssemblyRunOptions event_driven(double t_end) {
  AssemblyRunOptions o;
  o.t_end = t_end;
  o.scheme = AssemblyScheme::EventDriven;
  return o;
}

std::vector<double> impact_times(const AssemblyResult& r) {
  std::vector<double> t;
  for (const auto& e : r.events)
    if (e.kind == blockdyn::kAssemblyImpact) t.push_back(e.t);
  return t;
}

GroundMotion harmonic(double amplitude_g, double hz) {
  GroundMotion g;
  g.horizontal.amplitude = amplitude_g;
  g.horizontal.frequency = hz;
  return g;
}

}  // namespace

TEST(RigidEventDriven, BlockRocksWithHousnersImpactsAndRestitution) {
  const double theta0 = 0.1;
  PresetOptions o = rigid_preset();
  o.tilt = theta0;
  const Assembly a = make_preset("block", o);
  const double b = a.blocks[0].width, h = a.blocks[0].height, R = 0.5 * std::hypot(b, h);
  const double alpha = std::atan2(b, h), p = std::sqrt(3 * 9.81 / (4 * R));
  const double e = 1 - 1.5 * std::pow(std::sin(alpha), 2);
  const auto ref = housner_free_impacts(alpha, p, theta0, e, 5);
  const AssemblyResult r = simulate_assembly(a, {}, event_driven(ref.back().t + 0.05));
  const auto t = impact_times(r);
  ASSERT_GE(t.size(), ref.size());
  for (std::size_t k = 0; k < ref.size(); ++k) EXPECT_NEAR(t[k] / ref[k].t, 1.0, 1e-8) << k;
  // Each impact keeps e of the angular velocity about the corners: the losses are
  // (1 - e^2) of the kinetic energy before each impact.
  const double I_corner = a.blocks[0].inertia() + a.blocks[0].mass * R * R;
  double loss = 0;
  for (const auto& k : ref) loss += 0.5 * I_corner * k.w_before * k.w_before * (1 - e * e);
  EXPECT_NEAR(-r.work_normal / loss, 1.0, 1e-7);
  EXPECT_EQ(r.status, SimStatus::TEnd);
  EXPECT_LT(r.max_abs_energy_error, 1e-7 * loss);
}

TEST(RigidEventDriven, TrilithRocksAsTheFourBarFrameSolution) {
  // Released from alpha / 2: the first three returns to upright within 1e-6 (relative) of the
  // equivalent Housner block (issue 25's target), lintel level and columns in phase.
  PresetOptions o = rigid_preset();
  const double alpha = std::atan2(o.block_width, o.block_width * o.slenderness);
  o.tilt = 0.5 * alpha;
  for (double lintel : {-1.0, 0.36, 0.6}) {
    o.lintel_length = lintel;
    const Assembly a = make_preset("trilith", o);
    const double b = a.blocks[0].width, h = a.blocks[0].height, R = 0.5 * std::hypot(b, h);
    const double gamma = a.blocks[2].mass / (2 * a.blocks[0].mass);
    const double p = std::sqrt(3 * 9.81 / (4 * R));
    const double pf = p * std::sqrt((1 + 2 * gamma) / (1 + 3 * gamma));
    const double s = std::sin(alpha);
    const double ef = (1 - 1.5 * s * s + 3 * gamma * std::cos(2 * alpha)) / (1 + 3 * gamma);
    const auto ref = housner_free_impacts(alpha, pf, o.tilt, ef, 3);
    const AssemblyResult r = simulate_assembly(a, {}, event_driven(ref.back().t + 0.01));
    const auto t = impact_times(r);
    ASSERT_GE(t.size(), 3u) << lintel;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(t[k] / ref[k].t, 1.0, 1e-6) << lintel << ' ' << k;
    EXPECT_LT(std::fabs(r.blocks[2].max_abs_rotation), 1e-9) << lintel;
    EXPECT_NEAR(r.blocks[0].max_abs_rotation, r.blocks[1].max_abs_rotation, 1e-9) << lintel;
  }
}

TEST(RigidEventDriven, StaticLimitsAreTanAlphaWhateverTheLintelOrMuWhereSlidingGoverns) {
  struct Case {
    const char* preset;
    double mu, lintel, expected;
  };
  const double tan_alpha = 0.25;  // the whole column's or frame's b / h (slenderness 4)
  for (const Case c :
       {Case{"block", 1e12, -1, tan_alpha}, Case{"column", 1e12, -1, tan_alpha}, Case{"trilith", 1e12, -1, tan_alpha},
        Case{"trilith", 1e12, 0.6, tan_alpha}, Case{"block", 0.1, -1, 0.1}, Case{"column", 0.15, -1, 0.15}}) {
    PresetOptions o = rigid_preset();
    o.ground_law.mu_s = o.ground_law.mu_k = o.block_law.mu_s = o.block_law.mu_k = c.mu;
    o.lintel_length = c.lintel;
    const Assembly a = make_preset(c.preset, o);
    const RigidAssemblyModel<8> m(a, {});
    const auto lim = m.rest_limits(m.initial_state());
    ASSERT_TRUE(lim.has_value()) << c.preset;
    EXPECT_NEAR(lim->pos, c.expected, 1e-12) << c.preset << ' ' << c.mu;
    EXPECT_NEAR(lim->neg, c.expected, 1e-12) << c.preset << ' ' << c.mu;
  }
}

TEST(RigidEventDriven, RestIsExactlyRestBelowTheLimit) {
  for (const char* preset : {"block", "trilith", "column"}) {
    const Assembly a = make_preset(preset, rigid_preset());
    const AssemblyResult r = simulate_assembly(a, harmonic(0.999 * 0.25, 1.7359), event_driven(20));
    EXPECT_EQ(r.motion, "rest") << preset;
    EXPECT_EQ(r.events_total, 0) << preset;
    for (std::size_t b = 0; b < a.blocks.size(); ++b) {
      EXPECT_EQ(r.blocks[b].final_state[0], a.blocks[b].x) << preset;
      EXPECT_EQ(r.blocks[b].final_state[1], a.blocks[b].y) << preset;
      EXPECT_EQ(r.blocks[b].max_abs_rotation, 0.0) << preset;
    }
  }
}

TEST(RigidEventDriven, ForcedTrilithKeepsItsEnergyBalanceAndSettlesWhereTheForcingEnds) {
  // Issue 25's failing case (beta 1.04, omega 2): rocks, never fails a step; then a pulse
  // that ends: the frame's impacts accumulate and it comes to rest (exactly) on its bases.
  const Assembly a = make_preset("trilith", rigid_preset());
  const AssemblyResult r = simulate_assembly(a, harmonic(0.2548, 1.7359), event_driven(5));
  EXPECT_EQ(r.status, SimStatus::TEnd) << r.note;
  EXPECT_EQ(r.motion, "stable");
  const double scale = a.blocks[2].mass * 9.81 * a.blocks[0].height;
  EXPECT_LT(r.max_abs_energy_error, 1e-8 * scale);
  GroundMotion pulse;
  pulse.horizontal.pulse = PulseShape::HalfSine;
  pulse.horizontal.amplitude = 0.4;
  pulse.horizontal.duration = 0.3;
  const AssemblyResult s = simulate_assembly(a, pulse, event_driven(6));
  EXPECT_EQ(s.status, SimStatus::TEnd) << s.note;
  EXPECT_GT(s.impacts, 2);
  for (int b = 0; b < 3; ++b) {
    EXPECT_EQ(s.blocks[b].final_state[5], 0.0) << b;  // rest is exactly rest
    EXPECT_GT(s.blocks[b].max_abs_rotation + (b == 2 ? 1 : 0), 1e-3) << b;
  }
  EXPECT_LT(s.max_abs_energy_error, 1e-8 * scale);
}

TEST(RigidEventDriven, ChatteringContactsAreHandedToTimeSteppingAndBack) {
  // A trilith with friction (20 deg) at beta 3, omega 4: the lintel's contacts chatter at times;
  // those windows run on Moreau-Jean through the same observers (energy balance, events), are
  // reported, and the events take over again.
  PresetOptions o = rigid_preset();
  o.ground_law.mu_s = o.ground_law.mu_k = o.block_law.mu_s = o.block_law.mu_k = std::tan(20 * M_PI / 180);
  const Assembly a = make_preset("trilith", o);
  const double alpha = std::atan(0.25), p = 5.4535;
  GroundMotion g = harmonic(3 * alpha, 4 * p / (2 * M_PI));
  g.horizontal.phase = 0.5 * M_PI;
  AssemblyRunOptions run = event_driven(20);
  const AssemblyResult r = simulate_assembly(a, g, run);
  EXPECT_NE(r.status, SimStatus::Invalid) << r.note;
  ASSERT_GT(r.time_stepping_windows, 0);
  EXPECT_FALSE(r.time_stepping_reason.empty());
  EXPECT_NE(r.note.find("Moreau-Jean"), std::string::npos);
  EXPECT_EQ(r.event_counts[kAssemblyToTimeStepping], r.time_stepping_windows);
  EXPECT_GE(r.event_counts[kAssemblyToEventDriven], r.time_stepping_windows - 1);
  EXPECT_GT(r.time_stepping_steps, 0);
  EXPECT_NEAR(r.time_stepping_time, r.time_stepping_steps * run.step, 1e-9);
  const double scale = a.blocks[2].mass * 9.81 * a.blocks[0].height;
  EXPECT_LT(r.max_abs_energy_error, 1e-6 * scale);
}
