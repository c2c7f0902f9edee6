// SPDX-License-Identifier: Apache-2.0
// Stability studies of the block on the Winkler foundation (thesis 4.3.1-4.3.2): `overturn` (time
// and ihor at overturning versus k), `stability-curve` (k2/k3_stability(r) for ic2, k1_stability(r)
// for ic1), `blowup` (r2_s(mu), r3_s(mu): below them ic2 overturns whatever k is, up to a k cap).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/winkler/equilibrium_bifurcation.hpp"
#include "blockdyn/analysis/winkler/stability.hpp"
#include "blockdyn/base/range_check.hpp"
#include "blockdyn/commands/study_command.hpp"
#include "blockdyn/io/json_io.hpp"

namespace blockdyn {

using json = nlohmann::ordered_json;
namespace {

constexpr double kRMax = 100, kMuMax = 10, kKMaxAllowed = kWinklerKMax;

json header(const std::string& command, const std::string& ic, const StudyRunOptions& run) {
  return {{"run_info", run_info()}, {"command", command}, {"ic", ic}, {"run_options", run_options_json(run)}};
}

void add_common_options(std::vector<StudyOption>& o, bool with_search) {
  if (with_search) {
    const StabilitySearchOptions d;
    for (StudyOption x : std::vector<StudyOption>{
             {"k-lo", "lowest k searched", Settings::exact(d.k_lo)},
             {"k-hi", "highest k searched (the cap of 'regardless of k')", Settings::exact(d.k_hi)},
             {"per-decade", "coarse grid points per decade of k", Settings::exact(d.per_decade)},
             {"rel-tol", "relative tolerance of the bisection in k", Settings::exact(d.bisect.rel_tol)},
             {"eps", "relative width of the neighbourhood above k2 excluded from k3", Settings::exact(d.eps)}})
      o.push_back(x);
  }
  o = with_run_options(std::move(o), "30");
}

StabilitySearchOptions search_of(const StudyOptions& o) {
  StabilitySearchOptions s;
  s.k_lo = o.number("k-lo");
  s.k_hi = o.number("k-hi");
  s.per_decade = o.number("per-decade");
  s.bisect.rel_tol = o.number("rel-tol");
  s.eps = o.number("eps");
  require_in_range("k-lo", s.k_lo, kWinklerKMin, kKMaxAllowed);
  require_in_range("k-hi", s.k_hi, s.k_lo, kKMaxAllowed, false, true);
  require_in_range("per-decade", s.per_decade, 0.5, 1000);
  require_in_range("rel-tol", s.bisect.rel_tol, 1e-12, 1, false, false);
  require_in_range("eps", s.eps, 0.0, 1.0, false, false);
  return s;
}

json search_json(const StabilitySearchOptions& o) {
  return {{"k_range", {o.k_lo, o.k_hi}},
          {"points_per_decade", o.per_decade},
          {"bisection_rel_tol", o.bisect.rel_tol},
          {"k3_excluded_neighbourhood", "(k2, k2 (1 + eps)]"},
          {"eps", o.eps}};
}

// A search study's report: its table, meta as sidecar, meta plus the per-point results as summary.
StudyReport search_report(StudyTable t, const json& meta, const json& points, const std::string& panel) {
  StudyReport r;
  r.table = std::move(t);
  r.sidecar = meta;
  r.summary = meta;
  r.summary["points"] = points;
  r.figure = FigureSpec{"stability", {panel}, {}};
  return r;
}

// k_uns(r): below it no stable equilibrium exists, so the block falls over from any start
// (docs/equilibria.md). Defined for r <= 1; NaN beyond.
double k_uns_or_nan(double r) { return r <= 1.0 ? find_k_uns(r) : NAN; }

// ------------------------------------------------------------------ overturn

std::vector<StudyOption> overturn_options() {
  std::vector<StudyOption> o = {
      {"r", "aspect ratio (> 0)", "0.2"},
      {"mu", "friction coefficient (>= 0)", "0.2"},
      {"ic", "initial conditions: ic1, ic2, ic1:F", "ic2"},
      {"k-min", "lowest k (log grid)", "10"},
      {"k-max", "highest k", "1e5"},
      {"points", "number of k values", "120"},
      {"window-points", "ic2: add this many points over the second-swing window (k2_stability, k3_stability)", "0"}};
  add_common_options(o, false);
  return o;
}

// ic2: the k window where the block overturns on its second swing, (k2, k3), is a few per cent
// wide (r = 0.1: 730-794) and gets 2-3 points of the log grid; --window-points adds a fine grid
// over it, located first with the stability searches.
json add_window(std::vector<double>& ks, const WinklerParams& p, double k_min, double k_max, int window_points,
                const StudyRunOptions& run) {
  StabilitySearchOptions ss;
  ss.k_lo = k_min;
  ss.k_hi = k_max;
  ss.bisect.rel_tol = 1e-3;
  const CurvePoint k2 = k2_stability(p.r, p.mu, run, ss);
  const K3Point k3 = k3_stability(p.r, p.mu, k2.result, run, ss);
  if (!(k2.result.found() && k3.point.result.found() && k3.point.result.value > k2.result.value))
    return {{"k2_stability", boundary_cell(k2.result)},
            {"k3_stability", boundary_cell(k3.point.result)},
            {"k_range", nullptr}};
  const double lo = std::max(k_min, k2.result.value / 1.02), hi = std::min(k_max, k3.point.result.value * 1.02);
  if (hi > lo) {
    for (double k : log_grid(lo, hi, std::max(2, window_points))) ks.push_back(k);
    std::sort(ks.begin(), ks.end());
    ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
  }
  return {{"k2_stability", k2.result.value}, {"k3_stability", k3.point.result.value}, {"k_range", {lo, hi}}};
}

StudyReport overturn_study(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, overturn_options());
  const WinklerParams p{o.number("r"), o.number("mu"), 1e3};
  const double k_min = o.number("k-min"), k_max = o.number("k-max");
  require_in_range("r", p.r, kWinklerRMin, kRMax);
  require_in_range("mu", p.mu, 0.0, kMuMax);
  require_in_range("k-min", k_min, kWinklerKMin, kKMaxAllowed);
  require_in_range("k-max", k_max, k_min, kKMaxAllowed, false, true);
  const long points = o.integer("points"), window_points = o.integer("window-points");
  require_in_range("points", double(points), 2, 100000);
  const StudyRunOptions run = o.run_options();
  const int threads = o.threads();
  require_in_range("window-points", double(window_points), 0, 100000);
  const IcChoice ic = parse_ic_choice(o.text("ic"));
  auto ks = log_grid(k_min, k_max, int(points));
  json window = nullptr;
  if (window_points > 0 && !ic.is_ic1()) window = add_window(ks, p, k_min, k_max, int(window_points), run);
  const auto runs = overturn_scan(p, ic, ks, run, threads);
  StudyReport r;
  r.table.columns = {"k", "overturned", "time", "ihor", "status"};
  int over = 0, failed = 0;
  double k_first_stable = NAN;
  for (const auto& x : runs) {
    r.table.rows.push_back({Cell::shortest(x.k), Cell(x.overturned ? 1 : 0), Cell::shortest(x.time),
                            Cell(x.upright_passages), to_string(x.status)});
    over += x.overturned;
    failed += x.status == SimStatus::NumericalFailure;
    if (!x.overturned && std::isnan(k_first_stable)) k_first_stable = x.k;
  }
  json meta = header("overturn", ic.name(), run);
  meta["r"] = p.r;
  meta["mu"] = p.mu;
  meta["k_range"] = {k_min, k_max};
  meta["points"] = points;
  meta["window_points"] = window_points;
  meta["second_swing_window"] = window;
  meta["k_uns"] = finite_or_null(k_uns_or_nan(p.r));
  r.sidecar = meta;
  r.summary = meta;
  r.summary["runs"] = runs.size();
  r.summary["overturned"] = over;
  r.summary["numerical_failures"] = failed;
  r.summary["lowest_grid_k_without_overturning"] = finite_or_null(k_first_stable);
  append_text(r.text, "%zu runs (%s, r = %g, mu = %g, t_end = %g): %d overturned, %d failed; lowest k without: %s\n",
              runs.size(), ic.name().c_str(), p.r, p.mu, run.t_end, over, failed,
              std::isnan(k_first_stable) ? "none" : cell_text(k_first_stable).c_str());
  r.figure = FigureSpec{"stability", {"overturn"}, {}};
  return r;
}

// ------------------------------------------------------------------ stability-curve

std::vector<StudyOption> curve_options() {
  std::vector<StudyOption> o = {{"ic", "ic2 (k2, k3) or ic1 / ic1:F (k1)", "ic2"},
                                {"which", "k2, k3 or both for ic2 (default both); k1 for ic1", ""},
                                {"mu", "friction coefficient (>= 0)", "0.2"},
                                {"r-min", "lowest aspect ratio (log grid)", "0.05"},
                                {"r-max", "highest aspect ratio", "1"},
                                {"points", "number of r values", "16"}};
  add_common_options(o, true);
  return o;
}

struct CurveRow {
  CurvePoint k1, k2;
  K3Point k3;
  const BoundaryResult& result(const std::string& n) const {
    return n == "k1" ? k1.result : n == "k2" ? k2.result : k3.point.result;
  }
};

std::string curve_text(const std::vector<double>& rs, const std::vector<std::string>& names, const StudyTable& t) {
  std::string s;
  append_text(s, "%-10s", "r");
  for (const auto& n : names) append_text(s, " %-16s", (n + "_stability").c_str());
  s += "\n";
  for (std::size_t i = 0; i < rs.size(); ++i) {
    append_text(s, "%-10.4g", rs[i]);
    for (std::size_t j = 0; j < names.size(); ++j) {
      const std::string v = t.rows[i][1 + j].text();
      const std::string st = t.rows[i][1 + names.size() + j].text();
      append_text(s, " %-16s", st == "found" ? v.substr(0, 12).c_str() : st.c_str());
    }
    s += "\n";
  }
  return s;
}

StudyReport curve_study(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, curve_options());
  const double mu = o.number("mu"), r_min = o.number("r-min"), r_max = o.number("r-max");
  require_in_range("mu", mu, 0.0, kMuMax);
  require_in_range("r-min", r_min, kWinklerRMin, kRMax);
  require_in_range("r-max", r_max, r_min, kRMax, false, true);
  const long points = o.integer("points");
  require_in_range("points", double(points), 1, 100000);
  const StabilitySearchOptions search = search_of(o);
  const StudyRunOptions run = o.run_options();
  const int threads = o.threads();
  const IcChoice ic = parse_ic_choice(o.text("ic"));
  const std::string which = o.text("which").empty() ? (ic.is_ic1() ? "k1" : "both") : o.text("which");
  if (ic.is_ic1() && which != "k1")
    throw std::invalid_argument("which = '" + which + "' is not available for " + ic.name() +
                                ": use k1 (k2/k3 need ic2)");
  if (!ic.is_ic1() && which != "k2" && which != "k3" && which != "both")
    throw std::invalid_argument("which = '" + which + "' is not one of: k2, k3, both (ic2); k1 needs ic1");
  const bool want_k3 = which == "k3" || which == "both", want_k2 = which == "k2" || which == "both";
  const auto rs = points == 1 ? std::vector<double>{r_min} : log_grid(r_min, r_max, int(points));
  const auto rows = parallel_map<CurveRow>(rs.size(), threads, [&](std::size_t i) {
    CurveRow row;
    if (ic.is_ic1()) {
      row.k1 = k1_stability(rs[i], mu, ic, run, search);
    } else {
      row.k2 = k2_stability(rs[i], mu, run, search);  // k3 needs k2 in any case
      if (want_k3) row.k3 = k3_stability(rs[i], mu, row.k2.result, run, search);
    }
    return row;
  });
  StudyTable t;
  t.columns = {"r"};
  std::vector<std::string> names;
  if (ic.is_ic1()) names = {"k1"};
  if (want_k2) names.push_back("k2");
  if (want_k3) names.push_back("k3");
  for (const auto& n : names) t.columns.push_back(n + "_stability");
  for (const auto& n : names) t.columns.push_back(n + "_status");
  if (want_k3) t.columns.push_back("k3_equals_k2");
  t.columns.push_back("k_uns");  // below it no stable equilibrium: overturning from any start
  json points_json = json::array();
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const CurveRow& row = rows[i];
    CellRow cells{Cell::shortest(rs[i])};
    for (const auto& n : names) cells.push_back(Cell::shortest(boundary_cell(row.result(n))));
    for (const auto& n : names) cells.push_back(to_string(row.result(n).status));
    if (want_k3) cells.push_back(Cell(row.k3.coincides_with_k2 ? 1 : 0));
    const double k_uns = k_uns_or_nan(rs[i]);
    cells.push_back(Cell::shortest(k_uns));
    t.rows.push_back(cells);
    json p = {{"r", rs[i]}};
    p["k_uns"] = finite_or_null(k_uns);
    for (const auto& n : names) p[n + "_stability"] = boundary_json(row.result(n), true);
    if (want_k3) p["k3_equals_k2"] = row.k3.coincides_with_k2;
    points_json.push_back(p);
  }
  json meta = header("stability-curve", ic.name(), run);
  meta["mu"] = mu;
  meta["which"] = which;
  meta["r_range"] = {r_min, r_max};
  meta["search"] = search_json(search);
  meta["definitions"] =
      "kn_stability = sup K: the block overturns while ihor < n (within t_end) for all k < K "
      "(k1: ic1, n = 1; k2: ic2, n = 2; k3: ic2, n = 3, outside (k2, k2(1+eps)])";
  StudyReport r = search_report(std::move(t), meta, points_json, "curve");
  r.text = curve_text(rs, names, r.table);
  return r;
}

// ------------------------------------------------------------------ blowup

std::vector<StudyOption> blowup_options() {
  std::vector<StudyOption> o = {{"mu-list", "friction coefficients (comma-separated)", "0,0.1,0.2,0.3"},
                                {"which", "r2, r3 or both", "both"},
                                {"r-min", "lowest aspect ratio searched", "0.01"},
                                {"r-max", "highest aspect ratio searched", "0.5"},
                                {"r-per-decade", "coarse grid points per decade of r", "10"},
                                {"r-rel-tol", "relative tolerance of the bisection in r", "0.001"}};
  add_common_options(o, true);
  return o;
}

std::string blowup_text(const StudyTable& t, std::size_t nw) {
  std::string s;
  for (const auto& c : t.columns)
    if (c.find("_status") == std::string::npos) append_text(s, "%-16s", c.c_str());
  s += "\n";
  for (const auto& row : t.rows) {
    append_text(s, "%-16s", row[0].text().c_str());
    for (std::size_t j = 0; j < nw; ++j) {
      const std::string status = row[1 + nw + j].text();
      append_text(s, "%-16s", status == "found" ? row[1 + j].text().substr(0, 10).c_str() : status.c_str());
    }
    s += "\n";
  }
  return s;
}

StudyReport blowup_study(const Settings& given, const StudyRequest&) {
  const StudyOptions o(given, blowup_options());
  const auto mus = parse_number_list("mu-list", o.text("mu-list"));
  for (double mu : mus) require_in_range("mu-list entry", mu, 0.0, kMuMax);
  const double r_min = o.number("r-min"), r_max = o.number("r-max"), r_per_decade = o.number("r-per-decade");
  BisectionOptions r_bisect;
  r_bisect.rel_tol = o.number("r-rel-tol");
  require_in_range("r-min", r_min, kWinklerRMin, kRMax);
  require_in_range("r-max", r_max, r_min, kRMax, false, true);
  require_in_range("r-per-decade", r_per_decade, 0.5, 1000);
  require_in_range("r-rel-tol", r_bisect.rel_tol, 1e-12, 1, false, false);
  const StabilitySearchOptions search = search_of(o);
  const StudyRunOptions run = o.run_options();
  const int threads = o.threads();
  const std::string which = o.text("which");
  std::vector<BlowupWhich> whichs;
  if (which == "r2" || which == "both") whichs.push_back(BlowupWhich::R2);
  if (which == "r3" || which == "both") whichs.push_back(BlowupWhich::R3);
  if (whichs.empty()) throw std::invalid_argument("which = '" + which + "' is not one of: r2, r3, both");
  const std::size_t nw = whichs.size();
  const auto res = parallel_map<BlowupPoint>(mus.size() * nw, threads, [&](std::size_t i) {
    return blowup_ratio(mus[i / nw], whichs[i % nw], r_min, r_max, r_per_decade, r_bisect, run, search);
  });
  auto name = [](BlowupWhich w) { return std::string(w == BlowupWhich::R2 ? "r2_s" : "r3_s"); };
  StudyTable t;
  t.columns = {"mu"};
  for (auto w : whichs) t.columns.push_back(name(w));
  for (auto w : whichs) t.columns.push_back(name(w) + "_status");
  json points = json::array();
  for (std::size_t m = 0; m < mus.size(); ++m) {
    CellRow cells{Cell::shortest(mus[m])};
    for (std::size_t j = 0; j < nw; ++j) cells.push_back(Cell::shortest(boundary_cell(res[m * nw + j].result)));
    for (std::size_t j = 0; j < nw; ++j) cells.push_back(to_string(res[m * nw + j].result.status));
    t.rows.push_back(cells);
    json p = {{"mu", mus[m]}};
    for (std::size_t j = 0; j < nw; ++j) p[name(whichs[j])] = boundary_json(res[m * nw + j].result, true);
    points.push_back(p);
  }
  json meta = header("blowup", "ic2", run);
  meta["r_search"] = {
      {"r_range", {r_min, r_max}}, {"points_per_decade", r_per_decade}, {"bisection_rel_tol", r_bisect.rel_tol}};
  meta["k_search"] = search_json(search);
  meta["definition"] =
      "r2_s (r3_s) = sup R: for all r < R the block (ic2) overturns while ihor < 2 (< 3) for every k in "
      "the k range, i.e. k2_stability (k3_stability) is above the k cap";
  StudyReport r = search_report(std::move(t), meta, points, "blowup");
  r.text = blowup_text(r.table, nw);
  return r;
}

}  // namespace

void add_stability_studies(std::vector<StudyCommand>& to) {
  to.push_back({"overturn", "time and ihor at overturning versus k (Figs 4.21-4.28, 4.32)", 34, StudyOutputs::Table,
                overturn_options(), overturn_study});
  to.push_back({"stability-curve",
                "critical stability curves k2/k3_stability(r) (ic2), k1_stability(r) (ic1) (Figs 4.29-4.30, 4.33)", 35,
                StudyOutputs::Table, curve_options(), curve_study});
  to.push_back({"blowup", "aspect ratios r2_s(mu), r3_s(mu) where k2/k3_stability blow up (Fig 4.31)", 36,
                StudyOutputs::Table, blowup_options(), blowup_study});
}

}  // namespace blockdyn
