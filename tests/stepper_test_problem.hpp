// SPDX-License-Identifier: Apache-2.0
#pragma once
// The test problem of the Runge-Kutta steppers (Dopri5, Dop853): y0' = y0 cos t (y0 = exp(sin t))
// and y1'' = -y1 (y1 = cos t as the first-order pair y1, y2), with its exact solution; a stepper
// whose error estimate is the plain absolute error, and the global error of fixed steps.
#include <cmath>
#include <initializer_list>
#include <vector>

#include <gtest/gtest.h>

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

// The observed orders log2(e[i-1] / e[i]) of errors at halved steps, each in (lo, hi) (no upper
// bound when hi is infinite).
inline void expect_orders(const std::vector<double>& e, double lo, double hi, const char* what) {
  for (std::size_t i = 1; i < e.size(); ++i) {
    const double order = std::log2(e[i - 1] / e[i]);
    EXPECT_GT(order, lo) << what << " " << i;
    if (std::isfinite(hi)) {
      EXPECT_LT(order, hi) << what << " " << i;
    }
  }
}

// The error estimate of one step of each size from the exact value at t = 1.
template <class Stepper>
std::vector<double> step_estimates(std::initializer_list<double> steps) {
  std::vector<double> est;
  for (double h : steps) {
    Stepper st = absolute_stepper<Stepper>();
    blockdyn::StepperStats stats;
    Vec<kN> y = exact(1.0), k1, k_end, y1;
    rhs(1.0, y, k1);
    est.push_back(st.attempt(rhs, 1.0, h, y, k1, y1, k_end, stats));
  }
  return est;
}

// One step from the exact value at t0: its end y1 and rates; the last stage is the next step's
// first (FSAL).
template <class Stepper>
struct OneStep {
  Stepper st = absolute_stepper<Stepper>();
  blockdyn::StepperStats stats;
  Vec<kN> y, k1, k_end, y1;
  OneStep(double t0, double h) : y(exact(t0)) {
    rhs(t0, y, k1);
    st.attempt(rhs, t0, h, y, k1, y1, k_end, stats);
    Vec<kN> k_check;
    rhs(t0 + h, y1, k_check);
    for (std::size_t i = 0; i < kN; ++i) EXPECT_EQ(k_end[i], k_check[i]);  // FSAL
  }
};

// A dense segment reproduces the step's start exactly and its end to rounding.
inline void expect_segment_ends(const blockdyn::DenseSegment<kN>& seg, double t0, double h, const Vec<kN>& y,
                                const Vec<kN>& y1) {
  Vec<kN> ym, ye;
  seg.eval(t0, ym);
  for (std::size_t i = 0; i < kN; ++i) EXPECT_EQ(ym[i], y[i]);
  seg.eval(t0 + h, ye);
  for (std::size_t i = 0; i < kN; ++i) EXPECT_NEAR(ye[i], y1[i], 1e-15 * (1 + std::fabs(y1[i])));
}

}  // namespace stepper_test
