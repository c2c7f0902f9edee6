// SPDX-License-Identifier: Apache-2.0
#pragma once
// An overturning-spectrum row as cells of a runner table (grid_table.hpp) and back, so that
// `blockdyn spectrum` runs on the sweep runner (threads, MPI, journal, resume) and rebuilds its
// JSON and figures from the finished table.
#include <optional>
#include <string>
#include <vector>

#include "blockdyn/analysis/forced/overturning_spectrum.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"

namespace blockdyn {

// duration, min_overturning_amplitude, linearised_rect, safe_islands (count), at_scan_floor,
// islands ("from:to;from:to", g), runs, scan (one character per scan amplitude: 1 overturns,
// 0 survives)
const std::vector<std::string>& spectrum_columns();
void add_spectrum_cells(const SpectrumRow& r, std::optional<double> linearised_rect, RowBuilder& row);
SpectrumRow spectrum_row_from(const Table& t, const TableRow& r);

}  // namespace blockdyn
