// SPDX-License-Identifier: Apache-2.0
#pragma once
// The periodic-orbit study of the Housner block under a_H = K_s g sin(Omega t + phi) (seed 001
// sec. 4.1) in its three modes, as documents and tables: the orbits at one point (shooting from a
// guess or from the closed form and runs from rest), their continuation in K_s or omega, and the
// existence and stability map over (K_s, omega). Callable from C++ and Python; the command line
// (`blockdyn periodic-orbits`) only parses and writes.
#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/analysis/forced/housner_periodic_orbits.hpp"
#include "blockdyn/analysis/forced/orbit_continuation.hpp"
#include "blockdyn/analysis/forced/orbit_region_map.hpp"
#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

// The summary's common members: run, model, forcing, convention, integrator.
nlohmann::ordered_json orbit_study_header(const RockingForcing& f, const OrbitType& type, const ShootingOptions& so);

struct OrbitsAtPoint {
  std::vector<PeriodicOrbit> orbits;
  nlohmann::ordered_json summary;  // ks, beta, omega, guesses, orbits, linear theory (symmetric m = 1)
};
// The orbits at (K_s, omega), from `guess` (phase, velocity) or from orbit_guesses().
OrbitsAtPoint orbits_at_point(const RockingForcing& f, const OrbitType& type, const ShootingOptions& so,
                              const std::optional<std::array<double, 2>>& guess);
// Tables: one row per orbit; and the orbits' trajectories over one period (orbit, stable, t, theta, rate).
CellTable orbits_table(const RockingForcing& f, const std::vector<PeriodicOrbit>& orbits);
CellTable orbit_trajectories_table(const RockingForcing& f, const std::vector<PeriodicOrbit>& orbits,
                                   const IntegratorOptions& integ);

struct BranchRow {
  int branch;
  BranchPoint point;
};
struct OrbitBranches {
  std::vector<BranchRow> rows;
  nlohmann::ordered_json summary;  // continuation, branches
  int count = 0;
};
// Every orbit continued both ways (co.direction is set per branch).
OrbitBranches continue_orbits(const RockingForcing& f, const OrbitType& type, const std::vector<PeriodicOrbit>& orbits,
                              ContinuationOptions co);
CellTable branches_table(const RockingForcing& f, const std::vector<BranchRow>& rows);

struct OrbitRegion {
  std::vector<OrbitRegionPoint> points;
  nlohmann::ordered_json summary;  // points, counts, linear fold (symmetric m = 1)
  long with_orbits = 0, with_stable_orbits = 0;
};
OrbitRegion orbit_region(const RockingForcing& f, const OrbitType& type, const OrbitRegionOptions& ro,
                         const std::function<void(std::size_t)>& progress = {});
CellTable region_table(const RockingForcing& f, const std::vector<OrbitRegionPoint>& points);

}  // namespace blockdyn
