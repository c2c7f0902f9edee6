// SPDX-License-Identifier: Apache-2.0
#pragma once
// A point table computed in memory, stage after stage of its plan (the rows the sweep runner
// writes to a file, without a file): what Python and the typed entry points run.
#include <cstddef>
#include <functional>

#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/analysis/sweep/point_plan.hpp"
#include "blockdyn/analysis/sweep/point_table.hpp"

namespace blockdyn {

// The table computed in memory on `threads` threads, stage after stage: the rows the runner writes.
Table compute_table(const PointTable& t, int threads, PointPlan* plan,
                    const std::function<void(std::size_t done, std::size_t total)>& progress = {});

}  // namespace blockdyn
