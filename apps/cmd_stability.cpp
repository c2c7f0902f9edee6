// SPDX-License-Identifier: Apache-2.0
// Stability studies (thesis 4.3.1-4.3.2): `overturn` (time and ihor at overturning vs k),
// `stability-curve` (k2/k3_stability(r) for ic2, k1_stability(r) for ic1), `blowup` (r2_s(mu),
// r3_s(mu): below them ic2 overturns whatever k is, up to a k cap).
#include <cmath>
#include <cstdio>
#include <memory>

#include <algorithm>

#include "blockdyn/analysis/sweep/parallel_map.hpp"
#include "blockdyn/analysis/winkler/equilibrium_bifurcation.hpp"
#include "blockdyn/analysis/winkler/stability.hpp"
#include "blockdyn/io/json_io.hpp"
#include "bounds_common.hpp"
#include "cli_registry.hpp"

namespace blockdyn::cli {
namespace {

using namespace bounds;

constexpr double kRMax = 100, kMuMax = 10, kKMaxAllowed = kWinklerKMax;

json header(const std::string& command, const std::string& ic, const StudyRunOptions& run) {
  return {{"run_info", run_info()}, {"command", command}, {"ic", ic}, {"run_options", run_options_json(run)}};
}

void add_search_options(CLI::App& s, StabilitySearchOptions& o) {
  s.add_option("--k-lo", o.k_lo, "lowest k searched")->capture_default_str();
  s.add_option("--k-hi", o.k_hi, "highest k searched (the cap of 'regardless of k')")->capture_default_str();
  s.add_option("--per-decade", o.per_decade, "coarse grid points per decade of k")->capture_default_str();
  s.add_option("--rel-tol", o.bisect.rel_tol, "relative tolerance of the bisection in k")->capture_default_str();
  s.add_option("--eps", o.eps, "relative width of the neighbourhood above k2 excluded from k3")->capture_default_str();
}

void check_search(const StabilitySearchOptions& o) {
  require_range("k-lo", o.k_lo, kWinklerKMin, kKMaxAllowed);
  require_range("k-hi", o.k_hi, o.k_lo, kKMaxAllowed, false, true);
  require_range("per-decade", o.per_decade, 0.5, 1000);
  require_range("rel-tol", o.bisect.rel_tol, 1e-12, 1, false, false);
  require_range("eps", o.eps, 0.0, 1.0, false, false);
}

json search_json(const StabilitySearchOptions& o) {
  return {{"k_range", {o.k_lo, o.k_hi}},
          {"points_per_decade", o.per_decade},
          {"bisection_rel_tol", o.bisect.rel_tol},
          {"k3_excluded_neighbourhood", "(k2, k2 (1 + eps)]"},
          {"eps", o.eps}};
}

// Writes a search study's table and plot panel, and its summary: meta plus the per-point results.
void finish_search(const OutputFlags& out, const std::string& command, const std::string& panel, const Table& t,
                   const json& meta, const json& points) {
  json summary = meta;
  summary["points"] = points;
  finish(out, csv_target(out, command), t, meta, "plot_stability.py", {panel}, summary);
}

// ------------------------------------------------------------------ overturn

struct OverturnFlags {
  BlockParams p{0.2, 0.2, 1e3};
  std::string ic = "ic2";
  double k_min = 10, k_max = 1e5;
  int points = 120;
  int window_points = 0;
  StudyRunOptions run;
  OutputFlags out;
};

// k_uns(r): below it no stable equilibrium exists, so the block falls over from any start
// (docs/equilibria.md). Defined for r <= 1; NaN beyond.
double k_uns_or_nan(double r) { return r <= 1.0 ? find_k_uns(r) : NAN; }

void run_overturn(const OverturnFlags& f) {
  require_range("r", f.p.r, kWinklerRMin, kRMax);
  require_range("mu", f.p.mu, 0.0, kMuMax);
  require_range("k-min", f.k_min, kWinklerKMin, kKMaxAllowed);
  require_range("k-max", f.k_max, f.k_min, kKMaxAllowed, false, true);
  require_range("points", f.points, 2, 100000);
  check_run_options(f.run, f.out);
  require_range("window-points", f.window_points, 0, 100000);
  const IcChoice ic = parse_ic(f.ic);
  auto ks = log_grid(f.k_min, f.k_max, f.points);
  // ic2: the k window where the block overturns on its second swing, (k2, k3), is a few per cent
  // wide (r = 0.1: 730-794) and gets 2-3 points of the log grid; --window-points adds a fine grid
  // over it, located first with the stability searches.
  json window = nullptr;
  if (f.window_points > 0 && !ic.is_ic1()) {
    StabilitySearchOptions ss;
    ss.k_lo = f.k_min;
    ss.k_hi = f.k_max;
    ss.bisect.rel_tol = 1e-3;
    const CurvePoint k2 = k2_stability(f.p.r, f.p.mu, f.run, ss);
    const K3Point k3 = k3_stability(f.p.r, f.p.mu, k2.result, f.run, ss);
    if (k2.result.found() && k3.point.result.found() && k3.point.result.value > k2.result.value) {
      const double lo = std::max(f.k_min, k2.result.value / 1.02), hi = std::min(f.k_max, k3.point.result.value * 1.02);
      if (hi > lo) {
        for (double k : log_grid(lo, hi, std::max(2, f.window_points))) ks.push_back(k);
        std::sort(ks.begin(), ks.end());
        ks.erase(std::unique(ks.begin(), ks.end()), ks.end());
      }
      window = {{"k2_stability", k2.result.value}, {"k3_stability", k3.point.result.value}, {"k_range", {lo, hi}}};
    } else {
      window = {{"k2_stability", cell(k2.result)}, {"k3_stability", cell(k3.point.result)}, {"k_range", nullptr}};
    }
  }
  const auto runs = overturn_scan(f.p, ic, ks, f.run, f.out.threads);
  Table t{{"k", "overturned", "time", "ihor", "status"}, {}};
  int over = 0, failed = 0;
  double k_first_stable = NAN;
  for (const auto& x : runs) {
    t.rows.push_back({num(x.k), x.overturned ? "1" : "0", num(x.time), std::to_string(x.ihor), to_string(x.status)});
    over += x.overturned;
    failed += x.status == SimStatus::NumericalFailure;
    if (!x.overturned && std::isnan(k_first_stable)) k_first_stable = x.k;
  }
  json meta = header("overturn", ic.name(), f.run);
  meta["r"] = f.p.r;
  meta["mu"] = f.p.mu;
  meta["k_range"] = {f.k_min, f.k_max};
  meta["points"] = f.points;
  meta["window_points"] = f.window_points;
  meta["second_swing_window"] = window;
  meta["k_uns"] = std::isfinite(k_uns_or_nan(f.p.r)) ? json(k_uns_or_nan(f.p.r)) : json(nullptr);
  json summary = meta;
  summary["runs"] = runs.size();
  summary["overturned"] = over;
  summary["numerical_failures"] = failed;
  summary["lowest_grid_k_without_overturning"] = std::isnan(k_first_stable) ? json(nullptr) : json(k_first_stable);
  finish(f.out, csv_target(f.out, "overturn"), t, meta, "plot_stability.py", {"overturn"}, summary);
  if (f.out.json_out != "-")
    std::printf("%zu runs (%s, r = %g, mu = %g, t_end = %g): %d overturned, %d failed; lowest k without: %s\n",
                runs.size(), ic.name().c_str(), f.p.r, f.p.mu, f.run.t_end, over, failed,
                std::isnan(k_first_stable) ? "none" : num(k_first_stable).c_str());
}

void add_overturn(CLI::App& app) {
  auto f = std::make_shared<OverturnFlags>();
  CLI::App* s = app.add_subcommand("overturn", "time and ihor at overturning versus k (Figs 4.21-4.28, 4.32)");
  s->add_option("--r", f->p.r, "aspect ratio (> 0)")->capture_default_str();
  s->add_option("--mu", f->p.mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--ic", f->ic, "initial conditions: ic1, ic2, ic1:F")->capture_default_str();
  s->add_option("--k-min", f->k_min, "lowest k (log grid)")->capture_default_str();
  s->add_option("--k-max", f->k_max, "highest k")->capture_default_str();
  s->add_option("--points", f->points, "number of k values")->capture_default_str();
  s->add_option("--window-points", f->window_points,
                "ic2: add this many points over the second-swing window (k2_stability, k3_stability)")
      ->capture_default_str();
  add_run_options(*s, f->run, 30);
  add_output_options(*s, f->out);
  s->callback([f] { run_overturn(*f); });
}

// ------------------------------------------------------------------ stability-curve

struct CurveFlags {
  std::string ic = "ic2", which;
  double mu = 0.2, r_min = 0.05, r_max = 1;
  int points = 16;
  StabilitySearchOptions search;
  StudyRunOptions run;
  OutputFlags out;
};

void run_curve(const CurveFlags& f) {
  require_range("mu", f.mu, 0.0, kMuMax);
  require_range("r-min", f.r_min, kWinklerRMin, kRMax);
  require_range("r-max", f.r_max, f.r_min, kRMax, false, true);
  require_range("points", f.points, 1, 100000);
  check_search(f.search);
  check_run_options(f.run, f.out);
  const IcChoice ic = parse_ic(f.ic);
  const std::string which = f.which.empty() ? (ic.is_ic1() ? "k1" : "both") : f.which;
  if (ic.is_ic1() && which != "k1")
    throw UsageError("which = '" + which + "' is not available for " + ic.name() + ": use k1 (k2/k3 need ic2)");
  if (!ic.is_ic1() && which != "k2" && which != "k3" && which != "both")
    throw UsageError("which = '" + which + "' is not one of: k2, k3, both (ic2); k1 needs ic1");
  const bool want_k3 = which == "k3" || which == "both", want_k2 = which == "k2" || which == "both";
  const auto rs = f.points == 1 ? std::vector<double>{f.r_min} : log_grid(f.r_min, f.r_max, f.points);

  struct Row {
    CurvePoint k1, k2;
    K3Point k3;
  };
  const auto rows = parallel_map<Row>(rs.size(), f.out.threads, [&](std::size_t i) {
    Row row;
    if (ic.is_ic1()) {
      row.k1 = k1_stability(rs[i], f.mu, ic, f.run, f.search);
    } else {
      row.k2 = k2_stability(rs[i], f.mu, f.run, f.search);  // k3 needs k2 in any case
      if (want_k3) row.k3 = k3_stability(rs[i], f.mu, row.k2.result, f.run, f.search);
    }
    return row;
  });

  Table t;
  t.columns = {"r"};
  std::vector<std::string> names;
  if (ic.is_ic1()) names = {"k1"};
  if (want_k2) names.push_back("k2");
  if (want_k3) names.push_back("k3");
  for (const auto& n : names) t.columns.push_back(n + "_stability");
  for (const auto& n : names) t.columns.push_back(n + "_status");
  if (want_k3) t.columns.push_back("k3_equals_k2");
  t.columns.push_back("k_uns");  // below it no stable equilibrium: overturning from any start
  json points = json::array();
  for (std::size_t i = 0; i < rs.size(); ++i) {
    const Row& row = rows[i];
    auto result_of = [&](const std::string& n) -> const BoundaryResult& {
      return n == "k1" ? row.k1.result : n == "k2" ? row.k2.result : row.k3.point.result;
    };
    std::vector<std::string> cells{num(rs[i])};
    for (const auto& n : names) cells.push_back(num(cell(result_of(n))));
    for (const auto& n : names) cells.push_back(to_string(result_of(n).status));
    if (want_k3) cells.push_back(row.k3.coincides_with_k2 ? "1" : "0");
    const double k_uns = k_uns_or_nan(rs[i]);
    cells.push_back(num(k_uns));
    t.rows.push_back(cells);
    json p = {{"r", rs[i]}};
    p["k_uns"] = std::isfinite(k_uns) ? json(k_uns) : json(nullptr);
    for (const auto& n : names) p[n + "_stability"] = boundary_json(result_of(n), true);
    if (want_k3) p["k3_equals_k2"] = row.k3.coincides_with_k2;
    points.push_back(p);
  }
  json meta = header("stability-curve", ic.name(), f.run);
  meta["mu"] = f.mu;
  meta["which"] = which;
  meta["r_range"] = {f.r_min, f.r_max};
  meta["search"] = search_json(f.search);
  meta["definitions"] =
      "kn_stability = sup K: the block overturns while ihor < n (within t_end) for all k < K "
      "(k1: ic1, n = 1; k2: ic2, n = 2; k3: ic2, n = 3, outside (k2, k2(1+eps)])";
  finish_search(f.out, "stability-curve", "curve", t, meta, points);
  if (f.out.json_out != "-") {
    std::printf("%-10s", "r");
    for (const auto& n : names) std::printf(" %-16s", (n + "_stability").c_str());
    std::printf("\n");
    for (std::size_t i = 0; i < rs.size(); ++i) {
      std::printf("%-10.4g", rs[i]);
      for (std::size_t j = 0; j < names.size(); ++j) {
        const std::string& v = t.rows[i][1 + j];
        const std::string& st = t.rows[i][1 + names.size() + j];
        std::printf(" %-16s", st == "found" ? v.substr(0, 12).c_str() : st.c_str());
      }
      std::printf("\n");
    }
  }
}

void add_curve(CLI::App& app) {
  auto f = std::make_shared<CurveFlags>();
  CLI::App* s = app.add_subcommand("stability-curve",
                                   "critical stability curves k2/k3_stability(r) (ic2), k1_stability(r) (ic1) (Figs 4.29-4.30, 4.33)");
  s->add_option("--ic", f->ic, "ic2 (k2, k3) or ic1 / ic1:F (k1)")->capture_default_str();
  s->add_option("--which", f->which, "k2, k3 or both for ic2 (default both); k1 for ic1");
  s->add_option("--mu", f->mu, "friction coefficient (>= 0)")->capture_default_str();
  s->add_option("--r-min", f->r_min, "lowest aspect ratio (log grid)")->capture_default_str();
  s->add_option("--r-max", f->r_max, "highest aspect ratio")->capture_default_str();
  s->add_option("--points", f->points, "number of r values")->capture_default_str();
  add_search_options(*s, f->search);
  add_run_options(*s, f->run, 30);
  add_output_options(*s, f->out);
  s->callback([f] { run_curve(*f); });
}

// ------------------------------------------------------------------ blowup

struct BlowupFlags {
  std::string mu_list = "0,0.1,0.2,0.3", which = "both";
  double r_min = 0.01, r_max = 0.5, r_per_decade = 10;
  BisectionOptions r_bisect;
  StabilitySearchOptions search;
  StudyRunOptions run;
  OutputFlags out;
};

void run_blowup(const BlowupFlags& f) {
  const auto mus = parse_list("mu-list", f.mu_list);
  for (double mu : mus) require_range("mu-list entry", mu, 0.0, kMuMax);
  require_range("r-min", f.r_min, kWinklerRMin, kRMax);
  require_range("r-max", f.r_max, f.r_min, kRMax, false, true);
  require_range("r-per-decade", f.r_per_decade, 0.5, 1000);
  require_range("r-rel-tol", f.r_bisect.rel_tol, 1e-12, 1, false, false);
  check_search(f.search);
  check_run_options(f.run, f.out);
  std::vector<BlowupWhich> whichs;
  if (f.which == "r2" || f.which == "both") whichs.push_back(BlowupWhich::R2);
  if (f.which == "r3" || f.which == "both") whichs.push_back(BlowupWhich::R3);
  if (whichs.empty()) throw UsageError("which = '" + f.which + "' is not one of: r2, r3, both");
  const std::size_t nw = whichs.size();
  const auto res = parallel_map<BlowupPoint>(mus.size() * nw, f.out.threads, [&](std::size_t i) {
    return blowup_ratio(mus[i / nw], whichs[i % nw], f.r_min, f.r_max, f.r_per_decade, f.r_bisect, f.run, f.search);
  });
  Table t;
  t.columns = {"mu"};
  for (auto w : whichs) t.columns.push_back(w == BlowupWhich::R2 ? "r2_s" : "r3_s");
  for (auto w : whichs) t.columns.push_back(w == BlowupWhich::R2 ? "r2_s_status" : "r3_s_status");
  json points = json::array();
  for (std::size_t m = 0; m < mus.size(); ++m) {
    std::vector<std::string> cells{num(mus[m])};
    for (std::size_t j = 0; j < nw; ++j) cells.push_back(num(cell(res[m * nw + j].result)));
    for (std::size_t j = 0; j < nw; ++j) cells.push_back(to_string(res[m * nw + j].result.status));
    t.rows.push_back(cells);
    json p = {{"mu", mus[m]}};
    for (std::size_t j = 0; j < nw; ++j)
      p[whichs[j] == BlowupWhich::R2 ? "r2_s" : "r3_s"] = boundary_json(res[m * nw + j].result, true);
    points.push_back(p);
  }
  json meta = header("blowup", "ic2", f.run);
  meta["r_search"] = {{"r_range", {f.r_min, f.r_max}},
                      {"points_per_decade", f.r_per_decade},
                      {"bisection_rel_tol", f.r_bisect.rel_tol}};
  meta["k_search"] = search_json(f.search);
  meta["definition"] =
      "r2_s (r3_s) = sup R: for all r < R the block (ic2) overturns while ihor < 2 (< 3) for every k in "
      "the k range, i.e. k2_stability (k3_stability) is above the k cap";
  finish_search(f.out, "blowup", "blowup", t, meta, points);
  if (f.out.json_out != "-") {
    for (const auto& c : t.columns)
      if (c.find("_status") == std::string::npos) std::printf("%-16s", c.c_str());
    std::printf("\n");
    for (const auto& row : t.rows) {
      std::printf("%-16s", row[0].c_str());
      for (std::size_t j = 0; j < nw; ++j)
        std::printf("%-16s", row[1 + nw + j] == "found" ? row[1 + j].substr(0, 10).c_str() : row[1 + nw + j].c_str());
      std::printf("\n");
    }
  }
}

void add_blowup(CLI::App& app) {
  auto f = std::make_shared<BlowupFlags>();
  f->r_bisect.rel_tol = 1e-3;
  CLI::App* s = app.add_subcommand("blowup", "aspect ratios r2_s(mu), r3_s(mu) where k2/k3_stability blow up (Fig 4.31)");
  s->add_option("--mu-list", f->mu_list, "friction coefficients (comma-separated)")->capture_default_str();
  s->add_option("--which", f->which, "r2, r3 or both")->capture_default_str();
  s->add_option("--r-min", f->r_min, "lowest aspect ratio searched")->capture_default_str();
  s->add_option("--r-max", f->r_max, "highest aspect ratio searched")->capture_default_str();
  s->add_option("--r-per-decade", f->r_per_decade, "coarse grid points per decade of r")->capture_default_str();
  s->add_option("--r-rel-tol", f->r_bisect.rel_tol, "relative tolerance of the bisection in r")->capture_default_str();
  add_search_options(*s, f->search);
  add_run_options(*s, f->run, 30);
  add_output_options(*s, f->out);
  s->callback([f] { run_blowup(*f); });
}

RegisterCommand reg_overturn(34, add_overturn);
RegisterCommand reg_curve(35, add_curve);
RegisterCommand reg_blowup(36, add_blowup);

}  // namespace
}  // namespace blockdyn::cli
