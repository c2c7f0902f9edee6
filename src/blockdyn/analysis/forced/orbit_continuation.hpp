// SPDX-License-Identifier: Apache-2.0
#pragma once
// Continuation of a rocking periodic orbit of the Housner block (housner_periodic_orbits.hpp) in
// the forcing amplitude K_s or the frequency omega = Omega / p: pseudo-arclength (Keller) on the
// shooting residual F(psi, u, lambda) = 0 with lambda = K_s / alpha (= beta) or omega, so the
// branch is followed round folds. Along the branch the Floquet multipliers come from the
// shooting Jacobian A = D_(psi,u) (P or H); a sign change of
//   the tangent's lambda component          -> fold (two orbits merge and disappear),
//   det(A - I)                              -> a multiplier crosses +1,
//   det(A + I)                              -> a multiplier crosses -1: period doubling (flip)
//                                              or, for the symmetric half map H, symmetry breaking
//                                              (the full orbit's multiplier crosses +1, a pair of
//                                              asymmetric orbits branches off),
// marks the point. The branch ends where the orbit stops existing as the same impact sequence
// (grazing, an extra impact, overturn: the corrector fails at the smallest step) or leaves the
// parameter range.
#include <complex>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"

namespace blockdyn {

struct ContinuationOptions {
  std::string parameter = "ks";  // ks | omega
  double min = 0, max = 1;       // range of the parameter (ks in g)
  double ds = 0.02, ds_min = 1e-6, ds_max = 0.25;
  int max_points = 400;
  int direction = 1;  // initial direction of the parameter (+1 up, -1 down)
  ShootingOptions shooting;
};
void validate(const ContinuationOptions& o);

struct BranchPoint {
  double ks = 0, omega = 0;
  double phase = 0, velocity = 0;  // the orbit's impact (psi, u)
  double arclength = 0;
  std::array<std::complex<double>, 2> multipliers{};  // full orbit (shooting Jacobian)
  bool stable = false;
  std::string event;  // "", fold, flip, symmetry_breaking, multiplier_+1 (several: joined by '+')
};

struct Branch {
  OrbitType type;
  std::vector<BranchPoint> points;
  std::string end;  // why the branch ended
};

Branch continue_orbit(const RockingForcing& f, const OrbitType& type, double psi, double u,
                      const ContinuationOptions& o);

}  // namespace blockdyn
