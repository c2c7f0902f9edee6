// SPDX-License-Identifier: Apache-2.0
// `blockdyn map`: the response map of the thesis's chapter 6 (Figs 6.1-6.2), built by the library
// (blockdyn/commands/map_study.hpp): the grid's points on the sweep runner (threads, MPI, resumable
// journal), then the boundary curves beside it and the figure.
#include <memory>

#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/commands/map_study.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "table_files.hpp"

namespace blockdyn::cli {
// Each command's own names (add, Flags, ...) in its own namespace: the files build as one unity.
namespace cmd_map {
namespace {

struct MapFlags {
  int threads = 0;
  bool resume = false, overwrite = false, quiet = false;
};

void run(const CLI::App& s, const MapFlags& f) {
  require_range("threads", f.threads, 0, 4096);
  const Settings given = settings_of(s, {"--threads", "--resume", "--overwrite", "--quiet"});
  SweepRunOptions ro;
  ro.threads = f.threads;
  ro.resume = f.resume;
  ro.overwrite = f.overwrite;
  ro.progress = f.quiet ? ProgressMode::None : ProgressMode::Auto;
  const MapFiles files = write_map(given, ro);
  if (!files.grid.root) return;  // the other ranks computed their share of the points
  const SweepOutcome& out = files.grid.outcome;
  const std::string& bpath = files.boundaries_csv;
  if (!f.quiet)
    std::printf("map: %zu points (%zu computed, %zu resumed) in %.1f s -> %s, boundaries -> %s\n", out.points,
                out.computed, out.resumed, out.wall_seconds, out.paths.csv.c_str(), bpath.c_str());
}

void add(CLI::App& app) {
  auto f = std::make_shared<MapFlags>();
  CLI::App* s = app.add_subcommand(
      "map", "response types over the (k, 1/r) plane with stability and flight boundaries (thesis Figs 6.1-6.2)");
  add_spec_options(*s, map_options());
  s->add_option("--threads", f->threads, "worker threads (0: all cores)")->capture_default_str();
  s->add_option("-o,--output", "map CSV (journal, sidecar and boundaries CSV beside it)")->default_str("map.csv");
  s->add_flag("--resume", f->resume, "continue an interrupted map, recomputing nothing finished");
  s->add_flag("--overwrite", f->overwrite, "replace existing output");
  s->add_flag("--quiet", f->quiet, "no progress output");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(25, add, MpiUse::Distributes);

}  // namespace
}  // namespace cmd_map
}  // namespace blockdyn::cli
