// SPDX-License-Identifier: Apache-2.0
#pragma once
// Small dense systems A x = b whose rows may depend on each other (the contacts of a statically
// indeterminate assembly: an arch's joints, a face's two ends), solved in place on the caller's
// buffers: a row whose pivot is not above `min_pivot` is dropped, its unknown set to zero and
// its equation left to the consistency of the others (which the caller checks). A is m x m,
// row-major with row stride `stride`; x overwrites b.

namespace blockdyn {

// Gaussian elimination with partial pivoting (any A). `piv_row`: scratch of size m.
void gauss_solve(double* __restrict A, double* __restrict b, int m, int stride, double min_pivot,
                 int* __restrict piv_row);

// Cholesky's factorisation of a symmetric positive semi-definite A (its lower triangle is used
// and overwritten), inside the envelope of the lower triangle: a chain of blocks, whose
// contacts share blocks only with their neighbours, costs O(m b^2) for a band of width b.
// `dropped`: on return 1 for each dropped row, else 0 (size m).
void cholesky_solve(double* __restrict A, double* __restrict b, int m, int stride, double min_pivot,
                    int* __restrict dropped);

}  // namespace blockdyn
