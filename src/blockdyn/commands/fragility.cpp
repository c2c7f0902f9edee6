// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/commands/fragility.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>

#include "blockdyn/analysis/forced/fragility_study.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/harmonic_run.hpp"
#include "blockdyn/commands/record_suite.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/response_spectrum.hpp"
#include "blockdyn/io/file_glob.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

std::vector<StudyOption> fragility_options() {
  std::vector<StudyOption> o = forced_model_options();
  const std::vector<StudyOption> own = {
      {"records", "the suite: a glob of record files (PEER .AT2 or CSV), e.g. 'suite/*.AT2' (quoted)"},
      {"suite",
       "the suite: a directory written by `motion generate` (its motions.json), its records in one, two or three "
       "components (rigid3d: h1 along `incidence`, h2 across it, v vertical; the measure the geometric mean of h1's "
       "and h2's)"},
      {"im",
       "intensity measure: pga (g), pgv (m/s), sa:T (Sa at period T s, g) or pga-over-uplift (PGA / (g tan alpha))",
       "pga"},
      {"levels", "the intensity levels A:B:N (N uniform from A to B) or a list A,B,C (> 0)"},
      {"damping", "damping ratio of sa:T", "0.05"},
      {"t-end", "duration of every run [s] (default: each record's end + `t-after`)"},
      {"t-after", "simulated time after each record's end [s]", "5"},
      {"bootstrap", "bootstrap resamples of the records for the 90 % band (0: none)", "200"},
      {"seed", "seed of the bootstrap", "1"},
      {"threads", "worker threads (0: all cores)", "0"}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

// "pga", "pgv", "sa:T" or "pga-over-uplift".
IntensityMeasure parse_intensity_measure(const std::string& field, const std::string& text, double damping) {
  IntensityMeasure im;
  im.text = text;
  im.damping = damping;
  if (text == "pga") {
    im.kind = IntensityMeasure::Kind::Pga;
  } else if (text == "pgv") {
    im.kind = IntensityMeasure::Kind::Pgv;
  } else if (text == "pga-over-uplift") {
    im.kind = IntensityMeasure::Kind::PgaOverUplift;
  } else if (text.rfind("sa:", 0) == 0) {
    im.kind = IntensityMeasure::Kind::Sa;
    im.period = parse_number_list(field, text.substr(3)).at(0);
    require_in_range(field + " (sa:T, T)", im.period, 0, 1e4, false);
  } else {
    throw std::invalid_argument(field + " = '" + text + "' is not one of: pga, pgv, sa:T, pga-over-uplift");
  }
  return im;
}

json fit_json(const FragilityFit& f, const FragilityBand& b, int bootstrap) {
  if (!f.ok) return {{"status", "no_fit"}, {"why", f.why}, {"median", nullptr}, {"beta", nullptr}};
  json j = {{"status", "fitted"}, {"median", f.median}, {"beta", f.beta}, {"log_likelihood", f.log_likelihood}};
  if (bootstrap > 0 && !b.fits.empty())
    j["ci90"] = {{"median", {b.median_lo, b.median_hi}},
                 {"beta", {b.beta_lo, b.beta_hi}},
                 {"resamples", b.samples},
                 {"resamples_without_fit", b.failed}};
  return j;
}

json curve_json(const std::vector<FragilityCurvePoint>& curve) {
  json c = json::array();
  for (const FragilityCurvePoint& pt : curve) {
    json row = {{"im", pt.im}, {"p", pt.p}};
    if (pt.p05) {
      row["p05"] = *pt.p05;
      row["p95"] = *pt.p95;
    }
    c.push_back(row);
  }
  return c;
}

// What the figure's title names: "housner block 0.4 m x 1.7 m", "trilith (3 blocks)".
std::string studied_object(const json& model) {
  const std::string family = model.value("model", std::string("model"));
  if (model.contains("width") && model.contains("height"))
    return family + " block " + number_text(model.at("width").get<double>(), 4) + " m x " +
           number_text(model.at("height").get<double>(), 4) + " m" +
           (model.contains("mu_s") ? ", mu_s " + number_text(model.at("mu_s").get<double>(), 3) : "");
  if (model.contains("preset"))
    return model.at("preset").get<std::string>() +
           (model.contains("blocks") ? " (" + std::to_string(model.at("blocks").size()) + " blocks)" : "");
  return family;
}

// The forced model with `incidence` one angle of the study's.
ForcedModel model_at_incidence(const Settings& given, double incidence) {
  Settings s = given;
  if (given.has("incidence")) s.set("incidence", format_double(incidence));
  const StudyOptions so(s, fragility_options());
  return forced_model_of(so);
}

// The runs as the runner's table holds them (row index: level fastest, then record).
std::vector<FragilityRunOutcome> runs_of(const Table& t, std::size_t n_levels) {
  const std::size_t cl = t.column("level"), cr = t.column("record_im"), cs = t.column("scale"),
                    co = t.column("overturned"), cm = t.column("max_abs_rotation"), cf = t.column("t_failure");
  std::vector<FragilityRunOutcome> runs;
  for (const TableRow& r : t.rows) {
    FragilityRunOutcome o;
    o.record = r.index / n_levels;
    o.level = r.cells[cl].number();
    o.record_im = r.cells[cr].number();
    o.scale = r.cells[cs].number();
    o.overturned = !r.cells[co].empty() && r.cells[co].integer() == 1;
    o.invalid = r.cells[co].empty();  // a run that left the model
    o.max_abs_rotation = r.cells[cm].number();
    if (!r.cells[cf].empty()) o.t_failure = r.cells[cf].number();
    runs.push_back(o);
  }
  return runs;
}

// A 3D study's fits at each incidence, and the critical incidence: the one of the smallest fitted
// median (where none fits, of the most overturned runs; ties: the first).
void by_incidence(json& j, const std::vector<FragilityRunOutcome>& runs, const FragilitySuite& suite,
                  const FragilityOptions& o) {
  std::vector<double> angles;
  for (std::size_t k = 0; k < suite.names.size(); ++k)
    if (suite.incidence_index[k] == angles.size()) angles.push_back(suite.incidence[k]);
  json all = json::array();
  std::size_t critical = 0;
  double best_median = INFINITY;
  std::size_t most_overturned = 0;
  bool any_fit = false;
  for (std::size_t a = 0; a < angles.size(); ++a) {
    FragilityOptions oa = o;
    oa.bootstrap = 0;  // the band is the whole study's
    const FragilityResult r = fragility_result_at_incidence(runs, suite, oa, a);
    std::size_t overturned = 0;
    for (const FragilityLevel& l : r.levels) overturned += l.n_overturned;
    all.push_back({{"incidence", angles[a]}, {"fit", fit_json(r.fit, r.band, 0)}, {"n_overturned", overturned}});
    const bool better =
        r.fit.ok ? (!any_fit || r.fit.median < best_median) : (!any_fit && overturned > most_overturned);
    if (better) critical = a;
    if (r.fit.ok && (!any_fit || r.fit.median < best_median)) best_median = r.fit.median;
    any_fit = any_fit || r.fit.ok;
    most_overturned = std::max(most_overturned, overturned);
  }
  j["incidences"] = all;
  j["critical_incidence"] = angles[critical];
}

// The report of the finished runs: the stripes, the fit and its band, the curve, the figure.
StudyReport fragility_report(const Table& t, const FragilitySuite& suite, const FragilityOptions& o,
                             const json& definition, const std::string& im) {
  const FragilityResult res = fragility_result(runs_of(t, o.levels.size()), suite, o);
  StudyReport rep;
  json& j = rep.summary;
  j["run"] = run_info();
  j["definition"] = definition;
  json runs = json::array();
  for (const FragilityRunOutcome& r : res.runs) {
    json one = {{"record", suite.names[r.record]},
                {"level", r.level},
                {"im", im},
                {"scale", r.scale},
                {"overturned", r.invalid ? json(nullptr) : json(r.overturned)},
                {"max_abs_rotation", r.max_abs_rotation}};
    if (r.invalid) one["outside_model"] = true;
    runs.push_back(one);
  }
  json lv = json::array();
  for (const FragilityLevel& l : res.levels) {
    json one = {{"im", l.im}, {"n", l.n}, {"n_overturned", l.n_overturned}};
    if (l.n_outside_model > 0) one["n_outside_model"] = l.n_outside_model;
    lv.push_back(one);
  }
  j["levels"] = lv;
  j["fit"] = fit_json(res.fit, res.band, int(o.bootstrap));
  if (suite.three_dimensional()) by_incidence(j, res.runs, suite, o);
  j["curve"] = curve_json(res.curve);
  j["runs"] = runs;
  std::string curve;
  for (const json& c : j["curve"])
    curve += format_double(c["im"].get<double>()) + ":" + format_double(c["p"].get<double>()) + ":" +
             (c.contains("p05") ? format_double(c["p05"].get<double>()) + ":" + format_double(c["p95"].get<double>())
                                : std::string("nan:nan")) +
             ",";
  rep.figure = FigureSpec{"fragility",
                          {"@csv:table", "@plot"},
                          {{"im", {im}},
                           {"curve", {curve.empty() ? "-" : curve}},
                           {"title",
                            {studied_object(definition.at("model")) + " under " + std::to_string(suite.names.size()) +
                             " records, each scaled to " + std::to_string(o.levels.size()) + " levels of " + im}}}};
  if (res.fit.ok)
    append_text(rep.text, "fragility: %zu runs, median %s = %.4g, beta = %.3g", res.runs.size(), im.c_str(),
                res.fit.median, res.fit.beta);
  else
    append_text(rep.text, "fragility: %zu runs, no fit (%s)", res.runs.size(), res.fit.why.c_str());
  return rep;
}

GridStudy fragility_grid(const Settings& given, const std::string& output) {
  const StudyOptions so(given, fragility_options());
  IntensityMeasure imm = parse_intensity_measure("im", so.text("im"), 0.05);
  const double damping = so.number("damping");
  require_in_range("damping", damping, 0, 1, true, false);
  imm.damping = damping;
  FragilityOptions fo;
  if (!so.given("levels")) throw std::invalid_argument("levels: give the intensity levels A:B:N or A,B,C");
  fo.levels = parse_axis("levels", so.text("levels"), AxisSpacing::Linear).values;
  for (double l : fo.levels) require_in_range("levels", l, 0, 1e6, false);
  if (so.given("records") == so.given("suite"))
    throw std::invalid_argument("records, suite: give one of them (a glob of record files, or a suite's directory)");
  fo.bootstrap = so.integer("bootstrap");
  const long seed = so.integer("seed");
  if (fo.bootstrap < 0 || fo.bootstrap > 100000) throw std::invalid_argument("bootstrap: must be in [0, 100000]");
  if (seed < 0) throw std::invalid_argument("seed: must be >= 0");
  fo.seed = std::uint64_t(seed);
  fo.threads = so.threads();  // the bootstrap's fits (the band does not depend on it)
  fo.t_after = so.number("t-after");
  require_in_range("t-after", fo.t_after, 0, 1e4);
  if (so.given("t-end")) fo.t_end = so.number("t-end");
  if (fo.t_end) require_in_range("t-end", *fo.t_end, 0, 1e5, false);
  const SuiteRecords in = so.given("suite") ? suite_records(so.text("suite"))
                                            : SuiteRecords{expand_glob("records", so.text("records"), 100000), {}, {}};
  const std::vector<double> incidences = incidences_of(given);
  const auto fm = std::make_shared<const ForcedModel>(model_at_incidence(given, incidences.front()));
  const double g = given.number("g", 9.81);
  auto load_all = [](const std::vector<std::string>& files) {
    std::vector<std::shared_ptr<const Accelerogram>> out;
    for (const std::string& f : files)
      out.push_back(std::make_shared<const Accelerogram>(load_accelerogram(f, "suite")));
    return out;
  };
  const auto h1 = load_all(in.h1), h2 = load_all(in.h2), vert = load_all(in.v);
  const bool three_d = !h2.empty() || !vert.empty() || incidences.size() > 1;
  std::shared_ptr<const FragilitySuite> suite;
  if (three_d) {
    if (!fm->run3)
      throw std::invalid_argument("suite: records in components or several incidences need --model rigid3d");
    std::vector<double> alphas;
    for (double inc : incidences) alphas.push_back(model_at_incidence(given, inc).alpha);
    suite = std::make_shared<const FragilitySuite>(fragility_suite_3d(in.h1, h1, h2, vert, incidences, alphas, imm, g));
  } else {
    suite = std::make_shared<const FragilitySuite>(fragility_suite(in.h1, h1, imm, g, fm->alpha));
  }
  json digests = json::array();
  for (const auto& r : h1) digests.push_back(r->digest());
  for (const auto& r : h2) digests.push_back(r->digest());
  for (const auto& r : vert) digests.push_back(r->digest());
  const std::string im = imm.text;
  json definition = {{"model", fm->description},
                     {"records", suite->names},

                     {"record_digests", digests},
                     {"im", im},
                     {"levels", fo.levels},
                     {"t_end", fo.t_end ? json(*fo.t_end) : json(nullptr)},
                     {"t_after", fo.t_after},
                     {"damping", damping},
                     {"index", "level fastest, then record"}};
  if (three_d) {
    // Each entry a record at an incidence (entry = record * incidences + incidence).
    definition["components"] = in.component_names();
    definition["incidences"] = incidences;
    definition["index"] = "level fastest, then incidence, then record";
  }
  GridStudy gs;
  gs.table = std::make_shared<const GridTable>(
      "fragility",
      std::vector<std::string>{"record", "level", "record_im", "scale", "overturned", "max_abs_rotation", "t_failure"},
      fo.levels.size() * suite->names.size(),
      [suite, fo, fm](std::size_t i, CellRow& row) {
        const FragilityRunOutcome r = fragility_run(*fm, *suite, fo, i);
        row.emplace_back(suite->names[r.record]);
        row.emplace_back(r.level);
        row.emplace_back(r.record_im);
        row.emplace_back(r.scale);
        if (r.invalid)
          row.emplace_back();  // outside the model
        else
          row.emplace_back(r.overturned ? 1 : 0);
        row.emplace_back(r.max_abs_rotation);
        if (r.t_failure)
          row.emplace_back(*r.t_failure);
        else
          row.emplace_back();
      },
      definition, fm->tolerances, output);
  gs.threads = so.threads();
  gs.finish = [suite, fo, definition, im](const Table& t) { return fragility_report(t, *suite, fo, definition, im); };
  return gs;
}

}  // namespace

GridStudyCommand fragility_command() {
  return {
      "fragility",
      "fragility curve: every record of a suite scaled to every intensity level, overturning (collapse) counted per "
      "level and the lognormal curve fitted by maximum likelihood with a bootstrap band (threads, MPI, resumable)",
      17,
      fragility_options(),
      fragility_grid,
      "out",
      "the runs as CSV (the runner's table: journal and sidecar .json beside it)",
      {{"plot", "plot the stripes' fractions and the fitted curve with its 90 % band (PNG + SVG)"}},
      "no summary line, no progress"};
}

}  // namespace blockdyn
