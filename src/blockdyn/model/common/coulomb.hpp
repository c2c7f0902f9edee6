// SPDX-License-Identifier: Apache-2.0
#pragma once
// Coulomb dry friction shared by every model family: static and kinetic coefficients, the
// sticking margin and the direction of a sliding force.
#include <cmath>

namespace blockdyn {

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

// Static (f_s) and kinetic (f_k <= f_s) coefficients of an interface.
struct Coulomb {
  double mu_s = 0.5;
  double mu_k = 0.5;
};

// >= 0 while static friction can hold the contact: mu_s N - |T|.
inline double friction_margin(double mu_s, double N, double T) { return mu_s * N - std::fabs(T); }

// Friction force on a contact slipping with tangential velocity sign `slip`: -mu_k N slip.
inline double kinetic_force(double mu_k, double N, int slip) { return -mu_k * N * slip; }

}  // namespace blockdyn
