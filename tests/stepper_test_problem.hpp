// SPDX-License-Identifier: Apache-2.0
#pragma once
// The test problem of the Runge-Kutta steppers (Dopri5, Dop853): y0' = y0 cos t (y0 = exp(sin t))
// and y1'' = -y1 (y1 = cos t as the first-order pair y1, y2), with its exact solution; a stepper
// whose error estimate is the plain absolute error, and the global error of fixed steps.
#include <cmath>

#include "blockdyn/integrate/hybrid_integrator.hpp"

namespace stepper_test {

using blockdyn::Vec;
constexpr std::size_t kN = 3;

inline void rhs(double t, const Vec<kN>& y, Vec<kN>& dy) {
  dy[0] = y[0] * std::cos(t);
  dy[1] = y[2];
  dy[2] = -y[1];
}
inline Vec<kN> exact(double t) { return {std::exp(std::sin(t)), std::cos(t), -std::sin(t)}; }

inline double max_err(const Vec<kN>& a, const Vec<kN>& b) {
  double e = 0;
  for (std::size_t i = 0; i < kN; ++i) e = std::fmax(e, std::fabs(a[i] - b[i]));
  return e;
}

// A stepper whose error estimate is the plain absolute error (atol 1, rtol 0).
template <class Stepper>
Stepper absolute_stepper() {
  Stepper st;
  st.atol.fill(1.0);
  st.rtol.fill(0.0);
  return st;
}

// Fixed-step integration over [0, T] in n steps; the error estimate is ignored.
template <class Stepper>
double global_error(int n, double T) {
  Stepper st = absolute_stepper<Stepper>();
  blockdyn::StepperStats stats;
  Vec<kN> y = exact(0), k1, k_end, y1;
  rhs(0, y, k1);
  const double h = T / n;
  for (int i = 0; i < n; ++i) {
    st.attempt(rhs, i * h, h, y, k1, y1, k_end, stats);
    y = y1;
    k1 = k_end;
  }
  return max_err(y, exact(T));
}

}  // namespace stepper_test
