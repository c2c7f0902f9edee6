// SPDX-License-Identifier: Apache-2.0
#pragma once
// Survival domains (issue 9; seed 002 Figs. 2, 6-9): over a grid of (beta, omega), with
// a_H = beta alpha g cos(Omega t + phase) and omega = Omega / p, each point is run from rest and
// classified: rest (never left rest), stable (moved, did not fail) or collapse, with the collapse
// mode, t* and its duration class, and the largest rotation. Pulses (half-sine, half-cosine,
// rect) last half a forcing period, pi / Omega. Points run in parallel and land at their own
// index: the map is identical for any thread count.
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "blockdyn/excitation/ground_motion.hpp"
#include "blockdyn/simulation/sim_status.hpp"

namespace blockdyn {

struct SurvivalOptions {
  std::string excitation = "harmonic";  // harmonic | half-sine | half-cosine | rect
  double phase = 0.0;                   // rad, of cos(Omega t + phase)
  double beta_min = 0.5, beta_max = 5, omega_min = 1, omega_max = 20;
  int beta_points = 10, omega_points = 10;
  std::vector<double> betas;  // when given: these betas instead of the uniform range
  double t_end = 20;          // s; with periods > 0: that many forcing periods instead
  double periods = 0;
  std::vector<double> t_star_classes{5, 30, 100, 300};  // upper bounds of the t* classes (s)
  int threads = 0;
};
void validate(const SurvivalOptions& o);

struct SurvivalPoint {
  double beta = 0, omega = 0;
  std::string motion = "rest";  // rest | stable | collapse | invalid
  std::optional<int> collapse_mode;
  std::optional<double> t_failure;
  std::string t_star_class;  // "<=5 s", "short", "medium", "long", "very long" (collapse only)
  double max_abs_rotation = 0;
  double max_sliding = 0;  // m (assemblies: the largest slip between blocks)
  std::string cycle;       // harmonic: the dominant (m, n) cycle label of the run, "" if none
};

struct SurvivalOutcome {
  bool moved = false, invalid = false;
  std::optional<int> collapse_mode;
  std::optional<double> t_failure;
  double max_abs_rotation = 0, max_sliding = 0;
  std::string cycle;  // harmonic motion: the dominant cycle label (cycle_detection.hpp), "" if none
};
// A single block's run classified by how it ended: outside the model (invalid, a numerical
// failure), or overturned (collapse mode 1 at overturn_time).
inline void classify_block_end(SurvivalOutcome& out, SimStatus status, std::optional<double> overturn_time) {
  out.invalid = status == SimStatus::Invalid || status == SimStatus::NumericalFailure;
  if (status == SimStatus::Overturned) {
    out.collapse_mode = 1;
    out.t_failure = overturn_time;
  }
}
// Thread-safe: one run under g to t_end (s).
using SurvivalRun = std::function<SurvivalOutcome(const GroundMotion& g, double t_end)>;

// The ground motion of a point: amplitude beta alpha (g), Omega = omega p.
GroundMotion survival_motion(const SurvivalOptions& o, double beta, double omega, double alpha, double p);
std::string t_star_class(const SurvivalOptions& o, double t_star);

// One point: a pure function of its arguments (the runner's rule: any thread, rank or rerun
// computes the same point). t_end from o.t_end or o.periods.
SurvivalPoint survival_point(const SurvivalRun& run, const SurvivalOptions& o, double alpha, double p, double beta,
                             double omega);
// The value of point i of n uniform from lo to hi (lo when n == 1), as every grid here spaces them.
double grid_value(double lo, double hi, int n, int i);

// (beta, omega) of point k of o's grid (beta outer, omega inner; an explicit beta list, when
// given, must hold beta_points values).
std::pair<double, double> beta_omega_of(const SurvivalOptions& o, std::size_t k);
// point(beta, omega) at every point of o's grid on o.threads threads, each landing at its index
// (the same map for any thread count); progress(done) after each.
void for_each_beta_omega(const SurvivalOptions& o, const std::function<void(std::size_t, double, double)>& point,
                         const std::function<void(std::size_t)>& progress);

// Points in row-major order: beta outer, omega inner.
std::vector<SurvivalPoint> survival_map(const SurvivalRun& run, const SurvivalOptions& o, double alpha, double p,
                                        const std::function<void(std::size_t)>& progress = {});

}  // namespace blockdyn
