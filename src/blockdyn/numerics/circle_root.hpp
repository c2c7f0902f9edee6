// SPDX-License-Identifier: Apache-2.0
#pragma once
// The root of a function of an angle nearest a given angle on the circle: the slip directions of
// the contact problems (a point's slip at an impact, numerics/spatial_contact.cpp; a point starting
// to slip, model/rigid3d/slip_reference.hpp) are roots of d x u(d), looked for this way.
#include <algorithm>
#include <array>
#include <cmath>

namespace blockdyn {

// One angle's sample: the function's value, and whether a sign change there may count (a sample
// outside the function's domain brackets nothing).
struct CircleSample {
  double value = 0;
  bool usable = true;
};

struct CircleRootScan {
  int samples = 72;          // angles phi0 + 2 pi k / samples, k = 0 .. samples
  int bisections = 60;       // at most, each stopping at adjacent doubles
  double min_width = 1e-16;  // or at this width
};

inline constexpr int kMaxCircleSamples = 128;

// The angle nearest phi0 (along the circle, either way) at which `sample(phi).value` changes sign
// between two usable samples, refined by bisection, and that `accept(root)` takes; NaN if none.
// Intervals are looked at nearest phi0 first (k = 1, N, 2, N - 1, ...), and no further once they
// lie farther than the best root found; ties go to the smaller k (as a scan in order has them).
template <class Sample, class Accept>
double nearest_circle_root(double phi0, const CircleRootScan& scan, Sample&& sample, Accept&& accept) {
  const int n = std::min(scan.samples, kMaxCircleSamples);
  auto angle = [&](int k) { return phi0 + 2 * M_PI * k / n; };
  std::array<CircleSample, kMaxCircleSamples + 1> at{};
  std::array<bool, kMaxCircleSamples + 1> known{};
  auto sample_at = [&](int k) -> const CircleSample& {
    if (!known[std::size_t(k)]) {
      at[std::size_t(k)] = sample(angle(k));
      known[std::size_t(k)] = true;
    }
    return at[std::size_t(k)];
  };
  double best = NAN, best_gap = INFINITY;
  int best_k = 0;
  const double width = 2 * M_PI / n, margin = 1e-12;
  for (int step = 0; step < n; ++step) {
    const int k = step % 2 == 0 ? 1 + step / 2 : n - step / 2;
    if (std::min(k - 1, n - k) * width - margin > best_gap) break;
    const CircleSample lo_s = sample_at(k - 1), hi_s = sample_at(k);
    if (!lo_s.usable || !hi_s.usable || (lo_s.value <= 0) == (hi_s.value <= 0)) continue;
    double lo = angle(k - 1), hi = angle(k);
    const bool lo_neg = lo_s.value <= 0;
    for (int b = 0; b < scan.bisections && hi - lo > scan.min_width; ++b) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;  // adjacent doubles: nothing left to halve
      ((sample(mid).value <= 0) == lo_neg ? lo : hi) = mid;
    }
    const double root = 0.5 * (lo + hi);
    const double gap = std::fmin(root - phi0, phi0 + 2 * M_PI - root);
    if ((gap < best_gap || (gap == best_gap && k < best_k)) && accept(root)) {
      best = root;
      best_gap = gap;
      best_k = k;
    }
  }
  return best;
}

}  // namespace blockdyn
