// SPDX-License-Identifier: Apache-2.0
#pragma once
// One block's run of any registered family, from a Scenario to its outputs: the trajectory table
// (CSV or memory), each event as JSON as it happens, and the summary. The command line, the Python
// module and any C++ caller run a block through here; a family is one row of the registry
// (simulate_families()) with its run function.
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/io/scenario.hpp"
#include "blockdyn/simulation/run_clock.hpp"
#include "blockdyn/simulation/trajectory_table.hpp"

namespace blockdyn {

struct SimulateOutputs {
  TrajectoryTable* trajectory = nullptr;  // rows at the scenario's output interval and at events
  double max_output_rows = 1e7;           // refuse a trajectory longer than this (before running)
  // Each event as in the summary's "events" list, as it happens (the run keeps none in memory).
  std::function<void(const nlohmann::ordered_json&)> on_event;
  int timing_repeat = 1;  // repeat the integration (no outputs) and keep the least CPU time
};

// What a figure of the run needs (the plot and animation scripts' arguments).
struct SimulateFigure {
  std::string plot_script;
  std::vector<std::string> plot_args, animate_args;
};

struct SimulateReport {
  nlohmann::ordered_json summary;  // the JSON summary; its "events" member is left empty
  std::string text;                // the summary for a person, a few lines
  SimulateFigure figure;
  RunTiming timing;
};

struct SimulateFamily {
  const char* name;         // the --model value
  const char* description;  // for --help
  SimulateReport (*run)(const Scenario&, const SimulateOutputs&);
};

// Every family a Scenario may name, in the order --help lists them.
const std::vector<SimulateFamily>& simulate_families();
// The family named; throws std::invalid_argument listing the names.
const SimulateFamily& simulate_family(const std::string& name);
// Runs the scenario with its family. Throws std::invalid_argument on bad input (before running).
SimulateReport run_scenario(const Scenario& sc, const SimulateOutputs& out);

}  // namespace blockdyn
