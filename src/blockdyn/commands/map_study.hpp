// SPDX-License-Identifier: Apache-2.0
#pragma once
// The response map of the thesis's chapter 6 (Figs 6.1-6.2) from options by name: every point of
// a (k, 1/r) grid at fixed mu and initial conditions is classified (steady rocking, settle down,
// settled, zero-friction rock-flight, rock to vertical, overturned; optionally sensitive
// dependence) as a sweep table, and the stability boundary, k_high and k_critical are computed on
// a coarser set of 1/r values. The command line runs the table on the sweep runner (threads, MPI,
// journal); Python computes it in memory.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"
#include "blockdyn/commands/study_command.hpp"

namespace blockdyn {

// Every option of the map but --threads, --resume, --overwrite, --quiet.
const std::vector<StudyOption>& map_options();

struct MapStudy {
  std::shared_ptr<const SweepEvaluator> table;  // the grid of classified points
  std::string plot;                             // the figure's path ("" none)
  std::string title;                            // "mu = 0.2, ic1"
  int threads = 0;
};

// The map the options define; std::invalid_argument naming the option.
MapStudy map_study(const Settings& s);
// The boundary curves (the boundaries CSV's table) and their sidecar's meta, on `threads` threads.
struct MapBoundaries {
  StudyTable table;
  nlohmann::ordered_json meta;
};
MapBoundaries map_boundaries(const Settings& s, int threads);
// Where the boundaries go beside the map's CSV: OUT_boundaries.csv.
std::string map_boundaries_path(const std::string& csv);

}  // namespace blockdyn
