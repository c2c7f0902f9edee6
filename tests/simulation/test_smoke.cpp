// SPDX-License-Identifier: Apache-2.0
#include <gtest/gtest.h>

#include "blockdyn/model/winkler/initial_conditions.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

using namespace blockdyn;

TEST(Smoke, Ic1RunsToEnd) {
  const WinklerParams p{0.2, 0.2, 1e5};
  WinklerRunOptions o;
  o.t_end = 5;
  const auto r = simulate(p, {}, ic1(p), o);
  EXPECT_EQ(r.status, SimStatus::TEnd);
  EXPECT_GT(r.upright_passages, 0);
}
