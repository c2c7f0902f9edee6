// SPDX-License-Identifier: Apache-2.0
// `spectrum`: the smallest overturning amplitude of a pulse per duration, the safe islands above it
// and the overturn / survive picture of the scan.
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
    throw std::invalid_argument(list ? "give `durations` or `duration-min`/`duration-max`/`duration-points`, not both"
                                     : "give `durations` D1,D2,... or `duration-min` `duration-max` `duration-points`");
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
      [test, o, pulse, alpha, p](std::size_t i, CellRow& row) {
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
    rep.figure = FigureSpec{"spectrum", {"@csv:table", "@plot"}, {{"title", {title}}}};
    rep.more_figures.push_back(
        {"plot-map",
         FigureSpec{"spectrum",
                    {"@csv:table", "@plot"},
                    {{"title", {title}}, {"map", {format_double(o.amplitude_min), format_double(o.amplitude_max)}}}}});
    rep.text = spectrum_text(sp);
    return rep;
  };
  return g;
}

}  // namespace

GridStudyCommand spectrum_command() {
  return {"spectrum",
          "overturning spectrum: the smallest pulse amplitude that overturns a block (or collapses an assembly), per "
          "pulse duration (s, g) (threads, MPI, resumable)",
          13,
          spectrum_options(),
          spectrum_grid,
          "csv",
          "the spectrum as CSV (the runner's table: journal and sidecar .json beside it)",
          {{"plot", "plot the spectrum (PNG + SVG), with the linearised closed form for rect"},
           {"plot-map", "plot the overturn / survive picture over (duration, amplitude) from the scan (PNG + SVG)"}},
          "no table, no progress"};
}

}  // namespace blockdyn
