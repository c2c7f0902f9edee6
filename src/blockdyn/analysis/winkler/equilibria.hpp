// SPDX-License-Identifier: Apache-2.0
#pragma once
// Static equilibria of a block resting on the Winkler foundation (thesis 4.3.3).
//
// For a tilt w the vertical balance Ry(h, w) = 1 has one solution h_R(w) (Ry decreases strictly
// in h); equilibria are the zeros of arm(w) = x_R - x evaluated there. Sign convention: arm is
// the signed torque arm of the foundation reaction (torque = arm * Ry = arm), odd in w; for
// w > 0 a negative arm pushes the block back upright. The thesis plots the restoring arm
// (-arm for w > 0), so its energy landscape int_0^w arm_thesis equals our -int_0^w arm.
#include <vector>

#include "blockdyn/model/winkler/winkler_params.hpp"

namespace blockdyn {

// Range in which the equilibrium analysis is defined (the thesis's: r <= 1, k >= 2 keeps at most
// two corners submerged for every resting tilt |w| <= alpha). Throws std::invalid_argument.
void validate_equilibrium_params(const WinklerParams& p);

// h_R(w) = y_R(w) - 1/2: centre height at which the Region carries the weight at tilt w.
double resting_height(const WinklerParams& p, double w);

struct ArmSample {
  double w = 0, h = 0, arm = 0;
  int corners_below = 0;
};
// arm(w) = x_R - x = moment / area at h_R(w).
ArmSample arm_sample(const WinklerParams& p, double w);
inline double equilibrium_arm(const WinklerParams& p, double w) { return arm_sample(p, w).arm; }

// d arm/dw at w = 0 (limit of arm(w)/w, extrapolated from tilts inside the two-corner range).
double upright_arm_slope(const WinklerParams& p);
// The same from the linearisation at h = -1/k: 1/2 - r^2 k / 12 - 1 / (4k) (see docs/equilibria.md).
double upright_arm_slope_linearized(double r, double k);
// d arm/dw at w = alpha from below (for the square block arm(alpha) = 0 by symmetry).
double diagonal_arm_slope(const WinklerParams& p);

// Reduced arm whose zeros in the open interval (0, alpha) are exactly the tilted equilibria:
// g = arm / w, and for the square block (arm(alpha) = 0 by symmetry) g = arm / (w (alpha - w)).
// g(0) and g(alpha) are the one-sided limits, so a branch born at an endpoint is still
// bracketed. g > 0 near w = 0 means the upright is unstable; g decreasing through a zero means
// that equilibrium is stable.
struct ReducedArm {
  explicit ReducedArm(const WinklerParams& p);
  double operator()(double w) const;
  WinklerParams p;
  double alpha;
  bool square;            // r == 1
  double upright_slope;   // d arm/dw at 0
  double diagonal_slope;  // d arm/dw at alpha (square block only, else 0)
  double at0, at_alpha;   // endpoint values of g
};

enum class Stability { Stable, Unstable, Neutral };
const char* to_string(Stability s);

// Upright: w = 0 (always, by symmetry); Diagonal: w = alpha (square block: always, by symmetry).
enum class EquilibriumBranch { Upright, Tilted, Diagonal };
const char* to_string(EquilibriumBranch b);

struct Equilibrium {
  double w = 0;          // tilt, 0 <= w <= alpha
  double h = 0;          // h_R(w) = y - 1/2
  double arm_slope = 0;  // d arm/dw; < 0 stable (energy minimum)
  Stability stability = Stability::Neutral;
  EquilibriumBranch branch = EquilibriumBranch::Tilted;
  int corners_below = 0;
};

struct EquilibriumSearch {
  int scan_points = 256;  // uniform scan cells on [0, alpha] before bracketing
  double w_tol = 1e-12;   // absolute tolerance on w of each refined root
};

// All equilibria with 0 <= w <= alpha, sorted by w (their mirror images -w are equilibria too).
std::vector<Equilibrium> find_equilibria(const WinklerParams& p, const EquilibriumSearch& opt = {});

struct LandscapePoint {
  double w = 0, h = 0, arm = 0;
  double energy = 0;     // -int_0^w arm(q) dq: work to move quasi-statically from (h_R(0), 0)
  double potential = 0;  // V(h_R(w), w) + h_R(w) (springs + gravity) minus its value at w = 0
  int corners_below = 0;
};
// Uniform grid of `points` tilts on [0, alpha]; energy by adaptive Gauss-Kronrod per cell.
// energy and potential agree while only one corner is submerged; with two the thesis's force
// model is not conservative and they part (model/foundation_force.hpp).
std::vector<LandscapePoint> energy_landscape(const WinklerParams& p, int points);

}  // namespace blockdyn
