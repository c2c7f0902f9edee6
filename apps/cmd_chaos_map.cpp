// SPDX-License-Identifier: Apache-2.0
// `blockdyn chaos-map`: the largest Lyapunov exponent over (beta, omega) for seed 002's harmonic
// excitation a_H = beta alpha g cos(Omega t + phase), omega = Omega / p, each point from rest
// through a transient, classified rest / superstable / periodic / neutral / chaotic / collapse
// (analysis/forced/chaos_map.hpp), for a block on rigid ground or an assembly preset.
#include <cstdio>
#include <map>
#include <memory>

#include "blockdyn/analysis/forced/chaos_map.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "forced_model.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

struct ChaosMapFlags {
  ForcedModelFlags m;
  ChaosMapOptions o;
  IntegratorOptions integ{1e-10, 1e-12};
  std::string out, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

void run(const CLI::App& s, const ChaosMapFlags& f) {
  ChaosMapOptions o = f.o;
  require_range("threads", o.grid.threads, 0, 1024);
  if (given(s, "--t-end") && given(s, "--periods")) throw UsageError("give --t-end or --periods, not both");
  o.use_t_end = given(s, "--t-end");
  if (given(s, "--periods")) o.total_periods = o.grid.periods;
  o.grid.periods = 0;
  o.integrator = f.integ;
  // Assemblies: the tangent carries the stiff contact modes, which the integrator must resolve;
  // at 1e-6 the exponent agrees with 1e-8 to a few per cent at a hundredth of the cost
  // (docs/forced-chaos.md).
  if (f.m.model == "assembly" && !given(s, "--rtol")) o.integrator.rtol = 1e-6;
  if (f.m.model == "assembly" && !given(s, "--atol")) o.integrator.atol = 1e-8;
  try {
    validate(o);
    SimulationOptions so;
    so.integrator = o.integrator;
    validate(so);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  require_writable("out", f.out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const ForcedModel fm = build_forced_model(s);
  if (fm.description.contains("contact") && fm.description["contact"] == "rigid")
    throw UsageError("--contact rigid: no Lyapunov exponent (Moreau-Jean time-stepping); use --contact deformable");
  const auto lyap = fm.lyapunov;
  const ForcedLyapunovRun run = [lyap](const GroundMotion& g, const ForcedLyapunovOptions& fo) {
    return lyap(g, fo, RigidInitial{});
  };
  const std::size_t n = std::size_t(o.grid.beta_points) * o.grid.omega_points;
  Progress bar("chaos-map", n, 0, f.quiet ? ProgressMode::None : parse_progress_mode(f.progress));
  const auto pts = chaos_map(run, o, fm.alpha, fm.p, [&](std::size_t) { bar.advance(); });
  bar.finish();

  using json = nlohmann::ordered_json;
  json j;
  j["run"] = run_info();
  j["model"] = fm.description;
  j["alpha"] = fm.alpha;
  j["p"] = fm.p;
  j["units"] = "a_H = beta alpha g cos(omega p t + phase); exponent in 1/s, exponent_nondim = exponent / p";
  j["options"] = {{"phase", o.grid.phase},
                  {"periods", o.use_t_end ? json(nullptr) : json(o.total_periods)},
                  {"t_end", o.use_t_end ? json(o.grid.t_end) : json(nullptr)},
                  {"transient_periods", o.transient_periods},
                  {"interval_periods", o.interval_periods},
                  {"threshold", o.threshold},
                  {"method", "variational equation with saltation matrices, Benettin renormalisation"},
                  {"failure", fm.overturn_rule}};
  j["integrator"] = to_json(o.integrator);
  j["counts"] = chaos_counts_json(pts);
  j["points"] = chaos_points_json(pts);
  TrajectoryTarget table(f.out, f.plot);
  if (table.file) write_chaos_csv(table.file->stream(), pts);
  const std::string title = f.m.model + (f.m.preset.empty() ? "" : " " + f.m.preset) + ": largest Lyapunov exponent";
  table.figures_and_clean(
      {{"plot_chaos_map.py", f.plot, {"--title", title, "--threshold", std::to_string(o.threshold)}}});
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet) {
    std::printf("%zu points:", pts.size());
    for (const std::string& m : chaos_motions()) std::printf(" %ld %s", j["counts"][m].get<long>(), m.c_str());
    std::printf("\n");
  }
}

void add(CLI::App& app) {
  auto f = std::make_shared<ChaosMapFlags>();
  f->o.grid.beta_points = 10;
  CLI::App* s = app.add_subcommand(
      "chaos-map",
      "largest Lyapunov exponent over (beta, omega) for a_H = beta alpha g cos(Omega t + phase), "
      "omega = Omega/p (seed 002): rest, superstable, periodic, neutral, chaotic or collapse per point");
  add_forced_model_flags(*s, f->m);
  add_excitation_grid_flags(*s, f->o.grid);
  s->get_option("--periods")->description("forcing periods per run, transient included (default 150)");
  s->get_option("--t-end")->description("duration of each run [s] (instead of --periods)");
  s->add_option("--beta-min", f->o.grid.beta_min, "smallest beta (default 0.5)");
  s->add_option("--beta-max", f->o.grid.beta_max, "largest beta (default 5)");
  s->add_option("--beta-points", f->o.grid.beta_points, "betas, uniform (default 10)");
  s->add_option("--transient-periods", f->o.transient_periods, "forcing periods before the measurement (default 50)");
  s->add_option("--interval-periods", f->o.interval_periods, "renormalisation interval in forcing periods (default 1)");
  s->add_option("--threshold", f->o.threshold, "chaotic above, periodic below minus this exponent / p (default 0.01)");
  s->add_option("--rtol", f->integ.rtol, "relative tolerance (default 1e-10; assembly 1e-6)");
  s->add_option("--atol", f->integ.atol, "absolute tolerance (default 1e-12; assembly 1e-8)");
  s->add_option("--out", f->out, "write the points as CSV");
  s->add_option("--plot", f->plot, "plot the map of the exponent with the motion classes (PNG + SVG)");
  s->add_flag("--json", f->json, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_option("--progress", f->progress, "auto, bar, plain or none")
      ->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  s->add_flag("--quiet", f->quiet, "no summary line, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(16, add);

}  // namespace
}  // namespace blockdyn::cli
