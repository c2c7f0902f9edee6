// SPDX-License-Identifier: Apache-2.0
// `blockdyn sweep` and `blockdyn map` from Python: the grid in memory on threads, or on the sweep
// runner's files (output, journal, sidecar, the map's boundaries, the figure) as the commands write them.
#include <pybind11/stl.h>

#include <fstream>
#include <iterator>
#include <memory>
#include <string>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/analysis/sweep/table_in_memory.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/map_study.hpp"
#include "blockdyn/commands/sweep_settings.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "python_options.hpp"
#include "table_files.hpp"

namespace blockdyn::python {
namespace {

// A sweep or map grid computed in memory on `threads` threads: (columns, sidecar JSON text).
py::tuple grid_in_memory(const PointTable& table, int threads) {
  Table t;
  {
    py::gil_scoped_release release;
    t = compute_table(table, threads, nullptr);
  }
  return py::make_tuple(study_columns(study_table_of(t)), dump_json(table_sidecar(table, "complete")));
}

// A table run on files: the user's `output`, else scratch files (removed when `scratch` goes)
// that the figure is made from.
Settings with_output(Settings s, const std::string& kind, bool resume, bool overwrite,
                     std::unique_ptr<cli::GridOutput>& scratch) {
  if (s.has("output")) return s;
  cli::GridRunFlags g;
  g.resume = resume;
  g.overwrite = overwrite;
  scratch = std::make_unique<cli::GridOutput>("`output`", "", kind, g, "");
  s.set("output", scratch->csv());
  return s;
}

// The runner's options of a table on files; usage errors name the option.
struct FileRun {
  int threads = 0;
  bool resume = false, overwrite = false;
  std::string progress = "none";
  double progress_interval = 10;
  SweepRunOptions options() const {
    if (resume && overwrite) throw std::invalid_argument("`resume` and `overwrite`: give only one");
    require_in_range("progress-interval", progress_interval, 0.0, 1e9, false);
    SweepRunOptions o;
    o.threads = threads;
    o.resume = resume;
    o.overwrite = overwrite;
    o.progress = parse_progress_mode(progress);
    o.progress_interval = progress_interval;
    return o;
  }
};

// The sidecar the runner wrote (none beside a FIFO or a device: the table's own then).
std::string sidecar_text(const SweepOutcome& out, const PointTable& table) {
  std::ifstream in(out.paths.sidecar);
  if (!in) return dump_json(table_sidecar(table, "complete"));
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace

// `blockdyn sweep` and `blockdyn map`: in memory, or on files through the command line's writers.
void add_tables(py::module_& m) {
  m.def(
      "sweep",
      [](const OptionList& options, int threads) {
        const SweepDefinition d = sweep_definition(settings_of(options));
        return grid_in_memory(*d.table, threads);
      },
      py::arg("options"), py::arg("threads") = 0,
      "Runs `blockdyn sweep`'s grid in memory; returns ({column: array or list}, sidecar JSON text).");
  m.def(
      "map",
      [](const OptionList& options, int threads) {
        const Settings s = settings_of(options);
        const MapStudy study = map_study(s);
        py::tuple grid = grid_in_memory(*study.table, threads);
        MapBoundaries b;
        {
          py::gil_scoped_release release;
          b = map_boundaries(s, threads);
        }
        return py::make_tuple(grid[0], grid[1], study_columns(b.table), dump_json(b.meta));
      },
      py::arg("options"), py::arg("threads") = 0,
      "Runs `blockdyn map` in memory; returns (columns, sidecar JSON text, boundary columns, their meta JSON).");

  m.def(
      "sweep_files",
      [](const OptionList& options, int threads, bool resume, bool overwrite, const std::string& progress,
         double progress_interval) {
        const FileRun run{threads, resume, overwrite, progress, progress_interval};
        const SweepRunOptions o = run.options();
        std::unique_ptr<cli::GridOutput> scratch;
        const SweepDefinition d =
            sweep_definition(with_output(settings_of(options), "sweep", resume, overwrite, scratch));
        cli::GridRunResult r;
        {
          py::gil_scoped_release release;
          r = cli::write_sweep(d, o);
        }
        return py::make_tuple(study_columns(study_table_of(r.outcome.table)), sidecar_text(r.outcome, *d.table));
      },
      py::arg("options"), py::arg("threads") = 0, py::arg("resume") = false, py::arg("overwrite") = false,
      py::arg("progress") = "none", py::arg("progress_interval") = 10.0,
      "Runs `blockdyn sweep` on files (output, journal, sidecar, plot); returns (columns, sidecar JSON text).");
  m.def(
      "map_files",
      [](const OptionList& options, int threads, bool resume, bool overwrite, const std::string& progress,
         double progress_interval) {
        const FileRun run{threads, resume, overwrite, progress, progress_interval};
        const SweepRunOptions o = run.options();
        std::unique_ptr<cli::GridOutput> scratch;
        const Settings s = with_output(settings_of(options), "map", resume, overwrite, scratch);
        cli::MapFiles f;
        {
          py::gil_scoped_release release;
          f = cli::write_map(s, o);
        }
        return py::make_tuple(study_columns(study_table_of(f.grid.outcome.table)),
                              sidecar_text(f.grid.outcome, *f.table), study_columns(f.boundaries.table),
                              dump_json(f.boundaries.meta));
      },
      py::arg("options"), py::arg("threads") = 0, py::arg("resume") = false, py::arg("overwrite") = false,
      py::arg("progress") = "none", py::arg("progress_interval") = 10.0,
      "Runs `blockdyn map` on files (output, journal, sidecar, boundaries CSV, plot); returns (columns, sidecar "
      "JSON text, boundary columns, their meta JSON).");
}

}  // namespace blockdyn::python
