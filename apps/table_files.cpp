// SPDX-License-Identifier: Apache-2.0
#include "table_files.hpp"

#include <vector>

#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "study_table_output.hpp"

namespace blockdyn::cli {
namespace {

// Axes with more than one value become plot axes (the first two); the others are held at one value.
void plot_sweep(const SweepDefinition& d, const SweepPaths& paths) {
  std::vector<std::string> args = {paths.csv, d.plot};
  std::vector<const SweepPlotAxis*> varying;
  for (const SweepPlotAxis& a : d.plot_axes) {
    if (a.values.size() > 1 && varying.size() < 2) {
      varying.push_back(&a);
    } else {
      args.push_back("--where");
      args.push_back(a.name + "=" + format_double(a.values.front()));
    }
  }
  for (const auto& h : d.held) {
    args.push_back("--where");
    args.push_back(h);
  }
  if (varying.empty()) throw UsageError("plot: the sweep has no axis with more than one value");
  const char* axis_flag[2] = {"--x", "--y"};
  const char* log_flag[2] = {"--logx", "--logy"};
  for (std::size_t i = 0; i < varying.size(); ++i) {
    args.push_back(axis_flag[i]);
    args.push_back(varying[i]->name);
    const auto& v = varying[i]->values;
    if (varying[i]->log || (v.front() > 0 && v.back() / v.front() >= 100.0)) args.push_back(log_flag[i]);
  }
  args.insert(args.end(), {"--column", d.plot_column, "--t-end", format_double(d.t_end)});
  run_python("plot_sweep.py", args);
}

}  // namespace

GridRunResult write_sweep(const SweepDefinition& d, const SweepRunOptions& o) {
  require_writable("plot", d.plot);
  GridRunResult res = dispatch_points(*d.table, o);
  if (res.root && !d.plot.empty()) plot_sweep(d, res.outcome.paths);
  return res;
}

MapFiles write_map(const Settings& given, const SweepRunOptions& o) {
  const MapStudy m = map_study(given);
  require_writable("plot", m.plot);
  MapFiles f;
  f.table = m.table;
  f.grid = dispatch_points(*m.table, o);
  if (!f.grid.root) return f;  // the other ranks computed their share of the points
  f.boundaries = map_boundaries(given, o.threads);
  f.boundaries_csv = map_boundaries_path(f.grid.outcome.paths.csv);
  write_study_table(f.boundaries_csv, f.boundaries.table, f.boundaries.meta);
  if (!m.plot.empty()) run_python("plot_map.py", {f.grid.outcome.paths.csv, f.boundaries_csv, m.plot, m.title});
  return f;
}

}  // namespace blockdyn::cli
