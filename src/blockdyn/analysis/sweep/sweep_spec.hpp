// SPDX-License-Identifier: Apache-2.0
#pragma once
// A parameter sweep: grid axes over k, r (or 1/r), mu and the initial-condition set, plus the
// run options shared by every point. Points are numbered in a fixed order (the row id):
//   index = k_i + n_k * (r_i + n_r * (mu_i + n_mu * ic_i))
// i.e. k varies fastest, then r (or inv_r), then mu, then the initial-condition set.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/model/winkler/winkler_params.hpp"
#include "blockdyn/model/winkler/winkler_state.hpp"
#include "blockdyn/simulation/winkler_simulation.hpp"

namespace blockdyn {

struct SweepInitial {
  std::vector<std::string> sets = {"ic1"};      // ic1 | ic2 | custom: an axis of the grid
  std::optional<double> w0;                     // absolute tilt (ic1 tilt; ic2/custom: w)
  std::optional<double> w0_over_alpha;          // tilt as a fraction of alpha = atan(r), per point
  std::optional<double> x0, y0, vx0, vy0, vw0;  // overrides applied on top of the set
};

struct SweepSpec {
  SweepAxis k = axis_list("k", {1e5});
  SweepAxis r = axis_list("r", {0.5});  // name "r" or "inv_r" (then r = 1 / value)
  SweepAxis mu = axis_list("mu", {0.2});
  SweepInitial initial;
  WinklerRunOptions options = default_options();
  std::vector<std::string> metrics;  // extra per-point columns (see sweep_metrics.hpp)

  // Output settings: not part of the definition (they do not change any row).
  std::string output = "sweep.csv";
  std::string plot;
  std::string plot_column;

  static WinklerRunOptions default_options() {
    WinklerRunOptions o;
    o.t_end = 30.0;
    o.record_events = false;  // sweeps keep counts only, unless a metric asks for the list
    return o;
  }
};

struct SweepPoint {
  std::size_t index = 0;
  std::size_t k_i = 0, r_i = 0, mu_i = 0, ic_i = 0;
  WinklerParams params;
  double inv_r = 0;  // exact when the axis is inv_r, else 1 / r
  std::string ic;
};

std::size_t point_count(const SweepSpec& s);
SweepPoint sweep_point(const SweepSpec& s, std::size_t index);  // index < point_count

// Initial state vector of a point (set + overrides). Throws std::invalid_argument.
WinklerState sweep_initial_state(const SweepSpec& s, const SweepPoint& p);

// Checks axes, sets, overrides, options, and that every point has a valid initial state.
// Throws std::invalid_argument naming the key (and the point, for per-point failures).
void validate(const SweepSpec& s);

// Canonical description of everything that determines the rows (no output paths).
nlohmann::ordered_json definition_json(const SweepSpec& s);

// 64-bit FNV-1a of a string, as 16 hex digits (used to tie a journal to its definition).
std::string fingerprint_hex(const std::string& text);

}  // namespace blockdyn
