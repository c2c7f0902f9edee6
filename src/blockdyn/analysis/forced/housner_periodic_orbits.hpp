// SPDX-License-Identifier: Apache-2.0
#pragma once
// Periodic rocking orbits of the Housner block under harmonic forcing a_H = K_s g sin(Omega t)
// (seed 001 sec. 4.1), found by shooting on the impact map, with their Floquet multipliers.
//
// Convention (seed 002): an (m, n) orbit has 2m impacts in n forcing periods (seed 001 calls it
// an (n, k) motion with k = 2m impacts per period 2 pi n / Omega). An orbit is given by one of its
// impacts onto the side theta > 0: the forcing phase psi = Omega t mod 2 pi there and the rate
// right after it, u = theta'+ / (alpha p) > 0.
//   general:   the 2m-impact map P(psi, u) (phase advanced by the flight times, rate after the
//              2m-th impact) has the fixed point P(psi, u) = (psi + 2 pi n, u);
//   symmetric: (m and n odd) the second half of the orbit is the mirror image of the first
//              (theta -> -theta, forcing shifted by n/2 periods): the m-impact map followed by
//              the mirror, H(psi, u) = (psi_m - pi n, -u_m), has the fixed point (psi, u).
// Newton on (psi, u) with a central-difference Jacobian of the map (the shooting Jacobian DP - I
// or D H - I). Stability: the eigenvalues of DP (of DH, squared, for a symmetric orbit) are the
// orbit's Floquet multipliers (a Poincare map of the same orbit); they are also computed from
// the monodromy of the stroboscopic map (the variational equation with saltation matrices over
// n periods), which the output reports as `multipliers`, with the shooting ones beside them.
#include <array>
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/integrate/integrator_options.hpp"
#include "blockdyn/model/common/block_shape.hpp"

namespace blockdyn {

struct RockingForcing {
  BlockShape shape;
  double restitution = -1;  // < 0: Housner's e_H
  double ks = 0.1;          // amplitude K_s (g)
  double omega = 2.0;       // Omega / p
  double e() const;
  double alpha() const { return shape.alpha(); }
  double p() const { return shape.p(); }
  double Omega() const { return omega * shape.p(); }
};
void validate(const RockingForcing& f);

struct OrbitType {
  int m = 1, n = 1;
  bool symmetric = true;
};
void validate(const OrbitType& t);

struct ShootingOptions {
  IntegratorOptions integrator{1e-12, 1e-14};
  double tol = 1e-10;  // |residual| (phase rad, u)
  int max_iterations = 40;
  double fd_step = 1e-7;  // central-difference step of the shooting Jacobian (phase rad, u)
};

struct OrbitImpact {
  double t = 0;                            // s, from the reference impact
  double phase = 0;                        // Omega t mod 2 pi
  double rate_before = 0, rate_after = 0;  // theta' (rad/s)
};

// One pass of the map from the impact (psi, u): the impacts met (with the time origin at the
// start), the largest |theta|, or why the pass failed (overturn, rest, too few impacts).
struct ImpactMapPass {
  bool ok = false;
  std::string failure;
  std::vector<OrbitImpact> impacts;
  double max_abs_rotation = 0;
  std::array<double, 2> image{};     // (psi, u) after the map (general: P; symmetric: H)
  std::array<double, 2> residual{};  // image - (psi + 2 pi n or 0, u)
};
ImpactMapPass impact_map_pass(const RockingForcing& f, const OrbitType& type, double psi, double u,
                              const IntegratorOptions& integ);

struct PeriodicOrbit {
  bool converged = false;
  std::string failure;
  int iterations = 0;
  double residual = 0;
  double phase = 0, velocity = 0;  // psi in [0, 2 pi), u = theta'+ / (alpha p)
  double period = 0;               // n 2 pi / Omega (s)
  double max_abs_rotation = 0;     // rad
  std::vector<OrbitImpact> impacts;
  std::array<std::complex<double>, 2> multipliers{};       // from the monodromy (variational)
  std::array<std::complex<double>, 2> multipliers_fd{};    // from the shooting Jacobian
  std::array<std::complex<double>, 2> half_multipliers{};  // symmetric: of H (shooting Jacobian)
  std::array<double, 4> monodromy{};                       // stroboscopic map, (theta, theta'/p), row-major
  std::array<double, 4> jacobian{};                        // of P or H in (psi, u), row-major
  bool stable = false;                                     // every |multiplier| < 1
  double lyapunov_exponent = 0;                            // log max |multiplier| / period (1/s)
};

PeriodicOrbit find_periodic_orbit(const RockingForcing& f, const OrbitType& type, double psi0, double u0,
                                  const ShootingOptions& o = {});
// The monodromy (stroboscopic map over n periods, from half-way to the first impact) by the
// variational equation with saltation matrices; fills multipliers, monodromy.
void orbit_monodromy(const RockingForcing& f, const OrbitType& type, PeriodicOrbit& orbit,
                     const IntegratorOptions& integ);

// Starting guesses: symmetric (1, n): the two orbits of the linearised model (closed form);
// otherwise the impact reached after `settle_periods` forcing periods of a run from rest (or
// from theta' = u at phase 0 if the block does not uplift), integrated with `integ`.
std::vector<std::array<double, 2>> orbit_guesses(const RockingForcing& f, const OrbitType& type,
                                                 const IntegratorOptions& integ, double settle_periods = 60);

// Every distinct converged orbit from the guesses (duplicates within 1e-6 removed), sorted by u.
std::vector<PeriodicOrbit> find_periodic_orbits(const RockingForcing& f, const OrbitType& type,
                                                const std::vector<std::array<double, 2>>& guesses,
                                                const ShootingOptions& o = {});

}  // namespace blockdyn
