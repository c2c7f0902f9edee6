// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/body_pivot.hpp"

namespace blockdyn {

namespace {

// The centroid's acceleration and the reaction once the angular acceleration is known.
void complete_motion(PivotMotion& m, double mass, const Vec3& arm, const Vec3& omega, const Vec3& f) {
  m.accel = plus(cross(m.domega, arm), cross(omega, cross(omega, arm)));
  m.force = scaled(minus(m.accel, f), mass);
}

}  // namespace

Mat3 inertia_about(const Vec3& inertia, double mass, const Vec3& s) {
  const double s2 = dot(s, s);
  Mat3 j{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) j[i][k] = mass * ((i == k ? s2 : 0.0) - s[i] * s[k]) + (i == k ? inertia[i] : 0.0);
  return j;
}

Mat3 solve_matrix(const Mat3& a) {
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) {
      const int i1 = (i + 1) % 3, i2 = (i + 2) % 3, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      c[k][i] = a[i1][k1] * a[i2][k2] - a[i1][k2] * a[i2][k1];  // the adjugate (transposed cofactors)
    }
  const double det = a[0][0] * c[0][0] + a[0][1] * c[1][0] + a[0][2] * c[2][0];
  for (Vec3& row : c) row = scaled(row, 1.0 / det);
  return c;
}

Vec3 free_angular_acceleration(const Vec3& inertia, const Mat3& r, const Vec3& omega) {
  // Euler's equations in the body frame, I Omega' = (I Omega) x Omega, and omega' = R Omega'.
  const Vec3 om = transposed_times(r, omega);
  const Vec3 tq = cross({inertia[0] * om[0], inertia[1] * om[1], inertia[2] * om[2]}, om);
  return r * Vec3{tq[0] / inertia[0], tq[1] / inertia[1], tq[2] / inertia[2]};
}

PivotMotion point_pivot_motion(const Vec3& inertia, double mass, const Mat3& r, const Vec3& s_body, const Vec3& omega,
                               const Vec3& f) {
  // About the fixed point P: J Omega' + Omega x J Omega = s x (m R^T f), J the inertia about P.
  const Mat3 j = inertia_about(inertia, mass, s_body);
  const Vec3 om = transposed_times(r, omega);
  const Vec3 torque = minus(cross(s_body, scaled(transposed_times(r, f), mass)), cross(om, j * om));
  PivotMotion m;
  m.domega = r * (solve_matrix(j) * torque);
  complete_motion(m, mass, r * s_body, omega, f);
  return m;
}

PivotMotion line_pivot_motion(const Vec3& inertia, double mass, const Mat3& r, const Vec3& s_body, const Vec3& axis,
                              const Vec3& omega, const Vec3& f) {
  // A rotation theta about the fixed axis e: J_e theta'' = e . (arm x m f); the gyroscopic term
  // Omega x J Omega is normal to Omega and so to e.
  const Mat3 j = inertia_about(inertia, mass, s_body);
  const Vec3 e_body = transposed_times(r, axis);
  const Vec3 arm = r * s_body;
  const double je = dot(e_body, j * e_body);
  PivotMotion m;
  m.domega = scaled(axis, dot(axis, cross(arm, scaled(f, mass))) / je);
  complete_motion(m, mass, arm, omega, f);
  // The moment the line carries: dH_P/dt minus the applied force's moment about P.
  const Vec3 om = transposed_times(r, omega), dom = transposed_times(r, m.domega);
  const Vec3 dh = r * plus(j * dom, cross(om, j * om));
  m.moment = minus(dh, cross(arm, scaled(f, mass)));
  return m;
}

Vec3 angular_momentum_about(const Vec3& inertia, double mass, const Mat3& r, const Vec3& arm, const Vec3& v,
                            const Vec3& omega) {
  const Vec3 om = transposed_times(r, omega);
  const Vec3 lg = r * Vec3{inertia[0] * om[0], inertia[1] * om[1], inertia[2] * om[2]};
  return plus(lg, scaled(cross(arm, v), mass));
}

namespace {

// The force x along the axis at the plus end (fe - x at the minus end) that leaves the most
// friction to spare at the worse end: the largest min(mu n_p - |(t_p, x)|, mu n_m - |(t_m, fe - x)|),
// t_i the end's tangential force normal to the axis. From x = 0 to x = fe the plus end's margin
// falls and the minus end's rises, so the best is where they meet (a Newton step safeguarded by
// the bracket), or an end of that path.
double friction_split(double np, double tp, double nm, double tm, double fe, double mu) {
  auto gap = [&](double x) { return (mu * np - std::hypot(tp, x)) - (mu * nm - std::hypot(tm, fe - x)); };
  if (fe == 0 || gap(0) <= 0) return 0;
  if (gap(fe) >= 0) return fe;
  double a = 0, b = fe, x = fe * 0.5;  // gap(a) > 0 > gap(b)
  const double close = 1e-15 * mu * (np + nm);
  for (int it = 0; it < 100; ++it) {
    const double g = gap(x);
    if (std::fabs(g) <= close) break;
    (g > 0 ? a : b) = x;
    const double hp = std::hypot(tp, x), hm = std::hypot(tm, fe - x);
    const double slope = -(hp > 0 ? x / hp : 0.0) - (hm > 0 ? (fe - x) / hm : 0.0);
    double next = slope != 0 ? x - g / slope : 0.5 * (a + b);
    if (!((next - a) * (next - b) < 0)) next = 0.5 * (a + b);
    if (next == x) break;
    x = next;
  }
  return x;
}

}  // namespace

LineLoads split_line_reaction(const Vec3& force, const Vec3& moment, const Vec3& axis, double half_length, double mu) {
  // F+ + F- = F and L e x (F+ - F-) = M fix everything but the split of the force along e (the
  // axis is horizontal): a rigid edge sticking at both ends carries any split its ends' friction
  // allows. It takes the one that leaves the most friction to spare at the worse end, so that the
  // edge slips only where no split holds it; equally when either load is not positive.
  const Vec3 d = half_length > 0 ? scaled(cross(moment, axis), 1.0 / half_length) : Vec3{0, 0, 0};
  const double fe = dot(force, axis);
  const Vec3 normal_part = minus(force, scaled(axis, fe));
  LineLoads l{scaled(plus(normal_part, d), 0.5), scaled(minus(normal_part, d), 0.5)};
  const double np = l.plus[2], nm = l.minus[2];
  double x = 0.5 * fe;
  if (np > 0 && nm > 0) {
    const double tp = std::hypot(l.plus[0], l.plus[1]), tm = std::hypot(l.minus[0], l.minus[1]);
    x = friction_split(np, tp, nm, tm, fe, mu);
  }
  l.plus = plus(l.plus, scaled(axis, x));
  l.minus = plus(l.minus, scaled(axis, fe - x));
  return l;
}

}  // namespace blockdyn
