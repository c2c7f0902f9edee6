// SPDX-License-Identifier: Apache-2.0
// The grid studies: `survival` (survival domains over (beta, omega) for seed 002's excitation
// a_H = beta alpha g cos(Omega t + phase), harmonic or as a pulse, for a block on rigid ground or an
// assembly preset; --refine adds points near class changes) and `spectrum` (the smallest
// overturning amplitude of a pulse per duration, with the safe islands above it and the whole
// overturn / survive picture of the scan) and `response-curve` (the largest rotation theta_MAX /
// alpha, and for assemblies the largest slip between blocks over the block width, versus omega for
// several beta, or versus the friction angle between blocks phi_l: seed 001 Figs. 4-7, seed 002
// Figs. 3-5, 10-11).
#include "blockdyn/api/grid_studies.hpp"

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
#include "blockdyn/api/forced_model_settings.hpp"
#include "blockdyn/api/fragility.hpp"
#include "blockdyn/api/harmonic_run.hpp"
#include "blockdyn/api/rocking_spectrum.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

// --excitation --phase --omega-min/max/points --t-end --periods --threads (survival, response-curve).
std::vector<StudyOption> excitation_grid_options() {
  const SurvivalOptions d;
  auto x = [](double v) { return Settings::exact(v); };
  return {{"excitation", "harmonic (default), half-sine, half-cosine or rect (pulses last pi/Omega)", d.excitation},
          {"phase", "phase of cos(Omega t + phase) [rad]", x(d.phase)},
          {"omega-min", "smallest omega = Omega/p", x(d.omega_min)},
          {"omega-max", "largest omega", x(d.omega_max)},
          {"omega-points", "omegas, uniform", std::to_string(d.omega_points)},
          {"t-end", "duration of each run [s]: the transient window", x(d.t_end)},
          {"periods", "duration of each run in forcing periods (instead of --t-end)", ""},
          {"threads", "worker threads (0: all cores)", "0"}};
}

SurvivalOptions excitation_grid_of(const StudyOptions& o) {
  SurvivalOptions s;
  s.excitation = o.text("excitation");
  s.phase = o.number("phase");
  s.omega_min = o.number("omega-min");
  s.omega_max = o.number("omega-max");
  s.omega_points = o.small_integer("omega-points");
  s.t_end = o.number("t-end");
  if (o.given("periods")) s.periods = o.number("periods");
  s.threads = o.threads();
  return s;
}

std::string title_of(const ForcedModelChoice& m, const std::string& excitation) {
  std::string title = m.label() + ", " + excitation;
  if (m.friction_angles())
    title += ", " + m.contact + " law, phi_s = " + short_num(m.phi_s) + ", phi_l = " + short_num(m.phi_l);
  return title;
}

// ---------------------------------------------------------------- survival

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
        "--t-star-classes: 4 values are needed (the upper bounds of <=5 s, short, medium, long)");
  validate(o);
  if (so.given("t-end") && so.given("periods")) throw std::invalid_argument("give --t-end or --periods, not both");
  const long levels = so.integer("refine");
  require_in_range("refine", double(levels), 0, 8);
  refine = int(levels);
  const std::size_t nxf = RefinementPlan::fine_count(std::size_t(o.omega_points), refine);
  const std::size_t nyf = RefinementPlan::fine_count(std::size_t(o.beta_points), refine);
  if (double(nxf) * double(nyf) > 4e6)
    throw std::invalid_argument("refine: the fine lattice would have " + std::to_string(nxf * nyf) +
                                " points (at most 4e6): lower --refine or the point counts");
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
  rep.plot_script = "plot_survival.py";
  rep.plot_args = {"@csv:table", "@plot", "--title", title};
  if (refine > 0)
    rep.plot_args.insert(
        rep.plot_args.end(),
        {"--refined", format_double(o.omega_points > 1 ? (o.omega_max - o.omega_min) / (o.omega_points - 1) : 1.0),
         format_double(o.beta_points > 1 ? (o.beta_max - o.beta_min) / (o.beta_points - 1) : 1.0)});
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
                                " s at omega-min: at most 1e5 s (lower --periods or raise --omega-min)");
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
  auto stages = std::make_shared<RefinementPlan>(std::size_t(o.omega_points), std::size_t(o.beta_points), refine,
                                                 [](const std::string& r) {
                                                   const auto c = split_csv_line(r.substr(0, r.size() - 1));
                                                   return c[motion_col] + " " + c[mode_col];
                                                 });
  const std::size_t nxf = stages->nx_fine(), nyf = stages->ny_fine();
  // The table keeps the plan alive (a level per point), whoever holds the table.
  const std::shared_ptr<const RefinementPlan> plan = stages;
  GridStudy g;
  g.table = std::make_shared<const GridTable>(
      "survival", cols, stages->size(),
      [fm, o, nxf, nyf, plan](std::size_t i, RowBuilder& row) {
        const double omega = grid_value(o.omega_min, o.omega_max, int(nxf), int(i % nxf));
        const double beta = grid_value(o.beta_min, o.beta_max, int(nyf), int(i / nxf));
        add_survival_cells(survival_point(fm->run, o, fm->alpha, fm->p, beta, omega), row);
        row.add(static_cast<long long>(plan->level_of(i)));
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

// ---------------------------------------------------------------- spectrum

std::vector<StudyOption> spectrum_options() {
  const SpectrumOptions d;
  std::vector<StudyOption> o = forced_model_options();
  const std::vector<StudyOption> own = {
      {"pulse", std::string("pulse shape: ") + pulse_names(), "rect"},
      {"durations", "pulse durations t_p [s], comma separated", "", false, true},
      {"duration-min", "smallest duration [s] (geometric range)", ""},
      {"duration-max", "largest duration [s]", ""},
      {"duration-points", "number of durations", ""},
      {"amplitude-min", "smallest scanned amplitude [g]", Settings::exact(d.amplitude_min)},
      {"amplitude-max", "largest scanned amplitude [g]", Settings::exact(d.amplitude_max)},
      {"scan-points", "amplitudes scanned per duration, geometric", std::to_string(d.scan_points)},
      {"rel-tol", "relative tolerance of the minimum", Settings::exact(d.rel_tol)},
      {"t-after", "simulated time after the pulse [s]", "10"},
      {"threads", "worker threads (0: all cores)", "0"}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

std::vector<double> durations_of(const StudyOptions& o) {
  const bool list = o.given("durations");
  const bool range = o.given("duration-min") || o.given("duration-max") || o.given("duration-points");
  if (list == range)
    throw std::invalid_argument(list ? "give --durations or --duration-min/--duration-max/--duration-points, not both"
                                     : "give --durations D1,D2,... or --duration-min --duration-max --duration-points");
  if (list) return o.numbers("durations");
  const double lo = o.given("duration-min") ? o.number("duration-min") : 0.0;
  const double hi = o.given("duration-max") ? o.number("duration-max") : 0.0;
  const long n = o.given("duration-points") ? o.integer("duration-points") : 0;
  require_in_range("duration-min", lo, 0, 1e4, false);
  require_in_range("duration-max", hi, lo, 1e4);
  require_in_range("duration-points", double(n), 1, 100000);
  std::vector<double> d(static_cast<std::size_t>(n));
  for (long i = 0; i < n; ++i) d[std::size_t(i)] = n == 1 ? lo : lo * std::pow(hi / lo, double(i) / double(n - 1));
  return d;
}

GroundMotion pulse_motion(PulseShape shape, double amplitude, double duration) {
  GroundMotion g;
  g.horizontal.pulse = shape;
  g.horizontal.amplitude = amplitude;
  g.horizontal.duration = duration;
  return g;
}

std::string spectrum_text(const SpectrumPoints& sp) {
  std::string t = "duration [s]  min overturning amplitude [g]  safe islands above\n";
  for (const SpectrumRow& r : sp.rows)
    append_text(t, "%12.6g  %29s  %zu\n", r.duration,
                r.min_overturning_amplitude ? std::to_string(*r.min_overturning_amplitude).c_str() : "none in scan",
                r.safe_islands.size());
  append_text(t, "%ld simulations", sp.runs);
  return t;
}

GridStudy spectrum_grid(const Settings& given, const std::string& output) {
  const StudyOptions so(given, spectrum_options());
  const auto shape = pulse_from_string(so.text("pulse"));
  if (!shape || *shape == PulseShape::None)
    throw std::invalid_argument("pulse = '" + so.text("pulse") + "' must be one of " + pulse_names());
  SpectrumOptions o;
  o.durations = durations_of(so);
  o.amplitude_min = so.number("amplitude-min");
  o.amplitude_max = so.number("amplitude-max");
  o.scan_points = so.small_integer("scan-points");
  o.rel_tol = so.number("rel-tol");
  const double t_after = so.number("t-after");
  require_in_range("t-after", t_after, 0, 1e4);
  o.threads = so.threads();
  validate(o);
  const auto fm = std::make_shared<const ForcedModel>(forced_model_of(so));
  const PulseShape pulse = *shape;
  const OverturnTest test = [fm, pulse, t_after](double amplitude, double duration) {
    const SurvivalOutcome r =
        fm->run(pulse_motion(pulse, amplitude, duration), pulse_support(pulse) * duration + t_after);
    return r.collapse_mode ? kOverturns : r.invalid ? kOutsideModel : kSurvives;
  };
  const json options = {{"amplitude_min", o.amplitude_min},
                        {"amplitude_max", o.amplitude_max},
                        {"scan_points", o.scan_points},
                        {"rel_tol", o.rel_tol},
                        {"t_after", t_after},
                        {"overturn", fm->overturn_rule}};
  const json definition = {{"model", fm->description},
                           {"pulse", to_string(pulse)},
                           {"alpha", fm->alpha},
                           {"p", fm->p},
                           {"durations", o.durations},
                           {"options", options},
                           {"index", "the duration's position"}};
  GridStudy g;
  const double alpha = fm->alpha, p = fm->p;
  g.table = std::make_shared<const GridTable>(
      "spectrum", spectrum_columns(), o.durations.size(),
      [test, o, pulse, alpha, p](std::size_t i, RowBuilder& row) {
        const double d = o.durations[i];
        add_spectrum_cells(spectrum_row(test, o, d),
                           pulse == PulseShape::Rect ? std::optional<double>(rect_pulse_overturning_linear(alpha, p, d))
                                                     : std::nullopt,
                           row);
      },
      definition, fm->tolerances, output);
  g.threads = o.threads;
  const std::string title = forced_model_choice(given).label() + " " + to_string(pulse) + " pulse";
  g.finish = [fm, o, pulse, options, title](const Table& t) {
    StudyReport rep;
    json& j = rep.summary;
    j["run"] = run_info();
    j["model"] = fm->description;
    j["pulse"] = to_string(pulse);
    j["alpha"] = fm->alpha;
    j["p"] = fm->p;
    j["units"] = "durations in s, amplitudes in g";
    j["options"] = options;
    j["tolerances"] = fm->tolerances;
    j["scan_amplitudes"] = scan_amplitudes(o);
    const SpectrumPoints sp = spectrum_points(t, pulse, fm->alpha, fm->p);
    j["rows"] = sp.json;
    j["runs"] = sp.runs;
    rep.plot_script = "plot_spectrum.py";
    rep.plot_args = {"@csv:table", "@plot", "--title", title};
    rep.more_figures.push_back({"plot-map",
                                {"@csv:table", "@plot", "--title", title, "--map", format_double(o.amplitude_min),
                                 format_double(o.amplitude_max)}});
    rep.text = spectrum_text(sp);
    return rep;
  };
  return g;
}

// ---------------------------------------------------------------- response-curve

std::vector<StudyOption> response_curve_options() {
  std::vector<StudyOption> o = forced_model_options();
  o.push_back({"betas", "amplitudes beta, comma separated (a_H = beta alpha g ...)", "", false, true});
  for (const StudyOption& x : excitation_grid_options()) o.push_back(x);
  const std::vector<StudyOption> own = {
      {"omega", "one frequency omega = Omega/p (instead of --omega-min/max/points)", ""},
      {"phi-l-values",
       "assembly: friction angles between blocks [deg], \"v1,v2,...\" or \"min:max:points\"; more than one makes "
       "phi_l the curve's abscissa (seed 002 Figs. 4-5; needs one --omega)",
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
  if (o.betas.empty()) throw std::invalid_argument("--betas B1,B2,... is needed (the amplitudes, in units of alpha g)");
  o.beta_points = int(o.betas.size());
  if (so.given("omega")) {
    for (const char* n : {"omega-min", "omega-max", "omega-points"})
      if (so.given(n))
        throw std::invalid_argument(std::string("--omega and --") + n + ": give one frequency or a range");
    const double omega = so.number("omega");
    require_in_range("omega", omega, 0, 1e4, false);
    o.omega_min = o.omega_max = omega;
    o.omega_points = 1;
  }
  if (so.given("t-end") && so.given("periods")) throw std::invalid_argument("give --t-end or --periods, not both");
  validate(o);
  return o;
}

// A friction-angle axis (deg, in (0, 90]) from --phi-X-values, or the single --phi-X value.
std::vector<double> phi_axis(const StudyOptions& so, const std::string& name, double single) {
  if (!so.given(name + "-values")) return {single};
  if (so.given(name)) throw std::invalid_argument("--" + name + "-values and --" + name + ": give only one");
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
    throw std::invalid_argument("phi-s-values, phi-l-values: friction angles belong to --model assembly");
  CurveAxes a;
  a.phi_s = phi_axis(so, "phi-s", choice.phi_s);
  a.phi_l = phi_axis(so, "phi-l", choice.phi_l);
  if (a.phi_l.size() > 1 && o.omega_points > 1)
    throw std::invalid_argument("omega: give one frequency (--omega W) for a curve versus phi-l");
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

void add_curve_cells(const CurveAxes& a, const SurvivalOptions& o, bool assembly, std::size_t i, RowBuilder& row) {
  const std::size_t nw = std::size_t(o.omega_points), nl = a.phi_l.size(), ns = a.phi_s.size();
  const std::size_t iw = i % nw, il = (i / nw) % nl, is = (i / (nw * nl)) % ns, ib = i / (nw * nl * ns);
  const ForcedModel& m = a.models[is * nl + il];
  const double omega = grid_value(o.omega_min, o.omega_max, o.omega_points, int(iw));
  const SurvivalPoint p = survival_point(m.run, o, m.alpha, m.p, o.betas[ib], omega);
  add_survival_cells(p, row);
  if (assembly) {
    row.add(a.phi_s[is]);
    row.add(a.phi_l[il]);
  } else {
    row.empty();
    row.empty();
  }
  row.add(p.max_abs_rotation / m.alpha);
  row.add(p.max_sliding / m.width);
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
      [axes, o, assembly](std::size_t i, RowBuilder& row) { add_curve_cells(*axes, o, assembly, i, row); }, definition,
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
    rep.plot_script = "plot_response_curve.py";
    rep.plot_args = {"@csv:table", "@plot", "--title", title, "--x", versus_phi ? "phi_l" : "omega"};
    append_text(rep.text, "%zu points", t.rows.size());
    return rep;
  };
  return g;
}

}  // namespace

const std::vector<GridStudyCommand>& grid_study_commands() {
  static const std::vector<GridStudyCommand> all = {
      {"spectrum",
       "overturning spectrum: the smallest pulse amplitude that overturns a block (or collapses an assembly), per "
       "pulse duration (s, g) (threads, MPI, resumable)",
       13,
       spectrum_options(),
       spectrum_grid,
       "csv",
       "the spectrum as CSV (the runner's table: journal and sidecar .json beside it)",
       {{"plot", "plot the spectrum (PNG + SVG), with the linearised closed form for rect"},
        {"plot-map", "plot the overturn / survive picture over (duration, amplitude) from the scan (PNG + SVG)"}},
       "no table, no progress"},
      {"survival",
       "survival domain over (beta, omega): rest, stable or collapse per point for a_H = beta alpha g cos(Omega t + "
       "phase), omega = Omega/p (seed 002), harmonic or as a half-period pulse (threads, MPI, resumable)",
       14,
       survival_options(),
       survival_grid,
       "out",
       "the points as CSV (the runner's table: journal and sidecar .json beside it)",
       {{"plot", "plot the survival domain (PNG + SVG) in the style of seed 002"}},
       "no summary line, no progress"},
      {"response-curve",
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
       "no summary line, no progress"},
      rocking_spectrum_command(),
      fragility_command()};
  return all;
}

const GridStudyCommand& grid_study_command(const std::string& name) {
  for (const GridStudyCommand& c : grid_study_commands())
    if (c.name == name) return c;
  throw std::invalid_argument("grid study '" + name +
                              "' is not one of: spectrum, survival, response-curve, rocking-spectrum, fragility");
}

Table compute_table(const PointTable& t, int threads, PointPlan* plan,
                    const std::function<void(std::size_t, std::size_t)>& progress) {
  std::map<std::size_t, std::string> rows;
  AllPoints all(t.size());
  PointPlan& p = plan ? *plan : all;
  std::size_t done = 0;
  const FinishedRow finished = [&rows](std::size_t i) -> const std::string* {
    const auto it = rows.find(i);
    return it == rows.end() ? nullptr : &it->second;
  };
  for (std::vector<std::size_t> stage = p.next_stage(finished); !stage.empty(); stage = p.next_stage(finished)) {
    std::vector<std::size_t> todo;
    for (std::size_t i : stage)
      if (!rows.count(i)) todo.push_back(i);
    const std::size_t total = done + todo.size();
    compute_rows(t, todo, threads, [&](std::size_t i, const SweepRow& r) {
      rows[i] = r.text;
      if (progress) progress(++done, total);
    });
  }
  Table out;
  const std::string& header = t.header();
  out.columns = split_csv_line(header.substr(0, header.size() - 1));
  for (const auto& [i, text] : rows) {
    TableRow r;
    r.cells = split_csv_line(text.substr(0, text.size() - 1));
    r.index = i;
    out.rows.push_back(std::move(r));
  }
  return out;
}

StudyReport run_grid_study(const std::string& name, const Settings& s,
                           const std::function<void(std::size_t, std::size_t)>& progress) {
  const GridStudyCommand& c = grid_study_command(name);
  s.require_known(c.options, {}, name);
  const GridStudy g = c.prepare(s, "(memory)");
  const Table t = compute_table(*g.table, g.threads, g.plan.get(), progress);
  StudyReport rep = g.finish(t);
  rep.table.columns = t.columns;
  for (const TableRow& r : t.rows) rep.table.rows.push_back(r.cells);
  rep.text += "\n";
  return rep;
}

}  // namespace blockdyn
