// SPDX-License-Identifier: Apache-2.0
#pragma once
// Lemke's complementary pivoting method for the linear complementarity problem LCP(M, q):
//   find z >= 0 with w = M z + q >= 0 and z.w = 0.
// It ends with a solution for every matrix class that the contact problems give (positive
// semi-definite plus the Coulomb rows of a 2D friction cone: copositive-plus, Anitescu and
// Potra), or reports a secondary ray. Degenerate ties (redundant contacts) go to the largest
// pivot (Harris's ratio test) for accuracy; a cycle would end at the pivot limit. The tableau is
// dense: it is meant for the few steps where an active-set guess does not settle, and its answer
// is a guess to be checked.
#include <vector>

namespace blockdyn {

class Lemke {
 public:
  // Scratch for problems up to n unknowns (allocated here, not in solve()).
  explicit Lemke(int max_n = 0) { reserve(max_n); }
  void reserve(int max_n);
  // M is n x n, row-major with row stride `stride`. z receives the solution; false on a ray or
  // when the pivots run out (max_pivots; 0: 50 n).
  bool solve(int n, const double* M, int stride, const double* q, double* z, int max_pivots = 0);
  int pivots() const { return pivots_; }

 private:
  int cap_ = 0, pivots_ = 0;
  std::vector<double> tab_;  // n x (n + n + 1 + 1): the basis inverse's columns, -M, -e, q
  std::vector<int> basis_;   // basic variable of each row: 0..n-1 w, n..2n-1 z, 2n z0
};

}  // namespace blockdyn
