// SPDX-License-Identifier: Apache-2.0
#pragma once
// What the parts of the rigid law's model share (rigid_assembly_model.cpp and the .ipp files it
// includes: dynamics, impacts, rest, transitions): its tolerances and the dense contact system.
#include <array>
#include <cstddef>

#include "blockdyn/numerics/dense_solve.hpp"

namespace blockdyn::rigid_assembly {

// Relative tolerances of the mode selection: a force, gap, velocity or acceleration this small
// (against the assembly's weight, smallest size, sqrt(g L) and g) counts as zero.
inline constexpr double kTol = 1e-9;
// Rounding band of the gap and slip-rate events (relative to L and sqrt(g L)): a gap computed from
// positions of order L carries rounding of order 1e-16 L, so a point that leaves its face with a
// tiny velocity (the last impacts of an accumulation) would otherwise see its gap cross zero in
// the rounding, at once and again. A point closes 1e-12 L past contact.
inline constexpr double kNoiseBand = 1e-12;
// Iterations of an active-set search before it is declared unsettled.
inline constexpr int kMaxActiveSet = 64;

// The contact problem of a mode as a dense linear system over the unknown forces (or impulses):
// each unknown has a generalized force column, each constraint a row; A = rows M^-1 columns.
template <int NC, int MaxU>
struct ContactSystem {
  std::array<std::array<double, NC>, MaxU> col{}, row{};
  std::array<double, MaxU> rhs{};
  int n = 0;
  void clear() { n = 0; }
  int add() {
    col[n].fill(0.0);
    row[n].fill(0.0);
    return n++;
  }
  // Solve for the unknowns; the least-norm solution where the constraints are redundant.
  bool solve(const std::array<double, NC>& inv_mass, std::array<double, MaxU>& x) const {
    if (n == 0) return true;
    static_assert(MaxU <= kMaxDenseUnknowns, "the contact system exceeds the dense solver's size");
    std::array<double, MaxU * MaxU> A;
    for (int k = 0; k < n; ++k)
      for (int j = 0; j < n; ++j) {
        double s = 0.0;
        for (int c = 0; c < NC; ++c) s += row[k][c] * inv_mass[c] * col[j][c];
        A[std::size_t(k * n + j)] = s;
      }
    return solve_dense_least_norm(n, A.data(), rhs.data(), x.data());
  }
};

// A contact point's rows, scaled by s, added into a generalized vector (upper block's u, lower's l).
template <int NC, class Rows>
void place_rows(std::array<double, NC>& w, const Rows& k, const std::array<double, 3>& u,
                const std::array<double, 3>& l, double s) {
  for (int c = 0; c < 3; ++c) {
    w[3 * k.upper + c] += s * u[c];
    if (k.lower >= 0) w[3 * k.lower + c] += s * l[c];
  }
}

// The point's relative normal (or tangential) velocity for the generalized velocities w.
template <int NC, class Rows>
double relative_rate(const std::array<double, NC>& w, const Rows& k, bool normal) {
  const auto& u = normal ? k.nu : k.tu;
  const auto& l = normal ? k.nl : k.tl;
  double s = 0.0;
  for (int c = 0; c < 3; ++c) {
    s += u[c] * w[3 * k.upper + c];
    if (k.lower >= 0) s += l[c] * w[3 * k.lower + c];
  }
  return s;
}

}  // namespace blockdyn::rigid_assembly
