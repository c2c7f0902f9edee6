// SPDX-License-Identifier: Apache-2.0
#pragma once
// Independent references for the rigid-ground models, computed from first integrals of the exact
// (nonlinear) Housner equation by double-exponential quadrature (Boost tanh_sinh), not by the
// simulator. All SI; alpha the slenderness angle, p the frequency parameter.
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/math/tools/roots.hpp>

#include <cmath>
#include <vector>

namespace blockdyn::test {

// Free rocking released from rest at amplitude a (0 < a < alpha): time to reach theta = 0.
// From energy: theta'^2 = 2 p^2 (cos(alpha - a) - cos(alpha - theta)), so
//   tau(a) = int_0^a dtheta / (p sqrt(2 (cos(alpha - a) - cos(alpha - theta)))),
// with cos(alpha - a) - cos(alpha - theta) = 2 sin((a - theta)/2) sin(alpha - (a + theta)/2)
// written without cancellation near the singular end theta = a.
inline double housner_quarter_swing(double alpha, double p, double a) {
  boost::math::quadrature::tanh_sinh<double> q;
  auto f = [&](double th, double xc) {
    // xc = a - th on the right half (exact near the singular end theta = a).
    const double d = (th > 0.5 * a) ? xc : a - th;
    const double diff = 2.0 * std::sin(0.5 * d) * std::sin(alpha - 0.5 * (a + th));
    return 1.0 / (p * std::sqrt(2.0 * diff));
  };
  return q.integrate(f, 0.0, a);
}

// Amplitude reached after leaving theta = 0 with rate w (energy): cos(alpha - a) = cos(alpha) + w^2/(2 p^2).
inline double housner_amplitude(double alpha, double p, double w) {
  return alpha - std::acos(std::cos(alpha) + w * w / (2.0 * p * p));
}

// Rate at theta = 0 of a swing of amplitude a.
inline double housner_rate_at_zero(double alpha, double p, double a) {
  return p * std::sqrt(2.0 * (std::cos(alpha - a) - std::cos(alpha)));
}

struct ImpactRef {
  double t, w_before, w_after;  // |theta'| before and after
};

// The first n impacts of free rocking from rest at theta0 with restitution e.
inline std::vector<ImpactRef> housner_free_impacts(double alpha, double p, double theta0, double e, int n) {
  std::vector<ImpactRef> out;
  double t = housner_quarter_swing(alpha, p, theta0);
  double w = housner_rate_at_zero(alpha, p, theta0);
  for (int k = 0; k < n; ++k) {
    out.push_back({t, w, e * w});
    w *= e;
    t += 2.0 * housner_quarter_swing(alpha, p, housner_amplitude(alpha, p, w));
  }
  return out;
}

// Time at which free rocking from theta0 comes to rest (the accumulation point of its impacts).
inline double housner_rest_time(double alpha, double p, double theta0, double e) {
  double t = housner_quarter_swing(alpha, p, theta0);
  double w = housner_rate_at_zero(alpha, p, theta0);
  for (int k = 0; k < 100000 && w > 1e-14 * p; ++k) {
    w *= e;
    const double a = housner_amplitude(alpha, p, w);
    if (!(a > 0)) break;
    // For tiny amplitudes the swing is ballistic: 2 w / (p^2 sin alpha); sum the geometric tail.
    if (a < 1e-9 * alpha) {
      t += 2.0 * w / (p * p * std::sin(alpha)) / (1.0 - e);
      break;
    }
    t += 2.0 * housner_quarter_swing(alpha, p, a);
  }
  return t;
}

// Rectangular pulse a_H = A g on [0, tp] from rest (A > tan alpha): does the block overturn?
// During the pulse psi = theta - (alpha - beta), beta = atan A, obeys psi'' = K sin psi with
// K = p^2 sqrt(1 + A^2), so theta'^2 = 2 K (cos psi0 - cos psi), psi0 = beta - alpha. The time to
// reach theta is a quadrature; theta(tp) follows by root finding. Afterwards the free block
// overturns iff its energy exceeds the barrier at theta = alpha: theta'^2 >= 2 p^2 (1 - cos(alpha - theta)).
inline bool housner_rect_pulse_overturns(double alpha, double p, double A, double tp) {
  if (A <= std::tan(alpha)) return false;  // never uplifts
  const double beta = std::atan(A), K = p * p * std::sqrt(1.0 + A * A), psi0 = beta - alpha;
  auto rate = [&](double th) {  // theta' at theta during the pulse (psi = psi0 + theta)
    const double diff = 2.0 * std::sin(0.5 * th) * std::sin(psi0 + 0.5 * th);
    return std::sqrt(2.0 * K * diff);
  };
  boost::math::quadrature::tanh_sinh<double> q;
  auto time_to = [&](double th) {
    // Near theta = 0 the rate grows like sqrt(theta); with theta = u^2 the integrand
    // 2 u / rate(u^2) is regular.
    // 2 u / rate(u^2) = 2 / sqrt(2 K sinc(v) sin(psi0 + v/2)), v = u^2, sinc(v) = 2 sin(v/2) / v.
    auto integrand = [&](double u) {
      const double v = u * u;
      const double sinc = v > 0.0 ? 2.0 * std::sin(0.5 * v) / v : 1.0;
      return 2.0 / std::sqrt(2.0 * K * sinc * std::sin(psi0 + 0.5 * v));
    };
    return q.integrate(integrand, 0.0, std::sqrt(th));
  };
  // theta(tp): the block passes pi/2 during the pulse if time_to(pi/2) <= tp.
  const double th_max = 0.5 * M_PI - 1e-9;
  if (time_to(th_max) <= tp) return true;
  std::uintmax_t it = 200;
  auto r = boost::math::tools::bisect([&](double th) { return time_to(th) - tp; }, 1e-300, th_max,
                                      boost::math::tools::eps_tolerance<double>(50), it);
  const double th = 0.5 * (r.first + r.second);
  if (th >= alpha) return true;  // beyond alpha when the pulse ends: falls over
  const double w = rate(th);
  return w * w >= 2.0 * p * p * (1.0 - std::cos(alpha - th));
}

// Smallest rectangular-pulse amplitude A (in g) that overturns the block (monotone in A).
inline double housner_rect_pulse_threshold(double alpha, double p, double tp) {
  double lo = std::tan(alpha), hi = 2.0 * std::tan(alpha);
  while (!housner_rect_pulse_overturns(alpha, p, hi, tp)) hi *= 2.0;
  std::uintmax_t it = 200;
  auto r =
      boost::math::tools::bisect([&](double A) { return housner_rect_pulse_overturns(alpha, p, A, tp) ? 1.0 : -1.0; },
                                 lo, hi, boost::math::tools::eps_tolerance<double>(45), it);
  return 0.5 * (r.first + r.second);
}

}  // namespace blockdyn::test
