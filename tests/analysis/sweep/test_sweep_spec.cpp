// SPDX-License-Identifier: Apache-2.0
// Sweep definitions: axes, point order, TOML parsing and validation.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"
#include "blockdyn/analysis/sweep/sweep_toml.hpp"

#include "test_support.hpp"

using namespace blockdyn;
using blockdyn::test::error_of;

namespace {}  // namespace

TEST(SweepAxis, LogRangeHasExactDecadesAndEndpoints) {
  const SweepAxis a = parse_axis("k", "1e2:1e8:7", AxisSpacing::Log);
  ASSERT_EQ(a.values.size(), 7u);
  for (int i = 0; i < 7; ++i) EXPECT_EQ(a.values[i], std::pow(10.0, 2 + i)) << i;
  const SweepAxis b = axis_range("k", 1e2, 1e8, 40, AxisSpacing::Log);
  EXPECT_EQ(b.values.front(), 1e2);
  EXPECT_EQ(b.values.back(), 1e8);
  for (std::size_t i = 1; i < b.values.size(); ++i)
    EXPECT_NEAR(std::log10(b.values[i] / b.values[i - 1]), 6.0 / 39.0, 1e-13);
}

TEST(SweepAxis, LinearRangeListsAndSuffix) {
  const SweepAxis a = parse_axis("inv_r", "1:20:20", AxisSpacing::Linear);
  ASSERT_EQ(a.values.size(), 20u);
  for (int i = 0; i < 20; ++i) EXPECT_DOUBLE_EQ(a.values[i], 1.0 + i);
  EXPECT_EQ(parse_axis("mu", "0.1, 0.2,0.3", AxisSpacing::Linear).values, (std::vector<double>{0.1, 0.2, 0.3}));
  EXPECT_EQ(parse_axis("k", "1:100:3:lin", AxisSpacing::Log).values, (std::vector<double>{1, 50.5, 100}));
  EXPECT_EQ(parse_axis("r", "1:100:3:log", AxisSpacing::Linear).values[1], 10.0);
}

TEST(SweepAxis, BadTextNamesTheAxis) {
  EXPECT_NE(error_of([] { parse_axis("k", "1e2:1e8", AxisSpacing::Log); }).find("axes.k"), std::string::npos);
  EXPECT_NE(error_of([] { parse_axis("k", "0:1e8:5", AxisSpacing::Log); }).find("log spacing needs min > 0"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_axis("mu", "0.1,,0.2", AxisSpacing::Linear); }).find("axes.mu"), std::string::npos);
  EXPECT_NE(error_of([] { parse_axis("r", "1:2:2.5", AxisSpacing::Linear); }).find("integer"), std::string::npos);
  EXPECT_NE(error_of([] { parse_axis("r", "2:1:3", AxisSpacing::Linear); }).find("min must be <= max"),
            std::string::npos);
}

TEST(SweepSpec, PointOrderIsKFastestThenRMuIc) {
  SweepSpec s;
  s.k = axis_list("k", {1e3, 1e4, 1e5});
  s.r = axis_list("inv_r", {2, 4});
  s.mu = axis_list("mu", {0.1, 0.3});
  s.initial.sets = {"ic1", "ic2"};
  ASSERT_EQ(point_count(s), 24u);
  std::size_t index = 0;
  for (std::size_t ic = 0; ic < 2; ++ic)
    for (std::size_t m = 0; m < 2; ++m)
      for (std::size_t r = 0; r < 2; ++r)
        for (std::size_t k = 0; k < 3; ++k, ++index) {
          const SweepPoint p = sweep_point(s, index);
          EXPECT_EQ(p.params.k, s.k.values[k]);
          EXPECT_EQ(p.inv_r, s.r.values[r]);  // exact on an inv_r axis
          EXPECT_EQ(p.params.r, 1.0 / s.r.values[r]);
          EXPECT_EQ(p.params.mu, s.mu.values[m]);
          EXPECT_EQ(p.ic, s.initial.sets[ic]);
        }
}

TEST(SweepSpec, TomlFullDefinition) {
  const SweepSpec s = parse_sweep(R"(
[axes]
k = { min = 1e2, max = 1e8, points = 40 }
inv_r = "1:20:30"
mu = [0.1, 0.2]
[initial]
set = ["ic1", "ic2"]
w0_over_alpha = 0.25
vx0 = 0.05
[run]
t_end = 12.5
rtol = 1e-9
stop_at_ihor = 3
stop_at_first_flight = true
[output]
csv = "map.csv"
metrics = ["event_counts"]
)",
                                  "test.toml");
  EXPECT_EQ(s.k.values.size(), 40u);
  EXPECT_EQ(s.k.spacing, AxisSpacing::Log);  // the default for k
  EXPECT_EQ(s.r.name, "inv_r");
  EXPECT_EQ(s.r.values.size(), 30u);
  EXPECT_EQ(s.r.spacing, AxisSpacing::Linear);
  EXPECT_EQ(s.mu.values, (std::vector<double>{0.1, 0.2}));
  EXPECT_EQ(s.initial.sets, (std::vector<std::string>{"ic1", "ic2"}));
  EXPECT_EQ(*s.initial.w0_over_alpha, 0.25);
  EXPECT_EQ(*s.initial.vx0, 0.05);
  EXPECT_EQ(s.options.t_end, 12.5);
  EXPECT_EQ(s.options.integrator.rtol, 1e-9);
  EXPECT_EQ(s.options.stop_at_upright_passages, 3);
  EXPECT_TRUE(s.options.stop_at_first_flight);
  EXPECT_EQ(s.output, "map.csv");
  EXPECT_EQ(point_count(s), 40u * 30u * 2u * 2u);
  EXPECT_NO_THROW(validate(s));
}

TEST(SweepSpec, TomlErrorsNameTheKey) {
  auto err = [](const std::string& text) { return error_of([&] { validate(parse_sweep(text, "t.toml")); }); };
  EXPECT_NE(err("[axes]\nkk = 3\n").find("axes.kk: unknown key"), std::string::npos);
  EXPECT_NE(err("[axis]\nk = 3\n").find("axis: unknown key"), std::string::npos);
  EXPECT_NE(err("[axes]\nr = 1\ninv_r = 2\n").find("either r or inv_r"), std::string::npos);
  EXPECT_NE(err("[axes]\nk = { min = 1, max = 10 }\n").find("axes.k.points"), std::string::npos);
  EXPECT_NE(err("[axes]\nk = { min = 1, max = 10, points = 4.5 }\n").find("axes.k.points: must be an integer"),
            std::string::npos);
  EXPECT_NE(err("[axes]\nk = [1e3, -5]\n").find("axes.k: value -5 is out of range"), std::string::npos);
  EXPECT_NE(err("[axes]\nmu = -0.1\n").find("axes.mu"), std::string::npos);
  EXPECT_NE(err("[run]\nstop_at_ihor = 'two'\n").find("run.stop_at_ihor: must be an integer"), std::string::npos);
  EXPECT_NE(err("[run]\nt_end = -1\n").find("t-end"), std::string::npos);
  EXPECT_NE(err("[initial]\nset = 'ic3'\n").find("initial.set = 'ic3'"), std::string::npos);
  EXPECT_NE(err("[initial]\nw0 = 0.1\nw0_over_alpha = 0.5\n").find("either w0 or w0_over_alpha"), std::string::npos);
  EXPECT_NE(err("[output]\nmetrics = 'event_counts'\n").find("output.metrics"), std::string::npos);
  EXPECT_NE(err("[axes\n").find("t.toml:1"), std::string::npos);
}

TEST(SweepSpec, PerPointInitialStateErrorsNameThePoint) {
  // w0 = 0.3 exceeds alpha = atan(0.25) = 0.245 at the second r value only.
  const std::string e =
      error_of([] { validate(parse_sweep("[axes]\nr = [0.5, 0.25]\n[initial]\nset = 'ic1'\nw0 = 0.3\n", "t.toml")); });
  EXPECT_NE(e.find("point 1 (k=100000, r=0.25"), std::string::npos) << e;
  EXPECT_NE(e.find("w0"), std::string::npos) << e;
  // The fraction form scales with alpha and is valid everywhere.
  EXPECT_NO_THROW(validate(parse_sweep("[axes]\nr = [0.5, 0.25]\n[initial]\nw0_over_alpha = 0.25\n", "t.toml")));
}

TEST(SweepSpec, FingerprintFollowsDefinitionNotOutput) {
  SweepSpec a;
  a.k = axis_list("k", {1e3, 1e4});
  SweepSpec b = a;
  b.output = "elsewhere.csv";
  b.plot = "p.png";
  EXPECT_EQ(SweepEvaluator(a).fingerprint(), SweepEvaluator(b).fingerprint());
  SweepSpec c = a;
  c.options.t_end = 29;
  EXPECT_NE(SweepEvaluator(a).fingerprint(), SweepEvaluator(c).fingerprint());
  SweepSpec d = a;
  d.metrics = {"event_counts"};
  EXPECT_NE(SweepEvaluator(a).fingerprint(), SweepEvaluator(d).fingerprint());
}

TEST(SweepSpec, Ic1OverrideByFractionOfAlpha) {
  SweepSpec s;
  s.r = axis_list("r", {0.5});
  s.initial.w0_over_alpha = 0.25;
  const SweepPoint p = sweep_point(s, 0);
  EXPECT_DOUBLE_EQ(sweep_initial_state(s, p)[kW], 0.25 * std::atan(0.5));
  s.initial.sets = {"ic2"};
  s.initial.w0_over_alpha.reset();
  s.initial.vx0 = 0.03;
  const WinklerState z = sweep_initial_state(s, sweep_point(s, 0));
  EXPECT_EQ(z[kVX], 0.03);
  EXPECT_EQ(z[kW], 0.0);
}
