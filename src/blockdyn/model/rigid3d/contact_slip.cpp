// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/contact_slip.hpp"

#include <cmath>
#include <utility>

#include "blockdyn/model/rigid3d/body_pivot.hpp"

namespace blockdyn {

namespace {

constexpr int kMaxUnknowns = 4;

// I^-1 v for the world-frame inertia R diag(inertia) R^T.
Vec3 inverse_inertia_times(const Vec3& inertia, const Mat3& r, const Vec3& v) {
  const Vec3 b = transposed_times(r, v);
  return r * Vec3{b[0] / inertia[0], b[1] / inertia[1], b[2] / inertia[2]};
}

// a x = rhs for k <= 4 by Gaussian elimination with partial pivoting; the determinant.
double solve_small(int k, double a[kMaxUnknowns][kMaxUnknowns], double rhs[kMaxUnknowns], double x[kMaxUnknowns]) {
  double det = 1;
  for (int c = 0; c < k; ++c) {
    int p = c;
    for (int i = c + 1; i < k; ++i)
      if (std::fabs(a[i][c]) > std::fabs(a[p][c])) p = i;
    if (p != c) {
      for (int j = 0; j < k; ++j) std::swap(a[c][j], a[p][j]);
      std::swap(rhs[c], rhs[p]);
      det = -det;
    }
    det *= a[c][c];
    if (a[c][c] == 0) return 0;
    for (int i = c + 1; i < k; ++i) {
      const double f = a[i][c] / a[c][c];
      for (int j = c; j < k; ++j) a[i][j] -= f * a[c][j];
      rhs[i] -= f * rhs[c];
    }
  }
  for (int c = k - 1; c >= 0; --c) {
    double s = rhs[c];
    for (int j = c + 1; j < k; ++j) s -= a[c][j] * x[j];
    x[c] = s / a[c][c];
  }
  return det;
}

}  // namespace

SlipContactMotion slipping_contact_motion(const Vec3& inertia, double mass, const Mat3& r, const ContactPoints& p,
                                          const Vec3& omega, const Vec3& f, double mu_k) {
  // Without reactions: the gyroscopic angular acceleration -I^-1 (omega x I omega).
  const Vec3 om = transposed_times(r, omega);
  const Vec3 spin = r * Vec3{inertia[0] * om[0], inertia[1] * om[1], inertia[2] * om[2]};
  const Vec3 domega0 = scaled(inverse_inertia_times(inertia, r, cross(omega, spin)), -1.0);
  // The unknowns: a sticking point's force along X, Y, Z; a slipping point's load, its force per
  // unit load Z - mu_k d. Each gives the centroid's and the angular acceleration per unit.
  Vec3 unit_force[kMaxUnknowns]{}, unit_domega[kMaxUnknowns]{};
  int owner[kMaxUnknowns]{};
  int k = 0;
  for (int i = 0; i < p.n; ++i) {
    if (p.sticks[i]) {
      for (int c = 0; c < 3; ++c) {
        unit_force[k] = {c == 0 ? 1.0 : 0.0, c == 1 ? 1.0 : 0.0, c == 2 ? 1.0 : 0.0};
        owner[k++] = i;
      }
    } else {
      unit_force[k] = {-mu_k * p.dir[i][0], -mu_k * p.dir[i][1], 1.0};
      owner[k++] = i;
    }
  }
  for (int j = 0; j < k; ++j) unit_domega[j] = inverse_inertia_times(inertia, r, cross(p.arm[owner[j]], unit_force[j]));
  // The constraints: a sticking point's acceleration (three components), a slipping point's
  // vertical one, each zero.
  double a[kMaxUnknowns][kMaxUnknowns]{}, rhs[kMaxUnknowns]{}, x[kMaxUnknowns]{};
  int row = 0;
  for (int i = 0; i < p.n; ++i) {
    const Vec3 free = plus(f, plus(cross(domega0, p.arm[i]), cross(omega, cross(omega, p.arm[i]))));
    const int c0 = p.sticks[i] ? 0 : 2;
    for (int c = c0; c < 3; ++c, ++row) {
      rhs[row] = -free[c];
      for (int j = 0; j < k; ++j) a[row][j] = unit_force[j][c] / mass + cross(unit_domega[j], p.arm[i])[c];
    }
  }
  SlipContactMotion m;
  m.consistency = solve_small(k, a, rhs, x) * std::pow(mass, k);
  m.accel = f;
  m.domega = domega0;
  for (int j = 0; j < k; ++j) {
    const Vec3 fj = scaled(unit_force[j], x[j]);
    m.force[owner[j]] = plus(m.force[owner[j]], fj);
    m.accel = plus(m.accel, scaled(fj, 1.0 / mass));
    m.domega = plus(m.domega, scaled(unit_domega[j], x[j]));
  }
  return m;
}

}  // namespace blockdyn
