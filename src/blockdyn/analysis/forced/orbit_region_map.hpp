// SPDX-License-Identifier: Apache-2.0
#pragma once
// Where a rocking periodic orbit of the Housner block exists and where it is stable, over the
// (K_s, omega) plane (seed 001 sec. 4.1): at each grid point every orbit of the asked type that
// Newton reaches from the guesses (the linearised closed form for symmetric (1, n) orbits, runs
// from rest otherwise) and from the orbits found at the previous K_s of the same omega row
// (a natural continuation along the row), with its stability. Rows run on threads; each point
// lands at its own index, so the map is identical for any thread count. Beside each point the
// linearised model's answer (closed form) for symmetric (1, n) orbits.
#include <functional>
#include <vector>

#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"

namespace blockdyn {

struct OrbitRegionOptions {
  double ks_min = 0.01, ks_max = 0.5, omega_min = 1, omega_max = 10;
  int ks_points = 20, omega_points = 20;
  int threads = 0;
  ShootingOptions shooting;
};
void validate(const OrbitRegionOptions& o);

struct OrbitRegionPoint {
  double ks = 0, omega = 0;
  int orbits = 0, stable = 0;                  // found by Newton
  double phase = NAN, velocity = NAN;          // the most stable orbit found
  double max_multiplier = NAN;                 // its largest |multiplier|
  int linear_orbits = -1, linear_stable = -1;  // closed form (symmetric (1, n) only; -1: not available)
};

// Row-major: K_s outer, omega inner.
std::vector<OrbitRegionPoint> orbit_region_map(const RockingForcing& base, const OrbitType& type,
                                               const OrbitRegionOptions& o,
                                               const std::function<void(std::size_t)>& progress = {});

// One period of an orbit sampled at `samples` times from its reference impact: t (s from the
// impact), theta, theta'.
struct OrbitSamples {
  std::vector<double> t, theta, rate;
};
OrbitSamples orbit_trajectory(const RockingForcing& f, const PeriodicOrbit& orbit, const IntegratorOptions& integ,
                              int samples = 400);

}  // namespace blockdyn
