// SPDX-License-Identifier: Apache-2.0
// Sensitive dependence on initial conditions (thesis sec. 5.2, Table 5.1; issue 2, item 7):
// mu = 0, k = 1e5, r = 0.3, ic1 against ic1 with y'(0) = 1e-10. Both runs take off at the same
// time, separate to visibly different states by t = 20, and conserve energy throughout.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "blockdyn/analysis/winkler/twin_divergence.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

// Records the state at a given time from the dense output.
struct SampleAt : WinklerSink {
  double t_sample;
  WinklerState z{};
  bool have = false;
  explicit SampleAt(double t) : t_sample(t) {}
  void on_segment(const WinklerBlock& m, const DenseSegment<kStateDim>& seg, double t0, double t1,
                  const WinklerMode& mode) override {
    if (have || t_sample < t0 || t_sample > t1) return;
    z = completed_state(m, seg, mode, t_sample);
    have = true;
  }
};

double distance(const WinklerState& a, const WinklerState& b) {
  double d = 0;
  for (std::size_t i = 0; i < 6; ++i) d = std::fmax(d, std::fabs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST(Sensitivity, Table51TwoNearbyStartsSeparate) {
  const WinklerParams p{0.3, 0.0, 1e5};
  const WinklerState z1 = ic1(p);
  WinklerState z2 = z1;
  z2[kVY] = 1e-10;
  const WinklerRunOptions o = sim_options(20.0);
  SampleAt s1(1.0), s2(1.0);
  const WinklerResult a = simulate(p, {}, z1, o, &s1);
  const WinklerResult b = simulate(p, {}, z2, o, &s2);
  ASSERT_EQ(a.status, SimStatus::TEnd);
  ASSERT_EQ(b.status, SimStatus::TEnd);

  for (int i = 0; i < 2; ++i) {
    const WinklerResult& s = i == 0 ? a : b;
    const std::string run = i == 0 ? "ic1_" : "ic1_vy1e-10_";
    record((run + "first_flight").c_str(), s.first_flight_time.value_or(NAN));
    record((run + "w20").c_str(), s.final_state[kW]);
    record((run + "y20").c_str(), s.final_state[kH] + 0.5);
    record((run + "ihor20").c_str(), double(s.upright_passages));
    record((run + "max_energy_error").c_str(), s.max_abs_energy_error);
    record((run + "max_energy_change").c_str(), s.max_abs_energy_change);
    record((run + "E0").c_str(), s.initial_energy.total());
  }
  // Same first flight (the perturbation shifts it by ~1e-10).
  ASSERT_TRUE(a.first_flight_time && b.first_flight_time);
  EXPECT_NEAR(*a.first_flight_time, *b.first_flight_time, 1e-9);
  EXPECT_EQ(a.upright_passages_at_first_flight, b.upright_passages_at_first_flight);

  // Still together after the first second...
  ASSERT_TRUE(s1.have && s2.have);
  EXPECT_LT(distance(s1.z, s2.z), 1e-6);
  // ...visibly different at t = 20: tilt and height differ at the scale of the motion itself.
  const double dw = std::fabs(a.final_state[kW] - b.final_state[kW]);
  const double dy = std::fabs(a.final_state[kH] - b.final_state[kH]);
  EXPECT_TRUE(dw > 1e-2 * p.alpha() || dy > 1e-3) << "dw = " << dw << ", dy = " << dy;
  EXPECT_GT(distance(a.final_state, b.final_state), 1e4 * distance(s1.z, s2.z));

  // Energy: the same E0 to 1e-20 (the kick adds 5e-21), and each run's balance closes.
  EXPECT_NEAR(a.initial_energy.total(), b.initial_energy.total(), 1e-19);
  EXPECT_LT(a.max_abs_energy_error, 1e-9);
  EXPECT_LT(b.max_abs_energy_error, 1e-9);
  // Without friction the raw change is only the wall term of the two-corner Region.
  EXPECT_EQ(a.work_friction(), 0.0);
  EXPECT_LT(a.max_abs_energy_change, 1e-6 * a.initial_energy.total());
  EXPECT_LT(b.max_abs_energy_change, 1e-6 * b.initial_energy.total());
  // Many passages through w = 0 in 20 time units (the thesis reports 25 and 33).
  EXPECT_GT(a.upright_passages, 15);
  EXPECT_GT(b.upright_passages, 15);
}

// The opt-in map class (twin_divergence.hpp): a 1e-8 kick to y'(0) takes the Table 5.1 block
// apart within t = 20 but leaves steady rocking and a settled block together.
TEST(TwinDivergence, ChaoticPointDivergesRegularOnesDoNot) {
  const WinklerParams chaotic{0.3, 0.0, 1e5};
  const TwinDivergence a = twin_divergence(chaotic, {}, ic1(chaotic), sim_options(20.0));
  EXPECT_TRUE(a.divergent);
  EXPECT_FALSE(a.outcome_differs);
  EXPECT_GT(a.separation, 0.1);
  EXPECT_EQ(a.compared, std::size_t(TwinOptions{}.samples));

  const WinklerParams rock{0.5, 0.0, 100};  // Fig. 4.41, steady rocking
  const TwinDivergence b = twin_divergence(rock, {}, ic1(rock), sim_options(30.0));
  EXPECT_FALSE(b.divergent);
  EXPECT_LT(b.separation, 1e-4) << "a 1e-8 kick must stay small without sensitive dependence";

  const WinklerParams rest{1.0, 0.2, 1e6};  // flies, then settles (docs/response.md)
  const TwinDivergence c = twin_divergence(rest, {}, ic2(rest), sim_options(30.0));
  EXPECT_FALSE(c.divergent) << c.separation;

  // The threshold decides: asking for less than the measured separation flags the point.
  TwinOptions o;
  o.threshold = 0.5 * b.separation;
  EXPECT_TRUE(twin_divergence(rock, {}, ic1(rock), sim_options(30.0), o).divergent);
}

TEST(TwinDivergence, OnlyOneOverturningCountsAsDivergent) {
  // Below k_uns the block falls over whatever the kick: same outcome, nothing compared.
  const WinklerParams p{0.2, 0.2, 1e2};
  const TwinDivergence d = twin_divergence(p, {}, ic1(p), sim_options(20.0));
  EXPECT_FALSE(d.outcome_differs);
  EXPECT_FALSE(d.divergent);
}
