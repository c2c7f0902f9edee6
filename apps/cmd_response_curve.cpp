// SPDX-License-Identifier: Apache-2.0
// `blockdyn response-curve`: the largest rotation theta_MAX / alpha (and, for assemblies, the
// largest slip between blocks over the block width) versus omega = Omega / p for several
// amplitudes beta, under a_H = beta alpha g cos(Omega t + phase) (seed 001 Figs. 4-7, seed 002
// Figs. 3, 10-11), over a transient window (--t-end) or a number of forcing periods.
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/io/atomic_file.hpp"
#include "blockdyn/io/json_io.hpp"
#include "blockdyn/io/progress.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "forced_model.hpp"
#include "trajectory_target.hpp"

namespace blockdyn::cli {
namespace {

struct CurveFlags {
  ForcedModelFlags m;
  SurvivalOptions o;
  std::string out, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

void run(const CLI::App& s, const CurveFlags& f) {
  SurvivalOptions o = f.o;
  if (o.betas.empty()) throw UsageError("--betas B1,B2,... is needed (the amplitudes, in units of alpha g)");
  o.beta_points = int(o.betas.size());
  require_range("threads", o.threads, 0, 1024);
  if (given(s, "--t-end") && given(s, "--periods")) throw UsageError("give --t-end or --periods, not both");
  try {
    validate(o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  require_writable("out", f.out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const ForcedModel fm = build_forced_model(s, f.m);
  Progress bar("response-curve", std::size_t(o.beta_points) * o.omega_points, 0,
               f.quiet ? ProgressMode::None : parse_progress_mode(f.progress));
  const auto pts = survival_map(fm.run, o, fm.alpha, fm.p, [&](std::size_t) { bar.advance(); });
  bar.finish();

  using json = nlohmann::ordered_json;
  json j;
  j["run"] = run_info();
  j["model"] = fm.description;
  j["alpha"] = fm.alpha;
  j["p"] = fm.p;
  j["width"] = fm.width;
  j["units"] = "a_H = beta alpha g cos(omega p t + phase); rotations over alpha, slips over the block width";
  j["options"] = {{"excitation", o.excitation}, {"phase", o.phase}, {"t_end", o.periods > 0 ? json(nullptr) : json(o.t_end)},
                  {"periods", o.periods}};
  json arr = json::array();
  for (const SurvivalPoint& p : pts)
    arr.push_back({{"beta", p.beta},
                   {"omega", p.omega},
                   {"theta_max_over_alpha", p.max_abs_rotation / fm.alpha},
                   {"max_sliding_over_b", p.max_sliding / fm.width},
                   {"motion", p.motion},
                   {"t_failure", p.t_failure ? json(*p.t_failure) : json(nullptr)}});
  j["points"] = arr;
  // The table, or a temporary one when only the figure is asked for.
  TrajectoryTarget table(f.out, f.plot);
  if (table.file) {
    std::ostream& os = table.file->stream();
    os << "beta,omega,theta_max_over_alpha,max_sliding_over_b,motion,t_failure\n";
    char buf[256];
    for (const SurvivalPoint& p : pts) {
      std::snprintf(buf, sizeof buf, "%.17g,%.17g,%.17g,%.17g,%s,", p.beta, p.omega, p.max_abs_rotation / fm.alpha,
                    p.max_sliding / fm.width, p.motion.c_str());
      os << buf;
      if (p.t_failure) {
        std::snprintf(buf, sizeof buf, "%.17g", *p.t_failure);
        os << buf;
      }
      os << '\n';
    }
  }
  const std::string title = f.m.model + (f.m.preset.empty() ? "" : " " + f.m.preset) + ", " + o.excitation;
  table.figures_and_clean({{"plot_response_curve.py", f.plot, {"--title", title}}});
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet) std::printf("%zu points\n", pts.size());
}

void add(CLI::App& app) {
  auto f = std::make_shared<CurveFlags>();
  CLI::App* s = app.add_subcommand("response-curve",
                                   "largest rotation theta_MAX / alpha (and slip between blocks / b) versus omega = "
                                   "Omega/p for several beta, under a_H = beta alpha g cos(Omega t + phase)");
  add_forced_model_flags(*s, f->m);
  s->add_option("--betas", f->o.betas, "amplitudes beta, comma separated (a_H = beta alpha g ...)")->delimiter(',');
  add_excitation_grid_flags(*s, f->o);
  s->add_option("--out", f->out, "write the points as CSV");
  s->add_option("--plot", f->plot, "plot theta_MAX / alpha versus omega, one curve per beta (PNG + SVG)");
  s->add_flag("--json", f->json, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_option("--progress", f->progress, "auto, bar, plain or none")->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  s->add_flag("--quiet", f->quiet, "no summary line, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(15, add);

}  // namespace
}  // namespace blockdyn::cli
