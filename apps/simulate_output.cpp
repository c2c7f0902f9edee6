// SPDX-License-Identifier: Apache-2.0
#include "simulate_output.hpp"
#include "figure_script.hpp"

#include <cstdio>
#include <optional>

#include "blockdyn/io/csv_table.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {

void add_simulate_output_flags(CLI::App& s, SimulateOutputFlags& f, double default_interval) {
  f.output_interval = default_interval;
  s.add_option("--output-interval", f.output_interval, "trajectory output interval (0: every step; default 0.01)");
  s.add_option("--max-output-rows", f.max_output_rows,
               "refuse a trajectory of more rows than this at the output interval (default 1e7, ~4 GB)");
  s.add_option("--trajectory", f.trajectory, "write the trajectory CSV here");
  s.add_option("--plot", f.plot, "write a plot of the motion (PNG; an SVG is written beside it)");
  s.add_option("--animate", f.animate, "write an animation of the motion: F.gif (Pillow) or F.mp4 (ffmpeg)");
  s.add_option("--animate-frames", f.animate_frames, "frames of the animation, uniform in time (default 120)");
  s.add_flag("--json", f.json, "print the JSON summary on stdout");
  s.add_option("--json-out", f.json_out, "also write the JSON summary to this file");
  s.add_flag("--quiet", f.quiet, "no text summary on stdout");
  s.add_flag("--timing", f.timing,
             "report the integration's wall and CPU time (JSON: timing.integration_wall_s, integration_cpu_s; "
             "not reproducible, so off by default)");
  s.add_option("--timing-repeat", f.timing_repeat,
               "with --timing: repeat the integration this many times in-process and report the least CPU time "
               "(a warm measurement for benchmarks; default 1)")
      ->check(CLI::Range(1, 1000));
}

const std::vector<std::string>& simulate_output_flag_names() {
  static const std::vector<std::string> n{"--trajectory",    "--plot",           "--animate", "--animate-frames",
                                          "--json",          "--json-out",       "--quiet",   "--timing",
                                          "--timing-repeat", "--max-output-rows"};
  return n;
}

SimulateReport run_and_write(const PreparedRun& run, const SimulateOutputFlags& f, const std::string& trajectory,
                             const std::string& plot, const RunCapture& capture) {
  require_writable("plot", plot);
  require_animation(f.animate, f.animate_frames);
  require_writable("trajectory", trajectory);
  require_writable("json-out", f.json_out);
  TrajectoryTarget target(trajectory, plot.empty() ? f.animate : plot);
  std::optional<CsvTable> table;
  if (target.file) table.emplace(target.file->stream());
  std::optional<TableTee> both;
  if (table && capture.table) both.emplace(*table, *capture.table);
  // Events go to a spool of the JSON summary as the run makes them: O(1) memory whatever its length.
  const bool json = f.json || !f.json_out.empty();
  std::unique_ptr<JsonEventSpool> spool;
  if (json) spool = std::make_unique<JsonEventSpool>();
  SimulateOutputs out;
  out.trajectory = both    ? static_cast<TrajectoryTable*>(&*both)
                   : table ? static_cast<TrajectoryTable*>(&*table)
                           : capture.table;
  out.max_output_rows = f.max_output_rows;
  if (spool || capture.on_event)
    out.on_event = [&spool, &capture](const nlohmann::ordered_json& e) {
      if (spool) spool->add(e);
      if (capture.on_event) capture.on_event(e);
    };
  out.timing_repeat = f.timing_repeat;
  const SimulateReport rep = run.run(out);
  const SimulateFigure& figure = rep.figure.get();
  std::vector<std::string> animate_args = figure_arguments(figure.animation);
  animate_args.insert(animate_args.end(), {"--frames", std::to_string(f.animate_frames)});
  target.figures_and_clean({{plot_script(figure.plot), plot, figure_arguments(figure.plot)},
                            {animation_script(figure.animation), f.animate, animate_args}});
  if (spool) {
    nlohmann::ordered_json j = rep.summary.get();
    if (f.timing) j["timing"] = to_json(rep.timing);
    if (!f.json_out.empty()) emit_json(j, f.json_out, *spool);
    if (f.json) emit_json(j, "-", *spool);
  }
  if (!f.json && !f.quiet) std::fputs(rep.text.get().c_str(), stdout);
  if (f.timing && !f.json && !f.quiet)
    std::printf("integration: %.6g s CPU, %.6g s wall\n", rep.timing.cpu_s, rep.timing.wall_s);
  return rep;
}

}  // namespace blockdyn::cli
