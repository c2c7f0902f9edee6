// SPDX-License-Identifier: Apache-2.0
#pragma once
// The frictional contact problem in space at the velocity level, for a few points on one plane
// (the third component of each point's velocity and impulse is along the plane's normal); no
// mechanics (model/rigid3d/body_impact.cpp builds the impact problem of a body):
//   u = W p + q                 W the Delassus matrix (3n x 3n, symmetric, positive semidefinite),
//                               q the velocities without impulse,
//   0 <= p_N  _|_  u_N - v_N >= 0     v_N >= 0 the normal velocity asked for (Newton's law:
//                               v_N = -e u_N before the impact),
//   Coulomb: |p_T| <= mu_s p_N where u_T = 0 (stick); p_T = -mu_k p_N u_T / |u_T| where it slips.
// One point is solved exactly: no impulse, stick, or slip in the direction whose velocity after
// the impulse points along it (a root in the slip's angle, bisected to rounding). Several points:
// the approaching ones sticking, the others free, then all sticking (the least-norm impulses,
// accepted when they lie in every cone and no free point sinks), else nonsmooth Gauss-Seidel with
// each point's problem solved exactly, the others held, until the velocities settle (the points
// it leaves pressed and at rest then solved together exactly; where some slip, Newton's method
// on its classes, tried every second sweep, ends it where it solves the problem). With restitution and several
// points the problem may have more than one solution: this order picks one.
#include <array>

namespace blockdyn {

inline constexpr int kMaxSpatialPoints = 4;

struct SpatialContactProblem {
  int n = 0;
  std::array<double, 9 * kMaxSpatialPoints * kMaxSpatialPoints> w{};  // 3n x 3n, row-major
  std::array<double, 3 * kMaxSpatialPoints> q{};
  std::array<double, kMaxSpatialPoints> v_normal{};
  double mu_s = 0, mu_k = 0;
  double at(int r, int c) const { return w[std::size_t(r * 3 * n + c)]; }
};

struct SpatialContactSolution {
  bool solved = false;
  int sweeps = 0;  // Gauss-Seidel sweeps (0: one point, or all stick)
  // How: 1 one point; 2 the approaching points sticking; 3 all sticking; 4 Gauss-Seidel, its
  // sticking points solved together; 5 Gauss-Seidel alone (to 1e-10); 6 Gauss-Seidel, its classes
  // solved together by Newton's method (to rounding).
  int method = 0;
  std::array<double, 3 * kMaxSpatialPoints> p{};  // impulses
  std::array<double, 3 * kMaxSpatialPoints> u{};  // velocities after them
};

// One point: W (3 x 3, row-major), q, v_N; false when no slip direction is consistent (the
// normal compliance along the slip's friction not positive: Painleve at the impulse level).
bool solve_contact_3x3(const double* w, const double* q, double v_normal, double mu_s, double mu_k, double* p);

SpatialContactSolution solve_spatial_contact(const SpatialContactProblem& problem);

}  // namespace blockdyn
