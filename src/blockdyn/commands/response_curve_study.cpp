// SPDX-License-Identifier: Apache-2.0
// `response-curve`: the largest rotation theta_MAX / alpha (assemblies: the largest slip between
// blocks / b) versus omega for several beta, or versus the friction angle phi_l (seed 001 Figs.
// 4-7, seed 002 Figs. 3-5, 10-11).
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

std::vector<StudyOption> response_curve_options() {
  std::vector<StudyOption> o = forced_model_options();
  o.push_back({"betas", "amplitudes beta, comma separated (a_H = beta alpha g ...)", "", false, true});
  for (const StudyOption& x : excitation_grid_options()) o.push_back(x);
  const std::vector<StudyOption> own = {
      {"omega", "one frequency omega = Omega/p (instead of `omega-min`/max/points)", ""},
      {"phi-l-values",
       "assembly: friction angles between blocks [deg], \"v1,v2,...\" or \"min:max:points\"; more than one makes "
       "phi_l the curve's abscissa (seed 002 Figs. 4-5; needs one `omega`)",
       ""},
      {"phi-s-values",
       "assembly: friction angles on the ground [deg], \"v1,v2,...\" or \"min:max:points\" (one curve each)", ""}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

// The amplitudes and frequencies: --betas, and --omega (one frequency) or the omega range.
SurvivalOptions curve_grid_of(const StudyOptions& so) {
  SurvivalOptions o = excitation_grid_of(so);
  o.betas = so.given("betas") ? so.numbers("betas") : std::vector<double>{};
  if (o.betas.empty()) throw std::invalid_argument("`betas` B1,B2,... is needed (the amplitudes, in units of alpha g)");
  o.beta_points = int(o.betas.size());
  if (so.given("omega")) {
    for (const char* n : {"omega-min", "omega-max", "omega-points"})
      if (so.given(n))
        throw std::invalid_argument(std::string("`omega` and `") + n + "`: give one frequency or a range");
    const double omega = so.number("omega");
    require_in_range("omega", omega, 0, 1e4, false);
    o.omega_min = o.omega_max = omega;
    o.omega_points = 1;
  }
  if (so.given("t-end") && so.given("periods")) throw std::invalid_argument("give `t-end` or `periods`, not both");
  validate(o);
  return o;
}

// A friction-angle axis (deg, in (0, 90]) from --phi-X-values, or the single --phi-X value.
std::vector<double> phi_axis(const StudyOptions& so, const std::string& name, double single) {
  if (!so.given(name + "-values")) return {single};
  if (so.given(name))
    throw std::invalid_argument(std::string("`") + name + "-values` and `" + name + "`: give only one");
  const SweepAxis a = parse_axis(name + "-values", so.text(name + "-values"), AxisSpacing::Linear);
  for (double v : a.values)
    if (!(v > 0 && v <= 90)) throw std::invalid_argument(name + "-values: each angle must be in (0, 90] deg");
  return a.values;
}

struct CurveAxes {
  std::vector<double> phi_s, phi_l;
  std::vector<ForcedModel> models;  // one per friction pair, phi_s outer, built before any point runs
};

CurveAxes curve_axes(const StudyOptions& so, const ForcedModelChoice& choice, const SurvivalOptions& o) {
  if ((so.given("phi-s-values") || so.given("phi-l-values")) && !choice.friction_angles())
    throw std::invalid_argument("phi-s-values, phi-l-values: friction angles belong to `model` assembly");
  CurveAxes a;
  a.phi_s = phi_axis(so, "phi-s", choice.phi_s);
  a.phi_l = phi_axis(so, "phi-l", choice.phi_l);
  if (a.phi_l.size() > 1 && o.omega_points > 1)
    throw std::invalid_argument("omega: give one frequency (`omega` W) for a curve versus phi-l");
  Settings model;
  for (const std::string& n : forced_model_option_names())
    for (const std::string& v : so.given_settings().values(n)) model.add(n, v);
  for (double ps : a.phi_s)
    for (double pl : a.phi_l) {
      Settings m = model;
      if (choice.friction_angles()) {
        m.set("phi-s", Settings::exact(ps));
        m.set("phi-l", Settings::exact(pl));
      }
      a.models.push_back(forced_model_from(m));
    }
  return a;
}

std::string curve_title(const ForcedModelChoice& m, const SurvivalOptions& o, const CurveAxes& a, bool versus_phi) {
  std::string title = m.label() + ", " + o.excitation + (versus_phi ? ", omega = " + short_num(o.omega_min) : "");
  if (m.friction_angles()) {
    title += ", " + m.contact + " law" + (m.columns_rock_only ? " (columns only rock)" : "");
    if (a.phi_s.size() == 1) title += ", phi_s = " + short_num(a.phi_s[0]);
    if (a.phi_l.size() == 1) title += ", phi_l = " + short_num(a.phi_l[0]);
  }
  return title;
}

void add_curve_cells(const CurveAxes& a, const SurvivalOptions& o, bool assembly, std::size_t i, CellRow& row) {
  const std::size_t nw = std::size_t(o.omega_points), nl = a.phi_l.size(), ns = a.phi_s.size();
  const std::size_t iw = i % nw, il = (i / nw) % nl, is = (i / (nw * nl)) % ns, ib = i / (nw * nl * ns);
  const ForcedModel& m = a.models[is * nl + il];
  const double omega = grid_value(o.omega_min, o.omega_max, o.omega_points, int(iw));
  const SurvivalPoint p = survival_point(m.run, o, m.alpha, m.p, o.betas[ib], omega);
  add_survival_cells(p, row);
  if (assembly) {
    row.emplace_back(a.phi_s[is]);
    row.emplace_back(a.phi_l[il]);
  } else {
    row.emplace_back();
    row.emplace_back();
  }
  row.emplace_back(p.max_abs_rotation / m.alpha);
  row.emplace_back(p.max_sliding / m.width);
}

GridStudy response_curve_grid(const Settings& given, const std::string& output) {
  const StudyOptions so(given, response_curve_options());
  const SurvivalOptions o = curve_grid_of(so);
  const ForcedModelChoice choice = forced_model_choice(given);
  const auto axes = std::make_shared<const CurveAxes>(curve_axes(so, choice, o));
  const ForcedModel& fm = axes->models.front();
  const bool assembly = choice.friction_angles(), versus_phi = axes->phi_l.size() > 1;
  const json options = {{"excitation", o.excitation},
                        {"phase", o.phase},
                        {"t_end", o.periods > 0 ? json(nullptr) : json(o.t_end)},
                        {"periods", o.periods},
                        {"versus", versus_phi ? "phi_l" : "omega"}};
  json model = fm.description;
  if (assembly) {
    model["phi_s"] = axes->phi_s;
    model["phi_l"] = axes->phi_l;
  }
  const json definition = {
      {"model", model},     {"alpha", fm.alpha},
      {"p", fm.p},          {"width", fm.width},
      {"betas", o.betas},   {"omega", {{"min", o.omega_min}, {"max", o.omega_max}, {"points", o.omega_points}}},
      {"options", options}, {"index", "i_omega + n_omega * (i_phi_l + n_phi_l * (i_phi_s + n_phi_s * i_beta))"}};
  std::vector<std::string> cols = survival_columns();
  for (const char* c : {"phi_s", "phi_l", "theta_max_over_alpha", "max_sliding_over_b"}) cols.push_back(c);
  GridStudy g;
  g.table = std::make_shared<const GridTable>(
      "response-curve", cols, std::size_t(o.omega_points) * axes->phi_l.size() * axes->phi_s.size() * o.betas.size(),
      [axes, o, assembly](std::size_t i, CellRow& row) { add_curve_cells(*axes, o, assembly, i, row); }, definition,
      fm.tolerances, output);
  g.threads = o.threads;
  const std::string title = curve_title(choice, o, *axes, versus_phi);
  g.finish = [axes, model, options, assembly, title, versus_phi](const Table& t) {
    const ForcedModel& m = axes->models.front();
    StudyReport rep;
    json& j = rep.summary;
    j["run"] = run_info();
    j["model"] = model;
    j["alpha"] = m.alpha;
    j["p"] = m.p;
    j["width"] = m.width;
    j["units"] =
        "a_H = beta alpha g cos(omega p t + phase); rotations over alpha, slips over the block width; "
        "friction angles in deg";
    j["options"] = options;
    j["tolerances"] = m.tolerances;
    j["points"] = response_curve_points(t, assembly);
    rep.figure = FigureSpec{
        "response_curve", {"@csv:table", "@plot"}, {{"title", {title}}, {"x", {versus_phi ? "phi_l" : "omega"}}}};
    append_text(rep.text, "%zu points", t.rows.size());
    return rep;
  };
  return g;
}

}  // namespace

GridStudyCommand response_curve_command() {
  return {
      "response-curve",
      "largest rotation theta_MAX / alpha (and slip between blocks / b) versus omega = Omega/p for several beta, or "
      "versus the friction angle phi_l, under a_H = beta alpha g cos(Omega t + phase) (threads, MPI, resumable)",
      15,
      response_curve_options(),
      response_curve_grid,
      "out",
      "the points as CSV (the runner's table: journal and sidecar .json beside it)",
      {{"plot",
        "plot theta_MAX / alpha (and the slip) versus omega or phi_l, one curve per beta and phi_s (PNG + "
        "SVG)"}},
      "no summary line, no progress"};
}

}  // namespace blockdyn
