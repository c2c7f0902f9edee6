// SPDX-License-Identifier: Apache-2.0
#pragma once
// Running a sweep: rows computed on threads (any order), recorded by one writer (journal +
// progress), then the sorted CSV and the JSON sidecar. SweepSession is the writer's side; it is
// shared by the single-process driver below and the MPI driver (apps/mpi_sweep.cpp), where rank
// 0 owns the session and the other ranks only compute rows. The points run in the stages of a
// PointPlan (point_plan.hpp): all at once for a plain grid, stage by stage for adaptive analyses.
//
// Output files for `--output OUT.csv`:
//   OUT.csv          final table, written atomically when every point is done
//   OUT.json         sidecar (definition, version, tolerances, timing); OUT.csv.json if the
//                    output does not end in .csv
//   OUT.csv.journal  rows finished so far, while the sweep runs (deleted at the end)
#include <cstddef>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/analysis/sweep/point_plan.hpp"
#include "blockdyn/analysis/sweep/point_table.hpp"
#include "blockdyn/analysis/sweep/sweep_journal.hpp"
#include "blockdyn/io/progress.hpp"

namespace blockdyn {

struct SweepPaths {
  std::string csv, journal, sidecar;
};
SweepPaths sweep_paths(const std::string& csv);

struct SweepRunOptions {
  int threads = 0;  // per process; 0: all hardware threads
  bool resume = false;
  bool overwrite = false;
  ProgressMode progress = ProgressMode::Auto;
  double progress_interval = 10.0;  // seconds between plain progress lines
  int ranks = 1;                    // MPI ranks taking part (recorded in the sidecar)
};

struct SweepOutcome {
  std::size_t points = 0, computed = 0, resumed = 0, errors = 0;
  bool was_complete = false;  // --resume found a finished sweep: nothing recomputed
  double wall_seconds = 0;
  SweepPaths paths;
  Table table;  // the rows written, from memory (the CSV is never read back to build a result)
};

// Calls on_row(index, row) under a lock for each index as it finishes, on `threads` threads.
void compute_rows(const PointTable& ev, const std::vector<std::size_t>& indices, int threads,
                  const std::function<void(std::size_t, const SweepRow&)>& on_row);

class SweepSession {
 public:
  // Applies the existing-output policy and opens (or resumes) the journal. Throws
  // std::invalid_argument when outputs exist and neither resume nor overwrite allows using them.
  SweepSession(const PointTable& ev, const SweepRunOptions& o);
  ~SweepSession();

  bool was_complete() const { return was_complete_; }
  std::vector<std::size_t> pending() const;  // every point without a row
  // The unfinished points of the plan's next stage, and starts that stage's progress report;
  // empty when the plan is complete. A stage already finished (resumed) is passed over.
  std::vector<std::size_t> next_stage(PointPlan& plan);
  const CellRow* row(std::size_t index) const;          // a finished row, or nullptr
  void record(std::size_t index, const SweepRow& row);  // not thread-safe
  // Writes the CSV and the final sidecar, removes the journal. `threads`: per rank; `sparse`:
  // the plan left points out (PointPlan::sparse()).
  SweepOutcome finish(int threads, bool sparse = false);

 private:
  nlohmann::ordered_json sidecar(const std::string& status, int threads) const;
  const PointTable& ev_;
  SweepRunOptions opt_;
  SweepPaths paths_;
  std::unique_ptr<SweepJournal> journal_;
  std::unique_ptr<Progress> progress_;
  bool was_complete_ = false;
  bool stream_output_ = false;  // the CSV goes into a FIFO or a device: no sidecar
  std::size_t errors_ = 0;
  double t_start_ = 0;  // steady clock seconds
  std::string started_utc_;
  nlohmann::ordered_json load_at_start_;
};

// Single-process sweep (threads only) of the plan's points (nullptr: every point).
SweepOutcome run_sweep(const PointTable& ev, const SweepRunOptions& o, PointPlan* plan = nullptr);

// What a sidecar says of its table besides paths and timing: schema, run, status, fingerprint,
// point count, columns, definition, tolerances (in that order).
nlohmann::ordered_json table_sidecar(const PointTable& t, const std::string& status);

// Fingerprint recorded by a sidecar whose status is "complete"; "" if absent, unreadable or
// unfinished (lets --resume recognise a finished sweep).
std::string complete_sidecar_fingerprint(const std::string& sidecar_path);

}  // namespace blockdyn
