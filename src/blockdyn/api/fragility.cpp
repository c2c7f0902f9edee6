// SPDX-License-Identifier: Apache-2.0
#include "blockdyn/api/fragility.hpp"

#include <glob.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <stdexcept>

#include "blockdyn/analysis/forced/fragility_fit.hpp"
#include "blockdyn/analysis/sweep/grid_table.hpp"
#include "blockdyn/analysis/sweep/sweep_axis.hpp"
#include "blockdyn/api/harmonic_run.hpp"
#include "blockdyn/base/number_text.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/excitation/intensity_measures.hpp"
#include "blockdyn/excitation/response_spectrum.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

std::vector<StudyOption> fragility_options() {
  std::vector<StudyOption> o = forced_model_options();
  const std::vector<StudyOption> own = {
      {"records", "the suite: a glob of record files (PEER .AT2 or CSV), e.g. 'suite/*.AT2' (quoted)"},
      {"im",
       "intensity measure: pga (g), pgv (m/s), sa:T (Sa at period T s, g) or pga-over-uplift (PGA / (g tan alpha))",
       "pga"},
      {"levels", "the intensity levels A:B:N (N uniform from A to B) or a list A,B,C (> 0)"},
      {"damping", "damping ratio of sa:T", "0.05"},
      {"t-end", "duration of every run [s] (default: each record's end + --t-after)"},
      {"t-after", "simulated time after each record's end [s]", "5"},
      {"bootstrap", "bootstrap resamples of the records for the 90 % band (0: none)", "200"},
      {"seed", "seed of the bootstrap", "1"},
      {"threads", "worker threads (0: all cores)", "0"}};
  o.insert(o.end(), own.begin(), own.end());
  return o;
}

std::vector<std::string> expand_glob(const std::string& pattern) {
  glob_t g{};
  const int rc = ::glob(pattern.c_str(), 0, nullptr, &g);
  std::vector<std::string> files;
  if (rc == 0)
    for (std::size_t i = 0; i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i]);
  ::globfree(&g);
  if (files.empty()) throw std::invalid_argument("records = '" + pattern + "' matches no file");
  if (files.size() > 100000) throw std::invalid_argument("records: at most 100000 files");
  return files;
}

struct Suite {
  std::vector<std::string> files;
  std::vector<std::shared_ptr<const Accelerogram>> records;
  std::vector<double> im;  // of each record as recorded (scale 1)
};

// The record's IM at scale 1 (IMs scale linearly with the record).
double im_of(const Accelerogram& r, const std::string& im, double period, double damping, double g, double alpha) {
  if (im == "pga") return r.peak();
  if (im == "pga-over-uplift") return r.peak() / std::tan(alpha);
  if (im == "pgv") return intensity_measures(r, g).pgv;
  return spectral_ordinate(r, period, damping, g).sa;
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

// The fitted curve and the bootstrap's pointwise 90 % band on 80 levels across the stripes.
json curve_json(const FragilityFit& f, const FragilityBand& b, double lo, double hi) {
  json c = json::array();
  if (!f.ok) return c;
  for (int i = 0; i < 80; ++i) {
    const double x = lo * std::pow(hi / lo, double(i) / 79.0);
    std::vector<double> ps;
    for (const auto& [m, beta] : b.fits) ps.push_back(normal_cdf(std::log(x / m) / beta));
    std::sort(ps.begin(), ps.end());
    json row = {{"im", x}, {"p", normal_cdf(std::log(x / f.median) / f.beta)}};
    if (!ps.empty()) {
      row["p05"] = ps[std::size_t(0.05 * double(ps.size() - 1))];
      row["p95"] = ps[std::size_t(std::ceil(0.95 * double(ps.size() - 1)))];
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

// The report of the finished runs: the stripes, the fit and its band, the curve, the figure.
StudyReport fragility_report(const Table& t, const Suite& suite, const std::vector<double>& levels,
                             const json& definition, const std::string& im, long bootstrap, long seed) {
  StudyReport rep;
  json& j = rep.summary;
  j["run"] = run_info();
  j["definition"] = definition;
  const std::size_t cl = t.column("level"), cs = t.column("scale"), co = t.column("overturned"),
                    cm = t.column("max_abs_rotation");
  json runs = json::array();
  std::vector<FragilityRun> all;
  std::vector<std::vector<FragilityRun>> groups(suite.files.size());
  std::vector<std::size_t> n(levels.size()), n_over(levels.size());
  for (const TableRow& r : t.rows) {
    const double level = cell_double(r.cells[cl]);
    const bool over = r.cells[co] == "1";
    runs.push_back({{"record", suite.files[r.index / levels.size()]},
                    {"level", level},
                    {"im", im},
                    {"scale", cell_double(r.cells[cs])},
                    {"overturned", over},
                    {"max_abs_rotation", cell_double(r.cells[cm])}});
    all.push_back({level, over});
    groups[r.index / levels.size()].push_back({level, over});
    ++n[r.index % levels.size()];
    n_over[r.index % levels.size()] += over;
  }
  json lv = json::array();
  for (std::size_t i = 0; i < levels.size(); ++i)
    lv.push_back({{"im", levels[i]}, {"n", n[i]}, {"n_overturned", n_over[i]}});
  const FragilityFit fit = fit_fragility(all);
  const FragilityBand band =
      fit.ok && bootstrap > 0 ? bootstrap_fragility(groups, int(bootstrap), std::uint64_t(seed)) : FragilityBand{};
  j["levels"] = lv;
  j["fit"] = fit_json(fit, band, int(bootstrap));
  const double lo = *std::min_element(levels.begin(), levels.end()),
               hi = *std::max_element(levels.begin(), levels.end());
  j["curve"] = curve_json(fit, band, lo * 0.5, hi * 1.5);
  j["runs"] = runs;
  rep.plot_script = "plot_fragility.py";
  std::string curve;
  for (const json& c : j["curve"])
    curve += format_double(c["im"].get<double>()) + ":" + format_double(c["p"].get<double>()) + ":" +
             (c.contains("p05") ? format_double(c["p05"].get<double>()) + ":" + format_double(c["p95"].get<double>())
                                : std::string("nan:nan")) +
             ",";
  rep.plot_args = {"@csv:table",
                   "@plot",
                   "--im",
                   im,
                   "--curve",
                   curve.empty() ? "-" : curve,
                   "--title",
                   studied_object(definition.at("model")) + " under " + std::to_string(suite.files.size()) +
                       " records, each scaled to " + std::to_string(levels.size()) + " levels of " + im};
  if (fit.ok)
    append_text(rep.text, "fragility: %zu runs, median %s = %.4g, beta = %.3g", all.size(), im.c_str(), fit.median,
                fit.beta);
  else
    append_text(rep.text, "fragility: %zu runs, no fit (%s)", all.size(), fit.why.c_str());
  return rep;
}

GridStudy fragility_grid(const Settings& given, const std::string& output) {
  const StudyOptions so(given, fragility_options());
  const std::string im = so.text("im");
  double period = 0;
  if (im.rfind("sa:", 0) == 0) {
    period = parse_number_list("im", im.substr(3)).at(0);
    require_in_range("im (sa:T, T)", period, 0, 1e4, false);
  } else if (im != "pga" && im != "pgv" && im != "pga-over-uplift") {
    throw std::invalid_argument("im = '" + im + "' is not one of: pga, pgv, sa:T, pga-over-uplift");
  }
  const double damping = so.number("damping");
  require_in_range("damping", damping, 0, 1, true, false);
  if (!so.given("levels")) throw std::invalid_argument("levels: give the intensity levels A:B:N or A,B,C");
  const std::vector<double> levels = parse_axis("levels", so.text("levels"), AxisSpacing::Linear).values;
  for (double l : levels) require_in_range("levels", l, 0, 1e6, false);
  if (!so.given("records")) throw std::invalid_argument("records: give a glob of record files");
  const long bootstrap = so.integer("bootstrap"), seed = so.integer("seed");
  if (bootstrap < 0 || bootstrap > 100000) throw std::invalid_argument("bootstrap: must be in [0, 100000]");
  if (seed < 0) throw std::invalid_argument("seed: must be >= 0");
  const double t_after = so.number("t-after");
  require_in_range("t-after", t_after, 0, 1e4);
  const std::optional<double> t_fixed = so.given("t-end") ? std::optional<double>(so.number("t-end")) : std::nullopt;
  if (t_fixed) require_in_range("t-end", *t_fixed, 0, 1e5, false);
  const auto fm = std::make_shared<const ForcedModel>(forced_model_of(so));
  const double g = given.number("g", 9.81);
  auto suite = std::make_shared<Suite>();
  suite->files = expand_glob(so.text("records"));
  for (const std::string& f : suite->files) {
    suite->records.push_back(std::make_shared<const Accelerogram>(load_accelerogram(f, "records")));
    suite->im.push_back(im_of(*suite->records.back(), im, period, damping, g, fm->alpha));
    if (!(suite->im.back() > 0))
      throw std::invalid_argument("records: '" + f + "' has " + im + " = 0: it cannot be scaled to a level");
  }
  json digests = json::array();
  for (const auto& r : suite->records) digests.push_back(r->digest());
  const json definition = {{"model", fm->description},
                           {"records", suite->files},
                           {"record_digests", digests},
                           {"im", im},
                           {"levels", levels},
                           {"t_end", t_fixed ? json(*t_fixed) : json(nullptr)},
                           {"t_after", t_after},
                           {"damping", damping},
                           {"index", "level fastest, then record"}};
  GridStudy gs;
  gs.table = std::make_shared<const GridTable>(
      "fragility",
      std::vector<std::string>{"record", "level", "record_im", "scale", "overturned", "max_abs_rotation", "t_failure"},
      levels.size() * suite->files.size(),
      [suite, levels, fm, t_fixed, t_after](std::size_t i, RowBuilder& row) {
        const std::size_t k = i / levels.size();
        const double level = levels[i % levels.size()], scale = level / suite->im[k];
        GroundMotion gm;
        gm.horizontal.record = suite->records[k];
        gm.horizontal.scale = scale;
        const SurvivalOutcome out = fm->run(gm, t_fixed ? *t_fixed : suite->records[k]->t_last() + t_after);
        row.add(csv_escape(suite->files[k]));
        row.add(level);
        row.add(suite->im[k]);
        row.add(scale);
        row.add(std::string(out.collapse_mode ? "1" : "0"));
        row.add(out.max_abs_rotation);
        if (out.t_failure)
          row.add(*out.t_failure);
        else
          row.empty();
      },
      definition, fm->tolerances, output);
  gs.threads = so.threads();
  gs.finish = [suite, levels, definition, im, bootstrap, seed](const Table& t) {
    return fragility_report(t, *suite, levels, definition, im, bootstrap, seed);
  };
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
