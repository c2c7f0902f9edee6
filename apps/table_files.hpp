// SPDX-License-Identifier: Apache-2.0
#pragma once
// What `blockdyn sweep` and `blockdyn map` write, callable without parsing a command line (the
// commands and Python call these): the table on the sweep runner (CSV, journal, sidecar; resume;
// MPI under mpirun), the map's boundaries CSV beside its table, and the figure.
#include <nlohmann/json.hpp>

#include <memory>
#include <string>

#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/commands/map_study.hpp"
#include "blockdyn/commands/settings.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/commands/sweep_settings.hpp"
#include "grid_run.hpp"

namespace blockdyn::cli {

// The sweep's table and, when the definition names one, its figure.
GridRunResult write_sweep(const SweepDefinition& d, const SweepRunOptions& o);

struct MapFiles {
  std::shared_ptr<const SweepEvaluator> table;  // the grid's points
  GridRunResult grid;
  std::string boundaries_csv;  // OUT_boundaries.csv
  MapBoundaries boundaries;
};
// The map's table, its boundaries beside it and, when asked, its figure (only the root rank of an
// MPI launch has `grid.root` set and writes the boundaries and the figure).
MapFiles write_map(const Settings& given, const SweepRunOptions& o);

}  // namespace blockdyn::cli
