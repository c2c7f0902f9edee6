// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/numerics/lemke.hpp"

#include <algorithm>
#include <cmath>

namespace blockdyn {

void Lemke::reserve(int max_n) {
  if (max_n <= cap_) return;
  cap_ = max_n;
  tab_.assign(std::size_t(max_n) * std::size_t(2 * max_n + 2), 0.0);
  basis_.assign(std::size_t(max_n), 0);
}

bool Lemke::solve(int n, const double* M, int stride, const double* q, double* z, int max_pivots) {
  pivots_ = 0;
  std::fill(z, z + n, 0.0);
  if (n == 0) return true;
  int r = 0;
  for (int i = 1; i < n; ++i)
    if (q[i] < q[r]) r = i;
  if (q[r] >= 0.0) return true;  // z = 0
  reserve(n);
  // Columns: 0..n-1 the w's (identity at the start: they carry the basis inverse, used for the
  // lexicographic ties), n..2n-1 the z's (-M), 2n z0 (-e), 2n+1 the right-hand side.
  const int cols = 2 * n + 2, z0 = 2 * n, rhs = 2 * n + 1;
  auto T = [&](int i, int c) -> double& { return tab_[std::size_t(i) * std::size_t(cols) + std::size_t(c)]; };
  double scale = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int c = 0; c < n; ++c) {
      T(i, c) = i == c ? 1.0 : 0.0;
      T(i, n + c) = -M[std::size_t(i) * std::size_t(stride) + std::size_t(c)];
      scale = std::max(scale, std::fabs(T(i, n + c)));
    }
    T(i, z0) = -1.0;
    T(i, rhs) = q[i];
    basis_[i] = i;
  }
  const double pivot_tol = 1e-13 * std::max(scale, 1.0);
  double q_max = 0.0;
  for (int i = 0; i < n; ++i) q_max = std::max(q_max, std::fabs(q[i]));
  const double rhs_tol = 1e-13 * q_max;
  auto pivot = [&](int row, int col) {
    const double inv = 1.0 / T(row, col);
    for (int c = 0; c < cols; ++c) T(row, c) *= inv;
    T(row, col) = 1.0;
    for (int i = 0; i < n; ++i) {
      if (i == row) continue;
      const double f = T(i, col);
      if (f == 0.0) continue;
      for (int c = 0; c < cols; ++c) T(i, c) -= f * T(row, c);
      T(i, col) = 0.0;
    }
    ++pivots_;
  };
  // z0 enters at the most negative q, w_r leaves: every right-hand side becomes >= 0.
  pivot(r, z0);
  int leaving = basis_[r];
  basis_[r] = z0;
  if (max_pivots <= 0) max_pivots = 50 * n;
  while (pivots_ < max_pivots) {
    const int entering = leaving < n ? leaving + n : leaving - n;  // the complement
    // Harris's two-pass ratio test: the smallest ratio with every right-hand side relaxed by a
    // rounding tolerance, then, among the rows within it, the largest pivot (z0 first): on the
    // degenerate ties of redundant contacts a tiny pivot would amplify rounding without bound.
    double col_max = 0.0;
    for (int i = 0; i < n; ++i) col_max = std::max(col_max, std::fabs(T(i, entering)));
    const double tol = std::max(pivot_tol, 1e-11 * col_max);
    double theta = INFINITY;
    for (int i = 0; i < n; ++i) {
      const double a = T(i, entering);
      if (a > tol) theta = std::min(theta, (std::max(T(i, rhs), 0.0) + rhs_tol) / a);
    }
    int row = -1;
    double best = 0.0;
    for (int i = 0; i < n; ++i) {
      const double a = T(i, entering);
      if (!(a > tol) || std::max(T(i, rhs), 0.0) / a > theta) continue;
      const bool z0_row = basis_[i] == z0;
      if (row < 0 || (z0_row && basis_[row] != z0) || (a > best && !(basis_[row] == z0 && !z0_row))) {
        row = i;
        best = a;
      }
    }
    if (row < 0) return false;  // a secondary ray
    pivot(row, entering);
    leaving = basis_[row];
    basis_[row] = entering;
    if (leaving == z0) {
      for (int i = 0; i < n; ++i)
        if (basis_[i] >= n && basis_[i] < 2 * n) z[basis_[i] - n] = std::max(T(i, rhs), 0.0);
      return true;
    }
  }
  return false;
}

}  // namespace blockdyn
