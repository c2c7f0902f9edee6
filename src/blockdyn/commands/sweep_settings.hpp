// SPDX-License-Identifier: Apache-2.0
#pragma once
// `blockdyn sweep`'s definition from options by name: a TOML definition file (option
// "definition"), then the flags given, for the family it names (winkler: k, r | inv_r, mu, ic;
// housner and rigid: the block and --axis NAME=SPEC). The command line runs the resulting table
// on the sweep runner (threads, MPI, journal); Python computes the same rows in memory.
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/commands/option_spec.hpp"
#include "blockdyn/commands/settings.hpp"

namespace blockdyn {

// The options that define a sweep (its rows, output path and figure), without the runner's
// (threads, resume, progress) and the listing flags.
const std::vector<StudyOption>& sweep_options();

struct SweepPlotAxis {
  std::string name;
  std::vector<double> values;
  bool log = false;  // a range spaced logarithmically
};

struct SweepDefinition {
  std::string model;                        // the family's name
  std::shared_ptr<const PointTable> table;  // the points and their rows
  nlohmann::ordered_json definition;        // what determines the rows (the sidecar's)
  std::string output, plot, plot_column;    // plot_column: the figure's column (default resolved)
  std::vector<SweepPlotAxis> plot_axes;     // the axes in grid order
  std::vector<std::string> held;            // NAME=VALUE held fixed in the figure
  double t_end = 0;
};

struct Family;
// The family the options name: "model", else the definition file's `model` key, else the first
// registered; throws std::invalid_argument unless it has a sweep.
const Family& sweep_family(const Settings& s);
// The families' entries (family_registry.cpp): the Winkler block's sweep (axes k, r, mu, ic) and a
// block on rigid ground's (its axes from rigid_axis_catalog()).
SweepDefinition winkler_sweep(const Settings& s, const Family& family);
SweepDefinition rigid_sweep(const Settings& s, const Family& family);
std::vector<std::pair<std::string, std::string>> winkler_sweep_axes();
// The sweep the options define; std::invalid_argument naming the option (or the file's key).
SweepDefinition sweep_definition(const Settings& s);

}  // namespace blockdyn
