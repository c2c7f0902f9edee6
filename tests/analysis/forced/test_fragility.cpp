// SPDX-License-Identifier: Apache-2.0
// The lognormal fragility fit: recovers the curve that drew the data, equals an independent
// maximisation of the same likelihood (a grid search), reports the cases without a finite fit,
// and its bootstrap band covers the fit.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <random>
#include <tuple>
#include <vector>

#include "blockdyn/analysis/forced/fragility_fit.hpp"

using namespace blockdyn;

namespace {

// Multiple stripes drawn from P = Phi(ln(im / theta) / beta): `per_level` runs at each level.
std::vector<FragilityRun> stripes(double theta, double beta, int per_level, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<FragilityRun> runs;
  for (int i = 1; i <= 10; ++i) {
    const double im = 0.12 * i;
    const double p = 0.5 * std::erfc(-std::log(im / theta) / beta / std::sqrt(2.0));
    for (int k = 0; k < per_level; ++k) runs.push_back({im, u(rng) < p});
  }
  return runs;
}

// The log-likelihood written out independently of the library.
double loglik(const std::vector<FragilityRun>& runs, double theta, double beta) {
  double l = 0;
  for (const auto& r : runs) {
    const double p = 0.5 * std::erfc(-std::log(r.im / theta) / beta / std::sqrt(2.0));
    l += std::log(r.failed ? p : 1 - p);
  }
  return l;
}

}  // namespace

TEST(FragilityFit, RecoversTheCurveThatDrewTheData) {
  const FragilityFit f = fit_fragility(stripes(0.5, 0.4, 400, 3));
  ASSERT_TRUE(f.ok) << f.why;
  EXPECT_NEAR(f.median, 0.5, 0.03 * 0.5);
  EXPECT_NEAR(f.beta, 0.4, 0.1 * 0.4);
}

TEST(FragilityFit, EqualsAGridSearchOfTheLikelihood) {
  const std::vector<FragilityRun> runs = stripes(0.6, 0.5, 15, 9);
  const FragilityFit f = fit_fragility(runs);
  ASSERT_TRUE(f.ok) << f.why;
  // Coarse grid, then finer grids around the best point.
  double bt = 0.6, bb = 0.5, span_t = 0.5, span_b = 0.45;
  for (int level = 0; level < 6; ++level) {
    double best = -INFINITY, t0 = bt, b0 = bb;
    for (int i = -40; i <= 40; ++i)
      for (int j = -40; j <= 40; ++j) {
        const double t = t0 * std::exp(span_t * i / 40.0), b = b0 + span_b * j / 40.0;
        if (b <= 0) continue;
        const double l = loglik(runs, t, b);
        if (l > best) best = l, bt = t, bb = b;
      }
    span_t /= 10;
    span_b /= 10;
  }
  EXPECT_NEAR(f.median, bt, 1e-5 * bt);
  EXPECT_NEAR(f.beta, bb, 1e-5);
  EXPECT_NEAR(f.log_likelihood, loglik(runs, bt, bb), 1e-9);
}

TEST(FragilityFit, NoFiniteFitIsSaid) {
  std::vector<FragilityRun> none = {{0.1, false}, {0.2, false}}, all = {{0.1, true}, {0.2, true}};
  std::vector<FragilityRun> separated = {{0.1, false}, {0.2, false}, {0.3, true}, {0.4, true}};
  EXPECT_FALSE(fit_fragility(none).ok);
  EXPECT_FALSE(fit_fragility(all).ok);
  const FragilityFit s = fit_fragility(separated);
  EXPECT_FALSE(s.ok);
  EXPECT_NE(s.why.find("separated"), std::string::npos);
  EXPECT_TRUE(fit_fragility({{0.1, false}, {0.2, true}, {0.3, false}, {0.4, true}}).ok);
}

TEST(FragilityFit, BootstrapBandCoversTheFitAndReproduces) {
  // 40 "records", each run at every level.
  std::vector<std::vector<FragilityRun>> groups(40);
  const std::vector<FragilityRun> runs = stripes(0.5, 0.4, 40, 21);
  std::vector<FragilityRun> all;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    groups[i % 40].push_back(runs[i]);
    all.push_back(runs[i]);
  }
  const FragilityFit f = fit_fragility(all);
  const FragilityBand b = bootstrap_fragility(groups, 300, 5), again = bootstrap_fragility(groups, 300, 5);
  for (const auto& [lo, fitted, hi] :
       {std::array{b.median_lo, f.median, b.median_hi}, {b.beta_lo, f.beta, b.beta_hi}}) {
    EXPECT_LT(lo, fitted);
    EXPECT_GT(hi, fitted);
  }
  EXPECT_EQ(std::tie(b.median_lo, b.median_hi, b.beta_lo, b.beta_hi),
            std::tie(again.median_lo, again.median_hi, again.beta_lo, again.beta_hi));
  // Fitted on two threads: the same resamples, the same fits in the same order, bit for bit.
  const FragilityBand two = bootstrap_fragility(groups, 300, 5, 2);
  EXPECT_EQ(two.fits, b.fits);
  EXPECT_EQ(two.failed, b.failed);
  EXPECT_EQ(std::tie(b.median_lo, b.median_hi, b.beta_lo, b.beta_hi),
            std::tie(two.median_lo, two.median_hi, two.beta_lo, two.beta_hi));
}
