// SPDX-License-Identifier: Apache-2.0
// `blockdyn sweep`: a grid of runs, from a TOML definition and/or flags (the library builds it:
// blockdyn/commands/sweep_settings.hpp); threads, MPI, resumable journal, progress, CSV + JSON
// sidecar, plot. The axes come from the model family: k, r (or 1/r), mu and initial conditions
// for the Winkler block; the block's shape, interface, impact, initial state and ground motion
// (--axis NAME=SPEC) for the housner and rigid models.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/sweep/rigid_sweep.hpp"
#include "blockdyn/analysis/sweep/sweep_metrics.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/commands/sweep_settings.hpp"
#include "blockdyn/family/family.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "grid_run.hpp"
#include "table_files.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_sweep {
namespace {

// The runner's flags and the listings: not part of the sweep's definition.
struct RunnerFlags {
  std::string progress = "auto";
  double progress_interval = 10;
  int threads = 0;
  bool resume = false, overwrite = false, quiet = false, list_metrics = false, list_axes = false, dry_run = false;
};
const std::vector<std::string> kRunnerFlags = {
    "--threads", "--resume",       "--overwrite", "--progress", "--progress-interval",
    "--quiet",   "--list-metrics", "--list-axes", "--dry-run"};

void list_metrics() {
  for (const auto& m : metric_catalog()) {
    const auto cols = m.make()->columns();
    std::string c;
    for (const auto& x : cols) c += (c.empty() ? "" : ",") + x;
    // Name on its own line: names are longer than any fixed column (sensitive_dependence).
    std::printf("%s\n    %s\n    columns: %s\n", m.name.c_str(), m.description.c_str(), c.c_str());
  }
}

void dry_run(const SweepDefinition& d) {
  const PointTable& t = *d.table;
  const SweepPaths p = sweep_paths(t.output());
  nlohmann::ordered_json j;
  j["run"] = run_info();
  j["point_count"] = t.size();
  j["fingerprint"] = t.fingerprint();
  j["columns"] = t.columns();
  j["outputs"] = {{"csv", p.csv}, {"sidecar", p.sidecar}, {"journal", p.journal}};
  j["definition"] = d.definition;
  emit_json(j, "-");
}

void execute(const SweepDefinition& d, const RunnerFlags& f) {
  const auto& c = d.table->columns();
  if (std::find(c.begin(), c.end(), d.plot_column) == c.end())
    throw UsageError("plot-column = '" + d.plot_column + "' is not a column of this sweep (see --dry-run)");
  if (f.dry_run) return dry_run(d);
  SweepRunOptions o;
  o.threads = f.threads;
  o.resume = f.resume;
  o.overwrite = f.overwrite;
  o.progress = f.quiet ? ProgressMode::None : parse_progress_mode(f.progress);
  o.progress_interval = f.progress_interval;
  const GridRunResult res = write_sweep(d, o);
  if (!res.root) return;  // only rank 0 reports
  const SweepOutcome& out = res.outcome;
  if (f.quiet) return;
  if (out.was_complete) {
    std::printf("sweep: %zu points already complete in %s (nothing recomputed)\n", out.points, out.paths.csv.c_str());
    return;
  }
  std::printf("sweep: %zu points (%zu computed, %zu resumed, %zu errors) in %.3g s, %.3g points/s, %d rank(s)\n",
              out.points, out.computed, out.resumed, out.errors, out.wall_seconds,
              out.wall_seconds > 0 ? double(out.computed) / out.wall_seconds : 0.0, res.ranks);
  std::printf("wrote %s and %s\n", out.paths.csv.c_str(), out.paths.sidecar.c_str());
}

void run(const CLI::App& s, const RunnerFlags& f) {
  if (f.list_metrics) return list_metrics();
  if (f.resume && f.overwrite) throw UsageError("--resume and --overwrite: give only one");
  require_range("threads", f.threads, 0, 4096);
  require_range("progress-interval", f.progress_interval, 0.0, 1e9, false);
  const Settings given = settings_of(s, kRunnerFlags);
  if (f.list_axes) {
    for (const auto& [name, what] : sweep_family(given).sweep_axes())
      std::printf("%-20s %s\n", name.c_str(), cli_text(what).c_str());
    return;
  }
  const SweepDefinition d = sweep_definition(given);
  require_writable("plot", d.plot);
  execute(d, f);
}

void add(CLI::App& app) {
  auto f = std::make_shared<RunnerFlags>();
  CLI::App* s =
      app.add_subcommand("sweep",
                         "parameter sweep with the model family's axes (winkler: k, r, mu, ic; housner/rigid: --axis) "
                         "(threads, MPI, resumable)");
  s->footer(
      "Axis values: a list \"v1,v2,...\" or a range \"min:max:points[:log|:lin]\" (k: log by default).\n"
      "Points are numbered index = k_i + n_k*(r_i + n_r*(mu_i + n_mu*ic_i)). See docs/sweep.md.");
  s->add_option("definition", "TOML sweep definition (flags given as well override it)")->check(CLI::ExistingFile);
  add_spec_options(*s, sweep_options());
  s->add_flag("--list-axes", f->list_axes, "list the axes of the model family and exit");
  s->add_flag("--list-metrics", f->list_metrics, "list the available metrics and exit");
  s->add_option("-o,--output", "output CSV (default sweep.csv); sidecar .json and .journal beside it");
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
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(20, add, MpiUse::Distributes);

}  // namespace
}  // namespace cmd_sweep
}  // namespace blockdyn::cli
