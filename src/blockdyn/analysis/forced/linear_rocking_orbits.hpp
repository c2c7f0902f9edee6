// SPDX-License-Identifier: Apache-2.0
#pragma once
// Closed form of the symmetric rocking orbits of the LINEARISED Housner block (small alpha) under
// harmonic forcing, the independent reference of the periodic-orbit solver (docs/periodic-orbits.md).
//
// With x = theta / alpha, s = p t, a_H / g = beta alpha sin(omega s + phi) (beta = K_s / alpha,
// omega = Omega / p), the linearised rocking equation is, on the side x > 0 and x < 0,
//     x'' = x - 1 + beta sin(omega s + phi),     x'' = x + 1 + beta sin(omega s + phi),
// with x' -> e x' at x = 0. A symmetric (1, n) orbit (seed 002: 2 impacts per n forcing periods,
// n odd) impacts at s = 0 with forcing phase phi, leaves with x' = u > 0, impacts again at
// sigma = n pi / omega with x' = -u / e, and the second half is the mirror image (the forcing
// changes sign over n half periods). On (0, sigma), with B = beta / (1 + omega^2),
//     x(s) = 1 + (B sin phi - 1) cosh s + (u + B omega cos phi) sinh s - B sin(omega s + phi).
// The two conditions x(sigma) = 0, x'(sigma) = -u / e are linear in (u, sin phi, cos phi);
// eliminating u gives
//     a sin phi + b cos phi = c,   a = (1 + ch)(1 + e),  b = omega sh (1 - e),
//                                  c = (ch - 1)(1 - e) / B,   ch, sh = cosh, sinh(sigma),
// so orbits exist iff c^2 <= a^2 + b^2 (two of them, merging at the fold c^2 = a^2 + b^2), and
//     u = [(ch - 1) - B sin phi (1 + ch) - B omega cos phi sh] / sh   (must be > 0).
// Stability: the half-period map (flow, impact, mirror) has the Jacobian H = -S Phi in (x, x'),
// Phi = [[ch, sh], [sh, ch]], saltation S = [[e, 0], [(a+ - e a-) / x'-, e]] with x'- = -u / e,
// a- = -1 - beta sin phi, a+ = 1 - beta sin phi; the Floquet multipliers of the full orbit are
// the squares of H's eigenvalues (det H = e^2).
#include <array>
#include <complex>
#include <vector>

namespace blockdyn {

struct LinearRockingOrbit {
  double phase = 0;     // forcing phase omega s + phi at the impact onto the side x > 0 (rad, in [0, 2 pi))
  double velocity = 0;  // u = theta' / (alpha p) right after that impact
  bool valid = false;   // u > 0 and x > 0 between the impacts (no other impact)
  std::array<std::complex<double>, 2> half_multipliers{};  // of H
  std::array<std::complex<double>, 2> multipliers{};       // of the full orbit (squares)
  double max_x = 0;                                        // largest theta / alpha on the orbit
};

// Both symmetric (1, n) orbits (n odd) where they exist (empty otherwise).
std::vector<LinearRockingOrbit> linear_symmetric_orbits(double beta, double omega, double e, int n = 1);
// The smallest beta at which symmetric (1, n) orbits exist (the fold): (ch - 1)(1 - e)(1 + omega^2) / hypot(a, b).
double linear_symmetric_fold_beta(double omega, double e, int n = 1);
// Eigenvalues of a real 2 x 2 matrix [[a, b], [c, d]].
std::array<std::complex<double>, 2> eigenvalues2(double a, double b, double c, double d);

}  // namespace blockdyn
