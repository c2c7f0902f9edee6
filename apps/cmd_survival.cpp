// SPDX-License-Identifier: Apache-2.0
// `blockdyn survival`: survival domains over (beta, omega) for seed 002's excitation
// a_H = beta alpha g cos(Omega t + phase), omega = Omega / p, harmonic or as a pulse
// (analysis/forced/survival_map.hpp), for a block on rigid ground or an assembly preset.
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

struct SurvivalFlags {
  ForcedModelFlags m;
  SurvivalOptions o;
  std::string out, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

void run(const CLI::App& s, const SurvivalFlags& f) {
  SurvivalOptions o = f.o;
  require_range("threads", o.threads, 0, 1024);
  try {
    validate(o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (given(s, "--t-end") && given(s, "--periods")) throw UsageError("give --t-end or --periods, not both");
  require_writable("out", f.out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const ForcedModel fm = build_forced_model(s, f.m);
  const std::size_t n = std::size_t(o.beta_points) * o.omega_points;
  Progress bar("survival", n, 0, f.quiet ? ProgressMode::None : parse_progress_mode(f.progress));
  const auto pts = survival_map(fm.run, o, fm.alpha, fm.p, [&](std::size_t) { bar.advance(); });
  bar.finish();

  using json = nlohmann::ordered_json;
  json j;
  j["run"] = run_info();
  j["model"] = fm.description;
  j["alpha"] = fm.alpha;
  j["p"] = fm.p;
  j["units"] = "a_H = beta alpha g cos(omega p t + phase); t in s";
  j["options"] = {{"excitation", o.excitation}, {"phase", o.phase}, {"t_end", o.periods > 0 ? json(nullptr) : json(o.t_end)},
                  {"periods", o.periods}, {"t_star_classes_s", o.t_star_classes}, {"failure", fm.overturn_rule},
                  {"pulse_duration", o.excitation == "harmonic" ? "" : "pi / Omega (half a forcing period)"},
                  {"cycle", "harmonic: the dominant (m, n) cycle of block 0 over the run (2m impacts per n forcing "
                            "periods, seed 002; `blockdyn cycles` with its default window and tolerance, fitted to "
                            "the run's length; before t* for a collapse), or non-periodic / no-impacts; null at rest"}};
  json arr = json::array();
  std::array<long, 4> counts{};
  for (const SurvivalPoint& p : pts) {
    json x;
    x["beta"] = p.beta;
    x["omega"] = p.omega;
    x["motion"] = p.motion;
    x["collapse_mode"] = p.collapse_mode ? json(*p.collapse_mode) : json(nullptr);
    x["t_failure"] = p.t_failure ? json(*p.t_failure) : json(nullptr);
    x["t_star_class"] = p.t_star_class.empty() ? json(nullptr) : json(p.t_star_class);
    x["max_abs_rotation"] = p.max_abs_rotation;
    x["cycle"] = p.cycle.empty() ? json(nullptr) : json(p.cycle);
    arr.push_back(x);
    ++counts[p.motion == "rest" ? 0 : p.motion == "stable" ? 1 : p.motion == "collapse" ? 2 : 3];
  }
  j["counts"] = {{"rest", counts[0]}, {"stable", counts[1]}, {"collapse", counts[2]}, {"invalid", counts[3]}};
  j["points"] = arr;
  // The table, or a temporary one when only the figure is asked for.
  TrajectoryTarget table(f.out, f.plot);
  if (table.file) {
    std::ostream& os = table.file->stream();
    os << "beta,omega,motion,collapse_mode,t_failure,t_star_class,max_abs_rotation,cycle\n";
    char buf[256];
    for (const SurvivalPoint& p : pts) {
      std::snprintf(buf, sizeof buf, "%.17g,%.17g,%s,", p.beta, p.omega, p.motion.c_str());
      os << buf;
      if (p.collapse_mode) os << *p.collapse_mode;
      os << ',';
      if (p.t_failure) {
        std::snprintf(buf, sizeof buf, "%.17g", *p.t_failure);
        os << buf;
      }
      std::snprintf(buf, sizeof buf, ",%s,%.17g,", p.t_star_class.c_str(), p.max_abs_rotation);
      os << buf;
      if (!p.cycle.empty()) os << '"' << p.cycle << '"';
      os << '\n';
    }
  }
  const std::string title = f.m.model + (f.m.preset.empty() ? "" : " " + f.m.preset) + ", " + o.excitation;
  table.figures_and_clean({{"plot_survival.py", f.plot, {"--title", title}}});
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet)
    std::printf("%zu points: %ld rest, %ld stable, %ld collapse, %ld invalid\n", pts.size(), counts[0], counts[1],
                counts[2], counts[3]);
}

void add(CLI::App& app) {
  auto f = std::make_shared<SurvivalFlags>();
  CLI::App* s = app.add_subcommand(
      "survival", "survival domain over (beta, omega): rest, stable or collapse per point for a_H = beta alpha g "
                  "cos(Omega t + phase), omega = Omega/p (seed 002), harmonic or as a half-period pulse");
  add_forced_model_flags(*s, f->m);
  add_excitation_grid_flags(*s, f->o);
  s->add_option("--beta-min", f->o.beta_min, "smallest beta (default 0.5)");
  s->add_option("--beta-max", f->o.beta_max, "largest beta (default 5)");
  s->add_option("--beta-points", f->o.beta_points, "betas, uniform (default 10)");
  s->add_option("--t-star-classes", f->o.t_star_classes,
                "upper bounds [s] of the t* classes <=5 s, short, medium, long (default 5,30,100,300)")
      ->delimiter(',')
      ->expected(4);
  s->add_option("--out", f->out, "write the points as CSV");
  s->add_option("--plot", f->plot, "plot the survival domain (PNG + SVG) in the style of seed 002");
  s->add_flag("--json", f->json, "print the JSON summary");
  s->add_option("--json-out", f->json_out, "write the JSON summary here");
  s->add_option("--progress", f->progress, "auto, bar, plain or none")->check(CLI::IsMember({"auto", "bar", "plain", "none"}));
  s->add_flag("--quiet", f->quiet, "no summary line, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(14, add);

}  // namespace
}  // namespace blockdyn::cli
