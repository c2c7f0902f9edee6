// SPDX-License-Identifier: Apache-2.0
// Poincare section w = 0 and energy surfaces (thesis sec. 5.1-5.2).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "blockdyn/analysis/winkler/energy_surface.hpp"
#include "blockdyn/analysis/winkler/poincare.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/initial_conditions.hpp"

using namespace blockdyn;

namespace {

struct Section {
  std::vector<PoincarePoint> pts;
  WinklerResult res;
};

Section section(const WinklerParams& p, const WinklerState& z0, double t_end,
                CrossingDirection dir = CrossingDirection::Both) {
  PoincareCollector col(p, dir);
  WinklerRunOptions o;
  o.t_end = t_end;
  o.record_events = false;
  Section s;
  s.res = simulate(p, {}, z0, o, &col);
  s.pts = col.points();
  return s;
}

int poincare_cli(const std::string& args) {
  const int rc = std::system((std::string(BLOCKDYN_CLI) + " " + args + " >/dev/null 2>&1").c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

}  // namespace

TEST(PoincareSection, PointsLieOnWZeroToRoundoff) {
  const WinklerParams p{0.5, 0.0, 1e4};  // zero-friction rock-flight: crossings in every regime
  const auto s = section(p, ic1(p), 100);
  ASSERT_GT(s.pts.size(), 100u);
  EXPECT_EQ(long(s.pts.size()), s.res.upright_passages);  // ic1 starts tilted: every passage is a crossing
  constexpr double eps = std::numeric_limits<double>::epsilon();
  bool saw_flight = false;
  for (const auto& q : s.pts) {
    // The crossing time is located to a few ulps (w = w' dt there) and w itself carries the
    // rounding of a number of size alpha. Taken at step ends instead, |w| would be ~1e-3.
    EXPECT_LE(std::fabs(q.w), 32.0 * eps * (p.alpha() + (q.t + 1.0) * std::fabs(q.vw))) << "t = " << q.t;
    saw_flight |= q.regime == Regime::Flight;
  }
  EXPECT_TRUE(saw_flight);
}

TEST(PoincareSection, ZeroFrictionPointsLieOnTheEnergySurface) {
  // mu = 0: E = E0 + W_nonpotential (the thesis's foundation torque is not exactly conservative
  // with two corners submerged) up to the integration error.
  const WinklerParams p{0.5, 0.0, 1e4};
  const auto s = section(p, ic1(p), 100);
  const double e0 = s.res.initial_energy.total();
  ASSERT_FALSE(s.pts.empty());
  for (const auto& q : s.pts) {
    EXPECT_NEAR(q.energy, e0 + q.work_nonpotential, 1e-8) << "t = " << q.t;
    EXPECT_EQ(q.work_friction, 0.0);
  }
}

TEST(PoincareSection, PointsLieInsideTheProjectedEnergySurface) {
  // With friction the crossings stay inside E <= E0 (+ W_nonpotential): check the (y, y')
  // projection of eq. 5.1 at each crossing.
  const WinklerParams p{0.2, 0.3, 1e5};
  const auto s = section(p, ic1(p), 60);
  const double e0 = s.res.initial_energy.total();
  ASSERT_GT(s.pts.size(), 20u);
  for (const auto& q : s.pts)
    EXPECT_LE(0.5 * q.vy * q.vy + heave_potential(p, q.h), e0 + q.work_nonpotential + 1e-9) << "t = " << q.t;
}

TEST(PoincareSection, DirectionFilterKeepsOneSide) {
  const WinklerParams p{0.5, 0.0, 1e4};
  const auto all = section(p, ic1(p), 50);
  const auto pos = section(p, ic1(p), 50, CrossingDirection::Positive);
  const auto neg = section(p, ic1(p), 50, CrossingDirection::Negative);
  EXPECT_EQ(pos.pts.size() + neg.pts.size(), all.pts.size());
  for (const auto& q : pos.pts) EXPECT_GT(q.vw, 0.0);
  for (const auto& q : neg.pts) EXPECT_LT(q.vw, 0.0);
  // Crossings alternate in direction, so the two halves differ by at most one.
  EXPECT_LE(std::labs(long(pos.pts.size()) - long(neg.pts.size())), 1);
}

TEST(PoincareEnergySurface, NumericalHeaveMinimumMatchesTheThesisClosedForm) {
  // The (y, y') projection of the thesis uses min_w V(h, w) = V(h, 0); check it numerically.
  for (const WinklerParams p :
       {WinklerParams{0.2, 0.3, 1e5}, WinklerParams{0.5, 0.0, 1e4}, WinklerParams{1.0, 0.1, 50}}) {
    for (double s : {-3.0, -1.0, -0.3, 0.0, 0.5, 2.0}) {
      const double h = s / p.k;
      const double num = heave_potential(p, h), cf = heave_potential_closed_form(p, h);
      EXPECT_NEAR(num, cf, 1e-12 * (std::fabs(cf) + 1.0 / p.k)) << "k = " << p.k << ", h = " << h;
    }
  }
}

TEST(PoincareEnergySurface, RockPotentialIsTheMinimumOverHeight) {
  const WinklerParams p{0.2, 0.3, 1e5};
  for (double w : {0.0, 0.02, -0.05, 0.1}) {
    const double u = rock_potential(p, w);
    const double h = static_height(p, w, 1.0), dh = 1e-3 / p.k;
    EXPECT_LE(u, potential(p, h + dh, w));
    EXPECT_LE(u, potential(p, h - dh, w));
  }
  // Upright at rest: V = -1/k + (k/2)(1/k)^2 = -1/(2k).
  EXPECT_NEAR(rock_potential(p, 0.0), -0.5 / p.k, 1e-15);
}

TEST(PoincareEnergySurface, InitialConditionOnTheEnergyOfIc1ReproducesFigure511) {
  // Fig. 5.11: r = 0.2, k = 1e4, mu = 0.2, E of ic1, w0 = alpha/8, y0 = 0.50132 -> y0' = 0.0943112665.
  const WinklerParams p{0.2, 0.2, 1e4};
  const double E = energy(p, ic1(p)).total();
  const WinklerState z = state_on_energy_surface(p, E, p.alpha() / 8, 0.50132);
  EXPECT_NEAR(z[kVY], 0.0943112665, 5e-9);
  EXPECT_NEAR(energy(p, z).total(), E, 1e-15);
  EXPECT_EQ(z[kVX], 0.0);
  EXPECT_EQ(z[kVW], 0.0);
  // The lowest corner starts at x = 0 and at rest horizontally: no initial dissipation.
  WinklerRunOptions o;
  o.t_end = 0.5;
  const auto r = simulate(p, {}, z, o);
  EXPECT_LT(std::fabs(r.work_friction()), 1e-6 * E);
  EXPECT_THROW(state_on_energy_surface(p, -1.0, 0.0, 0.5), std::invalid_argument);
  EXPECT_THROW(state_on_energy_surface(p, E, 1.0, 0.5), std::invalid_argument);
}

TEST(PoincareEnergySurface, TrajectoryStaysInsideBothProjections) {
  const WinklerParams p{0.5, 0.0, 1e4};
  const double E = energy(p, ic1(p)).total();
  const auto s = section(p, ic1(p), 30);
  for (const auto& q : s.pts) {
    EXPECT_LE(0.5 * q.vy * q.vy + heave_potential(p, q.h), E + 1e-6);
    EXPECT_LE(0.5 * p.inertia() * q.vw * q.vw + rock_potential(p, 0.0), E + 1e-6);
  }
  const auto heave = heave_projection(p, E, 50);
  const auto rock = rock_projection(p, E, 51);
  ASSERT_EQ(heave.size(), 50u);
  ASSERT_EQ(rock.size(), 51u);
  EXPECT_NEAR(rock[25].w, 0.0, 1e-15);
  // Contact bound is tighter than the free one.
  for (const auto& b : rock) EXPECT_LE(b.vw_contact, b.vw_free);
}

TEST(PoincareCli, BadInputExitsWithStatus2) {
  EXPECT_EQ(poincare_cli("poincare --t-end 10 --t-min 20"), 2);
  EXPECT_EQ(poincare_cli("poincare --t-end 0"), 2);
  EXPECT_EQ(poincare_cli("energy-surface --ic surface --w0 0.01 --t-end 1"), 2);  // needs --y0
  EXPECT_EQ(poincare_cli("energy-surface --ic surface --w0 0.01 --y0 0.5 --energy -1 --t-end 1"), 2);
  EXPECT_EQ(poincare_cli("energy-surface --phase-dt 0 --t-end 1"), 2);
  EXPECT_EQ(poincare_cli("poincare --mu 0 --r 0.5 --k 1e4 --t-end 5"), 0);
}

TEST(PoincareCli, EnergySurfaceBuildsTheThesisInitialCondition) {
  const std::string out = "/tmp/blockdyn-test-energy-" + std::to_string(::getpid()) + ".json";
  ASSERT_EQ(poincare_cli("energy-surface --r 0.2 --k 1e4 --mu 0.2 --ic surface --w0-alpha 0.125 --y0 0.50132 "
                         "--t-end 2 --json-out " +
                         out),
            0);
  std::ifstream in(out);
  const auto j = nlohmann::json::parse(in);
  std::remove(out.c_str());
  EXPECT_NEAR(j["initial"]["state"]["vy"].get<double>(), 0.0943112665, 5e-9);  // Fig. 5.11
  EXPECT_LE(j["max_heave_excess"].get<double>(), 1e-9);
  EXPECT_LE(j["max_rock_excess"].get<double>(), 1e-9);
  EXPECT_EQ(poincare_cli("energy-surface --ic surface --w0 0.01 --w0-alpha 0.1 --y0 0.5 --t-end 1"), 2);
}
