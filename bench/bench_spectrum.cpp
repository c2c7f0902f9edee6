// SPDX-License-Identifier: Apache-2.0
// Issue 38, item 1: the exact elastic spectrum (closed form per linear segment, peaks between
// samples) beside the floor it is measured against, in the same run: the Nigam-Jennings recursion
// with its coefficients once per period and the peak taken at the samples only (no transcendental
// per sample, no search between samples). 113 periods (0.02 to 10 s, log-spaced) of the first
// 4,684 samples of the 60 s synthetic record, 5 % damping. Counter: ns per sample and period.
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/excitation/response_spectrum.hpp"

using namespace blockdyn;

namespace {

constexpr std::size_t kSamples = 4684;
constexpr int kPeriods = 113;
constexpr double kDamping = 0.05;

const Accelerogram& record() {
  static const Accelerogram rec = [] {
    const Accelerogram full =
        load_accelerogram(std::string(BLOCKDYN_SOURCE_DIR) + "/tests/fixtures/synthetic_60s.AT2", "record");
    std::vector<double> a(kSamples);
    for (std::size_t i = 0; i < kSamples; ++i) a[i] = full.at(double(i) * full.dt());
    return Accelerogram(a, full.dt(), "first 4684 samples");
  }();
  return rec;
}

std::vector<double> periods() {
  std::vector<double> p(kPeriods);
  for (int i = 0; i < kPeriods; ++i) p[std::size_t(i)] = 0.02 * std::pow(500.0, double(i) / (kPeriods - 1));
  return p;
}

using Mat4 = std::array<std::array<double, 4>, 4>;

Mat4 multiply(const Mat4& a, const Mat4& b) {
  Mat4 c{};
  for (int i = 0; i < 4; ++i)
    for (int k = 0; k < 4; ++k)
      for (int j = 0; j < 4; ++j) c[i][j] += a[i][k] * b[k][j];
  return c;
}

// exp(M) by scaling and squaring of its Taylor series (4 x 4, once per period).
Mat4 expm(Mat4 m) {
  double norm = 0;
  for (const auto& row : m)
    for (double v : row) norm = std::fmax(norm, std::fabs(v));
  int squarings = 0;
  while (norm > 0.25) norm *= 0.5, ++squarings;
  for (auto& row : m)
    for (double& v : row) v = std::ldexp(v, -squarings);
  Mat4 sum{}, term{};
  for (int i = 0; i < 4; ++i) sum[i][i] = term[i][i] = 1.0;
  for (int k = 1; k <= 20; ++k) {
    term = multiply(term, m);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) sum[i][j] += (term[i][j] /= (k == 1 ? 1.0 : double(k)));
  }
  for (int i = 0; i < squarings; ++i) sum = multiply(sum, sum);
  return sum;
}

// Nigam & Jennings (1969): the exact transition of the oscillator over a step of linear input,
// u_{i+1} = A u_i + B (a_i, a_{i+1}), its coefficients once per period (from the exponential of the
// system augmented with the input and its slope), the peak |u| taken at the samples only.
double sample_only_sd(const std::vector<double>& ag, double dt, double period) {
  const double w = 2.0 * M_PI / period;
  Mat4 m{};  // (u, v, a, a'): u' = v, v' = -w^2 u - 2 zeta w v - a, a'' = 0
  m[0][1] = dt;
  m[1][0] = -w * w * dt;
  m[1][1] = -2 * kDamping * w * dt;
  m[1][2] = -dt;
  m[2][3] = dt;
  const Mat4 e = expm(m);
  const double a11 = e[0][0], a12 = e[0][1], a21 = e[1][0], a22 = e[1][1];
  const double b11 = e[0][2] - e[0][3] / dt, b12 = e[0][3] / dt, b21 = e[1][2] - e[1][3] / dt, b22 = e[1][3] / dt;
  double u = 0, v = 0, peak = 0;
  for (std::size_t i = 1; i < ag.size(); ++i) {
    const double u1 = a11 * u + a12 * v + b11 * ag[i - 1] + b12 * ag[i];
    const double v1 = a21 * u + a22 * v + b21 * ag[i - 1] + b22 * ag[i];
    u = u1;
    v = v1;
    peak = std::fmax(peak, std::fabs(u));
  }
  return peak;
}

void BM_SpectrumExact(benchmark::State& state) {
  const Accelerogram& rec = record();
  const std::vector<double> p = periods();
  for (auto _ : state) benchmark::DoNotOptimize(response_spectrum(rec, p, kDamping));
  state.counters["ns_per_sample_period"] = benchmark::Counter(
      double(kSamples) * kPeriods, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SpectrumExact)->Unit(benchmark::kMillisecond);

void BM_SpectrumSampleOnlyFloor(benchmark::State& state) {
  const Accelerogram& rec = record();
  std::vector<double> ag(kSamples);
  for (std::size_t i = 0; i < kSamples; ++i) ag[i] = 9.81 * rec.at(double(i) * rec.dt());
  const std::vector<double> p = periods();
  for (auto _ : state)
    for (double T : p) benchmark::DoNotOptimize(sample_only_sd(ag, rec.dt(), T));
  // The floor misses the peaks between samples: how far below the exact spectrum it stays.
  const std::vector<SpectralOrdinate> exact = response_spectrum(rec, p, kDamping);
  double worst = 0;
  for (std::size_t k = 0; k < p.size(); ++k)
    worst = std::fmax(worst, std::fabs(sample_only_sd(ag, rec.dt(), p[k]) - exact[k].sd) / exact[k].sd);
  state.counters["max_rel_sd_below_exact"] = worst;
  state.counters["ns_per_sample_period"] = benchmark::Counter(
      double(kSamples) * kPeriods, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SpectrumSampleOnlyFloor)->Unit(benchmark::kMillisecond);

}  // namespace
