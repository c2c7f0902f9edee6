// SPDX-License-Identifier: Apache-2.0
#pragma once
// Bifurcations of the static equilibria as the foundation stiffness k varies (thesis 4.3.3):
// k_os(r), below which the upright loses stability (a stable tilted branch is born at w = 0),
// and k_uns(r), below which no stable equilibrium is left in 0 <= w <= alpha (the stable and
// the unstable tilted branches meet in a fold). For the square block the stable branch instead
// runs into w = alpha, which is stable for k < k_uns(1).
#include <vector>

#include "blockdyn/analysis/winkler/equilibria.hpp"

namespace blockdyn {

// Root of the linearised upright slope (k^2 r^2 - 6k + 3 = 0, larger root): (3 + sqrt(9 - 3r^2)) / r^2.
double k_os_linearized(double r);
// The thesis's small-r form of it: 6 / r^2 - 1/2.
double k_os_small_angle(double r);

// Fold in the one-corner range (the Region a triangle): there the tilted equilibria obey
// k = (8r/9) (1 - t^2)^2 / ((r - t)^2 t) with t = tan w, whose minimum sits at
// t^3 - 3 r t^2 + 3 t - r = 0, i.e. t = tanh(atanh(r) / 3). Valid while d <= r sin w there
// (checked numerically for 0.02 <= r <= 1; see docs/equilibria.md).
double fold_tilt_one_corner(double r);
double k_uns_one_corner(double r);

// k where d arm/dw at w = 0 changes sign, solved numerically from the Region integrals.
double find_k_os(double r);
// Minimum over 0 <= w <= alpha of the reduced arm g (ReducedArm); > 0 means no tilted equilibrium.
double reduced_arm_minimum(const WinklerParams& p, int scan_points = 256);
// k_uns: r < 1, the fold where min g crosses 0 below k_os; r = 1, where d arm/dw at alpha changes sign.
double find_k_uns(double r);

struct CriticalStiffness {
  double r = 0, k_os = 0, k_uns = 0;
};
CriticalStiffness critical_stiffness(double r);
// One entry per r (parallel, results by index: identical for any thread count).
std::vector<CriticalStiffness> critical_curves(const std::vector<double>& rs, int threads);

struct BifurcationSample {
  double k = 0;
  std::vector<Equilibrium> equilibria;
};
std::vector<BifurcationSample> bifurcation_diagram(double r, const std::vector<double>& ks, int threads);

// n points from a to b, uniform in k or in log k.
std::vector<double> sample_range(double a, double b, int n, bool logarithmic);

}  // namespace blockdyn
