// SPDX-License-Identifier: Apache-2.0
#pragma once
// Dormand-Prince 5(4) embedded Runge-Kutta pair with FSAL and the order-4 continuous
// extension of Hairer, Norsett & Wanner (Solving ODEs I, sec. II.6). Fixed-size state,
// no allocation: everything lives in std::array members.
//
// Step-size control constants (Hairer & Wanner, IV.2): error exponent 1/5 with the PI term.
#include <array>
#include <cmath>
#include <cstddef>

#include "blockdyn/integrate/dense_segment.hpp"

namespace blockdyn {

// Tableau (Dormand & Prince 1980) and dense-output weights (Shampine / Hairer).
namespace dp5 {
inline constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
inline constexpr double a21 = 1.0 / 5;
inline constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
inline constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
inline constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
inline constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                        a65 = -5103.0 / 18656;
inline constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784, a76 = 11.0 / 84;
inline constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                        e6 = 22.0 / 525, e7 = -1.0 / 40;
inline constexpr double d1 = -12715105075.0 / 11282082432, d3 = 87487479700.0 / 32700410799,
                        d4 = -10690763975.0 / 1880347072, d5 = 701980252875.0 / 199316789632,
                        d6 = -1453857185.0 / 822651844, d7 = 69997945.0 / 29380423;
}  // namespace dp5

// One attempted step. `Rhs` is a callable (t, y, dy). k1 must hold f(t, y) on entry (FSAL).
// On return y_new, k7 = f(t+h, y_new), err = scaled RMS error norm.
template <std::size_t N>
class Dopri5 {
 public:
  static constexpr double kAlpha = 0.17;  // PI control: err^-alpha * err_old^beta (0.2 - 0.75 beta)
  static constexpr double kBeta = 0.04;
  static constexpr double kOrderExponent = 0.2;          // 1 / (order of the error estimate + 1)
  static constexpr double kFacMin = 0.2, kFacMax = 5.0;  // bounds of one step-size change
  Vec<N> atol{}, rtol{};

  template <class Rhs>
  double attempt(Rhs&& f, double t, double h, const Vec<N>& y, const Vec<N>& k1, Vec<N>& y_new, Vec<N>& k7,
                 StepperStats& st) {
    using namespace dp5;
    Vec<N> tmp;
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * a21 * k1[i];
    f(t + c2 * h, tmp, k2_);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (a31 * k1[i] + a32 * k2_[i]);
    f(t + c3 * h, tmp, k3_);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (a41 * k1[i] + a42 * k2_[i] + a43 * k3_[i]);
    f(t + c4 * h, tmp, k4_);
    for (std::size_t i = 0; i < N; ++i) tmp[i] = y[i] + h * (a51 * k1[i] + a52 * k2_[i] + a53 * k3_[i] + a54 * k4_[i]);
    f(t + c5 * h, tmp, k5_);
    for (std::size_t i = 0; i < N; ++i)
      tmp[i] = y[i] + h * (a61 * k1[i] + a62 * k2_[i] + a63 * k3_[i] + a64 * k4_[i] + a65 * k5_[i]);
    f(t + h, tmp, k6_);
    for (std::size_t i = 0; i < N; ++i)
      y_new[i] = y[i] + h * (a71 * k1[i] + a73 * k3_[i] + a74 * k4_[i] + a75 * k5_[i] + a76 * k6_[i]);
    f(t + h, y_new, k7);
    st.rhs_evals += 6;
    double sum = 0.0;
    for (std::size_t i = 0; i < N; ++i) {
      const double e = h * (e1 * k1[i] + e3 * k3_[i] + e4 * k4_[i] + e5 * k5_[i] + e6 * k6_[i] + e7 * k7[i]);
      const double sc = atol[i] + rtol[i] * std::fmax(std::fabs(y[i]), std::fabs(y_new[i]));
      const double q = e / sc;
      sum += q * q;
    }
    return std::sqrt(sum / N);
  }

  // Fill the dense-output coefficients of the step just attempted (call only if accepted).
  void dense(double t, double h, const Vec<N>& y, const Vec<N>& y_new, const Vec<N>& k1, const Vec<N>& k7,
             DenseSegment<N>& seg) const {
    using namespace dp5;
    seg.set_hermite(t, h, 5, y, y_new, k1, k7);
    for (std::size_t i = 0; i < N; ++i)
      seg.r[4][i] = h * (d1 * k1[i] + d3 * k3_[i] + d4 * k4_[i] + d5 * k5_[i] + d6 * k6_[i] + d7 * k7[i]);
  }
  // The same with the integrator's common signature (this extension needs no further stages).
  template <class Rhs>
  void dense(Rhs&&, double t, double h, const Vec<N>& y, const Vec<N>& y_new, const Vec<N>& k1, const Vec<N>& k7,
             DenseSegment<N>& seg, StepperStats&) const {
    dense(t, h, y, y_new, k1, k7, seg);
  }

 private:
  Vec<N> k2_{}, k3_{}, k4_{}, k5_{}, k6_{};
};

}  // namespace blockdyn
