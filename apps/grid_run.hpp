// SPDX-License-Identifier: Apache-2.0
#pragma once
// The sweep runner for the grid analyses (spectrum, survival, response-curve, and any analysis
// whose points are a GridTable): threads, or MPI ranks under mpirun; the journal and --resume;
// progress with ETA; the table's JSON sidecar. The command then reads the finished table back
// and builds its own JSON and figures from it (docs/sweep.md, "Grid analyses").
#include <CLI/CLI.hpp>

#include <memory>
#include <string>

#include "blockdyn/analysis/sweep/point_plan.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/io/atomic_file.hpp"

namespace blockdyn::cli {

// --resume, --overwrite, --progress-interval (the commands already have --progress, --quiet and
// --threads).
struct GridRunFlags {
  bool resume = false, overwrite = false;
  double progress_interval = 10;
};
void add_grid_run_flags(CLI::App& s, GridRunFlags& f);
// The report flags of a grid command: --json, --json-out, --progress, the runner's flags above and
// --quiet (quiet_help: what it silences).
void add_grid_report_flags(CLI::App& s, GridRunFlags& g, bool& json, std::string& json_out, std::string& progress,
                           bool& quiet, const std::string& quiet_help);

// Where the table goes: the user's CSV (the journal and sidecar beside it), or, when only JSON
// or a figure was asked for, scratch files removed at the end (also on SIGINT/SIGTERM); such a
// run cannot be resumed. Checks the flags against it (exit 2 naming the field): --resume needs a
// CSV, --resume and --overwrite exclude each other, a JSON summary must not overwrite the sidecar.
class GridOutput {
 public:
  GridOutput(const std::string& csv_flag, const std::string& csv, const std::string& kind, const GridRunFlags& f,
             const std::string& json_out);
  ~GridOutput();
  GridOutput(const GridOutput&) = delete;
  GridOutput& operator=(const GridOutput&) = delete;
  const std::string& csv() const { return csv_; }
  bool scratch() const { return scratch_; }

 private:
  std::string csv_;
  bool scratch_ = false;
  std::unique_ptr<RemoveOnSignal> guard_[3];
};

struct GridRunResult {
  bool root = true;  // only the root rank reads the table, writes outputs and prints
  SweepOutcome outcome;
  int ranks = 1;
};
// Runs the table (the plan's stages; nullptr: every point) as `blockdyn sweep` runs its points.
GridRunResult run_grid(const PointTable& t, const GridRunFlags& f, int threads, const std::string& progress, bool quiet,
                       PointPlan* plan = nullptr);

// The one MPI dispatch of every command that distributes points: over the ranks of an mpirun
// launch (results byte-identical to one rank; only the root's result has root = true), else
// over threads. Usage errors (existing outputs, an unwritable directory) throw UsageError.
GridRunResult dispatch_points(const PointTable& t, const SweepRunOptions& o, PointPlan* plan = nullptr);

// A number for a figure's title (%.4g).
std::string short_number(double v);

// "(N computed, M resumed, 12.3 s, 45.6 points/s, 2 rank(s))" for the command's summary line.
std::string grid_run_note(const GridRunResult& r);

}  // namespace blockdyn::cli
