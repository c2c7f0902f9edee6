// SPDX-License-Identifier: Apache-2.0
// Studies of one run under seed 002's harmonic motion, for a block on rigid ground or an assembly:
// `cycles` (stroboscopic samples and (m, n) cycles over sliding windows, seed 002 Figs. 12-14) and
// `impact-map` (the forcing phase of every impact against the angular velocity before it, seed 002
// Fig. 15b, and the forced Poincare map at a forcing phase).
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "blockdyn/analysis/forced/cycle_detection.hpp"

#include "blockdyn/analysis/forced/impact_map.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/harmonic_run.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

// ---------------------------------------------------------------- cycles

constexpr const char* kConvention =
    "(m, n): 2m impacts in an orbit that repeats every n forcing periods (seed 002); seed 001 calls a motion with k "
    "impacts per n forcing periods an (n, k) motion, i.e. our (m, n) is its (n, 2m)";

std::vector<StudyOption> cycles_options() {
  const CycleOptions d;
  std::vector<StudyOption> o = harmonic_run_options(100);
  const std::vector<StudyOption> own = {
      {"window", "forcing periods per sliding window", std::to_string(d.window)},
      {"max-period", "largest n tried, at most window / 2", std::to_string(d.max_period)},
      {"tolerance",
       "largest return distance of the strobe samples after n periods, relative to the window's largest |theta| and "
       "|theta'|",
       Settings::exact(d.tolerance)},
      {"transient", "forcing periods skipped before the first window", std::to_string(d.transient)}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

json segment_json(const CycleSegment& s, double period) {
  const bool periodic = s.type == "periodic";
  json m = nullptr;
  if (periodic) m = s.impacts_per_cycle % 2 == 0 ? json(s.impacts_per_cycle / 2) : json(s.m());
  return {{"t_start", s.t_start},
          {"t_end", s.t_end},
          {"type", s.type},
          {"m", m},
          {"n", periodic ? json(s.n) : json(nullptr)},
          {"cycle", s.label()},
          {"impacts", s.impacts},
          {"periods", (s.t_end - s.t_start) / period},
          {"return_distance", periodic ? json(s.return_distance) : json(nullptr)}};
}

CycleOptions cycle_options_of(const StudyOptions& o) {
  CycleOptions c;
  c.window = o.small_integer("window");
  c.max_period = o.small_integer("max-period");
  c.tolerance = o.number("tolerance");
  c.transient = o.small_integer("transient");
  validate(c);
  return c;
}

json cycles_summary(const HarmonicSetup& h, const HarmonicRun& r, const CycleOptions& c, const CycleReport& rep,
                    std::size_t impacts) {
  const ForcedTrace& tr = *r.trace;
  json j;
  describe_run(j, h, r);
  j["convention"] = kConvention;
  j["options"] = {{"window", c.window},
                  {"max_period", c.max_period},
                  {"tolerance", c.tolerance},
                  {"transient", c.transient},
                  {"strobe", "t = k T, k = 0, 1, ... (forcing phase = phase)"},
                  {"compared", "theta and theta' of the block, relative to their largest magnitudes in the window"}};
  j["strobe_samples"] = tr.strobes();
  j["impacts"] = impacts;
  j["windows"] = rep.windows;
  const long periods = long(tr.strobes()) - 1;
  if (rep.windows == 0)
    j["note"] = "the run offers " + std::to_string(periods - c.transient) +
                " periods after the transient, fewer than one window of " + std::to_string(c.window) +
                ": no cycle classified";
  json segs = json::array();
  for (const CycleSegment& sg : rep.segments) segs.push_back(segment_json(sg, h.period));
  j["segments"] = segs;
  json ch = json::array();
  for (const CycleChange& x : rep.changes) ch.push_back({{"t", x.t}, {"from", x.from}, {"to", x.to}});
  j["changes"] = ch;
  j["dominant_cycle"] = rep.dominant.empty() ? json(nullptr) : json(rep.dominant);
  return j;
}

StudyReport cycles_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, cycles_options());
  const CycleOptions c = cycle_options_of(o);
  const HarmonicSetup h = harmonic_setup(o);
  const HarmonicRun r = run_harmonic(h, 0.0, request.wants("trace") ? h.trace_per_period : 1);
  const ForcedTrace& tr = *r.trace;
  const std::size_t impacts = impacts_of(tr, h.block, h.fm.impact_rule).size();
  const CycleReport cyc = cycles_of(tr, h.block, h.fm.impact_rule, c, r.outcome.t_failure);

  StudyReport rep;
  rep.summary = cycles_summary(h, r, c, cyc, impacts);
  // The cycle label of the segment holding t (the last segment's up to its end).
  auto label_at = [&](double t) -> Cell {
    for (const CycleSegment& sg : cyc.segments)
      if (sg.type != "collapse" && t >= sg.t_start && t <= sg.t_end) return Cell::quoted(sg.label());
    return c.transient > 0 && t < c.transient * h.period ? Cell("transient") : Cell();
  };
  if (request.wants("strobe")) rep.series.push_back({"strobe", samples_table(tr, true, "cycle", label_at)});
  if (request.wants("trace")) rep.series.push_back({"trace", samples_table(tr, false)});
  rep.figure = FigureSpec{"cycles",
                          {"@csv:strobe", "@plot"},
                          {{"trace", {"@csv:trace"}},
                           {"block", {std::to_string(h.block)}},
                           {"period", {short_num(h.period)}},
                           {"title", {h.title}}}};
  append_text(rep.text, "%zu strobe samples, %zu impacts, %s\n", tr.strobes(), impacts,
              rep.summary["status"].get<std::string>().c_str());
  for (const CycleSegment& sg : cyc.segments)
    append_text(rep.text, "  %10.4f .. %10.4f s  %s\n", sg.t_start, sg.t_end, sg.label().c_str());
  return rep;
}

// ---------------------------------------------------------------- impact-map

std::vector<StudyOption> impact_map_options() {
  std::vector<StudyOption> o = harmonic_run_options(200);
  o.push_back({"section-phase",
               "forcing phase phi0 of the Poincare section: the state where Omega t + phase = phi0 mod 2 pi [rad]",
               "0"});
  o.push_back({"transient", "forcing periods left out of the maps", "0"});
  return o;
}

StudyTable impacts_table(const std::vector<ImpactMapPoint>& map) {
  StudyTable t;
  t.columns = {"i", "t", "phase", "omega_before", "omega_after"};
  for (std::size_t i = 0; i < map.size(); ++i)
    t.rows.push_back({i, map[i].t, map[i].phase, map[i].omega_before, map[i].omega_after});
  return t;
}

StudyReport impact_map_study(const Settings& given, const StudyRequest& request) {
  const StudyOptions o(given, impact_map_options());
  const double section_phase = o.number("section-phase");
  const long transient = o.integer("transient");
  require_in_range("section-phase", section_phase, -1e3, 1e3);
  require_in_range("transient", double(transient), 0, 1e7);
  const HarmonicSetup h = harmonic_setup(o);
  const double t_from = double(transient) * h.period;
  if (!(t_from < h.t_end))
    throw std::invalid_argument("transient: " + std::to_string(transient) + " periods leave nothing of a run of " +
                                number_text(h.t_end / h.period, 6) + " periods");
  const double t0 = section_time(h.Omega, h.phase, section_phase);
  const HarmonicRun r = run_harmonic(h, t0, request.wants("trace") ? h.trace_per_period : 1);
  const ForcedTrace& tr = *r.trace;
  const std::vector<ImpactMapPoint> map =
      impact_map(impacts_of(tr, h.block, h.fm.impact_rule), h.Omega, h.phase, t_from);
  std::size_t sections = 0;
  for (std::size_t k = 0; k < tr.strobes(); ++k) sections += tr.strobe_t(k) >= t_from;

  StudyReport rep;
  json& j = rep.summary;
  describe_run(j, h, r);
  j["phase_definition"] =
      "Phi = (Omega t + phase) mod 2 pi in [0, 2 pi): the forcing phase (seed 002: Omega t mod 2 pi, "
      "phase 0); omega_before / omega_after: the block's angular velocity before / after the impact";
  j["section_phase"] = section_phase;
  j["section_t0"] = t0;
  j["transient"] = transient;
  j["impacts"] = map.size();
  j["poincare_samples"] = sections;
  double wmin = INFINITY, wmax = -INFINITY;
  for (const ImpactMapPoint& p : map) {
    wmin = std::fmin(wmin, p.omega_before);
    wmax = std::fmax(wmax, p.omega_before);
  }
  j["omega_before_range"] = map.empty() ? json(nullptr) : json::array({wmin, wmax});
  if (request.wants("impacts")) rep.series.push_back({"impacts", impacts_table(map)});
  if (request.wants("poincare")) rep.series.push_back({"poincare", samples_table(tr, true, "", {}, t_from)});
  if (request.wants("trace")) rep.series.push_back({"trace", samples_table(tr, false, "", {}, t_from)});
  rep.figure = FigureSpec{"impact_map",
                          {"@csv:impacts", "@plot"},
                          {{"poincare", {"@csv:poincare"}},
                           {"trace", {"@csv:trace"}},
                           {"block", {std::to_string(h.block)}},
                           {"section-phase", {short_num(section_phase)}},
                           {"period", {short_num(h.period)}},
                           {"title", {h.title}}}};
  append_text(rep.text, "%zu impacts, %zu Poincare samples (phase %g), %s\n", map.size(), sections, section_phase,
              j["status"].get<std::string>().c_str());
  return rep;
}

}  // namespace

void add_harmonic_studies(std::vector<StudyCommand>& to) {
  StudyCommand cycles{"cycles",
                      "stroboscopic samples at multiples of the forcing period and (m, n) cycles (2m impacts per n "
                      "forcing periods, seed 002) over sliding windows, under a_H = beta alpha g cos(Omega t + phase)",
                      16,
                      StudyOutputs::Series,
                      cycles_options(),
                      cycles_study};
  cycles.series_outputs = {
      {"strobe", "out", "write the strobe samples as CSV (k, t, states per block, cycle)"},
      {"trace", "trace", "write the trajectory sampled `trace-per-period` times per period as CSV"}};
  cycles.quiet_flag = true;
  to.push_back(cycles);
  StudyCommand map{"impact-map",
                   "impact map (forcing phase (Omega t + phase) mod 2 pi versus the angular velocity before each "
                   "impact, seed 002 Fig. 15b) and forced Poincare map at a forcing phase, under a_H = beta alpha g "
                   "cos(Omega t + phase)",
                   17,
                   StudyOutputs::Series,
                   impact_map_options(),
                   impact_map_study};
  map.series_outputs = {{"impacts", "out", "write the impacts as CSV (i, t, phase, omega_before, omega_after)"},
                        {"poincare", "poincare", "write the Poincare section as CSV (k, t, states per block)"},
                        {"trace", "trace", "write the trajectory sampled `trace-per-period` times per period as CSV"}};
  map.quiet_flag = true;
  to.push_back(map);
}

}  // namespace blockdyn
