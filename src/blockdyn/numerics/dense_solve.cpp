// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/numerics/dense_solve.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace blockdyn {

bool solve_dense_least_norm(int n, const double* A, const double* b, double* x) {
  if (n == 0) return true;
  if (n < 0 || n > kMaxDenseUnknowns) return false;
  using Mat = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxDenseUnknowns, kMaxDenseUnknowns>;
  using Vec = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxDenseUnknowns, 1>;
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
    Eigen::CompleteOrthogonalDecomposition<Mat> cod(M);
    cod.setThreshold(1e-11);
    sol = cod.solve(r);
  }
  for (int k = 0; k < n; ++k) {
    x[k] = sol(k);
    if (!std::isfinite(x[k])) return false;
  }
  return true;
}

}  // namespace blockdyn
