// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/numerics/dense_solve.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace blockdyn {

namespace {

// The solve on storage for at most `Max` unknowns: the same algorithm at every Max, so that a
// small system (a few contact points' 3n unknowns) does not pay for clearing and copying the
// largest storage (80 x 80 doubles, 51 kB, at every call).
template <int Max>
bool least_norm(int n, const double* A, const double* b, double* x) {
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, Max, Max>;
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, Max, 1>;
  Mat M(n, n);
  Vec r(n);
  for (int k = 0; k < n; ++k) {
    r(k) = b[k];
    for (int j = 0; j < n; ++j) M(k, j) = A[k * n + j];
  }
  const Eigen::PartialPivLU<Mat> lu(M);
  double lo = INFINITY, hi = 0.0;
  for (int k = 0; k < n; ++k) {
    const double d = std::fabs(lu.matrixLU()(k, k));
    lo = std::fmin(lo, d);
    hi = std::fmax(hi, d);
  }
  Vec sol;
  if (lo > 1e-10 * hi) {
    sol = lu.solve(r);
  } else {
    // The threshold before the decomposition: set after it, the solve takes a smaller rank than
    // the decomposition was completed for and reads Householder coefficients never computed.
    Eigen::CompleteOrthogonalDecomposition<Mat> cod(n, n);
    cod.setThreshold(1e-11);
    cod.compute(M);
    sol = cod.solve(r);
  }
  for (int k = 0; k < n; ++k) {
    x[k] = sol(k);
    if (!std::isfinite(x[k])) return false;
  }
  return true;
}

constexpr int kSmallUnknowns = 12;

}  // namespace

bool solve_dense_least_norm(int n, const double* A, const double* b, double* x) {
  if (n == 0) return true;
  if (n < 0 || n > kMaxDenseUnknowns) return false;
  return n <= kSmallUnknowns ? least_norm<kSmallUnknowns>(n, A, b, x) : least_norm<kMaxDenseUnknowns>(n, A, b, x);
}

}  // namespace blockdyn
