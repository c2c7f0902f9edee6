// SPDX-License-Identifier: Apache-2.0
// The contact solvers' linear algebra (numerics/redundant_solve.hpp) against Eigen: regular
// systems to rounding, and systems with dependent rows (redundant contacts) solved consistently
// with the dependent unknowns at zero.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "blockdyn/numerics/dense_solve.hpp"
#include "blockdyn/numerics/redundant_solve.hpp"

namespace {

using Matrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::vector<double> buffer(const Matrix& a, int stride) {
  std::vector<double> out(std::size_t(stride) * std::size_t(a.rows()), 0.0);
  for (int i = 0; i < a.rows(); ++i)
    for (int j = 0; j < a.cols(); ++j) out[std::size_t(i) * std::size_t(stride) + std::size_t(j)] = a(i, j);
  return out;
}

TEST(RedundantSolve, GaussMatchesEigenOnRegularSystems) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n;
  for (int m : {1, 2, 5, 12, 30}) {
    Matrix a(m, m);
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) {
      b[i] = n(rng);
      for (int j = 0; j < m; ++j) a(i, j) = n(rng) + (i == j ? 4.0 : 0.0);
    }
    const Eigen::VectorXd ref = a.partialPivLu().solve(b);
    std::vector<double> buf = buffer(a, m + 3), x(b.data(), b.data() + m);
    std::vector<int> scratch(static_cast<std::size_t>(m));
    blockdyn::gauss_solve(buf.data(), x.data(), m, m + 3, 1e-14, scratch.data());
    for (int i = 0; i < m; ++i) EXPECT_NEAR(x[std::size_t(i)], ref[i], 1e-12 * (1 + std::fabs(ref[i]))) << m;
  }
}

TEST(RedundantSolve, CholeskyMatchesEigenOnPositiveDefiniteSystems) {
  std::mt19937_64 rng(8);
  std::normal_distribution<double> n;
  for (int m : {1, 3, 8, 24}) {
    Matrix j(m, m + 2);
    for (int r = 0; r < m; ++r)
      for (int c = 0; c < m + 2; ++c) j(r, c) = n(rng);
    const Matrix a = j * j.transpose();
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) b[i] = n(rng);
    const Eigen::VectorXd ref = a.llt().solve(b);
    std::vector<double> buf = buffer(a, m), x(b.data(), b.data() + m);
    std::vector<int> dropped(static_cast<std::size_t>(m));
    blockdyn::cholesky_solve(buf.data(), x.data(), m, m, 1e-14, dropped.data());
    for (int i = 0; i < m; ++i) {
      EXPECT_EQ(dropped[std::size_t(i)], 0);
      EXPECT_NEAR(x[std::size_t(i)], ref[i], 1e-10 * (1 + ref.cwiseAbs().maxCoeff())) << m;
    }
  }
}

// A Delassus-like matrix J J^T whose last row repeats the first contact (a redundant end): both
// solvers set the dependent unknown to zero and still satisfy every equation (consistent b).
TEST(RedundantSolve, DependentRowsGetZeroUnknownsAndConsistentSolutions) {
  std::mt19937_64 rng(9);
  std::normal_distribution<double> n;
  const int m = 6;
  Matrix j(m, 9);
  for (int r = 0; r < m - 1; ++r)
    for (int c = 0; c < 9; ++c) j(r, c) = n(rng);
  j.row(m - 1) = j.row(0);
  const Matrix a = j * j.transpose();
  Eigen::VectorXd xs(m);
  for (int i = 0; i < m; ++i) xs[i] = n(rng);
  const Eigen::VectorXd b = a * xs;  // in the range of a: consistent
  for (int solver = 0; solver < 2; ++solver) {
    std::vector<double> buf = buffer(a, m), x(b.data(), b.data() + m);
    std::vector<int> scratch(static_cast<std::size_t>(m));
    const double min_pivot = 1e-10 * a.diagonal().maxCoeff();
    if (solver == 0)
      blockdyn::gauss_solve(buf.data(), x.data(), m, m, min_pivot, scratch.data());
    else
      blockdyn::cholesky_solve(buf.data(), x.data(), m, m, min_pivot, scratch.data());
    const Eigen::Map<const Eigen::VectorXd> sol(x.data(), m);
    EXPECT_EQ(x[m - 1], 0.0) << solver;
    if (solver == 1) {
      EXPECT_EQ(scratch[m - 1], 1);
    }
    EXPECT_LT((a * sol - b).norm(), 1e-10 * b.norm()) << solver;
  }
}

TEST(DenseLeastNorm, RowsDependentBelowTheThresholdGiveTheLeastNormSolution) {
  // [[1, 1], [1, 1 + 1e-13]] x = [1, 1]: full rank to rounding, rank one at the solve's threshold
  // (1e-11). The least-norm solution of the rank-one system is (1/2, 1/2); before, the threshold
  // was set after the decomposition, which had not been completed for rank one, and the solve
  // read coefficients never computed (valgrind: uninitialised; results varied with the stack).
  for (const double d : {1e-13, -3e-14, 0.0}) {
    const double a[4] = {1, 1, 1, 1 + d}, b[2] = {1, 1};
    double x[2] = {-7, -7};
    ASSERT_TRUE(blockdyn::solve_dense_least_norm(2, a, b, x)) << d;
    EXPECT_NEAR(x[0], 0.5, 1e-12) << d;
    EXPECT_NEAR(x[1], 0.5, 1e-12) << d;
  }
}

}  // namespace
