// SPDX-License-Identifier: Apache-2.0
#pragma once
// A small dense linear system A x = b (the contact problems of the rigid contact law: at most
// kMaxDenseUnknowns unknowns), solved on the stack: LU with partial pivoting where the pivots
// show A well conditioned, else the least-norm solution of a complete orthogonal decomposition
// (redundant constraints: a face's two closed ends with redundant neighbours, as at rest). Eigen's
// decompositions instantiated twice: on storage for 12 unknowns (up to four contact points in
// space) and for kMaxDenseUnknowns.
namespace blockdyn {

inline constexpr int kMaxDenseUnknowns = 80;

// A: n x n, row-major; false if n is out of range or the solution is not finite.
bool solve_dense_least_norm(int n, const double* A, const double* b, double* x);

}  // namespace blockdyn
