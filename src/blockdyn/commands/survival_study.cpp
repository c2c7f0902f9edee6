// SPDX-License-Identifier: Apache-2.0
// `survival`: survival domains over (beta, omega) for seed 002's excitation, harmonic or as a pulse,
// for a block on rigid ground or an assembly preset; --refine adds points near class changes.
#include "blockdyn/commands/grid_studies.hpp"
#include "blockdyn/commands/grid_study_common.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <map>
#include <sstream>
#include <stdexcept>

#include "blockdyn/analysis/forced/spectrum_table.hpp"
#include "blockdyn/analysis/forced/survival_table.hpp"
#include "blockdyn/analysis/sweep/refinement_plan.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/analysis/sweep/sweep_runner.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/commands/fragility.hpp"
#include "blockdyn/commands/harmonic_run.hpp"
#include "blockdyn/commands/rocking_spectrum.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

namespace {

std::vector<StudyOption> survival_options() {
  std::vector<StudyOption> o = forced_model_options();
  for (const StudyOption& x : excitation_grid_options()) o.push_back(x);
  const std::vector<StudyOption> own = {
      {"beta-min", "smallest beta", "0.5"},
      {"beta-max", "largest beta", "5"},
      {"beta-points", "betas, uniform", "10"},
      {"t-star-classes", "upper bounds [s] of the t* classes <=5 s, short, medium, long", "5,30,100,300", false, true},
      {"refine",
       "refinement levels near class changes (0-8): cells whose corners differ in motion or collapse mode are "
       "split in four, level after level",
       "0"}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

SurvivalOptions survival_options_of(const StudyOptions& so, int& refine) {
  SurvivalOptions o = excitation_grid_of(so);
  o.beta_min = so.number("beta-min");
  o.beta_max = so.number("beta-max");
  o.beta_points = so.small_integer("beta-points");
  o.t_star_classes = so.numbers("t-star-classes");
  if (o.t_star_classes.size() != 4)
    throw std::invalid_argument(
        "`t-star-classes`: 4 values are needed (the upper bounds of <=5 s, short, medium, long)");
  validate(o);
  if (so.given("t-end") && so.given("periods")) throw std::invalid_argument("give `t-end` or `periods`, not both");
  const long levels = so.integer("refine");
  require_in_range("refine", double(levels), 0, 8);
  refine = int(levels);
  const std::size_t nxf = RefinementPlan::fine_count(std::size_t(o.omega_points), refine);
  const std::size_t nyf = RefinementPlan::fine_count(std::size_t(o.beta_points), refine);
  if (double(nxf) * double(nyf) > 4e6)
    throw std::invalid_argument("refine: the fine lattice would have " + std::to_string(nxf * nyf) +
                                " points (at most 4e6): lower `refine` or the point counts");
  return o;
}

json survival_run_options(const SurvivalOptions& o, const ForcedModel& fm, int refine) {
  return {{"excitation", o.excitation},
          {"phase", o.phase},
          {"t_end", o.periods > 0 ? json(nullptr) : json(o.t_end)},
          {"periods", o.periods},
          {"t_star_classes_s", o.t_star_classes},
          {"failure", fm.overturn_rule},
          {"pulse_duration", o.excitation == "harmonic" ? "" : "pi / Omega (half a forcing period)"},
          {"refine", refine},
          {"cycle",
           "harmonic: the dominant (m, n) cycle of block 0 over the run (2m impacts per n forcing "
           "periods, seed 002; `blockdyn cycles` with its default window and tolerance, fitted to "
           "the run's length; before t* for a collapse), or non-periodic / no-impacts; null at rest"}};
}

StudyReport survival_report(const Table& t, const ForcedModel& fm, const SurvivalOptions& o, int refine,
                            const json& options, const std::string& title) {
  StudyReport rep;
  json& j = rep.summary;
  j = forced_summary_head(fm);
  j["units"] = "a_H = beta alpha g cos(omega p t + phase); t in s";
  j["options"] = options;
  j["tolerances"] = fm.tolerances;
  const SurvivalPoints sp = survival_points(t, refine > 0);
  j["counts"] = sp.counts_json();
  j["points"] = sp.points;
  rep.figure = FigureSpec{"survival", {"@csv:table", "@plot"}, {{"title", {title}}}};
  if (refine > 0)
    rep.figure.options.push_back(
        {"refined",
         {format_double(o.omega_points > 1 ? (o.omega_max - o.omega_min) / (o.omega_points - 1) : 1.0),
          format_double(o.beta_points > 1 ? (o.beta_max - o.beta_min) / (o.beta_points - 1) : 1.0)}});
  const auto& c = sp.counts;
  append_text(rep.text, "%zu points: %ld rest, %ld stable, %ld collapse, %ld invalid", t.rows.size(), c[0], c[1], c[2],
              c[3]);
  return rep;
}

GridStudy survival_grid(const Settings& given, const std::string& output) {
  const StudyOptions so(given, survival_options());
  int refine = 0;
  const SurvivalOptions o = survival_options_of(so, refine);
  const auto fm = std::make_shared<const ForcedModel>(forced_model_of(so));
  // The longest run the periods give (at the lowest frequency), before any file is made.
  if (o.periods > 0 && !(o.periods * 2 * M_PI / (o.omega_min * fm->p) <= 1e5))
    throw std::invalid_argument("periods = " + number_text(o.periods) + " gives runs of " +
                                number_text(o.periods * 2 * M_PI / (o.omega_min * fm->p), 6) +
                                " s at omega-min: at most 1e5 s (lower `periods` or raise `omega-min`)");
  const json options = survival_run_options(o, *fm, refine);
  const json definition = {{"model", fm->description},
                           {"alpha", fm->alpha},
                           {"p", fm->p},
                           {"beta", {{"min", o.beta_min}, {"max", o.beta_max}, {"points", o.beta_points}}},
                           {"omega", {{"min", o.omega_min}, {"max", o.omega_max}, {"points", o.omega_points}}},
                           {"options", options},
                           {"index", "omega fastest: index = i_omega + n_omega * i_beta on the (refined) lattice"}};
  std::vector<std::string> cols = survival_columns();
  cols.push_back("level");
  const std::size_t motion_col = 3, mode_col = 4;  // after index, beta, omega
  // Refinement classes points by motion and collapse mode.
  auto stages = std::make_shared<RefinementPlan>(
      std::size_t(o.omega_points), std::size_t(o.beta_points), refine,
      [](const CellRow& r) { return r[motion_col].text() + " " + r[mode_col].text(); });
  const std::size_t nxf = stages->nx_fine(), nyf = stages->ny_fine();
  // The table keeps the plan alive (a level per point), whoever holds the table.
  const std::shared_ptr<const RefinementPlan> plan = stages;
  GridStudy g;
  g.table = std::make_shared<const GridTable>(
      "survival", cols, stages->size(),
      [fm, o, nxf, nyf, plan](std::size_t i, CellRow& row) {
        const double omega = grid_value(o.omega_min, o.omega_max, int(nxf), int(i % nxf));
        const double beta = grid_value(o.beta_min, o.beta_max, int(nyf), int(i / nxf));
        add_survival_cells(survival_point(fm->run, o, fm->alpha, fm->p, beta, omega), row);
        row.emplace_back(static_cast<long long>(plan->level_of(i)));
      },
      definition, fm->tolerances, output);
  g.plan = stages;
  g.threads = o.threads;
  const std::string title = title_of(forced_model_choice(given), o.excitation);
  g.finish = [fm, o, refine, options, title](const Table& t) {
    return survival_report(t, *fm, o, refine, options, title);
  };
  return g;
}

}  // namespace

GridStudyCommand survival_command() {
  return {"survival",
          "survival domain over (beta, omega): rest, stable or collapse per point for a_H = beta alpha g cos(Omega t + "
          "phase), omega = Omega/p (seed 002), harmonic or as a half-period pulse (threads, MPI, resumable)",
          14,
          survival_options(),
          survival_grid,
          "out",
          "the points as CSV (the runner's table: journal and sidecar .json beside it)",
          {{"plot", "plot the survival domain (PNG + SVG) in the style of seed 002"}},
          "no summary line, no progress"};
}

}  // namespace blockdyn
