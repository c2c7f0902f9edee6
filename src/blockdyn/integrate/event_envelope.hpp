// SPDX-License-Identifier: Apache-2.0
#pragma once
// A lower envelope of one event function over one accepted step, from what the step already
// knows: the function's values and time derivatives at both ends (the derivatives from the
// right-hand sides the step computed anyway) and its values at a few interior points of the
// dense output.
//
// With s = (t - t0) / h in [0, 1], the cubic Hermite interpolant H of the end values and rates
// differs from the function by a remainder that vanishes doubly at both ends:
//   g(s) = H(s) + s^2 (1 - s)^2 phi(s),   phi = g''''(xi) h^4 / 24  (smooth functions),
// so each interior sample measures phi at its point. The envelope takes phi no larger than the
// smallest value measured minus the largest magnitude measured (a factor-of-two margin on a
// quantity that varies by O(h / T) over a step resolving the time scale T) and subtracts a floor
// (a small fraction of the function's variation over the step, and the error of rates obtained
// by differences). Written in the degree-4 Bernstein basis, the envelope is positive on [0, 1]
// if its five coefficients are (convex hull property); de Casteljau subdivision narrows down
// where it may not be. Only there does the integrator search the dense output.
#include <array>
#include <cmath>
#include <cstddef>

namespace blockdyn {

// Bernstein coefficients (degree 4) of a polynomial on s in [0, 1].
using Bernstein4 = std::array<double, 5>;

// Value of a degree-4 Bernstein polynomial at s (de Casteljau).
inline double bernstein_value(const Bernstein4& c, double s) {
  Bernstein4 b = c;
  for (int r = 1; r <= 4; ++r)
    for (int k = 0; k <= 4 - r; ++k) b[k] = (1.0 - s) * b[k] + s * b[k + 1];
  return b[0];
}

// The same polynomial in the power basis, a0 + a1 s + ... + a4 s^4, for the grid searches that
// evaluate one model many times (Horner: four multiply-adds a point instead of ten).
struct Power4 {
  std::array<double, 5> a{};
  double operator()(double s) const { return a[0] + s * (a[1] + s * (a[2] + s * (a[3] + s * a[4]))); }
};

inline Power4 to_power(const Bernstein4& b) {
  const double d1 = b[1] - b[0], d2 = b[2] - 2.0 * b[1] + b[0];
  const double d3 = b[3] - 3.0 * b[2] + 3.0 * b[1] - b[0];
  const double d4 = b[4] - 4.0 * b[3] + 6.0 * b[2] - 4.0 * b[1] + b[0];
  return Power4{{b[0], 4.0 * d1, 6.0 * d2, 4.0 * d3, d4}};
}

// Split at s = 1/2 into the coefficients on [0, 1/2] and on [1/2, 1] (each rescaled to [0, 1]).
inline void bernstein_halves(const Bernstein4& c, Bernstein4& left, Bernstein4& right) {
  Bernstein4 b = c;
  left[0] = b[0];
  right[4] = b[4];
  for (int r = 1; r <= 4; ++r) {
    for (int k = 0; k <= 4 - r; ++k) b[k] = 0.5 * (b[k] + b[k + 1]);
    left[r] = b[0];
    right[4 - r] = b[4 - r];
  }
}

struct EventEnvelope {
  Bernstein4 lower{};          // the lower envelope
  Bernstein4 model{};          // the best estimate of g (Hermite + the mean measured remainder)
  bool start_at_zero = false;  // g(t0) <= 0 was taken as exactly 0 (a function that just fired)

  // Sufficient test that the envelope is positive on (0, 1] (on [0, 1] unless start_at_zero).
  bool positive() const { return positive(lower, start_at_zero); }

  static bool positive(const Bernstein4& c, bool zero_start) {
    if (!(zero_start ? c[0] >= 0.0 : c[0] > 0.0)) return false;
    for (std::size_t k = 1; k < 5; ++k)
      if (!(c[k] > 0.0)) return false;
    return true;
  }

  // The first interval [sa, sb] after `from` (a union of consecutive pieces of width 2^-depth)
  // on which the positivity test fails; false if there is none. The dense search is confined to
  // such intervals.
  bool next_doubtful(int depth, double from, double& sa, double& sb) const {
    sa = 2.0;
    sb = -1.0;
    scan(lower, 0.0, 1.0, depth, start_at_zero, from, sa, sb);
    return sa <= 1.0;
  }

 private:
  static void scan(const Bernstein4& c, double a, double b, int depth, bool zero_start, double from, double& sa,
                   double& sb) {
    if (b <= from) return;
    if (sb >= 0.0 && a > sb) return;  // past the first doubtful run: done
    if (positive(c, zero_start)) return;
    if (depth == 0) {
      if (sa > 1.0) sa = a;
      if (sb < 0.0 || a <= sb) sb = b;
      return;
    }
    Bernstein4 l, r;
    bernstein_halves(c, l, r);
    const double m = 0.5 * (a + b);
    scan(l, a, m, depth - 1, zero_start, from, sa, sb);
    if (sb >= 0.0 && sb < m) return;  // the doubtful run ended inside the left half
    scan(r, m, b, depth - 1, false, from, sa, sb);
  }
};

// Relative floor of the envelope: the fraction of the function's variation over the step by
// which it is lowered everywhere inside the step.
inline constexpr double kEnvelopeFloor = 1e-3;

// The envelope of g on one step of length h from g0, g1, the rates gd0, gd1 at its ends, the
// values gs[j] at interior points s[j] (n >= 1), and `rate_error`: a bound on the error of the
// rates (0 when they are exact).
inline EventEnvelope make_event_envelope(double g0, double gd0, double g1, double gd1, double h, const double* s,
                                         const double* gs, int n, double rate_error, bool start_at_zero) {
  EventEnvelope e;
  e.start_at_zero = start_at_zero;
  const double a0 = start_at_zero ? 0.0 : g0;
  const double b0 = a0, b1 = a0 + h * gd0 / 3.0, b2 = g1 - h * gd1 / 3.0, b3 = g1;
  // Remainder samples phi_j = (g(s_j) - H(s_j)) / (s_j^2 (1 - s_j)^2).
  double phi_min = INFINITY, phi_abs = 0.0, phi_sum = 0.0;
  for (int j = 0; j < n; ++j) {
    const double u = s[j], v = 1.0 - u;
    const double hermite = v * v * v * b0 + 3.0 * u * v * v * b1 + 3.0 * u * u * v * b2 + u * u * u * b3;
    const double w = u * u * v * v;
    const double phi = (gs[j] - hermite) / w;
    phi_min = std::fmin(phi_min, phi);
    phi_abs = std::fmax(phi_abs, std::fabs(phi));
    phi_sum += phi;
  }
  if (!std::isfinite(phi_min) || !std::isfinite(phi_abs)) phi_min = -INFINITY;
  const double phi_lo = phi_min - phi_abs;
  const double variation = std::fabs(b1 - b0) + std::fabs(b2 - b1) + std::fabs(b3 - b2) + phi_abs / 16.0;
  const double floor = kEnvelopeFloor * variation + h * rate_error / 3.0;
  // Degree elevation of the cubic; s^2 (1 - s)^2 is B_{2,4} / 6.
  const Bernstein4 cubic{b0, 0.25 * (b0 + 3.0 * b1), 0.5 * (b1 + b2), 0.25 * (3.0 * b2 + b3), b3};
  e.model = cubic;
  e.model[2] += (n > 0 ? phi_sum / n : 0.0) / 6.0;
  e.lower = cubic;
  e.lower[2] += phi_lo / 6.0;
  for (std::size_t k = 1; k < 4; ++k) e.lower[k] -= floor;
  return e;
}

// The same with no interior sample: the remainder |phi| <= phi_bound (measured on an earlier step).
inline EventEnvelope make_event_envelope_bounded(double g0, double gd0, double g1, double gd1, double h,
                                                 double phi_bound, double rate_error) {
  EventEnvelope e;
  const double b0 = g0, b1 = g0 + h * gd0 / 3.0, b2 = g1 - h * gd1 / 3.0, b3 = g1;
  const double variation = std::fabs(b1 - b0) + std::fabs(b2 - b1) + std::fabs(b3 - b2) + phi_bound / 16.0;
  const double floor = kEnvelopeFloor * variation + h * rate_error / 3.0;
  const Bernstein4 cubic{b0, 0.25 * (b0 + 3.0 * b1), 0.5 * (b1 + b2), 0.25 * (3.0 * b2 + b3), b3};
  e.model = cubic;
  e.lower = cubic;
  e.lower[2] -= phi_bound / 6.0;
  for (std::size_t k = 1; k < 4; ++k) e.lower[k] -= floor;
  return e;
}

}  // namespace blockdyn
