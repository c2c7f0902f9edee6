// SPDX-License-Identifier: Apache-2.0
#pragma once
// Reads a sweep definition from TOML. Unknown keys and wrong types are errors naming the key
// (a typo must not silently sweep the wrong thing). Layout (all tables optional):
//   [axes]    k, r | inv_r, mu: number, list, "min:max:points[:log|:lin]" or
//             { min, max, points, spacing = "log" | "linear" }   (k defaults to log spacing)
//   [initial] set = "ic1" | ["ic1", "ic2"], w0 | w0_over_alpha, x0, y0, vx0, vy0, vw0
//   [run]     t_end, rtol, atol, max_steps, event_samples, track_energy,
//             stop_at_first_flight, stop_at_ihor
//   [output]  csv, plot, plot_column, metrics = ["name", ...]
#include <string>

#include "blockdyn/analysis/sweep/sweep_spec.hpp"

namespace blockdyn {

SweepSpec parse_sweep(const std::string& toml_text, const std::string& source_name);
SweepSpec load_sweep(const std::string& path);

}  // namespace blockdyn
