// SPDX-License-Identifier: Apache-2.0
// `blockdyn spectrum`: overturning spectra of a rigid-ground block (housner, rigid) or of an
// assembly preset under a horizontal pulse: the smallest overturning amplitude per duration,
// with the safe islands above it (analysis/forced/overturning_spectrum.hpp) and the whole
// overturn / survive picture of the scan. Durations run on the sweep runner (threads, MPI,
// journal, resume, progress).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "blockdyn/analysis/forced/spectrum_table.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "forced_model.hpp"
#include "grid_run.hpp"

namespace blockdyn::cli {
namespace {

struct SpectrumFlags {
  std::string pulse = "rect";
  std::vector<double> durations;
  double duration_min = 0, duration_max = 0;
  int duration_points = 0;
  SpectrumOptions spec;
  double t_after = 10.0;
  std::string csv, plot, plot_map, json_out, progress = "auto";
  bool json = false, quiet = false;
  GridRunFlags g;
};

std::vector<double> durations_of(const CLI::App& s, const SpectrumFlags& f) {
  const bool list = given(s, "--durations");
  const bool range = given(s, "--duration-min") || given(s, "--duration-max") || given(s, "--duration-points");
  if (list == range)
    throw UsageError(list ? "give --durations or --duration-min/--duration-max/--duration-points, not both"
                          : "give --durations D1,D2,... or --duration-min --duration-max --duration-points");
  if (list) return f.durations;
  require_range("duration-min", f.duration_min, 0, 1e4, false);
  require_range("duration-max", f.duration_max, f.duration_min, 1e4);
  require_range("duration-points", f.duration_points, 1, 100000);
  std::vector<double> d(f.duration_points);
  for (int i = 0; i < f.duration_points; ++i)
    d[i] = f.duration_points == 1
               ? f.duration_min
               : f.duration_min * std::pow(f.duration_max / f.duration_min, double(i) / (f.duration_points - 1));
  return d;
}

GroundMotion pulse_motion(PulseShape shape, double amplitude, double duration) {
  GroundMotion g;
  g.horizontal.pulse = shape;
  g.horizontal.amplitude = amplitude;
  g.horizontal.duration = duration;
  return g;
}

void run(const CLI::App& s, const SpectrumFlags& f) {
  const auto shape = pulse_from_string(f.pulse);
  if (!shape || *shape == PulseShape::None)
    throw UsageError(std::string("pulse = '") + f.pulse + "' must be one of " + pulse_names());
  SpectrumOptions o = f.spec;
  o.durations = durations_of(s, f);
  require_range("t-after", f.t_after, 0, 1e4);
  require_range("threads", o.threads, 0, 1024);
  try {
    validate(o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const GridOutput out("--csv", f.csv, "spectrum", f.g, f.json_out);
  require_writable("plot", f.plot);
  require_writable("plot-map", f.plot_map);
  require_writable("json-out", f.json_out);
  const ForcedModel fm = build_forced_model(s);
  const double alpha = fm.alpha, p = fm.p;
  const double t_after = f.t_after;
  const PulseShape pulse = *shape;
  const OverturnTest test = [&fm, pulse, t_after](double amplitude, double duration) {
    return fm.run(pulse_motion(pulse, amplitude, duration), pulse_support(pulse) * duration + t_after)
        .collapse_mode.has_value();
  };
  using json = nlohmann::ordered_json;
  const json options = {{"amplitude_min", o.amplitude_min},
                        {"amplitude_max", o.amplitude_max},
                        {"scan_points", o.scan_points},
                        {"rel_tol", o.rel_tol},
                        {"t_after", f.t_after},
                        {"overturn", fm.overturn_rule}};
  const json definition = {{"model", fm.description},
                           {"pulse", to_string(pulse)},
                           {"alpha", alpha},
                           {"p", p},
                           {"durations", o.durations},
                           {"options", options},
                           {"index", "the duration's position"}};
  const GridTable table(
      "spectrum", spectrum_columns(), o.durations.size(),
      [&](std::size_t i, RowBuilder& row) {
        const double d = o.durations[i];
        add_spectrum_cells(spectrum_row(test, o, d),
                           pulse == PulseShape::Rect ? std::optional<double>(rect_pulse_overturning_linear(alpha, p, d))
                                                     : std::nullopt,
                           row);
      },
      definition, fm.tolerances, out.csv());
  const GridRunResult res = run_grid(table, f.g, o.threads, f.progress, f.quiet);
  if (!res.root) return;

  const Table t = read_table(out.csv(), table.header());
  json j;
  j["run"] = run_info();
  j["model"] = fm.description;
  j["pulse"] = to_string(pulse);
  j["alpha"] = alpha;
  j["p"] = p;
  j["units"] = "durations in s, amplitudes in g";
  j["options"] = options;
  j["tolerances"] = fm.tolerances;
  j["scan_amplitudes"] = scan_amplitudes(o);
  const SpectrumPoints sp = spectrum_points(t, pulse, alpha, p);
  j["rows"] = sp.json;
  j["runs"] = sp.runs;
  const std::string title = forced_model_choice(s).label() + " " + to_string(pulse) + " pulse";
  if (!f.plot.empty()) run_python("plot_spectrum.py", {out.csv(), f.plot, "--title", title});
  if (!f.plot_map.empty())
    run_python("plot_spectrum.py", {out.csv(), f.plot_map, "--title", title, "--map", format_double(o.amplitude_min),
                                    format_double(o.amplitude_max)});
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet) {
    std::printf("duration [s]  min overturning amplitude [g]  safe islands above\n");
    for (const SpectrumRow& r : sp.rows)
      std::printf("%12.6g  %29s  %zu\n", r.duration,
                  r.min_overturning_amplitude ? std::to_string(*r.min_overturning_amplitude).c_str() : "none in scan",
                  r.safe_islands.size());
    std::printf("%ld simulations %s\n", sp.runs, grid_run_note(res).c_str());
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<SpectrumFlags>();
  CLI::App* s = app.add_subcommand("spectrum",
                                   "overturning spectrum: the smallest pulse amplitude that overturns a block (or "
                                   "collapses an assembly), per pulse duration (s, g) (threads, MPI, resumable)");
  add_forced_model_flags(*s);
  s->add_option("--pulse", f->pulse, std::string("pulse shape: ") + pulse_names() + " (default rect)");
  s->add_option("--durations", f->durations, "pulse durations t_p [s], comma separated")->delimiter(',');
  s->add_option("--duration-min", f->duration_min, "smallest duration [s] (geometric range)");
  s->add_option("--duration-max", f->duration_max, "largest duration [s]");
  s->add_option("--duration-points", f->duration_points, "number of durations");
  s->add_option("--amplitude-min", f->spec.amplitude_min, "smallest scanned amplitude [g] (default 0.01)");
  s->add_option("--amplitude-max", f->spec.amplitude_max, "largest scanned amplitude [g] (default 10)");
  s->add_option("--scan-points", f->spec.scan_points, "amplitudes scanned per duration, geometric (default 40)");
  s->add_option("--rel-tol", f->spec.rel_tol, "relative tolerance of the minimum (default 1e-6)");
  s->add_option("--t-after", f->t_after, "simulated time after the pulse [s] (default 10)");
  s->add_option("--threads", f->spec.threads, "worker threads (0: all cores; default 0)");
  s->add_option("--csv", f->csv, "the spectrum as CSV (the runner's table: journal and sidecar .json beside it)");
  s->add_option("--plot", f->plot, "plot the spectrum (PNG + SVG), with the linearised closed form for rect");
  s->add_option("--plot-map", f->plot_map,
                "plot the overturn / survive picture over (duration, amplitude) from the scan (PNG + SVG)");
  add_grid_report_flags(*s, f->g, f->json, f->json_out, f->progress, f->quiet, "no table, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(13, add, MpiUse::Distributes);

}  // namespace
}  // namespace blockdyn::cli
