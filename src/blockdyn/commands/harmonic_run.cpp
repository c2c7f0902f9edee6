// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/harmonic_run.hpp"

#include "blockdyn/base/number_text.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "blockdyn/analysis/forced/survival_map.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/forced_model_settings.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;

std::vector<StudyOption> forced_model_options(const std::vector<std::string>& extra_models) {
  std::string help =
      "housner, rigid (a block on rigid ground), assembly (with `preset`) or rigid3d (a box or cylinder, the motion "
      "along `incidence`)";
  for (const auto& m : extra_models) help += ", or " + m;
  return {{"model", help, extra_models.empty() ? "housner" : extra_models.front()},
          {"width", "housner/rigid/rigid3d: block width [m]", ""},
          {"height", "housner/rigid/rigid3d: block height [m]", ""},
          {"mass", "housner/rigid/rigid3d: mass [kg] (default 1; rigid3d 100)", ""},
          {"shape", "rigid3d: box or cylinder (default box)", ""},
          {"depth", "rigid3d: the box's depth along e2 [m] (default: `width`)", ""},
          {"incidence", "rigid3d: the motion's direction, degrees from the body's e1 towards e2 (default 0)", ""},
          {"g", "gravity [m/s^2] (default 9.81)", ""},
          {"mu-s", "rigid/rigid3d: static friction (default 0.7)", ""},
          {"mu-k", "rigid/rigid3d: kinetic friction (default mu-s)", ""},
          {"impact", "rigid: housner or newton", ""},
          {"restitution", "restitution (housner/rigid as in simulate; assembly as in assembly)", ""},
          {"preset", "assembly: block, trilith, column or arch", ""},
          {"contact", "assembly: deformable or rigid", ""},
          {"slenderness", "assembly: height / width (default 4)", ""},
          {"block-width", "assembly: width [m] (default 0.12)", ""},
          {"drums", "assembly column: drums (default 4)", ""},
          {"thickness", "assembly: out-of-plane depth [m] (default 0.06)", ""},
          {"density", "assembly: density [kg/m^3] (default 2700); rigid3d: instead of `mass`", ""},
          {"lintel-length", "assembly trilith: lintel length [m] (default: column height)", ""},
          {"overhang", "assembly trilith: lintel beyond each column's outer face [m] (default 0)", ""},
          {"voussoirs", "assembly arch: number of voussoirs (default 9)", ""},
          {"thickness-ratio", "assembly arch: ring thickness / centreline radius (default 0.15)", ""},
          {"radius", "assembly arch: centreline radius [m] (default 1); rigid3d cylinder: its radius [m]", ""},
          {"embrace", "assembly arch: angle spanned [deg] (default 180)", ""},
          {"phi-s", "assembly: friction angle on the ground [deg] (default 90)", ""},
          {"phi-l", "assembly: friction angle between blocks [deg] (default 90)", ""},
          {"columns-rock-only",
           "assembly, rigid law: the blocks on the ground only rock (no sliding, plastic impacts): seed 001's 5-DOF "
           "trilith",
           "", true}};
}

ForcedModel forced_model_of(const StudyOptions& o) {
  Settings model;
  const Settings& given = o.given_settings();
  for (const std::string& n : forced_model_option_names())
    for (const std::string& v : given.values(n)) model.add(n, v);
  return forced_model_from(model);
}

std::string forced_model_label(const StudyOptions& o) { return forced_model_choice(o.given_settings()).label(); }

std::vector<StudyOption> harmonic_run_options(double default_periods) {
  std::vector<StudyOption> o = forced_model_options();
  const std::vector<StudyOption> run = {
      {"excitation", "harmonic (the only one: cycles need a periodic motion)", "harmonic"},
      {"beta", "amplitude: a_H = beta alpha g cos(Omega t + phase) (required)", ""},
      {"omega", "frequency omega = Omega / p (required)", ""},
      {"phase", "phase of cos(Omega t + phase) [rad]", "0"},
      {"t-end", "duration of the run [s]", ""},
      {"periods", "duration of the run in forcing periods (instead of `t-end`)", Settings::exact(default_periods)},
      {"block", "the block analysed (assemblies: 0 is the first column)", "0"},
      {"trace-per-period", "samples per forcing period of the trace and of the figures' trajectories", "32"}};
  o.insert(o.end(), run.begin(), run.end());
  return o;
}

HarmonicSetup harmonic_setup(const StudyOptions& o) {
  if (o.text("excitation") != "harmonic")
    throw std::invalid_argument("`excitation` = '" + o.text("excitation") + "' is not one of: harmonic");
  if (!o.given("beta"))
    throw std::invalid_argument("`beta` is needed (a_H = beta alpha g cos(Omega t + phase)), in (0, 1000]");
  if (!o.given("omega")) throw std::invalid_argument("`omega` is needed (omega = Omega / p), in (0, 1e4]");
  HarmonicSetup h;
  h.beta = o.number("beta");
  h.omega = o.number("omega");
  h.phase = o.number("phase");
  require_in_range("beta", h.beta, 0, 1e3, false);
  require_in_range("omega", h.omega, 0, 1e4, false);
  require_in_range("phase", h.phase, -1e3, 1e3);
  if (o.given("t-end") && o.given("periods")) throw std::invalid_argument("give `t-end` or `periods`, not both");
  const double periods = o.number("periods");
  if (o.given("t-end"))
    require_in_range("t-end", o.number("t-end"), 0, 1e5, false);
  else
    require_in_range("periods", periods, 0, 1e6, false);
  const long per_period = o.integer("trace-per-period");
  require_in_range("trace-per-period", double(per_period), 1, 4096);
  h.trace_per_period = int(per_period);
  h.fm = forced_model_of(o);
  const long block = o.integer("block");
  require_in_range("block", double(block), 0, double(h.fm.block_names.size()) - 1);
  h.block = int(block);
  SurvivalOptions so;
  so.excitation = "harmonic";
  so.phase = h.phase;
  h.g = survival_motion(so, h.beta, h.omega, h.fm.alpha, h.fm.p);
  h.period = 1.0 / h.g.horizontal.frequency;
  h.Omega = 2 * M_PI * h.g.horizontal.frequency;
  h.t_end = o.given("t-end") ? o.number("t-end") : periods * h.period;
  if (!(h.t_end <= 1e5))
    throw std::invalid_argument("periods: the run would last " + number_text(h.t_end, 6) + " s, at most 1e5 s");
  if (h.t_end / h.period > 1e6) throw std::invalid_argument("t-end: more than 1e6 forcing periods");
  h.title = forced_model_label(o) + ", beta = " + short_num(h.beta) + ", omega = " + short_num(h.omega) +
            ", phase = " + short_num(h.phase) + ", " + h.fm.block_names[h.block];
  return h;
}

HarmonicRun run_harmonic(const HarmonicSetup& h, double t0, int per_period) {
  if (h.t_end / h.period * per_period > 1e7)
    throw std::invalid_argument("trace-per-period: " + std::to_string(per_period) + " samples per period over " +
                                number_text(h.t_end / h.period, 6) + " periods exceed 1e7 samples");
  HarmonicRun r;
  r.trace = std::make_unique<ForcedTrace>(t0, h.period, per_period);
  r.trace->keep_events_of(h.block);
  if (!h.fm.traced)
    throw std::invalid_argument("`model` " + h.fm.description.value("model", std::string("?")) +
                                ": no strobe trace of its runs yet (cycles and impact maps)");
  r.outcome = h.fm.traced(h.g, h.t_end, r.trace.get());
  return r;
}

CellTable samples_table(const ForcedTrace& tr, bool strobe_only, const std::string& extra_column,
                        const std::function<Cell(double)>& extra, double t_from) {
  CellTable table;
  table.columns = {"k", "t"};
  for (int b = 0; b < tr.blocks(); ++b)
    for (const char* c : {"x", "y", "theta", "vx", "vy", "omega"})
      table.columns.push_back(std::string(c) + "_" + std::to_string(b));
  if (!extra_column.empty()) table.columns.push_back(extra_column);
  const std::size_t n = strobe_only ? tr.strobes() : tr.samples();
  const std::size_t step = strobe_only ? std::size_t(tr.per_period()) : 1;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i * step;
    const double t = tr.sample_t(j);
    if (t < t_from) continue;
    CellRow row{i, t};
    for (int b = 0; b < tr.blocks(); ++b)
      for (double v : tr.state(j, b)) row.emplace_back(v);
    if (extra) row.push_back(extra(t));
    table.rows.push_back(std::move(row));
  }
  return table;
}

nlohmann::ordered_json forced_summary_head(const ForcedModel& fm) {
  return {{"run", run_info()}, {"model", fm.description}, {"alpha", fm.alpha}, {"p", fm.p}};
}

void describe_run(nlohmann::ordered_json& j, const HarmonicSetup& h, const HarmonicRun& r) {
  const json head = forced_summary_head(h.fm);
  for (auto it = head.begin(); it != head.end(); ++it) j[it.key()] = it.value();
  j["units"] = "a_H = beta alpha g cos(Omega t + phase), omega = Omega / p; t in s, theta in rad, theta' in rad/s";
  j["excitation"] = {{"type", "harmonic"},
                     {"beta", h.beta},
                     {"omega", h.omega},
                     {"phase", h.phase},
                     {"Omega", h.Omega},
                     {"period", h.period},
                     {"frequency", 1.0 / h.period},
                     {"amplitude_g", h.beta * h.fm.alpha}};
  j["t_end"] = h.t_end;
  j["block"] = h.block;
  j["block_name"] = h.fm.block_names[h.block];
  j["impact_definition"] = h.fm.impact_definition;
  const SurvivalOutcome& o = r.outcome;
  j["status"] = o.invalid ? "invalid" : o.collapse_mode ? "collapse" : "t_end";
  j["motion"] = o.invalid ? "invalid" : o.collapse_mode ? "collapse" : o.moved ? "stable" : "rest";
  j["collapse_mode"] = o.collapse_mode ? json(*o.collapse_mode) : json(nullptr);
  j["t_failure"] = o.t_failure ? json(*o.t_failure) : json(nullptr);
  j["t_final"] = r.trace->t_final();
  j["max_abs_rotation"] = o.max_abs_rotation;
}

std::string short_num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

}  // namespace blockdyn
