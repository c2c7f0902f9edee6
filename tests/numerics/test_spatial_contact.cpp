// SPDX-License-Identifier: Apache-2.0
// The spatial frictional contact problem at the velocity level (numerics/spatial_contact.hpp):
// a point mass in closed form (no impulse, stick, slip), and the conditions that define the
// solution - Newton's normal velocity, Coulomb's cone, the slip against its friction - checked on
// general problems of one and several points.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "blockdyn/numerics/spatial_contact.hpp"

namespace blockdyn::spatial_contact_test {

SpatialContactProblem point_mass(double m, double ux, double uy, double un, double e, double mu) {
  SpatialContactProblem p;
  p.n = 1;
  for (int i = 0; i < 3; ++i) p.w[std::size_t(4 * i)] = 1.0 / m;
  p.q = {ux, uy, un};
  p.v_normal[0] = un < 0 ? -e * un : 0.0;
  p.mu_s = p.mu_k = mu;
  return p;
}

TEST(SpatialContact, APointMassInClosedForm) {
  const double m = 2.5, e = 0.4, mu = 0.3;
  // Sticks: |u_t| <= mu (1 + e) |u_n|.
  {
    const SpatialContactSolution s = solve_spatial_contact(point_mass(m, 0.1, -0.2, -1.0, e, mu));
    ASSERT_TRUE(s.solved);
    EXPECT_NEAR(s.p[2], m * (1 + e), 1e-14);
    EXPECT_NEAR(s.p[0], -m * 0.1, 1e-14);
    EXPECT_NEAR(s.p[1], m * 0.2, 1e-14);
    EXPECT_NEAR(s.u[0], 0.0, 1e-15);
    EXPECT_NEAR(s.u[2], e, 1e-15);
  }
  // Slips: the tangential velocity shrinks by mu (1 + e) |u_n| along itself.
  {
    const double ux = 0.6, uy = -0.8, un = -0.5;  // |u_t| = 1
    const SpatialContactSolution s = solve_spatial_contact(point_mass(m, ux, uy, un, e, mu));
    ASSERT_TRUE(s.solved);
    const double pn = m * (1 + e) * 0.5, shrink = 1 - mu * (1 + e) * 0.5;
    EXPECT_NEAR(s.p[2], pn, 1e-14);
    EXPECT_NEAR(s.p[0], -mu * pn * ux, 1e-13);
    EXPECT_NEAR(s.p[1], -mu * pn * uy, 1e-13);
    EXPECT_NEAR(s.u[0], ux * shrink, 1e-13);
    EXPECT_NEAR(s.u[1], uy * shrink, 1e-13);
    EXPECT_NEAR(s.u[2], e * 0.5, 1e-14);
  }
  // Leaves: no impulse.
  {
    const SpatialContactSolution s = solve_spatial_contact(point_mass(m, 1.0, 0.0, 0.2, e, mu));
    ASSERT_TRUE(s.solved);
    EXPECT_EQ(s.p[0], 0.0);
    EXPECT_EQ(s.p[2], 0.0);
  }
}

// A random symmetric positive definite 3n x 3n matrix: a body's Delassus matrix has this form
// (I/m - [a_i] J^-1 [a_j]), so build one from a random body.
SpatialContactProblem random_body_problem(std::mt19937& rng, int n, double e, double mu) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double m = 1.0 + 2.0 * (u(rng) + 1.0);
  double jinv[3][3];
  {
    // J^-1 = R diag(1/I) R^T for a random rotation (Gram-Schmidt of random vectors).
    double a[3][3];
    for (auto& row : a)
      for (double& x : row) x = u(rng);
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < i; ++k) {
        const double d = a[i][0] * a[k][0] + a[i][1] * a[k][1] + a[i][2] * a[k][2];
        for (int c = 0; c < 3; ++c) a[i][c] -= d * a[k][c];
      }
      const double l = std::sqrt(a[i][0] * a[i][0] + a[i][1] * a[i][1] + a[i][2] * a[i][2]);
      for (int c = 0; c < 3; ++c) a[i][c] /= l;
    }
    const double inv[3] = {1.0 / (0.5 + u(rng) * 0.3), 1.0 / (0.7 + u(rng) * 0.3), 1.0 / (0.9 + u(rng) * 0.3)};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        jinv[i][j] = a[0][i] * inv[0] * a[0][j] + a[1][i] * inv[1] * a[1][j] + a[2][i] * inv[2] * a[2][j];
  }
  double arm[kMaxSpatialPoints][3];
  for (int i = 0; i < n; ++i) arm[i][0] = u(rng), arm[i][1] = u(rng), arm[i][2] = -0.5 - 0.5 * (u(rng) + 1.0);
  auto cross_m = [](const double* a, double c[3][3]) {
    c[0][0] = 0, c[0][1] = -a[2], c[0][2] = a[1];
    c[1][0] = a[2], c[1][1] = 0, c[1][2] = -a[0];
    c[2][0] = -a[1], c[2][1] = a[0], c[2][2] = 0;
  };
  SpatialContactProblem p;
  p.n = n;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double ci[3][3], cj[3][3];
      cross_m(arm[i], ci);
      cross_m(arm[j], cj);
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          double k = 0;
          for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) k += ci[r][a] * jinv[a][b] * cj[b][c];
          p.w[std::size_t((3 * i + r) * 3 * n + 3 * j + c)] = (r == c ? 1.0 / m : 0.0) - k;
        }
    }
  for (int i = 0; i < n; ++i) {
    p.q[std::size_t(3 * i)] = u(rng);
    p.q[std::size_t(3 * i + 1)] = u(rng);
    p.q[std::size_t(3 * i + 2)] = -std::fabs(u(rng)) - 0.1;
    p.v_normal[std::size_t(i)] = -e * p.q[std::size_t(3 * i + 2)];
  }
  p.mu_s = p.mu_k = mu;
  return p;
}

// The conditions of the solution, each point: Newton's normal velocity where it is pressed (not
// below it anywhere), the impulse in the cone, and where the point slips the friction at the
// cone's edge against the slip.
void expect_solution(const SpatialContactProblem& p, const SpatialContactSolution& s) {
  SCOPED_TRACE("method " + std::to_string(s.method) + ", sweeps " + std::to_string(s.sweeps));
  for (int i = 0; i < p.n; ++i) {
    const double* pi = &s.p[std::size_t(3 * i)];
    const double* ui = &s.u[std::size_t(3 * i)];
    const double vn = p.v_normal[std::size_t(i)], ps = std::fabs(pi[2]) + 1.0;
    EXPECT_GE(pi[2], -1e-12 * ps) << i;
    EXPECT_GE(ui[2], vn - 1e-11) << i;
    if (pi[2] > 1e-12 * ps) {
      EXPECT_NEAR(ui[2], vn, 1e-11) << i;
    }
    const double pt = std::hypot(pi[0], pi[1]), ut = std::hypot(ui[0], ui[1]);
    EXPECT_LE(pt, p.mu_s * pi[2] + 1e-11 * ps) << i;
    if (ut > 1e-9) {
      EXPECT_NEAR(pt, p.mu_k * pi[2], 1e-10 * ps) << i;
      // Against the slip: p_T = -|p_T| u_T / |u_T|.
      EXPECT_NEAR(pi[0] * ut + pt * ui[0], 0.0, 1e-9 * ps) << i;
      EXPECT_NEAR(pi[1] * ut + pt * ui[1], 0.0, 1e-9 * ps) << i;
    }
  }
}

TEST(SpatialContact, OnePointOfABodyMeetsNewtonAndCoulomb) {
  std::mt19937 rng(7);
  int slipped = 0;
  for (int k = 0; k < 200; ++k) {
    const SpatialContactProblem p = random_body_problem(rng, 1, 0.3 * (k % 3), 0.1 + 0.2 * (k % 5));
    const SpatialContactSolution s = solve_spatial_contact(p);
    if (!s.solved) continue;  // Painleve at the impulse level: no consistent slip
    expect_solution(p, s);
    slipped += std::hypot(s.u[0], s.u[1]) > 1e-9;
  }
  EXPECT_GT(slipped, 50);  // the test sees slips, not only sticks
}

TEST(SpatialContact, TwoAndFourPointsMeetNewtonAndCoulomb) {
  std::mt19937 rng(11);
  int solved = 0;
  for (int k = 0; k < 200; ++k) {
    const int n = k % 2 == 0 ? 2 : 4;
    const SpatialContactProblem p = random_body_problem(rng, n, 0.0, 0.3 + 0.5 * (k % 3));
    const SpatialContactSolution s = solve_spatial_contact(p);
    if (!s.solved) continue;
    ++solved;
    expect_solution(p, s);
  }
  EXPECT_GT(solved, 150);
}

}  // namespace blockdyn::spatial_contact_test
