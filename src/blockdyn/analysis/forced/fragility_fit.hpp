// SPDX-License-Identifier: Apache-2.0
#pragma once
// The lognormal fragility curve P(failure | IM) = Phi(ln(IM / theta) / beta) fitted to runs
// (IM_j, y_j) by maximum likelihood (Baker 2015), and its bootstrap over records. The likelihood
// is that of probit regression on ln IM, concave in (a, b) = (-ln theta / beta, 1 / beta):
// Newton's method with step halving finds its maximum.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace blockdyn {

struct FragilityRun {
  double im = 0;  // > 0
  bool failed = false;
};

struct FragilityFit {
  bool ok = false;
  std::string why;              // when not ok: no finite maximum (all failed, none failed, perfectly separated)
  double median = 0, beta = 0;  // theta and beta
  double log_likelihood = 0;
  int iterations = 0;
};
FragilityFit fit_fragility(const std::vector<FragilityRun>& runs);

// Percentiles (5 %, 95 %) of the median and beta over `samples` bootstrap resamples of the groups
// (records: every run of a group goes in or out together), from a seeded stream, fitted on
// `threads` (0: all cores; the band does not depend on it). Resamples with no finite fit are left
// out (counted).
struct FragilityBand {
  double median_lo = 0, median_hi = 0, beta_lo = 0, beta_hi = 0;
  int samples = 0, failed = 0;
  std::vector<std::pair<double, double>> fits;  // (median, beta) of each resample that fitted
};
FragilityBand bootstrap_fragility(const std::vector<std::vector<FragilityRun>>& groups, int samples, std::uint64_t seed,
                                  int threads = 1);

double normal_cdf(double x);

}  // namespace blockdyn
