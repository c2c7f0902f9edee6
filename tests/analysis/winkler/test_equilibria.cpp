// SPDX-License-Identifier: Apache-2.0
// Static equilibria and their bifurcations (thesis 4.3.3). Reference values come from
// closed forms derived independently of the numerical path (docs/equilibria.md):
//  - upright slope of the arm: 1/2 - r^2 k/12 - 1/(4k)  => k_os root of k^2 r^2 - 6k + 3 = 0;
//  - one corner submerged: the Region is a triangle, d = sqrt(2 r sin w cos w / k),
//    arm = -(r cos w - sin w)/2 + (d/3)(cot w - tan w); tilted equilibria at
//    k = (8r/9)(1 - t^2)^2 / ((r - t)^2 t), t = tan w, whose minimum over t is k_uns.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <unistd.h>
#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "blockdyn/analysis/winkler/equilibria.hpp"
#include "blockdyn/analysis/winkler/equilibrium_bifurcation.hpp"
#include "blockdyn/model/winkler/energy.hpp"
#include "blockdyn/model/winkler/region.hpp"

using namespace blockdyn;

namespace {

WinklerParams P(double r, double k) {
  WinklerParams p;
  p.r = r;
  p.k = k;
  return p;
}

double one_corner_depth(double r, double k, double w) { return std::sqrt(2.0 * r * std::sin(w) * std::cos(w) / k); }

double one_corner_arm(double r, double k, double w) {
  const double d = one_corner_depth(r, k, w);
  return -0.5 * (r * std::cos(w) - std::sin(w)) + d / 3.0 * (1.0 / std::tan(w) - std::tan(w));
}

// k at which tilt w = atan(t) is a one-corner equilibrium.
double one_corner_k(double r, double t) { return 8.0 * r / 9.0 * std::pow(1.0 - t * t, 2) / (std::pow(r - t, 2) * t); }

double linearized_k_os(double r) { return (3.0 + std::sqrt(9.0 - 3.0 * r * r)) / (r * r); }

int count_stable(const std::vector<Equilibrium>& e) {
  int n = 0;
  for (const auto& q : e) n += q.stability == Stability::Stable;
  return n;
}

struct CliResult {
  int status;
  std::string out;
};

CliResult run_cli(const std::string& args) {
  const std::string cmd = std::string(BLOCKDYN_CLI) + " " + args + " 2>/dev/null";
  FILE* f = ::popen(cmd.c_str(), "r");
  std::string out;
  char buf[4096];
  while (std::size_t n = std::fread(buf, 1, sizeof buf, f)) out.append(buf, n);
  const int st = ::pclose(f);
  return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, out};
}

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

// ------------------------------------------------------------------ resting height and arm

TEST(EquilRestingHeight, UprightSinksOneOverK) {
  for (double r : {0.05, 0.5, 1.0})
    for (double k : {2.0, 6.2, 1e3, 1e9}) {
      const double h = resting_height(P(r, k), 0.0);
      EXPECT_NEAR(h, -1.0 / k, 1e-14 / k) << "r=" << r << " k=" << k;
    }
}

TEST(EquilRestingHeight, CarriesTheWeightAtEveryTilt) {
  for (double r : {0.1, 0.7, 1.0})
    for (double k : {2.0, 30.0, 1e5, 1e9})
      for (double f : {1e-7, 0.01, 0.3, 0.77, 1.0}) {
        const double w = f * std::atan(r);
        const double h = resting_height(P(r, k), w);
        const RegionIntegrals g = region_integrals(r, h, w);
        EXPECT_NEAR(k / r * g.area, 1.0, 1e-11) << "r=" << r << " k=" << k << " w=" << w;
        // At most two corners below; at k = 2, r = 1, w = alpha the third corner sits exactly
        // on the surface, so its height is compared with a rounding allowance.
        const CornerHeights c = corner_heights(r, h, w);
        EXPECT_GE(std::max(c.other_bottom, c.upper_pivot_side), -1e-14) << "r=" << r << " k=" << k;
      }
}

TEST(EquilRestingHeight, OneCornerDepthClosedForm) {
  const double r = 0.5, k = 1e4;
  for (double w : {0.1, 0.3, 0.46}) {
    const double h = resting_height(P(r, k), w);
    const CornerHeights c = corner_heights(r, h, w);
    ASSERT_GT(c.other_bottom, 0.0);
    const double d = one_corner_depth(r, k, w);
    EXPECT_NEAR(-c.lowest, d, 1e-10 * d);
  }
}

TEST(EquilArm, OddInTilt) {
  for (double r : {0.2, 0.9, 1.0})
    for (double k : {3.0, 100.0, 1e6})
      for (double f : {1e-6, 0.05, 0.4, 0.9}) {
        const double w = f * std::atan(r);
        const WinklerParams p = P(r, k);
        EXPECT_NEAR(equilibrium_arm(p, -w), -equilibrium_arm(p, w), 1e-15 * (1.0 + std::fabs(equilibrium_arm(p, w))));
      }
}

TEST(EquilArm, OneCornerClosedForm) {
  int checked = 0;
  for (double r : {0.3, 0.8, 1.0})
    for (double k : {5.0, 100.0, 1e6})
      for (double f : {0.2, 0.5, 0.8, 0.99}) {
        const double w = f * std::atan(r);
        const ArmSample s = arm_sample(P(r, k), w);
        if (s.corners_below != 1) continue;
        ++checked;
        EXPECT_NEAR(s.arm, one_corner_arm(r, k, w), 1e-11) << "r=" << r << " k=" << k << " w=" << w;
      }
  EXPECT_GE(checked, 25);
}

TEST(EquilArm, UprightSlopeMatchesLinearization) {
  for (double r : {0.05, 0.3, 0.9, 1.0})
    for (double k : {2.0, 6.0 / (r * r), 1e4, 1e8}) {
      const double lin = 0.5 - r * r * k / 12.0 - 0.25 / k;
      EXPECT_NEAR(upright_arm_slope(P(r, k)), lin, 1e-9 * std::max(1.0, std::fabs(lin))) << r << " " << k;
    }
}

// ------------------------------------------------------------------ critical stiffnesses

TEST(EquilBifurcation, KosIsTheLinearizedRoot) {
  for (double r : {0.05, 0.1, 0.2, 0.5, 0.7, 0.9, 0.95, 1.0}) {
    const double k = find_k_os(r);
    EXPECT_NEAR(k, linearized_k_os(r), 1e-10 * k) << "r=" << r;
    EXPECT_NEAR((k * k * r * r - 6.0 * k + 3.0) / (k * k * r * r), 0.0, 1e-10);
  }
}

TEST(EquilBifurcation, KosApproachesSixOverRSquaredMinusHalf) {
  double prev = 1e300;
  for (double r : {1.0, 0.7, 0.5, 0.3, 0.2, 0.1, 0.05}) {
    const double k = find_k_os(r);
    const double rel = std::fabs(k - (6.0 / (r * r) - 0.5)) / k;
    EXPECT_LT(rel, prev) << "r=" << r;
    prev = rel;
  }
  EXPECT_LT(prev, 1e-7);  // ~ r^4 / 144 at r = 0.05
  EXPECT_NEAR(find_k_os(1.0), 3.0 + std::sqrt(6.0), 1e-9);
}

TEST(EquilBifurcation, KunsIsTheOneCornerFold) {
  for (double r : {0.05, 0.2, 0.5, 0.9, 0.99}) {
    // Independent reference: minimise the one-corner equilibrium stiffness over t = tan w.
    const auto m = boost::math::tools::brent_find_minima([r](double t) { return one_corner_k(r, t); }, 1e-6 * r,
                                                         r * (1 - 1e-9), 60);
    const double t = m.first, kf = m.second;
    const double w = std::atan(t);
    // The fold must lie where only one corner is submerged (far bottom corner above the surface).
    ASSERT_LT(one_corner_depth(r, kf, w), r * std::sin(w)) << "r=" << r;
    EXPECT_NEAR(find_k_uns(r), kf, 1e-9 * kf) << "r=" << r;
    EXPECT_NEAR(t * t * t - 3 * r * t * t + 3 * t - r, 0.0, 1e-7);
  }
}

TEST(EquilBifurcation, SquareBlockValues) {
  EXPECT_NEAR(find_k_os(1.0), 3.0 + std::sqrt(6.0), 1e-9);
  EXPECT_NEAR(find_k_uns(1.0), 32.0 / 9.0, 1e-9);
}

TEST(EquilBifurcation, GapTendsToFiveSixthsForTallBlocks) {
  // k_uns = 6/r^2 - 4/3 + O(r^2), k_os = 6/r^2 - 1/2 + O(r^2): the gap tends to 5/6.
  double prev = 1e300;
  for (double r : {1.0, 0.8, 0.5, 0.2, 0.1, 0.05, 0.02}) {
    const CriticalStiffness c = critical_stiffness(r);
    const double gap = c.k_os - c.k_uns;
    EXPECT_LT(gap, prev);
    EXPECT_GT(gap, 5.0 / 6.0);
    prev = gap;
  }
  EXPECT_NEAR(prev, 5.0 / 6.0, 1e-3);
}

TEST(EquilBifurcation, CurvesIndependentOfThreadCount) {
  const std::vector<double> rs = {0.1, 0.4, 0.7, 1.0};
  const auto a = critical_curves(rs, 1), b = critical_curves(rs, 2);
  for (std::size_t i = 0; i < rs.size(); ++i) {
    EXPECT_EQ(a[i].k_os, b[i].k_os);
    EXPECT_EQ(a[i].k_uns, b[i].k_uns);
  }
}

// ------------------------------------------------------------------ equilibrium search

TEST(EquilSearch, CountsInTheThreeStiffnessRanges) {
  for (double r : {0.1, 0.3, 0.5, 0.7, 0.9, 0.99}) {
    const CriticalStiffness c = critical_stiffness(r);
    const double gap = c.k_os - c.k_uns;
    struct Case {
      double k;
      std::size_t n;
      int stable;
    };
    // Includes points 1e-6 of the gap from each bifurcation: two roots closer than a scan cell.
    const Case cases[] = {{std::max(2.0, c.k_uns - 0.3 * gap), 1, 0},
                          {c.k_uns - 1e-6 * gap, 1, 0},
                          {c.k_uns + 1e-6 * gap, 3, 1},
                          {0.5 * (c.k_uns + c.k_os), 3, 1},
                          {c.k_os - 1e-6 * gap, 3, 1},
                          {c.k_os + 1e-6 * gap, 2, 1},
                          {c.k_os + 0.3 * gap, 2, 1},
                          {1e7, 2, 1}};
    for (const Case& cs : cases) {
      const auto e = find_equilibria(P(r, cs.k));
      ASSERT_EQ(e.size(), cs.n) << "r=" << r << " k=" << cs.k;
      EXPECT_EQ(count_stable(e), cs.stable) << "r=" << r << " k=" << cs.k;
      EXPECT_EQ(e.front().w, 0.0);
      EXPECT_EQ(e.front().branch, EquilibriumBranch::Upright);
      EXPECT_EQ(e.front().stability == Stability::Stable, cs.k > c.k_os);
      if (cs.n == 3) {
        EXPECT_EQ(e[1].stability, Stability::Stable);
        EXPECT_EQ(e[2].stability, Stability::Unstable);
      }
      if (cs.n == 2) {
        EXPECT_EQ(e[1].stability, Stability::Unstable);
      }
    }
  }
}

TEST(EquilSearch, EquilibriaBalanceWeightAndMoment) {
  for (double r : {0.1, 0.5, 0.9, 1.0})
    for (double k : {2.5, 4.0, 6.2, 23.0, 599.1, 1e4, 1e9}) {
      for (const auto& e : find_equilibria(P(r, k))) {
        const RegionIntegrals g = region_integrals(r, e.h, e.w);
        EXPECT_NEAR(k / r * g.area, 1.0, 1e-11);
        EXPECT_NEAR(g.moment / g.area, 0.0, 1e-11) << "r=" << r << " k=" << k << " w=" << e.w;
        EXPECT_GE(e.w, 0.0);
        EXPECT_LE(e.w, std::atan(r));
        // The mirror image is an equilibrium with the same stability (arm is odd in w).
        EXPECT_NEAR(equilibrium_arm(P(r, k), -e.w), 0.0, 1e-11);
      }
    }
}

TEST(EquilSearch, StabilityMatchesArmSlope) {
  for (double k : {5.0, 6.2, 6.8})
    for (const auto& e : find_equilibria(P(0.9, k)))
      EXPECT_EQ(e.stability == Stability::Stable, e.arm_slope < 0.0) << "k=" << k << " w=" << e.w;
}

TEST(EquilSearch, SquareBlockDiagonalAndTiltedBranch) {
  const double alpha = std::atan(1.0);
  for (double k : {2.0, 3.0, 3.5, 3.6, 4.0, 5.0, 5.4, 6.0, 100.0}) {
    const auto e = find_equilibria(P(1.0, k));
    ASSERT_EQ(e.back().branch, EquilibriumBranch::Diagonal);
    EXPECT_DOUBLE_EQ(e.back().w, alpha);
    EXPECT_EQ(e.back().stability == Stability::Stable, k < 32.0 / 9.0) << "k=" << k;
    const bool tilted = k > 32.0 / 9.0 && k < 3.0 + std::sqrt(6.0);
    ASSERT_EQ(e.size(), tilted ? 3u : 2u) << "k=" << k;
    if (tilted && e[1].corners_below == 1) {
      // One corner: sin 2w = 16 / (9k - 16).
      EXPECT_NEAR(std::sin(2.0 * e[1].w), 16.0 / (9.0 * k - 16.0), 1e-10) << "k=" << k;
      EXPECT_EQ(e[1].stability, Stability::Stable);
    }
  }
  EXPECT_NEAR(find_equilibria(P(1.0, 4.0))[1].w, std::atan(0.5), 1e-11);
}

TEST(EquilSearch, RejectsOutOfRangeParameters) {
  EXPECT_THROW(find_equilibria(P(1.5, 10)), std::invalid_argument);
  EXPECT_THROW(find_equilibria(P(0.5, 1.0)), std::invalid_argument);
  EXPECT_THROW(find_equilibria(P(0.5, NAN)), std::invalid_argument);
}

// ------------------------------------------------------------------ the thesis's statements

TEST(EquilThesis, AspectRatioPointNine) {
  const double alpha = std::atan(0.9);
  auto e = find_equilibria(P(0.9, 100.0));  // stable upright, unstable near alpha
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].stability, Stability::Stable);
  EXPECT_EQ(e[1].stability, Stability::Unstable);
  EXPECT_GT(e[1].w, 0.9 * alpha);
  e = find_equilibria(P(0.9, 6.2));  // upright unstable, stable and unstable tilted
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(e[0].stability, Stability::Unstable);
  EXPECT_EQ(e[1].stability, Stability::Stable);
  EXPECT_EQ(e[2].stability, Stability::Unstable);
  e = find_equilibria(P(0.9, 4.5));  // only the unstable upright
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].stability, Stability::Unstable);
}

TEST(EquilThesis, AspectRatioPointOne) {
  const double alpha = std::atan(0.1);
  auto e = find_equilibria(P(0.1, 2000.0));
  ASSERT_EQ(e.size(), 2u);
  EXPECT_EQ(e[0].stability, Stability::Stable);
  EXPECT_EQ(e[1].stability, Stability::Unstable);
  // "an unstable one near alpha": at k = 2000 (only 3.3 k_os) it sits at 0.76 alpha; it is the
  // branch that rises monotonically to alpha as k grows (the rigid-ground limit).
  double prev = e[1].w;
  EXPECT_GT(prev, 0.5 * alpha);
  for (double k : {1e4, 1e6, 1e9}) {
    const auto ek = find_equilibria(P(0.1, k));
    ASSERT_EQ(ek.size(), 2u);
    EXPECT_GT(ek[1].w, prev);
    prev = ek[1].w;
  }
  EXPECT_GT(prev, 0.999 * alpha);
  e = find_equilibria(P(0.1, 599.1));
  ASSERT_EQ(e.size(), 3u);
  EXPECT_EQ(count_stable(e), 1);
  EXPECT_EQ(e[1].stability, Stability::Stable);
  // "arm gets so close to zero that we cannot see where it crosses": |arm| tiny up to w_u.
  for (double f : {0.25, 0.5, 0.75}) EXPECT_LT(std::fabs(equilibrium_arm(P(0.1, 599.1), f * e[2].w)), 1e-5);
  e = find_equilibria(P(0.1, 500.0));
  ASSERT_EQ(e.size(), 1u);
  EXPECT_EQ(e[0].stability, Stability::Unstable);
}

// ------------------------------------------------------------------ energy landscape

TEST(EquilLandscape, EnergyAndPotentialAgreeWithOneCorner) {
  for (double r : {0.5, 0.9}) {
    const double k = 100.0;
    const auto l = energy_landscape(P(r, k), 201);
    std::size_t i0 = 0;
    while (l[i0].corners_below != 1) ++i0;
    ASSERT_LT(i0 + 50, l.size());
    for (std::size_t i = i0 + 1; i < l.size(); ++i)  // conservative with one corner
      EXPECT_NEAR(l[i].energy - l[i0].energy, l[i].potential - l[i0].potential, 1e-12);
    // Energy extremum at the unstable tilted equilibrium (maximum).
    const auto e = find_equilibria(P(r, k));
    std::size_t imax = 0;
    for (std::size_t i = 0; i < l.size(); ++i)
      if (l[i].energy > l[imax].energy) imax = i;
    EXPECT_NEAR(l[imax].w, e.back().w, 1.01 * std::atan(r) / 200);
  }
}

TEST(EquilLandscape, TwoCornerPotentialHasACusp) {
  // With two corners the gap triangle under the side edge stores spring energy ~ |w|:
  // V + y grows like w / (6 r k^2) while -int arm is O(w^2). The force model is not a gradient.
  const double r = 0.9, k = 6.2, w = 1e-6;
  const WinklerParams p = P(r, k);
  const double h0 = resting_height(p, 0.0), h = resting_height(p, w);
  const double dP = spring_energy(p, h, w) + h - spring_energy(p, h0, 0.0) - h0;
  EXPECT_NEAR(dP / w, 1.0 / (6.0 * r * k * k), 1e-4 / (6.0 * r * k * k));
  const auto l = energy_landscape(p, 3);
  EXPECT_EQ(l[0].energy, 0.0);
  EXPECT_EQ(l[0].potential, 0.0);
}

TEST(EquilLandscape, EnergyDerivativeIsMinusArm) {
  const WinklerParams p = P(0.7, 11.0);
  const auto l = energy_landscape(p, 401);
  for (std::size_t i = 1; i + 1 < l.size(); i += 37) {
    const double d = (l[i + 1].energy - l[i - 1].energy) / (l[i + 1].w - l[i - 1].w);
    EXPECT_NEAR(d, -l[i].arm, 1e-5);
  }
}

// ------------------------------------------------------------------ command line

TEST(EquilCli, EquilibriaJson) {
  const auto r = run_cli("equilibria --r 0.9 --k 6.2 --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["equilibria"].size(), 3u);
  EXPECT_FALSE(j["equilibria"][0]["stable"].get<bool>());
  EXPECT_TRUE(j["equilibria"][1]["stable"].get<bool>());
  EXPECT_NEAR(j["equilibria"][0]["y"].get<double>(), 0.5 - 1.0 / 6.2, 1e-14);
  EXPECT_TRUE(j.contains("run_info"));
  EXPECT_EQ(j["params"]["k"].get<double>(), 6.2);
}

TEST(EquilCli, BifurcationJsonSquareBlock) {
  const auto r = run_cli("bifurcation --r 1 --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_NEAR(j["k_os"].get<double>(), 3.0 + std::sqrt(6.0), 1e-6);
  EXPECT_NEAR(j["k_uns"].get<double>(), 32.0 / 9.0, 1e-6);
  EXPECT_EQ(j["k_os_small_angle"].get<double>(), 5.5);
}

TEST(EquilCli, CurvesCsvDeterministicAcrossThreads) {
  const std::string a = "/tmp/blockdyn-equil-test-" + std::to_string(::getpid()) + "-a.csv";
  const std::string b = "/tmp/blockdyn-equil-test-" + std::to_string(::getpid()) + "-b.csv";
  ASSERT_EQ(run_cli("bifurcation-curves --r-min 0.2 --r-max 1 --points 5 --threads 1 --csv " + a).status, 0);
  ASSERT_EQ(run_cli("bifurcation-curves --r-min 0.2 --r-max 1 --points 5 --threads 2 --csv " + b).status, 0);
  const std::string ta = read_all(a);
  EXPECT_EQ(ta, read_all(b));
  EXPECT_EQ(std::count(ta.begin(), ta.end(), '\n'), 6);
  const auto side = nlohmann::json::parse(read_all(a + ".json"));
  EXPECT_TRUE(side.contains("run_info"));
  for (const auto& p : {a, b}) {
    std::remove(p.c_str());
    std::remove((p + ".json").c_str());
  }
}

TEST(EquilCli, BadInputExitsTwo) {
  for (const char* args :
       {"equilibria --r 1.5 --k 10", "equilibria --r 0.5 --k 1", "equilibria --r 0.5 --k 10 --points 1",
        "bifurcation --r 0", "bifurcation --r 0.5 --k-min 10 --k-max 5 --csv /tmp/x.csv",
        "bifurcation --r 0.5 --spacing cubic", "bifurcation-curves --r-min 0.8 --r-max 0.5",
        "bifurcation-curves --threads -1"})
    EXPECT_EQ(run_cli(args).status, 2) << args;
}
