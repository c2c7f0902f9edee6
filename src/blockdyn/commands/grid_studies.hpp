// SPDX-License-Identifier: Apache-2.0
#pragma once
// A grid analysis (survival, ...): its points as a runner table with the plan of its stages, built
// from options by name, and its report from the finished table. The command line runs the table on
// the sweep runner (threads, MPI, journal, resume) and reads it back; Python computes it in memory
// (run_grid_study): the same rows, the same report.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/analysis/sweep/point_plan.hpp"
#include "blockdyn/analysis/sweep/table_in_memory.hpp"
#include "blockdyn/commands/study_command.hpp"

namespace blockdyn {

struct GridStudy {
  std::shared_ptr<const GridTable> table;
  std::shared_ptr<PointPlan> plan;  // the stages (null: every point at once)
  int threads = 0;
  // The report from the finished table: summary, text (one line, without the run's note), the
  // figure's script and arguments ("@csv:table" the table's CSV, "@plot" the figure).
  std::function<StudyReport(const Table&)> finish;
};

struct GridStudyCommand {
  std::string name;
  std::string description;  // for --help
  int order = 0;            // position in --help
  std::vector<StudyOption> options;
  // `output`: the table's CSV path (the runner's journal and sidecar beside it; unused in memory).
  GridStudy (*prepare)(const Settings&, const std::string& output) = nullptr;
  std::string csv_flag, csv_help;    // the table's output option ("out", "csv")
  std::vector<StudyOption> figures;  // the figures' output options ("plot", "plot-map")
  std::string quiet_help;            // what --quiet silences
};
const std::vector<GridStudyCommand>& grid_study_commands();
const GridStudyCommand& grid_study_command(const std::string& name);

// A grid study from options by name, in memory; the table as the report's table.
StudyReport run_grid_study(const std::string& name, const Settings& s,
                           const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace blockdyn
