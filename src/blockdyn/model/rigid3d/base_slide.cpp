// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/model/rigid3d/base_slide.hpp"

#include <utility>

#include "blockdyn/model/rigid3d/slip_reference.hpp"

namespace blockdyn {

namespace {

// A corner's slip below this (m/s) has no direction of its own.
constexpr double kNoSlip = 1e-300;

// The 4 x 4 system a x = rhs by Gaussian elimination with partial pivoting (it is regular: the
// corners span the base).
std::array<double, 4> solve4(std::array<std::array<double, 4>, 4> a, std::array<double, 4> rhs) {
  for (int k = 0; k < 4; ++k) {
    int p = k;
    for (int i = k + 1; i < 4; ++i)
      if (std::fabs(a[i][k]) > std::fabs(a[p][k])) p = i;
    std::swap(a[k], a[p]);
    std::swap(rhs[k], rhs[p]);
    for (int i = k + 1; i < 4; ++i) {
      const double f = a[i][k] / a[k][k];
      for (int j = k; j < 4; ++j) a[i][j] -= f * a[k][j];
      rhs[i] -= f * rhs[k];
    }
  }
  std::array<double, 4> x{};
  for (int k = 3; k >= 0; --k) {
    double s = rhs[k];
    for (int j = k + 1; j < 4; ++j) s -= a[k][j] * x[j];
    x[k] = s / a[k][k];
  }
  return x;
}

}  // namespace

BaseSlide base_slide(double b, double d, double c, double mass, double inertia_z, double mu_k, double yaw,
                     const Vec3& v, double omega_z, const Vec3& f, const Vec3& reference, double noise, int unloaded) {
  const double cy = std::cos(yaw), sy = std::sin(yaw), reach = base_reach(b, d);
  // The slip field whose directions the corners' friction takes (slip_reference.hpp): the
  // generalised slip's, reversed past its reversal (which only a stick's event ends), turning to
  // the reference's within the noise (a direction that jumped there would chatter at its edge).
  const Vec3 field = slip_reference::friction_direction({v[0], v[1], reach * omega_z}, reference, noise);
  std::array<Vec3, 4> r{}, slip{}, dir{}, dir_body{};
  std::array<double, 4> px{}, py{};
  for (int i = 0; i < 4; ++i) {
    px[i] = (i & 1 ? 0.5 : -0.5) * b;
    py[i] = (i & 2 ? 0.5 : -0.5) * d;
    r[i] = {cy * px[i] - sy * py[i], sy * px[i] + cy * py[i], 0};
    slip[i] = {v[0] - omega_z * r[i][1], v[1] + omega_z * r[i][0], 0};
    const Vec3 s = {field[0] - field[2] / reach * r[i][1], field[1] + field[2] / reach * r[i][0], 0};
    const double ns = std::hypot(s[0], s[1]);
    if (ns > kNoSlip) dir[i] = {s[0] / ns, s[1] / ns, 0};
    dir_body[i] = {cy * dir[i][0] + sy * dir[i][1], -sy * dir[i][0] + cy * dir[i][1], 0};
  }
  // The weight, no tilting moment about the centroid (x and y, body frame; the friction acts at
  // the base, c below it), and a linear pressure (its corner values have no twisted part).
  std::array<std::array<double, 4>, 4> a{};
  for (int i = 0; i < 4; ++i) {
    a[0][i] = 1;
    a[1][i] = py[i] - c * mu_k * dir_body[i][1];
    a[2][i] = c * mu_k * dir_body[i][0] - px[i];
    a[3][i] = unloaded >= 0 ? (i == unloaded ? 1 : 0) : (i == 0 || i == 3) ? 1 : -1;
  }
  BaseSlide s;
  s.load = solve4(a, {-mass * f[2], 0, 0, 0});
  Vec3 total{};
  double torque = 0;
  for (int i = 0; i < 4; ++i) {
    s.friction[i] = Vec3{-mu_k * s.load[i] * dir[i][0], -mu_k * s.load[i] * dir[i][1], 0};
    total = {total[0] + s.friction[i][0], total[1] + s.friction[i][1], 0};
    torque += r[i][0] * s.friction[i][1] - r[i][1] * s.friction[i][0];
    s.friction_power += s.friction[i][0] * slip[i][0] + s.friction[i][1] * slip[i][1];
  }
  s.accel = {f[0] + total[0] / mass, f[1] + total[1] / mass, 0};
  s.spin_accel = torque / inertia_z;
  return s;
}

}  // namespace blockdyn
