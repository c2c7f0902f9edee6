// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/numerics/redundant_solve.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace blockdyn {

// Solves A x = b in place (x into b) by Gaussian elimination with partial pivoting; A is m x m
// with row stride `stride`. A column whose best pivot is not above `min_pivot` belongs to a
// constraint that depends on the others (a redundant contact of a statically indeterminate
// assembly): its unknown is set to zero and its equation left to the consistency of the
// others, which the caller checks on the velocities. `piv_row` is scratch of size m.
void gauss_solve(double* __restrict A, double* __restrict b, int m, int stride, double min_pivot,
                 int* __restrict piv_row) {
  const std::size_t S = std::size_t(stride);
  int r = 0;  // the next pivot row
  for (int k = 0; k < m; ++k) {
    piv_row[k] = -1;
    if (r >= m) continue;
    int piv = r;
    for (int i = r + 1; i < m; ++i)
      if (std::fabs(A[std::size_t(i) * S + k]) > std::fabs(A[std::size_t(piv) * S + k])) piv = i;
    if (!(std::fabs(A[std::size_t(piv) * S + k]) > min_pivot)) continue;
    if (piv != r) {
      std::swap_ranges(A + std::size_t(r) * S + k, A + std::size_t(r) * S + m, A + std::size_t(piv) * S + k);
      std::swap(b[r], b[piv]);
    }
    const double* rk = A + std::size_t(r) * S;
    const double inv = 1.0 / rk[k];
    for (int i = r + 1; i < m; ++i) {
      double* ri = A + std::size_t(i) * S;
      const double f = ri[k] * inv;
      if (f == 0.0) continue;
      for (int c = k + 1; c < m; ++c) ri[c] -= f * rk[c];
      b[i] -= f * b[r];
    }
    piv_row[k] = r++;
  }
  // Back substitution over the pivot columns; the rows left over are the dependent equations.
  for (int k = m - 1; k >= 0; --k) {
    if (piv_row[k] < 0) continue;
    const double* rk = A + std::size_t(piv_row[k]) * S;
    double s = b[piv_row[k]];
    for (int c = k + 1; c < m; ++c)
      if (piv_row[c] >= 0) s -= rk[c] * b[piv_row[c]];
    b[piv_row[k]] = s / rk[k];
  }
  for (int k = 0; k < m; ++k) A[k] = piv_row[k] >= 0 ? b[piv_row[k]] : 0.0;  // first row as scratch
  for (int k = 0; k < m; ++k) b[k] = A[k];
}

// Solves A x = b in place for a symmetric positive semi-definite A (the Delassus matrix of
// sticking and separating ends) by Cholesky's factorisation (the lower triangle is used and
// overwritten). A row whose pivot is not above `min_pivot` depends on the rows before it (a
// redundant contact): its unknown is set to zero, as in gauss_solve.
void cholesky_solve(double* __restrict A, double* __restrict b, int m, int stride, double min_pivot,
                    int* __restrict dropped) {
  const std::size_t S = std::size_t(stride);
  // The envelope of the lower triangle (each row's first non-zero column; the contacts of blocks
  // that share no block have exact zeros): the factor fills only inside it, so a chain of blocks
  // costs O(m b^2) for a band of width b. `dropped` holds the envelope until a row is done.
  int* first = dropped;
  for (int j = 0; j < m; ++j) {
    const double* rj = A + std::size_t(j) * S;
    int f = 0;
    while (f < j && rj[f] == 0.0) ++f;
    first[j] = f;
  }
  for (int j = 0; j < m; ++j) {
    double* rj = A + std::size_t(j) * S;
    const int fj = first[j];
    double d = rj[j];
    for (int k = fj; k < j; ++k) d -= rj[k] * rj[k];
    const bool drop = !(d > min_pivot);
    if (drop) {
      // A unit pivot and a zero column: the unknown decouples and is solved as zero.
      for (int k = fj; k < j; ++k) rj[k] = 0.0;
      rj[j] = 1.0;
      for (int i = j + 1; i < m; ++i) A[std::size_t(i) * S + j] = 0.0;
    } else {
      const double l = std::sqrt(d), inv = 1.0 / l;
      rj[j] = l;
      for (int i = j + 1; i < m; ++i) {
        double* ri = A + std::size_t(i) * S;
        if (first[i] > j) continue;  // outside row i's envelope: stays zero
        double s = ri[j];
        for (int k = std::max(fj, first[i]); k < j; ++k) s -= ri[k] * rj[k];
        ri[j] = s * inv;
      }
    }
    first[j] = fj;  // (kept: the solves below use it)
    b[j] = drop ? 0.0 : b[j];
    rj[j] = drop ? -1.0 : rj[j];  // marks a dropped row for the solves (a real pivot is > 0)
  }
  for (int i = 0; i < m; ++i) {
    const double* ri = A + std::size_t(i) * S;
    if (ri[i] < 0.0) {
      b[i] = 0.0;
      continue;
    }
    double s = b[i];
    for (int k = first[i]; k < i; ++k) s -= ri[k] * b[k];
    b[i] = s / ri[i];
  }
  for (int i = m - 1; i >= 0; --i) {
    const double* ri = A + std::size_t(i) * S;
    if (ri[i] < 0.0) {
      b[i] = 0.0;
      continue;
    }
    double s = b[i];
    for (int k = i + 1; k < m; ++k) {
      const double* rk = A + std::size_t(k) * S;
      if (first[k] <= i) s -= rk[i] * b[k];
    }
    b[i] = s / ri[i];
  }
  for (int i = 0; i < m; ++i) dropped[i] = A[std::size_t(i) * S + i] < 0.0;
}

}  // namespace blockdyn
