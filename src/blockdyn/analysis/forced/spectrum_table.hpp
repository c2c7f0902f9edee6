// SPDX-License-Identifier: Apache-2.0
#pragma once
// An overturning-spectrum row as cells of a runner table (grid_table.hpp) and back, so that
// `blockdyn spectrum` runs on the sweep runner (threads, MPI, journal, resume) and rebuilds its
// JSON and figures from the finished table.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/analysis/forced/overturning_spectrum.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/excitation/pulses.hpp"

namespace blockdyn {

// duration, min_overturning_amplitude, linearised_rect, safe_islands (count), at_scan_floor,
// islands ("from:to;from:to", g), runs, scan (one character per scan amplitude: 1 overturns,
// 0 survives, 2 outside the model)
const std::vector<std::string>& spectrum_columns();
void add_spectrum_cells(const SpectrumRow& r, std::optional<double> linearised_rect, CellRow& row);
SpectrumRow spectrum_row_from(const Table& t, const TableRow& r);

// The finished table's rows, and as the summary's "rows" (duration, min_overturning_amplitude,
// at_scan_floor, linearised_rect for rect pulses, safe_islands, runs, scan_overturned (null: outside
// the model), scan_outside_model).
struct SpectrumPoints {
  std::vector<SpectrumRow> rows;
  nlohmann::ordered_json json = nlohmann::ordered_json::array();
  long runs = 0;  // simulations over all rows
};
SpectrumPoints spectrum_points(const Table& t, PulseShape pulse, double alpha, double p);

}  // namespace blockdyn
