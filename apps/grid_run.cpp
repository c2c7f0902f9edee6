// SPDX-License-Identifier: Apache-2.0
#include "grid_run.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdio>

#include "cli_common.hpp"
#include "mpi_sweep.hpp"

namespace blockdyn::cli {

void add_grid_run_flags(CLI::App& s, GridRunFlags& f) {
  s.add_flag("--resume", f.resume, "continue an interrupted run from its journal (needs the CSV output)");
  s.add_flag("--overwrite", f.overwrite, "replace an existing table (and journal) instead of refusing");
  s.add_option("--progress-interval", f.progress_interval, "seconds between plain progress lines (default 10)");
}

void add_grid_report_flags(CLI::App& s, GridRunFlags& g, bool& json, std::string& json_out, std::string& progress,
                           bool& quiet, const std::string& quiet_help) {
  s.add_flag("--json", json, "print the JSON summary");
  s.add_option("--json-out", json_out, "write the JSON summary here");
  s.add_option("--progress", progress, "auto, bar, plain or none")
      ->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  add_grid_run_flags(s, g);
  s.add_flag("--quiet", quiet, quiet_help);
}

GridOutput::GridOutput(const std::string& csv_flag, const std::string& csv, const std::string& kind,
                       const GridRunFlags& f, const std::string& json_out)
    : csv_(csv) {
  if (f.resume && f.overwrite) throw UsageError("--resume and --overwrite: give only one");
  require_range("progress-interval", f.progress_interval, 0.0, 1e9, false);
  if (csv_.empty()) {
    if (f.resume) throw UsageError("resume: needs " + csv_flag + " F.csv (the table whose journal is resumed)");
    scratch_ = true;
    // Distinct per call: Python may run several tables at once in one process.
    static std::atomic<unsigned> serial{0};
    csv_ = "/tmp/blockdyn-" + kind + "-" + std::to_string(::getpid()) + "-" + std::to_string(serial++) + ".csv";
    const SweepPaths p = sweep_paths(csv_);
    guard_[0] = std::make_unique<RemoveOnSignal>(p.csv);
    guard_[1] = std::make_unique<RemoveOnSignal>(p.journal);
    guard_[2] = std::make_unique<RemoveOnSignal>(p.sidecar);
    for (const std::string& x : {p.csv, p.journal, p.sidecar}) std::remove(x.c_str());
    return;
  }
  require_writable(csv_flag.substr(2), csv_);
  if (!json_out.empty() && json_out == sweep_paths(csv_).sidecar)
    throw UsageError("json-out: '" + json_out + "' is the sidecar of " + csv_flag + " " + csv_ +
                     "; choose another name");
}

GridOutput::~GridOutput() {
  if (!scratch_) return;
  const SweepPaths p = sweep_paths(csv_);
  for (const std::string& x : {p.csv, p.journal, p.sidecar}) std::remove(x.c_str());
}

GridRunResult run_grid(const PointTable& t, const GridRunFlags& f, int threads, const std::string& progress, bool quiet,
                       PointPlan* plan) {
  SweepRunOptions o;
  o.threads = threads;
  o.resume = f.resume;
  o.overwrite = f.overwrite;
  o.progress = quiet ? ProgressMode::None : parse_progress_mode(progress);
  o.progress_interval = f.progress_interval;
  return dispatch_points(t, o, plan);
}

GridRunResult dispatch_points(const PointTable& t, const SweepRunOptions& o, PointPlan* plan) {
  GridRunResult r;
  try {
    if (launched_by_mpi() && (mpi_built() || launcher_world_size() > 1)) {
      const MpiSweepResult m = run_sweep_mpi(t, o, plan);
      r.root = m.root;
      r.outcome = m.outcome;
      r.ranks = m.ranks;
      return r;
    }
    r.outcome = run_sweep(t, o, plan);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());  // existing outputs, an unwritable directory: exit 2
  }
  return r;
}

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

std::string grid_run_note(const GridRunResult& r) {
  const SweepOutcome& o = r.outcome;
  if (o.was_complete) return "(already complete: nothing recomputed)";
  char buf[200];
  std::snprintf(buf, sizeof buf, "(%zu computed, %zu resumed, %.3g s, %.3g points/s, %d rank(s))", o.computed,
                o.resumed, o.wall_seconds, o.wall_seconds > 0 ? double(o.computed) / o.wall_seconds : 0.0, r.ranks);
  return buf;
}

}  // namespace blockdyn::cli
