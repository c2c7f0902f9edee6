// SPDX-License-Identifier: Apache-2.0
#pragma once
// A survival point as cells of a runner table (grid_table.hpp) and back: survival and
// response-curve write their points with add_survival_cells and rebuild them from the finished
// table, so their JSON and figures are the same whatever computed the rows. A field added to
// SurvivalPoint (e.g. the dominant cycle) gets a column here.
#include <array>
#include <string>

#include <nlohmann/json.hpp>
#include <vector>

#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"

namespace blockdyn {

// beta, omega, motion, collapse_mode, t_failure, t_star_class, max_abs_rotation, max_sliding, cycle
const std::vector<std::string>& survival_columns();
void add_survival_cells(const SurvivalPoint& p, CellRow& row);
// The point of a row of a table that holds survival_columns() (found by name).
SurvivalPoint survival_point_from(const Table& t, const TableRow& r);

// The summary's points (with the refinement level when the table has one and `with_level`) and
// their counts per motion (rest, stable, collapse, invalid), from a finished table.
struct SurvivalPoints {
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  std::array<long, 4> counts{};  // rest, stable, collapse, invalid
  nlohmann::ordered_json counts_json() const;
};
SurvivalPoints survival_points(const Table& t, bool with_level);
// A response curve's points (beta, omega, theta_max_over_alpha, max_sliding_over_b, motion,
// t_failure; phi_s and phi_l with `with_friction`) from its finished table.
nlohmann::ordered_json response_curve_points(const Table& t, bool with_friction);

}  // namespace blockdyn
