// SPDX-License-Identifier: Apache-2.0
// Lemke's method (lemke.hpp) on the problems the contact solver gives it: positive definite,
// positive semi-definite with redundant rows (a statically indeterminate assembly), and the
// Anitescu-Potra form of 2D Coulomb friction; every solution checked for complementarity.
#include "blockdyn/numerics/lemke.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

using namespace blockdyn;

namespace {

// max over i of the violations of z >= 0, w = M z + q >= 0 and z_i w_i = 0, relative to the
// problem's scale.
double complementarity_error(int n, const std::vector<double>& M, const std::vector<double>& q,
                             const std::vector<double>& z) {
  double scale = 1e-300, err = 0;
  for (double x : q) scale = std::fmax(scale, std::fabs(x));
  for (int i = 0; i < n; ++i) {
    double w = q[i];
    for (int j = 0; j < n; ++j) w += M[i * n + j] * z[j];
    err = std::fmax(err, std::fmax(-z[i], -w));
    err = std::fmax(err, std::fmin(std::fabs(z[i]), std::fabs(w)));
  }
  return err / scale;
}

// M = A A^T (+ eps I): rank k when k < n.
std::vector<double> gram(int n, int k, double eps, std::mt19937& rng) {
  std::normal_distribution<double> N(0, 1);
  std::vector<double> A(std::size_t(n * k)), M(std::size_t(n * n));
  for (double& x : A) x = N(rng);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      double s = i == j ? eps : 0.0;
      for (int c = 0; c < k; ++c) s += A[i * k + c] * A[j * k + c];
      M[i * n + j] = s;
    }
  return M;
}

// A q for which the problem has a solution: w* - M z* with complementary z*, w* >= 0.
std::vector<double> solvable_q(int n, const std::vector<double>& M, std::mt19937& rng) {
  std::normal_distribution<double> N(0, 1);
  std::vector<double> q(static_cast<std::size_t>(n)), zs(q), ws(q);
  for (int i = 0; i < n; ++i) {
    const unsigned r = rng() % 3;
    if (r == 0) zs[i] = std::fabs(N(rng));
    if (r == 1) ws[i] = std::fabs(N(rng));
  }
  for (int i = 0; i < n; ++i) {
    double s = 0;
    for (int j = 0; j < n; ++j) s += M[i * n + j] * zs[j];
    q[i] = ws[i] - s;
  }
  return q;
}

}  // namespace

TEST(Lemke, PositiveDefiniteProblemsAreSolvedExactly) {
  std::mt19937 rng(7);
  std::normal_distribution<double> N(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 30;
    const std::vector<double> M = gram(n, n + 2, 0.0, rng);
    std::vector<double> q(static_cast<std::size_t>(n)), z(q);
    for (double& x : q) x = N(rng);
    Lemke lemke(n);
    ASSERT_TRUE(lemke.solve(n, M.data(), n, q.data(), z.data())) << "n " << n;
    EXPECT_LT(complementarity_error(n, M, q, z), 1e-10) << "n " << n;
    EXPECT_LE(lemke.pivots(), 2 * n + 1);
  }
}

TEST(Lemke, RedundantRowsAsInAStaticallyIndeterminateAssembly) {
  // Rank n/2 + 1 (each unknown a contact, many more than the blocks' freedoms), with and
  // without the contact solver's compliance.
  std::mt19937 rng(11);
  for (double eps : {0.0, 1e-10}) {
    for (int trial = 0; trial < 200; ++trial) {
      const int n = 2 + trial % 40;
      const std::vector<double> M = gram(n, n / 2 + 1, eps, rng);
      const std::vector<double> q = solvable_q(n, M, rng);
      std::vector<double> z(static_cast<std::size_t>(n));
      Lemke lemke(n);
      ASSERT_TRUE(lemke.solve(n, M.data(), n, q.data(), z.data())) << "n " << n << " eps " << eps;
      EXPECT_LT(complementarity_error(n, M, q, z), 1e-8) << "n " << n << " eps " << eps;
    }
  }
}

TEST(Lemke, TwoDimensionalCoulombFrictionSticksOrSlips) {
  // One block on two contacts (a face's ends) pushed along the face: the Anitescu-Potra LCP in
  // (P_N1, P_N2, beta+, beta-, lambda). The impulse needed to stop the block's free sliding speed
  // v within one step is m v; the face sticks when m v <= mu (P_N1 + P_N2) and otherwise slips
  // with P_T = mu (P_N1 + P_N2).
  const double m = 2.0, I = 0.5, half = 0.4, g_h = 0.01;  // mass, inertia, half face, g h
  for (double v : {0.001, 0.004, 0.0079, 0.0081, 0.02}) {
    for (double mu : {0.0, 0.2, 0.4}) {
      // Rows of the ends' normal (y) and the face's tangential (x) velocities on (vx, vy, w).
      const double Jn[2][3] = {{0, 1, -half}, {0, 1, half}}, Jt[3] = {1, 0, 0};
      const double Minv[3] = {1 / m, 1 / m, 1 / I};
      auto W = [&](const double* a, const double* b) {
        double s = 0;
        for (int c = 0; c < 3; ++c) s += a[c] * Minv[c] * b[c];
        return s;
      };
      const int n = 5;
      std::vector<double> M(25, 0.0), q(5, 0.0), z(5);
      for (int i = 0; i < 2; ++i) {
        for (int j = 0; j < 2; ++j) M[i * n + j] = W(Jn[i], Jn[j]);
        M[i * n + 2] = W(Jn[i], Jt);
        M[i * n + 3] = -W(Jn[i], Jt);
        q[i] = -g_h;  // the free motion falls by g h
      }
      for (int j = 0; j < 2; ++j) {
        M[2 * n + j] = W(Jt, Jn[j]);
        M[3 * n + j] = -W(Jt, Jn[j]);
        M[4 * n + j] = mu;
      }
      M[2 * n + 2] = M[3 * n + 3] = W(Jt, Jt);
      M[2 * n + 3] = M[3 * n + 2] = -W(Jt, Jt);
      M[2 * n + 4] = M[3 * n + 4] = 1;
      M[4 * n + 2] = M[4 * n + 3] = -1;
      q[2] = v;
      q[3] = -v;
      Lemke lemke(n);
      ASSERT_TRUE(lemke.solve(n, M.data(), n, q.data(), z.data()));
      EXPECT_LT(complementarity_error(n, M, q, z), 1e-12);
      const double N = z[0] + z[1], T = z[2] - z[3];
      EXPECT_NEAR(N, m * g_h, 1e-14) << "v " << v << " mu " << mu;
      if (m * v <= mu * N * (1 - 1e-9)) {
        EXPECT_NEAR(T, -m * v, 1e-14) << "sticks: v " << v << " mu " << mu;
        EXPECT_NEAR(z[4], 0.0, 1e-14);
      } else {
        EXPECT_NEAR(T, -mu * N, 1e-14) << "slips: v " << v << " mu " << mu;
        if (mu > 0) {
          EXPECT_NEAR(z[4], v - mu * N / m, 1e-14);  // the slip speed after the step
        }
      }
    }
  }
}

TEST(Lemke, ANonNegativeRightHandSideNeedsNoPivot) {
  const std::vector<double> M{2, 1, 1, 2}, q{0.5, 0.0};
  std::vector<double> z(2, 7.0);
  Lemke lemke;
  ASSERT_TRUE(lemke.solve(2, M.data(), 2, q.data(), z.data()));
  EXPECT_EQ(z[0], 0.0);
  EXPECT_EQ(z[1], 0.0);
  EXPECT_EQ(lemke.pivots(), 0);
}
