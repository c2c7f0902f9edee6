// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/fragility_fit.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "blockdyn/analysis/sweep/parallel_map.hpp"

namespace blockdyn {
namespace {

// log Phi(z) without underflow in the tails.
double log_cdf(double z) {
  if (z > -30.0) return std::log(normal_cdf(z));
  return -0.5 * z * z - std::log(-z) - 0.5 * std::log(2.0 * M_PI);  // Mills' ratio
}

// The inverse Mills ratio phi(z) / Phi(z), stable for z << 0.
double mills(double z) {
  if (z > -30.0) return std::exp(-0.5 * z * z) / std::sqrt(2.0 * M_PI) / normal_cdf(z);
  return -z;
}

double log_likelihood(const std::vector<FragilityRun>& runs, double a, double b) {
  double l = 0.0;
  for (const FragilityRun& r : runs) {
    const double z = a + b * std::log(r.im);
    l += r.failed ? log_cdf(z) : log_cdf(-z);
  }
  return l;
}

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * double(v.size() - 1);
  const std::size_t i = std::size_t(pos);
  return i + 1 < v.size() ? v[i] + (pos - double(i)) * (v[i + 1] - v[i]) : v.back();
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

FragilityFit fit_fragility(const std::vector<FragilityRun>& runs) {
  FragilityFit f;
  std::size_t failed = 0;
  double lo_fail = INFINITY, hi_safe = -INFINITY;
  for (const FragilityRun& r : runs) {
    failed += r.failed;
    if (r.failed) lo_fail = std::min(lo_fail, r.im);
    if (!r.failed) hi_safe = std::max(hi_safe, r.im);
  }
  if (runs.empty() || failed == 0 || failed == runs.size()) {
    f.why = runs.empty() ? "no runs" : failed == 0 ? "no run failed: no finite fit" : "every run failed: no finite fit";
    return f;
  }
  if (hi_safe < lo_fail) {
    f.why = "the runs are separated (every failure above every survival): beta -> 0, no finite fit";
    return f;
  }
  // Start: median at the mean ln IM, beta 0.5.
  double mean = 0.0;
  for (const FragilityRun& r : runs) mean += std::log(r.im);
  mean /= double(runs.size());
  double b = 2.0, a = -b * mean, l = log_likelihood(runs, a, b);
  for (f.iterations = 1; f.iterations <= 200; ++f.iterations) {
    // Gradient and (negative) Hessian of the probit log-likelihood.
    double ga = 0, gb = 0, haa = 0, hab = 0, hbb = 0;
    for (const FragilityRun& r : runs) {
      const double x = std::log(r.im), z = a + b * x, s = r.failed ? 1.0 : -1.0;
      const double m = mills(s * z), g = s * m, w = m * (m + s * z);  // d/dz log Phi(s z); -d2/dz2
      ga += g;
      gb += g * x;
      haa += w;
      hab += w * x;
      hbb += w * x * x;
    }
    const double det = haa * hbb - hab * hab;
    if (!(det > 0.0)) break;
    double da = (hbb * ga - hab * gb) / det, db = (haa * gb - hab * ga) / det;
    double step = 1.0, ln = l;
    while (step > 1e-12) {
      ln = log_likelihood(runs, a + step * da, b + step * db);
      if (ln >= l) break;
      step *= 0.5;
    }
    a += step * da;
    b += step * db;
    const bool done = std::fabs(ln - l) <= 1e-14 * std::fabs(l) && std::fabs(step * db) <= 1e-12 * std::fabs(b);
    l = ln;
    if (done) break;
  }
  if (!(b > 0.0) || !std::isfinite(a)) {
    f.why = "the likelihood has no maximum with beta > 0 (failures do not increase with the IM)";
    return f;
  }
  f.ok = true;
  f.beta = 1.0 / b;
  f.median = std::exp(-a / b);
  f.log_likelihood = l;
  return f;
}

FragilityBand bootstrap_fragility(const std::vector<std::vector<FragilityRun>>& groups, int samples, std::uint64_t seed,
                                  int threads) {
  FragilityBand band;
  band.samples = samples;
  std::seed_seq ss{std::uint32_t(seed), std::uint32_t(seed >> 32), std::uint32_t(0xb007)};
  std::mt19937_64 rng(ss);
  // The resamples drawn in order from the one stream, then fitted on the threads: the same fits
  // in the same order whatever the thread count.
  std::vector<std::size_t> picks(std::size_t(samples) * groups.size());
  for (std::size_t& p : picks) p = std::size_t(rng() % groups.size());
  const std::vector<FragilityFit> fits = parallel_map<FragilityFit>(std::size_t(samples), threads, [&](std::size_t s) {
    std::vector<FragilityRun> runs;
    for (std::size_t k = 0; k < groups.size(); ++k) {
      const auto& g = groups[picks[s * groups.size() + k]];
      runs.insert(runs.end(), g.begin(), g.end());
    }
    return fit_fragility(runs);
  });
  std::vector<double> medians, betas;
  for (const FragilityFit& f : fits) {
    if (!f.ok) {
      ++band.failed;
      continue;
    }
    medians.push_back(f.median);
    betas.push_back(f.beta);
    band.fits.push_back({f.median, f.beta});
  }
  if (!medians.empty()) {
    band.median_lo = percentile(medians, 0.05);
    band.median_hi = percentile(medians, 0.95);
    band.beta_lo = percentile(betas, 0.05);
    band.beta_hi = percentile(betas, 0.95);
  }
  return band;
}

}  // namespace blockdyn
