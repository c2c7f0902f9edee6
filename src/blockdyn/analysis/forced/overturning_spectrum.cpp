// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/overturning_spectrum.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "blockdyn/analysis/sweep/parallel_map.hpp"

namespace blockdyn {

void validate(const SpectrumOptions& o) {
  if (o.durations.empty() || o.durations.size() > 100000)
    throw std::invalid_argument("durations: 1 to 100000 values are needed");
  for (double d : o.durations)
    if (!(d > 0 && d <= 1e4)) throw std::invalid_argument("duration = " + number_text(d) + " must be in (0, 1e4] s");
  if (!(o.amplitude_min > 0 && o.amplitude_max > o.amplitude_min && o.amplitude_max <= 1e3))
    throw std::invalid_argument("amplitude-min, amplitude-max: need 0 < min < max <= 1000 g");
  if (!(o.scan_points >= 2 && o.scan_points <= 100000))
    throw std::invalid_argument("scan-points must be in [2, 100000]");
  if (!(o.rel_tol >= 1e-12 && o.rel_tol <= 0.1)) throw std::invalid_argument("rel-tol must be in [1e-12, 0.1]");
}

double rect_pulse_overturning_linear(double alpha, double p, double t_p) { return alpha / (1.0 - std::exp(-p * t_p)); }

std::vector<double> scan_amplitudes(const SpectrumOptions& o) {
  const int n = o.scan_points;
  std::vector<double> amp(n);
  for (int j = 0; j < n; ++j)
    amp[j] = o.amplitude_min * std::pow(o.amplitude_max / o.amplitude_min, double(j) / (n - 1));
  return amp;
}

SpectrumRow spectrum_row(const OverturnTest& overturns, const SpectrumOptions& o, double duration) {
  SpectrumRow row;
  row.duration = duration;
  const int n = o.scan_points;
  const std::vector<double> amp = scan_amplitudes(o);
  std::vector<char>& over = row.scan;
  over.resize(n);
  for (int j = 0; j < n; ++j) {
    over[j] = char(overturns(amp[j], duration));
    row.outside_model += over[j] == kOutsideModel;
    ++row.runs;
  }
  int k = 0;
  while (k < n && over[k] != kOverturns) ++k;
  if (k == n) return row;
  if (k == 0) {
    row.at_scan_floor = true;
    row.min_overturning_amplitude = amp[0];
  } else {
    double lo = amp[k - 1], hi = amp[k];
    while ((hi - lo) > o.rel_tol * hi) {
      const double mid = std::sqrt(lo * hi);
      const int o_mid = overturns(mid, duration);
      ++row.runs;
      if (o_mid == kOutsideModel) {
        // The model cannot decide here: the bracket stops narrowing, hi stays an upper bound.
        ++row.outside_model;
        ++row.bisection_outside_model;
        break;
      }
      (o_mid == kOverturns ? hi : lo) = mid;
    }
    row.min_overturning_amplitude = hi;
  }
  row.upper_bound = row.bisection_outside_model > 0;
  for (int j = 0; j < k; ++j) row.upper_bound = row.upper_bound || over[j] == kOutsideModel;
  // Safe islands: runs of scanned amplitudes that survive (a run outside the model is no island).
  for (int j = k + 1; j < n; ++j) {
    if (over[j] != kSurvives) continue;
    SpectrumIsland is{amp[j], amp[j]};
    while (j + 1 < n && over[j + 1] == kSurvives) is.to = amp[++j];
    row.safe_islands.push_back(is);
  }
  return row;
}

std::vector<SpectrumRow> overturning_spectrum(const OverturnTest& overturns, const SpectrumOptions& o,
                                              const std::function<void(std::size_t)>& progress) {
  validate(o);
  std::vector<SpectrumRow> rows(o.durations.size());
  std::size_t done = 0;
  parallel_for(
      rows.size(), o.threads, [&](std::size_t i) { rows[i] = spectrum_row(overturns, o, o.durations[i]); },
      [&](std::size_t) {
        ++done;
        if (progress) progress(done);
      });
  return rows;
}

}  // namespace blockdyn
