// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/disc_slide.hpp"

#include <cmath>

#include "blockdyn/model/rigid3d/body_pivot.hpp"
#include "blockdyn/model/rigid3d/slip_reference.hpp"

namespace blockdyn {

namespace {

// Three complete integrals over theta in [0, pi/2] with x = k^2 (k the modulus), by their
// series where the closed forms in K(k) and E(k) would cancel (x below kSeriesUpTo; 40 terms
// leave below 1e-21 there), else by the closed forms:
//   C(x) = int cos^2 sqrt(1 - x sin^2) = ((1 + x) E - (1 - x) K) / (3 x)
//   D(x) = int (1 - x sin^2)^(3/2)     = (2 (2 - x) E - (1 - x) K) / 3
//   H(x) = int cos^4 / sqrt(1 - x sin^2) = K - 2 (K - E) / x + ((2 + x) K - 2 (1 + x) E) / (3 x^2)
constexpr double kSeriesUpTo = 0.3;
constexpr int kSeriesTerms = 40;
// At x = 1 (the slip's centre on the rim) K is infinite, (1 - x) K zero, and all three are 2/3.
constexpr double kAtRim = 2.0 / 3;

// sum_n c_n x^n m_n: c_n the binomial series of (1 - y)^p, m_n = int cos^(2q) sin^(2n) (the
// recursion m_n = m_(n-1) (2n - 1) / (2n + 2q), m_0 = int cos^(2q)).
double binomial_series(double x, double p, int q, double m0) {
  double c = 1, m = m0, xn = 1, sum = m0;
  for (int n = 1; n < kSeriesTerms; ++n) {
    c *= (n - 1 - p) / n;
    m *= (2.0 * n - 1) / (2.0 * n + 2 * q);
    xn *= x;
    sum += c * xn * m;
  }
  return sum;
}

double ellint_c(double x) {
  if (x >= 1) return kAtRim;
  if (x < kSeriesUpTo) return binomial_series(x, 0.5, 1, M_PI / 4);
  const double k = std::sqrt(x), e = std::comp_ellint_2(k), kk = std::comp_ellint_1(k);
  return ((1 + x) * e - (1 - x) * kk) / (3 * x);
}

double ellint_d(double x) {
  if (x >= 1) return kAtRim;
  const double k = std::sqrt(x), e = std::comp_ellint_2(k), kk = std::comp_ellint_1(k);
  return (2 * (2 - x) * e - (1 - x) * kk) / 3;
}

double ellint_h(double x) {
  if (x >= 1) return kAtRim;
  if (x < kSeriesUpTo) return binomial_series(x, -0.5, 2, 3 * M_PI / 16);
  const double k = std::sqrt(x), e = std::comp_ellint_2(k), kk = std::comp_ellint_1(k);
  return kk - 2 * (kk - e) / x + ((2 + x) * kk - 2 * (1 + x) * e) / (3 * x * x);
}

// The unit disc whose points slip about the centre (d, 0): each point's friction direction is
// Z x e, e the unit vector from the centre to it. Returns int e_x dA and int r . e dA. Along a ray
// from the centre (inside, d < 1: rho to R = -d cos(phi) + sqrt(1 - d^2 sin^2 phi)) or across a
// chord (outside: the chord at psi, sin(psi) = sin(theta) / d, half length cos(theta), r . e
// measured along it) e is constant and the ray's integral a polynomial's; what is left is
//   inside:  int e_x = -4 d C(d^2),   int r . e = (4/3) D(d^2),
//   outside: int e_x = -4 C(1/d^2),   int r . e = 4 H(1/d^2) / (3 d)   (docs/3d.md).
struct CentreIntegrals {
  double ex = 0, radial = 0;
};

CentreIntegrals centre_integrals(double d) {
  if (d < 1) return {-4 * d * ellint_c(d * d), 4 * ellint_d(d * d) / 3};
  const double x = 1 / (d * d);
  return {-4 * ellint_c(x), 4 * ellint_h(x) / (3 * d)};
}

Vec3 unit_or_zero(const Vec3& v) {
  const double n = std::hypot(v[0], v[1]);
  return n > 0 ? Vec3{v[0] / n, v[1] / n, 0} : Vec3{0, 0, 0};
}

// The slip at the base point p for the slip field (v, omega), and its direction.
Vec3 slip_at(const Vec3& v, double omega, const Vec3& p) { return {v[0] - omega * p[1], v[1] + omega * p[0], 0}; }
Vec3 point_direction(const Vec3& v, double omega, const Vec3& p) { return unit_or_zero(slip_at(v, omega, p)); }

}  // namespace

DiscFrictionField disc_friction_field(double a, const Vec3& v, double omega) {
  const double speed = std::hypot(v[0], v[1]);
  DiscFrictionField out;
  if (!(std::fabs(omega) > 0)) {
    out.mean_direction = unit_or_zero(v);
    return out;
  }
  // The slip's centre lies at Z x v / omega, d a from the base's centre.
  const double d = speed / (std::fabs(omega) * a);
  const CentreIntegrals c = centre_integrals(d);
  // By the symmetry about the line through both centres the mean direction lies along v.
  const double along = speed > 0 ? -c.ex / M_PI : 0.0;
  out.mean_direction = scaled(unit_or_zero(v), along);
  out.mean_twist = std::copysign(c.radial / M_PI, omega);
  return out;
}

namespace {

// The resultant's offset E (in a) solving E = k ((1 - |E|) g + |E| u(a E / |E|)), k = c mu / a,
// by Newton's method from the pure slide's root k g.
Vec3 resultant_offset(double a, double k, const Vec3& g, const Vec3& v, double omega) {
  Vec3 e = scaled(g, k);
  if (!(std::hypot(e[0], e[1]) > 0)) return {0, 0, 0};
  for (int it = 0; it < 50; ++it) {
    const double w = std::hypot(e[0], e[1]);
    const Vec3 eh = {e[0] / w, e[1] / w, 0};
    const Vec3 slip = slip_at(v, omega, scaled(eh, a));
    const double sn = std::hypot(slip[0], slip[1]);
    const Vec3 u = unit_or_zero(slip);
    const double rx = k * ((1 - w) * g[0] + w * u[0]) - e[0];
    const double ry = k * ((1 - w) * g[1] + w * u[1]) - e[1];
    // d(residual)/dE = k ((u - g) eh^T + a omega (I - u u^T) J (I - eh eh^T) / |slip|) - I, J = Z x;
    // in 2D I - u u^T = n n^T (n = J u) and J (I - eh eh^T) = -eh t^T (t = J eh): the second term
    // is -(a omega / |slip|) (n . eh) n t^T.
    double j[2][2] = {{k * (u[0] - g[0]) * eh[0], k * (u[0] - g[0]) * eh[1]},
                      {k * (u[1] - g[1]) * eh[0], k * (u[1] - g[1]) * eh[1]}};
    if (sn > 0) {
      const double n[2] = {-u[1], u[0]}, t[2] = {-eh[1], eh[0]};
      const double f = -k * a * omega / sn * (n[0] * eh[0] + n[1] * eh[1]);
      for (int r = 0; r < 2; ++r)
        for (int c = 0; c < 2; ++c) j[r][c] += f * n[r] * t[c];
    }
    j[0][0] -= 1;
    j[1][1] -= 1;
    const double det = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    if (!(std::fabs(det) > 0)) break;
    const double dx = -(j[1][1] * rx - j[0][1] * ry) / det, dy = -(-j[1][0] * rx + j[0][0] * ry) / det;
    e = {e[0] + dx, e[1] + dy, 0};
    if (std::hypot(dx, dy) <= 1e-15 * (1 + std::hypot(e[0], e[1]))) break;
  }
  return e;
}

}  // namespace

DiscSlide disc_slide(double a, double c, double mass, double inertia_z, double mu_k, const Vec3& v, double omega_z,
                     const Vec3& f, const Vec3& reference, double noise) {
  // The slip field whose directions the friction takes (slip_reference.hpp): the generalised
  // slip's, reversed past its reversal, turning to the reference's within the noise.
  const Vec3 d = slip_reference::friction_direction({v[0], v[1], a * omega_z}, reference, noise);
  const Vec3 fv = {d[0], d[1], 0};
  const double fw = d[2] / a;
  const DiscFrictionField field = disc_friction_field(a, fv, fw);
  DiscSlide s;
  s.load = -mass * f[2];
  s.offset = resultant_offset(a, c * mu_k / a, field.mean_direction, fv, fw);
  const double w = std::hypot(s.offset[0], s.offset[1]);
  const Vec3 eh = w > 0 ? scaled(s.offset, 1 / w) : Vec3{0, 0, 0};
  const Vec3 u = point_direction(fv, fw, scaled(eh, a));
  const double mun = mu_k * s.load;
  s.friction = {-mun * ((1 - w) * field.mean_direction[0] + w * u[0]),
                -mun * ((1 - w) * field.mean_direction[1] + w * u[1]), 0};
  s.torque = -mun * a * ((1 - w) * field.mean_twist + w * (eh[0] * u[1] - eh[1] * u[0]));
  s.accel = {f[0] + s.friction[0] / mass, f[1] + s.friction[1] / mass, 0};
  s.spin_accel = s.torque / inertia_z;
  s.friction_power = s.friction[0] * v[0] + s.friction[1] * v[1] + s.torque * omega_z;
  return s;
}

}  // namespace blockdyn
