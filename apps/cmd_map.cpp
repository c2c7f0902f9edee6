// SPDX-License-Identifier: Apache-2.0
// `blockdyn map`: the response map of the thesis's chapter 6 (Figs 6.1-6.2). Every point of a
// (k, 1/r) grid at fixed mu and initial conditions is classified (steady rocking, settle down,
// settled, zero-friction rock-flight, rock to vertical, overturned; optionally sensitive
// dependence) by the sweep engine (threads, resumable journal), and the stability boundary,
// k_high and k_critical are computed on a coarser set of 1/r values and overlaid.
#include <cmath>
#include <map>
#include <memory>
#include <optional>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/sweep/sweep_evaluator.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/analysis/winkler/flight.hpp"
#include "blockdyn/analysis/winkler/stability.hpp"
#include "blockdyn/api/study_command.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "grid_run.hpp"
#include "study_table_output.hpp"

namespace blockdyn::cli {
namespace {

struct MapFlags {
  std::string k = "1e1:1e8:40", inv_r = "1:20:30", ic = "ic1", output = "map.csv", plot;
  double mu = 0.2, t_end = 30;
  IntegratorOptions integ;
  long max_steps = 20'000'000;
  int threads = 0, boundary_points = 10;
  double fine_per_decade = 48;  // fine scan next to the flight boundaries (docs/flight.md)
  long critical_n = 10;
  bool resume = false, overwrite = false, quiet = false, sensitivity = false;
};

struct BoundaryRow {
  double inv_r = 0, r = 0;
  CurvePoint stability, high, critical;
  std::optional<K3Point> k3;  // ic2 only: overturning before the third passage (docs/stability.md)
};

std::string boundaries_path(const std::string& csv) {
  const std::string stem =
      (csv.size() > 4 && csv.substr(csv.size() - 4) == ".csv") ? csv.substr(0, csv.size() - 4) : csv;
  return stem + "_boundaries.csv";
}

// Stability boundary (k1 for ic1, k2 for ic2), k_high and k_critical_n at one aspect ratio.
BoundaryRow boundary_row(double inv_r, double mu, const IcChoice& ic, long n, const StudyRunOptions& run, double k_lo,
                         double k_hi, double fine_per_decade) {
  BoundaryRow b;
  b.inv_r = inv_r;
  b.r = 1.0 / inv_r;
  StabilitySearchOptions ss;
  ss.k_lo = k_lo;
  ss.k_hi = k_hi;
  ss.per_decade = 4;
  ss.bisect.rel_tol = 1e-2;
  b.stability = ic.is_ic1() ? k1_stability(b.r, mu, ic, run, ss) : k2_stability(b.r, mu, run, ss);
  // ic2: k2 is where overturning on the first swing ends; the slender blocks above it can still
  // overturn on the second, up to k3 (the thesis's Fig 6.2 discussion).
  if (!ic.is_ic1()) b.k3 = k3_stability(b.r, mu, b.stability.result, run, ss);
  BoundarySearchOptions fs;
  fs.k_lo = k_lo;
  fs.k_hi = k_hi;
  fs.per_decade = 4;
  fs.bisect.rel_tol = 1e-2;
  fs.refine.per_decade = fine_per_decade;
  const FirstImpact fi = ic.is_ic1() ? FirstImpact::WNegative : FirstImpact::IhorBelow2;
  b.high = k_high(b.r, mu, ic, fi, run, fs);
  b.critical = k_critical(b.r, mu, ic, n, run, fs);
  return b;
}

void run(const CLI::App& s, const MapFlags& f) {
  (void)s;
  require_range("mu", f.mu, 0.0, kWinklerMuMax);
  require_range("t-end", f.t_end, 0.0, kMaxTime, false);
  require_range("threads", f.threads, 0, 4096);
  if (f.output.empty()) throw UsageError("output: the CSV path is empty");
  require_writable("plot", f.plot);
  if (f.boundary_points < 0 || f.boundary_points > 1000)
    throw UsageError("boundary-points = " + std::to_string(f.boundary_points) +
                     " is out of range: must be in [0, 1000]");
  require_range("fine-per-decade", f.fine_per_decade, 0.0, 1000);
  if (f.critical_n < 2)
    throw UsageError("critical-n = " + std::to_string(f.critical_n) + " is out of range: must be >= 2");
  const IcChoice ic = parse_ic_choice(f.ic);

  SweepSpec spec;
  spec.k = parse_axis("k", f.k, AxisSpacing::Log);
  spec.r = parse_axis("inv_r", f.inv_r, AxisSpacing::Linear);
  spec.mu = axis_list("mu", {f.mu});
  spec.initial.sets = {ic.is_ic1() ? "ic1" : "ic2"};
  if (ic.is_ic1()) spec.initial.w0_over_alpha = ic.w0_fraction;
  spec.options.t_end = f.t_end;
  spec.options.integrator = f.integ;
  spec.options.integrator.max_steps = f.max_steps;
  spec.metrics = {"response_type"};
  if (f.sensitivity) spec.metrics.push_back("sensitive_dependence");
  spec.output = f.output;
  validate(spec);
  const SweepEvaluator ev(spec);
  SweepRunOptions ro;
  ro.threads = f.threads;
  ro.resume = f.resume;
  ro.overwrite = f.overwrite;
  ro.progress = f.quiet ? ProgressMode::None : ProgressMode::Auto;
  const GridRunResult dispatched = dispatch_points(ev, ro);
  if (!dispatched.root) return;  // the other ranks computed their share of the points
  const SweepOutcome& out = dispatched.outcome;

  // Boundary curves on a coarser set of 1/r values spanning the grid.
  const double ir_lo = spec.r.values.front(), ir_hi = spec.r.values.back();
  const double k_lo = std::fmin(spec.k.values.front(), spec.k.values.back());
  const double k_hi = std::fmax(spec.k.values.front(), spec.k.values.back());
  StudyRunOptions run;
  run.t_end = f.t_end;
  run.integrator = spec.options.integrator;
  std::vector<BoundaryRow> rows;
  if (f.boundary_points > 0) {
    const int nb = f.boundary_points;
    rows = parallel_map<BoundaryRow>(std::size_t(nb), f.threads, [&](std::size_t i) {
      const double ir = nb == 1 ? ir_lo : ir_lo + (ir_hi - ir_lo) * double(i) / double(nb - 1);
      return boundary_row(ir, f.mu, ic, f.critical_n, run, k_lo, k_hi, f.fine_per_decade);
    });
  }
  StudyTable t;
  t.columns = {"inv_r",         "r",          "k_stability",      "stability_status", "k_high",
               "k_high_status", "k_critical", "k_critical_status"};
  t.columns.insert(t.columns.end(), {"k3_stability", "k3_status"});
  for (const auto& b : rows)
    t.rows.push_back({cell_text(b.inv_r), cell_text(b.r), cell_text(boundary_cell(b.stability.result)),
                      to_string(b.stability.result.status), cell_text(boundary_cell(b.high.result)),
                      to_string(b.high.result.status), cell_text(boundary_cell(b.critical.result)),
                      to_string(b.critical.result.status),
                      b.k3 ? cell_text(boundary_cell(b.k3->point.result)) : cell_text(NAN),
                      b.k3 ? to_string(b.k3->point.result.status) : "not_applicable"});
  const std::string bpath = boundaries_path(out.paths.csv);
  nlohmann::ordered_json meta = {{"run", run_info()},
                                 {"what", "boundaries of the response map"},
                                 {"mu", f.mu},
                                 {"ic", ic.name()},
                                 {"stability_curve", ic.is_ic1() ? "k1_stability" : "k2_stability"},
                                 {"k3_curve", ic.is_ic1() ? "none (ic2 only)" : "k3_stability"},
                                 {"k_high_criterion", ic.is_ic1() ? "w_negative" : "ihor2"},
                                 {"k_critical_n", f.critical_n},
                                 {"fine_points_per_decade", f.fine_per_decade},
                                 {"k_range", {k_lo, k_hi}},
                                 {"run_options", run_options_json(run)}};
  write_study_table(bpath, t, meta);
  if (!f.plot.empty())
    run_python("plot_map.py", {out.paths.csv, bpath, f.plot, "mu = " + cell_text(f.mu) + ", " + ic.name()});
  if (!f.quiet)
    std::printf("map: %zu points (%zu computed, %zu resumed) in %.1f s -> %s, boundaries -> %s\n", out.points,
                out.computed, out.resumed, out.wall_seconds, out.paths.csv.c_str(), bpath.c_str());
}

void add(CLI::App& app) {
  auto f = std::make_shared<MapFlags>();
  CLI::App* s = app.add_subcommand(
      "map", "response types over the (k, 1/r) plane with stability and flight boundaries (thesis Figs 6.1-6.2)");
  s->add_option("--k", f->k, "k axis: min:max:points[:log|:lin] or a list")->capture_default_str();
  s->add_option("--inv-r", f->inv_r, "1/r axis (height/width): min:max:points or a list")->capture_default_str();
  s->add_option("--mu", f->mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--ic", f->ic, "initial conditions: ic1, ic1:F (w0 = F alpha) or ic2")->capture_default_str();
  s->add_option("--t-end", f->t_end, "observation time of each run")->capture_default_str();
  add_tolerance_options(*s, f->integ);
  s->add_option("--max-steps", f->max_steps, "step cap per run (reported as numerical_failure)")->capture_default_str();
  s->add_option("--boundary-points", f->boundary_points, "1/r values for the boundary curves (0: none)")
      ->capture_default_str();
  s->add_option("--fine-per-decade", f->fine_per_decade,
                "fine grid next to k_high and k_critical (points per decade; 0: coarse search only)")
      ->capture_default_str();
  s->add_option("--critical-n", f->critical_n, "n of k_critical_n (no flight while ihor < n)")->capture_default_str();
  s->add_flag("--sensitivity", f->sensitivity,
              "also run every point from y'(0) + 1e-8 and mark sensitive dependence (twice the cost)");
  s->add_option("--threads", f->threads, "worker threads (0: all cores)")->capture_default_str();
  s->add_option("-o,--output", f->output, "map CSV (journal, sidecar and boundaries CSV beside it)")
      ->capture_default_str();
  s->add_flag("--resume", f->resume, "continue an interrupted map, recomputing nothing finished");
  s->add_flag("--overwrite", f->overwrite, "replace existing output");
  s->add_flag("--quiet", f->quiet, "no progress output");
  s->add_option("--plot", f->plot, "write the map figure (PNG; SVG beside it)");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(25, add, MpiUse::Distributes);

}  // namespace
}  // namespace blockdyn::cli
