// SPDX-License-Identifier: Apache-2.0
#pragma once
// The output flags of a run (`simulate`, `assembly`): trajectory CSV, figure, animation, JSON
// summary, text, timing; and the one function that runs a prepared run into them.
#include <CLI/CLI.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/commands/simulate_run.hpp"

namespace blockdyn::cli {

struct SimulateOutputFlags {
  std::string trajectory, plot, animate, json_out;
  int animate_frames = 120, timing_repeat = 1;
  double output_interval = 0.01, max_output_rows = 1e7;
  bool json = false, quiet = false, timing = false;
};

// --output-interval --max-output-rows --trajectory --plot --animate --animate-frames --json
// --json-out --quiet --timing --timing-repeat.
void add_simulate_output_flags(CLI::App& app, SimulateOutputFlags& f, double default_interval);
// Their names, less --output-interval (a model option: the library reads it).
const std::vector<std::string>& simulate_output_flag_names();
// What a caller keeps of the run besides the files (Python: its NumPy columns and events).
struct RunCapture {
  TrajectoryTable* table = nullptr;
  std::function<void(const nlohmann::ordered_json&)> on_event;
};

// Checks the outputs, runs, writes the CSV, figures, JSON and text. `trajectory` and `plot` are the
// paths to use (a scenario file may name them).
SimulateReport run_and_write(const PreparedRun& run, const SimulateOutputFlags& f, const std::string& trajectory,
                             const std::string& plot, const RunCapture& capture = {});
inline SimulateReport run_and_write(const PreparedRun& run, const SimulateOutputFlags& f) {
  return run_and_write(run, f, f.trajectory, f.plot);
}

}  // namespace blockdyn::cli
