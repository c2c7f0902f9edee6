// SPDX-License-Identifier: Apache-2.0
#pragma once
// Chaos map (issue 9, item 6): over a (beta, omega) grid of seed 002's harmonic excitation
// a_H = beta alpha g cos(Omega t + phase), omega = Omega / p, each point is run from rest through
// a transient and its largest Lyapunov exponent measured (forced_lyapunov.hpp), then classified:
//   rest         never moved after the transient;
//   superstable  came to rest after an accumulation of impacts (exponent -infinity);
//   periodic     exponent / p < -threshold (an attracting orbit);
//   neutral      |exponent / p| <= threshold;
//   chaotic      exponent / p > threshold;
//   collapse     overturned (or an assembly failed) before the end, with t* and the mode;
//   failed       the integration or the tangent failed.
// chaos_point() is a pure function of its arguments (one point, no shared state): a sweep runner
// may call it for any point in any order; chaos_map() runs the grid on threads, each point at
// its own index, so the map is identical for any thread count.
#include <functional>

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/forced_lyapunov.hpp"
#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/io/table_cell.hpp"

namespace blockdyn {

struct ChaosMapOptions {
  SurvivalOptions grid;        // beta and omega axes, phase, threads; excitation must be harmonic
  double total_periods = 150;  // forcing periods per run (grid.t_end instead when use_t_end)
  bool use_t_end = false;
  double transient_periods = 50;  // forcing periods before the tangent starts
  double interval_periods = 1;    // renormalisation interval in forcing periods
  double threshold = 0.01;        // on exponent / p
  IntegratorOptions integrator{1e-10, 1e-12};
};
void validate(const ChaosMapOptions& o);

struct ChaosPoint {
  double beta = 0, omega = 0;
  std::string motion = "rest";
  std::string status;            // of the tangent run (tangent_lyapunov.hpp)
  double exponent = NAN;         // 1/s (-inf: superstable; NaN: none)
  double exponent_nondim = NAN;  // exponent / p
  double exponent_second_half = NAN;
  double t_tangent = NAN;  // when the measurement started (s)
  long impacts = 0;
  std::optional<int> collapse_mode;
  std::optional<double> t_failure;
};

// Thread-safe: the largest Lyapunov exponent of one run under g.
using ForcedLyapunovRun = std::function<ForcedLyapunovOutcome(const GroundMotion& g, const ForcedLyapunovOptions& o)>;

ChaosPoint chaos_point(const ForcedLyapunovRun& run, const ChaosMapOptions& o, double beta, double omega, double alpha,
                       double p);
// Points in row-major order: beta outer, omega inner.
std::vector<ChaosPoint> chaos_map(const ForcedLyapunovRun& run, const ChaosMapOptions& o, double alpha, double p,
                                  const std::function<void(std::size_t)>& progress = {});

// The motions a point may have, in the order counts and summaries list them.
const std::vector<std::string>& chaos_motions();
// The points as the summary's "points" list, and their count per motion (every motion listed).
nlohmann::ordered_json chaos_points_json(const std::vector<ChaosPoint>& pts);
nlohmann::ordered_json chaos_counts_json(const std::vector<ChaosPoint>& pts);
// The table: beta, omega, motion, exponent, exponent_nondim, exponent_second_half, status, impacts,
// collapse_mode, t_failure (empty cells where none).
CellTable chaos_table(const std::vector<ChaosPoint>& pts);

}  // namespace blockdyn
