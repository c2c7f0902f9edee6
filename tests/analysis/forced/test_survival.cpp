// SPDX-License-Identifier: Apache-2.0
// Survival domains (issue 9): classes on points whose answer is known independently (below
// uplift: rest everywhere; a rectangular half-period pulse against the exact overturning
// threshold from quadrature), and the same map for 1 and 2 threads.
#include <gtest/gtest.h>

#include <cmath>

#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/simulation/rigid_simulation.hpp"
#include "housner_reference.hpp"

using namespace blockdyn;
using namespace blockdyn::test;

namespace {

const BlockShape kShape{0.3, 1.5, 1.0, 9.81};

SurvivalOutcome housner_run(const GroundMotion& g, double t_end) {
  RigidRunOptions ro;
  ro.t_end = t_end;
  ro.record_events = false;
  const RigidResult r = simulate_housner(kShape, std::nullopt, g, {}, ro);
  SurvivalOutcome o;
  o.moved = r.first_motion_time.has_value();
  o.max_abs_rotation = r.max_abs_rotation;
  if (r.status == SimStatus::Overturned) {
    o.collapse_mode = 1;
    o.t_failure = r.overturn_time;
  }
  return o;
}

}  // namespace

TEST(Survival, BelowUpliftTheBlockRestsEverywhere) {
  // beta alpha g < g tan(alpha): the block never lifts, whatever the frequency.
  const double alpha = kShape.alpha();
  SurvivalOptions o;
  o.beta_min = 0.2;
  o.beta_max = 0.99 * std::tan(alpha) / alpha;
  o.beta_points = 5;
  o.omega_min = 0.5;
  o.omega_max = 30;
  o.omega_points = 7;
  o.periods = 10;
  for (const char* ex : {"harmonic", "half-sine", "rect"}) {
    o.excitation = ex;
    for (const SurvivalPoint& p : survival_map(housner_run, o, alpha, kShape.p())) {
      EXPECT_EQ(p.motion, "rest") << ex << ' ' << p.beta << ' ' << p.omega;
      EXPECT_EQ(p.max_abs_rotation, 0.0);
    }
  }
}

TEST(Survival, RectangularPulseCollapsesExactlyAboveTheQuadratureThreshold) {
  // The pulse lasts pi / Omega: at omega = 2, t_p = pi / (2 p). Betas 0.1% below and above the
  // exact threshold (quadrature of the rocking equation) survive and overturn.
  const double alpha = kShape.alpha(), p = kShape.p();
  const double omega = 2.0, tp = M_PI / (omega * p);
  const double beta_star = housner_rect_pulse_threshold(alpha, p, tp) / alpha;
  SurvivalOptions o;
  o.excitation = "rect";
  o.omega_min = o.omega_max = omega;
  o.omega_points = 1;
  o.beta_min = 0.999 * beta_star;
  o.beta_max = 1.001 * beta_star;
  o.beta_points = 2;
  o.t_end = 10;
  const auto pts = survival_map(housner_run, o, alpha, p);
  EXPECT_EQ(pts[0].motion, "stable");
  EXPECT_EQ(pts[1].motion, "collapse");
  ASSERT_TRUE(pts[1].collapse_mode);
  EXPECT_EQ(*pts[1].collapse_mode, 1);
  EXPECT_EQ(pts[1].t_star_class, "<=5 s");
}

TEST(Survival, TheMapDoesNotDependOnTheThreadCount) {
  SurvivalOptions o;
  o.beta_points = 6;
  o.omega_points = 6;
  o.beta_max = 6;
  o.periods = 15;
  o.threads = 1;
  const auto a = survival_map(housner_run, o, kShape.alpha(), kShape.p());
  o.threads = 2;
  const auto b = survival_map(housner_run, o, kShape.alpha(), kShape.p());
  ASSERT_EQ(a.size(), b.size());
  int collapses = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].motion, b[i].motion);
    EXPECT_EQ(a[i].max_abs_rotation, b[i].max_abs_rotation);  // bit-identical
    EXPECT_EQ(a[i].t_failure, b[i].t_failure);
    collapses += a[i].motion == "collapse";
  }
  EXPECT_GT(collapses, 0);
  EXPECT_LT(collapses, int(a.size()));
}
