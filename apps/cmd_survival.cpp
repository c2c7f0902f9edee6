// SPDX-License-Identifier: Apache-2.0
// `blockdyn survival`: survival domains over (beta, omega) for seed 002's excitation
// a_H = beta alpha g cos(Omega t + phase), omega = Omega / p, harmonic or as a pulse
// (analysis/forced/survival_map.hpp), for a block on rigid ground or an assembly preset. The
// points run on the sweep runner (threads, MPI, journal, resume, progress); --refine adds points
// near class changes (analysis/sweep/refinement_plan.hpp).
#include <cmath>
#include <cstdio>
#include <memory>

#include "blockdyn/analysis/forced/survival_table.hpp"
#include "blockdyn/analysis/sweep/refinement_plan.hpp"
#include "blockdyn/io/json_io.hpp"
#include "cli_common.hpp"
#include "cli_registry.hpp"
#include "forced_model.hpp"
#include "grid_run.hpp"

namespace blockdyn::cli {
namespace {

struct SurvivalFlags {
  SurvivalOptions o;
  GridRunFlags g;
  int refine = 0;
  std::string out, plot, json_out, progress = "auto";
  bool json = false, quiet = false;
};

// Refinement and plots class points by motion and collapse mode.
std::string point_class(const std::string& motion, const std::string& mode) { return motion + " " + mode; }

void run(const CLI::App& s, const SurvivalFlags& f) {
  SurvivalOptions o = f.o;
  require_range("threads", o.threads, 0, 1024);
  try {
    validate(o);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  if (given(s, "--t-end") && given(s, "--periods")) throw UsageError("give --t-end or --periods, not both");
  require_range("refine", f.refine, 0, 8);
  const std::size_t nxf = RefinementPlan::fine_count(std::size_t(o.omega_points), f.refine);
  const std::size_t nyf = RefinementPlan::fine_count(std::size_t(o.beta_points), f.refine);
  if (double(nxf) * double(nyf) > 4e6)
    throw UsageError("refine: the fine lattice would have " + std::to_string(nxf * nyf) +
                     " points (at most 4e6): lower --refine or the point counts");
  const GridOutput out("--out", f.out, "survival", f.g, f.json_out);
  require_writable("plot", f.plot);
  require_writable("json-out", f.json_out);
  const ForcedModel fm = build_forced_model(s);
  // The longest run the periods give (at the lowest frequency) within the runs' range, before
  // any file is made.
  if (o.periods > 0 && !(o.periods * 2 * M_PI / (o.omega_min * fm.p) <= 1e5))
    throw UsageError("periods = " + std::to_string(o.periods) + " gives runs of " +
                     std::to_string(o.periods * 2 * M_PI / (o.omega_min * fm.p)) +
                     " s at omega-min: at most 1e5 s (lower --periods or raise --omega-min)");

  using json = nlohmann::ordered_json;
  json options = {{"excitation", o.excitation},
                  {"phase", o.phase},
                  {"t_end", o.periods > 0 ? json(nullptr) : json(o.t_end)},
                  {"periods", o.periods},
                  {"t_star_classes_s", o.t_star_classes},
                  {"failure", fm.overturn_rule},
                  {"pulse_duration", o.excitation == "harmonic" ? "" : "pi / Omega (half a forcing period)"},
                  {"refine", f.refine},
                  {"cycle",
                   "harmonic: the dominant (m, n) cycle of block 0 over the run (2m impacts per n forcing "
                   "periods, seed 002; `blockdyn cycles` with its default window and tolerance, fitted to "
                   "the run's length; before t* for a collapse), or non-periodic / no-impacts; null at rest"}};
  const json definition = {{"model", fm.description},
                           {"alpha", fm.alpha},
                           {"p", fm.p},
                           {"beta", {{"min", o.beta_min}, {"max", o.beta_max}, {"points", o.beta_points}}},
                           {"omega", {{"min", o.omega_min}, {"max", o.omega_max}, {"points", o.omega_points}}},
                           {"options", options},
                           {"index", "omega fastest: index = i_omega + n_omega * i_beta on the (refined) lattice"}};
  std::vector<std::string> cols = survival_columns();
  cols.push_back("level");
  const std::size_t motion_col = 3, mode_col = 4;  // after index, beta, omega
  RefinementPlan stages(std::size_t(o.omega_points), std::size_t(o.beta_points), f.refine, [&](const std::string& r) {
    const auto c = split_csv_line(r.substr(0, r.size() - 1));
    return point_class(c[motion_col], c[mode_col]);
  });
  const GridTable table(
      "survival", cols, stages.size(),
      [&](std::size_t i, RowBuilder& row) {
        const double omega = grid_value(o.omega_min, o.omega_max, int(nxf), int(i % nxf));
        const double beta = grid_value(o.beta_min, o.beta_max, int(nyf), int(i / nxf));
        add_survival_cells(survival_point(fm.run, o, fm.alpha, fm.p, beta, omega), row);
        row.add(static_cast<long long>(stages.level_of(i)));
      },
      definition, fm.tolerances, out.csv());
  const GridRunResult res = run_grid(table, f.g, o.threads, f.progress, f.quiet, &stages);
  if (!res.root) return;

  const Table t = read_table(out.csv(), table.header());
  json j;
  j["run"] = run_info();
  j["model"] = fm.description;
  j["alpha"] = fm.alpha;
  j["p"] = fm.p;
  j["units"] = "a_H = beta alpha g cos(omega p t + phase); t in s";
  j["options"] = options;
  j["tolerances"] = fm.tolerances;
  const SurvivalPoints sp = survival_points(t, f.refine > 0);
  const auto& counts = sp.counts;
  j["counts"] = sp.counts_json();
  j["points"] = sp.points;
  if (!f.plot.empty()) {
    const ForcedModelChoice m = forced_model_choice(s);
    std::string title = m.label() + ", " + o.excitation;
    if (m.assembly())
      title += ", " + m.contact + " law, phi_s = " + short_number(m.phi_s) + ", phi_l = " + short_number(m.phi_l);
    std::vector<std::string> args{out.csv(), f.plot, "--title", title};
    if (f.refine > 0) {
      args.insert(
          args.end(),
          {"--refined", format_double(o.omega_points > 1 ? (o.omega_max - o.omega_min) / (o.omega_points - 1) : 1.0),
           format_double(o.beta_points > 1 ? (o.beta_max - o.beta_min) / (o.beta_points - 1) : 1.0)});
    }
    run_python("plot_survival.py", args);
  }
  if (!f.json_out.empty()) emit_json(j, f.json_out);
  if (f.json) emit_json(j, "-");
  if (!f.json && !f.quiet)
    std::printf("%zu points: %ld rest, %ld stable, %ld collapse, %ld invalid %s\n", t.rows.size(), counts[0], counts[1],
                counts[2], counts[3], grid_run_note(res).c_str());
}

void add(CLI::App& app) {
  auto f = std::make_shared<SurvivalFlags>();
  CLI::App* s = app.add_subcommand(
      "survival",
      "survival domain over (beta, omega): rest, stable or collapse per point for a_H = beta alpha g "
      "cos(Omega t + phase), omega = Omega/p (seed 002), harmonic or as a half-period pulse "
      "(threads, MPI, resumable)");
  add_forced_model_flags(*s);
  add_excitation_grid_flags(*s, f->o);
  s->add_option("--beta-min", f->o.beta_min, "smallest beta (default 0.5)");
  s->add_option("--beta-max", f->o.beta_max, "largest beta (default 5)");
  s->add_option("--beta-points", f->o.beta_points, "betas, uniform (default 10)");
  s->add_option("--t-star-classes", f->o.t_star_classes,
                "upper bounds [s] of the t* classes <=5 s, short, medium, long (default 5,30,100,300)")
      ->delimiter(',')
      ->expected(4);
  s->add_option("--refine", f->refine,
                "refinement levels near class changes (0-8, default 0): cells whose corners differ in motion or "
                "collapse mode are split in four, level after level");
  s->add_option("--out", f->out, "the points as CSV (the runner's table: journal and sidecar .json beside it)");
  s->add_option("--plot", f->plot, "plot the survival domain (PNG + SVG) in the style of seed 002");
  add_grid_report_flags(*s, f->g, f->json, f->json_out, f->progress, f->quiet, "no summary line, no progress");
  s->callback([s, f] { run(*s, *f); });
}

RegisterCommand reg(14, add, MpiUse::Distributes);

}  // namespace
}  // namespace blockdyn::cli
