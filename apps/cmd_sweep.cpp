// SPDX-License-Identifier: Apache-2.0
// `blockdyn sweep`: a grid of runs, from a TOML definition and/or flags; threads, MPI, resumable
// journal, progress, CSV + JSON sidecar, plot. The axes come from the model family: k, r (or 1/r),
// mu and initial conditions for the Winkler block; the block's shape, interface, impact, initial
// state and ground motion (--axis NAME=SPEC) for the housner and rigid models.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/analysis/sweep/sweep_toml.hpp"
#include "blockdyn/api/ground_settings.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/scenario.hpp"
#include "blockdyn/io/toml_read.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "grid_run.hpp"
#include "mpi_sweep.hpp"

namespace blockdyn::cli {
namespace {

struct SweepFlags {
  std::string file;
  std::string model;
  std::vector<std::string> axes;  // housner/rigid: NAME=SPEC
  double width = 0, height = 0, mass = 1, g = 9.81, mu_s = 0.7, mu_k = 0.7, restitution = 0;
  std::string impact = "housner";
  std::string k, r, inv_r, mu, ic;
  double w0 = 0, w0_over_alpha = 0, x0 = 0, y0 = 0, vx0 = 0, vy0 = 0, vw0 = 0;
  double t_end = 30;
  IntegratorOptions integ;
  long max_steps = 0, stop_at_ihor = 0;
  bool stop_at_first_flight = false, no_energy = false;
  std::vector<std::string> metrics;
  std::string output, plot, plot_column, progress = "auto";
  double progress_interval = 10;
  int threads = 0;
  bool resume = false, overwrite = false, quiet = false, list_metrics = false, list_axes = false, dry_run = false;
};

std::vector<std::string> split_list(const std::string& s) {
  std::vector<std::string> out;
  std::string cur;
  for (char c : s) {
    if (c == ',') {
      out.push_back(cur);
      cur.clear();
    } else if (c != ' ') {
      cur += c;
    }
  }
  out.push_back(cur);
  return out;
}

// The initial-state overrides (--x0 --y0 --vx0 --vy0 --vw0) and the run's flags (--t-end --rtol
// --atol --method --max-steps --no-energy) both families share.
template <class Initial, class Options>
void apply_state_and_run_flags(const CLI::App& s, const SweepFlags& f, Initial& initial, Options& options) {
  if (given(s, "--x0")) initial.x0 = f.x0;
  if (given(s, "--y0")) initial.y0 = f.y0;
  if (given(s, "--vx0")) initial.vx0 = f.vx0;
  if (given(s, "--vy0")) initial.vy0 = f.vy0;
  if (given(s, "--vw0")) initial.vw0 = f.vw0;
  if (given(s, "--t-end")) options.t_end = f.t_end;
  if (given(s, "--rtol")) options.integrator.rtol = f.integ.rtol;
  if (given(s, "--atol")) options.integrator.atol = f.integ.atol;
  if (given(s, "--method")) options.integrator.method = f.integ.method;
  if (given(s, "--max-steps")) options.integrator.max_steps = f.max_steps;
  if (given(s, "--no-energy")) options.track_energy = false;
}

SweepSpec build_spec(const CLI::App& s, const SweepFlags& f) {
  SweepSpec sp = f.file.empty() ? SweepSpec{} : load_sweep(f.file);
  if (given(s, "--r") && given(s, "--inv-r")) throw UsageError("--r and --inv-r: give only one aspect-ratio axis");
  if (given(s, "--k")) sp.k = parse_axis("k", f.k, AxisSpacing::Log);
  if (given(s, "--r")) sp.r = parse_axis("r", f.r, AxisSpacing::Linear);
  if (given(s, "--inv-r")) sp.r = parse_axis("inv_r", f.inv_r, AxisSpacing::Linear);
  if (given(s, "--mu")) sp.mu = parse_axis("mu", f.mu, AxisSpacing::Linear);
  if (given(s, "--ic")) sp.initial.sets = split_list(f.ic);
  if (given(s, "--w0") && given(s, "--w0-over-alpha")) throw UsageError("--w0 and --w0-over-alpha: give only one");
  if (given(s, "--w0")) {
    sp.initial.w0 = f.w0;
    sp.initial.w0_over_alpha.reset();
  }
  if (given(s, "--w0-over-alpha")) {
    sp.initial.w0_over_alpha = f.w0_over_alpha;
    sp.initial.w0.reset();
  }
  apply_state_and_run_flags(s, f, sp.initial, sp.options);
  if (given(s, "--stop-at-first-flight")) sp.options.stop_at_first_flight = f.stop_at_first_flight;
  if (given(s, "--stop-at-ihor")) sp.options.stop_at_ihor = f.stop_at_ihor;
  if (given(s, "--metric")) sp.metrics = f.metrics;
  if (given(s, "--output")) sp.output = f.output;
  if (given(s, "--plot")) sp.plot = f.plot;
  if (given(s, "--plot-column")) sp.plot_column = f.plot_column;
  validate(sp);
  if (sp.output.empty()) throw UsageError("output: the CSV path is empty");
  require_writable("plot", sp.plot);
  return sp;
}

struct PlotAxis {
  std::string name;
  std::vector<double> values;
  bool log = false;
};

// Axes with more than one value become plot axes (the first two); the others are held at one value.
void plot_table(const std::vector<PlotAxis>& axes, const std::vector<std::string>& held, const SweepPaths& paths,
                const std::string& out, const std::string& column, double t_end) {
  std::vector<std::string> args = {paths.csv, out};
  std::vector<const PlotAxis*> varying;
  for (const PlotAxis& a : axes) {
    if (a.values.size() > 1 && varying.size() < 2) {
      varying.push_back(&a);
    } else {
      args.push_back("--where");
      args.push_back(a.name + "=" + format_double(a.values.front()));
    }
  }
  for (const auto& h : held) {
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
  args.push_back("--column");
  args.push_back(column);
  args.push_back("--t-end");
  args.push_back(format_double(t_end));
  run_python("plot_sweep.py", args);
}

PlotAxis plot_axis(const SweepAxis& a) { return {a.name, a.values, a.is_range && a.spacing == AxisSpacing::Log}; }

void plot(const SweepSpec& sp, const SweepPaths& paths) {
  std::vector<std::string> held;
  if (sp.initial.sets.size() > 1) held.push_back("ic=" + sp.initial.sets.front());
  plot_table({plot_axis(sp.k), plot_axis(sp.r), plot_axis(sp.mu)}, held, paths, sp.plot,
             sp.plot_column.empty() ? "first_flight_time" : sp.plot_column, sp.options.t_end);
}

void plot(const RigidSweepSpec& sp, const SweepPaths& paths) {
  std::vector<PlotAxis> axes;
  for (const auto& a : sp.axes) axes.push_back(plot_axis(a));
  plot_table(axes, {}, paths, sp.plot, sp.plot_column.empty() ? "max_abs_rotation_over_alpha" : sp.plot_column,
             sp.options.t_end);
}

void list_metrics() {
  for (const auto& m : metric_catalog()) {
    const auto cols = m.make()->columns();
    std::string c;
    for (const auto& x : cols) c += (c.empty() ? "" : ",") + x;
    // Name on its own line: names are longer than any fixed column (sensitive_dependence).
    std::printf("%s\n    %s\n    columns: %s\n", m.name.c_str(), m.description.c_str(), c.c_str());
  }
}

// The rigid-family definition: a sweep file (model = "housner" | "rigid") and/or flags.
RigidSweepSpec build_rigid_spec(const CLI::App& s, const SweepFlags& f, const std::string& model) {
  for (const char* n :
       {"--k", "--r", "--inv-r", "--mu", "--ic", "--metric", "--stop-at-first-flight", "--stop-at-ihor"})
    if (given(s, n)) throw UsageError(std::string(n) + " belongs to the winkler sweep, not to --model " + model);
  RigidSweepSpec sp;
  if (f.file.empty())
    sp.block.shape.width = sp.block.shape.height = 0.0;  // the block must be given
  else
    sp = load_rigid_sweep(f.file);
  sp.model = model;
  if (given(s, "--width")) sp.block.shape.width = f.width;
  if (given(s, "--height")) sp.block.shape.height = f.height;
  if (given(s, "--mass")) sp.block.shape.mass = f.mass;
  if (given(s, "--g")) sp.block.shape.g = f.g;
  if (given(s, "--mu-s")) {
    sp.block.interface.mu_s = f.mu_s;
    if (!given(s, "--mu-k")) sp.block.interface.mu_k = f.mu_s;
  }
  if (given(s, "--mu-k")) sp.block.interface.mu_k = f.mu_k;
  if (given(s, "--restitution")) sp.block.restitution = f.restitution;
  if (given(s, "--impact")) sp.block.impact = *impact_law_from_string(f.impact);
  apply_ground_settings(settings_of(s), sp.ground);
  if (given(s, "--w0") && given(s, "--w0-over-alpha")) throw UsageError("--w0 and --w0-over-alpha: give only one");
  if (given(s, "--w0")) {
    sp.initial.w0 = f.w0;
    sp.w0_over_alpha.reset();
  }
  if (given(s, "--w0-over-alpha")) {
    sp.w0_over_alpha = f.w0_over_alpha;
    sp.initial.w0 = 0.0;
  }
  apply_state_and_run_flags(s, f, sp.initial, sp.options);
  for (const auto& a : f.axes) {
    const auto eq = a.find('=');
    if (eq == std::string::npos || eq == 0)
      throw UsageError("--axis '" + a + "': expected NAME=SPEC, e.g. ground_h_amplitude=0.1:1:20");
    const std::string name = a.substr(0, eq);
    for (const auto& x : sp.axes)
      if (x.name == name) throw UsageError("--axis " + name + ": given twice (or also in the definition file)");
    sp.axes.push_back(parse_axis(name, a.substr(eq + 1), AxisSpacing::Linear));
  }
  if (given(s, "--output")) sp.output = f.output;
  if (given(s, "--plot")) sp.plot = f.plot;
  if (given(s, "--plot-column")) sp.plot_column = f.plot_column;
  bool has_width = sp.block.shape.width > 0, has_height = sp.block.shape.height > 0;
  for (const auto& a : sp.axes) {
    has_width |= a.name == "width" || a.name == "b_over_h" || a.name == "h_over_b";
    has_height |= a.name == "height";
  }
  if (!has_width || !has_height)
    throw UsageError(std::string("the ") + model + " sweep needs the block's " + (has_width ? "height" : "width") +
                     ": --width and --height [m] (or [physical] in the definition, or an axis)");
  validate(sp);
  if (sp.output.empty()) throw UsageError("output: the CSV path is empty");
  require_writable("plot", sp.plot);
  return sp;
}

// The model family of this sweep: --model, else the definition file's `model` key, else winkler.
std::string sweep_model(const CLI::App& s, const SweepFlags& f) {
  if (given(s, "--model")) return f.model;
  if (!f.file.empty()) {
    const toml::table root = toml_read::parse(toml_read::read_file(f.file, "sweep file"), f.file);
    if (const auto v = root["model"].value<std::string>()) return *v;
  }
  return "winkler";
}

void execute(const PointTable& ev, const SweepFlags& f, const nlohmann::ordered_json& definition,
             const std::string& plot_column, const std::function<void(const SweepPaths&)>& make_plot) {
  if (!plot_column.empty()) {
    const auto& c = ev.columns();
    if (std::find(c.begin(), c.end(), plot_column) == c.end())
      throw UsageError("plot-column = '" + plot_column + "' is not a column of this sweep (see --dry-run)");
  }
  if (f.dry_run) {
    nlohmann::ordered_json j;
    j["run"] = run_info();
    j["point_count"] = ev.size();
    j["fingerprint"] = ev.fingerprint();
    j["columns"] = ev.columns();
    j["outputs"] = {{"csv", sweep_paths(ev.output()).csv},
                    {"sidecar", sweep_paths(ev.output()).sidecar},
                    {"journal", sweep_paths(ev.output()).journal}};
    j["definition"] = definition;
    emit_json(j, "-");
    return;
  }
  SweepRunOptions o;
  o.threads = f.threads;
  o.resume = f.resume;
  o.overwrite = f.overwrite;
  o.progress = f.quiet ? ProgressMode::None : parse_progress_mode(f.progress);
  o.progress_interval = f.progress_interval;
  const GridRunResult res = dispatch_points(ev, o);
  if (!res.root) return;  // only rank 0 reports
  const SweepOutcome& out = res.outcome;
  const int ranks = res.ranks;
  make_plot(out.paths);
  if (f.quiet) return;
  if (out.was_complete) {
    std::printf("sweep: %zu points already complete in %s (nothing recomputed)\n", out.points, out.paths.csv.c_str());
    return;
  }
  std::printf("sweep: %zu points (%zu computed, %zu resumed, %zu errors) in %.3g s, %.3g points/s, %d rank(s)\n",
              out.points, out.computed, out.resumed, out.errors, out.wall_seconds,
              out.wall_seconds > 0 ? double(out.computed) / out.wall_seconds : 0.0, ranks);
  std::printf("wrote %s and %s\n", out.paths.csv.c_str(), out.paths.sidecar.c_str());
}

void list_rigid_axes() {
  for (const auto& [name, what] : rigid_axis_catalog()) std::printf("%-20s %s\n", name.c_str(), what.c_str());
}

void run(const CLI::App& s, const SweepFlags& f) {
  if (f.list_metrics) {
    list_metrics();
    return;
  }
  if (f.resume && f.overwrite) throw UsageError("--resume and --overwrite: give only one");
  require_range("threads", f.threads, 0, 4096);
  require_range("progress-interval", f.progress_interval, 0.0, 1e9, false);
  const std::string model = sweep_model(s, f);
  if (model != "winkler" && !is_rigid_family(model))
    throw UsageError("model = '" + model + "' is not one of: winkler, housner, rigid");
  if (f.list_axes) {
    if (model == "winkler")
      std::printf("k, r | inv_r, mu, ic (flags --k --r --inv-r --mu --ic; [axes] in a definition file)\n");
    else
      list_rigid_axes();
    return;
  }
  if (is_rigid_family(model)) {
    const RigidSweepSpec sp = build_rigid_spec(s, f, model);
    const RigidSweepEvaluator ev(sp);
    execute(ev, f, ev.definition(), sp.plot_column, [&](const SweepPaths& p) {
      if (!sp.plot.empty()) plot(sp, p);
    });
    return;
  }
  for (const char* n : {"--axis", "--width", "--height", "--mass", "--mu-s", "--mu-k", "--restitution", "--impact"})
    if (given(s, n)) throw UsageError(std::string(n) + " belongs to --model housner|rigid sweeps");
  const SweepSpec sp = build_spec(s, f);
  const SweepEvaluator ev(sp);
  execute(ev, f, definition_json(sp), sp.plot_column, [&](const SweepPaths& p) {
    if (!sp.plot.empty()) plot(sp, p);
  });
}

void add(CLI::App& app) {
  auto f = std::make_shared<SweepFlags>();
  CLI::App* s =
      app.add_subcommand("sweep",
                         "parameter sweep with the model family's axes (winkler: k, r, mu, ic; housner/rigid: --axis) "
                         "(threads, MPI, resumable)");
  s->footer(
      "Axis values: a list \"v1,v2,...\" or a range \"min:max:points[:log|:lin]\" (k: log by default).\n"
      "Points are numbered index = k_i + n_k*(r_i + n_r*(mu_i + n_mu*ic_i)). See docs/sweep.md.");
  s->add_option("definition", f->file, "TOML sweep definition (flags given as well override it)")
      ->check(CLI::ExistingFile);
  s->add_option("--model", f->model, "model family: winkler (default), housner, rigid")
      ->check(CLI::IsMember({"winkler", "housner", "rigid"}));
  s->add_option("--axis", f->axes,
                "housner/rigid: an axis NAME=SPEC (repeatable; the first varies fastest), e.g. "
                "ground_h_amplitude=0.1:1:20 (see --list-axes)");
  s->add_flag("--list-axes", f->list_axes, "list the axes of the model family and exit");
  s->add_option("--width", f->width, "housner/rigid: block width [m]");
  s->add_option("--height", f->height, "housner/rigid: block height [m]");
  s->add_option("--mass", f->mass, "housner/rigid: block mass [kg] (default 1)");
  s->add_option("--g", f->g, "housner/rigid: gravity [m/s^2] (default 9.81)");
  s->add_option("--mu-s", f->mu_s, "rigid: static friction (default 0.7)");
  s->add_option("--mu-k", f->mu_k, "rigid: kinetic friction (default mu-s)");
  s->add_option("--restitution", f->restitution, "housner/rigid: restitution in [0, 1]");
  s->add_option("--impact", f->impact, "rigid: impact law housner or newton")
      ->check(CLI::IsMember({"housner", "newton"}));
  add_spec_options(*s, ground_options());
  s->add_option("--k", f->k, "stiffness axis, e.g. 1e2:1e8:40 (log) or 1e4,1e5");
  s->add_option("--r", f->r, "aspect-ratio axis r = width/height, e.g. 0.1:1:10 or 0.2");
  s->add_option("--inv-r", f->inv_r, "slenderness axis 1/r, e.g. 1:20:30");
  s->add_option("--mu", f->mu, "friction axis, e.g. 0.2 or 0.1,0.2,0.3");
  s->add_option("--ic", f->ic, "initial-condition sets, comma-separated: ic1, ic2, custom");
  s->add_option("--w0", f->w0, "initial tilt w0 (ic1 tilt; ic2/custom: w)");
  s->add_option("--w0-over-alpha", f->w0_over_alpha, "initial tilt as a fraction of alpha = atan(r), in [-1, 1]");
  s->add_option("--x0", f->x0, "initial x (overrides the set)");
  s->add_option("--y0", f->y0, "initial y (overrides the set)");
  s->add_option("--vx0", f->vx0, "initial x' (overrides the set)");
  s->add_option("--vy0", f->vy0, "initial y' (overrides the set)");
  s->add_option("--vw0", f->vw0, "initial w' (overrides the set)");
  s->add_option("--t-end", f->t_end, "final time of every run (default 30)");
  add_tolerance_options(*s, f->integ);
  s->add_option("--max-steps", f->max_steps, "step limit per run (> 0)");
  s->add_flag("--stop-at-first-flight", f->stop_at_first_flight, "stop each run at its first take-off");
  s->add_option("--stop-at-ihor", f->stop_at_ihor, "stop each run once ihor reaches N (0: never)");
  s->add_flag("--no-energy", f->no_energy, "do not track the energy balance (max_abs_energy_error left empty)");
  s->add_option("--metric", f->metrics, "extra per-point columns by name (repeatable; see --list-metrics)");
  s->add_flag("--list-metrics", f->list_metrics, "list the available metrics and exit");
  s->add_option("-o,--output", f->output, "output CSV (default sweep.csv); sidecar .json and .journal beside it");
  s->add_option("--threads", f->threads, "worker threads per process (0: all cores; under MPI: cores per rank)")
      ->capture_default_str();
  s->add_flag("--resume", f->resume, "continue an interrupted sweep from its journal (recomputes nothing done)");
  s->add_flag("--overwrite", f->overwrite, "discard existing output/journal and start over");
  s->add_option("--progress", f->progress, "progress on stderr: auto (bar on a terminal, else lines), bar, plain, none")
      ->capture_default_str();
  s->add_option("--progress-interval", f->progress_interval, "seconds between plain progress lines")
      ->capture_default_str();
  s->add_flag("--quiet", f->quiet, "no progress and no summary");
  s->add_flag("--dry-run", f->dry_run, "print the definition, point count and columns as JSON; compute nothing");
  s->add_option("--plot", f->plot, "plot (PNG, SVG beside it): 1-D line or 2-D map of --plot-column");
  s->add_option("--plot-column", f->plot_column, "column to plot (default first_flight_time)");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(20, add, MpiUse::Distributes);

}  // namespace
}  // namespace blockdyn::cli
