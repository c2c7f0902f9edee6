// SPDX-License-Identifier: Apache-2.0
#pragma once
// One block's run of any registered family, from a Scenario to its outputs: the trajectory table
// (CSV or memory), each event as JSON as it happens, and the summary. The command line, the Python
// module and any C++ caller run a block through here; a family is one row of the registry
// (families(), family/family.hpp) with its run function.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "blockdyn/commands/settings.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/simulation/run_clock.hpp"
#include "blockdyn/simulation/trajectory_table.hpp"

#include "blockdyn/commands/figure_spec.hpp"

namespace blockdyn {

struct SimulateOutputs {
  TrajectoryTable* trajectory = nullptr;  // rows at the scenario's output interval and at events
  double max_output_rows = 1e7;           // refuse a trajectory longer than this (before running)
  // Each event as in the summary's "events" list, as it happens (the run keeps none in memory).
  std::function<void(const nlohmann::ordered_json&)> on_event;
  int timing_repeat = 1;  // repeat the integration (no outputs) and keep the least CPU time
};

// The run's figures: its plot (drawn from the trajectory's CSV and the figure's path, then the
// spec's inputs) and its animation.
struct SimulateFigure {
  FigureSpec plot, animation;
};

// A value given, or built when first read from what the run kept (a caller that never reads it,
// as most of Python's runs, does not pay for building it).
template <class T>
class Lazy {
 public:
  Lazy& operator=(T v) {
    value_ = std::move(v);
    build_ = nullptr;
    return *this;
  }
  void defer(std::function<T()> build) {
    build_ = std::move(build);
    value_.reset();
  }
  const T& get() const {
    if (!value_) value_ = build_ ? build_() : T{};
    return *value_;
  }
  T take() {
    get();
    return std::move(*value_);
  }

 private:
  mutable std::optional<T> value_;
  std::function<T()> build_;
};

struct SimulateReport {
  Lazy<nlohmann::ordered_json> summary;  // the JSON summary; its "events" member is left empty
  Lazy<std::string> text;                // the summary for a person, a few lines
  Lazy<SimulateFigure> figure;
  RunTiming timing;
};

// A run whose options are parsed and validated, ready to run as often as wanted.
class PreparedRun {
 public:
  virtual ~PreparedRun() = default;
  // Throws std::invalid_argument on bad input (before running).
  virtual SimulateReport run(const SimulateOutputs& out) const = 0;
  // The trajectory and figure paths a scenario file names ([output]), if any.
  virtual std::pair<std::string, std::string> scenario_outputs() const { return {}; }
};

// The families' entries (family_registry.cpp): a block described by a Scenario (winkler,
// housner, rigid) or an assembly, prepared from Settings, and each scenario family's run.
std::unique_ptr<PreparedRun> prepare_block(const Settings& s);
std::unique_ptr<PreparedRun> prepare_assembly(const Settings& s);
SimulateReport run_winkler(const Scenario& sc, const SimulateOutputs& out);
SimulateReport run_housner(const Scenario& sc, const SimulateOutputs& out);
SimulateReport run_rigid(const Scenario& sc, const SimulateOutputs& out);

// The run the Settings describe: the family named by `model` (without it, a scenario file's model,
// else the first registered family). Throws std::invalid_argument naming the option at fault.
std::unique_ptr<PreparedRun> prepare_run(const Settings& s);
// A block's run from a Scenario (winkler, housner, rigid).
SimulateReport run_scenario(const Scenario& sc, const SimulateOutputs& out);

}  // namespace blockdyn
