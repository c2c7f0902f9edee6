// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/analysis/forced/linear_rocking_orbits.hpp"

#include <cmath>
#include <stdexcept>

namespace blockdyn {

std::array<std::complex<double>, 2> eigenvalues2(double a, double b, double c, double d) {
  const double tr = a + d, det = a * d - b * c;
  const double disc = 0.25 * tr * tr - det;
  if (disc >= 0) {
    const double r = std::sqrt(disc);
    // The larger-modulus root first, the other from the determinant (no cancellation).
    const double l1 = 0.5 * tr + (tr >= 0 ? r : -r);
    const double l2 = l1 != 0.0 ? det / l1 : 0.5 * tr - (tr >= 0 ? r : -r);
    return {std::complex<double>(l1, 0.0), std::complex<double>(l2, 0.0)};
  }
  const double im = std::sqrt(-disc);
  return {std::complex<double>(0.5 * tr, im), std::complex<double>(0.5 * tr, -im)};
}

namespace {

void check(double omega, double e, int n) {
  if (!(omega > 0) || !std::isfinite(omega)) throw std::invalid_argument("omega must be finite and > 0");
  if (!(e >= 0 && e <= 1)) throw std::invalid_argument("restitution must be in [0, 1]");
  if (n < 1 || n % 2 == 0) throw std::invalid_argument("n must be odd and >= 1 for a symmetric orbit");
}

}  // namespace

double linear_symmetric_fold_beta(double omega, double e, int n) {
  check(omega, e, n);
  const double sigma = n * M_PI / omega, ch = std::cosh(sigma), sh = std::sinh(sigma);
  const double a = (1 + ch) * (1 + e), b = omega * sh * (1 - e);
  return (ch - 1) * (1 - e) * (1 + omega * omega) / std::hypot(a, b);
}

std::vector<LinearRockingOrbit> linear_symmetric_orbits(double beta, double omega, double e, int n) {
  check(omega, e, n);
  std::vector<LinearRockingOrbit> out;
  if (!(beta > 0)) return out;
  const double sigma = n * M_PI / omega, ch = std::cosh(sigma), sh = std::sinh(sigma);
  const double B = beta / (1 + omega * omega);
  const double a = (1 + ch) * (1 + e), b = omega * sh * (1 - e), c = (ch - 1) * (1 - e) / B;
  const double R = std::hypot(a, b);
  if (std::fabs(c) > R) return out;
  const double psi = std::atan2(b, a), as = std::asin(c / R);
  for (double phi : {as - psi, M_PI - as - psi}) {
    LinearRockingOrbit o;
    o.phase = std::fmod(phi, 2 * M_PI);
    if (o.phase < 0) o.phase += 2 * M_PI;
    const double S = std::sin(o.phase), C = std::cos(o.phase);
    o.velocity = ((ch - 1) - B * S * (1 + ch) - B * omega * C * sh) / sh;
    // x > 0 strictly inside (0, sigma): sampled finely (the arcs are smooth, of a few humps at most).
    const double C1 = B * S - 1, C2 = o.velocity + B * omega * C;
    bool inside = o.velocity > 0;
    const int samples = 4000;
    for (int k = 1; k < samples && inside; ++k) {
      const double s = sigma * k / samples;
      const double x = 1 + C1 * std::cosh(s) + C2 * std::sinh(s) - B * std::sin(omega * s + o.phase);
      o.max_x = std::fmax(o.max_x, x);
      if (x <= 0) inside = false;
    }
    o.valid = inside;
    const double vm = -o.velocity / e;  // x' just before the second impact
    const double am = -1 - beta * S, ap = 1 - beta * S;
    const double s21 = e > 0 ? (ap - e * am) / vm : 0.0;
    // H = -S Phi, S = [[e, 0], [s21, e]], Phi = [[ch, sh], [sh, ch]].
    const double h11 = -(e * ch), h12 = -(e * sh);
    const double h21 = -(s21 * ch + e * sh), h22 = -(s21 * sh + e * ch);
    o.half_multipliers = eigenvalues2(h11, h12, h21, h22);
    for (int k = 0; k < 2; ++k) o.multipliers[k] = o.half_multipliers[k] * o.half_multipliers[k];
    out.push_back(o);
  }
  return out;
}

}  // namespace blockdyn
