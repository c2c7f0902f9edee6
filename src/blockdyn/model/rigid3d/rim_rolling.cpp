// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/rim_rolling.hpp"

#include <cmath>

#include "blockdyn/model/rigid3d/body_pivot.hpp"

namespace blockdyn {

namespace {

// I^-1 v and I v for the world-frame inertia R diag(inertia) R^T.
Vec3 inertia_times(const Vec3& inertia, const Mat3& r, const Vec3& v, bool inverse) {
  const Vec3 b = transposed_times(r, v);
  return inverse ? r * Vec3{b[0] / inertia[0], b[1] / inertia[1], b[2] / inertia[2]}
                 : r * Vec3{b[0] * inertia[0], b[1] * inertia[1], b[2] * inertia[2]};
}

}  // namespace

Vec3 rim_lowest_point(double a, double c, const Mat3& r) {
  // The world's up in the body frame is R^T Z, the third row of R.
  const double ux = r[2][0], uy = r[2][1], rho = std::hypot(ux, uy);
  return {-a * ux / rho, -a * uy / rho, -c};
}

Vec3 rim_point_rate(double a, const Mat3& r, const Vec3& omega) {
  // u = R^T Z turns as du/dt = -Omega x u (Omega = R^T omega, the body-frame rate); the point
  // -a (ux, uy) / rho follows it.
  const Vec3 u{r[2][0], r[2][1], r[2][2]}, om = transposed_times(r, omega);
  const Vec3 du = scaled(cross(om, u), -1.0);
  const double rho2 = u[0] * u[0] + u[1] * u[1], rho = std::sqrt(rho2);
  const double radial = (u[0] * du[0] + u[1] * du[1]) / rho2;
  return {-a * (du[0] - u[0] * radial) / rho, -a * (du[1] - u[1] * radial) / rho, 0.0};
}

RimRolling rim_rolling_motion(const Vec3& inertia, double mass, double a, double c, const Mat3& r, const Vec3& omega,
                              const Vec3& f) {
  RimRolling m;
  m.contact_body = rim_lowest_point(a, c, r);
  const Vec3 arm = r * m.contact_body;
  m.arm = arm;
  const Vec3 spin = inertia_times(inertia, r, omega, false);
  const Vec3 gyro = inertia_times(inertia, r, cross(omega, spin), true);  // I^-1 (omega x I omega)
  const Vec3 travel = r * rim_point_rate(a, r, omega);
  // (1/m - [r]x I^-1 [r]x) F = -(f + r x I^-1 (omega x I omega) + omega x (omega x r) + omega x R p').
  Mat3 k{};
  for (int j = 0; j < 3; ++j) {
    const Vec3 e{j == 0 ? 1.0 : 0.0, j == 1 ? 1.0 : 0.0, j == 2 ? 1.0 : 0.0};
    const Vec3 col = minus(scaled(e, 1.0 / mass), cross(arm, inertia_times(inertia, r, cross(arm, e), true)));
    for (int i = 0; i < 3; ++i) k[i][j] = col[i];
  }
  const Vec3 rhs =
      scaled(plus(plus(f, cross(arm, gyro)), plus(cross(omega, cross(omega, arm)), cross(omega, travel))), -1.0);
  m.force = solve_matrix(k) * rhs;
  m.accel = plus(f, scaled(m.force, 1.0 / mass));
  m.domega = minus(inertia_times(inertia, r, cross(arm, m.force), true), gyro);
  return m;
}

RimSlip rim_slip_motion(const Vec3& inertia, double mass, double a, double c, const Mat3& r, const Vec3& v,
                        const Vec3& omega, const Vec3& f, double mu_k, const Vec3& d, const Vec3& side) {
  RimSlip m;
  const bool flat = rim_on_side(r, side);  // the contact does not travel
  m.contact_body = flat ? side : rim_lowest_point(a, c, r);
  const Vec3 arm = r * m.contact_body;
  m.arm = arm;
  const Vec3 spin = inertia_times(inertia, r, omega, false);
  const Vec3 alpha0 = scaled(inertia_times(inertia, r, cross(omega, spin), true), -1.0);
  const Vec3 travel = flat ? Vec3{0, 0, 0} : r * rim_point_rate(a, r, omega);
  // The contact's acceleration without a reaction, and per unit load along u = Z - mu_k d.
  const Vec3 free = plus(plus(f, cross(alpha0, arm)), plus(cross(omega, cross(omega, arm)), cross(omega, travel)));
  const Vec3 u{-mu_k * d[0], -mu_k * d[1], 1.0};
  const Vec3 per_load = plus(scaled(u, 1.0 / mass), cross(inertia_times(inertia, r, cross(arm, u), true), arm));
  m.consistency = per_load[2] * mass;
  const double load = -free[2] / per_load[2];
  m.force = scaled(u, load);
  m.accel = plus(f, scaled(m.force, 1.0 / mass));
  m.domega = plus(alpha0, inertia_times(inertia, r, cross(arm, m.force), true));
  const Vec3 s = plus(v, cross(omega, arm)), rate = plus(free, scaled(per_load, load));
  m.slip = {s[0], s[1], 0};
  m.slip_rate = {rate[0], rate[1], 0};
  return m;
}

}  // namespace blockdyn
